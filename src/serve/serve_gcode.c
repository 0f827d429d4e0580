/* tippe serve's G-code uploads (issue 37): a maker's sliced G-code, sent as the body
 * of POST /api/gcode, is read in memory by the library (tippe_gcode_parse_buffer:
 * never a path) once, at one density, and kept by an id; a design then names it as a
 * part's "print": {"gcode": "upload:ID"}, and the loader takes the kept body for that
 * part (tippe_design_load_text_gcode) as it would read a file. */
#include "serve/internal.h"

#include "tippe/design.h"
#include "tippe/print.h"

#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Uploads kept: a maker compares a slicing or two; each body is a few KiB. */
enum { GCODE_KEPT = 8 };
static struct {
    char id[24];
    char name[128];
    tippe_gcode_body body;
    tippe_gcode_beads beads; /* near the axis, for the holes' cuts (UPLOAD_BEADS_MM) */
    int used;
} kept[GCODE_KEPT];
/* The beads kept of an upload, mm from its axis: a part's holes are cut out to their
 * radius + 3 mm (tippe_gcode_cut_body); 30 mm holds any hole of a ball up to 60 mm
 * across (the largest the G-code reader's cap expects, print.h). */
#define UPLOAD_BEADS_MM 30.0
static int kept_next;
static pthread_mutex_t kept_lock = PTHREAD_MUTEX_INITIALIZER;

/* The upload's id: FNV-1a over its bytes (the same file uploaded twice is kept once). */
static void gcode_id(const char *text, size_t len, char *id, size_t size)
{
    uint64_t h = 1469598103934665603ull;
    for (size_t i = 0; i < len; i++)
        h = (h ^ (unsigned char)text[i]) * 1099511628211ull;
    snprintf(id, size, "%016llx", (unsigned long long)h);
}

int tippe_serve_gcode_find(const char *id, tippe_gcode_body *out, tippe_gcode_beads *beads,
                           char *name, size_t size)
{
    int found = 0;
    *beads = (tippe_gcode_beads){0};
    pthread_mutex_lock(&kept_lock);
    for (int i = 0; i < GCODE_KEPT && !found; i++)
        if (kept[i].used && !strcmp(kept[i].id, id)) {
            *out = kept[i].body;
            /* a copy: the slot may be reused while the request runs */
            const size_t nb = kept[i].beads.n * sizeof *kept[i].beads.bead;
            if (nb && (beads->bead = malloc(nb))) {
                memcpy(beads->bead, kept[i].beads.bead, nb);
                beads->n = kept[i].beads.n;
                beads->radius_mm = kept[i].beads.radius_mm;
            }
            snprintf(name, size, "%s", kept[i].name);
            found = 1;
        }
    pthread_mutex_unlock(&kept_lock);
    return found;
}

/* POST /api/gcode (Content-Type: text/x-gcode; ?name=FILE for messages): the body read
 * as G-code, kept, and answered with its id and what the slicer deposited. */
void tippe_serve_api_gcode(serve_server *s, const cJSON *req, serve_response *out)
{
    (void)s;
    const cJSON *t = cJSON_GetObjectItemCaseSensitive(req, "text");
    const cJSON *n = cJSON_GetObjectItemCaseSensitive(req, "name");
    char name[128] = "upload.gcode";
    if (cJSON_IsString(n) && n->valuestring[0])
        snprintf(name, sizeof name, "%s", n->valuestring);
    if (!cJSON_IsString(t) || !t->valuestring[0]) {
        tippe_serve_respond_error(out, 400, "gcode", "gcode: the body is empty (send the G-code "
                                                     "file's text)");
        return;
    }
    const size_t len = strlen(t->valuestring);
    /* one density for every tool, 1 g/cm^3: a part scales it to its material's */
    tippe_gcode_options opt = tippe_gcode_defaults();
    opt.density_g_cm3 = 1.0;
    opt.override_density = 1;
    tippe_gcode_body body;
    tippe_gcode_beads beads;
    tippe_error err = {0};
    int rc = tippe_gcode_parse_near(t->valuestring, len, name, &opt, UPLOAD_BEADS_MM, &body,
                                    &beads, &err);
    if (rc) {
        tippe_serve_respond_error(out, rc == TIPPE_EINPUT ? 400 : 500, "gcode", "%s", err.msg);
        return;
    }
    char id[24];
    gcode_id(t->valuestring, len, id, sizeof id);
    pthread_mutex_lock(&kept_lock);
    int slot = -1;
    for (int i = 0; i < GCODE_KEPT && slot < 0; i++)
        if (kept[i].used && !strcmp(kept[i].id, id))
            slot = i;
    if (slot < 0)
        slot = kept_next++ % GCODE_KEPT;
    snprintf(kept[slot].id, sizeof kept[slot].id, "%s", id);
    snprintf(kept[slot].name, sizeof kept[slot].name, "%s", name);
    kept[slot].body = body;
    tippe_gcode_beads_free(&kept[slot].beads);
    kept[slot].beads = beads;
    kept[slot].used = 1;
    pthread_mutex_unlock(&kept_lock);
    cJSON *o = cJSON_CreateObject();
    char ref[40];
    snprintf(ref, sizeof ref, "upload:%s", id);
    if (!o || !cJSON_AddStringToObject(o, "gcode", ref) ||
        !cJSON_AddStringToObject(o, "name", name) ||
        !cJSON_AddStringToObject(o, "generator", body.generator) ||
        !cJSON_AddNumberToObject(o, "lines", (double)body.n_lines) ||
        !cJSON_AddNumberToObject(o, "layers", body.n_layers) ||
        !cJSON_AddNumberToObject(o, "layer_height_mm", body.layer_height * 1e3) ||
        !cJSON_AddNumberToObject(o, "body_volume_mm3", body.body_volume_mm3) ||
        !cJSON_AddNumberToObject(o, "excluded_volume_mm3", body.excluded_volume_mm3) ||
        !cJSON_AddNumberToObject(o, "height_mm", (body.bbox_max[2] - body.bbox_min[2]) * 1e3)) {
        cJSON_Delete(o);
        tippe_serve_respond_error(out, 503, NULL, "out of memory");
        return;
    }
    tippe_serve_respond_json(out, 200, o);
}

void tippe_serve_gcode_forget(void)
{
    pthread_mutex_lock(&kept_lock);
    for (int i = 0; i < GCODE_KEPT; i++)
        tippe_gcode_beads_free(&kept[i].beads);
    memset(kept, 0, sizeof kept);
    pthread_mutex_unlock(&kept_lock);
}
