/* How a design's parts are printed, as a report (text and JSON) for eval and
 * sweep, with the bodies tippe export writes. Apart from profile.c, in the
 * library's core: it calls the profile builder (GEOS) through the command's
 * stub, so that a command loads GEOS only when it reports. */
#include "tippe/profile.h"

#include <cjson/cJSON.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

/* The options tippe export prints a design's bodies with, as far as the design
 * says them: the default clearance, and a hole printed at its
 * printed_radius_mm (the part as made) where tippe export prints it there
 * (tippe_build_design_fit: a heat-set insert's hole keeps its pilot). A "tap"
 * or "insert" fit without a printed radius needs the thread tables of the
 * build layer above: returned in *fit_only (the hole's index, else -1), so
 * that the report names it rather than give its volume as if it slid. */
static tippe_profile_options report_options(const tippe_design *d, int *fit_only)
{
    tippe_profile_options o = tippe_profile_defaults();
    *fit_only = -1;
    for (int i = 0; i < tippe_design_n_parts(d); i++) {
        tippe_design_solid hs;
        int fit = tippe_design_part_fit(d, i);
        if (tippe_design_part_solid(d, i, &hs) || !hs.is_void)
            continue;
        if (hs.printed_radius_mm > 0 && fit != TIPPE_DESIGN_FIT_INSERT && o.fit_diameter_mm == 0) {
            o.fit_part = i;
            o.fit_diameter_mm = 2 * hs.printed_radius_mm;
        } else if ((fit == TIPPE_DESIGN_FIT_TAP || fit == TIPPE_DESIGN_FIT_INSERT) &&
                   *fit_only < 0) {
            *fit_only = i;
        }
    }
    if (o.fit_diameter_mm > 0 && *fit_only == o.fit_part)
        *fit_only = -1;
    return o;
}

/* The printed bodies as tippe export writes them (default clearance, a hole
 * at its printed radius), with their exact volumes: what a slicer's volume
 * estimate should approach. */
static void print_bodies(FILE *out, const tippe_design *d)
{
    int fit_only;
    tippe_profile_options o = report_options(d, &fit_only);
    tippe_profile_set s;
    tippe_error err = {0};
    if (tippe_profile_build(d, &o, &s, &err)) {
        fprintf(out, "bodies   none printed (%s)\n", err.msg);
        return;
    }
    for (int b = 0; b < s.n_bodies; b++) {
        const tippe_profile_body *e = &s.body[b];
        double v = isnan(e->exact_volume_mm3) ? e->polygon_volume_mm3 : e->exact_volume_mm3;
        fprintf(out, "%s%s (%s): envelope %.1f mm^3 = %.3f cm^3 (the outline, not the filament)\n",
                b ? "         " : "bodies   ", e->name, e->material, v, v * 1e-3);
    }
    int grown = 0, fitted = o.fit_diameter_mm > 0 && o.fit_part < s.n_parts &&
                            s.clearance_applied[o.fit_part];
    for (int i = 0; i < s.n_parts; i++)
        grown |= s.clearance_applied[i] && !(fitted && i == o.fit_part);
    char fit[320] = "";
    tippe_design_part_info p;
    if (fitted && !tippe_design_part(d, o.fit_part, &p))
        snprintf(fit, sizeof fit, ", hole '%s' printed %.4g mm across (its printed_radius_mm)",
                 p.name, o.fit_diameter_mm);
    if (fit_only >= 0 && !tippe_design_part(d, fit_only, &p)) {
        size_t n = strlen(fit);
        snprintf(fit + n, sizeof fit - n,
                 "; but tippe export prints hole '%s' as its \"fit\": \"%s\" says, which this "
                 "volume does not count",
                 p.name,
                 tippe_design_part_fit(d, fit_only) == TIPPE_DESIGN_FIT_TAP ? "tap" : "insert");
    }
    fprintf(out, "         (as tippe export writes them%s%s; the filament, to compare with the "
                 "slicer's estimate, is under printed)\n",
            grown ? ", holes for hardware 0.2 mm wider in radius than in the mass model" : "",
            fit);
    tippe_profile_set_free(&s);
}

