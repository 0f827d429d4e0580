/* The parts of a design file and the materials table: their keys, each part's
 * shape, dimensions and material read and checked (naming the file and field). */
#include "design/internal.h"

#include <cjson/cJSON.h>
#include <gsl/gsl_errno.h>

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

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
void tippe_design_field_range(const char *field, double *lo, double *hi)
{
    static const struct {
        const char *key;
        double lo, hi;
    } print[] = {
        {"line_width_mm", PRINT_LINE_WIDTH_MIN_MM, PRINT_LINE_WIDTH_MAX_MM},
        {"layer_height_mm", PRINT_LAYER_HEIGHT_MIN_MM, PRINT_LAYER_HEIGHT_MAX_MM},
        {"infill", PRINT_INFILL_MIN, PRINT_INFILL_MAX},
        {"measured_mass_g", PRINT_MEASURED_MASS_MIN_G, PRINT_MEASURED_MASS_MAX_G},
        {"calibration", PRINT_CALIBRATION_MIN, PRINT_CALIBRATION_MAX},
        {"solid_infill_below_area_mm2", 0, PRINT_SOLID_BELOW_AREA_MAX_MM2},
    };
    const char *dot = strrchr(field, '.'), *key = dot ? dot + 1 : field;
    *lo = -INFINITY;
    *hi = INFINITY;
    if (!strcmp(field, "radius_mm")) { /* the sphere's */
        *lo = RADIUS_MIN_MM;
        *hi = RADIUS_MAX_MM;
    } else if (!strcmp(key, "density_g_cm3")) {
        *lo = 0;
        *hi = DENSITY_MAX_G_CM3;
    } else if (strstr(field, ".print.")) {
        for (size_t i = 0; i < sizeof print / sizeof print[0]; i++)
            if (!strcmp(key, print[i].key)) {
                *lo = print[i].lo;
                *hi = print[i].hi;
            }
    } else if (strcmp(key, "z_mm")) { /* a part's length */
        *lo = 0;
    }
}

/* A length in mm that must be > 0 (or >= 0 with allow_zero). */
int tippe_design_read_length(const tippe_json_reader *c, const cJSON *obj, const char *prefix,
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
    if (*out > 0 && *out < LENGTH_MIN_MM)
        return tippe_json_fail(c, p,
                               "%g mm is below %g mm, smaller than an atom: nothing is that thin "
                               "(lengths in a design are in mm)",
                               *out, LENGTH_MIN_MM);
    return TIPPE_OK;
}

/* ---------------------------------------------------------------- schema */

const char *const tippe_design_top_keys[] = {"name", "notes", "radius_mm", "travel_mm", "materials",
                                       "catalogue", "parts", "tolerances", NULL};
const char *const tippe_design_top_string_keys[] = {"name", "notes", "materials", "catalogue",
                                                    NULL};
static const char *const part_common_keys[] = {
    "name", "shape", "notes", "z_mm", "material", "density_g_cm3", "void", "cut_from",
    "clip", "moving", "may_protrude", "print", "fit", "catalogue_item", NULL};
const char *const tippe_design_part_string_keys[] = {"name", "shape", "notes", "material",
                                               "cut_from", "clip", "fit", "catalogue_item",
                                               NULL};
static const char *const ball_keys[] = {"radius_mm", NULL};
static const char *const shell_keys[] = {"radius_mm", "thickness_mm", NULL};
static const char *const cylinder_keys[] = {"radius_mm", "inner_radius_mm", "height_mm",
                                            "printed_radius_mm", NULL};
static const char *const torus_keys[] = {"centre_radius_mm", "radial_semi_mm", "axial_semi_mm",
                                         NULL};
static const char *const *const shape_keys[N_SHAPES] = {ball_keys, shell_keys, cylinder_keys,
                                                        cylinder_keys, torus_keys};
