/* Printed bodies as (r, z) profiles: polygons of the parts, GEOS booleans.
 *
 * Arcs are cut into chords whose sagitta is at most sag = chord_mm / 2: a
 * circle of radius rho needs a step of 2 acos(1 - sag / rho); an ellipse, the
 * affine image of a circle, is stepped in its parameter as the circle of its
 * larger semi-axis (its deviation is the circle's scaled by a or b, so at most
 * max(a, b) (1 - cos(step / 2))). The axis extremes of every arc are vertices,
 * so bounding boxes come out exact. A disc of given radius and centre is always
 * cut the same way, so parts that touch along an arc (a band fused to a shell's
 * inner wall, a clip ball) share their vertices and GEOS merges them exactly. */
#include "tippe/profile.h"

#include "tippe/design.h"

#include <geos_c.h>

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Vertices closer than this merge (mm): far below print resolution, far above
 * the float32 resolution of STL coordinates at 100 mm (~1e-5 mm). */
#define MERGE_MM 1e-4
/* |r| below this is on the axis (mm): GEOS's intersection points on r = 0 can
 * carry ~1e-17 mm of roundoff. */
#define AXIS_MM 1e-9
/* GEOS overlays snap-round to this grid (mm): two parts cut from the same
 * disc polygon then share their edges exactly, where floating-point
 * intersections would leave slivers ~1e-15 mm thick that close a through hole
 * or keep touching parts apart. */
#define GRID_MM 1e-6
/* Cracks narrower than twice this are closed (mm): see close_cracks. */
#define CRACK_MM 1e-5
/* A region smaller than this is nothing (mm^2). */
#define TINY_AREA_MM2 1e-9

typedef struct {
    GEOSContextHandle_t h;
    char msg[256];
} geos_ctx;

static void geos_error_r(const char *message, void *userdata)
{
    geos_ctx *g = userdata;
    snprintf(g->msg, sizeof g->msg, "%s", message);
}

static int geos_open(geos_ctx *g)
{
    g->msg[0] = '\0';
    g->h = GEOS_init_r();
    if (!g->h)
        return 0;
    GEOSContext_setErrorMessageHandler_r(g->h, geos_error_r, g);
    return 1;
}

static void geos_close(geos_ctx *g)
{
    if (g->h)
        GEOS_finish_r(g->h);
    g->h = NULL;
}

/* ------------------------------------------------------------ arc steps */

static int arc_segments(double span_rad, double radius_mm, double sag_mm)
{
    double step = (radius_mm > sag_mm) ? 2 * acos(1 - sag_mm / radius_mm) : M_PI / 2;
    int n = (int)ceil(span_rad / step - 1e-9);
    return n < 1 ? 1 : n;
}

int tippe_profile_angle_steps(double r_max_mm, double sag_mm)
{
    int n = arc_segments(2 * M_PI, r_max_mm, sag_mm);
    n = 4 * ((n + 3) / 4);
    return n < 8 ? 8 : n;
}

/* cos and sin of k * (pi/2) / n exactly at multiples of pi/2. */
static void unit_circle(int k, int n_quarter, double *c, double *s)
{
    int q = k / n_quarter, rest = k % n_quarter;
    if (rest == 0) {
        static const double cq[4] = {1, 0, -1, 0}, sq[4] = {0, 1, 0, -1};
        *c = cq[((q % 4) + 4) % 4];
        *s = sq[((q % 4) + 4) % 4];
        return;
    }
    double a = k * (M_PI / 2) / n_quarter;
    *c = cos(a);
    *s = sin(a);
}

/* ------------------------------------------------------- GEOS polygons */

static GEOSGeometry *polygon_from(geos_ctx *g, const double *r, const double *z, int n)
{
    GEOSCoordSequence *cs = GEOSCoordSeq_create_r(g->h, (unsigned)n + 1, 2);
    if (!cs)
        return NULL;
    for (int i = 0; i <= n; i++)
        GEOSCoordSeq_setXY_r(g->h, cs, (unsigned)i, r[i % n], z[i % n]);
    GEOSGeometry *ring = GEOSGeom_createLinearRing_r(g->h, cs);
    return ring ? GEOSGeom_createPolygon_r(g->h, ring, NULL, 0) : NULL;
}

/* The half-disc r >= 0, |(r, z - z0)| <= rho. */
static GEOSGeometry *half_disc(geos_ctx *g, double rho, double z0, double sag)
{
    int nq = arc_segments(M_PI / 2, rho, sag);
    int n = 2 * nq + 1;
    double *r = malloc(2 * (size_t)n * sizeof *r);
    if (!r)
        return NULL;
    double *z = r + n;
    for (int k = 0; k < n; k++) {
        double c, s;
        unit_circle(k - nq, nq, &c, &s); /* -pi/2 .. pi/2 */
        r[k] = rho * c;
        z[k] = z0 + rho * s;
    }
    GEOSGeometry *p = polygon_from(g, r, z, n);
    free(r);
    return p;
}

/* The ellipse ((r - c)/a)^2 + ((z - z0)/b)^2 <= 1 (a <= c: it stays in r >= 0). */
static GEOSGeometry *ellipse(geos_ctx *g, double c, double a, double b, double z0, double sag)
{
    int nq = arc_segments(M_PI / 2, fmax(a, b), sag);
    int n = 4 * nq;
    double *r = malloc(2 * (size_t)n * sizeof *r);
    if (!r)
        return NULL;
    double *z = r + n;
    for (int k = 0; k < n; k++) {
        double cs, sn;
        unit_circle(k, nq, &cs, &sn);
        r[k] = fmax(0, c + a * cs);
        z[k] = z0 + b * sn;
    }
    GEOSGeometry *p = polygon_from(g, r, z, n);
    free(r);
    return p;
}

