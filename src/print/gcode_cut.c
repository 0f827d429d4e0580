/* gcode_cut.c: what the part loses after printing, cut from a G-code's body
 * (see tippe_gcode_cut_body in include/tippe/print.h).
 *
 * A maker prints the screw's hole narrower than the mass model's (the tap drill,
 * an insert's pilot: build/build.c) and then taps, drills or bores it; the
 * model's hole is the thread as a smooth cylinder of the hole's radius. The
 * G-code holds the plastic the tap later removes, so the beads near the axis,
 * kept by the reader, lose the part of them inside the cut: each in pieces along
 * its path, the share of its width inside the radius (a wall's bead around the
 * hole lies across the radius) times the share of its height inside the cut's
 * z range. The removed pieces' mass moments (the same box beads as gcode_body.c
 * sums) are taken from the body's, about its centre of mass. */
#include "print/gcode_state.h"

#include <math.h>
#include <stdlib.h>

void tippe_gcode_beads_free(tippe_gcode_beads *beads)
{
    free(beads->bead);
    *beads = (tippe_gcode_beads){0};
}

static double clamp01(double x) { return x < 0 ? 0 : x > 1 ? 1 : x; }

/* The share of bead e's height (its box from the lower nozzle height less h up
 * to the higher) inside [lo, hi]. */
static double height_share(const tippe_gcode_near_bead *e, double lo, double hi)
{
    double top = e->z0 > e->z1 ? e->z0 : e->z1, bottom = (e->z0 < e->z1 ? e->z0 : e->z1) - e->h_mm;
    if (!(top > bottom))
        return top >= lo && top <= hi;
    double over = (hi < top ? hi : top) - (lo > bottom ? lo : bottom);
    return clamp01(over / (top - bottom));
}

/* Widens [*ta, *tb] (of t in [0, 1] along p0 + t (dx, dy)) to the stretch within
 * the cut's radius plus half the bead's width of its axis (a point: all of it). */
static void reach(const double p0[3], double dx, double dy, double lxy, const tippe_gcode_cut *c,
                  double w, double *ta, double *tb)
{
    double rr = c->radius_mm + w / 2, ox = p0[0] - c->axis_x_mm, oy = p0[1] - c->axis_y_mm;
    if (!(lxy > 0)) {
        if (ox * ox + oy * oy < rr * rr) {
            *ta = 0;
            *tb = 1;
        }
        return;
    }
    /* |o + t d|^2 = rr^2: t^2 L^2 + 2 t (o.d) + |o|^2 - rr^2 = 0 */
    double a = lxy * lxy, b = ox * dx + oy * dy, c0 = ox * ox + oy * oy - rr * rr;
    double disc = b * b - a * c0;
    if (!(disc > 0))
        return;
    double sq = sqrt(disc), t0 = (-b - sq) / a, t1 = (-b + sq) / a;
    t0 = t0 < 0 ? 0 : t0;
    t1 = t1 > 1 ? 1 : t1;
    if (t1 > t0) {
        *ta = t0 < *ta ? t0 : *ta;
        *tb = t1 > *tb ? t1 : *tb;
    }
}

