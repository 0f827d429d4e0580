/* print.c: the sparse core of a printed part under the continuous rule (the
 * print block's "model": "skins"; the default is the slicer's rules,
 * print_slicer.c; see include/tippe/print.h).
 *
 * Notation: P is the printed part (the part minus its voids) in the (r, z)
 * half-plane; w is the wall thickness, t the skin thickness. A point is in
 * the core when its horizontal segment [r - w, r + w] lies in the layer's
 * cross-section (mirrored through the axis: a full disc has no boundary at
 * r = 0) and its vertical segment [z - t, z + t] lies in P. At height z:
 *   H(z) = the layer's annuli, each shrunk by w at its bounding circles;
 *   V(z) = the radii whose vertical segment lies in P
 *        = (intersection over z' in [z - t, z + t] of the part's annulus)
 *          minus (union over the same z' of each void's annulus);
 *   core(z) = H(z) intersected with V(z).
 * Every bound is a value of one of the solids' radius functions at z, z - t,
 * z + t or a fixed height; each value carries a tag saying which, and the
 * list of tags along core(z) (its "signature") changes exactly where the
 * integrand stops being one smooth expression. */
#include "print/section.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#define MAX_VOIDS 48
/* Annuli per height: one per solid piece plus one per void cut. */
#define MAX_IV (4 + 4 * MAX_VOIDS)
#define N_SAMPLES 2048
/* Break heights are located to this fraction of the part's height: the
 * integrand is bounded, so a break misplaced by it costs ~1e-14 relative. */
#define BREAK_TOL 1e-14
#define QAGS_LIMIT 200
#define EPS_REL 1e-12
/* The accuracy below which a QAGS failure is an error (relative to the part). */
#define ACCEPT_REL 1e-10

/* Radius functions a bound can come from (the fn part of a tag). */
enum { FN_INNER, FN_AXIS, FN_CLIP_INNER, FN_OUTER, FN_CLIP_OUTER, N_FN };
/* Where the function was evaluated (the point part of a tag). */
enum { AT_Z, AT_BELOW, AT_ABOVE, AT_FIXED_CENTRE, AT_FIXED_ORIGIN, AT_FIXED_END, N_AT };
#define TAG(solid, fn, at) (((solid) * N_FN + (fn)) * N_AT + (at))
#define TAG_AXIS (-1)

typedef struct {
    double lo, hi;
    int tlo, thi;
} tiv;

typedef struct {
    int n;
    tiv iv[MAX_IV];
} tivset;

typedef struct {
    const tippe_solid *part;
    const tippe_solid *voids;
    int n_voids;
    double w, t;
} core_model;

/* ------------------------------------------------------------ one solid */

/* sqrt(a^2 - x^2) in factored form (no cancellation near the pole). */
static double chord(double a, double x) { return sqrt((a - x) * (a + x)); }

/* The solid's annulus at height z: [lo, hi] and the functions giving each end.
 * Returns 0 when the cross-section is empty. */
static int section(const tippe_solid *s, double z, double *lo, int *flo, double *hi, int *fhi)
{
    double dz = z - s->z_centre;
    *flo = FN_AXIS;
    *lo = 0;
    *fhi = FN_OUTER;
    switch (s->kind) {
    case TIPPE_SOLID_BALL:
    case TIPPE_SOLID_SHELL:
        if (!(fabs(dz) < s->radius))
            return 0;
        *hi = chord(s->radius, dz);
        if (s->kind == TIPPE_SOLID_SHELL && fabs(dz) < s->inner_radius) {
            *lo = chord(s->inner_radius, dz);
            *flo = FN_INNER;
        }
        break;
    case TIPPE_SOLID_TUBE:
        if (!(fabs(dz) <= 0.5 * s->height))
            return 0;
        *hi = s->radius;
        if (s->inner_radius > 0) {
            *lo = s->inner_radius;
            *flo = FN_INNER;
        }
        break;
    case TIPPE_SOLID_TORUS:
    default: {
        double y = dz / s->axial_semi;
        if (!(fabs(y) < 1))
            return 0;
        double pw = s->radial_semi * sqrt((1 - y) * (1 + y));
        *hi = s->centre_radius + pw;
        if (s->centre_radius - pw > 0) {
            *lo = s->centre_radius - pw;
            *flo = FN_INNER;
        }
        break;
    }
    }
    if (s->clip_outer > 0) {
        if (!(fabs(z) < s->clip_outer))
            return 0;
        double h = chord(s->clip_outer, z);
        if (h < *hi) {
            *hi = h;
            *fhi = FN_CLIP_OUTER;
        }
    }
    if (s->clip_inner > 0 && fabs(z) < s->clip_inner) {
        double h = chord(s->clip_inner, z);
        if (h > *lo) {
            *lo = h;
            *flo = FN_CLIP_INNER;
        }
    }
    return *lo < *hi;
}

