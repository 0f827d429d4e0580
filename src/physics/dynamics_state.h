/* physics/dynamics_state.h: what the dynamics files share (the state's
 * layout, the run's context, the contact) and no other module sees. */
#ifndef TIPPE_PHYSICS_DYNAMICS_STATE_H
#define TIPPE_PHYSICS_DYNAMICS_STATE_H

#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <stddef.h>

#include "tippe/physics.h"

/* State layout. Verdict level: axis k, angular velocity omega, horizontal
 * velocity of the centre of mass, dissipated energy. Trajectory level adds the
 * orientation quaternion and the position of the centre of mass on the table. */
enum { IK = 0, IW = 3, IV = 6, ID = 8, IQ = 9, IX = 13 };
enum { DIM_VERDICT = 9, DIM_TRAJECTORY = 15 };
/* Sticking is tried below this many v_s of slip, and needs the rolling force inside
 * the cone by this fraction of mu_c m g (run_try_stick; the rolling decision asks the
 * same room over a whole period). */
#define STICK_SLIP_FACTOR 30.0
#define STICK_MARGIN 1e-3
/* The step budget also caps the RHS evaluations at this many per allowed step: rk8pd
 * uses 13 a step (16 with the rejections of a stiff launch), but an implicit stepper's
 * finite-difference Jacobians cost up to ~240 (bsimp), so on a stiff launch (the creep
 * law at v_s = 1e-7 m/s) a budget of steps alone let bsimp run for more than 100 s
 * (stopped by hand) and rk4imp 90 s, where rk8pd stops after 13 s (docs/dynamics.md,
 * "Coulomb friction", "Extremes"). */
#define BUDGET_EVALS_PER_STEP 20


typedef struct {
    double m, R, eps, A, C, g, mu;
    int coulomb;          /* friction law: 0 viscous (mu), 1 Coulomb (regularised slip) */
    int stick_law;        /* Coulomb with the event-driven stick (rolling) phase */
    int patch;            /* Coulomb-Contensou on a patch of radius patch_a (m) */
    double patch_a;       /* its radius at the static load m g, m */
    int patch_follow;     /* 1: the radius follows Rn as patch_a (Rn / m g)^(1/3) */
    double inv_mg;        /* 1 / (m g), N^-1 */
    double roll_arm;      /* patch law: rolling resistance lever arm, m (0: off) */
    int stick;            /* current phase: 1 rolling without slipping (V_Q = 0) */
    double mu_c, vs, vs2; /* Coulomb coefficient, its slip scale v_s and v_s^2 */
    double min_stage_stick; /* smallest mu_c Rn - |F| met by a stage since reset (rolling) */
    /* Constants of the right-hand side, once per run rather than per call. */
    double one_minus_A_over_C, C_minus_A_over_A, inv_A;
    size_t dim;
    long nevals;
    double min_stage_Rn;  /* smallest Rn met by any right-hand-side call since reset */
    int bad_contact;      /* the denominator of eq 3.19 was <= 0 */
    double scale[DIM_TRAJECTORY]; /* absolute scale per component */
    /* The outline's contact (issue 35): the sphere cut flat at each pole whose cap is
     * open (tippe_dynamics_options.cap_half_angle_rad), [0] the pole down at theta = 0
     * (u = -k), [1] the other (u = +k): half-angle alpha, cos alpha, the rim's
     * distance from the centre R cos alpha and its radius R sin alpha (m). */
    int has_rims;
    double rim_alpha[2], rim_cos[2], rim_Rcos[2], rim_r[2];
    int rim;              /* the contact now: 0 the sphere, 1 pole [0]'s rim, 2 pole [1]'s */
    int face;             /* on a rim's pole, within RIM_FACE_SIN of upright: its flat face */
    double rim_rho[2], rim_D[2]; /* the face's sphere: radius, centre's distance along u, m */
    double rim_face_sin[2]; /* the face's edge: RIM_FACE_SIN, or half the rim's sine if less */
    double rim_mu_c;      /* viscous law on a rim: the Coulomb coefficient its force
                             saturates at (dynamics_equations.c, rim_friction) */
    double rim_mu_ratio2; /* (mu / rim_mu_c)^2, s^2/m^2: the saturation's scale, once */
    double min_stage_rim; /* least rim_stay over the stages of a step */
    double creep_cap;     /* patch law: the creep's relaxation held to at most creep_cap
                             times the motion's rate (creep_reduce); 0: the full law */
    double sqrt_g_over_R; /* the rocking rate's scale, rad/s */
} dyn_ctx;

/* The checks of a run's inputs (dynamics_model.c), before anything is set up. */
int tippe_dynamics_check_inputs(const tippe_dynamics_model *model,
                                const tippe_dynamics_initial *ic,
                                const tippe_dynamics_options *opt, tippe_error *err);

/* Tilts from a pole below RIM_FACE_SIN (sine) stand on the opening's flat face, not
 * on one point of its rim. A top whose spin is gone rocks on its flat end, its tilt
 * passing through 0: the rigid rim's contact would jump to the opposite point of the
 * rim (a rocking impact, Housner 1963), dq/dt unbounded, which no stepper crosses (msbdf
 * stalled at a tilt of 6e-11 rad). So the face is a sphere of radius r / RIM_FACE_SIN
 * through the rim (55 m on the M12, 0.27 um high): its lowest point moves smoothly
 * from the centre to the rim, where the load of a real face spreads once r times the
 * tilt is of the elastic approach's order (~1e-6 m over r ~ 5 mm: 1e-4). The face
 * carries the ring's drilling couple (dynamics_equations.c, ring_couple). An opening
 * narrower than that keeps half its sine for the face (a face sphere of radius 2 R). */
