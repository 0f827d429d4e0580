/* The equations of motion in the lab frame (the right-hand side, its Jacobian,
 * the contact and its normal force, eq 3.19) and the paper's variables and
 * monitors (energy, Jellett's J, Euler angles) computed from a state. */
#include "physics/contact_patch_law.h"
#include "physics/dynamics_state.h"
#include "tippe/base.h"

#include <float.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* The rolling resistance's regularisation speed, rad/s: the sign law smoothed below it. */
#define ROLL_W_S 1e-3
/* A radius that follows the load is corrected this many times from the static one: a
 * fixed count keeps the right-hand side a smooth function of the state. One correction
 * leaves a off Hertz's radius at the final Rn by the map a -> a0 (Rn(a) / m g)^(1/3)'s
 * slope (~1e-2, the drilling couple's share of the torque) times a's swing (~1 %):
 * measured 7.8e-5 of a0 on an M12 launch (tests/test_patch_dynamics.c), inside Hertz's
 * own accuracy (of order a / R ~ 1e-2). Each pass costs a whole wrench and normal
 * force: one correction costs ~1.3x the CPU of a fixed radius, where iterating to
 * rounding cost 2x. */
#define PATCH_LOAD_CORRECTIONS 1


/* The angular acceleration that a torque tau about the centre of mass adds:
 * A omega' = tau - (1 - A/C)(tau.k) k (the lab form of eq 3.13, L = A omega + (C - A) n k).
 * Inline here, where the creep's reduction applies it twice an evaluation. */
static inline void inv_inertia(const dyn_ctx *c, const double k[3], const double tau[3],
                               double out[3])
{
    const double tk = dot3(tau, k);
    for (int i = 0; i < 3; i++)
        out[i] = (tau[i] - c->one_minus_A_over_C * tk * k[i]) * c->inv_A;
}

/* inv_inertia for the other files (dynamics.c's impulses). */
void tippe_dynamics_inv_inertia(const dyn_ctx *c, const double k[3], const double tau[3], double out[3])
{
    inv_inertia(c, k, tau, out);
}

/* K P: the change of the contact point's velocity V_Q = v + omega x q that a
 * force (or impulse) P at the contact makes, P/m + (I^-1 (q x P)) x q. K is
 * symmetric positive definite (the contact's Delassus matrix). In closed form, with
 * I^-1 x = (x - beta (x.k) k) / A, beta = 1 - A/C (eq 3.13) and p = k x q:
 *   (q x P) x q = |q|^2 P - (q.P) q,  (q x P).k = p.P,  (k x q) = p, so
 *   K = (1/m + |q|^2/A) 1 - (q q^T + beta p p^T) / A,
 * a third of the work of applying I^-1 to three unit forces (the patch law's creep
 * reduction builds it at every evaluation). */
static void compliance(const dyn_ctx *c, const double k[3], const double q[3], double K[3][3])
{
    double p[3];
    cross3(k, q, p);
    const double inv_A = c->inv_A, beta = c->one_minus_A_over_C;
    const double diag = 1.0 / c->m + dot3(q, q) * inv_A;
    for (int i = 0; i < 3; i++)
        for (int j = i; j < 3; j++) {
            const double kij = (i == j ? diag : 0.0) - (q[i] * q[j] + beta * p[i] * p[j]) * inv_A;
            K[i][j] = K[j][i] = kij;
        }
}

/* x = K^-1 b by the adjugate (3 x 3; K positive definite, or the rolling system with
 * the patch's couples, nearly so: det > 0). Inline here for the creep's reduction. */
