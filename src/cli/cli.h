/* Private to the tippe command: one function per verb, each in src/cli/<verb>.c.
 * A verb parses its own arguments, calls the library, prints, and returns the
 * exit status: 0 success, 2 bad usage or bad input, 1 failed computation.
 * Output files go through tippe/report.h, so that none is ever half-written. */
#ifndef TIPPE_CLI_H
#define TIPPE_CLI_H

#include <stdio.h>

#include "tippe/dynamics.h"
#include "tippe/error.h"

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
int tippe_cli_compare(int argc, char **argv);
int tippe_cli_launch(int argc, char **argv);
int tippe_cli_map(int argc, char **argv);
int tippe_cli_check(int argc, char **argv);
int tippe_cli_export(int argc, char **argv);
/* Under mpirun with more than one rank (OMPI_COMM_WORLD_SIZE > 1), replaces the
 * process by tippe-mpi from the same directory with the same arguments; returns
 * only if it cannot (2, with a message) or if not under mpirun (0). */
int tippe_cli_mpi_reexec(int argc, char **argv);

/* ---- argument plumbing every verb shares (src/cli/common.c) ---- */

/* Prints "tippe VERB: MESSAGE (try tippe VERB --help)" on stderr; returns 2. */
int tippe_cli_usage_error(const char *verb, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));

/* Prints "tippe VERB: " and err's message on stderr; returns the exit status
 * for the library status rc (2 bad input, 1 failed computation). */
int tippe_cli_fail(const char *verb, const tippe_error *err, int rc);

/* 1 for "--help" and "-h". */
int tippe_cli_is_help(const char *arg);

/* 1 if arg is an option rather than a file name: "-" followed by something;
 * with numbers_are_values, "-5" or "-0.3" is not an option. */
int tippe_cli_is_option(const char *arg, int numbers_are_values);

/* The value of the option argv[*i]: the next argument (*i moves onto it), or
 * NULL after the usage error "OPTION needs a value". */
const char *tippe_cli_value(const char *verb, int argc, char **argv, int *i);

/* Whether argv[*i] is the option name ("--z2") given as "--z2 VALUE" or, with
 * eq, as "--z2=VALUE". On a match *value is VALUE, or NULL after the usage
 * error "--z2 needs a value". */
int tippe_cli_option(const char *verb, int argc, char **argv, int *i, const char *name, int eq,
                     const char **value);

/* A whole finite number (strtod) or a whole integer in lo .. hi (strtol):
 * 1 if text is one, 0 if not (*out unchanged for the integer). */
int tippe_cli_parse_double(const char *text, double *out);
int tippe_cli_parse_long(const char *text, long lo, long hi, long *out);

/* "FROM:TO" (steps NULL) or "FROM:TO:STEPS" with STEPS in 1 .. max_steps; a
 * single step needs FROM = TO. 1 if text is one, else 0. */
int tippe_cli_parse_range(const char *text, double *from, double *to, int *steps, int max_steps);

/* Parses option's number: 0, or 2 after the usage error
 * "OPTION: 'TEXT' is not a number" (followed by " of UNIT" unless unit is NULL). */
int tippe_cli_number(const char *verb, const char *option, const char *text, const char *unit,
                     double *out);

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

/* An output file (plot: its extension names a plot format) whose directory
 * can be written: 0, or 2 after a usage error naming option, path and reason.
 * Checked before any work, so that bad usage leaves nothing and costs nothing. */
int tippe_cli_check_output(const char *verb, const char *option, const char *path, int plot);

/* Prints o (NULL: out of memory while building it) as JSON on stdout and
 * deletes it: 0, or 1 after "tippe VERB: out of memory while writing JSON". */
int tippe_cli_print_json(const char *verb, struct cJSON *o);

/* Adds {"preset": preset, "stepper": ..., "rtol": ...} to o as "accuracy", the
 * same object in every verb that integrates. */
void tippe_cli_json_accuracy(struct cJSON *o, const char *preset,
                             const tippe_dynamics_accuracy *acc);

/* Seconds on the monotonic clock, for the run times the verbs report. */
double tippe_cli_now_s(void);

#endif
