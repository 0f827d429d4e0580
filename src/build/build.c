/* Build sheet: robust settings in measurable units, spins, launch verdicts, BOM. */
#include "build/internal.h"

#include "tippe/profile.h"
#include "tippe/sweep.h"
#include "tippe/launch.h"
#include "tippe/design.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *tippe_build_behaviour(int f) { return f >= 0 && f < 3 ? behaviours[f] : "?"; }
const char *tippe_build_family(int f) { return f >= 0 && f < 3 ? families[f] : "?"; }

/* The verdict the behaviour's launch should end in. */
static tippe_verdict expected_verdict(int f)
{
    return f == 0 ? TIPPE_VERDICT_NO_TIP : f == 1 ? TIPPE_VERDICT_TIP : TIPPE_VERDICT_HANG;
}

void tippe_build_options_default(tippe_build_options *o)
{
    memset(o, 0, sizeof *o);
    o->clearance_mm = tippe_profile_defaults().clearance_mm;
    o->hole_fit = TIPPE_BUILD_HOLE_DESIGN;
    tippe_launch_options_default(&o->launch);
}


/* ------------------------------------------------------------ measuring */

/* Extent of the moving group above and below Z2 (mm), its outer radius and
 * the smallest bore of its tubes (0 if none). */
static void weight_extent(const tippe_design *d, double *top, double *bottom, double *r_out,
                          double *bore, char *name, size_t name_size)
{
    *top = -INFINITY;
    *bottom = INFINITY;
    *r_out = 0;
    *bore = 0;
    name[0] = '\0';
    for (int i = 0; i < tippe_design_n_parts(d); i++) {
        tippe_design_solid s;
        tippe_design_part_info p;
        if (tippe_design_part_solid(d, i, &s) || tippe_design_part(d, i, &p) || !s.moving ||
            s.is_void)
            continue;
        double half = 0, r = 0;
        if (!strcmp(s.shape, "cylinder") || !strcmp(s.shape, "tube")) {
            half = s.height_mm / 2;
            r = s.radius_mm;
            if (s.inner_radius_mm > 0 && (*bore == 0 || s.inner_radius_mm < *bore))
                *bore = s.inner_radius_mm;
        } else if (!strcmp(s.shape, "torus")) {
            half = s.axial_semi_mm;
            r = s.centre_radius_mm + s.radial_semi_mm;
        } else {
            half = r = s.radius_mm;
        }
        *top = fmax(*top, s.z_mm + half);
        *bottom = fmin(*bottom, s.z_mm - half);
        *r_out = fmax(*r_out, r);
        if (!name[0])
            snprintf(name, name_size, "%s", p.name);
    }
}

/* A hole that takes the weight: an axial cylinder void of a printed body, grown
 * by the clearance, wide enough for it and open at one pole. */
static int find_hole(const tippe_design *d, const tippe_profile_set *ps, double clearance_mm,
                     double r_weight, tippe_build_sheet *out)
{
    double R = tippe_design_radius_mm(d);
    for (int i = 0; ps && i < ps->n_parts; i++) {
        tippe_design_solid s;
        tippe_design_part_info p;
        if (!ps->clearance_applied[i] || tippe_design_part_solid(d, i, &s) ||
            tippe_design_part(d, i, &p) || s.moving || strcmp(s.shape, "cylinder") ||
            s.radius_mm < r_weight - 1e-9 || s.radius_mm + clearance_mm >= R)
            continue;
        double a = s.radius_mm + clearance_mm;
        double rim = sqrt(R * R - a * a); /* where the hole's wall meets the sphere */
        double top = s.z_mm + s.height_mm / 2, bottom = s.z_mm - s.height_mm / 2;
        int up = top >= rim - 1e-9, down = bottom <= -rim + 1e-9;
        if (!up && !down)
            continue;
        out->measure = TIPPE_BUILD_MEASURE_HOLE;
        out->reference_up = up;
        out->reference_z_mm = up ? rim : -rim;
        out->hole_diameter_mm = 2 * a;
        out->hole_part = i;
        snprintf(out->reference, sizeof out->reference,
                 "the rim of hole '%s' at the %s pole (printed diameter %.2f mm), where a "
                 "caliper's depth rod rests",
                 p.name, up ? "top (+z)" : "bottom (-z)", 2 * a);
        return 1;
    }
    return 0;
}

/* A tap or insert fit belongs on the hole the weight's screw enters (hole,
 * -1: none): any other hole with one is an error naming the field. */
static int check_fits(const tippe_design *d, int hole, tippe_error *err)
{
    for (int i = 0; i < tippe_design_n_parts(d); i++) {
        int fit = tippe_design_part_fit(d, i);
        if (i == hole || fit == TIPPE_DESIGN_FIT_NONE || fit == TIPPE_DESIGN_FIT_SLIDE)
            continue;
        tippe_design_part_info p;
        tippe_design_part(d, i, &p);
        return tippe_error_set(err, TIPPE_EINPUT,
                               "%s: parts[%d].fit: \"%s\" on hole '%s', which no screw of the "
                               "weight enters (a tap or insert fit is for the axial hole the "
                               "weight is screwed into, open at a pole)",
                               tippe_design_path(d), i,
                               fit == TIPPE_DESIGN_FIT_TAP ? "tap" : "insert", p.name);
    }
    return TIPPE_OK;
}

