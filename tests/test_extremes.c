/* Numerical stability at the extremes: every case gives a correct finite answer
 * or a clear refusal, in bounded work. Eccentricity 1e-6 and 0.99 of R, A/C
 * within 1e-9 of each group boundary, launches exactly at theta = 0 and pi, spin
 * 1e4 rad/s, friction 1e-6 and 1e3 s/m, a t_end of a million periods, tops of
 * 1 mm and 1 m, and designs with a 1e-6 mm hole, a 1e-6 mm shell and the weight
 * at the very end of its travel. */
#include "tippe/design.h"
#include "tippe/physics.h"

#include "check.h"
#include "dynamics_fixtures.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

static int finite_sample(const tippe_dynamics_sample *s)
{
    return isfinite(s->t) && isfinite(s->theta) && isfinite(s->theta_dot) &&
           isfinite(s->phi_dot) && isfinite(s->spin) && isfinite(s->U) && isfinite(s->V) &&
           isfinite(s->Rn) && isfinite(s->E) && isfinite(s->J) && isfinite(s->D);
}

/* The options of the runs here: to t_end with rk8pd at rtol 1e-8 (one also tries
 * bsimp). */
static tippe_dynamics_options rk8pd(double t_end)
{
    return run_options(t_end, NULL, "rk8pd", 1e-8);
}

static void test_eccentricity(void)
{
    const double e_over_R[] = {1e-6, 0.99};
    for (int i = 0; i < 2; i++) {
        tippe_theory_class cls;
        CHECK(tippe_theory_classify(0.92, e_over_R[i], &cls) == TIPPE_OK, "classify e %g",
              e_over_R[i]);
        CHECK(!cls.has_b || isfinite(cls.b), "b %g", cls.b);
        CHECK(!cls.has_c || isfinite(cls.c), "c %g", cls.c);
        tippe_dynamics_model m = fig12(0.04);
        m.top.eps = e_over_R[i] * m.top.R;
        tippe_dynamics_initial ic = {0.5, 0, 0, 2.0, 0, 0};
        tippe_dynamics_result r;
        CHECK(run_with(&m, &ic, rk8pd(200.0), &r) == TIPPE_OK, "e %g", e_over_R[i]);
        CHECK(finite_sample(&r.last), "finite state at e %g", e_over_R[i]);
        /* rtol 1e-8 with a 100x margin, as in test_dynamics */
        CHECK(r.energy_rel_error < 1e-6 && r.jellett_rel_drift < 1e-6,
              "e %g: E+D error %g, J drift %g", e_over_R[i], r.energy_rel_error,
              r.jellett_rel_drift);
        /* energy can only decrease: at most the integration error above E0 */
        CHECK(r.energy_max_rise < 1e-6 * r.E0, "e %g: E rose by %g J", e_over_R[i],
              r.energy_max_rise);
    }
}

/* Root of b(k) = target at e (classify's b), bracketed in [lo, hi]. */
static double b_minus_target(double k, void *p)
{
    const double *a = p; /* {e, target} */
    tippe_theory_class c;
    tippe_theory_classify(k, a[0], &c);
    return c.b - a[1];
}

static int b_root(double e, double target, double lo, double hi, double *k)
{
    double a[2] = {e, target};
    gsl_function F = {b_minus_target, a};
    gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (!s || gsl_root_fsolver_set(s, &F, lo, hi) != GSL_SUCCESS) {
        gsl_root_fsolver_free(s);
        return 1;
    }
    int st = GSL_CONTINUE;
    for (int it = 0; it < 200 && st == GSL_CONTINUE; it++) {
        if (gsl_root_fsolver_iterate(s) != GSL_SUCCESS)
            break;
        st = gsl_root_test_interval(gsl_root_fsolver_x_lower(s), gsl_root_fsolver_x_upper(s),
                                    0.0, 1e-15);
    }
    *k = gsl_root_fsolver_root(s);
    gsl_root_fsolver_free(s);
    return st != GSL_SUCCESS;
}

