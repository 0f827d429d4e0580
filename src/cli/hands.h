/* What the hand-launch verbs share (private to src/cli): tippe launch
 * (launch.c), tippe map (map.c) and tippe check (check.c) read the same
 * options, describe the top and the launch model in the same words, and run
 * their launches through hands_run_plan (mpi.c), which shares them among MPI
 * ranks in tippe-mpi. */
#ifndef TIPPE_CLI_HANDS_H
#define TIPPE_CLI_HANDS_H

#include "cli.h"
#include "tippe/sweep.h"

#include "tippe/design.h"
#include "tippe/launch.h"
#include "tippe/base.h"

#include <stdint.h>

struct cJSON;

/* Largest launch spin (cli.h; a hand launch's spin is its size, >= 0). */
#define HANDS_SPIN_MAX_RAD_S TIPPE_CLI_SPIN_MAX_RAD_S

/* The patch law's radius sensitivity options, the same in check, launch and map
 * (docs/dynamics.md, "Radius sensitivity"), for the hands_args A; WHAT names what is
 * run again ("the launch", "every cell's launches"). */
#define HANDS_RADIUS_OPTIONS(A, WHAT)                                                          \
    hands_friction_opt(TIPPE_LAW_PARAM_RADIUS_SPAN, &(A)->o.patch_radius_span),                \
    {.name = "no-radius-sensitivity", .kind = TIPPE_CLI_FLAG,                                  \
     .value = &(A)->no_radius_sensitivity,                                                     \
     .help = "patch law: skip the reruns of " WHAT "\n"                                   \
             "at 1/F and F times the patch radius (two thirds of the work; by\n"             \
             "default the outcome is given at all three radii, docs/dynamics.md)"}

/* The contact option, the same in check, launch and map: the model before issue 35,
 * to compare (docs/dynamics.md, "The contact on a rim"). */
#define HANDS_CONTACT_OPTION(A)                                                                \
    {.name = "sphere-contact", .kind = TIPPE_CLI_FLAG, .value = &(A)->o.sphere_contact_only,  \
     .help = "keep the contact on the sphere within a hole's opening at a pole\n"             \
             "(the model before the rim contact, to compare; by default the top\n"          \
             "stands on the opening's rim there)"}

/* The friction options (--friction, --patch-mm, --table, --mu-c, --slip-scale,
 * --mu): tippe launch, map, check and build read them alike. */
enum { HANDS_MAX_LAWS = TIPPE_MAX_FRICTION_LAWS, HANDS_HELP_WIDTH = 70 };
typedef struct {
    const char *friction;      /* --friction: a law, or (check) laws, comma-separated */
    const char *table;         /* --table (patch law) */
    double patch_mm;           /* --patch-mm (patch law; 0: Hertz from the materials) */
    int n_laws;                /* the laws chosen (1 unless a verb compares laws) */
    tippe_friction_law laws[HANDS_MAX_LAWS];
    char help[512];            /* --friction's help, made from the laws' table */
} hands_friction;

/* A friction parameter's option as the laws' table gives it (tippe_friction_params:
 * name, unit, range, default, help), writing into value. */
tippe_cli_opt hands_friction_opt(tippe_friction_param_id id, void *value);
/* The friction options into t (room for 6), writing into f and o; their count. */
int hands_friction_options(hands_friction *f, tippe_launch_options *o, tippe_cli_opt *t);
/* After parsing: the law(s) into f->laws and o->law (the first), the patch radius into
 * o. A coefficient given without --friction selects its law (--mu the viscous one,
 * --mu-c or --slip-scale Coulomb's, --patch-mm or --table the patch law); a
 * coefficient of no law given is a usage error. allow_list: --friction may name
 * several laws. 0, or 2 after a usage error. */
int hands_friction_apply(const char *verb, hands_friction *f, tippe_launch_options *o,
                         const tippe_cli_spec *spec, int allow_list);
