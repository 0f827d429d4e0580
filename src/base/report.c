/* Output files that appear whole or not at all (see tippe/base.h). */
#define _GNU_SOURCE /* fopencookie: every write's errno, for the message */
#include "tippe/base.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* ---- the table of temporaries (read by signal handlers) ------------------ */

enum { BLOCK_TEMPS = 32, MAX_LINKS = 40 };

typedef struct {
    char tmp[4096 + 16];
    char target[4096];
    volatile sig_atomic_t live; /* tmp exists on disk and is ours */
    int finished;               /* complete and checked: waits for the set's commit */
} temp_entry;

/* As many entries as a run has files at once (a design of 50 parts, split,
 * has over a hundred): blocks of BLOCK_TEMPS, chained, never moved nor freed,
 * so that a signal handler can walk them while a block is being added (a
 * block is linked only once it is zeroed). */
typedef struct temp_block {
    temp_entry e[BLOCK_TEMPS];
    _Atomic(struct temp_block *) next;
} temp_block;

static temp_block first_block;
static int n_blocks = 1;
static int in_set;
static volatile sig_atomic_t renaming;

/* Entry slot (0 .. BLOCK_TEMPS * n_blocks - 1). */
static temp_entry *entry(int slot)
{
    temp_block *b = &first_block;
    for (int k = slot / BLOCK_TEMPS; k > 0; k--)
        b = atomic_load(&b->next);
    return &b->e[slot % BLOCK_TEMPS];
}

void tippe_report_remove_temporaries(void)
{
    for (temp_block *b = &first_block; b; b = atomic_load(&b->next))
        for (int i = 0; i < BLOCK_TEMPS; i++)
            if (b->e[i].live)
                unlink(b->e[i].tmp);
}

int tippe_report_committing(void)
{
    return renaming != 0;
}

/* Removes the temporary of slot (if any) and frees the slot. Unlink first:
 * a signal in between only repeats the unlink of a name that is gone. */
static void drop_temp(int slot)
{
    if (slot < 0)
        return;
    temp_entry *t = entry(slot);
    if (t->live)
        unlink(t->tmp);
    t->live = 0;
    t->finished = 0;
}

/* Renames slot's temporary over its target and frees the slot. */
static int rename_temp(int slot, const char *path, const char *what, tippe_error *err)
{
    temp_entry *t = entry(slot);
    if (rename(t->tmp, t->target) != 0) {
        int e = errno;
        drop_temp(slot);
        return tippe_error_set(err, TIPPE_ECOMPUTE, "%s: cannot put %s into place: %s", path,
                               what, strerror(e));
    }
    t->live = 0; /* the name is the user's file now */
    t->finished = 0;
    return TIPPE_OK;
}

/* Creates "TARGET.tmp.XXXXXX" with the permissions the final file must have
 * (those of the file it replaces, else 0666 less the umask) and records it. */
