/* Relative equilibria of the eccentric sphere and their stability: Ciocci et al.
 * 2012, section 5, Theorem 5.1, Appendix A and section 7.1. See docs/theory.md.
 *
 * Notation: k = A/C, e = eps/R, u = 1 - k, x = cos(theta). On the intermediate-state
 * curve the dimensionless Jellett invariant squared is
 *   F(x) = J^2 / (m g C R^3) = e P(x)^2 / D(x),
 *   P(x) = (x - e)^2 + k (1 - x^2),   D(x) = e - u x = (k - 1) x + e,
 * (eq 5.10 with alpha from 5.6 and n from 5.4). Because P'(x) = -2 D(x),
 *   F'(x) = P(x) Q(x) / D(x)^2,   Q(x) = u P(x) - 4 D(x)^2
 *         = -3 u^2 x^2 + 6 e u x + u e^2 + u k - 4 e^2,
 * whose smaller root (u > 0) is b of eq 5.11. Stability follows the rule that a
 * branch is stable where J^2 increases with theta, i.e. where Q(x) < 0; the tests
 * check that this rule reproduces Theorem 5.1 in every subgroup. */
#include "tippe/theory.h"
#include "tippe/error.h"

#include <float.h>
#include <math.h>
#include <stddef.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

static const char *const group_names[] = {"Ia", "Ib", "IIa", "IIb", "IIc", "III"};

const char *tippe_group_name(tippe_group g)
{
    if ((int)g < 0 || (int)g > (int)TIPPE_GROUP_III)
        return "?";
    return group_names[g];
}

const char *tippe_group_family(tippe_group g)
{
    switch (g) {
    case TIPPE_GROUP_IA:
    case TIPPE_GROUP_IB:
        return "I";
    case TIPPE_GROUP_IIA:
    case TIPPE_GROUP_IIB:
    case TIPPE_GROUP_IIC:
        return "II";
    case TIPPE_GROUP_III:
        return "III";
    }
    return "?";
}

const char *tippe_final_kind_name(tippe_final_kind kind)
{
    switch (kind) {
    case TIPPE_FINAL_NO_TIP:
        return "no_tip";
    case TIPPE_FINAL_TIP:
        return "tip";
    case TIPPE_FINAL_HANG:
        return "hang";
    }
    return "?";
}

/* b of eq 5.11, real only for u > 0 and u >= e^2 (the fold exists). */
static int fold_b(double k, double e, int snap_line, double *b)
{
    double u = 1.0 - k;
    if (!(u > 0.0))
        return 0;
    double s2 = k * (u - e * e) / 3.0;
    /* On the line k - 1 = -e^2 the radicand vanishes; rounding must not make a
     * point reported as on the line lose its b. */
    if (s2 < 0.0 && snap_line && fabs((k - 1.0) + e * e) <= TIPPE_THEORY_BOUNDARY_TOL)
        s2 = 0.0;
    if (s2 < 0.0)
        return 0;
    *b = (e - sqrt(s2)) / u;
    return 1;
}

/* acos that takes a cosine within the boundary tolerance of +-1 as exactly +-1:
 * acos would turn a rounding error of 1e-16 there into an angle of 1e-8 rad. */
static double snapped_acos(double x)
{
    if (x >= 1.0 - TIPPE_THEORY_BOUNDARY_TOL)
        return 0.0;
    if (x <= -1.0 + TIPPE_THEORY_BOUNDARY_TOL)
        return M_PI;
    return acos(x);
}

