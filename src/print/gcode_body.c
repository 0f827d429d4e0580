/* gcode_body.c: the deposit's mass moments, its layers, objects and clusters,
 * and the part found in it (see include/tippe/print.h).
 *
 * A bead of mass dm uniform along the segment a -> b (t in [0, 1]) has, about
 * the reference point o (a, b taken relative to o), the exact sums
 *   sum x_i     = dm (a_i + b_i) / 2,
 *   sum x_i x_j = dm ((a_i a_j + b_i b_j) / 3 + (a_i b_j + b_i a_j) / 6)
 * (the integral of a quadratic in t over [0, 1]); a box bead adds its
 * cross-section's second moments dm w^2/12 along the horizontal normal n and
 * dm h^2/12 along z (a uniform w x h rectangle's variances). Sums are kept
 * about the first deposit's (x, y, 0) so that the central moments, formed as
 * q - m c c^T, lose little to cancellation on a bed hundreds of mm wide. */
#include "print/gcode_state.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const feature_names[TIPPE_GCODE_N_FEATURES] = {
    "external perimeter", "perimeter",      "solid infill", "top solid infill",
    "bridge infill",      "sparse infill",  "gap fill",     "other",
    "skirt/brim",         "support",        "support interface",
    "wipe tower",         "custom",         "unlabelled"};

const char *tippe_gcode_feature_name(tippe_gcode_feature f)
{
    return (int)f >= 0 && f < TIPPE_GCODE_N_FEATURES ? feature_names[f] : "?";
}

void tippe_gcode_acc_init(tippe_gcode_acc *a, tippe_gcode_bead bead, int labelled)
{
    memset(a, 0, sizeof *a);
    a->bead = bead;
    a->labelled = labelled;
    for (int f = 0; f < TIPPE_GCODE_N_FEATURES; f++) {
        for (int i = 0; i < 3; i++) {
            a->lo[f][i] = INFINITY;
            a->hi[f][i] = -INFINITY;
        }
        a->zmin_nozzle[f] = INFINITY;
    }
}

void tippe_gcode_acc_free(tippe_gcode_acc *a)
{
    free(a->all.z);
    free(a->body.z);
    free(a->unlab.z);
    free(a->seg);
    free(a->near.bead);
    a->all.z = a->body.z = a->unlab.z = NULL;
    a->seg = NULL;
    a->near.bead = NULL;
    a->near.n = 0;
}

/* ------------------------------------------------------------ levels */

