/* Search a design space for the widest narrowest zone (see tippe/optimise.h).
 *
 * The spec is read strictly (tippe/json.h). A candidate is the base design with
 * overrides, built from a design source held in memory (no file is read per
 * candidate), with its physical travel as its travel; its zones come from the
 * root-found sweep. NLopt searches each choice on its own thread; nothing is
 * shared between choices but the read-only spec, so the result does not depend
 * on how many threads there are. */
#include "tippe/optimise.h"
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

#define MAX_CHOOSE 4
#define MAX_TIE 8
#define MAX_SETS_PER_OPTION 4
#define MAX_OPTIONS 400
#define MAX_CHOICES 2000
#define MAX_SPEC_MIB 1
/* Search sweeps use fewer scan intervals than a report (2000): a zone end is
 * still root-found to 1e-7 mm, only a boundary touched twice within one
 * interval (75 um over a 30 mm travel) could be missed; every reported best
 * is re-evaluated with the full sweep. */
#define SEARCH_SCAN 400
#define TIPPE_PI 3.14159265358979323846

typedef struct {
    char path[TIPPE_OPT_PATH_LEN];
    double lo, hi;
} vary_t;

typedef struct {
    char label[96];
    int n_set;
    char set[MAX_SETS_PER_OPTION][256];
} option_t;

typedef struct {
    char path[TIPPE_OPT_PATH_LEN];
    int n;
    option_t *opt;
} choose_t;

typedef struct {
    char path[TIPPE_OPT_PATH_LEN], follows[TIPPE_OPT_PATH_LEN];
    double plus_mm, times;
    int vary_index;   /* follows a vary parameter, or -1 */
    int tie_index;    /* follows another tie's field (a chain), or -1 */
    double base_value; /* the followed field in the base design (NAN if absent) */
} tie_t;

typedef enum { ALG_DIRECT_L, ALG_CRS2, ALG_MLSL, ALG_ISRES, N_ALG } algorithm_t;
static const char *const alg_names[N_ALG] = {"DIRECT-L", "CRS2", "MLSL", "ISRES"};
typedef enum { POLISH_COBYLA, POLISH_BOBYQA, POLISH_NONE, N_POLISH } polish_t;
static const char *const polish_names[N_POLISH] = {"COBYLA", "BOBYQA", "none"};

struct tippe_opt_spec {
    char *path, *design_path;
    char name[256];
    tippe_design_source *src;
    int n_vary;
    vary_t vary[TIPPE_OPT_MAX_VARY];
    int n_choose;
    choose_t choose[MAX_CHOOSE];
    int n_tie;
    tie_t tie[MAX_TIE];
    double eps_max_min_mm, spin_max_rev_s, min_wall_mm, max_weight_g;
    int robust;
    algorithm_t algorithm;
    polish_t polish;
    long evals, polish_evals;
    int n_choices;
};

static const char *const spec_keys[] = {"name",   "notes",       "design",    "catalogue",
                                        "vary",   "choose",      "tie",       "constraints",
                                        "objective", "search",   NULL};
static const char *const constraint_keys[] = {"eps_max_min_mm", "spin_max_rev_s", "min_wall_mm",
                                              "max_weight_g", NULL};
static const char *const search_keys[] = {"algorithm", "evaluations", "polish",
                                          "polish_evaluations", NULL};
static const char *const tie_keys[] = {"follows", "plus_mm", "times", NULL};
static const char *const choose_cat_keys[] = {"catalogue", "items", NULL};
static const char *const catalogue_keys[] = {"title", "source", "notes", "items", NULL};
static const char *const item_keys[] = {"name", "thread", "d_mm", "pitch_mm", "length_mm",
                                        "radius_mm", "height_mm", "socket_s_mm",
                                        "socket_t_mm", NULL};

const char *tippe_opt_status_name(tippe_opt_status s)
{
    static const char *const names[] = {"ok", "does not fit", "thin wall", "too heavy",
                                        "eps_max too small", "flip spin too high",
                                        "no zones"};
    return (int)s >= 0 && (int)s <= (int)TIPPE_OPT_NO_ZONES ? names[s] : "?";
}

void tippe_opt_options_default(tippe_opt_options *o)
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

/* dir of path + rel (rel absolute: itself). */
static void relative_to(char *out, size_t cap, const char *path, const char *rel)
{
    const char *slash = strrchr(path, '/');
    if (rel[0] == '/' || !slash)
        snprintf(out, cap, "%s", rel);
    else
        snprintf(out, cap, "%.*s/%s", (int)(slash - path), path, rel);
}

/* ---- reading the spec ------------------------------------------------------ */

/* A number in the design's JSON at an override path ("parts.NAME.KEY" or a
 * top-level key); NAN if absent or not a number. */
static double design_number(const cJSON *root, const char *path)
{
    const cJSON *obj = root;
    const char *key = path;
    char name[TIPPE_OPT_PATH_LEN];
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
    if (strlen(v->string) >= TIPPE_OPT_PATH_LEN || strchr(v->string, '='))
        return tippe_json_fail(c, p, "not a field path");
    return TIPPE_OK;
}

