/* The build sheet as one page (cairo): the section drawing, the settings
 * table, the bill of materials, print settings and the steps. */
#include "tippe/build.h"

#include "export/drawing.h"
#include "export/mesh.h"
#include "tippe/profile.h"
#include "tippe/base.h"
#include "tippe/design.h"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

/* A3 landscape in points (PDF, SVG); the PNG is drawn at PNG_SCALE px per point. */
#define SHEET_W 1191.0
#define SHEET_H 842.0
#define PNG_SCALE 1.6
#define M 24.0 /* margin */

static void font(cairo_t *cr, double size, int bold)
{
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size);
}

/* Text wrapped to width from (x, y) (the first baseline); returns the
 * baseline after the last line. */
static double wrapped(cairo_t *cr, const char *text, double x, double y, double width,
                      double size, int bold)
{
    font(cr, size, bold);
    char line[1024] = "", trial[1024];
    const char *p = text;
    double lh = 1.25 * size;
    while (*p) {
        size_t n = strcspn(p, " ");
        snprintf(trial, sizeof trial, "%s%s%.*s", line, line[0] ? " " : "", (int)n, p);
        cairo_text_extents_t e;
        cairo_text_extents(cr, trial, &e);
        if (e.x_advance > width && line[0]) {
            cairo_move_to(cr, x, y);
            cairo_show_text(cr, line);
            y += lh;
            snprintf(line, sizeof line, "%.*s", (int)n, p);
        } else {
            snprintf(line, sizeof line, "%s", trial);
        }
        p += n;
        while (*p == ' ')
            p++;
    }
    if (line[0]) {
        cairo_move_to(cr, x, y);
        cairo_show_text(cr, line);
        y += lh;
    }
    return y;
}

/* Height a wrapped text takes (without drawing it). */
static double wrapped_height(cairo_t *cr, const char *text, double width, double size, int bold)
{
    cairo_save(cr);
    cairo_push_group(cr);
    double h = wrapped(cr, text, 0, 0, width, size, bold);
    cairo_pattern_destroy(cairo_pop_group(cr));
    cairo_restore(cr);
    return h;
}

static void heading(cairo_t *cr, const char *text, double x, double y)
{
    font(cr, 13, 1);
    cairo_set_source_rgb(cr, 0.1, 0.2, 0.45);
    cairo_move_to(cr, x, y);
    cairo_show_text(cr, text);
    cairo_set_source_rgb(cr, 0, 0, 0);
}

/* One table row: cells wrapped in their columns; returns the next row's top. */
static double row(cairo_t *cr, const char *const *cells, const double *widths, int n, double x,
                  double y, double size, int bold, int shade)
{
    double h = 0;
    for (int k = 0; k < n; k++)
        h = fmax(h, wrapped_height(cr, cells[k], widths[k] - 6, size, bold));
    h += 4;
    if (shade) {
        double w = 0;
        for (int k = 0; k < n; k++)
            w += widths[k];
        cairo_set_source_rgb(cr, 0.92, 0.94, 0.97);
        cairo_rectangle(cr, x, y, w, h);
        cairo_fill(cr);
        cairo_set_source_rgb(cr, 0, 0, 0);
    }
    double cx = x;
    for (int k = 0; k < n; k++) {
        wrapped(cr, cells[k], cx + 3, y + size + 1, widths[k] - 6, size, bold);
        cx += widths[k];
    }
    cairo_set_source_rgb(cr, 0.7, 0.7, 0.7);
    cairo_set_line_width(cr, 0.5);
    cairo_move_to(cr, x, y + h);
    cairo_line_to(cr, cx, y + h);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    return y + h;
}

static const char *fmt_mm(double v, char *b, size_t n)
{
    if (isfinite(v))
        snprintf(b, n, "%.2f", v);
    else
        snprintf(b, n, "-");
    return b;
}

