/* Scenario files for `tippe simulate`: strict JSON reading, command-line
 * overrides, validation, and the launch they describe (docs/dynamics.md). */
#include "tippe/scenario.h"

#include "tippe/design.h"
#include "base/json.h"
#include "tippe/launch.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_SCENARIO_MIB 1
#define MAX_OVERRIDES 64
#define MAX_DESIGN_SETS 64
/* The longest FIELD an override may name. */
#define MAX_FIELD_LEN 127

static const char *const top_level_keys[] = {"name", "notes", "top", "g", "mu", "friction",
                                              "initial", "t_end", "accuracy", NULL};
static const char *const friction_keys[] = {"law", "mu_s_m", "mu", "slip_scale_m_s",
                                            "patch_mm", "table", "rolling_arm_um",
                                            "creep_cap", NULL};
static const char *const top_explicit_keys[] = {"m", "R", "eps", "A", "C", NULL};
static const char *const top_design_keys[] = {"design", "z2_mm", "set", NULL};
static const char *const top_all_keys[] = {"m", "R", "eps", "A", "C", "design", "z2_mm",
                                           "set", NULL};
static const char *const initial_keys[] = {"theta", "theta_dot", "phi_dot", "spin", "U", "V",
                                           NULL};
static const char *const accuracy_keys[] = {"stepper", "rtol", NULL};

/* ---- overrides ---- */

/* A friction block of the viscous law: "law": "viscous", or no law and "mu_s_m". */
static int viscous_block(const cJSON *f)
{
    const cJSON *law = cJSON_GetObjectItemCaseSensitive(f, "law");
    if (cJSON_IsString(law))
        return !strcmp(law->valuestring, "viscous");
    return cJSON_GetObjectItemCaseSensitive(f, "mu_s_m") != NULL;
}

/* The friction is described once: a later override replaces what the file (or an
 * earlier override) said. "mu" (viscous, s/m) drops a friction block, and a Coulomb
 * field (friction.mu, friction.slip_scale_m_s) replaces a viscous friction by
 * {"law": "coulomb"}: a coefficient names its law. Another field of the block turns
 * a top-level mu into {"law": "viscous", "mu_s_m": mu} first; and a new friction.law
 * drops the other law's coefficients. */
static int friction_before(cJSON *root, const char *field)
{
    if (!strcmp(field, "mu")) {
        cJSON_DeleteItemFromObjectCaseSensitive(root, "friction");
        return TIPPE_OK;
    }
    if (strncmp(field, "friction.", 9) != 0)
        return TIPPE_OK;
    cJSON *mu = cJSON_GetObjectItemCaseSensitive(root, "mu");
    cJSON *fr = cJSON_GetObjectItemCaseSensitive(root, "friction");
    if ((!strcmp(field, "friction.mu") || !strcmp(field, "friction.slip_scale_m_s")) &&
        (fr ? cJSON_IsObject(fr) && viscous_block(fr) : mu != NULL)) {
        /* (a file with both mu and a block stays refused: "not both") */
        cJSON_DeleteItemFromObjectCaseSensitive(root, fr ? "friction" : "mu");
        cJSON *f = cJSON_AddObjectToObject(root, "friction");
        return f && cJSON_AddStringToObject(f, "law", "coulomb") ? TIPPE_OK : TIPPE_ECOMPUTE;
    }
    if ((!strcmp(field, "friction.patch_mm") || !strcmp(field, "friction.table")) &&
        !(fr && cJSON_IsObject(fr) &&
          cJSON_IsString(cJSON_GetObjectItemCaseSensitive(fr, "law")) &&
          !strcmp(cJSON_GetObjectItemCaseSensitive(fr, "law")->valuestring, "patch"))) {
        /* the patch's radius names its law; a Coulomb block's mu carries over */
        double mu_c = TIPPE_LAUNCH_DEFAULT_MU_C;
        const cJSON *old = fr && cJSON_IsObject(fr) && !viscous_block(fr)
                               ? cJSON_GetObjectItemCaseSensitive(fr, "mu")
                               : NULL;
        if (cJSON_IsNumber(old))
            mu_c = old->valuedouble;
        if (fr || mu)
            cJSON_DeleteItemFromObjectCaseSensitive(root, fr ? "friction" : "mu");
        cJSON *f = cJSON_AddObjectToObject(root, "friction");
        return f && cJSON_AddStringToObject(f, "law", "patch") && cJSON_AddNumberToObject(f, "mu", mu_c)
                   ? TIPPE_OK
                   : TIPPE_ECOMPUTE;
    }
    if (!mu || cJSON_GetObjectItemCaseSensitive(root, "friction"))
        return TIPPE_OK;
    cJSON *f = cJSON_CreateObject();
    cJSON *m = cJSON_DetachItemViaPointer(root, mu);
    if (!f || !cJSON_AddStringToObject(f, "law", "viscous")) {
        cJSON_Delete(f);
        cJSON_Delete(m);
        return TIPPE_ECOMPUTE;
    }
    cJSON_AddItemToObject(f, "mu_s_m", m);
    cJSON_AddItemToObject(root, "friction", f);
    return TIPPE_OK;
}

