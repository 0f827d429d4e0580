/* Overrides (--set FIELD=VALUE) applied to a parsed design file, and design
 * sources: a design parsed once and derived many times (the optimiser, sweeps of
 * a field, the tolerance bands). */
#include "design/design_internal.h"

#include <cjson/cJSON.h>
#include <gsl/gsl_errno.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------------------------- overrides */

/* The index of the part "parts.NAME" or "parts[I]" (field, already cut
 * before its last dot) names in the file's parts array; -1 with the error set. */
static int override_part_index(tippe_json_reader *c, const cJSON *parts, const char *field,
                               const char *text)
{
    if (field[5] == '[') {
        char *endp = NULL;
        long i = strtol(field + 6, &endp, 10);
        if (!endp || endp == field + 6 || strcmp(endp, "]") || i < 0 ||
            i >= cJSON_GetArraySize(parts)) {
            tippe_error_set(c->err, TIPPE_EINPUT,
                            "%s: --set %s: no such part index (the file has %d parts)", c->file,
                            text, cJSON_GetArraySize(parts));
            return -1;
        }
        return (int)i;
    }
    const char *want = field + 6;
    char names[512] = "";
    size_t n = 0;
    int i = 0, index = -1;
    for (const cJSON *p = parts->child; p; p = p->next, i++) {
        const cJSON *nm = cJSON_GetObjectItemCaseSensitive(p, "name");
        if (!cJSON_IsString(nm))
            continue;
        if (!strcmp(nm->valuestring, want) && index < 0)
            index = i;
        int w = snprintf(names + n, sizeof names - n, "%s%s", n ? ", " : "", nm->valuestring);
        if (w > 0 && (size_t)w < sizeof names - n)
            n += (size_t)w;
    }
    if (index < 0)
        tippe_error_set(c->err, TIPPE_EINPUT, "%s: --set %s: no part named '%s' (parts: %s)",
                        c->file, text, want, names);
    return index;
}

/* The print block of part object obj (index), for --set parts.NAME.print.KEY:
 * true, false or no block becomes an object (the defaults), then takes key. */
static int override_print_block(tippe_json_reader *c, cJSON **obj, int index, const char *key,
                                const char *text, char *path, size_t path_cap)
{
    if (!tippe_json_in_list(key, tippe_design_print_keys)) {
        char list[256];
        tippe_json_key_list(list, sizeof list, tippe_design_print_keys, NULL);
        return tippe_error_set(c->err, TIPPE_EINPUT,
                               "%s: --set %s: '%s' is not a print setting (settings: %s)",
                               c->file, text, key, list);
    }
    cJSON *pr = cJSON_GetObjectItemCaseSensitive(*obj, "print");
    if (!cJSON_IsObject(pr)) {
        cJSON *fresh = cJSON_CreateObject();
        if (!fresh)
            return tippe_error_set(c->err, TIPPE_ECOMPUTE, "out of memory");
        int rc = tippe_json_put(c, *obj, "print", fresh);
        if (rc)
            return rc;
        pr = fresh;
    }
    *obj = pr;
    snprintf(path, path_cap, "parts[%d].print.%s", index, key);
    return TIPPE_OK;
}

/* Where --set parts.NAME.KEY (or parts.NAME.print.KEY) writes: *obj, *key and
 * the JSON path for messages. field is modified (cut at its last dot). */
static int override_part_target(tippe_json_reader *c, cJSON *root, char *field, const char *text,
                                cJSON **obj, const char **key, char *path, size_t path_cap)
{
    cJSON *parts = cJSON_GetObjectItemCaseSensitive(root, "parts");
    if (!cJSON_IsArray(parts))
        return tippe_json_fail(c, "parts", "must be an array of parts (cannot apply --set %s)",
                               text);
    char *dot = strrchr(field, '.');
    if (!dot || dot < field + 6 || dot[1] == '\0')
        return tippe_error_set(c->err, TIPPE_EINPUT,
                               "%s: --set %s: expected parts.NAME.FIELD=VALUE", c->file, text);
    *dot = '\0';
    *key = dot + 1;
    size_t flen = strlen(field);
    int in_print = flen > 12 && !strcmp(field + flen - 6, ".print");
    if (in_print)
        field[flen - 6] = '\0';
    int index = override_part_index(c, parts, field, text);
    if (index < 0)
        return TIPPE_EINPUT;
    *obj = cJSON_GetArrayItem(parts, index);
    if (!cJSON_IsObject(*obj)) {
        snprintf(path, path_cap, "parts[%d]", index);
        return tippe_json_fail(c, path, "must be an object (cannot apply --set %s)", text);
    }
    if (in_print)
        return override_print_block(c, obj, index, *key, text, path, path_cap);
    if (!tippe_json_in_list(*key, tippe_design_all_part_keys)) {
        char list[512];
        tippe_json_key_list(list, sizeof list, tippe_design_all_part_keys, NULL);
        return tippe_error_set(c->err, TIPPE_EINPUT,
                               "%s: --set %s: '%s' is not a part field (fields: %s)", c->file,
                               text, *key, list);
    }
    snprintf(path, path_cap, "parts[%d].%s", index, *key);
    return TIPPE_OK;
}

