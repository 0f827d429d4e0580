/* geometry.c: volume moments of solids of revolution about the z axis.
 *
 * A solid of revolution cut at height z is an annulus s_in(z) <= r <= s_out(z), so
 *   \int dV      = \int pi (s_out^2 - s_in^2) dz,
 *   \int r^2 dV  = \int (pi/2) (s_out^4 - s_in^4) dz,
 * and the z and z^2 moments carry an extra z or z^2 in the slice integrand.
 * For balls, shells, cylinders and their intersections the slice terms are
 * polynomials in z; for tori they are polynomials plus sqrt(1 - y^2) times a
 * polynomial, with y the scaled height inside the torus. Every moment here is
 * the exact integral of such terms (no adaptive quadrature); rounding is the
 * only error. Differences of nearly equal powers are always taken in factored
 * form so that thin shells, thin walls and tiny holes keep full relative
 * accuracy.
 *
 * The inertia that comes out (tippe_moments_inertia) is the paper's A and C:
 * the inertia tensor about the centre of mass is diag(A, A, C) for an axially
 * symmetric body (section 3, "I_x = I_y := A and I_z := C"). */
#include "tippe/print.h"
#include "tippe/base.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_poly.h>
#include <gsl/gsl_roots.h>

static const tippe_moments zero_moments = {0.0, 0.0, 0.0, 0.0};

/* "ball_radius <= 0 or INFINITY means not clipped" (NaN too: it cannot clip). */
static int is_clipping(double ball_radius)
{
    return ball_radius > 0.0 && isfinite(ball_radius);
}

/* Three-point Gauss-Legendre on [0, 1]. It integrates polynomials up to degree 5
 * exactly, and every polynomial slice integrand below has degree <= 4, so using
 * it is the closed-form integral; it is preferred to an expanded antiderivative
 * because the integrand can be evaluated at the nodes in factored form, which
 * keeps relative accuracy where the slice is a thin cap near a pole. */
static const double gl3_t[3] = {0.11270166537925831148, 0.5, 0.88729833462074168852};
static const double gl3_w[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};

/* ---------------------------------------------------------------- ball, shell */

tippe_moments tippe_ball(double radius, double z_centre)
{
    if (!(radius > 0.0))
        return zero_moments;
    double v = 4.0 / 3.0 * M_PI * radius * radius * radius;
    tippe_moments s;
    s.m = v;
    s.m_z = v * z_centre;
    /* about its centre \int z^2 dV = a^2 V / 5 and \int r^2 dV = 2 a^2 V / 5 */
    s.m_zz = v * (z_centre * z_centre + radius * radius / 5.0);
    s.m_rr = 0.4 * radius * radius * v;
    return s;
}

tippe_moments tippe_shell(double outer_radius, double thickness, double z_centre)
{
    double a = outer_radius, t = thickness;
    if (!(a > 0.0) || !(t > 0.0))
        return zero_moments;
    if (t >= a)
        return tippe_ball(a, z_centre);
    double b = a - t;
    /* a^3 - b^3 and a^5 - b^5 factored so that a shell of thickness 1e-9 a does not
     * lose nine digits to cancellation. */
    double d3 = t * (a * a + a * b + b * b);
    double d5 = t * (a * a * a * a + a * a * a * b + a * a * b * b + a * b * b * b + b * b * b * b);
    double v = 4.0 / 3.0 * M_PI * d3;
    tippe_moments s;
    s.m = v;
    s.m_z = v * z_centre;
    s.m_zz = 4.0 / 15.0 * M_PI * d5 + v * z_centre * z_centre;
    s.m_rr = 8.0 / 15.0 * M_PI * d5;
    return s;
}

/* ----------------------------------------------------------------------- tube */

/* Annulus r_in..r_out (area_over_pi = r_out^2 - r_in^2, sum_sq = r_out^2 + r_in^2)
 * over u <= z <= v. */
