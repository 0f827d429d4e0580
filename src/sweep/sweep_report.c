/* The reports both front ends give (tippe's --json and tippe serve's API): a
 * sweep with its bands and printed parts, and a design at one Z2. */
#include "tippe/physics.h"
#include "tippe/profile.h"
#include "tippe/sweep.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

cJSON *tippe_sweep_report_json(const tippe_design *d, const tippe_sweep_result *r,
                               const tippe_sweep_bands_result *b)
{
    cJSON *o = tippe_sweep_json(r, d);
    if (o && (tippe_sweep_json_add_bands(o, d, r, b) || tippe_profile_printed_parts_json(o, d))) {
        cJSON_Delete(o);
        return NULL;
    }
    return o;
}

cJSON *tippe_sweep_eval_json(const tippe_design *d, double z2_mm, const tippe_top *t)
{
    double from, to, cfrom, cto;
    tippe_design_travel_mm(d, &from, &to);
    tippe_design_contact_travel_mm(d, &cfrom, &cto);
    cJSON *o = cJSON_CreateObject();
    if (!o)
        return NULL;
    int ok = cJSON_AddStringToObject(o, "design", tippe_design_name(d)) &&
             cJSON_AddStringToObject(o, "file", tippe_design_path(d)) &&
             cJSON_AddNumberToObject(o, "z2_mm", z2_mm) &&
             cJSON_AddNumberToObject(o, "mass_kg", t->m) &&
             cJSON_AddNumberToObject(o, "moving_mass_kg", tippe_design_moving_mass_kg(d)) &&
             cJSON_AddNumberToObject(o, "R_m", t->R) &&
             cJSON_AddNumberToObject(o, "eps_m", t->eps) &&
             cJSON_AddNumberToObject(o, "eps_over_R", t->eps / t->R) &&
             cJSON_AddNumberToObject(o, "A_kg_m2", t->A) &&
             cJSON_AddNumberToObject(o, "C_kg_m2", t->C) &&
             cJSON_AddNumberToObject(o, "A_over_C", t->A / t->C) &&
             cJSON_AddNumberToObject(o, "com_side", t->com_side);
    tippe_theory_class cls;
    if (ok && tippe_theory_classify(t->A / t->C, t->eps / t->R, &cls) == TIPPE_OK)
        ok = cJSON_AddStringToObject(o, "group", tippe_group_family(cls.group)) &&
             cJSON_AddStringToObject(o, "subgroup", tippe_group_name(cls.group)) &&
             (cls.boundary ? cJSON_AddStringToObject(o, "boundary", cls.boundary)
                           : cJSON_AddNullToObject(o, "boundary")) != NULL;
    double tr[2] = {from, to}, ct[2] = {cfrom, cto};
    cJSON *a1 = cJSON_CreateDoubleArray(tr, 2);
    if (a1 && !cJSON_AddItemToObject(o, "travel_mm", a1)) {
        cJSON_Delete(a1);
        a1 = NULL;
    }
    cJSON *a2 = cJSON_CreateDoubleArray(ct, 2);
    if (a2 && !cJSON_AddItemToObject(o, "physical_travel_mm", a2)) {
        cJSON_Delete(a2);
        a2 = NULL;
    }
    if (!ok || !a1 || !a2) {
        cJSON_Delete(o);
        return NULL;
    }
    cJSON *parts = cJSON_AddArrayToObject(o, "parts");
    int n = tippe_design_n_parts(d);
    for (int i = 0; parts && i < n; i++) {
        tippe_design_part_info p;
        cJSON *po = cJSON_CreateObject();
        if (!po || tippe_design_part(d, i, &p) || !cJSON_AddItemToArray(parts, po)) {
            cJSON_Delete(po);
            ok = 0;
            break;
        }
        ok = cJSON_AddStringToObject(po, "name", p.name) &&
             cJSON_AddStringToObject(po, "shape", p.shape) &&
             cJSON_AddStringToObject(po, "role", p.role) &&
             cJSON_AddStringToObject(po, "material", p.material) &&
             cJSON_AddNumberToObject(po, "density_g_cm3", p.density_g_cm3) &&
             cJSON_AddNumberToObject(po, "mass_kg", p.mass_kg);
        tippe_design_print_info pi;
        ok = ok && !tippe_design_part_print(d, i, &pi) &&
             cJSON_AddBoolToObject(po, "printed", pi.printed);
        if (!ok)
            break;
    }
    tippe_design_protrusion pr;
    tippe_design_protrusion_at(d, z2_mm, &pr);
    tippe_design_protrusion_json(o, &pr);
    tippe_design_cap caps[2];
    tippe_design_polar_caps(d, z2_mm, caps);
    tippe_design_caps_json(o, caps);
    if (!ok || !parts || tippe_profile_printed_parts_json(o, d)) {
        cJSON_Delete(o);
        return NULL;
    }
    return o;
}


