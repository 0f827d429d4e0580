/* One launch of the eccentric sphere: the regular lab-frame equations of motion,
 * the energy and Jellett monitors, the lost-contact event and the settling
 * verdict. docs/dynamics.md derives the equations and documents each criterion. */
#include "tippe/dynamics.h"
#include "tippe/error.h"

#include <float.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* State layout. Verdict level: axis k, angular velocity omega, horizontal
 * velocity of the centre of mass, dissipated energy. Trajectory level adds the
 * orientation quaternion and the position of the centre of mass on the table. */
enum { IK = 0, IW = 3, IV = 6, ID = 8, IQ = 9, IX = 13 };
enum { DIM_VERDICT = 9, DIM_TRAJECTORY = 15 };

/* The accuracy presets, chosen from the work-precision benchmark
 * (tools/bench/run.sh, docs/performance.md): rk8pd is on the best front of
 * every non-stiff scenario from errors of 1e-4 down; its cost is set by the
 * step cap (1/8 period) down to rtol 1e-9, hence balanced there. fast is rkck,
 * which at the same cost as rkf45 is 2-6 times more accurate. */
static const struct {
    const char *name, *stepper;
    double rtol;
} presets[] = {
    {"fast", "rkck", 1e-6},
    {"balanced", "rk8pd", 1e-9},
    {"precise", "rk8pd", 1e-12},
};
enum { N_PRESETS = (int)(sizeof presets / sizeof presets[0]) };

static const struct {
    const char *name;
    const gsl_odeiv2_step_type *const *type;
} steppers[] = {
    {"rk2", &gsl_odeiv2_step_rk2},       {"rk4", &gsl_odeiv2_step_rk4},
    {"rkf45", &gsl_odeiv2_step_rkf45},   {"rkck", &gsl_odeiv2_step_rkck},
    {"rk8pd", &gsl_odeiv2_step_rk8pd},   {"rk1imp", &gsl_odeiv2_step_rk1imp},
    {"rk2imp", &gsl_odeiv2_step_rk2imp}, {"rk4imp", &gsl_odeiv2_step_rk4imp},
    {"bsimp", &gsl_odeiv2_step_bsimp},   {"msadams", &gsl_odeiv2_step_msadams},
    {"msbdf", &gsl_odeiv2_step_msbdf},
};
enum { N_STEPPERS = (int)(sizeof steppers / sizeof steppers[0]) };

const char *tippe_verdict_name(tippe_verdict v)
{
    switch (v) {
    case TIPPE_VERDICT_NO_TIP: return "no_tip";
    case TIPPE_VERDICT_TIP: return "tip";
    case TIPPE_VERDICT_HANG: return "hang";
    case TIPPE_VERDICT_LOST_CONTACT: return "lost_contact";
    case TIPPE_VERDICT_UNDECIDED: return "undecided";
    }
    return "?";
}

int tippe_dynamics_n_presets(void) { return N_PRESETS; }

const char *tippe_dynamics_preset_name(int i)
{
    return (i >= 0 && i < N_PRESETS) ? presets[i].name : NULL;
}

int tippe_dynamics_accuracy_preset(const char *name, tippe_dynamics_accuracy *out,
                                   tippe_error *err)
{
    for (int i = 0; i < N_PRESETS; i++)
        if (!strcmp(name, presets[i].name)) {
            snprintf(out->stepper, sizeof out->stepper, "%s", presets[i].stepper);
            out->rtol = presets[i].rtol;
            return TIPPE_OK;
        }
    return tippe_error_set(err, TIPPE_EINPUT,
                           "unknown accuracy preset '%s' (expected fast, balanced or precise)",
                           name);
}

static const gsl_odeiv2_step_type *stepper_type(const char *name)
{
    for (int i = 0; i < N_STEPPERS; i++)
        if (!strcmp(name, steppers[i].name))
            return *steppers[i].type;
    return NULL;
}

int tippe_dynamics_stepper_known(const char *name) { return stepper_type(name) != NULL; }

void tippe_dynamics_options_default(tippe_dynamics_options *o)
{
    memset(o, 0, sizeof *o);
    o->level = TIPPE_LEVEL_VERDICT;
    o->t_end = 100.0;
    tippe_dynamics_accuracy_preset("balanced", &o->accuracy, NULL);
    o->sample_dt = 0.0;
    o->settle_slip = 1e-4;
    o->settle_theta_rad = 2e-3;
    o->settle_vertical_rad = 1e-2;
    o->settle_periods = 4.0;
    o->settle_windows = 3;
    o->run_to_t_end = 0;
    o->max_steps = 10000000;
}

