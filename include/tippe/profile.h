/* tippe/profile.h: the printed bodies of a design as profiles in the (r, z) half-plane.
 *
 * Every part is a solid of revolution about the z axis, so a printed body is a
 * region of the half-plane r >= 0 revolved about the axis. This module builds
 * that region for the parts a maker prints -- every fixed, non-void part of a
 * printable material, with the voids cut from it -- as polygons whose chords
 * stay within chord_mm / 2 of the true arcs (circles and ellipses), so that the
 * revolved mesh (src/export/mesh.h, which spends the other half on its angular
 * steps) is within chord_mm of the true surface. Boolean operations on the
 * polygons (union of touching parts, voids cut, split plane) are GEOS's.
 *
 * Holes that take hardware (a void that a non-printable part enters at some
 * Z2 of the travel) are grown by clearance_mm radially before cutting; the
 * design's mass model (tippe/design.h) is not changed by this.
 *
 * Units: mm throughout (the design file's). */
#ifndef TIPPE_PROFILE_H
#define TIPPE_PROFILE_H

#include <stdio.h>

#include "tippe/design.h"
#include "tippe/base.h"

typedef struct {
    double r_mm, z_mm;
} tippe_profile_point;

/* A closed ring (last point != first). Exterior rings run counter-clockwise
 * in the (r, z) plane (r to the right, z up), holes clockwise. */
typedef struct {
    int n;
    tippe_profile_point *pt;
} tippe_profile_ring;

typedef struct {
    char name[128];     /* "body", "shell+band", "body-lower" */
    char material[64];
    int n_rings;        /* ring[0] exterior, the rest holes */
    tippe_profile_ring *ring;
    /* Volume of the region revolved exactly (Pappus on the polygon), mm^3:
     * what the mesh converges to as its angular step shrinks. */
    double polygon_volume_mm3;
    /* The body's exact volume from the geometry module's closed forms (parts
     * less voids, clearance included), mm^3; NAN when not known in closed form
     * (the halves of a split body: their sum is the whole's). */
    double exact_volume_mm3;
    double r_max_mm, z_min_mm, z_max_mm;
    /* Print orientation of a split half: 1 if it is printed upside down (the
     * lower half, whose cut face is on top in the design), else 0. */
    int flip;
    /* Height of the cut plane of a split half (mm, design frame), else NAN. */
    double cut_z_mm;
} tippe_profile_body;

typedef struct {
    double chord_mm;     /* deviation of mesh from true surface; the profile uses half */
    double clearance_mm; /* radial clearance of holes that take hardware */
    double min_wall_mm;  /* thinner walls get a warning (two perimeters) */
    int split;           /* cut each body at split_z_mm into two */
    double split_z_mm;
    int joint;           /* with split: a groove in both halves' cut faces and a
                            ring that fills them (body "joint-ring"), see below */
    /* A hole printed for its thread rather than for a sliding fit: void part
     * fit_part (one that takes hardware) is printed at fit_diameter_mm (e.g. a
     * tap drill) instead of its own diameter plus the clearance; 0: off. */
    int fit_part;
    double fit_diameter_mm;
    /* Sockets for a rod that spans a shell's cavity (a fixed hardware cylinder
     * clipped to the cavity, held by nothing else): at each pole the rod
     * reaches, a pocket of the rod's radius plus clearance_mm, cut into the
     * wall TIPPE_PROFILE_SOCKET_DEPTH_MM beyond where its side meets the
     * cavity, so that the rod (cut square, that much longer at each end) is
     * held on the axis: clipped to the cavity it could tilt about the centre.
     * Printed only, like the clearance: the mass model keeps the design. */
    int sockets;
} tippe_profile_options;

#define TIPPE_PROFILE_SOCKET_DEPTH_MM 1.0

/* The joint ring of split halves: its grooves are this deep in each half, mm;
 * a wall narrower than twice TIPPE_PROFILE_JOINT_MIN_MM (plus the clearance)
 * at the cut gets none. */
#define TIPPE_PROFILE_JOINT_DEPTH_MM 2.0
#define TIPPE_PROFILE_JOINT_MIN_MM 1.0

enum { TIPPE_PROFILE_MAX_WARNINGS = 16 };

