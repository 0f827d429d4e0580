/* tippe slice: the slicer in the loop. Writes the design's 3MF (tippe export),
 * slices it headless with PrusaSlicer's command line and a profile (the shipped
 * designs/slicer/prusa-pla-0.4mm.ini unless --profile), reads the G-code back as
 * the printed part (print.gcode) and prints the zone table of the sliced part
 * beside the print model's (docs/printing.md). */
#include "cli.h"

#include "tippe/base.h"
#include "tippe/build.h"
#include "tippe/design.h"
#include "tippe/export.h"
#include "tippe/profile.h"
#include "tippe/sweep.h"

#include <cjson/cJSON.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <math.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

extern char **environ;

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
                 "per-object settings (layers, perimeters, infill, pattern) win over it"},
        {.name = "slicer", .kind = TIPPE_CLI_STRING, .value = &a->slicer, .arg = "PROGRAM",
         .def = "prusa-slicer", .help = "the slicer's command line (PrusaSlicer 2.5 or later)"},
        {.name = "clearance-mm", .kind = TIPPE_CLI_DOUBLE, .value = &a->clearance_mm,
         .arg = "MM", .unit = "mm", .min = 0, .max = 2, .def = "0",
         .help = "radial clearance of holes that take hardware in the sliced part: 0 slices\n"
                 "the mass model's part, so that the two zone tables compare like with like"},
        {.name = "json", .kind = TIPPE_CLI_FLAG, .value = &a->json,
         .help = "print both sweeps and the bodies as one JSON object"},
        {.name = "set", .kind = TIPPE_CLI_SET, .value = &a->sets, .arg = "FIELD=VALUE",
         .help = "change a field of the design before it is checked (repeatable)"},
        {NULL},
    };
    tippe_cli_spec spec = {
        .verb = VERB,
        .synopsis = "DESIGN.json -o DIR [--profile FILE.ini] [--slicer PROGRAM] [--json]",
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

/* Runs the slicer (no shell: argv as given), its output into log. */
static int run_slicer(const char *slicer, const char *profile, const char *gcode,
                      const char *model, const char *log, char *why, size_t cap)
{
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, log, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&fa, STDOUT_FILENO, STDERR_FILENO);
    posix_spawn_file_actions_addopen(&fa, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    char *argv[] = {(char *)slicer, "--export-gcode", "--load", (char *)profile, "-o",
                    (char *)gcode, (char *)model, NULL};
    pid_t pid;
    int rc = posix_spawn(&pid, slicer, &fa, NULL, argv, environ);
    posix_spawn_file_actions_destroy(&fa);
    if (rc) {
        snprintf(why, cap, "could not start %s: %s", slicer, strerror(rc));
        return 1;
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
        ;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        snprintf(why, cap, "%s failed (exit %d; its log: %s)", slicer,
                 WIFEXITED(status) ? WEXITSTATUS(status) : -1, log);
        return 1;
    }
    return 0;
}

/* The one printed part of d (its index), or -1 with why. */
static int printed_part(const tippe_design *d, char *name, size_t cap)
{
    int found = -1, n = 0;
    for (int i = 0; i < tippe_design_n_parts(d); i++) {
        tippe_design_print_info pi;
        tippe_design_part_info p;
        if (!tippe_design_part_print(d, i, &pi) && pi.printed && !tippe_design_part(d, i, &p)) {
            if (!n++)
                snprintf(name, cap, "%s", p.name);
            found = i;
        }
    }
    return n == 1 ? found : -1 - n;
}

static void print_side_by_side(const tippe_design *model, const tippe_design *sliced,
                               const tippe_sweep_result *rm, const tippe_sweep_result *rs,
                               int part)
{
    tippe_design_print_info pi;
    tippe_design_part_print(sliced, part, &pi);
    printf("body     G-code %.3f g, body A/C %.4f (%s); print model %.3f g (%+.1f %%), body A/C "
           "%.4f (%+.4f)\n\n",
           pi.printed_mass_kg * 1e3, pi.body_A_over_C,
           pi.generator[0] ? pi.generator : "slicer not named", pi.model_mass_kg * 1e3,
           100 * (pi.model_mass_kg / pi.printed_mass_kg - 1), pi.model_body_A_over_C,
           pi.model_body_A_over_C - pi.body_A_over_C);
    printf("== the part as sliced (its G-code)\n");
    tippe_sweep_print_table(stdout, rs, sliced);
    printf("\n== the part as the print model has it\n");
    tippe_sweep_print_table(stdout, rm, model);
}

int tippe_cli_slice(int argc, char **argv)
{
    slice_args a = {.profile = NULL, .slicer = "prusa-slicer", .clearance_mm = 0};
    int rc = slice_parse(&a, argc, argv);
    if (rc)
        return rc == TIPPE_CLI_HELP ? 0 : rc;
    char slicer[PATH_MAX], why[PATH_MAX + 5000];
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
    int part = printed_part(d, part_name, sizeof part_name);
    if (part < 0) {
        fprintf(stderr, "tippe slice: %s: %s printed part%s (a part with a \"print\" block); "
                        "slice takes a design with exactly one\n",
                a.path, part == -1 ? "no" : "more than one", part == -1 ? "" : "s");
        tippe_design_free(d);
        return 2;
    }
    tippe_export_request q = {.profile = tippe_profile_defaults(), .formats = TIPPE_EXPORT_3MF,
                              .dir = a.dir};
    q.profile.clearance_mm = a.clearance_mm;
    double t0, t1;
    tippe_design_travel_mm(d, &t0, &t1);
    q.z2_mm = 0.5 * (t0 + t1);
    char(*planned)[4096] = NULL;
    int np = tippe_export_plan(d, &q, &planned, &err);
    char model3mf[4096] = "";
    if (np == 1)
        snprintf(model3mf, sizeof model3mf, "%s", planned[0]);
    free(planned);
    if (np != 1 || (rc = tippe_cli_make_output_dir(VERB, "-o", a.dir))) {
        rc = np < 0 ? tippe_cli_fail(VERB, &err, err.code ? err.code : 2) : rc ? rc : 2;
        tippe_design_free(d);
        return rc;
    }
    tippe_export_result xr;
    if ((rc = tippe_export_run(d, &q, &xr, &err))) {
        tippe_design_free(d);
        return tippe_cli_fail(VERB, &err, rc);
    }
    int bodies = xr.n_bodies;
    tippe_export_result_free(&xr);
    /* the report set commits the 3MF now: the slicer reads it from disk */
    if (bodies != 1 || (rc = tippe_report_set_commit(&err))) {
        if (bodies != 1)
            fprintf(stderr, "tippe slice: %s: %d printed bodies (a G-code of one is read)\n",
                    a.path, bodies);
        tippe_design_free(d);
        return bodies != 1 ? 2 : tippe_cli_fail(VERB, &err, rc);
    }
    tippe_report_set_begin();
    char gcode[4200], logf[4200], abs_gcode[PATH_MAX + 200];
    size_t plen = strlen(model3mf);
    snprintf(gcode, sizeof gcode, "%.*s.gcode", (int)(plen > 4 ? plen - 4 : plen), model3mf);
    snprintf(logf, sizeof logf, "%s/slicer.log", a.dir);
    if (!a.json)
        fprintf(stderr, "tippe slice: slicing %s with %s (%s)...\n", model3mf, slicer, profile);
    if (run_slicer(slicer, profile, gcode, model3mf, logf, why, sizeof why)) {
        fprintf(stderr, "tippe slice: %s\n", why);
        tippe_design_free(d);
        return 1;
    }
    if (!realpath(gcode, abs_gcode))
        snprintf(abs_gcode, sizeof abs_gcode, "%s", gcode);
    /* the sliced part: the same design with the G-code as its printed body */
    char set[PATH_MAX + 400];
    snprintf(set, sizeof set, "parts.%s.print.gcode=%s", part_name, abs_gcode);
    const char *all[TIPPE_CLI_MAX_SETS + 1];
    for (int k = 0; k < a.sets.n; k++)
        all[k] = a.sets.item[k];
    all[a.sets.n] = set;
    tippe_design *s = NULL;
    tippe_sweep_result rm, rs;
    if ((rc = tippe_design_load(a.path, all, a.sets.n + 1, &s, &err)) ||
        (rc = tippe_sweep_design(d, 0, 0, NULL, &rm, &err))) {
        tippe_design_free(d);
        tippe_design_free(s);
        return tippe_cli_fail(VERB, &err, rc);
    }
    if ((rc = tippe_sweep_design(s, 0, 0, NULL, &rs, &err))) {
        tippe_sweep_result_free(&rm);
        tippe_design_free(d);
        tippe_design_free(s);
        return tippe_cli_fail(VERB, &err, rc);
    }
    if (a.json) {
        cJSON *o = cJSON_CreateObject();
        cJSON_AddStringToObject(o, "design", a.path);
        cJSON_AddStringToObject(o, "gcode", gcode);
        cJSON_AddStringToObject(o, "profile", profile);
        cJSON_AddItemToObject(o, "sliced", tippe_sweep_json(&rs, s));
        cJSON_AddItemToObject(o, "model", tippe_sweep_json(&rm, d));
        cJSON *sp = cJSON_AddObjectToObject(o, "sliced_parts");
        if (sp)
            tippe_profile_printed_parts_json(sp, s);
        rc = tippe_cli_print_json(VERB, o);
    } else {
        printf("design   %s\nG-code   %s (profile %s)\n", a.path, gcode, profile);
        print_side_by_side(d, s, &rm, &rs, part);
    }
    tippe_sweep_result_free(&rm);
    tippe_sweep_result_free(&rs);
    tippe_design_free(s);
    tippe_design_free(d);
    return rc;
}
