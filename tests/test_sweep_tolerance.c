/* Tolerances and bands: the "tolerances" block is read strictly and its
 * defaults are the documented ones; each sensitivity d(Z2*)/dp from the implicit
 * function theorem agrees with re-sweeping the design with the field moved;
 * the quadrature band agrees with a Monte Carlo over the tolerances; robust
 * widths are width less both bands. Run from the repository root. */
#include "tippe/design.h"
#include "tippe/sweep.h"

#include "check.h"

#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const char *M12 = "designs/m12-setscrew.json";
static char tmp_design[600];

/* A copy of the M12 design with the given "tolerances" value (JSON text, or
 * NULL for none), the materials table named by absolute path. */
static const char *m12_with(const char *tolerances)
{
    char cwd[PATH_MAX];
    if (!getcwd(cwd, sizeof cwd))
        return NULL;
    const char *dir = getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp";
    snprintf(tmp_design, sizeof tmp_design, "%s/tippe-test-tol-%d.json", dir, (int)getpid());
    FILE *f = fopen(tmp_design, "w");
    if (!f)
        return NULL;
    fprintf(f,
            "{\"name\": \"m12\", \"radius_mm\": 25, \"travel_mm\": [0, 20],\n"
            " \"materials\": \"%s/designs/materials.json\",\n"
            " \"parts\": [\n"
            "  {\"name\": \"body\", \"shape\": \"ball\", \"material\": \"ABSplus\"},\n"
            "  {\"name\": \"hole\", \"shape\": \"cylinder\", \"radius_mm\": 5.5, \"clip\": \"sphere\",\n"
            "   \"void\": true, \"cut_from\": \"body\"},\n"
            "  {\"name\": \"screw\", \"shape\": \"cylinder\", \"radius_mm\": 5.5, \"height_mm\": 15,\n"
            "   \"material\": \"iron\", \"moving\": true, \"may_protrude\": true}]%s%s}\n",
            cwd, tolerances ? ",\n \"tolerances\": " : "", tolerances ? tolerances : "");
    fclose(f);
    return tmp_design;
}

static const tippe_tolerance *find_tol(const tippe_design *d, const char *field)
{
    for (int i = 0; i < tippe_design_n_tolerances(d); i++)
        if (!strcmp(tippe_design_tolerance(d, i)->field, field))
            return tippe_design_tolerance(d, i);
    return NULL;
}

