/* A film of one launch (see tippe/animate.h): plan at the verdict level,
 * sample the trajectory at exact times, draw and encode. */
#include "tippe/animate.h"

#include <cairo.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Film after the verdict, as a share of the time to reach it: enough to see
 * the settled state for about a second of a default film. */
#define HOLD_SHARE 0.1
/* The contact path drawn behind the ball: this many seconds of film. */
#define TRACE_FILM_S 2.5
/* Samples per turn at the launch's rotation rate, for the contact path (as
 * `tippe simulate` samples its plots). */
#define SAMPLES_PER_TURN 16
/* Points of the contact path at most (the last ones): ~125 turns, more than
 * enough to see its shape, few enough to stroke in a millisecond. */
#define TRACE_POINTS 2000
/* Points of the theta inset at most (it is a few hundred pixels wide). */
#define INSET_POINTS 2000

static int check_options(const tippe_animate_options *o, tippe_error *err)
{
    if (!isfinite(o->speed) || o->speed < 0)
        return tippe_error_set(err, TIPPE_EINPUT,
                               "speed %g: expected a positive number of model seconds per "
                               "second of film (or 0 for the whole launch in %g s)",
                               o->speed, o->film_s);
    if (!(o->film_s >= 0.5 && o->film_s <= 1200))
        return tippe_error_set(err, TIPPE_EINPUT, "film length %g s: expected 0.5 .. 1200 s",
                               o->film_s);
    if (o->fps < 1 || o->fps > 120)
        return tippe_error_set(err, TIPPE_EINPUT, "frame rate %d: expected 1 .. 120 fps", o->fps);
    if (o->width_px < 64 || o->width_px > 3840 || o->height_px < 64 || o->height_px > 2160 ||
        o->width_px % 2 || o->height_px % 2)
        return tippe_error_set(err, TIPPE_EINPUT,
                               "film size %dx%d: expected even widths 64 .. 3840 and heights "
                               "64 .. 2160 pixels",
                               o->width_px, o->height_px);
    return TIPPE_OK;
}

/* The launch's rotation rate plus the pendulum rate, rad/s: the fastest
 * motion the contact path must resolve. */
static double rotation_rate(const tippe_animate_launch *l)
{
    const tippe_dynamics_initial *ic = &l->initial;
    return sqrt(ic->theta_dot * ic->theta_dot + ic->spin * ic->spin +
                pow(ic->phi_dot * sin(ic->theta), 2)) +
           sqrt(l->model.g / l->model.top.R);
}

/* ---- plan: how long the launch takes to look settled ------------------------ */

/* A tilt within this of its final value looks still in a picture a few hundred
 * pixels high (a twentieth of a radian, 3 degrees). */
#define SETTLED_RAD 0.05
/* A film shows at least this many turns at the launch's rotation rate, so that
 * a launch that starts where it ends (a no_tip) is still seen spinning. */
#define MIN_TURNS 20
/* Samples of the planning run: enough to see when theta stops moving visibly. */
#define PLAN_SAMPLES 4096

typedef struct {
    double *t, *theta;
    int n, cap;
} track;

static int keep_theta(const tippe_dynamics_sample *s, void *ctx)
{
    track *k = ctx;
    if (k->n == k->cap) {
        int cap = k->cap ? 2 * k->cap : 1024;
        double *t = realloc(k->t, (size_t)cap * sizeof *t);
        if (t)
            k->t = t;
        double *th = t ? realloc(k->theta, (size_t)cap * sizeof *th) : NULL;
        if (!th)
            return 1;
        k->theta = th;
        k->cap = cap;
    }
    k->t[k->n] = s->t;
    k->theta[k->n++] = s->theta;
    return 0;
}

/* The first sampled time after which theta stays within SETTLED_RAD of
 * target, or NAN if it has not by the last sample. */
static double settled_time(const track *k, double target)
{
    int j = k->n;
    while (j > 0 && fabs(k->theta[j - 1] - target) < SETTLED_RAD)
        j--;
    return j < k->n ? k->t[j] : NAN;
}

