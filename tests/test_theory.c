/* Tests of the theory module against the definitions of Ciocci et al. 2012,
 * section 5, Theorem 5.1, Appendix A and section 7.1. The inequalities and
 * equations are re-derived here independently of src/physics/theory.c where possible. */
#include "tippe/physics.h"

#include "check.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>
#include <gsl/gsl_roots.h>

static double rel_diff(double a, double b)
{
    double s = fmax(fabs(a), fabs(b));
    return s == 0.0 ? 0.0 : fabs(a - b) / s;
}

/* b of eq 5.11, written out again here from the paper. */
static double b_of(double k, double e)
{
    return (e - sqrt(k * (1.0 - k - e * e) / 3.0)) / (1.0 - k);
}

/* The strict inequalities of Theorem 5.1 for each subgroup. */
static int in_group(tippe_group g, double k, double e)
{
    double d = k - 1.0;
    int I = d < -e, II = -e < d && d < e, III = d > e;
    switch (g) {
    case TIPPE_GROUP_IA:
        return I && b_of(k, e) < -1.0;
    case TIPPE_GROUP_IB:
        return I && b_of(k, e) > -1.0;
    case TIPPE_GROUP_IIA:
        return II && d < -e * e && fabs(b_of(k, e)) < 1.0;
    case TIPPE_GROUP_IIB:
        return II && (d > -e * e || b_of(k, e) > 1.0);
    case TIPPE_GROUP_IIC:
        return II && d < -e * e && b_of(k, e) < -1.0;
    case TIPPE_GROUP_III:
        return III;
    }
    return 0;
}

/* Dimensionless J^2 / (m g C R^3) on the curve of eq 5.10 as a function of
 * x = cos(theta), continued to any x where eq 5.7 holds (the fold b may lie
 * outside [-1, 1]). Built from 5.4, 5.6 and 3.22, not from theory.c. */
typedef struct {
    double k, e;
} ke;

static double f_curve(double x, void *p)
{
    const ke *q = p;
    double alpha2 = q->e / ((q->k - 1.0) * x + q->e);          /* 5.6, m g = C = R = 1 */
    double Jr = (x - q->e) * (x - q->e) + q->k * (1.0 - x * x); /* 3.22 with 5.4 */
    return alpha2 * Jr * Jr;
}

/* The tops chosen inside each subgroup (Figure 12 and 14 tops from the paper; the
 * others picked from the inequalities and checked against them below). */
typedef struct {
    const char *why;
    double k, e;
} pick;

static const pick picks[] = {
    {"Figure 12 top", 0.92, 0.3},  {"Figure 14 top", 0.55, 0.5},
    {"small eps, k near 1-e", 0.9, 0.05}, {"k well below 1-e", 0.6, 0.3},
    {"small eps inside II", 0.955, 0.05}, {"below the -e^2 line, b > 1", 0.88, 0.3},
    {"k - 1 > e", 1.5, 0.3},       {"IIa with n- above n+", 0.51, 0.5},
};
static const int n_picks = (int)(sizeof picks / sizeof picks[0]);

static tippe_top unit_top(double k, double e)
{
    /* m = g = C = R = 1 as in the paper's Figures 12-14 */
    tippe_top t = {1.0, 1.0, e, k, 1.0, e > 0 ? -1 : 0, {0.0, 0.0}};
    return t;
}

static void test_groups(void)
{
    int reached[6] = {0};
    for (int i = 0; i < n_picks; i++) {
        tippe_theory_class c;
        int rc = tippe_theory_classify(picks[i].k, picks[i].e, &c);
        CHECK(rc == TIPPE_OK, "%s: rc %d", picks[i].why, rc);
        CHECK(c.boundary == NULL, "%s: on boundary %s", picks[i].why, c.boundary);
        CHECK(in_group(c.group, picks[i].k, picks[i].e), "%s (k=%g, e=%g): group %s violates "
              "Theorem 5.1's inequalities", picks[i].why, picks[i].k, picks[i].e,
              tippe_group_name(c.group));
        reached[c.group] = 1;
    }
    for (int g = 0; g < 6; g++)
        CHECK(reached[g], "no pick reached group %s", tippe_group_name((tippe_group)g));

    /* The paper names the group of these two tops (sections 7.1). */
    tippe_theory_class c;
    tippe_theory_classify(0.92, 0.3, &c);
    CHECK(c.group == TIPPE_GROUP_IIB, "Figure 12 top is %s, paper says IIb", tippe_group_name(c.group));
    tippe_theory_classify(0.55, 0.5, &c);
    CHECK(c.group == TIPPE_GROUP_IIA, "Figure 14 top is %s, paper says IIa", tippe_group_name(c.group));

    /* A grid over the phase diagram of Figure 2 (irrational steps, so that no
     * node falls on a boundary): every group satisfies its inequalities. */
    int bad = 0, on_boundary = 0, nodes = 0;
    for (double k = 0.0123; k < 2.0; k += 0.0137 * M_SQRT2)
        for (double e = 0.0031; e < 1.0; e += 0.0071 * M_SQRT2) {
            nodes++;
            if (tippe_theory_classify(k, e, &c) != TIPPE_OK) {
                bad++;
                continue;
            }
            if (c.boundary) {
                on_boundary++;
                continue;
            }
            if (!in_group(c.group, k, e)) {
                if (bad < 5)
                    printf("  grid k=%.17g e=%.17g -> %s\n", k, e, tippe_group_name(c.group));
                bad++;
            }
        }
    CHECK(bad == 0, "%d of %d grid nodes violate the inequalities", bad, nodes);
    CHECK(on_boundary == 0, "%d grid nodes reported on a boundary", on_boundary);

    /* invalid input */
    CHECK(tippe_theory_classify(0.0, 0.3, &c) == TIPPE_EINPUT, "k = 0 accepted");
    CHECK(tippe_theory_classify(0.9, 1.0, &c) == TIPPE_EINPUT, "e = 1 accepted");
    CHECK(tippe_theory_classify(0.9, -0.1, &c) == TIPPE_EINPUT, "e < 0 accepted");
    CHECK(tippe_theory_classify(NAN, 0.1, &c) == TIPPE_EINPUT, "NaN accepted");
}