static int parse_vary(tippe_json_reader *c, const cJSON *vary, tippe_opt_spec *s)
{
    if (!vary)
        return TIPPE_OK;
    if (!cJSON_IsObject(vary))
        return tippe_json_wrong_type(c, "vary", "an object {FIELD: [from, to]}", vary);
    for (const cJSON *v = vary->child; v; v = v->next) {
        char p[256];
        int rc = entry_path(c, "vary", v, s->n_vary, TIPPE_OPT_MAX_VARY,
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
     * beside the base design. */
    snprintf(file, sizeof file, "%s", spec_path);
    tippe_json_reader *cc = tippe_json_reader_new(file, c->err, TIPPE_JSON_WORDS_FIELD, NULL);
    if (!cc)
        return TIPPE_ECOMPUTE;
    cJSON *cat = NULL;
    rc = tippe_json_load(cc, MAX_SPEC_MIB, "catalogue", &cat);
    if (!rc)
        rc = tippe_json_check_duplicates(cc, cat, "");
    const cJSON *set = NULL;
    if (!rc && !cJSON_IsObject(cat))
        rc = tippe_json_wrong_type(cc, NULL, "an object of named catalogues", cat);
    if (!rc && !(set = cJSON_GetObjectItemCaseSensitive(cat, name)))
        rc = tippe_json_fail(c, p, "no catalogue '%s' in %s", name, file);
    const cJSON *items = NULL;
    if (!rc)
        rc = tippe_json_check_keys(cc, set, name, "a catalogue", catalogue_keys, NULL);
    if (!rc) {
        items = cJSON_GetObjectItemCaseSensitive(set, "items");
        if (!cJSON_IsArray(items) || cJSON_GetArraySize(items) < 1)
            rc = tippe_json_wrong_type(cc, name, "an object with a non-empty items array",
                                       items);
    }
    int n = 0;
    if (!rc) {
        ch->opt = calloc((size_t)cJSON_GetArraySize(items), sizeof *ch->opt);
        if (!ch->opt)
            rc = tippe_error_set(c->err, TIPPE_ECOMPUTE, "out of memory");
    }
    int idx = 0;
    for (const cJSON *it = items ? items->child : NULL; !rc && it; it = it->next, idx++) {
        char ip[160], iname[96];
        snprintf(ip, sizeof ip, "%s.items[%d]", name, idx);
        double r = 0, h = 0;
        if ((rc = tippe_json_check_keys(cc, it, ip, "a catalogue item", item_keys, NULL)) ||
            (rc = tippe_json_string(cc, it, ip, "name", 1, iname, sizeof iname, NULL)) ||
            (rc = tippe_json_number(cc, it, ip, "radius_mm", 1, &r, NULL)) ||
            (rc = tippe_json_number(cc, it, ip, "height_mm", 1, &h, NULL)))
            break;
        if (!(r > 0) || !(h > 0)) {
            rc = tippe_json_fail(cc, ip, "radius_mm and height_mm must be positive");
            break;
        }
        int take = !want;
        for (const cJSON *w = want ? want->child : NULL; w; w = w->next)
            take |= cJSON_IsString(w) && !strcmp(w->valuestring, iname);
        if (!take)
            continue;
        option_t *o = &ch->opt[n++];
        snprintf(o->label, sizeof o->label, "%s", iname);
        snprintf(o->set[0], sizeof o->set[0], "%s.radius_mm=%.17g", part_path, r);
        snprintf(o->set[1], sizeof o->set[1], "%s.height_mm=%.17g", part_path, h);
        o->n_set = 2;
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
    cJSON_Delete(cat);
    free(cc);
    return rc;
}

static int parse_choose(tippe_json_reader *c, const cJSON *choose, const char *catalogue_file,
                        tippe_opt_spec *s)
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
                     tippe_opt_spec *s)
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
        char follows[TIPPE_OPT_PATH_LEN] = "";
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

static int parse_constraints(tippe_json_reader *c, const cJSON *con, tippe_opt_spec *s)
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

static int parse_search(tippe_json_reader *c, const cJSON *root, tippe_opt_spec *s)
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
static int check_materials(tippe_json_reader *c, const tippe_opt_spec *s)
{
    tippe_materials *tab = NULL;
    for (int k = 0; k < s->n_choose; k++) {
        const choose_t *ch = &s->choose[k];
        size_t n = strlen(ch->path);
        if (n < 8 || strcmp(ch->path + n - 8, "material") ||
            (n > 8 && ch->path[n - 9] != '.'))
            continue;
        if (!tab) {
            char file[1024];
            tippe_error e = {0};
            if (tippe_design_materials_file(s->design_path, file, sizeof file, &e) ||
                tippe_materials_load(file, &tab, &e)) {
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

static int check_paths(tippe_json_reader *c, tippe_opt_spec *s)
{
    int rc = check_materials(c, s);
    if (rc)
        return rc;
    double x[TIPPE_OPT_MAX_VARY];
    for (int k = 0; k < s->n_vary; k++)
        x[k] = 0.5 * (s->vary[k].lo + s->vary[k].hi);
    for (int ch = 0; ch < s->n_choices; ch++) {
        char buf[TIPPE_OPT_MAX_VARY + MAX_CHOOSE * MAX_SETS_PER_OPTION + MAX_TIE][256];
        int n = tippe_opt_overrides(s, ch, x, buf, (int)(sizeof buf / sizeof buf[0]));
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

int tippe_opt_spec_load(const char *path, tippe_opt_spec **out, tippe_error *err)
{
    *out = NULL;
    tippe_json_reader *c = tippe_json_reader_new(path, err, TIPPE_JSON_WORDS_FIELD, NULL);
    tippe_opt_spec *s = calloc(1, sizeof *s);
    if (!c || !s || !(s->path = dup_str(path))) {
        free(c);
        free(s);
        return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    }
    cJSON *root = NULL, *droot = NULL;
    char design_rel[512], design[1024], cat_rel[512] = "", cat[1024];
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
        rc = tippe_json_string(c, root, "", "notes", 0, NULL, 0, NULL);
    if (!rc)
        rc = tippe_json_string(c, root, "", "design", 1, design_rel, sizeof design_rel, NULL);
    if (!rc)
        rc = tippe_json_string(c, root, "", "catalogue", 0, cat_rel, sizeof cat_rel, NULL);
    if (!rc) {
        relative_to(design, sizeof design, path, design_rel);
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
    if (cat_rel[0])
        relative_to(cat, sizeof cat, path, cat_rel);
    else
        relative_to(cat, sizeof cat, design, "catalogue.json");
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
        tippe_opt_spec_free(s);
        return rc;
    }
    *out = s;
    return TIPPE_OK;
}

void tippe_opt_spec_free(tippe_opt_spec *s)
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

int tippe_opt_spec_n_vary(const tippe_opt_spec *s) { return s->n_vary; }
const char *tippe_opt_spec_vary_path(const tippe_opt_spec *s, int k) { return s->vary[k].path; }
int tippe_opt_spec_n_choices(const tippe_opt_spec *s) { return s->n_choices; }
const char *tippe_opt_spec_path(const tippe_opt_spec *s) { return s->path; }
const tippe_design_source *tippe_opt_spec_design(const tippe_opt_spec *s) { return s->src; }

/* The option of each choose entry in combination `choice` (mixed radix, the
 * first entry varying slowest). */
static void choice_options(const tippe_opt_spec *s, int choice, int *idx)
{
    for (int k = s->n_choose - 1; k >= 0; k--) {
        idx[k] = choice % s->choose[k].n;
        choice /= s->choose[k].n;
    }
}

const char *tippe_opt_spec_choice_label(const tippe_opt_spec *s, int choice, char *buf,
                                        size_t cap)
{
    int idx[MAX_CHOOSE];
    choice_options(s, choice, idx);
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

/* ---- one candidate --------------------------------------------------------- */

/* The value the tie's field follows, for candidate (options idx, x). */
static double tie_source(const tippe_opt_spec *s, const tie_t *t, const int *idx, const double *x)
{
    if (t->vary_index >= 0)
        return x[t->vary_index];
    for (int k = 0; k < s->n_choose; k++) {
        const option_t *o = &s->choose[k].opt[idx[k]];
        for (int j = 0; j < o->n_set; j++) {
            size_t n = strlen(t->follows);
            if (!strncmp(o->set[j], t->follows, n) && o->set[j][n] == '=') {
                char *end = NULL;
                double v = strtod(o->set[j] + n + 1, &end);
                if (end && !*end)
                    return v;
            }
        }
    }
    return t->base_value;
}

/* Tie k's value: along a chain, each link's value from the one it follows
 * (the spec load refused cycles, so the chain ends within n_tie links). */
static double tie_value(const tippe_opt_spec *s, int k, const int *idx, const double *x)
{
    const tie_t *t = &s->tie[k];
    double from = t->tie_index >= 0 ? tie_value(s, t->tie_index, idx, x)
                                    : tie_source(s, t, idx, x);
    return t->times * from + t->plus_mm;
}

int tippe_opt_overrides(const tippe_opt_spec *s, int choice, const double *x, char (*buf)[256],
                        int cap)
{
    int idx[MAX_CHOOSE], n = 0;
    choice_options(s, choice, idx);
    for (int k = 0; k < s->n_vary; k++) {
        if (n == cap)
            return -1;
        /* %.17g: the override is the exact double the search chose. */
        snprintf(buf[n++], 256, "%s=%.17g", s->vary[k].path, x[k]);
    }
    for (int k = 0; k < s->n_choose; k++) {
        const option_t *o = &s->choose[k].opt[idx[k]];
        for (int j = 0; j < o->n_set; j++) {
            if (n == cap)
                return -1;
            snprintf(buf[n++], 256, "%s", o->set[j]);
        }
    }
    for (int k = 0; k < s->n_tie; k++) {
        if (n == cap)
            return -1;
        snprintf(buf[n++], 256, "%s=%.17g", s->tie[k].path, tie_value(s, k, idx, x));
    }
    return n;
}

/* The widest run of group II within the travel (as tippe_sweep_summarise
 * measures it), or 0 if none. */
static int widest_ii_run(const tippe_sweep_result *r, double *from, double *to)
{
    double best = -1.0, f = 0.0;
    int in = 0;
    for (int i = 0; i <= r->n_zones; i++) {
        const tippe_sweep_zone *z = i < r->n_zones ? &r->zones[i] : NULL;
        int ii = z && z->within_travel && !strcmp(tippe_group_family(z->group), "II");
        if (ii && !in) {
            f = z->z2_from_mm;
            in = 1;
        }
        if (!ii && in) {
            double t = r->zones[i - 1].z2_to_mm;
            if (t - f > best) {
                best = t - f;
                *from = f;
                *to = t;
            }
            in = 0;
        }
    }
    return best > 0.0;
}

/* n* (section 7.1: the spin at theta = 0 that makes the inverted state
 * stable, i.e. the spin a hand must give for the top to flip) over the middle
 * half of zone II, where a maker sets the weight; n* grows without bound at
 * the II/III boundary, so the zone's ends cannot count. rev/s. */
static double flip_spin_rev_s(const tippe_design *d, double from, double to)
{
    double worst = 0.0;
    for (int j = 0; j <= 4; j++) {
        double z2 = from + (to - from) * (0.25 + 0.125 * j);
        tippe_top top;
        tippe_design_top_any(d, z2, &top);
        tippe_theory_thresholds th;
        tippe_error e = {0};
        if (tippe_theory_compute_thresholds(&top, TIPPE_DEFAULT_G_M_S2, &th, &e) != TIPPE_OK ||
            !th.has_n_star)
            return INFINITY;
        worst = fmax(worst, th.n_star_rad_s / (2.0 * TIPPE_PI));
    }
    return worst;
}

/* The tolerance bands of the sweep's zone ends and the widths that survive
 * them (tippe/sweep_bands.h); left unset if they cannot be computed. */
static void robust_widths(const tippe_design *d, const tippe_sweep_result *r, tippe_opt_eval *out)
{
    tippe_sweep_bands_result b;
    tippe_error e = {0};
    if (tippe_sweep_bands(d, r, &b, &e) == TIPPE_OK) {
        double narrow = 0.0;
        tippe_sweep_robust_widths(r, &b, out->robust_zone_mm, &narrow);
        out->robust_mm = narrow;
        out->has_robust = 1;
    }
    tippe_sweep_bands_free(&b);
}

/* Two perimeters around the hole: twice the line width of the part it is cut
 * from as printed (its print block), or of the slicer defaults
 * (tippe_print_defaults) for a part without one. */
static double perimeter_wall_mm(const tippe_design *d, const char *hole)
{
    tippe_print_settings set = tippe_print_defaults();
    int n = tippe_design_n_parts(d), parent = -1;
    tippe_design_part_info info;
    for (int i = 0; hole && i < n; i++)
        if (tippe_design_part(d, i, &info) == TIPPE_OK && !strcmp(info.name, hole))
            for (int j = 0; j < n && info.cut_from; j++) {
                tippe_design_part_info pj;
                if (tippe_design_part(d, j, &pj) == TIPPE_OK && !strcmp(pj.name, info.cut_from))
                    parent = j;
            }
    tippe_design_print_info pr;
    if (parent >= 0 && tippe_design_part_print(d, parent, &pr) == TIPPE_OK && pr.printed)
        set = pr.settings;
    return 2.0 * set.line_width_mm;
}

/* The constraints' margins of a candidate: relative (so that they add
 * across constraints), <= 0 where the constraint is met. */
enum { CON_EPS, CON_SPIN, CON_WALL, CON_WEIGHT, N_CON };

/* tippe_opt_evaluate, with the margins (the polish's constraints; the score's
 * violation is the sum of the positive ones). */
static void evaluate(const tippe_opt_spec *s, int choice, const double *x, int n_scan,
                     tippe_opt_eval *out, double margin[N_CON])
{
    memset(out, 0, sizeof *out);
    for (int k = 0; k < N_CON; k++)
        margin[k] = 1.0;
    out->choice = choice;
    for (int k = 0; k < s->n_vary; k++)
        out->x[k] = x[k];
    out->wall_mm = INFINITY;
    char buf[TIPPE_OPT_MAX_VARY + MAX_CHOOSE * MAX_SETS_PER_OPTION + MAX_TIE][256];
    const char *ov[sizeof buf / sizeof buf[0]];
    int n = tippe_opt_overrides(s, choice, x, buf, (int)(sizeof buf / sizeof buf[0]));
    for (int i = 0; i < n; i++)
        ov[i] = buf[i];
    tippe_design *d = NULL;
    tippe_error e = {0};
    /* Search candidates (n_scan > 0) are screened on the coarse layout grid; a
     * reported best (n_scan = 0) is built and swept at full resolution. */
    unsigned flags = TIPPE_DESIGN_TRAVEL_PHYSICAL | (n_scan > 0 ? TIPPE_DESIGN_COARSE_LAYOUT : 0);
    if (tippe_design_source_build(s->src, ov, n, flags, &d, &e)) {
        out->status = TIPPE_OPT_DOES_NOT_FIT;
        out->score = -2.0;
        return;
    }
    tippe_design_travel_mm(d, &out->travel_mm[0], &out->travel_mm[1]);
    out->weight_g = tippe_design_moving_mass_kg(d) * 1e3;
    const char *hole = NULL;
    out->wall_mm = tippe_design_min_hole_wall_mm(d, &hole);
    double min_wall = s->min_wall_mm >= 0 ? s->min_wall_mm : perimeter_wall_mm(d, hole);
    /* z_cm is linear in Z2 (the total mass does not change), so |eps| is
     * largest at an end of the travel. */
    tippe_top t0, t1;
    tippe_design_top_any(d, out->travel_mm[0], &t0);
    tippe_design_top_any(d, out->travel_mm[1], &t1);
    out->eps_max_mm = fmax(t0.eps, t1.eps) * 1e3;

    tippe_sweep_options so;
    tippe_sweep_options_default(&so);
    if (n_scan > 0)
        so.n_scan = n_scan;
    tippe_sweep_result r;
    tippe_sweep_summary sum;
    double violation = 0.0;
    margin[CON_SPIN] = -1.0;
    if (tippe_sweep_design(d, out->travel_mm[0], out->travel_mm[1], &so, &r, &e)) {
        out->status = TIPPE_OPT_NO_ZONES;
        violation += 1.0;
    } else {
        tippe_sweep_summarise(&r, &sum);
        for (int k = 0; k < 3; k++)
            out->zone_mm[k] = sum.widest_mm[k];
        out->objective_mm = sum.narrowest_zone_mm;
        if (n_scan <= 0 && s->robust)
            robust_widths(d, &r, out);
        double f = 0.0, t = 0.0;
        if (isfinite(s->spin_max_rev_s) && widest_ii_run(&r, &f, &t)) {
            out->spin_flip_rev_s = flip_spin_rev_s(d, f, t);
            margin[CON_SPIN] = isfinite(out->spin_flip_rev_s)
                                   ? out->spin_flip_rev_s / s->spin_max_rev_s - 1.0
                                   : 1.0;
            if (!(out->spin_flip_rev_s <= s->spin_max_rev_s)) {
                out->status = TIPPE_OPT_SPIN_HIGH;
                violation += margin[CON_SPIN];
            }
        }
    }
    tippe_sweep_result_free(&r);
    margin[CON_EPS] = s->eps_max_min_mm > 0 ? 1.0 - out->eps_max_mm / s->eps_max_min_mm : -1.0;
    margin[CON_WEIGHT] = isfinite(s->max_weight_g) ? out->weight_g / s->max_weight_g - 1.0 : -1.0;
    margin[CON_WALL] = !isfinite(out->wall_mm) ? -1.0
                       : min_wall > 0          ? fmin(1.0, 1.0 - out->wall_mm / min_wall)
                       : out->wall_mm < min_wall ? 1.0
                                                 : -1.0;
    if (out->eps_max_mm < s->eps_max_min_mm) {
        out->status = TIPPE_OPT_EPS_SMALL;
        violation += margin[CON_EPS];
    }
    if (out->weight_g > s->max_weight_g) {
        out->status = TIPPE_OPT_HEAVY;
        violation += margin[CON_WEIGHT];
    }
    if (out->wall_mm < min_wall) {
        out->status = TIPPE_OPT_THIN_WALL;
        violation += margin[CON_WALL];
    }
    out->score = out->status == TIPPE_OPT_OK ? out->objective_mm : -1.0 - fmin(violation, 0.99);
    tippe_design_free(d);
}

void tippe_opt_evaluate(const tippe_opt_spec *s, int choice, const double *x, int n_scan,
                        tippe_opt_eval *out)
{
    double margin[N_CON];
    evaluate(s, choice, x, n_scan, out, margin);
}

int tippe_opt_sweep(const tippe_opt_spec *s, const tippe_opt_eval *e, tippe_sweep_result *out,
                    tippe_error *err)
{
    memset(out, 0, sizeof *out);
    char buf[TIPPE_OPT_MAX_VARY + MAX_CHOOSE * MAX_SETS_PER_OPTION + MAX_TIE][256];
    const char *ov[sizeof buf / sizeof buf[0]];
    int n = tippe_opt_overrides(s, e->choice, e->x, buf, (int)(sizeof buf / sizeof buf[0]));
    for (int i = 0; i < n; i++)
        ov[i] = buf[i];
    tippe_design *d = NULL;
    int rc = tippe_design_source_build(s->src, ov, n, TIPPE_DESIGN_TRAVEL_PHYSICAL, &d, err);
    if (rc)
        return rc;
    double f, t;
    tippe_design_travel_mm(d, &f, &t);
    rc = tippe_sweep_design(d, f, t, NULL, out, err);
    tippe_design_free(d);
    return rc;
}

/* ---- the search ------------------------------------------------------------ */

typedef struct {
    const tippe_opt_spec *s;
    const tippe_opt_options *o;
    int choice;
    tippe_opt_choice_result *res;
    long cap;
    double best_score;
    double best_x[TIPPE_OPT_MAX_VARY];
    int failed;
    /* The last candidate evaluated (clamped x), for the polish's constraints,
     * which NLopt asks for at the point whose objective it has just asked. */
    tippe_opt_eval last;
    double last_margin[N_CON];
    double last_x[TIPPE_OPT_MAX_VARY];
    int has_last;
} job_t;

/* NLopt is opened when the first optimisation runs, as src/encode.c opens
 * FFmpeg: linked, it would be loaded by every tippe command at start-up.
 * TIPPE_NLOPT_SONAME is the linked library's file name (CMakeLists.txt). */
#define NLOPT_FUNCS(X) \
    X(nlopt_create) \
    X(nlopt_destroy) \
    X(nlopt_optimize) \
    X(nlopt_set_lower_bounds) \
    X(nlopt_set_upper_bounds) \
    X(nlopt_set_max_objective) \
    X(nlopt_set_maxeval) \
    X(nlopt_set_initial_step) \
    X(nlopt_set_xtol_rel) \
    X(nlopt_set_xtol_abs1) \
    X(nlopt_set_local_optimizer) \
    X(nlopt_add_inequality_mconstraint) \
    X(nlopt_srand)

static struct {
#define X(fn) __typeof__(fn) *fn;
    NLOPT_FUNCS(X)
#undef X
} nl;
static pthread_once_t nl_once = PTHREAD_ONCE_INIT;
static char nl_error[512];

static void nl_load(void)
{
    /* The library stays open for the life of the process. */
    void *h = dlopen(TIPPE_NLOPT_SONAME, RTLD_NOW | RTLD_LOCAL);
    if (!h) {
        snprintf(nl_error, sizeof nl_error,
                 "NLopt is missing (apt-get install libnlopt-dev): %s", dlerror());
        return;
    }
#define X(fn) \
    if (!nl_error[0] && !(nl.fn = (__typeof__(nl.fn))dlsym(h, #fn))) \
        snprintf(nl_error, sizeof nl_error, "NLopt (%s) has no %s", TIPPE_NLOPT_SONAME, #fn);
    NLOPT_FUNCS(X)
#undef X
}

static int nl_ready(tippe_error *err)
{
    pthread_once(&nl_once, nl_load);
    return nl_error[0] ? tippe_error_set(err, TIPPE_ECOMPUTE, "optimise: %s", nl_error) : TIPPE_OK;
}

/* Evaluates candidate x (its first n_vary values; clamped to the bounds, which
 * COBYLA may step a hair outside), records it and keeps it as j->last. */
static const tippe_opt_eval *evaluate_at(job_t *j, const double *x)
{
    unsigned n = (unsigned)j->s->n_vary;
    double xx[TIPPE_OPT_MAX_VARY] = {0};
    for (unsigned k = 0; k < n; k++)
        xx[k] = fmin(fmax(x[k], j->s->vary[k].lo), j->s->vary[k].hi);
    tippe_opt_eval *ev = &j->last;
    evaluate(j->s, j->choice, xx, SEARCH_SCAN, ev, j->last_margin);
    memcpy(j->last_x, x, n * sizeof *x);
    j->has_last = 1;
    tippe_opt_choice_result *r = j->res;
    if (r->n_evals < j->cap) {
        if (ev->score > j->best_score) {
            j->best_score = ev->score;
            memcpy(j->best_x, xx, n * sizeof *xx);
        }
        r->best_so_far[r->n_evals] = j->best_score;
        if (r->all)
            r->all[r->n_evals] = *ev;
        r->n_evals++;
    }
    if (j->o->progress)
        j->o->progress(j->o->progress_ctx, 1);
    return ev;
}

static double objective(unsigned n, const double *x, double *grad, void *data)
{
    (void)n;
    (void)grad;
    return evaluate_at(data, x)->score;
}

/* The polish (COBYLA) sees the problem in its epigraph form: maximise t over
 * (x, t) subject to t <= the width of each group's zone, with the spec's
 * constraints as inequality constraints. The narrowest of three widths has a
 * kink where two are equal, and the best design lies on such a ridge (two
 * widths equal at every shipped spec's best); a constraint scored as a penalty
 * is a cliff, and the best design lies on one too (eps_max at its bound).
 * COBYLA's linear model of the score cannot follow a kink and a cliff: its
 * trust region collapsed there 50 evaluations in, at 6.777 mm on the drilled
 * ball instead of 6.820 mm. The widths and the constraints are each smooth,
 * and COBYLA models each one (docs/optimise.md, "The method"). */
#define N_POLISH_CON (3 + N_CON)

/* Evaluates the candidate (NLopt asks for the constraints at the same point
 * next) and returns t. */
static double polish_objective(unsigned n, const double *x, double *grad, void *data)
{
    (void)grad;
    evaluate_at(data, x);
    return x[n - 1];
}

static void polish_constraints(unsigned m, double *c, unsigned n, const double *x, double *grad,
                               void *data)
{
    (void)m;
    (void)grad;
    job_t *j = data;
    unsigned nv = n - 1;
    const tippe_opt_eval *ev = j->has_last && !memcmp(j->last_x, x, nv * sizeof *x)
                                   ? &j->last
                                   : evaluate_at(j, x);
    double t = x[nv];
    for (int k = 0; k < 3; k++)
        c[k] = t - ev->zone_mm[k];
    for (int k = 0; k < N_CON; k++)
        c[3 + k] = j->last_margin[k];
}

static nlopt_algorithm nlopt_alg(algorithm_t a)
{
    switch (a) {
    case ALG_CRS2:
        return NLOPT_GN_CRS2_LM;
    case ALG_MLSL:
        return NLOPT_G_MLSL_LDS;
    case ALG_ISRES:
        return NLOPT_GN_ISRES;
    case ALG_DIRECT_L:
    default:
        return NLOPT_GN_DIRECT_L;
    }
}

/* One NLopt run over the bounds from x (in: start, out: unchanged), at most
 * maxeval evaluations. Returns 0, or -1 if NLopt could not be set up. */
static int run_nlopt(job_t *j, nlopt_algorithm alg, long maxeval, double *x)
{
    const tippe_opt_spec *s = j->s;
    unsigned n = (unsigned)s->n_vary;
    double lo[TIPPE_OPT_MAX_VARY], hi[TIPPE_OPT_MAX_VARY], step[TIPPE_OPT_MAX_VARY], f = 0;
    for (unsigned k = 0; k < n; k++) {
        lo[k] = s->vary[k].lo;
        hi[k] = s->vary[k].hi;
        step[k] = 0.05 * (hi[k] - lo[k]);
    }
    nlopt_opt opt = nl.nlopt_create(alg, n);
    nlopt_opt local = NULL;
    if (!opt)
        return -1;
    int ok = nl.nlopt_set_lower_bounds(opt, lo) > 0 && nl.nlopt_set_upper_bounds(opt, hi) > 0 &&
             nl.nlopt_set_max_objective(opt, objective, j) > 0 &&
             nl.nlopt_set_maxeval(opt, (int)maxeval) > 0 &&
             nl.nlopt_set_initial_step(opt, step) > 0;
    if (ok && alg == NLOPT_G_MLSL_LDS) {
        local = nl.nlopt_create(NLOPT_LN_COBYLA, n);
        ok = local && nl.nlopt_set_xtol_rel(local, 1e-6) > 0 &&
             nl.nlopt_set_local_optimizer(opt, local) > 0;
    }
    if (ok && (alg == NLOPT_LN_COBYLA || alg == NLOPT_LN_BOBYQA))
        ok = nl.nlopt_set_xtol_abs1(opt, 1e-7) > 0; /* the sweep's own resolution, mm */
    nlopt_result res = ok ? nl.nlopt_optimize(opt, x, &f) : NLOPT_FAILURE;
    nl.nlopt_destroy(opt);
    nl.nlopt_destroy(local);
    /* Running out of evaluations or stopping on a tolerance is success here;
     * a roundoff-limited stop still leaves the best point seen. */
    return (res > 0 || res == NLOPT_ROUNDOFF_LIMITED) ? 0 : -1;
}

/* The COBYLA polish in the epigraph form (above) from x, at most maxeval
 * evaluations. Returns 0, or -1 if NLopt could not be set up. */
static int run_polish(job_t *j, long maxeval, const double *x)
{
    const tippe_opt_spec *s = j->s;
    unsigned n = (unsigned)s->n_vary;
    double lo[TIPPE_OPT_MAX_VARY + 1], hi[TIPPE_OPT_MAX_VARY + 1], step[TIPPE_OPT_MAX_VARY + 1];
    double y[TIPPE_OPT_MAX_VARY + 1], tol[N_POLISH_CON] = {0}, f = 0;
    for (unsigned k = 0; k < n; k++) {
        lo[k] = s->vary[k].lo;
        hi[k] = s->vary[k].hi;
        step[k] = 0.05 * (hi[k] - lo[k]);
        y[k] = x[k];
    }
    /* t starts at the start's narrowest zone (0 if it is not feasible). */
    double t0 = fmax(0.0, j->best_score);
    lo[n] = 0.0;
    hi[n] = 1e4;
    y[n] = t0;
    step[n] = fmax(0.05 * t0, 0.01);
    nlopt_opt opt = nl.nlopt_create(NLOPT_LN_COBYLA, n + 1);
    if (!opt)
        return -1;
    int ok = nl.nlopt_set_lower_bounds(opt, lo) > 0 && nl.nlopt_set_upper_bounds(opt, hi) > 0 &&
             nl.nlopt_set_max_objective(opt, polish_objective, j) > 0 &&
             nl.nlopt_add_inequality_mconstraint(opt, N_POLISH_CON, polish_constraints, j,
                                                 tol) > 0 &&
             nl.nlopt_set_maxeval(opt, (int)maxeval) > 0 &&
             nl.nlopt_set_initial_step(opt, step) > 0 &&
             nl.nlopt_set_xtol_abs1(opt, 1e-7) > 0; /* the sweep's own resolution, mm */
    j->has_last = 0;
    nlopt_result res = ok ? nl.nlopt_optimize(opt, y, &f) : NLOPT_FAILURE;
    nl.nlopt_destroy(opt);
    return (res > 0 || res == NLOPT_ROUNDOFF_LIMITED) ? 0 : -1;
}

static void search_choice(job_t *j)
{
    const tippe_opt_spec *s = j->s;
    double x[TIPPE_OPT_MAX_VARY] = {0};
    j->best_score = -INFINITY;
    if (s->n_vary == 0) {
        objective(0, x, NULL, j);
        j->res->n_global = j->res->n_evals;
    } else {
        for (int k = 0; k < s->n_vary; k++)
            x[k] = 0.5 * (s->vary[k].lo + s->vary[k].hi);
        /* The stochastic algorithms draw from NLopt's generator, which is per
         * thread: seeding it here makes this choice's search depend on the
         * seed and the choice only. */
        nl.nlopt_srand(j->o->seed * 1000003ul + (unsigned long)j->choice);
        if (run_nlopt(j, nlopt_alg(s->algorithm), s->evals, x))
            j->failed = 1;
        j->res->n_global = j->res->n_evals;
        if (!j->failed && s->polish != POLISH_NONE && s->polish_evals > 0 &&
            isfinite(j->best_score)) {
            memcpy(x, j->best_x, (size_t)s->n_vary * sizeof *x);
            /* From a feasible start, COBYLA follows the widths in the epigraph
             * form; from an infeasible one (the global phase found nothing that
             * meets the constraints) it can only reduce the violation, which the
             * score measures: the epigraph form would spend its whole budget
             * looking for a feasible point that the global phase did not find. */
            if (s->polish == POLISH_BOBYQA || j->best_score < 0
                    ? run_nlopt(j, s->polish == POLISH_BOBYQA ? NLOPT_LN_BOBYQA : NLOPT_LN_COBYLA,
                                s->polish_evals, x)
                    : run_polish(j, s->polish_evals, x))
                j->failed = 1;
        }
    }
    /* The best point, measured as a report measures it (full sweep). */
    tippe_opt_evaluate(s, j->choice, j->best_x, 0, &j->res->best);
}

long tippe_opt_planned_evals(const tippe_opt_spec *s)
{
    long per = s->n_vary ? s->evals + (s->polish != POLISH_NONE ? s->polish_evals : 0) : 1;
    return per * s->n_choices;
}

void tippe_opt_result_free(tippe_opt_result *r)
{
    if (!r)
        return;
    for (int i = 0; r->choices && i < r->n_choices; i++) {
        free(r->choices[i].best_so_far);
        free(r->choices[i].all);
    }
    free(r->choices);
    memset(r, 0, sizeof *r);
}

/* Whether a ranks above b: feasible before infeasible, then by robust width
 * where both have one, else by score. */
int tippe_opt_rank_above(const tippe_opt_eval *a, const tippe_opt_eval *b)
{
    int fa = a->status == TIPPE_OPT_OK, fb = b->status == TIPPE_OPT_OK;
    if (fa != fb)
        return fa;
    if (fa && a->has_robust && b->has_robust && a->robust_mm != b->robust_mm)
        return a->robust_mm > b->robust_mm;
    return a->score > b->score;
}

int tippe_opt_run(const tippe_opt_spec *s, const tippe_opt_options *o, tippe_opt_result *out,
                  tippe_error *err)
{
    memset(out, 0, sizeof *out);
    int rc = nl_ready(err);
    if (rc)
        return rc;
    tippe_gsl_errors_as_codes();
    tippe_opt_options def;
    if (!o) {
        tippe_opt_options_default(&def);
        o = &def;
    }
    int nc = s->n_choices;
    long per = tippe_opt_planned_evals(s) / nc;
    /* COBYLA and MLSL may make a few more calls than asked when they stop. */
    long cap = per + 64;
    out->choices = calloc((size_t)nc, sizeof *out->choices);
    job_t *jobs = calloc((size_t)nc, sizeof *jobs);
    if (!out->choices || !jobs) {
        free(jobs);
        return tippe_error_set(err, TIPPE_ECOMPUTE, "optimise: out of memory");
    }
    out->n_choices = nc;
    out->robust = s->robust;
    int oom = 0;
    for (int c = 0; c < nc; c++) {
        tippe_opt_choice_result *r = &out->choices[c];
        r->best_so_far = malloc((size_t)cap * sizeof *r->best_so_far);
        if (o->keep_all)
            r->all = malloc((size_t)cap * sizeof *r->all);
        oom |= !r->best_so_far || (o->keep_all && !r->all);
        jobs[c] = (job_t){.s = s, .o = o, .choice = c, .res = r, .cap = cap};
    }
    if (oom) {
        free(jobs);
        return tippe_error_set(err, TIPPE_ECOMPUTE, "optimise: out of memory");
    }
    int threads = o->threads > 0 ? o->threads : omp_get_max_threads();
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (int c = 0; c < nc; c++)
        search_choice(&jobs[c]);
    int failed = -1;
    out->best_choice = 0;
    for (int c = 0; c < nc; c++) {
        out->total_evals += out->choices[c].n_evals;
        if (jobs[c].failed && failed < 0)
            failed = c;
        if (tippe_opt_rank_above(&out->choices[c].best, &out->choices[out->best_choice].best))
            out->best_choice = c;
    }
    free(jobs);
    if (failed >= 0) {
        char label[256];
        return tippe_error_set(err, TIPPE_ECOMPUTE, "optimise: NLopt failed on choice %s",
                               tippe_opt_spec_choice_label(s, failed, label, sizeof label));
    }
    return TIPPE_OK;
}

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
    const char *slash = strrchr(path, '/');
    if (!slash)
        snprintf(dir, sizeof dir, ".");
    else if (slash == path)
        snprintf(dir, sizeof dir, "/");
    else
        snprintf(dir, sizeof dir, "%.*s", (int)(slash - path), path);
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

cJSON *tippe_opt_design_json(const tippe_opt_spec *s, const tippe_opt_eval *e,
                             const char *out_path, const char *how, tippe_error *err)
{
    char buf[TIPPE_OPT_MAX_VARY + MAX_CHOOSE * MAX_SETS_PER_OPTION + MAX_TIE][256];
    const char *ov[sizeof buf / sizeof buf[0]];
    int n = tippe_opt_overrides(s, e->choice, e->x, buf, (int)(sizeof buf / sizeof buf[0]));
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
