/* What would make a design 3-in-1: single changes searched and checked by
 * sweeping the changed design. */
#include "build/internal.h"
#include "base/json.h"
#include "tippe/physics.h"
#include "tippe/profile.h"
#include "tippe/sweep.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------------------ 3-in-1 search */

/* 1 if the design with field=value is 3-in-1 within its physical travel, 0 if
 * not, -1 if it does not load (a layout the value breaks). */
static int three_in_one_at(const tippe_design *d, const tippe_build_options *o,
                           const char *field, double value)
{
    /* d's own overrides (o->sets, as loaded) come with it */
    char set[512];
    snprintf(set, sizeof set, "%s=%.10g", field, value);
    const char *ov[1] = {set};
    tippe_design *v = NULL;
    tippe_error e = {0};
    if (tippe_design_reload(d, ov, 1, &v, &e))
        return -1;
    tippe_sweep_result r;
    int yes = -1;
    if (tippe_sweep_design(v, 0, 0, NULL, &r, &e) == TIPPE_OK) {
        tippe_sweep_summary sm;
        tippe_sweep_summarise(&r, &sm);
        yes = sm.three_in_one;
    }
    tippe_sweep_result_free(&r);
    tippe_design_free(v);
    return yes;
}

/* Scans field over [lo, hi]; the 3-in-1 value nearest now, its edge bisected.
 * 1 found (advice filled), 0 none. */
static int search(const tippe_design *d, const tippe_build_options *o, const char *field,
                  double now, double lo, double hi, tippe_build_sheet *s)
{
    enum { N = 24 };
    int yes[N + 1];
    double x[N + 1];
    for (int i = 0; i <= N; i++) {
        x[i] = lo + (hi - lo) * i / N;
        yes[i] = three_in_one_at(d, o, field, x[i]);
    }
    int best = -1;
    for (int i = 0; i <= N; i++)
        if (yes[i] == 1 && (best < 0 || fabs(x[i] - now) < fabs(x[best] - now)))
            best = i;
    if (best < 0 || s->n_advice >= 6)
        return 0;
    /* the neighbour towards now that is not 3-in-1: bisect between them */
    int towards = x[best] > now ? best - 1 : best + 1;
    double edge = x[best];
    int at_least = x[best] > now;
    if (towards >= 0 && towards <= N && yes[towards] != 1) {
        double a = x[towards], b = x[best]; /* a: not, b: yes */
        while (fabs(b - a) > 1e-3 * (hi - lo)) {
            double m = 0.5 * (a + b);
            if (three_in_one_at(d, o, field, m) == 1)
                b = m;
            else
                a = m;
        }
        edge = b;
    }
    int k = s->n_advice++;
    snprintf(s->advice[k].field, sizeof s->advice[k].field, "%s", field);
    s->advice[k].now = now;
    s->advice[k].value = edge;
    s->advice[k].at_least = at_least;
    return 1;
}