/* Heights where the solid's cross-section is non-empty: up to two intervals
 * (a tube cut to a shell's wall meets the wall at both poles). */
static int support(const tippe_solid *s, double z0[2], double z1[2])
{
    double a, b;
    switch (s->kind) {
    case TIPPE_SOLID_BALL:
    case TIPPE_SOLID_SHELL:
        a = s->z_centre - s->radius;
        b = s->z_centre + s->radius;
        break;
    case TIPPE_SOLID_TUBE:
        a = s->z_centre - 0.5 * s->height;
        b = s->z_centre + 0.5 * s->height;
        break;
    case TIPPE_SOLID_TORUS:
    default:
        a = s->z_centre - s->axial_semi;
        b = s->z_centre + s->axial_semi;
        break;
    }
    if (s->clip_outer > 0) {
        /* a tube's inner wall meets the clip ball below its pole */
        double reach = s->kind == TIPPE_SOLID_TUBE && s->inner_radius > 0
                           ? chord(s->clip_outer, fmin(s->inner_radius, s->clip_outer))
                           : s->clip_outer;
        a = fmax(a, -reach);
        b = fmin(b, reach);
    }
    if (!(a < b))
        return 0;
    /* A tube cut to a shell's wall is empty where the inner clip ball covers
     * it: |z| < sqrt(ci^2 - ro^2). */
    if (s->kind == TIPPE_SOLID_TUBE && s->clip_inner > s->radius) {
        double gap = chord(s->clip_inner, s->radius);
        int n = 0;
        if (a < -gap) {
            z0[n] = a;
            z1[n++] = fmin(b, -gap);
        }
        if (b > gap) {
            z0[n] = fmax(a, gap);
            z1[n++] = b;
        }
        return n;
    }
    z0[0] = a;
    z1[0] = b;
    return 1;
}

/* Heights at which a radius function of s can have its extreme over a range:
 * its own centre and the clip balls' centre (the origin). */
static void centres(const tippe_solid *s, double c[2])
{
    c[0] = s->z_centre;
    c[1] = 0.0;
}

/* The extremes over z' in [u, v] (u <= v) of s's annulus, with tags:
 * intersect = 1: [max lo, min hi] (the radii inside s at every z');
 * intersect = 0: [min lo, max hi] over the z' where s is non-empty (its
 * annuli's union, connected when [u, v] is inside one support interval).
 * Each radius function is monotone either side of one of the centres, so
 * the extremes are at u, v or a centre inside (u, v). Returns 0 if empty. */
static int extreme_section(const tippe_solid *s, int index, double u, double v, int u_at,
                           int v_at, int intersect, tiv *out)
{
    double c[2];
    centres(s, c);
    double zs[4] = {u, v, c[0], c[1]};
    int at[4] = {u_at, v_at, AT_FIXED_CENTRE, AT_FIXED_ORIGIN};
    int any = 0;
    for (int k = 0; k < 4; k++) {
        if (k >= 2 && !(zs[k] > u && zs[k] < v))
            continue;
        double lo, hi;
        int flo, fhi;
        if (!section(s, zs[k], &lo, &flo, &hi, &fhi)) {
            if (intersect)
                return 0;
            continue;
        }
        int tlo = TAG(index, flo, at[k]), thi = TAG(index, fhi, at[k]);
        if (!any) {
            *out = (tiv){lo, hi, tlo, thi};
            any = 1;
        } else if (intersect) {
            if (lo > out->lo) {
                out->lo = lo;
                out->tlo = tlo;
            }
            if (hi < out->hi) {
                out->hi = hi;
                out->thi = thi;
            }
        } else {
            if (lo < out->lo) {
                out->lo = lo;
                out->tlo = tlo;
            }
            if (hi > out->hi) {
                out->hi = hi;
                out->thi = thi;
            }
        }
    }
    return any && out->lo < out->hi;
}