static double settings_table(cairo_t *cr, const tippe_build_sheet *s, double x, double y,
                             double w)
{
    static const double frac[] = {0.08, 0.14, 0.07, 0.13, 0.09, 0.07, 0.2, 0.22};
    double widths[8];
    for (int k = 0; k < 8; k++)
        widths[k] = frac[k] * w;
    char depth_head[80];
    snprintf(depth_head, sizeof depth_head, "depth range, mm (%s)",
             s->measure == TIPPE_BUILD_MEASURE_HOLE  ? "below the hole's rim"
             : s->measure == TIPPE_BUILD_MEASURE_ROD ? "below the rod's end"
                                                     : "no reference");
    char launch_head[120];
    snprintf(launch_head, sizeof launch_head, "hand launch at the set Z2 (tippe check), %s friction",
             tippe_friction_law_name(s->launch_model.law));
    const char *head[8] = {"behaviour",    "robust Z2 range, mm", "set Z2, mm", depth_head,
                           "depth to set, mm", "turns from flush", "spin needed (Theorem 5.1)",
                           launch_head};
    y = row(cr, head, widths, 8, x, y, 9.5, 1, 1);
    for (int f = 0; f < 3; f++) {
        const tippe_build_setting *t = &s->set[f];
        char c[8][320], a1[32], a2[32];
        snprintf(c[0], sizeof c[0], "%s (%s)", tippe_build_behaviour(f), tippe_build_family(f));
        if (!t->reachable) {
            snprintf(c[1], sizeof c[1], "not within the travel");
            for (int k = 2; k < 8; k++)
                c[k][0] = '\0';
        } else {
            if (t->robust)
                snprintf(c[1], sizeof c[1], "%.2f .. %.2f%s", t->robust_from_mm, t->robust_to_mm,
                         t->settable ? "" : " (too narrow to set)");
            else
                snprintf(c[1], sizeof c[1], "none robust (zone %.2f .. %.2f)", t->from_mm,
                         t->to_mm);
            snprintf(c[2], sizeof c[2], "%.2f", t->set_z2_mm);
            snprintf(c[3], sizeof c[3], "%s .. %s",
                     fmt_mm(fmin(t->depth_from_mm, t->depth_to_mm), a1, sizeof a1),
                     fmt_mm(fmax(t->depth_from_mm, t->depth_to_mm), a2, sizeof a2));
            snprintf(c[4], sizeof c[4], "%s", fmt_mm(t->depth_set_mm, a1, sizeof a1));
            if (isfinite(t->turns_set))
                snprintf(c[5], sizeof c[5], "%.1f", t->turns_set);
            else
                snprintf(c[5], sizeof c[5], "-");
            if (f == 0)
                snprintf(c[6], sizeof c[6], "any spin");
            else
                tippe_build_spin_text(s, f, c[6], sizeof c[6]);
            if (t->launch_status == TIPPE_OK)
                snprintf(c[7], sizeof c[7], "%s at %.1f rev/s: %s%s%s", tippe_verdict_name(t->verdict),
                         t->spin_launch_rev_s, t->verdict_ok ? "as expected" : "NOT as expected",
                         t->beyond_hand ? " (beyond a hand spin)" : "", tippe_build_cap_text(t));
            else
                snprintf(c[7], sizeof c[7], "not run");
        }
        const char *cells[8];
        for (int k = 0; k < 8; k++)
            cells[k] = c[k];
        y = row(cr, cells, widths, 8, x, y, 9.5, 0, 0);
    }
    return y;
}

static double bom_table(cairo_t *cr, const tippe_build_sheet *s, double x, double y, double w)
{
    double widths[3] = {0.06 * w, 0.36 * w, 0.58 * w};
    const char *head[3] = {"qty", "item", "detail"};
    y = row(cr, head, widths, 3, x, y, 9, 1, 1);
    for (int k = 0; k < s->n_bom; k++) {
        char q[16];
        snprintf(q, sizeof q, "%d", s->bom[k].quantity);
        const char *cells[3] = {q, s->bom[k].what, s->bom[k].detail};
        y = row(cr, cells, widths, 3, x, y, 9, 0, 0);
    }
    return y;
}

