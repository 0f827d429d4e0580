/* What a maker buys and follows: the bill of materials, the print settings,
 * the file names and the steps of the build sheet. */
#include "build/internal.h"
#include "base/json.h"
#include "tippe/physics.h"
#include "tippe/profile.h"
#include "tippe/sweep.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ----------------------------------------------------------------- BOM */

void tippe_build_stem(const char *design_path, char *out, size_t size)
{
    tippe_path_stem(design_path, out, size);
}

/* The sheet names the files it refers to as they are written. */
void tippe_build_file_stem(const tippe_build_sheet *s, char *out, size_t size)
{
    tippe_build_stem(s->design_file, out, size);
}

void tippe_build_bom(tippe_build_sheet *s, int qty, const char *what, const char *fmt, ...)
{
    if (s->n_bom >= TIPPE_BUILD_MAX_BOM)
        return;
    tippe_build_bom_line *l = &s->bom[s->n_bom++];
    l->quantity = qty;
    snprintf(l->what, sizeof l->what, "%s", what);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(l->detail, sizeof l->detail, fmt, ap);
    va_end(ap);
}

void tippe_build_note(tippe_build_sheet *s, const char *text)
{
    if (s->n_notes < (int)(sizeof s->note / sizeof s->note[0]))
        snprintf(s->note[s->n_notes++], sizeof s->note[0], "%s", text);
}

