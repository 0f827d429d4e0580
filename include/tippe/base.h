/* tippe/base.h: the bottom layer: errors as codes with a message, reports and safe file writing, progress.
 *
 * Contents:
 * - errors: status codes with a message a user can act on (tippe_error_*, src/base/error.c);
 * - reports: output files written whole or not at all, sets of them that commit together,
 *   and every input read through one safe reader (tippe_report_*, tippe_file_*;
 *   src/base/report.c, file.c);
 * - paths: a file's folder, name, stem and extension, and a name relative to the folder of
 *   the file that names it (tippe_path_*, src/base/path.c);
 * - cancel: a flag a thread watches, which the library's long loops check (tippe_cancel_*,
 *   src/base/cancel.c);
 * - progress: long loops with a time-left estimate (tippe_progress_*, src/base/progress.c).
 * Internal to the library: base/json.h, the strict JSON reader every loader uses.
 */
#ifndef TIPPE_BASE_H
#define TIPPE_BASE_H

#include <stdio.h>

/* ---- errors ---- */
/* Error: how every tippe function reports failure.
 *
 * Like GSL, a function returns an int status (TIPPE_OK on success) and, when it
 * fails, fills a tippe_error with a message a user can act on: which file, which
 * field (as a JSON path such as "parts[2].radius_mm"), and what is wrong.
 * The status doubles as the process exit code of the tippe command. */
enum {
    TIPPE_OK = 0,
    TIPPE_ECOMPUTE = 1, /* a computation failed (integrator, root finder, ...) */
    TIPPE_EINPUT = 2    /* bad usage or bad input: the user can fix it */
};

typedef struct {
    int code;
    char msg[1024];
    /* The input that was wrong, when one was: a JSON path ("parts[2].radius_mm") or a
     * parameter's name ("z2_mm", "patch_mm"), "" when none is known. A front end maps it
     * onto its own name (the server's field, the command's option) instead of reading
     * the message. */
    char field[128];
} tippe_error;

/* Sets err (if not NULL) and returns code, so that callers can write
 * `return tippe_error_set(err, TIPPE_EINPUT, "%s: %s: ...", file, path);`. The field
 * is cleared: a message set anew blames nothing it does not name. */
