/* tippe optimise: search a spec's design space for the widest narrowest zone. */
#include "cli.h"

#include "tippe/plot.h"
#include "tippe/optimise.h"
#include "tippe/base.h"

#include <cjson/cJSON.h>

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const VERB = "optimise";

typedef struct {
    const char *spec, *best, *plot, *csv;
    int json;
    long seed, threads;
} optimise_args;

static int parse_args(int argc, char **argv, optimise_args *a)
{
    a->seed = 1;
    a->threads = 0;
    tippe_cli_opt opts[] = {
        {.name = "output", .short_name = 'o', .kind = TIPPE_CLI_STRING, .value = &a->best,
         .arg = "BEST.json",
         .help = "write the best design as a design file (travel_mm its physical\n"
                 "travel, notes saying how it was found and its zone widths)"},
        {.name = "json", .kind = TIPPE_CLI_FLAG, .value = &a->json,
         .help = "print one JSON object instead of the table"},
        {.name = "plot", .kind = TIPPE_CLI_STRING, .value = &a->plot, .arg = "FILE",
         .help = "zones of the best design of each choice (the best ten) and the\n"
                 "search's convergence; PNG, SVG or PDF by the file's extension"},
        {.name = "csv", .kind = TIPPE_CLI_STRING, .value = &a->csv, .arg = "FILE",
         .help = "every evaluated candidate (choice, parameters, zones in mm,\n"
                 "constraint values, status, score)"},
        TIPPE_CLI_SEED_OPT(&a->seed, "seed of the stochastic algorithms (CRS2, MLSL, ISRES); "
                                     "DIRECT-L,\nCOBYLA and BOBYQA draw no random numbers"),
        TIPPE_CLI_THREADS_OPT(&a->threads, "OpenMP threads for the choices; the answer does "
                                           "not depend on it"),
        {NULL},
    };
    tippe_cli_spec spec = {
        .verb = VERB,
        .progress = 1,
        .synopsis = "SPEC.json [-o BEST.json] [--json] [--plot FILE] [--csv FILE] [--seed S]\n"
                    "                      [--threads N]",
        .about = "Searches the designs a spec allows (a base design with fields that vary over\n"
                 "ranges, discrete choices such as materials or catalogue screws, fields tied\n"
                 "to others, constraints) for the one whose narrowest zone is widest: for each\n"
                 "of the groups I, II and III its widest contiguous run of Z2 within the\n"
                 "physical travel, the narrowest of the three (0 unless all three are\n"
                 "reachable). NLopt's global algorithm (default DIRECT-L) runs for each choice\n"
                 "(choices in parallel), then a local polish (COBYLA); the best of each choice\n"
                 "is re-measured with the full sweep (zone ends to 1e-6 mm). With the objective\n"
                 "robust_narrowest_zone the choices are ranked by the widths left after the\n"
                 "tolerance bands of the zone ends.",
        .after = "A progress bar is shown on stderr when it is a terminal. The spec format and\n"
                 "the shipped specs: docs/optimise.md. Exit status: 0 ok, 2 bad usage or spec\n"
                 "(nothing written), 1 search failed or no candidate met the constraints\n"
                 "(the table shows each choice's status; nothing written).",
        .opts = opts,
        .min_args = 1,
        .max_args = 1,
        .args_name = "spec file",
    };
    int n_args = 0;
    int rc = tippe_cli_parse(&spec, argc, argv, &a->spec, &n_args);
    if (rc)
        return rc;
    const char *outs[3] = {a->best, a->plot, a->csv};
    const char *names[3] = {"-o", "--plot", "--csv"};
    for (int k = 0; k < 3; k++) {
        if (outs[k] && tippe_cli_check_output(VERB, names[k], outs[k], k == 1))
            return 2;
        for (int j = 0; j < k; j++)
            if (outs[k] && outs[j] && !strcmp(outs[k], outs[j]))
                return tippe_cli_usage_error(VERB, "%s and %s name the same file '%s'", names[j],
                                             names[k], outs[k]);
        if (outs[k] && !strcmp(outs[k], a->spec))
            return tippe_cli_usage_error(VERB, "%s would overwrite the spec '%s'", names[k],
                                         a->spec);
    }
    return 0;
}

static void progress_add(void *ctx, long n) { tippe_progress_add(ctx, n); }

