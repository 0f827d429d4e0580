/* test_print_geometry: the solids' closed forms against an independent numerical
 * integration of their regions, exact limits, composition, and thin-part accuracy. */
#include "tippe/design.h"

#include "check.h"

#include <math.h>
#include <stdio.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_rng.h>

static double rel(double got, double want, double scale)
{
    return fabs(got - want) / scale;
}

/* ------------------------------------------------------ the reference integrator */

typedef enum { S_BALL, S_SHELL, S_TUBE, S_TORUS } solid_kind;
static const char *const kind_name[] = {"ball", "shell", "tube", "torus"};

/* Parameters in the order of the constructor's arguments. */
typedef struct {
    solid_kind kind;
    double p[5];
} solid;

static tippe_moments solid_moments(const solid *s)
{
    switch (s->kind) {
    case S_BALL:
        return tippe_ball(s->p[0], s->p[1]);
    case S_SHELL:
        return tippe_shell(s->p[0], s->p[1], s->p[2]);
    case S_TUBE:
        return tippe_tube(s->p[0], s->p[1], s->p[2], s->p[3], s->p[4]);
    case S_TORUS:
    default:
        return tippe_torus(s->p[0], s->p[1], s->p[2], s->p[3], s->p[4]);
    }
}

static int clipped(double ball_radius)
{
    return ball_radius > 0 && isfinite(ball_radius);
}

/* The radial interval lo <= r <= hi of the solid at height z, straight from the
 * inequalities that define it (no use of the library's pieces or crossings).
 * Returns 0 if the slice is empty. */
static int slice(const solid *s, double z, double *lo, double *hi)
{
    const double *p = s->p;
    double clip = 0;
    *lo = *hi = 0;
    switch (s->kind) {
    case S_BALL: { /* (z - z0)^2 + r^2 <= a^2 */
        double dz = z - p[1];
        if (dz * dz >= p[0] * p[0])
            return 0;
        *hi = sqrt(p[0] * p[0] - dz * dz);
        break;
    }
    case S_SHELL: { /* b^2 <= (z - z0)^2 + r^2 <= a^2, b = a - t */
        double dz = z - p[2], b = fmax(p[0] - p[1], 0);
        if (dz * dz >= p[0] * p[0])
            return 0;
        *hi = sqrt(p[0] * p[0] - dz * dz);
        *lo = dz * dz < b * b ? sqrt(b * b - dz * dz) : 0;
        break;
    }
    case S_TUBE: /* r_in <= r <= r_out, |z - zc| <= h/2 */
        if (fabs(z - p[3]) > p[2] / 2)
            return 0;
        *lo = fmax(p[0], 0);
        *hi = p[1];
        clip = p[4];
        break;
    case S_TORUS: { /* ((r - Rc)/p)^2 + ((z - z0)/q)^2 <= 1, swept about the axis */
        double u = (z - p[3]) / p[2];
        if (fabs(u) >= 1)
            return 0;
        double w = sqrt(1 - u * u);
        *lo = fmax(p[0] - p[1] * w, 0);
        *hi = p[0] + p[1] * w;
        clip = p[4];
        break;
    }
    }
    if (clipped(clip)) { /* and r^2 + z^2 <= a^2 */
        if (z * z >= clip * clip)
            return 0;
        *hi = fmin(*hi, sqrt(clip * clip - z * z));
    }
    return *hi > *lo;
}

static void z_range(const solid *s, double *z1, double *z2)
{
    const double *p = s->p;
    double clip = 0;
    switch (s->kind) {
    case S_BALL:
        *z1 = p[1] - p[0], *z2 = p[1] + p[0];
        break;
    case S_SHELL:
        *z1 = p[2] - p[0], *z2 = p[2] + p[0];
        break;
    case S_TUBE:
        *z1 = p[3] - p[2] / 2, *z2 = p[3] + p[2] / 2, clip = p[4];
        break;
    case S_TORUS:
        *z1 = p[3] - p[2], *z2 = p[3] + p[2], clip = p[4];
        break;
    }
    if (clipped(clip))
        *z1 = fmax(*z1, -clip), *z2 = fmin(*z2, clip);
}

typedef struct {
    const solid *s;
    int zpow, rpow; /* integrand z^zpow r^rpow */
    gsl_integration_workspace *inner_ws;
    int status;
} ref_params;