/* The launch to t_end at the trajectory level, sampled coarsely: its verdict
 * (proved, often before the top has finished moving, docs/dynamics.md) and the
 * time it comes to look still at the proved end state. The film shows a tenth
 * more than the later of the two. */
static int plan(const tippe_animate_launch *l, tippe_film *f, tippe_error *err)
{
    tippe_dynamics_options o;
    tippe_dynamics_options_default(&o);
    o.level = TIPPE_LEVEL_TRAJECTORY;
    o.t_end = l->t_end;
    o.accuracy = l->accuracy;
    o.sample_dt = l->t_end / PLAN_SAMPLES;
    o.run_to_t_end = 1;
    track k = {NULL, NULL, 0, 0};
    o.on_sample = keep_theta;
    o.sample_ctx = &k;
    tippe_dynamics_result r;
    int rc = tippe_dynamics_run(&l->model, &l->initial, &o, &r, err);
    f->planned_verdict = r.verdict;
    f->planned_t_verdict = r.t_verdict;
    f->t_settled = NAN;
    if (!rc) {
        switch (r.verdict) {
        case TIPPE_VERDICT_NO_TIP:
        case TIPPE_VERDICT_TIP:
        case TIPPE_VERDICT_HANG:
            f->t_settled = settled_time(&k, r.theta_final_rad);
            f->t_show = isnan(f->t_settled)
                            ? r.last.t
                            : fmin(r.last.t, (1 + HOLD_SHARE) * fmax(f->t_settled, r.t_verdict));
            break;
        case TIPPE_VERDICT_LOST_CONTACT:
            f->t_show = r.t_verdict; /* the model ends there */
            break;
        default:
            f->t_show = r.last.t;
            break;
        }
        if (r.verdict != TIPPE_VERDICT_LOST_CONTACT)
            f->t_show = fmin(r.last.t, fmax(f->t_show, MIN_TURNS * 2 * M_PI / rotation_rate(l)));
    }
    free(k.t);
    free(k.theta);
    return rc;
}

/* ---- compute: samples at exact times ----------------------------------------- */

typedef struct {
    tippe_film *f;
    int cap;
} keep_ctx;

static int keep(const tippe_dynamics_sample *s, void *vctx)
{
    keep_ctx *k = vctx;
    tippe_film *f = k->f;
    if (f->n_samples == k->cap) {
        if (k->cap >= TIPPE_ANIMATE_MAX_SAMPLES + 2)
            return 2;
        int cap = k->cap ? 2 * k->cap : 1024;
        tippe_dynamics_sample *p = realloc(f->samples, (size_t)cap * sizeof *p);
        if (!p)
            return 1;
        f->samples = p;
        k->cap = cap;
    }
    f->samples[f->n_samples++] = *s;
    return 0;
}

/* Integrates to t_end with a sample every sample_dt (t_end a multiple of it). */
static int sample_run(const tippe_animate_launch *l, double t_end, double sample_dt,
                      tippe_film *f, tippe_error *err)
{
    tippe_dynamics_options o;
    tippe_dynamics_options_default(&o);
    o.level = TIPPE_LEVEL_TRAJECTORY;
    o.t_end = t_end;
    o.accuracy = l->accuracy;
    o.sample_dt = sample_dt;
    o.run_to_t_end = 1; /* the film goes on after the verdict */
    keep_ctx k = {f, 0};
    o.on_sample = keep;
    o.sample_ctx = &k;
    int rc = tippe_dynamics_run(&l->model, &l->initial, &o, &f->result, err);
    if (rc == TIPPE_OK && f->n_samples < 1)
        rc = tippe_error_set(err, TIPPE_ECOMPUTE, "the launch gave no state to draw");
    return rc;
}

