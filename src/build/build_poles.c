/* The poles as they are (issue 25.7): where a hole opens at a pole the top
 * standing on that pole rests on the hole's rim, not on the sphere the model
 * rolls. The sheet says which launch checks start or end there, and what a
 * maker can do about it, each fix tried by sweeping the changed design. */
#include "build/internal.h"
#include "tippe/design.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* A printed plug pressed into an opening reaches this far below the hole's
 * rim: its top is shaped to the sphere, the rest grips the hole's wall. A
 * judgement, not from a standard: the sheet says so. */
#define PLUG_GRIP_MM 3.0

static const char *pole_name(int pole) { return pole > 0 ? "+z" : "-z"; }

/* The void part named name and its extent along z, in the design's frame. */
static int void_extent(const tippe_design *d, const char *name, double *lo, double *hi)
{
    for (int i = 0; i < tippe_design_n_parts(d); i++) {
        tippe_design_part_info p;
        tippe_design_solid sd;
        if (tippe_design_part(d, i, &p) || tippe_design_part_solid(d, i, &sd) ||
            strcmp(p.name, name))
            continue;
        if (!sd.is_void || sd.moving || !(sd.height_mm > 0))
            return -1;
        *lo = sd.z_mm - 0.5 * sd.height_mm;
        *hi = sd.z_mm + 0.5 * sd.height_mm;
        return i;
    }
    return -1;
}

/* The moving weight's extent along z about Z2 (its parts' lowest and highest
 * points); 0 if it has no solid part. */
static int weight_extent(const tippe_design *d, double *below, double *above)
{
    int any = 0;
    *below = INFINITY;
    *above = -INFINITY;
    for (int i = 0; i < tippe_design_n_parts(d); i++) {
        tippe_design_solid sd;
        if (tippe_design_part_solid(d, i, &sd) || !sd.moving || sd.is_void)
            continue;
        *below = fmin(*below, sd.z_mm - 0.5 * sd.height_mm);
        *above = fmax(*above, sd.z_mm + 0.5 * sd.height_mm);
        any = 1;
    }
    return any;
}

/* The first part printed as its G-code deposits it (print.gcode): 1 with its name. */
static int gcode_part(const tippe_design *d, char *name, size_t size)
{
    for (int i = 0; i < tippe_design_n_parts(d); i++) {
        tippe_design_part_info p;
        tippe_design_print_info pr;
        if (!tippe_design_part(d, i, &p) && !tippe_design_part_print(d, i, &pr) && pr.printed &&
            pr.from_gcode) {
            snprintf(name, size, "%s", p.name);
            return 1;
        }
    }
    return 0;
}

/* One fix: the hole's void kept between lo and hi, the design's travel cut to
 * where the weight stays inside it (1e-6 mm in from touching), tried as the
 * sheet judges. */
static void try_fix(const tippe_design *d, tippe_build_sheet *s, const char *hole, double lo,
                    double hi, const char *what)
{
    double below, above, t0, t1;
    if (s->n_pole_fixes >= (int)(sizeof s->pole_fix / sizeof s->pole_fix[0]) || !(hi > lo) ||
        !weight_extent(d, &below, &above))
        return;
    tippe_design_travel_mm(d, &t0, &t1);
    t0 = fmax(t0, lo - below + 1e-6);
    t1 = fmin(t1, hi - above - 1e-6);
    typeof(s->pole_fix[0]) *x = &s->pole_fix[s->n_pole_fixes++];
    x->n_set = 3;
    snprintf(x->set[0], sizeof x->set[0], "parts.%s.height_mm=%.9g", hole, hi - lo);
    snprintf(x->set[1], sizeof x->set[1], "parts.%s.z_mm=%.9g", hole, 0.5 * (hi + lo));
    snprintf(x->set[2], sizeof x->set[2], "travel_mm=[%.9g,%.9g]", t0, t1);
    const char *ov[3] = {x->set[0], x->set[1], x->set[2]};
    tippe_build_zones_of z;
    x->verdict = t1 > t0 ? tippe_build_verdict_with(d, ov, 3, s->min_setting_mm, &z) : -1;
    char widths[160] = "";
    for (int f = 0, n = 0; x->verdict >= 0 && f < 3; f++) {
        const tippe_build_setting *st = &z.set[f];
        double w = st->reachable && st->robust ? st->robust_to_mm - st->robust_from_mm : 0;
        n += snprintf(widths + n, sizeof widths - (size_t)n, "%s%s %s", f ? ", " : "",
                      behaviours[f],
                      !st->reachable ? "lost" : st->robust ? "" : "no robust range");
        if (st->reachable && st->robust && n < (int)sizeof widths)
            n += snprintf(widths + n, sizeof widths - (size_t)n, "%.2f mm", w);
        if (n >= (int)sizeof widths)
            break;
    }
    x->narrowest_mm = x->verdict >= 0 ? z.narrowest_mm : NAN;
    char gpart[64];
    int n;
    if (!(t1 > t0))
        n = snprintf(x->text, sizeof x->text, "%s: no room is left for the weight.", what);
    else if (x->verdict < 0 && gcode_part(d, gpart, sizeof gpart))
        /* the G-code's deposit is matched to the part as printed (design_printed.c): a plug
         * changes the part, not the G-code, so the changed design cannot load with it */
        n = snprintf(x->text, sizeof x->text,
                     "%s: the changed design does not load or sweep: '%s' is printed as its "
                     "G-code deposits it, sliced without the fix; slice the fixed design and "
                     "give its G-code.",
                     what, gpart);
    else if (x->verdict < 0)
        n = snprintf(x->text, sizeof x->text, "%s: the changed design does not load or sweep.",
                     what);
    else
        n = snprintf(x->text, sizeof x->text,
                     "%s (the hole then spans z = %.2f .. %.2f mm): the weight's travel becomes "
                     "%.2f .. %.2f mm and the top %s (robust ranges: %s). Set the screw by this "
                     "sheet's depths before the plug goes in: the changed design models the plug "
                     "as part of the body, so its own sheet has no rim to measure from.",
                     what, lo, hi, t0, t1,
                     tippe_build_verdict_name(x->verdict), widths);
    (void)n; /* text[] holds the sentence; a cut one still reads */
}

