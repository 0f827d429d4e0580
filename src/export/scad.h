/* src/export/scad.h: the design as OpenSCAD source, for a maker to edit and re-render.
 *
 * The file opens with the design's numbers as named variables (mm), then one
 * module per part built from OpenSCAD's own solids (sphere, cylinder, and
 * rotate_extrude of the elliptical profile for a torus band), the printed body
 * as the printed parts less their voids (holes that take hardware grown by the
 * clearance), the fixed hardware, and the moving weight at z2_mm in its own
 * colour. Setting show = "printed" renders the printed bodies alone, which is
 * what tippe's STL files hold. Written atomically (tippe/base.h). */
#ifndef TIPPE_EXPORT_SCAD_H
#define TIPPE_EXPORT_SCAD_H

#include "tippe/design.h"
#include "tippe/base.h"
#include "tippe/profile.h"

/* fn: facets around a circle ($fn); clearance_applied as in tippe_profile_set. */
int tippe_scad_write(const tippe_design *d, const tippe_profile_set *s,
                     const tippe_profile_options *opt, double z2_mm, int fn, const char *path,
                     tippe_error *err);

#endif