int tippe_dynamics_precession(const tippe_dynamics_model *model, double theta, double spin,
                              tippe_precession_rule rule, double *phi_dot, tippe_error *err)
{
    const tippe_top *t = &model->top;
    const double c = cos(theta);
    if (fabs(c) < 1e-12)
        return tippe_error_set(err, TIPPE_EINPUT,
                               "no steady precession rule at theta = pi/2 (cos theta = 0): "
                               "give phi_dot as a number");
    /* theta_ddot = 0 in eq 3.15 with theta_dot = U = 0, hence Rn = m g (eq 3.17)
     * and no friction torque about e2: A cos(theta) a^2 - C n a - m g eps = 0. */
    const double Cn = t->C * spin;
    const double disc = Cn * Cn + 4.0 * t->A * c * t->m * model->g * t->eps;
    if (rule == TIPPE_PRECESSION_S3) {
        *phi_dot = Cn / (2.0 * t->A * c);
        return TIPPE_OK;
    }
    if (disc < 0.0)
        return tippe_error_set(err, TIPPE_EINPUT,
                               "no real steady precession at theta = %g rad for spin %g rad/s "
                               "(C^2 n^2 + 4 A m g eps cos(theta) = %g < 0): use s3 or a number",
                               theta, spin, disc);
    double sign = 1.0;
    if (rule == TIPPE_PRECESSION_S2)
        sign = -1.0;
    else if (rule == TIPPE_PRECESSION_STEADY && spin < 0.0)
        sign = -1.0;
    *phi_dot = (Cn + sign * sqrt(disc)) / (2.0 * t->A * c);
    return TIPPE_OK;
}

/* ---- the equations of motion ------------------------------------------- */

typedef struct {
    double m, R, eps, A, C, g, mu;
    /* Constants of the right-hand side, once per run rather than per call. */
    double one_minus_A_over_C, C_minus_A_over_A, inv_A;
    size_t dim;
    long nevals;
    double min_stage_Rn;  /* smallest Rn met by any right-hand-side call since reset */
    int bad_contact;      /* the denominator of eq 3.19 was <= 0 */
    double scale[DIM_TRAJECTORY]; /* absolute scale per component */
} dyn_ctx;

typedef struct {
    double k[3], w[3], v[3], q[3], VQ[3];
    double n, Rn, den, power;
    double wdot[3];
} contact;

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross3(const double a[3], const double b[3], double out[3])
{
    double r0 = a[1] * b[2] - a[2] * b[1];
    double r1 = a[2] * b[0] - a[0] * b[2];
    double r2 = a[0] * b[1] - a[1] * b[0];
    out[0] = r0;
    out[1] = r1;
    out[2] = r2;
}

/* Everything the right-hand side needs from a state: the contact velocity, the
 * normal force in closed form, the angular acceleration. The axis is
 * normalised here, so |k| drifting at the integrator's tolerance never enters
 * the physics. Returns nonzero where the contact force is undetermined. */
static int contact_eval(const dyn_ctx *c, const double *y, contact *o)
{
    const double inv_kn = 1.0 / sqrt(dot3(y + IK, y + IK));
    for (int i = 0; i < 3; i++) {
        o->k[i] = y[IK + i] * inv_kn;
        o->w[i] = y[IW + i];
    }
    const double *k = o->k, *w = o->w;
    o->n = dot3(w, k);
    double wk[3];
    cross3(w, k, wk);
    /* q = CoM -> contact = eps k - R e3 (eq 3.6) */
    o->q[0] = c->eps * k[0];
    o->q[1] = c->eps * k[1];
    o->q[2] = c->eps * k[2] - c->R;
    /* The CoM height is R - eps k_z (eq 3.10), so its vertical velocity is
     * -eps (omega x k)_z (eq 3.11). */
    o->v[0] = y[IV];
    o->v[1] = y[IV + 1];
    o->v[2] = -c->eps * wk[2];
    double wq[3];
    cross3(w, o->q, wq);
    o->VQ[0] = o->v[0] + wq[0]; /* eq 3.7 */
    o->VQ[1] = o->v[1] + wq[1];
    o->VQ[2] = 0.0; /* vanishes identically by the constraint (eq 3.11) */
    /* F = Rn (e3 - mu V_Q) (eq 3.12): force and torque are linear in Rn. */
    const double f[3] = {-c->mu * o->VQ[0], -c->mu * o->VQ[1], 1.0};
    double tau[3];
    cross3(o->q, f, tau); /* torque per unit Rn about the CoM (eq 3.13) */
    const double tk = dot3(tau, k);
    /* A omega' = tau - (C - A)(n' k + n omega x k) with C n' = tau.k (eq 3.13 in
     * the lab frame): omega' = Rn a1 + a0. */
    double a1[3], a0[3];
    const double one_minus_AC = c->one_minus_A_over_C, inv_A = c->inv_A;
    const double minus_CmA_A_n = -c->C_minus_A_over_A * o->n;
    for (int i = 0; i < 3; i++) {
        a1[i] = (tau[i] - one_minus_AC * tk * k[i]) * inv_A;
        a0[i] = minus_CmA_A_n * wk[i];
    }
    double a1k[3], a0k[3], wwk[3];
    cross3(a1, k, a1k);
    cross3(a0, k, a0k);
    cross3(w, wk, wwk);
    /* m z'' = Rn - m g with z'' = -eps ((omega' x k)_z + (omega x (omega x k))_z)
     * (eq 3.16-3.17), solved for Rn: the lab form of eq 3.19, any m. */
    o->den = 1.0 + c->m * c->eps * a1k[2];
    if (!(o->den > 0.0))
        return 1;
    o->Rn = c->m * (c->g - c->eps * (a0k[2] + wwk[2])) / o->den;
    for (int i = 0; i < 3; i++)
        o->wdot[i] = o->Rn * a1[i] + a0[i];
    o->power = c->mu * o->Rn * (o->VQ[0] * o->VQ[0] + o->VQ[1] * o->VQ[1]); /* eq 4.1 */
    return 0;
}

