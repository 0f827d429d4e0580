/* Private to the tippe command: one function per verb, each in src/cli/<verb>.c.
 * A verb parses its own arguments, calls the library, prints, and returns the
 * exit status: 0 success, 2 bad usage or bad input, 1 failed computation.
 * Output files go through tippe/base.h, so that none is ever half-written. */
#ifndef TIPPE_CLI_H
#define TIPPE_CLI_H

#include <math.h>
#include <stdio.h>

#include "tippe/physics.h"
#include "tippe/scenario.h"

/* A macro's value as a string literal, for defaults quoted in --help texts. */
#define TIPPE_CLI_STR_(x) #x
#define TIPPE_CLI_STR(x) TIPPE_CLI_STR_(x)
#include "tippe/base.h"

struct cJSON;

typedef struct {
    const char *name;
    int (*run)(int argc, char **argv); /* argv[0] is the verb's name */
    const char *summary;
    /* tippe-mpi: 1 if every rank takes part (the verb shares its work among
     * the ranks), 0 if rank 0 runs it alone. */
    int mpi_all_ranks;
} tippe_cli_verb;

/* The one verb table (src/cli/verbs.c), for tippe and tippe-mpi alike. */
extern const tippe_cli_verb tippe_cli_verbs[];
extern const int tippe_cli_n_verbs;
/* The verb called name, or NULL. */
const tippe_cli_verb *tippe_cli_find_verb(const char *name);

int tippe_cli_eval(int argc, char **argv);
int tippe_cli_classify(int argc, char **argv);
int tippe_cli_simulate(int argc, char **argv);
int tippe_cli_sweep(int argc, char **argv);
int tippe_cli_optimise(int argc, char **argv);
int tippe_cli_compare(int argc, char **argv);
int tippe_cli_launch(int argc, char **argv);
int tippe_cli_map(int argc, char **argv);
int tippe_cli_check(int argc, char **argv);
int tippe_cli_materials(int argc, char **argv);
int tippe_cli_animate(int argc, char **argv);
int tippe_cli_export(int argc, char **argv);
int tippe_cli_build(int argc, char **argv);
int tippe_cli_slice(int argc, char **argv);
int tippe_cli_serve(int argc, char **argv);
/* Under mpirun with more than one rank (OMPI_COMM_WORLD_SIZE > 1), replaces the
 * process by tippe-mpi from the same directory with the same arguments; returns
 * only if it cannot (2, with a message) or if not under mpirun (0). */
int tippe_cli_mpi_reexec(int argc, char **argv);

/* ---- the option parser every verb uses (src/cli/options.c) ----
 *
 * A verb describes its options in one table; the same table drives the
 * parsing (getopt_long: "--opt=value" and "--opt value", "-n 5"; a long
 * option by its whole name only, never a prefix) and the generated --help. Numbers are checked against their allowed range, and a
 * number whose unit is one of the unit families below may carry a unit
 * suffix, converted to the option's unit:
 *   rad/s (spin and other angular rates): 125rad/s, 20rev/s, 1200rpm
 *   mm (lengths): 5mm, 0.5cm, 0.005m          rad (angles): 0.1rad, 6deg
 * A number without a suffix is in the option's unit. */
typedef enum {
    TIPPE_CLI_FLAG,   /* no value; int *value = 1 */
    TIPPE_CLI_STRING, /* const char **value = the text as typed */
    TIPPE_CLI_DOUBLE, /* double *value, finite, in min .. max */
    TIPPE_CLI_LONG,   /* long *value, whole, in min .. max */
    TIPPE_CLI_RANGE,  /* tippe_cli_range *value: "X", "FROM:TO" or "FROM:TO:STEPS" */
    TIPPE_CLI_SET     /* tippe_cli_sets *value: appends the text (repeatable) */
} tippe_cli_kind;

/* A range of numbers: "X" (from = to = X, steps 1), "FROM:TO" (steps 0) or,
 * for an option with max_steps > 0, "FROM:TO:STEPS" (STEPS in 1 .. max_steps). */
typedef struct {
    double from, to;
    long steps;
} tippe_cli_range;