static double r_integrand(double r, void *vp)
{
    const ref_params *rp = vp;
    return 2 * M_PI * r * (rp->rpow ? r * r : 1.0);
}

static double z_integrand(double z, void *vp)
{
    ref_params *rp = vp;
    double lo = 0, hi = 0;
    if (!slice(rp->s, z, &lo, &hi))
        return 0;
    gsl_function f = {r_integrand, rp};
    double val, err;
    int st = gsl_integration_qag(&f, lo, hi, 0, 1e-13, 100, GSL_INTEG_GAUSS15, rp->inner_ws, &val,
                                 &err);
    if (st != GSL_SUCCESS)
        rp->status = st;
    return val * (rp->zpow == 0 ? 1.0 : rp->zpow == 1 ? z : z * z);
}

/* Nested 1D integration: QAG in r inside CQUAD in z over the solid's z range. CQUAD
 * copes with the kinks (where a wall changes) and the square-root ends (torus tips)
 * without being told where they are. */
static int reference_moments(const solid *s, tippe_moments *out, double *max_err_est)
{
    gsl_integration_workspace *iws = gsl_integration_workspace_alloc(100);
    gsl_integration_cquad_workspace *cws = gsl_integration_cquad_workspace_alloc(400);
    double z1, z2, vals[4], errs[4];
    int status = GSL_SUCCESS;
    z_range(s, &z1, &z2);
    const int zp[4] = {0, 1, 2, 0}, rpw[4] = {0, 0, 0, 1};
    for (int i = 0; i < 4; i++) {
        ref_params rp = {s, zp[i], rpw[i], iws, GSL_SUCCESS};
        gsl_function f = {z_integrand, &rp};
        size_t nev;
        vals[i] = errs[i] = 0;
        if (z2 > z1) {
            int st = gsl_integration_cquad(&f, z1, z2, 0, 1e-13, cws, &vals[i], &errs[i], &nev);
            if (st != GSL_SUCCESS)
                status = st;
        }
        if (rp.status != GSL_SUCCESS)
            status = rp.status;
    }
    out->m = vals[0], out->m_z = vals[1], out->m_zz = vals[2], out->m_rr = vals[3];
    *max_err_est = 0;
    double scale_z = vals[0] * fmax(fabs(z1), fabs(z2));
    double sc[4] = {vals[0], fmax(fabs(vals[1]), scale_z), vals[2], vals[3]};
    for (int i = 0; i < 4; i++)
        if (sc[i] > 0)
            *max_err_est = fmax(*max_err_est, errs[i] / sc[i]);
    gsl_integration_cquad_workspace_free(cws);
    gsl_integration_workspace_free(iws);
    return status;
}

static double max_err_by_kind[4];

static void check_against_reference(const solid *s, const char *label)
{
    tippe_moments ref, got = solid_moments(s);
    double est;
    int st = reference_moments(s, &ref, &est);
    CHECK(st == GSL_SUCCESS, "%s: reference integration failed: %s", label, gsl_strerror(st));
    /* The reference asks CQUAD for 1e-13; if its own estimate says it got worse than
     * 1e-11 the comparison below would not mean anything. */
    CHECK(est < 1e-11, "%s: reference error estimate %.3g", label, est);
    CHECK(ref.m > 0, "%s: empty region (a useless case)", label);
    double z1, z2;
    z_range(s, &z1, &z2);
    /* m_z is signed and vanishes for symmetric solids: its natural error scale is m
     * times the largest |z| in the solid (the size of the halves that cancel). */
    double scale_z = fmax(fabs(ref.m_z), ref.m * fmax(fabs(z1), fabs(z2)));
    double e[4] = {rel(got.m, ref.m, ref.m), rel(got.m_z, ref.m_z, scale_z),
                   rel(got.m_zz, ref.m_zz, ref.m_zz), rel(got.m_rr, ref.m_rr, ref.m_rr)};
    const char *names[4] = {"m", "m_z", "m_zz", "m_rr"};
    for (int i = 0; i < 4; i++) {
        /* Closed forms are exact up to rounding (~1e-15) and the reference is good to
         * ~1e-13, so 1e-10 only fails on a wrong formula or a missed wall crossing
         * (the smallest piece tested here is far above 1e-10 of the whole). */
        CHECK(e[i] <= 1e-10, "%s: %s = %.17g, reference %.17g, rel err %.3g", label, names[i],
              i == 0 ? got.m : i == 1 ? got.m_z : i == 2 ? got.m_zz : got.m_rr,
              i == 0 ? ref.m : i == 1 ? ref.m_z : i == 2 ? ref.m_zz : ref.m_rr, e[i]);
        max_err_by_kind[s->kind] = fmax(max_err_by_kind[s->kind], e[i]);
    }
}

