/* tippe serve's G-code uploads (issue 37): a maker's sliced G-code, sent as the body
 * of POST /api/gcode, is read in memory by the library (tippe_gcode_parse_buffer:
 * never a path) once, at one density, and kept by an id; a design then names it as a
 * part's "print": {"gcode": "upload:ID"}, and the loader takes the kept body for that
 * part (tippe_design_load_text_gcode) as it would read a file. The text is kept too:
 * a build's zip carries it beside the design, which names it as a file the command
 * reads (tippe build STEM.json in the unzipped folder). */
#include "serve/internal.h"

#include "tippe/design.h"
#include "tippe/print.h"

#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Uploads kept: a maker compares a slicing or two; each body is a few KiB, its text
 * what the slicer wrote (8.5 MB for the M12 at 0.2 mm layers). The texts kept add up
 * to at most GCODE_TEXT_BYTES (two uploads at the largest size the server takes):
 * beyond, the oldest uploads are forgotten whole, so that an upload kept is always
 * one a build can put in its zip. */
enum { GCODE_KEPT = 8 };
#define GCODE_TEXT_BYTES ((size_t)2 * TIPPE_SERVE_MAX_GCODE_BYTES)
static struct {
    char id[24];
    char name[128];
    tippe_gcode_body body;
    tippe_gcode_beads beads; /* near the axis, for the holes' cuts (UPLOAD_BEADS_MM) */
    /* read again with a design's print.filament_diameter_mm (as tippe eval reads a
     * file with it): the last diameter asked, its body and beads */
    double alt_diameter_mm;
    tippe_gcode_body alt_body;
    tippe_gcode_beads alt_beads;
    char *text;              /* the file's text, for a build's zip */
    size_t len;
    unsigned long seq;       /* when it was uploaded (the oldest is forgotten first) */
    int used;
} kept[GCODE_KEPT];
/* The beads kept of an upload, mm from its axis: a part's holes are cut out to their
 * radius + 3 mm (tippe_gcode_cut_body); 30 mm holds any hole of a ball up to 60 mm
 * across (the largest the G-code reader's cap expects, print.h). */
#define UPLOAD_BEADS_MM 30.0
static unsigned long kept_seq;
static pthread_mutex_t kept_lock = PTHREAD_MUTEX_INITIALIZER;

/* The upload's id: FNV-1a over its bytes (the same file uploaded twice is kept once). */
static void gcode_id(const char *text, size_t len, char *id, size_t size)
{
    uint64_t h = 1469598103934665603ull;
    for (size_t i = 0; i < len; i++)
        h = (h ^ (unsigned char)text[i]) * 1099511628211ull;
    snprintf(id, size, "%016llx", (unsigned long long)h);
}

/* Copies body and beads (the slot may be reused while the request runs). */
static void copy_out(const tippe_gcode_body *body, const tippe_gcode_beads *b,
                     tippe_gcode_body *out, tippe_gcode_beads *beads)
{
    *out = *body;
    const size_t nb = b->n * sizeof *b->bead;
    if (nb && (beads->bead = malloc(nb))) {
        memcpy(beads->bead, b->bead, nb);
        beads->n = b->n;
        beads->radius_mm = b->radius_mm;
    }
}

/* The options an upload is read with: one density for every tool, 1 g/cm^3 (a
 * part scales it to its material's), and the design's filament diameter when it
 * gives one (0: the file's own), as the command reads a file (design_printed.c). */
static tippe_gcode_options upload_options(double diameter_mm)
{
    tippe_gcode_options opt = tippe_gcode_defaults();
    opt.density_g_cm3 = 1.0;
    opt.override_density = 1;
    if (diameter_mm > 0) {
        opt.filament_diameter_mm = diameter_mm;
        opt.override_diameter = 1;
    }
    return opt;
}

