/* tippe map: hand launches over a grid of weight positions and spins, the
 * most frequent outcome of each cell as a table, CSV, JSON and heat map. */
#include "hands.h"

#include "tippe/plot.h"
#include "tippe/launch.h"
#include "tippe/base.h"
#include "tippe/sweep.h"

#include <cjson/cJSON.h>
#include <inttypes.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define MAP_ABOUT                                                                          \
    "Hand launches over a grid of weight positions Z2 and launch spins: the share of\n"     \
    "no_tip, tip, hang, lost_contact, undecided and bounded in each cell. Within a cell the spin\n"  \
    "is fixed and the rest of each hand launch (tilt, precession, sliding) is drawn as in\n"\
    "tippe launch; every cell uses the same N draws, so that differences between cells\n"   \
    "are not noise of the draws."

static const char verdict_letter[TIPPE_LAUNCH_N_VERDICTS] = {'N', 'T', 'H', 'L', 'U', 'B'};

static int write_map_csv(const char *path, const tippe_launch_map *m, const tippe_top *tops,
                         tippe_error *err)
{
    tippe_report_file rf;
    int rc = tippe_report_open(&rf, path, "the CSV file", err);
    if (rc)
        return rc;
    FILE *f = rf.f;
    fprintf(f, "z2_mm,spin_rad_s,group,subgroup,n,no_tip,tip,hang,lost_contact,undecided,"
               "bounded,agree,comparable,dominant,dominant_share\n");
    for (int i = 0; i < m->n_z2; i++)
        for (int j = 0; j < m->n_spin; j++) {
            const tippe_launch_tally *c = &m->cells[(long)i * m->n_spin + j];
            tippe_theory_class cls;
            tippe_theory_classify(tops[i].A / tops[i].C, tops[i].eps / tops[i].R, &cls);
            int v = tippe_launch_dominant(c);
            fprintf(f, "%.10g,%.10g,%s,%s,%ld,%ld,%ld,%ld,%ld,%ld,%ld,%ld,%ld,%s,%.6g\n",
                    m->z2_mm[i], 2 * M_PI * m->spin_rev_s[j], tippe_group_family(cls.group),
                    tippe_group_name(cls.group), c->n, c->counts[0], c->counts[1],
                    c->counts[2], c->counts[3], c->counts[4], c->counts[5], c->agree,
                    c->comparable, hands_verdict_names[v], (double)c->counts[v] / (double)c->n);
        }
    return tippe_report_commit(&rf, err);
}

static void print_map_table(const tippe_launch_map *m, const unsigned char *invalid)
{
    printf("\nmost frequent outcome and its share in %% (N no_tip, T tip, H hang, L lost_contact, "
           "U undecided, B bounded)\n");
    printf("spin rev/s |");
    int any_invalid = 0;
    for (int i = 0; i < m->n_z2; i++) {
        printf(invalid[i] ? " %5.2f!" : " %6.2f", m->z2_mm[i]);
        any_invalid |= invalid[i];
    }
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
    if (any_invalid)
        printf("! at this Z2 a part stands out of the sphere: the top rests on it and the model "
               "(contact on\n  the sphere only) does not apply; the column is no prediction\n");
}

/* Most launches one map may ask for: their records take ~150 bytes each
 * (1.5 GB at the limit), so the request bounds the memory. */
#define MAP_MAX_LAUNCHES 1e7

