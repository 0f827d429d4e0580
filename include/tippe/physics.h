/* tippe/physics.h: the physics of a top: the paper's theory (section 5), the equations of motion and their proved verdicts (section 3), hand launches and maps.
 *
 * One public header per module (docs/architecture.md); the sections below keep
 * the notes of the headers they were. */
#ifndef TIPPE_PHYSICS_H
#define TIPPE_PHYSICS_H

#include <stdint.h>

#include "tippe/base.h"
#include "tippe/design.h"

/* ==== from tippe/theory.h ==== */
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

/* ==== from tippe/dynamics.h ==== */
/* Dynamics: one launch of an eccentric sphere on a table (paper section 3).
 *
 * The model: a sphere (tippe_top) on a horizontal plane under gravity g, with
 * the normal force of the contact constraint (eq 3.17/3.19, any mass m) and
 * friction: viscous Rf = -mu Rn V_Q (eq 3.12, mu in s/m), or Coulomb: sliding
 * |Rf| = mu_c Rn against the slip (regularised below a stated slip speed v_s,
 * Rf = -mu_c Rn V_Q / sqrt(|V_Q|^2 + v_s^2)) and sticking, rolling without
 * slipping while the force that needs stays inside the cone |Rf| <= mu_c Rn
 * (event-driven, as Leine and Glocker 2003; docs/dynamics.md, "Coulomb friction").
 *
 * The equations are integrated in a lab-frame form that is regular at
 * theta = 0 and pi: the state is the symmetry axis k (unit vector), the
 * angular velocity omega and the horizontal velocity of the centre of mass,
 * plus the dissipated energy. The paper's Euler-angle form (3.15-3.18), which
 * is singular where sin(theta) = 0, is provided separately as a reference.
 * docs/dynamics.md derives both and documents every criterion used here.
 *
 * Everything is reentrant: no globals, no static mutable state; every
 * tippe_dynamics_run() call owns its GSL driver, so many launches may run at
 * once on OpenMP threads. */

/* Verdicts no_tip, tip and hang are proved (docs/dynamics.md, "Proved verdicts"):
 * the energy is below every barrier of the effective potential V(theta; J) around
 * the current well and the normal force stays positive over the trapped set, so the
 * top ends in the well's minimum. */
typedef enum {
    TIPPE_VERDICT_NO_TIP,       /* trapped in the well of theta = 0 */
    TIPPE_VERDICT_TIP,          /* trapped in the well of theta = pi */
    TIPPE_VERDICT_HANG,         /* trapped in a well whose minimum is 0 < theta < pi */
    TIPPE_VERDICT_LOST_CONTACT, /* Rn reached 0: the top leaves the table */
    TIPPE_VERDICT_UNDECIDED,    /* t_end (or the step budget) reached first */
    TIPPE_VERDICT_BOUNDED       /* mu = 0 (nothing dissipates), eps = 0 (rolling
                                   dissipates nothing), or (Coulomb) rolling for ever
                                   across pi/2: no rest state is forced, but theta stays
                                   for ever in [theta_lo_rad, theta_hi_rad] */
} tippe_verdict;

/* With Coulomb sticking (nothing dissipates while the top rolls) a tip is the
 * inverted state reached: theta proved to stay within this of pi for ever (30
 * deg: the M12 ball at Z2 = 15 mm launched at 300 rad/s sticks and rolls for ever
 * at 155.5 deg, upside down; at 30 rev/s it rolls at 137.8 deg, tilted 42 deg off
 * inverted: bounded, with its range). */
#define TIPPE_INVERTED_TOL_RAD 0.52359877559829882 /* 30 deg */

/* "no_tip", "tip", "hang", "lost_contact", "undecided", "bounded". */
const char *tippe_verdict_name(tippe_verdict v);

/* How a verdict was reached. */
typedef enum {
    TIPPE_DECIDED_T_END,        /* not decided: t_end reached */
    TIPPE_DECIDED_TRAPPED,      /* energy below the well's barrier, contact bound > 0 */
    TIPPE_DECIDED_LOST_CONTACT, /* Rn crossed 0 (located by bisection) */
    TIPPE_DECIDED_FLAT_WELL,    /* undecided for ever at this accuracy: confined to a well
                                   that is flat, or whose barrier above its minimum is
                                   within the energy margin (which never shrinks) */
    TIPPE_DECIDED_BUDGET,       /* not decided: the step budget ran out before t_end */
    TIPPE_DECIDED_ROLLING,      /* Coulomb friction: the top rolls without slipping, and
                                   over one whole period of its nutation (the rolling
                                   sphere is integrable: the motion repeats) the force
                                   that rolling needs stayed inside the friction cone,
                                   so it rolls for ever, theta within the period's range
                                   (no_tip below pi/2, tip above, else bounded) */
    TIPPE_DECIDED_OBSERVED,     /* patch friction: NOT proved. The drilling torque changes
                                   Jellett's J, on which every proof rests, so the run goes
                                   to t_end and the verdict is the state observed there
                                   (no_tip within 0.25 rad of theta = 0, tip within 0.25
                                   rad of pi, else hang); end_state_proved 0 and
                                   unproved_reason says why */
    TIPPE_DECIDED_ENERGY_CONE   /* patch friction: no_tip proved without J. The energy only
                                   falls and E >= m g (R - eps cos theta), so once E and its
                                   margin are below that height at 0.25 rad, theta stays
                                   below theta_hi_rad (< 0.25 rad) for ever; the rest state
                                   within it is not proved (end_state_proved 0) */
} tippe_decision;

/* "t_end", "trapped", "lost_contact", "flat_well", "budget", "rolling", "observed". */
const char *tippe_decision_name(tippe_decision d);

/* The friction law. Zero (viscous) is the paper's, so a model initialised with
 * only {top, g, mu} keeps eq 3.12. */
typedef enum {
    TIPPE_FRICTION_VISCOUS = 0, /* Rf = -mu Rn V_Q (eq 3.12), mu in s/m */
    TIPPE_FRICTION_COULOMB = 1, /* sliding: Rf = -mu_c Rn V_Q / sqrt(|V_Q|^2 + v_s^2)
                                   (Coulomb's |Rf| = mu_c Rn against the slip for
                                   |V_Q| >> v_s); sticking once |V_Q| < 30 v_s and rolling
                                   needs |Rf| <= mu_c Rn, until it needs more */
    TIPPE_FRICTION_COULOMB_CREEP = 2, /* the regularised sliding law alone, no sticking:
                                   below v_s the contact creeps (|Rf| < mu_c Rn) and
                                   dissipates; kept to measure what the stick phase
                                   changes (docs/dynamics.md) */
    TIPPE_FRICTION_PATCH = 3    /* Coulomb-Contensou (issue 27): Coulomb's law mu_c over a
                                   circular patch of radius patch_radius_m (Hertz pressure)
                                   that slides and drills: the force and the drilling torque
                                   M about e3 of tippe_contact_patch_friction (v_s
                                   regularises the point v = 0, omega_n = 0). Smooth through
                                   slip 0 while the patch spins: no stick phase. Radius 0:
                                   coulomb-creep. Verdicts are observed, not proved
                                   (TIPPE_DECIDED_OBSERVED) */
} tippe_friction_law;

/* "viscous", "coulomb", "coulomb-creep", "patch"; tippe_friction_law_parse returns -1 for an
 * unknown name. */
const char *tippe_friction_law_name(tippe_friction_law law);
int tippe_friction_law_parse(const char *name);

/* The regularisation speed v_s of the Coulomb law when the model leaves it 0, m/s:
 * the sliding law's width and the slip below which sticking is tried.
 * docs/dynamics.md measures the reported times against smaller v_s. */
#define TIPPE_COULOMB_SLIP_SCALE_M_S 1e-5

/* The patch law's creep reduction (docs/dynamics.md, "The creep reduced"): where the
 * creep would relax the slip faster than this many times the motion's rate
 * (|omega| + sqrt(g/R)), it is slowed to that rate, so that the explicit rk8pd
 * serves; the slip's lag is then off by O(1/cap). The front ends' default; a model's
 * creep_cap of 0 integrates the full law. */
#define TIPPE_PATCH_CREEP_CAP 20.0

