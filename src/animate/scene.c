/* One picture of the top on its table (see tippe/animate.h), drawn with cairo. */
#include "tippe/animate.h"

#include <cairo.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* Camera elevation: low enough that a tilt of the axis reads as a tilt, high
 * enough to see the contact path on the table. */
#define DEFAULT_ELEVATION_RAD (28.0 * M_PI / 180.0)
/* Largest ball radius as a share of the picture height. */
#define BALL_MAX_SHARE 0.25
/* Angular radii of the pole dots on the shell, rad. */
#define RED_DOT_RAD 0.26
#define BLUE_DOT_RAD 0.10

typedef struct {
    double r, g, b;
} rgb;

static const rgb TABLE_NEAR = {0.86, 0.84, 0.80}, TABLE_FAR = {0.95, 0.94, 0.92},
                 GRID = {0.78, 0.76, 0.72}, TRACE = {0.05, 0.45, 0.35},
                 STRIPE = {0.10, 0.22, 0.62}, EQUATOR = {0.35, 0.50, 0.72},
                 RED = {0.86, 0.06, 0.06}, AXIS = {0.25, 0.25, 0.30}, INK = {0.12, 0.12, 0.14};

/* The camera and the pose of one picture. */
typedef struct {
    const tippe_scene *sc;
    double right[3], up[3], toward[3]; /* toward: from the scene to the camera */
    double M[3][3];                    /* body to lab: Rz(phi) Ry(theta) Rz(psi) */
    double c[3];                       /* sphere's centre, m */
    double r_px;                       /* ball radius on screen */
} view;

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void camera(double e, double right[3], double up[3], double toward[3])
{
    right[0] = 1, right[1] = 0, right[2] = 0;
    up[0] = 0, up[1] = sin(e), up[2] = cos(e);
    toward[0] = 0, toward[1] = -cos(e), toward[2] = sin(e);
}

/* The rotation of the Euler angles of docs/dynamics.md. */
static void rotation(double phi, double theta, double psi, double M[3][3])
{
    const double cf = cos(phi), sf = sin(phi), ct = cos(theta), st = sin(theta), cp = cos(psi),
                 sp = sin(psi);
    /* Rz(phi) Ry(theta) */
    const double A[3][3] = {{cf * ct, -sf, cf * st}, {sf * ct, cf, sf * st}, {-st, 0, ct}};
    for (int i = 0; i < 3; i++) {
        M[i][0] = A[i][0] * cp + A[i][1] * sp;
        M[i][1] = -A[i][0] * sp + A[i][1] * cp;
        M[i][2] = A[i][2];
    }
}

static void apply(const double M[3][3], const double b[3], double out[3])
{
    for (int i = 0; i < 3; i++)
        out[i] = M[i][0] * b[0] + M[i][1] * b[1] + M[i][2] * b[2];
}

void tippe_scene_centre(const tippe_scene *sc, const tippe_dynamics_sample *s, double c_m[3])
{
    /* k = (sin theta cos phi, sin theta sin phi, cos theta); the centre is
     * eps k from the centre of mass and R above the table (eq 3.10). */
    c_m[0] = s->x + sc->eps * sin(s->theta) * cos(s->phi);
    c_m[1] = s->y + sc->eps * sin(s->theta) * sin(s->phi);
    c_m[2] = sc->R;
}

void tippe_scene_body_to_lab(const tippe_scene *sc, const tippe_dynamics_sample *s,
                             const double b_m[3], double p_m[3])
{
    double M[3][3], c[3], d[3];
    rotation(s->phi, s->theta, s->psi, M);
    tippe_scene_centre(sc, s, c);
    apply(M, b_m, d);
    for (int i = 0; i < 3; i++)
        p_m[i] = c[i] + d[i];
}

void tippe_scene_contact(const tippe_scene *sc, const tippe_dynamics_sample *s, double *x_m,
                         double *y_m)
{
    double c[3];
    tippe_scene_centre(sc, s, c);
    *x_m = c[0];
    *y_m = c[1];
}