/* The printed diameter of hole part for a tap or insert fit on thread t. */
static int fit_diameter(const tippe_design *d, int part, tippe_build_hole_fit fit,
                        int from_design, const tippe_build_thread *t, const char *tname,
                        double *dia, char *note, size_t note_size,
                        const tippe_build_insert **ins, tippe_error *err)
{
    *ins = NULL;
    if (fit == TIPPE_BUILD_HOLE_TAP) {
        *dia = tippe_build_tap_drill_mm(t);
        snprintf(note, note_size, "%s x %g tap drill", tname, t->pitch_mm);
        return TIPPE_OK;
    }
    *ins = tippe_build_insert_for(tname);
    if (!*ins && !from_design)
        return tippe_error_set(err, TIPPE_EINPUT,
                               "%s: --hole insert: no heat-set insert for the screw's %s thread "
                               "in the table (M3 .. M6, from %s); use tap or slide",
                               tippe_design_path(d), tname, TIPPE_BUILD_INSERT_SOURCE);
    if (!*ins)
        return tippe_error_set(err, TIPPE_EINPUT,
                               "%s: parts[%d].fit: \"insert\": no heat-set insert for the "
                               "screw's %s thread in the table (M3 .. M6, from %s); use \"tap\" "
                               "or \"slide\"",
                               tippe_design_path(d), part, tname, TIPPE_BUILD_INSERT_SOURCE);
    *dia = (*ins)->pilot_mm;
    snprintf(note, note_size, "%s heat-set insert's hole", tname);
    return TIPPE_OK;
}

int tippe_build_design_fit(const tippe_design *d, double clearance_mm, int *part,
                           double *diameter_mm, char *note, size_t note_size, tippe_error *err)
{
    *part = -1;
    *diameter_mm = 0;
    if (note_size)
        note[0] = '\0';
    double top, bottom, r_weight, bore;
    char name[128];
    weight_extent(d, &top, &bottom, &r_weight, &bore, name, sizeof name);
    tippe_profile_options po = tippe_profile_defaults();
    po.clearance_mm = clearance_mm;
    tippe_profile_set ps;
    tippe_error perr = {0};
    int have_ps = tippe_profile_build(d, &po, &ps, &perr) == TIPPE_OK;
    tippe_build_sheet *s = calloc(1, sizeof *s);
    if (!s) {
        if (have_ps)
            tippe_profile_set_free(&ps);
        return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    }
    s->hole_part = -1;
    s->radius_mm = tippe_design_radius_mm(d);
    if (isfinite(top))
        find_hole(d, have_ps ? &ps : NULL, clearance_mm, r_weight, s);
    if (have_ps)
        tippe_profile_set_free(&ps);
    int hole = s->hole_part;
    free(s);
    int rc = check_fits(d, hole, err);
    tippe_design_solid hs;
    if (!rc && hole >= 0 && !tippe_design_part_solid(d, hole, &hs) && hs.printed_radius_mm > 0 &&
        !hs.printed_radius_from_fit && tippe_design_part_fit(d, hole) != TIPPE_DESIGN_FIT_INSERT) {
        /* printed where the design says (printed_radius_mm), then cut to its radius */
        *part = hole;
        *diameter_mm = 2 * hs.printed_radius_mm;
        snprintf(note, note_size, "the design's printed_radius_mm");
        return TIPPE_OK;
    }
    int fit = hole >= 0 ? tippe_design_part_fit(d, hole) : TIPPE_DESIGN_FIT_NONE;
    if (rc || (fit != TIPPE_DESIGN_FIT_TAP && fit != TIPPE_DESIGN_FIT_INSERT))
        return rc;
    /* the screw is modelled as a cylinder of its pitch diameter (the
     * catalogue's convention), as tippe_build_compute assumes without a
     * catalogue match */
    const tippe_build_thread *t = tippe_build_thread_by_pitch_diameter(2 * r_weight);
    const tippe_build_insert *ins;
    rc = fit_diameter(d, hole,
                      fit == TIPPE_DESIGN_FIT_TAP ? TIPPE_BUILD_HOLE_TAP : TIPPE_BUILD_HOLE_INSERT,
                      1, t, t->name, diameter_mm, note, note_size, &ins, err);
    if (!rc)
        *part = hole;
    return rc;
}

/* A fixed rod the weight is threaded on: a hardware cylinder on the axis that
 * fits its bore. */
static int find_rod(const tippe_design *d, double bore, double *rod_r, int *rod_part,
                    tippe_build_sheet *out)
{
    for (int i = 0; bore > 0 && i < tippe_design_n_parts(d); i++) {
        tippe_design_solid s;
        tippe_design_part_info p;
        tippe_design_print_info pr;
        if (tippe_design_part_solid(d, i, &s) || tippe_design_part(d, i, &p) ||
            tippe_design_part_print(d, i, &pr) || s.moving || s.is_void || p.printable ||
            pr.printed || strcmp(s.shape, "cylinder") || s.inner_radius_mm > 0 ||
            s.radius_mm > bore + 1e-6)
            continue;
        double top = s.z_mm + s.height_mm / 2;
        if (s.clip_radius_mm > 0)
            top = fmin(top, sqrt(s.clip_radius_mm * s.clip_radius_mm - s.radius_mm * s.radius_mm));
        out->measure = TIPPE_BUILD_MEASURE_ROD;
        out->reference_up = 1;
        out->reference_z_mm = top;
        *rod_r = s.radius_mm;
        *rod_part = i;
        out->rod_diameter_mm = 2 * s.radius_mm;
        snprintf(out->reference, sizeof out->reference, "the top (+z) end of rod '%s'", p.name);
        return 1;
    }
    return 0;
}

/* depth below the reference of the weight's measured end at Z2 (mm) */
static double depth_at(const tippe_build_sheet *s, double z2_mm)
{
    if (s->measure == TIPPE_BUILD_MEASURE_NONE)
        return NAN;
    double end = z2_mm + s->weight_end_offset_mm;
    return s->reference_up ? s->reference_z_mm - end : end - s->reference_z_mm;
}

/* --------------------------------------------------------- catalogue */

/* The catalogue item the weight is: the one its part names ("catalogue_item",
 * which must be in the catalogue and of the part's radius and height), else
 * the one with the screw's radius and height. 1 matched, 0 not, or a status
 * < 0 with err set if the file does not read or the named item is wrong. */
