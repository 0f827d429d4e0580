/* The printed part as PrusaSlicer 2.5 deposits it, layer by layer.
 *
 * The slicer's rules, each from its source (docs/slicer-rules.md names the file and function
 * of each; PrusaSlicer version_2.5.0, src/libslic3r/), applied to a solid of revolution printed
 * with its axis vertical. Every layer is a set of rings, so each rule is interval arithmetic on
 * radii, and the deposit of a layer is a set of annular slabs whose moments are closed forms
 * (tippe_tube). Nothing is sampled but the heights the slicer samples (the middle of each
 * layer, PrintObjectSlice.cpp), so the model is exact arithmetic on the slicer's own
 * discretisation; what it leaves out is listed in docs/printing.md. */
#include "print/section.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Rings per layer: the part's one ring less up to one per void, times two for the
 * differences taken below. */
#define MAX_RINGS 64
/* Layers at most: a 1 m ball at 0.1 mm layers (each layer keeps ~5 kB of rings). */
#define MAX_LAYERS 20000
/* The extremes of the printed part in z are found to this (m). */
#define EDGE_TOL_M 1e-12
/* PrusaSlicer 2.5 grows top and bottom fill surfaces by 3 mm into the infill
 * (EXTERNAL_INFILL_MARGIN, libslic3r.h; LayerRegion::process_external_surfaces). */
#define EXTERNAL_INFILL_MARGIN_M 3e-3
/* Vertical shells: the grown region is opened by 0.5 and 0.8 of 1.05 x the solid
 * infill's spacing (PrintObject::discover_vertical_shells). */
#define SHELL_SPACING_FACTOR 1.05
/* Infill regions narrower than 0.6 x the infill spacing vanish (offset by
 * INSET_OVERLAP_TOLERANCE = 0.4 of the spacing each side, PerimeterGenerator.cpp). */
#define INFILL_MIN_WIDTH_FACTOR 0.6
/* Bridges are round threads of the nozzle's diameter (bridge_flow_ratio 1, PrusaSlicer's
 * default) laid 0.05 mm further apart than their diameter (Flow::bridge_extrusion_spacing,
 * BRIDGE_EXTRA_SPACING in Flow.hpp). */
#define BRIDGE_EXTRA_SPACING_M 0.05e-3
/* Top and bottom surfaces are opened by a tenth of the external perimeter's width
 * (PrintObject::detect_surfaces_type). */
#define SURFACE_OPENING_FACTOR 0.1

typedef struct {
    int n;
    double lo[MAX_RINGS], hi[MAX_RINGS]; /* m; sorted, disjoint; lo == 0: a disc */
} rings;

/* ------------------------------------------------------------ rings */

static void rings_push(rings *s, double lo, double hi)
{
    if (!(lo < hi) || s->n >= MAX_RINGS)
        return;
    if (s->n && lo <= s->hi[s->n - 1]) { /* touching or overlapping: merge */
        if (hi > s->hi[s->n - 1])
            s->hi[s->n - 1] = hi;
        return;
    }
    s->lo[s->n] = lo;
    s->hi[s->n++] = hi;
}

static void rings_intersect(const rings *a, const rings *b, rings *out)
{
    rings r = {0};
    for (int i = 0, j = 0; i < a->n && j < b->n;) {
        rings_push(&r, fmax(a->lo[i], b->lo[j]), fmin(a->hi[i], b->hi[j]));
        if (a->hi[i] < b->hi[j])
            i++;
        else
            j++;
    }
    *out = r;
}

static void rings_subtract(const rings *a, const rings *b, rings *out)
{
    rings r = {0};
    for (int i = 0; i < a->n; i++) {
        double lo = a->lo[i];
        for (int j = 0; j < b->n && lo < a->hi[i]; j++) {
            if (b->hi[j] <= lo || b->lo[j] >= a->hi[i])
                continue;
            rings_push(&r, lo, b->lo[j]);
            lo = fmax(lo, b->hi[j]);
        }
        rings_push(&r, lo, a->hi[i]);
    }
    *out = r;
}

static void rings_union(const rings *a, const rings *b, rings *out)
{
    rings r = {0};
    int i = 0, j = 0;
    while (i < a->n || j < b->n) {
        if (j >= b->n || (i < a->n && a->lo[i] <= b->lo[j])) {
            rings_push(&r, a->lo[i], a->hi[i]);
            i++;
        } else {
            rings_push(&r, b->lo[j], b->hi[j]);
            j++;
        }
    }
    *out = r;
}

/* Each ring's bounding circles moved by d (d < 0 shrinks, d > 0 grows): a 2-D
 * offset of an annulus is the annulus of the offset radii. The axis is not a
 * boundary (a disc keeps lo = 0), and a grown ring stops at the axis. */
static void rings_offset(const rings *a, double d, rings *out)
{
    rings r = {0};
    for (int i = 0; i < a->n; i++) {
        double lo = a->lo[i] > 0 ? fmax(0.0, a->lo[i] - d) : 0.0;
        rings_push(&r, lo, a->hi[i] + d);
    }
    *out = r;
}

