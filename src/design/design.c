/* Design files: parse (cJSON), override, validate, and place the moving weight.
 *
 * Everything geometric in this file is in mm (as in the design file); the
 * moments handed to the geometry module, and the top, are SI.
 *
 * Overlap and travel are decided on the (r, z) half-plane, where every part is
 * a region of revolution. At a fixed r each region is a finite union of z
 * intervals, known in closed form (a disc, an annulus, a rectangle, an
 * ellipse, cut by a clip disc, minus voids). So at each sampled r the overlap
 * of two parts, and the Z2 shifts at which a moving part meets a fixed one,
 * are exact interval arithmetic; only r is sampled (a uniform grid plus every
 * radius where some part's boundary starts or ends, see sample_radii). To let
 * parts touch, material is eroded and voids dilated by TOL_MM before comparing:
 * "overlap" means sharing volume more than TOL_MM deep. docs/design-format.md
 * states the resolution this gives. */
#include "design/design_internal.h"
#include "tippe/base.h"
#include "base/json.h"

#include <cjson/cJSON.h>
#include <gsl/gsl_errno.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NAME_LEN 64
#define MAX_PARTS 50
#define MAX_FILE_MIB 4
/* Overlap depth that still counts as touching: far below print resolution
 * (~0.1 mm), far above double roundoff on mm-sized numbers (~1e-14 mm). */
#define TOL_MM 1e-6
/* Uniform r samples across the widest part; see the resolution note in docs. */
#define N_R_UNIFORM 4000
/* The same for an optimiser's candidates (TIPPE_DESIGN_COARSE_LAYOUT): 20 times
 * fewer uniform samples; every part's edges are still sampled exactly. */
#define N_R_COARSE 200
/* A sphere radius match (the part forming the sphere's surface), mm. */
#define SAME_LENGTH_MM 1e-9
/* Slack on the travel check for a sweep's rounded steps, mm. */
#define TRAVEL_SLACK_MM 1e-9
/* Beyond any coordinate in a design, mm: stands for an unbounded interval. */
#define BIG_MM 1e12
/* The densest solid: osmium, 22.587 g/cm^3 at 20 C (J. W. Arblaster, "Densities
 * of osmium and iridium", Platinum Metals Review 33 (1989) 14-16; the CRC
 * Handbook of Chemistry and Physics gives 22.59). Anything denser was typed in
 * another unit (kg/m^3 for g/cm^3: 7850 for steel). */
#define DENSITY_MAX_G_CM3 22.6
/* Sphere radii of a tippe top: a 2 mm bead to a 2 m ball. Outside, the number
 * was typed in another unit (metres: 0.025; um: 25000). */
#define RADIUS_MIN_MM 1.0
#define RADIUS_MAX_MM 1000.0
/* A part length below 10 um is finer than anything printed or machined: a
 * warning (probably metres); smaller lengths still load, for limit studies. */
#define LENGTH_HINT_MM 0.01
/* Intervals per r: a part gives at most 2, each void removes at most 2 more. */
#define MAX_IV (4 + 4 * MAX_PARTS)

enum { CLIP_NONE, CLIP_SPHERE, CLIP_CAVITY, CLIP_SHELL };

typedef enum { SHAPE_BALL, SHAPE_SHELL, SHAPE_CYLINDER, SHAPE_TUBE, SHAPE_TORUS, N_SHAPES } shape_kind;
static const char *const shape_names[N_SHAPES] = {"ball", "shell", "cylinder", "tube", "torus"};

typedef struct {
    char name[NAME_LEN];
    char material[NAME_LEN]; /* "" when density_g_cm3 was given inline */
    shape_kind shape;
    double radius_mm;       /* ball, shell (outer), cylinder, tube (outer) */
    double inner_radius_mm; /* cylinder, tube */
    double thickness_mm;    /* shell */
    double height_mm;       /* cylinder, tube; resolved when only a clip is given */
    double centre_radius_mm, radial_semi_mm, axial_semi_mm; /* torus */
    double z_mm;            /* moving parts: offset from Z2 */
    double density_g_cm3;   /* voids: the parent's */
    int is_void, moving, may_protrude;
    int printable;          /* the material's "printable" flag (voids: the parent's) */
    int has_height, has_radius;
    int parent;             /* voids: index of the part cut from; else -1 */
    int clip;               /* CLIP_NONE, CLIP_SPHERE, CLIP_CAVITY, CLIP_SHELL */
    double clip_radius_mm;  /* resolved; 0 = not clipped */
    double clip_inner_mm;   /* CLIP_SHELL: the shell's cavity radius (the part is cut to
                               the wall between it and clip_radius_mm); else 0 */
    int printed;            /* has a "print" block */
    tippe_print_settings print;
    int calibrated;         /* the infill comes from measured_mass_g */
    double measured_mass_g;
    double infill;          /* used: print.infill, or the calibrated one */
    double solid_mass_kg, skin_mass_kg, print_rel_error;
    double mass_kg;         /* signed contribution */
    int fit;                /* a hole's "fit": TIPPE_DESIGN_FIT_* (NONE when not given) */
} part;

struct tippe_design {
    char *path, *name;
    double radius_mm;
    double travel_mm[2], contact_mm[2];
    char contact_limit[2][256];
    /* Z2 where every part stays within the sphere (from > to: nowhere); the
     * sampled radii it and tippe_design_protrusion_at use (NULL: no layout) */
    double sphere_only_mm[2];
    double *rs;
    int nr;
    int n_parts;
    part *parts;
    tippe_moments fixed, moving; /* SI; moving at Z2 = 0 */
    char **overrides;            /* as loaded, for tippe_design_derive */
    int n_overrides;
    tippe_tolerance *tolerances; /* the tolerances block and the defaults */
    int n_tolerances;
    /* Set only while a tippe_design_source builds it: the source's parsed
     * materials table (not owned) and whether the travel is the physical one. */
    const struct tippe_design_source *source;
    int travel_physical, coarse_layout;
};

static int source_materials(const tippe_design *d, const char *mat_file, cJSON **out);
static double widest_free_gap_mid(const tippe_design *d, const double *rs, int nr);

/* A length in mm that must be > 0 (or >= 0 with allow_zero). */
static int field_length(const tippe_json_reader *c, const cJSON *obj, const char *prefix,
                        const char *key, int required, int allow_zero, double *out, int *present)
{
    int here = 0;
    int rc = tippe_json_number(c, obj, prefix, key, required, out, &here);
    if (present)
        *present = here;
    if (rc || !here)
        return rc;
    char p[256];
    tippe_json_path(p, sizeof p, prefix, key);
    if (allow_zero ? *out < 0 : *out <= 0)
        return tippe_json_fail(c, p, "must be %s (a length in mm), got %g",
                               allow_zero ? ">= 0" : "positive", *out);
    return TIPPE_OK;
}

/* A density above the densest solid's: refused, with the number it would be
 * if it was typed in kg/m^3. */
static int check_density(const tippe_json_reader *c, const char *path, double v)
{
    if (v <= DENSITY_MAX_G_CM3)
        return TIPPE_OK;
    char hint[160] = "";
    if (v * 1e-3 <= DENSITY_MAX_G_CM3)
        snprintf(hint, sizeof hint, "; did you mean kg/m^3? %g kg/m^3 is %g g/cm^3", v,
                 v * 1e-3);
    return tippe_json_fail(c, path,
                           "%g g/cm^3 is denser than any solid (osmium, the densest, is "
                           "22.59 g/cm^3)%s",
                           v, hint);
}

/* "0.025 m is 25 mm" / "25000 um is 25 mm": what a length would be in mm if it
 * was typed in metres (small) or micrometres (large), when that fits in
 * [lo_mm, hi_mm] (and, from micrometres, is at least 1 mm: a 60 mm rod too long
 * for its ball is not 60 um); else "". */
static void unit_hint(double v_mm, double lo_mm, double hi_mm, char *buf, size_t cap)
{
    buf[0] = '\0';
    if (v_mm < lo_mm && v_mm * 1e3 >= lo_mm && v_mm * 1e3 <= hi_mm)
        snprintf(buf, cap, "; did you mean metres? %g m is %g mm", v_mm, v_mm * 1e3);
    else if (v_mm > hi_mm && v_mm * 1e-3 >= fmax(lo_mm, 1.0) && v_mm * 1e-3 <= hi_mm)
        snprintf(buf, cap, "; did you mean micrometres? %g um is %g mm", v_mm, v_mm * 1e-3);
}

/* The sphere's radius, checked before anything that depends on it, so that a
 * radius in the wrong unit is said as such (not as a travel or a part that no
 * longer fits). */
static int check_sphere_radius(const tippe_json_reader *c, double R)
{
    if (R >= RADIUS_MIN_MM && R <= RADIUS_MAX_MM)
        return TIPPE_OK;
    char hint[160];
    unit_hint(R, RADIUS_MIN_MM, RADIUS_MAX_MM, hint, sizeof hint);
    return tippe_json_fail(c, "radius_mm",
                           "%g mm is %s than any tippe top (a sphere radius is %g .. %g mm; "
                           "lengths in a design are in mm)%s",
                           R, R < RADIUS_MIN_MM ? "smaller" : "larger", RADIUS_MIN_MM,
                           RADIUS_MAX_MM, hint);
}

/* ---------------------------------------------------------------- schema */

static const char *const top_keys[] = {"name", "notes", "radius_mm", "travel_mm", "materials",
                                       "parts", "tolerances", NULL};
static const char *const top_string_keys[] = {"name", "notes", "materials", NULL};
static const char *const part_common_keys[] = {
    "name", "shape", "notes", "z_mm", "material", "density_g_cm3", "void", "cut_from",
    "clip", "moving", "may_protrude", "print", "fit", NULL};
static const char *const part_string_keys[] = {"name", "shape", "notes", "material",
                                               "cut_from", "clip", "fit", NULL};
static const char *const ball_keys[] = {"radius_mm", NULL};
static const char *const shell_keys[] = {"radius_mm", "thickness_mm", NULL};
static const char *const cylinder_keys[] = {"radius_mm", "inner_radius_mm", "height_mm", NULL};
static const char *const torus_keys[] = {"centre_radius_mm", "radial_semi_mm", "axial_semi_mm",
                                         NULL};
static const char *const *const shape_keys[N_SHAPES] = {ball_keys, shell_keys, cylinder_keys,
                                                        cylinder_keys, torus_keys};
static const char *const all_part_keys[] = {
    "name", "shape", "notes", "z_mm", "material", "density_g_cm3", "void", "cut_from", "clip",
    "moving", "may_protrude", "print", "fit", "radius_mm", "inner_radius_mm", "thickness_mm",
    "height_mm", "centre_radius_mm", "radial_semi_mm", "axial_semi_mm", NULL};
static const char *const print_keys[] = {"perimeters", "line_width_mm", "top_bottom_layers",
                                         "layer_height_mm", "infill", "measured_mass_g",
                                         "notes", NULL};
static const char *const material_keys[] = {"density_g_cm3", "source", "printable", "notes",
                                             NULL};

/* ------------------------------------------------------------- overrides */

/* The index of the part "parts.NAME" or "parts[I]" (field, already cut
 * before its last dot) names in the file's parts array; -1 with the error set. */
static int override_part_index(tippe_json_reader *c, const cJSON *parts, const char *field,
                               const char *text)
{
    if (field[5] == '[') {
        char *endp = NULL;
        long i = strtol(field + 6, &endp, 10);
        if (!endp || endp == field + 6 || strcmp(endp, "]") || i < 0 ||
            i >= cJSON_GetArraySize(parts)) {
            tippe_error_set(c->err, TIPPE_EINPUT,
                            "%s: --set %s: no such part index (the file has %d parts)", c->file,
                            text, cJSON_GetArraySize(parts));
            return -1;
        }
        return (int)i;
    }
    const char *want = field + 6;
    char names[512] = "";
    size_t n = 0;
    int i = 0, index = -1;
    for (const cJSON *p = parts->child; p; p = p->next, i++) {
        const cJSON *nm = cJSON_GetObjectItemCaseSensitive(p, "name");
        if (!cJSON_IsString(nm))
            continue;
        if (!strcmp(nm->valuestring, want) && index < 0)
            index = i;
        int w = snprintf(names + n, sizeof names - n, "%s%s", n ? ", " : "", nm->valuestring);
        if (w > 0 && (size_t)w < sizeof names - n)
            n += (size_t)w;
    }
    if (index < 0)
        tippe_error_set(c->err, TIPPE_EINPUT, "%s: --set %s: no part named '%s' (parts: %s)",
                        c->file, text, want, names);
    return index;
}

/* The print block of part object obj (index), for --set parts.NAME.print.KEY:
 * true, false or no block becomes an object (the defaults), then takes key. */
static int override_print_block(tippe_json_reader *c, cJSON **obj, int index, const char *key,
                                const char *text, char *path, size_t path_cap)
{
    if (!tippe_json_in_list(key, print_keys)) {
        char list[256];
        tippe_json_key_list(list, sizeof list, print_keys, NULL);
        return tippe_error_set(c->err, TIPPE_EINPUT,
                               "%s: --set %s: '%s' is not a print setting (settings: %s)",
                               c->file, text, key, list);
    }
    cJSON *pr = cJSON_GetObjectItemCaseSensitive(*obj, "print");
    if (!cJSON_IsObject(pr)) {
        cJSON *fresh = cJSON_CreateObject();
        if (!fresh)
            return tippe_error_set(c->err, TIPPE_ECOMPUTE, "out of memory");
        int rc = tippe_json_put(c, *obj, "print", fresh);
        if (rc)
            return rc;
        pr = fresh;
    }
    *obj = pr;
    snprintf(path, path_cap, "parts[%d].print.%s", index, key);
    return TIPPE_OK;
}

/* Where --set parts.NAME.KEY (or parts.NAME.print.KEY) writes: *obj, *key and
 * the JSON path for messages. field is modified (cut at its last dot). */