void tippe_build_advise(const tippe_design *d, const tippe_build_options *o, tippe_build_sheet *s)
{
    char field[200];
    for (int i = 0; i < tippe_design_n_parts(d); i++) {
        tippe_design_part_info p;
        tippe_design_print_info pr;
        tippe_design_solid sd;
        if (tippe_design_part(d, i, &p) || tippe_design_part_print(d, i, &pr) ||
            tippe_design_part_solid(d, i, &sd))
            continue;
        int k = s->n_advice;
        if (pr.printed && !pr.calibrated) {
            snprintf(field, sizeof field, "parts.%s.print.infill", p.name);
            if (search(d, o, field, pr.infill, 0, 1, s))
                snprintf(s->advice[k].text, sizeof s->advice[k].text,
                         "3-in-1 at %s %.1f %% infill of '%s' (the slicer's %.0f %%): print at "
                         "that infill (weighing a print says how much plastic it holds, not "
                         "where: it cannot show that this one is 3-in-1; its G-code can, "
                         "tippe slice)",
                         s->advice[k].at_least ? "or above" : "or below",
                         100 * s->advice[k].value, p.name, 100 * pr.infill);
        } else if (pr.printed) {
            snprintf(field, sizeof field, "parts.%s.print.measured_mass_g", p.name);
            if (search(d, o, field, pr.measured_mass_kg * 1e3, pr.skin_mass_kg * 1e3,
                       pr.solid_mass_kg * 1e3, s))
                snprintf(s->advice[k].text, sizeof s->advice[k].text,
                         "3-in-1 if '%s' weighs %s %.2f g (weighed %.2f g): print it at a %s "
                         "infill",
                         p.name, s->advice[k].at_least ? "at least" : "at most",
                         s->advice[k].value, pr.measured_mass_kg * 1e3,
                         s->advice[k].at_least ? "denser" : "sparser");
        } else if (sd.moving && !sd.is_void) {
            snprintf(field, sizeof field, "parts.%s.density_g_cm3", p.name);
            if (search(d, o, field, p.density_g_cm3, 1, 22, s))
                snprintf(s->advice[k].text, sizeof s->advice[k].text,
                         "3-in-1 with a %s weight: density %s %.2f g/cm^3 for '%s' (now %.2f, "
                         "%s)",
                         s->advice[k].at_least ? "heavier" : "lighter",
                         s->advice[k].at_least ? "at least" : "at most", s->advice[k].value,
                         p.name, p.density_g_cm3, p.material);
            k = s->n_advice;
            if ((!strcmp(sd.shape, "cylinder") || !strcmp(sd.shape, "tube"))) {
                snprintf(field, sizeof field, "parts.%s.height_mm", p.name);
                if (search(d, o, field, sd.height_mm, 0.5 * sd.height_mm, 2 * sd.height_mm, s))
                    snprintf(s->advice[k].text, sizeof s->advice[k].text,
                             "3-in-1 with a %s weight: '%s' %s %.2f mm long (now %.4g mm)",
                             s->advice[k].at_least ? "longer" : "shorter", p.name,
                             s->advice[k].at_least ? "at least" : "at most",
                             s->advice[k].value, sd.height_mm);
            }
        }
    }
}

/* The print model's mass of the hole's part with the hole as printed, against
 * the mass model's hole: what a scale reading of the print lacks (or has too
 * much) for calibrating the design (measured_mass_g describes the design's
 * part). The derived design is geometry only (tippe_design_derive), so a hole
 * narrower than the screw (a tap drill) is allowed. */
double tippe_build_hole_model_radius(const tippe_design *d, int i)
{
    tippe_design_solid hs;
    return tippe_design_part_solid(d, i, &hs) ? NAN : hs.radius_mm;
}

void tippe_build_weigh_offset(const tippe_design *d, tippe_build_sheet *s)
{
    tippe_design_solid hs;
    tippe_design_part_info hp, pp;
    tippe_design_print_info before, after;
    if (s->measure != TIPPE_BUILD_MEASURE_HOLE || s->hole_part < 0 ||
        tippe_design_part_solid(d, s->hole_part, &hs) || hs.parent < 0 ||
        tippe_design_part(d, s->hole_part, &hp) || tippe_design_part(d, hs.parent, &pp) ||
        tippe_design_part_print(d, hs.parent, &before) || !before.printed)
        return;
    /* the print's hole, at the same infill (a calibrated design's, the one solved,
     * with the weighing taken out so that it is not solved again) */
    char set[3][300];
    snprintf(set[0], sizeof set[0], "parts.%s.radius_mm=%.10g", hp.name, s->hole_diameter_mm / 2);
    snprintf(set[1], sizeof set[1], "parts.%s.print.infill=%.17g", pp.name, before.infill);
    snprintf(set[2], sizeof set[2], "parts.%s.print.measured_mass_g=null", pp.name);
    const char *extra[3] = {set[0], set[1], set[2]};
    tippe_design *v = NULL;
    tippe_error e = {0};
    if (tippe_design_derive(d, extra, before.calibrated ? 3 : 2, &v, &e) == TIPPE_OK &&
        tippe_design_part_print(v, hs.parent, &after) == TIPPE_OK && after.printed)
        s->weigh_offset_g = (before.printed_mass_kg - after.printed_mass_kg) * 1e3;
    tippe_design_free(v);
}