static void check_parsing(void)
{
    struct {
        const char *block, *want;
    } bad[] = {
        {"{\"parts.bolt.height_mm\": 0.1}", "no part .bolt"},
        {"{\"parts.screw.colour\": 0.1}", "not a number field of a cylinder"},
        {"{\"radius\": 0.1}", "not a number field of the design"},
        {"{\"parts.screw.height_mm\": -0.1}", "must be >= 0"},
        {"{\"parts.screw.height_mm\": \"abc\"}", "not a percentage"},
        {"{\"parts.screw.height_mm\": \"150%\"}", "outside 0 .. 100%"},
        {"{\"parts.screw.height_mm\": true}", "true/false"},
        {"{\"parts.screw.height_mm\": 15}", "not less than the value itself"},
        {"{\"parts.screw.height_mm\": 0.1, \"parts[2].height_mm\": 0.2}", "same field"},
        {"{\"materials.unobtainium.density_g_cm3\": \"1%\"}", "made of 'unobtainium'"},
        {"{\"materials.ABSplus.colour\": 1}", "materials.NAME.density_g_cm3"},
        {"{\"parts.hole.height_mm\": 0.1}", "the clip decides it"},
        {"{\"parts.body.radius_mm\": 0.1}", "forms the sphere"},
        {"{\"parts.hole.density_g_cm3\": 0.1}", "a void has its part's density"},
        {"{\"contact.patch_radius\": 1.005}", "outside 1.01 .. 10"},
        {"{\"contact.patch_radius\": \"50%\"}", "a number F"},
        {"[0.1]", "tolerances: must be an object"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        const char *path = m12_with(bad[i].block);
        tippe_error err = {0};
        tippe_design *d = NULL;
        int rc = tippe_design_load(path, NULL, 0, &d, &err);
        /* the message names the file and, but for the last case, the entry */
        CHECK(rc == TIPPE_EINPUT && !d && strstr(err.msg, path) && strstr(err.msg, bad[i].want) &&
                  (i + 1 == sizeof bad / sizeof bad[0] || strstr(err.msg, "tolerances[\"")),
              "block %s: rc %d, '%s' (want '%s')", bad[i].block, rc, err.msg, bad[i].want);
        tippe_design_free(d);
    }

    /* The defaults of the M12 design: printed ball (its radius is radius_mm)
     * and hole, bought screw. */
    tippe_error err = {0};
    tippe_design *d = NULL;
    CHECK(tippe_design_load(M12, NULL, 0, &d, &err) == TIPPE_OK, "%s", err.msg);
    if (d) {
        CHECK(tippe_design_n_tolerances(d) == 4, "%d defaults", tippe_design_n_tolerances(d));
        const tippe_tolerance *t;
        CHECK((t = find_tol(d, "radius_mm")) && t->plus_minus == 0.2, "radius_mm default");
        CHECK((t = find_tol(d, "parts.hole.radius_mm")) && t->plus_minus == 0.2, "hole default");
        CHECK((t = find_tol(d, "materials.ABSplus.density_g_cm3")) &&
                  fabs(t->plus_minus - 0.03 * 1.08) < 1e-15,
              "filament density default");
        CHECK((t = find_tol(d, "parts.screw.density_g_cm3")) &&
                  fabs(t->plus_minus - 0.02 * 7.87) < 1e-15,
              "hardware mass default");
        CHECK(!find_tol(d, "parts.screw.height_mm"), "a bought screw's height is exact by default");
        /* the patch radius's factor: the default, and not a per-field (zone) tolerance */
        CHECK(tippe_design_patch_radius_span(d) == TIPPE_TOL_PATCH_RADIUS_FACTOR,
              "patch radius factor %g", tippe_design_patch_radius_span(d));
        CHECK(!find_tol(d, TIPPE_TOL_PATCH_RADIUS_KEY), "the patch radius is not a zone tolerance");
        tippe_design_free(d);
    }
    {
        const char *pp = m12_with("{\"contact.patch_radius\": 3}");
        tippe_design *dp = NULL;
        CHECK(tippe_design_load(pp, NULL, 0, &dp, &err) == TIPPE_OK, "%s", err.msg);
        if (dp) {
            CHECK(tippe_design_patch_radius_span(dp) == 3.0, "patch radius factor %g, want 3",
                  tippe_design_patch_radius_span(dp));
            CHECK(tippe_design_n_tolerances(dp) == 4, "%d tolerances: the factor joined the list",
                  tippe_design_n_tolerances(dp));
        }
        tippe_design_free(dp);
    }
    /* A block adds, replaces and (with 0) removes. */
    const char *path = m12_with("{\"parts[2].height_mm\": 0.05, \"parts.hole.radius_mm\": 0, "
                                "\"materials.ABSplus.density_g_cm3\": \"5%\"}");
    d = NULL;
    CHECK(tippe_design_load(path, NULL, 0, &d, &err) == TIPPE_OK, "%s", err.msg);
    if (d) {
        const tippe_tolerance *t;
        CHECK(tippe_design_n_tolerances(d) == 4, "%d tolerances", tippe_design_n_tolerances(d));
        CHECK((t = find_tol(d, "parts.screw.height_mm")) && t->plus_minus == 0.05 &&
                  t->value == 15,
              "added, by index, named by name");
        CHECK(!find_tol(d, "parts.hole.radius_mm"), "0 removes a default");
        CHECK((t = find_tol(d, "materials.ABSplus.density_g_cm3")) &&
                  fabs(t->plus_minus - 0.054) < 1e-15 && t->percent == 5,
              "5%% of 1.08");
        tippe_design_free(d);
    }
    /* --set replaces the block like any top-level field. */
    const char *set[] = {"tolerances={\"parts.screw.z_mm\": 0.1}"};
    d = NULL;
    CHECK(tippe_design_load(M12, set, 1, &d, &err) == TIPPE_OK, "%s", err.msg);
    if (d) {
        CHECK(find_tol(d, "parts.screw.z_mm") && tippe_design_n_tolerances(d) == 5,
              "--set tolerances: %d", tippe_design_n_tolerances(d));
        tippe_design_free(d);
    }
    /* A printed body: its infill gets +/-25 % of itself; weighed, the scale's
     * 0.1 g instead; whole numbers of lines have no tolerance. */
    const char *printed[] = {"parts.body.print={\"infill\": 0.4}"};
    d = NULL;
    CHECK(tippe_design_load(M12, printed, 1, &d, &err) == TIPPE_OK, "%s", err.msg);
    if (d) {
        const tippe_tolerance *t = find_tol(d, "parts.body.print.infill");
        CHECK(t && fabs(t->plus_minus - 0.1) < 1e-15 && !strcmp(t->rule, "slicer infill"),
              "infill default");
        tippe_design_free(d);
    }
    const char *weighed[] = {"parts.body.print={\"measured_mass_g\": 40}"};
    d = NULL;
    CHECK(tippe_design_load(M12, weighed, 1, &d, &err) == TIPPE_OK, "%s", err.msg);
    if (d) {
        const tippe_tolerance *t = find_tol(d, "parts.body.print.measured_mass_g");
        CHECK(t && t->plus_minus == 0.1 && t->value == 40 && !find_tol(d, "parts.body.print.infill"),
              "weighed: the scale's reading, not the slicer's infill");
        CHECK(!find_tol(d, "parts.body.print.model_error"),
              "weighed: no model-error term (the scale has the mass)");
        tippe_design_free(d);
    }
    /* The same body with its density inline and a print block is printed too
     * (the mass model and the export print it): its dimensions, its infill and
     * its filament's density get a printed part's tolerances, not the +/-2 %
     * of a bought part's mass. */
    const char *inline_printed[] = {"parts.body.density_g_cm3=1.08",
                                    "parts.body.print={\"infill\": 0.4}"};
    d = NULL;
    CHECK(tippe_design_load(M12, inline_printed, 2, &d, &err) == TIPPE_OK, "%s", err.msg);
    if (d) {
        const tippe_tolerance *t;
        CHECK(tippe_design_n_tolerances(d) == 6, "inline printed: %d tolerances",
              tippe_design_n_tolerances(d));
        CHECK((t = find_tol(d, "parts.body.print.model_error")) && t->plus_minus == 1 &&
                  t->value == 0 && !strcmp(t->rule, "print model vs slicer"),
              "inline printed: the print model's error against the slicer, +/-1");
        CHECK((t = find_tol(d, "parts.body.print.infill")) && fabs(t->plus_minus - 0.1) < 1e-15 &&
                  !strcmp(t->rule, "slicer infill"),
              "inline printed: infill default");
        CHECK((t = find_tol(d, "parts.body.density_g_cm3")) &&
                  fabs(t->plus_minus - 0.03 * 1.08) < 1e-15 && !strcmp(t->rule, "filament density"),
              "inline printed: filament density +/-3 %%, got %s",
              t ? t->rule : "none");
        CHECK((t = find_tol(d, "radius_mm")) && t->plus_minus == 0.2, "inline printed: radius");
        CHECK((t = find_tol(d, "parts.hole.radius_mm")) && t->plus_minus == 0.2,
              "inline printed: its hole is a printed dimension");
        CHECK((t = find_tol(d, "parts.screw.density_g_cm3")) && !strcmp(t->rule, "hardware mass"),
              "inline printed: the screw is still hardware");
        tippe_design_free(d);
    }
    /* Without a print block an inline density is a bought part's. */
    const char *inline_bought[] = {"parts.body.density_g_cm3=1.08"};
    d = NULL;
    CHECK(tippe_design_load(M12, inline_bought, 1, &d, &err) == TIPPE_OK, "%s", err.msg);
    if (d) {
        const tippe_tolerance *t = find_tol(d, "parts.body.density_g_cm3");
        CHECK(t && !strcmp(t->rule, "hardware mass") && !find_tol(d, "parts.hole.radius_mm"),
              "inline, no print block: hardware mass");
        tippe_design_free(d);
    }
    const char *layers[] = {"parts.body.print={\"infill\": 0.4}",
                            "tolerances={\"parts.body.print.perimeters\": 1}"};
    d = NULL;
    CHECK(tippe_design_load(M12, layers, 2, &d, &err) == TIPPE_EINPUT &&
              strstr(err.msg, "whole number"),
          "perimeters: '%s'", err.msg);
    tippe_design_free(d);
    remove(tmp_design);
}

/* The crossing of boundary b nearest z of the design derived from d with the
 * overrides, found by a sweep of [z - w, z + w] located to 1e-10 mm. */
static double crossing(const tippe_design *d, const char *const *sets, int n, tippe_sweep_boundary b,
                       double z, double w, int n_scan)
{
    tippe_design *m = NULL;
    tippe_error err = {0};
    if (tippe_design_derive(d, sets, n, &m, &err) != TIPPE_OK)
        return NAN;
    tippe_sweep_path p = tippe_sweep_design_path(m);
    tippe_sweep_options o;
    tippe_sweep_options_default(&o);
    o.xtol_mm = 1e-10;
    o.n_scan = n_scan;
    tippe_sweep_result r;
    double best = NAN;
    if (tippe_sweep_run(&p, z - w, z + w, &o, &r, &err) == TIPPE_OK)
        for (int i = 0; i < r.n_events; i++)
            if (r.events[i].boundary == b && !r.events[i].touch &&
                !(fabs(r.events[i].z2_mm - z) >= fabs(best - z)))
                best = r.events[i].z2_mm;
    tippe_sweep_result_free(&r);
    tippe_design_free(m);
    return best;
}

/* d(Z2*)/dp against (Z2*(p + h) - Z2*(p - h)) / 2h by re-sweeping. */
static void check_derivatives(const tippe_design *d, const tippe_sweep_bands_result *b)
{
    double worst = 0;
    char sets[2][8][TIPPE_TOLERANCE_FIELD_LEN + 40];
    for (int i = 0; i < tippe_design_n_tolerances(d); i++) {
        const tippe_tolerance *t = tippe_design_tolerance(d, i);
        /* h = t/16. The central difference's truncation error h^2 z'''/6
         * shrinks 16-fold from h = t/4 (measured: largest difference 1.7e-5
         * -> 1.1e-6 for the solid design, 1.5e-3 -> 9.1e-5 for the printed
         * one, whose boundaries bend more with the infill): second order, as
         * it must be if the implicit derivative is right. The 1e-10 mm root
         * location adds 1e-10 / h < 1e-7. */
        double h = 0.0625 * t->plus_minus;
        int n = tippe_tolerance_overrides(d, t, h, sets[0], 8);
        int m = tippe_tolerance_overrides(d, t, -h, sets[1], 8);
        const char *up[8], *down[8];
        for (int k = 0; k < n; k++)
            up[k] = sets[0][k];
        for (int k = 0; k < m; k++)
            down[k] = sets[1][k];
        for (int k = 0; k < b->n; k++) {
            const tippe_sweep_band *bd = &b->bands[k];
            double zp = crossing(d, up, n, bd->boundary, bd->z2_mm, 1.0, 200);
            double zm = crossing(d, down, m, bd->boundary, bd->z2_mm, 1.0, 200);
            double fd = (zp - zm) / (2 * h);
            /* 1e-3 relative: far above both errors above, far below any
             * mistake of sign, factor or missing term */
            worst = fmax(worst, fabs(fd - bd->dz_dp[i]) / fabs(fd));
            CHECK(fabs(fd - bd->dz_dp[i]) <= 1e-3 * fabs(fd) + 1e-6,
                  "%s at %s (Z2 = %.4f): implicit %.10g, re-sweep %.10g mm per %s", t->field,
                  tippe_sweep_boundary_name(bd->boundary), bd->z2_mm, bd->dz_dp[i], fd, t->unit);
            /* the reported error estimate is honest */
            CHECK(bd->dz_dp_err[i] <= 1e-3 * fabs(bd->dz_dp[i]) + 1e-9, "%s: error %g",
                  t->field, bd->dz_dp_err[i]);
        }
    }
    printf("sensitivities: implicit vs re-sweep, largest relative difference %.2g\n", worst);
}

/* Every field drawn at once from a normal law with its tolerance as standard
 * deviation; the spread of each boundary against its quadrature band. */
enum { N_MC = 10000 };

static void check_monte_carlo(const tippe_design *d, const tippe_sweep_bands_result *b)
{
    int nt = tippe_design_n_tolerances(d);
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, 20121);
    double sum[16] = {0}, sum2[16] = {0}, res2[16] = {0};
    char sets[32][TIPPE_TOLERANCE_FIELD_LEN + 40];
    const char *ptr[32];
    int failed = 0;
    for (int s = 0; s < N_MC; s++) {
        int n = 0;
        double delta[32];
        for (int i = 0; i < nt; i++) {
            const tippe_tolerance *t = tippe_design_tolerance(d, i);
            delta[i] = gsl_ran_gaussian(rng, t->plus_minus);
            n += tippe_tolerance_overrides(d, t, delta[i], sets + n, 32 - n);
        }
        for (int k = 0; k < n; k++)
            ptr[k] = sets[k];
        for (int k = 0; k < b->n && k < 16; k++) {
            const tippe_sweep_band *bd = &b->bands[k];
            double z = crossing(d, ptr, n, bd->boundary, bd->z2_mm, 6 * bd->band_mm, 24);
            if (!isfinite(z)) {
                failed++;
                continue;
            }
            double dz = z - bd->z2_mm, lin = 0;
            for (int i = 0; i < nt; i++)
                lin += bd->dz_dp[i] * delta[i];
            sum[k] += dz;
            sum2[k] += dz * dz;
            res2[k] += (dz - lin) * (dz - lin);
        }
    }
    gsl_rng_free(rng);
    CHECK(failed == 0, "%d Monte Carlo crossings not found", failed);
    /* The sample standard deviation of N normal draws has relative standard
     * error 1/sqrt(2(N - 1)) = 0.71 % for N = 10000; 4 of those (2.8 %) fails
     * a correct band with probability 6e-5. Second order adds about
     * (rms_res / band)^2 / 2 < 0.1 % to the ratio (for symmetric draws the
     * quadratic term does not correlate with the linear one). The first-order
     * law is checked sample by sample as well: what it leaves unexplained
     * must be small against the band (measured: 1.7 % to 3.3 % of it). */
    double tol = 4.0 / sqrt(2.0 * (N_MC - 1));
    for (int k = 0; k < b->n && k < 16; k++) {
        double mean = sum[k] / N_MC, sd = sqrt((sum2[k] - N_MC * mean * mean) / (N_MC - 1));
        double rms_res = sqrt(res2[k] / N_MC);
        CHECK(fabs(sd / b->bands[k].band_mm - 1) <= tol,
              "%s at %.3f mm: Monte Carlo sd %.4f mm, band %.4f mm (ratio %.4f, allowed 1 +- %.3f)",
              tippe_sweep_boundary_name(b->bands[k].boundary), b->bands[k].z2_mm, sd,
              b->bands[k].band_mm, sd / b->bands[k].band_mm, tol);
        CHECK(rms_res <= 0.05 * b->bands[k].band_mm,
              "%s: rms departure from first order %.4f mm, band %.4f mm",
              tippe_sweep_boundary_name(b->bands[k].boundary), rms_res, b->bands[k].band_mm);
        printf("MC %s at %.3f mm: sd %.4f mm, band %.4f mm, rms(second order) %.2g mm\n",
               tippe_sweep_boundary_name(b->bands[k].boundary), b->bands[k].z2_mm, sd,
               b->bands[k].band_mm, rms_res);
    }
}

