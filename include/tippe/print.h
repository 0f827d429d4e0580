/* tippe/print.h: a part as it is printed, and the mass moments of solids.
 *
 * Contents:
 * - solids of revolution about the z axis and their mass moments (tippe_moments,
 *   tippe_ball, tippe_shell, tippe_tube, tippe_torus, tippe_inertia);
 * - the printed part: an FDM printer's walls, skins and sparse infill, as PrusaSlicer
 *   lays them layer by layer (tippe_print_*), and the infill a weighed mass gives;
 * - G-code: a slicer's printed body read back from its extrusion moves (tippe_gcode_*).
 * It knows no design file: tippe/design.h builds a design's printed parts on it. */
#ifndef TIPPE_PRINT_H
#define TIPPE_PRINT_H

#include <stddef.h>

#include "tippe/base.h"

/* ---- solids of revolution and their mass moments (src/print/geometry.c) ---- */
/* Geometry: mass properties of solids of revolution about the z axis.
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

/* ---- the printed part: walls, skins, infill, layer by layer (src/print/print.c,
 *      print_slicer.c) ---- */
/* Print: a part as an FDM printer makes it -- walls, top/bottom skins
 * and sparse infill -- and the mass moments that follow.
 *
 * The part is printed with the top's axis vertical (z up): the only
 * orientation in which every layer is a set of concentric annuli, so the
 * printed part stays a solid of revolution and the top's A, C and eps keep
 * their meaning. Two models: the slicer's rules applied layer by layer (the
 * default; tippe_print_slice_moments below, print_slicer.c), and the continuous
 * rule described here (print.c; "model": "skins"). The printed part P is the
 * part's region minus the voids cut from it. Under the continuous rule a point
 * of P is solid material when
 *   - (walls) in the horizontal layer through it, its radial distance to a
 *     circle bounding the annulus that contains it is at most wall_m
 *     (= perimeters x line width); the axis is not a boundary, so a layer that
 *     is a full disc has a wall only at its rim, but a ring with a tiny hole
 *     (near the pole of a shell's cavity) has one at the hole too;
 *   - (skins) on the vertical line through it, its distance to an end of the
 *     segment of P containing it is at most skin_m (= top/bottom layers x
 *     layer height);
 * and elsewhere (the "sparse core") it has infill x the material's density.
 * Layers are continuous (not quantised to the layer height).
 *
 * In the (r, z) half-plane the core is the set of points whose horizontal
 * segment [r - wall, r + wall] (mirrored through the axis) and vertical
 * segment [z - skin, z + skin] both lie in P. Its cross-section at a height z
 * is a union of annuli found exactly (every cross-section of a ball, shell,
 * tube or torus, clipped or not, is one annulus whose radii are monotone
 * either side of one centre height, so the extremes over [z - skin, z + skin]
 * are values at the ends or at a centre). The moments of each annulus are
 * closed forms in r; the remaining integral over z is done by GSL's adaptive
 * QAGS between breakpoints: every height where the set of curves bounding the
 * core changes (a wall meeting a skin, a hole's wall ending, ...), found by
 * bisection to ~1e-15 of the part's height from 2048 samples plus every centre
 * and end of a solid shifted by 0 and +-skin. The error bound returned is the
 * sum of QAGS's estimates; the requested accuracy is 1e-12 relative. */

/* The sparse infill patterns PrusaSlicer offers (its fill_pattern names). */
typedef enum {
    TIPPE_PATTERN_GYROID,
    TIPPE_PATTERN_RECTILINEAR,
    TIPPE_PATTERN_ALIGNED_RECTILINEAR,
    TIPPE_PATTERN_MONOTONIC,
    TIPPE_PATTERN_GRID,
    TIPPE_PATTERN_TRIANGLES,
    TIPPE_PATTERN_STARS,
    TIPPE_PATTERN_CUBIC,
    TIPPE_PATTERN_CONCENTRIC,
    TIPPE_PATTERN_HONEYCOMB,
    TIPPE_PATTERN_ADAPTIVE_CUBIC,
    TIPPE_PATTERN_SUPPORT_CUBIC,
    TIPPE_PATTERN_LIGHTNING,
    TIPPE_PATTERN_3D_HONEYCOMB,
    TIPPE_PRINT_N_PATTERNS
} tippe_print_pattern;