static tippe_moments cylinder_piece(double area_over_pi, double sum_sq, double u, double v)
{
    if (!(v > u))
        return zero_moments;
    double h = v - u;
    double area = M_PI * area_over_pi;
    tippe_moments s;
    s.m = area * h;
    s.m_z = area * h * (u + v) / 2.0;
    s.m_zz = area * h * (u * u + u * v + v * v) / 3.0;
    s.m_rr = s.m * sum_sq / 2.0;
    return s;
}

/* The part of the tube where the ball is the outer wall: r_in <= r <= sqrt(a^2 - z^2)
 * over u <= z <= v, with zi = sqrt(a^2 - r_in^2) the height where the ball meets the
 * inner wall. upper: 0 <= u < v <= zi; otherwise -zi <= u < v <= 0. The slice area
 * is pi (zi - |z|)(zi + |z|), never a^2 - z^2 - r_in^2 (which cancels near the pole),
 * and the depth zi - |z| is (zi - v) or (u + zi) plus an offset along the interval,
 * not a difference of two nearly equal heights. */
static tippe_moments cap_piece(double u, double v, double zi, double r_in2, int upper)
{
    tippe_moments s = zero_moments;
    if (!(v > u))
        return s;
    double h = v - u;
    for (int k = 0; k < 3; k++) {
        double z = u + h * gl3_t[k];
        double d = upper ? (zi - v) + h * (1.0 - gl3_t[k]) : (u + zi) + h * gl3_t[k];
        double e = upper ? zi + z : zi - z;
        double de = d * e; /* s_out^2 - s_in^2 */
        double wk = gl3_w[k] * h * M_PI;
        s.m += wk * de;
        s.m_z += wk * de * z;
        s.m_zz += wk * de * z * z;
        /* s_out^2 + s_in^2 = (a^2 - z^2) + r_in^2 = de + 2 r_in^2 */
        s.m_rr += 0.5 * wk * de * (de + 2.0 * r_in2);
    }
    return s;
}

tippe_moments tippe_tube(double r_in, double r_out, double height, double z_centre,
                         double ball_radius)
{
    if (!(r_in > 0.0))
        r_in = 0.0; /* a negative inner radius means a plain cylinder */
    if (!(r_out > r_in) || !(height > 0.0))
        return zero_moments;
    double area_over_pi = (r_out - r_in) * (r_out + r_in); /* factored: thin walls */
    double sum_sq = r_out * r_out + r_in * r_in;
    double z1 = z_centre - height / 2.0, z2 = z_centre + height / 2.0;
    if (!is_clipping(ball_radius))
        return cylinder_piece(area_over_pi, sum_sq, z1, z2);

    double a = ball_radius;
    if (r_in >= a)
        return zero_moments;
    double zi = sqrt((a - r_in) * (a + r_in));                   /* ball meets inner wall */
    double zo = r_out < a ? sqrt((a - r_out) * (a + r_out)) : 0; /* ball meets outer wall */
    tippe_moments s = cylinder_piece(area_over_pi, sum_sq, fmax(z1, -zo), fmin(z2, zo));
    s = tippe_moments_add(s, cap_piece(fmax(z1, zo), fmin(z2, zi), zi, r_in * r_in, 1));
    s = tippe_moments_add(s, cap_piece(fmax(z1, -zi), fmin(z2, -zo), zi, r_in * r_in, 0));
    return s;
}

/* ---------------------------------------------------------------------- torus */

/* Unclipped, cross-section not reaching the axis: (r, z) = (Rc + p x, z0 + q y) over
 * the unit disk, dV = 2 pi r p q dx dy (Pappus), with \int x^2 = \int y^2 = pi/4. */
static tippe_moments torus_closed(double Rc, double p, double q, double z0)
{
    double v = 2.0 * M_PI * M_PI * Rc * p * q;
    tippe_moments s;
    s.m = v;
    s.m_z = v * z0;
    s.m_zz = v * (z0 * z0 + q * q / 4.0);
    s.m_rr = v * (Rc * Rc + 0.75 * p * p);
    return s;
}