int tippe_gcode_cut_body(tippe_gcode_body *body, const tippe_gcode_beads *beads,
                         const tippe_gcode_cut *cut, int n_cuts)
{
    if (n_cuts > TIPPE_GCODE_MAX_CUTS)
        n_cuts = TIPPE_GCODE_MAX_CUTS;
    double ax = 1e3 * (body->bbox_min[0] + body->bbox_max[0]) / 2;
    double ay = 1e3 * (body->bbox_min[1] + body->bbox_max[1]) / 2;
    for (int k = 0; k < n_cuts; k++) {
        double off = hypot(cut[k].axis_x_mm - ax, cut[k].axis_y_mm - ay);
        if (off + cut[k].radius_mm + 3 > beads->radius_mm + 1e-9)
            return -1;
    }
    /* about the body's centre of mass, mm and kg */
    double c[3] = {1e3 * body->com[0], 1e3 * body->com[1], 1e3 * body->com[2]};
    double rho = 1e-6 * body->density_g_cm3; /* kg/mm^3 */
    tippe_gcode_moments gone = {0};
    double hole[TIPPE_GCODE_MAX_CUTS];
    for (int k = 0; k < TIPPE_GCODE_MAX_CUTS; k++)
        hole[k] = INFINITY;
    double vol_cut = 0;
    for (size_t j = 0; j < beads->n; j++) {
        const tippe_gcode_near_bead *e = &beads->bead[j];
        double p0[3] = {e->x0, e->y0, e->z0}, p1[3] = {e->x1, e->y1, e->z1};
        double w = e->w_mm, h = e->h_mm, fz[TIPPE_GCODE_MAX_CUTS];
        int near = 0;
        for (int k = 0; k < n_cuts; k++) {
            fz[k] = height_share(e, cut[k].z_lo_mm, cut[k].z_hi_mm);
            if (!(fz[k] > 0))
                continue;
            double d = tippe_gcode_distance_xy(cut[k].axis_x_mm, cut[k].axis_y_mm, p0, p1);
            if (fz[k] > 0.5 && d < cut[k].radius_mm + 2 && d - w / 2 < hole[k])
                hole[k] = d - w / 2;
            near |= d < cut[k].radius_mm + w / 2;
        }
        if (!near)
            continue;
        double dx = p1[0] - p0[0], dy = p1[1] - p0[1], lxy = sqrt(dx * dx + dy * dy);
        /* only the stretch of the path within a cut's reach is cut: pieces there alone */
        double ta = 1, tb = 0;
        for (int k = 0; k < n_cuts; k++)
            if (fz[k] > 0)
                reach(p0, dx, dy, lxy, &cut[k], w, &ta, &tb);
        if (!(tb > ta))
            continue;
        int n = (int)ceil(lxy * (tb - ta) / TIPPE_GCODE_CUT_STEP_MM);
        n = n < 1 ? 1 : n > 100000 ? 100000 : n;
        double dm = e->volume_mm3 * rho, frac = (tb - ta) / n;
        for (int i = 0; i < n; i++) {
            double t0 = ta + i * frac, t1 = ta + (i + 1) * frac, tm = (t0 + t1) / 2;
            double x = p0[0] + tm * dx, y = p0[1] + tm * dy, share = 0;
            for (int k = 0; k < n_cuts; k++) {
                if (!(fz[k] > 0))
                    continue;
                double r = hypot(x - cut[k].axis_x_mm, y - cut[k].axis_y_mm);
                double fw = w > 0 ? clamp01((cut[k].radius_mm - (r - w / 2)) / w)
                                  : r < cut[k].radius_mm;
                if (fw * fz[k] > share)
                    share = fw * fz[k];
            }
            if (!(share > 0))
                continue;
            double u[3], v[3];
            for (int q = 0; q < 3; q++) {
                u[q] = p0[q] + t0 * (p1[q] - p0[q]) - c[q];
                v[q] = p0[q] + t1 * (p1[q] - p0[q]) - c[q];
            }
            u[2] -= h / 2; /* the box below the nozzle, as gcode_body.c lays it */
            v[2] -= h / 2;
            tippe_gcode_add_bead(&gone, u, v, share * dm * (t1 - t0), 1, h, w, dx, dy, lxy);
            vol_cut += share * e->volume_mm3 * (t1 - t0);
        }
    }
    for (int k = 0; k < TIPPE_GCODE_MAX_CUTS; k++)
        body->cut_hole_radius_mm[k] = k < n_cuts ? hole[k] : INFINITY;
    body->cut_volume_mm3 = vol_cut;
    body->cut_mass_kg = gone.m;
    if (!(gone.m > 0))
        return 0;
    /* the central second moments P = tr(I)/2 - I (mm^2 kg), less the cut's
     * about the old centre, then moved to the new centre */
    static const int qi[6] = {0, 1, 2, 0, 0, 1}, qj[6] = {0, 1, 2, 1, 2, 2};
    const double *I = body->inertia;
    double tr = (I[0] + I[1] + I[2]) / 2, P[6];
    P[0] = 1e6 * (tr - I[0]);
    P[1] = 1e6 * (tr - I[1]);
    P[2] = 1e6 * (tr - I[2]);
    P[3] = -1e6 * I[3]; /* Ixy = -sum m x y */
    P[4] = -1e6 * I[4];
    P[5] = -1e6 * I[5];
    double m = body->m - gone.m, dc[3];
    for (int i = 0; i < 3; i++)
        dc[i] = -gone.s[i] / m;
    for (int k = 0; k < 6; k++)
        P[k] -= gone.q[k] + m * dc[qi[k]] * dc[qj[k]];
    body->m = m;
    for (int i = 0; i < 3; i++)
        body->com[i] += 1e-3 * dc[i];
    body->inertia[0] = 1e-6 * (P[1] + P[2]);
    body->inertia[1] = 1e-6 * (P[0] + P[2]);
    body->inertia[2] = 1e-6 * (P[0] + P[1]);
    body->inertia[3] = -1e-6 * P[3];
    body->inertia[4] = -1e-6 * P[4];
    body->inertia[5] = -1e-6 * P[5];
    body->body_volume_mm3 -= vol_cut;
    return 0;
}