/* PrusaSlicer's perimeter_generator: its walls deposit the same volume either
 * way (docs/slicer-rules.md), so the model is one for both; the 3MF carries it. */
typedef enum { TIPPE_PERIMETERS_ARACHNE, TIPPE_PERIMETERS_CLASSIC } tippe_print_perimeter_generator;

/* Which rules make the printed part: the slicer's, layer by layer (the default,
 * print_slicer.c), or the earlier continuous rule of walls and vertical skins
 * (print.c), kept for comparison. */
typedef enum { TIPPE_PRINT_MODEL_SLICER, TIPPE_PRINT_MODEL_SKINS } tippe_print_model_kind;

/* Slicer settings, as a design file gives them; the defaults are PrusaSlicer
 * 2.5's for a 0.4 mm nozzle and 0.2 mm layers (its "0.20mm QUALITY" preset;
 * designs/slicer/prusa-pla-0.4mm.ini, which tippe slice uses). */
typedef struct {
    int perimeters;           /* walls, line widths */
    double line_width_mm;     /* perimeters (PrusaSlicer: perimeter_extrusion_width) */
    int top_bottom_layers;    /* skins, layers */
    double layer_height_mm;
    double infill;            /* fraction 0 .. 1 of the solid density */
    /* the slicer's rules (docs/slicer-rules.md) */
    int model;                     /* tippe_print_model_kind */
    int pattern;                   /* tippe_print_pattern */
    double external_width_mm;      /* external_perimeter_extrusion_width */
    double infill_width_mm;        /* infill_extrusion_width (sparse and solid) */
    double first_layer_height_mm;  /* first_layer_height */
    double first_layer_width_mm;   /* first_layer_extrusion_width; 0: each role's own */
    double top_min_mm, bottom_min_mm; /* top/bottom_solid_min_thickness */
    double infill_overlap;         /* of the perimeter spacing */
    double anchor_mm, anchor_max_mm; /* infill_anchor, infill_anchor_max */
    double nozzle_mm;              /* nozzle_diameter: bridges and overhangs are round threads */
    int thick_bridges;             /* thick_bridges: 1 bridges are round threads of the nozzle's
                                      diameter; 0 the role's own flat lines */
    /* solid_infill_below_area: a sparse island of a layer no larger than this is
     * solid (0: none) */
    double solid_infill_below_area_mm2;
    int perimeter_generator;       /* tippe_print_perimeter_generator */
    /* where a weighed mass (measured_mass_g) puts what the model lacks: 0 all in
     * the sparse infill (the infill that gives the mass), 1 all on every line (a
     * flow factor); the tolerance bands span the two readings */
    double calibration;
    double flow;                   /* extrusion multiplier */
    /* the print model's measured error against PrusaSlicer's G-code, in units of
     * the largest measured (TIPPE_PRINT_MODEL_ERROR_*): +1 moves the body as the
     * slicer's differs from it at most; 0 the model as it is. A tolerance term
     * (the bands' knife edge), not a setting of the slicer's */
    double model_error;
    /* printed in two halves cut at split_z_mm, each standing on its cut face (as
     * tippe export --split writes them): solid layers on both faces */
    int split;
    double split_z_mm;
} tippe_print_settings;

/* The print model against PrusaSlicer 2.5's G-code, every shipped design with
 * one printed body at 15, 25 and 40 % infill under three profiles
 * (tools/profiles_vs_model.py, docs/printing.md): the model's mass was 0.2 to
 * 1.4 % above the G-code's, its body A/C up to 0.0058 below (0.001 above).
 * model_error +1 is the G-code's side of the largest of each. Since bridges
 * over infill are modelled the A/C errors have both signs (the M3 -0.003, the
 * shells +0.004: docs/printing.md); the constants are kept as measured. */
