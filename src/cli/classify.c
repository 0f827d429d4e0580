/* tippe classify: the group of Theorem 5.1 for (A/C, eps/R), and the spin
 * thresholds when the top's m, R and C are given. */
#include "cli.h"

#include "tippe/design.h"
#include "tippe/physics.h"

#include <cjson/cJSON.h>

#include <stdio.h>
#include <string.h>

#define RAD_TO_DEG (180.0 / 3.14159265358979323846)
#define RAD_S_TO_REV_S (1.0 / (2.0 * 3.14159265358979323846))

static const char *const VERB = "classify";

enum { OPT_K, OPT_E, OPT_M, OPT_R, OPT_C, OPT_G, N_OPTS };

/* Where a threshold is undefined, say why in words. */
static const char *why_no_n_minus = "none: theta = 0 is stable at every spin (A/C - 1 <= -eps/R)";
static const char *why_no_n_plus = "none: theta = pi is unstable at every spin (A/C - 1 >= eps/R)";

static void print_spin(const char *label, int has, double rad_s, const char *why_not,
                       const char *meaning)
{
    if (has)
        printf("  %-5s %12.6g rad/s = %10.6g rev/s   %s\n", label, rad_s, rad_s * RAD_S_TO_REV_S,
               meaning);
    else
        printf("  %-5s %s\n", label, why_not);
}

static void print_text(const tippe_theory_class *c, const tippe_theory_thresholds *th,
                       const double *v, int have_top)
{
    printf("A/C       %.10g   (A/C - 1 = %+.10g)\n", c->A_over_C, c->A_over_C - 1.0);
    printf("eps/R     %.10g\n", c->eps_over_R);
    printf("group     %s, subgroup %s\n", tippe_group_family(c->group), tippe_group_name(c->group));
    if (c->boundary)
        printf("boundary  %s (within 1e-12; the side chosen is in docs/theory.md)\n", c->boundary);
    else
        printf("boundary  none\n");
    if (c->eps_over_R == 0.0)
        printf("note      eps = 0: a balanced ball, no preferred side to rest on\n");
    if (c->A_over_C < 0.5)
        printf("note      A/C < 1/2 cannot be realised by a rigid body (C <= 2 A)\n");
    if (c->has_b)
        printf("b         %.10g\n", c->b);
    else
        printf("b         undefined (not real: needs A/C < 1 and A/C - 1 <= -(eps/R)^2)\n");
    if (c->has_theta_b)
        printf("theta_b   %.6f deg (%.10g rad)\n", c->theta_b_rad * RAD_TO_DEG, c->theta_b_rad);
    else
        printf("theta_b   undefined (%s)\n", c->has_b ? "|b| > 1: no fold on the branch" : "no fold");
    if (c->has_c)
        printf("c         %.10g\n", c->c);
    else
        printf("c         undefined (A/C = 1)\n");
    if (c->has_theta_c)
        printf("theta_c   %.6f deg (%.10g rad)\n", c->theta_c_rad * RAD_TO_DEG, c->theta_c_rad);
    else
        printf("theta_c   undefined (|c| > 1 or A/C = 1: intermediate states at every theta)\n");
    if (!have_top)
        return;
    printf("\nspin thresholds for m = %g kg, R = %g m, C = %g kg m^2, g = %g m/s^2:\n", v[OPT_M],
           v[OPT_R], v[OPT_C], v[OPT_G]);
    print_spin("n-", th->has_n_minus, th->n_minus_rad_s, why_no_n_minus,
               "theta = 0 unstable when |n0| exceeds it (eq 5.11, A.14)");
    print_spin("n+", th->has_n_plus, th->n_plus_rad_s, why_no_n_plus,
               "theta = pi stable when |n_pi| exceeds it (eq 5.11, A.27)");
    print_spin("n*", th->has_n_star, th->n_star_rad_s, why_no_n_plus,
               "spin at theta = 0 above which theta = pi is stable (sec 7.1)");
    if (th->has_n_b) {
        print_spin("n_b", 1, th->n_b_0_rad_s, NULL,
                   "spin at theta = 0 with the Jellett of the fold theta_b (sec 7.1)");
        print_spin("", 1, th->n_b_pi_rad_s, NULL, "the same seen at theta = pi (Figure 14)");
    } else {
        printf("  %-5s none: no fold on the branch (only in Ib and IIa)\n", "n_b");
    }
}

