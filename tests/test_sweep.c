/* Tests of the Z2 sweep core and its plots on synthetic paths Z2 -> (A/C, eps/R),
 * checked against an independent reference: a dense scan of
 * tippe_theory_classify() with each change of group refined by bisection. */
#include "tippe/plot.h"
#include "tippe/sweep.h"

#include "check.h"

#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* The sweep promises 1e-6 mm; its solver stops at TIPPE_SWEEP_XTOL_MM = 1e-7. */
#define ZTOL_MM 1e-6

/* ---- synthetic paths ---------------------------------------------------- */

typedef struct {
    int kind;
    double a, z0, w, e;
} path_params;

enum { LINEAR, WAVY, FLAT, TOUCH_ABOVE, TOUCH_BELOW, DIP, BALANCE, OUTSIDE, VEE };

static void eval(double z, void *vp, double *k, double *es)
{
    const path_params *p = vp;
    switch (p->kind) {
    case LINEAR: /* crosses I -> II -> III, at z = 5 and z = 15 exactly */
        *k = 0.9 + 0.01 * z;
        *es = p->e;
        break;
    case WAVY: /* wanders through several subgroups */
        *k = 1.0 + 0.08 * sin(z / 3.0) - 0.03;
        *es = 0.04 + 0.02 * cos(z / 5.0);
        break;
    case FLAT: /* deep inside group I (Ib), nowhere near a boundary */
        *k = 0.5 + 0.001 * z;
        *es = 0.3;
        break;
    case TOUCH_ABOVE: /* g = (k-1)+e = a (z - z0)^2 >= 0: touches I/II from group II */
        *es = p->e;
        *k = 1.0 - p->e + p->a * (z - p->z0) * (z - p->z0);
        break;
    case TOUCH_BELOW: /* g = -a (z - z0)^2 <= 0: touches I/II from group I */
        *es = p->e;
        *k = 1.0 - p->e - p->a * (z - p->z0) * (z - p->z0);
        break;
    case DIP: /* g = c - 2c exp(-((z-z0)/w)^2): dips into group I over |z - z0| < w sqrt(ln 2) */
        *es = p->e;
        *k = 1.0 - p->e + p->a - 2.0 * p->a * exp(-pow((z - p->z0) / p->w, 2));
        break;
    case VEE: /* k - 1 falls (slope 0.02) to -0.1 at z = 10, then rises (0.01); e = 0.05
               * except over [9, 13], where the centre of mass crosses the centre at 11:
               * III [0, 2.5], II [2.5, 7.5], I [7.5, 15], II [15, 25], III [25, 30] */
        *k = 1.0 - 0.1 + (z < 10.0 ? 0.02 * (10.0 - z) : 0.01 * (z - 10.0));
        *es = z < 9.0 ? 0.05 : z > 13.0 ? -0.05 : 0.05 - 0.025 * (z - 9.0);
        break;
    case BALANCE: /* centre of mass crosses the sphere's centre at z = z0 */
        *k = 0.9;
        *es = p->a * (z - p->z0);
        break;
    case OUTSIDE: /* e reaches 1 at z = 10: outside the phase diagram */
        *k = 0.9;
        *es = 0.1 * z;
        break;
    }
}

/* ---- reference: dense scan of the classification, refined by bisection --- */

static int label(const tippe_sweep_path *p, double z)
{
    double k, es;
    p->eval(z, p->params, &k, &es);
    tippe_theory_class c;
    if (tippe_theory_classify(k, fabs(es), &c) != TIPPE_OK)
        return -1;
    return (int)c.group * 2 + (es < 0 ? 0 : 1); /* es = 0 counts as the + side */
}

/* Changes of (group, side) along [a, b]: n_scan samples, then 80 bisections of
 * each change (to far below 1e-6 mm). Returns how many, positions in out. */
static int reference_changes(const tippe_sweep_path *p, double a, double b, int n_scan,
                             double *out, int max)
{
    int n = 0, prev = label(p, a);
    double zprev = a;
    for (int j = 1; j <= n_scan; j++) {
        double z = a + (b - a) * j / n_scan;
        int l = label(p, z);
        if (l != prev && n < max) {
            double lo = zprev, hi = z;
            for (int it = 0; it < 80; it++) {
                double mid = 0.5 * (lo + hi);
                if (label(p, mid) == prev)
                    lo = mid;
                else
                    hi = mid;
            }
            out[n++] = 0.5 * (lo + hi);
        }
        prev = l;
        zprev = z;
    }
    return n;
}