/* Theory just off each boundary of Theorem 5.1's diagram: finite numbers, no
 * boundary named (1e-9 is far outside the 1e-12 tolerance), the two sides in
 * the groups the boundary separates, and finite predictions. eps/R = 0.3 for the
 * lines and b = 1; b = -1 exists only at small eps/R (0.05 here), once in
 * group I (Ia/Ib) and once in group II (IIa/IIc). */
static void test_group_boundaries(void)
{
    const double e = 0.3, e2 = 0.05;
    double k_b1 = NAN, k_bm1_I = NAN, k_bm1_II = NAN;
    gsl_set_error_handler_off();
    /* b = +-1 where b is real (k < 1 - e^2), by Brent */
    CHECK(!b_root(e, 1.0, 1.0 - e + 1e-6, 1.0 - e * e - 1e-6, &k_b1), "no b = 1 root");
    CHECK(!b_root(e2, -1.0, 0.5, 1.0 - e2 - 1e-6, &k_bm1_I), "no b = -1 root in I");
    CHECK(!b_root(e2, -1.0, 1.0 - e2 + 1e-6, 1.0 - e2 * e2 - 1e-6, &k_bm1_II),
          "no b = -1 root in II");
    const struct {
        const char *name;
        double e, k;
        tippe_group g1, g2; /* the groups on the two sides */
        int differ;         /* the sides must differ */
    } B[] = {
        {"A/C-1=-eps/R", e, 1.0 - e, TIPPE_GROUP_IB, TIPPE_GROUP_IIA, 1},
        {"b=1", e, k_b1, TIPPE_GROUP_IIA, TIPPE_GROUP_IIB, 1},
        /* b = 1/e > 1 on this line: IIb on both sides */
        {"A/C-1=-(eps/R)^2", e, 1.0 - e * e, TIPPE_GROUP_IIB, TIPPE_GROUP_IIB, 0},
        {"A/C-1=+eps/R", e, 1.0 + e, TIPPE_GROUP_IIB, TIPPE_GROUP_III, 1},
        {"b=-1 (I)", e2, k_bm1_I, TIPPE_GROUP_IA, TIPPE_GROUP_IB, 1},
        {"b=-1 (II)", e2, k_bm1_II, TIPPE_GROUP_IIC, TIPPE_GROUP_IIA, 1},
    };
    for (int i = 0; i < (int)(sizeof B / sizeof B[0]); i++) {
        if (!isfinite(B[i].k))
            continue;
        tippe_theory_class on;
        CHECK(tippe_theory_classify(B[i].k, B[i].e, &on) == TIPPE_OK, "%s", B[i].name);
        /* exact for the closed forms; Brent to 1e-15 in k for the b roots */
        CHECK(on.boundary != NULL, "%s: k = %.17g not reported on a boundary", B[i].name, B[i].k);
        tippe_group side_group[2];
        for (int side = 0; side < 2; side++) {
            const double k = B[i].k + (side ? 1e-9 : -1e-9);
            tippe_theory_class c;
            CHECK(tippe_theory_classify(k, B[i].e, &c) == TIPPE_OK, "%s side %d", B[i].name,
                  side);
            side_group[side] = c.group;
            CHECK(c.boundary == NULL, "%s side %d: on %s", B[i].name, side, c.boundary);
            CHECK((!c.has_b || isfinite(c.b)) && (!c.has_c || isfinite(c.c)),
                  "%s side %d: b %g c %g", B[i].name, side, c.b, c.c);
            CHECK(c.group == B[i].g1 || c.group == B[i].g2, "%s side %d: group %s", B[i].name,
                  side, tippe_group_name(c.group));
            tippe_top top = {1.0, 1.0, B[i].e, k, 1.0, 0, {0.0, 0.0}};
            tippe_theory_thresholds th;
            tippe_error err;
            CHECK(tippe_theory_compute_thresholds(&top, 1.0, &th, &err) == TIPPE_OK, "%s: %s",
                  B[i].name, err.msg);
            CHECK((!th.has_n_minus || isfinite(th.n_minus_rad_s)) &&
                      (!th.has_n_plus || isfinite(th.n_plus_rad_s)) &&
                      (!th.has_n_b || isfinite(th.n_b_0_rad_s)),
                  "%s side %d: thresholds", B[i].name, side);
            /* small to large launches: 1 or 2 finite states in [0, pi] */
            const double Js[] = {0.05, 0.5, 5.0};
            for (int j = 0; j < 3; j++) {
                tippe_theory_prediction p;
                int s = tippe_theory_predict(&top, 1.0, Js[j], &p, &err);
                int fin = s == TIPPE_OK && p.n >= 1 && p.n <= 2;
                for (int q = 0; fin && q < p.n; q++)
                    fin = isfinite(p.state[q].theta_rad) && p.state[q].theta_rad >= 0 &&
                          p.state[q].theta_rad <= M_PI;
                CHECK(fin, "%s side %d J %g: %d states", B[i].name, side, Js[j], p.n);
            }
        }
        CHECK(!B[i].differ || side_group[0] != side_group[1], "%s: %s on both sides", B[i].name,
              tippe_group_name(side_group[0]));
    }
}

