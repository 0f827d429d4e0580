/* A design's tolerances: the block, checked strictly, and the documented
 * defaults (see tippe/design.h and docs/design-format.md). */
#include "design/tolerance_read.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MATERIAL_PREFIX "materials."
#define DENSITY_KEY "density_g_cm3"

typedef struct {
    tippe_tolerance *v;
    int n;
} tol_list;

static tippe_tolerance *find(tol_list *l, const char *field)
{
    for (int i = 0; i < l->n; i++)
        if (!strcmp(l->v[i].field, field))
            return &l->v[i];
    return NULL;
}

/* Adds or replaces the tolerance on field (a later one wins: the block is
 * read after the defaults). */
static void put(tol_list *l, const char *field, double value, double plus_minus, double percent,
                const char *unit, const char *rule)
{
    tippe_tolerance *t = find(l, field);
    if (!t) {
        if (l->n >= TIPPE_TOLERANCE_MAX)
            return;
        t = &l->v[l->n++];
    }
    snprintf(t->field, sizeof t->field, "%s", field);
    t->value = value;
    t->plus_minus = plus_minus;
    t->percent = percent;
    t->unit = unit;
    t->rule = rule;
}

/* The density of material name in d, if some non-void part is made of it. */
static int material_density(const tippe_design *d, const char *name, double *rho)
{
    tippe_design_part_info info;
    for (int i = 0; i < tippe_design_n_parts(d); i++)
        if (tippe_design_part(d, i, &info) == TIPPE_OK && strcmp(info.role, "void") &&
            !strcmp(info.material, name)) {
            *rho = info.density_g_cm3;
            return 1;
        }
    return 0;
}

/* A printed part's infill: weighed, the scale's reading; else the slicer's
 * infill, unless solid (it cannot be denser). */
static void add_print_default(const tippe_design *d, int i, const char *name, tol_list *l)
{
    tippe_design_print_info pi;
    char field[TIPPE_TOLERANCE_FIELD_LEN];
    if (tippe_design_part_print(d, i, &pi) != TIPPE_OK || !pi.printed)
        return;
    if (pi.calibrated) {
        snprintf(field, sizeof field, "parts.%s.print.measured_mass_g", name);
        put(l, field, pi.measured_mass_kg * 1e3, TIPPE_TOL_WEIGHED_G, 0, "g", "scale reading");
        /* a mass says how much, not where (no G-code: the layer model's reading):
         * from all in the sparse infill (0) to all on every line (1) */
        if (!pi.from_gcode && strcmp(pi.model, "skins")) {
            snprintf(field, sizeof field, "parts.%s.print.calibration", name);
            put(l, field, pi.settings.calibration, 1.0, 0, "", "where the weighed mass is");
        }
    } else if (pi.infill < 1) {
        snprintf(field, sizeof field, "parts.%s.print.infill", name);
        put(l, field, pi.infill, pi.infill * TIPPE_TOL_INFILL_PERCENT / 100,
            TIPPE_TOL_INFILL_PERCENT, "", "slicer infill");
    }
    /* the print model's own error against the slicer (TIPPE_PRINT_MODEL_ERROR_*,
     * docs/printing.md): +/-1 of the largest measured, so that a zone hinging on a
     * few thousandths of A/C shows as the knife edge it is. Not for a G-code (the
     * slicer's own part) nor a weighed part (the scale has the mass; the reading
     * of where is the calibration's term) nor the continuous rule (not measured) */
    if (!pi.calibrated && !pi.from_gcode && !strcmp(pi.model, "slicer")) {
        snprintf(field, sizeof field, "parts.%s.print.model_error", name);
        put(l, field, pi.settings.model_error, 1.0, 0, "", "print model vs slicer");
    }
}

/* Whether part i is printed filament: a printable material, or a print block
 * with the density given inline (the mass model and the export print it, as
 * tippe_profile_part_filament says); a void: its part's. */
