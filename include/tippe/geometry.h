/* tippe/geometry.h: mass properties of solids of revolution about the z axis.
 *
 * Every solid is described by four integrals over its region (SI units):
 *   m    = rho * \int dV          [kg]
 *   m_z  = rho * \int z dV        [kg m]
 *   m_zz = rho * \int z^2 dV      [kg m^2]
 *   m_rr = rho * \int r^2 dV      [kg m^2]   (r = distance from the z axis)
 * These add for parts, subtract for voids and shift exactly along z, so a
 * composite top is a sum of them. From the sum (tippe_moments_inertia):
 *   z_cm = m_z / m,  C = m_rr,  A_origin = m_rr / 2 + m_zz,  A = A_origin - m z_cm^2.
 * The constructors below return the moments at unit density (rho = 1), i.e.
 * volume moments; tippe_moments_scale() applies a density in kg/m^3.
 * Lengths are in metres. z is measured from the centre of the sphere. */
#ifndef TIPPE_GEOMETRY_H
#define TIPPE_GEOMETRY_H

typedef struct {
    double m, m_z, m_zz, m_rr;
} tippe_moments;

/* The solids (unit density). ball_radius <= 0 or INFINITY means "not clipped";
 * otherwise the solid is intersected with the ball of that radius centred at
 * the origin (a hole drilled through a sphere, a rod that spans a shell, a
 * band inside a shell). A zero or negative size (radius, thickness, height,
 * semi-axis, r_out <= r_in) gives zero moments, never NaN; a negative r_in is a
 * plain cylinder, a shell thicker than its radius is the ball. All moments are
 * exact integrals (closed forms) up to rounding, thin shells and walls included:
 * relative error ~1e-15. */
tippe_moments tippe_ball(double radius, double z_centre);
tippe_moments tippe_shell(double outer_radius, double thickness, double z_centre);
/* Annular cylinder r_in <= r <= r_out, |z - z_centre| <= height/2; r_in = 0 is a
 * plain cylinder. */
tippe_moments tippe_tube(double r_in, double r_out, double height, double z_centre,
                         double ball_radius);
/* Solid torus of elliptical cross-section: ((r - centre_radius)/radial_semi)^2 +
 * ((z - z_centre)/axial_semi)^2 <= 1, normally with radial_semi <= centre_radius
 * (if larger, the cross-section reaches past the axis and the solid is the region
 * it sweeps, counted once). When the ball cuts it, the heights where the ball's
 * surface crosses the torus are found by GSL root finding and the integrals
 * between them are closed forms; reentrant, NaN only if GSL cannot allocate. */
tippe_moments tippe_torus(double centre_radius, double radial_semi, double axial_semi,
                          double z_centre, double ball_radius);

tippe_moments tippe_moments_add(tippe_moments a, tippe_moments b);
tippe_moments tippe_moments_sub(tippe_moments a, tippe_moments b);
tippe_moments tippe_moments_scale(tippe_moments a, double density_kg_m3);
/* The same solid moved by dz along the axis (parallel-axis theorem). */
tippe_moments tippe_moments_shift(tippe_moments a, double dz);

/* A = m_rr/2 + m_zz - m z_cm^2 is formed from sums about the origin: it loses about
 * log10(z_cm^2 / var(z)) digits, little for a top built around its sphere's centre.
 * m = 0 gives z_cm = 0. */
typedef struct {
    double m;     /* kg */
    double z_cm;  /* m, signed: centre of mass above (+) or below (-) the origin */
    double A;     /* kg m^2, about a transverse axis through the centre of mass */
    double C;     /* kg m^2, about the symmetry axis */
} tippe_inertia;

tippe_inertia tippe_moments_inertia(tippe_moments a);

#endif
