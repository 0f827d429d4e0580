/* tippe/sweep_bands.h: how far each zone boundary of a sweep moves under the
 * design's tolerances (tippe/tolerance.h), and the zone widths that survive.
 *
 * A zone boundary is a root Z2* of a boundary function f(Z2; p) (tippe/sweep.h;
 * p the design's fields). To first order a change dp of one field moves it by
 *     d(Z2*) / dp = -(df/dp) / (df/dZ2)      (implicit function theorem)
 * with df/dZ2 along the swept path and df/dp by differentiating the design:
 * the design is reloaded with the field moved (tippe_design_derive) and f
 * evaluated at the nominal Z2*, both derivatives by GSL's 5-point central
 * difference (gsl_deriv_central, which also estimates its error). Tolerances
 * are taken as independent and combined in quadrature (root sum of squares):
 * if every +/- is the same multiple of its field's standard deviation, the
 * band is that multiple of the boundary's; worst_mm, the linear sum (every
 * field at its limit, each in the adverse direction), is a hard bound to first
 * order and is reported too.
 *
 * The robust width of a zone is its width less the bands at both ends (0 when
 * they overlap). An end where the zone meets the end of the physical travel or
 * of the sweep has no band (the travel's own tolerance is not modelled). */
#ifndef TIPPE_SWEEP_BANDS_H
#define TIPPE_SWEEP_BANDS_H

#include <stdio.h>

#include "tippe/design.h"
#include "tippe/error.h"
#include "tippe/sweep.h"

typedef struct {
    int event;                      /* index into the sweep's events */
    tippe_sweep_boundary boundary;
    double z2_mm;                   /* the nominal crossing */
    double df_dz_per_mm;            /* slope of the boundary function along the path */
    double band_mm;                 /* +/- (quadrature); INFINITY if df/dZ2 = 0 */
    double worst_mm;                /* +/- (linear sum) */
    double *dz_dp;                  /* [n_tolerances]: mm per unit of the field */
    double *dz_dp_err;              /* [n_tolerances]: error estimate of dz_dp */
} tippe_sweep_band;

typedef struct {
    int n;                          /* one per crossing that ends a zone */
    tippe_sweep_band *bands;
    int n_tolerances;               /* the design's (tippe_design_n_tolerances) */
} tippe_sweep_bands_result;

/* Bands of every crossing of r that ends a zone; r is the sweep of d
 * (tippe_sweep_design). Costs a few design loads per tolerance (about 8):
 * nothing is computed per zone. *out must be freed with
 * tippe_sweep_bands_free() whatever the return. TIPPE_EINPUT if the design
 * does not load with a field moved by a fraction of its tolerance (the
 * message names the field). */
int tippe_sweep_bands(const tippe_design *d, const tippe_sweep_result *r,
                      tippe_sweep_bands_result *out, tippe_error *err);
void tippe_sweep_bands_free(tippe_sweep_bands_result *b);

/* The band at Z2 = z2_mm: the largest band of the crossings there (within
 * twice the sweep's location tolerance), 0 if none. */
double tippe_sweep_band_at(const tippe_sweep_bands_result *b, double z2_mm);

/* Robust width of r->zones[i] (mm, >= 0). */
double tippe_sweep_zone_robust_mm(const tippe_sweep_result *r, const tippe_sweep_bands_result *b,
                                  int i);

/* Per group (index 0, 1, 2 for I, II, III), the largest robust width of its
 * runs within the physical travel (runs as tippe_sweep_summarise joins them),
 * and the narrowest of the three (0 unless all three are reachable): the robust
 * counterpart of tippe_sweep_summary's widest_mm and narrowest_zone_mm. */
void tippe_sweep_robust_widths(const tippe_sweep_result *r, const tippe_sweep_bands_result *b,
                               double robust_mm[3], double *narrowest_mm);

/* Reports: a table of the bands (boundary, Z2, +/- band, worst case, the
 * tolerance that moves it most) and the robust width of every zone; and the
 * same added to a sweep's JSON (tippe_sweep_json): "tolerances" [{field,
 * value, plus_minus, unit, rule}], "bands" [{boundary, z2_mm, band_mm,
 * worst_mm, combined: "quadrature", sensitivities [{field, dz2_dfield,
 * error}]}], and band_from_mm, band_to_mm, robust_width_mm in every zone and
 * interval, robust_zone_widths_mm {I, II, III}, robust_narrowest_zone_mm.
 * The JSON function returns 0, or -1 if out of memory. */
void tippe_sweep_print_bands(FILE *out, const tippe_design *d, const tippe_sweep_result *r,
                             const tippe_sweep_bands_result *b);
/* The zone plot (tippe_sweep_plot_zones) with each band shaded across it. */
int tippe_sweep_plot_zones_banded(const char *file, const tippe_sweep_path *path,
                                  const tippe_sweep_result *r, const tippe_sweep_bands_result *b,
                                  const char *title, tippe_error *err);
struct cJSON;
int tippe_sweep_json_add_bands(struct cJSON *o, const tippe_design *d,
                               const tippe_sweep_result *r, const tippe_sweep_bands_result *b);

#endif
