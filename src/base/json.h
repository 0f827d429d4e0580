/* src/base/json.h: strict reading of the JSON files tippe takes (designs,
 * materials tables, scenarios).
 *
 * cJSON accepts what a user almost never means: keys differing only in case
 * are looked up loosely by cJSON_GetObjectItem, and a repeated key is kept
 * but only the first is seen. A tippe_json_reader refuses both, and every
 * message it writes names the file, the JSON path ("parts[2].radius_mm") and
 * what is wrong. When a command-line override set the path, the message says
 * so, since the file is then not to blame. */
#ifndef TIPPE_BASE_JSON_H
#define TIPPE_BASE_JSON_H

#include "tippe/base.h"

#include <cjson/cJSON.h>
#include <stddef.h>

/* Overrides a reader remembers for blame: more than any command line passes
 * (64 --set options, plus one a sweep adds). */
#define TIPPE_JSON_MAX_SETS 80
#define TIPPE_JSON_PATH_LEN 300

/* Design files and scenario files were documented with different words for
 * the same two errors; each keeps its own, since scripts may match them. */
typedef enum {
    TIPPE_JSON_WORDS_FIELD, /* "must be a number, not a string";
                               "unknown field (a ball has: ...)" */
    TIPPE_JSON_WORDS_KEY    /* "expected a number, got a string";
                               "unknown key (allowed here: ...; keys are case-sensitive)" */
} tippe_json_words;

typedef struct {
    const char *file;   /* the file every message starts with */
    tippe_error *err;
    tippe_json_words words;
    const char *set_by; /* introduces a blamed override: "set by --set " gives
                           "(set by --set parts.rod.radius_mm=0)" */
    int n_set;
    /* The JSON paths overrides set, and the overrides (not copied). */
    char set_path[TIPPE_JSON_MAX_SETS][TIPPE_JSON_PATH_LEN];
    const char *set_text[TIPPE_JSON_MAX_SETS];
} tippe_json_reader;

/* A reader for file with no overrides noted yet, on the heap (it holds the
 * override paths); free() it. NULL, with err set, when out of memory. */
tippe_json_reader *tippe_json_reader_new(const char *file, tippe_error *err,
                                         tippe_json_words words, const char *set_by);

/* Reads r->file (at most max_mib MiB, no NUL byte) and parses it as one JSON
 * value with nothing after it. A syntax error gives FILE:LINE:COLUMN and the
 * text before the error. what names the kind of file ("design") for a file
 * too large to be one. On success the caller owns *root (cJSON_Delete). */
int tippe_json_load(const tippe_json_reader *r, int max_mib, const char *what, cJSON **root);

/* r->file's text alone, read and checked as tippe_json_load reads it (*len bytes
 * before the NUL; the caller frees *text): for a loader that keeps the text to
 * parse it again rather than open the file again. */
int tippe_json_read(const tippe_json_reader *r, int max_mib, const char *what, char **text,
                    size_t *len);

/* The same for a text in memory (len bytes, not NUL-terminated; at most
 * max_mib MiB, no NUL byte), r->file naming it in messages ("request"). */
int tippe_json_parse_text(const tippe_json_reader *r, const char *text, size_t len,
                          int max_mib, const char *what, cJSON **root);

/* "FILE: PATH: message" (or "FILE: message" when path is NULL or ""), with
 * the override that set PATH or a parent of it appended. Returns TIPPE_EINPUT. */
int tippe_json_fail(const tippe_json_reader *r, const char *path, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* A value of the wrong type at path, worded per r->words; want is "a number",
 * "an object", ... */
int tippe_json_wrong_type(const tippe_json_reader *r, const char *path, const char *want,
                          const cJSON *got);

/* "a string", "a number", "true/false", "null", "an array", "an object";
 * "missing" for NULL. */
const char *tippe_json_kind(const cJSON *item);

/* prefix.key, or key when prefix is NULL or "". */
void tippe_json_path(char *buf, size_t cap, const char *prefix, const char *key);

/* Whether key is in the NULL-terminated list. */
int tippe_json_in_list(const char *key, const char *const *list);

/* The keys of lists a and b (b may be NULL), comma-separated. */
void tippe_json_key_list(char *buf, size_t cap, const char *const *a, const char *const *b);

/* Refuses a key repeated in any object of the tree below node (at path). */
int tippe_json_check_duplicates(const tippe_json_reader *r, const cJSON *node, const char *path);

/* Refuses a key of obj (at path) in neither list a nor b (b may be NULL);
 * what ("a shell") names the object in TIPPE_JSON_WORDS_FIELD messages. */
int tippe_json_check_keys(const tippe_json_reader *r, const cJSON *obj, const char *path,
                          const char *what, const char *const *a, const char *const *b);

/* Typed getters for obj.key (obj at path). A missing key is an error when
 * required, else leaves *out as it was; *present (if not NULL) says whether
 * the key was there. */
int tippe_json_number(const tippe_json_reader *r, const cJSON *obj, const char *path,
                      const char *key, int required, double *out, int *present);
/* out may be NULL to check the type only; else a string of cap - 1 characters
 * or more is an error. The string must be UTF-8 and one line of printable text
 * (a name, a label, a file name): a control character (U+0000..U+001F,
 * U+007F..U+009F) would reach a terminal as an escape sequence, break a table
 * or a Markdown line, and cannot be written in XML 1.0 (3MF, SVG). */
int tippe_json_string(const tippe_json_reader *r, const cJSON *obj, const char *path,
                      const char *key, int required, char *out, size_t cap, int *present);
/* As tippe_json_string, for free text (notes): line breaks (\n) and tabs
 * (\t) are allowed there, no other control character (not CR, not ESC). */
int tippe_json_text(const tippe_json_reader *r, const cJSON *obj, const char *path,
                    const char *key, int required, char *out, size_t cap, int *present);
/* The check of both on a text s at path (a key used as a name, a value read
 * otherwise): TIPPE_OK, or TIPPE_EINPUT with the character and its place. */
int tippe_json_check_text(const tippe_json_reader *r, const char *path, const char *s,
                          int free_text);
/* Never required (a flag's absence means false to every caller). */
int tippe_json_bool(const tippe_json_reader *r, const cJSON *obj, const char *path,
                    const char *key, int *out, int *present);

/* Overrides: obj.key = item, replacing any value there (item is owned by obj
 * afterwards, or freed on failure); and remembering that the override text
 * set path, so that a later error at path blames it. */
int tippe_json_put(const tippe_json_reader *r, cJSON *obj, const char *key, cJSON *item);
void tippe_json_note_set(tippe_json_reader *r, const char *path, const char *text);

/* Adds key: [lo, hi], or key: null when either end is not finite (a range the
 * caller could not bound). */
void tippe_json_add_range(cJSON *o, const char *key, double lo, double hi);

#endif