/* The clipped (or axis-crossing) torus is cut in slices by y = sin(phi) in [-1, 1],
 * z = z0 + q y, w = cos(phi) = sqrt(1 - y^2); the torus slice is Rc - p w <= r <= Rc + p w.
 * Between breakpoints each wall of the slice is one of these edges. */
typedef enum { EDGE_AXIS, EDGE_TORUS_IN, EDGE_TORUS_OUT, EDGE_BALL } torus_edge;

typedef struct {
    double Rc, p, q, z0, a; /* a = 0: not clipped */
} torus_geom;

/* Polynomial (in y) parts of s^2 and s^4 on an edge. The torus edges also carry
 * w-terms: s^2 gets beta w and s^4 gets 2 beta w (Rc^2 + p^2 w^2), beta = +-2 Rc p. */
static void edge_poly(const torus_geom *g, torus_edge e, double y, double *s2, double *s4)
{
    switch (e) {
    case EDGE_TORUS_IN:
    case EDGE_TORUS_OUT: {
        double R2 = g->Rc * g->Rc;
        double pw2 = g->p * g->p * (1.0 - y) * (1.0 + y);
        *s2 = R2 + pw2;
        *s4 = R2 * R2 + 6.0 * R2 * pw2 + pw2 * pw2;
        break;
    }
    case EDGE_BALL: {
        double z = g->z0 + g->q * y;
        double b2 = (g->a - z) * (g->a + z);
        *s2 = b2;
        *s4 = b2 * b2;
        break;
    }
    case EDGE_AXIS:
    default:
        *s2 = *s4 = 0.0;
        break;
    }
}

static double edge_beta(const torus_geom *g, torus_edge e)
{
    if (e == EDGE_TORUS_OUT)
        return 2.0 * g->Rc * g->p;
    if (e == EDGE_TORUS_IN)
        return -2.0 * g->Rc * g->p;
    return 0.0;
}

/* Moments of the slices phi1 <= phi <= phi2 with outer wall eo and inner wall ei.
 * Polynomial parts (degree <= 4 in y) by the exact 3-point rule; the w-parts use
 * I_k = \int y^k sqrt(1 - y^2) dy, whose antiderivatives in phi are
 * F0 = (phi + sin phi cos phi)/2, F1 = -cos^3 phi / 3, F2 = phi/8 - sin(4 phi)/32,
 * with their differences written as products (sin A - sin B = 2 cos sin). */
static tippe_moments torus_piece(const torus_geom *g, double phi1, double phi2, torus_edge eo,
                                 torus_edge ei)
{
    double dphi = phi2 - phi1, sphi = phi1 + phi2;
    double y1 = sin(phi1);
    double dy = 2.0 * cos(sphi / 2.0) * sin(dphi / 2.0);
    double pm = 0, pz = 0, pzz = 0, prr = 0;
    for (int k = 0; k < 3; k++) {
        double y = y1 + dy * gl3_t[k];
        double so2, so4, si2, si4;
        edge_poly(g, eo, y, &so2, &so4);
        edge_poly(g, ei, y, &si2, &si4);
        double z = g->z0 + g->q * y;
        double d2 = so2 - si2, wk = gl3_w[k] * dy;
        pm += wk * d2;
        pz += wk * d2 * z;
        pzz += wk * d2 * z * z;
        prr += wk * (so4 - si4);
    }
    double c1 = cos(phi1), c2 = cos(phi2);
    double I0 = (dphi + cos(sphi) * sin(dphi)) / 2.0;
    double I1 = 2.0 * sin(sphi / 2.0) * sin(dphi / 2.0) * (c1 * c1 + c1 * c2 + c2 * c2) / 3.0;
    double I2 = dphi / 8.0 - cos(2.0 * sphi) * sin(2.0 * dphi) / 16.0;
    double db = edge_beta(g, eo) - edge_beta(g, ei);
    double z0 = g->z0, q = g->q, p2 = g->p * g->p;
    tippe_moments s;
    s.m = M_PI * q * (pm + db * I0);
    s.m_z = M_PI * q * (pz + db * (z0 * I0 + q * I1));
    s.m_zz = M_PI * q * (pzz + db * (z0 * z0 * I0 + 2.0 * z0 * q * I1 + q * q * I2));
    s.m_rr = 0.5 * M_PI * q * (prr + 2.0 * db * ((g->Rc * g->Rc + p2) * I0 - p2 * I2));
    return s;
}