static inline int solve3(const double K[3][3], const double b[3], double x[3])
{
    const double c00 = K[1][1] * K[2][2] - K[1][2] * K[2][1];
    const double c01 = K[1][2] * K[2][0] - K[1][0] * K[2][2];
    const double c02 = K[1][0] * K[2][1] - K[1][1] * K[2][0];
    const double det = K[0][0] * c00 + K[0][1] * c01 + K[0][2] * c02;
    if (!(det > 0.0))
        return 1;
    const double c10 = K[0][2] * K[2][1] - K[0][1] * K[2][2];
    const double c11 = K[0][0] * K[2][2] - K[0][2] * K[2][0];
    const double c12 = K[0][1] * K[2][0] - K[0][0] * K[2][1];
    const double c20 = K[0][1] * K[1][2] - K[0][2] * K[1][1];
    const double c21 = K[0][2] * K[1][0] - K[0][0] * K[1][2];
    const double c22 = K[0][0] * K[1][1] - K[0][1] * K[1][0];
    const double inv_det = 1.0 / det;
    /* x_j = sum_i C_ij b_i / det, C the cofactors (adj K = C^T) */
    x[0] = (c00 * b[0] + c10 * b[1] + c20 * b[2]) * inv_det;
    x[1] = (c01 * b[0] + c11 * b[1] + c21 * b[2]) * inv_det;
    x[2] = (c02 * b[0] + c12 * b[1] + c22 * b[2]) * inv_det;
    return 0;
}

/* solve3 for the other files (dynamics.c's impulses). */
int tippe_dynamics_solve3(const double K[3][3], const double b[3], double x[3])
{
    return solve3(K, b, x);
}

/* The contact's wrench per unit Rn: the force f (f[2] = 1, the normal), the
 * drilling couple M about e3 and the rolling couple Mroll, and the power they
 * dissipate. Viscous and Coulomb fill f alone. */
typedef struct {
    double f[3];
    double M, diss;
    double Mroll[2];
} per_Rn;

/* The patch law's wrench at radius a (docs/contact-patch.md): Coulomb-Contensou
 * over the patch, mu_c times functions of (V_Q, omega_n) alone, with omega_n =
 * omega.e3 as the table is at rest; and the rolling couple when its arm is set
 * (docs/contact-patch.md, section 5). */
static void patch_wrench(const dyn_ctx *c, const contact *o, double a, per_Rn *u)
{
    tippe_contact_patch_wrench pw;
    /* tippe_contact_patch_friction's Hertz law, inlined with its coefficients as constants */
    patch_friction(PATCH_LAW_HERTZ, c->mu_c, a, c->vs, o->VQ, o->w[2], &pw);
    u->f[0] = pw.F[0];
    u->f[1] = pw.F[1];
    u->M = pw.M;
    u->diss = pw.dissipation;
    if (c->roll_arm > 0.0)
        u->diss += tippe_contact_rolling_resistance(1.0, c->roll_arm, ROLL_W_S, o->w, u->Mroll);
}

/* The contact on rim c->rim (docs/dynamics.md, "The contact on a rim"): the
 * lowest point of the hull is the rim circle's lowest point,
 *   q = eps k + R cos(alpha) u + r W,  r = R sin(alpha),
 * u = -k on pole [0], +k on pole [1], and W the unit vector perpendicular to u
 * pointing down in the vertical plane through u: W = (u_z u_h/|u_h|, -|u_h|). The
 * contact runs along the rim as the axis turns; its rate dq/dt enters the normal
 * force and the rolling constraint through omega x dq/dt (the sphere's eps omega x
 * (omega x k)). The rim's tangent at its lowest point is horizontal, so the
 * centre's height -q_z still changes at -(omega x q)_z, as on the sphere. */
