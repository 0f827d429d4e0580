/* One launch of the eccentric sphere: the regular lab-frame equations of motion,
 * the energy and Jellett monitors, the lost-contact event, and the run that ends
 * in a proved verdict (dynamics_verdict.c). docs/dynamics.md derives the
 * equations and documents each criterion. */
#include "physics/dynamics_state.h"
#include "tippe/base.h"

#include "physics/dynamics_verdict.h"

#include <float.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* ---- the run --------------------------------------------------------------- */

static void set_omega_scale(const dyn_ctx *c, const double *y, double *omega_scale)
{
    *omega_scale = sqrt(dot3(y + IW, y + IW)) + sqrt(c->g / c->R);
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
    c->coulomb = model->law == TIPPE_FRICTION_COULOMB ||
                 model->law == TIPPE_FRICTION_COULOMB_CREEP || model->law == TIPPE_FRICTION_PATCH;
    c->patch = model->law == TIPPE_FRICTION_PATCH;
    c->patch_a = tippe_dynamics_patch_radius(model);
    c->patch_follow = c->patch && c->patch_a > 0.0 && !model->patch_radius_fixed;
    c->inv_mg = 1.0 / (model->top.m * model->g);
    c->roll_arm = c->patch ? model->rolling_arm_m : 0.0;
    c->stick_law = model->law == TIPPE_FRICTION_COULOMB && model->mu_c > 0.0;
    c->mu_c = model->mu_c;
    c->vs = model->slip_scale_m_s > 0.0 ? model->slip_scale_m_s : TIPPE_COULOMB_SLIP_SCALE_M_S;
    c->vs2 = c->vs * c->vs;
    c->min_stage_stick = INFINITY;
    c->one_minus_A_over_C = 1.0 - c->A / c->C;
    c->C_minus_A_over_A = (c->C - c->A) / c->A;
    c->inv_A = 1.0 / c->A;
    c->dim = dim;
    c->min_stage_Rn = INFINITY;
    c->creep_cap = c->patch ? model->creep_cap : 0.0;
    c->sqrt_g_over_R = sqrt(c->g / c->R);
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
    int st = tippe_dynamics_check_inputs(model, s, &o, err);
    if (st)
        return st;
    dyn_ctx c;
    ctx_init(&c, model, DIM_VERDICT);
    double y[DIM_VERDICT];
    initial_state(&c, s, y);
    contact ct;
    if (tippe_dynamics_contact_eval(&c, y, &ct))
        return tippe_error_set(err, TIPPE_ECOMPUTE,
                               "contact force undetermined at this state (denominator of eq "
                               "3.19 <= 0: friction too strong for the model)");
    tippe_dynamics_paper_variables(&c, 0.0, y, &ct, out);
    out->phi = out->psi = out->x = out->y = 0.0;
    return TIPPE_OK;
}

double tippe_dynamics_launch_slip(const tippe_top *top, const tippe_dynamics_initial *ic)
{
    /* V_Q is kinematic (eq 3.7): any valid law and g give the same; the sample's
     * slip_speed is the right-hand side's own |V_Q| */
    tippe_dynamics_model m;
    memset(&m, 0, sizeof m);
    m.top = *top;
    m.g = TIPPE_DEFAULT_G_M_S2;
    m.law = TIPPE_FRICTION_VISCOUS;
    tippe_dynamics_sample s;
    tippe_error e;
    return tippe_dynamics_evaluate(&m, ic, &s, &e) == TIPPE_OK ? s.slip_speed : NAN;
}

/* ---- the run, in named steps -------------------------------------------------- */

typedef struct {
    const tippe_dynamics_options *opt;
    int traj;
    dyn_ctx c;
    gsl_odeiv2_system sys;
    gsl_odeiv2_driver *drv;
    double y[DIM_TRAJECTORY], y_prev[DIM_TRAJECTORY];
    double t, t_prev, theta_prev, theta_launch, h;
    double theta_dot_prev;          /* theta's rate at t_prev, rad/s (the crossings) */
    double k_prev[3], dk_prev[3];   /* the axis and its rate omega x k at t_prev */
    double w_prev;                  /* |omega| at t_prev, rad/s */
    double theta_prev_step;         /* theta at the previous accepted step (rolling) */
    double phi, psi;                /* continued Euler angles (trajectory level) */
    long i_sample;                  /* index of the next sample time */
    int at_sample;                  /* the last step landed on a sample time */
    double J_scale, E_min;
    double energy_abs_err, J_abs_err; /* running maxima of |E + D - E0|, |J - J0| */
    tippe_dynamics_verdict_ctx vc;
    double contact_retry_excess;    /* try the contact bound when E - V_min is below this */
    /* Rolling: 1 waiting for a minimum of theta, 2 following a period from it; the
     * period's theta range (widened by half the largest step in theta), its least
     * margin mu_c Rn - |F| and least Rn. */
    int roll_phase, roll_seen_max;
    double roll_prev_thd, roll_lo, roll_hi, roll_dtheta, roll_gmin, roll_Rn_min;
    contact ct;
    tippe_dynamics_sample smp;
    /* Rims: J changes while the contact is on one (its friction has a lever arm about
     * the axis), so the wells of V are those of J at the last time the contact left
     * a rim (J_ref), its error since then J_ref_err; touched: the run has been on one */
    const tippe_dynamics_model *model;
    int rim_touched, wells_stale, launched_on_rim;
    double J_ref, J_ref_err;
    double creep_power_prev; /* W, |the power the creep reduction changed| at t_prev */
} run_state;

/* Inputs, context, launch state, tolerance scales, monitors at t = 0, the wells of
 * V for the launch's J, and the GSL driver. */