/* Exactly vertical launches are relative equilibria: nothing slides, nothing
 * moves off the axis. At spin 1.5 (n- 0.82 < 1.5, n+ 1.16 < 1.5) theta = 0 is
 * unstable: E = V(0) sits on a critical value, so nothing is proved (undecided);
 * theta = pi is the stable minimum of V and is proved at once (tip at t = 0). */
static void test_vertical(void)
{
    tippe_dynamics_model m = fig12(0.04);
    const double th0[] = {0.0, M_PI};
    for (int i = 0; i < 2; i++) {
        tippe_dynamics_initial ic = {th0[i], 0, 0, 1.5, 0, 0};
        tippe_dynamics_result r;
        CHECK(run_with(&m, &ic, rk8pd(500.0), &r) == TIPPE_OK, "theta0 %g", th0[i]);
        /* exact: omega stays parallel to k, so every cross product is 0 */
        CHECK(r.last.theta == th0[i], "theta0 %g drifted to %.17g", th0[i], r.last.theta);
        CHECK(r.last.spin == 1.5 && r.last.D == 0.0, "spin %.17g D %g", r.last.spin, r.last.D);
        const tippe_verdict want = i ? TIPPE_VERDICT_TIP : TIPPE_VERDICT_UNDECIDED;
        CHECK(r.verdict == want && !r.budget_exhausted, "theta0 %g: %s", th0[i],
              tippe_verdict_name(r.verdict));
        CHECK(!i || r.t_verdict == 0.0, "theta = pi proved at t %g", r.t_verdict);
    }
}

/* The section 7.2 top at 1e4 rad/s, 40 times its hand spin. */
static void test_high_spin(void)
{
    tippe_dynamics_model m = {.top = {0.006, 0.015, 0.0075, 0.82e-6, 0.7e-6, 0}, .g = 9.81, .mu = 0.3};
    tippe_dynamics_initial ic = steady(&m, 0.1, 1e4);
    tippe_dynamics_result r;
    CHECK(run_with(&m, &ic, rk8pd(0.5), &r) == TIPPE_OK, "spin 1e4");
    CHECK(finite_sample(&r.last), "finite state at spin 1e4");
    CHECK(r.jellett_rel_drift < 1e-6 && r.energy_rel_error < 1e-6, "J drift %g, E+D %g",
          r.jellett_rel_drift, r.energy_rel_error); /* rtol 1e-8, 100x margin */
    /* the step is capped at 1/8 of the period 2 pi / W: ~8 steps per turn */
    const double W = 1e4 + sqrt(9.81 / 0.015);
    CHECK(r.steps < 4.0 * 8.0 * W * 0.5 / (2.0 * M_PI), "%ld steps", r.steps);
}

