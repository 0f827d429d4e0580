/* The search: NLopt's global algorithm over each choice, then a local polish
 * (see tippe/optimise.h); NLopt is opened when a search runs. */
#include "optimise/internal.h"
#include "tippe/design.h"
#include "tippe/physics.h"
#include "tippe/sweep.h"

#include <cjson/cJSON.h>
#include <dlfcn.h>
#include <limits.h>
#include <math.h>
#include <nlopt.h>
#include <omp.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

/* ---- the search ------------------------------------------------------------ */

typedef struct {
    const tippe_optimise_spec *s;
    const tippe_optimise_options *o;
    int choice;
    tippe_optimise_choice_result *res;
    long cap;
    double best_score;
    double best_x[TIPPE_OPTIMISE_MAX_VARY];
    int failed;
    /* The last candidate evaluated (clamped x), for the polish's constraints,
     * which NLopt asks for at the point whose objective it has just asked. */
    tippe_optimise_eval last;
    double last_margin[N_CON];
    double last_x[TIPPE_OPTIMISE_MAX_VARY];
    int has_last;
} job_t;

/* NLopt is opened when the first optimisation runs, as src/animate/encode.c opens
 * FFmpeg: linked, it would be loaded by every tippe command at start-up.
 * TIPPE_NLOPT_SONAME is the linked library's file name (CMakeLists.txt). */
#define NLOPT_FUNCS(X) \
    X(nlopt_create) \
    X(nlopt_destroy) \
    X(nlopt_optimize) \
    X(nlopt_set_lower_bounds) \
    X(nlopt_set_upper_bounds) \
    X(nlopt_set_max_objective) \
    X(nlopt_set_maxeval) \
    X(nlopt_set_initial_step) \
    X(nlopt_set_xtol_rel) \
    X(nlopt_set_xtol_abs1) \
    X(nlopt_set_local_optimizer) \
    X(nlopt_add_inequality_mconstraint) \
    X(nlopt_srand)

static struct {
#define X(fn) __typeof__(fn) *fn;
    NLOPT_FUNCS(X)
#undef X
} nl;
static pthread_once_t nl_once = PTHREAD_ONCE_INIT;
static char nl_error[512];

