/* Search a design space for the widest narrowest zone (see tippe/optimise.h).
 *
 * The spec is read strictly (src/base/json.h). A candidate is the base design with
 * overrides, built from a design source held in memory (no file is read per
 * candidate), with its physical travel as its travel; its zones come from the
 * root-found sweep. NLopt searches each choice on its own thread; nothing is
 * shared between choices but the read-only spec, so the result does not depend
 * on how many threads there are. */
#include "optimise/internal.h"
#include "tippe/build.h"
#include "tippe/design.h"
#include "base/json.h"
#include "tippe/sweep.h"
#include "tippe/physics.h"

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

static const char *const spec_keys[] = {"name",   "notes",       "design",    "catalogue",
                                        "vary",   "choose",      "tie",       "constraints",
                                        "objective", "search",   NULL};
static const char *const constraint_keys[] = {"eps_max_min_mm", "spin_max_rev_s", "min_wall_mm",
                                              "max_weight_g", NULL};
static const char *const search_keys[] = {"algorithm", "evaluations", "polish",
                                          "polish_evaluations", NULL};
static const char *const tie_keys[] = {"follows", "plus_mm", "times", NULL};
static const char *const choose_cat_keys[] = {"catalogue", "items", NULL};

const char *tippe_optimise_status_name(tippe_optimise_status s)
{
    static const char *const names[] = {"ok", "does not fit", "thin wall", "too heavy",
                                        "eps_max too small", "flip spin too high",
                                        "no zones"};
    return (int)s >= 0 && (int)s <= (int)TIPPE_OPTIMISE_NO_ZONES ? names[s] : "?";
}

void tippe_optimise_options_default(tippe_optimise_options *o)
{
    memset(o, 0, sizeof *o);
    o->seed = 1;
}

static char *dup_str(const char *s)
{
    size_t n = strlen(s) + 1;
    char *r = malloc(n);
    if (r)
        memcpy(r, s, n);
    return r;
}

/* ---- reading the spec ------------------------------------------------------ */

/* A number in the design's JSON at an override path ("parts.NAME.KEY" or a
 * top-level key); NAN if absent or not a number. */
static double design_number(const cJSON *root, const char *path)
{
    const cJSON *obj = root;
    const char *key = path;
    char name[TIPPE_OPTIMISE_PATH_LEN];
    if (!strncmp(path, "parts.", 6)) {
        const char *dot = strrchr(path, '.');
        if (dot <= path + 6 || (size_t)(dot - path - 6) >= sizeof name)
            return NAN;
        memcpy(name, path + 6, (size_t)(dot - path - 6));
        name[dot - path - 6] = '\0';
        key = dot + 1;
        obj = NULL;
        const cJSON *parts = cJSON_GetObjectItemCaseSensitive(root, "parts");
        for (const cJSON *p = parts ? parts->child : NULL; p; p = p->next) {
            const cJSON *nm = cJSON_GetObjectItemCaseSensitive(p, "name");
            if (cJSON_IsString(nm) && !strcmp(nm->valuestring, name))
                obj = p;
        }
        if (!obj)
            return NAN;
    }
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(obj, key);
    return cJSON_IsNumber(v) ? v->valuedouble : NAN;
}

/* The JSON path of entry v of section ("vary.parts.hole.z_mm") into p; refuses
 * one entry too many (n of max) and a key that is not a field path. */
static int entry_path(tippe_json_reader *c, const char *section, const cJSON *v, int n, int max,
                      const char *what, char *p, size_t cap)
{
    tippe_json_path(p, cap, section, v->string);
    if (n == max)
        return tippe_json_fail(c, p, "at most %d %s", max, what);
    if (strlen(v->string) >= TIPPE_OPTIMISE_PATH_LEN || strchr(v->string, '='))
        return tippe_json_fail(c, p, "not a field path");
    return TIPPE_OK;
}

