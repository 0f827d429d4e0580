/* tippe compare: the zone tables of several designs side by side. */
#include "cli.h"

#include "tippe/plot.h"
#include "tippe/design.h"
#include "tippe/base.h"
#include "tippe/sweep.h"

#include <cjson/cJSON.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#define MAX_DESIGNS 16
#define COL 44 /* characters per design column */

static const char *const VERB = "compare";

typedef struct {
    const char *paths[MAX_DESIGNS], *csv, *plot;
    int n, json, wide;
    tippe_cli_sets all_sets;          /* --set as given */
    tippe_cli_sets sets[MAX_DESIGNS]; /* each design's */
} compare_args;

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

/* Whether the designs' names, cut to width characters, still differ wherever the
 * whole names differ (issue 25.5: two long names alike in their first 40
 * characters made two rows look alike). */
static int names_cut_distinct(int n, tippe_design **d, int width)
{
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++) {
            const char *a = tippe_design_name(d[i]), *b = tippe_design_name(d[j]);
            if (strcmp(a, b) && !strncmp(a, b, (size_t)width))
                return 0;
        }
    return 1;
}

/* The width of the summary's name column: 40, or the longest name when cutting
 * to 40 would make two different names alike. */
static int name_width(int n, tippe_design **d)
{
    if (names_cut_distinct(n, d, 39))
        return 40;
    int w = 40;
    for (int i = 0; i < n; i++)
        if ((int)strlen(tippe_design_name(d[i])) > w)
            w = (int)strlen(tippe_design_name(d[i]));
    return w;
}

/* "!" for a zone where some part stands out of the sphere (the model does not
 * apply there: docs/design-format.md). */
static const char *invalid_mark(const tippe_sweep_result *r, const tippe_sweep_zone *z)
{
    double f[2], t[2];
    return z->within_travel && tippe_sweep_zone_model_invalid(r, z, f, t) ? "!" : "";
}

/* "yes (I II III)", "no (III)": whether the design has all three families and
 * which it has, one space between them. Returns buf. */
static const char *three_in_one_text(const tippe_sweep_summary *s, char *buf, size_t size)
{
    const char *fam[3] = {s->has_I ? "I" : NULL, s->has_II ? "II" : NULL,
                          s->has_III ? "III" : NULL};
    size_t len = (size_t)snprintf(buf, size, "%s (", s->three_in_one ? "yes" : "no");
    int any = 0;
    for (int k = 0; k < 3 && len < size; k++)
        if (fam[k])
            len += (size_t)snprintf(buf + len, size - len, "%s%s", any++ ? " " : "", fam[k]);
    if (len < size)
        snprintf(buf + len, size - len, "%s)", any ? "" : "none");
    return buf;
}

static void print_wide(int n, tippe_design **d, tippe_sweep_result *r,
                               const tippe_sweep_bands_result *b)
{
    char buf[256];
    if (!names_cut_distinct(n, d, COL - 3)) /* the columns cut them alike: say them whole */
        for (int i = 0; i < n; i++)
            printf("column %d: %s\n", i + 1, tippe_design_name(d[i]));
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
                snprintf(buf, sizeof buf, "%-4s %8.3f %8.3f %8.3f %8.3f%s%s",
                         tippe_group_name(z->group), clean(z->z2_from_mm), clean(z->z2_to_mm),
                         z->z2_to_mm - z->z2_from_mm, tippe_sweep_zone_robust_mm(&r[i], &b[i], j),
                         z->within_travel ? "" : "*", invalid_mark(&r[i], z));
            }
            cell(buf);
        }
        printf("\n");
    }
    for (int i = 0; i < n; i++) {
        tippe_sweep_summary s;
        tippe_sweep_summarise(&r[i], &s);
        char fam[16];
        snprintf(buf, sizeof buf, "3-in-1: %s", three_in_one_text(&s, fam, sizeof fam));
        cell(buf);
    }
    printf("\n");
    for (int i = 0; i < n; i++) {
        tippe_sweep_summary s;
        tippe_sweep_summarise(&r[i], &s);
        if (s.three_in_one)
            snprintf(buf, sizeof buf, "narrowest: %.3f mm (%s)", s.narrowest_zone_mm,
                     s.narrowest_family);
        else
            snprintf(buf, sizeof buf, "narrowest: 0 mm (not 3-in-1)");
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
    printf("\n* beyond the physical travel (a moving part would pass through a fixed one)");
    printf("\n! a part stands out of the sphere in (part of) the zone: the model does not apply\n");
}

