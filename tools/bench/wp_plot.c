/* wp_plot: the work-precision figure of one scenario from the benchmark's CSV
 * files: achieved error (x) against wall time (y), both log10, one line per
 * stepper (tippe's GSL steppers solid, SciPy's methods dashed), points at each
 * tolerance, rows that are not "ok" left out.
 *
 *   usage: wp_plot OUT.png SCENARIO FILE.csv [FILE.csv ...] */
#include "plot/canvas.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_PTS = 4096, MAX_SERIES = 24, MAX_FIELDS = 32 };

typedef struct {
    char tool[16], stepper[16];
    int n;
    double x[32], y[32]; /* log10 err, log10 time */
} series;

/* Splits line at commas in place (empty fields kept). */
static int split(char *line, char **f, int max)
{
    int n = 0;
    char *p = line;
    while (n < max) {
        f[n++] = p;
        char *c = strchr(p, ',');
        if (!c)
            break;
        *c = '\0';
        p = c + 1;
    }
    char *nl = strpbrk(f[n - 1], "\r\n");
    if (nl)
        *nl = '\0';
    return n;
}

int main(int argc, char **argv)
{
    if (argc < 4) {
        fprintf(stderr, "usage: wp_plot OUT.png SCENARIO FILE.csv [FILE.csv ...]\n");
        return 2;
    }
    static series S[MAX_SERIES];
    int ns = 0;
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
    for (int a = 3; a < argc; a++) {
        FILE *f = fopen(argv[a], "r");
        if (!f) {
            fprintf(stderr, "wp_plot: cannot read %s\n", argv[a]);
            return 2;
        }
        char line[2048];
        int first = 1;
        while (fgets(line, sizeof line, f)) {
            if (first) { /* header: columns as written by work_precision */
                first = 0;
                continue;
            }
            char *fl[MAX_FIELDS];
            int nf = split(line, fl, MAX_FIELDS);
            /* tool,scenario,stepper,rtol,status,time_s,rhs_evals,steps,rejected,err */
            if (nf < 10 || strcmp(fl[1], argv[2]) || strcmp(fl[4], "ok"))
                continue;
            const double t = atof(fl[5]), e = atof(fl[9]);
            if (!(t > 0) || !(e > 0))
                continue;
            int k;
            for (k = 0; k < ns; k++)
                if (!strcmp(S[k].tool, fl[0]) && !strcmp(S[k].stepper, fl[2]))
                    break;
            if (k == ns) {
                if (ns == MAX_SERIES)
                    continue;
                snprintf(S[ns].tool, sizeof S[ns].tool, "%s", fl[0]);
                snprintf(S[ns].stepper, sizeof S[ns].stepper, "%s", fl[2]);
                ns++;
            }
            if (S[k].n < 32) {
                S[k].x[S[k].n] = log10(e);
                S[k].y[S[k].n] = log10(t);
                xmin = fmin(xmin, S[k].x[S[k].n]);
                xmax = fmax(xmax, S[k].x[S[k].n]);
                ymin = fmin(ymin, S[k].y[S[k].n]);
                ymax = fmax(ymax, S[k].y[S[k].n]);
                S[k].n++;
            }
        }
        fclose(f);
    }
    if (ns == 0) {
        fprintf(stderr, "wp_plot: no rows for scenario %s\n", argv[2]);
        return 1;
    }
    tippe_plot *p;
    tippe_error err;
    if (tippe_plot_open(argv[1], 1000, 700, &p, &err)) {
        fprintf(stderr, "wp_plot: %s\n", err.msg);
        return 1;
    }
    static const unsigned colours[] = {0x1f77b4, 0xd62728, 0x2ca02c, 0xff7f0e, 0x9467bd,
                                       0x8c564b, 0xe377c2, 0x7f7f7f, 0xbcbd22, 0x17becf,
                                       0x000000, 0x393b79};
    const int n_col = (int)(sizeof colours / sizeof colours[0]);
    tippe_plot_panel(0.09, 0.74, 0.10, 0.90, floor(xmin) - 0.2, ceil(xmax) + 0.2,
                     floor(ymin * 2) / 2 - 0.1, ceil(ymax * 2) / 2 + 0.1);
    tippe_plot_grid();
    char title[256];
    snprintf(title, sizeof title, "work-precision: %s (one core)", argv[2]);
    tippe_plot_axes("log#d10#u error (max over 4 times of |#gh-#gh#dref#u| and |n-n#dref#u|/W)",
                    "log#d10#u wall time (s)", title);
    tippe_plot_key keys[MAX_SERIES];
    char labels[MAX_SERIES][40];
    int n_tippe = 0, n_scipy = 0;
    for (int k = 0; k < ns; k++) {
        const int scipy = !strcmp(S[k].tool, "scipy");
        const unsigned rgb = scipy ? (n_scipy++ ? 0x555555 : 0x000000) : colours[n_tippe++ % n_col];
        const int style = scipy ? TIPPE_PLOT_DASHED : TIPPE_PLOT_SOLID;
        tippe_plot_line(S[k].n, S[k].x, S[k].y, rgb, 1.6, style);
        tippe_plot_points(S[k].n, S[k].x, S[k].y, scipy ? 4 : 17, 1.0, rgb);
        snprintf(labels[k], sizeof labels[k], "%s%s", scipy ? "SciPy " : "", S[k].stepper);
        keys[k] = (tippe_plot_key){TIPPE_PLOT_KEY_LINE, labels[k], rgb, 1.0, 1.6, style};
    }
    tippe_plot_legend(keys, ns, "outside", 1, 0.8);
    return tippe_plot_close(p, &err) ? (fprintf(stderr, "wp_plot: %s\n", err.msg), 1) : 0;
}
