/* Argument plumbing shared by the verbs of the tippe command (see cli.h), so
 * that every verb words its usage errors, reads numbers and --set options and
 * checks its output files the same way. */
#include "cli.h"
#include "../modules/module.h"

#include "tippe/design.h"
#include "base/json.h"
#include "tippe/plot.h"
#include "tippe/base.h"

#include <cjson/cJSON.h>

#include <errno.h>
#include <pthread.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <sys/stat.h>
#include <unistd.h>

int tippe_cli_usage_error(const char *verb, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "tippe %s: ", verb);
    vfprintf(stderr, fmt, ap);
    fprintf(stderr, " (try tippe %s --help)\n", verb);
    va_end(ap);
    return 2;
}

int tippe_cli_fail(const char *verb, const tippe_error *err, int rc)
{
    fprintf(stderr, "tippe %s: %s\n", verb, err->msg);
    return rc == TIPPE_EINPUT ? 2 : 1;
}

int tippe_cli_is_help(const char *arg)
{
    return !strcmp(arg, "--help") || !strcmp(arg, "-h");
}

int tippe_cli_parse_double(const char *text, double *out)
{
    /* No errno test: an underflow to 0 or a subnormal is still the number the
     * user meant, and an overflow is caught as infinite. */
    char *end = NULL;
    *out = strtod(text, &end);
    return end != text && *end == '\0' && isfinite(*out);
}

int tippe_cli_parse_long(const char *text, long lo, long hi, long *out)
{
    char *end = NULL;
    errno = 0;
    long v = strtol(text, &end, 10);
    if (end == text || *end != '\0' || errno != 0 || v < lo || v > hi)
        return 0;
    *out = v;
    return 1;
}

int tippe_cli_parse_range(const char *text, double *from, double *to, int *steps, int max_steps)
{
    char buf[256];
    if (strlen(text) >= sizeof buf)
        return 0;
    snprintf(buf, sizeof buf, "%s", text);
    char *c1 = strchr(buf, ':');
    if (!c1)
        return 0;
    *c1 = '\0';
    char *c2 = strchr(c1 + 1, ':');
    if ((c2 != NULL) != (steps != NULL))
        return 0;
    if (c2)
        *c2 = '\0';
    if (!tippe_cli_parse_double(buf, from) || !tippe_cli_parse_double(c1 + 1, to))
        return 0;
    if (steps) {
        long s;
        if (!tippe_cli_parse_long(c2 + 1, 1, max_steps, &s) || (s == 1 && *from != *to))
            return 0;
        *steps = (int)s;
    }
    return 1;
}

int tippe_cli_sets_add(tippe_cli_sets *s, const char *field, const char *value)
{
    if (s->n == TIPPE_CLI_MAX_SETS)
        return -1;
    if (field) {
        snprintf(s->text[s->n], sizeof s->text[s->n], "%s=%s", field, value);
        s->item[s->n] = s->text[s->n];
    } else {
        s->item[s->n] = value;
    }
    s->n++;
    return 0;
}

int tippe_cli_add_set(const char *verb, tippe_cli_sets *s, const char *value)
{
    if (tippe_cli_sets_add(s, NULL, value))
        return tippe_cli_usage_error(verb, "too many --set options (at most %d)",
                                     TIPPE_CLI_MAX_SETS);
    return 0;
}

const char *tippe_cli_sets_text(const tippe_cli_sets *s, char *buf, size_t size)
{
    size_t len = 0;
    buf[0] = '\0';
    for (int i = 0; i < s->n; i++) {
        int n = snprintf(buf + len, size - len, "%s%s", i ? ", " : "", s->item[i]);
        if (n < 0 || (size_t)n >= size - len) {
            if (size > 4)
                snprintf(buf + size - 4, 4, "...");
            break;
        }
        len += (size_t)n;
    }
    return buf;
}

void tippe_cli_json_sets(cJSON *o, const tippe_cli_sets *s)
{
    cJSON *a = cJSON_AddArrayToObject(o, "set");
    for (int i = 0; a && i < s->n; i++)
        cJSON_AddItemToArray(a, cJSON_CreateString(s->item[i]));
}

