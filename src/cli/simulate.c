/* tippe simulate: integrate one launch described by a scenario file. */
#include "cli.h"

#include "tippe/launch.h"
#include "base/json.h"
#include "tippe/plot.h"
#include "tippe/base.h"
#include "tippe/scenario.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const char *const VERB = "simulate";


typedef tippe_dynamics_samples samples;

static int write_csv(const char *path, const samples *b, tippe_error *err)
{
    tippe_report_file rf;
    int rc = tippe_report_open(&rf, path, "the CSV file", err);
    if (rc)
        return rc;
    tippe_dynamics_write_csv(rf.f, b->s, b->n);
    return tippe_report_commit(&rf, err);
}

/* Theory's stable final states for the launch's J, and whether the simulated
 * outcome is one of them (-1: not comparable, i.e. lost contact, undecided or
 * bounded). */
typedef struct {
    int ok;
    char error[sizeof ((tippe_error *)0)->msg];
    tippe_theory_class cls;
    tippe_theory_prediction pred;
    int agrees;
} theory_check;

static void check_theory(const tippe_scenario *sc, const tippe_dynamics_result *r,
                         theory_check *tc)
{
    memset(tc, 0, sizeof *tc);
    const tippe_top *t = &sc->model.top;
    tippe_theory_classify(t->A / t->C, t->eps / t->R, &tc->cls);
    tippe_error e;
    if (tippe_theory_predict(t, sc->model.g, r->J0, &tc->pred, &e)) {
        snprintf(tc->error, sizeof tc->error, "%s", e.msg);
        tc->agrees = -1;
        return;
    }
    tc->ok = 1;
    if (r->verdict == TIPPE_VERDICT_LOST_CONTACT || r->verdict == TIPPE_VERDICT_UNDECIDED ||
        r->verdict == TIPPE_VERDICT_BOUNDED || r->how == TIPPE_DECIDED_OBSERVED ||
        r->how == TIPPE_DECIDED_ENERGY_CONE) {
        tc->agrees = -1;
        return;
    }
    for (int i = 0; i < tc->pred.n; i++) {
        tippe_final_kind k = tc->pred.state[i].kind;
        if ((k == TIPPE_FINAL_NO_TIP && r->verdict == TIPPE_VERDICT_NO_TIP) ||
            (k == TIPPE_FINAL_TIP && r->verdict == TIPPE_VERDICT_TIP) ||
            (k == TIPPE_FINAL_HANG && r->verdict == TIPPE_VERDICT_HANG &&
             fabs(tc->pred.state[i].theta_rad - r->theta_final_rad) <
                 TIPPE_LAUNCH_HANG_AGREE_RAD))
            tc->agrees = 1;
    }
}