#define TIPPE_PRINT_MODEL_ERROR_MASS 0.014
#define TIPPE_PRINT_MODEL_ERROR_AC 0.006

/* PrusaSlicer 2.5's: 2 x 0.45 mm perimeters, 4 x 0.2 mm top/bottom (at least
 * 0.7 / 0.5 mm), 15 % gyroid, 0.2 mm first layer of 0.42 mm lines, 25 % overlap,
 * anchors 2.5 / 12 mm, flow 1; the slicer's rules. */
tippe_print_settings tippe_print_defaults(void);

/* A slicer setting the model assumes that the print block does not give:
 * its PrusaSlicer 2.5 key, the value the model follows and what it decides. */
typedef struct {
    const char *key, *value, *decides;
} tippe_print_assumed;
/* The settings that change the deposit and that PrusaSlicer 2.5 takes per
 * object (PrintObjectConfig or PrintRegionConfig, PrintConfig.hpp), pinned in
 * tippe's 3MF so that any profile slices what the model assumes; ends with a
 * NULL key. The first layer's height and width are the print profile's alone
 * in 2.5 (PrintConfig): the build sheet names them. */
const tippe_print_assumed *tippe_print_assumed_settings(void);
/* One of them with the value a design's print block gives (thick_bridges,
 * solid_infill_below_area, perimeter_generator are modelled; the rest keep the
 * model's value): what tippe's 3MF writes for the part. */
typedef struct {
    const char *key;
    char value[32];
    const char *decides;
} tippe_print_pin;
/* The pinned settings for s into out[0 .. cap); returns how many (all of
 * tippe_print_assumed_settings, or cap). */
int tippe_print_pinned_settings(const tippe_print_settings *s, tippe_print_pin *out, int cap);

const char *tippe_print_pattern_name(int pattern);
/* The pattern of a PrusaSlicer fill_pattern name, -1 if none. */
int tippe_print_pattern_parse(const char *name);
/* The fraction of the nominal density a pattern deposits in bulk (print_slicer.c
 * gives each its source); 0 for a pattern whose deposit depends on the part's
 * shape (adaptive cubic, support cubic, lightning, 3D honeycomb). */
double tippe_print_pattern_bulk(int pattern);

/* The part as the slicer deposits it (print_slicer.c): unit-density volume
 * moments of everything laid down, and the volume of each kind of line. */
typedef struct {
    tippe_moments deposit;   /* SI, unit density, at the settings' infill and flow */
    double wall_m3, solid_m3, sparse_m3, anchor_m3; /* each kind of line, flow included */
    int n_layers;
    double bed_z_m, top_z_m; /* design frame: the face on the bed, the last layer's top */
    /* what tippe_print_sliced_at needs for another infill (unit density, no flow):
     * walls and solid infill, the sparse region, its boundary band s/2 wide */
    tippe_moments fixed, sparse_region, sparse_band;
    /* what the bridges over sparse infill add to the solid infill (none at 100 %) */
    tippe_moments over_infill;
    double s_fill_m;         /* the infill lines' spacing (layers after the first) */
} tippe_print_sliced;

static inline double tippe_print_wall_mm(const tippe_print_settings *s)
{
    return s->perimeters * s->line_width_mm;
}
static inline double tippe_print_skin_mm(const tippe_print_settings *s)
{
    return s->top_bottom_layers * s->layer_height_mm;
}

/* A solid of revolution about the z axis (lengths in m), as the geometry
 * module's constructors take them, with its clip: the solid is intersected
 * with the ball |x| <= clip_outer (0: not clipped) and, if clip_inner > 0,
 * with the outside of the ball |x| >= clip_inner (the wall of a shell). Both
 * clip balls are centred at the origin. */
typedef enum {
    TIPPE_SOLID_BALL,
    TIPPE_SOLID_SHELL,
    TIPPE_SOLID_TUBE, /* inner_radius 0: a plain cylinder */
    TIPPE_SOLID_TORUS
} tippe_solid_kind;