/* The sweep's zone ends agree with the reference, one to one, within ZTOL_MM. */
static void check_against_reference(const char *name, path_params *pp, double a, double b)
{
    tippe_sweep_path p = {eval, pp};
    tippe_sweep_result r;
    tippe_error err = {0};
    int st = tippe_sweep_run(&p, a, b, NULL, &r, &err);
    CHECK(st == TIPPE_OK, "%s: sweep failed: %s", name, err.msg);
    if (st != TIPPE_OK) {
        tippe_sweep_result_free(&r);
        return;
    }
    double ref[64];
    int nref = reference_changes(&p, a, b, 200000, ref, 64);
    CHECK(r.n_zones == nref + 1, "%s: %d zones, reference has %d changes", name, r.n_zones,
          nref);
    for (int i = 0; i + 1 < r.n_zones && i < nref; i++) {
        double z = r.zones[i].z2_to_mm;
        CHECK(fabs(z - ref[i]) <= ZTOL_MM, "%s: zone end %d at %.9f mm, reference %.9f mm",
              name, i, z, ref[i]);
        CHECK(r.zones[i + 1].z2_from_mm == z, "%s: zones %d and %d do not meet", name, i, i + 1);
        CHECK(r.zones[i].to_boundaries != 0, "%s: zone end %d names no boundary", name, i);
    }
    /* Each zone's group is the classification inside it (a quarter of the way in,
     * not at the midpoint the sweep itself used). */
    for (int i = 0; i < r.n_zones; i++) {
        tippe_sweep_zone *zn = &r.zones[i];
        double z = zn->z2_from_mm + 0.25 * (zn->z2_to_mm - zn->z2_from_mm);
        CHECK(label(&p, z) / 2 == (int)zn->group, "%s: zone %d labelled %s", name, i,
              tippe_group_name(zn->group));
    }
    CHECK(r.zones[0].z2_from_mm == a && r.zones[r.n_zones - 1].z2_to_mm == b,
          "%s: zones do not cover the range", name);
    tippe_sweep_result_free(&r);
}

static void test_linear(void)
{
    path_params pp = {.kind = LINEAR, .e = 0.05};
    check_against_reference("linear", &pp, 0.0, 20.0);
    tippe_sweep_path p = {eval, &pp};
    tippe_sweep_result r;
    tippe_error err = {0};
    tippe_sweep_run(&p, 0.0, 20.0, NULL, &r, &err);
    /* The group I/II and II/III lines are crossed where 0.01 z - 0.1 = -+0.05,
     * at z = 5 and 15 mm exactly. */
    double i_ii = NAN, ii_iii = NAN;
    for (int i = 0; i + 1 < r.n_zones; i++) {
        if (r.zones[i].to_boundaries & (1u << TIPPE_SWEEP_I_II))
            i_ii = r.zones[i].z2_to_mm;
        if (r.zones[i].to_boundaries & (1u << TIPPE_SWEEP_II_III))
            ii_iii = r.zones[i].z2_to_mm;
    }
    CHECK(fabs(i_ii - 5.0) <= ZTOL_MM, "I/II at %.9f mm, expected 5", i_ii);
    CHECK(fabs(ii_iii - 15.0) <= ZTOL_MM, "II/III at %.9f mm, expected 15", ii_iii);
    CHECK(!strcmp(tippe_group_family(r.zones[0].group), "I") &&
              !strcmp(tippe_group_family(r.zones[r.n_zones - 1].group), "III"),
          "linear path should start in I and end in III");

    /* The physical travel [2, 12] mm: III lies beyond it; parts are split there. */
    tippe_sweep_summary s;
    tippe_sweep_mark_travel(&r, 2.0, 12.0, &err);
    tippe_sweep_summarise(&r, &s);
    CHECK(s.has_I && s.has_II && !s.has_III && !s.three_in_one,
          "travel [2,12]: I %d II %d III %d", s.has_I, s.has_II, s.has_III);
    int split_ok = 0;
    for (int i = 0; i < r.n_zones; i++)
        if (fabs(r.zones[i].z2_from_mm - 2.0) < 1e-12 && r.zones[i].within_travel &&
            i > 0 && !r.zones[i - 1].within_travel)
            split_ok = 1;
    CHECK(split_ok, "no split at the physical travel limit 2 mm");
    /* The reachable part of group I is [2, 5]: 3 mm; III is not reachable, so
     * the narrowest zone is 0 (the optimiser's measure: not 3-in-1). */
    CHECK(fabs(s.widest_mm[0] - 3.0) <= 2 * ZTOL_MM && s.narrowest_zone_mm == 0.0 &&
              !s.narrowest_family,
          "I %g mm, narrowest %g mm (%s), expected 3 mm and 0 (not 3-in-1)", s.widest_mm[0],
          s.narrowest_zone_mm, s.narrowest_family ? s.narrowest_family : "none");
    tippe_sweep_result_free(&r);

    tippe_sweep_run(&p, 0.0, 20.0, NULL, &r, &err);
    tippe_sweep_mark_travel(&r, 0.0, 20.0, &err);
    tippe_sweep_summarise(&r, &s);
    /* Runs: I [0,5], II [5,15], III [15,20]: narrowest 5 mm (ends each within 1e-6). */
    CHECK(s.three_in_one, "linear path over [0,20] should be 3-in-1");
    CHECK(fabs(s.narrowest_zone_mm - 5.0) <= 2 * ZTOL_MM, "narrowest %g mm, expected 5",
          s.narrowest_zone_mm);
    tippe_sweep_result_free(&r);
}

