/* tippe launch: many hand launches of a design's top at one Z2, counted by
 * outcome beside theory's prediction (the drawing of the launches is in
 * tippe/launch.h; what launch, map and check share is in hands.c). */
#include "hands.h"

#include "tippe/base.h"
#include "tippe/launch.h"

#include <cjson/cJSON.h>
#include <inttypes.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>

#define LAUNCH_ABOUT                                                                       \
    "Launches the design's top N times by hand, as a person would: a spin, a small tilt,\n"  \
    "a precession near the steady one and a little sliding, each drawn at random\n"         \
    "(docs/launch.md), and integrates each launch (the paper's section 3 model, with its\n" \
    "viscous friction by default) until its verdict is proved (an energy barrier and a\n" \
    "contact bound, docs/dynamics.md), it leaves the table or it reaches t_end.\n"        \
    "Prints how many launches end in no_tip, tip, hang, lost_contact, undecided and\n"     \
    "bounded (no friction, eps = 0 or rolling: confined, no end state), with 95% Wilson confidence\n"   \
    "intervals, beside Theorem 5.1's prediction for each launch's Jellett invariant and\n" \
    "the fraction of launches that agree with it."

/* A finite number in format fmt, or nothing (an empty CSV field). */
static void csv_number(FILE *f, const char *fmt, double v)
{
    if (isfinite(v))
        fprintf(f, fmt, v);
}

/* Rounds the last bits away: "%.10g" etc. keep CSV deterministic and short. */
static int write_launch_csv(const char *path, const tippe_launch_record *r, long n,
                            tippe_error *err)
{
    tippe_report_file rf;
    int rc = tippe_report_open(&rf, path, "the CSV file", err);
    if (rc)
        return rc;
    FILE *f = rf.f;
    fprintf(f, "index,draw,spin_rad_s,tilt_rad,theta_dot_rad_s,phi_dot_rad_s,U_m_s,"
               "V_m_s,verdict,t_s,theta_final_rad,spin_final_rad_s,J0_kg_m3_s,jellett_rel_drift,"
               "rhs_evals,theory,theory_hang_theta_rad,agrees,decided_by,barrier_gap_J,margin_J,"
               "t_flip_s,cap_time_s,cap_first_s,t_fall_s,inverted_time_s\n");
    for (long i = 0; i < n; i++) {
        const tippe_launch_record *x = &r[i];
        fprintf(f, "%ld,%ld,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%s,%.10g,", x->index, x->draw,
                x->ic.spin, x->ic.theta, x->ic.theta_dot, x->ic.phi_dot, x->ic.U, x->ic.V,
                tippe_verdict_name(x->verdict), x->t_s);
        /* empty for a bounded launch: a range, no end state */
        csv_number(f, "%.10g", x->theta_final_rad);
        fputc(',', f);
        csv_number(f, "%.10g", x->spin_final_rad_s);
        fprintf(f, ",%.10g,%.3g,%ld,%s,", x->J0, x->jellett_rel_drift, x->rhs_evals,
                x->theory_ok ? tippe_launch_predicted_name(x->predicted) : "none");
        csv_number(f, "%.10g", x->hang_theta_rad);
        fprintf(f, ",%s,%s,", x->agrees > 0 ? "yes" : x->agrees == 0 ? "no" : "",
                tippe_decision_name(x->how));
        /* empty where not applicable: an infinite gap (a well with no barrier) too */
        csv_number(f, "%.4g", x->barrier_gap_J);
        fputc(',', f);
        csv_number(f, "%.4g", x->margin_J);
        fputc(',', f);
        csv_number(f, "%.10g", x->t_flip_s);
        fprintf(f, ",%.10g,", x->cap_time_s); /* on a hole's rim at a pole (issue 25.7) */
        csv_number(f, "%.10g", x->cap_first_s);
        fputc(',', f);
        /* back below pi/2 after the flip, and the model time spent above it */
        csv_number(f, "%.10g", x->t_fall_s);
        fputc(',', f);
        csv_number(f, "%.10g", x->inverted_time_s);
        fputc('\n', f);
    }
    return tippe_report_commit(&rf, err);
}

