/* export_slice.c: the slicer in the loop (tippe slice, docs/printing.md). Writes
 * the design's 3MF (tippe export), slices it headless with PrusaSlicer's command
 * line and a profile, reads the G-code back as the printed part (print.gcode)
 * and sweeps and judges the top both ways: the layer model's part and the
 * slicer's, each with its zone table, bands and the build sheet's verdict. Here
 * rather than in the command, so that every front end slices alike (issue 34:
 * the command never computes). The slicer runs without a shell; its output goes
 * to its log. */
#include "tippe/export.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

extern char **environ;

int tippe_export_slice_part(const tippe_design *d, char *name, size_t cap, tippe_error *err)
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
    if (n == 1)
        return found;
    tippe_error_set(err, TIPPE_EINPUT,
                    "%s: %s printed part%s (a part with a \"print\" block); slice takes a "
                    "design with exactly one",
                    tippe_design_path(d), n ? "more than one" : "no", n ? "s" : "");
    return -1;
}

/* Runs the slicer on model (argv as given; posix_spawnp looks a bare name up
 * on PATH), its output into log. */
static int run_slicer(const tippe_export_slice_request *q, const char *gcode, const char *model,
                      const char *log, tippe_error *err)
{
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, log, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&fa, STDOUT_FILENO, STDERR_FILENO);
    posix_spawn_file_actions_addopen(&fa, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    char *argv[] = {(char *)q->slicer, "--export-gcode", "--load", (char *)q->profile, "-o",
                    (char *)gcode, (char *)model, NULL};
    pid_t pid;
    int rc = posix_spawnp(&pid, q->slicer, &fa, NULL, argv, environ);
    posix_spawn_file_actions_destroy(&fa);
    if (rc)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "could not start %s: %s", q->slicer,
                               strerror(rc));
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
        ;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "%s failed (exit %d; its log: %s)", q->slicer,
                               WIFEXITED(status) ? WEXITSTATUS(status) : -1, log);
    return TIPPE_OK;
}

/* The 3MF of d's one printed body, written and committed (the slicer reads it).
 * Its screw's hole is printed as the build sheet prints it (sheet: its tap
 * drill or insert's pilot, as export_build.c's 3MF has it), so that the G-code
 * is the part tippe build makes and its verdict models (the part as made). */
static int write_model(const tippe_design *d, const tippe_export_slice_request *q,
                       const tippe_build_sheet *sheet, tippe_export_slice_result *out,
                       tippe_error *err)
{
    tippe_export_request x = {.profile = tippe_profile_defaults(), .formats = TIPPE_EXPORT_3MF,
                              .dir = q->dir};
    x.profile.clearance_mm = q->clearance_mm;
    if (sheet->hole_tapped || sheet->hole_insert) {
        x.profile.fit_part = sheet->hole_part;
        x.profile.fit_diameter_mm = sheet->hole_diameter_mm;
        x.fit_note = sheet->fit_note;
    }
    double t0, t1;
    tippe_design_travel_mm(d, &t0, &t1);
    x.z2_mm = 0.5 * (t0 + t1);
    char(*planned)[4096] = NULL;
    int np = tippe_export_plan(d, &x, &planned, err);
    if (np == 1)
        snprintf(out->model_3mf, sizeof out->model_3mf, "%s", planned[0]);
    free(planned);
    if (np < 0)
        return err->code ? err->code : TIPPE_EINPUT;
    tippe_export_result xr;
    int rc = np == 1 ? tippe_export_run(d, &x, &xr, err) : TIPPE_OK;
    int bodies = np == 1 && !rc ? xr.n_bodies : np;
    if (np == 1 && !rc)
        tippe_export_result_free(&xr);
    if (rc)
        return rc;
    if (bodies != 1)
        return tippe_error_set(err, TIPPE_EINPUT,
                               "%s: %d printed bodies (a G-code of one is read)",
                               tippe_design_path(d), bodies);
    if ((rc = tippe_report_set_commit(err)))
        return rc;
    tippe_report_set_begin();
    return TIPPE_OK;
}

int tippe_export_slice(const tippe_design *d, const tippe_export_slice_request *q,
                       tippe_export_slice_result *out, tippe_error *err)
{
    memset(out, 0, sizeof *out);
    out->part = tippe_export_slice_part(d, out->part_name, sizeof out->part_name, err);
    if (out->part < 0)
        return TIPPE_EINPUT;
    out->model_sheet = calloc(1, sizeof *out->model_sheet);
    out->sliced_sheet = calloc(1, sizeof *out->sliced_sheet);
    int rc = !out->model_sheet || !out->sliced_sheet
                 ? tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory")
                 : tippe_build_compute_verdict(d, &q->verdict, out->model_sheet, err);
    if (!rc)
        rc = write_model(d, q, out->model_sheet, out, err);
    if (rc) {
        tippe_export_slice_result_free(out);
        return rc;
    }
    size_t plen = strlen(out->model_3mf);
    snprintf(out->gcode, sizeof out->gcode, "%.*s.gcode", (int)(plen > 4 ? plen - 4 : plen),
             out->model_3mf);
    snprintf(out->log, sizeof out->log, "%s/slicer.log", q->dir);
    if ((rc = run_slicer(q, out->gcode, out->model_3mf, out->log, err))) {
        tippe_export_slice_result_free(out);
        return rc;
    }
    /* the sliced part: the design as first read, the G-code as its printed body */
    char abs_gcode[PATH_MAX + 4200], set[PATH_MAX + 4400];
    if (!realpath(out->gcode, abs_gcode))
        snprintf(abs_gcode, sizeof abs_gcode, "%s", out->gcode);
    snprintf(set, sizeof set, "parts.%s.print.gcode=%s", out->part_name, abs_gcode);
    const char *extra[1] = {set};
    /* both as made: the model's hole printed as the 3MF's, tapped after (build.h) */
    tippe_design *made = NULL;
    rc = tippe_build_as_made(d, out->model_sheet, &made, err);
    if (made)
        d = made;
    if (!rc)
        rc = tippe_design_reload(d, extra, 1, &out->sliced, err);
    if (!rc)
        rc = tippe_sweep_design(d, 0, 0, NULL, &out->model_sweep, err);
    if (!rc)
        rc = tippe_sweep_design(out->sliced, 0, 0, NULL, &out->sliced_sweep, err);
    if (!rc)
        rc = tippe_build_compute_verdict(out->sliced, &q->verdict, out->sliced_sheet, err);
    tippe_design_free(made);
    if (rc)
        tippe_export_slice_result_free(out);
    return rc;
}

void tippe_export_slice_result_free(tippe_export_slice_result *r)
{
    tippe_sweep_result_free(&r->model_sweep); /* a zeroed result frees nothing */
    tippe_sweep_result_free(&r->sliced_sweep);
    tippe_design_free(r->sliced);
    free(r->model_sheet);
    free(r->sliced_sheet);
    r->sliced = NULL;
    r->model_sheet = r->sliced_sheet = NULL;
}