static int match_catalogue(const tippe_design *d, const tippe_build_options *o, int named,
                           double r_mm, double h_mm, tippe_build_sheet *out, tippe_error *err)
{
    tippe_build_catalogue *own = NULL;
    const tippe_build_catalogue *c = o->catalogue_read;
    const char *file = o->catalogue ? o->catalogue : tippe_design_catalogue(d);
    const char *name = named >= 0 ? tippe_design_part_catalogue_item(d, named) : NULL;
    if (!c && !file)
        return -tippe_error_set(err, TIPPE_EINPUT,
                                "%s: parts[%d].catalogue_item: '%s' names an item, but no "
                                "catalogue is given (the design's \"catalogue\", --catalogue "
                                "or catalogue.json beside the design)",
                                tippe_design_path(d), named, name);
    if (!c) {
        int rc = tippe_build_catalogue_load(file, &own, err);
        if (rc)
            return -rc;
        c = own;
    }
    const tippe_build_catalogue_set *set = NULL;
    const tippe_build_catalogue_item *it = NULL;
    int rc = TIPPE_OK;
    tippe_design_solid ws;
    if (name && !tippe_design_part_solid(d, named, &ws)) {
        /* the named part itself (the weight may have more parts) */
        r_mm = ws.radius_mm;
        h_mm = ws.height_mm;
    }
    if (name) {
        it = tippe_build_catalogue_find(c, name, &set);
        if (!it)
            rc = tippe_error_set(err, TIPPE_EINPUT,
                                 "%s: parts[%d].catalogue_item: '%s' is not an item of the "
                                 "catalogue %s",
                                 tippe_design_path(d), named, name, c->file);
        else if (fabs(it->radius_mm - r_mm) > 1e-6 || fabs(it->height_mm - h_mm) > 1e-6)
            rc = tippe_error_set(err, TIPPE_EINPUT,
                                 "%s: parts[%d].catalogue_item: '%s' of %s is modelled %g mm in "
                                 "radius and %g mm long, the part %g and %g mm: change the part "
                                 "or name another item (--set parts.NAME.catalogue_item=null "
                                 "to name none)",
                                 tippe_design_path(d), named, name, c->file, it->radius_mm,
                                 it->height_mm, r_mm, h_mm);
    } else {
        it = tippe_build_catalogue_match(c, r_mm, h_mm, &set);
    }
    if (!rc && it) {
        const tippe_build_thread *iso = tippe_build_thread_by_diameter(it->d_mm);
        snprintf(out->thread_name, sizeof out->thread_name, "%s", iso ? iso->name : it->thread);
        out->thread.d_mm = it->d_mm;
        out->thread.pitch_mm = it->pitch_mm; /* the catalogue's */
        snprintf(out->catalogue_item, sizeof out->catalogue_item, "%s", it->name);
        snprintf(out->catalogue_title, sizeof out->catalogue_title, "%s", set->title);
    }
    tippe_build_catalogue_free(own);
    return rc ? -rc : it != NULL;
}

/* The weight's part that names a catalogue item, or -1. */
static int named_weight(const tippe_design *d)
{
    for (int i = 0; i < tippe_design_n_parts(d); i++) {
        tippe_design_solid s;
        if (!tippe_design_part_solid(d, i, &s) && s.moving && !s.is_void &&
            tippe_design_part_catalogue_item(d, i)[0])
            return i;
    }
    return -1;
}

/* ------------------------------------------------------------- spins */

/* The spin (rad/s) family f needs at Z2, from Theorem 5.1's thresholds; 0 for
 * any spin, INFINITY where none suffices. */
static int spin_needed(const tippe_design *d, int f, double z2_mm, double g, double *rad_s,
                       const char **rule, tippe_error *err)
{
    tippe_top top;
    tippe_theory_thresholds th;
    int rc = tippe_design_top(d, z2_mm, &top, err);
    if (!rc)
        rc = tippe_theory_compute_thresholds(&top, g, &th, err);
    if (rc)
        return rc;
    if (f == 0) {
        *rad_s = 0;
        *rule = "any spin: theta = 0 is stable at every spin (group I)";
    } else if (f == 1) {
        /* theta = 0 must be unstable (n0 > n-, A.14) and theta = pi stable for
         * the launch's Jellett (n0 > n*, section 7.1) */
        double n = th.has_n_minus ? th.n_minus_rad_s : 0;
        if (th.has_n_star)
            n = fmax(n, th.n_star_rad_s);
        *rad_s = th.has_n_star ? n : INFINITY;
        *rule = "above n* (theta = pi stable for the launch's Jellett) and n- (theta = 0 unstable)";
    } else {
        *rad_s = th.has_n_minus ? th.n_minus_rad_s : INFINITY;
        *rule = "above n- (theta = 0 unstable; theta = pi never stable in group III)";
    }
    return TIPPE_OK;
}

/* The needed spin (rad/s) of family f at Z2; NAN where it cannot be computed. */
static double needed_at(const tippe_design *d, int f, double z2_mm, double g)
{
    double n = NAN;
    const char *rule;
    tippe_error e = {0};
    if (spin_needed(d, f, z2_mm, g, &n, &rule, &e) != TIPPE_OK)
        return NAN;
    return n;
}

/* The part of [a, b] whose needed spin is at most hand (rad/s), from the 21
 * samples n[] over it: the longest run of samples within reach, each end that
 * borders a sample beyond it bisected to 1e-9 of the range. NAN: none. */