static int map_parse(hands_args *a, int argc, char **argv)
{
    tippe_cli_opt own[] = {
        {.name = "z2", .kind = TIPPE_CLI_RANGE, .value = &a->z2_range, .arg = "FROM:TO:STEPS",
         .unit = "mm", .min = -TIPPE_CLI_Z2_MAX_MM, .max = TIPPE_CLI_Z2_MAX_MM,
         .max_steps = 1000, .required = 1,
         .help = "weight positions, STEPS evenly spaced (in the design's travel)"},
        {.name = "spin", .kind = TIPPE_CLI_RANGE, .value = &a->spin, .arg = "FROM:TO:STEPS",
         .unit = "rad/s", .min = 0, .max = HANDS_SPIN_MAX_RAD_S, .max_steps = 1000,
         .required = 1,
         .help = "launch spins, STEPS evenly spaced, e.g. 5:40rev/s:8 (a unit on TO\n"
                 "applies to FROM)"},
        {.name = "n", .short_name = 'n', .kind = TIPPE_CLI_LONG, .value = &a->n,
         .arg = "PER_CELL", .min = 1, .max = 1e6, .def = "10", .help = "launches per cell"},
        {.name = "plot", .kind = TIPPE_CLI_STRING, .value = &a->plot, .arg = "FILE",
         .help = "heat map (.png, .svg or .pdf): the most frequent outcome of each cell\n"
                 "as colour, paler for a smaller share, with the zone boundaries of\n"
                 "tippe sweep and the thresholds n-, n*"},
        {.name = "csv", .kind = TIPPE_CLI_STRING, .value = &a->csv, .arg = "FILE",
         .help = "one row per cell: counts of each outcome, theory agreement"},
        HANDS_RADIUS_OPTIONS(a, "every cell's launches"),
        HANDS_CONTACT_OPTION(a),
        {NULL},
    };
    hands_verb v = {
        .spec = {.verb = "map",
                 .progress = 1,
                 .synopsis = "DESIGN.json --z2 FROM:TO:STEPS --spin FROM:TO:STEPS [-n PER_CELL]\n"
                             "                 [--plot FILE] [--csv FILE] [--json] [options]",
                 .about = MAP_ABOUT,
                 .after = "Under mpirun -np N (N > 1) the launches of all cells are shared among\n"
                          "the ranks. Exit status: 0 ok, 2 bad usage or design, 1 a launch could\n"
                          "not be computed. Details: docs/launch.md."},
        .own = own,
        .distribution = 1,
    };
    int rc = hands_parse(&v, a, argc, argv);
    if (rc)
        return rc;
    const double total = (double)a->z2_range.steps * (double)a->spin.steps * (double)a->n;
    if (a->z2_range.steps == 0 || a->spin.steps == 0)
        return tippe_cli_usage_error(a->verb, "--z2 and --spin need FROM:TO:STEPS");
    if (total > MAP_MAX_LAUNCHES)
        return tippe_cli_usage_error(a->verb,
                                     "%ld x %ld cells x %ld launches is %.3g launches; at most "
                                     "%.0e (their records take ~%zu bytes each)",
                                     a->z2_range.steps, a->spin.steps, a->n, total,
                                     MAP_MAX_LAUNCHES, sizeof(tippe_launch_record));
    if (hands_mpi_rank() == 0 &&
        ((a->csv && tippe_cli_check_output(a->verb, "--csv", a->csv, 0)) ||
         (a->plot && tippe_cli_check_output(a->verb, "--plot", a->plot, 1))))
        return 2;
    if (a->plot && a->csv && !strcmp(a->plot, a->csv))
        return tippe_cli_usage_error(a->verb, "--plot and --csv name the same file '%s'",
                                     a->plot);
    return 0;
}

/* The grid, its launches and tallies: the library's (tippe_launch_grid). */
typedef tippe_launch_grid map_grid;

/* The patch law's reruns of every cell's launches at 1/F and F times the radius (every
 * rank), into g->rec_radius. */
static int grid_radius_runs(const hands_args *a, map_grid *g, tippe_progress *prog,
                            tippe_error *err)
{
    const tippe_launch_plan plan = tippe_launch_grid_plan(g);
    for (int i = 0; i < 3; i += 2) {
        if (!g->rec_radius[i])
            continue;
        tippe_launch_options oi;
        tippe_launch_grid_radius_options(g, &a->o, i, &oi);
        int rc = hands_run_plan(&plan, &oi, (uint64_t)a->seed, g->rec_radius[i], prog, err);
        if (rc)
            return rc;
    }
    return 0;
}

/* The zones of the design's sweep over the map's Z2 range, or null. */
static cJSON *zones_json(const tippe_design *d, const map_grid *g)
{
    tippe_sweep_result r;
    tippe_error err;
    cJSON *zj = NULL;
    if (tippe_sweep_design(d, g->z2_mm[0] - 1e-9, g->z2_mm[g->n_z2 - 1] + 1e-9, NULL, &r, &err) ==
        TIPPE_OK) {
        zj = cJSON_CreateArray();
        for (int k = 0; zj && k < r.n_zones; k++) {
            cJSON *zo = cJSON_CreateObject();
            if (!zo)
                break;
            cJSON_AddStringToObject(zo, "group", tippe_group_family(r.zones[k].group));
            cJSON_AddStringToObject(zo, "subgroup", tippe_group_name(r.zones[k].group));
            cJSON_AddNumberToObject(zo, "z2_from_mm", r.zones[k].z2_from_mm);
            cJSON_AddNumberToObject(zo, "z2_to_mm", r.zones[k].z2_to_mm);
            cJSON_AddItemToArray(zj, zo);
        }
    }
    tippe_sweep_result_free(&r);
    return zj ? zj : cJSON_CreateNull();
}