static int rhs(double t, const double y[], double f[], void *params)
{
    (void)t;
    dyn_ctx *c = params;
    c->nevals++;
    contact o;
    if (contact_eval(c, y, &o)) {
        /* Not GSL_EBADFUNC: a trial stage of a too-long step can leave the
         * region where eq 3.19 is defined, and GSL then retries with a shorter
         * step. Only if the step shrinks to nothing is the model at fault. */
        c->bad_contact = 1;
        return GSL_EDOM;
    }
    if (o.Rn < c->min_stage_Rn)
        c->min_stage_Rn = o.Rn;
    /* dk/dt = omega x k with the unnormalised k: the exact flow keeps |k|. */
    cross3(o.w, y + IK, f + IK);
    for (int i = 0; i < 3; i++)
        f[IW + i] = o.wdot[i];
    f[IV] = -c->mu * o.Rn * o.VQ[0] / c->m; /* eq 3.14 horizontal */
    f[IV + 1] = -c->mu * o.Rn * o.VQ[1] / c->m;
    f[ID] = o.power;
    if (c->dim == DIM_TRAJECTORY) {
        /* q' = (0, omega) q / 2 for a lab-frame angular velocity. */
        const double *p = y + IQ;
        double wp[3];
        cross3(o.w, p + 1, wp);
        f[IQ] = -0.5 * dot3(o.w, p + 1);
        for (int i = 0; i < 3; i++)
            f[IQ + 1 + i] = 0.5 * (p[0] * o.w[i] + wp[i]);
        f[IX] = o.v[0];
        f[IX + 1] = o.v[1];
    }
    return GSL_SUCCESS;
}

/* Forward-difference Jacobian for the implicit steppers (rk1imp, rk2imp,
 * rk4imp, bsimp, msbdf): its error only slows their Newton iterations. */
static int jacobian(double t, const double y[], double *dfdy, double dfdt[], void *params)
{
    dyn_ctx *c = params;
    const size_t d = c->dim;
    double f0[DIM_TRAJECTORY], f1[DIM_TRAJECTORY], yp[DIM_TRAJECTORY];
    int s = rhs(t, y, f0, c);
    if (s != GSL_SUCCESS)
        return s;
    memcpy(yp, y, d * sizeof *y);
    for (size_t j = 0; j < d; j++) {
        const double save = yp[j];
        double hj = sqrt(DBL_EPSILON) * fmax(fabs(save), c->scale[j]);
        yp[j] = save + hj;
        hj = yp[j] - save; /* the step actually representable */
        s = rhs(t, yp, f1, c);
        yp[j] = save;
        if (s != GSL_SUCCESS)
            return s;
        for (size_t i = 0; i < d; i++)
            dfdy[i * d + j] = (f1[i] - f0[i]) / hj;
    }
    for (size_t i = 0; i < d; i++)
        dfdt[i] = 0.0;
    return GSL_SUCCESS;
}

/* ---- paper variables and monitors -------------------------------------- */

static double energy(const dyn_ctx *c, const contact *o)
{
    double L[3];
    for (int i = 0; i < 3; i++)
        L[i] = c->A * o->w[i] + (c->C - c->A) * o->n * o->k[i];
    /* sec 4: translational + rotational kinetic energy + m g h (eq 3.10) */
    return 0.5 * c->m * dot3(o->v, o->v) + 0.5 * dot3(o->w, L) +
           c->m * c->g * (c->R - c->eps * o->k[2]);
}

