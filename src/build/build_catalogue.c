/* The hardware catalogue (designs/catalogue.json), read strictly as designs
 * are (src/base/json.h): every message names the file, the JSON path and what
 * is wrong, and an item holds a thread that can be made (see tippe/build.h). */
#include "tippe/build.h"
#include "base/json.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const char *const set_keys[] = {"title", "source", "notes", "items", NULL};
static const char *const item_keys[] = {"name",      "thread",    "d_mm",
                                        "pitch_mm",  "length_mm", "radius_mm",
                                        "height_mm", "socket_s_mm", "socket_t_mm", NULL};

/* A catalogue is a few kB; a larger file is not one. */
enum { MAX_CATALOGUE_MIB = 16 };

/* obj.key, a length in mm within (0, max]: required or, if absent, NAN. */
static int length(const tippe_json_reader *r, const cJSON *obj, const char *path,
                  const char *key, int required, double max_mm, double *out)
{
    int present = 0;
    *out = NAN;
    int rc = tippe_json_number(r, obj, path, key, required, out, &present);
    if (rc || !present)
        return rc;
    char p[256];
    tippe_json_path(p, sizeof p, path, key);
    if (!(*out > 0))
        return tippe_json_fail(r, p, "must be positive (a length in mm), got %g", *out);
    if (*out > max_mm)
        return tippe_json_fail(r, p, "%g mm is longer than any screw of a tippe top (at most "
                                     "%g mm)", *out, max_mm);
    return TIPPE_OK;
}

/* The thread of item (at path) can be made: ISO 261's diameters and pitches,
 * and a pitch no coarser than a quarter of the diameter (so the tap drill,
 * d - P, is at least three quarters of d). */
static int check_thread(const tippe_json_reader *r, const char *path,
                        const tippe_build_catalogue_item *it)
{
    char p[256];
    tippe_json_path(p, sizeof p, path, "d_mm");
    if (it->d_mm < TIPPE_BUILD_THREAD_D_MIN_MM || it->d_mm > TIPPE_BUILD_THREAD_D_MAX_MM)
        return tippe_json_fail(r, p,
                               "%g mm is not a metric thread's diameter (ISO 261: %g .. %g mm)",
                               it->d_mm, TIPPE_BUILD_THREAD_D_MIN_MM,
                               TIPPE_BUILD_THREAD_D_MAX_MM);
    tippe_json_path(p, sizeof p, path, "pitch_mm");
    double most = fmin(TIPPE_BUILD_THREAD_PITCH_MAX_MM, it->d_mm / 4);
    if (it->pitch_mm < TIPPE_BUILD_THREAD_PITCH_MIN_MM || it->pitch_mm > most) {
        char drill[96] = "";
        if (it->pitch_mm > most)
            snprintf(drill, sizeof drill, "; its tap drill d - P would be %g mm",
                     it->d_mm - it->pitch_mm);
        return tippe_json_fail(
            r, p,
            "%g mm is not the pitch of a thread of d_mm = %g mm: ISO 261's pitches are %g .. %g "
            "mm and at most a quarter of the diameter (the coarse M1 x 0.25), so %g .. %g mm "
            "here%s",
            it->pitch_mm, it->d_mm, TIPPE_BUILD_THREAD_PITCH_MIN_MM,
            TIPPE_BUILD_THREAD_PITCH_MAX_MM, TIPPE_BUILD_THREAD_PITCH_MIN_MM, most, drill);
    }
    /* "M10" must be the thread of d_mm = 10 */
    char *end = NULL;
    double named = it->thread[0] == 'M' ? strtod(it->thread + 1, &end) : NAN;
    if (end && end != it->thread + 1 && (*end == '\0' || *end == 'x' || *end == ' ') &&
        fabs(named - it->d_mm) > 1e-9) {
        tippe_json_path(p, sizeof p, path, "thread");
        return tippe_json_fail(r, p, "'%s' is not the thread of d_mm = %g mm", it->thread,
                               it->d_mm);
    }
    /* the screw as modelled: a cylinder no wider than the thread */
    if (it->radius_mm > it->d_mm / 2) {
        tippe_json_path(p, sizeof p, path, "radius_mm");
        return tippe_json_fail(r, p,
                               "%g mm is wider than the thread (d_mm / 2 = %g mm): the screw is "
                               "modelled as a cylinder of its pitch diameter",
                               it->radius_mm, it->d_mm / 2);
    }
    if (!isnan(it->socket_s_mm) && !(it->socket_s_mm < it->d_mm)) {
        tippe_json_path(p, sizeof p, path, "socket_s_mm");
        return tippe_json_fail(r, p, "%g mm: a socket is narrower than the thread (d_mm %g mm)",
                               it->socket_s_mm, it->d_mm);
    }
    return TIPPE_OK;
}

