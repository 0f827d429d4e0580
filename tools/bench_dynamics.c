/* bench_dynamics: what one launch costs at each level of detail and preset.
 *
 * For a few launches (the shipped scenarios' tops), with each accuracy preset,
 * runs three modes: the verdict level (9-component state, no samples); the
 * trajectory level (15 components) handing every accepted step to a callback
 * ("traj/step"); and the trajectory level on a grid of t_end/10^5 that the
 * integrator must land on ("traj/grid", what tippe simulate --csv does). It
 * prints RHS evaluations, steps, the best wall time of several repeats, and the
 * Jellett drift reached.
 *   usage: bench_dynamics [REPEATS]   (default 5) */
#include "tippe/physics.h"
#include "bench_util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

/* designs/m12-setscrew.json at Z2 = 15 mm, and the central hand launch's tilt */
#define M12_TOP {0.0768353146, 0.025, 0.00219013874, 1.9053487e-05, 1.77647865e-05, 1}
#define M12_TILT 0.067448975019608171

typedef struct {
    const char *name;
    tippe_dynamics_model model;
    tippe_dynamics_initial ic;
    tippe_precession_rule rule;
    double t_end;
} launch;

typedef struct {
    long n;
    double sum_theta; /* keeps the samples "used" */
} sink;

static int take(const tippe_dynamics_sample *s, void *ctx)
{
    sink *k = ctx;
    k->n++;
    k->sum_theta += s->theta;
    return 0;
}

int main(int argc, char **argv)
{
    int repeats = argc > 1 ? atoi(argv[1]) : 5;
    if (repeats < 1)
        repeats = 1;
    launch launches[] = {
        {"fig12 hang (n 1.5)", {.top = {1, 1, 0.3, 0.92, 1, 0}, .g = 1, .mu = 0.04}, {0.01, 0, 0, 1.5, 0, 0},
         TIPPE_PRECESSION_STEADY, 10000},
        {"fig14 hang (n 0.7)", {.top = {1, 1, 0.5, 0.55, 1, 0}, .g = 1, .mu = 0.04},
         {M_PI - 0.01, 0, 0, 0.7, 0, 0}, TIPPE_PRECESSION_S3, 10000},
        {"film IIb flip", {.top = {0.006, 0.015, 0.0075, 0.82e-6, 0.7e-6, -1}, .g = 9.81, .mu = 0.3},
         {0.01, 0, 0, 250, 0, 0}, TIPPE_PRECESSION_STEADY, 90},
        /* issue 21: the M12 ball (Z2 = 15 mm), central hand launch, viscous against
         * Coulomb friction: at 15 rev/s (Coulomb: sticks and rolls) and 300 rad/s (slides
         * over: its flip takes 3 times the viscous one's model time) */
        {"M12 94 viscous", {.top = M12_TOP, .g = 9.81, .mu = 2.3}, {M12_TILT, 0, 0, 94.2477796, 0, 0},
         TIPPE_PRECESSION_STEADY, 600},
        {"M12 94 coulomb", {.top = M12_TOP, .g = 9.81, .law = TIPPE_FRICTION_COULOMB, .mu_c = 0.3},
         {M12_TILT, 0, 0, 94.2477796, 0, 0}, TIPPE_PRECESSION_STEADY, 600},
        {"M12 300 viscous", {.top = M12_TOP, .g = 9.81, .mu = 2.3}, {M12_TILT, 0, 0, 300, 0, 0},
         TIPPE_PRECESSION_STEADY, 600},
        {"M12 300 coulomb", {.top = M12_TOP, .g = 9.81, .law = TIPPE_FRICTION_COULOMB, .mu_c = 0.3},
         {M12_TILT, 0, 0, 300, 0, 0}, TIPPE_PRECESSION_STEADY, 600},
    };
    const int n_launch = (int)(sizeof launches / sizeof launches[0]);
    printf("%-20s %-9s %-10s %8s %9s %9s %10s %9s %10s %10s %8s\n", "launch", "preset", "level",
           "verdict", "t_s", "steps", "rhs_evals", "samples", "time_ms", "us/eval", "J_drift");
    for (int l = 0; l < n_launch; l++) {
        launch *L = &launches[l];
        tippe_error err;
        if (tippe_dynamics_precession(&L->model, L->ic.theta, L->ic.spin, L->rule,
                                      &L->ic.phi_dot, &err)) {
            fprintf(stderr, "%s: %s\n", L->name, err.msg);
            return 1;
        }
        for (int p = 0; p < tippe_dynamics_n_presets(); p++) {
            for (int mode = 0; mode < 3; mode++) {
                tippe_dynamics_options o;
                tippe_dynamics_options_default(&o);
                o.t_end = L->t_end;
                tippe_dynamics_accuracy_preset(tippe_dynamics_preset_name(p), &o.accuracy, NULL);
                sink k = {0, 0};
                if (mode) {
                    o.level = TIPPE_LEVEL_TRAJECTORY;
                    o.sample_dt = mode == 2 ? 1e-5 * L->t_end : 0.0;
                    o.on_sample = take;
                    o.sample_ctx = &k;
                }
                tippe_dynamics_result r;
                double best = INFINITY;
                for (int rep = 0; rep < repeats; rep++) {
                    k.n = 0;
                    double t0 = bench_now_s();
                    if (tippe_dynamics_run(&L->model, &L->ic, &o, &r, &err)) {
                        fprintf(stderr, "%s: %s\n", L->name, err.msg);
                        return 1;
                    }
                    best = fmin(best, bench_now_s() - t0);
                }
                printf("%-20s %-9s %-10s %8s %9.4g %9ld %10ld %9ld %10.3f %10.3f %8.1e\n",
                       L->name, tippe_dynamics_preset_name(p),
                       mode == 0 ? "verdict" : mode == 1 ? "traj/step" : "traj/grid",
                       tippe_verdict_name(r.verdict), r.t_verdict, r.steps, r.rhs_evals, k.n,
                       1e3 * best, 1e6 * best / (double)r.rhs_evals, r.jellett_rel_drift);
            }
        }
    }
    return 0;
}