static cJSON *cells_json(const map_grid *g)
{
    /* per cell: radius_changed under the patch law's radius sensitivity, else absent */
    cJSON *arr = cJSON_CreateArray();
    for (int i = 0; arr && i < g->n_z2; i++)
        for (int j = 0; j < g->n_spin; j++) {
            const tippe_launch_tally *c = &g->cells[(long)i * g->n_spin + j];
            cJSON *co = hands_json_tally(c);
            if (!co)
                continue;
            const tippe_top *t = &g->tops[i];
            tippe_theory_class cls;
            tippe_theory_classify(t->A / t->C, t->eps / t->R, &cls);
            cJSON_AddNumberToObject(co, "z2_mm", g->z2_mm[i]);
            cJSON_AddNumberToObject(co, "spin_rad_s", 2 * M_PI * g->spin_rev_s[j]);
            cJSON_AddStringToObject(co, "group", tippe_group_family(cls.group));
            cJSON_AddStringToObject(co, "subgroup", tippe_group_name(cls.group));
            cJSON_AddNumberToObject(co, "agree", (double)c->agree);
            cJSON_AddNumberToObject(co, "comparable", (double)c->comparable);
            cJSON_AddBoolToObject(co, "model_valid", !g->model_invalid[i]);
            if (g->radius_runs)
                cJSON_AddNumberToObject(co, "radius_changed",
                                        (double)g->cell_changed[(long)i * g->n_spin + j]);
            cJSON_AddItemToArray(arr, co);
        }
    return arr;
}

/* {robust, changed, cells_changed, runs: [{factor, patch_mm, ran}]}; null when not run
 * (another law, or --no-radius-sensitivity). */
static cJSON *radius_json(const map_grid *g)
{
    if (!g->radius_runs)
        return cJSON_CreateNull();
    cJSON *o = cJSON_CreateObject();
    cJSON *runs = o ? cJSON_AddArrayToObject(o, "runs") : NULL;
    if (!runs)
        return o;
    for (int i = 0; i < 3; i++) {
        cJSON *x = cJSON_CreateObject();
        if (!x)
            break;
        cJSON_AddItemToArray(runs, x);
        cJSON_AddNumberToObject(x, "factor", g->factor[i]);
        cJSON_AddNumberToObject(x, "patch_mm", g->radius_m[i] * 1e3);
        cJSON_AddBoolToObject(x, "ran", i == 1 || g->rec_radius[i] != NULL);
    }
    const int all_ran = g->rec_radius[0] && g->rec_radius[2];
    if (all_ran || g->changed > 0)
        cJSON_AddBoolToObject(o, "robust", all_ran && g->changed == 0);
    else
        cJSON_AddNullToObject(o, "robust"); /* not known: a radius was not run */
    cJSON_AddNumberToObject(o, "changed", (double)g->changed);
    cJSON_AddNumberToObject(o, "cells_changed", (double)g->cells_changed);
    return o;
}

static int map_json(const hands_args *a, const tippe_design *d, const map_grid *g)
{
    cJSON *o = cJSON_CreateObject();
    if (o) {
        cJSON_AddStringToObject(o, "design", tippe_design_name(d));
        cJSON_AddStringToObject(o, "file", tippe_design_path(d));
        tippe_cli_json_sets(o, &a->sets);
        cJSON_AddNumberToObject(o, "seed", (double)a->seed);
        cJSON_AddNumberToObject(o, "per_cell", (double)a->n);
        cJSON_AddItemToObject(o, "z2_mm", cJSON_CreateDoubleArray(g->z2_mm, g->n_z2));
        cJSON *sp = cJSON_AddArrayToObject(o, "spin_rad_s");
        for (int j = 0; sp && j < g->n_spin; j++)
            cJSON_AddItemToArray(sp, cJSON_CreateNumber(2 * M_PI * g->spin_rev_s[j]));
        cJSON_AddItemToObject(o, "distribution", tippe_launch_options_json(&a->o, 1));
        cJSON_AddItemToObject(o, "zones", zones_json(d, g));
        cJSON_AddItemToObject(o, "cells", cells_json(g));
        cJSON_AddItemToObject(o, "radius_sensitivity", radius_json(g));
    }
    return tippe_cli_print_json(a->verb, o);
}

