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
#include "tippe/base.h"

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

/* ---- Effective potential and its wells ------------------------------------------
 * Energy (section 4) at fixed theta and Jellett J (eq 3.20): the kinetic energy
 * A a^2/2 + C n^2/2 of the rotation about i and k (a = phi_dot sin theta) is least,
 * on the line A R sin(theta) a + C (R cos theta - eps) n = J, at J^2 / (2 D); every
 * other term (theta_dot, sliding, the vertical motion of eq 3.11) only adds. */

static double potential_D(const tippe_top *t, double x, double s)
{
    const double z = t->R * x - t->eps;
    return t->A * t->R * t->R * s * s + t->C * z * z;
}

double tippe_theory_potential(const tippe_top *top, double g, double J, double theta)
{
    const double x = cos(theta), s = sin(theta);
    return top->m * g * (top->R - top->eps * x) + 0.5 * J * J / potential_D(top, x, s);
}

/* dV/dtheta = sin(theta) (m g eps - J^2 R ((A - C) R cos theta + C eps) / D^2). */
double tippe_theory_potential_slope(const tippe_top *top, double g, double J, double theta)
{
    const double x = cos(theta), s = sin(theta), D = potential_D(top, x, s);
    return s * (top->m * g * top->eps -
                J * J * top->R * ((top->A - top->C) * top->R * x + top->C * top->eps) / (D * D));
}

/* A polynomial c[0] + c[1] x + ... + c[deg] x^deg, deg <= 4. */
typedef struct {
    int deg;
    double c[5];
} poly;

static double poly_eval(const poly *p, double x)
{
    double v = 0.0;
    for (int i = p->deg; i >= 0; i--)
        v = v * x + p->c[i];
    return v;
}

static poly poly_deriv(const poly *p)
{
    poly d = {p->deg > 0 ? p->deg - 1 : 0, {0}};
    for (int i = 1; i <= p->deg; i++)
        d.c[i - 1] = i * p->c[i];
    return d;
}

/* Bisection of a sign change of f on [lo, hi] down to adjacent doubles. */
static double bisect_sign_change(double (*f)(double, const void *), const void *ctx, double lo,
                                 double hi)
{
    double f_lo = f(lo, ctx);
    for (int it = 0; it < 200; it++) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi)
            break;
        const double fm = f(mid, ctx);
        if (fm == 0.0)
            return mid;
        if ((fm < 0.0) == (f_lo < 0.0)) {
            lo = mid;
            f_lo = fm;
        } else {
            hi = mid;
        }
    }
    return 0.5 * (lo + hi);
}

static double poly_at(double x, const void *p) { return poly_eval(p, x); }

/* The points in (a, b) where p changes sign, sorted, found by splitting [a, b] at
 * the sign changes of p' (recursively): on each piece p is monotone, so it has at
 * most one root there and the subdivision misses none. A root of even multiplicity
 * is no sign change and is not returned (the caller checks the points of p'). */
static int poly_sign_changes(const poly *p, double a, double b, double *roots)
{
    if (p->deg <= 0)
        return 0;
    double cuts[6];
    int n_cuts = 0;
    cuts[n_cuts++] = a;
    if (p->deg >= 2) {
        poly d = poly_deriv(p);
        n_cuts += poly_sign_changes(&d, a, b, cuts + 1);
    }
    cuts[n_cuts++] = b;
    int n = 0;
    for (int i = 0; i + 1 < n_cuts; i++) {
        const double f_lo = poly_eval(p, cuts[i]), f_hi = poly_eval(p, cuts[i + 1]);
        if (f_lo == 0.0 && i > 0 && (n == 0 || roots[n - 1] != cuts[i]))
            roots[n++] = cuts[i];
        else if ((f_lo < 0.0 && f_hi > 0.0) || (f_lo > 0.0 && f_hi < 0.0))
            roots[n++] = bisect_sign_change(poly_at, p, cuts[i], cuts[i + 1]);
    }
    return n;
}

/* G(x) of tippe_theory_find_wells, its scale for "is this zero" tests. */
typedef struct {
    double k, e, T;
    poly G;
} wells_ctx;

static void wells_ctx_init(wells_ctx *w, const tippe_top *top, double g, double J)
{
    w->k = top->A / top->C;
    w->e = top->eps / top->R;
    w->T = J * J / (top->m * g * top->C * top->R * top->R * top->R);
    const double p2 = 1.0 - w->k, p1 = -2.0 * w->e, p0 = w->e * w->e + w->k;
    /* e P^2 - T ((k - 1) x + e) */
    w->G.deg = 4;
    w->G.c[4] = w->e * p2 * p2;
    w->G.c[3] = w->e * 2.0 * p2 * p1;
    w->G.c[2] = w->e * (p1 * p1 + 2.0 * p2 * p0);
    w->G.c[1] = w->e * 2.0 * p1 * p0 - w->T * (w->k - 1.0);
    w->G.c[0] = w->e * p0 * p0 - w->T * w->e;
    while (w->G.deg > 0 && w->G.c[w->G.deg] == 0.0)
        w->G.deg--;
}

