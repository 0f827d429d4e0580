/* The outline's contact and the events of a run (issue 35 and before): the rims a
 * run's context carries, the height of the centre of mass on the hull, and the
 * crossings located inside an accepted step (lift-off, the end of sticking, a switch
 * between sphere and rim). Split from dynamics.c along its banners. */
#include "physics/dynamics_state.h"
#include "tippe/base.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <string.h>

/* The outline the table meets (issue 35): the sphere cut flat at the open poles.
 * The viscous law's saturation on a rim is the model's Coulomb coefficient, or the
 * tabletop's default where the model gives none (rim_viscous_mu). */
void tippe_dynamics_set_rims(dyn_ctx *c, const tippe_dynamics_model *model,
                              const tippe_dynamics_options *opt)
{
    if (opt->sphere_contact_only)
        return;
    for (int p = 0; p < 2; p++) {
        const double a = model->top.rim_half_angle_rad[p];
        if (!(a > 0.0))
            continue;
        c->has_rims = 1;
        c->rim_alpha[p] = a;
        c->rim_cos[p] = cos(a);
        c->rim_Rcos[p] = c->R * cos(a);
        c->rim_r[p] = c->R * sin(a);
        c->rim_face_sin[p] = fmin(RIM_FACE_SIN, 0.5 * sin(a));
        c->rim_rho[p] = c->rim_r[p] / c->rim_face_sin[p];
        c->rim_D[p] = c->rim_Rcos[p] - sqrt((c->rim_rho[p] - c->rim_r[p]) *
                                            (c->rim_rho[p] + c->rim_r[p]));
    }
    c->rim_mu_c = model->mu_c > 0.0 ? model->mu_c : TIPPE_LAUNCH_DEFAULT_MU_C;
    c->rim_mu_ratio2 = (model->mu / c->rim_mu_c) * (model->mu / c->rim_mu_c);
    c->min_stage_rim = INFINITY;
}

/* The height of the centre of mass above the table at tilt theta, m: R cos d - eps
 * cos theta on the hull, d the tilt left to the rim's polar angle where the contact
 * is on a rim (R cos(alpha - theta) on pole [0]'s), 0 on the sphere (eq 3.10). */
double tippe_dynamics_hull_height(const dyn_ctx *c, double theta)
{
    double d = 0.0;
    if (c->has_rims && theta < c->rim_alpha[0])
        d = c->rim_alpha[0] - theta;
    else if (c->has_rims && M_PI - theta < c->rim_alpha[1])
        d = c->rim_alpha[1] - (M_PI - theta);
    return c->R * cos(d) - c->eps * cos(theta);
}


double tippe_dynamics_event_value(const dyn_ctx *c, const contact *o, int event)
{
    if (event == EVENT_RIM)
        return rim_stay(c, o->k) + RIM_EVENT_TOL;
    return event == EVENT_SLIP ? c->mu_c * o->Rn - hypot(o->F[0], o->F[1]) : o->Rn;
}

/* The event's function (Rn, or mu_c Rn - |F|) after a trial step of length h from
 * (t0, y0) with a high-order one-step method: what the bisection brackets. */
static int Rn_after(dyn_ctx *c, gsl_odeiv2_step *bs, const gsl_odeiv2_system *sys, double t0,
                    const double *y0, double h, int event, double *y, double *Rn)
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
    if (tippe_dynamics_contact_eval(c, y, &o))
        return GSL_EBADFUNC;
    *Rn = tippe_dynamics_event_value(c, &o, event);
    return GSL_SUCCESS;
}

/* Finds where Rn crosses 0 inside the accepted step (t0, y0) -> t0 + H. The
 * crossing is bracketed either by Rn(H) < 0 or, when only an intermediate
 * stage saw Rn < 0, by scanning 16 sub-steps; it is then bisected to 1e-13 H
 * with an rk8pd step from y0, whatever the main stepper (a single rk8pd step no
 * longer than an accepted step is at least as accurate). On success y holds
 * the state with Rn >= 0 at the crossing and *h_cross its offset from t0.
 * Returns 1 if a crossing was found, 0 if none, < 0 on failure. */
