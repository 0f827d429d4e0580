/* src/export/drawing.h: the dimensioned cross-section of a design, for the maker.
 *
 * The section through the axis: every part cut and hatched by material (a
 * legend names them), the printed bodies' holes with their clearance, the
 * moving weight at Z2 in its own colour with its travel as a bracket, the
 * centre of the sphere (O) and the centre of mass (G) marked, and the main
 * dimensions with their values in mm (sphere radius, shell thickness, hole and
 * weight diameters and heights, band semi-axes, Z2). The format follows the
 * file's extension: .svg (written directly; each dimension is a <text> with
 * class "dim" and data-mm="VALUE", so a test can read the values back), .png
 * or .pdf (cairo). Written atomically (tippe/base.h). */
#ifndef TIPPE_EXPORT_DRAWING_H
#define TIPPE_EXPORT_DRAWING_H

#include "tippe/design.h"
#include "tippe/base.h"

typedef struct {
    double z2_mm;
    double com_z_mm;            /* centre of mass above (+) the sphere's centre */
    const char *title;          /* first line */
    const char *note;           /* second line (the zone at Z2), or NULL */
    double clearance_mm;        /* grown holes are drawn grown, and say so */
    const int *clearance_applied; /* per part, or NULL */
    double chord_mm;            /* outline accuracy */
    /* a hole printed for its thread (tippe_profile_options.fit_*): its printed
     * diameter and why ("M10 x 1.5 tap drill"); fit_diameter_mm 0: none */
    int fit_part;
    double fit_diameter_mm;
    const char *fit_note;
    /* printed in halves: the cut plane at cut_z_mm is drawn (and the joint's
     * grooves named when joint) */
    int has_cut, joint;
    double cut_z_mm;
    /* a rod's sockets (tippe_profile_set's): drawn cut into the wall, the rod
     * drawn to their floors and its length dimensioned; n_sockets 0: none */
    int n_sockets, socket_part[2];
    double socket_r_mm[2], socket_rim_z_mm[2], socket_floor_z_mm[2];
    /* the build sheet's setting: the depth from the rim (depth_rim_z_mm) to
     * the weight's end (depth_end_z_mm) as a dimension, at depth_x_mm from the
     * axis (the hole's wall), labelled "depth_label"; has_depth 0: none */
    int has_depth;
    double depth_rim_z_mm, depth_end_z_mm, depth_x_mm;
    const char *depth_label;
    const char *depth_from; /* "the rim" (NULL), "the rod's end" */
    /* a .pdf at 1:1 on an A4 landscape page (1 mm of the top is 1 mm of
     * paper when printed at 100 %), with a 50 mm bar to check it; TIPPE_EINPUT
     * when the drawing does not fit the page at 1:1 */
    int one_to_one;
} tippe_drawing_options;

int tippe_drawing_write(const tippe_design *d, const tippe_drawing_options *o, const char *path,
                        tippe_error *err);

/* The same drawing rendered into the box (x, y, w, h) of a cairo context
 * (a cairo_t *, in its units), scaled to fit with its aspect kept: for a page
 * that holds it beside other things (the build sheet, tippe/build.h). */
int tippe_drawing_render(const tippe_design *d, const tippe_drawing_options *o, void *cairo,
                         double x, double y, double w, double h, tippe_error *err);

#endif