/* Morphological opening: shrink by a, grow by b (b >= a): rings narrower than
 * 2a (a disc: whose diameter is) vanish, the rest grow by b - a. */
static void rings_opening(const rings *a, double shrink, double grow, rings *out)
{
    rings t;
    rings_offset(a, -shrink, &t);
    rings_offset(&t, grow, out);
}

/* Rings narrower than w vanish (a disc: narrower than its diameter). */
static void rings_drop_narrow(rings *s, double w)
{
    rings r = {0};
    for (int i = 0; i < s->n; i++)
        if ((s->lo[i] > 0 ? s->hi[i] - s->lo[i] : 2 * s->hi[i]) >= w)
            rings_push(&r, s->lo[i], s->hi[i]);
    *s = r;
}

/* Unit-density moments of the slab of rings r, thickness t, centred at z. */
static tippe_moments rings_slab(const rings *r, double t, double z)
{
    tippe_moments m = {0, 0, 0, 0};
    for (int i = 0; i < r->n; i++)
        m = tippe_moments_add(m, tippe_tube(r->lo[i], r->hi[i], t, z, 0.0));
    return m;
}

/* ------------------------------------------------------------ layers */

typedef struct {
    double z_mid;       /* design frame, m: where the slicer cuts (the layer's middle) */
    double t;           /* thickness, m */
    double w_ext;       /* the external perimeter's width, m */
    double s_ext, s_per, s_fill; /* spacings of its lines, m */
    rings outline, walls, infill, surface;
    rings slice_surface; /* the slice's own top and bottom (perimeters' area included) */
    rings bridge;       /* bottom surfaces over air, grown onto their support: bridged */
    rings solid, sparse; /* its solid infill (surfaces included) and the rest of its infill */
} layer_t;

/* A line of width w laid in layers t thick is a band w - t (1 - pi/4) wide
 * (Flow::rounded_rectangle_extrusion_spacing, Flow.cpp). */
static double spacing(double w, double t) { return w - t * (1.0 - M_PI / 4.0); }

typedef struct {
    const tippe_solid *part, *voids;
    int n_voids, flip;
    int half;   /* 0: the whole part; +1: only z >= cut; -1: only z <= cut (a split half) */
    double cut; /* m, design frame */
} slicer_part;

static void outline_at(const slicer_part *p, double z_print, rings *out)
{
    double z = p->flip ? -z_print : z_print;
    double lo[MAX_RINGS], hi[MAX_RINGS];
    out->n = 0;
    if ((p->half > 0 && z < p->cut) || (p->half < 0 && z > p->cut))
        return;
    int n = tippe_print_section(p->part, p->voids, p->n_voids, z, lo, hi, MAX_RINGS);
    out->n = 0;
    for (int i = 0; i < n; i++)
        rings_push(out, lo[i], hi[i]);
}

/* The lowest (dir = +1) or highest (dir = -1) height in the print frame where
 * the part has material: where the slicer's bed (or the last layer) is. */
static int printed_edge(const slicer_part *p, double zlo, double zhi, int dir, double *edge)
{
    enum { N = 4096 };
    rings r;
    double prev = dir > 0 ? zlo : zhi;
    for (int k = 1; k <= N; k++) {
        double z = dir > 0 ? zlo + (zhi - zlo) * k / N : zhi - (zhi - zlo) * k / N;
        outline_at(p, z, &r);
        if (!r.n) {
            prev = z;
            continue;
        }
        double a = prev, b = z; /* a empty, b not: bisect */
        while (fabs(b - a) > EDGE_TOL_M) {
            double m = 0.5 * (a + b);
            outline_at(p, m, &r);
            if (r.n)
                b = m;
            else
                a = m;
        }
        *edge = b;
        return 1;
    }
    return 0;
}

/* Layer i's walls and infill region (PerimeterGenerator::process_arachne): the
 * external perimeter's band starts (w_e - s_e)/2 inside the outline, the walls
 * are s_e + (n - 1) s_p thick, and the infill region starts infill_overlap x s_p
 * before their inner edge (so the two overlap there). */
static void walls_and_infill(const tippe_print_settings *s, layer_t *L)
{
    const int n = s->perimeters;
    double d0 = n > 0 ? 0.5 * (L->w_ext - L->s_ext) : 0.0;
    double W = n > 0 ? L->s_ext + (n - 1) * L->s_per : 0.0;
    double d_f = n > 0 ? d0 + W - s->infill_overlap * L->s_per : 0.0;
    rings inner, band, outer;
    rings_offset(&L->outline, -d0, &outer);
    rings_offset(&L->outline, -(d0 + W), &inner);
    rings_subtract(&outer, &inner, &band);
    L->walls = band;
    rings_offset(&L->outline, -d_f, &L->infill);
    rings_drop_narrow(&L->infill, INFILL_MIN_WIDTH_FACTOR * L->s_fill);
}