static int override_part_target(tippe_json_reader *c, cJSON *root, char *field, const char *text,
                                cJSON **obj, const char **key, char *path, size_t path_cap)
{
    cJSON *parts = cJSON_GetObjectItemCaseSensitive(root, "parts");
    if (!cJSON_IsArray(parts))
        return tippe_json_fail(c, "parts", "must be an array of parts (cannot apply --set %s)",
                               text);
    char *dot = strrchr(field, '.');
    if (!dot || dot < field + 6 || dot[1] == '\0')
        return tippe_error_set(c->err, TIPPE_EINPUT,
                               "%s: --set %s: expected parts.NAME.FIELD=VALUE", c->file, text);
    *dot = '\0';
    *key = dot + 1;
    size_t flen = strlen(field);
    int in_print = flen > 12 && !strcmp(field + flen - 6, ".print");
    if (in_print)
        field[flen - 6] = '\0';
    int index = override_part_index(c, parts, field, text);
    if (index < 0)
        return TIPPE_EINPUT;
    *obj = cJSON_GetArrayItem(parts, index);
    if (!cJSON_IsObject(*obj)) {
        snprintf(path, path_cap, "parts[%d]", index);
        return tippe_json_fail(c, path, "must be an object (cannot apply --set %s)", text);
    }
    if (in_print)
        return override_print_block(c, obj, index, *key, text, path, path_cap);
    if (!tippe_json_in_list(*key, all_part_keys)) {
        char list[512];
        tippe_json_key_list(list, sizeof list, all_part_keys, NULL);
        return tippe_error_set(c->err, TIPPE_EINPUT,
                               "%s: --set %s: '%s' is not a part field (fields: %s)", c->file,
                               text, *key, list);
    }
    snprintf(path, path_cap, "parts[%d].%s", index, *key);
    return TIPPE_OK;
}

static int apply_override(tippe_json_reader *c, cJSON *root, const char *text)
{
    const char *eq = strchr(text, '=');
    if (!eq || eq == text)
        return tippe_error_set(c->err, TIPPE_EINPUT,
                               "%s: --set %s: expected FIELD=VALUE, e.g. parts.rod.material=nylon",
                               c->file, text);
    char field[256];
    size_t flen = (size_t)(eq - text);
    if (flen >= sizeof field)
        return tippe_error_set(c->err, TIPPE_EINPUT, "%s: --set %s: field name too long", c->file,
                               text);
    memcpy(field, text, flen);
    field[flen] = '\0';
    const char *value = eq + 1;

    cJSON *obj = root;
    const char *key = field;
    char path[300];
    if (!strncmp(field, "parts.", 6) || !strncmp(field, "parts[", 6)) {
        int rc = override_part_target(c, root, field, text, &obj, &key, path, sizeof path);
        if (rc)
            return rc;
    } else {
        if (!tippe_json_in_list(key, top_keys) || !strcmp(key, "parts")) {
            char list[256];
            tippe_json_key_list(list, sizeof list, top_keys, NULL);
            return tippe_error_set(
                c->err, TIPPE_EINPUT,
                "%s: --set %s: '%s' is not a design field (fields: %s, parts.NAME.FIELD)", c->file,
                text, key, list);
        }
        snprintf(path, sizeof path, "%s", key);
    }

    int is_string = obj == root ? tippe_json_in_list(key, top_string_keys)
                                : tippe_json_in_list(key, part_string_keys);
    cJSON *item = NULL;
    if (!strcmp(value, "null")) {
        cJSON_DeleteItemFromObjectCaseSensitive(obj, key);
    } else {
        if (is_string) {
            item = cJSON_CreateString(value);
        } else {
            const char *end = NULL;
            item = cJSON_ParseWithOpts(value, &end, 1);
            if (!item)
                return tippe_error_set(c->err, TIPPE_EINPUT,
                                       "%s: --set %s: '%s' is not a JSON value (a number, true, "
                                       "false, [from, to], or null to remove the field)",
                                       c->file, text, value);
        }
        if (!item)
            return tippe_error_set(c->err, TIPPE_ECOMPUTE, "out of memory");
        int rc = tippe_json_put(c, obj, key, item);
        if (rc)
            return rc;
    }
    /* material and density_g_cm3 exclude each other: setting one replaces the other. */
    if (obj != root && !strcmp(key, "material"))
        cJSON_DeleteItemFromObjectCaseSensitive(obj, "density_g_cm3");
    if (obj != root && !strcmp(key, "density_g_cm3"))
        cJSON_DeleteItemFromObjectCaseSensitive(obj, "material");
    tippe_json_note_set(c, path, text);
    return TIPPE_OK;
}

/* ----------------------------------------------------------------- parts */

/* A print setting: a number in [lo, hi] (an integer if integer). */
static int print_number(const tippe_json_reader *c, const cJSON *obj, const char *pre,
                        const char *key, double lo, double hi, int integer, const char *unit,
                        double *out)
{
    int here = 0;
    int rc = tippe_json_number(c, obj, pre, key, 0, out, &here);
    if (rc || !here)
        return rc;
    char path[96];
    tippe_json_path(path, sizeof path, pre, key);
    if (integer && *out != floor(*out))
        return tippe_json_fail(c, path, "must be a whole number of %s, got %g", unit, *out);
    if (!(*out >= lo && *out <= hi))
        return tippe_json_fail(c, path, "must be %g .. %g %s, got %g", lo, hi, unit, *out);
    return TIPPE_OK;
}

/* "print": true (slicer defaults), false (solid), or an object of settings
 * (defaults for the ones left out). docs/design-format.md gives the ranges. */
static int parse_print(const tippe_json_reader *c, const cJSON *obj, const char *pre, part *p)
{
    const cJSON *item = cJSON_GetObjectItemCaseSensitive(obj, "print");
    if (!item || cJSON_IsFalse(item))
        return TIPPE_OK;
    char path[64];
    tippe_json_path(path, sizeof path, pre, "print");
    if (p->is_void)
        return tippe_json_fail(c, path,
                               "a void is not printed: give the part it is cut from the "
                               "print block (its holes get walls too)");
    p->printed = 1;
    p->print = tippe_print_defaults();
    if (cJSON_IsTrue(item))
        return TIPPE_OK;
    if (!cJSON_IsObject(item))
        return tippe_json_wrong_type(c, path, "true, false or an object of print settings",
                                     item);
    int rc;
    double per = p->print.perimeters, layers = p->print.top_bottom_layers;
    if ((rc = tippe_json_check_keys(c, item, path, "a print block", print_keys, NULL)) ||
        (rc = tippe_json_string(c, item, path, "notes", 0, NULL, 0, NULL)) ||
        (rc = print_number(c, item, path, "perimeters", 0, 50, 1, "perimeters", &per)) ||
        (rc = print_number(c, item, path, "line_width_mm", 0.05, 3, 0, "mm",
                           &p->print.line_width_mm)) ||
        (rc = print_number(c, item, path, "top_bottom_layers", 0, 200, 1, "layers", &layers)) ||
        (rc = print_number(c, item, path, "layer_height_mm", 0.01, 2, 0, "mm",
                           &p->print.layer_height_mm)) ||
        (rc = print_number(c, item, path, "infill", 0, 1, 0,
                           "(a fraction of the solid density: 15 % is 0.15)", &p->print.infill)) ||
        (rc = print_number(c, item, path, "measured_mass_g", 1e-6, 1e6, 0, "g",
                           &p->measured_mass_g)))
        return rc;
    p->print.perimeters = (int)per;
    p->print.top_bottom_layers = (int)layers;
    p->calibrated = cJSON_GetObjectItemCaseSensitive(item, "measured_mass_g") != NULL;
    return TIPPE_OK;
}

/* How a hole is printed for the hardware it takes ("fit", docs/design-format.md):
 * only a void has one; the printed diameter is decided where the thread is
 * known (tippe/build.h). */
static int parse_part_fit(const tippe_json_reader *c, const cJSON *obj, const char *pre, part *p)
{
    char fit[16] = "", path[64];
    int has_fit = 0;
    int rc = tippe_json_string(c, obj, pre, "fit", 0, fit, sizeof fit, &has_fit);
    if (rc || !has_fit)
        return rc;
    tippe_json_path(path, sizeof path, pre, "fit");
    if (!p->is_void)
        return tippe_json_fail(c, path,
                               "only a hole (a void) has a fit: it says how the hole is printed "
                               "for the screw it takes");
    if (!strcmp(fit, "tap"))
        p->fit = TIPPE_DESIGN_FIT_TAP;
    else if (!strcmp(fit, "insert"))
        p->fit = TIPPE_DESIGN_FIT_INSERT;
    else if (!strcmp(fit, "slide"))
        p->fit = TIPPE_DESIGN_FIT_SLIDE;
    else if (!strcmp(fit, "self_tap"))
        return tippe_json_fail(c, path,
                               "\"self_tap\" is not supported: no sourced hole diameter for a "
                               "metric set screw cutting its own thread in a print (fits: tap, "
                               "insert, slide)");
    else
        return tippe_json_fail(c, path,
                               "must be \"tap\", \"insert\" or \"slide\", not '%s'", fit);
    return TIPPE_OK;
}

/* What part p is made of and how it is cut: material or density, void and
 * cut_from, clip (has_moving, has_protrude: whether the file gave those). */
static int parse_part_material(const tippe_json_reader *c, const cJSON *obj, const char *pre,
                               part *p, int has_moving, int has_protrude)
{
    char path[64];
    int rc;
    int has_mat = 0, has_dens = 0, has_cut = 0, has_clip = 0;
    char cut[NAME_LEN] = "", clip[16] = "";
    if ((rc = tippe_json_string(c, obj, pre, "material", 0, p->material, sizeof p->material,
                                &has_mat)) ||
        (rc = tippe_json_number(c, obj, pre, "density_g_cm3", 0, &p->density_g_cm3, &has_dens)) ||
        (rc = tippe_json_string(c, obj, pre, "cut_from", 0, cut, sizeof cut, &has_cut)) ||
        (rc = tippe_json_string(c, obj, pre, "clip", 0, clip, sizeof clip, &has_clip)))
        return rc;
    if (p->is_void) {
        const char *bad = has_mat ? "material" : has_dens ? "density_g_cm3"
                        : has_moving ? "moving" : has_protrude ? "may_protrude" : NULL;
        if (bad) {
            tippe_json_path(path, sizeof path, pre, bad);
            return tippe_json_fail(c, path,
                                   "not allowed on a void: a void removes material of the part "
                                   "named by cut_from and moves with it");
        }
        if (!has_cut) {
            tippe_json_path(path, sizeof path, pre, "cut_from");
            return tippe_json_fail(c, path, "missing: a void must name the part it is cut from");
        }
        strcpy(p->material, cut); /* resolved to a part index later */
    } else {
        if (has_cut) {
            tippe_json_path(path, sizeof path, pre, "cut_from");
            return tippe_json_fail(c, path, "only a void (\"void\": true) is cut from a part");
        }
        if (has_mat == has_dens) {
            tippe_json_path(path, sizeof path, pre, has_mat ? "density_g_cm3" : "material");
            return tippe_json_fail(c, path,
                                   has_mat ? "give either material or density_g_cm3, not both"
                                           : "missing: give a material (a name in the materials "
                                             "table) or density_g_cm3");
        }
        if (has_dens && p->density_g_cm3 <= 0) {
            tippe_json_path(path, sizeof path, pre, "density_g_cm3");
            return tippe_json_fail(c, path, "must be positive, got %g g/cm^3", p->density_g_cm3);
        }
        if (has_dens) {
            tippe_json_path(path, sizeof path, pre, "density_g_cm3");
            if ((rc = check_density(c, path, p->density_g_cm3)))
                return rc;
        }
        if (has_mat && !p->material[0]) {
            tippe_json_path(path, sizeof path, pre, "material");
            return tippe_json_fail(c, path, "must not be empty");
        }
    }
    if (has_clip) {
        tippe_json_path(path, sizeof path, pre, "clip");
        if (!strcmp(clip, "sphere"))
            p->clip = CLIP_SPHERE;
        else if (!strcmp(clip, "cavity"))
            p->clip = CLIP_CAVITY;
        else if (!strcmp(clip, "shell"))
            p->clip = CLIP_SHELL;
        else
            return tippe_json_fail(c, path,
                                   "must be \"sphere\", \"cavity\" or \"shell\", not '%s'", clip);
        if (p->shape == SHAPE_BALL || p->shape == SHAPE_SHELL)
            return tippe_json_fail(c, path, "only a cylinder, tube or torus can be clipped");
        if (p->moving)
            return tippe_json_fail(c, path,
                                   "a moving part cannot be clipped (its shape would change as "
                                   "it moves)");
    }
    return parse_part_fit(c, obj, pre, p);
}

