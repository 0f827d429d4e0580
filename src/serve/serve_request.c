/* A request's JSON, read strictly: its nesting is bounded before cJSON sees it,
 * unknown fields and wrong types are refused with the field's name, numbers are
 * checked against their range, and a design is loaded from memory with the
 * shipped materials table. Every refusal is a 400 JSON error. */
#include "serve/internal.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The deepest nesting of [ and { in a JSON text (outside strings), stopping
 * once it passes limit: cJSON recurses per level. */
static int nesting_exceeds(const char *text, size_t len, int limit)
{
    int depth = 0, in_string = 0;
    for (size_t i = 0; i < len; i++) {
        const char c = text[i];
        if (in_string) {
            if (c == '\\')
                i++;
            else if (c == '"')
                in_string = 0;
        } else if (c == '"') {
            in_string = 1;
        } else if (c == '[' || c == '{') {
            if (++depth > limit)
                return 1;
        } else if (c == ']' || c == '}') {
            depth--;
        }
    }
    return 0;
}

/* Whether a string of the JSON text holds the escape \u0000: cJSON would end
 * the string there (C strings), so that the text checked is not the text sent. */
static int has_escaped_nul(const char *text, size_t len)
{
    int in_string = 0;
    for (size_t i = 0; i < len; i++) {
        const char c = text[i];
        if (!in_string) {
            in_string = c == '"';
        } else if (c == '\\') {
            if (i + 5 < len && text[i + 1] == 'u' && !memcmp(text + i + 2, "0000", 4))
                return 1;
            i++;
        } else if (c == '"') {
            in_string = 0;
        }
    }
    return 0;
}

/* A number beyond a double (1e999 reads as infinity, which cJSON would print as
 * null, so that the design's loader said "not null"): refused with its path. */
static int non_finite(const cJSON *v, char *path, size_t size, size_t at)
{
    if (cJSON_IsNumber(v))
        return !isfinite(v->valuedouble);
    int i = 0;
    for (const cJSON *k = v->child; k; k = k->next, i++) {
        if (at < size) {
            if (k->string)
                snprintf(path + at, size - at, "%s%s", at ? "." : "", k->string);
            else
                snprintf(path + at, size - at, "[%d]", i);
        }
        size_t next = strlen(path);
        if (non_finite(k, path, size, next))
            return 1;
        path[at < size ? at : size - 1] = '\0';
    }
    return 0;
}

cJSON *tippe_serve_request_parse(const char *body, size_t len, serve_response *out)
{
    if (!body || len == 0) {
        tippe_serve_respond_error(out, 400, NULL, "the request has no body: send a JSON object");
        return NULL;
    }
    if (memchr(body, '\0', len)) {
        tippe_serve_respond_error(out, 400, NULL, "the body contains a NUL byte: not a JSON text");
        return NULL;
    }
    if (has_escaped_nul(body, len)) {
        tippe_serve_respond_error(out, 400, NULL,
                                  "a string contains \\u0000 (a NUL character): no field takes "
                                  "one");
        return NULL;
    }
    if (nesting_exceeds(body, len, TIPPE_SERVE_MAX_DEPTH)) {
        tippe_serve_respond_error(out, 400, NULL,
                            "the JSON is nested more than %d levels deep (a design needs 4)",
                            TIPPE_SERVE_MAX_DEPTH);
        return NULL;
    }
    char *text = malloc(len + 1);
    if (!text) {
        tippe_serve_respond_error(out, 503, NULL, "out of memory");
        return NULL;
    }
    memcpy(text, body, len);
    text[len] = '\0';
    const char *end = NULL;
    cJSON *root = cJSON_ParseWithOpts(text, &end, 1);
    if (!root) {
        size_t at = end && end >= text ? (size_t)(end - text) : 0;
        tippe_serve_respond_error(out, 400, NULL, "not valid JSON (at byte %zu of %zu)", at, len);
        free(text);
        return NULL;
    }
    free(text);
    if (!cJSON_IsObject(root)) {
        tippe_serve_respond_error(out, 400, NULL, "the body must be a JSON object, not %s",
                            cJSON_IsArray(root) ? "an array" : "a single value");
        cJSON_Delete(root);
        return NULL;
    }
    char path[400] = "";
    if (non_finite(root, path, sizeof path, 0)) {
        tippe_serve_respond_error(out, 400, path,
                                  "%s: not a finite number (beyond a double's range, "
                                  "1.8e308)", path);
        cJSON_Delete(root);
        return NULL;
    }
    return root;
}

