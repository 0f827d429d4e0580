/* tippe/sweep.h: Z2 sweeps: zones along the weight's travel, their tolerance bands.
 *
 * Contents:
 * - the sweep: zones along the weight's travel, the zone table, --vary (tippe_sweep_*;
 *   src/sweep/sweep.c, sweep_check.c, sweep_report.c, sweep_vary.c);
 * - bands: how far each boundary moves under the design's tolerances, and the robust
 *   widths (src/sweep/sweep_bands.c).
 */
#ifndef TIPPE_SWEEP_H
#define TIPPE_SWEEP_H

#include <stdio.h>

#include "tippe/design.h"
#include "tippe/base.h"
#include "tippe/launch.h"

/* ---- the sweep ---- */
/* Sweep: the zones of a top as its moving weight travels (paper section 6).
 *
 * As the weight's midpoint Z2 moves, k = A/C and e = eps/R trace a path through
 * the phase diagram of Theorem 5.1 (Figure 2). A sweep cuts [from, to] into
 * zones of constant group (Ia, Ib, IIa, IIb, IIc, III). The zone ends are roots,
 * found with GSL's Brent solver to TIPPE_SWEEP_XTOL_MM, of the continuous
 * boundary functions along the path:
 *   (k - 1) + e, (k - 1) - e, (k - 1) + e^2, b - 1, b + 1 (b of eq 5.11) and
 *   the signed eccentricity (the balanced point, eps = 0, where the centre of
 *   mass crosses the sphere's centre and the top starts resting on its other pole).
 * b is real only below the line k - 1 = -e^2, where it ends at the value 1/e; it
 * is continued by 1/e above the line so that b -+ 1 stay continuous (neither can
 * vanish there, as 1/e > 1).
 * Roots are bracketed by a uniform scan and refined. Where the path touches a
 * boundary without crossing it (|g| has a near-zero local minimum, found with
 * GSL's Brent minimiser), the touch is reported as an event and does not cut a
 * zone; a dip across a boundary and back between two scan points is found the
 * same way and gives its two roots.
 *
 * The group of each zone is tippe_theory_classify() at its midpoint, so a sweep
 * never disagrees with the classification. The core takes a callback Z2 -> (k, e),
 * so that it can run on any path, not only a design's. */

/* Zone ends are located to within this (GSL root interval), mm. */
#define TIPPE_SWEEP_XTOL_MM 1e-7

/* A path through the phase diagram. eval fills k = A/C and the signed
 * eccentricity e_signed = +-eps/R (positive when the centre of mass lies on the
 * +z side of the sphere's centre, the side that then rests on the table); its
 * magnitude is e. It must be continuous in Z2 and safe to call many times. */
typedef struct {
    void (*eval)(double z2_mm, void *params, double *A_over_C, double *e_signed);
    void *params;
} tippe_sweep_path;

typedef enum {
    TIPPE_SWEEP_I_II = 0,  /* (k - 1) + e = 0, "A/C-1=-eps/R" */
    TIPPE_SWEEP_II_III,    /* (k - 1) - e = 0, "A/C-1=+eps/R" */
    TIPPE_SWEEP_E2_LINE,   /* (k - 1) + e^2 = 0, "A/C-1=-(eps/R)^2" */
    TIPPE_SWEEP_B_PLUS,    /* b = 1 */
    TIPPE_SWEEP_B_MINUS,   /* b = -1 */
    TIPPE_SWEEP_BALANCED,  /* eps = 0 */
    TIPPE_SWEEP_N_BOUNDARIES
} tippe_sweep_boundary;

/* The boundary functions at z2_mm (the list above, in this enum's order; a
 * boundary is where its function changes sign). TIPPE_EINPUT where the path
 * leaves the classification's domain. */
int tippe_sweep_boundary_values(const tippe_sweep_path *path, double z2_mm,
                                double g[TIPPE_SWEEP_N_BOUNDARIES], tippe_error *err);

/* The boundary's name, as tippe_theory_class.boundary spells it. */
const char *tippe_sweep_boundary_name(tippe_sweep_boundary b);

/* A point where the path meets a boundary. */
typedef struct {
    double z2_mm;
    tippe_sweep_boundary boundary;
    int touch; /* 1: the path touches the boundary and turns back (no zone change) */
} tippe_sweep_event;