/* ------------------------------------------------------ tagged intervals */

static void tiv_push(tivset *s, tiv x)
{
    if (x.lo < x.hi && s->n < MAX_IV)
        s->iv[s->n++] = x;
}

/* a minus [b.lo, b.hi], in place of out. */
static void tiv_subtract(const tivset *a, tiv b, tivset *out)
{
    out->n = 0;
    for (int i = 0; i < a->n; i++) {
        tiv x = a->iv[i];
        if (b.hi <= x.lo || b.lo >= x.hi) {
            tiv_push(out, x);
            continue;
        }
        tiv_push(out, (tiv){x.lo, b.lo, x.tlo, b.tlo});
        tiv_push(out, (tiv){b.hi, x.hi, b.thi, x.thi});
    }
}

static void tiv_intersect(const tivset *a, const tivset *b, tivset *out)
{
    out->n = 0;
    int i = 0, j = 0;
    while (i < a->n && j < b->n) {
        const tiv *x = &a->iv[i], *y = &b->iv[j];
        tiv z = x->lo >= y->lo ? (tiv){x->lo, 0, x->tlo, 0} : (tiv){y->lo, 0, y->tlo, 0};
        if (x->hi <= y->hi) {
            z.hi = x->hi;
            z.thi = x->thi;
            i++;
        } else {
            z.hi = y->hi;
            z.thi = y->thi;
            j++;
        }
        tiv_push(out, z);
    }
}

/* ------------------------------------------------------- core at height z */

/* The layer at z: the part's annulus minus the voids' annuli, with touching
 * annuli merged (they are one region of the layer). */
static void layer(const core_model *M, double z, tivset *out)
{
    out->n = 0;
    tiv x;
    int flo, fhi;
    if (!section(M->part, z, &x.lo, &flo, &x.hi, &fhi))
        return;
    x.tlo = TAG(0, flo, AT_Z);
    x.thi = TAG(0, fhi, AT_Z);
    tiv_push(out, x);
    for (int k = 0; k < M->n_voids; k++) {
        tiv h;
        if (!section(&M->voids[k], z, &h.lo, &flo, &h.hi, &fhi))
            continue;
        h.tlo = TAG(k + 1, flo, AT_Z);
        h.thi = TAG(k + 1, fhi, AT_Z);
        tivset t;
        tiv_subtract(out, h, &t);
        *out = t;
    }
    /* voids are subtracted in file order, so sort, then merge touching ends */
    for (int i = 1; i < out->n; i++)
        for (int j = i; j > 0 && out->iv[j].lo < out->iv[j - 1].lo; j--) {
            tiv s = out->iv[j];
            out->iv[j] = out->iv[j - 1];
            out->iv[j - 1] = s;
        }
    int m = 0;
    for (int i = 0; i < out->n; i++) {
        if (m > 0 && out->iv[i].lo <= out->iv[m - 1].hi) {
            if (out->iv[i].hi > out->iv[m - 1].hi) {
                out->iv[m - 1].hi = out->iv[i].hi;
                out->iv[m - 1].thi = out->iv[i].thi;
            }
        } else {
            out->iv[m++] = out->iv[i];
        }
    }
    out->n = m;
}

/* H(z): the layer's annuli shrunk by the walls. A disc (lo = 0) is bounded
 * by its rim only. */
static void walls_removed(const core_model *M, const tivset *lay, tivset *out)
{
    out->n = 0;
    for (int i = 0; i < lay->n; i++) {
        tiv x = lay->iv[i];
        if (x.lo <= 0) {
            x.lo = 0;
            x.tlo = TAG_AXIS;
        } else {
            x.lo += M->w;
        }
        x.hi -= M->w;
        tiv_push(out, x);
    }
}

/* V(z): radii whose vertical segment [z - t, z + t] lies in the printed part. */
static void skins_removed(const core_model *M, double z, tivset *out)
{
    out->n = 0;
    double u = z - M->t, v = z + M->t;
    tiv x;
    if (!extreme_section(M->part, 0, u, v, AT_BELOW, AT_ABOVE, 1, &x))
        return;
    tiv_push(out, x);
    for (int k = 0; k < M->n_voids && out->n; k++) {
        double s0[2], s1[2];
        int ns = support(&M->voids[k], s0, s1);
        for (int j = 0; j < ns; j++) {
            double a = fmax(u, s0[j]), b = fmin(v, s1[j]);
            if (!(a <= b))
                continue;
            tiv h;
            if (!extreme_section(&M->voids[k], k + 1, a, b, a == u ? AT_BELOW : AT_FIXED_END,
                                 b == v ? AT_ABOVE : AT_FIXED_END, 0, &h))
                continue;
            tivset t;
            tiv_subtract(out, h, &t);
            *out = t;
        }
    }
}