/* The files the verb's outputs finally name, to refuse two outputs that are
 * one file (each would replace the other). */
enum { MAX_OUTPUTS = 16 };
static struct {
    char file[4096 + 256];
    const char *option;
} checked[MAX_OUTPUTS];
static int n_checked;

/* dir's real path + "/" + base of a (link-resolved) target: one name per file. */
static int canonical_name(const char *target, char *out, size_t size)
{
    char dir[4096];
    const char *slash = strrchr(target, '/');
    const char *base = slash ? slash + 1 : target;
    if (!slash)
        snprintf(dir, sizeof dir, ".");
    else if (slash == target)
        snprintf(dir, sizeof dir, "/");
    else
        snprintf(dir, sizeof dir, "%.*s", (int)(slash - target), target);
    char real[PATH_MAX];
    if (!realpath(dir, real))
        return 0;
    return snprintf(out, size, "%s/%s", real, base) < (int)size;
}

/* The verb's input files (its positional arguments), to refuse an output that
 * would replace one of them. */
enum { MAX_INPUTS = 16 };
static struct {
    const char *path;
    dev_t dev;
    ino_t ino;
} inputs[MAX_INPUTS];
static int n_inputs;

void tippe_cli_note_inputs(const char *const *paths, int n)
{
    n_inputs = 0;
    for (int i = 0; i < n && n_inputs < MAX_INPUTS; i++) {
        struct stat st;
        if (strcmp(paths[i], "-") && stat(paths[i], &st) == 0 && S_ISREG(st.st_mode)) {
            inputs[n_inputs].path = paths[i];
            inputs[n_inputs].dev = st.st_dev;
            inputs[n_inputs++].ino = st.st_ino;
        }
    }
}

/* The input that path (through any symlink) already is, or NULL. */
static const char *input_named_by(const char *path)
{
    struct stat st;
    if (!strcmp(path, "-") || stat(path, &st) != 0)
        return NULL;
    for (int i = 0; i < n_inputs; i++)
        if (inputs[i].dev == st.st_dev && inputs[i].ino == st.st_ino)
            return inputs[i].path;
    return NULL;
}

/* Every file the run has read or is about to read through tippe/json.h (a
 * design's materials table, a spec's catalogue and base design, a scenario's
 * design), and the existing files the outputs name: an output is refused when
 * it is one of them, whichever the run meets first. Reads may come from
 * several threads (an optimiser's candidates), hence the lock. */
enum { MAX_READ = 64 };
static struct {
    char path[512];
    char what[64];
    dev_t dev;
    ino_t ino;
} read_files[MAX_READ];
static int n_read;
static struct {
    const char *option, *path;
    dev_t dev;
    ino_t ino;
} out_ids[MAX_OUTPUTS];
static int n_out_ids;
static pthread_mutex_t read_lock = PTHREAD_MUTEX_INITIALIZER;

static int refuse_read_output(const char *path, const char *what, tippe_error *err)
{
    struct stat st;
    if (stat(path, &st) != 0 || !S_ISREG(st.st_mode))
        return TIPPE_OK; /* reading it fails with its own message */
    int rc = TIPPE_OK;
    pthread_mutex_lock(&read_lock);
    for (int i = 0; i < n_out_ids; i++)
        if (out_ids[i].dev == st.st_dev && out_ids[i].ino == st.st_ino) {
            rc = tippe_error_set(err, TIPPE_EINPUT,
                                 "%s %s is the %s file '%s' that this run reads: it would be "
                                 "replaced; choose another output name",
                                 out_ids[i].option, out_ids[i].path, what, path);
            break;
        }
    int known = 0;
    for (int i = 0; i < n_read && !known; i++)
        known = read_files[i].dev == st.st_dev && read_files[i].ino == st.st_ino;
    if (!rc && !known && n_read < MAX_READ) {
        snprintf(read_files[n_read].path, sizeof read_files[n_read].path, "%s", path);
        snprintf(read_files[n_read].what, sizeof read_files[n_read].what, "%s", what);
        read_files[n_read].dev = st.st_dev;
        read_files[n_read++].ino = st.st_ino;
    }
    pthread_mutex_unlock(&read_lock);
    return rc;
}

