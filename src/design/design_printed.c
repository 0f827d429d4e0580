/* A printed part's mass moments: by the slicer's rules layer by layer (the
 * default), by the continuous rule of walls and skins, or from the slicer's
 * own G-code of the part, which is then the truth (docs/printing.md). */
#include "design/internal.h"

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

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
           a->nozzle_mm == b->nozzle_mm && a->thick_bridges == b->thick_bridges &&
           a->solid_infill_below_area_mm2 == b->solid_infill_below_area_mm2 &&
           a->perimeter_generator == b->perimeter_generator &&
           a->flow == b->flow && a->split == b->split &&
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

/* The deposit moved by x times the print model's largest measured error
 * against the slicer (print.model_error): every moment scaled by the mass's
 * 1 - x TIPPE_PRINT_MODEL_ERROR_MASS, and C set so that the body's A/C (about
 * its own centre of mass) rises by x TIPPE_PRINT_MODEL_ERROR_AC at the same A. */
static tippe_moments model_error_moved(tippe_moments d, double x)
{
    double k = 1 - x * TIPPE_PRINT_MODEL_ERROR_MASS;
    d.m *= k;
    d.m_z *= k;
    d.m_zz *= k;
    d.m_rr *= k;
    double zc = d.m_z / d.m, zz = d.m_zz - d.m * zc * zc; /* about the centre of mass */
    double A = 0.5 * d.m_rr + zz, ac = A / d.m_rr + x * TIPPE_PRINT_MODEL_ERROR_AC;
    if (!(ac > 0))
        return d;
    double rr = A / ac;
    d.m_zz += 0.5 * (d.m_rr - rr); /* A = rr/2 + zz kept */
    d.m_rr = rr;
    return d;
}

/* The rings the cut after printing takes from part i's deposit, unit density
 * and flow 1: for each hole printed narrower than its radius (printed_radius_mm),
 * the plastic between the printed hole and radius_mm, over the hole's heights
 * within the part. The slicer lays the hole's walls from its printed outline
 * (print_slicer.c: the external perimeter's edge (w - s)/2 inside it, then
 * s_ext + (n - 1) s_per of solid lines, Flow::rounded_rectangle_extrusion_spacing),
 * so the ring within the walls is solid (wall) and the rest of it, if the cut
 * reaches past them, is sparse infill (sparse, to be scaled by the infill's
 * density; solid infill near the top and bottom there is taken as sparse). Each
 * ring is the part with the hole at the ring's inner radius less the part with
 * it at the outer (tippe_print_core_moments without walls or skins: the exact
 * solid), the other holes as printed. holes[] are the part's voids as printed,
 * in the order of d's parts. */
/* A ring's exact moments take three quadratures per hole, and the tolerance
 * bands reload a design ~190 times changing mostly what the ring does not
 * depend on (a density, the infill): the last few are kept, keyed by the part,
 * its voids as printed and the ring's radii (m), as the slicings are. */
#define RING_CACHE 8
typedef struct {
    int used, n_voids, at;
    tippe_solid part, voids[MAX_PARTS];
    double r_m;
    tippe_moments m;
} ring_entry;
static ring_entry ring_cache[RING_CACHE];
static int ring_next;
static pthread_mutex_t ring_lock = PTHREAD_MUTEX_INITIALIZER;

/* The exact moments of shape less voids[] with void `at` at radius r_m. */
static int ring_moments(const tippe_solid *shape, const tippe_solid *holes, int n_holes, int at,
                        double r_m, tippe_moments *out, tippe_error *err)
{
    pthread_mutex_lock(&ring_lock);
    for (int k = 0; k < RING_CACHE; k++) {
        const ring_entry *e = &ring_cache[k];
        int hit = e->used && e->n_voids == n_holes && e->at == at && e->r_m == r_m &&
                  same_solid(&e->part, shape);
        for (int j = 0; hit && j < n_holes; j++)
            hit = same_solid(&e->voids[j], &holes[j]); /* the ring's hole too: z, height */
        if (hit) {
            *out = e->m;
            pthread_mutex_unlock(&ring_lock);
            return TIPPE_OK;
        }
    }
    pthread_mutex_unlock(&ring_lock);
    tippe_solid v[MAX_PARTS];
    memcpy(v, holes, (size_t)n_holes * sizeof *v);
    v[at].radius = r_m;
    tippe_print_core core;
    int rc = tippe_print_core_moments(shape, v, n_holes, 0, 0, &core, err);
    if (rc)
        return rc;
    *out = core.core;
    pthread_mutex_lock(&ring_lock);
    ring_entry *e = &ring_cache[ring_next];
    ring_next = (ring_next + 1) % RING_CACHE;
    *e = (ring_entry){.used = 1, .n_voids = n_holes, .at = at, .part = *shape, .r_m = r_m,
                      .m = core.core};
    memcpy(e->voids, holes, (size_t)n_holes * sizeof *holes);
    pthread_mutex_unlock(&ring_lock);
    return TIPPE_OK;
}