typedef struct tippe_cli_opt {
    const char *name;  /* long name without "--"; NULL ends the table */
    char short_name;   /* e.g. 'n' for -n, 0 if none */
    tippe_cli_kind kind;
    void *value;       /* where the value goes (see tippe_cli_kind) */
    const char *arg;   /* the value's placeholder in --help, e.g. "FILE" (default: UNIT or X) */
    const char *unit;  /* unit of the value, e.g. "mm"; NULL for none */
    double min, max;   /* allowed values (DOUBLE, LONG, both ends of a RANGE) */
    const char *def;   /* the default as shown in --help; NULL: no default */
    const char *help;  /* one line or more ("\n" starts a continuation line) */
    int required;      /* 1: the verb cannot run without it */
    long max_steps;    /* RANGE: largest STEPS; 0: "FROM:TO" without steps */
    const char *field; /* with value a tippe_cli_sets *: the option is a shorthand
                        * for --set FIELD=VALUE (numbers in the option's unit) */
    int seen;          /* set by tippe_cli_parse: the option was given */
} tippe_cli_opt;

typedef struct {
    const char *verb;
    const char *synopsis; /* after "usage: tippe VERB " */
    const char *about;    /* paragraph before the options */
    const char *after;    /* text after the options: outputs, exit status, docs */
    tippe_cli_opt *opts;  /* ends with {NULL}; --help is added */
    int min_args, max_args;  /* positional arguments (files) */
    const char *args_name;   /* what they are, for messages: "design file" */
    int quiet_help;          /* 1: --help prints nothing (tippe-mpi's other ranks) */
    int progress;            /* 1: long work: --progress is added (tippe_cli_progress_mode) */
} tippe_cli_spec;

enum { TIPPE_CLI_HELP = -1 };

/* Largest |Z2| any verb accepts, mm: a top a metre across is not a tippe top. */
#define TIPPE_CLI_Z2_MAX_MM 1000.0

/* Options several verbs read, defined once so that each verb takes the same
 * range and says the same in --help (issue 19.10). */
/* Largest launch spin any verb accepts, rad/s (1592 rev/s: ten times what a
 * hand or a launcher gives a tippe top). */
#define TIPPE_CLI_SPIN_MAX_RAD_S 1e4
/* Largest --seed: seeds go into JSON as numbers, exact up to 2^53. */
#define TIPPE_CLI_SEED_MAX 9007199254740991.0
#define TIPPE_CLI_THREADS_MAX 4096
/* --seed S into the long *P; HELP says what it seeds. */
#define TIPPE_CLI_SEED_OPT(P, HELP)                                                              \
    {.name = "seed", .kind = TIPPE_CLI_LONG, .value = (P), .arg = "S", .min = 0,                \
     .max = TIPPE_CLI_SEED_MAX, .def = "1", .help = (HELP)}
/* --threads N into the long *P (0 when not given: OMP_NUM_THREADS or all cores). */
#define TIPPE_CLI_THREADS_OPT(P, HELP)                                                           \
    {.name = "threads", .kind = TIPPE_CLI_LONG, .value = (P), .arg = "N", .min = 1,             \
     .max = TIPPE_CLI_THREADS_MAX, .def = "OMP_NUM_THREADS or all cores", .help = (HELP)}

/* Parses argv[1 .. argc-1] (argv[0] is the verb) into the options' values and
 * the positional arguments into args[0 .. *n_args-1] (room for max_args).
 * Returns 0, TIPPE_CLI_HELP after printing --help on stdout (the verb exits
 * 0), or 2 after a usage error on stderr. */
int tippe_cli_parse(tippe_cli_spec *spec, int argc, char **argv, const char **args,
                    int *n_args);

/* How a verb shows progress on stderr (tippe/base.h): TIPPE_PROGRESS_ON
 * after --progress (plain lines when stderr is not a terminal), else
 * TIPPE_PROGRESS_AUTO (a bar on a terminal only). */
int tippe_cli_progress_mode(void);

/* Prints the --help generated from spec. */
void tippe_cli_help(const tippe_cli_spec *spec, FILE *out);

/* Reads text as a number in unit (with an optional unit suffix of unit's
 * family): 1 if it is one, else 0. */
int tippe_cli_parse_unit(const char *text, const char *unit, double *out);

/* The option of the table called name (without "--"), or NULL. */
tippe_cli_opt *tippe_cli_find_opt(tippe_cli_spec *spec, const char *name);

