/* Scenario files for `tippe simulate`: strict JSON reading, command-line
 * overrides, validation, and the launch they describe (docs/dynamics.md). */
#include "tippe/scenario.h"

#include "tippe/design.h"

#include <cjson/cJSON.h>
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_SCENARIO_BYTES (1 << 20)
#define MAX_OVERRIDES 64
#define MAX_DESIGN_SETS 64

typedef struct {
    const char *file;
    tippe_error *err;
    int n_over;
    char over_path[MAX_OVERRIDES][128]; /* the JSON path each override set */
    const char *over_text[MAX_OVERRIDES];
} ctx;

/* An error at a JSON path; if a command-line override set that path (or a
 * parent of it), the message says so, since the file is then not to blame. */
__attribute__((format(printf, 3, 4)))
static int fail(const ctx *c, const char *path, const char *fmt, ...)
{
    char what[700];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    const char *by = NULL;
    for (int i = 0; i < c->n_over && path; i++) {
        size_t n = strlen(c->over_path[i]);
        if (!strncmp(path, c->over_path[i], n) && (path[n] == '\0' || path[n] == '.'))
            by = c->over_text[i];
    }
    if (by)
        return tippe_error_set(c->err, TIPPE_EINPUT, "%s: %s: %s (set on the command line: %s)",
                               c->file, path, what, by);
    if (path && path[0])
        return tippe_error_set(c->err, TIPPE_EINPUT, "%s: %s: %s", c->file, path, what);
    return tippe_error_set(c->err, TIPPE_EINPUT, "%s: %s", c->file, what);
}

static const char *kind(const cJSON *it)
{
    if (!it) return "missing";
    if (cJSON_IsString(it)) return "a string";
    if (cJSON_IsNumber(it)) return "a number";
    if (cJSON_IsBool(it)) return "true/false";
    if (cJSON_IsNull(it)) return "null";
    if (cJSON_IsArray(it)) return "an array";
    if (cJSON_IsObject(it)) return "an object";
    return "an invalid value";
}

static void join(char *buf, size_t cap, const char *prefix, const char *key)
{
    if (prefix && prefix[0])
        snprintf(buf, cap, "%s.%s", prefix, key);
    else
        snprintf(buf, cap, "%s", key);
}

static int read_text(const char *path, char **out, tippe_error *err)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return tippe_error_set(err, TIPPE_EINPUT, "%s: cannot open: %s", path, strerror(errno));
    char *buf = malloc(MAX_SCENARIO_BYTES + 1);
    if (!buf) {
        fclose(f);
        return tippe_error_set(err, TIPPE_ECOMPUTE, "%s: out of memory", path);
    }
    size_t n = fread(buf, 1, MAX_SCENARIO_BYTES + 1, f);
    int bad = ferror(f);
    fclose(f);
    if (bad || n > MAX_SCENARIO_BYTES || memchr(buf, '\0', n)) {
        free(buf);
        return tippe_error_set(err, TIPPE_EINPUT, "%s: %s", path,
                               bad ? "read error"
                               : n > MAX_SCENARIO_BYTES ? "larger than 1 MiB: not a scenario file"
                                                        : "contains a NUL byte: not JSON");
    }
    buf[n] = '\0';
    *out = buf;
    return TIPPE_OK;
}

/* The error position comes from cJSON_ParseWithOpts: cJSON_GetErrorPtr is
 * global state and not thread-safe. */
static int parse(const char *path, const char *text, cJSON **out, tippe_error *err)
{
    const char *end = NULL;
    *out = cJSON_ParseWithOpts(text, &end, 1);
    if (*out)
        return TIPPE_OK;
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
    return tippe_error_set(err, TIPPE_EINPUT, "%s:%d:%d: not valid JSON%s", path, line, col,
                           *end ? "" : " (the text ends too early)");
}