#define RIM_FACE_SIN 1e-4

/* Positive while the contact regime (c->rim, c->face) holds at axis k, crossing 0
 * where the contact moves between the sphere, a rim and its face: at the rim's polar
 * angle, where the rim's lowest point is the sphere's, and at the face's edge, where
 * the face's lowest point is on the rim (the contact is continuous at both). */
static inline double rim_stay(const dyn_ctx *c, const double k[3])
{
    if (c->rim) {
        const double S = hypot(k[0], k[1]);
        const double fs = c->rim_face_sin[c->rim - 1];
        if (c->face)
            return fs - S;
        const double edge = c->rim == 1 ? k[2] - c->rim_cos[0] : -k[2] - c->rim_cos[1];
        return fmin(edge, S - fs);
    }
    double s = INFINITY;
    if (c->rim_alpha[0] > 0.0)
        s = c->rim_cos[0] - k[2];
    if (c->rim_alpha[1] > 0.0 && c->rim_cos[1] + k[2] < s)
        s = c->rim_cos[1] + k[2];
    return s;
}

/* The regime at axis k: the rim of the pole within its half-angle (its face within
 * RIM_FACE_SIN of the pole), else the sphere. */
static inline int rim_regime(const dyn_ctx *c, const double k[3], int *face)
{
    const double S = hypot(k[0], k[1]);
    *face = 0;
    if (c->rim_alpha[0] > 0.0 && k[2] > c->rim_cos[0]) {
        *face = S < c->rim_face_sin[0];
        return 1;
    }
    if (c->rim_alpha[1] > 0.0 && -k[2] > c->rim_cos[1]) {
        *face = S < c->rim_face_sin[1];
        return 2;
    }
    return 0;
}

typedef struct {
    double k[3], w[3], v[3], q[3], VQ[3];
    double n, Rn, den, power;
    double M;       /* N m, drilling torque about e3 (patch law; 0 otherwise) */
    double patch_a; /* m, the patch radius at this Rn (patch law) */
    double mu_eff;  /* s/m: mu (viscous) or mu_c / sqrt(|V_Q|^2 + v_s^2) (Coulomb) */
    double F[2];    /* N, horizontal friction force */
    double wqd[3];  /* m/s^2, omega x dq/dt (q's rate as the contact moves over the body) */
    int ring;       /* on a rim exactly upright: the whole ring touches */
    double K[3][3]; /* contact compliance (Delassus) matrix, rolling phase only */
    double creep_slow; /* patch law: the factor s <= 1 the creep's relaxation ran at
                          (1: the full law) */
    double creep_power; /* W: the power the reduction changed, |(F - F_full).V_Q| */
    double wdot[3];
} contact;

static inline double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline void cross3(const double a[3], const double b[3], double out[3])
{
    double r0 = a[1] * b[2] - a[2] * b[1];
    double r1 = a[2] * b[0] - a[0] * b[2];
    double r2 = a[0] * b[1] - a[1] * b[0];
    out[0] = r0;
    out[1] = r1;
    out[2] = r2;
}

/* dynamics_equations.c */
int tippe_dynamics_contact_eval(const dyn_ctx *c, const double *y, contact *o);
void tippe_dynamics_paper_variables(const dyn_ctx *c, double t, const double *y, const contact *o,
                                    tippe_dynamics_sample *s);
double tippe_dynamics_energy(const dyn_ctx *c, const contact *o);
double tippe_dynamics_jellett(const dyn_ctx *c, const contact *o);
int tippe_dynamics_rhs(double t, const double y[], double f[], void *params);
int tippe_dynamics_jacobian(double t, const double y[], double *dfdy, double dfdt[], void *params);
void tippe_dynamics_euler_angles(const double *p, double *phi, double *psi);
int tippe_dynamics_solve3(const double K[3][3], const double b[3], double x[3]);
void tippe_dynamics_inv_inertia(const dyn_ctx *c, const double k[3], const double tau[3],
                                double out[3]);

/* The events located by bisection: lift-off (Rn = 0) and, while rolling, the end
 * of sticking (|F| = mu_c Rn, the edge of Coulomb's friction cone). */
enum { EVENT_LIFT_OFF = 0, EVENT_SLIP = 1, EVENT_RIM = 2 };

/* A switch between the sphere and a rim is taken once the regime's rim_stay is
 * below -this (cos alpha units, ~1e-12 rad): the bisection leaves the state within
 * 1e-13 of a step of the crossing, where |rim_stay| is ~1e-16, so the new regime
 * does not see its own start as a crossing back. */
#define RIM_EVENT_TOL 1e-12

/* dynamics_rim.c */
void tippe_dynamics_set_rims(dyn_ctx *c, const tippe_dynamics_model *model,
                             const tippe_dynamics_options *opt);
double tippe_dynamics_hull_height(const dyn_ctx *c, double theta);
double tippe_dynamics_event_value(const dyn_ctx *c, const contact *o, int event);
int tippe_dynamics_locate_lift_off(dyn_ctx *c, const gsl_odeiv2_system *sys, double t0,
                                   const double *y0, double H, int end_negative, int event,
                                   double *y, double *h_cross);
void tippe_dynamics_axis_rate(const contact *o, double k[3], double dk[3]);
int tippe_dynamics_step_may_dip(const dyn_ctx *c, const double k0[3], const double dk0[3],
                                double w0, const contact *end, double H);
int tippe_dynamics_locate_rim(dyn_ctx *c, const gsl_odeiv2_system *sys, double t0,
                              const double *y0, double H, int end_negative, double *y,
                              double *h_cross);

/* dynamics_model.c */
const gsl_odeiv2_step_type *tippe_dynamics_stepper_type(const char *name);

#endif
