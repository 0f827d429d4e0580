/* The contact patch: Hertz radius, Coulomb-Contensou friction (cheap form and quadrature
 * reference), sticking load, rolling resistance. docs/contact-patch.md derives every
 * formula; equation numbers "Johnson" are K.L. Johnson, Contact Mechanics (CUP 1985). */
#include "physics/contact_patch_law.h"
#include "tippe/physics.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- the laws --------------------------------------------------------------------- */

static const patch_law *law_of(tippe_contact_patch_pressure p)
{
    return &tippe_patch_laws[p == TIPPE_CONTACT_PATCH_HERTZ ? 1 : 0];
}

tippe_contact_patch_limits tippe_contact_patch_limits_of(tippe_contact_patch_pressure p)
{
    const patch_law *L = law_of(p);
    tippe_contact_patch_limits l = {L->m0, L->c1, L->c2};
    return l;
}

const char *tippe_contact_patch_pressure_name(tippe_contact_patch_pressure p) { return law_of(p)->name; }

int tippe_contact_patch_pressure_parse(const char *name)
{
    if (!strcmp(name, "uniform"))
        return TIPPE_CONTACT_PATCH_UNIFORM;
    if (!strcmp(name, "hertz"))
        return TIPPE_CONTACT_PATCH_HERTZ;
    return -1;
}

/* ---- Hertz --------------------------------------------------------------------------- */

static int check_material(double E, double nu, const char *which, tippe_error *err)
{
    if (!(E > 0.0) || !isfinite(E))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "%s Young's modulus must be positive and finite (Pa), got %g",
                               which, E);
    if (!(nu > -1.0 && nu <= 0.5))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "%s Poisson ratio must lie in (-1, 0.5], got %g", which, nu);
    return TIPPE_OK;
}

int tippe_contact_hertz_modulus(double E1, double nu1, double E2, double nu2, double *E_star,
                        tippe_error *err)
{
    int rc = check_material(E1, nu1, "first material's", err);
    if (rc)
        return rc;
    if ((rc = check_material(E2, nu2, "second material's", err)))
        return rc;
    /* Johnson eq 4.22/4.23: 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2. */
    const double inv = (1.0 - nu1 * nu1) / E1 + (1.0 - nu2 * nu2) / E2;
    if (!(inv > 0.0))
        return tippe_error_set(err, TIPPE_EINPUT, "contact modulus out of range: 1/E* = %g",
                               inv);
    *E_star = 1.0 / inv;
    return TIPPE_OK;
}

int tippe_contact_hertz_radius(double R, double N, double E_star, double *a, tippe_error *err)
{
    if (!(R > 0.0) || !isfinite(R))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "sphere radius must be positive and finite (m), got %g", R);
    if (!(N >= 0.0) || !isfinite(N))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "normal force must be >= 0 and finite (N), got %g", N);
    if (!(E_star > 0.0) || !isfinite(E_star))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "contact modulus E* must be positive and finite (Pa), got %g",
                               E_star);
    *a = cbrt(3.0 * N * R / (4.0 * E_star)); /* Johnson eq 4.22: a^3 = 3 N R / (4 E*) */
    return TIPPE_OK;
}

/* ---- the cheap form ------------------------------------------------------------------ */

void tippe_contact_patch_friction(tippe_contact_patch_pressure p, double mu_N, double a, double v_s,
                          const double v[2], double omega_n, tippe_contact_patch_wrench *out)
{
    patch_friction(law_of(p), mu_N, a, v_s, v, omega_n, out); /* contact_patch_law.h */
}