static int bodies_json(struct cJSON *o, const tippe_design *d)
{
    int fit_only;
    tippe_profile_options opt = report_options(d, &fit_only);
    tippe_profile_set s;
    tippe_error err = {0};
    cJSON *arr = cJSON_AddArrayToObject(o, "printed_bodies");
    if (!arr)
        return -1;
    if (tippe_profile_build(d, &opt, &s, &err))
        return 0; /* nothing printable: an empty list */
    int ok = 1;
    for (int b = 0; ok && b < s.n_bodies; b++) {
        const tippe_profile_body *e = &s.body[b];
        cJSON *j = cJSON_CreateObject();
        ok = j && cJSON_AddItemToArray(arr, j);
        if (!ok) {
            cJSON_Delete(j);
            break;
        }
        ok = cJSON_AddStringToObject(j, "name", e->name) &&
             cJSON_AddStringToObject(j, "material", e->material) &&
             cJSON_AddNumberToObject(j, "volume_mm3", e->exact_volume_mm3) &&
             cJSON_AddNumberToObject(j, "clearance_mm", opt.clearance_mm);
        tippe_design_part_info p;
        if (ok && opt.fit_diameter_mm > 0 && !tippe_design_part(d, opt.fit_part, &p)) {
            cJSON *h = cJSON_AddObjectToObject(j, "printed_hole");
            ok = h && cJSON_AddStringToObject(h, "hole", p.name) &&
                 cJSON_AddNumberToObject(h, "diameter_mm", opt.fit_diameter_mm);
        } else if (ok) {
            ok = cJSON_AddNullToObject(j, "printed_hole") != NULL;
        }
        if (ok && fit_only >= 0 && !tippe_design_part(d, fit_only, &p))
            ok = cJSON_AddStringToObject(j, "fit_not_counted", p.name) != NULL;
        else if (ok)
            ok = cJSON_AddNullToObject(j, "fit_not_counted") != NULL;
    }
    tippe_profile_set_free(&s);
    return ok ? 0 : -1;
}

