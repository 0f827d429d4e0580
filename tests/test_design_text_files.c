/* A design sent as text (tippe serve's requests) opens no file but the designs
 * folder's materials and catalogue tables, whatever its fields say (issue 36:
 * print.gcode read any file of the server). Every string of every shipped
 * design is set in turn to an absolute path, a ../ path and a device, and a
 * print.gcode is added to every part; each is loaded from memory with a read
 * check that records every file the library tries to open. A field that opens
 * anything else fails the test, whether the load then succeeds or not. */
#include "tippe/base.h"
#include "tippe/design.h"

#include "check.h"

#include <cjson/cJSON.h>
#include <dirent.h>
#include <stdlib.h>
#include <string.h>

static char designs_dir[4096];
static int n_opened_elsewhere;
static char last_elsewhere[512];

/* Allowed: the two tables a design from memory may use, in the designs folder. */
static int record_read(const char *path, const char *what, tippe_error *err)
{
    (void)what;
    (void)err;
    char mat[4200], cat[4200];
    snprintf(mat, sizeof mat, "%s/materials.json", designs_dir);
    snprintf(cat, sizeof cat, "%s/catalogue.json", designs_dir);
    if (strcmp(path, mat) && strcmp(path, cat)) {
        n_opened_elsewhere++;
        snprintf(last_elsewhere, sizeof last_elsewhere, "%s", path);
    }
    return TIPPE_OK;
}

static const char *const probes[] = {"/etc/passwd", "../../../../etc/passwd", "/dev/zero",
                                     "/proc/self/environ", "materials.json", NULL};

/* Loads the text of root from memory; returns the number of files opened
 * outside the allowed two. */
static int load_counting(const cJSON *root)
{
    char *text = cJSON_PrintUnformatted(root);
    n_opened_elsewhere = 0;
    tippe_design *d = NULL;
    tippe_error err = {0};
    tippe_design_load_text("design", text, strlen(text), designs_dir, NULL, 0, &d, &err);
    tippe_design_free(d);
    free(text);
    return n_opened_elsewhere;
}

/* Every string value below node, set to each probe in turn. */
static void probe_strings(cJSON *root, cJSON *node, const char *file, int *n_tried)
{
    for (cJSON *c = node->child; c; c = c->next) {
        if (cJSON_IsString(c)) {
            char *old = strdup(c->valuestring);
            for (const char *const *p = probes; *p; p++) {
                cJSON_SetValuestring(c, *p);
                int n = load_counting(root);
                (*n_tried)++;
                CHECK(n == 0, "%s: field '%s' = '%s' opened %s", file,
                      c->string ? c->string : "[]", *p, last_elsewhere);
            }
            cJSON_SetValuestring(c, old);
            free(old);
        } else if (cJSON_IsObject(c) || cJSON_IsArray(c)) {
            probe_strings(root, c, file, n_tried);
        }
    }
}

/* A print block with a G-code path on every part (the field of issue 36). */
static void probe_gcode(cJSON *root, const char *file, int *n_tried)
{
    cJSON *parts = cJSON_GetObjectItemCaseSensitive(root, "parts");
    int i = 0;
    for (cJSON *p = parts ? parts->child : NULL; p; p = p->next, i++) {
        for (const char *const *g = probes; *g; g++) {
            cJSON *copy = cJSON_Duplicate(root, 1);
            cJSON *cp = cJSON_GetArrayItem(cJSON_GetObjectItemCaseSensitive(copy, "parts"), i);
            cJSON *print = cJSON_GetObjectItemCaseSensitive(cp, "print");
            if (!cJSON_IsObject(print)) {
                cJSON_DeleteItemFromObjectCaseSensitive(cp, "print");
                print = cJSON_AddObjectToObject(cp, "print");
            }
            cJSON_DeleteItemFromObjectCaseSensitive(print, "gcode");
            cJSON_AddStringToObject(print, "gcode", *g);
            int n = load_counting(copy);
            (*n_tried)++;
            CHECK(n == 0, "%s: parts[%d].print.gcode = '%s' opened %s", file, i, *g,
                  last_elsewhere);
            cJSON_Delete(copy);
        }
    }
}

/* And the refusal names the field. */
static void gcode_refused_by_name(void)
{
    char path[4200];
    snprintf(path, sizeof path, "%s/m12-setscrew-printed.json", designs_dir);
    char *text = NULL;
    size_t len = 0;
    tippe_error err = {0};
    CHECK(tippe_file_read(path, 1 << 20, "design", &text, &len, &err) == TIPPE_OK, "%s",
          err.msg);
    cJSON *root = cJSON_Parse(text);
    free(text);
    cJSON *body = cJSON_GetArrayItem(cJSON_GetObjectItemCaseSensitive(root, "parts"), 0);
    cJSON_DeleteItemFromObjectCaseSensitive(body, "print");
    cJSON *print = cJSON_AddObjectToObject(body, "print");
    cJSON_AddStringToObject(print, "gcode", "/etc/passwd");
    char *t = cJSON_PrintUnformatted(root);
    tippe_design *d = NULL;
    int rc = tippe_design_load_text("design", t, strlen(t), designs_dir, NULL, 0, &d, &err);
    CHECK(rc == TIPPE_EINPUT && strstr(err.msg, "parts[0].print.gcode") &&
              !strstr(err.msg, "root:"),
          "refused naming the field, quoting nothing of the file: rc %d, %s", rc, err.msg);
    tippe_design_free(d);
    free(t);
    cJSON_Delete(root);
}

int main(void)
{
    if (!realpath("designs", designs_dir)) {
        printf("FAIL: run from the source tree (designs/ not found)\n");
        return 1;
    }
    tippe_file_set_read_check(record_read);
    gcode_refused_by_name();
    DIR *dir = opendir(designs_dir);
    struct dirent *e;
    int n_designs = 0, n_tried = 0;
    while ((e = readdir(dir))) {
        size_t n = strlen(e->d_name);
        if (n < 6 || strcmp(e->d_name + n - 5, ".json") || !strcmp(e->d_name, "materials.json") ||
            !strcmp(e->d_name, "catalogue.json"))
            continue;
        char path[4400];
        snprintf(path, sizeof path, "%s/%s", designs_dir, e->d_name);
        char *text = NULL;
        size_t len = 0;
        tippe_error err = {0};
        if (tippe_file_read(path, 1 << 20, "design", &text, &len, &err))
            continue;
        cJSON *root = cJSON_Parse(text);
        free(text);
        if (!root)
            continue;
        probe_strings(root, root, e->d_name, &n_tried);
        probe_gcode(root, e->d_name, &n_tried);
        cJSON_Delete(root);
        n_designs++;
    }
    closedir(dir);
    CHECK(n_designs >= 10 && n_tried > 500, "probed %d designs, %d loads", n_designs, n_tried);
    printf("%d designs, %d loads from memory with a path in a field\n", n_designs, n_tried);
    return check_summary("test_design_text_files");
}