/* Squared distance from the origin minus a^2, of the outer (side = +1) or inner
 * (side = -1) edge point of the slice at angle phi: the ball crossings are its roots. */
typedef struct {
    const torus_geom *g;
    double side;
} edge_fn_params;

static double edge_excess(double phi, void *params)
{
    const edge_fn_params *ep = params;
    const torus_geom *g = ep->g;
    double r = g->Rc + ep->side * g->p * cos(phi);
    double z = g->z0 + g->q * sin(phi);
    return r * r + z * z - g->a * g->a;
}

static int cmp_double(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

#define TORUS_GRID 24
#define TORUS_MAX_SAMPLES (TORUS_GRID + 1 + 8 + 8)
#define TORUS_MAX_BREAKS (6 + 2 * TORUS_MAX_SAMPLES)

/* Starting points for the crossing search: the real parts of the roots in y of the
 * quartic (Q^2 - 4 Rc^2 p^2 (1 - y^2)) = 0, Q = a^2 - z^2 - Rc^2 - p^2 (1 - y^2), which
 * holds at every crossing of the ball with either wall (squaring r = Rc +- p w).
 * Lengths are scaled by a so that the coefficients are O(1). Returns how many
 * candidates (as phi) were written; 0 if the solver fails (the grid still works). */
static int crossing_candidates(const torus_geom *g, double *phi_out)
{
    double Rc = g->Rc / g->a, p = g->p / g->a, q = g->q / g->a, z0 = g->z0 / g->a;
    double k0 = 1.0 - z0 * z0 - Rc * Rc - p * p, k1 = -2.0 * z0 * q, k2 = (p - q) * (p + q);
    double c[5] = {k0 * k0 - 4.0 * Rc * Rc * p * p, 2.0 * k0 * k1,
                   k1 * k1 + 2.0 * k0 * k2 + 4.0 * Rc * Rc * p * p, 2.0 * k1 * k2, k2 * k2};
    int n = 5;
    while (n > 1 && c[n - 1] == 0.0)
        n--;
    double re[4];
    int nre = 0;
    if (n == 2) {
        re[nre++] = -c[0] / c[1];
    } else if (n > 2) {
        double zr[8];
        gsl_poly_complex_workspace *ws = gsl_poly_complex_workspace_alloc((size_t)n);
        if (ws == NULL)
            return 0;
        int status = gsl_poly_complex_solve(c, (size_t)n, ws, zr);
        gsl_poly_complex_workspace_free(ws);
        if (status != GSL_SUCCESS)
            return 0;
        for (int i = 0; i < n - 1; i++)
            re[nre++] = zr[2 * i];
    }
    int m = 0;
    for (int i = 0; i < nre; i++)
        if (fabs(re[i]) <= 1.0 + 1e-8)
            phi_out[m++] = asin(fmax(-1.0, fmin(1.0, re[i])));
    return m;
}

/* Root of edge_excess in (lo, hi), where it changes sign. Brent to a few ulps of phi;
 * if GSL fails the bracket's midpoint is used, which costs only second order in the
 * bracket width because the slice walls agree at a crossing. */
static double crossing_root(gsl_root_fsolver *solver, edge_fn_params *ep, double lo, double hi)
{
    gsl_function f = {edge_excess, ep};
    if (gsl_root_fsolver_set(solver, &f, lo, hi) != GSL_SUCCESS)
        return 0.5 * (lo + hi);
    for (int iter = 0; iter < 200; iter++) {
        if (gsl_root_fsolver_iterate(solver) != GSL_SUCCESS)
            break;
        lo = gsl_root_fsolver_x_lower(solver);
        hi = gsl_root_fsolver_x_upper(solver);
        if (gsl_root_test_interval(lo, hi, 4.0 * DBL_EPSILON, 0.0) == GSL_SUCCESS)
            break;
    }
    return gsl_root_fsolver_root(solver);
}

/* Which walls bound the slice at angle phi (returns 0 if the slice is empty). */
static int classify_slice(const torus_geom *g, double phi, torus_edge *eo, torus_edge *ei)
{
    double w = cos(phi), z = g->z0 + g->q * sin(phi);
    double ro = g->Rc + g->p * w, ri = g->Rc - g->p * w;
    /* r_in < 0: the cross-section reaches past the axis and the swept slice is
     * 0 <= r <= Rc + p w (the mirrored part lies inside it). */
    *ei = ri > 0.0 ? EDGE_TORUS_IN : EDGE_AXIS;
    *eo = EDGE_TORUS_OUT;
    if (g->a > 0.0) {
        double rmin = ri > 0.0 ? ri : 0.0;
        if (rmin * rmin + z * z >= g->a * g->a)
            return 0;
        if (ro * ro + z * z > g->a * g->a)
            *eo = EDGE_BALL;
    }
    return 1;
}

/* Moments of the torus clipped to the ball (or reaching past the axis): exact
 * integrals between breakpoints in phi; the breakpoints (ball crossings) are found
 * by Brent's method. Crossings that the search could miss are closer than ~1e-8 rad
 * (a near-tangency), where the slice the ball cuts off is ~1e-24 of the volume.
 * Conditioning: where the ball is a wall, the polynomial and w-terms are each of
 * the size of the whole torus slice, so the relative error is ~1e-16 times (torus
 * volume / volume kept): ~1e-15 for a band in a shell, 2e-12 seen (against 30-digit
 * quadrature) when the ball keeps only 1e-4 of the torus.
 * Returns NaN moments only if GSL cannot allocate its solver. */
static tippe_moments torus_piecewise(const torus_geom *g)
{
    double brk[TORUS_MAX_BREAKS];
    int nb = 0;
    brk[nb++] = -M_PI_2;
    brk[nb++] = M_PI_2;
    if (g->p > g->Rc) { /* where the inner wall reaches the axis: Rc = p w */
        double phi_axis = acos(g->Rc / g->p);
        brk[nb++] = -phi_axis;
        brk[nb++] = phi_axis;
    }
    if (g->a > 0.0) {
        /* the poles of the ball: where the slice through the axis ends */
        for (int side = -1; side <= 1; side += 2) {
            double y_pole = (side * g->a - g->z0) / g->q;
            if (fabs(y_pole) < 1.0)
                brk[nb++] = asin(y_pole);
        }
        double samp[TORUS_MAX_SAMPLES], cand[4];
        int ns = 0;
        for (int i = 0; i <= TORUS_GRID; i++)
            samp[ns++] = -M_PI_2 + M_PI * i / TORUS_GRID;
        int nc = crossing_candidates(g, cand);
        qsort(cand, (size_t)nc, sizeof cand[0], cmp_double);
        for (int i = 0; i < nc; i++) {
            samp[ns++] = cand[i];
            /* A near-double root may come back as two approximations that both miss
             * the short interval between the true roots; their midpoint lies in it. */
            if (i + 1 < nc)
                samp[ns++] = 0.5 * (cand[i] + cand[i + 1]);
        }
        qsort(samp, (size_t)ns, sizeof samp[0], cmp_double);

        gsl_root_fsolver *solver = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
        if (solver == NULL) {
            tippe_moments bad = {NAN, NAN, NAN, NAN};
            return bad;
        }
        for (int side = -1; side <= 1; side += 2) {
            edge_fn_params ep = {g, (double)side};
            double prev = edge_excess(samp[0], &ep);
            for (int i = 0; i + 1 < ns; i++) {
                double next = edge_excess(samp[i + 1], &ep);
                if (prev == 0.0)
                    brk[nb++] = samp[i];
                else if ((prev < 0.0 && next > 0.0) || (prev > 0.0 && next < 0.0))
                    brk[nb++] = crossing_root(solver, &ep, samp[i], samp[i + 1]);
                prev = next;
            }
        }
        gsl_root_fsolver_free(solver);
    }
    qsort(brk, (size_t)nb, sizeof brk[0], cmp_double);

    tippe_moments s = zero_moments;
    for (int i = 0; i + 1 < nb; i++) {
        double lo = brk[i], hi = brk[i + 1];
        torus_edge eo, ei;
        if (!(hi > lo) || !classify_slice(g, 0.5 * (lo + hi), &eo, &ei))
            continue;
        s = tippe_moments_add(s, torus_piece(g, lo, hi, eo, ei));
    }
    return s;
}

tippe_moments tippe_torus(double centre_radius, double radial_semi, double axial_semi,
                          double z_centre, double ball_radius)
{
    double Rc = centre_radius, p = radial_semi, q = axial_semi;
    if (!(Rc > 0.0) || !(p > 0.0) || !(q > 0.0))
        return zero_moments;
    int clip = is_clipping(ball_radius);
    /* The bounding box's far corner inside the ball means nothing is cut off. */
    int inside = !clip || hypot(Rc + p, fabs(z_centre) + q) <= ball_radius;
    if (p <= Rc && inside)
        return torus_closed(Rc, p, q, z_centre);
    tippe_gsl_errors_as_codes();
    torus_geom g = {Rc, p, q, z_centre, inside ? 0.0 : ball_radius};
    return torus_piecewise(&g);
}

/* ---------------------------------------------------------------- composition */

tippe_moments tippe_moments_add(tippe_moments a, tippe_moments b)
{
    tippe_moments s = {a.m + b.m, a.m_z + b.m_z, a.m_zz + b.m_zz, a.m_rr + b.m_rr};
    return s;
}

tippe_moments tippe_moments_sub(tippe_moments a, tippe_moments b)
{
    tippe_moments s = {a.m - b.m, a.m_z - b.m_z, a.m_zz - b.m_zz, a.m_rr - b.m_rr};
    return s;
}

tippe_moments tippe_moments_scale(tippe_moments a, double density_kg_m3)
{
    tippe_moments s = {a.m * density_kg_m3, a.m_z * density_kg_m3, a.m_zz * density_kg_m3,
                       a.m_rr * density_kg_m3};
    return s;
}

tippe_moments tippe_moments_shift(tippe_moments a, double dz)
{
    /* (z + dz)^2 = z^2 + 2 z dz + dz^2; r is unchanged */
    tippe_moments s = {a.m, a.m_z + a.m * dz, a.m_zz + 2.0 * dz * a.m_z + dz * dz * a.m, a.m_rr};
    return s;
}

tippe_inertia tippe_moments_inertia(tippe_moments a)
{
    tippe_inertia in;
    in.m = a.m;
    in.C = a.m_rr;
    if (a.m != 0.0) {
        in.z_cm = a.m_z / a.m;
        /* Parallel axis: A = m_rr/2 + (m_zz - m z_cm^2). The bracket is a difference
         * of sums already formed about the origin, so it loses about
         * log10(z_cm^2 / (m_zz/m - z_cm^2)) digits; for a top assembled around the
         * sphere centre z_cm <= R and the loss is at most a digit or two. */
        in.A = a.m_rr / 2.0 + (a.m_zz - a.m_z * in.z_cm);
    } else {
        in.z_cm = 0.0;
        in.A = a.m_rr / 2.0 + a.m_zz;
    }
    return in;
}