static double print_table(cairo_t *cr, const tippe_build_sheet *s, double x, double y, double w)
{
    double widths[5] = {0.2 * w, 0.18 * w, 0.18 * w, 0.2 * w, 0.24 * w};
    const char *head[5] = {"part", "perimeters", "top/bottom", "infill", "orientation"};
    y = row(cr, head, widths, 5, x, y, 9, 1, 1);
    for (int k = 0; k < s->n_print; k++) {
        const tippe_print_settings *p = &s->print[k].settings;
        char c[5][160];
        snprintf(c[0], sizeof c[0], "%s (%s)", s->print[k].part, s->print[k].material);
        if (s->print[k].has_block) {
            snprintf(c[1], sizeof c[1], "%d x %.2f mm", p->perimeters, p->line_width_mm);
            snprintf(c[2], sizeof c[2], "%d x %.2f mm layers", p->top_bottom_layers,
                     p->layer_height_mm);
            snprintf(c[3], sizeof c[3], "%.0f %%%s", 100 * s->print[k].infill,
                     s->print[k].calibrated ? " (calibrated by weighing)" : " (slicer's)");
        } else {
            snprintf(c[1], sizeof c[1], "solid");
            snprintf(c[2], sizeof c[2], "solid");
            snprintf(c[3], sizeof c[3], "100 %% (no print block: modelled solid)");
        }
        snprintf(c[4], sizeof c[4], "%s", s->needs_split ? "axis vertical, halves on their cut faces"
                                                          : "axis vertical");
        const char *cells[5] = {c[0], c[1], c[2], c[3], c[4]};
        y = row(cr, cells, widths, 5, x, y, 9, 0, 0);
    }
    return y;
}