typedef struct {
    tippe_top top;
    double g;  /* m/s^2 */
    double mu; /* s/m, viscous sliding friction coefficient (eq 3.12), >= 0 */
    tippe_friction_law law;  /* TIPPE_FRICTION_VISCOUS (0) uses mu, the others mu_c */
    double mu_c;             /* Coulomb friction coefficient (dimensionless), >= 0 */
    double slip_scale_m_s;   /* Coulomb's regularisation speed v_s, m/s (0: the default
                                TIPPE_COULOMB_SLIP_SCALE_M_S) */
    double patch_radius_m;   /* law patch: the contact patch's radius a at the static load
                                m g, m, >= 0; 0 with patch_E_star_pa > 0: Hertz's radius
                                at m g (tippe_contact_hertz_radius); both 0: a point
                                (a = 0). During the run it follows the normal force unless
                                patch_radius_fixed */
    int patch_radius_fixed;  /* law patch: 1: the radius is held constant through the run
                                (Leine and Glocker's model); 0 (the default): it follows
                                the normal force, a (Rn / m g)^(1/3), as Hertz's radius of
                                an elastic sphere on a flat does (Johnson 1985, eq 4.22) */
    double patch_E_star_pa;  /* law patch: the contact modulus E* of ball and table, Pa
                                (tippe_contact_hertz_modulus), or 0 */
    double rolling_arm_m;    /* law patch: rolling resistance, a couple -Rn arm w_roll /
                                sqrt(|w_roll|^2 + w_s^2) against the horizontal angular
                                velocity (tippe_contact_rolling_resistance, w_s 1e-3 rad/s);
                                m, >= 0; 0 (the default): off */
    double creep_cap;        /* law patch: the creep reduction's cap (TIPPE_PATCH_CREEP_CAP,
                                the front ends' default), >= 0; 0: the full law, which
                                the presets' rk8pd integrates as msbdf */
} tippe_dynamics_model;

/* The patch radius a model's run uses (m): patch_radius_m if > 0, else Hertz's at
 * N = m g if patch_E_star_pa > 0, else 0. 0 for the other laws. */
double tippe_dynamics_patch_radius(const tippe_dynamics_model *model);

/* The bound on |dJ/dt| under the patch law at the static load, kg m^3/s^2: the drilling
 * couple changes J at dJ/dt = M (R - eps cos theta) (docs/dynamics.md), and Hertz's
 * pressure bounds |M| by (3 pi / 16) mu_c Rn a, so |dJ/dt| <= (3 pi / 16) mu_c m g a (R + eps)
 * at Rn = m g (the radius a at m g). 0 under the other laws. */
double tippe_dynamics_jellett_rate_bound(const tippe_dynamics_model *model);

/* The stepper a run under law uses for the named one: the presets' rk8pd runs as msbdf
 * under the patch law's full creep (creep_cap 0: stiff as the spin about the vertical
 * drains; docs/dynamics.md, "Patch friction"), any other as named. */
const char *tippe_dynamics_stepper_used(tippe_friction_law law, double creep_cap,
                                        const char *stepper);

/* The reason a patch-law verdict is not proved (tippe_dynamics_result.unproved_reason). */
#define TIPPE_PATCH_UNPROVED_REASON "J changes under drilling friction: not proved"
/* The reason a verdict of a run whose contact stood on a rim is not proved: the rim's
 * friction has a lever arm about the axis, so J changes there, and a motion that may
 * come back to the rim has no well of V(theta; J) to be trapped in (docs/dynamics.md,
 * "The contact on a rim"). */
#define TIPPE_RIM_UNPROVED_REASON "J changes while the top stands on a rim: not proved"

/* Whether the model's friction is zero (no dissipation at all). */
int tippe_dynamics_frictionless(const tippe_dynamics_model *model);

/* A launch in the paper's variables (eq 3.4): nutation angle theta in [0, pi],
 * its rate, the precession rate phi_dot (alpha), the spin n = omega.k, and the
 * velocity of the centre of mass along e1 (horizontal direction of the axis k)
 * and e2 = e3 x e1. At sin(theta) = 0, phi_dot does not enter the state and
 * e1 is the lab x axis. The launch has phi = psi = 0 and the centre of mass
 * above the lab origin. */
typedef struct {
    double theta, theta_dot, phi_dot, spin, U, V; /* rad, rad/s, rad/s, rad/s, m/s, m/s */
} tippe_dynamics_initial;

/* Named precession rates that keep theta stationary at launch (theta_dot = 0,
 * U = 0): the roots alpha of A cos(theta) alpha^2 - C n alpha - m g eps = 0
 * (eq 3.15 with theta_ddot = 0 and Rn = m g). With D = C^2 n^2 + 4 A m g eps cos(theta):
 *   STEADY: (C n + sgn(n) sqrt(D)) / (2 A cos theta)  (sec 7.1 / Figure 12 near theta = 0)
 *   S1:     (C n + sqrt(D)) / (2 A cos theta)          (Figure 14's s1 near theta = pi)
 *   S2:     (C n - sqrt(D)) / (2 A cos theta)          (s2)
 *   S3:      C n / (2 A cos theta)                     (s3: the real part when D < 0)
 * TIPPE_EINPUT if cos(theta) = 0 or (STEADY, S1, S2) D < 0. */
typedef enum {
    TIPPE_PRECESSION_STEADY,
    TIPPE_PRECESSION_S1,
    TIPPE_PRECESSION_S2,
    TIPPE_PRECESSION_S3
} tippe_precession_rule;
int tippe_dynamics_precession(const tippe_dynamics_model *model, double theta, double spin,
                              tippe_precession_rule rule, double *phi_dot, tippe_error *err);

/* Integrator choice: a GSL odeiv2 stepper by name (rk2, rk4, rkf45, rkck, rk8pd,
 * rk1imp, rk2imp, rk4imp, bsimp, msadams, msbdf) and a relative tolerance. The
 * absolute tolerance is rtol times a per-component scale (docs/dynamics.md). */
typedef struct {
    char stepper[16];
    double rtol;
} tippe_dynamics_accuracy;

/* The named presets "fast", "balanced", "precise" (one table in dynamics.c). */
int tippe_dynamics_accuracy_preset(const char *name, tippe_dynamics_accuracy *out,
                                   tippe_error *err);
int tippe_dynamics_n_presets(void);
const char *tippe_dynamics_preset_name(int i);
/* 1 if name is one of the allowed steppers. */
int tippe_dynamics_stepper_known(const char *name);

typedef enum {
    TIPPE_LEVEL_VERDICT,   /* reduced state (9 components), no samples */
    TIPPE_LEVEL_TRAJECTORY /* adds orientation and position (15), samples */
} tippe_dynamics_level;

/* The state at one time, in the paper's variables plus monitors. */
typedef struct {
    double t;                                      /* s */
    double theta, theta_dot, phi_dot, spin, U, V;  /* as tippe_dynamics_initial */
    double phi, psi, x, y;  /* rad, rad, m, m: trajectory level only (NAN otherwise) */
    double Rn;              /* N, normal force (eq 3.19) */
    double slip_speed;      /* m/s, |V_Q| (eq 3.9) */
    double E;               /* J, energy (sec 4) */
    double D;               /* J, energy dissipated so far (integral of eq 4.1) */
    double J;               /* kg m^3/s, Jellett -L.q (eq 3.20) */
    double patch_radius;    /* m, the contact patch's radius at this Rn (patch law; 0 else) */
    double drill_torque;    /* N m, the drilling couple about the table's normal (patch law;
                               0 else): what changes J (docs/dynamics.md) */
    int rim;                /* where the contact is: 0 the sphere; 1 the rim of the opening
                               at the pole down at theta = 0, 2 at the other pole
                               (tippe_dynamics_options.cap_half_angle_rad) */
} tippe_dynamics_sample;

/* Called for each sample; a nonzero return stops the run (TIPPE_ECOMPUTE,
 * with the callback's code in the message). */
typedef int (*tippe_dynamics_sample_fn)(const tippe_dynamics_sample *s, void *ctx);

typedef struct {
    tippe_dynamics_level level;
    double t_end;                      /* s */
    tippe_dynamics_accuracy accuracy;
    /* Trajectory level: one sample every sample_dt seconds (the integrator
     * lands on these times), or every accepted step if sample_dt <= 0. */
    double sample_dt;
    tippe_dynamics_sample_fn on_sample;
    void *sample_ctx;
    /* The energy margin of a decision is margin_factor times (energy-balance
     * error + the change of V that the Jellett drift can make), docs/dynamics.md. */
    double margin_factor;
    int run_to_t_end;  /* 1: record the verdict but keep integrating to t_end */
    /* 1: after a tip verdict, integrate on until theta first passes pi/2 so that
     * t_flip is known (a verdict is usually proved well before the flip). */
    int until_flip;
    /* Step budget: the run stops, undecided, with budget_exhausted set, after
     * this many accepted steps or 20 times as many RHS evaluations, whichever
     * comes first (an implicit stepper's step can cost ~240; 0: no budget). Bounds
     * the work of a launch that never settles (mu = 0, or a t_end of millions of
     * periods, or a stiff law: the creep law at a small v_s). */
    long max_steps;
    /* Where the surface is not the sphere (tippe_design_polar_caps): the half-
     * angle of a hole's opening at the pole down at theta = 0 ([0]) and at the
     * other pole ([1]), rad, below pi/2; 0 (the default) where the sphere is whole.
     * The run records the time its contact spends within them (cap_time_s). The
     * contact itself follows the top's outline (tippe_top.rim_half_angle_rad): the
     * sphere cut flat at each opening, so a top tilted less than the half-angle on
     * that pole stands on the opening's rim (radius R sin(half-angle)), and exactly
     * upright on the whole ring (docs/dynamics.md, "The contact on a rim"), under
     * every law. */
    double cap_half_angle_rad[2];
    /* 1: the contact stays on the sphere even within an opening (the model before
     * issue 35, kept to compare: the run then only records the time spent there) */
    int sphere_contact_only;
} tippe_dynamics_options;