/* cJSON helpers: a number, or null where undefined. */
static int add_num(cJSON *o, const char *key, int has, double v)
{
    return has ? cJSON_AddNumberToObject(o, key, v) != NULL : cJSON_AddNullToObject(o, key) != NULL;
}

static cJSON *to_json(const tippe_theory_class *c, const tippe_theory_thresholds *th,
                      const double *v, int have_top)
{
    cJSON *o = cJSON_CreateObject();
    if (!o)
        return NULL;
    /* Theorem 5.1's words: groups I, II, III; subgroups Ia .. IIc (III has none
     * of its own and is its own category). */
    int ok = cJSON_AddStringToObject(o, "group", tippe_group_family(c->group)) &&
             cJSON_AddStringToObject(o, "subgroup", tippe_group_name(c->group)) &&
             (c->boundary ? cJSON_AddStringToObject(o, "boundary", c->boundary) != NULL
                          : cJSON_AddNullToObject(o, "boundary") != NULL) &&
             add_num(o, "A_over_C", 1, c->A_over_C) && add_num(o, "eps_over_R", 1, c->eps_over_R) &&
             add_num(o, "b", c->has_b, c->b) &&
             add_num(o, "theta_b_rad", c->has_theta_b, c->theta_b_rad) &&
             add_num(o, "theta_b_deg", c->has_theta_b, c->theta_b_rad * RAD_TO_DEG) &&
             add_num(o, "c", c->has_c, c->c) &&
             add_num(o, "theta_c_rad", c->has_theta_c, c->theta_c_rad) &&
             add_num(o, "theta_c_deg", c->has_theta_c, c->theta_c_rad * RAD_TO_DEG);
    if (ok && have_top)
        ok = add_num(o, "m_kg", 1, v[OPT_M]) && add_num(o, "R_m", 1, v[OPT_R]) &&
             add_num(o, "C_kg_m2", 1, v[OPT_C]) && add_num(o, "g_m_s2", 1, v[OPT_G]) &&
             add_num(o, "n_minus_rad_s", th->has_n_minus, th->n_minus_rad_s) &&
             add_num(o, "n_plus_rad_s", th->has_n_plus, th->n_plus_rad_s) &&
             add_num(o, "n_star_rad_s", th->has_n_star, th->n_star_rad_s) &&
             add_num(o, "n_b_0_rad_s", th->has_n_b, th->n_b_0_rad_s) &&
             add_num(o, "n_b_pi_rad_s", th->has_n_b, th->n_b_pi_rad_s);
    if (!ok) {
        cJSON_Delete(o);
        return NULL;
    }
    return o;
}

typedef struct {
    double v[N_OPTS]; /* by OPT_* */
    int seen[N_OPTS];
    const char *design;
    double z2_mm;
    int has_z2, json;
    tippe_cli_sets sets;
    tippe_design_protrusion protrusion; /* a design's, at z2_mm */
} classify_args;