static int make_temp(tippe_report_file *rf, const struct stat *old, tippe_error *err, int *fd_out)
{
    int slot = -1;
    for (int i = 0; i < BLOCK_TEMPS * n_blocks && slot < 0; i++)
        if (!entry(i)->live && !entry(i)->finished)
            slot = i;
    if (slot < 0) { /* every entry is taken: one more block */
        temp_block *nb = calloc(1, sizeof *nb), *last = &first_block;
        if (!nb)
            return tippe_error_set(err, TIPPE_ECOMPUTE, "%s: out of memory", rf->path);
        atomic_init(&nb->next, NULL);
        while (atomic_load(&last->next))
            last = atomic_load(&last->next);
        atomic_store(&last->next, nb);
        slot = BLOCK_TEMPS * n_blocks++;
    }
    temp_entry *t = entry(slot);
    char tmp[sizeof t->tmp];
    if (snprintf(tmp, sizeof tmp, "%s.tmp.XXXXXX", rf->target) >= (int)sizeof tmp)
        return tippe_error_set(err, TIPPE_EINPUT, "%s: path too long", rf->path);
    /* The slot holds the name while mkostemp fills it in and creates the file:
     * a signal handler that comes meanwhile unlinks a name not yet created
     * (harmless) or the new file, never misses it. */
    memcpy(t->tmp, tmp, sizeof tmp);
    t->live = 1;
    int fd = mkostemp(t->tmp, O_CLOEXEC);
    memcpy(tmp, t->tmp, sizeof tmp);
    if (fd < 0) {
        t->live = 0;
        int e = errno;
        struct stat dir;
        char folder[sizeof tmp];
        tippe_path_dir(tmp, folder, sizeof folder);
        if (e == ENOENT && stat(folder, &dir) != 0) {
            if (strcmp(rf->path, rf->target) != 0)
                return tippe_error_set(err, TIPPE_EINPUT,
                                       "%s: cannot write %s: a dangling symlink to '%s', whose "
                                       "directory does not exist",
                                       rf->path, rf->what, rf->target);
            return tippe_error_set(err, TIPPE_EINPUT,
                                   "%s: cannot write %s: its directory does not exist", rf->path,
                                   rf->what);
        }
        if (e == ENOENT) /* /proc, /sys: a directory that takes no new files */
            return tippe_error_set(err, TIPPE_EINPUT,
                                   "%s: cannot write %s: no new file can be made in '%s'",
                                   rf->path, rf->what, folder);
        return tippe_error_set(err, TIPPE_EINPUT, "%s: cannot write %s: %s", rf->path, rf->what,
                               strerror(e));
    }
    snprintf(t->target, sizeof t->target, "%s", rf->target);
    rf->slot = slot;
    snprintf(rf->write_path, sizeof rf->write_path, "%s", tmp);
    mode_t mode;
    if (old) {
        mode = old->st_mode & 07777;
        /* Keeps the owner when allowed (root); otherwise the file becomes ours. */
        if (fchown(fd, old->st_uid, old->st_gid) != 0)
            mode &= 0777;
    } else {
        mode_t mask = umask(0);
        umask(mask);
        mode = 0666 & ~mask;
    }
    if (fchmod(fd, mode) != 0) {
        int e = errno;
        close(fd);
        drop_temp(slot);
        rf->slot = -1;
        return tippe_error_set(err, TIPPE_ECOMPUTE, "%s: cannot write %s: %s", rf->path,
                               rf->what, strerror(e));
    }
    *fd_out = fd;
    return TIPPE_OK;
}

/* ---- where a path leads --------------------------------------------------- */

int tippe_report_target(const char *path, char *out, size_t size, tippe_error *err)
{
    char cur[4096];
    if (!path || !path[0])
        return tippe_error_set(err, TIPPE_EINPUT, "empty output file name");
    if (snprintf(cur, sizeof cur, "%s", path) >= (int)sizeof cur)
        return tippe_error_set(err, TIPPE_EINPUT, "%s: path too long", path);
    for (int hops = 0;; hops++) {
        struct stat st;
        if (lstat(cur, &st) != 0 || !S_ISLNK(st.st_mode))
            break; /* the caller looks at what is (or is not) there */
        if (hops == MAX_LINKS)
            return tippe_error_set(err, TIPPE_EINPUT, "%s: %s", path, strerror(ELOOP));
        char link[4096];
        ssize_t n = readlink(cur, link, sizeof link - 1);
        if (n < 0)
            return tippe_error_set(err, TIPPE_EINPUT, "%s: %s", path, strerror(errno));
        link[n] = '\0';
        char next[4096];
        if (tippe_path_beside(cur, link, next, sizeof next) != TIPPE_OK)
            return tippe_error_set(err, TIPPE_EINPUT, "%s: path too long", path);
        memcpy(cur, next, sizeof cur);
    }
    if (strlen(cur) >= size)
        return tippe_error_set(err, TIPPE_EINPUT, "%s: path too long", path);
    memcpy(out, cur, strlen(cur) + 1);
    return TIPPE_OK;
}

/* Fills rf's path, target and mode; *old is the file to be replaced (exists
 * = 1) or nothing (0). Refuses what cannot be written. */
