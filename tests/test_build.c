/* The build module against hand values: ISO 261's coarse pitches, ISO 2306's tap drills,
 * ISO 724's pitch diameters, the heat-set inserts' table, the shipped hardware catalogue,
 * the bill of materials of the paper's M12 top and of a catalogue design, and the advice
 * (each change it offers, applied, gives a settable sheet). Run from the repository root. */
#include "tippe/build.h"
#include "tippe/design.h"

#include "check.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ISO 261, coarse series, first-choice sizes, typed from the standard's table; beside each
 * the tap drill of ISO 2306's table (the drill, not the rule). */
static const struct {
    const char *name;
    double d, pitch, tap_drill;
} iso[] = {
    {"M1.6", 1.6, 0.35, 1.25}, {"M2", 2, 0.4, 1.6},    {"M2.5", 2.5, 0.45, 2.05},
    {"M3", 3, 0.5, 2.5},       {"M4", 4, 0.7, 3.3},    {"M5", 5, 0.8, 4.2},
    {"M6", 6, 1.0, 5.0},       {"M8", 8, 1.25, 6.8},   {"M10", 10, 1.5, 8.5},
    {"M12", 12, 1.75, 10.2},   {"M14", 14, 2.0, 12.0}, {"M16", 16, 2.0, 14.0},
    {"M20", 20, 2.5, 17.5},    {"M24", 24, 3.0, 21.0},
};
enum { N_ISO = sizeof iso / sizeof iso[0] };

static void test_threads(void)
{
    for (int k = 0; k < N_ISO; k++) {
        const tippe_build_thread *t = tippe_build_thread_by_diameter(iso[k].d);
        CHECK(t && !strcmp(t->name, iso[k].name), "%s by its diameter", iso[k].name);
        if (!t)
            continue;
        /* a pitch is a table entry, typed the same: equal to rounding */
        CHECK(fabs(t->pitch_mm - iso[k].pitch) < 1e-12, "%s pitch %g, ISO 261 %g", t->name,
              t->pitch_mm, iso[k].pitch);
        /* ISO 2306 rounds d - P to a drill of the 0.1 mm series (M8: 6.8, M12: 10.2): half a
         * step, 0.05 mm */
        double drill = tippe_build_tap_drill_mm(t);
        CHECK(fabs(drill - iso[k].tap_drill) <= 0.05 + 1e-12, "%s tap drill %g, ISO 2306 %g",
              t->name, drill, iso[k].tap_drill);
        /* ISO 724: d2 = d - 0.649519 P; the thread of that pitch diameter is itself, and
         * half-way to its neighbour (2 % of d2, less than any gap between sizes) still is */
        double d2 = iso[k].d - 0.649519 * iso[k].pitch;
        CHECK(tippe_build_thread_by_pitch_diameter(d2) == t, "%s by its d2 %g", t->name, d2);
    }
    /* not a first-choice size, or a size off by a micrometre and more: none */
    CHECK(!tippe_build_thread_by_diameter(7), "M7 is no ISO 261 size");
    CHECK(!tippe_build_thread_by_diameter(12.001), "12.001 mm is no ISO 261 size");
    /* the paper's M12 setscrew is modelled as an 11 mm cylinder: nearest d2 is M12's 10.86 */
    const tippe_build_thread *t = tippe_build_thread_by_pitch_diameter(11);
    CHECK(t && !strcmp(t->name, "M12"), "an 11 mm pitch diameter is M12's");
}

