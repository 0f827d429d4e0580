/* tippe/optimise.h: search a design space for the top whose narrowest zone is
 * widest (issue 13; docs/optimise.md).
 *
 * A spec (JSON) names a base design and what may change, with the override
 * paths of `--set`: continuous ranges (`vary`), discrete options (`choose`:
 * values, or items of a hardware catalogue), fields that follow others (`tie`),
 * constraints and the objective. For each combination of discrete options
 * (a "choice") a global NLopt algorithm searches the continuous parameters and
 * a local one polishes the best point; choices run in parallel (OpenMP), each
 * on its own, so the answer depends on the seed only, not on the threads.
 *
 * A candidate's zones are the sweep's (tippe/sweep.h): each group's widest
 * contiguous run of Z2 within the physical travel. The objective is the
 * narrowest of the three (0 if a group is not reachable). Infeasible candidates
 * score below 0 (-1 - violation), so every algorithm sees one function. */
#ifndef TIPPE_OPTIMISE_H
#define TIPPE_OPTIMISE_H

#include "tippe/design.h"
#include "tippe/base.h"
#include "tippe/sweep.h"

#include <stddef.h>

#define TIPPE_OPTIMISE_MAX_VARY 8
#define TIPPE_OPTIMISE_PATH_LEN 128

typedef struct tippe_optimise_spec tippe_optimise_spec; /* opaque */

/* Reads and checks a spec: every message names the file and the JSON path.
 * The design (and the catalogue) paths are relative to the spec's directory.
 * TIPPE_EINPUT for a bad spec. */
int tippe_optimise_spec_load(const char *path, tippe_optimise_spec **out, tippe_error *err);
void tippe_optimise_spec_free(tippe_optimise_spec *s);

int tippe_optimise_spec_n_vary(const tippe_optimise_spec *s);
const char *tippe_optimise_spec_vary_path(const tippe_optimise_spec *s, int k);
int tippe_optimise_spec_n_choices(const tippe_optimise_spec *s);
/* "parts.screw.material=iron, parts.screw=M8x10" (into buf). */
const char *tippe_optimise_spec_choice_label(const tippe_optimise_spec *s, int choice, char *buf,
                                        size_t cap);
const char *tippe_optimise_spec_path(const tippe_optimise_spec *s);

/* Why a candidate is not feasible. */
typedef enum {
    TIPPE_OPTIMISE_OK = 0,
    TIPPE_OPTIMISE_DOES_NOT_FIT,    /* the design does not build: parts overlap, no travel */
    TIPPE_OPTIMISE_THIN_WALL,       /* a hole's wall or floor is thinner than min_wall_mm */
    TIPPE_OPTIMISE_HEAVY,           /* the moving weight is heavier than max_weight_g */
    TIPPE_OPTIMISE_EPS_SMALL,       /* eps_max over the travel below eps_max_min_mm */
    TIPPE_OPTIMISE_SPIN_HIGH,       /* flipping in zone II needs more than spin_max_rev_s */
    TIPPE_OPTIMISE_NO_ZONES         /* the sweep failed (outside the phase diagram) */
} tippe_optimise_status;

const char *tippe_optimise_status_name(tippe_optimise_status s);

/* One evaluated candidate. */
typedef struct {
    int choice;
    double x[TIPPE_OPTIMISE_MAX_VARY];  /* the vary values, in spec order */
    tippe_optimise_status status;
    double score;                  /* what the search maximises: the objective in mm
                                      (>= 0) if feasible, else -1 - violation */
    double zone_mm[3];             /* I, II, III: widest run within the travel */
    double objective_mm;           /* narrowest of the three (0 unless 3-in-1) */
    double travel_mm[2];           /* physical travel */
    double eps_max_mm;             /* largest |eps| over the travel */
    double spin_flip_rev_s;        /* n* (section 7.1) over zone II's middle half; 0 if none */
    double wall_mm;                /* thinnest hole wall or floor (INFINITY: no hole) */
    double weight_g;               /* moving mass */
    /* Robust widths (tippe/sweep.h: each width less the tolerance bands
     * of its ends), computed for the reported best of each choice only. */
    int has_robust;
    double robust_zone_mm[3], robust_mm;
} tippe_optimise_eval;

typedef struct {
    unsigned long seed;     /* for the stochastic algorithms (CRS2, MLSL, ISRES) */
    int threads;            /* OpenMP threads; <= 0: the OpenMP default */
    int keep_all;           /* keep every evaluated candidate (for a CSV) */
    /* Called after every evaluation, from any thread (tippe_progress_add is safe). */
    void (*progress)(void *ctx, long n);
    void *progress_ctx;
} tippe_optimise_options;

void tippe_optimise_options_default(tippe_optimise_options *o);

/* The best of one choice, and how the search went. */
typedef struct {
    tippe_optimise_eval best;     /* re-evaluated with the full sweep (1e-7 mm) */
    long n_evals;            /* global + polish */
    long n_global;           /* of which in the global phase */
    double *best_so_far;     /* score after each evaluation, n_evals entries */
    tippe_optimise_eval *all;     /* every candidate in order if keep_all, else NULL */
} tippe_optimise_choice_result;

typedef struct {
    int n_choices;
    tippe_optimise_choice_result *choices;
    int best_choice;         /* highest best.score (robust_mm with the robust objective);
                                the lowest index on a tie */
    long total_evals;
    int robust;              /* 1: robust objective: the search maximises nominal widths,
                                the choices are ranked by robust widths at their best */
} tippe_optimise_result;

/* Whether candidate a ranks above b: feasible before infeasible, then by the
 * robust width where both have one, else by score. */
int tippe_optimise_rank_above(const tippe_optimise_eval *a, const tippe_optimise_eval *b);

/* Total evaluations the search will make at most (for a progress bar). */
long tippe_optimise_planned_evals(const tippe_optimise_spec *s);

/* Runs the search. TIPPE_ECOMPUTE if NLopt fails; *out must be freed with
 * tippe_optimise_result_free() whatever the return. */
int tippe_optimise_run(const tippe_optimise_spec *s, const tippe_optimise_options *o, tippe_optimise_result *out,
                  tippe_error *err);
void tippe_optimise_result_free(tippe_optimise_result *r);

/* Evaluates one candidate (n_scan sweep intervals; 0 for the sweep's default). */
void tippe_optimise_evaluate(const tippe_optimise_spec *s, int choice, const double *x, int n_scan,
                        tippe_optimise_eval *out);

/* The overrides that make candidate (choice, x) from the base design, as
 * "FIELD=VALUE" strings (vary, choices, ties, in that order) in buf; returns
 * how many (at most cap), or -1 if buf is too small. */
int tippe_optimise_overrides(const tippe_optimise_spec *s, int choice, const double *x, char (*buf)[256],
                        int cap);

/* The candidate's sweep over its physical travel (full resolution), for
 * plots and checks; *out must be freed with tippe_sweep_result_free(). */
int tippe_optimise_sweep(const tippe_optimise_spec *s, const tippe_optimise_eval *e, tippe_sweep_result *out,
                    tippe_error *err);

/* The candidate as a design file a user can load: the base design with its
 * overrides, travel_mm the physical travel, materials relative to out_path's
 * directory, and notes saying how it was found and the objective's value.
 * NULL, with err set, on failure. */
struct cJSON *tippe_optimise_design_json(const tippe_optimise_spec *s, const tippe_optimise_eval *e,
                                    const char *out_path, const char *how, tippe_error *err);

#endif