/* The rule "a branch is stable where J^2 increases with theta", evaluated by finite
 * differences of the curve, against Theorem 5.1 as branch_stable() states it. */
static void test_stability_rule(void)
{
    for (int i = 0; i < n_picks; i++) {
        double k = picks[i].k, e = picks[i].e;
        tippe_theory_class c;
        tippe_theory_classify(k, e, &c);
        int mismatch = 0, n_stable = 0, n_unstable = 0, n = 0;
        const double h = 1e-5;
        for (int j = 1; j < 2000; j++) {
            double th = M_PI * j / 2000.0, jm, jp;
            if (c.has_theta_b && fabs(th - c.theta_b_rad) < 1e-2)
                continue; /* dJ^2/dtheta vanishes at the fold: sign not resolvable */
            if (tippe_theory_curve_j2(k, e, th - h, &jm) || tippe_theory_curve_j2(k, e, th + h, &jp))
                continue; /* no intermediate state (eq 5.7) */
            n++;
            int rises = jp > jm;
            int stable = tippe_theory_branch_stable(&c, th);
            mismatch += rises != stable;
            n_stable += stable;
            n_unstable += !stable;
        }
        CHECK(n > 100 && mismatch == 0, "%s (%s): %d of %d points where the J^2 rule and "
              "Theorem 5.1 disagree", picks[i].why, tippe_group_name(c.group), mismatch, n);
        if (c.group == TIPPE_GROUP_IB || c.group == TIPPE_GROUP_IIA)
            CHECK(n_stable > 0 && n_unstable > 0, "%s: fold not inside the branch", picks[i].why);
    }
}

/* b is the fold of J^2 in cos(theta): find the minimum of F(x) numerically. */
static void test_fold(void)
{
    gsl_set_error_handler_off();
    for (int i = 0; i < n_picks; i++) {
        double k = picks[i].k, e = picks[i].e;
        tippe_theory_class c;
        tippe_theory_classify(k, e, &c);
        if (!c.has_b)
            continue;
        ke p = {k, e};
        /* F is finite for x < c (eq 5.7 with k < 1); scan for a bracket */
        double x_hi = fmin(e / (1.0 - k), 4.0) - 1e-6, x_lo = -4.0;
        int nsc = 4000, jmin = 0;
        double fmin_val = INFINITY;
        for (int j = 0; j <= nsc; j++) {
            double x = x_lo + (x_hi - x_lo) * j / nsc, f = f_curve(x, &p);
            if (f < fmin_val) {
                fmin_val = f;
                jmin = j;
            }
        }
        CHECK(jmin > 0 && jmin < nsc, "%s: no interior minimum of J^2 in cos(theta)", picks[i].why);
        if (!(jmin > 0 && jmin < nsc))
            continue;
        double a = x_lo + (x_hi - x_lo) * (jmin - 1) / nsc, z = x_lo + (x_hi - x_lo) * (jmin + 1) / nsc;
        double m = x_lo + (x_hi - x_lo) * jmin / nsc;
        gsl_function F = {f_curve, &p};
        gsl_min_fminimizer *s = gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent);
        int status = gsl_min_fminimizer_set(s, &F, m, a, z);
        for (int it = 0; status == GSL_SUCCESS && it < 200; it++) {
            status = gsl_min_fminimizer_iterate(s);
            if (status)
                break;
            status = gsl_min_test_interval(gsl_min_fminimizer_x_lower(s),
                                           gsl_min_fminimizer_x_upper(s), 1e-12, 0.0);
            if (status == GSL_SUCCESS)
                break;
            status = GSL_SUCCESS;
        }
        double xm = gsl_min_fminimizer_x_minimum(s);
        gsl_min_fminimizer_free(s);
        CHECK(status == GSL_SUCCESS, "%s: minimiser failed", picks[i].why);
        /* A quadratic minimum is located only to ~sqrt(DBL_EPSILON) ~ 1.5e-8 in x
         * (F is flat to rounding there); 1e-6 leaves a factor of 60. */
        CHECK(fabs(xm - c.b) < 1e-6, "%s: numerical fold x = %.12g, closed-form b = %.12g",
              picks[i].why, xm, c.b);
        if (c.has_theta_b) /* acos amplifies by 1/sin(theta_b) <= ~3 here */
            CHECK(fabs(acos(xm) - c.theta_b_rad) < 1e-5, "%s: theta_b %.12g vs %.12g",
                  picks[i].why, acos(xm), c.theta_b_rad);
    }
}

