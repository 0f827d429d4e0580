/* physics/contact_patch_law.h: the patch law's cheap form (docs/contact-patch.md), shared
 * by contact_patch.c (the public tippe_contact_patch_friction) and the right-hand side in
 * dynamics_equations.c, which inlines it with the Hertz coefficients as constants: the law is
 * a fifth of a patch-law evaluation's cost, and a call through the public function could not
 * be inlined across files (issue 38, docs/performance.md, "third round"). */
#ifndef TIPPE_PHYSICS_CONTACT_PATCH_LAW_H
#define TIPPE_PHYSICS_CONTACT_PATCH_LAW_H

#include <math.h>

#include "tippe/physics.h"

#ifndef PI
#define PI 3.14159265358979323846
#endif

/* The cheap form is a dissipation potential Phi(v, omega_n) = mu N sqrt(S), with
 * S(V, W) = Ph(V, W) / Qh(V, W), V = |v|^2, W = (a omega_n)^2, Ph and Qh homogeneous
 * of degrees 5 and 4 (so S is a squared speed), F = -dPhi/dv, M = -dPhi/domega_n
 * (docs/contact-patch.md, "The cheap form"). Normalised, S(eps^2, 1) = psi(eps)^2 with
 * f = psi', m = psi - eps psi', and psi^2 = P(E)/Q(E), E = eps^2:
 * P = E^5 + p4 E^4 + ... + p0, Q = E^4 + q3 E^3 + ... + q0. Six coefficients are free
 * (q0..q3, p2, p3), fitted (minimax relative error of f and m on eps in [1e-3, 1e3], 640 points, dense
 * over [0.1, 10] where the error peaks)
 * against tippe_contact_patch_reference; the others follow from the exact limits:
 * p0 = m0^2 q0 (m -> m0), p1 = m0 c1 q0 + m0^2 q1 (f ~ c1 eps), p4 = c2 + q3 (m ~ c2/eps),
 * p5 = q4 = 1 (f -> 1). All are positive, so Ph, Qh > 0 away from the origin. */
typedef struct {
    const char *name;
    double m0, c1, c2;
    double p[6], q[5];
    /* d/dx of Ph(x, 1 - x) and Qh(x, 1 - x), homogeneous of degrees 4 and 3:
     * dp[j] = (j + 1) p[j+1] - (5 - j) p[j], dq[j] = (j + 1) q[j+1] - (4 - j) q[j]. */
    double dp[5], dq[4];
} patch_law;

#define M0_U (2.0 / 3.0)       /* uniform: m0 = int r dA / (pi a^3) = 2/3 */
#define C1_U 1.0               /* uniform: c1 = pi int_0^1 p dr = 1 */
#define C2_U 0.25              /* uniform: c2 = (1/2) int p r^2 dA = 1/4 */
#define M0_H (3.0 * PI / 16.0) /* Hertz: m0 = 3 int_0^1 r^2 sqrt(1 - r^2) dr = 3 pi/16 */
#define C1_H (3.0 * PI / 8.0)  /* Hertz: c1 = (3/2) int_0^1 sqrt(1 - r^2) dr = 3 pi/8 */
#define C2_H 0.2               /* Hertz: c2 = (3/2) int_0^1 r^3 sqrt(1 - r^2) dr = 1/5 */
/* The fitted coefficients (q0..q3, p2, p3) of each law. */
#define QU0 0.407634999900462
#define QU1 0.161335913220097
#define QU2 0.186104511033113
#define QU3 7.47241633991972e-05
#define PU2 0.272586567225555
#define PU3 0.200787103723107
#define QH0 0.22819823409715
#define QH1 0.193302620984183
#define QH2 0.21632710067164
#define QH3 8.35991797517446e-05
#define PH2 0.264803946277881
#define PH3 0.228436712575513
/* The rest, from the limits. */
#define PU0 (M0_U * M0_U * QU0)
#define PU1 (M0_U * C1_U * QU0 + M0_U * M0_U * QU1)
#define PU4 (C2_U + QU3)
#define PH0 (M0_H * M0_H * QH0)
#define PH1 (M0_H * C1_H * QH0 + M0_H * M0_H * QH1)
#define PH4 (C2_H + QH3)
#define DP(p0, p1, p2, p3, p4)                                                                \
    {(p1) - 5.0 * (p0), 2.0 * (p2) - 4.0 * (p1), 3.0 * (p3) - 3.0 * (p2),                      \
     4.0 * (p4) - 2.0 * (p3), 5.0 - (p4)}
