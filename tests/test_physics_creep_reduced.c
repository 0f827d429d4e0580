/* The patch law with its creep reduced (issue 38; docs/dynamics.md, "The creep reduced"):
 * the reduced law (creep_cap TIPPE_PATCH_CREEP_CAP, integrated by the explicit rk8pd)
 * against the full law (creep_cap 0, integrated by msbdf at a tighter tolerance, the
 * reference) on Leine and Glocker's top, Cohen's sphere at 0.1 to 2 mm, the M12 ball on
 * its holes' rims, and the extremes: the flip and fall-back times, the end verdicts, the
 * energy books and the reduction's own estimate of the energy it moved. */
#include "check.h"
#include "dynamics_fixtures.h"
#include "tippe/physics.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* The M12's hole opens at both poles, 12.7 deg (designs/m12-setscrew.json). */
#define M12_RIM_RAD (12.7 * M_PI / 180.0)

typedef struct {
    double t_flip, t_fall, theta_end, energy_err, creep_rel;
    long evals;
    tippe_verdict verdict;
} outcome;

static tippe_dynamics_model patch(tippe_top top, double mu_c, double a, double creep_cap)
{
    tippe_dynamics_model md = friction_model(top, 0.0, TIPPE_FRICTION_PATCH, mu_c, 0.0);
    md.patch_radius_m = a;
    md.creep_cap = creep_cap;
    return md;
}

/* One run to t_end (on past any verdict): the reduced law at the balanced preset
 * (rk8pd, rtol 1e-9), the full law with msbdf at rtol 1e-11. */
static outcome run_law(tippe_dynamics_model md, const tippe_dynamics_initial *ic, double t_end)
{
    outcome out = {NAN, NAN, NAN, NAN, NAN, 0, TIPPE_VERDICT_UNDECIDED};
    tippe_dynamics_options o =
        md.creep_cap > 0 ? run_options(t_end, NULL, NULL, 0.0)
                         : run_options(t_end, NULL, "msbdf", 1e-11);
    tippe_dynamics_result r;
    if (run_to_end(&md, ic, o, &r) != TIPPE_OK)
        return out;
    out.t_flip = r.t_flip;
    out.t_fall = r.t_fall;
    out.theta_end = r.last.theta;
    out.energy_err = r.energy_rel_error;
    out.creep_rel = r.creep_energy_J / r.E0;
    out.evals = r.rhs_evals;
    out.verdict = r.verdict;
    return out;
}

/* Two times agree within rel (both NaN: neither happened). */
static int same_time(double a, double b, double rel)
{
    if (isnan(a) || isnan(b))
        return isnan(a) && isnan(b);
    return fabs(a - b) <= rel * fabs(b);
}

/* The reduced and the full law on one launch: flip and fall-back within rel, the
 * energy books of the reduced run closed to 1e-7 of E0 (rk8pd at rtol 1e-9 closes
 * them to ~1e-8 on these runs: the books count the reduced law's own power), and the
 * energy the reduction moved printed beside them. */
static void compare(const char *name, tippe_dynamics_model md, const tippe_dynamics_initial *ic,
                    double t_end, double rel)
{
    md.creep_cap = TIPPE_PATCH_CREEP_CAP;
    const outcome red = run_law(md, ic, t_end);
    md.creep_cap = 0.0;
    const outcome full = run_law(md, ic, t_end);
    printf("  %-34s flip %.7g / %.7g s, fall %.7g / %.7g s, theta at %g s %.4f / %.4f rad; "
           "energy books %.2g / %.2g, the reduction moved %.2g of E0; %ld / %ld RHS "
           "(reduced / full)\n",
           name, red.t_flip, full.t_flip, red.t_fall, full.t_fall, t_end, red.theta_end,
           full.theta_end, red.energy_err, full.energy_err, red.creep_rel, red.evals, full.evals);
    CHECK(same_time(red.t_flip, full.t_flip, rel), "%s: flip %.9g s reduced, %.9g s full", name,
          red.t_flip, full.t_flip);
    CHECK(same_time(red.t_fall, full.t_fall, rel), "%s: fall %.9g s reduced, %.9g s full", name,
          red.t_fall, full.t_fall);
    CHECK(red.energy_err < 1e-7, "%s: reduced energy books %g", name, red.energy_err);
    CHECK(red.creep_rel >= 0.0 && red.creep_rel < 1.0, "%s: the reduction moved %g of E0", name,
          red.creep_rel);
}

/* Leine and Glocker's top (docs/dynamics.md, "Validation"), the patch held at 0.5 mm,
 * and Cohen's sphere on Hertz-sized to large patches, 60 s: the flip and the fall back
 * (where there is one) within 1e-3. Measured: 3e-7 on the flips (the reduction does
 * not act before them: the two runs differ by their steppers' errors), 1.5e-5 on
 * Cohen's falls at 0.5 and 2 mm (the reduction acts while the top stands inverted). */