typedef struct {
    tippe_solid_kind kind;
    double z_centre;
    double radius;        /* ball, shell (outer), tube (outer) */
    double inner_radius;  /* shell (of its cavity), tube */
    double height;        /* tube */
    double centre_radius, radial_semi, axial_semi; /* torus */
    double clip_outer, clip_inner;
} tippe_solid;

typedef struct {
    tippe_moments core; /* unit-density volume moments of the sparse core (SI) */
    double abserr[4];   /* error bounds on core.m, m_z, m_zz, m_rr (QAGS estimates) */
    int n_pieces;       /* z intervals integrated separately */
} tippe_print_core;

/* The sparse core of part minus voids[0..n_voids) for walls wall_m thick and
 * skins skin_m thick (both >= 0; 0 and 0 give the whole printed part, which
 * tests compare with the closed forms). TIPPE_EINPUT for a void the model
 * cannot handle (a clipped torus void: its extreme radii over a height range
 * are not at a centre); TIPPE_ECOMPUTE if GSL cannot allocate or QAGS cannot
 * reach 1e-10 of the part's scale. Reentrant. */
int tippe_print_core_moments(const tippe_solid *part, const tippe_solid *voids, int n_voids,
                             double wall_m, double skin_m, tippe_print_core *out,
                             tippe_error *err);

/* The slicer's rules applied layer by layer to part minus voids[0..n_voids),
 * printed with its axis vertical on the bed at its lowest point (flip: upside
 * down, on its highest). TIPPE_EINPUT for a pattern whose deposit is not
 * modelled, or more layers than the model takes. Reentrant. */
int tippe_print_slice_moments(const tippe_solid *part, const tippe_solid *voids, int n_voids,
                              const tippe_print_settings *s, int flip, tippe_print_sliced *out,
                              tippe_error *err);
/* Where part minus voids[0..n_voids), printed whole with its axis vertical,
 * meets the bed and where its last layer's top is (design frame, m; as
 * tippe_print_slice_moments's bed_z_m and top_z_m): to place a G-code whose
 * holes are printed otherwise than the model's. 0 when nothing is printed. */
int tippe_print_edges(const tippe_solid *part, const tippe_solid *voids, int n_voids,
                      double *bed_z_m, double *top_z_m);
/* One layer of tippe_print_slice_layers: where it is and what it deposits. */
typedef struct {
    double z_mid_m, thickness_m; /* design frame */
    double wall_m3, solid_m3, sparse_m3, anchor_m3;
} tippe_print_layer;
/* The same, with each layer's deposit in rows[0 .. min(n_layers, cap)) (bottom
 * up, as printed): to hold the model against a G-code layer by layer. */
int tippe_print_slice_layers(const tippe_solid *part, const tippe_solid *voids, int n_voids,
                             const tippe_print_settings *s, int flip, tippe_print_sliced *out,
                             tippe_print_layer *rows, int cap, tippe_error *err);
/* The same part's deposit (unit density) at another infill, and its sparse and
 * anchor volumes (may be NULL): walls and solid infill stay. */
tippe_moments tippe_print_sliced_at(const tippe_print_sliced *sl, const tippe_print_settings *s,
                                    double infill, double *sparse_m3, double *anchor_m3);

/* Mass is affine in the infill, m(f) = rho (V_solid - (1 - f) V_core), so the
 * infill that gives a weighed mass is (m / rho - V_solid + V_core) / V_core.
 * Returns 0 and sets *infill, or -1 if the mass is below the walls and skins
 * alone (f < 0), +1 if above the solid part (f > 1). mass_at_0 and mass_at_1
 * (kg, may be NULL) get the two limits for messages. */
int tippe_print_infill_for_mass(double mass_kg, double solid_volume_m3, double core_volume_m3,
                                double density_kg_m3, double *infill, double *mass_at_0,
                                double *mass_at_1);

/* ---- G-code: the body a slicer deposits, read back (src/print/gcode.c, gcode_body.c,
 *      gcode_text.c) ---- */
