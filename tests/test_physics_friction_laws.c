/* The friction laws' table (src/physics/friction_laws.c) and the friction options'
 * rules both front ends share (tippe_friction_choose): the table agrees with the
 * dynamics' names and steppers, a parameter alone names its law, a parameter of
 * another law is refused naming its field, and --friction's help is made whole. */
#include "check.h"

#include "tippe/design.h"
#include "tippe/launch.h"

#include <stdio.h>
#include <string.h>

static const tippe_friction_names names = {
    .name = {"--friction", "--patch-mm", "--table", "--mu-c", "--slip-scale", "--mu",
             "--radius-span"},
    .choose = "--friction %s",
};

#define BIT(p) (1u << (p))

/* Every law once, its name the dynamics' name, its stiff stepper the dynamics'. */
static void test_table(void)
{
    int n = 0;
    for (const tippe_friction_law_type *t; (t = tippe_friction_law_at(n)) != NULL; n++) {
        CHECK(!strcmp(tippe_friction_law_name(t->law), t->name), "law %d: '%s' vs '%s'", n,
              tippe_friction_law_name(t->law), t->name);
        CHECK(tippe_friction_law_parse(t->name) == (int)t->law, "%s parses back", t->name);
        CHECK(tippe_friction_law_find(t->name) == t, "%s found", t->name);
        CHECK(tippe_friction_law_type_of(t->law) == t, "%s by its enum", t->name);
        const char *used = tippe_dynamics_stepper_used(t->law, 0.0, "rk8pd");
        CHECK(t->stiff_stepper ? !strcmp(used, t->stiff_stepper) : !strcmp(used, "rk8pd"),
              "%s runs %s for rk8pd, its entry says %s", t->name, used,
              t->stiff_stepper ? t->stiff_stepper : "rk8pd");
        /* with its creep reduced (the front ends' default) the explicit stepper serves */
        used = tippe_dynamics_stepper_used(t->law, TIPPE_PATCH_CREEP_CAP, "rk8pd");
        CHECK(!strcmp(used, "rk8pd"), "%s with a creep cap runs %s for rk8pd", t->name, used);
        CHECK(t->text && t->word && t->describe && t->json, "%s: every entry filled", t->name);
    }
    CHECK(n == TIPPE_N_FRICTION_LAWS, "%d laws listed", n);
    CHECK(tippe_friction_law_find("dry") == NULL, "an unknown name");
    char list[128];
    CHECK(!strcmp(tippe_friction_law_list(" or ", list, sizeof list),
                  "viscous, coulomb, coulomb-creep or patch"),
          "the list: %s", list);
    /* a coefficient names its law */
    CHECK(tippe_friction_law_named_by(TIPPE_LAW_PARAM_MU) == tippe_friction_law_at(0),
          "mu names the default law");
    CHECK(!strcmp(tippe_friction_law_named_by(TIPPE_LAW_PARAM_MU_C)->name, "coulomb"), "mu_c");
    CHECK(!strcmp(tippe_friction_law_named_by(TIPPE_LAW_PARAM_PATCH_MM)->name, "patch"),
          "patch_mm");
}

/* The help: every line within 70 columns, every law named, "|F| = mu_c" whole. */
static void test_help(void)
{
    char buf[1024];
    tippe_friction_law_help(70, "; docs/dynamics.md", buf, sizeof buf);
    int longest = 0;
    for (const char *line = buf; *line;) {
        const char *end = strchr(line, '\n');
        const int len = end ? (int)(end - line) : (int)strlen(line);
        if (len > longest)
            longest = len;
        line += len + (end != NULL);
    }
    CHECK(longest <= 70, "a help line of %d columns", longest);
    char flat[1024], want[256]; /* unwrapped: each law as "name (text)" */
    snprintf(flat, sizeof flat, "%s", buf);
    for (char *p = flat; (p = strchr(p, '\n')) != NULL;)
        *p = ' ';
    for (int i = 0; tippe_friction_law_at(i); i++) {
        snprintf(want, sizeof want, "%s (%s)", tippe_friction_law_at(i)->name,
                 tippe_friction_law_at(i)->text);
        CHECK(strstr(flat, want) != NULL, "%s in the help: %s", want, flat);
    }
    CHECK(strstr(buf, "|F| = mu_c") != NULL, "the equation is not cut: %s", buf);
}

static int choose(tippe_friction_given g, tippe_launch_options *o, tippe_error *e)
{
    tippe_friction_law laws[TIPPE_MAX_FRICTION_LAWS];
    int n = 0;
    tippe_launch_options_default(o);
    return tippe_friction_choose(&g, &names, laws, &n, o, e);
}

