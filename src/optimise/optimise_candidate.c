/* One candidate of a search: the spec's choice and parameters turned into
 * design overrides, loaded and swept, and scored (see tippe/optimise.h). */
#include "optimise/internal.h"
#include "tippe/design.h"
#include "tippe/physics.h"
#include "tippe/sweep.h"

#include <cjson/cJSON.h>
#include <dlfcn.h>
#include <limits.h>
#include <math.h>
#include <nlopt.h>
#include <omp.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

/* ---- one candidate --------------------------------------------------------- */

/* The value the tie's field follows, for candidate (options idx, x). */
static double tie_source(const tippe_optimise_spec *s, const tie_t *t, const int *idx, const double *x)
{
    if (t->vary_index >= 0)
        return x[t->vary_index];
    for (int k = 0; k < s->n_choose; k++) {
        const option_t *o = &s->choose[k].opt[idx[k]];
        for (int j = 0; j < o->n_set; j++) {
            size_t n = strlen(t->follows);
            if (!strncmp(o->set[j], t->follows, n) && o->set[j][n] == '=') {
                char *end = NULL;
                double v = strtod(o->set[j] + n + 1, &end);
                if (end && !*end)
                    return v;
            }
        }
    }
    return t->base_value;
}

/* Tie k's value: along a chain, each link's value from the one it follows
 * (the spec load refused cycles, so the chain ends within n_tie links). */
static double tie_value(const tippe_optimise_spec *s, int k, const int *idx, const double *x)
{
    const tie_t *t = &s->tie[k];
    double from = t->tie_index >= 0 ? tie_value(s, t->tie_index, idx, x)
                                    : tie_source(s, t, idx, x);
    return t->times * from + t->plus_mm;
}

/* The option of each choose entry in combination `choice` (mixed radix, the
 * first entry varying slowest). */
void tippe_optimise_choice_options(const tippe_optimise_spec *s, int choice, int *idx)
{
    for (int k = s->n_choose - 1; k >= 0; k--) {
        idx[k] = choice % s->choose[k].n;
        choice /= s->choose[k].n;
    }
}

int tippe_optimise_overrides(const tippe_optimise_spec *s, int choice, const double *x, char (*buf)[256],
                        int cap)
{
    int idx[MAX_CHOOSE], n = 0;
    tippe_optimise_choice_options(s, choice, idx);
    for (int k = 0; k < s->n_vary; k++) {
        if (n == cap)
            return -1;
        /* %.17g: the override is the exact double the search chose. */
        snprintf(buf[n++], 256, "%s=%.17g", s->vary[k].path, x[k]);
    }
    for (int k = 0; k < s->n_choose; k++) {
        const option_t *o = &s->choose[k].opt[idx[k]];
        for (int j = 0; j < o->n_set; j++) {
            if (n == cap)
                return -1;
            snprintf(buf[n++], 256, "%s", o->set[j]);
        }
    }
    for (int k = 0; k < s->n_tie; k++) {
        if (n == cap)
            return -1;
        snprintf(buf[n++], 256, "%s=%.17g", s->tie[k].path, tie_value(s, k, idx, x));
    }
    return n;
}

/* The widest run of group II within the travel (as tippe_sweep_summarise
 * measures it), or 0 if none. */
static int widest_ii_run(const tippe_sweep_result *r, double *from, double *to)
{
    double best = -1.0, f = 0.0;
    int in = 0;
    for (int i = 0; i <= r->n_zones; i++) {
        const tippe_sweep_zone *z = i < r->n_zones ? &r->zones[i] : NULL;
        int ii = z && z->within_travel && !strcmp(tippe_group_family(z->group), "II");
        if (ii && !in) {
            f = z->z2_from_mm;
            in = 1;
        }
        if (!ii && in) {
            double t = r->zones[i - 1].z2_to_mm;
            if (t - f > best) {
                best = t - f;
                *from = f;
                *to = t;
            }
            in = 0;
        }
    }
    return best > 0.0;
}

/* n* (section 7.1: the spin at theta = 0 that makes the inverted state
 * stable, i.e. the spin a hand must give for the top to flip) over the middle
 * half of zone II, where a maker sets the weight; n* grows without bound at
 * the II/III boundary, so the zone's ends cannot count. rev/s. */