/* Index of the first level >= z - eps. */
static size_t levels_lower(const tippe_gcode_levels *l, double z)
{
    size_t lo = 0, hi = l->n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (l->z[mid] < z - GC_LEVEL_EPS_MM)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

static void levels_insert(tippe_gcode_acc *a, tippe_gcode_levels *l, double z)
{
    /* the common case: at or above the last level */
    size_t i = l->n;
    if (l->n && z < l->z[l->n - 1] + GC_LEVEL_EPS_MM)
        i = levels_lower(l, z);
    if (i < l->n && fabs(l->z[i] - z) <= GC_LEVEL_EPS_MM)
        return;
    if (l->n == l->cap) {
        size_t cap = l->cap ? 2 * l->cap : 256;
        double *z2 = realloc(l->z, cap * sizeof *z2);
        if (!z2) {
            a->oom = 1;
            return;
        }
        l->z = z2;
        l->cap = cap;
    }
    memmove(l->z + i + 1, l->z + i, (l->n - i) * sizeof *l->z);
    l->z[i] = z;
    l->n++;
}

double tippe_gcode_fallback_height(const tippe_gcode_acc *a, double z_mm)
{
    size_t i = levels_lower(&a->all, z_mm);
    double below = i > 0 ? a->all.z[i - 1] : 0.0;
    double h = z_mm - below;
    return h > GC_LEVEL_EPS_MM ? h : 0.0;
}

/* ------------------------------------------------------------ deposits */

/* Plain comparisons, not fmin/fmax (library calls, a tenth of the reader's time);
 * no value here is a NaN (the reader refuses non-numbers). */
static inline double lesser(double a, double b) { return b < a ? b : a; }
static inline double greater(double a, double b) { return b > a ? b : a; }

static void grow(double lo[3], double hi[3], double x, double y, double z, double r)
{
    lo[0] = lesser(lo[0], x - r);
    hi[0] = greater(hi[0], x + r);
    lo[1] = lesser(lo[1], y - r);
    hi[1] = greater(hi[1], y + r);
    lo[2] = lesser(lo[2], z);
    hi[2] = greater(hi[2], z);
}

/* The sums of the header for one bead (gcode_state.h). */
void tippe_gcode_add_bead(tippe_gcode_moments *m, const double u[3], const double v[3], double dm,
                          int box, double h, double w, double dx, double dy, double lxy)
{
    m->m += dm;
    for (int i = 0; i < 3; i++)
        m->s[i] += dm * (u[i] + v[i]) / 2;
    static const int qi[6] = {0, 1, 2, 0, 0, 1}, qj[6] = {0, 1, 2, 1, 2, 2};
    for (int k = 0; k < 6; k++) {
        int i = qi[k], j = qj[k];
        m->q[k] += dm * ((u[i] * u[j] + v[i] * v[j]) / 3 + (u[i] * v[j] + v[i] * u[j]) / 6);
    }
    if (box && h > 0) {
        m->q[2] += dm * h * h / 12;
        if (lxy > 0) {
            double nx = -dy / lxy, ny = dx / lxy, c = dm * w * w / 12;
            m->q[0] += c * nx * nx;
            m->q[1] += c * ny * ny;
            m->q[3] += c * nx * ny;
        }
    }
}

double tippe_gcode_distance_xy(double x, double y, const double p0[3], const double p1[3])
{
    double dx = p1[0] - p0[0], dy = p1[1] - p0[1], l2 = dx * dx + dy * dy;
    double t = l2 > 0 ? ((x - p0[0]) * dx + (y - p0[1]) * dy) / l2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    double ex = p0[0] + t * dx - x, ey = p0[1] + t * dy - y;
    return sqrt(ex * ex + ey * ey);
}

/* Keeps a body bead for later cuts (filtered to the axis's neighbourhood at the end). */
static void keep_near(tippe_gcode_acc *a, const double p0[3], const double p1[3], double h,
                      double w, double vol)
{
    tippe_gcode_beads *nb = &a->near;
    if (nb->n == a->cap_near) {
        size_t cap = a->cap_near ? 2 * a->cap_near : 4096;
        tippe_gcode_near_bead *b2 = realloc(nb->bead, cap * sizeof *b2);
        if (!b2) {
            a->oom = 1;
            return;
        }
        nb->bead = b2;
        a->cap_near = cap;
    }
    nb->bead[nb->n++] = (tippe_gcode_near_bead){(float)p0[0], (float)p0[1], (float)p0[2],
                                                (float)p1[0], (float)p1[1], (float)p1[2],
                                                (float)h,     (float)w,     (float)vol};
}

void tippe_gcode_deposit(tippe_gcode_acc *a, int f, const double p0[3], const double p1[3], double vol,
                double rho, double h, int count)
{
    if (!(vol > 0))
        return;
    if (!a->have_ref) {
        a->ref[0] = p0[0];
        a->ref[1] = p0[1];
        a->ref[2] = 0;
        a->have_ref = 1;
    }
    double dx = p1[0] - p0[0], dy = p1[1] - p0[1], dz = p1[2] - p0[2];
    /* sqrt, not hypot: a bed's lengths neither overflow nor underflow */
    double len = sqrt(dx * dx + dy * dy + dz * dz), lxy = sqrt(dx * dx + dy * dy);
    double w = h > 0 && len > 0 ? lesser(vol / (len * h), GC_MAX_BEAD_WIDTH_MM) : 0;
    int box = a->bead == TIPPE_GCODE_BEAD_BOX;
    double shift = box ? h / 2 : 0;
    double u[3], v[3];
    for (int i = 0; i < 3; i++) {
        u[i] = p0[i] - a->ref[i];
        v[i] = p1[i] - a->ref[i];
    }
    u[2] -= shift;
    v[2] -= shift;
    double dm = vol * rho;
    tippe_gcode_add_bead(&a->mom[f], u, v, dm, box, h, w, dx, dy, lxy);
    if (a->keep_radius_mm > 0 && box &&
        (f < TIPPE_GCODE_SKIRT_BRIM || (f == TIPPE_GCODE_UNLABELLED && !a->labelled)))
        keep_near(a, p0, p1, h, w, vol);
    a->vol[f] += vol;
    a->mass[f] += dm;
    a->len[f] += len;
    a->len_h[f] += len * h;
    a->vol_h[f] += vol * h;
    if (len == 0)
        a->point_vol[f] += vol;
    if (count)
        a->n_moves[f]++;
    /* the beads' extents: w/2 sideways, from the nozzle down by h */
    grow(a->lo[f], a->hi[f], p0[0], p0[1], p0[2], w / 2);
    grow(a->lo[f], a->hi[f], p1[0], p1[1], p1[2], w / 2);
    a->lo[f][2] = lesser(a->lo[f][2], lesser(p0[2], p1[2]) - h);
    a->zmin_nozzle[f] = lesser(a->zmin_nozzle[f], lesser(p0[2], p1[2]));

    if (f != TIPPE_GCODE_CUSTOM && !(f == TIPPE_GCODE_UNLABELLED && a->labelled))
        levels_insert(a, &a->all, p1[2]);
    if (!tippe_gcode_body_candidate(f))
        return;
    levels_insert(a, f == TIPPE_GCODE_UNLABELLED ? &a->unlab : &a->body, p1[2]);
    if (a->n_seg == a->cap_seg) {
        size_t cap = a->cap_seg ? 2 * a->cap_seg : 4096;
        tippe_gcode_seg *s2 = realloc(a->seg, cap * sizeof *s2);
        if (!s2) {
            a->oom = 1;
            return;
        }
        a->seg = s2;
        a->cap_seg = cap;
    }
    a->seg[a->n_seg++] = (tippe_gcode_seg){(float)p0[0], (float)p0[1], (float)p1[0], (float)p1[1],
                                  (float)vol, (unsigned char)f};
}

void tippe_gcode_object_seen(tippe_gcode_acc *a, int scheme, const char *name)
{
    tippe_gcode_names *ns = &a->objects[scheme];
    for (int i = 0; i < ns->n && i < GC_MAX_NAMES; i++)
        if (!strcmp(ns->name[i], name))
            return;
    if (ns->n < GC_MAX_NAMES)
        snprintf(ns->name[ns->n], TIPPE_GCODE_NAME_MAX, "%s", name);
    if (ns->n < GC_MAX_NAMES)
        ns->n++;
}

/* ------------------------------------------------------------ clusters */

/* Groups of the body's footprint: the centre lines rasterised on cells of
 * max(0.5 mm, extent / 1024), cells within two of each other joined (a gap of
 * one empty cell is closed: infill lines a few mm apart cross the walls
 * anyway; parts the slicer arranges >= 1 mm apart stay apart). */
static int clusters(tippe_gcode_acc *a, int unlab_body, tippe_gcode_body *out)
{
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    size_t n = 0;
    for (size_t k = 0; k < a->n_seg; k++) {
        const tippe_gcode_seg *s = &a->seg[k];
        if (s->feature == TIPPE_GCODE_UNLABELLED && !unlab_body)
            continue;
        x0 = fmin(x0, fmin(s->x0, s->x1));
        x1 = fmax(x1, fmax(s->x0, s->x1));
        y0 = fmin(y0, fmin(s->y0, s->y1));
        y1 = fmax(y1, fmax(s->y0, s->y1));
        n++;
    }
    if (!n)
        return 0;
    double cell = fmax(0.5, fmax(x1 - x0, y1 - y0) / 1024);
    int nx = (int)((x1 - x0) / cell) + 1, ny = (int)((y1 - y0) / cell) + 1;
    size_t nc = (size_t)nx * ny;
    int *label = malloc(nc * sizeof *label), *stack = malloc(nc * sizeof *stack);
    if (!label || !stack) {
        free(label);
        free(stack);
        return -1;
    }
    for (size_t c = 0; c < nc; c++)
        label[c] = -2; /* empty */
#define CELL(x, y) ((size_t)(int)(((y) - y0) / cell) * nx + (size_t)(int)(((x) - x0) / cell))
    for (size_t k = 0; k < a->n_seg; k++) {
        const tippe_gcode_seg *s = &a->seg[k];
        if (s->feature == TIPPE_GCODE_UNLABELLED && !unlab_body)
            continue;
        double ux = s->x1 - s->x0, uy = s->y1 - s->y0, len = sqrt(ux * ux + uy * uy);
        int steps = (int)ceil(len / (cell / 2));
        for (int i = 0; i <= steps; i++) {
            double t = steps ? (double)i / steps : 0;
            double x = s->x0 + t * ux, y = s->y0 + t * uy;
            label[CELL(lesser(greater(x, x0), x1), lesser(greater(y, y0), y1))] = -1;
        }
    }
    int ncl = 0;
    for (size_t c = 0; c < nc; c++) {
        if (label[c] != -1)
            continue;
        size_t top = 0;
        stack[top++] = (int)c;
        label[c] = ncl;
        while (top) {
            int cc = stack[--top], cx = cc % nx, cy = cc / nx;
            for (int j = cy - 2; j <= cy + 2; j++)
                for (int i = cx - 2; i <= cx + 2; i++)
                    if (i >= 0 && j >= 0 && i < nx && j < ny && label[(size_t)j * nx + i] == -1) {
                        label[(size_t)j * nx + i] = ncl;
                        stack[top++] = j * nx + i;
                    }
        }
        ncl++;
    }
    double *vol = calloc((size_t)ncl, sizeof *vol);
    double *box = malloc((size_t)ncl * 4 * sizeof *box);
    if (!vol || !box) {
        free(vol);
        free(box);
        free(label);
        free(stack);
        return -1;
    }
    for (int k = 0; k < ncl; k++) {
        box[4 * k] = box[4 * k + 1] = INFINITY;
        box[4 * k + 2] = box[4 * k + 3] = -INFINITY;
    }
    for (size_t c = 0; c < nc; c++) {
        int k = label[c];
        if (k < 0)
            continue;
        double x = x0 + (c % nx + 0.5) * cell, y = y0 + (c / nx + 0.5) * cell;
        box[4 * k] = fmin(box[4 * k], x);
        box[4 * k + 1] = fmin(box[4 * k + 1], y);
        box[4 * k + 2] = fmax(box[4 * k + 2], x);
        box[4 * k + 3] = fmax(box[4 * k + 3], y);
    }
    for (size_t k = 0; k < a->n_seg; k++) {
        const tippe_gcode_seg *s = &a->seg[k];
        if (s->feature == TIPPE_GCODE_UNLABELLED && !unlab_body)
            continue;
        vol[label[CELL(s->x0, s->y0)]] += s->volume;
    }
#undef CELL
    int best[2] = {-1, -1};
    for (int k = 0; k < ncl; k++) {
        if (best[0] < 0 || vol[k] > vol[best[0]]) {
            best[1] = best[0];
            best[0] = k;
        } else if (best[1] < 0 || vol[k] > vol[best[1]]) {
            best[1] = k;
        }
    }
    out->n_clusters = ncl;
    for (int i = 0; i < 2; i++) {
        int k = best[i];
        if (k < 0)
            continue;
        out->cluster_volume_mm3[i] = vol[k];
        out->cluster_centre[i][0] = 1e-3 * (box[4 * k] + box[4 * k + 2]) / 2;
        out->cluster_centre[i][1] = 1e-3 * (box[4 * k + 1] + box[4 * k + 3]) / 2;
    }
    free(vol);
    free(box);
    free(label);
    free(stack);
    return 0;
}

/* ------------------------------------------------------------ finishing */

int tippe_gcode_acc_finish(tippe_gcode_acc *a, tippe_gcode_body *out, tippe_error *err)
{
    if (a->oom)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "%s: out of memory", out->source);
    int unlab_body = !a->labelled;
    tippe_gcode_moments b = {0};
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    double vol_h = 0, zmin = INFINITY;
    out->body_volume_mm3 = out->excluded_volume_mm3 = out->excluded_mass_kg = 0;
    out->point_volume_mm3 = 0;
    for (int f = 0; f < TIPPE_GCODE_N_FEATURES; f++) {
        tippe_gcode_share *sh = &out->feature[f];
        sh->volume_mm3 = a->vol[f];
        sh->mass_kg = a->mass[f];
        sh->length_mm = a->len[f];
        sh->width_mm = a->len_h[f] > 0 ? a->vol[f] / a->len_h[f] : 0;
        sh->n_moves = a->n_moves[f];
        int body = f < TIPPE_GCODE_SKIRT_BRIM || (f == TIPPE_GCODE_UNLABELLED && unlab_body);
        if (!body) {
            out->excluded_volume_mm3 += a->vol[f];
            out->excluded_mass_kg += a->mass[f];
            continue;
        }
        out->body_volume_mm3 += a->vol[f];
        out->point_volume_mm3 += a->point_vol[f];
        b.m += a->mom[f].m;
        for (int i = 0; i < 3; i++)
            b.s[i] += a->mom[f].s[i];
        for (int k = 0; k < 6; k++)
            b.q[k] += a->mom[f].q[k];
        for (int i = 0; i < 3; i++) {
            lo[i] = fmin(lo[i], a->lo[f][i]);
            hi[i] = fmax(hi[i], a->hi[f][i]);
        }
        vol_h += a->vol_h[f];
        zmin = fmin(zmin, a->zmin_nozzle[f]);
    }
    if (!(b.m > 0)) {
        return tippe_error_set(
            err, TIPPE_EINPUT,
            "%s: no extrusion in the part's body (%.6g mm^3 deposited in excluded features: "
            "skirt, brim, support, towers, custom or unlabelled G-code)",
            out->source, out->excluded_volume_mm3);
    }
    /* centre of mass and central moments, mm and kg */
    double c[3], qc[6];
    for (int i = 0; i < 3; i++)
        c[i] = b.s[i] / b.m;
    static const int qi[6] = {0, 1, 2, 0, 0, 1}, qj[6] = {0, 1, 2, 1, 2, 2};
    for (int k = 0; k < 6; k++)
        qc[k] = b.q[k] - b.m * c[qi[k]] * c[qj[k]];
    out->m = b.m;
    for (int i = 0; i < 3; i++) {
        out->com[i] = 1e-3 * (c[i] + a->ref[i]);
        out->bbox_min[i] = 1e-3 * lo[i];
        out->bbox_max[i] = 1e-3 * hi[i];
    }
    out->inertia[0] = 1e-6 * (qc[1] + qc[2]);
    out->inertia[1] = 1e-6 * (qc[0] + qc[2]);
    out->inertia[2] = 1e-6 * (qc[0] + qc[1]);
    out->inertia[3] = -1e-6 * qc[3];
    out->inertia[4] = -1e-6 * qc[4];
    out->inertia[5] = -1e-6 * qc[5];
    out->layer_height = 1e-3 * vol_h / out->body_volume_mm3;
    out->cut_volume_mm3 = out->cut_mass_kg = 0;
    for (int k = 0; k < TIPPE_GCODE_MAX_CUTS; k++)
        out->cut_hole_radius_mm[k] = INFINITY;
    if (a->keep_radius_mm > 0) { /* the beads near the footprint's axis, as tippe_gcode_match has it */
        double ax = (lo[0] + hi[0]) / 2, ay = (lo[1] + hi[1]) / 2, r = a->keep_radius_mm;
        tippe_gcode_beads *nb = &a->near;
        size_t k = 0;
        for (size_t j = 0; j < nb->n; j++) {
            const tippe_gcode_near_bead *e = &nb->bead[j];
            double p0[3] = {e->x0, e->y0, e->z0}, p1[3] = {e->x1, e->y1, e->z1};
            if (tippe_gcode_distance_xy(ax, ay, p0, p1) < r + e->w_mm / 2)
                nb->bead[k++] = *e;
        }
        nb->n = k;
        nb->radius_mm = r;
    }
    out->first_layer_z = 1e-3 * zmin;

    /* layers: the body's distinct nozzle heights (with the unlabelled ones if body) */
    size_t nl = a->body.n;
    if (unlab_body) {
        for (size_t i = 0; i < a->unlab.n; i++) {
            size_t j = levels_lower(&a->body, a->unlab.z[i]);
            if (!(j < a->body.n && fabs(a->body.z[j] - a->unlab.z[i]) <= GC_LEVEL_EPS_MM))
                nl++;
        }
    }
    out->n_layers = (int)nl;

    /* objects: the scheme that names most (a file may label one object twice over) */
    out->n_objects = 0;
    for (int s = 0; s < GC_SCHEMES; s++) {
        const tippe_gcode_names *ns = &a->objects[s];
        if (ns->n > out->n_objects) {
            out->n_objects = ns->n;
            for (int i = 0; i < 2; i++)
                snprintf(out->object[i], TIPPE_GCODE_NAME_MAX, "%s", i < ns->n ? ns->name[i] : "");
        }
    }
    if (clusters(a, unlab_body, out))
        return tippe_error_set(err, TIPPE_ECOMPUTE, "%s: out of memory", out->source);
    return TIPPE_OK;
}

