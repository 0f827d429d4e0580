/* The slicer's rules layer by layer (src/print/print_slicer.c) against hand
 * computations on parts whose layers are known in closed form: a cylinder
 * (every layer the same disc), a tube, and the bulk factor of the gyroid
 * recomputed from its level set; then the design-level wiring (the weighing
 * solves the infill back). The model against PrusaSlicer's own G-code is in
 * tests/test_slicer.sh (run where prusa-slicer is installed). */
#include "tippe/design.h"

#include "check.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define MM 1e-3

static double spacing(double w, double t) { return w - t * (1 - M_PI / 4); }

/* A cylinder of radius R, height H (a whole number of 0.2 mm layers), no
 * perimeters and no top/bottom layers, 100 % rectilinear: every layer is its
 * disc, so the deposit is the cylinder exactly (relative 1e-12: sums of ~100
 * closed forms). */
static void test_plain_cylinder(void)
{
    tippe_solid cyl = {.kind = TIPPE_SOLID_TUBE, .radius = 10 * MM, .height = 20 * MM};
    tippe_print_settings s = tippe_print_defaults();
    s.perimeters = 0;
    s.top_bottom_layers = 0;
    s.infill = 1;
    s.pattern = TIPPE_PATTERN_RECTILINEAR;
    s.first_layer_width_mm = 0;
    tippe_print_sliced o;
    tippe_error err;
    CHECK(tippe_print_slice_moments(&cyl, NULL, 0, &s, 0, &o, &err) == 0, "%s", err.msg);
    tippe_moments want = tippe_tube(0, 10 * MM, 20 * MM, 0, 0);
    CHECK(o.n_layers == 100, "layers %d", o.n_layers);
    CHECK_CLOSE(o.deposit.m, want.m, 1e-12, "cylinder volume");
    CHECK_CLOSE(o.deposit.m_zz, want.m_zz, 1e-12, "cylinder m_zz");
    CHECK_CLOSE(o.deposit.m_rr, want.m_rr, 1e-12, "cylinder m_rr");
    CHECK(fabs(o.bed_z_m + 10 * MM) < 1e-12 && fabs(o.top_z_m - 10 * MM) < 1e-12,
          "bed %g, top %g", o.bed_z_m, o.top_z_m);
}

/* The same cylinder with the defaults: 2 perimeters, 4 layers (0.7/0.5 mm at
 * least), 15 % gyroid. Per layer, by hand from the rules of docs/slicer-rules.md:
 * walls the ring from d0 = (w - s)/2 to d0 + 2 s inside the rim; the infill disc
 * r < R - d_f, d_f = d0 + 2 s - 0.25 s; the first layer (0.42 mm lines) and the
 * last, and the 3 layers next to each (the vertical shells: a disc cylinder has
 * a top and a bottom surface only there), solid; the rest sparse at bulk x 15 %
 * plus the anchor band along r = R - d_f: lines d = s / (bulk f) apart joined
 * along the boundary where d / sin(theta) <= 12 mm (half of it traced), else
 * anchored by 2.5 mm each, a sin(theta) / d of it; averaged over theta in closed
 * form, s (2/pi) [(pi/2 - theta_c)/2 + (a/d)(1 - cos theta_c)], sin theta_c =
 * d / 12 mm, less the strip s/2 x bulk f the line ends leave. The model takes
 * the mean by a 256-point rule: 1e-4 relative on the anchors. */
