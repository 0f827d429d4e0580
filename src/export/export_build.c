/* tippe build's files, for both front ends (tippe build, tippe serve's
 * /api/build): the sheet as JSON, Markdown, PDF, SVG and PNG, its depth
 * gauges, and tippe export's files with the screw's hole as the sheet says.
 * In the library's core: it calls the drawing and mesh writers through the
 * command's stubs, so that only a build loads cairo and lib3MF. */
#include "tippe/build.h"
#include "tippe/export.h"

#include <cjson/cJSON.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The sheet's files: JSON, Markdown, the page as PDF, SVG and PNG, then the
 * depth gauges of the three settings (those that apply are written). */
static const char *const sheet_tails[TIPPE_EXPORT_BUILD_FILES] = {
    "-build.json", "-build.md", "-sheet.pdf", "-sheet.svg", "-sheet.png",
    "-gauge-stays-up.stl", "-gauge-flips.stl", "-gauge-hangs.stl"};

void tippe_export_build_paths(const tippe_design *d, const char *dir, char (*out)[4096])
{
    char stem[1024];
    tippe_build_stem(tippe_design_path(d), stem, sizeof stem);
    const char *sep = dir[0] && dir[strlen(dir) - 1] != '/' ? "/" : "";
    for (int k = 0; k < TIPPE_EXPORT_BUILD_FILES; k++)
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
    for (int k = 2; !rc && k < TIPPE_EXPORT_BUILD_SHEET; k++)
        rc = tippe_cancel_requested() ? tippe_cancel_error(err)
                               : tippe_export_sheet_write(d, s, paths[k], err);
    double pin;
    for (int f = 0; !rc && f < 3; f++)
        if (tippe_build_gauge_applies(s, f, &pin))
            rc = tippe_cancel_requested() ? tippe_cancel_error(err)
                                   : tippe_export_gauge_write(s, f,
                                                              paths[TIPPE_EXPORT_BUILD_SHEET + f],
                                                              err);
    return rc;
}

int tippe_export_build_write(const tippe_design *d, const tippe_build_sheet *s,
                             char (*paths)[4096], tippe_export_request *q, char *fit_note,
                             size_t fit_note_size, tippe_export_result *r, tippe_error *err)
{
    if (q) {
        /* the drawing shows the weight where the flip is set, else at the first
         * setting there is, with its depth below the rim dimensioned */
        double z2 = NAN;
        if (tippe_export_shown_setting(s, &z2, &q->has_depth, &q->depth_rim_z_mm,
                                       &q->depth_end_z_mm, &q->depth_x_mm, q->depth_label,
                                       sizeof q->depth_label) >= 0)
            q->z2_mm = z2;
        q->depth_from = tippe_export_depth_from(s);
    }
    int rc = write_sheet(d, s, paths, err);
    if (!q || rc)
        return rc;
    if (s->hole_tapped || s->hole_insert) {
        q->profile.fit_part = s->hole_part;
        q->profile.fit_diameter_mm = s->hole_diameter_mm;
        snprintf(fit_note, fit_note_size, "%s", s->fit_note);
        q->fit_note = fit_note;
    }
    if (tippe_cancel_requested())
        return tippe_cancel_error(err);
    return tippe_export_run(d, q, r, err);
}

void tippe_export_build_request(const tippe_design *d, double clearance_mm, const char *dir,
                                tippe_export_request *q)
{
    q->profile.clearance_mm = clearance_mm;
    q->dir = dir;
    q->formats = TIPPE_EXPORT_ALL;
    /* a body that closes around its hardware is printed in halves */
    q->profile.split = tippe_build_needs_split(d, clearance_mm);
    q->profile.joint = q->profile.split;   /* and joined on a ring */
    q->profile.sockets = q->profile.split; /* a rod spanning it held at the poles */
    double t0, t1;
    tippe_design_travel_mm(d, &t0, &t1);
    q->z2_mm = 0.5 * (t0 + t1);
}
