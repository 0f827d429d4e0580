/* tippe/theory.h: the paper's theory of a top (Ciocci et al. 2012, section 5).
 *
 * Contents:
 * - groups: Theorem 5.1's classification of (A/C, eps/R) and its boundaries
 *   (tippe_theory_classify, tippe_group_*);
 * - relative equilibria and their spin thresholds n-, n+, n*, n_b, the final states
 *   Theorem 5.1 predicts for a Jellett invariant (tippe_theory_*);
 * - the effective potential V(theta; J) and its wells, on which the dynamics' proofs
 *   rest (tippe_theory_wells, tippe_theory_well_*).
 * src/theory/theory.c. Depends on base and the top (tippe/top.h) only. */
#ifndef TIPPE_THEORY_H
#define TIPPE_THEORY_H

#include "tippe/base.h"
#include "tippe/top.h"

/* Theory: relative equilibria of the eccentric sphere and their stability
 * (Ciocci et al. 2012, section 5, Theorem 5.1, Appendix A, section 7.1).
 *
 * Pure functions of a top (tippe_top) and g; no state, safe on any number of threads.
 * Throughout, k = A/C and e = eps/R; the Jellett invariant J is in kg m^3/s (SI).
 * docs/theory.md says which equation each function implements and how points on a
 * group boundary are decided. */

typedef enum { TIPPE_GROUP_IA, TIPPE_GROUP_IB, TIPPE_GROUP_IIA, TIPPE_GROUP_IIB,
               TIPPE_GROUP_IIC, TIPPE_GROUP_III } tippe_group;

/* "Ia", "Ib", "IIa", "IIb", "IIc", "III". */
const char *tippe_group_name(tippe_group g);
/* The main group of a subgroup: "I", "II" or "III". */
const char *tippe_group_family(tippe_group g);

/* Points closer than this to a boundary of the phase diagram (in k - 1 +- e,
 * k - 1 + e^2 or b -+ 1) are reported as lying on it. */
#define TIPPE_THEORY_BOUNDARY_TOL 1e-12

typedef struct {
    tippe_group group;       /* never undefined: on a boundary, the side chosen is documented */
    const char *boundary;    /* NULL, or the name of the boundary it lies on within 1e-12 */
    double A_over_C, eps_over_R;
    int has_b; double b, theta_b_rad;   /* eq 5.11 */
    int has_c; double c, theta_c_rad;   /* eq 5.8/5.9 */
    /* Added to the contract: b and c are real numbers more often than their angles
     * exist. has_b means b is real (k < 1 and k - 1 <= -e^2); has_theta_b means
     * also |b| <= 1, so that theta_b_rad = acos(b) is the fold angle. has_c means
     * k != 1; has_theta_c means |c| <= 1 (groups I and III), where theta_c_rad
     * bounds the intermediate states. theta_*_rad is 0 when its flag is 0. */
    int has_theta_b, has_theta_c;
} tippe_theory_class;

/* Classifies (k, e) by Theorem 5.1. TIPPE_EINPUT unless k > 0 and 0 <= e < 1 are
 * finite numbers. Points within TIPPE_THEORY_BOUNDARY_TOL of a boundary get its
 * name in out->boundary and the group of the documented side:
 *   "A/C-1=-eps/R"     (I/II)   -> I (Ia or Ib by b): n- is infinite there, so
 *                                  theta = 0 is stable for every J, as in group I;
 *   "A/C-1=+eps/R"     (II/III) -> III: n+ is infinite, theta = pi never stable;
 *   "A/C-1=-(eps/R)^2"          -> IIb (b = 1/e > 1 on this line);
 *   "b=1"              (IIa/IIb) -> IIb: the whole branch 0 < theta < pi is stable;
 *   "b=-1"             (Ia/Ib, IIa/IIc) -> Ia or IIc: the whole branch is unstable;
 *   "A/C-1=-eps/R,b=-1"          -> Ia (the one point where both hold);
 *   "eps/R=0"          balanced ball, no preferred side: group I if k <= 1, else III.
 * A = C (k = 1, e > 0) is inside IIb with has_b = has_c = 0 and no boundary. */
int tippe_theory_classify(double A_over_C, double eps_over_R, tippe_theory_class *out);

/* Whether an intermediate state (eq 5.7) exists at theta: (k - 1) cos(theta) + e > 0. */
int tippe_theory_exists(double A_over_C, double eps_over_R, double theta);

