/* Reports of launches that several verbs and both front ends give (tippe's
 * --json, tippe serve): the friction law, the accuracy and a launch's options. */
#include "tippe/physics.h"

#include <cjson/cJSON.h>

#include <math.h>
#include <string.h>

void tippe_launch_friction_model(const tippe_launch_options *o, tippe_dynamics_model *m)
{
    memset(m, 0, sizeof *m);
    m->g = o->g;
    m->law = o->law;
    m->mu = o->mu;
    m->mu_c = o->mu_c;
    m->slip_scale_m_s = o->slip_scale_m_s;
    m->patch_radius_m = o->patch_radius_m;
    m->patch_E_star_pa = o->patch_E_star_pa;
}

void tippe_dynamics_friction_json(cJSON *o, const tippe_dynamics_model *m)
{
    if (m->law == TIPPE_FRICTION_VISCOUS)
        cJSON_AddNumberToObject(o, "mu_s_m", m->mu);
    else
        cJSON_AddNullToObject(o, "mu_s_m");
    cJSON *f = cJSON_AddObjectToObject(o, "friction");
    if (!f)
        return;
    cJSON_AddStringToObject(f, "law", tippe_friction_law_name(m->law));
    if (m->law == TIPPE_FRICTION_VISCOUS) {
        cJSON_AddNumberToObject(f, "mu_s_m", m->mu);
        return;
    }
    cJSON_AddNumberToObject(f, "mu", m->mu_c);
    cJSON_AddNumberToObject(f, "slip_scale_m_s", m->slip_scale_m_s > 0
                                                     ? m->slip_scale_m_s
                                                     : TIPPE_COULOMB_SLIP_SCALE_M_S);
    if (m->law == TIPPE_FRICTION_PATCH) {
        /* the radius given, or the contact modulus Hertz's radius comes from (at m g) */
        if (m->patch_radius_m > 0 || !(m->patch_E_star_pa > 0))
            cJSON_AddNumberToObject(f, "patch_mm", m->patch_radius_m * 1e3);
        else
            cJSON_AddNumberToObject(f, "E_star_GPa", m->patch_E_star_pa * 1e-9);
        cJSON_AddStringToObject(f, "pressure", "hertz");
        cJSON_AddNumberToObject(f, "rolling_arm_um", m->rolling_arm_m * 1e6);
    }
}

void tippe_dynamics_accuracy_json(cJSON *o, const char *preset, const tippe_dynamics_accuracy *acc)
{
    cJSON *a = cJSON_AddObjectToObject(o, "accuracy");
    if (a) {
        cJSON_AddStringToObject(a, "preset", preset);
        cJSON_AddStringToObject(a, "stepper", acc->stepper);
        cJSON_AddNumberToObject(a, "rtol", acc->rtol);
    }
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
    tippe_dynamics_accuracy_json(d, o->accuracy_name, &o->accuracy);
    return d;
}