static void test_thresholds(void)
{
    const double g = 1.0;
    for (int i = 0; i < n_picks; i++) {
        double k = picks[i].k, e = picks[i].e;
        tippe_top t = unit_top(k, e);
        tippe_theory_thresholds th;
        tippe_error err = {0};
        int rc = tippe_theory_compute_thresholds(&t, g, &th, &err);
        CHECK(rc == TIPPE_OK, "%s: %s", picks[i].why, err.msg);
        double j2;
        /* The test's own curve agrees with the library's (same formula, different
         * algebra: rounding only). */
        for (double th_ = 0.3; th_ < 3.0; th_ += 0.7)
            if (tippe_theory_curve_j2(k, e, th_, &j2) == TIPPE_OK) {
                ke p = {k, e};
                CHECK(rel_diff(j2, f_curve(cos(th_), &p)) < 1e-12, "%s: curve %g vs %g",
                      picks[i].why, j2, f_curve(cos(th_), &p));
            }
        /* group I has no finite n-; group III no n+ */
        CHECK(th.has_n_minus == (k - 1.0 > -e), "%s: has_n_minus", picks[i].why);
        CHECK(th.has_n_plus == (k - 1.0 < e), "%s: has_n_plus", picks[i].why);
        /* The curve meets theta = 0 at n0 = n- (closed forms; rounding only: 1e-12) */
        if (th.has_n_minus) {
            CHECK(tippe_theory_curve_j2(k, e, 0.0, &j2) == TIPPE_OK, "%s: curve at 0", picks[i].why);
            double n0 = tippe_theory_n0(&t, sqrt(j2)); /* J = sqrt(j2) with m g C R^3 = 1 */
            CHECK(rel_diff(n0, th.n_minus_rad_s) < 1e-12, "%s: curve at theta=0 has n0 = %.15g, "
                  "n- = %.15g", picks[i].why, n0, th.n_minus_rad_s);
            /* Jellett of the vertical state theta = 0 spinning at n- (any phi_dot) */
            double J = tippe_theory_jellett(&t, 0.0, 0.37, th.n_minus_rad_s);
            CHECK(rel_diff(J, th.J_minus) < 1e-12, "%s: J(n-) %g vs %g", picks[i].why, J, th.J_minus);
        }
        /* ... and theta = pi at |n_pi| = n+ */
        if (th.has_n_plus) {
            CHECK(tippe_theory_curve_j2(k, e, M_PI, &j2) == TIPPE_OK, "%s: curve at pi", picks[i].why);
            double npi = tippe_theory_npi(&t, sqrt(j2));
            CHECK(rel_diff(-npi, th.n_plus_rad_s) < 1e-12, "%s: curve at theta=pi has |n_pi| = "
                  "%.15g, n+ = %.15g", picks[i].why, -npi, th.n_plus_rad_s);
            /* sin(pi)^2 ~ 1e-32 leaves the phi_dot term at rounding level */
            double J = tippe_theory_jellett(&t, M_PI, 0.37, -th.n_plus_rad_s);
            CHECK(rel_diff(J, th.J_plus) < 1e-12, "%s: J(n+) %g vs %g", picks[i].why, J, th.J_plus);
            /* n*: the spin at theta = 0 with the J that puts theta = pi at n+ */
            CHECK(th.has_n_star, "%s: no n*", picks[i].why);
            double Js = tippe_theory_jellett(&t, 0.0, 0.0, th.n_star_rad_s);
            CHECK(rel_diff(-tippe_theory_npi(&t, Js), th.n_plus_rad_s) < 1e-12,
                  "%s: n* does not map to n+", picks[i].why);
            /* A.24: n+ >= 2 sqrt(A m g eps) / C in groups I and II */
            double n_hat = 2.0 * sqrt(t.A * t.m * g * t.eps) / t.C;
            CHECK(th.n_plus_rad_s >= n_hat * (1.0 - 1e-12), "%s: n+ %g < n_hat %g (A.24)",
                  picks[i].why, th.n_plus_rad_s, n_hat);
        }
        /* n_b: J on the curve at the fold, seen from theta = 0 and theta = pi */
        int want_nb = th.cls.group == TIPPE_GROUP_IB || th.cls.group == TIPPE_GROUP_IIA;
        CHECK(th.has_n_b == want_nb, "%s: has_n_b = %d", picks[i].why, th.has_n_b);
        if (th.has_n_b) {
            tippe_theory_state st;
            rc = tippe_theory_intermediate(&t, g, th.cls.theta_b_rad, 1, &st, &err);
            CHECK(rc == TIPPE_OK && rel_diff(st.J, th.J_b) < 1e-12, "%s: J_b %g vs curve %g",
                  picks[i].why, th.J_b, st.J);
            CHECK(rel_diff(tippe_theory_jellett(&t, 0.0, 0.0, th.n_b_0_rad_s), th.J_b) < 1e-12,
                  "%s: n_b at theta=0", picks[i].why);
            CHECK(rel_diff(tippe_theory_jellett(&t, M_PI, 0.0, -th.n_b_pi_rad_s), th.J_b) < 1e-12,
                  "%s: n_b at theta=pi", picks[i].why);
        }
    }
    /* A.24 with equality at A/C = (1 + e)/2 */
    for (double e = 0.1; e < 0.95; e += 0.2) {
        tippe_top t = unit_top(0.5 * (1.0 + e), e);
        tippe_theory_thresholds th;
        tippe_theory_compute_thresholds(&t, 1.0, &th, NULL);
        double n_hat = 2.0 * sqrt(t.A * t.m * t.eps) / t.C;
        CHECK(rel_diff(th.n_plus_rad_s, n_hat) < 1e-12, "e=%g: n+ %.15g != n_hat %.15g at "
              "k=(1+e)/2", e, th.n_plus_rad_s, n_hat);
    }
}