typedef struct {
    tippe_group group;
    double z2_from_mm, z2_to_mm;
    int com_side;  /* sign of e_signed inside the zone (0 only for a path stuck at e = 0) */
    /* Bit set of the boundaries (1u << tippe_sweep_boundary) at each end; 0 where
     * the zone ends with the swept range or with the physical travel. */
    unsigned from_boundaries, to_boundaries;
    /* 1 inside the physical travel, 0 beyond it (tippe_sweep_mark_travel splits
     * zones at its ends); 1 until it is called. */
    int within_travel;
} tippe_sweep_zone;

typedef struct {
    double from_mm, to_mm;       /* the swept range */
    int n_zones;
    tippe_sweep_zone *zones;     /* in order of Z2, covering [from, to] */
    int n_events;
    tippe_sweep_event *events;   /* every crossing and touch, in order of Z2 */
    /* Set by tippe_sweep_mark_travel (has_travel = 0 before). */
    int has_travel;
    double travel_from_mm, travel_to_mm;
    /* Set by tippe_sweep_design (has_sphere_only = 0 before): the Z2 interval in
     * which every part stays within the sphere (tippe_design_sphere_only_mm;
     * from > to: none). Beyond it the top rests on the part standing out and
     * the model does not apply: the reports mark the zones there. */
    int has_sphere_only;
    double sphere_only_from_mm, sphere_only_to_mm;
} tippe_sweep_result;

/* The parts of zone z outside r's sphere-only interval, where the model does
 * not apply: up to two [from, to] pieces into from[], to[]; returns how many. */
int tippe_sweep_zone_model_invalid(const tippe_sweep_result *r, const tippe_sweep_zone *z,
                                   double from[2], double to[2]);
/* The run that starts at zone i: the usable parts (the parts a maker can use:
 * within the physical travel and the sphere-only interval) of the adjacent zones
 * whose groups are of one family (Theorem 5.1's I, II, III: *family 0, 1, 2; the
 * com_side split at the balanced point does not end a run), joined into
 * [*from_mm, *to_mm]. *family is -1 when zone i has no usable
 * part. Returns the index of the zone after the run (i + 1 at least), so that
 * for (i = 0; i < r->n_zones; i = tippe_sweep_family_run(r, i, ...)) visits
 * every run once; the summary, the robust widths and tippe build all join runs
 * this way. */
int tippe_sweep_family_run(const tippe_sweep_result *r, int i, int *family, double *from_mm,
                           double *to_mm);

typedef struct {
    int n_scan;        /* scan intervals for bracketing (default 2000) */
    double xtol_mm;    /* root and minimum location tolerance (default TIPPE_SWEEP_XTOL_MM) */
    /* |g| below this at a local minimum is a touch (default 1e-9: seven orders
     * above the rounding of k - 1 +- e, far below any printable difference). */
    double touch_tol;
} tippe_sweep_options;

void tippe_sweep_options_default(tippe_sweep_options *opt);

/* Sweeps the path over [from_mm, to_mm] (from < to). opt may be NULL for the
 * defaults. TIPPE_EINPUT for a bad range or options, or where the path leaves
 * the domain of the classification (k <= 0, e >= 1, not finite; the message
 * names Z2); TIPPE_ECOMPUTE if a GSL solver fails. *out is zeroed first and must
 * be freed with tippe_sweep_result_free() whatever the return. */
int tippe_sweep_run(const tippe_sweep_path *path, double from_mm, double to_mm,
                    const tippe_sweep_options *opt, tippe_sweep_result *out, tippe_error *err);

/* Splits the zones at the ends of the physical travel [from_mm, to_mm] and marks
 * the parts beyond it (within_travel = 0). */
int tippe_sweep_mark_travel(tippe_sweep_result *r, double from_mm, double to_mm,
                            tippe_error *err);

void tippe_sweep_result_free(tippe_sweep_result *r);

/* Whether ev (one of r's events) is a crossing where a zone of r ends. */
int tippe_sweep_event_ends_zone(const tippe_sweep_result *r, const tippe_sweep_event *ev);

/* The path of a design: Z2 -> its top (tippe_design_top_any), k and signed e. */
tippe_sweep_path tippe_sweep_design_path(const tippe_design *d);

/* Sweeps a design over [from_mm, to_mm] (from >= to means its stated travel)
 * and marks its physical travel. */
int tippe_sweep_design(const tippe_design *d, double from_mm, double to_mm,
                       const tippe_sweep_options *opt, tippe_sweep_result *out,
                       tippe_error *err);