/* G-code: the printed body as a slicer's G-code deposits it, and its
 * mass moments.
 *
 * The G-code is the truth of where the plastic is: every extruding move lays a
 * bead along its segment. We read FFF G-code as PrusaSlicer, SuperSlicer,
 * OrcaSlicer (BambuStudio's "; FEATURE:" comments too) and Cura write it, sum
 * the beads into the mass, first and second moments of the deposit, and find the
 * printed part in it: its axis, bottom, height and footprint.
 *
 * What a move deposits (the filament's bookkeeping, see src/gcode.c):
 *   - E is filament length (mm) unless volumetric (M200 D>0 or the slicer's
 *     "; use_volumetric_e = 1": E is then mm^3); dV = (pi d^2 / 4) dE.
 *   - A negative dE (a retraction, also while wiping) deposits nothing and is
 *     owed; a positive dE first pays back what is owed (a deretraction
 *     restores filament, it does not lay new plastic) and deposits only the
 *     rest. So the deposit is exactly the net filament pushed plus what is
 *     still retracted at the end (a retraction sucks back melt, it does not
 *     unlay plastic): the filament is conserved.
 *   - The rest is laid uniformly along the move's segment (G2/G3 arcs: along
 *     chords within 1e-4 mm of the arc); with no motion (a deretraction longer
 *     than the retraction, PrusaSlicer's retract_restart_extra) it is a point.
 *   - Firmware retraction (G10/G11) moves filament the firmware puts back:
 *     nothing.
 *
 * The bead (TIPPE_GCODE_BEAD_BOX, the default): the nozzle's height z is the
 * top of the bead it lays (the slicer's model: a layer is the slab h thick
 * below the nozzle; placing the mass at the nozzle would raise the centre of
 * mass by h/2, 0.1 mm, a few % of a top's eps). So a bead is a box h high and
 * w = dV / (L h) wide (the slicer's flow, inverted) around the segment of
 * length L at z - h/2; h is the slicer's ";HEIGHT:" / "; LAYER_HEIGHT:"
 * comment, else the height above the highest earlier deposit's nozzle height
 * below z, or above the bed (custom G-code and, in a labelled file, unlabelled
 * G-code -- start G-code's purge lines -- do not count). Its moments are the
 * segment's (a uniform rod) plus the box's cross-section, dV w^2/12 across the
 * segment and dV h^2/12 vertically: exact for a box, and a stack of layers of
 * one path is exactly the prism it approximates. A real bead differs by ~1e-4
 * of a top's moments: PrusaSlicer's rounded sides, and a curved bead's mass
 * leaning outwards (w^2/6 of r^2 on a ring of radius r). TIPPE_GCODE_BEAD_LINE
 * is the thin rod along the nozzle's path (no shift, no cross-section), for
 * checks.
 *
 * Features. Each move carries the feature its slicer labelled it with. The
 * part's body is the walls, skins, infill, bridges, gap fill (and what is
 * labelled otherwise, "other"); skirt, brim, support, support interface, wipe
 * and prime towers and the slicer's custom G-code (start, end) are excluded
 * and counted apart. Extrusion before any label is "unlabelled": excluded when
 * the file labels its features, the body when it labels none.
 *
 * Frames: the body's numbers are in the bed's frame (SI); tippe_gcode_match
 * finds the part and gives the part's frame (z from its bottom, the axis
 * through the centre of its footprint). The library never prints; reentrant. */