/* Robust widths: width less the bands at both ends, 0 when they overlap, and
 * no band at an end that is the end of the sweep or of the travel. */
static void check_robust(const tippe_sweep_result *r, const tippe_sweep_bands_result *b)
{
    for (int i = 0; i < r->n_zones; i++) {
        const tippe_sweep_zone *z = &r->zones[i];
        double lo = z->from_boundaries ? tippe_sweep_band_at(b, z->z2_from_mm) : 0;
        double hi = z->to_boundaries ? tippe_sweep_band_at(b, z->z2_to_mm) : 0;
        CHECK(!z->from_boundaries || lo > 0, "zone %d: a boundary has a band", i);
        double want = fmax(0, z->z2_to_mm - z->z2_from_mm - lo - hi);
        CHECK_CLOSE(tippe_sweep_zone_robust_mm(r, b, i) + 1, want + 1, 1e-14, "zone %d", i);
    }
    /* A hand-made case: zones [0, 5] [5, 6] [6, 10], bands 0.3 at 5 and 0.8 at 6. */
    tippe_sweep_zone zones[3] = {
        {.group = TIPPE_GROUP_IA, .z2_from_mm = 0, .z2_to_mm = 5, .within_travel = 1,
         .to_boundaries = 1},
        {.group = TIPPE_GROUP_IIA, .z2_from_mm = 5, .z2_to_mm = 6, .within_travel = 1,
         .from_boundaries = 1, .to_boundaries = 2},
        {.group = TIPPE_GROUP_III, .z2_from_mm = 6, .z2_to_mm = 10, .within_travel = 1,
         .from_boundaries = 2},
    };
    tippe_sweep_result hr = {.from_mm = 0, .to_mm = 10, .n_zones = 3, .zones = zones};
    tippe_sweep_band bands[2] = {{.z2_mm = 5, .band_mm = 0.3}, {.z2_mm = 6, .band_mm = 0.8}};
    tippe_sweep_bands_result hb = {.n = 2, .bands = bands};
    CHECK(fabs(tippe_sweep_zone_robust_mm(&hr, &hb, 0) - 4.7) < 1e-12, "5 - 0.3");
    CHECK(tippe_sweep_zone_robust_mm(&hr, &hb, 1) == 0, "1 - 0.3 - 0.8 < 0: 0");
    CHECK(fabs(tippe_sweep_zone_robust_mm(&hr, &hb, 2) - 3.2) < 1e-12, "4 - 0.8");
    double rob[3], narrow;
    tippe_sweep_robust_widths(&hr, &hb, rob, &narrow);
    CHECK(fabs(rob[0] - 4.7) < 1e-12 && rob[1] == 0 && fabs(rob[2] - 3.2) < 1e-12 && narrow == 0,
          "robust I %g II %g III %g narrowest %g", rob[0], rob[1], rob[2], narrow);
}