/* cJSON keeps duplicate keys but lookups see only the first: refuse them. */
static int check_duplicates(const ctx *c, const cJSON *node, const char *path)
{
    char sub[256];
    int i = 0;
    for (const cJSON *ch = node->child; ch; ch = ch->next, i++) {
        if (cJSON_IsObject(node)) {
            join(sub, sizeof sub, path, ch->string);
            for (const cJSON *prev = node->child; prev != ch; prev = prev->next)
                if (!strcmp(prev->string, ch->string))
                    return fail(c, sub, "duplicate key (a key may appear once per object)");
        } else {
            snprintf(sub, sizeof sub, "%s[%d]", path, i);
        }
        if (ch->child) {
            int rc = check_duplicates(c, ch, sub);
            if (rc)
                return rc;
        }
    }
    return TIPPE_OK;
}

static int in_list(const char *key, const char *const *list)
{
    for (; *list; list++)
        if (!strcmp(key, *list))
            return 1;
    return 0;
}

static int check_keys(const ctx *c, const cJSON *obj, const char *path,
                      const char *const *allowed)
{
    for (const cJSON *ch = obj->child; ch; ch = ch->next)
        if (!in_list(ch->string, allowed)) {
            char list[256] = "", sub[256];
            size_t n = 0;
            for (const char *const *a = allowed; *a; a++) {
                int w = snprintf(list + n, sizeof list - n, "%s%s", n ? ", " : "", *a);
                if (w > 0 && (size_t)w < sizeof list - n)
                    n += (size_t)w;
            }
            join(sub, sizeof sub, path, ch->string);
            return fail(c, sub, "unknown key (allowed here: %s; keys are case-sensitive)", list);
        }
    return TIPPE_OK;
}

static const char *const top_level_keys[] = {"name", "notes", "top", "g", "mu",
                                              "initial", "t_end", "accuracy", NULL};
static const char *const top_explicit_keys[] = {"m", "R", "eps", "A", "C", NULL};
static const char *const top_design_keys[] = {"design", "z2_mm", "set", NULL};
static const char *const top_all_keys[] = {"m", "R", "eps", "A", "C", "design", "z2_mm",
                                           "set", NULL};
static const char *const initial_keys[] = {"theta", "theta_dot", "phi_dot", "spin", "U", "V",
                                           NULL};
static const char *const accuracy_keys[] = {"stepper", "rtol", NULL};

/* Reads a finite number at obj.key; a missing key gives def, or an error if
 * required. */
static int number(const ctx *c, const cJSON *obj, const char *path, const char *key,
                  int required, double def, double *out)
{
    char sub[256];
    join(sub, sizeof sub, path, key);
    const cJSON *it = cJSON_GetObjectItemCaseSensitive(obj, key);
    if (!it) {
        if (required)
            return fail(c, sub, "missing (a number is required)");
        *out = def;
        return TIPPE_OK;
    }
    if (!cJSON_IsNumber(it))
        return fail(c, sub, "expected a number, got %s", kind(it));
    if (!isfinite(it->valuedouble))
        return fail(c, sub, "must be a finite number");
    *out = it->valuedouble;
    return TIPPE_OK;
}

/* ---- overrides ---- */

