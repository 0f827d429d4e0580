/* tippe sweep: the zones of a design along the travel of its moving weight. */
#include "cli.h"

#include "tippe/design.h"
#include "tippe/profile.h"
#include "tippe/plot.h"
#include "tippe/sweep.h"

#include <cjson/cJSON.h>

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

static const char *const VERB = "sweep";

/* "FIELD=FROM:TO:STEPS"; FROM may exceed TO (the values then fall). */
static int parse_vary(const char *spec, char *field, size_t n, double *from, double *to,
                      int *steps)
{
    const char *eq = strrchr(spec, '=');
    if (!eq || eq == spec || (size_t)(eq - spec) >= n)
        return 0;
    memcpy(field, spec, (size_t)(eq - spec));
    field[eq - spec] = '\0';
    return tippe_cli_parse_range(eq + 1, from, to, steps, 10000);
}

static void print_vary_table(const tippe_design *d, const tippe_sweep_vary_result *v,
                             const char *field, const tippe_cli_sets *sets)
{
    char text[1024];
    printf("design   %s (%s)\n", tippe_design_name(d), tippe_design_path(d));
    if (sets->n)
        printf("changes  %s\n", tippe_cli_sets_text(sets, text, sizeof text));
    printf("vary     %s from %g to %g in %d steps\n\n", field, v->values[0],
           v->values[v->n - 1], v->n);
    int w = (int)strlen(field) > 10 ? (int)strlen(field) : 10;
    printf("%*s  %-6s %-16s %s\n", w, field, "3-in-1", "narrowest (mm)",
           "zones: group from..to mm (* beyond physical travel, ! a part stands out of "
           "the sphere: model invalid)");
    for (int i = 0; i < v->n; i++) {
        const tippe_sweep_result *r = &v->results[i];
        if (v->collision[i]) { /* kept, not swept: the reason is below the table */
            printf("%*.6g  %-6s %-16spart collides (see below)\n", w, v->values[i], "-", "-");
            continue;
        }
        tippe_sweep_summary s;
        tippe_sweep_summarise(r, &s);
        char narrow[40] = "0";
        if (s.three_in_one)
            snprintf(narrow, sizeof narrow, "%.3f (%s)", s.narrowest_zone_mm, s.narrowest_family);
        printf("%*.6g  %-6s %-16s", w, v->values[i], s.three_in_one ? "yes" : "no", narrow);
        for (int j = 0; j < r->n_zones; j++) {
            const tippe_sweep_zone *z = &r->zones[j];
            double bf[2], bt[2];
            printf("%s%s %.3f..%.3f%s%s", j ? " | " : "", tippe_group_name(z->group),
                   fabs(z->z2_from_mm) < 5e-4 ? 0.0 : z->z2_from_mm,
                   fabs(z->z2_to_mm) < 5e-4 ? 0.0 : z->z2_to_mm, z->within_travel ? "" : "*",
                   z->within_travel && tippe_sweep_zone_model_invalid(r, z, bf, bt) ? "!" : "");
        }
        printf("\n");
    }
    if (v->n_collisions)
        printf("\n");
    for (int i = 0; i < v->n; i++)
        if (v->collision[i])
            printf("%s = %g: part collides: %s\n", field, v->values[i], v->collision[i]);
}