static int cut_rings(const tippe_design *d, int i, const tippe_solid *shape,
                     const tippe_solid *holes, int n_holes, tippe_moments *wall,
                     tippe_moments *sparse, tippe_error *err)
{
    const part *p = &d->parts[i];
    const double t = p->print.layer_height_mm, w_e = p->print.external_width_mm;
    const double s_e = w_e - t * (1.0 - M_PI / 4.0);
    const double s_p = p->print.line_width_mm - t * (1.0 - M_PI / 4.0);
    const double edge_mm = 0.5 * (w_e - s_e);
    const double band_mm = p->print.perimeters > 0 ? s_e + (p->print.perimeters - 1) * s_p : 0;
    for (int k = 0, j = 0; k < d->n_parts && j < n_holes; k++) {
        const part *h = &d->parts[k];
        if (h->parent != i)
            continue;
        int at = j++;
        if (!(h->printed_radius_mm > 0) || !(h->printed_radius_mm < h->radius_mm))
            continue;
        double r[3] = {h->printed_radius_mm + edge_mm,
                       fmin(h->radius_mm, h->printed_radius_mm + edge_mm + band_mm),
                       h->radius_mm};
        tippe_moments m[3];
        for (int q = 0; q < 3; q++) {
            if (q == 2 && !(r[2] > r[1]))
                break;
            int rc = ring_moments(shape, holes, n_holes, at, 1e-3 * r[q], &m[q], err);
            if (rc)
                return rc;
        }
        if (r[1] > r[0])
            *wall = tippe_moments_add(*wall, tippe_moments_sub(m[0], m[1]));
        if (r[2] > r[1])
            *sparse = tippe_moments_add(*sparse, tippe_moments_sub(m[1], m[2]));
    }
    return TIPPE_OK;
}

/* Part p's deposit at infill as made: as the slicer lays it (its holes at
 * their printed radii), less what the cut after printing takes (p->cut_*,
 * at the deposit's flow: the ring within the walls solid, beyond them sparse). */
static tippe_moments as_made(const part *p, const tippe_moments *cut_wall,
                             const tippe_moments *cut_sparse, double infill)
{
    tippe_moments dep = tippe_print_sliced_at(&p->sliced, &p->print, infill, NULL, NULL);
    double bulk = (infill >= 1 ? 1.0 : tippe_print_pattern_bulk(p->print.pattern)) * infill;
    tippe_moments cut = tippe_moments_add(tippe_moments_scale(*cut_wall, p->print.flow),
                                          tippe_moments_scale(*cut_sparse, bulk * p->print.flow));
    return tippe_moments_sub(dep, cut);
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
    tippe_moments cw = {0, 0, 0, 0}, cs = {0, 0, 0, 0};
    if (!rc)
        rc = cut_rings(d, i, shape, holes, n_holes, &cw, &cs, &perr);
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
        double m_s = rho * as_made(p, &cw, &cs, p->print.infill).m;
        p->print.flow *= 1 + c_share * (want - m_s) / m_s;
        double m0 = rho * as_made(p, &cw, &cs, 0).m;
        double m1 = rho * as_made(p, &cw, &cs, 1).m;
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
            if (rho * as_made(p, &cw, &cs, mid).m < want)
                lo = mid;
            else
                hi = mid;
        }
        p->infill = 0.5 * (lo + hi);
    }
    tippe_moments dep = as_made(p, &cw, &cs, p->infill);
    p->cut = tippe_moments_sub(tippe_print_sliced_at(&p->sliced, &p->print, p->infill, NULL, NULL),
                               dep);
    if (p->print.model_error != 0)
        dep = model_error_moved(dep, p->print.model_error);
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