static void hand_part(const tippe_design *d, int f, double g, double a, double b,
                      const double n[21], double hand, double *from, double *to)
{
    int best = -1, best_len = 0;
    for (int k = 0; k <= 20;) {
        if (!(n[k] <= hand)) {
            k++;
            continue;
        }
        int j = k;
        while (j + 1 <= 20 && n[j + 1] <= hand)
            j++;
        if (j - k + 1 > best_len) {
            best = k;
            best_len = j - k + 1;
        }
        k = j + 1;
    }
    *from = *to = NAN;
    if (best < 0)
        return;
    int lo = best, hi = best + best_len - 1;
    double z_lo = a + (b - a) * lo / 20.0, z_hi = a + (b - a) * hi / 20.0;
    if (lo > 0) { /* between lo - 1 (beyond) and lo (within) */
        double x = a + (b - a) * (lo - 1) / 20.0, y = z_lo;
        while (y - x > 1e-9 * (b - a))
            if (needed_at(d, f, 0.5 * (x + y), g) <= hand)
                y = 0.5 * (x + y);
            else
                x = 0.5 * (x + y);
        z_lo = y;
    }
    if (hi < 20) { /* between hi (within) and hi + 1 (beyond) */
        double x = z_hi, y = a + (b - a) * (hi + 1) / 20.0;
        while (y - x > 1e-9 * (b - a))
            if (needed_at(d, f, 0.5 * (x + y), g) <= hand)
                x = 0.5 * (x + y);
            else
                y = 0.5 * (x + y);
        z_hi = x;
    }
    *from = z_lo;
    *to = z_hi;
}

static void spins_and_launch(const tippe_design *d, const tippe_build_options *o, int f,
                             tippe_build_setting *s)
{
    const double rev = 2 * M_PI;
    tippe_error e = {0};
    double n_set = NAN, n_max = 0, n_at[21];
    if (spin_needed(d, f, s->set_z2_mm, o->launch.g, &n_set, &s->spin_rule, &e))
        n_set = NAN;
    double a = s->robust ? s->robust_from_mm : s->from_mm;
    double b = s->robust ? s->robust_to_mm : s->to_mm;
    /* 21 points: the thresholds are smooth in Z2 and monotone over a zone's
     * middle; their maximum is at an end or near it */
    for (int k = 0; k <= 20; k++) {
        n_at[k] = needed_at(d, f, a + (b - a) * k / 20.0, o->launch.g);
        n_max = fmax(n_max, n_at[k]); /* fmax skips a NAN (not computed) */
    }
    s->hand_from_mm = s->hand_to_mm = NAN;
    if (f > 0)
        hand_part(d, f, o->launch.g, a, b, n_at, o->launch.spin_to_rev_s * rev, &s->hand_from_mm,
                  &s->hand_to_mm);
    s->spin_needed_rev_s = n_set / rev;
    s->spin_needed_max_rev_s = n_max / rev;
    /* The check's spin: the hand's middle spin for group I; else a quarter above
     * what the set Z2 needs (a threshold is a bifurcation: exactly on it the
     * outcome is marginal). */
    double mid = 0.5 * (o->launch.spin_from_rev_s + o->launch.spin_to_rev_s);
    s->spin_launch_rev_s = f == 0 ? mid : 1.25 * s->spin_needed_rev_s;
    s->beyond_hand = !(s->spin_launch_rev_s <= o->launch.spin_to_rev_s);
    s->verdict = TIPPE_VERDICT_UNDECIDED;
    if (!isfinite(s->spin_launch_rev_s)) {
        s->launch_status = TIPPE_EINPUT;
        return;
    }
    tippe_top top;
    tippe_dynamics_initial ic;
    tippe_launch_record rec;
    tippe_launch_options lo = o->launch;
    int rc = tippe_design_top(d, s->set_z2_mm, &top, &e);
    if (!rc) {
        tippe_launch_polar_caps(d, s->set_z2_mm, &top, lo.cap_half_angle_rad);
        rc = tippe_launch_central(&top, &lo, s->spin_launch_rev_s * rev, &ic, &e);
    }
    if (!rc)
        rc = tippe_launch_run_initial(&top, &lo, &ic, &rec, &e);
    s->launch_status = rc;
    if (!rc) {
        s->verdict = rec.verdict;
        s->launch_t_s = rec.t_s;
        s->verdict_ok = rec.verdict == expected_verdict(f);
        /* where the launch starts and ends against the poles' openings (issue
         * 25.7): on a hole's rim, which the launch follows (issue 35) and the
         * zones' sphere theory does not */
        tippe_design_cap caps[2];
        tippe_design_polar_caps(d, s->set_z2_mm, caps);
        int side = top.com_side ? top.com_side : 1;
        s->launch_theta0_rad = ic.theta;
        s->launch_theta_end_rad = rec.theta_final_rad;
        s->launch_cap_start = tippe_design_cap_at_tilt(caps, side, ic.theta);
        s->launch_cap_end = isfinite(rec.theta_final_rad)
                                ? tippe_design_cap_at_tilt(caps, side, rec.theta_final_rad)
                                : 0;
        s->rest_pole = side;
        s->launch_cap_time_s = rec.cap_time_s;
    }
}

/* ------------------------------------------------------------ compute */

/* What tippe_build_compute's steps share: the design, the options, the sheet
 * being filled, the printed profiles (when GEOS could build them) and the
 * weight's extent along the axis. */
typedef struct {
    const tippe_design *d;
    const tippe_build_options *o;
    tippe_build_sheet *out;
    tippe_profile_set ps;
    int have_ps;
    double top, bottom, r_weight, bore, rod_r; /* mm */
    int rod_part;
    int launched; /* the settings' launches ran (the hand's part of each range is known) */
} compute_ctx;

/* Step 1: the zones, and the robust range of each behaviour. */
static int compute_zones(compute_ctx *c, tippe_error *err)
{
    tippe_build_sheet *out = c->out;
    int rc = tippe_build_zones(c->d, out->set, &out->travel_from_mm, &out->travel_to_mm, err);
    if (rc)
        return rc;
    out->three_in_one = out->set[0].reachable && out->set[1].reachable && out->set[2].reachable;
    return TIPPE_OK;
}

