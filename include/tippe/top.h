/* tippe/top.h: the one struct that crosses from geometry to physics.
 *
 * An eccentric sphere (paper section 3, Figure 4): mass m, sphere radius R,
 * eccentricity eps = distance from the geometric centre to the centre of mass
 * (0 <= eps < R; the centre of mass is below the centre when theta = 0),
 * A = transverse moment through the centre of mass, C = axial moment. SI units.
 * Theory and dynamics take only this (plus g and friction). */
#ifndef TIPPE_TOP_H
#define TIPPE_TOP_H

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
} tippe_top;

/* Gravity used wherever a user gives none (scenarios, classify, launches), m/s^2. */
#define TIPPE_DEFAULT_G_M_S2 9.81

static inline double tippe_top_A_over_C(const tippe_top *t) { return t->A / t->C; }
static inline double tippe_top_eps_over_R(const tippe_top *t) { return t->eps / t->R; }

#endif