/* Issue 36: a band moved a field beyond the range it loads in (an infill of
 * 0.95 +/- 25 % past 1) and every sweep of the design failed. Each bounded field
 * at each end of its range: its interval stays inside the range (cut at the
 * end, the full +/- on the other side), the design loads at both ends of the
 * interval, and the sweep's bands are found. */
static void check_field_ends(void)
{
    static const char *P = "designs/m12-setscrew-printed.json";
    struct {
        const char *design, *field, *sets[6];
    } cases[] = {
        /* the M12 scaled to the ends of the sphere's 1 .. 1000 mm (printed: +/-0.2 mm) */
        {M12, "radius_mm", {"radius_mm=1", "parts.hole.radius_mm=0.22", "parts.screw.radius_mm=0.22",
                            "parts.screw.height_mm=0.6", "travel_mm=[0, 0.8]"}},
        {M12, "radius_mm", {"radius_mm=1000", "parts.hole.radius_mm=220",
                            "parts.screw.radius_mm=220", "parts.screw.height_mm=600",
                            "travel_mm=[0, 800]"}},
        /* a density up to osmium's 22.6 g/cm^3 (hardware +/-2 %), down to above 0 */
        {M12, "parts.screw.density_g_cm3", {"parts.screw.density_g_cm3=22.59"}},
        {M12, "parts.screw.density_g_cm3", {"parts.screw.density_g_cm3=0.01"}},
        {M12, "materials.ABSplus.density_g_cm3",
         {"tolerances={\"materials.ABSplus.density_g_cm3\": \"1%\"}"}},
        /* infill 0 .. 1: the slicer's +/-25 %, or the block's at 1 */
        {P, "parts.body.print.infill", {"parts.body.print={\"infill\": 0.95}"}},
        {P, "parts.body.print.infill", {"parts.body.print={\"infill\": 0.99}"}},
        {P, "parts.body.print.infill",
         {"parts.body.print={\"infill\": 1}", "tolerances={\"parts.body.print.infill\": 0.2}"}},
        {P, "parts.body.print.infill", {"parts.body.print={\"infill\": 0.01}"}},
        /* line width 0.05 .. 3 mm, layer height 0.01 .. 2 mm: the block's 10 % */
        {P, "parts.body.print.line_width_mm",
         {"parts.body.print={\"line_width_mm\": 3}",
          "tolerances={\"parts.body.print.line_width_mm\": \"10%\"}"}},
        {P, "parts.body.print.line_width_mm",
         {"parts.body.print={\"line_width_mm\": 0.05}",
          "tolerances={\"parts.body.print.line_width_mm\": \"10%\"}"}},
        {P, "parts.body.print.layer_height_mm",
         {"parts.body.print={\"layer_height_mm\": 2}",
          "tolerances={\"parts.body.print.layer_height_mm\": \"10%\"}"}},
        {P, "parts.body.print.layer_height_mm",
         {"parts.body.print={\"layer_height_mm\": 0.01}",
          "tolerances={\"parts.body.print.layer_height_mm\": \"10%\"}"}},
        /* a weighing's calibration -1 .. 2 (its default +/-1) */
        {P, "parts.body.print.calibration",
         {"parts.body.print={\"measured_mass_g\": 15, \"calibration\": -1}"}},
        {P, "parts.body.print.calibration",
         {"parts.body.print={\"measured_mass_g\": 15, \"calibration\": 2}"}},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        int n = 0;
        while (n < 6 && cases[k].sets[n])
            n++;
        tippe_error err = {0};
        tippe_design *d = NULL;
        const char *what = cases[k].sets[0];
        CHECK(tippe_design_load(cases[k].design, cases[k].sets, n, &d, &err) == TIPPE_OK,
              "%s: %s", what, err.msg);
        if (!d)
            continue;
        const tippe_tolerance *t = find_tol(d, cases[k].field);
        CHECK(t != NULL, "%s: no tolerance on %s", what, cases[k].field);
        if (!t) {
            tippe_design_free(d);
            continue;
        }
        double lo, hi;
        tippe_design_field_range(t->field, &lo, &hi);
        const double from = t->value - t->minus, to = t->value + t->plus;
        CHECK(from >= lo && to <= hi, "%s: %s's interval %.17g .. %.17g outside %g .. %g", what,
              t->field, from, to, lo, hi);
        /* cut only where the range ends: the full +/- wherever there is room */
        CHECK(t->minus == fmin(t->plus_minus, t->value - lo) &&
                  t->plus == fmin(t->plus_minus, hi - t->value),
              "%s: %s -%g +%g of +/-%g in %g .. %g", what, t->field, t->minus, t->plus,
              t->plus_minus, lo, hi);
        for (int end = 0; end < 2; end++) {
            char sets[8][TIPPE_TOLERANCE_FIELD_LEN + 40];
            const char *ptr[8];
            int m = tippe_tolerance_overrides(d, t, end ? t->plus : -t->minus, sets, 8);
            for (int i = 0; i < m; i++)
                ptr[i] = sets[i];
            tippe_design *moved = NULL;
            CHECK(m > 0 && tippe_design_derive(d, ptr, m, &moved, &err) == TIPPE_OK,
                  "%s: moved to the interval's %s: %s", what, end ? "top" : "bottom", err.msg);
            tippe_design_free(moved);
        }
        tippe_sweep_result r;
        tippe_sweep_bands_result b = {0};
        int rc = tippe_sweep_design(d, 0, 0, NULL, &r, &err);
        CHECK(rc == TIPPE_OK, "%s: sweep: %s", what, err.msg);
        if (!rc) {
            CHECK(tippe_sweep_bands(d, &r, &b, &err) == TIPPE_OK, "%s: bands: %s", what, err.msg);
            for (int i = 0; i < b.n; i++)
                CHECK(isfinite(b.bands[i].band_mm), "%s: band %d is %g", what, i,
                      b.bands[i].band_mm);
            tippe_sweep_bands_free(&b);
            tippe_sweep_result_free(&r);
        }
        tippe_design_free(d);
    }
}

