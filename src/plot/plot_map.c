/* The outcome map of `tippe map` as a heat map over (Z2, spin), with the zones
 * of the design's sweep and theory's spin thresholds drawn over it
 * (tippe/launch.h, tippe/theory.h). */
#include "tippe/launch.h"
#include "plot/canvas.h"
#include "tippe/sweep.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const unsigned verdict_rgb[TIPPE_LAUNCH_N_VERDICTS] = {
    0x2f62b0u, /* no_tip: blue */
    0xd2462au, /* tip: red */
    0x2e9a46u, /* hang: green */
    0x8e2ac0u, /* lost_contact: purple */
    0x707070u, /* undecided: grey */
    0xb08a2eu, /* bounded: ochre */
};
#define C_NMINUS 0xffd21fu /* yellow */
#define C_NSTAR 0x25d0e8u  /* cyan */
#define C_INVALID 0xC00000u /* a part stands out of the sphere, as in the zone plot */

static const char *const verdict_key[TIPPE_LAUNCH_N_VERDICTS] = {
    "no_tip (stays upright)", "tip (flips to #gh = #gp)", "hang (intermediate #gh)",
    "lost_contact (lifts off)", "undecided by t_end", "bounded (no rest state)",
};

static double luminance(unsigned rgb)
{
    return (0.299 * ((rgb >> 16) & 0xff) + 0.587 * ((rgb >> 8) & 0xff) + 0.114 * (rgb & 0xff)) /
           255.0;
}

/* Edges of the cells around grid values v[0..n-1] (evenly spaced): half a step
 * either side, or +-half_single for a single value. */
static void cell_edges(const double *v, int n, double half_single, double *lo, double *hi)
{
    double half = n > 1 ? 0.5 * (v[n - 1] - v[0]) / (n - 1) : half_single;
    *lo = v[0] - half;
    *hi = v[n - 1] + half;
}

/* Draws y(x) where finite, as separate polylines over the gaps. */
static void line_where_finite(int n, const double *x, const double *y, unsigned rgb, double width,
                              int style)
{
    int i = 0;
    while (i < n) {
        while (i < n && !isfinite(y[i]))
            i++;
        int j = i;
        while (j < n && isfinite(y[j]))
            j++;
        if (j - i >= 2)
            tippe_plot_line(j - i, x + i, y + i, rgb, width, style);
        i = j;
    }
}

enum { NT = 400 }; /* points along the threshold curves */

/* Theory's thresholds for a launch from theta = 0 along Z2, in rev/s (NAN where
 * the threshold does not exist, e.g. n- in group I, or lies above the window). */
typedef struct {
    double zx[NT], nminus[NT], nstar[NT];
    int any_minus, any_star;
} map_thresholds;

static void thresholds_fill(const tippe_design *d, double g, double xmin, double xmax,
                            double ymax, map_thresholds *m)
{
    m->any_minus = m->any_star = 0;
    for (int i = 0; i < NT; i++) {
        m->zx[i] = xmin + (xmax - xmin) * i / (NT - 1);
        tippe_top top;
        tippe_design_top_any(d, m->zx[i], &top);
        tippe_theory_thresholds th;
        tippe_error e;
        m->nminus[i] = m->nstar[i] = NAN;
        if (tippe_theory_compute_thresholds(&top, g, &th, &e) != TIPPE_OK)
            continue;
        if (th.has_n_minus && th.n_minus_rad_s / (2 * M_PI) < ymax) {
            m->nminus[i] = th.n_minus_rad_s / (2 * M_PI);
            m->any_minus = 1;
        }
        if (th.has_n_star && th.n_star_rad_s / (2 * M_PI) < ymax) {
            m->nstar[i] = th.n_star_rad_s / (2 * M_PI);
            m->any_star = 1;
        }
    }
}

/* The map's window in (Z2 mm, spin rev/s) and its panel. */
typedef struct {
    double xmin, xmax, ymin, ymax;
    double px_per_mm, cell_w, cell_h;
    int numbers; /* cells large enough for their share in % */
} map_frame;

/* Each cell in its most frequent outcome's colour, paler for a smaller share;
 * present[v] set for the outcomes shown. */