/* Layer i's top and bottom fill surfaces (PrintObject::detect_surfaces_type):
 * what of its slice the layer above (below) does not cover, opened by w_e / 10
 * (the first layer is all bottom), and only then clipped to the infill region
 * (LayerRegion::slices_to_fill_surfaces_clipped): a step of the outline wider
 * than d_f leaves a fill surface however thin. Grown by EXTERNAL_INFILL_MARGIN
 * within the infill region (2.5's process_external_surfaces). */
static void surfaces(const tippe_print_settings *s, layer_t *layers, int n_layers, int i)
{
    layer_t *L = &layers[i];
    static const rings none = {0};
    double d = 0.5 * SURFACE_OPENING_FACTOR * L->w_ext;
    /* the slice's own top and bottom, the perimeters' area included: the
     * vertical shells take these too (discover_vertical_shells' cache of
     * layerm.slices' stTop and stBottom, beside the fill surfaces') */
    rings st, sb, top, bottom, both;
    rings_subtract(&L->outline, i + 1 < n_layers ? &layers[i + 1].outline : &none, &st);
    if (i == 0)
        sb = L->outline;
    else
        rings_subtract(&L->outline, &layers[i - 1].outline, &sb);
    if (s->top_bottom_layers == 0)
        st.n = sb.n = 0; /* no solid layers: surfaces are filled as the rest (PrintObject.cpp) */
    rings_opening(&st, d, d, &top);
    rings_opening(&sb, d, d, &bottom);
    rings_union(&top, &bottom, &L->slice_surface);
    rings_intersect(&L->slice_surface, &L->infill, &both);
    rings grown;
    rings_offset(&both, both.n ? EXTERNAL_INFILL_MARGIN_M : 0.0, &grown);
    rings_intersect(&grown, &L->infill, &L->surface);
    /* a bottom surface above the first layer hangs over air: bridged, over the
     * area it was grown to (it anchors there; LayerRegion::process_external_surfaces) */
    L->bridge.n = 0;
    if (i > 0) {
        rings ob, gb;
        rings_intersect(&bottom, &L->infill, &ob);
        rings_offset(&ob, ob.n ? EXTERNAL_INFILL_MARGIN_M : 0.0, &gb);
        rings_intersect(&gb, &L->infill, &L->bridge);
    }
}

/* The layers whose shells count for layer i (PrintObject::discover_vertical_shells):
 * upwards while fewer than top_solid_layers or thinner than top_solid_min_thickness,
 * downwards likewise with the bottom settings. */
static void shell_range(const tippe_print_settings *s, const layer_t *layers, int n_layers, int i,
                        int *lo, int *hi)
{
    if (s->top_bottom_layers == 0) { /* no shells: the minimum thicknesses need layers */
        *lo = *hi = i;
        return;
    }
    int j = i + 1;
    while (j < n_layers && (j < i + s->top_bottom_layers ||
                            layers[j].z_mid - layers[i].z_mid < s->top_min_mm * 1e-3 - 1e-12))
        j++;
    *hi = j - 1;
    j = i - 1;
    while (j >= 0 && (j > i - s->top_bottom_layers ||
                      layers[i].z_mid - layers[j].z_mid < s->bottom_min_mm * 1e-3 - 1e-12))
        j--;
    *lo = j + 1;
}

/* solid_infill_below_area (LayerRegion::prepare_fill_surfaces, LayerRegion.cpp):
 * before the surfaces grow and the shells are found, each island of a layer's
 * internal region (its infill region less its opened top and bottom) whose area
 * is at most the setting becomes solid, when there is any infill at all (the
 * model takes the design's infill: tippe_print_sliced_at keeps them at 0 %). On
 * a body of revolution every island is a ring, or a disc at the axis. */
static void small_islands(const tippe_print_settings *s, const layer_t *L, rings *out)
{
    out->n = 0;
    const double a_max = s->solid_infill_below_area_mm2 * 1e-6;
    if (!(a_max > 0) || !(s->infill > 0))
        return;
    rings internal;
    rings_subtract(&L->infill, &L->slice_surface, &internal);
    for (int k = 0; k < internal.n; k++)
        if (M_PI * (internal.hi[k] * internal.hi[k] - internal.lo[k] * internal.lo[k]) <= a_max)
            rings_push(out, internal.lo[k], internal.hi[k]);
}

/* Layer i's solid infill: its own surfaces, and the vertical shell: where its
 * infill region is not inside every neighbour's infill region, or a neighbour's
 * surface (grown by 1.05 s) lies over it; the shell opened (bands narrower than
 * 1.05 s vanish, the rest grow by 0.3 x 1.05 s), all within the infill region. */