static int run_setup(run_state *rs, const tippe_dynamics_model *model,
                     const tippe_dynamics_initial *ic, const tippe_dynamics_options *opt,
                     tippe_dynamics_result *res, tippe_error *err)
{
    int st = tippe_dynamics_check_inputs(model, ic, opt, err);
    if (st)
        return st;
    rs->opt = opt;
    rs->traj = opt->level == TIPPE_LEVEL_TRAJECTORY;
    dyn_ctx *c = &rs->c;
    ctx_init(c, model, rs->traj ? DIM_TRAJECTORY : DIM_VERDICT);
    tippe_dynamics_set_rims(c, model, opt);
    res->state_dim = (int)c->dim;
    initial_state(c, ic, rs->y);
    rs->model = model;
    if (c->has_rims) {
        const double inv_kn = 1.0 / sqrt(dot3(rs->y + IK, rs->y + IK));
        const double k[3] = {rs->y[IK] * inv_kn, rs->y[IK + 1] * inv_kn, rs->y[IK + 2] * inv_kn};
        c->rim = rim_regime(c, k, &c->face);
        rs->rim_touched = rs->launched_on_rim = c->rim != 0;
    }
    double omega_scale;
    set_omega_scale(c, rs->y, &omega_scale);
    /* Absolute tolerance = rtol * scale per component: unit vectors 1, angular
     * velocity the launch's rotation rate, velocities and positions from R. */
    for (size_t i = 0; i < c->dim; i++)
        c->scale[i] = 1.0;
    for (int i = 0; i < 3; i++)
        c->scale[IW + i] = omega_scale;
    c->scale[IV] = c->scale[IV + 1] = c->R * omega_scale;
    if (tippe_dynamics_contact_eval(c, rs->y, &rs->ct))
        return tippe_error_set(err, TIPPE_ECOMPUTE,
                               "contact force undetermined at launch (denominator of eq 3.19 "
                               "= %g <= 0: friction too strong for the model)",
                               rs->ct.den);
    res->E0 = tippe_dynamics_energy(c, &rs->ct);
    res->J0 = tippe_dynamics_jellett(c, &rs->ct);
    c->scale[ID] = res->E0;
    if (rs->traj)
        c->scale[IX] = c->scale[IX + 1] = c->R;
    rs->J_scale = fmax(fabs(res->J0), 1e-6 * c->C * omega_scale * c->R);
    rs->J_ref = res->J0;
    rs->E_min = res->E0;
    rs->contact_retry_excess = INFINITY;
    st = tippe_dynamics_verdict_init(&rs->vc, model, res->J0, err);
    if (st)
        return st;
    rs->sys = (gsl_odeiv2_system){tippe_dynamics_rhs, tippe_dynamics_jacobian, c->dim, c};
    /* A first step of 1e-4 of the fastest period; the controller grows it. */
    rs->h = 1e-4 * 2.0 * M_PI / omega_scale;
    /* The patch law turns stiff as the spin about the vertical drains: its small-slip
     * drag mu_c c1 / (a |omega_n|) relaxes the slip at ~ mu_c g c1 / (a |omega_n|)
     * (2e4 /s for the M12 on glass at 1 rad/s, up to mu_c g / v_s = 3e5 /s), where rk8pd
     * crawls at its stability limit (an M12 check: 1.7e8 evaluations for 117 s). So the
     * presets' rk8pd becomes msbdf (BDF, implicit) under the patch law, at the same
     * rtol: 2.4e5 evaluations for 120 s (docs/dynamics.md, "Patch friction"). */
    const char *stepper =
        tippe_dynamics_stepper_used(model->law, model->creep_cap, opt->accuracy.stepper);
    rs->drv = gsl_odeiv2_driver_alloc_scaled_new(&rs->sys, tippe_dynamics_stepper_type(stepper),
                                                 rs->h, opt->accuracy.rtol, opt->accuracy.rtol,
                                                 1.0, 0.0, c->scale);
    if (!rs->drv)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "cannot allocate the GSL driver");
    return TIPPE_OK;
}

/* The reported state at rs->t, with the orientation at trajectory level. */
static void run_fill_sample(run_state *rs)
{
    tippe_dynamics_paper_variables(&rs->c, rs->t, rs->y, &rs->ct, &rs->smp);
    if (rs->traj) {
        tippe_dynamics_euler_angles(rs->y + IQ, &rs->phi, &rs->psi);
        rs->smp.phi = rs->phi;
        rs->smp.psi = rs->psi;
        rs->smp.x = rs->y[IX];
        rs->smp.y = rs->y[IX + 1];
    }
}

static int run_emit(run_state *rs, tippe_error *err)
{
    if (!rs->opt->on_sample)
        return TIPPE_OK;
    int cb = rs->opt->on_sample(&rs->smp, rs->opt->sample_ctx);
    if (cb)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "sample callback stopped the run (%d)", cb);
    return TIPPE_OK;
}

/* Whether the motion must end at a steady state (section 4, Proposition 4.2): it
 * needs friction (mu > 0, or mu_c > 0) and an eccentric sphere (eps > 0); with
 * Coulomb sticking the end state is still not proved (end_state_proved = 0). With mu = 0 nothing
 * dissipates; with eps = 0 the ball can roll without slipping for ever, its axis
 * turning, and rolling dissipates nothing. Then only confinement is proved. */
static int run_dissipates_to_rest(const run_state *rs)
{
    return rs->vc.dissipative && rs->vc.top.eps > 0.0;
}

/* The verdict of a trapped well and the steady state at its minimum for J0. */
static void run_set_trapped(run_state *rs, const tippe_dynamics_verdict_trap *tr, double margin, double Rn_bound,
                            tippe_dynamics_result *res)
{
    const tippe_theory_well *wl = &rs->vc.wells.well[tr->well];
    const tippe_top *top = &rs->vc.top;
    const double th = wl->theta_min_rad;
    res->how = TIPPE_DECIDED_TRAPPED;
    res->verdict = TIPPE_VERDICT_UNDECIDED;
    res->t_verdict = rs->t;
    res->final = rs->smp;
    res->theta_final_rad = th;
    res->theta_lo_rad = tr->lo;
    res->theta_hi_rad = tr->hi;
    res->barrier_gap_J = tr->gap;
    res->margin_J = margin;
    res->Rn_bound_N = Rn_bound;
    res->phi_dot_final_rad_s = 0.0;
    res->rolling = rs->c.stick;
    if (!run_dissipates_to_rest(rs)) {
        /* a range, not an end state */
        res->verdict = TIPPE_VERDICT_BOUNDED;
        res->theta_final_rad = res->spin_final_rad_s = res->phi_dot_final_rad_s = NAN;
    } else if (!tr->trapped) {
        /* unresolvable: one of the well's steady states, not provably which */
        res->how = TIPPE_DECIDED_FLAT_WELL;
        res->spin_final_rad_s = rs->smp.spin;
        res->phi_dot_final_rad_s = NAN;
    } else if (th == 0.0) {
        res->verdict = TIPPE_VERDICT_NO_TIP;
        res->spin_final_rad_s = tippe_theory_n0(top, res->J0);
    } else if (th == M_PI) {
        res->verdict = TIPPE_VERDICT_TIP;
        res->spin_final_rad_s = tippe_theory_npi(top, res->J0);
    } else {
        res->verdict = TIPPE_VERDICT_HANG;
        tippe_theory_state st;
        if (tippe_theory_intermediate(top, rs->c.g, th, res->J0 < 0.0 ? -1 : 1, &st, NULL) ==
            TIPPE_OK) {
            res->spin_final_rad_s = st.spin_rad_s;
            res->phi_dot_final_rad_s = st.phi_dot_rad_s;
        } else { /* eps = 0 ball hanging at pi/2: no spin, precession from J */
            res->spin_final_rad_s = 0.0;
            res->phi_dot_final_rad_s = res->J0 / (top->A * top->R);
        }
    }
}