static int start(const tippe_animate_launch *launch, const tippe_animate_options *opt,
                 tippe_film *f, tippe_error *err)
{
    memset(f, 0, sizeof *f);
    f->launch = *launch;
    f->opt = *opt;
    int rc = check_options(opt, err);
    if (!rc && !(launch->t_end > 0))
        rc = tippe_error_set(err, TIPPE_EINPUT, "t_end %g s: expected a positive time",
                             launch->t_end);
    if (!rc)
        rc = plan(launch, f, err);
    if (!rc && !(f->t_show > 0))
        rc = tippe_error_set(err, TIPPE_EINPUT,
                             "nothing to film: the launch ends at t = 0 (%s)",
                             tippe_verdict_name(f->planned_verdict));
    return rc;
}

int tippe_film_make(const tippe_animate_launch *launch, const tippe_animate_options *opt,
                    tippe_film *f, tippe_error *err)
{
    int rc = start(launch, opt, f, err);
    if (rc)
        return rc;
    if (opt->speed > 0) {
        f->frame_dt = opt->speed / opt->fps;
        const double n = floor(f->t_show / f->frame_dt + 1e-9) + 1;
        if (n > TIPPE_ANIMATE_MAX_FRAMES)
            return tippe_error_set(err, TIPPE_EINPUT,
                                   "speed %g: the launch's %.4g s would take %.0f frames (%.0f s "
                                   "of film); at most %d: choose a speed of at least %.3g",
                                   opt->speed, f->t_show, n, n / opt->fps,
                                   TIPPE_ANIMATE_MAX_FRAMES,
                                   f->t_show * opt->fps / (TIPPE_ANIMATE_MAX_FRAMES - 1));
        f->n_frames = n < 2 ? 2 : (int)n;
        if (n < 2) /* shorter than a frame: show its start and end */
            f->frame_dt = f->t_show;
    } else {
        f->n_frames = (int)lround(opt->film_s * opt->fps);
        if (f->n_frames < 2)
            f->n_frames = 2;
        f->frame_dt = f->t_show / (f->n_frames - 1);
    }
    f->speed = f->frame_dt * opt->fps;
    const double dt_path = 2 * M_PI / (SAMPLES_PER_TURN * rotation_rate(launch));
    double m = ceil(f->frame_dt / dt_path - 1e-9);
    if (m * f->n_frames > TIPPE_ANIMATE_MAX_SAMPLES)
        m = floor((double)TIPPE_ANIMATE_MAX_SAMPLES / f->n_frames);
    f->samples_per_frame = m < 1 ? 1 : (int)m;
    const double sample_dt = f->frame_dt / f->samples_per_frame;
    /* The last frame is sample (n_frames - 1) m, at this time exactly. */
    const double t_last = (double)((long)(f->n_frames - 1) * f->samples_per_frame) * sample_dt;
    return sample_run(launch, t_last, sample_dt, f, err);
}