static void rim_geometry(const dyn_ctx *c, contact *o, const double wk[3])
{
    const int p = c->rim - 1;
    const double s = p ? 1.0 : -1.0, Rc = c->rim_Rcos[p], r = c->rim_r[p];
    const double *k = o->k;
    const double u[3] = {s * k[0], s * k[1], s * k[2]};
    const double ud[3] = {s * wk[0], s * wk[1], s * wk[2]}; /* du/dt = omega x u */
    o->ring = c->face;
    if (c->face) {
        /* the face's sphere (RIM_FACE_SIN): its lowest point, as the paper's sphere's */
        double qd[3];
        const double D = c->rim_D[p];
        for (int i = 0; i < 3; i++) {
            o->q[i] = c->eps * k[i] + D * u[i];
            qd[i] = c->eps * wk[i] + D * ud[i];
        }
        o->q[2] -= c->rim_rho[p];
        cross3(o->w, qd, o->wqd);
        return;
    }
    /* off the face S >= its edge's sine (> 0): the tilt's direction u_h / S is defined
     * (and sqrt of the squares is exact enough: no underflow above 1e-154) */
    const double S = sqrt(u[0] * u[0] + u[1] * u[1]), inv_S = 1.0 / S;
    const double hx = u[0] * inv_S, hy = u[1] * inv_S;
    const double Sd = hx * ud[0] + hy * ud[1];
    const double hdx = (ud[0] - hx * Sd) * inv_S, hdy = (ud[1] - hy * Sd) * inv_S;
    const double W[3] = {u[2] * hx, u[2] * hy, -S};
    const double Wd[3] = {ud[2] * hx + u[2] * hdx, ud[2] * hy + u[2] * hdy, -Sd};
    double qd[3];
    for (int i = 0; i < 3; i++) {
        o->q[i] = c->eps * k[i] + Rc * u[i] + r * W[i];
        qd[i] = c->eps * wk[i] + Rc * ud[i] + r * Wd[i];
    }
    cross3(o->w, qd, o->wqd);
}

/* The viscous law on a rim, s/m. Eq 3.12's coefficient is a Coulomb coefficient
 * over a typical slip of the sphere's contact (TIPPE_LAUNCH_DEFAULT_MU_S_M: 0.3 /
 * 0.13 m/s); on a rim the slip is the spin times the rim's radius (0.7 m/s for the
 * M12 at 20 rev/s), where the linear law would ask 1.6 Rn of a dry contact. There
 * the force saturates at Coulomb's mu_c Rn: mu / sqrt(1 + (mu |V_Q| / mu_c)^2), mu
 * below the slip mu_c / mu, mu_c / |V_Q| above it. On the sphere the paper's law
 * is kept as it is. */
static double rim_viscous_mu(const dyn_ctx *c, double slip2)
{
    return c->mu / sqrt(1.0 + c->rim_mu_ratio2 * slip2);
}

/* The couple about e3 per unit Rn of the face within RIM_FACE_SIN of upright, as a
 * ring (the load on the rim, radius r, uniform): each element slips at omega_n r along the
 * rim. Coulomb (and the patch law, whose patch is then the ring): -mu_c r
 * sgn(omega_n), regularised as the sliding law; viscous: -mu r^2 omega_n,
 * saturated as on the rim (rim_viscous_mu). */
static double ring_couple(const dyn_ctx *c, double r, double omega_n)
{
    const double slip = omega_n * r;
    if (c->coulomb)
        return -c->mu_c * r * slip / sqrt(slip * slip + c->vs2);
    return -rim_viscous_mu(c, slip * slip) * r * slip;
}

/* The part of omega' = Rn a1 + a0 and of the normal force that the contact's wrench does
 * not change: the gyroscopic a0 = -((C - A)/A) n omega x k (eq 3.13 in the lab frame) and
 * the numerator of eq 3.19, m (g - (a0 x q)_z - (omega x dq/dt)_z), whose last term is
 * eps (omega x (omega x k))_z on the sphere. Apart from normal_force so that the patch law's
 * second pass at the load's radius (PATCH_LOAD_CORRECTIONS) does not compute it again. */
typedef struct {
    double a0[3];
    double Rn_num; /* N: Rn times eq 3.19's denominator */
} gyro_part;

static inline void gyroscopic(const dyn_ctx *c, const contact *o, const double wk[3], gyro_part *g)
{
    const double minus_CmA_A_n = -c->C_minus_A_over_A * o->n;
    for (int i = 0; i < 3; i++)
        g->a0[i] = minus_CmA_A_n * wk[i];
    if (c->rim) {
        /* m z'' = Rn - m g with z = -q_z: z'' = -((omega' x q)_z + (omega x dq/dt)_z) */
        double a0q[3];
        cross3(g->a0, o->q, a0q);
        g->Rn_num = c->m * (c->g - a0q[2] - o->wqd[2]);
        return;
    }
    double a0k[3], wwk[3];
    cross3(g->a0, o->k, a0k);
    cross3(o->w, wk, wwk);
    /* z'' = -eps ((omega' x k)_z + (omega x (omega x k))_z) */
    g->Rn_num = c->m * (c->g - c->eps * (a0k[2] + wwk[2]));
}

