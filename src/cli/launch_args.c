/* One launch's arguments, from a scenario file or a design with --z2 and
 * --spin, shared by simulate, check, animate, launch and map. */
#include "cli.h"

#include "base/json.h"
#include "tippe/base.h"
#include "tippe/design.h"
#include "tippe/scenario.h"

#include <cjson/cJSON.h>

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- one launch, from a scenario file or a design ---------------------------- */

/* The input file's text as read to tell its kind, kept so that the load parses
 * it rather than reading the file a second time (issue 34); one input per
 * command. NULL when it did not read: the load then reads the file and says why. */
static struct {
    char *path, *text;
    size_t len;
} input;

/* The file's kind: a design has "parts" at its top (a scenario never has). */
static int is_design_file(const char *path)
{
    tippe_error err;
    tippe_json_reader *c = tippe_json_reader_new(path, &err, TIPPE_JSON_WORDS_KEY, "");
    cJSON *root = NULL;
    char *text = NULL;
    size_t len = 0;
    int design = c && tippe_json_read(c, 16, "file", &text, &len) == TIPPE_OK &&
                 tippe_json_parse_text(c, text, len, 16, "file", &root) == TIPPE_OK &&
                 cJSON_IsObject(root) && cJSON_GetObjectItemCaseSensitive(root, "parts");
    cJSON_Delete(root);
    free(c);
    free(input.path);
    free(input.text);
    input.path = text ? strdup(path) : NULL;
    input.text = input.path ? text : NULL;
    input.len = input.path ? len : 0;
    if (!input.path)
        free(text);
    return design;
}

/* --phi-dot: a rule, or a rate with its unit, as the override initial.phi_dot. */
static int add_phi_dot(const char *verb, tippe_cli_launch_args *l)
{
    static const char *const rules[] = {"steady", "s1", "s2", "s3"};
    for (int i = 0; i < 4; i++)
        if (!strcmp(l->phi_dot, rules[i]))
            return tippe_cli_sets_add(&l->over, "initial.phi_dot", l->phi_dot) ? 2 : 0;
    double x;
    char num[64];
    if (!tippe_cli_parse_unit(l->phi_dot, "rad/s", &x) || !(fabs(x) <= TIPPE_CLI_RATE_MAX_RAD_S))
        return tippe_cli_usage_error(verb,
                                     "--phi-dot '%s': expected steady, s1, s2, s3 or a number "
                                     "of rad/s from -%g to %g",
                                     l->phi_dot, TIPPE_CLI_RATE_MAX_RAD_S,
                                     TIPPE_CLI_RATE_MAX_RAD_S);
    snprintf(num, sizeof num, "%.17g", x);
    return tippe_cli_sets_add(&l->over, "initial.phi_dot", num) ? 2 : 0;
}

/* The words --friction, --accuracy and --stepper take, checked here so that a bad
 * one is the option's fault, not the file's: 0, or 2 after a usage error. */
static int check_words(const char *verb, const tippe_cli_launch_args *l)
{
    tippe_dynamics_accuracy acc;
    for (int i = 0; i < l->over.n; i++) {
        const char *it = l->over.item[i];
        char list[128];
        if (!strncmp(it, "friction.law=", 13) && !tippe_friction_law_find(it + 13))
            return tippe_cli_usage_error(verb, "--friction '%s': expected %s", it + 13,
                                         tippe_friction_law_list(" or ", list, sizeof list));
        double E, nu;
        if (!strncmp(it, "friction.table=", 15) && tippe_contact_table_surface(it + 15, &E, &nu))
            return tippe_cli_usage_error(verb, "--table '%s': expected " TIPPE_CONTACT_TABLES,
                                         it + 15);
        if (!strncmp(it, "accuracy=", 9) && tippe_dynamics_accuracy_preset(it + 9, &acc, NULL))
            return tippe_cli_usage_error(verb, "--accuracy '%s': expected fast, balanced or "
                                               "precise",
                                         it + 9);
        if (!strncmp(it, "accuracy.stepper=", 17) && !tippe_dynamics_stepper_known(it + 17))
            return tippe_cli_usage_error(verb, "--stepper '%s': expected rk2, rk4, rkf45, rkck, "
                                               "rk8pd, rk1imp, rk2imp, rk4imp, bsimp, msadams "
                                               "or msbdf",
                                         it + 17);
    }
    return 0;
}

/* --friction, --mu, --mu-c and --slip-scale name one law, as in tippe launch (a
 * coefficient alone selects its law: the scenario's overrides do that). 0, or 2. */
