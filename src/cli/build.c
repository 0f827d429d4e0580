/* tippe build: the build sheet (settings a maker measures, BOM) and the files
 * to print, in one directory. */
#include "cli.h"

#include "tippe/build.h"
#include "tippe/design.h"
#include "tippe/export.h"
#include "tippe/base.h"

#include <cjson/cJSON.h>

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static const char *const VERB = "build";

typedef struct {
    const char *dir, *path, *catalogue, *hole;
    int json, no_export;
    tippe_build_options o;
    tippe_export_request q;
    tippe_cli_sets sets;
} build_args;

static int build_parse(build_args *a, int argc, char **argv)
{
    tippe_cli_opt opts[] = {
        {.name = "output", .short_name = 'o', .kind = TIPPE_CLI_STRING, .value = &a->dir,
         .arg = "DIR", .required = 1,
         .help = "output directory (created if missing; its parent must exist)"},
        {.name = "catalogue", .kind = TIPPE_CLI_STRING, .value = &a->catalogue, .arg = "FILE",
         .def = "catalogue.json beside the design, if there is one",
         .help = "hardware catalogue the weight is looked up in (designs/catalogue.json)"},
        {.name = "clearance-mm", .kind = TIPPE_CLI_DOUBLE, .value = &a->o.clearance_mm,
         .arg = "MM", .unit = "mm", .min = 0, .max = 2, .def = "0.2",
         .help = "radial clearance of holes that take hardware (as tippe export)"},
        {.name = "hole", .kind = TIPPE_CLI_STRING, .value = &a->hole, .arg = "FIT",
         .def = "the hole's \"fit\" in the design, else tap",
         .help = "the screw's hole, overriding the design's fit: tap (printed at the\n"
                 "thread's tap drill, d - P, and tapped), insert (at a heat-set insert's\n"
                 "pilot hole, M3 .. M6) or slide (the design's hole plus the clearance)"},
        {.name = "no-export", .kind = TIPPE_CLI_FLAG, .value = &a->no_export,
         .help = "write the sheet only, not the files to print"},
        {.name = "json", .kind = TIPPE_CLI_FLAG, .value = &a->json,
         .help = "print the sheet as one JSON object"},
        {.name = "set", .kind = TIPPE_CLI_SET, .value = &a->sets, .arg = "FIELD=VALUE",
         .help = "change a field of the design before it is checked (repeatable)"},
        {NULL},
    };
    tippe_cli_spec spec = {
        .verb = VERB,
        .synopsis = "DESIGN.json -o DIR [--catalogue FILE] [--clearance-mm MM] [--hole FIT]\n"
                    "       [--no-export] [--json] [--set FIELD=VALUE]",
        .about = "What a maker follows, from the design's numbers: for each behaviour (stays\n"
                 "up, flips, hangs) the robust range of Z2 (the widest zone within the travel\n"
                 "where the model applies, less its tolerance bands) as the depth of the\n"
                 "weight's end below the rim of its hole (or the end of its rod) and the turns\n"
                 "of its thread, the spin it needs (Theorem 5.1) and the verdict of one\n"
                 "central hand launch there (tippe check's); the bill of materials with the\n"
                 "catalogue screw and tap drills; and the files tippe export writes.",
        .after = "Writes into DIR (STEM: the design file's name without .json) the sheet as\n"
                 "STEM-build.json, STEM-build.md and one A3 page STEM-sheet.pdf, .svg, .png;\n"
                 "a depth gauge STEM-gauge-stays-up.stl, -flips.stl, -hangs.stl per setting\n"
                 "deeper than 1 mm; and, unless --no-export, tippe export's files (STL, 3MF,\n"
                 "OpenSCAD, section drawing; split into halves when the printed body closes\n"
                 "around its hardware). Exit status: 0 ok, 2 bad usage or design, 1 a\n"
                 "computation or a file failed. See docs/build.md.",
        .opts = opts,
        .min_args = 1,
        .max_args = 1,
        .args_name = "design file",
    };
    int n = 0;
    int rc = tippe_cli_parse(&spec, argc, argv, &a->path, &n);
    if (rc)
        return rc;
    if (!a->hole)
        a->o.hole_fit = TIPPE_BUILD_HOLE_DESIGN;
    else if (!strcmp(a->hole, "tap"))
        a->o.hole_fit = TIPPE_BUILD_HOLE_TAP;
    else if (!strcmp(a->hole, "insert"))
        a->o.hole_fit = TIPPE_BUILD_HOLE_INSERT;
    else if (!strcmp(a->hole, "slide"))
        a->o.hole_fit = TIPPE_BUILD_HOLE_SLIDE;
    else
        return tippe_cli_usage_error(VERB, "--hole %s: not a fit (tap, insert or slide)",
                                     a->hole);
    return 0;
}

