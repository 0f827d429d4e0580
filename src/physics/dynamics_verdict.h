/* Private to the dynamics module: the proved verdict (docs/dynamics.md, "Proved
 * verdicts"). Pure functions of a top, g, mu and the launch's Jellett invariant. */
#ifndef TIPPE_PHYSICS_DYNAMICS_VERDICT_H
#define TIPPE_PHYSICS_DYNAMICS_VERDICT_H

#include "tippe/physics.h"

typedef struct {
    tippe_top top;
    double g, mu, J;
    int coulomb;      /* friction law: regularised Coulomb (mu_c, v_s) instead of mu */
    double mu_c, vs;  /* Coulomb coefficient, regularisation speed (m/s) */
    int dissipative;  /* friction is nonzero: E falls while the contact slides */
    int stick;        /* Coulomb with sticking: while rolling the friction is anything
                         inside the cone |F| <= mu_c Rn */
    tippe_theory_wells wells;
    double D_min;  /* kg m^2, least of D(theta) = A R^2 sin^2 + C (R cos - eps)^2 */
} tippe_dynamics_verdict_ctx;

int tippe_dynamics_verdict_init(tippe_dynamics_verdict_ctx *v, const tippe_dynamics_model *model, double J, tippe_error *err);

/* Energy margin, J: factor * (energy-balance error + the change of V that a Jellett
 * error dJ can make, |J| dJ / D_min) plus 1e-12 E0 for rounding. */
double tippe_dynamics_verdict_margin(const tippe_dynamics_verdict_ctx *v, double factor, double energy_err_J, double J_err,
                      double E0);

/* What the energy test found for a state at angle theta with energy E. */
typedef struct {
    int well;            /* index in v->wells */
    int confined;        /* E + margin < the well's escape level: theta stays in it */
    int trapped;         /* confined, E + margin < barrier and the well is not flat */
    int unresolvable;    /* confined, and the well flat or its barrier within the margin
                            of its minimum: as the margin never shrinks, never trapped */
    double barrier;      /* J, least V of the well's other critical points where a motion can
                            end (interior maxima, degenerate points; INFINITY: none) */
    double gap;          /* J, barrier - E */
    double lo, hi;       /* rad, where V <= E + margin in the well (tippe_dynamics_verdict_trap_range) */
} tippe_dynamics_verdict_trap;

/* Cheap (a few comparisons): called at every accepted step. rest_pole_rad is 0 or pi
 * when the state is exactly the steady state at that pole (no tilt rate, no slip),
 * NAN otherwise: only then is a pole that is a maximum of V a barrier. */
void tippe_dynamics_verdict_energy_test(const tippe_dynamics_verdict_ctx *v, double theta, double E, double margin,
                         double rest_pole_rad, tippe_dynamics_verdict_trap *out);
/* Fills tr->lo, tr->hi by bisection on V (~100 evaluations): only before a contact bound. */
void tippe_dynamics_verdict_trap_range(const tippe_dynamics_verdict_ctx *v, double E, double margin, tippe_dynamics_verdict_trap *tr);

/* A lower bound of the normal force Rn (eq 3.19) over every state with theta in
 * [lo, hi], Jellett J and energy <= E_max (N); -INFINITY where the bound fails. */
double tippe_dynamics_verdict_contact_bound(const tippe_dynamics_verdict_ctx *v, double E_max, double lo, double hi);

/* Number of theta nodes at which the contact bound is evaluated. */
enum { TIPPE_DYNAMICS_VERDICT_CONTACT_NODES = 65 };

#endif
