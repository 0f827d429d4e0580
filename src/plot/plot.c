/* Shared plotting helpers over PLplot's cairo drivers (see tippe/plot.h). */
#include "plot/canvas.h"
#include "tippe/base.h"

#include <math.h>
#include <plplot/plplot.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

struct tippe_plot {
    tippe_report_file file; /* the output, opened before drawing so that it is checked first */
    const char *device;     /* "pngcairo", ... */
    char *bytes;            /* PLplot draws into memory (open_memstream) ... */
    size_t n_bytes;         /* ... and tippe_plot_close() writes it out, every write checked */
    int width, height;
};

/* PLplot has one global state; these mirror it for the helpers. */
static tippe_plot *open_plot;
static double panel_vp[4], panel_win[4];
static char abort_msg[256];
/* Character height relative to PLplot's default, which is large on a
 * 1000-pixel cairo page; every helper's scale multiplies it. */
static const double char_base = 0.82;

/* cmap0 slots: 0 background, 1 frame and text, 2 the "current colour" used by
 * every drawing helper, LEGEND_SLOT.. one per legend entry. */
enum { SLOT_BG = 0, SLOT_FG = 1, SLOT_DRAW = 2, LEGEND_SLOT = 16, N_SLOTS = 64 };

static void on_plabort(PLCHAR_VECTOR msg)
{
    /* plabort() is PLplot's non-fatal error: remember it so that close fails. */
    if (!abort_msg[0])
        snprintf(abort_msg, sizeof abort_msg, "%s", msg ? msg : "PLplot error");
}

static void set_slot(int slot, unsigned rgb, double alpha)
{
    plscol0a(slot, (PLINT)((rgb >> 16) & 0xff), (PLINT)((rgb >> 8) & 0xff), (PLINT)(rgb & 0xff),
             alpha);
}

static void use_colour(unsigned rgb, double alpha)
{
    set_slot(SLOT_DRAW, rgb, alpha);
    plcol0(SLOT_DRAW);
}

int tippe_plot_open(const char *path, int width, int height, tippe_plot **out, tippe_error *err)
{
    *out = NULL;
    const char *dev = tippe_plot_device(path);
    if (!dev)
        return tippe_error_set(err, TIPPE_EINPUT,
                               "%s: unsupported plot format (use a .png, .svg or .pdf file name)",
                               path ? path : "(null)");
    if (open_plot)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "%s: another plot (%s) is still open", path,
                               open_plot->file.path);
    if (width < 100 || height < 100 || width > 20000 || height > 20000)
        return tippe_error_set(err, TIPPE_EINPUT, "%s: plot size %d x %d is out of range", path,
                               width, height);
    tippe_plot *p = calloc(1, sizeof *p);
    if (!p)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "%s: out of memory", path);
    int rc = tippe_report_open(&p->file, path, "the plot", err);
    if (rc) {
        free(p);
        return rc;
    }
    /* PLplot reports no write error and closes the stream itself in plend():
     * it gets a stream in memory, and the file is written by report.c, which
     * checks every write. */
    FILE *f = open_memstream(&p->bytes, &p->n_bytes);
    if (!f) {
        tippe_report_abort(&p->file);
        free(p);
        return tippe_error_set(err, TIPPE_ECOMPUTE, "%s: out of memory", path);
    }
    p->device = dev;
    p->width = width;
    p->height = height;
    abort_msg[0] = '\0';
    plsabort(on_plabort);
    plsdev(dev);
    plsfile(f); /* PLplot owns f from here and closes it in plend() */
    plspage(0.0, 0.0, width, height, 0, 0);
    plscmap0n(N_SLOTS);
    plscolbg(255, 255, 255);
    set_slot(SLOT_FG, 0x000000, 1.0);
    plinit();
    pladv(0);
    plschr(0.0, char_base);
    plcol0(SLOT_FG);
    open_plot = p;
    *out = p;
    return TIPPE_OK;
}

/* Whether the bytes end as a whole file of the device's format does: PNG's
 * IEND chunk, SVG's closing tag, PDF's %%EOF marker. A second check, beside
 * the checked writes, that the cairo driver finished its file. */