static void test_against_numerical_integration(void)
{
    const double a = 0.025; /* the paper's prototypes: a 50 mm sphere */
    const solid cases[] = {
        {S_BALL, {0.025, 0}},
        {S_BALL, {0.01, 0.007}},
        {S_BALL, {0.003, -0.02}},
        {S_SHELL, {0.025, 0.0025, 0}},
        {S_SHELL, {0.025, 0.003, 0.004}},
        {S_SHELL, {0.01, 0.02, -0.003}}, /* thicker than its radius: a ball */
        {S_TUBE, {0, 0.003, 0.04, 0, 0}},
        {S_TUBE, {0.0015, 0.0055, 0.015, 0.0075, INFINITY}},
        {S_TUBE, {0, 0.003, 0.06, 0, a}},            /* rod spanning the shell */
        {S_TUBE, {0, 0.0055, 0.015, 0.0175, a}},     /* setscrew hole reaching the top */
        {S_TUBE, {0.003, 0.01, 0.01, 0.02, a}},      /* annulus poking out of the ball */
        {S_TUBE, {0.02, 0.03, 0.03, -0.01, a}},      /* wider than the ball */
        {S_TUBE, {0.001, 0.004, 0.01, -0.005, a}},   /* inside: the clip does nothing */
        {S_TUBE, {0, 0.012, 0.02, -0.018, a}},       /* bottom cap */
        {S_TORUS, {0.02, 0.007, 0.004, 0, 0}},
        {S_TORUS, {0.01, 0.003, 0.006, 0.005, -1}},
        {S_TORUS, {0.003, 0.005, 0.004, 0.01, 0}},   /* cross-section past the axis */
        {S_TORUS, {0.022, 0.007, 0.004, 0, a}},      /* band inside a shell, cut by it */
        {S_TORUS, {0.018, 0.006, 0.005, 0.012, a}},  /* off-centre band, cut */
        {S_TORUS, {0.018, 0.007, 0.004, 0, a}},      /* band touching the sphere */
        {S_TORUS, {0.0181, 0.007, 0.004, 0, a}},     /* band cut by a 0.1 mm sliver */
        {S_TORUS, {0.026, 0.004, 0.003, 0, a}},      /* mostly outside: inner wall cut */
        {S_TORUS, {0.005, 0.004, 0.006, 0.022, a}},  /* ring around the pole, cut */
        {S_TORUS, {0.003, 0.005, 0.004, 0.02, a}},   /* past the axis, cut near the pole */
        {S_TORUS, {0.003, 0.005, 0.004, 0.023, a}},  /* past the axis and past the pole */
        /* circular cross-section (radius 5 mm) whose far point, at 0.3 rad, sticks out
         * of the ball by 1 um: the cut is a 1.7e-6 sliver between two close crossings */
        {S_TORUS, {0.020001 * 0.95533648912560601964, 0.005, 0.005,
                   0.020001 * 0.29552020666133957511, a}},
        {S_TORUS, {0.02, 0.006, 0.006, 0.003, a}},   /* circular cross-section, cut */
        {S_TORUS, {0.015, 0.005, 0.004, 0, 0.0202}}, /* inside, bounding box is not */
    };
    char label[128];
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const solid *s = &cases[i];
        snprintf(label, sizeof label, "%s(%g, %g, %g, %g, %g)", kind_name[s->kind], s->p[0],
                 s->p[1], s->p[2], s->p[3], s->p[4]);
        check_against_reference(s, label);
    }
}

/* ------------------------------------------------------------------ exact limits */

static int all_zero(tippe_moments s)
{
    return s.m == 0 && s.m_z == 0 && s.m_zz == 0 && s.m_rr == 0;
}