static double G_of_theta(const wells_ctx *w, double theta)
{
    return poly_eval(&w->G, cos(theta));
}

/* G(cos theta): its sign changes are bisected in theta, not in x, whose rounding
 * near x = +-1 would cost digits of theta. */
static double G_at_theta(double theta, const void *w) { return G_of_theta(w, theta); }

static void add_crit(tippe_theory_wells *out, const tippe_top *top, double g, double theta,
                     int kind, double V2, double V2_scale)
{
    if (out->n_crit >= TIPPE_THEORY_MAX_CRIT)
        return;
    int i = out->n_crit++;
    while (i > 0 && out->crit_theta_rad[i - 1] > theta) {
        out->crit_theta_rad[i] = out->crit_theta_rad[i - 1];
        out->crit_kind[i] = out->crit_kind[i - 1];
        out->crit_degenerate[i] = out->crit_degenerate[i - 1];
        out->crit_V[i] = out->crit_V[i - 1];
        i--;
    }
    out->crit_theta_rad[i] = theta;
    out->crit_kind[i] = kind;
    out->crit_degenerate[i] = !(fabs(V2) > 1e-9 * V2_scale);
    out->crit_V[i] = tippe_theory_potential(top, g, out->J, theta);
}

/* Critical points: the poles, the sign changes of G, and the points of G' where G
 * nearly vanishes without changing sign (double points, kind 0). */
static void find_critical_points(const tippe_top *top, double g, const wells_ctx *w,
                                 tippe_theory_wells *out)
{
    const double mgR = top->m * g * top->R;
    const double V2_scale = top->m * g * top->eps + out->J * out->J / (top->C * top->R * top->R);
    const double G1 = poly_eval(&w->G, 1.0), Gm1 = poly_eval(&w->G, -1.0);
    const double P1 = (1.0 - w->e) * (1.0 - w->e), Pm1 = (1.0 + w->e) * (1.0 + w->e);
    /* V''(0) = m g R G(1) / P(1)^2, V''(pi) = -m g R G(-1) / P(-1)^2 */
    add_crit(out, top, g, 0.0, G1 > 0.0 ? -1 : G1 < 0.0 ? 1 : 0, mgR * G1 / (P1 * P1), V2_scale);
    add_crit(out, top, g, M_PI, Gm1 < 0.0 ? -1 : Gm1 > 0.0 ? 1 : 0, mgR * Gm1 / (Pm1 * Pm1),
             V2_scale);

    double xr[6];
    const int n = poly_sign_changes(&w->G, -1.0, 1.0, xr);
    const poly dG = poly_deriv(&w->G);
    for (int i = n - 1; i >= 0; i--) {
        /* the piece of monotony around xr[i], from the neighbouring roots of G' */
        const double x = xr[i];
        const double th = acos(x);
        /* bracket in theta: G changes sign within [acos(x + d), acos(x - d)] */
        double d = 1e-9, th_lo = acos(fmin(1.0, x + d)), th_hi = acos(fmax(-1.0, x - d));
        const double root = (G_of_theta(w, th_lo) < 0.0) != (G_of_theta(w, th_hi) < 0.0)
                                ? bisect_sign_change(G_at_theta, w, th_lo, th_hi)
                                : th;
        const double xx = cos(root), s = sin(root);
        const double P = (xx - w->e) * (xx - w->e) + w->k * s * s;
        const double G_prime = poly_eval(&dG, xx);
        /* V'' = -m g R sin^2 G'(x) / P^2; a max where G rises with x */
        add_crit(out, top, g, root, G_prime > 0.0 ? 1 : -1, -mgR * s * s * G_prime / (P * P),
                 V2_scale);
    }
    double xd[6];
    const int nd = w->G.deg >= 2 ? poly_sign_changes(&dG, -1.0, 1.0, xd) : 0;
    for (int i = 0; i < nd; i++) {
        const double x = xd[i], P = (x - w->e) * (x - w->e) + w->k * (1.0 - x * x);
        const double G_scale = w->e * P * P + w->T * fabs((w->k - 1.0) * x + w->e);
        if (fabs(poly_eval(&w->G, x)) <= 1e-9 * G_scale)
            add_crit(out, top, g, acos(x), 0, 0.0, V2_scale);
    }
}