static void solid_infill(const tippe_print_settings *s, const layer_t *layers, int n_layers,
                         int i, rings *solid)
{
    const layer_t *L = &layers[i];
    int lo, hi;
    shell_range(s, layers, n_layers, i, &lo, &hi);
    double sp = SHELL_SPACING_FACTOR * L->s_fill;
    rings common = L->infill, cover = {0}, t;
    for (int j = lo; j <= hi; j++) {
        if (j == i)
            continue;
        rings_intersect(&common, &layers[j].infill, &t);
        common = t;
        rings g, g2, both;
        rings_offset(&layers[j].surface, sp, &g);
        rings_offset(&layers[j].slice_surface, sp, &g2);
        rings_union(&g, &g2, &both);
        rings_union(&cover, &both, &t);
        cover = t;
    }
    rings shell, opened, small;
    rings_subtract(&L->infill, &common, &shell);
    rings_union(&shell, &cover, &t);
    rings_intersect(&t, &L->infill, &shell);
    small_islands(s, L, &small);
    if (!shell.n) { /* no shell: the layer keeps its small islands as they are */
        rings_union(&small, &L->surface, solid);
        return;
    }
    rings_union(&shell, &small, &t); /* they join the shell before its opening */
    rings_opening(&t, 0.5 * sp, 0.8 * sp, &opened);
    rings_intersect(&opened, &L->infill, &shell);
    rings_union(&shell, &L->surface, solid);
}

/* A bridge's thread (LayerRegion::bridging_flow): with thick_bridges a round
 * thread of the nozzle's diameter (bridge_flow_ratio 1), as high as it is wide;
 * without, the role's own flat line. Its height decides how many layers below a
 * bridge over infill must be sparse, its width how narrow a bridge vanishes. */
static double bridge_height(const tippe_print_settings *s, const layer_t *L)
{
    return s->thick_bridges ? s->nozzle_mm * 1e-3 : L->t;
}

/* Layer i's solid infill laid as a bridge over the sparse infill below
 * (PrintObject::bridge_over_infill, PrintObject.cpp): its internal solid infill
 * (the vertical shells, not its own surfaces) over the sparse infill of every
 * layer whose top lies within the bridge's height below its top (EPSILON =
 * 1e-4 mm, libslic3r.h), opened by 3 x the bridge's width (narrower parts are
 * laid as solid infill); skipped on the first layer. At 100 % infill there is
 * none (fill_density 100 skips it): tippe_print_sliced_at leaves it out there. */
static void bridge_over_infill(const tippe_print_settings *s, const layer_t *layers, int i,
                               rings *out)
{
    const layer_t *L = &layers[i];
    out->n = 0;
    if (i == 0)
        return;
    rings cand, t;
    rings_subtract(&L->solid, &L->surface, &cand);
    const double top = L->z_mid + 0.5 * L->t, h_b = bridge_height(s, L);
    const double bottom_z = top - h_b - 1e-7;
    for (int j = i - 1; j >= 0 && cand.n; j--) {
        if (layers[j].z_mid + 0.5 * layers[j].t < bottom_z)
            break;
        rings_intersect(&cand, &layers[j].sparse, &t);
        cand = t;
    }
    /* the bridge's width: the nozzle's thread, or the solid infill's line */
    double w_b = s->thick_bridges ? s->nozzle_mm * 1e-3 : s->infill_width_mm * 1e-3;
    rings_opening(&cand, 3 * w_b, 3 * w_b, &t);
    rings_intersect(&t, &L->solid, out);
}

/* Overhang perimeters (PerimeterGenerator.cpp, "detect overhanging/bridging
 * perimeters"): a perimeter loop whose centre line lies outside the layer
 * below's slices grown by half the nozzle is laid with the overhang flow,
 * LayerRegion::bridging_flow(frPerimeter): with thick_bridges a round thread of
 * the nozzle's diameter (pi d^2 / 4 per unit length) instead of its flat line
 * (s t); without, the (inner) perimeters' flat line (s_p t). The loops' centre lines: the external one w_e / 2 inside the outline,
 * the next (s_e + s_p) / 2 further, then s_p apart. Returns the extra moments. */
static tippe_moments overhang_extra(const tippe_print_settings *s, const layer_t *L,
                                    const layer_t *below, double z)
{
    tippe_moments m = {0, 0, 0, 0};
    if (!below || s->perimeters <= 0)
        return m;
    rings support;
    rings_offset(&below->outline, 0.5 * s->nozzle_mm * 1e-3, &support);
    const double d = s->nozzle_mm * 1e-3;
    const double thread = s->thick_bridges ? M_PI * d * d / 4 : L->s_per * L->t;
    for (int r = 0; r < L->outline.n; r++)
        for (int side = 0; side < 2; side++) {
            double edge = side ? L->outline.lo[r] : L->outline.hi[r];
            if (!(edge > 0))
                continue; /* the axis is no boundary */
            double depth = 0.5 * L->w_ext;
            for (int k = 0; k < s->perimeters; k++) {
                double sp = k ? L->s_per : L->s_ext;
                if (k == 1)
                    depth += 0.5 * (L->s_ext + L->s_per);
                else if (k > 1)
                    depth += L->s_per;
                double rc = side ? edge + depth : edge - depth;
                int held = 0;
                for (int j = 0; j < support.n && !held; j++)
                    held = rc >= support.lo[j] && rc <= support.hi[j];
                if (held || !(rc > 0))
                    continue;
                double v = 2 * M_PI * rc * (thread - sp * L->t);
                m = tippe_moments_add(m, (tippe_moments){v, v * z, v * (z * z + L->t * L->t / 12),
                                                         v * rc * rc});
            }
        }
    return m;
}

