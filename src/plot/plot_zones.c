/* Plots of a sweep: zones along Z2 (Figures 7, 9, 11), the phase diagram with
 * the design's path (Figure 2), and the zones of a vary. See tippe/sweep.h. */
#include "plot/canvas.h"
#include "tippe/sweep.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Colours: the paper's blue A/C - 1, black +-eps/R, red -(eps/R)^2; b curves
 * and zones in colours of their own. */
#define C_PATH 0x1f4fd0u
#define C_E 0x000000u
#define C_E2 0xd01c1cu
#define C_BPLUS 0x8e2ac0u
#define C_BMINUS 0x9a6a1eu
#define C_TRAVEL 0x555555u
#define C_INVALID 0xC00000u /* a part stands out of the sphere: the model does not apply */
#define C_COLLIDE 0x8a5a00u /* a --vary step whose parts collide: not swept */
#define C_BAND 0x202020u
#define BAND_ALPHA 0.30

static unsigned group_rgb(tippe_group g)
{
    switch (g) {
    case TIPPE_GROUP_IA: return 0x3f6fb5u;
    case TIPPE_GROUP_IB: return 0x7fb2e5u;
    case TIPPE_GROUP_IIA: return 0x3a9a46u;
    case TIPPE_GROUP_IIB: return 0xb5d65au;
    case TIPPE_GROUP_IIC: return 0x36b3a8u;
    case TIPPE_GROUP_III: return 0xf08c3cu;
    }
    return 0x999999u;
}

#define SHADE 0.42

static const char *const group_text[] = {
    "Ia: no tipping",          "Ib: no tipping",        "IIa: tipping (branch folds)",
    "IIb: tipping or hanging", "IIc: complete tipping", "III: hanging only",
};

/* A/C at which b = sign (+1 or -1) for eps/R = e: eq 5.11 squared,
 * sqrt(k (1 - k - e^2) / 3) = e -+ u with u = 1 - k, is the quadratic
 *   4 u^2 - (1 + e^2 + 6 sign e) u + 4 e^2 = 0;
 * roots are kept where b is real and tippe_theory_classify confirms b = sign. */
static int k_where_b(double e, int sign, double k_out[2])
{
    double p = 1.0 + e * e + 6.0 * sign * e, disc = p * p - 64.0 * e * e;
    if (disc < 0.0)
        return 0;
    int n = 0;
    /* The larger root directly, the smaller from the product of the roots (e^2),
     * which avoids cancellation when e is small. */
    double big = (p + sqrt(disc)) / 8.0;
    double u[2] = {big > 0.0 ? e * e / big : 0.0, big};
    for (int i = 0; i < 2; i++) {
        double k = 1.0 - u[i];
        tippe_theory_class c;
        if (!(k > 0.0) || u[i] < e * e || tippe_theory_classify(k, e, &c) != TIPPE_OK || !c.has_b)
            continue;
        if (fabs(c.b - sign) > 1e-6 * (1.0 + fabs(c.b)))
            continue;
        if (n == 1 && fabs(k - k_out[0]) < 1e-12)
            continue;
        k_out[n++] = k;
    }
    if (n == 2 && k_out[0] > k_out[1]) {
        double t = k_out[0];
        k_out[0] = k_out[1];
        k_out[1] = t;
    }
    return n;
}

/* Draws y(x) where valid, as separate polylines over the gaps. */
static void line_where(int n, const double *x, const double *y, const int *ok, unsigned rgb,
                       double width, int style)
{
    int i = 0;
    while (i < n) {
        while (i < n && !ok[i])
            i++;
        int j = i;
        while (j < n && ok[j])
            j++;
        if (j - i >= 2)
            tippe_plot_line(j - i, x + i, y + i, rgb, width, style);
        i = j;
    }
}

static void fmt_mm(char *buf, size_t n, double v)
{
    snprintf(buf, n, "%.2f", fabs(v) < 5e-3 ? 0.0 : v);
}

/* ---- zone plot ------------------------------------------------------------ */

enum { NS = 1200 };

int tippe_sweep_plot_zones(const char *file, const tippe_sweep_path *path,
                           const tippe_sweep_result *r, const char *title, tippe_error *err)
{
    return tippe_sweep_plot_zones_banded(file, path, r, NULL, title, err);
}

/* The zone plot's frame: the path's A/C - 1 and +-e/R sampled along Z2, the
 * y window, and the panel's scale. */
typedef struct {
    double z[NS], km1[NS], ep[NS];
    double ymin, ymax, xspan, px_per_mm;
    double curve[3][NS]; /* room for the boundary curves */
    int ok[3][NS];
} zone_frame;

static void frame_sample(const tippe_sweep_path *path, const tippe_sweep_result *r,
                         zone_frame *f)
{
    f->ymin = INFINITY;
    f->ymax = -INFINITY;
    for (int i = 0; i < NS; i++) {
        f->z[i] = r->from_mm + (r->to_mm - r->from_mm) * i / (NS - 1);
        double k, es;
        path->eval(f->z[i], path->params, &k, &es);
        f->km1[i] = k - 1.0;
        f->ep[i] = fabs(es);
        f->ymin = fmin(f->ymin, fmin(f->km1[i], -f->ep[i]));
        f->ymax = fmax(f->ymax, fmax(f->km1[i], f->ep[i]));
    }
    double pad = 0.08 * (f->ymax - f->ymin);
    if (!(pad > 0))
        pad = 0.01;
    f->ymin -= pad;
    f->ymax += 2.2 * pad; /* room for the zone labels */
    f->xspan = r->to_mm - r->from_mm;
}