int tippe_design_apply_override(tippe_json_reader *c, cJSON *root, const char *text)
{
    const char *eq = strchr(text, '=');
    if (!eq || eq == text)
        return tippe_error_set(c->err, TIPPE_EINPUT,
                               "%s: --set %s: expected FIELD=VALUE, e.g. parts.rod.material=nylon",
                               c->file, text);
    char field[256];
    size_t flen = (size_t)(eq - text);
    if (flen >= sizeof field)
        return tippe_error_set(c->err, TIPPE_EINPUT, "%s: --set %s: field name too long", c->file,
                               text);
    memcpy(field, text, flen);
    field[flen] = '\0';
    const char *value = eq + 1;

    cJSON *obj = root;
    const char *key = field;
    char path[300];
    if (!strncmp(field, "parts.", 6) || !strncmp(field, "parts[", 6)) {
        int rc = override_part_target(c, root, field, text, &obj, &key, path, sizeof path);
        if (rc)
            return rc;
    } else {
        if (!tippe_json_in_list(key, tippe_design_top_keys) || !strcmp(key, "parts")) {
            char list[256];
            tippe_json_key_list(list, sizeof list, tippe_design_top_keys, NULL);
            return tippe_error_set(
                c->err, TIPPE_EINPUT,
                "%s: --set %s: '%s' is not a design field (fields: %s, parts.NAME.FIELD)", c->file,
                text, key, list);
        }
        snprintf(path, sizeof path, "%s", key);
    }

    int is_string = obj == root ? tippe_json_in_list(key, tippe_design_top_string_keys)
                                : tippe_json_in_list(key, tippe_design_part_string_keys);
    cJSON *item = NULL;
    if (!strcmp(value, "null")) {
        cJSON_DeleteItemFromObjectCaseSensitive(obj, key);
    } else {
        if (is_string) {
            item = cJSON_CreateString(value);
        } else {
            const char *end = NULL;
            item = cJSON_ParseWithOpts(value, &end, 1);
            if (!item)
                return tippe_error_set(c->err, TIPPE_EINPUT,
                                       "%s: --set %s: '%s' is not a JSON value (a number, true, "
                                       "false, [from, to], or null to remove the field)",
                                       c->file, text, value);
        }
        if (!item)
            return tippe_error_set(c->err, TIPPE_ECOMPUTE, "out of memory");
        int rc = tippe_json_put(c, obj, key, item);
        if (rc)
            return rc;
    }
    /* material and density_g_cm3 exclude each other: setting one replaces the other. */
    if (obj != root && !strcmp(key, "material"))
        cJSON_DeleteItemFromObjectCaseSensitive(obj, "density_g_cm3");
    if (obj != root && !strcmp(key, "density_g_cm3"))
        cJSON_DeleteItemFromObjectCaseSensitive(obj, "material");
    tippe_json_note_set(c, path, text);
    return TIPPE_OK;
}

/* ------------------------------------------------------- design sources */

struct tippe_design_source {
    char *path;
    cJSON *root;      /* the design file as parsed (duplicate keys refused) */
    char mat_file[1024];
    cJSON *materials; /* the materials table it names, read and checked once; or NULL */
};

/* The source's materials table (a copy the caller deletes) if it is the one
 * tippe_design_build() is about to read; 0 if not. */
int tippe_design_source_materials(const tippe_design *d, const char *mat_file, cJSON **out)
{
    if (!d->source || !d->source->materials || strcmp(mat_file, d->source->mat_file))
        return 0;
    *out = cJSON_Duplicate(d->source->materials, 1);
    return *out != NULL;
}