static void print_counts_table(const tippe_launch_tally *t)
{
    printf("\noutcome         count  share   95%% CI (Wilson)   median theta_final   median t "
           "decided\n");
    for (int v = 0; v < TIPPE_LAUNCH_N_VERDICTS; v++) {
        double lo, hi;
        tippe_launch_wilson(t->counts[v], t->n, TIPPE_LAUNCH_Z95, &lo, &hi);
        printf("%-14s %6ld  %5.3f   [%5.3f, %5.3f]", hands_verdict_names[v], t->counts[v],
               t->n ? (double)t->counts[v] / (double)t->n : 0.0, lo, hi);
        if (t->counts[v] && isfinite(t->median_theta_rad[v]))
            printf("    %7.4f rad %6.1f deg  %8.1f s\n", t->median_theta_rad[v],
                   t->median_theta_rad[v] * 180 / M_PI, t->median_t_s[v]);
        else if (t->counts[v]) /* bounded: a range, no end angle */
            printf("    %-19s  %8.1f s\n", "(a range)", t->median_t_s[v]);
        else
            printf("\n");
    }
}

static void print_theory_summary(const tippe_launch_tally *t, const tippe_launch_options *o)
{
    printf("\ntheory     Theorem 5.1 for each launch's Jellett invariant predicts:");
    int first = 1;
    for (unsigned m = 1; m < 8; m++)
        if (t->predicted[m]) {
            printf("%s %s %ld", first ? "" : ";", tippe_launch_predicted_name(m), t->predicted[m]);
            first = 0;
        }
    if (t->predicted[0])
        printf("%s no prediction %ld", first ? "" : ";", t->predicted[0]);
    printf("\n");
    double lo, hi;
    tippe_launch_wilson(t->agree, t->comparable, TIPPE_LAUNCH_Z95, &lo, &hi);
    if (t->comparable)
        printf("agreement  %ld of %ld settled launches end in a state theory predicts for their J "
               "(%.3f, 95%% CI [%.3f, %.3f]; a hang within %g rad)\n",
               t->agree, t->comparable, (double)t->agree / (double)t->comparable, lo, hi,
               TIPPE_LAUNCH_HANG_AGREE_RAD);
    else
        printf("agreement  no settled launch to compare\n");
    /* how the verdicts were reached (docs/dynamics.md, "Proved verdicts") */
    if (t->trapped) {
        printf("proof      %ld no_tip/tip/hang proved by energy trapping and a contact bound",
               t->trapped);
        if (t->trapped_no_barrier)
            printf(", %ld of them in a well with no barrier", t->trapped_no_barrier);
        if (isfinite(t->min_gap_over_margin))
            printf("; smallest barrier gap %.3g times its margin", t->min_gap_over_margin);
        printf("\n");
    }
    if (t->rolling)
        printf("rolling    %ld launches stick and roll without slipping for ever (Coulomb "
               "friction: nothing dissipates; docs/dynamics.md)\n",
               t->rolling);
    if (t->flips)
        printf("flip       %ld tips followed to theta = 90 deg: median model time %.3g s\n",
               t->flips, t->median_t_flip_s);
    if (tippe_friction_law_type_of(o->law)->drills && o->mu_c > 0)
        printf("observed   the end verdicts are the state at t_end, NOT proved (drilling "
               "changes J: docs/dynamics.md); only no_tip by the energy cone is\n");
    else if (t->on_cap && !o->sphere_contact_only)
        printf("observed   a launch that stood on a rim and was not decided by t_end is the "
               "state there, NOT proved (J changes on a rim: docs/dynamics.md, \"The contact on "
               "a rim\")\n");
    if (t->passed > t->flips) { /* flips that did not end as tip (the patch law's fall back) */
        printf("passed     %ld of %ld launches passed 90 deg (median %.3g s)", t->passed, t->n,
               t->median_t_passed_s);
        if (t->fell)
            printf("; %ld of them came back below it (median %.3g s)", t->fell,
                   t->median_t_fall_s);
        printf("\n");
    }
}