int tippe_theory_classify(double A_over_C, double eps_over_R, tippe_theory_class *out)
{
    const double k = A_over_C, e = eps_over_R, tol = TIPPE_THEORY_BOUNDARY_TOL;
    if (!out)
        return TIPPE_EINPUT;
    *out = (tippe_theory_class){0};
    if (!isfinite(k) || !isfinite(e) || !(k > 0.0) || !(e >= 0.0) || !(e < 1.0))
        return TIPPE_EINPUT;
    out->A_over_C = k;
    out->eps_over_R = e;

    const double u = 1.0 - k;
    const double d_lo = (k - 1.0) + e;     /* I/II boundary, eq 5.8 */
    const double d_hi = (k - 1.0) - e;     /* II/III boundary, eq 5.9 */
    const double d_line = (k - 1.0) + e * e; /* IIb line of Theorem 5.1 */

    out->has_b = fold_b(k, e, 1, &out->b);
    if (out->has_b && fabs(out->b) <= 1.0 + tol) {
        out->has_theta_b = 1;
        out->theta_b_rad = snapped_acos(out->b);
    }
    if (u != 0.0) {
        out->has_c = 1;
        out->c = e / u; /* eq 5.8/5.9 */
        if (fabs(out->c) <= 1.0 + tol) {
            out->has_theta_c = 1;
            out->theta_c_rad = snapped_acos(out->c);
        }
    }

    /* Main group, with the documented side on each boundary. */
    enum { FAM_I, FAM_II, FAM_III } fam;
    const char *boundary = NULL;
    if (e <= tol) {
        /* Both I/II and II/III boundaries meet here: no group II, no preferred
         * side; decide by the sign of k - 1 alone. */
        boundary = "eps/R=0";
        fam = (k - 1.0 <= 0.0) ? FAM_I : FAM_III;
    } else if (fabs(d_lo) <= tol) {
        boundary = "A/C-1=-eps/R";
        fam = FAM_I;
    } else if (fabs(d_hi) <= tol) {
        boundary = "A/C-1=+eps/R";
        fam = FAM_III;
    } else if (d_lo < 0.0) {
        fam = FAM_I;
    } else if (d_hi < 0.0) {
        fam = FAM_II;
    } else {
        fam = FAM_III;
    }

    switch (fam) {
    case FAM_I:
        if (!out->has_b) {
            /* Only e = 0, k = 1: the limit of b -> -infinity along e = 0. */
            out->group = TIPPE_GROUP_IA;
        } else if (fabs(out->b + 1.0) <= tol) {
            out->group = TIPPE_GROUP_IA; /* the whole branch is unstable, as in Ia */
            if (!boundary)
                boundary = "b=-1";
            else if (boundary[0] == 'A')
                boundary = "A/C-1=-eps/R,b=-1";
        } else {
            out->group = out->b < -1.0 ? TIPPE_GROUP_IA : TIPPE_GROUP_IB;
        }
        break;
    case FAM_II:
        if (fabs(d_line) <= tol) {
            boundary = "A/C-1=-(eps/R)^2";
            out->group = TIPPE_GROUP_IIB; /* b = 1/e > 1 here */
        } else if (d_line > 0.0 || !out->has_b) {
            out->group = TIPPE_GROUP_IIB;
        } else if (fabs(out->b - 1.0) <= tol) {
            boundary = "b=1";
            out->group = TIPPE_GROUP_IIB; /* stable on all of 0 < theta < pi */
        } else if (out->b > 1.0) {
            out->group = TIPPE_GROUP_IIB;
        } else if (fabs(out->b + 1.0) <= tol) {
            boundary = "b=-1";
            out->group = TIPPE_GROUP_IIC; /* unstable on all of 0 < theta < pi */
        } else {
            out->group = out->b < -1.0 ? TIPPE_GROUP_IIC : TIPPE_GROUP_IIA;
        }
        break;
    case FAM_III:
        out->group = TIPPE_GROUP_III;
        break;
    }
    out->boundary = boundary;
    return TIPPE_OK;
}

int tippe_theory_exists(double A_over_C, double eps_over_R, double theta)
{
    return (A_over_C - 1.0) * cos(theta) + eps_over_R > 0.0; /* eq 5.7 */
}

int tippe_theory_branch_stable(const tippe_theory_class *cls, double theta)
{
    switch (cls->group) {
    case TIPPE_GROUP_IA:
    case TIPPE_GROUP_IIC:
        return 0;
    case TIPPE_GROUP_IIB:
    case TIPPE_GROUP_III:
        return 1;
    case TIPPE_GROUP_IB:
    case TIPPE_GROUP_IIA:
        return cls->has_theta_b && theta > cls->theta_b_rad;
    }
    return 0;
}

/* F(x) of the header comment; D(x) > 0 is the caller's business. */
static double curve_F(double k, double e, double x, double s)
{
    double P = (x - e) * (x - e) + k * s * s;
    double D = (k - 1.0) * x + e;
    return e * P * P / D;
}

int tippe_theory_curve_j2(double A_over_C, double eps_over_R, double theta, double *j2)
{
    double x = cos(theta), s = sin(theta);
    if (!((A_over_C - 1.0) * x + eps_over_R > 0.0)) /* eq 5.7 */
        return TIPPE_EINPUT;
    *j2 = curve_F(A_over_C, eps_over_R, x, s); /* eq 5.10 */
    return TIPPE_OK;
}

