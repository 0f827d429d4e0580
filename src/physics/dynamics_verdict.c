/* The proved verdict: energy trapping in a well of the effective potential and a
 * contact bound over the trapped set (docs/dynamics.md, "Proved verdicts").
 *
 * With friction (viscous mu > 0, or Coulomb mu_c > 0: both are F = -mu_eff Rn V_Q with
 * mu_eff > 0) and contact, E never increases (eq 4.1) and J is conserved (eq 3.21);
 * E >= V(theta; J) (tippe/theory.h). So if E + margin is below every other critical
 * value of V in the current well, theta stays in the well and the only steady state
 * the motion can approach is the well's minimum (the states where dissipation stops
 * are the steady states of section 5, the critical points of V). That needs contact
 * for ever: a lower bound of Rn over the trapped set does it. */
#include "physics/dynamics_verdict.h"

#include <math.h>
#include <string.h>

int tippe_dynamics_verdict_init(tippe_dynamics_verdict_ctx *v, const tippe_dynamics_model *model, double J, tippe_error *err)
{
    memset(v, 0, sizeof *v);
    v->top = model->top;
    v->g = model->g;
    v->mu = model->mu;
    v->coulomb = model->law != TIPPE_FRICTION_VISCOUS;
    v->mu_c = model->mu_c;
    v->vs = model->slip_scale_m_s > 0.0 ? model->slip_scale_m_s : TIPPE_COULOMB_SLIP_SCALE_M_S;
    v->dissipative = !tippe_dynamics_frictionless(model);
    v->stick = model->law == TIPPE_FRICTION_COULOMB;
    v->J = J;
    int rc = tippe_theory_find_wells(&v->top, v->g, J, &v->wells, err);
    if (rc)
        return rc;
    /* dD/dtheta = 2 R sin (((A - C) R cos + C eps): D's extremes are at the poles
     * and at cos theta = C eps / ((C - A) R) when that lies in [-1, 1]. */
    const tippe_top *t = &v->top;
    const double Dp0 = t->C * (t->R - t->eps) * (t->R - t->eps);
    const double Dpi = t->C * (t->R + t->eps) * (t->R + t->eps);
    v->D_min = fmin(Dp0, Dpi);
    if (t->C != t->A) {
        const double x = t->C * t->eps / ((t->C - t->A) * t->R);
        if (x > -1.0 && x < 1.0) {
            const double z = t->R * x - t->eps;
            v->D_min = fmin(v->D_min, t->A * t->R * t->R * (1.0 - x * x) + t->C * z * z);
        }
    }
    return TIPPE_OK;
}

double tippe_dynamics_verdict_margin(const tippe_dynamics_verdict_ctx *v, double factor, double energy_err_J, double J_err,
                      double E0)
{
    /* dV/dJ = J / D <= |J| / D_min */
    return factor * (energy_err_J + fabs(v->J) * J_err / v->D_min) + 1e-12 * E0;
}

/* The least V over the critical points of well i other than its minimum that the
 * motion can end at: interior maxima and degenerate points. A pole that is a strict
 * maximum of V is an unstable steady state (Theorem 5.1): a motion that dissipates
 * (eq 4.1) ends there only from that state's stable manifold, a set of launches of
 * measure zero, so it is not a barrier, except when the state is exactly that steady
 * state (at the pole, no tilt rate, no slip: E never falls and it stays for ever). */
static double well_barrier(const tippe_dynamics_verdict_ctx *v, int i, double rest_pole_rad)
{
    const tippe_theory_wells *w = &v->wells;
    const tippe_theory_well *wl = &w->well[i];
    double b = INFINITY;
    for (int c = 0; c < w->n_crit; c++) {
        const double th = w->crit_theta_rad[c];
        if (th < wl->theta_lo_rad || th > wl->theta_hi_rad || th == wl->theta_min_rad)
            continue;
        const int pole = th == 0.0 || th == M_PI;
        if (pole && w->crit_kind[c] == 1 && !w->crit_degenerate[c] && th != rest_pole_rad)
            continue;
        if (w->crit_V[c] < b)
            b = w->crit_V[c];
    }
    return b;
}

void tippe_dynamics_verdict_energy_test(const tippe_dynamics_verdict_ctx *v, double theta, double E, double margin,
                         double rest_pole_rad, tippe_dynamics_verdict_trap *out)
{
    out->well = tippe_theory_well_index(&v->wells, theta);
    const tippe_theory_well *wl = &v->wells.well[out->well];
    out->barrier = well_barrier(v, out->well, rest_pole_rad);
    out->gap = out->barrier - E;
    out->confined = E + margin < wl->V_escape;
    out->trapped = out->confined && !wl->flat && E + margin < out->barrier;
    out->unresolvable = out->confined && (wl->flat || !(out->barrier - wl->V_min > margin));
    out->lo = out->hi = wl->theta_min_rad;
}

