/* optimise/internal.h: the spec's representation and what the
 * optimise module's files share; no other module sees it. */
#ifndef TIPPE_OPTIMISE_INTERNAL_H
#define TIPPE_OPTIMISE_INTERNAL_H

#include "base/json.h"
#include "tippe/optimise.h"

#define MAX_CHOOSE 4
#define MAX_TIE 8
#define MAX_SETS_PER_OPTION 4
#define MAX_OPTIONS 400
#define MAX_CHOICES 2000
#define MAX_SPEC_MIB 1
/* Search sweeps use fewer scan intervals than a report (2000): a zone end is
 * still root-found to 1e-7 mm, only a boundary touched twice within one
 * interval (75 um over a 30 mm travel) could be missed; every reported best
 * is re-evaluated with the full sweep. */
#define SEARCH_SCAN 400
#define TIPPE_PI 3.14159265358979323846

typedef struct {
    char path[TIPPE_OPTIMISE_PATH_LEN];
    double lo, hi;
} vary_t;

typedef struct {
    char label[96];
    int n_set;
    char set[MAX_SETS_PER_OPTION][256];
} option_t;

typedef struct {
    char path[TIPPE_OPTIMISE_PATH_LEN];
    int n;
    option_t *opt;
} choose_t;

typedef struct {
    char path[TIPPE_OPTIMISE_PATH_LEN], follows[TIPPE_OPTIMISE_PATH_LEN];
    double plus_mm, times;
    int vary_index;   /* follows a vary parameter, or -1 */
    int tie_index;    /* follows another tie's field (a chain), or -1 */
    double base_value; /* the followed field in the base design (NAN if absent) */
} tie_t;

typedef enum { ALG_DIRECT_L, ALG_CRS2, ALG_MLSL, ALG_ISRES, N_ALG } algorithm_t;
static const char *const alg_names[N_ALG] = {"DIRECT-L", "CRS2", "MLSL", "ISRES"};
typedef enum { POLISH_COBYLA, POLISH_BOBYQA, POLISH_NONE, N_POLISH } polish_t;
static const char *const polish_names[N_POLISH] = {"COBYLA", "BOBYQA", "none"};

struct tippe_optimise_spec {
    char *path, *design_path;
    char name[256];
    tippe_design_source *src;
    int n_vary;
    vary_t vary[TIPPE_OPTIMISE_MAX_VARY];
    int n_choose;
    choose_t choose[MAX_CHOOSE];
    int n_tie;
    tie_t tie[MAX_TIE];
    double eps_max_min_mm, spin_max_rev_s, min_wall_mm, max_weight_g;
    int robust;
    algorithm_t algorithm;
    polish_t polish;
    long evals, polish_evals;
    int n_choices;
    /* a catalogue choice's file (the spec's "catalogue", else catalogue.json
     * beside the base design), which the best design names; "" without one */
    char catalogue_file[1024];
};

/* optimise_candidate.c */
void tippe_optimise_choice_options(const tippe_optimise_spec *s, int choice, int *idx);

/* The constraints' margins of a candidate: relative (so that they add
 * across constraints), <= 0 where the constraint is met. */
enum { CON_EPS, CON_SPIN, CON_WALL, CON_WEIGHT, N_CON };

/* optimise_candidate.c */
void tippe_optimise_evaluate_margins(const tippe_optimise_spec *s, int choice, const double *x,
                                     int n_scan, tippe_optimise_eval *out, double margin[N_CON]);

#endif