typedef enum {
    /* the body; the labels (PrusaSlicer/SuperSlicer; OrcaSlicer; Cura) that mean each */
    TIPPE_GCODE_EXTERNAL_PERIMETER, /* External perimeter; Outer wall; WALL-OUTER */
    TIPPE_GCODE_PERIMETER,          /* (Internal, Overhang) perimeter, Thin wall; Inner wall,
                                       Overhang wall; WALL-INNER */
    TIPPE_GCODE_SOLID_INFILL,       /* Solid infill; Internal solid infill, Bottom surface; SKIN */
    TIPPE_GCODE_TOP_SOLID_INFILL,   /* Top solid infill; Top surface */
    TIPPE_GCODE_BRIDGE_INFILL,      /* (Internal) bridge infill; Bridge, Internal Bridge */
    TIPPE_GCODE_SPARSE_INFILL,      /* Internal infill; Sparse infill; FILL */
    TIPPE_GCODE_GAP_FILL,           /* Gap fill; Gap infill */
    TIPPE_GCODE_OTHER,              /* Ironing, Mixed, any label we do not know */
    /* excluded */
    TIPPE_GCODE_SKIRT_BRIM,         /* Skirt/Brim; Skirt, Brim; SKIRT */
    TIPPE_GCODE_SUPPORT,            /* Support material; Support, Support transition; SUPPORT */
    TIPPE_GCODE_SUPPORT_INTERFACE,  /* Support material interface; Support interface;
                                       SUPPORT-INTERFACE */
    TIPPE_GCODE_WIPE_TOWER,         /* Wipe tower; Prime tower; PRIME-TOWER */
    TIPPE_GCODE_CUSTOM,             /* Custom: the slicer's start, end and custom G-code */
    TIPPE_GCODE_UNLABELLED,         /* before any label (Cura: after a layer's ;TIME_ELAPSED:) */
    TIPPE_GCODE_N_FEATURES
} tippe_gcode_feature;

/* "external perimeter", "sparse infill", ...; "?" out of range. */
const char *tippe_gcode_feature_name(tippe_gcode_feature f);

typedef enum {
    TIPPE_GCODE_BEAD_BOX,  /* a w x h box below the nozzle (default) */
    TIPPE_GCODE_BEAD_LINE  /* a thin rod along the nozzle's path */
} tippe_gcode_bead;

/* Plastic the part loses after printing: a cylinder about a vertical axis
 * (bed frame, mm) cut away -- a thread tapped to the hole's modelled radius,
 * a hole drilled out, a bore for an insert (tippe_gcode_cut_body). */
typedef struct {
    double axis_x_mm, axis_y_mm, radius_mm, z_lo_mm, z_hi_mm;
} tippe_gcode_cut;
#define TIPPE_GCODE_MAX_CUTS 4
#define TIPPE_GCODE_CUT_STEP_MM 0.05

/* How to read a file. The filament's diameter and density come from the
 * slicer's config comments ("; filament_diameter = 1.75", "; filament_density
 * = 1.24"; comma lists per extruder, picked by T<n>) when the file has them;
 * a value > 0 here fills in what the file lacks (Cura writes neither), or
 * replaces the file's when its override flag is set. Neither known: refused. */
typedef struct {
    double filament_diameter_mm;
    int override_diameter;
    double density_g_cm3;
    int override_density;
    int volumetric_e;      /* -1: as the file says; 0: E is filament mm; 1: E is mm^3 */
    tippe_gcode_bead bead;
} tippe_gcode_options;

/* No values, no overrides, volumetric_e -1, the box bead. */
tippe_gcode_options tippe_gcode_defaults(void);

/* What each feature deposited. */
typedef struct {
    double volume_mm3;
    double mass_kg;
    double length_mm;      /* of the moves that deposited, along the nozzle's path */
    double width_mm;       /* mean bead width: volume / sum(length x bead height); 0 if unknown */
    long n_moves;          /* depositing moves (an arc counts once) */
} tippe_gcode_share;

#define TIPPE_GCODE_NAME_MAX 128