void tippe_dynamics_verdict_trap_range(const tippe_dynamics_verdict_ctx *v, double E, double margin, tippe_dynamics_verdict_trap *tr)
{
    tippe_theory_well_range(&v->top, v->g, &v->wells, tr->well, E + margin, &tr->lo, &tr->hi);
}

/* The bound at one theta. Rn = m N / den (eq 3.19) with
 *   N = g + eps theta_dot^2 cos + eps (A cos a^2 - C sin a n) / A,  a = phi_dot sin,
 *   den = 1 + m eps sin (eps sin - mu h V_QX) / A,  h = R - eps cos,
 * where the state has kinetic energy above its minimum J^2 / 2D of at most
 * dK = E_max - V(theta): (a, n) lies on the Jellett line within energy distance dK
 * of its minimiser, and theta_dot, U (hence V_QX = U - h theta_dot) within dK. */
static double bound_at(const tippe_dynamics_verdict_ctx *v, double theta, double E_max)
{
    const tippe_top *t = &v->top;
    const double x = cos(theta), s = sin(theta), m = t->m, eps = t->eps;
    const double dK = fmax(0.0, E_max - tippe_theory_potential(t, v->g, v->J, theta));
    const double z = t->R * x - eps;
    const double D = t->A * t->R * t->R * s * s + t->C * z * z;
    /* minimiser on the line A R s a + C z n = J, and the line's direction */
    const double a0 = v->J * t->R * s / D, n0 = v->J * z / D;
    const double da = t->C * z, dn = -t->A * t->R * s;
    const double t_max = sqrt(2.0 * dK / (t->A * da * da + t->C * dn * dn));
    /* q(a, n) = eps cos a^2 - (eps C / A) sin a n along the line: q2 u^2 + q1 u + q0 */
    const double cq = eps * x, cx = -eps * t->C / t->A * s;
    const double q2 = cq * da * da + cx * da * dn;
    const double q1 = 2.0 * cq * a0 * da + cx * (a0 * dn + n0 * da);
    const double q0 = cq * a0 * a0 + cx * a0 * n0;
    double q_min = fmin(q2 * t_max * t_max + q1 * t_max, q2 * t_max * t_max - q1 * t_max);
    if (q2 > 0.0 && fabs(q1 / (2.0 * q2)) < t_max)
        q_min = fmin(q_min, -q1 * q1 / (4.0 * q2));
    q_min += q0;
    const double Ieff = t->A + m * eps * eps * s * s; /* theta_dot's inertia, eq 3.11 */
    const double thd2_max = 2.0 * dK / Ieff;
    const double N = v->g + fmin(0.0, eps * x) * thd2_max + q_min;
    const double h = t->R - eps * x;
    const double VQX_max = sqrt(2.0 * dK * (1.0 / m + h * h / Ieff)); /* Cauchy-Schwarz */
    const double base = 1.0 + m * eps * eps * s * s / t->A;
    /* |F_X| / Rn: viscous mu |V_QX|; sliding Coulomb mu_c |V_QX| / sqrt(|V_Q|^2 + v_s^2)
     * <= mu_c x / sqrt(x^2 + v_s^2) at x = VQX_max (increasing in x); rolling, any
     * force in the cone, so mu_c. Eq 3.19's denominator holds for any friction force
     * (only F_X enters the torque about e2). */
    double mu_VQX = v->mu * VQX_max;
    if (v->stick)
        mu_VQX = v->mu_c;
    else if (v->coulomb)
        mu_VQX = v->mu_c * VQX_max / sqrt(VQX_max * VQX_max + v->vs * v->vs);
    const double fr = m * eps * s * h * mu_VQX / t->A;
    if (!(N > 0.0) || !(base - fr > 0.0))
        return -INFINITY;
    return m * N / (base + fr);
}

double tippe_dynamics_verdict_contact_bound(const tippe_dynamics_verdict_ctx *v, double E_max, double lo, double hi)
{
    double b = INFINITY;
    for (int i = 0; i < TIPPE_DYNAMICS_VERDICT_CONTACT_NODES; i++) {
        const double th = lo + (hi - lo) * i / (TIPPE_DYNAMICS_VERDICT_CONTACT_NODES - 1);
        const double r = bound_at(v, th, E_max);
        if (r < b)
            b = r;
    }
    return b;
}