static void test_default_cylinder(void)
{
    const double R = 10 * MM, H = 20 * MM, h = 0.2 * MM;
    tippe_solid cyl = {.kind = TIPPE_SOLID_TUBE, .radius = R, .height = H};
    tippe_print_settings s = tippe_print_defaults();
    tippe_print_sliced o;
    tippe_error err;
    CHECK(tippe_print_slice_moments(&cyl, NULL, 0, &s, 0, &o, &err) == 0, "%s", err.msg);
    double bulk = tippe_print_pattern_bulk(TIPPE_PATTERN_GYROID), f = 0.15;
    double walls = 0, solid = 0, sparse = 0, anchors = 0;
    const double s_reg = spacing(0.45 * MM, h), dd = s_reg / (bulk * f), a = 2.5 * MM;
    const double tc = asin(dd / (12 * MM));
    const double lambda = s_reg * (2 / M_PI) * (0.5 * (M_PI / 2 - tc) + a / dd * (1 - cos(tc))) -
                          0.5 * s_reg * bulk * f;
    for (int i = 0; i < 100; i++) {
        double w = (i == 0 ? 0.42 : 0.45) * MM, sp = spacing(w, h);
        double d0 = 0.5 * (w - sp), d_f = d0 + 2 * sp - 0.25 * sp;
        double ring = M_PI * (pow(R - d0, 2) - pow(R - d0 - 2 * sp, 2)) * h;
        double disc = M_PI * pow(R - d_f, 2) * h;
        walls += ring;
        /* solid: the first and last layer (bottom, top surfaces) and the
         * three above / below them (4 layers each way); the first solid layer
         * over the sparse infill (96) is a bridge over infill
         * (PrintObject::bridge_over_infill), 0.4 mm round threads 0.45 mm apart */
        if (i == 96)
            solid += disc / h * M_PI * 0.4 * MM * 0.4 * MM / 4 / (0.45 * MM);
        else if (i < 4 || i > 96)
            solid += disc;
        else {
            sparse += bulk * f * disc;
            anchors += lambda * 2 * M_PI * (R - d_f) * h;
        }
    }
    CHECK_CLOSE(o.wall_m3, walls, 1e-12, "walls");
    CHECK_CLOSE(o.solid_m3, solid, 1e-12, "solid infill");
    CHECK_CLOSE(o.sparse_m3, sparse, 1e-12, "sparse infill");
    CHECK_CLOSE(o.anchor_m3, anchors, 1e-12, "anchors");
    CHECK_CLOSE(o.deposit.m, walls + solid + sparse + anchors, 1e-12, "total");
    printf("cylinder R 10 H 20 mm, defaults: walls %.1f, solid %.1f, sparse %.1f, anchors %.1f "
           "mm^3\n",
           walls * 1e9, solid * 1e9, sparse * 1e9, anchors * 1e9);
    /* tippe_print_sliced_at reproduces the deposit and moves it with the infill */
    tippe_moments at = tippe_print_sliced_at(&o, &s, 0.15, NULL, NULL);
    CHECK_CLOSE(at.m, o.deposit.m, 1e-14, "sliced_at at the same infill");
    double sp40 = 0;
    tippe_moments m40 = tippe_print_sliced_at(&o, &s, 0.4, &sp40, NULL);
    CHECK_CLOSE(sp40, sparse / 0.15 * 0.4, 1e-12, "sparse at 40 %%");
    CHECK(m40.m > at.m, "more infill, more mass");
    double disc96 = M_PI * pow(R - (0.5 * (0.45 * MM - s_reg) + 1.75 * s_reg), 2) * h;
    double bridge96 = disc96 / h * M_PI * 0.4 * MM * 0.4 * MM / 4 / (0.45 * MM);
    /* thick_bridges off: the bridge is the solid infill's own line, no extra
     * (LayerRegion::bridging_flow) */
    tippe_print_settings thin = s;
    thin.thick_bridges = 0;
    tippe_print_sliced o2;
    CHECK(tippe_print_slice_moments(&cyl, NULL, 0, &thin, 0, &o2, &err) == 0, "%s", err.msg);
    CHECK_CLOSE(o2.solid_m3, solid - bridge96 + disc96, 1e-12, "thin bridges: solid infill");
    /* at 100 % there is no bridge over infill (fill_density 100 skips it), and
     * the cylinder has no bridge over air: thick and thin bridges deposit the same */
    CHECK_CLOSE(tippe_print_sliced_at(&o, &s, 1.0, NULL, NULL).m,
                tippe_print_sliced_at(&o2, &thin, 1.0, NULL, NULL).m, 1e-12,
                "100 %%: no bridge over infill");
}