int tippe_film_make_still(const tippe_animate_launch *launch, const tippe_animate_options *opt,
                          double t_s, tippe_film *f, tippe_error *err)
{
    /* before start(), which integrates the launch (f is freeable either way) */
    memset(f, 0, sizeof *f);
    if (!(t_s >= 0 && t_s <= launch->t_end))
        return tippe_error_set(err, TIPPE_EINPUT, "time %g s: expected 0 .. t_end = %g s", t_s,
                               launch->t_end);
    int rc = start(launch, opt, f, err);
    if (rc)
        return rc;
    if (f->planned_verdict == TIPPE_VERDICT_LOST_CONTACT && t_s > f->t_show)
        return tippe_error_set(err, TIPPE_EINPUT,
                               "time %g s: the top leaves the table at t = %.6g s, where the "
                               "model ends",
                               t_s, f->t_show);
    /* The film's time scale, so that the contact path is as long as in the film. */
    f->n_frames = 1;
    f->speed = opt->speed > 0 ? opt->speed : f->t_show / opt->film_s;
    f->frame_dt = f->speed / opt->fps;
    if (t_s == 0) {
        /* The launch itself: no integration. */
        tippe_dynamics_sample s;
        if ((rc = tippe_dynamics_evaluate(&launch->model, &launch->initial, &s, err)) != 0)
            return rc;
        keep_ctx k = {f, 0};
        if (keep(&s, &k))
            return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
        /* what is proved at the launch itself (often the verdict, docs/dynamics.md):
         * a run whose t_end is the next double after 0 takes at most one tiny step */
        tippe_dynamics_options o;
        tippe_dynamics_options_default(&o);
        o.t_end = DBL_MIN;
        o.accuracy = launch->accuracy;
        if ((rc = tippe_dynamics_run(&launch->model, &launch->initial, &o, &f->result, err)))
            return rc;
        if (f->result.t_verdict <= DBL_MIN) /* not proved at once: report t = 0, not 2e-308 */
            f->result.t_verdict = f->result.last.t = f->result.final.t = 0.0;
        f->samples_per_frame = 1;
        return TIPPE_OK;
    }
    const double dt_path = 2 * M_PI / (SAMPLES_PER_TURN * rotation_rate(launch));
    double m = fmin(ceil(t_s / dt_path), TIPPE_ANIMATE_MAX_SAMPLES);
    f->samples_per_frame = m < 1 ? 1 : (int)m;
    return sample_run(launch, t_s, t_s / f->samples_per_frame, f, err);
}

void tippe_film_free(tippe_film *f)
{
    free(f->samples);
    f->samples = NULL;
    f->n_samples = 0;
}

/* ---- draw ---------------------------------------------------------------------- */

typedef struct {
    const tippe_film *f;
    tippe_scene scene;
    double *trace_xy;           /* contact point of every sample */
    double *plot_t, *plot_theta; /* every plot_step-th sample */
    int plot_step, n_plot;
    tippe_error *err;
} painter;

static int painter_init(painter *p, const tippe_film *f, tippe_error *err)
{
    memset(p, 0, sizeof *p);
    p->f = f;
    p->err = err;
    const tippe_animate_launch *l = &f->launch;
    int rc = tippe_scene_init(&p->scene, l->model.top.R, l->model.top.eps, f->opt.width_px,
                              f->opt.height_px, f->samples, f->n_samples, err);
    if (rc)
        return rc;
    p->scene.weight_offset_m = l->weight_offset_m;
    p->scene.weight_radius_m = l->weight_radius_m;
    p->plot_step = (f->n_samples + INSET_POINTS - 1) / INSET_POINTS;
    if (p->plot_step < 1)
        p->plot_step = 1;
    p->n_plot = (f->n_samples + p->plot_step - 1) / p->plot_step;
    p->trace_xy = malloc(2 * (size_t)f->n_samples * sizeof *p->trace_xy);
    p->plot_t = malloc((size_t)p->n_plot * sizeof *p->plot_t);
    p->plot_theta = malloc((size_t)p->n_plot * sizeof *p->plot_theta);
    if (!p->trace_xy || !p->plot_t || !p->plot_theta)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory for the film's paths");
    for (int i = 0; i < f->n_samples; i++)
        tippe_scene_contact(&p->scene, &f->samples[i], &p->trace_xy[2 * i],
                            &p->trace_xy[2 * i + 1]);
    for (int j = 0; j < p->n_plot; j++) {
        p->plot_t[j] = f->samples[j * p->plot_step].t;
        p->plot_theta[j] = f->samples[j * p->plot_step].theta;
    }
    return TIPPE_OK;
}

static void painter_free(painter *p)
{
    free(p->trace_xy);
    free(p->plot_t);
    free(p->plot_theta);
}

