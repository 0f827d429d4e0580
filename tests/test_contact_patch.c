/* The contact patch (issue 27): Hertz radius; the quadrature reference of
 * Coulomb-Contensou friction against two independent forms (Hertz's closed form for
 * eps <= 1, the chord integrals of docs/contact-patch.md, a brute-force grid); the cheap
 * form against the reference over eps in [1e-6, 1e6]; the limits (point Coulomb, pure
 * drilling, the viscous slope); sticking loads; rolling resistance; the sign of the
 * dissipated power on random inputs; and the cost of one call (printed, not asserted).
 * docs/contact-patch.md quotes the numbers printed here. */
#include "check.h"
#include "tippe/physics.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#define PI 3.14159265358979323846

/* The worst relative errors of the cheap form against the reference on the grid below
 * (measured: uniform f 3.087e-3, m 3.320e-3; Hertz f 1.461e-3, m 1.917e-3), rounded up:
 * the reference is good to 1e-12 (checked below), so the bound is the fit's own minimax
 * error, with room only for a different libm's last bits. */
static const double BOUND_F[2] = {3.2e-3, 1.5e-3};
static const double BOUND_M[2] = {3.4e-3, 2.0e-3};

/* ---- an independent reference: the chord integrals ------------------------------- */

/* Integrating along chords of the patch through the point that does not slip (at
 * distance eps from the centre, docs/contact-patch.md, "Two references"):
 *   eps <= 1: f = eps int_0^pi sin^2(t) H(h) dt, m = int_0^pi G(h) dt, h^2 = 1 - eps^2 cos^2 t;
 *   eps >= 1: f = int sqrt(1 - sin^2(t)/eps^2) H(cos t) cos t dt,
 *             m = int G(cos t) cos t / sqrt(eps^2 - sin^2 t) dt, t in [-pi/2, pi/2];
 * H(h), G(h): the pressure and its second moment along a chord of half-length h. */
typedef struct {
    int hertz, moment;
    double eps;
} chord_ctx;

static double chord_H(int hertz, double h) { return hertz ? 0.75 * h * h : 2.0 * h / PI; }
static double chord_G(int hertz, double h)
{
    return hertz ? 3.0 * h * h * h * h / 16.0 : 2.0 * h * h * h / (3.0 * PI);
}

static double chord_integrand(double t, void *par)
{
    const chord_ctx *c = par;
    const double e = c->eps;
    if (e <= 1.0) {
        const double ct = cos(t), st = sin(t), h = sqrt(fmax(0.0, 1.0 - e * e * ct * ct));
        return c->moment ? chord_G(c->hertz, h) : e * st * st * chord_H(c->hertz, h);
    }
    const double st = sin(t), ct = cos(t);
    return c->moment ? chord_G(c->hertz, ct) * ct / sqrt(e * e - st * st)
                     : sqrt(1.0 - st * st / (e * e)) * chord_H(c->hertz, ct) * ct;
}

static void chord(int hertz, double eps, double *f, double *m)
{
    gsl_integration_workspace *w = gsl_integration_workspace_alloc(1000);
    double err;
    for (int moment = 0; moment < 2; moment++) {
        chord_ctx c = {hertz, moment, eps};
        gsl_function F = {chord_integrand, &c};
        double *out = moment ? m : f;
        if (eps <= 1.0)
            gsl_integration_qag(&F, 0.0, PI, 0.0, 1e-13, 1000, 6, w, out, &err);
        else
            gsl_integration_qag(&F, -PI / 2, PI / 2, 0.0, 1e-13, 1000, 6, w, out, &err);
    }
    gsl_integration_workspace_free(w);
}

/* Brute force: Coulomb's law summed over an n x n grid of cell centres in the unit
 * square clipped to the patch (uniform pressure), no symmetry used. */
static void brute_uniform(double eps, int n, double *f, double *m)
{
    double sf = 0.0, sm = 0.0, cnt = 0.0;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            const double x = -1.0 + (i + 0.5) * 2.0 / n, y = -1.0 + (j + 0.5) * 2.0 / n;
            if (x * x + y * y > 1.0)
                continue;
            const double sx = eps - y, sy = x, d = hypot(sx, sy); /* slip: v + e3 x r */
            sf += sx / d;
            sm += (x * sy - y * sx) / d;
            cnt += 1.0;
        }
    *f = sf / cnt;
    *m = sm / cnt;
}