static void draw_cells(const tippe_launch_map *map, const map_frame *f, int *present)
{
    for (int i = 0; i < map->n_z2; i++)
        for (int j = 0; j < map->n_spin; j++) {
            const tippe_launch_tally *c = &map->cells[(long)i * map->n_spin + j];
            if (c->n <= 0)
                continue;
            int v = tippe_launch_dominant(c);
            double share = (double)c->counts[v] / (double)c->n;
            unsigned rgb = tippe_plot_pale(verdict_rgb[v], share);
            present[v] = 1;
            double x0 = f->xmin + i * f->cell_w, y0 = f->ymin + j * f->cell_h;
            tippe_plot_rect(x0, x0 + f->cell_w, y0, y0 + f->cell_h, rgb, 1.0);
            if (f->numbers) {
                char buf[16];
                snprintf(buf, sizeof buf, "%.0f%%", 100.0 * share);
                tippe_plot_text(x0 + 0.5 * f->cell_w, y0 + 0.5 * f->cell_h - 0.12 * f->cell_h,
                                0.0, 0.5, 0.7, luminance(rgb) < 0.5 ? 0xffffffu : 0x202020u,
                                buf);
            }
        }
}

/* Red hatching over the columns whose Z2 puts a part out of the sphere (map's
 * '!' columns): the top rests on the part and the model does not apply there.
 * 1 if any. */
static int draw_invalid_columns(const tippe_launch_map *map, const tippe_design *d,
                                const map_frame *f)
{
    double a, b;
    tippe_design_sphere_only_mm(d, &a, &b);
    int any = 0;
    for (int i = 0; i < map->n_z2; i++) {
        const double z = map->z2_mm[i];
        if (z >= a && z <= b)
            continue;
        double x0 = f->xmin + i * f->cell_w;
        tippe_plot_hatch(x0, x0 + f->cell_w, f->ymin, f->ymax, C_INVALID);
        any = 1;
    }
    return any;
}

/* Zone boundaries inside the window, and zone names above the panel. */
static void draw_zones(const tippe_sweep_result *zones, const map_frame *f)
{
    for (int i = 0; i + 1 < zones->n_zones; i++) {
        double x = zones->zones[i].z2_to_mm;
        if (x <= f->xmin || x >= f->xmax || zones->zones[i].group == zones->zones[i + 1].group)
            continue;
        double lx[2] = {x, x}, ly[2] = {f->ymin, f->ymax};
        tippe_plot_line(2, lx, ly, 0x000000u, 2.2, TIPPE_PLOT_SOLID);
    }
    for (int i = 0; i < zones->n_zones; i++) {
        const tippe_sweep_zone *z = &zones->zones[i];
        double a = fmax(z->z2_from_mm, f->xmin), b = fmin(z->z2_to_mm, f->xmax);
        if ((b - a) * f->px_per_mm < 28.0)
            continue;
        tippe_plot_margin_text("t", 0.7, (0.5 * (a + b) - f->xmin) / (f->xmax - f->xmin), 0.5,
                               1.0, 0x000000u, tippe_group_name(z->group));
    }
}

/* Yellow or cyan with a black edge reads on every cell colour and on white. */
static void draw_thresholds(const map_thresholds *m)
{
    if (m->any_minus) {
        line_where_finite(NT, m->zx, m->nminus, 0x000000u, 4.6, TIPPE_PLOT_SOLID);
        line_where_finite(NT, m->zx, m->nminus, C_NMINUS, 2.4, TIPPE_PLOT_SOLID);
    }
    if (m->any_star) {
        line_where_finite(NT, m->zx, m->nstar, 0x000000u, 4.6, TIPPE_PLOT_SOLID);
        line_where_finite(NT, m->zx, m->nstar, C_NSTAR, 2.4, TIPPE_PLOT_SOLID);
    }
}

