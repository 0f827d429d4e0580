/* tippe/top.h: the top as physics sees it: the one struct that crosses from a design
 * to the theory and the dynamics (tippe_top), and the gravity used where none is given.
 * A header alone (no sources): design.h builds a tippe_top from a design file, theory.h
 * and physics.h take it, so that neither of those knows a design file. */
#ifndef TIPPE_TOP_H
#define TIPPE_TOP_H

/* Top: the one struct that crosses from geometry to physics.
 *
 * An eccentric sphere (paper section 3, Figure 4): mass m, sphere radius R,
 * eccentricity eps = distance from the geometric centre to the centre of mass
 * (0 <= eps < R; the centre of mass is below the centre when theta = 0),
 * A = transverse moment through the centre of mass, C = axial moment. SI units.
 * Theory and dynamics take only this (plus g and friction). */
typedef struct {
    double m;   /* kg */
    double R;   /* m */
    double eps; /* m, >= 0 */
    double A;   /* kg m^2 */
    double C;   /* kg m^2 */
    /* Which side of the sphere's centre the centre of mass lies on, along the
     * design's +z axis: +1 above, -1 below, 0 at the centre. That side is the one
     * that rests on the table at theta = 0. Informational only. */
    int com_side;
    /* The outline the table meets where it is not the sphere (issue 35): the
     * half-angle of the flat cut at the pole down at theta = 0 ([0]) and at the
     * other pole ([1]) by a hole's opening (tippe_design_polar_caps), rad; 0 where
     * the sphere is whole. The dynamics rolls the sphere cut flat there (its rim
     * radius R sin(half-angle)); the theory of the paper, the sphere. */
    double rim_half_angle_rad[2];
} tippe_top;

/* Gravity used wherever a user gives none (scenarios, classify, launches), m/s^2. */
#define TIPPE_DEFAULT_G_M_S2 9.81

#endif