static cJSON *vary_json(const tippe_design *d, const tippe_sweep_vary_result *v,
                        const char *field)
{
    cJSON *o = cJSON_CreateObject(), *steps = NULL;
    if (!o || !cJSON_AddStringToObject(o, "design", tippe_design_name(d)) ||
        !cJSON_AddStringToObject(o, "file", tippe_design_path(d)) ||
        !cJSON_AddStringToObject(o, "field", field) ||
        !(steps = cJSON_AddArrayToObject(o, "steps"))) {
        cJSON_Delete(o);
        return NULL;
    }
    for (int i = 0; i < v->n; i++) {
        if (v->collision[i]) { /* {value, result: null, reason}: kept, not swept */
            cJSON *s = cJSON_CreateObject();
            if (!s || !cJSON_AddItemToArray(steps, s)) {
                cJSON_Delete(s);
                cJSON_Delete(o);
                return NULL;
            }
            if (!cJSON_AddNumberToObject(s, "value", v->values[i]) ||
                !cJSON_AddNullToObject(s, "zones") ||
                !cJSON_AddStringToObject(s, "collision", v->collision[i])) {
                cJSON_Delete(o);
                return NULL;
            }
            continue;
        }
        cJSON *s = tippe_sweep_json(&v->results[i], NULL);
        double tr[2] = {v->travel_from_mm[i], v->travel_to_mm[i]};
        cJSON *t = s ? cJSON_CreateDoubleArray(tr, 2) : NULL;
        if (!s || !t || !cJSON_AddItemToArray(steps, s)) {
            cJSON_Delete(s);
            cJSON_Delete(t);
            cJSON_Delete(o);
            return NULL;
        }
        if (!cJSON_AddNumberToObject(s, "value", v->values[i]) ||
            !cJSON_AddItemToObject(s, "travel_mm", t)) {
            cJSON_Delete(o);
            return NULL;
        }
    }
    return o;
}

typedef struct {
    const char *design, *plot, *phase, *vary, *csv;
    double from, to; /* from >= to: the design's stated travel */
    int has_from, has_to, json;
    tippe_cli_sets sets;
    char field[256]; /* --vary's */
    double vfrom, vto;
    int vsteps;
} sweep_args;

