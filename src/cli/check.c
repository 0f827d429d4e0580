/* tippe check: one central hand launch at one Z2 beside the calculator's zone
 * and theory's prediction. */
#include "hands.h"

#include "tippe/launch.h"
#include "tippe/plot.h"
#include "tippe/scenario.h"
#include "tippe/sweep.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int check_parse(hands_args *a, int argc, char **argv)
{
    tippe_cli_opt own[] = {
        {.name = "z2", .kind = TIPPE_CLI_DOUBLE, .value = &a->z2_mm, .arg = "MM", .unit = "mm",
         .min = -TIPPE_CLI_Z2_MAX_MM, .max = TIPPE_CLI_Z2_MAX_MM, .required = 1,
         .help = "position of the moving weight's midpoint (in the design's travel)"},
        {.name = "spin", .kind = TIPPE_CLI_DOUBLE, .value = &a->spin.from, .arg = "RATE",
         .unit = "rad/s", .min = 0, .max = HANDS_SPIN_MAX_RAD_S, .def = "15rev/s",
         .help = "launch spin (the default is the middle of tippe launch's range)"},
        {.name = "csv", .kind = TIPPE_CLI_STRING, .value = &a->csv, .arg = "FILE",
         .help = "write the launch's trajectory, integrated to --t-end as tippe simulate\n"
                 "does (t, theta, theta_dot, phi_dot, n, U, V, Rn, |V_Q|, E, J, ...;\n"
                 "units in the header)"},
        {.name = "plot", .kind = TIPPE_CLI_STRING, .value = &a->plot, .arg = "FILE",
         .help = "theta, spin and contact speed against time and the (phi_dot, theta, n)\n"
                 "path, as tippe simulate draws them; .png, .svg or .pdf"},
        HANDS_RADIUS_OPTIONS(a, "the launch"),
        HANDS_CONTACT_OPTION(a),
        {NULL},
    };
    hands_verb v = {
        .spec = {.verb = "check",
                 .synopsis = "DESIGN.json --z2 MM [--spin RATE] [--json] [options]",
                 .about = "One realistic hand launch of the design's top with the weight at Z2:\n"
                          "the central values of tippe launch's distributions (the median tilt,\n"
                          "steady precession, the centre at rest: its contact point slips, at\n"
                          "the speed printed) at the given spin, integrated to its outcome. Prints\n"
                          "the outcome beside the zone the calculator (tippe sweep) puts Z2 in\n"
                          "and Theorem 5.1's prediction for the launch's Jellett invariant.",
                 .after = "--friction LAW,LAW,... (up to 4) runs the same launch under each law\n"
                          "and prints one table: the verdict, how and when it was decided, when\n"
                          "theta first passed 90 deg, the end state, and theta and the share of\n"
                          "the launch energy E0 dissipated at the end of the run (t_end); --mu\n"
                          "applies to viscous, --mu-c to the others, --patch-mm and --table to\n"
                          "patch; --plot draws theta(t) of every law in one figure, --json gives\n"
                          "\"laws\". docs/launch.md, \"Friction laws side by side\".\n"
                          "--tilt is the scale of the hand-launch distribution; the launch uses\n"
                          "its median, 0.674 SD. Exit status: 0 ok (whatever the outcome), 2 bad\n"
                          "usage or design, 1 the launch could not be computed."},
        .own = own,
        .friction_list = 1,
    };
    int rc = hands_parse(&v, a, argc, argv);
    if (!rc && a->fr.n_laws > 1 && a->csv)
        return tippe_cli_usage_error(a->verb, "--csv writes one law's trajectory: give one law "
                                              "with --friction (--plot draws theta(t) of each)");
    /* before the launch, so that a bad output path costs nothing */
    if (!rc && ((a->csv && tippe_cli_check_output(a->verb, "--csv", a->csv, 0)) ||
                (a->plot && tippe_cli_check_output(a->verb, "--plot", a->plot, 1))))
        return 2;
    if (!rc && a->csv && a->plot && !strcmp(a->csv, a->plot))
        return tippe_cli_usage_error(a->verb, "--csv and --plot name the same file '%s'", a->csv);
    return rc;
}

