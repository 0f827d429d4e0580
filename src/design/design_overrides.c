/* Overrides (--set FIELD=VALUE) applied to a parsed design file, and design
 * sources: a design parsed once and derived many times (the optimiser, sweeps of
 * a field, the tolerance bands). */
#include "design/internal.h"

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

    int in_print = strstr(path, ".print.") != NULL;
    int is_string = obj == root ? tippe_json_in_list(key, tippe_design_top_string_keys)
                    : in_print  ? tippe_json_in_list(key, tippe_design_print_string_keys)
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
