/* The section drawing: a display list in mm, rendered by cairo (PNG, PDF) or
 * written as SVG text (so that the labels stay text a test can read). */
#include "export/drawing.h"
#include "export/drawing_list.h"

#include "tippe/profile.h"
#include "tippe/base.h"

#include <cairo.h>

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>


static item *add(dlist *L, int kind, int n_pts)
{
    if (L->n == L->cap) {
        int cap = L->cap ? 2 * L->cap : 64;
        item *ni = realloc(L->it, (size_t)cap * sizeof *ni);
        if (!ni) {
            L->fail = 1;
            return NULL;
        }
        L->it = ni;
        L->cap = cap;
    }
    item *t = &L->it[L->n];
    memset(t, 0, sizeof *t);
    t->kind = kind;
    t->hatch_deg = NAN;
    t->dim_mm = NAN;
    t->width_px = 1;
    t->size_px = 15;
    t->n = n_pts;
    t->xy = calloc(2 * (size_t)(n_pts > 0 ? n_pts : 1), sizeof *t->xy);
    if (!t->xy) {
        L->fail = 1;
        return NULL;
    }
    L->n++;
    return t;
}

static const rgb BLACK = {0, 0, 0}, GREY = {0.45, 0.45, 0.45}, WHITE = {1, 1, 1},
                 DIM = {0.05, 0.2, 0.55}, MOVING = {0.95, 0.55, 0.1}, RED = {0.8, 0.1, 0.1};

static void line(dlist *L, double x0, double y0, double x1, double y1, rgb c, double w, int dashed,
                 int a0, int a1)
{
    item *t = add(L, K_LINE, 2);
    if (!t)
        return;
    double p[4] = {x0, y0, x1, y1};
    memcpy(t->xy, p, sizeof p);
    t->stroke = c;
    t->width_px = w;
    t->dashed = dashed;
    t->arrow_start = a0;
    t->arrow_end = a1;
}

static item *text(dlist *L, double x, double y, int anchor, double size, rgb c, const char *fmt,
                  ...) __attribute__((format(printf, 7, 8)));
static item *text(dlist *L, double x, double y, int anchor, double size, rgb c, const char *fmt,
                  ...)
{
    item *t = add(L, K_TEXT, 1);
    if (!t)
        return NULL;
    t->xy[0] = x;
    t->xy[1] = y;
    t->anchor = anchor;
    t->size_px = size;
    t->stroke = c;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(t->text, sizeof t->text, fmt, ap);
    va_end(ap);
    return t;
}

/* A dimension label: its text and the value it states. */
static void dim_text(dlist *L, double x, double y, int anchor, const char *name, double value_mm,
                     const char *fmt, ...) __attribute__((format(printf, 7, 8)));
static void dim_text(dlist *L, double x, double y, int anchor, const char *name, double value_mm,
                     const char *fmt, ...)
{
    item *t = add(L, K_TEXT, 1);
    if (!t)
        return;
    t->xy[0] = x;
    t->xy[1] = y;
    t->anchor = anchor;
    t->size_px = 15;
    t->stroke = DIM;
    t->dim_mm = value_mm;
    snprintf(t->dim_name, sizeof t->dim_name, "%s", name);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(t->text, sizeof t->text, fmt, ap);
    va_end(ap);
}

/* ------------------------------------------------------------ materials */

typedef struct {
    rgb fill;
    double hatch_deg;
    int cross;
} style;

static style material_style(int index, int printable)
{
    static const style printed[] = {{{0.78, 0.87, 0.97}, 45, 0},
                                    {{0.80, 0.93, 0.78}, -45, 0},
                                    {{0.97, 0.90, 0.75}, 60, 0},
                                    {{0.92, 0.82, 0.95}, -60, 0}};
    static const style metal[] = {{{0.70, 0.70, 0.72}, 45, 1},
                                  {{0.86, 0.78, 0.50}, -45, 1},
                                  {{0.60, 0.62, 0.70}, 30, 1},
                                  {{0.75, 0.72, 0.68}, -30, 1}};
    return printable ? printed[index % 4] : metal[index % 4];
}

typedef struct {
    int n;
    char name[16][64];
    int printable[16];
} material_list;