/* Red hatching where a part stands out of the sphere (outside the sphere-only
 * interval) within the physical travel (beyond it is hatched already): the top
 * rests on the part there and the model does not apply. 1 if any. */
static int draw_invalid_hatch(const tippe_sweep_result *r, const zone_frame *f)
{
    if (!r->has_sphere_only)
        return 0;
    double lo = r->from_mm, hi = r->to_mm;
    if (r->has_travel) {
        lo = fmax(lo, r->travel_from_mm);
        hi = fmin(hi, r->travel_to_mm);
    }
    const double a = r->sphere_only_from_mm, b = r->sphere_only_to_mm;
    double x0[2] = {lo, fmax(b, lo)}, x1[2] = {fmin(a, hi), hi};
    if (a > b) {
        x1[0] = hi;
        x0[1] = hi;
    }
    int any = 0;
    for (int k = 0; k < 2; k++)
        if (x1[k] > x0[k]) {
            tippe_plot_hatch(x0[k], x1[k], f->ymin, f->ymax, C_INVALID);
            any = 1;
        }
    return any;
}

/* Red hatching over the part of zone zn where a part stands out of the sphere,
 * across [a, b] of the other axis (Z2 along x when z2_on_x, else along y). */
static int hatch_invalid_zone(const tippe_sweep_result *r, const tippe_sweep_zone *zn, double a,
                              double b, int z2_on_x)
{
    double f[2], t[2];
    int n = tippe_sweep_zone_model_invalid(r, zn, f, t);
    for (int k = 0; k < n; k++) {
        if (z2_on_x)
            tippe_plot_hatch(f[k], t[k], a, b, C_INVALID);
        else
            tippe_plot_hatch(a, b, f[k], t[k], C_INVALID);
    }
    return n > 0;
}

/* Each zone shaded in its group's colour, and hatching beyond the physical
 * travel; present[g] set for the groups shown. 1 if any hatching. */
static int draw_zone_shading(const tippe_sweep_result *r, const zone_frame *f, int present[6])
{
    for (int i = 0; i < r->n_zones; i++) {
        const tippe_sweep_zone *zn = &r->zones[i];
        present[zn->group] = 1;
        tippe_plot_rect(zn->z2_from_mm, zn->z2_to_mm, f->ymin, f->ymax,
                        tippe_plot_pale(group_rgb(zn->group), SHADE), 1.0);
    }
    int beyond = 0;
    if (r->has_travel && r->travel_from_mm > r->from_mm) {
        tippe_plot_hatch(r->from_mm, fmin(r->travel_from_mm, r->to_mm), f->ymin, f->ymax,
                         C_TRAVEL);
        beyond = 1;
    }
    if (r->has_travel && r->travel_to_mm < r->to_mm) {
        tippe_plot_hatch(fmax(r->travel_to_mm, r->from_mm), r->to_mm, f->ymin, f->ymax, C_TRAVEL);
        beyond = 1;
    }
    return beyond;
}

/* The tolerance bands, shaded once where several overlap (stacked shades would
 * hide the zone beneath). 1 if any band was drawn. */
static int draw_band_shading(const tippe_sweep_result *r, const tippe_sweep_bands_result *b,
                             const zone_frame *f)
{
    double *lo = b && b->n > 0 ? malloc(2 * (size_t)b->n * sizeof *lo) : NULL;
    if (!lo)
        return 0;
    double *hi = lo + b->n;
    int nb = 0;
    for (int i = 0; i < b->n; i++) {
        double w = b->bands[i].band_mm, x = b->bands[i].z2_mm;
        if (!(w > 0))
            continue;
        w = isfinite(w) ? w : f->xspan;
        lo[nb] = fmax(r->from_mm, x - w);
        hi[nb++] = fmin(r->to_mm, x + w);
    }
    /* bands come in order of Z2 and have similar widths; merge by sweep */
    for (int i = 0; i < nb;) {
        double a = lo[i], e = hi[i];
        int j = i + 1;
        while (j < nb && lo[j] <= e) {
            a = fmin(a, lo[j]);
            e = fmax(e, hi[j]);
            j++;
        }
        tippe_plot_rect(a, e, f->ymin, f->ymax, C_BAND, BAND_ALPHA);
        i = j;
    }
    free(lo);
    return nb > 0;
}

/* Zone ends: a thin line and the Z2 value along it, skipping values that would
 * overprint the previous one. */
static void draw_zone_ends(const tippe_sweep_result *r, const zone_frame *f)
{
    double last_px = -1e9;
    for (int i = 0; i + 1 < r->n_zones; i++) {
        double x = r->zones[i].z2_to_mm;
        double lx[2] = {x, x}, ly[2] = {f->ymin, f->ymax};
        tippe_plot_line(2, lx, ly, 0x606060u, 0.6, TIPPE_PLOT_SOLID);
        double px = (x - r->from_mm) * f->px_per_mm;
        if (px - last_px > 16.0 && px > 12.0 && (r->to_mm - x) * f->px_per_mm > 12.0) {
            char buf[32];
            fmt_mm(buf, sizeof buf, x);
            tippe_plot_text(x - 0.004 * f->xspan, f->ymin + 0.03 * (f->ymax - f->ymin), 90.0, 0.0,
                            0.75, 0x303030u, buf);
            last_px = px;
        }
    }
}

/* The group boundaries of the classification along the path: b = +1 (only in
 * group II), b = -1 (two branches for small e), +-e/R and -(e/R)^2; then the
 * path's A/C - 1 over them. */