/* A G-code is the same part however often a command loads the design: the
 * tolerance bands, the build sheet's fixes and an optimiser reload it with
 * another radius, density, infill or hole (about 100 loads for one sweep of
 * the M12, 190 for its build sheet), and a 25 MB G-code takes a tenth of a
 * second to read. So the bodies read are kept, with their beads near the axis
 * (for the holes' cuts, below), keyed by the file's identity and change time
 * (device, inode, size, mtime to the nanosecond) and by the options but the
 * density, whose masses scale with it (tippe_gcode_body_set_density). A file
 * rewritten in place gets a new mtime and is read again. A content hash would
 * key across commands too, but the read itself is a fraction of a second
 * (docs/printing.md): it does not pay. */
#define GCODE_CACHE 4
/* Beads are kept this far beyond the widest hole, so that a hole's tolerance
 * and the build sheet's fixes find them kept (a cut needs its radius + 3 mm). */
#define GCODE_KEEP_MARGIN_MM 5.0
typedef struct {
    int used;
    dev_t dev;
    ino_t ino;
    off_t size;
    struct timespec mtime;
    tippe_gcode_options opt; /* density zeroed: not part of the key */
    tippe_gcode_body body;   /* as read: nothing cut */
    tippe_gcode_beads beads;
} gcode_entry;
static gcode_entry gcode_cache[GCODE_CACHE];
static int gcode_next;
static pthread_mutex_t gcode_lock = PTHREAD_MUTEX_INITIALIZER;

static int same_gcode_options(const tippe_gcode_options *a, const tippe_gcode_options *b)
{
    return a->filament_diameter_mm == b->filament_diameter_mm &&
           a->override_diameter == b->override_diameter &&
           a->override_density == b->override_density && a->volumetric_e == b->volumetric_e &&
           a->bead == b->bead;
}

/* A hole of the part, in the design's frame (mm), to be cut from the G-code. */
typedef struct {
    double radius_mm, z_lo_mm, z_hi_mm;
} hole_cut;

/* The cuts of holes on the body's axis, the design's z placed on its bed: the
 * body's bottom is where the layer model has the bed (bed_z_mm). */
static void apply_cuts(tippe_gcode_body *body, const tippe_gcode_beads *beads,
                       const hole_cut *holes, int n, double bed_z_mm)
{
    tippe_gcode_cut cut[TIPPE_GCODE_MAX_CUTS];
    double to_bed = 1e3 * body->bbox_min[2] - bed_z_mm;
    for (int k = 0; k < n; k++) {
        cut[k].axis_x_mm = 1e3 * (body->bbox_min[0] + body->bbox_max[0]) / 2;
        cut[k].axis_y_mm = 1e3 * (body->bbox_min[1] + body->bbox_max[1]) / 2;
        cut[k].radius_mm = holes[k].radius_mm;
        cut[k].z_lo_mm = holes[k].z_lo_mm + to_bed;
        cut[k].z_hi_mm = holes[k].z_hi_mm + to_bed;
    }
    tippe_gcode_cut_body(body, beads, cut, n);
}

/* tippe_gcode_read through the cache, with the holes cut (n 0: none); the
 * density must be the options' own (override_density), one density for every
 * tool, for a hit to rescale. */
static int gcode_read_cached(const char *file, const tippe_gcode_options *opt,
                             const hole_cut *holes, int n, double bed_z_mm,
                             tippe_gcode_body *out, tippe_error *err)
{
    struct stat st;
    tippe_gcode_options key = *opt;
    key.density_g_cm3 = 0;
    double need = 0;
    for (int k = 0; k < n; k++)
        need = fmax(need, holes[k].radius_mm + 3);
    int keyed = opt->override_density && opt->density_g_cm3 > 0 && stat(file, &st) == 0 &&
                S_ISREG(st.st_mode);
    if (keyed) {
        pthread_mutex_lock(&gcode_lock);
        for (int k = 0; k < GCODE_CACHE; k++) {
            const gcode_entry *e = &gcode_cache[k];
            if (e->used && e->dev == st.st_dev && e->ino == st.st_ino && e->size == st.st_size &&
                e->mtime.tv_sec == st.st_mtim.tv_sec && e->mtime.tv_nsec == st.st_mtim.tv_nsec &&
                same_gcode_options(&e->opt, &key) && (!n || e->beads.radius_mm >= need)) {
                *out = e->body;
                tippe_gcode_body_set_density(out, opt->density_g_cm3);
                if (n)
                    apply_cuts(out, &e->beads, holes, n, bed_z_mm);
                pthread_mutex_unlock(&gcode_lock);
                snprintf(out->source, sizeof out->source, "%.*s", (int)sizeof out->source - 1,
                         file);
                return TIPPE_OK;
            }
        }
        pthread_mutex_unlock(&gcode_lock);
    }
    tippe_gcode_beads beads;
    int rc = tippe_gcode_read_beads(file, opt, n ? need + GCODE_KEEP_MARGIN_MM : 0, out, &beads,
                                    err);
    if (rc)
        return rc;
    tippe_gcode_body read = *out;
    if (n)
        apply_cuts(out, &beads, holes, n, bed_z_mm);
    if (!keyed) {
        tippe_gcode_beads_free(&beads);
        return TIPPE_OK;
    }
    pthread_mutex_lock(&gcode_lock);
    gcode_entry *e = &gcode_cache[gcode_next];
    gcode_next = (gcode_next + 1) % GCODE_CACHE;
    tippe_gcode_beads_free(&e->beads);
    e->used = 1;
    e->dev = st.st_dev;
    e->ino = st.st_ino;
    e->size = st.st_size;
    e->mtime = st.st_mtim;
    e->opt = key;
    e->body = read;
    e->beads = beads;
    pthread_mutex_unlock(&gcode_lock);
    return TIPPE_OK;
}