void tippe_profile_print_printed_parts(FILE *out, const tippe_design *d)
{
    int any = 0;
    for (int i = 0; i < tippe_design_n_parts(d); i++) {
        tippe_design_part_info p;
        tippe_design_print_info pi;
        if (tippe_design_part(d, i, &p) || tippe_design_part_print(d, i, &pi) || !pi.printed)
            continue;
        const tippe_print_settings *s = &pi.settings;
        const char *lead = any ? "         " : "printed  ";
        if (!strcmp(pi.model, "skins"))
            fprintf(out,
                    "%s%s: axis vertical, the continuous rule (print model \"skins\"): %d x "
                    "%.2f mm perimeters (walls %.2f mm), %d x %.2f mm top/bottom layers (skins "
                    "%.2f mm), ",
                    lead, p.name, s->perimeters, s->line_width_mm, pi.wall_mm,
                    s->top_bottom_layers, s->layer_height_mm, pi.skin_mm);
        else
            fprintf(out,
                    "%s%s: axis vertical, PrusaSlicer 2.5's rules in %d layers: %d perimeters of "
                    "%.2f mm lines, %d top/bottom layers of %.2f mm (at least %.2f / %.2f mm), "
                    "%s, %s",
                    lead, p.name, pi.n_layers, s->perimeters, s->line_width_mm,
                    s->top_bottom_layers, s->layer_height_mm, s->top_min_mm, s->bottom_min_mm,
                    tippe_print_pattern_name(s->pattern),
                    s->thick_bridges ? "" : "thin bridges (thick_bridges off), ");
        if (pi.calibrated)
            fprintf(out, "infill %.2f %% from the weighed %.3f g (slicer: %.0f %%)",
                    pi.infill * 100, pi.measured_mass_kg * 1e3, s->infill * 100);
        else
            fprintf(out, "infill %.0f %%", pi.infill * 100);
        /* the cut after printing (a hole printed at its tap drill, then tapped) */
        char cut[400] = "";
        if (pi.cut_mass_kg > 0) {
            int n = snprintf(cut, sizeof cut, ", less %.3f g cut from its holes after printing",
                             pi.cut_mass_kg * 1e3);
            /* which hole, and whether the file or the tap drill says so (design_fit.c) */
            for (int k = 0; k < tippe_design_n_parts(d) && n > 0 && (size_t)n < sizeof cut;
                 k++) {
                tippe_design_solid hs;
                tippe_design_part_info hp;
                if (tippe_design_part_solid(d, k, &hs) || hs.parent != i ||
                    !(hs.printed_radius_mm > 0 && hs.printed_radius_mm < hs.radius_mm) ||
                    tippe_design_part(d, k, &hp))
                    continue;
                n += snprintf(cut + n, sizeof cut - (size_t)n,
                              " ('%s' printed %.2f mm across%s, cut to %.2f mm)", hp.name,
                              2 * hs.printed_radius_mm,
                              hs.printed_radius_from_fit ? ", its thread's tap drill" : "",
                              2 * hs.radius_mm);
            }
        }
        if (!strcmp(pi.model, "skins"))
            fprintf(out,
                    "\n         %.3f g as printed (%.3f g solid, %.3f g walls and skins alone); "
                    "print model error < %.0e\n",
                    pi.printed_mass_kg * 1e3, pi.solid_mass_kg * 1e3, pi.skin_mass_kg * 1e3,
                    pi.rel_error > 1e-15 ? pi.rel_error : 1e-15);
        else if (!pi.from_gcode)
            fprintf(out,
                    "\n         %.3f g as printed (%.3f g solid): walls %.3f g, solid infill "
                    "%.3f g, sparse infill %.3f g, its anchors %.3f g%s; filament "
                    "%.2f cm^3; body A/C %.4f\n",
                    pi.printed_mass_kg * 1e3, pi.solid_mass_kg * 1e3, pi.wall_mass_kg * 1e3,
                    pi.solid_infill_mass_kg * 1e3, pi.sparse_mass_kg * 1e3,
                    pi.anchor_mass_kg * 1e3, cut, pi.filament_volume_mm3 * 1e-3,
                    pi.body_A_over_C);
        else
            fprintf(out,
                    "\n         from its G-code %s (%s): %.3f g, body A/C %.4f%s; the layer model "
                    "beside it: %.3f g (%+.1f %%), body A/C %.4f; filament %.2f cm^3\n",
                    pi.gcode, pi.generator[0] ? pi.generator : "slicer not named",
                    pi.printed_mass_kg * 1e3, pi.body_A_over_C,
                    pi.calibrated ? " (its lines scaled by the weighing)" : "",
                    pi.model_mass_kg * 1e3,
                    100 * (pi.model_mass_kg / pi.printed_mass_kg - 1), pi.model_body_A_over_C,
                    pi.filament_volume_mm3 * 1e-3);
        if (pi.from_gcode && pi.gcode_note[0])
            fprintf(out, "         the G-code: %s\n", pi.gcode_note);
        if (pi.from_gcode && pi.gcode_support_mass_kg > 0)
            fprintf(out, "         supports, removed: %.3f g (not part of the body)\n",
                    pi.gcode_support_mass_kg * 1e3);
        any = 1;
    }
    if (!any)
        fprintf(out, "printed  no part has a print block: every part is solid\n");
    print_bodies(out, d);
}