void tippe_scene_project(const tippe_scene *sc, const double p_m[3], double *x_px, double *y_px)
{
    double right[3], up[3], toward[3];
    camera(sc->elevation_rad, right, up, toward);
    *x_px = 0.5 * sc->width_px + sc->px_per_m * (dot3(p_m, right) - sc->view_x_m);
    *y_px = 0.5 * sc->height_px - sc->px_per_m * (dot3(p_m, up) - sc->view_y_m);
}

int tippe_scene_init(tippe_scene *sc, double R_m, double eps_m, int width_px, int height_px,
                     const tippe_dynamics_sample *samples, int n, tippe_error *err)
{
    if (width_px < 16 || width_px > 8192 || height_px < 16 || height_px > 8192)
        return tippe_error_set(err, TIPPE_EINPUT,
                               "picture size %dx%d: expected 16 .. 8192 pixels each way", width_px,
                               height_px);
    if (!(R_m > 0) || !isfinite(R_m) || !(eps_m >= 0) || !(eps_m < R_m))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "scene: radius %g m and eccentricity %g m: expected 0 <= eps < R",
                               R_m, eps_m);
    if (n < 1)
        return tippe_error_set(err, TIPPE_EINPUT, "scene: no state to frame");
    memset(sc, 0, sizeof *sc);
    sc->R = R_m;
    sc->eps = eps_m;
    sc->width_px = width_px;
    sc->height_px = height_px;
    sc->elevation_rad = DEFAULT_ELEVATION_RAD;
    double right[3], up[3], toward[3];
    camera(sc->elevation_rad, right, up, toward);
    /* Box, in the camera plane, of the ball's outline and the contact points. */
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int i = 0; i < n; i++) {
        double c[3], q[3];
        tippe_scene_centre(sc, &samples[i], c);
        q[0] = c[0], q[1] = c[1], q[2] = 0;
        const double cx = dot3(c, right), cy = dot3(c, up), qx = dot3(q, right),
                     qy = dot3(q, up);
        lo[0] = fmin(lo[0], fmin(cx - R_m, qx));
        hi[0] = fmax(hi[0], fmax(cx + R_m, qx));
        lo[1] = fmin(lo[1], fmin(cy - R_m, qy));
        hi[1] = fmax(hi[1], fmax(cy + R_m, qy));
    }
    if (!isfinite(lo[0]) || !isfinite(lo[1]) || !isfinite(hi[0]) || !isfinite(hi[1]))
        return tippe_error_set(err, TIPPE_EINPUT, "scene: a state to frame is not finite");
    /* Leave room for the head-up text above and the inset below. */
    const double s_ball = BALL_MAX_SHARE * height_px / R_m;
    const double s_w = 0.86 * width_px / (hi[0] - lo[0]);
    const double s_h = 0.56 * height_px / (hi[1] - lo[1]);
    sc->px_per_m = fmin(s_ball, fmin(s_w, s_h));
    sc->view_x_m = 0.5 * (lo[0] + hi[0]);
    /* A little below the middle: the text sits at the top. */
    sc->view_y_m = 0.5 * (lo[1] + hi[1]) + 0.10 * height_px / sc->px_per_m;
    return TIPPE_OK;
}

/* ---- drawing ----------------------------------------------------------------- */

static void set_rgb(cairo_t *cr, rgb c, double alpha)
{
    cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha);
}

static void to_screen(const view *v, const double p[3], double *x, double *y)
{
    tippe_scene_project(v->sc, p, x, y);
}

/* A body point (m from the centre) in the lab. */
static void body(const view *v, const double b[3], double p[3])
{
    double d[3];
    apply(v->M, b, d);
    for (int i = 0; i < 3; i++)
        p[i] = v->c[i] + d[i];
}