static GEOSGeometry *rect(geos_ctx *g, double r0, double r1, double z0, double z1)
{
    double r[4] = {r0, r1, r1, r0}, z[4] = {z0, z0, z1, z1};
    return polygon_from(g, r, z, 4);
}

/* a op b, consuming both; NULL on failure. */
enum { OP_UNION, OP_DIFF, OP_INTER };
static GEOSGeometry *combine(geos_ctx *g, GEOSGeometry *a, GEOSGeometry *b, int op)
{
    GEOSGeometry *out = NULL;
    if (a && b)
        out = op == OP_UNION  ? GEOSUnionPrec_r(g->h, a, b, GRID_MM)
              : op == OP_DIFF ? GEOSDifferencePrec_r(g->h, a, b, GRID_MM)
                              : GEOSIntersectionPrec_r(g->h, a, b, GRID_MM);
    if (a)
        GEOSGeom_destroy_r(g->h, a);
    if (b)
        GEOSGeom_destroy_r(g->h, b);
    return out;
}

/* The solid's region, grown by grow_mm (a hole's clearance), moved by dz. */
static GEOSGeometry *solid_region(geos_ctx *g, const tippe_design_solid *s, double grow_mm,
                                  double dz, double sag)
{
    GEOSGeometry *p = NULL;
    double z0 = s->z_mm + dz;
    if (!strcmp(s->shape, "ball")) {
        p = half_disc(g, s->radius_mm + grow_mm, z0, sag);
    } else if (!strcmp(s->shape, "shell")) {
        double inner = s->radius_mm - s->thickness_mm - grow_mm;
        p = half_disc(g, s->radius_mm + grow_mm, z0, sag);
        if (inner > 0)
            p = combine(g, p, half_disc(g, inner, z0, sag), OP_DIFF);
    } else if (!strcmp(s->shape, "cylinder") || !strcmp(s->shape, "tube")) {
        double rin = s->inner_radius_mm > 0 ? fmax(0, s->inner_radius_mm - grow_mm) : 0;
        double h = s->height_mm;
        /* A clipped solid needs no more height than its clip ball: a rectangle
         * ending exactly on the ball's poles would only add a degenerate touch. */
        if (s->clip_radius_mm > 0)
            h = fmin(h, 2 * s->clip_radius_mm + 2);
        p = rect(g, rin, s->radius_mm + grow_mm, z0 - h / 2, z0 + h / 2);
    } else {
        p = ellipse(g, s->centre_radius_mm, s->radial_semi_mm + grow_mm,
                    s->axial_semi_mm + grow_mm, z0, sag);
    }
    if (p && s->clip_radius_mm > 0) {
        GEOSGeometry *clip = half_disc(g, s->clip_radius_mm, 0, sag);
        if (s->clip_inner_mm > 0) /* clip "shell": the wall only */
            clip = combine(g, clip, half_disc(g, s->clip_inner_mm, 0, sag), OP_DIFF);
        p = combine(g, p, clip, OP_INTER);
    }
    return p;
}

/* --------------------------------------------------------- printability */

/* Filament: a printable material, or a part with a print block (which the
 * mass model prints, tippe/design.h, whether its density is a material's or
 * given inline); a void: its part's. */
static int part_is_filament(const tippe_design *d, int i, const tippe_design_part_info *p)
{
    if (p->printable)
        return 1;
    int k = i;
    if (p->cut_from) {
        for (k = 0; k < tippe_design_n_parts(d); k++) {
            tippe_design_part_info q;
            if (!tippe_design_part(d, k, &q) && !strcmp(q.name, p->cut_from))
                break;
        }
    }
    tippe_design_print_info pr;
    return !tippe_design_part_print(d, k, &pr) && pr.printed;
}

int tippe_profile_part_printed(const tippe_design *d, int i)
{
    tippe_design_part_info p;
    if (tippe_design_part(d, i, &p))
        return 0;
    return !strcmp(p.role, "fixed") && part_is_filament(d, i, &p);
}

int tippe_profile_part_filament(const tippe_design *d, int i)
{
    tippe_design_part_info p;
    return !tippe_design_part(d, i, &p) && part_is_filament(d, i, &p);
}

/* Hardware: a non-void part that is not printed (a fixed rod, the weight). */
static int part_is_hardware(const tippe_design *d, int i)
{
    tippe_design_part_info p;
    if (tippe_design_part(d, i, &p) || !strcmp(p.role, "void"))
        return 0;
    return !part_is_filament(d, i, &p);
}

/* ------------------------------------------------------- profile rings */

static double ring_area2(const tippe_profile_ring *r)
{
    double a = 0;
    for (int i = 0; i < r->n; i++) {
        const tippe_profile_point *p = &r->pt[i], *q = &r->pt[(i + 1) % r->n];
        a += p->r_mm * q->z_mm - q->r_mm * p->z_mm;
    }
    return a;
}

/* 2 pi times the first moment in r of the region left of the ring (Pappus). */
static double ring_volume(const tippe_profile_ring *r)
{
    double s = 0;
    for (int i = 0; i < r->n; i++) {
        const tippe_profile_point *p = &r->pt[i], *q = &r->pt[(i + 1) % r->n];
        s += (p->r_mm + q->r_mm) * (p->r_mm * q->z_mm - q->r_mm * p->z_mm);
    }
    return 2 * M_PI * s / 6;
}

/* Copies a GEOS ring: snapped to the axis, near-duplicate points merged,
 * oriented counter-clockwise (exterior) or clockwise (hole). */