/* ---- argument plumbing every verb shares (src/cli/args.c) ---- */

/* Prints "tippe VERB: MESSAGE (try tippe VERB --help)" on stderr; returns 2. */
int tippe_cli_usage_error(const char *verb, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));

/* Prints "tippe VERB: " and err's message on stderr; returns the exit status
 * for the library status rc (2 bad input, 1 failed computation). */
int tippe_cli_fail(const char *verb, const tippe_error *err, int rc);

/* 1 for "--help" and "-h". */
int tippe_cli_is_help(const char *arg);

/* A whole finite number (strtod) or a whole integer in lo .. hi (strtol):
 * 1 if text is one, 0 if not (*out unchanged for the integer). */
int tippe_cli_parse_double(const char *text, double *out);
int tippe_cli_parse_long(const char *text, long lo, long hi, long *out);

/* "FROM:TO" (steps NULL) or "FROM:TO:STEPS" with STEPS in 1 .. max_steps; a
 * single step needs FROM = TO. 1 if text is one, else 0. */
int tippe_cli_parse_range(const char *text, double *from, double *to, int *steps, int max_steps);

/* Overrides of design or scenario fields, "FIELD=VALUE", in the order given. */
enum { TIPPE_CLI_MAX_SETS = 64 };
typedef struct {
    const char *item[TIPPE_CLI_MAX_SETS];
    int n;
    char text[TIPPE_CLI_MAX_SETS][512]; /* item[k] of an option that names its field */
} tippe_cli_sets;

/* Appends value ("FIELD=VALUE" as the user typed it, kept by reference) or,
 * with field, "field=value" (copied). 0, or -1 if the list is full. */
int tippe_cli_sets_add(tippe_cli_sets *s, const char *field, const char *value);
/* Appends one --set value: 0, or 2 after the usage error "too many --set
 * options (at most 64)". */
int tippe_cli_add_set(const char *verb, tippe_cli_sets *s, const char *value);

/* The changes as one line for titles and reports, "radius_mm=30,
 * parts.rod.material=nylon" (cut with "..." to fit size), or "" without any.
 * Returns buf. */
const char *tippe_cli_sets_text(const tippe_cli_sets *s, char *buf, size_t size);
/* Adds the changes to o as "set": ["FIELD=VALUE", ...] (an empty array without
 * any), so that a report never claims to show the file's design when it shows
 * a variant. */
void tippe_cli_json_sets(struct cJSON *o, const tippe_cli_sets *s);

/* An output file (plot: its extension names a plot format) that can be
 * written, found by really creating (and removing) a temporary next to it
 * (tippe/base.h): 0, or 2 after a usage error naming option, path and
 * reason (a directory, a path through a file, /proc, no permission, or the
 * same file as an earlier output of this run). "-" is standard output, and
 * from then on the verb's text (printf) goes to stderr, so that a piped file
 * is only the file. Every
 * verb calls it for every output before any work, so that bad usage leaves
 * nothing and costs nothing. A plot is also refused (2) when the command's
 * plotting module (src/modules/) does not load: said before the work, not after. */
int tippe_cli_check_output(const char *verb, const char *option, const char *path, int plot);
/* The output directory of a verb that writes one (export, build): created if
 * missing (one level, its parent must exist): 0, or 2 after a usage error
 * naming option ("-", a file, no parent, no permission). One made by this run is
 * removed again when the run fails (tippe_cli_run, after its files are
 * dropped), so a failed run leaves nothing. */
int tippe_cli_make_output_dir(const char *verb, const char *option, const char *dir);
/* Records the verb's input files (tippe_cli_parse does it for the positional
 * arguments): tippe_cli_check_output refuses an output that is one of them. */
void tippe_cli_note_inputs(const char *const *paths, int n);
/* Records whether --json prints to standard output (tippe_cli_parse does it):
 * tippe_cli_check_output then refuses an output named "-", as it refuses a
 * second one. */
void tippe_cli_note_json(int json);

/* Runs verb v (argv[0] is its name) the way both front ends do: signals stop
 * it cleanly (tippe_cli_signals_install), its output files form one set that
 * is committed only if it succeeds, and a failed write to standard output is a
 * failure (exit 1 with a message). Returns the exit status. */
