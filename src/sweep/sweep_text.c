/* The reports of --json as text, for programs that bind libtippe from another
 * language (python/tippe over ctypes, docs/python.md): one call per verb's
 * report, the same builders and the same printer (cJSON_Print) as the command,
 * so that a binding's numbers are the command's to the last digit. */
#include "tippe/sweep.h"

#include <cjson/cJSON.h>

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Adds "set" (the design's overrides) as the command's reports do, prints o
 * into *out and deletes it. */
static int print_report(cJSON *o, const tippe_design *d, char **out, tippe_error *err)
{
    *out = NULL;
    cJSON *set = o ? cJSON_AddArrayToObject(o, "set") : NULL;
    for (int i = 0; set && i < tippe_design_n_overrides(d); i++)
        cJSON_AddItemToArray(set, cJSON_CreateString(tippe_design_override(d, i)));
    *out = set ? cJSON_Print(o) : NULL;
    cJSON_Delete(o);
    return *out ? TIPPE_OK : tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
}

int tippe_sweep_text_eval(const tippe_design *d, double z2_mm, char **out, tippe_error *err)
{
    tippe_top top;
    *out = NULL;
    int rc = tippe_design_top(d, z2_mm, &top, err);
    if (rc)
        return tippe_error_blame(err, "z2_mm");
    return print_report(tippe_sweep_eval_json(d, z2_mm, &top), d, out, err);
}

int tippe_sweep_text_sweep(const tippe_design *d, double from_mm, double to_mm, char **out,
                           tippe_error *err)
{
    tippe_sweep_result r;
    tippe_sweep_bands_result b = {0};
    *out = NULL;
    int rc = tippe_sweep_design(d, from_mm, to_mm, NULL, &r, err);
    if (!rc)
        rc = tippe_sweep_bands(d, &r, &b, err);
    if (!rc)
        rc = print_report(tippe_sweep_report_json(d, &r, &b), d, out, err);
    tippe_sweep_bands_free(&b);
    tippe_sweep_result_free(&r);
    return rc;
}

/* The options of a design's hand launch as the command's defaults make them
 * (tippe check, tippe launch without friction options: the paper's viscous law). */
static int default_options(const tippe_design *d, tippe_launch_options *o, tippe_error *err)
{
    static const tippe_friction_names names = {
        .name = {[TIPPE_LAW_PARAM_LAW] = "friction", [TIPPE_LAW_PARAM_PATCH_MM] = "patch_mm",
                 [TIPPE_LAW_PARAM_TABLE] = "table", [TIPPE_LAW_PARAM_MU_C] = "mu_c",
                 [TIPPE_LAW_PARAM_SLIP_SCALE] = "slip_scale", [TIPPE_LAW_PARAM_MU] = "mu",
                 [TIPPE_LAW_PARAM_RADIUS_SPAN] = "radius_span"},
        .choose = "friction %s",
    };
    tippe_friction_given g = {0};
    tippe_friction_law laws[TIPPE_MAX_FRICTION_LAWS];
    int n_laws = 0;
    tippe_launch_options_default(o);
    int rc = tippe_friction_choose(&g, &names, laws, &n_laws, o, err);
    return rc ? rc : tippe_friction_for_design(d, laws, n_laws, NULL, &names, o, err);
}

/* Appends the trajectory's columns: {t_s: [...], theta_rad: [...], ...}. */
static int add_trajectory(cJSON *o, const tippe_dynamics_sample *s, int n)
{
    static const char *const keys[] = {"t_s", "theta_rad", "theta_dot_rad_s", "phi_dot_rad_s",
                                       "spin_rad_s", "Rn_N", "E_J", "D_J", "J_kg_m3_s"};
    cJSON *tr = cJSON_AddObjectToObject(o, "trajectory");
    for (int k = 0; tr && k < (int)(sizeof keys / sizeof keys[0]); k++) {
        double *v = malloc((size_t)(n > 0 ? n : 1) * sizeof *v);
        if (!v)
            return -1;
        for (int i = 0; i < n; i++) {
            const tippe_dynamics_sample *x = &s[i];
            const double col[] = {x->t, x->theta, x->theta_dot, x->phi_dot, x->spin,
                                  x->Rn, x->E, x->D, x->J};
            v[i] = col[k];
        }
        cJSON *a = cJSON_CreateDoubleArray(v, n);
        free(v);
        if (!a || !cJSON_AddItemToObject(tr, keys[k], a))
            return -1;
    }
    return tr ? 0 : -1;
}

int tippe_sweep_text_check(const tippe_design *d, double z2_mm, double spin_rad_s, char **out,
                           tippe_error *err)
{
    *out = NULL;
    tippe_launch_options o;
    tippe_sweep_check c;
    int rc = default_options(d, &o, err);
    if (!rc)
        rc = tippe_sweep_check_run(d, z2_mm, &o, spin_rad_s, &c, err);
    if (rc)
        return rc;
    /* the trajectory as tippe check --csv integrates it (src/cli/check.c) */
    tippe_dynamics_samples buf = {0, 0, NULL};
    tippe_dynamics_result res;
    tippe_dynamics_initial ic = c.ic;
    rc = tippe_launch_trajectory(&c.top, &o, &ic, 0.0, &buf, &res, err);
    const char *const *sets = NULL;
    int n_sets = tippe_design_n_overrides(d);
    const char **s = n_sets ? calloc((size_t)n_sets, sizeof *s) : NULL;
    for (int i = 0; s && i < n_sets; i++)
        s[i] = tippe_design_override(d, i);
    sets = s;
    cJSON *j = rc ? NULL : tippe_sweep_check_json(&c, &o, sets, s ? n_sets : 0);
    free(s);
    if (!rc && (!j || add_trajectory(j, buf.s, buf.n)))
        rc = tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    tippe_dynamics_samples_free(&buf);
    if (!rc && !(*out = cJSON_Print(j)))
        rc = tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    cJSON_Delete(j);
    return rc;
}

int tippe_sweep_text_launch(const tippe_design *d, double z2_mm, long n, uint64_t seed,
                            char **out, tippe_error *err)
{
    *out = NULL;
    if (n < 1 || n > 10000000)
        return tippe_error_set_field(err, TIPPE_EINPUT, "n", "n: %ld launches: 1 .. 10000000",
                                     n);
    tippe_launch_options o;
    tippe_top top;
    int rc = default_options(d, &o, err);
    if (!rc && (rc = tippe_design_top(d, z2_mm, &top, err)))
        tippe_error_blame(err, "z2_mm");
    if (rc)
        return rc;
    tippe_launch_polar_caps(d, z2_mm, &top, o.cap_half_angle_rad);
    tippe_launch_record *rec = calloc((size_t)n, sizeof *rec);
    if (!rec)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory for %ld launches", n);
    tippe_launch_plan plan = {1, n, &top, NULL, NULL};
    tippe_launch_tally t;
    rc = tippe_launch_run(&plan, &o, seed, 0, n, rec, NULL, err);
    if (!rc)
        rc = tippe_launch_tally_records(rec, n, &t, err);
    cJSON *j = rc ? NULL : cJSON_CreateObject();
    cJSON *counts = j ? cJSON_AddObjectToObject(j, "counts") : NULL;
    for (int v = 0; counts && v < TIPPE_LAUNCH_N_VERDICTS; v++)
        cJSON_AddNumberToObject(counts, tippe_verdict_name((tippe_verdict)v), (double)t.counts[v]);
    /* one entry per launch, in order: the columns of tippe launch --csv that a
     * notebook plots */
    static const char *const keys[] = {"spin_rad_s", "theta0_rad", "t_s", "theta_final_rad",
                                       "spin_final_rad_s", "t_flip_s"};
    cJSON *l = j ? cJSON_AddObjectToObject(j, "launches") : NULL;
    cJSON *verdicts = l ? cJSON_AddArrayToObject(l, "verdict") : NULL;
    for (long i = 0; verdicts && i < n; i++)
        cJSON_AddItemToArray(verdicts, cJSON_CreateString(tippe_verdict_name(rec[i].verdict)));
    double *v = l ? malloc((size_t)n * sizeof *v) : NULL;
    for (int k = 0; v && k < (int)(sizeof keys / sizeof keys[0]); k++) {
        for (long i = 0; i < n; i++) {
            const tippe_launch_record *r = &rec[i];
            const double col[] = {r->ic.spin, r->ic.theta, r->t_s, r->theta_final_rad,
                                  r->spin_final_rad_s, r->t_flip_s};
            v[i] = col[k];
        }
        cJSON_AddItemToObject(l, keys[k], cJSON_CreateDoubleArray(v, (int)n));
    }
    free(v);
    free(rec);
    if (!rc && !(*out = j ? cJSON_Print(j) : NULL))
        rc = tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    cJSON_Delete(j);
    return rc;
}

void tippe_sweep_text_free(char *text)
{
    free(text);
}