static int ring_from(geos_ctx *g, const GEOSGeometry *lr, int exterior, tippe_profile_ring *out)
{
    const GEOSCoordSequence *cs = GEOSGeom_getCoordSeq_r(g->h, lr);
    unsigned n = 0;
    if (!cs || !GEOSCoordSeq_getSize_r(g->h, cs, &n) || n < 4)
        return 0;
    n--; /* GEOS repeats the first point */
    out->pt = malloc(n * sizeof *out->pt);
    if (!out->pt)
        return 0;
    int m = 0;
    for (unsigned i = 0; i < n; i++) {
        double r, z;
        GEOSCoordSeq_getXY_r(g->h, cs, i, &r, &z);
        if (fabs(r) < AXIS_MM)
            r = 0;
        if (m > 0 && hypot(r - out->pt[m - 1].r_mm, z - out->pt[m - 1].z_mm) < MERGE_MM) {
            if (r == 0) /* keep the point that lies on the axis */
                out->pt[m - 1] = (tippe_profile_point){r, z};
            continue;
        }
        out->pt[m++] = (tippe_profile_point){r, z};
    }
    while (m > 1 && hypot(out->pt[0].r_mm - out->pt[m - 1].r_mm,
                          out->pt[0].z_mm - out->pt[m - 1].z_mm) < MERGE_MM)
        m--;
    out->n = m;
    if (m < 3)
        return 0;
    if ((ring_area2(out) > 0) != (exterior != 0))
        for (int i = 0, j = m - 1; i < j; i++, j--) {
            tippe_profile_point t = out->pt[i];
            out->pt[i] = out->pt[j];
            out->pt[j] = t;
        }
    return 1;
}

void tippe_profile_rings_free(tippe_profile_ring *rings, int n)
{
    if (!rings)
        return;
    for (int i = 0; i < n; i++)
        free(rings[i].pt);
    free(rings);
}

/* Polygon -> body rings and their derived figures; 0 on failure. */
static int body_from_polygon(geos_ctx *g, const GEOSGeometry *poly, tippe_profile_body *b)
{
    int nh = GEOSGetNumInteriorRings_r(g->h, poly);
    if (nh < 0)
        return 0;
    b->ring = calloc((size_t)nh + 1, sizeof *b->ring);
    if (!b->ring)
        return 0;
    if (!ring_from(g, GEOSGetExteriorRing_r(g->h, poly), 1, &b->ring[0]))
        return 0;
    b->n_rings = 1;
    for (int k = 0; k < nh; k++)
        if (ring_from(g, GEOSGetInteriorRingN_r(g->h, poly, k), 0, &b->ring[b->n_rings]))
            b->n_rings++;
    b->polygon_volume_mm3 = 0;
    b->r_max_mm = 0;
    b->z_min_mm = INFINITY;
    b->z_max_mm = -INFINITY;
    for (int k = 0; k < b->n_rings; k++) {
        b->polygon_volume_mm3 += ring_volume(&b->ring[k]);
        for (int i = 0; i < b->ring[k].n; i++) {
            b->r_max_mm = fmax(b->r_max_mm, b->ring[k].pt[i].r_mm);
            b->z_min_mm = fmin(b->z_min_mm, b->ring[k].pt[i].z_mm);
            b->z_max_mm = fmax(b->z_max_mm, b->ring[k].pt[i].z_mm);
        }
    }
    return 1;
}

/* ------------------------------------------------------------- bodies */