static void test_degenerate(void)
{
    CHECK(all_zero(tippe_ball(0, 0.01)), "ball of zero radius");
    CHECK(all_zero(tippe_ball(-1, 0.01)), "ball of negative radius");
    CHECK(all_zero(tippe_shell(0.025, 0, 0.003)), "shell of zero thickness");
    CHECK(all_zero(tippe_shell(0, 0.001, 0.003)), "shell of zero radius");
    CHECK(all_zero(tippe_tube(0, 0, 0.01, 0.002, 0.025)), "hole of zero radius");
    CHECK(all_zero(tippe_tube(0.003, 0.003, 0.01, 0.002, 0)), "tube of zero wall");
    CHECK(all_zero(tippe_tube(0, 0.003, 0, 0.002, 0.025)), "tube of zero height");
    CHECK(all_zero(tippe_tube(0.026, 0.03, 0.01, 0, 0.025)), "tube entirely outside the ball");
    CHECK(all_zero(tippe_torus(0.02, 0, 0.004, 0, 0.025)), "torus of zero radial semi-axis");
    CHECK(all_zero(tippe_torus(0.02, 0.007, 0, 0, 0.025)), "torus of zero axial semi-axis");
    CHECK(all_zero(tippe_torus(0, 0.007, 0.004, 0, 0)), "torus of zero centre radius");
    CHECK(all_zero(tippe_torus(0.04, 0.005, 0.004, 0, 0.025)), "torus entirely outside ball");
    tippe_inertia in = tippe_moments_inertia(tippe_shell(0.025, 0, 0));
    CHECK(in.m == 0 && in.z_cm == 0 && in.A == 0 && in.C == 0 && !isnan(in.A),
          "inertia of nothing: m %g z_cm %g A %g C %g", in.m, in.z_cm, in.A, in.C);
}