int tippe_design_source_open(const char *path, tippe_design_source **out, tippe_error *err)
{
    tippe_gsl_errors_as_codes();
    *out = NULL;
    /* A first full load checks the file and resolves its materials table. */
    tippe_design *d = NULL;
    int rc = tippe_design_load(path, NULL, 0, &d, err);
    if (rc)
        return rc;
    tippe_design_free(d);
    tippe_design_source *s = calloc(1, sizeof *s);
    tippe_json_reader *c = tippe_json_reader_new(path, err, TIPPE_JSON_WORDS_FIELD, NULL);
    if (!s || !c || !(s->path = tippe_design_dup_string(path))) {
        rc = tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
        goto fail;
    }
    if ((rc = tippe_json_load(c, MAX_FILE_MIB, "design", &s->root)))
        goto fail;
    char mat_rel[512] = "materials.json";
    const cJSON *m = cJSON_GetObjectItemCaseSensitive(s->root, "materials");
    if (cJSON_IsString(m))
        snprintf(mat_rel, sizeof mat_rel, "%s", m->valuestring);
    const char *slash = strrchr(path, '/');
    if (mat_rel[0] == '/' || !slash)
        snprintf(s->mat_file, sizeof s->mat_file, "%s", mat_rel);
    else
        snprintf(s->mat_file, sizeof s->mat_file, "%.*s/%s", (int)(slash - path), path, mat_rel);
    tippe_error ignored = {0};
    /* A design with inline densities only has no table: then none is cached. */
    if (tippe_design_load_materials(s->mat_file, &s->materials, &ignored))
        s->materials = NULL;
    free(c);
    *out = s;
    return TIPPE_OK;
fail:
    free(c);
    tippe_design_source_free(s);
    return rc;
}

int tippe_design_source_apply(const tippe_design_source *s, const char *const *overrides,
                              int n_overrides, cJSON **out, tippe_error *err)
{
    *out = NULL;
    tippe_json_reader *c = tippe_json_reader_new(s->path, err, TIPPE_JSON_WORDS_FIELD, "set by ");
    cJSON *root = cJSON_Duplicate(s->root, 1);
    int rc = (!c || !root) ? tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory") : TIPPE_OK;
    for (int i = 0; !rc && i < n_overrides; i++)
        rc = tippe_design_apply_override(c, root, overrides[i]);
    free(c);
    if (rc) {
        cJSON_Delete(root);
        return rc;
    }
    *out = root;
    return TIPPE_OK;
}

/* A built variant remembers its overrides (and its travel, when that was the
 * physical one) so that tippe_design_derive() rebuilds the same design. */
int tippe_design_remember_overrides(tippe_design *d, const char *const *overrides, int n,
                              tippe_error *err)
{
    if (!(d->overrides = calloc((size_t)n + 1, sizeof *d->overrides)))
        return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    char travel[128];
    snprintf(travel, sizeof travel, "travel_mm=[%.17g,%.17g]", d->travel_mm[0], d->travel_mm[1]);
    for (int i = 0; i <= n; i++) {
        if (i == n && !d->travel_physical)
            break;
        if (!(d->overrides[d->n_overrides++] = tippe_design_dup_string(i < n ? overrides[i] : travel)))
            return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    }
    return TIPPE_OK;
}

int tippe_design_source_build(const tippe_design_source *s, const char *const *overrides,
                              int n_overrides, unsigned flags, tippe_design **out,
                              tippe_error *err)
{
    *out = NULL;
    tippe_json_reader *c = tippe_json_reader_new(s->path, err, TIPPE_JSON_WORDS_FIELD, "set by ");
    cJSON *root = cJSON_Duplicate(s->root, 1);
    tippe_design *d = calloc(1, sizeof *d);
    int rc = (!c || !root || !d) ? tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory")
                                 : TIPPE_OK;
    for (int i = 0; !rc && i < n_overrides; i++)
        rc = tippe_design_apply_override(c, root, overrides[i]);
    if (!rc) {
        d->source = s;
        d->travel_physical = (flags & TIPPE_DESIGN_TRAVEL_PHYSICAL) != 0;
        d->coarse_layout = (flags & TIPPE_DESIGN_COARSE_LAYOUT) != 0;
        rc = tippe_design_build(c, root, s->path, d, 1);
        d->source = NULL;
    }
    if (!rc)
        rc = tippe_design_remember_overrides(d, overrides, n_overrides, err);
    cJSON_Delete(root);
    free(c);
    if (rc) {
        tippe_design_free(d);
        return rc;
    }
    *out = d;
    return TIPPE_OK;
}

const char *tippe_design_source_path(const tippe_design_source *s) { return s->path; }

void tippe_design_source_free(tippe_design_source *s)
{
    if (!s)
        return;
    free(s->path);
    cJSON_Delete(s->root);
    cJSON_Delete(s->materials);
    free(s);
}
