/* Strict JSON reading shared by design files, materials tables and scenarios
 * (src/base/json.h). */
#include "base/json.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

tippe_json_reader *tippe_json_reader_new(const char *file, tippe_error *err,
                                         tippe_json_words words, const char *set_by)
{
    tippe_json_reader *r = calloc(1, sizeof *r);
    if (!r) {
        tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
        return NULL;
    }
    r->file = file;
    r->err = err;
    r->words = words;
    r->set_by = set_by;
    return r;
}


/* Through base's reader: regular files only, capped (src/base/file.c). */
static int read_text(const char *path, int max_mib, const char *what, char **out,
                     tippe_error *err)
{
    size_t len = 0;
    int rc = tippe_file_read(path, (size_t)max_mib << 20, what, out, &len, err);
    if (rc)
        return rc;
    if (memchr(*out, '\0', len)) {
        free(*out);
        *out = NULL;
        /* cJSON reads a C string: a NUL would silently end the text there. */
        return tippe_error_set(err, TIPPE_EINPUT, "%s: contains a NUL byte: not a JSON text",
                               path);
    }
    return TIPPE_OK;
}

/* The position comes from cJSON_ParseWithOpts: cJSON_GetErrorPtr is global
 * state and not thread-safe. */
static int parse(const char *path, const char *text, cJSON **out, tippe_error *err)
{
    const char *end = NULL;
    cJSON *root = cJSON_ParseWithOpts(text, &end, 1);
    if (root) {
        *out = root;
        return TIPPE_OK;
    }
    if (!end || end < text)
        end = text;
    int line = 1, col = 1;
    for (const char *p = text; p < end && *p; p++) {
        if (*p == '\n') {
            line++;
            col = 1;
        } else {
            col++;
        }
    }
    /* Quote the line up to the error: cJSON may point just past the bad token. */
    const char *ls = end;
    while (ls > text && ls[-1] != '\n')
        ls--;
    if (end - ls > 40)
        ls = end - 40;
    char line_text[48];
    int k = 0;
    for (const char *p = ls; p < end && k < (int)sizeof line_text - 1; p++)
        line_text[k++] = isprint((unsigned char)*p) ? *p : ' ';
    line_text[k] = '\0';
    if (!*end)
        return tippe_error_set(err, TIPPE_EINPUT,
                               "%s:%d:%d: not valid JSON: the text ends too early (after '%s')",
                               path, line, col, line_text);
    return tippe_error_set(err, TIPPE_EINPUT, "%s:%d:%d: not valid JSON (line %d, column %d, "
                           "after '%s')", path, line, col, line, col, line_text);
}

int tippe_json_parse_text(const tippe_json_reader *r, const char *text, size_t len,
                          int max_mib, const char *what, cJSON **root)
{
    *root = NULL;
    if (len > ((size_t)max_mib << 20))
        return tippe_error_set(r->err, TIPPE_EINPUT, "%s: larger than %d MiB: not a %s",
                               r->file, max_mib, what);
    if (memchr(text, '\0', len))
        return tippe_error_set(r->err, TIPPE_EINPUT, "%s: contains a NUL byte: not a JSON text",
                               r->file);
    char *copy = malloc(len + 1);
    if (!copy)
        return tippe_error_set(r->err, TIPPE_ECOMPUTE, "%s: out of memory", r->file);
    memcpy(copy, text, len);
    copy[len] = '\0';
    int rc = parse(r->file, copy, root, r->err);
    free(copy);
    return rc;
}

int tippe_json_read(const tippe_json_reader *r, int max_mib, const char *what, char **text,
                    size_t *len)
{
    *len = 0;
    int rc = read_text(r->file, max_mib, what, text, r->err);
    if (!rc)
        *len = strlen(*text);
    return rc;
}

int tippe_json_load(const tippe_json_reader *r, int max_mib, const char *what, cJSON **root)
{
    *root = NULL;
    char *text = NULL;
    int rc = read_text(r->file, max_mib, what, &text, r->err);
    if (rc)
        return rc;
    rc = parse(r->file, text, root, r->err);
    free(text);
    return rc;
}

/* A message that quotes the file's text (a key, a name) must not carry its
 * control characters to the terminal: each is shown as \xNN. */
static void visible(char *out, size_t cap, const char *in)
{
    size_t n = 0;
    for (; *in && n + 5 < cap; in++) {
        unsigned char ch = (unsigned char)*in;
        if (ch < 0x20 || ch == 0x7f)
            n += (size_t)snprintf(out + n, cap - n, "\\x%02X", ch);
        else
            out[n++] = (char)ch;
    }
    out[n] = '\0';
}