/* The energy test at every accepted step (a comparison with a constant of the
 * well), and the contact bound when the energy excess over the well's minimum has
 * halved since its last failure (it only gets easier as E falls). 1 if decided:
 * trapped; bounded (mu = 0 or eps = 0, confined: E never rises); or stopped early in a
 * well that can never be resolved (undecided, flat_well). */
static int run_try_energy_cone(run_state *rs, tippe_dynamics_result *res);
static int run_try_decide(run_state *rs, tippe_dynamics_result *res)
{
    /* Patch friction drills: its couple M e3 changes Jellett's J = -L.q at the rate
     * dJ/dt = -M e3.q = M (R - eps cos theta), nonzero while the patch spins (the force's
     * part stays 0 as for a point contact), and every proof below (the wells of V(theta; J0), the contact
     * bound on the Jellett line) assumes J = J0. No proof, then: the run goes on to
     * t_end and reports what it observes there (run_set_observed). */
    if (rs->c.patch && rs->vc.dissipative)
        return run_try_energy_cone(rs, res);
    /* On the outline's rims: the energy alone proves what it can (run_try_energy_cone),
     * and the wells of V, which need J constant, only off a rim, for the J it left
     * the last rim with, over a range that can no longer reach a rim. */
    if (rs->c.has_rims) {
        if (rs->vc.dissipative && run_try_energy_cone(rs, res))
            return 1;
        if (rs->c.rim)
            return 0;
        if (rs->wells_stale) {
            tippe_error ignored;
            if (tippe_dynamics_verdict_init(&rs->vc, rs->model, rs->J_ref, &ignored))
                return 0;
            rs->wells_stale = 0;
            rs->contact_retry_excess = INFINITY;
        }
    }
    const double margin = tippe_dynamics_verdict_margin(
        &rs->vc, rs->opt->margin_factor, rs->energy_abs_err,
        rs->rim_touched ? rs->J_ref_err : rs->J_abs_err, res->E0);
    const tippe_dynamics_sample *s = &rs->smp;
    const int at_rest = (s->theta == 0.0 || s->theta == M_PI) && s->theta_dot == 0.0 &&
                        s->slip_speed == 0.0;
    tippe_dynamics_verdict_trap tr;
    tippe_dynamics_verdict_energy_test(&rs->vc, s->theta, s->E, margin, at_rest ? s->theta : NAN, &tr);
    const int decidable =
        run_dissipates_to_rest(rs) ? (tr.trapped || tr.unresolvable) : tr.confined;
    if (!decidable)
        return 0;
    const double excess = rs->smp.E - rs->vc.wells.well[tr.well].V_min;
    if (!(excess < rs->contact_retry_excess))
        return 0;
    tippe_dynamics_verdict_trap_range(&rs->vc, rs->smp.E, margin, &tr);
    const double Rn_bound = tippe_dynamics_verdict_contact_bound(&rs->vc, rs->smp.E + margin, tr.lo, tr.hi);
    /* With sticking the top can roll for ever anywhere in [lo, hi] (nothing dissipates
     * while it rolls), so only the range is proved: tip needs all of it above pi/2,
     * no_tip all of it below. */
    /* A tip is the inverted state reached: with sticking, all of the range within
     * TIPPE_INVERTED_TOL_RAD of pi (a top that sticks and rolls for ever at 138 deg
     * has not flipped: run_try_rolling gives its range). */
    const double th_min = rs->vc.wells.well[tr.well].theta_min_rad;
    const int side_ok = !rs->c.stick_law || !tr.trapped ||
                        (th_min == M_PI ? tr.lo >= M_PI - TIPPE_INVERTED_TOL_RAD
                                        : th_min == 0.0 ? tr.hi < 0.5 * M_PI : 1);
    /* a range that reaches a rim may take the contact there, where J changes */
    const int off_rims = !rs->c.has_rims || (tr.lo >= rs->c.rim_alpha[0] &&
                                             tr.hi <= M_PI - rs->c.rim_alpha[1]);
    /* a twentieth of m g: room for the variation of the bound between its nodes */
    if (!(Rn_bound > 0.05 * rs->c.m * rs->c.g) || !side_ok || !off_rims) {
        rs->contact_retry_excess = 0.5 * excess;
        return 0;
    }
    run_set_trapped(rs, &tr, margin, Rn_bound, res);
    return 1;
}

/* When theta crossed pi/2 in the step from (t0, theta0) to (t1, theta1): the root of
 * the cubic Hermite interpolant through both ends and their rates (error O(h^4), where
 * the chord's is O(h^2): a 2 ms step of rk8pd put the chord's crossing 1e-4 s off the
 * flip), by bisection, since the cubic may leave the bracket's monotone chord. */
static double crossing_time(double t0, double th0, double thd0, double t1, double th1,
                            double thd1)
{
    const double h = t1 - t0, target = 0.5 * M_PI;
    double a = 0.0, b = 1.0;
    const double sgn = th1 > th0 ? 1.0 : -1.0;
    for (int it = 0; it < 60; it++) {
        const double u = 0.5 * (a + b), u2 = u * u, u3 = u2 * u;
        const double th = (2 * u3 - 3 * u2 + 1) * th0 + (u3 - 2 * u2 + u) * h * thd0 +
                          (-2 * u3 + 3 * u2) * th1 + (u3 - u2) * h * thd1;
        if (sgn * (th - target) < 0.0)
            a = u;
        else
            b = u;
    }
    return t0 + 0.5 * (a + b) * h;
}