static int material_index(material_list *m, const char *name, int printable)
{
    for (int k = 0; k < m->n; k++)
        if (!strcmp(m->name[k], name) && m->printable[k] == printable)
            return k; /* "(inline)" printed and "(inline)" hardware differ */
    if (m->n == 16)
        return 15;
    snprintf(m->name[m->n], sizeof m->name[0], "%s", name);
    m->printable[m->n] = printable;
    return m->n++;
}

/* Index among materials of the same kind (printed or not), for its style. */
static int kind_index(const material_list *m, int k)
{
    int i = 0;
    for (int j = 0; j < k; j++)
        i += m->printable[j] == m->printable[k];
    return i;
}

/* ---------------------------------------------------------------- parts */

/* Part i's outline, both halves of the section (r and -r), as polygons. */
static void part_polys(dlist *L, const tippe_design *d, int i, double dz, double chord, rgb fill,
                       double hatch, int cross, int filled)
{
    tippe_profile_ring *rings = NULL;
    int n = tippe_profile_part_outline(d, i, dz, chord, &rings);
    if (n < 0) {
        L->fail = 1;
        return;
    }
    for (int side = -1; side <= 1; side += 2)
        for (int k = 0; k < n; k++) {
            item *t = add(L, K_POLY, rings[k].n);
            if (!t)
                break;
            for (int j = 0; j < rings[k].n; j++) {
                t->xy[2 * j] = side * rings[k].pt[j].r_mm;
                t->xy[2 * j + 1] = rings[k].pt[j].z_mm;
            }
            t->fill = fill;
            t->filled = filled;
            t->hatch_deg = hatch;
            t->cross = cross;
            t->stroke = BLACK;
            t->width_px = 1.4;
        }
    tippe_profile_rings_free(rings, n);
}

/* A filled rectangle |r| <= r_mm between heights z0 and z1. */
static void box(dlist *L, double r_mm, double z0, double z1, rgb fill, double hatch, int cross)
{
    item *t = add(L, K_POLY, 4);
    if (!t)
        return;
    double p[8] = {-r_mm, z0, r_mm, z0, r_mm, z1, -r_mm, z1};
    memcpy(t->xy, p, sizeof p);
    t->fill = fill;
    t->filled = 1;
    t->hatch_deg = hatch;
    t->cross = cross;
    t->stroke = BLACK;
    t->width_px = 1.4;
}

static void draw_parts(dlist *L, const tippe_design *d, const tippe_drawing_options *o,
                       material_list *mats)
{
    int n = tippe_design_n_parts(d);
    /* printed and fixed parts, then their voids (the page's white), then the
     * fixed hardware, then the moving parts at Z2 */
    for (int pass = 0; pass < 4; pass++)
        for (int i = 0; i < n; i++) {
            tippe_design_part_info p;
            tippe_design_part(d, i, &p);
            int is_void = !strcmp(p.role, "void"), moving = !strcmp(p.role, "moving");
            /* as export prints it (a print block with an inline density too) */
            int filament = tippe_profile_part_filament(d, i);
            int want = pass == 0   ? !is_void && !moving && filament
                       : pass == 1 ? is_void
                       : pass == 2 ? !is_void && !moving && !filament
                                   : !is_void && moving;
            if (!want)
                continue;
            double dz = 0;
            if (is_void) {
                tippe_design_solid s;
                tippe_design_part_solid(d, i, &s);
                dz = s.moving ? o->z2_mm : 0;
                if (s.moving)
                    continue; /* a moving part's void: drawn with it below */
                part_polys(L, d, i, 0, o->chord_mm, WHITE, NAN, 0, 1);
                continue;
            }
            dz = moving ? o->z2_mm : 0;
            int k = material_index(mats, p.material, filament);
            style st = material_style(kind_index(mats, k), filament);
            rgb fill = moving ? (rgb){1.0, 0.80, 0.55} : st.fill;
            part_polys(L, d, i, dz, o->chord_mm, fill, st.hatch_deg, st.cross, 1);
            if (pass == 0) /* the sockets cut into the wall, as voids are */
                for (int q = 0; q < o->n_sockets; q++)
                    box(L, o->socket_r_mm[q], o->socket_rim_z_mm[q], o->socket_floor_z_mm[q],
                        WHITE, NAN, 0);
            for (int q = 0; pass == 2 && q < o->n_sockets; q++) {
                /* the rod as bought: cut square, reaching the socket's floor */
                tippe_design_solid s;
                tippe_design_part_solid(d, i, &s);
                if (o->socket_part[q] != i)
                    continue;
                double rim = o->socket_rim_z_mm[q];
                box(L, s.radius_mm, rim - (rim > 0 ? 1 : -1), o->socket_floor_z_mm[q], fill,
                    st.hatch_deg, st.cross);
            }
            if (moving) /* its own voids, if any */
                for (int v = 0; v < n; v++) {
                    tippe_design_solid s;
                    tippe_design_part_solid(d, v, &s);
                    if (s.is_void && s.parent == i)
                        part_polys(L, d, v, dz, o->chord_mm, WHITE, NAN, 0, 1);
                }
        }
}