static double jellett(const dyn_ctx *c, const contact *o)
{
    double L[3];
    for (int i = 0; i < 3; i++)
        L[i] = c->A * o->w[i] + (c->C - c->A) * o->n * o->k[i];
    return -dot3(L, o->q); /* eq 3.20 */
}

/* The paper's variables (eq 3.4) from the regular state: e1 is the horizontal
 * direction of k (the lab x axis when k is vertical), i = cos(theta) e1 -
 * sin(theta) e3, omega = -phi_dot sin(theta) i + theta_dot e2 + n k. */
static void paper_variables(const dyn_ctx *c, double t, const double *y, const contact *o,
                            tippe_dynamics_sample *s)
{
    const double *k = o->k, *w = o->w;
    const double sth = hypot(k[0], k[1]), cth = k[2];
    double e1x = 1.0, e1y = 0.0;
    if (sth > 0.0) {
        e1x = k[0] / sth;
        e1y = k[1] / sth;
    }
    s->t = t;
    s->theta = atan2(sth, cth);
    s->theta_dot = -w[0] * e1y + w[1] * e1x;
    const double wi = cth * (w[0] * e1x + w[1] * e1y) - sth * w[2];
    /* phi_dot is undefined on the vertical; reported as 0 there. */
    s->phi_dot = sth > 1e-9 ? -wi / sth : 0.0;
    s->spin = o->n;
    s->U = o->v[0] * e1x + o->v[1] * e1y;
    s->V = -o->v[0] * e1y + o->v[1] * e1x;
    s->phi = s->psi = s->x = s->y = NAN;
    s->Rn = o->Rn;
    s->slip_speed = hypot(o->VQ[0], o->VQ[1]);
    s->E = energy(c, o);
    s->D = y[ID];
    s->J = jellett(c, o);
}

static double unwrap(double raw, double prev)
{
    return raw + 2.0 * M_PI * round((prev - raw) / (2.0 * M_PI));
}

/* Euler angles (phi, theta, psi), rotation Rz(phi) Ry(theta) Rz(psi), from the
 * orientation quaternion, continued from the previous values; on the vertical
 * only phi + psi (theta = 0) or phi - psi (theta = pi) is defined, and phi keeps
 * its previous value. */
static void euler_angles(const double *p, double *phi, double *psi)
{
    const double nq = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2] + p[3] * p[3]);
    const double w = p[0] / nq, x = p[1] / nq, y = p[2] / nq, z = p[3] / nq;
    const double R11 = 1 - 2 * (y * y + z * z), R21 = 2 * (x * y + w * z);
    const double R13 = 2 * (x * z + w * y), R23 = 2 * (y * z - w * x);
    const double R31 = 2 * (x * z - w * y), R32 = 2 * (y * z + w * x);
    const double R33 = 1 - 2 * (x * x + y * y);
    const double sth = hypot(R13, R23);
    if (sth > 1e-9) {
        *phi = unwrap(atan2(R23, R13), *phi);
        *psi = unwrap(atan2(R32, -R31), *psi);
    } else if (R33 > 0) {
        *psi = unwrap(atan2(R21, R11) - *phi, *psi);
    } else {
        *psi = unwrap(*phi - atan2(-R21, -R11), *psi);
    }
}

/* ---- settling ------------------------------------------------------------ */

typedef struct {
    double t_start, length;
    double theta_min, theta_max, slip_max;
    double prev_slip[8]; /* largest slip ratio of the previous windows, newest first */
    int n_prev;
} settle_window;

/* The slowest natural rate near the current state: the smaller root of
 * A cos(theta) a^2 - C n a - m g eps = 0, the slow precession of a sleeping
 * top (eq A.11 at theta = 0) and the pendulum rate without spin. */
static double slow_rate(const dyn_ctx *c, double theta, double n, double omega_scale)
{
    const double co = cos(theta), Cn = c->C * n, mge = c->m * c->g * c->eps;
    const double disc = Cn * Cn + 4.0 * c->A * co * mge;
    double rate;
    if (disc >= 0.0) {
        const double big = Cn + copysign(sqrt(disc), Cn);
        rate = big != 0.0 ? fabs(2.0 * mge / big) : 0.0;
    } else {
        rate = sqrt(mge / (c->A * fabs(co))); /* complex pair: common modulus */
    }
    /* A centred sphere (eps = 0) has no gravitational precession: fall back to
     * a hundredth of the rotation rate so that windows stay finite. */
    return fmax(rate, 1e-2 * omega_scale);
}

static void window_start(settle_window *w, const dyn_ctx *c, const tippe_dynamics_options *o,
                         double t, double theta, double n, double omega_scale)
{
    w->t_start = t;
    w->length = o->settle_periods * 2.0 * M_PI / slow_rate(c, theta, n, omega_scale);
    w->theta_min = INFINITY;
    w->theta_max = -INFINITY;
    w->slip_max = 0.0;
}