/* TIPPE_BUILD_INSERT_SOURCE's table, M3 .. M6, and the lengths of the ruthex part names. */
static void test_inserts(void)
{
    static const struct {
        const char *thread;
        double d, length;
    } want[] = {{"M3", 3, 5.7}, {"M4", 4, 8.1}, {"M5", 5, 9.5}, {"M6", 6, 12.7}};
    for (int k = 0; k < 4; k++) {
        const tippe_build_insert *in = tippe_build_insert_for(want[k].thread);
        CHECK(in != NULL, "an insert for %s", want[k].thread);
        if (!in)
            continue;
        /* the part name states the length to 0.1 mm: typed the same, equal to rounding */
        CHECK(fabs(in->length_mm - want[k].length) < 1e-12, "%s insert %g mm long, ruthex %g",
              in->thread, in->length_mm, want[k].length);
        /* a brass wall stands around the thread, and the knurl must bite into the plastic
         * around the pilot hole: d < pilot < knurl, each by at least 0.3 mm */
        CHECK(in->pilot_mm >= want[k].d + 0.3, "%s pilot %g mm around a %g mm thread",
              in->thread, in->pilot_mm, want[k].d);
        CHECK(in->outer_max_mm >= in->pilot_mm + 0.3, "%s knurl %g mm over a %g mm pilot",
              in->thread, in->outer_max_mm, in->pilot_mm);
    }
    CHECK(!tippe_build_insert_for("M8"), "the table stops at M6");
    CHECK(!tippe_build_insert_for(NULL), "no thread, no insert");
}

/* designs/catalogue.json: every screw is an ISO 261 coarse thread, modelled as a cylinder
 * of its pitch diameter (radius written to 4 decimals: within 5e-5 mm), found by its
 * radius and height and by its name. */
static void test_catalogue(void)
{
    tippe_build_catalogue *c = NULL;
    tippe_error err = {0};
    int rc = tippe_build_catalogue_load("designs/catalogue.json", &c, &err);
    CHECK(rc == 0 && c, "the shipped catalogue reads: %s", err.msg);
    if (rc)
        return;
    int n = 0;
    for (int s = 0; s < c->n_sets; s++)
        for (int i = 0; i < c->sets[s].n_items; i++, n++) {
            const tippe_build_catalogue_item *it = &c->sets[s].items[i];
            const tippe_build_thread *t = tippe_build_thread_by_diameter(it->d_mm);
            CHECK(t && !strcmp(t->name, it->thread) && fabs(t->pitch_mm - it->pitch_mm) < 1e-12,
                  "%s: %s x %g is ISO 261's coarse thread", it->name, it->thread, it->pitch_mm);
            CHECK(fabs(it->radius_mm - (it->d_mm - 0.649519 * it->pitch_mm) / 2) <= 5e-5 + 1e-12,
                  "%s: radius %g is half its pitch diameter", it->name, it->radius_mm);
            const tippe_build_catalogue_set *set = NULL;
            CHECK(tippe_build_catalogue_find(c, it->name, &set) == it && set == &c->sets[s],
                  "%s found by its name", it->name);
            CHECK(tippe_build_catalogue_match(c, it->radius_mm, it->height_mm, NULL) != NULL,
                  "%s found by its radius and height", it->name);
        }
    CHECK(n >= 20, "the catalogue lists %d screws", n);
    CHECK(!tippe_build_catalogue_find(c, "M12x999", NULL), "no such screw");
    tippe_build_catalogue_free(c);
}

static tippe_design *load(const char *path, const char *const *sets, int n)
{
    tippe_design *d = NULL;
    tippe_error err = {0};
    int rc = tippe_design_load(path, sets, n, &d, &err);
    CHECK(rc == 0, "%s loads: %s", path, err.msg);
    return rc ? NULL : d;
}

static const char *bom_with(const tippe_build_sheet *s, const char *what)
{
    for (int k = 0; k < s->n_bom; k++)
        if (strstr(s->bom[k].what, what) || strstr(s->bom[k].detail, what))
            return s->bom[k].detail;
    return NULL;
}

/* The paper's M12 top: no catalogue screw is an 11 mm cylinder, so the nearest ISO 261
 * thread (M12 x 1.75) is assumed, tapped at d - P = 10.25 mm; a quarter turn of it (0.4375
 * mm) is the narrowest setting; its hangs range is narrower (0.107 mm), so the sheet is 3-in-1
 * on paper only, and each change of its advice, applied, makes a settable sheet. */
