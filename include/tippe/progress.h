/* tippe/progress.h: progress of long loops with a time-left estimate.
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