static void test_limits(void)
{
    const double a = 0.025;
    /* Ball: C = 2/5 m a^2 exactly; both sides are a few roundings, so 1e-14. */
    tippe_inertia b = tippe_moments_inertia(tippe_ball(a, 0.004));
    CHECK(rel(b.C, 0.4 * b.m * a * a, b.C) < 1e-14, "ball C = %.17g vs 2/5 m a^2", b.C);
    CHECK(rel(b.A, 0.4 * b.m * a * a, b.A) < 1e-13, "ball A = %.17g vs 2/5 m a^2", b.A);
    CHECK(rel(b.z_cm, 0.004, 0.004) < 1e-14, "ball z_cm = %.17g", b.z_cm);

    /* A ball as two clipped cylinders of radius >= a, one over z in [0, a] and one
     * over [-a, 0]: a different code path (caps) that must give the same solid. Each
     * side is O(10) roundings, so agreement to 1e-13 is expected. */
    tippe_moments ball = tippe_ball(a, 0);
    tippe_moments halves = tippe_moments_add(tippe_tube(0, a, a, a / 2, a),
                                             tippe_tube(0, 1.5 * a, a, -a / 2, a));
    CHECK(rel(halves.m, ball.m, ball.m) < 1e-13, "halves m %.17g vs %.17g", halves.m, ball.m);
    CHECK(fabs(halves.m_z) < 1e-13 * ball.m * a, "halves m_z %.3g", halves.m_z);
    CHECK(rel(halves.m_zz, ball.m_zz, ball.m_zz) < 1e-13, "halves m_zz %.17g vs %.17g",
          halves.m_zz, ball.m_zz);
    CHECK(rel(halves.m_rr, ball.m_rr, ball.m_rr) < 1e-13, "halves m_rr %.17g vs %.17g",
          halves.m_rr, ball.m_rr);
    tippe_inertia hi = tippe_moments_inertia(halves);
    CHECK(rel(hi.C, 0.4 * hi.m * a * a, hi.C) < 1e-13, "halves C %.17g vs 2/5 m a^2", hi.C);

    /* Thin shell, leading order: m -> 4 pi a^2 t and C -> (2/3) m a^2, each with a
     * first correction of relative size t/a; allowing 1.5 t/a checks the limit and
     * the sign-free size of the first correction. */
    double t = 1e-5 * a;
    tippe_inertia sh = tippe_moments_inertia(tippe_shell(a, t, 0));
    CHECK(fabs(sh.m / (4 * M_PI * a * a * t) - 1) <= 1.5 * t / a, "thin shell m %.17g", sh.m);
    CHECK(fabs(sh.C / (2.0 / 3.0 * sh.m * a * a) - 1) <= 1.5 * t / a, "thin shell C %.17g",
          sh.C);
    CHECK(fabs(sh.z_cm) == 0, "centred shell z_cm %g", sh.z_cm);

    /* Thin torus -> ring of radius Rc at height z0. Pappus makes the volume exact at any
     * thickness (2 pi^2 Rc p q, 1e-14: roundings only); the moments approach the ring's
     * with relative corrections 3p^2/(4Rc^2) (m_rr) and q^2/(4 z0^2) (m_zz), so the
     * bounds p^2/Rc^2 and q^2/z0^2 hold with margin. */
    double Rc = 0.02, p = 1e-6, q = 2e-6, z0 = 0.005;
    tippe_moments tr = tippe_torus(Rc, p, q, z0, INFINITY);
    CHECK(rel(tr.m, 2 * M_PI * M_PI * Rc * p * q, tr.m) < 1e-14, "thin torus m %.17g", tr.m);
    CHECK(fabs(tr.m_rr / (tr.m * Rc * Rc) - 1) <= p * p / (Rc * Rc), "thin torus m_rr %.17g",
          tr.m_rr);
    CHECK(fabs(tr.m_zz / (tr.m * z0 * z0) - 1) <= q * q / (z0 * z0), "thin torus m_zz %.17g",
          tr.m_zz);
    /* The same ring inside the ball: clipping must change nothing (1e-14: same formula). */
    tippe_moments trc = tippe_torus(Rc, p, q, z0, a);
    CHECK(rel(trc.m, tr.m, tr.m) < 1e-14 && rel(trc.m_rr, tr.m_rr, tr.m_rr) < 1e-14,
          "thin torus inside the ball changed: %.17g vs %.17g", trc.m, tr.m);
    /* A thin circular ring centred on the sphere's surface (Rc = a, z0 = 0) is cut in
     * half, up to the sliver between the chord r = a and the arc r = sqrt(a^2 - z^2),
     * of relative size (2/(3 pi)) p/a; bound it by p/a. */
    tippe_moments half = tippe_torus(a, 1e-6, 1e-6, 0, a);
    double half_ring = M_PI * M_PI * a * 1e-6 * 1e-6;
    CHECK(fabs(half.m / half_ring - 1) <= 1e-6 / a, "half ring m %.17g vs %.17g", half.m,
          half_ring);

    /* Tiny hole through the ball: m = 2 pi r^2 a, m_rr = m r^2/2, m_zz = m a^2/3, with
     * relative corrections O(r^2/a^2) ~ 1e-15 from the rounded ends. */
    double r = 1e-9;
    tippe_moments hole = tippe_tube(0, r, 2.4 * a, 0, a);
    double hm = 2 * M_PI * r * r * a;
    CHECK(rel(hole.m, hm, hm) < 1e-9, "tiny hole m %.17g vs %.17g", hole.m, hm);
    CHECK(rel(hole.m_rr, hm * r * r / 2, hm * r * r / 2) < 1e-9, "tiny hole m_rr %.17g",
          hole.m_rr);
    CHECK(rel(hole.m_zz, hm * a * a / 3, hm * a * a / 3) < 1e-9, "tiny hole m_zz %.17g",
          hole.m_zz);
}

/* Thin parts keep full relative accuracy (1e-9 asked) where a naive difference of
 * big solids would lose ~ log10(a/t) digits. */