/* The monitors of an accepted state. */
static void run_monitor(run_state *rs, tippe_dynamics_result *res)
{
    const tippe_dynamics_sample *s = &rs->smp;
    const double dJ = fabs(s->J - res->J0);
    if (dJ > rs->J_abs_err)
        rs->J_abs_err = dJ;
    if (!rs->c.rim && fabs(s->J - rs->J_ref) > rs->J_ref_err)
        rs->J_ref_err = fabs(s->J - rs->J_ref);
    /* the creep reduction's change to the contact's power, integrated (trapezoids):
     * its estimate of the energy it moved, which the energy cone's margin carries */
    res->creep_energy_J += 0.5 * (rs->creep_power_prev + rs->ct.creep_power) * (rs->t - rs->t_prev);
    rs->creep_power_prev = rs->ct.creep_power;
    const double dE = fabs(s->E + s->D - res->E0);
    if (dE > rs->energy_abs_err)
        rs->energy_abs_err = dE;
    if (s->E - rs->E_min > res->energy_max_rise)
        res->energy_max_rise = s->E - rs->E_min;
    if (s->E < rs->E_min)
        rs->E_min = s->E;
    if (s->Rn < res->min_Rn)
        res->min_Rn = s->Rn;
    if (isnan(res->t_flip) && rs->theta_prev <= 0.5 * M_PI && s->theta > 0.5 * M_PI)
        res->t_flip = crossing_time(rs->t_prev, rs->theta_prev, rs->theta_dot_prev, rs->t,
                                    s->theta, s->theta_dot);
    else if (!isnan(res->t_flip) && isnan(res->t_fall) && rs->theta_prev > 0.5 * M_PI &&
             s->theta <= 0.5 * M_PI)
        res->t_fall = crossing_time(rs->t_prev, rs->theta_prev, rs->theta_dot_prev, rs->t,
                                    s->theta, s->theta_dot);
    if (rs->theta_prev > 0.5 * M_PI && s->theta > 0.5 * M_PI)
        res->inverted_time_s += rs->t - rs->t_prev;
    /* on a hole's rim at a pole (issue 25.7) */
    const double *cap = rs->opt->cap_half_angle_rad;
    const int on = s->theta < cap[0] || M_PI - s->theta < cap[1];
    if (on) {
        if (isnan(res->cap_first_s))
            res->cap_first_s = rs->t;
        res->cap_last_s = rs->t;
        if (rs->theta_prev < cap[0] || M_PI - rs->theta_prev < cap[1])
            res->cap_time_s += rs->t - rs->t_prev;
    }
    rs->theta_prev = s->theta;
    rs->theta_dot_prev = s->theta_dot;
}

/* Coulomb's stick (Leine and Glocker 2003): once the slip is below 30 v_s and the force
 * that rolling without slipping needs lies inside the friction cone (|F| <= mu_c Rn,
 * Rn > 0), the contact sticks. The slip left (< 30 v_s) is removed by the contact
 * impulse P = -K^-1 V_Q that brings it to 0 (a perfectly inelastic tangential
 * impact): the energy falls by V_Q.K^-1 V_Q / 2 >= 0, booked as dissipated (D). The
 * run then integrates the rolling equations until |F| reaches mu_c Rn. */
static void run_try_stick(run_state *rs, tippe_dynamics_result *res)
{
    dyn_ctx *c = &rs->c;
    /* The regularised law leaves a creeping slip v_s r / sqrt(1 - r^2) where exact
     * Coulomb friction would stick (r = |F| / mu_c Rn < 1): 30 v_s catches r < 0.9994. */
    const double slip2 = rs->ct.VQ[0] * rs->ct.VQ[0] + rs->ct.VQ[1] * rs->ct.VQ[1];
    if (!c->stick_law || c->stick || !(slip2 < STICK_SLIP_FACTOR * STICK_SLIP_FACTOR * c->vs2))
        return;
    c->stick = 1;
    contact o;
    /* inside the cone by STICK_MARGIN mu_c m g: where the contact just broke loose (the
     * force on the cone's edge) it slides on rather than sticking again at once */
    if (tippe_dynamics_contact_eval(c, rs->y, &o) || !(o.Rn > 0.0) ||
        !(tippe_dynamics_event_value(c, &o, EVENT_SLIP) > STICK_MARGIN * c->mu_c * c->m * c->g)) {
        c->stick = 0; /* rolling needs more than the cone gives: it keeps sliding */
        return;
    }
    const double V[3] = {o.VQ[0], o.VQ[1], 0.0};
    double P[3], qP[3], dw[3];
    if (tippe_dynamics_solve3(o.K, V, P)) {
        c->stick = 0;
        return;
    }
    for (int i = 0; i < 3; i++)
        P[i] = -P[i];
    cross3(o.q, P, qP);
    tippe_dynamics_inv_inertia(c, o.k, qP, dw);
    rs->y[IV] += P[0] / c->m;
    rs->y[IV + 1] += P[1] / c->m;
    for (int i = 0; i < 3; i++)
        rs->y[IW + i] += dw[i];
    rs->y[ID] -= 0.5 * dot3(V, P);
    gsl_odeiv2_driver_reset(rs->drv);
    tippe_dynamics_contact_eval(c, rs->y, &rs->ct);
    res->stick_events++;
    run_fill_sample(rs);
    rs->roll_phase = 1;
    rs->roll_prev_thd = rs->smp.theta_dot;
}

/* Whether a rolling top rolls for ever. A sphere with an axisymmetric mass
 * distribution rolling without slipping on a plane is integrable (Routh 1884: E,
 * Jellett's J and Routh's integral), and the force the contact needs depends only
 * on the reduced state, which is periodic in the nutation: theta swings between
 * two minima of the same value. So if over one period, from one minimum of theta
 * to the next, the force stayed inside the cone with room to spare (1e-3 mu_c m g,
 * for the error of the integration and of sampling the period at the steps), it
 * does so for ever. Then theta stays within the period's range: no_tip below pi/2,
 * tip above, else bounded. 1 if decided. */