/* The patch law's radius sensitivity over the map: how many launches change verdict,
 * passage over pi/2 or fall back between 1/F and F times the radius, and where. */
static void print_radius(const hands_args *a, const map_grid *g)
{
    printf("radius     the patch radius is uncertain (surface, table, wear): the same launches "
           "at");
    for (int i = 0; i < 3; i += 2)
        printf("%s %.3gx (%.4g mm)%s", i ? " and" : "", g->factor[i], g->radius_m[i] * 1e3,
               g->rec_radius[i] ? "" : ", not run: wider than half the ball's radius");
    printf("\n");
    if (g->changed > 0)
        printf("           NOT robust to the radius: ");
    else if (!g->rec_radius[0] || !g->rec_radius[2])
        printf("           robustness to the radius not known: a radius was not run; ");
    else
        printf("           robust to the radius: ");
    printf("%ld of %ld launches change flip, fall back or decided verdict, in %ld of %ld "
           "cells\n",
           g->changed, g->total, g->cells_changed, g->n_cells);
    if (g->changed)
        for (int i = 0; i < g->n_z2; i++)
            for (int j = 0; j < g->n_spin; j++) {
                const long k = g->cell_changed[(long)i * g->n_spin + j];
                if (k)
                    printf("           Z2 %.4g mm, %.3g rev/s: %ld of %ld\n", g->z2_mm[i],
                           g->spin_rev_s[j], k, a->n);
            }
}

static void map_text(const hands_args *a, const tippe_design *d, const map_grid *g,
                     const tippe_launch_map *m, double elapsed)
{
    char sets[1024];
    printf("design     %s (%s)\n", tippe_design_name(d), tippe_design_path(d));
    if (a->sets.n)
        printf("changes    %s\n", tippe_cli_sets_text(&a->sets, sets, sizeof sets));
    printf("map        Z2 %g .. %g mm (%d) x spin %.4g .. %.4g rad/s = %g .. %g rev/s (%d), "
           "%ld launches per cell, seed %ld\n",
           a->z2_range.from, a->z2_range.to, g->n_z2, a->spin.from, a->spin.to,
           g->spin_rev_s[0], g->spin_rev_s[g->n_spin - 1], g->n_spin, a->n, a->seed);
    hands_print_distribution(&a->o, 1);
    hands_print_model(&a->o, &g->tops[0]);
    print_map_table(m, g->model_invalid);
    tippe_launch_tally all;
    tippe_error err;
    if (tippe_launch_tally_records(g->rec, g->total, &all, &err) == TIPPE_OK) {
        printf("\nall cells ");
        for (int v = 0; v < TIPPE_LAUNCH_N_VERDICTS; v++)
            printf("%s %s %ld", v ? "," : "", hands_verdict_names[v], all.counts[v]);
        printf(" of %ld; %ld of %ld settled launches agree with theory\n", g->total, all.agree,
               all.comparable);
        if (all.on_cap && a->o.sphere_contact_only) /* as tippe launch says it */
            printf("pole       INVALID for %ld of %ld launches: their contact lay within a "
                   "hole's opening at a pole before their verdict, where the top stands on the "
                   "hole's rim, not on its sphere as --sphere-contact assumes (JSON "
                   "on_polar_cap per cell)\n",
                   all.on_cap, g->total);
        else if (all.on_cap)
            printf("rim        %ld of %ld launches stood on a hole's rim at a pole before their "
                   "verdict: the contact follows the rim there (JSON on_polar_cap per cell)\n",
                   all.on_cap, g->total);
        char jellett[64] = "J not conserved (drilling)";
        if (!tippe_friction_law_type_of(a->o.law)->drills || !(a->o.mu_c > 0)) /* nothing drills */
            snprintf(jellett, sizeof jellett, "largest Jellett drift %.2g",
                     all.max_jellett_rel_drift);
        printf("accuracy   %s; %.2f s on %d thread%s x %d rank%s "
               "(%.1f launches/s)\n",
               jellett, elapsed, omp_get_max_threads(),
               omp_get_max_threads() > 1 ? "s" : "", hands_mpi_size(),
               hands_mpi_size() > 1 ? "s" : "",
               (double)tippe_launch_grid_work(g) / elapsed);
    }
    if (g->radius_runs)
        print_radius(a, g);
    if (a->csv)
        printf("csv        %s (%ld cells)\n", a->csv, g->n_cells);
    if (a->plot)
        printf("plot       %s\n", a->plot);
}