static int check_top(const tippe_top *t, double g, tippe_error *err)
{
    if (!t)
        return tippe_error_set(err, TIPPE_EINPUT, "theory: no top given");
    if (!(isfinite(t->m) && t->m > 0.0))
        return tippe_error_set(err, TIPPE_EINPUT, "theory: mass m = %g kg must be > 0", t->m);
    if (!(isfinite(t->R) && t->R > 0.0))
        return tippe_error_set(err, TIPPE_EINPUT, "theory: radius R = %g m must be > 0", t->R);
    if (!(isfinite(t->A) && t->A > 0.0) || !(isfinite(t->C) && t->C > 0.0))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "theory: moments A = %g, C = %g kg m^2 must be > 0", t->A, t->C);
    if (!(isfinite(t->eps) && t->eps >= 0.0 && t->eps < t->R))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "theory: eccentricity eps = %g m must satisfy 0 <= eps < R = %g m",
                               t->eps, t->R);
    if (!(isfinite(g) && g > 0.0))
        return tippe_error_set(err, TIPPE_EINPUT, "theory: gravity g = %g m/s^2 must be > 0", g);
    return TIPPE_OK;
}

double tippe_theory_jellett(const tippe_top *top, double theta, double phi_dot, double spin)
{
    double s = sin(theta);
    /* eq 3.20/3.22: J = -L.q with q = R sin(th) i + (eps - R cos(th)) k */
    return top->C * spin * (top->R * cos(theta) - top->eps) + top->A * phi_dot * top->R * s * s;
}

double tippe_theory_n0(const tippe_top *top, double J)
{
    return J / (top->C * (top->R - top->eps));
}

double tippe_theory_npi(const tippe_top *top, double J)
{
    return -J / (top->C * (top->R + top->eps));
}

/* The state on the curve at (x, s) = (cos th, sin th); D(x) > 0 assumed. */
static void state_at(const tippe_top *top, double g, double theta, double sign,
                     tippe_theory_state *st)
{
    double x = cos(theta), s = sin(theta), e = top->eps / top->R;
    double D = (top->A - top->C) * x + top->C * e;
    double alpha = sign * sqrt(top->m * g * top->eps / D); /* eq 5.6 */
    st->theta_rad = theta;
    st->phi_dot_rad_s = alpha;
    st->spin_rad_s = alpha * (x - e); /* eq 5.4 */
    /* eq 5.10 before squaring: J = alpha R (C (cos th - e)^2 + A sin^2 th) */
    st->J = alpha * top->R * (top->C * (x - e) * (x - e) + top->A * s * s);
}

int tippe_theory_intermediate(const tippe_top *top, double g, double theta, int sign,
                              tippe_theory_state *out, tippe_error *err)
{
    int rc = check_top(top, g, err);
    if (rc)
        return rc;
    if (!(theta > 0.0 && theta < M_PI))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "theory: theta = %g rad is not strictly between 0 and pi", theta);
    if (!tippe_theory_exists(top->A / top->C, top->eps / top->R, theta))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "theory: no intermediate state at theta = %g rad "
                               "((A/C - 1) cos theta + eps/R <= 0, eq 5.7)", theta);
    state_at(top, g, theta, sign < 0 ? -1.0 : 1.0, out);
    return TIPPE_OK;
}

int tippe_theory_compute_thresholds(const tippe_top *top, double g, tippe_theory_thresholds *out,
                                     tippe_error *err)
{
    int rc = check_top(top, g, err);
    if (rc)
        return rc;
    *out = (tippe_theory_thresholds){0};
    const double k = top->A / top->C, e = top->eps / top->R;
    tippe_theory_classify(k, e, &out->cls);
    const double mge_C = top->m * g * top->eps / top->C;
    const double d_lo = (k - 1.0) + e, d_pi = e - (k - 1.0);

    if (d_lo > 0.0) { /* eq 5.11 / A.14 */
        out->has_n_minus = 1;
        out->n_minus_rad_s = (1.0 - e) * sqrt(mge_C / d_lo);
        out->J_minus = out->n_minus_rad_s * top->C * (top->R - top->eps);
    }
    if (d_pi > 0.0) { /* eq 5.11 / A.27 */
        out->has_n_plus = 1;
        out->n_plus_rad_s = (1.0 + e) * sqrt(mge_C / d_pi);
        out->J_plus = out->n_plus_rad_s * top->C * (top->R + top->eps);
        out->has_n_star = 1; /* section 7.1 */
        out->n_star_rad_s = out->n_plus_rad_s * (top->R + top->eps) / (top->R - top->eps);
    }
    if ((out->cls.group == TIPPE_GROUP_IB || out->cls.group == TIPPE_GROUP_IIA) &&
        out->cls.has_theta_b) {
        double b = out->cls.b, F;
        double sb = sqrt(fmax(0.0, 1.0 - b * b));
        if ((k - 1.0) * b + e > 0.0) {
            F = curve_F(k, e, b, sb);
            out->has_n_b = 1;
            out->J_b = sqrt(top->m * g * top->C * top->R * top->R * top->R * F);
            out->n_b_0_rad_s = tippe_theory_n0(top, out->J_b);
            out->n_b_pi_rad_s = -tippe_theory_npi(top, out->J_b);
        }
    }
    return TIPPE_OK;
}

