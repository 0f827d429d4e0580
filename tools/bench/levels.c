/* levels: what a launch costs at each level of detail, and per RHS evaluation.
 *
 * For one scenario at one accuracy it times (median of REPEATS runs, one core):
 *   verdict      the 9-component state, no samples (what launches and maps use);
 *   traj/step    the 15-component state, every accepted step handed to a callback;
 *   traj/grid    the 15-component state landing on a grid of N samples (what
 *                `tippe simulate --csv` asks for), samples kept in memory;
 *   traj/csv     the same grid, each sample written to a CSV file as it comes
 *                (the `--csv` column set and format).
 * It prints wall time, RHS evaluations, steps and wall time per evaluation (the
 * whole run divided by the evaluations: an upper bound on the cost of one RHS;
 * perf gives the share of the RHS itself, see tools/bench/run.sh).
 *
 *   usage: levels SCENARIO.json [REPEATS [N_SAMPLES [CSV_PATH [verdict]]]]
 *   (defaults 7, 20000, /tmp/tippe-levels.csv; the CSV is removed at the end;
 *   a fifth argument "verdict" runs the verdict level only, for perf) */
#include "tippe/physics.h"
#include "../bench_util.h"
#include "tippe/scenario.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

typedef struct {
    long n;
    double sum_theta; /* keeps the samples live, so nothing is optimised away */
    FILE *csv;
    tippe_dynamics_sample *keep;
    long cap;
} sink;

static int take(const tippe_dynamics_sample *s, void *ctx)
{
    sink *k = ctx;
    if (k->keep && k->n < k->cap)
        k->keep[k->n] = *s;
    k->n++;
    k->sum_theta += s->theta;
    if (k->csv &&
        fprintf(k->csv,
                "%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,"
                "%.10g,%.10g,%.10g,%.10g\n",
                s->t, s->theta, s->theta_dot, s->phi_dot, s->spin, s->U, s->V, s->Rn,
                s->slip_speed, s->E, s->J, s->D, s->phi, s->psi, s->x, s->y) < 0)
        return 1;
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: levels SCENARIO.json [REPEATS [N_SAMPLES [CSV_PATH [verdict]]]]\n");
        return 2;
    }
    const int repeats = argc > 2 ? atoi(argv[2]) : 7;
    const long n_samples = argc > 3 ? atol(argv[3]) : 20000;
    const char *csv_path = argc > 4 ? argv[4] : "/tmp/tippe-levels.csv";
    const int n_modes = argc > 5 && !strcmp(argv[5], "verdict") ? 1 : 4;
    if (repeats < 1 || repeats > 1000 || n_samples < 1) {
        fprintf(stderr, "levels: REPEATS in 1..1000 and N_SAMPLES >= 1\n");
        return 2;
    }
    tippe_scenario sc;
    tippe_error err;
    if (tippe_scenario_load(argv[1], NULL, 0, &sc, &err)) {
        fprintf(stderr, "levels: %s\n", err.msg);
        return 2;
    }
    /* The grid modes integrate to the verdict-level run's verdict time, so
     * that every mode covers the same stretch of the motion. */
    double t_stop = sc.t_end;
    printf("scenario %s, %s rtol %g\n", sc.path, sc.accuracy.stepper, sc.accuracy.rtol);
    printf("%-10s %8s %10s %9s %10s %10s %12s %9s\n", "level", "verdict", "t_s", "steps",
           "rhs_evals", "time_ms", "ns/eval(all)", "samples");
    tippe_dynamics_sample *keep = malloc((size_t)(n_samples + 2) * sizeof *keep);
    double *times = malloc((size_t)repeats * sizeof *times);
    if (!keep || !times) {
        fprintf(stderr, "levels: out of memory\n");
        return 1;
    }
    int rc = 0;
    for (int mode = 0; mode < n_modes && !rc; mode++) {
        static const char *names[] = {"verdict", "traj/step", "traj/grid", "traj/csv"};
        tippe_dynamics_options o;
        tippe_dynamics_options_default(&o);
        o.accuracy = sc.accuracy;
        o.t_end = mode == 0 ? sc.t_end : t_stop;
        if (mode > 0) {
            o.level = TIPPE_LEVEL_TRAJECTORY;
            o.on_sample = take;
            o.sample_dt = mode >= 2 ? t_stop / (double)n_samples : 0.0;
        }
        tippe_dynamics_result r;
        sink k;
        for (int rep = 0; rep < repeats; rep++) {
            memset(&k, 0, sizeof k);
            k.keep = mode == 2 ? keep : NULL;
            k.cap = n_samples + 2;
            if (mode == 3) {
                k.csv = fopen(csv_path, "w");
                if (!k.csv) {
                    fprintf(stderr, "levels: cannot write %s\n", csv_path);
                    rc = 1;
                    break;
                }
                fprintf(k.csv, "t_s,theta_rad,theta_dot_rad_s,phi_dot_rad_s,spin_rad_s,U_m_s,"
                               "V_m_s,Rn_N,slip_speed_m_s,E_J,J_kg_m3_s,D_J,phi_rad,psi_rad,"
                               "x_m,y_m\n");
            }
            o.sample_ctx = &k;
            const double t0 = bench_now_s();
            int s = tippe_dynamics_run(&sc.model, &sc.initial, &o, &r, &err);
            if (k.csv && fclose(k.csv))
                s = s ? s : 1;
            times[rep] = bench_now_s() - t0;
            if (s) {
                fprintf(stderr, "levels: %s: %s\n", names[mode], err.msg);
                rc = 1;
                break;
            }
        }
        if (rc)
            break;
        if (mode == 0)
            t_stop = r.t_verdict;
        const double med = bench_median(times, (size_t)repeats);
        printf("%-10s %8s %10.4g %9ld %10ld %10.3f %12.1f %9ld\n", names[mode],
               tippe_verdict_name(r.verdict), r.t_verdict, r.steps, r.rhs_evals, 1e3 * med,
               1e9 * med / (double)r.rhs_evals, k.n);
    }
    remove(csv_path);
    free(keep);
    free(times);
    return rc;
}