/* The zone of a group is its widest run (group II appears twice, 5 and 10 mm
 * wide); zone I is not split where the centre of mass crosses the centre. */
static void test_group_zones(void)
{
    path_params pp = {.kind = VEE};
    tippe_sweep_path p = {eval, &pp};
    tippe_sweep_result r;
    tippe_error err = {0};
    tippe_sweep_summary s;
    int st = tippe_sweep_run(&p, 0.0, 30.0, NULL, &r, &err);
    CHECK(st == TIPPE_OK, "vee sweep: %s", err.msg);
    tippe_sweep_summarise(&r, &s);
    const double want[3] = {7.5, 10.0, 5.0}; /* the crossings are exact in closed form */
    for (int k = 0; k < 3; k++)
        CHECK(fabs(s.widest_mm[k] - want[k]) <= 2 * ZTOL_MM, "group %d zone %.9f mm, expected %g",
              k + 1, s.widest_mm[k], want[k]);
    CHECK(s.three_in_one && !strcmp(s.narrowest_family, "III") &&
              fabs(s.narrowest_zone_mm - 5.0) <= 2 * ZTOL_MM,
          "narrowest %g mm (%s), expected 5 mm of III (the 2.5 mm runs are not the zones)",
          s.narrowest_zone_mm, s.narrowest_family ? s.narrowest_family : "none");
    /* Travel [3, 20]: III is not reachable, so the top is not 3-in-1 (objective 0);
     * II's widest reachable run is [15, 20]. */
    tippe_sweep_mark_travel(&r, 3.0, 20.0, &err);
    tippe_sweep_summarise(&r, &s);
    CHECK(!s.has_III && s.narrowest_zone_mm == 0.0 && !s.narrowest_family &&
              fabs(s.widest_mm[1] - 5.0) <= 2 * ZTOL_MM && fabs(s.widest_mm[0] - 7.5) <= 2 * ZTOL_MM,
          "travel [3,20]: III %d, II %g mm (expected 5), I %g mm (expected 7.5)", s.has_III,
          s.widest_mm[1], s.widest_mm[0]);
    tippe_sweep_result_free(&r);
}

static void test_wavy(void)
{
    path_params pp = {.kind = WAVY};
    check_against_reference("wavy", &pp, 0.0, 40.0);
    check_against_reference("wavy-offset", &pp, -3.7, 31.3);
}

static void test_flat(void)
{
    path_params pp = {.kind = FLAT};
    tippe_sweep_path p = {eval, &pp};
    tippe_sweep_result r;
    tippe_error err = {0};
    int st = tippe_sweep_run(&p, 0.0, 20.0, NULL, &r, &err);
    CHECK(st == TIPPE_OK && r.n_zones == 1, "flat path: %d zones (expected 1): %s", r.n_zones,
          err.msg);
    CHECK(r.n_zones == 1 && r.zones[0].group == TIPPE_GROUP_IB, "flat path group %s",
          r.n_zones ? tippe_group_name(r.zones[0].group) : "-");
    CHECK(r.n_events == 0, "flat path: %d events", r.n_events);
    tippe_sweep_result_free(&r);
}

/* A path touching the I/II line at z0 without crossing it gives one zone and
 * one touch event at z0. Where g = a (z - z0)^2 is computed with rounding
 * ~1e-17 (|k - 1| ~ 0.05 times 2^-53), its minimum is located only to
 * sqrt(1e-17 / a) ~ 3e-7 mm for a = 1.5e-4 /mm^2; 1e-5 mm leaves a margin of 30.
 * With e = 0.05 and |z - z0| <= 12.7 mm, k - 1 stays within 0.025 of -e: inside
 * IIc above the line (b = -1 is at k - 1 = -0.0156) and inside Ia below it. */