static void warn(tippe_profile_set *s, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void warn(tippe_profile_set *s, const char *fmt, ...)
{
    if (s->n_warnings >= TIPPE_PROFILE_MAX_WARNINGS)
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(s->warning[s->n_warnings++], sizeof s->warning[0], fmt, ap);
    va_end(ap);
}

/* Unit-density volume of a solid cut to the ball of radius clip_mm (0: not
 * cut), in mm^3, from the geometry module's closed forms. */
static double clipped_volume_mm3(const tippe_design_solid *s, double grow_mm, double clip_mm)
{
    const double mm = 1e-3;
    double clip = clip_mm * mm;
    tippe_moments m;
    if (!strcmp(s->shape, "ball"))
        m = tippe_ball((s->radius_mm + grow_mm) * mm, 0);
    else if (!strcmp(s->shape, "shell"))
        m = tippe_shell((s->radius_mm + grow_mm) * mm, (s->thickness_mm + 2 * grow_mm) * mm, 0);
    else if (!strcmp(s->shape, "cylinder") || !strcmp(s->shape, "tube"))
        m = tippe_tube(s->inner_radius_mm > 0 ? fmax(0, s->inner_radius_mm - grow_mm) * mm : 0,
                       (s->radius_mm + grow_mm) * mm, s->height_mm * mm, s->z_mm * mm, clip);
    else
        m = tippe_torus(s->centre_radius_mm * mm, (s->radial_semi_mm + grow_mm) * mm,
                        (s->axial_semi_mm + grow_mm) * mm, s->z_mm * mm, clip);
    return m.m * 1e9;
}

/* The same, with the solid's own clip (a shell clip: the outer ball less the inner). */
static double solid_volume_mm3(const tippe_design_solid *s, double grow_mm)
{
    double v = clipped_volume_mm3(s, grow_mm, s->clip_radius_mm);
    if (s->clip_inner_mm > 0)
        v -= clipped_volume_mm3(s, grow_mm, s->clip_inner_mm);
    return v;
}

/* Region a hardware part occupies over the travel (a moving one at nine
 * places from end to end), or NULL if none. */
static GEOSGeometry *hardware_region(geos_ctx *g, const tippe_design *d, double sag)
{
    double t0, t1;
    tippe_design_travel_mm(d, &t0, &t1);
    GEOSGeometry *all = NULL;
    for (int i = 0; i < tippe_design_n_parts(d); i++) {
        tippe_design_solid s;
        if (!part_is_hardware(d, i) || tippe_design_part_solid(d, i, &s))
            continue;
        int n_at = s.moving ? 9 : 1;
        for (int k = 0; k < n_at; k++) {
            double dz = s.moving ? t0 + (t1 - t0) * k / (n_at - 1) : 0;
            GEOSGeometry *p = solid_region(g, &s, 0, dz, sag);
            all = all ? combine(g, all, p, OP_UNION) : p;
        }
    }
    return all;
}

/* Marks the voids (of printed parts) that hardware enters. */
static int mark_clearance(geos_ctx *g, const tippe_design *d, double sag, int *grown)
{
    GEOSGeometry *hw = hardware_region(g, d, sag);
    if (!hw)
        return 1;
    for (int i = 0; i < tippe_design_n_parts(d); i++) {
        tippe_design_solid s;
        if (tippe_design_part_solid(d, i, &s) || !s.is_void ||
            !tippe_profile_part_printed(d, s.parent))
            continue;
        GEOSGeometry *v = solid_region(g, &s, 0, 0, sag);
        GEOSGeometry *x = v ? GEOSIntersectionPrec_r(g->h, v, hw, GRID_MM) : NULL;
        double area = 0;
        if (x)
            GEOSArea_r(g->h, x, &area);
        grown[i] = area > TINY_AREA_MM2;
        if (x)
            GEOSGeom_destroy_r(g->h, x);
        if (v)
            GEOSGeom_destroy_r(g->h, v);
    }
    GEOSGeom_destroy_r(g->h, hw);
    return 1;
}

static int mirror_r(double *x, double *y, void *unused)
{
    (void)y;
    (void)unused;
    *x = -*x;
    return 1;
}

/* Morphological opening of the body mirrored across the axis (so that a rod
 * on the axis counts its full diameter): what it loses are walls thinner than
 * min_wall. Corner residues are no wider than min_wall/2 in any direction, so
 * only a lost piece longer than 2 min_wall counts. Returns the estimated
 * thickness of the thinnest such wall (twice the area over the length), or NAN. */
static double thin_wall_mm(geos_ctx *g, const GEOSGeometry *body, double min_wall)
{
    GEOSGeometry *mirror = GEOSGeom_transformXY_r(g->h, body, mirror_r, NULL);
    GEOSGeometry *whole = mirror ? combine(g, GEOSGeom_clone_r(g->h, body), mirror, OP_UNION) : NULL;
    if (!whole)
        return NAN;
    GEOSGeometry *in = GEOSBuffer_r(g->h, whole, -min_wall / 2, 16);
    /* grown by 1 um more, so that the buffer's own roundoff leaves no slivers */
    GEOSGeometry *open = in ? GEOSBuffer_r(g->h, in, min_wall / 2 + 1e-3, 16) : NULL;
    GEOSGeometry *lost = open ? GEOSDifferencePrec_r(g->h, whole, open, GRID_MM) : NULL;
    double worst = NAN;
    int n = lost ? GEOSGetNumGeometries_r(g->h, lost) : 0;
    for (int k = 0; k < n; k++) {
        const GEOSGeometry *piece = GEOSGetGeometryN_r(g->h, lost, k);
        double area = 0, length = 0;
        GEOSArea_r(g->h, piece, &area);
        GEOSLength_r(g->h, piece, &length); /* perimeter ~ 2 x the wall's length */
        if (length / 2 > 2 * min_wall && area > 0) {
            double t = area / (length / 2);
            if (isnan(worst) || t < worst)
                worst = t;
        }
    }
    GEOSGeometry *tmp[4] = {whole, in, open, lost};
    for (int k = 0; k < 4; k++)
        if (tmp[k])
            GEOSGeom_destroy_r(g->h, tmp[k]);
    return worst;
}

static int shift_z(double *x, double *y, void *dz)
{
    (void)x;
    *y += *(const double *)dz;
    return 1;
}

/* Whether the region p, slid along the axis by +-travel (the only way a part
 * of revolution goes in), runs into the printed body both ways. The swept
 * region is the convex hull of p and its shifted copy: exact for the convex
 * (r, z) outlines of rods and weights, larger for others (a warning too many,
 * never one too few). */
static int trapped(geos_ctx *g, const GEOSGeometry *p, const GEOSGeometry *printed,
                   double travel)
{
    int blocked = 0;
    for (int dir = -1; dir <= 1; dir += 2) {
        double dz = dir * travel;
        GEOSGeometry *moved = GEOSGeom_transformXY_r(g->h, p, shift_z, &dz);
        GEOSGeometry *both = moved ? combine(g, GEOSGeom_clone_r(g->h, p), moved, OP_UNION) : NULL;
        GEOSGeometry *sweep = both ? GEOSConvexHull_r(g->h, both) : NULL;
        GEOSGeometry *hit = sweep ? GEOSIntersectionPrec_r(g->h, sweep, printed, GRID_MM) : NULL;
        double area = 0;
        if (hit)
            GEOSArea_r(g->h, hit, &area);
        blocked += area > TINY_AREA_MM2;
        GEOSGeometry *tmp[3] = {both, sweep, hit};
        for (int k = 0; k < 3; k++)
            if (tmp[k])
                GEOSGeom_destroy_r(g->h, tmp[k]);
    }
    return blocked == 2;
}

/* The first hardware part that cannot be slid in along the axis from either
 * end (a rod or weight inside a closed shell), or -1. A hole printed for its
 * thread (fit_diameter_mm > 0: a tap drill, narrower than the screw) takes the
 * moving screw by being tapped, so the screw is tried at the hole's size. */
static int hardware_enclosed(geos_ctx *g, const tippe_design *d, const GEOSGeometry *printed,
                             double sag, double fit_diameter_mm)
{
    double R = tippe_design_radius_mm(d), t0, t1;
    tippe_design_travel_mm(d, &t0, &t1);
    for (int i = 0; i < tippe_design_n_parts(d); i++) {
        tippe_design_solid s;
        if (!part_is_hardware(d, i) || tippe_design_part_solid(d, i, &s))
            continue;
        if (fit_diameter_mm > 0 && s.moving && !strcmp(s.shape, "cylinder") &&
            s.inner_radius_mm == 0)
            s.radius_mm = fmin(s.radius_mm, 0.5 * fit_diameter_mm - 1e-3);
        GEOSGeometry *p = solid_region(g, &s, 0, s.moving ? 0.5 * (t0 + t1) : 0, sag);
        int stuck = p && trapped(g, p, printed, 4 * R);
        if (p)
            GEOSGeom_destroy_r(g->h, p);
        if (stuck)
            return i;
    }
    return -1;
}

static int fail(geos_ctx *g, tippe_error *err, const tippe_design *d, const char *what)
{
    return tippe_error_set(err, TIPPE_ECOMPUTE, "%s: %s failed%s%s", tippe_design_path(d), what,
                           g->msg[0] ? ": " : "", g->msg);
}

/* Names the body after the printed parts whose region it meets. */
static void name_body(geos_ctx *g, const tippe_design *d, const GEOSGeometry *poly,
                      GEOSGeometry *const *part_geom, tippe_profile_body *b)
{
    b->name[0] = b->material[0] = '\0';
    size_t used = 0;
    for (int i = 0; i < tippe_design_n_parts(d); i++) {
        if (!part_geom[i] || GEOSIntersects_r(g->h, poly, part_geom[i]) != 1)
            continue;
        tippe_design_part_info p;
        tippe_design_part(d, i, &p);
        int w = snprintf(b->name + used, sizeof b->name - used, "%s%s", used ? "+" : "", p.name);
        if (w > 0 && (size_t)w < sizeof b->name - used)
            used += (size_t)w;
        if (!b->material[0])
            snprintf(b->material, sizeof b->material, "%s", p.material);
        else if (strcmp(b->material, p.material) && !strstr(b->material, "mixed"))
            snprintf(b->material, sizeof b->material, "mixed");
    }
    if (!used)
        snprintf(b->name, sizeof b->name, "body");
}

static int add_bodies(geos_ctx *g, const tippe_design *d, const GEOSGeometry *region,
                      GEOSGeometry *const *part_geom, double exact_mm3, const char *suffix,
                      int flip, double cut_z, tippe_profile_set *s, tippe_error *err)
{
    int n = GEOSGetNumGeometries_r(g->h, region);
    int first = s->n_bodies;
    for (int k = 0; k < n; k++) {
        const GEOSGeometry *poly = GEOSGetGeometryN_r(g->h, region, k);
        double area = 0;
        if (GEOSGeomTypeId_r(g->h, poly) != GEOS_POLYGON || !GEOSArea_r(g->h, poly, &area) ||
            area < TINY_AREA_MM2)
            continue;
        tippe_profile_body *nb = realloc(s->body, (size_t)(s->n_bodies + 1) * sizeof *nb);
        if (!nb)
            return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
        s->body = nb;
        tippe_profile_body *b = &s->body[s->n_bodies];
        memset(b, 0, sizeof *b);
        s->n_bodies++;
        if (!body_from_polygon(g, poly, b))
            return fail(g, err, d, "reading a profile polygon");
        name_body(g, d, poly, part_geom, b);
        if (suffix[0]) {
            size_t len = strlen(b->name);
            snprintf(b->name + len, sizeof b->name - len, "-%s", suffix);
        }
        b->flip = flip;
        b->cut_z_mm = cut_z;
        b->exact_volume_mm3 = NAN;
    }
    int made = s->n_bodies - first;
    if (made == 1)
        s->body[first].exact_volume_mm3 = exact_mm3;
    else if (made > 1)
        warn(s, "%s: the printed region%s%s falls apart into %d separate pieces; each is "
                "written as its own body",
             tippe_design_path(d), suffix[0] ? " " : "", suffix, made);
    return TIPPE_OK;
}

static int check_options(const tippe_design *d, const tippe_profile_options *o, tippe_error *err)
{
    double R = tippe_design_radius_mm(d);
    if (!(o->chord_mm >= 1e-3 && o->chord_mm <= 1))
        return tippe_error_set(err, TIPPE_EINPUT, "chord tolerance %g mm is outside 0.001 .. 1 mm",
                               o->chord_mm);
    if (!(o->clearance_mm >= 0 && o->clearance_mm <= 2))
        return tippe_error_set(err, TIPPE_EINPUT, "clearance %g mm is outside 0 .. 2 mm",
                               o->clearance_mm);
    if (!(o->min_wall_mm >= 0 && o->min_wall_mm <= 10))
        return tippe_error_set(err, TIPPE_EINPUT, "minimum wall %g mm is outside 0 .. 10 mm",
                               o->min_wall_mm);
    if (o->fit_diameter_mm > 0 && !(o->fit_diameter_mm < 2 * R))
        return tippe_error_set(err, TIPPE_EINPUT, "a hole printed %g mm across does not fit the "
                               "sphere", o->fit_diameter_mm);
    if (o->split && !(fabs(o->split_z_mm) < R))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "split plane z = %g mm is outside the sphere (|z| < %g mm)",
                               o->split_z_mm, R);
    return TIPPE_OK;
}