static void core_at(const core_model *M, double z, tivset *out)
{
    tivset lay, h, v;
    layer(M, z, &lay);
    walls_removed(M, &lay, &h);
    if (!h.n) {
        out->n = 0;
        return;
    }
    skins_removed(M, z, &v);
    tiv_intersect(&h, &v, out);
}

static int same_signature(const tivset *a, const tivset *b)
{
    if (a->n != b->n)
        return 0;
    for (int i = 0; i < a->n; i++)
        if (a->iv[i].tlo != b->iv[i].tlo || a->iv[i].thi != b->iv[i].thi)
            return 0;
    return 1;
}

/* ------------------------------------------------------------- integrals */

typedef struct {
    const core_model *M;
    int moment; /* 0: m, 1: m_z, 2: m_zz, 3: m_rr */
} slice_params;

/* The moment's integrand at z: the closed-form r-integral over core(z) of
 * 2 pi r (1, z, z^2, r^2) dr. */
static double slice(double z, void *params)
{
    const slice_params *sp = params;
    tivset c;
    core_at(sp->M, z, &c);
    double sum = 0;
    for (int i = 0; i < c.n; i++) {
        double lo = c.iv[i].lo, hi = c.iv[i].hi;
        double d2 = (hi - lo) * (hi + lo); /* factored: thin annuli */
        sum += sp->moment == 3 ? 0.5 * M_PI * d2 * (hi * hi + lo * lo) : M_PI * d2;
    }
    if (sp->moment == 1)
        sum *= z;
    else if (sp->moment == 2)
        sum *= z * z;
    return sum;
}

typedef struct {
    double *z;
    int n, cap;
} breaks;

static int add_break(breaks *b, double z)
{
    if (b->n == b->cap) {
        int cap = b->cap ? 2 * b->cap : 256;
        double *nz = realloc(b->z, (size_t)cap * sizeof *nz);
        if (!nz)
            return -1;
        b->z = nz;
        b->cap = cap;
    }
    b->z[b->n++] = z;
    return 0;
}

/* Breaks between a and b where the signature changes, by bisection. */
static int find_breaks(const core_model *M, double a, const tivset *sa, double b,
                       const tivset *sb, double tol, breaks *out, int depth)
{
    if (same_signature(sa, sb))
        return 0;
    if (b - a <= tol || depth > 80)
        return add_break(out, 0.5 * (a + b));
    double m = 0.5 * (a + b);
    tivset sm;
    core_at(M, m, &sm);
    if (find_breaks(M, a, sa, m, &sm, tol, out, depth + 1))
        return -1;
    return find_breaks(M, m, &sm, b, sb, tol, out, depth + 1);
}