static int parse_vary(tippe_json_reader *c, const cJSON *vary, tippe_optimise_spec *s)
{
    if (!vary)
        return TIPPE_OK;
    if (!cJSON_IsObject(vary))
        return tippe_json_wrong_type(c, "vary", "an object {FIELD: [from, to]}", vary);
    for (const cJSON *v = vary->child; v; v = v->next) {
        char p[256];
        int rc = entry_path(c, "vary", v, s->n_vary, TIPPE_OPTIMISE_MAX_VARY,
                            "continuous parameters", p, sizeof p);
        if (rc)
            return rc;
        if (!cJSON_IsArray(v) || cJSON_GetArraySize(v) != 2 ||
            !cJSON_IsNumber(cJSON_GetArrayItem(v, 0)) || !cJSON_IsNumber(cJSON_GetArrayItem(v, 1)))
            return tippe_json_wrong_type(c, p, "[from, to] (two numbers)", v);
        vary_t *w = &s->vary[s->n_vary++];
        snprintf(w->path, sizeof w->path, "%s", v->string);
        w->lo = cJSON_GetArrayItem(v, 0)->valuedouble;
        w->hi = cJSON_GetArrayItem(v, 1)->valuedouble;
        if (!isfinite(w->lo) || !isfinite(w->hi) || !(w->lo < w->hi) ||
            fabs(w->lo) > 1e4 || fabs(w->hi) > 1e4)
            return tippe_json_fail(c, p, "must be [from, to] with from < to, both within "
                                         "+-10000 (mm), got [%g, %g]", w->lo, w->hi);
    }
    return TIPPE_OK;
}

/* The options of a catalogue choice: every item (or the named ones) sets the
 * part's radius_mm and height_mm. */
static int catalogue_options(tippe_json_reader *c, const char *cpath, const cJSON *spec_item,
                             const char *part_path, const char *spec_path, choose_t *ch)
{
    char p[256], file[1024], name[96];
    tippe_json_path(p, sizeof p, cpath, "catalogue");
    int rc = tippe_json_check_keys(c, spec_item, cpath, "a catalogue choice", choose_cat_keys,
                                   NULL);
    if (rc)
        return rc;
    if ((rc = tippe_json_string(c, spec_item, cpath, "catalogue", 1, name, sizeof name, NULL)))
        return rc;
    const cJSON *want = cJSON_GetObjectItemCaseSensitive(spec_item, "items");
    if (want && (!cJSON_IsArray(want) || cJSON_GetArraySize(want) < 1)) {
        tippe_json_path(p, sizeof p, cpath, "items");
        return tippe_json_wrong_type(c, p, "a non-empty array of item names", want);
    }
    /* The catalogue file: "catalogue" at the spec's top, default catalogue.json
     * beside the base design; read as tippe build reads it. */
    snprintf(file, sizeof file, "%s", spec_path);
    tippe_build_catalogue *cat = NULL;
    if ((rc = tippe_build_catalogue_load(file, &cat, c->err)))
        return rc;
    const tippe_build_catalogue_set *set = NULL;
    for (int k = 0; k < cat->n_sets && !set; k++)
        if (!strcmp(cat->sets[k].key, name))
            set = &cat->sets[k];
    if (!set)
        rc = tippe_json_fail(c, p, "no catalogue '%s' in %s", name, file);
    int n = 0;
    if (!rc && !(ch->opt = calloc((size_t)set->n_items, sizeof *ch->opt)))
        rc = tippe_error_set(c->err, TIPPE_ECOMPUTE, "out of memory");
    for (int i = 0; !rc && i < set->n_items; i++) {
        const tippe_build_catalogue_item *it = &set->items[i];
        int take = !want;
        for (const cJSON *w = want ? want->child : NULL; w; w = w->next)
            take |= cJSON_IsString(w) && !strcmp(w->valuestring, it->name);
        if (!take)
            continue;
        option_t *o = &ch->opt[n++];
        snprintf(o->label, sizeof o->label, "%s", it->name);
        snprintf(o->set[0], sizeof o->set[0], "%s.radius_mm=%.17g", part_path, it->radius_mm);
        snprintf(o->set[1], sizeof o->set[1], "%s.height_mm=%.17g", part_path, it->height_mm);
        /* the part is the item: tippe build names it (docs/design-format.md) */
        snprintf(o->set[2], sizeof o->set[2], "%s.catalogue_item=%s", part_path, it->name);
        o->n_set = 3;
    }
    for (const cJSON *w = want ? want->child : NULL; !rc && w; w = w->next) {
        int found = 0;
        for (int k = 0; k < n; k++)
            found |= cJSON_IsString(w) && !strcmp(ch->opt[k].label, w->valuestring);
        if (!found) {
            tippe_json_path(p, sizeof p, cpath, "items");
            rc = tippe_json_fail(c, p, "'%s' is not an item of catalogue '%s'",
                                 cJSON_IsString(w) ? w->valuestring : "?", name);
        }
    }
    if (!rc && n == 0) {
        tippe_json_path(p, sizeof p, cpath, "items");
        rc = tippe_json_fail(c, p, "names no item of catalogue '%s'", name);
    }
    ch->n = n;
    tippe_build_catalogue_free(cat);
    return rc;
}

