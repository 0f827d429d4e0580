/* tippe serve's section drawing (issue 37): the design's dimensioned section, as
 * tippe export draws it (its SVG), for the page to show beside the form. The export
 * writes into a temporary folder (removed before the answer leaves), read back whole. */
#include "serve/internal.h"

#include "tippe/export.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The largest drawing read back: a section's SVG is some 10 to 30 KiB. */
enum { SECTION_MAX_BYTES = 4 << 20 };

/* POST /api/section {design, z2_mm?}: image/svg+xml, tippe export's section drawing of
 * the design with its weight at z2_mm (default the middle of the travel, as tippe
 * export's). */
void tippe_serve_api_section(serve_server *s, const cJSON *req, serve_response *out)
{
    static const char *const keys[] = {"design", "z2_mm", NULL};
    double z2 = NAN;
    if (tippe_serve_request_keys(req, keys, out) ||
        tippe_serve_request_number(req, "z2_mm", -1000, 1000, 0, &z2, out))
        return;
    tippe_design *d = tippe_serve_request_design(s, req, "design", "design", out);
    if (!d)
        return;
    if (!cJSON_HasObjectItem(req, "z2_mm")) {
        double f, t;
        tippe_design_travel_mm(d, &f, &t);
        z2 = 0.5 * (f + t);
    }
    char dir[4096];
    if (tippe_serve_tmp_make(s, dir, sizeof dir)) {
        tippe_serve_respond_error(out, 503, NULL, "cannot make a temporary folder");
        tippe_design_free(d);
        return;
    }
    tippe_export_request q = {.profile = tippe_profile_defaults()};
    q.z2_mm = z2;
    q.formats = TIPPE_EXPORT_SVG;
    q.dir = dir;
    tippe_export_result r = {0};
    tippe_error err = {0};
    int rc = tippe_export_run(d, &q, &r, &err);
    char *svg = NULL;
    size_t len = 0;
    for (int i = 0; !rc && i < r.n_files && !svg; i++) {
        const size_t n = strlen(r.file[i]);
        if (n > 12 && !strcmp(r.file[i] + n - 12, "-section.svg"))
            rc = tippe_file_read(r.file[i], SECTION_MAX_BYTES, "section drawing", &svg, &len,
                                 &err);
    }
    if (!rc && !svg)
        rc = tippe_error_set(&err, TIPPE_ECOMPUTE, "the export drew no section");
    tippe_export_result_free(&r);
    tippe_serve_tmp_remove(s, dir);
    tippe_design_free(d);
    if (rc) {
        free(svg);
        tippe_serve_respond_error(out, rc == TIPPE_EINPUT ? 400 : 500, NULL, "%s", err.msg);
        return;
    }
    tippe_serve_response_free(out);
    out->status = 200;
    out->type = "image/svg+xml";
    out->body = svg;
    out->len = len;
}