static int plan(tippe_report_file *rf, const char *path, const char *what, struct stat *old,
                int *exists, tippe_error *err)
{
    memset(rf, 0, sizeof *rf);
    rf->slot = -1;
    rf->fd = -1;
    rf->what = what;
    *exists = 0;
    if (!path || !path[0])
        return tippe_error_set(err, TIPPE_EINPUT, "empty file name for %s", what);
    if (snprintf(rf->path, sizeof rf->path, "%s", path) >= (int)sizeof rf->path)
        return tippe_error_set(err, TIPPE_EINPUT, "%s: path too long", path);
    if (!strcmp(path, "-")) {
        rf->mode = TIPPE_REPORT_STDOUT;
        snprintf(rf->target, sizeof rf->target, "/dev/stdout");
        snprintf(rf->write_path, sizeof rf->write_path, "/dev/stdout");
        return TIPPE_OK;
    }
    int rc = tippe_report_target(path, rf->target, sizeof rf->target, err);
    if (rc)
        return rc;
    snprintf(rf->write_path, sizeof rf->write_path, "%s", rf->target);
    if (stat(rf->target, old) != 0) {
        if (errno == ENOENT) {
            rf->mode = TIPPE_REPORT_REPLACE; /* a new file (the directory is tried later) */
            return TIPPE_OK;
        }
        return tippe_error_set(err, TIPPE_EINPUT, "%s: cannot write %s: %s", path, what,
                               strerror(errno));
    }
    *exists = 1;
    if (S_ISREG(old->st_mode))
        rf->mode = TIPPE_REPORT_REPLACE;
    else if (S_ISCHR(old->st_mode) || S_ISFIFO(old->st_mode))
        rf->mode = TIPPE_REPORT_DIRECT;
    else if (S_ISDIR(old->st_mode))
        return tippe_error_set(err, TIPPE_EINPUT, "%s: cannot write %s: it is a directory", path,
                               what);
    else
        return tippe_error_set(err, TIPPE_EINPUT,
                               "%s: cannot write %s: not a regular file, character device or FIFO",
                               path, what);
    return TIPPE_OK;
}

/* An existing file must be one the user may write: the old file of a read-only
 * name is kept rather than replaced behind the user's back. O_WRONLY without
 * O_TRUNC changes nothing. A FIFO is not opened (a reader waiting on it would
 * take the open and close for an empty file): its permission is asked. */
static int may_write(const tippe_report_file *rf, const struct stat *st, tippe_error *err)
{
    int fd = -1;
    if (S_ISFIFO(st->st_mode) ? faccessat(AT_FDCWD, rf->target, W_OK, AT_EACCESS) != 0
                              : (fd = open(rf->target, O_WRONLY | O_NOCTTY | O_NONBLOCK |
                                                           O_CLOEXEC)) < 0)
        return tippe_error_set(err, TIPPE_EINPUT, "%s: cannot write %s: %s", rf->path, rf->what,
                               strerror(errno));
    if (fd >= 0)
        close(fd);
    return TIPPE_OK;
}

/* ---- a stream that remembers why a write failed --------------------------- */

static ssize_t checked_write(void *cookie, const char *buf, size_t size)
{
    tippe_report_file *rf = cookie;
    size_t done = 0;
    while (done < size) {
        ssize_t n = write(rf->fd, buf + done, size - done);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            if (!rf->io_errno)
                rf->io_errno = n < 0 ? errno : EIO;
            return done > 0 ? (ssize_t)done : -1;
        }
        done += (size_t)n;
    }
    return (ssize_t)done;
}

static int checked_close(void *cookie)
{
    tippe_report_file *rf = cookie;
    /* Some file systems report a full disk only here (delayed allocation, NFS). */
    if (rf->sync_on_close && fsync(rf->fd) != 0 && !rf->io_errno)
        rf->io_errno = errno;
    if (close(rf->fd) != 0 && !rf->io_errno)
        rf->io_errno = errno;
    rf->fd = -1;
    return rf->io_errno ? -1 : 0;
}

/* A stream over fd whose every failure is remembered in rf->io_errno. */
static FILE *checked_stream(tippe_report_file *rf, int fd)
{
    rf->fd = fd;
    rf->sync_on_close = rf->mode == TIPPE_REPORT_REPLACE;
    rf->io_errno = 0;
    cookie_io_functions_t io = {NULL, checked_write, NULL, checked_close};
    return fopencookie(rf, "w", io);
}

/* ---- open, check, commit, abort ------------------------------------------- */

static int open_common(tippe_report_file *rf, const char *path, const char *what, int stream,
                       tippe_error *err)
{
    struct stat old;
    int exists;
    int rc = plan(rf, path, what, &old, &exists, err);
    if (!rc && exists)
        rc = may_write(rf, &old, err);
    if (rc)
        return rc;
    int fd = -1;
    /* "-" is descriptor 1, not the C stream stdout: a program that writes its
     * data to "-" may send its own text elsewhere by pointing stdout there. */
    if (rf->mode == TIPPE_REPORT_STDOUT && stream &&
        (fd = fcntl(STDOUT_FILENO, F_DUPFD_CLOEXEC, 3)) < 0)
        return tippe_error_set(err, TIPPE_EINPUT, "%s: cannot write %s: %s", path, what,
                               strerror(errno));
    if (rf->mode == TIPPE_REPORT_STDOUT && !stream)
        return TIPPE_OK;
    if (rf->mode == TIPPE_REPORT_REPLACE) {
        if ((rc = make_temp(rf, exists ? &old : NULL, err, &fd)) != 0)
            return rc;
    } else if (rf->mode == TIPPE_REPORT_DIRECT) {
        if (stream && (fd = open(rf->target, O_WRONLY | O_NOCTTY | O_CLOEXEC)) < 0)
            return tippe_error_set(err, TIPPE_EINPUT, "%s: cannot write %s: %s", path, what,
                                   strerror(errno));
    }
    if (!stream) {
        if (fd >= 0)
            close(fd);
        return TIPPE_OK;
    }
    rf->f = checked_stream(rf, fd);
    if (!rf->f) {
        int e = errno;
        close(fd);
        drop_temp(rf->slot);
        rf->slot = -1;
        return tippe_error_set(err, TIPPE_ECOMPUTE, "%s: cannot write %s: %s", path, what,
                               strerror(e));
    }
    return TIPPE_OK;
}

