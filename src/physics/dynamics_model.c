/* The dynamics' model and options: the names of verdicts, decisions and
 * friction laws, the accuracy presets and steppers, whether a model dissipates,
 * and the steady precession a launch starts from. Calls nothing of the run. */
#include "physics/dynamics_state.h"
#include "tippe/base.h"

#include <float.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* The accuracy presets, chosen from the work-precision benchmark
 * (tools/bench/run.sh, docs/performance.md): without a step cap rk8pd is on the
 * best front of every non-stiff scenario at every error measured (1e-2 down), so
 * all three are rk8pd; fast was rkck 1e-6, which rk8pd 1e-6 now beats in cost and
 * error (Figure 12 flip: 4.7e-3 in 1.82 ms against 6.9e-2 in 2.32 ms). */
static const struct {
    const char *name, *stepper;
    double rtol;
} presets[] = {
    {"fast", "rk8pd", 1e-6},
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
    case TIPPE_VERDICT_BOUNDED: return "bounded";
    }
    return "?";
}

const char *tippe_decision_name(tippe_decision d)
{
    switch (d) {
    case TIPPE_DECIDED_T_END: return "t_end";
    case TIPPE_DECIDED_TRAPPED: return "trapped";
    case TIPPE_DECIDED_LOST_CONTACT: return "lost_contact";
    case TIPPE_DECIDED_FLAT_WELL: return "flat_well";
    case TIPPE_DECIDED_BUDGET: return "budget";
    case TIPPE_DECIDED_ROLLING: return "rolling";
    case TIPPE_DECIDED_OBSERVED: return "observed";
    case TIPPE_DECIDED_ENERGY_CONE: return "energy_cone";
    }
    return "?";
}

const char *tippe_friction_law_name(tippe_friction_law law)
{
    switch (law) {
    case TIPPE_FRICTION_VISCOUS: return "viscous";
    case TIPPE_FRICTION_COULOMB: return "coulomb";
    case TIPPE_FRICTION_COULOMB_CREEP: return "coulomb-creep";
    case TIPPE_FRICTION_PATCH: return "patch";
    }
    return "?";
}

int tippe_friction_law_parse(const char *name)
{
    if (!strcmp(name, "viscous"))
        return TIPPE_FRICTION_VISCOUS;
    if (!strcmp(name, "coulomb"))
        return TIPPE_FRICTION_COULOMB;
    if (!strcmp(name, "coulomb-creep"))
        return TIPPE_FRICTION_COULOMB_CREEP;
    if (!strcmp(name, "patch"))
        return TIPPE_FRICTION_PATCH;
    return -1;
}

int tippe_dynamics_frictionless(const tippe_dynamics_model *model)
{
    return model->law == TIPPE_FRICTION_VISCOUS ? !(model->mu > 0.0) : !(model->mu_c > 0.0);
}

double tippe_dynamics_patch_radius(const tippe_dynamics_model *model)
{
    if (model->law != TIPPE_FRICTION_PATCH)
        return 0.0;
    if (model->patch_radius_m > 0.0)
        return model->patch_radius_m;
    double a = 0.0;
    if (model->patch_E_star_pa > 0.0 &&
        tippe_contact_hertz_radius(model->top.R, model->top.m * model->g, model->patch_E_star_pa,
                                   &a, NULL) != TIPPE_OK)
        a = 0.0;
    return a;
}