static int draw_page(const tippe_design *d, const tippe_build_sheet *s, cairo_t *cr,
                     double *bottom, tippe_error *err)
{
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    char t[6144];
    snprintf(t, sizeof t, "Build sheet: %s", s->design_name);
    /* a long name or path wraps: what follows moves down, not under it */
    double y_sub = wrapped(cr, t, M, M + 14, SHEET_W - 2 * M, 18, 1) - 0.5;
    char verdict[512];
    tippe_build_verdict_text(s, verdict, sizeof verdict);
    char head[4400];
    tippe_build_header_text(s, head, sizeof head);
    snprintf(t, sizeof t, "%s (Z2: its midpoint above the sphere's centre). %s", head, verdict);
    double y_head = wrapped(cr, t, M, y_sub, SHEET_W - 2 * M, 10.5, 0);
    /* the settings too narrow to set, in red under the verdict */
    cairo_set_source_rgb(cr, 0.75, 0.05, 0.05);
    for (int k = 0; k < s->n_warnings; k++) {
        snprintf(t, sizeof t, "Warning: %s", s->warning[k]);
        y_head = wrapped(cr, t, M, y_head, SHEET_W - 2 * M, 10, 0);
    }
    cairo_set_source_rgb(cr, 0, 0, 0);

    /* the section, with the weight at the flip's setting (else the first there is) */
    double z2 = NAN, rim_z = 0, end_z = 0, depth_x = 0;
    int has_depth = 0;
    char depth_label[64] = "";
    tippe_export_shown_setting(s, &z2, &has_depth, &rim_z, &end_z, &depth_x, depth_label,
                               sizeof depth_label);
    if (!isfinite(z2))
        z2 = 0.5 * (s->travel_from_mm + s->travel_to_mm);
    tippe_top top;
    tippe_design_top_any(d, z2, &top);
    tippe_profile_options po = tippe_profile_defaults();
    po.sockets = s->needs_split; /* as tippe build exports it */
    tippe_profile_set ps;
    tippe_error pe = {0};
    int have_ps = tippe_profile_build(d, &po, &ps, &pe) == TIPPE_OK;
    char note[120];
    snprintf(note, sizeof note, "the weight at the %s setting",
             s->set[1].reachable ? "flip" : "first");
    tippe_drawing_options o = {.z2_mm = z2,
                               .com_z_mm = top.com_side * top.eps * 1e3,
                               .title = "Section",
                               .note = note,
                               .clearance_mm = po.clearance_mm,
                               .clearance_applied = have_ps ? ps.clearance_applied : NULL,
                               .chord_mm = 0.05,
                               .fit_part = s->hole_part,
                               .fit_diameter_mm =
                                   s->hole_tapped || s->hole_insert ? s->hole_diameter_mm : 0,
                               .fit_note = s->fit_note,
                               .has_cut = s->needs_split,
                               .joint = s->joint_ring,
                               .cut_z_mm = 0,
                               .n_sockets = have_ps ? ps.n_sockets : 0,
                               .has_depth = has_depth,
                               .depth_rim_z_mm = rim_z,
                               .depth_end_z_mm = end_z,
                               .depth_x_mm = depth_x,
                               .depth_label = depth_label,
                               .depth_from = tippe_export_depth_from(s)};
    for (int k = 0; k < o.n_sockets; k++) {
        o.socket_part[k] = ps.socket_part[k];
        o.socket_r_mm[k] = ps.socket_r_mm[k];
        o.socket_rim_z_mm[k] = ps.socket_rim_z_mm[k];
        o.socket_floor_z_mm[k] = ps.socket_floor_z_mm[k];
    }
    double top_y = fmax(M + 52, y_head + 2.5);
    int rc = tippe_drawing_render(d, &o, cr, M, top_y, 520, 433, err);
    if (have_ps)
        tippe_profile_set_free(&ps);
    if (rc)
        return rc;
    cairo_set_source_rgb(cr, 0.6, 0.6, 0.6);
    cairo_set_line_width(cr, 0.6);
    cairo_rectangle(cr, M, top_y, 520, 433);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);

    /* right: bill of materials, thread, print settings */
    double rx = M + 540, rw = SHEET_W - M - rx, y = top_y + 12;
    heading(cr, "Bill of materials", rx, y);
    y = bom_table(cr, s, rx, y + 6, rw) + 14;
    if (s->has_thread) {
        if (s->catalogue_item[0])
            snprintf(t, sizeof t, "Thread %s x %g mm: catalogue item %s (%s). Tap drill %.2f mm "
                                  "(d - P, ISO 261 coarse pitch, ISO 2306).",
                     s->thread_name, s->thread.pitch_mm, s->catalogue_item, s->catalogue_title,
                     s->tap_drill_mm);
        else
            snprintf(t, sizeof t, "Thread %s x %g mm%s. Tap drill %.2f mm (d - P, ISO 261 "
                                  "coarse pitch, ISO 2306).",
                     s->thread_name, s->thread.pitch_mm,
                     s->thread_assumed ? " (assumed: no catalogue item matches the weight; the "
                                         "ISO 261 size nearest its modelled diameter)"
                                       : "",
                     s->tap_drill_mm);
        y = wrapped(cr, t, rx, y, rw, 9.5, 0) + 8;
    }
    heading(cr, "Print settings", rx, y);
    y = print_table(cr, s, rx, y + 6, rw) + 14;
    for (int k = 0; k < s->n_notes; k++)
        y = wrapped(cr, s->note[k], rx, y, rw, 9, 0) + 2;
    if (!s->settable) {
        y += 10;
        heading(cr, s->n_advice && s->advice[0].pair ? "What would make it settable (pairs)"
                                                     : "What would make it settable",
                rx, y);
        y += 16;
        for (int k = 0; k < s->n_advice; k++) {
            char sets[1400];
            tippe_build_advice_sets(s, k, sets, sizeof sets);
            snprintf(t, sizeof t, "- %s.", s->advice[k].text);
            y = wrapped(cr, t, rx, y, rw, 9.5, 0) + 1;
            y = wrapped(cr, sets, rx + 8, y, rw - 8, 7.5, 0) + 3;
        }
        if (!s->n_advice)
            y = wrapped(cr, tippe_build_advice_none(), rx, y, rw, 9.5, 0);
    }
    if (s->n_caps) {
        y += 10;
        heading(cr, "The poles: a hole opens there", rx, y);
        y += 16;
        for (int k = 0; k < 2; k++)
            if (s->caps[k].half_angle_rad > 0) {
                char made[160] = "";
                if (s->cap_made_mm[k] > 0)
                    snprintf(made, sizeof made, "; %s, %.2f mm across, within %.1f deg",
                             s->hole_tapped ? "tapped" : "with its insert", s->cap_made_mm[k],
                             s->cap_made_half_angle_rad[k] * 180 / M_PI);
                snprintf(t, sizeof t,
                         "'%s' opens at the %s pole (%.2f mm across as modelled%s): tilted less "
                         "than %.1f deg on it the top stands on the hole's rim, not on its "
                         "sphere.",
                         s->caps[k].part, k ? "-z" : "+z", 2 * s->caps[k].radius_mm, made,
                         s->caps[k].half_angle_rad * 180 / M_PI);
                y = wrapped(cr, t, rx, y, rw, 9, 0) + 1;
            }
        for (int k = 0; k < s->n_pole_fixes; k++) {
            snprintf(t, sizeof t, "- %s", s->pole_fix[k].text);
            y = wrapped(cr, t, rx, y, rw, 9, 0) + 1;
            int n = 0;
            for (int i = 0; i < s->pole_fix[k].n_set && n < (int)sizeof t; i++)
                n += snprintf(t + n, sizeof t - (size_t)n, "%s--set %s", i ? " " : "",
                              s->pole_fix[k].set[i]);
            y = wrapped(cr, t, rx + 8, y, rw - 8, 7.5, 0) + 3;
        }
    }

    /* below: the settings, then the steps */
    y = fmax(y, top_y + 433) + 20;
    heading(cr, "Settings: where to put the weight, how fast to spin", M, y);
    double y_table = y + 6;
    if (s->measure != TIPPE_BUILD_MEASURE_NONE) {
        snprintf(t, sizeof t, "Depth measured from %s.", s->reference);
        /* 1.25 x 9 pt a line: a second line pushes the table down */
        y_table = fmax(y_table, wrapped(cr, t, M + 380, y, SHEET_W - 2 * M - 380, 9, 0) - 5.25);
    }
    y = settings_table(cr, s, M, y_table, SHEET_W - 2 * M) + 16;
    heading(cr, "Steps", M, y);
    y += 14;
    for (int k = 0; k < s->n_steps; k++) {
        snprintf(t, sizeof t, "%d. %s", k + 1, s->step[k]);
        y = wrapped(cr, t, M, y, SHEET_W - 2 * M, 9.5, 0) + 1;
    }
    *bottom = y;
    return cairo_status(cr) == CAIRO_STATUS_SUCCESS
               ? TIPPE_OK
               : tippe_error_set(err, TIPPE_ECOMPUTE, "cairo could not draw the build sheet");
}