/* Rn and a1 of omega' = Rn a1 + a0 for the wrench u per unit Rn: the torque about the
 * CoM (eq 3.13 in the lab frame, with the couples), then m z'' = Rn - m g (eqs
 * 3.16-3.17) solved for Rn, the lab form of eq 3.19, with the wrench-free part g.
 * Returns nonzero where eq 3.19's denominator is not positive. */
static inline int normal_force(const dyn_ctx *c, contact *o, const gyro_part *g, const per_Rn *u,
                        double a1[3])
{
    const double *k = o->k;
    double tau[3];
    cross3(o->q, u->f, tau); /* torque per unit Rn about the CoM (eq 3.13) */
    tau[0] += u->Mroll[0];
    tau[1] += u->Mroll[1];
    tau[2] += u->M; /* the drilling couple about e3 (patch law) */
    const double tk = dot3(tau, k);
    /* A omega' = tau - (C - A)(n' k + n omega x k) with C n' = tau.k */
    const double one_minus_AC = c->one_minus_A_over_C, inv_A = c->inv_A;
    for (int i = 0; i < 3; i++)
        a1[i] = (tau[i] - one_minus_AC * tk * k[i]) * inv_A;
    /* (a1 x q)_z on a rim, eps (a1 x k)_z on the sphere */
    if (c->rim)
        o->den = 1.0 + c->m * (a1[0] * o->q[1] - a1[1] * o->q[0]);
    else
        o->den = 1.0 + c->m * c->eps * (a1[0] * k[1] - a1[1] * k[0]);
    if (!(o->den > 0.0))
        return 1;
    o->Rn = g->Rn_num / o->den;
    return 0;
}

/* The rolling constraint's right-hand side (run_try_stick's system, docs/dynamics.md,
 * "Sticking"): d/dt V_Q = 0 reads K Fc = b, with
 *   b = g e3 - a0 x q - omega x dq/dt,
 * a0 the gyroscopic part of omega' (gyroscopic) and dq/dt = eps omega x k on the sphere,
 * the rim's own rate on a rim (o->wqd). */
static void rolling_rhs(const dyn_ctx *c, const contact *o, const double wk[3],
                        const double a0[3], double b[3])
{
    double a0q[3], wq_dot[3];
    cross3(a0, o->q, a0q);
    if (c->rim) {
        memcpy(wq_dot, o->wqd, sizeof wq_dot);
    } else {
        cross3(o->w, wk, wq_dot);
        for (int i = 0; i < 3; i++)
            wq_dot[i] *= c->eps;
    }
    for (int i = 0; i < 3; i++)
        b[i] = -a0q[i] - wq_dot[i];
    b[2] += c->g;
}

/* What creep_reduce needs of the kinematics alone: the rate cap, the tangential trace of
 * the Delassus matrix K, K itself and b, the rolling constraint's right-hand side. None
 * of it depends on the patch's wrench, so patch_eval computes it before the radius
 * passes, whose divisions, square roots and cube root are one long chain of latencies:
 * the processor overlaps this work with them (issue 38, docs/performance.md, "third
 * round"). */
typedef struct {
    double k_cap, trace;
    double K[3][3], b[3];
} creep_pre;

static inline void creep_prepare(const dyn_ctx *c, const contact *o, const double wk[3],
                                 const double a0[3], creep_pre *p)
{
    /* K's tangential trace without K: K_jj = 1/m + (q x e_j).I^-1 (q x e_j), with
     * I^-1 x = (x - (1 - A/C)(x.k) k) / A, q x e_x = (0, q_z, -q_y), q x e_y = (-q_z, 0, q_x) */
    const double *q = o->q, *k = o->k;
    const double px = q[2] * k[1] - q[1] * k[2], py = q[0] * k[2] - q[2] * k[0];
    p->trace = 2.0 / c->m + (q[0] * q[0] + q[1] * q[1] + 2.0 * q[2] * q[2] -
                             c->one_minus_A_over_C * (px * px + py * py)) * c->inv_A;
    p->k_cap = c->creep_cap * (sqrt(dot3(o->w, o->w)) + c->sqrt_g_over_R);
    compliance(c, o->k, o->q, p->K);
    rolling_rhs(c, o, wk, a0, p->b);
}