/* The default catalogue: catalogue.json beside the design, if it exists. */
static const char *default_catalogue(const char *design, char *buf, size_t size)
{
    const char *slash = strrchr(design, '/');
    if (slash)
        snprintf(buf, size, "%.*scatalogue.json", (int)(slash - design + 1), design);
    else
        snprintf(buf, size, "catalogue.json");
    return access(buf, R_OK) == 0 ? buf : NULL;
}

/* The sheet's files: JSON, Markdown, the page as PDF, SVG and PNG, then the
 * depth gauges of the three settings (those that apply are written). */
enum { N_SHEET = 5, N_OUT = 8 };
static const char *const sheet_tails[N_OUT] = {
    "-build.json", "-build.md", "-sheet.pdf", "-sheet.svg", "-sheet.png",
    "-gauge-stays-up.stl", "-gauge-flips.stl", "-gauge-hangs.stl"};

static void sheet_paths(const tippe_design *d, const char *dir, char (*out)[4096])
{
    char stem[1024];
    tippe_build_stem(tippe_design_path(d), stem, sizeof stem);
    const char *sep = dir[0] && dir[strlen(dir) - 1] != '/' ? "/" : "";
    for (int k = 0; k < N_OUT; k++)
        snprintf(out[k], 4096, "%s%s%s%s", dir, sep, stem, sheet_tails[k]);
}

static int write_sheet(const tippe_design *d, const tippe_build_sheet *s,
                       char (*paths)[4096], tippe_error *err)
{
    const char *json = paths[0], *md = paths[1];
    tippe_report_file rf;
    cJSON *o = tippe_build_json(s);
    char *text = o ? cJSON_Print(o) : NULL;
    cJSON_Delete(o);
    if (!text)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    int rc = tippe_report_open(&rf, json, "the build sheet (JSON)", err);
    if (!rc) {
        fputs(text, rf.f);
        fputc('\n', rf.f);
        rc = tippe_report_commit(&rf, err);
    }
    free(text);
    if (!rc && !(rc = tippe_report_open(&rf, md, "the build sheet (Markdown)", err))) {
        tippe_build_markdown(rf.f, s);
        rc = tippe_report_commit(&rf, err);
    }
    for (int k = 2; !rc && k < N_SHEET; k++)
        rc = tippe_export_sheet_write(d, s, paths[k], err);
    double pin;
    for (int f = 0; !rc && f < 3; f++)
        if (tippe_build_gauge_applies(s, f, &pin))
            rc = tippe_export_gauge_write(s, f, paths[N_SHEET + f], err);
    return rc;
}

static int run_checked(build_args *a, const tippe_design *d, char (*sheet)[4096]);

static int run(build_args *a, const tippe_design *d)
{
    tippe_error err = {0};
    char sheet[N_OUT][4096], cat[4096];
    if (!a->catalogue)
        a->catalogue = default_catalogue(a->path, cat, sizeof cat);
    a->o.catalogue = a->catalogue;
    a->o.sets = a->sets.item;
    a->o.n_sets = a->sets.n;
    sheet_paths(d, a->dir, sheet);
    /* the catalogue is input: a bad one is refused before any work or output */
    tippe_build_catalogue *catalogue = NULL;
    if (a->catalogue && tippe_build_catalogue_load(a->catalogue, &catalogue, &err))
        return err.code == TIPPE_EINPUT ? tippe_cli_usage_error(VERB, "%s", err.msg)
                                        : tippe_cli_fail(VERB, &err, err.code);
    a->o.catalogue_read = catalogue;
    int rc = run_checked(a, d, sheet);
    tippe_build_catalogue_free(catalogue);
    return rc;
}