/* What the part loses after printing. The model's part has its holes at the
 * design's radii (a thread modelled as a smooth cylinder of the hole's radius);
 * a maker prints the screw's hole at the tap drill or an insert's pilot
 * (tippe build's 3MF) and then taps, drills or bores it to that radius. So the
 * G-code's plastic inside each hole of the part (a cylinder void cut from it,
 * on the axis as every part is), over the hole's heights, is cut away
 * (gcode_cut.c). The insert's own brass is not added: the model does not have
 * it either (a design part for it would give both). Fills holes (at most
 * TIPPE_GCODE_MAX_CUTS) and which part each is; returns how many. */
static int part_holes(const tippe_design *d, int i, hole_cut *holes, int *which)
{
    int n = 0;
    for (int k = 0; k < d->n_parts && n < TIPPE_GCODE_MAX_CUTS; k++) {
        const part *h = &d->parts[k];
        if (h->parent != i || !h->is_void || h->shape != SHAPE_CYLINDER || h->inner_radius_mm > 0)
            continue;
        double zlo = h->z_mm - h->height_mm / 2, zhi = h->z_mm + h->height_mm / 2;
        if (h->clip_radius_mm > 0) {
            zlo = fmax(zlo, -h->clip_radius_mm);
            zhi = fmin(zhi, h->clip_radius_mm);
        }
        holes[n] = (hole_cut){h->radius_mm, zlo, zhi};
        which[n++] = k;
    }
    return n;
}

/* The hole the G-code leaves against the design's: narrower, the cut says how
 * much plastic went; wider by more than GCODE_HOLE_TOL_MM, the part lacks
 * plastic the model has (no cut can add it). "" when they agree. */
#define GCODE_HOLE_TOL_MM 0.05
static void hole_note(part *p, const tippe_design *d, const int *which, int n,
                      const tippe_gcode_body *body)
{
    size_t used = 0;
    p->gcode_note[0] = 0;
    for (int k = 0; k < n; k++) {
        const part *h = &d->parts[which[k]];
        double rg = body->cut_hole_radius_mm[k];
        if (!isfinite(rg) || fabs(rg - h->radius_mm) <= GCODE_HOLE_TOL_MM)
            continue;
        int m;
        if (h->printed_radius_mm > 0 && rg < h->radius_mm)
            m = snprintf(p->gcode_note + used, sizeof p->gcode_note - used,
                         "%sits hole '%s' is %.2f mm across (printed %.2f mm across: printed_radius_mm), the "
                         "design's %.2f mm: the plastic inside the design's hole (%.3f g in "
                         "all) is taken as cut away after printing (tapped, drilled or bored)",
                         used ? "; " : "", h->name, 2 * rg, 2 * h->printed_radius_mm,
                         2 * h->radius_mm, body->cut_mass_kg * 1e3);
        else
            m = snprintf(p->gcode_note + used, sizeof p->gcode_note - used,
                         rg < h->radius_mm
                             ? "%sits hole '%s' is %.2f mm across, the design's %.2f mm: the "
                               "plastic inside the design's hole (%.3f g in all) is taken as "
                               "cut away after printing (tapped, drilled or bored)"
                             : "%sits hole '%s' is %.2f mm across, wider than the design's "
                               "%.2f mm: the part lacks plastic the model has (%.3f g cut)",
                         used ? "; " : "", h->name, 2 * rg, 2 * h->radius_mm,
                         body->cut_mass_kg * 1e3);
        if (m < 0 || (size_t)m >= sizeof p->gcode_note - used)
            break;
        used += (size_t)m;
    }
}

