/* The section drawing's display list made into pictures: laid out on the page
 * (mm to px), rendered by cairo (PNG, PDF; A4 at 1:1) or written as SVG text,
 * so that the labels stay text a test can read. drawing.c composes the list. */
#include "export/drawing_list.h"

#include <cairo-pdf.h>
#include <cairo.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

/* ------------------------------------------------------------- layout */

/* Approximate width of a label in px (sans-serif averages ~0.58 em). */
static double text_px(const item *t)
{
    size_t n = 0;
    for (const unsigned char *s = (const unsigned char *)t->text; *s; s++)
        n += (*s & 0xc0) != 0x80; /* count UTF-8 characters */
    return 0.58 * t->size_px * (double)n;
}

/* Fits everything drawn in mm (labels included, at the scale being fitted)
 * into the page between the title and the legend. */
void tippe_drawing_layout(dlist *L, double fixed_scale)
{
    double w = PAGE_W - 2 * MARGIN_PX, h = PAGE_H - TITLE_PX - LEGEND_PX;
    L->scale = fixed_scale > 0 ? fixed_scale : 1;
    for (int pass = 0; pass < 3; pass++) {
        double x0 = 1e30, x1 = -1e30, y0 = 1e30, y1 = -1e30;
        for (int i = 0; i < L->n; i++) {
            const item *t = &L->it[i];
            if (t->page || (t->kind == K_TEXT && pass == 0))
                continue;
            for (int j = 0; j < (t->kind == K_POLY || t->kind == K_LINE ? t->n : 1); j++) {
                double x = t->xy[2 * j], y = t->xy[2 * j + 1], pad = 0, tw = 0, th = 0;
                if (t->kind == K_MARK)
                    pad = 12 / L->scale;
                if (t->kind == K_TEXT && pass > 0) {
                    tw = text_px(t) / L->scale;
                    th = 1.2 * t->size_px / L->scale;
                    if (t->rotate_deg != 0) {
                        double s = tw;
                        tw = th;
                        th = s;
                    }
                }
                double left = t->anchor == 0 ? 0 : t->anchor == 1 ? tw / 2 : tw;
                x0 = fmin(x0, x - pad - left);
                x1 = fmax(x1, x + pad + tw - left);
                y0 = fmin(y0, y - pad - (t->rotate_deg != 0 ? th / 2 : th * 0.3));
                y1 = fmax(y1, y + pad + (t->rotate_deg != 0 ? th / 2 : th));
            }
        }
        L->xmin = x0, L->xmax = x1, L->ymin = y0, L->ymax = y1;
        if (!(fixed_scale > 0))
            L->scale = fmin(w / (x1 - x0), h / (y1 - y0));
    }
    L->too_big = L->scale * (L->xmax - L->xmin) > w || L->scale * (L->ymax - L->ymin) > h;
    L->ox = MARGIN_PX + (w - L->scale * (L->xmax - L->xmin)) / 2 - L->scale * L->xmin;
    L->oy = TITLE_PX + (h - L->scale * (L->ymax - L->ymin)) / 2 + L->scale * L->ymax;
}

static void to_px(const dlist *L, const item *t, int j, double *x, double *y)
{
    if (t->page) {
        *x = t->xy[2 * j];
        *y = t->xy[2 * j + 1];
    } else {
        *x = L->ox + L->scale * t->xy[2 * j];
        *y = L->oy - L->scale * t->xy[2 * j + 1];
    }
}

/* --------------------------------------------------------------- cairo */

static void cairo_hatch(cairo_t *cr, double deg, int cross, double x0, double y0, double x1,
                        double y1)
{
    const double step = 7;
    double cx = (x0 + x1) / 2, cy = (y0 + y1) / 2, span = hypot(x1 - x0, y1 - y0) / 2 + step;
    for (int pass = 0; pass < (cross ? 2 : 1); pass++) {
        double a = (deg + 90 * pass) * M_PI / 180, ux = cos(a), uy = -sin(a);
        for (double s = -span; s <= span; s += step) {
            cairo_move_to(cr, cx + s * -uy - span * ux, cy + s * ux - span * uy);
            cairo_line_to(cr, cx + s * -uy + span * ux, cy + s * ux + span * uy);
        }
    }
    cairo_set_source_rgb(cr, 0.25, 0.25, 0.3);
    cairo_set_line_width(cr, 0.6);
    cairo_stroke(cr);
}