const char *const tippe_design_all_part_keys[] = {
    "name", "shape", "notes", "z_mm", "material", "density_g_cm3", "void", "cut_from", "clip",
    "moving", "may_protrude", "print", "fit", "catalogue_item", "radius_mm", "inner_radius_mm",
    "thickness_mm", "printed_radius_mm",
    "height_mm", "centre_radius_mm", "radial_semi_mm", "axial_semi_mm", NULL};
const char *const tippe_design_print_keys[] = {
    "perimeters", "line_width_mm", "top_bottom_layers", "layer_height_mm", "infill",
    "measured_mass_g", "notes", "model", "pattern", "external_width_mm", "infill_width_mm",
    "first_layer_height_mm", "first_layer_width_mm", "top_min_mm", "bottom_min_mm",
    "infill_overlap", "flow", "gcode", "calibration", "split", "split_z_mm",
    "filament_diameter_mm", "model_error", "thick_bridges", "solid_infill_below_area_mm2",
    "perimeter_generator", NULL};
/* The print settings that are text (--set writes them as strings). */
const char *const tippe_design_print_string_keys[] = {"notes", "model", "pattern", "gcode",
                                                      "perimeter_generator", NULL};
static const char *const material_keys[] = {"density_g_cm3", "source", "printable", "notes",
                                             "E_GPa", "nu", "elastic_source", "set_screws",
                                             NULL};

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

/* A text field that names one of n choices: *value the chosen one's, untouched when the
 * field is absent; an unknown name is an error naming the field, what it should be
 * (`what`) and the choices (`hint`). */
static int parse_choice(const tippe_json_reader *c, const cJSON *item, const char *path,
                        const char *key, const char *const names[], const int values[], int n,
                        const char *what, const char *hint, int *value)
{
    char text[64] = "", full[96];
    int rc, here = 0;
    if ((rc = tippe_json_string(c, item, path, key, 0, text, sizeof text, &here)) || !here)
        return rc;
    for (int k = 0; k < n; k++)
        if (!strcmp(text, names[k])) {
            *value = values[k];
            return 0;
        }
    tippe_json_path(full, sizeof full, path, key);
    return tippe_json_fail(c, full, "'%s' is not a %s (%s)", text, what, hint);
}

/* The print block's settings of the slicer's rules (docs/design-format.md):
 * which model, the infill pattern, the widths the slicer's flow takes, the
 * first layer, the minimum skin thicknesses, the overlap, the flow, and a
 * G-code of the part (a path relative to the design file). The widths of the
 * external perimeter and the infill default to line_width_mm, as a slicer
 * profile whose widths are all one. */