static void friction_after(cJSON *root, const char *field)
{
    cJSON *f = cJSON_GetObjectItemCaseSensitive(root, "friction");
    /* the patch's radius is given or derived: the later of the two wins */
    if (!strcmp(field, "friction.patch_mm"))
        cJSON_DeleteItemFromObjectCaseSensitive(f, "table");
    if (!strcmp(field, "friction.table"))
        cJSON_DeleteItemFromObjectCaseSensitive(f, "patch_mm");
    if (strcmp(field, "friction.law") != 0)
        return;
    const cJSON *law = cJSON_GetObjectItemCaseSensitive(f, "law");
    if (!cJSON_IsString(law))
        return;
    if (!strcmp(law->valuestring, "viscous")) {
        cJSON_DeleteItemFromObjectCaseSensitive(f, "mu");
        cJSON_DeleteItemFromObjectCaseSensitive(f, "slip_scale_m_s");
    } else {
        cJSON_DeleteItemFromObjectCaseSensitive(f, "mu_s_m");
    }
    if (strcmp(law->valuestring, "patch") != 0) {
        cJSON_DeleteItemFromObjectCaseSensitive(f, "patch_mm");
        cJSON_DeleteItemFromObjectCaseSensitive(f, "table");
    }
}

static int apply_override_raw(tippe_json_reader *c, cJSON *root, const char *text);

static int apply_override(tippe_json_reader *c, cJSON *root, const char *text)
{
    const char *eq = strchr(text, '=');
    char field[MAX_FIELD_LEN + 1] = "";
    if (eq && (size_t)(eq - text) <= MAX_FIELD_LEN) {
        memcpy(field, text, (size_t)(eq - text));
        field[eq - text] = '\0';
    }
    if (friction_before(root, field))
        return tippe_error_set(c->err, TIPPE_ECOMPUTE, "out of memory");
    int rc = apply_override_raw(c, root, text);
    if (!rc)
        friction_after(root, field);
    return rc;
}

static int apply_override_raw(tippe_json_reader *c, cJSON *root, const char *text)
{
    const char *eq = strchr(text, '=');
    if (!eq || eq == text)
        return tippe_error_set(c->err, TIPPE_EINPUT,
                               "%s: override '%s': expected FIELD=VALUE, e.g. initial.spin=3",
                               c->file, text);
    size_t flen = (size_t)(eq - text);
    if (flen > MAX_FIELD_LEN)
        return tippe_error_set(c->err, TIPPE_EINPUT, "%s: override '%s': field name too long",
                               c->file, text);
    char field[MAX_FIELD_LEN + 1];
    memcpy(field, text, flen);
    field[flen] = '\0';
    /* Noted before it is applied: a failure applying it is its fault too. */
    tippe_json_note_set(c, field, text);

    /* Walk to the parent object, creating objects that are missing. A preset
     * name under "accuracy" is expanded so that accuracy.rtol can refine it. */
    cJSON *obj = root;
    char *key = field;
    for (char *dot; (dot = strchr(key, '.'));) {
        *dot = '\0';
        cJSON *next = cJSON_GetObjectItemCaseSensitive(obj, key);
        if (next && cJSON_IsString(next) && obj == root && !strcmp(key, "accuracy")) {
            tippe_dynamics_accuracy a;
            if (tippe_dynamics_accuracy_preset(next->valuestring, &a, NULL))
                return tippe_json_fail(c, "accuracy",
                                       "unknown preset '%s' (fast, balanced, precise)",
                                       next->valuestring);
            cJSON *o = cJSON_CreateObject();
            if (!o || !cJSON_AddStringToObject(o, "stepper", a.stepper) ||
                !cJSON_AddNumberToObject(o, "rtol", a.rtol)) {
                cJSON_Delete(o);
                return tippe_error_set(c->err, TIPPE_ECOMPUTE, "out of memory");
            }
            cJSON_ReplaceItemInObjectCaseSensitive(obj, key, o);
            next = o;
        }
        if (!next) {
            next = cJSON_AddObjectToObject(obj, key);
            if (!next)
                return tippe_error_set(c->err, TIPPE_ECOMPUTE, "out of memory");
        }
        if (!cJSON_IsObject(next)) {
            *dot = '.';
            return tippe_error_set(c->err, TIPPE_EINPUT,
                                   "%s: override '%s': '%.*s' is %s, not an object", c->file, text,
                                   (int)(dot - field), field, tippe_json_kind(next));
        }
        obj = next;
        key = dot + 1;
        *dot = '.'; /* field stays whole for messages; key ends at the next '\0' */
    }
    if (!key[0])
        return tippe_error_set(c->err, TIPPE_EINPUT, "%s: override '%s': empty field name",
                               c->file, text);
    const char *value = eq + 1;
    const char *end = NULL;
    cJSON *item = cJSON_ParseWithOpts(value, &end, 1);
    if (!item)
        item = cJSON_CreateString(value); /* not JSON: a word such as steady or precise */
    if (!item)
        return tippe_error_set(c->err, TIPPE_ECOMPUTE, "out of memory");
    return tippe_json_put(c, obj, key, item);
}

/* ---- the parts of a scenario ---- */

/* The numbers a scenario may hold: wide enough for every top and launch the
 * model describes (a 1 mm bead to a 1 km ball), narrow enough that no product
 * of them in the equations of motion overflows or underflows a double. */
#define TOP_M_MIN_KG 1e-9
#define TOP_M_MAX_KG 1e9
#define TOP_R_MIN_M 1e-6
#define TOP_R_MAX_M 1e3
#define TOP_I_MIN_KG_M2 1e-30
#define TOP_I_MAX_KG_M2 1e15
#define RATE_MAX_RAD_S 1e6
#define SPEED_MAX_M_S 1e4
#define T_END_MAX_S 1e8
#define G_MAX_M_S2 1e6
#define MU_MAX_S_M 1e9
#define MU_C_MAX 10
#define SLIP_SCALE_MIN_M_S 1e-9
#define SLIP_SCALE_MAX_M_S 1

/* TIPPE_OK if lo <= x <= hi, else the message naming path and the range. */
static int check_range(tippe_json_reader *c, const char *path, double x, double lo, double hi,
                       const char *unit)
{
    if (x >= lo && x <= hi)
        return TIPPE_OK;
    return tippe_json_fail(c, path, "%g %s is outside the allowed %g .. %g %s", x, unit, lo, hi,
                           unit);
}