static int classify_parse(classify_args *a, int argc, char **argv)
{
    double *v = a->v;
    tippe_cli_opt opts[] = {
        [OPT_K] = {.name = "A-over-C", .kind = TIPPE_CLI_DOUBLE, .value = &v[OPT_K], .arg = "K",
                   .min = 1e-6, .max = 1e6,
                   .help = "A/C, A transverse through the centre of mass, C axial"},
        [OPT_E] = {.name = "eps-over-R", .kind = TIPPE_CLI_DOUBLE, .value = &v[OPT_E],
                   .arg = "E", .min = 0, .max = 1,
                   .help = "eps/R, centre of mass below the sphere's centre (E < 1)"},
        [OPT_M] = {.name = "m", .kind = TIPPE_CLI_DOUBLE, .value = &v[OPT_M], .unit = "kg",
                   .min = 1e-9, .max = 1e6,
                   .help = "mass; --m, --R and --C together give the spin thresholds\nn-, n+, n* and n_b"},
        [OPT_R] = {.name = "R", .kind = TIPPE_CLI_DOUBLE, .value = &v[OPT_R], .unit = "m",
                   .min = 1e-6, .max = 100,
                   .help = "radius of the sphere"},
        [OPT_C] = {.name = "C", .kind = TIPPE_CLI_DOUBLE, .value = &v[OPT_C], .unit = "kg m^2",
                   .min = 1e-24, .max = 1e6, .help = "axial moment of inertia"},
        [OPT_G] = {.name = "g", .kind = TIPPE_CLI_DOUBLE, .value = &v[OPT_G], .unit = "m/s^2",
                   .min = 0.01, .max = 1000, .def = "9.81", .help = "gravity"},
        [N_OPTS] = {.name = "z2", .kind = TIPPE_CLI_DOUBLE, .value = &a->z2_mm, .arg = "MM",
                    .unit = "mm", .min = -TIPPE_CLI_Z2_MAX_MM, .max = TIPPE_CLI_Z2_MAX_MM,
                    .help = "with a design: the moving weight's position (instead of the\n"
                            "numbers above, which the design gives)"},
        {.name = "set", .kind = TIPPE_CLI_SET, .value = &a->sets, .arg = "FIELD=VALUE",
         .help = "with a design: change a field of it (repeatable)"},
        {.name = "json", .kind = TIPPE_CLI_FLAG, .value = &a->json,
         .help = "print one JSON object (SI units) instead of the text"},
        {NULL},
    };
    tippe_cli_spec spec = {
        .verb = VERB,
        .synopsis = "--A-over-C K --eps-over-R E [--m KG --R M --C KG_M2] [--g M_S2] [--json]\n"
                    "       tippe classify DESIGN.json --z2 MM [--set FIELD=VALUE ...] [--json]",
        .about = "The group (I, II, III) and subgroup (Ia, Ib, IIa, IIb, IIc) of Theorem 5.1 of\n"
                 "Ciocci et al. 2012 for an eccentric sphere with inertia ratio K = A/C and\n"
                 "eccentricity E = eps/R, with b, theta_b (eq 5.11) and c, theta_c (eq 5.8/5.9);\n"
                 "given a design and Z2, for the design's top there (with its thresholds).",
        .after = "A point within 1e-12 of a boundary of the phase diagram is reported on it,\n"
                 "with the side chosen as docs/theory.md says. Exit status: 0 ok, 2 bad\n"
                 "usage or design.",
        .opts = opts,
        .max_args = 1,
        .args_name = "design file",
    };
    v[OPT_G] = TIPPE_DEFAULT_G_M_S2;
    int n_args = 0, rc = tippe_cli_parse(&spec, argc, argv, &a->design, &n_args);
    if (rc)
        return rc;
    if (!n_args)
        a->design = NULL;
    for (int j = 0; j < N_OPTS; j++)
        a->seen[j] = opts[j].seen;
    a->has_z2 = opts[N_OPTS].seen;
    return 0;
}

/* A/C, eps/R and the top's numbers given by hand: 0, or 2 after a usage error. */
static int check_numbers(classify_args *a, int *have_top)
{
    if (a->sets.n || a->has_z2)
        return tippe_cli_usage_error(VERB, "--z2 and --set need a design file");
    if (!a->seen[OPT_K] || !a->seen[OPT_E])
        return tippe_cli_usage_error(VERB, "--A-over-C and --eps-over-R are both required "
                                           "(or a design file and --z2)");
    if (!(a->v[OPT_E] < 1.0))
        return tippe_cli_usage_error(VERB,
                                     "--eps-over-R: %g must satisfy 0 <= eps/R < 1 (centre of "
                                     "mass inside the sphere)",
                                     a->v[OPT_E]);
    int n_top = a->seen[OPT_M] + a->seen[OPT_R] + a->seen[OPT_C];
    if (n_top != 0 && n_top != 3)
        return tippe_cli_usage_error(
            VERB, "--m, --R and --C go together (the thresholds need all three)");
    *have_top = n_top == 3;
    if (a->seen[OPT_G] && !*have_top)
        return tippe_cli_usage_error(VERB, "--g only matters with --m, --R and --C");
    return 0;
}

