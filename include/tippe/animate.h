/* tippe/animate.h: films of a launch: the scene, the frames, the encoder.
 *
 * Contents:
 * - the encoder: a film from frames, with FFmpeg's libraries (tippe_encode_*,
 *   src/animate/encode.c);
 * - the scene: one picture of the top on its table, drawn with cairo (tippe_scene_*,
 *   src/animate/scene.c);
 * - the film of a launch, what `tippe animate` writes (tippe_animate_*, tippe_film_*;
 *   src/animate/animate.c, animate_setup.c).
 */
#ifndef TIPPE_ANIMATE_H
#define TIPPE_ANIMATE_H

#include <stdio.h>

#include "tippe/base.h"
#include "tippe/launch.h"
#include "tippe/design.h"
#include "tippe/sweep.h"

/* ---- the encoder ---- */
/* Encode: a film from frames drawn one at a time, with FFmpeg's libraries.
 *
 * The caller draws frames into a 32-bit pixel buffer in cairo's ARGB32 layout
 * (one native-endian 32-bit word per pixel, alpha in the top byte, opaque);
 * the encoder converts and compresses them:
 *   MP4   H.264 (libx264, crf 23, tune animation), yuv420p, one thread;
 *   WebM  VP9 (libvpx-vp9, crf 33, cpu-used 8), yuv420p, one thread;
 *   GIF   one 256-colour palette for the whole film, chosen by libavfilter's
 *         palettegen from every few frames, applied by paletteuse with ordered
 *         (Bayer) dithering; unchanged pixels are left transparent between
 *         frames, so that still parts of the picture cost nothing.
 * Width and height must be even (yuv420p halves the chroma planes).
 *
 * The film goes to an open stream (a tippe_report_file's temporary, so that a
 * failed film leaves nothing behind). MP4 is finished by seeking back to write
 * its index; on a stream that cannot seek (a pipe) it is written fragmented. */

typedef enum { TIPPE_FILM_MP4, TIPPE_FILM_WEBM, TIPPE_FILM_GIF } tippe_film_format;

/* The format named by path's extension (.mp4, .webm, .gif, any case): 1 and
 * *format set, or 0 if the extension is none of them. */
int tippe_film_format_of(const char *path, tippe_film_format *format);

/* "H.264 MP4", "VP9 WebM", "GIF". */
const char *tippe_film_format_name(tippe_film_format format);

/* Draws frame i (0-based) into pixels (height rows of stride bytes). A nonzero
 * return stops the film (TIPPE_ECOMPUTE, or the code itself if it is TIPPE_EINPUT). */
typedef int (*tippe_frame_fn)(int i, unsigned char *pixels, int stride, void *ctx);

typedef struct {
    tippe_film_format format;
    int width_px, height_px; /* even, 16 .. 8192 */
    int fps;                 /* frames per second of film, 1 .. 240 */
    int n_frames;            /* >= 1 */
} tippe_encode_options;

/* Encodes n_frames frames asked of draw in order 0 .. n_frames - 1 (a GIF first
 * asks every k-th frame once more for its palette, k chosen so that about 60
 * frames are looked at). prog (may be NULL) counts frames drawn. TIPPE_EINPUT
 * for bad options, TIPPE_ECOMPUTE if the codec is missing or a write fails. */
/* How many times tippe_encode_film() will call draw (n_frames, plus the GIF's
 * palette frames): the total of a progress bar. */
long tippe_encode_draw_count(const tippe_encode_options *o);

int tippe_encode_film(FILE *out, const tippe_encode_options *o, tippe_frame_fn draw, void *ctx,
                      tippe_progress *prog, tippe_error *err);

/* ---- the scene ---- */
/* Scene: one picture of the top on its table, drawn with cairo.
 *
 * The ball is a transparent shell seen from a camera above the table (an
 * orthographic view, elevation 28 degrees by default, looking along the lab's
 * +y axis, so that the lab x axis runs left to right). On the shell: a red dot
 * at the pole on the centre of mass's side (the pole that touches the table at
 * theta = 0), a small blue dot at the other pole, a blue stripe along one
 * meridian (it turns with the spin psi) and the equator; inside: the symmetry
 * axis, the moving weight (if known) and the centre of mass (the quartered
 * disc). Under the ball: its shadow and the recent path of the contact point.
 * Parts on the far side of the shell are drawn faded, seen through it.
 *
 * The pose comes from a trajectory-level sample of tippe/physics.h: the
 * rotation Rz(phi) Ry(theta) Rz(psi) (docs/dynamics.md), the centre of mass at
 * (x, y) on the table and the sphere's centre R above the table.
 *
 * Pixels are cairo's ARGB32 (tippe/animate.h): the public interface keeps cairo
 * to itself. Reentrant: nothing global. */