/* The G-code's body, at density rho_g_cm3, cut for holes[0..n) with the design's
 * bed at bed_z_mm: an upload's (mem, tippe serve: its body as read in memory,
 * cut from the beads kept with it), else the file's through the cache. */
static int gcode_body_cut(const tippe_design_gcode *mem, const char *file,
                          const tippe_gcode_options *opt, double rho_g_cm3,
                          const hole_cut *holes, int n, double bed_z_mm, tippe_gcode_body *out,
                          tippe_error *err)
{
    if (!mem)
        return gcode_read_cached(file, opt, holes, n, bed_z_mm, out, err);
    *out = mem->body;
    tippe_gcode_body_set_density(out, rho_g_cm3);
    if (n)
        apply_cuts(out, &mem->beads, holes, n, bed_z_mm);
    return TIPPE_OK;
}

/* Where part i printed as the G-code's holes show would meet the bed and end
 * (design frame, m): the part's voids as the model prints them, but the holes
 * cut from the G-code (which[0..n)) whose measured radius differs from the
 * model's printed one by more than GCODE_HOLE_TOL_MM, at the G-code's outline:
 * the measured radius is the edge of the external perimeter's rectangle, whose
 * centre line lies s/2 from the outline, so the edge sticks (w - s)/2 =
 * t (1 - pi/4) / 2 into the hole (print_slicer.c, Flow's rounded rectangle).
 * A hole measured from beads read at a wrong filament diameter (too wide or
 * narrow, so their edge is off) would move them wrongly: the G-code's own height,
 * a whole number of layers at or above the part's (about half a layer above on
 * average), is the second witness, and the edges nearer to it are kept.
 * 1 with *bed_m and *top_m set when they move; 0 when the model's stand. */
