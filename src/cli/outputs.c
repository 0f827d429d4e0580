/* The outputs of the tippe command: which files a verb reads and writes (an
 * output checked before any work, never one of the inputs), the run that
 * commits them only when every output is complete, and JSON on stdout. */
#include "cli.h"
#include "../modules/module.h"

#include "tippe/design.h"
#include "base/json.h"
#include "tippe/plot.h"
#include "tippe/base.h"

#include <cjson/cJSON.h>

#include <errno.h>
#include <pthread.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <sys/stat.h>
#include <unistd.h>

/* The files the verb's outputs finally name, to refuse two outputs that are
 * one file (each would replace the other): as many as the verb has (an
 * export of a design of many parts writes over a hundred). */
typedef struct {
    char file[4096 + 256];
    const char *option;
} checked_output;
static checked_output *checked;
static int n_checked, cap_checked;

/* arr (n used of *cap elements of size bytes) with room for one more, or NULL
 * when memory ran out (arr is then kept, and the caller only loses a check it
 * could not record). */
static void *grown(void *arr, int n, int *cap, size_t size)
{
    if (n < *cap)
        return arr;
    int want = *cap ? 2 * *cap : 16;
    void *more = realloc(arr, (size_t)want * size);
    if (more)
        *cap = want;
    return more;
}

/* dir's real path + "/" + base of a (link-resolved) target: one name per file. */
static int canonical_name(const char *target, char *out, size_t size)
{
    char dir[4096];
    const char *base = tippe_path_base(target);
    tippe_path_dir(target, dir, sizeof dir);
    char real[PATH_MAX];
    if (!realpath(dir, real))
        return 0;
    return snprintf(out, size, "%s/%s", real, base) < (int)size;
}

/* The verb's input files (its positional arguments), to refuse an output that
 * would replace one of them. */
enum { MAX_INPUTS = 16 };
static struct {
    const char *path;
    dev_t dev;
    ino_t ino;
} inputs[MAX_INPUTS];
static int n_inputs;

void tippe_cli_note_inputs(const char *const *paths, int n)
{
    n_inputs = 0;
    for (int i = 0; i < n && n_inputs < MAX_INPUTS; i++) {
        struct stat st;
        if (strcmp(paths[i], "-") && stat(paths[i], &st) == 0 && S_ISREG(st.st_mode)) {
            inputs[n_inputs].path = paths[i];
            inputs[n_inputs].dev = st.st_dev;
            inputs[n_inputs++].ino = st.st_ino;
        }
    }
}

/* The input that path (through any symlink) already is, or NULL. */
static const char *input_named_by(const char *path)
{
    struct stat st;
    if (!strcmp(path, "-") || stat(path, &st) != 0)
        return NULL;
    for (int i = 0; i < n_inputs; i++)
        if (inputs[i].dev == st.st_dev && inputs[i].ino == st.st_ino)
            return inputs[i].path;
    return NULL;
}

/* Every file the run has read or is about to read through src/base/json.h (a
 * design's materials table, a spec's catalogue and base design, a scenario's
 * design), and the existing files the outputs name: an output is refused when
 * it is one of them, whichever the run meets first. Reads may come from
 * several threads (an optimiser's candidates), hence the lock. */
enum { MAX_READ = 64 };
static struct {
    char path[512];
    char what[64];
    dev_t dev;
    ino_t ino;
} read_files[MAX_READ];
static int n_read;
typedef struct {
    const char *option, *path;
    dev_t dev;
    ino_t ino;
} output_id;
static output_id *out_ids;
static int n_out_ids, cap_out_ids;
static pthread_mutex_t read_lock = PTHREAD_MUTEX_INITIALIZER;