static int parse_choose(tippe_json_reader *c, const cJSON *choose, const char *catalogue_file,
                        tippe_optimise_spec *s)
{
    if (!choose)
        return TIPPE_OK;
    if (!cJSON_IsObject(choose))
        return tippe_json_wrong_type(c, "choose", "an object {FIELD: [options]}", choose);
    for (const cJSON *v = choose->child; v; v = v->next) {
        char p[256];
        int rc = entry_path(c, "choose", v, s->n_choose, MAX_CHOOSE, "discrete choices", p,
                            sizeof p);
        if (rc)
            return rc;
        choose_t *ch = &s->choose[s->n_choose++];
        snprintf(ch->path, sizeof ch->path, "%s", v->string);
        if (cJSON_IsObject(v)) {
            if (strncmp(v->string, "parts.", 6) || strchr(v->string + 6, '.'))
                return tippe_json_fail(c, p, "a catalogue choice is keyed by a part "
                                             "(parts.NAME), whose radius_mm and height_mm "
                                             "each item sets");
            rc = catalogue_options(c, p, v, v->string, catalogue_file, ch);
            if (rc)
                return rc;
            snprintf(s->catalogue_file, sizeof s->catalogue_file, "%s", catalogue_file);
            continue;
        }
        int n = cJSON_IsArray(v) ? cJSON_GetArraySize(v) : 0;
        if (n < 1 || n > MAX_OPTIONS)
            return tippe_json_fail(c, p, "must be an array of 1 to %d options (strings or "
                                         "numbers) or {\"catalogue\": NAME}", MAX_OPTIONS);
        if (!(ch->opt = calloc((size_t)n, sizeof *ch->opt)))
            return tippe_error_set(c->err, TIPPE_ECOMPUTE, "out of memory");
        int k = 0;
        for (const cJSON *o = v->child; o; o = o->next, k++) {
            char op[300];
            snprintf(op, sizeof op, "%s[%d]", p, k);
            option_t *opt = &ch->opt[k];
            if (cJSON_IsString(o) && o->valuestring[0] && strlen(o->valuestring) < 80) {
                if ((rc = tippe_json_check_text(c, op, o->valuestring, 0)))
                    return rc;
                snprintf(opt->label, sizeof opt->label, "%s", o->valuestring);
                snprintf(opt->set[0], sizeof opt->set[0], "%s=%s", v->string, o->valuestring);
            } else if (cJSON_IsNumber(o) && isfinite(o->valuedouble)) {
                snprintf(opt->label, sizeof opt->label, "%.10g", o->valuedouble);
                snprintf(opt->set[0], sizeof opt->set[0], "%s=%.17g", v->string,
                         o->valuedouble);
            } else {
                return tippe_json_wrong_type(c, op, "a number or a short non-empty string", o);
            }
            opt->n_set = 1;
        }
        ch->n = n;
    }
    return TIPPE_OK;
}