static void print_params(FILE *f, const tippe_optimise_spec *s, const tippe_optimise_eval *e, int csv)
{
    for (int k = 0; k < tippe_optimise_spec_n_vary(s); k++)
        fprintf(f, csv ? ",%.10g" : " %12.4f", e->x[k]);
}

static void print_table(const tippe_optimise_spec *s, const tippe_optimise_result *r, double seconds)
{
    int nv = tippe_optimise_spec_n_vary(s);
    printf("spec     %s\n", tippe_optimise_spec_path(s));
    printf("search   %ld candidates in %.1f s over %d choice%s\n\n", r->total_evals, seconds,
           r->n_choices, r->n_choices == 1 ? "" : "s");
    printf("%-24s", "choice");
    for (int k = 0; k < nv; k++) {
        /* "parts.rod.radius_mm" -> "rod.radius": the part and the field, which
         * tell two radii apart in 12 characters. */
        const char *p = tippe_optimise_spec_vary_path(s, k);
        char head[TIPPE_OPTIMISE_PATH_LEN];
        snprintf(head, sizeof head, "%s", strncmp(p, "parts.", 6) ? p : p + 6);
        size_t n = strlen(head);
        if (n > 3 && !strcmp(head + n - 3, "_mm"))
            head[n - 3] = '\0';
        printf(" %12.12s", head);
    }
    printf(" %8s %8s %8s %9s%s %8s %8s  %s\n", "I (mm)", "II (mm)", "III (mm)", "narrowest",
           r->robust ? "    robust" : "", "eps_max", "n* rev/s", "status");
    /* with no feasible candidate there is no best, only the least infeasible */
    const int feasible = r->choices[r->best_choice].best.status == TIPPE_OPTIMISE_OK;
    for (int c = 0; c < r->n_choices; c++) {
        const tippe_optimise_eval *e = &r->choices[c].best;
        char label[256];
        printf("%-24.24s", tippe_optimise_spec_choice_label(s, c, label, sizeof label));
        print_params(stdout, s, e, 0);
        printf(" %8.3f %8.3f %8.3f %9.3f", e->zone_mm[0], e->zone_mm[1], e->zone_mm[2],
               e->objective_mm);
        if (r->robust)
            printf(" %9.3f", e->robust_mm);
        printf(" %8.3f %8.2f  %s%s\n", e->eps_max_mm, e->spin_flip_rev_s,
               tippe_optimise_status_name(e->status),
               c != r->best_choice ? "" : feasible ? "  <- best" : "  <- closest (infeasible)");
    }
    const tippe_optimise_eval *b = &r->choices[r->best_choice].best;
    if (!feasible) {
        printf("\nbest     none: no candidate meets every constraint of the spec\n");
        return;
    }
    printf("\nbest     narrowest zone %.6f mm (I %.6f, II %.6f, III %.6f mm), travel %.3f .. "
           "%.3f mm\n",
           b->objective_mm, b->zone_mm[0], b->zone_mm[1], b->zone_mm[2], b->travel_mm[0],
           b->travel_mm[1]);
    printf("accuracy zone ends root-found to 1e-7 mm (full sweep of the best point); the search\n"
           "         itself is a global search, not a proof of the global optimum\n");
    if (r->robust && b->has_robust)
        printf("robust   narrowest zone %.6f mm (I %.6f, II %.6f, III %.6f mm): each width less\n"
               "         the tolerance bands of its ends (tippe sweep's bands); the search\n"
               "         maximised nominal widths and ranked the choices by this\n",
               b->robust_mm, b->robust_zone_mm[0], b->robust_zone_mm[1], b->robust_zone_mm[2]);
}

