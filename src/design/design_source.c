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
    tippe_design_source *s = calloc(1, sizeof *s);
    tippe_json_reader *c = tippe_json_reader_new(path, err, TIPPE_JSON_WORDS_FIELD, NULL);
    if (!s || !c || !(s->path = tippe_design_dup_string(path))) {
        rc = tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
        goto fail;
    }
    /* the text the load read, parsed again: the file is read once */
    s->text = d->text;
    s->text_len = d->text_len;
    d->text = NULL;
    if ((rc = tippe_json_parse_text(c, s->text, s->text_len, MAX_FILE_MIB, "design", &s->root)))
        goto fail;
    char mat_rel[512] = "materials.json";
    const cJSON *m = cJSON_GetObjectItemCaseSensitive(s->root, "materials");
    if (cJSON_IsString(m))
        snprintf(mat_rel, sizeof mat_rel, "%s", m->valuestring);
    tippe_path_beside(path, mat_rel, s->mat_file, sizeof s->mat_file);
    /* the table that load read (beside the file, or the shipped one) */
    if (d->mat_file)
        snprintf(s->mat_file, sizeof s->mat_file, "%s", d->mat_file);
    tippe_error ignored = {0};
    /* A design with inline densities only has no table: then none is cached.
     * The load read it already when some part names a material. */
    if (d->mat_table && d->mat_file && !strcmp(d->mat_file, s->mat_file)) {
        s->materials = d->mat_table;
        d->mat_table = NULL;
    } else if (tippe_design_load_materials(s->mat_file, &s->materials, &ignored)) {
        s->materials = NULL;
    }
    tippe_design_free(d);
    free(c);
    *out = s;
    return TIPPE_OK;
fail:
    tippe_design_free(d);
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
        d->known_table = s->materials;
        d->known_table_file = s->mat_file;
        /* the variant keeps the file's text, so that deriving it reads no file */
        if (!(d->text = malloc(s->text_len + 1)))
            rc = tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
        else {
            memcpy(d->text, s->text, s->text_len + 1);
            d->text_len = s->text_len;
        }
        d->travel_physical = (flags & TIPPE_DESIGN_TRAVEL_PHYSICAL) != 0;
        d->coarse_layout = (flags & TIPPE_DESIGN_COARSE_LAYOUT) != 0;
        if (!rc)
            rc = tippe_design_build(c, root, s->path, d, 1);
        d->known_table = NULL;
        d->known_table_file = NULL;
    }
    return tippe_design_finish(c, root, d, overrides, n_overrides, rc, out, err);
}

void tippe_design_source_free(tippe_design_source *s)
{
    if (!s)
        return;
    free(s->path);
    free(s->text);
    cJSON_Delete(s->root);
    cJSON_Delete(s->materials);
    free(s);
}
