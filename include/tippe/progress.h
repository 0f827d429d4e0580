/* tippe/progress.h: a progress bar with a time-left estimate, for long loops.
 *
 * The bar is drawn on a stream (stderr in the tippe command) only when it is
 * enabled; tippe_progress_start() with TIPPE_PROGRESS_AUTO enables it exactly
 * when the stream is a terminal, so that pipes, files and test logs stay quiet.
 * tippe_progress_add() may be called from any number of OpenMP threads at once;
 * redraws are throttled (at most ~5 per second) so that the bar costs nothing
 * measurable next to a launch. */
#ifndef TIPPE_PROGRESS_H
#define TIPPE_PROGRESS_H

#include <stdio.h>

enum { TIPPE_PROGRESS_OFF = 0, TIPPE_PROGRESS_ON = 1, TIPPE_PROGRESS_AUTO = -1 };

typedef struct {
    FILE *out;
    int enabled;
    char label[48];
    long total, done;
    double t_start, t_last_draw; /* s, monotonic clock */
    int drawn;                   /* 1 once a line was drawn (it must be finished) */
} tippe_progress;

/* Starts a bar for `total` units of work. enabled: TIPPE_PROGRESS_ON, _OFF or
 * _AUTO (on iff out is a terminal). out may be NULL (then off). */
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
