/* tippe serve's endpoints: each reads its request strictly, calls the library
 * and answers with the JSON the command's --json gives for the same verb (the
 * same builders, tippe/sweep.h's reports), plus what only a page needs (the
 * sampled path of the zone plot). docs/serve.md lists every field. */
#include "serve/internal.h"

#include "tippe/animate.h"
#include "tippe/build.h"
#include "tippe/export.h"
#include "tippe/launch.h"
#include "tippe/sweep.h"

#include <dirent.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Samples of the zone plot's path a sweep answer carries. */
enum { CURVE_SAMPLES = 241 };

/* The sweep of d as tippe sweep --json gives it (range: the stated travel
 * unless from_mm < to_mm), with "curve" for the plot. NULL with out set. */
static cJSON *sweep_answer(const tippe_design *d, double from_mm, double to_mm,
                           serve_response *out)
{
    tippe_error err = {0};
    tippe_sweep_result r;
    tippe_sweep_bands_result b = {0};
    int rc = tippe_sweep_design(d, from_mm, to_mm, NULL, &r, &err);
    if (!rc)
        rc = tippe_sweep_bands(d, &r, &b, &err);
    cJSON *o = NULL;
    if (rc) {
        tippe_serve_respond_error(out, rc == TIPPE_EINPUT ? 400 : 500, "design", "%s", err.msg);
    } else if (!(o = tippe_sweep_report_json(d, &r, &b))) {
        tippe_serve_respond_error(out, 503, NULL, "out of memory");
    } else {
        cJSON *curve = tippe_sweep_samples_json(d, r.from_mm, r.to_mm, CURVE_SAMPLES);
        if (!curve || !cJSON_AddItemToObject(o, "curve", curve)) {
            cJSON_Delete(curve);
            cJSON_Delete(o);
            o = NULL;
            tippe_serve_respond_error(out, 503, NULL, "out of memory");
        }
    }
    tippe_sweep_bands_free(&b);
    tippe_sweep_result_free(&r);
    return o;
}

/* The optional sweep range of a request: 0, or -1 with out set. */
static int sweep_range(const cJSON *req, double *from_mm, double *to_mm, serve_response *out)
{
    const double big = 1000.0; /* as the command's --from, --to */
    *from_mm = *to_mm = 0.0;
    if (tippe_serve_request_number(req, "from_mm", -big, big, 0, from_mm, out) ||
        tippe_serve_request_number(req, "to_mm", -big, big, 0, to_mm, out))
        return -1;
    const int has_from = cJSON_HasObjectItem(req, "from_mm"),
              has_to = cJSON_HasObjectItem(req, "to_mm");
    if (has_from != has_to) {
        tippe_serve_respond_error(out, 400, has_from ? "to_mm" : "from_mm",
                            "from_mm and to_mm go together (neither: the design's travel)");
        return -1;
    }
    if (has_from && !(*from_mm < *to_mm)) {
        tippe_serve_respond_error(out, 400, "from_mm", "from_mm %g must be below to_mm %g", *from_mm,
                            *to_mm);
        return -1;
    }
    return 0;
}

/* POST /api/sweep {design, from_mm?, to_mm?}: tippe sweep --json, and curve. */
static void api_sweep(serve_server *s, const cJSON *req, serve_response *out)
{
    static const char *const keys[] = {"design", "from_mm", "to_mm", NULL};
    double from, to;
    if (tippe_serve_request_keys(req, keys, out) || sweep_range(req, &from, &to, out))
        return;
    tippe_design *d = tippe_serve_request_design(s, req, "design", NULL, out);
    if (!d)
        return;
    cJSON *o = sweep_answer(d, from, to, out);
    if (o)
        tippe_serve_respond_json(out, 200, o);
    tippe_design_free(d);
}

/* POST /api/eval {design, z2_mm}: tippe eval --json. */
static void api_eval(serve_server *s, const cJSON *req, serve_response *out)
{
    static const char *const keys[] = {"design", "z2_mm", NULL};
    double z2 = 0;
    if (tippe_serve_request_keys(req, keys, out) ||
        tippe_serve_request_number(req, "z2_mm", -1000, 1000, 1, &z2, out))
        return;
    tippe_design *d = tippe_serve_request_design(s, req, "design", NULL, out);
    if (!d)
        return;
    tippe_error err = {0};
    tippe_top top;
    if (tippe_design_top(d, z2, &top, &err))
        tippe_serve_respond_error(out, 400, "z2_mm", "%s", err.msg);
    else
        tippe_serve_respond_json(out, 200, tippe_sweep_eval_json(d, z2, &top));
    tippe_design_free(d);
}