static int parse_tie(tippe_json_reader *c, const cJSON *tie, const cJSON *design_root,
                     tippe_optimise_spec *s)
{
    if (!tie)
        return TIPPE_OK;
    if (!cJSON_IsObject(tie))
        return tippe_json_wrong_type(c, "tie", "an object {FIELD: OTHER_FIELD}", tie);
    for (const cJSON *v = tie->child; v; v = v->next) {
        char p[256];
        int rc = entry_path(c, "tie", v, s->n_tie, MAX_TIE, "ties", p, sizeof p);
        if (rc)
            return rc;
        tie_t *t = &s->tie[s->n_tie++];
        snprintf(t->path, sizeof t->path, "%s", v->string);
        t->times = 1.0;
        t->plus_mm = 0.0;
        char follows[TIPPE_OPTIMISE_PATH_LEN] = "";
        if (cJSON_IsString(v)) {
            snprintf(follows, sizeof follows, "%s", v->valuestring);
        } else if (cJSON_IsObject(v)) {
            if ((rc = tippe_json_check_keys(c, v, p, "a tie", tie_keys, NULL)) ||
                (rc = tippe_json_string(c, v, p, "follows", 1, follows, sizeof follows, NULL)) ||
                (rc = tippe_json_number(c, v, p, "plus_mm", 0, &t->plus_mm, NULL)) ||
                (rc = tippe_json_number(c, v, p, "times", 0, &t->times, NULL)))
                return rc;
            if (!(fabs(t->plus_mm) <= 1e3) || !(fabs(t->times) <= 1e3) || t->times == 0)
                return tippe_json_fail(c, p, "plus_mm must be within +-1000 mm and times "
                                             "within +-1000, not 0");
        } else {
            return tippe_json_wrong_type(c, p, "a field path or {\"follows\", \"plus_mm\", "
                                               "\"times\"}", v);
        }
        snprintf(t->follows, sizeof t->follows, "%s", follows);
        t->vary_index = -1;
        for (int k = 0; k < s->n_vary; k++)
            if (!strcmp(s->vary[k].path, follows))
                t->vary_index = k;
        t->base_value = design_number(design_root, follows);
        for (int k = 0; k < s->n_vary; k++)
            if (!strcmp(s->vary[k].path, t->path))
                return tippe_json_fail(c, p, "is also varied: a field either varies or follows");
        int set_by_choice = 0;
        for (int k = 0; k < s->n_choose; k++) {
            size_t n = strlen(s->choose[k].path);
            set_by_choice |= !strcmp(s->choose[k].path, follows) ||
                             (!strncmp(s->choose[k].path, follows, n) && follows[n] == '.');
        }
        for (int k = 0; k < s->n_choose; k++)
            for (int o = 0; o < s->choose[k].n; o++)
                for (int j = 0; j < s->choose[k].opt[o].n_set; j++) {
                    const char *set = s->choose[k].opt[o].set[j];
                    size_t n = strlen(t->path);
                    if (!strncmp(set, t->path, n) && set[n] == '=')
                        return tippe_json_fail(c, p, "is also set by the choice '%s': a field "
                                                     "either is chosen or follows", set);
                }
        int follows_tie = 0;
        for (const cJSON *w = tie->child; w; w = w->next)
            follows_tie |= w != v && !strcmp(w->string, follows);
        if (t->vary_index < 0 && !set_by_choice && !follows_tie && isnan(t->base_value))
            return tippe_json_fail(c, p, "follows '%s', which is neither varied, nor chosen, "
                                         "nor tied, nor a number in the base design", follows);
    }
    /* A tie may follow another tie's field (a chain): its value is computed
     * from the other's, whatever their order in the file. A cycle has no
     * value and is refused. */
    for (int k = 0; k < s->n_tie; k++) {
        s->tie[k].tie_index = -1;
        for (int j = 0; j < s->n_tie; j++)
            if (j != k && !strcmp(s->tie[j].path, s->tie[k].follows))
                s->tie[k].tie_index = j;
        if (!strcmp(s->tie[k].path, s->tie[k].follows))
            return tippe_json_fail(c, "tie", "'%s' follows itself", s->tie[k].path);
    }
    for (int k = 0; k < s->n_tie; k++) {
        int j = k;
        for (int steps = 0; steps <= s->n_tie && j >= 0; steps++) {
            j = s->tie[j].tie_index;
            if (j == k)
                return tippe_json_fail(c, "tie", "'%s' is in a cycle of ties (each follows "
                                                 "the next, back to itself): no value "
                                                 "satisfies it", s->tie[k].path);
        }
    }
    return TIPPE_OK;
}