/* ----------------------------------------------------------- dimensions */

static const char *part_name(const tippe_design *d, int i)
{
    tippe_design_part_info p;
    tippe_design_part(d, i, &p);
    return p.name;
}

/* Horizontal diameter dimension above the sphere, at height y_line, with
 * extension lines down to the part's edge at height y_edge. The diameter is marked
 * U+00D8, not the diameter sign U+2300, which common sans-serif fonts (Noto Sans) lack:
 * cairo's toy font API has no fallback and drew it as a box (tests/test_glyphs.sh). */
static void diameter_dim(dlist *L, const char *name, double radius, double y_edge, double y_line,
                         const char *fmt_extra)
{
    line(L, -radius, y_edge, -radius, y_line + 1.5, DIM, 0.7, 0, 0, 0);
    line(L, radius, y_edge, radius, y_line + 1.5, DIM, 0.7, 0, 0, 0);
    line(L, -radius, y_line, radius, y_line, DIM, 1, 0, 1, 1);
    char what[100];
    snprintf(what, sizeof what, "%s.diameter_mm", name);
    dim_text(L, radius + 1.2, y_line - 0.2, 0, what, 2 * radius, "\u00d8%.4g %s%s", 2 * radius,
             name, fmt_extra ? fmt_extra : "");
}

/* Vertical dimension on the right at x_line from y0 to y1, extension lines
 * from x_edge. */
static void height_dim_at(dlist *L, const char *name, const char *field, double x_edge,
                          double x_line, double y0, double y1, double y_label)
{
    line(L, x_edge, y0, x_line + 1.5, y0, DIM, 0.7, 0, 0, 0);
    line(L, x_edge, y1, x_line + 1.5, y1, DIM, 0.7, 0, 0, 0);
    line(L, x_line, y0, x_line, y1, DIM, 1, 0, 1, 1);
    char what[100];
    snprintf(what, sizeof what, "%s.%s", name, field);
    dim_text(L, x_line + 1.2, y_label - 0.6, 0, what, y1 - y0, "%.4g", y1 - y0);
    text(L, x_line + 1.2, y_label - 3.2, 0, 12, DIM, "%s", name);
}

/* A right-hand column's label block (value, name, a note: from about y + 1.5
 * down to y - 7.5 mm) moved off the cut plane's label, which runs across those
 * columns at the cut: below it if the dimension reaches there, else above. */
static double label_clear_of_cut(const tippe_drawing_options *o, double y, double y0, double y1)
{
    if (!o->has_cut || y + 1.5 < o->cut_z_mm - 1.2 || y - 7.5 > o->cut_z_mm + 1.2)
        return y;
    double below = o->cut_z_mm - 2.7, above = o->cut_z_mm + 8.7;
    return below >= fmin(y0, y1) ? below : above;
}

static void height_dim(dlist *L, const tippe_drawing_options *o, const char *name,
                       const char *field, double x_edge, double x_line, double y0, double y1)
{
    height_dim_at(L, name, field, x_edge, x_line, y0, y1,
                  label_clear_of_cut(o, 0.5 * (y0 + y1), y0, y1));
}

