/* tippe compare: the zone tables of several designs side by side. */
#include "cli.h"

#include "tippe/design.h"
#include "tippe/sweep.h"

#include <cjson/cJSON.h>

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_SETS 64
#define MAX_DESIGNS 16
#define COL 38 /* characters per design column */

static void compare_usage(FILE *out)
{
    fprintf(out,
            "usage: tippe compare A.json B.json ... [--json] [--set FIELD=VALUE ...]\n"
            "\n"
            "The zones of several designs (each swept over its stated travel) side by side:\n"
            "group, from .. to and width in mm (* marks a zone beyond the physical travel),\n"
            "then whether each is \"3-in-1\" and its narrowest reachable zone.\n"
            "\n"
            "  --json             print {\"designs\": [...]} with one sweep object per design\n"
            "                     (as tippe sweep --json) instead of the table\n"
            "  --set FIELD=VALUE  change a field in every design before it is checked\n"
            "  --help             this text\n"
            "\n"
            "Exit status: 0 ok, 2 bad usage or design, 1 computation failed.\n");
}

__attribute__((format(printf, 1, 2))) static int usage_error(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "tippe compare: ");
    vfprintf(stderr, fmt, ap);
    fprintf(stderr, " (try tippe compare --help)\n");
    va_end(ap);
    return 2;
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

static void print_side_by_side(int n, tippe_design **d, tippe_sweep_result *r)
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
        cell("zone  from (mm)  to (mm) width (mm)");
    printf("\n");
    int rows = 0;
    for (int i = 0; i < n; i++)
        rows = r[i].n_zones > rows ? r[i].n_zones : rows;
    for (int j = 0; j < rows; j++) {
        for (int i = 0; i < n; i++) {
            buf[0] = '\0';
            if (j < r[i].n_zones) {
                const tippe_sweep_zone *z = &r[i].zones[j];
                snprintf(buf, sizeof buf, "%-4s %9.3f %9.3f %9.3f%s", tippe_group_name(z->group),
                         clean(z->z2_from_mm), clean(z->z2_to_mm), z->z2_to_mm - z->z2_from_mm,
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
    printf("\n* beyond the physical travel (a moving part would pass through a fixed one)\n");
}

int tippe_cli_compare(int argc, char **argv)
{
    const char *paths[MAX_DESIGNS], *sets[MAX_SETS];
    int n = 0, n_sets = 0, json = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            compare_usage(stdout);
            return 0;
        } else if (!strcmp(a, "--json")) {
            json = 1;
        } else if (!strcmp(a, "--set")) {
            if (i + 1 >= argc)
                return usage_error("--set needs a value");
            if (n_sets == MAX_SETS)
                return usage_error("too many --set options (at most %d)", MAX_SETS);
            sets[n_sets++] = argv[++i];
        } else if (a[0] == '-' && a[1] != '\0') {
            return usage_error("unknown option '%s'", a);
        } else {
            if (n == MAX_DESIGNS)
                return usage_error("too many designs (at most %d)", MAX_DESIGNS);
            paths[n++] = a;
        }
    }
    if (n < 1)
        return usage_error("no design file given");

    tippe_design *d[MAX_DESIGNS] = {0};
    tippe_sweep_result r[MAX_DESIGNS];
    memset(r, 0, sizeof r);
    tippe_error err = {0};
    int rc = TIPPE_OK, loaded = 0;
    for (int i = 0; i < n && rc == TIPPE_OK; i++, loaded++) {
        rc = tippe_design_load(paths[i], sets, n_sets, &d[i], &err);
        if (rc == TIPPE_OK)
            rc = tippe_sweep_design(d[i], 0.0, 0.0, NULL, &r[i], &err);
    }
    if (rc != TIPPE_OK) {
        fprintf(stderr, "tippe compare: %s\n", err.msg);
        rc = rc == TIPPE_EINPUT ? 2 : 1;
    } else if (json) {
        cJSON *o = cJSON_CreateObject();
        cJSON *arr = o ? cJSON_AddArrayToObject(o, "designs") : NULL;
        for (int i = 0; arr && i < n; i++) {
            cJSON *s = tippe_sweep_json(&r[i], d[i]);
            if (!s || !cJSON_AddItemToArray(arr, s)) {
                cJSON_Delete(s);
                arr = NULL;
            }
        }
        char *text = arr ? cJSON_Print(o) : NULL;
        cJSON_Delete(o);
        if (text) {
            printf("%s\n", text);
            free(text);
        } else {
            fprintf(stderr, "tippe compare: out of memory while writing JSON\n");
            rc = 1;
        }
    } else {
        print_side_by_side(n, d, r);
    }
    for (int i = 0; i < loaded; i++) {
        tippe_sweep_result_free(&r[i]);
        tippe_design_free(d[i]);
    }
    return rc;
}