/* Intermediate states are relative equilibria with the Jellett they claim. */
static void test_intermediate_states(void)
{
    /* an SI top too, so that a unit slip would show: 60 g, R = 25 mm */
    const double g = 9.81;
    for (int i = 0; i < n_picks; i++) {
        double k = picks[i].k, e = picks[i].e;
        tippe_top t = {0.06, 0.025, e * 0.025, k * 1.2e-5, 1.2e-5, -1, {0.0, 0.0}};
        for (double th = 0.2; th < 3.1; th += 0.45) {
            tippe_theory_state s, r;
            tippe_error err = {0};
            int rc = tippe_theory_intermediate(&t, g, th, 1, &s, &err);
            if (!tippe_theory_exists(k, e, th)) {
                CHECK(rc == TIPPE_EINPUT, "%s: state at %g where 5.7 fails", picks[i].why, th);
                continue;
            }
            CHECK(rc == TIPPE_OK, "%s: %s", picks[i].why, err.msg);
            double a = s.phi_dot_rad_s, n = s.spin_rad_s;
            /* theta equation of 3.15 at rest (5.5): alpha (A alpha cos - C n) = m g eps */
            double lhs = a * (t.A * a * cos(th) - t.C * n), rhs = t.m * g * t.eps;
            CHECK(rel_diff(lhs, rhs) < 1e-12, "%s th=%g: 5.5 gives %g vs %g", picks[i].why, th,
                  lhs, rhs);
            /* rolling at the contact (Y component of 3.9 with V = 0); scale a R */
            double vq = sin(th) * (a * t.eps + t.R * (n - a * cos(th)));
            CHECK(fabs(vq) < 1e-12 * fabs(a) * t.R, "%s th=%g: contact slips, V_Q = %g",
                  picks[i].why, th, vq);
            double J = tippe_theory_jellett(&t, th, a, n);
            CHECK(rel_diff(J, s.J) < 1e-12, "%s th=%g: Jellett %g vs curve %g", picks[i].why,
                  th, J, s.J);
            /* symmetry (n, alpha) -> (-n, -alpha) flips J and nothing else */
            tippe_theory_intermediate(&t, g, th, -1, &r, &err);
            CHECK(r.phi_dot_rad_s == -a && r.spin_rad_s == -n && r.J == -s.J &&
                  tippe_theory_jellett(&t, th, -a, -n) == -J, "%s th=%g: symmetry", picks[i].why, th);
        }
    }
}

/* Boundaries: exactly on (as near as doubles allow) and 1e-9 to either side in k. */
typedef struct {
    double e;
    int kind; /* 0: I/II, 1: II/III, 2: -e^2 line, 3: b = 1, 4: b = -1 in II, 5: b = -1 in I */
} bcase;

static double b_minus(double k, void *p)
{
    return b_of(k, *(double *)p) - ((double *)p)[1];
}

/* k in (lo, hi) with b(k, e) = target, by GSL Brent on the test's own b. */
static double k_for_b(double e, double target, double lo, double hi, int *ok)
{
    double p[2] = {e, target};
    gsl_function f = {b_minus, p};
    /* scan for a sign change first: b need not be monotone over (lo, hi) */
    int n = 400;
    double a = lo, fa = b_minus(lo, p);
    *ok = 0;
    for (int j = 1; j <= n; j++) {
        double z = lo + (hi - lo) * j / n, fz = b_minus(z, p);
        if ((fa < 0) != (fz < 0)) {
            gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
            gsl_root_fsolver_set(s, &f, a, z);
            for (int it = 0; it < 200; it++) {
                gsl_root_fsolver_iterate(s);
                if (gsl_root_test_interval(gsl_root_fsolver_x_lower(s), gsl_root_fsolver_x_upper(s),
                                           0.0, 1e-16) == GSL_SUCCESS)
                    break;
            }
            double k = gsl_root_fsolver_root(s);
            gsl_root_fsolver_free(s);
            *ok = 1;
            return k;
        }
        a = z;
        fa = fz;
    }
    return lo;
}