/* Whether the intermediate state at theta (0 < theta < pi, existing) is stable, by
 * Theorem 5.1 applied to cls: Ia, IIc never; IIb, III always; Ib, IIa for
 * theta > theta_b. */
int tippe_theory_branch_stable(const tippe_theory_class *cls, double theta);

/* Dimensionless intermediate-state curve (eq 5.10): J^2 / (m g C R^3) at theta,
 *   e (C (cos th - e)^2 + A sin^2 th)^2 / (C^2 ((k - 1) cos th + e)).
 * TIPPE_EINPUT if no intermediate state exists at theta (eq 5.7). */
int tippe_theory_curve_j2(double A_over_C, double eps_over_R, double theta, double *j2);

/* One intermediate state (a relative equilibrium, U = V = 0, theta constant). */
typedef struct {
    double theta_rad;
    double phi_dot_rad_s;  /* precession rate alpha, eq 5.6 */
    double spin_rad_s;     /* n = alpha (cos theta - eps/R), eq 5.4 */
    double J;              /* eq 3.20/3.22 on the state, kg m^3/s */
} tippe_theory_state;

/* The intermediate state at theta with sign(alpha) = sign (+1 or -1): the symmetry
 * (n, alpha) -> (-n, -alpha) maps one onto the other and flips J. TIPPE_EINPUT if
 * the top or g is invalid or no intermediate state exists at theta (eq 5.7). */
int tippe_theory_intermediate(const tippe_top *top, double g, double theta, int sign,
                              tippe_theory_state *out, tippe_error *err);

/* Jellett invariant J = -L.q (eq 3.20/3.22) of a state, SI:
 *   J = C n (R cos theta - eps) + A phi_dot R sin^2 theta. */
double tippe_theory_jellett(const tippe_top *top, double theta, double phi_dot, double spin);
/* Spin of the vertical state theta = 0 (n0) and theta = pi (n_pi) with Jellett J
 * (section 5, before Theorem 5.1). */
double tippe_theory_n0(const tippe_top *top, double J);
double tippe_theory_npi(const tippe_top *top, double J);

/* The spins at which stability changes, in rad/s (eq 5.11, A.14, A.27, section 7.1). */
typedef struct {
    tippe_theory_class cls;
    /* theta = 0 is stable iff |n0| < n-. has_n_minus = 0 where n- is infinite
     * (group I and its boundary: stable for every J). */
    int has_n_minus; double n_minus_rad_s, J_minus;
    /* theta = pi is stable iff |n_pi| > n+. has_n_plus = 0 where no spin suffices
     * (group III and its boundary). */
    int has_n_plus; double n_plus_rad_s, J_plus;
    /* n* = n+ (R + eps) / (R - eps): the spin at theta = 0 whose J puts the
     * inverted state at n+ (section 7.1). */
    int has_n_star; double n_star_rad_s;
    /* The spin at theta = 0 (n_b_0) and at theta = pi (n_b_pi) whose J equals J on
     * the curve at the fold theta_b (section 7.1, Figure 14); only in Ib and IIa,
     * where the fold lies on the branch. */
    int has_n_b; double n_b_0_rad_s, n_b_pi_rad_s, J_b;
} tippe_theory_thresholds;

int tippe_theory_compute_thresholds(const tippe_top *top, double g, tippe_theory_thresholds *out,
                                     tippe_error *err);

/* Stable final states for a given Jellett invariant (Theorem 5.1): 1 or 2 of them. */
typedef enum { TIPPE_FINAL_NO_TIP, TIPPE_FINAL_TIP, TIPPE_FINAL_HANG } tippe_final_kind;
/* state[i].spin_rad_s and phi_dot_rad_s were added to the contract: the spin and
 * precession of that state (phi_dot is 0 for a vertical state, where it is
 * arbitrary). States are sorted by theta. */
typedef struct {
    int n;
    struct {
        tippe_final_kind kind;
        double theta_rad;
        double spin_rad_s, phi_dot_rad_s;
    } state[3];
} tippe_theory_prediction;

/* theta = 0 is stable iff k - 1 <= -e or |n0| < n- (A.14); theta = pi iff
 * k - 1 < e and |n_pi| > n+ (A.27); an intermediate state is stable where the
 * curve J(theta) of eq 5.10 meets |J| with J^2 increasing in theta. J of either
 * sign. If |J| equals a threshold exactly, the vertical state where the stable
 * branch ends is returned (marginally stable). eps = 0 (balanced ball): k < 1 gives
 * both vertical states (no preferred side), k > 1 a HANG at theta = pi/2;
 * k = 1 or J = 0 is neutral (any orientation) and gives TIPPE_EINPUT. */
