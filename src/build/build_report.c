/* The build sheet's text: the terminal report, Markdown and JSON. */
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

/* ------------------------------------------------------------ reports */

const char *tippe_build_verdict(const tippe_build_sheet *s)
{
    return !s->three_in_one ? "not 3-in-1"
           : s->settable    ? "3-in-1 and settable"
                            : "3-in-1 on paper only";
}

int tippe_build_poles_invalid(const tippe_build_sheet *s)
{
    for (int f = 0; f < 3; f++)
        if (s->set[f].reachable && s->set[f].launch_status == TIPPE_OK &&
            (s->set[f].launch_cap_start || s->set[f].launch_cap_end))
            return 1;
    return 0;
}

/* The verdict's sentence, and where the poles undo it a second one: the
 * zones assume the sphere at the pole a top stands on, and a hole's rim there
 * is not it. */
static void verdict_sentence(const tippe_build_sheet *s, char *buf, size_t size);
void tippe_build_verdict_text(const tippe_build_sheet *s, char *buf, size_t size)
{
    verdict_sentence(s, buf, size);
    size_t n = strlen(buf);
    if (tippe_build_poles_invalid(s) && n < size)
        snprintf(buf + n, size - n,
                 " But a hole opens at a pole the top stands or spins on: there it stands on the "
                 "hole's rim, not on its sphere; the launch checks follow the rim, the zones "
                 "(the paper's theory) assume the sphere; see the poles' fixes.");
}

static void verdict_sentence(const tippe_build_sheet *s, char *buf, size_t size)
{
    if (!s->three_in_one) {
        snprintf(buf, size, "It is not 3-in-1: not every behaviour is reachable within the travel "
                            "where the model applies.");
        return;
    }
    if (s->settable) {
        snprintf(buf, size, "It is 3-in-1 and settable: every behaviour's robust range is at "
                            "least %.2f mm wide (%s).",
                 s->min_setting_mm, s->min_setting_rule);
        return;
    }
    char which[64] = "";
    for (int f = 0, n = 0; f < 3; f++)
        if (!s->set[f].settable)
            snprintf(which + strlen(which), sizeof which - strlen(which), "%s%s",
                     n++ ? ", " : "", behaviours[f]);
    snprintf(buf, size, "It is 3-in-1 on paper only: all three behaviours are reachable within "
                        "the travel where the model applies, but the robust range of %s is "
                        "narrower than %.2f mm (%s), too narrow to set by hand.",
             which, s->min_setting_mm, s->min_setting_rule);
}

/* A flips or hangs row's part a hand's spin reaches: "; a hand (up to 25
 * rev/s) reaches it at depth 1.03 .. 9.10 mm" (at Z2 without a reference). */
static void hand_text(const tippe_build_sheet *s, int f, char *buf, size_t size)
{
    const tippe_build_setting *x = &s->set[f];
    buf[0] = '\0';
    if (f == 0 || !x->reachable)
        return;
    if (!isfinite(x->hand_from_mm)) {
        snprintf(buf, size, "; a hand (up to %g rev/s) reaches it nowhere in the range",
                 s->hand_spin_rev_s);
        return;
    }
    if (isfinite(x->depth_hand_from_mm))
        snprintf(buf, size, "; a hand (up to %g rev/s) reaches it at depth %.2f .. %.2f mm",
                 s->hand_spin_rev_s, fmin(x->depth_hand_from_mm, x->depth_hand_to_mm),
                 fmax(x->depth_hand_from_mm, x->depth_hand_to_mm));
    else
        snprintf(buf, size, "; a hand (up to %g rev/s) reaches it at Z2 %.2f .. %.2f mm",
                 s->hand_spin_rev_s, x->hand_from_mm, x->hand_to_mm);
}

void tippe_build_spin_text(const tippe_build_sheet *s, int f, char *buf, size_t size)
{
    const tippe_build_setting *x = &s->set[f];
    char hand[160];
    hand_text(s, f, hand, sizeof hand);
    if (f == 0)
        snprintf(buf, size, "any");
    else if (isfinite(x->spin_needed_max_rev_s))
        snprintf(buf, size, "above %.1f rev/s (%.1f at the range's worst end)%s",
                 x->spin_needed_rev_s, x->spin_needed_max_rev_s, hand);
    else
        snprintf(buf, size, "no spin suffices%s", hand);
}

static cJSON *num(double x) { return isfinite(x) ? cJSON_CreateNumber(x) : cJSON_CreateNull(); }