/* Top z of a (possibly clipped) cylinder wall at radius r. */
static double wall_top(const tippe_design_solid *s, double r, double dz)
{
    double top = s->z_mm + dz + s->height_mm / 2;
    if (s->clip_radius_mm > 0 && r < s->clip_radius_mm)
        top = fmin(top, sqrt(s->clip_radius_mm * s->clip_radius_mm - r * r));
    return top;
}

static void draw_dimensions(dlist *L, const tippe_design *d, const tippe_drawing_options *o)
{
    double R = tippe_design_radius_mm(d);
    /* sphere radius: from O down-left to the surface */
    double a = 215 * M_PI / 180;
    line(L, 0, 0, R * cos(a), R * sin(a), DIM, 1, 0, 0, 1);
    dim_text(L, 0.55 * R * cos(a), 0.55 * R * sin(a) + 1.2, 2, "sphere.radius_mm", R, "R %.4g",
             R);
    int top_k = 0, right_k = 0;
    int n = tippe_design_n_parts(d);
    for (int i = 0; i < n; i++) {
        tippe_design_solid s;
        tippe_design_part_solid(d, i, &s);
        const char *name = part_name(d, i);
        double dz = s.moving ? o->z2_mm : 0;
        char extra[80] = "";
        if (s.is_void && o->clearance_applied && o->clearance_applied[i] &&
            o->fit_diameter_mm > 0 && i == o->fit_part)
            snprintf(extra, sizeof extra, " (printed %.4g: %s)", o->fit_diameter_mm,
                     o->fit_note ? o->fit_note : "for its thread");
        else if (s.is_void && o->clearance_applied && o->clearance_applied[i])
            snprintf(extra, sizeof extra, " (printed %.4g: +%.4g clearance)",
                     2 * (s.radius_mm + o->clearance_mm), o->clearance_mm);
        if (!strcmp(s.shape, "cylinder") || !strcmp(s.shape, "tube")) {
            double y_line = R + 5 + 6.5 * top_k++;
            diameter_dim(L, name, s.radius_mm, wall_top(&s, s.radius_mm, dz), y_line, extra);
            if (s.inner_radius_mm > 0) { /* a tube's bore, a bead's too */
                y_line = R + 5 + 6.5 * top_k++;
                char what[100];
                snprintf(what, sizeof what, "%s bore", name);
                diameter_dim(L, what, s.inner_radius_mm, wall_top(&s, s.inner_radius_mm, dz),
                             y_line, NULL);
            }
            if (s.clip_radius_mm <= 0) {
                double x_line = R + 6 + 12 * right_k++;
                height_dim(L, o, name, "height_mm", s.radius_mm, x_line,
                           s.z_mm + dz - s.height_mm / 2, s.z_mm + dz + s.height_mm / 2);
            } else if (s.is_void && !s.moving && s.clip_radius_mm > 0 && s.clip_inner_mm == 0) {
                /* a blind hole: its depth from the rim as printed (where a depth rod
                 * rests: the hole's wall, grown or printed for its thread, meets the
                 * clip ball) down to its floor */
                double ap = s.radius_mm;
                if (o->clearance_applied && o->clearance_applied[i])
                    ap = o->fit_diameter_mm > 0 && i == o->fit_part ? 0.5 * o->fit_diameter_mm
                                                                   : s.radius_mm + o->clearance_mm;
                double rc = s.clip_radius_mm;
                if (ap < rc) {
                    double rim = sqrt(rc * rc - ap * ap);
                    double hi = s.z_mm + s.height_mm / 2, lo = s.z_mm - s.height_mm / 2;
                    int up = hi >= rim - 1e-9, down = lo <= -rim + 1e-9;
                    if (up != down) {
                        double x_line = R + 6 + 12 * right_k++;
                        double y0 = up ? lo : -rim, y1 = up ? rim : hi;
                        double yl = label_clear_of_cut(o, y0 + 0.3 * (y1 - y0), y0, y1);
                        height_dim_at(L, name, "depth_mm", ap, x_line, y0, y1, yl);
                        text(L, x_line + 1.2, yl - 6.4, 0, 12, DIM, "deep from the rim");
                    }
                }
            } else if (!s.is_void && !s.moving && s.inner_radius_mm == 0 &&
                       !tippe_profile_part_filament(d, i)) {
                /* a rod the clip ends: its length as bought, cut square where its end
                 * edges meet the clip ball, or at the sockets' floors */
                double cap = sqrt(s.clip_radius_mm * s.clip_radius_mm - s.radius_mm * s.radius_mm);
                double lo = fmax(s.z_mm - s.height_mm / 2, -cap), hi = fmin(s.z_mm + s.height_mm / 2, cap);
                int held = 0;
                for (int q = 0; q < o->n_sockets; q++)
                    if (o->socket_part[q] == i) {
                        held++;
                        if (o->socket_floor_z_mm[q] > 0)
                            hi = o->socket_floor_z_mm[q];
                        else
                            lo = o->socket_floor_z_mm[q];
                        if (o->socket_floor_z_mm[q] > 0) {
                            char what[100];
                            snprintf(what, sizeof what, "%s.socket_diameter_mm", name);
                            double ra = o->socket_r_mm[q];
                            line(L, ra, o->socket_floor_z_mm[q], R * 0.45, R + 3, DIM, 0.8, 0, 1, 0);
                            dim_text(L, R * 0.45 + 0.8, R + 2.6, 0, what, 2 * ra,
                                     "socket \u00d8%.4g, %.4g deep", 2 * ra,
                                     o->socket_floor_z_mm[q] - o->socket_rim_z_mm[q]);
                        }
                    }
                double x_line = R + 6 + 12 * right_k++;
                /* the label below the middle, clear of a cut plane at the equator */
                double yl = label_clear_of_cut(o, lo + 0.3 * (hi - lo), lo, hi);
                height_dim_at(L, name, "length_mm", s.radius_mm, x_line, lo, hi, yl);
                text(L, x_line + 1.2, yl - 6.4, 0, 12, DIM, "%s",
                     held ? "cut square, in sockets" : "cut square");
            }
        } else if (!strcmp(s.shape, "shell") && !s.is_void) {
            double b = 40 * M_PI / 180, ri = s.radius_mm - s.thickness_mm;
            line(L, ri * cos(b), ri * sin(b), (s.radius_mm + 6) * cos(b),
                 (s.radius_mm + 6) * sin(b), DIM, 1, 0, 1, 0);
            char what[100];
            snprintf(what, sizeof what, "%s.thickness_mm", name);
            dim_text(L, (s.radius_mm + 6.5) * cos(b), (s.radius_mm + 6.5) * sin(b), 0, what,
                     s.thickness_mm, "wall %.4g", s.thickness_mm);
        } else if (!strcmp(s.shape, "torus")) {
            /* the label under the sphere, clear of the right-hand columns' labels
             * (a rod's length sits at the band's height) and of the cut plane's */
            double xr = s.centre_radius_mm - s.radial_semi_mm * 0.5, yr = s.z_mm + dz;
            line(L, xr, yr, R + 1, -R - 2, DIM, 1, 0, 1, 0);
            char what[100];
            snprintf(what, sizeof what, "%s.radial_semi_mm", name);
            dim_text(L, R + 1.5, -R - 3.2, 0, what, s.radial_semi_mm,
                     "%s semi-axes: radial %.4g", name, s.radial_semi_mm);
            snprintf(what, sizeof what, "%s.axial_semi_mm", name);
            dim_text(L, R + 1.5, -R - 7.2, 0, what, s.axial_semi_mm, "axial %.4g",
                     s.axial_semi_mm);
        } else if (!strcmp(s.shape, "ball") && fabs(s.radius_mm - R) > 1e-9) {
            double y_line = R + 5 + 6.5 * top_k++;
            diameter_dim(L, name, s.radius_mm, s.z_mm + dz, y_line, extra);
        }
    }
    if (o->has_depth) {
        /* the sheet's setting: what a caliper's depth rod on the rim reads */
        double x_line = R + 6 + 12 * right_k++, y0 = o->depth_end_z_mm, y1 = o->depth_rim_z_mm;
        double depth = fabs(y1 - y0), yl = label_clear_of_cut(o, 0.5 * (y0 + y1), fmin(y0, y1),
                                                              fmax(y0, y1));
        line(L, o->depth_x_mm, y0, x_line + 1.5, y0, MOVING, 0.7, 0, 0, 0);
        line(L, o->depth_x_mm, y1, x_line + 1.5, y1, MOVING, 0.7, 0, 0, 0);
        line(L, x_line, y0, x_line, y1, MOVING, 1.2, 0, 1, 1);
        dim_text(L, x_line + 1.2, yl - 0.6, 0, "setting.depth_mm", depth, "%.2f", depth);
        /* the dimensions' ink, a size up from the parts' names: a maker reads it */
        text(L, x_line + 1.2, yl - 3.4, 0, 14, DIM, "depth below %s",
             o->depth_from ? o->depth_from : "the rim");
        if (o->depth_label)
            text(L, x_line + 1.2, yl - 6.8, 0, 14, DIM, "%s", o->depth_label);
    }
}