static void cairo_arrow(cairo_t *cr, double x, double y, double fx, double fy)
{
    double a = atan2(y - fy, x - fx), len = 9, w = 0.35;
    cairo_move_to(cr, x, y);
    cairo_line_to(cr, x - len * cos(a - w), y - len * sin(a - w));
    cairo_line_to(cr, x - len * cos(a + w), y - len * sin(a + w));
    cairo_close_path(cr);
    cairo_fill(cr);
}

static void render_list(const dlist *L, cairo_t *cr)
{
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    for (int i = 0; i < L->n; i++) {
        const item *t = &L->it[i];
        double x, y;
        if (t->kind == K_POLY) {
            double x0 = 1e30, y0 = 1e30, x1 = -1e30, y1 = -1e30;
            for (int j = 0; j < t->n; j++) {
                to_px(L, t, j, &x, &y);
                j ? cairo_line_to(cr, x, y) : cairo_move_to(cr, x, y);
                x0 = fmin(x0, x), y0 = fmin(y0, y), x1 = fmax(x1, x), y1 = fmax(y1, y);
            }
            cairo_close_path(cr);
            if (t->filled) {
                cairo_set_source_rgb(cr, t->fill.r, t->fill.g, t->fill.b);
                cairo_fill_preserve(cr);
            }
            if (!isnan(t->hatch_deg)) {
                cairo_save(cr);
                cairo_clip_preserve(cr);
                cairo_new_path(cr);
                cairo_hatch(cr, t->hatch_deg, t->cross, x0, y0, x1, y1);
                cairo_restore(cr);
            }
            cairo_set_source_rgb(cr, t->stroke.r, t->stroke.g, t->stroke.b);
            cairo_set_line_width(cr, t->width_px);
            cairo_stroke(cr);
        } else if (t->kind == K_LINE) {
            double xa, ya, xb, yb;
            to_px(L, t, 0, &xa, &ya);
            to_px(L, t, 1, &xb, &yb);
            cairo_set_source_rgb(cr, t->stroke.r, t->stroke.g, t->stroke.b);
            cairo_set_line_width(cr, t->width_px);
            double dash[2] = {10, 4};
            cairo_set_dash(cr, dash, t->dashed ? 2 : 0, 0);
            cairo_move_to(cr, xa, ya);
            cairo_line_to(cr, xb, yb);
            cairo_stroke(cr);
            cairo_set_dash(cr, NULL, 0, 0);
            if (t->arrow_end)
                cairo_arrow(cr, xb, yb, xa, ya);
            if (t->arrow_start)
                cairo_arrow(cr, xa, ya, xb, yb);
        } else if (t->kind == K_MARK) {
            to_px(L, t, 0, &x, &y);
            cairo_set_source_rgb(cr, t->stroke.r, t->stroke.g, t->stroke.b);
            cairo_set_line_width(cr, 1.6);
            cairo_new_path(cr);
            cairo_arc(cr, x, y, 7, 0, 2 * M_PI);
            cairo_stroke(cr);
            if (t->mark_style == 1) { /* centre-of-mass symbol: two filled quadrants */
                cairo_move_to(cr, x, y);
                cairo_arc(cr, x, y, 7, 0, M_PI / 2);
                cairo_close_path(cr);
                cairo_move_to(cr, x, y);
                cairo_arc(cr, x, y, 7, M_PI, 1.5 * M_PI);
                cairo_close_path(cr);
                cairo_fill(cr);
            }
            cairo_move_to(cr, x - 11, y);
            cairo_line_to(cr, x + 11, y);
            cairo_move_to(cr, x, y - 11);
            cairo_line_to(cr, x, y + 11);
            cairo_stroke(cr);
        } else {
            to_px(L, t, 0, &x, &y);
            cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                                   t->bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
            cairo_set_font_size(cr, t->size_px);
            cairo_text_extents_t ext;
            cairo_text_extents(cr, t->text, &ext);
            cairo_save(cr);
            cairo_translate(cr, x, y);
            cairo_rotate(cr, t->rotate_deg * M_PI / 180);
            double dx = t->anchor == 0 ? 0 : t->anchor == 1 ? -ext.x_advance / 2 : -ext.x_advance;
            /* a white halo keeps labels readable over hatching */
            cairo_set_source_rgba(cr, 1, 1, 1, 0.85);
            cairo_rectangle(cr, dx + ext.x_bearing - 2, ext.y_bearing - 2, ext.width + 4,
                            ext.height + 4);
            cairo_fill(cr);
            cairo_set_source_rgb(cr, t->stroke.r, t->stroke.g, t->stroke.b);
            cairo_move_to(cr, dx, 0);
            cairo_show_text(cr, t->text);
            cairo_restore(cr);
        }
    }
}