/* G(theta) = D (F - T) = e P^2 - T D: the sign of F - T wherever D > 0, and finite
 * where the curve goes to infinity (D -> 0), so that Brent can bracket it. */
typedef struct {
    double k, e, T;
} g_params;

static double g_of_theta(double theta, void *p)
{
    const g_params *q = p;
    double x = cos(theta), s = sin(theta);
    double P = (x - q->e) * (x - q->e) + q->k * s * s;
    double D = (q->k - 1.0) * x + q->e;
    return q->e * P * P - q->T * D;
}

static int solve_branch(double k, double e, double T, double th_lo, double th_hi,
                        double *theta, tippe_error *err)
{
    g_params p = {k, e, T};
    gsl_function f = {g_of_theta, &p};
    double g_lo = g_of_theta(th_lo, &p), g_hi = g_of_theta(th_hi, &p);
    /* T within rounding of an end value: the end is the answer. */
    if (g_lo >= 0.0) {
        *theta = th_lo;
        return TIPPE_OK;
    }
    if (g_hi <= 0.0) {
        *theta = th_hi;
        return TIPPE_OK;
    }
    gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (!s)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "theory: out of memory (root solver)");
    int status = gsl_root_fsolver_set(s, &f, th_lo, th_hi);
    for (int it = 0; status == GSL_SUCCESS; it++) {
        if (it == 200) {
            status = GSL_EMAXITER;
            break;
        }
        status = gsl_root_fsolver_iterate(s);
        if (status != GSL_SUCCESS)
            break;
        /* theta to ~1e-14: far below anything a launch can resolve */
        status = gsl_root_test_interval(gsl_root_fsolver_x_lower(s), gsl_root_fsolver_x_upper(s),
                                        1e-15, 1e-14);
        if (status == GSL_SUCCESS)
            break;
        if (status == GSL_CONTINUE)
            status = GSL_SUCCESS;
    }
    *theta = gsl_root_fsolver_root(s);
    gsl_root_fsolver_free(s);
    if (status != GSL_SUCCESS)
        return tippe_error_set(err, TIPPE_ECOMPUTE,
                               "theory: intermediate state for A/C = %.17g, eps/R = %.17g, "
                               "J^2/(m g C R^3) = %.17g not found: %s", k, e, T,
                               gsl_strerror(status));
    return TIPPE_OK;
}

static void add_state(tippe_theory_prediction *out, tippe_final_kind kind, double theta,
                      double spin, double phi_dot)
{
    for (int i = 0; i < out->n; i++)
        if (out->state[i].kind == kind && out->state[i].theta_rad == theta)
            return;
    if (out->n >= 3)
        return;
    int i = out->n++;
    /* keep sorted by theta */
    while (i > 0 && out->state[i - 1].theta_rad > theta) {
        out->state[i] = out->state[i - 1];
        i--;
    }
    out->state[i].kind = kind;
    out->state[i].theta_rad = theta;
    out->state[i].spin_rad_s = spin;
    out->state[i].phi_dot_rad_s = phi_dot;
}