static void print_text(const tippe_scenario *sc, const tippe_dynamics_result *r,
                       const theory_check *tc, double elapsed_s)
{
    const tippe_top *t = &sc->model.top;
    const tippe_dynamics_initial *ic = &sc->initial;
    printf("scenario  %s (%s)\n", sc->name, sc->path);
    if (sc->design_path[0])
        printf("design    %s at Z2 = %g mm\n", sc->design_path, sc->z2_mm);
    printf("top       m %.6g kg, R %.6g m, eps %.6g m, A %.6g kg m^2, C %.6g kg m^2\n", t->m,
           t->R, t->eps, t->A, t->C);
    printf("          A/C %.6g, eps/R %.6g: group %s\n", t->A / t->C, t->eps / t->R,
           tippe_group_name(tc->cls.group));
    char fr[160];
    printf("model     g %.6g m/s^2, friction %s\n", sc->model.g,
           tippe_dynamics_friction_text(&sc->model, fr, sizeof fr));
    printf("launch    theta %.6g rad, theta_dot %.6g rad/s, phi_dot %.6g rad/s (%s), spin %.6g "
           "rad/s, U %.6g m/s, V %.6g m/s\n",
           ic->theta, ic->theta_dot, ic->phi_dot,
           tippe_scenario_phi_dot_rule_name(sc->phi_dot_rule), ic->spin, ic->U, ic->V);
    char slide[200];
    printf("          %s\n", tippe_launch_slip_text(t, ic, NULL, slide, sizeof slide));
    printf("          Jellett J0 %.6g kg m^3/s, energy E0 %.6g J\n", r->J0, r->E0);
    const tippe_dynamics_sample *f = &r->final;
    switch (r->verdict) {
    case TIPPE_VERDICT_NO_TIP:
    case TIPPE_VERDICT_TIP:
    case TIPPE_VERDICT_HANG:
    case TIPPE_VERDICT_BOUNDED:
        tippe_cli_print_verdict_proof(r, "verdict   ");
        printf("          at the decision: theta %.6g rad, spin %.6g rad/s, contact speed %.3g m/s\n",
               f->theta, f->spin, f->slip_speed);
        break;
    case TIPPE_VERDICT_LOST_CONTACT:
        printf("verdict   lost_contact: the normal force reached 0 at t = %.6g s, theta %.6g rad "
               "(%.2f deg), spin %.6g rad/s, theta_dot %.6g rad/s\n",
               r->t_verdict, f->theta, f->theta * 180 / M_PI, f->spin, f->theta_dot);
        break;
    case TIPPE_VERDICT_UNDECIDED:
        if (r->how == TIPPE_DECIDED_FLAT_WELL) {
            tippe_cli_print_verdict_proof(r, "verdict   ");
            break;
        }
        printf("verdict   undecided: not proved by %s = %.6g s; theta %.6g rad (%.2f deg), "
               "spin %.6g rad/s, phi_dot %.6g rad/s, contact speed %.3g m/s\n",
               r->budget_exhausted ? "t" : "t_end", r->t_verdict, f->theta, f->theta * 180 / M_PI,
               f->spin, f->phi_dot, f->slip_speed);
        break;
    }
    tippe_cli_print_model_validity(&sc->protrusion, sc->z2_mm, "contact   ",
                                   "the verdict above is");
    if (r->last.t > r->t_verdict) /* --full, --csv or --plot: the run went on to t_end */
        printf("          at the end of the run, t = %.6g s: theta %.6g rad (%.2f deg), spin %.6g "
               "rad/s, contact speed %.3g m/s\n",
               r->last.t, r->last.theta, r->last.theta * 180 / M_PI, r->last.spin,
               r->last.slip_speed);
    if (!isnan(r->cap_first_s))
        printf("rim       on a hole's rim for %.4g s (within %.1f deg of the pole it rests on, "
               "%.1f deg of the other) from t = %.4g s to %.4g s, %ld switches between rim and "
               "sphere: the contact follows the rim there\n",
               r->cap_time_s, sc->cap_half_angle_rad[0] * 180 / M_PI,
               sc->cap_half_angle_rad[1] * 180 / M_PI, r->cap_first_s, r->cap_last_s,
               r->rim_switches);
    if (!isnan(r->t_flip))
        printf("flip      theta passed 90 deg at t = %.6g s (model time)\n", r->t_flip);
    if (!isnan(r->t_fall))
        printf("fall      back below 90 deg at t = %.6g s: above 90 deg for %.6g s in all\n",
               r->t_fall, r->inverted_time_s);
    else if (!isnan(r->t_flip))
        printf("inverted  above 90 deg for %.6g s, to t = %.6g s\n", r->inverted_time_s,
               r->last.t);
    if (tippe_friction_law_type_of(sc->model.law)->sticks)
        printf("contact   stuck %ld time%s and broke loose %ld time%s; rolled without slipping "
               "for %.6g s of the %.6g s integrated\n",
               r->stick_events, r->stick_events == 1 ? "" : "s", r->slip_events,
               r->slip_events == 1 ? "" : "s", r->rolling_time_s, r->last.t);
    if (r->budget_exhausted)
        printf("budget    exhausted: the integration stopped at its step budget (%ld accepted "
               "steps, %ld RHS evaluations) at t = %.6g s, before t_end = %.6g s\n",
               r->steps, r->rhs_evals, r->last.t, sc->t_end);
    if (!tc->ok) {
        printf("theory    no prediction: %s\n", tc->error);
    } else {
        printf("theory    Theorem 5.1 for J0: ");
        for (int i = 0; i < tc->pred.n; i++) {
            const char *k = tippe_final_kind_name(tc->pred.state[i].kind);
            if (tc->pred.state[i].kind == TIPPE_FINAL_HANG)
                printf("%s%s at theta %.6g rad (%.2f deg)", i ? " or " : "", k,
                       tc->pred.state[i].theta_rad, tc->pred.state[i].theta_rad * 180 / M_PI);
            else
                printf("%s%s", i ? " or " : "", k);
        }
        printf(" -> %s\n", tc->agrees > 0   ? "agrees"
                           : tc->agrees == 0 ? "DISAGREES"
                                             : "not comparable (no proved end state)");
    }
    char stepper[64]; /* the one that ran: the patch law's msbdf for the presets' rk8pd */
    const char *used = tippe_dynamics_stepper_used(sc->model.law, sc->model.creep_cap,
                                                   sc->accuracy.stepper);
    if (strcmp(used, sc->accuracy.stepper) != 0)
        snprintf(stepper, sizeof stepper, "%s (the %s law's stiff stepper)", used,
                 tippe_friction_law_name(sc->model.law));
    else
        snprintf(stepper, sizeof stepper, "%s", used);
    /* under drilling J moves by the physics: its drift is no error measure there */
    char jellett[64] = "J not conserved (drilling)";
    if (!isfinite(r->jellett_drift_time_s))
        snprintf(jellett, sizeof jellett, "Jellett drift %.2g", r->jellett_rel_drift);
    char creep[64] = ""; /* the patch law's creep reduction (creep_reduce) */
    if (r->creep_energy_J > 0)
        snprintf(creep, sizeof creep, ", the creep's reduction moved %.2g of E0",
                 r->creep_energy_J / r->E0);
    printf("accuracy  %s rtol %g (%s): %s, energy balance error %.2g%s, "
           "%ld steps (%ld rejected), %ld RHS evaluations, %.3g s\n",
           stepper,
           sc->accuracy.rtol, sc->accuracy_name, jellett, r->energy_rel_error, creep, r->steps,
           r->rejected_steps, r->rhs_evals, elapsed_s);
}