/* --csv and --plot: the check's launch as a scenario (its top, friction, initial
 * state, t_end and accuracy), integrated at the trajectory level to t_end and
 * written by the writers tippe simulate uses (tippe_dynamics_write_csv,
 * tippe_plot_sim). 0, or the status after saying why. */
static int check_trajectory(const hands_args *a, const tippe_sweep_check *r, int *n_samples)
{
    tippe_scenario sc;
    memset(&sc, 0, sizeof sc);
    snprintf(sc.path, sizeof sc.path, "%s", tippe_design_path(r->d));
    snprintf(sc.design_path, sizeof sc.design_path, "%s", tippe_design_path(r->d));
    snprintf(sc.name, sizeof sc.name, "%s: tippe check at Z2 = %g mm", tippe_design_name(r->d),
             a->z2_mm);
    sc.z2_mm = a->z2_mm;
    tippe_design_protrusion_at(r->d, a->z2_mm, &sc.protrusion);
    tippe_launch_friction_model(&a->o, &sc.model);
    sc.model.top = r->top;
    sc.initial = r->ic;
    sc.phi_dot_rule = TIPPE_PHI_DOT_GIVEN;
    sc.t_end = a->o.t_end;
    sc.accuracy = a->o.accuracy;
    snprintf(sc.accuracy_name, sizeof sc.accuracy_name, "%s", a->o.accuracy_name);

    tippe_dynamics_samples buf = {0, 0, NULL};
    tippe_dynamics_result res;
    tippe_error err = {0};
    int rc = tippe_launch_trajectory(&r->top, &a->o, &sc.initial, 0.0, &buf, &res, &err);
    if (!rc && a->csv) {
        tippe_report_file rf;
        if ((rc = tippe_report_open(&rf, a->csv, "the CSV file", &err)) == 0) {
            tippe_dynamics_write_csv(rf.f, buf.s, buf.n);
            rc = tippe_report_commit(&rf, &err);
        }
    }
    if (!rc && a->plot) /* one set with the CSV (tippe_cli_run): both or neither */
        rc = tippe_plot_sim(a->plot, &sc, &res, buf.s, buf.n, &err);
    if (rc)
        rc = tippe_cli_fail(a->verb, &err, rc);
    *n_samples = buf.n;
    tippe_dynamics_samples_free(&buf);
    return rc;
}

/* What the launch does: an end state, a range (bounded), the lift-off, or the
 * state where the run stopped without a proof. */