/* The stacked table (fits 100 columns): one block of zones per design, then
 * one summary line per design. */
static void print_stacked(int n, tippe_design **d, tippe_sweep_result *r,
                          const tippe_sweep_bands_result *b, const compare_args *a)
{
    char sets[1024];
    for (int i = 0; i < n; i++) {
        printf("[%d] %s (%s)\n", i + 1, tippe_design_name(d[i]), tippe_design_path(d[i]));
        if (a->sets[i].n)
            printf("    changes %s\n", tippe_cli_sets_text(&a->sets[i], sets, sizeof sets));
        printf("    travel %.3f .. %.3f mm, physical %.3f .. %.3f mm\n", clean(r[i].from_mm),
               clean(r[i].to_mm), clean(r[i].travel_from_mm), clean(r[i].travel_to_mm));
        printf("    zone    from (mm)    to (mm)  width (mm)  robust (mm)\n");
        for (int j = 0; j < r[i].n_zones; j++) {
            const tippe_sweep_zone *z = &r[i].zones[j];
            printf("    %-4s %12.3f %10.3f %11.3f %12.3f%s%s\n", tippe_group_name(z->group),
                   clean(z->z2_from_mm), clean(z->z2_to_mm), z->z2_to_mm - z->z2_from_mm,
                   tippe_sweep_zone_robust_mm(&r[i], &b[i], j), z->within_travel ? "" : "  *",
                   invalid_mark(&r[i], z)[0] ? "  !" : "");
        }
        printf("\n");
    }
    int nw = name_width(n, d);
    printf("%-4s %-*s %-15s %-18s %s\n", "", nw, "design", "3-in-1", "narrowest (mm)",
           "robust narrowest");
    for (int i = 0; i < n; i++) {
        tippe_sweep_summary s;
        tippe_sweep_summarise(&r[i], &s);
        double rob[3], narrow;
        tippe_sweep_robust_widths(&r[i], &b[i], rob, &narrow);
        char groups[32], nar[40];
        three_in_one_text(&s, groups, sizeof groups);
        if (s.three_in_one)
            snprintf(nar, sizeof nar, "%.3f (%s)", s.narrowest_zone_mm, s.narrowest_family);
        else
            snprintf(nar, sizeof nar, "0");
        const char *name = tippe_design_name(d[i]);
        if ((int)strlen(name) > nw) /* cut, and said so */
            printf("[%-2d] %.*s~ %-15s %-18s %.3f\n", i + 1, nw - 1, name, groups, nar, narrow);
        else
            printf("[%-2d] %-*s %-15s %-18s %.3f\n", i + 1, nw, name, groups, nar, narrow);
    }
    printf("\n(robust: less the tolerance bands of the zone's ends, see tippe sweep; * beyond "
           "the physical\ntravel, where a moving part would pass through a fixed one; ! a part "
           "stands out of the\nsphere in (part of) the zone, where the model does not apply; "
           "--wide puts the designs side by side)\n");
}