static int is_filament(const tippe_design *d, int i, const tippe_design_part_info *info)
{
    if (info->printable)
        return 1;
    int k = i;
    if (info->cut_from) {
        tippe_design_part_info q;
        for (k = 0; k < tippe_design_n_parts(d); k++)
            if (tippe_design_part(d, k, &q) == TIPPE_OK && !strcmp(q.name, info->cut_from))
                break;
    }
    tippe_design_print_info pi;
    return tippe_design_part_print(d, k, &pi) == TIPPE_OK && pi.printed;
}

/* The defaults: printed dimensions +/-0.2 mm (parts of filament and the voids
 * cut from them, and the sphere's radius when a printed part forms it); +/-3 %
 * on each filament's density, one error per material (one spool), or per part
 * when its density is inline; +/-2 % on each bought part's mass, through its
 * density. */
static void add_defaults(const tippe_design *d, tol_list *l)
{
    char field[TIPPE_TOLERANCE_FIELD_LEN];
    tippe_design_part_info info;
    for (int i = 0; i < tippe_design_n_parts(d); i++) {
        if (tippe_design_part(d, i, &info) != TIPPE_OK)
            continue;
        int is_void = !strcmp(info.role, "void");
        if (is_filament(d, i, &info)) {
            if (tippe_design_forms_sphere(d, i))
                put(l, "radius_mm", tippe_design_radius_mm(d), TIPPE_TOL_PRINTED_MM, 0, "mm",
                    "printed dimension");
            const char *keys[8];
            int nk = tippe_design_part_lengths(d, i, keys, 8);
            for (int k = 0; k < nk; k++) {
                double v = 0;
                int pi = 0;
                char why[8];
                snprintf(field, sizeof field, "parts.%s.%s", info.name, keys[k]);
                if (tippe_design_field(d, field, &v, &pi, why, sizeof why) == TIPPE_OK &&
                    v > TIPPE_TOL_PRINTED_MM)
                    put(l, field, v, TIPPE_TOL_PRINTED_MM, 0, "mm", "printed dimension");
            }
            if (!is_void) {
                if (info.printable)
                    snprintf(field, sizeof field, MATERIAL_PREFIX "%s." DENSITY_KEY,
                             info.material);
                else
                    snprintf(field, sizeof field, "parts.%s." DENSITY_KEY, info.name);
                put(l, field, info.density_g_cm3,
                    info.density_g_cm3 * TIPPE_TOL_FILAMENT_DENSITY_PERCENT / 100,
                    TIPPE_TOL_FILAMENT_DENSITY_PERCENT, "g/cm^3", "filament density");
            }
            add_print_default(d, i, info.name, l);
        } else if (!is_void) {
            snprintf(field, sizeof field, "parts.%s." DENSITY_KEY, info.name);
            put(l, field, info.density_g_cm3,
                info.density_g_cm3 * TIPPE_TOL_HARDWARE_MASS_PERCENT / 100,
                TIPPE_TOL_HARDWARE_MASS_PERCENT, "g/cm^3", "hardware mass");
        }
    }
}

