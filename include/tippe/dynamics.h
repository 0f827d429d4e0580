/* tippe/dynamics.h: one launch of an eccentric sphere on a table (paper section 3).
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
#ifndef TIPPE_DYNAMICS_H
#define TIPPE_DYNAMICS_H

#include "tippe/error.h"
#include "tippe/top.h"

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
    TIPPE_DECIDED_ROLLING       /* Coulomb friction: the top rolls without slipping, and
                                   over one whole period of its nutation (the rolling
                                   sphere is integrable: the motion repeats) the force
                                   that rolling needs stayed inside the friction cone,
                                   so it rolls for ever, theta within the period's range
                                   (no_tip below pi/2, tip above, else bounded) */
} tippe_decision;

/* "t_end", "trapped", "lost_contact", "flat_well", "budget", "rolling". */
const char *tippe_decision_name(tippe_decision d);

/* The friction law. Zero (viscous) is the paper's, so a model initialised with
 * only {top, g, mu} keeps eq 3.12. */
typedef enum {
    TIPPE_FRICTION_VISCOUS = 0, /* Rf = -mu Rn V_Q (eq 3.12), mu in s/m */
    TIPPE_FRICTION_COULOMB = 1, /* sliding: Rf = -mu_c Rn V_Q / sqrt(|V_Q|^2 + v_s^2)
                                   (Coulomb's |Rf| = mu_c Rn against the slip for
                                   |V_Q| >> v_s); sticking once |V_Q| < 30 v_s and rolling
                                   needs |Rf| <= mu_c Rn, until it needs more */
    TIPPE_FRICTION_COULOMB_CREEP = 2 /* the regularised sliding law alone, no sticking:
                                   below v_s the contact creeps (|Rf| < mu_c Rn) and
                                   dissipates; kept to measure what the stick phase
                                   changes (docs/dynamics.md) */
} tippe_friction_law;

/* "viscous", "coulomb", "coulomb-creep"; tippe_friction_law_parse returns -1 for an
 * unknown name. */
const char *tippe_friction_law_name(tippe_friction_law law);
int tippe_friction_law_parse(const char *name);

/* The regularisation speed v_s of the Coulomb law when the model leaves it 0, m/s:
 * the sliding law's width and the slip below which sticking is tried.
 * docs/dynamics.md measures the reported times against smaller v_s. */
#define TIPPE_COULOMB_SLIP_SCALE_M_S 1e-5

typedef struct {
    tippe_top top;
    double g;  /* m/s^2 */
    double mu; /* s/m, viscous sliding friction coefficient (eq 3.12), >= 0 */
    tippe_friction_law law;  /* TIPPE_FRICTION_VISCOUS (0) uses mu, the others mu_c */
    double mu_c;             /* Coulomb friction coefficient (dimensionless), >= 0 */
    double slip_scale_m_s;   /* Coulomb's regularisation speed v_s, m/s (0: the default
                                TIPPE_COULOMB_SLIP_SCALE_M_S) */
} tippe_dynamics_model;

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
    double J;               /* kg m^2/s, Jellett -L.q (eq 3.20) */
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
} tippe_dynamics_options;

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
    tippe_dynamics_sample last;  /* state where integration stopped */
    double J0, E0;               /* at launch */
    double jellett_rel_drift;    /* max |J - J0| / max(|J0|, 1e-6 C W R), W = |omega0| + sqrt(g/R) */
    double energy_rel_error;     /* max |E + D - E0| / E0 */
    double energy_max_rise;      /* J, max over steps of E(t_i) - min_{j<i} E(t_j) (>= 0) */
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
    double rolling_time_s;
    int rolling;
    int end_state_proved;
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

/* Reference: the paper's Euler-angle equations (3.15-3.19, derived for any m),
 * valid for 0 < theta < pi. y = (theta, theta_dot, phi_dot, spin, U, V, phi, psi),
 * dydt its derivative; *Rn the normal force. TIPPE_ECOMPUTE where sin(theta) = 0
 * or the contact force is undetermined. */
enum { TIPPE_EULER_DIM = 8 };
int tippe_dynamics_euler_rhs(const tippe_dynamics_model *model, const double y[TIPPE_EULER_DIM],
                             double dydt[TIPPE_EULER_DIM], double *Rn);

#endif
