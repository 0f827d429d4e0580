/* Where the parts are: each part as z intervals at a radius r of the (r, z)
 * half-plane, overlap and travel decided by interval arithmetic (see the note at
 * the top of design.c), the physical travel, and what can be printed. */
#include "design/internal.h"

#include <cjson/cJSON.h>
#include <gsl/gsl_errno.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static double widest_free_gap_mid(const tippe_design *d, const double *rs, int nr);

/* limit_by_contact's answer when asked quietly: a moving part overlaps a fixed one there. */
#define BLOCKED (-1)

/* ------------------------------------------------------ z intervals at r */


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
void tippe_design_material_ivs(const tippe_design *d, int i, double r, double dz, ivset *s)
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

const char *tippe_design_role_of(const part *p)
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
        tippe_design_material_ivs(d, i, L->rs[k], 0, &a);
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
            tippe_design_material_ivs(d, i, L->rs[k], 0, &a);
            tippe_design_material_ivs(d, j, L->rs[k], 0, &b);
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
 * if mid itself is forbidden (BLOCKED, with no message, unless report). */
static int limit_by_contact(const layout *L, int i, int j, double mid, double lim[2], int report)
{
    tippe_design *d = L->d;
    const part *p = &d->parts[i];
    ivset a, b;
    for (int k = 0; k < L->nr; k++) {
        tippe_design_material_ivs(d, i, L->rs[k], 0, &a);
        if (!a.n)
            continue;
        if (j < 0)
            outside_ivs(d->radius_mm, L->rs[k], &b);
        else
            tippe_design_material_ivs(d, j, L->rs[k], 0, &b);
        for (int u = 0; u < a.n; u++)
            for (int w = 0; w < b.n; w++) {
                double f0 = b.lo[w] - a.hi[u], f1 = b.hi[w] - a.lo[u];
                int s = -1;
                if (f0 < mid && mid < f1) {
                    if (!report)
                        return BLOCKED;
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
static int physical_travel_around(const layout *L, double mid, double lim[2], int report)
{
    tippe_design *d = L->d;
    lim[0] = -BIG_MM;
    lim[1] = BIG_MM;
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
            rc = limit_by_contact(L, i, j, mid, lim, report);
        }
    }
    return rc;
}

/* A stated travel whose middle is forbidden (a huge end: travel_mm [0, 100] in a
 * ball of radius 25) is measured against the free stretch around its start, else its
 * end, so that check_travel says "ends at 100 mm, beyond the physical travel A .. B mm"
 * (issue 25.5); only when neither end is free does the message name the middle. */
static int find_physical_travel(const layout *L)
{
    tippe_design *d = L->d;
    double mid = d->travel_physical ? widest_free_gap_mid(d, L->rs, L->nr)
                                    : 0.5 * (d->travel_mm[0] + d->travel_mm[1]);
    double lim[2];
    int rc = physical_travel_around(L, mid, lim, 0);
    for (int e = 0; rc == BLOCKED && !d->travel_physical && e < 2; e++)
        rc = physical_travel_around(L, d->travel_mm[e], lim, 0);
    if (rc == BLOCKED)
        rc = physical_travel_around(L, mid, lim, 1);
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
            tippe_design_material_ivs(d, i, rs[k], 0, &a);
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
int tippe_design_check_layout(const tippe_json_reader *c, tippe_design *d)
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
 * physical travel in tippe_design_check_layout), and the stretch is a gap between their
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
                tippe_design_material_ivs(d, i, rs[k], 0, &a);
                if (!a.n)
                    continue;
                if (j < 0)
                    outside_ivs(R, rs[k], &b);
                else
                    tippe_design_material_ivs(d, j, rs[k], 0, &b);
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
                                .clip_inner_mm = p->clip_inner_mm,
                                .printed_radius_mm = p->printed_radius_mm,
                                .printed_radius_from_fit = p->printed_radius_from_fit};
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