static int complete_file(const char *dev, const char *b, size_t n)
{
    static const char png_end[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', (char)0xae, 0x42, 0x60,
                                     (char)0x82};
    while (n > 0 && strcmp(dev, "pngcairo") && (b[n - 1] == '\n' || b[n - 1] == '\r' ||
                                                  b[n - 1] == ' '))
        n--; /* text formats may end in white space */
    if (!strcmp(dev, "pngcairo"))
        return n >= 8 + 12 && !memcmp(b, "\x89PNG", 4) && !memcmp(b + n - 12, png_end, 12);
    if (!strcmp(dev, "svgcairo"))
        return n >= 6 && !memcmp(b + n - 6, "</svg>", 6);
    return n >= 5 + 5 && !memcmp(b, "%PDF-", 5) && !memcmp(b + n - 5, "%%EOF", 5);
}

int tippe_plot_close(tippe_plot *p, tippe_error *err)
{
    if (!p)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "no plot to close");
    plend(); /* closes the memory stream: p->bytes, p->n_bytes are final */
    open_plot = NULL;
    int status = TIPPE_OK;
    if (abort_msg[0])
        status = tippe_error_set(err, TIPPE_ECOMPUTE, "%s: plotting failed: %s", p->file.path,
                                 abort_msg);
    else if (!p->bytes || !complete_file(p->device, p->bytes, p->n_bytes))
        status = tippe_error_set(err, TIPPE_ECOMPUTE,
                                 "%s: the plot came out incomplete (%zu bytes from the %s driver)",
                                 p->file.path, p->n_bytes, p->device);
    if (status == TIPPE_OK) {
        /* A short write is remembered by the stream; commit names its reason. */
        fwrite(p->bytes, 1, p->n_bytes, p->file.f);
        status = tippe_report_commit(&p->file, err);
    } else {
        tippe_report_abort(&p->file);
    }
    free(p->bytes);
    free(p);
    return status;
}

void tippe_plot_abort(tippe_plot *p)
{
    if (!p)
        return;
    plend();
    open_plot = NULL;
    tippe_report_abort(&p->file);
    free(p->bytes);
    free(p);
}

void tippe_plot_panel(double vx0, double vx1, double vy0, double vy1, double xmin, double xmax,
                      double ymin, double ymax)
{
    plvpor(vx0, vx1, vy0, vy1);
    plwind(xmin, xmax, ymin, ymax);
    panel_vp[0] = vx0, panel_vp[1] = vx1, panel_vp[2] = vy0, panel_vp[3] = vy1;
    panel_win[0] = xmin, panel_win[1] = xmax, panel_win[2] = ymin, panel_win[3] = ymax;
}

/* A 1-2-5 tick step giving about n ticks over span. */
static double nice_step(double span, double n)
{
    if (!(span > 0) || !isfinite(span))
        return 1.0;
    double raw = span / n;
    double p10 = pow(10.0, floor(log10(raw)));
    double m = raw / p10;
    return (m < 1.5 ? 1.0 : m < 3.5 ? 2.0 : m < 7.5 ? 5.0 : 10.0) * p10;
}

static void tick_label(PLINT axis, PLFLT value, char *label, PLINT length, PLPointer data)
{
    const double *steps = data;
    double step = axis == PL_X_AXIS ? steps[0] : steps[1];
    int decimals = (int)fmax(0.0, -floor(log10(step) + 1e-9));
    if (fabs(value) < 1e-9 * step)
        value = 0.0; /* no "-0.00" */
    snprintf(label, (size_t)length, "%.*f", decimals, value);
}

static double axis_steps[2];

/* Tick steps for the current panel: about one labelled tick per 90 pixels
 * across and 55 pixels up, so that numbers never run into each other. */
static void panel_steps(double steps[2])
{
    double w = open_plot ? open_plot->width : 1000, h = open_plot ? open_plot->height : 700;
    double nx = fmax(3.0, fmin(9.0, (panel_vp[1] - panel_vp[0]) * w / 90.0));
    double ny = fmax(3.0, fmin(10.0, (panel_vp[3] - panel_vp[2]) * h / 55.0));
    steps[0] = nice_step(panel_win[1] - panel_win[0], nx);
    steps[1] = nice_step(panel_win[3] - panel_win[2], ny);
}

