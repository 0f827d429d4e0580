/* What a film needs before any drawing (see tippe/animate.h): the default
 * options and the weight's marker. Apart from animate.c, which draws with
 * cairo, so that the command prepares a film without loading cairo. */
#include "tippe/animate.h"

#include <math.h>
#include <string.h>

void tippe_animate_options_default(tippe_animate_options *o)
{
    o->speed = 0;
    o->film_s = 10;
    o->fps = 30;
    o->width_px = 640;
    o->height_px = 480;
}

/* ---- the weight of a design ---------------------------------------------------- */

void tippe_animate_design_weight(const tippe_design *d, double z2_mm, const tippe_top *top,
                                 double *offset_m, double *radius_m)
{
    double volume_m3 = 0, moment = 0;
    for (int i = 0; i < tippe_design_n_parts(d); i++) {
        tippe_design_part_info pi;
        if (tippe_design_part(d, i, &pi) || strcmp(pi.role, "moving") ||
            !(pi.density_g_cm3 > 0) || !(pi.mass_kg > 0))
            continue;
        const double v = pi.mass_kg / (pi.density_g_cm3 * 1000.0);
        volume_m3 += v;
        moment += v * (z2_mm + pi.z_mm) * 1e-3;
    }
    *offset_m = *radius_m = 0;
    if (!(volume_m3 > 0))
        return;
    /* The red pole is on the centre of mass's side of the design's z axis. */
    const double side = top->com_side < 0 ? -1.0 : 1.0;
    *offset_m = side * moment / volume_m3;
    *radius_m = cbrt(3 * volume_m3 / (4 * M_PI));
}

/* ---- the launch of tippe check, as a film -------------------------------------- */

int tippe_animate_check_launch(const tippe_sweep_check *c, const tippe_launch_options *o,
                               tippe_animate_launch *out)
{
    memset(out, 0, sizeof *out);
    snprintf(out->title, sizeof out->title, "%s at Z2 = %g mm, central hand launch",
             tippe_design_name(c->d), c->z2_mm);
    tippe_launch_friction_model(o, &out->model);
    out->model.top = c->top;
    out->initial = c->ic;
    out->t_end = o->t_end;
    out->accuracy = o->accuracy;
    tippe_animate_design_weight(c->d, c->z2_mm, &c->top, &out->weight_offset_m,
                                &out->weight_radius_m);
    return TIPPE_OK;
}