static int parse_print_rules(const tippe_json_reader *c, const cJSON *item, const char *path,
                             part *p)
{
    tippe_print_settings *s = &p->print;
    char text[64] = "", full[96];
    int rc, here = 0;
    s->external_width_mm = s->infill_width_mm = s->line_width_mm;
    static const char *const models[] = {"slicer", "skins"};
    static const int model_values[] = {TIPPE_PRINT_MODEL_SLICER, TIPPE_PRINT_MODEL_SKINS};
    int choice = -1;
    if ((rc = parse_choice(c, item, path, "model", models, model_values, 2, "print model",
                           "slicer: PrusaSlicer's rules layer by layer; skins: the continuous "
                           "rule",
                           &choice)))
        return rc;
    if (choice >= 0)
        s->model = choice;
    if ((rc = tippe_json_string(c, item, path, "pattern", 0, text, sizeof text, &here)))
        return rc;
    if (here && (s->pattern = tippe_print_pattern_parse(text)) < 0) {
        char list[400] = "";
        for (int k = 0; k < TIPPE_PRINT_N_PATTERNS; k++)
            snprintf(list + strlen(list), sizeof list - strlen(list), "%s%s", k ? ", " : "",
                     tippe_print_pattern_name(k));
        tippe_json_path(full, sizeof full, path, "pattern");
        return tippe_json_fail(c, full, "'%s' is not a PrusaSlicer infill pattern (%s)", text,
                               list);
    }
    static const char *const generators[] = {"arachne", "classic"};
    static const int generator_values[] = {TIPPE_PERIMETERS_ARACHNE, TIPPE_PERIMETERS_CLASSIC};
    choice = -1;
    if ((rc = parse_choice(c, item, path, "perimeter_generator", generators, generator_values, 2,
                           "PrusaSlicer perimeter generator", "arachne or classic", &choice)))
        return rc;
    if (choice >= 0)
        s->perimeter_generator = choice;
    if ((rc = tippe_json_string(c, item, path, "gcode", 0, p->gcode, sizeof p->gcode, &here)))
        return rc;
    if ((rc = print_number(c, item, path, "external_width_mm", 0.05, 3, 0, "mm",
                           &s->external_width_mm)) ||
        (rc = print_number(c, item, path, "infill_width_mm", 0.05, 3, 0, "mm",
                           &s->infill_width_mm)) ||
        (rc = print_number(c, item, path, "first_layer_height_mm", 0.01, 2, 0, "mm",
                           &s->first_layer_height_mm)) ||
        (rc = print_number(c, item, path, "first_layer_width_mm", 0, 3, 0,
                           "mm (0: each line its own width)", &s->first_layer_width_mm)) ||
        (rc = print_number(c, item, path, "top_min_mm", 0, 100, 0, "mm", &s->top_min_mm)) ||
        (rc = print_number(c, item, path, "bottom_min_mm", 0, 100, 0, "mm", &s->bottom_min_mm)) ||
        (rc = print_number(c, item, path, "infill_overlap", 0, 1, 0,
                           "(a fraction of the perimeter spacing: 25 % is 0.25)",
                           &s->infill_overlap)) ||
        (rc = print_number(c, item, path, "flow", 0.5, 1.5, 0, "(extrusion multiplier)",
                           &s->flow)) ||
        (rc = tippe_json_bool(c, item, path, "split", &s->split, NULL)) ||
        (rc = tippe_json_bool(c, item, path, "thick_bridges", &s->thick_bridges, NULL)) ||
        (rc = print_number(c, item, path, "solid_infill_below_area_mm2", 0,
                           PRINT_SOLID_BELOW_AREA_MAX_MM2, 0,
                           "mm^2 (a sparse island no larger is made solid; 0: none)",
                           &s->solid_infill_below_area_mm2)) ||
        (rc = print_number(c, item, path, "split_z_mm", -1000, 1000, 0, "mm", &s->split_z_mm)) ||
        (rc = print_number(c, item, path, "model_error", -3, 3, 0,
                           "(the print model's error against the slicer, in units of the "
                           "largest measured: a tolerance term)",
                           &s->model_error)) ||
        (rc = print_number(c, item, path, "filament_diameter_mm", 1, 3.5, 0,
                           "mm (the G-code's filament: CuraEngine writes E in mm of 2.85 mm "
                           "filament; overrides the file's)",
                           &p->filament_diameter_mm)) ||
        (rc = print_number(c, item, path, "calibration", PRINT_CALIBRATION_MIN,
                           PRINT_CALIBRATION_MAX, 0,
                           "(where a weighed mass goes: 0 sparse infill, 1 every line; the "
                           "tolerance bands look either side)",
                           &s->calibration)))
        return rc;
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
    tippe_print_settings *s = &p->print;
    if ((rc = tippe_json_check_keys(c, item, path, "a print block", tippe_design_print_keys, NULL)) ||
        (rc = tippe_json_text(c, item, path, "notes", 0, NULL, 0, NULL)) ||
        (rc = print_number(c, item, path, "perimeters", 0, 50, 1, "perimeters", &per)) ||
        (rc = print_number(c, item, path, "line_width_mm", PRINT_LINE_WIDTH_MIN_MM,
                           PRINT_LINE_WIDTH_MAX_MM, 0, "mm", &s->line_width_mm)) ||
        (rc = print_number(c, item, path, "top_bottom_layers", 0, 200, 1, "layers", &layers)) ||
        (rc = print_number(c, item, path, "layer_height_mm", PRINT_LAYER_HEIGHT_MIN_MM,
                           PRINT_LAYER_HEIGHT_MAX_MM, 0, "mm",
                           &s->layer_height_mm)) ||
        (rc = print_number(c, item, path, "infill", PRINT_INFILL_MIN, PRINT_INFILL_MAX, 0,
                           "(a fraction of the solid density: 15 % is 0.15)", &s->infill)) ||
        (rc = print_number(c, item, path, "measured_mass_g", PRINT_MEASURED_MASS_MIN_G,
                           PRINT_MEASURED_MASS_MAX_G, 0, "g",
                           &p->measured_mass_g)) ||
        (rc = parse_print_rules(c, item, path, p)))
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

/* The hardware catalogue's item a part is ("catalogue_item",
 * docs/design-format.md): a name, on a part that is not a void; the item
 * itself is looked up where the catalogue is read (tippe/build.h). */
static int parse_part_catalogue_item(const tippe_json_reader *c, const cJSON *obj,
                                     const char *pre, part *p)
{
    char path[64];
    int has = 0;
    int rc = tippe_json_string(c, obj, pre, "catalogue_item", 0, p->catalogue_item,
                               sizeof p->catalogue_item, &has);
    if (rc || !has)
        return rc;
    tippe_json_path(path, sizeof path, pre, "catalogue_item");
    if (!p->catalogue_item[0])
        return tippe_json_fail(c, path, "must not be empty (an item's name in the catalogue)");
    if (p->is_void)
        return tippe_json_fail(c, path,
                               "only hardware (a part that is not a void) is a catalogue item");
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
    if ((rc = parse_part_fit(c, obj, pre, p)))
        return rc;
    return parse_part_catalogue_item(c, obj, pre, p);
}

/* A hole printed at another radius than the mass model's ("printed_radius_mm",
 * docs/design-format.md): the tap drill or an insert's pilot, as tippe build's
 * 3MF prints it; the print model lays its walls from there, and what lies
 * inside radius_mm is cut after printing (design_printed.c). Only a plain
 * cylinder cut from a printed part has one. */
static int parse_printed_radius(const tippe_json_reader *c, const cJSON *obj, const char *pre,
                                part *p)
{
    char path[64];
    int has = 0;
    int rc = tippe_design_read_length(c, obj, pre, "printed_radius_mm", 0, 0,
                                      &p->printed_radius_mm, &has);
    if (rc || !has)
        return rc;
    tippe_json_path(path, sizeof path, pre, "printed_radius_mm");
    if (!p->is_void || p->shape != SHAPE_CYLINDER || p->inner_radius_mm > 0)
        return tippe_json_fail(c, path,
                               "only a hole (a void cylinder, no inner_radius_mm) is printed at "
                               "a radius of its own");
    return TIPPE_OK;
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
        if ((rc = tippe_design_read_length(c, obj, pre, "radius_mm", 0, 0, &p->radius_mm, &p->has_radius)))
            return rc;
        if (p->shape == SHAPE_SHELL &&
            (rc = tippe_design_read_length(c, obj, pre, "thickness_mm", 1, 0, &p->thickness_mm, NULL)))
            return rc;
        break;
    case SHAPE_CYLINDER:
    case SHAPE_TUBE: {
        int has_inner = 0;
        if ((rc = tippe_design_read_length(c, obj, pre, "radius_mm", 1, 0, &p->radius_mm, NULL)) ||
            (rc = tippe_design_read_length(c, obj, pre, "inner_radius_mm", p->shape == SHAPE_TUBE,
                               p->shape == SHAPE_CYLINDER, &p->inner_radius_mm, &has_inner)) ||
            (rc = tippe_design_read_length(c, obj, pre, "height_mm", 0, 0, &p->height_mm, &p->has_height)))
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
        return parse_printed_radius(c, obj, pre, p);
    }
    case SHAPE_TORUS:
        if ((rc = tippe_design_read_length(c, obj, pre, "centre_radius_mm", 1, 0, &p->centre_radius_mm,
                               NULL)) ||
            (rc = tippe_design_read_length(c, obj, pre, "radial_semi_mm", 1, 0, &p->radial_semi_mm, NULL)) ||
            (rc = tippe_design_read_length(c, obj, pre, "axial_semi_mm", 1, 0, &p->axial_semi_mm, NULL)))
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

int tippe_design_parse_part(const tippe_json_reader *c, const cJSON *obj, int index, part *p)
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
    if ((rc = tippe_json_text(c, obj, pre, "notes", 0, NULL, 0, NULL)))
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

int tippe_design_lookup_material(const tippe_json_reader *c, const cJSON *table, const char *mat_file,
                           const char *name, const char *path, double *density, int *printable,
                           double *E_pa, double *nu)
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
    const cJSON *E = cJSON_GetObjectItemCaseSensitive(m, "E_GPa");
    const cJSON *n = cJSON_GetObjectItemCaseSensitive(m, "nu");
    *E_pa = cJSON_IsNumber(E) ? E->valuedouble * 1e9 : 0.0;
    *nu = cJSON_IsNumber(n) ? n->valuedouble : 0.0;
    return TIPPE_OK;
}

int tippe_design_load_materials(const char *mat_file, cJSON **out, tippe_error *err)
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
        int printable = 0, set_screws = 0;
        /* a material's name is its key: a label like a part's name */
        if ((rc = tippe_json_check_text(mc, m->string, m->string, 0)) ||
            (rc = tippe_json_check_keys(mc, m, m->string, "a material", material_keys, NULL)) ||
            (rc = tippe_json_number(mc, m, m->string, "density_g_cm3", 1, &dens, NULL)) ||
            (rc = tippe_json_string(mc, m, m->string, "source", 1, NULL, 0, NULL)) ||
            (rc = tippe_json_bool(mc, m, m->string, "printable", &printable, NULL)) ||
            (rc = tippe_json_bool(mc, m, m->string, "set_screws", &set_screws, NULL)) ||
            (rc = tippe_json_text(mc, m, m->string, "notes", 0, NULL, 0, NULL)))
            goto done;
        /* the elastic constants (issue 27, the Hertz patch): both with their source, or
         * none */
        {
            double E = 0, nu = 0;
            char ep[256];
            const int hasE = cJSON_GetObjectItemCaseSensitive(m, "E_GPa") != NULL;
            const int hasnu = cJSON_GetObjectItemCaseSensitive(m, "nu") != NULL;
            const int hassrc = cJSON_GetObjectItemCaseSensitive(m, "elastic_source") != NULL;
            if ((rc = tippe_json_number(mc, m, m->string, "E_GPa", 0, &E, NULL)) ||
                (rc = tippe_json_number(mc, m, m->string, "nu", 0, &nu, NULL)) ||
                (rc = tippe_json_string(mc, m, m->string, "elastic_source", 0, NULL, 0, NULL)))
                goto done;
            if (hasE != hasnu || hasE != hassrc) {
                tippe_json_path(ep, sizeof ep, m->string, hasE ? "nu" : "E_GPa");
                rc = tippe_json_fail(mc, ep, "E_GPa, nu and elastic_source come together "
                                            "(the Hertz patch needs both constants and their "
                                            "source)");
                goto done;
            }
            if (hasE && (!(E > 0 && E <= 1e4) || !(nu > -1 && nu <= 0.5))) {
                tippe_json_path(ep, sizeof ep, m->string, !(E > 0 && E <= 1e4) ? "E_GPa" : "nu");
                rc = tippe_json_fail(mc, ep, "E_GPa must be in (0, 1e4] and nu in (-1, 0.5], got "
                                            "%g and %g", E, nu);
                goto done;
            }
        }
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
    int rc = tippe_design_load_materials(path, &t->root, err);
    if (rc) {
        free(t);
        return rc;
    }
    t->n = cJSON_GetArraySize(t->root);
    *out = t;
    return TIPPE_OK;
}

