/* The best candidate as a design file a user can load. */
#include "optimise/internal.h"
#include "tippe/design.h"
#include "tippe/physics.h"
#include "tippe/sweep.h"

#include <cjson/cJSON.h>
#include <dlfcn.h>
#include <limits.h>
#include <math.h>
#include <nlopt.h>
#include <omp.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

/* ---- the best design as a file --------------------------------------------- */

/* root.key = the string value, replacing any; 0 if out of memory. */
static int put_string(cJSON *root, const char *key, const char *value)
{
    cJSON *item = cJSON_CreateString(value);
    if (!item)
        return 0;
    if (cJSON_GetObjectItemCaseSensitive(root, key))
        return cJSON_ReplaceItemInObjectCaseSensitive(root, key, item);
    cJSON_AddItemToObject(root, key, item);
    return 1;
}

/* The directory of path, made absolute (realpath), into out; 0 on failure. */
static int abs_dir(const char *path, char *out)
{
    char dir[PATH_MAX];
    tippe_path_dir(path, dir, sizeof dir);
    return realpath(dir, out) != NULL;
}

/* The path of file `target` (absolute) as seen from directory `from` (absolute). */
static void relative_path(const char *from, const char *target, char *out, size_t cap)
{
    size_t common = 0, i = 0;
    for (; from[i] && target[i] && from[i] == target[i]; i++)
        if (from[i] == '/')
            common = i;
    if (!from[i] && target[i] == '/')
        common = i;
    if (!from[i] && !target[i])
        common = i;
    size_t n = 0;
    out[0] = '\0';
    for (const char *p = from + common; *p; p++)
        if (*p == '/' && n + 4 < cap)
            n += (size_t)snprintf(out + n, cap - n, "../");
    snprintf(out + n, cap - n, "%s", target + common + (target[common] == '/'));
}

cJSON *tippe_optimise_design_json(const tippe_optimise_spec *s, const tippe_optimise_eval *e,
                             const char *out_path, const char *how, tippe_error *err)
{
    char buf[TIPPE_OPTIMISE_MAX_VARY + MAX_CHOOSE * MAX_SETS_PER_OPTION + MAX_TIE][256];
    const char *ov[sizeof buf / sizeof buf[0]];
    int n = tippe_optimise_overrides(s, e->choice, e->x, buf, (int)(sizeof buf / sizeof buf[0]));
    for (int i = 0; i < n; i++)
        ov[i] = buf[i];
    cJSON *root = NULL;
    if (tippe_design_source_apply(s->src, ov, n, &root, err))
        return NULL;
    /* travel_mm: the physical travel, so that every verb sweeps what was scored. */
    /* Rounded inward by 1e-9 mm: the file's numbers, read back, may move the
     * contact a few ulps (4e-15 mm seen), and a stated travel must lie within
     * the physical one. 1e-9 mm is far below the 1e-6 mm zone ends carry. */
    double tr[2] = {e->travel_mm[0] + 1e-9, e->travel_mm[1] - 1e-9};
    cJSON *travel = cJSON_CreateDoubleArray(tr, 2);
    /* materials: the base design's table, seen from where the file is written. */
    char mat_rel[512] = "materials.json", mat_abs[PATH_MAX], base_dir[PATH_MAX],
         out_dir[PATH_MAX], rel[PATH_MAX], mat_join[PATH_MAX + 600];
    const cJSON *m = cJSON_GetObjectItemCaseSensitive(root, "materials");
    if (cJSON_IsString(m))
        snprintf(mat_rel, sizeof mat_rel, "%s", m->valuestring);
    int ok = travel != NULL;
    if (ok && abs_dir(s->design_path, base_dir) && abs_dir(out_path, out_dir)) {
        if (mat_rel[0] == '/')
            snprintf(mat_join, sizeof mat_join, "%s", mat_rel);
        else
            snprintf(mat_join, sizeof mat_join, "%s/%s", base_dir, mat_rel);
        if (realpath(mat_join, mat_abs)) {
            relative_path(out_dir, mat_abs, rel, sizeof rel);
            ok = put_string(root, "materials", rel);
        }
    }
    /* catalogue: the one a catalogue choice took its items from (the parts name
     * them), else the base design's; seen from where the file is written, as
     * materials is. */
    const cJSON *cat = cJSON_GetObjectItemCaseSensitive(root, "catalogue");
    if (ok && (s->catalogue_file[0] || cJSON_IsString(cat)) && abs_dir(out_path, out_dir)) {
        if (s->catalogue_file[0])
            snprintf(mat_join, sizeof mat_join, "%s", s->catalogue_file);
        else if (cat->valuestring[0] == '/' || !abs_dir(s->design_path, base_dir))
            snprintf(mat_join, sizeof mat_join, "%s", cat->valuestring);
        else
            snprintf(mat_join, sizeof mat_join, "%s/%s", base_dir, cat->valuestring);
        if (realpath(mat_join, mat_abs)) {
            relative_path(out_dir, mat_abs, rel, sizeof rel);
            ok = put_string(root, "catalogue", rel);
        }
    }
    if (ok)
        ok = cJSON_ReplaceItemInObjectCaseSensitive(root, "travel_mm", travel);
    else
        cJSON_Delete(travel);
    const cJSON *nm = cJSON_GetObjectItemCaseSensitive(root, "name");
    char name[512], notes[4096];
    snprintf(name, sizeof name, "%s (optimised)", cJSON_IsString(nm) ? nm->valuestring : "design");
    size_t k = (size_t)snprintf(notes, sizeof notes,
                                "Found by tippe optimise %s (%s). Narrowest zone %.6f mm "
                                "(group I %.6f, II %.6f, III %.6f mm, each its widest run of Z2 "
                                "within the physical travel %.3f .. %.3f mm); eps_max %.3f mm",
                                s->path, how, e->objective_mm, e->zone_mm[0], e->zone_mm[1],
                                e->zone_mm[2], e->travel_mm[0], e->travel_mm[1], e->eps_max_mm);
    if (e->spin_flip_rev_s > 0 && k < sizeof notes)
        k += (size_t)snprintf(notes + k, sizeof notes - k,
                              "; flip spin n* up to %.1f rev/s over zone II's middle half",
                              e->spin_flip_rev_s);
    if (isfinite(e->wall_mm) && k < sizeof notes)
        k += (size_t)snprintf(notes + k, sizeof notes - k, "; thinnest hole wall %.2f mm",
                              e->wall_mm);
    if (k < sizeof notes)
        k += (size_t)snprintf(notes + k, sizeof notes - k, ". Overrides of %s:", s->design_path);
    for (int i = 0; i < n && k < sizeof notes; i++)
        k += (size_t)snprintf(notes + k, sizeof notes - k, " %s", buf[i]);
    if (k < sizeof notes && e->has_robust)
        snprintf(notes + k, sizeof notes - k,
                 ". Robust widths (less the tolerance bands of each zone's ends, the design's "
                 "tolerances): I %.3f, II %.3f, III %.3f mm, narrowest %.3f mm; the search "
                 "maximised the nominal widths and ranked the choices by the robust one.",
                 e->robust_zone_mm[0], e->robust_zone_mm[1], e->robust_zone_mm[2], e->robust_mm);
    if (ok)
        ok = put_string(root, "name", name) && put_string(root, "notes", notes);
    if (!ok) {
        cJSON_Delete(root);
        tippe_error_set(err, TIPPE_ECOMPUTE, "optimise: out of memory");
        return NULL;
    }
    return root;
}