static int gcode_edges(const tippe_design *d, int i, const int *which, int n,
                       const tippe_gcode_body *body, double *bed_m, double *top_m)
{
    const part *p = &d->parts[i];
    if (p->print.split || !n)
        return 0;
    const double edge_mm = 0.5 * p->print.layer_height_mm * (1.0 - M_PI / 4.0);
    tippe_solid shape = print_solid(p), voids[MAX_PARTS];
    int n_voids = 0, moved = 0;
    for (int k = 0; k < d->n_parts; k++) {
        if (d->parts[k].parent != i)
            continue;
        part h = d->parts[k];
        if (h.printed_radius_mm > 0)
            h.radius_mm = h.printed_radius_mm;
        for (int j = 0; j < n; j++) {
            double rg = body->cut_hole_radius_mm[j] + edge_mm;
            if (which[j] == k && isfinite(rg) && rg > 0 &&
                fabs(rg - h.radius_mm) > GCODE_HOLE_TOL_MM) {
                h.radius_mm = rg;
                moved = 1;
            }
        }
        voids[n_voids++] = print_solid(&h);
    }
    double bed, top;
    if (!moved || !tippe_print_edges(&shape, voids, n_voids, &bed, &top) ||
        (fabs(bed - *bed_m) < 1e-9 && fabs(top - *top_m) < 1e-9))
        return 0;
    const double want_m = body->bbox_max[2] - body->bbox_min[2] - 0.5e-3 * p->print.layer_height_mm;
    if (!(fabs(top - bed - want_m) < fabs(*top_m - *bed_m - want_m)))
        return 0;
    *bed_m = bed;
    *top_m = top;
    return 1;
}

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
    if (!mem) {
        if (p->gcode[0] == '/') {
            snprintf(file, sizeof file, "%s", p->gcode);
        } else {
            char dir[1024];
            tippe_path_dir(d->path, dir, sizeof dir);
            snprintf(file, sizeof file, "%s/%s", dir, p->gcode);
        }
    }
    tippe_gcode_options opt = tippe_gcode_defaults();
    opt.density_g_cm3 = p->density_g_cm3;
    opt.override_density = 1;
    if (p->filament_diameter_mm > 0) { /* the design knows the filament better (Cura) */
        opt.filament_diameter_mm = p->filament_diameter_mm;
        opt.override_diameter = 1;
    }
    tippe_gcode_body body;
    tippe_error gerr = {0};
    hole_cut holes[TIPPE_GCODE_MAX_CUTS];
    int which[TIPPE_GCODE_MAX_CUTS];
    int n_holes = part_holes(d, i, holes, which);
    const tippe_print_sliced *sl = &p->sliced;
    double bed_m = sl->bed_z_m, top_m = sl->top_z_m;
    if (mem) {
        double need = 0;
        for (int k = 0; k < n_holes; k++)
            need = fmax(need, holes[k].radius_mm + 3);
        if (!(n_holes && mem->beads.radius_mm >= need))
            n_holes = 0; /* beyond the beads kept: not cut (hole_note says none) */
    }
    int rc = gcode_body_cut(mem, file, &opt, p->density_g_cm3, holes, n_holes, 1e3 * bed_m,
                            &body, &gerr);
    /* a G-code whose holes are printed otherwise than the model's (tippe slice's
     * 3MF of an older design, tippe export's sliding fit) meets the bed where its
     * own holes open: placed by them, and cut again from there */
    if (!rc && gcode_edges(d, i, which, n_holes, &body, &bed_m, &top_m))
        rc = gcode_body_cut(mem, file, &opt, p->density_g_cm3, holes, n_holes, 1e3 * bed_m,
                            &body, &gerr);
    if (rc)
        return rc == TIPPE_EINPUT ? tippe_json_fail(c, pth, "%s", gerr.msg)
                                  : tippe_error_set(c->err, rc, "%s: %s: %s", c->file, pth,
                                                    gerr.msg);
    p->gcode_bed_shift_mm = 1e3 * (bed_m - sl->bed_z_m);
    tippe_gcode_expect ex = {0};
    ex.height_mm = (top_m - bed_m) * 1e3;
    ex.diameter_mm = 2 * p->radius_mm;
    tippe_gcode_part gp;
    if ((rc = tippe_gcode_match(&body, &ex, &gp, &gerr)))
        return tippe_json_fail(c, pth, "%s does not match part '%s' (printed %.2f mm high and "
                                       "%.2f mm across): %s (read with E in %s%.3g%s)",
                               p->gcode, p->name, ex.height_mm, ex.diameter_mm, gerr.msg,
                               body.volumetric_e ? "mm^3" : "mm of ",
                               body.volumetric_e ? 0.0 : body.filament_diameter_mm,
                               body.volumetric_e ? "" : p->filament_diameter_mm > 0
                                   ? " mm filament, print.filament_diameter_mm"
                                   : " mm filament; a wrong diameter scales every bead: "
                                     "give print.filament_diameter_mm");
    hole_note(p, d, which, n_holes, &body);
    /* the design's diameter wins over the header's (CuraEngine writes E in mm of 2.85 mm
     * filament whatever its header says, issue 40), but a mass that scales as the
     * diameter's square must not change silently: say both */
    if (p->filament_diameter_mm > 0 && !body.volumetric_e && body.header_diameter_mm > 0 &&
        fabs(p->filament_diameter_mm / body.header_diameter_mm - 1) > 1e-3) {
        size_t used = strlen(p->gcode_note);
        const double r = p->filament_diameter_mm / body.header_diameter_mm;
        snprintf(p->gcode_note + used, sizeof p->gcode_note - used,
                 "%sits E is read in mm of the design's %.3g mm filament "
                 "(print.filament_diameter_mm), where its header says %.3g mm: %+.1f %% of "
                 "plastic against the header's", used ? "; " : "", p->filament_diameter_mm,
                 body.header_diameter_mm, 100 * (r * r - 1));
    }
    if (p->gcode_bed_shift_mm != 0) {
        size_t used = strlen(p->gcode_note);
        snprintf(p->gcode_note + used, sizeof p->gcode_note - used,
                 "%sits bed is where its own holes open, %.3f mm %s the model's", used ? "; " : "",
                 fabs(p->gcode_bed_shift_mm), p->gcode_bed_shift_mm > 0 ? "above" : "below");
    }
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
    double m = gp.m * scale, zc = bed_m + gp.z_cm;
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
    const int sliced = p->print.model == TIPPE_PRINT_MODEL_SLICER || p->gcode[0];
    for (int k = 0; k < d->n_parts; k++)
        if (d->parts[k].parent == i) {
            /* the slicer's layers have the hole as printed (printed_radius_mm) */
            part h = d->parts[k];
            if (h.printed_radius_mm > 0 && sliced)
                h.radius_mm = h.printed_radius_mm;
            holes[n_holes++] = print_solid(&h);
            solid = tippe_moments_sub(solid, tippe_design_part_moments(&d->parts[k]));
        }
    if (sliced) {
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