void tippe_drawing_render_list(const dlist *L, void *cairo)
{
    cairo_t *cr = cairo;
    render_list(L, cr);
}

static cairo_status_t to_file(void *closure, const unsigned char *data, unsigned int length)
{
    return fwrite(data, 1, length, (FILE *)closure) == length ? CAIRO_STATUS_SUCCESS
                                                              : CAIRO_STATUS_WRITE_ERROR;
}

int tippe_drawing_write_cairo(const dlist *L, FILE *f, int pdf, int a4)
{
    cairo_surface_t *sf =
        pdf ? cairo_pdf_surface_create_for_stream(to_file, f, a4 ? A4_W_PT : PAGE_W,
                                                  a4 ? A4_H_PT : PAGE_H)
            : cairo_image_surface_create(CAIRO_FORMAT_RGB24, PAGE_W, PAGE_H);
    cairo_t *cr = cairo_create(sf);
    if (a4) {
        cairo_set_source_rgb(cr, 1, 1, 1);
        cairo_paint(cr);
        cairo_translate(cr, (A4_W_PT - A4_K * PAGE_W) / 2, 0);
        cairo_scale(cr, A4_K, A4_K);
    }
    render_list(L, cr);
    int ok = cairo_status(cr) == CAIRO_STATUS_SUCCESS;
    cairo_destroy(cr);
    if (!pdf && ok)
        ok = cairo_surface_write_to_png_stream(sf, to_file, f) == CAIRO_STATUS_SUCCESS;
    cairo_surface_finish(sf);
    ok = ok && cairo_surface_status(sf) == CAIRO_STATUS_SUCCESS;
    cairo_surface_destroy(sf);
    return ok;
}

/* ----------------------------------------------------------------- SVG */

static void svg_escaped(FILE *f, const char *s)
{
    for (; *s; s++)
        switch (*s) {
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '&': fputs("&amp;", f); break;
        case '"': fputs("&quot;", f); break;
        default: fputc(*s, f);
        }
}

static void svg_colour(FILE *f, const char *attr, rgb c)
{
    fprintf(f, " %s=\"#%02x%02x%02x\"", attr, (int)lround(255 * c.r), (int)lround(255 * c.g),
            (int)lround(255 * c.b));
}