/* The open poles at the drawn setting, the warning when a launch check starts
 * or ends on one (the zones and the checks assume the sphere there), and the
 * fixes: plug every opening, or, for a hole open at both poles, only the one
 * the top rests on (a blind hole from the other pole). Each fix is judged by
 * the sheet's own test, so its verdict is what the changed design's sheet says. */
void tippe_build_poles(const tippe_design *d, tippe_build_sheet *s)
{
    double z2 = NAN;
    for (int f = 2; f >= 0; f--)
        if (s->set[f].reachable)
            z2 = s->set[f].set_z2_mm;
    if (!isfinite(z2))
        z2 = 0.5 * (s->travel_from_mm + s->travel_to_mm);
    s->n_caps = tippe_design_polar_caps(d, z2, s->caps);
    if (!s->n_caps)
        return;
    /* the model's hole is the design's; a tapped hole opens at the thread's
     * diameter, one with an insert at the insert's knurl (what the top stands on) */
    tippe_design_part_info hp;
    double made = s->hole_tapped && s->has_thread ? s->thread.d_mm
                  : s->hole_insert                ? s->insert.outer_max_mm
                                                  : 0;
    for (int k = 0; k < 2 && made > 0 && made < 2 * s->radius_mm; k++)
        if (s->caps[k].half_angle_rad > 0 && s->hole_part >= 0 &&
            !tippe_design_part(d, s->hole_part, &hp) && !strcmp(hp.name, s->caps[k].part)) {
            s->cap_made_mm[k] = made;
            s->cap_made_half_angle_rad[k] = asin(0.5 * made / s->radius_mm);
        }
    /* the launch checks that start or end on an opening's rim */
    char which[200] = "";
    int rest = 0;
    for (int f = 0, n = 0; f < 3; f++) {
        const tippe_build_setting *st = &s->set[f];
        if (!st->reachable || st->launch_status)
            continue;
        if (!rest)
            rest = st->rest_pole;
        if (!st->launch_cap_start && !st->launch_cap_end)
            continue;
        n += snprintf(which + n, sizeof which - (size_t)n, "%s%s (%s %s)", n ? ", " : "",
                      behaviours[f],
                      st->launch_cap_start ? "starts on" : "ends on",
                      pole_name(st->launch_cap_start ? st->launch_cap_start : st->launch_cap_end));
        if (n >= (int)sizeof which)
            break;
    }
    const tippe_design_cap *c = s->caps[0].half_angle_rad > 0 ? &s->caps[0] : &s->caps[1];
    if (which[0] && s->n_warnings < 6)
        snprintf(s->warning[s->n_warnings++], sizeof s->warning[0],
                 "On the rim in the launch checks of %s: the hole '%s' (%.2f mm) opens at the "
                 "pole, so a top tilted less than %.1f deg on it stands on its rim. The checks "
                 "follow the rim; the zones (the paper's theory) assume the sphere there. The "
                 "poles' fixes restore the sphere.",
                 which, c->part, 2 * c->radius_mm, c->half_angle_rad * 180 / M_PI);
    /* the fixes: plug every opening; for a hole open at both poles, plug only
     * the one the top rests on (a blind hole from the other pole) */
    double lo, hi, R = s->radius_mm;
    if (void_extent(d, c->part, &lo, &hi) < 0)
        return;
    int top_open = s->caps[0].half_angle_rad > 0 && !strcmp(s->caps[0].part, c->part);
    int bot_open = s->caps[1].half_angle_rad > 0 && !strcmp(s->caps[1].part, c->part);
    double rim_top = sqrt(fmax(0, R * R - s->caps[0].radius_mm * s->caps[0].radius_mm));
    double rim_bot = sqrt(fmax(0, R * R - s->caps[1].radius_mm * s->caps[1].radius_mm));
    double hi_plug = top_open ? rim_top - PLUG_GRIP_MM : hi;
    double lo_plug = bot_open ? -rim_bot + PLUG_GRIP_MM : lo;
    char what[200];
    snprintf(what, sizeof what,
             "Plug %s of '%s' with a printed plug, its top shaped to the sphere, reaching %.0f mm "
             "below the rim",
             top_open && bot_open ? "both openings" : top_open ? "the +z opening"
                                                            : "the -z opening",
             c->part, PLUG_GRIP_MM);
    try_fix(d, s, c->part, lo_plug, hi_plug, what);
    if (top_open && bot_open && rest) {
        snprintf(what, sizeof what,
                 "Make '%s' a blind hole from the %s pole (plug or print shut the %s opening, "
                 "the pole the top rests on, %.0f mm below its rim)",
                 c->part, pole_name(-rest), pole_name(rest), PLUG_GRIP_MM);
        try_fix(d, s, c->part, rest < 0 ? lo_plug : lo, rest > 0 ? hi_plug : hi, what);
    }
}
