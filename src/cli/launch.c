/* tippe launch, tippe map, tippe check: hand launches of a design's top
 * (tippe/launch.h), on OpenMP threads and, in tippe-mpi, across MPI ranks.
 *
 * This file is compiled twice: into `tippe`, and with TIPPE_WITH_MPI into
 * `tippe-mpi` (src/cli/main_mpi.c), where launch and map share their launches
 * among the ranks: rank 0 hands out chunks of launch indices to the other ranks
 * as they return results, computes chunks itself in between, and alone writes
 * output. Every launch depends only on (seed, draw, top, options), so the
 * result is the single-process result whatever the number of ranks. */
#include "cli.h"

#include "tippe/design.h"
#include "tippe/launch.h"
#include "tippe/plot.h"
#include "tippe/progress.h"
#include "tippe/report.h"
#include "tippe/sweep.h"
#include "tippe/theory.h"

#include <cjson/cJSON.h>
#include <errno.h>
#include <inttypes.h>
#include <limits.h>
#include <math.h>
#include <omp.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#ifdef TIPPE_WITH_MPI
#include <mpi.h>
#endif

/* Largest --seed: seeds go into JSON as numbers, exact up to 2^53. */
#define SEED_MAX 9007199254740991.0

enum { V_LAUNCH = 1, V_MAP = 2, V_CHECK = 4 };

static const char *const verdict_names[TIPPE_LAUNCH_N_VERDICTS] = {
    "no_tip", "tip", "hang", "lost_contact", "undecided", "bounded"};

/* ---- MPI ------------------------------------------------------------------ */

static int mpi_rank(void)
{
#ifdef TIPPE_WITH_MPI
    int r = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &r);
    return r;
#else
    return 0;
#endif
}

static int mpi_size(void)
{
#ifdef TIPPE_WITH_MPI
    int s = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &s);
    return s;
#else
    return 1;
#endif
}

/* All ranks go on only if every rank got this far (they parse the same
 * arguments, but a rank must never wait for work that will not come). */