static double flip_spin_rev_s(const tippe_design *d, double from, double to)
{
    double worst = 0.0;
    for (int j = 0; j <= 4; j++) {
        double z2 = from + (to - from) * (0.25 + 0.125 * j);
        tippe_top top;
        tippe_design_top_any(d, z2, &top);
        tippe_theory_thresholds th;
        tippe_error e = {0};
        if (tippe_theory_compute_thresholds(&top, TIPPE_DEFAULT_G_M_S2, &th, &e) != TIPPE_OK ||
            !th.has_n_star)
            return INFINITY;
        worst = fmax(worst, th.n_star_rad_s / (2.0 * TIPPE_PI));
    }
    return worst;
}

/* The tolerance bands of the sweep's zone ends and the widths that survive
 * them (tippe/sweep.h); left unset if they cannot be computed. */
static void robust_widths(const tippe_design *d, const tippe_sweep_result *r, tippe_optimise_eval *out)
{
    tippe_sweep_bands_result b;
    tippe_error e = {0};
    if (tippe_sweep_bands(d, r, &b, &e) == TIPPE_OK) {
        double narrow = 0.0;
        tippe_sweep_robust_widths(r, &b, out->robust_zone_mm, &narrow);
        out->robust_mm = narrow;
        out->has_robust = 1;
    }
    tippe_sweep_bands_free(&b);
}

/* Two perimeters around the hole: twice the line width of the part it is cut
 * from as printed (its print block), or of the slicer defaults
 * (tippe_print_defaults) for a part without one. */
static double perimeter_wall_mm(const tippe_design *d, const char *hole)
{
    tippe_print_settings set = tippe_print_defaults();
    int n = tippe_design_n_parts(d), parent = -1;
    tippe_design_part_info info;
    for (int i = 0; hole && i < n; i++)
        if (tippe_design_part(d, i, &info) == TIPPE_OK && !strcmp(info.name, hole))
            for (int j = 0; j < n && info.cut_from; j++) {
                tippe_design_part_info pj;
                if (tippe_design_part(d, j, &pj) == TIPPE_OK && !strcmp(pj.name, info.cut_from))
                    parent = j;
            }
    tippe_design_print_info pr;
    if (parent >= 0 && tippe_design_part_print(d, parent, &pr) == TIPPE_OK && pr.printed)
        set = pr.settings;
    return 2.0 * set.line_width_mm;
}


/* tippe_optimise_evaluate, with the margins (the polish's constraints; the score's
 * violation is the sum of the positive ones). */