/* Canonical name and nominal value of a field in the block, or a message. */
static int resolve(const tippe_json_reader *c, const tippe_design *d, const char *key,
                   const char *path, char *canon, size_t cap, double *value, const char **unit)
{
    size_t np = strlen(MATERIAL_PREFIX), nk = strlen(DENSITY_KEY);
    size_t len = strlen(key);
    if (!strncmp(key, MATERIAL_PREFIX, np)) {
        if (len <= np + nk + 1 || strcmp(key + len - nk, DENSITY_KEY) || key[len - nk - 1] != '.')
            return tippe_json_fail(c, path, "a material's tolerance is on its density: "
                                            "materials.NAME." DENSITY_KEY);
        char name[TIPPE_TOLERANCE_FIELD_LEN];
        snprintf(name, sizeof name, "%.*s", (int)(len - np - nk - 1), key + np);
        if (!material_density(d, name, value))
            return tippe_json_fail(c, path, "no part of this design is made of '%s'", name);
        snprintf(canon, cap, "%s", key);
        *unit = "g/cm^3";
        return TIPPE_OK;
    }
    char why[256];
    int part = -1;
    if (tippe_design_field(d, key, value, &part, why, sizeof why) != TIPPE_OK)
        return tippe_json_fail(c, path, "%s", why);
    if (strstr(key, ".print.perimeters") || strstr(key, ".print.top_bottom_layers"))
        return tippe_json_fail(c, path, "a whole number of lines or layers has no tolerance "
                                        "(give one on the infill or on line_width_mm)");
    const char *field = strrchr(key, '.');
    int in_print = strstr(key, ".print.") != NULL;
    tippe_design_part_info info;
    if (part >= 0 && tippe_design_part(d, part, &info) == TIPPE_OK)
        snprintf(canon, cap, "parts.%s%s%s", info.name, in_print ? ".print" : "", field);
    else
        snprintf(canon, cap, "%s", key);
    *unit = strstr(key, DENSITY_KEY)          ? "g/cm^3"
            : strstr(key, "measured_mass_g")  ? "g"
            : strstr(key, ".print.infill") || strstr(key, ".print.model_error") ||
                      strstr(key, ".print.calibration")
                ? ""
                : "mm";
    return TIPPE_OK;
}

/* A +/- value: a number >= 0 in the field's unit, or "N%" with 0 <= N < 100. */
static int read_amount(const tippe_json_reader *c, const cJSON *item, const char *path,
                       double value, const char *unit, double *plus_minus, double *percent)
{
    *percent = 0;
    if (cJSON_IsNumber(item)) {
        *plus_minus = item->valuedouble;
        if (!isfinite(*plus_minus) || *plus_minus < 0)
            return tippe_json_fail(c, path, "must be >= 0 (a +/- value in %s), got %g", unit,
                                   *plus_minus);
    } else if (cJSON_IsString(item)) {
        char *end = NULL;
        double p = strtod(item->valuestring, &end);
        if (end == item->valuestring || strcmp(end, "%") || !isfinite(p))
            return tippe_json_fail(c, path, "'%s' is not a percentage (write e.g. \"3%%\")",
                                   item->valuestring);
        if (p < 0 || p >= 100)
            return tippe_json_fail(c, path, "%g%% is outside 0 .. 100%% (exclusive)", p);
        *percent = p;
        *plus_minus = fabs(value) * p / 100;
    } else {
        return tippe_json_wrong_type(c, path, "a number (+/- in the field's unit) or \"N%\"",
                                     item);
    }
    /* A length or a density moved by its whole value is no longer a part; the
     * print model's error and a weighing's calibration are offsets about 0. */
    if ((strcmp(unit, "mm") || !strstr(path, "z_mm")) && !strstr(path, ".print.model_error") &&
        !strstr(path, ".print.calibration")) {
        if (*plus_minus >= fabs(value))
            return tippe_json_fail(c, path,
                                   "+/-%g %s is not less than the value itself (%g %s)",
                                   *plus_minus, unit, value, unit);
    }
    return TIPPE_OK;
}

/* The patch radius's tolerance: a factor F, a in [a/F, a F] (tippe/design.h). */
static int read_patch_span(const tippe_json_reader *c, const cJSON *item, const char *path,
                           double *span)
{
    if (!cJSON_IsNumber(item))
        return tippe_json_wrong_type(c, path, "a number F (the radius lies in [a/F, a F])",
                                     item);
    const double f = item->valuedouble;
    /* at least 1 %: a narrower span is noise (and --radius-span's bound) */
    if (!(f >= 1.01 && f <= 10.0))
        return tippe_json_fail(c, path, "factor %g is outside 1.01 .. 10 (the radius lies in "
                                        "[a/F, a F]; the default is %g)",
                               f, TIPPE_TOL_PATCH_RADIUS_FACTOR);
    *span = f;
    return TIPPE_OK;
}

