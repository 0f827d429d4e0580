/* A design's reports shared by every verb that places the weight at one Z2. */
#include "tippe/design.h"

#include <cjson/cJSON.h>

#include <math.h>

void tippe_design_protrusion_json(cJSON *o, const tippe_design_protrusion *p)
{
    const int out = p->protrusion_mm > 0;
    cJSON_AddBoolToObject(o, "model_valid", !out);
    if (!out) {
        cJSON_AddNullToObject(o, "protrusion");
        return;
    }
    cJSON *po = cJSON_AddObjectToObject(o, "protrusion");
    if (!po)
        return;
    cJSON_AddStringToObject(po, "part", p->part);
    cJSON_AddNumberToObject(po, "protrusion_mm", p->protrusion_mm);
    cJSON_AddStringToObject(po, "pole", p->pole > 0 ? "+z" : "-z");
    if (!isfinite(p->theta_from_rad) || !isfinite(p->theta_to_rad)) {
        cJSON_AddNullToObject(po, "theta_range_rad");
        return;
    }
    const double range[2] = {p->theta_from_rad, p->theta_to_rad};
    cJSON_AddItemToObject(po, "theta_range_rad", cJSON_CreateDoubleArray(range, 2));
}

void tippe_design_caps_json(cJSON *o, const tippe_design_cap caps[2])
{
    cJSON *arr = cJSON_AddArrayToObject(o, "polar_caps");
    for (int k = 0; arr && k < 2; k++) {
        if (!(caps[k].half_angle_rad > 0))
            continue;
        cJSON *c = cJSON_CreateObject();
        if (!c || !cJSON_AddItemToArray(arr, c)) {
            cJSON_Delete(c);
            return;
        }
        cJSON_AddStringToObject(c, "pole", caps[k].pole > 0 ? "+z" : "-z");
        cJSON_AddStringToObject(c, "part", caps[k].part);
        cJSON_AddNumberToObject(c, "opening_mm", 2 * caps[k].radius_mm);
        cJSON_AddNumberToObject(c, "half_angle_rad", caps[k].half_angle_rad);
    }
}

cJSON *tippe_materials_json(const tippe_materials *t, const char *file)
{
    cJSON *o = cJSON_CreateObject();
    cJSON *arr = o ? cJSON_AddArrayToObject(o, "materials") : NULL;
    if (!arr || (file && !cJSON_AddStringToObject(o, "file", file))) {
        cJSON_Delete(o);
        return NULL;
    }
    for (int i = 0; i < tippe_materials_count(t); i++) {
        tippe_material m;
        tippe_materials_get(t, i, &m);
        cJSON *e = cJSON_CreateObject();
        if (!e || !cJSON_AddItemToArray(arr, e) || !cJSON_AddStringToObject(e, "name", m.name) ||
            !cJSON_AddNumberToObject(e, "density_g_cm3", m.density_g_cm3) ||
            !cJSON_AddBoolToObject(e, "printable", m.printable) ||
            !cJSON_AddBoolToObject(e, "set_screws", m.set_screws) ||
            !(isfinite(m.E_GPa) ? cJSON_AddNumberToObject(e, "E_GPa", m.E_GPa)
                                : cJSON_AddNullToObject(e, "E_GPa")) ||
            !(isfinite(m.nu) ? cJSON_AddNumberToObject(e, "nu", m.nu)
                             : cJSON_AddNullToObject(e, "nu")) ||
            !cJSON_AddStringToObject(e, "elastic_source", m.elastic_source) ||
            !cJSON_AddStringToObject(e, "source", m.source) ||
            !cJSON_AddStringToObject(e, "notes", m.notes)) {
            cJSON_Delete(o);
            return NULL;
        }
    }
    return o;
}