/* Trajectory samples kept in memory (simulate's and check's --csv and --plot): pass
 * tippe_dynamics_samples_keep as on_sample and a zeroed tippe_dynamics_samples as
 * sample_ctx; free with tippe_dynamics_samples_free. keep returns 1 when out of memory. */
typedef struct {
    int n, cap;
    tippe_dynamics_sample *s;
} tippe_dynamics_samples;
int tippe_dynamics_samples_keep(const tippe_dynamics_sample *s, void *ctx);
void tippe_dynamics_samples_free(tippe_dynamics_samples *b);
/* The default sample interval of a trajectory of ic on a top of radius R_m under g:
 * 16 samples per turn at the launch's rotation rate (so that plots resolve the
 * precession), within t_end/10^5 .. t_end/10^4 s. */
double tippe_dynamics_default_sample_dt(const tippe_dynamics_initial *ic, double g,
                                        double R_m, double t_end);
/* The samples as CSV, a header with units and one row per sample (%.10g):
 * t_s,theta_rad,theta_dot_rad_s,phi_dot_rad_s,spin_rad_s,U_m_s,V_m_s,Rn_N,slip_speed_m_s,
 * E_J,J_kg_m3_s,dissipated_J,phi_rad,psi_rad,x_m,y_m,patch_radius_m,drill_torque_N_m. */
void tippe_dynamics_write_csv(FILE *out, const tippe_dynamics_sample *s, int n);

/* Defaults: verdict level, t_end 100 s, preset "balanced", margin_factor 10,
 * sample_dt 0, no callback, until_flip 0, max_steps 1e7 (a few seconds of one
 * core at the verdict level with rk8pd; docs/performance.md). */
void tippe_dynamics_options_default(tippe_dynamics_options *o);

typedef struct {
    tippe_verdict verdict;
    tippe_decision how;          /* how it was reached */
    double t_verdict;            /* s, when the verdict was reached (decision time) */
    tippe_dynamics_sample final; /* state at t_verdict (not the end state: see below) */
    /* The end state. Trapped: the well's minimum of V (to ~1e-14 rad) and the steady
     * state there for J0 (tippe_theory_intermediate, n0 or n_pi; phi_dot 0 on the
     * vertical); bounded: the minimum the motion oscillates about; otherwise the
     * state at t_verdict. */
    double theta_final_rad, spin_final_rad_s, phi_dot_final_rad_s;
    /* Trapped or bounded: theta stays in [theta_lo_rad, theta_hi_rad] (the part of
     * the well where V <= E + margin); the barrier gap is the least other critical
     * value of V in the well minus E (INFINITY if the well has none), the margin
     * the energy margin demanded, Rn_bound_N the lower bound of Rn over that set.
     * NAN when not trapped. */
    double theta_lo_rad, theta_hi_rad, barrier_gap_J, margin_J, Rn_bound_N;
    double t_flip;               /* s, first time theta passed pi/2 upwards (NAN if it did
                                    not), linear between accepted steps */
    double t_fall;               /* s, first time after t_flip that theta came back below
                                    pi/2 (NAN if it did not): a patch-law top that drains
                                    its spin falls back */
    double inverted_time_s;      /* s, model time spent above pi/2 (between accepted steps
                                    on the same side, up to the end of the run) */
    /* s, model time the contact spent within a hole's opening at a pole
     * (tippe_dynamics_options.cap_half_angle_rad: theta below [0] or above pi - [1]),
     * between accepted steps both within, up to where the run stopped; the first
     * and last times it was there (NAN: never). Where it is, the model's sphere
     * contact does not hold. */
    double cap_time_s, cap_first_s, cap_last_s;
    tippe_dynamics_sample last;  /* state where integration stopped */
    double J0, E0;               /* at launch */
    double jellett_rel_drift;    /* max |J - J0| / max(|J0|, 1e-6 C W R),
                                                       W = |omega0| + sqrt(g/R); under the
                                    patch law the drilling's change, not an error */
    double jellett_drift_time_s; /* patch law: |J0| / tippe_dynamics_jellett_rate_bound, how
                                    soon drilling at m g could change J by all of J0
                                    (NAN under the other laws, or with mu_c or a 0) */
    double energy_rel_error;     /* max |E + D - E0| / E0 */
    double energy_max_rise;      /* J, max over steps of E(t_i) - min_{j<i} E(t_j) (>= 0) */
    double creep_energy_J;       /* J, the patch law's creep reduction: the integral of
                                    |the power it changed| (its energy error's estimate; in
                                    the energy cone's margin). 0 with the full law */
    double min_Rn;               /* N, smallest normal force at an accepted step */
    long rhs_evals;              /* including those of a finite-difference Jacobian */
    long steps, rejected_steps;
    int state_dim;               /* 9 at verdict level, 15 at trajectory level */
    int budget_exhausted;        /* 1 if the run stopped at max_steps before t_end */
    /* Coulomb friction with sticking: how often the contact stuck (began rolling
     * without slipping) and broke loose, the model time spent rolling, and whether
     * it rolls at t_verdict. While rolling nothing dissipates, so a trapped verdict
     * proves the well and the range [theta_lo_rad, theta_hi_rad] but not the end
     * state: end_state_proved is 0 (1 for viscous and creeping friction). */
    long stick_events, slip_events;
    /* Switches of the contact between the sphere and a rim (an event each, located
     * to 1e-13 of the step), and the spin at the first time the contact left a rim
     * it was launched on (rad/s; NAN if it was not launched on one or never left):
     * what the rim drained. */
    long rim_switches;
    double spin_leaving_rim_rad_s;
    int rim_touched;             /* the contact stood on a rim at some time */
    double rolling_time_s;
    int rolling;
    int end_state_proved;
    /* Why the verdict is not proved where a proof is out of reach (a static string,
     * TIPPE_PATCH_UNPROVED_REASON under the patch law), NULL otherwise. */
    const char *unproved_reason;
} tippe_dynamics_result;

/* Integrates one launch. TIPPE_EINPUT for an invalid model, launch or option,
 * TIPPE_ECOMPUTE if the integrator fails or the contact force is undetermined
 * (the denominator of eq 3.19 reaches 0: friction too strong for the model). */
int tippe_dynamics_run(const tippe_dynamics_model *model, const tippe_dynamics_initial *ic,
                       const tippe_dynamics_options *opt, tippe_dynamics_result *res,
                       tippe_error *err);

/* Energy, Jellett invariant, normal force and contact speed of a launch state
 * (fields t, phi, psi, x, y, D of *out are 0). */
int tippe_dynamics_evaluate(const tippe_dynamics_model *model, const tippe_dynamics_initial *s,
                            tippe_dynamics_sample *out, tippe_error *err);

/* The slip of the contact point at a launch state, m/s: |V_Q| = |v + omega x q|
 * (eq 3.7; v the velocity of the centre of mass, q the vector from it to the
 * contact, eq 3.6). It does not depend on the friction law or g. NAN for a top
 * or state tippe_dynamics_evaluate refuses. */
double tippe_dynamics_launch_slip(const tippe_top *top, const tippe_dynamics_initial *ic);

/* The contact is at rest at a launch when its slip is below this fraction of the
 * speed scale R |omega| + |v| (rounding: the terms of V_Q are of that size and
 * cancel to ~1e-16 of it where they cancel at all). */
#define TIPPE_LAUNCH_SLIP_ROUNDING_REL 1e-12

/* How a launch state slides, in words for the launch lines of check, simulate,
 * animate: "no sliding (contact at rest)" only where the slip
 * (tippe_dynamics_launch_slip) is 0 to rounding; otherwise "centre at rest (U = V =
 * 0), contact slip 0.0222 m/s" or "centre sliding at 0.05 m/s (U 0.03, V 0.04 m/s),
 * contact slip 0.071 m/s". *slip_m_s (may be NULL) gets the slip. Returns buf. */