static int apply_override(ctx *c, cJSON *root, const char *text, int index)
{
    const char *eq = strchr(text, '=');
    if (!eq || eq == text)
        return tippe_error_set(c->err, TIPPE_EINPUT,
                               "%s: override '%s': expected FIELD=VALUE, e.g. initial.spin=3",
                               c->file, text);
    size_t flen = (size_t)(eq - text);
    if (flen >= sizeof c->over_path[0])
        return tippe_error_set(c->err, TIPPE_EINPUT, "%s: override '%s': field name too long",
                               c->file, text);
    char field[128];
    memcpy(field, text, flen);
    field[flen] = '\0';
    snprintf(c->over_path[index], sizeof c->over_path[index], "%s", field);
    c->over_text[index] = text;
    c->n_over = index + 1;

    /* Walk to the parent object, creating objects that are missing. A preset
     * name under "accuracy" is expanded so that accuracy.rtol can refine it. */
    cJSON *obj = root;
    char *key = field;
    for (char *dot; (dot = strchr(key, '.'));) {
        *dot = '\0';
        cJSON *next = cJSON_GetObjectItemCaseSensitive(obj, key);
        if (next && cJSON_IsString(next) && obj == root && !strcmp(key, "accuracy")) {
            tippe_dynamics_accuracy a;
            if (tippe_dynamics_accuracy_preset(next->valuestring, &a, NULL))
                return fail(c, "accuracy", "unknown preset '%s' (fast, balanced, precise)",
                            next->valuestring);
            cJSON *o = cJSON_CreateObject();
            if (!o || !cJSON_AddStringToObject(o, "stepper", a.stepper) ||
                !cJSON_AddNumberToObject(o, "rtol", a.rtol)) {
                cJSON_Delete(o);
                return tippe_error_set(c->err, TIPPE_ECOMPUTE, "out of memory");
            }
            cJSON_ReplaceItemInObjectCaseSensitive(obj, key, o);
            next = o;
        }
        if (!next) {
            next = cJSON_AddObjectToObject(obj, key);
            if (!next)
                return tippe_error_set(c->err, TIPPE_ECOMPUTE, "out of memory");
        }
        if (!cJSON_IsObject(next)) {
            *dot = '.';
            return tippe_error_set(c->err, TIPPE_EINPUT,
                                   "%s: override '%s': '%.*s' is %s, not an object", c->file,
                                   text, (int)(dot - field), field, kind(next));
        }
        obj = next;
        key = dot + 1;
    }
    if (!key[0])
        return tippe_error_set(c->err, TIPPE_EINPUT, "%s: override '%s': empty field name",
                               c->file, text);
    const char *value = eq + 1;
    const char *end = NULL;
    cJSON *item = cJSON_ParseWithOpts(value, &end, 1);
    if (!item)
        item = cJSON_CreateString(value); /* not JSON: a word such as steady or precise */
    if (!item)
        return tippe_error_set(c->err, TIPPE_ECOMPUTE, "out of memory");
    if (cJSON_GetObjectItemCaseSensitive(obj, key))
        cJSON_ReplaceItemInObjectCaseSensitive(obj, key, item);
    else
        cJSON_AddItemToObject(obj, key, item);
    return TIPPE_OK;
}

/* ---- the parts of a scenario ---- */

static void dirname_of(const char *path, char *dir, size_t cap)
{
    const char *slash = strrchr(path, '/');
    if (!slash)
        snprintf(dir, cap, ".");
    else if (slash == path)
        snprintf(dir, cap, "/");
    else
        snprintf(dir, cap, "%.*s", (int)(slash - path), path);
}