static int read_item(const tippe_json_reader *r, const cJSON *obj, const char *path,
                     tippe_build_catalogue_item *it)
{
    if (!cJSON_IsObject(obj))
        return tippe_json_wrong_type(r, path, "an object (a catalogue item)", obj);
    int rc;
    if ((rc = tippe_json_check_keys(r, obj, path, "a catalogue item", item_keys, NULL)) ||
        (rc = tippe_json_string(r, obj, path, "name", 1, it->name, sizeof it->name, NULL)) ||
        (rc = tippe_json_string(r, obj, path, "thread", 1, it->thread, sizeof it->thread,
                                NULL)) ||
        (rc = tippe_json_number(r, obj, path, "d_mm", 1, &it->d_mm, NULL)) ||
        (rc = tippe_json_number(r, obj, path, "pitch_mm", 1, &it->pitch_mm, NULL)) ||
        (rc = length(r, obj, path, "radius_mm", 1, TIPPE_BUILD_THREAD_D_MAX_MM / 2,
                     &it->radius_mm)) ||
        (rc = length(r, obj, path, "height_mm", 1, TIPPE_BUILD_SCREW_MAX_MM, &it->height_mm)) ||
        (rc = length(r, obj, path, "length_mm", 0, TIPPE_BUILD_SCREW_MAX_MM, &it->length_mm)) ||
        (rc = length(r, obj, path, "socket_s_mm", 0, TIPPE_BUILD_THREAD_D_MAX_MM,
                     &it->socket_s_mm)) ||
        (rc = length(r, obj, path, "socket_t_mm", 0, TIPPE_BUILD_SCREW_MAX_MM,
                     &it->socket_t_mm)))
        return rc;
    char p[256];
    if (!it->name[0]) {
        tippe_json_path(p, sizeof p, path, "name");
        return tippe_json_fail(r, p, "must not be empty");
    }
    return check_thread(r, path, it);
}

static int read_set(const tippe_json_reader *r, const cJSON *obj, tippe_build_catalogue_set *s)
{
    const char *key = obj->string;
    int rc;
    if ((rc = tippe_json_check_text(r, key, key, 0)))
        return rc;
    if (strlen(key) >= sizeof s->key)
        return tippe_json_fail(r, key, "a catalogue's name is at most %zu characters",
                               sizeof s->key - 1);
    snprintf(s->key, sizeof s->key, "%s", key);
    if (!cJSON_IsObject(obj))
        return tippe_json_wrong_type(r, key, "an object (a catalogue: title, source, notes, "
                                             "items)", obj);
    if ((rc = tippe_json_check_keys(r, obj, key, "a catalogue", set_keys, NULL)) ||
        (rc = tippe_json_string(r, obj, key, "title", 0, s->title, sizeof s->title, NULL)) ||
        (rc = tippe_json_string(r, obj, key, "source", 0, NULL, 0, NULL)) ||
        (rc = tippe_json_text(r, obj, key, "notes", 0, NULL, 0, NULL)))
        return rc;
    if (!s->title[0])
        snprintf(s->title, sizeof s->title, "%s", key);
    char p[256];
    tippe_json_path(p, sizeof p, key, "items");
    const cJSON *items = cJSON_GetObjectItemCaseSensitive(obj, "items");
    if (!items)
        return tippe_json_fail(r, p, "missing (required: an array of items)");
    if (!cJSON_IsArray(items))
        return tippe_json_wrong_type(r, p, "an array of items", items);
    int n = cJSON_GetArraySize(items);
    if (n < 1)
        return tippe_json_fail(r, p, "must hold at least one item");
    if (!(s->items = calloc((size_t)n, sizeof *s->items)))
        return tippe_error_set(r->err, TIPPE_ECOMPUTE, "out of memory");
    int i = 0;
    for (const cJSON *it = items->child; it; it = it->next, i++) {
        char ip[300];
        snprintf(ip, sizeof ip, "%s[%d]", p, i);
        s->n_items = i + 1;
        if ((rc = read_item(r, it, ip, &s->items[i])))
            return rc;
        for (int j = 0; j < i; j++)
            if (!strcmp(s->items[j].name, s->items[i].name)) {
                char np[320];
                snprintf(np, sizeof np, "%s.name", ip);
                return tippe_json_fail(r, np, "'%s' is already the name of %s[%d]: names must "
                                              "be unique", s->items[i].name, p, j);
            }
    }
    return TIPPE_OK;
}

/* A design names its catalogue, or keeps one beside it as the shipped designs
 * do (designs/catalogue.json); one that reads the shipped materials table for want
 * of its own reads the shipped catalogue beside it (a design saved from tippe serve's
 * page then gets the page's advice); an absent default is no catalogue, not an error
 * (a design without catalogue screws needs none). */