/* The verb's own options beside hands.c's shared ones. */
static int launch_parse(hands_args *a, int argc, char **argv)
{
    tippe_cli_opt own[] = {
        {.name = "z2", .kind = TIPPE_CLI_DOUBLE, .value = &a->z2_mm, .arg = "MM", .unit = "mm",
         .min = -TIPPE_CLI_Z2_MAX_MM, .max = TIPPE_CLI_Z2_MAX_MM, .required = 1,
         .help = "position of the moving weight's midpoint (in the design's travel)"},
        {.name = "n", .short_name = 'n', .kind = TIPPE_CLI_LONG, .value = &a->n, .arg = "N",
         .min = 1, .max = 1e7, .def = "50", .help = "number of launches"},
        {.name = "spin", .kind = TIPPE_CLI_RANGE, .value = &a->spin, .arg = "FROM:TO",
         .unit = "rad/s", .min = 0, .max = HANDS_SPIN_MAX_RAD_S, .def = "5:25rev/s",
         .help = "spin drawn uniformly in FROM .. TO (a unit on TO applies to FROM)"},
        {.name = "csv", .kind = TIPPE_CLI_STRING, .value = &a->csv, .arg = "FILE",
         .help = "one row per launch: initial state, verdict, t_s, theta_final,\n"
                 "Jellett drift, theory's prediction, how it was decided (barrier gap,\n"
                 "margin), the flip time, the time on a hole's opening at a pole\n"
                 "(cap_time_s, cap_first_s), the fall back and the time above 90 deg\n"
                 "(t_fall_s, inverted_time_s) (- for stdout)"},
        HANDS_RADIUS_OPTIONS(a, "the same launches"),
        HANDS_CONTACT_OPTION(a),
        {NULL},
    };
    hands_verb v = {
        .spec = {.verb = "launch",
                 .progress = 1,
                 .synopsis = "DESIGN.json --z2 MM [-n N] [--seed S] [--spin FROM:TO] [options]",
                 .about = LAUNCH_ABOUT,
                 .after = "A progress bar with the time left is shown on stderr when it is a\n"
                          "terminal. Under mpirun -np N (N > 1) the launches are shared among\n"
                          "the ranks (tippe-mpi). Exit status: 0 ok, 2 bad usage or design,\n"
                          "1 a launch could not be computed. Details: docs/launch.md."},
        .own = own,
        .distribution = 1,
    };
    int rc = hands_parse(&v, a, argc, argv);
    a->o.spin_from_rev_s = a->spin.from / (2 * M_PI);
    a->o.spin_to_rev_s = a->spin.to / (2 * M_PI);
    if (!rc && a->csv && hands_mpi_rank() == 0)
        rc = tippe_cli_check_output(a->verb, "--csv", a->csv, 0);
    return rc;
}

static void launch_json(const hands_args *a, const tippe_design *d, const tippe_top *top,
                        const tippe_launch_tally *t, const tippe_sweep_point_zone *z,
                        const tippe_launch_radius_sensitivity *sens, int *rc)
{
    /* No timings or thread counts: the JSON is the same on any machine
     * layout, byte for byte. */
    cJSON *o = hands_json_tally(t);
    if (o) {
        cJSON_AddStringToObject(o, "design", tippe_design_name(d));
        cJSON_AddStringToObject(o, "file", tippe_design_path(d));
        tippe_cli_json_sets(o, &a->sets);
        cJSON_AddNumberToObject(o, "z2_mm", a->z2_mm);
        cJSON_AddNumberToObject(o, "seed", (double)a->seed);
        tippe_design_protrusion pr;
        tippe_design_protrusion_at(d, a->z2_mm, &pr);
        tippe_design_protrusion_json(o, &pr);
        cJSON_AddItemToObject(o, "theory", tippe_sweep_theory_json(top, a->o.g, z, t));
        cJSON_AddItemToObject(o, "distribution", tippe_launch_options_json(&a->o, 0));
        cJSON_AddNumberToObject(o, "max_jellett_rel_drift", t->max_jellett_rel_drift);
        cJSON_AddNumberToObject(o, "rhs_evals", t->rhs_evals);
        const int patch = tippe_friction_law_type_of(a->o.law)->patch;
        if (patch) /* the radius at m g the launches started from */
            cJSON_AddNumberToObject(o, "patch_radius_mm", 1e3 * tippe_launch_patch_radius(top, &a->o));
        if (patch)
            cJSON_AddItemToObject(o, "radius_sensitivity",
                                  sens ? tippe_launch_radius_json(sens, 0) : cJSON_CreateNull());
    }
    *rc = tippe_cli_print_json(a->verb, o);
}