static void draw_boundary_curves(zone_frame *f)
{
    double(*y)[NS] = f->curve;
    int(*ok)[NS] = f->ok;
    for (int i = 0; i < NS; i++) {
        double kb[2];
        int n = k_where_b(f->ep[i], 1, kb);
        ok[0][i] = n >= 1;
        y[0][i] = n >= 1 ? kb[n - 1] - 1.0 : 0.0;
        n = k_where_b(f->ep[i], -1, kb);
        ok[1][i] = n >= 1;
        ok[2][i] = n == 2;
        y[1][i] = n >= 1 ? kb[0] - 1.0 : 0.0;
        y[2][i] = n == 2 ? kb[1] - 1.0 : 0.0;
    }
    line_where(NS, f->z, y[0], ok[0], C_BPLUS, 1.6, TIPPE_PLOT_DASHED);
    line_where(NS, f->z, y[1], ok[1], C_BMINUS, 1.6, TIPPE_PLOT_DASHED);
    line_where(NS, f->z, y[2], ok[2], C_BMINUS, 1.6, TIPPE_PLOT_DASHED);
    for (int i = 0; i < NS; i++) {
        y[0][i] = -f->ep[i];
        y[1][i] = -f->ep[i] * f->ep[i];
    }
    tippe_plot_line(NS, f->z, f->ep, C_E, 1.6, TIPPE_PLOT_SOLID);
    tippe_plot_line(NS, f->z, y[0], C_E, 1.6, TIPPE_PLOT_SOLID);
    tippe_plot_line(NS, f->z, y[1], C_E2, 1.6, TIPPE_PLOT_SOLID);
    tippe_plot_line(NS, f->z, f->km1, C_PATH, 2.6, TIPPE_PLOT_SOLID);
}

/* Touches and balanced points on the A/C - 1 curve, the physical travel's ends,
 * the zone names along the top where they fit. */
static void draw_marks(const tippe_sweep_path *path, const tippe_sweep_result *r,
                       const zone_frame *f)
{
    const double h = f->ymax - f->ymin;
    for (int i = 0; i < r->n_events; i++) {
        const tippe_sweep_event *ev = &r->events[i];
        if (!ev->touch && ev->boundary != TIPPE_SWEEP_BALANCED)
            continue;
        double k, es, x = ev->z2_mm;
        path->eval(x, path->params, &k, &es);
        double y = k - 1.0;
        tippe_plot_points(1, &x, &y, 4, 1.3, 0x000000u);
        /* centred over its mark, unless half the word would leave the panel (a mark
         * near an end of the travel): then it starts or ends at the mark */
        const double half_px = 30.0; /* half of "balanced" at 0.7 of the text height */
        const double just = (x - r->from_mm) * f->px_per_mm < half_px ? 0.0
                            : (r->to_mm - x) * f->px_per_mm < half_px ? 1.0 : 0.5;
        tippe_plot_text(x, y + 0.035 * h, 0.0, just, 0.7, 0x000000u,
                        ev->touch ? "touch" : "balanced");
    }
    double ends[2] = {r->travel_from_mm, r->travel_to_mm};
    for (int i = 0; r->has_travel && i < 2; i++) {
        if (ends[i] <= r->from_mm || ends[i] >= r->to_mm)
            continue;
        double lx[2] = {ends[i], ends[i]}, ly[2] = {f->ymin, f->ymax};
        tippe_plot_line(2, lx, ly, 0x000000u, 2.0, TIPPE_PLOT_DASHED);
    }
    for (int i = 0; i < r->n_zones; i++) {
        const tippe_sweep_zone *zn = &r->zones[i];
        if ((zn->z2_to_mm - zn->z2_from_mm) * f->px_per_mm < 34.0)
            continue;
        tippe_plot_text(0.5 * (zn->z2_from_mm + zn->z2_to_mm), f->ymax - 0.06 * h, 0.0, 0.5, 1.1,
                        0x000000u, tippe_group_name(zn->group));
    }
}

/* Each tolerance band also as an error bar below the zone names, so that
 * overlapping bands stay apart. */
static void draw_band_bars(const tippe_sweep_result *r, const tippe_sweep_bands_result *b,
                           const zone_frame *f)
{
    const double h = f->ymax - f->ymin;
    for (int i = 0; i < b->n; i++) {
        double w = b->bands[i].band_mm, x = b->bands[i].z2_mm;
        if (!(w > 0) || !isfinite(w))
            continue;
        double y = f->ymax - (0.14 + 0.035 * (i % 3)) * h, dy = 0.012 * h;
        double bx[2] = {fmax(r->from_mm, x - w), fmin(r->to_mm, x + w)}, by[2] = {y, y};
        tippe_plot_line(2, bx, by, C_BAND, 1.4, TIPPE_PLOT_SOLID);
        for (int e = 0; e < 2; e++) {
            double tx[2] = {bx[e], bx[e]}, ty[2] = {y - dy, y + dy};
            tippe_plot_line(2, tx, ty, C_BAND, 1.4, TIPPE_PLOT_SOLID);
        }
    }
}