static void test_m12_sheet(void)
{
    tippe_design *d = load("designs/m12-setscrew.json", NULL, 0);
    if (!d)
        return;
    tippe_build_options o;
    tippe_build_options_default(&o);
    tippe_build_sheet *s = calloc(1, sizeof *s);
    tippe_error err = {0};
    int rc = tippe_build_compute(d, &o, s, &err);
    CHECK(rc == 0, "the M12 sheet: %s", err.msg);
    if (rc)
        goto done;
    CHECK(s->has_thread && s->thread_assumed && !strcmp(s->thread_name, "M12"),
          "the M12 is assumed an M12 (%s)", s->thread_name);
    CHECK(fabs(s->thread.pitch_mm - 1.75) < 1e-12, "its pitch %g", s->thread.pitch_mm);
    /* d - P, both table entries: equal to rounding */
    CHECK(fabs(s->tap_drill_mm - 10.25) < 1e-12, "tap drill %g", s->tap_drill_mm);
    CHECK(fabs(s->min_setting_mm - 1.75 / 4) < 1e-12, "a quarter turn %g", s->min_setting_mm);
    CHECK(s->three_in_one && !s->settable, "3-in-1 on paper only");
    CHECK(!strcmp(tippe_build_verdict(s), "3-in-1 on paper only"), "%s", tippe_build_verdict(s));
    const char *screw = bom_with(s, "'screw'");
    CHECK(screw && strstr(screw, "M12 x 1.75"), "the bill names the thread: %s",
          screw ? screw : "(no line)");
    const char *body = bom_with(s, "printed body 'body'");
    /* the sphere's diameter, printed to 0.01 mm */
    CHECK(body && strstr(body, "50.00 mm across"), "the body is the 50 mm ball: %s",
          body ? body : "(no line)");
    CHECK(s->n_advice >= 1, "advice offered (%d)", s->n_advice);
    for (int k = 0; k < s->n_advice; k++) {
        const char *sets[8];
        for (int j = 0; j < s->advice[k].n_set; j++)
            sets[j] = s->advice[k].set[j];
        tippe_design *dk = load("designs/m12-setscrew.json", sets, s->advice[k].n_set);
        if (!dk)
            continue;
        tippe_build_sheet *sk = calloc(1, sizeof *sk);
        rc = tippe_build_compute(dk, &o, sk, &err);
        CHECK(rc == 0 && sk->settable == s->advice[k].settable,
              "advice %d (%s) applied: settable %d, as it says %d", k, s->advice[k].text,
              sk->settable, s->advice[k].settable);
        /* the same sweep of the same design: the same widths to rounding */
        double narrowest = INFINITY;
        for (int f = 0; f < 3; f++)
            narrowest = fmin(narrowest, sk->set[f].robust_width_mm);
        CHECK(rc == 0 && fabs(narrowest - s->advice[k].narrowest_mm) < 1e-9,
              "advice %d: narrowest %g, as it says %g", k, narrowest, s->advice[k].narrowest_mm);
        CHECK(fabs(sk->min_setting_mm - s->advice[k].min_setting_mm) < 1e-12,
              "advice %d: its thread's quarter turn %g, as it says %g", k, sk->min_setting_mm,
              s->advice[k].min_setting_mm);
        free(sk);
        tippe_design_free(dk);
    }
done:
    free(s);
    tippe_design_free(d);
}

/* A design whose screw is a catalogue item: the bill names the item and its ISO thread. */
static void test_catalogue_sheet(void)
{
    tippe_design *d = load("designs/drilled-ball-catalogue-best.json", NULL, 0);
    if (!d)
        return;
    tippe_build_options o;
    tippe_build_options_default(&o);
    tippe_build_sheet *s = calloc(1, sizeof *s);
    tippe_error err = {0};
    int rc = tippe_build_compute(d, &o, s, &err);
    CHECK(rc == 0, "the catalogue design's sheet: %s", err.msg);
    if (!rc) {
        CHECK(!strcmp(s->catalogue_item, "M10x12") && !s->thread_assumed,
              "its screw is the catalogue's M10x12 (%s)", s->catalogue_item);
        CHECK(!strcmp(s->thread_name, "M10") && fabs(s->tap_drill_mm - 8.5) < 1e-12,
              "M10, tapped at 8.5 mm (%s, %g)", s->thread_name, s->tap_drill_mm);
        CHECK(bom_with(s, "M10x12") != NULL || bom_with(s, "M10 x 1.5") != NULL,
              "the bill names the screw");
    }
    free(s);
    tippe_design_free(d);
}

int main(void)
{
    test_threads();
    test_inserts();
    test_catalogue();
    test_m12_sheet();
    test_catalogue_sheet();
    return check_summary("test_build");
}
