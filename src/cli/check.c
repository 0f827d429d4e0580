/* tippe check: one central hand launch at one Z2 beside the calculator's zone
 * and theory's prediction. */
#include "hands.h"

#include "tippe/physics.h"
#include "tippe/sweep.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>

static int check_parse(hands_args *a, int argc, char **argv)
{
    tippe_cli_opt own[] = {
        {.name = "z2", .kind = TIPPE_CLI_DOUBLE, .value = &a->z2_mm, .arg = "MM", .unit = "mm",
         .min = -TIPPE_CLI_Z2_MAX_MM, .max = TIPPE_CLI_Z2_MAX_MM, .required = 1,
         .help = "position of the moving weight's midpoint (in the design's travel)"},
        {.name = "spin", .kind = TIPPE_CLI_DOUBLE, .value = &a->spin.from, .arg = "RATE",
         .unit = "rad/s", .min = 0, .max = HANDS_SPIN_MAX_RAD_S, .def = "15rev/s",
         .help = "launch spin (the default is the middle of tippe launch's range)"},
        {NULL},
    };
    hands_verb v = {
        .spec = {.verb = "check",
                 .synopsis = "DESIGN.json --z2 MM [--spin RATE] [--json] [options]",
                 .about = "One realistic hand launch of the design's top with the weight at Z2:\n"
                          "the central values of tippe launch's distributions (the median tilt,\n"
                          "steady precession, no sliding) at the given spin, integrated to its\n"
                          "outcome. Prints the outcome beside the zone the calculator (tippe\n"
                          "sweep) puts Z2 in and Theorem 5.1's prediction for the launch's\n"
                          "Jellett invariant.",
                 .after = "--tilt is the scale of the hand-launch distribution; the launch uses\n"
                          "its median, 0.674 SD. Exit status: 0 ok (whatever the outcome), 2 bad\n"
                          "usage or design, 1 the launch could not be computed."},
        .own = own,
    };
    return hands_parse(&v, a, argc, argv);
}

/* What the launch does: an end state, a range (bounded), the lift-off, or the
 * state where the run stopped without a proof. */
static void print_verdict_line(const tippe_launch_record *rec)
{
    const double th = rec->theta_final_rad, deg = 180 / M_PI;
    switch (rec->verdict) {
    case TIPPE_VERDICT_BOUNDED:
        printf("\nverdict    bounded (no rest state is forced: no friction, eps = 0, or rolling "
               "without slipping): theta stays for ever in [%.4f, %.4f] rad ([%.1f, %.1f] deg)\n",
               rec->theta_lo_rad, rec->theta_hi_rad, rec->theta_lo_rad * deg,
               rec->theta_hi_rad * deg);
        break;
    case TIPPE_VERDICT_UNDECIDED:
        printf("\nverdict    undecided: not proved by t = %.4g s; theta there %.4f rad "
               "(%.1f deg)\n", rec->t_s, th, th * deg);
        break;
    case TIPPE_VERDICT_LOST_CONTACT:
        printf("\nverdict    lost_contact: leaves the table at theta %.4f rad (%.1f deg), "
               "spin %.4g rad/s\n", th, th * deg, rec->spin_final_rad_s);
        break;
    default:
        if (rec->how == TIPPE_DECIDED_OBSERVED)
            printf("\nverdict    %s (observed at t = %.4g s, NOT proved): theta %.4f rad (%.1f "
                   "deg), spin %.4g rad/s; " TIPPE_PATCH_UNPROVED_REASON "\n",
                   tippe_verdict_name(rec->verdict), rec->t_s, th, th * deg,
                   rec->spin_final_rad_s);
        else if (rec->how == TIPPE_DECIDED_ROLLING)
            printf("\nverdict    %s: rolls without slipping for ever, theta in [%.4f, %.4f] rad "
                   "([%.1f, %.1f] deg)\n",
                   tippe_verdict_name(rec->verdict), rec->theta_lo_rad, rec->theta_hi_rad,
                   rec->theta_lo_rad * deg, rec->theta_hi_rad * deg);
        else if (!rec->end_state_proved)
            printf("\nverdict    %s: stays in the well of theta %.4f rad (%.1f deg), theta in "
                   "[%.4f, %.4f] rad; it ends there if it keeps sliding (rolling without "
                   "slipping dissipates nothing)\n",
                   tippe_verdict_name(rec->verdict), th, th * deg, rec->theta_lo_rad,
                   rec->theta_hi_rad);
        else
            printf("\nverdict    %s: ends at theta %.4f rad (%.1f deg), spin %.4g rad/s\n",
                   tippe_verdict_name(rec->verdict), th, th * deg, rec->spin_final_rad_s);
    }
}

