/* tippe/contact_patch.h: the contact of the sphere on the table as a small circular
 * patch that spins with the top (issue 27, the contact law).
 *
 * - Hertz: the patch radius a of a sphere pressed on a flat (Johnson 1985, eqs 4.22-4.23).
 * - Coulomb-Contensou friction: Coulomb's law integrated over the patch, which both
 *   slides (velocity v of the material point at its centre) and drills (spin omega_n
 *   about the table's normal). After normalising, the force and torque depend only on
 *   eps = |v| / (a |omega_n|) and on the pressure law (uniform, or Hertz's
 *   p ~ sqrt(1 - r^2/a^2)): |F| = mu N f(eps) against v, |M| = mu N a m(eps) against
 *   omega_n.
 *   * tippe_patch_reference: f and m by adaptive 2-D quadrature (GSL). Slow; a reference.
 *   * tippe_patch_friction: the cheap form for the right-hand side of an ODE: a rational
 *     approximant of the dissipation potential (docs/contact-patch.md), no allocation, no
 *     quadrature, one square root. Smooth except at (v, omega_n) = (0, 0).
 * - Sticking: the Leine-Glocker ellipse, and the exact limit curve of the cheap form.
 * - Rolling resistance: a resisting torque against the rolling angular velocity.
 *
 * Frame: the table's normal e3 points up into the body; v and the returned F are
 * 2-vectors in the table plane (e1, e2); omega_n and M are about e3. F and M act on the
 * body, at the patch centre. SI units. docs/contact-patch.md derives everything here and
 * gives the accuracy, the cost and the materials data. Depends on nothing in tippe but
 * tippe/error.h. */
#ifndef TIPPE_CONTACT_PATCH_H
#define TIPPE_CONTACT_PATCH_H

#include "tippe/error.h"

/* The pressure over the patch. Both integrate to N. */
typedef enum {
    TIPPE_PATCH_UNIFORM = 0, /* p = N / (pi a^2) */
    TIPPE_PATCH_HERTZ = 1    /* p = (3 N / (2 pi a^2)) sqrt(1 - r^2/a^2), Johnson sec. 4.2 */
} tippe_patch_pressure;

/* The exact limits of f and m (docs/contact-patch.md derives them):
 * f ~ c1 eps and m -> m0 as eps -> 0; f -> 1 and m ~ c2 / eps as eps -> inf.
 * Uniform: m0 = 2/3, c1 = 1, c2 = 1/4. Hertz: m0 = 3 pi/16, c1 = 3 pi/8, c2 = 1/5. */
typedef struct {
    double m0, c1, c2;
} tippe_patch_limits;

tippe_patch_limits tippe_patch_limits_of(tippe_patch_pressure p);
const char *tippe_patch_pressure_name(tippe_patch_pressure p); /* "uniform", "hertz" */
int tippe_patch_pressure_parse(const char *name);               /* the enum, or -1 */

/* ---- Hertz -------------------------------------------------------------- */

/* The contact modulus of two materials, 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2
 * (Johnson 1985, eq 4.22 with 4.23). E in Pa (> 0, finite), -1 < nu <= 0.5. */
int tippe_hertz_modulus(double E1, double nu1, double E2, double nu2, double *E_star,
                        tippe_error *err);

/* The patch radius of a sphere of radius R (m, > 0) on a flat under the normal force
 * N (N, >= 0): a = (3 N R / (4 E*))^(1/3) (Johnson 1985, eq 4.22). a grows as N^(1/3):
 * the right-hand side can scale a value computed once, a = a_ref cbrt(N / N_ref). */
int tippe_hertz_radius(double R, double N, double E_star, double *a, tippe_error *err);

/* ---- Coulomb-Contensou friction ------------------------------------------ */

typedef struct {
    double F[2];        /* N: friction force on the body, in the table plane */
    double M;           /* N m: drilling torque on the body, about e3 */
    double dissipation; /* W, >= 0: -(F.v + M omega_n), the power friction takes */
} tippe_patch_wrench;