static void draw_zone_legend(const int present[6], int banded, int beyond, int invalid)
{
    tippe_plot_key keys[20];
    int nk = 0;
    keys[nk++] = (tippe_plot_key){TIPPE_PLOT_KEY_LINE, "A/C − 1", C_PATH, 1, 2.6, 1};
    keys[nk++] = (tippe_plot_key){TIPPE_PLOT_KEY_LINE, "±#ge/R (I | II | III)", C_E, 1, 1.6, 1};
    keys[nk++] = (tippe_plot_key){TIPPE_PLOT_KEY_LINE, "−(#ge/R)#u2#d", C_E2, 1, 1.6, 1};
    keys[nk++] = (tippe_plot_key){TIPPE_PLOT_KEY_LINE, "b = +1 (IIa | IIb)", C_BPLUS, 1, 1.6,
                                  TIPPE_PLOT_DASHED};
    keys[nk++] = (tippe_plot_key){TIPPE_PLOT_KEY_LINE, "b = −1 (Ia|Ib, IIa|IIc)", C_BMINUS, 1,
                                  1.6, TIPPE_PLOT_DASHED};
    for (int g = 0; g < 6; g++)
        if (present[g])
            keys[nk++] = (tippe_plot_key){TIPPE_PLOT_KEY_BOX, group_text[g],
                                          tippe_plot_pale(group_rgb((tippe_group)g), SHADE), 1.0,
                                          0, 0};
    if (banded)
        keys[nk++] = (tippe_plot_key){TIPPE_PLOT_KEY_BOX, "boundary ± tolerance band",
                                      C_BAND, BAND_ALPHA, 0, 0};
    if (beyond) {
        keys[nk++] = (tippe_plot_key){TIPPE_PLOT_KEY_HATCH, "beyond physical travel", C_TRAVEL,
                                      1.0, 0, 0};
        keys[nk++] = (tippe_plot_key){TIPPE_PLOT_KEY_LINE, "physical travel ends", 0x000000u, 1,
                                      2.0, TIPPE_PLOT_DASHED};
    }
    if (invalid)
        keys[nk++] = (tippe_plot_key){TIPPE_PLOT_KEY_HATCH, "part out: model invalid",
                                      C_INVALID, 1.0, 0, 0};
    tippe_plot_legend(keys, nk, "outside", 1, 0.8);
}

int tippe_sweep_plot_zones_banded(const char *file, const tippe_sweep_path *path,
                                  const tippe_sweep_result *r, const tippe_sweep_bands_result *b,
                                  const char *title, tippe_error *err)
{
    if (!r || r->n_zones < 1 || !path)
        return tippe_error_set(err, TIPPE_EINPUT, "%s: nothing to plot", file);
    zone_frame *f = malloc(sizeof *f);
    if (!f)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "%s: out of memory", file);
    frame_sample(path, r, f);
    tippe_plot *p;
    int st = tippe_plot_open(file, 1100, 660, &p, err);
    if (st != TIPPE_OK) {
        free(f);
        return st;
    }
    const double vx0 = 0.09, vx1 = 0.70, vy0 = 0.11, vy1 = 0.88;
    tippe_plot_panel(vx0, vx1, vy0, vy1, r->from_mm, r->to_mm, f->ymin, f->ymax);
    f->px_per_mm = (vx1 - vx0) * 1100 / f->xspan;

    int present[6] = {0};
    const int beyond = draw_zone_shading(r, f, present);
    const int invalid = draw_invalid_hatch(r, f);
    const int banded = draw_band_shading(r, b, f);
    tippe_plot_grid();
    double zero[2] = {0.0, 0.0}, xr[2] = {r->from_mm, r->to_mm};
    tippe_plot_line(2, xr, zero, 0x888888u, 0.8, TIPPE_PLOT_SOLID);
    draw_zone_ends(r, f);
    draw_boundary_curves(f);
    draw_marks(path, r, f);
    if (banded)
        draw_band_bars(r, b, f);
    tippe_plot_axes("Z#d2#u: height of the moving weight's midpoint above the centre (mm)",
                    "A/C − 1", "groups of Theorem 5.1 along the travel");
    if (title) {
        char esc[400];
        tippe_plot_page_title(tippe_plot_escape(title, esc, sizeof esc), 1.1);
    }
    draw_zone_legend(present, banded, beyond, invalid);
    free(f);
    return tippe_plot_close(p, err);
}

/* ---- phase diagram ------------------------------------------------------- */

/* Regions of the classification in the window [e0, e1] x [k0, k1]: in each of
 * NC columns the runs of one group along k, their ends refined by bisection,
 * joined column to column into polygons. */
enum { NC = 160, NR = 240, MAXRUN = 12 };

typedef struct {
    int n;
    tippe_group g[MAXRUN];
    double lo[MAXRUN], hi[MAXRUN];
} column;

static int group_at(double e, double k)
{
    tippe_theory_class c;
    if (tippe_theory_classify(k, e, &c) != TIPPE_OK)
        return -1;
    return (int)c.group;
}

static void column_runs(double e, double k0, double k1, column *col)
{
    col->n = 0;
    int prev = group_at(e, k0);
    double kprev = k0, start = k0;
    for (int j = 1; j <= NR; j++) {
        double k = k0 + (k1 - k0) * j / NR;
        int g = group_at(e, k);
        if (g != prev || j == NR) {
            double end = k1;
            if (g != prev) {
                double lo = kprev, hi = k;
                for (int it = 0; it < 40; it++) {
                    double mid = 0.5 * (lo + hi);
                    if (group_at(e, mid) == prev)
                        lo = mid;
                    else
                        hi = mid;
                }
                end = 0.5 * (lo + hi);
            }
            if (prev >= 0 && col->n < MAXRUN) {
                col->g[col->n] = (tippe_group)prev;
                col->lo[col->n] = start;
                col->hi[col->n] = end;
                col->n++;
            }
            if (g != prev && j == NR && g >= 0 && col->n < MAXRUN) {
                col->g[col->n] = (tippe_group)g;
                col->lo[col->n] = end;
                col->hi[col->n] = k1;
                col->n++;
            }
            start = end;
        }
        prev = g;
        kprev = k;
    }
}

/* Index of the q-th run of group g in col, or -1. */
static int run_of(const column *col, tippe_group g, int q)
{
    for (int i = 0; i < col->n; i++)
        if (col->g[i] == g && q-- == 0)
            return i;
    return -1;
}