static void test_thin_accuracy(void)
{
    const double a = 0.025, t = 1e-9;
    tippe_moments sh = tippe_shell(a, t, 0);
    /* First-order formulas with their first correction; what is left is O((t/a)^2) =
     * 1.6e-15, so the tolerance 1e-9 only measures our rounding. */
    double m1 = 4 * M_PI * a * a * t * (1 - t / a);
    double rr1 = 8.0 / 3.0 * M_PI * a * a * a * a * t * (1 - 2 * t / a);
    CHECK(rel(sh.m, m1, m1) < 1e-9, "thin shell m %.17g vs %.17g", sh.m, m1);
    CHECK(rel(sh.m_rr, rr1, rr1) < 1e-9, "thin shell m_rr %.17g vs %.17g", sh.m_rr, rr1);
    CHECK(rel(sh.m_zz, rr1 / 2, rr1 / 2) < 1e-9, "thin shell m_zz %.17g", sh.m_zz);
    /* Thinner still: factored differences keep rounding-level accuracy at any t/a, while
     * a difference of balls would lose log10(a/t) digits (1e-6 at t = 1e-12 m). */
    for (double tt = 1e-10; tt > 1e-14; tt /= 10) {
        tippe_moments ts = tippe_shell(a, tt, 0);
        double tm1 = 4 * M_PI * a * a * tt * (1 - tt / a);
        double trr1 = 8.0 / 3.0 * M_PI * a * a * a * a * tt * (1 - 2 * tt / a);
        CHECK(rel(ts.m, tm1, tm1) < 1e-9 && rel(ts.m_rr, trr1, trr1) < 1e-9,
              "shell t = %g: m rel err %.3g, m_rr rel err %.3g", tt, rel(ts.m, tm1, tm1),
              rel(ts.m_rr, trr1, trr1));
    }
    tippe_inertia in = tippe_moments_inertia(sh);
    double C1 = 2.0 / 3.0 * in.m * a * a * (1 - t / a);
    CHECK(rel(in.C, C1, C1) < 1e-9, "thin shell C %.17g vs (2/3) m a^2 (1 - t/a)", in.C);
    tippe_moments naive = tippe_moments_sub(tippe_ball(a, 0), tippe_ball(a - t, 0));
    printf("thin shell t = %g m: relative error of m %.2e (ball - ball would give %.2e)\n", t,
           rel(sh.m, m1, m1), rel(naive.m, m1, m1));

    /* Thin-walled tube: area pi (2 r t + t^2). The wall is given as r and r + t, so the
     * reference uses the wall actually represented, (r + t) - r (exact by Sterbenz). */
    double r = 0.003, h = 0.01;
    for (double tt = 1e-9; tt > 1e-14; tt /= 10) {
        double wall = (r + tt) - r;
        tippe_moments tw = tippe_tube(r, r + tt, h, 0.001, 0);
        double tm = M_PI * wall * (2 * r + wall) * h;
        double trr = tm * (r * r + (r + wall) * (r + wall)) / 2;
        CHECK(rel(tw.m, tm, tm) < 1e-9 && rel(tw.m_rr, trr, trr) < 1e-9,
              "thin-walled tube t = %g: m %.17g vs %.17g, m_rr %.17g vs %.17g", tt, tw.m, tm,
              tw.m_rr, trr);
    }

    /* Tiny annular hole through the ball (r_in = 1e-9, r_out = 2e-9): m = 2 pi (r2^2 -
     * r1^2) a up to O(r^2/a^2). */
    tippe_moments th = tippe_tube(1e-9, 2e-9, 3 * a, 0, a);
    double thm = 2 * M_PI * 3e-18 * a;
    CHECK(rel(th.m, thm, thm) < 1e-9, "tiny annular hole m %.17g vs %.17g", th.m, thm);

    /* Thin slices of a ball near its pole: the cylinder of radius >= b over
     * [b - d1, b - d2], clipped to the ball of radius b, has volume
     * pi (b (d1^2 - d2^2) - (d1^3 - d2^3)/3) (integrate (b - z)(b + z) in the depth).
     * b and the depths are powers of two so that the tube's ends are exact: a rounding
     * of an end by ulp(b) would change the solid itself by ulp(b)/d ~ 1e-7. Both sides
     * are then a few roundings with no cancellation, so 1e-13. */
    const double b = 0.03125, d = 0x1p-35; /* d / b = 9.3e-10 */
    const double d2s[2] = {0, d / 4};
    for (int i = 0; i < 2; i++) {
        double d1 = d, d2 = d2s[i];
        tippe_moments cap = tippe_tube(0, b, d1 - d2, b - (d1 + d2) / 2, b);
        double cm = M_PI * (b * (d1 * d1 - d2 * d2) - (d1 * d1 * d1 - d2 * d2 * d2) / 3);
        CHECK(rel(cap.m, cm, cm) < 1e-13, "thin polar slice [b - %g, b - %g]: m %.17g vs %.17g",
              d1, d2, cap.m, cm);
    }
}

/* ------------------------------------------------------------------- composition */

static int moments_close(tippe_moments x, tippe_moments y, double L, double tol)
{
    double sm = fmax(fabs(y.m), 1e-300);
    return rel(x.m, y.m, sm) < tol && fabs(x.m_z - y.m_z) < tol * sm * L &&
           rel(x.m_zz, y.m_zz, fmax(y.m_zz, 1e-300)) < tol &&
           rel(x.m_rr, y.m_rr, fmax(y.m_rr, 1e-300)) < tol;
}