static void nl_load(void)
{
    /* The library stays open for the life of the process. */
    void *h = dlopen(TIPPE_NLOPT_SONAME, RTLD_NOW | RTLD_LOCAL);
    if (!h) {
        snprintf(nl_error, sizeof nl_error,
                 "NLopt is missing (apt-get install libnlopt-dev): %s", dlerror());
        return;
    }
#define X(fn) \
    if (!nl_error[0] && !(nl.fn = (__typeof__(nl.fn))dlsym(h, #fn))) \
        snprintf(nl_error, sizeof nl_error, "NLopt (%s) has no %s", TIPPE_NLOPT_SONAME, #fn);
    NLOPT_FUNCS(X)
#undef X
}

static int nl_ready(tippe_error *err)
{
    pthread_once(&nl_once, nl_load);
    return nl_error[0] ? tippe_error_set(err, TIPPE_ECOMPUTE, "optimise: %s", nl_error) : TIPPE_OK;
}

/* Evaluates candidate x (its first n_vary values; clamped to the bounds, which
 * COBYLA may step a hair outside), records it and keeps it as j->last. */
static const tippe_optimise_eval *evaluate_at(job_t *j, const double *x)
{
    unsigned n = (unsigned)j->s->n_vary;
    double xx[TIPPE_OPTIMISE_MAX_VARY] = {0};
    for (unsigned k = 0; k < n; k++)
        xx[k] = fmin(fmax(x[k], j->s->vary[k].lo), j->s->vary[k].hi);
    tippe_optimise_eval *ev = &j->last;
    tippe_optimise_evaluate_margins(j->s, j->choice, xx, SEARCH_SCAN, ev, j->last_margin);
    memcpy(j->last_x, x, n * sizeof *x);
    j->has_last = 1;
    tippe_optimise_choice_result *r = j->res;
    if (r->n_evals < j->cap) {
        if (ev->score > j->best_score) {
            j->best_score = ev->score;
            memcpy(j->best_x, xx, n * sizeof *xx);
        }
        r->best_so_far[r->n_evals] = j->best_score;
        if (r->all)
            r->all[r->n_evals] = *ev;
        r->n_evals++;
    }
    if (j->o->progress)
        j->o->progress(j->o->progress_ctx, 1);
    return ev;
}

static double objective(unsigned n, const double *x, double *grad, void *data)
{
    (void)n;
    (void)grad;
    return evaluate_at(data, x)->score;
}

/* The polish (COBYLA) sees the problem in its epigraph form: maximise t over
 * (x, t) subject to t <= the width of each group's zone, with the spec's
 * constraints as inequality constraints. The narrowest of three widths has a
 * kink where two are equal, and the best design lies on such a ridge (two
 * widths equal at every shipped spec's best); a constraint scored as a penalty
 * is a cliff, and the best design lies on one too (eps_max at its bound).
 * COBYLA's linear model of the score cannot follow a kink and a cliff: its
 * trust region collapsed there 50 evaluations in, at 6.777 mm on the drilled
 * ball instead of 6.820 mm. The widths and the constraints are each smooth,
 * and COBYLA models each one (docs/optimise.md, "The method"). */
#define N_POLISH_CON (3 + N_CON)

/* Evaluates the candidate (NLopt asks for the constraints at the same point
 * next) and returns t. */
static double polish_objective(unsigned n, const double *x, double *grad, void *data)
{
    (void)grad;
    evaluate_at(data, x);
    return x[n - 1];
}

static void polish_constraints(unsigned m, double *c, unsigned n, const double *x, double *grad,
                               void *data)
{
    (void)m;
    (void)grad;
    job_t *j = data;
    unsigned nv = n - 1;
    const tippe_optimise_eval *ev = j->has_last && !memcmp(j->last_x, x, nv * sizeof *x)
                                   ? &j->last
                                   : evaluate_at(j, x);
    double t = x[nv];
    for (int k = 0; k < 3; k++)
        c[k] = t - ev->zone_mm[k];
    for (int k = 0; k < N_CON; k++)
        c[3 + k] = j->last_margin[k];
}

static nlopt_algorithm nlopt_alg(algorithm_t a)
{
    switch (a) {
    case ALG_CRS2:
        return NLOPT_GN_CRS2_LM;
    case ALG_MLSL:
        return NLOPT_G_MLSL_LDS;
    case ALG_ISRES:
        return NLOPT_GN_ISRES;
    case ALG_DIRECT_L:
    default:
        return NLOPT_GN_DIRECT_L;
    }
}

/* One NLopt run over the bounds from x (in: start, out: unchanged), at most
 * maxeval evaluations. Returns 0, or -1 if NLopt could not be set up. */
static int run_nlopt(job_t *j, nlopt_algorithm alg, long maxeval, double *x)
{
    const tippe_optimise_spec *s = j->s;
    unsigned n = (unsigned)s->n_vary;
    double lo[TIPPE_OPTIMISE_MAX_VARY], hi[TIPPE_OPTIMISE_MAX_VARY], step[TIPPE_OPTIMISE_MAX_VARY], f = 0;
    for (unsigned k = 0; k < n; k++) {
        lo[k] = s->vary[k].lo;
        hi[k] = s->vary[k].hi;
        step[k] = 0.05 * (hi[k] - lo[k]);
    }
    nlopt_opt opt = nl.nlopt_create(alg, n);
    nlopt_opt local = NULL;
    if (!opt)
        return -1;
    int ok = nl.nlopt_set_lower_bounds(opt, lo) > 0 && nl.nlopt_set_upper_bounds(opt, hi) > 0 &&
             nl.nlopt_set_max_objective(opt, objective, j) > 0 &&
             nl.nlopt_set_maxeval(opt, (int)maxeval) > 0 &&
             nl.nlopt_set_initial_step(opt, step) > 0;
    if (ok && alg == NLOPT_G_MLSL_LDS) {
        local = nl.nlopt_create(NLOPT_LN_COBYLA, n);
        ok = local && nl.nlopt_set_xtol_rel(local, 1e-6) > 0 &&
             nl.nlopt_set_local_optimizer(opt, local) > 0;
    }
    if (ok && (alg == NLOPT_LN_COBYLA || alg == NLOPT_LN_BOBYQA))
        ok = nl.nlopt_set_xtol_abs1(opt, 1e-7) > 0; /* the sweep's own resolution, mm */
    nlopt_result res = ok ? nl.nlopt_optimize(opt, x, &f) : NLOPT_FAILURE;
    nl.nlopt_destroy(opt);
    nl.nlopt_destroy(local);
    /* Running out of evaluations or stopping on a tolerance is success here;
     * a roundoff-limited stop still leaves the best point seen. */
    return (res > 0 || res == NLOPT_ROUNDOFF_LIMITED) ? 0 : -1;
}

/* The COBYLA polish in the epigraph form (above) from x, at most maxeval
 * evaluations. Returns 0, or -1 if NLopt could not be set up. */
static int run_polish(job_t *j, long maxeval, const double *x)
{
    const tippe_optimise_spec *s = j->s;
    unsigned n = (unsigned)s->n_vary;
    double lo[TIPPE_OPTIMISE_MAX_VARY + 1], hi[TIPPE_OPTIMISE_MAX_VARY + 1], step[TIPPE_OPTIMISE_MAX_VARY + 1];
    double y[TIPPE_OPTIMISE_MAX_VARY + 1], tol[N_POLISH_CON] = {0}, f = 0;
    for (unsigned k = 0; k < n; k++) {
        lo[k] = s->vary[k].lo;
        hi[k] = s->vary[k].hi;
        step[k] = 0.05 * (hi[k] - lo[k]);
        y[k] = x[k];
    }
    /* t starts at the start's narrowest zone (0 if it is not feasible). */
    double t0 = fmax(0.0, j->best_score);
    lo[n] = 0.0;
    hi[n] = 1e4;
    y[n] = t0;
    step[n] = fmax(0.05 * t0, 0.01);
    nlopt_opt opt = nl.nlopt_create(NLOPT_LN_COBYLA, n + 1);
    if (!opt)
        return -1;
    int ok = nl.nlopt_set_lower_bounds(opt, lo) > 0 && nl.nlopt_set_upper_bounds(opt, hi) > 0 &&
             nl.nlopt_set_max_objective(opt, polish_objective, j) > 0 &&
             nl.nlopt_add_inequality_mconstraint(opt, N_POLISH_CON, polish_constraints, j,
                                                 tol) > 0 &&
             nl.nlopt_set_maxeval(opt, (int)maxeval) > 0 &&
             nl.nlopt_set_initial_step(opt, step) > 0 &&
             nl.nlopt_set_xtol_abs1(opt, 1e-7) > 0; /* the sweep's own resolution, mm */
    j->has_last = 0;
    nlopt_result res = ok ? nl.nlopt_optimize(opt, y, &f) : NLOPT_FAILURE;
    nl.nlopt_destroy(opt);
    return (res > 0 || res == NLOPT_ROUNDOFF_LIMITED) ? 0 : -1;
}

static void search_choice(job_t *j)
{
    const tippe_optimise_spec *s = j->s;
    double x[TIPPE_OPTIMISE_MAX_VARY] = {0};
    j->best_score = -INFINITY;
    if (s->n_vary == 0) {
        objective(0, x, NULL, j);
        j->res->n_global = j->res->n_evals;
    } else {
        for (int k = 0; k < s->n_vary; k++)
            x[k] = 0.5 * (s->vary[k].lo + s->vary[k].hi);
        /* The stochastic algorithms draw from NLopt's generator, which is per
         * thread: seeding it here makes this choice's search depend on the
         * seed and the choice only. */
        nl.nlopt_srand(j->o->seed * 1000003ul + (unsigned long)j->choice);
        if (run_nlopt(j, nlopt_alg(s->algorithm), s->evals, x))
            j->failed = 1;
        j->res->n_global = j->res->n_evals;
        if (!j->failed && s->polish != POLISH_NONE && s->polish_evals > 0 &&
            isfinite(j->best_score)) {
            memcpy(x, j->best_x, (size_t)s->n_vary * sizeof *x);
            /* From a feasible start, COBYLA follows the widths in the epigraph
             * form; from an infeasible one (the global phase found nothing that
             * meets the constraints) it can only reduce the violation, which the
             * score measures: the epigraph form would spend its whole budget
             * looking for a feasible point that the global phase did not find. */
            if (s->polish == POLISH_BOBYQA || j->best_score < 0
                    ? run_nlopt(j, s->polish == POLISH_BOBYQA ? NLOPT_LN_BOBYQA : NLOPT_LN_COBYLA,
                                s->polish_evals, x)
                    : run_polish(j, s->polish_evals, x))
                j->failed = 1;
        }
    }
    /* The best point, measured as a report measures it (full sweep). */
    tippe_optimise_evaluate(s, j->choice, j->best_x, 0, &j->res->best);
}

long tippe_optimise_planned_evals(const tippe_optimise_spec *s)
{
    long per = s->n_vary ? s->evals + (s->polish != POLISH_NONE ? s->polish_evals : 0) : 1;
    return per * s->n_choices;
}

void tippe_optimise_result_free(tippe_optimise_result *r)
{
    if (!r)
        return;
    for (int i = 0; r->choices && i < r->n_choices; i++) {
        free(r->choices[i].best_so_far);
        free(r->choices[i].all);
    }
    free(r->choices);
    memset(r, 0, sizeof *r);
}

/* Whether a ranks above b: feasible before infeasible, then by robust width
 * where both have one, else by score. */
int tippe_optimise_rank_above(const tippe_optimise_eval *a, const tippe_optimise_eval *b)
{
    int fa = a->status == TIPPE_OPTIMISE_OK, fb = b->status == TIPPE_OPTIMISE_OK;
    if (fa != fb)
        return fa;
    if (fa && a->has_robust && b->has_robust && a->robust_mm != b->robust_mm)
        return a->robust_mm > b->robust_mm;
    return a->score > b->score;
}

int tippe_optimise_run(const tippe_optimise_spec *s, const tippe_optimise_options *o, tippe_optimise_result *out,
                  tippe_error *err)
{
    memset(out, 0, sizeof *out);
    int rc = nl_ready(err);
    if (rc)
        return rc;
    tippe_gsl_errors_as_codes();
    tippe_optimise_options def;
    if (!o) {
        tippe_optimise_options_default(&def);
        o = &def;
    }
    int nc = s->n_choices;
    long per = tippe_optimise_planned_evals(s) / nc;
    /* COBYLA and MLSL may make a few more calls than asked when they stop. */
    long cap = per + 64;
    out->choices = calloc((size_t)nc, sizeof *out->choices);
    job_t *jobs = calloc((size_t)nc, sizeof *jobs);
    if (!out->choices || !jobs) {
        free(jobs);
        return tippe_error_set(err, TIPPE_ECOMPUTE, "optimise: out of memory");
    }
    out->n_choices = nc;
    out->robust = s->robust;
    int oom = 0;
    for (int c = 0; c < nc; c++) {
        tippe_optimise_choice_result *r = &out->choices[c];
        r->best_so_far = malloc((size_t)cap * sizeof *r->best_so_far);
        if (o->keep_all)
            r->all = malloc((size_t)cap * sizeof *r->all);
        oom |= !r->best_so_far || (o->keep_all && !r->all);
        jobs[c] = (job_t){.s = s, .o = o, .choice = c, .res = r, .cap = cap};
    }
    if (oom) {
        free(jobs);
        return tippe_error_set(err, TIPPE_ECOMPUTE, "optimise: out of memory");
    }
    int threads = o->threads > 0 ? o->threads : omp_get_max_threads();
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (int c = 0; c < nc; c++)
        search_choice(&jobs[c]);
    int failed = -1;
    out->best_choice = 0;
    for (int c = 0; c < nc; c++) {
        out->total_evals += out->choices[c].n_evals;
        if (jobs[c].failed && failed < 0)
            failed = c;
        if (tippe_optimise_rank_above(&out->choices[c].best, &out->choices[out->best_choice].best))
            out->best_choice = c;
    }
    free(jobs);
    if (failed >= 0) {
        char label[256];
        return tippe_error_set(err, TIPPE_ECOMPUTE, "optimise: NLopt failed on choice %s",
                               tippe_optimise_spec_choice_label(s, failed, label, sizeof label));
    }
    return TIPPE_OK;
}