/* Distance, as a fraction of the window, from (e, k) to the nearest of the n
 * points (pe, pk): region labels keep clear of the path drawn over them. */
static double clearance(double e, double k, double e0, double e1, double k0, double k1, int n,
                        const double *pe, const double *pk)
{
    double best = INFINITY;
    for (int i = 0; i < n; i++)
        best = fmin(best, hypot((pe[i] - e) / (e1 - e0), (pk[i] - k) / (k1 - k0)));
    return best;
}

static void draw_regions(double e0, double e1, double k0, double k1, int label, double scale,
                         int n_path, const double *pe, const double *pk)
{
    column *cols = malloc(NC * sizeof *cols);
    double *px = malloc(2 * NC * sizeof *px), *py = malloc(2 * NC * sizeof *py);
    if (!cols || !px || !py) {
        free(cols);
        free(px);
        free(py);
        return;
    }
    double *ec = malloc(NC * sizeof *ec);
    for (int i = 0; ec && i < NC; i++) {
        ec[i] = e0 + (e1 - e0) * i / (NC - 1);
        column_runs(ec[i], k0, k1, &cols[i]);
    }
    for (int g = 0; ec && g < 6; g++) {
        for (int q = 0; q < 3; q++) {
            int i = 0;
            double best_w = 0, lx = 0, ly = 0;
            while (i < NC) {
                while (i < NC && run_of(&cols[i], (tippe_group)g, q) < 0)
                    i++;
                int j = i, n = 0;
                while (j < NC && run_of(&cols[j], (tippe_group)g, q) >= 0)
                    j++;
                if (j - i >= 2) {
                    for (int c = i; c < j; c++) {
                        int r = run_of(&cols[c], (tippe_group)g, q);
                        px[n] = ec[c], py[n++] = cols[c].lo[r];
                        /* Room around a label: the least of its distances to the
                         * run's ends along k, to the region's ends across, and
                         * to the path. Five candidate heights per column. */
                        double lo = cols[c].lo[r], hi = cols[c].hi[r];
                        double across = 2.0 * fmin(c - i, j - 1 - c) / NC;
                        for (int t = 1; t <= 5; t++) {
                            double kc = lo + (hi - lo) * t / 6.0;
                            double w = fmin(2.0 * fmin(kc - lo, hi - kc) / (k1 - k0), across);
                            if (w > best_w && n_path > 0)
                                w = fmin(w, 2.0 * clearance(ec[c], kc, e0, e1, k0, k1, n_path,
                                                            pe, pk));
                            if (w > best_w)
                                best_w = w, lx = ec[c], ly = kc;
                        }
                    }
                    for (int c = j - 1; c >= i; c--) {
                        int r = run_of(&cols[c], (tippe_group)g, q);
                        px[n] = ec[c], py[n++] = cols[c].hi[r];
                    }
                    tippe_plot_polygon(n, px, py, tippe_plot_pale(group_rgb((tippe_group)g), SHADE), 1.0);
                }
                i = j;
            }
            if (label && best_w > 0.06)
                tippe_plot_text(lx, ly, 0.0, 0.5, scale, 0x000000u,
                                tippe_group_name((tippe_group)g));
        }
    }
    free(ec);
    free(cols);
    free(px);
    free(py);
}

static void draw_boundaries(double e0, double e1)
{
    enum { N = 600 };
    double e[N], a[N], b[N], c[N], bp[N], bl[N], bu[N];
    int okp[N], okl[N], oku[N];
    for (int i = 0; i < N; i++) {
        e[i] = e0 + (e1 - e0) * i / (N - 1);
        a[i] = 1.0 - e[i];        /* I | II */
        b[i] = 1.0 + e[i];        /* II | III */
        c[i] = 1.0 - e[i] * e[i]; /* the -(eps/R)^2 line */
        double kb[2];
        int n = k_where_b(e[i], 1, kb);
        okp[i] = n >= 1;
        bp[i] = n >= 1 ? kb[n - 1] : 0;
        n = k_where_b(e[i], -1, kb);
        okl[i] = n >= 1, oku[i] = n == 2;
        bl[i] = n >= 1 ? kb[0] : 0;
        bu[i] = n == 2 ? kb[1] : 0;
    }
    line_where(N, e, bp, okp, C_BPLUS, 1.4, TIPPE_PLOT_DASHED);
    line_where(N, e, bl, okl, C_BMINUS, 1.4, TIPPE_PLOT_DASHED);
    line_where(N, e, bu, oku, C_BMINUS, 1.4, TIPPE_PLOT_DASHED);
    tippe_plot_line(N, e, c, C_E2, 1.4, TIPPE_PLOT_SOLID);
    tippe_plot_line(N, e, a, C_E, 1.4, TIPPE_PLOT_SOLID);
    tippe_plot_line(N, e, b, C_E, 1.4, TIPPE_PLOT_SOLID);
}

/* The path as (e, k) points; within[i] says whether Z2 is inside the physical travel. */
static void draw_path(const tippe_sweep_path *path, const tippe_sweep_result *r, int n,
                      double *pe, double *pk, int *within, double width)
{
    for (int i = 0; i < n; i++) {
        double zz = r->from_mm + (r->to_mm - r->from_mm) * i / (n - 1), k, es;
        path->eval(zz, path->params, &k, &es);
        pe[i] = fabs(es);
        pk[i] = k;
        within[i] = !r->has_travel || (zz >= r->travel_from_mm && zz <= r->travel_to_mm);
    }
    tippe_plot_line(n, pe, pk, 0x000000u, width + 2.0, TIPPE_PLOT_SOLID);
    int *out = malloc((size_t)n * sizeof *out);
    if (out) {
        for (int i = 0; i < n; i++)
            out[i] = !within[i] || (i > 0 && !within[i - 1]);
        line_where(n, pe, pk, out, 0xbbbbbbu, width, TIPPE_PLOT_SOLID);
        free(out);
    }
    line_where(n, pe, pk, within, 0xffd21fu, width, TIPPE_PLOT_SOLID);
}

