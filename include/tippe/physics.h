/* tippe/physics.h: one launch of a top: the equations of motion (paper section 3),
 * their friction laws and proved verdicts.
 *
 * Contents:
 * - dynamics: the model, a launch's initial state, the accuracy presets, the
 *   integration and its verdicts (tippe_dynamics_*; src/physics/dynamics*.c);
 * - the contact patch: Hertz's radius, Coulomb-Contensou friction, sticking, rolling
 *   resistance, the table surfaces (tippe_contact_*; contact_patch.c);
 * - the friction laws' table: one entry per law (tippe_friction_law_*;
 *   friction_laws.c), and a model's friction and accuracy in reports
 *   (dynamics_report.c).
 * Depends on base, the top (tippe/top.h) and the theory (tippe/theory.h) only: no
 * design file. Hand launches of a design are tippe/launch.h's. */
#ifndef TIPPE_PHYSICS_H
#define TIPPE_PHYSICS_H

#include <stddef.h>

#include "tippe/base.h"
#include "tippe/theory.h"
#include "tippe/top.h"

/* ---- dynamics (src/physics/dynamics*.c) ---- */
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

/* ---- the contact patch (src/physics/contact_patch.c) ---- */
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

/* The lever arm of elastic hysteresis for a sphere: arm = (3/16) alpha a, alpha the
 * fraction of the elastic work lost per cycle (Johnson 1985, section 9.2, after Tabor
 * 1955). */
double tippe_contact_rolling_arm_hysteresis(double alpha, double a);

/* ---- reports of a model (src/physics/dynamics_report.c) ---- */
struct cJSON;
/* Adds "friction": {"law", "mu_s_m" | "mu" and "slip_scale_m_s"} to o, and the
 * older "mu_s_m" (the viscous coefficient; null under a Coulomb law). */
void tippe_dynamics_friction_json(struct cJSON *o, const tippe_dynamics_model *m);
/* Adds {"preset": preset, "stepper": ..., "rtol": ...} to o as "accuracy", the
 * same object in every verb that integrates. */
void tippe_dynamics_accuracy_json(struct cJSON *o, const char *preset,
                                  const tippe_dynamics_accuracy *acc, tippe_friction_law law,
                                  double creep_cap);

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

/* The laws' default coefficients (a design's launches, docs/launch.md). */
/* Viscous friction (eq 3.12) for a plastic ball on a table, s/m: a Coulomb
 * coefficient of about 0.3 divided by a typical contact slip speed of 0.13 m/s
 * (docs/launch.md derives it and gives the sources). */
#define TIPPE_LAUNCH_DEFAULT_MU_S_M 2.3

/* Coulomb friction of a printed (PLA or nylon) ball on a tabletop: 0.3, within the
 * published 0.2-0.5 for plastic on wood or laminate (docs/launch.md gives the sources). */
#define TIPPE_LAUNCH_DEFAULT_MU_C 0.3

#endif