/* The patch law with its creep reduced (docs/dynamics.md, "The creep reduced"; issue 38).
 * Where the patch drills slowly the creep drag mu_c c1 / (a |omega_n|) relaxes the slip
 * at a rate k far above the motion's (2e4 /s on the M12 at 1 rad/s), and an explicit
 * stepper must crawl at 1/k. The slip is then a fast variable slaved to the slow state
 * (Tikhonov's theorem): it sits where the patch's force equals the force that would keep
 * the contact point at rest, F_p(v*) = F_s, up to a lag of order (d/dt v*) / k. So where k
 * exceeds k_cap = creep_cap (|omega| + sqrt(g/R)) the contact force is the blend
 *   Fc = (1 - s) Fc_s + s Fc_p,   s = k_cap / k,
 * of the rolling constraint's Fc_s (with the patch's couples at this state) and the full
 * law's Fc_p. Both satisfy the normal constraint and give the contact point the
 * accelerations 0 and a_p, so the blend gives it s a_p: the slip relaxes to the same
 * slaved value v* at the rate s k = k_cap instead of k. The force on the body is the
 * full law's to first order in the lag (its lag term (C/k) d/dt v* does not depend on s);
 * the slip itself lags by (d/dt v*) / k_cap, so the creep's power is off by a relative
 * O((|omega| + sqrt(g/R)) / k_cap) = O(1/creep_cap). Where k <= k_cap (sliding, a fast
 * drilling patch) s = 1: the full law, unchanged. k is bounded above by the trace of
 * the Delassus matrix's tangential block (>= its largest eigenvalue, and >= that of its
 * Schur complement under the normal constraint) times the law's drag |F| / |V_Q| (the
 * secant, which for this law is the largest slope of F in V_Q: docs/contact-patch.md).
 * p: creep_prepare's part, at the same state. */
static void creep_reduce(const dyn_ctx *c, contact *o, const double a0[3], const per_Rn *u,
                         const creep_pre *p)
{
    o->creep_slow = 1.0;
    o->creep_power = 0.0;
    /* squares, not hypot (a tenth of an evaluation's cost): a slip under 1e-154 m/s
     * squares to 0 and takes the bound's value at rest; a force that underflows gives
     * drag 0, the full law, which is never wrong */
    const double slip2 = o->VQ[0] * o->VQ[0] + o->VQ[1] * o->VQ[1];
    const double f2 = u->f[0] * u->f[0] + u->f[1] * u->f[1];
    const double drag = slip2 > 0.0 ? sqrt(f2 / slip2) : c->mu_c / c->vs;
    const double k_rate = o->Rn * drag * p->trace;
    const double k_cap = p->k_cap;
    if (!(k_rate > k_cap))
        return;
    const double s = k_cap / k_rate;
    /* The rolling constraint with the couples per unit Rn tc:
     *   K Fc + Rn (I^-1 tc) x q = b   (rolling_rhs) */
    const double tc[3] = {u->Mroll[0], u->Mroll[1], u->M};
    double K[3][3], wc[3], cq[3], Fs[3], tau[3], wt[3];
    memcpy(K, p->K, sizeof K);
    inv_inertia(c, o->k, tc, wc);
    cross3(wc, o->q, cq);
    for (int i = 0; i < 3; i++)
        K[i][2] += cq[i];
    if (solve3(K, p->b, Fs) || !(Fs[2] > 0.0))
        return; /* no rolling solution here: the full law */
    cross3(o->q, Fs, tau);
    for (int i = 0; i < 3; i++)
        tau[i] += Fs[2] * tc[i];
    inv_inertia(c, o->k, tau, wt);
    const double Rn = (1.0 - s) * Fs[2] + s * o->Rn;
    double dF[2];
    for (int i = 0; i < 2; i++) {
        const double F = (1.0 - s) * Fs[i] + s * o->F[i];
        dF[i] = F - Rn * u->f[i]; /* what the reduction adds to the law's force at Rn */
        o->F[i] = F;
    }
    for (int i = 0; i < 3; i++)
        o->wdot[i] = (1.0 - s) * (wt[i] + a0[i]) + s * o->wdot[i];
    o->Rn = Rn;
    o->M = Rn * u->M;
    const double dP = dF[0] * o->VQ[0] + dF[1] * o->VQ[1];
    o->power = Rn * u->diss - dP;
    o->creep_slow = s;
    o->creep_power = fabs(dP);
}