void tippe_plot_axes_x(const char *xlabel, const char *title)
{
    panel_steps(axis_steps);
    plslabelfunc(tick_label, axis_steps);
    plcol0(SLOT_FG);
    plwidth(1.0);
    pllsty(1);
    plbox("bcnsto", axis_steps[0], 0, "bc", 0, 0);
    plslabelfunc(NULL, NULL);
    if (xlabel)
        plmtex("b", 3.0, 0.5, 0.5, xlabel);
    if (title)
        plmtex("t", 1.0, 0.5, 0.5, title);
}

void tippe_plot_axes(const char *xlabel, const char *ylabel, const char *title)
{
    panel_steps(axis_steps);
    plslabelfunc(tick_label, axis_steps);
    plcol0(SLOT_FG);
    plwidth(1.0);
    pllsty(1);
    plbox("bcnsto", axis_steps[0], 0, "bcnstvo", axis_steps[1], 0);
    plslabelfunc(NULL, NULL);
    if (xlabel)
        plmtex("b", 3.0, 0.5, 0.5, xlabel);
    if (ylabel) {
        /* Clear of the widest tick label (a digit is about 0.6 character heights). */
        size_t widest = 1;
        char buf[64];
        for (double t = ceil(panel_win[2] / axis_steps[1]) * axis_steps[1];
             t <= panel_win[3] + 1e-9 * axis_steps[1]; t += axis_steps[1]) {
            tick_label(PL_Y_AXIS, t, buf, (PLINT)sizeof buf, axis_steps);
            widest = strlen(buf) > widest ? strlen(buf) : widest;
        }
        plmtex("l", 1.6 + 0.62 * (double)widest, 0.5, 0.5, ylabel);
    }
    if (title)
        plmtex("t", 1.0, 0.5, 0.5, title);
}

void tippe_plot_grid(void)
{
    double steps[2];
    panel_steps(steps);
    use_colour(0xb0b0b0, 1.0);
    plwidth(0.5);
    pllsty(2);
    plbox("g", steps[0], 0, "g", steps[1], 0);
    pllsty(1);
    plwidth(1.0);
    plcol0(SLOT_FG);
}

void tippe_plot_line(int n, const double *x, const double *y, unsigned rgb, double width,
                     int style)
{
    if (n < 2)
        return;
    use_colour(rgb, 1.0);
    plwidth(width);
    pllsty(style);
    plline(n, x, y);
    pllsty(1);
    plwidth(1.0);
}

void tippe_plot_polygon(int n, const double *x, const double *y, unsigned rgb, double alpha)
{
    if (n < 3)
        return;
    use_colour(rgb, alpha);
    plpsty(0);
    plfill(n, x, y);
}

void tippe_plot_rect(double x0, double x1, double y0, double y1, unsigned rgb, double alpha)
{
    double x[4] = {x0, x1, x1, x0}, y[4] = {y0, y0, y1, y1};
    tippe_plot_polygon(4, x, y, rgb, alpha);
}

void tippe_plot_hatch(double x0, double x1, double y0, double y1, unsigned rgb)
{
    double x[4] = {x0, x1, x1, x0}, y[4] = {y0, y0, y1, y1};
    use_colour(rgb, 1.0);
    plwidth(0.6);
    plpsty(3); /* lines at 45 degrees */
    plfill(4, x, y);
    plpsty(0);
    plwidth(1.0);
}

void tippe_plot_points(int n, const double *x, const double *y, int symbol, double scale,
                       unsigned rgb)
{
    if (n < 1)
        return;
    use_colour(rgb, 1.0);
    plssym(0.0, scale);
    plpoin(n, x, y, symbol);
    plssym(0.0, 1.0);
}

/* World units per pixel along x and y in the current panel, so that angles and
 * arrow heads come out right whatever the axes' scales. */
static void world_per_px(double *wx, double *wy)
{
    tippe_plot *p = open_plot;
    double w = p ? p->width : 1.0, h = p ? p->height : 1.0;
    *wx = (panel_win[1] - panel_win[0]) / ((panel_vp[1] - panel_vp[0]) * w);
    *wy = (panel_win[3] - panel_win[2]) / ((panel_vp[3] - panel_vp[2]) * h);
}

