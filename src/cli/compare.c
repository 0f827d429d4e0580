/* tippe compare: the zone tables of several designs side by side. */
#include "cli.h"

#include "tippe/design.h"
#include "tippe/sweep.h"
#include "tippe/sweep_bands.h"

#include <cjson/cJSON.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#define MAX_DESIGNS 16
#define COL 44 /* characters per design column */

static const char *const VERB = "compare";

static void compare_usage(FILE *out)
{
    fprintf(out,
            "usage: tippe compare A.json B.json ... [--json] [--set FIELD=VALUE ...]\n"
            "\n"
            "The zones of several designs (each swept over its stated travel) side by side:\n"
            "group, from .. to, width and robust width in mm (the width less the tolerance\n"
            "bands at both ends, as tippe sweep reports them; * marks a zone beyond the\n"
            "physical travel), then whether each is \"3-in-1\" and its narrowest reachable\n"
            "zone, as found and robust.\n"
            "\n"
            "  --json             print {\"designs\": [...]} with one sweep object per design\n"
            "                     (as tippe sweep --json) instead of the table\n"
            "  --set FIELD=VALUE  change a field in every design before it is checked\n"
            "  --help             this text\n"
            "\n"
            "Exit status: 0 ok, 2 bad usage or design, 1 computation failed.\n");
}

/* Prints s in a column of COL characters (cut with "~" if longer). */
static void cell(const char *s)
{
    int len = (int)strlen(s);
    if (len > COL - 2)
        printf("%.*s~ ", COL - 3, s);
    else
        printf("%-*s", COL, s);
}

static double clean(double x) { return fabs(x) < 5e-4 ? 0.0 : x; }

static void print_side_by_side(int n, tippe_design **d, tippe_sweep_result *r,
                               const tippe_sweep_bands_result *b)
{
    char buf[256];
    for (int i = 0; i < n; i++)
        cell(tippe_design_name(d[i]));
    printf("\n");
    for (int i = 0; i < n; i++)
        cell(tippe_design_path(d[i]));
    printf("\n");
    for (int i = 0; i < n; i++) {
        snprintf(buf, sizeof buf, "travel %.2f..%.2f, phys. %.2f..%.2f", clean(r[i].from_mm),
                 clean(r[i].to_mm), clean(r[i].travel_from_mm), clean(r[i].travel_to_mm));
        cell(buf);
    }
    printf("\n");
    for (int i = 0; i < n; i++)
        cell("zone     from       to    width   robust");
    printf("\n");
    int rows = 0;
    for (int i = 0; i < n; i++)
        rows = r[i].n_zones > rows ? r[i].n_zones : rows;
    for (int j = 0; j < rows; j++) {
        for (int i = 0; i < n; i++) {
            buf[0] = '\0';
            if (j < r[i].n_zones) {
                const tippe_sweep_zone *z = &r[i].zones[j];
                snprintf(buf, sizeof buf, "%-4s %8.3f %8.3f %8.3f %8.3f%s",
                         tippe_group_name(z->group), clean(z->z2_from_mm), clean(z->z2_to_mm),
                         z->z2_to_mm - z->z2_from_mm, tippe_sweep_zone_robust_mm(&r[i], &b[i], j),
                         z->within_travel ? "" : "*");
            }
            cell(buf);
        }
        printf("\n");
    }
    for (int i = 0; i < n; i++) {
        tippe_sweep_summary s;
        tippe_sweep_summarise(&r[i], &s);
        snprintf(buf, sizeof buf, "3-in-1: %s (%s%s%s)", s.three_in_one ? "yes" : "no",
                 s.has_I ? "I " : "", s.has_II ? "II " : "", s.has_III ? "III" : "");
        cell(buf);
    }
    printf("\n");
    for (int i = 0; i < n; i++) {
        tippe_sweep_summary s;
        tippe_sweep_summarise(&r[i], &s);
        if (s.narrowest_family)
            snprintf(buf, sizeof buf, "narrowest: %.3f mm (%s)", s.narrowest_zone_mm,
                     s.narrowest_family);
        else
            snprintf(buf, sizeof buf, "narrowest: -");
        cell(buf);
    }
    printf("\n");
    for (int i = 0; i < n; i++) {
        double rob[3], narrow;
        tippe_sweep_robust_widths(&r[i], &b[i], rob, &narrow);
        snprintf(buf, sizeof buf, "robust narrowest: %.3f mm", narrow);
        cell(buf);
    }
    printf("\n(mm; robust: less the tolerance bands of the zone's ends, see tippe sweep)");
    printf("\n* beyond the physical travel (a moving part would pass through a fixed one)\n");
}

int tippe_cli_compare(int argc, char **argv)
{
    const char *paths[MAX_DESIGNS], *v;
    tippe_cli_sets sets = {.n = 0};
    int n = 0, json = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (tippe_cli_is_help(a)) {
            compare_usage(stdout);
            return 0;
        } else if (!strcmp(a, "--json")) {
            json = 1;
        } else if (tippe_cli_option(VERB, argc, argv, &i, "--set", 0, &v)) {
            if (!v || tippe_cli_add_set(VERB, &sets, v))
                return 2;
        } else if (tippe_cli_is_option(a, 0)) {
            return tippe_cli_usage_error(VERB, "unknown option '%s'", a);
        } else {
            if (n == MAX_DESIGNS)
                return tippe_cli_usage_error(VERB, "too many designs (at most %d)", MAX_DESIGNS);
            paths[n++] = a;
        }
    }
    if (n < 1)
        return tippe_cli_usage_error(VERB, "no design file given");

    tippe_design *d[MAX_DESIGNS] = {0};
    tippe_sweep_result r[MAX_DESIGNS];
    tippe_sweep_bands_result b[MAX_DESIGNS];
    memset(r, 0, sizeof r);
    memset(b, 0, sizeof b);
    tippe_error err = {0};
    int rc = TIPPE_OK, loaded = 0;
    for (int i = 0; i < n && rc == TIPPE_OK; i++, loaded++) {
        rc = tippe_design_load(paths[i], sets.item, sets.n, &d[i], &err);
        if (rc == TIPPE_OK)
            rc = tippe_sweep_design(d[i], 0.0, 0.0, NULL, &r[i], &err);
        if (rc == TIPPE_OK)
            rc = tippe_sweep_bands(d[i], &r[i], &b[i], &err);
    }
    if (rc != TIPPE_OK) {
        rc = tippe_cli_fail(VERB, &err, rc);
    } else if (json) {
        cJSON *o = cJSON_CreateObject();
        cJSON *arr = o ? cJSON_AddArrayToObject(o, "designs") : NULL;
        for (int i = 0; arr && i < n; i++) {
            cJSON *s = tippe_sweep_json(&r[i], d[i]);
            if (!s || tippe_sweep_json_add_bands(s, d[i], &r[i], &b[i]) ||
                !cJSON_AddItemToArray(arr, s)) {
                cJSON_Delete(s);
                arr = NULL;
            }
        }
        if (!arr) {
            cJSON_Delete(o);
            o = NULL;
        }
        rc = tippe_cli_print_json(VERB, o);
    } else {
        print_side_by_side(n, d, r, b);
    }
    for (int i = 0; i < loaded; i++) {
        tippe_sweep_bands_free(&b[i]);
        tippe_sweep_result_free(&r[i]);
        tippe_design_free(d[i]);
    }
    return rc;
}