static cJSON *json_sample_fields(cJSON *o, const tippe_dynamics_sample *s)
{
    cJSON_AddNumberToObject(o, "theta_rad", s->theta);
    cJSON_AddNumberToObject(o, "theta_dot_rad_s", s->theta_dot);
    cJSON_AddNumberToObject(o, "phi_dot_rad_s", s->phi_dot);
    cJSON_AddNumberToObject(o, "spin_rad_s", s->spin);
    cJSON_AddNumberToObject(o, "U_m_s", s->U);
    cJSON_AddNumberToObject(o, "V_m_s", s->V);
    cJSON_AddNumberToObject(o, "Rn_N", s->Rn);
    cJSON_AddNumberToObject(o, "slip_speed_m_s", s->slip_speed);
    cJSON_AddNumberToObject(o, "E_J", s->E);
    cJSON_AddNumberToObject(o, "dissipated_J", s->D);
    if (s->patch_radius > 0.0) {
        cJSON_AddNumberToObject(o, "patch_mm", s->patch_radius * 1e3);
        cJSON_AddNumberToObject(o, "drill_torque_N_m", s->drill_torque);
    }
    return o;
}

static cJSON *to_json(const tippe_scenario *sc, const tippe_dynamics_result *r,
                      const theory_check *tc, double elapsed_s)
{
    const tippe_top *t = &sc->model.top;
    cJSON *o = cJSON_CreateObject();
    if (!o)
        return NULL;
    cJSON_AddStringToObject(o, "scenario", sc->path);
    cJSON_AddStringToObject(o, "name", sc->name);
    cJSON *top = cJSON_AddObjectToObject(o, "top");
    if (top) {
        if (sc->design_path[0]) {
            cJSON_AddStringToObject(top, "design", sc->design_path);
            cJSON_AddNumberToObject(top, "z2_mm", sc->z2_mm);
        }
        cJSON_AddNumberToObject(top, "m_kg", t->m);
        cJSON_AddNumberToObject(top, "R_m", t->R);
        cJSON_AddNumberToObject(top, "eps_m", t->eps);
        cJSON_AddNumberToObject(top, "A_kg_m2", t->A);
        cJSON_AddNumberToObject(top, "C_kg_m2", t->C);
        cJSON_AddNumberToObject(top, "A_over_C", t->A / t->C);
        cJSON_AddNumberToObject(top, "eps_over_R", t->eps / t->R);
        cJSON_AddStringToObject(top, "group", tippe_group_name(tc->cls.group));
    }
    cJSON_AddNumberToObject(o, "g_m_s2", sc->model.g);
    tippe_dynamics_friction_json(o, &sc->model);
    cJSON *ini = cJSON_AddObjectToObject(o, "initial");
    if (ini) {
        cJSON_AddNumberToObject(ini, "theta_rad", sc->initial.theta);
        cJSON_AddNumberToObject(ini, "theta_dot_rad_s", sc->initial.theta_dot);
        cJSON_AddNumberToObject(ini, "phi_dot_rad_s", sc->initial.phi_dot);
        cJSON_AddStringToObject(ini, "phi_dot_rule",
                                tippe_scenario_phi_dot_rule_name(sc->phi_dot_rule));
        cJSON_AddNumberToObject(ini, "spin_rad_s", sc->initial.spin);
        cJSON_AddNumberToObject(ini, "U_m_s", sc->initial.U);
        cJSON_AddNumberToObject(ini, "V_m_s", sc->initial.V);
        /* |v + omega x q| at launch (eq 3.7) */
        cJSON_AddNumberToObject(ini, "contact_slip_m_s",
                                tippe_dynamics_launch_slip(&sc->model.top, &sc->initial));
    }
    cJSON_AddStringToObject(o, "verdict", tippe_verdict_name(r->verdict));
    tippe_design_protrusion_json(o, &sc->protrusion);
    cJSON_AddNumberToObject(o, "t_s", r->t_verdict);
    json_sample_fields(o, &r->final);
    tippe_cli_json_verdict_proof(o, r);
    /* the state where the run stopped: past the decision with --full, --csv, --plot */
    cJSON *end = cJSON_AddObjectToObject(o, "end_of_run");
    if (end) {
        cJSON_AddNumberToObject(end, "t_s", r->last.t);
        json_sample_fields(end, &r->last);
    }
    cJSON_AddNumberToObject(o, "J0_kg_m3_s", r->J0);
    cJSON_AddNumberToObject(o, "E0_J", r->E0);
    cJSON_AddNumberToObject(o, "t_end_s", sc->t_end);
    cJSON_AddNumberToObject(o, "jellett_rel_drift", r->jellett_rel_drift);
    cJSON_AddNumberToObject(o, "energy_rel_error", r->energy_rel_error);
    cJSON_AddNumberToObject(o, "creep_energy_rel", r->creep_energy_J / r->E0);
    cJSON_AddNumberToObject(o, "min_Rn_N", r->min_Rn);
    cJSON_AddNumberToObject(o, "rhs_evals", (double)r->rhs_evals);
    cJSON_AddNumberToObject(o, "steps", (double)r->steps);
    cJSON_AddNumberToObject(o, "rejected_steps", (double)r->rejected_steps);
    cJSON_AddBoolToObject(o, "budget_exhausted", r->budget_exhausted);
    cJSON_AddNumberToObject(o, "state_dim", r->state_dim);
    cJSON_AddNumberToObject(o, "elapsed_s", elapsed_s);
    tippe_dynamics_accuracy_json(o, sc->accuracy_name, &sc->accuracy, sc->model.law,
                                 sc->model.creep_cap);
    cJSON *th = cJSON_AddObjectToObject(o, "theory");
    if (th) {
        cJSON_AddStringToObject(th, "group", tippe_group_name(tc->cls.group));
        if (!tc->ok) {
            cJSON_AddStringToObject(th, "error", tc->error);
        } else {
            cJSON *arr = cJSON_AddArrayToObject(th, "prediction");
            for (int i = 0; arr && i < tc->pred.n; i++) {
                cJSON *p = cJSON_CreateObject();
                if (!p)
                    continue;
                cJSON_AddStringToObject(p, "kind", tippe_final_kind_name(tc->pred.state[i].kind));
                cJSON_AddNumberToObject(p, "theta_rad", tc->pred.state[i].theta_rad);
                cJSON_AddNumberToObject(p, "spin_rad_s", tc->pred.state[i].spin_rad_s);
                cJSON_AddNumberToObject(p, "phi_dot_rad_s", tc->pred.state[i].phi_dot_rad_s);
                cJSON_AddItemToArray(arr, p);
            }
        }
        if (tc->agrees < 0)
            cJSON_AddNullToObject(th, "agrees");
        else
            cJSON_AddBoolToObject(th, "agrees", tc->agrees);
        cJSON_AddNumberToObject(th, "hang_tolerance_rad", TIPPE_LAUNCH_HANG_AGREE_RAD);
    }
    return o;
}