static cJSON *result_json(const tippe_optimise_spec *s, const tippe_optimise_result *r, double seconds,
                          const char *best_path)
{
    cJSON *o = cJSON_CreateObject(), *choices = NULL;
    if (!o || !cJSON_AddStringToObject(o, "spec", tippe_optimise_spec_path(s)) ||
        !cJSON_AddNumberToObject(o, "evaluations", (double)r->total_evals) ||
        !cJSON_AddNumberToObject(o, "seconds", seconds) ||
        !cJSON_AddStringToObject(o, "objective", r->robust ? "robust_narrowest_zone"
                                                            : "narrowest_zone") ||
        !(choices = cJSON_AddArrayToObject(o, "choices"))) {
        cJSON_Delete(o);
        return NULL;
    }
    for (int c = 0; c < r->n_choices; c++) {
        const tippe_optimise_eval *e = &r->choices[c].best;
        char label[256];
        cJSON *ch = cJSON_CreateObject(), *params = NULL, *zones = NULL;
        if (!ch || !cJSON_AddItemToArray(choices, ch)) {
            cJSON_Delete(ch);
            cJSON_Delete(o);
            return NULL;
        }
        int ok = cJSON_AddStringToObject(ch, "choice",
                                         tippe_optimise_spec_choice_label(s, c, label, sizeof label)) &&
                 (params = cJSON_AddObjectToObject(ch, "parameters")) &&
                 (zones = cJSON_AddObjectToObject(ch, "zone_widths_mm"));
        for (int k = 0; ok && k < tippe_optimise_spec_n_vary(s); k++)
            ok = cJSON_AddNumberToObject(params, tippe_optimise_spec_vary_path(s, k), e->x[k]) != NULL;
        const char *g[3] = {"I", "II", "III"};
        for (int k = 0; ok && k < 3; k++)
            ok = cJSON_AddNumberToObject(zones, g[k], e->zone_mm[k]) != NULL;
        double tr[2] = {e->travel_mm[0], e->travel_mm[1]};
        cJSON *t = ok ? cJSON_CreateDoubleArray(tr, 2) : NULL;
        ok = ok && t && cJSON_AddItemToObject(ch, "physical_travel_mm", t);
        ok = ok && cJSON_AddNumberToObject(ch, "narrowest_zone_mm", e->objective_mm) &&
             cJSON_AddNumberToObject(ch, "eps_max_mm", e->eps_max_mm) &&
             cJSON_AddNumberToObject(ch, "flip_spin_rev_s", e->spin_flip_rev_s) &&
             (isfinite(e->wall_mm) ? cJSON_AddNumberToObject(ch, "wall_mm", e->wall_mm)
                                   : cJSON_AddNullToObject(ch, "wall_mm")) &&
             cJSON_AddNumberToObject(ch, "weight_g", e->weight_g) &&
             (e->has_robust ? cJSON_AddNumberToObject(ch, "robust_narrowest_zone_mm", e->robust_mm)
                            : cJSON_AddNullToObject(ch, "robust_narrowest_zone_mm")) &&
             cJSON_AddStringToObject(ch, "status", tippe_optimise_status_name(e->status)) &&
             cJSON_AddNumberToObject(ch, "evaluations", (double)r->choices[c].n_evals) &&
             cJSON_AddBoolToObject(ch, "best", c == r->best_choice);
        if (!ok) {
            cJSON_Delete(o);
            return NULL;
        }
    }
    if (!(best_path ? cJSON_AddStringToObject(o, "best_design", best_path)
                    : cJSON_AddNullToObject(o, "best_design"))) {
        cJSON_Delete(o);
        return NULL;
    }
    return o;
}

static int write_csv(const char *path, const tippe_optimise_spec *s, const tippe_optimise_result *r,
                     tippe_error *err)
{
    tippe_report_file rf;
    int rc = tippe_report_open(&rf, path, "the CSV file", err);
    if (rc)
        return rc;
    FILE *f = rf.f;
    fprintf(f, "choice,index");
    for (int k = 0; k < tippe_optimise_spec_n_vary(s); k++)
        fprintf(f, ",%s", tippe_optimise_spec_vary_path(s, k));
    fprintf(f, ",zone_I_mm,zone_II_mm,zone_III_mm,narrowest_mm,travel_from_mm,travel_to_mm,"
               "eps_max_mm,flip_spin_rev_s,wall_mm,weight_g,status,score\n");
    for (int c = 0; c < r->n_choices; c++) {
        char label[256];
        tippe_optimise_spec_choice_label(s, c, label, sizeof label);
        for (char *p = label; *p; p++)
            if (*p == ',' || *p == '"')
                *p = ';';
        for (long i = 0; i < r->choices[c].n_evals; i++) {
            const tippe_optimise_eval *e = &r->choices[c].all[i];
            fprintf(f, "%s,%ld", label, i);
            print_params(f, s, e, 1);
            fprintf(f, ",%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.6g,%.6g,", e->zone_mm[0], e->zone_mm[1],
                    e->zone_mm[2], e->objective_mm, e->travel_mm[0], e->travel_mm[1],
                    e->eps_max_mm, e->spin_flip_rev_s);
            if (isfinite(e->wall_mm))
                fprintf(f, "%.6g", e->wall_mm);
            fprintf(f, ",%.6g,%s,%.9g\n", e->weight_g, tippe_optimise_status_name(e->status),
                    e->score);
        }
    }
    return tippe_report_commit(&rf, err);
}

