/* The shipped designs' mass properties, checked against closed forms written
 * out here by hand (not through the geometry module), plus overrides, travel
 * and a few load errors. Run from the repository root. */
#include "tippe/design.h"

#include "check.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* Densities of materials.json, kg/m^3 (ABSplus and iron are the paper's, section 6.1). */
#define RHO_ABS 1080.0
#define RHO_IRON 7870.0
#define RHO_NYLON 1140.0
#define RHO_BRASS 8500.0

/* Mass moments (m, m_z, m_zz, m_rr) about the sphere's centre, SI. */
typedef struct {
    double m, mz, mzz, mrr;
} mom;

static mom add(mom a, mom b) { return (mom){a.m + b.m, a.mz + b.mz, a.mzz + b.mzz, a.mrr + b.mrr}; }
static mom sub(mom a, mom b) { return (mom){a.m - b.m, a.mz - b.mz, a.mzz - b.mzz, a.mrr - b.mrr}; }

/* Solid ball of radius a at the origin. */
static mom ball(double rho, double a)
{
    double v = 4.0 / 3.0 * M_PI * pow(a, 3);
    return (mom){rho * v, 0, rho * 4 * M_PI / 15 * pow(a, 5), rho * 8 * M_PI / 15 * pow(a, 5)};
}

/* Ball of radius a less a coaxial cylinder of radius c through it (napkin
 * ring, half-height H = sqrt(a^2 - c^2)): integrate 2 pi r dr over c..a with
 * z from -sqrt(a^2 - r^2) to +sqrt(a^2 - r^2), substituting u = a^2 - r^2. */
static mom napkin_ring(double rho, double a, double c)
{
    double H = sqrt(a * a - c * c);
    return (mom){rho * 4 * M_PI / 3 * pow(H, 3), 0, rho * 4 * M_PI / 15 * pow(H, 5),
                 rho * 4 * M_PI * (a * a * pow(H, 3) / 3 - pow(H, 5) / 5)};
}

/* Annular cylinder ri..ro, height h, centred at z. */
static mom tube(double rho, double ri, double ro, double h, double z)
{
    double m = rho * M_PI * (ro * ro - ri * ri) * h;
    return (mom){m, m * z, m * (z * z + h * h / 12), m * (ro * ro + ri * ri) / 2};
}

typedef struct {
    double m, zcm, A, C;
} props;

static props props_of(mom a)
{
    props p;
    p.m = a.m;
    p.zcm = a.mz / a.m;
    p.C = a.mrr;
    p.A = a.mrr / 2 + a.mzz - a.m * p.zcm * p.zcm;
    return p;
}

static props props_top(const tippe_top *t)
{
    return (props){t->m, t->com_side * t->eps, t->A, t->C};
}

/* The design's numbers and the hand computation agree to 1e-9: both are
 * closed forms in double precision (the geometry module's clipped solids are
 * closed forms with roots to ~1e-15), while a slip in units, density, sign or
 * a part left out moves them by 1e-3 or more. */
#define REL 1e-9

static void compare(const char *what, double z2_mm, const tippe_top *t, props h)
{
    props d = props_top(t);
    CHECK_CLOSE(d.m, h.m, REL, "%s Z2=%g: m %.15g vs hand %.15g kg", what, z2_mm, d.m, h.m);
    /* z_cm is ~1e-3 m built from the same mass: compare at REL of R. */
    CHECK(fabs(d.zcm - h.zcm) <= REL * t->R, "%s Z2=%g: z_cm %.15g vs hand %.15g m", what, z2_mm,
          d.zcm, h.zcm);
    CHECK_CLOSE(d.A, h.A, REL, "%s Z2=%g: A %.15g vs hand %.15g", what, z2_mm, d.A, h.A);
    CHECK_CLOSE(d.C, h.C, REL, "%s Z2=%g: C %.15g vs hand %.15g", what, z2_mm, d.C, h.C);
}