static cairo_status_t to_file(void *closure, const unsigned char *data, unsigned int length)
{
    return fwrite(data, 1, length, (FILE *)closure) == length ? CAIRO_STATUS_SUCCESS
                                                              : CAIRO_STATUS_WRITE_ERROR;
}

int tippe_export_sheet_write(const tippe_design *d, const tippe_build_sheet *s, const char *path,
                             tippe_error *err)
{
    const char *dot = strrchr(path, '.');
    const char *ext = dot ? dot + 1 : "";
    int pdf = !strcmp(ext, "pdf"), svg = !strcmp(ext, "svg"), png = !strcmp(ext, "png");
    if (!pdf && !svg && !png)
        return tippe_error_set(err, TIPPE_EINPUT, "%s: a build sheet is .pdf, .svg or .png", path);
    /* A3 landscape, longer when the sheet holds more than a page (advice, the
     * poles' fixes): laid out once on a recording surface to measure it */
    double bottom = SHEET_H;
    cairo_surface_t *probe = cairo_recording_surface_create(CAIRO_CONTENT_COLOR, NULL);
    cairo_t *pc = cairo_create(probe);
    int rc = draw_page(d, s, pc, &bottom, err);
    cairo_destroy(pc);
    cairo_surface_destroy(probe);
    if (rc)
        return rc;
    const double H = fmax(SHEET_H, ceil(bottom + 30));
    tippe_report_file rf;
    rc = tippe_report_open(&rf, path, "the build sheet", err);
    if (rc)
        return rc;
    cairo_surface_t *sf =
        pdf   ? cairo_pdf_surface_create_for_stream(to_file, rf.f, SHEET_W, H)
        : svg ? cairo_svg_surface_create_for_stream(to_file, rf.f, SHEET_W, H)
              : cairo_image_surface_create(CAIRO_FORMAT_RGB24, (int)(SHEET_W * PNG_SCALE),
                                           (int)(H * PNG_SCALE));
    cairo_t *cr = cairo_create(sf);
    if (png)
        cairo_scale(cr, PNG_SCALE, PNG_SCALE);
    rc = draw_page(d, s, cr, &bottom, err);
    cairo_destroy(cr);
    int ok = !rc;
    if (ok && png)
        ok = cairo_surface_write_to_png_stream(sf, to_file, rf.f) == CAIRO_STATUS_SUCCESS;
    cairo_surface_finish(sf);
    ok = ok && cairo_surface_status(sf) == CAIRO_STATUS_SUCCESS;
    cairo_surface_destroy(sf);
    if (!ok && rc) {
        tippe_report_abort(&rf);
        return rc;
    }
    if (!ok)
        return tippe_report_fail(&rf, err, "cairo could not write the build sheet");
    return tippe_report_commit(&rf, err);
}