int tippe_sweep_plot_phase(const char *file, const tippe_sweep_path *path,
                           const tippe_sweep_result *r, const char *title, tippe_error *err)
{
    enum { NP = 800 };
    if (!r || r->n_zones < 1 || !path)
        return tippe_error_set(err, TIPPE_EINPUT, "%s: nothing to plot", file);
    double *pe = malloc(2 * NP * sizeof *pe);
    int *within = malloc(NP * sizeof *within);
    if (!pe || !within) {
        free(pe);
        free(within);
        return tippe_error_set(err, TIPPE_ECOMPUTE, "%s: out of memory", file);
    }
    double *pk = pe + NP;
    double emin = INFINITY, emax = -INFINITY, kmin = INFINITY, kmax = -INFINITY;
    for (int i = 0; i < NP; i++) {
        double zz = r->from_mm + (r->to_mm - r->from_mm) * i / (NP - 1), k, es;
        path->eval(zz, path->params, &k, &es);
        emin = fmin(emin, fabs(es)), emax = fmax(emax, fabs(es));
        kmin = fmin(kmin, k), kmax = fmax(kmax, k);
    }
    /* The zoom: the path's box, padded, at least 0.02 wide in each direction. */
    double de = fmax(emax - emin, 0.02), dk = fmax(kmax - kmin, 0.02);
    double ze0 = fmax(0.0, 0.5 * (emin + emax) - 0.65 * de), ze1 = ze0 + 1.3 * de;
    double zk0 = fmax(1e-6, 0.5 * (kmin + kmax) - 0.65 * dk), zk1 = zk0 + 1.3 * dk;
    if (ze1 > 0.999)
        ze1 = 0.999;

    tippe_plot *p;
    int st = tippe_plot_open(file, 1200, 640, &p, err);
    if (st != TIPPE_OK) {
        free(pe);
        free(within);
        return st;
    }
    /* Left: the whole diagram (Figure 2). */
    tippe_plot_panel(0.065, 0.355, 0.34, 0.86, 0.0, 1.0, 0.0, 2.0);
    draw_regions(0.0, 1.0, 1e-6, 2.0, 1, 0.9, 0, NULL, NULL);
    draw_boundaries(0.0, 1.0);
    double bx[5] = {ze0, ze1, ze1, ze0, ze0}, by[5] = {zk0, zk0, zk1, zk1, zk0};
    draw_path(path, r, NP, pe, pk, within, 2.0);
    tippe_plot_line(5, bx, by, 0x000000u, 1.0, TIPPE_PLOT_SOLID);
    tippe_plot_axes("#ge/R", "A/C", "whole diagram (Figure 2)");

    /* Right: zoomed on the path, labelled with Z2. */
    tippe_plot_panel(0.43, 0.725, 0.11, 0.86, ze0, ze1, zk0, zk1);
    /* The path first (into pe, pk), so that region labels can keep clear of it. */
    for (int i = 0; i < NP; i++) {
        double zz = r->from_mm + (r->to_mm - r->from_mm) * i / (NP - 1), es;
        path->eval(zz, path->params, &pk[i], &es);
        pe[i] = fabs(es);
    }
    draw_regions(ze0, ze1, zk0, zk1, 1, 1.0, NP, pe, pk);
    tippe_plot_grid();
    draw_boundaries(ze0, ze1);
    draw_path(path, r, NP, pe, pk, within, 3.0);
    /* Z2 ticks: about eight, at round values. */
    double span = r->to_mm - r->from_mm, raw = span / 8.0, p10 = pow(10.0, floor(log10(raw)));
    double step = (raw / p10 < 1.5 ? 1 : raw / p10 < 3.5 ? 2 : raw / p10 < 7.5 ? 5 : 10) * p10;
    for (double t = ceil(r->from_mm / step) * step; t <= r->to_mm + 1e-9 * span; t += step) {
        double k, es;
        path->eval(t, path->params, &k, &es);
        double e = fabs(es);
        tippe_plot_points(1, &e, &k, 17, 1.4, 0x000000u);
        char buf[32];
        snprintf(buf, sizeof buf, " %g mm", fabs(t) < 1e-9 * span ? 0.0 : t);
        tippe_plot_text(e + 0.012 * (ze1 - ze0), k, 0.0, 0.0, 0.75, 0x000000u, buf);
    }
    /* The direction of increasing Z2, at the end of the path. */
    tippe_plot_arrow(pe[NP - 12], pk[NP - 12], pe[NP - 1], pk[NP - 1], 0x000000u, 2.0);
    char ttl[512], esc[400];
    snprintf(ttl, sizeof ttl, "the path as Z#d2#u goes from %g to %g mm", r->from_mm, r->to_mm);
    tippe_plot_axes("#ge/R", "A/C", ttl);
    if (title)
        tippe_plot_page_title(tippe_plot_escape(title, esc, sizeof esc), 1.1);

    tippe_plot_key keys[16];
    int nk = 0;
    keys[nk++] = (tippe_plot_key){TIPPE_PLOT_KEY_LINE, "path (Z#d2#u increasing ➜)", 0xffd21fu, 1,
                                  3.0, 1};
    if (r->has_travel)
        keys[nk++] = (tippe_plot_key){TIPPE_PLOT_KEY_LINE, "beyond physical travel",
                                      0xbbbbbbu, 1, 3.0, 1};
    keys[nk++] = (tippe_plot_key){TIPPE_PLOT_KEY_LINE, "A/C = 1 ± #ge/R", C_E, 1, 1.4, 1};
    keys[nk++] = (tippe_plot_key){TIPPE_PLOT_KEY_LINE, "A/C = 1 − (#ge/R)#u2#d", C_E2, 1, 1.4, 1};
    keys[nk++] = (tippe_plot_key){TIPPE_PLOT_KEY_LINE, "b = +1", C_BPLUS, 1, 1.4,
                                  TIPPE_PLOT_DASHED};
    keys[nk++] = (tippe_plot_key){TIPPE_PLOT_KEY_LINE, "b = −1", C_BMINUS, 1, 1.4,
                                  TIPPE_PLOT_DASHED};
    for (int g = 0; g < 6; g++)
        keys[nk++] = (tippe_plot_key){TIPPE_PLOT_KEY_BOX, group_text[g],
                                      tippe_plot_pale(group_rgb((tippe_group)g), SHADE), 1.0, 0, 0};
    tippe_plot_legend(keys, nk, "outside", 1, 0.72);
    free(pe);
    free(within);
    return tippe_plot_close(p, err);
}

