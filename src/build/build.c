/* Build sheet: robust settings in measurable units, spins, launch verdicts, BOM. */
#include "tippe/build.h"

#include "base/json.h"
#include "tippe/profile.h"
#include "tippe/sweep.h"
#include "tippe/physics.h"
#include "tippe/design.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ISO 261, coarse series (first choice sizes M1.6 .. M24). */
static const tippe_build_thread iso261[] = {
    {"M1.6", 1.6, 0.35}, {"M2", 2, 0.4},     {"M2.5", 2.5, 0.45}, {"M3", 3, 0.5},
    {"M4", 4, 0.7},      {"M5", 5, 0.8},     {"M6", 6, 1.0},      {"M8", 8, 1.25},
    {"M10", 10, 1.5},    {"M12", 12, 1.75},  {"M14", 14, 2.0},    {"M16", 16, 2.0},
    {"M20", 20, 2.5},    {"M24", 24, 3.0},
};
enum { N_ISO = sizeof iso261 / sizeof iso261[0] };

/* ISO 724: the pitch diameter of the basic profile, d2 = d - (3 sqrt(3) / 8) P. */
static double pitch_diameter_mm(const tippe_build_thread *t)
{
    return t->d_mm - 0.649519052838329 * t->pitch_mm;
}

const tippe_build_thread *tippe_build_thread_by_diameter(double d_mm)
{
    for (int k = 0; k < N_ISO; k++)
        if (fabs(iso261[k].d_mm - d_mm) < 1e-6)
            return &iso261[k];
    return NULL;
}

const tippe_build_thread *tippe_build_thread_by_pitch_diameter(double d2_mm)
{
    int best = 0;
    for (int k = 1; k < N_ISO; k++)
        if (fabs(pitch_diameter_mm(&iso261[k]) - d2_mm) <
            fabs(pitch_diameter_mm(&iso261[best]) - d2_mm))
            best = k;
    return &iso261[best];
}

double tippe_build_tap_drill_mm(const tippe_build_thread *t) { return t->d_mm - t->pitch_mm; }

/* TIPPE_BUILD_INSERT_SOURCE's chart, non-flanged inserts, pilot hole -0/+0.1 mm. */
static const tippe_build_insert inserts[] = {
    {"M3", 4.0, 4.4}, {"M4", 5.6, 6.1}, {"M5", 6.4, 7.1}, {"M6", 8.0, 8.5},
};

const tippe_build_insert *tippe_build_insert_for(const char *thread)
{
    for (size_t k = 0; thread && k < sizeof inserts / sizeof inserts[0]; k++)
        if (!strcmp(inserts[k].thread, thread))
            return &inserts[k];
    return NULL;
}

/* ISO 724: basic minor diameter of the internal thread, D1 = D - (5 sqrt(3) / 8) P. */
static double minor_diameter_mm(const tippe_build_thread *t)
{
    return t->d_mm - 1.082531754730548 * t->pitch_mm;
}

static const char *const behaviours[3] = {"stays up", "flips", "hangs"};
static const char *const families[3] = {"I", "II", "III"};

const char *tippe_build_behaviour(int f) { return f >= 0 && f < 3 ? behaviours[f] : "?"; }
const char *tippe_build_family(int f) { return f >= 0 && f < 3 ? families[f] : "?"; }

tippe_verdict tippe_build_expected_verdict(int f)
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

/* ------------------------------------------------------------ ranges */

/* The run of each family with the largest robust width (the nominal widest if
 * none is robust), as tippe_sweep_robust_widths joins runs: only the usable
 * part of each zone (tippe_sweep_zone_usable: within the physical travel and
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

/* The catalogue item with the screw's radius and height: 1 matched, 0 not,
 * or a status < 0 with err set if the file does not read. */
