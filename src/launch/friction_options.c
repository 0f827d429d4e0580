/* The rules of the friction options, one place for the command and the server
 * (tippe_friction_choose, tippe/launch.h): which law the options name, and which
 * parameter belongs to which law, asked of the laws' table (friction_laws.c). */
#include "tippe/launch.h"

#include <stdio.h>
#include <string.h>

#define BIT(p) (1u << (p))

static int given(const tippe_friction_given *g, tippe_friction_param_id p)
{
    return (g->given & BIT(p)) != 0;
}

static int among(const tippe_friction_law *laws, int n, tippe_friction_param_id p)
{
    for (int i = 0; i < n; i++)
        if (tippe_friction_law_takes(laws[i], p))
            return 1;
    return 0;
}

/* The laws of g->laws ("a" or "a,b,..."): 0, or TIPPE_EINPUT. */
static int parse_laws(const tippe_friction_given *g, const tippe_friction_names *nm,
                      tippe_friction_law *out, int *n, tippe_error *err)
{
    const char *opt = nm->name[TIPPE_LAW_PARAM_LAW], *key = "friction";
    char buf[128], list[128];
    snprintf(buf, sizeof buf, "%s", g->laws);
    *n = 0;
    for (char *save = NULL, *w = strtok_r(buf, ",", &save); w; w = strtok_r(NULL, ",", &save)) {
        const tippe_friction_law_type *t = tippe_friction_law_find(w);
        if (!t)
            return tippe_error_set_field(err, TIPPE_EINPUT, key, "%s '%s': expected %s%s", opt, w,
                                         tippe_friction_law_list(" or ", list, sizeof list),
                                         nm->list ? " (or several, comma-separated)" : "");
        for (int i = 0; i < *n; i++)
            if (out[i] == t->law)
                return tippe_error_set_field(err, TIPPE_EINPUT, key, "%s '%s': %s twice", opt,
                                             g->laws, w);
        if (*n == TIPPE_MAX_FRICTION_LAWS)
            return tippe_error_set_field(err, TIPPE_EINPUT, key, "%s '%s': at most %d laws", opt,
                                         g->laws, TIPPE_MAX_FRICTION_LAWS);
        out[(*n)++] = t->law;
    }
    if (*n == 0)
        return tippe_error_set_field(err, TIPPE_EINPUT, key, "%s '%s': expected a law", opt,
                                     g->laws);
    if (*n > 1 && !nm->list)
        return tippe_error_set_field(err, TIPPE_EINPUT, key,
                                     "%s '%s': one law (tippe check compares several)", opt,
                                     g->laws);
    return TIPPE_OK;
}