/* POST /api/compare {designs: [A, B]}: each design's sweep, as /api/sweep. */
static void api_compare(serve_server *s, const cJSON *req, serve_response *out)
{
    static const char *const keys[] = {"designs", NULL};
    if (tippe_serve_request_keys(req, keys, out))
        return;
    const cJSON *list = cJSON_GetObjectItemCaseSensitive(req, "designs");
    if (!cJSON_IsArray(list) || cJSON_GetArraySize(list) < 1 || cJSON_GetArraySize(list) > 4) {
        tippe_serve_respond_error(out, 400, "designs",
                            "designs: must be an array of 1 to 4 designs (objects or shipped "
                            "names)");
        return;
    }
    cJSON *o = cJSON_CreateObject();
    cJSON *arr = o ? cJSON_AddArrayToObject(o, "designs") : NULL;
    if (!arr) {
        cJSON_Delete(o);
        tippe_serve_respond_error(out, 503, NULL, "out of memory");
        return;
    }
    int i = 0;
    for (const cJSON *x = list->child; x; x = x->next, i++) {
        char key[32];
        snprintf(key, sizeof key, "designs[%d]", i);
        cJSON *one = cJSON_CreateObject();
        if (!one || !cJSON_AddItemReferenceToObject(one, key, (cJSON *)x)) {
            cJSON_Delete(one);
            cJSON_Delete(o);
            tippe_serve_respond_error(out, 503, NULL, "out of memory");
            return;
        }
        tippe_design *d = tippe_serve_request_design(s, one, key, NULL, out);
        cJSON_Delete(one);
        cJSON *sw = d ? sweep_answer(d, 0, 0, out) : NULL;
        tippe_design_free(d);
        if (!sw) {
            cJSON_Delete(o);
            return;
        }
        cJSON_AddItemToArray(arr, sw);
    }
    tippe_serve_respond_json(out, 200, o);
}

/* The server's names of the friction parameters (its request fields), for the
 * library's messages. */
static const tippe_friction_names serve_friction_names = {
    .name = {[TIPPE_LAW_PARAM_LAW] = "friction",
             [TIPPE_LAW_PARAM_PATCH_MM] = "patch_mm",
             [TIPPE_LAW_PARAM_TABLE] = "table",
             [TIPPE_LAW_PARAM_MU_C] = "mu_c",
             [TIPPE_LAW_PARAM_SLIP_SCALE] = "slip_scale_m_s",
             [TIPPE_LAW_PARAM_MU] = "mu_s_m",
             [TIPPE_LAW_PARAM_RADIUS_SPAN] = "radius_span",
             [TIPPE_LAW_PARAM_CREEP_CAP] = "creep_cap"},
    .choose = "\"friction\": \"%s\"",
};

/* The launch of a request: z2_mm, spin (spin_rev_s or spin_rad_s; default 15
 * rev/s, as tippe check) and friction (a law of the table, default the first,
 * viscous; the patch law's patch_mm or table), checked by the library's rules as
 * tippe check's options are. 0, or -1 with out set. */
static int launch_request(const cJSON *req, double *z2, double *spin_rad_s,
                          tippe_launch_options *o, serve_response *out)
{
    const char *laws[TIPPE_N_FRICTION_LAWS + 1] = {NULL};
    for (int i = 0; i < TIPPE_N_FRICTION_LAWS; i++)
        laws[i] = tippe_friction_law_at(i)->name;
    double rev = 15.0, rad = NAN;
    tippe_launch_options_default(o);
    if (tippe_serve_request_number(req, "z2_mm", -1000, 1000, 1, z2, out) ||
        tippe_serve_request_number(req, "spin_rev_s", 0.1, 100, 0, &rev, out) ||
        tippe_serve_request_number(req, "spin_rad_s", 0.5, 2 * M_PI * 100, 0, &rad, out))
        return -1;
    if (cJSON_HasObjectItem(req, "spin_rev_s") && cJSON_HasObjectItem(req, "spin_rad_s")) {
        tippe_serve_respond_error(out, 400, "spin_rad_s",
                                  "spin_rev_s and spin_rad_s are one spin: give one");
        return -1;
    }
    *spin_rad_s = isfinite(rad) ? rad : 2 * M_PI * rev;
    const int law = tippe_serve_request_word(req, "friction", laws, 0, out);
    if (law < 0)
        return -1;
    /* the patch law: a radius (mm), or Hertz's on a table (tippe check's --patch-mm,
     * --table) */
    const tippe_friction_param *pm = &tippe_friction_params[TIPPE_LAW_PARAM_PATCH_MM];
    tippe_friction_given g = {.laws = laws[law]};
    /* from 1 um, as docs/serve.md says (the command's --patch-mm from pm->min) */
    if (tippe_serve_request_number(req, pm->key, 1e-3, pm->max, 0, &g.patch_mm, out))
        return -1;
    const cJSON *table = cJSON_GetObjectItemCaseSensitive(req, "table");
    if (table && !cJSON_IsString(table)) {
        tippe_serve_respond_error(out, 400, "table",
                                  "table: must be a string (" TIPPE_CONTACT_TABLES ")");
        return -1;
    }
    g.table = table ? table->valuestring : NULL;
    g.given = (cJSON_HasObjectItem(req, pm->key) ? 1u << TIPPE_LAW_PARAM_PATCH_MM : 0) |
              (table ? 1u << TIPPE_LAW_PARAM_TABLE : 0);
    tippe_friction_law chosen[TIPPE_MAX_FRICTION_LAWS];
    int n = 0;
    tippe_error err = {0};
    if (tippe_friction_choose(&g, &serve_friction_names, chosen, &n, o, &err)) {
        tippe_serve_respond_error(out, 400, err.field[0] ? err.field : "friction", "%s", err.msg);
        return -1;
    }
    return 0;
}