/* Where a patch law has no --patch-mm: the Hertz contact modulus of the design's ball
 * on --table into o (tippe_launch_patch_modulus). A library status. */
int hands_friction_patch(const hands_friction *f, tippe_launch_options *o, const tippe_design *d,
                         tippe_error *err);
/* o with law i of f (its coefficients are o's: --mu for viscous, --mu-c for the others). */
void hands_friction_law(const hands_friction *f, int i, const tippe_launch_options *o,
                        tippe_launch_options *out);

/* The options of a hand-launch verb, filled by hands_parse. */
typedef struct {
    const char *verb;          /* "launch", "map", "check" */
    const char *design;        /* the design file */
    double z2_mm;              /* launch, check: --z2 */
    tippe_cli_range z2_range;  /* map: --z2 FROM:TO:STEPS, mm */
    tippe_cli_range spin;      /* --spin, rad/s: launch FROM:TO, map FROM:TO:STEPS,
                                * check one value (from = to) */
    long n, threads, seed;
    int json;
    int no_radius_sensitivity; /* check, launch, map: --no-radius-sensitivity */
    const char *csv, *plot, *accuracy, *stepper;
    hands_friction fr;         /* --friction and its coefficients */
    tippe_launch_options o;    /* the distributions and the model */
    tippe_cli_sets sets;       /* --set */
} hands_args;

/* The verbs and their own options: appended to the shared ones by hands_parse. */
typedef struct {
    tippe_cli_spec spec;      /* verb, synopsis, about, after (opts are made here) */
    tippe_cli_opt *own;       /* the verb's own options, ending with {NULL} */
    int distribution;         /* 1: the hand-launch distribution options too */
    int friction_list;        /* 1: --friction may name several laws (check) */
} hands_verb;

/* Parses argv for v into a (whose verb, n and spin defaults the caller set):
 * 0, TIPPE_CLI_HELP after --help (printed by rank 0 only), or 2. */
int hands_parse(hands_verb *v, hands_args *a, int argc, char **argv);

/* Under the patch law without --patch-mm: the Hertz contact modulus of the design's
 * ball on --table into a->o (tippe_launch_patch_modulus). A library status. */
int hands_patch(hands_args *a, const tippe_design *d, tippe_error *err);

const char *hands_group_meaning(tippe_group g);

/* The text lines: the top at z2 (with its zone and thresholds), the launch
 * distribution (fixed_spin: the spin is not drawn) and the model. */
void hands_print_top(const tippe_design *d, double z2, const tippe_top *t, double g,
                     const tippe_sweep_point_zone *z);
void hands_print_distribution(const tippe_launch_options *o, int fixed_spin);
void hands_print_model(const tippe_launch_options *o, const tippe_top *top);
/* The stepper that runs for o (tippe_dynamics_stepper_used): its name, or, where the law
 * runs another than the one named, stiff (a format of the stepper and the law, "%s for
 * the stiff %s law"). Returns buf. */
const char *hands_stepper_text(const tippe_launch_options *o, const char *stiff, char *buf,
                               size_t size);

/* The JSON of one tally (the options: tippe_launch_options_json; theory beside
 * a tally: tippe_sweep_theory_json). */
struct cJSON *hands_json_tally(const tippe_launch_tally *t);

extern const char *const hands_verdict_names[TIPPE_LAUNCH_N_VERDICTS];

/* ---- ranks (mpi.c): 0 and 1 without MPI ---- */
int hands_mpi_rank(void);
int hands_mpi_size(void);
/* The worst status of all ranks, so that no rank waits for work that will not come. */
int hands_mpi_agree(int status);
/* Runs every launch of the plan into rec (on rank 0; other ranks only help).
 * Returns the error of the lowest-numbered failed launch, if any. */
int hands_run_plan(const tippe_launch_plan *plan, const tippe_launch_options *o, uint64_t seed,
                   tippe_launch_record *rec, tippe_progress *prog, tippe_error *err);

#endif