static int finite_class(const tippe_theory_class *c)
{
    return isfinite(c->A_over_C) && isfinite(c->eps_over_R) && isfinite(c->b) &&
           isfinite(c->theta_b_rad) && isfinite(c->c) && isfinite(c->theta_c_rad);
}

static int finite_thresholds(const tippe_theory_thresholds *t)
{
    return isfinite(t->n_minus_rad_s) && isfinite(t->n_plus_rad_s) && isfinite(t->n_star_rad_s) &&
           isfinite(t->n_b_0_rad_s) && isfinite(t->n_b_pi_rad_s) && isfinite(t->J_minus) &&
           isfinite(t->J_plus) && isfinite(t->J_b) && finite_class(&t->cls);
}

/* predict() at a few J gives 1 or 2 finite states. */
static int predict_sane(double k, double e, const char *what)
{
    tippe_top t = unit_top(k, e);
    int ok = 1;
    for (double J = 0.01; J < 300.0; J *= 3.7) {
        for (int sgn = -1; sgn <= 1; sgn += 2) {
            tippe_theory_prediction p;
            tippe_error err = {0};
            int rc = tippe_theory_predict(&t, 1.0, sgn * J, &p, &err);
            int good = rc == TIPPE_OK && p.n >= 1 && p.n <= 2;
            for (int i = 0; good && i < p.n; i++)
                good = isfinite(p.state[i].theta_rad) && p.state[i].theta_rad >= 0.0 &&
                       p.state[i].theta_rad <= M_PI && isfinite(p.state[i].spin_rad_s) &&
                       isfinite(p.state[i].phi_dot_rad_s);
            if (!good) {
                printf("  %s k=%.17g e=%.17g J=%g: rc %d n %d %s\n", what, k, e, sgn * J, rc,
                       rc ? 0 : p.n, err.msg);
                ok = 0;
            }
        }
    }
    return ok;
}