/* The anchors and joins of sparse lines along their region's boundary
 * (Fill::connect_infill, FillBase.cpp). Lines d = s / (bulk x infill) apart meet
 * a boundary at an angle theta to it, their ends sin(theta) / d apart per unit
 * length: neighbouring ends are joined along the boundary when that gap
 * d / sin(theta) is at most infill_anchor_max, and every other gap is joined
 * (a zigzag), so half the boundary is traced; where the gap is longer, each end
 * gets an anchor of at most infill_anchor along it, a sin(theta) / d of it (at
 * most half). Over a closed boundary every angle comes equally often, so the
 * traced share is the mean over theta in [0, pi/2], in closed form. The lines stop
 * s/2 inside the boundary, which takes back the pattern's bulk x infill of that
 * strip. Returned as the band's width over s/2. */
static double anchor_factor(const tippe_print_settings *s, double s_fill, double bulk)
{
    if (!(bulk > 0))
        return 0.0;
    double d = s_fill / bulk, a = s->anchor_mm * 1e-3, a_max = s->anchor_max_mm * 1e-3;
    /* mean over theta of: 1/2 where sin(theta) >= d / a_max, else min(1/2, a sin(theta) / d) */
    double tc = asin(fmin(1.0, d / fmax(a_max, 1e-300)));
    double th = a > 0 ? asin(fmin(1.0, d / (2 * a))) : M_PI / 2; /* where a sin / d reaches 1/2 */
    double low = th >= tc ? (a / d) * (1 - cos(tc)) : (a / d) * (1 - cos(th)) + 0.5 * (tc - th);
    double share = (0.5 * (0.5 * M_PI - tc) + low) / (0.5 * M_PI);
    /* at full density the lines fill the strip themselves: no band, never a negative one */
    return fmax(0.0, 2.0 * share - fmin(bulk, 1.0));
}

/* Moments of a band lambda wide along the circles bounding r, in a slab t thick
 * at z: 2 pi rho lambda t at each boundary radius rho (the axis is none). */
static tippe_moments boundary_band(const rings *r, double lambda, double t, double z)
{
    tippe_moments m = {0, 0, 0, 0};
    for (int i = 0; i < r->n; i++) {
        double rho[2] = {r->lo[i], r->hi[i]};
        for (int k = 0; k < 2; k++) {
            if (!(rho[k] > 0))
                continue;
            double v = 2 * M_PI * rho[k] * lambda * t;
            m = tippe_moments_add(m, (tippe_moments){v, v * z, v * (z * z + t * t / 12),
                                                     v * rho[k] * rho[k]});
        }
    }
    return m;
}

/* ------------------------------------------------------------ the part */

int tippe_print_slice_moments(const tippe_solid *part, const tippe_solid *voids, int n_voids,
                              const tippe_print_settings *s, int flip, tippe_print_sliced *out,
                              tippe_error *err)
{
    return tippe_print_slice_layers(part, voids, n_voids, s, flip, out, NULL, 0, err);
}

