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

/* ------------------------------------------------- buyable changes */

/* PrusaSlicer's list of infill densities (src/libslic3r/PrintConfig.cpp,
 * fill_density's enum_values): the steps a maker picks from. */
static const double slicer_infill_steps[] = {0,    0.05, 0.10, 0.15, 0.20, 0.25, 0.30,
                                             0.40, 0.50, 0.60, 0.70, 0.80, 0.90, 1.00};

/* the travel first: a change that costs nothing is said before those one buys */
enum { FAM_TRAVEL, FAM_INFILL, FAM_MATERIAL, FAM_WEIGHT, N_FAM };
enum { MAX_SETS = 8, MAX_CHANGES = 160 };

/* One change a maker can make: the overrides that make it, what it is in
 * words, how far it is from the design (relative, for choosing the nearest),
 * and, once tried, what the sheet would say of the changed design. */
typedef struct {
    int family;
    int n_set;
    char set[MAX_SETS][200];
    char what[320];
    double change;
    double min_setting_mm;
    int tried, loads, settable;
    double narrowest_mm, score;
} change;

typedef struct {
    const tippe_design *d;
    const tippe_build_options *o;
    tippe_build_sheet *s;
    change *c;
    int n;
} advice_ctx;

static change *add_change(advice_ctx *a, int family, double change_by, double min_setting_mm)
{
    if (a->n >= MAX_CHANGES)
        return NULL;
    change *c = &a->c[a->n++];
    memset(c, 0, sizeof *c);
    c->family = family;
    c->change = change_by;
    c->min_setting_mm = min_setting_mm;
    return c;
}

