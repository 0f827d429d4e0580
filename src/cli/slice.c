/* tippe slice: the slicer in the loop (tippe_export_slice does the work: the
 * design's 3MF, PrusaSlicer headless with a profile, the shipped
 * designs/slicer/prusa-pla-0.4mm.ini unless --profile, the G-code read back as
 * the printed part). Prints the zone table of the sliced part beside the print
 * model's and ends with the build sheet's verdict for both (docs/printing.md). */
#include "cli.h"

#include "tippe/base.h"
#include "tippe/build.h"
#include "tippe/design.h"
#include "tippe/export.h"
#include "tippe/profile.h"
#include "tippe/sweep.h"

#include <cjson/cJSON.h>
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const char *const VERB = "slice";

typedef struct {
    const char *path, *dir, *profile, *slicer;
    double clearance_mm;
    int json;
    tippe_cli_sets sets;
} slice_args;

static int slice_parse(slice_args *a, int argc, char **argv)
{
    tippe_cli_opt opts[] = {
        {.name = "output", .short_name = 'o', .kind = TIPPE_CLI_STRING, .value = &a->dir,
         .arg = "DIR", .required = 1,
         .help = "output directory: the 3MF, the G-code and the slicer's log\n"
                 "(created if missing; its parent must exist)"},
        {.name = "profile", .kind = TIPPE_CLI_STRING, .value = &a->profile, .arg = "FILE.ini",
         .def = "the shipped designs/slicer/prusa-pla-0.4mm.ini",
         .help = "a PrusaSlicer config (File > Export > Export Config); the 3MF's\n"
                 "per-object settings win over it: layers, perimeters, infill, pattern,\n"
                 "supports and the settings the print model assumes (docs/printing.md,\n"
                 "\"Under other profiles\"); the first layer's height and width are its own"},
        {.name = "slicer", .kind = TIPPE_CLI_STRING, .value = &a->slicer, .arg = "PROGRAM",
         .def = "prusa-slicer", .help = "the slicer's command line (PrusaSlicer 2.5 or later)"},
        {.name = "clearance-mm", .kind = TIPPE_CLI_DOUBLE, .value = &a->clearance_mm,
         .arg = "MM", .unit = "mm", .min = 0, .max = 2, .def = "0",
         .help = "radial clearance of holes that take hardware in the sliced part: 0 slices\n"
                 "the mass model's part, so that the two zone tables compare like with like;\n"
                 "the screw's hole is printed at its tap drill (or insert's pilot hole) as\n"
                 "tippe build prints it, whatever this says, and the print model's table is\n"
                 "of that part too (docs/printing.md, \"The part as made\")"},
        {.name = "json", .kind = TIPPE_CLI_FLAG, .value = &a->json,
         .help = "print both sweeps and the bodies as one JSON object"},
        {.name = "set", .kind = TIPPE_CLI_SET, .value = &a->sets, .arg = "FIELD=VALUE",
         .help = "change a field of the design before it is checked (repeatable)"},
        {NULL},
    };
    tippe_cli_spec spec = {
        .verb = VERB,
        .synopsis = "DESIGN.json -o DIR [--profile FILE.ini] [--slicer PROGRAM]\n"
                    "       [--clearance-mm MM] [--json] [--set FIELD=VALUE ...]",
        .about = "Slices the design's printed body with PrusaSlicer and reads the G-code back:\n"
                 "the body's mass, centre of mass, A and C summed from its extrusion moves,\n"
                 "and the zone table of the top with that body beside the print model's.",
        .after = "Needs PrusaSlicer's command line: apt-get install prusa-slicer (Debian 12:\n"
                 "2.5.0; about 5 s of CPU per body). One printed body per design (the G-code\n"
                 "must hold one object). The G-code is DIR/STEM.gcode; give it to any verb as\n"
                 "the part's \"print\": {\"gcode\": \"FILE\"} (docs/printing.md). Exit status: 0\n"
                 "ok, 2 bad usage or design, or no slicer, 1 the slicer or a file failed.",
        .opts = opts,
        .min_args = 1,
        .max_args = 1,
        .args_name = "design file",
    };
    int n_args = 0;
    int rc = tippe_cli_parse(&spec, argc, argv, &a->path, &n_args);
    if (rc)
        return rc;
    if (!strcmp(a->dir, "-"))
        return tippe_cli_usage_error(VERB, "-o -: slice writes several files into a directory, "
                                           "not to standard output; give a directory");
    return 0;
}