/* top as {m, R, eps, A, C} in SI units, each checked. */
static int read_explicit_top(tippe_json_reader *c, const cJSON *top, tippe_scenario *s)
{
    tippe_top *t = &s->model.top;
    int rc;
    if ((rc = tippe_json_check_keys(c, top, "top", NULL, top_explicit_keys, NULL)))
        return rc;
    if ((rc = tippe_json_number(c, top, "top", "m", 1, &t->m, NULL)) ||
        (rc = tippe_json_number(c, top, "top", "R", 1, &t->R, NULL)) ||
        (rc = tippe_json_number(c, top, "top", "eps", 1, &t->eps, NULL)) ||
        (rc = tippe_json_number(c, top, "top", "A", 1, &t->A, NULL)) ||
        (rc = tippe_json_number(c, top, "top", "C", 1, &t->C, NULL)))
        return rc;
    if ((rc = check_range(c, "top.m", t->m, TOP_M_MIN_KG, TOP_M_MAX_KG, "kg")) ||
        (rc = check_range(c, "top.R", t->R, TOP_R_MIN_M, TOP_R_MAX_M, "m")) ||
        (rc = check_range(c, "top.A", t->A, TOP_I_MIN_KG_M2, TOP_I_MAX_KG_M2, "kg m^2")) ||
        (rc = check_range(c, "top.C", t->C, TOP_I_MIN_KG_M2, TOP_I_MAX_KG_M2, "kg m^2")))
        return rc;
    if (!(t->eps >= 0 && t->eps < t->R))
        return tippe_json_fail(c, "top.eps", "must satisfy 0 <= eps < R = %g m, got %g", t->R,
                               t->eps);
    if (!(t->A > 0))
        return tippe_json_fail(c, "top.A", "must be > 0 kg m^2, got %g", t->A);
    if (!(t->C > 0))
        return tippe_json_fail(c, "top.C", "must be > 0 kg m^2, got %g", t->C);
    /* A rigid body of revolution has A >= C/2 about its centre of mass
     * (A = int (r^2/2 + z^2) dm, C = int r^2 dm). */
    if (t->A < 0.5 * t->C * (1 - 1e-12))
        return tippe_json_fail(c, "top.A",
                               "A = %g kg m^2 < C/2 = %g: no rigid body has these moments", t->A,
                               0.5 * t->C);
    t->com_side = t->eps > 0 ? -1 : 0;
    s->design_path[0] = '\0';
    s->z2_mm = NAN;
    memset(&s->protrusion, 0, sizeof s->protrusion);
    s->cap_half_angle_rad[0] = s->cap_half_angle_rad[1] = 0;
    return TIPPE_OK;
}

/* top.set: the design's "FIELD=VALUE" overrides, pointing into the JSON. */
static int read_design_sets(tippe_json_reader *c, const cJSON *top, const char **sets,
                            int *n_sets)
{
    *n_sets = 0;
    const cJSON *set = cJSON_GetObjectItemCaseSensitive(top, "set");
    if (!set)
        return TIPPE_OK;
    if (!cJSON_IsArray(set))
        return tippe_json_wrong_type(c, "top.set", "an array of \"FIELD=VALUE\" strings", set);
    int i = 0;
    for (const cJSON *it = set->child; it; it = it->next, i++) {
        char sub[64];
        snprintf(sub, sizeof sub, "top.set[%d]", i);
        if (!cJSON_IsString(it))
            return tippe_json_wrong_type(c, sub, "a \"FIELD=VALUE\" string", it);
        if (*n_sets == MAX_DESIGN_SETS)
            return tippe_json_fail(c, "top.set", "more than %d overrides", MAX_DESIGN_SETS);
        sets[(*n_sets)++] = it->valuestring;
    }
    return TIPPE_OK;
}

/* top as {design, z2_mm, set}: the design file (relative to the scenario's
 * directory), loaded with its overrides (from design_text when the caller has
 * read that file already, else from the file) and kept in s->design, and its
 * top with the weight at z2_mm. */
static int read_design_top(tippe_json_reader *c, const cJSON *top, const cJSON *design,
                           tippe_scenario *s, const char *design_text, size_t design_len)
{
    int rc;
    if ((rc = tippe_json_check_keys(c, top, "top", NULL, top_design_keys, NULL)))
        return rc;
    if (!cJSON_IsString(design) || !design->valuestring[0])
        return tippe_json_wrong_type(c, "top.design", "a file name", design);
    if ((rc = tippe_json_number(c, top, "top", "z2_mm", 1, &s->z2_mm, NULL)))
        return rc;
    if (design->valuestring[0] == '/') {
        snprintf(s->design_path, sizeof s->design_path, "%s", design->valuestring);
    } else {
        char dir[1024];
        tippe_path_dir(c->file, dir, sizeof dir);
        if (snprintf(s->design_path, sizeof s->design_path, "%s/%s", dir, design->valuestring) >=
            (int)sizeof s->design_path)
            return tippe_json_fail(c, "top.design", "path too long");
    }
    const char *sets[MAX_DESIGN_SETS];
    int n_sets;
    if ((rc = read_design_sets(c, top, sets, &n_sets)))
        return rc;
    tippe_design *d = NULL;
    tippe_error derr;
    rc = design_text ? tippe_design_load_read(s->design_path, design_text, design_len, sets,
                                              n_sets, &d, &derr)
                     : tippe_design_load(s->design_path, sets, n_sets, &d, &derr);
    if (rc)
        return rc == TIPPE_EINPUT ? tippe_json_fail(c, "top.design", "%s", derr.msg)
                                  : tippe_error_set(c->err, rc, "%s", derr.msg);
    rc = tippe_design_top(d, s->z2_mm, &s->model.top, &derr);
    tippe_design_protrusion_at(d, s->z2_mm, &s->protrusion);
    if (!rc)
        tippe_launch_polar_caps(d, s->z2_mm, &s->model.top, s->cap_half_angle_rad);
    const char *mat = "";
    if (!tippe_design_ball_elastic(d, &s->ball_E_pa, &s->ball_nu, &mat))
        s->ball_E_pa = s->ball_nu = 0.0;
    snprintf(s->ball_material, sizeof s->ball_material, "%s", mat);
    s->design = d;
    if (rc)
        return rc == TIPPE_EINPUT ? tippe_json_fail(c, "top.z2_mm", "%s", derr.msg)
                                  : tippe_error_set(c->err, rc, "%s", derr.msg);
    return TIPPE_OK;
}