/* The patch law's radius for d (the library's rules: the design's tolerance as the
 * span, Hertz's radius on the request's table when none was given); 0, or -1 after an
 * answer. */
static int patch_request(const cJSON *req, const tippe_design *d, tippe_launch_options *o,
                         serve_response *out)
{
    /* launch_request checked it: a known surface, or none (the default table) */
    const cJSON *table = cJSON_GetObjectItemCaseSensitive(req, "table");
    tippe_error err = {0};
    if (tippe_friction_for_design(d, &o->law, 1, cJSON_IsString(table) ? table->valuestring : NULL,
                                  &serve_friction_names, o, &err)) {
        tippe_serve_respond_error(out, 400, err.field[0] ? err.field : "friction", "%s", err.msg);
        return -1;
    }
    return 0;
}

/* A launch's design, with the patch law's Hertz modulus resolved for it
 * (patch_request); NULL after an answer. */
static tippe_design *launch_design(serve_server *s, const cJSON *req, tippe_launch_options *o,
                                   serve_response *out)
{
    tippe_design *d = tippe_serve_request_design(s, req, "design", NULL, out);
    if (d && patch_request(req, d, o, out)) {
        tippe_design_free(d);
        return NULL;
    }
    return d;
}

/* Samples of theta(t) a check answer carries for its plot, and how far in model time:
 * a patch-law top's fall back comes a minute or two after its flip (docs/dynamics.md). */
enum { THETA_SAMPLES = 301 };
#define THETA_MAX_S 60.0
#define THETA_MAX_PATCH_S 180.0

/* POST /api/check {design, z2_mm, spin_rev_s | spin_rad_s, friction, radius_sensitivity?}:
 * tippe check --json, and theta_samples {t_s, theta_rad} over the launch (to past its
 * flip, or its decision). Under the patch law, as the command, the launch again at 1/F and
 * F times the patch radius (radius_sensitivity; "off" skips it). */
static void api_check(serve_server *s, const cJSON *req, serve_response *out)
{
    static const char *const keys[] = {"design",   "z2_mm",    "spin_rev_s",
                                       "spin_rad_s", "friction", "patch_mm",
                                       "table",    "radius_sensitivity", NULL};
    static const char *const on_off[] = {"on", "off", NULL};
    double z2 = 0, spin = 0;
    tippe_launch_options o;
    if (tippe_serve_request_keys(req, keys, out) || launch_request(req, &z2, &spin, &o, out))
        return;
    const int sensitivity = tippe_serve_request_word(req, "radius_sensitivity", on_off, 0, out);
    if (sensitivity < 0)
        return;
    tippe_design *d = launch_design(s, req, &o, out);
    if (!d)
        return;
    tippe_error err = {0};
    tippe_sweep_check c;
    int rc = tippe_sweep_check_run(d, z2, &o, spin, &c, &err);
    cJSON *j = rc ? NULL : tippe_sweep_check_json(&c, &o, NULL, 0);
    if (rc) {
        tippe_serve_respond_error(out, rc == TIPPE_EINPUT ? 400 : 500,
                                  err.field[0] ? err.field : NULL, "%s", err.msg);
        tippe_design_free(d);
        return;
    }
    const int patch = tippe_friction_law_type_of(o.law)->patch;
    if (patch && sensitivity == 0) {
        /* the radius is uncertain: the verdict at 1/F and F times it (tippe check's) */
        tippe_launch_radius_sensitivity sens;
        if (tippe_launch_radius_sensitivity_initial(&c.top, &o, &c.ic, &c.rec, &sens, &err)) {
            cJSON_Delete(j);
            tippe_serve_respond_error(out, 500, NULL, "%s", err.msg);
            tippe_design_free(d);
            return;
        }
        if (j)
            cJSON_AddItemToObject(j, "radius_sensitivity", tippe_launch_radius_json(&sens, 1));
    }
    /* theta(t) to half as far again past the flip, or to the decision; past the fall back
     * of a patch-law top too (the end of its story), within a longer bound */
    const double flip = c.rec.t_flip_s, fall = c.rec.t_fall_s;
    double t_end = isfinite(flip) ? fmax(1.5 * flip, flip + 1.0) : fmax(c.rec.t_s, 2.0);
    if (isfinite(fall))
        t_end = fmax(t_end, 1.2 * fall);
    t_end = fmin(t_end, patch ? THETA_MAX_PATCH_S : THETA_MAX_S);
    double t[THETA_SAMPLES], th[THETA_SAMPLES];
    int n = 0;
    tippe_error terr = {0};
    tippe_launch_trace(&c.top, &o, &c.ic, t_end, THETA_SAMPLES, t, th, &n, &terr);
    cJSON *ts = cJSON_CreateObject();
    if (j && ts && cJSON_AddItemToObject(j, "theta_samples", ts)) {
        cJSON_AddItemToObject(ts, "t_s", cJSON_CreateDoubleArray(t, n));
        cJSON_AddItemToObject(ts, "theta_rad", cJSON_CreateDoubleArray(th, n));
    } else {
        cJSON_Delete(ts);
    }
    tippe_serve_respond_json(out, 200, j);
    tippe_design_free(d);
}