static tippe_design *load(const char *path, const char *const *sets, int n)
{
    tippe_error err = {0};
    tippe_design *d = NULL;
    int rc = tippe_design_load(path, sets, n, &d, &err);
    CHECK(rc == TIPPE_OK && d, "loading %s: %s", path, err.msg);
    return rc ? NULL : d;
}

/* Setscrew designs: ABS ball less a through hole of radius a, iron screw of
 * radius a and height hs at Z2. */
static void check_setscrew(const char *path, double a_mm, double hs_mm, const double *z2s, int n)
{
    tippe_design *d = load(path, NULL, 0);
    if (!d)
        return;
    const double R = 25e-3, a = a_mm * 1e-3, hs = hs_mm * 1e-3;
    for (int i = 0; i < n; i++) {
        tippe_top t;
        tippe_error err = {0};
        int rc = tippe_design_top(d, z2s[i], &t, &err);
        CHECK(rc == TIPPE_OK, "%s Z2=%g: %s", path, z2s[i], err.msg);
        mom h = add(napkin_ring(RHO_ABS, R, a), tube(RHO_IRON, 0, a, hs, z2s[i] * 1e-3));
        compare(path, z2s[i], &t, props_of(h));
    }
    CHECK_CLOSE(tippe_design_moving_mass_kg(d), RHO_IRON * M_PI * a * a * hs, REL,
                "%s: moving mass %g kg", path, tippe_design_moving_mass_kg(d));
    tippe_design_free(d);
}

/* Shell designs: ABS shell R, thickness ts; rod of radius ar spanning the
 * cavity (ball of the cavity's radius less the napkin ring outside the rod);
 * iron bead ar..rb, height hb at Z2. */
static void check_shell_rod(const char *path, double ts_mm, double ar_mm, double rho_rod,
                            double rb_mm, double hb_mm, const double *z2s, int n)
{
    tippe_design *d = load(path, NULL, 0);
    if (!d)
        return;
    const double R = 25e-3, Ri = R - ts_mm * 1e-3, ar = ar_mm * 1e-3;
    mom fixed = add(sub(ball(RHO_ABS, R), ball(RHO_ABS, Ri)),
                    sub(ball(rho_rod, Ri), napkin_ring(rho_rod, Ri, ar)));
    for (int i = 0; i < n; i++) {
        tippe_top t;
        tippe_error err = {0};
        int rc = tippe_design_top(d, z2s[i], &t, &err);
        CHECK(rc == TIPPE_OK, "%s Z2=%g: %s", path, z2s[i], err.msg);
        mom h = add(fixed, tube(RHO_IRON, ar, rb_mm * 1e-3, hb_mm * 1e-3, z2s[i] * 1e-3));
        compare(path, z2s[i], &t, props_of(h));
    }
    /* The bead's rim (r = rb, z = Z2 + hb/2) meets the cavity's wall at
     * Z2 = sqrt(Ri^2 - rb^2) - hb/2. Parts may overlap by TOL_MM = 1e-6 mm
     * each before it counts, and the corner is sampled 2e-6 mm inside: the
     * computed end is within 1e-5 mm. */
    double lo, hi, Ri_mm = 25 - ts_mm;
    double expect = sqrt(Ri_mm * Ri_mm - rb_mm * rb_mm) - hb_mm / 2;
    tippe_design_contact_travel_mm(d, &lo, &hi);
    CHECK(fabs(hi - expect) < 1e-5 && fabs(lo + expect) < 1e-5,
          "%s: physical travel %.9f .. %.9f mm, expected +-%.9f", path, lo, hi, expect);
    tippe_design_free(d);
}

/* The band of shell-band.json: the ellipse ((r - 22)/4)^2 + (z/7)^2 <= 1 (mm)
 * cut by the cavity r^2 + z^2 <= 22^2, integrated numerically over r. */
typedef struct {
    int moment; /* 0: volume, 1: int z^2, 2: int r^2 */
} band_par;