/* Where a program is on PATH (or itself if it has a slash); 0 if nowhere. */
static int find_program(const char *name, char *out, size_t cap)
{
    if (strchr(name, '/')) {
        snprintf(out, cap, "%s", name);
        return access(out, X_OK) == 0;
    }
    const char *path = getenv("PATH");
    for (const char *p = path ? path : "/usr/bin:/bin"; *p;) {
        const char *colon = strchr(p, ':');
        size_t len = colon ? (size_t)(colon - p) : strlen(p);
        snprintf(out, cap, "%.*s/%s", (int)len, p, name);
        if (len && access(out, X_OK) == 0)
            return 1;
        p += len + (colon != NULL);
    }
    return 0;
}

static void print_side_by_side(const tippe_export_slice_result *r, const tippe_design *model)
{
    tippe_design_print_info pi;
    tippe_design_part_print(r->sliced, r->part, &pi);
    printf("body     G-code %.3f g, body A/C %.4f (%s); print model %.3f g (%+.1f %%), body A/C "
           "%.4f (%+.4f)\n",
           pi.printed_mass_kg * 1e3, pi.body_A_over_C,
           pi.generator[0] ? pi.generator : "slicer not named", pi.model_mass_kg * 1e3,
           100 * (pi.model_mass_kg / pi.printed_mass_kg - 1), pi.model_body_A_over_C,
           pi.model_body_A_over_C - pi.body_A_over_C);
    if (pi.gcode_note[0])
        printf("         the G-code: %s\n", pi.gcode_note);
    if (pi.gcode_support_mass_kg > 0)
        printf("         supports, removed: %.3f g (not part of the body)\n",
               pi.gcode_support_mass_kg * 1e3);
    printf("\n== the part as sliced (its G-code)\n");
    tippe_sweep_print_table(stdout, &r->sliced_sweep, r->sliced);
    printf("\n== the part as the print model has it\n");
    tippe_sweep_print_table(stdout, &r->model_sweep, model);
}

static const char *const BEHAVIOUR[3] = {"stays up", "flips", "hangs"};

/* One verdict line: the sheet's words and each behaviour's robust width. */
static void print_verdict(const char *lead, const char *who, const tippe_build_sheet *s)
{
    printf("%s%-7s %s (robust:", lead, who, tippe_build_verdict(s));
    for (int f = 0; f < 3; f++) {
        if (s->set[f].reachable)
            printf(" %s %.3f mm%s", BEHAVIOUR[f], s->set[f].robust_width_mm, f < 2 ? "," : "");
        else
            printf(" %s none%s", BEHAVIOUR[f], f < 2 ? "," : "");
    }
    printf(")\n");
}

static cJSON *verdict_json(const tippe_build_sheet *s)
{
    cJSON *v = cJSON_CreateObject();
    cJSON_AddStringToObject(v, "verdict", tippe_build_verdict(s));
    cJSON_AddBoolToObject(v, "three_in_one", s->three_in_one);
    cJSON_AddBoolToObject(v, "settable", s->settable);
    cJSON_AddNumberToObject(v, "min_setting_mm", s->min_setting_mm);
    cJSON *w = cJSON_AddObjectToObject(v, "robust_width_mm");
    for (int f = 0; w && f < 3; f++) {
        if (s->set[f].reachable)
            cJSON_AddNumberToObject(w, BEHAVIOUR[f], s->set[f].robust_width_mm);
        else
            cJSON_AddNullToObject(w, BEHAVIOUR[f]);
    }
    return v;
}