static int read_top(tippe_json_reader *c, const cJSON *top, tippe_scenario *s,
                    const char *design_text, size_t design_len)
{
    if (!top)
        return tippe_json_fail(c, "top",
                               "missing: give {\"m\", \"R\", \"eps\", \"A\", \"C\"} in SI units "
                               "or {\"design\": FILE, \"z2_mm\": MM}");
    if (!cJSON_IsObject(top))
        return tippe_json_wrong_type(c, "top", "an object", top);
    int rc = tippe_json_check_keys(c, top, "top", NULL, top_all_keys, NULL);
    if (rc)
        return rc;
    const cJSON *design = cJSON_GetObjectItemCaseSensitive(top, "design");
    int any_explicit = 0;
    for (const char *const *k = top_explicit_keys; *k; k++)
        any_explicit |= cJSON_GetObjectItemCaseSensitive(top, *k) != NULL;
    if (design && any_explicit)
        return tippe_json_fail(c, "top",
                               "give either a design (design, z2_mm) or the explicit top "
                               "(m, R, eps, A, C), not both");
    return design ? read_design_top(c, top, design, s, design_text, design_len)
                  : read_explicit_top(c, top, s);
}

/* The patch law's radius: "patch_mm" given, or Hertz's at m g from the design ball's
 * material (the materials table's E_GPa, nu) on "table" (default laminate). */
static int read_patch(tippe_json_reader *c, const cJSON *f, tippe_scenario *s)
{
    tippe_dynamics_model *m = &s->model;
    const cJSON *pm = cJSON_GetObjectItemCaseSensitive(f, "patch_mm");
    const cJSON *tb = cJSON_GetObjectItemCaseSensitive(f, "table");
    const cJSON *ra = cJSON_GetObjectItemCaseSensitive(f, "rolling_arm_um");
    const cJSON *cc = cJSON_GetObjectItemCaseSensitive(f, "creep_cap");
    int rc;
    if (!tippe_friction_law_type_of(m->law)->patch) {
        if (pm || tb || ra || cc)
            return tippe_json_fail(c, pm   ? "friction.patch_mm"
                                      : tb ? "friction.table"
                                      : ra ? "friction.rolling_arm_um"
                                           : "friction.creep_cap",
                                   "belongs to the patch law (\"law\": \"patch\")");
        return TIPPE_OK;
    }
    /* the creep reduced by default, as the command's --creep-cap; 0 the full law */
    m->creep_cap = TIPPE_PATCH_CREEP_CAP;
    if (cc && ((rc = tippe_json_number(c, f, "friction", "creep_cap", 1, &m->creep_cap, NULL)) ||
               (rc = check_range(c, "friction.creep_cap", m->creep_cap, 0, 1e4,
                                 "(dimensionless; 0: the full law)"))))
        return rc;
    if (ra) {
        double um = 0.0;
        if ((rc = tippe_json_number(c, f, "friction", "rolling_arm_um", 1, &um, NULL)) ||
            (rc = check_range(c, "friction.rolling_arm_um", um, 0, 1000, "um")))
            return rc;
        m->rolling_arm_m = um * 1e-6;
    }
    if (pm && tb)
        return tippe_json_fail(c, "friction.patch_mm",
                               "gives the radius that \"table\" derives: give one");
    if (pm) {
        double mm = 0.0;
        if ((rc = tippe_json_number(c, f, "friction", "patch_mm", 1, &mm, NULL)) ||
            (rc = check_range(c, "friction.patch_mm", mm, 0, 10, "mm")))
            return rc;
        m->patch_radius_m = mm * 1e-3;
        return TIPPE_OK;
    }
    const char *table = TIPPE_CONTACT_DEFAULT_TABLE;
    if (tb) {
        if (!cJSON_IsString(tb))
            return tippe_json_wrong_type(c, "friction.table", "a surface name", tb);
        table = tb->valuestring;
    }
    double Et, nut;
    if (tippe_contact_table_surface(table, &Et, &nut))
        return tippe_json_fail(c, "friction.table",
                               "unknown surface '%s' (" TIPPE_CONTACT_TABLES ")", table);
    if (!(s->ball_E_pa > 0))
        return tippe_json_fail(c, tb ? "friction.table" : "friction.patch_mm",
                               "%s: the Hertz patch needs the ball's E and nu%s%s%s; give "
                               "\"patch_mm\"",
                               tb ? "cannot derive the radius" : "missing",
                               s->design_path[0] ? " (material '" : " (an explicit top has no "
                                                                     "material)",
                               s->design_path[0] ? s->ball_material : "",
                               s->design_path[0] ? "' has none in the materials table)" : "");
    if (tippe_contact_hertz_modulus(s->ball_E_pa, s->ball_nu, Et, nut, &m->patch_E_star_pa,
                                    c->err))
        return TIPPE_EINPUT;
    return TIPPE_OK;
}