static void test_validation_runs(void)
{
    const tippe_top lg = {0.006, 0.015, 0.003, 8e-7, 7e-7, 1, {0.0, 0.0}};
    tippe_dynamics_model md = patch(lg, 0.3, 0.5e-3, 0.0);
    md.patch_radius_fixed = 1;
    const tippe_dynamics_initial lg_ic = {0.1, 0, 0, 180, 0, 0};
    compare("Leine-Glocker, a 0.5 mm held, 3 s", md, &lg_ic, 3.0, 1e-3);

    const tippe_dynamics_initial co_ic = {0.1, 0, 0, 100, 0, 0};
    const double radii_mm[] = {0.1, 0.5, 2.0};
    for (int i = 0; i < 3; i++) {
        char name[64];
        snprintf(name, sizeof name, "Cohen, a %g mm, 60 s", radii_mm[i]);
        compare(name, patch(cohen_ball(0.005), 0.3, radii_mm[i] * 1e-3, 0.0), &co_ic, 60.0,
                1e-3);
    }
}

/* The M12 ball (Z2 = 15 mm) on its holes' rims: a hand launch at 20 rev/s with a
 * 0.05 m/s slide, 120 s, through a flip and a fall back. The reduction acts on the
 * rims, where the spin about the vertical drains; flip and fall within 1 %, the
 * issue's bound on median times (measured: 1.3e-6 and 2.6e-4). */
static void test_m12_on_rims(void)
{
    tippe_top t = m12_ball(1.0);
    t.rim_half_angle_rad[0] = t.rim_half_angle_rad[1] = M12_RIM_RAD;
    tippe_dynamics_model md = patch(t, 0.3, 0.1859e-3, 0.0);
    tippe_dynamics_initial ic = m12_launch(&md, 2.0 * M_PI * 20.0);
    ic.U = 0.05;
    compare("M12 on its rims, 20 rev/s, 120 s", md, &ic, 120.0, 1e-2);
}

/* The extremes (as test_patch_dynamics.c's): spin 1e4 rad/s, mu_c 10, tops of radius
 * 1 mm and 1 m with a Hertz-sized patch (0.0069 R): the reduced run ends where the full
 * one does (the same verdict at t_end) with its energy books closed to 1e-6. */
static void test_extremes(void)
{
    struct {
        const char *name;
        double s, mu_c, spin, t_end;
    } cases[] = {{"spin 1e4 rad/s", 1.0, 0.3, 1e4, 0.2},
                 {"mu_c 10", 1.0, 10.0, 94.0, 1.0},
                 {"radius 1 mm", 0.04, 0.3, 94.0 / 0.04, 0.2},
                 {"radius 1 m", 40.0, 0.3, 94.0 / sqrt(40.0), 5.0}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const tippe_top t = m12_ball(cases[i].s);
        tippe_dynamics_model md = patch(t, cases[i].mu_c, 0.0069 * t.R, TIPPE_PATCH_CREEP_CAP);
        const tippe_dynamics_initial ic = m12_launch(&md, cases[i].spin);
        const outcome red = run_law(md, &ic, cases[i].t_end);
        md.creep_cap = 0.0;
        const outcome full = run_law(md, &ic, cases[i].t_end);
        printf("  extreme %-16s verdict %s / %s, theta %.6f / %.6f rad, energy books %.2g, "
               "%ld / %ld RHS (reduced / full)\n",
               cases[i].name, tippe_verdict_name(red.verdict), tippe_verdict_name(full.verdict),
               red.theta_end, full.theta_end, red.energy_err, red.evals, full.evals);
        CHECK(red.verdict == full.verdict, "%s: verdict %s reduced, %s full", cases[i].name,
              tippe_verdict_name(red.verdict), tippe_verdict_name(full.verdict));
        CHECK(red.energy_err < 1e-6, "%s: energy books %g", cases[i].name, red.energy_err);
    }
}

/* The options' rule: the presets' rk8pd runs as msbdf only for the full law. */
static void test_stepper(void)
{
    CHECK(!strcmp(tippe_dynamics_stepper_used(TIPPE_FRICTION_PATCH, 0.0, "rk8pd"), "msbdf"),
          "the full law's stiff stepper");
    CHECK(!strcmp(tippe_dynamics_stepper_used(TIPPE_FRICTION_PATCH, TIPPE_PATCH_CREEP_CAP,
                                              "rk8pd"),
                  "rk8pd"),
          "the reduced law's explicit stepper");
}

int main(void)
{
    test_stepper();
    test_validation_runs();
    test_m12_on_rims();
    test_extremes();
    return check_summary("test_physics_creep_reduced");
}