/* The dimensions of part p's shape. */
static int parse_part_shape(const tippe_json_reader *c, const cJSON *obj, const char *pre,
                            part *p)
{
    char path[64];
    int rc;
    switch (p->shape) {
    case SHAPE_BALL:
    case SHAPE_SHELL:
        if ((rc = field_length(c, obj, pre, "radius_mm", 0, 0, &p->radius_mm, &p->has_radius)))
            return rc;
        if (p->shape == SHAPE_SHELL &&
            (rc = field_length(c, obj, pre, "thickness_mm", 1, 0, &p->thickness_mm, NULL)))
            return rc;
        break;
    case SHAPE_CYLINDER:
    case SHAPE_TUBE: {
        int has_inner = 0;
        if ((rc = field_length(c, obj, pre, "radius_mm", 1, 0, &p->radius_mm, NULL)) ||
            (rc = field_length(c, obj, pre, "inner_radius_mm", p->shape == SHAPE_TUBE,
                               p->shape == SHAPE_CYLINDER, &p->inner_radius_mm, &has_inner)) ||
            (rc = field_length(c, obj, pre, "height_mm", 0, 0, &p->height_mm, &p->has_height)))
            return rc;
        if (!p->has_height && !p->clip) {
            tippe_json_path(path, sizeof path, pre, "height_mm");
            return tippe_json_fail(c, path,
                                   "missing (required unless clip is given: a clipped %s without "
                                   "a height spans the clip ball)",
                                   shape_names[p->shape]);
        }
        if (p->inner_radius_mm >= p->radius_mm) {
            tippe_json_path(path, sizeof path, pre, "inner_radius_mm");
            return tippe_json_fail(c, path, "%g mm is not less than radius_mm %g mm",
                                   p->inner_radius_mm, p->radius_mm);
        }
        break;
    }
    case SHAPE_TORUS:
        if ((rc = field_length(c, obj, pre, "centre_radius_mm", 1, 0, &p->centre_radius_mm,
                               NULL)) ||
            (rc = field_length(c, obj, pre, "radial_semi_mm", 1, 0, &p->radial_semi_mm, NULL)) ||
            (rc = field_length(c, obj, pre, "axial_semi_mm", 1, 0, &p->axial_semi_mm, NULL)))
            return rc;
        if (p->radial_semi_mm > p->centre_radius_mm) {
            tippe_json_path(path, sizeof path, pre, "radial_semi_mm");
            return tippe_json_fail(c, path,
                                   "%g mm is more than centre_radius_mm %g mm (the ring would "
                                   "cross the axis)",
                                   p->radial_semi_mm, p->centre_radius_mm);
        }
        break;
    default:
        break;
    }
    return TIPPE_OK;
}

static int parse_part(const tippe_json_reader *c, const cJSON *obj, int index, part *p)
{
    char pre[32], path[64], shape[16];
    snprintf(pre, sizeof pre, "parts[%d]", index);
    memset(p, 0, sizeof *p);
    p->parent = -1;
    if (!cJSON_IsObject(obj))
        return tippe_json_wrong_type(c, pre, "an object", obj);
    int rc;
    if ((rc = tippe_json_string(c, obj, pre, "shape", 1, shape, sizeof shape, NULL)))
        return rc;
    int s = 0;
    while (s < N_SHAPES && strcmp(shape, shape_names[s]))
        s++;
    if (s == N_SHAPES) {
        tippe_json_path(path, sizeof path, pre, "shape");
        return tippe_json_fail(
            c, path, "unknown shape '%s' (shapes: ball, shell, cylinder, tube, torus)", shape);
    }
    p->shape = (shape_kind)s;
    char what[32];
    snprintf(what, sizeof what, "a %s", shape_names[s]);
    if ((rc = tippe_json_check_keys(c, obj, pre, what, part_common_keys, shape_keys[s])))
        return rc;
    if ((rc = tippe_json_string(c, obj, pre, "name", 1, p->name, sizeof p->name, NULL)))
        return rc;
    if (!p->name[0]) {
        tippe_json_path(path, sizeof path, pre, "name");
        return tippe_json_fail(c, path, "must not be empty");
    }
    if ((rc = tippe_json_string(c, obj, pre, "notes", 0, NULL, 0, NULL)))
        return rc;
    if ((rc = tippe_json_number(c, obj, pre, "z_mm", 0, &p->z_mm, NULL)))
        return rc;
    int has_void = 0, has_moving = 0, has_protrude = 0;
    if ((rc = tippe_json_bool(c, obj, pre, "void", &p->is_void, &has_void)) ||
        (rc = tippe_json_bool(c, obj, pre, "moving", &p->moving, &has_moving)) ||
        (rc = tippe_json_bool(c, obj, pre, "may_protrude", &p->may_protrude, &has_protrude)) ||
        (rc = parse_print(c, obj, pre, p)))
        return rc;
    if ((rc = parse_part_material(c, obj, pre, p, has_moving, has_protrude)))
        return rc;
    return parse_part_shape(c, obj, pre, p);
}

/* --------------------------------------------------------- materials table */

static int lookup_material(const tippe_json_reader *c, const cJSON *table, const char *mat_file,
                           const char *name, const char *path, double *density, int *printable)
{
    const cJSON *m = cJSON_GetObjectItemCaseSensitive(table, name);
    if (!m) {
        char list[512] = "";
        size_t n = 0;
        for (const cJSON *ch = table->child; ch; ch = ch->next) {
            int w = snprintf(list + n, sizeof list - n, "%s%s", n ? ", " : "", ch->string);
            if (w > 0 && (size_t)w < sizeof list - n)
                n += (size_t)w;
        }
        return tippe_json_fail(c, path, "unknown material '%s' (%s has: %s)", name, mat_file, list);
    }
    *density = cJSON_GetObjectItemCaseSensitive(m, "density_g_cm3")->valuedouble;
    *printable = cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(m, "printable"));
    return TIPPE_OK;
}

static int load_materials(const char *mat_file, cJSON **out, tippe_error *err)
{
    tippe_json_reader *mc = tippe_json_reader_new(mat_file, err, TIPPE_JSON_WORDS_FIELD, NULL);
    if (!mc)
        return TIPPE_ECOMPUTE;
    cJSON *root = NULL;
    int rc = tippe_json_load(mc, MAX_FILE_MIB, "materials", &root);
    if (rc)
        goto done;
    if (!cJSON_IsObject(root)) {
        rc = tippe_json_fail(mc, NULL,
                             "must be an object mapping material names to "
                             "{\"density_g_cm3\": ..., \"source\": ...}");
        goto done;
    }
    if ((rc = tippe_json_check_duplicates(mc, root, "")))
        goto done;
    for (const cJSON *m = root->child; m; m = m->next) {
        if (!cJSON_IsObject(m)) {
            rc = tippe_json_wrong_type(mc, m->string, "an object", m);
            goto done;
        }
        double dens = 0;
        int printable = 0;
        if ((rc = tippe_json_check_keys(mc, m, m->string, "a material", material_keys, NULL)) ||
            (rc = tippe_json_number(mc, m, m->string, "density_g_cm3", 1, &dens, NULL)) ||
            (rc = tippe_json_string(mc, m, m->string, "source", 1, NULL, 0, NULL)) ||
            (rc = tippe_json_bool(mc, m, m->string, "printable", &printable, NULL)) ||
            (rc = tippe_json_string(mc, m, m->string, "notes", 0, NULL, 0, NULL)))
            goto done;
        char p[256];
        tippe_json_path(p, sizeof p, m->string, "density_g_cm3");
        if (dens <= 0) {
            rc = tippe_json_fail(mc, p, "must be positive, got %g g/cm^3", dens);
            goto done;
        }
        if ((rc = check_density(mc, p, dens)))
            goto done;
        if (!cJSON_GetObjectItemCaseSensitive(m, "source")->valuestring[0]) {
            tippe_json_path(p, sizeof p, m->string, "source");
            rc = tippe_json_fail(mc, p, "must say where the density comes from");
            goto done;
        }
    }
done:
    free(mc);
    if (rc)
        cJSON_Delete(root);
    else
        *out = root;
    return rc;
}

struct tippe_materials {
    cJSON *root;
    int n;
};

int tippe_materials_load(const char *path, tippe_materials **out, tippe_error *err)
{
    *out = NULL;
    tippe_materials *t = calloc(1, sizeof *t);
    if (!t)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    int rc = load_materials(path, &t->root, err);
    if (rc) {
        free(t);
        return rc;
    }
    t->n = cJSON_GetArraySize(t->root);
    *out = t;
    return TIPPE_OK;
}

int tippe_materials_count(const tippe_materials *t) { return t->n; }

void tippe_materials_get(const tippe_materials *t, int i, tippe_material *out)
{
    const cJSON *m = cJSON_GetArrayItem(t->root, i);
    const cJSON *notes = cJSON_GetObjectItemCaseSensitive(m, "notes");
    out->name = m->string;
    out->source = cJSON_GetObjectItemCaseSensitive(m, "source")->valuestring;
    out->notes = cJSON_IsString(notes) ? notes->valuestring : "";
    out->density_g_cm3 = cJSON_GetObjectItemCaseSensitive(m, "density_g_cm3")->valuedouble;
    out->printable = cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(m, "printable"));
}

void tippe_materials_free(tippe_materials *t)
{
    if (t)
        cJSON_Delete(t->root);
    free(t);
}

int tippe_design_materials_file(const char *design_path, char *buf, size_t size,
                                tippe_error *err)
{
    tippe_json_reader *c = tippe_json_reader_new(design_path, err, TIPPE_JSON_WORDS_FIELD, NULL);
    if (!c)
        return TIPPE_ECOMPUTE;
    cJSON *root = NULL;
    char rel[512] = "materials.json";
    int rc = tippe_json_load(c, MAX_FILE_MIB, "design", &root);
    if (!rc && !(cJSON_IsObject(root) && cJSON_GetObjectItemCaseSensitive(root, "parts")))
        rc = tippe_json_fail(c, "", "not a design (no parts)");
    if (!rc)
        rc = tippe_json_string(c, root, "", "materials", 0, rel, sizeof rel, NULL);
    const char *slash = strrchr(design_path, '/');
    if (!rc && (rel[0] == '/' || !slash ? snprintf(buf, size, "%s", rel)
                                        : snprintf(buf, size, "%.*s/%s",
                                                   (int)(slash - design_path), design_path,
                                                   rel)) >= (int)size)
        rc = tippe_error_set(err, TIPPE_EINPUT, "%s: materials: path too long", design_path);
    cJSON_Delete(root);
    free(c);
    return rc;
}

/* ------------------------------------------------------ z intervals at r */

typedef struct {
    int n;
    double lo[MAX_IV], hi[MAX_IV]; /* sorted, disjoint, lo < hi */
} ivset;

static void iv_push(ivset *s, double lo, double hi)
{
    if (lo < hi && s->n < MAX_IV) {
        s->lo[s->n] = lo;
        s->hi[s->n] = hi;
        s->n++;
    }
}

static void iv_intersect(const ivset *a, const ivset *b, ivset *out)
{
    out->n = 0;
    int i = 0, j = 0;
    while (i < a->n && j < b->n) {
        iv_push(out, fmax(a->lo[i], b->lo[j]), fmin(a->hi[i], b->hi[j]));
        if (a->hi[i] < b->hi[j])
            i++;
        else
            j++;
    }
}

static void iv_subtract(const ivset *a, const ivset *b, ivset *out)
{
    out->n = 0;
    for (int i = 0; i < a->n; i++) {
        double lo = a->lo[i];
        for (int j = 0; j < b->n && lo < a->hi[i]; j++) {
            if (b->hi[j] <= lo || b->lo[j] >= a->hi[i])
                continue;
            iv_push(out, lo, b->lo[j]);
            lo = b->hi[j];
        }
        iv_push(out, lo, a->hi[i]);
    }
}

/* Half-height of a disc of radius a at distance r from its axis, or -1. */
static double chord(double a, double r)
{
    return (a > 0 && r < a) ? sqrt(a * a - r * r) : -1;
}

/* z intervals of part p's own region (before voids) at radius r, moved by
 * dz_mm, grown outward by grow_mm (negative: eroded). */
static void prim_ivs(const part *p, double r, double dz, double g, ivset *s)
{
    s->n = 0;
    double zc = p->z_mm + dz, h, hi;
    switch (p->shape) {
    case SHAPE_BALL:
        if ((h = chord(p->radius_mm + g, r)) > 0)
            iv_push(s, zc - h, zc + h);
        break;
    case SHAPE_SHELL:
        if ((h = chord(p->radius_mm + g, r)) <= 0)
            break;
        if ((hi = chord(p->radius_mm - p->thickness_mm - g, r)) > 0) {
            iv_push(s, zc - h, zc - hi);
            iv_push(s, zc + hi, zc + h);
        } else {
            iv_push(s, zc - h, zc + h);
        }
        break;
    case SHAPE_CYLINDER:
    case SHAPE_TUBE:
        /* r = 0 is the axis, not a boundary: a solid cylinder is not eroded there. */
        if (r < p->radius_mm + g && (p->inner_radius_mm == 0 || r > p->inner_radius_mm - g))
            iv_push(s, zc - p->height_mm / 2 - g, zc + p->height_mm / 2 + g);
        break;
    case SHAPE_TORUS: {
        double ra = p->radial_semi_mm + g, az = p->axial_semi_mm + g;
        double x = (r - p->centre_radius_mm) / ra;
        if (ra > 0 && az > 0 && fabs(x) < 1) {
            h = az * sqrt(1 - x * x);
            iv_push(s, zc - h, zc + h);
        }
        break;
    }
    default:
        break;
    }
    if (p->clip_radius_mm > 0) {
        /* the clip ball, or with clip_inner_mm the shell's wall */
        ivset c = {0}, t;
        if ((h = chord(p->clip_radius_mm + g, r)) > 0) {
            if (p->clip_inner_mm > 0 && (hi = chord(p->clip_inner_mm - g, r)) > 0) {
                iv_push(&c, -h, -hi);
                iv_push(&c, hi, h);
            } else {
                iv_push(&c, -h, h);
            }
        }
        iv_intersect(s, &c, &t);
        *s = t;
    }
}

/* Material of non-void part i at r, moved by dz: eroded part minus dilated voids. */
static void material_ivs(const tippe_design *d, int i, double r, double dz, ivset *s)
{
    prim_ivs(&d->parts[i], r, dz, -TOL_MM, s);
    for (int v = 0; v < d->n_parts && s->n; v++) {
        if (d->parts[v].parent != i)
            continue;
        ivset hole, t;
        prim_ivs(&d->parts[v], r, dz, TOL_MM, &hole);
        iv_subtract(s, &hole, &t);
        *s = t;
    }
}