/* The friction: the top-level "mu" (viscous, s/m: the paper's eq 3.12, as every
 * scenario before issue 21 gave it), or a block {"law": "viscous", "mu_s_m": X} or
 * {"law": "coulomb" | "coulomb-creep", "mu": X, "slip_scale_m_s": V}. Without a law
 * the coefficient names it; a missing coefficient is the launch default. */
static int read_friction(tippe_json_reader *c, const cJSON *root, tippe_scenario *s)
{
    tippe_dynamics_model *m = &s->model;
    const cJSON *mu = cJSON_GetObjectItemCaseSensitive(root, "mu");
    const cJSON *f = cJSON_GetObjectItemCaseSensitive(root, "friction");
    int rc;
    m->law = tippe_friction_law_at(0)->law; /* the paper's viscous law */
    m->mu_c = 0.0;
    m->slip_scale_m_s = 0.0;
    if (mu && f)
        return tippe_json_fail(c, "friction",
                               "give either \"mu\" (viscous, s/m) or a \"friction\" block, "
                               "not both");
    if (!mu && !f)
        return tippe_json_fail(c, "friction",
                               "missing: give {\"law\": \"coulomb\", \"mu\": 0.3} or "
                               "{\"law\": \"viscous\", \"mu_s_m\": S_M} (or \"mu\": S_M)");
    if (mu) {
        if ((rc = tippe_json_number(c, root, "", "mu", 1, &m->mu, NULL)))
            return rc;
        if (!(m->mu >= 0))
            return tippe_json_fail(c, "mu", "friction coefficient must be >= 0 s/m, got %g",
                                   m->mu);
        return check_range(c, "mu", m->mu, 0, MU_MAX_S_M, "s/m");
    }
    if (!cJSON_IsObject(f))
        return tippe_json_wrong_type(c, "friction", "an object", f);
    if ((rc = tippe_json_check_keys(c, f, "friction", NULL, friction_keys, NULL)))
        return rc;
    const cJSON *law = cJSON_GetObjectItemCaseSensitive(f, "law");
    const int has_viscous = cJSON_GetObjectItemCaseSensitive(f, "mu_s_m") != NULL;
    /* A block names its law, or a coefficient names it: an empty block says
     * nothing, as a missing one (refused above) says nothing. */
    char list[128];
    tippe_friction_law_list(", ", list, sizeof list);
    if (!law && !has_viscous && !cJSON_GetObjectItemCaseSensitive(f, "mu") &&
        !cJSON_GetObjectItemCaseSensitive(f, "slip_scale_m_s"))
        return tippe_json_fail(c, "friction.law",
                               "missing: the block names no law; give {\"law\": \"coulomb\", "
                               "\"mu\": 0.3} or {\"law\": \"viscous\", \"mu_s_m\": S_M} "
                               "(laws: %s)", list);
    /* without a law, the coefficient's: mu_s_m the viscous law's, mu Coulomb's */
    const tippe_friction_law_type *l =
        tippe_friction_law_named_by(has_viscous ? TIPPE_LAW_PARAM_MU : TIPPE_LAW_PARAM_MU_C);
    if (law) {
        if (!cJSON_IsString(law))
            return tippe_json_wrong_type(c, "friction.law", "a law name", law);
        if (!(l = tippe_friction_law_find(law->valuestring)))
            return tippe_json_fail(c, "friction.law", "unknown law '%s' (%s)", law->valuestring,
                                   list);
    }
    m->law = l->law;
    if (tippe_friction_law_takes(l->law, TIPPE_LAW_PARAM_MU)) {
        if (cJSON_GetObjectItemCaseSensitive(f, "mu"))
            return tippe_json_fail(c, "friction.mu",
                                   "is the Coulomb coefficient: the viscous law takes mu_s_m "
                                   "(s/m)");
        if (cJSON_GetObjectItemCaseSensitive(f, "slip_scale_m_s"))
            return tippe_json_fail(c, "friction.slip_scale_m_s",
                                   "belongs to the Coulomb laws, not the viscous one");
        if ((rc = read_patch(c, f, s)))
            return rc;
        m->mu = TIPPE_LAUNCH_DEFAULT_MU_S_M;
        if ((rc = tippe_json_number(c, f, "friction", "mu_s_m", 0, &m->mu, NULL)))
            return rc;
        return check_range(c, "friction.mu_s_m", m->mu, 0, MU_MAX_S_M, "s/m");
    }
    if (has_viscous)
        return tippe_json_fail(c, "friction.mu_s_m",
                               "is the viscous coefficient (s/m): the %s law takes mu",
                               tippe_friction_law_name(m->law));
    m->mu = 0.0;
    m->mu_c = TIPPE_LAUNCH_DEFAULT_MU_C;
    m->slip_scale_m_s = TIPPE_COULOMB_SLIP_SCALE_M_S;
    if ((rc = tippe_json_number(c, f, "friction", "mu", 0, &m->mu_c, NULL)) ||
        (rc = check_range(c, "friction.mu", m->mu_c, 0, MU_C_MAX, "(dimensionless)")) ||
        (rc = tippe_json_number(c, f, "friction", "slip_scale_m_s", 0, &m->slip_scale_m_s,
                                NULL)) ||
        (rc = check_range(c, "friction.slip_scale_m_s", m->slip_scale_m_s, SLIP_SCALE_MIN_M_S,
                          SLIP_SCALE_MAX_M_S, "m/s")))
        return rc;
    return read_patch(c, f, s);
}

