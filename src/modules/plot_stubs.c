/* Stubs of the plots (the files of src/plot/, PLplot) for the tippe command: see module.h. */
#include "module.h"
#include "tippe/plot.h"
#include "tippe/launch.h"
#include "tippe/optimise.h"
#include "tippe/scenario.h"
#include "tippe/sweep.h"

static tippe_module plot =
    TIPPE_MODULE("plot", "PLplot: apt-get install libplplot-dev plplot-driver-cairo");

int tippe_module_plot_ready(tippe_error *err)
{
    return tippe_module_function(&plot, "tippe_plot_sim", err) ? TIPPE_OK : TIPPE_ECOMPUTE;
}

int tippe_launch_plot_map(const char *file, const tippe_launch_map *map, const tippe_design *d,
                          double g, const char *title, tippe_error *err)
{
    TIPPE_MODULE_CALL(&plot, tippe_launch_plot_map, err, file, map, d, g, title, err);
}

int tippe_plot_sim(const char *path, const tippe_scenario *sc, const tippe_dynamics_result *res,
                   const tippe_dynamics_sample *samples, int n_samples, tippe_error *err)
{
    TIPPE_MODULE_CALL(&plot, tippe_plot_sim, err, path, sc, res, samples, n_samples, err);
}

int tippe_plot_sim_laws(const char *path, const char *title, int n_laws,
                        const char *const *labels, const tippe_dynamics_samples *runs,
                        double t_window_s, tippe_error *err)
{
    TIPPE_MODULE_CALL(&plot, tippe_plot_sim_laws, err, path, title, n_laws, labels, runs,
                      t_window_s, err);
}

int tippe_sweep_plot_zones(const char *file, const tippe_sweep_path *path,
                           const tippe_sweep_result *r, const char *title, tippe_error *err)
{
    TIPPE_MODULE_CALL(&plot, tippe_sweep_plot_zones, err, file, path, r, title, err);
}

int tippe_sweep_plot_zones_banded(const char *file, const tippe_sweep_path *path,
                                  const tippe_sweep_result *r, const tippe_sweep_bands_result *b,
                                  const char *title, tippe_error *err)
{
    TIPPE_MODULE_CALL(&plot, tippe_sweep_plot_zones_banded, err, file, path, r, b, title, err);
}

int tippe_sweep_plot_phase(const char *file, const tippe_sweep_path *path,
                           const tippe_sweep_result *r, const char *title, tippe_error *err)
{
    TIPPE_MODULE_CALL(&plot, tippe_sweep_plot_phase, err, file, path, r, title, err);
}

int tippe_sweep_plot_vary(const char *file, const tippe_sweep_vary_result *v, const char *field,
                          const char *title, tippe_error *err)
{
    TIPPE_MODULE_CALL(&plot, tippe_sweep_plot_vary, err, file, v, field, title, err);
}

int tippe_sweep_plot_compare(const char *file, const tippe_sweep_result *r,
                             const char *const *labels, int n, const char *title,
                             tippe_error *err)
{
    TIPPE_MODULE_CALL(&plot, tippe_sweep_plot_compare, err, file, r, labels, n, title, err);
}

int tippe_optimise_plot(const char *file, const tippe_optimise_spec *s, const tippe_optimise_result *r,
                   tippe_error *err)
{
    TIPPE_MODULE_CALL(&plot, tippe_optimise_plot, err, file, s, r, err);
}