void tippe_contact_patch_normalised(tippe_contact_patch_pressure p, double eps, double *f, double *m)
{
    /* V = eps^2, W = 1, T = 1 + eps^2, written so that eps = 0 and eps = inf are exact. */
    double x, y, rx, ry; /* x = V/T, y = W/T, rx = sqrt(x), ry = sqrt(y) */
    if (eps <= 1.0) {
        const double h = sqrt(1.0 + eps * eps);
        rx = eps / h;
        ry = 1.0 / h;
    } else {
        const double e = 1.0 / eps, h = sqrt(1.0 + e * e);
        rx = 1.0 / h;
        ry = e / h;
    }
    x = rx * rx;
    y = ry * ry;
    double s, sV, sW;
    patch_potential(law_of(p), x, y, &s, &sV, &sW);
    const double rs = sqrt(s);
    *f = rx * sV / rs; /* |v| S_V / sqrt(S) */
    *m = ry * sW / rs; /* a |omega_n| S_W / sqrt(S) */
}

double tippe_contact_patch_viscous_mu(tippe_contact_patch_pressure p, double mu_c, double a, double omega_n)
{
    /* F -> -mu N c1 v / (a |omega_n|) as eps -> 0; eq 3.12 writes Rf = -mu Rn V_Q. */
    return mu_c * law_of(p)->c1 / (a * fabs(omega_n));
}

/* ---- the reference ------------------------------------------------------------------- */

/* Normalised (a = 1, omega_n = 1, v = eps e1): a point r (cos t, sin t) of the patch
 * slips at (eps - r sin t, r cos t), of length D; Coulomb's law gives it the traction
 * -mu p (slip)/D. f is the e1 part of the total over mu N, m its moment about e3 over
 * mu N a. The integrand is even under t -> pi - t, so t runs over [-pi/2, pi/2] (twice).
 * The odd parts -sin t (of f) and -r sin t (of m) integrate to 0 there and are added
 * back in closed form, which removes the cancellation at small eps (for f) and large eps
 * (for m):
 *   (eps - r sin t)/D + sin t = eps (1 + sin t (eps - 2 r sin t)/(D + r)) / D,
 *   (r^2 - eps r sin t)/D + r sin t = r^2 (1 + sin t (r - 2 eps sin t)/(D + eps)) / D. */
typedef struct {
    int hertz, moment;
    double eps, r;
    gsl_integration_workspace *inner;
    int status;
} ref_ctx;

static double ref_inner(double t, void *par)
{
    const ref_ctx *c = par;
    const double st = sin(t), r = c->r, e = c->eps;
    const double D = sqrt(e * e - 2.0 * e * r * st + r * r);
    if (c->moment)
        return r * r * (1.0 + st * (r - 2.0 * e * st) / (D + e)) / D;
    return e * (1.0 + st * (e - 2.0 * r * st) / (D + r)) / D;
}

static double ref_outer(double r, void *par)
{
    ref_ctx *c = par;
    c->r = r;
    gsl_function F = {ref_inner, c};
    double val, abserr;
    int rc = gsl_integration_qags(&F, -PI / 2, PI / 2, 0.0, 1e-12, 1000, c->inner, &val,
                                  &abserr);
    if (rc && rc != GSL_EROUND && !c->status)
        c->status = rc;
    /* Pressure over N / a^2: uniform 1/pi, Hertz 3 sqrt(1 - r^2) / (2 pi) (Johnson
     * section 4.2, with N = (2/3) p0 pi a^2); the factor 2 counts both halves of the circle. */
    const double pr = c->hertz ? 1.5 * sqrt(fmax(0.0, 1.0 - r * r)) / PI : 1.0 / PI;
    return 2.0 * r * pr * val;
}

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static int ref_integral(ref_ctx *c, gsl_integration_workspace *outer, double *out)
{
    gsl_function F = {ref_outer, c};
    /* The integrand varies on the scale |r - eps| around r = eps (a kink there, and a log
     * singularity of the inner integral): cut [0, 1] at eps and at points geometrically
     * spaced away from it, and, for eps just above 1, towards r = 1. One QAGS over
     * [eps, 1] misjudged its error at eps = 1e-6 (f off by 1.5e-7 relative). */
    double cut[64];
    int n = 0;
    const double e = c->eps;
    cut[n++] = 0.0;
    cut[n++] = 1.0;
    if (e < 1.0) {
        cut[n++] = e;
        for (double k = 1e-3; k < 1.0; k *= 10.0)
            cut[n++] = e * (1.0 - k);
    }
    for (double k = 1e-3; e * (1.0 + k) < 1.0 && n < 60; k *= 10.0)
        cut[n++] = e * (1.0 + k);
    for (double k = 1e-3; e > 1.0 && k < 1.0 && n < 60; k *= 10.0)
        if (1.0 - (e - 1.0) / k > 0.0)
            cut[n++] = 1.0 - (e - 1.0) / k;
    qsort(cut, (size_t)n, sizeof cut[0], cmp_double);
    double total = 0.0;
    for (int i = 0; i + 1 < n; i++) {
        if (!(cut[i + 1] > cut[i]))
            continue;
        double val, abserr;
        int rc = gsl_integration_qags(&F, cut[i], cut[i + 1], 0.0, 1e-11, 1000, outer, &val,
                                      &abserr);
        if (rc && rc != GSL_EROUND)
            return rc;
        if (c->status)
            return c->status;
        total += val;
    }
    *out = total;
    return 0;
}