static int match_catalogue(const char *file, double r_mm, double h_mm, tippe_build_sheet *out,
                           tippe_error *err)
{
    tippe_json_reader *c = tippe_json_reader_new(file, err, TIPPE_JSON_WORDS_FIELD, NULL);
    if (!c)
        return -TIPPE_ECOMPUTE;
    cJSON *root = NULL;
    int rc = tippe_json_load(c, 16, "catalogue", &root);
    free(c);
    if (rc)
        return -rc;
    int found = 0;
    const cJSON *set;
    cJSON_ArrayForEach(set, root)
    {
        const cJSON *items = cJSON_GetObjectItemCaseSensitive(set, "items");
        const cJSON *it;
        cJSON_ArrayForEach(it, items)
        {
            const cJSON *r = cJSON_GetObjectItemCaseSensitive(it, "radius_mm");
            const cJSON *h = cJSON_GetObjectItemCaseSensitive(it, "height_mm");
            const cJSON *n = cJSON_GetObjectItemCaseSensitive(it, "name");
            const cJSON *d = cJSON_GetObjectItemCaseSensitive(it, "d_mm");
            const cJSON *p = cJSON_GetObjectItemCaseSensitive(it, "pitch_mm");
            const cJSON *th = cJSON_GetObjectItemCaseSensitive(it, "thread");
            if (!cJSON_IsNumber(r) || !cJSON_IsNumber(h) || !cJSON_IsString(n) ||
                !cJSON_IsNumber(d) || !cJSON_IsNumber(p) || fabs(r->valuedouble - r_mm) > 1e-6 ||
                fabs(h->valuedouble - h_mm) > 1e-6)
                continue;
            const tippe_build_thread *iso = tippe_build_thread_by_diameter(d->valuedouble);
            snprintf(out->thread_name, sizeof out->thread_name, "%s",
                     iso ? iso->name : cJSON_IsString(th) ? th->valuestring : "M?");
            out->thread.d_mm = d->valuedouble;
            out->thread.pitch_mm = p->valuedouble; /* the catalogue's */
            snprintf(out->catalogue_item, sizeof out->catalogue_item, "%s", n->valuestring);
            const cJSON *t = cJSON_GetObjectItemCaseSensitive(set, "title");
            snprintf(out->catalogue_title, sizeof out->catalogue_title, "%s",
                     cJSON_IsString(t) ? t->valuestring : set->string);
            found = 1;
            break;
        }
        if (found)
            break;
    }
    cJSON_Delete(root);
    return found;
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

static void spins_and_launch(const tippe_design *d, const tippe_build_options *o, int f,
                             tippe_build_setting *s)
{
    const double rev = 2 * M_PI;
    tippe_error e = {0};
    double n_set = NAN, n_max = 0;
    if (spin_needed(d, f, s->set_z2_mm, o->launch.g, &n_set, &s->spin_rule, &e))
        n_set = NAN;
    double a = s->robust ? s->robust_from_mm : s->from_mm;
    double b = s->robust ? s->robust_to_mm : s->to_mm;
    /* 21 points: the thresholds are smooth in Z2 and monotone over a zone's
     * middle; their maximum is at an end or near it */
    for (int k = 0; k <= 20; k++) {
        double n = 0;
        const char *rule;
        if (spin_needed(d, f, a + (b - a) * k / 20.0, o->launch.g, &n, &rule, &e) == TIPPE_OK)
            n_max = fmax(n_max, n);
    }
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
    int rc = tippe_design_top(d, s->set_z2_mm, &top, &e);
    if (!rc)
        rc = tippe_launch_central(&top, &o->launch, s->spin_launch_rev_s * rev, &ic, &e);
    if (!rc)
        rc = tippe_launch_run_initial(&top, &o->launch, &ic, &rec, &e);
    s->launch_status = rc;
    if (!rc) {
        s->verdict = rec.verdict;
        s->launch_t_s = rec.t_s;
        s->verdict_ok = rec.verdict == tippe_build_expected_verdict(f);
    }
}

/* ----------------------------------------------------------------- BOM */

void tippe_build_stem(const char *design_path, char *out, size_t size)
{
    const char *base = strrchr(design_path, '/');
    snprintf(out, size, "%s", base ? base + 1 : design_path);
    char *dot = strrchr(out, '.');
    if (dot && dot != out)
        *dot = '\0';
}

/* The sheet names the files it refers to as they are written. */
static void file_stem(const tippe_build_sheet *s, char *out, size_t size)
{
    tippe_build_stem(s->design_file, out, size);
}

static void bom(tippe_build_sheet *s, int qty, const char *what, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
static void bom(tippe_build_sheet *s, int qty, const char *what, const char *fmt, ...)
{
    if (s->n_bom >= TIPPE_BUILD_MAX_BOM)
        return;
    tippe_build_bom_line *l = &s->bom[s->n_bom++];
    l->quantity = qty;
    snprintf(l->what, sizeof l->what, "%s", what);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(l->detail, sizeof l->detail, fmt, ap);
    va_end(ap);
}

static void note(tippe_build_sheet *s, const char *text)
{
    if (s->n_notes < 4)
        snprintf(s->note[s->n_notes++], sizeof s->note[0], "%s", text);
}

static void bill(const tippe_design *d, const tippe_profile_set *ps, const tippe_build_options *o,
                 tippe_build_sheet *s, double rod_r)
{
    char what[512];
    for (int b = 0; ps && b < ps->n_bodies; b++) {
        snprintf(what, sizeof what, "printed body '%s', %s", ps->body[b].name,
                 ps->body[b].material);
        bom(s, 1, what, "%.2f mm tall, %.2f mm across; printed with the axis vertical",
            ps->body[b].z_max_mm - ps->body[b].z_min_mm, 2 * ps->body[b].r_max_mm);
    }
    for (int i = 0; i < tippe_design_n_parts(d); i++) {
        tippe_design_solid sd;
        tippe_design_part_info p;
        tippe_design_print_info pr;
        if (tippe_design_part_solid(d, i, &sd) || tippe_design_part(d, i, &p) ||
            tippe_design_part_print(d, i, &pr) || sd.is_void || p.printable || pr.printed)
            continue;
        int cyl = !strcmp(sd.shape, "cylinder") || !strcmp(sd.shape, "tube");
        if (sd.moving && s->catalogue_item[0]) {
            snprintf(what, sizeof what, "set screw %s (%s), %s", s->catalogue_item,
                     s->catalogue_title, p.material);
            bom(s, 1, what, "thread %s x %.4g mm, length %.4g mm; the weight ('%s')",
                s->thread_name, s->thread.pitch_mm, sd.height_mm, p.name);
        } else if (sd.moving && s->measure == TIPPE_BUILD_MEASURE_HOLE && cyl) {
            snprintf(what, sizeof what, "screw or slug '%s', %s", p.name, p.material);
            bom(s, 1, what,
                "diameter %.4g mm (modelled), length %.4g mm; no catalogue item matches: "
                "nearest ISO 261 thread %s x %.4g mm",
                2 * sd.radius_mm, sd.height_mm, s->thread_name, s->thread.pitch_mm);
        } else if (sd.moving && cyl && sd.inner_radius_mm > 0) {
            snprintf(what, sizeof what, "bead (weight) '%s', %s", p.name, p.material);
            if (s->has_thread)
                bom(s, 1, what,
                    "outer diameter %.4g mm, height %.4g mm, bore tapped %s x %.4g mm "
                    "(tap drill %.2f mm)",
                    2 * sd.radius_mm, sd.height_mm, s->thread_name, s->thread.pitch_mm,
                    s->tap_drill_mm);
            else
                bom(s, 1, what, "outer diameter %.4g mm, height %.4g mm, bore %.4g mm",
                    2 * sd.radius_mm, sd.height_mm, 2 * sd.inner_radius_mm);
        } else if (!sd.moving && cyl && sd.inner_radius_mm == 0) {
            double len = sd.height_mm;
            const char *ends = "cut square";
            int ns = 0;
            double lo = 0, hi = 0;
            for (int k = 0; ps && k < ps->n_sockets; k++)
                if (ps->socket_part[k] == i) {
                    ns++;
                    lo = fmin(lo, ps->socket_floor_z_mm[k]);
                    hi = fmax(hi, ps->socket_floor_z_mm[k]);
                }
            if (ns == 2) {
                /* held on the axis by the shell's sockets (tippe/profile.h):
                 * longer than the model's rod, whose ends the cavity clips */
                len = hi - lo;
                char t[320];
                double extra_g = (M_PI * sd.radius_mm * sd.radius_mm * len * 1e-3 *
                                      p.density_g_cm3 - p.mass_kg * 1e3);
                snprintf(t, sizeof t,
                         "The rod is cut %.2f mm long, its ends %.1f mm deep in the shell's "
                         "sockets at the poles (they hold it on the axis): %+.3f g against the "
                         "model's rod, whose ends the cavity clips; the sockets remove %.1f mm^3 "
                         "of printed wall. Neither is in the mass model.",
                         len, TIPPE_PROFILE_SOCKET_DEPTH_MM, extra_g,
                         ps->socket_volume_mm3[0] + ps->socket_volume_mm3[1]);
                note(s, t);
                ends = "cut square; its ends sit in the shell's sockets at the poles";
                s->rod_sockets = 1;
            } else if (sd.clip_radius_mm > 0) {
                double cap = sqrt(sd.clip_radius_mm * sd.clip_radius_mm -
                                  sd.radius_mm * sd.radius_mm);
                if (sd.z_mm + sd.height_mm / 2 > cap && sd.z_mm - sd.height_mm / 2 < -cap) {
                    len = 2 * cap;
                    ends = "cut square at this length, its end edges touching the clip ball "
                           "(the model's rounded ends hold a little more metal)";
                }
            }
            const tippe_build_thread *t = tippe_build_thread_by_diameter(2 * sd.radius_mm);
            snprintf(what, sizeof what, "%s '%s', %s", t ? "threaded rod" : "rod", p.name,
                     p.material);
            if (t)
                bom(s, 1, what, "%s x %.4g mm (ISO 261 coarse), length %.2f mm, %s", t->name,
                    t->pitch_mm, len, ends);
            else
                bom(s, 1, what, "diameter %.4g mm, length %.2f mm, %s", 2 * sd.radius_mm, len,
                    ends);
            (void)rod_r;
        } else {
            snprintf(what, sizeof what, "part '%s', %s %s", p.name, p.material, sd.shape);
            bom(s, 1, what, "%s", sd.moving ? "moving (the weight)" : "fixed hardware");
        }
    }
    if (s->hole_insert)
        bom(s, 1, "heat-set threaded insert, brass, non-flanged",
            "%s (for the %s x %g screw), outer diameter at most %.1f mm; pressed into the "
            "hole's rim, printed %.1f mm across (its vendor's pilot hole: %s)",
            s->insert.thread, s->thread_name, s->thread.pitch_mm, s->insert.outer_max_mm,
            s->insert.pilot_mm, TIPPE_BUILD_INSERT_SOURCE);
    int split = 0;
    for (int k = 0; ps && k < ps->n_warnings; k++)
        split |= strstr(ps->warning[k], "--split") != NULL;
    s->needs_split = split;
    if (split) {
        /* tippe export makes the ring only where a wall at the cut is wide
         * enough for its groove (a thin shell gets none): ask it */
        tippe_profile_options po = tippe_profile_defaults();
        po.clearance_mm = o->clearance_mm;
        po.split = po.joint = 1;
        tippe_profile_set js;
        tippe_error e = {0};
        if (tippe_profile_build(d, &po, &js, &e) == TIPPE_OK) {
            s->joint_ring = js.n_grooves > 0;
            tippe_profile_set_free(&js);
        }
    }
    char stem[sizeof ((tippe_build_sheet *)0)->design_file];
    file_stem(s, stem, sizeof stem);
    if (s->joint_ring)
        bom(s, 1, "joint ring, printed (the body's filament)",
            "%s-joint-ring.stl: fills the 2 mm grooves of both halves' cut faces to align them "
            "(tippe export --split --joint)", stem);
    if (split)
        bom(s, 1, "adhesive for the two printed halves",
            "the body closes around its hardware, so it is printed in halves (--split): join "
            "them (solvent weld for ABS, cyanoacrylate for PLA or PETG)");
}

int tippe_build_needs_split(const tippe_design *d, double clearance_mm)
{
    tippe_profile_options po = tippe_profile_defaults();
    po.clearance_mm = clearance_mm;
    tippe_profile_set ps;
    tippe_error e = {0};
    if (tippe_profile_build(d, &po, &ps, &e))
        return 0;
    int split = 0;
    for (int k = 0; k < ps.n_warnings; k++)
        split |= strstr(ps.warning[k], "--split") != NULL;
    tippe_profile_set_free(&ps);
    return split;
}

static void print_settings(const tippe_design *d, const tippe_profile_set *ps,
                           tippe_build_sheet *s)
{
    for (int i = 0; ps && i < tippe_design_n_parts(d) && s->n_print < 4; i++) {
        tippe_design_part_info p;
        tippe_design_print_info pr;
        tippe_design_solid sd;
        if (tippe_design_part(d, i, &p) || tippe_design_part_print(d, i, &pr) ||
            tippe_design_part_solid(d, i, &sd) || sd.is_void || sd.moving ||
            !(p.printable || pr.printed))
            continue;
        int k = s->n_print++;
        snprintf(s->print[k].part, sizeof s->print[k].part, "%s", p.name);
        snprintf(s->print[k].material, sizeof s->print[k].material, "%s", p.material);
        s->print[k].has_block = pr.printed;
        s->print[k].settings = pr.printed ? pr.settings : tippe_print_defaults();
        s->print[k].infill = pr.printed ? pr.infill : 1.0;
        s->print[k].calibrated = pr.calibrated;
    }
}

static void step(tippe_build_sheet *s, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void step(tippe_build_sheet *s, const char *fmt, ...)
{
    if (s->n_steps >= 10)
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(s->step[s->n_steps++], sizeof s->step[0], fmt, ap);
    va_end(ap);
}

/* The order a maker works in, from what the sheet found. */
static void steps(tippe_build_sheet *s)
{
    const tippe_build_setting *first = NULL;
    for (int f = 0; f < 3 && !first; f++)
        if (s->set[f].reachable)
            first = &s->set[f];
    char stem[sizeof ((tippe_build_sheet *)0)->design_file];
    file_stem(s, stem, sizeof stem);
    if (s->needs_split)
        step(s, "Print the body in two halves (%s-*-lower.stl and %s-*-upper.stl, each standing "
                "on its flat cut face at the equator: no supports) with the print settings.",
             stem, stem);
    else
        step(s, "Print the body with the print settings, its axis vertical (the mass model "
                "assumes it), no supports inside the hole.");
    if (s->measure == TIPPE_BUILD_MEASURE_HOLE) {
        double bite = 0.5 * (s->thread.d_mm - s->hole_diameter_mm);
        if (s->hole_insert)
            step(s, "Press the %s heat-set insert into the hole at the rim with a soldering iron "
                    "(its insert tip), straight along the axis, until its top is flush with the "
                    "rim; let it cool. The hole is printed %.1f mm across for it.",
                 s->insert.thread, s->hole_diameter_mm);
        else if (s->hole_diameter_mm > s->tap_drill_mm + 1e-9)
            step(s, "Check the hole: printed diameter %.2f mm for the %s x %g screw, wider than "
                    "its tap drill %.2f mm (a sliding fit: the design's hole, the screw's pitch "
                    "diameter, plus the clearance): the thread bites %.2f mm deep into the wall. "
                    "If the screw turns loose, fix it with a drop of glue.",
                 s->hole_diameter_mm, s->thread_name, s->thread.pitch_mm, s->tap_drill_mm,
                 bite > 0 ? bite : 0);
        else
            step(s, "Tap the hole %s x %g: it is printed at the tap drill, %.2f mm across (d - "
                    "P; drill it to %.2f mm first if the print came out narrower).",
                 s->thread_name, s->thread.pitch_mm, s->hole_diameter_mm, s->tap_drill_mm);
        step(s, "Turn the screw in with a hex key until its end is flush with the rim, then "
                "the turns of the table for the behaviour wanted. Check the depth with the "
                "printed gauge of that setting (%s-gauge-*.stl: pin in the hole, disc on the rim, "
                "the screw's end just touching the pin) or a caliper's depth rod on the rim.",
             stem);
    } else if (s->measure == TIPPE_BUILD_MEASURE_ROD) {
        step(s, "Cut the rod to the length in the bill of materials, square.");
        step(s, "Screw the bead onto the rod until its top face lies at the table's depth "
                "below the rod's top end%s: the printed sleeve gauge (%s-gauge-*.stl) standing on "
                "the bead is then flush with the rod's end. Fix it with a drop of threadlocker.",
             first ? " for the behaviour wanted" : "", stem);
        const char *rod_in_sockets = s->rod_sockets
                                         ? " with its lower end in the lower half's socket (the "
                                           "upper end goes into the upper half's)"
                                         : "";
        if (s->joint_ring)
            step(s, "Put the joint ring in the groove of the lower half's cut face, stand the rod "
                    "on the axis%s, close with the upper half (its groove over the ring) and join "
                    "them (adhesive in the bill of materials); the bead can no longer be moved: "
                    "build one top per behaviour, or choose the one you want first.",
                 rod_in_sockets);
        else
            step(s, "Stand the rod on the axis of the lower half%s, close with the upper half "
                    "and join them (adhesive in the bill of materials; the wall at the cut is too "
                    "thin for a joint ring: align the halves by hand); the bead can no longer "
                    "be moved: build one top per behaviour, or choose the one you want first.",
                 rod_in_sockets);
    } else {
        step(s, "Place the weight at the set Z2 of the table (its midpoint above the sphere's "
                "centre).");
    }
    step(s, "Spin the top on a hard, flat table at the spin of the table (a flick of the "
            "fingers gives 5 to 25 rev/s) and watch it stay up, flip or hang.");
}

int tippe_build_gauge_applies(const tippe_build_sheet *s, int f, double *pin_mm)
{
    *pin_mm = NAN;
    if (f < 0 || f > 2 || !s->set[f].reachable || s->measure == TIPPE_BUILD_MEASURE_NONE ||
        !(s->set[f].depth_set_mm >= TIPPE_BUILD_GAUGE_MIN_MM))
        return 0;
    *pin_mm = s->set[f].depth_set_mm;
    return 1;
}

double tippe_build_gauge_pin_diameter_mm(const tippe_build_sheet *s)
{
    double d = s->hole_diameter_mm - 1;
    /* an insert's bore is its thread: the pin passes its minor diameter (ISO 724) */
    if (s->hole_insert && s->has_thread)
        d = fmin(d, minor_diameter_mm(&s->thread) - 0.5);
    return d;
}

/* ------------------------------------------------------ 3-in-1 search */

/* 1 if the design with field=value is 3-in-1 within its physical travel, 0 if
 * not, -1 if it does not load (a layout the value breaks). */
static int three_in_one_at(const tippe_design *d, const tippe_build_options *o,
                           const char *field, double value)
{
    const char *ov[TIPPE_JSON_MAX_SETS];
    int n = 0;
    for (int k = 0; k < o->n_sets && n < TIPPE_JSON_MAX_SETS - 1; k++)
        ov[n++] = o->sets[k];
    char set[512];
    snprintf(set, sizeof set, "%s=%.10g", field, value);
    ov[n++] = set;
    tippe_design *v = NULL;
    tippe_error e = {0};
    if (tippe_design_load(tippe_design_path(d), ov, n, &v, &e))
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

static void advise(const tippe_design *d, const tippe_build_options *o, tippe_build_sheet *s)
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
                         "3-in-1 at %s %.1f %% infill of '%s' (the slicer's %.0f %%): weigh the "
                         "print (a print's real infill often differs from the slicer's) and give "
                         "measured_mass_g, or print at that infill",
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
static double hole_model_radius(const tippe_design *d, int i)
{
    tippe_design_solid hs;
    return tippe_design_part_solid(d, i, &hs) ? NAN : hs.radius_mm;
}

static void weigh_offset(const tippe_design *d, tippe_build_sheet *s)
{
    tippe_design_solid hs;
    tippe_design_part_info hp, pp;
    tippe_design_print_info before, after;
    if (s->measure != TIPPE_BUILD_MEASURE_HOLE || s->hole_part < 0 ||
        tippe_design_part_solid(d, s->hole_part, &hs) || hs.parent < 0 ||
        tippe_design_part(d, s->hole_part, &hp) || tippe_design_part(d, hs.parent, &pp) ||
        tippe_design_part_print(d, hs.parent, &before) || !before.printed)
        return;
    char set[300];
    snprintf(set, sizeof set, "parts.%s.radius_mm=%.10g", hp.name, s->hole_diameter_mm / 2);
    const char *extra[1] = {set};
    tippe_design *v = NULL;
    tippe_error e = {0};
    if (tippe_design_derive(d, extra, 1, &v, &e) == TIPPE_OK &&
        tippe_design_part_print(v, hs.parent, &after) == TIPPE_OK && after.printed) {
        /* at the same infill: a calibrated design's infill is the one solved */
        double m_model = before.skin_mass_kg + before.infill * (before.solid_mass_kg - before.skin_mass_kg);
        double m_print = after.skin_mass_kg + before.infill * (after.solid_mass_kg - after.skin_mass_kg);
        s->weigh_offset_g = (m_model - m_print) * 1e3;
    }
    tippe_design_free(v);
}

/* ------------------------------------------------------------ compute */

int tippe_build_compute(const tippe_design *d, const tippe_build_options *o,
                        tippe_build_sheet *out, tippe_error *err)
{
    memset(out, 0, sizeof *out);
    out->hole_part = -1;
    out->weigh_offset_g = NAN;
    snprintf(out->design_name, sizeof out->design_name, "%s", tippe_design_name(d));
    snprintf(out->design_file, sizeof out->design_file, "%s", tippe_design_path(d));
    out->radius_mm = tippe_design_radius_mm(d);
    tippe_sweep_result r;
    tippe_sweep_bands_result b = {0};
    int rc = tippe_sweep_design(d, 0, 0, NULL, &r, err);
    if (!rc)
        rc = tippe_sweep_bands(d, &r, &b, err);
    if (rc) {
        tippe_sweep_bands_free(&b);
        tippe_sweep_result_free(&r);
        return rc;
    }
    out->travel_from_mm = r.travel_from_mm;
    out->travel_to_mm = r.travel_to_mm;
    robust_runs(&r, &b, out->set);
    out->three_in_one = out->set[0].reachable && out->set[1].reachable && out->set[2].reachable;
    tippe_sweep_bands_free(&b);
    tippe_sweep_result_free(&r);

    /* where the weight is measured from */
    double top, bottom, r_weight, bore, rod_r = 0;
    weight_extent(d, &top, &bottom, &r_weight, &bore, out->weight_name, sizeof out->weight_name);
    tippe_profile_options po = tippe_profile_defaults();
    po.clearance_mm = o->clearance_mm;
    po.sockets = 1; /* a rod spanning a cavity gets them (tippe build exports them so) */
    tippe_profile_set ps;
    tippe_error perr = {0};
    int have_ps = tippe_profile_build(d, &po, &ps, &perr) == TIPPE_OK;
    int rod_part = -1;
    if (isfinite(top) && !find_hole(d, have_ps ? &ps : NULL, o->clearance_mm, r_weight, out) &&
        find_rod(d, bore, &rod_r, &rod_part, out)) {
        /* a rod held by sockets is cut longer: its top end is the upper socket's floor */
        for (int k = 0; have_ps && k < ps.n_sockets; k++)
            if (ps.socket_part[k] == rod_part && ps.socket_floor_z_mm[k] > 0) {
                out->reference_z_mm = ps.socket_floor_z_mm[k];
                snprintf(out->reference + strlen(out->reference),
                         sizeof out->reference - strlen(out->reference),
                         " (cut to sit in the shell's sockets)");
            }
    }
    out->weight_end_offset_mm = out->reference_up ? top : bottom;

    /* the thread the weight turns on */
    if (out->measure == TIPPE_BUILD_MEASURE_HOLE) {
        int m = 0;
        double h = top - bottom;
        if (o->catalogue && (m = match_catalogue(o->catalogue, r_weight, h, out, err)) < 0) {
            if (have_ps)
                tippe_profile_set_free(&ps);
            return -m;
        }
        if (!m) {
            /* the screw is modelled as a cylinder of its pitch diameter (the
             * catalogue's convention) */
            out->thread = *tippe_build_thread_by_pitch_diameter(2 * r_weight);
            out->thread_assumed = 1;
        }
        out->has_thread = 1;
    } else if (out->measure == TIPPE_BUILD_MEASURE_ROD) {
        const tippe_build_thread *t = tippe_build_thread_by_diameter(2 * rod_r);
        if (t) {
            out->thread = *t;
            out->has_thread = 1;
        }
    }
    /* how the screw's hole is printed: the option, else the design's fit, else tapped */
    tippe_build_hole_fit fit = o->hole_fit;
    if ((rc = check_fits(d, out->measure == TIPPE_BUILD_MEASURE_HOLE ? out->hole_part : -1,
                         err))) {
        if (have_ps)
            tippe_profile_set_free(&ps);
        return rc;
    }
    if (fit == TIPPE_BUILD_HOLE_DESIGN) {
        int df = out->hole_part >= 0 ? tippe_design_part_fit(d, out->hole_part)
                                     : TIPPE_DESIGN_FIT_NONE;
        out->hole_fit_from_design = df != TIPPE_DESIGN_FIT_NONE;
        fit = df == TIPPE_DESIGN_FIT_SLIDE    ? TIPPE_BUILD_HOLE_SLIDE
              : df == TIPPE_DESIGN_FIT_INSERT ? TIPPE_BUILD_HOLE_INSERT
                                              : TIPPE_BUILD_HOLE_TAP;
    }
    if (out->has_thread) {
        out->tap_drill_mm = tippe_build_tap_drill_mm(&out->thread);
        if (out->measure == TIPPE_BUILD_MEASURE_HOLE && fit != TIPPE_BUILD_HOLE_SLIDE) {
            /* printed for its thread: its rim, where depths start, moves */
            const tippe_build_insert *ins;
            double dia;
            /* a catalogue screw's thread is named in thread_name only */
            const char *tname = out->thread.name ? out->thread.name : out->thread_name;
            if ((rc = fit_diameter(d, out->hole_part, fit, o->hole_fit == TIPPE_BUILD_HOLE_DESIGN,
                                   &out->thread, tname, &dia, out->fit_note,
                                   sizeof out->fit_note, &ins, err))) {
                if (have_ps)
                    tippe_profile_set_free(&ps);
                return rc;
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
    }

    weigh_offset(d, out);
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
        spins_and_launch(d, o, f, s);
    }
    bill(d, have_ps ? &ps : NULL, o, out, rod_r);
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
    file_stem(out, stem, sizeof stem);
    if (n_gauges)
        bom(out, n_gauges, "depth gauges, printed (any filament)",
            "%s-gauge-*.stl, one per setting (%s), printed flat side down", stem, which);
    print_settings(d, have_ps ? &ps : NULL, out);
    steps(out);
    if (!out->three_in_one)
        advise(d, o, out);
    if (have_ps)
        tippe_profile_set_free(&ps);
    if (out->measure == TIPPE_BUILD_MEASURE_HOLE)
        note(out, "Depth is measured from the rim of the hole to the screw's end; a negative "
                  "depth means the screw stands out of the ball. Turns are counted from the "
                  "screw's end flush with the rim.");
    else if (out->measure == TIPPE_BUILD_MEASURE_ROD)
        note(out, "Depth is measured along the rod from its top end down to the bead's top "
                  "face, before the shell is closed. Turns are counted from the bead's top "
                  "face flush with the rod's end.");
    else
        note(out, "No hole or rod on the axis holds the weight: set it by Z2 directly "
                  "(its midpoint's height above the sphere's centre).");
    if (out->hole_insert) {
        /* below the insert the pilot hole is wider than the thread: the screw
         * holds only while all of it is within the insert */
        char t[320];
        int n = snprintf(t, sizeof t, "The screw holds only within the insert (below it the "
                                      "pilot hole is wider than the thread): its far end lies");
        for (int f = 0, k = 0; f < 3; f++)
            if (out->set[f].reachable && n > 0 && (size_t)n < sizeof t)
                n += snprintf(t + n, sizeof t - (size_t)n, "%s %.1f mm (%s)", k++ ? "," : "",
                              out->set[f].depth_set_mm + (top - bottom), behaviours[f]);
        if (n > 0 && (size_t)n < sizeof t)
            snprintf(t + n, sizeof t - (size_t)n,
                     " below the rim: an insert shorter than that lets the screw fall; tap "
                     "the hole instead.");
        note(out, t);
        note(out, "The insert's brass is not in the mass model (the zones are the design's): "
                  "for a top whose zones hold with it, add the insert to the design as a fixed "
                  "tube of its size and weight. Weigh the print before pressing the insert in.");
    }
    if (isfinite(out->weigh_offset_g)) {
        char t[320];
        snprintf(t, sizeof t,
                 "Weighing to calibrate the infill: the hole is printed %.2f mm across, the mass "
                 "model's is %.2f mm, so add %+.3f g (the print model's difference, same infill) "
                 "to the scale's reading of the bare print before giving it as measured_mass_g.",
                 out->hole_diameter_mm, 2 * hole_model_radius(d, out->hole_part),
                 out->weigh_offset_g);
        note(out, t);
    }
    return TIPPE_OK;
}

/* ------------------------------------------------------------ reports */

static cJSON *num(double x) { return isfinite(x) ? cJSON_CreateNumber(x) : cJSON_CreateNull(); }

static const char *measure_name(tippe_build_measure m)
{
    return m == TIPPE_BUILD_MEASURE_HOLE ? "hole" : m == TIPPE_BUILD_MEASURE_ROD ? "rod" : "none";
}

cJSON *tippe_build_json(const tippe_build_sheet *s)
{
    cJSON *o = cJSON_CreateObject();
    if (!o)
        return NULL;
    cJSON_AddStringToObject(o, "design", s->design_name);
    cJSON_AddStringToObject(o, "file", s->design_file);
    cJSON_AddNumberToObject(o, "radius_mm", s->radius_mm);
    cJSON *t = cJSON_AddArrayToObject(o, "physical_travel_mm");
    cJSON_AddItemToArray(t, num(s->travel_from_mm));
    cJSON_AddItemToArray(t, num(s->travel_to_mm));
    cJSON_AddBoolToObject(o, "three_in_one", s->three_in_one);
    cJSON *m = cJSON_AddObjectToObject(o, "measure");
    if (m) {
        cJSON_AddStringToObject(m, "kind", measure_name(s->measure));
        cJSON_AddStringToObject(m, "reference", s->reference);
        cJSON_AddItemToObject(m, "reference_z_mm",
                              num(s->measure ? s->reference_z_mm : NAN));
        cJSON_AddStringToObject(m, "weight", s->weight_name);
        if (s->measure == TIPPE_BUILD_MEASURE_HOLE) {
            cJSON_AddNumberToObject(m, "hole_printed_diameter_mm", s->hole_diameter_mm);
            cJSON_AddStringToObject(m, "hole_fit", s->hole_tapped   ? "tap"
                                                   : s->hole_insert ? "insert"
                                                                    : "slide");
            cJSON_AddStringToObject(m, "hole_fit_from",
                                    s->hole_fit_from_design ? "design" : "default or option");
            if (s->hole_insert) {
                cJSON *in = cJSON_AddObjectToObject(m, "insert");
                if (in) {
                    cJSON_AddStringToObject(in, "thread", s->insert.thread);
                    cJSON_AddNumberToObject(in, "pilot_hole_mm", s->insert.pilot_mm);
                    cJSON_AddNumberToObject(in, "outer_diameter_max_mm", s->insert.outer_max_mm);
                    cJSON_AddStringToObject(in, "source", TIPPE_BUILD_INSERT_SOURCE);
                }
            }
            cJSON_AddItemToObject(m, "weigh_offset_g", num(s->weigh_offset_g));
        }
        cJSON_AddNumberToObject(m, "weight_end_above_z2_mm", s->weight_end_offset_mm);
    }
    cJSON *th = cJSON_AddObjectToObject(o, "thread");
    if (th && s->has_thread) {
        cJSON_AddStringToObject(th, "name", s->thread_name);
        cJSON_AddNumberToObject(th, "d_mm", s->thread.d_mm);
        cJSON_AddNumberToObject(th, "pitch_mm", s->thread.pitch_mm);
        cJSON_AddNumberToObject(th, "tap_drill_mm", s->tap_drill_mm);
        cJSON_AddStringToObject(th, "tap_drill_rule", "d - P (ISO 2306 for ISO 261 threads)");
        if (s->catalogue_item[0]) {
            cJSON_AddStringToObject(th, "catalogue_item", s->catalogue_item);
            cJSON_AddStringToObject(th, "catalogue", s->catalogue_title);
        } else {
            cJSON_AddNullToObject(th, "catalogue_item");
        }
        cJSON_AddBoolToObject(th, "assumed", s->thread_assumed);
    }
    cJSON *arr = cJSON_AddArrayToObject(o, "settings");
    for (int f = 0; arr && f < 3; f++) {
        const tippe_build_setting *x = &s->set[f];
        cJSON *j = cJSON_CreateObject();
        if (!j || !cJSON_AddItemToArray(arr, j)) {
            cJSON_Delete(j);
            break;
        }
        cJSON_AddStringToObject(j, "behaviour", behaviours[f]);
        cJSON_AddStringToObject(j, "group", families[f]);
        cJSON_AddBoolToObject(j, "reachable", x->reachable);
        if (!x->reachable)
            continue;
        cJSON_AddBoolToObject(j, "robust", x->robust);
        cJSON_AddNumberToObject(j, "z2_from_mm", x->from_mm);
        cJSON_AddNumberToObject(j, "z2_to_mm", x->to_mm);
        cJSON_AddNumberToObject(j, "band_from_mm", x->band_from_mm);
        cJSON_AddNumberToObject(j, "band_to_mm", x->band_to_mm);
        cJSON_AddNumberToObject(j, "robust_from_mm", x->robust_from_mm);
        cJSON_AddNumberToObject(j, "robust_to_mm", x->robust_to_mm);
        cJSON_AddNumberToObject(j, "robust_width_mm",
                                x->robust ? x->robust_to_mm - x->robust_from_mm : 0);
        cJSON_AddNumberToObject(j, "set_z2_mm", x->set_z2_mm);
        cJSON_AddItemToObject(j, "depth_from_mm", num(x->depth_from_mm));
        cJSON_AddItemToObject(j, "depth_set_mm", num(x->depth_set_mm));
        cJSON_AddItemToObject(j, "depth_to_mm", num(x->depth_to_mm));
        cJSON_AddItemToObject(j, "turns_from", num(x->turns_from));
        cJSON_AddItemToObject(j, "turns_set", num(x->turns_set));
        cJSON_AddItemToObject(j, "turns_to", num(x->turns_to));
        cJSON_AddItemToObject(j, "spin_needed_rev_s", num(x->spin_needed_rev_s));
        cJSON_AddItemToObject(j, "spin_needed_max_rev_s", num(x->spin_needed_max_rev_s));
        cJSON_AddStringToObject(j, "spin_rule", x->spin_rule ? x->spin_rule : "");
        cJSON_AddItemToObject(j, "launch_spin_rev_s", num(x->spin_launch_rev_s));
        cJSON_AddBoolToObject(j, "beyond_hand_spin", x->beyond_hand);
        if (x->launch_status == TIPPE_OK) {
            cJSON_AddStringToObject(j, "launch_verdict", tippe_verdict_name(x->verdict));
            cJSON_AddBoolToObject(j, "launch_as_expected", x->verdict_ok);
            cJSON_AddNumberToObject(j, "launch_decided_s", x->launch_t_s);
        } else {
            cJSON_AddNullToObject(j, "launch_verdict");
            cJSON_AddBoolToObject(j, "launch_as_expected", 0);
        }
    }
    cJSON *b = cJSON_AddArrayToObject(o, "bill_of_materials");
    for (int k = 0; b && k < s->n_bom; k++) {
        cJSON *j = cJSON_CreateObject();
        if (!j || !cJSON_AddItemToArray(b, j)) {
            cJSON_Delete(j);
            break;
        }
        cJSON_AddNumberToObject(j, "quantity", s->bom[k].quantity);
        cJSON_AddStringToObject(j, "item", s->bom[k].what);
        cJSON_AddStringToObject(j, "detail", s->bom[k].detail);
    }
    cJSON *pa = cJSON_AddArrayToObject(o, "print");
    for (int k = 0; pa && k < s->n_print; k++) {
        cJSON *j = cJSON_CreateObject();
        if (!j || !cJSON_AddItemToArray(pa, j)) {
            cJSON_Delete(j);
            break;
        }
        const tippe_print_settings *p = &s->print[k].settings;
        cJSON_AddStringToObject(j, "part", s->print[k].part);
        cJSON_AddStringToObject(j, "material", s->print[k].material);
        cJSON_AddBoolToObject(j, "print_block", s->print[k].has_block);
        /* a body with no print block is modelled solid: no walls to count */
        if (s->print[k].has_block) {
            cJSON_AddNumberToObject(j, "perimeters", p->perimeters);
            cJSON_AddNumberToObject(j, "top_bottom_layers", p->top_bottom_layers);
        } else {
            cJSON_AddNullToObject(j, "perimeters");
            cJSON_AddNullToObject(j, "top_bottom_layers");
        }
        cJSON_AddNumberToObject(j, "line_width_mm", p->line_width_mm);
        cJSON_AddNumberToObject(j, "layer_height_mm", p->layer_height_mm);
        cJSON_AddNumberToObject(j, "infill", s->print[k].infill);
        cJSON_AddBoolToObject(j, "calibrated", s->print[k].calibrated);
        cJSON_AddStringToObject(j, "orientation",
                                s->needs_split ? "axis vertical, halves on their cut faces"
                                               : "axis vertical");
    }
    cJSON_AddBoolToObject(o, "split", s->needs_split);
    cJSON_AddBoolToObject(o, "joint_ring", s->joint_ring);
    cJSON *adv = cJSON_AddArrayToObject(o, "to_make_it_three_in_one");
    for (int k = 0; adv && k < s->n_advice; k++) {
        cJSON *j = cJSON_CreateObject();
        if (!j || !cJSON_AddItemToArray(adv, j)) {
            cJSON_Delete(j);
            break;
        }
        cJSON_AddStringToObject(j, "field", s->advice[k].field);
        cJSON_AddNumberToObject(j, "now", s->advice[k].now);
        cJSON_AddNumberToObject(j, "edge", s->advice[k].value);
        cJSON_AddStringToObject(j, "side", s->advice[k].at_least ? "at_least" : "at_most");
        cJSON_AddStringToObject(j, "advice", s->advice[k].text);
    }
    cJSON *stp = cJSON_AddArrayToObject(o, "steps");
    for (int k = 0; stp && k < s->n_steps; k++)
        cJSON_AddItemToArray(stp, cJSON_CreateString(s->step[k]));
    cJSON *n = cJSON_AddArrayToObject(o, "notes");
    for (int k = 0; n && k < s->n_notes; k++)
        cJSON_AddItemToArray(n, cJSON_CreateString(s->note[k]));
    return o;
}

/* "12.34 mm" or "-" */
static const char *mm(double v, char *buf, size_t size)
{
    if (isfinite(v))
        snprintf(buf, size, "%.2f mm", v);
    else
        snprintf(buf, size, "-");
    return buf;
}

static const char *turns(double v, char *buf, size_t size)
{
    if (isfinite(v))
        snprintf(buf, size, "%.1f", v);
    else
        snprintf(buf, size, "-");
    return buf;
}

void tippe_build_markdown(FILE *f, const tippe_build_sheet *s)
{
    char a[32], b[32], c[32], d[32], e[32], g[32];
    fprintf(f, "# Build sheet: %s\n\nDesign file `%s`; sphere radius %g mm; the weight's "
               "physical travel Z2 = %.2f .. %.2f mm.\n\n",
            s->design_name, s->design_file, s->radius_mm, s->travel_from_mm, s->travel_to_mm);
    fprintf(f, "## Settings\n\n");
    if (s->measure != TIPPE_BUILD_MEASURE_NONE)
        fprintf(f, "Measure from %s.\n\n", s->reference);
    fprintf(f, "| behaviour | group | robust Z2 range | set Z2 | depth (range) | depth to set | "
               "turns to set | spin needed | launch check |\n"
               "|---|---|---|---|---|---|---|---|---|\n");
    for (int k = 0; k < 3; k++) {
        const tippe_build_setting *x = &s->set[k];
        if (!x->reachable) {
            fprintf(f, "| %s | %s | not reachable within the travel where the model applies "
                       "| | | | | | |\n",
                    behaviours[k], families[k]);
            continue;
        }
        char range[80], spin[96], check[120];
        if (x->robust)
            snprintf(range, sizeof range, "%.2f .. %.2f mm", x->robust_from_mm, x->robust_to_mm);
        else
            snprintf(range, sizeof range, "none robust (zone %.2f .. %.2f mm)", x->from_mm,
                     x->to_mm);
        if (k == 0)
            snprintf(spin, sizeof spin, "any");
        else if (isfinite(x->spin_needed_max_rev_s))
            snprintf(spin, sizeof spin, "above %.1f rev/s (%.1f at the range's worst end)",
                     x->spin_needed_rev_s, x->spin_needed_max_rev_s);
        else
            snprintf(spin, sizeof spin, "no spin suffices");
        if (x->launch_status == TIPPE_OK)
            snprintf(check, sizeof check, "%s at %.1f rev/s%s%s", tippe_verdict_name(x->verdict),
                     x->spin_launch_rev_s, x->verdict_ok ? " (as expected)" : " (NOT as expected)",
                     x->beyond_hand ? "; beyond a hand spin" : "");
        else
            snprintf(check, sizeof check, "not run");
        double lo = fmin(x->depth_from_mm, x->depth_to_mm);
        double hi = fmax(x->depth_from_mm, x->depth_to_mm);
        fprintf(f, "| %s | %s | %s | %.2f mm | %s .. %s | %s | %s | %s | %s |\n", behaviours[k],
                families[k], range, x->set_z2_mm, mm(lo, a, sizeof a),
                mm(hi, b, sizeof b), mm(x->depth_set_mm, c, sizeof c),
                turns(x->turns_set, d, sizeof d), spin, check);
    }
    (void)e;
    (void)g;
    fprintf(f, "\n%s 3-in-1: %s.\n", s->three_in_one ? "It is" : "It is not",
            s->three_in_one ? "all three behaviours are reachable within the travel where the model applies"
                            : "not every behaviour is reachable within the travel where the model applies");
    if (!s->three_in_one) {
        fprintf(f, "\nWhat would make it 3-in-1 (one change at a time, found by sweeping the "
                   "zones at each value; at the edge given the missing zone is just born, so go "
                   "beyond it for a zone wide enough to set):\n\n");
        for (int k = 0; k < s->n_advice; k++)
            fprintf(f, "- %s (`--set %s=%.4g`).\n", s->advice[k].text, s->advice[k].field,
                    s->advice[k].value);
        if (!s->n_advice)
            fprintf(f, "- no single change of the infill, the weight's density (1 .. 22 g/cm^3) "
                       "or its length (half to double) makes it 3-in-1.\n");
    }
    if (s->has_thread) {
        fprintf(f, "\nThread: %s x %g mm", s->thread_name, s->thread.pitch_mm);
        if (s->catalogue_item[0])
            fprintf(f, " (catalogue item %s, %s)", s->catalogue_item, s->catalogue_title);
        else if (s->thread_assumed)
            fprintf(f, " (assumed: no catalogue item matches the weight; the ISO 261 size whose "
                       "pitch diameter is nearest its modelled diameter)");
        fprintf(f, "; tap drill %.2f mm (d - P, ISO 2306).\n", s->tap_drill_mm);
    }
    fprintf(f, "\n## Bill of materials\n\n| qty | item | detail |\n|---|---|---|\n");
    for (int k = 0; k < s->n_bom; k++)
        fprintf(f, "| %d | %s | %s |\n", s->bom[k].quantity, s->bom[k].what, s->bom[k].detail);
    fprintf(f, "\n## Print settings\n\n| part | material | perimeters | top/bottom layers | "
               "infill | orientation |\n|---|---|---|---|---|---|\n");
    for (int k = 0; k < s->n_print; k++) {
        const tippe_print_settings *p = &s->print[k].settings;
        if (s->print[k].has_block)
            fprintf(f, "| %s | %s | %d x %.2f mm | %d x %.2f mm | %.0f %%%s | axis vertical%s |\n",
                    s->print[k].part, s->print[k].material, p->perimeters, p->line_width_mm,
                    p->top_bottom_layers, p->layer_height_mm, 100 * s->print[k].infill,
                    s->print[k].calibrated ? " (calibrated by weighing)" : "",
                    s->needs_split ? ", halves on their cut faces" : "");
        else
            fprintf(f, "| %s | %s | as many as fill it | - | 100 %% (solid: the design has no "
                       "print block) | axis vertical%s |\n",
                    s->print[k].part, s->print[k].material,
                    s->needs_split ? ", halves on their cut faces" : "");
    }
    fprintf(f, "\n## Steps\n\n");
    for (int k = 0; k < s->n_steps; k++)
        fprintf(f, "%d. %s\n", k + 1, s->step[k]);
    if (s->n_notes) {
        fprintf(f, "\n## Notes\n\n");
        for (int k = 0; k < s->n_notes; k++)
            fprintf(f, "- %s\n", s->note[k]);
    }
}