/* The summary at 1/F, 1 and F times the patch radius, the same draws at each. */
static void print_radius_sensitivity(const tippe_launch_radius_sensitivity *s, long n)
{
    printf("radius     the patch radius is uncertain (surface, table, wear): the same %ld "
           "launches at\n", n);
    for (int i = 0; i < TIPPE_LAUNCH_RADIUS_RUNS; i++) {
        const tippe_launch_radius_run *r = &s->run[i];
        char factor[16];
        snprintf(factor, sizeof factor, "%.3gx", r->factor);
        printf("           %-5s %.4g mm: ", factor, r->radius_m * 1e3);
        if (!r->ran) {
            printf("not run (wider than half the ball's radius)\n");
            continue;
        }
        const char *sep = "";
        for (int v = 0; v < TIPPE_LAUNCH_N_VERDICTS; v++)
            if (r->counts[v]) {
                printf("%s%s %ld", sep, tippe_verdict_name((tippe_verdict)v), r->counts[v]);
                sep = ", ";
            }
        printf("; over 90 deg %ld", r->passed);
        if (r->passed)
            printf(" (median %.3g s)", r->median_t_flip_s);
        printf(", back below %ld", r->fell);
        if (r->fell)
            printf(" (median %.3g s)", r->median_t_fall_s);
        printf("\n");
    }
    if (s->robust)
        printf("           robust to the radius: every launch gives the same flip and "
               "fall back at all three\n");
    else if (s->changed == 0) /* a radius was not run */
        printf("           robustness to the radius not known: a radius was not run\n");
    else
        printf("           NOT robust to the radius: %ld of %ld launches change flip, fall back "
               "or decided verdict between %.3gx and %.3gx the radius\n", s->changed, n, s->run[0].factor,
               s->run[2].factor);
}

static void launch_text(const hands_args *a, const tippe_design *d, const tippe_top *top,
                        const tippe_launch_tally *t, const tippe_sweep_point_zone *z, double elapsed)
{
    hands_print_top(d, a->z2_mm, top, a->o.g, z);
    char sets[1024];
    if (a->sets.n)
        printf("changes    %s\n", tippe_cli_sets_text(&a->sets, sets, sizeof sets));
    printf("launches   %ld by hand, seed %ld\n", a->n, a->seed);
    hands_print_distribution(&a->o, 0);
    hands_print_model(&a->o, top);
    print_counts_table(t);
    tippe_design_protrusion pr;
    tippe_design_protrusion_at(d, a->z2_mm, &pr);
    tippe_cli_print_model_validity(&pr, a->z2_mm, "contact    ", "the outcomes above are");
    if (t->on_cap && a->o.sphere_contact_only)
        printf("pole       INVALID for %ld of %ld launches: their contact lay within a hole's "
               "opening at a pole (within %.1f deg of the pole they rest on, %.1f deg of the "
               "other) before their verdict, where the top stands on the hole's rim, not on "
               "its sphere as --sphere-contact assumes\n",
               t->on_cap, t->n, a->o.cap_half_angle_rad[0] * 180 / M_PI,
               a->o.cap_half_angle_rad[1] * 180 / M_PI);
    else if (t->on_cap)
        printf("rim        %ld of %ld launches stood on a hole's rim at a pole (within %.1f deg "
               "of the pole they rest on, %.1f deg of the other) before their verdict: the "
               "contact follows the rim there\n",
               t->on_cap, t->n, a->o.cap_half_angle_rad[0] * 180 / M_PI,
               a->o.cap_half_angle_rad[1] * 180 / M_PI);
    print_theory_summary(t, &a->o);
    char jellett[64] = "J not conserved (drilling)";
    if (!tippe_friction_law_type_of(a->o.law)->drills || !(a->o.mu_c > 0)) /* nothing drills */
        snprintf(jellett, sizeof jellett, "largest Jellett drift %.2g", t->max_jellett_rel_drift);
    printf("accuracy   %s; %.3g RHS evaluations; %.2f s on %d "
           "thread%s x %d rank%s (%.1f launches/s)\n",
           jellett, t->rhs_evals, elapsed, omp_get_max_threads(),
           omp_get_max_threads() > 1 ? "s" : "", hands_mpi_size(),
           hands_mpi_size() > 1 ? "s" : "", (double)a->n / elapsed);
    if (a->csv)
        printf("csv        %s (%ld launches)\n", a->csv, a->n);
}

/* Under the patch law (unless --no-radius-sensitivity): the same launches at 1/F and F times
 * the patch radius into rec + n and rec + 2n (every rank), summarised beside the plain run
 * rec on rank 0 into *s. */