static int read_top(ctx *c, const cJSON *top, tippe_scenario *s)
{
    if (!top)
        return fail(c, "top", "missing: give {\"m\", \"R\", \"eps\", \"A\", \"C\"} in SI units "
                              "or {\"design\": FILE, \"z2_mm\": MM}");
    if (!cJSON_IsObject(top))
        return fail(c, "top", "expected an object, got %s", kind(top));
    int rc = check_keys(c, top, "top", top_all_keys);
    if (rc)
        return rc;
    const cJSON *design = cJSON_GetObjectItemCaseSensitive(top, "design");
    int any_explicit = 0;
    for (const char *const *k = top_explicit_keys; *k; k++)
        any_explicit |= cJSON_GetObjectItemCaseSensitive(top, *k) != NULL;
    if (design && any_explicit)
        return fail(c, "top", "give either a design (design, z2_mm) or the explicit top "
                              "(m, R, eps, A, C), not both");
    tippe_top *t = &s->model.top;
    if (!design) {
        if ((rc = check_keys(c, top, "top", top_explicit_keys)))
            return rc;
        if ((rc = number(c, top, "top", "m", 1, 0, &t->m)) ||
            (rc = number(c, top, "top", "R", 1, 0, &t->R)) ||
            (rc = number(c, top, "top", "eps", 1, 0, &t->eps)) ||
            (rc = number(c, top, "top", "A", 1, 0, &t->A)) ||
            (rc = number(c, top, "top", "C", 1, 0, &t->C)))
            return rc;
        if (!(t->m > 0))
            return fail(c, "top.m", "mass must be > 0 kg, got %g", t->m);
        if (!(t->R > 0))
            return fail(c, "top.R", "radius must be > 0 m, got %g", t->R);
        if (!(t->eps >= 0 && t->eps < t->R))
            return fail(c, "top.eps", "must satisfy 0 <= eps < R = %g m, got %g", t->R, t->eps);
        if (!(t->A > 0))
            return fail(c, "top.A", "must be > 0 kg m^2, got %g", t->A);
        if (!(t->C > 0))
            return fail(c, "top.C", "must be > 0 kg m^2, got %g", t->C);
        /* A rigid body of revolution has A >= C/2 about its centre of mass
         * (A = int (r^2/2 + z^2) dm, C = int r^2 dm). */
        if (t->A < 0.5 * t->C * (1 - 1e-12))
            return fail(c, "top.A", "A = %g kg m^2 < C/2 = %g: no rigid body has these moments",
                        t->A, 0.5 * t->C);
        t->com_side = t->eps > 0 ? -1 : 0;
        s->design_path[0] = '\0';
        s->z2_mm = NAN;
        return TIPPE_OK;
    }
    if ((rc = check_keys(c, top, "top", top_design_keys)))
        return rc;
    if (!cJSON_IsString(design) || !design->valuestring[0])
        return fail(c, "top.design", "expected a file name, got %s", kind(design));
    if ((rc = number(c, top, "top", "z2_mm", 1, 0, &s->z2_mm)))
        return rc;
    if (design->valuestring[0] == '/') {
        snprintf(s->design_path, sizeof s->design_path, "%s", design->valuestring);
    } else {
        char dir[1024];
        dirname_of(c->file, dir, sizeof dir);
        if (snprintf(s->design_path, sizeof s->design_path, "%s/%s", dir, design->valuestring) >=
            (int)sizeof s->design_path)
            return fail(c, "top.design", "path too long");
    }
    const char *sets[MAX_DESIGN_SETS];
    int n_sets = 0;
    const cJSON *set = cJSON_GetObjectItemCaseSensitive(top, "set");
    if (set) {
        if (!cJSON_IsArray(set))
            return fail(c, "top.set", "expected an array of \"FIELD=VALUE\" strings, got %s",
                        kind(set));
        int i = 0;
        for (const cJSON *it = set->child; it; it = it->next, i++) {
            char sub[64];
            snprintf(sub, sizeof sub, "top.set[%d]", i);
            if (!cJSON_IsString(it))
                return fail(c, sub, "expected a \"FIELD=VALUE\" string, got %s", kind(it));
            if (n_sets == MAX_DESIGN_SETS)
                return fail(c, "top.set", "more than %d overrides", MAX_DESIGN_SETS);
            sets[n_sets++] = it->valuestring;
        }
    }
    tippe_design *d = NULL;
    tippe_error derr;
    rc = tippe_design_load(s->design_path, sets, n_sets, &d, &derr);
    if (rc)
        return rc == TIPPE_EINPUT ? fail(c, "top.design", "%s", derr.msg)
                                  : tippe_error_set(c->err, rc, "%s", derr.msg);
    rc = tippe_design_top(d, s->z2_mm, t, &derr);
    tippe_design_free(d);
    if (rc)
        return rc == TIPPE_EINPUT ? fail(c, "top.z2_mm", "%s", derr.msg)
                                  : tippe_error_set(c->err, rc, "%s", derr.msg);
    return TIPPE_OK;
}