static int refuse_read_output(const char *path, const char *what, tippe_error *err)
{
    struct stat st;
    if (stat(path, &st) != 0 || !S_ISREG(st.st_mode))
        return TIPPE_OK; /* reading it fails with its own message */
    int rc = TIPPE_OK;
    pthread_mutex_lock(&read_lock);
    for (int i = 0; i < n_out_ids; i++)
        if (out_ids[i].dev == st.st_dev && out_ids[i].ino == st.st_ino) {
            rc = tippe_error_set(err, TIPPE_EINPUT,
                                 "%s %s is the %s file '%s' that this run reads: it would be "
                                 "replaced; choose another output name",
                                 out_ids[i].option, out_ids[i].path, what, path);
            break;
        }
    int known = 0;
    for (int i = 0; i < n_read && !known; i++)
        known = read_files[i].dev == st.st_dev && read_files[i].ino == st.st_ino;
    if (!rc && !known && n_read < MAX_READ) {
        snprintf(read_files[n_read].path, sizeof read_files[n_read].path, "%s", path);
        snprintf(read_files[n_read].what, sizeof read_files[n_read].what, "%s", what);
        read_files[n_read].dev = st.st_dev;
        read_files[n_read++].ino = st.st_ino;
    }
    pthread_mutex_unlock(&read_lock);
    return rc;
}

/* Notes that option writes path, and returns the read file path already is
 * (an index of read_files), or -1. */
static int note_output_id(const char *option, const char *path)
{
    struct stat st;
    if (!strcmp(path, "-") || stat(path, &st) != 0 || !S_ISREG(st.st_mode))
        return -1;
    pthread_mutex_lock(&read_lock);
    int found = -1;
    for (int i = 0; i < n_read && found < 0; i++)
        if (read_files[i].dev == st.st_dev && read_files[i].ino == st.st_ino)
            found = i;
    output_id *ids = grown(out_ids, n_out_ids, &cap_out_ids, sizeof *out_ids);
    if (ids) {
        out_ids = ids;
        out_ids[n_out_ids].option = option;
        out_ids[n_out_ids].path = path;
        out_ids[n_out_ids].dev = st.st_dev;
        out_ids[n_out_ids++].ino = st.st_ino;
    }
    pthread_mutex_unlock(&read_lock);
    return found;
}

/* Who writes to standard output besides the text: --json, or an output named "-". */
static const char *stdout_owner;

void tippe_cli_note_json(int json)
{
    stdout_owner = json ? "--json" : NULL;
}

int tippe_cli_check_output(const char *verb, const char *option, const char *path, int plot)
{
    if (!strcmp(path, "-")) {
        if (stdout_owner)
            return tippe_cli_usage_error(verb, "%s -: standard output already carries %s; "
                                         "give %s a file name", option, stdout_owner, option);
        stdout_owner = option;
        /* The data owns descriptor 1 (tippe/base.h writes "-" there); the
         * text report goes to stderr so that the piped file stays clean.
         * glibc's stdout is an ordinary variable that may be set. */
        fflush(stdout);
        stdout = stderr;
    }
    const char *input = input_named_by(path);
    if (input)
        return tippe_cli_usage_error(verb, "%s %s is the input file '%s': it would be "
                                     "replaced; choose another output name",
                                     option, path, input);
    const int read = note_output_id(option, path);
    if (read >= 0)
        return tippe_cli_usage_error(verb, "%s %s is the %s file '%s' that this run reads: it "
                                     "would be replaced; choose another output name", option,
                                     path, read_files[read].what, read_files[read].path);
    if (plot && !tippe_plot_device(path))
        return tippe_cli_usage_error(
            verb, "%s %s: unsupported plot format (use a .png, .svg or .pdf file name)", option,
            path);
    tippe_error err = {0};
    if (tippe_report_check(path, plot ? "the plot" : "the output file", &err))
        return tippe_cli_usage_error(verb, "%s %s", option, err.msg);
    char target[4096], name[sizeof ((checked_output *)0)->file];
    struct stat st;
    if (strcmp(path, "-") && tippe_report_target(path, target, sizeof target, &err) == 0 &&
        (stat(target, &st) != 0 || S_ISREG(st.st_mode)) &&
        canonical_name(target, name, sizeof name)) {
        for (int i = 0; i < n_checked; i++)
            if (!strcmp(checked[i].file, name) && strcmp(checked[i].option, option))
                return tippe_cli_usage_error(verb, "%s and %s name the same file '%s'",
                                             checked[i].option, option, path);
        checked_output *c = grown(checked, n_checked, &cap_checked, sizeof *checked);
        if (c) {
            checked = c;
            memcpy(checked[n_checked].file, name, sizeof name);
            checked[n_checked++].option = option;
        }
    }
    /* The plotting module is loaded now: if it is missing, say so before the work. */
    if (plot && tippe_module_plot_ready(&err))
        return tippe_cli_fail(verb, &err, TIPPE_EINPUT);
    return 0;
}