static void test_friction_extremes(void)
{
    /* mu 1e-6: sliding decays a million times slower than at 1; within 2000 s
     * nothing settles; the estimate is Theorem 5.1 for the conserved J. */
    tippe_dynamics_model m = fig12(1e-6);
    tippe_dynamics_initial ic = steady(&m, 0.01, 3.0);
    tippe_dynamics_result r;
    CHECK(run_with(&m, &ic, rk8pd(2000.0), &r) == TIPPE_OK, "mu 1e-6");
    CHECK(r.verdict == TIPPE_VERDICT_UNDECIDED && !r.budget_exhausted, "mu 1e-6: %s",
          tippe_verdict_name(r.verdict));
    CHECK(r.last.D > 0.0 && r.last.D < 1e-3 * r.E0, "dissipated %g of %g", r.last.D, r.E0);
    CHECK(r.jellett_rel_drift < 1e-6, "J drift %g", r.jellett_rel_drift); /* 100x rtol */
    tippe_theory_prediction p;
    tippe_error e;
    CHECK(tippe_theory_predict(&m.top, m.g, r.J0, &p, &e) == TIPPE_OK && p.n >= 1 &&
              p.state[0].kind == TIPPE_FINAL_TIP,
          "estimate for J0 %g", r.J0);

    /* mu 1e3: stiff (sliding relaxes in ~1e-3 s). The explicit default and the
     * implicit bsimp agree; both finish in bounded work. */
    tippe_dynamics_model ms = fig12(1e3);
    tippe_dynamics_initial is = steady(&ms, 0.01, 3.0);
    tippe_dynamics_result a, b;
    CHECK(run_with(&ms, &is, rk8pd(50.0), &a) == TIPPE_OK, "mu 1e3 rk8pd");
    CHECK(run_with(&ms, &is, run_options(50.0, NULL, "bsimp", 1e-8), &b) == TIPPE_OK,
          "mu 1e3 bsimp");
    CHECK(finite_sample(&a.last) && finite_sample(&b.last), "finite");
    /* both at rtol 1e-8; 100x margin on an O(1) angle */
    CHECK(fabs(a.last.theta - b.last.theta) < 1e-6, "theta %.12g vs %.12g", a.last.theta,
          b.last.theta);
    CHECK(a.rhs_evals < 2000000 && b.rhs_evals < 2000000, "evals %ld, %ld", a.rhs_evals,
          b.rhs_evals);
    CHECK(a.energy_max_rise < 1e-6 * a.E0, "E rose by %g J", a.energy_max_rise);
}

/* A t_end of a million periods: the run ends by settling, or, when nothing can
 * settle (mu = 0), by the step budget, and says which. */
static void test_long_t_end(void)
{
    tippe_dynamics_options o;
    tippe_dynamics_options_default(&o);
    CHECK(o.max_steps > 0, "default budget %ld", o.max_steps);
    tippe_dynamics_model m = fig12(0.04);
    tippe_dynamics_initial ic = steady(&m, 0.01, 3.0);
    const double W = 3.0 + 1.0, periods = 1e6 * 2.0 * M_PI / W;
    tippe_dynamics_result r;
    CHECK(run_with(&m, &ic, rk8pd(periods), &r) == TIPPE_OK, "1e6 periods");
    CHECK(r.verdict == TIPPE_VERDICT_TIP && !r.budget_exhausted && r.t_verdict < 1e-2 * periods,
          "%s at %g s, budget %d", tippe_verdict_name(r.verdict), r.t_verdict,
          r.budget_exhausted);
    tippe_dynamics_model m0 = fig12(0.0);
    tippe_dynamics_options budget = rk8pd(periods);
    budget.max_steps = 20000;
    CHECK(run_with(&m0, &ic, budget, &r) == TIPPE_OK, "mu 0, 1e6 periods");
    CHECK(r.budget_exhausted && r.steps == 20000 && r.verdict == TIPPE_VERDICT_UNDECIDED &&
              r.last.t < periods,
          "budget %d, %ld steps, %s at %g s", r.budget_exhausted, r.steps,
          tippe_verdict_name(r.verdict), r.last.t);
    tippe_error e;
    o.max_steps = -1;
    CHECK(tippe_dynamics_run(&m, &ic, &o, &r, &e) == TIPPE_EINPUT && strstr(e.msg, "max_steps"),
          "negative budget: %s", e.msg);
}