static void check_text(const hands_args *a, const tippe_sweep_check *r)
{
    const tippe_dynamics_initial *ic = &r->ic;
    const tippe_launch_record *rec = &r->rec;
    hands_print_top(r->d, a->z2_mm, &r->top, a->o.g, &r->zone);
    char sets[1024];
    if (a->sets.n)
        printf("changes    %s\n", tippe_cli_sets_text(&a->sets, sets, sizeof sets));
    printf("launch     spin %.4g rad/s (%.3g rev/s), tilt %.4g rad (%.2f deg), steady "
           "precession %.4g rad/s, no sliding\n",
           ic->spin, ic->spin / (2 * M_PI), ic->theta, ic->theta * 180 / M_PI, ic->phi_dot);
    hands_print_model(&a->o);
    print_verdict_line(rec);
    if (rec->how == TIPPE_DECIDED_T_END || rec->how == TIPPE_DECIDED_BUDGET) {
        /* The launch is a steady precession: without friction nothing dissipates
         * and it stays one; with friction, only a launch exactly on an unstable
         * steady state (--tilt 0) stays. */
        tippe_dynamics_model law;
        tippe_launch_friction_model(&a->o, &law);
        if (tippe_dynamics_frictionless(&law))
            printf("           (t_end or the step budget came first: without friction this "
                   "launch, a steady precession, dissipates nothing and never leaves it)\n");
        else
            printf("           (t_end or the step budget came first; exactly on an unstable "
                   "steady state, as with --tilt 0, nothing ever decides)\n");
    } else {
        printf("           decided by %s at t = %.4g s", tippe_decision_name(rec->how), rec->t_s);
        if (rec->verdict == TIPPE_VERDICT_BOUNDED)
            printf(" (energy below the well's escape level, margin %.3g J)", rec->margin_J);
        else if (rec->how == TIPPE_DECIDED_TRAPPED && isinf(rec->barrier_gap_J))
            printf(" (a well with no barrier; energy margin %.3g J)", rec->margin_J);
        else if (rec->how == TIPPE_DECIDED_TRAPPED)
            printf(" (energy %.3g J below the well's barrier, margin %.3g J)",
                   rec->barrier_gap_J, rec->margin_J);
        if (isfinite(rec->Rn_bound_N))
            printf("; Rn >= %.3g N for ever", rec->Rn_bound_N);
        printf("\n");
    }
    tippe_design_protrusion pr;
    tippe_design_protrusion_at(r->d, a->z2_mm, &pr);
    tippe_cli_print_model_validity(&pr, a->z2_mm, "contact    ", "the verdict above is");
    if (isfinite(rec->t_flip_s))
        printf("flip       theta passed 90 deg at t = %.4g s of model time (%s)\n",
               rec->t_flip_s, a->o.law == TIPPE_FRICTION_VISCOUS ? "viscous friction"
                              : a->o.law == TIPPE_FRICTION_PATCH ? "patch friction"
                                                                 : "Coulomb friction");
    tippe_theory_class cls;
    tippe_theory_classify(r->top.A / r->top.C, r->top.eps / r->top.R, &cls);
    const tippe_group g = r->zone.ok ? r->zone.group : cls.group;
    printf("calculator zone %s at Z2 = %g mm (%s)\n", tippe_group_name(g), a->z2_mm,
           hands_group_meaning(g));
    if (rec->theory_ok) {
        printf("theory     Theorem 5.1 for J0 = %.4g kg m^3/s: %s", rec->J0,
               tippe_launch_predicted_name(rec->predicted));
        if (isfinite(rec->hang_theta_rad))
            printf(" (hang at %.4f rad, %.1f deg)", rec->hang_theta_rad,
                   rec->hang_theta_rad * 180 / M_PI);
        printf(" -> %s\n", rec->agrees > 0    ? "agrees"
                           : rec->agrees == 0 ? "DISAGREES"
                                              : "not comparable");
    } else {
        printf("theory     no prediction for J0 = %.4g kg m^3/s\n", rec->J0);
    }
    printf("accuracy   Jellett drift %.2g, %ld RHS evaluations\n", rec->jellett_rel_drift,
           rec->rhs_evals);
}

int tippe_cli_check(int argc, char **argv)
{
    hands_args a = {.verb = "check", .spin = {2 * M_PI * 15.0, 0, 0}};
    tippe_launch_options_default(&a.o);
    int rc = check_parse(&a, argc, argv);
    if (rc)
        return rc == TIPPE_CLI_HELP ? 0 : rc;
    tippe_error err;
    tippe_design *d = NULL;
    if ((rc = tippe_design_load(a.design, a.sets.item, a.sets.n, &d, &err)) != 0)
        return tippe_cli_fail(a.verb, &err, rc);
    tippe_cli_design_warnings(a.verb, d);
    if ((rc = hands_patch(&a, d, &err)) != 0) {
        tippe_design_free(d);
        return tippe_cli_fail(a.verb, &err, rc);
    }
    tippe_sweep_check r;
    if ((rc = tippe_sweep_check_run(d, a.z2_mm, &a.o, a.spin.from, &r, &err)) != 0) {
        tippe_design_free(d);
        return tippe_cli_fail(a.verb, &err, rc);
    }
    if (a.json)
        rc = tippe_cli_print_json(a.verb, tippe_sweep_check_json(&r, &a.o, a.sets.item, a.sets.n));
    else
        check_text(&a, &r);
    tippe_design_free(d);
    return rc;
}