typedef struct {
    double R, eps; /* m: sphere radius, centre of mass below the centre at theta = 0 */
    /* The moving weight, drawn as a ball of its volume: centre on the axis at
     * weight_offset_m from the sphere's centre toward the red pole (negative:
     * toward the other pole), radius weight_radius_m (0: not drawn). */
    double weight_offset_m, weight_radius_m;
    int width_px, height_px;
    double elevation_rad;  /* camera above the table, 0 < e <= pi/2 */
    double px_per_m;       /* scale of the picture */
    double view_x_m, view_y_m; /* picture centre in the camera plane (right, up), m */
} tippe_scene;

/* A scene for a top of radius R_m, eccentricity eps_m (no weight), with the
 * default camera, framed so that the ball and the contact path of every sample
 * (n >= 1, trajectory level) stay in the picture: the ball is at most 0.25 of
 * the height in radius. TIPPE_EINPUT for sizes outside 16 .. 8192 pixels or a
 * radius that is not positive. */
int tippe_scene_init(tippe_scene *sc, double R_m, double eps_m, int width_px, int height_px,
                     const tippe_dynamics_sample *samples, int n, tippe_error *err);

/* Where a lab point (m) appears in the picture, pixels from the top left. */
void tippe_scene_project(const tippe_scene *sc, const double p_m[3], double *x_px,
                         double *y_px);

/* The lab position of the sphere's centre and of a point given in the body
 * frame (m, z along the axis k) for the pose of s. */
void tippe_scene_centre(const tippe_scene *sc, const tippe_dynamics_sample *s, double c_m[3]);
void tippe_scene_body_to_lab(const tippe_scene *sc, const tippe_dynamics_sample *s,
                             const double b_m[3], double p_m[3]);

/* What is drawn over the ball: the contact path, the head-up text and a small
 * plot of theta against time. Any part may be empty (NULL or 0). */
typedef struct {
    const double *trace_xy; /* contact points on the table, (x, y) pairs in m, oldest first */
    int n_trace;
    const char *const *lines; /* head-up text, top left */
    int n_lines;
    const char *title;        /* bottom left, shortened to fit */
    const double *plot_t, *plot_theta; /* s, rad: theta so far, for the inset */
    int n_plot;
    double plot_t_end;        /* s, right end of the inset's time axis (> 0 to draw it) */
    double plot_t_mark;       /* s, a dashed mark (the verdict), NAN for none */
} tippe_scene_overlay;

/* Draws the state s (trajectory level: phi, psi, x, y finite) with ov (may be
 * NULL) into pixels (height_px rows of stride bytes, cairo ARGB32, stride a
 * multiple of 4 and at least 4 width_px). TIPPE_EINPUT for a state that is not
 * finite, TIPPE_ECOMPUTE if cairo fails. */
int tippe_scene_render(const tippe_scene *sc, const tippe_dynamics_sample *s,
                       const tippe_scene_overlay *ov, unsigned char *pixels, int stride,
                       tippe_error *err);

/* The contact point of the pose s on the table, m. */
void tippe_scene_contact(const tippe_scene *sc, const tippe_dynamics_sample *s, double *x_m,
                         double *y_m);

/* ---- the film of a launch ---- */
/* Animate: a film of one launch (what `tippe animate` writes).
 *
 * A film is made in three steps, each reading only what the one before made:
 *   1. plan:    the launch to its t_end, sampled coarsely (4096 samples), says
 *               when its verdict is proved and when theta comes for good
 *               within 0.05 rad (3 degrees: still, to the eye) of the proved
 *               end state; the film shows [0, t_show], t_show a tenth past the
 *               later of the two (the lift-off for lost_contact, t_end when
 *               nothing is proved), and maps model time to film time (speed:
 *               model seconds per film second);
 *   2. compute: the launch again at the trajectory level, sampled at exact
 *               times (the integrator lands on them, tippe/physics.h): every
 *               frame's time, and between frames often enough to draw the
 *               contact point's path (16 samples per turn at the launch's
 *               rotation rate). Frames therefore do not depend on step sizes;
 *   3. draw:    each frame from its sample (tippe/animate.h), encoded with
 *               tippe/animate.h, or one frame as a PNG.
 * The library never prints: a tippe_progress (may be NULL) counts frames. */

