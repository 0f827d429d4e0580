/* tippe/print.h: a part as an FDM printer makes it -- walls, top/bottom skins
 * and sparse infill -- and the mass moments that follow.
 *
 * The part is printed with the top's axis vertical (z up): the only
 * orientation in which every layer is a set of concentric annuli, so the
 * printed part stays a solid of revolution and the top's A, C and eps keep
 * their meaning. The printed part P is the part's region minus the voids cut
 * from it. A point of P is solid material when
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
#ifndef TIPPE_PRINT_H
#define TIPPE_PRINT_H

#include "tippe/error.h"
#include "tippe/geometry.h"

/* Slicer settings, as a design file gives them. */
typedef struct {
    int perimeters;           /* walls, line widths */
    double line_width_mm;
    int top_bottom_layers;    /* skins, layers */
    double layer_height_mm;
    double infill;            /* fraction 0 .. 1 of the solid density */
} tippe_print_settings;

/* PrusaSlicer-like defaults: 2 x 0.45 mm perimeters, 4 x 0.2 mm top/bottom,
 * 15 % infill. */
tippe_print_settings tippe_print_defaults(void);

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

/* Mass moments of the printed part: density x (solid - (1 - infill) x core),
 * where solid is the printed part's unit-density moments (closed form). */
tippe_moments tippe_print_moments(tippe_moments solid, tippe_moments core, double density_kg_m3,
                                  double infill);

/* Mass is affine in the infill, m(f) = rho (V_solid - (1 - f) V_core), so the
 * infill that gives a weighed mass is (m / rho - V_solid + V_core) / V_core.
 * Returns 0 and sets *infill, or -1 if the mass is below the walls and skins
 * alone (f < 0), +1 if above the solid part (f > 1). mass_at_0 and mass_at_1
 * (kg, may be NULL) get the two limits for messages. */
int tippe_print_infill_for_mass(double mass_kg, double solid_volume_m3, double core_volume_m3,
                                double density_kg_m3, double *infill, double *mass_at_0,
                                double *mass_at_1);

#endif
