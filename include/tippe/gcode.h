/* tippe/gcode.h: the printed body as a slicer's G-code deposits it, and its
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
#ifndef TIPPE_GCODE_H
#define TIPPE_GCODE_H

#include "tippe/error.h"

#include <stddef.h>

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

/* The same for a file; TIPPE_EINPUT if it cannot be read. */
int tippe_gcode_read(const char *path, const tippe_gcode_options *opt, tippe_gcode_body *out,
                     tippe_error *err);

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