/* The cheap form (for an ODE's right-hand side): mu_N = mu N (N, >= 0), a the patch
 * radius (m, >= 0), v the slip velocity of the body's material point at the patch
 * centre relative to the table (m/s), omega_n the body's spin relative to the table
 * about e3 (rad/s).
 * v_s (m/s, >= 0) regularises the one singular point: with v_s = 0 the law is the
 * approximant itself, smooth except at (v, omega_n) = (0, 0), where it returns a zero
 * wrench (the set-valued sticking point: see tippe_patch_load); with v_s > 0 it is
 * Lipschitz everywhere and, at a = 0, exactly the regularised Coulomb law
 * F = -mu N v / sqrt(|v|^2 + v_s^2) that src/dynamics.c uses now.
 * Limits (exact in floating point unless noted): a = 0 or omega_n = 0 gives point
 * Coulomb friction F = -mu N v/|v|, M = 0; v = 0 gives F = 0, M = -mu N a m0 sgn(omega_n)
 * (to rounding). No allocation, no library calls but one sqrt; thread-safe. */
void tippe_patch_friction(tippe_patch_pressure p, double mu_N, double a, double v_s,
                          const double v[2], double omega_n, tippe_patch_wrench *out);

/* The cheap form normalised: f and m at eps (>= 0; +inf gives f = 1, m = 0). */
void tippe_patch_normalised(tippe_patch_pressure p, double eps, double *f, double *m);

/* The reference: f and m at eps (>= 0, may be +inf) by nested adaptive quadrature (GSL
 * QAGS) of Coulomb's law over the patch in polar coordinates, to a relative 1e-10 or
 * better. Allocates GSL workspaces; milliseconds a call. TIPPE_EINPUT for a negative or
 * NaN eps, TIPPE_ECOMPUTE if GSL fails. */
int tippe_patch_reference(tippe_patch_pressure p, double eps, double *f, double *m,
                          tippe_error *err);

/* The small-slip limit: for |v| << a |omega_n| the force is viscous,
 * F = -mu N c1 v / (a |omega_n|), i.e. the paper's eq 3.12 Rf = -mu Rn V_Q with
 * mu = mu_c c1 / (a |omega_n|) (s/m), which this returns (+inf if a omega_n = 0). */
double tippe_patch_viscous_mu(tippe_patch_pressure p, double mu_c, double a, double omega_n);

/* ---- sticking ------------------------------------------------------------- */

/* While the patch sticks (v = 0 and omega_n = 0 together) the table supplies whatever
 * force F and torque M keep it stuck, if the pair lies in the set that sliding can
 * reach. These return the load factor lambda of a demanded (F, M): the pair sits on the
 * set's boundary when scaled by 1/lambda, so it sticks iff lambda <= 1.
 * Leine and Glocker's ellipse (Eur. J. Mech. A/Solids 22 (2003) 193):
 * lambda^2 = (|F|/(mu N))^2 + (M/(mu N a m0))^2. */
double tippe_patch_load_ellipse(tippe_patch_pressure p, double mu_N, double a,
                                const double F[2], double M);

/* The same against the limit curve (mu N f(eps), mu N a m(eps)) of the cheap form (by
 * bisection, ~60 evaluations; for events, not the hot path). If eps_exit is not NULL it
 * receives the eps of the boundary point hit: where the patch leaves a stuck state it
 * starts to slide with |v| / (a |omega_n|) = eps_exit, v against F and omega_n against M.
 * a = 0 reduces both to |F|/(mu N) (M must be 0: +inf otherwise); mu N = 0 holds only a
 * zero wrench (0, else +inf). */
double tippe_patch_load(tippe_patch_pressure p, double mu_N, double a, const double F[2],
                        double M, double *eps_exit);

/* ---- rolling resistance --------------------------------------------------- */

/* A resisting torque against the rolling angular velocity w_roll (rad/s, the part of
 * the body's angular velocity relative to the table that lies in the table plane):
 * M_roll = -N arm w_roll / sqrt(|w_roll|^2 + w_s^2), i.e. Coulomb-like with lever arm
 * `arm` (m; the rolling resistance coefficient is arm / R), regularised by w_s (rad/s,
 * >= 0; w_s = 0 gives M_roll = -N arm w_roll/|w_roll|, and 0 at w_roll = 0). Off by
 * default: arm = 0 gives no torque. Returns the dissipation -M_roll.w_roll >= 0 (W). */
double tippe_rolling_resistance(double N, double arm, double w_s, const double w_roll[2],
                                double M_roll[2]);

/* The lever arm of elastic hysteresis for a sphere: arm = (3/16) alpha a, alpha the
 * fraction of the elastic work lost per cycle (Johnson 1985, section 9.2, after Tabor
 * 1955). */
double tippe_rolling_arm_hysteresis(double alpha, double a);

#endif
