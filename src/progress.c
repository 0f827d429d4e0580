/* A progress bar on a terminal, shared by OpenMP threads (tippe/progress.h). */
#include "tippe/progress.h"

#include <math.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

/* Redraw no more often than this: a terminal write per launch would be noise. */
#define REDRAW_S 0.2

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
    if (enabled == TIPPE_PROGRESS_AUTO)
        enabled = out && isatty(fileno(out));
    p->enabled = out && enabled && total > 0;
    snprintf(p->label, sizeof p->label, "%s", label ? label : "");
    p->total = total;
    p->t_start = p->t_last_draw = now_s();
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
    char left[48], spent[24];
    const double eta = tippe_progress_eta_s(t - p->t_start, p->done, p->total);
    tippe_progress_format_duration(t - p->t_start, spent, sizeof spent);
    if (p->done >= p->total)
        snprintf(left, sizeof left, "done in %s", spent);
    else if (eta < 0)
        snprintf(left, sizeof left, "estimating time left");
    else {
        char d[24];
        snprintf(left, sizeof left, "%s left", tippe_progress_format_duration(eta, d, sizeof d));
    }
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
            if (t - p->t_last_draw >= REDRAW_S || !p->drawn)
                draw(p, t);
        }
    }
}

void tippe_progress_finish(tippe_progress *p)
{
    if (!p || !p->enabled)
        return;
#pragma omp critical(tippe_progress)
    {
        draw(p, now_s());
        fputc('\n', p->out);
        fflush(p->out);
        p->enabled = 0;
    }
}
