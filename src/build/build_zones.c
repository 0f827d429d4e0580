/* The zones of a design as the build sheet judges them: each behaviour's
 * widest run and its robust part (the run less its tolerance bands). Below
 * the sheet and its advice, which both judge designs by it. */
#include "build/internal.h"

#include "tippe/sweep.h"

#include <math.h>
#include <string.h>

/* ------------------------------------------------------------ ranges */

/* The run of each family with the largest robust width (the nominal widest if
 * none is robust), as tippe_sweep_robust_widths joins runs: only the usable
 * part of each zone (as tippe_sweep_family_run: within the physical travel and
 * where no part stands out of the sphere, so the model applies). */
static void robust_runs(const tippe_sweep_result *r, const tippe_sweep_bands_result *b,
                        tippe_build_setting set[3])
{
    for (int i = 0, f; i < r->n_zones;) {
        double from, to;
        i = tippe_sweep_family_run(r, i, &f, &from, &to);
        if (f >= 0) {
            double bf = tippe_sweep_band_at(b, from), bt = tippe_sweep_band_at(b, to);
            double w = to - from - bf - bt;
            tippe_build_setting *s = &set[f];
            double best_w = s->reachable ? s->robust_to_mm - s->robust_from_mm : -INFINITY;
            int better = !s->reachable || (w > 0 && w > best_w) ||
                         (!s->robust && w <= 0 && to - from > s->to_mm - s->from_mm);
            if (better) {
                s->reachable = 1;
                s->robust = w > 0;
                s->from_mm = from;
                s->to_mm = to;
                s->band_from_mm = bf;
                s->band_to_mm = bt;
                s->robust_from_mm = from + bf;
                s->robust_to_mm = to - bt;
            }
        }
    }
    for (int f = 0; f < 3; f++) {
        tippe_build_setting *s = &set[f];
        if (!s->reachable)
            continue;
        double a = s->robust ? s->robust_from_mm : s->from_mm;
        double z = s->robust ? s->robust_to_mm : s->to_mm;
        s->set_z2_mm = 0.5 * (a + z);
        /* A run through the balanced point (eps = 0: a balanced ball with no
         * side to rest on, e.g. a symmetric shell's Z2 = 0) is set in the
         * middle of its longer side. */
        for (int k = 0; k < r->n_events; k++) {
            const tippe_sweep_event *e = &r->events[k];
            if (e->boundary != TIPPE_SWEEP_BALANCED || e->z2_mm <= a || e->z2_mm >= z)
                continue;
            s->set_z2_mm = e->z2_mm - a > z - e->z2_mm ? 0.5 * (a + e->z2_mm)
                                                       : 0.5 * (e->z2_mm + z);
            break;
        }
    }
}

/* The zones of d and the robust range of each behaviour (set[] zeroed
 * first), and the physical travel: step 1 of the sheet, and the test the
 * advice puts each change it tries to. */
int tippe_build_zones(const tippe_design *d, tippe_build_setting set[3], double *travel_from_mm,
                      double *travel_to_mm, tippe_error *err)
{
    tippe_sweep_result r;
    tippe_sweep_bands_result b = {0};
    memset(set, 0, 3 * sizeof *set);
    int rc = tippe_sweep_design(d, 0, 0, NULL, &r, err);
    if (!rc)
        rc = tippe_sweep_bands(d, &r, &b, err);
    if (!rc) {
        *travel_from_mm = r.travel_from_mm;
        *travel_to_mm = r.travel_to_mm;
        robust_runs(&r, &b, set);
    }
    tippe_sweep_bands_free(&b);
    tippe_sweep_result_free(&r);
    return rc;
}

/* The sheet's verdict for d with the overrides: 2 settable, 1 3-in-1 on paper
 * only, 0 not 3-in-1, -1 when it does not load or sweep; the settings in set
 * (if not NULL) and their travel. */
int tippe_build_verdict_with(const tippe_design *d, const char *const *ov, int n,
                             double min_setting_mm, tippe_build_zones_of *out)
{
    tippe_design *v = NULL;
    tippe_error e = {0};
    tippe_build_zones_of z;
    int verdict = -1;
    if (!tippe_design_reload(d, ov, n, &v, &e) &&
        !tippe_build_zones(v, z.set, &z.travel_from_mm, &z.travel_to_mm, &e)) {
        int all = 1, wide = 1;
        z.narrowest_mm = INFINITY;
        for (int f = 0; f < 3; f++) {
            double w = z.set[f].reachable && z.set[f].robust
                           ? z.set[f].robust_to_mm - z.set[f].robust_from_mm
                           : 0;
            z.narrowest_mm = fmin(z.narrowest_mm, w);
            all = all && z.set[f].reachable;
            wide = wide && w >= min_setting_mm;
        }
        verdict = !all ? 0 : wide ? 2 : 1;
        if (out)
            *out = z;
    }
    tippe_design_free(v);
    return verdict;
}

const char *tippe_build_verdict_name(int v)
{
    return v == 2 ? "3-in-1 and settable" : v == 1 ? "3-in-1 on paper only" : "not 3-in-1";
}