static int check_friction_opts(const char *verb, tippe_cli_spec *spec,
                               const tippe_cli_launch_args *l)
{
    const tippe_cli_opt *fr = tippe_cli_find_opt(spec, "friction");
    const tippe_cli_opt *mu = tippe_cli_find_opt(spec, "mu");
    const tippe_cli_opt *mu_c = tippe_cli_find_opt(spec, "mu-c");
    const tippe_cli_opt *vs = tippe_cli_find_opt(spec, "slip-scale");
    const int mu_seen = mu && mu->seen, mu_c_seen = mu_c && mu_c->seen;
    const int coulomb_seen = mu_c_seen || (vs && vs->seen);
    const char *law = NULL; /* --friction's value: the last friction.law override */
    if (fr && fr->seen)
        for (int i = 0; i < l->over.n; i++)
            if (!strncmp(l->over.item[i], "friction.law=", 13))
                law = l->over.item[i] + 13;
    /* check_words found it in the table: the parameters it takes */
    const tippe_friction_law_type *t = law ? tippe_friction_law_find(law) : NULL;
    if (!law && mu_seen && coulomb_seen)
        return tippe_cli_usage_error(verb, "--mu (s/m, viscous) and --mu-c or --slip-scale "
                                           "(Coulomb) name different laws: give one, or "
                                           "--friction");
    if (t && !(t->params & (1u << TIPPE_LAW_PARAM_MU_C)) && coulomb_seen)
        return tippe_cli_usage_error(verb, "%s: with the viscous law give --mu (s/m)",
                                     mu_c_seen ? "--mu-c is the Coulomb coefficient"
                                               : "--slip-scale is the Coulomb law's "
                                                 "regularisation");
    const tippe_cli_opt *pm = tippe_cli_find_opt(spec, "patch-mm");
    const tippe_cli_opt *tb = tippe_cli_find_opt(spec, "table");
    if (t && !(t->params & (1u << TIPPE_LAW_PARAM_PATCH_MM)) &&
        ((pm && pm->seen) || (tb && tb->seen)))
        return tippe_cli_usage_error(verb, "--%s belongs to the patch law, not %s",
                                     pm && pm->seen ? "patch-mm" : "table", law);
    if (t && !(t->params & (1u << TIPPE_LAW_PARAM_MU)) && mu_seen)
        return tippe_cli_usage_error(verb, "--mu (s/m) is the viscous coefficient: with the "
                                           "%s law give --mu-c",
                                     law);
    return 0;
}

/* The option (without "--") whose shorthand made the override item, or NULL. */
static const char *option_of(const tippe_cli_spec *spec, const tippe_cli_launch_args *l,
                             const char *item)
{
    const char *eq = strchr(item, '=');
    const size_t len = eq ? (size_t)(eq - item) : 0;
    if (len == 15 && !strncmp(item, "initial.phi_dot", len))
        return "phi-dot";
    if (len == 9 && !strncmp(item, "top.z2_mm", len))
        return "z2";
    for (const tippe_cli_opt *o = spec->opts; o->name; o++)
        if (o->field && o->value == &l->over && strlen(o->field) == len &&
            !strncmp(item, o->field, len))
            return o->name;
    return NULL;
}

int tippe_cli_launch_finish(const char *verb, tippe_cli_spec *spec, const char *file,
                            tippe_cli_launch_args *l)
{
    int rc;
    if ((rc = check_words(verb, l)) != 0 || (rc = check_friction_opts(verb, spec, l)) != 0)
        return rc;
    if (l->phi_dot && (rc = add_phi_dot(verb, l)) != 0)
        return rc;
    const tippe_cli_opt *theta = tippe_cli_find_opt(spec, "theta");
    const tippe_cli_opt *spin = tippe_cli_find_opt(spec, "spin");
    l->theta_given = theta && theta->seen;
    l->spin_given = spin && spin->seen;
    const int has_z2 = tippe_cli_find_opt(spec, "z2")->seen;
    l->is_design = is_design_file(file);
    if (l->is_design && !has_z2)
        return tippe_cli_usage_error(verb, "--z2 MM is required with a design file");
    if (!l->is_design && has_z2) {
        char num[64];
        snprintf(num, sizeof num, "%.17g", l->z2_mm);
        tippe_cli_sets_add(&l->over, "top.z2_mm", num);
    }
    for (int i = 0; i < l->over.n; i++) /* the shorthands, for messages */
        l->over_opt[i] = option_of(spec, l, l->over.item[i]);
    l->n_named = l->over.n;
    if (!l->is_design) /* --set names scenario fields, after the shorthands */
        for (int i = 0; i < l->sets.n; i++)
            if (tippe_cli_sets_add(&l->over, NULL, l->sets.item[i]))
                return tippe_cli_usage_error(verb, "more than %d overrides", TIPPE_CLI_MAX_SETS);
    return 0;
}