void tippe_optimise_evaluate_margins(const tippe_optimise_spec *s, int choice, const double *x, int n_scan,
                     tippe_optimise_eval *out, double margin[N_CON])
{
    memset(out, 0, sizeof *out);
    for (int k = 0; k < N_CON; k++)
        margin[k] = 1.0;
    out->choice = choice;
    for (int k = 0; k < s->n_vary; k++)
        out->x[k] = x[k];
    out->wall_mm = INFINITY;
    char buf[TIPPE_OPTIMISE_MAX_VARY + MAX_CHOOSE * MAX_SETS_PER_OPTION + MAX_TIE][256];
    const char *ov[sizeof buf / sizeof buf[0]];
    int n = tippe_optimise_overrides(s, choice, x, buf, (int)(sizeof buf / sizeof buf[0]));
    for (int i = 0; i < n; i++)
        ov[i] = buf[i];
    tippe_design *d = NULL;
    tippe_error e = {0};
    /* Search candidates (n_scan > 0) are screened on the coarse layout grid; a
     * reported best (n_scan = 0) is built and swept at full resolution. */
    unsigned flags = TIPPE_DESIGN_TRAVEL_PHYSICAL | (n_scan > 0 ? TIPPE_DESIGN_COARSE_LAYOUT : 0);
    if (tippe_design_source_build(s->src, ov, n, flags, &d, &e)) {
        out->status = TIPPE_OPTIMISE_DOES_NOT_FIT;
        out->score = -2.0;
        return;
    }
    tippe_design_travel_mm(d, &out->travel_mm[0], &out->travel_mm[1]);
    out->weight_g = tippe_design_moving_mass_kg(d) * 1e3;
    const char *hole = NULL;
    out->wall_mm = tippe_design_min_hole_wall_mm(d, &hole);
    double min_wall = s->min_wall_mm >= 0 ? s->min_wall_mm : perimeter_wall_mm(d, hole);
    /* z_cm is linear in Z2 (the total mass does not change), so |eps| is
     * largest at an end of the travel. */
    tippe_top t0, t1;
    tippe_design_top_any(d, out->travel_mm[0], &t0);
    tippe_design_top_any(d, out->travel_mm[1], &t1);
    out->eps_max_mm = fmax(t0.eps, t1.eps) * 1e3;

    tippe_sweep_options so;
    tippe_sweep_options_default(&so);
    if (n_scan > 0)
        so.n_scan = n_scan;
    tippe_sweep_result r;
    tippe_sweep_summary sum;
    double violation = 0.0;
    margin[CON_SPIN] = -1.0;
    if (tippe_sweep_design(d, out->travel_mm[0], out->travel_mm[1], &so, &r, &e)) {
        out->status = TIPPE_OPTIMISE_NO_ZONES;
        violation += 1.0;
    } else {
        tippe_sweep_summarise(&r, &sum);
        for (int k = 0; k < 3; k++)
            out->zone_mm[k] = sum.widest_mm[k];
        out->objective_mm = sum.narrowest_zone_mm;
        if (n_scan <= 0 && s->robust)
            robust_widths(d, &r, out);
        double f = 0.0, t = 0.0;
        if (isfinite(s->spin_max_rev_s) && widest_ii_run(&r, &f, &t)) {
            out->spin_flip_rev_s = flip_spin_rev_s(d, f, t);
            margin[CON_SPIN] = isfinite(out->spin_flip_rev_s)
                                   ? out->spin_flip_rev_s / s->spin_max_rev_s - 1.0
                                   : 1.0;
            if (!(out->spin_flip_rev_s <= s->spin_max_rev_s)) {
                out->status = TIPPE_OPTIMISE_SPIN_HIGH;
                violation += margin[CON_SPIN];
            }
        }
    }
    tippe_sweep_result_free(&r);
    margin[CON_EPS] = s->eps_max_min_mm > 0 ? 1.0 - out->eps_max_mm / s->eps_max_min_mm : -1.0;
    margin[CON_WEIGHT] = isfinite(s->max_weight_g) ? out->weight_g / s->max_weight_g - 1.0 : -1.0;
    margin[CON_WALL] = !isfinite(out->wall_mm) ? -1.0
                       : min_wall > 0          ? fmin(1.0, 1.0 - out->wall_mm / min_wall)
                       : out->wall_mm < min_wall ? 1.0
                                                 : -1.0;
    if (out->eps_max_mm < s->eps_max_min_mm) {
        out->status = TIPPE_OPTIMISE_EPS_SMALL;
        violation += margin[CON_EPS];
    }
    if (out->weight_g > s->max_weight_g) {
        out->status = TIPPE_OPTIMISE_HEAVY;
        violation += margin[CON_WEIGHT];
    }
    if (out->wall_mm < min_wall) {
        out->status = TIPPE_OPTIMISE_THIN_WALL;
        violation += margin[CON_WALL];
    }
    out->score = out->status == TIPPE_OPTIMISE_OK ? out->objective_mm : -1.0 - fmin(violation, 0.99);
    tippe_design_free(d);
}

void tippe_optimise_evaluate(const tippe_optimise_spec *s, int choice, const double *x, int n_scan,
                        tippe_optimise_eval *out)
{
    double margin[N_CON];
    tippe_optimise_evaluate_margins(s, choice, x, n_scan, out, margin);
}

int tippe_optimise_sweep(const tippe_optimise_spec *s, const tippe_optimise_eval *e, tippe_sweep_result *out,
                    tippe_error *err)
{
    memset(out, 0, sizeof *out);
    char buf[TIPPE_OPTIMISE_MAX_VARY + MAX_CHOOSE * MAX_SETS_PER_OPTION + MAX_TIE][256];
    const char *ov[sizeof buf / sizeof buf[0]];
    int n = tippe_optimise_overrides(s, e->choice, e->x, buf, (int)(sizeof buf / sizeof buf[0]));
    for (int i = 0; i < n; i++)
        ov[i] = buf[i];
    tippe_design *d = NULL;
    int rc = tippe_design_source_build(s->src, ov, n, TIPPE_DESIGN_TRAVEL_PHYSICAL, &d, err);
    if (rc)
        return rc;
    double f, t;
    tippe_design_travel_mm(d, &f, &t);
    rc = tippe_sweep_design(d, f, t, NULL, out, err);
    tippe_design_free(d);
    return rc;
}