int tippe_report_open(tippe_report_file *rf, const char *path, const char *what,
                      tippe_error *err)
{
    return open_common(rf, path, what, 1, err);
}

int tippe_report_open_name(tippe_report_file *rf, const char *path, const char *what,
                           tippe_error *err)
{
    return open_common(rf, path, what, 0, err);
}

int tippe_report_check(const char *path, const char *what, tippe_error *err)
{
    tippe_report_file rf;
    struct stat old;
    int exists;
    int rc = plan(&rf, path, what, &old, &exists, err);
    if (!rc && exists)
        rc = may_write(&rf, &old, err);
    if (rc || rf.mode != TIPPE_REPORT_REPLACE)
        return rc;
    int fd;
    if ((rc = make_temp(&rf, exists ? &old : NULL, err, &fd)) != 0)
        return rc;
    close(fd);
    drop_temp(rf.slot);
    return TIPPE_OK;
}

/* Closes rf->f and returns the errno of the first failed write, flush, sync
 * or close (0 if all succeeded). */
static int close_stream(tippe_report_file *rf)
{
    if (!rf->f)
        return 0;
    int e = 0;
    if (fclose(rf->f) != 0 || rf->io_errno)
        e = rf->io_errno ? rf->io_errno : EIO;
    rf->f = NULL;
    return e;
}

/* For a writer that wrote rf->write_path by name: makes the data durable. */
static int sync_named(const tippe_report_file *rf)
{
    int fd = open(rf->write_path, O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return errno;
    int e = fsync(fd) != 0 ? errno : 0;
    close(fd);
    return e;
}

int tippe_report_commit(tippe_report_file *rf, tippe_error *err)
{
    const int named = rf->f == NULL;
    int e = close_stream(rf);
    if (!e && named && rf->mode == TIPPE_REPORT_REPLACE && rf->slot >= 0)
        e = sync_named(rf);
    if (e) {
        drop_temp(rf->slot);
        rf->slot = -1;
        return tippe_error_set(err, TIPPE_ECOMPUTE, "%s: writing %s failed: %s", rf->path,
                               rf->what, strerror(e));
    }
    if (rf->mode != TIPPE_REPORT_REPLACE || rf->slot < 0)
        return TIPPE_OK;
    const int slot = rf->slot;
    rf->slot = -1;
    if (in_set) {
        entry(slot)->finished = 1;
        return TIPPE_OK;
    }
    return rename_temp(slot, rf->path, rf->what, err);
}

void tippe_report_abort(tippe_report_file *rf)
{
    close_stream(rf);
    drop_temp(rf->slot);
    rf->slot = -1;
}

int tippe_report_fail(tippe_report_file *rf, tippe_error *err, const char *why)
{
    const int e = close_stream(rf);
    drop_temp(rf->slot);
    rf->slot = -1;
    if (e)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "%s: writing %s failed: %s", rf->path,
                               rf->what, strerror(e));
    return tippe_error_set(err, TIPPE_ECOMPUTE, "%s: %s", rf->path, why);
}

void tippe_report_set_begin(void)
{
    in_set = 1;
}

int tippe_report_set_commit(tippe_error *err)
{
    int status = TIPPE_OK;
    renaming = 1;
    for (int i = 0; i < BLOCK_TEMPS * n_blocks; i++) {
        if (!entry(i)->finished)
            continue;
        if (status != TIPPE_OK)
            drop_temp(i);
        else
            status = rename_temp(i, entry(i)->target, "an output file", err);
    }
    renaming = 0;
    in_set = 0;
    return status;
}

void tippe_report_set_abort(void)
{
    for (int i = 0; i < BLOCK_TEMPS * n_blocks; i++)
        drop_temp(i);
    in_set = 0;
}