static void draw_marks_and_travel(dlist *L, const tippe_design *d, const tippe_drawing_options *o)
{
    double R = tippe_design_radius_mm(d), t0, t1;
    tippe_design_travel_mm(d, &t0, &t1);
    /* axis */
    line(L, 0, -R - 4, 0, R + 4, GREY, 0.8, 1, 0, 0);
    /* Z2: from O to the weight's midpoint */
    double xz = -R - 7;
    line(L, -1.5, 0, xz - 1.5, 0, DIM, 0.7, 0, 0, 0);
    line(L, -1.5, o->z2_mm, xz - 1.5, o->z2_mm, MOVING, 0.9, 1, 0, 0);
    if (fabs(o->z2_mm) > 1e-9)
        line(L, xz, 0, xz, o->z2_mm, DIM, 1, 0, 1, 1);
    dim_text(L, xz - 1.2, 0.5 * o->z2_mm - 0.6, 2, "z2_mm", o->z2_mm, "Z2 = %.4g", o->z2_mm);
    /* travel bracket of the weight's midpoint */
    /* at 1:1 the labels are larger against the top: the bracket moves clear of
     * Z2's label */
    double xb = -R - (o->one_to_one ? 38 : 20);
    line(L, xb, t0, xb, t1, MOVING, 2.2, 0, 0, 0);
    line(L, xb, t0, xb + 2, t0, MOVING, 2.2, 0, 0, 0);
    line(L, xb, t1, xb + 2, t1, MOVING, 2.2, 0, 0, 0);
    dim_text(L, xb - 1, t1 - 0.6, 2, "travel_mm[1]", t1, "%.4g", t1);
    dim_text(L, xb - 1, t0 - 0.6, 2, "travel_mm[0]", t0, "%.4g", t0);
    item *t = text(L, xb - 1, 0.5 * (t0 + t1), 1, 13, MOVING, "travel of Z2");
    if (t)
        t->rotate_deg = -90;
    /* O and G */
    item *m = add(L, K_MARK, 1);
    if (m) {
        m->mark_style = 0;
        m->stroke = BLACK;
    }
    text(L, 1.2, -2.8, 0, 14, BLACK, "O");
    m = add(L, K_MARK, 1);
    if (m) {
        m->xy[1] = o->com_z_mm;
        m->mark_style = 1;
        m->stroke = RED;
    }
    if (o->has_cut) {
        /* the cut plane of the halves, across the whole sphere */
        line(L, -R - 3, o->cut_z_mm, R + 3, o->cut_z_mm, RED, 1.2, 1, 0, 0);
        text(L, R + 3.5, o->cut_z_mm - 0.6, 0, 13, RED,
             o->joint ? "cut (--split): 2 mm grooves + joint ring" : "cut plane (--split)");
    }
    double eps = fabs(o->com_z_mm);
    text(L, -1.6, o->com_z_mm + 1.0, 2, 14, RED, "G");
    line(L, 0, o->com_z_mm, 0.3 * R, -0.4 * R, RED, 0.7, 0, 0, 0);
    dim_text(L, 0.3 * R + 0.8, -0.4 * R - 0.6, 0, "eps_mm", eps, "eps = %.3f (G %s O)", eps,
             o->com_z_mm > 0 ? "above" : o->com_z_mm < 0 ? "below" : "at");
}