/* One piece printed standing on the bed: the whole part, or a split half. */
static int slice_piece(const slicer_part *Pp, const tippe_print_settings *s,
                       tippe_print_sliced *out, tippe_print_layer *rows, int cap,
                       tippe_error *err)
{
    const slicer_part P = *Pp;
    const int flip = P.flip;
    memset(out, 0, sizeof *out);
    double bulk = tippe_print_pattern_bulk(s->pattern);
    double zlo, zhi;
    if (!tippe_print_extent(P.part, &zlo, &zhi))
        return TIPPE_OK;
    if (flip) {
        double t = zlo;
        zlo = -zhi;
        zhi = -t;
    }
    double bed, top;
    if (!printed_edge(&P, zlo, zhi, +1, &bed) || !printed_edge(&P, zlo, zhi, -1, &top))
        return TIPPE_OK; /* nothing printed */
    const double h = s->layer_height_mm * 1e-3, h1 = s->first_layer_height_mm * 1e-3;
    double height = top - bed;
    long n_layers = height <= h1 ? 1 : 1 + (long)ceil((height - h1) / h - 1e-9);
    if (n_layers > MAX_LAYERS)
        return tippe_error_set(err, TIPPE_EINPUT,
                               "%ld layers of %g mm: more than the layer model takes (%d)",
                               n_layers, s->layer_height_mm, MAX_LAYERS);
    layer_t *L = calloc((size_t)n_layers, sizeof *L);
    if (!L)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "print model: out of memory");
    int n = 0;
    for (long i = 0; i < n_layers; i++) {
        double t = i ? h : h1, bottom = i ? bed + h1 + (double)(i - 1) * h : bed;
        layer_t *l = &L[n];
        outline_at(&P, bottom + 0.5 * t, &l->outline);
        if (!l->outline.n)
            continue; /* a layer that cuts no material is no layer */
        /* the first layer takes first_layer_extrusion_width for every line (PrintRegion::flow) */
        int first = i == 0 && s->first_layer_width_mm > 0;
        double w_e = (first ? s->first_layer_width_mm : s->external_width_mm) * 1e-3;
        double w_p = (first ? s->first_layer_width_mm : s->line_width_mm) * 1e-3;
        double w_f = (first ? s->first_layer_width_mm : s->infill_width_mm) * 1e-3;
        l->t = t;
        l->z_mid = bottom + 0.5 * t;
        l->w_ext = w_e;
        l->s_ext = spacing(w_e, t);
        l->s_per = spacing(w_p, t);
        l->s_fill = spacing(w_f, t);
        walls_and_infill(s, l);
        n++;
    }
    for (int i = 0; i < n; i++)
        surfaces(s, L, n, i);
    for (int i = 0; i < n; i++) {
        solid_infill(s, L, n, i, &L[i].solid);
        rings_subtract(&L[i].infill, &L[i].solid, &L[i].sparse);
    }
    tippe_moments fixed = {0, 0, 0, 0}, sparse = {0, 0, 0, 0}, band = {0, 0, 0, 0};
    tippe_moments over_infill = {0, 0, 0, 0};
    for (int i = 0; i < n; i++) {
        layer_t *l = &L[i];
        double z = flip ? -l->z_mid : l->z_mid;
        const rings *solid = &l->solid, *sp = &l->sparse;
        tippe_moments w = rings_slab(&l->walls, l->t, z), so = rings_slab(solid, l->t, z);
        /* bridged areas deposit the bridge's thread per its spacing instead of t:
         * pi d^2 / 4 per (d + 0.05 mm) (Flow::mm3_per_mm, bridge_extrusion_spacing);
         * without thick_bridges the solid infill's own line, no change */
        const double dn = s->nozzle_mm * 1e-3;
        const double bridge_ratio =
            s->thick_bridges ? M_PI * dn * dn / 4 / ((dn + BRIDGE_EXTRA_SPACING_M) * l->t) : 1.0;
        rings br, inner;
        rings_intersect(&l->bridge, solid, &br);
        so = tippe_moments_add(so, tippe_moments_scale(rings_slab(&br, l->t, z), bridge_ratio - 1));
        bridge_over_infill(s, L, i, &inner);
        tippe_moments ob = tippe_moments_scale(rings_slab(&inner, l->t, z), bridge_ratio - 1);
        over_infill = tippe_moments_add(over_infill, ob);
        w = tippe_moments_add(w, overhang_extra(s, l, i > 0 ? &L[i - 1] : NULL, z));
        fixed = tippe_moments_add(fixed, tippe_moments_add(w, so));
        if (s->infill < 1) /* the bridges over infill, kept apart for another infill */
            so = tippe_moments_add(so, ob);
        out->wall_m3 += w.m * s->flow;
        out->solid_m3 += so.m * s->flow;
        tippe_moments spm = rings_slab(sp, l->t, z);
        tippe_moments bm = boundary_band(sp, 0.5 * l->s_fill, l->t, z);
        sparse = tippe_moments_add(sparse, spm);
        band = tippe_moments_add(band, bm);
        if (rows && i < cap) {
            double bulk_f = bulk * s->infill;
            double a = s->infill > 0 ? anchor_factor(s, n > 1 ? L[1].s_fill : l->s_fill, bulk_f)
                                     : 0.0;
            rows[i] = (tippe_print_layer){.z_mid_m = z, .thickness_m = l->t,
                                          .wall_m3 = w.m * s->flow, .solid_m3 = so.m * s->flow,
                                          .sparse_m3 = spm.m * bulk_f * s->flow,
                                          .anchor_m3 = bm.m * a * s->flow};
        }
    }
    out->fixed = fixed;
    out->over_infill = over_infill;
    out->sparse_region = sparse;
    out->sparse_band = band;
    out->s_fill_m = n > 1 ? L[1].s_fill : n ? L[0].s_fill : 0.0;
    out->deposit = tippe_print_sliced_at(out, s, s->infill, &out->sparse_m3, &out->anchor_m3);
    out->n_layers = n;
    out->bed_z_m = flip ? -bed : bed;
    out->top_z_m = flip ? -top : top;
    free(L);
    return TIPPE_OK;
}