/* Main-group summary over the usable parts of the zones (as tippe_sweep_family_run:
 * within the physical travel, the whole range before tippe_sweep_mark_travel, and
 * where no part stands out of the sphere). */
typedef struct {
    int has_I, has_II, has_III;
    int three_in_one;             /* I, II and III all reachable */
    /* The zone of each group (index 0, 1, 2 for I, II, III) is its widest
     * contiguous run of Z2 within the physical travel: adjacent subgroups of the
     * group count as one run (Ia|Ib, IIa|IIb|IIc), and so do the two sides of
     * the balanced point (the top turned over is the same top: zone I is not
     * split there); runs at Z2 < 0 count like any other. 0 if not reachable. */
    double widest_mm[3];
    /* The narrowest of the three zones, 0 unless the top is 3-in-1: a top that
     * lacks a group shows two behaviours at most, however wide their zones.
     * The one measure of `sweep`, `compare` and the optimiser's objective.
     * narrowest_family names its group ("I", "II", "III"), NULL unless 3-in-1. */
    double narrowest_zone_mm;
    const char *narrowest_family;
} tippe_sweep_summary;

void tippe_sweep_summarise(const tippe_sweep_result *r, tippe_sweep_summary *out);

/* How the zones move as one dimension of a design changes: the design file is
 * reloaded at each of `steps` values evenly spaced over [from, to] with the
 * override "field=value" after the caller's overrides, and swept over
 * [z2_from_mm, z2_to_mm] (z2_from_mm >= z2_to_mm: each step's stated travel). */
typedef struct {
    int n;
    double *values;                        /* the field's value at each step */
    tippe_sweep_result *results;           /* physical travel marked */
    double *travel_from_mm, *travel_to_mm; /* each step's stated travel */
    /* NULL, or why step i's design does not hold together: its value is a valid
     * one, but a part then overlaps or touches another, leaves the sphere or the
     * stated travel leaves the physical one (the layout check's message). Such a step
     * is kept, not swept: its result has no zones and its travel is 0 .. 0. */
    char **collision;
    int n_collisions;
} tippe_sweep_vary_result;

/* TIPPE_EINPUT if steps < 1 (or steps = 1 with from != to), a bound is not
 * finite, every step's parts collide, or a step's design does not load for a reason
 * other than where its parts are (the message names the step's override: a bad field
 * or value). Each step is base (as loaded, with its overrides) with field set
 * to the step's value, derived from base in memory: no file is read again.
 * *out must be freed with tippe_sweep_vary_free() whatever the return. */
int tippe_sweep_vary(const tippe_design *base, const char *field, double from, double to,
                     int steps, double z2_from_mm,
                     double z2_to_mm, const tippe_sweep_options *opt,
                     tippe_sweep_vary_result *out, tippe_error *err);
void tippe_sweep_vary_free(tippe_sweep_vary_result *v);
/* A vary's zone tables as one CSV: tippe_sweep_write_csv's columns after a first one
 * named field (the step's value), and a last one, collision: empty, or for a step whose
 * parts collide (its only row, with the zone columns empty) the reason. */
void tippe_sweep_vary_write_csv(FILE *out, const tippe_sweep_vary_result *v, const char *field);

/* Reports. d may be NULL for a path that is not a design. */
struct cJSON;
/* The sweep as a cJSON object: design, file, sweep_mm, travel_mm,
 * physical_travel_mm, zones [{group ("I", "IIa", "IIb", "IIc", "III": Ia and Ib
 * joined), subgroups, z2_from_mm, z2_to_mm, width_mm, within_travel (all of it),
 * reachable_mm (the part within the physical travel, or null), com_side,
 * ends_on}], intervals (the zones as found: subgroup in group, family, split at
 * the physical travel; z2_from_mm, z2_to_mm, width_mm, within_travel, com_side,
 * ends_on), touches [{boundary, z2_mm}], crossings
 * [{boundary, z2_mm, ends_zone}] (every crossing, also those that change no group),
 * three_in_one, narrowest_zone_mm (null if nothing is reachable),
 * narrowest_zone_family, zone_widths_mm {I, II, III} (each group's widest
 * reachable run, tippe_sweep_summary.widest_mm). NULL if out of memory. */
struct cJSON *tippe_sweep_json(const tippe_sweep_result *r, const tippe_design *d);
/* The zone table a designer reads: group, from, to, width (mm), the boundary
 * that ends each zone, notes (beyond the physical travel, the side that rests
 * on the table when the sweep crosses the balanced point), touches, and the
 * 3-in-1 verdict with the narrowest reachable zone. */