/* The patch law's part of tippe_dynamics_contact_eval (o's kinematics set): the wrench per
 * unit Rn at radius a is linear in Rn, so Rn follows from eq 3.19 as for the other laws; a
 * radius that follows the load (Hertz) is corrected from the static one with the Rn it
 * gives (PATCH_LOAD_CORRECTIONS); then the creep's reduction where it applies. The
 * gyroscopic part is the same in every pass and is computed once. */
static int patch_eval(const dyn_ctx *c, contact *o, const double wk[3])
{
    const double *w = o->w;
    const double ring_M = o->ring ? ring_couple(c, c->rim_r[c->rim - 1], w[2]) : 0.0;
    per_Rn u = {{0.0, 0.0, 1.0}, ring_M, 0.0, {0.0, 0.0}};
    gyro_part g;
    double a1[3];
    double a = c->patch_a;
    gyroscopic(c, o, wk, &g);
    creep_pre pre;
    if (c->creep_cap > 0.0)
        creep_prepare(c, o, wk, g.a0, &pre);
    for (int pass = 0;; pass++) {
        patch_wrench(c, o, a, &u);
        if (o->ring) {
            /* the ring's couple, not a patch's: the ring is the patch (its power
             * -(F.V_Q + M omega_n) per unit Rn rebooked with the ring's M) */
            u.diss += (u.M - ring_M) * w[2];
            u.M = ring_M;
        }
        if (normal_force(c, o, &g, &u, a1))
            return 1;
        if (!c->patch_follow || pass == PATCH_LOAD_CORRECTIONS)
            break;
        /* Hertz: a grows as the cube root of the load (Johnson 1985, eq 4.22); no
         * load, no patch */
        a = c->patch_a * cbrt(o->Rn > 0.0 ? o->Rn * c->inv_mg : 0.0);
    }
    o->patch_a = a;
    o->mu_eff = NAN; /* not a viscous multiple of V_Q */
    for (int i = 0; i < 3; i++)
        o->wdot[i] = o->Rn * a1[i] + g.a0[i];
    o->F[0] = o->Rn * u.f[0];
    o->F[1] = o->Rn * u.f[1];
    o->M = o->Rn * u.M;
    o->power = o->Rn * u.diss; /* -(F.V_Q + M omega_n + M_roll.w_roll) >= 0 */
    o->creep_slow = 1.0;
    o->creep_power = 0.0;
    if (c->creep_cap > 0.0)
        creep_reduce(c, o, g.a0, &u, &pre);
    return 0;
}

/* Everything the right-hand side needs from a state: the contact velocity, the
 * normal force in closed form, the angular acceleration. The axis is
 * normalised here, so |k| drifting at the integrator's tolerance never enters
 * the physics. Returns nonzero where the contact force is undetermined. */
