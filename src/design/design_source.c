/* Design sources: a design file parsed (and its materials table read) once,
 * then built many times with different overrides: the optimiser's candidates,
 * sweeps of a field, the tolerance bands. */
#include "design/internal.h"

#include <cjson/cJSON.h>
#include <gsl/gsl_errno.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>



int tippe_design_source_open(const char *path, tippe_design_source **out, tippe_error *err)
{
    tippe_gsl_errors_as_codes();
    *out = NULL;
    /* A first full load checks the file and resolves its materials table. */
    tippe_design *d = NULL;
    int rc = tippe_design_load(path, NULL, 0, &d, err);
    if (rc)
        return rc;
    /* the table that load read (beside the file, or the shipped one) */
    char resolved[sizeof((tippe_design_source *)0)->mat_file] = "";
    if (d->mat_file)
        snprintf(resolved, sizeof resolved, "%s", d->mat_file);
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
    if (resolved[0])
        snprintf(s->mat_file, sizeof s->mat_file, "%s", resolved);
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
    return tippe_design_finish(c, root, d, overrides, n_overrides, rc, out, err);
}

void tippe_design_source_free(tippe_design_source *s)
{
    if (!s)
        return;
    free(s->path);
    cJSON_Delete(s->root);
    cJSON_Delete(s->materials);
    free(s);
}