/* POST /api/animate {design, z2_mm, spin_rev_s | spin_rad_s, friction, format?
 * (webm, gif), seconds?, width_px?, height_px?, fps?}: the check's launch as a
 * short film (tippe animate's), the whole launch in `seconds` of film. The
 * film is encoded into an anonymous temporary file (tmpfile: it has no name,
 * so nothing is left whatever happens) and sent from memory. */
static void api_animate(serve_server *s, const cJSON *req, serve_response *out)
{
    static const char *const keys[] = {"design", "z2_mm", "spin_rev_s", "spin_rad_s", "friction",
                                       "patch_mm", "table", "format", "seconds", "width_px",
                                       "height_px", "fps", NULL};
    static const char *const formats[] = {"webm", "gif", NULL};
    double z2 = 0, spin = 0, seconds = 6, w = 320, h = 240, fps = 15;
    tippe_launch_options o;
    if (tippe_serve_request_keys(req, keys, out) || launch_request(req, &z2, &spin, &o, out) ||
        tippe_serve_request_number(req, "seconds", 1, TIPPE_SERVE_MAX_FILM_S, 0, &seconds, out) ||
        tippe_serve_request_number(req, "width_px", 64, TIPPE_SERVE_MAX_FILM_PX, 0, &w, out) ||
        tippe_serve_request_number(req, "height_px", 64, TIPPE_SERVE_MAX_FILM_PX, 0, &h, out) ||
        tippe_serve_request_number(req, "fps", 5, TIPPE_SERVE_MAX_FILM_FPS, 0, &fps, out))
        return;
    const int format = tippe_serve_request_word(req, "format", formats, 0, out);
    if (format < 0)
        return;
    if ((int)w % 2 || (int)h % 2 || w != (int)w || h != (int)h || fps != (int)fps) {
        tippe_serve_respond_error(out, 400, (int)w % 2 || w != (int)w ? "width_px"
                                            : (int)h % 2 || h != (int)h ? "height_px" : "fps",
                                  "width_px and height_px must be even whole numbers, fps whole");
        return;
    }
    tippe_design *d = launch_design(s, req, &o, out);
    if (!d)
        return;
    tippe_error err = {0};
    tippe_sweep_check c;
    tippe_animate_launch launch;
    tippe_animate_options ao;
    tippe_animate_options_default(&ao);
    ao.speed = 0;
    ao.film_s = seconds;
    ao.fps = (int)fps;
    ao.width_px = (int)w;
    ao.height_px = (int)h;
    tippe_film film = {0};
    FILE *f = NULL;
    int rc = tippe_sweep_check_run(d, z2, &o, spin, &c, &err);
    if (!rc)
        rc = tippe_animate_check_launch(&c, &o, &launch);
    if (!rc)
        rc = tippe_film_make(&launch, &ao, &film, &err);
    if (!rc && !(f = tmpfile()))
        rc = tippe_error_set(&err, TIPPE_ECOMPUTE, "cannot make a temporary file for the film");
    if (!rc)
        rc = tippe_film_write(&film, format ? TIPPE_FILM_GIF : TIPPE_FILM_WEBM, f, NULL, &err);
    long len = -1;
    char *body = NULL;
    if (!rc && (fflush(f) || fseek(f, 0, SEEK_END) || (len = ftell(f)) < 0 ||
                fseek(f, 0, SEEK_SET) || !(body = malloc((size_t)len + 1)) ||
                fread(body, 1, (size_t)len, f) != (size_t)len))
        rc = tippe_error_set(&err, TIPPE_ECOMPUTE, "cannot read the film back");
    if (f)
        fclose(f);
    tippe_film_free(&film);
    if (rc) {
        free(body);
        tippe_serve_respond_error(out, rc == TIPPE_EINPUT ? 400 : 500, NULL, "%s", err.msg);
    } else {
        tippe_serve_response_free(out);
        out->status = 200;
        out->type = format ? "image/gif" : "video/webm";
        out->body = body;
        out->len = (size_t)len;
        snprintf(out->filename, sizeof out->filename, "launch.%s", format ? "gif" : "webm");
    }
    tippe_design_free(d);
}

static int by_string(const void *a, const void *b)
{
    return strcmp(*(const char *const *)a, *(const char *const *)b);
}

/* The G-codes a build's zip carries: a part's upload ("print": {"gcode": "upload:ID"})
 * renamed in dup, the design that goes into the zip, to STEM-PART.gcode, a file beside
 * it (a part's G-code is named relative to its design file, design_printed.c), whose
 * text comes from the upload kept in memory (never a path of the request's). So the
 * unzipped folder builds with the command as on the page (tippe build STEM.json). */
typedef struct {
    char name[160];
    char *text;
    size_t len;
} zip_gcode;

/* Frees the n texts read and the array. */
static void zip_gcodes_free(zip_gcode *g, int n)
{
    for (int i = 0; i < n; i++)
        free(g[i].text);
    free(g);
}

/* The uploads of dup's parts renamed and their texts read: their count (*out_g
 * malloc'd), or -1 with out set. */