/* The sockets (tippe_profile_options.sockets) cut from *printed, their
 * volumes taken from *vol: a pocket {r <= a, cavity surface <= |z| <= floor}
 * keeps pi a^2 floor - (2 pi / 3) (Rc^3 - (Rc^2 - a^2)^(3/2)) of wall (the
 * cavity's spherical cap under the pocket's floor, by the shell method). */
static int cut_sockets(geos_ctx *g, const tippe_design *d, const tippe_profile_options *o,
                       tippe_profile_set *s, GEOSGeometry **printed, double *vol)
{
    double R = tippe_design_radius_mm(d), depth = TIPPE_PROFILE_SOCKET_DEPTH_MM;
    for (int i = 0; i < tippe_design_n_parts(d); i++) {
        tippe_design_solid sd;
        if (!part_is_hardware(d, i) || tippe_design_part_solid(d, i, &sd) || sd.moving ||
            strcmp(sd.shape, "cylinder") || sd.inner_radius_mm > 0 || !(sd.clip_radius_mm > 0) ||
            sd.clip_radius_mm > R - 1e-9 || sd.clip_inner_mm > 0)
            continue;
        double Rc = sd.clip_radius_mm, r = sd.radius_mm, a = r + o->clearance_mm;
        if (a >= Rc)
            continue;
        double cap = sqrt(Rc * Rc - r * r), rim = sqrt(Rc * Rc - a * a), floor_z = rim + depth;
        double wall = sqrt(R * R - a * a) - floor_z;
        for (int e = 1; e >= -1; e -= 2) {
            double end = sd.z_mm + e * sd.height_mm / 2;
            if (e * end < cap - 1e-6 || s->n_sockets >= 2)
                continue; /* the rod does not reach this pole */
            if (floor_z < Rc || wall < o->min_wall_mm) {
                tippe_design_part_info p;
                tippe_design_part(d, i, &p);
                warn(s, "%s: no socket for rod '%s' at the %s pole: the wall there is too thin "
                        "(%.2f mm would be left under a %.1f mm deep pocket)",
                     tippe_design_path(d), p.name, e > 0 ? "+z" : "-z", wall,
                     depth);
                continue;
            }
            GEOSGeometry *pocket = e > 0 ? rect(g, 0, a, rim - 1, floor_z)
                                         : rect(g, 0, a, -floor_z, -rim + 1);
            *printed = pocket ? combine(g, *printed, pocket, OP_DIFF) : NULL;
            if (!*printed)
                return 0;
            double v = M_PI * a * a * floor_z -
                       2 * M_PI / 3 * (Rc * Rc * Rc - pow(Rc * Rc - a * a, 1.5));
            *vol -= v;
            int k = s->n_sockets++;
            s->socket_part[k] = i;
            s->socket_r_mm[k] = a;
            s->socket_rim_z_mm[k] = e * rim;
            s->socket_floor_z_mm[k] = e * floor_z;
            s->socket_volume_mm3[k] = v;
        }
    }
    return 1;
}