static const char *measure_name(tippe_build_measure m)
{
    return m == TIPPE_BUILD_MEASURE_HOLE ? "hole" : m == TIPPE_BUILD_MEASURE_ROD ? "rod" : "none";
}

/* A change's JSON entry in arr, with its --set lines as "set": the advice's
 * and the poles' fixes alike; NULL if out of memory. */
static cJSON *entry_with_sets(cJSON *arr, const char (*set)[200], int n)
{
    cJSON *j = cJSON_CreateObject();
    if (!j || !cJSON_AddItemToArray(arr, j)) {
        cJSON_Delete(j);
        return NULL;
    }
    cJSON *sets = cJSON_AddArrayToObject(j, "set");
    for (int i = 0; sets && i < n; i++)
        cJSON_AddItemToArray(sets, cJSON_CreateString(set[i]));
    return j;
}

cJSON *tippe_build_json(const tippe_build_sheet *s)
{
    cJSON *o = cJSON_CreateObject();
    if (!o)
        return NULL;
    cJSON_AddStringToObject(o, "design", s->design_name);
    cJSON_AddStringToObject(o, "file", s->design_file);
    cJSON *ov = cJSON_AddArrayToObject(o, "set");
    for (int i = 0; ov && i < s->n_overrides; i++)
        cJSON_AddItemToArray(ov, cJSON_CreateString(s->override[i]));
    cJSON_AddNumberToObject(o, "radius_mm", s->radius_mm);
    cJSON *dt = cJSON_AddArrayToObject(o, "travel_mm");
    cJSON_AddItemToArray(dt, num(s->design_travel_from_mm));
    cJSON_AddItemToArray(dt, num(s->design_travel_to_mm));
    cJSON *t = cJSON_AddArrayToObject(o, "physical_travel_mm");
    cJSON_AddItemToArray(t, num(s->travel_from_mm));
    cJSON_AddItemToArray(t, num(s->travel_to_mm));
    cJSON_AddBoolToObject(o, "three_in_one", s->three_in_one);
    cJSON_AddBoolToObject(o, "settable", s->settable);
    cJSON_AddStringToObject(o, "verdict", tippe_build_verdict(s));
    cJSON_AddBoolToObject(o, "model_holds_at_poles", !tippe_build_poles_invalid(s));
    cJSON_AddNumberToObject(o, "min_setting_mm", s->min_setting_mm);
    cJSON_AddStringToObject(o, "min_setting_rule", s->min_setting_rule);
    cJSON_AddNumberToObject(o, "hand_spin_max_rev_s", s->hand_spin_rev_s);
    /* the law every setting's launch check ran under (tippe build --friction ...) */
    cJSON *lc = cJSON_AddObjectToObject(o, "launch_check");
    if (lc) {
        tippe_dynamics_friction_json(lc, &s->launch_model);
        cJSON_AddStringToObject(lc, "friction_text", s->launch_friction);
    }
    cJSON *m = cJSON_AddObjectToObject(o, "measure");
    if (m) {
        cJSON_AddStringToObject(m, "kind", measure_name(s->measure));
        cJSON_AddStringToObject(m, "reference", s->reference);
        cJSON_AddItemToObject(m, "reference_z_mm",
                              num(s->measure ? s->reference_z_mm : NAN));
        cJSON_AddStringToObject(m, "weight", s->weight_name);
        if (s->measure == TIPPE_BUILD_MEASURE_HOLE) {
            cJSON_AddNumberToObject(m, "hole_printed_diameter_mm", s->hole_diameter_mm);
            cJSON_AddStringToObject(m, "hole_fit", s->hole_tapped   ? "tap"
                                                   : s->hole_insert ? "insert"
                                                                    : "slide");
            cJSON_AddStringToObject(m, "hole_fit_from",
                                    s->hole_fit_from_design ? "design" : "default or option");
            /* the zones are the part as made: the hole printed so, then tapped */
            if (s->as_made_set[0])
                cJSON_AddStringToObject(m, "as_made_set", s->as_made_set);
            if (s->hole_insert) {
                cJSON *in = cJSON_AddObjectToObject(m, "insert");
                if (in) {
                    cJSON_AddStringToObject(in, "thread", s->insert.thread);
                    cJSON_AddNumberToObject(in, "pilot_hole_mm", s->insert.pilot_mm);
                    cJSON_AddNumberToObject(in, "outer_diameter_max_mm", s->insert.outer_max_mm);
                    cJSON_AddStringToObject(in, "source", TIPPE_BUILD_INSERT_SOURCE);
                }
            }
            cJSON_AddItemToObject(m, "weigh_offset_g", num(s->weigh_offset_g));
        }
        cJSON_AddNumberToObject(m, "weight_end_above_z2_mm", s->weight_end_offset_mm);
    }
    cJSON *th = cJSON_AddObjectToObject(o, "thread");
    if (th && s->has_thread) {
        cJSON_AddStringToObject(th, "name", s->thread_name);
        cJSON_AddNumberToObject(th, "d_mm", s->thread.d_mm);
        cJSON_AddNumberToObject(th, "pitch_mm", s->thread.pitch_mm);
        cJSON_AddNumberToObject(th, "tap_drill_mm", s->tap_drill_mm);
        cJSON_AddStringToObject(th, "tap_drill_rule", "d - P (ISO 2306 for ISO 261 threads)");
        if (s->catalogue_item[0]) {
            cJSON_AddStringToObject(th, "catalogue_item", s->catalogue_item);
            cJSON_AddStringToObject(th, "catalogue", s->catalogue_title);
        } else {
            cJSON_AddNullToObject(th, "catalogue_item");
        }
        cJSON_AddBoolToObject(th, "assumed", s->thread_assumed);
    }
    cJSON *arr = cJSON_AddArrayToObject(o, "settings");
    for (int f = 0; arr && f < 3; f++) {
        const tippe_build_setting *x = &s->set[f];
        cJSON *j = cJSON_CreateObject();
        if (!j || !cJSON_AddItemToArray(arr, j)) {
            cJSON_Delete(j);
            break;
        }
        cJSON_AddStringToObject(j, "behaviour", behaviours[f]);
        cJSON_AddStringToObject(j, "group", families[f]);
        cJSON_AddBoolToObject(j, "reachable", x->reachable);
        if (!x->reachable)
            continue;
        cJSON_AddBoolToObject(j, "robust", x->robust);
        cJSON_AddNumberToObject(j, "z2_from_mm", x->from_mm);
        cJSON_AddNumberToObject(j, "z2_to_mm", x->to_mm);
        cJSON_AddNumberToObject(j, "band_from_mm", x->band_from_mm);
        cJSON_AddNumberToObject(j, "band_to_mm", x->band_to_mm);
        cJSON_AddNumberToObject(j, "robust_from_mm", x->robust_from_mm);
        cJSON_AddNumberToObject(j, "robust_to_mm", x->robust_to_mm);
        cJSON_AddNumberToObject(j, "robust_width_mm", x->robust_width_mm);
        cJSON_AddBoolToObject(j, "settable", x->settable);
        cJSON_AddNumberToObject(j, "set_z2_mm", x->set_z2_mm);
        cJSON_AddItemToObject(j, "depth_from_mm", num(x->depth_from_mm));
        cJSON_AddItemToObject(j, "depth_set_mm", num(x->depth_set_mm));
        cJSON_AddItemToObject(j, "depth_to_mm", num(x->depth_to_mm));
        cJSON_AddItemToObject(j, "turns_from", num(x->turns_from));
        cJSON_AddItemToObject(j, "turns_set", num(x->turns_set));
        cJSON_AddItemToObject(j, "turns_to", num(x->turns_to));
        cJSON_AddItemToObject(j, "spin_needed_rev_s", num(x->spin_needed_rev_s));
        cJSON_AddItemToObject(j, "spin_needed_max_rev_s", num(x->spin_needed_max_rev_s));
        cJSON_AddStringToObject(j, "spin_rule", x->spin_rule ? x->spin_rule : "");
        if (f > 0) {
            cJSON_AddItemToObject(j, "hand_z2_from_mm", num(x->hand_from_mm));
            cJSON_AddItemToObject(j, "hand_z2_to_mm", num(x->hand_to_mm));
            cJSON_AddItemToObject(j, "hand_depth_from_mm", num(x->depth_hand_from_mm));
            cJSON_AddItemToObject(j, "hand_depth_to_mm", num(x->depth_hand_to_mm));
        }
        cJSON_AddItemToObject(j, "launch_spin_rev_s", num(x->spin_launch_rev_s));
        cJSON_AddBoolToObject(j, "beyond_hand_spin", x->beyond_hand);
        if (x->launch_status == TIPPE_OK) {
            cJSON_AddStringToObject(j, "launch_verdict", tippe_verdict_name(x->verdict));
            cJSON_AddBoolToObject(j, "launch_as_expected", x->verdict_ok);
            cJSON_AddNumberToObject(j, "launch_decided_s", x->launch_t_s);
            cJSON_AddNumberToObject(j, "launch_theta0_rad", x->launch_theta0_rad);
            cJSON_AddItemToObject(j, "launch_theta_end_rad", num(x->launch_theta_end_rad));
            cJSON_AddStringToObject(j, "rest_pole", x->rest_pole > 0 ? "+z" : "-z");
            cJSON_AddNumberToObject(j, "launch_cap_time_s", x->launch_cap_time_s);
            cJSON *oc = cJSON_AddObjectToObject(j, "launch_on_polar_cap");
            if (oc) {
                if (x->launch_cap_start)
                    cJSON_AddStringToObject(oc, "start", x->launch_cap_start > 0 ? "+z" : "-z");
                else
                    cJSON_AddNullToObject(oc, "start");
                if (x->launch_cap_end)
                    cJSON_AddStringToObject(oc, "end", x->launch_cap_end > 0 ? "+z" : "-z");
                else
                    cJSON_AddNullToObject(oc, "end");
            }
        } else {
            cJSON_AddNullToObject(j, "launch_verdict");
            cJSON_AddBoolToObject(j, "launch_as_expected", 0);
        }
    }
    cJSON *b = cJSON_AddArrayToObject(o, "bill_of_materials");
    for (int k = 0; b && k < s->n_bom; k++) {
        cJSON *j = cJSON_CreateObject();
        if (!j || !cJSON_AddItemToArray(b, j)) {
            cJSON_Delete(j);
            break;
        }
        cJSON_AddNumberToObject(j, "quantity", s->bom[k].quantity);
        cJSON_AddStringToObject(j, "item", s->bom[k].what);
        cJSON_AddStringToObject(j, "detail", s->bom[k].detail);
    }
    cJSON *pa = cJSON_AddArrayToObject(o, "print");
    for (int k = 0; pa && k < s->n_print; k++) {
        cJSON *j = cJSON_CreateObject();
        if (!j || !cJSON_AddItemToArray(pa, j)) {
            cJSON_Delete(j);
            break;
        }
        const tippe_print_settings *p = &s->print[k].settings;
        cJSON_AddStringToObject(j, "part", s->print[k].part);
        cJSON_AddStringToObject(j, "material", s->print[k].material);
        cJSON_AddBoolToObject(j, "print_block", s->print[k].has_block);
        /* a body with no print block is modelled solid: no walls to count */
        if (s->print[k].has_block) {
            cJSON_AddNumberToObject(j, "perimeters", p->perimeters);
            cJSON_AddNumberToObject(j, "top_bottom_layers", p->top_bottom_layers);
        } else {
            cJSON_AddNullToObject(j, "perimeters");
            cJSON_AddNullToObject(j, "top_bottom_layers");
        }
        cJSON_AddNumberToObject(j, "line_width_mm", p->line_width_mm);
        cJSON_AddNumberToObject(j, "layer_height_mm", p->layer_height_mm);
        cJSON_AddNumberToObject(j, "infill", s->print[k].infill);
        cJSON_AddBoolToObject(j, "calibrated", s->print[k].calibrated);
        if (s->print[k].has_block) { /* the zones' part: eval's printed_mass_kg */
            cJSON_AddNumberToObject(j, "printed_mass_kg", s->print[k].printed_mass_kg);
            cJSON_AddNumberToObject(j, "cut_mass_kg", s->print[k].cut_mass_kg);
        } else {
            cJSON_AddNullToObject(j, "printed_mass_kg");
            cJSON_AddNullToObject(j, "cut_mass_kg");
        }
        cJSON_AddStringToObject(j, "orientation",
                                s->needs_split ? "axis vertical, halves on their cut faces"
                                               : "axis vertical");
        if (s->print[k].has_block) {
            /* what the model assumed of the slicer: pinned in the 3MF, or the profile's */
            cJSON *sa = cJSON_AddObjectToObject(j, "slicer_settings_in_3mf");
            tippe_print_pin pins[32];
            int n_pins = tippe_print_pinned_settings(&s->print[k].settings, pins, 32);
            for (int a = 0; sa && a < n_pins; a++)
                cJSON_AddStringToObject(sa, pins[a].key, pins[a].value);
            cJSON *pr = cJSON_AddObjectToObject(j, "slicer_settings_of_profile");
            if (pr) {
                cJSON_AddNumberToObject(pr, "first_layer_height", p->first_layer_height_mm);
                cJSON_AddNumberToObject(pr, "first_layer_extrusion_width",
                                        p->first_layer_width_mm);
            }
        }
    }
    cJSON_AddBoolToObject(o, "split", s->needs_split);
    cJSON_AddBoolToObject(o, "joint_ring", s->joint_ring);
    cJSON *adv = cJSON_AddArrayToObject(o, "to_make_it_settable");
    cJSON_AddNumberToObject(o, "changes_tried", s->n_advice_tried);
    for (int k = 0; adv && k < s->n_advice; k++) {
        cJSON *j = entry_with_sets(adv, s->advice[k].set, s->advice[k].n_set);
        if (!j)
            break;
        cJSON_AddBoolToObject(j, "pair", s->advice[k].pair);
        cJSON_AddBoolToObject(j, "settable", s->advice[k].settable);
        cJSON_AddNumberToObject(j, "narrowest_robust_mm", s->advice[k].narrowest_mm);
        cJSON_AddNumberToObject(j, "min_setting_mm", s->advice[k].min_setting_mm);
        cJSON_AddStringToObject(j, "advice", s->advice[k].text);
    }
    tippe_design_caps_json(o, s->caps);
    cJSON *pf = cJSON_AddArrayToObject(o, "pole_fixes");
    for (int k = 0; pf && k < s->n_pole_fixes; k++) {
        cJSON *j = entry_with_sets(pf, s->pole_fix[k].set, s->pole_fix[k].n_set);
        if (!j)
            break;
        cJSON_AddStringToObject(j, "verdict", s->pole_fix[k].verdict >= 0
                                                  ? tippe_build_verdict_name(s->pole_fix[k].verdict)
                                                  : "failed");
        if (isfinite(s->pole_fix[k].narrowest_mm))
            cJSON_AddNumberToObject(j, "narrowest_robust_mm", s->pole_fix[k].narrowest_mm);
        else
            cJSON_AddNullToObject(j, "narrowest_robust_mm");
        cJSON_AddStringToObject(j, "fix", s->pole_fix[k].text);
    }
    cJSON *stp = cJSON_AddArrayToObject(o, "steps");
    for (int k = 0; stp && k < s->n_steps; k++)
        cJSON_AddItemToArray(stp, cJSON_CreateString(s->step[k]));
    cJSON *wa = cJSON_AddArrayToObject(o, "warnings");
    for (int k = 0; wa && k < s->n_warnings; k++)
        cJSON_AddItemToArray(wa, cJSON_CreateString(s->warning[k]));
    cJSON *n = cJSON_AddArrayToObject(o, "notes");
    for (int k = 0; n && k < s->n_notes; k++)
        cJSON_AddItemToArray(n, cJSON_CreateString(s->note[k]));
    return o;
}