int tippe_serve_gcode_find(const char *id, double diameter_mm, tippe_gcode_body *out,
                           tippe_gcode_beads *beads, char *name, size_t size, tippe_error *err)
{
    int found = 0;
    *beads = (tippe_gcode_beads){0};
    char *text = NULL;
    size_t len = 0;
    pthread_mutex_lock(&kept_lock);
    for (int i = 0; i < GCODE_KEPT && !found; i++) {
        if (!kept[i].used || strcmp(kept[i].id, id))
            continue;
        found = 1;
        snprintf(name, size, "%s", kept[i].name);
        if (!(diameter_mm > 0) || diameter_mm == kept[i].body.filament_diameter_mm)
            copy_out(&kept[i].body, &kept[i].beads, out, beads);
        else if (diameter_mm == kept[i].alt_diameter_mm)
            copy_out(&kept[i].alt_body, &kept[i].alt_beads, out, beads);
        else if (!(text = malloc(kept[i].len + 1)))
            found = -1;
        else {
            memcpy(text, kept[i].text, kept[i].len + 1);
            len = kept[i].len;
        }
    }
    pthread_mutex_unlock(&kept_lock);
    if (found < 0)
        return -tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    if (!text)
        return found;
    /* another diameter than the file's: read once more (outside the lock), kept */
    tippe_gcode_options opt = upload_options(diameter_mm);
    tippe_gcode_body body;
    tippe_gcode_beads near;
    int rc = tippe_gcode_parse_near(text, len, name, &opt, UPLOAD_BEADS_MM, &body, &near, err);
    free(text);
    if (rc)
        return -rc;
    copy_out(&body, &near, out, beads);
    pthread_mutex_lock(&kept_lock);
    for (int i = 0; i < GCODE_KEPT; i++)
        if (kept[i].used && !strcmp(kept[i].id, id)) {
            tippe_gcode_beads_free(&kept[i].alt_beads);
            kept[i].alt_diameter_mm = diameter_mm;
            kept[i].alt_body = body;
            kept[i].alt_beads = near;
            near = (tippe_gcode_beads){0};
            break;
        }
    pthread_mutex_unlock(&kept_lock);
    tippe_gcode_beads_free(&near);
    return 1;
}

/* Forgets slot i (under kept_lock). */
static void kept_drop(int i)
{
    tippe_gcode_beads_free(&kept[i].beads);
    tippe_gcode_beads_free(&kept[i].alt_beads);
    free(kept[i].text);
    memset(&kept[i], 0, sizeof kept[i]);
}

int tippe_serve_gcode_text(const char *id, char **text, size_t *len)
{
    int found = 0;
    *text = NULL;
    *len = 0;
    pthread_mutex_lock(&kept_lock);
    for (int i = 0; i < GCODE_KEPT && !found; i++)
        if (kept[i].used && !strcmp(kept[i].id, id)) {
            found = 1;
            if (kept[i].text && (*text = malloc(kept[i].len + 1))) {
                memcpy(*text, kept[i].text, kept[i].len + 1);
                *len = kept[i].len;
            } else {
                found = -1;
            }
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
    /* at the file's own diameter: a design's print.filament_diameter_mm reads it
     * again when a part names it (tippe_serve_gcode_find) */
    tippe_gcode_options opt = upload_options(0);
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
    char *copy = malloc(len + 1);
    if (!copy) {
        tippe_gcode_beads_free(&beads);
        tippe_serve_respond_error(out, 503, NULL, "out of memory");
        return;
    }
    memcpy(copy, t->valuestring, len + 1);
    pthread_mutex_lock(&kept_lock);
    /* its own slot again, else a free one, else the oldest */
    int slot = -1;
    for (int i = 0; i < GCODE_KEPT && slot < 0; i++)
        if (kept[i].used && !strcmp(kept[i].id, id))
            slot = i;
    for (int i = 0; i < GCODE_KEPT && slot < 0; i++)
        if (!kept[i].used)
            slot = i;
    if (slot < 0) { /* all in use: the oldest */
        slot = 0;
        for (int i = 1; i < GCODE_KEPT; i++)
            if (kept[i].seq < kept[slot].seq)
                slot = i;
    }
    kept_drop(slot);
    /* the texts kept within GCODE_TEXT_BYTES: the oldest others forgotten */
    for (;;) {
        size_t total = len;
        int oldest = -1;
        for (int i = 0; i < GCODE_KEPT; i++)
            if (kept[i].used) {
                total += kept[i].len;
                if (oldest < 0 || kept[i].seq < kept[oldest].seq)
                    oldest = i;
            }
        if (total <= GCODE_TEXT_BYTES || oldest < 0)
            break;
        kept_drop(oldest);
    }
    snprintf(kept[slot].id, sizeof kept[slot].id, "%s", id);
    snprintf(kept[slot].name, sizeof kept[slot].name, "%s", name);
    kept[slot].body = body;
    kept[slot].beads = beads;
    kept[slot].text = copy;
    kept[slot].len = len;
    kept[slot].seq = ++kept_seq;
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
        kept_drop(i);
    pthread_mutex_unlock(&kept_lock);
}
