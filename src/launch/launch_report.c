/* Reports of launches that several verbs and both front ends give (tippe's
 * --json, tippe serve): a launch's friction model, its slip in words and its
 * options (the model's friction and accuracy: src/physics/dynamics_report.c). */
#include "tippe/launch.h"

#include <cjson/cJSON.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

void tippe_launch_friction_model(const tippe_launch_options *o, tippe_dynamics_model *m)
{
    memset(m, 0, sizeof *m);
    m->g = o->g;
    m->law = o->law;
    m->mu = o->mu;
    m->mu_c = o->mu_c;
    m->slip_scale_m_s = o->slip_scale_m_s;
    m->creep_cap = o->creep_cap;
    m->patch_radius_m = o->patch_radius_m;
    m->patch_E_star_pa = o->patch_E_star_pa;
}

const char *tippe_launch_slip_text(const tippe_top *top, const tippe_dynamics_initial *ic,
                                   double *slip_m_s, char *buf, size_t size)
{
    const double slip = tippe_dynamics_launch_slip(top, ic);
    if (slip_m_s)
        *slip_m_s = slip;
    /* the speeds V_Q is made of (eq 3.7): R |omega| and |v| */
    const double w = fabs(ic->spin) + fabs(ic->phi_dot) + fabs(ic->theta_dot);
    const double v = hypot(ic->U, ic->V);
    const double scale = top->R * w + v;
    const int at_rest = slip <= TIPPE_LAUNCH_SLIP_ROUNDING_REL * scale;
    if (!isfinite(slip))
        snprintf(buf, size, "contact slip unknown");
    else if (v == 0 && at_rest)
        snprintf(buf, size, "no sliding (centre and contact at rest)");
    else if (v == 0)
        snprintf(buf, size, "centre at rest (U = V = 0), contact slip %.3g m/s", slip);
    else if (at_rest)
        snprintf(buf, size, "centre moving at %.3g m/s (U %.3g, V %.3g m/s), no sliding "
                 "(contact at rest)", v, ic->U, ic->V);
    else
        snprintf(buf, size, "centre sliding at %.3g m/s (U %.3g, V %.3g m/s), contact slip "
                 "%.3g m/s", v, ic->U, ic->V, slip);
    return buf;
}

cJSON *tippe_launch_options_json(const tippe_launch_options *o, int fixed_spin)
{
    cJSON *d = cJSON_CreateObject();
    if (!d)
        return NULL;
    if (!fixed_spin) {
        double sp[2] = {2 * M_PI * o->spin_from_rev_s, 2 * M_PI * o->spin_to_rev_s};
        cJSON_AddItemToObject(d, "spin_uniform_rad_s", cJSON_CreateDoubleArray(sp, 2));
    }
    cJSON_AddNumberToObject(d, "tilt_half_normal_scale_rad", o->tilt_sd_rad);
    cJSON_AddNumberToObject(d, "tilt_max_rad", o->tilt_max_rad);
    cJSON_AddNumberToObject(d, "precession_rel_sd", o->precession_sd_rel);
    cJSON_AddNumberToObject(d, "slide_half_normal_scale_m_s", o->slide_sd_m_s);
    tippe_dynamics_model m;
    tippe_launch_friction_model(o, &m);
    tippe_dynamics_friction_json(d, &m);
    cJSON_AddNumberToObject(d, "g_m_s2", o->g);
    cJSON_AddNumberToObject(d, "t_end_s", o->t_end);
    tippe_dynamics_accuracy_json(d, o->accuracy_name, &o->accuracy, o->law, o->creep_cap);
    return d;
}