int tippe_dynamics_locate_lift_off(dyn_ctx *c, const gsl_odeiv2_system *sys, double t0,
                                    const double *y0, double H, int end_negative, int event, double *y, double *h_cross)
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
            if (Rn_after(c, bs, sys, t0, y0, hh, event, ytmp, &Rn) != GSL_SUCCESS) {
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
            if (Rn_after(c, bs, sys, t0, y0, mid, event, ytmp, &Rn) != GSL_SUCCESS) {
                status = -1;
                break;
            }
            if (Rn < 0.0)
                hi = mid;
            else
                lo = mid;
        }
        if (status == 0 && Rn_after(c, bs, sys, t0, y0, lo, event, y, &Rn) != GSL_SUCCESS)
            status = -1;
        *h_cross = lo;
    }
    gsl_odeiv2_step_free(bs);
    return status < 0 ? status : found;
}

/* The axis k of a contact and its rate dk/dt = omega x k (k is fixed in the body). */
void tippe_dynamics_axis_rate(const contact *o, double k[3], double dk[3])
{
    memcpy(k, o->k, sizeof o->k);
    dk[0] = o->w[1] * o->k[2] - o->w[2] * o->k[1];
    dk[1] = o->w[2] * o->k[0] - o->w[0] * o->k[2];
    dk[2] = o->w[0] * o->k[1] - o->w[1] * o->k[0];
}

/* Whether the accepted step (axis k0, rate dk0 and |omega| w0 at its start; the contact
 * `end` at its end, H later), whose end stays in its regime, may have left it and come
 * back. A trial stage of rk8pd dipped past the edge, but stages are not the solution
 * (a stage of a 5 ms step sees states the step never passes through), and probing the
 * step with four rk8pd sub-steps costs 52 evaluations: 37 of every 47 probes of the M12
 * at Z2 = 5 mm found nothing. So the axis is followed on the cubic Hermite interpolant
 * of the step (k and omega x k at both ends) at 15 interior points, and the step is
 * probed unless the interpolant stays clear of the edge by more than its error:
 * - the interpolant's, H^4 |k| / 384, with |k| = |omega|^3 |omega x k| for an
 *   axis turning at a steady omega (the larger of both ends; rim_stay is 1-Lipschitz in
 *   k, so an error in k is one in rim_stay);
 * - the sampling's, (H/16)^2 |k''| / 8 between two samples, |k''| = |omega| |omega x k|.
 * Without this allowance a test on the interpolant alone skipped 2 real crossings in
 * ~1000 skipped probes of a viscous map (a review of issue 38's fourth round). What it
 * still cannot see is a dip the angular acceleration makes within one step beyond that
 * estimate; the old four probes could miss one between them as well. */
int tippe_dynamics_step_may_dip(const dyn_ctx *c, const double k0[3], const double dk0[3],
                                double w0, const contact *end, double H)
{
    double k1[3], dk1[3];
    tippe_dynamics_axis_rate(end, k1, dk1);
    const double w = fmax(w0, sqrt(end->w[0] * end->w[0] + end->w[1] * end->w[1] +
                                   end->w[2] * end->w[2]));
    const double dk = fmax(sqrt(dk0[0] * dk0[0] + dk0[1] * dk0[1] + dk0[2] * dk0[2]),
                           sqrt(dk1[0] * dk1[0] + dk1[1] * dk1[1] + dk1[2] * dk1[2]));
    const double Hw = H * w;
    const double allowance = Hw * Hw * Hw * H * dk / 384.0 + H * H * w * dk / (256.0 * 8.0);
    for (int j = 1; j < 16; j++) {
        const double u = j / 16.0, u2 = u * u, u3 = u2 * u;
        const double h00 = 2 * u3 - 3 * u2 + 1, h10 = (u3 - 2 * u2 + u) * H,
                     h01 = -2 * u3 + 3 * u2, h11 = (u3 - u2) * H;
        double k[3];
        for (int i = 0; i < 3; i++)
            k[i] = h00 * k0[i] + h10 * dk0[i] + h01 * k1[i] + h11 * dk1[i];
        const double inv = 1.0 / sqrt(k[0] * k[0] + k[1] * k[1] + k[2] * k[2]);
        for (int i = 0; i < 3; i++)
            k[i] *= inv;
        if (rim_stay(c, k) < allowance - RIM_EVENT_TOL)
            return 1;
    }
    return 0;
}