cJSON *tippe_sweep_samples_json(const tippe_design *d, double from_mm, double to_mm, int n)
{
    if (n < 2)
        n = 2;
    cJSON *o = cJSON_CreateObject();
    cJSON *z = o ? cJSON_AddArrayToObject(o, "z2_mm") : NULL;
    cJSON *k = o ? cJSON_AddArrayToObject(o, "A_over_C") : NULL;
    cJSON *e = o ? cJSON_AddArrayToObject(o, "eps_over_R_signed") : NULL;
    cJSON *m = o ? cJSON_AddArrayToObject(o, "mass_kg") : NULL;
    if (!z || !k || !e || !m) {
        cJSON_Delete(o);
        return NULL;
    }
    const tippe_sweep_path path = tippe_sweep_design_path(d);
    for (int i = 0; i < n; i++) {
        const double z2 = from_mm + (to_mm - from_mm) * i / (n - 1);
        tippe_top t;
        double A_over_C, signed_e;
        tippe_design_top_any(d, z2, &t);
        path.eval(z2, path.params, &A_over_C, &signed_e);
        if (!cJSON_AddItemToArray(z, cJSON_CreateNumber(z2)) ||
            !cJSON_AddItemToArray(k, cJSON_CreateNumber(A_over_C)) ||
            !cJSON_AddItemToArray(e, cJSON_CreateNumber(signed_e)) ||
            !cJSON_AddItemToArray(m, cJSON_CreateNumber(t.m))) {
            cJSON_Delete(o);
            return NULL;
        }
    }
    return o;
}

/* ---- the zone table as CSV (tippe sweep --csv) ---------------------------- */

/* mm with no "-0" (as the tables print them). */
static double csv_mm(double x) { return fabs(x) < 5e-13 ? 0.0 : x; }

static const char CSV_HEADER[] = "zone,group,family,z2_from_mm,z2_to_mm,width_mm,"
                                 "robust_width_mm,ends_on,within_travel,model_valid";

/* One zone's CSV cells, without a line end. */
static void csv_zone(FILE *out, const tippe_sweep_result *r, const tippe_sweep_bands_result *b,
                     int i)
{
    const tippe_sweep_zone *z = &r->zones[i];
    char ends[160] = "", robust[40] = "";
    for (int k = 0; k < 32; k++) /* the boundaries that end it, "; " between them */
        if (z->to_boundaries & (1u << k)) {
            size_t len = strlen(ends);
            snprintf(ends + len, sizeof ends - len, "%s%s", len ? "; " : "",
                     tippe_sweep_boundary_name((tippe_sweep_boundary)k));
        }
    if (b)
        snprintf(robust, sizeof robust, "%.12g", tippe_sweep_zone_robust_mm(r, b, i));
    double bf[2], bt[2];
    int n_bad = tippe_sweep_zone_model_invalid(r, z, bf, bt);
    const char *valid = !n_bad ? "yes"
                        : (n_bad == 1 && bf[0] <= z->z2_from_mm && bt[0] >= z->z2_to_mm) ? "no"
                                                                                        : "partly";
    fprintf(out, "%d,%s,%s,%.12g,%.12g,%.12g,%s,\"%s\",%s,%s", i + 1, tippe_group_name(z->group),
            tippe_group_family(z->group), csv_mm(z->z2_from_mm), csv_mm(z->z2_to_mm),
            z->z2_to_mm - z->z2_from_mm, robust, ends, z->within_travel ? "yes" : "no", valid);
}

void tippe_sweep_write_csv(FILE *out, const tippe_sweep_result *r,
                           const tippe_sweep_bands_result *b)
{
    fprintf(out, "%s\n", CSV_HEADER);
    for (int i = 0; i < r->n_zones; i++) {
        csv_zone(out, r, b, i);
        fputc('\n', out);
    }
}

void tippe_sweep_vary_write_csv(FILE *out, const tippe_sweep_vary_result *v, const char *field)
{
    fprintf(out, "%s,%s,collision\n", field, CSV_HEADER);
    for (int s = 0; s < v->n; s++) {
        if (v->collision && v->collision[s]) {
            fprintf(out, "%.10g,,,,,,,,,,,\"", v->values[s]);
            for (const char *c = v->collision[s]; *c; c++) { /* a quote doubled */
                if (*c == '"')
                    fputc('"', out);
                fputc(*c, out);
            }
            fputs("\"\n", out);
            continue;
        }
        for (int i = 0; i < v->results[s].n_zones; i++) {
            fprintf(out, "%.10g,", v->values[s]);
            csv_zone(out, &v->results[s], NULL, i);
            fputs(",\n", out);
        }
    }
}