/* ---- the run --------------------------------------------------------------- */

static void set_omega_scale(const dyn_ctx *c, const double *y, double *omega_scale)
{
    *omega_scale = sqrt(dot3(y + IW, y + IW)) + sqrt(c->g / c->R);
}

static int check_inputs(const tippe_dynamics_model *model, const tippe_dynamics_initial *ic,
                        const tippe_dynamics_options *opt, tippe_error *err)
{
    const tippe_top *t = &model->top;
    if (!(t->m > 0 && isfinite(t->m)) || !(t->R > 0 && isfinite(t->R)) ||
        !(t->A > 0 && isfinite(t->A)) || !(t->C > 0 && isfinite(t->C)))
        return tippe_error_set(err, TIPPE_EINPUT, "top: m, R, A and C must be positive and finite");
    if (!(t->eps >= 0 && t->eps < t->R))
        return tippe_error_set(err, TIPPE_EINPUT, "top: eps = %g m must satisfy 0 <= eps < R = %g m",
                               t->eps, t->R);
    if (!(model->g > 0 && isfinite(model->g)))
        return tippe_error_set(err, TIPPE_EINPUT, "g = %g m/s^2 must be positive", model->g);
    if (!(model->mu >= 0 && isfinite(model->mu)))
        return tippe_error_set(err, TIPPE_EINPUT, "mu = %g s/m must be >= 0", model->mu);
    if (!(ic->theta >= 0 && ic->theta <= M_PI))
        return tippe_error_set(err, TIPPE_EINPUT, "initial theta = %g rad must be in [0, pi]",
                               ic->theta);
    if (!isfinite(ic->theta_dot) || !isfinite(ic->phi_dot) || !isfinite(ic->spin) ||
        !isfinite(ic->U) || !isfinite(ic->V))
        return tippe_error_set(err, TIPPE_EINPUT, "initial state must be finite");
    if (!(opt->t_end > 0 && isfinite(opt->t_end)))
        return tippe_error_set(err, TIPPE_EINPUT, "t_end = %g s must be positive", opt->t_end);
    if (!stepper_type(opt->accuracy.stepper))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "unknown stepper '%s' (rk2, rk4, rkf45, rkck, rk8pd, rk1imp, "
                               "rk2imp, rk4imp, bsimp, msadams, msbdf)",
                               opt->accuracy.stepper);
    if (!(opt->accuracy.rtol >= 1e-14 && opt->accuracy.rtol <= 1e-2))
        return tippe_error_set(err, TIPPE_EINPUT, "rtol = %g must be in [1e-14, 1e-2]",
                               opt->accuracy.rtol);
    if (opt->max_steps < 0)
        return tippe_error_set(err, TIPPE_EINPUT, "max_steps = %ld must be >= 0 (0: no budget)",
                               opt->max_steps);
    if (!(opt->settle_slip > 0) || !(opt->settle_theta_rad > 0) ||
        !(opt->settle_vertical_rad > 0) || !(opt->settle_periods > 0) ||
        opt->settle_windows < 2 || opt->settle_windows > 8)
        return tippe_error_set(err, TIPPE_EINPUT,
                               "settling options must be positive, with 2..8 windows");
    return TIPPE_OK;
}

static void ctx_init(dyn_ctx *c, const tippe_dynamics_model *model, size_t dim)
{
    memset(c, 0, sizeof *c);
    c->m = model->top.m;
    c->R = model->top.R;
    c->eps = model->top.eps;
    c->A = model->top.A;
    c->C = model->top.C;
    c->g = model->g;
    c->mu = model->mu;
    c->one_minus_A_over_C = 1.0 - c->A / c->C;
    c->C_minus_A_over_A = (c->C - c->A) / c->A;
    c->inv_A = 1.0 / c->A;
    c->dim = dim;
    c->min_stage_Rn = INFINITY;
}

/* The regular state of a launch given in the paper's variables (eq 3.4),
 * with phi = psi = 0: k = (sin theta, 0, cos theta). */
static void initial_state(const dyn_ctx *c, const tippe_dynamics_initial *ic, double *y)
{
    const double s = ic->theta == M_PI ? 0.0 : sin(ic->theta), co = cos(ic->theta);
    const double iv[3] = {co, 0.0, -s}, jv[3] = {0.0, 1.0, 0.0}, kv[3] = {s, 0.0, co};
    for (int a = 0; a < 3; a++) {
        y[IK + a] = kv[a];
        y[IW + a] = -ic->phi_dot * s * iv[a] + ic->theta_dot * jv[a] + ic->spin * kv[a];
    }
    y[IV] = ic->U;
    y[IV + 1] = ic->V;
    y[ID] = 0.0;
    if (c->dim == DIM_TRAJECTORY) {
        y[IQ] = cos(0.5 * ic->theta); /* rotation by theta about the lab y axis */
        y[IQ + 1] = 0.0;
        y[IQ + 2] = sin(0.5 * ic->theta);
        y[IQ + 3] = 0.0;
        y[IX] = y[IX + 1] = 0.0;
    }
}