/* The verdict and how it was proved, in one or two lines of the picture. */
static int verdict_lines(const tippe_film *f, char *l1, char *l2, size_t size)
{
    const tippe_dynamics_result *r = &f->result;
    const double deg = 180 / M_PI;
    if (r->how == TIPPE_DECIDED_ENERGY_CONE) {
        snprintf(l1, size, "proved at t = %.4g s: no_tip, within %.1f\xc2\xb0 of upright for ever",
                 r->t_verdict, r->theta_hi_rad * deg);
        snprintf(l2, size, "by the energy alone (the rest state is not proved)");
        return 2;
    }
    if (r->how == TIPPE_DECIDED_OBSERVED) {
        /* the patch law: what the run saw at its end, never a proof */
        snprintf(l1, size, "observed at t = %.4g s: %s, \xce\xb8 = %.1f\xc2\xb0 (NOT proved)",
                 r->t_verdict, tippe_verdict_name(r->verdict), r->theta_final_rad * deg);
        snprintf(l2, size, "%s", r->unproved_reason ? r->unproved_reason : "not proved");
        return 2;
    }
    switch (r->verdict) {
    case TIPPE_VERDICT_NO_TIP:
    case TIPPE_VERDICT_TIP:
    case TIPPE_VERDICT_HANG:
        if (r->verdict == TIPPE_VERDICT_HANG)
            snprintf(l1, size, "verdict: hang at \xce\xb8 = %.1f\xc2\xb0, proved at t = %.4g s",
                     r->theta_final_rad * deg, r->t_verdict);
        else
            snprintf(l1, size, "verdict: %s, proved at t = %.4g s",
                     r->verdict == TIPPE_VERDICT_TIP ? "tip" : "no tip", r->t_verdict);
        if (r->how == TIPPE_DECIDED_ROLLING)
            snprintf(l2, size, "rolls without slipping for ever, \xce\xb8 in %.1f\xc2\xb0 .. %.1f\xc2\xb0",
                     r->theta_lo_rad * deg, r->theta_hi_rad * deg);
        else if (isfinite(r->barrier_gap_J))
            snprintf(l2, size, "energy below barrier by %.2g J (margin %.2g J)",
                     r->barrier_gap_J, r->margin_J);
        else
            snprintf(l2, size, "trapped: the well has no barrier (margin %.2g J)", r->margin_J);
        return 2;
    case TIPPE_VERDICT_LOST_CONTACT:
        snprintf(l1, size, "verdict: leaves the table at t = %.4g s (model ends)", r->t_verdict);
        return 1;
    case TIPPE_VERDICT_BOUNDED:
        snprintf(l1, size, "verdict: bounded, \xce\xb8 stays in %.1f\xc2\xb0 .. %.1f\xc2\xb0%s",
                 r->theta_lo_rad * deg, r->theta_hi_rad * deg,
                 r->how == TIPPE_DECIDED_ROLLING ? " (rolling)" : "");
        return 1;
    default:
        snprintf(l1, size, "verdict: not proved by t = %.4g s", r->last.t);
        return 1;
    }
}

/* Draws sample idx (a frame) with its text, path and inset. */
static int paint(painter *p, int idx, int last_frame, unsigned char *pixels, int stride)
{
    const tippe_film *f = p->f;
    const tippe_dynamics_sample *s = &f->samples[idx];
    const double deg = 180 / M_PI;
    char l0[96], l1[128], l2[128], l3[160], l4[160];
    snprintf(l0, sizeof l0, "t = %.4g s   (1 s of film = %.3g s)", s->t, f->speed);
    snprintf(l1, sizeof l1, "\xce\xb8 = %.1f\xc2\xb0   spin n = %.4g rad/s (%.3g rev/s)",
             s->theta * deg, s->spin, s->spin / (2 * M_PI));
    const double J0 = f->samples[0].J;
    if (J0 != 0)
        snprintf(l2, sizeof l2, "Jellett drift %.1e", fabs(s->J - J0) / fabs(J0));
    else
        snprintf(l2, sizeof l2, "Jellett J - J0 = %.2e kg m\xc2\xb3/s", s->J - J0);
    const char *lines[5] = {l0, l1, l2, l3, l4};
    int n_lines = 3;
    const tippe_dynamics_result *r = &f->result;
    const int decided = r->verdict != TIPPE_VERDICT_UNDECIDED;
    if ((decided && s->t >= r->t_verdict) || last_frame)
        n_lines += verdict_lines(f, l3, l4, sizeof l3);
    /* The contact path of the last TRACE_FILM_S seconds of film (at most
     * TRACE_POINTS points). */
    int first = idx;
    while (first > 0 && idx - first < TRACE_POINTS &&
           f->samples[first - 1].t >= s->t - TRACE_FILM_S * f->speed)
        first--;
    tippe_scene_overlay ov = {
        .trace_xy = p->trace_xy + 2 * first,
        .n_trace = idx - first + 1,
        .lines = lines,
        .n_lines = n_lines,
        .title = f->launch.title,
        .plot_t = p->plot_t,
        .plot_theta = p->plot_theta,
        .n_plot = idx / p->plot_step + 1,
        .plot_t_end = fmax(f->t_show, s->t),
        .plot_t_mark = decided && s->t >= r->t_verdict ? r->t_verdict : NAN,
    };
    return tippe_scene_render(&p->scene, s, &ov, pixels, stride, p->err);
}