/* "12.34 mm" or "-" */
const char *tippe_build_mm(double v, char *buf, size_t size)
{
    if (isfinite(v))
        snprintf(buf, size, "%.2f mm", v);
    else
        snprintf(buf, size, "-");
    return buf;
}

const char *tippe_build_turns(double v, char *buf, size_t size)
{
    if (isfinite(v))
        snprintf(buf, size, "%.1f", v);
    else
        snprintf(buf, size, "-");
    return buf;
}

/* Text from the design (names, and the sentences that quote them) in Markdown:
 * '|' would end a table cell, '<' and '&' start raw HTML or an entity (a name
 * "<!--" would hide the rest of the page), '[' ']' a link, '`' a code span;
 * each is backslash-escaped (CommonMark), so the page reads as the text. */
static const char *md(const char *text, char *buf, size_t size)
{
    size_t n = 0;
    for (const char *t = text; *t && n + 2 < size; t++) {
        if (strchr("\\|<>&[]`", *t))
            buf[n++] = '\\';
        buf[n++] = *t;
    }
    buf[n] = '\0';
    return buf;
}

void tippe_build_markdown(FILE *f, const tippe_build_sheet *s)
{
    char m1[2048], m2[2048];
    char a[32], b[32], c[32], d[32], e[32], g[32];
    char head[4400];
    tippe_build_header_text(s, head, sizeof head);
    fprintf(f, "# Build sheet: %s\n\nDesign file %s.\n\n", md(s->design_name, m1, sizeof m1),
            md(head, m2, sizeof m2));
    fprintf(f, "## Settings\n\n");
    if (s->measure != TIPPE_BUILD_MEASURE_NONE)
        fprintf(f, "Measure from %s.\n\n", md(s->reference, m1, sizeof m1));
    fprintf(f, "| behaviour | group | robust Z2 range | set Z2 | depth (range) | depth to set | "
               "turns to set | spin needed | launch check |\n"
               "|---|---|---|---|---|---|---|---|---|\n");
    for (int k = 0; k < 3; k++) {
        const tippe_build_setting *x = &s->set[k];
        if (!x->reachable) {
            fprintf(f, "| %s | %s | not reachable within the travel where the model applies "
                       "| | | | | | |\n",
                    behaviours[k], families[k]);
            continue;
        }
        char range[80], spin[320], check[200];
        if (x->robust)
            snprintf(range, sizeof range, "%.2f .. %.2f mm", x->robust_from_mm, x->robust_to_mm);
        else
            snprintf(range, sizeof range, "none robust (zone %.2f .. %.2f mm)", x->from_mm,
                     x->to_mm);
        tippe_build_spin_text(s, k, spin, sizeof spin);
        tippe_build_launch_text(s, k, check, sizeof check);
        double lo = fmin(x->depth_from_mm, x->depth_to_mm);
        double hi = fmax(x->depth_from_mm, x->depth_to_mm);
        fprintf(f, "| %s | %s | %s | %.2f mm | %s .. %s | %s | %s | %s | %s |\n", behaviours[k],
                families[k], range, x->set_z2_mm, tippe_build_mm(lo, a, sizeof a),
                tippe_build_mm(hi, b, sizeof b), tippe_build_mm(x->depth_set_mm, c, sizeof c),
                tippe_build_turns(x->turns_set, d, sizeof d), spin, check);
    }
    (void)e;
    (void)g;
    fprintf(f, "\nLaunch check: tippe check's central hand launch at the set Z2, friction %s.\n",
            md(s->launch_friction, m1, sizeof m1));
    char verdict[512];
    tippe_build_verdict_text(s, verdict, sizeof verdict);
    fprintf(f, "\n%s\n", verdict);
    for (int k = 0; k < s->n_warnings; k++)
        fprintf(f, "%s- **Warning**: %s\n", k ? "" : "\n", md(s->warning[k], m1, sizeof m1));
    if (!s->settable) {
        fprintf(f, "\n%s:\n\n", tippe_build_advice_heading(s));
        for (int k = 0; k < s->n_advice; k++) {
            char sets[1400];
            tippe_build_advice_sets(s, k, sets, sizeof sets);
            fprintf(f, "- %s (`%s`).\n", md(s->advice[k].text, m1, sizeof m1), sets);
        }
        if (!s->n_advice)
            fprintf(f, "- %s\n", tippe_build_advice_none());
    }
    if (s->n_caps) {
        fprintf(f, "\nThe poles: ");
        for (int k = 0; k < 2; k++) {
            if (!(s->caps[k].half_angle_rad > 0))
                continue;
            char made[160] = "";
            if (s->cap_made_mm[k] > 0)
                snprintf(made, sizeof made, "; %s, %.2f mm across, within %.1f deg",
                         s->hole_tapped ? "tapped" : "with its insert", s->cap_made_mm[k],
                         s->cap_made_half_angle_rad[k] * 180 / M_PI);
            fprintf(f, "The hole '%s' opens at the %s pole (%.2f mm across as modelled%s): tilted "
                       "less than %.1f deg on it the top stands on the hole's rim, not on its "
                       "sphere. ",
                    md(s->caps[k].part, m1, sizeof m1), k ? "-z" : "+z", 2 * s->caps[k].radius_mm,
                    made, s->caps[k].half_angle_rad * 180 / M_PI);
        }
        fprintf(f, "%s\n", s->n_pole_fixes ? "Fixes, each tried by sweeping the changed design:"
                                           : "");
        if (s->n_pole_fixes)
            fprintf(f, "\n");
        for (int k = 0; k < s->n_pole_fixes; k++) {
            fprintf(f, "- %s (`", md(s->pole_fix[k].text, m1, sizeof m1));
            for (int i = 0; i < s->pole_fix[k].n_set; i++)
                fprintf(f, "%s--set %s", i ? " " : "", s->pole_fix[k].set[i]);
            fprintf(f, "`)\n");
        }
    }
    if (s->has_thread) {
        fprintf(f, "\nThread: %s x %g mm", md(s->thread_name, m1, sizeof m1), s->thread.pitch_mm);
        if (s->catalogue_item[0])
            fprintf(f, " (catalogue item %s, %s)", md(s->catalogue_item, m1, sizeof m1),
                    md(s->catalogue_title, m2, sizeof m2));
        else if (s->thread_assumed)
            fprintf(f, " (assumed: no catalogue item matches the weight; the ISO 261 size whose "
                       "pitch diameter is nearest its modelled diameter)");
        fprintf(f, "; tap drill %.2f mm (d - P, ISO 2306).\n", s->tap_drill_mm);
    }
    fprintf(f, "\n## Bill of materials\n\n| qty | item | detail |\n|---|---|---|\n");
    for (int k = 0; k < s->n_bom; k++)
        fprintf(f, "| %d | %s | %s |\n", s->bom[k].quantity, md(s->bom[k].what, m1, sizeof m1),
                md(s->bom[k].detail, m2, sizeof m2));
    fprintf(f, "\n## Print settings\n\n| part | material | perimeters | top/bottom layers | "
               "infill | orientation |\n|---|---|---|---|---|---|\n");
    for (int k = 0; k < s->n_print; k++) {
        const tippe_print_settings *p = &s->print[k].settings;
        if (s->print[k].has_block)
            fprintf(f, "| %s | %s | %d x %.2f mm | %d x %.2f mm | %.0f %%%s | axis vertical%s |\n",
                    md(s->print[k].part, m1, sizeof m1), md(s->print[k].material, m2, sizeof m2), p->perimeters, p->line_width_mm,
                    p->top_bottom_layers, p->layer_height_mm, 100 * s->print[k].infill,
                    s->print[k].calibrated ? " (calibrated by weighing)" : "",
                    s->needs_split ? ", halves on their cut faces" : "");
        else
            fprintf(f, "| %s | %s | as many as fill it | - | 100 %% (solid: the design has no "
                       "print block) | axis vertical%s |\n",
                    md(s->print[k].part, m1, sizeof m1), md(s->print[k].material, m2, sizeof m2),
                    s->needs_split ? ", halves on their cut faces" : "");
    }
    for (int k = 0; k < s->n_print; k++) {
        if (!s->print[k].has_block)
            continue;
        /* the slicer settings the model assumed (issue 40): the 3MF pins those PrusaSlicer
         * takes per object; the first layer's are the profile's alone in 2.5 */
        const tippe_print_settings *p = &s->print[k].settings;
        fprintf(f, "\nThe mass model of '%s' assumes these slicer settings. The 3MF sets them "
                   "for the part:",
                md(s->print[k].part, m1, sizeof m1));
        tippe_print_pin pins[32];
        int n_pins = tippe_print_pinned_settings(p, pins, 32);
        for (int q = 0; q < n_pins; q++)
            fprintf(f, "%s `%s = %s`", q ? "," : "", pins[q].key, pins[q].value);
        fprintf(f, ". Set these in your print profile (PrusaSlicer takes them from it alone): "
                   "`first_layer_height = %g`, `first_layer_extrusion_width = %g`.\n",
                p->first_layer_height_mm, p->first_layer_width_mm);
        break; /* one list: every printed part assumes the same */
    }
    fprintf(f, "\n## Steps\n\n");
    for (int k = 0; k < s->n_steps; k++)
        fprintf(f, "%d. %s\n", k + 1, md(s->step[k], m1, sizeof m1));
    if (s->n_notes) {
        fprintf(f, "\n## Notes\n\n");
        for (int k = 0; k < s->n_notes; k++)
            fprintf(f, "- %s\n", md(s->note[k], m1, sizeof m1));
    }
}