void tippe_plot_text(double x, double y, double angle_deg, double just, double scale,
                     unsigned rgb, const char *text)
{
    double wx, wy;
    world_per_px(&wx, &wy);
    double a = angle_deg * M_PI / 180.0;
    use_colour(rgb, 1.0);
    plschr(0.0, char_base * scale);
    plptex(x, y, cos(a) * wx, sin(a) * wy, just, text);
    plschr(0.0, char_base);
    plcol0(SLOT_FG);
}

void tippe_plot_margin_text(const char *side, double disp, double pos, double just,
                            double scale, unsigned rgb, const char *text)
{
    use_colour(rgb, 1.0);
    plschr(0.0, char_base * scale);
    plmtex(side, disp, pos, just, text);
    plschr(0.0, char_base);
    plcol0(SLOT_FG);
}

void tippe_plot_arrow(double x0, double y0, double x1, double y1, unsigned rgb, double width)
{
    double wx, wy;
    world_per_px(&wx, &wy);
    /* Work in pixels, where the head's shape is not distorted by the axes. */
    double dx = (x1 - x0) / wx, dy = (y1 - y0) / wy, len = hypot(dx, dy);
    if (!(len > 0))
        return;
    double ux = dx / len, uy = dy / len;
    double head = 0.012 * (open_plot ? open_plot->width : 800);
    double bx = x1 / wx - ux * head, by = y1 / wy - uy * head;
    double hx[3] = {x1, (bx - uy * head * 0.45) * wx, (bx + uy * head * 0.45) * wx};
    double hy[3] = {y1, (by + ux * head * 0.45) * wy, (by - ux * head * 0.45) * wy};
    double lx[2] = {x0, bx * wx}, ly[2] = {y0, by * wy};
    tippe_plot_line(2, lx, ly, rgb, width, TIPPE_PLOT_SOLID);
    tippe_plot_polygon(3, hx, hy, rgb, 1.0);
}

void tippe_plot_legend(const tippe_plot_key *keys, int n, const char *where, int n_columns,
                       double text_scale)
{
    enum { MAX_KEYS = N_SLOTS - LEGEND_SLOT };
    if (n <= 0)
        return;
    if (n > MAX_KEYS)
        n = MAX_KEYS;
    PLINT opt[MAX_KEYS], text_col[MAX_KEYS], box_col[MAX_KEYS], box_pat[MAX_KEYS];
    PLINT line_col[MAX_KEYS], line_sty[MAX_KEYS];
    PLFLT box_scale[MAX_KEYS], box_lw[MAX_KEYS], line_w[MAX_KEYS];
    PLCHAR_VECTOR text[MAX_KEYS];
    for (int i = 0; i < n; i++) {
        int slot = LEGEND_SLOT + i;
        set_slot(slot, keys[i].rgb, keys[i].kind == TIPPE_PLOT_KEY_BOX ? keys[i].alpha : 1.0);
        opt[i] = keys[i].kind == TIPPE_PLOT_KEY_LINE ? PL_LEGEND_LINE : PL_LEGEND_COLOR_BOX;
        text_col[i] = SLOT_FG;
        text[i] = keys[i].text;
        box_col[i] = slot;
        box_pat[i] = keys[i].kind == TIPPE_PLOT_KEY_HATCH ? 3 : 0;
        box_scale[i] = 0.8;
        box_lw[i] = 0.6;
        line_col[i] = slot;
        line_sty[i] = keys[i].style > 0 ? keys[i].style : 1;
        line_w[i] = keys[i].width > 0 ? keys[i].width : 1.0;
    }
    /* "outside": a viewport of its own between the panel and the page's right
     * edge, so that the legend neither covers data nor leaves the page. */
    int outside = !strcmp(where, "outside");
    if (outside)
        plvpor(fmin(panel_vp[1] + 0.015, 0.98), 0.995, panel_vp[2], panel_vp[3]);
    PLINT pos = PL_POSITION_INSIDE | PL_POSITION_VIEWPORT;
    if (outside)
        pos |= PL_POSITION_TOP | PL_POSITION_LEFT;
    else
        pos |= (where[0] == 'b' ? PL_POSITION_BOTTOM : PL_POSITION_TOP) |
               (where[1] == 'l' ? PL_POSITION_LEFT : PL_POSITION_RIGHT);
    PLFLT lw, lh;
    int rows = (n + n_columns - 1) / n_columns;
    /* An outside legend wider than its strip (long keys on a narrow page) would
     * lose its right edge: it is painted over and drawn again with smaller text
     * until it fits (PLplot measures a legend only by drawing it). */
    for (int attempt = 0; attempt < 8; attempt++) {
        pllegend(&lw, &lh, PL_LEGEND_BACKGROUND | PL_LEGEND_BOUNDING_BOX, pos,
                 outside ? 0.0 : 0.015, outside ? 0.0 : 0.015, 0.06, SLOT_BG, SLOT_FG, 1, rows,
                 n_columns, n, opt, 0.8, text_scale, 1.8, 0.0, text_col, text, box_col, box_pat,
                 box_scale, box_lw, line_col, line_sty, line_w, NULL, NULL, NULL, NULL);
        if (!outside || lw <= 1.0)
            break;
        double x0 = fmin(panel_vp[1] + 0.015, 0.98);
        /* in page coordinates, the legend's frame line included */
        double h = panel_vp[3] - panel_vp[2];
        double y0 = panel_vp[3] - (lh + 0.01) * h, y1 = fmin(panel_vp[3] + 0.01, 1.0);
        plvpor(0.0, 1.0, 0.0, 1.0);
        plwind(0.0, 1.0, 0.0, 1.0);
        PLFLT ex[4] = {x0 - 0.002, 1.0, 1.0, x0 - 0.002}, ey[4] = {y0, y0, y1, y1};
        plcol0(SLOT_BG);
        plfill(4, ex, ey);
        plvpor(x0, 0.995, panel_vp[2], panel_vp[3]);
        text_scale *= 0.97 / lw;
    }
    if (outside)
        tippe_plot_panel(panel_vp[0], panel_vp[1], panel_vp[2], panel_vp[3], panel_win[0],
                         panel_win[1], panel_win[2], panel_win[3]);
    plcol0(SLOT_FG);
}