/* 1 if the surface point at body direction b (on the shell) faces the camera. */
static int faces_camera(const view *v, const double b[3])
{
    double d[3];
    apply(v->M, b, d);
    return dot3(d, v->toward) >= 0;
}

static void draw_table(cairo_t *cr, const view *v)
{
    const tippe_scene *sc = v->sc;
    cairo_pattern_t *bg = cairo_pattern_create_linear(0, 0, 0, sc->height_px);
    cairo_pattern_add_color_stop_rgb(bg, 0, TABLE_FAR.r, TABLE_FAR.g, TABLE_FAR.b);
    cairo_pattern_add_color_stop_rgb(bg, 1, TABLE_NEAR.r, TABLE_NEAR.g, TABLE_NEAR.b);
    cairo_set_source(cr, bg);
    cairo_paint(cr);
    cairo_pattern_destroy(bg);
    /* Rings on the table round the launch point, a round number of metres
     * apart near R: circles seen at a slant read as a level floor. */
    const double R = sc->R;
    double step = pow(10, floor(log10(R)));
    if (R / step >= 5)
        step *= 5;
    else if (R / step >= 2)
        step *= 2;
    const double s = sc->px_per_m, se = sin(sc->elevation_rad);
    const double origin[3] = {0, 0, 0};
    double ox, oy;
    to_screen(v, origin, &ox, &oy);
    const double reach = hypot(sc->width_px, sc->height_px / se) / s + fabs(ox) / s;
    set_rgb(cr, GRID, 1.0);
    cairo_set_line_width(cr, 1.0);
    for (int k = 1; k * step < reach && k < 400; k++) {
        cairo_save(cr);
        cairo_translate(cr, ox, oy);
        cairo_scale(cr, 1.0, se);
        cairo_new_sub_path(cr);
        cairo_arc(cr, 0, 0, k * step * s, 0, 2 * M_PI);
        cairo_restore(cr);
    }
    cairo_stroke(cr);
}

static void draw_shadow(cairo_t *cr, const view *v)
{
    double p[3] = {v->c[0], v->c[1], 0}, x, y;
    to_screen(v, p, &x, &y);
    cairo_save(cr);
    cairo_translate(cr, x, y);
    cairo_scale(cr, 1.0, sin(v->sc->elevation_rad));
    cairo_pattern_t *pat = cairo_pattern_create_radial(0, 0, 0, 0, 0, 1.05 * v->r_px);
    cairo_pattern_add_color_stop_rgba(pat, 0, 0, 0, 0, 0.30);
    cairo_pattern_add_color_stop_rgba(pat, 1, 0, 0, 0, 0);
    cairo_set_source(cr, pat);
    cairo_arc(cr, 0, 0, 1.05 * v->r_px, 0, 2 * M_PI);
    cairo_fill(cr);
    cairo_pattern_destroy(pat);
    cairo_restore(cr);
}

/* The contact path: the newest quarter dark, the rest pale. Two strokes, and
 * from frame to frame only the ends and the boundary move (a GIF stays small). */
static void draw_trace(cairo_t *cr, const view *v, const tippe_scene_overlay *ov)
{
    if (!ov || ov->n_trace < 2)
        return;
    cairo_set_line_width(cr, fmax(1.2, v->r_px / 70));
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    const int n = ov->n_trace, split = (3 * (n - 1)) / 4;
    const int from[2] = {0, split}, to[2] = {split, n - 1};
    const double alpha[2] = {0.35, 0.95};
    for (int b = 0; b < 2; b++) {
        if (to[b] <= from[b])
            continue;
        for (int i = from[b]; i <= to[b]; i++) {
            double p[3] = {ov->trace_xy[2 * i], ov->trace_xy[2 * i + 1], 0}, x, y;
            to_screen(v, p, &x, &y);
            if (i == from[b])
                cairo_move_to(cr, x, y);
            else
                cairo_line_to(cr, x, y);
        }
        set_rgb(cr, TRACE, alpha[b]);
        cairo_stroke(cr);
    }
}