void tippe_sweep_print_table(FILE *out, const tippe_sweep_result *r, const tippe_design *d);

/* ---- tolerance bands ---- */
/* Sweep bands: how far each zone boundary of a sweep moves under the
 * design's tolerances (tippe/design.h), and the zone widths that survive.
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

/* The zone table as CSV (tippe sweep --csv): the header
 *   zone,group,family,z2_from_mm,z2_to_mm,width_mm,robust_width_mm,ends_on,within_travel,
 *   model_valid
 * then one row per zone: its index (1-based), group (Ia ... III), family (I, II, III), ends
 * and width in mm (%.12g), robust width (empty when b is NULL), the boundaries that end it
 * ("b=-1; A/C-1=+eps/R", quoted; empty at the end of the sweep or the physical travel),
 * yes/no whether it lies within the physical travel, and yes/no/partly whether no part
 * stands out of the sphere there. */
void tippe_sweep_write_csv(FILE *out, const tippe_sweep_result *r,
                           const tippe_sweep_bands_result *b);

struct cJSON;
int tippe_sweep_json_add_bands(struct cJSON *o, const tippe_design *d,
                               const tippe_sweep_result *r, const tippe_sweep_bands_result *b);

/* ==== reports both front ends give (tippe --json, tippe serve) ==== */
/* tippe sweep --json: tippe_sweep_json with the bands added
 * (tippe_sweep_json_add_bands) and the printed parts and bodies
 * (tippe_profile_printed_parts_json). NULL if out of memory. */
struct cJSON *tippe_sweep_report_json(const tippe_design *d, const tippe_sweep_result *r,
                                      const tippe_sweep_bands_result *b);
/* tippe eval --json: the design with its weight at z2_mm (top: tippe_design_top
 * there): design, file, z2_mm, mass_kg, moving_mass_kg, R_m, eps_m,
 * eps_over_R, A_kg_m2, C_kg_m2, A_over_C, com_side, group, subgroup, boundary
 * (Theorem 5.1), travel_mm, physical_travel_mm, parts [{name, shape, role,
 * material, density_g_cm3, mass_kg, printed}], model_valid, protrusion and the
 * printed parts. NULL if out of memory. */
struct cJSON *tippe_sweep_eval_json(const tippe_design *d, double z2_mm, const tippe_top *t);
/* The design's path through the phase diagram sampled at n (>= 2) evenly spaced
 * Z2 over [from_mm, to_mm], for a page that draws the zone plot (the paper's
 * Figure 7: A/C - 1 against +-eps/R over Z2): {z2_mm: [...], A_over_C: [...],
 * eps_over_R_signed: [...] (the sign of tippe_sweep_path's e_signed),
 * mass_kg: [...]}. NULL if out of memory. */
struct cJSON *tippe_sweep_samples_json(const tippe_design *d, double from_mm, double to_mm,
                                       int n);


/* ==== one launch beside its zone (tippe check, tippe serve's /api/check) ==== */
/* The zone of the design's sweep (over its stated travel) that contains z2. */
typedef struct {
    int ok;
    tippe_group group;
    double from_mm, to_mm;
} tippe_sweep_point_zone;
void tippe_sweep_zone_at(const tippe_design *d, double z2, tippe_sweep_point_zone *z);

/* Theory for a top beside launches: group, subgroup, A/C, eps/R, the zone
 * (zone_mm), the spin thresholds n-, n*; with a tally tl (may be NULL) what
 * Theorem 5.1 predicts for its launches and how many agree. NULL if out of
 * memory. */
struct cJSON *tippe_sweep_theory_json(const tippe_top *t, double g,
                                      const tippe_sweep_point_zone *z,
                                      const tippe_launch_tally *tl);

/* One central hand launch (tippe_launch_central) of d at z2_mm with the given
 * spin, integrated, beside the sweep's zone there. */
typedef struct {
    const tippe_design *d;
    double z2_mm;
    tippe_top top;
    tippe_dynamics_initial ic;
    tippe_launch_record rec;
    tippe_sweep_point_zone zone;
} tippe_sweep_check;
/* err->field is "z2_mm" when the design has no top at z2_mm. */
int tippe_sweep_check_run(const tippe_design *d, double z2_mm, const tippe_launch_options *o,
                          double spin_rad_s, tippe_sweep_check *out, tippe_error *err);