static int read_accuracy(ctx *c, const cJSON *acc, tippe_scenario *s)
{
    if (!acc) {
        tippe_dynamics_accuracy_preset("balanced", &s->accuracy, NULL);
        snprintf(s->accuracy_name, sizeof s->accuracy_name, "balanced");
        return TIPPE_OK;
    }
    if (cJSON_IsString(acc)) {
        if (tippe_dynamics_accuracy_preset(acc->valuestring, &s->accuracy, NULL))
            return fail(c, "accuracy", "unknown preset '%s' (fast, balanced, precise, or "
                                       "{\"stepper\": NAME, \"rtol\": NUMBER})",
                        acc->valuestring);
        snprintf(s->accuracy_name, sizeof s->accuracy_name, "%s", acc->valuestring);
        return TIPPE_OK;
    }
    if (!cJSON_IsObject(acc))
        return fail(c, "accuracy", "expected a preset name or an object, got %s", kind(acc));
    int rc = check_keys(c, acc, "accuracy", accuracy_keys);
    if (rc)
        return rc;
    const cJSON *st = cJSON_GetObjectItemCaseSensitive(acc, "stepper");
    if (!cJSON_IsString(st))
        return fail(c, "accuracy.stepper", "expected a stepper name, got %s", kind(st));
    if (!tippe_dynamics_stepper_known(st->valuestring))
        return fail(c, "accuracy.stepper",
                    "unknown stepper '%s' (rk2, rk4, rkf45, rkck, rk8pd, rk1imp, rk2imp, "
                    "rk4imp, bsimp, msadams, msbdf)",
                    st->valuestring);
    snprintf(s->accuracy.stepper, sizeof s->accuracy.stepper, "%s", st->valuestring);
    if ((rc = number(c, acc, "accuracy", "rtol", 1, 0, &s->accuracy.rtol)))
        return rc;
    if (!(s->accuracy.rtol >= 1e-14 && s->accuracy.rtol <= 1e-2))
        return fail(c, "accuracy.rtol", "must be in [1e-14, 1e-2], got %g", s->accuracy.rtol);
    snprintf(s->accuracy_name, sizeof s->accuracy_name, "custom");
    return TIPPE_OK;
}

static int read_initial(ctx *c, const cJSON *ini, tippe_scenario *s)
{
    if (!ini)
        return fail(c, "initial", "missing: give at least {\"theta\": RAD, \"spin\": RAD_S}");
    if (!cJSON_IsObject(ini))
        return fail(c, "initial", "expected an object, got %s", kind(ini));
    int rc = check_keys(c, ini, "initial", initial_keys);
    if (rc)
        return rc;
    tippe_dynamics_initial *ic = &s->initial;
    if ((rc = number(c, ini, "initial", "theta", 1, 0, &ic->theta)) ||
        (rc = number(c, ini, "initial", "theta_dot", 0, 0, &ic->theta_dot)) ||
        (rc = number(c, ini, "initial", "spin", 1, 0, &ic->spin)) ||
        (rc = number(c, ini, "initial", "U", 0, 0, &ic->U)) ||
        (rc = number(c, ini, "initial", "V", 0, 0, &ic->V)))
        return rc;
    if (!(ic->theta >= 0 && ic->theta <= M_PI))
        return fail(c, "initial.theta", "must be in [0, pi] rad, got %g", ic->theta);
    const cJSON *pd = cJSON_GetObjectItemCaseSensitive(ini, "phi_dot");
    if (!pd || cJSON_IsNumber(pd)) {
        if ((rc = number(c, ini, "initial", "phi_dot", 0, 0, &ic->phi_dot)))
            return rc;
        s->phi_dot_rule = TIPPE_PHI_DOT_GIVEN;
        return TIPPE_OK;
    }
    if (!cJSON_IsString(pd))
        return fail(c, "initial.phi_dot", "expected a number (rad/s) or steady, s1, s2, s3; "
                                          "got %s", kind(pd));
    static const struct {
        const char *name;
        tippe_precession_rule rule;
    } rules[] = {{"steady", TIPPE_PRECESSION_STEADY}, {"s1", TIPPE_PRECESSION_S1},
                 {"s2", TIPPE_PRECESSION_S2}, {"s3", TIPPE_PRECESSION_S3}};
    int found = -1;
    for (int i = 0; i < 4; i++)
        if (!strcmp(pd->valuestring, rules[i].name))
            found = i;
    if (found < 0)
        return fail(c, "initial.phi_dot", "unknown rule '%s' (a number in rad/s, or steady, "
                                          "s1, s2, s3)", pd->valuestring);
    s->phi_dot_rule = (int)rules[found].rule;
    tippe_error e;
    if (tippe_dynamics_precession(&s->model, ic->theta, ic->spin, rules[found].rule,
                                  &ic->phi_dot, &e))
        return fail(c, "initial.phi_dot", "%s", e.msg);
    return TIPPE_OK;
}