/* Dynamical similarity: Figure 12's flip in SI at R = 1 mm and R = 1 m, with
 * times in units of sqrt(R/g), spins in sqrt(g/R) and mu sqrt(g R) = 0.04, is
 * the dimensionless run (m = g = R = 1) rescaled. */
static void test_sizes(void)
{
    tippe_dynamics_model base = fig12(0.04);
    tippe_dynamics_initial ib = steady(&base, 0.01, 3.0);
    tippe_dynamics_result rb;
    CHECK(run_with(&base, &ib, rk8pd(10000.0), &rb) == TIPPE_OK, "base");
    const double sizes[] = {1e-3, 1.0};
    for (int i = 0; i < 2; i++) {
        const double R = sizes[i], g = 9.81, mass = 0.006, tau = sqrt(R / g);
        const double C = mass * R * R; /* same C / (m R^2) = 1 as the base */
        tippe_dynamics_model m = {.top = {mass, R, 0.3 * R, 0.92 * C, C, 0}, .g = g, .mu = 0.04 / sqrt(g * R)};
        tippe_dynamics_initial ic = steady(&m, 0.01, 3.0 / tau);
        tippe_dynamics_result r;
        CHECK(run_with(&m, &ic, rk8pd(10000.0 * tau), &r) == TIPPE_OK, "R %g", R);
        CHECK(r.verdict == rb.verdict && r.verdict == TIPPE_VERDICT_TIP, "R %g: %s", R,
              tippe_verdict_name(r.verdict));
        /* The same motion, step for step (the step control is relative to the
         * launch's scales): only rounding differs, ~1e-16 per operation. The
         * decision is a threshold test at a step (energy below a barrier, the
         * contact bound retried when the excess halves), so rounding can move it
         * by a step or two: 2 mean steps. The end angle comes from V: 1e-9. */
        CHECK(fabs(r.t_verdict / tau - rb.t_verdict) < 2.0 * rb.t_verdict / (double)rb.steps,
              "R %g: t %.15g vs %.15g", R, r.t_verdict / tau, rb.t_verdict);
        CHECK(fabs(r.theta_final_rad - rb.theta_final_rad) < 1e-9, "R %g: theta %.15g vs %.15g",
              R, r.theta_final_rad, rb.theta_final_rad);
        /* the trajectory itself, at the same model time */
        tippe_dynamics_result ra, rc;
        run_to_end(&base, &ib, rk8pd(800.0), &ra);
        run_to_end(&m, &ic, rk8pd(800.0 * tau), &rc);
        CHECK(fabs(ra.last.theta - rc.last.theta) < 1e-7, "R %g: theta(800) %.15g vs %.15g", R,
              rc.last.theta, ra.last.theta);
        CHECK(r.jellett_rel_drift < 1e-6, "R %g: J drift %g", R, r.jellett_rel_drift);
    }
}

static int physical_top(const tippe_top *t)
{
    return isfinite(t->m) && t->m > 0 && isfinite(t->R) && t->R > 0 && isfinite(t->eps) &&
           t->eps >= 0 && t->eps < t->R && isfinite(t->A) && isfinite(t->C) && t->C > 0 &&
           t->A >= 0.5 * t->C * (1 - 1e-12);
}

