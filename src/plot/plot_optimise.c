/* The optimiser's plot: zones of the best designs and the convergence. */
#include "tippe/optimise.h"
#include "plot/canvas.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_SHOWN 10

/* The zone plot's shades, one per main group. */
static unsigned family_rgb(tippe_group g)
{
    const char *f = tippe_group_family(g);
    return !strcmp(f, "I") ? 0x3f6fb5u : !strcmp(f, "II") ? 0x3a9a46u : 0xf08c3cu;
}

static const unsigned line_rgb[MAX_SHOWN] = {0x1f4fd0u, 0xd01c1cu, 0x2a9a2au, 0x8e2ac0u,
                                             0x9a6a1eu, 0x000000u, 0x36b3a8u, 0xf08c3cu,
                                             0x777777u, 0xc0317au};

/* The best MAX_SHOWN choices as the search ranks them, best first (lower index
 * first on a tie). */
static int order_choices(const tippe_optimise_result *r, int *idx)
{
    int n = 0;
    for (int c = 0; c < r->n_choices; c++) {
        int k = n;
        while (k > 0 && tippe_optimise_rank_above(&r->choices[c].best, &r->choices[idx[k - 1]].best))
            k--;
        if (k >= MAX_SHOWN)
            continue;
        for (int m = (n < MAX_SHOWN ? n : MAX_SHOWN - 1); m > k; m--)
            idx[m] = idx[m - 1];
        idx[k] = c;
        if (n < MAX_SHOWN)
            n++;
    }
    return n;
}

static void zone_bars(const tippe_optimise_spec *s, const tippe_optimise_result *r, const int *idx, int n,
                      tippe_sweep_result *sw, const int *ok)
{
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < n; i++)
        if (ok[i]) {
            lo = fmin(lo, sw[i].from_mm);
            hi = fmax(hi, sw[i].to_mm);
        }
    if (!(lo < hi))
        lo = 0, hi = 1;
    double pad = 0.03 * (hi - lo), ymax = n - 0.5 + 0.9; /* room for the legend */
    tippe_plot_panel(0.05, 0.60, 0.12, 0.86, lo - pad, hi + pad, -0.5, ymax);
    for (int i = 0; i < n; i++) {
        double y = n - 1 - i; /* best at the top */
        char label[256], esc[300], text[600];
        tippe_optimise_spec_choice_label(s, idx[i], label, sizeof label);
        tippe_plot_escape(label, esc, sizeof esc);
        const tippe_optimise_eval *e = &r->choices[idx[i]].best;
        char robust[64] = "";
        if (e->has_robust)
            snprintf(robust, sizeof robust, ", robust %.3f", e->robust_mm);
        snprintf(text, sizeof text, "%s: narrowest %.3f mm (I %.3f, II %.3f, III %.3f)%s%s", esc,
                 e->objective_mm, e->zone_mm[0], e->zone_mm[1], e->zone_mm[2], robust,
                 e->status == TIPPE_OPTIMISE_OK ? "" : " infeasible");
        tippe_plot_text(lo, y + 0.2, 0, 0.0, 0.7, line_rgb[i], text); /* as its convergence line */
        if (!ok[i])
            continue;
        for (int z = 0; z < sw[i].n_zones; z++) {
            const tippe_sweep_zone *zn = &sw[i].zones[z];
            if (!zn->within_travel)
                continue;
            tippe_plot_rect(zn->z2_from_mm, zn->z2_to_mm, y - 0.38, y + 0.08,
                            tippe_plot_pale(family_rgb(zn->group), 0.75), 1.0);
        }
    }
    tippe_plot_axes_x("Z#d2#u within the physical travel (mm)",
                      "zones of the best design of each choice (best at the top)");
    tippe_plot_key keys[3] = {
        {TIPPE_PLOT_KEY_BOX, "group I", tippe_plot_pale(0x3f6fb5u, 0.75), 1, 0, 0},
        {TIPPE_PLOT_KEY_BOX, "group II", tippe_plot_pale(0x3a9a46u, 0.75), 1, 0, 0},
        {TIPPE_PLOT_KEY_BOX, "group III", tippe_plot_pale(0xf08c3cu, 0.75), 1, 0, 0}};
    tippe_plot_legend(keys, 3, "tr", 3, 0.7);
}

