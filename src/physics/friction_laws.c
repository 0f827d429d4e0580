/* The friction laws, one table entry each (tippe/physics.h, "friction laws"): their
 * names and words, their parameters with units and ranges, what each one needs and
 * says of itself. The force of each law is in the dynamics (dynamics_equations.c); the
 * rules of the friction options that the command and the server share are in
 * friction_options.c. */
#include "tippe/physics.h"

#include <cjson/cJSON.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#define BIT(p) (1u << (p))
#define STR_(x) #x
#define STR(x) STR_(x)
#define COULOMB_PARAMS (BIT(TIPPE_LAW_PARAM_MU_C) | BIT(TIPPE_LAW_PARAM_SLIP_SCALE))

const tippe_friction_param tippe_friction_params[TIPPE_LAW_N_PARAMS] = {
    [TIPPE_LAW_PARAM_LAW] = {.key = "friction", .option = "friction", .arg = "LAW",
                                  .def = "viscous"},
    [TIPPE_LAW_PARAM_PATCH_MM] =
        {.key = "patch_mm", .option = "patch-mm", .arg = "A", .unit = "mm", .number = 1,
         .min = 1e-6, .max = 10, .def = "Hertz at m g",
         .help = "patch law: the contact patch's radius (default: Hertz's from the\n"
                 "ball's and the table's E and nu at the static load m g; given alone,\n"
                 "it selects --friction patch)"},
    [TIPPE_LAW_PARAM_TABLE] =
        {.key = "table", .option = "table", .arg = "SURFACE", .def = TIPPE_CONTACT_DEFAULT_TABLE,
         .help = "patch law: the table's surface for the Hertz patch: glass, laminate,\n"
                 "wood or steel (docs/contact-patch.md; given alone, it selects\n"
                 "--friction patch)"},
    [TIPPE_LAW_PARAM_MU_C] =
        {.key = "mu_c", .option = "mu-c", .arg = "X", .number = 1, .min = 0, .max = 10,
         .def = STR(TIPPE_LAUNCH_DEFAULT_MU_C),
         .help = "Coulomb friction coefficient (given alone, it selects --friction\n"
                 "coulomb): a printed PLA or nylon ball on a tabletop (docs/launch.md)"},
    [TIPPE_LAW_PARAM_SLIP_SCALE] =
        {.key = "slip_scale_m_s", .option = "slip-scale", .arg = "V", .unit = "m/s",
         .number = 1, .min = 1e-9, .max = 1, .def = STR(TIPPE_COULOMB_SLIP_SCALE_M_S),
         .help = "Coulomb's regularisation speed v_s (given alone, it selects --friction\n"
                 "coulomb): sliding below it is smoothed, and sticking is tried below\n"
                 "30 v_s (docs/dynamics.md)"},
    [TIPPE_LAW_PARAM_MU] =
        {.key = "mu_s_m", .option = "mu", .unit = "s/m", .number = 1, .min = 0, .max = 1e6,
         .def = STR(TIPPE_LAUNCH_DEFAULT_MU_S_M),
         .help = "viscous sliding friction (eq 3.12), the default law's coefficient: a\n"
                 "table's Coulomb coefficient over a typical slip speed (docs/launch.md)"},
    [TIPPE_LAW_PARAM_RADIUS_SPAN] =
        {.key = "radius_span", .option = "radius-span", .arg = "F", .number = 1, .min = 1.01,
         .max = 10, .def = "the design's tolerance, else 2",
         .help = "patch law: the radius sensitivity's reruns at a/F and a F, a the\n"
                 "patch radius used (Hertz's or --patch-mm)"},
    [TIPPE_LAW_PARAM_CREEP_CAP] =
        {.key = "creep_cap", .option = "creep-cap", .arg = "K", .number = 1, .min = 0,
         .max = 1e4, .def = STR(TIPPE_PATCH_CREEP_CAP),
         .help = "patch law: the creep's relaxation held to at most K times the motion's\n"
                 "rate |omega| + sqrt(g/R), so that the explicit rk8pd serves (the\n"
                 "slip's lag off by O(1/K)); 0: the full law, with msbdf\n"
                 "(docs/dynamics.md, \"The creep reduced\")"},
};

/* ---- each law's model in words and in JSON ------------------------------------ */

static void viscous_describe(const tippe_dynamics_model *m, double v_s, char *buf, size_t size)
{
    (void)v_s;
    snprintf(buf, size, "viscous mu %g s/m (eq 3.12)", m->mu);
}

static void viscous_json(cJSON *f, const tippe_dynamics_model *m)
{
    cJSON_AddNumberToObject(f, "mu_s_m", m->mu);
}

