/* The G-code reader (src/print/gcode.c, src/print/gcode_body.c) against closed forms.
 *
 * Synthetic G-code, written here, of shapes whose moments are known: one
 * straight bead (a rod, and a box), a tube of stacked polygon or arc rings
 * (thin-walled tube), a disc of raster lines (solid disc). Then the filament's
 * bookkeeping (absolute/relative E, G92, retractions, firmware retraction,
 * volumetric E), the features (excluded skirt, support, custom and unlabelled
 * G-code; Cura's and Orca's labels), the syntax (CRLF, N and checksums,
 * comments), and the refusals. Coordinates and E are written with 9 decimals;
 * expectations use the values as written where exactness is claimed. Last, when
 * they are installed, tools/gcode_moments.py (Python, numpy) reads a slicer-like
 * file by its own method, and PrusaSlicer slices a real ball. */
#include "tippe/design.h"

#include "check.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* ------------------------------------------------------------ G-code text */

typedef struct {
    char *s;
    size_t n, cap;
} sb;

static void put(sb *b, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void put(sb *b, const char *fmt, ...)
{
    va_list ap;
    for (;;) {
        va_start(ap, fmt);
        int k = vsnprintf(b->s ? b->s + b->n : NULL, b->s ? b->cap - b->n : 0, fmt, ap);
        va_end(ap);
        if (b->s && b->n + (size_t)k < b->cap) {
            b->n += (size_t)k;
            return;
        }
        b->cap = 2 * (b->cap + (size_t)k + 1024);
        b->s = realloc(b->s, b->cap);
    }
}

static void clear(sb *b) { b->n = 0; if (b->s) b->s[0] = 0; }

/* x as written with 9 decimals and read back. */
static double w9(double x)
{
    char t[64];
    snprintf(t, sizeof t, "%.9f", x);
    return strtod(t, NULL);
}

static tippe_gcode_options volumetric_options(void)
{
    /* E in mm^3 and 1 g/cm^3: mass in kg = 1e-6 x volume in mm^3 */
    tippe_gcode_options o = tippe_gcode_defaults();
    o.volumetric_e = 1;
    o.density_g_cm3 = 1.0;
    return o;
}

static int parse(const sb *b, const tippe_gcode_options *o, tippe_gcode_body *body,
                 tippe_error *err)
{
    return tippe_gcode_parse_buffer(b->s, b->n, "test.gcode", o, body, err);
}

/* One layer of a regular N-gon ring of circumradius r about (cx, cy) at nozzle
 * height z, bead h high and w wide (volumetric E = w h L per chord), relative E.
 * Returns the E written per chord. */
static double ring(sb *b, double cx, double cy, double r, int N, double z, double h, double w)
{
    double L = 2 * r * sin(M_PI / N), e = w9(w * h * L);
    put(b, ";LAYER_CHANGE\n;Z:%.3f\n;HEIGHT:%.3f\nG1 Z%.3f\nG1 X%.9f Y%.9f\n", z, h, z, cx + r,
        cy);
    for (int k = 1; k <= N; k++)
        put(b, "G1 X%.9f Y%.9f E%.9f\n", cx + r * cos(2 * M_PI * k / N),
            cy + r * sin(2 * M_PI * k / N), e);
    return e;
}

/* ------------------------------------------------------------ (a) one bead */

static void test_rod(void)
{
    sb b = {0};
    tippe_gcode_options o = volumetric_options();
    tippe_gcode_body body;
    tippe_error err = {0};
    /* from (10, 20, 5) to (40, 60, 5) mm: L = 50 mm along t = (0.6, 0.8, 0) */
    put(&b, "M83\nG1 Z5\nG1 X10 Y20\n;HEIGHT:0.2\nG1 X40 Y60 E2\n");
    double m = 2e-6, L = 50e-3, t[2] = {0.6, 0.8};
    o.bead = TIPPE_GCODE_BEAD_LINE;
    int rc = parse(&b, &o, &body, &err);
    CHECK(rc == TIPPE_OK, "a single bead parses: %s", err.msg);
    /* a rod: exact in closed form up to rounding */
    CHECK_CLOSE(body.m, m, 1e-14, "rod mass");
    CHECK_CLOSE(body.com[0], 25e-3, 1e-14, "rod com x");
    CHECK_CLOSE(body.com[1], 40e-3, 1e-14, "rod com y");
    CHECK_CLOSE(body.com[2], 5e-3, 1e-14, "rod com z: the line model sits at the nozzle");
    double k = m * L * L / 12; /* I = m L^2/12 (1 - t t^T) */
    CHECK_CLOSE(body.inertia[0], k * (1 - t[0] * t[0]), 1e-12, "rod Ixx");
    CHECK_CLOSE(body.inertia[1], k * (1 - t[1] * t[1]), 1e-12, "rod Iyy");
    CHECK_CLOSE(body.inertia[2], k, 1e-12, "rod Izz");
    CHECK_CLOSE(body.inertia[3], -k * t[0] * t[1], 1e-12, "rod Ixy");
    CHECK(fabs(body.inertia[4]) < 1e-14 * k && fabs(body.inertia[5]) < 1e-14 * k,
          "rod Ixz %g, Iyz %g: a level rod", body.inertia[4], body.inertia[5]);

    /* a box bead 0.2 mm high: w = V / (L h) = 2 / (50 x 0.2) = 0.2 mm, below the nozzle */
    o.bead = TIPPE_GCODE_BEAD_BOX;
    rc = parse(&b, &o, &body, &err);
    CHECK(rc == TIPPE_OK, "%s", err.msg);
    double h = 0.2e-3, w = 0.2e-3, n[2] = {-0.8, 0.6};
    CHECK_CLOSE(body.com[2], 4.9e-3, 1e-14, "box com z: half a layer below the nozzle");
    CHECK_CLOSE(body.inertia[0], k * (1 - t[0] * t[0]) + m * (w * w * n[1] * n[1] + h * h) / 12,
                1e-12, "box Ixx");
    CHECK_CLOSE(body.inertia[1], k * (1 - t[1] * t[1]) + m * (w * w * n[0] * n[0] + h * h) / 12,
                1e-12, "box Iyy");
    CHECK_CLOSE(body.inertia[2], k + m * w * w / 12, 1e-12, "box Izz");
    CHECK_CLOSE(body.inertia[3], -k * t[0] * t[1] - m * w * w * n[0] * n[1] / 12, 1e-12,
                "box Ixy");
    CHECK_CLOSE(body.bbox_min[2], 4.8e-3, 1e-14, "the bead's bottom");
    CHECK_CLOSE(body.bbox_max[2], 5.0e-3, 1e-14, "the bead's top");
    CHECK_CLOSE(body.feature[TIPPE_GCODE_UNLABELLED].width_mm, 0.2, 1e-14, "bead width");
    CHECK(body.labelled == 0 && body.n_layers == 1, "unlabelled file, one layer (%d, %d)",
          body.labelled, body.n_layers);

    /* the same with the syntax's decorations: a byte order mark, CRLF, N and checksums,
     * comments, blanks */
    const char *lines[] = {"M83 ; relative E", "", "G1 Z5 (lift)", "G1 X10 Y20",
                           ";HEIGHT:0.2", "G1 X40 Y60 E2.0 ; the bead"};
    clear(&b);
    put(&b, "\xEF\xBB\xBF");
    for (int i = 0; i < 6; i++) {
        char l[128];
        if (lines[i][0] == ';') {
            put(&b, "%s\r\n", lines[i]);
            continue;
        }
        snprintf(l, sizeof l, "N%d %s", i + 1, lines[i]);
        char *semi = strchr(l, ';');
        if (semi && l[0] != ';')
            *semi = 0; /* the checksum covers the code before any comment */
        unsigned cs = 0;
        for (char *p = l; *p; p++)
            cs ^= (unsigned char)*p;
        put(&b, "%s*%u ; note\r\n", l, cs);
    }
    tippe_gcode_body deco;
    rc = parse(&b, &o, &deco, &err);
    CHECK(rc == TIPPE_OK, "decorated: %s", err.msg);
    CHECK(rc == TIPPE_OK && deco.m == body.m && deco.inertia[3] == body.inertia[3] &&
              deco.com[2] == body.com[2],
          "CRLF, N, checksums and comments change nothing");
    free(b.s);
}

/* ------------------------------------------------------------ (b) tubes */

/* The tube every test below builds on: 50 layers of 0.2 mm, r = 20 mm about (100, 100). */
#define TUBE_R 20.0
#define TUBE_N 360
#define TUBE_LAYERS 50
#define TUBE_H 0.2
#define TUBE_W 0.45

static double tube(sb *b, double cx, double cy)
{
    double e = 0;
    for (int l = 1; l <= TUBE_LAYERS; l++)
        e = ring(b, cx, cy, TUBE_R, TUBE_N, l * TUBE_H, TUBE_H, TUBE_W);
    return e;
}

static void test_tube(void)
{
    sb b = {0};
    tippe_gcode_options o = volumetric_options();
    tippe_gcode_body body;
    tippe_error err = {0};
    put(&b, "M83\n;TYPE:External perimeter\n");
    double e = tube(&b, 100, 100);
    int rc = parse(&b, &o, &body, &err);
    CHECK(rc == TIPPE_OK, "tube: %s", err.msg);
    double r = TUBE_R * 1e-3, H = TUBE_LAYERS * TUBE_H * 1e-3, h = TUBE_H * 1e-3;
    double m = 1e-6 * e * TUBE_N * TUBE_LAYERS;
    double L = 2 * TUBE_R * sin(M_PI / TUBE_N), w = 1e-3 * e / (L * TUBE_H);
    /* 18000 terms summed: n eps = 2e-12 */
    CHECK_CLOSE(body.m, m, 2e-12, "tube mass: the E written");
    CHECK_CLOSE(body.com[2], H / 2, 1e-12, "boxes below the nozzle stack to [0, H]");
    CHECK(hypot(body.com[0] - 0.1, body.com[1] - 0.1) < 1e-12, "com on the axis (%g, %g)",
          body.com[0], body.com[1]);
    /* exactly, for chords of an N-gon: mean r^2 along a chord is r^2 (cos^2 + sin^2 / 3)(pi/N),
     * plus the box's w^2/12; z spreads uniformly over [0, H] */
    double c = cos(M_PI / TUBE_N), s = sin(M_PI / TUBE_N);
    double rr = r * r * (c * c + s * s / 3) + w * w / 12;
    /* exact for the polygon but for its coordinates written to 1e-9 mm */
    CHECK_CLOSE(body.inertia[2], m * rr, 1e-9, "tube Izz, exact");
    CHECK_CLOSE(body.inertia[0], m * (rr / 2 + H * H / 12), 1e-9, "tube Ixx, exact");
    CHECK_CLOSE(body.inertia[1], m * (rr / 2 + H * H / 12), 1e-9, "tube Iyy, exact");
    /* the thin-walled tube's closed forms, C = m r^2 and A = m (r^2/2 + H^2/12): off by the
     * chords, -(2/3)(pi/N)^2 = -5e-5, and the bead's width, +w^2/(12 r^2) = +4e-5 */
    CHECK_CLOSE(body.inertia[2], m * r * r, 1e-4, "tube C against the thin-walled tube");
    CHECK_CLOSE(body.inertia[0], m * (r * r / 2 + H * H / 12), 1e-4,
                "tube A against the thin-walled tube");
    CHECK(body.n_layers == TUBE_LAYERS, "layers %d", body.n_layers);
    CHECK_CLOSE(body.layer_height, h, 1e-12, "layer height");
    CHECK_CLOSE(body.first_layer_z, h, 1e-12, "first layer");
    CHECK(body.n_clusters == 1 && body.n_objects == 0, "one cluster (%d), no labels (%d)",
          body.n_clusters, body.n_objects);

    /* the part: found axis, frame, A and C */
    tippe_gcode_expect x = {0};
    x.height_mm = TUBE_LAYERS * TUBE_H;
    x.diameter_mm = 2 * TUBE_R + TUBE_W;
    x.axis_known = 1;
    x.axis_x_mm = x.axis_y_mm = 100;
    tippe_gcode_part p;
    rc = tippe_gcode_match(&body, &x, &p, &err);
    CHECK(rc == TIPPE_OK, "the tube matches its part: %s", err.msg);
    CHECK(fabs(p.axis_x - 0.1) < 1e-9 && fabs(p.axis_y - 0.1) < 1e-9, "axis (%g, %g)", p.axis_x,
          p.axis_y);
    CHECK_CLOSE(p.z_cm, H / 2, 1e-12, "z_cm from the bottom");
    CHECK_CLOSE(p.height, H, 1e-12, "height");
    CHECK_CLOSE(p.A, m * (rr / 2 + H * H / 12), 1e-9, "A");
    CHECK_CLOSE(p.C, m * rr, 1e-9, "C");
    CHECK(p.asymmetry < 1e-9 && p.off_diagonal < 1e-9, "asymmetry %g, off-diagonal %g",
          p.asymmetry, p.off_diagonal);

    /* the reader's cache rescales a body read once to another density: equal to a read at
     * that density but for the rounding of the 18000 terms each sum adds (n eps = 2e-12) */
    tippe_gcode_body dense;
    tippe_gcode_options od = o;
    od.density_g_cm3 = 1.24;
    od.override_density = 1;
    o.override_density = 1;
    CHECK(parse(&b, &od, &dense, &err) == TIPPE_OK && parse(&b, &o, &body, &err) == TIPPE_OK,
          "tube at two densities: %s", err.msg);
    tippe_gcode_body_set_density(&body, 1.24);
    CHECK_CLOSE(body.m, dense.m, 2e-12, "rescaled mass");
    for (int i = 0; i < 3; i++)
        CHECK_CLOSE(body.inertia[i], dense.inertia[i], 2e-12, "rescaled inertia %d", i);
    CHECK_CLOSE(body.feature[TIPPE_GCODE_EXTERNAL_PERIMETER].mass_kg,
                dense.feature[TIPPE_GCODE_EXTERNAL_PERIMETER].mass_kg, 2e-12, "rescaled share");
    CHECK(body.density_g_cm3 == 1.24 && body.body_volume_mm3 == dense.body_volume_mm3,
          "the density is the new one (%g), the volumes stay", body.density_g_cm3);
    o.override_density = 0;

    /* the same tube as arcs: G3 full circles (I, J) and G2 half circles (R); chords within
     * 1e-4 mm of the arc make C off by (4/3) sagitta / r = 7e-6 */
    double earc = w9(TUBE_W * TUBE_H * 2 * M_PI * TUBE_R);
    for (int variant = 0; variant < 2; variant++) {
        clear(&b);
        put(&b, "M83\n;TYPE:External perimeter\n");
        for (int l = 1; l <= TUBE_LAYERS; l++) {
            put(&b, ";HEIGHT:0.2\nG1 Z%.3f\nG1 X120 Y100\n", l * TUBE_H);
            if (variant == 0)
                put(&b, "G3 X120 Y100 I-20 J0 E%.9f\n", earc);
            else
                put(&b, "G2 X80 Y100 R20 E%.9f\nG2 X120 Y100 R20 E%.9f\n", earc / 2, earc / 2);
        }
        rc = parse(&b, &o, &body, &err);
        CHECK(rc == TIPPE_OK, "arcs: %s", err.msg);
        double ma = 1e-6 * (variant ? 2 * w9(earc / 2) : earc) * TUBE_LAYERS, wa = TUBE_W * 1e-3;
        CHECK_CLOSE(body.m, ma, 1e-12, "arc tube mass: the E written, summed over the chords");
        CHECK_CLOSE(body.inertia[2], ma * (r * r + wa * wa / 12), 1e-5, "arc tube C (variant %d)",
                    variant);
        CHECK_CLOSE(body.inertia[0], ma * ((r * r + wa * wa / 12) / 2 + H * H / 12), 1e-5,
                    "arc tube A (variant %d)", variant);
        CHECK(hypot(body.com[0] - 0.1, body.com[1] - 0.1) < 1e-9, "arc com on the axis (%g, %g)",
              body.com[0], body.com[1]);
        CHECK(body.feature[TIPPE_GCODE_EXTERNAL_PERIMETER].n_moves == TUBE_LAYERS * (1 + variant),
              "an arc is one move (%ld)", body.feature[TIPPE_GCODE_EXTERNAL_PERIMETER].n_moves);
    }
    free(b.s);
}

/* Cura's headers: the Marlin and Griffin flavours write E in mm of filament without naming
 * its diameter (CuraEngine's GCodeExport::getFileHeader), so the options (a design's
 * print.filament_diameter_mm) give it; UltiGCode writes E as volume (mm^3). One straight bead
 * of E = 2, density 1. */
static void test_cura_headers(void)
{
    sb b = {0};
    tippe_gcode_options o = tippe_gcode_defaults();
    o.density_g_cm3 = 1.0;
    tippe_gcode_body body;
    tippe_error err = {0};
    put(&b, ";FLAVOR:Griffin\n;EXTRUDER_TRAIN.0.MATERIAL.VOLUME_USED:12\n;Generated with "
            "Cura_SteamEngine 5.0.0\nM83\n;TYPE:WALL-OUTER\nG1 X10 Y10 Z0.2\nG1 X30 Y10 E2\n");
    CHECK(parse(&b, &o, &body, &err) == TIPPE_EINPUT && strstr(err.msg, "diameter is not known"),
          "Griffin without a diameter is refused, naming it: %s", err.msg);
    o.filament_diameter_mm = 2.85;
    o.override_diameter = 1;
    CHECK(parse(&b, &o, &body, &err) == TIPPE_OK, "Griffin, 2.85 given: %s", err.msg);
    /* exact but for the rounding of pi d^2 / 4 x 2 x 1e-6 (a few ulp) */
    CHECK_CLOSE(body.m, 1e-6 * 2 * M_PI * 2.85 * 2.85 / 4, 1e-14, "the options' 2.85 mm filament");
    CHECK(body.filament_diameter_mm == 2.85, "diameter %g", body.filament_diameter_mm);
    clear(&b);
    o = tippe_gcode_defaults();
    o.density_g_cm3 = 1.0;
    put(&b, ";FLAVOR:UltiGCode\nM83\n;TYPE:WALL-OUTER\nG1 X10 Y10 Z0.2\nG1 X30 Y10 E2\n");
    CHECK(parse(&b, &o, &body, &err) == TIPPE_OK && body.volumetric_e,
          "UltiGCode's E is volume: %s", err.msg);
    CHECK_CLOSE(body.m, 2e-6, 1e-15, "2 mm^3 at 1 g/cm^3");
    free(b.s);
}

/* ------------------------------------------------------------ (c) filament bookkeeping */

/* A zig-zag path of 4 beads at z = 0.3 in one of several styles; the beads are the same. */
static void path(sb *b, int style)
{
    static const double pts[5][2] = {{10, 10}, {30, 10}, {30, 25}, {12, 27}, {11, 40}};
    const double ev[4] = {1.25, 0.75, 1.5, 0.5}; /* mm of filament */
    double eabs = 0;
    put(b, "G90\n%s\nG92 E0\nG1 Z0.3\nG1 X10 Y10\n;TYPE:Perimeter\n", style == 1 ? "M82" : "M83");
    for (int k = 0; k < 4; k++) {
        switch (style) {
        case 0: /* relative, nothing else */
            put(b, "G1 X%g Y%g E%g\n", pts[k + 1][0], pts[k + 1][1], ev[k]);
            break;
        case 1: /* absolute, reset by G92 E0 after each bead, retractions between */
            eabs += ev[k];
            put(b, "G1 X%g Y%g E%g\n", pts[k + 1][0], pts[k + 1][1], eabs);
            put(b, "G1 E%g\nG92 E0\n", eabs - 0.8); /* retract 0.8 */
            put(b, "G1 E0.8\n");                    /* and back */
            eabs = 0.8;
            put(b, "G92 E%g\n", eabs);
            break;
        case 2: /* relative with PrusaSlicer's wipe (retracting while moving) and a travel */
            put(b, "G1 X%g Y%g E%g\n", pts[k + 1][0], pts[k + 1][1], ev[k]);
            put(b, ";WIPE_START\nG1 X%g Y%g E-0.5\n;WIPE_END\nG1 E-0.3\nG1 X%g Y%g\n",
                pts[k][0], pts[k][1], pts[k + 1][0], pts[k + 1][1]);
            put(b, "G1 Z0.9\nG1 Z0.3\nG1 E0.8\n");
            break;
        case 3: /* firmware retraction */
            put(b, "G1 X%g Y%g E%g\nG10\nG1 X0 Y0\nG1 X%g Y%g\nG11\n", pts[k + 1][0],
                pts[k + 1][1], ev[k], pts[k + 1][0], pts[k + 1][1]);
            break;
        case 4: /* relative E under G91 XYZ: every coordinate relative, G90 back */
            put(b, "G91\nG1 X%g Y%g E%g\nG90\n", pts[k + 1][0] - pts[k][0],
                pts[k + 1][1] - pts[k][1], ev[k]);
            break;
        case 5: /* G92 renames X: the nozzle does not move, so neither does the plastic */
            put(b, "G92 X%g Y%g\nG1 X%g Y%g E%g\nG92 X%g Y%g\n", pts[k][0] + 100, pts[k][1] - 50,
                pts[k + 1][0] + 100, pts[k + 1][1] - 50, ev[k], pts[k + 1][0], pts[k + 1][1]);
            break;
        }
    }
}

/* tippe serve keeps an upload read at 1 g/cm^3 and scales it to a part's material
 * (tippe_gcode_body_set_density): the same as reading the text at that density. */
static void test_density(void)
{
    sb b = {0};
    tippe_gcode_options o = volumetric_options();
    o.override_density = 1;
    tippe_gcode_body one, read;
    tippe_error err = {0};
    put(&b, "M83\n;TYPE:External perimeter\n");
    tube(&b, 100, 100);
    put(&b, ";TYPE:Skirt/Brim\n");
    ring(&b, 100, 100, TUBE_R + 5, TUBE_N, TUBE_H, TUBE_H, TUBE_W);
    int rc = parse(&b, &o, &one, &err);
    o.density_g_cm3 = 1.24;
    rc |= parse(&b, &o, &read, &err);
    CHECK(rc == TIPPE_OK, "tube at two densities: %s", err.msg);
    tippe_gcode_body_set_density(&one, 1.24);
    /* the same 18000-odd terms, the density applied to each or to their sum: rounding of
     * order n eps = 4e-12 (as the tube's mass above), 1e-11 of the largest moment */
    CHECK_CLOSE(one.m, read.m, 1e-11, "mass scaled from 1 g/cm^3");
    for (int k = 0; k < 6; k++)
        CHECK(fabs(one.inertia[k] - read.inertia[k]) <= 1e-11 * fabs(read.inertia[2]),
              "inertia[%d] scaled: %g, read %g", k, one.inertia[k], read.inertia[k]);
    CHECK_CLOSE(one.excluded_mass_kg, read.excluded_mass_kg, 1e-11, "the skirt's mass scaled");
    CHECK(one.body_volume_mm3 == read.body_volume_mm3 && one.density_g_cm3 == 1.24,
          "volumes kept, the density is the new one");
    free(b.s);
}

static void test_bookkeeping(void)
{
    sb b = {0};
    tippe_gcode_options o = tippe_gcode_defaults();
    o.filament_diameter_mm = 1.75;
    o.density_g_cm3 = 1.24;
    tippe_error err = {0};
    tippe_gcode_body ref, body;
    path(&b, 0);
    int rc = parse(&b, &o, &ref, &err);
    CHECK(rc == TIPPE_OK, "reference path: %s", err.msg);
    double area = M_PI * 1.75 * 1.75 / 4;
    CHECK_CLOSE(ref.body_volume_mm3, 4.0 * area, 1e-14, "(pi d^2/4) x 4 mm of filament");
    CHECK_CLOSE(ref.m, 4.0 * area * 1.24e-6, 1e-14, "mass at 1.24 g/cm^3");
    const char *names[] = {"", "absolute E, G92 E0, retract/unretract", "wipe and retraction",
                           "firmware retraction", "G91 relative moves", "G92 X Y"};
    for (int style = 1; style <= 5; style++) {
        clear(&b);
        path(&b, style);
        rc = parse(&b, &o, &body, &err);
        CHECK(rc == TIPPE_OK, "%s: %s", names[style], err.msg);
        /* the same beads: equal up to the rounding of E's differences (1e-15 of 1 mm) */
        CHECK_CLOSE(body.m, ref.m, 1e-13, "%s: mass", names[style]);
        for (int i = 0; i < 3; i++)
            CHECK_CLOSE(body.com[i], ref.com[i], 1e-13, "%s: com[%d]", names[style], i);
        for (int i = 0; i < 3; i++)
            CHECK_CLOSE(body.inertia[i], ref.inertia[i], 1e-12, "%s: inertia[%d]", names[style],
                        i);
        for (int i = 3; i < 6; i++) /* Ixz, Iyz are 0 but for rounding */
            CHECK(fabs(body.inertia[i] - ref.inertia[i]) < 1e-12 * ref.inertia[2],
                  "%s: inertia[%d] %g vs %g", names[style], i, body.inertia[i], ref.inertia[i]);
        /* a retraction restored by an equal E written differently leaves ~1e-16 mm over */
        CHECK(body.point_volume_mm3 < 1e-12, "%s: nothing laid at a point (%g mm^3)",
              names[style], body.point_volume_mm3);
    }

    /* a deretraction longer than the retraction (retract_restart_extra) lays the extra at the
     * nozzle, and the filament is conserved: laid = pushed - still retracted */
    clear(&b);
    path(&b, 0);
    put(&b, "G1 E-0.8\nG1 X20 Y20\nG1 E0.85\nG1 E-1\n");
    rc = parse(&b, &o, &body, &err);
    CHECK(rc == TIPPE_OK, "restart extra: %s", err.msg);
    CHECK_CLOSE(body.point_volume_mm3, 0.05 * area, 1e-12, "the extra 0.05 mm, at a point");
    CHECK_CLOSE(body.body_volume_mm3, 4.05 * area, 1e-14, "body");
    CHECK_CLOSE(body.filament_mm, 3.05, 1e-14, "net filament pushed");
    CHECK_CLOSE(body.retracted_at_end_mm, 1.0, 1e-14, "retracted at the end");
    CHECK_CLOSE(body.body_volume_mm3 + body.excluded_volume_mm3,
                (body.filament_mm + body.retracted_at_end_mm) * area, 1e-14,
                "laid = pushed + still retracted");

    /* volumetric E by M200 D, and the options' override of the file's config */
    clear(&b);
    put(&b, "M200 D1.75\n");
    path(&b, 0);
    put(&b, "; filament_diameter = 2.85\n; filament_density = 2.0\n");
    rc = parse(&b, &o, &body, &err);
    CHECK(rc == TIPPE_OK && fabs(body.body_volume_mm3 - 4.0) < 1e-13 && body.volumetric_e,
          "M200 D1.75: E is mm^3 (%g)", body.body_volume_mm3);
    CHECK(rc == TIPPE_OK && body.density_g_cm3 == 2.0, "the file's density wins unless "
          "overridden (%g)", body.density_g_cm3);
    clear(&b);
    path(&b, 0);
    put(&b, "; filament_diameter = 2.85\n; filament_density = 2.0,1.1\n");
    o.override_density = 1;
    rc = parse(&b, &o, &body, &err);
    CHECK(rc == TIPPE_OK && body.filament_diameter_mm == 2.85 && body.density_g_cm3 == 1.24,
          "config read (d %g), density overridden (%g)", body.filament_diameter_mm,
          body.density_g_cm3);
    CHECK_CLOSE(body.body_volume_mm3, 4.0 * M_PI * 2.85 * 2.85 / 4, 1e-14, "2.85 mm filament");
    clear(&b);
    put(&b, "; use_volumetric_e = 1\n");
    path(&b, 0);
    rc = parse(&b, &o, &body, &err);
    CHECK(rc == TIPPE_OK && fabs(body.body_volume_mm3 - 4.0) < 1e-13,
          "use_volumetric_e = 1: E is mm^3 (%g)", body.body_volume_mm3);
    free(b.s);
}

/* ------------------------------------------------------------ (d) features */

static void test_features(void)
{
    sb b = {0};
    tippe_gcode_options o = volumetric_options();
    tippe_error err = {0};
    tippe_gcode_body ref, body;
    put(&b, "M83\n;TYPE:External perimeter\n");
    tube(&b, 100, 100);
    int rc = parse(&b, &o, &ref, &err);
    CHECK(rc == TIPPE_OK, "%s", err.msg);

    /* PrusaSlicer: custom start G-code with a purge line, a skirt, support beside the tube */
    clear(&b);
    put(&b, "; generated by PrusaSlicer 2.6.1+linux on 2024-01-01 at 10:00:00 UTC\nM83\n"
            ";TYPE:Custom\nG1 Z0.2\nG1 X0 Y-3\nG1 X60 Y-3 E9\n");
    put(&b, ";TYPE:Skirt/Brim\n");
    double es = ring(&b, 100, 100, 30, 36, 0.2, 0.2, 0.45);
    put(&b, ";TYPE:Support material\nG1 X150 Y90\nG1 X150 Y110 E4\n"
            ";TYPE:Support material interface\nG1 X151 Y110 E0.5\n");
    put(&b, ";TYPE:External perimeter\n");
    tube(&b, 100, 100);
    put(&b, "; filament used [mm] = 1234.5\n; filament used [g] = 3.1\n");
    rc = parse(&b, &o, &body, &err);
    CHECK(rc == TIPPE_OK, "prusa features: %s", err.msg);
    CHECK(!strncmp(body.generator, "PrusaSlicer 2.6.1", 17), "generator '%s'", body.generator);
    CHECK_CLOSE(body.m, ref.m, 1e-13, "the body is the tube alone");
    /* the sums' reference point differs (the purge line's start): rounding only */
    for (int i = 0; i < 3; i++)
        CHECK_CLOSE(body.inertia[i], ref.inertia[i], 1e-10, "inertia[%d]", i);
    for (int i = 3; i < 6; i++)
        CHECK(fabs(body.inertia[i] - ref.inertia[i]) < 1e-10 * ref.inertia[2],
              "product of inertia [%d]: %g vs %g", i, body.inertia[i], ref.inertia[i]);
    CHECK_CLOSE(body.feature[TIPPE_GCODE_SKIRT_BRIM].volume_mm3, 36 * es, 1e-13, "skirt volume");
    CHECK_CLOSE(body.feature[TIPPE_GCODE_SUPPORT].volume_mm3, 4, 1e-14, "support volume");
    CHECK_CLOSE(body.feature[TIPPE_GCODE_SUPPORT_INTERFACE].volume_mm3, 0.5, 1e-14, "interface");
    CHECK_CLOSE(body.feature[TIPPE_GCODE_CUSTOM].volume_mm3, 9, 1e-14, "purge line");
    CHECK_CLOSE(body.excluded_volume_mm3, 36 * es + 13.5, 1e-13, "excluded volume");
    CHECK_CLOSE(body.excluded_mass_kg, 1e-6 * (36 * es + 13.5), 1e-13, "excluded mass");
    CHECK(body.slicer_filament_mm == 1234.5 && body.slicer_filament_g == 3.1,
          "the slicer's totals read (%g mm, %g g)", body.slicer_filament_mm,
          body.slicer_filament_g);
    CHECK(body.n_layers == TUBE_LAYERS, "skirt and support add no layer (%d)", body.n_layers);

    /* Cura: absolute E, its labels, an unlabelled start and an extruding end after the last
     * ;TIME_ELAPSED:, no density in the file */
    clear(&b);
    put(&b, ";FLAVOR:Marlin\n;Generated with Cura_SteamEngine 5.4.0\nM82\nG92 E0\n"
            "G1 X0 Y0 Z0.3\nG1 X0 Y100 E5\nG92 E0\n;LAYER:0\n;MESH:NONMESH\n;TYPE:SKIRT\n"
            "G1 X60 Y60 Z0.2\nG1 X140 Y60 E3\n;MESH:tube.stl\n;TYPE:WALL-OUTER\n");
    double e = 3;
    for (int l = 1; l <= TUBE_LAYERS; l++) {
        double L = 2 * TUBE_R * sin(M_PI / TUBE_N), de = w9(TUBE_W * TUBE_H * L);
        put(&b, ";LAYER:%d\n;TYPE:WALL-OUTER\nG0 Z%.3f\nG0 X120 Y100\n", l, l * TUBE_H);
        for (int k = 1; k <= TUBE_N; k++) {
            e += de;
            put(&b, "G1 X%.9f Y%.9f E%.9f\n", 100 + TUBE_R * cos(2 * M_PI * k / TUBE_N),
                100 + TUBE_R * sin(2 * M_PI * k / TUBE_N), e);
        }
        put(&b, ";TIME_ELAPSED:%d\n", l);
    }
    put(&b, "G1 X0 Y0\nG1 X10 Y0 E%.9f\n;End of Gcode\n", e + 2);
    tippe_gcode_options oc = tippe_gcode_defaults();
    oc.volumetric_e = 1;
    rc = parse(&b, &oc, &body, &err);
    CHECK(rc == TIPPE_EINPUT && strstr(err.msg, "test.gcode") && strstr(err.msg, "density"),
          "Cura without a density is refused: %s", err.msg);
    rc = parse(&b, &o, &body, &err);
    CHECK(rc == TIPPE_OK, "cura: %s", err.msg);
    /* absolute E as written accumulates rounding of 1e-9 per bead over 18000 beads */
    CHECK_CLOSE(body.m, ref.m, 1e-9, "cura body is the tube");
    CHECK_CLOSE(body.inertia[2], ref.inertia[2], 1e-8, "cura C");
    CHECK_CLOSE(body.feature[TIPPE_GCODE_SKIRT_BRIM].volume_mm3, 3, 1e-12, "cura skirt");
    CHECK_CLOSE(body.feature[TIPPE_GCODE_UNLABELLED].volume_mm3, 7, 1e-12,
                "start purge and end G-code: unlabelled, excluded");
    CHECK(body.n_objects == 1 && !strcmp(body.object[0], "tube.stl"), "one mesh '%s' (%d)",
          body.object[0], body.n_objects);

    /* Cura's support labels (issue 37): ;TYPE:SUPPORT and ;TYPE:SUPPORT-INTERFACE lines
     * between the walls are not the part: its body is the walls' alone, to rounding (the
     * same sums over the same beads; 1e-12 of the mass), and each kind is counted apart */
    tippe_gcode_body with, without;
    for (int k = 0; k < 2; k++) {
        clear(&b);
        put(&b, ";FLAVOR:Marlin\n;Generated with Cura_SteamEngine 5.4.0\nM83\n;LAYER:0\n"
                ";MESH:part.stl\n;TYPE:WALL-OUTER\nG1 X0 Y0 Z0.2\nG1 X10 Y0 E2\n");
        if (k == 0)
            put(&b, ";TYPE:SUPPORT\nG1 X10 Y5 E1.5\n;TYPE:SUPPORT-INTERFACE\nG1 X12 Y5 E0.25\n"
                    ";TYPE:WALL-OUTER\nG0 X10 Y0\n");
        put(&b, "G1 X10 Y10 E2\n;LAYER:1\n;TYPE:WALL-INNER\nG1 Z0.4\nG1 X0 Y10 E2\n");
        rc = parse(&b, &o, k == 0 ? &with : &without, &err);
        CHECK(rc == TIPPE_OK, "cura supports (%d): %s", k, err.msg);
    }
    CHECK(with.feature[TIPPE_GCODE_SUPPORT].volume_mm3 == 1.5 &&
              with.feature[TIPPE_GCODE_SUPPORT_INTERFACE].volume_mm3 == 0.25,
          "Cura's support %g and interface %g", with.feature[TIPPE_GCODE_SUPPORT].volume_mm3,
          with.feature[TIPPE_GCODE_SUPPORT_INTERFACE].volume_mm3);
    CHECK(with.body_volume_mm3 == 6 && without.body_volume_mm3 == 6,
          "the body is the walls alone (%g, %g)", with.body_volume_mm3, without.body_volume_mm3);
    CHECK_CLOSE(with.m, without.m, 1e-12, "the body's mass with supports as without");
    for (int i = 0; i < 3; i++)
        CHECK_CLOSE(with.inertia[i], without.inertia[i], 1e-12, "inertia[%d] with supports", i);

    /* Orca / BambuStudio labels */
    clear(&b);
    put(&b, "M83\n; FEATURE: Outer wall\n; LAYER_HEIGHT: 0.2\nG1 Z0.2\nG1 X0 Y0\nG1 X10 Y0 E1\n"
            "; FEATURE: Inner wall\nG1 X10 Y10 E2\n; FEATURE: Sparse infill\nG1 X0 Y10 E3\n"
            "; FEATURE: Top surface\nG1 X0 Y1 E4\n; FEATURE: Prime tower\nG1 X1 Y1 E5\n"
            "; FEATURE: Ironing\nG1 X2 Y1 E6\n");
    rc = parse(&b, &o, &body, &err);
    CHECK(rc == TIPPE_OK, "orca: %s", err.msg);
    CHECK(body.feature[TIPPE_GCODE_EXTERNAL_PERIMETER].volume_mm3 == 1 &&
              body.feature[TIPPE_GCODE_PERIMETER].volume_mm3 == 2 &&
              body.feature[TIPPE_GCODE_SPARSE_INFILL].volume_mm3 == 3 &&
              body.feature[TIPPE_GCODE_TOP_SOLID_INFILL].volume_mm3 == 4 &&
              body.feature[TIPPE_GCODE_WIPE_TOWER].volume_mm3 == 5 &&
              body.feature[TIPPE_GCODE_OTHER].volume_mm3 == 6,
          "Orca's features sorted");
    CHECK(body.body_volume_mm3 == 16 && body.excluded_volume_mm3 == 5, "body %g, excluded %g",
          body.body_volume_mm3, body.excluded_volume_mm3);
    free(b.s);
}

/* ------------------------------------------------------------ (e) a disc */

static void test_disc(void)
{
    sb b = {0};
    tippe_gcode_options o = volumetric_options();
    tippe_error err = {0};
    tippe_gcode_body body;
    /* K raster lines s = w = 2R/K apart (the beads cover the disc's diameter exactly) over a
     * disc of radius R, one layer h high, centred at (50, 60) */
    double R = 20, h = 0.2;
    int K = 89;
    double s = 2 * R / K;
    put(&b, "M83\n;TYPE:Solid infill\n;HEIGHT:0.2\nG1 Z0.2\n");
    for (int k = 0; k < K; k++) {
        double y = (k - (K - 1) / 2.0) * s, x = sqrt(R * R - y * y);
        int dir = k % 2 ? -1 : 1;
        put(&b, "G1 X%.9f Y%.9f\nG1 X%.9f Y%.9f E%.9f\n", 50 - dir * x, 60 + y, 50 + dir * x,
            60 + y, s * h * 2 * x);
    }
    int rc = parse(&b, &o, &body, &err);
    CHECK(rc == TIPPE_OK, "disc: %s", err.msg);
    double Rm = R * 1e-3, hm = h * 1e-3, m0 = 1e-6 * M_PI * R * R * h;
    /* the raster is a midpoint rule over the disc's chord lengths, whose square-root ends make
     * its error O((s/R)^{3/2}) = 3.4e-3 (the constants are 0.1 to 0.5 at K = 20, 44, 89) */
    double tol = pow(s / R, 1.5);
    CHECK_CLOSE(body.m, m0, tol, "disc mass");
    CHECK_CLOSE(body.inertia[2], m0 * Rm * Rm / 2, tol, "disc C = m R^2/2");
    CHECK_CLOSE(body.inertia[0], m0 * (Rm * Rm / 4 + hm * hm / 12), tol,
                "disc A = m (R^2/4 + h^2/12)");
    CHECK_CLOSE(body.inertia[1], m0 * (Rm * Rm / 4 + hm * hm / 12), tol, "disc Iyy");
    CHECK(hypot(body.com[0] - 0.05, body.com[1] - 0.06) < 1e-9, "com at the centre");
    CHECK_CLOSE(body.com[2], hm / 2, 1e-12, "com in the middle of the layer");
    CHECK_CLOSE(body.feature[TIPPE_GCODE_SOLID_INFILL].width_mm, s, 1e-9, "bead width = spacing");

    /* a hole of radius Rc drilled out of the disc after printing: the beads near the axis kept,
     * the plastic inside Rc cut (gcode_cut.c); the disc less a disc, whose moments are known.
     * The cut is the raster's midpoint rule again, over the hole's chords: (s/Rc)^{3/2} */
    double Rc = 5, tolc = pow(s / Rc, 1.5);
    tippe_gcode_beads near;
    o.override_density = 1;
    char path[] = "/tmp/tippe-disc-XXXXXX";
    int fd = mkstemp(path);
    FILE *f = fd >= 0 ? fdopen(fd, "w") : NULL;
    CHECK(f && fprintf(f, "; filament_diameter = 1.75\n%s", b.s) > 0 && fclose(f) == 0,
          "the disc's G-code written to %s", path);
    rc = tippe_gcode_read_beads(path, &o, Rc + 5, &body, &near, &err);
    unlink(path);
    CHECK(rc == TIPPE_OK && near.n > 0 && near.n < (size_t)K, "disc kept %zu of %d beads: %s",
          near.n, K, err.msg);
    tippe_gcode_body whole = body;
    tippe_gcode_cut cut = {50, 60, Rc, -1, 1};
    CHECK(tippe_gcode_cut_body(&body, &near, &cut, 1) == 0, "the cut is within the beads kept");
    double mc = whole.m * Rc * Rc / (R * R), Rcm = Rc * 1e-3;
    CHECK_CLOSE(body.cut_mass_kg, mc, tolc, "the hole's plastic");
    CHECK_CLOSE(body.m, whole.m - body.cut_mass_kg, 1e-12, "the body less the cut");
    CHECK_CLOSE(body.inertia[2], whole.inertia[2] - mc * Rcm * Rcm / 2, tolc * mc / body.m,
                "C of the disc less the hole");
    CHECK(hypot(body.com[0] - 0.05, body.com[1] - 0.06) < 1e-9 * 0.05, "com stays at the centre");
    CHECK(body.cut_hole_radius_mm[0] < 0, "raster lines cross the axis: no hole (%g)",
          body.cut_hole_radius_mm[0]);
    /* a cut over the bead's lower half takes half of it */
    body = whole;
    cut.z_hi_mm = 0.1;
    tippe_gcode_cut_body(&body, &near, &cut, 1);
    CHECK_CLOSE(body.cut_mass_kg, mc / 2, tolc, "half the layer's height");
    /* a cut the beads kept do not reach is refused */
    body = whole;
    cut.radius_mm = Rc + 3;
    CHECK(tippe_gcode_cut_body(&body, &near, &cut, 1) == -1 && body.m == whole.m,
          "a cut beyond the beads kept changes nothing");
    tippe_gcode_beads_free(&near);
    free(b.s);
}

/* ------------------------------------------------------------ (f) refusals */

static void expect_refusal(const sb *b, const tippe_gcode_options *o, const char *what,
                           const char *must1, const char *must2)
{
    tippe_gcode_body body;
    tippe_error err = {0};
    int rc = parse(b, o, &body, &err);
    CHECK(rc == TIPPE_EINPUT && strstr(err.msg, must1) && (!must2 || strstr(err.msg, must2)),
          "%s refused with '%s'%s%s: rc %d, '%s'", what, must1, must2 ? " and " : "",
          must2 ? must2 : "", rc, err.msg);
}

static void expect_mismatch(const tippe_gcode_body *body, const tippe_gcode_expect *x,
                            const char *what, const char *must1, const char *must2)
{
    tippe_gcode_part p;
    tippe_error err = {0};
    int rc = tippe_gcode_match(body, x, &p, &err);
    CHECK(rc == TIPPE_EINPUT && strstr(err.msg, "test.gcode") && strstr(err.msg, must1) &&
              (!must2 || strstr(err.msg, must2)),
          "%s refused with '%s': rc %d, '%s'", what, must1, rc, err.msg);
}

static void test_refusals(void)
{
    sb b = {0};
    tippe_gcode_options o = volumetric_options();
    tippe_error err = {0};
    tippe_gcode_body body;

    put(&b, "GCDE\x01");
    expect_refusal(&b, &o, "binary G-code", "test.gcode: binary G-code", NULL);
    clear(&b);
    put(&b, "M83\nG1 Z0.2\nG1 X1.2.3 E1\n");
    expect_refusal(&b, &o, "a bad number", "test.gcode:3:", "bad number");
    clear(&b);
    put(&b, "M83\nG1 Z0.2 E\n");
    expect_refusal(&b, &o, "E without a number", "test.gcode:2:", "without its number");
    clear(&b);
    put(&b, "G21\nG20\nG1 X1 E1\n");
    expect_refusal(&b, &o, "inch units", "test.gcode:2:", "G20");
    clear(&b);
    put(&b, "G18\n");
    expect_refusal(&b, &o, "an XZ arc plane", "test.gcode:1:", "plane");
    clear(&b);
    put(&b, "N1 G1 X1*12\n");
    expect_refusal(&b, &o, "a bad checksum", "test.gcode:1:", "checksum 12");
    clear(&b);
    put(&b, "M83\nG1 Z0.2\nG1 X10\nG1 E-1\nG1 E1\n;TYPE:Skirt\nG1 X20 E1\n");
    expect_refusal(&b, &o, "no extrusion in the body", "test.gcode:", "no extrusion");
    clear(&b);
    put(&b, "M83\nG1 Z0.2\nG1 X10 E1\n");
    tippe_gcode_options od = tippe_gcode_defaults();
    od.density_g_cm3 = 1.24;
    expect_refusal(&b, &od, "E without a filament diameter", "test.gcode:3:", "diameter");
    CHECK(tippe_gcode_read("/nonexistent/dir/x.gcode", &o, &body, &err) == TIPPE_EINPUT &&
              strstr(err.msg, "/nonexistent/dir/x.gcode") && strstr(err.msg, "cannot open"),
          "an unreadable file: '%s'", err.msg);

    /* the part's checks */
    clear(&b);
    put(&b, "M83\n;TYPE:External perimeter\n");
    tube(&b, 100, 100);
    int rc = parse(&b, &o, &body, &err);
    CHECK(rc == TIPPE_OK, "%s", err.msg);
    tippe_gcode_expect x = {0};
    x.height_mm = 12;
    expect_mismatch(&body, &x, "a wrong height", "10.000 mm high", "12.000");
    x.height_mm = 10.25; /* within one layer + 0.1 mm */
    tippe_gcode_part p;
    CHECK(tippe_gcode_match(&body, &x, &p, &err) == TIPPE_OK, "10.25 mm passes: %s", err.msg);
    x.diameter_mm = 38;
    expect_mismatch(&body, &x, "a wrong diameter", "40.450 mm x 40.450 mm", "38.000");
    x.diameter_mm = 0;
    x.axis_known = 1;
    x.axis_x_mm = 110;
    x.axis_y_mm = 100;
    expect_mismatch(&body, &x, "an axis elsewhere", "x = 100.000, y = 100.000", "10.000 mm away");
    x.axis_known = 0;
    x.bottom_z_mm = 2;
    expect_mismatch(&body, &x, "a part above the bed", "bottom is at z = 0.000", "2.000");

    /* two objects: PrusaSlicer's labels, Klipper's and M486 on the same two */
    clear(&b);
    put(&b, "M83\n;TYPE:External perimeter\n");
    for (int i = 0; i < 2; i++) {
        put(&b, "; printing object ball-%d.stl id:%d copy 0\nEXCLUDE_OBJECT_START NAME=ball_%d\n"
                "M486 S%d\nM486 Aball-%d.stl\n", i, i, i, i, i);
        ring(&b, 60 + 80 * i, 100, 10, 36, 0.2, 0.2, 0.45);
        put(&b, "; stop printing object ball-%d.stl id:%d copy 0\nEXCLUDE_OBJECT_END NAME=ball_%d\n"
                "M486 S-1\n", i, i, i);
    }
    rc = parse(&b, &o, &body, &err);
    CHECK(rc == TIPPE_OK && body.n_objects == 2, "two labelled objects parse (%d): %s",
          body.n_objects, err.msg);
    memset(&x, 0, sizeof x);
    expect_mismatch(&body, &x, "two labelled objects", "2 objects", "ball-1.stl id:1 copy 0");

    /* two unlabelled tubes apart: two clusters */
    clear(&b);
    put(&b, "M83\n;TYPE:External perimeter\n");
    ring(&b, 60, 100, 10, 36, 0.2, 0.2, 0.45);
    ring(&b, 90, 100, 5, 36, 0.2, 0.2, 0.45);
    rc = parse(&b, &o, &body, &err);
    CHECK(rc == TIPPE_OK && body.n_clusters == 2, "two disjoint rings: %d clusters",
          body.n_clusters);
    expect_mismatch(&body, &x, "two disjoint rings", "2 separate groups", "x = 90.");
    /* ... but a ring inside a ring joined by infill is one */
    put(&b, ";TYPE:Internal infill\nG1 X50 Y100\nG1 X85 Y100 E2\n");
    rc = parse(&b, &o, &body, &err);
    CHECK(rc == TIPPE_OK && body.n_clusters == 1, "joined by infill: %d clusters",
          body.n_clusters);
    free(b.s);
}

/* ------------------------------------------------------------ (g) the Python check */

/* A print like a slicer's: start G-code with a purge, a skirt, absolute E reset by G92,
 * retractions with wipes, z-hops, a ball-like stack of rings shrinking upwards (some laid
 * as G2/G3 arcs), raster infill, support, and the config at the end. */
static void mixed(sb *b)
{
    put(b, "; generated by PrusaSlicer 2.6.1 on 2024-01-01 at 10:00:00 UTC\n;TYPE:Custom\nG90\n"
           "M82\nG92 E0\nG1 Z0.3\nG1 X5 Y5\nG1 X80 Y5 E12\nG92 E0\n");
    double e = 0, cx = 110, cy = 95;
    for (int l = 1; l <= 40; l++) {
        double z = 0.2 * l, zc = 4.2, R = 12;
        double r = sqrt(fmax(R * R - (z - 0.1 - zc) * (z - 0.1 - zc), 4.0));
        put(b, ";LAYER_CHANGE\n;Z:%.3f\n;HEIGHT:0.2\nG1 Z%.3f\n", z, z);
        if (l == 1) {
            put(b, ";TYPE:Skirt/Brim\nG1 X%.3f Y%.3f\n", cx + r + 6, cy);
            for (int k = 1; k <= 48; k++)
                put(b, "G1 X%.3f Y%.3f E%.5f\n", cx + (r + 6) * cos(2 * M_PI * k / 48),
                    cy + (r + 6) * sin(2 * M_PI * k / 48), e += 0.05);
            put(b, "G1 E%.5f\nG92 E0\n", (e -= 0.8, e)); /* retract 0.8, reset */
            e = 0;
            put(b, "G1 E0.8\nG92 E0\n"); /* unretract */
        }
        put(b, ";TYPE:External perimeter\nG1 X%.3f Y%.3f\n", cx + r, cy);
        if (l % 3 == 0) {
            put(b, "G3 X%.3f Y%.3f I%.3f J0 E%.5f\n", cx - r, cy, -r, e += 0.033 * M_PI * r);
            put(b, "G2 X%.3f Y%.3f R%.3f E%.5f\n", cx + r, cy, -r, e += 0.033 * M_PI * r);
        } else {
            int n = 90;
            for (int k = 1; k <= n; k++)
                put(b, "G1 X%.3f Y%.3f E%.5f\n", cx + r * cos(2 * M_PI * k / n),
                    cy + r * sin(2 * M_PI * k / n), e += 0.033 * 2 * M_PI * r / n);
        }
        /* wipe while retracting, hop, travel, unretract */
        put(b, ";WIPE_START\nG1 X%.3f Y%.3f E%.5f\n;WIPE_END\n", cx + r * cos(0.2),
            cy + r * sin(0.2), e -= 0.5);
        e -= 0.3;
        put(b, "G1 E%.5f\nG1 Z%.3f\nG1 X%.3f Y%.3f\nG1 Z%.3f\n", e, z + 0.4, cx - r + 1, cy, z);
        put(b, "G1 E%.5f\n", e += 0.8);
        put(b, ";TYPE:%s\n", l <= 3 || l >= 38 ? "Solid infill" : "Internal infill");
        double step = l <= 3 || l >= 38 ? 0.45 : 3.0;
        for (double y = -r + 1; y <= r - 1; y += step) {
            double x = sqrt(fmax((r - 1) * (r - 1) - y * y, 0));
            put(b, "G1 X%.3f Y%.3f\nG1 X%.3f Y%.3f E%.5f\n", cx - x, cy + y, cx + x, cy + y,
                e += 0.033 * 2 * x);
        }
        if (l <= 10) {
            put(b, ";TYPE:Support material\nG1 X%.3f Y%.3f\nG1 X%.3f Y%.3f E%.5f\n", cx + 14,
                cy - 3, cx + 14, cy + 3, e += 0.2);
        }
        put(b, "G92 E0\n");
        e = 0;
    }
    put(b, ";TYPE:Custom\nG1 Z20\nG1 X0 Y200\n; filament used [mm] = 1000\n"
           "; filament_diameter = 1.75\n; filament_density = 1.24\n");
}

static double json_num(const cJSON *o, const char *path)
{
    char buf[128];
    snprintf(buf, sizeof buf, "%s", path);
    const cJSON *x = o;
    for (char *tok = strtok(buf, "."); tok && x; tok = strtok(NULL, ".")) {
        char *br = strchr(tok, '[');
        int idx = -1;
        if (br) {
            idx = atoi(br + 1);
            *br = 0;
        }
        x = cJSON_GetObjectItemCaseSensitive(x, tok);
        if (x && idx >= 0)
            x = cJSON_GetArrayItem(x, idx);
    }
    return cJSON_IsNumber(x) ? x->valuedouble : NAN;
}

static void test_python_check(void)
{
    if (access("/usr/bin/python3", X_OK) ||
        system("/usr/bin/python3 -c 'import numpy' 2>/dev/null")) {
        printf("skip: the Python cross-check needs /usr/bin/python3 with numpy\n");
        return;
    }
    sb b = {0};
    mixed(&b);
    char path[] = "/tmp/test_gcode_XXXXXX";
    int fd = mkstemp(path);
    CHECK(fd >= 0, "a temporary file");
    if (fd < 0)
        return;
    FILE *f = fdopen(fd, "w");
    fwrite(b.s, 1, b.n, f);
    fclose(f);
    tippe_gcode_body body;
    tippe_error err = {0};
    int rc = tippe_gcode_read(path, NULL, &body, &err);
    CHECK(rc == TIPPE_OK, "mixed file: %s", err.msg);
    char cmd[256];
    snprintf(cmd, sizeof cmd, "/usr/bin/python3 tools/gcode_moments.py --json %s", path);
    FILE *p = popen(cmd, "r");
    sb out = {0};
    char chunk[4096];
    size_t got;
    while (p && (got = fread(chunk, 1, sizeof chunk, p)) > 0)
        put(&out, "%.*s", (int)got, chunk);
    int status = p ? pclose(p) : -1;
    remove(path);
    cJSON *j = status == 0 && out.s ? cJSON_Parse(out.s) : NULL;
    CHECK(j != NULL, "tools/gcode_moments.py ran and gave JSON (status %d): %s", status,
          out.s ? out.s : "");
    if (rc == TIPPE_OK && j) {
        tippe_gcode_part part;
        rc = tippe_gcode_match(&body, NULL, &part, &err);
        CHECK(rc == TIPPE_OK, "mixed part: %s", err.msg);
        /* straight beads agree to rounding; every third layer's outer wall is an arc, which
         * the C reader lays along chords (sagitta 1e-4 mm: ~1e-5 of r^2) and Python along
         * the arc, so moments agree to 1e-5 and the mass exactly */
        CHECK_CLOSE(body.m, json_num(j, "mass_kg"), 1e-12, "mass, C vs Python");
        CHECK_CLOSE(body.body_volume_mm3, json_num(j, "volume_mm3"), 1e-12, "volume");
        CHECK_CLOSE(body.excluded_volume_mm3, json_num(j, "excluded_volume_mm3"), 1e-12,
                    "excluded volume");
        static const char *const com_key[3] = {"com_m[0]", "com_m[1]", "com_m[2]"};
        for (int i = 0; i < 3; i++)
            CHECK_CLOSE(body.com[i], json_num(j, com_key[i]), 1e-6, "com[%d]", i);
        CHECK_CLOSE(part.A, json_num(j, "part.A_kg_m2"), 1e-5, "A, C vs Python");
        CHECK_CLOSE(part.C, json_num(j, "part.C_kg_m2"), 1e-5, "C, C vs Python");
        CHECK_CLOSE(part.z_cm, json_num(j, "part.z_cm_m"), 1e-6, "z_cm, C vs Python");
        CHECK_CLOSE(body.inertia[2], json_num(j, "inertia_kg_m2[2]"), 1e-5, "Izz");
        /* the footprint: the arcs' extremes are chord vertices in C (within 1e-4 mm) */
        CHECK(fabs(body.bbox_max[0] - json_num(j, "bbox_max_m[0]")) < 1e-7 &&
                  fabs(body.bbox_min[1] - json_num(j, "bbox_min_m[1]")) < 1e-7 &&
                  fabs(body.bbox_min[2] - json_num(j, "bbox_min_m[2]")) < 1e-12,
              "bounding box, C vs Python");
    }
    cJSON_Delete(j);
    free(out.s);
    free(b.s);
}

/* ------------------------------------------------------------ (h) a real slicer's file */

/* A binary STL of a UV sphere of radius r standing on z = 0 (its centre at z = r). */
static int write_sphere_stl(const char *path, double r, int nt, int np)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return -1;
    char head[80] = {0};
    unsigned n = (unsigned)(2 * nt * np - 2 * np);
    fwrite(head, 1, 80, f);
    fwrite(&n, 4, 1, f);
    for (int i = 0; i < nt; i++)
        for (int j = 0; j < np; j++) {
            double t[2] = {M_PI * i / nt, M_PI * (i + 1) / nt};
            double q[2] = {2 * M_PI * j / np, 2 * M_PI * (j + 1) / np};
            float v[4][3];
            int idx[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
            for (int k = 0; k < 4; k++) {
                double th = t[idx[k][0]], ph = q[idx[k][1]];
                v[k][0] = (float)(r * sin(th) * cos(ph));
                v[k][1] = (float)(r * sin(th) * sin(ph));
                v[k][2] = (float)(r + r * cos(th));
            }
            int tri[2][3] = {{0, 1, 3}, {1, 2, 3}};
            for (int k = 0; k < 2; k++) {
                if ((k == 0 && i == 0) || (k == 1 && i == nt - 1))
                    continue; /* the poles' degenerate triangles */
                float rec[12] = {0};
                for (int c = 0; c < 3; c++)
                    memcpy(rec + 3 + 3 * c, v[tri[k][c]], sizeof v[0]);
                fwrite(rec, sizeof rec, 1, f);
                fwrite("\0\0", 2, 1, f);
            }
        }
    return fclose(f);
}

static void test_prusaslicer(void)
{
    if (access("/usr/bin/prusa-slicer", X_OK)) {
        printf("skip: the real-slicer check needs /usr/bin/prusa-slicer\n");
        return;
    }
    char dir[] = "/tmp/test_gcode_slicer_XXXXXX";
    if (!mkdtemp(dir)) {
        CHECK(0, "a temporary directory");
        return;
    }
    char stl[64], gcode[64], cmd[512];
    snprintf(stl, sizeof stl, "%s/ball.stl", dir);
    snprintf(gcode, sizeof gcode, "%s/ball.gcode", dir);
    CHECK(write_sphere_stl(stl, 8, 48, 96) == 0, "the sphere's STL");
    /* a 16 mm PLA ball: 2 perimeters, 4 top/bottom layers, 15 % infill, 0.3 mm layers */
    snprintf(cmd, sizeof cmd,
             "/usr/bin/prusa-slicer --export-gcode --perimeters 2 --top-solid-layers 4 "
             "--bottom-solid-layers 4 --fill-density 15%% --layer-height 0.3 "
             "--first-layer-height 0.3 --skirts 1 --filament-density 1.24 --gcode-label-objects "
             "--use-relative-e-distances --center 120,100 -o %s %s >/dev/null 2>&1",
             gcode, stl);
    int sliced = system(cmd);
    CHECK(sliced == 0, "prusa-slicer sliced the ball (status %d)", sliced);
    tippe_gcode_body body;
    tippe_error err = {0};
    int rc = sliced ? -1 : tippe_gcode_read(gcode, NULL, &body, &err);
    CHECK(rc == TIPPE_OK, "the sliced ball reads: %s", err.msg);
    if (rc == TIPPE_OK) {
        double area = M_PI * body.filament_diameter_mm * body.filament_diameter_mm / 4;
        double laid_mm = (body.body_volume_mm3 + body.excluded_volume_mm3) / area;
        /* the slicer's own total is what it laid, written to 0.01 mm */
        CHECK(fabs(laid_mm - body.slicer_filament_mm) <= 0.006,
              "laid %.4f mm of filament, the slicer says %.2f mm", laid_mm,
              body.slicer_filament_mm);
        CHECK(fabs(1e3 * (body.m + body.excluded_mass_kg) - body.slicer_filament_g) <= 0.006,
              "laid %.4f g, the slicer says %.2f g", 1e3 * (body.m + body.excluded_mass_kg),
              body.slicer_filament_g);
        CHECK(body.feature[TIPPE_GCODE_SKIRT_BRIM].volume_mm3 > 0 && body.n_objects == 1 &&
                  body.n_clusters == 1,
              "a skirt, one object (%d), one cluster (%d)", body.n_objects, body.n_clusters);
        tippe_gcode_expect x = {0};
        x.height_mm = 16;
        x.diameter_mm = 16;
        x.axis_known = 1;
        x.axis_x_mm = 120;
        x.axis_y_mm = 100;
        tippe_gcode_part p;
        rc = tippe_gcode_match(&body, &x, &p, &err);
        CHECK(rc == TIPPE_OK, "the ball matches a 16 mm ball at (120, 100): %s", err.msg);
        /* symmetric about its equator but for the top layer's quantisation (<= 0.3 mm) */
        CHECK(fabs(p.z_cm - 8e-3) < 0.3e-3, "z_cm %.4f mm", 1e3 * p.z_cm);
        /* walls and skins outside, sparse inside: between a solid ball's 2/5 and a shell's 2/3 */
        double k = p.C / (p.m * 8e-3 * 8e-3);
        CHECK(k > 0.4 && k < 2.0 / 3, "C / (m R^2) = %.4f", k);
        CHECK(sqrt(p.com_offset_x * p.com_offset_x + p.com_offset_y * p.com_offset_y) < 0.1e-3,
              "the centre of mass within 0.1 mm of the axis (%.4f, %.4f) mm",
              1e3 * p.com_offset_x, 1e3 * p.com_offset_y);
    }
    remove(gcode);
    remove(stl);
    rmdir(dir);
}

int main(void)
{
    test_rod();
    test_tube();
    test_cura_headers();
    test_density();
    test_bookkeeping();
    test_features();
    test_disc();
    test_refusals();
    test_python_check();
    test_prusaslicer();
    return check_summary("test_print_gcode");
}