int tippe_cli_slice(int argc, char **argv)
{
    slice_args a = {.profile = NULL, .slicer = "prusa-slicer", .clearance_mm = 0};
    int rc = slice_parse(&a, argc, argv);
    if (rc)
        return rc == TIPPE_CLI_HELP ? 0 : rc;
    char slicer[PATH_MAX];
    if (!find_program(a.slicer, slicer, sizeof slicer)) {
        fprintf(stderr,
                "tippe slice: %s not found: install PrusaSlicer's command line, the Debian "
                "package prusa-slicer (apt-get install --no-install-recommends prusa-slicer), "
                "or name it with --slicer\n",
                a.slicer);
        return 2;
    }
    /* the shipped profile: the checkout's, or the installed one */
    char shipped[4096 + 64];
    if (!a.profile && tippe_file_shipped_dir(shipped, sizeof shipped - 64))
        strcat(shipped, "/slicer/prusa-pla-0.4mm.ini");
    const char *profile = a.profile ? a.profile : shipped;
    if (access(profile, R_OK) != 0) {
        fprintf(stderr, "tippe slice: --profile %s: %s\n", profile, strerror(errno));
        return 2;
    }
    tippe_error err = {0};
    tippe_design *d = NULL;
    if ((rc = tippe_design_load(a.path, a.sets.item, a.sets.n, &d, &err)))
        return tippe_cli_fail(VERB, &err, rc);
    char part_name[128];
    if (tippe_export_slice_part(d, part_name, sizeof part_name, &err) < 0 ||
        (rc = tippe_cli_make_output_dir(VERB, "-o", a.dir))) {
        if (!rc)
            rc = tippe_cli_fail(VERB, &err, TIPPE_EINPUT);
        tippe_design_free(d);
        return rc;
    }
    tippe_export_slice_request q = {.dir = a.dir, .slicer = slicer, .profile = profile,
                                    .clearance_mm = a.clearance_mm};
    tippe_build_options_default(&q.verdict);
    if (!a.json)
        fprintf(stderr, "tippe slice: slicing %s with %s (%s)...\n", a.path, slicer, profile);
    tippe_export_slice_result r;
    if ((rc = tippe_export_slice(d, &q, &r, &err))) {
        tippe_design_free(d);
        return tippe_cli_fail(VERB, &err, rc);
    }
    if (a.json) {
        cJSON *o = cJSON_CreateObject();
        cJSON_AddStringToObject(o, "design", a.path);
        cJSON_AddStringToObject(o, "gcode", r.gcode);
        cJSON_AddStringToObject(o, "profile", profile);
        cJSON_AddItemToObject(o, "sliced", tippe_sweep_json(&r.sliced_sweep, r.sliced));
        cJSON_AddItemToObject(o, "model", tippe_sweep_json(&r.model_sweep, d));
        cJSON *sp = cJSON_AddObjectToObject(o, "sliced_parts");
        if (sp)
            tippe_profile_printed_parts_json(sp, r.sliced);
        cJSON *v = cJSON_AddObjectToObject(o, "verdict");
        if (v) {
            cJSON_AddItemToObject(v, "sliced", verdict_json(r.sliced_sheet));
            cJSON_AddItemToObject(v, "model", verdict_json(r.model_sheet));
        }
        rc = tippe_cli_print_json(VERB, o);
    } else {
        printf("design   %s\nG-code   %s (profile %s)\n", a.path, r.gcode, profile);
        print_side_by_side(&r, d);
        printf("\n");
        print_verdict("verdict  ", "G-code:", r.sliced_sheet);
        print_verdict("         ", "model:", r.model_sheet);
        printf("         (the build sheet's: settable when every behaviour's robust range is at "
               "least %.2f mm, %s)\n",
               r.model_sheet->min_setting_mm, r.model_sheet->min_setting_rule);
    }
    tippe_export_slice_result_free(&r);
    tippe_design_free(d);
    return rc;
}