static void coulomb_describe(const tippe_dynamics_model *m, double v_s, char *buf, size_t size)
{
    snprintf(buf, size, "Coulomb mu_c %g, sliding and sticking (sliding regularised below "
             "%g m/s)", m->mu_c, v_s);
}

static void creep_describe(const tippe_dynamics_model *m, double v_s, char *buf, size_t size)
{
    snprintf(buf, size, "Coulomb mu_c %g regularised below %g m/s, no sticking (creep)",
             m->mu_c, v_s);
}

static void coulomb_json(cJSON *f, const tippe_dynamics_model *m)
{
    cJSON_AddNumberToObject(f, "mu", m->mu_c);
    cJSON_AddNumberToObject(f, "slip_scale_m_s", m->slip_scale_m_s > 0
                                                     ? m->slip_scale_m_s
                                                     : TIPPE_COULOMB_SLIP_SCALE_M_S);
}

static void patch_describe(const tippe_dynamics_model *m, double v_s, char *buf, size_t size)
{
    /* the radius: given, or Hertz's from E* (known once the model has its top: m g
     * and R); how it moves in the run; the rolling couple when on */
    const double a_mm = tippe_dynamics_patch_radius(m) * 1e3;
    char where[64], modulus[32] = "", roll[64] = "";
    if (m->patch_radius_m > 0 || !(m->patch_E_star_pa > 0)) {
        snprintf(where, sizeof where, "a patch of radius %g mm at m g", a_mm);
    } else {
        snprintf(modulus, sizeof modulus, "E* %.3g GPa, ", m->patch_E_star_pa * 1e-9);
        if (a_mm > 0)
            snprintf(where, sizeof where, "Hertz's patch, radius %.4g mm at m g", a_mm);
        else
            snprintf(where, sizeof where, "Hertz's patch");
    }
    if (m->rolling_arm_m > 0)
        snprintf(roll, sizeof roll, ", rolling resistance arm %g um", m->rolling_arm_m * 1e6);
    char creep[64] = ", the full creep";
    if (m->creep_cap > 0)
        snprintf(creep, sizeof creep, ", creep reduced above %g x the motion's rate",
                 m->creep_cap);
    snprintf(buf, size, "patch (Coulomb-Contensou) mu_c %g on %s (%sHertz pressure, %s)%s, "
             "regularised below %g m/s%s", m->mu_c, where, modulus,
             m->patch_radius_fixed ? "held" : "following the load as Rn^(1/3)", roll, v_s,
             creep);
}

static void patch_json(cJSON *f, const tippe_dynamics_model *m)
{
    coulomb_json(f, m);
    /* the radius given, or the contact modulus Hertz's radius comes from (at m g) */
    if (m->patch_radius_m > 0 || !(m->patch_E_star_pa > 0))
        cJSON_AddNumberToObject(f, "patch_mm", m->patch_radius_m * 1e3);
    else
        cJSON_AddNumberToObject(f, "E_star_GPa", m->patch_E_star_pa * 1e-9);
    cJSON_AddStringToObject(f, "pressure", "hertz");
    /* the radius the run starts from, however it was found (when the model has its
     * top: Hertz's needs m g and R) */
    if (tippe_dynamics_patch_radius(m) > 0)
        cJSON_AddNumberToObject(f, "patch_mm_at_mg", tippe_dynamics_patch_radius(m) * 1e3);
    cJSON_AddBoolToObject(f, "radius_follows_load", !m->patch_radius_fixed);
    cJSON_AddNumberToObject(f, "rolling_arm_um", m->rolling_arm_m * 1e6);
    cJSON_AddNumberToObject(f, "creep_cap", m->creep_cap);
}

/* ---- the table ------------------------------------------------------------------ */