static void test_rules(void)
{
    tippe_launch_options o;
    tippe_error e;
    /* a parameter alone names its law */
    CHECK(choose((tippe_friction_given){.given = BIT(TIPPE_LAW_PARAM_PATCH_MM), .patch_mm = 0.3},
                 &o, &e) == TIPPE_OK &&
              tippe_friction_law_type_of(o.law)->patch && o.patch_radius_m == 0.3e-3,
          "--patch-mm alone: the patch law, a = 0.3 mm");
    CHECK(choose((tippe_friction_given){.given = BIT(TIPPE_LAW_PARAM_MU_C)}, &o, &e) == TIPPE_OK &&
              tippe_friction_law_type_of(o.law)->sticks,
          "--mu-c alone: Coulomb's");
    CHECK(choose((tippe_friction_given){0}, &o, &e) == TIPPE_OK &&
              o.law == tippe_friction_law_at(0)->law,
          "nothing given: the default law");
    /* refused, naming the field */
    CHECK(choose((tippe_friction_given){.given = BIT(TIPPE_LAW_PARAM_MU) |
                                                 BIT(TIPPE_LAW_PARAM_MU_C)},
                 &o, &e) == TIPPE_EINPUT &&
              !strcmp(e.field, "mu_s_m") && strstr(e.msg, "name different laws"),
          "mu and mu_c: %s (%s)", e.msg, e.field);
    CHECK(choose((tippe_friction_given){.laws = "viscous", .given = BIT(TIPPE_LAW_PARAM_TABLE),
                                        .table = "glass"},
                 &o, &e) == TIPPE_EINPUT &&
              !strcmp(e.field, "table") &&
              !strcmp(e.msg, "--table belongs to the patch law: give --friction patch"),
          "a table under the viscous law: %s (%s)", e.msg, e.field);
    CHECK(choose((tippe_friction_given){.laws = "coulomb",
                                        .given = BIT(TIPPE_LAW_PARAM_RADIUS_SPAN)},
                 &o, &e) == TIPPE_EINPUT &&
              !strcmp(e.field, "radius_span"),
          "--radius-span under Coulomb's: %s (%s)", e.msg, e.field);
    CHECK(choose((tippe_friction_given){.laws = "patch",
                                        .given = BIT(TIPPE_LAW_PARAM_PATCH_MM) |
                                                 BIT(TIPPE_LAW_PARAM_TABLE),
                                        .patch_mm = 0.3, .table = "glass"},
                 &o, &e) == TIPPE_EINPUT &&
              !strcmp(e.field, "table"),
          "a radius and a table: %s (%s)", e.msg, e.field);
    CHECK(choose((tippe_friction_given){.laws = "patch", .given = BIT(TIPPE_LAW_PARAM_TABLE),
                                        .table = "ice"},
                 &o, &e) == TIPPE_EINPUT &&
              !strcmp(e.field, "table") && strstr(e.msg, "'ice'"),
          "an unknown table: %s (%s)", e.msg, e.field);
    CHECK(choose((tippe_friction_given){.laws = "viscous,patch"}, &o, &e) == TIPPE_EINPUT &&
              !strcmp(e.field, "friction"),
          "two laws where one is taken: %s (%s)", e.msg, e.field);
    CHECK(choose((tippe_friction_given){.laws = "dry"}, &o, &e) == TIPPE_EINPUT &&
              strstr(e.msg, "expected viscous, coulomb, coulomb-creep or patch"),
          "an unknown law: %s", e.msg);
}

/* The rules that need the design (tippe_friction_for_design), on the M12 ball. */
static void test_for_design(void)
{
    tippe_design *d = NULL;
    tippe_error e;
    if (tippe_design_load("designs/m12-setscrew.json", NULL, 0, &d, &e)) {
        CHECK(0, "the M12 design loads: %s", e.msg);
        return;
    }
    const tippe_friction_law patch = tippe_friction_law_named_by(TIPPE_LAW_PARAM_PATCH_MM)->law;
    const tippe_friction_law viscous = tippe_friction_law_at(0)->law;
    tippe_launch_options o;
    tippe_launch_options_default(&o);
    o.law = viscous;
    CHECK(tippe_friction_for_design(d, &viscous, 1, NULL, &names, &o, &e) == TIPPE_OK &&
              o.patch_radius_span == 0 && o.patch_E_star_pa == 0,
          "the viscous law: nothing to do");
    o.law = patch;
    CHECK(tippe_friction_for_design(d, &patch, 1, "glass", &names, &o, &e) == TIPPE_OK &&
              o.patch_E_star_pa > 1e9 && o.patch_radius_span == tippe_design_patch_radius_span(d),
          "Hertz on glass: E* %g Pa, span %g", o.patch_E_star_pa, o.patch_radius_span);
    tippe_launch_options_default(&o);
    o.law = patch;
    o.patch_radius_m = 0.6 * tippe_design_radius_mm(d) * 1e-3;
    CHECK(tippe_friction_for_design(d, &patch, 1, NULL, &names, &o, &e) == TIPPE_EINPUT &&
              !strcmp(e.field, "patch_mm") && !strncmp(e.msg, "--patch-mm ", 11),
          "a patch wider than R/2: %s (%s)", e.msg, e.field);
    tippe_design_free(d);
}

int main(void)
{
    test_table();
    test_help();
    test_rules();
    test_for_design();
    return check_summary("test_physics_friction_laws");
}