static void test_boundaries(void)
{
    static const char *const names[] = {"A/C-1=-eps/R", "A/C-1=+eps/R", "A/C-1=-(eps/R)^2",
                                        "b=1", "b=-1", "b=-1"};
    static const double es[] = {0.05, 0.3, 0.5, 0.9};
    const double d = 1e-9;
    int cases = 0;
    for (int ie = 0; ie < 4; ie++)
        for (int kind = 0; kind < 6; kind++) {
            double e = es[ie], k = 0.0;
            int ok = 1;
            switch (kind) {
            case 0: k = 1.0 - e; break;
            case 1: k = 1.0 + e; break;
            case 2: k = 1.0 - e * e; break;
            case 3: k = k_for_b(e, 1.0, 1.0 - e + 1e-7, 1.0 - e * e - 1e-7, &ok); break;
            case 4: k = k_for_b(e, -1.0, 1.0 - e + 1e-7, 1.0 - e * e - 1e-7, &ok); break;
            case 5: k = k_for_b(e, -1.0, 1e-6, 1.0 - e - 1e-7, &ok); break;
            }
            if (!ok)
                continue; /* this boundary does not exist at this e (b = -1 needs small e) */
            cases++;
            tippe_theory_class on, lo, hi;
            CHECK(tippe_theory_classify(k, e, &on) == TIPPE_OK && finite_class(&on),
                  "%s e=%g: not finite", names[kind], e);
            CHECK(on.boundary && !strcmp(on.boundary, names[kind]), "e=%g k=%.17g: boundary %s, "
                  "expected %s", e, k, on.boundary ? on.boundary : "(none)", names[kind]);
            tippe_theory_classify(k - d, e, &lo);
            tippe_theory_classify(k + d, e, &hi);
            CHECK(!lo.boundary && !hi.boundary && finite_class(&lo) && finite_class(&hi),
                  "%s e=%g: 1e-9 away still on a boundary", names[kind], e);
            CHECK(in_group(lo.group, k - d, e) && in_group(hi.group, k + d, e),
                  "%s e=%g: groups %s / %s beside the boundary violate the inequalities",
                  names[kind], e, tippe_group_name(lo.group), tippe_group_name(hi.group));
            CHECK(on.group == lo.group || on.group == hi.group, "%s e=%g: on-boundary group %s "
                  "is neither side (%s, %s)", names[kind], e, tippe_group_name(on.group),
                  tippe_group_name(lo.group), tippe_group_name(hi.group));
            /* the documented side (theory.h) */
            static const char *const fam[] = {"I", "III", "II", "II", "II", "I"};
            CHECK(!strcmp(tippe_group_family(on.group), fam[kind]), "%s e=%g: family %s",
                  names[kind], e, tippe_group_family(on.group));
            if (kind >= 2 && kind <= 4) {
                tippe_group want = kind == 4 ? TIPPE_GROUP_IIC : TIPPE_GROUP_IIB;
                CHECK(on.group == want, "%s e=%g: group %s", names[kind], e,
                      tippe_group_name(on.group));
            }
            if (kind == 5)
                CHECK(on.group == TIPPE_GROUP_IA, "b=-1 in I, e=%g: group %s", e,
                      tippe_group_name(on.group));
            tippe_top t = unit_top(k, e);
            tippe_theory_thresholds th;
            CHECK(tippe_theory_compute_thresholds(&t, 1.0, &th, NULL) == TIPPE_OK &&
                  finite_thresholds(&th), "%s e=%g: thresholds not finite", names[kind], e);
            CHECK(predict_sane(k, e, names[kind]) && predict_sane(k - d, e, names[kind]) &&
                  predict_sane(k + d, e, names[kind]), "%s e=%g: predict", names[kind], e);
        }
    /* b = -1 exists in II only for e < 7 - 4 sqrt(3), in I only for small e too */
    CHECK(cases >= 4 * 4 + 2, "only %d boundary cases found", cases);

    /* The point where k - 1 = -e and b = -1 meet: (1 - e) = 2 sqrt(3 e). */
    {
        double e = 7.0 - 4.0 * sqrt(3.0), k = 1.0 - e;
        tippe_theory_class c;
        tippe_theory_classify(k, e, &c);
        CHECK(c.boundary && !strcmp(c.boundary, "A/C-1=-eps/R,b=-1") && c.group == TIPPE_GROUP_IA,
              "triple point: %s %s", c.boundary ? c.boundary : "(none)", tippe_group_name(c.group));
    }

    /* Degenerate tops: balanced ball, A = C, e -> 1, k -> 0 */
    static const struct {
        double k, e;
        const char *boundary;
    } deg[] = {{0.5, 0.0, "eps/R=0"}, {1.0, 0.0, "eps/R=0"}, {1.5, 0.0, "eps/R=0"},
               {0.9, 1e-13, "eps/R=0"}, {1.0, 0.3, NULL}, {0.5, 1.0 - 1e-9, NULL},
               {1.0, 1.0 - 1e-9, NULL}, {1.7, 1.0 - 1e-12, NULL}, {1e-10, 1.0 - 1e-9, NULL},
               {1e-9, 0.5, NULL}};
    for (size_t i = 0; i < sizeof deg / sizeof deg[0]; i++) {
        tippe_theory_class c;
        int rc = tippe_theory_classify(deg[i].k, deg[i].e, &c);
        CHECK(rc == TIPPE_OK && finite_class(&c), "k=%g e=%g: rc %d or not finite", deg[i].k,
              deg[i].e, rc);
        CHECK((c.boundary == NULL) == (deg[i].boundary == NULL) &&
              (!c.boundary || !strcmp(c.boundary, deg[i].boundary)),
              "k=%g e=%g: boundary %s", deg[i].k, deg[i].e, c.boundary ? c.boundary : "(none)");
        if (!c.boundary)
            CHECK(in_group(c.group, deg[i].k, deg[i].e), "k=%g e=%g: group %s", deg[i].k,
                  deg[i].e, tippe_group_name(c.group));
        tippe_top t = unit_top(deg[i].k, deg[i].e);
        tippe_theory_thresholds th;
        CHECK(tippe_theory_compute_thresholds(&t, 1.0, &th, NULL) == TIPPE_OK &&
              finite_thresholds(&th), "k=%g e=%g: thresholds", deg[i].k, deg[i].e);
        if (!(deg[i].e == 0.0 && deg[i].k == 1.0))
            CHECK(predict_sane(deg[i].k, deg[i].e, "degenerate"), "k=%g e=%g: predict",
                  deg[i].k, deg[i].e);
    }
    tippe_theory_class c;
    tippe_theory_classify(1.0, 0.3, &c);
    CHECK(c.group == TIPPE_GROUP_IIB && !c.has_b && !c.has_c, "A = C: group %s has_b %d has_c %d",
          tippe_group_name(c.group), c.has_b, c.has_c);

    /* Balanced ball: no preferred side (both vertical states for k < 1), a transverse
     * spin for k > 1, and no answer where every orientation is neutral. */
    tippe_theory_prediction p;
    tippe_top t = unit_top(0.8, 0.0);
    CHECK(tippe_theory_predict(&t, 1.0, 2.0, &p, NULL) == TIPPE_OK && p.n == 2 &&
          p.state[0].kind == TIPPE_FINAL_NO_TIP && p.state[1].kind == TIPPE_FINAL_TIP,
          "balanced ball, k < 1: %d states", p.n);
    t = unit_top(1.3, 0.0);
    CHECK(tippe_theory_predict(&t, 1.0, 2.0, &p, NULL) == TIPPE_OK && p.n == 1 &&
          p.state[0].kind == TIPPE_FINAL_HANG && fabs(p.state[0].theta_rad - M_PI / 2) < 1e-15 &&
          rel_diff(tippe_theory_jellett(&t, M_PI / 2, p.state[0].phi_dot_rad_s,
                                        p.state[0].spin_rad_s), 2.0) < 1e-12,
          "balanced ball, k > 1");
    tippe_error err = {0};
    t = unit_top(1.0, 0.0);
    CHECK(tippe_theory_predict(&t, 1.0, 2.0, &p, &err) == TIPPE_EINPUT && strstr(err.msg, "neutral"),
          "balanced sphere with A = C: %s", err.msg);
    t = unit_top(0.8, 0.0);
    CHECK(tippe_theory_predict(&t, 1.0, 0.0, &p, &err) == TIPPE_EINPUT, "balanced ball, J = 0");
    t = unit_top(0.8, 1.0);
    CHECK(tippe_theory_predict(&t, 1.0, 1.0, &p, &err) == TIPPE_EINPUT && strstr(err.msg, "eps"),
          "eps = R accepted: %s", err.msg);
}