static int zip_gcodes(cJSON *dup, const char *stem, zip_gcode **out_g, serve_response *out)
{
    *out_g = NULL;
    const cJSON *parts = cJSON_GetObjectItemCaseSensitive(dup, "parts");
    const int n_parts = cJSON_IsArray(parts) ? cJSON_GetArraySize(parts) : 0;
    zip_gcode *g = n_parts ? calloc((size_t)n_parts, sizeof *g) : NULL;
    int n = 0, i = 0;
    for (cJSON *p = n_parts ? parts->child : NULL; p; p = p->next, i++) {
        cJSON *pr = cJSON_IsObject(p) ? cJSON_GetObjectItemCaseSensitive(p, "print") : NULL;
        cJSON *gc = cJSON_IsObject(pr) ? cJSON_GetObjectItemCaseSensitive(pr, "gcode") : NULL;
        const cJSON *pn = cJSON_GetObjectItemCaseSensitive(p, "name");
        if (!cJSON_IsString(gc) || strncmp(gc->valuestring, "upload:", 7) || !cJSON_IsString(pn))
            continue;
        if (!g) {
            tippe_serve_respond_error(out, 503, NULL, "out of memory");
            return -1;
        }
        /* the part's name as a file name's letters (a '-' for any other), at most 64 */
        char part[65];
        size_t k = 0;
        for (const char *c = pn->valuestring; *c && k < sizeof part - 1; c++, k++)
            part[k] = ((*c >= 'a' && *c <= 'z') || (*c >= 'A' && *c <= 'Z') ||
                       (*c >= '0' && *c <= '9') || *c == '_' || *c == '-')
                          ? *c
                          : '-';
        part[k] = 0;
        snprintf(g[n].name, sizeof g[n].name, "%s-%s.gcode", stem, part);
        for (int j = 0; j < n; j++)
            if (!strcmp(g[j].name, g[n].name)) /* two names alike once cleaned */
                snprintf(g[n].name, sizeof g[n].name, "%s-%s-%d.gcode", stem, part, i);
        const int got = tippe_serve_gcode_text(gc->valuestring + 7, &g[n].text, &g[n].len);
        if (got <= 0) {
            zip_gcodes_free(g, n);
            char field[64];
            snprintf(field, sizeof field, "design.parts[%d].print.gcode", i);
            if (got < 0)
                tippe_serve_respond_error(out, 503, NULL, "out of memory");
            else
                tippe_serve_respond_error(out, 400, field,
                                          "design: parts[%d].print.gcode: the uploaded G-code "
                                          "'%.40s' is not kept any more: upload it again",
                                          i, gc->valuestring);
            return -1;
        }
        n++;
        cJSON *renamed = cJSON_CreateString(g[n - 1].name);
        if (!renamed || !cJSON_ReplaceItemInObjectCaseSensitive(pr, "gcode", renamed)) {
            cJSON_Delete(renamed);
            zip_gcodes_free(g, n);
            tippe_serve_respond_error(out, 503, NULL, "out of memory");
            return -1;
        }
    }
    *out_g = g;
    return n;
}

/* POST /api/build {design, name?, hole?, clearance_mm?}: what tippe build -o DIR writes
 * (the sheet as JSON, Markdown, PDF, SVG, PNG, the gauges, tippe export's STL,
 * 3MF, OpenSCAD and drawing) as one zip. The files go to a temporary folder
 * (removed before the answer leaves, and at a stop); only one build runs at a
 * time (the library's file writer keeps one table of temporaries). */
