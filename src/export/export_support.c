/* export_support.c: which printed bodies want supports, so that tippe's 3MF
 * turns them on for those objects alone (issue 37: the build sheet's steps say
 * which; docs/printing.md, "Supports"). */
#include "export/mesh.h"

#include <math.h>

/* A body wants supports when, standing as printed (a split half flipped), a
 * surface of it faces down more steeply than TIPPE_EXPORT_SUPPORT_ANGLE_DEG
 * from the vertical anywhere above the bed: the lower hemisphere of a ball
 * printed whole, the dome inside a hollow half. The 45 degree rule is the
 * usual overhang limit; PrusaSlicer 2.5's automatic supports (support_material_auto,
 * threshold 0: SupportMaterial.cpp's overhang test against half the extrusion
 * width per layer) agreed on every shipped shape (docs/slicer-measurements.md:
 * a whole ball about 3 cm^3, a shell's halves about 8 cm^3 each, a solid
 * ball's halves none). The profile's rings are the body's (r, z) section,
 * exterior counter-clockwise and holes clockwise (tippe/profile.h), so the
 * outward normal of an edge from p to q is (dz, -dr) over its length. */
#define TIPPE_EXPORT_SUPPORT_ANGLE_DEG 45.0
int tippe_export_body_needs_support(const tippe_profile_body *b)
{
    const double sin_lim = sin(TIPPE_EXPORT_SUPPORT_ANGLE_DEG * M_PI / 180);
    const double s = b->flip ? -1.0 : 1.0; /* z as printed */
    double bed = INFINITY;
    for (int k = 0; k < b->n_rings; k++)
        for (int i = 0; i < b->ring[k].n; i++)
            bed = fmin(bed, s * b->ring[k].pt[i].z_mm);
    for (int k = 0; k < b->n_rings; k++) {
        const tippe_profile_ring *g = &b->ring[k];
        for (int i = 0; i < g->n; i++) {
            const tippe_profile_point *p = &g->pt[i], *q = &g->pt[(i + 1) % g->n];
            double dr = q->r_mm - p->r_mm, dz = s * (q->z_mm - p->z_mm), L = hypot(dr, dz);
            if (!(L > 0) || (p->r_mm == 0 && q->r_mm == 0))
                continue; /* the axis is no surface */
            /* outward normal as printed: (dz, -dr) / L, its z part -dr / L (flipped: z -> -z
             * reverses the ring's sense, so the normal's z is -s dr / L with s dz above) */
            double nz = -(b->flip ? -dr : dr) / L;
            double zp = s * p->z_mm, zq = s * q->z_mm;
            /* facing down more than the limit from the vertical: nz < -sin(limit) */
            if (nz < -sin_lim && fmax(zp, zq) > bed + 0.3)
                return 1;
        }
    }
    return 0;
}