static int parse_constraints(tippe_json_reader *c, const cJSON *con, tippe_optimise_spec *s)
{
    /* Unset (-1): two perimeters of the hole's part as printed (its print block,
     * else tippe_print_defaults: 2 x 0.45 mm). */
    s->min_wall_mm = -1.0;
    s->eps_max_min_mm = 0.0;
    s->spin_max_rev_s = INFINITY;
    s->max_weight_g = INFINITY;
    if (!con)
        return TIPPE_OK;
    if (!cJSON_IsObject(con))
        return tippe_json_wrong_type(c, "constraints", "an object", con);
    int rc;
    if ((rc = tippe_json_check_keys(c, con, "constraints", "the constraints", constraint_keys,
                                    NULL)) ||
        (rc = tippe_json_number(c, con, "constraints", "eps_max_min_mm", 0, &s->eps_max_min_mm,
                                NULL)) ||
        (rc = tippe_json_number(c, con, "constraints", "spin_max_rev_s", 0, &s->spin_max_rev_s,
                                NULL)) ||
        (rc = tippe_json_number(c, con, "constraints", "min_wall_mm", 0, &s->min_wall_mm,
                                NULL)) ||
        (rc = tippe_json_number(c, con, "constraints", "max_weight_g", 0, &s->max_weight_g,
                                NULL)))
        return rc;
    if (!(s->eps_max_min_mm >= 0 && s->eps_max_min_mm < 1e3))
        return tippe_json_fail(c, "constraints.eps_max_min_mm", "must be in [0, 1000) mm, got %g",
                               s->eps_max_min_mm);
    if (!(s->spin_max_rev_s > 0 && s->spin_max_rev_s <= 1e4) && !isinf(s->spin_max_rev_s))
        return tippe_json_fail(c, "constraints.spin_max_rev_s",
                               "must be in (0, 10000] rev/s, got %g", s->spin_max_rev_s);
    if (s->min_wall_mm != -1.0 && !(s->min_wall_mm >= 0 && s->min_wall_mm <= 100))
        return tippe_json_fail(c, "constraints.min_wall_mm", "must be in [0, 100] mm, got %g",
                               s->min_wall_mm);
    if (!(s->max_weight_g > 0 && s->max_weight_g <= 1e6) && !isinf(s->max_weight_g))
        return tippe_json_fail(c, "constraints.max_weight_g", "must be in (0, 1e6] g, got %g",
                               s->max_weight_g);
    return TIPPE_OK;
}

static int parse_search(tippe_json_reader *c, const cJSON *root, tippe_optimise_spec *s)
{
    char obj[32] = "robust_narrowest_zone";
    int rc = tippe_json_string(c, root, "", "objective", 0, obj, sizeof obj, NULL);
    if (rc)
        return rc;
    if (!strcmp(obj, "robust_narrowest_zone"))
        s->robust = 1;
    else if (strcmp(obj, "narrowest_zone"))
        return tippe_json_fail(c, "objective",
                               "must be \"narrowest_zone\" or \"robust_narrowest_zone\", not '%s'",
                               obj);
    s->algorithm = ALG_DIRECT_L;
    s->polish = POLISH_COBYLA;
    s->evals = 1500;
    /* COBYLA stops by itself when its steps fall below 1e-7 mm: the cap
     * costs only where it is still climbing (the 6-parameter band family). */
    s->polish_evals = 1000;
    const cJSON *se = cJSON_GetObjectItemCaseSensitive(root, "search");
    if (!se)
        return TIPPE_OK;
    if (!cJSON_IsObject(se))
        return tippe_json_wrong_type(c, "search", "an object", se);
    char alg[16] = "DIRECT-L", pol[16] = "COBYLA";
    double ev = (double)s->evals, pev = (double)s->polish_evals;
    if ((rc = tippe_json_check_keys(c, se, "search", "the search", search_keys, NULL)) ||
        (rc = tippe_json_string(c, se, "search", "algorithm", 0, alg, sizeof alg, NULL)) ||
        (rc = tippe_json_string(c, se, "search", "polish", 0, pol, sizeof pol, NULL)) ||
        (rc = tippe_json_number(c, se, "search", "evaluations", 0, &ev, NULL)) ||
        (rc = tippe_json_number(c, se, "search", "polish_evaluations", 0, &pev, NULL)))
        return rc;
    int a = 0, q = 0;
    while (a < N_ALG && strcmp(alg, alg_names[a]))
        a++;
    while (q < N_POLISH && strcmp(pol, polish_names[q]))
        q++;
    if (a == N_ALG)
        return tippe_json_fail(c, "search.algorithm",
                               "must be DIRECT-L, CRS2, MLSL or ISRES, not '%s'", alg);
    if (q == N_POLISH)
        return tippe_json_fail(c, "search.polish", "must be COBYLA, BOBYQA or none, not '%s'",
                               pol);
    if (!(ev >= 1 && ev <= 1e7 && ev == floor(ev)))
        return tippe_json_fail(c, "search.evaluations", "must be a whole number in 1 .. 1e7, "
                                                        "got %g", ev);
    if (!(pev >= 0 && pev <= 1e6 && pev == floor(pev)))
        return tippe_json_fail(c, "search.polish_evaluations",
                               "must be a whole number in 0 .. 1e6, got %g", pev);
    s->algorithm = (algorithm_t)a;
    s->polish = (polish_t)q;
    s->evals = (long)ev;
    s->polish_evals = (long)pev;
    return TIPPE_OK;
}