static void api_build(serve_server *s, const cJSON *req, serve_response *out)
{
    static const char *const keys[] = {"design", "name", "hole", "clearance_mm", NULL};
    static const char *const fits[] = {"design", "tap", "insert", "slide", NULL};
    tippe_build_options o;
    tippe_build_options_default(&o);
    if (tippe_serve_request_keys(req, keys, out) ||
        tippe_serve_request_number(req, "clearance_mm", 0, 2, 0, &o.clearance_mm, out))
        return;
    const int fit = tippe_serve_request_word(req, "hole", fits, 0, out);
    if (fit < 0)
        return;
    o.hole_fit = fit == 0 ? TIPPE_BUILD_HOLE_DESIGN
                 : fit == 1 ? TIPPE_BUILD_HOLE_TAP
                 : fit == 2 ? TIPPE_BUILD_HOLE_INSERT : TIPPE_BUILD_HOLE_SLIDE;
    /* the files' stem: "name", else the shipped design's, else "design" */
    char stem[80] = "design";
    const cJSON *given = cJSON_GetObjectItemCaseSensitive(req, "design");
    if (cJSON_IsString(given) && tippe_serve_find_design(s, given->valuestring))
        snprintf(stem, sizeof stem, "%s", given->valuestring);
    if (tippe_serve_request_stem(req, "name", stem, sizeof stem, out))
        return;
    /* the design travels in the zip as STEM.json, and the sheet names that file */
    char file[96];
    snprintf(file, sizeof file, "%s.json", stem);
    tippe_design *d = tippe_serve_request_design(s, req, "design", file, out);
    if (!d)
        return;
    char *design_text = NULL;
    size_t design_len = 0;
    zip_gcode *gcodes = NULL;
    int n_gcodes = 0;
    const serve_design *shipped =
        cJSON_IsString(given) ? tippe_serve_find_design(s, given->valuestring) : NULL;
    if (shipped) {
        design_text = malloc(shipped->len + 1);
        if (design_text) {
            memcpy(design_text, shipped->text, shipped->len);
            design_len = shipped->len;
        }
    } else {
        /* sent as an object: printed by cJSON, its uploads named as the zip's files */
        cJSON *dup = cJSON_Duplicate(given, 1);
        n_gcodes = dup ? zip_gcodes(dup, stem, &gcodes, out) : -1;
        if (n_gcodes < 0) {
            cJSON_Delete(dup);
            tippe_design_free(d);
            if (!dup)
                tippe_serve_respond_error(out, 503, NULL, "out of memory");
            return;
        }
        if ((design_text = cJSON_Print(dup)))
            design_len = strlen(design_text);
        cJSON_Delete(dup);
    }
    serve_zip_member *members = calloc((size_t)n_gcodes + 1, sizeof *members);
    if (!design_text || !members) {
        tippe_serve_respond_error(out, 503, NULL, "out of memory");
        free(design_text);
        free(members);
        zip_gcodes_free(gcodes, n_gcodes);
        tippe_design_free(d);
        return;
    }
    members[0] = (serve_zip_member){file, design_text, design_len};
    for (int k = 0; k < n_gcodes; k++)
        members[k + 1] = (serve_zip_member){gcodes[k].name, gcodes[k].text, gcodes[k].len};
    char cat[4096 + 32], dir[4096];
    o.catalogue = tippe_build_catalogue_file(d, cat, sizeof cat);
    tippe_build_sheet *sheet = malloc(sizeof *sheet);
    char(*paths)[4096] = malloc(TIPPE_EXPORT_BUILD_FILES * sizeof *paths);
    if (!sheet || !paths || tippe_serve_tmp_make(s, dir, sizeof dir)) {
        tippe_serve_respond_error(out, 503, NULL, "cannot make a temporary folder for the build");
        free(design_text);
        free(members);
        zip_gcodes_free(gcodes, n_gcodes);
        free(sheet);
        free(paths);
        tippe_design_free(d);
        return;
    }
    tippe_error err = {0};
    tippe_export_request q = {.profile = tippe_profile_defaults()};
    tippe_export_result r = {0};
    char fit_note[64];
    tippe_export_build_request(d, o.clearance_mm, dir, &q);
    tippe_export_build_paths(d, dir, paths);
    int rc = tippe_build_compute(d, &o, sheet, &err);
    if (!rc)
        rc = tippe_export_build_write(d, sheet, paths, &q, fit_note, sizeof fit_note, &r, &err);
    /* every file the build wrote, by name (the export's and the sheet's) */
    const int cap = r.n_files + TIPPE_EXPORT_BUILD_FILES;
    tippe_export_result_free(&r);
    char **names = calloc((size_t)cap, sizeof *names);
    int n = 0;
    DIR *dd = rc || !names ? NULL : opendir(dir);
    for (struct dirent *e; dd && (e = readdir(dd)) && n < cap;)
        if (e->d_name[0] != '.' && (names[n] = strdup(e->d_name)))
            n++;
    if (dd)
        closedir(dd);
    qsort(names, (size_t)n, sizeof *names, by_string);
    char *zip = NULL;
    size_t len = 0;
    if (!rc)
        rc = tippe_serve_zip_folder(dir, (const char *const *)names, n, members, n_gcodes + 1,
                                    &zip, &len, &err);
    free(design_text);
    free(members);
    zip_gcodes_free(gcodes, n_gcodes);
    tippe_serve_tmp_remove(s, dir);
    for (int i = 0; i < n; i++)
        free(names[i]);
    free(names);
    if (rc) {
        tippe_serve_respond_error(out, rc == TIPPE_EINPUT ? 400 : 500, NULL, "%s", err.msg);
    } else {
        tippe_serve_response_free(out);
        out->status = 200;
        out->type = "application/zip";
        out->body = zip;
        out->len = len;
        snprintf(out->filename, sizeof out->filename, "%s-build.zip", stem);
    }
    free(sheet);
    free(paths);
    tippe_design_free(d);
}

/* The build options every sheet of the server uses: tippe build's defaults,
 * the design's catalogue as tippe build finds it (the designs folder's). */
static void sheet_options(const tippe_design *d, tippe_build_options *o, char *cat, size_t size)
{
    tippe_build_options_default(o);
    o->catalogue = tippe_build_catalogue_file(d, cat, size);
}

/* {verdict, three_in_one, settable, text, min_setting_mm, min_setting_rule, settings}
 * of a sheet; NULL when out of memory. */