static int run_try_rolling(run_state *rs, tippe_dynamics_result *res)
{
    dyn_ctx *c = &rs->c;
    if (!c->stick) {
        rs->roll_phase = 0;
        return 0;
    }
    const tippe_dynamics_sample *s = &rs->smp;
    const int minimum = rs->roll_prev_thd < 0.0 && s->theta_dot >= 0.0;
    /* a period passes a maximum of theta too: a sign change of theta_dot at a minimum
     * that noise repeats within a step or two is not a period */
    if (rs->roll_prev_thd > 0.0 && s->theta_dot <= 0.0)
        rs->roll_seen_max = 1;
    rs->roll_prev_thd = s->theta_dot;
    if (rs->roll_phase == 2) {
        const double g = fmin(tippe_dynamics_event_value(c, &rs->ct, EVENT_SLIP), c->min_stage_stick);
        rs->roll_gmin = fmin(rs->roll_gmin, g);
        rs->roll_Rn_min = fmin(rs->roll_Rn_min, fmin(s->Rn, c->min_stage_Rn));
        rs->roll_dtheta = fmax(rs->roll_dtheta, fabs(s->theta - rs->theta_prev_step));
        rs->roll_lo = fmin(rs->roll_lo, s->theta);
        rs->roll_hi = fmax(rs->roll_hi, s->theta);
    }
    rs->theta_prev_step = s->theta;
    if (!minimum)
        return 0;
    if (rs->roll_phase == 2 && rs->roll_seen_max &&
        rs->roll_gmin > STICK_MARGIN * c->mu_c * c->m * c->g) {
        const double lo = fmax(0.0, rs->roll_lo - 0.5 * rs->roll_dtheta);
        const double hi = fmin(M_PI, rs->roll_hi + 0.5 * rs->roll_dtheta);
        res->how = TIPPE_DECIDED_ROLLING;
        /* rolling dissipates nothing: a tip only where the whole range is the
         * inverted state (within TIPPE_INVERTED_TOL_RAD of pi), else a range */
        res->verdict = hi < 0.5 * M_PI                        ? TIPPE_VERDICT_NO_TIP
                       : lo >= M_PI - TIPPE_INVERTED_TOL_RAD ? TIPPE_VERDICT_TIP
                                                              : TIPPE_VERDICT_BOUNDED;
        res->t_verdict = rs->t;
        res->final = *s;
        res->theta_final_rad = s->theta;
        res->spin_final_rad_s = s->spin;
        res->phi_dot_final_rad_s = s->phi_dot;
        res->theta_lo_rad = lo;
        res->theta_hi_rad = hi;
        res->Rn_bound_N = rs->roll_Rn_min;
        res->rolling = 1;
        return 1;
    }
    rs->roll_phase = 2;
    rs->roll_seen_max = 0;
    rs->roll_lo = rs->roll_hi = s->theta;
    rs->roll_dtheta = 0.0;
    rs->roll_gmin = rs->roll_Rn_min = INFINITY;
    return 0;
}

/* The contact moves between the sphere and a rim inside the accepted step (t_prev,
 * y_prev) -> t: the crossing of rim_stay is located as lift-off is (bisection of an
 * rk8pd step to 1e-13 of the step), the state put there and the regime switched, and
 * the stepper restarted, so that no step spans the jump of the normal force's rate.
 * Each regime's equations extend smoothly past the crossing, so the stepper's trial
 * stages there are harmless. t_full: the step's end before another event cut it
 * (then only the end state is tested, the stages having gone beyond it). Returns 1
 * if it switched, 2 if the step was undone to be taken again shorter, 0 if
 * nothing happened, < 0 on failure. */
static int run_rim_event(run_state *rs, tippe_dynamics_result *res, double t_full)
{
    dyn_ctx *c = &rs->c;
    const double end = rim_stay(c, rs->ct.k);
    const int cut = rs->t < t_full;
    if (!(end < -RIM_EVENT_TOL) && (cut || !(c->min_stage_rim < -RIM_EVENT_TOL)))
        return 0;
    if (!(end < -RIM_EVENT_TOL) &&
        !tippe_dynamics_step_may_dip(c, rs->k_prev, rs->dk_prev, rs->w_prev, &rs->ct,
                                     rs->t - rs->t_prev))
        return 0;
    double hc = 0.0, ycross[DIM_TRAJECTORY];
    const double H = rs->t - rs->t_prev;
    int f = tippe_dynamics_locate_rim(c, &rs->sys, rs->t_prev, rs->y_prev, H, end < -RIM_EVENT_TOL, ycross, &hc);
    if (f < 0)
        return f;
    if (f == 0 && !(end < -RIM_EVENT_TOL))
        return 0; /* only a trial stage dipped past: no crossing in the step */
    if (f == 0) {
        /* The step ends past the switch but a single rk8pd probe of it cannot bracket
         * the crossing: a long step of an implicit stepper (msbdf under the patch law,
         * steps far beyond rk8pd's stability). Take the step again, 16 times shorter,
         * until the probe can; below 1e-12 s switch where it ended. */
        if (H > 1e-12) {
            if (c->stick)
                res->rolling_time_s -= H;
            if (rs->traj && rs->opt->sample_dt > 0.0 && rs->at_sample) {
                rs->at_sample = 0;
                rs->i_sample--;
            }
            rs->t = rs->t_prev;
            memcpy(rs->y, rs->y_prev, c->dim * sizeof *rs->y);
            rs->h = H / 16.0;
            gsl_odeiv2_driver_reset(rs->drv);
            if (tippe_dynamics_contact_eval(c, rs->y, &rs->ct))
                return -1;
            return 2;
        }
        hc = H;
        memcpy(ycross, rs->y, c->dim * sizeof *rs->y);
    }
    if (c->stick)
        res->rolling_time_s -= rs->t - rs->t_prev - hc;
    rs->t = rs->t_prev + hc;
    memcpy(rs->y, ycross, c->dim * sizeof *rs->y);
    if (rs->traj && rs->opt->sample_dt > 0.0 && rs->at_sample) {
        rs->at_sample = 0; /* stopped short of the sample time */
        rs->i_sample--;
    }
    contact o;
    if (tippe_dynamics_contact_eval(c, rs->y, &o))
        return -1;
    const int from = c->rim, from_face = c->face;
    if (from && from_face) {
        c->face = 0; /* off the face onto the rim */
    } else if (from) {
        /* the nearer of the rim's two edges: its polar angle (to the sphere) or its face */
        const double S = hypot(o.k[0], o.k[1]);
        const double edge = from == 1 ? o.k[2] - c->rim_cos[0] : -o.k[2] - c->rim_cos[1];
        if (S - c->rim_face_sin[from - 1] < edge)
            c->face = 1;
        else
            c->rim = 0;
    } else { /* onto the rim whose stay went below 0 */
        const double s0 = c->rim_alpha[0] > 0.0 ? c->rim_cos[0] - o.k[2] : INFINITY;
        const double s1 = c->rim_alpha[1] > 0.0 ? c->rim_cos[1] + o.k[2] : INFINITY;
        c->rim = s0 <= s1 ? 1 : 2;
    }
    gsl_odeiv2_driver_reset(rs->drv);
    if (tippe_dynamics_contact_eval(c, rs->y, &rs->ct))
        return -1;
    res->rim_switches++;
    if (from && !c->rim) {
        /* off the rim: J is constant again (on the sphere), from here */
        tippe_dynamics_sample here;
        tippe_dynamics_paper_variables(c, rs->t, rs->y, &rs->ct, &here);
        rs->J_ref = here.J;
        rs->J_ref_err = 0.0;
        rs->wells_stale = 1;
        if (rs->launched_on_rim && isnan(res->spin_leaving_rim_rad_s))
            res->spin_leaving_rim_rad_s = here.spin;
    } else {
        rs->rim_touched = 1;
    }
    return 1;
}