int tippe_tolerances_read(const tippe_json_reader *c, const cJSON *block, const tippe_design *d,
                          tippe_tolerance **out, int *n_out, double *patch_radius_span)
{
    *out = NULL;
    *n_out = 0;
    *patch_radius_span = 0.0;
    tol_list l = {calloc(TIPPE_TOLERANCE_MAX, sizeof(tippe_tolerance)), 0};
    if (!l.v)
        return tippe_error_set(c->err, TIPPE_ECOMPUTE, "out of memory");
    add_defaults(d, &l);
    int rc = TIPPE_OK;
    if (block && !cJSON_IsObject(block))
        rc = tippe_json_wrong_type(c, "tolerances",
                                   "an object {\"FIELD\": +/- value, ...} (FIELD as --set "
                                   "names it)",
                                   block);
    for (const cJSON *it = block ? block->child : NULL; it && !rc; it = it->next) {
        char path[TIPPE_TOLERANCE_FIELD_LEN + 20], canon[TIPPE_TOLERANCE_FIELD_LEN];
        snprintf(path, sizeof path, "tolerances[\"%s\"]", it->string);
        if (!strcmp(it->string, TIPPE_TOL_PATCH_RADIUS_KEY)) {
            if ((rc = read_patch_span(c, it, path, patch_radius_span)))
                break;
            continue;
        }
        double value = 0, pm = 0, pct = 0;
        const char *unit = "mm";
        if ((rc = resolve(c, d, it->string, path, canon, sizeof canon, &value, &unit)) ||
            (rc = read_amount(c, it, path, value, unit, &pm, &pct)))
            break;
        if (find(&l, canon) && !strcmp(find(&l, canon)->rule, "tolerances block")) {
            rc = tippe_json_fail(c, path, "the same field as another entry (%s)", canon);
            break;
        }
        if (l.n >= TIPPE_TOLERANCE_MAX && !find(&l, canon)) {
            rc = tippe_json_fail(c, path, "more than %d tolerances", TIPPE_TOLERANCE_MAX);
            break;
        }
        put(&l, canon, value, pm, pct, unit, "tolerances block");
    }
    if (rc) {
        free(l.v);
        return rc;
    }
    /* A zero removes the field (a default the maker does not want). Each band
     * stays inside the range its field loads in (issue 36: an infill of 0.95 +/-
     * 25 % went past 1 and every sweep of the design failed). */
    int k = 0;
    for (int i = 0; i < l.n; i++)
        if (l.v[i].plus_minus > 0) {
            tippe_tolerance *t = &l.v[k++];
            *t = l.v[i];
            double lo, hi;
            tippe_design_field_range(t->field, &lo, &hi);
            t->minus = fmax(0, fmin(t->plus_minus, t->value - lo));
            t->plus = fmax(0, fmin(t->plus_minus, hi - t->value));
        }
    *out = l.v;
    *n_out = k;
    return TIPPE_OK;
}

int tippe_tolerance_overrides(const tippe_design *d, const tippe_tolerance *t, double delta,
                              char (*buf)[TIPPE_TOLERANCE_FIELD_LEN + 40], int cap)
{
    size_t np = strlen(MATERIAL_PREFIX);
    /* %.17g: the override must carry the perturbed value exactly. */
    if (strncmp(t->field, MATERIAL_PREFIX, np)) {
        if (cap < 1)
            return -1;
        snprintf(buf[0], sizeof buf[0], "%s=%.17g", t->field, t->value + delta);
        return 1;
    }
    const char *name = t->field + np;
    size_t len = strlen(name) - strlen(DENSITY_KEY) - 1;
    int n = 0;
    tippe_design_part_info info;
    for (int i = 0; i < tippe_design_n_parts(d); i++) {
        if (tippe_design_part(d, i, &info) != TIPPE_OK || !strcmp(info.role, "void") ||
            strlen(info.material) != len || strncmp(info.material, name, len))
            continue;
        if (n >= cap)
            return -1;
        snprintf(buf[n++], sizeof buf[0], "parts.%s." DENSITY_KEY "=%.17g", info.name,
                 info.density_g_cm3 + delta);
    }
    return n;
}