/* ------------------------------------------------------- title, legend */

static void page_text(dlist *L, double x, double y, int anchor, double size, int bold, rgb c,
                      const char *s)
{
    item *t = text(L, x, y, anchor, size, c, "%s", s);
    if (t) {
        t->page = 1;
        t->bold = bold;
    }
}

static void draw_title_legend(dlist *L, const tippe_design *d, const tippe_drawing_options *o,
                              const material_list *mats)
{
    page_text(L, MARGIN_PX, 34, 0, 22, 1, BLACK, o->title);
    char line2[400];
    snprintf(line2, sizeof line2, "Section through the axis at Z2 = %.4g mm%s%s. Dimensions in mm.",
             o->z2_mm, o->note ? ": " : "", o->note ? o->note : "");
    page_text(L, MARGIN_PX, 64, 0, 16, 0, BLACK, line2);
    double y = PAGE_H - LEGEND_PX + 26, x = MARGIN_PX;
    for (int k = 0; k < mats->n; k++) {
        style st = material_style(kind_index(mats, k), mats->printable[k]);
        item *sw = add(L, K_POLY, 4);
        if (!sw)
            return;
        double p[8] = {x, y - 14, x + 30, y - 14, x + 30, y + 4, x, y + 4};
        memcpy(sw->xy, p, sizeof p);
        sw->page = 1;
        sw->filled = 1;
        sw->fill = st.fill;
        sw->hatch_deg = st.hatch_deg;
        sw->cross = st.cross;
        sw->stroke = BLACK;
        char s[100];
        snprintf(s, sizeof s, "%s (%s)", mats->name[k], mats->printable[k] ? "printed" : "hardware");
        page_text(L, x + 38, y, 0, 14, 0, BLACK, s);
        x += 60 + 8.5 * (double)strlen(s);
    }
    item *sw = add(L, K_POLY, 4);
    if (sw) {
        double p[8] = {x, y - 14, x + 30, y - 14, x + 30, y + 4, x, y + 4};
        memcpy(sw->xy, p, sizeof p);
        sw->page = 1;
        sw->filled = 1;
        sw->fill = (rgb){1.0, 0.80, 0.55};
        sw->stroke = BLACK;
        page_text(L, x + 38, y, 0, 14, 0, BLACK, "moving weight (at Z2)");
    }
    char notes[400], holes[200];
    /* a hole printed at a fit diameter (a tap drill) has no clearance: say which */
    int fitted = o->fit_diameter_mm > 0 && o->fit_part >= 0, grown = 0;
    for (int i = 0; o->clearance_applied && i < tippe_design_n_parts(d); i++)
        grown |= o->clearance_applied[i] && !(fitted && i == o->fit_part);
    const char *fit = o->fit_note ? o->fit_note : "fit diameter";
    if (fitted && grown)
        snprintf(holes, sizeof holes, "holes for hardware printed with radial clearance, the "
                 "screw's at its %s (not in the mass model)", fit);
    else if (fitted)
        snprintf(holes, sizeof holes, "the screw's hole printed at its %s (not in the mass model)",
                 fit);
    else
        snprintf(holes, sizeof holes, "%s",
                 grown ? "holes for hardware printed with radial clearance (not in the mass model)"
                       : "no hole takes hardware");
    snprintf(notes, sizeof notes,
             "O centre of the sphere   G centre of mass   %s   outlines within %.3g mm", holes,
             o->chord_mm / 2);
    page_text(L, MARGIN_PX, y + 34, 0, 13, 0, GREY, notes);
}