/* ------------------------------------------------------------ gauges */

int tippe_export_gauge_write(const tippe_build_sheet *s, int f, const char *path,
                             tippe_error *err)
{
    double pin;
    if (!tippe_build_gauge_applies(s, f, &pin))
        return tippe_error_set(err, TIPPE_EINPUT, "%s: no gauge for the '%s' setting", path,
                               tippe_build_behaviour(f));
    tippe_profile_point pt[6];
    int n;
    double r_max;
    const double t = TIPPE_BUILD_GAUGE_FLANGE_MM;
    if (s->measure == TIPPE_BUILD_MEASURE_HOLE) {
        /* printed flange down: the pin's end is pin mm from the flange's face */
        double rp = 0.5 * tippe_build_gauge_pin_diameter_mm(s),
               rf = 0.5 * s->hole_diameter_mm + 4;
        tippe_profile_point p[6] = {{0, 0}, {rf, 0}, {rf, t}, {rp, t}, {rp, t + pin}, {0, t + pin}};
        memcpy(pt, p, sizeof p);
        n = 6;
        r_max = rf;
    } else {
        double ri = 0.5 * s->rod_diameter_mm + 0.25, ro = ri + 2.5;
        tippe_profile_point p[4] = {{ri, 0}, {ro, 0}, {ro, pin}, {ri, pin}};
        memcpy(pt, p, sizeof p);
        n = 4;
        r_max = ro;
    }
    tippe_profile_ring ring = {.n = n, .pt = pt};
    tippe_profile_body b = {.n_rings = 1, .ring = &ring, .r_max_mm = r_max, .cut_z_mm = NAN};
    snprintf(b.name, sizeof b.name, "gauge-%s", tippe_build_behaviour(f));
    tippe_mesh m;
    tippe_mesh_audit a;
    int rc = tippe_mesh_revolve(&b, tippe_profile_angle_steps(r_max, 0.005), &m, err);
    if (!rc)
        rc = tippe_mesh_check(&m, &a, err);
    if (!rc && (a.open_edges || a.nonmanifold_edges || a.flipped_edges || a.degenerate_triangles))
        rc = tippe_error_set(err, TIPPE_ECOMPUTE, "%s: the gauge's mesh is not closed", path);
    if (!rc)
        rc = tippe_mesh_write_stl(&m, path, b.name, err);
    tippe_mesh_free(&m);
    return rc;
}