int tippe_dynamics_evaluate(const tippe_dynamics_model *model, const tippe_dynamics_initial *s,
                            tippe_dynamics_sample *out, tippe_error *err)
{
    tippe_dynamics_options o;
    tippe_dynamics_options_default(&o);
    int st = check_inputs(model, s, &o, err);
    if (st)
        return st;
    dyn_ctx c;
    ctx_init(&c, model, DIM_VERDICT);
    double y[DIM_VERDICT];
    initial_state(&c, s, y);
    contact ct;
    if (contact_eval(&c, y, &ct))
        return tippe_error_set(err, TIPPE_ECOMPUTE,
                               "contact force undetermined at this state (denominator of eq "
                               "3.19 <= 0: friction too strong for the model)");
    paper_variables(&c, 0.0, y, &ct, out);
    out->phi = out->psi = out->x = out->y = 0.0;
    return TIPPE_OK;
}

/* Normal force after a trial step of length h from (t0, y0) with a high-order
 * one-step method: the function that the lost-contact bisection brackets. */
static int Rn_after(dyn_ctx *c, gsl_odeiv2_step *bs, const gsl_odeiv2_system *sys, double t0,
                    const double *y0, double h, double *y, double *Rn)
{
    double yerr[DIM_TRAJECTORY];
    memcpy(y, y0, c->dim * sizeof *y);
    if (h > 0.0) {
        gsl_odeiv2_step_reset(bs);
        int s = gsl_odeiv2_step_apply(bs, t0, h, y, yerr, NULL, NULL, sys);
        if (s != GSL_SUCCESS)
            return s;
    }
    contact o;
    if (contact_eval(c, y, &o))
        return GSL_EBADFUNC;
    *Rn = o.Rn;
    return GSL_SUCCESS;
}

/* Finds where Rn crosses 0 inside the accepted step (t0, y0) -> t0 + H. The
 * crossing is bracketed either by Rn(H) < 0 or, when only an intermediate
 * stage saw Rn < 0, by scanning 16 sub-steps; it is then bisected to 1e-13 H
 * with an rk8pd step from y0, whatever the main stepper (a single rk8pd step no
 * longer than an accepted step is at least as accurate). On success y holds
 * the state with Rn >= 0 at the crossing and *h_cross its offset from t0.
 * Returns 1 if a crossing was found, 0 if none, < 0 on failure. */
static int locate_lift_off(dyn_ctx *c, const gsl_odeiv2_system *sys, double t0, const double *y0,
                           double H, int end_negative, double *y, double *h_cross)
{
    gsl_odeiv2_step *bs = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, c->dim);
    if (!bs)
        return -1;
    double ytmp[DIM_TRAJECTORY], Rn = 0.0, lo = 0.0, hi = H;
    int found = end_negative, status = 0;
    if (!found) {
        const int n_scan = 16;
        for (int i = 1; i <= n_scan; i++) {
            double hh = H * i / n_scan;
            if (Rn_after(c, bs, sys, t0, y0, hh, ytmp, &Rn) != GSL_SUCCESS) {
                status = -1;
                break;
            }
            if (Rn < 0.0) {
                lo = H * (i - 1) / n_scan;
                hi = hh;
                found = 1;
                break;
            }
        }
    }
    if (found && status == 0) {
        for (int it = 0; it < 200 && hi - lo > 1e-13 * H; it++) {
            double mid = 0.5 * (lo + hi);
            if (Rn_after(c, bs, sys, t0, y0, mid, ytmp, &Rn) != GSL_SUCCESS) {
                status = -1;
                break;
            }
            if (Rn < 0.0)
                hi = mid;
            else
                lo = mid;
        }
        if (status == 0 && Rn_after(c, bs, sys, t0, y0, lo, y, &Rn) != GSL_SUCCESS)
            status = -1;
        *h_cross = lo;
    }
    gsl_odeiv2_step_free(bs);
    return status < 0 ? status : found;
}