/* ---- vary ------------------------------------------------------------------ */

int tippe_sweep_plot_vary(const char *file, const tippe_sweep_vary_result *v,
                          const char *field, const char *title, tippe_error *err)
{
    if (!v || v->n < 1)
        return tippe_error_set(err, TIPPE_EINPUT, "%s: nothing to plot", file);
    double x0 = v->values[0], x1 = v->values[v->n - 1];
    double dv = v->n > 1 ? (x1 - x0) / (v->n - 1) : 1.0;
    double zmin = INFINITY, zmax = -INFINITY;
    for (int i = 0; i < v->n; i++) {
        if (v->collision && v->collision[i])
            continue; /* not swept: its column is hatched grey below */
        zmin = fmin(zmin, v->results[i].from_mm);
        zmax = fmax(zmax, v->results[i].to_mm);
    }
    if (!(zmin < zmax))
        return tippe_error_set(err, TIPPE_EINPUT, "%s: nothing to plot", file);
    double xa = fmin(x0, x1) - 0.5 * fabs(dv), xb = fmax(x0, x1) + 0.5 * fabs(dv);
    tippe_plot *p;
    int st = tippe_plot_open(file, 1100, 660, &p, err);
    if (st != TIPPE_OK)
        return st;
    tippe_plot_panel(0.09, 0.70, 0.11, 0.88, xa, xb, zmin, zmax);
    int present[6] = {0}, beyond = 0, invalid = 0, collide = 0;
    for (int i = 0; i < v->n; i++) {
        const tippe_sweep_result *r = &v->results[i];
        double c0 = v->values[i] - 0.5 * fabs(dv), c1 = v->values[i] + 0.5 * fabs(dv);
        if (v->collision && v->collision[i]) {
            tippe_plot_hatch(c0, c1, zmin, zmax, C_COLLIDE);
            collide = 1;
            continue;
        }
        for (int j = 0; j < r->n_zones; j++) {
            const tippe_sweep_zone *zn = &r->zones[j];
            present[zn->group] = 1;
            tippe_plot_rect(c0, c1, zn->z2_from_mm, zn->z2_to_mm,
                            tippe_plot_pale(group_rgb(zn->group), 0.75), 1.0);
            if (!zn->within_travel) {
                tippe_plot_hatch(c0, c1, zn->z2_from_mm, zn->z2_to_mm, C_TRAVEL);
                beyond = 1;
            } else {
                invalid |= hatch_invalid_zone(r, zn, c0, c1, 0);
            }
        }
    }
    /* Zone ends as dots, so that each step's boundaries read exactly. */
    for (int i = 0; i < v->n; i++) {
        const tippe_sweep_result *r = &v->results[i];
        for (int j = 0; j + 1 < r->n_zones; j++) {
            if (r->zones[j].to_boundaries == 0)
                continue; /* a physical travel split, not a boundary */
            double x = v->values[i], y = r->zones[j].z2_to_mm;
            tippe_plot_points(1, &x, &y, 17, 0.9, 0x000000u);
        }
    }
    double *tx = malloc((size_t)v->n * 3 * sizeof *tx);
    if (tx) {
        double *ty0 = tx + v->n, *ty1 = tx + 2 * v->n;
        int m = 0; /* a run of swept steps, drawn when a collision or the end breaks it */
        for (int i = 0; i <= v->n; i++) {
            if (i < v->n && !(v->collision && v->collision[i])) {
                tx[m] = v->values[i];
                ty0[m] = v->results[i].travel_from_mm;
                ty1[m] = v->results[i].travel_to_mm;
                m++;
                continue;
            }
            if (m >= 2) {
                tippe_plot_line(m, tx, ty0, 0x000000u, 2.0, TIPPE_PLOT_DASHED);
                tippe_plot_line(m, tx, ty1, 0x000000u, 2.0, TIPPE_PLOT_DASHED);
            }
            m = 0;
        }
        free(tx);
    }
    char xl[300], esc[256], ttl[512];
    snprintf(xl, sizeof xl, "%s", tippe_plot_escape(field ? field : "value", esc, sizeof esc));
    snprintf(ttl, sizeof ttl, "zones as %s varies (dots: zone ends)", esc);
    tippe_plot_axes(xl, "Z#d2#u (mm)", ttl);
    if (title) {
        char e2[300];
        tippe_plot_page_title(tippe_plot_escape(title, e2, sizeof e2), 1.1);
    }
    tippe_plot_key keys[12];
    int nk = 0;
    for (int g = 0; g < 6; g++)
        if (present[g])
            keys[nk++] = (tippe_plot_key){TIPPE_PLOT_KEY_BOX, group_text[g],
                                          tippe_plot_pale(group_rgb((tippe_group)g), 0.75), 1.0, 0, 0};
    if (beyond)
        keys[nk++] = (tippe_plot_key){TIPPE_PLOT_KEY_HATCH, "beyond physical travel", C_TRAVEL,
                                      1.0, 0, 0};
    if (invalid)
        keys[nk++] = (tippe_plot_key){TIPPE_PLOT_KEY_HATCH, "part out: model invalid",
                                      C_INVALID, 1.0, 0, 0};
    if (collide)
        keys[nk++] = (tippe_plot_key){TIPPE_PLOT_KEY_HATCH, "parts collide: not swept",
                                      C_COLLIDE, 1.0, 0, 0};
    int travel_shown = 0;
    for (int i = 0; i < v->n; i++) {
        if (v->collision && v->collision[i])
            continue;
        double a = v->results[i].travel_from_mm, b = v->results[i].travel_to_mm;
        travel_shown |= (a >= zmin && a <= zmax) || (b >= zmin && b <= zmax);
    }
    if (travel_shown)
        keys[nk++] = (tippe_plot_key){TIPPE_PLOT_KEY_LINE, "physical travel ends", 0x000000u, 1,
                                      2.0, TIPPE_PLOT_DASHED};
    tippe_plot_legend(keys, nk, "outside", 1, 0.8);
    return tippe_plot_close(p, err);
}