static double band_integrand(double r, void *vp)
{
    const band_par *p = vp;
    const double rc = 22e-3, ra = 4e-3, az = 7e-3, Rc = 22e-3;
    double x = (r - rc) / ra;
    if (fabs(x) >= 1 || r >= Rc)
        return 0;
    double h = fmin(az * sqrt(1 - x * x), sqrt(Rc * Rc - r * r));
    double w = 2 * M_PI * r;
    return p->moment == 0 ? w * 2 * h : p->moment == 1 ? w * 2 * h * h * h / 3 : w * 2 * h * r * r;
}

static mom band_moments(void)
{
    gsl_integration_workspace *ws = gsl_integration_workspace_alloc(1000);
    double v[3] = {0, 0, 0};
    for (int k = 0; k < 3; k++) {
        band_par p = {k};
        gsl_function f = {band_integrand, &p};
        double err;
        int st = gsl_integration_qags(&f, 18e-3, 22e-3, 0, 1e-12, 1000, ws, &v[k], &err);
        CHECK(st == GSL_SUCCESS, "band quadrature %d: %s", k, gsl_strerror(st));
    }
    gsl_integration_workspace_free(ws);
    return (mom){RHO_ABS * v[0], 0, RHO_ABS * v[1], RHO_ABS * v[2]};
}

static void check_shell_band(const double *z2s, int n)
{
    const char *path = "designs/shell-band.json";
    tippe_design *d = load(path, NULL, 0);
    if (!d)
        return;
    const double R = 25e-3, Ri = 22e-3, ar = 3e-3;
    mom fixed = add(sub(ball(RHO_ABS, R), ball(RHO_ABS, Ri)),
                    sub(ball(RHO_IRON, Ri), napkin_ring(RHO_IRON, Ri, ar)));
    fixed = add(fixed, band_moments());
    for (int i = 0; i < n; i++) {
        tippe_top t;
        tippe_error err = {0};
        CHECK(tippe_design_top(d, z2s[i], &t, &err) == TIPPE_OK, "%s: %s", path, err.msg);
        mom h = add(fixed, tube(RHO_IRON, ar, 6e-3, 10e-3, z2s[i] * 1e-3));
        compare(path, z2s[i], &t, props_of(h));
    }
    double lo, hi, expect = sqrt(22.0 * 22.0 - 6.0 * 6.0) - 5;
    tippe_design_contact_travel_mm(d, &lo, &hi);
    CHECK(fabs(hi - expect) < 1e-5, "%s: physical travel ends at %.9f, expected %.9f", path, hi,
          expect); /* 1e-5 mm: see check_shell_rod */
    tippe_design_free(d);
}