/* run, once the inputs are read */
static int run_checked(build_args *a, const tippe_design *d, char (*sheet)[4096])
{
    tippe_error err = {0};
    char fit_note[64];
    /* every output checked before any work */
    int rc = tippe_cli_make_output_dir(VERB, "-o", a->dir);
    for (int k = 0; !rc && k < N_OUT; k++)
        rc = tippe_cli_check_output(VERB, "-o", sheet[k], 0);
    char(*paths)[4096] = NULL;
    if (!rc && !a->no_export) {
        a->q.profile.clearance_mm = a->o.clearance_mm;
        a->q.dir = a->dir;
        a->q.formats = TIPPE_EXPORT_ALL;
        /* a body that closes around its hardware is printed in halves */
        a->q.profile.split = tippe_build_needs_split(d, a->o.clearance_mm);
        a->q.profile.joint = a->q.profile.split; /* and joined on a ring */
        a->q.profile.sockets = a->q.profile.split; /* a rod spanning it held at the poles */
        double t0, t1;
        tippe_design_travel_mm(d, &t0, &t1);
        a->q.z2_mm = 0.5 * (t0 + t1);
        int np = tippe_export_plan(d, &a->q, &paths, &err);
        if (np < 0)
            rc = tippe_cli_fail(VERB, &err, err.code ? err.code : TIPPE_EINPUT);
        for (int k = 0; !rc && k < np; k++) {
            /* a printed body named like a sheet file ("gauge-flips") would
             * overwrite it: both are -o, which tippe_cli_check_output does not
             * compare with each other */
            for (int j = 0; !rc && j < N_OUT; j++)
                if (!strcmp(paths[k], sheet[j]))
                    rc = tippe_cli_usage_error(VERB, "-o %s: tippe export's file %s is also "
                                               "the sheet's (a printed body named like a sheet "
                                               "file); rename the part", a->dir, paths[k]);
            if (!rc)
                rc = tippe_cli_check_output(VERB, "-o", paths[k], 0);
        }
    }
    if (rc) {
        free(paths);
        return rc;
    }
    tippe_build_sheet *s = malloc(sizeof *s);
    if (!s) {
        free(paths);
        return fprintf(stderr, "tippe %s: out of memory\n", VERB), 1;
    }
    rc = tippe_build_compute(d, &a->o, s, &err);
    if (!rc) {
        /* the drawing shows the weight where the flip is set, else at the first
         * setting there is */
        for (int f = 2; f >= 0; f--)
            if (s->set[f].reachable)
                a->q.z2_mm = s->set[f].set_z2_mm;
        if (s->set[1].reachable)
            a->q.z2_mm = s->set[1].set_z2_mm;
        rc = write_sheet(d, s, sheet, &err);
        if (s->hole_tapped || s->hole_insert) {
            a->q.profile.fit_part = s->hole_part;
            a->q.profile.fit_diameter_mm = s->hole_diameter_mm;
            snprintf(fit_note, sizeof fit_note, "%s", s->fit_note);
            a->q.fit_note = fit_note;
        }
    }
    tippe_export_result r = {0};
    if (!rc && !a->no_export)
        rc = tippe_export_run(d, &a->q, &r, &err);
    if (rc) {
        tippe_export_result_free(&r);
        free(s);
        free(paths);
        return tippe_cli_fail(VERB, &err, rc);
    }
    if (a->json) {
        cJSON *o = tippe_build_json(s);
        cJSON *files = o ? cJSON_AddArrayToObject(o, "files") : NULL;
        if (files) {
            double pin;
            for (int k = 0; k < N_OUT; k++)
                if (k < N_SHEET || tippe_build_gauge_applies(s, k - N_SHEET, &pin))
                    cJSON_AddItemToArray(files, cJSON_CreateString(sheet[k]));
            for (int k = 0; k < r.n_files; k++)
                cJSON_AddItemToArray(files, cJSON_CreateString(r.file[k]));
        }
        rc = tippe_cli_print_json(VERB, o);
    } else {
        tippe_build_markdown(stdout, s);
        printf("\n");
        double pin;
        for (int k = 0; k < N_OUT; k++)
            if (k < N_SHEET || tippe_build_gauge_applies(s, k - N_SHEET, &pin))
                printf("wrote      %s\n", sheet[k]);
        for (int k = 0; k < r.n_files; k++)
            printf("wrote      %s\n", r.file[k]);
    }
    tippe_export_result_free(&r);
    free(s);
    free(paths);
    return rc;
}

int tippe_cli_build(int argc, char **argv)
{
    build_args a = {.q = {.profile = tippe_profile_defaults()}};
    tippe_build_options_default(&a.o);
    int rc = build_parse(&a, argc, argv);
    if (rc)
        return rc == TIPPE_CLI_HELP ? 0 : rc;
    tippe_error err = {0};
    tippe_design *d = NULL;
    if ((rc = tippe_design_load(a.path, a.sets.item, a.sets.n, &d, &err)))
        return tippe_cli_fail(VERB, &err, rc);
    tippe_cli_design_warnings(VERB, d);
    rc = run(&a, d);
    tippe_design_free(d);
    return rc;
}