static int read_accuracy(tippe_json_reader *c, const cJSON *acc, tippe_scenario *s)
{
    if (!acc) {
        tippe_dynamics_accuracy_preset("balanced", &s->accuracy, NULL);
        snprintf(s->accuracy_name, sizeof s->accuracy_name, "balanced");
        return TIPPE_OK;
    }
    if (cJSON_IsString(acc)) {
        if (tippe_dynamics_accuracy_preset(acc->valuestring, &s->accuracy, NULL))
            return tippe_json_fail(c, "accuracy",
                                   "unknown preset '%s' (fast, balanced, precise, or "
                                   "{\"stepper\": NAME, \"rtol\": NUMBER})",
                                   acc->valuestring);
        snprintf(s->accuracy_name, sizeof s->accuracy_name, "%s", acc->valuestring);
        return TIPPE_OK;
    }
    if (!cJSON_IsObject(acc))
        return tippe_json_wrong_type(c, "accuracy", "a preset name or an object", acc);
    int rc = tippe_json_check_keys(c, acc, "accuracy", NULL, accuracy_keys, NULL);
    if (rc)
        return rc;
    const cJSON *st = cJSON_GetObjectItemCaseSensitive(acc, "stepper");
    if (!cJSON_IsString(st))
        return tippe_json_wrong_type(c, "accuracy.stepper", "a stepper name", st);
    if (!tippe_dynamics_stepper_known(st->valuestring))
        return tippe_json_fail(
            c, "accuracy.stepper",
            "unknown stepper '%s' (rk2, rk4, rkf45, rkck, rk8pd, rk1imp, rk2imp, "
            "rk4imp, bsimp, msadams, msbdf)",
            st->valuestring);
    snprintf(s->accuracy.stepper, sizeof s->accuracy.stepper, "%s", st->valuestring);
    if ((rc = tippe_json_number(c, acc, "accuracy", "rtol", 1, &s->accuracy.rtol, NULL)))
        return rc;
    if (!(s->accuracy.rtol >= 1e-14 && s->accuracy.rtol <= 1e-2))
        return tippe_json_fail(c, "accuracy.rtol", "must be in [1e-14, 1e-2], got %g",
                               s->accuracy.rtol);
    snprintf(s->accuracy_name, sizeof s->accuracy_name, "custom");
    return TIPPE_OK;
}

static int read_initial(tippe_json_reader *c, const cJSON *ini, tippe_scenario *s)
{
    if (!ini)
        return tippe_json_fail(c, "initial",
                               "missing: give at least {\"theta\": RAD, \"spin\": RAD_S}");
    if (!cJSON_IsObject(ini))
        return tippe_json_wrong_type(c, "initial", "an object", ini);
    int rc = tippe_json_check_keys(c, ini, "initial", NULL, initial_keys, NULL);
    if (rc)
        return rc;
    tippe_dynamics_initial *ic = &s->initial;
    if ((rc = tippe_json_number(c, ini, "initial", "theta", 1, &ic->theta, NULL)) ||
        (rc = tippe_json_number(c, ini, "initial", "theta_dot", 0, &ic->theta_dot, NULL)) ||
        (rc = tippe_json_number(c, ini, "initial", "spin", 1, &ic->spin, NULL)) ||
        (rc = tippe_json_number(c, ini, "initial", "U", 0, &ic->U, NULL)) ||
        (rc = tippe_json_number(c, ini, "initial", "V", 0, &ic->V, NULL)))
        return rc;
    if (!(ic->theta >= 0 && ic->theta <= M_PI))
        return tippe_json_fail(c, "initial.theta", "must be in [0, pi] rad, got %g", ic->theta);
    if ((rc = check_range(c, "initial.theta_dot", ic->theta_dot, -RATE_MAX_RAD_S,
                          RATE_MAX_RAD_S, "rad/s")) ||
        (rc = check_range(c, "initial.spin", ic->spin, -RATE_MAX_RAD_S, RATE_MAX_RAD_S,
                          "rad/s")) ||
        (rc = check_range(c, "initial.U", ic->U, -SPEED_MAX_M_S, SPEED_MAX_M_S, "m/s")) ||
        (rc = check_range(c, "initial.V", ic->V, -SPEED_MAX_M_S, SPEED_MAX_M_S, "m/s")))
        return rc;
    const cJSON *pd = cJSON_GetObjectItemCaseSensitive(ini, "phi_dot");
    if (!pd || cJSON_IsNumber(pd)) {
        if ((rc = tippe_json_number(c, ini, "initial", "phi_dot", 0, &ic->phi_dot, NULL)) ||
            (rc = check_range(c, "initial.phi_dot", ic->phi_dot, -RATE_MAX_RAD_S,
                              RATE_MAX_RAD_S, "rad/s")))
            return rc;
        s->phi_dot_rule = TIPPE_PHI_DOT_GIVEN;
        return TIPPE_OK;
    }
    if (!cJSON_IsString(pd))
        return tippe_json_fail(c, "initial.phi_dot",
                               "expected a number (rad/s) or steady, s1, s2, s3; "
                               "got %s",
                               tippe_json_kind(pd));
    static const struct {
        const char *name;
        tippe_precession_rule rule;
    } rules[] = {{"steady", TIPPE_PRECESSION_STEADY}, {"s1", TIPPE_PRECESSION_S1},
                 {"s2", TIPPE_PRECESSION_S2}, {"s3", TIPPE_PRECESSION_S3}};
    int found = -1;
    for (int i = 0; i < 4; i++)
        if (!strcmp(pd->valuestring, rules[i].name))
            found = i;
    if (found < 0)
        return tippe_json_fail(c, "initial.phi_dot",
                               "unknown rule '%s' (a number in rad/s, or steady, "
                               "s1, s2, s3)",
                               pd->valuestring);
    s->phi_dot_rule = (int)rules[found].rule;
    tippe_error e;
    if (tippe_dynamics_precession(&s->model, ic->theta, ic->spin, rules[found].rule,
                                  &ic->phi_dot, &e))
        return tippe_json_fail(c, "initial.phi_dot", "%s", e.msg);
    /* The rule divides by cos(theta): near pi/2 it gives any rate at all. What it
     * gives must be a rate the file could have given as a number; the field to
     * blame is the tilt near pi/2, else the spin. */
    if (!(fabs(ic->phi_dot) <= RATE_MAX_RAD_S)) {
        if (fabs(cos(ic->theta)) < 0.5)
            return tippe_json_fail(c, "initial.theta",
                                   "%.17g rad is %.3g rad from pi/2, where the %s rule of "
                                   "initial.phi_dot gives a precession of %.3g rad/s (spin %g "
                                   "rad/s), outside the allowed -%g .. %g rad/s: tilt less, or "
                                   "give initial.phi_dot as a number",
                                   ic->theta, fabs(M_PI_2 - ic->theta), pd->valuestring,
                                   ic->phi_dot, ic->spin, RATE_MAX_RAD_S, RATE_MAX_RAD_S);
        return tippe_json_fail(c, "initial.spin",
                               "%g rad/s: the %s rule of initial.phi_dot gives a precession of "
                               "%.3g rad/s at theta %g rad, outside the allowed -%g .. %g rad/s: "
                               "spin slower, or give initial.phi_dot as a number",
                               ic->spin, pd->valuestring, ic->phi_dot, ic->theta,
                               RATE_MAX_RAD_S, RATE_MAX_RAD_S);
    }
    return TIPPE_OK;
}

