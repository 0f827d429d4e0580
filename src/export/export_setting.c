/* The setting the section drawings show, with its depth below the rim: below
 * both the build's files (export_build.c, core) and the sheet's page
 * (build_sheet.c, the export module), which draw it. */
#include "tippe/build.h"
#include "tippe/export.h"

#include <math.h>
#include <stdio.h>

/* The flips setting, since a flip is what a tippe top is built to show; else
 * the first setting there is. */
int tippe_export_shown_setting(const tippe_build_sheet *s, double *z2_mm, int *has_depth,
                               double *rim_z_mm, double *end_z_mm, double *x_mm, char *label,
                               size_t label_size)
{
    int shown = -1;
    for (int f = 2; f >= 0; f--)
        if (s->set[f].reachable)
            shown = f;
    if (s->set[1].reachable)
        shown = 1;
    *has_depth = 0;
    if (shown < 0)
        return -1;
    const tippe_build_setting *st = &s->set[shown];
    *z2_mm = st->set_z2_mm;
    *has_depth = s->measure != TIPPE_BUILD_MEASURE_NONE && isfinite(st->depth_set_mm);
    *rim_z_mm = s->reference_z_mm;
    *end_z_mm = st->set_z2_mm + s->weight_end_offset_mm;
    *x_mm = s->measure == TIPPE_BUILD_MEASURE_HOLE ? 0.5 * s->hole_diameter_mm : 0;
    if (isfinite(st->turns_set))
        snprintf(label, label_size, "%s: %.1f turns", tippe_build_behaviour(shown), st->turns_set);
    else
        snprintf(label, label_size, "the %s setting", tippe_build_behaviour(shown));
    return shown;
}

const char *tippe_export_depth_from(const tippe_build_sheet *s)
{
    return s->measure == TIPPE_BUILD_MEASURE_ROD ? "the rod's end" : "the rim";
}
