/* tippe classify: the group of Theorem 5.1 for (A/C, eps/R), and the spin
 * thresholds when the top's m, R and C are given. */
#include "cli.h"

#include "tippe/theory.h"

#include <cjson/cJSON.h>

#include <stdio.h>
#include <string.h>

#define RAD_TO_DEG (180.0 / 3.14159265358979323846)
#define RAD_S_TO_REV_S (1.0 / (2.0 * 3.14159265358979323846))

static void classify_usage(FILE *out)
{
    fprintf(out,
            "usage: tippe classify --A-over-C K --eps-over-R E [--m KG --R M --C KG_M2]\n"
            "                      [--g M_S2] [--json]\n"
            "\n"
            "The group (I, II, III) and subgroup (Ia, Ib, IIa, IIb, IIc) of Theorem 5.1 of\n"
            "Ciocci et al. 2012 for an eccentric sphere with inertia ratio K = A/C and\n"
            "eccentricity E = eps/R, with b, theta_b (eq 5.11) and c, theta_c (eq 5.8/5.9).\n"
            "\n"
            "  --A-over-C K   A/C, A transverse through the centre of mass, C axial (> 0)\n"
            "  --eps-over-R E eps/R, centre of mass below the sphere's centre (0 <= E < 1)\n"
            "  --m KG         mass, kg         } all three give the spin thresholds n-, n+,\n"
            "  --R M          sphere radius, m } n* and n_b in rad/s and rev/s\n"
            "  --C KG_M2      axial moment, kg m^2 }\n"
            "  --g M_S2       gravity, m/s^2 (default %.5f)\n"
            "  --json         print one JSON object (SI units) instead of the text\n"
            "  --help         this text\n"
            "\n"
            "A point within 1e-12 of a boundary of the phase diagram is reported on it, with\n"
            "the side chosen as docs/theory.md says. Exit status: 0 ok, 2 bad usage.\n",
            TIPPE_DEFAULT_G_M_S2);
}

static const char *const VERB = "classify";

typedef struct {
    const char *name; /* "--A-over-C" */
    const char *text;
    double value;
} num_opt;

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

int tippe_cli_classify(int argc, char **argv)
{
    num_opt opt[N_OPTS] = {{"--A-over-C", NULL, 0}, {"--eps-over-R", NULL, 0}, {"--m", NULL, 0},
                           {"--R", NULL, 0},        {"--C", NULL, 0},          {"--g", NULL, 0}};
    int json = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (tippe_cli_is_help(a)) {
            classify_usage(stdout);
            return 0;
        }
        if (!strcmp(a, "--json")) {
            json = 1;
            continue;
        }
        int found = 0;
        for (int j = 0; j < N_OPTS && !found; j++)
            if ((found = tippe_cli_option(VERB, argc, argv, &i, opt[j].name, 1, &opt[j].text)) &&
                !opt[j].text)
                return 2;
        if (!found)
            return tippe_cli_usage_error(VERB, "unknown argument '%s'", a);
    }
    for (int j = 0; j < N_OPTS; j++)
        if (opt[j].text && tippe_cli_number(VERB, opt[j].name, opt[j].text, NULL, &opt[j].value))
            return 2;
    if (!opt[OPT_K].text || !opt[OPT_E].text)
        return tippe_cli_usage_error(VERB, "--A-over-C and --eps-over-R are both required");
    if (!(opt[OPT_K].value > 0.0))
        return tippe_cli_usage_error(VERB, "--A-over-C: %g must be > 0", opt[OPT_K].value);
    if (!(opt[OPT_E].value >= 0.0 && opt[OPT_E].value < 1.0))
        return tippe_cli_usage_error(VERB,
                                     "--eps-over-R: %g must satisfy 0 <= eps/R < 1 (centre of mass "
                                     "inside the sphere)",
                                     opt[OPT_E].value);
    int n_top = !!opt[OPT_M].text + !!opt[OPT_R].text + !!opt[OPT_C].text;
    if (n_top != 0 && n_top != 3)
        return tippe_cli_usage_error(
            VERB, "--m, --R and --C go together (the thresholds need all three)");
    int have_top = n_top == 3;
    if (opt[OPT_G].text && !have_top)
        return tippe_cli_usage_error(VERB, "--g only matters with --m, --R and --C");
    if (!opt[OPT_G].text)
        opt[OPT_G].value = TIPPE_DEFAULT_G_M_S2;
    for (int j = OPT_M; j < N_OPTS; j++)
        if ((opt[j].text || j == OPT_G) && have_top && !(opt[j].value > 0.0))
            return tippe_cli_usage_error(VERB, "%s: %g must be > 0", opt[j].name, opt[j].value);

    double v[N_OPTS];
    for (int j = 0; j < N_OPTS; j++)
        v[j] = opt[j].value;
    tippe_theory_class cls;
    if (tippe_theory_classify(v[OPT_K], v[OPT_E], &cls) != TIPPE_OK)
        return tippe_cli_usage_error(VERB, "A/C = %g, eps/R = %g cannot be classified", v[OPT_K],
                                     v[OPT_E]);
    tippe_theory_thresholds th = {0};
    if (have_top) {
        tippe_top top = {v[OPT_M], v[OPT_R], v[OPT_E] * v[OPT_R], v[OPT_K] * v[OPT_C], v[OPT_C],
                         v[OPT_E] > 0.0 ? -1 : 0};
        tippe_error err = {0};
        int rc = tippe_theory_compute_thresholds(&top, v[OPT_G], &th, &err);
        if (rc)
            return tippe_cli_fail(VERB, &err, rc);
    }
    if (json)
        return tippe_cli_print_json(VERB, to_json(&cls, &th, v, have_top));
    print_text(&cls, &th, v, have_top);
    return 0;
}
