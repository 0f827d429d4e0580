/* tippe/tolerance.h: how far a built top may be from its design file.
 *
 * A design's "tolerances" block (docs/design-format.md) gives, per field, a
 * +/- value: absolute in the field's unit, or "N%" of it. Fields are named as
 * --set names them ("radius_mm", "parts.screw.height_mm", "parts[2].z_mm") or,
 * for a material's density shared by every part made of it (one spool of
 * filament, one error), "materials.NAME.density_g_cm3". Fields the block leaves
 * out get the documented defaults (printed dimension +/-0.2 mm, filament
 * density +/-3 %, hardware mass +/-2 % through its density, a printed part's
 * infill +/-25 % of it, or its weighed mass +/-0.1 g); 0 removes one.
 * The design reads and checks the block when it loads; a loaded design lists
 * the result (tippe_design_n_tolerances, tippe_design_tolerance). */
#ifndef TIPPE_TOLERANCE_H
#define TIPPE_TOLERANCE_H

#include "tippe/design.h"
#include "tippe/json.h"

#define TIPPE_TOLERANCE_FIELD_LEN 160
#define TIPPE_TOLERANCE_MAX 200

/* Documented defaults. */
#define TIPPE_TOL_PRINTED_MM 0.2
#define TIPPE_TOL_FILAMENT_DENSITY_PERCENT 3.0
#define TIPPE_TOL_HARDWARE_MASS_PERCENT 2.0
/* A printed part's infill as the slicer states it (its real density is not
 * known: slicer mass estimates are off by 3 to 26 % against the scale), and
 * the reading of a 0.1 g kitchen scale when the part was weighed. */
#define TIPPE_TOL_INFILL_PERCENT 25.0
#define TIPPE_TOL_WEIGHED_G 0.1

typedef struct {
    char field[TIPPE_TOLERANCE_FIELD_LEN]; /* canonical: parts by name */
    double value;      /* nominal, in the field's unit */
    double plus_minus; /* absolute, in the field's unit (> 0) */
    double percent;    /* as given when relative, else 0 */
    const char *unit;  /* "mm", "g/cm^3", "g" or "" (infill, a fraction) */
    const char *rule;  /* "tolerances block", or the default's: "printed dimension",
                          "filament density", "hardware mass", "slicer infill",
                          "scale reading" */
} tippe_tolerance;

int tippe_design_n_tolerances(const tippe_design *d);
/* Tolerance i (0-based), NULL out of range. */
const tippe_tolerance *tippe_design_tolerance(const tippe_design *d, int i);

/* The overrides that move t's field from its nominal value by delta (one per
 * part made of the material, for a material's density), written into
 * buf[0..cap-1]; returns how many, or -1 if cap is too small. For
 * tippe_design_derive. */
int tippe_tolerance_overrides(const tippe_design *d, const tippe_tolerance *t, double delta,
                              char (*buf)[TIPPE_TOLERANCE_FIELD_LEN + 40], int cap);

/* Called by the design loader once the parts are resolved: checks block (NULL
 * if the file has none) and builds the list with the defaults. Messages name
 * the file and tolerances["FIELD"]. *out is malloc'ed (free). */
int tippe_tolerances_read(const tippe_json_reader *c, const cJSON *block, const tippe_design *d,
                          tippe_tolerance **out, int *n_out);

#endif
