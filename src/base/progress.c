/* Progress as a bar on a terminal or plain lines elsewhere, shared by OpenMP
 * threads (tippe/base.h). */
#include "tippe/base.h"

#include <math.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

/* Redraw no more often than this: a terminal write per launch would be noise. */
#define REDRAW_S 0.2
/* Plain lines: one per tenth of the work or per LINE_EVERY_S, at most one per
 * LINE_MIN_S, so that a log shows the work moving without filling up. */
#define LINE_EVERY_S 30.0
#define LINE_MIN_S 2.0

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double tippe_progress_eta_s(double elapsed_s, long done, long total)
{
    if (done <= 0 || total <= 0)
        return -1.0;
    if (done >= total)
        return 0.0;
    return elapsed_s * (double)(total - done) / (double)done;
}

char *tippe_progress_format_duration(double s, char *buf, size_t size)
{
    if (!(s >= 0) || !isfinite(s))
        snprintf(buf, size, "?");
    else if (s < 59.5)
        snprintf(buf, size, "%.0f s", s);
    else if (s < 3599.5) {
        long t = lround(s);
        snprintf(buf, size, "%ld min %02ld s", t / 60, t % 60);
    } else {
        long t = lround(s / 60.0);
        snprintf(buf, size, "%ld h %02ld min", t / 60, t % 60);
    }
    return buf;
}

void tippe_progress_start(tippe_progress *p, FILE *out, const char *label, long total,
                          int enabled)
{
    memset(p, 0, sizeof *p);
    p->out = out;
    const int terminal = out && isatty(fileno(out));
    if (enabled == TIPPE_PROGRESS_AUTO)
        enabled = terminal;
    p->enabled = out && enabled && total > 0;
    p->plain = !terminal;
    snprintf(p->label, sizeof p->label, "%s", label ? label : "");
    p->total = total;
    p->t_start = p->t_last_draw = now_s();
}

/* "3 min 05 s left", "done in 42 s" or "estimating time left" into buf. */
static void time_text(const tippe_progress *p, double t, char *buf, size_t size)
{
    char d[24];
    const double eta = tippe_progress_eta_s(t - p->t_start, p->done, p->total);
    if (p->done >= p->total)
        snprintf(buf, size, "done in %s",
                 tippe_progress_format_duration(t - p->t_start, d, sizeof d));
    else if (eta < 0)
        snprintf(buf, size, "estimating time left");
    else
        snprintf(buf, size, "%s left", tippe_progress_format_duration(eta, d, sizeof d));
}

/* One plain line: "LABEL: DONE/TOTAL (PCT%), TIME". */
static void draw_line(tippe_progress *p, double t)
{
    char left[48];
    time_text(p, t, left, sizeof left);
    fprintf(p->out, "%s: %ld/%ld (%.1f%%), %s\n", p->label, p->done, p->total,
            100.0 * (double)p->done / (double)p->total, left);
    fflush(p->out);
    p->t_last_draw = t;
    p->done_at_last_line = p->done;
}

/* Whether a plain line is due at t: another tenth done or LINE_EVERY_S passed. */
static int line_due(const tippe_progress *p, double t)
{
    const double since = t - p->t_last_draw;
    if (since < LINE_MIN_S)
        return 0;
    return since >= LINE_EVERY_S || 10 * (p->done - p->done_at_last_line) >= p->total;
}

static void draw(tippe_progress *p, double t)
{
    enum { WIDTH = 30 };
    const double frac = p->total > 0 ? (double)p->done / (double)p->total : 1.0;
    char bar[WIDTH + 1];
    const int full = (int)(frac * WIDTH);
    for (int i = 0; i < WIDTH; i++)
        bar[i] = i < full ? '#' : '.';
    bar[WIDTH] = '\0';
    char left[48];
    time_text(p, t, left, sizeof left);
    /* \r and a clear-to-end-of-line so that a shorter line leaves no residue. */
    fprintf(p->out, "\r%s [%s] %3.0f%% %ld/%ld, %s\033[K", p->label, bar, 100.0 * frac, p->done,
            p->total, left);
    fflush(p->out);
    p->drawn = 1;
    p->t_last_draw = t;
}

void tippe_progress_add(tippe_progress *p, long n)
{
    if (!p)
        return;
#pragma omp critical(tippe_progress)
    {
        p->done += n;
        if (p->enabled) {
            const double t = now_s();
            if (p->plain) {
                if (line_due(p, t))
                    draw_line(p, t);
            } else if (t - p->t_last_draw >= REDRAW_S || !p->drawn) {
                draw(p, t);
            }
        }
    }
}

void tippe_progress_finish(tippe_progress *p)
{
    if (!p || !p->enabled)
        return;
#pragma omp critical(tippe_progress)
    {
        if (p->plain) {
            draw_line(p, now_s());
        } else {
            draw(p, now_s());
            fputc('\n', p->out);
            fflush(p->out);
        }
        p->enabled = 0;
    }
}