const char *tippe_launch_slip_text(const tippe_top *top, const tippe_dynamics_initial *ic,
                                   double *slip_m_s, char *buf, size_t size);

/* The friction law of a model in words, with its coefficients ("viscous mu 2.3
 * s/m (eq 3.12)", "Coulomb mu_c 0.3, sliding and sticking (...)", "patch
 * (Coulomb-Contensou) mu_c 0.3 on Hertz's patch at m g (...)"). Returns buf. */
const char *tippe_dynamics_friction_text(const tippe_dynamics_model *m, char *buf, size_t size);

/* Reference: the paper's Euler-angle equations (3.15-3.19, derived for any m),
 * valid for 0 < theta < pi. y = (theta, theta_dot, phi_dot, spin, U, V, phi, psi),
 * dydt its derivative; *Rn the normal force. TIPPE_ECOMPUTE where sin(theta) = 0
 * or the contact force is undetermined. */
enum { TIPPE_EULER_DIM = 8 };
int tippe_dynamics_euler_rhs(const tippe_dynamics_model *model, const double y[TIPPE_EULER_DIM],
                             double dydt[TIPPE_EULER_DIM], double *Rn);

/* ==== from tippe/launch.h ==== */
/* Launch: many hand launches of a top, and what they end in.
 *
 * A hand launch is a spin, a tilt of the symmetry axis away from the vertical,
 * a precession rate near the steady one for that tilt and spin, and a small
 * sliding velocity of the centre of mass in a random direction, drawn from
 * distributions whose defaults describe a hand-spun top of 50 mm diameter
 * (docs/launch.md justifies each default). Each launch runs through the
 * dynamics core at the verdict level (tippe/physics.h) and is compared with
 * Theorem 5.1's stable final states for its own Jellett invariant.
 *
 * Reproducibility: launch number `draw` of a run with seed S takes its random
 * numbers from its own GSL generator (mt19937) seeded by tippe_launch_mix(S,
 * draw), so a launch's initial state and outcome depend only on (S, draw, the
 * top, the options), not on the order in which launches run, on the number of
 * threads or on the number of MPI ranks. Results go to per-index slots and are
 * tallied in index order, so tallies are bit-identical whatever the parallelism.
 *
 * Everything here is reentrant; tippe_launch_run() runs its launches on OpenMP
 * threads (schedule(dynamic): launches differ in length by orders of magnitude). */

/* The launch distributions and the model they run in. */
typedef struct {
    double spin_from_rev_s, spin_to_rev_s; /* spin n uniform in [from, to], rev/s */
    double tilt_sd_rad;       /* tilt theta0 half-normal with this scale, rad */
    double tilt_max_rad;      /* draws above this are drawn again (< pi/2), rad */
    double precession_sd_rel; /* phi_dot = steady rate * (1 + sd * N(0, 1)) */
    double slide_sd_m_s;      /* sliding speed half-normal with this scale, m/s;
                                 direction uniform in [0, 2 pi) */
    tippe_friction_law law;   /* friction law (default viscous, eq 3.12) */
    double mu;                /* s/m, viscous sliding friction (eq 3.12), law viscous */
    double mu_c;              /* Coulomb coefficient, the Coulomb laws */
    double slip_scale_m_s;    /* Coulomb's regularisation speed v_s (0: the default) */
    double creep_cap;         /* law patch: the creep reduction's cap (default
                                 TIPPE_PATCH_CREEP_CAP; 0: the full law) */
    double patch_radius_m;    /* law patch: the patch radius, m (0: Hertz from E*) */
    double patch_E_star_pa;   /* law patch: contact modulus for Hertz at m g, Pa (or 0) */
    double patch_radius_span; /* law patch: the radius sensitivity runs at a/F and a F with
                                 this F (> 1; 0: TIPPE_LAUNCH_RADIUS_SPAN); a design's is its
                                 tolerance on contact.patch_radius
                                 (tippe_design_patch_radius_span) */
    double g;                 /* m/s^2 */
    double t_end;             /* s, bound on each launch's simulated time */
    int until_flip;           /* 1: follow a tip to its flip (t_flip_s), 0: stop at the proof */
    /* the holes' openings at the pole down at theta = 0 and at the other, rad
     * (tippe_launch_polar_caps; 0: the sphere is whole): each launch records the
     * time its contact spends there (tippe_launch_record.cap_time_s) */
    double cap_half_angle_rad[2];
    /* 1: every launch's contact stays on the sphere within an opening (the model
     * before issue 35; tippe_dynamics_options.sphere_contact_only), to compare */
    int sphere_contact_only;
    char accuracy_name[16];   /* a preset of tippe/physics.h, or "custom" */
    tippe_dynamics_accuracy accuracy;
} tippe_launch_options;

/* Viscous friction (eq 3.12) for a plastic ball on a table, s/m: a Coulomb
 * coefficient of about 0.3 divided by a typical contact slip speed of 0.13 m/s
 * (docs/launch.md derives it and gives the sources). */
#define TIPPE_LAUNCH_DEFAULT_MU_S_M 2.3

/* Coulomb friction of a printed (PLA or nylon) ball on a tabletop: 0.3, within the
 * published 0.2-0.5 for plastic on wood or laminate (docs/launch.md gives the sources). */
#define TIPPE_LAUNCH_DEFAULT_MU_C 0.3

/* The median of a half-normal distribution of scale 1 (sqrt(2) erf^-1(1/2)):
 * a central launch's tilt is this times the tilt scale. */
#define TIPPE_LAUNCH_HALF_NORMAL_MEDIAN 0.6744897501960817

/* The documented defaults (docs/launch.md): spin 5..25 rev/s, tilt scale
 * 0.1 rad (redrawn above 1 rad), precession spread 0.1, sliding 0.05 m/s,
 * viscous friction mu TIPPE_LAUNCH_DEFAULT_MU_S_M (eq 3.12; mu_c TIPPE_LAUNCH_DEFAULT_MU_C
 * if the law is set to Coulomb), g TIPPE_DEFAULT_G_M_S2,
 * t_end 600 s, preset "balanced", until_flip 1. */
void tippe_launch_options_default(tippe_launch_options *o);

/* TIPPE_EINPUT naming the first bad field. */
int tippe_launch_options_check(const tippe_launch_options *o, tippe_error *err);

/* The seed of launch `draw` of a run with seed `seed`: the (draw + 1)-th output
 * of a splitmix64 generator whose state is the first output of a splitmix64
 * generator started at `seed` (docs/launch.md). */
uint64_t tippe_launch_mix(uint64_t seed, uint64_t draw);

/* Draws launch `draw`'s initial state. The random numbers are always drawn in
 * the same order (spin, tilt, precession, sliding speed, sliding direction);
 * spin_rad_s, if finite, then replaces the drawn spin (a map cell's spin), so
 * that the other variables of a draw are the same at every spin. */
int tippe_launch_draw(const tippe_top *top, const tippe_launch_options *o, uint64_t seed,
                      uint64_t draw, double spin_rad_s, tippe_dynamics_initial *ic,
                      tippe_error *err);

/* The central hand launch (for `tippe check`): the median tilt of the
 * half-normal (0.674 tilt_sd_rad), steady precession, the centre at rest
 * (U = V = 0; the contact point slips: tippe_dynamics_launch_slip), and the
 * given spin (rad/s). */
int tippe_launch_central(const tippe_top *top, const tippe_launch_options *o, double spin_rad_s,
                         tippe_dynamics_initial *ic, tippe_error *err);

/* A hang agrees with theory when the angles differ by less than this, rad: a
 * proved hang reports the well's minimum of V, a root of eq 5.10 like theory's
 * angle, so both agree to ~1e-12; 1e-8 leaves room for ill-conditioned roots. */
#define TIPPE_LAUNCH_HANG_AGREE_RAD 1e-8

enum { TIPPE_LAUNCH_N_VERDICTS = 6 }; /* tippe_verdict values 0 .. 5 */

/* One launch and its outcome. Plain data (no pointers), so that records can be
 * sent between MPI ranks as bytes. */