/* Step 2: where the weight is measured from (a hole's rim or a rod's end). */
static void compute_reference(compute_ctx *c)
{
    tippe_build_sheet *out = c->out;
    weight_extent(c->d, &c->top, &c->bottom, &c->r_weight, &c->bore, out->weight_name,
                  sizeof out->weight_name);
    tippe_profile_options po = tippe_profile_defaults();
    po.clearance_mm = c->o->clearance_mm;
    po.sockets = 1; /* a rod spanning a cavity gets them (tippe build exports them so) */
    tippe_error perr = {0};
    c->have_ps = tippe_profile_build(c->d, &po, &c->ps, &perr) == TIPPE_OK;
    c->rod_part = -1;
    if (isfinite(c->top) &&
        !find_hole(c->d, c->have_ps ? &c->ps : NULL, c->o->clearance_mm, c->r_weight, out) &&
        find_rod(c->d, c->bore, &c->rod_r, &c->rod_part, out)) {
        /* a rod held by sockets is cut longer: its top end is the upper socket's floor */
        for (int k = 0; c->have_ps && k < c->ps.n_sockets; k++)
            if (c->ps.socket_part[k] == c->rod_part && c->ps.socket_floor_z_mm[k] > 0) {
                out->reference_z_mm = c->ps.socket_floor_z_mm[k];
                snprintf(out->reference + strlen(out->reference),
                         sizeof out->reference - strlen(out->reference),
                         " (cut to sit in the shell's sockets)");
            }
    }
    out->weight_end_offset_mm = out->reference_up ? c->top : c->bottom;
}

/* Step 3: the thread the weight turns on (a catalogue screw, or the ISO thread
 * of the modelled cylinder). */
static int compute_thread(compute_ctx *c, tippe_error *err)
{
    tippe_build_sheet *out = c->out;
    if (out->measure == TIPPE_BUILD_MEASURE_HOLE) {
        int m = 0, named = named_weight(c->d);
        double h = c->top - c->bottom;
        if ((c->o->catalogue || c->o->catalogue_read || tippe_design_catalogue(c->d) ||
             named >= 0) &&
            (m = match_catalogue(c->d, c->o, named, c->r_weight, h, out, err)) < 0)
            return -m;
        if (!m) {
            /* the screw is modelled as a cylinder of its pitch diameter (the
             * catalogue's convention) */
            out->thread = *tippe_build_thread_by_pitch_diameter(2 * c->r_weight);
            out->thread_assumed = 1;
        }
        out->has_thread = 1;
    } else if (out->measure == TIPPE_BUILD_MEASURE_ROD) {
        const tippe_build_thread *t = tippe_build_thread_by_diameter(2 * c->rod_r);
        if (t) {
            out->thread = *t;
            out->has_thread = 1;
        }
    }
    return TIPPE_OK;
}

/* Step 4: how the screw's hole is printed (the option, else the design's fit,
 * else tapped), and the rim where depths start when that moves it. */
static int compute_hole_fit(compute_ctx *c, tippe_error *err)
{
    const tippe_design *d = c->d;
    const tippe_build_options *o = c->o;
    tippe_build_sheet *out = c->out;
    tippe_build_hole_fit fit = o->hole_fit;
    int rc = check_fits(d, out->measure == TIPPE_BUILD_MEASURE_HOLE ? out->hole_part : -1, err);
    if (rc)
        return rc;
    if (fit == TIPPE_BUILD_HOLE_DESIGN) {
        int df = out->hole_part >= 0 ? tippe_design_part_fit(d, out->hole_part)
                                     : TIPPE_DESIGN_FIT_NONE;
        out->hole_fit_from_design = df != TIPPE_DESIGN_FIT_NONE;
        fit = df == TIPPE_DESIGN_FIT_SLIDE    ? TIPPE_BUILD_HOLE_SLIDE
              : df == TIPPE_DESIGN_FIT_INSERT ? TIPPE_BUILD_HOLE_INSERT
                                              : TIPPE_BUILD_HOLE_TAP;
    }
    if (!out->has_thread)
        return TIPPE_OK;
    out->tap_drill_mm = tippe_build_tap_drill_mm(&out->thread);
    if (out->measure == TIPPE_BUILD_MEASURE_HOLE && fit != TIPPE_BUILD_HOLE_SLIDE) {
        /* printed for its thread: its rim, where depths start, moves */
        const tippe_build_insert *ins;
        double dia = 0.0; /* set by fit_diameter when it returns 0 */
        /* a catalogue screw's thread is named in thread_name only */
        const char *tname = out->thread.name ? out->thread.name : out->thread_name;
        if ((rc = fit_diameter(d, out->hole_part, fit, o->hole_fit == TIPPE_BUILD_HOLE_DESIGN,
                               &out->thread, tname, &dia, out->fit_note, sizeof out->fit_note,
                               &ins, err)))
            return rc;
        /* the design's own printed radius, unless --hole says otherwise */
        tippe_design_solid hs;
        if (o->hole_fit == TIPPE_BUILD_HOLE_DESIGN && !ins &&
            !tippe_design_part_solid(d, out->hole_part, &hs) && hs.printed_radius_mm > 0 &&
            !hs.printed_radius_from_fit) {
            dia = 2 * hs.printed_radius_mm;
            snprintf(out->fit_note, sizeof out->fit_note, "the design's printed_radius_mm");
        }
        double R = out->radius_mm, a = dia / 2, rim = sqrt(R * R - a * a);
        out->hole_tapped = fit == TIPPE_BUILD_HOLE_TAP;
        out->hole_insert = fit == TIPPE_BUILD_HOLE_INSERT;
        if (ins)
            out->insert = *ins;
        out->hole_diameter_mm = dia;
        out->reference_z_mm = out->reference_up ? rim : -rim;
        tippe_design_part_info hp;
        tippe_design_part(d, out->hole_part, &hp);
        snprintf(out->reference, sizeof out->reference,
                 "the rim of hole '%s' at the %s pole (printed %.2f mm across, %s), "
                 "where a caliper's depth rod rests",
                 hp.name, out->reference_up ? "top (+z)" : "bottom (-z)", 2 * a,
                 ins ? "for the insert" : "the tap drill");
    }
    if (out->thread.name)
        snprintf(out->thread_name, sizeof out->thread_name, "%s", out->thread.name);
    out->thread.name = NULL; /* the sheet's copy is thread_name */
    return TIPPE_OK;
}

/* Step 5: each behaviour's setting as a depth below the reference and turns of
 * the thread, with the spin it needs and a launch there. */