int tippe_theory_predict(const tippe_top *top, double g, double J, tippe_theory_prediction *out,
                         tippe_error *err);

const char *tippe_final_kind_name(tippe_final_kind kind); /* "no_tip", "tip", "hang" */

/* ---- Effective potential and its wells (docs/dynamics.md, "Proved verdicts") ----
 *
 * V(theta; J) = m g (R - eps cos theta) + J^2 / (2 D(theta)),
 * D(theta) = A R^2 sin^2 theta + C (R cos theta - eps)^2:
 * the least energy (section 4) of any state at angle theta with Jellett invariant J
 * (eq 3.20), reached with no sliding, theta_dot = 0 and the spin/precession split
 * that minimises the kinetic energy for that J. In J. Along a motion in contact,
 * E(t) >= V(theta(t); J). */
double tippe_theory_potential(const tippe_top *top, double g, double J, double theta);
/* dV/dtheta, in J/rad. */
double tippe_theory_potential_slope(const tippe_top *top, double g, double J, double theta);

enum { TIPPE_THEORY_MAX_CRIT = 10, TIPPE_THEORY_MAX_WELLS = 3 };

/* A well of V: the interval between two neighbouring interior maxima (or 0, pi:
 * the poles separate nothing, theta passes through them), holding exactly one
 * local minimum. */
typedef struct {
    double theta_min_rad;   /* the minimum, to ~1e-14 rad: a steady state (Theorem 5.1) */
    double V_min;           /* J */
    double theta_lo_rad, theta_hi_rad; /* its ends: interior maxima, or 0 and pi */
    double V_escape;        /* J, the lower of the V at its interior maxima (INFINITY if none):
                               with E below this, theta can never leave the well */
    double curvature;       /* J/rad^2, V'' at the minimum (> 0) */
    int flat;               /* 1 if the minimum or an end is degenerate (V'' ~ 0 there,
                               or a double critical point nearby): no decision there */
} tippe_theory_well;

typedef struct {
    double J;                                  /* the J they were computed for */
    int n_crit;                                /* critical points in [0, pi], sorted */
    double crit_theta_rad[TIPPE_THEORY_MAX_CRIT];
    int crit_kind[TIPPE_THEORY_MAX_CRIT];      /* -1 minimum, +1 maximum, 0 neither (a
                                                  double point where V' keeps its sign) */
    int crit_degenerate[TIPPE_THEORY_MAX_CRIT]; /* 1 if |V''| is below 1e-9 of its scale */
    double crit_V[TIPPE_THEORY_MAX_CRIT];      /* J */
    int n_wells;
    tippe_theory_well well[TIPPE_THEORY_MAX_WELLS];
} tippe_theory_wells;

/* All critical points of V(.; J) on [0, pi] and its wells. The critical points are
 * theta = 0, pi (always) and the roots in (-1, 1) of the quartic in x = cos theta
 *   G(x) = e P(x)^2 - T ((k - 1) x + e),  P(x) = (x - e)^2 + k (1 - x^2),
 *   T = J^2 / (m g C R^3),
 * since dV/dtheta = m g R sin(theta) G(cos theta) / P^2; G = 0 is eq 5.10 (the
 * intermediate states). The roots are isolated on intervals where G is monotone,
 * found from the roots of G', whose own monotone pieces come from the quadratic
 * G'' in closed form: a subdivision proven complete, no sampling. A critical point
 * where |V''| < 1e-9 of its natural scale (m g eps + J^2 / (C R^2)) is degenerate
 * and makes the wells it touches flat. TIPPE_EINPUT for a bad top, g or J. */
int tippe_theory_find_wells(const tippe_top *top, double g, double J, tippe_theory_wells *out,
                            tippe_error *err);

/* The index of the well whose [theta_lo, theta_hi] holds theta (the lower on a tie). */
int tippe_theory_well_index(const tippe_theory_wells *w, double theta);

/* The part of well i where V <= E: [*lo, *hi] around its minimum, found by bisection
 * on the monotone sides to 1e-14 rad. E below V_min gives lo = hi = theta_min. */
void tippe_theory_well_range(const tippe_top *top, double g, const tippe_theory_wells *w, int i,
                             double E, double *lo, double *hi);

#endif