/* ---------------------------------------------------------------- entry */

static void dlist_free(dlist *L)
{
    for (int i = 0; i < L->n; i++)
        free(L->it[i].xy);
    free(L->it);
}

/* The drawing's display list: parts, marks, dimensions, title and legend, laid
 * out; L->fail when memory ran out. */

/* The page's units per mm of the top at 1:1 on A4: a PDF point is 1/72 in. */
static double one_to_one_scale(void) { return 72.0 / 25.4 / A4_K; }

/* A 50 mm bar under the top at 1:1, to check the printer kept the scale. */
static void scale_bar(dlist *L, const tippe_design *d)
{
    double R = tippe_design_radius_mm(d), y = -R - 10;
    line(L, -25, y, 25, y, BLACK, 2, 0, 0, 0);
    line(L, -25, y - 1.5, -25, y + 1.5, BLACK, 1.5, 0, 0, 0);
    line(L, 25, y - 1.5, 25, y + 1.5, BLACK, 1.5, 0, 0, 0);
    text(L, 0, y - 5, 1, 13, BLACK, "scale 1:1 - this bar is 50 mm when printed at 100 %% "
                                     "(actual size, not fit to page)");
}

static void compose(dlist *L, const tippe_design *d, const tippe_drawing_options *o,
                    int one_to_one)
{
    material_list mats = {0};
    draw_parts(L, d, o, &mats);
    draw_marks_and_travel(L, d, o);
    draw_dimensions(L, d, o);
    if (one_to_one)
        scale_bar(L, d);
    draw_title_legend(L, d, o, &mats);
    tippe_drawing_layout(L, one_to_one ? one_to_one_scale() : 0);
}

