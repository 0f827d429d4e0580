/* A printed part's mass moments: by the slicer's rules layer by layer (the
 * default), by the continuous rule of walls and skins, or from the slicer's
 * own G-code of the part, which is then the truth (docs/printing.md). */
#include "design/internal.h"

#include <libgen.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

/* The layers of a part do not depend on its infill, its calibration or its
 * density (tippe_print_sliced_at applies the infill), and the tolerance bands
 * and an optimiser's candidates reload a design many times changing only those
 * (or another part): a few recent slicings are kept, keyed by everything that
 * shapes the layers. Shared by the threads of tippe serve and the OpenMP loops,
 * hence the lock. */
#define SLICE_CACHE 8
typedef struct {
    int used, n_voids;
    tippe_solid part, voids[MAX_PARTS];
    tippe_print_settings s; /* infill and calibration zeroed: not part of the key */
    tippe_print_sliced out;
} slice_entry;
static slice_entry slice_cache[SLICE_CACHE];
static int slice_next;
static pthread_mutex_t slice_lock = PTHREAD_MUTEX_INITIALIZER;

static int same_solid(const tippe_solid *a, const tippe_solid *b)
{
    return a->kind == b->kind && a->z_centre == b->z_centre && a->radius == b->radius &&
           a->inner_radius == b->inner_radius && a->height == b->height &&
           a->centre_radius == b->centre_radius && a->radial_semi == b->radial_semi &&
           a->axial_semi == b->axial_semi && a->clip_outer == b->clip_outer &&
           a->clip_inner == b->clip_inner;
}

static int same_settings(const tippe_print_settings *a, const tippe_print_settings *b)
{
    return a->perimeters == b->perimeters && a->line_width_mm == b->line_width_mm &&
           a->top_bottom_layers == b->top_bottom_layers &&
           a->layer_height_mm == b->layer_height_mm && a->model == b->model &&
           a->pattern == b->pattern && a->external_width_mm == b->external_width_mm &&
           a->infill_width_mm == b->infill_width_mm &&
           a->first_layer_height_mm == b->first_layer_height_mm &&
           a->first_layer_width_mm == b->first_layer_width_mm && a->top_min_mm == b->top_min_mm &&
           a->bottom_min_mm == b->bottom_min_mm && a->infill_overlap == b->infill_overlap &&
           a->anchor_mm == b->anchor_mm && a->anchor_max_mm == b->anchor_max_mm &&
           a->nozzle_mm == b->nozzle_mm && a->flow == b->flow && a->split == b->split &&
           a->split_z_mm == b->split_z_mm;
}

static int sliced_cached(const tippe_solid *shape, const tippe_solid *holes, int n_holes,
                         const tippe_print_settings *s, tippe_print_sliced *out, tippe_error *err)
{
    pthread_mutex_lock(&slice_lock);
    for (int k = 0; k < SLICE_CACHE; k++) {
        const slice_entry *e = &slice_cache[k];
        int hit = e->used && e->n_voids == n_holes && same_solid(&e->part, shape) &&
                  same_settings(&e->s, s);
        for (int j = 0; hit && j < n_holes; j++)
            hit = same_solid(&e->voids[j], &holes[j]);
        if (hit) {
            *out = e->out;
            pthread_mutex_unlock(&slice_lock);
            /* the infill is the caller's: the deposit at it */
            out->deposit = tippe_print_sliced_at(out, s, s->infill, &out->sparse_m3,
                                                 &out->anchor_m3);
            return TIPPE_OK;
        }
    }
    pthread_mutex_unlock(&slice_lock);
    int rc = tippe_print_slice_moments(shape, holes, n_holes, s, 0, out, err);
    if (rc || n_holes > MAX_PARTS)
        return rc;
    pthread_mutex_lock(&slice_lock);
    slice_entry *e = &slice_cache[slice_next];
    slice_next = (slice_next + 1) % SLICE_CACHE;
    e->used = 1;
    e->n_voids = n_holes;
    e->part = *shape;
    for (int j = 0; j < n_holes; j++)
        e->voids[j] = holes[j];
    e->s = *s;
    e->out = *out;
    pthread_mutex_unlock(&slice_lock);
    return TIPPE_OK;
}

/* The printed part under the slicer's rules (print_slicer.c), layer by layer.
 * A weighed mass says how much, not where: the nominal reading puts the
 * difference in the sparse infill (the infill that gives that mass, found by
 * bisection: the deposit grows with the infill); the tolerance bands carry the
 * other reading, extra material on every line (print.flow). */
