/* Sensitivity of patch-law launches to the patch radius (issue 27): the same launches
 * at 0.5x, 1x and 2x the radius used, and whether their outcomes agree
 * (tippe/launch.h, docs/dynamics.md "Radius sensitivity"). */
#include "tippe/launch.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The span F of the runs a/F, a, a F: the options' (the design's tolerance
 * contact.patch_radius, or --radius-span), else 2, the span the issue asks for (surface
 * finish, the table, wear move the radius by about that much; docs/contact-patch.md). */
double tippe_launch_radius_span(const tippe_launch_options *o)
{
    return o->patch_radius_span > 1.0 ? o->patch_radius_span : TIPPE_LAUNCH_RADIUS_SPAN;
}

double tippe_launch_radius_factor(const tippe_launch_options *o, int i)
{
    const double span = tippe_launch_radius_span(o);
    return i == 0 ? 1.0 / span : i == 1 ? 1.0 : i == 2 ? span : NAN;
}

double tippe_launch_patch_radius(const tippe_top *top, const tippe_launch_options *o)
{
    tippe_dynamics_model m;
    tippe_launch_friction_model(o, &m);
    m.top = *top;
    return tippe_dynamics_patch_radius(&m);
}

int tippe_launch_radius_options(const tippe_top *top, const tippe_launch_options *o,
                                double factor, tippe_launch_options *out)
{
    *out = *o;
    out->patch_radius_m = factor * tippe_launch_patch_radius(top, o);
    /* the dynamics' own bound (dynamics.c: a patch wider than R/2 is no patch) */
    return !(out->patch_radius_m <= 0.5 * top->R);
}

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *v, long n)
{
    if (n == 0)
        return NAN;
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* The same outcome: the passage over pi/2 and the fall back, a lost contact, and the
 * verdict where both were decided (by a proof, or by losing contact). An observed
 * verdict is a snapshot at t_end of a top that rocks on, not converged at the default
 * accuracy (docs/dynamics.md, "Radius sensitivity"): a radius 1 % off changes it as
 * often as the integrator's tolerance does, so two observed verdicts are not compared. */
static int same_outcome(const tippe_launch_record *a, const tippe_launch_record *b)
{
    if (a->status != TIPPE_OK || b->status != TIPPE_OK)
        return 0;
    const int observed = a->how == TIPPE_DECIDED_OBSERVED || b->how == TIPPE_DECIDED_OBSERVED;
    const int lost_a = a->verdict == TIPPE_VERDICT_LOST_CONTACT;
    const int lost_b = b->verdict == TIPPE_VERDICT_LOST_CONTACT;
    return (observed ? lost_a == lost_b : a->verdict == b->verdict) &&
           !isfinite(a->t_flip_s) == !isfinite(b->t_flip_s) &&
           !isfinite(a->t_fall_s) == !isfinite(b->t_fall_s);
}

int tippe_launch_radius_summary(const tippe_launch_record *const rec[TIPPE_LAUNCH_RADIUS_RUNS],
                                long n, const double radius_m[TIPPE_LAUNCH_RADIUS_RUNS],
                                tippe_launch_radius_sensitivity *out, tippe_error *err)
{
    memset(out, 0, sizeof *out);
    double *buf = malloc((size_t)(n > 0 ? n : 1) * sizeof *buf);
    if (!buf)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory for %ld launches", n);
    int all_ran = 1;
    for (int i = 0; i < TIPPE_LAUNCH_RADIUS_RUNS; i++) {
        tippe_launch_radius_run *r = &out->run[i];
        r->factor = radius_m[1] > 0 ? radius_m[i] / radius_m[1] : NAN;
        r->radius_m = radius_m[i];
        r->median_t_flip_s = r->median_t_fall_s = NAN;
        r->ran = rec[i] != NULL;
        if (!r->ran) {
            all_ran = 0;
            continue;
        }
        r->n = n;
        if (n > 0)
            r->first = rec[i][0];
        long k = 0;
        for (long j = 0; j < n; j++) {
            const tippe_launch_record *q = &rec[i][j];
            if (q->status == TIPPE_OK && (int)q->verdict >= 0 &&
                (int)q->verdict < TIPPE_LAUNCH_N_VERDICTS)
                r->counts[q->verdict]++;
            if (isfinite(q->t_flip_s))
                buf[k++] = q->t_flip_s;
        }
        r->passed = k;
        r->median_t_flip_s = median(buf, k);
        k = 0;
        for (long j = 0; j < n; j++)
            if (isfinite(rec[i][j].t_fall_s))
                buf[k++] = rec[i][j].t_fall_s;
        r->fell = k;
        r->median_t_fall_s = median(buf, k);
    }
    free(buf);
    for (long j = 0; j < n; j++) {
        int same = 1;
        for (int i = 0; i < TIPPE_LAUNCH_RADIUS_RUNS; i++)
            if (rec[i] && i != 1 && rec[1] && !same_outcome(&rec[i][j], &rec[1][j]))
                same = 0;
        out->changed += !same;
    }
    out->robust = all_ran && out->changed == 0;
    return TIPPE_OK;
}

int tippe_launch_radius_sensitivity_initial(const tippe_top *top, const tippe_launch_options *o,
                                            const tippe_dynamics_initial *ic,
                                            const tippe_launch_record *plain,
                                            tippe_launch_radius_sensitivity *out,
                                            tippe_error *err)
{
    const tippe_friction_law_type *law = tippe_friction_law_type_of(o->law);
    if (!law || !law->patch)
        return tippe_error_set(err, TIPPE_EINPUT,
                               "the radius sensitivity needs the patch law, not %s",
                               tippe_friction_law_name(o->law));
    tippe_launch_record rec[TIPPE_LAUNCH_RADIUS_RUNS];
    const tippe_launch_record *ptr[TIPPE_LAUNCH_RADIUS_RUNS];
    double radius_m[TIPPE_LAUNCH_RADIUS_RUNS];
    for (int i = 0; i < TIPPE_LAUNCH_RADIUS_RUNS; i++) {
        tippe_launch_options oi;
        ptr[i] = NULL;
        const int beyond = tippe_launch_radius_options(top, o, tippe_launch_radius_factor(o, i),
                                                       &oi);
        radius_m[i] = oi.patch_radius_m;
        if (beyond)
            continue;
        memset(&rec[i], 0, sizeof rec[i]);
        if (i == 1 && plain) {
            rec[i] = *plain;
        } else {
            /* the middle run under o itself, so that it is the plain run bit for bit */
            int rc = tippe_launch_run_initial(top, i == 1 ? o : &oi, ic, &rec[i], err);
            if (rc)
                return rc;
        }
        ptr[i] = &rec[i];
    }
    return tippe_launch_radius_summary(ptr, 1, radius_m, out, err);
}

static void number_or_null(cJSON *o, const char *key, double v)
{
    if (isfinite(v))
        cJSON_AddNumberToObject(o, key, v);
    else
        cJSON_AddNullToObject(o, key);
}

cJSON *tippe_launch_radius_json(const tippe_launch_radius_sensitivity *s, int one_launch)
{
    cJSON *o = cJSON_CreateObject(), *runs = cJSON_CreateArray();
    if (!o || !runs) {
        cJSON_Delete(o);
        cJSON_Delete(runs);
        return NULL;
    }
    /* robust: true, false, or null when not known (a radius was not run) */
    int all_ran = 1;
    for (int i = 0; i < TIPPE_LAUNCH_RADIUS_RUNS; i++)
        all_ran = all_ran && s->run[i].ran;
    if (all_ran || s->changed > 0)
        cJSON_AddBoolToObject(o, "robust", s->robust);
    else
        cJSON_AddNullToObject(o, "robust");
    cJSON_AddNumberToObject(o, "changed", (double)s->changed);
    cJSON_AddItemToObject(o, "runs", runs);
    for (int i = 0; i < TIPPE_LAUNCH_RADIUS_RUNS; i++) {
        const tippe_launch_radius_run *r = &s->run[i];
        cJSON *x = cJSON_CreateObject();
        if (!x)
            break;
        cJSON_AddItemToArray(runs, x);
        cJSON_AddNumberToObject(x, "factor", r->factor);
        cJSON_AddNumberToObject(x, "patch_mm", r->radius_m * 1e3);
        cJSON_AddBoolToObject(x, "ran", r->ran);
        if (!r->ran)
            continue;
        if (one_launch) {
            const tippe_launch_record *q = &r->first;
            cJSON_AddStringToObject(x, "verdict", tippe_verdict_name(q->verdict));
            number_or_null(x, "t_s", q->t_s);
            number_or_null(x, "theta_final_rad", q->theta_final_rad);
            number_or_null(x, "t_flip_s", q->t_flip_s);
            number_or_null(x, "t_fall_s", q->t_fall_s);
            number_or_null(x, "inverted_time_s", q->inverted_time_s);
            number_or_null(x, "energy_rel_error", q->energy_rel_error);
        } else {
            cJSON *c = cJSON_AddObjectToObject(x, "counts");
            for (int v = 0; c && v < TIPPE_LAUNCH_N_VERDICTS; v++)
                cJSON_AddNumberToObject(c, tippe_verdict_name((tippe_verdict)v),
                                        (double)r->counts[v]);
            cJSON_AddNumberToObject(x, "passed_pi_2", (double)r->passed);
            cJSON_AddNumberToObject(x, "fell_back", (double)r->fell);
            number_or_null(x, "median_t_flip_s", r->median_t_flip_s);
            number_or_null(x, "median_t_fall_s", r->median_t_fall_s);
        }
    }
    return o;
}