int tippe_serve_request_keys(const cJSON *req, const char *const *allowed, serve_response *out)
{
    for (const cJSON *k = req->child; k; k = k->next) {
        int ok = 0;
        for (const char *const *a = allowed; *a && !ok; a++)
            ok = !strcmp(k->string, *a);
        if (!ok) {
            char list[512] = "";
            size_t n = 0;
            for (const char *const *a = allowed; *a && n < sizeof list; a++)
                n += (size_t)snprintf(list + n, sizeof list - n, "%s%s", n ? ", " : "", *a);
            tippe_serve_respond_error(out, 400, k->string,
                                "%.100s: unknown field (this request takes: %s)", k->string,
                                list);
            return -1;
        }
        for (const cJSON *o = req->child; o != k; o = o->next)
            if (!strcmp(o->string, k->string)) {
                tippe_serve_respond_error(out, 400, k->string, "%.100s: given twice", k->string);
                return -1;
            }
    }
    return 0;
}

static const char *kind(const cJSON *v)
{
    if (cJSON_IsString(v))
        return "a string";
    if (cJSON_IsNumber(v))
        return "a number";
    if (cJSON_IsBool(v))
        return "true/false";
    if (cJSON_IsNull(v))
        return "null";
    if (cJSON_IsArray(v))
        return "an array";
    return "an object";
}

int tippe_serve_request_number(const cJSON *req, const char *key, double min, double max,
                         int required, double *v, serve_response *out)
{
    const cJSON *x = cJSON_GetObjectItemCaseSensitive(req, key);
    if (!x) {
        if (!required)
            return 0;
        tippe_serve_respond_error(out, 400, key, "%s: missing (a number in %g .. %g)", key, min, max);
        return -1;
    }
    if (!cJSON_IsNumber(x)) {
        tippe_serve_respond_error(out, 400, key, "%s: must be a number, not %s", key, kind(x));
        return -1;
    }
    if (!isfinite(x->valuedouble) || x->valuedouble < min || x->valuedouble > max) {
        tippe_serve_respond_error(out, 400, key, "%s: %g is outside %g .. %g", key, x->valuedouble,
                            min, max);
        return -1;
    }
    *v = x->valuedouble;
    return 0;
}

int tippe_serve_request_word(const cJSON *req, const char *key, const char *const *words, int def,
                       serve_response *out)
{
    const cJSON *x = cJSON_GetObjectItemCaseSensitive(req, key);
    char list[256] = "";
    size_t n = 0;
    for (const char *const *w = words; *w && n < sizeof list; w++)
        n += (size_t)snprintf(list + n, sizeof list - n, "%s%s", n ? ", " : "", *w);
    if (!x) {
        if (def >= 0)
            return def;
        tippe_serve_respond_error(out, 400, key, "%s: missing (one of %s)", key, list);
        return -1;
    }
    if (!cJSON_IsString(x)) {
        tippe_serve_respond_error(out, 400, key, "%s: must be a string (one of %s), not %s", key, list,
                            kind(x));
        return -1;
    }
    for (int i = 0; words[i]; i++)
        if (!strcmp(x->valuestring, words[i]))
            return i;
    tippe_serve_respond_error(out, 400, key, "%s: '%.60s' is not one of %s", key, x->valuestring,
                        list);
    return -1;
}