/* A copy of a table read already, as tippe_materials_load gives it. */
static int materials_copy(const cJSON *table, tippe_materials **out, tippe_error *err)
{
    tippe_materials *t = calloc(1, sizeof *t);
    if (!t || !(t->root = cJSON_Duplicate(table, 1))) {
        free(t);
        return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    }
    t->n = cJSON_GetArraySize(t->root);
    *out = t;
    return TIPPE_OK;
}

/* The loaded design keeps its table (design.c, resolve_materials): the build
 * sheet's advice asks it for each material it may propose. */
int tippe_design_materials(const tippe_design *d, tippe_materials **out, tippe_error *err)
{
    *out = NULL;
    if (!d->mat_table)
        return tippe_error_set(err, TIPPE_EINPUT, "%s: no part names a material of a table",
                               d->path);
    return materials_copy(d->mat_table, out, err);
}

/* The source read its table when it opened (design_source.c); a table that did
 * not read then is read now, for the message that says why. */
int tippe_design_source_materials(const tippe_design_source *s, tippe_materials **out,
                                  tippe_error *err)
{
    *out = NULL;
    if (!s->materials)
        return tippe_materials_load(s->mat_file, out, err);
    return materials_copy(s->materials, out, err);
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
    out->set_screws = cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(m, "set_screws"));
    const cJSON *E = cJSON_GetObjectItemCaseSensitive(m, "E_GPa");
    const cJSON *nu = cJSON_GetObjectItemCaseSensitive(m, "nu");
    out->E_GPa = cJSON_IsNumber(E) ? E->valuedouble : NAN;
    out->nu = cJSON_IsNumber(nu) ? nu->valuedouble : NAN;
    const cJSON *es = cJSON_GetObjectItemCaseSensitive(m, "elastic_source");
    out->elastic_source = cJSON_IsString(es) ? es->valuestring : "";
}