static int cmp_double(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

/* Sample heights: a uniform grid over [zlo, zhi] plus every centre and end of
 * every solid (and the clip balls' poles), shifted by 0 and +-t. */
static int sample_heights(const core_model *M, double zlo, double zhi, breaks *s)
{
    for (int i = 0; i <= N_SAMPLES; i++)
        if (add_break(s, zlo + (zhi - zlo) * i / N_SAMPLES))
            return -1;
    for (int k = -1; k < M->n_voids; k++) {
        const tippe_solid *so = k < 0 ? M->part : &M->voids[k];
        double z0[2], z1[2], sp[12];
        int n = 0, ns = support(so, z0, z1);
        for (int j = 0; j < ns; j++) {
            sp[n++] = z0[j];
            sp[n++] = z1[j];
        }
        sp[n++] = so->z_centre;
        sp[n++] = 0;
        if (so->kind == TIPPE_SOLID_SHELL) {
            sp[n++] = so->z_centre - so->inner_radius;
            sp[n++] = so->z_centre + so->inner_radius;
        }
        if (so->clip_inner > 0) {
            sp[n++] = -so->clip_inner;
            sp[n++] = so->clip_inner;
        }
        for (int j = 0; j < n; j++)
            for (int e = -1; e <= 1; e++) {
                double z = sp[j] + e * M->t;
                if (z > zlo && z < zhi && add_break(s, z))
                    return -1;
            }
    }
    qsort(s->z, (size_t)s->n, sizeof *s->z, cmp_double);
    return 0;
}

/* Every break of the core's signature in [zlo, zhi] (ends included, sorted),
 * and the widest layer radius seen (*rmax). -1 if out of memory. */
static int find_all_breaks(const core_model *M, double zlo, double zhi, breaks *brk,
                           double *rmax)
{
    breaks samples = {0};
    int rc = -1;
    if (sample_heights(M, zlo, zhi, &samples) || add_break(brk, zlo))
        goto done;
    *rmax = 0;
    tivset prev, cur;
    core_at(M, samples.z[0], &prev);
    for (int i = 0; i < samples.n; i++) {
        tivset lay;
        layer(M, samples.z[i], &lay);
        if (lay.n)
            *rmax = fmax(*rmax, lay.iv[lay.n - 1].hi);
        if (i == 0)
            continue;
        core_at(M, samples.z[i], &cur);
        if (find_breaks(M, samples.z[i - 1], &prev, samples.z[i], &cur, BREAK_TOL * (zhi - zlo),
                        brk, 0))
            goto done;
        prev = cur;
    }
    rc = add_break(brk, zhi);
done:
    free(samples.z);
    return rc;
}

/* QAGS on every piece between breaks where the core is not empty; scale[k]
 * sets the absolute tolerance of moment k. */
static int integrate_pieces(const core_model *M, const breaks *brk, const double scale[4],
                            gsl_integration_workspace *ws, tippe_print_core *out,
                            tippe_error *err)
{
    double sum[4] = {0, 0, 0, 0};
    for (int i = 0; i + 1 < brk->n; i++) {
        double a = brk->z[i], b = brk->z[i + 1];
        if (!(b > a))
            continue;
        tivset mid;
        core_at(M, 0.5 * (a + b), &mid);
        if (!mid.n)
            continue;
        out->n_pieces++;
        for (int k = 0; k < 4; k++) {
            slice_params sp = {M, k};
            gsl_function f = {slice, &sp};
            double res = 0, abserr = 0;
            int st = gsl_integration_qags(&f, a, b, 1e-3 * EPS_REL * scale[k], EPS_REL, QAGS_LIMIT,
                                          ws, &res, &abserr);
            if (st != GSL_SUCCESS && !(abserr <= 1e-3 * ACCEPT_REL * scale[k]))
                return tippe_error_set(err, TIPPE_ECOMPUTE,
                                       "print model: GSL QAGS failed on z = %g .. %g m (%s, error "
                                       "estimate %g of the part's scale)",
                                       a, b, gsl_strerror(st), abserr / scale[k]);
            sum[k] += res;
            out->abserr[k] += abserr;
        }
    }
    out->core = (tippe_moments){sum[0], sum[1], sum[2], sum[3]};
    return TIPPE_OK;
}

/* Refuses what the model cannot do. */
static int check_core_input(const tippe_solid *voids, int n_voids, double wall_m, double skin_m,
                            tippe_error *err)
{
    if (n_voids < 0 || n_voids > MAX_VOIDS)
        return tippe_error_set(err, TIPPE_EINPUT, "print model: %d voids (at most %d)", n_voids,
                               MAX_VOIDS);
    if (!(wall_m >= 0) || !(skin_m >= 0) || !isfinite(wall_m) || !isfinite(skin_m))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "print model: walls and skins must be finite and >= 0");
    for (int k = 0; k < n_voids; k++)
        if (voids[k].kind == TIPPE_SOLID_TORUS &&
            (voids[k].clip_outer > 0 || voids[k].clip_inner > 0))
            return tippe_error_set(err, TIPPE_EINPUT,
                                   "print model: a clipped torus void is not supported (the "
                                   "extreme radii of its annulus over a range of heights are "
                                   "not at a fixed height)");
    return TIPPE_OK;
}