int tippe_cli_make_output_dir(const char *verb, const char *option, const char *dir)
{
    struct stat st;
    if (!strcmp(dir, "-")) /* several files cannot share standard output */
        return tippe_cli_usage_error(verb, "%s -: %s writes several files into a directory, not "
                                     "to standard output; give a directory", option, verb);
    if (stat(dir, &st) == 0)
        return S_ISDIR(st.st_mode) ? 0
                                   : tippe_cli_usage_error(verb, "%s %s: not a directory", option,
                                                           dir);
    /* A dangling symlink keeps pointing at its new directory, as a symlink to
     * a file keeps pointing at its new file: the directory is made where it
     * points (and removed from there if the run fails or is stopped: noted by
     * tippe_cli_signals_mkdir for tippe_cli_run and the stop signals). */
    char target[4096];
    tippe_error err = {0};
    if (tippe_report_target(dir, target, sizeof target, &err))
        return tippe_cli_usage_error(verb, "%s %s", option, err.msg);
    const int link = strcmp(target, dir) != 0;
    if (tippe_cli_signals_mkdir(target) != 0) {
        const int e = errno;
        if (link)
            return tippe_cli_usage_error(verb, "%s %s: a dangling symlink to '%s', which cannot "
                                         "be created as a directory: %s", option, dir, target,
                                         strerror(e));
        return tippe_cli_usage_error(verb, "%s %s: cannot create the directory: %s", option, dir,
                                     strerror(e));
    }
    return 0;
}

int tippe_cli_run(const tippe_cli_verb *v, int argc, char **argv)
{
    tippe_cli_signals_install(v->name);
    tippe_report_set_begin();
    tippe_file_set_read_check(refuse_read_output);
    int status = v->run(argc, argv);
    /* Stdout is an output like the others: a full disk or a closed pipe there
     * is a failure, and the files of a failed run are not committed. */
    errno = 0;
    if (fflush(stdout) != 0 || ferror(stdout)) {
        const int e = errno ? errno : EIO;
        fprintf(stderr, "tippe %s: writing to standard output failed: %s\n", v->name,
                strerror(e));
        if (status == 0)
            status = 1;
    }
    tippe_error err = {0};
    if (status != 0) {
        tippe_report_set_abort();
        /* rmdir takes only an empty directory: one holding other files stays */
        if (tippe_cli_signals_made_dir())
            rmdir(tippe_cli_signals_made_dir());
    } else if (tippe_report_set_commit(&err) != TIPPE_OK)
        status = tippe_cli_fail(v->name, &err, TIPPE_ECOMPUTE);
    const int stopped = tippe_cli_signal_pending(v->name);
    return stopped ? stopped : status;
}

int tippe_cli_print_json(const char *verb, cJSON *o)
{
    char *s = o ? cJSON_Print(o) : NULL;
    cJSON_Delete(o);
    if (!s) {
        fprintf(stderr, "tippe %s: out of memory while writing JSON\n", verb);
        return 1;
    }
    printf("%s\n", s);
    free(s);
    return 0;
}


double tippe_cli_now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void tippe_cli_design_warnings(const char *verb, const tippe_design *d)
{
    char msg[512];
    for (int i = 0; tippe_design_warning(d, i, msg, sizeof msg); i++)
        fprintf(stderr, "tippe %s: warning: %s: %s\n", verb, tippe_design_path(d), msg);
    for (int i = 0; tippe_design_note(d, i, msg, sizeof msg); i++)
        fprintf(stderr, "tippe %s: note: %s: %s\n", verb, tippe_design_path(d), msg);
}