/* A loader's message blames an override as "(set on the command line:
 * FIELD=VALUE)" (tippe/scenario.h): where an option's shorthand made it, the
 * message names the option as it was given, "(set by --theta 1.5707963267)". */
static void name_options(const tippe_cli_launch_args *l, tippe_error *err)
{
    for (int i = 0; i < l->n_named; i++) {
        if (!l->over_opt[i])
            continue;
        char needle[600];
        snprintf(needle, sizeof needle, "(set on the command line: %s)", l->over.item[i]);
        char *at = strstr(err->msg, needle);
        if (!at)
            continue;
        char tail[sizeof err->msg];
        snprintf(tail, sizeof tail, "(set by --%s %s)%s", l->over_opt[i],
                 strchr(l->over.item[i], '=') + 1, at + strlen(needle));
        snprintf(at, sizeof err->msg - (size_t)(at - err->msg), "%s", tail);
    }
}

/* A precession a rule derived from the command line's --theta, --spin or --phi-dot
 * RULE: within the range --phi-dot allows a number (near pi/2 the rule divides by
 * cos(theta) ~ 0 and gives any rate at all). TIPPE_OK, or TIPPE_EINPUT naming the
 * option to change: the tilt's near pi/2, else the spin's. */
static int check_derived_rate(const char *file, const tippe_cli_launch_args *l,
                              const tippe_scenario *sc, tippe_error *err)
{
    const tippe_dynamics_initial *ic = &sc->initial;
    /* --phi-dot was checked: a rule (steady, s1, s2, s3) or a number, never 's...' */
    const int rule_given = l->phi_dot && l->phi_dot[0] == 's';
    if (sc->phi_dot_rule == TIPPE_PHI_DOT_GIVEN || fabs(ic->phi_dot) <= TIPPE_CLI_RATE_MAX_RAD_S ||
        !(l->theta_given || l->spin_given || rule_given))
        return TIPPE_OK;
    const char *rule = tippe_scenario_phi_dot_rule_name(sc->phi_dot_rule);
    const int near = fabs(cos(ic->theta)) < 0.5;
    const char *opt = near ? (l->theta_given ? "--theta" : l->spin_given ? "--spin" : NULL)
                           : (l->spin_given ? "--spin" : l->theta_given ? "--theta" : NULL);
    char who[1200];
    if (!opt)
        snprintf(who, sizeof who, "--phi-dot %s (with %s's initial.%s %.17g %s)", l->phi_dot,
                 file, near ? "theta" : "spin", near ? ic->theta : ic->spin,
                 near ? "rad" : "rad/s");
    else if (!strcmp(opt, "--theta"))
        snprintf(who, sizeof who, "--theta %.17g rad (%.3g rad from pi/2)", ic->theta,
                 fabs(M_PI_2 - ic->theta));
    else
        snprintf(who, sizeof who, "--spin %.17g rad/s", ic->spin);
    return tippe_error_set(err, TIPPE_EINPUT,
                           "%s: the %s precession there is %.3g rad/s (theta %.6g rad, spin %g "
                           "rad/s), outside the -%g .. %g rad/s --phi-dot allows: %s, or give "
                           "--phi-dot RATE",
                           who, rule, ic->phi_dot, ic->theta, ic->spin, TIPPE_CLI_RATE_MAX_RAD_S,
                           TIPPE_CLI_RATE_MAX_RAD_S,
                           near ? "tilt less (theta further from pi/2)" : "spin slower");
}

int tippe_cli_launch_load(const char *file, const tippe_cli_launch_args *l, tippe_scenario *sc,
                          tippe_error *err)
{
    const int known = input.path && !strcmp(input.path, file);
    const char *text = known ? input.text : NULL;
    const size_t len = known ? input.len : 0;
    int rc = l->is_design ? tippe_scenario_for_design(file, text, len, l->z2_mm, l->sets.item,
                                                      l->sets.n, l->over.item, l->over.n, sc, err)
                          : tippe_scenario_load_text(file, text, len, l->over.item, l->over.n,
                                                     sc, err);
    if (rc == TIPPE_EINPUT)
        name_options(l, err);
    if (!rc && (rc = check_derived_rate(file, l, sc, err)))
        tippe_scenario_free(sc);
    return rc;
}
