/* tippe/animate.h: a film of one launch (what `tippe animate` writes).
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
 *               times (the integrator lands on them, tippe/dynamics.h): every
 *               frame's time, and between frames often enough to draw the
 *               contact point's path (16 samples per turn at the launch's
 *               rotation rate). Frames therefore do not depend on step sizes;
 *   3. draw:    each frame from its sample (tippe/scene.h), encoded with
 *               tippe/encode.h, or one frame as a PNG.
 * The library never prints: a tippe_progress (may be NULL) counts frames. */
#ifndef TIPPE_ANIMATE_H
#define TIPPE_ANIMATE_H

#include <stdio.h>

#include "tippe/design.h"
#include "tippe/dynamics.h"
#include "tippe/encode.h"
#include "tippe/error.h"
#include "tippe/progress.h"

/* The launch to film. */
typedef struct {
    char title[256];                 /* shown at the bottom of the picture */
    tippe_dynamics_model model;
    tippe_dynamics_initial initial;
    double t_end;                    /* s, the launch's bound (as in a scenario) */
    tippe_dynamics_accuracy accuracy;
    /* The moving weight in the picture (tippe/scene.h); radius 0: none. */
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

/* Step 3: the film in the given format to out (see tippe/encode.h). */
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

#endif