#define DQ(q0, q1, q2, q3)                                                                    \
    {(q1) - 4.0 * (q0), 2.0 * (q2) - 3.0 * (q1), 3.0 * (q3) - 2.0 * (q2), 4.0 - (q3)}

static const patch_law tippe_patch_laws[2] = {
    {"uniform", M0_U, C1_U, C2_U, {PU0, PU1, PU2, PU3, PU4, 1.0}, {QU0, QU1, QU2, QU3, 1.0},
     DP(PU0, PU1, PU2, PU3, PU4), DQ(QU0, QU1, QU2, QU3)},
    {"hertz", M0_H, C1_H, C2_H, {PH0, PH1, PH2, PH3, PH4, 1.0}, {QH0, QH1, QH2, QH3, 1.0},
     DP(PH0, PH1, PH2, PH3, PH4), DQ(QH0, QH1, QH2, QH3)},
};

/* The Hertz law's entry, for callers that know their pressure at compile time. */
#define PATCH_LAW_HERTZ (&tippe_patch_laws[1])

/* S/T, dS/dV and dS/dW at V = x T, W = y T with x + y = 1 (S is homogeneous of degree 1
 * in (V, W), so its derivatives are of degree 0: evaluated at (x, y) they are those at
 * (V, W); x, y in [0, 1] keep every power in range). With s(x) = S(x, 1 - x)/T and
 * s' = ds/dx = S_V - S_W, Euler's x S_V + y S_W = s gives S_V = s + y s', S_W = s - x s'.
 * The polynomials go by Horner's rule in homogeneous form, so that x = 1 (a point
 * contact) gives s = S_V = 1 exactly. */
static inline void patch_potential(const patch_law *L, double x, double y, double *s, double *sV,
                             double *sW)
{
    const double y2 = y * y, y3 = y2 * y, y4 = y2 * y2, y5 = y4 * y;
    const double *p = L->p, *q = L->q, *dp = L->dp, *dq = L->dq;
    const double P = ((((p[5] * x + p[4] * y) * x + p[3] * y2) * x + p[2] * y3) * x +
                      p[1] * y4) * x + p[0] * y5;
    const double Q = (((q[4] * x + q[3] * y) * x + q[2] * y2) * x + q[1] * y3) * x + q[0] * y4;
    const double DPx = (((dp[4] * x + dp[3] * y) * x + dp[2] * y2) * x + dp[1] * y3) * x +
                       dp[0] * y4;
    const double DQx = ((dq[3] * x + dq[2] * y) * x + dq[1] * y2) * x + dq[0] * y3;
    const double iQ = 1.0 / Q;
    const double sv = P * iQ, sp = (DPx - sv * DQx) * iQ;
    *s = sv;
    *sV = sv + y * sp;
    *sW = sv - x * sp;
}

/* The cheap form's force F and drilling couple M for the slip v of the patch's centre and
 * the spin omega_n about the normal, at radius a (tippe_contact_patch_friction, whose
 * header comment says more). */
static inline void patch_friction(const patch_law *L, double mu_N, double a, double v_s,
                                  const double v[2], double omega_n,
                                  tippe_contact_patch_wrench *out)
{
    const double V = v[0] * v[0] + v[1] * v[1];
    const double w = a * omega_n; /* the patch rim's drilling speed */
    const double W = w * w;
    const double T = V + W;
    if (T == 0.0) { /* v = 0 and a omega_n = 0: the sticking point (a NaN input propagates) */
        out->F[0] = out->F[1] = out->M = out->dissipation = 0.0;
        return;
    }
    double s, sV, sW;
    const double iT = 1.0 / T;
    patch_potential(L, V * iT, W * iT, &s, &sV, &sW);
    const double S = T * s;
    /* Phi = mu N sqrt(S + v_s^2): F = -dPhi/dv = -mu N S_V v / sqrt(S + v_s^2),
     * M = -dPhi/domega_n = -mu N S_W a^2 omega_n / sqrt(S + v_s^2) (Leine and Glocker
     * 2003: Coulomb-Contensou friction derives from a velocity pseudo-potential). */
    const double k = mu_N / sqrt(S + v_s * v_s);
    out->F[0] = -k * sV * v[0];
    out->F[1] = -k * sV * v[1];
    out->M = -k * sW * a * w;
    /* -(F.v + M omega_n) = k (V S_V + W S_W) = k S (Euler: S is of degree 1). */
    out->dissipation = k * S;
}


#endif