/* Closes cracks narrower than 2 CRACK_MM in region (consumed): a dilation by
 * CRACK_MM and an erosion by as much (mitred joins, so corners come back where
 * they were), then r >= 0 again on the grid. Where a clipped part (a band cut
 * to the cavity) meets the part it is fused to along a shared chord, the point
 * where its clip crosses that chord is rounded to the grid off the chord, and
 * the snap-rounded union may leave the two walls 1e-6 mm apart along a whole
 * chord: a crack 0.5 mm deep into the body whose two facing walls the mesh
 * keeps, far outside the chord tolerance from the true (fused) surface. */
static GEOSGeometry *close_cracks(geos_ctx *g, GEOSGeometry *region, double R)
{
    if (!region)
        return NULL;
    GEOSGeometry *grown =
        GEOSBufferWithStyle_r(g->h, region, CRACK_MM, 1, GEOSBUF_CAP_FLAT, GEOSBUF_JOIN_MITRE, 1e3);
    GEOSGeom_destroy_r(g->h, region);
    GEOSGeometry *back = grown ? GEOSBufferWithStyle_r(g->h, grown, -CRACK_MM, 1, GEOSBUF_CAP_FLAT,
                                                       GEOSBUF_JOIN_MITRE, 1e3)
                               : NULL;
    if (grown)
        GEOSGeom_destroy_r(g->h, grown);
    return combine(g, back, rect(g, 0, 3 * R, -3 * R, 3 * R), OP_INTER);
}

/* The printed parts' union less the voids: *printed, with each printed part's
 * own region in part_geom (for naming) and the exact volume of the whole. */
static int printed_region(geos_ctx *g, const tippe_design *d, const tippe_profile_options *o,
                          tippe_profile_set *s, GEOSGeometry **part_geom, GEOSGeometry **printed,
                          double *exact_mm3, tippe_error *err)
{
    const double sag = o->chord_mm / 2;
    int n = tippe_design_n_parts(d);
    GEOSGeometry *solid = NULL, *holes = NULL;
    double vol = 0;
    for (int i = 0; i < n; i++) {
        tippe_design_solid sd;
        tippe_design_part_solid(d, i, &sd);
        int cut = sd.is_void && tippe_profile_part_printed(d, sd.parent);
        if (!cut && !tippe_profile_part_printed(d, i))
            continue;
        double grow = s->clearance_applied[i] ? o->clearance_mm : 0;
        if (o->fit_diameter_mm > 0 && i == o->fit_part && s->clearance_applied[i])
            grow = o->fit_diameter_mm / 2 - sd.radius_mm; /* printed for its thread */
        GEOSGeometry *p = solid_region(g, &sd, grow, 0, sag);
        if (!p) {
            if (solid)
                GEOSGeom_destroy_r(g->h, solid);
            if (holes)
                GEOSGeom_destroy_r(g->h, holes);
            return fail(g, err, d, "building a part's profile");
        }
        if (cut) {
            vol -= solid_volume_mm3(&sd, grow);
            holes = holes ? combine(g, holes, p, OP_UNION) : p;
        } else {
            vol += solid_volume_mm3(&sd, 0);
            part_geom[i] = GEOSGeom_clone_r(g->h, p);
            solid = solid ? combine(g, solid, p, OP_UNION) : p;
        }
    }
    if (!solid) {
        if (holes)
            GEOSGeom_destroy_r(g->h, holes);
        return tippe_error_set(err, TIPPE_EINPUT,
                               "%s: parts: nothing to print: no fixed part is of a printable "
                               "material or has a print block (all are hardware or moving)",
                               tippe_design_path(d));
    }
    *printed = close_cracks(g, holes ? combine(g, solid, holes, OP_DIFF) : solid,
                            tippe_design_radius_mm(d));
    if (!*printed)
        return fail(g, err, d, "cutting the voids from the printed parts");
    if (o->sockets && !cut_sockets(g, d, o, s, printed, &vol))
        return fail(g, err, d, "cutting the rod's sockets");
    double area = 0;
    GEOSArea_r(g->h, *printed, &area);
    if (area < TINY_AREA_MM2)
        return tippe_error_set(err, TIPPE_EINPUT,
                               "%s: parts: the voids leave nothing of the printed parts: "
                               "there is no solid to print",
                               tippe_design_path(d));
    *exact_mm3 = vol;
    return TIPPE_OK;
}