/* Most trajectory samples one run may keep: 10^6 samples of ~130 bytes. */
#define MAX_SAMPLES 1e6

typedef struct {
    const char *file, *csv, *plot;
    int json, full;
    double sample_dt;
    tippe_cli_launch_args l; /* the launch: scenario or design, and its options */
} simulate_args;

#define SIMULATE_ABOUT                                                                    \
    "Integrates one launch (the paper's section 3 model with the scenario's friction:\n" \
    "viscous, eq 3.12, or Coulomb with sticking) until its verdict is proved, it loses\n" \
    "contact or it reaches t_end, and compares it with Theorem 5.1's prediction for the\n" \
    "launch's Jellett invariant. Verdicts: no_tip, tip, hang, lost_contact, undecided,\n" \
    "bounded (no rest state is forced). The launch is a scenario file\n"                 \
    "(docs/dynamics.md), or a design with --z2 and the launch options below: without\n"   \
    "them, tippe launch's central hand launch (tilt 0.0674 rad, steady precession, spin\n" \
    "15 rev/s, centre at rest (its contact slips), viscous friction mu " TIPPE_CLI_STR(TIPPE_LAUNCH_DEFAULT_MU_S_M) " s/m)."

static int simulate_parse(simulate_args *a, int argc, char **argv)
{
    tippe_cli_opt opts[] = {
        TIPPE_CLI_LAUNCH_OPTS(&a->l),
        {.name = "json", .kind = TIPPE_CLI_FLAG, .value = &a->json,
         .help = "print one JSON object (SI units) instead of the summary"},
        {.name = "csv", .kind = TIPPE_CLI_STRING, .value = &a->csv, .arg = "FILE",
         .help = "write the trajectory (t, theta, theta_dot, phi_dot, n, U, V, Rn,\n"
                 "|V_Q|, E, J, ...; units in the header)"},
        {.name = "plot", .kind = TIPPE_CLI_STRING, .value = &a->plot, .arg = "FILE",
         .help = "theta, spin and contact speed against time and the (phi_dot, theta, n)\n"
                 "path; .png, .svg or .pdf"},
        {.name = "sample-dt", .kind = TIPPE_CLI_DOUBLE, .value = &a->sample_dt, .unit = "s",
         .min = 1e-9, .max = 1e6, .def = "16 per turn, t_end/10^5 .. t_end/10^4",
         .help = "trajectory sample interval (at most 10^6 samples in all)"},
        {.name = "full", .kind = TIPPE_CLI_FLAG, .value = &a->full,
         .help = "keep integrating to t_end after the verdict (always with --csv or\n--plot)"},
        {NULL},
    };
    tippe_cli_spec spec = {
        .verb = VERB,
        .synopsis = "SCENARIO.json [options]\n"
                    "       tippe simulate DESIGN.json --z2 MM [--spin RATE] [--theta RAD] "
                    "[options]",
        .about = SIMULATE_ABOUT,
        .after = "Exit status: 0 ok (whatever the verdict), 2 bad usage or scenario, 1\n"
                 "computation failed. The scenario format and the verdicts: docs/dynamics.md.",
        .opts = opts,
        .min_args = 1,
        .max_args = 1,
        .args_name = "scenario or design file",
    };
    int n_args, rc = tippe_cli_parse(&spec, argc, argv, &a->file, &n_args);
    if (rc)
        return rc;
    if ((rc = tippe_cli_launch_finish(VERB, &spec, a->file, &a->l)) != 0)
        return rc;
    /* Before the integration, so that a bad output path costs nothing. */
    if ((a->csv && tippe_cli_check_output(VERB, "--csv", a->csv, 0)) ||
        (a->plot && tippe_cli_check_output(VERB, "--plot", a->plot, 1)))
        return 2;
    return 0;
}