const char *tippe_scenario_phi_dot_rule_name(int rule)
{
    switch (rule) {
    case TIPPE_PRECESSION_STEADY: return "steady";
    case TIPPE_PRECESSION_S1: return "s1";
    case TIPPE_PRECESSION_S2: return "s2";
    case TIPPE_PRECESSION_S3: return "s3";
    default: return "given";
    }
}

/* Appends "sep FIELD=VALUE" to name, a number to 6 digits: the command line
 * passes exact values (%.17g), which would only clutter a title. */
static void append_override(char *name, size_t size, const char *sep, const char *override)
{
    size_t len = strlen(name);
    const char *eq = strchr(override, '=');
    char *end = NULL;
    double x = eq ? strtod(eq + 1, &end) : 0.0;
    if (eq && end != eq + 1 && *end == '\0' && isfinite(x))
        snprintf(name + len, size - len, "%s%.*s=%.6g", sep, (int)(eq - override), override, x);
    else
        snprintf(name + len, size - len, "%s%s", sep, override);
}

/* The scenario of root (read from the file, or made for a design: then
 * design_text is that design file's text, read already), with the overrides
 * applied and everything checked. */
static int scenario_from_root(tippe_json_reader *c, cJSON *root, const char *path,
                              const char *const *overrides, int n_overrides,
                              const char *design_text, size_t design_len, tippe_scenario *out)
{
    int rc;
    if ((rc = tippe_json_check_duplicates(c, root, "")))
        return rc;
    for (int i = 0; i < n_overrides; i++)
        if ((rc = apply_override(c, root, overrides[i])))
            return rc;
    if ((rc = tippe_json_check_keys(c, root, "", NULL, top_level_keys, NULL)))
        return rc;

    const cJSON *name = cJSON_GetObjectItemCaseSensitive(root, "name");
    if ((rc = tippe_json_string(c, root, "", "name", 0, NULL, 0, NULL)))
        return rc;
    snprintf(out->name, sizeof out->name, "%s", name ? name->valuestring : path);
    /* the file's name may describe values the command line changed: say so */
    for (int i = 0; i < n_overrides; i++)
        append_override(out->name, sizeof out->name, i ? ", " : " [changed: ", overrides[i]);
    if (n_overrides > 0) {
        size_t len = strlen(out->name);
        if (len + 1 < sizeof out->name)
            snprintf(out->name + len, sizeof out->name - len, "]");
    }
    if ((rc = tippe_json_text(c, root, "", "notes", 0, NULL, 0, NULL)))
        return rc;
    if ((rc = read_top(c, cJSON_GetObjectItemCaseSensitive(root, "top"), out, design_text,
                       design_len)))
        return rc;
    out->model.g = TIPPE_DEFAULT_G_M_S2;
    if ((rc = tippe_json_number(c, root, "", "g", 0, &out->model.g, NULL)))
        return rc;
    if (!(out->model.g > 0))
        return tippe_json_fail(c, "g", "must be > 0 m/s^2, got %g", out->model.g);
    if ((rc = check_range(c, "g", out->model.g, 0, G_MAX_M_S2, "m/s^2")))
        return rc;
    if ((rc = read_friction(c, root, out)))
        return rc;
    if ((rc = tippe_json_number(c, root, "", "t_end", 1, &out->t_end, NULL)))
        return rc;
    if (!(out->t_end > 0))
        return tippe_json_fail(c, "t_end", "must be > 0 s, got %g", out->t_end);
    if ((rc = check_range(c, "t_end", out->t_end, 0, T_END_MAX_S, "s")))
        return rc;
    if ((rc = read_accuracy(c, cJSON_GetObjectItemCaseSensitive(root, "accuracy"), out)))
        return rc;
    return read_initial(c, cJSON_GetObjectItemCaseSensitive(root, "initial"), out);
}

int tippe_scenario_load(const char *path, const char *const *overrides, int n_overrides,
                        tippe_scenario *out, tippe_error *err)
{
    return tippe_scenario_load_text(path, NULL, 0, overrides, n_overrides, out, err);
}