void tippe_materials_free(tippe_materials *t)
{
    if (t)
        cJSON_Delete(t->root);
    free(t);
}

int tippe_design_default_table(const char *beside, char *buf, size_t size, int *fell_back)
{
    *fell_back = 0;
    if (access(beside, F_OK) == 0)
        return snprintf(buf, size, "%s", beside) < (int)size;
    char dir[PATH_MAX];
    int found = tippe_file_shipped_dir(dir, sizeof dir);
    if (found) {
        *fell_back = 1;
        return snprintf(buf, size, "%s/materials.json", dir) < (int)size;
    }
    snprintf(buf, size, "%s", dir);
    return 0;
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
    if (!rc && tippe_path_beside(design_path, rel, buf, size) != TIPPE_OK)
        rc = tippe_error_set(err, TIPPE_EINPUT, "%s: materials: path too long", design_path);
    /* no "materials" field and no table beside: the shipped one, as at load */
    int given = cJSON_GetObjectItemCaseSensitive(root, "materials") != NULL, fell_back = 0;
    char shipped[PATH_MAX + 32];
    if (!rc && !given && tippe_design_default_table(buf, shipped, sizeof shipped, &fell_back) &&
        fell_back)
        snprintf(buf, size, "%s", shipped);
    cJSON_Delete(root);
    free(c);
    return rc;
}

/* The materials table already read (a source's, or the table of the design
 * being derived; a copy the caller deletes) if it is the one tippe_design_build()
 * is about to read; 0 if not. */
int tippe_design_known_materials(const tippe_design *d, const char *mat_file, cJSON **out)
{
    if (!d->known_table || !d->known_table_file || strcmp(mat_file, d->known_table_file))
        return 0;
    *out = cJSON_Duplicate(d->known_table, 1);
    return *out != NULL;
}