/* A curve on the shell through body directions b[0..n-1] (unit vectors),
 * keeping only the segments on the near (front = 1) or far side. */
static void shell_curve(cairo_t *cr, const view *v, const double (*b)[3], int n, int front)
{
    const double R = v->sc->R;
    int pen = 0;
    for (int i = 0; i + 1 < n; i++) {
        double mid[3] = {b[i][0] + b[i + 1][0], b[i][1] + b[i + 1][1], b[i][2] + b[i + 1][2]};
        if (faces_camera(v, mid) != front) {
            pen = 0;
            continue;
        }
        for (int k = pen ? 1 : 0; k < 2; k++) {
            double q[3] = {R * b[i + k][0], R * b[i + k][1], R * b[i + k][2]}, p[3], x, y;
            body(v, q, p);
            to_screen(v, p, &x, &y);
            if (k == 0)
                cairo_move_to(cr, x, y);
            else
                cairo_line_to(cr, x, y);
        }
        pen = 1;
    }
    cairo_stroke(cr);
}

/* A round dot of angular radius a around the pole sign * e3; drawn on the side
 * its centre is on. */
static void pole_dot(cairo_t *cr, const view *v, double sign, double a, int front, rgb colour,
                     double alpha)
{
    const double pole[3] = {0, 0, sign};
    if (faces_camera(v, pole) != front)
        return;
    const double R = v->sc->R;
    enum { N = 40 };
    for (int j = 0; j < N; j++) {
        const double c = 2 * M_PI * j / N;
        double q[3] = {R * sin(a) * cos(c), R * sin(a) * sin(c), sign * R * cos(a)}, p[3], x, y;
        body(v, q, p);
        to_screen(v, p, &x, &y);
        if (j == 0)
            cairo_move_to(cr, x, y);
        else
            cairo_line_to(cr, x, y);
    }
    cairo_close_path(cr);
    set_rgb(cr, colour, alpha);
    cairo_fill(cr);
}

/* The markings of the shell on one side: stripe, equator, pole dots. */
static void draw_markings(cairo_t *cr, const view *v, int front)
{
    enum { N = 64 };
    double meridian[N + 1][3], equator[N + 1][3];
    for (int i = 0; i <= N; i++) {
        const double a = RED_DOT_RAD + (M_PI - RED_DOT_RAD - BLUE_DOT_RAD) * i / N,
                     c = 2 * M_PI * i / N;
        /* From the red dot (round -e3) to the blue one along the body's x side. */
        meridian[i][0] = sin(a), meridian[i][1] = 0, meridian[i][2] = -cos(a);
        equator[i][0] = cos(c), equator[i][1] = sin(c), equator[i][2] = 0;
    }
    const double fade = front ? 1.0 : 0.35;
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    cairo_set_line_width(cr, fmax(1.0, 0.025 * v->r_px));
    set_rgb(cr, EQUATOR, 0.9 * fade);
    shell_curve(cr, v, (const double (*)[3])equator, N + 1, front);
    cairo_set_line_width(cr, fmax(2.0, 0.07 * v->r_px));
    set_rgb(cr, STRIPE, 0.95 * fade);
    shell_curve(cr, v, (const double (*)[3])meridian, N + 1, front);
    pole_dot(cr, v, -1, RED_DOT_RAD, front, RED, front ? 1.0 : 0.75);
    pole_dot(cr, v, +1, BLUE_DOT_RAD, front, STRIPE, fade);
}