static int sliced_moments(const tippe_json_reader *c, tippe_design *d, int i,
                          const tippe_solid *shape, const tippe_solid *holes, int n_holes,
                          tippe_moments solid, tippe_moments *out)
{
    part *p = &d->parts[i];
    char pth[64];
    snprintf(pth, sizeof pth, "parts[%d].print", i);
    tippe_error perr;
    int rc = sliced_cached(shape, holes, n_holes, &p->print, &p->sliced, &perr);
    if (rc)
        return rc == TIPPE_EINPUT ? tippe_json_fail(c, pth, "%s", perr.msg)
                                  : tippe_error_set(c->err, rc, "%s: %s: %s", c->file, pth,
                                                    perr.msg);
    const double rho = p->density_g_cm3 * 1e3;
    p->infill = p->print.infill;
    if (p->calibrated) {
        /* reading c of the weighing: a share c of what the model lacks at the
         * slicer's infill is put on every line (a flow factor), the rest in the
         * sparse infill */
        const double want = p->measured_mass_g * 1e-3, c_share = p->print.calibration;
        double m_s = rho * tippe_print_sliced_at(&p->sliced, &p->print, p->print.infill, NULL,
                                                 NULL).m;
        p->print.flow *= 1 + c_share * (want - m_s) / m_s;
        double m0 = rho * tippe_print_sliced_at(&p->sliced, &p->print, 0, NULL, NULL).m;
        double m1 = rho * tippe_print_sliced_at(&p->sliced, &p->print, 1, NULL, NULL).m;
        snprintf(pth, sizeof pth, "parts[%d].print.measured_mass_g", i);
        if (want < m0)
            return tippe_json_fail(c, pth,
                                   "%g g is less than the walls and solid infill alone weigh "
                                   "(%.3f g at 0 %% infill with these settings and %g g/cm^3)",
                                   p->measured_mass_g, m0 * 1e3, p->density_g_cm3);
        if (want > m1)
            return tippe_json_fail(c, pth,
                                   "%g g is more than part '%s' weighs printed at 100 %% infill "
                                   "(%.3f g at %g g/cm^3)",
                                   p->measured_mass_g, p->name, m1 * 1e3, p->density_g_cm3);
        double lo = 0, hi = 1;
        for (int k = 0; k < 80 && hi - lo > 1e-15; k++) {
            double mid = 0.5 * (lo + hi);
            if (rho * tippe_print_sliced_at(&p->sliced, &p->print, mid, NULL, NULL).m < want)
                lo = mid;
            else
                hi = mid;
        }
        p->infill = 0.5 * (lo + hi);
    }
    tippe_moments dep = tippe_print_sliced_at(&p->sliced, &p->print, p->infill, NULL, NULL);
    p->solid_mass_kg = rho * solid.m;
    p->skin_mass_kg = rho * (p->sliced.wall_m3 + p->sliced.solid_m3);
    p->printed_mass_kg = rho * dep.m;
    if (!(dep.m > 0) || !(dep.m_rr > 0))
        return tippe_json_fail(c, pth, "part '%s' printed this way has no material", p->name);
    /* exact arithmetic on the slicer's layers; the printed part's bottom and
     * top are found to 1e-12 m */
    p->print_rel_error = 1e-12 / fmax(p->radius_mm * 1e-3, 1e-3);
    p->deposit = dep;
    /* the part's own region, its voids added back: they subtract as usual */
    *out = tippe_moments_add(dep, tippe_moments_sub(tippe_design_part_moments(p), solid));
    return TIPPE_OK;
}

/* Unit-density moments of printed part i as printed: the part minus its voids
 * (closed forms) less (1 - infill) x its sparse core (print model). Sets the
 * part's infill (calibrated from a weighed mass when one is given), its solid
 * and skin masses and the relative error bound. */
/* The printed part from the slicer's G-code of it (print.gcode, relative to the
 * design file): its extrusion moves summed into mass moments (gcode.c), at the
 * design's density (the volumes are the slicer's, the material the design's).
 * The deposit is matched to the part as the layer model places it on the bed:
 * its height and diameter must agree (one layer's slack), else it is refused.
 * A weighed mass then scales every line (a flow factor): the G-code says where
 * the material is, the scale how much. The layer model is kept beside it. */