static void compute_settings(compute_ctx *c)
{
    tippe_build_sheet *out = c->out;
    for (int f = 0; f < 3; f++) {
        tippe_build_setting *s = &out->set[f];
        if (!s->reachable)
            continue;
        double a = s->robust ? s->robust_from_mm : s->from_mm;
        double bb = s->robust ? s->robust_to_mm : s->to_mm;
        s->depth_from_mm = depth_at(out, a);
        s->depth_set_mm = depth_at(out, s->set_z2_mm);
        s->depth_to_mm = depth_at(out, bb);
        double p = out->has_thread ? out->thread.pitch_mm : NAN;
        s->turns_from = s->depth_from_mm / p;
        s->turns_set = s->depth_set_mm / p;
        s->turns_to = s->depth_to_mm / p;
        spins_and_launch(c->d, c->o, f, s);
        s->depth_hand_from_mm = depth_at(out, s->hand_from_mm);
        s->depth_hand_to_mm = depth_at(out, s->hand_to_mm);
    }
}

/* Step 5b: which settings a maker can set (a robust width of at least a
 * quarter turn of the thread, 0.5 mm without one, or the option's), the
 * verdict, and a warning on each setting narrower than that or whose part a
 * hand's spin reaches is. */
static void compute_settable(compute_ctx *c)
{
    tippe_build_sheet *out = c->out;
    const tippe_build_options *o = c->o;
    double p = out->has_thread ? out->thread.pitch_mm : NAN;
    if (o->min_setting_mm > 0) {
        out->min_setting_mm = o->min_setting_mm;
        snprintf(out->min_setting_rule, sizeof out->min_setting_rule, "--min-setting-mm %g",
                 o->min_setting_mm);
    } else if (out->has_thread) {
        out->min_setting_mm = p / 4;
        snprintf(out->min_setting_rule, sizeof out->min_setting_rule,
                 "a quarter turn of the %s x %g thread", out->thread_name, p);
    } else {
        out->min_setting_mm = TIPPE_BUILD_MIN_SETTING_MM;
        snprintf(out->min_setting_rule, sizeof out->min_setting_rule,
                 "%g mm: the weight has no thread", TIPPE_BUILD_MIN_SETTING_MM);
    }
    out->settable = out->three_in_one;
    out->hand_spin_rev_s = o->launch.spin_to_rev_s;
    for (int f = 0; f < 3; f++) {
        tippe_build_setting *s = &out->set[f];
        s->robust_width_mm = s->reachable && s->robust ? s->robust_to_mm - s->robust_from_mm : 0;
        s->settable = s->reachable && s->robust_width_mm >= out->min_setting_mm;
        out->settable = out->settable && s->settable;
        if (!s->reachable || out->n_warnings >= 6)
            continue;
        char turn[64] = "";
        if (out->has_thread)
            snprintf(turn, sizeof turn, " (%.2f of a turn)", s->robust_width_mm / p);
        if (!s->settable && !s->robust)
            snprintf(out->warning[out->n_warnings++], sizeof out->warning[0],
                     "The %s setting has no robust range (the tolerance bands of its zone, "
                     "%.2f mm wide, overlap), narrower than %.2f mm (%s): it holds on paper "
                     "only.",
                     behaviours[f], s->to_mm - s->from_mm, out->min_setting_mm,
                     out->min_setting_rule);
        else if (!s->settable)
            snprintf(out->warning[out->n_warnings++], sizeof out->warning[0],
                     "The %s setting's robust range is %.2f mm wide%s, narrower than %.2f mm "
                     "(%s): too narrow to set by hand; it holds on paper only.",
                     behaviours[f], s->robust_width_mm, turn, out->min_setting_mm,
                     out->min_setting_rule);
        else if (f > 0 && c->launched && !(s->hand_to_mm - s->hand_from_mm >= out->min_setting_mm))
            snprintf(out->warning[out->n_warnings++], sizeof out->warning[0],
                     "The %s setting's robust range is %.2f mm wide, but the spin it needs is "
                     "within a hand's %g rev/s over %s%.2f mm of it, narrower than %.2f mm (%s).",
                     behaviours[f], s->robust_width_mm, o->launch.spin_to_rev_s,
                     isfinite(s->hand_from_mm) ? "" : "none: ",
                     isfinite(s->hand_from_mm) ? s->hand_to_mm - s->hand_from_mm : 0.0,
                     out->min_setting_mm, out->min_setting_rule);
    }
}

/* Step 6: what a maker buys and prints (bill, gauges, print settings), the
 * steps, and advice when the design is not settable. */
static void compute_bill_and_steps(compute_ctx *c)
{
    tippe_build_sheet *out = c->out;
    const tippe_profile_set *ps = c->have_ps ? &c->ps : NULL;
    /* the bill gives the body as exported: a hole printed for its thread (a
     * tap drill, an insert's pilot) moves the rims, hence the body's height */
    tippe_profile_set printed;
    int have_printed = 0;
    if (ps && (out->hole_tapped || out->hole_insert) && out->hole_part >= 0) {
        tippe_profile_options po = tippe_profile_defaults();
        tippe_error perr = {0};
        po.clearance_mm = c->o->clearance_mm;
        po.sockets = 1;
        po.fit_part = out->hole_part;
        po.fit_diameter_mm = out->hole_diameter_mm;
        have_printed = tippe_profile_build(c->d, &po, &printed, &perr) == TIPPE_OK;
    }
    tippe_build_bill(c->d, have_printed ? &printed : ps, c->o, out, c->rod_r);
    if (have_printed)
        tippe_profile_set_free(&printed);
    int n_gauges = 0;
    char which[64] = "";
    for (int f = 0; f < 3; f++) {
        double pin;
        if (tippe_build_gauge_applies(out, f, &pin)) {
            n_gauges++;
            snprintf(which + strlen(which), sizeof which - strlen(which), "%s%s",
                     which[0] ? ", " : "", behaviours[f]);
        }
    }
    char stem[sizeof ((tippe_build_sheet *)0)->design_file];
    tippe_build_file_stem(out, stem, sizeof stem);
    if (n_gauges)
        tippe_build_bom(out, n_gauges, "depth gauges, printed (any filament)",
                        "%s-gauge-*.stl, one per setting (%s), printed flat side down", stem,
                        which);
    tippe_build_print_settings(c->d, ps, out);
    tippe_build_weigh_step(c->d, out);
    tippe_build_steps(out);
    if (!out->settable)
        tippe_build_advise(c->d, c->o, out);
}