/* Facts every design must satisfy at every Z2 in its travel. */
static void check_invariants(const char *path)
{
    tippe_design *d = load(path, NULL, 0);
    if (!d)
        return;
    double from, to;
    tippe_design_travel_mm(d, &from, &to);
    double mw = tippe_design_moving_mass_kg(d), C0 = 0;
    const double step_mm = 0.5;
    for (int i = 0; i <= 8; i++) {
        double z2 = from + (to - from) * i / 8.0;
        tippe_top t, t2;
        tippe_error err = {0};
        CHECK(tippe_design_top(d, z2, &t, &err) == TIPPE_OK, "%s Z2=%g: %s", path, z2, err.msg);
        /* Axisymmetric: A_x + A_y = C + 2 int z^2 dm >= C, so C <= 2A; 1e-12
         * covers roundoff in A (a difference of ~1e-5 kg m^2 terms). */
        CHECK(t.A > 0 && t.C > 0 && t.C <= 2 * t.A * (1 + 1e-12), "%s Z2=%g: A %g, C %g", path,
              z2, t.A, t.C);
        CHECK(t.eps >= 0 && t.eps < t.R, "%s Z2=%g: eps %g m, R %g m", path, z2, t.eps, t.R);
        /* The weight slides along the axis: C does not change (paper, section
         * 6.1); 1e-12 relative is roundoff on sums of ~10 terms. */
        if (i == 0)
            C0 = t.C;
        CHECK_CLOSE(t.C, C0, 1e-12, "%s: C %.17g at Z2=%g, %.17g at the start", path,
                    t.C, z2, C0);
        /* Moving the weight by d moves the CoM by m_w d / m (first moment
         * m z_cm = fixed + m_w Z2). z_cm ~ 1e-3 m from sums of a few terms:
         * roundoff < 1e-17 m, so 1e-13 m is strict yet safe. */
        tippe_design_top_any(d, z2 + step_mm, &t2);
        double dz = props_top(&t2).zcm - props_top(&t).zcm;
        CHECK(fabs(dz - mw * step_mm * 1e-3 / t.m) < 1e-13, "%s Z2=%g: CoM moved %.17g m, "
              "expected %.17g m", path, z2, dz, mw * step_mm * 1e-3 / t.m);
    }
    /* Where the weight sits symmetric in a symmetric body, the CoM is at the
     * centre: the design reports eps = 0 there. */
    tippe_top t0;
    tippe_design_top_any(d, 0, &t0);
    CHECK(t0.eps == 0 && t0.com_side == 0, "%s: Z2=0 gives eps %g m, side %d", path, t0.eps,
          t0.com_side);
    tippe_error err = {0};
    tippe_top t;
    CHECK(tippe_design_top(d, to + 0.5, &t, &err) == TIPPE_EINPUT && strstr(err.msg, "travel"),
          "%s: Z2 beyond the travel was accepted (%s)", path, err.msg);
    double clo, chi;
    tippe_design_contact_travel_mm(d, &clo, &chi);
    CHECK(clo <= from && chi >= to, "%s: physical travel %g..%g does not hold the travel", path,
          clo, chi);
    tippe_design_free(d);
}