static void test_geometry_extremes(void)
{
    tippe_design *d = NULL;
    tippe_error e;
    tippe_top t, t_ref;
    /* a 1e-6 mm hole and screw: the top tends to the plain ABS ball, whose
     * centre of mass is its centre and whose A = C (2/5 m R^2) */
    const char *tiny[] = {"parts.hole.radius_mm=1e-6", "parts.screw.radius_mm=1e-6"};
    int s = tippe_design_load("designs/m3-setscrew.json", tiny, 2, &d, &e);
    CHECK(s == TIPPE_OK, "tiny hole: %s", e.msg);
    if (s == TIPPE_OK) {
        CHECK(tippe_design_top(d, 10.0, &t, &e) == TIPPE_OK, "%s", e.msg);
        CHECK(physical_top(&t), "m %g eps %g A %g C %g", t.m, t.eps, t.A, t.C);
        /* the removed and added volumes are ~1e-17 of the ball */
        CHECK(t.eps < 1e-9 * t.R && fabs(t.A / t.C - 1.0) < 1e-9, "eps %g A/C %.17g", t.eps,
              t.A / t.C);
        tippe_theory_class c;
        CHECK(tippe_theory_classify(t.A / t.C, t.eps / t.R, &c) == TIPPE_OK, "classify");
        tippe_design_free(d);
    }
    /* a 1e-6 mm shell: its mass vanishes, the rest of the top remains */
    const char *thin[] = {"parts.shell.thickness_mm=1e-6"};
    tippe_design *d0 = NULL;
    d = NULL;
    s = tippe_design_load("designs/shell-band.json", thin, 1, &d, &e);
    CHECK(s == TIPPE_OK, "thin shell: %s", e.msg);
    const char *ref_shell[] = {"parts.shell.thickness_mm=1e-3"};
    int s0 = tippe_design_load("designs/shell-band.json", ref_shell, 1, &d0, &e);
    if (s == TIPPE_OK && s0 == TIPPE_OK) {
        CHECK(tippe_design_top(d, 5.0, &t, &e) == TIPPE_OK, "%s", e.msg);
        CHECK(tippe_design_top(d0, 5.0, &t_ref, &e) == TIPPE_OK, "%s", e.msg);
        CHECK(physical_top(&t), "m %g eps %g A %g C %g", t.m, t.eps, t.A, t.C);
        /* the 1e-3 mm shell weighs ~4 pi R^2 1e-6 m rho ~ 1e-5 of... just more */
        CHECK(t.m < t_ref.m && t_ref.m - t.m < 1e-2 * t_ref.m, "m %g vs %g", t.m, t_ref.m);
    }
    tippe_design_free(d);
    tippe_design_free(d0);
    /* the weight at the very end of its stated travel, and just beyond */
    d = NULL;
    s = tippe_design_load("designs/shell-band.json", NULL, 0, &d, &e);
    CHECK(s == TIPPE_OK, "%s", e.msg);
    if (s == TIPPE_OK) {
        double lo, hi;
        tippe_design_travel_mm(d, &lo, &hi);
        CHECK(tippe_design_top(d, hi, &t, &e) == TIPPE_OK && physical_top(&t), "end %g: %s", hi,
              e.msg);
        CHECK(tippe_design_top(d, lo, &t, &e) == TIPPE_OK && physical_top(&t), "start %g: %s",
              lo, e.msg);
        /* design.c allows 1e-9 mm of rounding slack; 1e-6 mm beyond is refused */
        CHECK(tippe_design_top(d, hi + 1e-6, &t, &e) == TIPPE_EINPUT &&
                  strstr(e.msg, "travel"),
              "beyond the travel accepted");
        double clo, chi;
        tippe_design_contact_travel_mm(d, &clo, &chi);
        tippe_design_top_any(d, chi, &t);
        CHECK(physical_top(&t), "at contact %g mm: eps %g", chi, t.eps);
        tippe_design_free(d);
    }
}

int main(void)
{
    test_eccentricity();
    test_group_boundaries();
    test_vertical();
    test_high_spin();
    test_friction_extremes();
    test_long_t_end();
    test_sizes();
    test_geometry_extremes();
    return check_summary("test_extremes");
}