/* A screw turned into a heat-set insert is held only by the thread within
 * the insert: below it the pilot hole is wider than the thread. A setting
 * whose screw top lies at or below the insert's far end (a common insert's
 * length, TIPPE_BUILD_INSERT_LENGTH_SOURCE) has no thread engaged at all.
 * When that is so of every setting, the top of the sheet (and stderr) says
 * so: the insert cannot hold any setting. */
static void insert_reach_warning(compute_ctx *c)
{
    tippe_build_sheet *out = c->out;
    double L = out->insert.length_mm;
    int any = 0, held = 0;
    char depths[160] = "";
    for (int f = 0; f < 3; f++) {
        const tippe_build_setting *st = &out->set[f];
        if (!st->reachable || !isfinite(st->depth_set_mm))
            continue;
        any = 1;
        held = held || st->depth_set_mm < L;
        size_t n = strlen(depths);
        snprintf(depths + n, sizeof depths - n, "%s%.1f mm (%s)", n ? ", " : "", st->depth_set_mm,
                 behaviours[f]);
    }
    if (!any || held || !(L > 0) || out->n_warnings >= 6)
        return;
    snprintf(out->warning[out->n_warnings++], sizeof out->warning[0],
             "--hole insert: no setting lies within the %s insert's %.1f mm: the screw's top is "
             "set %s below the rim, beyond the insert, where the pilot hole is wider than the "
             "thread and nothing holds the screw. Tap the hole instead (--hole tap).",
             out->insert.thread, L, depths);
}

/* Step 7: the notes on how depths are read, an insert's reach and weighing. */
static void compute_notes(compute_ctx *c)
{
    tippe_build_sheet *out = c->out;
    if (out->measure == TIPPE_BUILD_MEASURE_HOLE)
        tippe_build_note(out, "Depth is measured from the rim of the hole to the screw's end; a "
                              "negative depth means the screw stands out of the ball. Turns are "
                              "counted from the screw's end flush with the rim.");
    else if (out->measure == TIPPE_BUILD_MEASURE_ROD)
        tippe_build_note(out, "Depth is measured along the rod from its top end down to the "
                              "bead's top face, before the shell is closed. Turns are counted "
                              "from the bead's top face flush with the rod's end.");
    else
        tippe_build_note(out, "No hole or rod on the axis holds the weight: set it by Z2 "
                              "directly (its midpoint's height above the sphere's centre).");
    tippe_design_solid hs;
    if (out->hole_tapped && out->hole_part >= 0 &&
        !tippe_design_part_solid(c->d, out->hole_part, &hs) && hs.printed_radius_mm > 0 &&
        hs.printed_radius_mm < hs.radius_mm) {
        /* the model is the part as made (design_fit.c, or tippe_build_as_made) */
        char t[512];
        snprintf(t, sizeof t,
                 "The zones are the part as made: the hole printed %.2f mm across and tapped "
                 "after, which cuts the inner %.3f mm of its walls (tippe sweep%s%s gives the "
                 "same).",
                 2 * hs.printed_radius_mm, hs.radius_mm - hs.printed_radius_mm,
                 out->as_made_set[0] ? " --set " : "", out->as_made_set);
        tippe_build_note(out, t);
    } else if (out->as_made_set[0]) {
        /* --hole prints it otherwise than the design's tapped hole: not cut */
        char t[512];
        snprintf(t, sizeof t,
                 "The zones are the part as this sheet prints it: the hole not tapped, its "
                 "plastic modelled from the design's radius (tippe sweep --set %s gives the "
                 "same; without --hole the hole is tapped from its drill).",
                 out->as_made_set);
        tippe_build_note(out, t);
    }
    if (out->hole_insert)
        insert_reach_warning(c);
    if (out->hole_insert) {
        /* below the insert the pilot hole is wider than the thread: the screw
         * holds only by the thread within the insert: the length of the screw
         * between the rim and the insert's far end */
        char t[480];
        const double L = out->insert.length_mm, h = c->top - c->bottom;
        int n = snprintf(t, sizeof t, "The screw holds only by its thread within the %.1f mm "
                                      "insert (below it the pilot hole is wider than the thread): "
                                      "thread engaged",
                         L);
        for (int f = 0, k = 0; f < 3; f++) {
            const double top = out->set[f].depth_set_mm;
            if (!out->set[f].reachable || !(n > 0 && (size_t)n < sizeof t) || !isfinite(top))
                continue;
            const double engaged = fmax(0, fmin(L, top + h) - fmax(0, top));
            n += snprintf(t + n, sizeof t - (size_t)n, "%s %.1f mm (%s%s)", k++ ? "," : "",
                          engaged, behaviours[f], engaged > 0 ? "" : ": not held");
        }
        if (n > 0 && (size_t)n < sizeof t)
            snprintf(t + n, sizeof t - (size_t)n,
                     ". A setting with little or none of its thread in the insert lets the "
                     "screw fall: tap the hole instead.");
        tippe_build_note(out, t);
        tippe_build_note(out, "The insert's brass is not in the mass model (the zones are the "
                              "design's): for a top whose zones hold with it, add the insert to "
                              "the design as a fixed tube of its size and weight. Weigh the print "
                              "before pressing the insert in.");
    }
    if (out->weigh_note[0])
        tippe_build_note(out, out->weigh_note);
    if (isfinite(out->weigh_offset_g)) {
        char t[320];
        snprintf(t, sizeof t,
                 "Weighing to calibrate the infill: the hole is printed %.2f mm across, the mass "
                 "model's is %.2f mm, so %s %.3f g (the print model's difference, same infill) "
                 "%s the scale's reading of the bare print before giving it as measured_mass_g.",
                 out->hole_diameter_mm, 2 * tippe_build_hole_model_radius(c->d, out->hole_part),
                 out->weigh_offset_g < 0 ? "take" : "add", fabs(out->weigh_offset_g),
                 out->weigh_offset_g < 0 ? "from" : "to");
        tippe_build_note(out, t);
    }
}