static int simulate_load(const simulate_args *a, tippe_scenario *sc)
{
    tippe_error err;
    int rc = tippe_cli_launch_load(a->file, &a->l, sc, &err);
    if (rc)
        return tippe_cli_fail(VERB, &err, rc);
    tippe_scenario_free(sc); /* the launch is the scenario's numbers; its design is not shown */
    /* the design's --set changes go into the name, hence the text and plot titles */
    if (a->l.is_design && a->l.sets.n) {
        char sets[512];
        const size_t len = strlen(sc->name);
        snprintf(sc->name + len, sizeof sc->name - len, " [design: %s]",
                 tippe_cli_sets_text(&a->l.sets, sets, sizeof sets));
    }
    return 0;
}

/* The trajectory sampling (with --csv or --plot): 0, or 2 if the samples
 * would be more than MAX_SAMPLES. */
static int plan_samples(const simulate_args *a, const tippe_scenario *sc,
                        tippe_dynamics_options *opt, samples *buf)
{
    if (!a->csv && !a->plot)
        return 0;
    double dt = a->sample_dt;
    if (dt <= 0) /* 16 per turn, no more than 10^5 samples */
        dt = tippe_dynamics_default_sample_dt(&sc->initial, sc->model.g, sc->model.top.R,
                                              sc->t_end);
    if (sc->t_end / dt > MAX_SAMPLES)
        return tippe_cli_usage_error(VERB,
                                     "--sample-dt %g s over t_end = %g s is %.3g samples; at "
                                     "most %.0e (%.0f MB): give a larger --sample-dt or a "
                                     "smaller --t-end",
                                     dt, sc->t_end, sc->t_end / dt, MAX_SAMPLES,
                                     MAX_SAMPLES * sizeof(tippe_dynamics_sample) / 1e6);
    opt->level = TIPPE_LEVEL_TRAJECTORY;
    opt->sample_dt = dt;
    opt->on_sample = tippe_dynamics_samples_keep;
    opt->sample_ctx = buf;
    return 0;
}