/* The joint of split halves (o->joint): where the printed region crosses the
 * cut plane, each stretch of wall [ra, rb] at least 2 TIPPE_PROFILE_JOINT_MIN_MM
 * wide gets a groove of its inner half, TIPPE_PROFILE_JOINT_DEPTH_MM deep, in
 * both halves, and a separate printed ring fills the two grooves with
 * clearance_mm of play (radial on its outer side, and in its height), so that
 * the halves align on it. Both halves keep their flat cut face for printing;
 * the ring prints flat too. Grooves reach 0.5 mm (at most half the gap to the
 * next stretch) beyond the wall's inner edge, so that a curved inner surface
 * leaves no sliver. The halves then hold a little less than the whole (the
 * play): the mass model keeps the design's solid. */
static int joint(geos_ctx *g, const tippe_design *d, const tippe_profile_options *o,
                 const GEOSGeometry *printed, GEOSGeometry **lo, GEOSGeometry **hi,
                 GEOSGeometry **ring, tippe_profile_set *s, tippe_error *err)
{
    double R = tippe_design_radius_mm(d), zc = o->split_z_mm, h = TIPPE_PROFILE_JOINT_DEPTH_MM;
    double c = o->clearance_mm;
    GEOSGeometry *cross = combine(g, GEOSGeom_clone_r(g->h, printed),
                                  rect(g, 0, 3 * R, zc - 1e-4, zc + 1e-4), OP_INTER);
    if (!cross)
        return fail(g, err, d, "finding the wall at the cut plane");
    int n = GEOSGetNumGeometries_r(g->h, cross), made = 0, thin = 0;
    double prev_rb = 0;
    /* stretches in order of r (GEOS gives the pieces of an intersection unordered) */
    double ra_list[64], rb_list[64];
    int m = 0;
    for (int k = 0; k < n && m < 64; k++) {
        const GEOSGeometry *piece = GEOSGetGeometryN_r(g->h, cross, k);
        double a = 0, b = 0;
        if (GEOSGeom_getXMin_r(g->h, piece, &a) && GEOSGeom_getXMax_r(g->h, piece, &b) && b > a) {
            int j = m++;
            while (j > 0 && ra_list[j - 1] > a) {
                ra_list[j] = ra_list[j - 1];
                rb_list[j] = rb_list[j - 1];
                j--;
            }
            ra_list[j] = a;
            rb_list[j] = b;
        }
    }
    GEOSGeom_destroy_r(g->h, cross);
    for (int k = 0; k < m && *lo && *hi; k++) {
        double ra = ra_list[k], rb = rb_list[k], mid = 0.5 * (ra + rb);
        if (rb - ra < 2 * TIPPE_PROFILE_JOINT_MIN_MM + c) {
            thin = 1;
            prev_rb = rb;
            continue;
        }
        double r_in = fmax(ra - fmin(0.5, 0.5 * (ra - prev_rb)), 0);
        if (ra < 1e-9)
            r_in = 0; /* a wall that reaches the axis: the ring is a disc */
        if (s->n_grooves < 8) {
            s->groove_r_in_mm[s->n_grooves] = r_in;
            s->groove_r_wall_mm[s->n_grooves] = ra;
            s->groove_r_mid_mm[s->n_grooves++] = mid;
        }
        *lo = combine(g, *lo, rect(g, r_in, mid, zc - h, zc), OP_DIFF);
        *hi = combine(g, *hi, rect(g, r_in, mid, zc, zc + h), OP_DIFF);
        GEOSGeometry *r = rect(g, ra, mid - c, 0, 2 * h - c);
        *ring = *ring ? combine(g, *ring, r, OP_UNION) : r;
        made++;
        prev_rb = rb;
    }
    if (thin)
        warn(s, "%s: a wall at the cut plane is narrower than %.1f mm: no joint ring there",
             tippe_design_path(d), 2 * TIPPE_PROFILE_JOINT_MIN_MM + c);
    if (!made)
        warn(s, "%s: no wall at the cut plane is wide enough for a joint ring: the halves "
                "are written without one",
             tippe_design_path(d));
    return TIPPE_OK;
}