double tippe_dynamics_jellett_rate_bound(const tippe_dynamics_model *model)
{
    if (model->law != TIPPE_FRICTION_PATCH)
        return 0.0;
    /* m1 = 3 pi / 16, the pure-drilling limit of Hertz's pressure (docs/contact-patch.md) */
    const double m1 = tippe_contact_patch_limits_of(TIPPE_CONTACT_PATCH_HERTZ).m0;
    return m1 * model->mu_c * model->top.m * model->g * tippe_dynamics_patch_radius(model) *
           (model->top.R + model->top.eps);
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

const gsl_odeiv2_step_type *tippe_dynamics_stepper_type(const char *name)
{
    for (int i = 0; i < N_STEPPERS; i++)
        if (!strcmp(name, steppers[i].name))
            return *steppers[i].type;
    return NULL;
}

int tippe_dynamics_stepper_known(const char *name) { return tippe_dynamics_stepper_type(name) != NULL; }

void tippe_dynamics_options_default(tippe_dynamics_options *o)
{
    memset(o, 0, sizeof *o);
    o->level = TIPPE_LEVEL_VERDICT;
    o->t_end = 100.0;
    tippe_dynamics_accuracy_preset("balanced", &o->accuracy, NULL);
    o->sample_dt = 0.0;
    o->margin_factor = 10.0;
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

/* A run's inputs, each refused with what is wrong and its range (TIPPE_EINPUT): the
 * top, g and the friction law's parameters, the launch state, the accuracy, the
 * openings and the margin. */
int tippe_dynamics_check_inputs(const tippe_dynamics_model *model,
                                const tippe_dynamics_initial *ic,
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
    if (model->law != TIPPE_FRICTION_VISCOUS && model->law != TIPPE_FRICTION_COULOMB &&
        model->law != TIPPE_FRICTION_COULOMB_CREEP && model->law != TIPPE_FRICTION_PATCH)
        return tippe_error_set(err, TIPPE_EINPUT, "unknown friction law %d", (int)model->law);
    if (model->law == TIPPE_FRICTION_PATCH) {
        /* a patch larger than the sphere is no patch: a < R/2 keeps Hertz's small-contact
         * assumption within reach, and refuses a nonsensical input at once */
        if (!(model->patch_radius_m >= 0 && model->patch_radius_m <= 0.5 * t->R))
            return tippe_error_set(err, TIPPE_EINPUT,
                                   "patch radius %g m must be in [0, R/2 = %g m]",
                                   model->patch_radius_m, 0.5 * t->R);
        if (!(model->rolling_arm_m >= 0 && model->rolling_arm_m <= 0.1 * t->R))
            return tippe_error_set(err, TIPPE_EINPUT,
                                   "rolling resistance arm %g m must be in [0, R/10 = %g m]",
                                   model->rolling_arm_m, 0.1 * t->R);
        if (!(model->patch_E_star_pa >= 0 && isfinite(model->patch_E_star_pa)))
            return tippe_error_set(err, TIPPE_EINPUT, "contact modulus E* = %g Pa must be >= 0",
                                   model->patch_E_star_pa);
        if (!(tippe_dynamics_patch_radius(model) <= 0.5 * t->R))
            return tippe_error_set(err, TIPPE_EINPUT,
                                   "Hertz patch radius %g m (E* %g Pa, load m g) exceeds R/2 = "
                                   "%g m: the table or ball is too soft for the model",
                                   tippe_dynamics_patch_radius(model), model->patch_E_star_pa,
                                   0.5 * t->R);
    }
    if (model->law != TIPPE_FRICTION_VISCOUS) {
        if (!(model->mu_c >= 0 && model->mu_c <= 1e6))
            return tippe_error_set(err, TIPPE_EINPUT,
                                   "Coulomb friction coefficient mu_c = %g must be in [0, 1e6]",
                                   model->mu_c);
        if (!(model->slip_scale_m_s >= 0 && model->slip_scale_m_s <= 1e3))
            return tippe_error_set(err, TIPPE_EINPUT,
                                   "Coulomb slip scale v_s = %g m/s must be in [0, 1e3] "
                                   "(0: the default %g m/s)",
                                   model->slip_scale_m_s, TIPPE_COULOMB_SLIP_SCALE_M_S);
        if (!(model->creep_cap >= 0 && model->creep_cap <= 1e6))
            return tippe_error_set(err, TIPPE_EINPUT,
                                   "the creep reduction's cap %g must be in [0, 1e6] (0: the "
                                   "full law)", model->creep_cap);
    }
    if (!(ic->theta >= 0 && ic->theta <= M_PI))
        return tippe_error_set(err, TIPPE_EINPUT, "initial theta = %g rad must be in [0, pi]",
                               ic->theta);
    if (!isfinite(ic->theta_dot) || !isfinite(ic->phi_dot) || !isfinite(ic->spin) ||
        !isfinite(ic->U) || !isfinite(ic->V))
        return tippe_error_set(err, TIPPE_EINPUT, "initial state must be finite");
    if (!(opt->t_end > 0 && isfinite(opt->t_end)))
        return tippe_error_set(err, TIPPE_EINPUT, "t_end = %g s must be positive", opt->t_end);
    if (!tippe_dynamics_stepper_type(opt->accuracy.stepper))
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
    const double *cap = opt->cap_half_angle_rad, *rim = t->rim_half_angle_rad;
    if (!(cap[0] >= 0 && cap[0] < 0.5 * M_PI && cap[1] >= 0 && cap[1] < 0.5 * M_PI) ||
        !(rim[0] >= 0 && rim[0] < 0.5 * M_PI && rim[1] >= 0 && rim[1] < 0.5 * M_PI))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "the openings' half-angles (%g, %g rad; top %g, %g rad) must "
                               "be in [0, pi/2)",
                               cap[0], cap[1], rim[0], rim[1]);
    if (!(opt->margin_factor >= 1.0 && opt->margin_factor <= 1e6))
        return tippe_error_set(err, TIPPE_EINPUT, "margin_factor = %g must be in [1, 1e6]",
                               opt->margin_factor);
    return TIPPE_OK;
}