/* Notes that option writes path, and returns the read file path already is
 * (an index of read_files), or -1. */
static int note_output_id(const char *option, const char *path)
{
    struct stat st;
    if (!strcmp(path, "-") || stat(path, &st) != 0 || !S_ISREG(st.st_mode))
        return -1;
    pthread_mutex_lock(&read_lock);
    int found = -1;
    for (int i = 0; i < n_read && found < 0; i++)
        if (read_files[i].dev == st.st_dev && read_files[i].ino == st.st_ino)
            found = i;
    if (n_out_ids < MAX_OUTPUTS) {
        out_ids[n_out_ids].option = option;
        out_ids[n_out_ids].path = path;
        out_ids[n_out_ids].dev = st.st_dev;
        out_ids[n_out_ids++].ino = st.st_ino;
    }
    pthread_mutex_unlock(&read_lock);
    return found;
}

/* Who writes to standard output besides the text: --json, or an output named "-". */
static const char *stdout_owner;

void tippe_cli_note_json(int json)
{
    stdout_owner = json ? "--json" : NULL;
}

int tippe_cli_check_output(const char *verb, const char *option, const char *path, int plot)
{
    if (!strcmp(path, "-")) {
        if (stdout_owner)
            return tippe_cli_usage_error(verb, "%s -: standard output already carries %s; "
                                         "give %s a file name", option, stdout_owner, option);
        stdout_owner = option;
        /* The data owns descriptor 1 (tippe/report.h writes "-" there); the
         * text report goes to stderr so that the piped file stays clean.
         * glibc's stdout is an ordinary variable that may be set. */
        fflush(stdout);
        stdout = stderr;
    }
    const char *input = input_named_by(path);
    if (input)
        return tippe_cli_usage_error(verb, "%s %s is the input file '%s': it would be "
                                     "replaced; choose another output name",
                                     option, path, input);
    const int read = note_output_id(option, path);
    if (read >= 0)
        return tippe_cli_usage_error(verb, "%s %s is the %s file '%s' that this run reads: it "
                                     "would be replaced; choose another output name", option,
                                     path, read_files[read].what, read_files[read].path);
    if (plot && !tippe_plot_device(path))
        return tippe_cli_usage_error(
            verb, "%s %s: unsupported plot format (use a .png, .svg or .pdf file name)", option,
            path);
    tippe_error err = {0};
    if (tippe_report_check(path, plot ? "the plot" : "the output file", &err))
        return tippe_cli_usage_error(verb, "%s %s", option, err.msg);
    char target[4096], name[sizeof checked[0].file];
    struct stat st;
    if (strcmp(path, "-") && tippe_report_target(path, target, sizeof target, &err) == 0 &&
        (stat(target, &st) != 0 || S_ISREG(st.st_mode)) &&
        canonical_name(target, name, sizeof name)) {
        for (int i = 0; i < n_checked; i++)
            if (!strcmp(checked[i].file, name) && strcmp(checked[i].option, option))
                return tippe_cli_usage_error(verb, "%s and %s name the same file '%s'",
                                             checked[i].option, option, path);
        if (n_checked < MAX_OUTPUTS) {
            memcpy(checked[n_checked].file, name, sizeof name);
            checked[n_checked++].option = option;
        }
    }
    /* The plotting module is loaded now: if it is missing, say so before the work. */
    if (plot && tippe_module_plot_ready(&err))
        return tippe_cli_fail(verb, &err, TIPPE_EINPUT);
    return 0;
}

/* The directory tippe_cli_make_output_dir created in this run, if any. */
static char made_dir[4096];