const serve_design *tippe_serve_find_design(const serve_server *s, const char *name)
{
    for (int i = 0; i < s->n_designs; i++)
        if (!strcmp(s->designs[i].name, name))
            return &s->designs[i];
    return NULL;
}

tippe_design *tippe_serve_request_design(serve_server *s, const cJSON *req, const char *key,
                                         const char *stem, serve_response *out)
{
    const char *name = stem ? stem : key;
    const cJSON *x = cJSON_GetObjectItemCaseSensitive(req, key);
    if (!x) {
        tippe_serve_respond_error(out, 400, key,
                            "%s: missing (a design: the content of a design file, or the name "
                            "of a shipped design)", key);
        return NULL;
    }
    char *text = NULL;
    size_t len = 0;
    const serve_design *shipped = NULL;
    if (cJSON_IsString(x)) {
        /* a name, never a path: only the shipped designs, by their stems */
        if (!(shipped = tippe_serve_find_design(s, x->valuestring))) {
            tippe_serve_respond_error(out, 400, key,
                                "%s: '%.80s' is not a shipped design (GET /api/designs lists "
                                "them; send a design's content to use another)",
                                key, x->valuestring);
            return NULL;
        }
    } else if (cJSON_IsObject(x)) {
        if (!(text = cJSON_PrintUnformatted(x))) {
            tippe_serve_respond_error(out, 503, NULL, "out of memory");
            return NULL;
        }
        len = strlen(text);
    } else {
        tippe_serve_respond_error(out, 400, key,
                            "%s: must be an object (a design) or a shipped design's name, not %s",
                            key, kind(x));
        return NULL;
    }
    /* a part's "print": {"gcode": "upload:ID"}: an uploaded G-code, kept by the server
     * (serve_gcode.c), read in memory; any other G-code names a file and is refused */
    tippe_design_gcode *gcodes = NULL;
    int n_gcodes = 0;
    const cJSON *parts = cJSON_IsObject(x) ? cJSON_GetObjectItemCaseSensitive(x, "parts") : NULL;
    int i = 0;
    for (const cJSON *p = cJSON_IsArray(parts) ? parts->child : NULL; p; p = p->next, i++) {
        const cJSON *pr = cJSON_IsObject(p) ? cJSON_GetObjectItemCaseSensitive(p, "print") : NULL;
        const cJSON *g = cJSON_IsObject(pr) ? cJSON_GetObjectItemCaseSensitive(pr, "gcode") : NULL;
        const cJSON *pn = cJSON_GetObjectItemCaseSensitive(p, "name");
        if (!cJSON_IsString(g) || strncmp(g->valuestring, "upload:", 7) || !cJSON_IsString(pn))
            continue;
        tippe_design_gcode *more = realloc(gcodes, (size_t)(n_gcodes + 1) * sizeof *gcodes);
        if (!more) {
            for (int k = 0; k < n_gcodes; k++)
                tippe_gcode_beads_free(&gcodes[k].beads);
            free(gcodes);
            free(text);
            tippe_serve_respond_error(out, 503, NULL, "out of memory");
            return NULL;
        }
        gcodes = more;
        char gname[128];
        /* the part's filament diameter reads it, as the command reads a file (Cura's E) */
        const cJSON *fd = cJSON_GetObjectItemCaseSensitive(pr, "filament_diameter_mm");
        tippe_error gerr = {0};
        int found = tippe_serve_gcode_find(g->valuestring + 7,
                                           cJSON_IsNumber(fd) ? fd->valuedouble : 0,
                                           &gcodes[n_gcodes].body, &gcodes[n_gcodes].beads,
                                           gname, sizeof gname, &gerr);
        if (found <= 0) {
            for (int k = 0; k < n_gcodes; k++)
                tippe_gcode_beads_free(&gcodes[k].beads);
            free(gcodes);
            free(text);
            char field[96];
            snprintf(field, sizeof field, "%s.parts[%d].print.gcode", key, i);
            if (found < 0)
                tippe_serve_respond_error(out, gerr.code == TIPPE_EINPUT ? 400 : 503, field,
                                          "%s: parts[%d].print.gcode: the uploaded G-code "
                                          "'%.40s' read with print.filament_diameter_mm: %s",
                                          key, i, gname, gerr.msg);
            else
                tippe_serve_respond_error(out, 400, field, "%s: parts[%d].print.gcode: the "
                                          "uploaded G-code '%.40s' is not kept any more (the "
                                          "server keeps the last 8, 128 MiB): upload it again",
                                          key, i, g->valuestring);
            return NULL;
        }
        snprintf(gcodes[n_gcodes].part, sizeof gcodes[n_gcodes].part, "%s", pn->valuestring);
        n_gcodes++;
    }
    tippe_error err = {0};
    tippe_design *d = NULL;
    int rc = tippe_design_load_text_gcode(name, shipped ? shipped->text : text,
                                          shipped ? shipped->len : len, s->designs_dir, gcodes,
                                          n_gcodes, NULL, 0, &d, &err);
    for (int k = 0; k < n_gcodes; k++)
        tippe_gcode_beads_free(&gcodes[k].beads);
    free(gcodes);
    free(text);
    if (rc) {
        /* the server's folders are nobody's business: its designs folder is "designs/" */
        const size_t dl = strlen(s->designs_dir);
        for (char *at = err.msg; dl > 7 && (at = strstr(at, s->designs_dir)) != NULL; at += 7) {
            memmove(at + 7, at + dl, strlen(at + dl) + 1); /* shorter: stays in msg */
            memcpy(at, "designs", 7);
        }
        /* the loader names the field (err.field, "parts[0].radius_mm") of the design's
         * own text ("design: parts[0].radius_mm: ..."; not of the materials table's) */
        char field[160] = "";
        const size_t klen = strlen(name);
        const int own = !strncmp(err.msg, name, klen) && !strncmp(err.msg + klen, ": ", 2);
        if (own && err.field[0] && strlen(err.field) < sizeof field - strlen(key) - 2) {
            snprintf(field, sizeof field, "%s.%s", key, err.field);
        } else if (own) {
            /* the checks of design/ that set their message by hand name the path only in
             * it ("design: parts[0].material: ..."), until they set err.field too */
            const char *f = err.msg + klen + 2, *colon = strstr(f, ": ");
            if (colon && (size_t)(colon - f) < sizeof field - strlen(key) - 2 &&
                !memchr(f, ' ', (size_t)(colon - f)))
                snprintf(field, sizeof field, "%s.%.*s", key, (int)(colon - f), f);
        }
        tippe_serve_respond_error(out, rc == TIPPE_EINPUT ? 400 : 500, field[0] ? field : key, "%s",
                            err.msg);
        return NULL;
    }
    return d;
}

int tippe_serve_request_stem(const cJSON *req, const char *key, char *stem, size_t size,
                             serve_response *out)
{
    const cJSON *x = cJSON_GetObjectItemCaseSensitive(req, key);
    if (!x)
        return 0;
    const char *v = cJSON_IsString(x) ? x->valuestring : NULL;
    size_t n = v ? strlen(v) : 0;
    int ok = n >= 1 && n < size && n <= 64;
    for (size_t i = 0; ok && i < n; i++)
        ok = (v[i] >= 'a' && v[i] <= 'z') || (v[i] >= 'A' && v[i] <= 'Z') ||
             (v[i] >= '0' && v[i] <= '9') || v[i] == '-' || v[i] == '_';
    if (!ok) {
        tippe_serve_respond_error(out, 400, key,
                                  "%s: a name for the files: 1 to 64 letters, digits, '-' or "
                                  "'_' (it never names a file of the server)", key);
        return -1;
    }
    snprintf(stem, size, "%s", v);
    return 0;
}