static int write_csv(const char *path, int n, tippe_design **d, const tippe_sweep_result *r,
                     const tippe_sweep_bands_result *b, tippe_error *err)
{
    tippe_report_file rf;
    int rc = tippe_report_open(&rf, path, "the CSV file", err);
    if (rc)
        return rc;
    fprintf(rf.f, "design_index,design,file,zone,group,z2_from_mm,z2_to_mm,width_mm,"
                  "robust_width_mm,within_travel\n");
    for (int i = 0; i < n; i++)
        for (int j = 0; j < r[i].n_zones; j++) {
            const tippe_sweep_zone *z = &r[i].zones[j];
            fprintf(rf.f, "%d,\"%s\",\"%s\",%s,%s,%.10g,%.10g,%.10g,%.10g,%s\n", i + 1,
                    tippe_design_name(d[i]), tippe_design_path(d[i]), tippe_group_name(z->group),
                    tippe_group_family(z->group), z->z2_from_mm, z->z2_to_mm,
                    z->z2_to_mm - z->z2_from_mm, tippe_sweep_zone_robust_mm(&r[i], &b[i], j),
                    z->within_travel ? "yes" : "no");
        }
    return tippe_report_commit(&rf, err);
}

static cJSON *to_json(int n, tippe_design **d, tippe_sweep_result *r,
                      tippe_sweep_bands_result *b, const compare_args *a)
{
    cJSON *o = cJSON_CreateObject();
    cJSON *arr = o ? cJSON_AddArrayToObject(o, "designs") : NULL;
    for (int i = 0; arr && i < n; i++) {
        cJSON *s = tippe_sweep_json(&r[i], d[i]);
        if (!s || tippe_sweep_json_add_bands(s, d[i], &r[i], &b[i]) ||
            !cJSON_AddItemToArray(arr, s)) {
            cJSON_Delete(s);
            arr = NULL;
            break;
        }
        tippe_cli_json_sets(s, &a->sets[i]);
    }
    if (!arr) {
        cJSON_Delete(o);
        return NULL;
    }
    return o;
}

/* --set [N:]FIELD=VALUE: to design N (1-based) only, or to every design. */
static int add_sets(compare_args *a)
{
    for (int k = 0; k < a->all_sets.n; k++) {
        const char *item = a->all_sets.item[k], *colon = strchr(item, ':'),
                   *eq = strchr(item, '=');
        long which = 0;
        char num[16];
        if (colon && (!eq || colon < eq) && colon - item < (long)sizeof num) {
            snprintf(num, sizeof num, "%.*s", (int)(colon - item), item);
            if (!tippe_cli_parse_long(num, 1, a->n, &which))
                return tippe_cli_usage_error(VERB, "--set '%s': %s is not a design's number "
                                                   "(1 .. %d, in the order given)",
                                             item, num, a->n);
            item = colon + 1;
        }
        for (int i = 0; i < a->n; i++)
            if ((which == 0 || which == i + 1) && tippe_cli_sets_add(&a->sets[i], NULL, item))
                return tippe_cli_usage_error(VERB, "too many --set options");
    }
    return 0;
}

static int compare_parse(compare_args *a, int argc, char **argv)
{
    tippe_cli_opt opts[] = {
        {.name = "json", .kind = TIPPE_CLI_FLAG, .value = &a->json,
         .help = "print {\"designs\": [...]} with one sweep object per design (as tippe\n"
                 "sweep --json, with its \"set\" changes) instead of the table"},
        {.name = "csv", .kind = TIPPE_CLI_STRING, .value = &a->csv, .arg = "FILE",
         .help = "one row per zone of each design: group, from, to, width, robust width"},
        {.name = "plot", .kind = TIPPE_CLI_STRING, .value = &a->plot, .arg = "FILE",
         .help = "the designs' zone bars side by side (.png, .svg or .pdf)"},
        {.name = "wide", .kind = TIPPE_CLI_FLAG, .value = &a->wide,
         .help = "the designs side by side in columns (44 characters each)"},
        {.name = "set", .kind = TIPPE_CLI_SET, .value = &a->all_sets, .arg = "[N:]FIELD=VALUE",
         .help = "change a field of every design, or with N: of the N-th design only\n"
                 "(e.g. --set 2:radius_mm=30); repeatable"},
        {NULL},
    };
    tippe_cli_spec spec = {
        .verb = VERB,
        .synopsis = "A.json B.json ... [--json] [--csv FILE] [--plot FILE] [--wide]\n"
                    "                     [--set [N:]FIELD=VALUE ...]",
        .about = "The zones of several designs (each swept over its stated travel): group,\n"
                 "from .. to, width and robust width in mm (the width less the tolerance\n"
                 "bands at both ends, as tippe sweep reports them), then whether each is\n"
                 "\"3-in-1\" and its narrowest zone (0 unless 3-in-1), as found and robust.",
        .after = "Exit status: 0 ok, 2 bad usage or design, 1 computation failed.",
        .opts = opts,
        .min_args = 1,
        .max_args = MAX_DESIGNS,
        .args_name = "design file",
    };
    int rc = tippe_cli_parse(&spec, argc, argv, a->paths, &a->n);
    if (rc)
        return rc;
    if ((rc = add_sets(a)) != 0)
        return rc;
    if ((a->csv && tippe_cli_check_output(VERB, "--csv", a->csv, 0)) ||
        (a->plot && tippe_cli_check_output(VERB, "--plot", a->plot, 1)))
        return 2;
    return 0;
}