int tippe_json_fail(const tippe_json_reader *r, const char *path, const char *fmt, ...)
{
    char raw[768], what[768 * 2], shown_path[TIPPE_JSON_PATH_LEN * 2];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(raw, sizeof raw, fmt, ap);
    va_end(ap);
    visible(what, sizeof what, raw);
    const char *blamed = path;
    if (path) {
        visible(shown_path, sizeof shown_path, path);
        path = shown_path;
    }
    /* The last override wins, as it does on the tree. */
    const char *by = NULL;
    for (int i = 0; i < r->n_set && blamed; i++) {
        size_t n = strlen(r->set_path[i]);
        if (!strncmp(blamed, r->set_path[i], n) && (blamed[n] == '\0' || blamed[n] == '.'))
            by = r->set_text[i];
    }
    if (by) {
        char shown_by[768];
        visible(shown_by, sizeof shown_by, by);
        return tippe_error_set_field(r->err, TIPPE_EINPUT, path, "%s: %s: %s (%s%s)", r->file,
                                     path, what, r->set_by ? r->set_by : "set by ", shown_by);
    }
    if (path && path[0])
        return tippe_error_set_field(r->err, TIPPE_EINPUT, path, "%s: %s: %s", r->file, path,
                                     what);
    return tippe_error_set(r->err, TIPPE_EINPUT, "%s: %s", r->file, what);
}

const char *tippe_json_kind(const cJSON *item)
{
    if (!item) return "missing";
    if (cJSON_IsString(item)) return "a string";
    if (cJSON_IsNumber(item)) return "a number";
    if (cJSON_IsBool(item)) return "true/false";
    if (cJSON_IsNull(item)) return "null";
    if (cJSON_IsArray(item)) return "an array";
    if (cJSON_IsObject(item)) return "an object";
    return "an invalid value";
}

int tippe_json_wrong_type(const tippe_json_reader *r, const char *path, const char *want,
                          const cJSON *got)
{
    if (r->words == TIPPE_JSON_WORDS_KEY)
        return tippe_json_fail(r, path, "expected %s, got %s", want, tippe_json_kind(got));
    return tippe_json_fail(r, path, "must be %s, not %s", want, tippe_json_kind(got));
}

void tippe_json_path(char *buf, size_t cap, const char *prefix, const char *key)
{
    if (prefix && prefix[0])
        snprintf(buf, cap, "%s.%s", prefix, key);
    else
        snprintf(buf, cap, "%s", key);
}

int tippe_json_in_list(const char *key, const char *const *list)
{
    for (; *list; list++)
        if (!strcmp(key, *list))
            return 1;
    return 0;
}

void tippe_json_key_list(char *buf, size_t cap, const char *const *a, const char *const *b)
{
    buf[0] = '\0';
    size_t n = 0;
    for (int pass = 0; pass < 2; pass++)
        for (const char *const *l = pass ? b : a; l && *l; l++) {
            int w = snprintf(buf + n, cap - n, "%s%s", n ? ", " : "", *l);
            if (w < 0 || (size_t)w >= cap - n)
                return;
            n += (size_t)w;
        }
}

/* A key and its place among its object's members, for finding duplicates. */
typedef struct {
    const char *key;
    int index;
} member_key;

static int by_key_then_index(const void *a, const void *b)
{
    const member_key *x = a, *y = b;
    int c = strcmp(x->key, y->key);
    return c ? c : (x->index > y->index) - (x->index < y->index);
}

/* The index of the first member of obj (in document order) whose key an
 * earlier member already has, or -1: sorting the keys makes it O(k log k)
 * for k members (a pairwise scan took minutes on 340k keys). Small objects,
 * the usual case, keep the pairwise scan, which needs no memory. *status is
 * TIPPE_ECOMPUTE if the sort's memory was not there. */
static int first_repeat(const cJSON *obj, int *status)
{
    enum { PAIRWISE_MAX = 16 };
    *status = TIPPE_OK;
    int k = 0;
    for (const cJSON *ch = obj->child; ch; ch = ch->next)
        k++;
    if (k <= PAIRWISE_MAX) {
        int i = 0;
        for (const cJSON *ch = obj->child; ch; ch = ch->next, i++)
            for (const cJSON *prev = obj->child; prev != ch; prev = prev->next)
                if (!strcmp(prev->string, ch->string))
                    return i;
        return -1;
    }
    member_key *m = malloc((size_t)k * sizeof *m);
    if (!m) {
        *status = TIPPE_ECOMPUTE;
        return -1;
    }
    int i = 0;
    for (const cJSON *ch = obj->child; ch; ch = ch->next, i++)
        m[i] = (member_key){ch->string, i};
    qsort(m, (size_t)k, sizeof *m, by_key_then_index);
    /* In a run of equal keys the second has the earliest repeat of that key. */
    int first = -1;
    for (i = 1; i < k; i++)
        if (!strcmp(m[i - 1].key, m[i].key) && (i < 2 || strcmp(m[i - 2].key, m[i].key)) &&
            (first < 0 || m[i].index < first))
            first = m[i].index;
    free(m);
    return first;
}