/* A tube (a cylinder with a hole through it): its layers are rings with walls
 * at both circles; the shell rule makes no solid away from the ends. The walls'
 * volume is closed form; the infill region is the ring between the two d_f. */
static void test_tube_walls(void)
{
    const double R = 10 * MM, a = 3 * MM, H = 10 * MM, h = 0.2 * MM;
    tippe_solid tube = {.kind = TIPPE_SOLID_TUBE, .radius = R, .inner_radius = a, .height = H};
    tippe_print_settings s = tippe_print_defaults();
    s.first_layer_width_mm = 0;
    tippe_print_sliced o;
    tippe_error err;
    CHECK(tippe_print_slice_moments(&tube, NULL, 0, &s, 0, &o, &err) == 0, "%s", err.msg);
    double sp = spacing(0.45 * MM, h), d0 = 0.5 * (0.45 * MM - sp), W = 2 * sp;
    double per_layer = M_PI * (pow(R - d0, 2) - pow(R - d0 - W, 2)) +
                       M_PI * (pow(a + d0 + W, 2) - pow(a + d0, 2));
    CHECK_CLOSE(o.wall_m3, 50 * per_layer * h, 1e-12, "tube walls, both circles");
}

/* The gyroid's bulk factor: PrusaSlicer scales the gyroid to spacing /
 * (2.44 density) (FillGyroid.cpp), so its lines deposit 2.44 x L of the
 * density, L the mean length per unit area of the level set sin x cos y +
 * sin y cos z + sin z cos x = 0 in a horizontal slice over one period of z.
 * Recomputed here by the co-area formula (length per area = the mean of
 * |grad g| over |g| < e, over 2e) on a 600 x 600 x 24 grid: its sampling
 * error is ~1e-3 (halving the grid moves it by 4e-4), so 3e-3. */
static void test_gyroid_bulk(void)
{
    const int n = 600, nz = 24;
    const double e = 0.01, step = 2 * M_PI / n;
    double sum = 0;
    for (int k = 0; k < nz; k++) {
        double z = 2 * M_PI * k / nz, sz = sin(z), cz = cos(z);
        double acc = 0;
        for (int i = 0; i < n; i++) {
            double x = i * step, sx = sin(x), cx = cos(x);
            for (int j = 0; j < n; j++) {
                double y = j * step, sy = sin(y), cy = cos(y);
                double g = sx * cy + sy * cz + sz * cx;
                if (fabs(g) < e)
                    acc += hypot(cx * cy - sz * sx, -sx * sy + cy * cz);
            }
        }
        sum += acc / ((double)n * n) / (2 * e);
    }
    double bulk = 2.44 * sum / nz;
    CHECK(fabs(bulk - tippe_print_pattern_bulk(TIPPE_PATTERN_GYROID)) < 3e-3,
          "gyroid bulk: recomputed %.4f, model %.4f", bulk,
          tippe_print_pattern_bulk(TIPPE_PATTERN_GYROID));
    printf("gyroid bulk factor: recomputed %.4f, model %.4f\n", bulk,
           tippe_print_pattern_bulk(TIPPE_PATTERN_GYROID));
    CHECK(tippe_print_pattern_parse("gyroid") == TIPPE_PATTERN_GYROID &&
              tippe_print_pattern_parse("Gyroid") < 0,
          "pattern names are PrusaSlicer's, case-sensitive");
}

/* solid_infill_below_area (LayerRegion::prepare_fill_surfaces): a cylinder of
 * radius 4 mm, whose infill disc (radius 4 - d_f = 3.27 mm, 33.5 mm^2) is one
 * island on every layer: at 70 mm^2 every layer is solid (no sparse infill, no
 * anchors, no bridge over infill), each the disc's area times its height (sums
 * of 50 closed forms: 1e-12); at 30 mm^2 nothing changes from 0. */
