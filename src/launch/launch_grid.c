/* A map's grid (tippe map; tippe/launch.h, "a map's grid"): the Z2 and spin values,
 * the top and the holes' openings of every cell, the launch records of the plain run
 * and of the patch law's radius reruns, and their tallies. The front end runs the
 * plan (on its MPI ranks) and reports; the grid is the library's. */
#include "tippe/launch.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void tippe_launch_grid_free(tippe_launch_grid *g)
{
    free(g->z2_mm);
    free(g->spin_rev_s);
    free(g->cell_spin_rad_s);
    free(g->tops);
    free(g->cell_tops);
    free(g->cells);
    free(g->rec);
    free(g->model_invalid);
    free(g->rec_radius[0]);
    free(g->rec_radius[2]);
    free(g->cell_changed);
    free(g->cell_caps);
    memset(g, 0, sizeof *g);
}

static int no_memory(tippe_error *err, const char *what, long n)
{
    return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory for %ld %s", n, what);
}

/* The patch law's reruns: their factors and radii, and room for the runs that can be
 * made (a radius beyond R/2 is not run). */
static int radius_runs(tippe_launch_grid *g, const tippe_launch_options *o, tippe_error *err)
{
    g->cell_changed = calloc((size_t)g->n_cells, sizeof *g->cell_changed);
    if (!g->cell_changed)
        return no_memory(err, "cells", g->n_cells);
    for (int i = 0; i < TIPPE_LAUNCH_RADIUS_RUNS; i++) {
        tippe_launch_options oi;
        g->factor[i] = tippe_launch_radius_factor(o, i);
        /* the weight moves inside the ball: every cell's top has the mass and
         * radius of the first, hence its Hertz radius */
        const int beyond = tippe_launch_radius_options(&g->tops[0], o, g->factor[i], &oi);
        g->radius_m[i] = oi.patch_radius_m;
        if (i == 1 || beyond)
            continue;
        g->rec_radius[i] = calloc((size_t)g->total, sizeof *g->rec_radius[i]);
        if (!g->rec_radius[i])
            return no_memory(err, "launches", 3 * g->total);
    }
    return TIPPE_OK;
}

int tippe_launch_grid_make(const tippe_design *d, double z2_from_mm, double z2_to_mm, int n_z2,
                           double spin_from_rad_s, double spin_to_rad_s, int n_spin,
                           long per_cell, const tippe_launch_options *o, int radius_sensitivity,
                           tippe_launch_grid *g, tippe_error *err)
{
    memset(g, 0, sizeof *g);
    g->n_z2 = n_z2;
    g->n_spin = n_spin;
    g->per_cell = per_cell;
    g->n_cells = (long)n_z2 * n_spin;
    g->total = g->n_cells * per_cell;
    g->z2_mm = malloc((size_t)n_z2 * sizeof *g->z2_mm);
    g->spin_rev_s = malloc((size_t)n_spin * sizeof *g->spin_rev_s);
    g->tops = malloc((size_t)n_z2 * sizeof *g->tops);
    g->cell_tops = malloc((size_t)g->n_cells * sizeof *g->cell_tops);
    g->cell_spin_rad_s = malloc((size_t)g->n_cells * sizeof *g->cell_spin_rad_s);
    g->cells = calloc((size_t)g->n_cells, sizeof *g->cells);
    g->rec = calloc((size_t)g->total, sizeof *g->rec);
    g->model_invalid = calloc((size_t)n_z2, 1);
    g->cell_caps = malloc((size_t)g->n_cells * sizeof *g->cell_caps);
    if (!g->z2_mm || !g->spin_rev_s || !g->tops || !g->cell_tops || !g->cell_spin_rad_s ||
        !g->cells || !g->rec || !g->model_invalid || !g->cell_caps)
        return no_memory(err, "launches", g->total);
    for (int i = 0; i < n_z2; i++) {
        g->z2_mm[i] = n_z2 == 1 ? z2_from_mm
                                : z2_from_mm + (z2_to_mm - z2_from_mm) * i / (n_z2 - 1);
        int rc = tippe_design_top(d, g->z2_mm[i], &g->tops[i], err);
        if (rc)
            return tippe_error_blame(err, "z2_mm");
        tippe_design_protrusion pr;
        g->model_invalid[i] = (unsigned char)tippe_design_protrusion_at(d, g->z2_mm[i], &pr);
    }
    for (int j = 0; j < n_spin; j++)
        g->spin_rev_s[j] =
            (n_spin == 1 ? spin_from_rad_s
                         : spin_from_rad_s + (spin_to_rad_s - spin_from_rad_s) * j / (n_spin - 1)) /
            (2 * M_PI);
    /* where a hole opens at a pole the contact is not on the sphere: every launch records
     * its time there (as tippe launch's), with its row's openings (they move with Z2) */
    for (long c = 0; c < g->n_cells; c++) {
        g->cell_tops[c] = g->tops[c / n_spin];
        g->cell_spin_rad_s[c] = 2 * M_PI * g->spin_rev_s[c % n_spin];
        tippe_launch_polar_caps(d, g->z2_mm[c / n_spin], &g->cell_tops[c], g->cell_caps[c]);
    }
    g->radius_runs = tippe_friction_law_type_of(o->law)->patch && radius_sensitivity;
    return g->radius_runs ? radius_runs(g, o, err) : TIPPE_OK;
}

tippe_launch_plan tippe_launch_grid_plan(const tippe_launch_grid *g)
{
    return (tippe_launch_plan){(int)g->n_cells, g->per_cell, g->cell_tops, g->cell_spin_rad_s,
                               (const double(*)[2])g->cell_caps};
}

void tippe_launch_grid_radius_options(const tippe_launch_grid *g, const tippe_launch_options *o,
                                      int i, tippe_launch_options *out)
{
    tippe_launch_radius_options(&g->tops[0], o, g->factor[i], out);
}

long tippe_launch_grid_work(const tippe_launch_grid *g)
{
    return g->total * (1 + (g->rec_radius[0] != NULL) + (g->rec_radius[2] != NULL));
}

int tippe_launch_grid_tally(tippe_launch_grid *g, tippe_error *err)
{
    int rc = TIPPE_OK;
    for (long c = 0; !rc && c < g->n_cells; c++)
        rc = tippe_launch_tally_records(g->rec + c * g->per_cell, g->per_cell, &g->cells[c], err);
    g->changed = g->cells_changed = 0;
    /* each cell's launches compared across the radii (tippe_launch_radius_summary) */
    for (long c = 0; !rc && g->radius_runs && c < g->n_cells; c++) {
        const tippe_launch_record *ptr[TIPPE_LAUNCH_RADIUS_RUNS];
        for (int i = 0; i < TIPPE_LAUNCH_RADIUS_RUNS; i++) {
            const tippe_launch_record *base = i == 1 ? g->rec : g->rec_radius[i];
            ptr[i] = base ? base + c * g->per_cell : NULL;
        }
        tippe_launch_radius_sensitivity s;
        if ((rc = tippe_launch_radius_summary(ptr, g->per_cell, g->radius_m, &s, err)) != 0)
            break;
        g->cell_changed[c] = s.changed;
        g->changed += s.changed;
        g->cells_changed += s.changed > 0;
    }
    return rc;
}

tippe_launch_map tippe_launch_grid_map(const tippe_launch_grid *g)
{
    return (tippe_launch_map){g->n_z2, g->n_spin, g->z2_mm, g->spin_rev_s, g->cells,
                              g->per_cell};
}