static void build_wells(tippe_theory_wells *out)
{
    double ends[TIPPE_THEORY_MAX_CRIT + 2];
    int n_ends = 0;
    ends[n_ends++] = 0.0;
    for (int i = 0; i < out->n_crit; i++) {
        const double th = out->crit_theta_rad[i];
        if (out->crit_kind[i] == 1 && th > 0.0 && th < M_PI)
            ends[n_ends++] = th;
    }
    ends[n_ends++] = M_PI;
    out->n_wells = 0;
    for (int j = 0; j + 1 < n_ends && out->n_wells < TIPPE_THEORY_MAX_WELLS; j++) {
        tippe_theory_well *wl = &out->well[out->n_wells++];
        const double lo = ends[j], hi = ends[j + 1];
        wl->theta_lo_rad = lo;
        wl->theta_hi_rad = hi;
        wl->V_escape = INFINITY;
        wl->flat = 0;
        int best = -1, best_is_min = 0;
        for (int i = 0; i < out->n_crit; i++) {
            const double th = out->crit_theta_rad[i];
            if (th < lo || th > hi)
                continue;
            if (out->crit_degenerate[i])
                wl->flat = 1;
            const int interior_max = out->crit_kind[i] == 1 && th > 0.0 && th < M_PI;
            if (interior_max) {
                if (out->crit_V[i] < wl->V_escape)
                    wl->V_escape = out->crit_V[i];
                continue;
            }
            const int is_min = out->crit_kind[i] == -1;
            if (best < 0 || (is_min && !best_is_min) ||
                (is_min == best_is_min && out->crit_V[i] < out->crit_V[best])) {
                best = i;
                best_is_min = is_min;
            }
        }
        if (best < 0) { /* cannot happen with a sign change on each side; be safe */
            wl->flat = 1;
            wl->theta_min_rad = 0.5 * (lo + hi);
            wl->V_min = NAN;
            wl->curvature = 0.0;
            continue;
        }
        if (!best_is_min)
            wl->flat = 1;
        wl->theta_min_rad = out->crit_theta_rad[best];
        wl->V_min = out->crit_V[best];
    }
}

/* V'' at theta by the closed forms of find_critical_points (G = 0 there). */
static double curvature_at(const tippe_top *top, double g, const wells_ctx *w, double theta)
{
    const double mgR = top->m * g * top->R, x = cos(theta), s = sin(theta);
    const double P = (x - w->e) * (x - w->e) + w->k * s * s;
    if (theta == 0.0 || theta == M_PI) {
        const double Gx = poly_eval(&w->G, theta == 0.0 ? 1.0 : -1.0);
        return (theta == 0.0 ? mgR : -mgR) * Gx / (P * P);
    }
    const poly dG = poly_deriv(&w->G);
    return -mgR * s * s * poly_eval(&dG, x) / (P * P);
}

int tippe_theory_find_wells(const tippe_top *top, double g, double J, tippe_theory_wells *out,
                            tippe_error *err)
{
    int rc = check_top(top, g, err);
    if (rc)
        return rc;
    if (!isfinite(J))
        return tippe_error_set(err, TIPPE_EINPUT, "theory: Jellett invariant J = %g is not finite",
                               J);
    *out = (tippe_theory_wells){0};
    out->J = J;
    wells_ctx w;
    wells_ctx_init(&w, top, g, J);
    find_critical_points(top, g, &w, out);
    build_wells(out);
    for (int i = 0; i < out->n_wells; i++) {
        tippe_theory_well *wl = &out->well[i];
        wl->curvature = curvature_at(top, g, &w, wl->theta_min_rad);
        if (!(wl->curvature > 0.0))
            wl->flat = 1;
    }
    return TIPPE_OK;
}

int tippe_theory_well_index(const tippe_theory_wells *w, double theta)
{
    for (int i = 0; i < w->n_wells; i++)
        if (theta <= w->well[i].theta_hi_rad)
            return i;
    return w->n_wells - 1;
}

/* Where V = E between a (V(a) <= E) and b (V(b) > E), V monotone in between. */
static double level_crossing(const tippe_top *top, double g, double J, double E, double a,
                             double b)
{
    for (int it = 0; it < 200; it++) {
        const double mid = 0.5 * (a + b);
        if (mid == a || mid == b || fabs(b - a) < 1e-14)
            break;
        if (tippe_theory_potential(top, g, J, mid) <= E)
            a = mid;
        else
            b = mid;
    }
    return a;
}

void tippe_theory_well_range(const tippe_top *top, double g, const tippe_theory_wells *w, int i,
                             double E, double *lo, double *hi)
{
    const tippe_theory_well *wl = &w->well[i];
    const double th0 = wl->theta_min_rad;
    *lo = *hi = th0;
    if (!(E > wl->V_min))
        return;
    *lo = tippe_theory_potential(top, g, w->J, wl->theta_lo_rad) <= E
              ? wl->theta_lo_rad
              : level_crossing(top, g, w->J, E, th0, wl->theta_lo_rad);
    *hi = tippe_theory_potential(top, g, w->J, wl->theta_hi_rad) <= E
              ? wl->theta_hi_rad
              : level_crossing(top, g, w->J, E, th0, wl->theta_hi_rad);
}
