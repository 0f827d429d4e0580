/* tippe/scene.h: one picture of the top on its table, drawn with cairo.
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
 * The pose comes from a trajectory-level sample of tippe/dynamics.h: the
 * rotation Rz(phi) Ry(theta) Rz(psi) (docs/dynamics.md), the centre of mass at
 * (x, y) on the table and the sphere's centre R above the table.
 *
 * Pixels are cairo's ARGB32 (tippe/encode.h): the public interface keeps cairo
 * to itself. Reentrant: nothing global. */
#ifndef TIPPE_SCENE_H
#define TIPPE_SCENE_H

#include "tippe/dynamics.h"
#include "tippe/error.h"

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

#endif