int main(void)
{
    check_parsing();
    check_field_ends();
    tippe_error err = {0};
    tippe_design *d = NULL;
    CHECK(tippe_design_load(M12, NULL, 0, &d, &err) == TIPPE_OK, "%s", err.msg);
    if (!d)
        return check_summary("test_sweep_tolerance");
    tippe_sweep_result r;
    tippe_sweep_bands_result b;
    CHECK(tippe_sweep_design(d, 0, 0, NULL, &r, &err) == TIPPE_OK, "%s", err.msg);
    CHECK(tippe_sweep_bands(d, &r, &b, &err) == TIPPE_OK, "%s", err.msg);
    CHECK(b.n == 4, "M12: four zone ends, %d bands", b.n);
    check_derivatives(d, &b);
    check_monte_carlo(d, &b);
    check_robust(&r, &b);
    tippe_sweep_bands_free(&b);
    tippe_sweep_result_free(&r);
    tippe_design_free(d);

    /* The docs' example block (a material's density among them: the designs
     * moved by a tolerance carry no tolerances of their own). A moving part's
     * z_mm is its offset from Z2, so the whole path shifts with it: every
     * boundary moves by exactly -1 mm per mm (to the derivatives' ~1e-9). */
    const char *block[] = {"tolerances={\"parts.screw.height_mm\": 0.1, \"parts.hole.radius_mm\": "
                           "0.1, \"materials.ABSplus.density_g_cm3\": \"2%\", "
                           "\"parts.screw.z_mm\": 0.25, \"radius_mm\": 0}"};
    d = NULL;
    CHECK(tippe_design_load(M12, block, 1, &d, &err) == TIPPE_OK, "%s", err.msg);
    if (d && tippe_sweep_design(d, 0, 0, NULL, &r, &err) == TIPPE_OK) {
        CHECK(tippe_sweep_bands(d, &r, &b, &err) == TIPPE_OK, "docs block: %s", err.msg);
        int iz = -1;
        for (int i = 0; i < tippe_design_n_tolerances(d); i++)
            if (!strcmp(tippe_design_tolerance(d, i)->field, "parts.screw.z_mm"))
                iz = i;
        CHECK(iz >= 0 && b.n == 4, "z_mm tolerance %d, %d bands", iz, b.n);
        for (int k = 0; iz >= 0 && k < b.n; k++)
            CHECK(fabs(b.bands[k].dz_dp[iz] + 1) < 1e-6, "%s: dZ2*/dz_mm = %.12g, want -1",
                  tippe_sweep_boundary_name(b.bands[k].boundary), b.bands[k].dz_dp[iz]);
        tippe_sweep_bands_free(&b);
        tippe_sweep_result_free(&r);
    }
    tippe_design_free(d);

    /* The printed body at 40 % infill: the infill's sensitivity goes through
     * the print model's quadrature (relative error ~1e-9), still far inside
     * the 1e-3 of check_derivatives. The continuous rule ("skins"): the
     * derivatives this checks need moments smooth in the dimensions, and the
     * slicer's rules (the default model) are thresholds on whole layers, so
     * its moments jump where a dimension moves a layer edge across one
     * (docs/printing.md, "Tolerances of a sliced part"). */
    const char *printed[] = {"parts.body.print={\"infill\": 0.4, \"model\": \"skins\"}"};
    d = NULL;
    CHECK(tippe_design_load(M12, printed, 1, &d, &err) == TIPPE_OK, "%s", err.msg);
    if (d && tippe_sweep_design(d, 0, 0, NULL, &r, &err) == TIPPE_OK) {
        CHECK(tippe_sweep_bands(d, &r, &b, &err) == TIPPE_OK, "%s", err.msg);
        CHECK(b.n == 4 && tippe_design_n_tolerances(d) == 5, "printed: %d bands, %d tolerances",
              b.n, tippe_design_n_tolerances(d));
        check_derivatives(d, &b);
        tippe_sweep_bands_free(&b);
        tippe_sweep_result_free(&r);
    }
    tippe_design_free(d);
    return check_summary("test_sweep_tolerance");
}