void tippe_plot_page_title(const char *text, double scale)
{
    double vp[4], win[4];
    memcpy(vp, panel_vp, sizeof vp);
    memcpy(win, panel_win, sizeof win);
    plvpor(0.0, 1.0, 0.0, 1.0);
    plwind(0.0, 1.0, 0.0, 1.0);
    plcol0(SLOT_FG);
    /* Shrink a long title to the page: PLplot's characters scale with the page
     * height; measured on 1800 x 1100 titles at scale 1, a character is 0.0123 of
     * the height wide on average and up to 0.0145 in titles full of capitals,
     * brackets and '_': 0.015. */
    double w = open_plot ? open_plot->width : 1200.0, h = open_plot ? open_plot->height : 900.0;
    double fit = 0.94 / (0.015 * (h / w) * (double)strlen(text));
    plschr(0.0, char_base * fmin(scale, fit));
    plptex(0.5, 0.955, 1.0, 0.0, 0.5, text);
    plschr(0.0, char_base);
    tippe_plot_panel(vp[0], vp[1], vp[2], vp[3], win[0], win[1], win[2], win[3]);
}

char *tippe_plot_escape(const char *s, char *buf, size_t size)
{
    size_t j = 0;
    if (size == 0)
        return buf;
    for (; s && *s && j + 2 < size; s++) {
        if (*s == '#') { /* PLplot's escape character: "##" draws one */
            buf[j++] = '#';
            buf[j++] = '#';
        } else if (*s == '<' || *s == '>' || *s == '&') {
            buf[j++] = '_'; /* the cairo driver passes text to Pango as markup */
        } else {
            buf[j++] = *s;
        }
    }
    buf[j] = '\0';
    return buf;
}

unsigned tippe_plot_pale(unsigned rgb, double a)
{
    unsigned out = 0;
    for (int s = 0; s <= 16; s += 8) {
        double c = (rgb >> s) & 0xff;
        out |= (unsigned)lround(255.0 * (1.0 - a) + c * a) << s;
    }
    return out;
}
