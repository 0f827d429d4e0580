/* plot/canvas.h: small helpers over PLplot's cairo drivers, shared by every plot.
 *
 * A figure goes to PNG, SVG or PDF according to the extension of its path
 * (pngcairo, svgcairo, pdfcairo). PLplot draws into memory; tippe_plot_close()
 * checks that the driver finished a whole file (PNG IEND chunk, SVG closing
 * tag, PDF %%EOF) and writes it through tippe/base.h (every write checked,
 * a temporary renamed into place, devices and FIFOs straight through), so a
 * failed or abandoned plot leaves nothing behind and no old file is lost.
 *
 * PLplot keeps one global drawing state, so only one figure can be open at a
 * time in a process and these functions must be called from one thread.
 *
 * Colours are 0xRRGGBB with an opacity alpha in [0, 1]. Coordinates are world
 * coordinates of the current window unless a name says otherwise. Text uses
 * PLplot's escapes ("#ge" epsilon, "#d...#u" subscript); tippe_plot_escape()
 * makes user strings (design names, file names) safe to draw. */
#ifndef TIPPE_PLOT_CANVAS_H
#define TIPPE_PLOT_CANVAS_H

#include <stddef.h>

#include "tippe/plot.h"

typedef struct tippe_plot tippe_plot; /* opaque: one open figure */

/* Opens a figure of width x height (pixels for PNG, points for SVG and PDF)
 * with a white background. TIPPE_EINPUT if the extension is not supported or
 * the directory cannot be written (the message names the file),
 * TIPPE_ECOMPUTE if another figure is still open. */
int tippe_plot_open(const char *path, int width, int height, tippe_plot **out, tippe_error *err);

/* Finishes the figure and renames it into place; frees p. On failure nothing
 * is left on disk. */
int tippe_plot_close(tippe_plot *p, tippe_error *err);

/* Abandons the figure: removes the temporary file, frees p. NULL is allowed. */
void tippe_plot_abort(tippe_plot *p);

/* Places the next panel: the viewport in normalised page coordinates
 * (0..1 from the left and from the bottom) and its world window. */
void tippe_plot_panel(double vx0, double vx1, double vy0, double vy1, double xmin, double xmax,
                      double ymin, double ymax);

/* Draws the frame of the current panel with ticks, numeric labels (never in
 * the "x10^n" form, so that the numbers read as they are), axis labels and a
 * title; any label may be NULL. */
void tippe_plot_axes(const char *xlabel, const char *ylabel, const char *title);

/* The same with numbers on the x axis only (rows of bars, whose y means nothing). */
void tippe_plot_axes_x(const char *xlabel, const char *title);

/* Dashed vertical and horizontal grid lines at the major ticks. */
void tippe_plot_grid(void);

enum { TIPPE_PLOT_SOLID = 1, TIPPE_PLOT_DASHED = 3, TIPPE_PLOT_DOTTED = 2 };

void tippe_plot_line(int n, const double *x, const double *y, unsigned rgb, double width,
                     int style);
void tippe_plot_polygon(int n, const double *x, const double *y, unsigned rgb, double alpha);
/* rgb (0xRRGGBB) blended over white with weight a in [0, 1]: an opaque pale
 * shade, so that touching fills show no seams where a translucent one would. */
unsigned tippe_plot_pale(unsigned rgb, double a);
void tippe_plot_rect(double x0, double x1, double y0, double y1, unsigned rgb, double alpha);
/* Hatches the rectangle with diagonal lines (for "not reachable" regions). */
void tippe_plot_hatch(double x0, double x1, double y0, double y1, unsigned rgb);
/* A marker (PLplot symbol code, e.g. 17 dot, 4 circle) at each point. */
void tippe_plot_points(int n, const double *x, const double *y, int symbol, double scale,
                       unsigned rgb);
/* Text at (x, y): angle in degrees, just = 0 left, 0.5 centred, 1 right;
 * scale multiplies the default character height. */
void tippe_plot_text(double x, double y, double angle_deg, double just, double scale,
                     unsigned rgb, const char *text);
/* Text in the margin of the current panel (PLplot plmtex sides "t", "b", "l",
 * "r", "lv", "rv"), disp in character heights from the edge, pos 0..1 along it. */
void tippe_plot_margin_text(const char *side, double disp, double pos, double just,
                            double scale, unsigned rgb, const char *text);
/* An arrow from (x0, y0) to (x1, y1), head size in character heights. */
void tippe_plot_arrow(double x0, double y0, double x1, double y1, unsigned rgb, double width);

typedef enum { TIPPE_PLOT_KEY_LINE, TIPPE_PLOT_KEY_BOX, TIPPE_PLOT_KEY_HATCH } tippe_plot_key_kind;
typedef struct {
    tippe_plot_key_kind kind;
    const char *text;
    unsigned rgb;
    double alpha; /* boxes */
    double width; /* lines */
    int style;    /* lines: TIPPE_PLOT_SOLID, ... */
} tippe_plot_key;

/* A legend inside the current panel at the given corner ("tr", "tl", "br",
 * "bl") or to its right, between the panel and the page's edge ("outside"),
 * with n_columns columns, on a white box so that it stays readable over shading. */
void tippe_plot_legend(const tippe_plot_key *keys, int n, const char *where, int n_columns,
                       double text_scale);

/* A title centred at the top of the page (above all panels). */
void tippe_plot_page_title(const char *text, double scale);

/* Copies s into buf (size bytes) with PLplot's escape character doubled and
 * markup characters replaced, so that it draws literally. Returns buf. */
char *tippe_plot_escape(const char *s, char *buf, size_t size);

#endif