/* The files asked for (one set: all or none) and the report. */
static int compare_report(const compare_args *a, tippe_design **d, tippe_sweep_result *r,
                          tippe_sweep_bands_result *b)
{
    tippe_error err = {0};
    int rc = 0;
    if (a->csv)
        rc = write_csv(a->csv, a->n, d, r, b, &err);
    if (!rc && a->plot) {
        const char *labels[MAX_DESIGNS];
        char text[MAX_DESIGNS][300], sets[200];
        for (int i = 0; i < a->n; i++) {
            /* the file's name, short and exact; the design names are in the table */
            snprintf(text[i], sizeof text[i], "[%d] %.40s%s%.60s", i + 1,
                     tippe_path_base(tippe_design_path(d[i])), a->sets[i].n ? ", " : "",
                     tippe_cli_sets_text(&a->sets[i], sets, sizeof sets));
            labels[i] = text[i];
        }
        rc = tippe_sweep_plot_compare(a->plot, r, labels, a->n, "tippe compare", &err);
    }
    if (rc)
        return tippe_cli_fail(VERB, &err, rc);
    if (a->json)
        return tippe_cli_print_json(VERB, to_json(a->n, d, r, b, a));
    if (a->wide)
        print_wide(a->n, d, r, b);
    else
        print_stacked(a->n, d, r, b, a);
    return 0;
}

int tippe_cli_compare(int argc, char **argv)
{
    static compare_args a; /* 16 x 64 --set items: too big for the stack */
    memset(&a, 0, sizeof a);
    int rc = compare_parse(&a, argc, argv);
    if (rc)
        return rc == TIPPE_CLI_HELP ? 0 : rc;
    tippe_design *d[MAX_DESIGNS] = {0};
    tippe_sweep_result r[MAX_DESIGNS];
    tippe_sweep_bands_result b[MAX_DESIGNS];
    memset(r, 0, sizeof r);
    memset(b, 0, sizeof b);
    tippe_error err = {0};
    int loaded = 0;
    for (int i = 0; i < a.n && rc == TIPPE_OK; i++, loaded++) {
        rc = tippe_design_load(a.paths[i], a.sets[i].item, a.sets[i].n, &d[i], &err);
        if (rc == TIPPE_OK)
            tippe_cli_design_warnings(VERB, d[i]);
        if (rc == TIPPE_OK)
            rc = tippe_sweep_design(d[i], 0.0, 0.0, NULL, &r[i], &err);
        if (rc == TIPPE_OK)
            rc = tippe_sweep_bands(d[i], &r[i], &b[i], &err);
    }
    rc = rc ? tippe_cli_fail(VERB, &err, rc) : compare_report(&a, d, r, b);
    for (int i = 0; i < loaded; i++) {
        tippe_sweep_bands_free(&b[i]);
        tippe_sweep_result_free(&r[i]);
        tippe_design_free(d[i]);
    }
    return rc;
}