static void convergence(const tippe_optimise_result *r, const int *idx, int n)
{
    long nmax = 1;
    double top = 0.0;
    for (int i = 0; i < n; i++) {
        const tippe_optimise_choice_result *c = &r->choices[idx[i]];
        nmax = c->n_evals > nmax ? c->n_evals : nmax;
        if (c->n_evals)
            top = fmax(top, c->best_so_far[c->n_evals - 1]);
    }
    double ytop = top > 0 ? 1.1 * top : 1.0;
    tippe_plot_panel(0.69, 0.97, 0.12, 0.86, 1.0, (double)nmax, 0.0, ytop);
    tippe_plot_grid();
    for (int i = n - 1; i >= 0; i--) {
        const tippe_optimise_choice_result *c = &r->choices[idx[i]];
        double *x = malloc((size_t)c->n_evals * sizeof *x);
        double *y = malloc((size_t)c->n_evals * sizeof *y);
        int m = 0;
        for (long k = 0; x && y && k < c->n_evals; k++)
            if (c->best_so_far[k] >= 0) { /* feasible so far; infeasible scores are < 0 */
                x[m] = (double)(k + 1);
                y[m++] = c->best_so_far[k];
            }
        if (m > 1)
            tippe_plot_line(m, x, y, line_rgb[i], i == 0 ? 2.0 : 1.0, TIPPE_PLOT_SOLID);
        if (c->n_global > 0 && c->n_global < c->n_evals && i == 0) {
            double vx[2] = {(double)c->n_global, (double)c->n_global}, vy[2] = {0, ytop};
            tippe_plot_line(2, vx, vy, 0x777777u, 1.0, TIPPE_PLOT_DASHED);
            /* left of the line, off it and off the right axis (the polish often starts
             * near the last evaluation) */
            tippe_plot_text(fmax((double)c->n_global - 0.03 * (double)nmax, 0.04 * nmax),
                            0.04 * ytop, 90, 0.0, 0.6, 0x555555u, "polish starts");
        }
        free(x);
        free(y);
    }
    tippe_plot_axes("evaluations", "best narrowest zone so far (mm)",
                    "convergence (colours as the labels)");
}

int tippe_optimise_plot(const char *file, const tippe_optimise_spec *s, const tippe_optimise_result *r,
                   tippe_error *err)
{
    int idx[MAX_SHOWN], ok[MAX_SHOWN];
    int n = order_choices(r, idx);
    tippe_sweep_result sw[MAX_SHOWN];
    memset(sw, 0, sizeof sw);
    for (int i = 0; i < n; i++) {
        tippe_error e = {0};
        ok[i] = r->choices[idx[i]].best.status != TIPPE_OPTIMISE_DOES_NOT_FIT &&
                tippe_optimise_sweep(s, &r->choices[idx[i]].best, &sw[i], &e) == TIPPE_OK;
    }
    tippe_plot *p = NULL;
    int st = tippe_plot_open(file, 1300, 140 + 64 * (n < 6 ? 6 : n), &p, err);
    if (st == TIPPE_OK) {
        char title[600], esc[520];
        tippe_plot_escape(tippe_optimise_spec_path(s), esc, sizeof esc);
        snprintf(title, sizeof title, "tippe optimise %s: widest narrowest zone", esc);
        zone_bars(s, r, idx, n, sw, ok);
        convergence(r, idx, n);
        tippe_plot_page_title(title, 1.0); /* last: it restores the current panel */
        st = tippe_plot_close(p, err);
    }
    for (int i = 0; i < n; i++)
        tippe_sweep_result_free(&sw[i]);
    return st;
}