/* The outputs (all of them or none) and the report. */
static int simulate_report(const simulate_args *a, const tippe_scenario *sc,
                           const tippe_dynamics_result *res, const samples *buf,
                           double elapsed)
{
    theory_check tc;
    check_theory(sc, res, &tc);
    tippe_error err;
    int rc = 0;
    if (a->csv && (rc = write_csv(a->csv, buf, &err)) != 0)
        return tippe_cli_fail(VERB, &err, rc);
    /* The outputs form one set (tippe_cli_run): a failed plot keeps the CSV's
     * old file too. */
    if (a->plot && (rc = tippe_plot_sim(a->plot, sc, res, buf->s, buf->n, &err)) != 0)
        return tippe_cli_fail(VERB, &err, rc);
    if (a->json) {
        cJSON *o = to_json(sc, res, &tc, elapsed);
        if (o && a->l.is_design)
            tippe_cli_json_sets(o, &a->l.sets);
        return tippe_cli_print_json(VERB, o);
    }
    print_text(sc, res, &tc, elapsed);
    if (a->csv)
        printf("csv       %s (%d samples)\n", a->csv, buf->n);
    if (a->plot)
        printf("plot      %s\n", a->plot);
    return 0;
}

int tippe_cli_simulate(int argc, char **argv)
{
    simulate_args a = {.sample_dt = 0.0};
    int rc = simulate_parse(&a, argc, argv);
    if (rc)
        return rc == TIPPE_CLI_HELP ? 0 : rc;
    tippe_scenario sc;
    if ((rc = simulate_load(&a, &sc)) != 0)
        return rc;
    tippe_dynamics_options opt;
    tippe_dynamics_options_default(&opt);
    opt.t_end = sc.t_end;
    opt.accuracy = sc.accuracy;
    /* A verdict is often proved long before the motion ends (even at t = 0): a
     * trajectory asked for runs to t_end; a flip is followed to report its time. */
    opt.run_to_t_end = a.full || a.csv || a.plot;
    opt.until_flip = 1;
    opt.cap_half_angle_rad[0] = sc.cap_half_angle_rad[0];
    opt.cap_half_angle_rad[1] = sc.cap_half_angle_rad[1];
    samples buf = {0, 0, NULL};
    if ((rc = plan_samples(&a, &sc, &opt, &buf)) != 0)
        return rc;
    tippe_dynamics_result res;
    tippe_error err;
    const double t0 = tippe_cli_now_s();
    rc = tippe_dynamics_run(&sc.model, &sc.initial, &opt, &res, &err);
    const double elapsed = tippe_cli_now_s() - t0;
    if (rc)
        fprintf(stderr, "tippe simulate: %s: %s\n", a.file, err.msg);
    else
        rc = simulate_report(&a, &sc, &res, &buf, elapsed);
    tippe_dynamics_samples_free(&buf);
    return rc;
}