static void print_verdict_line(const tippe_launch_record *rec)
{
    const double th = rec->theta_final_rad, deg = 180 / M_PI;
    switch (rec->verdict) {
    case TIPPE_VERDICT_BOUNDED:
        if (rec->how == TIPPE_DECIDED_ROLLING) {
            printf("\nverdict    bounded: sticks and rolls without slipping for ever (nothing "
                   "dissipates), theta in [%.4f, %.4f] rad ([%.1f, %.1f] deg): %s\n",
                   rec->theta_lo_rad, rec->theta_hi_rad, rec->theta_lo_rad * deg,
                   rec->theta_hi_rad * deg,
                   rec->theta_lo_rad > 0.5 * M_PI ? "over, but not inverted (no flip)"
                                                  : "across 90 deg (no flip)");
            break;
        }
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
        if (rec->how == TIPPE_DECIDED_ENERGY_CONE && rec->verdict == TIPPE_VERDICT_TIP)
            printf("\nverdict    tip: proved at t = %.4g s by the energy alone (energy_cone): it "
                   "stays within %.2f deg of inverted for ever, on its flat end's well (theta "
                   "now %.1f deg); the rest state is not proved\n",
                   rec->t_s, (M_PI - rec->theta_lo_rad) * deg, th * deg);
        else if (rec->how == TIPPE_DECIDED_ENERGY_CONE)
            printf("\nverdict    %s: proved at t = %.4g s by the energy alone (energy_cone): it "
                   "stays within %.2f deg of upright for ever (theta now %.1f deg); the rest "
                   "state is not proved\n",
                   tippe_verdict_name(rec->verdict), rec->t_s, rec->theta_hi_rad * deg, th * deg);
        else if (rec->how == TIPPE_DECIDED_OBSERVED) {
            printf("\nverdict    %s (observed at t = %.4g s, NOT proved): theta %.4f rad (%.1f "
                   "deg), spin %.4g rad/s; %s\n",
                   tippe_verdict_name(rec->verdict), rec->t_s, th, th * deg,
                   rec->spin_final_rad_s,
                   rec->rim_touched ? TIPPE_RIM_UNPROVED_REASON : TIPPE_PATCH_UNPROVED_REASON);
            if (isfinite(rec->jellett_drift_time_s))
                printf("           J moved by up to %.3g %% of J0 in the run; drilling at m g "
                       "can move it by all of J0 in %.3g s (|dJ/dt| <= (3 pi/16) mu_c m g a "
                       "(R + eps)), so no proof that holds J = J0 for ever applies\n",
                       100 * rec->jellett_rel_drift, rec->jellett_drift_time_s);
        } else if (rec->how == TIPPE_DECIDED_ROLLING)
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

/* The outcome at 1/F, 1 and F times the patch radius (tippe_launch_radius_sensitivity_initial). */
static void print_radius_sensitivity(const tippe_launch_radius_sensitivity *s)
{
    printf("radius     the patch radius is uncertain (surface, table, wear): the same launch at\n");
    for (int i = 0; i < TIPPE_LAUNCH_RADIUS_RUNS; i++) {
        const tippe_launch_radius_run *r = &s->run[i];
        char factor[16];
        snprintf(factor, sizeof factor, "%.3gx", r->factor);
        printf("           %-5s %.4g mm: ", factor, r->radius_m * 1e3);
        if (!r->ran) {
            printf("not run (wider than half the ball's radius)\n");
            continue;
        }
        const tippe_launch_record *q = &r->first;
        printf("%s", tippe_verdict_name(q->verdict));
        if (isfinite(q->t_flip_s))
            printf(", over 90 deg at %.4g s", q->t_flip_s);
        else
            printf(", never over 90 deg");
        if (isfinite(q->t_fall_s))
            printf(", back below at %.4g s", q->t_fall_s);
        printf("\n");
    }
    if (s->robust)
        printf("           robust to the radius: the same flip and fall back at all three (observed "
               "end states are snapshots, not compared)\n");
    else if (s->changed == 0) /* a radius was not run */
        printf("           robustness to the radius not known: a radius was not run\n");
    else
        printf("           NOT robust to the radius: the outcome changes between %.3gx and %.3gx "
               "the radius\n", s->run[0].factor, s->run[2].factor);
}

static void check_text(const hands_args *a, const tippe_sweep_check *r)
{
    const tippe_dynamics_initial *ic = &r->ic;
    const tippe_launch_record *rec = &r->rec;
    hands_print_top(r->d, a->z2_mm, &r->top, a->o.g, &r->zone);
    char sets[1024];
    if (a->sets.n)
        printf("changes    %s\n", tippe_cli_sets_text(&a->sets, sets, sizeof sets));
    char slide[200];
    printf("launch     spin %.4g rad/s (%.3g rev/s), tilt %.4g rad (%.2f deg), steady "
           "precession %.4g rad/s, %s\n",
           ic->spin, ic->spin / (2 * M_PI), ic->theta, ic->theta * 180 / M_PI, ic->phi_dot,
           tippe_launch_slip_text(&r->top, ic, NULL, slide, sizeof slide));
    hands_print_model(&a->o, &r->top);
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
        if (rec->how == TIPPE_DECIDED_ROLLING)
            printf(" (over one whole nutation period the force rolling needs stayed inside "
                   "the friction cone: the motion repeats)");
        else if (rec->verdict == TIPPE_VERDICT_BOUNDED)
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
    tippe_design_cap caps[2];
    tippe_design_polar_caps(r->d, a->z2_mm, caps);
    const int side = r->top.com_side ? r->top.com_side : 1;
    const double th[2] = {r->ic.theta, rec->theta_final_rad};
    for (int k = 0; k < 2; k++) {
        int pole = isfinite(th[k]) ? tippe_design_cap_at_tilt(caps, side, th[k]) : 0;
        if (!pole)
            continue;
        const tippe_design_cap *c = &caps[pole > 0 ? 0 : 1];
        printf("pole       the launch %s %.1f deg from the %s pole, within the opening of '%s' "
               "(%.1f deg): the top stands on its rim there%s\n",
               k ? "ends" : "starts", (pole == side ? th[k] : M_PI - th[k]) * 180 / M_PI,
               pole > 0 ? "+z" : "-z", c->part, c->half_angle_rad * 180 / M_PI,
               a->o.sphere_contact_only ? ", not on its sphere, which --sphere-contact assumes: "
                                          "INVALID"
                                        : " (the contact follows the rim)");
    }
    if (isfinite(rec->cap_first_s) && a->o.sphere_contact_only)
        printf("pole       INVALID contact: theta lay within a hole's opening at a pole for %.4g "
               "s in all (first at t = %.4g s), where --sphere-contact keeps the contact on the "
               "sphere\n",
               rec->cap_time_s, rec->cap_first_s);
    else if (isfinite(rec->cap_first_s)) {
        /* not "of the t_s run": t_s is when the verdict was decided (0 for one proved at
         * launch), not how long the launch was followed */
        printf("rim        on a hole's rim for %.4g s in all (first at t = %.4g s; %ld switches "
               "between rim and sphere)",
               rec->cap_time_s, rec->cap_first_s, rec->rim_switches);
        if (isfinite(rec->spin_leaving_rim_rad_s))
            printf("; it left the rim it was launched on with spin %.4g rad/s of %.4g "
                   "(%.0f %% drained)",
                   fabs(rec->spin_leaving_rim_rad_s), fabs(rec->ic.spin),
                   100 * (1 - fabs(rec->spin_leaving_rim_rad_s) / fabs(rec->ic.spin)));
        printf("\n");
    }
    if (isfinite(rec->t_flip_s))
        printf("flip       theta passed 90 deg at t = %.4g s of model time (%s)\n",
               rec->t_flip_s, tippe_friction_law_type_of(a->o.law)->word);
    if (isfinite(rec->t_flip_s) && isfinite(rec->t_fall_s)) /* the drilling drained the spin */
        printf("fall       first back below 90 deg at t = %.4g s; above 90 deg for %.4g s in all "
               "of the %.4g s run\n",
               rec->t_fall_s, rec->inverted_time_s, rec->t_s);
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
    if (isfinite(rec->jellett_drift_time_s)) /* J moves by the physics: not an error */
        printf("accuracy   energy balance %.2g, the creep's reduction moved %.2g of E0, %ld RHS "
               "evaluations (J is not conserved under the patch law: no Jellett check)\n",
               rec->energy_rel_error, rec->creep_energy_rel, rec->rhs_evals);
    else
        printf("accuracy   Jellett drift %.2g, energy balance %.2g, %ld RHS evaluations\n",
               rec->jellett_rel_drift, rec->energy_rel_error, rec->rhs_evals);
}

/* Under the patch law (unless --no-radius-sensitivity): the launch again at 1/F and F times
 * its patch radius. 0 and *done 1, or the status after saying why. */
static int check_radius(const hands_args *a, const tippe_sweep_check *r,
                        tippe_launch_radius_sensitivity *s, int *done)
{
    *done = 0;
    if (!tippe_friction_law_type_of(a->o.law)->patch || a->no_radius_sensitivity)
        return 0;
    tippe_error err;
    int rc = tippe_launch_radius_sensitivity_initial(&r->top, &a->o, &r->ic, &r->rec, s, &err);
    if (rc)
        return tippe_cli_fail(a->verb, &err, rc);
    *done = 1;
    return 0;
}

/* --friction A,B,...: the same launch under each law, one table (and one plot). */
static int check_laws(const hands_args *a, const tippe_design *d)
{
    const int n = a->fr.n_laws;
    tippe_launch_options o[HANDS_MAX_LAWS];
    for (int i = 0; i < n; i++)
        hands_friction_law(&a->fr, i, &a->o, &o[i]);
    tippe_sweep_check_law *l = calloc((size_t)n, sizeof *l);
    if (!l)
        return fprintf(stderr, "tippe %s: out of memory\n", a->verb), 1;
    tippe_error err = {0};
    int rc = tippe_sweep_check_laws(d, a->z2_mm, o, n, a->spin.from, l, &err);
    const double deg = 180 / M_PI;
    if (!rc && a->plot) {
        char lab[HANDS_MAX_LAWS][200], title[600];
        const char *labels[HANDS_MAX_LAWS];
        tippe_dynamics_samples runs[HANDS_MAX_LAWS];
        double t_w = 0; /* the launch's window: three times its latest flip or decision */
        for (int i = 0; i < n; i++) {
            const tippe_launch_record *rec = &l[i].check.rec;
            if (isfinite(l[i].run.t_flip))
                snprintf(lab[i], sizeof lab[i], "%s: %s, over 90 deg at %.3g s",
                         tippe_friction_law_name(o[i].law), tippe_verdict_name(rec->verdict),
                         l[i].run.t_flip);
            else
                snprintf(lab[i], sizeof lab[i], "%s: %s, never over 90 deg",
                         tippe_friction_law_name(o[i].law), tippe_verdict_name(rec->verdict));
            labels[i] = lab[i];
            runs[i] = l[i].samples;
            if (isfinite(l[i].run.t_flip))
                t_w = fmax(t_w, 3 * l[i].run.t_flip);
            if (isfinite(rec->t_s) && rec->t_s < 0.5 * o[i].t_end)
                t_w = fmax(t_w, 3 * rec->t_s);
        }
        snprintf(title, sizeof title, "%s at Z2 = %g mm, spin %.3g rev/s: theta(t) under each "
                 "friction law", tippe_design_name(d), a->z2_mm, a->spin.from / (2 * M_PI));
        rc = tippe_plot_sim_laws(a->plot, title, n, labels, runs, fmax(t_w, 1.0), &err);
    }
    if (rc) {
        tippe_sweep_check_laws_free(l, n);
        free(l);
        return tippe_cli_fail(a->verb, &err, rc);
    }
    if (a->json) {
        rc = tippe_cli_print_json(a->verb,
                                  tippe_sweep_check_laws_json(l, n, a->sets.item, a->sets.n));
    } else {
        const tippe_sweep_check *r = &l[0].check;
        hands_print_top(d, a->z2_mm, &r->top, a->o.g, &r->zone);
        char sets[1024], slide[200];
        if (a->sets.n)
            printf("changes    %s\n", tippe_cli_sets_text(&a->sets, sets, sizeof sets));
        printf("launch     spin %.4g rad/s (%.3g rev/s), tilt %.4g rad (%.2f deg), steady "
               "precession %.4g rad/s, %s\n",
               r->ic.spin, r->ic.spin / (2 * M_PI), r->ic.theta, r->ic.theta * deg,
               r->ic.phi_dot, tippe_launch_slip_text(&r->top, &r->ic, NULL, slide, sizeof slide));
        printf("           the same launch under each friction law, t_end %g s, accuracy %s; "
               "energy E0 %.4g J\n\n", a->o.t_end, a->o.accuracy_name, l[0].run.E0);
        printf("%-14s %-12s %-24s %-13s %-11s %-26s %s\n", "law", "verdict", "decided",
               "over 90 deg", "back below", "end state",
               "at the end of the run: theta, energy lost");
        for (int i = 0; i < n; i++) {
            const tippe_launch_record *rec = &l[i].check.rec;
            char how[64], flip[32], fall[32], end[64];
            snprintf(how, sizeof how, "%s at %.3g s", tippe_decision_name(rec->how), rec->t_s);
            if (isfinite(l[i].run.t_flip))
                snprintf(flip, sizeof flip, "%.3g s", l[i].run.t_flip);
            else
                snprintf(flip, sizeof flip, "never");
            /* the patch law's fall back (drilling drains the spin) */
            if (isfinite(l[i].run.t_flip) && isfinite(l[i].run.t_fall))
                snprintf(fall, sizeof fall, "%.3g s", l[i].run.t_fall);
            else
                snprintf(fall, sizeof fall, "-");
            if (rec->verdict == TIPPE_VERDICT_BOUNDED || rec->how == TIPPE_DECIDED_ROLLING)
                snprintf(end, sizeof end, "rolls, %.1f .. %.1f deg", rec->theta_lo_rad * deg,
                         rec->theta_hi_rad * deg);
            else if (rec->how == TIPPE_DECIDED_OBSERVED)
                snprintf(end, sizeof end, "%.1f deg (not proved)", rec->theta_final_rad * deg);
            else if (rec->how == TIPPE_DECIDED_ENERGY_CONE && rec->verdict == TIPPE_VERDICT_TIP)
                snprintf(end, sizeof end, "above %.1f deg for ever", rec->theta_lo_rad * deg);
            else if (rec->how == TIPPE_DECIDED_ENERGY_CONE)
                snprintf(end, sizeof end, "within %.1f deg for ever", rec->theta_hi_rad * deg);
            else if (isfinite(rec->theta_final_rad))
                snprintf(end, sizeof end, "%.1f deg", rec->theta_final_rad * deg);
            else
                snprintf(end, sizeof end, "-");
            printf("%-14s %-12s %-24s %-13s %-11s %-26s %.1f deg at %.4g s, %.1f %% (%.3g J)\n",
                   tippe_friction_law_name(o[i].law), tippe_verdict_name(rec->verdict), how, flip,
                   fall, end, l[i].run.last.theta * deg, l[i].run.last.t,
                   100 * tippe_sweep_check_law_energy_lost(&l[i]), l[i].run.last.D);
        }
        printf("\n");
        for (int i = 0; i < n; i++) {
            char stepper[64] = ""; /* only where the law runs another stepper */
            if (strcmp(hands_stepper_text(&o[i], "%s for the stiff %s law", stepper,
                                          sizeof stepper),
                       o[i].accuracy.stepper) == 0)
                stepper[0] = '\0';
            printf("%-14s %s%s%s\n", tippe_friction_law_name(o[i].law), l[i].friction,
                   stepper[0] ? "; " : "", stepper);
        }
        if (a->plot)
            printf("plot       %s\n", a->plot);
    }
    tippe_sweep_check_laws_free(l, n);
    free(l);
    return rc;
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
    if (a.fr.n_laws > 1) {
        rc = check_laws(&a, d);
        tippe_design_free(d);
        return rc;
    }
    tippe_sweep_check r;
    if ((rc = tippe_sweep_check_run(d, a.z2_mm, &a.o, a.spin.from, &r, &err)) != 0) {
        tippe_design_free(d);
        return tippe_cli_fail(a.verb, &err, rc);
    }
    int n_samples = 0;
    if ((a.csv || a.plot) && (rc = check_trajectory(&a, &r, &n_samples)) != 0) {
        tippe_design_free(d);
        return rc;
    }
    tippe_launch_radius_sensitivity sens;
    int sens_done = 0;
    if ((rc = check_radius(&a, &r, &sens, &sens_done)) != 0) {
        tippe_design_free(d);
        return rc;
    }
    if (a.json) {
        cJSON *o = tippe_sweep_check_json(&r, &a.o, a.sets.item, a.sets.n);
        if (o && tippe_friction_law_type_of(a.o.law)->patch)
            cJSON_AddItemToObject(o, "radius_sensitivity",
                                  sens_done ? tippe_launch_radius_json(&sens, 1)
                                            : cJSON_CreateNull());
        rc = tippe_cli_print_json(a.verb, o);
    } else {
        check_text(&a, &r);
        if (sens_done)
            print_radius_sensitivity(&sens);
        if (a.csv)
            printf("csv        %s (%d samples, to t = %g s)\n", a.csv, n_samples, a.o.t_end);
        if (a.plot)
            printf("plot       %s\n", a.plot);
    }
    tippe_design_free(d);
    return rc;
}