static void test_composition(void)
{
    const double a = 0.025;
    tippe_moments ball = tippe_ball(a, 0);
    /* Core cylinder (clipped) + the annulus around it (clipped) = the ball. Different
     * pieces and caps on each side; O(10) roundings each, so 1e-13. */
    for (double rc = 0.001; rc < a; rc += 0.006) {
        tippe_moments core = tippe_tube(0, rc, 2.2 * a, 0.001, a);
        tippe_moments rest = tippe_tube(rc, 1.1 * a, 2.2 * a, -0.001, a);
        CHECK(moments_close(tippe_moments_add(core, rest), ball, a, 1e-13),
              "core(r=%g) + annulus != ball: m %.17g vs %.17g", rc,
              tippe_moments_add(core, rest).m, ball.m);
        /* and the ball minus its core is that annulus */
        CHECK(moments_close(tippe_moments_sub(ball, core), rest, a, 1e-12),
              "ball - core(r=%g) != annulus", rc);
    }
    /* Slabs: clipped cylinders over a partition of [-a, a] sum to the ball. */
    const double cuts[] = {-a, -0.021, -0.008, 0.0, 0.0033, 0.019, 0.0249, a};
    tippe_moments slabs = {0, 0, 0, 0};
    for (int i = 0; i + 1 < (int)(sizeof cuts / sizeof cuts[0]); i++)
        slabs = tippe_moments_add(slabs, tippe_tube(0, a, cuts[i + 1] - cuts[i],
                                                    (cuts[i] + cuts[i + 1]) / 2, a));
    CHECK(moments_close(slabs, ball, a, 1e-13), "slabs != ball: m %.17g vs %.17g", slabs.m,
          ball.m);
    /* Shell = ball(a) - ball(a - t) when t is not thin (t = a/10: cancellation costs one
     * digit, so 1e-13). */
    CHECK(moments_close(tippe_shell(a, 0.0025, 0.002),
                        tippe_moments_sub(tippe_ball(a, 0.002), tippe_ball(0.0225, 0.002)), a,
                        1e-13),
          "shell != ball - ball");

    /* Shifting: a solid built at z + d equals the one built at z and shifted by d
     * (1e-13: the parallel-axis sums are O(5) roundings). */
    const double d = 0.0037;
    CHECK(moments_close(tippe_moments_shift(tippe_ball(0.01, 0.002), d), tippe_ball(0.01, 0.002 + d),
                        a, 1e-13),
          "shifted ball");
    CHECK(moments_close(tippe_moments_shift(tippe_shell(0.02, 0.003, -0.001), d),
                        tippe_shell(0.02, 0.003, -0.001 + d), a, 1e-13),
          "shifted shell");
    CHECK(moments_close(tippe_moments_shift(tippe_tube(0.003, 0.01, 0.01, 0.004, 0), d),
                        tippe_tube(0.003, 0.01, 0.01, 0.004 + d, 0), a, 1e-13),
          "shifted tube");
    CHECK(moments_close(tippe_moments_shift(tippe_torus(0.02, 0.007, 0.004, 0.001, 0), d),
                        tippe_torus(0.02, 0.007, 0.004, 0.001 + d, 0), a, 1e-13),
          "shifted torus");

    /* The second prototype (shell, rod, moving weight) with the weight moved by d: the
     * centre of mass moves by m_weight d / m_total. z_cm is a ratio of sums whose
     * terms are at most m a, so its rounding is ~1e-15 a; 1e-12 a is far below what
     * a wrong parallel-axis term would give (~d). */
    const double abs_kg_m3 = 1080, iron_kg_m3 = 7870;
    tippe_moments shell = tippe_moments_scale(tippe_shell(a, 0.0025, 0), abs_kg_m3);
    tippe_moments rod = tippe_moments_scale(tippe_tube(0, 0.003, 2 * a, 0, a - 0.0025), iron_kg_m3);
    tippe_moments weight = tippe_moments_scale(tippe_tube(0.003, 0.01, 0.01, 0.005, 0), iron_kg_m3);
    tippe_moments fixed = tippe_moments_add(shell, rod);
    tippe_inertia before = tippe_moments_inertia(tippe_moments_add(fixed, weight));
    tippe_inertia after =
        tippe_moments_inertia(tippe_moments_add(fixed, tippe_moments_shift(weight, d)));
    double expect = weight.m * d / before.m;
    CHECK(fabs((after.z_cm - before.z_cm) - expect) < 1e-12 * a,
          "CoM moved %.17g m, expected m_w d / M = %.17g m", after.z_cm - before.z_cm, expect);
    CHECK(after.m == before.m, "mass changed by a shift");
    CHECK(after.C == before.C, "C changed by an axial shift");
}