int tippe_profile_build(const tippe_design *d, const tippe_profile_options *o,
                        tippe_profile_set *s, tippe_error *err)
{
    memset(s, 0, sizeof *s);
    s->thinnest_wall_mm = NAN;
    int rc = check_options(d, o, err);
    if (rc)
        return rc;
    int n = tippe_design_n_parts(d);
    s->n_parts = n;
    s->clearance_applied = calloc((size_t)n, sizeof *s->clearance_applied);
    GEOSGeometry **part_geom = calloc((size_t)n, sizeof *part_geom);
    geos_ctx g;
    if (!s->clearance_applied || !part_geom || !geos_open(&g)) {
        free(part_geom);
        return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    }
    GEOSGeometry *printed = NULL;
    double exact = 0;
    mark_clearance(&g, d, o->chord_mm / 2, s->clearance_applied);
    rc = printed_region(&g, d, o, s, part_geom, &printed, &exact, err);
    if (!rc) {
        s->thinnest_wall_mm = thin_wall_mm(&g, printed, o->min_wall_mm);
        if (!isnan(s->thinnest_wall_mm))
            warn(s, "%s: a printed wall is about %.2f mm thick, thinner than %.2f mm (two "
                    "perimeters): the slicer may drop or weaken it",
                 tippe_design_path(d), s->thinnest_wall_mm, o->min_wall_mm);
        int stuck = o->split ? -1 : hardware_enclosed(&g, d, printed, o->chord_mm / 2,
                                                        o->fit_diameter_mm);
        if (stuck >= 0) {
            tippe_design_part_info p;
            tippe_design_part(d, stuck, &p);
            warn(s, "%s: part '%s' cannot be slid into the printed body along the axis from "
                    "either end: print the body in two halves (--split) to fit it",
                 tippe_design_path(d), p.name);
        }
    }
    if (!rc && !o->split) {
        rc = add_bodies(&g, d, printed, part_geom, exact, "", 0, NAN, s, err);
    } else if (!rc) {
        double R = tippe_design_radius_mm(d), zc = o->split_z_mm;
        GEOSGeometry *lo = combine(&g, GEOSGeom_clone_r(g.h, printed),
                                   rect(&g, 0, 3 * R, -3 * R, zc), OP_INTER);
        GEOSGeometry *hi = combine(&g, GEOSGeom_clone_r(g.h, printed),
                                   rect(&g, 0, 3 * R, zc, 3 * R), OP_INTER);
        if (!lo || !hi)
            rc = fail(&g, err, d, "cutting at the split plane");
        GEOSGeometry *ring = NULL;
        if (!rc && o->joint && (rc = joint(&g, d, o, printed, &lo, &hi, &ring, s, err)) == 0 &&
            (!lo || !hi))
            rc = fail(&g, err, d, "cutting the joint's groove");
        if (!rc)
            rc = add_bodies(&g, d, lo, part_geom, NAN, "lower", 1, zc, s, err);
        if (!rc)
            rc = add_bodies(&g, d, hi, part_geom, NAN, "upper", 0, zc, s, err);
        if (!rc && ring) {
            int first = s->n_bodies;
            rc = add_bodies(&g, d, ring, part_geom, NAN, "", 0, NAN, s, err);
            for (int b = first; !rc && b < s->n_bodies; b++) {
                snprintf(s->body[b].name, sizeof s->body[b].name, "joint-ring%s",
                         s->n_bodies - first > 1 ? "s" : "");
                if (s->n_bodies - first > 1)
                    snprintf(s->body[b].name + strlen(s->body[b].name),
                             sizeof s->body[b].name - strlen(s->body[b].name), "-%d", b - first + 1);
            }
        }
        if (ring)
            GEOSGeom_destroy_r(g.h, ring);
        if (lo)
            GEOSGeom_destroy_r(g.h, lo);
        if (hi)
            GEOSGeom_destroy_r(g.h, hi);
    }
    if (!rc && s->n_bodies == 0)
        rc = tippe_error_set(err, TIPPE_EINPUT, "%s: nothing is left to print",
                             tippe_design_path(d));
    if (printed)
        GEOSGeom_destroy_r(g.h, printed);
    for (int i = 0; i < n; i++)
        if (part_geom[i])
            GEOSGeom_destroy_r(g.h, part_geom[i]);
    free(part_geom);
    geos_close(&g);
    if (rc)
        tippe_profile_set_free(s);
    return rc;
}

int tippe_profile_part_outline(const tippe_design *d, int i, double dz_mm, double chord_mm,
                               tippe_profile_ring **rings)
{
    *rings = NULL;
    tippe_design_solid sd;
    if (tippe_design_part_solid(d, i, &sd))
        return -1;
    geos_ctx g;
    if (!geos_open(&g))
        return -1;
    GEOSGeometry *p = solid_region(&g, &sd, 0, dz_mm, chord_mm / 2);
    int count = -1;
    if (p) {
        int np = GEOSGetNumGeometries_r(g.h, p), total = 0;
        for (int k = 0; k < np; k++)
            total += 1 + GEOSGetNumInteriorRings_r(g.h, GEOSGetGeometryN_r(g.h, p, k));
        *rings = calloc((size_t)total + 1, sizeof **rings);
        count = *rings ? 0 : -1;
        for (int k = 0; *rings && k < np; k++) {
            const GEOSGeometry *poly = GEOSGetGeometryN_r(g.h, p, k);
            if (GEOSGeomTypeId_r(g.h, poly) != GEOS_POLYGON)
                continue;
            if (ring_from(&g, GEOSGetExteriorRing_r(g.h, poly), 1, &(*rings)[count]))
                count++;
            for (int h = 0; h < GEOSGetNumInteriorRings_r(g.h, poly); h++)
                if (ring_from(&g, GEOSGetInteriorRingN_r(g.h, poly, h), 0, &(*rings)[count]))
                    count++;
        }
        GEOSGeom_destroy_r(g.h, p);
    }
    geos_close(&g);
    return count;
}

void tippe_profile_set_free(tippe_profile_set *s)
{
    if (!s)
        return;
    for (int b = 0; b < s->n_bodies; b++) {
        for (int k = 0; k < s->body[b].n_rings; k++)
            free(s->body[b].ring[k].pt);
        free(s->body[b].ring);
    }
    free(s->body);
    free(s->clearance_applied);
    memset(s, 0, sizeof *s);
}
