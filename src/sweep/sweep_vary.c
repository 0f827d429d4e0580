/* A sweep of the zones along one field of a design: --vary FIELD=FROM:TO:N
 * (see tippe/sweep.h). */
#include "tippe/sweep.h"
#include "tippe/base.h"
#include <cjson/cJSON.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_min.h>
#include <gsl/gsl_roots.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void tippe_sweep_vary_free(tippe_sweep_vary_result *v)
{
    if (!v)
        return;
    for (int i = 0; v->results && i < v->n; i++)
        tippe_sweep_result_free(&v->results[i]);
    free(v->results);
    free(v->values);
    free(v->travel_from_mm);
    free(v->travel_to_mm);
    for (int i = 0; v->collision && i < v->n; i++)
        free(v->collision[i]);
    free(v->collision);
    memset(v, 0, sizeof *v);
}

int tippe_sweep_vary(const tippe_design *base, const char *field, double from, double to,
                     int steps, double z2_from_mm,
                     double z2_to_mm, const tippe_sweep_options *opt,
                     tippe_sweep_vary_result *out, tippe_error *err)
{
    memset(out, 0, sizeof *out);
    if (!field || !field[0] || strchr(field, '='))
        return tippe_error_set(err, TIPPE_EINPUT, "vary: bad field name '%s'",
                               field ? field : "");
    if (!isfinite(from) || !isfinite(to) || steps < 1 || steps > 100000 ||
        (steps == 1 && from != to))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "vary: %s=%g:%g:%d is not a range (need finite bounds and "
                               "1 to 100000 steps, 1 only if from = to)",
                               field, from, to, steps);
    out->values = calloc((size_t)steps, sizeof *out->values);
    out->results = calloc((size_t)steps, sizeof *out->results);
    out->travel_from_mm = calloc((size_t)steps, sizeof(double));
    out->travel_to_mm = calloc((size_t)steps, sizeof(double));
    out->collision = calloc((size_t)steps, sizeof *out->collision);
    if (!out->values || !out->results || !out->travel_from_mm || !out->travel_to_mm ||
        !out->collision)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "vary: out of memory");
    /* A step that fails to load is one whose parts collide if the same value
     * passes every check but the layout's (tippe_design_derive). */
    int st = TIPPE_OK;
    for (int i = 0; i < steps && st == TIPPE_OK; i++) {
        double v = steps == 1 ? from : from + (to - from) * i / (steps - 1);
        char set[512];
        /* %.10g: exact for any value typed with up to 10 significant digits. */
        if (snprintf(set, sizeof set, "%s=%.10g", field, v) >= (int)sizeof set) {
            st = tippe_error_set(err, TIPPE_EINPUT, "vary: field name too long");
            break;
        }
        const char *one[1] = {set};
        tippe_design *d = NULL;
        tippe_error e = {0};
        out->values[i] = v;
        out->n = i + 1;
        st = tippe_design_reload(base, one, 1, &d, &e);
        if (st == TIPPE_EINPUT) {
            tippe_design *loose = NULL;
            tippe_error le = {0};
            if (tippe_design_derive(base, one, 1, &loose, &le) == TIPPE_OK) {
                tippe_design_free(loose);
                out->collision[i] = strdup(e.msg);
                if (!out->collision[i]) {
                    st = tippe_error_set(err, TIPPE_ECOMPUTE, "vary: out of memory");
                    break;
                }
                out->n_collisions++;
                st = TIPPE_OK;
                continue;
            }
        }
        if (st == TIPPE_OK) {
            tippe_design_travel_mm(d, &out->travel_from_mm[i], &out->travel_to_mm[i]);
            st = tippe_sweep_design(d, z2_from_mm, z2_to_mm, opt, &out->results[i], &e);
            tippe_design_free(d);
        }
        if (st != TIPPE_OK)
            tippe_error_set(err, st, "with %s: %s", set, e.msg);
    }
    if (st == TIPPE_OK && out->n_collisions == out->n) {
        int last = out->n - 1;
        char msg[sizeof err->msg];
        snprintf(msg, sizeof msg, "%s", out->collision[last]);
        return tippe_error_set(err, TIPPE_EINPUT, "vary: at every value of %s the parts collide "
                               "(with %s=%.10g: %s)", field, field, out->values[last], msg);
    }
    return st;
}