/* Kinds in a prediction as a string such as "no_tip+hang". */
static void kinds(const tippe_theory_prediction *p, char *buf, size_t n)
{
    buf[0] = 0;
    for (int i = 0; i < p->n; i++) {
        if (i)
            strncat(buf, "+", n - strlen(buf) - 1);
        strncat(buf, tippe_final_kind_name(p->state[i].kind), n - strlen(buf) - 1);
    }
}

/* predict() at J just below/above each threshold: the states Theorem 5.1 says. */
typedef struct {
    const char *why;
    double k, e;
    const char *what; /* which threshold: "n-", "n+", "nb" */
    double factor;    /* J = factor * J(threshold) */
    const char *want; /* the states, from Theorem 5.1 and the group's diagram (Figure 3) */
} pcase;

static const pcase pcases[] = {
    /* IIb: theta = 0 stable below n-, the rising branch between, theta = pi above n+ */
    {"IIb (Fig 12)", 0.92, 0.3, "n-", 1 - 1e-6, "no_tip"},
    {"IIb (Fig 12)", 0.92, 0.3, "n-", 1 + 1e-6, "hang"},
    {"IIb (Fig 12)", 0.92, 0.3, "n+", 1 - 1e-6, "hang"},
    {"IIb (Fig 12)", 0.92, 0.3, "n+", 1 + 1e-6, "tip"},
    {"IIb (b > 1)", 0.88, 0.3, "n-", 1 + 1e-6, "hang"},
    {"IIb (b > 1)", 0.88, 0.3, "n+", 1 + 1e-6, "tip"},
    /* III: never tips fully; above n- it hangs below theta_c */
    {"III", 1.5, 0.3, "n-", 1 - 1e-6, "no_tip"},
    {"III", 1.5, 0.3, "n-", 1 + 1e-6, "hang"},
    {"III", 1.5, 0.3, "n-", 1e3, "hang"},
    /* Ib: theta = 0 always stable; stable branch theta > theta_b from n_b to n+ */
    {"Ib", 0.6, 0.3, "nb", 1 - 1e-6, "no_tip"},
    {"Ib", 0.6, 0.3, "nb", 1 + 1e-6, "no_tip+hang"},
    {"Ib", 0.6, 0.3, "n+", 1 - 1e-6, "no_tip+hang"},
    {"Ib", 0.6, 0.3, "n+", 1 + 1e-6, "no_tip+tip"},
    /* Ia: no stable intermediate state */
    {"Ia", 0.9, 0.05, "n+", 1 - 1e-6, "no_tip"},
    {"Ia", 0.9, 0.05, "n+", 1 + 1e-6, "no_tip+tip"},
    /* IIa (Fig 14, n_b < n- < n+ in J) */
    {"IIa (Fig 14)", 0.55, 0.5, "nb", 1 - 1e-6, "no_tip"},
    {"IIa (Fig 14)", 0.55, 0.5, "nb", 1 + 1e-6, "no_tip+hang"},
    {"IIa (Fig 14)", 0.55, 0.5, "n-", 1 - 1e-6, "no_tip+hang"},
    {"IIa (Fig 14)", 0.55, 0.5, "n-", 1 + 1e-6, "hang"},
    {"IIa (Fig 14)", 0.55, 0.5, "n+", 1 - 1e-6, "hang"},
    {"IIa (Fig 14)", 0.55, 0.5, "n+", 1 + 1e-6, "tip"},
    /* IIa with J(n-) > J(n+): bistable between the vertical states */
    {"IIa (n- high)", 0.51, 0.5, "n+", 1 - 1e-6, "no_tip+hang"},
    {"IIa (n- high)", 0.51, 0.5, "n+", 1 + 1e-6, "no_tip+tip"},
    {"IIa (n- high)", 0.51, 0.5, "n-", 1 + 1e-6, "tip"},
    /* IIc: the whole branch unstable; J(n+) < J(n-), bistable in between */
    {"IIc", 0.955, 0.05, "n+", 1 - 1e-6, "no_tip"},
    {"IIc", 0.955, 0.05, "n+", 1 + 1e-6, "no_tip+tip"},
    {"IIc", 0.955, 0.05, "n-", 1 + 1e-6, "tip"},
};