/* cJSON keeps every duplicate key and lookups see only the first: a second
 * "radius_mm" would be silently ignored, so refuse it anywhere in the tree.
 * Reports what a walk in document order meets first. */
int tippe_json_check_duplicates(const tippe_json_reader *r, const cJSON *node, const char *path)
{
    char sub[256];
    int repeat = -1;
    if (cJSON_IsObject(node)) {
        int st;
        repeat = first_repeat(node, &st);
        if (st)
            return tippe_error_set(r->err, st, "%s: out of memory", r->file);
    }
    int i = 0;
    for (const cJSON *ch = node->child; ch; ch = ch->next, i++) {
        if (cJSON_IsObject(node)) {
            tippe_json_path(sub, sizeof sub, path, ch->string);
            if (i == repeat)
                return tippe_json_fail(r, sub,
                                       "duplicate key (a key may appear once per object)");
        } else {
            snprintf(sub, sizeof sub, "%s[%d]", path ? path : "", i);
        }
        if (ch->child) {
            int rc = tippe_json_check_duplicates(r, ch, sub);
            if (rc)
                return rc;
        }
    }
    return TIPPE_OK;
}

int tippe_json_check_keys(const tippe_json_reader *r, const cJSON *obj, const char *path,
                          const char *what, const char *const *a, const char *const *b)
{
    char sub[256], list[512];
    for (const cJSON *ch = obj->child; ch; ch = ch->next)
        if (!tippe_json_in_list(ch->string, a) && !(b && tippe_json_in_list(ch->string, b))) {
            tippe_json_key_list(list, sizeof list, a, b);
            tippe_json_path(sub, sizeof sub, path, ch->string);
            if (r->words == TIPPE_JSON_WORDS_KEY)
                return tippe_json_fail(r, sub, "unknown key (allowed here: %s; keys are "
                                               "case-sensitive)", list);
            return tippe_json_fail(r, sub, "unknown field (%s has: %s)", what ? what : "it",
                                   list);
        }
    return TIPPE_OK;
}

/* obj.key, its path in sub, and whether it is there in *present. */
static const cJSON *lookup(const cJSON *obj, const char *path, const char *key, char *sub,
                           size_t cap, int *present)
{
    tippe_json_path(sub, cap, path, key);
    const cJSON *it = cJSON_GetObjectItemCaseSensitive(obj, key);
    if (present)
        *present = it != NULL;
    return it;
}

int tippe_json_number(const tippe_json_reader *r, const cJSON *obj, const char *path,
                      const char *key, int required, double *out, int *present)
{
    char sub[256];
    const cJSON *it = lookup(obj, path, key, sub, sizeof sub, present);
    if (!it)
        return required ? tippe_json_fail(r, sub, "missing (a number is required)") : TIPPE_OK;
    if (!cJSON_IsNumber(it))
        return tippe_json_wrong_type(r, sub, "a number", it);
    /* cJSON turns 1e999 into inf: no physical input is infinite. */
    if (!isfinite(it->valuedouble))
        return tippe_json_fail(r, sub, "must be a finite number");
    *out = it->valuedouble;
    return TIPPE_OK;
}

/* The length of the UTF-8 sequence at s and its code point in *cp, or 0 when
 * s does not start a well-formed one (overlong, a surrogate, above U+10FFFF). */
static int utf8_char(const unsigned char *s, unsigned *cp)
{
    if (s[0] < 0x80) {
        *cp = s[0];
        return 1;
    }
    int n = s[0] >= 0xf0 && s[0] <= 0xf4 ? 4 : s[0] >= 0xe0 ? (s[0] <= 0xef ? 3 : 0)
                                          : s[0] >= 0xc2 ? 2 : 0;
    if (!n)
        return 0;
    unsigned c = s[0] & (0x7f >> n);
    for (int k = 1; k < n; k++) {
        if ((s[k] & 0xc0) != 0x80)
            return 0;
        c = (c << 6) | (s[k] & 0x3f);
    }
    static const unsigned least[5] = {0, 0, 0x80, 0x800, 0x10000};
    if (c < least[n] || c > 0x10ffff || (c >= 0xd800 && c <= 0xdfff))
        return 0;
    *cp = c;
    return n;
}