typedef struct {
    long index;              /* position in the run */
    long draw;               /* the random draw it used (tippe_launch_mix) */
    int status;              /* TIPPE_OK, or the dynamics' error code */
    tippe_dynamics_initial ic;
    tippe_verdict verdict;
    double t_s;              /* s, when the verdict was reached (decision time) */
    tippe_decision how;      /* trapped, lost_contact or t_end */
    double theta_final_rad;  /* the end state (tippe_dynamics_result.theta_final_rad) */
    double spin_final_rad_s; /* its spin */
    double barrier_gap_J, margin_J; /* of a trapped decision (NAN otherwise) */
    /* trapped or bounded: theta stays in [theta_lo_rad, theta_hi_rad] with Rn above
     * Rn_bound_N (NAN otherwise); a bounded launch has no end state (NAN) */
    double theta_lo_rad, theta_hi_rad, Rn_bound_N;
    double t_flip_s;         /* s, theta first passed pi/2 (NAN: not, or not followed) */
    /* s, time the contact spent within a hole's opening at a pole up to t_s, and
     * the first time it was there (NAN: never): the model does not hold there */
    double cap_time_s, cap_first_s;
    /* the contact stood on a rim (1) at some time; its switches between sphere and
     * rim; the spin when it first left the rim it was launched on (NAN: did not) */
    int rim_touched;
    long rim_switches;
    double spin_leaving_rim_rad_s;
    double t_fall_s;         /* s, first came back below pi/2 after t_flip_s (NAN: did not) */
    double inverted_time_s;  /* s, model time spent above pi/2 */
    double energy_rel_error; /* max |E + D - E0| / E0 over the run */
    double creep_energy_rel; /* the patch law's creep reduction: the energy it moved over
                                E0 (tippe_dynamics_result.creep_energy_J; 0 otherwise) */
    int rolling;             /* Coulomb: rolling without slipping at the decision */
    int end_state_proved;    /* 0 under Coulomb friction with sticking: a trapped verdict
                                proves the well and range, not the rest state */
    double J0;               /* kg m^3/s, Jellett invariant at launch (eq 3.20) */
    double jellett_rel_drift;
    double jellett_drift_time_s; /* patch law: how soon drilling could change J by J0 (s) */
    long rhs_evals;
    /* Theorem 5.1 for J0: theory_ok = 0 where it gives no prediction (J0 = 0,
     * or a neutral balanced ball). predicted is a bit set of (1 << tippe_final_kind);
     * hang_theta_rad the predicted hanging angle (NAN if no hang is predicted). */
    int theory_ok;
    unsigned predicted;
    double hang_theta_rad;
    /* 1 the verdict is a predicted state (a hang within TIPPE_LAUNCH_HANG_AGREE_RAD),
     * 0 it is not, -1 not comparable (lost_contact, undecided, no prediction). */
    int agrees;
} tippe_launch_record;

/* The half-angles of the holes' openings (tippe_design_polar_caps) at the pole
 * the top of d at z2_mm rests on at theta = 0 (its centre of mass's side,
 * top->com_side; +z when centred) into caps_rad[0], at the other into
 * caps_rad[1]; 0 where the sphere is whole. For tippe_launch_options and
 * tippe_dynamics_options.cap_half_angle_rad. */
void tippe_launch_polar_caps(const tippe_design *d, double z2_mm, const tippe_top *top,
                             double caps_rad[2]);

/* Runs the given initial state (for `tippe check`) as tippe_launch_run runs a
 * drawn one: integrated and compared with theory. Returns the dynamics' status
 * (rec->status). */
int tippe_launch_run_initial(const tippe_top *top, const tippe_launch_options *o,
                             const tippe_dynamics_initial *ic, tippe_launch_record *rec,
                             tippe_error *err);

/* The tilt theta(t) of a launch (ic) sampled every t_end_s / (n - 1) from 0
 * to t_end_s (trajectory level; the samples stop early where the contact is
 * lost): t_s[0 .. *n_out - 1], theta_rad[...]. For a plot of one launch. */
int tippe_launch_trace(const tippe_top *top, const tippe_launch_options *o,
                       const tippe_dynamics_initial *ic, double t_end_s, int n, double *t_s,
                       double *theta_rad, int *n_out, tippe_error *err);

/* One launch (ic) at the trajectory level to o->t_end, as tippe check --csv and
 * --plot and tippe simulate --csv integrate it: the verdict is recorded and the run
 * goes on to t_end (run_to_t_end), a tip is followed to its flip, samples every
 * sample_dt_s (<= 0: tippe_dynamics_default_sample_dt) into *samples (zeroed by
 * the caller; free with tippe_dynamics_samples_free, also on failure). *res has
 * E0 and the state where the run stopped (res->last: theta, the energy dissipated
 * D). The dynamics' status. */
int tippe_launch_trajectory(const tippe_top *top, const tippe_launch_options *o,
                            const tippe_dynamics_initial *ic, double sample_dt_s,
                            tippe_dynamics_samples *samples, tippe_dynamics_result *res,
                            tippe_error *err);

/* Many launches in groups: group i has top tops[i] and, if spin_rad_s is not
 * NULL, the fixed spin spin_rad_s[i] (a map cell). Launch number `index`
 * (0 <= index < n_groups * per_group) belongs to group index / per_group and
 * uses draw index % per_group: every group sees the same hands (common random
 * numbers), so differences between groups are not sampling noise of the draws. */
typedef struct {
    int n_groups;
    long per_group;
    const tippe_top *tops;
    const double *spin_rad_s;
    /* NULL, or each group's holes' openings at the poles (tippe_launch_polar_caps: a
     * map's cells at different Z2), in place of the options' cap_half_angle_rad */
    const double (*caps_rad)[2];
} tippe_launch_plan;

long tippe_launch_plan_total(const tippe_launch_plan *plan);

/* Runs launches [from, to) of the plan on OpenMP threads into out[0 .. to-from)
 * and reports each to prog (may be NULL). Returns TIPPE_OK, or the error of the
 * lowest-numbered launch that failed (its message names the launch); the other
 * records are filled in any case. */
int tippe_launch_run(const tippe_launch_plan *plan, const tippe_launch_options *o, uint64_t seed,
                     long from, long to, tippe_launch_record *out, tippe_progress *prog,
                     tippe_error *err);

/* Counts over a run of records, in index order. */
typedef struct {
    long n;
    long counts[TIPPE_LAUNCH_N_VERDICTS]; /* by tippe_verdict */
    long comparable, agree;               /* launches with agrees >= 0, and agrees = 1 */
    long predicted[8];                    /* by predicted bit set (no prediction: 0) */
    /* median final theta and verdict time of each verdict (NAN where no launch
     * has it), and the largest Jellett drift */
    double median_theta_rad[TIPPE_LAUNCH_N_VERDICTS];
    double median_t_s[TIPPE_LAUNCH_N_VERDICTS];
    double max_jellett_rel_drift;
    double rhs_evals; /* total */
    /* Over tips followed to the flip (until_flip): how many, and the median model
     * time at which theta passed pi/2 (NAN if none). */
    long flips;
    double median_t_flip_s;
    /* Over every launch, whatever its verdict (the patch law's flips that fall back and
     * end as observed hangs): how many passed pi/2 (t_flip_s set) and the median time,
     * how many of those came back below it (t_fall_s set) and the median time (NAN if
     * none). */
    long passed, fell;
    double median_t_passed_s, median_t_fall_s;
    /* Trapped decisions (no_tip, tip, hang): how many, how many of them in a well
     * with no barrier, and the smallest barrier gap / margin of the others
     * (INFINITY if none). */
    long trapped, trapped_no_barrier;
    long rolling; /* decided rolling for ever (Coulomb friction with sticking) */
    double min_gap_over_margin;
    /* launches whose contact lay within a hole's opening at a pole at some time
     * up to their verdict (cap_first_s finite): the model does not hold there */
    long on_cap;
} tippe_launch_tally;

/* TIPPE_ECOMPUTE if out of memory. */
int tippe_launch_tally_records(const tippe_launch_record *r, long n, tippe_launch_tally *out,
                               tippe_error *err);

/* The normal quantile for a two-sided 95% interval, Phi^-1(0.975). */
#define TIPPE_LAUNCH_Z95 1.959963984540054

/* Wilson score interval for k successes in n trials at normal quantile z:
 * (p + z^2/2n -+ z sqrt(p (1 - p)/n + z^2/4n^2)) / (1 + z^2/n), p = k/n,
 * clamped to [0, 1]; [0, 1] for n = 0. */
void tippe_launch_wilson(long k, long n, double z, double *lo, double *hi);

/* The predicted bit set as text: "no_tip", "tip or hang", ..., "none". */
const char *tippe_launch_predicted_name(unsigned predicted);

/* An outcome map over a grid of Z2 and spin (`tippe map`). Cell (i, j), at
 * z2_mm[i] and spin_rev_s[j], is cells[i * n_spin + j]. */