static cJSON *verdict_json(const tippe_build_sheet *sheet)
{
    cJSON *o = cJSON_CreateObject();
    char text[2048];
    tippe_build_verdict_text(sheet, text, sizeof text);
    cJSON *sets = o ? cJSON_AddArrayToObject(o, "settings") : NULL;
    int ok = sets && cJSON_AddStringToObject(o, "verdict", tippe_build_verdict(sheet)) &&
             cJSON_AddBoolToObject(o, "three_in_one", sheet->three_in_one) &&
             cJSON_AddBoolToObject(o, "settable", sheet->settable) &&
             cJSON_AddStringToObject(o, "text", text) &&
             cJSON_AddNumberToObject(o, "min_setting_mm", sheet->min_setting_mm) &&
             cJSON_AddStringToObject(o, "min_setting_rule", sheet->min_setting_rule);
    for (int f = 0; ok && f < 3; f++) {
        const tippe_build_setting *x = &sheet->set[f];
        cJSON *e = cJSON_CreateObject();
        ok = e && cJSON_AddItemToArray(sets, e) &&
             cJSON_AddStringToObject(e, "behaviour", tippe_build_behaviour(f)) &&
             cJSON_AddBoolToObject(e, "reachable", x->reachable) &&
             cJSON_AddNumberToObject(e, "robust_width_mm", x->robust_width_mm) &&
             cJSON_AddBoolToObject(e, "settable", x->settable);
    }
    if (!ok) {
        cJSON_Delete(o);
        return NULL;
    }
    return o;
}

/* POST /api/verdict {design}: the build sheet's verdict (tippe build's: 3-in-1 and
 * settable, on paper only, or not 3-in-1), so that the page says "3-in-1" only where
 * each behaviour can be set by hand, with the sentence that says why. Only what the
 * verdict needs is computed (tippe_build_compute_verdict: the zones with their bands,
 * the thread): a sweep's cost. The changes one can buy and the launch checks are
 * /api/advice's. */
static void api_verdict(serve_server *s, const cJSON *req, serve_response *out)
{
    static const char *const keys[] = {"design", NULL};
    if (tippe_serve_request_keys(req, keys, out))
        return;
    tippe_design *d = tippe_serve_request_design(s, req, "design", "design", out);
    if (!d)
        return;
    tippe_build_options o;
    char cat[4096 + 32];
    sheet_options(d, &o, cat, sizeof cat);
    tippe_build_sheet *sheet = malloc(sizeof *sheet);
    tippe_error err = {0};
    int rc = sheet ? tippe_build_compute_verdict(d, &o, sheet, &err)
                   : tippe_error_set(&err, TIPPE_ECOMPUTE, "out of memory");
    tippe_design_free(d);
    if (rc)
        tippe_serve_respond_error(out, rc == TIPPE_EINPUT ? 400 : 500, "design", "%s", err.msg);
    else
        tippe_serve_respond_json(out, 200, verdict_json(sheet));
    free(sheet);
}

/* ---- the advice's answers, kept per design text (an edit undone, or the
 * same design opened again, costs nothing) ---- */
/* 32 designs (a page's recent edits, or several pages'); a design text over 64 KiB (a
 * design file is a few) is not kept, so that the cache stays under 32 x 64 KiB of keys. */
enum { ADVICE_CACHE = 32, ADVICE_KEY_MAX = 64 << 10 };
static struct {
    char *key;    /* the design's text (a shipped one's name) */
    char *answer; /* the JSON answered */
    size_t len;
} advice_cache[ADVICE_CACHE];
static int advice_next;
static pthread_mutex_t advice_lock = PTHREAD_MUTEX_INITIALIZER;

/* A copy of the answer kept for key, or NULL. */
static char *advice_find(const char *key, size_t *len)
{
    char *copy = NULL;
    pthread_mutex_lock(&advice_lock);
    for (int i = 0; i < ADVICE_CACHE && !copy; i++)
        if (advice_cache[i].key && !strcmp(advice_cache[i].key, key) &&
            (copy = malloc(advice_cache[i].len + 1))) {
            memcpy(copy, advice_cache[i].answer, advice_cache[i].len + 1);
            *len = advice_cache[i].len;
        }
    pthread_mutex_unlock(&advice_lock);
    return copy;
}

static void advice_keep(const char *key, const char *answer, size_t len)
{
    if (strlen(key) > ADVICE_KEY_MAX)
        return;
    char *k = strdup(key), *a = malloc(len + 1);
    if (!k || !a) {
        free(k);
        free(a);
        return;
    }
    memcpy(a, answer, len + 1);
    pthread_mutex_lock(&advice_lock);
    const int i = advice_next++ % ADVICE_CACHE;
    free(advice_cache[i].key);
    free(advice_cache[i].answer);
    advice_cache[i].key = k;
    advice_cache[i].answer = a;
    advice_cache[i].len = len;
    pthread_mutex_unlock(&advice_lock);
}

void tippe_serve_advice_forget(void)
{
    pthread_mutex_lock(&advice_lock);
    for (int i = 0; i < ADVICE_CACHE; i++) {
        free(advice_cache[i].key);
        free(advice_cache[i].answer);
        advice_cache[i].key = advice_cache[i].answer = NULL;
    }
    pthread_mutex_unlock(&advice_lock);
}

/* What the whole sheet says beside its verdict, with tippe build --json's names and
 * values: whether the model holds at the poles the launch checks stand on, the poles'
 * openings and fixes (with their --set lines), the warnings, the notes, the changes that
 * make it settable (with their --set lines) and each setting's
 * launch check as the sheet's table words it ("launch_checks": behaviour, text). 0, or
 * -1 when out of memory. */