/* Outside the sphere (eroded by TOL_MM). */
static void outside_ivs(double R, double r, ivset *s)
{
    s->n = 0;
    double h = chord(R + TOL_MM, r);
    if (h > 0) {
        iv_push(s, -BIG_MM, -h);
        iv_push(s, h, BIG_MM);
    } else {
        iv_push(s, -BIG_MM, BIG_MM);
    }
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* r samples: a uniform grid across every part, plus points just inside and
 * just outside each radius where a part's boundary begins or ends, so that
 * parts meeting at a corner or along a cylinder wall are resolved exactly. */
static double *sample_radii(const tippe_design *d, int *n_out)
{
    double rmax = d->radius_mm;
    double brk[9 * MAX_PARTS + 2];
    int nb = 0;
    brk[nb++] = d->radius_mm;
    for (int i = 0; i < d->n_parts; i++) {
        const part *p = &d->parts[i];
        switch (p->shape) {
        case SHAPE_BALL:
            brk[nb++] = p->radius_mm;
            break;
        case SHAPE_SHELL:
            brk[nb++] = p->radius_mm;
            brk[nb++] = p->radius_mm - p->thickness_mm;
            break;
        case SHAPE_CYLINDER:
        case SHAPE_TUBE:
            brk[nb++] = p->radius_mm;
            brk[nb++] = p->inner_radius_mm;
            break;
        case SHAPE_TORUS:
            brk[nb++] = p->centre_radius_mm - p->radial_semi_mm;
            brk[nb++] = p->centre_radius_mm;
            brk[nb++] = p->centre_radius_mm + p->radial_semi_mm;
            break;
        default:
            break;
        }
        if (p->clip_radius_mm > 0)
            brk[nb++] = p->clip_radius_mm;
        if (p->clip_inner_mm > 0)
            brk[nb++] = p->clip_inner_mm;
    }
    for (int k = 0; k < nb; k++)
        rmax = fmax(rmax, brk[k]);
    rmax += 1.0;
    int n_uniform = d->coarse_layout ? N_R_COARSE : N_R_UNIFORM;
    int n = n_uniform + 3 * nb + 1;
    double *r = malloc((size_t)n * sizeof *r);
    if (!r)
        return NULL;
    int m = 0;
    r[m++] = 0;
    for (int k = 0; k < n_uniform; k++)
        r[m++] = (k + 0.5) * rmax / n_uniform;
    for (int k = 0; k < nb; k++) {
        double off[3] = {-2 * TOL_MM, 0, 2 * TOL_MM};
        for (int j = 0; j < 3; j++)
            if (brk[k] + off[j] >= 0)
                r[m++] = brk[k] + off[j];
    }
    qsort(r, (size_t)m, sizeof *r, cmp_double);
    *n_out = m;
    return r;
}

static const char *role_of(const part *p)
{
    return p->is_void ? "void" : p->moving ? "moving" : "fixed";
}

/* The layout checks below share the sampled radii. */
typedef struct {
    const tippe_json_reader *c;
    tippe_design *d;
    const double *rs;
    int nr;
} layout;

/* The sphere the top rolls on must be material: a fixed ball or shell of
 * radius R centred on the sphere's centre. */
static int check_surface(const layout *L)
{
    const tippe_design *d = L->d;
    for (int i = 0; i < d->n_parts; i++) {
        const part *p = &d->parts[i];
        if (!p->is_void && !p->moving && (p->shape == SHAPE_BALL || p->shape == SHAPE_SHELL) &&
            fabs(p->radius_mm - d->radius_mm) < SAME_LENGTH_MM && p->z_mm == 0)
            return TIPPE_OK;
    }
    return tippe_json_fail(L->c, "parts",
                           "no part forms the sphere's surface: the top needs a fixed ball "
                           "or shell of radius radius_mm (%g mm) centred at z_mm = 0",
                           d->radius_mm);
}

/* Void i must lie inside the part it is cut from, or it would subtract mass
 * that is not there; and it must not share volume with an earlier void of the
 * same part, or the shared volume would be removed twice. */
static int check_void(const layout *L, int i)
{
    const tippe_design *d = L->d;
    const part *p = &d->parts[i], *q = &d->parts[p->parent];
    char path[64];
    snprintf(path, sizeof path, "parts[%d]", i);
    ivset a, b, t;
    for (int k = 0; k < L->nr; k++) {
        prim_ivs(p, L->rs[k], 0, -TOL_MM, &a);
        prim_ivs(q, L->rs[k], 0, TOL_MM, &b);
        iv_subtract(&a, &b, &t);
        if (t.n)
            return tippe_json_fail(L->c, path,
                                   "void '%s' reaches outside the part it is cut from ('%s') "
                                   "at r = %.3f mm, z = %.3f mm: it would remove material "
                                   "that is not there",
                                   p->name, q->name, L->rs[k], t.lo[0]);
    }
    for (int j = 0; j < i; j++) {
        if (d->parts[j].parent != p->parent)
            continue;
        for (int k = 0; k < L->nr; k++) {
            prim_ivs(p, L->rs[k], 0, -TOL_MM, &a);
            prim_ivs(&d->parts[j], L->rs[k], 0, -TOL_MM, &b);
            iv_intersect(&a, &b, &t);
            if (t.n)
                return tippe_json_fail(L->c, path,
                                       "voids '%s' and '%s' (parts[%d]) overlap at r = "
                                       "%.3f mm: the shared volume would be removed twice",
                                       p->name, d->parts[j].name, j, L->rs[k]);
        }
    }
    return TIPPE_OK;
}

/* A fixed part that may not protrude must stay inside the sphere. */
static int check_inside_sphere(const layout *L, int i)
{
    const tippe_design *d = L->d;
    const part *p = &d->parts[i];
    const double R = d->radius_mm;
    double worst = 0, wr = 0, wz = 0;
    ivset a;
    for (int k = 0; k < L->nr; k++) {
        material_ivs(d, i, L->rs[k], 0, &a);
        for (int j = 0; j < a.n; j++)
            for (int e = 0; e < 2; e++) {
                double z = e ? a.hi[j] : a.lo[j];
                double out = hypot(L->rs[k], z) - R;
                if (out > worst) {
                    worst = out;
                    wr = L->rs[k];
                    wz = z;
                }
            }
    }
    if (worst <= TOL_MM)
        return TIPPE_OK;
    char path[64];
    snprintf(path, sizeof path, "parts[%d]", i);
    return tippe_json_fail(L->c, path,
                           "part '%s' sticks out of the sphere (radius %g mm) by %.3f mm "
                           "(at r = %.3f mm, z = %.3f mm); set \"may_protrude\": true if "
                           "it is meant to, like a setscrew",
                           p->name, R, worst + TOL_MM, wr, wz);
}

/* Fixed against fixed, moving against moving: their relative place never
 * changes, so they must not share volume. */
static int check_no_overlap(const layout *L, int i)
{
    const tippe_design *d = L->d;
    const part *p = &d->parts[i];
    char path[64];
    snprintf(path, sizeof path, "parts[%d]", i);
    ivset a, b, t;
    for (int j = 0; j < i; j++) {
        const part *q = &d->parts[j];
        if (q->is_void || q->moving != p->moving)
            continue;
        for (int k = 0; k < L->nr; k++) {
            material_ivs(d, i, L->rs[k], 0, &a);
            material_ivs(d, j, L->rs[k], 0, &b);
            iv_intersect(&a, &b, &t);
            if (t.n)
                return tippe_json_fail(L->c, path,
                                       "part '%s' overlaps part '%s' (parts[%d]) at r = %.3f mm, "
                                       "z = %.3f .. %.3f mm%s: parts may touch but not share "
                                       "volume (cut one with a void, or clip it)",
                                       p->name, q->name, j, L->rs[k], t.lo[0], t.hi[0],
                                       p->moving ? " relative to Z2" : "");
        }
    }
    return TIPPE_OK;
}

static int check_parts_placed(const layout *L)
{
    const tippe_design *d = L->d;
    int rc = TIPPE_OK, n_moving = 0;
    for (int i = 0; i < d->n_parts && !rc; i++) {
        const part *p = &d->parts[i];
        if (p->is_void) {
            rc = check_void(L, i);
            continue;
        }
        n_moving += p->moving;
        if (!p->moving && !p->may_protrude)
            rc = check_inside_sphere(L, i);
        if (!rc)
            rc = check_no_overlap(L, i);
    }
    if (!rc && !n_moving)
        rc = tippe_json_fail(L->c, "parts",
                             "no moving part: mark the weight's part(s) with \"moving\": true");
    return rc;
}

/* Narrows the physical travel lim[] by what stops moving part p: its centre
 * reaching the surface, if it may protrude. */
static void limit_by_protrusion(tippe_design *d, const part *p, double lim[2])
{
    const double R = d->radius_mm;
    double e[2] = {-R - p->z_mm, R - p->z_mm};
    for (int s = 0; s < 2; s++)
        if (s ? e[s] < lim[1] : e[s] > lim[0]) {
            lim[s] = e[s];
            snprintf(d->contact_limit[s], sizeof d->contact_limit[s],
                     "the centre of protruding part '%s' reaches the sphere's surface", p->name);
        }
}

/* Narrows lim[] by moving part i meeting fixed part j (j = -1: the outside of
 * the sphere). A moving interval [lo, hi] (at Z2 = 0) and a fixed one
 * [flo, fhi] share volume exactly for shifts in (flo - hi, fhi - lo); the
 * physical travel is the gap between such forbidden shifts around mid. Fails
 * if mid itself is forbidden. */
static int limit_by_contact(const layout *L, int i, int j, double mid, double lim[2])
{
    tippe_design *d = L->d;
    const part *p = &d->parts[i];
    ivset a, b;
    for (int k = 0; k < L->nr; k++) {
        material_ivs(d, i, L->rs[k], 0, &a);
        if (!a.n)
            continue;
        if (j < 0)
            outside_ivs(d->radius_mm, L->rs[k], &b);
        else
            material_ivs(d, j, L->rs[k], 0, &b);
        for (int u = 0; u < a.n; u++)
            for (int w = 0; w < b.n; w++) {
                double f0 = b.lo[w] - a.hi[u], f1 = b.hi[w] - a.lo[u];
                int s = -1;
                if (f0 < mid && mid < f1) {
                    if (j < 0)
                        return tippe_json_fail(L->c, "travel_mm",
                                               "at Z2 = %g mm (the middle of the travel) moving "
                                               "part '%s' sticks out of the sphere",
                                               mid, p->name);
                    return tippe_json_fail(L->c, "travel_mm",
                                           "at Z2 = %g mm (the middle of the travel) moving "
                                           "part '%s' overlaps part '%s'",
                                           mid, p->name, d->parts[j].name);
                }
                if (f1 <= mid && f1 > lim[0])
                    lim[s = 0] = f1;
                else if (f0 >= mid && f0 < lim[1])
                    lim[s = 1] = f0;
                if (s < 0)
                    continue;
                if (j < 0)
                    snprintf(d->contact_limit[s], sizeof d->contact_limit[s],
                             "part '%s' reaches the sphere's surface", p->name);
                else
                    snprintf(d->contact_limit[s], sizeof d->contact_limit[s],
                             "part '%s' touches part '%s'", p->name, d->parts[j].name);
            }
    }
    return TIPPE_OK;
}

/* The physical travel (d->contact_mm, d->contact_limit) around the middle of
 * the stated travel, or for a travel_physical design (an optimiser's
 * candidate) the widest free stretch, which then becomes its travel. */
static int find_physical_travel(const layout *L)
{
    tippe_design *d = L->d;
    double mid = d->travel_physical ? widest_free_gap_mid(d, L->rs, L->nr)
                                    : 0.5 * (d->travel_mm[0] + d->travel_mm[1]);
    double lim[2] = {-BIG_MM, BIG_MM};
    snprintf(d->contact_limit[0], sizeof d->contact_limit[0], "nothing");
    snprintf(d->contact_limit[1], sizeof d->contact_limit[1], "nothing");
    int rc = TIPPE_OK;
    for (int i = 0; i < d->n_parts && !rc; i++) {
        const part *p = &d->parts[i];
        if (p->is_void || !p->moving)
            continue;
        if (p->may_protrude)
            limit_by_protrusion(d, p, lim); /* held only while its centre is inside */
        for (int j = -1; j < d->n_parts && !rc; j++) {
            if (j < 0 ? p->may_protrude : (d->parts[j].is_void || d->parts[j].moving))
                continue;
            rc = limit_by_contact(L, i, j, mid, lim);
        }
    }
    d->contact_mm[0] = lim[0];
    d->contact_mm[1] = lim[1];
    if (!rc && d->travel_physical) {
        if (!(lim[0] > -BIG_MM && lim[1] < BIG_MM && lim[0] < lim[1]))
            return tippe_json_fail(L->c, "travel_mm", "the moving weight has no bounded "
                                                      "physical travel (nothing stops it)");
        d->travel_mm[0] = lim[0];
        d->travel_mm[1] = lim[1];
    }
    return rc;
}

/* The stated travel must lie inside the physical one. */
static int check_travel(const layout *L)
{
    const tippe_design *d = L->d;
    const double *lim = d->contact_mm;
    if (d->travel_mm[0] < lim[0])
        return tippe_json_fail(L->c, "travel_mm",
                               "starts at %g mm, below the physical travel %.3f .. %.3f mm "
                               "(at Z2 = %.3f mm %s)",
                               d->travel_mm[0], lim[0], lim[1], lim[0], d->contact_limit[0]);
    if (d->travel_mm[1] > lim[1])
        return tippe_json_fail(L->c, "travel_mm",
                               "ends at %g mm, beyond the physical travel %.3f .. %.3f mm "
                               "(at Z2 = %.3f mm %s)",
                               d->travel_mm[1], lim[0], lim[1], lim[1], d->contact_limit[1]);
    return TIPPE_OK;
}

/* The Z2 interval in which every part's material stays within the sphere (the
 * model's contact is the sphere only): at each sampled r, a moving interval
 * [lo, hi] (at Z2 = 0) stays inside the chord [-h, h] for shifts in
 * [-h - lo, h - hi]; material where the sphere has no chord, or fixed material
 * outside it, leaves no such Z2. Material is eroded and the sphere grown by
 * TOL_MM, as for every contact: flush is inside. */
static void find_sphere_only(tippe_design *d, const double *rs, int nr)
{
    double lo = -BIG_MM, hi = BIG_MM;
    ivset a;
    for (int i = 0; i < d->n_parts; i++) {
        const part *p = &d->parts[i];
        if (p->is_void)
            continue;
        for (int k = 0; k < nr; k++) {
            material_ivs(d, i, rs[k], 0, &a);
            double h = chord(d->radius_mm + TOL_MM, rs[k]);
            for (int u = 0; u < a.n; u++) {
                if (h > 0 && p->moving) {
                    lo = fmax(lo, -h - a.lo[u]);
                    hi = fmin(hi, h - a.hi[u]);
                } else if (h <= 0 || a.lo[u] < -h || a.hi[u] > h) {
                    lo = BIG_MM;
                    hi = -BIG_MM;
                }
            }
        }
    }
    d->sphere_only_mm[0] = lo;
    d->sphere_only_mm[1] = hi;
}

/* Everything about where parts are, once the parts are parsed and resolved. */
static int check_layout(const tippe_json_reader *c, tippe_design *d)
{
    layout L = {c, d, NULL, 0};
    double *rs = sample_radii(d, &L.nr);
    if (!rs)
        return tippe_error_set(c->err, TIPPE_ECOMPUTE, "out of memory");
    L.rs = rs;
    int rc = check_surface(&L);
    if (!rc)
        rc = check_parts_placed(&L);
    if (!rc)
        rc = find_physical_travel(&L);
    if (!rc)
        rc = check_travel(&L);
    if (!rc)
        find_sphere_only(d, rs, L.nr);
    free(d->rs);
    d->rs = rs; /* for tippe_design_protrusion_at */
    d->nr = L.nr;
    return rc;
}

/* ------------------------------------------------------------ mass moments */

/* Unit-density moments of p's own shape cut to the ball of radius clip_m
 * (0: not cut), SI, at its z_mm. */
static tippe_moments shape_moments(const part *p, double clip_m)
{
    const double mm = 1e-3;
    double zc = p->z_mm * mm;
    switch (p->shape) {
    case SHAPE_BALL:
        return tippe_ball(p->radius_mm * mm, zc);
    case SHAPE_SHELL:
        return tippe_shell(p->radius_mm * mm, p->thickness_mm * mm, zc);
    case SHAPE_CYLINDER:
    case SHAPE_TUBE:
        return tippe_tube(p->inner_radius_mm * mm, p->radius_mm * mm, p->height_mm * mm, zc,
                          clip_m);
    case SHAPE_TORUS:
    default:
        return tippe_torus(p->centre_radius_mm * mm, p->radial_semi_mm * mm,
                           p->axial_semi_mm * mm, zc, clip_m);
    }
}

/* Unit-density moments of p's own region (SI), at its z_mm. Cut to a shell's
 * wall, it is the part cut to the outer ball less the part cut to the cavity
 * (the second lies inside the first). */
static tippe_moments part_moments(const part *p)
{
    tippe_moments m = shape_moments(p, p->clip_radius_mm * 1e-3);
    if (p->clip_inner_mm > 0)
        m = tippe_moments_sub(m, shape_moments(p, p->clip_inner_mm * 1e-3));
    return m;
}

static int finite_moments(tippe_moments m)
{
    return isfinite(m.m) && isfinite(m.m_z) && isfinite(m.m_zz) && isfinite(m.m_rr);
}

/* ------------------------------------------------------------------- load */

static char *dup_string(const char *s)
{
    size_t n = strlen(s) + 1;
    char *r = malloc(n);
    if (r)
        memcpy(r, s, n);
    return r;
}

/* travel_mm: [from, to], from < to. */
static int parse_travel(const tippe_json_reader *c, const cJSON *root, tippe_design *d)
{
    const cJSON *tr = cJSON_GetObjectItemCaseSensitive(root, "travel_mm");
    if (!tr)
        return tippe_json_fail(c, "travel_mm",
                               "missing (required: [from, to] in mm, the range of Z2)");
    if (!cJSON_IsArray(tr) || cJSON_GetArraySize(tr) != 2)
        return tippe_json_fail(c, "travel_mm", "must be an array [from, to] of two numbers (mm)");
    for (int k = 0; k < 2; k++) {
        const cJSON *v = cJSON_GetArrayItem(tr, k);
        char p[32];
        snprintf(p, sizeof p, "travel_mm[%d]", k);
        if (!cJSON_IsNumber(v) || !isfinite(v->valuedouble))
            return tippe_json_wrong_type(c, p, "a finite number (mm)", v);
        d->travel_mm[k] = v->valuedouble;
    }
    if (!(d->travel_mm[0] < d->travel_mm[1]))
        return tippe_json_fail(c, "travel_mm", "from (%g mm) must be less than to (%g mm)",
                               d->travel_mm[0], d->travel_mm[1]);
    return TIPPE_OK;
}

/* The top-level fields other than parts; mat_rel gets the materials file as
 * written (default materials.json), *has_mat_file whether it was given. */
static int parse_header(const tippe_json_reader *c, const cJSON *root, const char *path,
                        tippe_design *d, char *mat_rel, size_t mat_cap, int *has_mat_file)
{
    int rc;
    char name[256];
    if (!cJSON_IsObject(root))
        return tippe_json_wrong_type(c, NULL, "a JSON object (a design)", root);
    if ((rc = tippe_json_check_keys(c, root, "", "a design", top_keys, NULL)) ||
        (rc = tippe_json_string(c, root, "", "name", 1, name, sizeof name, NULL)) ||
        (rc = tippe_json_string(c, root, "", "notes", 0, NULL, 0, NULL)) ||
        (rc = field_length(c, root, "", "radius_mm", 1, 0, &d->radius_mm, NULL)) ||
        (rc = check_sphere_radius(c, d->radius_mm)))
        return rc;
    if (!(d->name = dup_string(name)) || !(d->path = dup_string(path)))
        return tippe_error_set(c->err, TIPPE_ECOMPUTE, "out of memory");
    if ((rc = parse_travel(c, root, d)))
        return rc;
    snprintf(mat_rel, mat_cap, "materials.json");
    if ((rc = tippe_json_string(c, root, "", "materials", 0, mat_rel, mat_cap, has_mat_file)))
        return rc;
    if (*has_mat_file && !mat_rel[0])
        return tippe_json_fail(c, "materials", "must be a file name (relative to the design file)");
    return TIPPE_OK;
}

/* parts: 1 to MAX_PARTS parts with unique names. */
static int parse_parts(const tippe_json_reader *c, const cJSON *root, tippe_design *d)
{
    int rc;
    const cJSON *parts = cJSON_GetObjectItemCaseSensitive(root, "parts");
    if (!parts)
        return tippe_json_fail(c, "parts", "missing (required: an array of parts)");
    if (!cJSON_IsArray(parts))
        return tippe_json_wrong_type(c, "parts", "an array of parts", parts);
    int n = cJSON_GetArraySize(parts);
    if (n < 1 || n > MAX_PARTS)
        return tippe_json_fail(c, "parts", "must hold 1 to %d parts, not %d", MAX_PARTS, n);
    if (!(d->parts = calloc((size_t)n, sizeof *d->parts)))
        return tippe_error_set(c->err, TIPPE_ECOMPUTE, "out of memory");
    d->n_parts = n;
    int i = 0;
    for (const cJSON *p = parts->child; p; p = p->next, i++)
        if ((rc = parse_part(c, p, i, &d->parts[i])))
            return rc;
    char pth[64];
    for (i = 0; i < n; i++)
        for (int j = 0; j < i; j++)
            if (!strcmp(d->parts[i].name, d->parts[j].name)) {
                snprintf(pth, sizeof pth, "parts[%d].name", i);
                return tippe_json_fail(
                    c, pth, "'%s' is already the name of parts[%d]: names must be unique",
                    d->parts[i].name, j);
            }
    return TIPPE_OK;
}

/* Densities of the parts that name a material. The table is read only when
 * some part names one; its path is relative to the design file. */
static int resolve_materials(const tippe_json_reader *c, const char *path, const char *mat_rel,
                             int has_mat_file, tippe_design *d)
{
    int uses_table = 0;
    for (int i = 0; i < d->n_parts; i++)
        uses_table |= !d->parts[i].is_void && d->parts[i].material[0];
    if (!uses_table)
        return TIPPE_OK;
    char mat_file[1024];
    const char *slash = strrchr(path, '/');
    if (mat_rel[0] == '/' || !slash)
        snprintf(mat_file, sizeof mat_file, "%s", mat_rel);
    else
        snprintf(mat_file, sizeof mat_file, "%.*s/%s", (int)(slash - path), path, mat_rel);
    cJSON *table = NULL;
    int rc = source_materials(d, mat_file, &table) ? TIPPE_OK
                                                   : load_materials(mat_file, &table, c->err);
    if (rc) {
        if (has_mat_file) {
            char inner[sizeof c->err->msg];
            snprintf(inner, sizeof inner, "%s", c->err->msg);
            return tippe_json_fail(c, "materials", "%s", inner);
        }
        return rc;
    }
    char pth[64];
    for (int i = 0; i < d->n_parts && !rc; i++) {
        part *p = &d->parts[i];
        if (p->is_void || !p->material[0])
            continue;
        snprintf(pth, sizeof pth, "parts[%d].material", i);
        rc = lookup_material(c, table, mat_file, p->material, pth, &p->density_g_cm3,
                             &p->printable);
    }
    cJSON_Delete(table);
    return rc;
}

/* Void p takes its parent's density and motion. */
static int resolve_void(const tippe_json_reader *c, tippe_design *d, int i)
{
    part *p = &d->parts[i];
    char pth[64];
    int j = 0;
    while (j < d->n_parts && strcmp(d->parts[j].name, p->material))
        j++;
    snprintf(pth, sizeof pth, "parts[%d].cut_from", i);
    if (j == d->n_parts)
        return tippe_json_fail(c, pth, "no part named '%s'", p->material);
    if (d->parts[j].is_void)
        return tippe_json_fail(c, pth, "'%s' is itself a void: cut from the solid part",
                               p->material);
    p->parent = j;
    p->moving = d->parts[j].moving;
    p->density_g_cm3 = d->parts[j].density_g_cm3;
    p->printable = d->parts[j].printable;
    snprintf(p->material, sizeof p->material, "%s", d->parts[j].material);
    return TIPPE_OK;
}

/* The clip radius of part i: the sphere, or the cavity of the one fixed
 * shell (shell: its index, n_shell: how many fixed shells there are). */
static int resolve_clip(const tippe_json_reader *c, tippe_design *d, int i, int shell,
                        int n_shell)
{
    part *p = &d->parts[i];
    char pth[64];
    snprintf(pth, sizeof pth, "parts[%d].clip", i);
    if (p->clip && p->moving)
        return tippe_json_fail(c, pth,
                               "a void cut from a moving part cannot be clipped (its shape "
                               "would change as it moves)");
    if (p->clip == CLIP_SPHERE) {
        p->clip_radius_mm = d->radius_mm;
    } else if (p->clip == CLIP_CAVITY || p->clip == CLIP_SHELL) {
        const char *word = p->clip == CLIP_CAVITY ? "cavity" : "shell";
        if (n_shell != 1)
            return tippe_json_fail(c, pth,
                                   "\"%s\" needs exactly one fixed shell part, the design "
                                   "has %d",
                                   word, n_shell);
        if (d->parts[shell].z_mm != 0)
            return tippe_json_fail(c, pth, "\"%s\" needs the shell '%s' centred at z_mm = 0",
                                   word, d->parts[shell].name);
        double cavity = d->parts[shell].radius_mm - d->parts[shell].thickness_mm;
        p->clip_radius_mm = p->clip == CLIP_CAVITY ? cavity : d->parts[shell].radius_mm;
        p->clip_inner_mm = p->clip == CLIP_SHELL ? cavity : 0;
    }
    return TIPPE_OK;
}

/* Voids, clips and default sizes, resolved against the sphere and the shell. */
static int resolve_parts(const tippe_json_reader *c, tippe_design *d)
{
    int rc, shell = -1, n_shell = 0;
    char pth[64];
    for (int i = 0; i < d->n_parts; i++)
        if (d->parts[i].shape == SHAPE_SHELL && !d->parts[i].is_void && !d->parts[i].moving) {
            shell = i;
            n_shell++;
        }
    for (int i = 0; i < d->n_parts; i++) {
        part *p = &d->parts[i];
        if ((p->shape == SHAPE_BALL || p->shape == SHAPE_SHELL) && !p->has_radius)
            p->radius_mm = d->radius_mm; /* default: the sphere itself */
        if (p->shape == SHAPE_SHELL && p->thickness_mm >= p->radius_mm) {
            snprintf(pth, sizeof pth, "parts[%d].thickness_mm", i);
            return tippe_json_fail(c, pth, "%g mm is not less than the shell's radius %g mm",
                                   p->thickness_mm, p->radius_mm);
        }
        if (p->is_void && (rc = resolve_void(c, d, i)))
            return rc;
        if ((rc = resolve_clip(c, d, i, shell, n_shell)))
            return rc;
        if ((p->shape == SHAPE_CYLINDER || p->shape == SHAPE_TUBE) && !p->has_height)
            p->height_mm = 2 * p->clip_radius_mm; /* spans the clip ball */
        if (p->printed && p->material[0] && !p->printable) {
            snprintf(pth, sizeof pth, "parts[%d].print", i);
            return tippe_json_fail(c, pth,
                                   "material '%s' is not printable (the materials table says "
                                   "so): only a printed part has a print block",
                                   p->material);
        }
    }
    return TIPPE_OK;
}

typedef struct {
    const char *key;
    double value, extent; /* the field, and the part's size it makes */
    int axial;
} size_field;

/* No part is longer than the sphere's diameter in any direction, nor centred
 * beyond it: such a part cannot fit in the ball, and the top would rest on it
 * rather than on its sphere (the model's only contact). A clipped part is cut
 * to a ball no larger than the sphere, so only its fields are bounded. */
static int check_sizes(const tippe_json_reader *c, const tippe_design *d)
{
    const double D = 2 * d->radius_mm;
    char path[64], hint[160];
    for (int i = 0; i < d->n_parts; i++) {
        const part *p = &d->parts[i];
        size_field f[4];
        int n = 0;
        switch (p->shape) {
        case SHAPE_BALL:
        case SHAPE_SHELL:
            f[n++] = (size_field){"radius_mm", p->radius_mm, 2 * p->radius_mm, 0};
            break;
        case SHAPE_CYLINDER:
        case SHAPE_TUBE:
            f[n++] = (size_field){"radius_mm", p->radius_mm, 2 * p->radius_mm, 0};
            if (p->has_height)
                f[n++] = (size_field){"height_mm", p->height_mm, p->height_mm, 1};
            break;
        case SHAPE_TORUS:
        default:
            f[n++] = (size_field){"axial_semi_mm", p->axial_semi_mm, 2 * p->axial_semi_mm, 1};
            if (p->clip) {
                f[n++] = (size_field){"centre_radius_mm", p->centre_radius_mm,
                                        p->centre_radius_mm, 0};
                f[n++] = (size_field){"radial_semi_mm", p->radial_semi_mm, p->radial_semi_mm,
                                        0};
            } else {
                f[n++] = (size_field){"centre_radius_mm", p->centre_radius_mm,
                                        2 * (p->centre_radius_mm + p->radial_semi_mm), 0};
            }
            break;
        }
        for (int k = 0; k < n; k++) {
            if (!(f[k].extent > D + TOL_MM))
                continue;
            snprintf(path, sizeof path, "parts[%d].%s", i, f[k].key);
            unit_hint(f[k].value, LENGTH_HINT_MM, D * f[k].value / f[k].extent, hint,
                      sizeof hint);
            if (f[k].extent == f[k].value || !isfinite(f[k].extent))
                return tippe_json_fail(c, path,
                                       "%g mm is more than the sphere's diameter (%g mm): "
                                       "part '%s' cannot fit in the ball, and the top would "
                                       "rest on it rather than on its sphere%s",
                                       f[k].value, D, p->name, hint);
            return tippe_json_fail(c, path,
                                   "%g mm makes part '%s' %g mm %s, more than the sphere's "
                                   "diameter (%g mm): it cannot fit in the ball, and the top "
                                   "would rest on it rather than on its sphere%s",
                                   f[k].value, p->name, f[k].extent,
                                   f[k].axial ? "long" : "across", D, hint);
        }
        if (fabs(p->z_mm) > D) {
            snprintf(path, sizeof path, "parts[%d].z_mm", i);
            return tippe_json_fail(c, path,
                                   "%g mm puts part '%s' farther from %s than the sphere's "
                                   "diameter (%g mm)",
                                   p->z_mm, p->name, p->moving ? "Z2" : "the sphere's centre",
                                   D);
        }
    }
    return TIPPE_OK;
}

/* The print model's description of p's own region (SI). */
static tippe_solid print_solid(const part *p)
{
    const double mm = 1e-3;
    tippe_solid s = {0};
    s.z_centre = p->z_mm * mm;
    s.radius = p->radius_mm * mm;
    s.clip_outer = p->clip_radius_mm * mm;
    s.clip_inner = p->clip_inner_mm * mm;
    switch (p->shape) {
    case SHAPE_BALL:
        s.kind = TIPPE_SOLID_BALL;
        break;
    case SHAPE_SHELL:
        s.kind = TIPPE_SOLID_SHELL;
        s.inner_radius = (p->radius_mm - p->thickness_mm) * mm;
        break;
    case SHAPE_CYLINDER:
    case SHAPE_TUBE:
        s.kind = TIPPE_SOLID_TUBE;
        s.inner_radius = p->inner_radius_mm * mm;
        s.height = p->height_mm * mm;
        break;
    case SHAPE_TORUS:
    default:
        s.kind = TIPPE_SOLID_TORUS;
        s.centre_radius = p->centre_radius_mm * mm;
        s.radial_semi = p->radial_semi_mm * mm;
        s.axial_semi = p->axial_semi_mm * mm;
        break;
    }
    return s;
}

/* Unit-density moments of printed part i as printed: the part minus its voids
 * (closed forms) less (1 - infill) x its sparse core (print model). Sets the
 * part's infill (calibrated from a weighed mass when one is given), its solid
 * and skin masses and the relative error bound. */
static int printed_moments(const tippe_json_reader *c, tippe_design *d, int i,
                           tippe_moments *out)
{
    part *p = &d->parts[i];
    tippe_solid shape = print_solid(p), holes[MAX_PARTS];
    tippe_moments solid = part_moments(p);
    int n_holes = 0;
    for (int k = 0; k < d->n_parts; k++)
        if (d->parts[k].parent == i) {
            holes[n_holes++] = print_solid(&d->parts[k]);
            solid = tippe_moments_sub(solid, part_moments(&d->parts[k]));
        }
    tippe_print_core core;
    tippe_error perr;
    char pth[64];
    snprintf(pth, sizeof pth, "parts[%d].print", i);
    int rc = tippe_print_core_moments(&shape, holes, n_holes, tippe_print_wall_mm(&p->print) * 1e-3,
                                      tippe_print_skin_mm(&p->print) * 1e-3, &core, &perr);
    if (rc)
        return rc == TIPPE_EINPUT ? tippe_json_fail(c, pth, "%s", perr.msg)
                                  : tippe_error_set(c->err, rc, "%s: %s: %s", c->file, pth,
                                                    perr.msg);
    double rho = p->density_g_cm3 * 1e3;
    p->infill = p->print.infill;
    if (p->calibrated) {
        double m0, m1;
        int side = tippe_print_infill_for_mass(p->measured_mass_g * 1e-3, solid.m, core.core.m,
                                               rho, &p->infill, &m0, &m1);
        snprintf(pth, sizeof pth, "parts[%d].print.measured_mass_g", i);
        if (side < 0)
            return tippe_json_fail(c, pth,
                                   "%g g is less than the walls and top/bottom skins alone "
                                   "weigh (%.3f g at 0 %% infill with these settings and %g "
                                   "g/cm^3)",
                                   p->measured_mass_g, m0 * 1e3, p->density_g_cm3);
        if (side > 0)
            return tippe_json_fail(c, pth,
                                   "%g g is more than part '%s' weighs printed solid (%.3f g at "
                                   "%g g/cm^3)",
                                   p->measured_mass_g, p->name, m1 * 1e3, p->density_g_cm3);
    }
    p->solid_mass_kg = rho * solid.m;
    /* no walls and no skins: the core is the part, up to QAGS's 1e-12 */
    p->skin_mass_kg = rho * fmax(0.0, solid.m - core.core.m);
    /* the error bound of each moment, relative to the printed part's */
    double lack = 1.0 - p->infill, printed_m = solid.m - lack * core.core.m;
    double printed_rr = solid.m_rr - lack * core.core.m_rr;
    if (!(printed_m > 0) || !(printed_rr > 0))
        return tippe_json_fail(c, pth, "part '%s' printed this way has no material (no walls, "
                                       "no skins and 0 infill)",
                               p->name);
    p->print_rel_error = lack * fmax(core.abserr[0] / printed_m, core.abserr[3] / printed_rr);
    /* the part's own region, its voids added back: they subtract as usual */
    *out = tippe_moments_sub(part_moments(p), tippe_moments_scale(core.core, lack));
    return TIPPE_OK;
}

/* Moments: parts add, voids subtract (with the parent's density); the fixed
 * parts and the moving group at Z2 = 0. */
static int sum_moments(const tippe_json_reader *c, tippe_design *d)
{
    d->fixed = d->moving = (tippe_moments){0, 0, 0, 0};
    for (int i = 0; i < d->n_parts; i++) {
        part *p = &d->parts[i];
        tippe_moments unit = part_moments(p);
        int rc;
        if (p->printed && (rc = printed_moments(c, d, i, &unit)))
            return rc;
        tippe_moments m = tippe_moments_scale(unit, p->density_g_cm3 * 1e3);
        if (!finite_moments(m) || !(m.m > 0))
            return tippe_error_set(c->err, TIPPE_ECOMPUTE,
                                   "%s: parts[%d]: the geometry module gave no finite positive "
                                   "mass for part '%s'", c->file, i, p->name);
        p->mass_kg = p->is_void ? -m.m : m.m;
        tippe_moments *into = p->moving ? &d->moving : &d->fixed;
        *into = p->is_void ? tippe_moments_sub(*into, m) : tippe_moments_add(*into, m);
    }
    if (!(d->moving.m > 0) || !(d->fixed.m + d->moving.m > 0))
        return tippe_error_set(c->err, TIPPE_ECOMPUTE, "%s: total or moving mass is not "
                                                       "positive", c->file);
    return TIPPE_OK;
}

/* A parsed (and overridden) design file, checked step by step; check = 0
 * skips the layout checks (overlaps, travel), for tippe_design_derive. */
static int build(tippe_json_reader *c, cJSON *root, const char *path, tippe_design *d,
                 int check)
{
    char mat_rel[512];
    int has_mat_file = 0, rc;
    d->sphere_only_mm[0] = -BIG_MM; /* no layout (a derived design): no limit known */
    d->sphere_only_mm[1] = BIG_MM;
    if ((rc = parse_header(c, root, path, d, mat_rel, sizeof mat_rel, &has_mat_file)) ||
        (rc = parse_parts(c, root, d)) ||
        (rc = resolve_materials(c, path, mat_rel, has_mat_file, d)) ||
        (rc = resolve_parts(c, d)) || (check && (rc = check_sizes(c, d))) ||
        (check && (rc = check_layout(c, d))) ||
        (rc = sum_moments(c, d)))
        return rc;
    if (!check) /* a derived design (a field moved by a tolerance) needs no tolerances */
        return TIPPE_OK;
    return tippe_tolerances_read(c, cJSON_GetObjectItemCaseSensitive(root, "tolerances"), d,
                                 &d->tolerances, &d->n_tolerances);
}

/* Keeps the overrides a design was built with (src/design.c, below), so that
 * tippe_design_derive can rebuild it with more. */
static int remember_overrides(tippe_design *d, const char *const *overrides, int n,
                              tippe_error *err);

static int load(const char *path, const char *const *overrides, int n_overrides, int check,
                tippe_design **out, tippe_error *err)
{
    /* The geometry module may call GSL: report, never abort. */
    tippe_gsl_errors_as_codes();
    *out = NULL;
    if (!path)
        return tippe_error_set(err, TIPPE_EINPUT, "no design file given");
    if (n_overrides < 0)
        n_overrides = 0;
    tippe_json_reader *c =
        tippe_json_reader_new(path, err, TIPPE_JSON_WORDS_FIELD, "set by --set ");
    tippe_design *d = calloc(1, sizeof *d);
    if (!c || !d) {
        free(c);
        tippe_design_free(d);
        return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    }
    cJSON *root = NULL;
    int rc = tippe_json_load(c, MAX_FILE_MIB, "design", &root);
    if (!rc)
        rc = tippe_json_check_duplicates(c, root, "");
    for (int i = 0; !rc && i < n_overrides; i++)
        rc = apply_override(c, root, overrides[i]);
    if (!rc)
        rc = build(c, root, path, d, check);
    if (!rc)
        rc = remember_overrides(d, overrides, n_overrides, err);
    cJSON_Delete(root);
    free(c);
    if (rc) {
        tippe_design_free(d);
        return rc;
    }
    *out = d;
    return TIPPE_OK;
}

int tippe_design_load(const char *path, const char *const *overrides, int n_overrides,
                      tippe_design **out, tippe_error *err)
{
    return load(path, overrides, n_overrides, 1, out, err);
}

int tippe_design_derive(const tippe_design *d, const char *const *extra, int n_extra,
                        tippe_design **out, tippe_error *err)
{
    *out = NULL;
    if (n_extra < 0)
        n_extra = 0;
    const char **all = malloc(((size_t)d->n_overrides + (size_t)n_extra + 1) * sizeof *all);
    if (!all)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    for (int i = 0; i < d->n_overrides; i++)
        all[i] = d->overrides[i];
    for (int i = 0; i < n_extra; i++)
        all[d->n_overrides + i] = extra[i];
    int rc = load(d->path, all, d->n_overrides + n_extra, 0, out, err);
    free(all);
    return rc;
}

/* Part i's length fields below LENGTH_HINT_MM, one at a time (*k counts them
 * across parts): the key, or NULL past the last. */
static const char *small_length(const part *p, int which, double *value)
{
    const struct {
        const char *key;
        double v;
        int on;
    } f[] = {
        {"radius_mm", p->radius_mm, p->shape != SHAPE_TORUS},
        {"inner_radius_mm", p->inner_radius_mm,
         (p->shape == SHAPE_CYLINDER || p->shape == SHAPE_TUBE) && p->inner_radius_mm > 0},
        {"thickness_mm", p->thickness_mm, p->shape == SHAPE_SHELL},
        {"height_mm", p->height_mm,
         (p->shape == SHAPE_CYLINDER || p->shape == SHAPE_TUBE) && p->has_height},
        {"centre_radius_mm", p->centre_radius_mm, p->shape == SHAPE_TORUS},
        {"radial_semi_mm", p->radial_semi_mm, p->shape == SHAPE_TORUS},
        {"axial_semi_mm", p->axial_semi_mm, p->shape == SHAPE_TORUS},
    };
    for (size_t j = 0; j < sizeof f / sizeof f[0]; j++)
        if (f[j].on && f[j].v < LENGTH_HINT_MM && which-- == 0) {
            *value = f[j].v;
            return f[j].key;
        }
    return NULL;
}

int tippe_design_warning(const tippe_design *d, int i, char *buf, size_t size)
{
    int k = 0;
    for (int j = 0; j < d->n_parts; j++) {
        const part *p = &d->parts[j];
        double v;
        const char *key;
        for (int w = 0; (key = small_length(p, w, &v)) != NULL; w++) {
            if (k++ != i)
                continue;
            char hint[160];
            unit_hint(v, LENGTH_HINT_MM, 2 * d->radius_mm, hint, sizeof hint);
            snprintf(buf, size,
                     "parts[%d].%s: %g mm (part '%s') is finer than anything printed or "
                     "machined (lengths in a design are in mm)%s",
                     j, key, v, p->name, hint);
            return 1;
        }
    }
    return 0;
}

void tippe_design_protrusion_text(const tippe_design_protrusion *p, char *buf, size_t size)
{
    snprintf(buf, size,
             "part '%s' stands out of the sphere by %.3f mm near the %cz pole: the top rests "
             "on it, not on its sphere, for theta %.1f .. %.1f deg",
             p->part, p->protrusion_mm, p->pole > 0 ? '+' : '-', p->theta_from_rad * 180 / M_PI,
             p->theta_to_rad * 180 / M_PI);
}

void tippe_design_sphere_only_mm(const tippe_design *d, double *from_mm, double *to_mm)
{
    *from_mm = d->sphere_only_mm[0];
    *to_mm = d->sphere_only_mm[1];
}

int tippe_design_protrusion_at(const tippe_design *d, double z2_mm, tippe_design_protrusion *out)
{
    memset(out, 0, sizeof *out);
    const double *so = d->sphere_only_mm;
    if (!d->rs || !isfinite(z2_mm) ||
        (z2_mm >= so[0] - TRAVEL_SLACK_MM && z2_mm <= so[1] + TRAVEL_SLACK_MM))
        return 0;
    const double R = d->radius_mm;
    double worst = 0, worst_z = 0, a_lo = INFINITY, a_hi = -INFINITY;
    int worst_i = -1;
    ivset a;
    for (int i = 0; i < d->n_parts; i++) {
        const part *p = &d->parts[i];
        if (p->is_void)
            continue;
        for (int k = 0; k < d->nr; k++) {
            const double r = d->rs[k];
            material_ivs(d, i, r, p->moving ? z2_mm : 0, &a);
            for (int u = 0; u < 2 * a.n; u++) {
                /* p . n = r sin(alpha) + z cos(alpha) is linear in z: at each r an
                 * interval's end is the material farthest along any direction */
                const double z = u % 2 ? a.hi[u / 2] : a.lo[u / 2], rho = hypot(r, z);
                if (!(rho > R + TOL_MM))
                    continue;
                const double beta = atan2(r, z), w = acos(R / rho);
                a_lo = fmin(a_lo, fmax(0.0, beta - w));
                a_hi = fmax(a_hi, fmin(M_PI, beta + w));
                if (rho - R > worst) {
                    worst = rho - R;
                    worst_z = z;
                    worst_i = i;
                }
            }
        }
    }
    if (worst_i < 0)
        return 0;
    out->protrusion_mm = worst;
    snprintf(out->part, sizeof out->part, "%s", d->parts[worst_i].name);
    out->pole = worst_z >= 0 ? 1 : -1;
    /* theta = 0 rests on the centre of mass's side: the -z pole when it is below */
    tippe_top t;
    tippe_design_top_any(d, z2_mm, &t);
    out->theta_from_rad = t.com_side < 0 ? M_PI - a_hi : a_lo;
    out->theta_to_rad = t.com_side < 0 ? M_PI - a_lo : a_hi;
    return 1;
}

void tippe_design_free(tippe_design *d)
{
    if (!d)
        return;
    for (int i = 0; d->overrides && i < d->n_overrides; i++)
        free(d->overrides[i]);
    free(d->overrides);
    free(d->tolerances);
    free(d->rs);
    free(d->path);
    free(d->name);
    free(d->parts);
    free(d);
}

/* ------------------------------------------------------------------ top */

void tippe_design_top_any(const tippe_design *d, double z2_mm, tippe_top *top)
{
    tippe_moments all = tippe_moments_add(d->fixed, tippe_moments_shift(d->moving, z2_mm * 1e-3));
    tippe_inertia in = tippe_moments_inertia(all);
    top->m = in.m;
    top->R = d->radius_mm * 1e-3;
    top->A = in.A;
    top->C = in.C;
    /* A CoM within 1e-12 R of the centre is roundoff of a symmetric design:
     * call it centred, so that Z2 = 0 reads eps = 0 and not +-1e-19 m. */
    if (fabs(in.z_cm) <= 1e-12 * top->R) {
        top->eps = 0;
        top->com_side = 0;
    } else {
        top->eps = fabs(in.z_cm);
        top->com_side = in.z_cm > 0 ? 1 : -1;
    }
}

int tippe_design_top(const tippe_design *d, double z2_mm, tippe_top *top, tippe_error *err)
{
    if (!isfinite(z2_mm))
        return tippe_error_set(err, TIPPE_EINPUT, "%s: Z2 must be a finite number of mm",
                               d->path);
    if (z2_mm < d->travel_mm[0] - TRAVEL_SLACK_MM || z2_mm > d->travel_mm[1] + TRAVEL_SLACK_MM)
        return tippe_error_set(err, TIPPE_EINPUT,
                               "%s: travel_mm: Z2 = %g mm is outside the design's travel "
                               "[%g, %g] mm",
                               d->path, z2_mm, d->travel_mm[0], d->travel_mm[1]);
    tippe_design_top_any(d, z2_mm, top);
    if (!(top->m > 0) || !(top->A > 0) || !(top->C > 0) || !isfinite(top->eps))
        return tippe_error_set(err, TIPPE_ECOMPUTE,
                               "%s: at Z2 = %g mm the mass properties are not physical "
                               "(m = %g kg, A = %g, C = %g kg m^2)",
                               d->path, z2_mm, top->m, top->A, top->C);
    if (top->eps >= top->R)
        return tippe_error_set(err, TIPPE_EINPUT,
                               "%s: at Z2 = %g mm the centre of mass (%g mm from the centre) "
                               "lies outside the sphere",
                               d->path, z2_mm, top->eps * 1e3);
    return TIPPE_OK;
}

/* -------------------------------------------------------------- accessors */

void tippe_design_travel_mm(const tippe_design *d, double *from_mm, double *to_mm)
{
    *from_mm = d->travel_mm[0];
    *to_mm = d->travel_mm[1];
}

void tippe_design_contact_travel_mm(const tippe_design *d, double *from_mm, double *to_mm)
{
    *from_mm = d->contact_mm[0];
    *to_mm = d->contact_mm[1];
}

const char *tippe_design_contact_limit(const tippe_design *d, int upper)
{
    return d->contact_limit[upper ? 1 : 0];
}

const char *tippe_design_name(const tippe_design *d) { return d->name; }
const char *tippe_design_path(const tippe_design *d) { return d->path; }
double tippe_design_radius_mm(const tippe_design *d) { return d->radius_mm; }
double tippe_design_moving_mass_kg(const tippe_design *d) { return d->moving.m; }
int tippe_design_n_parts(const tippe_design *d) { return d->n_parts; }

int tippe_design_part(const tippe_design *d, int i, tippe_design_part_info *out)
{
    if (i < 0 || i >= d->n_parts)
        return tippe_error_set(NULL, TIPPE_EINPUT, "no part %d", i);
    const part *p = &d->parts[i];
    out->name = p->name;
    out->shape = shape_names[p->shape];
    out->material = p->material[0] ? p->material : "(inline)";
    out->role = role_of(p);
    out->cut_from = p->is_void ? d->parts[p->parent].name : NULL;
    out->density_g_cm3 = p->density_g_cm3;
    out->mass_kg = p->mass_kg;
    out->z_mm = p->z_mm;
    out->may_protrude = p->may_protrude;
    out->printable = p->printable;
    return TIPPE_OK;
}

int tippe_design_part_fit(const tippe_design *d, int i)
{
    return i < 0 || i >= d->n_parts ? TIPPE_DESIGN_FIT_NONE : d->parts[i].fit;
}

int tippe_design_part_print(const tippe_design *d, int i, tippe_design_print_info *out)
{
    memset(out, 0, sizeof *out);
    if (i < 0 || i >= d->n_parts)
        return tippe_error_set(NULL, TIPPE_EINPUT, "no part %d", i);
    const part *p = &d->parts[i];
    if (!p->printed)
        return TIPPE_OK;
    out->printed = 1;
    out->settings = p->print;
    out->wall_mm = tippe_print_wall_mm(&p->print);
    out->skin_mm = tippe_print_skin_mm(&p->print);
    out->infill = p->infill;
    out->calibrated = p->calibrated;
    out->measured_mass_kg = p->calibrated ? p->measured_mass_g * 1e-3 : 0;
    out->solid_mass_kg = p->solid_mass_kg;
    out->skin_mass_kg = p->skin_mass_kg;
    out->printed_mass_kg = p->skin_mass_kg + p->infill * (p->solid_mass_kg - p->skin_mass_kg);
    out->rel_error = p->print_rel_error;
    return TIPPE_OK;
}

int tippe_design_has_printed_parts(const tippe_design *d)
{
    for (int i = 0; i < d->n_parts; i++)
        if (d->parts[i].printed)
            return 1;
    return 0;
}

int tippe_design_part_printable(const tippe_design *d, int i)
{
    return i >= 0 && i < d->n_parts && d->parts[i].printable;
}

/* ------------------------------------------------------ numeric fields */

/* The length fields a part of this shape has, and where each lives. */
static double *length_field(part *p, const char *key)
{
    int cyl = p->shape == SHAPE_CYLINDER || p->shape == SHAPE_TUBE;
    if (!strcmp(key, "radius_mm") && p->shape != SHAPE_TORUS)
        return &p->radius_mm;
    if (!strcmp(key, "thickness_mm") && p->shape == SHAPE_SHELL)
        return &p->thickness_mm;
    if (!strcmp(key, "inner_radius_mm") && cyl)
        return &p->inner_radius_mm;
    if (!strcmp(key, "height_mm") && cyl)
        return &p->height_mm;
    if (p->shape == SHAPE_TORUS) {
        if (!strcmp(key, "centre_radius_mm"))
            return &p->centre_radius_mm;
        if (!strcmp(key, "radial_semi_mm"))
            return &p->radial_semi_mm;
        if (!strcmp(key, "axial_semi_mm"))
            return &p->axial_semi_mm;
    }
    return NULL;
}

/* Index of the part a "parts.NAME" / "parts[I]" prefix (len characters of
 * field) names, or -1. */
static int part_named(const tippe_design *d, const char *field, size_t len)
{
    if (len > 7 && field[5] == '[') {
        char *end = NULL;
        long i = strtol(field + 6, &end, 10);
        return end == field + len - 1 && *end == ']' && i >= 0 && i < d->n_parts ? (int)i : -1;
    }
    for (int i = 0; i < d->n_parts; i++)
        if (strlen(d->parts[i].name) == len - 6 && !strncmp(d->parts[i].name, field + 6, len - 6))
            return i;
    return -1;
}

/* parts.NAME.print.KEY: the print settings that are numbers (infill: the one
 * used, calibrated or not). */
static int print_field(const tippe_design *d, int i, const char *key, double *value,
                       int *part_index, char *why, size_t why_cap)
{
    const part *p = &d->parts[i];
    *part_index = i;
    if (!p->printed) {
        snprintf(why, why_cap, "part '%s' has no print block", p->name);
        return TIPPE_EINPUT;
    }
    if (!strcmp(key, "infill"))
        *value = p->infill;
    else if (!strcmp(key, "line_width_mm"))
        *value = p->print.line_width_mm;
    else if (!strcmp(key, "layer_height_mm"))
        *value = p->print.layer_height_mm;
    else if (!strcmp(key, "perimeters"))
        *value = p->print.perimeters;
    else if (!strcmp(key, "top_bottom_layers"))
        *value = p->print.top_bottom_layers;
    else if (!strcmp(key, "measured_mass_g") && p->calibrated)
        *value = p->measured_mass_g;
    else {
        snprintf(why, why_cap, "not a number setting of the print block (infill, "
                               "line_width_mm, layer_height_mm, perimeters, "
                               "top_bottom_layers, measured_mass_g when given)");
        return TIPPE_EINPUT;
    }
    return TIPPE_OK;
}

int tippe_design_field(const tippe_design *d, const char *field, double *value, int *part_index,
                       char *why, size_t why_cap)
{
    *part_index = -1;
    if (!strcmp(field, "radius_mm")) {
        *value = d->radius_mm;
        return TIPPE_OK;
    }
    const char *dot = strrchr(field, '.');
    if (strncmp(field, "parts", 5) || (field[5] != '.' && field[5] != '[') || !dot ||
        dot < field + 6) {
        snprintf(why, why_cap, "not a number field of the design (radius_mm, "
                               "parts.NAME.FIELD or parts[I].FIELD)");
        return TIPPE_EINPUT;
    }
    int i = part_named(d, field, (size_t)(dot - field));
    size_t plen = (size_t)(dot - field);
    if (i < 0 && plen > 12 && !strncmp(dot - 6, ".print", 6) &&
        (i = part_named(d, field, plen - 6)) >= 0)
        return print_field(d, i, dot + 1, value, part_index, why, why_cap);
    if (i < 0) {
        snprintf(why, why_cap, "no part %.*s", (int)(dot - field - 5), field + 5);
        return TIPPE_EINPUT;
    }
    part *p = &d->parts[i];
    const char *key = dot + 1;
    *part_index = i;
    if (!strcmp(key, "z_mm")) {
        *value = p->z_mm;
        return TIPPE_OK;
    }
    if (!strcmp(key, "density_g_cm3")) {
        if (p->is_void) {
            snprintf(why, why_cap, "a void has its part's density: give the tolerance to "
                                   "'%s'", d->parts[p->parent].name);
            return TIPPE_EINPUT;
        }
        *value = p->density_g_cm3;
        return TIPPE_OK;
    }
    const double *v = length_field(p, key);
    if (!v) {
        snprintf(why, why_cap, "not a number field of a %s (radius_mm, ... as the shape has; "
                               "z_mm; density_g_cm3)", shape_names[p->shape]);
        return TIPPE_EINPUT;
    }
    if (!strcmp(key, "height_mm") && !p->has_height) {
        snprintf(why, why_cap, "the height is not in the file: the part spans its clip ball, "
                               "so the clip decides it");
        return TIPPE_EINPUT;
    }
    if (!strcmp(key, "radius_mm") && tippe_design_forms_sphere(d, i)) {
        snprintf(why, why_cap, "the part forms the sphere the top rolls on: its radius is "
                               "radius_mm (give the tolerance there)");
        return TIPPE_EINPUT;
    }
    *value = *v;
    return TIPPE_OK;
}

int tippe_design_part_lengths(const tippe_design *d, int i, const char **keys, int cap)
{
    static const char *const all[] = {"radius_mm", "thickness_mm", "inner_radius_mm",
                                      "height_mm", "centre_radius_mm", "radial_semi_mm",
                                      "axial_semi_mm"};
    if (i < 0 || i >= d->n_parts)
        return 0;
    part *p = &d->parts[i];
    int n = 0;
    for (size_t k = 0; k < sizeof all / sizeof all[0] && n < cap; k++) {
        const double *v = length_field(p, all[k]);
        if (!v || *v <= 0 || (!strcmp(all[k], "height_mm") && !p->has_height) ||
            (!strcmp(all[k], "radius_mm") && tippe_design_forms_sphere(d, i)))
            continue;
        keys[n++] = all[k];
    }
    return n;
}

int tippe_design_forms_sphere(const tippe_design *d, int i)
{
    if (i < 0 || i >= d->n_parts)
        return 0;
    const part *p = &d->parts[i];
    return !p->is_void && !p->moving && (p->shape == SHAPE_BALL || p->shape == SHAPE_SHELL) &&
           fabs(p->radius_mm - d->radius_mm) < SAME_LENGTH_MM && p->z_mm == 0;
}

int tippe_design_n_tolerances(const tippe_design *d) { return d->n_tolerances; }

const tippe_tolerance *tippe_design_tolerance(const tippe_design *d, int i)
{
    return i >= 0 && i < d->n_tolerances ? &d->tolerances[i] : NULL;
}

/* ------------------------------------------ physical travel without a guess */

typedef struct {
    double lo, hi;
} shift_iv;

static int cmp_shift(const void *a, const void *b)
{
    const shift_iv *x = a, *y = b;
    return (x->lo > y->lo) - (x->lo < y->lo);
}

static int push_shift(shift_iv **v, int *n, int *cap, double lo, double hi)
{
    if (*n == *cap) {
        int nc = *cap ? 2 * *cap : 256;
        shift_iv *t = realloc(*v, (size_t)nc * sizeof *t);
        if (!t)
            return -1;
        *v = t;
        *cap = nc;
    }
    (*v)[(*n)++] = (shift_iv){lo, hi};
    return 0;
}

/* The middle of the widest stretch of Z2 where no moving part overlaps a fixed
 * one or leaves the sphere: the Z2 shifts that make a moving z interval share
 * volume with a fixed one are open intervals (the same arithmetic as the
 * physical travel in check_layout), and the stretch is a gap between their
 * union. Used when the travel is to be the physical one (an optimiser's
 * candidate, whose stated travel means nothing); NAN when there is no gap. */
static double widest_free_gap_mid(const tippe_design *d, const double *rs, int nr)
{
    shift_iv *v = NULL;
    int n = 0, cap = 0, oom = 0;
    const double R = d->radius_mm;
    ivset a, b;
    for (int i = 0; i < d->n_parts && !oom; i++) {
        const part *p = &d->parts[i];
        if (p->is_void || !p->moving)
            continue;
        if (p->may_protrude) /* held only while its centre is inside */
            oom |= push_shift(&v, &n, &cap, -BIG_MM, -R - p->z_mm) ||
                   push_shift(&v, &n, &cap, R - p->z_mm, BIG_MM);
        for (int j = -1; j < d->n_parts && !oom; j++) {
            if (j < 0 ? p->may_protrude : (d->parts[j].is_void || d->parts[j].moving))
                continue;
            for (int k = 0; k < nr && !oom; k++) {
                material_ivs(d, i, rs[k], 0, &a);
                if (!a.n)
                    continue;
                if (j < 0)
                    outside_ivs(R, rs[k], &b);
                else
                    material_ivs(d, j, rs[k], 0, &b);
                for (int u = 0; u < a.n && !oom; u++)
                    for (int w = 0; w < b.n && !oom; w++)
                        oom |= push_shift(&v, &n, &cap, b.lo[w] - a.hi[u], b.hi[w] - a.lo[u]);
            }
        }
    }
    double best = 0.0, mid = NAN;
    if (!oom) {
        qsort(v, (size_t)n, sizeof *v, cmp_shift);
        double reach = -BIG_MM; /* the union of intervals so far ends here */
        for (int k = 0; k <= n; k++) {
            double next = k < n ? v[k].lo : BIG_MM;
            if (next > reach && next - reach > best) {
                best = next - reach;
                mid = 0.5 * (next + reach);
            }
            if (k < n)
                reach = fmax(reach, v[k].hi);
        }
    }
    free(v);
    return mid;
}

/* ------------------------------------------------------- design sources */

struct tippe_design_source {
    char *path;
    cJSON *root;      /* the design file as parsed (duplicate keys refused) */
    char mat_file[1024];
    cJSON *materials; /* the materials table it names, read and checked once; or NULL */
};

/* The source's materials table (a copy the caller deletes) if it is the one
 * build() is about to read; 0 if not. */
static int source_materials(const tippe_design *d, const char *mat_file, cJSON **out)
{
    if (!d->source || !d->source->materials || strcmp(mat_file, d->source->mat_file))
        return 0;
    *out = cJSON_Duplicate(d->source->materials, 1);
    return *out != NULL;
}

int tippe_design_source_open(const char *path, tippe_design_source **out, tippe_error *err)
{
    tippe_gsl_errors_as_codes();
    *out = NULL;
    /* A first full load checks the file and resolves its materials table. */
    tippe_design *d = NULL;
    int rc = tippe_design_load(path, NULL, 0, &d, err);
    if (rc)
        return rc;
    tippe_design_free(d);
    tippe_design_source *s = calloc(1, sizeof *s);
    tippe_json_reader *c = tippe_json_reader_new(path, err, TIPPE_JSON_WORDS_FIELD, NULL);
    if (!s || !c || !(s->path = dup_string(path))) {
        rc = tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
        goto fail;
    }
    if ((rc = tippe_json_load(c, MAX_FILE_MIB, "design", &s->root)))
        goto fail;
    char mat_rel[512] = "materials.json";
    const cJSON *m = cJSON_GetObjectItemCaseSensitive(s->root, "materials");
    if (cJSON_IsString(m))
        snprintf(mat_rel, sizeof mat_rel, "%s", m->valuestring);
    const char *slash = strrchr(path, '/');
    if (mat_rel[0] == '/' || !slash)
        snprintf(s->mat_file, sizeof s->mat_file, "%s", mat_rel);
    else
        snprintf(s->mat_file, sizeof s->mat_file, "%.*s/%s", (int)(slash - path), path, mat_rel);
    tippe_error ignored = {0};
    /* A design with inline densities only has no table: then none is cached. */
    if (load_materials(s->mat_file, &s->materials, &ignored))
        s->materials = NULL;
    free(c);
    *out = s;
    return TIPPE_OK;
fail:
    free(c);
    tippe_design_source_free(s);
    return rc;
}

int tippe_design_source_apply(const tippe_design_source *s, const char *const *overrides,
                              int n_overrides, cJSON **out, tippe_error *err)
{
    *out = NULL;
    tippe_json_reader *c = tippe_json_reader_new(s->path, err, TIPPE_JSON_WORDS_FIELD, "set by ");
    cJSON *root = cJSON_Duplicate(s->root, 1);
    int rc = (!c || !root) ? tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory") : TIPPE_OK;
    for (int i = 0; !rc && i < n_overrides; i++)
        rc = apply_override(c, root, overrides[i]);
    free(c);
    if (rc) {
        cJSON_Delete(root);
        return rc;
    }
    *out = root;
    return TIPPE_OK;
}

/* A built variant remembers its overrides (and its travel, when that was the
 * physical one) so that tippe_design_derive() rebuilds the same design. */
static int remember_overrides(tippe_design *d, const char *const *overrides, int n,
                              tippe_error *err)
{
    if (!(d->overrides = calloc((size_t)n + 1, sizeof *d->overrides)))
        return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    char travel[128];
    snprintf(travel, sizeof travel, "travel_mm=[%.17g,%.17g]", d->travel_mm[0], d->travel_mm[1]);
    for (int i = 0; i <= n; i++) {
        if (i == n && !d->travel_physical)
            break;
        if (!(d->overrides[d->n_overrides++] = dup_string(i < n ? overrides[i] : travel)))
            return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    }
    return TIPPE_OK;
}

int tippe_design_source_build(const tippe_design_source *s, const char *const *overrides,
                              int n_overrides, unsigned flags, tippe_design **out,
                              tippe_error *err)
{
    *out = NULL;
    tippe_json_reader *c = tippe_json_reader_new(s->path, err, TIPPE_JSON_WORDS_FIELD, "set by ");
    cJSON *root = cJSON_Duplicate(s->root, 1);
    tippe_design *d = calloc(1, sizeof *d);
    int rc = (!c || !root || !d) ? tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory")
                                 : TIPPE_OK;
    for (int i = 0; !rc && i < n_overrides; i++)
        rc = apply_override(c, root, overrides[i]);
    if (!rc) {
        d->source = s;
        d->travel_physical = (flags & TIPPE_DESIGN_TRAVEL_PHYSICAL) != 0;
        d->coarse_layout = (flags & TIPPE_DESIGN_COARSE_LAYOUT) != 0;
        rc = build(c, root, s->path, d, 1);
        d->source = NULL;
    }
    if (!rc)
        rc = remember_overrides(d, overrides, n_overrides, err);
    cJSON_Delete(root);
    free(c);
    if (rc) {
        tippe_design_free(d);
        return rc;
    }
    *out = d;
    return TIPPE_OK;
}

const char *tippe_design_source_path(const tippe_design_source *s) { return s->path; }

void tippe_design_source_free(tippe_design_source *s)
{
    if (!s)
        return;
    free(s->path);
    cJSON_Delete(s->root);
    cJSON_Delete(s->materials);
    free(s);
}

/* ------------------------------------------------------------ printability */

/* Thinnest wall around a hole (a cylinder or tube void cut from a fixed ball):
 * the side wall at the hole's layer nearest the ball's centre (the widest ring
 * of material around it), and a floor or roof where the hole ends inside the
 * ball (measured along the hole's wall, r = its radius, where it is thinnest).
 * Where a hole opens through the surface its rim thins to nothing in every
 * drilled ball; that is not counted. INFINITY if there is no such hole. */
double tippe_design_min_hole_wall_mm(const tippe_design *d, const char **hole)
{
    double wall = INFINITY;
    if (hole)
        *hole = NULL;
    for (int i = 0; i < d->n_parts; i++) {
        const part *p = &d->parts[i];
        if (!p->is_void || p->moving || (p->shape != SHAPE_CYLINDER && p->shape != SHAPE_TUBE))
            continue;
        const part *q = &d->parts[p->parent];
        if (q->shape != SHAPE_BALL)
            continue;
        double a = p->radius_mm, rb = q->radius_mm, zb = q->z_mm;
        double lo = p->z_mm - p->height_mm / 2, hi = p->z_mm + p->height_mm / 2;
        double open_at = p->clip_radius_mm > a ? sqrt(p->clip_radius_mm * p->clip_radius_mm - a * a)
                                               : INFINITY; /* the clip opens the hole there */
        double surf = rb > a ? sqrt(rb * rb - a * a) : 0.0; /* ball surface at r = a */
        double zs = fmin(fmax(zb, lo), hi);
        double w = rb * rb > (zs - zb) * (zs - zb) ? sqrt(rb * rb - (zs - zb) * (zs - zb)) - a : -a;
        if (lo > -open_at + TOL_MM)
            w = fmin(w, lo - (zb - surf));
        if (hi < open_at - TOL_MM)
            w = fmin(w, (zb + surf) - hi);
        if (w < wall) {
            wall = w;
            if (hole)
                *hole = p->name;
        }
    }
    return wall;
}

int tippe_design_part_solid(const tippe_design *d, int i, tippe_design_solid *out)
{
    if (i < 0 || i >= d->n_parts)
        return tippe_error_set(NULL, TIPPE_EINPUT, "no part %d", i);
    const part *p = &d->parts[i];
    *out = (tippe_design_solid){.shape = shape_names[p->shape],
                                .is_void = p->is_void,
                                .moving = p->moving,
                                .parent = p->parent,
                                .z_mm = p->z_mm,
                                .clip_radius_mm = p->clip_radius_mm,
                                .clip_inner_mm = p->clip_inner_mm};
    switch (p->shape) {
    case SHAPE_BALL:
        out->radius_mm = p->radius_mm;
        break;
    case SHAPE_SHELL:
        out->radius_mm = p->radius_mm;
        out->thickness_mm = p->thickness_mm;
        break;
    case SHAPE_CYLINDER:
    case SHAPE_TUBE:
        out->radius_mm = p->radius_mm;
        out->inner_radius_mm = p->inner_radius_mm;
        out->height_mm = p->height_mm;
        break;
    default:
        out->centre_radius_mm = p->centre_radius_mm;
        out->radial_semi_mm = p->radial_semi_mm;
        out->axial_semi_mm = p->axial_semi_mm;
        break;
    }
    return TIPPE_OK;
}
