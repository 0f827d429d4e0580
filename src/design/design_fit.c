/* The part as made: the weight's hole of a printed part is printed at its
 * thread's tap drill and tapped after (docs/printing.md, "The part as made"),
 * so the design that every command models is that part, unless the file says
 * where the hole is printed (printed_radius_mm) or that it is not tapped
 * ("fit": "insert" or "slide"). Also the ISO 261 threads the tap drill comes
 * from (tippe/build.h reads the same table). */
#include "design/internal.h"

#include <math.h>

/* ISO 261, coarse series (first choice sizes M1.6 .. M24). */
static const tippe_design_thread iso261[] = {
    {"M1.6", 1.6, 0.35}, {"M2", 2, 0.4},     {"M2.5", 2.5, 0.45}, {"M3", 3, 0.5},
    {"M4", 4, 0.7},      {"M5", 5, 0.8},     {"M6", 6, 1.0},      {"M8", 8, 1.25},
    {"M10", 10, 1.5},    {"M12", 12, 1.75},  {"M14", 14, 2.0},    {"M16", 16, 2.0},
    {"M20", 20, 2.5},    {"M24", 24, 3.0},
};
enum { N_ISO = sizeof iso261 / sizeof iso261[0] };

/* ISO 724: the pitch diameter of the basic profile, d2 = d - (3 sqrt(3) / 8) P. */
static double pitch_diameter_mm(const tippe_design_thread *t)
{
    return t->d_mm - 0.649519052838329 * t->pitch_mm;
}

/* A thread named by its nominal diameter (a rod's, a catalogue item's). */
const tippe_design_thread *tippe_design_thread_by_diameter(double d_mm)
{
    for (int k = 0; k < N_ISO; k++)
        if (fabs(iso261[k].d_mm - d_mm) < 1e-6)
            return &iso261[k];
    return NULL;
}

/* A screw modelled as a cylinder of its pitch diameter (the catalogue's
 * convention): the thread nearest it. */
const tippe_design_thread *tippe_design_thread_by_pitch_diameter(double d2_mm)
{
    int best = 0;
    for (int k = 1; k < N_ISO; k++)
        if (fabs(pitch_diameter_mm(&iso261[k]) - d2_mm) <
            fabs(pitch_diameter_mm(&iso261[best]) - d2_mm))
            best = k;
    return &iso261[best];
}

/* ISO 2306's tap drill for metric threads, d - P (about 77 % engagement). */
double tippe_design_tap_drill_mm(const tippe_design_thread *t) { return t->d_mm - t->pitch_mm; }

/* A hole counts as the weight's when it is at most this much narrower than the
 * weight (mm): a checked design's screw fits its hole, and the tolerance bands
 * move a printed hole's radius by TIPPE_TOL_PRINTED_MM, which must not change
 * which hole is tapped (the band's part would lose its cut). */
#define WEIGHT_HOLE_SLACK_MM (2 * TIPPE_TOL_PRINTED_MM)
/* A hole's end may sit exactly on the sphere it opens through (mm). */
#define RIM_SLACK_MM 1e-6

/* The moving group's outer radius (mm; 0 when nothing moves), as tippe build
 * measures the weight (build.c's weight_extent). */
static double weight_radius_mm(const tippe_design *d)
{
    double r = 0;
    for (int i = 0; i < d->n_parts; i++) {
        const part *p = &d->parts[i];
        if (!p->moving || p->is_void)
            continue;
        r = fmax(r, p->shape == SHAPE_TORUS ? p->centre_radius_mm + p->radial_semi_mm
                                            : p->radius_mm);
    }
    return r;
}

/* The build sheet's rule (build.c, find_hole and compute_hole_fit): the
 * weight's screw enters the first axial hole of a printed part that is as
 * wide as the weight and open at a pole; without a fit, or with "tap", the
 * sheet prints it at the tap drill of the ISO 261 thread whose pitch diameter
 * is nearest the weight's modelled diameter, and the maker taps it to the
 * design's radius. That hole gets the tap drill's radius as its
 * printed_radius_mm, marked as derived. */
void tippe_design_derive_printed_radii(tippe_design *d)
{
    const double r_weight = weight_radius_mm(d), R = d->radius_mm;
    if (!(r_weight > 0))
        return;
    for (int i = 0; i < d->n_parts; i++) {
        part *h = &d->parts[i];
        h->printed_radius_from_fit = 0;
        if (!h->is_void || h->moving || h->shape != SHAPE_CYLINDER || h->inner_radius_mm > 0 ||
            h->parent < 0 || !d->parts[h->parent].printed ||
            !(h->radius_mm >= r_weight - WEIGHT_HOLE_SLACK_MM) || !(h->radius_mm < R))
            continue;
        double rim = sqrt(R * R - h->radius_mm * h->radius_mm);
        double top = h->z_mm + h->height_mm / 2, bottom = h->z_mm - h->height_mm / 2;
        if (!(top >= rim - RIM_SLACK_MM) && !(bottom <= -rim + RIM_SLACK_MM))
            continue;
        /* the weight's hole: the file's printed radius or fit decide, else tapped */
        if (h->printed_radius_mm > 0 ||
            (h->fit != TIPPE_DESIGN_FIT_NONE && h->fit != TIPPE_DESIGN_FIT_TAP))
            return;
        const tippe_design_thread *t = tippe_design_thread_by_pitch_diameter(2 * r_weight);
        double r_tap = tippe_design_tap_drill_mm(t) / 2;
        if (r_tap < h->radius_mm - 1e-9) {
            h->printed_radius_mm = r_tap;
            h->printed_radius_from_fit = 1;
        }
        return;
    }
}