int tippe_print_core_moments(const tippe_solid *part, const tippe_solid *voids, int n_voids,
                             double wall_m, double skin_m, tippe_print_core *out,
                             tippe_error *err)
{
    tippe_gsl_errors_as_codes();
    memset(out, 0, sizeof *out);
    int rc = check_core_input(voids, n_voids, wall_m, skin_m, err);
    if (rc)
        return rc;
    core_model M = {part, voids, n_voids, wall_m, skin_m};
    double z0[2], z1[2];
    int ns = support(part, z0, z1);
    if (!ns)
        return TIPPE_OK; /* nothing printed */
    double zlo = z0[0], zhi = z1[ns - 1], rmax = 0;
    breaks brk = {0};
    gsl_integration_workspace *ws = gsl_integration_workspace_alloc(QAGS_LIMIT);
    if (!ws || find_all_breaks(&M, zlo, zhi, &brk, &rmax)) {
        rc = tippe_error_set(err, TIPPE_ECOMPUTE, "print model: out of memory");
    } else {
        /* scales for the absolute tolerances: the part's bounding cylinder */
        double zabs = fmax(fabs(zlo), fabs(zhi)), vol = M_PI * rmax * rmax * (zhi - zlo);
        double scale[4] = {vol, vol * zabs, vol * zabs * zabs, vol * rmax * rmax};
        rc = integrate_pieces(&M, &brk, scale, ws, out, err);
    }
    gsl_integration_workspace_free(ws);
    free(brk.z);
    return rc;
}

/* ------------------------------------------------------ mass, calibration */

tippe_print_settings tippe_print_defaults(void)
{
    /* PrusaSlicer 2.5, "0.20mm QUALITY @MK3" with a 0.4 mm nozzle
     * (designs/slicer/prusa-pla-0.4mm.ini): widths 1.125 x the nozzle
     * (Flow::auto_extrusion_width), gyroid, 25 % overlap, anchors 2.5 / 12 mm */
    tippe_print_settings s = {.perimeters = 2,
                              .line_width_mm = 0.45,
                              .top_bottom_layers = 4,
                              .layer_height_mm = 0.2,
                              .infill = 0.15,
                              .model = TIPPE_PRINT_MODEL_SLICER,
                              .pattern = TIPPE_PATTERN_GYROID,
                              .external_width_mm = 0.45,
                              .infill_width_mm = 0.45,
                              .first_layer_height_mm = 0.2,
                              .first_layer_width_mm = 0.42,
                              .top_min_mm = 0.7,
                              .bottom_min_mm = 0.5,
                              .infill_overlap = 0.25,
                              .anchor_mm = 2.5,
                              .anchor_max_mm = 12,
                              .nozzle_mm = 0.4,
                              .thick_bridges = 1,
                              .flow = 1.0};
    return s;
}

int tippe_print_infill_for_mass(double mass_kg, double solid_volume_m3, double core_volume_m3,
                                double density_kg_m3, double *infill, double *mass_at_0,
                                double *mass_at_1)
{
    double m1 = density_kg_m3 * solid_volume_m3;
    double m0 = density_kg_m3 * (solid_volume_m3 - core_volume_m3);
    if (mass_at_0)
        *mass_at_0 = m0;
    if (mass_at_1)
        *mass_at_1 = m1;
    if (mass_kg < m0)
        return -1;
    if (mass_kg > m1)
        return 1;
    *infill = core_volume_m3 > 0 ? (mass_kg - m0) / (m1 - m0) : 1.0;
    return 0;
}

/* ---------------------------------------------- for the slicer's rules */

/* The printed part's cross-section at height z (m): its annuli, sorted and
 * disjoint, written to lo[], hi[] (at most cap); returns how many. The layer
 * model (print_slicer.c) slices the part with it as a slicer does. */
int tippe_print_section(const tippe_solid *part, const tippe_solid *voids, int n_voids, double z,
                        double *lo, double *hi, int cap)
{
    core_model M = {part, voids, n_voids, 0, 0};
    tivset lay;
    layer(&M, z, &lay);
    int n = 0;
    for (int i = 0; i < lay.n && n < cap; i++, n++) {
        lo[n] = lay.iv[i].lo;
        hi[n] = lay.iv[i].hi;
    }
    return n;
}

/* Heights (m) between which the part can have material. */
int tippe_print_extent(const tippe_solid *part, double *z_lo, double *z_hi)
{
    double z0[2], z1[2];
    int ns = support(part, z0, z1);
    if (!ns)
        return 0;
    *z_lo = z0[0];
    *z_hi = z1[ns - 1];
    return 1;
}