static int gcode_moments(const tippe_json_reader *c, tippe_design *d, int i, tippe_moments solid,
                         tippe_moments *out)
{
    part *p = &d->parts[i];
    char pth[64], file[2048];
    snprintf(pth, sizeof pth, "parts[%d].print.gcode", i);
    /* A design from memory (tippe serve's requests) names no file on disk, as
     * for its materials table (issue 36: the path read any file of the server):
     * its G-code is a body read from memory for this part (an upload), or none. */
    const tippe_design_gcode *mem = NULL;
    for (int k = 0; d->materials_dir && k < d->n_gcodes && !mem; k++)
        if (!strcmp(d->gcodes[k].part, p->name))
            mem = &d->gcodes[k];
    if (d->materials_dir && !mem)
        return tippe_json_fail(c, pth,
                               "a design sent as text names no file: its G-code cannot be "
                               "read from the server's disk (upload it on the page, or slice "
                               "and weigh with the command, tippe slice or tippe eval)");
    tippe_gcode_options opt = tippe_gcode_defaults();
    opt.density_g_cm3 = p->density_g_cm3;
    opt.override_density = 1;
    tippe_gcode_body body;
    tippe_error gerr = {0};
    int rc = TIPPE_OK;
    if (mem) {
        body = mem->body;
        tippe_gcode_body_at_density(&body, p->density_g_cm3);
    } else {
        if (p->gcode[0] == '/') {
            snprintf(file, sizeof file, "%s", p->gcode);
        } else {
            char dir[1024];
            snprintf(dir, sizeof dir, "%s", d->path);
            snprintf(file, sizeof file, "%s/%s", dirname(dir), p->gcode);
        }
        rc = tippe_gcode_read(file, &opt, &body, &gerr);
    }
    if (rc)
        return rc == TIPPE_EINPUT ? tippe_json_fail(c, pth, "%s", gerr.msg)
                                  : tippe_error_set(c->err, rc, "%s: %s: %s", c->file, pth,
                                                    gerr.msg);
    const tippe_print_sliced *sl = &p->sliced;
    tippe_gcode_expect ex = {0};
    ex.height_mm = (sl->top_z_m - sl->bed_z_m) * 1e3;
    ex.diameter_mm = 2 * p->radius_mm;
    tippe_gcode_part gp;
    if ((rc = tippe_gcode_match(&body, &ex, &gp, &gerr)))
        return tippe_json_fail(c, pth, "%s does not match part '%s' (printed %.2f mm high and "
                                       "%.2f mm across): %s",
                               p->gcode, p->name, ex.height_mm, ex.diameter_mm, gerr.msg);
    double scale = 1.0;
    if (p->calibrated) {
        scale = p->measured_mass_g * 1e-3 / gp.m;
        snprintf(pth, sizeof pth, "parts[%d].print.measured_mass_g", i);
        if (!(scale > 0.5 && scale < 1.5))
            return tippe_json_fail(c, pth, "%g g is %.0f %% of what the G-code deposits (%.3f g "
                                           "at %g g/cm^3): not the same part, or not this "
                                           "material",
                                   p->measured_mass_g, 100 * scale, gp.m * 1e3,
                                   p->density_g_cm3);
    }
    /* to the design frame: z from the bed, the bed where the layer model has it;
     * unit density, as the other models give */
    const double rho = p->density_g_cm3 * 1e3;
    double m = gp.m * scale, zc = sl->bed_z_m + gp.z_cm;
    double m_rr = gp.C * scale / rho, vol = m / rho;
    tippe_moments dep = {vol, vol * zc, (gp.A * scale + m * zc * zc) / rho - 0.5 * m_rr, m_rr};
    p->gcode_flow = scale;
    p->model_deposit = p->deposit;
    p->deposit = dep;
    p->gcode_body = body;
    p->gcode_part = gp;
    p->has_gcode = 1;
    p->printed_mass_kg = m;
    p->skin_mass_kg = rho * (sl->wall_m3 + sl->solid_m3);
    *out = tippe_moments_add(dep, tippe_moments_sub(tippe_design_part_moments(p), solid));
    return TIPPE_OK;
}

int tippe_design_printed_moments(const tippe_json_reader *c, tippe_design *d, int i,
                                 tippe_moments *out)
{
    part *p = &d->parts[i];
    tippe_solid shape = print_solid(p), holes[MAX_PARTS];
    tippe_moments solid = tippe_design_part_moments(p);
    int n_holes = 0;
    for (int k = 0; k < d->n_parts; k++)
        if (d->parts[k].parent == i) {
            holes[n_holes++] = print_solid(&d->parts[k]);
            solid = tippe_moments_sub(solid, tippe_design_part_moments(&d->parts[k]));
        }
    if (p->print.model == TIPPE_PRINT_MODEL_SLICER || p->gcode[0]) {
        int rc = sliced_moments(c, d, i, &shape, holes, n_holes, solid, out);
        if (rc || !p->gcode[0])
            return rc;
        p->model_moments = *out; /* the layer model's, kept for the report */
        p->model_mass_kg = p->printed_mass_kg;
        return gcode_moments(c, d, i, solid, out);
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
    p->printed_mass_kg = rho * printed_m;
    /* the part's own region, its voids added back: they subtract as usual */
    *out = tippe_moments_sub(tippe_design_part_moments(p), tippe_moments_scale(core.core, lack));
    return TIPPE_OK;
}

