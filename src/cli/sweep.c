/* tippe sweep: the zones of a design along the travel of its moving weight. */
#include "cli.h"

#include "tippe/design.h"
#include "tippe/plot.h"
#include "tippe/sweep.h"
#include "tippe/sweep_bands.h"

#include <cjson/cJSON.h>

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

static const char *const VERB = "sweep";

static void sweep_usage(FILE *out)
{
    fprintf(out,
            "usage: tippe sweep DESIGN.json [--from MM] [--to MM] [--json] [--plot FILE]\n"
            "                   [--phase-plot FILE] [--set FIELD=VALUE ...]\n"
            "                   [--vary FIELD=FROM:TO:STEPS]\n"
            "\n"
            "Where along the travel of the moving weight (its midpoint at height Z2 above the\n"
            "sphere's centre) the top is of group Ia, Ib, IIa, IIb, IIc or III (Theorem 5.1 of\n"
            "Ciocci et al. 2012). Zone ends are located to 1e-6 mm.\n"
            "\n"
            "  --from MM, --to MM  sweep Z2 over [FROM, TO] mm (default: the design's stated\n"
            "                      travel); zones beyond the physical travel (where a moving\n"
            "                      part would pass through a fixed one) are marked\n"
            "  --json              print one JSON object instead of the table\n"
            "  --plot FILE         zone plot (A/C - 1 against Z2, as the paper's Figures 7, 9,\n"
            "                      11); PNG, SVG or PDF by the file's extension\n"
            "  --phase-plot FILE   the design's path through the phase diagram (Figure 2)\n"
            "  --set FIELD=VALUE   change a field of the design before it is checked, e.g.\n"
            "                      --set parts.rod.material=nylon  --set radius_mm=30\n"
            "  --vary FIELD=FROM:TO:STEPS\n"
            "                      sweep again with FIELD set to STEPS values from FROM to TO\n"
            "                      (e.g. parts.weight.height_mm=5:15:11) and show how the zones\n"
            "                      move; --plot then draws the zones against FIELD\n"
            "  --help              this text\n"
            "\n"
            "The table lists each zone: its group, where it starts and ends (mm), its width\n"
            "(mm), the boundary that ends it and notes; then whether the top is \"3-in-1\"\n"
            "(groups I, II and III all reachable within the physical travel) and its narrowest\n"
            "reachable zone. Exit status: 0 ok, 2 bad usage or design, 1 computation failed.\n");
}

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
                             const char *field)
{
    printf("design   %s (%s)\n", tippe_design_name(d), tippe_design_path(d));
    printf("vary     %s from %g to %g in %d steps\n\n", field, v->values[0],
           v->values[v->n - 1], v->n);
    int w = (int)strlen(field) > 10 ? (int)strlen(field) : 10;
    printf("%*s  %-6s %-16s %s\n", w, field, "3-in-1", "narrowest (mm)",
           "zones: group from..to mm (* beyond physical travel)");
    for (int i = 0; i < v->n; i++) {
        const tippe_sweep_result *r = &v->results[i];
        tippe_sweep_summary s;
        tippe_sweep_summarise(r, &s);
        char narrow[40] = "-";
        if (s.narrowest_family)
            snprintf(narrow, sizeof narrow, "%.3f (%s)", s.narrowest_zone_mm, s.narrowest_family);
        printf("%*.6g  %-6s %-16s", w, v->values[i], s.three_in_one ? "yes" : "no", narrow);
        for (int j = 0; j < r->n_zones; j++) {
            const tippe_sweep_zone *z = &r->zones[j];
            printf("%s%s %.3f..%.3f%s", j ? " | " : "", tippe_group_name(z->group),
                   fabs(z->z2_from_mm) < 5e-4 ? 0.0 : z->z2_from_mm,
                   fabs(z->z2_to_mm) < 5e-4 ? 0.0 : z->z2_to_mm, z->within_travel ? "" : "*");
        }
        printf("\n");
    }
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

int tippe_cli_sweep(int argc, char **argv)
{
    const char *path = NULL, *plot = NULL, *phase = NULL, *vary = NULL;
    const char *from_text = NULL, *to_text = NULL, *set = NULL;
    tippe_cli_sets sets = {.n = 0};
    int json = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char **val = NULL;
        if (tippe_cli_is_help(a)) {
            sweep_usage(stdout);
            return 0;
        } else if (!strcmp(a, "--json")) {
            json = 1;
            continue;
        } else if (!strcmp(a, "--from")) {
            val = &from_text;
        } else if (!strcmp(a, "--to")) {
            val = &to_text;
        } else if (!strcmp(a, "--plot")) {
            val = &plot;
        } else if (!strcmp(a, "--phase-plot")) {
            val = &phase;
        } else if (!strcmp(a, "--vary")) {
            val = &vary;
        } else if (!strcmp(a, "--set")) {
            val = &set;
        } else if (tippe_cli_is_option(a, 1)) {
            return tippe_cli_usage_error(VERB, "unknown option '%s'", a);
        } else if (!path) {
            path = a;
            continue;
        } else {
            return tippe_cli_usage_error(
                VERB, "one design file only (got also '%s'; tippe compare takes several)", a);
        }
        if (!(*val = tippe_cli_value(VERB, argc, argv, &i)))
            return 2;
        if (val == &set && tippe_cli_add_set(VERB, &sets, set))
            return 2;
    }
    if (!path)
        return tippe_cli_usage_error(VERB, "no design file given");
    double from = 0.0, to = 0.0; /* from >= to: the design's stated travel */
    int has_from = from_text != NULL, has_to = to_text != NULL;
    if ((has_from && tippe_cli_number(VERB, "--from", from_text, "mm", &from)) ||
        (has_to && tippe_cli_number(VERB, "--to", to_text, "mm", &to)))
        return 2;
    if (has_from && has_to && !(from < to))
        return tippe_cli_usage_error(VERB, "--from %g must be below --to %g", from, to);
    if ((plot && tippe_cli_check_output(VERB, "--plot", plot, 1)) ||
        (phase && tippe_cli_check_output(VERB, "--phase-plot", phase, 1)))
        return 2;
    if (plot && phase && !strcmp(plot, phase))
        return tippe_cli_usage_error(VERB, "--plot and --phase-plot name the same file '%s'", plot);
    char field[256];
    double vfrom = 0, vto = 0;
    int vsteps = 0;
    if (vary && !parse_vary(vary, field, sizeof field, &vfrom, &vto, &vsteps))
        return tippe_cli_usage_error(
            VERB,
            "--vary '%s': expected FIELD=FROM:TO:STEPS with numbers FROM, TO "
            "and 1 to 10000 STEPS (e.g. parts.weight.height_mm=5:15:11)",
            vary);
    if (vary && phase)
        return tippe_cli_usage_error(
            VERB, "--phase-plot draws one sweep; it cannot be combined with --vary");

    tippe_error err = {0};
    tippe_design *d = NULL;
    int rc = tippe_design_load(path, sets.item, sets.n, &d, &err);
    if (rc)
        return tippe_cli_fail(VERB, &err, rc);
    /* One end given: the other is the stated travel's. */
    double tf, tt;
    tippe_design_travel_mm(d, &tf, &tt);
    if (has_from != has_to) {
        if (!has_from)
            from = tf;
        if (!has_to)
            to = tt;
        if (!(from < to)) {
            tippe_design_free(d);
            return tippe_cli_usage_error(
                VERB,
                "the sweep Z2 = %g .. %g mm is empty (the stated travel is "
                "%g .. %g mm)",
                from, to, tf, tt);
        }
    }

    if (vary) {
        tippe_sweep_vary_result v;
        rc = tippe_sweep_vary(path, sets.item, sets.n, field, vfrom, vto, vsteps, from, to, NULL,
                              &v, &err);
        if (!rc && plot)
            rc = tippe_sweep_plot_vary(plot, &v, field, tippe_design_name(d), &err);
        if (!rc) {
            if (json)
                rc = tippe_cli_print_json(VERB, vary_json(d, &v, field));
            else
                print_vary_table(d, &v, field);
        } else {
            rc = tippe_cli_fail(VERB, &err, rc);
        }
        tippe_sweep_vary_free(&v);
        tippe_design_free(d);
        return rc;
    }

    tippe_sweep_result r;
    tippe_sweep_bands_result b = {0};
    rc = tippe_sweep_design(d, from, to, NULL, &r, &err);
    if (!rc)
        rc = tippe_sweep_bands(d, &r, &b, &err);
    tippe_sweep_path p = tippe_sweep_design_path(d);
    if (!rc && plot)
        rc = tippe_sweep_plot_zones_banded(plot, &p, &r, &b, tippe_design_name(d), &err);
    if (!rc && phase) {
        rc = tippe_sweep_plot_phase(phase, &p, &r, tippe_design_name(d), &err);
        if (rc && plot)
            unlink(plot); /* all outputs or none */
    }
    if (rc) {
        rc = tippe_cli_fail(VERB, &err, rc);
    } else if (json) {
        cJSON *o = tippe_sweep_json(&r, d);
        if (o && tippe_sweep_json_add_bands(o, d, &r, &b)) {
            cJSON_Delete(o);
            o = NULL;
        }
        rc = tippe_cli_print_json(VERB, o);
    } else {
        tippe_sweep_print_table(stdout, &r, d);
        tippe_sweep_print_bands(stdout, d, &r, &b);
    }
    tippe_sweep_bands_free(&b);
    tippe_sweep_result_free(&r);
    tippe_design_free(d);
    return rc;
}
