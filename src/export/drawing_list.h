/* src/export/drawing_list.h: the section drawing's display list, shared by
 * what composes it (drawing.c) and what lays it out and writes it
 * (drawing_list.c). Internal to the export module. */
#ifndef TIPPE_EXPORT_DRAWING_LIST_H
#define TIPPE_EXPORT_DRAWING_LIST_H

#include <stdio.h>

/* Page in px (PNG at 1:1; PDF in points). */
#define PAGE_W 1200
#define PAGE_H 1000
#define TITLE_PX 86
#define LEGEND_PX 92
#define MARGIN_PX 24
/* A4 landscape in points, and the factor the 1200 x 1000 page is drawn at on
 * it (its height fills the sheet). */
#define A4_W_PT 841.89
#define A4_H_PT 595.28
#define A4_K (A4_H_PT / PAGE_H)

typedef struct {
    double r, g, b;
} rgb;

enum { K_POLY, K_LINE, K_TEXT, K_MARK };

typedef struct {
    int kind;
    int n;
    double *xy; /* mm, 2 per point (POLY, LINE); TEXT and MARK use xy[0..1] */
    rgb fill, stroke;
    int filled;
    double hatch_deg; /* NAN: no hatch */
    int cross;
    double width_px;
    int dashed, arrow_start, arrow_end;
    double size_px, rotate_deg;
    int anchor, bold; /* anchor: 0 left, 1 centre, 2 right */
    char text[160];
    double dim_mm;    /* a dimension's value (NAN: not a dimension) */
    char dim_name[80];
    int mark_style;   /* 0: centre cross (O), 1: centre of mass (G) */
    int page;         /* text in page px (title, legend) rather than mm */
} item;

typedef struct {
    int n, cap;
    item *it;
    double xmin, xmax, ymin, ymax; /* world window, mm */
    double scale, ox, oy;          /* px = ox + scale x, py = oy - scale y */
    int too_big;                   /* a fixed scale (1:1) does not fit the page */
    int fail;
} dlist;

/* Fits everything drawn in mm into the page between the title and the legend,
 * or, with fixed_scale > 0 (px per mm), centres it at that scale and sets
 * too_big when it does not fit. */
void tippe_drawing_layout(dlist *L, double fixed_scale);
/* Paints the laid-out list on a cairo context (a cairo_t *), in page px. */
void tippe_drawing_render_list(const dlist *L, void *cairo);
/* The page as PDF (a4: on A4 landscape, the page scaled by A4_K) or PNG to f;
 * 1 if cairo wrote it. */
int tippe_drawing_write_cairo(const dlist *L, FILE *f, int pdf, int a4);
/* The page as SVG text to f. */
void tippe_drawing_write_svg(const dlist *L, FILE *f);

#endif