typedef struct {
    int n_z2, n_spin;
    const double *z2_mm, *spin_rev_s;
    const tippe_launch_tally *cells;
    long per_cell;
} tippe_launch_map;

/* The index of the most frequent verdict of a cell (the lowest on a tie). */
int tippe_launch_dominant(const tippe_launch_tally *t);

/* ---- Sensitivity to the patch radius (issue 27; docs/dynamics.md, "Radius sensitivity")
 * The patch radius is uncertain (surface finish, the table, wear): under the patch law a
 * launch (or a batch of launches, with the same draws) is run again at 1/F and F times the
 * radius it used (F the options' span, 2 by default: 0.5x and 2x), and called robust to
 * the radius only when every launch makes the same passage over pi/2 (t_flip set or not),
 * the same fall back (t_fall set or not), loses contact or not alike, and gives the same
 * verdict where both verdicts were decided (an observed verdict, a snapshot at t_end of a
 * top that rocks on, is not compared: it is not converged), at all three radii. */
enum { TIPPE_LAUNCH_RADIUS_RUNS = 3 };
/* The span F when the options leave it 0: runs at 0.5x and 2x. */
#define TIPPE_LAUNCH_RADIUS_SPAN 2.0
/* The span F of o (o->patch_radius_span if > 1, else TIPPE_LAUNCH_RADIUS_SPAN). */
double tippe_launch_radius_span(const tippe_launch_options *o);
/* The factors on the used radius, in run order: 1/F, 1 (the plain run), F. */
double tippe_launch_radius_factor(const tippe_launch_options *o, int i);

/* The patch radius a launch of top under o uses, m: o->patch_radius_m if > 0, else Hertz's
 * at m g from o->patch_E_star_pa; 0 for the other laws. */
double tippe_launch_patch_radius(const tippe_top *top, const tippe_launch_options *o);

/* *out = *o with the patch radius factor times the used one (given, not Hertz). 1 if that
 * radius is beyond what the dynamics accepts (R/2: not run), else 0. */
int tippe_launch_radius_options(const tippe_top *top, const tippe_launch_options *o,
                                double factor, tippe_launch_options *out);

typedef struct {
    double factor, radius_m;
    int ran;                 /* 0: not run, the radius exceeds R/2 */
    long n;                  /* launches */
    long counts[TIPPE_LAUNCH_N_VERDICTS];
    long passed, fell;       /* launches that passed pi/2; of those, came back below */
    double median_t_flip_s, median_t_fall_s; /* over those (NAN if none) */
    tippe_launch_record first; /* launch 0: tippe check's one launch */
} tippe_launch_radius_run;

typedef struct {
    tippe_launch_radius_run run[TIPPE_LAUNCH_RADIUS_RUNS]; /* 1/F, 1x, F */
    long changed; /* launches whose outcome (verdict, flip, fall) differs between radii */
    int robust;   /* all three ran and changed == 0 */
} tippe_launch_radius_sensitivity;

/* Summarises three runs of the same n launches (rec[i] at radius_m[i], rec[i] NULL: not
 * run). TIPPE_ECOMPUTE if out of memory. */
int tippe_launch_radius_summary(const tippe_launch_record *const rec[TIPPE_LAUNCH_RADIUS_RUNS],
                                long n, const double radius_m[TIPPE_LAUNCH_RADIUS_RUNS],
                                tippe_launch_radius_sensitivity *out, tippe_error *err);

/* One launch ic (tippe check) at the three radii. plain: the launch already run under o
 * (used as the middle run), or NULL to run it here. TIPPE_EINPUT if o is not the patch
 * law; otherwise the status of a run that failed. */
int tippe_launch_radius_sensitivity_initial(const tippe_top *top, const tippe_launch_options *o,
                                            const tippe_dynamics_initial *ic,
                                            const tippe_launch_record *plain,
                                            tippe_launch_radius_sensitivity *out,
                                            tippe_error *err);

/* ==== from tippe/contact_patch.h ==== */
/* Contact patch: the contact of the sphere on the table as a small circular
 * patch that spins with the top (issue 27, the contact law).
 *
 * - Hertz: the patch radius a of a sphere pressed on a flat (Johnson 1985, eqs 4.22-4.23).
 * - Coulomb-Contensou friction: Coulomb's law integrated over the patch, which both
 *   slides (velocity v of the material point at its centre) and drills (spin omega_n
 *   about the table's normal). After normalising, the force and torque depend only on
 *   eps = |v| / (a |omega_n|) and on the pressure law (uniform, or Hertz's
 *   p ~ sqrt(1 - r^2/a^2)): |F| = mu N f(eps) against v, |M| = mu N a m(eps) against
 *   omega_n.
 *   * tippe_contact_patch_reference: f and m by adaptive 2-D quadrature (GSL). Slow; a reference.
 *   * tippe_contact_patch_friction: the cheap form for the right-hand side of an ODE: a rational
 *     approximant of the dissipation potential (docs/contact-patch.md), no allocation, no
 *     quadrature, one square root. Smooth except at (v, omega_n) = (0, 0).
 * - Sticking: the Leine-Glocker ellipse, and the exact limit curve of the cheap form.
 * - Rolling resistance: a resisting torque against the rolling angular velocity.
 *
 * Frame: the table's normal e3 points up into the body; v and the returned F are
 * 2-vectors in the table plane (e1, e2); omega_n and M are about e3. F and M act on the
 * body, at the patch centre. SI units. docs/contact-patch.md derives everything here and
 * gives the accuracy, the cost and the materials data. Depends on nothing in tippe but
 * tippe/error.h. */
/* The pressure over the patch. Both integrate to N. */
typedef enum {
    TIPPE_CONTACT_PATCH_UNIFORM = 0, /* p = N / (pi a^2) */
    TIPPE_CONTACT_PATCH_HERTZ = 1    /* p = (3 N / (2 pi a^2)) sqrt(1 - r^2/a^2),
                                             Johnson sec. 4.2 */
} tippe_contact_patch_pressure;

/* The exact limits of f and m (docs/contact-patch.md derives them):
 * f ~ c1 eps and m -> m0 as eps -> 0; f -> 1 and m ~ c2 / eps as eps -> inf.
 * Uniform: m0 = 2/3, c1 = 1, c2 = 1/4. Hertz: m0 = 3 pi/16, c1 = 3 pi/8, c2 = 1/5. */
typedef struct {
    double m0, c1, c2;
} tippe_contact_patch_limits;

tippe_contact_patch_limits tippe_contact_patch_limits_of(tippe_contact_patch_pressure p);
const char *tippe_contact_patch_pressure_name(tippe_contact_patch_pressure p); /* "uniform",
                                              "hertz" */
int tippe_contact_patch_pressure_parse(const char *name);               /* the enum, or -1 */

/* ---- Hertz -------------------------------------------------------------- */

/* The contact modulus of two materials, 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2
 * (Johnson 1985, eq 4.22 with 4.23). E in Pa (> 0, finite), -1 < nu <= 0.5. */
int tippe_contact_hertz_modulus(double E1, double nu1, double E2, double nu2, double *E_star,
                        tippe_error *err);

/* The patch radius of a sphere of radius R (m, > 0) on a flat under the normal force
 * N (N, >= 0): a = (3 N R / (4 E*))^(1/3) (Johnson 1985, eq 4.22). a grows as N^(1/3):
 * the right-hand side can scale a value computed once, a = a_ref cbrt(N / N_ref). */
int tippe_contact_hertz_radius(double R, double N, double E_star, double *a, tippe_error *err);

/* ---- Coulomb-Contensou friction ------------------------------------------ */

typedef struct {
    double F[2];        /* N: friction force on the body, in the table plane */
    double M;           /* N m: drilling torque on the body, about e3 */
    double dissipation; /* W, >= 0: -(F.v + M omega_n), the power friction takes */
} tippe_contact_patch_wrench;

/* The cheap form (for an ODE's right-hand side): mu_N = mu N (N, >= 0), a the patch
 * radius (m, >= 0), v the slip velocity of the body's material point at the patch
 * centre relative to the table (m/s), omega_n the body's spin relative to the table
 * about e3 (rad/s).
 * v_s (m/s, >= 0) regularises the one singular point: with v_s = 0 the law is the
 * approximant itself, smooth except at (v, omega_n) = (0, 0), where it returns a zero
 * wrench (the set-valued sticking point: see tippe_contact_patch_load); with v_s > 0 it is
 * Lipschitz everywhere and, at a = 0, exactly the regularised Coulomb law
 * F = -mu N v / sqrt(|v|^2 + v_s^2) that src/dynamics.c uses now.
 * Limits (exact in floating point unless noted): a = 0 or omega_n = 0 gives point
 * Coulomb friction F = -mu N v/|v|, M = 0; v = 0 gives F = 0, M = -mu N a m0 sgn(omega_n)
 * (to rounding). No allocation, no library calls but one sqrt; thread-safe. */