void tippe_build_advice_sets(const tippe_build_sheet *s, int k, char *buf, size_t size)
{
    size_t n = 0;
    buf[0] = 0;
    for (int i = 0; k >= 0 && k < s->n_advice && i < s->advice[k].n_set && n < size; i++) {
        int w = snprintf(buf + n, size - n, "%s--set %s", i ? " " : "", s->advice[k].set[i]);
        if (w < 0)
            break;
        n += (size_t)w;
    }
}

const char *tippe_build_advice_heading(const tippe_build_sheet *s)
{
    int pair = s->n_advice > 0 && s->advice[0].pair, poles = tippe_build_poles_invalid(s);
    if (pair)
        return poles ? "What would make it settable (no single change is enough: pairs of "
                       "changes a maker can buy or set, each tried by sweeping the changed "
                       "design with its tolerance bands; none of them closes the open poles, "
                       "below)"
                     : "What would make it settable (no single change is enough: pairs of "
                       "changes a maker can buy or set, each tried by sweeping the changed "
                       "design with its tolerance bands)";
    return poles ? "What would make it settable (changes a maker can buy or set, one at a time, "
                   "each tried by sweeping the changed design with its tolerance bands; the "
                   "nearest of each kind, and the widest; none of them closes the open poles, "
                   "below)"
                 : "What would make it settable (changes a maker can buy or set, one at a time, "
                   "each tried by sweeping the changed design with its tolerance bands; the "
                   "nearest of each kind, and the widest)";
}