int tippe_error_set(tippe_error *err, int code, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* The same, blaming field (a JSON path or a parameter's name; NULL: none). */
int tippe_error_set_field(tippe_error *err, int code, const char *field, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
/* Names the field of an error already set (NULL: none); returns err->code (TIPPE_OK if
 * err is NULL). */
int tippe_error_blame(tippe_error *err, const char *field);

/* Turns GSL's abort-on-error handler off, once per process and thread-safely:
 * every library entry point that calls GSL calls this first, and then checks
 * GSL's return codes itself (GSL's default handler would abort the process). */
void tippe_gsl_errors_as_codes(void);

/* ==== files read ==== */
/* The whole of an input file in memory (NUL-terminated; *out_len bytes before
 * the NUL; the caller frees *out): a regular file only (a FIFO, a device or a
 * directory is refused without blocking), at most max_bytes (refused above),
 * what naming the kind of file in messages ("design", "G-code"). Every file
 * the library reads comes through here. */
int tippe_file_read(const char *path, size_t max_bytes, const char *what, char **out,
                    size_t *out_len, tippe_error *err);

/* A check made before any input file is read: 0 to read it, or a status with
 * err set to refuse it. The command uses it to refuse an output that names a
 * file the run reads however the file is reached (a design's materials table, a
 * spec's catalogue or base design, a part's G-code). NULL (the default): every
 * file is read. The check may be called from several threads at once. */
typedef int (*tippe_file_read_check)(const char *path, const char *what, tippe_error *err);
void tippe_file_set_read_check(tippe_file_read_check check);

/* ---- the shipped data ---- */
/* The folder of the shipped designs and tables (materials.json, catalogue.json,
 * scenarios/, slicer/) into buf: in a build tree, the checkout's designs/; else
 * the installed PREFIX/share/tippe/designs, found from the file running this code
 * (the tippe command in PREFIX/bin or libtippe.so in PREFIX/lib/...: an install
 * moved elsewhere still finds its data), else the configured prefix's. Returns
 * 1 if found, 0 if none holds materials.json (buf then lists where it looked). */
int tippe_file_shipped_dir(char *buf, size_t size);
/* ---- paths (src/base/path.c) ---- */
/* Every file a file names (a design's materials table, catalogue and G-code, a
 * scenario's design, a spec's base design) is found relative to the folder of
 * the file that names it; these say that once. */
/* The name after the last '/' (a pointer into path). */
const char *tippe_path_base(const char *path);
/* The folder of path: "." for a bare name, "/" for a file at the root.
 * TIPPE_EINPUT (out cut) when it does not fit in size. */
int tippe_path_dir(const char *path, char *out, size_t size);
/* name as seen from the folder of the file path: name itself when it is
 * absolute or path has no folder, else "FOLDER/name". TIPPE_EINPUT (out cut)
 * when it does not fit in size. */
int tippe_path_beside(const char *path, const char *name, char *out, size_t size);
/* The name without its folder and last extension ("m12-setscrew" for
 * "designs/m12-setscrew.json"; ".json" stays ".json"). */
void tippe_path_stem(const char *path, char *out, size_t size);
/* The extension after the name's last '.', without the dot; "" if none. */
const char *tippe_path_ext(const char *path);

/* ---- reports and safe files ---- */
/* Report: output files that appear whole or not at all, and never
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
 * verb's outputs are all written or none is (src/cli/outputs.c).
 *
 * Signals: every temporary is recorded in a table (as large as the files open
 * at once need: it grows in blocks that never move) that
 * tippe_report_remove_temporaries() empties with unlink() only, so that a
 * signal handler may call it (the command's handler, src/cli/signals.c).
 * Outputs are written from one thread. */

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

/* For a writer that gave up (a library's status said so): aborts rf and sets
 * err (TIPPE_ECOMPUTE) to why it failed: "PATH: writing WHAT failed: REASON"
 * when a write to rf->f failed (a full disk: "No space left on device"), else
 * "PATH: " and the writer's own words, why ("cairo could not write the
 * drawing"). Returns TIPPE_ECOMPUTE. */
int tippe_report_fail(tippe_report_file *rf, tippe_error *err, const char *why);

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

/* ---- cancel ---- */
/* Cancel: a long computation stopped from outside (tippe serve: a request past
 * its budget, or whose client has gone). A thread names a flag it watches; the
 * library's long loops (each step of a launch's integration, each tolerance of a
 * sweep's bands, each change the build's advice tries, each frame of a film, each
 * file of an export) check it and fail with TIPPE_ECOMPUTE "cancelled" once it is
 * set, well within a second. The command watches none: nothing is ever
 * cancelled there (its Ctrl-C ends the process). OpenMP threads a loop starts do
 * not inherit the watch; the loop that starts them checks it between them. */

/* This thread's flag (NULL: none); the previous one is returned. */
const volatile int *tippe_cancel_watch(const volatile int *flag);
/* Nonzero once this thread's flag is set. */
int tippe_cancel_requested(void);
/* err set to "cancelled" (TIPPE_ECOMPUTE); returns TIPPE_ECOMPUTE. */
int tippe_cancel_error(tippe_error *err);

/* ---- progress ---- */
/* Progress: progress of long loops with a time-left estimate.
 *
 * On a terminal it is a bar redrawn in place (at most ~5 times a second). On
 * anything else (a pipe, a file, a CI log) a redrawn bar would be noise, so:
 * with TIPPE_PROGRESS_AUTO nothing is shown there, and with TIPPE_PROGRESS_ON
 * (the command's --progress) plain lines are written instead,
 *     tippe map: 1200/16000 (7.5%), 3 min 05 s left
 * one when another tenth of the work is done or 30 s have passed since the
 * last line (never more than one per 2 s), and a last line when it finishes.
 * tippe_progress_add() may be called from any number of OpenMP threads at once;
 * it costs one critical section, nothing measurable next to a launch. */

enum { TIPPE_PROGRESS_OFF = 0, TIPPE_PROGRESS_ON = 1, TIPPE_PROGRESS_AUTO = -1 };

typedef struct {
    FILE *out;
    int enabled;
    char label[48];
    long total, done;
    double t_start, t_last_draw; /* s, monotonic clock */
    int drawn;                   /* 1 once a line was drawn (it must be finished) */
    int plain;                   /* 1: plain lines (not a terminal), 0: a bar */
    long done_at_last_line;      /* plain lines: units done at the last line */
} tippe_progress;

/* Starts a bar for `total` units of work. enabled: TIPPE_PROGRESS_ON (a bar
 * on a terminal, plain lines elsewhere), _OFF or _AUTO (a bar on a terminal,
 * nothing elsewhere). out may be NULL (then off). */
void tippe_progress_start(tippe_progress *p, FILE *out, const char *label, long total,
                          int enabled);

/* Records n more units done; thread-safe. p may be NULL. */
void tippe_progress_add(tippe_progress *p, long n);

/* Draws the final state (if anything was drawn) and ends the line. p may be NULL. */
void tippe_progress_finish(tippe_progress *p);

/* Seconds left at the average rate so far: elapsed_s (total - done) / done;
 * negative when nothing is done yet (no estimate). Pure, for tests. */
double tippe_progress_eta_s(double elapsed_s, long done, long total);

/* Formats a duration as "42 s", "3 min 05 s" or "2 h 07 min" into buf. */
char *tippe_progress_format_duration(double s, char *buf, size_t size);

#endif