/* The launch to film. */
typedef struct {
    char title[256];                 /* shown at the bottom of the picture */
    tippe_dynamics_model model;
    tippe_dynamics_initial initial;
    double t_end;                    /* s, the launch's bound (as in a scenario) */
    tippe_dynamics_accuracy accuracy;
    /* The moving weight in the picture (tippe/animate.h); radius 0: none. */
    double weight_offset_m, weight_radius_m;
} tippe_animate_launch;

typedef struct {
    double speed;      /* model s per film s; <= 0: the whole launch in film_s */
    double film_s;     /* s of film for the whole launch when speed <= 0 */
    int fps;           /* frames per film second */
    int width_px, height_px;
} tippe_animate_options;

/* Defaults: speed 0 (the whole launch in film_s = 10 s), 30 fps, 640x480. */
void tippe_animate_options_default(tippe_animate_options *o);

/* Limits the options are checked against (TIPPE_EINPUT outside them). */
#define TIPPE_ANIMATE_MAX_FRAMES 36000 /* 20 min at 30 fps */
#define TIPPE_ANIMATE_MAX_SAMPLES 400000

typedef struct {
    tippe_animate_launch launch;
    tippe_animate_options opt;
    /* plan */
    tippe_verdict planned_verdict;  /* of the planning run */
    double planned_t_verdict;       /* s */
    double t_settled;               /* s, theta within 0.05 rad of its end for good (NAN: not
                                       by t_end, or no proved end state) */
    double t_show;                  /* s, model time of the last frame */
    double speed;                   /* model s per film s (as used) */
    double frame_dt;                /* s of model time between frames */
    int n_frames;
    int samples_per_frame;          /* trajectory samples per frame interval */
    /* compute */
    tippe_dynamics_result result;   /* of the trajectory-level run (to t_show) */
    tippe_dynamics_sample *samples; /* in time order; sample k * samples_per_frame is frame k */
    int n_samples;
} tippe_film;

/* Steps 1 and 2 for a film. TIPPE_EINPUT for bad options or a film longer
 * than TIPPE_ANIMATE_MAX_FRAMES; TIPPE_ECOMPUTE if the dynamics fail. Free
 * with tippe_film_free() (also after a failure). */
int tippe_film_make(const tippe_animate_launch *launch, const tippe_animate_options *opt,
                    tippe_film *film, tippe_error *err);

/* Steps 1 and 2 for one picture at model time t_s (0 <= t_s <= the launch's
 * end): samples up to t_s, the last one at t_s exactly. n_frames is 1. */
int tippe_film_make_still(const tippe_animate_launch *launch, const tippe_animate_options *opt,
                          double t_s, tippe_film *film, tippe_error *err);

void tippe_film_free(tippe_film *film);

/* Step 3: the film in the given format to out (see tippe/animate.h). */
int tippe_film_write(const tippe_film *film, tippe_film_format format, FILE *out,
                     tippe_progress *prog, tippe_error *err);

/* Frames drawn by tippe_film_write() in format: a progress bar's total. */
long tippe_film_work(const tippe_film *film, tippe_film_format format);

/* Step 3 for a still: its last frame as a PNG to out. */
int tippe_film_write_png(const tippe_film *film, FILE *out, tippe_error *err);

/* The moving weight of a design at z2_mm, as the scene draws it: its centre of
 * volume along the axis (from the sphere's centre toward the pole on the
 * centre of mass's side) and the radius of a ball of its volume; 0 and 0 if
 * the design has no moving part. */
void tippe_animate_design_weight(const tippe_design *d, double z2_mm, const tippe_top *top,
                                 double *offset_m, double *radius_m);

/* The launch tippe check integrates (tippe_sweep_check_run with options o) as a
 * film's launch: its model, initial state, t_end and accuracy, the design's
 * weight for the picture, and a title naming the design and Z2. */
int tippe_animate_check_launch(const tippe_sweep_check *c, const tippe_launch_options *o,
                               tippe_animate_launch *out);

#endif