int tippe_profile_printed_parts_json(struct cJSON *o, const tippe_design *d)
{
    cJSON *arr = cJSON_AddArrayToObject(o, "printed_parts");
    if (!arr)
        return -1;
    for (int i = 0; i < tippe_design_n_parts(d); i++) {
        tippe_design_part_info p;
        tippe_design_print_info pi;
        if (tippe_design_part(d, i, &p) || tippe_design_part_print(d, i, &pi) || !pi.printed)
            continue;
        cJSON *e = cJSON_CreateObject();
        if (!e || !cJSON_AddItemToArray(arr, e)) {
            cJSON_Delete(e);
            return -1;
        }
        const tippe_print_settings *s = &pi.settings;
        int ok =
            cJSON_AddStringToObject(e, "part", p.name) &&
            cJSON_AddNumberToObject(e, "perimeters", s->perimeters) &&
            cJSON_AddNumberToObject(e, "line_width_mm", s->line_width_mm) &&
            cJSON_AddNumberToObject(e, "top_bottom_layers", s->top_bottom_layers) &&
            cJSON_AddNumberToObject(e, "layer_height_mm", s->layer_height_mm) &&
            cJSON_AddNumberToObject(e, "wall_mm", pi.wall_mm) &&
            cJSON_AddNumberToObject(e, "skin_mm", pi.skin_mm) &&
            cJSON_AddNumberToObject(e, "infill", pi.infill) &&
            cJSON_AddNumberToObject(e, "slicer_infill", s->infill) &&
            cJSON_AddBoolToObject(e, "calibrated", pi.calibrated) &&
            (pi.calibrated ? cJSON_AddNumberToObject(e, "measured_mass_kg", pi.measured_mass_kg)
                           : cJSON_AddNullToObject(e, "measured_mass_kg")) &&
            cJSON_AddNumberToObject(e, "printed_mass_kg", pi.printed_mass_kg) &&
            cJSON_AddNumberToObject(e, "solid_mass_kg", pi.solid_mass_kg) &&
            cJSON_AddNumberToObject(e, "skin_mass_kg", pi.skin_mass_kg) &&
            cJSON_AddNumberToObject(e, "model_rel_error", pi.rel_error) &&
            cJSON_AddStringToObject(e, "model", pi.model) &&
            cJSON_AddStringToObject(e, "pattern", tippe_print_pattern_name(s->pattern)) &&
            cJSON_AddBoolToObject(e, "thick_bridges", s->thick_bridges) &&
            cJSON_AddNumberToObject(e, "filament_volume_mm3", pi.filament_volume_mm3) &&
            cJSON_AddNumberToObject(e, "wall_mass_kg", pi.wall_mass_kg) &&
            cJSON_AddNumberToObject(e, "solid_infill_mass_kg", pi.solid_infill_mass_kg) &&
            cJSON_AddNumberToObject(e, "sparse_mass_kg", pi.sparse_mass_kg) &&
            cJSON_AddNumberToObject(e, "anchor_mass_kg", pi.anchor_mass_kg) &&
            cJSON_AddNumberToObject(e, "cut_mass_kg", pi.cut_mass_kg) &&
            cJSON_AddNumberToObject(e, "layers", pi.n_layers) &&
            (isfinite(pi.body_A_over_C) ? cJSON_AddNumberToObject(e, "body_A_over_C",
                                                                   pi.body_A_over_C)
                                        : cJSON_AddNullToObject(e, "body_A_over_C")) &&
            (pi.from_gcode
                 ? cJSON_AddStringToObject(e, "gcode", pi.gcode) &&
                       cJSON_AddStringToObject(e, "gcode_generator", pi.generator) &&
                       cJSON_AddNumberToObject(e, "flow_factor", pi.flow_factor) &&
                       cJSON_AddNumberToObject(e, "model_mass_kg", pi.model_mass_kg) &&
                       cJSON_AddNumberToObject(e, "model_body_A_over_C", pi.model_body_A_over_C) &&
                       cJSON_AddNumberToObject(e, "gcode_cut_mass_kg", pi.gcode_cut_mass_kg) &&
                       cJSON_AddNumberToObject(e, "gcode_support_mass_kg",
                                               pi.gcode_support_mass_kg) &&
                       cJSON_AddStringToObject(e, "gcode_note", pi.gcode_note)
                 : cJSON_AddNullToObject(e, "gcode") != NULL);
        if (!ok)
            return -1;
    }
    return bodies_json(o, d);
}