static void test_predict(void)
{
    const double g = 9.81;
    for (size_t i = 0; i < sizeof pcases / sizeof pcases[0]; i++) {
        const pcase *pc = &pcases[i];
        /* SI top: 50 g, R = 20 mm, C = 8e-6 kg m^2 */
        tippe_top t = {0.05, 0.02, pc->e * 0.02, pc->k * 8e-6, 8e-6, -1, {0.0, 0.0}};
        tippe_theory_thresholds th;
        tippe_error err = {0};
        tippe_theory_compute_thresholds(&t, g, &th, &err);
        double Jt = !strcmp(pc->what, "n-") ? th.J_minus : !strcmp(pc->what, "n+") ? th.J_plus : th.J_b;
        int has = !strcmp(pc->what, "n-") ? th.has_n_minus : !strcmp(pc->what, "n+") ? th.has_n_plus
                                                                                       : th.has_n_b;
        CHECK(has, "%s: threshold %s undefined", pc->why, pc->what);
        /* the other thresholds lie > 1e-3 away, so a 1e-6 step crosses only this one */
        double others[3] = {th.has_n_minus ? th.J_minus : 0, th.has_n_plus ? th.J_plus : 0,
                            th.has_n_b ? th.J_b : 0};
        for (int j = 0; j < 3; j++)
            if (others[j] != 0.0 && others[j] != Jt)
                CHECK(rel_diff(others[j], Jt) > 1e-3, "%s: thresholds too close", pc->why);
        for (int sgn = -1; sgn <= 1; sgn += 2) {
            double J = sgn * pc->factor * Jt;
            tippe_theory_prediction p;
            int rc = tippe_theory_predict(&t, g, J, &p, &err);
            CHECK(rc == TIPPE_OK, "%s: %s", pc->why, err.msg);
            if (rc)
                continue;
            char got[64];
            kinds(&p, got, sizeof got);
            CHECK(!strcmp(got, pc->want), "%s, J = %g x J(%s), sign %d: got %s, Theorem 5.1 says %s",
                  pc->why, pc->factor, pc->what, sgn, got, pc->want);
            /* vertical states straight from the theorem's inequalities on n0, n_pi */
            double n0 = fabs(tippe_theory_n0(&t, J)), npi = fabs(tippe_theory_npi(&t, J));
            int want0 = th.cls.group <= TIPPE_GROUP_IB || n0 < th.n_minus_rad_s;
            int wantpi = th.cls.group != TIPPE_GROUP_III && npi > th.n_plus_rad_s;
            int got0 = 0, gotpi = 0;
            for (int s = 0; s < p.n; s++) {
                double th_s = p.state[s].theta_rad;
                got0 |= p.state[s].kind == TIPPE_FINAL_NO_TIP;
                gotpi |= p.state[s].kind == TIPPE_FINAL_TIP;
                /* every state carries the J it was asked for (root to 1e-14 in theta;
                 * J^2 is flat only at the vertical ends, not at these states) */
                double Js = tippe_theory_jellett(&t, th_s, p.state[s].phi_dot_rad_s,
                                                 p.state[s].spin_rad_s);
                CHECK(rel_diff(Js, J) < 1e-9, "%s: state %d has J = %.12g, asked %.12g", pc->why,
                      s, Js, J);
                if (p.state[s].kind == TIPPE_FINAL_HANG) {
                    CHECK(th_s > 0 && th_s < M_PI && tippe_theory_branch_stable(&th.cls, th_s),
                          "%s: hang at %g on an unstable branch", pc->why, th_s);
                    if (th.cls.group == TIPPE_GROUP_III)
                        CHECK(th_s < th.cls.theta_c_rad, "%s: hang beyond theta_c", pc->why);
                }
            }
            CHECK(got0 == want0 && gotpi == wantpi, "%s: vertical states %d/%d, theorem %d/%d",
                  pc->why, got0, gotpi, want0, wantpi);
        }
    }
    /* symmetry: -J gives the same angles and the opposite spins */
    tippe_top t = unit_top(0.92, 0.3);
    for (double J = 0.05; J < 20.0; J *= 1.9) {
        tippe_theory_prediction a, b;
        tippe_theory_predict(&t, 1.0, J, &a, NULL);
        tippe_theory_predict(&t, 1.0, -J, &b, NULL);
        int same = a.n == b.n;
        for (int s = 0; same && s < a.n; s++)
            same = a.state[s].kind == b.state[s].kind && a.state[s].theta_rad == b.state[s].theta_rad &&
                   a.state[s].spin_rad_s == -b.state[s].spin_rad_s &&
                   a.state[s].phi_dot_rad_s == -b.state[s].phi_dot_rad_s;
        CHECK(same, "J = +-%g: predictions not mirror images", J);
    }
    /* exactly on n-: the stable branch ends on theta = 0, which is returned */
    tippe_theory_thresholds th;
    tippe_theory_compute_thresholds(&t, 1.0, &th, NULL);
    tippe_theory_prediction p;
    double Jm = tippe_theory_jellett(&t, 0.0, 0.0, th.n_minus_rad_s);
    CHECK(tippe_theory_predict(&t, 1.0, Jm, &p, NULL) == TIPPE_OK && p.n == 1 &&
          p.state[0].theta_rad < 1e-6, "J exactly at n-: %d states, theta %g", p.n,
          p.state[0].theta_rad);
    CHECK(tippe_theory_predict(&t, 1.0, INFINITY, &p, NULL) == TIPPE_EINPUT, "J = inf accepted");
}

int main(void)
{
    test_groups();
    test_stability_rule();
    test_fold();
    test_thresholds();
    test_intermediate_states();
    test_boundaries();
    test_predict();
    return check_summary("test_theory");
}