/* Every override path must exist in the design: applied once at the middle. */
/* A choice of materials names only materials of the base design's table
 * (exactly: names are case-sensitive), so that a misspelt option is refused
 * here rather than reported as a candidate that "does not fit". */
static int check_materials(tippe_json_reader *c, const tippe_optimise_spec *s)
{
    tippe_materials *tab = NULL;
    for (int k = 0; k < s->n_choose; k++) {
        const choose_t *ch = &s->choose[k];
        size_t n = strlen(ch->path);
        if (n < 8 || strcmp(ch->path + n - 8, "material") ||
            (n > 8 && ch->path[n - 9] != '.'))
            continue;
        if (!tab) {
            tippe_error e = {0};
            if (tippe_design_source_materials(s->src, &tab, &e)) {
                tippe_materials_free(tab);
                return tippe_json_fail(c, "choose", "%s", e.msg);
            }
        }
        for (int o = 0; o < ch->n; o++) {
            const char *want = ch->opt[o].label, *near = NULL;
            int found = 0;
            for (int i = 0; i < tippe_materials_count(tab) && !found; i++) {
                tippe_material m;
                tippe_materials_get(tab, i, &m);
                found = !strcmp(m.name, want);
                if (!strcasecmp(m.name, want))
                    near = m.name;
            }
            if (!found) {
                char p[300];
                snprintf(p, sizeof p, "choose.%s[%d]", ch->path, o);
                int rc = near ? tippe_json_fail(c, p, "unknown material '%s' (did you mean "
                                                      "'%s'? names are case-sensitive)",
                                                want, near)
                              : tippe_json_fail(c, p, "unknown material '%s': not in the "
                                                      "materials table ('tippe materials %s' "
                                                      "lists its names)", want, s->design_path);
                tippe_materials_free(tab);
                return rc;
            }
        }
    }
    tippe_materials_free(tab);
    return TIPPE_OK;
}

static int check_paths(tippe_json_reader *c, tippe_optimise_spec *s)
{
    int rc = check_materials(c, s);
    if (rc)
        return rc;
    double x[TIPPE_OPTIMISE_MAX_VARY];
    for (int k = 0; k < s->n_vary; k++)
        x[k] = 0.5 * (s->vary[k].lo + s->vary[k].hi);
    for (int ch = 0; ch < s->n_choices; ch++) {
        char buf[TIPPE_OPTIMISE_MAX_VARY + MAX_CHOOSE * MAX_SETS_PER_OPTION + MAX_TIE][256];
        int n = tippe_optimise_overrides(s, ch, x, buf, (int)(sizeof buf / sizeof buf[0]));
        const char *ov[sizeof buf / sizeof buf[0]];
        for (int i = 0; i < n; i++)
            ov[i] = buf[i];
        cJSON *root = NULL;
        tippe_error e = {0};
        rc = tippe_design_source_apply(s->src, ov, n, &root, &e);
        cJSON_Delete(root);
        if (rc)
            return tippe_json_fail(c, NULL, "%s", e.msg);
        if (ch > 0 && s->n_choose == 0)
            break;
        if (ch >= 64) /* every option has been applied once by then in practice */
            break;
    }
    return TIPPE_OK;
}