const char *tippe_scenario_phi_dot_rule_name(int rule)
{
    switch (rule) {
    case TIPPE_PRECESSION_STEADY: return "steady";
    case TIPPE_PRECESSION_S1: return "s1";
    case TIPPE_PRECESSION_S2: return "s2";
    case TIPPE_PRECESSION_S3: return "s3";
    default: return "given";
    }
}

int tippe_scenario_load(const char *path, const char *const *overrides, int n_overrides,
                        tippe_scenario *out, tippe_error *err)
{
    memset(out, 0, sizeof *out);
    if (!path || !path[0])
        return tippe_error_set(err, TIPPE_EINPUT, "no scenario file given");
    if (n_overrides > MAX_OVERRIDES)
        return tippe_error_set(err, TIPPE_EINPUT, "more than %d overrides", MAX_OVERRIDES);
    snprintf(out->path, sizeof out->path, "%s", path);
    ctx c = {.file = path, .err = err};
    char *text = NULL;
    int rc = read_text(path, &text, err);
    if (rc)
        return rc;
    cJSON *root = NULL;
    rc = parse(path, text, &root, err);
    free(text);
    if (rc)
        return rc;
    if (!cJSON_IsObject(root)) {
        rc = fail(&c, "", "expected a JSON object at the top, got %s", kind(root));
        goto done;
    }
    if ((rc = check_duplicates(&c, root, "")))
        goto done;
    for (int i = 0; i < n_overrides; i++)
        if ((rc = apply_override(&c, root, overrides[i], i)))
            goto done;
    if ((rc = check_keys(&c, root, "", top_level_keys)))
        goto done;

    const cJSON *name = cJSON_GetObjectItemCaseSensitive(root, "name");
    if (name && !cJSON_IsString(name)) {
        rc = fail(&c, "name", "expected a string, got %s", kind(name));
        goto done;
    }
    snprintf(out->name, sizeof out->name, "%s", name ? name->valuestring : path);
    /* the file's name may describe values the command line changed: say so */
    for (int i = 0; i < n_overrides; i++) {
        size_t len = strlen(out->name);
        snprintf(out->name + len, sizeof out->name - len, "%s%s", i ? ", " : " [changed: ",
                 overrides[i]);
    }
    if (n_overrides > 0) {
        size_t len = strlen(out->name);
        if (len + 1 < sizeof out->name)
            snprintf(out->name + len, sizeof out->name - len, "]");
    }
    const cJSON *notes = cJSON_GetObjectItemCaseSensitive(root, "notes");
    if (notes && !cJSON_IsString(notes)) {
        rc = fail(&c, "notes", "expected a string, got %s", kind(notes));
        goto done;
    }
    if ((rc = read_top(&c, cJSON_GetObjectItemCaseSensitive(root, "top"), out)))
        goto done;
    if ((rc = number(&c, root, "", "g", 0, TIPPE_DEFAULT_G_M_S2, &out->model.g)))
        goto done;
    if (!(out->model.g > 0)) {
        rc = fail(&c, "g", "must be > 0 m/s^2, got %g", out->model.g);
        goto done;
    }
    if ((rc = number(&c, root, "", "mu", 1, 0, &out->model.mu)))
        goto done;
    if (!(out->model.mu >= 0)) {
        rc = fail(&c, "mu", "friction coefficient must be >= 0 s/m, got %g", out->model.mu);
        goto done;
    }
    if ((rc = number(&c, root, "", "t_end", 1, 0, &out->t_end)))
        goto done;
    if (!(out->t_end > 0)) {
        rc = fail(&c, "t_end", "must be > 0 s, got %g", out->t_end);
        goto done;
    }
    if ((rc = read_accuracy(&c, cJSON_GetObjectItemCaseSensitive(root, "accuracy"), out)))
        goto done;
    rc = read_initial(&c, cJSON_GetObjectItemCaseSensitive(root, "initial"), out);
done:
    cJSON_Delete(root);
    return rc;
}