int tippe_cli_run(const tippe_cli_verb *v, int argc, char **argv);

/* ---- signals (src/cli/signals.c) ----
 * SIGINT, SIGTERM, SIGHUP (and, quietly, SIGPIPE) remove every temporary output
 * file and end the process at once as killed by that signal (exit status
 * 128 + signal: 130, 143), after the one line "tippe VERB: stopped by SIGINT;
 * ..."; files already in place are never touched. SIGXFSZ (ulimit -f) is
 * caught so that the write fails with EFBIG and is reported. Nothing to poll:
 * a verb (or a library loop) needs no cancel flag; it only has to write its
 * files through tippe/base.h. */
void tippe_cli_signals_install(const char *verb);
/* After the outputs were renamed into place: if a stop signal came during the
 * renames, says so and ends the process by it; otherwise returns 0. */
int tippe_cli_signal_pending(const char *verb);
/* mkdir(dir, 0777) with the stop signals held off until the new directory is
 * noted: a stop signal then removes it (rmdir: only while it is empty, after
 * the temporaries in it were removed), as a failed run does. 0, or -1 with
 * errno set. */
int tippe_cli_signals_mkdir(const char *dir);
/* The directory tippe_cli_signals_mkdir made in this run, or NULL. */
const char *tippe_cli_signals_made_dir(void);

/* Prints the design's probable unit mistakes (tippe_design_warning) on stderr,
 * "tippe VERB: warning: FILE: ...", after a design loaded. */
struct tippe_design;
void tippe_cli_design_warnings(const char *verb, const struct tippe_design *d);

/* Prints o (NULL: out of memory while building it) as JSON on stdout and
 * deletes it: 0, or 1 after "tippe VERB: out of memory while writing JSON". */
int tippe_cli_print_json(const char *verb, struct cJSON *o);


/* How a dynamics verdict was reached (src/cli/verdict_out.c), the same words in
 * simulate, check and launch: the final state, the decision (trapped,
 * lost_contact, t_end), its time, barrier gap, margin and contact bound. */
void tippe_cli_print_verdict_proof(const tippe_dynamics_result *r, const char *prefix);
/* The same as JSON fields of o: decided_by, decision_t_s, theta_final_rad,
 * spin_final_rad_s, phi_dot_final_rad_s, theta_range_rad, barrier_gap_J,
 * margin_J, Rn_bound_N, t_flip_s (null where not applicable). */
void tippe_cli_json_verdict_proof(struct cJSON *o, const tippe_dynamics_result *r);
/* Where the design's material stands out of its sphere at the Z2 of a result
 * (tippe_design_protrusion_at), the top rests on it and the model (contact on
 * the sphere only) does not apply: prints "PREFIXINVALID at Z2 = ... mm: part
 * ... stands out ..., so WHAT no prediction" (what: "the verdict above is") and returns
 * 1; prints nothing and returns 0 where the model applies. */
int tippe_cli_print_model_validity(const tippe_design_protrusion *p, double z2_mm,
                                   const char *prefix, const char *what);
/* The same onto out (a report that gives standard output to a '-' file). */
int tippe_cli_fprint_model_validity(FILE *out, const tippe_design_protrusion *p, double z2_mm,
                                    const char *prefix, const char *what);

/* v, or null where it is not finite (not applicable). */
void tippe_cli_json_number_or_null(struct cJSON *o, const char *key, double v);
/* [lo, hi], or null where either is not finite. */

/* ---- one launch, from a scenario file or a design (tippe simulate, animate) ---- */

/* Largest spin or other rate a launch option takes, rad/s. */
#define TIPPE_CLI_RATE_MAX_RAD_S 1e5

typedef struct {
    double z2_mm;
    const char *phi_dot;  /* --phi-dot as typed: a rule or a rate */
    int theta_given, spin_given; /* --theta, --spin were given (for messages) */
    /* the option each of over's first n_named items stands for ("theta"), or
     * NULL: a message blaming the item names the option instead */
    const char *over_opt[TIPPE_CLI_MAX_SETS];
    int n_named;
    int is_design;        /* the file is a design (it has "parts") */
    tippe_cli_sets over;  /* scenario fields: the option shorthands (and a scenario's --set) */
    tippe_cli_sets sets;  /* --set as given: of the scenario, or of the design */
    char friction_help[512]; /* --friction's help, made from the laws' table */
} tippe_cli_launch_args;