static int sweep_parse(sweep_args *a, int argc, char **argv)
{
    tippe_cli_opt opts[] = {
        {.name = "from", .kind = TIPPE_CLI_DOUBLE, .value = &a->from, .arg = "MM", .unit = "mm",
         .min = -TIPPE_CLI_Z2_MAX_MM, .max = TIPPE_CLI_Z2_MAX_MM,
         .def = "the travel's start",
         .help = "sweep Z2 from FROM (zones beyond the physical travel, where a moving\n"
                 "part would pass through a fixed one, are marked)"},
        {.name = "to", .kind = TIPPE_CLI_DOUBLE, .value = &a->to, .arg = "MM", .unit = "mm",
         .min = -TIPPE_CLI_Z2_MAX_MM, .max = TIPPE_CLI_Z2_MAX_MM, .def = "the travel's end",
         .help = "sweep Z2 up to TO"},
        {.name = "json", .kind = TIPPE_CLI_FLAG, .value = &a->json,
         .help = "print one JSON object instead of the table"},
        {.name = "plot", .kind = TIPPE_CLI_STRING, .value = &a->plot, .arg = "FILE",
         .help = "zone plot (A/C - 1 against Z2, as the paper's Figures 7, 9, 11);\n"
                 "PNG, SVG or PDF by the file's extension"},
        {.name = "phase-plot", .kind = TIPPE_CLI_STRING, .value = &a->phase, .arg = "FILE",
         .help = "the design's path through the phase diagram (Figure 2)"},
        {.name = "csv", .kind = TIPPE_CLI_STRING, .value = &a->csv, .arg = "FILE",
         .help = "the zone table as CSV: one row per zone (group, family, from, to, width,\n"
                 "robust width in mm, ends on, within the travel, model valid); with\n"
                 "--vary, one row per step and zone after a column of FIELD's value"},
        {.name = "set", .kind = TIPPE_CLI_SET, .value = &a->sets, .arg = "FIELD=VALUE",
         .help = "change a field of the design before it is checked (repeatable), e.g.\n"
                 "--set parts.rod.material=nylon  --set radius_mm=30"},
        {.name = "vary", .kind = TIPPE_CLI_STRING, .value = &a->vary,
         .arg = "FIELD=FROM:TO:STEPS",
         .help = "sweep again with FIELD set to STEPS (1 .. 10000) values from FROM to TO\n"
                 "(e.g. parts.weight.height_mm=5:15:11) and show how the zones move;\n"
                 "--plot then draws the zones against FIELD"},
        {NULL},
    };
    tippe_cli_spec spec = {
        .verb = VERB,
        .synopsis = "DESIGN.json [--from MM] [--to MM] [--json] [--plot FILE]\n"
                    "                   [--phase-plot FILE] [--csv FILE] [--set FIELD=VALUE ...]\n"
                    "                   [--vary FIELD=FROM:TO:STEPS]",
        .about = "Where along the travel of the moving weight (its midpoint at height Z2 above\n"
                 "the sphere's centre) the top is of group Ia, Ib, IIa, IIb, IIc or III\n"
                 "(Theorem 5.1 of Ciocci et al. 2012). Zone ends are located to 1e-6 mm.",
        .after = "The table lists each zone: its group, where it starts and ends (mm), its\n"
                 "width (mm), the boundary that ends it and notes; then whether the top is\n"
                 "\"3-in-1\" (groups I, II and III all reachable within the physical travel)\n"
                 "and its narrowest zone (0 unless 3-in-1). Then the design's tolerances (its\n"
                 "\"tolerances\" block and the defaults: printed dimensions +/-0.2 mm,\n"
                 "filament density +/-3 %, hardware mass +/-2 %), each zone boundary's band\n"
                 "(+/- mm, first order, independent tolerances in quadrature; docs/sweep.md)\n"
                 "and each zone's robust width (its width less the bands at both ends).\n"
                 "Exit status: 0 ok, 2 bad usage or design, 1 computation failed. tippe\n"
                 "compare takes several designs.",
        .opts = opts,
        .min_args = 1,
        .max_args = 1,
        .args_name = "design file",
    };
    int n_args, rc = tippe_cli_parse(&spec, argc, argv, &a->design, &n_args);
    if (rc)
        return rc;
    a->has_from = opts[0].seen;
    a->has_to = opts[1].seen;
    if (a->has_from && a->has_to && !(a->from < a->to))
        return tippe_cli_usage_error(VERB, "--from %g must be below --to %g", a->from, a->to);
    if ((a->plot && tippe_cli_check_output(VERB, "--plot", a->plot, 1)) ||
        (a->phase && tippe_cli_check_output(VERB, "--phase-plot", a->phase, 1)))
        return 2;
    if (a->csv && tippe_cli_check_output(VERB, "--csv", a->csv, 0))
        return 2;
    if (a->plot && a->phase && !strcmp(a->plot, a->phase))
        return tippe_cli_usage_error(VERB, "--plot and --phase-plot name the same file '%s'",
                                     a->plot);
    if (a->csv && ((a->plot && !strcmp(a->csv, a->plot)) ||
                   (a->phase && !strcmp(a->csv, a->phase))))
        return tippe_cli_usage_error(VERB, "--csv names the same file '%s' as a plot", a->csv);
    if (a->vary &&
        !parse_vary(a->vary, a->field, sizeof a->field, &a->vfrom, &a->vto, &a->vsteps))
        return tippe_cli_usage_error(VERB,
                                     "--vary '%s': expected FIELD=FROM:TO:STEPS with numbers "
                                     "FROM, TO and 1 to 10000 STEPS (e.g. "
                                     "parts.weight.height_mm=5:15:11)",
                                     a->vary);
    if (a->vary && a->phase)
        return tippe_cli_usage_error(
            VERB, "--phase-plot draws one sweep; it cannot be combined with --vary");
    return 0;
}

/* One end given: the other is the stated travel's. 0, or 2 if that is empty. */
static int sweep_ends(sweep_args *a, const tippe_design *d)
{
    double tf, tt;
    tippe_design_travel_mm(d, &tf, &tt);
    if (a->has_from == a->has_to)
        return 0;
    if (!a->has_from)
        a->from = tf;
    if (!a->has_to)
        a->to = tt;
    if (!(a->from < a->to))
        return tippe_cli_usage_error(
            VERB, "the sweep Z2 = %g .. %g mm is empty (the stated travel is %g .. %g mm)",
            a->from, a->to, tf, tt);
    return 0;
}