/* Where rim_stay crosses -RIM_EVENT_TOL inside the accepted step (t0, y0) -> t0 + H:
 * the same brackets as locate_lift_off (the end, or 4 sub-steps when only a stage
 * saw the crossing), closed by the Illinois variant of regula falsi (Dahlquist and
 * Bjorck 1974, sec 6.2.2) to 1e-13 H: the event function is smooth along the step
 * (each regime's equations extend past the crossing), so it converges in ~6 rk8pd
 * steps where bisection takes ~45; a top wobbling on its rim's edge crosses it
 * hundreds of times (issue 35). Returns 1 with y at the crossing (on the side not
 * yet crossed, within the tolerance) and *h_cross its offset, 0 if none, < 0 on
 * failure. */
int tippe_dynamics_locate_rim(dyn_ctx *c, const gsl_odeiv2_system *sys, double t0,
                               const double *y0, double H, int end_negative, double *y, double *h_cross)
{
    gsl_odeiv2_step *bs = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, c->dim);
    if (!bs)
        return -1;
    double ytmp[DIM_TRAJECTORY], f = 0.0, lo = 0.0, hi = H, flo = 0.0, fhi = 0.0;
    int found = 0, status = 0;
    if (Rn_after(c, bs, sys, t0, y0, 0.0, EVENT_RIM, ytmp, &flo) != GSL_SUCCESS)
        status = -1;
    if (!status && end_negative &&
        Rn_after(c, bs, sys, t0, y0, H, EVENT_RIM, ytmp, &fhi) != GSL_SUCCESS)
        status = -1;
    found = !status && end_negative && fhi < 0.0;
    for (int i = 1; !status && !found && i <= 4; i++) {
        const double hh = H * i / 4;
        if (Rn_after(c, bs, sys, t0, y0, hh, EVENT_RIM, ytmp, &f) != GSL_SUCCESS) {
            status = -1;
            break;
        }
        if (f < 0.0) {
            hi = hh;
            fhi = f;
            found = 1;
        } else {
            lo = hh;
            flo = f;
        }
    }
    if (found && !(flo >= 0.0))
        found = 0; /* already past at the step's start: nothing to locate */
    int side = 0;  /* Illinois: halve the weight of an end kept twice */
    for (int it = 0; found && !status && it < 100 && hi - lo > 1e-13 * H; it++) {
        double mid = (lo * fhi - hi * flo) / (fhi - flo);
        if (!(mid > lo && mid < hi))
            mid = 0.5 * (lo + hi);
        if (Rn_after(c, bs, sys, t0, y0, mid, EVENT_RIM, ytmp, &f) != GSL_SUCCESS) {
            status = -1;
            break;
        }
        if (f < 0.0) {
            hi = mid;
            fhi = f;
            if (side == -1)
                flo *= 0.5;
            side = -1;
        } else {
            lo = mid;
            flo = f;
            if (side == 1)
                fhi *= 0.5;
            side = 1;
        }
        if (f == 0.0)
            break;
    }
    if (found && !status) {
        if (Rn_after(c, bs, sys, t0, y0, lo, EVENT_RIM, y, &f) != GSL_SUCCESS)
            status = -1;
        *h_cross = lo;
    }
    gsl_odeiv2_step_free(bs);
    return status < 0 ? status : found;
}