static int launch_radius_runs(const hands_args *a, const tippe_top *top,
                              tippe_launch_record *rec, tippe_progress *prog,
                              tippe_launch_radius_sensitivity *s, tippe_error *err)
{
    tippe_launch_plan plan = {1, a->n, top, NULL, NULL};
    const tippe_launch_record *ptr[TIPPE_LAUNCH_RADIUS_RUNS];
    double radius_m[TIPPE_LAUNCH_RADIUS_RUNS];
    for (int i = 0; i < TIPPE_LAUNCH_RADIUS_RUNS; i++) {
        tippe_launch_options oi;
        const int beyond = tippe_launch_radius_options(
            top, &a->o, tippe_launch_radius_factor(&a->o, i), &oi);
        radius_m[i] = oi.patch_radius_m;
        tippe_launch_record *ri = i == 1 ? rec : rec + (i == 0 ? 1 : 2) * a->n;
        ptr[i] = beyond ? NULL : ri;
        if (i == 1 || beyond)
            continue;
        int rc = hands_run_plan(&plan, &oi, (uint64_t)a->seed, ri, prog, err);
        if (rc)
            return rc;
    }
    if (hands_mpi_rank() != 0)
        return 0;
    return tippe_launch_radius_summary(ptr, a->n, radius_m, s, err);
}

/* Runs the launches (every rank) and, on rank 0, writes and prints the results. rec has
 * room for 3 n records when the radius sensitivity runs. */
static int launch_run(const hands_args *a, const tippe_design *d, const tippe_top *top,
                      tippe_launch_record *rec, int radius_runs)
{
    tippe_error err;
    tippe_launch_plan plan = {1, a->n, top, NULL, NULL};
    tippe_progress prog;
    tippe_progress_start(&prog, stderr, "tippe launch", radius_runs ? 3 * a->n : a->n,
                         tippe_cli_progress_mode());
    const double t0 = tippe_cli_now_s();
    int rc = hands_run_plan(&plan, &a->o, (uint64_t)a->seed, rec, &prog, &err);
    const double elapsed = tippe_cli_now_s() - t0;
    tippe_launch_radius_sensitivity sens;
    if (!rc && radius_runs)
        rc = launch_radius_runs(a, top, rec, &prog, &sens, &err);
    tippe_progress_finish(&prog);
    if (hands_mpi_rank() != 0)
        return 0;
    tippe_launch_tally t;
    if (!rc && (rc = tippe_launch_tally_records(rec, a->n, &t, &err)) == 0 && a->csv)
        rc = write_launch_csv(a->csv, rec, a->n, &err);
    if (rc)
        return tippe_cli_fail(a->verb, &err, rc);
    tippe_sweep_point_zone z;
    tippe_sweep_zone_at(d, a->z2_mm, &z);
    if (a->json) {
        launch_json(a, d, top, &t, &z, radius_runs ? &sens : NULL, &rc);
    } else {
        launch_text(a, d, top, &t, &z, elapsed);
        if (radius_runs)
            print_radius_sensitivity(&sens, a->n);
    }
    return rc;
}

int tippe_cli_launch(int argc, char **argv)
{
    hands_args a = {.verb = "launch", .n = 50, .seed = 1,
                    .spin = {2 * M_PI * 5.0, 2 * M_PI * 25.0, 0}};
    tippe_launch_options_default(&a.o);
    int rc = launch_parse(&a, argc, argv);
    if (rc == TIPPE_CLI_HELP)
        return 0;
    tippe_error err;
    tippe_design *d = NULL;
    tippe_top top;
    if (!rc && (rc = tippe_design_load(a.design, a.sets.item, a.sets.n, &d, &err)) != 0)
        rc = tippe_cli_fail(a.verb, &err, rc);
    if (!rc && hands_mpi_rank() == 0)
        tippe_cli_design_warnings(a.verb, d);
    if (!rc && (rc = hands_patch(&a, d, &err)) != 0)
        rc = tippe_cli_fail(a.verb, &err, rc);
    if (!rc && (rc = tippe_design_top(d, a.z2_mm, &top, &err)) != 0)
        rc = tippe_cli_fail(a.verb, &err, rc);
    if (!rc) /* each launch records its time on a hole's rim at a pole (issue 25.7) */
        tippe_launch_polar_caps(d, a.z2_mm, &top, a.o.cap_half_angle_rad);
    tippe_launch_record *rec = NULL;
    const int radius_runs = tippe_friction_law_type_of(a.o.law)->patch && !a.no_radius_sensitivity;
    if (!rc && !(rec = calloc((size_t)a.n * (radius_runs ? 3 : 1), sizeof *rec))) {
        fprintf(stderr, "tippe launch: out of memory for %ld launches\n", a.n);
        rc = 1;
    }
    if (!rc && a.n >= 100000 && hands_mpi_rank() == 0)
        fprintf(stderr, "tippe launch: %ld launches ahead; this takes a while (progress below)\n",
                a.n);
    if ((rc = hands_mpi_agree(rc)) == 0)
        rc = launch_run(&a, d, &top, rec, radius_runs);
    free(rec);
    tippe_design_free(d);
    return rc;
}