int tippe_build_as_made(const tippe_design *d, const tippe_build_sheet *s, tippe_design **made,
                        tippe_error *err)
{
    tippe_design_solid hs;
    tippe_design_part_info hp;
    tippe_design_print_info pp;
    *made = NULL;
    if (s->hole_part < 0 || tippe_design_part_solid(d, s->hole_part, &hs) ||
        (hs.printed_radius_mm > 0 && !hs.printed_radius_from_fit) || hs.parent < 0 ||
        tippe_design_part_print(d, hs.parent, &pp) || !pp.printed ||
        tippe_design_part(d, s->hole_part, &hp))
        return TIPPE_OK;
    /* the design already models a hole tapped from the sheet's drill
     * (design_fit.c: the same rule and table); else --hole or a catalogue
     * screw's own pitch print it otherwise: tapped from the sheet's hole, or
     * (insert, slide) left at the design's radius, as the sheet's notes say */
    double want = s->hole_tapped && s->hole_diameter_mm / 2 < hs.radius_mm - 1e-9
                      ? s->hole_diameter_mm / 2
                      : 0;
    double have = hs.printed_radius_mm > 0 && hs.printed_radius_mm < hs.radius_mm
                      ? hs.printed_radius_mm
                      : 0;
    if (fabs(want - have) < 1e-9)
        return TIPPE_OK;
    char set[300];
    snprintf(set, sizeof set, "parts.%s.printed_radius_mm=%.10g", hp.name,
             want > 0 ? want : hs.radius_mm);
    const char *extra[1] = {set};
    return tippe_design_reload(d, extra, 1, made, err);
}

/* Step 4b: the part as made (tippe_build_as_made): the zones and every later
 * step are its. */
static int as_made(compute_ctx *c, tippe_design **made, tippe_error *err)
{
    int rc = tippe_build_as_made(c->d, c->out, made, err);
    if (!rc && *made) {
        c->d = *made;
        int n = tippe_design_n_overrides(*made);
        snprintf(c->out->as_made_set, sizeof c->out->as_made_set, "%s",
                 n ? tippe_design_override(*made, n - 1) : "");
    }
    return rc;
}

/* The sheet in named steps: zones, the reference depths start from, the
 * thread, the hole's fit, the settings, the bill and steps, the notes; with
 * verdict_only, the steps the verdict needs (no launch, bill or advice). */
static int compute(const tippe_design *d, const tippe_build_options *o, tippe_build_sheet *out,
                   int verdict_only, tippe_error *err)
{
    memset(out, 0, sizeof *out);
    out->hole_part = -1;
    out->weigh_offset_g = NAN;
    snprintf(out->design_name, sizeof out->design_name, "%s", tippe_design_name(d));
    snprintf(out->design_file, sizeof out->design_file, "%s", tippe_design_path(d));
    for (int i = 0; i < tippe_design_n_overrides(d) && out->n_overrides < 16; i++)
        snprintf(out->override[out->n_overrides++], sizeof out->override[0], "%s",
                 tippe_design_override(d, i));
    out->radius_mm = tippe_design_radius_mm(d);
    tippe_design_travel_mm(d, &out->design_travel_from_mm, &out->design_travel_to_mm);
    /* the launch check's law: a patch without a radius gets Hertz's of the ball
     * on the default table (tippe/physics.h), as tippe check without --table */
    tippe_build_options ol = *o;
    int rc;
    if (tippe_friction_law_type_of(ol.launch.law)->patch && !(ol.launch.patch_radius_m > 0) &&
        !(ol.launch.patch_E_star_pa > 0) &&
        (rc = tippe_launch_patch_modulus(d, NULL, &ol.launch.patch_E_star_pa, err)) != 0)
        return rc;
    o = &ol;
    tippe_launch_friction_model(&o->launch, &out->launch_model);
    tippe_dynamics_friction_text(&out->launch_model, out->launch_friction,
                                 sizeof out->launch_friction);
    compute_ctx c = {.d = d, .o = o, .out = out, .rod_r = 0};
    /* how the hole is printed first: the zones are the part's as made */
    compute_reference(&c);
    tippe_design *made = NULL;
    rc = compute_thread(&c, err);
    if (!rc)
        rc = compute_hole_fit(&c, err);
    if (!rc)
        rc = as_made(&c, &made, err);
    if (!rc)
        rc = compute_zones(&c, err);
    d = c.d;
    if (!rc && verdict_only) {
        compute_settable(&c);
    } else if (!rc) {
        tippe_build_weigh_offset(d, out);
        compute_settings(&c);
        c.launched = 1;
        compute_settable(&c);
        tippe_build_poles(d, out);
        compute_bill_and_steps(&c);
        compute_notes(&c);
    }
    if (c.have_ps)
        tippe_profile_set_free(&c.ps);
    tippe_design_free(made);
    /* a cancelled launch or advice left the sheet short: it is no sheet */
    if (!rc && tippe_cancel_requested())
        rc = tippe_cancel_error(err);
    return rc;
}

int tippe_build_compute(const tippe_design *d, const tippe_build_options *o,
                        tippe_build_sheet *out, tippe_error *err)
{
    return compute(d, o, out, 0, err);
}

int tippe_build_compute_verdict(const tippe_design *d, const tippe_build_options *o,
                                tippe_build_sheet *out, tippe_error *err)
{
    return compute(d, o, out, 1, err);
}