void tippe_scenario_free(tippe_scenario *s)
{
    if (!s)
        return;
    tippe_design_free(s->design);
    s->design = NULL;
}

int tippe_scenario_load_text(const char *path, const char *text, size_t len,
                             const char *const *overrides, int n_overrides, tippe_scenario *out,
                             tippe_error *err)
{
    memset(out, 0, sizeof *out);
    if (!path || !path[0])
        return tippe_error_set(err, TIPPE_EINPUT, "no scenario file given");
    if (n_overrides > MAX_OVERRIDES)
        return tippe_error_set(err, TIPPE_EINPUT, "more than %d overrides", MAX_OVERRIDES);
    snprintf(out->path, sizeof out->path, "%s", path);
    tippe_json_reader *c =
        tippe_json_reader_new(path, err, TIPPE_JSON_WORDS_KEY, "set on the command line: ");
    if (!c)
        return TIPPE_ECOMPUTE;
    cJSON *root = NULL;
    if (len > ((size_t)MAX_SCENARIO_MIB << 20))
        text = NULL; /* the file's own read refuses it, in its words */
    int rc = text ? tippe_json_parse_text(c, text, len, MAX_SCENARIO_MIB, "scenario", &root)
                  : tippe_json_load(c, MAX_SCENARIO_MIB, "scenario", &root);
    if (!rc && !cJSON_IsObject(root))
        rc = tippe_json_wrong_type(c, "", "a JSON object at the top", root);
    if (!rc)
        rc = scenario_from_root(c, root, path, overrides, n_overrides, NULL, 0, out);
    cJSON_Delete(root);
    free(c);
    if (rc)
        tippe_scenario_free(out);
    return rc;
}

/* The scenario of a design's central hand launch (the defaults of tippe
 * launch, docs/launch.md): the median tilt of the half-normal, steady
 * precession, the middle of the spin range, centre at rest; its mu, g and t_end. */
static cJSON *design_root(const char *design_path, double z2_mm, const char *const *sets,
                          int n_sets)
{
    tippe_launch_options o;
    tippe_launch_options_default(&o);
    const char *file = tippe_path_base(design_path);
    cJSON *root = cJSON_CreateObject(), *top = cJSON_AddObjectToObject(root, "top"),
          *ini = cJSON_AddObjectToObject(root, "initial"),
          *set = cJSON_AddArrayToObject(top, "set");
    if (!root || !top || !ini || !set) {
        cJSON_Delete(root);
        return NULL;
    }
    char name[1200];
    /* what differs from launch to launch first: a film's caption may be cut at its end */
    snprintf(name, sizeof name, "%s at Z2 = %g mm, central hand launch", file, z2_mm);
    cJSON_AddStringToObject(root, "name", name);
    /* the design's path is read relative to the "scenario" file: the design itself */
    cJSON_AddStringToObject(top, "design", file);
    cJSON_AddNumberToObject(top, "z2_mm", z2_mm);
    for (int i = 0; i < n_sets; i++)
        cJSON_AddItemToArray(set, cJSON_CreateString(sets[i]));
    cJSON_AddNumberToObject(root, "g", o.g);
    if (tippe_friction_law_takes(o.law, TIPPE_LAW_PARAM_MU)) {
        cJSON_AddNumberToObject(root, "mu", o.mu);
    } else {
        cJSON *f = cJSON_AddObjectToObject(root, "friction");
        if (f) {
            cJSON_AddStringToObject(f, "law", tippe_friction_law_name(o.law));
            cJSON_AddNumberToObject(f, "mu", o.mu_c);
        }
    }
    cJSON_AddNumberToObject(root, "t_end", o.t_end);
    cJSON_AddStringToObject(root, "accuracy", o.accuracy_name);
    cJSON_AddNumberToObject(ini, "theta", TIPPE_LAUNCH_HALF_NORMAL_MEDIAN * o.tilt_sd_rad);
    cJSON_AddNumberToObject(ini, "theta_dot", 0.0);
    cJSON_AddStringToObject(ini, "phi_dot", "steady");
    cJSON_AddNumberToObject(ini, "spin", M_PI * (o.spin_from_rev_s + o.spin_to_rev_s));
    cJSON_AddNumberToObject(ini, "U", 0.0);
    cJSON_AddNumberToObject(ini, "V", 0.0);
    return root;
}

int tippe_scenario_for_design(const char *design_path, const char *design_text,
                              size_t design_len, double z2_mm,
                              const char *const *design_sets, int n_design_sets,
                              const char *const *overrides, int n_overrides,
                              tippe_scenario *out, tippe_error *err)
{
    memset(out, 0, sizeof *out);
    if (!design_path || !design_path[0])
        return tippe_error_set(err, TIPPE_EINPUT, "no design file given");
    if (n_overrides > MAX_OVERRIDES || n_design_sets > MAX_DESIGN_SETS)
        return tippe_error_set(err, TIPPE_EINPUT, "more than %d overrides", MAX_OVERRIDES);
    if (!isfinite(z2_mm))
        return tippe_error_set(err, TIPPE_EINPUT, "Z2 = %g mm is not a number", z2_mm);
    snprintf(out->path, sizeof out->path, "%s", design_path);
    tippe_json_reader *c = tippe_json_reader_new(design_path, err, TIPPE_JSON_WORDS_KEY,
                                                 "set on the command line: ");
    if (!c)
        return TIPPE_ECOMPUTE;
    cJSON *root = design_root(design_path, z2_mm, design_sets, n_design_sets);
    int rc = root ? TIPPE_OK : tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    if (!rc)
        rc = scenario_from_root(c, root, design_path, overrides, n_overrides, design_text,
                                design_len, out);
    cJSON_Delete(root);
    free(c);
    if (rc)
        tippe_scenario_free(out);
    return rc;
}