/* The launch options both verbs read alike, for their option tables:
 * --z2, --spin, --theta, --theta-dot, --phi-dot, --U, --V, --mu, --g, --t-end,
 * --accuracy, --stepper, --rtol and --set, into the tippe_cli_launch_args *L. */
#define TIPPE_CLI_LAUNCH_OPTS(L)                                                                   \
    {.name = "z2", .kind = TIPPE_CLI_DOUBLE, .value = &(L)->z2_mm, .arg = "MM", .unit = "mm",    \
     .min = -TIPPE_CLI_Z2_MAX_MM, .max = TIPPE_CLI_Z2_MAX_MM,                                     \
     .help = "the moving weight's position: required with a design; with a scenario\n"           \
             "whose top is a design, its top.z2_mm"},                                             \
    {.name = "spin", .kind = TIPPE_CLI_DOUBLE, .value = &(L)->over, .field = "initial.spin",      \
     .arg = "RATE", .unit = "rad/s", .min = -TIPPE_CLI_SPIN_MAX_RAD_S,                            \
     .max = TIPPE_CLI_SPIN_MAX_RAD_S,                                                              \
     .help = "spin about the symmetry axis (initial.spin; design: 15rev/s);\n"                   \
             "negative: the other way round, a mirror image of the same launch"},                 \
    {.name = "theta", .kind = TIPPE_CLI_DOUBLE, .value = &(L)->over, .field = "initial.theta",    \
     .unit = "rad", .min = 0, .max = M_PI, .help = "tilt (initial.theta; design: 0.0674)"},       \
    {.name = "theta-dot", .kind = TIPPE_CLI_DOUBLE, .value = &(L)->over,                          \
     .field = "initial.theta_dot", .arg = "RATE", .unit = "rad/s",                                \
     .min = -TIPPE_CLI_RATE_MAX_RAD_S, .max = TIPPE_CLI_RATE_MAX_RAD_S,                           \
     .help = "tilt rate (initial.theta_dot; design: 0)"},                                         \
    {.name = "phi-dot", .kind = TIPPE_CLI_STRING, .value = &(L)->phi_dot, .arg = "RATE|RULE",     \
     .unit = "rad/s", .min = -TIPPE_CLI_RATE_MAX_RAD_S, .max = TIPPE_CLI_RATE_MAX_RAD_S,          \
     .help = "precession (initial.phi_dot): rad/s, or steady, s1, s2, s3 (design:\n"             \
             "steady); a rule's rate must lie in the range a number may"},                        \
    {.name = "U", .kind = TIPPE_CLI_DOUBLE, .value = &(L)->over, .field = "initial.U",            \
     .unit = "m/s", .min = -100, .max = 100,                                                       \
     .help = "sliding velocity of the centre (initial.U; design: 0)"},                            \
    {.name = "V", .kind = TIPPE_CLI_DOUBLE, .value = &(L)->over, .field = "initial.V",            \
     .unit = "m/s", .min = -100, .max = 100, .help = "its other component (initial.V; design: 0)"}, \
    {.name = "friction", .kind = TIPPE_CLI_STRING, .value = &(L)->over,                         \
     .field = "friction.law", .arg = "LAW",                                                       \
     .help = tippe_friction_law_help(70, "; design: viscous", (L)->friction_help,               \
                                     sizeof (L)->friction_help)},                                 \
    {.name = "patch-mm", .kind = TIPPE_CLI_DOUBLE, .value = &(L)->over,                           \
     .field = "friction.patch_mm", .arg = "A", .unit = "mm", .min = 0, .max = 10,                 \
     .help = "patch law: the contact patch's radius (friction.patch_mm; default: Hertz's\n"      \
             "at m g from the ball's material and --table; alone, it selects patch)"},            \
    {.name = "table", .kind = TIPPE_CLI_STRING, .value = &(L)->over, .field = "friction.table",  \
     .arg = "SURFACE",                                                                             \
     .help = "patch law: the table's surface for the Hertz patch (friction.table):\n"           \
             "glass, laminate, wood or steel; default laminate; alone, it selects patch"},       \
    {.name = "mu-c", .kind = TIPPE_CLI_DOUBLE, .value = &(L)->over, .field = "friction.mu",      \
     .arg = "X", .min = 0, .max = 10,                                                              \
     .help = "Coulomb friction coefficient (friction.mu; given alone on a viscous\nlaw, it selects coulomb; default " TIPPE_CLI_STR(TIPPE_LAUNCH_DEFAULT_MU_C) ")"}, \
    {.name = "slip-scale", .kind = TIPPE_CLI_DOUBLE, .value = &(L)->over,                         \
     .field = "friction.slip_scale_m_s", .arg = "V", .unit = "m/s", .min = 1e-9, .max = 1,      \
     .help = "Coulomb's regularisation speed v_s (docs/dynamics.md; default 1e-5;\nselects coulomb as --mu-c does)"}, \
    {.name = "creep-cap", .kind = TIPPE_CLI_DOUBLE, .value = &(L)->over,                          \
     .field = "friction.creep_cap", .arg = "K", .min = 0, .max = 1e4,                            \
     .help = "patch law: the creep reduction's cap (friction.creep_cap; default " TIPPE_CLI_STR(TIPPE_PATCH_CREEP_CAP) ";\n0: the full law, with msbdf; docs/dynamics.md, \"The creep reduced\")"}, \
    {.name = "mu", .kind = TIPPE_CLI_DOUBLE, .value = &(L)->over, .field = "mu", .unit = "s/m",   \
     .min = 0, .max = 1e6, .help = "viscous sliding friction, eq 3.12: sets the viscous law\n(design: " TIPPE_CLI_STR(TIPPE_LAUNCH_DEFAULT_MU_S_M) ")"}, \
    {.name = "g", .kind = TIPPE_CLI_DOUBLE, .value = &(L)->over, .field = "g", .unit = "m/s^2",   \
     .min = 0.01, .max = 1000, .help = "gravity (design: 9.81)"},                                 \
    {.name = "t-end", .kind = TIPPE_CLI_DOUBLE, .value = &(L)->over, .field = "t_end",            \
     .unit = "s", .min = 1e-3, .max = 1e6, .help = "longest simulated time (design: 600)"},       \
    {.name = "accuracy", .kind = TIPPE_CLI_STRING, .value = &(L)->over, .field = "accuracy",      \
     .arg = "PRESET", .help = "fast, balanced or precise (design: balanced)"},                    \
    {.name = "stepper", .kind = TIPPE_CLI_STRING, .value = &(L)->over,                            \
     .field = "accuracy.stepper", .arg = "NAME",                                                  \
     .help = "a GSL stepper instead of the preset's (docs/dynamics.md)"},                         \
    {.name = "rtol", .kind = TIPPE_CLI_DOUBLE, .value = &(L)->over, .field = "accuracy.rtol",     \
     .min = 1e-14, .max = 1e-2, .help = "relative tolerance instead of the preset's"},            \
    {.name = "set", .kind = TIPPE_CLI_SET, .value = &(L)->sets, .arg = "FIELD=VALUE",             \
     .help = "any field of the scenario (e.g. --set top.C=1e-6) or, with a design,\n"            \
             "of the design (e.g. --set radius_mm=30); repeatable"}

/* After tippe_cli_parse(): tells a design from a scenario by file's content,
 * requires --z2 with a design, and turns --phi-dot, a scenario's --z2 and
 * its --set into overrides. 0, or 2 after a usage error. */
int tippe_cli_launch_finish(const char *verb, tippe_cli_spec *spec, const char *file,
                            tippe_cli_launch_args *l);

/* The launch as a scenario: the file's, or the design's central hand launch
 * (tippe_scenario_for_design), with the overrides. A library status. A
 * precession that a rule derives from --theta, --spin or --phi-dot RULE must lie
 * in the range --phi-dot allows a number (TIPPE_CLI_RATE_MAX_RAD_S): else
 * TIPPE_EINPUT naming the option to change. */
int tippe_cli_launch_load(const char *file, const tippe_cli_launch_args *l,
                          tippe_scenario *sc, tippe_error *err);

/* Seconds on the monotonic clock, for the run times the verbs report. */
double tippe_cli_now_s(void);

#endif