/* The printed body, in the bed's frame (SI unless the name says otherwise). */
typedef struct {
    char source[256];          /* the file's name as given, for messages */
    char generator[64];        /* e.g. "PrusaSlicer 2.6.1", "Cura_SteamEngine 5.4.0"; "" unknown */
    double filament_diameter_mm;  /* as used for tool 0 (NAN when E is volumetric throughout) */
    double header_diameter_mm;    /* tool 0's as the file's own header says (NAN: none) */
    double density_g_cm3;         /* as used for tool 0 */
    int volumetric_e;             /* E was volumetric at the first deposit */
    int labelled;                 /* the file labels its features */
    long n_lines;

    tippe_gcode_share feature[TIPPE_GCODE_N_FEATURES];
    double body_volume_mm3, excluded_volume_mm3;
    double excluded_mass_kg;
    double point_volume_mm3;      /* of the body, laid with no motion (as points) */
    double filament_mm;           /* net filament pushed, every feature (0 if E volumetric) */
    double retracted_at_end_mm;   /* tool 0's filament still retracted at the end, never
                                     deposited (mm^3 if E is volumetric then) */
    double slicer_filament_mm;    /* the slicer's own total ("; filament used [mm] =", Cura
                                     ";Filament used: ...m"); NAN if absent */
    double slicer_filament_g;     /* "; filament used [g] ="; NAN if absent */

    /* tippe_gcode_cut_body's cuts (0 until then): the body's plastic they
     * took away, and the hole the G-code leaves about each cut's axis within
     * its z range (the innermost edge of a bead more than half of whose height
     * lies in it; INFINITY if none comes within the cut's radius plus 2 mm) */
    double cut_volume_mm3, cut_mass_kg;
    double cut_hole_radius_mm[TIPPE_GCODE_MAX_CUTS];

    /* the body's mass properties */
    double m;                     /* kg */
    double com[3];                /* m */
    /* inertia tensor about the centre of mass, bed axes, kg m^2: Ixx, Iyy, Izz,
     * Ixy, Ixz, Iyz with the products of inertia signed as tensor components
     * (Ixy = -sum m x y) */
    double inertia[6];
    double bbox_min[3], bbox_max[3]; /* m, the beads' extents (w/2 sideways, h below) */
    int n_layers;                 /* distinct nozzle heights of the body's deposits */
    double layer_height;          /* m, volume-weighted mean bead height of the body */
    double first_layer_z;         /* m, nozzle height of the body's lowest deposit */

    /* one part? */
    int n_objects;                /* objects labelled with body in them (0: none labelled) */
    char object[2][TIPPE_GCODE_NAME_MAX]; /* the first two */
    int n_clusters;               /* disjoint groups of the body's footprint (seen from above) */
    double cluster_volume_mm3[2]; /* the two largest */
    double cluster_centre[2][2];  /* m, x y of their footprints' bounding-box centres */
} tippe_gcode_body;

/* Reads a G-code text (len bytes, not necessarily NUL-terminated); name is
 * used in messages; opt NULL: the defaults. TIPPE_EINPUT for: a bad number or
 * word ("NAME:LINE: ..."), a bad checksum, inch units (G20), an arc in another
 * plane (G18/G19) or whose radius cannot reach its end, no filament diameter
 * (for E in mm) or density, binary G-code (.bgcode), no extrusion in the body.
 * TIPPE_ECOMPUTE if memory runs out. */
int tippe_gcode_parse_buffer(const char *text, size_t len, const char *name,
                             const tippe_gcode_options *opt, tippe_gcode_body *out,
                             tippe_error *err);

/* The same body at another density (g/cm^3): every mass scales with it.
 * Exact only for a body read with one density for every tool (the options'
 * own, override_density): the reader's cache rescales a body read once. */
void tippe_gcode_body_set_density(tippe_gcode_body *b, double density_g_cm3);

/* The largest G-code file read: PrusaSlicer's G-code of a 60 mm ball at
 * 0.1 mm layers is about 30 MiB; eight times that leaves room for any top. */
#define TIPPE_GCODE_MAX_MIB 256

/* The same for a file: a regular file of at most TIPPE_GCODE_MAX_MIB MiB
 * (tippe_file_read); TIPPE_EINPUT if it cannot be read. */
int tippe_gcode_read(const char *path, const tippe_gcode_options *opt, tippe_gcode_body *out,
                     tippe_error *err);

/* The body's beads near its axis (the vertical through the centre of its
 * footprint, as tippe_gcode_match finds it), kept to cut from it later: each
 * a box bead's nozzle path (bed frame, mm), height, width and volume. */
typedef struct {
    float x0, y0, z0, x1, y1, z1, h_mm, w_mm, volume_mm3;
} tippe_gcode_near_bead;
typedef struct {
    tippe_gcode_near_bead *bead;
    size_t n;
    double radius_mm; /* every body bead that comes this near the axis is kept */
} tippe_gcode_beads;