/* The edges slice_piece finds for the whole part, without its layers. */
int tippe_print_edges(const tippe_solid *part, const tippe_solid *voids, int n_voids,
                      double *bed_z_m, double *top_z_m)
{
    const slicer_part P = {part, voids, n_voids, 0, 0, 0};
    double zlo, zhi;
    return tippe_print_extent(part, &zlo, &zhi) && printed_edge(&P, zlo, zhi, +1, bed_z_m) &&
           printed_edge(&P, zlo, zhi, -1, top_z_m);
}

int tippe_print_slice_layers(const tippe_solid *part, const tippe_solid *voids, int n_voids,
                             const tippe_print_settings *s, int flip, tippe_print_sliced *out,
                             tippe_print_layer *rows, int cap, tippe_error *err)
{
    memset(out, 0, sizeof *out);
    if (!(tippe_print_pattern_bulk(s->pattern) > 0))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "infill pattern '%s' deposits a shape-dependent amount (no bulk "
                               "fraction to model): slice the part and give its G-code",
                               tippe_print_pattern_name(s->pattern));
    if (!s->split) {
        slicer_part P = {part, voids, n_voids, flip, 0, 0};
        return slice_piece(&P, s, out, rows, cap, err);
    }
    /* in two halves, each standing on its cut face (tippe export --split): the
     * upper half as designed, the lower one upside down; the cut face is each
     * half's first layer, a bottom surface like any other */
    const double cut = s->split_z_mm * 1e-3;
    slicer_part up = {part, voids, n_voids, 0, +1, cut}, down = {part, voids, n_voids, 1, -1, cut};
    tippe_print_sliced a, b;
    int rc = slice_piece(&up, s, &a, rows, cap, err);
    if (!rc)
        rc = slice_piece(&down, s, &b, rows && cap > a.n_layers ? rows + a.n_layers : NULL,
                         cap - a.n_layers, err);
    if (rc)
        return rc;
    out->fixed = tippe_moments_add(a.fixed, b.fixed);
    out->over_infill = tippe_moments_add(a.over_infill, b.over_infill);
    out->sparse_region = tippe_moments_add(a.sparse_region, b.sparse_region);
    out->sparse_band = tippe_moments_add(a.sparse_band, b.sparse_band);
    out->wall_m3 = a.wall_m3 + b.wall_m3;
    out->solid_m3 = a.solid_m3 + b.solid_m3;
    out->n_layers = a.n_layers + b.n_layers;
    out->s_fill_m = a.s_fill_m > 0 ? a.s_fill_m : b.s_fill_m;
    out->bed_z_m = out->top_z_m = cut;
    out->deposit = tippe_print_sliced_at(out, s, s->infill, &out->sparse_m3, &out->anchor_m3);
    return TIPPE_OK;
}

/* The deposit at another infill: the walls and solid infill do not depend on
 * it, the sparse lines deposit bulk x infill of their region and the anchors a
 * band (1 - bulk x infill) x s/2 (times the anchor factor) along its boundary. */
tippe_moments tippe_print_sliced_at(const tippe_print_sliced *sl, const tippe_print_settings *s,
                                    double infill, double *sparse_m3, double *anchor_m3)
{
    /* at 100 % the slicer fills with lines (a 3MF from tippe export says rectilinear) */
    double bulk = (infill >= 1 ? 1.0 : tippe_print_pattern_bulk(s->pattern)) * infill;
    double a = infill > 0 ? anchor_factor(s, sl->s_fill_m, bulk) : 0.0;
    tippe_moments sp = tippe_moments_scale(sl->sparse_region, bulk);
    tippe_moments an = tippe_moments_scale(sl->sparse_band, a);

    if (sparse_m3)
        *sparse_m3 = sp.m * s->flow;
    if (anchor_m3)
        *anchor_m3 = an.m * s->flow;
    tippe_moments all = tippe_moments_add(sl->fixed, tippe_moments_add(sp, an));
    /* no bridges over infill at 100 % (PrintObject::bridge_over_infill) */
    if (infill < 1)
        all = tippe_moments_add(all, sl->over_infill);
    return tippe_moments_scale(all, s->flow);
}

/* ------------------------------------------------------------ patterns */