/* ---- compare ----------------------------------------------------------------- */

/* One design's bar: its zones along Z2 between y0 and y1, hatched beyond the
 * physical travel, each zone named where it is wide enough to hold the name. */
static void compare_bar(const tippe_sweep_result *r, double y0, double y1, double span,
                        int *present, int *beyond, int *invalid)
{
    for (int j = 0; j < r->n_zones; j++) {
        const tippe_sweep_zone *zn = &r->zones[j];
        present[zn->group] = 1;
        tippe_plot_rect(zn->z2_from_mm, zn->z2_to_mm, y0, y1,
                        tippe_plot_pale(group_rgb(zn->group), 0.75), 1.0);
        if (!zn->within_travel) {
            tippe_plot_hatch(zn->z2_from_mm, zn->z2_to_mm, y0, y1, C_TRAVEL);
            *beyond = 1;
        } else {
            *invalid |= hatch_invalid_zone(r, zn, y0, y1, 1);
        }
        if (zn->z2_to_mm - zn->z2_from_mm > 0.06 * span)
            tippe_plot_text(0.5 * (zn->z2_from_mm + zn->z2_to_mm), 0.5 * (y0 + y1) - 0.08, 0.0,
                            0.5, 0.8, 0x000000u, tippe_group_name(zn->group));
        if (j + 1 < r->n_zones && zn->to_boundaries) { /* a boundary, not a travel split */
            double x[2] = {zn->z2_to_mm, zn->z2_to_mm}, y[2] = {y0, y1};
            tippe_plot_line(2, x, y, 0x000000u, 1.2, TIPPE_PLOT_SOLID);
        }
    }
}

int tippe_sweep_plot_compare(const char *file, const tippe_sweep_result *r,
                             const char *const *labels, int n, const char *title,
                             tippe_error *err)
{
    if (n < 1)
        return tippe_error_set(err, TIPPE_EINPUT, "%s: nothing to plot", file);
    double zmin = INFINITY, zmax = -INFINITY;
    for (int i = 0; i < n; i++) {
        zmin = fmin(zmin, r[i].from_mm);
        zmax = fmax(zmax, r[i].to_mm);
    }
    tippe_plot *p;
    int st = tippe_plot_open(file, 1200, 220 + 70 * n, &p, err);
    if (st != TIPPE_OK)
        return st;
    tippe_plot_panel(0.27, 0.70, 0.16 + 0.3 / (n + 2), 0.86, zmin, zmax, 0.0, (double)n);
    int present[6] = {0}, beyond = 0, invalid = 0;
    char esc[300];
    for (int i = 0; i < n; i++) {
        double y1 = n - i - 0.15, y0 = n - i - 0.85; /* the first design on top */
        compare_bar(&r[i], y0, y1, zmax - zmin, present, &beyond, &invalid);
        tippe_plot_margin_text("lv", 0.8, (n - i - 0.5) / n, 1.0, 0.8, 0x000000u,
                               tippe_plot_escape(labels[i], esc, sizeof esc));
    }
    tippe_plot_axes_x("Z#d2#u (mm)", "zones of each design along its weight's travel");
    if (title)
        tippe_plot_page_title(tippe_plot_escape(title, esc, sizeof esc), 1.1);
    tippe_plot_key keys[8];
    int nk = 0;
    for (int g = 0; g < 6; g++)
        if (present[g])
            keys[nk++] = (tippe_plot_key){TIPPE_PLOT_KEY_BOX, group_text[g],
                                          tippe_plot_pale(group_rgb((tippe_group)g), 0.75), 1.0,
                                          0, 0};
    if (beyond)
        keys[nk++] = (tippe_plot_key){TIPPE_PLOT_KEY_HATCH, "beyond physical travel", C_TRAVEL,
                                      1.0, 0, 0};
    if (invalid)
        keys[nk++] = (tippe_plot_key){TIPPE_PLOT_KEY_HATCH, "part out: model invalid",
                                      C_INVALID, 1.0, 0, 0};
    tippe_plot_legend(keys, nk, "outside", 1, 0.8);
    return tippe_plot_close(p, err);
}