/* tippe_gcode_read, keeping in *beads (freed by tippe_gcode_beads_free) the
 * body's beads within radius_mm of its axis (the box bead only). */
int tippe_gcode_read_beads(const char *path, const tippe_gcode_options *opt, double radius_mm,
                           tippe_gcode_body *out, tippe_gcode_beads *beads, tippe_error *err);
void tippe_gcode_beads_free(tippe_gcode_beads *beads);
/* tippe_gcode_parse_buffer, the body's beads within keep_radius_mm of its axis kept
 * in *near (keep_radius_mm 0: none, near may be NULL): a G-code in memory (tippe
 * serve's uploads) cut for its part's holes as a file's is. */
int tippe_gcode_parse_near(const char *text, size_t len, const char *name,
                           const tippe_gcode_options *opt, double keep_radius_mm,
                           tippe_gcode_body *out, tippe_gcode_beads *near, tippe_error *err);

/* Cuts from the body (read at one density for every tool, with the beads near
 * its axis out to every cut's radius + 3 mm) what n cuts take away: a bead
 * loses, in pieces of TIPPE_GCODE_CUT_STEP_MM along its path, the share of its
 * width inside a cut's radius (its width taken across the radius, as a wall's
 * bead around a hole lies) times the share of its height inside the cut's z
 * range; its mass moments go with it. Sets the body's cut_* fields; m, com,
 * inertia and body_volume_mm3 are then the part's after the cut. Returns 0, or
 * -1 when a cut reaches beyond the beads kept (nothing changed). */
int tippe_gcode_cut_body(tippe_gcode_body *body, const tippe_gcode_beads *beads,
                         const tippe_gcode_cut *cut, int n_cuts);

/* What the part should be: a solid of revolution printed with its axis
 * vertical. A size 0 is not checked; a tolerance 0 is the default; NULL
 * expects nothing but one part on the bed. */
typedef struct {
    double height_mm;          /* the part's height */
    double diameter_mm;        /* its widest horizontal extent (a sphere's diameter) */
    double bottom_z_mm;        /* bed height of its bottom (0: on the bed) */
    int axis_known;
    double axis_x_mm, axis_y_mm; /* where its axis stands on the bed, if known */
    double height_tol_mm;      /* default: one layer (the body's) + 0.1 mm; also for the bottom */
    double diameter_tol_mm;    /* default: the external perimeter's bead width + 0.1 mm */
    double axis_tol_mm;        /* default: as the diameter's */
} tippe_gcode_expect;

/* The part in its own frame, SI: z from the part's bottom, the axis through the
 * centre of its footprint (the bounding box of the beads seen from above). */
typedef struct {
    double axis_x, axis_y;     /* m, bed frame */
    double bottom_z;           /* m, bed frame */
    double height, diameter_x, diameter_y; /* m, of the deposit */
    double m;                  /* kg */
    double z_cm;               /* m above the bottom */
    double com_offset_x, com_offset_y; /* m, the centre of mass from the axis */
    double A;                  /* kg m^2: mean of Ixx, Iyy about the centre of mass */
    double C;                  /* kg m^2: Izz about the axis */
    double Ixx, Iyy, Ixy;      /* kg m^2, about the centre of mass (Ixy a tensor component) */
    double asymmetry;          /* (I1 - I2) / A for the principal transverse moments I1 >= I2 */
    double off_diagonal;       /* hypot(Ixz, Iyz) / A about the centre of mass: 0 when z is a
                                  principal axis (a top's A ~ C, so no tilt angle is given) */
} tippe_gcode_part;

/* Finds the part in the body and checks it against what is expected: refuses
 * (TIPPE_EINPUT, the message naming body->source, what is wrong and the
 * numbers) several objects (labelled, or disjoint footprints), a height, a
 * bottom or a footprint off by more than their tolerance, an axis away from
 * the expected one. */
int tippe_gcode_match(const tippe_gcode_body *body, const tippe_gcode_expect *expect,
                      tippe_gcode_part *out, tippe_error *err);

#endif