void tippe_contact_patch_friction(tippe_contact_patch_pressure p, double mu_N, double a, double v_s,
                          const double v[2], double omega_n, tippe_contact_patch_wrench *out);

/* The cheap form normalised: f and m at eps (>= 0; +inf gives f = 1, m = 0). */
void tippe_contact_patch_normalised(tippe_contact_patch_pressure p, double eps, double *f,
                                    double *m);

/* The reference: f and m at eps (>= 0, may be +inf) by nested adaptive quadrature (GSL
 * QAGS) of Coulomb's law over the patch in polar coordinates, to a relative 1e-10 or
 * better. Allocates GSL workspaces; milliseconds a call. TIPPE_EINPUT for a negative or
 * NaN eps, TIPPE_ECOMPUTE if GSL fails. */
int tippe_contact_patch_reference(tippe_contact_patch_pressure p, double eps, double *f, double *m,
                          tippe_error *err);

/* The small-slip limit: for |v| << a |omega_n| the force is viscous,
 * F = -mu N c1 v / (a |omega_n|), i.e. the paper's eq 3.12 Rf = -mu Rn V_Q with
 * mu = mu_c c1 / (a |omega_n|) (s/m), which this returns (+inf if a omega_n = 0). */
double tippe_contact_patch_viscous_mu(tippe_contact_patch_pressure p, double mu_c, double a,
                                      double omega_n);

/* ---- sticking ------------------------------------------------------------- */

/* While the patch sticks (v = 0 and omega_n = 0 together) the table supplies whatever
 * force F and torque M keep it stuck, if the pair lies in the set that sliding can
 * reach. These return the load factor lambda of a demanded (F, M): the pair sits on the
 * set's boundary when scaled by 1/lambda, so it sticks iff lambda <= 1.
 * Leine and Glocker's ellipse (Eur. J. Mech. A/Solids 22 (2003) 193):
 * lambda^2 = (|F|/(mu N))^2 + (M/(mu N a m0))^2. */
double tippe_contact_patch_load_ellipse(tippe_contact_patch_pressure p, double mu_N, double a,
                                const double F[2], double M);

/* The same against the limit curve (mu N f(eps), mu N a m(eps)) of the cheap form (by
 * bisection, ~60 evaluations; for events, not the hot path). If eps_exit is not NULL it
 * receives the eps of the boundary point hit: where the patch leaves a stuck state it
 * starts to slide with |v| / (a |omega_n|) = eps_exit, v against F and omega_n against M.
 * a = 0 reduces both to |F|/(mu N) (M must be 0: +inf otherwise); mu N = 0 holds only a
 * zero wrench (0, else +inf). */
double tippe_contact_patch_load(tippe_contact_patch_pressure p, double mu_N, double a,
                                const double F[2],
                        double M, double *eps_exit);

/* ---- rolling resistance --------------------------------------------------- */

/* A resisting torque against the rolling angular velocity w_roll (rad/s, the part of
 * the body's angular velocity relative to the table that lies in the table plane):
 * M_roll = -N arm w_roll / sqrt(|w_roll|^2 + w_s^2), i.e. Coulomb-like with lever arm
 * `arm` (m; the rolling resistance coefficient is arm / R), regularised by w_s (rad/s,
 * >= 0; w_s = 0 gives M_roll = -N arm w_roll/|w_roll|, and 0 at w_roll = 0). Off by
 * default: arm = 0 gives no torque. Returns the dissipation -M_roll.w_roll >= 0 (W). */
double tippe_contact_rolling_resistance(double N, double arm, double w_s, const double w_roll[2],
                                double M_roll[2]);

/* ---- table surfaces and the patch of a design ------------------------------ */

/* The table surfaces a top is spun on (docs/contact-patch.md, "Materials"): "glass"
 * (soda-lime float, E 72 GPa, nu 0.23, Pilkington ATS-129), "laminate" (HPL, 9 GPa,
 * 0.3, makers' EN ISO 178 flexural modulus), "wood" (hard maple across the grain,
 * 1.0 GPa, 0.4), "steel" (210 GPa, 0.30, EN 1993-1-1). 0 with E (Pa) and nu, or -1 for
 * an unknown name. */
int tippe_contact_table_surface(const char *name, double *E_pa, double *nu);
#define TIPPE_CONTACT_TABLES "glass, laminate, wood or steel"
#define TIPPE_CONTACT_DEFAULT_TABLE "laminate"

/* The contact modulus E* of a design's ball (the materials table's E_GPa and nu of its
 * sphere's material) on a table surface (NULL: TIPPE_CONTACT_DEFAULT_TABLE), for the
 * Hertz patch at m g. TIPPE_EINPUT naming what is missing (then give the radius). */
int tippe_launch_patch_modulus(const tippe_design *d, const char *table, double *E_star_pa,
                               tippe_error *err);

/* The lever arm of elastic hysteresis for a sphere: arm = (3/16) alpha a, alpha the
 * fraction of the elastic work lost per cycle (Johnson 1985, section 9.2, after Tabor
 * 1955). */
double tippe_contact_rolling_arm_hysteresis(double alpha, double a);
/* ==== reports of launches (tippe's --json, tippe serve) ==== */
struct cJSON;
/* The model of a launch's options: law, coefficients, g (no top). */
void tippe_launch_friction_model(const tippe_launch_options *o, tippe_dynamics_model *m);
/* Adds "friction": {"law", "mu_s_m" | "mu" and "slip_scale_m_s"} to o, and the
 * older "mu_s_m" (the viscous coefficient; null under a Coulomb law). */
void tippe_dynamics_friction_json(struct cJSON *o, const tippe_dynamics_model *m);
/* Adds {"preset": preset, "stepper": ..., "rtol": ...} to o as "accuracy", the
 * same object in every verb that integrates. */
void tippe_dynamics_accuracy_json(struct cJSON *o, const char *preset,
                                  const tippe_dynamics_accuracy *acc, tippe_friction_law law,
                                  double creep_cap);
/* A launch's options: the hand-launch distribution (without the spin's when
 * fixed_spin), the friction, g, t_end and the accuracy. NULL if out of memory. */
struct cJSON *tippe_launch_options_json(const tippe_launch_options *o, int fixed_spin);
/* The radius sensitivity as JSON: {"robust", "changed", "runs": [{"factor", "patch_mm",
 * "ran", and for one launch (one_launch) "verdict", "t_s", "theta_final_rad", "t_flip_s",
 * "t_fall_s", "inverted_time_s", else "counts" {verdict: n}, "passed_pi_2", "fell_back",
 * "median_t_flip_s", "median_t_fall_s"}]}. NULL if out of memory. */
struct cJSON *tippe_launch_radius_json(const tippe_launch_radius_sensitivity *s, int one_launch);

/* ==== friction laws: one table entry per law (src/physics/friction_laws.c) ====
 * What the command, the server and the scenario reader say of a law and take for it
 * comes from its entry, as GSL describes a stepper by its gsl_odeiv2_step_type: a new
 * law is an entry here and its force in the dynamics, never a case in a verb. */

/* The friction options' parameters, in the order the command's --help lists them. */
typedef enum {
    TIPPE_LAW_PARAM_LAW,         /* the law, by name */
    TIPPE_LAW_PARAM_PATCH_MM,    /* the patch's radius, mm */
    TIPPE_LAW_PARAM_TABLE,       /* the table's surface (Hertz's patch) */
    TIPPE_LAW_PARAM_MU_C,        /* Coulomb's coefficient */
    TIPPE_LAW_PARAM_SLIP_SCALE,  /* Coulomb's regularisation speed, m/s */
    TIPPE_LAW_PARAM_MU,          /* the viscous coefficient, s/m */
    TIPPE_LAW_PARAM_RADIUS_SPAN, /* the radius sensitivity's factor F */
    TIPPE_LAW_PARAM_CREEP_CAP,   /* the patch law's creep reduction's cap */
    TIPPE_LAW_N_PARAMS
} tippe_friction_param_id;

typedef struct {
    const char *key;    /* its name in JSON and the library ("patch_mm") */
    const char *option; /* the command's option, without "--" ("patch-mm") */
    const char *arg;    /* --help's placeholder ("A"), NULL: the unit's */
    const char *unit;   /* NULL: dimensionless or a word */
    int number;         /* 1 a number in [min, max], 0 a word */
    double min, max;
    const char *def;    /* the default, in words */
    const char *help;   /* the command's --help ("\n" continues a line) */
} tippe_friction_param;