static void test_solid_below_area(void)
{
    const double R = 4 * MM, H = 10 * MM, h = 0.2 * MM;
    tippe_solid cyl = {.kind = TIPPE_SOLID_TUBE, .radius = R, .height = H};
    tippe_print_settings s = tippe_print_defaults();
    tippe_print_sliced o0, o30, o70;
    tippe_error err;
    CHECK(tippe_print_slice_moments(&cyl, NULL, 0, &s, 0, &o0, &err) == 0, "%s", err.msg);
    s.solid_infill_below_area_mm2 = 30;
    CHECK(tippe_print_slice_moments(&cyl, NULL, 0, &s, 0, &o30, &err) == 0, "%s", err.msg);
    s.solid_infill_below_area_mm2 = 70;
    CHECK(tippe_print_slice_moments(&cyl, NULL, 0, &s, 0, &o70, &err) == 0, "%s", err.msg);
    double solid = 0;
    for (int i = 0; i < 50; i++) {
        double w = (i == 0 ? 0.42 : 0.45) * MM, sp = spacing(w, h);
        double d_f = 0.5 * (w - sp) + 1.75 * sp;
        solid += M_PI * pow(R - d_f, 2) * h;
    }
    CHECK(o70.sparse_m3 == 0 && o70.anchor_m3 == 0, "70 mm^2: no sparse infill (%g, %g m^3)",
          o70.sparse_m3, o70.anchor_m3);
    CHECK_CLOSE(o70.solid_m3, solid, 1e-12, "70 mm^2: every layer's disc solid");
    CHECK(o0.sparse_m3 > 0, "0 mm^2: sparse infill in the middle");
    CHECK_CLOSE(o30.deposit.m, o0.deposit.m, 1e-15, "30 mm^2: as 0 (the island is 33.5 mm^2)");
}

/* A pattern whose deposit depends on the part's shape is refused, saying so. */
static void test_unmodelled_pattern(void)
{
    tippe_solid ball = {.kind = TIPPE_SOLID_BALL, .radius = 10 * MM};
    tippe_print_settings s = tippe_print_defaults();
    s.pattern = TIPPE_PATTERN_LIGHTNING;
    tippe_print_sliced o;
    tippe_error err = {0};
    CHECK(tippe_print_slice_moments(&ball, NULL, 0, &s, 0, &o, &err) == TIPPE_EINPUT &&
              strstr(err.msg, "lightning") && strstr(err.msg, "G-code"),
          "lightning: %s", err.msg);
}

/* Design level: the printed M12 body's mass is the deposit times ABSplus's
 * density, and a weighing solves the infill back (bisection to 1e-15 of the
 * infill range; the mass is linear in it, so 1e-9 relative). */
static void test_design_weighing(void)
{
    tippe_design *d = NULL, *w = NULL;
    tippe_error err;
    const char *sets[] = {"parts.body.print.infill=0.3"};
    CHECK(tippe_design_load("designs/m12-setscrew-printed.json", sets, 1, &d, &err) == 0, "%s",
          err.msg);
    if (!d)
        return;
    tippe_design_print_info pi;
    tippe_design_part_print(d, 0, &pi);
    char set_mass[96];
    snprintf(set_mass, sizeof set_mass, "parts.body.print.measured_mass_g=%.17g",
             pi.printed_mass_kg * 1e3);
    const char *sets2[] = {set_mass};
    CHECK(tippe_design_load("designs/m12-setscrew-printed.json", sets2, 1, &w, &err) == 0, "%s",
          err.msg);
    if (w) {
        tippe_design_print_info p2;
        tippe_design_part_print(w, 0, &p2);
        CHECK(p2.calibrated && fabs(p2.infill - 0.3) < 1e-9, "infill back %.12f", p2.infill);
        CHECK_CLOSE(p2.printed_mass_kg, pi.printed_mass_kg, 1e-9, "weighed mass kept");
        tippe_design_free(w);
    }
    tippe_design_free(d);
}

int main(void)
{
    test_plain_cylinder();
    test_default_cylinder();
    test_tube_walls();
    test_gyroid_bulk();
    test_unmodelled_pattern();
    test_solid_below_area();
    test_design_weighing();
    return check_summary("test_print_slicer");
}