/* Rank 0, after the launches: tallies, files, report. */
static int map_report(const hands_args *a, const tippe_design *d, map_grid *g, double elapsed)
{
    tippe_error err;
    int rc = tippe_launch_grid_tally(g, &err);
    tippe_launch_map m = tippe_launch_grid_map(g);
    if (!rc && a->csv)
        rc = write_map_csv(a->csv, &m, g->tops, &err);
    char title[1024], sets[900];
    snprintf(title, sizeof title, "%s%s%s", tippe_design_name(d), a->sets.n ? " with " : "",
             tippe_cli_sets_text(&a->sets, sets, sizeof sets));
    /* one set with the CSV: both or neither (tippe/base.h) */
    if (!rc && a->plot)
        rc = tippe_launch_plot_map(a->plot, &m, d, a->o.g, title, &err);
    if (rc)
        return tippe_cli_fail(a->verb, &err, rc);
    if (a->json)
        return map_json(a, d, g);
    map_text(a, d, g, &m, elapsed);
    return 0;
}

int tippe_cli_map(int argc, char **argv)
{
    hands_args a = {.verb = "map", .n = 10, .seed = 1};
    tippe_launch_options_default(&a.o);
    a.o.until_flip = 0; /* the map shows shares of outcomes, not flip times */
    int rc = map_parse(&a, argc, argv);
    if (rc == TIPPE_CLI_HELP)
        return 0;
    tippe_error err;
    tippe_design *d = NULL;
    map_grid g = {0};
    if (!rc && (rc = tippe_design_load(a.design, a.sets.item, a.sets.n, &d, &err)) != 0)
        rc = tippe_cli_fail(a.verb, &err, rc);
    if (!rc && hands_mpi_rank() == 0)
        tippe_cli_design_warnings(a.verb, d);
    if (!rc && (rc = hands_patch(&a, d, &err)) != 0)
        rc = tippe_cli_fail(a.verb, &err, rc);
    if (!rc && (rc = tippe_launch_grid_make(d, a.z2_range.from, a.z2_range.to,
                                            (int)a.z2_range.steps, a.spin.from, a.spin.to,
                                            (int)a.spin.steps, a.n, &a.o,
                                            !a.no_radius_sensitivity, &g, &err)) != 0)
        rc = tippe_cli_fail(a.verb, &err, rc);
    if (!rc && g.total >= 100000 && hands_mpi_rank() == 0)
        fprintf(stderr, "tippe map: %ld launches (%d x %d cells x %ld) ahead; this takes a "
                        "while (progress below)\n", g.total, g.n_z2, g.n_spin, a.n);
    if ((rc = hands_mpi_agree(rc)) == 0) {
        const tippe_launch_plan plan = tippe_launch_grid_plan(&g);
        tippe_progress prog;
        const long work = tippe_launch_grid_work(&g);
        tippe_progress_start(&prog, stderr, "tippe map", work, tippe_cli_progress_mode());
        const double t0 = tippe_cli_now_s();
        rc = hands_run_plan(&plan, &a.o, (uint64_t)a.seed, g.rec, &prog, &err);
        if (!rc && g.radius_runs)
            rc = grid_radius_runs(&a, &g, &prog, &err);
        const double elapsed = tippe_cli_now_s() - t0;
        tippe_progress_finish(&prog);
        if (hands_mpi_rank() != 0)
            rc = 0;
        else if (rc)
            rc = tippe_cli_fail(a.verb, &err, rc);
        else
            rc = map_report(&a, d, &g, elapsed);
    }
    tippe_launch_grid_free(&g);
    tippe_design_free(d);
    return rc;
}