const char *tippe_build_advice_none(void)
{
    return "No change tried makes it settable: the slicer's infill steps (of a part not "
           "given by its G-code), the table's bought materials, the catalogue's screws or "
           "whole-mm lengths (half to double), alone or in pairs.";
}

/* The sheet's launch-check cell of setting k (the Markdown table's, the page's), so that
 * both say the same words. */
void tippe_build_launch_text(const tippe_build_sheet *s, int k, char *buf, size_t size)
{
    const tippe_build_setting *x = &s->set[k];
    if (x->launch_status == TIPPE_OK)
        snprintf(buf, size, "%s at %.1f rev/s%s%s%s", tippe_verdict_name(x->verdict),
                 x->spin_launch_rev_s, x->verdict_ok ? " (as expected)" : " (NOT as expected)",
                 x->beyond_hand ? "; beyond a hand spin" : "", tippe_build_cap_text(x));
    else
        snprintf(buf, size, "not run");
}

const char *tippe_build_cap_text(const tippe_build_setting *x)
{
    if (x->launch_status != TIPPE_OK || (!x->launch_cap_start && !x->launch_cap_end))
        return "";
    /* the launch follows the rim (issue 35): said, not flagged invalid */
    if (x->launch_cap_start && x->launch_cap_end)
        return x->launch_cap_start > 0
                   ? (x->launch_cap_end > 0 ? "; on the hole's rim at +z from start to end "
                                              "(modelled)"
                                            : "; starts on the hole's rim at +z, ends on it "
                                              "at -z (modelled)")
                   : (x->launch_cap_end < 0 ? "; on the hole's rim at -z from start to end "
                                              "(modelled)"
                                            : "; starts on the hole's rim at -z, ends on it "
                                              "at +z (modelled)");
    if (x->launch_cap_start)
        return x->launch_cap_start > 0 ? "; starts on the hole's rim at +z (modelled)"
                                       : "; starts on the hole's rim at -z (modelled)";
    return x->launch_cap_end > 0 ? "; ends on the hole's rim at +z (modelled)"
                                 : "; ends on the hole's rim at -z (modelled)";
}