/* The design's top at --z2 into top and a->v: 0, or the exit status after a message. */
static int design_numbers(classify_args *a, tippe_top *top)
{
    for (int j = OPT_K; j <= OPT_C; j++)
        if (a->seen[j])
            return tippe_cli_usage_error(VERB, "a design gives A/C, eps/R, m, R and C: give "
                                               "either the design or the numbers");
    if (!a->has_z2)
        return tippe_cli_usage_error(VERB, "--z2 MM is required with a design");
    tippe_error err = {0};
    tippe_design *d = NULL;
    int rc = tippe_design_load(a->design, a->sets.item, a->sets.n, &d, &err);
    if (!rc)
        tippe_cli_design_warnings(VERB, d);
    if (!rc)
        rc = tippe_design_top(d, a->z2_mm, top, &err);
    if (!rc)
        tippe_design_protrusion_at(d, a->z2_mm, &a->protrusion);
    tippe_design_free(d);
    if (rc)
        return tippe_cli_fail(VERB, &err, rc);
    double *v = a->v;
    v[OPT_K] = top->A / top->C;
    v[OPT_E] = top->eps / top->R;
    v[OPT_M] = top->m;
    v[OPT_R] = top->R;
    v[OPT_C] = top->C;
    return 0;
}

int tippe_cli_classify(int argc, char **argv)
{
    classify_args a = {.z2_mm = 0};
    int rc = classify_parse(&a, argc, argv), have_top = 1;
    if (rc)
        return rc == TIPPE_CLI_HELP ? 0 : rc;
    const double *v = a.v;
    tippe_top top = {v[OPT_M], v[OPT_R], v[OPT_E] * v[OPT_R], v[OPT_K] * v[OPT_C], v[OPT_C],
                     v[OPT_E] > 0.0 ? -1 : 0, {0.0, 0.0}};
    rc = a.design ? design_numbers(&a, &top) : check_numbers(&a, &have_top);
    if (rc)
        return rc;
    tippe_theory_class cls;
    if (tippe_theory_classify(v[OPT_K], v[OPT_E], &cls) != TIPPE_OK)
        return tippe_cli_usage_error(VERB, "A/C = %g, eps/R = %g cannot be classified", v[OPT_K],
                                     v[OPT_E]);
    tippe_theory_thresholds th = {0};
    if (have_top) {
        tippe_error err = {0};
        rc = tippe_theory_compute_thresholds(&top, v[OPT_G], &th, &err);
        if (rc)
            return tippe_cli_fail(VERB, &err, rc);
    }
    if (a.json) {
        cJSON *o = to_json(&cls, &th, v, have_top);
        if (o && a.design) {
            cJSON_AddStringToObject(o, "file", a.design);
            cJSON_AddNumberToObject(o, "z2_mm", a.z2_mm);
            tippe_cli_json_sets(o, &a.sets);
            tippe_design_protrusion_json(o, &a.protrusion);
        }
        return tippe_cli_print_json(VERB, o);
    }
    if (a.design) {
        char sets[1024];
        printf("design    %s at Z2 = %g mm%s%s\n", a.design, a.z2_mm, a.sets.n ? " with " : "",
               tippe_cli_sets_text(&a.sets, sets, sizeof sets));
    }
    print_text(&cls, &th, v, have_top);
    if (a.design)
        tippe_cli_print_model_validity(&a.protrusion, a.z2_mm, "contact   ",
                                       "the group above is");
    return 0;
}
