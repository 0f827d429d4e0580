/* tippe/plot.h: every figure tippe draws (PLplot, in the plot module), and the
 * formats it draws them in.
 *
 * Each figure is PNG, SVG or PDF by its file's extension and written atomically.
 * PLplot has one global state: call these from one thread. The command loads
 * PLplot only when it draws (src/modules/plot_stubs.c). */
#ifndef TIPPE_PLOT_H
#define TIPPE_PLOT_H

#include "tippe/base.h"
#include "tippe/optimise.h"
#include "tippe/launch.h"
#include "tippe/scenario.h"
#include "tippe/sweep.h"

/* "pngcairo", "svgcairo" or "pdfcairo" for a path ending in .png, .svg or .pdf
 * (any case); NULL for anything else. */
const char *tippe_plot_device(const char *path);

/* ---- zones (src/plot/plot_zones.c) ---- */
/* Plots (src/plot/plot_zones.c), PNG, SVG or PDF by the file's extension, written
 * atomically (src/plot/canvas.h). title may be NULL. TIPPE_EINPUT for a bad file
 * name or directory.
 *
 * The zone plot (the paper's Figures 7, 9, 11): A/C - 1 against Z2 with the
 * curves +eps/R, -eps/R, -(eps/R)^2 and the A/C - 1 where b = +1 and b = -1,
 * the zones shaded and labelled, the physical travel marked. */
int tippe_sweep_plot_zones(const char *file, const tippe_sweep_path *path,
                           const tippe_sweep_result *r, const char *title, tippe_error *err);
/* The phase diagram (the paper's Figure 2) in the (eps/R, A/C) plane, whole and
 * zoomed on the path, with the path drawn over it and labelled with Z2. */
int tippe_sweep_plot_phase(const char *file, const tippe_sweep_path *path,
                           const tippe_sweep_result *r, const char *title, tippe_error *err);
/* The zones of every step of a vary (one column per value of the field) with
 * the physical travel. */
int tippe_sweep_plot_vary(const char *file, const tippe_sweep_vary_result *v,
                          const char *field, const char *title, tippe_error *err);
/* The zones of several sweeps as horizontal bars, one per design (labels[i]),
 * the first on top, against Z2 (mm): tippe compare --plot. */
int tippe_sweep_plot_compare(const char *file, const tippe_sweep_result *r,
                             const char *const *labels, int n, const char *title,
                             tippe_error *err);
/* The zone plot (tippe_sweep_plot_zones) with each band shaded across it. */
int tippe_sweep_plot_zones_banded(const char *file, const tippe_sweep_path *path,
                                  const tippe_sweep_result *r, const tippe_sweep_bands_result *b,
                                  const char *title, tippe_error *err);

/* ---- launch maps (src/plot/plot_map.c) ---- */
/* The map as a heat map (src/plot/plot_map.c): each cell coloured by its dominant
 * outcome, paler the smaller that outcome's share, against Z2 (mm) and spin
 * (rev/s); the zone boundaries of the design's sweep as vertical lines with the
 * zones named along the top, and theory's spin thresholds n- and n* (eq 5.11,
 * section 7.1) as curves. PNG, SVG or PDF by the extension, written atomically.
 * PLplot has one global state: call from one thread. */
int tippe_launch_plot_map(const char *file, const tippe_launch_map *map, const tippe_design *d,
                          double g, const char *title, tippe_error *err);

/* ---- optimisation (src/plot/plot_optimise.c) ---- */
/* The plot (src/plot/plot_optimise.c; PNG, SVG or PDF by extension): the zones along
 * Z2 of the best design of each choice (the best ten when there are more),
 * with each group's width, and the convergence of the search (best score so
 * far against evaluations) for the same choices. */
int tippe_optimise_plot(const char *file, const tippe_optimise_spec *s, const tippe_optimise_result *r,
                   tippe_error *err);

/* ---- a simulated launch (src/plot/plot_sim.c) ---- */
/* The figure of a simulated scenario (src/plot/plot_sim.c): theta, spin and contact
 * speed against time in stacked panels, and the path in (phi_dot, theta, n)
 * space as in the paper's Figures 12 and 14, with the intermediate states of
 * eq 5.10 and theory's final states. PNG, SVG or PDF by the extension of path,
 * written atomically. samples are trajectory-level samples in time order.
 * PLplot has one global state: call from one thread. */
int tippe_plot_sim(const char *path, const tippe_scenario *sc, const tippe_dynamics_result *res,
                   const tippe_dynamics_sample *samples, int n_samples, tippe_error *err);

/* theta(t) of one launch under 1 to 4 friction laws, overlaid (tippe check
 * --friction A,B --plot; src/plot/plot_sim.c): above, the launch on a linear time
 * axis over [0, t_window_s] (<= 0: the whole run); below, the whole run on a
 * logarithmic one; one line per law (labels[k], runs[k]'s trajectory samples) and
 * theta = pi/2 dashed. PNG, SVG or PDF by the extension, written atomically. */
int tippe_plot_sim_laws(const char *path, const char *title, int n_laws,
                        const char *const *labels, const tippe_dynamics_samples *runs,
                        double t_window_s, tippe_error *err);

#endif