/* The centre of mass: the usual quartered disc. */
static void com_symbol(cairo_t *cr, double x, double y, double r)
{
    for (int q = 0; q < 4; q++) {
        cairo_move_to(cr, x, y);
        cairo_arc(cr, x, y, r, q * M_PI / 2, (q + 1) * M_PI / 2);
        cairo_close_path(cr);
        if (q % 2)
            cairo_set_source_rgb(cr, 1, 1, 1);
        else
            set_rgb(cr, INK, 1);
        cairo_fill(cr);
    }
    cairo_arc(cr, x, y, r, 0, 2 * M_PI);
    set_rgb(cr, INK, 1);
    cairo_set_line_width(cr, fmax(1.0, 0.18 * r));
    cairo_stroke(cr);
}

static void draw_inside(cairo_t *cr, const view *v)
{
    const tippe_scene *sc = v->sc;
    double top[3], bottom[3], tx, ty, bx, by;
    const double bt[3] = {0, 0, sc->R}, bb[3] = {0, 0, -sc->R};
    body(v, bt, top);
    body(v, bb, bottom);
    to_screen(v, top, &tx, &ty);
    to_screen(v, bottom, &bx, &by);
    const double dash[2] = {0.06 * v->r_px, 0.04 * v->r_px};
    cairo_set_dash(cr, dash, 2, 0);
    cairo_set_line_width(cr, fmax(1.0, 0.015 * v->r_px));
    set_rgb(cr, AXIS, 0.8);
    cairo_move_to(cr, tx, ty);
    cairo_line_to(cr, bx, by);
    cairo_stroke(cr);
    cairo_set_dash(cr, NULL, 0, 0);
    const double s = sc->px_per_m;
    if (sc->weight_radius_m > 0) {
        const double bw[3] = {0, 0, -sc->weight_offset_m};
        double p[3], x, y;
        body(v, bw, p);
        to_screen(v, p, &x, &y);
        const double r = s * sc->weight_radius_m;
        cairo_pattern_t *pat = cairo_pattern_create_radial(x - 0.35 * r, y - 0.4 * r, 0.1 * r, x, y, r);
        cairo_pattern_add_color_stop_rgb(pat, 0, 0.98, 0.88, 0.55);
        cairo_pattern_add_color_stop_rgb(pat, 1, 0.55, 0.40, 0.12);
        cairo_set_source(cr, pat);
        cairo_arc(cr, x, y, r, 0, 2 * M_PI);
        cairo_fill_preserve(cr);
        cairo_pattern_destroy(pat);
        cairo_set_source_rgb(cr, 0.35, 0.25, 0.08);
        cairo_set_line_width(cr, 1.0);
        cairo_stroke(cr);
    }
    const double bc[3] = {0, 0, -sc->eps};
    double p[3], x, y;
    body(v, bc, p);
    to_screen(v, p, &x, &y);
    com_symbol(cr, x, y, fmax(4.0, 0.07 * v->r_px));
}

/* The glass: one flat tint (so that a moving ball changes few pixels, and a
 * film stays small), a darker rim, and a small highlight from the upper left. */
static void draw_shell(cairo_t *cr, const view *v)
{
    double x, y;
    to_screen(v, v->c, &x, &y);
    const double r = v->r_px;
    cairo_arc(cr, x, y, r, 0, 2 * M_PI);
    cairo_set_source_rgba(cr, 0.70, 0.80, 0.95, 0.40);
    cairo_fill_preserve(cr);
    cairo_set_source_rgba(cr, 0.20, 0.32, 0.52, 0.9);
    cairo_set_line_width(cr, fmax(1.0, 0.012 * r));
    cairo_stroke(cr);
    cairo_arc(cr, x, y, 0.94 * r, 0, 2 * M_PI);
    cairo_set_source_rgba(cr, 0.45, 0.58, 0.80, 0.35);
    cairo_set_line_width(cr, 0.10 * r);
    cairo_stroke(cr);
    const double hx = x - 0.45 * r, hy = y - 0.5 * r, hr = 0.22 * r;
    cairo_pattern_t *pat = cairo_pattern_create_radial(hx, hy, 0, hx, hy, hr);
    cairo_pattern_add_color_stop_rgba(pat, 0, 1, 1, 1, 0.8);
    cairo_pattern_add_color_stop_rgba(pat, 1, 1, 1, 1, 0);
    cairo_set_source(cr, pat);
    cairo_arc(cr, hx, hy, hr, 0, 2 * M_PI);
    cairo_fill(cr);
    cairo_pattern_destroy(pat);
}