static void test_touch(int kind, double z0)
{
    path_params pp = {.kind = kind, .a = 1.5e-4, .z0 = z0, .e = 0.05};
    tippe_sweep_path p = {eval, &pp};
    tippe_sweep_result r;
    tippe_error err = {0};
    int st = tippe_sweep_run(&p, 0.0, 20.0, NULL, &r, &err);
    const char *side = kind == TOUCH_ABOVE ? "above" : "below";
    CHECK(st == TIPPE_OK, "touch %s at %g: %s", side, z0, err.msg);
    CHECK(r.n_zones == 1, "touch %s at %g: %d zones, expected 1", side, z0, r.n_zones);
    int touches = 0;
    for (int i = 0; i < r.n_events; i++)
        if (r.events[i].touch && r.events[i].boundary == TIPPE_SWEEP_I_II) {
            touches++;
            CHECK(fabs(r.events[i].z2_mm - z0) <= 1e-5, "touch %s at %.9f, expected %g", side,
                  r.events[i].z2_mm, z0);
        }
    CHECK(touches == 1, "touch %s at %g: %d touch events, expected 1", side, z0, touches);
    tippe_sweep_result_free(&r);
}

static void test_dip(void)
{
    /* Dip 2 * 0.00167 mm wide, between scan points 0.01 mm apart. */
    path_params pp = {.kind = DIP, .a = 0.01, .z0 = 7.3042, .w = 0.002, .e = 0.05};
    tippe_sweep_path p = {eval, &pp};
    tippe_sweep_result r;
    tippe_error err = {0};
    int st = tippe_sweep_run(&p, 0.0, 20.0, NULL, &r, &err);
    CHECK(st == TIPPE_OK && r.n_zones == 3, "dip: %d zones, expected 3: %s", r.n_zones,
          err.msg);
    if (r.n_zones == 3) {
        /* g < 0 where exp(-((z-z0)/w)^2) > 1/2: |z - z0| < w sqrt(ln 2). */
        double half = pp.w * sqrt(log(2.0));
        CHECK(fabs(r.zones[1].z2_from_mm - (pp.z0 - half)) <= ZTOL_MM &&
                  fabs(r.zones[1].z2_to_mm - (pp.z0 + half)) <= ZTOL_MM,
              "dip zone [%.9f, %.9f], expected z0 -+ %.9f", r.zones[1].z2_from_mm,
              r.zones[1].z2_to_mm, half);
        CHECK(!strcmp(tippe_group_family(r.zones[1].group), "I") &&
                  !strcmp(tippe_group_family(r.zones[0].group), "II"),
              "dip groups %s %s", tippe_group_name(r.zones[0].group),
              tippe_group_name(r.zones[1].group));
    }
    tippe_sweep_result_free(&r);
}

static void test_balance(void)
{
    path_params pp = {.kind = BALANCE, .a = 0.002, .z0 = 4.0};
    check_against_reference("balance", &pp, 0.0, 20.0);
    tippe_sweep_path p = {eval, &pp};
    tippe_sweep_result r;
    tippe_error err = {0};
    tippe_sweep_run(&p, 0.0, 20.0, NULL, &r, &err);
    /* es = 0.002 (z - 4) vanishes at z = 4 exactly. */
    CHECK(r.n_zones == 2 && fabs(r.zones[0].z2_to_mm - 4.0) <= ZTOL_MM &&
              (r.zones[0].to_boundaries & (1u << TIPPE_SWEEP_BALANCED)),
          "balance: %d zones, first ends at %g", r.n_zones,
          r.n_zones ? r.zones[0].z2_to_mm : NAN);
    CHECK(r.n_zones == 2 && r.zones[0].com_side == -1 && r.zones[1].com_side == 1,
          "balance: sides not -1, +1");
    CHECK(r.n_zones == 2 && r.zones[0].group == r.zones[1].group,
          "balance: group changed across eps = 0");
    tippe_sweep_result_free(&r);
}

static void test_errors(void)
{
    path_params pp = {.kind = LINEAR, .e = 0.05};
    tippe_sweep_path p = {eval, &pp};
    tippe_sweep_result r;
    tippe_error err = {0};
    CHECK(tippe_sweep_run(&p, 5.0, 5.0, NULL, &r, &err) == TIPPE_EINPUT, "empty range accepted");
    CHECK(tippe_sweep_run(&p, 0.0, NAN, NULL, &r, &err) == TIPPE_EINPUT, "NaN range accepted");
    tippe_sweep_result_free(&r);
    path_params po = {.kind = OUTSIDE};
    tippe_sweep_path q = {eval, &po};
    err.msg[0] = 0;
    CHECK(tippe_sweep_run(&q, 0.0, 20.0, NULL, &r, &err) == TIPPE_EINPUT && strstr(err.msg, "Z2"),
          "path leaving the diagram: '%s'", err.msg);
    tippe_sweep_result_free(&r);
}