int tippe_friction_choose(const tippe_friction_given *g, const tippe_friction_names *nm,
                          tippe_friction_law *out, int *n, tippe_launch_options *o,
                          tippe_error *err)
{
    const char *const *name = nm->name;
    const tippe_friction_param *p = tippe_friction_params;
    const int mu = given(g, TIPPE_LAW_PARAM_MU), mu_c = given(g, TIPPE_LAW_PARAM_MU_C);
    const int coulomb = mu_c || given(g, TIPPE_LAW_PARAM_SLIP_SCALE);
    const int patch_mm = given(g, TIPPE_LAW_PARAM_PATCH_MM) && g->patch_mm > 0;
    const int table = given(g, TIPPE_LAW_PARAM_TABLE) && g->table;
    const tippe_friction_param_id radius = patch_mm ? TIPPE_LAW_PARAM_PATCH_MM
                                                    : TIPPE_LAW_PARAM_TABLE;
    char choose[96];
    int rc;
    if (g->laws) {
        if ((rc = parse_laws(g, nm, out, n, err)) != 0)
            return rc;
    } else if (mu && coulomb) {
        return tippe_error_set_field(err, TIPPE_EINPUT, p[TIPPE_LAW_PARAM_MU].key,
                                     "%s (s/m, viscous) and %s or %s (Coulomb) name different "
                                     "laws: give one, or %s",
                                     name[TIPPE_LAW_PARAM_MU],
                                     name[TIPPE_LAW_PARAM_MU_C],
                                     name[TIPPE_LAW_PARAM_SLIP_SCALE],
                                     name[TIPPE_LAW_PARAM_LAW]);
    } else {
        /* a parameter given alone names the law it belongs to (the patch's radius before
         * Coulomb's coefficient: both belong to the patch law) */
        *n = 1;
        const tippe_friction_law_type *t =
            (patch_mm || table) && !mu ? tippe_friction_law_named_by(radius)
            : coulomb                  ? tippe_friction_law_named_by(TIPPE_LAW_PARAM_MU_C)
            : mu                       ? tippe_friction_law_named_by(TIPPE_LAW_PARAM_MU)
                                       : NULL;
        out[0] = t ? t->law : o->law;
    }
    o->law = out[0];
    /* each parameter given belongs to a law among those given */
    if (coulomb && !among(out, *n, TIPPE_LAW_PARAM_MU_C))
        return tippe_error_set_field(
            err, TIPPE_EINPUT, p[mu_c ? TIPPE_LAW_PARAM_MU_C : TIPPE_LAW_PARAM_SLIP_SCALE].key,
            "%s %s: with the viscous law give %s (s/m)",
            name[mu_c ? TIPPE_LAW_PARAM_MU_C : TIPPE_LAW_PARAM_SLIP_SCALE],
            mu_c ? "is the Coulomb coefficient" : "is the Coulomb law's regularisation",
            name[TIPPE_LAW_PARAM_MU]);
    if (mu && !among(out, *n, TIPPE_LAW_PARAM_MU))
        return tippe_error_set_field(err, TIPPE_EINPUT, p[TIPPE_LAW_PARAM_MU].key,
                                     "%s (s/m) is the viscous coefficient: with the %s law give "
                                     "%s",
                                     name[TIPPE_LAW_PARAM_MU],
                                     tippe_friction_law_type_of(o->law)->name,
                                     name[TIPPE_LAW_PARAM_MU_C]);
    snprintf(choose, sizeof choose, nm->choose, tippe_friction_law_named_by(radius)->name);
    if ((patch_mm || table) && !among(out, *n, radius))
        return tippe_error_set_field(err, TIPPE_EINPUT, p[radius].key,
                                     "%s belongs to the patch law: give %s", name[radius], choose);
    if (given(g, TIPPE_LAW_PARAM_RADIUS_SPAN) &&
        !among(out, *n, TIPPE_LAW_PARAM_RADIUS_SPAN))
        return tippe_error_set_field(err, TIPPE_EINPUT, p[TIPPE_LAW_PARAM_RADIUS_SPAN].key,
                                     "%s belongs to the patch law (its radius sensitivity): "
                                     "give %s",
                                     name[TIPPE_LAW_PARAM_RADIUS_SPAN], choose);
    if (given(g, TIPPE_LAW_PARAM_CREEP_CAP) && !among(out, *n, TIPPE_LAW_PARAM_CREEP_CAP))
        return tippe_error_set_field(err, TIPPE_EINPUT, p[TIPPE_LAW_PARAM_CREEP_CAP].key,
                                     "%s belongs to the patch law (its creep): give %s",
                                     name[TIPPE_LAW_PARAM_CREEP_CAP], choose);
    double E, nu;
    if (table && tippe_contact_table_surface(g->table, &E, &nu))
        return tippe_error_set_field(err, TIPPE_EINPUT, p[TIPPE_LAW_PARAM_TABLE].key,
                                     "%s '%s': expected " TIPPE_CONTACT_TABLES,
                                     name[TIPPE_LAW_PARAM_TABLE], g->table);
    if (table && patch_mm)
        return tippe_error_set_field(err, TIPPE_EINPUT, p[TIPPE_LAW_PARAM_TABLE].key,
                                     "%s gives the radius, %s derives it: give one",
                                     name[TIPPE_LAW_PARAM_PATCH_MM],
                                     name[TIPPE_LAW_PARAM_TABLE]);
    o->patch_radius_m = patch_mm ? g->patch_mm * 1e-3 : 0.0;
    return TIPPE_OK;
}

int tippe_friction_for_design(const tippe_design *d, const tippe_friction_law *laws, int n_laws,
                              const char *table, const tippe_friction_names *nm,
                              tippe_launch_options *o, tippe_error *err)
{
    int patch = 0;
    for (int i = 0; i < n_laws; i++)
        patch |= tippe_friction_law_type_of(laws[i])->patch;
    if (!patch)
        return TIPPE_OK;
    /* the dynamics' bound (a patch wider than R/2 is no patch), said with the parameter */
    const double R_mm = tippe_design_radius_mm(d), a_mm = o->patch_radius_m * 1e3;
    if (a_mm > 0.5 * R_mm)
        return tippe_error_set_field(err, TIPPE_EINPUT,
                                     tippe_friction_params[TIPPE_LAW_PARAM_PATCH_MM].key,
                                     "%s %g: wider than half the ball's radius (R/2 = %g mm); "
                                     "a contact patch is small beside the ball (Hertz: a << R)",
                                     nm->name[TIPPE_LAW_PARAM_PATCH_MM], a_mm, 0.5 * R_mm);
    if (!(o->patch_radius_span > 0)) /* given, else the design's tolerance */
        o->patch_radius_span = tippe_design_patch_radius_span(d);
    if (o->patch_radius_m > 0)
        return TIPPE_OK;
    return tippe_launch_patch_modulus(d, table, &o->patch_E_star_pa, err);
}