int tippe_dynamics_contact_eval(const dyn_ctx *c, const double *y, contact *o)
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
    o->ring = 0;
    o->creep_slow = 1.0; /* the full law unless creep_reduce slows it */
    o->creep_power = 0.0;
    double wq[3];
    if (c->rim) {
        rim_geometry(c, o, wk);
        cross3(w, o->q, wq);
        o->v[2] = -wq[2]; /* the constraint: the contact point does not leave the table */
    } else {
        /* q = CoM -> contact = eps k - R e3 (eq 3.6) */
        o->q[0] = c->eps * k[0];
        o->q[1] = c->eps * k[1];
        o->q[2] = c->eps * k[2] - c->R;
        /* The CoM height is R - eps k_z (eq 3.10), so its vertical velocity is
         * -eps (omega x k)_z (eq 3.11). */
        o->v[2] = -c->eps * wk[2];
        cross3(w, o->q, wq);
    }
    o->v[0] = y[IV];
    o->v[1] = y[IV + 1];
    o->VQ[0] = o->v[0] + wq[0]; /* eq 3.7 */
    o->VQ[1] = o->v[1] + wq[1];
    o->VQ[2] = 0.0; /* vanishes identically by the constraint (eq 3.11) */
    if (c->stick) {
        /* Rolling without slipping: the contact force Fc = (F, Rn) keeps the contact
         * point at rest, d/dt V_Q = 0 with q' = eps omega x k:
         *   Fc/m - g e3 + (I^-1 (q x Fc) + a0) x q + eps omega x (omega x k) = 0,
         * i.e. K Fc = g e3 - a0 x q - eps omega x (omega x k), a0 the gyroscopic
         * part of omega'. Its z row is eq 3.17; K is positive definite, so Fc is
         * always determined (no Painleve case while rolling). */
        double b[3], Fc[3], tau[3], wt[3];
        gyro_part g;
        gyroscopic(c, o, wk, &g);
        const double *a0 = g.a0;
        rolling_rhs(c, o, wk, a0, b);
        compliance(c, k, o->q, o->K);
        if (solve3(o->K, b, Fc))
            return 1;
        cross3(o->q, Fc, tau);
        tippe_dynamics_inv_inertia(c, k, tau, wt);
        for (int i = 0; i < 3; i++)
            o->wdot[i] = wt[i] + a0[i];
        o->Rn = Fc[2];
        o->F[0] = Fc[0];
        o->F[1] = Fc[1];
        o->den = 1.0;
        o->mu_eff = 0.0;
        o->M = 0.0;
        o->patch_a = 0.0;
        /* exact rolling dissipates nothing: any change of E while rolling is
         * integration error, and shows in the energy balance |E + D - E0| */
        o->power = 0.0;
        return 0;
    }
    if (c->patch)
        return patch_eval(c, o, wk);
    const double slip2 = o->VQ[0] * o->VQ[0] + o->VQ[1] * o->VQ[1];
    /* Both laws are F = -mu_eff Rn V_Q with mu_eff fixed by the state alone (V_Q does
     * not depend on Rn): viscous mu (eq 3.12), or regularised Coulomb
     * mu_c / sqrt(|V_Q|^2 + v_s^2), so |F| -> mu_c Rn for |V_Q| >> v_s. */
    o->mu_eff = c->coulomb ? c->mu_c / sqrt(slip2 + c->vs2)
                : c->rim   ? rim_viscous_mu(c, slip2)
                           : c->mu;
    /* F = Rn (e3 - mu_eff V_Q): force and torque are linear in Rn. */
    const double ring_M = o->ring ? ring_couple(c, c->rim_r[c->rim - 1], w[2]) : 0.0;
    per_Rn u = {{-o->mu_eff * o->VQ[0], -o->mu_eff * o->VQ[1], 1.0}, ring_M, 0.0, {0.0, 0.0}};
    gyro_part g;
    double a1[3];
    gyroscopic(c, o, wk, &g);
    if (normal_force(c, o, &g, &u, a1))
        return 1;
    o->patch_a = c->patch_a;
    for (int i = 0; i < 3; i++)
        o->wdot[i] = o->Rn * a1[i] + g.a0[i];
    o->M = 0.0;
    o->F[0] = -o->mu_eff * o->Rn * o->VQ[0];
    o->F[1] = -o->mu_eff * o->Rn * o->VQ[1];
    o->power = o->mu_eff * o->Rn * slip2; /* eq 4.1; Coulomb: mu_c Rn |V_Q| for |V_Q| >> v_s */
    if (o->ring) {
        o->M = o->Rn * ring_M;
        o->power -= o->M * w[2];
    }
    return 0;
}