/* Random composites: A > 0, C > 0 and C <= 2A (C = I_xx + I_yy - ... i.e. I_zz <=
 * I_xx + I_yy for any body). 2A - C = 2 m var(z) >= 0 is computed as a difference,
 * so allow a rounding slack of 1e-12 C. */
static void test_random_composites(void)
{
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, 20120101);
    const double a = 0.025, mm = 1e-3;
    int bad = 0, n = 400;
    for (int i = 0; i < n; i++) {
        tippe_moments sum = {0, 0, 0, 0};
        int parts = 1 + (int)gsl_rng_uniform_int(rng, 6);
        for (int j = 0; j < parts; j++) {
            double rho = gsl_rng_uniform(rng) * 7500 + 500;
            double z = (gsl_rng_uniform(rng) * 30 - 15) * mm;
            double clip = gsl_rng_uniform(rng) < 0.5 ? a : INFINITY;
            tippe_moments part;
            switch (gsl_rng_uniform_int(rng, 5)) {
            case 0:
                part = tippe_ball((1 + 11 * gsl_rng_uniform(rng)) * mm, z);
                break;
            case 1: {
                double r = (5 + 20 * gsl_rng_uniform(rng)) * mm;
                part = tippe_shell(r, (0.1 * mm + (r - 0.1 * mm) * gsl_rng_uniform(rng)), z);
                break;
            }
            case 2: {
                double ri = 8 * mm * gsl_rng_uniform(rng);
                part = tippe_tube(ri, ri + (0.1 + 10 * gsl_rng_uniform(rng)) * mm,
                                  (0.1 + 40 * gsl_rng_uniform(rng)) * mm, z, clip);
                break;
            }
            case 3: {
                double Rc = (5 + 15 * gsl_rng_uniform(rng)) * mm;
                part = tippe_torus(Rc, (0.5 * mm + 1.3 * Rc * gsl_rng_uniform(rng)),
                                   (0.5 + 7.5 * gsl_rng_uniform(rng)) * mm, z / 3, clip);
                break;
            }
            default: /* a ball with a hole drilled along the axis: a void inside a part */
                part = tippe_moments_sub(tippe_ball(a, 0),
                                         tippe_tube(0, (0.5 + 9.5 * gsl_rng_uniform(rng)) * mm,
                                                    3 * a, 0, a));
                break;
            }
            sum = tippe_moments_add(sum, tippe_moments_scale(part, rho));
        }
        tippe_inertia in = tippe_moments_inertia(sum);
        /* A is also m_rr/2 + m_zz of the composite moved to its centre of mass (shift,
         * not the parallel-axis formula). All parts lie within 45 mm of the origin and
         * z_cm within 15 mm, so the subtraction costs at most ~1 digit: 1e-12. */
        tippe_moments centred = tippe_moments_shift(sum, -in.z_cm);
        double A_centred = centred.m_rr / 2 + centred.m_zz;
        if (rel(in.A, A_centred, A_centred) > 1e-12 && bad++ < 5)
            printf("  composite %d: A %.17g vs %.17g about the CoM\n", i, in.A, A_centred);
        int ok = isfinite(in.A) && isfinite(in.C) && in.m > 0 && in.A > 0 && in.C > 0 &&
                 in.C <= 2 * in.A + 1e-12 * in.C;
        if (!ok && bad++ < 5)
            printf("  composite %d: m %g kg, A %g, C %g kg m^2\n", i, in.m, in.A, in.C);
    }
    CHECK(bad == 0, "%d of %d random composites violate A > 0, C > 0, C <= 2A or A about the CoM", bad, n);
    gsl_rng_free(rng);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_against_numerical_integration();
    test_degenerate();
    test_limits();
    test_thin_accuracy();
    test_composition();
    test_random_composites();
    for (int k = 0; k < 4; k++)
        printf("max relative error vs numerical integration, %s: %.2e\n", kind_name[k],
               max_err_by_kind[k]);
    return check_summary("test_print_geometry");
}