static const struct {
    const char *name;
    double bulk; /* deposited fraction of the nominal density in bulk; 0: not modelled */
} patterns[TIPPE_PRINT_N_PATTERNS] = {
    /* 2.44 x the gyroid's mean curve length per unit area of a horizontal slice in
     * its own units (0.3944, by the co-area formula over a period; tests/test_print_slicer.c
     * recomputes it): FillGyroid.cpp scales the pattern by spacing / (2.44 density). */
    [TIPPE_PATTERN_GYROID] = {"gyroid", 0.9623},
    /* lines spacing / density apart (FillRectilinear.cpp, fill_surface_by_lines): exactly */
    [TIPPE_PATTERN_RECTILINEAR] = {"rectilinear", 1.0},
    [TIPPE_PATTERN_ALIGNED_RECTILINEAR] = {"alignedrectilinear", 1.0},
    [TIPPE_PATTERN_MONOTONIC] = {"monotonic", 1.0},
    /* n directions, each n spacing / density apart (fill_surface_by_multilines) */
    [TIPPE_PATTERN_GRID] = {"grid", 1.0},
    [TIPPE_PATTERN_TRIANGLES] = {"triangles", 1.0},
    [TIPPE_PATTERN_STARS] = {"stars", 1.0},
    [TIPPE_PATTERN_CUBIC] = {"cubic", 1.0},
    /* loops spacing / density apart (FillConcentric.cpp) */
    [TIPPE_PATTERN_CONCENTRIC] = {"concentric", 1.0},
    /* zigzag columns a distance d = spacing / density apart, each period 2 sqrt(3) d long
     * tracing 8 d / sqrt(3) of line (FillHoneycomb.cpp): 4/3 of the density */
    [TIPPE_PATTERN_HONEYCOMB] = {"honeycomb", 4.0 / 3.0},
    /* shape-dependent: an octree or a tree that follows the part (FillAdaptive.cpp,
     * FillLightning.cpp), 3D honeycomb's per-layer truncated octahedra */
    [TIPPE_PATTERN_ADAPTIVE_CUBIC] = {"adaptivecubic", 0},
    [TIPPE_PATTERN_SUPPORT_CUBIC] = {"supportcubic", 0},
    [TIPPE_PATTERN_LIGHTNING] = {"lightning", 0},
    [TIPPE_PATTERN_3D_HONEYCOMB] = {"3dhoneycomb", 0},
};

const char *tippe_print_pattern_name(int pattern)
{
    return pattern >= 0 && pattern < TIPPE_PRINT_N_PATTERNS ? patterns[pattern].name : "?";
}

int tippe_print_pattern_parse(const char *name)
{
    for (int i = 0; i < TIPPE_PRINT_N_PATTERNS; i++)
        if (!strcmp(name, patterns[i].name))
            return i;
    return -1;
}

double tippe_print_pattern_bulk(int pattern)
{
    return pattern >= 0 && pattern < TIPPE_PRINT_N_PATTERNS ? patterns[pattern].bulk : 0.0;
}

/* The shipped profile's values (designs/slicer/prusa-pla-0.4mm.ini), which the
 * model follows; PrusaSlicer 2.5's own defaults differ where noted
 * (PrintConfig.cpp, set_default_value), and a maker's profile may differ in any:
 * issue 40 measured thick_bridges off moving the shells' body A/C by 0.009. */
static const tippe_print_assumed assumed[] = {
    {"thick_bridges", "1", "bridges and overhang perimeters as round threads of the nozzle's "
                           "diameter (the model's overhang rule)"},
    {"solid_infill_below_area", "0", "no small region made solid (2.5's default: 70 mm^2)"},
    {"extra_perimeters", "0", "no perimeter added over sloping layers (2.5's default: on)"},
    {"perimeter_generator", "arachne", "the walls' beads (the measured model error assumes it)"},
    {"thin_walls", "0", "no single thin walls (2.5's default: on)"},
    {"gap_fill_enabled", "1", "gaps between perimeters filled"},
    {"top_fill_pattern", "monotonic", "the top surfaces' lines"},
    {"bottom_fill_pattern", "monotonic", "the bottom surfaces' lines"},
    {"infill_every_layers", "1", "sparse infill on every layer"},
    {"solid_infill_every_layers", "0", "no solid layer every N layers"},
    {"infill_only_where_needed", "0", "infill everywhere inside"},
    {"overhangs", "1", "overhanging perimeters detected (laid as bridges)"},
    {"bridge_flow_ratio", "1", "a bridge's flow"},
    {"fill_angle", "45", "the sparse lines' angle"},
    {"bridge_angle", "0", "bridges at their own best angle"},
    {NULL, NULL, NULL},
};

const tippe_print_assumed *tippe_print_assumed_settings(void) { return assumed; }

/* The pinned settings with the design's values where the print block models
 * them, so that tippe's 3MF makes the slicer deposit what the model assumed. */
int tippe_print_pinned_settings(const tippe_print_settings *s, tippe_print_pin *out, int cap)
{
    int n = 0;
    for (const tippe_print_assumed *a = assumed; a->key && n < cap; a++, n++) {
        out[n].key = a->key;
        out[n].decides = a->decides;
        snprintf(out[n].value, sizeof out[n].value, "%s", a->value);
        if (!strcmp(a->key, "thick_bridges"))
            snprintf(out[n].value, sizeof out[n].value, "%d", s->thick_bridges ? 1 : 0);
        else if (!strcmp(a->key, "solid_infill_below_area"))
            snprintf(out[n].value, sizeof out[n].value, "%.9g", s->solid_infill_below_area_mm2);
        else if (!strcmp(a->key, "perimeter_generator"))
            snprintf(out[n].value, sizeof out[n].value, "%s",
                     s->perimeter_generator == TIPPE_PERIMETERS_CLASSIC ? "classic" : "arachne");
    }
    return n;
}