/* Every mass of the body is its volume times the one density (override_density). */
void tippe_gcode_body_set_density(tippe_gcode_body *b, double density_g_cm3)
{
    if (!(b->density_g_cm3 > 0) || b->density_g_cm3 == density_g_cm3)
        return;
    double k = density_g_cm3 / b->density_g_cm3;
    for (int f = 0; f < TIPPE_GCODE_N_FEATURES; f++)
        b->feature[f].mass_kg *= k;
    b->excluded_mass_kg *= k;
    b->cut_mass_kg *= k;
    b->m *= k;
    for (int i = 0; i < 6; i++)
        b->inertia[i] *= k;
    b->density_g_cm3 = density_g_cm3;
}

/* ------------------------------------------------------------ the part */

int tippe_gcode_match(const tippe_gcode_body *b, const tippe_gcode_expect *e,
                      tippe_gcode_part *out, tippe_error *err)
{
    static const tippe_gcode_expect none = {0};
    if (!e)
        e = &none;
    const char *src = b->source;
    if (b->n_objects > 1)
        return tippe_error_set(err, TIPPE_EINPUT,
                               "%s: %d objects are printed ('%s', '%s'%s): the G-code must "
                               "hold the part alone",
                               src, b->n_objects, b->object[0], b->object[1],
                               b->n_objects > 2 ? ", ..." : "");
    if (b->n_clusters > 1)
        return tippe_error_set(
            err, TIPPE_EINPUT,
            "%s: seen from above the deposit falls in %d separate groups (%.4g mm^3 around "
            "x = %.2f, y = %.2f mm; %.4g mm^3 around x = %.2f, y = %.2f mm%s): the G-code must "
            "hold the part alone",
            src, b->n_clusters, b->cluster_volume_mm3[0], 1e3 * b->cluster_centre[0][0],
            1e3 * b->cluster_centre[0][1], b->cluster_volume_mm3[1], 1e3 * b->cluster_centre[1][0],
            1e3 * b->cluster_centre[1][1], b->n_clusters > 2 ? "; ..." : "");

    double layer_mm = 1e3 * b->layer_height;
    double height_mm = 1e3 * (b->bbox_max[2] - b->bbox_min[2]);
    double bottom_mm = 1e3 * b->bbox_min[2];
    double dx_mm = 1e3 * (b->bbox_max[0] - b->bbox_min[0]);
    double dy_mm = 1e3 * (b->bbox_max[1] - b->bbox_min[1]);
    double ax_mm = 1e3 * (b->bbox_max[0] + b->bbox_min[0]) / 2;
    double ay_mm = 1e3 * (b->bbox_max[1] + b->bbox_min[1]) / 2;
    double htol = e->height_tol_mm > 0 ? e->height_tol_mm : layer_mm + 0.1;
    double bead_mm = b->feature[TIPPE_GCODE_EXTERNAL_PERIMETER].width_mm;
    if (!(bead_mm > 0))
        bead_mm = 0.5;
    double dtol = e->diameter_tol_mm > 0 ? e->diameter_tol_mm : bead_mm + 0.1;
    double atol = e->axis_tol_mm > 0 ? e->axis_tol_mm : dtol;
    if (e->height_mm > 0 && !(fabs(height_mm - e->height_mm) <= htol))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "%s: the deposit is %.3f mm high (z %.3f to %.3f mm), the part "
                               "%.3f mm: off by %.3f mm, more than the tolerance %.3f mm%s",
                               src, height_mm, bottom_mm, 1e3 * b->bbox_max[2], e->height_mm,
                               height_mm - e->height_mm, htol,
                               e->height_tol_mm > 0 ? "" : " (one layer + 0.1 mm)");
    if (!(fabs(bottom_mm - e->bottom_z_mm) <= htol))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "%s: the deposit's bottom is at z = %.3f mm, the part's at %.3f "
                               "mm: off by more than the tolerance %.3f mm",
                               src, bottom_mm, e->bottom_z_mm, htol);
    if (e->diameter_mm > 0 &&
        !(fabs(dx_mm - e->diameter_mm) <= dtol && fabs(dy_mm - e->diameter_mm) <= dtol))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "%s: the deposit's footprint is %.3f mm x %.3f mm (x by y), the "
                               "part's diameter %.3f mm: off by more than the tolerance %.3f mm%s",
                               src, dx_mm, dy_mm, e->diameter_mm, dtol,
                               e->diameter_tol_mm > 0 ? "" : " (a bead's width + 0.1 mm)");
    if (e->axis_known && !(hypot(ax_mm - e->axis_x_mm, ay_mm - e->axis_y_mm) <= atol))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "%s: the deposit's axis stands at x = %.3f, y = %.3f mm on the "
                               "bed, the part's at x = %.3f, y = %.3f mm: %.3f mm away, more "
                               "than the tolerance %.3f mm",
                               src, ax_mm, ay_mm, e->axis_x_mm, e->axis_y_mm,
                               hypot(ax_mm - e->axis_x_mm, ay_mm - e->axis_y_mm), atol);

    tippe_gcode_part p;
    p.axis_x = 1e-3 * ax_mm;
    p.axis_y = 1e-3 * ay_mm;
    p.bottom_z = b->bbox_min[2];
    p.height = b->bbox_max[2] - b->bbox_min[2];
    p.diameter_x = b->bbox_max[0] - b->bbox_min[0];
    p.diameter_y = b->bbox_max[1] - b->bbox_min[1];
    p.m = b->m;
    p.z_cm = b->com[2] - p.bottom_z;
    p.com_offset_x = b->com[0] - p.axis_x;
    p.com_offset_y = b->com[1] - p.axis_y;
    p.Ixx = b->inertia[0];
    p.Iyy = b->inertia[1];
    p.Ixy = b->inertia[3];
    p.A = (p.Ixx + p.Iyy) / 2;
    /* parallel axes: Izz about the centre of mass plus m d^2 to the axis */
    p.C = b->inertia[2] +
          b->m * (p.com_offset_x * p.com_offset_x + p.com_offset_y * p.com_offset_y);
    p.asymmetry = 2 * hypot((p.Ixx - p.Iyy) / 2, p.Ixy) / p.A;
    p.off_diagonal = hypot(b->inertia[4], b->inertia[5]) / p.A;
    *out = p;
    return TIPPE_OK;
}