void tippe_build_header_text(const tippe_build_sheet *s, char *buf, size_t size)
{
    size_t n = 0;
    /* an absolute path names the maker's disk, not the sheet's folder (issue 37): its
     * file's name alone; a relative one is kept, as the command was given it */
    int w = snprintf(buf, size, "%s",
                     s->design_file[0] == '/' ? tippe_path_base(s->design_file) : s->design_file);
    for (int i = 0; w >= 0 && (n += (size_t)w) < size && i < s->n_overrides; i++)
        w = snprintf(buf + n, size - n, "%s--set %s", i ? " " : " changed by ", s->override[i]);
    if (n >= size)
        return;
    const int same = fabs(s->design_travel_from_mm - s->travel_from_mm) < 5e-3 &&
                     fabs(s->design_travel_to_mm - s->travel_to_mm) < 5e-3;
    if (same)
        snprintf(buf + n, size - n, "; sphere radius %g mm; the weight's travel Z2 = %.2f .. %.2f mm",
                 s->radius_mm, s->design_travel_from_mm, s->design_travel_to_mm);
    else
        snprintf(buf + n, size - n,
                 "; sphere radius %g mm; the weight's travel Z2 = %.2f .. %.2f mm (the design's "
                 "travel_mm; its parts would allow %.2f .. %.2f)",
                 s->radius_mm, s->design_travel_from_mm, s->design_travel_to_mm,
                 s->travel_from_mm, s->travel_to_mm);
}