int tippe_cli_make_output_dir(const char *verb, const char *option, const char *dir)
{
    struct stat st;
    if (!strcmp(dir, "-")) /* several files cannot share standard output */
        return tippe_cli_usage_error(verb, "%s -: %s writes several files into a directory, not "
                                     "to standard output; give a directory", option, verb);
    if (stat(dir, &st) == 0)
        return S_ISDIR(st.st_mode) ? 0
                                   : tippe_cli_usage_error(verb, "%s %s: not a directory", option,
                                                           dir);
    if (mkdir(dir, 0777) != 0)
        return tippe_cli_usage_error(verb, "%s %s: cannot create the directory: %s", option, dir,
                                     strerror(errno));
    snprintf(made_dir, sizeof made_dir, "%s", dir);
    return 0;
}

int tippe_cli_run(const tippe_cli_verb *v, int argc, char **argv)
{
    tippe_cli_signals_install(v->name);
    tippe_report_set_begin();
    tippe_json_set_read_check(refuse_read_output);
    int status = v->run(argc, argv);
    /* Stdout is an output like the others: a full disk or a closed pipe there
     * is a failure, and the files of a failed run are not committed. */
    errno = 0;
    if (fflush(stdout) != 0 || ferror(stdout)) {
        const int e = errno ? errno : EIO;
        fprintf(stderr, "tippe %s: writing to standard output failed: %s\n", v->name,
                strerror(e));
        if (status == 0)
            status = 1;
    }
    tippe_error err = {0};
    if (status != 0) {
        tippe_report_set_abort();
        /* rmdir takes only an empty directory: one holding other files stays */
        if (made_dir[0])
            rmdir(made_dir);
    } else if (tippe_report_set_commit(&err) != TIPPE_OK)
        status = tippe_cli_fail(v->name, &err, TIPPE_ECOMPUTE);
    const int stopped = tippe_cli_signal_pending(v->name);
    return stopped ? stopped : status;
}

int tippe_cli_print_json(const char *verb, cJSON *o)
{
    char *s = o ? cJSON_Print(o) : NULL;
    cJSON_Delete(o);
    if (!s) {
        fprintf(stderr, "tippe %s: out of memory while writing JSON\n", verb);
        return 1;
    }
    printf("%s\n", s);
    free(s);
    return 0;
}

void tippe_cli_json_accuracy(cJSON *o, const char *preset, const tippe_dynamics_accuracy *acc)
{
    cJSON *a = cJSON_AddObjectToObject(o, "accuracy");
    if (a) {
        cJSON_AddStringToObject(a, "preset", preset);
        cJSON_AddStringToObject(a, "stepper", acc->stepper);
        cJSON_AddNumberToObject(a, "rtol", acc->rtol);
    }
}

double tippe_cli_now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void tippe_cli_design_warnings(const char *verb, const tippe_design *d)
{
    char msg[512];
    for (int i = 0; tippe_design_warning(d, i, msg, sizeof msg); i++)
        fprintf(stderr, "tippe %s: warning: %s: %s\n", verb, tippe_design_path(d), msg);
}

/* ---- one launch, from a scenario file or a design ---------------------------- */

/* The file's kind: a design has "parts" at its top (a scenario never has). */
static int is_design_file(const char *path)
{
    tippe_error err;
    tippe_json_reader *c = tippe_json_reader_new(path, &err, TIPPE_JSON_WORDS_KEY, "");
    cJSON *root = NULL;
    int design = c && tippe_json_load(c, 16, "file", &root) == TIPPE_OK &&
                 cJSON_IsObject(root) && cJSON_GetObjectItemCaseSensitive(root, "parts");
    cJSON_Delete(root);
    free(c);
    return design;
}

/* --phi-dot: a rule, or a rate with its unit, as the override initial.phi_dot. */
static int add_phi_dot(const char *verb, tippe_cli_launch_args *l)
{
    static const char *const rules[] = {"steady", "s1", "s2", "s3"};
    for (int i = 0; i < 4; i++)
        if (!strcmp(l->phi_dot, rules[i]))
            return tippe_cli_sets_add(&l->over, "initial.phi_dot", l->phi_dot) ? 2 : 0;
    double x;
    char num[64];
    if (!tippe_cli_parse_unit(l->phi_dot, "rad/s", &x) || !(fabs(x) <= TIPPE_CLI_RATE_MAX_RAD_S))
        return tippe_cli_usage_error(verb,
                                     "--phi-dot '%s': expected steady, s1, s2, s3 or a number "
                                     "of rad/s from -%g to %g",
                                     l->phi_dot, TIPPE_CLI_RATE_MAX_RAD_S,
                                     TIPPE_CLI_RATE_MAX_RAD_S);
    snprintf(num, sizeof num, "%.17g", x);
    return tippe_cli_sets_add(&l->over, "initial.phi_dot", num) ? 2 : 0;
}