extern const tippe_friction_param tippe_friction_params[TIPPE_LAW_N_PARAMS];

typedef struct {
    tippe_friction_law law;
    const char *name;  /* "patch": --friction's word, "law" in JSON */
    const char *word;  /* "patch friction": in a sentence */
    const char *label; /* a plot's name of its coefficient's law ("Coulomb") */
    const char *text;  /* one line: what it is (--help) */
    const char *doc;   /* where it is documented */
    unsigned params;   /* the parameters it takes: bits 1 << tippe_friction_param_id */
    int sticks;        /* sticks and rolls without slipping: stick and slip events */
    int drills;        /* a couple about the normal changes J: its verdicts are observed */
    int patch;         /* a contact patch: its radius (given, or Hertz's), its sensitivity */
    /* the stepper that runs for the presets' rk8pd with the full creep (creep_cap 0;
     * tippe_dynamics_stepper_used) */
    const char *stiff_stepper;
    /* its model in words (tippe_dynamics_friction_text), and its keys in the
     * "friction" object of a report (tippe_dynamics_friction_json) */
    void (*describe)(const tippe_dynamics_model *m, double v_s, char *buf, size_t size);
    void (*json)(struct cJSON *f, const tippe_dynamics_model *m);
} tippe_friction_law_type;

enum { TIPPE_N_FRICTION_LAWS = 4, TIPPE_MAX_FRICTION_LAWS = TIPPE_N_FRICTION_LAWS };

/* The laws in the order they are listed; NULL past the last. */
const tippe_friction_law_type *tippe_friction_law_at(int i);
/* The entry of law (NULL if none), of a name (NULL if unknown). */
const tippe_friction_law_type *tippe_friction_law_type_of(tippe_friction_law law);
const tippe_friction_law_type *tippe_friction_law_find(const char *name);
/* The law a parameter given alone names: the first listed that takes it (mu the
 * viscous law, mu_c and slip_scale Coulomb's, patch_mm and table the patch law).
 * tippe_friction_law_at(0) is the default, the paper's viscous law. */
const tippe_friction_law_type *tippe_friction_law_named_by(tippe_friction_param_id p);
/* 1 if law takes parameter p. */
int tippe_friction_law_takes(tippe_friction_law law, tippe_friction_param_id p);
/* The laws' names as a list: "viscous, coulomb, coulomb-creep or patch" (last " or ")
 * or "viscous, coulomb, coulomb-creep, patch" (last ", "). Returns buf. */
const char *tippe_friction_law_list(const char *last, char *buf, size_t size);
/* The command's --help of --friction: "friction law: viscous (eq 3.12, the paper's),
 * ...", then tail ("; docs/dynamics.md"), wrapped at width columns with "\n". Returns
 * buf. */
const char *tippe_friction_law_help(int width, const char *tail, char *buf, size_t size);

/* The friction options as a front end was given them (its names mapped onto the
 * parameters): which were given, and the values the rules need. */
typedef struct {
    const char *laws;   /* the law, or (names.list) several comma-separated; NULL: none */
    unsigned given;     /* bits 1 << tippe_friction_param_id of the parameters given */
    double patch_mm;    /* when given */
    const char *table;  /* when given */
} tippe_friction_given;

/* How a front end names the parameters in its messages ("--patch-mm" or "patch_mm"),
 * says "choose the law L" (a format with one %s: "--friction %s"), and whether the
 * law may be a list (tippe check compares laws). */
typedef struct {
    const char *name[TIPPE_LAW_N_PARAMS];
    const char *choose;
    int list;
} tippe_friction_names;

/* The rules of the friction options, one place for both front ends: the laws named
 * (or, with none, the law a coefficient given alone names: mu the viscous, mu_c or
 * slip_scale Coulomb's, patch_mm or table the patch law; else o->law), each parameter
 * given belongs to a law among them, one of patch_mm and table, a known table. Fills
 * laws[0 .. *n_laws - 1] (room for TIPPE_MAX_FRICTION_LAWS), o->law (the first) and
 * o->patch_radius_m. TIPPE_EINPUT naming the parameter in err->field (its key) and,
 * in the message, by names. */
int tippe_friction_choose(const tippe_friction_given *g, const tippe_friction_names *names,
                          tippe_friction_law *laws, int *n_laws, tippe_launch_options *o,
                          tippe_error *err);
/* The rules that need the design, where one of laws[0 .. n_laws - 1] has a patch: the
 * radius sensitivity's span is the design's tolerance unless given (o->patch_radius_span
 * > 0), a given radius (o->patch_radius_m) is at most half the ball's radius, else the
 * radius is Hertz's on table (NULL: TIPPE_CONTACT_DEFAULT_TABLE; o->patch_E_star_pa,
 * tippe_launch_patch_modulus). Nothing under the other laws. TIPPE_EINPUT with
 * err->field, the parameter named by names in the message. */
int tippe_friction_for_design(const tippe_design *d, const tippe_friction_law *laws, int n_laws,
                              const char *table, const tippe_friction_names *names,
                              tippe_launch_options *o, tippe_error *err);

/* ==== a map's grid (tippe map; src/physics/launch_grid.c) ====
 * Hand launches over a grid of Z2 and spin (tippe_launch_plan's groups are its cells,
 * cell (i, j) at z2_mm[i] and spin_rev_s[j] is i * n_spin + j), with the patch law's
 * reruns at 1/F and F times the radius. The front end runs the plan (and the reruns)
 * where it likes, on threads or ranks; making the grid and tallying it are here. */
typedef struct {
    int n_z2, n_spin;
    long per_cell, n_cells, total;  /* launches per cell, cells, launches */
    double *z2_mm, *spin_rev_s;     /* the grid's values */
    tippe_top *tops;                /* the top at each Z2 */
    /* 1 where a part stands out of the sphere at z2_mm[i]: the top rests on it and the
     * model does not apply (docs/design-format.md) */
    unsigned char *model_invalid;
    tippe_top *cell_tops;           /* each cell's top, spin and holes' openings: the plan */
    double *cell_spin_rad_s;
    double (*cell_caps)[2];
    tippe_launch_record *rec;       /* the plan's launches, cell after cell */
    tippe_launch_tally *cells;      /* each cell's tally (tippe_launch_grid_tally) */
    /* the patch law's radius sensitivity: the same launches at 1/F ([0]) and F ([2])
     * times the radius, the plain run being rec ([1]); NULL where not run (a radius
     * beyond R/2) */
    int radius_runs;
    tippe_launch_record *rec_radius[TIPPE_LAUNCH_RADIUS_RUNS];
    double radius_m[TIPPE_LAUNCH_RADIUS_RUNS], factor[TIPPE_LAUNCH_RADIUS_RUNS];
    long *cell_changed;          /* launches of each cell whose outcome differs between radii */
    long changed, cells_changed; /* their sum, and the cells with any */
} tippe_launch_grid;

/* The grid of d: n_z2 values from z2_from_mm to z2_to_mm, n_spin spins from
 * spin_from_rad_s to spin_to_rad_s (evenly, both ends; one value: the first), per_cell
 * launches each under o; the radius reruns if o's law has a patch and
 * radius_sensitivity. TIPPE_EINPUT (err->field "z2_mm") where d has no top at a Z2,
 * TIPPE_ECOMPUTE out of memory. Free with tippe_launch_grid_free, also on failure. */
int tippe_launch_grid_make(const tippe_design *d, double z2_from_mm, double z2_to_mm, int n_z2,
                           double spin_from_rad_s, double spin_to_rad_s, int n_spin,
                           long per_cell, const tippe_launch_options *o, int radius_sensitivity,
                           tippe_launch_grid *g, tippe_error *err);
/* The plan of its launches (into g->rec, or g->rec_radius[i] with the options of
 * tippe_launch_grid_radius_options). */
tippe_launch_plan tippe_launch_grid_plan(const tippe_launch_grid *g);
void tippe_launch_grid_radius_options(const tippe_launch_grid *g, const tippe_launch_options *o,
                                      int i, tippe_launch_options *out);
/* The launches to run, reruns included (for a progress bar). */
long tippe_launch_grid_work(const tippe_launch_grid *g);
/* After the runs: each cell's tally and, with the reruns, what changed between radii.
 * TIPPE_ECOMPUTE if out of memory. */
int tippe_launch_grid_tally(tippe_launch_grid *g, tippe_error *err);
/* The tallied grid as a map (for tables and plots). */
tippe_launch_map tippe_launch_grid_map(const tippe_launch_grid *g);
void tippe_launch_grid_free(tippe_launch_grid *g);

#endif