void tippe_build_bill(const tippe_design *d, const tippe_profile_set *ps, const tippe_build_options *o,
                 tippe_build_sheet *s, double rod_r)
{
    char what[512];
    for (int b = 0; ps && b < ps->n_bodies; b++) {
        snprintf(what, sizeof what, "printed body '%s', %s", ps->body[b].name,
                 ps->body[b].material);
        tippe_build_bom(s, 1, what, "%.2f mm tall, %.2f mm across; printed with the axis vertical",
            ps->body[b].z_max_mm - ps->body[b].z_min_mm, 2 * ps->body[b].r_max_mm);
    }
    for (int i = 0; i < tippe_design_n_parts(d); i++) {
        tippe_design_solid sd;
        tippe_design_part_info p;
        tippe_design_print_info pr;
        if (tippe_design_part_solid(d, i, &sd) || tippe_design_part(d, i, &p) ||
            tippe_design_part_print(d, i, &pr) || sd.is_void || p.printable || pr.printed)
            continue;
        int cyl = !strcmp(sd.shape, "cylinder") || !strcmp(sd.shape, "tube");
        if (sd.moving && s->catalogue_item[0]) {
            snprintf(what, sizeof what, "set screw %s (%s), %s", s->catalogue_item,
                     s->catalogue_title, p.material);
            tippe_build_bom(s, 1, what, "thread %s x %.4g mm, length %.4g mm; the weight ('%s')",
                s->thread_name, s->thread.pitch_mm, sd.height_mm, p.name);
        } else if (sd.moving && s->measure == TIPPE_BUILD_MEASURE_HOLE && cyl) {
            snprintf(what, sizeof what, "screw or slug '%s', %s", p.name, p.material);
            tippe_build_bom(s, 1, what,
                "diameter %.4g mm (modelled), length %.4g mm; no catalogue item matches: "
                "nearest ISO 261 thread %s x %.4g mm",
                2 * sd.radius_mm, sd.height_mm, s->thread_name, s->thread.pitch_mm);
        } else if (sd.moving && cyl && sd.inner_radius_mm > 0) {
            snprintf(what, sizeof what, "bead (weight) '%s', %s", p.name, p.material);
            if (s->has_thread)
                tippe_build_bom(s, 1, what,
                    "outer diameter %.4g mm, height %.4g mm, bore tapped %s x %.4g mm "
                    "(tap drill %.2f mm)",
                    2 * sd.radius_mm, sd.height_mm, s->thread_name, s->thread.pitch_mm,
                    s->tap_drill_mm);
            else
                tippe_build_bom(s, 1, what, "outer diameter %.4g mm, height %.4g mm, bore %.4g mm",
                    2 * sd.radius_mm, sd.height_mm, 2 * sd.inner_radius_mm);
        } else if (!sd.moving && cyl && sd.inner_radius_mm == 0) {
            double len = sd.height_mm;
            const char *ends = "cut square";
            int ns = 0;
            double lo = 0, hi = 0;
            for (int k = 0; ps && k < ps->n_sockets; k++)
                if (ps->socket_part[k] == i) {
                    ns++;
                    lo = fmin(lo, ps->socket_floor_z_mm[k]);
                    hi = fmax(hi, ps->socket_floor_z_mm[k]);
                }
            if (ns == 2) {
                /* held on the axis by the shell's sockets (tippe/profile.h):
                 * longer than the model's rod, whose ends the cavity clips */
                len = hi - lo;
                char t[320];
                double extra_g = (M_PI * sd.radius_mm * sd.radius_mm * len * 1e-3 *
                                      p.density_g_cm3 - p.mass_kg * 1e3);
                snprintf(t, sizeof t,
                         "The rod is cut %.2f mm long, its ends %.1f mm deep in the shell's "
                         "sockets at the poles (they hold it on the axis): %+.3f g against the "
                         "model's rod, whose ends the cavity clips; the sockets remove %.1f mm^3 "
                         "of printed wall. Neither is in the mass model.",
                         len, TIPPE_PROFILE_SOCKET_DEPTH_MM, extra_g,
                         ps->socket_volume_mm3[0] + ps->socket_volume_mm3[1]);
                tippe_build_note(s, t);
                ends = "cut square; its ends sit in the shell's sockets at the poles";
                s->rod_sockets = 1;
            } else if (sd.clip_radius_mm > 0) {
                double cap = sqrt(sd.clip_radius_mm * sd.clip_radius_mm -
                                  sd.radius_mm * sd.radius_mm);
                if (sd.z_mm + sd.height_mm / 2 > cap && sd.z_mm - sd.height_mm / 2 < -cap) {
                    len = 2 * cap;
                    ends = "cut square at this length, its end edges touching the clip ball "
                           "(the model's rounded ends hold a little more metal)";
                }
            }
            const tippe_build_thread *t = tippe_build_thread_by_diameter(2 * sd.radius_mm);
            snprintf(what, sizeof what, "%s '%s', %s", t ? "threaded rod" : "rod", p.name,
                     p.material);
            if (t)
                tippe_build_bom(s, 1, what, "%s x %.4g mm (ISO 261 coarse), length %.2f mm, %s", t->name,
                    t->pitch_mm, len, ends);
            else
                tippe_build_bom(s, 1, what, "diameter %.4g mm, length %.2f mm, %s", 2 * sd.radius_mm, len,
                    ends);
            (void)rod_r;
        } else {
            snprintf(what, sizeof what, "part '%s', %s %s", p.name, p.material, sd.shape);
            tippe_build_bom(s, 1, what, "%s", sd.moving ? "moving (the weight)" : "fixed hardware");
        }
    }
    if (s->hole_insert)
        tippe_build_bom(s, 1, "heat-set threaded insert, brass, non-flanged",
            "%s (for the %s x %g screw), %.1f mm long, outer diameter at most %.1f mm; "
            "pressed into the hole's rim, printed %.1f mm across (its vendor's pilot hole: %s)",
            s->insert.thread, s->thread_name, s->thread.pitch_mm, s->insert.length_mm,
            s->insert.outer_max_mm, s->insert.pilot_mm, TIPPE_BUILD_INSERT_SOURCE);
    int split = 0;
    for (int k = 0; ps && k < ps->n_warnings; k++)
        split |= strstr(ps->warning[k], "--split") != NULL;
    s->needs_split = split;
    if (split) {
        /* tippe export makes the ring only where a wall at the cut is wide
         * enough for its groove (a thin shell gets none): ask it */
        tippe_profile_options po = tippe_profile_defaults();
        po.clearance_mm = o->clearance_mm;
        po.split = po.joint = 1;
        tippe_profile_set js;
        tippe_error e = {0};
        if (tippe_profile_build(d, &po, &js, &e) == TIPPE_OK) {
            s->joint_ring = js.n_grooves > 0;
            tippe_profile_set_free(&js);
        }
    }
    char stem[sizeof ((tippe_build_sheet *)0)->design_file];
    tippe_build_file_stem(s, stem, sizeof stem);
    if (s->joint_ring)
        tippe_build_bom(s, 1, "joint ring, printed (the body's filament)",
            "%s-joint-ring.stl: fills the 2 mm grooves of both halves' cut faces to align them "
            "(tippe export --split --joint)", stem);
    if (split)
        tippe_build_bom(s, 1, "adhesive for the two printed halves",
            "the body closes around its hardware, so it is printed in halves (--split): join "
            "them (solvent weld for ABS, cyanoacrylate for PLA or PETG)");
}