static uint64_t rng_state = 0x9E3779B97F4A7C15ull;
static double uniform01(void)
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 7;
    rng_state ^= rng_state << 17;
    return (double)(rng_state >> 11) / 9007199254740992.0;
}
/* A magnitude log-uniform in [10^lo, 10^hi], with a random sign; exactly 0 one time in 8. */
static double random_value(double lo, double hi)
{
    if (uniform01() < 0.125)
        return 0.0;
    const double mag = pow(10.0, lo + (hi - lo) * uniform01());
    return uniform01() < 0.5 ? -mag : mag;
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static void test_hertz(void)
{
    tippe_error err;
    double Es, a;
    /* Two equal steels: E* = E / (2 (1 - nu^2)). */
    CHECK(tippe_contact_hertz_modulus(210e9, 0.3, 210e9, 0.3, &Es, &err) == TIPPE_OK, "%s", err.msg);
    CHECK_CLOSE(Es, 210e9 / (2.0 * (1.0 - 0.09)), 1e-15, "steel on steel");
    /* PLA (2.5 GPa, 0.36) on glass (72 GPa, 0.23), the M12 ball's load (m 0.075 kg) and
     * radius 25 mm; values by hand (Python): E* = 2.7676745e9 Pa, a = 0.17082005 mm. */
    CHECK(tippe_contact_hertz_modulus(2.5e9, 0.36, 72e9, 0.23, &Es, &err) == TIPPE_OK, "%s", err.msg);
    CHECK_CLOSE(Es, 2767674484.578287, 1e-12, "PLA on glass");
    CHECK(tippe_contact_hertz_radius(0.025, 0.075 * 9.81, Es, &a, &err) == TIPPE_OK, "%s", err.msg);
    CHECK_CLOSE(a, 0.00017082004985781812, 1e-12, "PLA ball on glass");
    CHECK(tippe_contact_hertz_radius(0.025, 0.0, Es, &a, &err) == TIPPE_OK && a == 0.0, "N = 0: a = %g", a);
    /* Bad inputs say what is wrong. */
    CHECK(tippe_contact_hertz_modulus(0.0, 0.3, 1e9, 0.3, &Es, &err) == TIPPE_EINPUT &&
              strstr(err.msg, "Young's modulus"),
          "E = 0: %s", err.msg);
    CHECK(tippe_contact_hertz_modulus(1e9, 0.6, 1e9, 0.3, &Es, &err) == TIPPE_EINPUT &&
              strstr(err.msg, "Poisson"),
          "nu = 0.6: %s", err.msg);
    CHECK(tippe_contact_hertz_modulus(1e9, 0.3, NAN, 0.3, &Es, &err) == TIPPE_EINPUT, "E2 NaN");
    CHECK(tippe_contact_hertz_radius(0.0, 1.0, 1e9, &a, &err) == TIPPE_EINPUT &&
              strstr(err.msg, "radius"),
          "R = 0: %s", err.msg);
    CHECK(tippe_contact_hertz_radius(0.025, -1.0, 1e9, &a, &err) == TIPPE_EINPUT &&
              strstr(err.msg, "normal force"),
          "N < 0: %s", err.msg);
}

static void test_reference(void)
{
    tippe_error err;
    double f, m, fc, mc;
    for (int law = 0; law < 2; law++) {
        const tippe_contact_patch_limits L = tippe_contact_patch_limits_of(law);
        CHECK(tippe_contact_patch_reference(law, 0.0, &f, &m, &err) == TIPPE_OK, "%s", err.msg);
        CHECK(f == 0.0, "law %d: pure drilling has no force, f = %g", law, f);
        CHECK_CLOSE(m, L.m0, 1e-12, "law %d: pure drilling m = m0", law);
        CHECK(tippe_contact_patch_reference(law, INFINITY, &f, &m, &err) == TIPPE_OK && f == 1.0 &&
                  m == 0.0,
              "law %d: pure sliding", law);
        /* The asymptotic slopes of the reference itself. */
        tippe_contact_patch_reference(law, 1e-7, &f, &m, &err);
        CHECK_CLOSE(f / 1e-7, L.c1, 1e-10, "law %d: f ~ c1 eps", law);
        tippe_contact_patch_reference(law, 1e7, &f, &m, &err);
        CHECK_CLOSE(m * 1e7, L.c2, 1e-10, "law %d: m ~ c2 / eps", law);
        /* Against the chord integrals, across eps = 1 where the non-slipping point leaves
         * the patch. */
        const double eps[] = {1e-4, 0.03, 0.3, 0.9, 0.99, 1.0, 1.01, 1.5, 3.0, 30.0, 1e4};
        for (size_t i = 0; i < sizeof eps / sizeof eps[0]; i++) {
            CHECK(tippe_contact_patch_reference(law, eps[i], &f, &m, &err) == TIPPE_OK, "%s", err.msg);
            chord(law, eps[i], &fc, &mc);
            CHECK_CLOSE(f, fc, 1e-12, "law %d eps %g: f against the chords", law, eps[i]);
            CHECK_CLOSE(m, mc, 1e-12, "law %d eps %g: m against the chords", law, eps[i]);
        }
    }
    /* Hertz, eps <= 1, in closed form: f = (3 pi/8) eps (1 - eps^2/4),
     * m = (3 pi/16)(1 - eps^2 + 3 eps^4/8). */
    const double eh[] = {0.1, 0.5, 0.9, 1.0};
    for (size_t i = 0; i < sizeof eh / sizeof eh[0]; i++) {
        const double e = eh[i];
        tippe_contact_patch_reference(TIPPE_CONTACT_PATCH_HERTZ, e, &f, &m, &err);
        CHECK_CLOSE(f, 3.0 * PI / 8.0 * e * (1.0 - e * e / 4.0), 1e-12, "Hertz f at %g", e);
        CHECK_CLOSE(m, 3.0 * PI / 16.0 * (1.0 - e * e + 3.0 * e * e * e * e / 8.0), 1e-12,
                    "Hertz m at %g", e);
    }
    /* Brute force, uniform pressure, eps = 0.5: a 1500 x 1500 grid; its error is the
     * clipped rim's, O(1/n) = 1e-3. */
    brute_uniform(0.5, 1500, &fc, &mc);
    tippe_contact_patch_reference(TIPPE_CONTACT_PATCH_UNIFORM, 0.5, &f, &m, &err);
    CHECK_CLOSE(f, fc, 2e-3, "uniform eps 0.5: f against a grid");
    CHECK_CLOSE(m, mc, 2e-3, "uniform eps 0.5: m against a grid");
    CHECK(tippe_contact_patch_reference(TIPPE_CONTACT_PATCH_HERTZ, -1.0, &f, &m, &err) == TIPPE_EINPUT,
          "negative eps refused");
    CHECK(tippe_contact_patch_reference(TIPPE_CONTACT_PATCH_HERTZ, NAN, &f, &m, &err) == TIPPE_EINPUT,
          "NaN eps refused");
}

static void test_cheap_against_reference(void)
{
    tippe_error err;
    for (int law = 0; law < 2; law++) {
        double wf = 0.0, wm = 0.0, ef = 0.0, em = 0.0;
        /* 10 points a decade over [1e-6, 1e6], plus a fine pass over [0.1, 10] where the
         * error peaks. */
        for (int i = 0; i <= 120 + 200; i++) {
            const double e = i <= 120 ? pow(10.0, -6.0 + i / 10.0)
                                      : pow(10.0, -1.0 + (i - 121) / 99.5);
            double f, m, fa, ma;
            CHECK(tippe_contact_patch_reference(law, e, &f, &m, &err) == TIPPE_OK, "%s", err.msg);
            tippe_contact_patch_normalised(law, e, &fa, &ma);
            if (fabs(fa / f - 1.0) > wf) {
                wf = fabs(fa / f - 1.0);
                ef = e;
            }
            if (fabs(ma / m - 1.0) > wm) {
                wm = fabs(ma / m - 1.0);
                em = e;
            }
        }
        printf("cheap form, %s pressure: worst relative error f %.3e (eps %.3g), m %.3e "
               "(eps %.3g)\n",
               tippe_contact_patch_pressure_name(law), wf, ef, wm, em);
        CHECK(wf <= BOUND_F[law], "law %d: f error %.3e > %.3e", law, wf, BOUND_F[law]);
        CHECK(wm <= BOUND_M[law], "law %d: m error %.3e > %.3e", law, wm, BOUND_M[law]);
    }
}

static void test_cheap_limits(void)
{
    for (int law = 0; law < 2; law++) {
        const tippe_contact_patch_limits L = tippe_contact_patch_limits_of(law);
        double f, m;
        tippe_contact_patch_normalised(law, 0.0, &f, &m);
        CHECK(f == 0.0, "law %d: f(0) = %g", law, f);
        CHECK_CLOSE(m, L.m0, 1e-15, "law %d: m(0) = m0", law);
        tippe_contact_patch_normalised(law, INFINITY, &f, &m);
        CHECK(f == 1.0 && m == 0.0, "law %d: f(inf) = %g, m(inf) = %g", law, f, m);
        tippe_contact_patch_normalised(law, 1e-8, &f, &m);
        CHECK_CLOSE(f / 1e-8, L.c1, 1e-12, "law %d: f ~ c1 eps", law);
        tippe_contact_patch_normalised(law, 1e8, &f, &m);
        CHECK_CLOSE(m * 1e8, L.c2, 1e-12, "law %d: m ~ c2 / eps", law);
        /* f increases and m decreases (the potential is convex: a dissipative law). */
        double fp = 0.0, mp = INFINITY;
        int mono = 1;
        for (int i = 0; i <= 1200; i++) {
            tippe_contact_patch_normalised(law, pow(10.0, -6.0 + i / 100.0), &f, &m);
            mono &= f > fp && m < mp;
            fp = f;
            mp = m;
        }
        CHECK(mono, "law %d: f increasing and m decreasing in eps", law);

        const double muN = 0.7, v[2] = {0.03, -0.04}, vn = 0.05, om = 120.0, a = 1.7e-4;
        tippe_contact_patch_wrench w;
        /* a = 0 and omega_n = 0: point Coulomb friction. */
        tippe_contact_patch_friction(law, muN, 0.0, 0.0, v, om, &w);
        CHECK_CLOSE(w.F[0], -muN * v[0] / vn, 1e-15, "a = 0: Fx");
        CHECK_CLOSE(w.F[1], -muN * v[1] / vn, 1e-15, "a = 0: Fy");
        CHECK(w.M == 0.0, "a = 0: M = %g", w.M);
        tippe_contact_patch_friction(law, muN, a, 0.0, v, 0.0, &w);
        CHECK_CLOSE(w.F[0], -muN * v[0] / vn, 1e-15, "omega_n = 0: Fx");
        CHECK(w.M == 0.0, "omega_n = 0: M = %g", w.M);
        /* a -> 0: Coulomb to O(eps^-2) in f and M ~ c2 mu N a^2 omega/|v| -> 0. */
        tippe_contact_patch_friction(law, muN, 1e-9, 0.0, v, om, &w);
        CHECK_CLOSE(w.F[0], -muN * v[0] / vn, 1e-12, "a -> 0: Fx");
        CHECK_CLOSE(w.M, -muN * L.c2 * 1e-9 * 1e-9 * om / vn, 1e-6, "a -> 0: M");
        /* v = 0: pure drilling. */
        const double v0[2] = {0.0, 0.0};
        tippe_contact_patch_friction(law, muN, a, 0.0, v0, om, &w);
        CHECK(w.F[0] == 0.0 && w.F[1] == 0.0, "v = 0: F = (%g, %g)", w.F[0], w.F[1]);
        CHECK_CLOSE(w.M, -muN * a * L.m0, 1e-14, "v = 0: M = -mu N a m0");
        tippe_contact_patch_friction(law, muN, a, 0.0, v0, -om, &w);
        CHECK_CLOSE(w.M, muN * a * L.m0, 1e-14, "v = 0: M against a negative spin");
        /* (0, 0): the sticking point, a zero wrench. */
        tippe_contact_patch_friction(law, muN, a, 0.0, v0, 0.0, &w);
        CHECK(w.F[0] == 0.0 && w.F[1] == 0.0 && w.M == 0.0 && w.dissipation == 0.0,
              "(0, 0): zero wrench");
        const double vnan[2] = {NAN, 0.0};
        tippe_contact_patch_friction(law, muN, a, 0.0, vnan, om, &w);
        CHECK(isnan(w.F[0]), "a NaN slip propagates");
        /* v_s at a = 0 is the regularised Coulomb law of src/physics/dynamics.c. */
        const double vs = 1e-5, vsmall[2] = {3e-6, 4e-6};
        tippe_contact_patch_friction(law, muN, 0.0, vs, vsmall, om, &w);
        CHECK_CLOSE(w.F[0], -muN * vsmall[0] / sqrt(25e-12 + vs * vs), 1e-15, "creep law");
        /* The physical form is the normalised one, scaled: F against v. */
        tippe_contact_patch_friction(law, muN, a, 0.0, v, om, &w);
        tippe_contact_patch_normalised(law, vn / (a * om), &f, &m);
        CHECK_CLOSE(hypot(w.F[0], w.F[1]), muN * f, 1e-13, "|F| = mu N f");
        CHECK_CLOSE(w.M, -muN * a * m, 1e-13, "M = -mu N a m");
        CHECK(fabs(w.F[0] * v[1] - w.F[1] * v[0]) <= 1e-15 * hypot(w.F[0], w.F[1]) * vn &&
                  w.F[0] * v[0] + w.F[1] * v[1] < 0.0,
              "F against v");
    }
}

static void test_viscous_limit(void)
{
    /* |v| = 1e-7 a omega: F = -mu N c1 v / (a omega) to O(eps^2), i.e. eq 3.12 with
     * mu = mu_c c1 / (a omega). */
    const double N = 0.75, mu_c = 0.3, a = 1.7e-4, om = 125.0;
    const double v[2] = {1e-7 * a * om, 0.0};
    for (int law = 0; law < 2; law++) {
        tippe_contact_patch_wrench w;
        tippe_contact_patch_friction(law, mu_c * N, a, 0.0, v, om, &w);
        CHECK_CLOSE(-w.F[0] / (N * v[0]), tippe_contact_patch_viscous_mu(law, mu_c, a, om), 1e-9,
                    "law %d: viscous slope", law);
    }
    /* The M12 ball (m 0.0768 kg, R 25 mm) at 20 rev/s with mu_c 0.3 on two tables. */
    const struct {
        const char *name;
        double E1, nu1, E2, nu2;
    } pairs[] = {{"PLA on glass", 2.5e9, 0.36, 72e9, 0.23},
                 {"PLA on HPL", 2.5e9, 0.36, 9e9, 0.3},
                 {"ABS on glass", 2.4e9, 0.35, 72e9, 0.23}};
    for (size_t i = 0; i < sizeof pairs / sizeof pairs[0]; i++) {
        double Es, a12;
        tippe_contact_hertz_modulus(pairs[i].E1, pairs[i].nu1, pairs[i].E2, pairs[i].nu2, &Es, NULL);
        tippe_contact_hertz_radius(0.025, 0.0768 * 9.81, Es, &a12, NULL);
        const double w20 = 20.0 * 2.0 * PI;
        printf("M12, %s: a = %.4f mm, a omega = %.4f m/s, viscous mu = %.1f s/m (Hertz), "
               "%.1f s/m (uniform)\n",
               pairs[i].name, 1e3 * a12, a12 * w20,
               tippe_contact_patch_viscous_mu(TIPPE_CONTACT_PATCH_HERTZ, 0.3, a12, w20),
               tippe_contact_patch_viscous_mu(TIPPE_CONTACT_PATCH_UNIFORM, 0.3, a12, w20));
        CHECK(a12 > 1e-4 && a12 < 3e-4, "%s: a = %g m", pairs[i].name, a12);
    }
}

static void test_sticking(void)
{
    tippe_error err;
    const double muN = 0.5, a = 2e-4;
    for (int law = 0; law < 2; law++) {
        const tippe_contact_patch_limits L = tippe_contact_patch_limits_of(law);
        /* Points of the cheap form's limit curve load it to 1 and give back their eps. */
        const double eps[] = {1e-3, 0.1, 0.7, 1.0, 2.0, 50.0};
        for (size_t i = 0; i < sizeof eps / sizeof eps[0]; i++) {
            double f, m, e_out;
            tippe_contact_patch_normalised(law, eps[i], &f, &m);
            const double F[2] = {0.6 * muN * f, -0.8 * muN * f};
            CHECK_CLOSE(tippe_contact_patch_load(law, muN, a, F, muN * a * m, &e_out), 1.0, 1e-12,
                        "law %d: on the curve at eps %g", law, eps[i]);
            CHECK_CLOSE(e_out, eps[i], 1e-6, "law %d: exit eps", law);
            const double Fh[2] = {0.5 * F[0], 0.5 * F[1]};
            CHECK_CLOSE(tippe_contact_patch_load(law, muN, a, Fh, -0.5 * muN * a * m, NULL), 0.5,
                        1e-12, "law %d: half the load", law);
        }
        /* The ends: pure force and pure torque. */
        const double F1[2] = {muN, 0.0}, F0[2] = {0.0, 0.0};
        CHECK_CLOSE(tippe_contact_patch_load(law, muN, a, F1, 0.0, NULL), 1.0, 1e-15, "force only");
        CHECK_CLOSE(tippe_contact_patch_load(law, muN, a, F0, muN * a * L.m0, NULL), 1.0, 1e-14,
                    "torque only");
        CHECK_CLOSE(tippe_contact_patch_load_ellipse(law, muN, a, F1, 0.0), 1.0, 1e-15, "ellipse: F");
        CHECK_CLOSE(tippe_contact_patch_load_ellipse(law, muN, a, F0, muN * a * L.m0), 1.0, 1e-15,
                    "ellipse: M");
        /* a = 0: the Coulomb cone, and no torque can be held. */
        CHECK(tippe_contact_patch_load(law, muN, 0.0, F1, 0.0, NULL) == 1.0, "a = 0, force");
        CHECK(isinf(tippe_contact_patch_load(law, muN, 0.0, F0, 1e-9, NULL)), "a = 0, torque");
        CHECK(isinf(tippe_contact_patch_load(law, 0.0, a, F1, 0.0, NULL)) &&
                  isinf(tippe_contact_patch_load_ellipse(law, 0.0, a, F1, 0.0)) &&
                  tippe_contact_patch_load(law, 0.0, a, F0, 0.0, NULL) == 0.0,
              "mu N = 0 holds only a zero wrench");
        /* The exact (reference) limit curve lies inside Leine and Glocker's ellipse: the
         * ellipse lets a wrench stick that the patch cannot hold, by up to this much. */
        double lmin = 2.0, emin = 0.0;
        for (int i = 0; i <= 120; i++) {
            const double e = pow(10.0, -3.0 + i / 20.0);
            double f, m;
            tippe_contact_patch_reference(law, e, &f, &m, &err);
            const double F[2] = {muN * f, 0.0};
            const double l = tippe_contact_patch_load_ellipse(law, muN, a, F, muN * a * m);
            if (l < lmin) {
                lmin = l;
                emin = e;
            }
            CHECK(l <= 1.0 + 1e-12, "law %d: the exact curve outside the ellipse at %g", law, e);
        }
        printf("%s pressure: the exact limit curve reaches in to %.4f of the ellipse "
               "(eps %.3g)\n",
               tippe_contact_patch_pressure_name(law), lmin, emin);
    }
}

static void test_rolling(void)
{
    CHECK_CLOSE(tippe_contact_rolling_arm_hysteresis(0.04, 2e-4), 3.0 / 16.0 * 0.04 * 2e-4, 1e-15,
                "hysteresis arm");
    double M[2];
    const double w[2] = {3.0, -4.0};
    CHECK(tippe_contact_rolling_resistance(0.7, 0.0, 0.0, w, M) == 0.0 && M[0] == 0.0 && M[1] == 0.0,
          "off by default (arm 0)");
    const double D = tippe_contact_rolling_resistance(0.7, 1e-5, 0.0, w, M);
    CHECK_CLOSE(M[0], -0.7 * 1e-5 * 0.6, 1e-15, "against w, magnitude N arm");
    CHECK_CLOSE(M[1], 0.7 * 1e-5 * 0.8, 1e-15, "against w, magnitude N arm");
    CHECK_CLOSE(D, 0.7 * 1e-5 * 5.0, 1e-15, "dissipation N arm |w|");
    const double w0[2] = {0.0, 0.0};
    CHECK(tippe_contact_rolling_resistance(0.7, 1e-5, 0.0, w0, M) == 0.0 && M[0] == 0.0,
          "no rolling, no torque");
}

static void test_energy(void)
{
    /* Random inputs over many decades, zeros included: the power -(F.v + M omega_n +
     * M_roll.w_roll) is never negative, and the returned dissipation is that power. */
    int bad = 0, badsum = 0;
    double worst = 0.0;
    for (int i = 0; i < 200000; i++) {
        const int law = i & 1;
        const double muN = fabs(random_value(-3, 2)), a = fabs(random_value(-7, -2));
        const double vs = uniform01() < 0.5 ? 0.0 : fabs(random_value(-9, -2));
        const double v[2] = {random_value(-9, 1), random_value(-9, 1)};
        const double om = random_value(-4, 3);
        const double wr[2] = {random_value(-4, 3), random_value(-4, 3)};
        const double arm = fabs(random_value(-7, -3)), ws = fabs(random_value(-6, 0));
        tippe_contact_patch_wrench w;
        tippe_contact_patch_friction(law, muN, a, vs, v, om, &w);
        double Mr[2];
        const double Dr = tippe_contact_rolling_resistance(muN, arm, ws, wr, Mr);
        const double P = w.F[0] * v[0] + w.F[1] * v[1] + w.M * om; /* power on the body */
        const double Pr = Mr[0] * wr[0] + Mr[1] * wr[1];
        const double scale = muN * (hypot(v[0], v[1]) + fabs(a * om)) + 1e-300;
        if (P > 1e-15 * scale || Pr > 0.0 || w.dissipation < 0.0 || Dr < 0.0)
            bad++;
        const double d = fabs(-P - w.dissipation) / scale;
        if (d > worst)
            worst = d;
        if (d > 1e-14 || fabs(-Pr - Dr) > 1e-15 * (Dr + 1e-300))
            badsum++;
    }
    CHECK(bad == 0, "%d inputs with positive power", bad);
    CHECK(badsum == 0, "%d inputs whose dissipation is not -power (worst %.3g)", badsum, worst);
}

/* Point Coulomb friction as src/physics/dynamics.c's creep law computes it, F = -mu N v /
 * sqrt(|v|^2 + v_s^2), behind a call like the patch law's. */
static __attribute__((noinline)) void point_coulomb(double mu_N, double v_s, const double v[2],
                                                    double F[2])
{
    const double k = mu_N / sqrt(v[0] * v[0] + v[1] * v[1] + v_s * v_s);
    F[0] = -k * v[0];
    F[1] = -k * v[1];
}

static void bench(void)
{
    /* One call of the cheap form against one point-Coulomb evaluation, on inputs that
     * vary from call to call: independent calls (throughput), and calls each of whose
     * input depends on the previous result (latency, as in a right-hand side). */
    enum { NIN = 1024, REPS = 2000 };
    static double vx[NIN], vy[NIN], om[NIN];
    for (int i = 0; i < NIN; i++) {
        vx[i] = random_value(-4, 0);
        vy[i] = random_value(-4, 0);
        om[i] = random_value(0, 2.5);
    }
    volatile double sink = 0.0;
    double best[2][2] = {{INFINITY, INFINITY}, {INFINITY, INFINITY}};
    for (int round = 0; round < 7; round++)
        for (int chain = 0; chain < 2; chain++) {
            const double dep = chain ? 1e-300 : 0.0;
            double t0 = now_s(), acc = 0.0;
            for (int r = 0; r < REPS; r++)
                for (int i = 0; i < NIN; i++) {
                    const double v[2] = {vx[i] + dep * acc, vy[i]};
                    tippe_contact_patch_wrench w;
                    tippe_contact_patch_friction(TIPPE_CONTACT_PATCH_HERTZ, 0.22, 1.7e-4, 1e-5, v, om[i], &w);
                    acc += w.F[0] + w.F[1] + w.M;
                }
            double t1 = now_s();
            sink += acc;
            acc = 0.0;
            for (int r = 0; r < REPS; r++)
                for (int i = 0; i < NIN; i++) {
                    const double v[2] = {vx[i] + dep * acc, vy[i]};
                    double F[2];
                    point_coulomb(0.22, 1e-5, v, F);
                    acc += F[0] + F[1];
                }
            double t2 = now_s();
            sink += acc;
            best[chain][0] = fmin(best[chain][0], (t1 - t0) / ((double)NIN * REPS));
            best[chain][1] = fmin(best[chain][1], (t2 - t1) / ((double)NIN * REPS));
        }
    printf("cost of one call (best of 7): cheap patch form %.1f ns independent, %.1f ns "
           "chained; point Coulomb %.1f ns, %.1f ns (sink %d)\n",
           1e9 * best[0][0], 1e9 * best[1][0], 1e9 * best[0][1], 1e9 * best[1][1],
           sink != sink);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_hertz();
    test_reference();
    test_cheap_against_reference();
    test_cheap_limits();
    test_viscous_limit();
    test_sticking();
    test_rolling();
    test_energy();
    bench();
    return check_summary("test_contact_patch");
}