static int draw_frame(int k, unsigned char *pixels, int stride, void *ctx)
{
    painter *p = ctx;
    const tippe_film *f = p->f;
    /* A run that ended early (lift-off) holds its last state. */
    long idx = (long)k * f->samples_per_frame;
    if (idx > f->n_samples - 1)
        idx = f->n_samples - 1;
    return paint(p, (int)idx, k == f->n_frames - 1, pixels, stride);
}

static tippe_encode_options encode_options(const tippe_film *f, tippe_film_format format)
{
    tippe_encode_options eo = {.format = format,
                               .width_px = f->opt.width_px,
                               .height_px = f->opt.height_px,
                               .fps = f->opt.fps,
                               .n_frames = f->n_frames};
    return eo;
}

long tippe_film_work(const tippe_film *f, tippe_film_format format)
{
    tippe_encode_options eo = encode_options(f, format);
    return tippe_encode_draw_count(&eo);
}

int tippe_film_write(const tippe_film *f, tippe_film_format format, FILE *out,
                     tippe_progress *prog, tippe_error *err)
{
    painter p;
    int rc = painter_init(&p, f, err);
    if (!rc) {
        tippe_encode_options eo = encode_options(f, format);
        tippe_error draw_err = {0};
        p.err = &draw_err;
        rc = tippe_encode_film(out, &eo, draw_frame, &p, prog, err);
        if (rc && draw_err.code)
            *err = draw_err; /* the drawing's own message says more */
    }
    painter_free(&p);
    return rc;
}

static cairo_status_t png_write(void *closure, const unsigned char *data, unsigned int length)
{
    return fwrite(data, 1, length, closure) == length ? CAIRO_STATUS_SUCCESS
                                                        : CAIRO_STATUS_WRITE_ERROR;
}

int tippe_film_write_png(const tippe_film *f, FILE *out, tippe_error *err)
{
    painter p;
    int rc = painter_init(&p, f, err);
    cairo_surface_t *surf = NULL;
    if (!rc) {
        surf = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, f->opt.width_px, f->opt.height_px);
        if (cairo_surface_status(surf) != CAIRO_STATUS_SUCCESS)
            rc = tippe_error_set(err, TIPPE_ECOMPUTE, "cannot make a %dx%d picture",
                                 f->opt.width_px, f->opt.height_px);
    }
    if (!rc) {
        cairo_surface_flush(surf);
        rc = paint(&p, f->n_samples - 1, 0, cairo_image_surface_get_data(surf),
                   cairo_image_surface_get_stride(surf));
        cairo_surface_mark_dirty(surf);
    }
    if (!rc && cairo_surface_write_to_png_stream(surf, png_write, out) != CAIRO_STATUS_SUCCESS)
        rc = tippe_error_set(err, TIPPE_ECOMPUTE, "writing the PNG failed");
    if (surf)
        cairo_surface_destroy(surf);
    painter_free(&p);
    return rc;
}