int tippe_build_needs_split(const tippe_design *d, double clearance_mm)
{
    tippe_profile_options po = tippe_profile_defaults();
    po.clearance_mm = clearance_mm;
    tippe_profile_set ps;
    tippe_error e = {0};
    if (tippe_profile_build(d, &po, &ps, &e))
        return 0;
    int split = 0;
    for (int k = 0; k < ps.n_warnings; k++)
        split |= strstr(ps.warning[k], "--split") != NULL;
    tippe_profile_set_free(&ps);
    return split;
}

void tippe_build_print_settings(const tippe_design *d, const tippe_profile_set *ps,
                           tippe_build_sheet *s)
{
    for (int i = 0; ps && i < tippe_design_n_parts(d) && s->n_print < 4; i++) {
        tippe_design_part_info p;
        tippe_design_print_info pr;
        tippe_design_solid sd;
        if (tippe_design_part(d, i, &p) || tippe_design_part_print(d, i, &pr) ||
            tippe_design_part_solid(d, i, &sd) || sd.is_void || sd.moving ||
            !(p.printable || pr.printed))
            continue;
        int k = s->n_print++;
        snprintf(s->print[k].part, sizeof s->print[k].part, "%s", p.name);
        snprintf(s->print[k].material, sizeof s->print[k].material, "%s", p.material);
        s->print[k].has_block = pr.printed;
        s->print[k].settings = pr.printed ? pr.settings : tippe_print_defaults();
        s->print[k].infill = pr.printed ? pr.infill : 1.0;
        s->print[k].calibrated = pr.calibrated;
        s->print[k].printed_mass_kg = pr.printed ? pr.printed_mass_kg : 0;
        s->print[k].cut_mass_kg = pr.printed ? pr.cut_mass_kg : 0;
    }
}

void tippe_build_step(tippe_build_sheet *s, const char *fmt, ...)
{
    if (s->n_steps >= 10)
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(s->step[s->n_steps++], sizeof s->step[0], fmt, ap);
    va_end(ap);
}