typedef struct {
    int n_bodies;
    tippe_profile_body *body;
    /* Voids grown by the clearance, by part index (1 grown, 0 not); n_parts entries. */
    int n_parts;
    int *clearance_applied;
    int n_warnings;
    char warning[TIPPE_PROFILE_MAX_WARNINGS][320];
    double thinnest_wall_mm; /* thinnest wall found below min_wall_mm, else NAN */
    /* The joint's grooves (split with joint): each removes r in [r_in, r_mid]
     * to TIPPE_PROFILE_JOINT_DEPTH_MM on both sides of the cut; its ring is
     * r in [r_wall, r_mid - clearance], 2 depth - clearance high. */
    int n_grooves;
    double groove_r_in_mm[8], groove_r_wall_mm[8], groove_r_mid_mm[8];
    /* The sockets cut (options.sockets): rod part, pocket radius, the height
     * where the pocket's side meets the cavity (rim) and of its flat floor,
     * signed (negative at the -z pole); the printed volume each removes. */
    int n_sockets;
    int socket_part[2];
    double socket_r_mm[2], socket_rim_z_mm[2], socket_floor_z_mm[2], socket_volume_mm3[2];
} tippe_profile_set;

/* Defaults: chord 0.01 mm, clearance 0.2 mm, min wall 0.9 mm (two 0.45 mm
 * perimeters of a 0.4 mm nozzle), no split. */
tippe_profile_options tippe_profile_defaults(void);

/* Whether part i is printed: a fixed, non-void part of a printable material
 * or with a print block (an inline density_g_cm3 with a print block is
 * filament too: the mass model prints it). */
int tippe_profile_part_printed(const tippe_design *d, int i);

/* Whether part i is filament (printed, or to be printed if it moves), by the
 * rule above; a void: its part's. For drawings. */
int tippe_profile_part_filament(const tippe_design *d, int i);

/* Builds the printed bodies. TIPPE_EINPUT (message naming the design file) if
 * the design prints nothing, if a body is cut away entirely, or if an option is
 * out of range; TIPPE_ECOMPUTE if GEOS fails. Warnings (thin walls, hardware
 * enclosed by a body, a body in several pieces) go to out->warning. */
int tippe_profile_build(const tippe_design *d, const tippe_profile_options *opt,
                        tippe_profile_set *out, tippe_error *err);

/* The (r, z) outline of part i's own solid (before voids), moved by dz_mm,
 * with the same chord rule; for drawings. Returns the number of rings written
 * into *rings (caller frees with tippe_profile_rings_free), or -1 on failure. */
int tippe_profile_part_outline(const tippe_design *d, int i, double dz_mm, double chord_mm,
                               tippe_profile_ring **rings);
void tippe_profile_rings_free(tippe_profile_ring *rings, int n);

/* Number of steps around the axis that keeps the chord of a circle of radius
 * r_max_mm within sag_mm: a multiple of 4 (so the bounding box is exact), >= 8. */
int tippe_profile_angle_steps(double r_max_mm, double sag_mm);

void tippe_profile_set_free(tippe_profile_set *s);

/* Reports for eval and sweep: how each printed part is printed (settings,
 * infill as given or calibrated, masses) and the bodies as tippe export writes
 * them (default clearance, a hole at its printed_radius_mm) with their exact
 * volumes; or a line saying every
 * part is solid. The JSON adds "printed_parts": [{part, perimeters,
 * line_width_mm, top_bottom_layers, layer_height_mm, wall_mm, skin_mm, infill,
 * slicer_infill, calibrated, measured_mass_kg, printed_mass_kg, solid_mass_kg,
 * skin_mass_kg, model_rel_error}] (empty when all parts are solid) and
 * "printed_bodies": [{name, material, volume_mm3, clearance_mm, printed_hole:
 * {hole, diameter_mm} or null (a hole at its printed_radius_mm, as tippe export
 * prints it), fit_not_counted: a hole whose "tap"/"insert" fit tippe export
 * applies and this volume does not, or null}] to o; -1 when out of memory. */
void tippe_profile_print_printed_parts(FILE *out, const tippe_design *d);
struct cJSON;
int tippe_profile_printed_parts_json(struct cJSON *o, const tippe_design *d);

#endif