int tippe_dynamics_rhs(double t, const double y[], double f[], void *params)
{
    (void)t;
    dyn_ctx *c = params;
    c->nevals++;
    contact o;
    if (tippe_dynamics_contact_eval(c, y, &o)) {
        /* Not GSL_EBADFUNC: a trial stage of a too-long step can leave the
         * region where eq 3.19 is defined, and GSL then retries with a shorter
         * step. Only if the step shrinks to nothing is the model at fault. */
        c->bad_contact = 1;
        return GSL_EDOM;
    }
    if (o.Rn < c->min_stage_Rn)
        c->min_stage_Rn = o.Rn;
    if (c->has_rims) {
        const double st = rim_stay(c, o.k);
        if (st < c->min_stage_rim)
            c->min_stage_rim = st;
    }
    if (c->stick) {
        const double g = c->mu_c * o.Rn - hypot(o.F[0], o.F[1]);
        if (g < c->min_stage_stick)
            c->min_stage_stick = g;
    }
    /* dk/dt = omega x k with the unnormalised k: the exact flow keeps |k|. */
    cross3(o.w, y + IK, f + IK);
    for (int i = 0; i < 3; i++)
        f[IW + i] = o.wdot[i];
    f[IV] = o.F[0] / c->m; /* eq 3.14 horizontal */
    f[IV + 1] = o.F[1] / c->m;
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
int tippe_dynamics_jacobian(double t, const double y[], double *dfdy, double dfdt[], void *params)
{
    dyn_ctx *c = params;
    const size_t d = c->dim;
    double f0[DIM_TRAJECTORY], f1[DIM_TRAJECTORY], yp[DIM_TRAJECTORY];
    int s = tippe_dynamics_rhs(t, y, f0, c);
    if (s != GSL_SUCCESS)
        return s;
    memcpy(yp, y, d * sizeof *y);
    for (size_t j = 0; j < d; j++) {
        const double save = yp[j];
        double hj = sqrt(DBL_EPSILON) * fmax(fabs(save), c->scale[j]);
        yp[j] = save + hj;
        hj = yp[j] - save; /* the step actually representable */
        s = tippe_dynamics_rhs(t, yp, f1, c);
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

double tippe_dynamics_energy(const dyn_ctx *c, const contact *o)
{
    double L[3];
    for (int i = 0; i < 3; i++)
        L[i] = c->A * o->w[i] + (c->C - c->A) * o->n * o->k[i];
    /* sec 4: translational + rotational kinetic energy + m g h (eq 3.10) */
    if (c->rim) /* the centre of mass -q_z above the table: the hull's support */
        return 0.5 * c->m * dot3(o->v, o->v) + 0.5 * dot3(o->w, L) - c->m * c->g * o->q[2];
    return 0.5 * c->m * dot3(o->v, o->v) + 0.5 * dot3(o->w, L) +
           c->m * c->g * (c->R - c->eps * o->k[2]);
}

double tippe_dynamics_jellett(const dyn_ctx *c, const contact *o)
{
    double L[3];
    for (int i = 0; i < 3; i++)
        L[i] = c->A * o->w[i] + (c->C - c->A) * o->n * o->k[i];
    return -dot3(L, o->q); /* eq 3.20 */
}

/* The paper's variables (eq 3.4) from the regular state: e1 is the horizontal
 * direction of k (the lab x axis when k is vertical), i = cos(theta) e1 -
 * sin(theta) e3, omega = -phi_dot sin(theta) i + theta_dot e2 + n k. */
void tippe_dynamics_paper_variables(const dyn_ctx *c, double t, const double *y, const contact *o,
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
    s->patch_radius = c->patch ? o->patch_a : 0.0;
    s->drill_torque = o->M;
    s->rim = c->rim;
    s->E = tippe_dynamics_energy(c, o);
    s->D = y[ID];
    s->J = tippe_dynamics_jellett(c, o);
}

static double unwrap(double raw, double prev)
{
    return raw + 2.0 * M_PI * round((prev - raw) / (2.0 * M_PI));
}

/* Euler angles (phi, theta, psi), rotation Rz(phi) Ry(theta) Rz(psi), from the
 * orientation quaternion, continued from the previous values; on the vertical
 * only phi + psi (theta = 0) or phi - psi (theta = pi) is defined, and phi keeps
 * its previous value. */
void tippe_dynamics_euler_angles(const double *p, double *phi, double *psi)
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
