/* tippe build: the build sheet (settings a maker measures, BOM) and the files
 * to print, in one directory. */
#include "cli.h"
#include "hands.h"

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
    hands_friction fr; /* the launch check's friction (as tippe check's) */
} build_args;

static int build_parse(build_args *a, int argc, char **argv)
{
    tippe_cli_opt own[] = {
        {.name = "output", .short_name = 'o', .kind = TIPPE_CLI_STRING, .value = &a->dir,
         .arg = "DIR", .required = 1,
         .help = "output directory (created if missing; its parent must exist)"},
        {.name = "catalogue", .kind = TIPPE_CLI_STRING, .value = &a->catalogue, .arg = "FILE",
         .def = "the design's \"catalogue\", else catalogue.json beside the design, if there is one",
         .help = "hardware catalogue the weight is looked up in (designs/catalogue.json)"},
        {.name = "clearance-mm", .kind = TIPPE_CLI_DOUBLE, .value = &a->o.clearance_mm,
         .arg = "MM", .unit = "mm", .min = 0, .max = 2, .def = "0.2",
         .help = "radial clearance of holes that take hardware (as tippe export)"},
        {.name = "hole", .kind = TIPPE_CLI_STRING, .value = &a->hole, .arg = "FIT",
         .def = "the hole's \"fit\" in the design, else tap",
         .help = "the screw's hole, overriding the design's fit: tap (printed at the\n"
                 "thread's tap drill, d - P, and tapped), insert (at a heat-set insert's\n"
                 "pilot hole, M3 .. M6) or slide (the design's hole plus the clearance)"},
        {.name = "min-setting-mm", .kind = TIPPE_CLI_DOUBLE, .value = &a->o.min_setting_mm,
         .arg = "MM", .unit = "mm", .min = 0.001, .max = 100,
         .def = "a quarter turn of the weight's thread, or 0.5 without one",
         .help = "the narrowest robust range a maker can set: a behaviour whose robust\n"
                 "range is narrower is warned about, and a 3-in-1 top with one is\n"
                 "\"3-in-1 on paper only\" rather than \"3-in-1 and settable\""},
        {.name = "no-export", .kind = TIPPE_CLI_FLAG, .value = &a->no_export,
         .help = "write the sheet only, not the files to print"},
        {.name = "one-to-one", .kind = TIPPE_CLI_FLAG, .value = &a->q.section_one_to_one,
         .help = "write the section's PDF (STEM-section.pdf) at 1:1 on an A4 landscape\n"
                 "page, with a 50 mm bar to check the print's scale: print it at 100 %\n"
                 "and hold the part or a caliper against it (the SVG and PNG stay fitted)"},
        {.name = "json", .kind = TIPPE_CLI_FLAG, .value = &a->json,
         .help = "print the sheet as one JSON object"},
        {.name = "set", .kind = TIPPE_CLI_SET, .value = &a->sets, .arg = "FIELD=VALUE",
         .help = "change a field of the design before it is checked (repeatable)"},
    };
    /* the launch check's friction options, as tippe check reads them */
    tippe_cli_opt opts[sizeof own / sizeof own[0] + 8];
    int n_opts = (int)(sizeof own / sizeof own[0]);
    memcpy(opts, own, sizeof own);
    n_opts += hands_friction_options(&a->fr, &a->o.launch, opts + n_opts);
    opts[n_opts] = (tippe_cli_opt){NULL};
    tippe_cli_spec spec = {
        .verb = VERB,
        .synopsis = "DESIGN.json -o DIR [--catalogue FILE] [--clearance-mm MM] [--hole FIT]\n"
                    "       [--min-setting-mm MM] [--no-export] [--one-to-one] [--json]\n"
                    "       [--set FIELD=VALUE] [--friction LAW] [--mu S_PER_M | --mu-c X]\n"
                    "       [--patch-mm A | --table SURFACE]",
        .about = "What a maker follows, from the design's numbers: for each behaviour (stays\n"
                 "up, flips, hangs) the robust range of Z2 (the widest zone within the travel\n"
                 "where the model applies, less its tolerance bands) as the depth of the\n"
                 "weight's end below the rim of its hole (or the end of its rod) and the turns\n"
                 "of its thread, the spin it needs (Theorem 5.1) and the verdict of one\n"
                 "central hand launch there (tippe check's, under the friction options below:\n"
                 "viscous, 2.3 s/m, unless told); the bill of materials with the\n"
                 "catalogue screw and tap drills; and the files tippe export writes.",
        .after = "Writes into DIR (STEM: the design file's name without .json) the sheet as\n"
                 "STEM-build.json, STEM-build.md and one A3-wide page STEM-sheet.pdf, .svg, .png;\n"
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
    if (!rc)
        rc = hands_friction_apply(VERB, &a->fr, &a->o.launch, &spec, 0);
    tippe_error e;
    tippe_launch_options chk = a->o.launch; /* a patch's Hertz modulus comes with the design */
    if (tippe_friction_law_type_of(chk.law)->patch && !(chk.patch_radius_m > 0))
        chk.patch_E_star_pa = 1.0;
    if (!rc && tippe_launch_options_check(&chk, &e))
        rc = tippe_cli_usage_error(VERB, "%s", e.msg);
    if (rc)
        return rc;
    if (a->q.section_one_to_one && a->no_export)
        return tippe_cli_usage_error(VERB, "--one-to-one draws the exported section at 1:1: "
                                           "not with --no-export");
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

static int run_checked(build_args *a, const tippe_design *d, char (*sheet)[4096]);

static int run(build_args *a, const tippe_design *d)
{
    tippe_error err = {0};
    char sheet[TIPPE_EXPORT_BUILD_FILES][4096], cat[4096];
    if (!a->catalogue)
        a->catalogue = tippe_build_catalogue_file(d, cat, sizeof cat);
    a->o.catalogue = a->catalogue;
    tippe_export_build_paths(d, a->dir, sheet);
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
    for (int k = 0; !rc && k < TIPPE_EXPORT_BUILD_FILES; k++)
        rc = tippe_cli_check_output(VERB, "-o", sheet[k], 0);
    char(*paths)[4096] = NULL;
    if (!rc && !a->no_export) {
        tippe_export_build_request(d, a->o.clearance_mm, a->dir, &a->q);
        int np = tippe_export_plan(d, &a->q, &paths, &err);
        if (np < 0)
            rc = tippe_cli_fail(VERB, &err, err.code ? err.code : TIPPE_EINPUT);
        for (int k = 0; !rc && k < np; k++) {
            /* a printed body named like a sheet file ("gauge-flips") would
             * overwrite it: both are -o, which tippe_cli_check_output does not
             * compare with each other */
            for (int j = 0; !rc && j < TIPPE_EXPORT_BUILD_FILES; j++)
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
    tippe_export_result r = {0};
    if (!rc)
        rc = tippe_export_build_write(d, s, sheet, a->no_export ? NULL : &a->q, fit_note,
                                      sizeof fit_note, &r, &err);
    if (rc) {
        tippe_export_result_free(&r);
        free(s);
        free(paths);
        return tippe_cli_fail(VERB, &err, rc);
    }
    for (int k = 0; k < s->n_warnings; k++)
        fprintf(stderr, "tippe %s: warning: %s\n", VERB, s->warning[k]);
    if (a->json) {
        cJSON *o = tippe_build_json(s);
        cJSON *files = o ? cJSON_AddArrayToObject(o, "files") : NULL;
        if (files) {
            double pin;
            for (int k = 0; k < TIPPE_EXPORT_BUILD_FILES; k++)
                if (k < TIPPE_EXPORT_BUILD_SHEET || tippe_build_gauge_applies(s, k - TIPPE_EXPORT_BUILD_SHEET, &pin))
                    cJSON_AddItemToArray(files, cJSON_CreateString(sheet[k]));
            for (int k = 0; k < r.n_files; k++)
                cJSON_AddItemToArray(files, cJSON_CreateString(r.file[k]));
        }
        rc = tippe_cli_print_json(VERB, o);
    } else {
        tippe_build_markdown(stdout, s);
        printf("\n");
        double pin;
        for (int k = 0; k < TIPPE_EXPORT_BUILD_FILES; k++)
            if (k < TIPPE_EXPORT_BUILD_SHEET || tippe_build_gauge_applies(s, k - TIPPE_EXPORT_BUILD_SHEET, &pin))
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
    if ((rc = hands_friction_patch(&a.fr, &a.o.launch, d, &err)) != 0) {
        tippe_design_free(d);
        return tippe_cli_fail(VERB, &err, rc);
    }
    rc = run(&a, d);
    tippe_design_free(d);
    return rc;
}