int tippe_dynamics_run(const tippe_dynamics_model *model, const tippe_dynamics_initial *ic,
                       const tippe_dynamics_options *opt, tippe_dynamics_result *res,
                       tippe_error *err)
{
    tippe_gsl_errors_as_codes();

    memset(res, 0, sizeof *res);
    res->verdict = TIPPE_VERDICT_UNDECIDED;
    int st = check_inputs(model, ic, opt, err);
    if (st)
        return st;

    const int traj = opt->level == TIPPE_LEVEL_TRAJECTORY;
    dyn_ctx c;
    ctx_init(&c, model, traj ? DIM_TRAJECTORY : DIM_VERDICT);
    res->state_dim = (int)c.dim;

    double y[DIM_TRAJECTORY], y_prev[DIM_TRAJECTORY];
    initial_state(&c, ic, y);
    double omega_scale;
    set_omega_scale(&c, y, &omega_scale);

    /* Absolute tolerance = rtol * scale per component: unit vectors 1, angular
     * velocity the launch's rotation rate, velocities and positions from R. */
    const double v_scale = c.R * omega_scale;
    for (size_t i = 0; i < c.dim; i++)
        c.scale[i] = 1.0;
    for (int i = 0; i < 3; i++)
        c.scale[IW + i] = omega_scale;
    c.scale[IV] = c.scale[IV + 1] = v_scale;

    contact ct;
    if (contact_eval(&c, y, &ct))
        return tippe_error_set(err, TIPPE_ECOMPUTE,
                               "contact force undetermined at launch (denominator of eq 3.19 "
                               "= %g <= 0: friction too strong for the model)",
                               ct.den);
    res->E0 = energy(&c, &ct);
    res->J0 = jellett(&c, &ct);
    c.scale[ID] = res->E0;
    if (traj)
        c.scale[IX] = c.scale[IX + 1] = c.R;
    const double J_scale = fmax(fabs(res->J0), 1e-6 * c.C * omega_scale * c.R);

    gsl_odeiv2_system sys = {rhs, jacobian, c.dim, &c};
    const gsl_odeiv2_step_type *T = stepper_type(opt->accuracy.stepper);
    const double rtol = opt->accuracy.rtol;
    /* The fastest natural period bounds the step, so that the settling windows
     * see every oscillation. */
    const double h_max = 0.125 * 2.0 * M_PI / omega_scale;
    double h = 1e-3 * h_max;
    gsl_odeiv2_driver *drv =
        gsl_odeiv2_driver_alloc_scaled_new(&sys, T, h, rtol, rtol, 1.0, 0.0, c.scale);
    if (!drv)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "cannot allocate the GSL driver");

    double t = 0.0, phi = 0.0, psi = 0.0;
    double E_min = res->E0;
    tippe_dynamics_sample smp;
    paper_variables(&c, t, y, &ct, &smp);
    res->min_Rn = ct.Rn;
    res->final = smp;
    int status = TIPPE_OK, done = 0;

    if (ct.Rn < 0.0) {
        /* Launched already pulling away from the table. */
        res->verdict = TIPPE_VERDICT_LOST_CONTACT;
        done = 1;
    }
    if (traj) {
        smp.phi = phi;
        smp.psi = psi;
        smp.x = smp.y = 0.0;
        res->final = smp;
        if (opt->on_sample) {
            int cb = opt->on_sample(&smp, opt->sample_ctx);
            if (cb) {
                status = tippe_error_set(err, TIPPE_ECOMPUTE, "sample callback stopped the run (%d)", cb);
                done = 1;
            }
        }
    }

    settle_window win;
    memset(&win, 0, sizeof win);
    window_start(&win, &c, opt, t, smp.theta, smp.spin, omega_scale);
    long i_sample = 1;

    while (!done && t < opt->t_end) {
        if (opt->max_steps > 0 && res->steps >= opt->max_steps) {
            res->budget_exhausted = 1;
            break;
        }
        double t_target = opt->t_end;
        if (traj && opt->sample_dt > 0.0)
            t_target = fmin(opt->t_end, (double)i_sample * opt->sample_dt);
        if (h > h_max)
            h = h_max;
        const double t_prev = t;
        memcpy(y_prev, y, c.dim * sizeof *y);
        c.min_stage_Rn = INFINITY;
        c.bad_contact = 0;
        int s = gsl_odeiv2_evolve_apply(drv->e, drv->c, drv->s, &sys, &t, t_target, &h, y);
        if (s != GSL_SUCCESS) {
            if (c.bad_contact)
                status = tippe_error_set(err, TIPPE_ECOMPUTE,
                                         "at t = %g s the contact force became undetermined "
                                         "(denominator of eq 3.19 <= 0: friction mu = %g s/m "
                                         "too strong for the model)",
                                         t, c.mu);
            else
                status = tippe_error_set(err, TIPPE_ECOMPUTE,
                                         "integrator (%s, rtol %g) failed at t = %g s: %s",
                                         opt->accuracy.stepper, rtol, t, gsl_strerror(s));
            break;
        }
        res->steps++;
        if (contact_eval(&c, y, &ct)) {
            status = tippe_error_set(err, TIPPE_ECOMPUTE,
                                     "at t = %g s the contact force became undetermined "
                                     "(denominator of eq 3.19 <= 0)", t);
            break;
        }
        if (ct.Rn < 0.0 || c.min_stage_Rn < 0.0) {
            /* Never accept a state with Rn < 0: find where it reached 0. */
            double hc = 0.0, ycross[DIM_TRAJECTORY];
            int f = locate_lift_off(&c, &sys, t_prev, y_prev, t - t_prev, ct.Rn < 0.0, ycross, &hc);
            if (f < 0) {
                status = tippe_error_set(err, TIPPE_ECOMPUTE,
                                         "failed to locate the lift-off near t = %g s", t);
                break;
            }
            if (f == 1) {
                t = t_prev + hc;
                memcpy(y, ycross, c.dim * sizeof *y);
                contact_eval(&c, y, &ct);
                res->verdict = TIPPE_VERDICT_LOST_CONTACT;
                done = 1;
            }
        }

        paper_variables(&c, t, y, &ct, &smp);
        /* monitors */
        const double dJ = fabs(smp.J - res->J0) / J_scale;
        if (dJ > res->jellett_rel_drift)
            res->jellett_rel_drift = dJ;
        const double dE = fabs(smp.E + smp.D - res->E0) / res->E0;
        if (dE > res->energy_rel_error)
            res->energy_rel_error = dE;
        if (smp.E - E_min > res->energy_max_rise)
            res->energy_max_rise = smp.E - E_min;
        if (smp.E < E_min)
            E_min = smp.E;
        if (ct.Rn < res->min_Rn)
            res->min_Rn = ct.Rn;

        if (traj) {
            euler_angles(y + IQ, &phi, &psi);
            smp.phi = phi;
            smp.psi = psi;
            smp.x = y[IX];
            smp.y = y[IX + 1];
            int due = opt->sample_dt <= 0.0 || t >= t_target || done;
            if (opt->sample_dt > 0.0 && t >= t_target)
                i_sample++;
            if (due && opt->on_sample) {
                int cb = opt->on_sample(&smp, opt->sample_ctx);
                if (cb) {
                    status = tippe_error_set(err, TIPPE_ECOMPUTE,
                                             "sample callback stopped the run (%d)", cb);
                    break;
                }
            }
        }
        if (done) {
            res->t_verdict = t;
            res->final = smp;
            break;
        }

        /* settling */
        if (res->verdict == TIPPE_VERDICT_UNDECIDED) {
            set_omega_scale(&c, y, &omega_scale);
            const double slip = smp.slip_speed / (c.R * omega_scale);
            if (slip > win.slip_max)
                win.slip_max = slip;
            if (smp.theta < win.theta_min)
                win.theta_min = smp.theta;
            if (smp.theta > win.theta_max)
                win.theta_max = smp.theta;
            if (t - win.t_start >= win.length) {
                int ok = win.n_prev >= opt->settle_windows - 1 && win.slip_max < opt->settle_slip &&
                         win.theta_max - win.theta_min < opt->settle_theta_rad;
                /* Decaying: near an unstable equilibrium the contact speed grows. */
                for (int i = 0; ok && i < opt->settle_windows - 1; i++) {
                    double newer = i == 0 ? win.slip_max : win.prev_slip[i - 1];
                    if (!(newer < win.prev_slip[i]))
                        ok = 0;
                }
                if (ok) {
                    const double th = 0.5 * (win.theta_min + win.theta_max);
                    if (th < opt->settle_vertical_rad)
                        res->verdict = TIPPE_VERDICT_NO_TIP;
                    else if (th > M_PI - opt->settle_vertical_rad)
                        res->verdict = TIPPE_VERDICT_TIP;
                    else
                        res->verdict = TIPPE_VERDICT_HANG;
                    res->t_verdict = t;
                    res->final = smp;
                    if (!opt->run_to_t_end)
                        break;
                }
                for (int i = 7; i > 0; i--)
                    win.prev_slip[i] = win.prev_slip[i - 1];
                win.prev_slip[0] = win.slip_max;
                if (win.n_prev < 8)
                    win.n_prev++;
                window_start(&win, &c, opt, t, smp.theta, smp.spin, omega_scale);
            }
        }
    }

    res->last = smp;
    if (res->verdict == TIPPE_VERDICT_UNDECIDED) {
        res->t_verdict = t;
        res->final = smp;
    }
    res->rhs_evals = c.nevals;
    res->rejected_steps = (long)drv->e->failed_steps;
    gsl_odeiv2_driver_free(drv);
    return status;
}