static const tippe_friction_law_type law_types[TIPPE_N_FRICTION_LAWS] = {
    {.law = TIPPE_FRICTION_VISCOUS, .name = "viscous", .word = "viscous friction",
     .label = "viscous", .text = "eq 3.12, the paper's",
     .doc = "docs/dynamics.md, \"The model\"", .params = BIT(TIPPE_LAW_PARAM_MU),
     .describe = viscous_describe, .json = viscous_json},
    {.law = TIPPE_FRICTION_COULOMB, .name = "coulomb", .word = "Coulomb friction",
     .label = "Coulomb", .text = "sliding |F| = mu_c Rn, sticking and rolling without slipping",
     .doc = "docs/dynamics.md, \"Coulomb friction\"", .params = COULOMB_PARAMS, .sticks = 1,
     .describe = coulomb_describe, .json = coulomb_json},
    {.law = TIPPE_FRICTION_COULOMB_CREEP, .name = "coulomb-creep", .word = "Coulomb friction",
     .label = "Coulomb creep", .text = "regularised, no sticking",
     .doc = "docs/dynamics.md, \"Coulomb friction\"", .params = COULOMB_PARAMS,
     .describe = creep_describe, .json = coulomb_json},
    /* a plot has said "Coulomb creep" of the patch law's mu_c: kept (no behaviour change
     * in a restructure); its own label is the next change */
    {.law = TIPPE_FRICTION_PATCH, .name = "patch", .word = "patch friction",
     .label = "Coulomb creep",
     .text = "Coulomb-Contensou on a spinning contact patch: --patch-mm, or Hertz on --table; "
             "verdicts observed, not proved",
     .doc = "docs/dynamics.md, \"Patch friction\"",
     .params = COULOMB_PARAMS | BIT(TIPPE_LAW_PARAM_PATCH_MM) |
               BIT(TIPPE_LAW_PARAM_TABLE) | BIT(TIPPE_LAW_PARAM_RADIUS_SPAN) |
               BIT(TIPPE_LAW_PARAM_CREEP_CAP),
     .drills = 1, .patch = 1, .stiff_stepper = "msbdf", .describe = patch_describe,
     .json = patch_json},
};

const tippe_friction_law_type *tippe_friction_law_at(int i)
{
    return i >= 0 && i < TIPPE_N_FRICTION_LAWS ? &law_types[i] : NULL;
}

const tippe_friction_law_type *tippe_friction_law_type_of(tippe_friction_law law)
{
    for (int i = 0; i < TIPPE_N_FRICTION_LAWS; i++)
        if (law_types[i].law == law)
            return &law_types[i];
    return NULL;
}

const tippe_friction_law_type *tippe_friction_law_find(const char *name)
{
    for (int i = 0; name && i < TIPPE_N_FRICTION_LAWS; i++)
        if (!strcmp(law_types[i].name, name))
            return &law_types[i];
    return NULL;
}

const tippe_friction_law_type *tippe_friction_law_named_by(tippe_friction_param_id p)
{
    for (int i = 0; i < TIPPE_N_FRICTION_LAWS; i++)
        if (law_types[i].params & BIT(p))
            return &law_types[i];
    return NULL;
}

int tippe_friction_law_takes(tippe_friction_law law, tippe_friction_param_id p)
{
    const tippe_friction_law_type *t = tippe_friction_law_type_of(law);
    return t && (t->params & BIT(p)) != 0;
}

const char *tippe_friction_law_list(const char *last, char *buf, size_t size)
{
    size_t n = 0;
    buf[0] = '\0';
    for (int i = 0; i < TIPPE_N_FRICTION_LAWS && n < size; i++)
        n += (size_t)snprintf(buf + n, size - n, "%s%s",
                              i == 0 ? "" : i == TIPPE_N_FRICTION_LAWS - 1 ? last : ", ",
                              law_types[i].name);
    return buf;
}

const char *tippe_friction_law_help(int width, const char *tail, char *buf, size_t size)
{
    /* the sentence, then wrapped at spaces */
    char text[1024];
    size_t n = (size_t)snprintf(text, sizeof text, "friction law: ");
    for (int i = 0; i < TIPPE_N_FRICTION_LAWS && n < sizeof text; i++)
        n += (size_t)snprintf(text + n, sizeof text - n, "%s%s (%s)",
                              i == 0 ? "" : i == TIPPE_N_FRICTION_LAWS - 1 ? " or " : ", ",
                              law_types[i].name, law_types[i].text);
    if (n < sizeof text)
        snprintf(text + n, sizeof text - n, "%s", tail);
    snprintf(buf, size, "%s", text);
    /* greedy, at most width columns a line; never around "=" ("|F| = mu_c" stays whole) */
    for (char *line = buf, *space = NULL, *p = buf; *p; p++) {
        if (*p == ' ' && p > buf && p[-1] != '=' && p[1] != '=')
            space = p;
        if (p - line >= width && space) {
            *space = '\n';
            line = space + 1;
            space = NULL;
        }
    }
    return buf;
}

/* The stiff stepper of a law's entry stands in for the presets' rk8pd unless its creep is
 * reduced (creep_cap > 0: docs/dynamics.md, "The creep reduced"). */
const char *tippe_dynamics_stepper_used(tippe_friction_law law, double creep_cap,
                                        const char *stepper)
{
    const tippe_friction_law_type *t = tippe_friction_law_type_of(law);
    return t && t->stiff_stepper && !(creep_cap > 0) && !strcmp(stepper, "rk8pd")
               ? t->stiff_stepper
               : stepper;
}