/* ---- plots ---------------------------------------------------------------- */

static long file_size(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 ? (long)st.st_size : -1;
}

static int has_prefix(const char *path, const char *magic, size_t n)
{
    char buf[64] = {0};
    FILE *f = fopen(path, "rb");
    if (!f)
        return 0;
    size_t got = fread(buf, 1, n, f);
    fclose(f);
    return got == n && !memcmp(buf, magic, n);
}

static int svg_ok(const char *path)
{
    char buf[4096] = {0};
    FILE *f = fopen(path, "rb");
    if (!f)
        return 0;
    size_t got = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    return got > 0 && strstr(buf, "<svg") != NULL;
}

/* Files in dir other than the expected ones (temporaries left behind). */
static int stray_files(const char *dir, int n_expected)
{
    DIR *d = opendir(dir);
    int n = 0;
    struct dirent *e;
    while (d && (e = readdir(d)))
        if (e->d_name[0] != '.')
            n++;
    if (d)
        closedir(d);
    return n - n_expected;
}

static void test_plots(void)
{
    char dir[] = "/tmp/tippe-test-sweep-XXXXXX";
    CHECK(mkdtemp(dir) != NULL, "mkdtemp failed");
    path_params pp = {.kind = WAVY};
    tippe_sweep_path p = {eval, &pp};
    tippe_sweep_result r;
    tippe_error err = {0};
    tippe_sweep_run(&p, 0.0, 40.0, NULL, &r, &err);
    tippe_sweep_mark_travel(&r, 3.0, 35.0, &err);

    const char *kinds[] = {"zones", "phase"};
    const char *exts[] = {"png", "svg"};
    int made = 0;
    for (int k = 0; k < 2; k++)
        for (int x = 0; x < 2; x++) {
            char path[256];
            snprintf(path, sizeof path, "%s/%s.%s", dir, kinds[k], exts[x]);
            int st = k == 0 ? tippe_sweep_plot_zones(path, &p, &r, "wavy path", &err)
                            : tippe_sweep_plot_phase(path, &p, &r, "wavy path", &err);
            CHECK(st == TIPPE_OK, "%s: %s", path, err.msg);
            made++;
            /* A PNG starts with its 8-byte signature; a real plot of this size
             * with text and fills is tens of kB, far above 5 kB. */
            if (x == 0)
                CHECK(has_prefix(path, "\x89PNG\r\n\x1a\n", 8) && file_size(path) > 5000,
                      "%s: not a PNG or too small (%ld bytes)", path, file_size(path));
            else
                CHECK(svg_ok(path) && file_size(path) > 5000, "%s: not an SVG (%ld bytes)", path,
                      file_size(path));
        }
    /* A vary plot over three steps of a synthetic family is not possible without
     * a design; the CLI test covers it. Bad formats leave nothing behind. */
    char bad[256];
    snprintf(bad, sizeof bad, "%s/zones.jpg", dir);
    CHECK(tippe_sweep_plot_zones(bad, &p, &r, NULL, &err) == TIPPE_EINPUT,
          "a .jpg plot was accepted");
    snprintf(bad, sizeof bad, "%s/no/such/dir/zones.png", dir);
    CHECK(tippe_sweep_plot_zones(bad, &p, &r, NULL, &err) == TIPPE_EINPUT,
          "a plot into a missing directory was accepted");
    CHECK(stray_files(dir, made) == 0, "stray files in %s", dir);
    tippe_sweep_result_free(&r);

    char cmd[512];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (getenv("TIPPE_KEEP_TEST_PLOTS"))
        printf("plots kept in %s\n", dir);
    else if (system(cmd) != 0)
        printf("note: could not remove %s\n", dir);
}

int main(void)
{
    test_linear();
    test_group_zones();
    test_wavy();
    test_flat();
    test_touch(TOUCH_ABOVE, 7.3042); /* between scan points (0.01 mm apart) */
    test_touch(TOUCH_ABOVE, 10.0);  /* on a scan point (2000 intervals over 20 mm) */
    test_touch(TOUCH_BELOW, 7.3042);
    test_touch(TOUCH_BELOW, 10.0);
    test_dip();
    test_balance();
    test_errors();
    test_plots();
    return check_summary("test_sweep");
}