/* The order a maker works in, from what the sheet found. */
void tippe_build_steps(tippe_build_sheet *s)
{
    const tippe_build_setting *first = NULL;
    for (int f = 0; f < 3 && !first; f++)
        if (s->set[f].reachable)
            first = &s->set[f];
    char stem[sizeof ((tippe_build_sheet *)0)->design_file];
    tippe_build_file_stem(s, stem, sizeof stem);
    if (s->needs_split)
        tippe_build_step(s, "Print the body in two halves (%s-*-lower.stl and %s-*-upper.stl, each standing "
                "on its flat cut face at the equator) with the print settings. A hollow half "
                "needs support inside its dome (PrusaSlicer: about 8 cm^3 for a 50 mm shell, "
                "docs/printing.md; the 3MF turns it on, from the build plate only); keep it out "
                "of the joint's groove with a support blocker.",
             stem, stem);
    else
        tippe_build_step(s, "Print the body with the print settings, its axis vertical (the mass model "
                "assumes it). A ball printed whole stands on a few mm^2 and needs support "
                "under its lower hemisphere (PrusaSlicer: about 3 cm^3 for a 50 mm ball; the 3MF "
                "turns them on for it, from the build plate only), none inside the hole; printed "
                "in halves (tippe export --split) a solid ball needs none.");
    if (s->weigh_step[0])
        tippe_build_step(s, "%s", s->weigh_step);
    if (s->measure == TIPPE_BUILD_MEASURE_HOLE) {
        double bite = 0.5 * (s->thread.d_mm - s->hole_diameter_mm);
        if (s->hole_insert)
            tippe_build_step(s, "Press the %s heat-set insert into the hole at the rim with a soldering iron "
                    "(its insert tip), straight along the axis, until its top is flush with the "
                    "rim; let it cool. The hole is printed %.1f mm across for it.",
                 s->insert.thread, s->hole_diameter_mm);
        else if (s->hole_diameter_mm > s->tap_drill_mm + 1e-9)
            tippe_build_step(s, "Check the hole: printed diameter %.2f mm for the %s x %g screw, wider than "
                    "its tap drill %.2f mm (a sliding fit: the design's hole, the screw's pitch "
                    "diameter, plus the clearance): the thread bites %.2f mm deep into the wall. "
                    "If the screw turns loose, fix it with a drop of glue.",
                 s->hole_diameter_mm, s->thread_name, s->thread.pitch_mm, s->tap_drill_mm,
                 bite > 0 ? bite : 0);
        else
            tippe_build_step(s, "Tap the hole %s x %g: it is printed at the tap drill, %.2f mm across (d - "
                    "P; drill it to %.2f mm first if the print came out narrower).",
                 s->thread_name, s->thread.pitch_mm, s->hole_diameter_mm, s->tap_drill_mm);
        tippe_build_step(s, "Turn the screw in with a hex key until its end is flush with the rim, then "
                "the turns of the table for the behaviour wanted. Check the depth with the "
                "printed gauge of that setting (%s-gauge-*.stl: pin in the hole, disc on the rim, "
                "the screw's end just touching the pin) or a caliper's depth rod on the rim.",
             stem);
    } else if (s->measure == TIPPE_BUILD_MEASURE_ROD) {
        tippe_build_step(s, "Cut the rod to the length in the bill of materials, square.");
        tippe_build_step(s, "Screw the bead onto the rod until its top face lies at the table's depth "
                "below the rod's top end%s: the printed sleeve gauge (%s-gauge-*.stl) standing on "
                "the bead is then flush with the rod's end. Fix it with a drop of threadlocker.",
             first ? " for the behaviour wanted" : "", stem);
        const char *rod_in_sockets = s->rod_sockets
                                         ? " with its lower end in the lower half's socket (the "
                                           "upper end goes into the upper half's)"
                                         : "";
        if (s->joint_ring)
            tippe_build_step(s, "Put the joint ring in the groove of the lower half's cut face, stand the rod "
                    "on the axis%s, close with the upper half (its groove over the ring) and join "
                    "them (adhesive in the bill of materials); the bead can no longer be moved: "
                    "build one top per behaviour, or choose the one you want first.",
                 rod_in_sockets);
        else
            tippe_build_step(s, "Stand the rod on the axis of the lower half%s, close with the upper half "
                    "and join them (adhesive in the bill of materials; the wall at the cut is too "
                    "thin for a joint ring: align the halves by hand); the bead can no longer "
                    "be moved: build one top per behaviour, or choose the one you want first.",
                 rod_in_sockets);
    } else {
        tippe_build_step(s, "Place the weight at the set Z2 of the table (its midpoint above the sphere's "
                "centre).");
    }
    tippe_build_step(s, "Spin the top on a hard, flat table at the spin of the table (a flick of the "
            "fingers gives 5 to 25 rev/s) and watch it stay up, flip or hang.");
}

int tippe_build_gauge_applies(const tippe_build_sheet *s, int f, double *pin_mm)
{
    *pin_mm = NAN;
    if (f < 0 || f > 2 || !s->set[f].reachable || s->measure == TIPPE_BUILD_MEASURE_NONE ||
        !(s->set[f].depth_set_mm >= TIPPE_BUILD_GAUGE_MIN_MM))
        return 0;
    *pin_mm = s->set[f].depth_set_mm;
    return 1;
}

double tippe_build_gauge_pin_diameter_mm(const tippe_build_sheet *s)
{
    double d = s->hole_diameter_mm - 1;
    /* an insert's bore is its thread: the pin passes its minor diameter (ISO 724) */
    if (s->hole_insert && s->has_thread)
        d = fmin(d, tippe_build_minor_diameter_mm(&s->thread) - 0.5);
    return d;
}