static void draw_map_legend(const int *present, int boundaries, int invalid,
                            const map_thresholds *m)
{
    tippe_plot_key keys[12];
    int nk = 0;
    for (int v = 0; v < TIPPE_LAUNCH_N_VERDICTS; v++)
        if (present[v])
            keys[nk++] = (tippe_plot_key){TIPPE_PLOT_KEY_BOX, verdict_key[v], verdict_rgb[v], 1.0,
                                          0, 0};
    keys[nk++] = (tippe_plot_key){TIPPE_PLOT_KEY_BOX, "paler: smaller share (50%)",
                                  tippe_plot_pale(verdict_rgb[1], 0.5), 1.0, 0, 0};
    if (boundaries)
        keys[nk++] = (tippe_plot_key){TIPPE_PLOT_KEY_LINE, "zone boundary", 0x000000u, 1, 2.2,
                                      TIPPE_PLOT_SOLID};
    if (invalid)
        keys[nk++] = (tippe_plot_key){TIPPE_PLOT_KEY_HATCH, "part out: model invalid",
                                      C_INVALID, 1.0, 0, 0};
    if (m->any_minus)
        keys[nk++] = (tippe_plot_key){TIPPE_PLOT_KEY_LINE, "n#d-#u: #gh = 0 unstable above",
                                      C_NMINUS, 1, 3.0, TIPPE_PLOT_SOLID};
    if (m->any_star)
        keys[nk++] = (tippe_plot_key){TIPPE_PLOT_KEY_LINE, "n#d*#u: #gh = #gp stable above",
                                      C_NSTAR, 1, 3.0, TIPPE_PLOT_SOLID};
    tippe_plot_legend(keys, nk, "outside", 1, 0.75);
}

int tippe_launch_plot_map(const char *file, const tippe_launch_map *map, const tippe_design *d,
                          double g, const char *title, tippe_error *err)
{
    if (!map || map->n_z2 < 1 || map->n_spin < 1 || !map->cells || !d)
        return tippe_error_set(err, TIPPE_EINPUT, "%s: nothing to plot", file);
    map_frame f;
    cell_edges(map->z2_mm, map->n_z2, 0.5, &f.xmin, &f.xmax);
    cell_edges(map->spin_rev_s, map->n_spin, 0.5, &f.ymin, &f.ymax);

    /* Zones over the part of the map's Z2 window inside the stated travel
     * (the cells are inside it; beyond it the top cannot be built). */
    double tf, tt;
    tippe_design_travel_mm(d, &tf, &tt);
    tippe_sweep_result zones;
    tippe_error zerr;
    int have_zones = fmax(f.xmin, tf) < fmin(f.xmax, tt) &&
                     tippe_sweep_design(d, fmax(f.xmin, tf), fmin(f.xmax, tt), NULL, &zones,
                                        &zerr) == TIPPE_OK;
    if (!have_zones)
        memset(&zones, 0, sizeof zones);
    map_thresholds *m = malloc(sizeof *m);
    if (!m) {
        tippe_sweep_result_free(&zones);
        return tippe_error_set(err, TIPPE_ECOMPUTE, "%s: out of memory", file);
    }
    thresholds_fill(d, g, f.xmin, f.xmax, f.ymax, m);

    const int W = 1150, H = 720;
    tippe_plot *p;
    int st = tippe_plot_open(file, W, H, &p, err);
    if (st != TIPPE_OK) {
        free(m);
        tippe_sweep_result_free(&zones);
        return st;
    }
    const double vx0 = 0.075, vx1 = 0.665, vy0 = 0.11, vy1 = 0.84;
    tippe_plot_panel(vx0, vx1, vy0, vy1, f.xmin, f.xmax, f.ymin, f.ymax);
    f.px_per_mm = (vx1 - vx0) * W / (f.xmax - f.xmin);
    f.cell_w = (f.xmax - f.xmin) / map->n_z2;
    f.cell_h = (f.ymax - f.ymin) / map->n_spin;
    f.numbers = (vx1 - vx0) * W / map->n_z2 >= 34 && (vy1 - vy0) * H / map->n_spin >= 16;

    int present[TIPPE_LAUNCH_N_VERDICTS] = {0};
    draw_cells(map, &f, present);
    const int invalid = draw_invalid_columns(map, d, &f);
    if (have_zones)
        draw_zones(&zones, &f);
    draw_thresholds(m);
    tippe_plot_axes("Z#d2#u: height of the moving weight's midpoint above the centre (mm)",
                    "spin at launch (rev/s)", NULL);
    tippe_plot_margin_text("t", 2.3, 0.5, 0.5, 0.95, 0x000000u,
                           "zones of Theorem 5.1 (tippe sweep); cell: most frequent outcome and "
                           "its share");
    char sub[160], esc[400];
    snprintf(sub, sizeof sub, "%s: outcome of %ld hand launches per cell",
             title ? title : tippe_design_name(d), map->per_cell);
    tippe_plot_page_title(tippe_plot_escape(sub, esc, sizeof esc), 1.05);
    draw_map_legend(present, have_zones && zones.n_zones > 1, invalid, m);

    free(m);
    tippe_sweep_result_free(&zones); /* zeroed by the sweep even when it failed */
    return tippe_plot_close(p, err);
}