static int sheet_extras(const tippe_build_sheet *sheet, cJSON *o)
{
    static const char *const keep[] = {"model_holds_at_poles", "polar_caps", "pole_fixes",
                                       "warnings", "notes", "to_make_it_settable", NULL};
    cJSON *whole = tippe_build_json(sheet);
    if (!whole)
        return -1;
    for (int k = 0; keep[k]; k++) {
        cJSON *x = cJSON_DetachItemFromObjectCaseSensitive(whole, keep[k]);
        if (x && !cJSON_AddItemToObject(o, keep[k], x)) {
            cJSON_Delete(x);
            cJSON_Delete(whole);
            return -1;
        }
    }
    cJSON_Delete(whole);
    cJSON *checks = cJSON_AddArrayToObject(o, "launch_checks");
    for (int f = 0; checks && f < 3; f++) {
        if (!sheet->set[f].reachable)
            continue;
        char text[400];
        tippe_build_launch_text(sheet, f, text, sizeof text);
        cJSON *e = cJSON_CreateObject();
        if (!e || !cJSON_AddItemToArray(checks, e) ||
            !cJSON_AddStringToObject(e, "behaviour", tippe_build_behaviour(f)) ||
            !cJSON_AddStringToObject(e, "text", text))
            return -1;
    }
    return checks ? 0 : -1;
}

/* POST /api/advice {design}: what the whole build sheet adds to the verdict: the
 * verdict's text with the launch checks (where a hole's opening at a pole undoes
 * it), the changes one can buy when it is not settable ("advice"), and the
 * verdict itself (the same as /api/verdict's). It costs what tippe build's sheet
 * costs (its launches and the changes tried, each a sweep), once per design text:
 * answers are kept for the last 32 designs. */
static void api_advice(serve_server *s, const cJSON *req, serve_response *out)
{
    static const char *const keys[] = {"design", NULL};
    if (tippe_serve_request_keys(req, keys, out))
        return;
    const cJSON *given = cJSON_GetObjectItemCaseSensitive(req, "design");
    char *key = cJSON_PrintUnformatted(given);
    size_t len = 0;
    char *kept = key ? advice_find(key, &len) : NULL;
    if (kept) {
        tippe_serve_response_free(out);
        out->status = 200;
        out->type = "application/json";
        out->body = kept;
        out->len = len;
        free(key);
        return;
    }
    tippe_design *d = tippe_serve_request_design(s, req, "design", "design", out);
    if (!d) {
        free(key);
        return;
    }
    tippe_build_options o;
    char cat[4096 + 32];
    sheet_options(d, &o, cat, sizeof cat);
    tippe_build_sheet *sheet = malloc(sizeof *sheet);
    tippe_error err = {0};
    int rc = sheet ? tippe_build_compute(d, &o, sheet, &err)
                   : tippe_error_set(&err, TIPPE_ECOMPUTE, "out of memory");
    tippe_design_free(d);
    cJSON *o_json = rc ? NULL : verdict_json(sheet);
    cJSON *advice = o_json ? cJSON_AddArrayToObject(o_json, "advice") : NULL;
    for (int k = 0; advice && !sheet->settable && k < sheet->n_advice; k++)
        if (!cJSON_AddItemToArray(advice, cJSON_CreateString(sheet->advice[k].text)))
            advice = NULL;
    if (advice && sheet_extras(sheet, o_json))
        advice = NULL;
    free(sheet);
    if (rc) {
        tippe_serve_respond_error(out, rc == TIPPE_EINPUT ? 400 : 500, "design", "%s", err.msg);
    } else if (!advice) {
        cJSON_Delete(o_json);
        tippe_serve_respond_error(out, 503, NULL, "out of memory");
    } else {
        tippe_serve_respond_json(out, 200, o_json);
        if (key && out->status == 200)
            advice_keep(key, out->body, out->len);
    }
    free(key);
}

const serve_route tippe_serve_routes[] = {
    {"/api/sweep", 1, SERVE_LANE_SHARED, api_sweep, 0},
    {"/api/eval", 1, SERVE_LANE_SHARED, api_eval, 0},
    {"/api/compare", 1, SERVE_LANE_SHARED, api_compare, 0},
    {"/api/check", 1, SERVE_LANE_SHARED, api_check, 0},
    {"/api/build", 1, SERVE_LANE_EXCLUSIVE, api_build, 0},
    {"/api/verdict", 1, SERVE_LANE_SHARED, api_verdict, 0},
    {"/api/advice", 1, SERVE_LANE_ADVICE, api_advice, 0},
    {"/api/animate", 1, SERVE_LANE_EXCLUSIVE, api_animate, 0},
    {"/api/gcode", 1, SERVE_LANE_EXCLUSIVE, tippe_serve_api_gcode, 1},
    {"/api/section", 1, SERVE_LANE_EXCLUSIVE, tippe_serve_api_section, 0},
    {NULL, 0, 0, NULL, 0},
};

const serve_route *tippe_serve_find_route(const char *path)
{
    for (const serve_route *r = tippe_serve_routes; r->path; r++)
        if (!strcmp(r->path, path))
            return r;
    return NULL;
}