int tippe_contact_patch_reference(tippe_contact_patch_pressure p, double eps, double *f, double *m,
                          tippe_error *err)
{
    if (!(eps >= 0.0))
        return tippe_error_set(err, TIPPE_EINPUT, "eps must be >= 0, got %g", eps);
    if (isinf(eps)) { /* pure sliding: point Coulomb, no torque */
        *f = 1.0;
        *m = 0.0;
        return TIPPE_OK;
    }
    tippe_gsl_errors_as_codes();
    gsl_integration_workspace *outer = gsl_integration_workspace_alloc(1000);
    gsl_integration_workspace *inner = gsl_integration_workspace_alloc(1000);
    if (!outer || !inner) {
        gsl_integration_workspace_free(outer);
        gsl_integration_workspace_free(inner);
        return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory for the quadrature");
    }
    ref_ctx c = {p == TIPPE_CONTACT_PATCH_HERTZ, 0, eps, 0.0, inner, 0};
    int rc = 0;
    if (eps == 0.0)
        *f = 0.0; /* by symmetry: pure drilling has no net force */
    else
        rc = ref_integral(&c, outer, f);
    if (!rc) {
        c.moment = 1;
        c.status = 0;
        rc = ref_integral(&c, outer, m);
    }
    gsl_integration_workspace_free(outer);
    gsl_integration_workspace_free(inner);
    if (rc)
        return tippe_error_set(err, TIPPE_ECOMPUTE,
                               "contact patch quadrature failed at eps = %g: %s", eps,
                               gsl_strerror(rc));
    return TIPPE_OK;
}

/* ---- sticking ------------------------------------------------------------------------ */

double tippe_contact_patch_load_ellipse(tippe_contact_patch_pressure p, double mu_N, double a,
                                const double F[2], double M)
{
    if (!(mu_N > 0.0)) /* no friction: only a zero wrench is held */
        return (F[0] == 0.0 && F[1] == 0.0 && M == 0.0) ? 0.0 : INFINITY;
    /* Leine and Glocker 2003: (|F|/(mu N))^2 + (M/(mu N a m0))^2 <= 1 while sticking. */
    const double x = hypot(F[0], F[1]) / mu_N;
    const double y = fabs(M) / (mu_N * a * law_of(p)->m0);
    return hypot(x, y);
}