static void check_overrides(void)
{
    const char *m12 = "designs/m12-setscrew.json";
    tippe_design *base = load(m12, NULL, 0);
    if (!base)
        return;
    double mw = tippe_design_moving_mass_kg(base);

    const char *brass[] = {"parts.screw.material=brass"};
    tippe_design *d = load(m12, brass, 1);
    if (d) {
        /* Same volume, other density: the mass scales exactly by the ratio. */
        CHECK_CLOSE(tippe_design_moving_mass_kg(d), mw * RHO_BRASS / RHO_IRON, 1e-12,
                    "brass screw %g kg vs %g", tippe_design_moving_mass_kg(d),
                    mw * RHO_BRASS / RHO_IRON);
        tippe_design_free(d);
    }
    const char *shorter[] = {"parts.screw.height_mm=10"};
    if ((d = load(m12, shorter, 1))) {
        CHECK_CLOSE(tippe_design_moving_mass_kg(d), mw * 10 / 15, 1e-12,
                    "10 mm screw %g kg vs %g", tippe_design_moving_mass_kg(d), mw * 10 / 15);
        tippe_design_free(d);
    }
    const char *inline_density[] = {"parts.screw.density_g_cm3=7.87"};
    if ((d = load(m12, inline_density, 1))) {
        CHECK(tippe_design_moving_mass_kg(d) == mw, "inline density: %g vs %g kg",
              tippe_design_moving_mass_kg(d), mw);
        tippe_design_free(d);
    }
    /* A bigger sphere: the ball (radius defaults to the sphere's) and the
     * through hole (no height: spans the sphere) follow radius_mm. */
    const char *bigger[] = {"radius_mm=30"};
    if ((d = load(m12, bigger, 1))) {
        tippe_top t;
        tippe_design_top_any(d, 12, &t);
        mom h = add(napkin_ring(RHO_ABS, 30e-3, 5.5e-3), tube(RHO_IRON, 0, 5.5e-3, 15e-3, 12e-3));
        compare("m12 radius_mm=30", 12, &t, props_of(h));
        double lo, hi;
        tippe_design_contact_travel_mm(d, &lo, &hi);
        CHECK(lo == -30 && hi == 30, "protruding screw's centre may reach the surface: %g..%g",
              lo, hi);
        tippe_design_free(d);
    }
    const char *by_index[] = {"parts[2].height_mm=10"};
    if ((d = load(m12, by_index, 1))) {
        CHECK_CLOSE(tippe_design_moving_mass_kg(d), mw * 10 / 15, 1e-12, "parts[2] override");
        tippe_design_free(d);
    }
    tippe_design_free(base);

    struct {
        const char *set, *want;
    } bad[] = {
        {"parts.bolt.material=iron", "no part named 'bolt'"},
        {"parts.screw.colour=red", "'colour' is not a part field"},
        {"parts.screw.height_mm=ten", "'ten' is not a JSON value"},
        {"parts.screw.height_mm=-1", "parts[2].height_mm: must be positive"},
        {"parts.screw.material=unobtainium", "unknown material 'unobtainium'"},
        {"radius=25", "'radius' is not a design field"},
        {"travel_mm=[0,30]", "travel_mm: ends at 30 mm"},
        {"radius_mm", "expected FIELD=VALUE"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        tippe_error err = {0};
        tippe_design *x = NULL;
        const char *sets[] = {bad[i].set};
        int rc = tippe_design_load(m12, sets, 1, &x, &err);
        CHECK(rc == TIPPE_EINPUT && !x && strstr(err.msg, bad[i].want) &&
                  strstr(err.msg, bad[i].set),
              "--set %s: rc %d, message '%s' (want '%s' and the override named)", bad[i].set, rc,
              err.msg, bad[i].want);
        tippe_design_free(x);
    }
}

/* The materials table: every entry has a source and a printable flag; the
 * shipped designs' parts are printable exactly when they are ABSplus; a flag
 * that is not true/false is refused naming the table and the material. */
static void check_materials(void)
{
    const char *m12 = "designs/m12-setscrew.json";
    tippe_design *d = load(m12, NULL, 0);
    if (d) {
        tippe_design_part_info info;
        for (int i = 0; i < tippe_design_n_parts(d); i++) {
            CHECK(tippe_design_part(d, i, &info) == TIPPE_OK, "part %d", i);
            int want = !strcmp(info.material, "ABSplus"); /* body and its hole */
            CHECK(info.printable == want && tippe_design_part_printable(d, i) == want,
                  "part %s (%s): printable %d, want %d", info.name, info.material,
                  info.printable, want);
        }
        CHECK(!tippe_design_part_printable(d, 99), "out of range is not printable");
        tippe_design_free(d);
    }
    /* A bought weight swapped for each hardware metal, and the body for each
     * filament: all load, and the flag follows the table. */
    const char *filaments[] = {"ABS", "PLA", "PETG", "ASA", "TPU", "nylon-filament"};
    const char *hardware[] = {"steel", "stainless", "brass", "iron", "tungsten-putty", "lead",
                              "nylon", "aluminium"};
    char set[2][80];
    for (size_t i = 0; i < 8; i++) {
        snprintf(set[0], sizeof set[0], "parts.screw.material=%s", hardware[i]);
        snprintf(set[1], sizeof set[1], "parts.body.material=%s", filaments[i % 6]);
        const char *sets[] = {set[0], set[1]};
        if ((d = load(m12, sets, 2))) {
            CHECK(tippe_design_part_printable(d, 0) && tippe_design_part_printable(d, 1) &&
                      !tippe_design_part_printable(d, 2),
                  "%s body, %s screw", filaments[i % 6], hardware[i]);
            tippe_design_free(d);
        }
    }
    /* The generic ABS filament is lighter than the paper's ABSplus (1.04 vs
     * 1.08 g/cm^3): the body's mass scales exactly with the density. */
    const char *abs[] = {"parts.body.material=ABS"};
    tippe_design *a = load(m12, abs, 1), *b = load(m12, NULL, 0);
    if (a && b) {
        tippe_design_part_info ia, ib;
        tippe_design_part(a, 0, &ia);
        tippe_design_part(b, 0, &ib);
        CHECK_CLOSE(ia.mass_kg / ib.mass_kg, 1.04 / 1.08, 1e-14, "ABS vs ABSplus body");
    }
    tippe_design_free(a);
    tippe_design_free(b);

    /* A broken flag in a private table. */
    const char *dir = getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp";
    char tab[512], des[512];
    snprintf(tab, sizeof tab, "%s/tippe-test-materials-%d.json", dir, (int)getpid());
    snprintf(des, sizeof des, "%s/tippe-test-design-%d.json", dir, (int)getpid());
    FILE *f = fopen(tab, "w");
    FILE *g = fopen(des, "w");
    if (f && g) {
        fprintf(f, "{\"goo\": {\"density_g_cm3\": 2, \"source\": \"x\", \"printable\": \"yes\"}}");
        fprintf(g, "{\"name\": \"t\", \"radius_mm\": 10, \"travel_mm\": [0, 1], "
                   "\"materials\": \"%s\", \"parts\": [{\"name\": \"b\", \"shape\": "
                   "\"ball\", \"material\": \"goo\"}]}",
                strrchr(tab, '/') + 1);
    }
    if (f)
        fclose(f);
    if (g)
        fclose(g);
    tippe_error err = {0};
    tippe_design *x = NULL;
    int rc = tippe_design_load(des, NULL, 0, &x, &err);
    CHECK(rc == TIPPE_EINPUT && strstr(err.msg, "goo.printable") && strstr(err.msg, "true or false"),
          "bad printable flag: rc %d '%s'", rc, err.msg);
    tippe_design_free(x);
    remove(tab);
    remove(des);
}

/* Issue 19.6: where the screw stands out of the sphere the top rests on it and
 * the model (contact on the sphere only) does not apply. The M12 screw
 * (radius a = 5.5, height h = 15, R = 25) has its rim at (a, Z2 + h/2): it
 * leaves the sphere at Z2 = sqrt(R^2 - a^2) - h/2 = 16.8875 mm, and at Z2 its
 * rim stands rho - R out, rho = hypot(a, Z2 + h/2). The table direction at
 * polar angle alpha meets the rim while rho cos(alpha - beta) > R, beta =
 * atan(a / (Z2 + h/2)): up to beta + acos(R / rho). The design samples r (rim
 * radius exactly, 2e-6 mm either side) and erodes by 1e-6 mm: 1e-5 mm and 1e-4
 * rad cover that, and a wrong formula (the face instead of the rim, the wrong
 * pole) is off by 0.5 mm or 0.2 rad. */
static void check_protrusion(void)
{
    const double R = 25, a = 5.5, h = 15;
    tippe_design *d = load("designs/m12-setscrew.json", NULL, 0);
    if (!d)
        return;
    double lo, hi;
    tippe_design_sphere_only_mm(d, &lo, &hi);
    const double edge = sqrt(R * R - a * a) - h / 2;
    CHECK(fabs(hi - edge) < 1e-5 && fabs(lo + edge) < 1e-5, "sphere only %.9g .. %.9g, want +-%.9g",
          lo, hi, edge);
    tippe_design_protrusion p;
    CHECK(tippe_design_protrusion_at(d, 16.8, &p) == 0 && p.protrusion_mm == 0 && !p.part[0],
          "Z2 = 16.8 mm: inside, yet %g mm out", p.protrusion_mm);
    const double z2s[] = {17.5, 20, -17.5};
    for (int k = 0; k < 3; k++) {
        const double z2 = z2s[k], top = fabs(z2) + h / 2, rho = hypot(a, top);
        const double theta_hi = atan(a / top) + acos(R / rho);
        CHECK(tippe_design_protrusion_at(d, z2, &p) == 1, "Z2 = %g: no protrusion", z2);
        CHECK(fabs(p.protrusion_mm - (rho - R)) < 1e-5, "Z2 = %g: %.9g mm out, want %.9g", z2,
              p.protrusion_mm, rho - R);
        CHECK(!strcmp(p.part, "screw") && p.pole == (z2 > 0 ? 1 : -1), "Z2 = %g: '%s' pole %d",
              z2, p.part, p.pole);
        /* the centre of mass is on the screw's side: theta = 0 rests on it (at
         * Z2 = 17.5 mm the face is flush with the pole: the band starts there
         * to within the erosion, acos(1 - 1e-6 / R) < 1e-3 rad) */
        CHECK(p.theta_from_rad < 1e-3 && fabs(p.theta_to_rad - theta_hi) < 1e-4,
              "Z2 = %g: theta %.6f .. %.6f, want 0 .. %.6f", z2, p.theta_from_rad,
              p.theta_to_rad, theta_hi);
    }
    tippe_design_free(d);
    /* A screw lighter than the ABS it replaces: the centre of mass goes to -z,
     * theta = 0 rests on the -z pole and the screw is met only turned over */
    const char *dir = getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp";
    char light[512];
    snprintf(light, sizeof light, "%s/tippe-test-light-%d.json", dir, (int)getpid());
    FILE *f = fopen(light, "w");
    if (f) {
        /* a blind hole in the +z half, the screw lighter than the ABS it replaces */
        fprintf(f, "{\"name\": \"light\", \"radius_mm\": 25, \"travel_mm\": [8, 20], "
                   "\"parts\": [{\"name\": \"body\", \"shape\": \"ball\", \"density_g_cm3\": 1.08},"
                   "{\"name\": \"hole\", \"shape\": \"cylinder\", \"radius_mm\": 5.5, "
                   "\"height_mm\": 25, \"z_mm\": 12.5, \"clip\": \"sphere\", \"void\": true, "
                   "\"cut_from\": \"body\"}, {\"name\": \"screw\", \"shape\": \"cylinder\", "
                   "\"radius_mm\": 5.5, \"height_mm\": 15, \"density_g_cm3\": 0.1, "
                   "\"moving\": true, \"may_protrude\": true}]}");
        fclose(f);
    }
    if ((d = load(light, NULL, 0))) {
        const double top = 20 + h / 2, rho = hypot(a, top);
        const double theta_hi = atan(a / top) + acos(R / rho);
        tippe_top t;
        tippe_design_top_any(d, 20, &t);
        CHECK(t.com_side < 0, "light screw: com_side %d", t.com_side);
        CHECK(tippe_design_protrusion_at(d, 20, &p) == 1 && p.pole == 1 &&
                  fabs(p.theta_to_rad - M_PI) < 1e-12 &&
                  fabs(p.theta_from_rad - (M_PI - theta_hi)) < 1e-4,
              "light screw: pole %d theta %.6f .. %.6f, want %.6f .. pi", p.pole,
              p.theta_from_rad, p.theta_to_rad, M_PI - theta_hi);
        tippe_design_free(d);
    }
    remove(light);
    /* The M3 design's travel ends just inside (sqrt(R^2 - 1.5^2) - 1.5 = 23.455 mm) */
    if ((d = load("designs/m3-setscrew.json", NULL, 0))) {
        CHECK(tippe_design_protrusion_at(d, 23.4, &p) == 0, "m3 at 23.4 mm: %g mm out",
              p.protrusion_mm);
        tippe_design_free(d);
    }
    /* Parts longer than the ball, or absurd numbers, are refused naming the field. */
    const struct {
        const char *set, *want;
    } bad[] = {
        {"parts.screw.height_mm=50.1", "parts[2].height_mm: 50.1 mm is more than the sphere's "
                                       "diameter (50 mm)"},
        {"parts.screw.radius_mm=1e308", "parts[2].radius_mm: 1e+308 mm"},
        {"parts.screw.z_mm=1e308", "parts[2].z_mm: 1e+308 mm"},
        {"radius_mm=1e308", "radius_mm: 1e+308 mm is larger than any tippe top"},
        {"radius_mm=0.025", "radius_mm: 0.025 mm is smaller than any tippe top"},
        {"parts.screw.density_g_cm3=22.7", "parts[2].density_g_cm3: 22.7 g/cm^3 is denser"},
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        tippe_error err = {0};
        tippe_design *x = NULL;
        const char *sets[] = {bad[k].set};
        int rc = tippe_design_load("designs/m12-setscrew.json", sets, 1, &x, &err);
        CHECK(rc == TIPPE_EINPUT && !x && strstr(err.msg, bad[k].want), "%s: rc %d '%s'",
              bad[k].set, rc, err.msg);
        tippe_design_free(x);
    }
    /* the screw exactly as long as the ball still loads (flush at both poles) */
    const char *flush[] = {"parts.screw.height_mm=50", "travel_mm=[0,0.1]"};
    if ((d = load("designs/m12-setscrew.json", flush, 2)))
        tippe_design_free(d);
}

/* print.model_error moves the printed body by its largest measured error against the slicer:
 * the mass by -1.2 % and the body's A/C by +0.006 per unit (exact arithmetic on the same layers:
 * 1e-12 allows the rounding of a few products) */
static void check_model_error(void)
{
    const char *one[] = {"parts.body.print.model_error=1"};
    tippe_design *d0 = NULL, *d1 = NULL;
    tippe_error err = {0};
    CHECK(tippe_design_load("designs/m12-setscrew-printed.json", NULL, 0, &d0, &err) == TIPPE_OK &&
              tippe_design_load("designs/m12-setscrew-printed.json", one, 1, &d1, &err) ==
                  TIPPE_OK,
          "model_error loads: %s", err.msg);
    tippe_design_print_info p0, p1;
    if (d0 && d1 && !tippe_design_part_print(d0, 0, &p0) && !tippe_design_part_print(d1, 0, &p1)) {
        CHECK_CLOSE(p1.printed_mass_kg, p0.printed_mass_kg * (1 - TIPPE_PRINT_MODEL_ERROR_MASS),
                    1e-12, "the mass moved by the model's error");
        CHECK_CLOSE(p1.body_A_over_C - p0.body_A_over_C, TIPPE_PRINT_MODEL_ERROR_AC, 1e-9,
                    "the body's A/C moved by the model's error");
    }
    tippe_design_free(d0);
    tippe_design_free(d1);
}

int main(void)
{
    check_model_error();
    const double m12_z2[] = {0, 2.5, 8, 12.5, 17.5, 20};
    const double m3_z2[] = {0, 3, 10, 18, 23.4};
    const double rod_z2[] = {0, 4, 9.5, 15};
    check_setscrew("designs/m12-setscrew.json", 5.5, 15, m12_z2, 6);
    check_setscrew("designs/m3-setscrew.json", 1.5, 3, m3_z2, 5);
    check_shell_rod("designs/shell-rod-iron.json", 2.5, 3, RHO_IRON, 10, 10, rod_z2, 4);
    check_shell_rod("designs/shell-rod-nylon.json", 2.5, 2.5, RHO_NYLON, 10, 10, rod_z2, 4);
    check_shell_band(rod_z2, 4);
    const char *all[] = {"designs/m12-setscrew.json", "designs/m3-setscrew.json",
                         "designs/shell-rod-iron.json", "designs/shell-rod-nylon.json",
                         "designs/shell-band.json"};
    for (int i = 0; i < 5; i++)
        check_invariants(all[i]);
    check_overrides();
    check_materials();
    check_protrusion();
    return check_summary("test_design");
}
