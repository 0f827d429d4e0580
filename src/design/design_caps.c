/* Where the surface the top stands on is not its sphere: the polar caps cut
 * away by a hole that opens at a pole (issue 25.7). The paper's model rolls a
 * sphere on the table; a hole of radius r through the pole of a sphere of
 * radius R removes the cap within asin(r / R) of the pole, and a top tilted
 * less than that on that pole stands on the hole's rim (a circle), not on its
 * sphere (the M12: r 5.5 mm, R 25 mm, 12.7 degrees, which holds both the hand
 * launch's 3.9 degrees and the upright "stays up" state). */
#include "design/internal.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* Slack for a hole that reaches the rim (mm): its end may sit exactly on it. */
#define RIM_SLACK_MM 1e-6

int tippe_design_polar_caps(const tippe_design *d, double z2_mm, tippe_design_cap caps[2])
{
    const double R = d->radius_mm;
    memset(caps, 0, 2 * sizeof *caps);
    for (int k = 0; k < 2; k++)
        caps[k].pole = k ? -1 : +1;
    for (int i = 0; i < d->n_parts; i++) {
        const part *p = &d->parts[i];
        if (!p->is_void || (p->shape != SHAPE_CYLINDER && p->shape != SHAPE_TUBE) ||
            p->inner_radius_mm > 0 || !(p->radius_mm < R))
            continue;
        /* a moving void travels with Z2 */
        double zc = p->z_mm + (p->moving ? z2_mm : 0.0);
        double top = zc + 0.5 * p->height_mm, bottom = zc - 0.5 * p->height_mm;
        double rim = sqrt((R - p->radius_mm) * (R + p->radius_mm)); /* where it meets the sphere */
        double alpha = asin(p->radius_mm / R);
        for (int k = 0; k < 2; k++) {
            int opens = k ? bottom <= -rim + RIM_SLACK_MM : top >= rim - RIM_SLACK_MM;
            if (opens && alpha > caps[k].half_angle_rad) {
                caps[k].half_angle_rad = alpha;
                caps[k].radius_mm = p->radius_mm;
                snprintf(caps[k].part, sizeof caps[k].part, "%s", p->name);
            }
        }
    }
    return (caps[0].half_angle_rad > 0) + (caps[1].half_angle_rad > 0);
}

int tippe_design_cap_at_tilt(const tippe_design_cap caps[2], int rest_side, double theta_rad)
{
    /* at tilt theta the contact is theta from the pole it rests on, pi - theta
     * from the other; rest_side is the design's z side down at theta = 0 */
    for (int k = 0; k < 2; k++) {
        if (!(caps[k].half_angle_rad > 0))
            continue;
        double from_pole = caps[k].pole == rest_side ? theta_rad : M_PI - theta_rad;
        if (from_pole < caps[k].half_angle_rad)
            return caps[k].pole;
    }
    return 0;
}
