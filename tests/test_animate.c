/* tippe/animate.h and tippe/animate.h: the picture shows the state it is given,
 * and a film's frames are states at exact frame times. */
#include "check.h"

#include "tippe/animate.h"
#include "tippe/scenario.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

enum { W = 320, H = 240 };

/* The top of the paper's section 7.2 films (R = 1.5 cm, eps = R/2). */
static const double R = 0.015, EPS = 0.0075;

/* Centroid of the red pixels (red exceeds green and blue by more than 35 of
 * 255: the dot seen directly is ~200 above, seen faded through the shell ~60;
 * nothing else in a picture without text is red) inside the ball's outline. */
static int red_centroid(const uint32_t *px, double cx, double cy, double r, double *x,
                        double *y)
{
    double sx = 0, sy = 0;
    int n = 0;
    for (int j = 0; j < H; j++)
        for (int i = 0; i < W; i++) {
            const uint32_t p = px[j * W + i];
            const int red = (p >> 16) & 0xff, green = (p >> 8) & 0xff, blue = p & 0xff;
            if (hypot(i + 0.5 - cx, j + 0.5 - cy) > 1.05 * r)
                continue;
            if (red - (green > blue ? green : blue) > 35) {
                sx += i + 0.5;
                sy += j + 0.5;
                n++;
            }
        }
    if (n) {
        *x = sx / n;
        *y = sy / n;
    }
    return n;
}

/* The red dot marks the pole on the centre of mass's side: at theta = 0 it is
 * at the bottom of the ball, at pi/2 at the side the axis leans away from, at
 * pi at the top. Checked from the pixels, against the outline's centre. */
static void test_pole_dot(void)
{
    static const struct {
        double theta, phi;
        const char *where;
    } cases[] = {
        {0.0, 0.0, "bottom"},
        /* phi = 30 deg turns the dot towards the camera (at phi = 0 it would
         * sit exactly on the outline, seen edge-on). */
        {M_PI / 2, M_PI / 6, "left side"},
        {M_PI, 0.0, "top"},
    };
    uint32_t *px = malloc(sizeof(uint32_t) * W * H);
    for (int k = 0; k < 3; k++) {
        tippe_dynamics_sample s;
        memset(&s, 0, sizeof s);
        s.theta = cases[k].theta;
        s.phi = cases[k].phi;
        s.psi = 0.7;
        tippe_scene sc;
        tippe_error err;
        CHECK(tippe_scene_init(&sc, R, EPS, W, H, &s, 1, &err) == TIPPE_OK, "%s", err.msg);
        CHECK(tippe_scene_render(&sc, &s, NULL, (unsigned char *)px, 4 * W, &err) == TIPPE_OK,
              "%s", err.msg);
        double c[3], cx, cy, x = 0, y = 0;
        tippe_scene_centre(&sc, &s, c);
        tippe_scene_project(&sc, c, &cx, &cy);
        const double r = sc.px_per_m * R;
        const int n = red_centroid(px, cx, cy, r, &x, &y);
        /* The dot (0.26 rad) covers ~1.7% of the disc, foreshortened at most 3x. */
        CHECK(n > 0.003 * M_PI * r * r, "%s: only %d red pixels", cases[k].where, n);
        const double dx = (x - cx) / r, dy = (y - cy) / r; /* screen y points down */
        if (k == 0)
            CHECK(dy > 0.6 && fabs(dx) < 0.15, "bottom: dot at (%.3f, %.3f) r", dx, dy);
        else if (k == 1)
            CHECK(dx < -0.6 && fabs(dy) < 0.35, "side: dot at (%.3f, %.3f) r", dx, dy);
        else
            CHECK(dy < -0.6 && fabs(dx) < 0.15, "top: dot at (%.3f, %.3f) r", dx, dy);
        /* And where the body-to-lab map puts the pole, within 0.1 r: the dot's
         * centroid lies off its centre by the cap's bulge, < 0.03 r. */
        const double pole_b[3] = {0, 0, -R};
        double pole[3], ex, ey;
        tippe_scene_body_to_lab(&sc, &s, pole_b, pole);
        tippe_scene_project(&sc, pole, &ex, &ey);
        CHECK(hypot(x - ex, y - ey) < 0.1 * r, "%s: dot at (%.1f, %.1f), pole at (%.1f, %.1f)",
              cases[k].where, x, y, ex, ey);
    }
    free(px);
}