double tippe_contact_patch_load(tippe_contact_patch_pressure p, double mu_N, double a, const double F[2],
                        double M, double *eps_exit)
{
    if (!(mu_N > 0.0)) { /* no friction: only a zero wrench is held */
        if (eps_exit)
            *eps_exit = 0.0;
        return (F[0] == 0.0 && F[1] == 0.0 && M == 0.0) ? 0.0 : INFINITY;
    }
    const double x = hypot(F[0], F[1]) / mu_N; /* |F| / (mu N) */
    if (!(a > 0.0)) {                           /* point contact: the Coulomb cone */
        if (eps_exit)
            *eps_exit = INFINITY;
        return M == 0.0 ? x : INFINITY;
    }
    const double y = fabs(M) / (mu_N * a); /* |M| / (mu N a) */
    const patch_law *L = law_of(p);
    if (y == 0.0) { /* on the f axis: f = 1 at eps = inf */
        if (eps_exit)
            *eps_exit = INFINITY;
        return x;
    }
    /* The limit curve, parametrised by u = V/T in [0, 1] (eps^2 = u/(1 - u)):
     * f = sqrt(u) S_V / sqrt(s), m = sqrt(1 - u) S_W / sqrt(s). Its polar angle falls
     * from pi/2 (u = 0) to 0 (u = 1); bisect for the angle of (x, y). */
    double lo = 0.0, hi = 1.0, f = 0.0, m = L->m0;
    for (int i = 0; i < 64 && hi - lo > 0.0; i++) {
        const double u = 0.5 * (lo + hi);
        double s, sV, sW;
        patch_potential(L, u, 1.0 - u, &s, &sV, &sW);
        const double rs = sqrt(s);
        const double fu = sqrt(u) * sV / rs, mu = sqrt(1.0 - u) * sW / rs;
        if (mu * x > fu * y) /* the curve's point is still steeper than (x, y) */
            lo = u;
        else
            hi = u;
        f = fu;
        m = mu;
    }
    if (eps_exit) {
        const double u = 0.5 * (lo + hi);
        *eps_exit = u < 1.0 ? sqrt(u / (1.0 - u)) : INFINITY;
    }
    /* (x, y) = lambda (f, m): use the larger component for accuracy. */
    return x * m > y * f ? x / f : y / m;
}

/* ---- rolling resistance -------------------------------------------------------------- */

double tippe_contact_rolling_resistance(double N, double arm, double w_s, const double w_roll[2],
                                double M_roll[2])
{
    const double w2 = w_roll[0] * w_roll[0] + w_roll[1] * w_roll[1];
    const double den = sqrt(w2 + w_s * w_s);
    if (!(arm > 0.0) || !(den > 0.0)) {
        M_roll[0] = M_roll[1] = 0.0;
        return 0.0;
    }
    /* Constant-torque rolling resistance (a lever arm times N against the rolling
     * direction), regularised like the creep law: M = -N arm w / sqrt(|w|^2 + w_s^2). */
    const double k = N * arm / den;
    M_roll[0] = -k * w_roll[0];
    M_roll[1] = -k * w_roll[1];
    return k * w2;
}

double tippe_contact_rolling_arm_hysteresis(double alpha, double a)
{
    /* Johnson section 9.2 (Tabor 1955): a sphere rolling with hysteresis loss alpha
     * meets the resistance F_R = (3/16) alpha N a / R, i.e. a torque (3/16) alpha N a. */
    return 3.0 / 16.0 * alpha * a;
}

int tippe_contact_table_surface(const char *name, double *E_pa, double *nu)
{
    /* docs/contact-patch.md, "Materials", gives each value's source */
    static const struct {
        const char *name;
        double E_GPa, nu;
    } tables[] = {{"glass", 72.0, 0.23}, {"laminate", 9.0, 0.3}, {"wood", 1.0, 0.4},
                  {"steel", 210.0, 0.30}};
    for (size_t i = 0; i < sizeof tables / sizeof tables[0]; i++)
        if (name && !strcmp(name, tables[i].name)) {
            *E_pa = tables[i].E_GPa * 1e9;
            *nu = tables[i].nu;
            return 0;
        }
    return -1;
}