/* tippe check --json: design, file, set (sets[0 .. n_sets - 1]), z2_mm, initial,
 * verdict, model_valid, protrusion, t_s, decided_by, margin_J, barrier_gap_J,
 * theta_range_rad, Rn_bound_N, t_flip_s, theta_final_rad, spin_final_rad_s,
 * J0_kg_m3_s, jellett_rel_drift, options, theory. NULL if out of memory. */
struct cJSON *tippe_sweep_check_json(const tippe_sweep_check *c, const tippe_launch_options *o,
                                     const char *const *sets, int n_sets);

/* The same central launch under one friction law of several (tippe check
 * --friction viscous,patch): its check (the verdict, as tippe_sweep_check_run)
 * and its trajectory to t_end (tippe_launch_trajectory: theta(t), the energy
 * dissipated by the end of the run). */
typedef struct {
    tippe_launch_options o;        /* the law's options */
    tippe_sweep_check check;
    tippe_dynamics_samples samples;
    tippe_dynamics_result run;     /* the trajectory's: E0, last (t, theta, D), t_flip */
    char friction[320];            /* the law in words (tippe_dynamics_friction_text) */
} tippe_sweep_check_law;
/* Runs the launch under each o[i] into out[i] (0 <= i < n); on failure the
 * failed law's status, its message naming the law. Free with
 * tippe_sweep_check_laws_free in any case. */
int tippe_sweep_check_laws(const tippe_design *d, double z2_mm, const tippe_launch_options *o,
                           int n, double spin_rad_s, tippe_sweep_check_law *out, tippe_error *err);
void tippe_sweep_check_laws_free(tippe_sweep_check_law *l, int n);
/* The energy dissipated by the end of law l's run as a share of E0 (0 .. 1). */
double tippe_sweep_check_law_energy_lost(const tippe_sweep_check_law *l);
/* tippe check --friction A,B --json: design, file, set, z2_mm, initial (of the
 * first law: the launch is the same), and laws: [{friction (law and coefficients),
 * friction_text, verdict, decided_by, t_s, theta_final_rad, theta_range_rad,
 * t_flip_s, t_fall_s, t_end_s (where the run stopped), theta_end_rad, E0_J,
 * dissipated_J, energy_lost}], theory (of the first law's J0: the launch is the
 * same, J0 too). NULL if out of memory. */
struct cJSON *tippe_sweep_check_laws_json(const tippe_sweep_check_law *l, int n,
                                          const char *const *sets, int n_sets);

/* ==== the reports as JSON text, for bindings (python/tippe; src/sweep/sweep_text.c) ====
 * Each fills *out with the JSON text the command prints with --json (the same
 * builders and printer, so the numbers agree to the last digit; "set" lists the
 * design's overrides), to be freed with tippe_sweep_text_free; *out is NULL on
 * failure, with err set (err->field "z2_mm" or "n" when that was wrong).
 *   eval:   tippe eval --json at z2_mm;
 *   sweep:  tippe sweep --json over [from_mm, to_mm] (from >= to: the stated
 *           travel), bands and robust widths included;
 *   check:  tippe check --json of the central launch at z2_mm and spin_rad_s with
 *           the command's default options, plus "trajectory": {t_s, theta_rad,
 *           theta_dot_rad_s, phi_dot_rad_s, spin_rad_s, Rn_N, E_J, D_J, J_kg_m3_s},
 *           the samples tippe check --csv writes;
 *   launch: n hand launches at z2_mm drawn with seed as tippe launch draws them
 *           (default options): "counts" by verdict (tippe launch --json's) and
 *           "launches" {verdict, spin_rad_s, theta0_rad, t_s, theta_final_rad,
 *           spin_final_rad_s, t_flip_s}, one entry per launch. */
int tippe_sweep_text_eval(const tippe_design *d, double z2_mm, char **out, tippe_error *err);
int tippe_sweep_text_sweep(const tippe_design *d, double from_mm, double to_mm, char **out,
                           tippe_error *err);
int tippe_sweep_text_check(const tippe_design *d, double z2_mm, double spin_rad_s, char **out,
                           tippe_error *err);
int tippe_sweep_text_launch(const tippe_design *d, double z2_mm, long n, uint64_t seed,
                            char **out, tippe_error *err);
void tippe_sweep_text_free(char *text);

#endif