/* --csv: the zone table (or a vary's tables), written whole or not at all. */
static int write_zone_csv(const char *path, const tippe_sweep_result *r,
                          const tippe_sweep_bands_result *b, const tippe_sweep_vary_result *v,
                          const char *field, tippe_error *err)
{
    tippe_report_file rf;
    int rc = tippe_report_open(&rf, path, "the CSV file", err);
    if (rc)
        return rc;
    if (v)
        tippe_sweep_vary_write_csv(rf.f, v, field);
    else
        tippe_sweep_write_csv(rf.f, r, b);
    return tippe_report_commit(&rf, err);
}

static int sweep_vary_run(const sweep_args *a, const tippe_design *d, const char *title)
{
    tippe_error err = {0};
    tippe_sweep_vary_result v;
    int rc = tippe_sweep_vary(d, a->field, a->vfrom, a->vto, a->vsteps, a->from, a->to, NULL,
                              &v, &err);
    if (!rc && a->plot)
        rc = tippe_sweep_plot_vary(a->plot, &v, a->field, title, &err);
    if (!rc && a->csv)
        rc = write_zone_csv(a->csv, NULL, NULL, &v, a->field, &err);
    if (!rc) {
        if (a->json) {
            cJSON *o = vary_json(d, &v, a->field);
            if (o)
                tippe_cli_json_sets(o, &a->sets);
            rc = tippe_cli_print_json(VERB, o);
        } else {
            print_vary_table(d, &v, a->field, &a->sets);
        }
    } else {
        rc = tippe_cli_fail(VERB, &err, rc);
    }
    tippe_sweep_vary_free(&v);
    return rc;
}

static int sweep_run(const sweep_args *a, const tippe_design *d, const char *title)
{
    tippe_error err = {0};
    tippe_sweep_result r;
    tippe_sweep_bands_result b = {0};
    int rc = tippe_sweep_design(d, a->from, a->to, NULL, &r, &err);
    if (!rc)
        rc = tippe_sweep_bands(d, &r, &b, &err);
    tippe_sweep_path p = tippe_sweep_design_path(d);
    if (!rc && a->plot)
        rc = tippe_sweep_plot_zones_banded(a->plot, &p, &r, &b, title, &err);
    if (!rc && a->phase) /* one set with the plot (tippe_cli_run): both or neither */
        rc = tippe_sweep_plot_phase(a->phase, &p, &r, title, &err);
    if (!rc && a->csv)
        rc = write_zone_csv(a->csv, &r, &b, NULL, NULL, &err);
    if (rc) {
        rc = tippe_cli_fail(VERB, &err, rc);
    } else if (a->json) {
        cJSON *o = tippe_sweep_report_json(d, &r, &b);
        if (o)
            tippe_cli_json_sets(o, &a->sets);
        rc = tippe_cli_print_json(VERB, o);
    } else {
        char sets[1024];
        if (a->sets.n) /* first, so that the design line below reads as the variant */
            printf("changes  %s\n", tippe_cli_sets_text(&a->sets, sets, sizeof sets));
        tippe_sweep_print_table(stdout, &r, d);
        tippe_sweep_print_bands(stdout, d, &r, &b);
        printf("\n");
        tippe_profile_print_printed_parts(stdout, d);
    }
    tippe_sweep_bands_free(&b);
    tippe_sweep_result_free(&r);
    return rc;
}

int tippe_cli_sweep(int argc, char **argv)
{
    sweep_args a = {.from = 0.0};
    int rc = sweep_parse(&a, argc, argv);
    if (rc)
        return rc == TIPPE_CLI_HELP ? 0 : rc;
    tippe_error err = {0};
    tippe_design *d = NULL;
    rc = tippe_design_load(a.design, a.sets.item, a.sets.n, &d, &err);
    if (rc)
        return tippe_cli_fail(VERB, &err, rc);
    tippe_cli_design_warnings(VERB, d);
    /* the plots' titles name the variant, not only the file's design */
    char title[1024], sets[900];
    snprintf(title, sizeof title, "%s%s%s", tippe_design_name(d), a.sets.n ? " with " : "",
             tippe_cli_sets_text(&a.sets, sets, sizeof sets));
    rc = sweep_ends(&a, d);
    if (!rc)
        rc = a.vary ? sweep_vary_run(&a, d, title) : sweep_run(&a, d, title);
    tippe_design_free(d);
    return rc;
}