static int write_best(const char *path, const tippe_optimise_spec *s, const tippe_optimise_result *r,
                      unsigned long seed, tippe_error *err)
{
    const tippe_optimise_choice_result *b = &r->choices[r->best_choice];
    char how[512], label[256];
    snprintf(how, sizeof how, "best of %d choice%s, this one %s, after %ld evaluations in all, "
                              "seed %lu",
             r->n_choices, r->n_choices == 1 ? "" : "s",
             tippe_optimise_spec_choice_label(s, r->best_choice, label, sizeof label),
             r->total_evals, seed);
    cJSON *d = tippe_optimise_design_json(s, &b->best, path, how, err);
    if (!d)
        return err->code ? err->code : TIPPE_ECOMPUTE;
    /* On standard output the file may land anywhere: its materials table by
     * its absolute path (it came relative to the current directory). */
    const cJSON *m = cJSON_GetObjectItemCaseSensitive(d, "materials");
    char abs_mat[PATH_MAX];
    if (!strcmp(path, "-") && cJSON_IsString(m) && m->valuestring[0] != '/' &&
        realpath(m->valuestring, abs_mat))
        cJSON_ReplaceItemInObjectCaseSensitive(d, "materials", cJSON_CreateString(abs_mat));
    char *text = cJSON_Print(d);
    cJSON_Delete(d);
    if (!text)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    tippe_report_file rf;
    int rc = tippe_report_open(&rf, path, "the design file", err);
    if (!rc) {
        fprintf(rf.f, "%s\n", text);
        rc = tippe_report_commit(&rf, err);
    }
    free(text);
    return rc;
}

int tippe_cli_optimise(int argc, char **argv)
{
    optimise_args a = {0};
    int rc = parse_args(argc, argv, &a);
    if (rc)
        return rc == TIPPE_CLI_HELP ? 0 : rc;
    tippe_error err = {0};
    tippe_optimise_spec *s = NULL;
    if ((rc = tippe_optimise_spec_load(a.spec, &s, &err)))
        return tippe_cli_fail(VERB, &err, rc);
    tippe_progress bar;
    tippe_progress_start(&bar, stderr, "tippe optimise", tippe_optimise_planned_evals(s),
                         tippe_cli_progress_mode());
    tippe_optimise_options o;
    tippe_optimise_options_default(&o);
    o.seed = (unsigned long)a.seed;
    o.threads = (int)a.threads;
    o.keep_all = a.csv != NULL;
    o.progress = progress_add;
    o.progress_ctx = &bar;
    tippe_optimise_result r;
    double t0 = tippe_cli_now_s();
    rc = tippe_optimise_run(s, &o, &r, &err);
    double seconds = tippe_cli_now_s() - t0;
    tippe_progress_finish(&bar);
    /* No candidate met the constraints: the table says why (each choice's
     * status), but no file is written, since none would be a design to make. */
    const int feasible = rc || r.choices[r.best_choice].best.status == TIPPE_OPTIMISE_OK;
    if (!feasible) {
        if (a.json)
            rc = tippe_cli_print_json(VERB, result_json(s, &r, seconds, NULL));
        else
            print_table(s, &r, seconds);
        fprintf(stderr, "tippe %s: no feasible design: every candidate of the %ld evaluated "
                        "breaks a constraint or does not fit (status column); nothing written\n",
                VERB, r.total_evals);
        tippe_optimise_result_free(&r);
        tippe_optimise_spec_free(s);
        return 1;
    }
    if (!rc && a.csv)
        rc = write_csv(a.csv, s, &r, &err);
    if (!rc && a.plot)
        rc = tippe_optimise_plot(a.plot, s, &r, &err);
    if (!rc && a.best)
        rc = write_best(a.best, s, &r, o.seed, &err);
    if (rc) {
        rc = tippe_cli_fail(VERB, &err, rc);
    } else if (a.json) {
        rc = tippe_cli_print_json(VERB, result_json(s, &r, seconds, a.best));
    } else {
        print_table(s, &r, seconds);
        if (a.best)
            printf("wrote    %s\n", a.best);
    }
    tippe_optimise_result_free(&r);
    tippe_optimise_spec_free(s);
    return rc;
}
