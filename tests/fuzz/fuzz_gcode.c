/* libFuzzer target: a slicer's G-code (print.gcode), the largest parser of a
 * user's file: read as a file with the beads near the axis kept
 * (tippe_gcode_read_beads, as the design's cache reads it), a hole cut from the
 * body about its axis (tippe_gcode_cut_body), the part matched
 * (tippe_gcode_match) and the body rescaled to another density. The diameter
 * and density are given, as Cura's G-code needs; the file's own win where it
 * has them. Seeds: tests/data/gcode/ (PrusaSlicer 2.5's G-code of the M12's
 * first layers and its config block; a Cura-flavour file written by hand). */
#include "fuzz.h"

#include "tippe/print.h"

#include <math.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *path = fuzz_write("part.gcode", data, size);
    tippe_gcode_options o = tippe_gcode_defaults();
    o.filament_diameter_mm = 1.75;
    o.density_g_cm3 = 1.24;
    tippe_gcode_body body;
    tippe_gcode_beads beads;
    tippe_error err;
    if (tippe_gcode_read_beads(path, &o, 8, &body, &beads, &err) != TIPPE_OK)
        return 0;
    tippe_gcode_cut cut = {1e3 * (body.bbox_min[0] + body.bbox_max[0]) / 2,
                           1e3 * (body.bbox_min[1] + body.bbox_max[1]) / 2, 5,
                           1e3 * body.bbox_min[2], 1e3 * body.bbox_max[2]};
    tippe_gcode_cut_body(&body, &beads, &cut, 1);
    tippe_gcode_beads_free(&beads);
    tippe_gcode_part part;
    tippe_gcode_match(&body, NULL, &part, &err);
    tippe_gcode_body_set_density(&body, 1.05);
    return 0;
}