/* One accepted step towards the next sample time or t_end. Returns 1 if the top
 * lost contact in it (the state is then the lift-off), 0 if not, or an error. */
static int run_step(run_state *rs, tippe_dynamics_result *res, tippe_error *err)
{
    const tippe_dynamics_options *opt = rs->opt;
    dyn_ctx *c = &rs->c;
    if (tippe_cancel_requested()) /* a step is microseconds: the watch is read each one */
        return -tippe_cancel_error(err);
    double t_target = opt->t_end;
    if (rs->traj && opt->sample_dt > 0.0)
        t_target = fmin(opt->t_end, (double)rs->i_sample * opt->sample_dt);
    rs->t_prev = rs->t;
    memcpy(rs->y_prev, rs->y, c->dim * sizeof *rs->y);
    if (c->has_rims) { /* the rim probes' Hermite test (run_rim_event) */
        tippe_dynamics_axis_rate(&rs->ct, rs->k_prev, rs->dk_prev);
        rs->w_prev = sqrt(dot3(rs->ct.w, rs->ct.w));
    }
    c->min_stage_Rn = INFINITY;
    c->min_stage_stick = INFINITY;
    c->min_stage_rim = INFINITY;
    c->bad_contact = 0;
    const int was_stuck = c->stick;
    int s = gsl_odeiv2_evolve_apply(rs->drv->e, rs->drv->c, rs->drv->s, &rs->sys, &rs->t,
                                    t_target, &rs->h, rs->y);
    if (s != GSL_SUCCESS) {
        if (c->bad_contact)
            return -tippe_error_set(err, TIPPE_ECOMPUTE,
                                    "at t = %g s the contact force became undetermined "
                                    "(denominator of eq 3.19 <= 0: friction %s %g%s "
                                    "too strong for the model)",
                                    rs->t, c->coulomb ? "mu_c" : "mu",
                                    c->coulomb ? c->mu_c : c->mu, c->coulomb ? "" : " s/m");
        return -tippe_error_set(err, TIPPE_ECOMPUTE,
                                "integrator (%s, rtol %g) failed at t = %g s: %s",
                                opt->accuracy.stepper, opt->accuracy.rtol, rs->t,
                                gsl_strerror(s));
    }
    res->steps++;
    const double t_full = rs->t;
    rs->at_sample = rs->t >= t_target;
    if (rs->traj && opt->sample_dt > 0.0 && rs->at_sample)
        rs->i_sample++;
    if (tippe_dynamics_contact_eval(c, rs->y, &rs->ct))
        return -tippe_error_set(err, TIPPE_ECOMPUTE,
                                "at t = %g s the contact force became undetermined "
                                "(denominator of eq 3.19 <= 0)", rs->t);
    if (was_stuck)
        res->rolling_time_s += rs->t - rs->t_prev;
    int lost = 0;
    const double stick_end = was_stuck ? tippe_dynamics_event_value(c, &rs->ct, EVENT_SLIP) : INFINITY;
    if (was_stuck && (stick_end < 0.0 || c->min_stage_stick < 0.0)) {
        /* The rolling force left the friction cone in this step (its edge comes
         * before Rn = 0): find where, and slide from there. */
        double hc = 0.0, ycross[DIM_TRAJECTORY];
        int f = tippe_dynamics_locate_lift_off(c, &rs->sys, rs->t_prev, rs->y_prev, rs->t - rs->t_prev,
                                stick_end < 0.0, EVENT_SLIP, ycross, &hc);
        if (f < 0)
            return -tippe_error_set(err, TIPPE_ECOMPUTE,
                                    "failed to locate the end of rolling near t = %g s", rs->t);
        if (f == 1) {
            res->rolling_time_s -= rs->t - rs->t_prev - hc;
            rs->t = rs->t_prev + hc;
            memcpy(rs->y, ycross, c->dim * sizeof *rs->y);
            c->stick = 0;
            res->slip_events++;
            gsl_odeiv2_driver_reset(rs->drv);
            tippe_dynamics_contact_eval(c, rs->y, &rs->ct);
            if (rs->traj && opt->sample_dt > 0.0 && rs->at_sample) {
                rs->at_sample = 0; /* stopped short of the sample time */
                rs->i_sample--;
            }
        }
    } else if (rs->ct.Rn < 0.0 || c->min_stage_Rn < 0.0) {
        /* Never accept a state with Rn < 0: find where it reached 0. */
        double hc = 0.0, ycross[DIM_TRAJECTORY];
        int f = tippe_dynamics_locate_lift_off(c, &rs->sys, rs->t_prev, rs->y_prev, rs->t - rs->t_prev,
                                rs->ct.Rn < 0.0, EVENT_LIFT_OFF, ycross, &hc);
        if (f < 0)
            return -tippe_error_set(err, TIPPE_ECOMPUTE,
                                    "failed to locate the lift-off near t = %g s", rs->t);
        if (f == 1) {
            rs->t = rs->t_prev + hc;
            memcpy(rs->y, ycross, c->dim * sizeof *rs->y);
            tippe_dynamics_contact_eval(c, rs->y, &rs->ct);
            lost = 1;
        }
    }
    if (!lost && c->has_rims && run_rim_event(rs, res, t_full) < 0)
        return -tippe_error_set(err, TIPPE_ECOMPUTE,
                                "failed to locate where the contact moves between the sphere "
                                "and a rim near t = %g s", rs->t);
    run_fill_sample(rs);
    run_monitor(rs, res);
    if (!lost)
        run_try_stick(rs, res);
    return lost;
}