int tippe_theory_predict(const tippe_top *top, double g, double J, tippe_theory_prediction *out,
                         tippe_error *err)
{
    tippe_gsl_errors_as_codes();
    int rc = check_top(top, g, err);
    if (rc)
        return rc;
    if (!isfinite(J))
        return tippe_error_set(err, TIPPE_EINPUT, "theory: Jellett invariant J = %g is not finite",
                               J);
    *out = (tippe_theory_prediction){0};
    const double k = top->A / top->C, e = top->eps / top->R, u = 1.0 - k;
    const double n0 = tippe_theory_n0(top, J), npi = tippe_theory_npi(top, J);
    const double sign = J < 0.0 ? -1.0 : 1.0; /* symmetry (n, alpha) -> (-n, -alpha) */

    if (e == 0.0) {
        /* Balanced ball: eq 5.6 gives alpha = 0 off theta = pi/2, so the curve
         * collapses; the stable states follow from A.14/A.27 at eps = 0 and 5.5. */
        if (J == 0.0 || k == 1.0)
            return tippe_error_set(err, TIPPE_EINPUT,
                                   "theory: eps = 0 with %s: every orientation is a steady "
                                   "state (neutral), no final state can be predicted",
                                   J == 0.0 ? "J = 0" : "A = C");
        if (k > 1.0) {
            /* Only theta = pi/2 (n = 0) balances eq 5.5; spinning about the larger
             * transverse moment, it is the stable state (group III). */
            add_state(out, TIPPE_FINAL_HANG, M_PI / 2.0, 0.0, J / (top->A * top->R));
            return TIPPE_OK;
        }
        /* k < 1: both vertical states, no preferred side; falls through. */
    }

    const double T = J * J / (top->m * g * top->C * top->R * top->R * top->R);
    const double d_lo = (k - 1.0) + e, d_pi = e - (k - 1.0);

    /* eq A.14: stable for all J when k - 1 <= -e (n- infinite), else iff |n0| < n-,
     * i.e. J^2 below the curve's value at theta = 0. */
    if (d_lo <= 0.0 || T < curve_F(k, e, 1.0, 0.0))
        add_state(out, TIPPE_FINAL_NO_TIP, 0.0, n0, 0.0);
    /* eq A.27: iff k - 1 < e and |n_pi| > n+, i.e. J^2 above the curve at pi. */
    if (d_pi > 0.0 && T > curve_F(k, e, -1.0, 0.0))
        add_state(out, TIPPE_FINAL_TIP, M_PI, npi, 0.0);

    /* The stable part of the intermediate branch, as an interval [x_b, x_a] of
     * x = cos(theta) on which D > 0 and Q < 0, so that F decreases in x there. */
    enum { END_VERTICAL, END_FOLD, END_INFINITE } end_a = END_VERTICAL, end_b = END_VERTICAL;
    double x_a = 1.0, x_b = -1.0, b;
    int has_b = fold_b(k, e, 0, &b);
    /* D(1) = d_lo and D(-1) = d_pi exactly as curve_F rounds them, so that the
     * vertical decisions above and the branch ends here agree on a boundary. */
    if (d_lo <= 0.0) { /* eq 5.8: the branch ends where D -> 0, at c <= 1 */
        x_a = fmin(e / u, 1.0);
        end_a = END_INFINITE;
    }
    if (d_pi <= 0.0) { /* eq 5.9: ends at c >= -1 */
        x_b = fmax(e / u, -1.0);
        end_b = END_INFINITE;
    }
    if (has_b && b < x_a) { /* Q >= 0 for b <= x < c: unstable */
        x_a = b;
        end_a = END_FOLD;
    }
    /* An infinite end at small theta would mean J^2 decreasing there (unstable);
     * D -> 0 with u > 0 always has the fold b < c in between. */
    if (x_a > x_b && end_a != END_INFINITE) {
        double th_lo = x_a >= 1.0 ? 0.0 : acos(x_a);
        double th_hi = x_b <= -1.0 ? M_PI : acos(x_b);
        double T_a = curve_F(k, e, x_a, sin(th_lo));
        double T_b = end_b == END_INFINITE ? INFINITY : curve_F(k, e, x_b, 0.0);
        if (T > T_a && T < T_b) {
            double theta = 0.0;
            rc = solve_branch(k, e, T, th_lo, th_hi, &theta, err);
            if (rc)
                return rc;
            if (theta <= 0.0) {
                add_state(out, TIPPE_FINAL_NO_TIP, 0.0, n0, 0.0);
            } else if (theta >= M_PI) {
                add_state(out, TIPPE_FINAL_TIP, M_PI, npi, 0.0);
            } else {
                tippe_theory_state st;
                state_at(top, g, theta, sign, &st);
                add_state(out, TIPPE_FINAL_HANG, theta, st.spin_rad_s, st.phi_dot_rad_s);
            }
        } else if (T == T_a && end_a == END_VERTICAL) {
            /* |n0| = n- exactly: the stable branch ends on theta = 0 */
            add_state(out, TIPPE_FINAL_NO_TIP, 0.0, n0, 0.0);
        } else if (T == T_b && end_b == END_VERTICAL) {
            /* |n_pi| = n+ exactly: the stable branch ends on theta = pi */
            add_state(out, TIPPE_FINAL_TIP, M_PI, npi, 0.0);
        }
    }
    if (out->n == 0)
        return tippe_error_set(err, TIPPE_ECOMPUTE,
                               "theory: no stable state for A/C = %.17g, eps/R = %.17g, "
                               "J = %.17g kg m^3/s", k, e, J);
    return TIPPE_OK;
}
