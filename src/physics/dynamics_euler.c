/* The paper's Euler-angle equations of motion, kept as an independent reference
 * for the regular lab-frame form in dynamics.c (docs/dynamics.md derives both).
 * Singular where sin(theta) = 0: the precession equation divides by it. */
#include "tippe/physics.h"

#include <math.h>

int tippe_dynamics_euler_rhs(const tippe_dynamics_model *model, const double y[TIPPE_EULER_DIM],
                             double dydt[TIPPE_EULER_DIM], double *Rn_out)
{
    const double m = model->top.m, R = model->top.R, eps = model->top.eps;
    const double A = model->top.A, C = model->top.C, g = model->g;
    const double theta = y[0], beta = y[1], alpha = y[2], n = y[3], U = y[4], V = y[5];
    const double s = sin(theta), c = cos(theta);
    if (s == 0.0)
        return TIPPE_ECOMPUTE;

    const double h = R - eps * c;   /* eq 3.10: height of the centre of mass */
    const double zQ = eps - R * c;  /* eq 3.6: contact point, body frame z */
    const double xQ = R * s;        /* eq 3.6: contact point, body frame x */
    /* eq 3.9: contact-point velocity in the frame (e1, e2, e3) */
    const double VQx = U - beta * h;
    const double VQy = V + s * (alpha * eps + R * (n - alpha * c));
    /* Coulomb while sliding: F = -mu_c Rn V_Q / sqrt(|V_Q|^2 + v_s^2), i.e. eq 3.12
     * with a coefficient fixed by the slip alone, so Rn stays linear (eq 3.19). */
    const double vs = model->slip_scale_m_s > 0.0 ? model->slip_scale_m_s
                                                  : TIPPE_COULOMB_SLIP_SCALE_M_S;
    const double mu = model->law != TIPPE_FRICTION_VISCOUS
                          ? model->mu_c / sqrt(VQx * VQx + VQy * VQy + vs * vs)
                          : model->mu;

    /* eq 3.15 (second) without the normal force: the gyroscopic term. */
    const double P = -alpha * s * (C * n - A * alpha * c);
    /* theta_ddot = (P + Rn * Q1) / A: the torque of Rn e3 + Rf about the
     * centre of mass in the e2 direction, per unit Rn (Z_Q F_X - X_Q Rn). */
    const double Q1 = mu * VQx * h - eps * s;
    /* eq 3.17 with theta_ddot substituted, solved for Rn (eq 3.19, any m). */
    const double den = 1.0 - m * eps * s * Q1 / A;
    if (!(den > 0.0))
        return TIPPE_ECOMPUTE;
    const double Rn = m * (g + eps * beta * beta * c + eps * s * P / A) / den;
    const double FX = -mu * Rn * VQx, FY = -mu * Rn * VQy; /* eq 3.12 */

    dydt[0] = beta;
    dydt[1] = (P + Rn * Q1) / A;                                  /* eq 3.15 */
    dydt[2] = (beta * (C * n - 2.0 * A * alpha * c) + zQ * FY) / (A * s); /* eq 3.15 */
    dydt[3] = xQ * FY / C;                                        /* eq 3.15 */
    dydt[4] = alpha * V + FX / m;                                 /* eq 3.16 */
    dydt[5] = -alpha * U + FY / m;                                /* eq 3.16 */
    dydt[6] = alpha;                                              /* eq 3.18 */
    dydt[7] = n - alpha * c;                                      /* eq 3.18 */
    if (Rn_out)
        *Rn_out = Rn;
    return TIPPE_OK;
}