static void run_set_lost_contact(run_state *rs, tippe_dynamics_result *res)
{
    res->verdict = TIPPE_VERDICT_LOST_CONTACT;
    res->how = TIPPE_DECIDED_LOST_CONTACT;
    res->t_verdict = rs->t;
    res->final = rs->smp;
    res->theta_final_rad = rs->smp.theta;
    res->spin_final_rad_s = rs->smp.spin;
    res->phi_dot_final_rad_s = rs->smp.phi_dot;
}

/* Whether the loop may stop once the verdict is known. */
static int run_may_stop(const run_state *rs, const tippe_dynamics_result *res)
{
    if ((res->verdict == TIPPE_VERDICT_UNDECIDED && res->how != TIPPE_DECIDED_FLAT_WELL) ||
        rs->opt->run_to_t_end)
        return 0;
    /* a tip launched below pi/2 must cross it; one launched above has no flip */
    if (rs->opt->until_flip && res->verdict == TIPPE_VERDICT_TIP && isnan(res->t_flip) &&
        rs->theta_launch <= 0.5 * M_PI)
        return 0;
    return 1;
}

/* Patch law at t_end: the state there as the verdict, marked not proved: no_tip within
 * this of theta = 0, tip within it of pi, else hang. */
#define PATCH_POLE_RAD 0.25

/* The one proof that needs no J: every law's friction (the patch's sliding and
 * drilling, the rolling couple, a rim's sliding) only takes energy (power >= 0;
 * contact_patch.c: a dissipation potential), and E = T + m g h(theta) with T >= 0,
 * h the height of the centre of mass over the outline's lowest point (hull_height;
 * R - eps cos theta on the sphere, paper section 3). So theta can never again
 * reach an angle where m g h exceeds E.
 * - no_tip: a top within PATCH_POLE_RAD of upright whose E plus its margin is below
 *   m g h(PATCH_POLE_RAD) can never reach that angle (theta is continuous), so it
 *   stays within theta_hi < PATCH_POLE_RAD of upright for ever, however J drifts (h
 *   rises on [0, PATCH_POLE_RAD] for eps >= 0: theta_hi is where it meets E). A top
 *   that flipped and fell back ends here too. The top must be on this side now: where
 *   eps is small and the other pole is cut, the flat end's well lies below
 *   m g h(PATCH_POLE_RAD) too (eps < R (1 - cos alpha) / (1 + cos 0.25), 0.3 mm for
 *   the M12), and a top resting there is no no_tip. With eps = 0 the sphere is level
 *   (h = R) and only a rim's well holds the top; without one the test never passes.
 * - the margin: margin_factor times the energy balance's error so far (an estimate of
 *   the integrator's, hence the factor), plus the creep reduction's energy counted
 *   once: the integral of |the power the blend changed| so far, by the triangle
 *   inequality no less than what the blend has moved of E, so the full law's energy is
 *   at most E plus it and only falls from there. Not covered: the reduced run's own
 *   future, where the blend's power can be positive for a moment (creep_reduce);
 *   tests/test_physics_energy_cone.c runs such decisions on to t_end.
 * - tip, where the other pole is cut flat: h falls from its crest at
 *   pi - beta*, tan beta* = R sin(alpha) / (R cos(alpha) + eps), to pi (standing
 *   on the flat end is a well); a top beyond the crest with E plus margin below it
 *   stays beyond it for ever. */
static int run_try_energy_cone(run_state *rs, tippe_dynamics_result *res)
{
    const dyn_ctx *c = &rs->c;
    if (!(c->eps >= 0) || rs->opt->run_to_t_end)
        return 0;
    const double margin = rs->opt->margin_factor * rs->energy_abs_err + res->creep_energy_J +
                          1e-12 * res->E0;
    const double E = rs->smp.E + margin, mg = c->m * c->g;
    double lo = NAN, hi = NAN;
    tippe_verdict verdict;
    if (rs->smp.theta < PATCH_POLE_RAD && E < mg * tippe_dynamics_hull_height(c, PATCH_POLE_RAD)) {
        verdict = TIPPE_VERDICT_NO_TIP;
        lo = 0.0;
        if (!(c->rim_alpha[0] > 0.0) || E >= mg * tippe_dynamics_hull_height(c, c->rim_alpha[0])) {
            /* on the sphere: m g (R - eps cos theta_hi) = E */
            if (!(c->eps > 0)) /* level sphere, no rim: E >= m g R, only rounding gets here */
                return 0;
            const double cos_hi = (c->R - E / mg) / c->eps;
            hi = cos_hi >= 1.0 ? 0.0 : acos(cos_hi);
        } else { /* within the rim, where h rises: bisection */
            double a = 0.0, b = c->rim_alpha[0];
            for (int it = 0; it < 100 && b - a > 1e-15; it++) {
                const double mid = 0.5 * (a + b);
                if (mg * tippe_dynamics_hull_height(c, mid) > E)
                    b = mid;
                else
                    a = mid;
            }
            hi = b;
        }
    } else if (c->rim_alpha[1] > 0.0) {
        const double s1 = sin(c->rim_alpha[1]), c1 = cos(c->rim_alpha[1]);
        const double crest = M_PI - atan2(c->R * s1, c->R * c1 + c->eps);
        if (!(rs->smp.theta > crest && E < mg * tippe_dynamics_hull_height(c, crest)))
            return 0;
        verdict = TIPPE_VERDICT_TIP;
        double a = crest, b = M_PI; /* h falls on [crest, pi]: where it meets E */
        for (int it = 0; it < 100 && b - a > 1e-15; it++) {
            const double mid = 0.5 * (a + b);
            if (mg * tippe_dynamics_hull_height(c, mid) > E)
                a = mid;
            else
                b = mid;
        }
        lo = a;
        hi = M_PI;
    } else {
        return 0;
    }
    res->verdict = verdict;
    res->how = TIPPE_DECIDED_ENERGY_CONE;
    res->t_verdict = rs->t;
    res->final = rs->smp;
    res->theta_final_rad = rs->smp.theta;
    res->spin_final_rad_s = rs->smp.spin;
    res->phi_dot_final_rad_s = rs->smp.phi_dot;
    res->theta_lo_rad = lo;
    res->theta_hi_rad = hi;
    res->margin_J = margin;
    res->end_state_proved = 0;
    return 1;
}
static void run_set_observed(run_state *rs, tippe_dynamics_result *res, const char *why)
{
    res->how = TIPPE_DECIDED_OBSERVED;
    /* near a pole: that pole's verdict; in between: hang (the angle reported) */
    const double th = rs->smp.theta;
    res->verdict = th < PATCH_POLE_RAD          ? TIPPE_VERDICT_NO_TIP
                   : th > M_PI - PATCH_POLE_RAD ? TIPPE_VERDICT_TIP
                                                : TIPPE_VERDICT_HANG;
    res->end_state_proved = 0;
    res->unproved_reason = why;
}