/* --friction, --mu, --mu-c and --slip-scale name one law, as in tippe launch (a
 * coefficient alone selects its law: the scenario's overrides do that). 0, or 2. */
static int check_friction_opts(const char *verb, tippe_cli_spec *spec,
                               const tippe_cli_launch_args *l)
{
    const tippe_cli_opt *fr = tippe_cli_find_opt(spec, "friction");
    const tippe_cli_opt *mu = tippe_cli_find_opt(spec, "mu");
    const tippe_cli_opt *mu_c = tippe_cli_find_opt(spec, "mu-c");
    const tippe_cli_opt *vs = tippe_cli_find_opt(spec, "slip-scale");
    const int mu_seen = mu && mu->seen, mu_c_seen = mu_c && mu_c->seen;
    const int coulomb_seen = mu_c_seen || (vs && vs->seen);
    const char *law = NULL; /* --friction's value: the last friction.law override */
    if (fr && fr->seen)
        for (int i = 0; i < l->over.n; i++)
            if (!strncmp(l->over.item[i], "friction.law=", 13))
                law = l->over.item[i] + 13;
    if (!law && mu_seen && coulomb_seen)
        return tippe_cli_usage_error(verb, "--mu (s/m, viscous) and --mu-c or --slip-scale "
                                           "(Coulomb) name different laws: give one, or "
                                           "--friction");
    if (law && !strcmp(law, "viscous") && coulomb_seen)
        return tippe_cli_usage_error(verb, "%s: with the viscous law give --mu (s/m)",
                                     mu_c_seen ? "--mu-c is the Coulomb coefficient"
                                               : "--slip-scale is the Coulomb law's "
                                                 "regularisation");
    if (law && strcmp(law, "viscous") != 0 && mu_seen)
        return tippe_cli_usage_error(verb, "--mu (s/m) is the viscous coefficient: with the "
                                           "%s law give --mu-c",
                                     law);
    return 0;
}

int tippe_cli_launch_finish(const char *verb, tippe_cli_spec *spec, const char *file,
                            tippe_cli_launch_args *l)
{
    int rc;
    if ((rc = check_friction_opts(verb, spec, l)) != 0)
        return rc;
    if (l->phi_dot && (rc = add_phi_dot(verb, l)) != 0)
        return rc;
    const int has_z2 = tippe_cli_find_opt(spec, "z2")->seen;
    l->is_design = is_design_file(file);
    if (l->is_design && !has_z2)
        return tippe_cli_usage_error(verb, "--z2 MM is required with a design file");
    if (!l->is_design && has_z2) {
        char num[64];
        snprintf(num, sizeof num, "%.17g", l->z2_mm);
        tippe_cli_sets_add(&l->over, "top.z2_mm", num);
    }
    if (!l->is_design) /* --set names scenario fields, after the shorthands */
        for (int i = 0; i < l->sets.n; i++)
            if (tippe_cli_sets_add(&l->over, NULL, l->sets.item[i]))
                return tippe_cli_usage_error(verb, "more than %d overrides", TIPPE_CLI_MAX_SETS);
    return 0;
}

int tippe_cli_launch_load(const char *file, const tippe_cli_launch_args *l, tippe_scenario *sc,
                          tippe_error *err)
{
    return l->is_design ? tippe_scenario_for_design(file, l->z2_mm, l->sets.item, l->sets.n,
                                                    l->over.item, l->over.n, sc, err)
                        : tippe_scenario_load(file, l->over.item, l->over.n, sc, err);
}
