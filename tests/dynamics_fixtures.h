/* The dynamics tests' shared fixtures: the tops they launch (the paper's
 * dimensionless tops of Figures 12 and 14, the M12 set-screw ball, Cohen's sphere),
 * the steady-precession launch, the run wrapper (options from t_end, preset,
 * stepper and rtol; a failed run prints its error), the sample buffer and its
 * callback, and the Euler-angle reference system. Included by tests/test_*.c that
 * run tippe_dynamics_run; static functions, one copy per test. Not a test itself:
 * its name stays out of the test_*.c glob in tests/CMakeLists.txt. */
#ifndef TIPPE_TESTS_DYNAMICS_FIXTURES_H
#define TIPPE_TESTS_DYNAMICS_FIXTURES_H

#include "tippe/physics.h"

#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* ---- tops ---- */

/* The paper's dimensionless top: m = g = R = C = 1, eccentricity eps/R, A/C = a,
 * viscous friction mu. */
static inline tippe_dynamics_model unit_top(double eps, double a, double mu)
{
    tippe_dynamics_model m = {.top = {1.0, 1.0, eps, a, 1.0, 0}, .g = 1.0, .mu = mu};
    return m;
}

/* Figure 12's top (group IIb): eps/R = 0.3, A/C = 0.92. */
static inline tippe_dynamics_model fig12(double mu) { return unit_top(0.3, 0.92, mu); }

/* Figure 14's top (group IIa): eps/R = 0.5, A/C = 0.55. */
static inline tippe_dynamics_model fig14(double mu) { return unit_top(0.5, 0.55, mu); }

/* The M12 set-screw ball (designs/m12-setscrew.json) with its weight at Z2 = 15 mm,
 * scaled by s (lengths s, mass s^3, inertias s^5; s = 1: the ball itself). */
static inline tippe_top m12_ball(double s)
{
    tippe_top t = {0.0768353146 * s * s * s, 0.025 * s, 0.00219013874 * s,
                   1.9053487e-05 * pow(s, 5), 1.77647865e-05 * pow(s, 5), 1, {0.0, 0.0}};
    return t;
}

/* The M12 ball's central hand launch tilts it 0.674 x 0.1 rad. */
#define M12_TILT 0.067448975019608171

/* Cohen (1977): R = 2.5 cm, I1 = I3 = 0.4 m R^2, m = 15 g, the centre of mass eps
 * from the centre (Cohen's own: 0.5 cm). */
static inline tippe_top cohen_ball(double eps)
{
    const double m = 0.015, R = 0.025, I = 0.4 * m * R * R;
    tippe_top t = {m, R, eps, I, I, -1, {0.0, 0.0}};
    return t;
}

/* A top on the table at g = 9.81 m/s^2: viscous friction mu (s/m) or, by law,
 * Coulomb's mu_c with the regularisation speed vs (m/s, 0: the default). */
static inline tippe_dynamics_model friction_model(tippe_top top, double mu,
                                                  tippe_friction_law law, double mu_c,
                                                  double vs)
{
    tippe_dynamics_model md = {.top = top, .g = 9.81, .mu = mu, .law = law, .mu_c = mu_c,
                               .slip_scale_m_s = vs};
    return md;
}

/* ---- launches ---- */

/* A launch at theta0 on the steady-precession curve (theta_dot = U = V = 0). */
static inline tippe_dynamics_initial steady(const tippe_dynamics_model *m, double theta0,
                                            double spin)
{
    tippe_dynamics_initial ic = {theta0, 0, 0, spin, 0, 0};
    tippe_error e;
    tippe_dynamics_precession(m, theta0, spin, TIPPE_PRECESSION_STEADY, &ic.phi_dot, &e);
    return ic;
}

/* The M12 ball's central hand launch at spin. */
static inline tippe_dynamics_initial m12_launch(const tippe_dynamics_model *md, double spin)
{
    return steady(md, M12_TILT, spin);
}

/* ---- runs ---- */

/* The default options to t_end, with the accuracy of preset (NULL: the default,
 * balanced), then stepper (NULL: the preset's) and rtol (0: the preset's). */
static inline tippe_dynamics_options run_options(double t_end, const char *preset,
                                                 const char *stepper, double rtol)
{
    tippe_dynamics_options o;
    tippe_dynamics_options_default(&o);
    o.t_end = t_end;
    if (preset)
        tippe_dynamics_accuracy_preset(preset, &o.accuracy, NULL);
    if (stepper)
        snprintf(o.accuracy.stepper, sizeof o.accuracy.stepper, "%s", stepper);
    if (rtol > 0)
        o.accuracy.rtol = rtol;
    return o;
}

/* One run with the options the caller filled; a failure prints its error. */
static inline int run_with(const tippe_dynamics_model *m, const tippe_dynamics_initial *ic,
                           tippe_dynamics_options o, tippe_dynamics_result *r)
{
    tippe_error e;
    int s = tippe_dynamics_run(m, ic, &o, r, &e);
    if (s)
        printf("  run failed: %s\n", e.msg);
    return s;
}

/* To t_end at a preset's accuracy. */
static inline int run(const tippe_dynamics_model *m, const tippe_dynamics_initial *ic,
                      double t_end, const char *preset, tippe_dynamics_result *r)
{
    return run_with(m, ic, run_options(t_end, preset, NULL, 0.0), r);
}

/* Integrates on past any verdict to o's t_end (the reference runs). */
static inline int run_to_end(const tippe_dynamics_model *m, const tippe_dynamics_initial *ic,
                             tippe_dynamics_options o, tippe_dynamics_result *r)
{
    o.run_to_t_end = 1;
    return run_with(m, ic, o, r);
}

/* ---- samples ---- */

typedef struct {
    int n, cap;
    tippe_dynamics_sample *s;
} sample_buf;

/* The sample callback: appends to the sample_buf at ctx (free its s). */
static inline int collect(const tippe_dynamics_sample *s, void *ctx)
{
    sample_buf *b = ctx;
    if (b->n == b->cap) {
        b->cap = b->cap ? 2 * b->cap : 256;
        b->s = realloc(b->s, (size_t)b->cap * sizeof *b->s);
        if (!b->s)
            return 1;
    }
    b->s[b->n++] = *s;
    return 0;
}

/* The trajectory to t_end (on past any verdict) into b, a sample every dt seconds
 * (0: every step), at preset's accuracy (NULL: the default). */
static inline int run_samples(const tippe_dynamics_model *m, const tippe_dynamics_initial *ic,
                              double t_end, double dt, const char *preset, sample_buf *b,
                              tippe_dynamics_result *r)
{
    tippe_dynamics_options o = run_options(t_end, preset, NULL, 0.0);
    o.level = TIPPE_LEVEL_TRAJECTORY;
    o.sample_dt = dt;
    o.on_sample = collect;
    o.sample_ctx = b;
    return run_to_end(m, ic, o, r);
}

/* The Euler-angle reference form (eqs 3.15-3.19) as a GSL odeiv2 system; p is the
 * tippe_dynamics_model. */
static inline int euler_sys(double t, const double y[], double f[], void *p)
{
    (void)t;
    return tippe_dynamics_euler_rhs(p, y, f, NULL) == TIPPE_OK ? GSL_SUCCESS : GSL_EBADFUNC;
}

#endif