int tippe_optimise_spec_load(const char *path, tippe_optimise_spec **out, tippe_error *err)
{
    *out = NULL;
    tippe_json_reader *c = tippe_json_reader_new(path, err, TIPPE_JSON_WORDS_FIELD, NULL);
    tippe_optimise_spec *s = calloc(1, sizeof *s);
    if (!c || !s || !(s->path = dup_str(path))) {
        free(c);
        free(s);
        return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    }
    cJSON *root = NULL, *droot = NULL;
    char design_rel[512], design[1024], cat_rel[512] = "", cat[1024] = "";
    int rc = tippe_json_load(c, MAX_SPEC_MIB, "optimisation spec", &root);
    if (!rc)
        rc = tippe_json_check_duplicates(c, root, "");
    if (!rc && !cJSON_IsObject(root))
        rc = tippe_json_wrong_type(c, NULL, "a JSON object (an optimisation spec)", root);
    if (!rc)
        rc = tippe_json_check_keys(c, root, "", "an optimisation spec", spec_keys, NULL);
    if (!rc)
        rc = tippe_json_string(c, root, "", "name", 0, s->name, sizeof s->name, NULL);
    if (!rc)
        rc = tippe_json_text(c, root, "", "notes", 0, NULL, 0, NULL);
    if (!rc)
        rc = tippe_json_string(c, root, "", "design", 1, design_rel, sizeof design_rel, NULL);
    if (!rc)
        rc = tippe_json_string(c, root, "", "catalogue", 0, cat_rel, sizeof cat_rel, NULL);
    if (!rc) {
        tippe_path_beside(path, design_rel, design, sizeof design);
        tippe_error e = {0};
        rc = tippe_design_source_open(design, &s->src, &e);
        if (rc)
            rc = tippe_json_fail(c, "design", "%s", e.msg);
        else if (!(s->design_path = dup_str(design)))
            rc = tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    }
    if (!rc) {
        tippe_error e = {0};
        rc = tippe_design_source_apply(s->src, NULL, 0, &droot, &e);
        if (rc)
            rc = tippe_error_set(err, rc, "%s", e.msg);
    }
    if (cat_rel[0]) {
        tippe_path_beside(path, cat_rel, cat, sizeof cat);
    } else if (!rc) { /* the base design's, as tippe build finds it */
        tippe_design *base = NULL;
        tippe_error e = {0};
        if (tippe_design_source_build(s->src, NULL, 0, 0, &base, &e) == TIPPE_OK) {
            const char *own = tippe_build_catalogue_file(base, cat, sizeof cat);
            if (own && own != cat)
                snprintf(cat, sizeof cat, "%s", own);
        }
        tippe_design_free(base);
    }
    if (!rc)
        rc = parse_vary(c, cJSON_GetObjectItemCaseSensitive(root, "vary"), s);
    if (!rc)
        rc = parse_choose(c, cJSON_GetObjectItemCaseSensitive(root, "choose"), cat, s);
    if (!rc)
        rc = parse_tie(c, cJSON_GetObjectItemCaseSensitive(root, "tie"), droot, s);
    if (!rc)
        rc = parse_constraints(c, cJSON_GetObjectItemCaseSensitive(root, "constraints"), s);
    if (!rc)
        rc = parse_search(c, root, s);
    if (!rc) {
        long n = 1;
        for (int k = 0; k < s->n_choose && n <= MAX_CHOICES; k++)
            n *= s->choose[k].n;
        if (n > MAX_CHOICES)
            rc = tippe_json_fail(c, "choose", "more than %d combinations of options",
                                 MAX_CHOICES);
        s->n_choices = (int)n;
    }
    if (!rc && s->n_vary == 0 && s->n_choices == 1)
        rc = tippe_json_fail(c, NULL, "nothing to search: give \"vary\" or \"choose\"");
    if (!rc)
        rc = check_paths(c, s);
    if (!s->name[0] && !rc)
        snprintf(s->name, sizeof s->name, "%s", path);
    cJSON_Delete(root);
    cJSON_Delete(droot);
    free(c);
    if (rc) {
        tippe_optimise_spec_free(s);
        return rc;
    }
    *out = s;
    return TIPPE_OK;
}

void tippe_optimise_spec_free(tippe_optimise_spec *s)
{
    if (!s)
        return;
    for (int k = 0; k < s->n_choose; k++)
        free(s->choose[k].opt);
    tippe_design_source_free(s->src);
    free(s->path);
    free(s->design_path);
    free(s);
}

int tippe_optimise_spec_n_vary(const tippe_optimise_spec *s) { return s->n_vary; }
const char *tippe_optimise_spec_vary_path(const tippe_optimise_spec *s, int k) { return s->vary[k].path; }
int tippe_optimise_spec_n_choices(const tippe_optimise_spec *s) { return s->n_choices; }
const char *tippe_optimise_spec_path(const tippe_optimise_spec *s) { return s->path; }

const char *tippe_optimise_spec_choice_label(const tippe_optimise_spec *s, int choice, char *buf,
                                        size_t cap)
{
    int idx[MAX_CHOOSE];
    tippe_optimise_choice_options(s, choice, idx);
    size_t n = 0;
    buf[0] = '\0';
    for (int k = 0; k < s->n_choose && n < cap; k++) {
        int w = snprintf(buf + n, cap - n, "%s%s", k ? ", " : "", s->choose[k].opt[idx[k]].label);
        if (w > 0)
            n += (size_t)w;
    }
    if (!s->n_choose)
        snprintf(buf, cap, "(one choice)");
    return buf;
}