static void add_set(change *c, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void add_set(change *c, const char *fmt, ...)
{
    if (c->n_set >= MAX_SETS)
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(c->set[c->n_set++], sizeof c->set[0], fmt, ap);
    va_end(ap);
}

/* The sheet's test of a changed design (tippe_build_verdict_with: its zones
 * with their tolerance bands, as step 1 of the sheet); settable when every
 * behaviour's robust width reaches the change's min_setting_mm. score counts
 * the behaviours that do, with partial credit, for choosing which changes to
 * pair. */
static void try_change(advice_ctx *a, change *c)
{
    const char *ov[MAX_SETS];
    for (int i = 0; i < c->n_set; i++)
        ov[i] = c->set[i];
    c->tried = 1;
    a->s->n_advice_tried++;
    tippe_build_zones_of z;
    const int verdict = tippe_build_verdict_with(a->d, ov, c->n_set, c->min_setting_mm, &z);
    if (verdict < 0)
        return;
    c->loads = 1;
    c->settable = verdict == 2;
    c->narrowest_mm = z.narrowest_mm;
    for (int f = 0; f < 3; f++) {
        const tippe_build_setting *st = &z.set[f];
        double w = st->reachable && st->robust ? st->robust_to_mm - st->robust_from_mm : 0;
        c->score += fmin(w / c->min_setting_mm, 1) + (st->reachable ? 0.01 : 0);
    }
}

/* The infill steps of each printed part that is not the design's own. A
 * weighed part's scale reading belongs to the old infill: it goes. */
static void infill_changes(advice_ctx *a, const char *name,
                           const tippe_design_print_info *pr)
{
    for (size_t k = 0; k < sizeof slicer_infill_steps / sizeof *slicer_infill_steps; k++) {
        double x = slicer_infill_steps[k];
        if (fabs(x - pr->infill) < 5e-3)
            continue;
        change *c = add_change(a, FAM_INFILL, fabs(x - pr->infill), a->s->min_setting_mm);
        if (!c)
            return;
        add_set(c, "parts.%s.print.infill=%g", name, x);
        if (pr->calibrated)
            add_set(c, "parts.%s.print.measured_mass_g=null", name);
        snprintf(c->what, sizeof c->what, "print '%s' at %.0f %% infill (now %.0f %%%s)", name,
                 100 * x, 100 * pr->infill, pr->calibrated ? ", weighed: weigh the new print" : "");
    }
}

/* The bought materials of the design's table (printable: false) for the
 * moving part, other than its own; for a screw turned in a thread only those
 * set screws are sold in ("set_screws"). */
static void material_changes(advice_ctx *a, const char *name, const tippe_design_part_info *p,
                             int screw)
{
    tippe_materials *t = NULL;
    tippe_error e = {0};
    if (tippe_design_materials(a->d, &t, &e))
        return;
    for (int k = 0; k < tippe_materials_count(t); k++) {
        tippe_material m;
        tippe_materials_get(t, k, &m);
        if (m.printable || (screw && !m.set_screws) || !strcmp(m.name, p->material) ||
            fabs(m.density_g_cm3 - p->density_g_cm3) < 1e-9)
            continue;
        change *c = add_change(a, FAM_MATERIAL,
                               fabs(m.density_g_cm3 / p->density_g_cm3 - 1), a->s->min_setting_mm);
        if (!c)
            break;
        add_set(c, "parts.%s.material=%s", name, m.name);
        snprintf(c->what, sizeof c->what, "make '%s' of %s (%.2f g/cm^3; now %s, %.2f)", name,
                 m.name, m.density_g_cm3, p->material, p->density_g_cm3);
    }
    tippe_materials_free(t);
}

/* The catalogue's screws in place of a screw in a hole: each item's size and
 * length, the hole tied to the screw's radius (the catalogue's advice), the
 * item named so that the sheet of the changed design names it. A new thread
 * brings its own quarter turn. */
static void catalogue_changes(advice_ctx *a, const char *name, const tippe_design_solid *sd,
                              const tippe_build_catalogue *cat, const char *hole,
                              const char *material)
{
    /* a catalogue screw is bought in a material set screws are sold in: the
     * design's, if it is one, else steel (ISO 4026's usual grade 45H) */
    const char *buy = NULL;
    tippe_materials *t = NULL;
    tippe_error e = {0};
    if (!tippe_design_materials(a->d, &t, &e)) {
        int own = 0, steel = 0;
        for (int k = 0; k < tippe_materials_count(t); k++) {
            tippe_material m;
            tippe_materials_get(t, k, &m);
            own |= m.set_screws && !strcmp(m.name, material);
            steel |= m.set_screws && !strcmp(m.name, "steel");
        }
        buy = !own && steel ? "steel" : NULL;
    }
    tippe_materials_free(t);
    double R = tippe_design_radius_mm(a->d);
    double m_now = sd->radius_mm * sd->radius_mm * sd->height_mm;
    for (int k = 0; k < cat->n_sets; k++)
        for (int j = 0; j < cat->sets[k].n_items; j++) {
            const tippe_build_catalogue_item *it = &cat->sets[k].items[j];
            if (it->height_mm > R || it->radius_mm > R / 2 ||
                (fabs(it->radius_mm - sd->radius_mm) < 1e-6 &&
                 fabs(it->height_mm - sd->height_mm) < 1e-6))
                continue;
            double m = it->radius_mm * it->radius_mm * it->height_mm;
            change *c = add_change(a, FAM_WEIGHT, fabs(m / m_now - 1),
                                   a->o->min_setting_mm > 0 ? a->o->min_setting_mm
                                                            : it->pitch_mm / 4);
            if (!c)
                return;
            add_set(c, "parts.%s.radius_mm=%.10g", name, it->radius_mm);
            add_set(c, "parts.%s.height_mm=%.10g", name, it->height_mm);
            add_set(c, "parts.%s.catalogue_item=%s", name, it->name);
            if (hole)
                add_set(c, "parts.%s.radius_mm=%.10g", hole, it->radius_mm);
            if (buy)
                add_set(c, "parts.%s.material=%s", name, buy);
            if (snprintf(c->what, sizeof c->what, "set screw %s (%s)%s%s as '%s'", it->name,
                         cat->sets[k].title, buy ? " in " : "", buy ? buy : "",
                         name) >= (int)sizeof c->what)
                a->n--; /* no room to say it: not offered */
        }
}

/* A cylinder's or tube's length in whole millimetres, from half to double
 * the design's (within the sphere's diameter). */
static void length_changes(advice_ctx *a, const char *name, const tippe_design_solid *sd)
{
    double R = tippe_design_radius_mm(a->d);
    int lo = (int)fmax(1, ceil(sd->height_mm / 2));
    int hi = (int)fmin(floor(2 * sd->height_mm), floor(2 * R));
    for (int L = lo; L <= hi; L++) {
        if (fabs(L - sd->height_mm) < 1e-9)
            continue;
        change *c = add_change(a, FAM_WEIGHT, fabs(L / sd->height_mm - 1), a->s->min_setting_mm);
        if (!c)
            return;
        add_set(c, "parts.%s.height_mm=%d", name, L);
        snprintf(c->what, sizeof c->what, "cut '%s' %d mm long (now %.4g mm)", name, L,
                 sd->height_mm);
    }
}

/* The weight's travel out to what its parts allow (the sheet's physical travel), where the
 * design's own travel_mm stops short of it (issue 37: a zone cut by travel_mm, not by the
 * physics, was sent to buy a screw): nothing to buy, a screw turned further. */
static void travel_change(advice_ctx *a)
{
    const tippe_build_sheet *s = a->s;
    /* an end more than 1 um short moves to the parts' limit, 0.01 um inside it (the
     * limit is found to within 1e-6 mm by bisection: its last digit may lie beyond) */
    const double f0 = s->design_travel_from_mm, t0 = s->design_travel_to_mm;
    const double f1 = s->travel_from_mm < f0 - 1e-3 ? s->travel_from_mm + 1e-5 : f0;
    const double t1 = s->travel_to_mm > t0 + 1e-3 ? s->travel_to_mm - 1e-5 : t0;
    if (f1 == f0 && t1 == t0)
        return;
    change *c = add_change(a, FAM_TRAVEL, 0, s->min_setting_mm);
    if (!c)
        return;
    add_set(c, "travel_mm=[%.9g,%.9g]", f1, t1);
    snprintf(c->what, sizeof c->what,
             "let the weight travel %.2f .. %.2f mm, as far as its parts allow (now %.2f .. "
             "%.2f mm, the design's travel_mm): nothing to buy",
             f1, t1, f0, t0);
}

/* Every single change the design allows: the weight's travel as far as its parts allow,
 * the infill of each printed part (not one a G-code gives),
 * and for the moving weight its material, and a catalogue screw (a screw in
 * a hole, with a catalogue) or its length in whole mm. */
static void list_changes(advice_ctx *a, const tippe_build_catalogue *cat)
{
    const char *hole = NULL;
    tippe_design_part_info hp;
    if (a->s->measure == TIPPE_BUILD_MEASURE_HOLE && a->s->hole_part >= 0 &&
        !tippe_design_part(a->d, a->s->hole_part, &hp))
        hole = hp.name;
    travel_change(a);
    for (int i = 0; i < tippe_design_n_parts(a->d); i++) {
        tippe_design_part_info p;
        tippe_design_print_info pr;
        tippe_design_solid sd;
        if (tippe_design_part(a->d, i, &p) || tippe_design_part_print(a->d, i, &pr) ||
            tippe_design_part_solid(a->d, i, &sd))
            continue;
        /* a part printed as its G-code deposits it: the infill is the slicer's, in the
         * G-code (a sweep at another infill is the same body): slicing again is the
         * change, which the print model's sheet (without the G-code) tries */
        if (pr.printed && !pr.from_gcode) {
            infill_changes(a, p.name, &pr);
        } else if (pr.printed) {
            char t[400];
            snprintf(t, sizeof t,
                     "'%s' is printed as its G-code deposits it: the changes tried keep its "
                     "slicing, infill included. To try the slicer's infill steps, build the "
                     "design without print.gcode (the print model), then slice again at the "
                     "infill it advises.",
                     p.name);
            tippe_build_note(a->s, t);
        }
        else if (sd.moving && !sd.is_void) {
            int cyl = !strcmp(sd.shape, "cylinder") || !strcmp(sd.shape, "tube");
            material_changes(a, p.name, &p, hole && a->s->has_thread && cyl);
            if (cyl && cat && hole && !strcmp(sd.shape, "cylinder"))
                catalogue_changes(a, p.name, &sd, cat, hole, p.material);
            else if (cyl)
                length_changes(a, p.name, &sd);
        }
    }
}

/* Both changes at once (of different families). */
static int pair_of(const change *x, const change *y, change *out)
{
    if (x->n_set + y->n_set > MAX_SETS || x->family == y->family)
        return 0;
    *out = *x;
    out->tried = out->loads = out->settable = 0;
    out->narrowest_mm = out->score = 0;
    for (int i = 0; i < y->n_set; i++)
        snprintf(out->set[out->n_set++], sizeof out->set[0], "%s", y->set[i]);
    if (snprintf(out->what, sizeof out->what, "%s, and %s", x->what, y->what) >=
        (int)sizeof out->what)
        return 0;
    out->change = x->change + y->change;
    out->min_setting_mm = fmin(x->min_setting_mm, y->min_setting_mm);
    if (x->family == FAM_WEIGHT || y->family == FAM_WEIGHT)
        out->min_setting_mm = x->family == FAM_WEIGHT ? x->min_setting_mm : y->min_setting_mm;
    out->family = -1;
    return 1;
}

static void put_advice(tippe_build_sheet *s, const change *c, int pair)
{
    if (s->n_advice >= (int)(sizeof s->advice / sizeof s->advice[0]))
        return;
    int k = s->n_advice++;
    s->advice[k].n_set = c->n_set;
    for (int i = 0; i < c->n_set; i++)
        snprintf(s->advice[k].set[i], sizeof s->advice[k].set[i], "%s", c->set[i]);
    s->advice[k].pair = pair;
    s->advice[k].settable = c->settable;
    s->advice[k].narrowest_mm = c->narrowest_mm;
    s->advice[k].min_setting_mm = c->min_setting_mm;
    int n;
    if (c->settable)
        n = snprintf(s->advice[k].text, sizeof s->advice[k].text,
                 "%s: settable, its narrowest robust range %.2f mm (at least %.2f needed)",
                 c->what, c->narrowest_mm, c->min_setting_mm);
    else
        n = snprintf(s->advice[k].text, sizeof s->advice[k].text,
                 "%s: the nearest to settable found, yet not (narrowest robust range %.2f mm, "
                 "%.2f needed)",
                 c->what, c->narrowest_mm, c->min_setting_mm);
    (void)n; /* text[] holds what[] and the figures */
}

/* Index of the settable change of family f (or of pairs, f = -1) nearest the
 * design, or widest; -1 if none. */
static int pick(const change *c, int n, int f, int widest)
{
    int best = -1;
    for (int i = 0; i < n; i++) {
        if (!c[i].settable || c[i].family != f)
            continue;
        if (best < 0 ||
            (widest ? c[i].narrowest_mm > c[best].narrowest_mm : c[i].change < c[best].change))
            best = i;
    }
    return best;
}

static int by_score(const void *x, const void *y)
{
    const change *a = x, *b = y;
    return a->score < b->score ? 1 : a->score > b->score ? -1 : (a->change > b->change) - (a->change < b->change);
}

/* What would make the design settable, as a maker can buy or set it: every
 * single change is tried as the sheet would judge it (its zones with their
 * tolerance bands, every behaviour at least min_setting_mm wide); for each
 * family the nearest settable change and the widest are given. Where no single
 * change is enough, pairs of the most promising changes of different families
 * (the four best-scoring of each) are tried. Cost: one sweep with bands per
 * change tried (n_advice_tried). */
void tippe_build_advise(const tippe_design *d, const tippe_build_options *o, tippe_build_sheet *s)
{
    advice_ctx a = {.d = d, .o = o, .s = s, .c = calloc(MAX_CHANGES, sizeof(change))};
    if (!a.c)
        return;
    tippe_build_catalogue *own = NULL;
    const tippe_build_catalogue *cat = o->catalogue_read;
    tippe_error e = {0};
    const char *file = o->catalogue ? o->catalogue : tippe_design_catalogue(d);
    if (!cat && file && !tippe_build_catalogue_load(file, &own, &e))
        cat = own;
    list_changes(&a, cat);
    tippe_build_catalogue_free(own);
    for (int i = 0; i < a.n && !tippe_cancel_requested(); i++) /* each a sweep */
        try_change(&a, &a.c[i]);
    int any = 0;
    for (int f = 0; f < N_FAM; f++) {
        int near = pick(a.c, a.n, f, 0), wide = pick(a.c, a.n, f, 1);
        if (near >= 0)
            put_advice(s, &a.c[near], 0), any = 1;
        if (wide >= 0 && wide != near && a.c[wide].narrowest_mm > 1.2 * a.c[near].narrowest_mm)
            put_advice(s, &a.c[wide], 0);
    }
    if (any) {
        free(a.c);
        return;
    }
    /* pairs: the four best of each family, two families at a time */
    qsort(a.c, (size_t)a.n, sizeof *a.c, by_score);
    int top[N_FAM][4], nt[N_FAM] = {0};
    for (int i = 0; i < a.n; i++) {
        int f = a.c[i].family;
        if (a.c[i].loads && nt[f] < 4)
            top[f][nt[f]++] = i;
    }
    change *pairs = calloc(N_FAM * (N_FAM - 1) / 2 * 16, sizeof(change)); /* 4 x 4 per two families */
    int np = 0;
    for (int f = 0; pairs && f < N_FAM; f++)
        for (int g = f + 1; g < N_FAM; g++)
            for (int i = 0; i < nt[f]; i++)
                for (int j = 0; j < nt[g]; j++)
                    if (!tippe_cancel_requested() &&
                        pair_of(&a.c[top[f][i]], &a.c[top[g][j]], &pairs[np])) {
                        try_change(&a, &pairs[np]);
                        np++;
                    }
    int near = pairs ? pick(pairs, np, -1, 0) : -1, wide = pairs ? pick(pairs, np, -1, 1) : -1;
    if (near >= 0)
        put_advice(s, &pairs[near], 1);
    if (wide >= 0 && wide != near)
        put_advice(s, &pairs[wide], 1);
    /* none: the change that comes nearest, if it is nearer than the design */
    double own_score = 0;
    for (int f = 0; f < 3; f++) {
        const tippe_build_setting *st = &s->set[f];
        double w = st->reachable && st->robust ? st->robust_to_mm - st->robust_from_mm : 0;
        own_score += fmin(w / s->min_setting_mm, 1) + (st->reachable ? 0.01 : 0);
    }
    const change *best = a.n > 0 && a.c[0].loads ? &a.c[0] : NULL;
    for (int i = 0; i < np; i++)
        if (pairs[i].loads && (!best || pairs[i].score > best->score))
            best = &pairs[i];
    if (near < 0 && best && best->score > own_score + 0.05)
        put_advice(s, best, best->family < 0);
    free(pairs);
    free(a.c);
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
    char set[4][300];
    snprintf(set[0], sizeof set[0], "parts.%s.radius_mm=%.10g", hp.name, s->hole_diameter_mm / 2);
    /* printed there and not cut: the bare print (no tap drill of its own, design_fit.c) */
    snprintf(set[1], sizeof set[1], "parts.%s.printed_radius_mm=%.10g", hp.name,
             s->hole_diameter_mm / 2);
    snprintf(set[2], sizeof set[2], "parts.%s.print.infill=%.17g", pp.name, before.infill);
    snprintf(set[3], sizeof set[3], "parts.%s.print.measured_mass_g=null", pp.name);
    const char *extra[4] = {set[0], set[1], set[2], set[3]};
    tippe_design *v = NULL;
    tippe_error e = {0};
    if (tippe_design_derive(d, extra, before.calibrated ? 4 : 3, &v, &e) == TIPPE_OK &&
        tippe_design_part_print(v, hs.parent, &after) == TIPPE_OK && after.printed)
        s->weigh_offset_g = (before.printed_mass_kg - after.printed_mass_kg) * 1e3;
    tippe_design_free(v);
}

/* ------------------------------------------------------ weighing */

static const char *verdict_name(int v) { return tippe_build_verdict_name(v); }

/* A printed part not yet weighed: its infill is the slicer's, within the
 * slicer-infill tolerance (docs/printing.md). Where the sheet's verdict
 * differs across that tolerance a weighing can decide (a scale says how much
 * plastic the print holds, which pins the effective infill; not where it
 * lies, which the G-code says: tippe slice), so the sheet gets a step to
 * weigh the print and run it again; where it does not, a note says so. */
void tippe_build_weigh_step(const tippe_design *d, tippe_build_sheet *s)
{
    for (int i = 0; i < tippe_design_n_parts(d) && !s->weigh_step[0]; i++) {
        tippe_design_part_info p;
        tippe_design_print_info pr;
        if (tippe_design_part(d, i, &p) || tippe_design_part_print(d, i, &pr) || !pr.printed ||
            pr.calibrated)
            continue;
        char field[200];
        snprintf(field, sizeof field, "parts.%s.print.infill", p.name);
        const tippe_tolerance *t = NULL;
        for (int k = 0; k < tippe_design_n_tolerances(d) && !t; k++)
            if (!strcmp(tippe_design_tolerance(d, k)->field, field))
                t = tippe_design_tolerance(d, k);
        if (!t)
            continue;
        double lo = pr.infill - t->minus, hi = pr.infill + t->plus; /* within 0 .. 1 */
        char set_lo[260], set_hi[260];
        snprintf(set_lo, sizeof set_lo, "%s=%.10g", field, lo);
        snprintf(set_hi, sizeof set_hi, "%s=%.10g", field, hi);
        const char *ov_lo[1] = {set_lo}, *ov_hi[1] = {set_hi};
        int v_lo = tippe_build_verdict_with(d, ov_lo, 1, s->min_setting_mm, NULL);
        int v_hi = tippe_build_verdict_with(d, ov_hi, 1, s->min_setting_mm, NULL);
        int v_now = s->settable ? 2 : s->three_in_one ? 1 : 0;
        if (v_lo < 0 || v_hi < 0)
            continue;
        char offset[160] = "";
        if (isfinite(s->weigh_offset_g))
            snprintf(offset, sizeof offset, " %s %.3f g (the printed hole against the model's)",
                     s->weigh_offset_g < 0 ? "less" : "plus", fabs(s->weigh_offset_g));
        /* the run again repeats the sheet's own changes (but an old weighing) */
        char again[1200] = "", mass[260];
        snprintf(mass, sizeof mass, "parts.%s.print.measured_mass_g=", p.name);
        for (int k = 0, m = 0; k < s->n_overrides && m < (int)sizeof again; k++)
            if (strncmp(s->override[k], mass, strlen(mass)))
                m += snprintf(again + m, sizeof again - (size_t)m, "--set %s ", s->override[k]);
        int n;
        if (v_lo != v_now || v_hi != v_now)
            n = snprintf(s->weigh_step, sizeof s->weigh_step,
                         "Weigh the bare print of '%s' (before any hardware goes in) and run "
                         "tippe build again with %s--set %sG, G the scale's reading%s: the "
                         "verdict hangs on how much plastic the slicer laid (%s at %.1f %% "
                         "infill, %s at %.1f %%, %s at the slicer's %.1f %%; the slicer-infill "
                         "tolerance), which a weighing pins.",
                         p.name, again, mass, offset, verdict_name(v_lo), 100 * lo,
                         verdict_name(v_hi), 100 * hi, verdict_name(v_now), 100 * pr.infill);
        else
            n = snprintf(s->weigh_note, sizeof s->weigh_note,
                         "Weighing '%s' would not change the verdict: it is %s at %.1f %% and at "
                         "%.1f %% infill too (the slicer's %.1f %% within its infill tolerance, "
                         "%.1f %%).",
                         p.name, verdict_name(v_now), 100 * lo, 100 * hi, 100 * pr.infill,
                         100 * t->plus_minus);
        (void)n; /* the buffers hold the sentences with their figures */
    }
}