static int mpi_agree(int status)
{
#ifdef TIPPE_WITH_MPI
    int worst = status;
    MPI_Allreduce(&status, &worst, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    return worst;
#else
    return status;
#endif
}

int tippe_cli_mpi_reexec(int argc, char **argv)
{
#ifndef TIPPE_WITH_MPI
    const char *size = getenv("OMPI_COMM_WORLD_SIZE");
    if (!size || atoi(size) <= 1)
        return 0;
    const char *rank = getenv("OMPI_COMM_WORLD_RANK");
    const int quiet = rank && atoi(rank) != 0; /* one message, not one per rank */
    char exe[PATH_MAX];
    ssize_t len = readlink("/proc/self/exe", exe, sizeof exe - 16);
    if (len <= 0) {
        if (!quiet)
            fprintf(stderr, "tippe: running under mpirun with %s ranks, but cannot find my own "
                            "directory (/proc/self/exe) to run tippe-mpi from\n", size);
        return 2;
    }
    exe[len] = '\0';
    char *slash = strrchr(exe, '/');
    snprintf(slash ? slash + 1 : exe, sizeof exe - (size_t)(slash ? slash + 1 - exe : 0),
             "tippe-mpi");
    if (access(exe, X_OK) != 0) {
        if (!quiet)
            fprintf(stderr,
                    "tippe: running under mpirun with %s ranks, but %s was not built (configure "
                    "with Open MPI installed, e.g. apt-get install libopenmpi-dev, to get it); "
                    "run tippe without mpirun instead\n", size, exe);
        return 2;
    }
    char **args = malloc((size_t)(argc + 1) * sizeof *args);
    if (!args)
        return 1;
    args[0] = exe;
    for (int i = 1; i < argc; i++)
        args[i] = argv[i];
    args[argc] = NULL;
    execv(exe, args);
    if (!quiet)
        fprintf(stderr, "tippe: cannot run %s: %s\n", exe, strerror(errno));
    free(args);
    return 2;
#else
    (void)argc;
    (void)argv;
    return 0;
#endif
}

#ifdef TIPPE_WITH_MPI
enum { TAG_WORK = 7101, TAG_RESULT = 7102 };

/* Launches per chunk: a quarter of an even share of what is left (guided
 * scheduling: big chunks first, small ones at the end for balance), at least
 * one per OpenMP thread. */
static long chunk_size(long remaining, int ranks)
{
    long c = remaining / (4L * ranks);
    long t = omp_get_max_threads();
    if (c < t)
        c = t;
    return c < remaining ? c : remaining;
}

/* Rank 0: keeps every worker two chunks ahead (so that a worker never waits
 * while rank 0 computes a chunk of its own) and collects results into rec. */
static int mpi_master(const tippe_launch_plan *plan, const tippe_launch_options *o,
                      uint64_t seed, tippe_launch_record *rec, tippe_progress *prog,
                      tippe_error *err)
{
    const int size = mpi_size();
    const long total = tippe_launch_plan_total(plan);
    long next = 0;
    int *assigned = calloc((size_t)size, sizeof *assigned);
    if (!assigned)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    int active = 0;
    for (int w = 1; w < size; w++) {
        for (int k = 0; k < 2 && next < total; k++) {
            long c = chunk_size(total - next, size), msg[2] = {next, next + c};
            MPI_Send(msg, 2, MPI_LONG, w, TAG_WORK, MPI_COMM_WORLD);
            next += c;
            assigned[w]++;
        }
        if (assigned[w])
            active++;
        else {
            long stop[2] = {-1, -1};
            MPI_Send(stop, 2, MPI_LONG, w, TAG_WORK, MPI_COMM_WORLD);
        }
    }
    int status = TIPPE_OK;
    char *buf = NULL;
    size_t buf_size = 0;
    for (;;) {
        int flag = 0;
        MPI_Status st;
        if (next < total) {
            MPI_Iprobe(MPI_ANY_SOURCE, TAG_RESULT, MPI_COMM_WORLD, &flag, &st);
            if (!flag) {
                long c = chunk_size(total - next, size), from = next;
                next += c;
                tippe_error e;
                tippe_launch_run(plan, o, seed, from, from + c, rec + from, prog, &e);
                continue;
            }
        } else {
            if (active == 0)
                break;
            MPI_Probe(MPI_ANY_SOURCE, TAG_RESULT, MPI_COMM_WORLD, &st);
        }
        int bytes = 0;
        MPI_Get_count(&st, MPI_BYTE, &bytes);
        if ((size_t)bytes > buf_size) {
            char *nb = realloc(buf, (size_t)bytes);
            if (!nb) {
                status = tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory receiving results");
                MPI_Abort(MPI_COMM_WORLD, 1);
            }
            buf = nb;
            buf_size = (size_t)bytes;
        }
        MPI_Recv(buf, bytes, MPI_BYTE, st.MPI_SOURCE, TAG_RESULT, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE);
        long range[2];
        memcpy(range, buf, sizeof range);
        memcpy(rec + range[0], buf + sizeof range,
               (size_t)(range[1] - range[0]) * sizeof *rec);
        tippe_progress_add(prog, range[1] - range[0]);
        const int w = st.MPI_SOURCE;
        assigned[w]--;
        if (next < total) {
            long c = chunk_size(total - next, size), msg[2] = {next, next + c};
            MPI_Send(msg, 2, MPI_LONG, w, TAG_WORK, MPI_COMM_WORLD);
            next += c;
            assigned[w]++;
        } else if (assigned[w] == 0) {
            long stop[2] = {-1, -1};
            MPI_Send(stop, 2, MPI_LONG, w, TAG_WORK, MPI_COMM_WORLD);
            active--;
        }
    }
    free(buf);
    free(assigned);
    return status;
}

/* Other ranks: compute chunks as they come, send each back without waiting
 * (the next chunk is already queued), until told to stop. */
static void mpi_worker(const tippe_launch_plan *plan, const tippe_launch_options *o,
                       uint64_t seed)
{
    long cur[2];
    MPI_Recv(cur, 2, MPI_LONG, 0, TAG_WORK, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    MPI_Request req = MPI_REQUEST_NULL;
    char *sending = NULL;
    while (cur[0] >= 0) {
        const long n = cur[1] - cur[0];
        const size_t bytes = 2 * sizeof(long) + (size_t)n * sizeof(tippe_launch_record);
        char *buf = malloc(bytes);
        if (!buf)
            MPI_Abort(MPI_COMM_WORLD, 1);
        memcpy(buf, cur, 2 * sizeof(long));
        tippe_error e;
        tippe_launch_run(plan, o, seed, cur[0], cur[1],
                         (tippe_launch_record *)(void *)(buf + 2 * sizeof(long)), NULL, &e);
        MPI_Wait(&req, MPI_STATUS_IGNORE);
        free(sending);
        MPI_Isend(buf, (int)bytes, MPI_BYTE, 0, TAG_RESULT, MPI_COMM_WORLD, &req);
        sending = buf;
        MPI_Recv(cur, 2, MPI_LONG, 0, TAG_WORK, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    }
    MPI_Wait(&req, MPI_STATUS_IGNORE);
    free(sending);
}
#endif

/* Runs every launch of the plan into rec (on rank 0; other ranks only help).
 * Returns the error of the lowest-numbered failed launch, if any. */
static int run_plan(const tippe_launch_plan *plan, const tippe_launch_options *o, uint64_t seed,
                    tippe_launch_record *rec, tippe_progress *prog, tippe_error *err)
{
    const long total = tippe_launch_plan_total(plan);
#ifdef TIPPE_WITH_MPI
    if (mpi_size() > 1) {
        if (mpi_rank() != 0) {
            mpi_worker(plan, o, seed);
            return TIPPE_OK;
        }
        int rc = mpi_master(plan, o, seed, rec, prog, err);
        if (rc)
            return rc;
        for (long i = 0; i < total; i++)
            if (rec[i].status != TIPPE_OK) /* rerun the one launch for its message */
                return tippe_launch_run(plan, o, seed, i, i + 1, rec + i, NULL, err);
        return TIPPE_OK;
    }
#endif
    return tippe_launch_run(plan, o, seed, 0, total, rec, prog, err);
}

/* ---- arguments ------------------------------------------------------------ */

typedef struct {
    const char *verb; /* "launch", "map", "check" */
    int mask;         /* V_LAUNCH, ... */
    const char *design, *z2_text, *spin_text, *csv, *plot;
    long n;
    int has_n;
    uint64_t seed;
    int json, threads;
    tippe_launch_options o;
    tippe_cli_sets sets;
} args;

/* The ranges of hand launches rise: FROM <= TO, and FROM < TO over several steps. */
static int parse_rising(const char *text, double *from, double *to, int *steps, int max_steps)
{
    return tippe_cli_parse_range(text, from, to, steps, max_steps) &&
           (steps && *steps > 1 ? *from < *to : *from <= *to);
}

/* Parses the options every verb shares; verb-specific meaning of --z2 and
 * --spin is left to the verb. Returns -1 after --help, else an exit status. */
static int parse_args(args *a, int argc, char **argv)
{
    tippe_launch_options_default(&a->o);
    a->seed = 1;
    for (int i = 1; i < argc; i++) {
        const char *s = argv[i];
        if (tippe_cli_is_help(s))
            return -1;
        if (!strcmp(s, "--json")) {
            a->json = 1;
            continue;
        }
        if (!tippe_cli_is_option(s, 1)) {
            if (a->design)
                return tippe_cli_usage_error(a->verb, "one design file only (got '%s' and '%s')",
                                             a->design, s);
            a->design = s;
            continue;
        }
        static const struct {
            const char *name;
            int verbs;
        } known[] = {
            {"-n", V_LAUNCH | V_MAP},          {"--seed", V_LAUNCH | V_MAP},
            {"--z2", V_LAUNCH | V_MAP | V_CHECK},
            {"--spin", V_MAP | V_CHECK},       {"--spin-rev-s", V_LAUNCH},
            {"--tilt-rad", V_LAUNCH | V_MAP | V_CHECK},
            {"--tilt-max-rad", V_LAUNCH | V_MAP},
            {"--precession-rel", V_LAUNCH | V_MAP},
            {"--slide-m-s", V_LAUNCH | V_MAP}, {"--mu", V_LAUNCH | V_MAP | V_CHECK},
            {"--g", V_LAUNCH | V_MAP | V_CHECK}, {"--t-end", V_LAUNCH | V_MAP | V_CHECK},
            {"--accuracy", V_LAUNCH | V_MAP | V_CHECK},
            {"--stepper", V_LAUNCH | V_MAP | V_CHECK},
            {"--rtol", V_LAUNCH | V_MAP | V_CHECK}, {"--csv", V_LAUNCH | V_MAP},
            {"--plot", V_MAP},                 {"--set", V_LAUNCH | V_MAP | V_CHECK},
            {"--threads", V_LAUNCH | V_MAP},
        };
        int k = -1;
        for (int j = 0; j < (int)(sizeof known / sizeof known[0]); j++)
            if (!strcmp(s, known[j].name))
                k = j;
        if (k < 0 || !(known[k].verbs & a->mask))
            return tippe_cli_usage_error(a->verb, "unknown option '%s'", s);
        const char *v = tippe_cli_value(a->verb, argc, argv, &i);
        if (!v)
            return 2;
        double x;
        long l;
        tippe_launch_options *o = &a->o;
        if (!strcmp(s, "-n")) {
            if (!tippe_cli_parse_long(v, 1, 10000000, &a->n))
                return tippe_cli_usage_error(
                    a->verb, "-n '%s': expected a whole number of launches, 1 .. 10^7", v);
            a->has_n = 1;
        } else if (!strcmp(s, "--seed")) {
            if (!tippe_cli_parse_double(v, &x) || x < 0 || x > SEED_MAX || x != floor(x))
                return tippe_cli_usage_error(
                    a->verb, "--seed '%s': expected a whole number 0 .. 2^53 - 1", v);
            a->seed = (uint64_t)x;
        } else if (!strcmp(s, "--z2")) {
            a->z2_text = v;
        } else if (!strcmp(s, "--spin")) {
            a->spin_text = v;
        } else if (!strcmp(s, "--spin-rev-s")) {
            if (!parse_rising(v, &o->spin_from_rev_s, &o->spin_to_rev_s, NULL, 0) ||
                o->spin_from_rev_s < 0)
                return tippe_cli_usage_error(
                    a->verb, "--spin-rev-s '%s': expected FROM:TO in rev/s, 0 <= FROM <= TO", v);
        } else if (!strcmp(s, "--threads")) {
            if (!tippe_cli_parse_long(v, 1, 4096, &l))
                return tippe_cli_usage_error(a->verb, "--threads '%s': expected 1 .. 4096", v);
            a->threads = (int)l;
        } else if (!strcmp(s, "--csv")) {
            a->csv = v;
        } else if (!strcmp(s, "--plot")) {
            a->plot = v;
        } else if (!strcmp(s, "--set")) {
            if (tippe_cli_add_set(a->verb, &a->sets, v))
                return 2;
        } else if (!strcmp(s, "--accuracy")) {
            tippe_error e;
            if (tippe_dynamics_accuracy_preset(v, &o->accuracy, &e))
                return tippe_cli_usage_error(a->verb, "--accuracy: %s", e.msg);
            snprintf(o->accuracy_name, sizeof o->accuracy_name, "%s", v);
        } else if (!strcmp(s, "--stepper")) {
            if (!tippe_dynamics_stepper_known(v) || strlen(v) >= sizeof o->accuracy.stepper)
                return tippe_cli_usage_error(
                    a->verb,
                    "--stepper '%s': unknown (rk2, rk4, rkf45, rkck, rk8pd, "
                    "rk1imp, rk2imp, rk4imp, bsimp, msadams, msbdf)",
                    v);
            snprintf(o->accuracy.stepper, sizeof o->accuracy.stepper, "%s", v);
            snprintf(o->accuracy_name, sizeof o->accuracy_name, "custom");
        } else {
            /* the rest are plain numbers */
            if (!tippe_cli_parse_double(v, &x))
                return tippe_cli_usage_error(a->verb, "%s '%s': not a number", s, v);
            if (!strcmp(s, "--tilt-rad"))
                o->tilt_sd_rad = x;
            else if (!strcmp(s, "--tilt-max-rad"))
                o->tilt_max_rad = x;
            else if (!strcmp(s, "--precession-rel"))
                o->precession_sd_rel = x;
            else if (!strcmp(s, "--slide-m-s"))
                o->slide_sd_m_s = x;
            else if (!strcmp(s, "--mu"))
                o->mu = x;
            else if (!strcmp(s, "--g"))
                o->g = x;
            else if (!strcmp(s, "--t-end"))
                o->t_end = x;
            else if (!strcmp(s, "--rtol")) {
                o->accuracy.rtol = x;
                snprintf(o->accuracy_name, sizeof o->accuracy_name, "custom");
            }
        }
    }
    if (!a->design)
        return tippe_cli_usage_error(a->verb, "no design file given");
    if (!a->z2_text)
        return tippe_cli_usage_error(a->verb, "--z2 is required");
    tippe_error e;
    if (tippe_launch_options_check(&a->o, &e))
        return tippe_cli_usage_error(a->verb, "%s", e.msg);
    if (a->threads > 0)
        omp_set_num_threads(a->threads);
    return 0;
}

/* The zone of the design's sweep that contains z2 (over the stated travel). */
typedef struct {
    int ok;
    tippe_group group;
    double from_mm, to_mm;
} zone_at;

static void find_zone(const tippe_design *d, double z2, zone_at *z)
{
    memset(z, 0, sizeof *z);
    tippe_sweep_result r;
    tippe_error e;
    if (tippe_sweep_design(d, 0.0, 0.0, NULL, &r, &e) == TIPPE_OK)
        for (int i = 0; i < r.n_zones; i++)
            if (z2 >= r.zones[i].z2_from_mm && z2 <= r.zones[i].z2_to_mm) {
                z->ok = 1;
                z->group = r.zones[i].group;
                z->from_mm = r.zones[i].z2_from_mm;
                z->to_mm = r.zones[i].z2_to_mm;
                break;
            }
    tippe_sweep_result_free(&r);
}

static const char *group_meaning(tippe_group g)
{
    switch (g) {
    case TIPPE_GROUP_IA:
    case TIPPE_GROUP_IB: return "theta = 0 stable at every spin: no tipping";
    case TIPPE_GROUP_IIA: return "tips at high spin; the hanging branch folds";
    case TIPPE_GROUP_IIB: return "tips at high spin, hangs at moderate spin";
    case TIPPE_GROUP_IIC: return "tips completely above n-";
    case TIPPE_GROUP_III: return "theta = pi never stable: hangs at high spin";
    }
    return "";
}

static void print_top(const tippe_design *d, double z2, const tippe_top *t, double g,
                      const zone_at *z)
{
    tippe_theory_class cls;
    tippe_theory_classify(t->A / t->C, t->eps / t->R, &cls);
    printf("design     %s (%s) at Z2 = %g mm\n", tippe_design_name(d), tippe_design_path(d), z2);
    printf("top        m %.2f g, R %.2f mm, eps %.3f mm, A/C %.5f, eps/R %.5f: group %s (%s)\n",
           1e3 * t->m, 1e3 * t->R, 1e3 * t->eps, t->A / t->C, t->eps / t->R,
           tippe_group_name(cls.group), group_meaning(cls.group));
    if (z->ok)
        printf("zone       %s from %.3f to %.3f mm along the stated travel (tippe sweep)\n",
               tippe_group_name(z->group), z->from_mm, z->to_mm);
    tippe_theory_thresholds th;
    tippe_error e;
    if (tippe_theory_compute_thresholds(t, g, &th, &e) == TIPPE_OK) {
        printf("thresholds");
        if (th.has_n_minus)
            printf(" n- %.2f rev/s (theta = 0 unstable above);", th.n_minus_rad_s / (2 * M_PI));
        else
            printf(" n- none (theta = 0 stable at every spin);");
        if (th.has_n_star)
            printf(" n* %.2f rev/s (theta = pi stable above, from theta = 0)\n",
                   th.n_star_rad_s / (2 * M_PI));
        else
            printf(" n* none (theta = pi never stable)\n");
    }
}

static void print_distribution(const tippe_launch_options *o, int fixed_spin)
{
    if (!fixed_spin)
        printf("hands      spin uniform %g .. %g rev/s; ", o->spin_from_rev_s, o->spin_to_rev_s);
    else
        printf("hands      spin fixed per cell; ");
    printf("tilt half-normal, scale %g rad (redrawn above %g rad); precession steady x (1 + %g "
           "N(0,1)); sliding half-normal, scale %g m/s, random direction\n",
           o->tilt_sd_rad, o->tilt_max_rad, o->precession_sd_rel, o->slide_sd_m_s);
}

static void print_model(const tippe_launch_options *o)
{
    printf("model      mu %g s/m (viscous sliding, eq 3.12), g %g m/s^2, t_end %g s, accuracy %s "
           "(%s, rtol %g), verdict level\n",
           o->mu, o->g, o->t_end, o->accuracy_name, o->accuracy.stepper, o->accuracy.rtol);
}

static cJSON *json_options(const tippe_launch_options *o, int fixed_spin)
{
    cJSON *d = cJSON_CreateObject();
    if (!d)
        return NULL;
    if (!fixed_spin) {
        double sp[2] = {o->spin_from_rev_s, o->spin_to_rev_s};
        cJSON_AddItemToObject(d, "spin_uniform_rev_s", cJSON_CreateDoubleArray(sp, 2));
    }
    cJSON_AddNumberToObject(d, "tilt_half_normal_scale_rad", o->tilt_sd_rad);
    cJSON_AddNumberToObject(d, "tilt_max_rad", o->tilt_max_rad);
    cJSON_AddNumberToObject(d, "precession_rel_sd", o->precession_sd_rel);
    cJSON_AddNumberToObject(d, "slide_half_normal_scale_m_s", o->slide_sd_m_s);
    cJSON_AddNumberToObject(d, "mu_s_m", o->mu);
    cJSON_AddNumberToObject(d, "g_m_s2", o->g);
    cJSON_AddNumberToObject(d, "t_end_s", o->t_end);
    tippe_cli_json_accuracy(d, o->accuracy_name, &o->accuracy);
    return d;
}

static cJSON *json_counts(const tippe_launch_tally *t)
{
    cJSON *c = cJSON_CreateObject();
    for (int v = 0; c && v < TIPPE_LAUNCH_N_VERDICTS; v++)
        cJSON_AddNumberToObject(c, verdict_names[v], (double)t->counts[v]);
    return c;
}

/* Rounds the last bits away: "%.10g" etc. keep CSV deterministic and short. */
static int write_launch_csv(const char *path, const tippe_launch_record *r, long n,
                            tippe_error *err)
{
    tippe_report_file rf;
    int rc = tippe_report_open(&rf, path, "the CSV file", err);
    if (rc)
        return rc;
    FILE *f = rf.f;
    fprintf(f, "index,draw,spin_rad_s,spin_rev_s,tilt_rad,theta_dot_rad_s,phi_dot_rad_s,U_m_s,"
               "V_m_s,verdict,t_s,theta_final_rad,spin_final_rad_s,J0_kg_m3_s,jellett_rel_drift,"
               "rhs_evals,theory,theory_hang_theta_rad,agrees\n");
    for (long i = 0; i < n; i++) {
        const tippe_launch_record *x = &r[i];
        fprintf(f, "%ld,%ld,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%s,%.10g,%.10g,%.10g,%.10g,"
                   "%.3g,%ld,%s,",
                x->index, x->draw, x->ic.spin, x->ic.spin / (2 * M_PI), x->ic.theta,
                x->ic.theta_dot, x->ic.phi_dot, x->ic.U, x->ic.V, tippe_verdict_name(x->verdict),
                x->t_s, x->theta_final_rad, x->spin_final_rad_s, x->J0, x->jellett_rel_drift,
                x->rhs_evals, x->theory_ok ? tippe_launch_predicted_name(x->predicted) : "none");
        if (isfinite(x->hang_theta_rad))
            fprintf(f, "%.10g", x->hang_theta_rad);
        fprintf(f, ",%s\n", x->agrees > 0 ? "yes" : x->agrees == 0 ? "no" : "");
    }
    return tippe_report_commit(&rf, err);
}

/* ---- tippe launch ---------------------------------------------------------- */

static void launch_usage(FILE *out)
{
    fprintf(out,
        "usage: tippe launch DESIGN.json --z2 MM [-n N] [--seed S] [--spin-rev-s FROM:TO]\n"
        "                    [--mu S_PER_M] [--accuracy PRESET] [--json] [--csv FILE]\n"
        "                    [--set FIELD=VALUE ...] [more options below]\n"
        "\n"
        "Launches the design's top N times by hand, as a person would: a spin, a small tilt,\n"
        "a precession near the steady one and a little sliding, each drawn at random\n"
        "(docs/launch.md), and integrates each launch (the paper's section 3 model with\n"
        "viscous sliding friction) until it settles, leaves the table or reaches t_end.\n"
        "Prints how many launches end in no_tip, tip, hang, lost_contact and undecided, with\n"
        "95%% Wilson confidence intervals, beside Theorem 5.1's prediction for each launch's\n"
        "Jellett invariant and the fraction of launches that agree with it.\n"
        "\n"
        "  --z2 MM              position of the moving weight's midpoint, mm (in the travel)\n"
        "  -n N                 number of launches (default 50)\n"
        "  --seed S             random seed, 0 .. 2^53-1 (default 1); the same seed gives the\n"
        "                       same launches and counts on any number of threads or ranks\n"
        "  --spin-rev-s FROM:TO spin uniform in FROM .. TO rev/s (default 5:25)\n"
        "  --tilt-rad SD        tilt half-normal with scale SD, rad (default 0.1)\n"
        "  --tilt-max-rad MAX   tilts above MAX are drawn again, rad (default 1)\n"
        "  --precession-rel SD  precession = steady rate x (1 + SD N(0,1)) (default 0.1)\n"
        "  --slide-m-s SD       sliding speed half-normal with scale SD, m/s (default 0.05)\n"
        "  --mu S_PER_M         viscous sliding friction, s/m (default 2.3: docs/launch.md)\n"
        "  --g M_S2             gravity, m/s^2 (default 9.81)\n"
        "  --t-end S            longest simulated time of one launch, s (default 600)\n"
        "  --accuracy PRESET    fast, balanced or precise (default balanced)\n"
        "  --stepper NAME, --rtol X   a custom integrator instead of a preset\n"
        "  --json               print one JSON object (counts, n, ci95, theory, seed, ...)\n"
        "  --csv FILE           write one row per launch (initial state, verdict, t_s,\n"
        "                       theta_final, Jellett drift, theory's prediction)\n"
        "  --set FIELD=VALUE    change a field of the design, e.g. --set radius_mm=30\n"
        "  --threads N          OpenMP threads (default: OMP_NUM_THREADS or all cores)\n"
        "  --help               this text\n"
        "\n"
        "A progress bar with the time left is shown on stderr when it is a terminal. Under\n"
        "mpirun -np N (N > 1) the launches are shared among the ranks (tippe-mpi).\n"
        "Exit status: 0 ok, 2 bad usage or design, 1 a launch could not be computed.\n");
}

static void print_counts_table(const tippe_launch_tally *t)
{
    printf("\noutcome         count  share   95%% CI (Wilson)   median theta_final   median t "
           "decided\n");
    for (int v = 0; v < TIPPE_LAUNCH_N_VERDICTS; v++) {
        double lo, hi;
        tippe_launch_wilson(t->counts[v], t->n, TIPPE_LAUNCH_Z95, &lo, &hi);
        printf("%-14s %6ld  %5.3f   [%5.3f, %5.3f]", verdict_names[v], t->counts[v],
               t->n ? (double)t->counts[v] / (double)t->n : 0.0, lo, hi);
        if (t->counts[v])
            printf("    %7.4f rad %6.1f deg  %8.1f s\n", t->median_theta_rad[v],
                   t->median_theta_rad[v] * 180 / M_PI, t->median_t_s[v]);
        else
            printf("\n");
    }
}

static void print_theory_summary(const tippe_launch_tally *t)
{
    printf("\ntheory     Theorem 5.1 for each launch's Jellett invariant predicts:");
    int first = 1;
    for (unsigned m = 1; m < 8; m++)
        if (t->predicted[m]) {
            printf("%s %s %ld", first ? "" : ";", tippe_launch_predicted_name(m), t->predicted[m]);
            first = 0;
        }
    if (t->predicted[0])
        printf("%s no prediction %ld", first ? "" : ";", t->predicted[0]);
    printf("\n");
    double lo, hi;
    tippe_launch_wilson(t->agree, t->comparable, TIPPE_LAUNCH_Z95, &lo, &hi);
    if (t->comparable)
        printf("agreement  %ld of %ld settled launches end in a state theory predicts for their J "
               "(%.3f, 95%% CI [%.3f, %.3f]; a hang within %g rad)\n",
               t->agree, t->comparable, (double)t->agree / (double)t->comparable, lo, hi,
               TIPPE_LAUNCH_HANG_AGREE_RAD);
    else
        printf("agreement  no settled launch to compare\n");
    /* how the verdicts were reached (docs/dynamics.md, "Proved verdicts") */
    if (isfinite(t->min_gap_over_margin))
        printf("proof      no_tip/tip/hang proved by energy trapping and a contact bound; "
               "smallest barrier gap %.3g times its margin\n",
               t->min_gap_over_margin);
    if (t->flips)
        printf("flip       %ld tips followed to theta = 90 deg: median model time %.3g s\n",
               t->flips, t->median_t_flip_s);
}

static cJSON *tally_json(const tippe_launch_tally *t)
{
    cJSON *o = cJSON_CreateObject();
    if (!o)
        return NULL;
    cJSON_AddNumberToObject(o, "n", (double)t->n);
    cJSON_AddItemToObject(o, "counts", json_counts(t));
    cJSON_AddNumberToObject(o, "flips", (double)t->flips);
    if (t->flips)
        cJSON_AddNumberToObject(o, "median_t_flip_s", t->median_t_flip_s);
    else
        cJSON_AddNullToObject(o, "median_t_flip_s");
    if (isfinite(t->min_gap_over_margin))
        cJSON_AddNumberToObject(o, "min_gap_over_margin", t->min_gap_over_margin);
    else
        cJSON_AddNullToObject(o, "min_gap_over_margin");
    cJSON *fr = cJSON_AddObjectToObject(o, "fractions");
    cJSON *ci = cJSON_AddObjectToObject(o, "ci95");
    cJSON *mt = cJSON_AddObjectToObject(o, "median_theta_final_rad");
    cJSON *ms = cJSON_AddObjectToObject(o, "median_t_s");
    for (int v = 0; v < TIPPE_LAUNCH_N_VERDICTS; v++) {
        double lo, hi;
        tippe_launch_wilson(t->counts[v], t->n, TIPPE_LAUNCH_Z95, &lo, &hi);
        double b[2] = {lo, hi};
        if (fr)
            cJSON_AddNumberToObject(fr, verdict_names[v],
                                    t->n ? (double)t->counts[v] / (double)t->n : 0.0);
        if (ci)
            cJSON_AddItemToObject(ci, verdict_names[v], cJSON_CreateDoubleArray(b, 2));
        if (mt) {
            if (t->counts[v])
                cJSON_AddNumberToObject(mt, verdict_names[v], t->median_theta_rad[v]);
            else
                cJSON_AddNullToObject(mt, verdict_names[v]);
        }
        if (ms) {
            if (t->counts[v])
                cJSON_AddNumberToObject(ms, verdict_names[v], t->median_t_s[v]);
            else
                cJSON_AddNullToObject(ms, verdict_names[v]);
        }
    }
    return o;
}

static cJSON *theory_json(const tippe_top *t, double g, const zone_at *z,
                          const tippe_launch_tally *tl)
{
    cJSON *o = cJSON_CreateObject();
    if (!o)
        return NULL;
    tippe_theory_class cls;
    tippe_theory_classify(t->A / t->C, t->eps / t->R, &cls);
    cJSON_AddStringToObject(o, "group", tippe_group_name(cls.group));
    cJSON_AddNumberToObject(o, "A_over_C", t->A / t->C);
    cJSON_AddNumberToObject(o, "eps_over_R", t->eps / t->R);
    if (z->ok) {
        double b[2] = {z->from_mm, z->to_mm};
        cJSON_AddItemToObject(o, "zone_mm", cJSON_CreateDoubleArray(b, 2));
    } else {
        cJSON_AddNullToObject(o, "zone_mm");
    }
    tippe_theory_thresholds th;
    tippe_error e;
    if (tippe_theory_compute_thresholds(t, g, &th, &e) == TIPPE_OK) {
        if (th.has_n_minus)
            cJSON_AddNumberToObject(o, "n_minus_rev_s", th.n_minus_rad_s / (2 * M_PI));
        else
            cJSON_AddNullToObject(o, "n_minus_rev_s");
        if (th.has_n_star)
            cJSON_AddNumberToObject(o, "n_star_rev_s", th.n_star_rad_s / (2 * M_PI));
        else
            cJSON_AddNullToObject(o, "n_star_rev_s");
    }
    if (tl) {
        cJSON *p = cJSON_AddObjectToObject(o, "predicted");
        for (unsigned m = 0; p && m < 8; m++)
            if (tl->predicted[m])
                cJSON_AddNumberToObject(p, tippe_launch_predicted_name(m), (double)tl->predicted[m]);
        cJSON_AddNumberToObject(o, "agree", (double)tl->agree);
        cJSON_AddNumberToObject(o, "comparable", (double)tl->comparable);
        double lo, hi;
        tippe_launch_wilson(tl->agree, tl->comparable, TIPPE_LAUNCH_Z95, &lo, &hi);
        if (tl->comparable)
            cJSON_AddNumberToObject(o, "agreement", (double)tl->agree / (double)tl->comparable);
        else
            cJSON_AddNullToObject(o, "agreement");
        double b[2] = {lo, hi};
        cJSON_AddItemToObject(o, "agreement_ci95", cJSON_CreateDoubleArray(b, 2));
        cJSON_AddNumberToObject(o, "hang_tolerance_rad", TIPPE_LAUNCH_HANG_AGREE_RAD);
    }
    return o;
}

int tippe_cli_launch(int argc, char **argv)
{
    args a = {.verb = "launch", .mask = V_LAUNCH, .n = 50};
    int rc = parse_args(&a, argc, argv);
    if (rc < 0) {
        if (mpi_rank() == 0)
            launch_usage(stdout);
        return 0;
    }
    double z2 = 0.0;
    if (!rc && !tippe_cli_parse_double(a.z2_text, &z2))
        rc = tippe_cli_usage_error(a.verb, "--z2 '%s': expected a number of mm", a.z2_text);
    if (!rc && a.csv && mpi_rank() == 0)
        rc = tippe_cli_check_output(a.verb, "--csv", a.csv, 0);

    tippe_error err;
    tippe_design *d = NULL;
    tippe_top top;
    if (!rc && (rc = tippe_design_load(a.design, a.sets.item, a.sets.n, &d, &err)) != 0)
        rc = tippe_cli_fail(a.verb, &err, rc);
    if (!rc && (rc = tippe_design_top(d, z2, &top, &err)) != 0)
        rc = tippe_cli_fail(a.verb, &err, rc);
    tippe_launch_record *rec = NULL;
    if (!rc && !(rec = calloc((size_t)a.n, sizeof *rec))) {
        fprintf(stderr, "tippe launch: out of memory for %ld launches\n", a.n);
        rc = 1;
    }
    if ((rc = mpi_agree(rc)) != 0) {
        free(rec);
        tippe_design_free(d);
        return rc;
    }

    tippe_launch_plan plan = {1, a.n, &top, NULL};
    tippe_progress prog;
    tippe_progress_start(&prog, stderr, "tippe launch", a.n, TIPPE_PROGRESS_AUTO);
    const double t0 = tippe_cli_now_s();
    rc = run_plan(&plan, &a.o, a.seed, rec, &prog, &err);
    const double elapsed = tippe_cli_now_s() - t0;
    tippe_progress_finish(&prog);
    if (mpi_rank() != 0) {
        free(rec);
        tippe_design_free(d);
        return 0;
    }
    if (rc) {
        rc = tippe_cli_fail(a.verb, &err, rc);
        free(rec);
        tippe_design_free(d);
        return rc;
    }
    tippe_launch_tally t;
    if ((rc = tippe_launch_tally_records(rec, a.n, &t, &err)) == 0 && a.csv)
        rc = write_launch_csv(a.csv, rec, a.n, &err);
    if (rc) {
        rc = tippe_cli_fail(a.verb, &err, rc);
        free(rec);
        tippe_design_free(d);
        return rc;
    }
    zone_at z;
    find_zone(d, z2, &z);
    if (a.json) {
        /* No timings or thread counts: the JSON is the same on any machine
         * layout, byte for byte. */
        cJSON *o = tally_json(&t);
        if (o) {
            cJSON_AddStringToObject(o, "design", tippe_design_name(d));
            cJSON_AddStringToObject(o, "file", tippe_design_path(d));
            cJSON_AddNumberToObject(o, "z2_mm", z2);
            cJSON_AddNumberToObject(o, "seed", (double)a.seed);
            cJSON_AddItemToObject(o, "theory", theory_json(&top, a.o.g, &z, &t));
            cJSON_AddItemToObject(o, "distribution", json_options(&a.o, 0));
            cJSON_AddNumberToObject(o, "max_jellett_rel_drift", t.max_jellett_rel_drift);
            cJSON_AddNumberToObject(o, "rhs_evals", t.rhs_evals);
        }
        rc = tippe_cli_print_json(a.verb, o);
    } else {
        print_top(d, z2, &top, a.o.g, &z);
        printf("launches   %ld by hand, seed %" PRIu64 "\n", a.n, a.seed);
        print_distribution(&a.o, 0);
        print_model(&a.o);
        print_counts_table(&t);
        print_theory_summary(&t);
        printf("accuracy   largest Jellett drift %.2g; %.3g RHS evaluations; %.2f s on %d "
               "thread%s x %d rank%s (%.1f launches/s)\n",
               t.max_jellett_rel_drift, t.rhs_evals, elapsed, omp_get_max_threads(),
               omp_get_max_threads() > 1 ? "s" : "", mpi_size(), mpi_size() > 1 ? "s" : "",
               (double)a.n / elapsed);
        if (a.csv)
            printf("csv        %s (%ld launches)\n", a.csv, a.n);
    }
    free(rec);
    tippe_design_free(d);
    return rc;
}

/* ---- tippe map --------------------------------------------------------------- */

static void map_usage(FILE *out)
{
    fprintf(out,
        "usage: tippe map DESIGN.json --z2 FROM:TO:STEPS --spin FROM:TO:STEPS [-n PER_CELL]\n"
        "                 [--seed S] [--plot FILE] [--csv FILE] [--json] [options]\n"
        "\n"
        "Hand launches over a grid of weight positions Z2 (mm) and launch spins (rev/s):\n"
        "the share of no_tip, tip, hang, lost_contact and undecided in each cell. Within a\n"
        "cell the spin is fixed and the rest of each hand launch (tilt, precession, sliding)\n"
        "is drawn as in tippe launch; every cell uses the same N draws, so that differences\n"
        "between cells are not noise of the draws.\n"
        "\n"
        "  --z2 FROM:TO:STEPS   weight positions, mm, STEPS evenly spaced (in the travel)\n"
        "  --spin FROM:TO:STEPS launch spins in rev/s (revolutions per second), STEPS values\n"
        "  -n PER_CELL          launches per cell (default 10)\n"
        "  --seed S             random seed, 0 .. 2^53-1 (default 1)\n"
        "  --plot FILE          heat map (.png, .svg or .pdf): the most frequent outcome of\n"
        "                       each cell as colour, paler for a smaller share, with the\n"
        "                       zone boundaries of tippe sweep and the thresholds n-, n*\n"
        "  --csv FILE           one row per cell: counts of each outcome, theory agreement\n"
        "  --json               print one JSON object instead of the table\n"
        "  --tilt-rad SD, --tilt-max-rad MAX, --precession-rel SD, --slide-m-s SD,\n"
        "  --mu S_PER_M, --g M_S2, --t-end S, --accuracy PRESET, --stepper NAME, --rtol X,\n"
        "  --set FIELD=VALUE, --threads N   as for tippe launch (see tippe launch --help)\n"
        "  --help               this text\n"
        "\n"
        "Under mpirun -np N (N > 1) the launches of all cells are shared among the ranks.\n"
        "Exit status: 0 ok, 2 bad usage or design, 1 a launch could not be computed.\n");
}

static const char verdict_letter[TIPPE_LAUNCH_N_VERDICTS] = {'N', 'T', 'H', 'L', 'U', 'B'};

static int write_map_csv(const char *path, const tippe_launch_map *m, const tippe_top *tops,
                         tippe_error *err)
{
    tippe_report_file rf;
    int rc = tippe_report_open(&rf, path, "the CSV file", err);
    if (rc)
        return rc;
    FILE *f = rf.f;
    fprintf(f, "z2_mm,spin_rev_s,group,n,no_tip,tip,hang,lost_contact,undecided,agree,"
               "comparable,dominant,dominant_share\n");
    for (int i = 0; i < m->n_z2; i++)
        for (int j = 0; j < m->n_spin; j++) {
            const tippe_launch_tally *c = &m->cells[(long)i * m->n_spin + j];
            tippe_theory_class cls;
            tippe_theory_classify(tops[i].A / tops[i].C, tops[i].eps / tops[i].R, &cls);
            int v = tippe_launch_dominant(c);
            fprintf(f, "%.10g,%.10g,%s,%ld,%ld,%ld,%ld,%ld,%ld,%ld,%ld,%s,%.6g\n", m->z2_mm[i],
                    m->spin_rev_s[j], tippe_group_name(cls.group), c->n, c->counts[0],
                    c->counts[1], c->counts[2], c->counts[3], c->counts[4], c->agree,
                    c->comparable, verdict_names[v], (double)c->counts[v] / (double)c->n);
        }
    return tippe_report_commit(&rf, err);
}

static void print_map_table(const tippe_launch_map *m)
{
    printf("\nmost frequent outcome and its share in %% (N no_tip, T tip, H hang, L lost_contact, "
           "U undecided)\n");
    printf("spin rev/s |");
    for (int i = 0; i < m->n_z2; i++)
        printf(" %6.2f", m->z2_mm[i]);
    printf("   <- Z2 (mm)\n-----------+");
    for (int i = 0; i < m->n_z2; i++)
        printf("-------");
    printf("\n");
    for (int j = m->n_spin - 1; j >= 0; j--) {
        printf("%10.3g |", m->spin_rev_s[j]);
        for (int i = 0; i < m->n_z2; i++) {
            const tippe_launch_tally *c = &m->cells[(long)i * m->n_spin + j];
            int v = tippe_launch_dominant(c);
            printf("  %c%4.0f", verdict_letter[v], 100.0 * (double)c->counts[v] / (double)c->n);
        }
        printf("\n");
    }
}

int tippe_cli_map(int argc, char **argv)
{
    args a = {.verb = "map", .mask = V_MAP, .n = 10};
    int rc = parse_args(&a, argc, argv);
    if (rc < 0) {
        if (mpi_rank() == 0)
            map_usage(stdout);
        return 0;
    }
    double zf = 0, zt = 0, sf = 0, st = 0;
    int zn = 0, sn = 0;
    if (!rc && !parse_rising(a.z2_text, &zf, &zt, &zn, 1000))
        rc = tippe_cli_usage_error(
            a.verb,
            "--z2 '%s': expected FROM:TO:STEPS in mm with FROM < TO and 1 .. "
            "1000 STEPS (one step: FROM = TO)",
            a.z2_text);
    if (!rc && !a.spin_text)
        rc = tippe_cli_usage_error(a.verb, "--spin FROM:TO:STEPS (rev/s) is required");
    if (!rc && (!parse_rising(a.spin_text, &sf, &st, &sn, 1000) || sf < 0))
        rc = tippe_cli_usage_error(
            a.verb,
            "--spin '%s': expected FROM:TO:STEPS in rev/s with 0 <= FROM < TO "
            "and 1 .. 1000 STEPS (one step: FROM = TO)",
            a.spin_text);
    if (!rc && (double)zn * sn * a.n > 1e8)
        rc = tippe_cli_usage_error(
            a.verb, "%d x %d cells x %ld launches is more than 10^8 launches", zn, sn, a.n);
    if (!rc && a.csv && mpi_rank() == 0)
        rc = tippe_cli_check_output(a.verb, "--csv", a.csv, 0);
    if (!rc && a.plot && mpi_rank() == 0)
        rc = tippe_cli_check_output(a.verb, "--plot", a.plot, 1);
    if (!rc && a.plot && a.csv && !strcmp(a.plot, a.csv))
        rc = tippe_cli_usage_error(a.verb, "--plot and --csv name the same file '%s'", a.plot);

    tippe_error err;
    tippe_design *d = NULL;
    double *z2 = NULL, *spin = NULL, *spin_rad = NULL;
    tippe_top *tops = NULL, *cell_tops = NULL;
    tippe_launch_record *rec = NULL;
    tippe_launch_tally *cells = NULL;
    const long n_cells = (long)zn * sn, total = n_cells * a.n;
    if (!rc && (rc = tippe_design_load(a.design, a.sets.item, a.sets.n, &d, &err)) != 0)
        rc = tippe_cli_fail(a.verb, &err, rc);
    if (!rc) {
        z2 = malloc((size_t)zn * sizeof *z2);
        spin = malloc((size_t)sn * sizeof *spin);
        tops = malloc((size_t)zn * sizeof *tops);
        cell_tops = malloc((size_t)n_cells * sizeof *cell_tops);
        spin_rad = malloc((size_t)n_cells * sizeof *spin_rad);
        cells = calloc((size_t)n_cells, sizeof *cells);
        rec = calloc((size_t)total, sizeof *rec);
        if (!z2 || !spin || !tops || !cell_tops || !spin_rad || !cells || !rec) {
            fprintf(stderr, "tippe map: out of memory for %ld launches\n", total);
            rc = 1;
        }
    }
    for (int i = 0; !rc && i < zn; i++) {
        z2[i] = zn == 1 ? zf : zf + (zt - zf) * i / (zn - 1);
        if ((rc = tippe_design_top(d, z2[i], &tops[i], &err)) != 0)
            rc = tippe_cli_fail(a.verb, &err, rc);
    }
    for (int j = 0; !rc && j < sn; j++)
        spin[j] = sn == 1 ? sf : sf + (st - sf) * j / (sn - 1);
    for (long c = 0; !rc && c < n_cells; c++) {
        cell_tops[c] = tops[c / sn];
        spin_rad[c] = 2 * M_PI * spin[c % sn];
    }
    if ((rc = mpi_agree(rc)) != 0)
        goto done;

    {
        tippe_launch_plan plan = {(int)n_cells, a.n, cell_tops, spin_rad};
        tippe_progress prog;
        tippe_progress_start(&prog, stderr, "tippe map", total, TIPPE_PROGRESS_AUTO);
        const double t0 = tippe_cli_now_s();
        rc = run_plan(&plan, &a.o, a.seed, rec, &prog, &err);
        const double elapsed = tippe_cli_now_s() - t0;
        tippe_progress_finish(&prog);
        if (mpi_rank() != 0) {
            rc = 0;
            goto done;
        }
        if (rc) {
            rc = tippe_cli_fail(a.verb, &err, rc);
            goto done;
        }
        for (long c = 0; !rc && c < n_cells; c++)
            if ((rc = tippe_launch_tally_records(rec + c * a.n, a.n, &cells[c], &err)) != 0)
                rc = tippe_cli_fail(a.verb, &err, rc);
        if (rc)
            goto done;
        tippe_launch_map m = {zn, sn, z2, spin, cells, a.n};
        if (a.csv && (rc = write_map_csv(a.csv, &m, tops, &err)) != 0) {
            rc = tippe_cli_fail(a.verb, &err, rc);
            goto done;
        }
        /* One set with the CSV (tippe_cli_run): both or neither. */
        if (a.plot && (rc = tippe_launch_plot_map(a.plot, &m, d, a.o.g, NULL, &err)) != 0) {
            rc = tippe_cli_fail(a.verb, &err, rc);
            goto done;
        }
        if (a.json) {
            cJSON *o = cJSON_CreateObject();
            if (o) {
                cJSON_AddStringToObject(o, "design", tippe_design_name(d));
                cJSON_AddStringToObject(o, "file", tippe_design_path(d));
                cJSON_AddNumberToObject(o, "seed", (double)a.seed);
                cJSON_AddNumberToObject(o, "per_cell", (double)a.n);
                cJSON_AddItemToObject(o, "z2_mm", cJSON_CreateDoubleArray(z2, zn));
                cJSON_AddItemToObject(o, "spin_rev_s", cJSON_CreateDoubleArray(spin, sn));
                cJSON_AddItemToObject(o, "distribution", json_options(&a.o, 1));
                tippe_sweep_result r;
                cJSON *zj = NULL;
                if (tippe_sweep_design(d, z2[0] - 1e-9, z2[zn - 1] + 1e-9, NULL, &r, &err) ==
                    TIPPE_OK) {
                    zj = cJSON_CreateArray();
                    for (int k = 0; zj && k < r.n_zones; k++) {
                        cJSON *zo = cJSON_CreateObject();
                        if (!zo)
                            break;
                        cJSON_AddStringToObject(zo, "group", tippe_group_name(r.zones[k].group));
                        cJSON_AddNumberToObject(zo, "z2_from_mm", r.zones[k].z2_from_mm);
                        cJSON_AddNumberToObject(zo, "z2_to_mm", r.zones[k].z2_to_mm);
                        cJSON_AddItemToArray(zj, zo);
                    }
                }
                tippe_sweep_result_free(&r);
                cJSON_AddItemToObject(o, "zones", zj ? zj : cJSON_CreateNull());
                cJSON *arr = cJSON_AddArrayToObject(o, "cells");
                for (int i = 0; arr && i < zn; i++)
                    for (int j = 0; j < sn; j++) {
                        const tippe_launch_tally *c = &cells[(long)i * sn + j];
                        cJSON *co = tally_json(c);
                        if (!co)
                            continue;
                        tippe_theory_class cls;
                        tippe_theory_classify(tops[i].A / tops[i].C, tops[i].eps / tops[i].R,
                                              &cls);
                        cJSON_AddNumberToObject(co, "z2_mm", z2[i]);
                        cJSON_AddNumberToObject(co, "spin_rev_s", spin[j]);
                        cJSON_AddStringToObject(co, "group", tippe_group_name(cls.group));
                        cJSON_AddNumberToObject(co, "agree", (double)c->agree);
                        cJSON_AddNumberToObject(co, "comparable", (double)c->comparable);
                        cJSON_AddItemToArray(arr, co);
                    }
            }
            rc = tippe_cli_print_json(a.verb, o);
        } else {
            printf("design     %s (%s)\n", tippe_design_name(d), tippe_design_path(d));
            printf("map        Z2 %g .. %g mm (%d) x spin %g .. %g rev/s (%d), %ld launches per "
                   "cell, seed %" PRIu64 "\n", zf, zt, zn, sf, st, sn, a.n, a.seed);
            print_distribution(&a.o, 1);
            print_model(&a.o);
            print_map_table(&m);
            tippe_launch_tally all;
            if (tippe_launch_tally_records(rec, total, &all, &err) == TIPPE_OK) {
                printf("\nall cells ");
                for (int v = 0; v < TIPPE_LAUNCH_N_VERDICTS; v++)
                    printf("%s %s %ld", v ? "," : "", verdict_names[v], all.counts[v]);
                printf(" of %ld; %ld of %ld settled launches agree with theory\n", total,
                       all.agree, all.comparable);
                printf("accuracy   largest Jellett drift %.2g; %.2f s on %d thread%s x %d "
                       "rank%s (%.1f launches/s)\n",
                       all.max_jellett_rel_drift, elapsed, omp_get_max_threads(),
                       omp_get_max_threads() > 1 ? "s" : "", mpi_size(),
                       mpi_size() > 1 ? "s" : "", (double)total / elapsed);
            }
            if (a.csv)
                printf("csv        %s (%ld cells)\n", a.csv, n_cells);
            if (a.plot)
                printf("plot       %s\n", a.plot);
        }
    }
done:
    free(z2);
    free(spin);
    free(spin_rad);
    free(tops);
    free(cell_tops);
    free(cells);
    free(rec);
    tippe_design_free(d);
    return rc;
}

/* ---- tippe check ------------------------------------------------------------- */

static void check_usage(FILE *out)
{
    fprintf(out,
        "usage: tippe check DESIGN.json --z2 MM [--spin RAD_S] [--json] [options]\n"
        "\n"
        "One realistic hand launch of the design's top with the weight at Z2: the central\n"
        "values of tippe launch's distributions (the median tilt, steady precession, no\n"
        "sliding) at the given spin, integrated to its outcome. Prints the outcome beside\n"
        "the zone the calculator (tippe sweep) puts Z2 in and Theorem 5.1's prediction for\n"
        "the launch's Jellett invariant.\n"
        "\n"
        "  --z2 MM              position of the moving weight's midpoint, mm (in the travel)\n"
        "  --spin RAD_S         launch spin in rad/s (default: the middle of tippe launch's\n"
        "                       spin range, 15 rev/s = 94.25 rad/s)\n"
        "  --tilt-rad SD        tilt scale of the hand-launch distribution, rad (default 0.1;\n"
        "                       the launch uses its median, 0.674 SD)\n"
        "  --mu S_PER_M, --g M_S2, --t-end S, --accuracy PRESET, --stepper NAME, --rtol X,\n"
        "  --set FIELD=VALUE    as for tippe launch\n"
        "  --json               print one JSON object instead of the text\n"
        "  --help               this text\n"
        "\n"
        "Exit status: 0 ok (whatever the outcome), 2 bad usage or design, 1 the launch could\n"
        "not be computed.\n");
}

int tippe_cli_check(int argc, char **argv)
{
    args a = {.verb = "check", .mask = V_CHECK};
    int rc = parse_args(&a, argc, argv);
    if (rc < 0) {
        check_usage(stdout);
        return 0;
    }
    if (rc)
        return rc;
    double z2, spin = M_PI * (a.o.spin_from_rev_s + a.o.spin_to_rev_s);
    if (!tippe_cli_parse_double(a.z2_text, &z2))
        return tippe_cli_usage_error(a.verb, "--z2 '%s': expected a number of mm", a.z2_text);
    if (a.spin_text && !tippe_cli_parse_double(a.spin_text, &spin))
        return tippe_cli_usage_error(a.verb, "--spin '%s': expected a number of rad/s",
                                     a.spin_text);
    tippe_error err;
    tippe_design *d = NULL;
    tippe_top top;
    if ((rc = tippe_design_load(a.design, a.sets.item, a.sets.n, &d, &err)) != 0)
        return tippe_cli_fail(a.verb, &err, rc);
    tippe_dynamics_initial ic;
    tippe_launch_record rec;
    if ((rc = tippe_design_top(d, z2, &top, &err)) != 0 ||
        (rc = tippe_launch_central(&top, &a.o, spin, &ic, &err)) != 0 ||
        (rc = tippe_launch_run_initial(&top, &a.o, &ic, &rec, &err)) != 0) {
        tippe_design_free(d);
        return tippe_cli_fail(a.verb, &err, rc);
    }
    zone_at z;
    find_zone(d, z2, &z);
    tippe_theory_class cls;
    tippe_theory_classify(top.A / top.C, top.eps / top.R, &cls);
    const char *agrees = rec.agrees > 0 ? "agrees" : rec.agrees == 0 ? "DISAGREES" : "not comparable";
    if (a.json) {
        cJSON *o = cJSON_CreateObject();
        if (o) {
            cJSON_AddStringToObject(o, "design", tippe_design_name(d));
            cJSON_AddStringToObject(o, "file", tippe_design_path(d));
            cJSON_AddNumberToObject(o, "z2_mm", z2);
            cJSON *ini = cJSON_AddObjectToObject(o, "initial");
            if (ini) {
                cJSON_AddNumberToObject(ini, "theta_rad", ic.theta);
                cJSON_AddNumberToObject(ini, "phi_dot_rad_s", ic.phi_dot);
                cJSON_AddStringToObject(ini, "phi_dot_rule", "steady");
                cJSON_AddNumberToObject(ini, "spin_rad_s", ic.spin);
                cJSON_AddNumberToObject(ini, "U_m_s", ic.U);
                cJSON_AddNumberToObject(ini, "V_m_s", ic.V);
            }
            cJSON_AddStringToObject(o, "verdict", tippe_verdict_name(rec.verdict));
            cJSON_AddNumberToObject(o, "t_s", rec.t_s);
            cJSON_AddStringToObject(o, "decided_by", tippe_decision_name(rec.how));
            if (rec.how == TIPPE_DECIDED_TRAPPED) {
                cJSON_AddNumberToObject(o, "margin_J", rec.margin_J);
                if (isfinite(rec.barrier_gap_J))
                    cJSON_AddNumberToObject(o, "barrier_gap_J", rec.barrier_gap_J);
                else
                    cJSON_AddNullToObject(o, "barrier_gap_J");
            }
            if (isfinite(rec.t_flip_s))
                cJSON_AddNumberToObject(o, "t_flip_s", rec.t_flip_s);
            else
                cJSON_AddNullToObject(o, "t_flip_s");
            cJSON_AddNumberToObject(o, "theta_final_rad", rec.theta_final_rad);
            cJSON_AddNumberToObject(o, "spin_final_rad_s", rec.spin_final_rad_s);
            cJSON_AddNumberToObject(o, "J0_kg_m3_s", rec.J0);
            cJSON_AddNumberToObject(o, "jellett_rel_drift", rec.jellett_rel_drift);
            cJSON_AddItemToObject(o, "options", json_options(&a.o, 1));
            cJSON *th = theory_json(&top, a.o.g, &z, NULL);
            if (th) {
                if (rec.theory_ok) {
                    cJSON_AddStringToObject(th, "prediction",
                                            tippe_launch_predicted_name(rec.predicted));
                    if (isfinite(rec.hang_theta_rad))
                        cJSON_AddNumberToObject(th, "hang_theta_rad", rec.hang_theta_rad);
                } else {
                    cJSON_AddNullToObject(th, "prediction");
                }
                if (rec.agrees < 0)
                    cJSON_AddNullToObject(th, "agrees");
                else
                    cJSON_AddBoolToObject(th, "agrees", rec.agrees);
                cJSON_AddItemToObject(o, "theory", th);
            }
        }
        rc = tippe_cli_print_json(a.verb, o);
    } else {
        print_top(d, z2, &top, a.o.g, &z);
        printf("launch     spin %.4g rad/s (%.3g rev/s), tilt %.4g rad (%.2f deg), steady "
               "precession %.4g rad/s, no sliding\n",
               ic.spin, ic.spin / (2 * M_PI), ic.theta, ic.theta * 180 / M_PI, ic.phi_dot);
        print_model(&a.o);
        printf("\nverdict    %s: ends at theta %.4f rad (%.1f deg), spin %.4g rad/s\n",
               tippe_verdict_name(rec.verdict), rec.theta_final_rad,
               rec.theta_final_rad * 180 / M_PI, rec.spin_final_rad_s);
        printf("           decided by %s at t = %.4g s", tippe_decision_name(rec.how), rec.t_s);
        if (rec.how == TIPPE_DECIDED_TRAPPED)
            printf(" (energy %.3g J below the well's barrier, margin %.3g J)", rec.barrier_gap_J,
                   rec.margin_J);
        printf("\n");
        if (isfinite(rec.t_flip_s))
            printf("flip       theta passed 90 deg at t = %.4g s of model time (mu = %g s/m)\n",
                   rec.t_flip_s, a.o.mu);
        printf("calculator zone %s at Z2 = %g mm (%s)\n",
               tippe_group_name(z.ok ? z.group : cls.group), z2,
               group_meaning(z.ok ? z.group : cls.group));
        if (rec.theory_ok) {
            printf("theory     Theorem 5.1 for J0 = %.4g kg m^3/s: %s", rec.J0,
                   tippe_launch_predicted_name(rec.predicted));
            if (isfinite(rec.hang_theta_rad))
                printf(" (hang at %.4f rad, %.1f deg)", rec.hang_theta_rad,
                       rec.hang_theta_rad * 180 / M_PI);
            printf(" -> %s\n", agrees);
        } else {
            printf("theory     no prediction for J0 = %.4g kg m^3/s\n", rec.J0);
        }
        printf("accuracy   Jellett drift %.2g, %ld RHS evaluations\n", rec.jellett_rel_drift,
               rec.rhs_evals);
    }
    tippe_design_free(d);
    return rc;
}