static double font_px(const tippe_scene *sc)
{
    return fmax(9.0, sc->height_px / 30.0);
}

static void draw_text_box(cairo_t *cr, const tippe_scene *sc, const tippe_scene_overlay *ov)
{
    if (!ov || ov->n_lines < 1)
        return;
    const double f = font_px(sc), pad = 0.5 * f, lh = 1.3 * f;
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, f);
    double w = 0;
    for (int i = 0; i < ov->n_lines; i++) {
        cairo_text_extents_t te;
        cairo_text_extents(cr, ov->lines[i], &te);
        w = fmax(w, te.x_advance);
    }
    cairo_rectangle(cr, pad, pad, w + 2 * pad, ov->n_lines * lh + pad);
    cairo_set_source_rgba(cr, 1, 1, 1, 0.75);
    cairo_fill(cr);
    set_rgb(cr, INK, 1);
    for (int i = 0; i < ov->n_lines; i++) {
        cairo_move_to(cr, 2 * pad, pad + (i + 1) * lh - 0.2 * f);
        cairo_show_text(cr, ov->lines[i]);
    }
}

static void draw_title(cairo_t *cr, const tippe_scene *sc, const tippe_scene_overlay *ov,
                       double right_px)
{
    if (!ov || !ov->title || !ov->title[0])
        return;
    const double f = 0.8 * font_px(sc);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_ITALIC, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, f);
    char buf[512];
    snprintf(buf, sizeof buf, "%s", ov->title);
    const double room = right_px - 1.5 * f;
    size_t len = strlen(buf);
    cairo_text_extents_t te;
    cairo_text_extents(cr, buf, &te);
    while (len > 4 && te.x_advance > room) {
        /* Cut at a character boundary (UTF-8 continuation bytes are 10xxxxxx). */
        do
            len--;
        while (len > 4 && ((unsigned char)buf[len] & 0xC0) == 0x80);
        memcpy(buf + len, "...", 4);
        cairo_text_extents(cr, buf, &te);
    }
    set_rgb(cr, INK, 0.85);
    cairo_move_to(cr, 0.75 * f, sc->height_px - 0.7 * f);
    cairo_show_text(cr, buf);
}