int tippe_drawing_render(const tippe_design *d, const tippe_drawing_options *o, void *cairo,
                         double x, double y, double w, double h, tippe_error *err)
{
    cairo_t *cr = cairo;
    dlist L = {0};
    compose(&L, d, o, 0);
    if (L.fail) {
        dlist_free(&L);
        return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory while drawing");
    }
    double k = fmin(w / PAGE_W, h / PAGE_H);
    cairo_save(cr);
    cairo_rectangle(cr, x, y, w, h);
    cairo_clip(cr);
    cairo_translate(cr, x + (w - k * PAGE_W) / 2, y + (h - k * PAGE_H) / 2);
    cairo_scale(cr, k, k);
    tippe_drawing_render_list(&L, cr);
    cairo_restore(cr);
    dlist_free(&L);
    return TIPPE_OK;
}

int tippe_drawing_write(const tippe_design *d, const tippe_drawing_options *o, const char *path,
                        tippe_error *err)
{
    const char *ext = tippe_path_ext(path);
    int svg = !strcmp(ext, "svg"), png = !strcmp(ext, "png"), pdf = !strcmp(ext, "pdf");
    if (!svg && !png && !pdf)
        return tippe_error_set(err, TIPPE_EINPUT, "%s: a drawing is .svg, .png or .pdf", path);
    if (o->one_to_one && !pdf)
        return tippe_error_set(err, TIPPE_EINPUT, "%s: a drawing at 1:1 is a .pdf (paper has "
                                                  "a size; a screen or an SVG viewer does not)",
                               path);
    dlist L = {0};
    compose(&L, d, o, o->one_to_one);
    if (L.fail) {
        dlist_free(&L);
        return tippe_error_set(err, TIPPE_ECOMPUTE, "%s: out of memory while drawing", path);
    }
    if (o->one_to_one && L.too_big) {
        double w_mm = L.xmax - L.xmin, h_mm = L.ymax - L.ymin;
        dlist_free(&L);
        return tippe_error_set(err, TIPPE_EINPUT,
                               "%s: at 1:1 the drawing (with its labels) is %.0f x %.0f mm, "
                               "larger than an A4 landscape page can hold (%.0f x %.0f mm): "
                               "use the scaled drawing",
                               path, w_mm, h_mm,
                               (PAGE_W - 2 * MARGIN_PX) / one_to_one_scale(),
                               (PAGE_H - TITLE_PX - LEGEND_PX) / one_to_one_scale());
    }
    tippe_report_file rf;
    int rc = tippe_report_open(&rf, path, "the drawing", err);
    if (!rc) {
        int ok = 1;
        if (svg)
            tippe_drawing_write_svg(&L, rf.f);
        else
            ok = tippe_drawing_write_cairo(&L, rf.f, pdf, o->one_to_one);
        if (ok)
            rc = tippe_report_commit(&rf, err);
        else
            rc = tippe_report_fail(&rf, err, "cairo could not write the drawing");
    }
    dlist_free(&L);
    return rc;
}
