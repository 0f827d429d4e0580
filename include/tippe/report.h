/* tippe/report.h: output files that appear whole or not at all, and never
 * cost a user an old file.
 *
 * Where the bytes go depends on what the path names:
 *   - a regular file or a new path: a temporary next to the file
 *     ("NAME.tmp.XXXXXX"), renamed over it once everything is written and
 *     checked, so that a reader never sees a half-written file and a failed run
 *     leaves the old file as it was. The new file keeps the old one's
 *     permissions (a new one gets 0666 less the umask, as fopen() gives);
 *   - a symbolic link: the same, for the file the link finally points to (the
 *     temporary sits next to that file and the link is kept);
 *   - a character device, a FIFO (/dev/null, /dev/stdout, a named pipe):
 *     straight through, since such a file cannot be replaced;
 *   - "-": standard output, straight through: file descriptor 1 through a
 *     duplicate of it (closed at commit), whatever the C stream stdout is.
 * A directory, a path through a regular file or one that cannot be created is
 * refused (TIPPE_EINPUT) with the reason; tippe_report_check() finds that out
 * before any work by really creating (and removing) a temporary.
 *
 * Every write is checked: commit flushes, syncs and closes the stream and fails
 * (TIPPE_ECOMPUTE, "PATH: writing WHAT failed: REASON") if any of it failed.
 *
 *     tippe_report_file rf;
 *     if ((rc = tippe_report_open(&rf, path, "the CSV file", err)) != 0) return rc;
 *     fprintf(rf.f, ...);
 *     return tippe_report_commit(&rf, err);    // or tippe_report_abort(&rf)
 *
 * Sets of outputs: between tippe_report_set_begin() and tippe_report_set_commit()
 * (or _set_abort()), commit only finishes a file (complete and checked under
 * its temporary name); the set's files are renamed into place together at the
 * end, or all removed. The tippe command runs every verb inside one set, so a
 * verb's outputs are all written or none is (src/cli/common.c).
 *
 * Signals: every temporary is recorded in a fixed table that
 * tippe_report_remove_temporaries() empties with unlink() only, so that a
 * signal handler may call it (the command's handler, src/cli/signals.c).
 * Outputs are written from one thread. */
#ifndef TIPPE_REPORT_H
#define TIPPE_REPORT_H

#include <stdio.h>

#include "tippe/error.h"

typedef enum {
    TIPPE_REPORT_REPLACE = 0, /* temporary + rename (regular file, new path) */
    TIPPE_REPORT_DIRECT,      /* straight through (device, FIFO) */
    TIPPE_REPORT_STDOUT       /* "-" */
} tippe_report_mode;

typedef struct {
    FILE *f;                  /* write here; NULL once closed */
    const char *what;         /* "the CSV file", "the plot": for messages */
    tippe_report_mode mode;
    char path[4096];          /* as given, for messages */
    char target[4096];        /* the file written or replaced (a link's target) */
    char write_path[4096 + 16]; /* where the bytes go: the temporary or target */
    int slot;                 /* the temporary's entry in the table, or -1 */
    int fd, sync_on_close, io_errno; /* private: the stream's descriptor and first error */
} tippe_report_file;

/* Opens path for writing (see above for where the bytes go). what (a string
 * that outlives rf) names the file in messages; rf must stay where it is until
 * commit or abort (its stream refers to it). TIPPE_EINPUT if path cannot
 * be written ("PATH: cannot write WHAT: REASON"); on failure nothing is left
 * on disk. */
int tippe_report_open(tippe_report_file *rf, const char *path, const char *what,
                      tippe_error *err);

/* As tippe_report_open(), for a writer that opens the file by name itself
 * (FFmpeg, lib3mf): rf->f is NULL and the writer writes to rf->write_path (the
 * temporary, the device, or /dev/stdout for "-"). The caller checks its
 * writer's status and then commits or aborts. */
int tippe_report_open_name(tippe_report_file *rf, const char *path, const char *what,
                           tippe_error *err);

/* Whether path can be written as tippe_report_open() would write it, found by
 * creating and removing a temporary next to it (an existing file must also
 * open for writing; a FIFO need not have a reader yet). Changes nothing on
 * disk. TIPPE_EINPUT with the reason if not. */
int tippe_report_check(const char *path, const char *what, tippe_error *err);

/* The file path finally names: path, or what its symbolic links point to
 * (relative links resolved from their own directory; a dangling link gives
 * the file it would create). For telling whether two outputs are one file. */
int tippe_report_target(const char *path, char *out, size_t size, tippe_error *err);

/* Flushes, syncs and closes rf->f (unless NULL) and checks that every write
 * succeeded, then renames the temporary into place (inside a set: leaves it
 * for tippe_report_set_commit()). On failure (TIPPE_ECOMPUTE) the temporary is
 * removed and the old file is untouched. */
int tippe_report_commit(tippe_report_file *rf, tippe_error *err);

/* Closes rf->f (unless NULL) and removes the temporary. Safe after a failed
 * open or a commit (then it does nothing). */
void tippe_report_abort(tippe_report_file *rf);

/* Starts a set of outputs (see above). A set already open is kept. */
void tippe_report_set_begin(void);
/* Renames every finished file of the set into place and ends the set. A
 * rename that fails is reported (TIPPE_ECOMPUTE) and the temporaries not yet
 * renamed are removed. */
int tippe_report_set_commit(tippe_error *err);
/* Removes every temporary (finished or not) and ends the set. */
void tippe_report_set_abort(void);

/* Removes every temporary still on disk, with unlink() only: safe in a signal
 * handler. Files already renamed into place are not touched. */
void tippe_report_remove_temporaries(void);

/* 1 while tippe_report_set_commit() renames files into place (a signal
 * handler should then let it finish); safe in a signal handler. */
int tippe_report_committing(void);

#endif