/* theta (0 at the bottom, pi at the top) against time, bottom right. */
static void draw_inset(cairo_t *cr, const tippe_scene *sc, const tippe_scene_overlay *ov,
                       double *left_px)
{
    *left_px = sc->width_px;
    if (!ov || !(ov->plot_t_end > 0))
        return;
    const double f = fmax(8.0, 0.72 * font_px(sc));
    const double w = 0.34 * sc->width_px, h = 0.2 * sc->height_px, m = 0.6 * f;
    const double x0 = sc->width_px - w - m, y0 = sc->height_px - h - m;
    *left_px = x0;
    cairo_rectangle(cr, x0, y0, w, h);
    cairo_set_source_rgba(cr, 1, 1, 1, 0.8);
    cairo_fill(cr);
    /* plot area inside the labels */
    const double px0 = x0 + 3.2 * f, px1 = x0 + w - 0.6 * f, py0 = y0 + 2.0 * f,
                 py1 = y0 + h - 0.6 * f;
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, f);
    set_rgb(cr, INK, 1);
    cairo_move_to(cr, x0 + 0.4 * f, y0 + 1.1 * f);
    cairo_show_text(cr, "\xce\xb8 (0\xc2\xb0: red pole down)");
    static const char *const ticks[] = {"0\xc2\xb0", "90\xc2\xb0", "180\xc2\xb0"};
    cairo_set_line_width(cr, 1.0);
    for (int i = 0; i < 3; i++) {
        const double y = py1 - (py1 - py0) * i / 2.0;
        cairo_set_source_rgba(cr, 0.6, 0.6, 0.6, 1);
        cairo_move_to(cr, px0, y);
        cairo_line_to(cr, px1, y);
        cairo_stroke(cr);
        set_rgb(cr, INK, 1);
        cairo_move_to(cr, x0 + 0.4 * f, y + 0.35 * f);
        cairo_show_text(cr, ticks[i]);
    }
    const double sx = (px1 - px0) / ov->plot_t_end, sy = (py1 - py0) / M_PI;
    if (isfinite(ov->plot_t_mark) && ov->plot_t_mark <= ov->plot_t_end) {
        const double d[2] = {3, 3};
        cairo_set_dash(cr, d, 2, 0);
        set_rgb(cr, RED, 0.8);
        cairo_move_to(cr, px0 + sx * ov->plot_t_mark, py0);
        cairo_line_to(cr, px0 + sx * ov->plot_t_mark, py1);
        cairo_stroke(cr);
        cairo_set_dash(cr, NULL, 0, 0);
    }
    if (ov->n_plot > 0) {
        set_rgb(cr, STRIPE, 1);
        cairo_set_line_width(cr, fmax(1.2, 0.15 * f));
        for (int i = 0; i < ov->n_plot; i++) {
            const double x = px0 + sx * fmin(ov->plot_t[i], ov->plot_t_end);
            const double y = py1 - sy * ov->plot_theta[i];
            if (i == 0)
                cairo_move_to(cr, x, y);
            else
                cairo_line_to(cr, x, y);
        }
        cairo_stroke(cr);
        const int k = ov->n_plot - 1;
        cairo_arc(cr, px0 + sx * fmin(ov->plot_t[k], ov->plot_t_end),
                  py1 - sy * ov->plot_theta[k], fmax(2.0, 0.25 * f), 0, 2 * M_PI);
        set_rgb(cr, RED, 1);
        cairo_fill(cr);
    }
}

int tippe_scene_render(const tippe_scene *sc, const tippe_dynamics_sample *s,
                       const tippe_scene_overlay *ov, unsigned char *pixels, int stride,
                       tippe_error *err)
{
    if (!isfinite(s->theta) || !isfinite(s->phi) || !isfinite(s->psi) || !isfinite(s->x) ||
        !isfinite(s->y))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "scene: the state at t = %g s has no finite pose (trajectory "
                               "level needed)", s->t);
    cairo_surface_t *surf = cairo_image_surface_create_for_data(
        pixels, CAIRO_FORMAT_ARGB32, sc->width_px, sc->height_px, stride);
    cairo_t *cr = cairo_create(surf);
    view v = {.sc = sc};
    camera(sc->elevation_rad, v.right, v.up, v.toward);
    rotation(s->phi, s->theta, s->psi, v.M);
    tippe_scene_centre(sc, s, v.c);
    v.r_px = sc->px_per_m * sc->R;

    draw_table(cr, &v);
    draw_shadow(cr, &v);
    draw_trace(cr, &v, ov);
    draw_markings(cr, &v, 0);
    draw_inside(cr, &v);
    draw_shell(cr, &v);
    draw_markings(cr, &v, 1);
    draw_text_box(cr, sc, ov);
    double inset_left;
    draw_inset(cr, sc, ov, &inset_left);
    draw_title(cr, sc, ov, inset_left);

    cairo_status_t st = cairo_status(cr);
    cairo_destroy(cr);
    cairo_surface_flush(surf);
    if (st == CAIRO_STATUS_SUCCESS)
        st = cairo_surface_status(surf);
    cairo_surface_destroy(surf);
    if (st != CAIRO_STATUS_SUCCESS)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "drawing the picture: %s",
                               cairo_status_to_string(st));
    return TIPPE_OK;
}