void tippe_drawing_write_svg(const dlist *L, FILE *f)
{
    fprintf(f,
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" "
            "viewBox=\"0 0 %d %d\" font-family=\"sans-serif\">\n"
            "<rect width=\"100%%\" height=\"100%%\" fill=\"#ffffff\"/>\n<defs>\n",
            PAGE_W, PAGE_H, PAGE_W, PAGE_H);
    for (int i = 0; i < L->n; i++) {
        const item *t = &L->it[i];
        if (t->kind != K_POLY || isnan(t->hatch_deg))
            continue;
        fprintf(f,
                "<pattern id=\"h%d\" patternUnits=\"userSpaceOnUse\" width=\"7\" height=\"7\" "
                "patternTransform=\"rotate(%g)\">",
                i, -t->hatch_deg);
        fprintf(f, "<rect width=\"7\" height=\"7\"");
        svg_colour(f, "fill", t->fill);
        fprintf(f, "/><line x1=\"0\" y1=\"0\" x2=\"7\" y2=\"0\" stroke=\"#40404c\" "
                   "stroke-width=\"1.2\"/>");
        if (t->cross)
            fprintf(f, "<line x1=\"0\" y1=\"0\" x2=\"0\" y2=\"7\" stroke=\"#40404c\" "
                       "stroke-width=\"1.2\"/>");
        fprintf(f, "</pattern>\n");
    }
    fprintf(f, "<marker id=\"arrow\" viewBox=\"0 0 10 10\" refX=\"10\" refY=\"5\" "
               "markerWidth=\"9\" markerHeight=\"9\" orient=\"auto-start-reverse\">"
               "<path d=\"M0,1 L10,5 L0,9 z\" fill=\"#0d338c\"/></marker>\n</defs>\n");
    for (int i = 0; i < L->n; i++) {
        const item *t = &L->it[i];
        double x, y;
        if (t->kind == K_POLY) {
            fprintf(f, "<polygon points=\"");
            for (int j = 0; j < t->n; j++) {
                to_px(L, t, j, &x, &y);
                fprintf(f, "%s%.2f,%.2f", j ? " " : "", x, y);
            }
            fprintf(f, "\"");
            if (!isnan(t->hatch_deg))
                fprintf(f, " fill=\"url(#h%d)\"", i);
            else if (t->filled)
                svg_colour(f, "fill", t->fill);
            else
                fprintf(f, " fill=\"none\"");
            svg_colour(f, "stroke", t->stroke);
            fprintf(f, " stroke-width=\"%.2f\"/>\n", t->width_px);
        } else if (t->kind == K_LINE) {
            double xa, ya, xb, yb;
            to_px(L, t, 0, &xa, &ya);
            to_px(L, t, 1, &xb, &yb);
            fprintf(f, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"", xa, ya, xb, yb);
            svg_colour(f, "stroke", t->stroke);
            fprintf(f, " stroke-width=\"%.2f\"%s%s%s/>\n", t->width_px,
                    t->dashed ? " stroke-dasharray=\"10 4\"" : "",
                    t->arrow_start ? " marker-start=\"url(#arrow)\"" : "",
                    t->arrow_end ? " marker-end=\"url(#arrow)\"" : "");
        } else if (t->kind == K_MARK) {
            to_px(L, t, 0, &x, &y);
            fprintf(f, "<g class=\"%s\"", t->mark_style ? "centre-of-mass" : "centre");
            svg_colour(f, "stroke", t->stroke);
            fprintf(f, " stroke-width=\"1.6\" fill=\"none\"><circle cx=\"%.2f\" cy=\"%.2f\" "
                       "r=\"7\"/>",
                    x, y);
            if (t->mark_style)
                fprintf(f,
                        "<path d=\"M%.2f,%.2f h7 a7,7 0 0,1 -7,7 z M%.2f,%.2f h-7 a7,7 0 0,1 "
                        "7,-7 z\" fill=\"#cc1a1a\"/>",
                        x, y, x, y);
            fprintf(f, "<path d=\"M%.2f,%.2f h22 M%.2f,%.2f v22\"/></g>\n", x - 11, y, x,
                    y - 11);
        } else {
            to_px(L, t, 0, &x, &y);
            static const char *const anchors[3] = {"start", "middle", "end"};
            fprintf(f, "<text x=\"%.2f\" y=\"%.2f\" font-size=\"%.1f\" text-anchor=\"%s\"%s", x,
                    y, t->size_px, anchors[t->anchor], t->bold ? " font-weight=\"bold\"" : "");
            svg_colour(f, "fill", t->stroke);
            if (t->rotate_deg != 0)
                fprintf(f, " transform=\"rotate(%g %.2f %.2f)\"", t->rotate_deg, x, y);
            if (!isnan(t->dim_mm)) {
                fprintf(f, " class=\"dim\" data-name=\"");
                svg_escaped(f, t->dim_name);
                fprintf(f, "\" data-mm=\"%.10g\"", t->dim_mm);
            }
            fprintf(f, " stroke=\"#ffffff\" stroke-width=\"3\" paint-order=\"stroke\">");
            svg_escaped(f, t->text);
            fprintf(f, "</text>\n");
        }
    }
    fprintf(f, "</svg>\n");
}
