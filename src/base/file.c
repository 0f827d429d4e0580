/* Reading a whole input file into memory, for every file the library reads
 * (design and materials JSON, G-code): only regular files, opened so that a
 * FIFO or a device cannot block or feed the reader for ever, and no larger
 * than the caller's cap (issue 36: the zero device as a G-code grew the buffer
 * to 2 GiB; a FIFO blocked a server worker). */
#define _GNU_SOURCE
#include "tippe/base.h"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static tippe_file_read_check read_check;

void tippe_file_set_read_check(tippe_file_read_check check)
{
    read_check = check;
}

/* O_NONBLOCK on the open only: a FIFO with no writer would otherwise block in
 * open() itself, before fstat() can tell what the file is. The flag is cleared
 * again for a regular file, where it means nothing anyway. */
int tippe_file_read(const char *path, size_t max_bytes, const char *what, char **out,
                    size_t *out_len, tippe_error *err)
{
    *out = NULL;
    *out_len = 0;
    if (read_check) {
        int rc = read_check(path, what, err);
        if (rc)
            return rc;
    }
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0)
        return tippe_error_set(err, TIPPE_EINPUT, "%s: cannot open: %s", path, strerror(errno));
    struct stat st;
    if (fstat(fd, &st) != 0) {
        int e = errno;
        close(fd);
        return tippe_error_set(err, TIPPE_EINPUT, "%s: cannot read: %s", path, strerror(e));
    }
    if (!S_ISREG(st.st_mode)) {
        close(fd);
        return tippe_error_set(err, TIPPE_EINPUT,
                               "%s: not a regular file (%s): a %s file must be a file on disk",
                               path,
                               S_ISDIR(st.st_mode)    ? "a directory"
                               : S_ISFIFO(st.st_mode) ? "a FIFO"
                               : S_ISCHR(st.st_mode)  ? "a character device"
                               : S_ISBLK(st.st_mode)  ? "a block device"
                               : S_ISSOCK(st.st_mode) ? "a socket"
                                                      : "not a file",
                               what);
    }
    if ((unsigned long long)st.st_size > max_bytes) {
        close(fd);
        return tippe_error_set(err, TIPPE_EINPUT, "%s: %lld bytes, more than the %zu MiB a %s "
                                                  "file may have",
                               path, (long long)st.st_size, max_bytes >> 20, what);
    }
    (void)fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    /* The size may change under us: read at most max_bytes + 1 and refuse the +1. */
    size_t cap = (size_t)st.st_size + 1;
    if (cap > max_bytes + 1)
        cap = max_bytes + 1;
    char *buf = malloc(cap + 1);
    if (!buf) {
        close(fd);
        return tippe_error_set(err, TIPPE_ECOMPUTE, "%s: out of memory", path);
    }
    size_t len = 0;
    for (;;) {
        if (len == cap) {
            if (cap > max_bytes)
                break;
            size_t more = cap * 2 > max_bytes + 1 ? max_bytes + 1 : cap * 2;
            char *b2 = realloc(buf, more + 1);
            if (!b2) {
                free(buf);
                close(fd);
                return tippe_error_set(err, TIPPE_ECOMPUTE, "%s: out of memory", path);
            }
            buf = b2;
            cap = more;
        }
        ssize_t got = read(fd, buf + len, cap - len);
        if (got < 0 && errno == EINTR)
            continue;
        if (got < 0) {
            int e = errno;
            free(buf);
            close(fd);
            return tippe_error_set(err, TIPPE_EINPUT, "%s: cannot read: %s", path, strerror(e));
        }
        if (got == 0)
            break;
        len += (size_t)got;
    }
    close(fd);
    if (len > max_bytes) {
        free(buf);
        return tippe_error_set(err, TIPPE_EINPUT, "%s: more than the %zu MiB a %s file may have",
                               path, max_bytes >> 20, what);
    }
    buf[len] = '\0';
    *out = buf;
    *out_len = len;
    return TIPPE_OK;
}
