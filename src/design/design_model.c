/* A loaded design as the rest of tippe sees it: the top at Z2, the accessors of
 * its parts and the numeric fields that --set, --vary and the tolerances name.
 * Calls neither the loader nor the tolerances (which call these). */
#include "design/internal.h"

#include <cjson/cJSON.h>
#include <gsl/gsl_errno.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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
tippe_moments tippe_design_part_moments(const part *p)
{
    tippe_moments m = shape_moments(p, p->clip_radius_mm * 1e-3);
    if (p->clip_inner_mm > 0)
        m = tippe_moments_sub(m, shape_moments(p, p->clip_inner_mm * 1e-3));
    return m;
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
    /* the openings at the poles, the one down at theta = 0 first (+z when centred) */
    tippe_design_cap caps[2];
    top->rim_half_angle_rad[0] = top->rim_half_angle_rad[1] = 0.0;
    if (tippe_design_polar_caps(d, z2_mm, caps)) {
        const int rest = top->com_side ? top->com_side : 1; /* caps[0] is +z, caps[1] -z */
        top->rim_half_angle_rad[0] = caps[rest > 0 ? 0 : 1].half_angle_rad;
        top->rim_half_angle_rad[1] = caps[rest > 0 ? 1 : 0].half_angle_rad;
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
    out->role = tippe_design_role_of(p);
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

const char *tippe_design_materials_path(const tippe_design *d) { return d->mat_file; }

int tippe_design_n_overrides(const tippe_design *d) { return d->n_overrides; }

const char *tippe_design_override(const tippe_design *d, int i)
{
    return i >= 0 && i < d->n_overrides ? d->overrides[i] : "";
}

const char *tippe_design_part_catalogue_item(const tippe_design *d, int i)
{
    return i < 0 || i >= d->n_parts ? "" : d->parts[i].catalogue_item;
}

const char *tippe_design_catalogue(const tippe_design *d) { return d->catalogue; }

/* A design from memory names no file on disk: its folder is the designs
 * folder it reads its materials table from (design.c, resolve_materials). */
int tippe_design_beside(const tippe_design *d, const char *name, char *buf, size_t size)
{
    if (!d->materials_dir)
        return tippe_path_beside(d->path, name, buf, size);
    int n = snprintf(buf, size, "%s/%s", d->materials_dir, name);
    return n < 0 || (size_t)n >= size ? TIPPE_EINPUT : TIPPE_OK;
}

/* A/C of unit-density moments alone: A about a transverse axis through their
 * own centre of mass, C about the axis; NAN for no material. */
static double body_a_over_c(tippe_moments m)
{
    if (!(m.m > 0) || !(m.m_rr > 0))
        return NAN;
    double zc = m.m_z / m.m;
    return (0.5 * m.m_rr + m.m_zz - m.m * zc * zc) / m.m_rr;
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
    out->printed_mass_kg = p->printed_mass_kg;
    const double rho = p->density_g_cm3 * 1e3;
    out->model = p->has_gcode ? "gcode" : p->print.model == TIPPE_PRINT_MODEL_SKINS ? "skins"
                                                                                    : "slicer";
    out->filament_volume_mm3 = (p->printed_mass_kg + rho * p->cut.m) / rho * 1e9; /* before the cut */
    if (p->print.model == TIPPE_PRINT_MODEL_SLICER || p->has_gcode) {
        const tippe_print_sliced *sl = &p->sliced;
        double sp = 0, an = 0;
        tippe_print_sliced_at(sl, &p->print, p->infill, &sp, &an);
        out->wall_mass_kg = rho * sl->wall_m3;
        out->solid_infill_mass_kg = rho * sl->solid_m3;
        out->sparse_mass_kg = rho * sp;
        out->anchor_mass_kg = rho * an;
        out->cut_mass_kg = rho * p->cut.m;
        out->n_layers = sl->n_layers;
        out->body_A_over_C = body_a_over_c(p->deposit);
    }
    out->from_gcode = p->has_gcode;
    out->gcode = p->gcode;
    out->generator = p->has_gcode ? p->gcode_body.generator : "";
    out->gcode_cut_mass_kg = p->has_gcode ? p->gcode_body.cut_mass_kg * p->gcode_flow : 0;
    out->gcode_note = p->has_gcode ? p->gcode_note : "";
    out->gcode_support_mass_kg =
        p->has_gcode ? p->gcode_body.feature[TIPPE_GCODE_SUPPORT].mass_kg +
                           p->gcode_body.feature[TIPPE_GCODE_SUPPORT_INTERFACE].mass_kg
                     : 0;
    out->flow_factor = p->has_gcode ? p->gcode_flow : 1.0;
    out->model_mass_kg = p->has_gcode ? p->model_mass_kg : p->printed_mass_kg;
    out->model_body_A_over_C = p->has_gcode ? body_a_over_c(p->model_deposit)
                                            : out->body_A_over_C;
    out->rel_error = p->print_rel_error;
    return TIPPE_OK;
}

int tippe_design_part_printable(const tippe_design *d, int i)
{
    return i >= 0 && i < d->n_parts && d->parts[i].printable;
}

int tippe_design_ball_elastic(const tippe_design *d, double *E_pa, double *nu,
                              const char **material)
{
    for (int i = 0; i < d->n_parts; i++) {
        const part *p = &d->parts[i];
        if (p->is_void || p->moving || (p->shape != SHAPE_BALL && p->shape != SHAPE_SHELL))
            continue;
        *material = p->material;
        *E_pa = p->E_pa;
        *nu = p->nu;
        return p->E_pa > 0.0;
    }
    *material = "";
    return 0;
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
    else if (!strcmp(key, "calibration") && p->calibrated)
        *value = p->print.calibration;
    else if (!strcmp(key, "model_error") && !p->gcode[0] &&
             p->print.model == TIPPE_PRINT_MODEL_SLICER)
        *value = p->print.model_error;
    else {
        snprintf(why, why_cap, "not a number setting of the print block (infill, "
                               "line_width_mm, layer_height_mm, perimeters, "
                               "top_bottom_layers, measured_mass_g and calibration when "
                               "weighed, model_error under the slicer's rules without a "
                               "G-code)");
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

double tippe_design_patch_radius_span(const tippe_design *d)
{
    return d->patch_radius_span > 1.0 ? d->patch_radius_span : TIPPE_TOL_PATCH_RADIUS_FACTOR;
}

const tippe_tolerance *tippe_design_tolerance(const tippe_design *d, int i)
{
    return i >= 0 && i < d->n_tolerances ? &d->tolerances[i] : NULL;
}
