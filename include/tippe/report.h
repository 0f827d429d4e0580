/* tippe/report.h: output files (CSV tables, plots) that appear whole or not at all.
 *
 * A report file is written to a temporary file next to its target and renamed
 * into place by tippe_report_commit(), so a reader never sees a half-written
 * file and a failed run leaves nothing behind (not even the temporary). The
 * finished file gets the permissions fopen() would give it (0666 less the
 * umask), not mkstemp()'s private 0600.
 *
 *     tippe_report_file rf;
 *     if ((rc = tippe_report_open(&rf, path, "the CSV file", err)) != 0) return rc;
 *     fprintf(rf.f, ...);
 *     return tippe_report_commit(&rf, err);    // or tippe_report_abort(&rf)
 *
 * A writer that closes the stream itself (PLplot's plend() closes the FILE it
 * was given by plsfile()) sets rf.f to NULL once it has taken it over; commit
 * and abort then only rename or remove the temporary. */
#ifndef TIPPE_REPORT_H
#define TIPPE_REPORT_H

#include <stdio.h>

#include "tippe/error.h"

typedef struct {
    FILE *f;                /* write here; NULL once closed or taken over */
    const char *what;       /* "the CSV file", "the plot": for messages */
    char path[4096];        /* the target */
    char tmp_path[4096 + 16];
} tippe_report_file;

/* Creates the temporary for path. what (a string that outlives rf) names the
 * file in messages. TIPPE_EINPUT if the path is too long or its directory
 * cannot be written ("PATH: cannot write WHAT here: REASON"), TIPPE_ECOMPUTE if
 * the stream cannot be set up. On failure nothing is left on disk. */
int tippe_report_open(tippe_report_file *rf, const char *path, const char *what,
                      tippe_error *err);

/* Closes rf->f (unless NULL) and renames the temporary into place. On a write
 * or rename error (TIPPE_ECOMPUTE) the temporary is removed. */
int tippe_report_commit(tippe_report_file *rf, tippe_error *err);

/* Closes rf->f (unless NULL) and removes the temporary. */
void tippe_report_abort(tippe_report_file *rf);

#endif