/* A state that is not a pose is refused, not drawn. */
static void test_bad_state(void)
{
    tippe_dynamics_sample s;
    memset(&s, 0, sizeof s);
    tippe_scene sc;
    tippe_error err;
    CHECK(tippe_scene_init(&sc, R, EPS, W, H, &s, 1, &err) == TIPPE_OK, "%s", err.msg);
    s.phi = NAN; /* verdict level: no angles */
    unsigned char *px = malloc(4 * W * H);
    CHECK(tippe_scene_render(&sc, &s, NULL, px, 4 * W, &err) == TIPPE_EINPUT, "NaN pose drawn");
    free(px);
    CHECK(tippe_scene_init(&sc, R, R, W, H, &s, 1, &err) == TIPPE_EINPUT, "eps = R accepted");
}

/* Frames are samples at exactly k * frame_dt, whatever the integrator's steps:
 * two accuracies (different step sequences) give the same frame times, and
 * states that agree to the coarser one's accuracy. */
static void test_frame_times(void)
{
    tippe_scenario sc;
    tippe_error err;
    const char *over[] = {"t_end=6"};
    if (tippe_scenario_load("designs/scenarios/film-IIb-flip.json", over, 1, &sc, &err)) {
        CHECK(0, "%s", err.msg);
        return;
    }
    tippe_animate_launch l;
    memset(&l, 0, sizeof l);
    l.model = sc.model;
    l.initial = sc.initial;
    l.t_end = sc.t_end;
    tippe_animate_options o;
    tippe_animate_options_default(&o);
    o.speed = 1.0; /* 1 model s per film s, 10 fps: 61 frames over 6 s */
    o.fps = 10;
    o.width_px = 160;
    o.height_px = 120;
    tippe_film f[2];
    const char *presets[2] = {"fast", "precise"};
    for (int i = 0; i < 2; i++) {
        tippe_dynamics_accuracy_preset(presets[i], &l.accuracy, &err);
        CHECK(tippe_film_make(&l, &o, &f[i], &err) == TIPPE_OK, "%s: %s", presets[i], err.msg);
    }
    /* Undecided at t_end = 6 s (the flip settles at 15 s): the film shows it all. */
    CHECK(f[0].n_frames == 61 && f[1].n_frames == 61, "frames %d and %d, want 61",
          f[0].n_frames, f[1].n_frames);
    double worst_theta = 0;
    int exact = 1;
    for (int k = 0; k < f[0].n_frames && k < f[1].n_frames; k++) {
        const tippe_dynamics_sample *a = &f[0].samples[k * f[0].samples_per_frame],
                                    *b = &f[1].samples[k * f[1].samples_per_frame];
        /* The integrator is asked to land on (k m) * (frame_dt / m); 4 ulp. */
        if (fabs(a->t - k * 0.1) > 1e-15 * 4 * 6 || a->t != b->t)
            exact = 0;
        worst_theta = fmax(worst_theta, fabs(a->theta - b->theta));
    }
    CHECK(exact, "frame times are not k * 0.1 s in both runs");
    /* docs/performance.md: "fast" errs by up to ~7e-2 rad on the flip (rkck 1e-6; rk8pd
     * 1e-6, the preset now, by 5e-3): 0.1 rad bounds either. */
    CHECK(worst_theta < 0.1, "theta at frames differs by %.3g rad between presets", worst_theta);
    CHECK(f[0].samples_per_frame >= 1 && f[0].n_samples >= f[0].n_frames, "%d samples",
          f[0].n_samples);
    tippe_film_free(&f[0]);
    tippe_film_free(&f[1]);
}

int main(void)
{
    test_pole_dot();
    test_bad_state();
    test_frame_times();
    return check_summary("test_animate");
}
