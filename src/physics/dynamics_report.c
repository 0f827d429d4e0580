/* A model's friction and accuracy as several verbs and both front ends report
 * them (tippe's --json, tippe serve), from the friction laws' table. */
#include "tippe/physics.h"

#include <cjson/cJSON.h>

#include <stdio.h>

const char *tippe_dynamics_friction_text(const tippe_dynamics_model *m, char *buf, size_t size)
{
    const double vs = m->slip_scale_m_s > 0 ? m->slip_scale_m_s : TIPPE_COULOMB_SLIP_SCALE_M_S;
    const tippe_friction_law_type *t = tippe_friction_law_type_of(m->law);
    if (!t) /* as the model's check words it */
        t = tippe_friction_law_type_of(TIPPE_FRICTION_VISCOUS);
    t->describe(m, vs, buf, size);
    return buf;
}

void tippe_dynamics_friction_json(cJSON *o, const tippe_dynamics_model *m)
{
    /* the older top-level key: the viscous coefficient, null under the others */
    if (tippe_friction_law_takes(m->law, TIPPE_LAW_PARAM_MU))
        cJSON_AddNumberToObject(o, "mu_s_m", m->mu);
    else
        cJSON_AddNullToObject(o, "mu_s_m");
    cJSON *f = cJSON_AddObjectToObject(o, "friction");
    const tippe_friction_law_type *t = tippe_friction_law_type_of(m->law);
    if (!f || !t)
        return;
    cJSON_AddStringToObject(f, "law", t->name);
    t->json(f, m);
}

void tippe_dynamics_accuracy_json(cJSON *o, const char *preset, const tippe_dynamics_accuracy *acc,
                                  tippe_friction_law law, double creep_cap)
{
    cJSON *a = cJSON_AddObjectToObject(o, "accuracy");
    if (a) {
        cJSON_AddStringToObject(a, "preset", preset);
        /* the stepper that ran (the patch law's msbdf for the presets' rk8pd, its creep full) */
        cJSON_AddStringToObject(a, "stepper",
                                tippe_dynamics_stepper_used(law, creep_cap, acc->stepper));
        cJSON_AddNumberToObject(a, "rtol", acc->rtol);
    }
}