const char *tippe_build_catalogue_file(const tippe_design *d, char *buf, size_t size)
{
    const int fits = tippe_design_beside(d, "catalogue.json", buf, size) == TIPPE_OK;
    if (tippe_design_catalogue(d))
        return tippe_design_catalogue(d);
    if (fits && access(buf, R_OK) == 0)
        return buf;
    /* buf keeps the path beside the design unless the shipped one is used (build.h) */
    char shipped[4096 + 32];
    if (tippe_design_shipped_catalogue(d, shipped, sizeof shipped) && strlen(shipped) < size) {
        snprintf(buf, size, "%s", shipped);
        return buf;
    }
    return NULL;
}

int tippe_build_catalogue_load(const char *path, tippe_build_catalogue **out, tippe_error *err)
{
    *out = NULL;
    tippe_json_reader *r = tippe_json_reader_new(path, err, TIPPE_JSON_WORDS_FIELD, NULL);
    if (!r)
        return TIPPE_ECOMPUTE;
    cJSON *root = NULL;
    tippe_build_catalogue *c = NULL;
    int rc = tippe_json_load(r, MAX_CATALOGUE_MIB, "catalogue", &root);
    if (!rc)
        rc = tippe_json_check_duplicates(r, root, "");
    if (!rc && !cJSON_IsObject(root))
        rc = tippe_json_wrong_type(r, NULL, "an object of named catalogues", root);
    if (!rc && cJSON_GetArraySize(root) < 1)
        rc = tippe_json_fail(r, NULL, "holds no catalogue (an object of named catalogues, "
                                      "each with its items)");
    if (!rc && !(c = calloc(1, sizeof *c)))
        rc = tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    if (!rc && !(c->sets = calloc((size_t)cJSON_GetArraySize(root), sizeof *c->sets)))
        rc = tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    if (!rc)
        snprintf(c->file, sizeof c->file, "%s", path);
    for (const cJSON *s = root && !rc ? root->child : NULL; s && !rc; s = s->next)
        rc = read_set(r, s, &c->sets[c->n_sets++]);
    cJSON_Delete(root);
    free(r);
    if (rc) {
        tippe_build_catalogue_free(c);
        return rc;
    }
    *out = c;
    return TIPPE_OK;
}

void tippe_build_catalogue_free(tippe_build_catalogue *c)
{
    if (!c)
        return;
    for (int k = 0; k < c->n_sets; k++)
        free(c->sets[k].items);
    free(c->sets);
    free(c);
}

/* Half the IT15 tolerance of a length (ISO 286-1, Table 1): ISO 4026's set screws are
 * product grade A, whose lengths are js15 (ISO 4759-1, Table 1). */
static double js15_mm(double length_mm)
{
    static const struct {
        double up_to_mm, it15_mm;
    } it15[] = {{3, 0.40}, {6, 0.48}, {10, 0.58}, {18, 0.70}, {30, 0.84}, {50, 1.00},
                {80, 1.20}, {120, 1.40}, {180, 1.60}, {250, 1.85}, {315, 2.10}, {400, 2.30},
                {500, 2.50}, {630, 2.80}, {800, 3.20}, {1000, 3.60}};
    for (size_t k = 0; k < sizeof it15 / sizeof *it15; k++)
        if (length_mm <= it15[k].up_to_mm)
            return it15[k].it15_mm / 2;
    return 3.6 / 2;
}

const tippe_build_catalogue_item *tippe_build_catalogue_match(const tippe_build_catalogue *c,
                                                              double radius_mm, double height_mm,
                                                              const tippe_build_catalogue_set **set)
{
    /* the item modelled as the part is, else (issue 37) the thread the part's radius can
     * be: from the item's pitch radius (as the catalogue models it) to its nominal d/2 (as
     * design-format.md writes a set screw, the radius of its hole), and a length within
     * the item's js15 */
    for (int pass = 0; pass < 2; pass++)
        for (int k = 0; c && k < c->n_sets; k++)
            for (int i = 0; i < c->sets[k].n_items; i++) {
                const tippe_build_catalogue_item *it = &c->sets[k].items[i];
                const int ok =
                    pass == 0 ? fabs(it->radius_mm - radius_mm) <= 1e-6 &&
                                    fabs(it->height_mm - height_mm) <= 1e-6
                              : radius_mm >= it->radius_mm - 1e-6 &&
                                    radius_mm <= it->d_mm / 2 + 1e-6 &&
                                    fabs(it->height_mm - height_mm) <= js15_mm(it->height_mm);
                if (ok) {
                    if (set)
                        *set = &c->sets[k];
                    return it;
                }
            }
    return NULL;
}

const tippe_build_catalogue_item *tippe_build_catalogue_find(const tippe_build_catalogue *c,
                                                             const char *name,
                                                             const tippe_build_catalogue_set **set)
{
    for (int k = 0; c && name && k < c->n_sets; k++)
        for (int i = 0; i < c->sets[k].n_items; i++)
            if (!strcmp(c->sets[k].items[i].name, name)) {
                if (set)
                    *set = &c->sets[k];
                return &c->sets[k].items[i];
            }
    return NULL;
}