int tippe_json_check_text(const tippe_json_reader *r, const char *path, const char *s,
                          int free_text)
{
    int at = 1;
    for (const unsigned char *p = (const unsigned char *)s; *p; at++) {
        unsigned c;
        int n = utf8_char(p, &c);
        if (!n)
            return tippe_json_fail(r, path, "character %d is not valid UTF-8 (byte 0x%02X): "
                                            "a text must be UTF-8", at, *p);
        int control = c < 0x20 || (c >= 0x7f && c <= 0x9f);
        if (control && !(free_text && (c == '\n' || c == '\t'))) {
            if (free_text)
                return tippe_json_fail(r, path, "character %d is the control character U+%04X: "
                                                "free text may hold line breaks (\\n) and tabs "
                                                "(\\t), no other control character", at, c);
            return tippe_json_fail(r, path, "character %d is the control character U+%04X: a "
                                            "name or label is one line of printable text", at, c);
        }
        p += n;
    }
    return TIPPE_OK;
}

/* tippe_json_string and tippe_json_text: a string checked as one line or as free text. */
static int get_text(const tippe_json_reader *r, const cJSON *obj, const char *path,
                    const char *key, int required, char *out, size_t cap, int *present,
                    int free_text)
{
    char sub[256];
    const cJSON *it = lookup(obj, path, key, sub, sizeof sub, present);
    if (!it)
        return required ? tippe_json_fail(r, sub, "missing (a string is required)") : TIPPE_OK;
    if (!cJSON_IsString(it))
        return tippe_json_wrong_type(r, sub, "a string", it);
    int rc = tippe_json_check_text(r, sub, it->valuestring, free_text);
    if (rc)
        return rc;
    if (out) {
        if (strlen(it->valuestring) >= cap)
            return tippe_json_fail(r, sub, "longer than %zu characters", cap - 1);
        strcpy(out, it->valuestring);
    }
    return TIPPE_OK;
}

int tippe_json_string(const tippe_json_reader *r, const cJSON *obj, const char *path,
                      const char *key, int required, char *out, size_t cap, int *present)
{
    return get_text(r, obj, path, key, required, out, cap, present, 0);
}

int tippe_json_text(const tippe_json_reader *r, const cJSON *obj, const char *path,
                    const char *key, int required, char *out, size_t cap, int *present)
{
    return get_text(r, obj, path, key, required, out, cap, present, 1);
}

int tippe_json_bool(const tippe_json_reader *r, const cJSON *obj, const char *path,
                    const char *key, int *out, int *present)
{
    char sub[256];
    const cJSON *it = lookup(obj, path, key, sub, sizeof sub, present);
    if (!it)
        return TIPPE_OK;
    if (!cJSON_IsBool(it))
        return tippe_json_wrong_type(r, sub, "true or false", it);
    *out = cJSON_IsTrue(it);
    return TIPPE_OK;
}

int tippe_json_put(const tippe_json_reader *r, cJSON *obj, const char *key, cJSON *item)
{
    cJSON_bool done = cJSON_GetObjectItemCaseSensitive(obj, key)
                          ? cJSON_ReplaceItemInObjectCaseSensitive(obj, key, item)
                          : cJSON_AddItemToObject(obj, key, item);
    if (!done) {
        cJSON_Delete(item);
        return tippe_error_set(r->err, TIPPE_ECOMPUTE, "out of memory");
    }
    return TIPPE_OK;
}

void tippe_json_note_set(tippe_json_reader *r, const char *path, const char *text)
{
    if (r->n_set == TIPPE_JSON_MAX_SETS)
        return; /* only blame is lost: the override itself was applied */
    snprintf(r->set_path[r->n_set], sizeof r->set_path[0], "%s", path);
    r->set_text[r->n_set] = text;
    r->n_set++;
}

void tippe_json_add_range(cJSON *o, const char *key, double lo, double hi)
{
    if (!isfinite(lo) || !isfinite(hi)) {
        cJSON_AddNullToObject(o, key);
        return;
    }
    cJSON *range = cJSON_AddArrayToObject(o, key);
    if (range) {
        cJSON_AddItemToArray(range, cJSON_CreateNumber(lo));
        cJSON_AddItemToArray(range, cJSON_CreateNumber(hi));
    }
}
