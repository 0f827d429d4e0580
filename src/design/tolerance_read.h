/* design/tolerance_read.h: the tolerances block, read by the design loader.
 * Apart from design_internal.h so that tolerance.c sees the design only through
 * its public accessors (the loader calls tolerance, tolerance calls the
 * accessors, the accessors call neither). */
#ifndef TIPPE_DESIGN_TOLERANCE_READ_H
#define TIPPE_DESIGN_TOLERANCE_READ_H

#include "base/json.h"
#include "tippe/design.h"

/* Called by the design loader once the parts are resolved: checks block (NULL
 * if the file has none) and builds the list with the defaults. Messages name
 * the file and tolerances["FIELD"]. *out is malloc'ed (free). The patch radius's
 * factor (contact.patch_radius) goes to *patch_radius_span, 0 when not given. */
int tippe_tolerances_read(const tippe_json_reader *c, const cJSON *block, const tippe_design *d,
                          tippe_tolerance **out, int *n_out, double *patch_radius_span);

#endif