static void run_result_init(tippe_dynamics_result *res)
{
    memset(res, 0, sizeof *res);
    res->verdict = TIPPE_VERDICT_UNDECIDED;
    res->how = TIPPE_DECIDED_T_END;
    res->theta_lo_rad = res->theta_hi_rad = NAN;
    res->barrier_gap_J = res->margin_J = res->Rn_bound_N = NAN;
    res->t_flip = NAN;
    res->t_fall = NAN;
    res->jellett_drift_time_s = NAN;
    res->cap_first_s = res->cap_last_s = NAN;
    res->spin_leaving_rim_rad_s = NAN;
}

int tippe_dynamics_run(const tippe_dynamics_model *model, const tippe_dynamics_initial *ic,
                       const tippe_dynamics_options *opt, tippe_dynamics_result *res,
                       tippe_error *err)
{
    tippe_gsl_errors_as_codes();
    run_result_init(res);
    run_state rs;
    memset(&rs, 0, sizeof rs);
    int status = run_setup(&rs, model, ic, opt, res, err);
    if (status) {
        if (rs.drv)
            gsl_odeiv2_driver_free(rs.drv);
        return status;
    }
    rs.i_sample = 1;
    run_fill_sample(&rs);
    res->end_state_proved = !rs.c.stick_law && !(rs.c.patch && rs.vc.dissipative);
    if (rs.c.patch && rs.vc.dissipative)
        res->unproved_reason = TIPPE_PATCH_UNPROVED_REASON;
    run_try_stick(&rs, res);
    rs.theta_prev = rs.theta_launch = rs.smp.theta;
    rs.theta_dot_prev = rs.smp.theta_dot;
    if (rs.smp.theta < opt->cap_half_angle_rad[0] || M_PI - rs.smp.theta < opt->cap_half_angle_rad[1])
        res->cap_first_s = res->cap_last_s = rs.t; /* launched on a hole's rim */
    res->min_Rn = rs.ct.Rn;
    res->final = rs.smp;
    if (rs.traj)
        status = run_emit(&rs, err);
    if (rs.ct.Rn < 0.0) /* launched already pulling away from the table */
        run_set_lost_contact(&rs, res);
    else if (!status)
        run_try_decide(&rs, res);

    while (!status && !run_may_stop(&rs, res) && rs.t < opt->t_end &&
           res->verdict != TIPPE_VERDICT_LOST_CONTACT) {
        if (opt->max_steps > 0 && (res->steps >= opt->max_steps ||
                                   rs.c.nevals >= BUDGET_EVALS_PER_STEP * opt->max_steps)) {
            res->budget_exhausted = 1;
            break;
        }
        const int lost = run_step(&rs, res, err);
        if (lost < 0) {
            status = -lost;
            break;
        }
        if (lost && res->how == TIPPE_DECIDED_T_END)
            run_set_lost_contact(&rs, res);
        if (rs.traj) {
            const int due = opt->sample_dt <= 0.0 || rs.at_sample || lost;
            if (due)
                status = run_emit(&rs, err);
        }
        if (lost)
            break;
        if (res->how == TIPPE_DECIDED_T_END && !run_try_rolling(&rs, res))
            run_try_decide(&rs, res);
    }

    res->last = rs.smp;
    if (res->how == TIPPE_DECIDED_T_END && res->budget_exhausted)
        res->how = TIPPE_DECIDED_BUDGET;
    if (res->how == TIPPE_DECIDED_T_END || res->how == TIPPE_DECIDED_BUDGET) {
        res->t_verdict = rs.t;
        res->final = rs.smp;
        res->theta_final_rad = rs.smp.theta;
        res->spin_final_rad_s = rs.smp.spin;
        res->phi_dot_final_rad_s = rs.smp.phi_dot;
        res->rolling = rs.c.stick;
        if (res->how == TIPPE_DECIDED_T_END && rs.c.patch && rs.vc.dissipative && !status)
            run_set_observed(&rs, res, TIPPE_PATCH_UNPROVED_REASON);
        else if (res->how == TIPPE_DECIDED_T_END && rs.rim_touched && rs.vc.dissipative &&
                 !status)
            run_set_observed(&rs, res, TIPPE_RIM_UNPROVED_REASON);
    }
    res->jellett_rel_drift = rs.J_abs_err / rs.J_scale;
    const double J_rate = tippe_dynamics_jellett_rate_bound(model);
    if (J_rate > 0.0)
        res->jellett_drift_time_s = fabs(res->J0) / J_rate;
    res->energy_rel_error = rs.energy_abs_err / res->E0;
    res->rim_touched = rs.rim_touched;
    res->rhs_evals = rs.c.nevals;
    res->rejected_steps = (long)rs.drv->e->failed_steps;
    gsl_odeiv2_driver_free(rs.drv);
    return status;
}
