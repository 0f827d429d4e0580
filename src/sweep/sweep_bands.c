/* Tolerance bands on the zone boundaries of a sweep (see tippe/sweep.h). */
#include "tippe/sweep.h"
#include "tippe/design.h"

#include <cjson/cJSON.h>
#include <gsl/gsl_deriv.h>
#include <gsl/gsl_math.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The step of the derivative in Z2 along the path, mm: the boundary functions
 * vary on the scale of the travel (tens of mm), so 1e-2 mm leaves a 5-point
 * truncation error ~ (h/L)^4 ~ 1e-14 relative, above round-off/h ~ 1e-14. */
#define DZ_STEP_MM 1e-2
/* The step in a field, as a fraction of its tolerance: small enough that the
 * 5-point rule is exact to ~ (0.25 t / L)^4, large enough that the reloaded
 * design's mass properties (exact to ~1e-15) leave round-off far below. */
#define DP_STEP_OF_TOL 0.25
/* Designs kept per field: gsl_deriv_central asks for 4 points per step and at
 * most two steps. */
#define CACHE 8
#define MAX_SETS 64

/* The design with one field moved, loaded once per distinct delta. */
typedef struct {
    const tippe_design *base;
    const tippe_tolerance *tol;
    double delta[CACHE];
    tippe_design *d[CACHE];
    int n, next;
    int failed;
    tippe_error err;
} moved_cache;

static const tippe_design *moved(moved_cache *c, double delta)
{
    for (int i = 0; i < c->n; i++)
        if (c->delta[i] == delta)
            return c->d[i];
    char sets[MAX_SETS][TIPPE_TOLERANCE_FIELD_LEN + 40];
    const char *ptr[MAX_SETS];
    int n = tippe_tolerance_overrides(c->base, c->tol, delta, sets, MAX_SETS);
    tippe_design *d = NULL;
    tippe_error e = {0};
    for (int i = 0; i < n; i++)
        ptr[i] = sets[i];
    if (n < 0 || tippe_design_derive(c->base, ptr, n, &d, &e) != TIPPE_OK) {
        if (!c->failed)
            tippe_error_set(&c->err, n < 0 ? TIPPE_ECOMPUTE : e.code,
                            "tolerance on %s: the design does not load with it moved by %g %s: %s",
                            c->tol->field, delta, c->tol->unit,
                            n < 0 ? "too many parts of one material" : e.msg);
        c->failed = 1;
        return NULL;
    }
    int slot = c->n < CACHE ? c->n++ : c->next++ % CACHE;
    tippe_design_free(c->d[slot]);
    c->d[slot] = d;
    c->delta[slot] = delta;
    return d;
}

static void cache_clear(moved_cache *c)
{
    for (int i = 0; i < c->n; i++)
        tippe_design_free(c->d[i]);
    c->n = c->next = 0;
}

/* One boundary function at one Z2, on a design (moved) or along the path. */
typedef struct {
    moved_cache *cache;
    const tippe_sweep_path *path; /* when cache is NULL */
    double z2_mm;
    tippe_sweep_boundary which;
    int failed;
    tippe_error err;
} f_params;

static double f_of_delta(double delta, void *vp)
{
    f_params *p = vp;
    const tippe_design *d = moved(p->cache, delta);
    if (!d)
        return GSL_NAN;
    tippe_sweep_path path = tippe_sweep_design_path(d);
    double g[TIPPE_SWEEP_N_BOUNDARIES];
    if (tippe_sweep_boundary_values(&path, p->z2_mm, g, &p->err) != TIPPE_OK) {
        p->failed = 1;
        return GSL_NAN;
    }
    return g[p->which];
}

static double f_of_z(double z2_mm, void *vp)
{
    f_params *p = vp;
    double g[TIPPE_SWEEP_N_BOUNDARIES];
    if (tippe_sweep_boundary_values(p->path, z2_mm, g, &p->err) != TIPPE_OK) {
        p->failed = 1;
        return GSL_NAN;
    }
    return g[p->which];
}

void tippe_sweep_bands_free(tippe_sweep_bands_result *b)
{
    if (!b)
        return;
    for (int i = 0; b->bands && i < b->n; i++) {
        free(b->bands[i].dz_dp);
        free(b->bands[i].dz_dp_err);
    }
    free(b->bands);
    memset(b, 0, sizeof *b);
}

/* The crossings that end zones, with df/dZ2 along the nominal path. */
static int find_crossings(const tippe_design *d, const tippe_sweep_result *r, int nt,
                          tippe_sweep_bands_result *out, tippe_error *err)
{
    out->bands = calloc((size_t)r->n_events + 1, sizeof *out->bands);
    if (!out->bands)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "bands: out of memory");
    tippe_sweep_path path = tippe_sweep_design_path(d);
    for (int e = 0; e < r->n_events; e++) {
        const tippe_sweep_event *ev = &r->events[e];
        if (ev->touch || !tippe_sweep_event_ends_zone(r, ev))
            continue;
        tippe_sweep_band *b = &out->bands[out->n++];
        b->event = e;
        b->boundary = ev->boundary;
        b->z2_mm = ev->z2_mm;
        b->dz_dp = calloc((size_t)nt + 1, sizeof(double));
        b->dz_dp_err = calloc((size_t)nt + 1, sizeof(double));
        if (!b->dz_dp || !b->dz_dp_err)
            return tippe_error_set(err, TIPPE_ECOMPUTE, "bands: out of memory");
        f_params fp = {.path = &path, .z2_mm = ev->z2_mm, .which = ev->boundary};
        gsl_function F = {f_of_z, &fp};
        double abserr = 0;
        int st = gsl_deriv_central(&F, ev->z2_mm, DZ_STEP_MM, &b->df_dz_per_mm, &abserr);
        if (fp.failed)
            return tippe_error_set(err, fp.err.code, "bands: %s", fp.err.msg);
        if (st || !isfinite(b->df_dz_per_mm))
            return tippe_error_set(err, TIPPE_ECOMPUTE,
                                   "bands: slope of %s at Z2 = %g mm not found",
                                   tippe_sweep_boundary_name(ev->boundary), ev->z2_mm);
    }
    return TIPPE_OK;
}

/* How far a field may move either way: the farther end of its interval (an
 * infill at 0.95 +/- 25 % reaches 0.2375 down and 0.05 up: a boundary moves by
 * up to its slope times 0.2375 whichever way it goes). */
static double tol_reach(const tippe_tolerance *t)
{
    return fmax(t->minus, t->plus);
}

/* d(Z2*)/dp of every crossing for tolerance i (eq. of tippe/sweep.h). */
static int sensitivities(const tippe_design *d, int i, tippe_sweep_bands_result *out,
                         tippe_error *err)
{
    const tippe_tolerance *t = tippe_design_tolerance(d, i);
    moved_cache cache = {.base = d, .tol = t};
    int st = TIPPE_OK;
    for (int k = 0; k < out->n && st == TIPPE_OK; k++) {
        tippe_sweep_band *b = &out->bands[k];
        f_params fp = {.cache = &cache, .z2_mm = b->z2_mm, .which = b->boundary};
        gsl_function F = {f_of_delta, &fp};
        double df_dp = 0, abserr = 0;
        /* every point the rule asks for inside the field's interval (its range):
         * central when both sides have room for the step, else one-sided toward
         * the room (GSL's adaptive step only shrinks) */
        const double h = DP_STEP_OF_TOL * t->plus_minus;
        int gs = h <= t->minus && h <= t->plus
                     ? gsl_deriv_central(&F, 0.0, h, &df_dp, &abserr)
                 : t->plus >= t->minus
                     ? gsl_deriv_forward(&F, 0.0, fmin(h, t->plus), &df_dp, &abserr)
                     : gsl_deriv_backward(&F, 0.0, fmin(h, t->minus), &df_dp, &abserr);
        if (cache.failed)
            st = tippe_error_set(err, cache.err.code, "%s", cache.err.msg);
        else if (fp.failed)
            st = tippe_error_set(err, fp.err.code, "tolerance on %s: %s", t->field, fp.err.msg);
        else if (gs || !isfinite(df_dp))
            st = tippe_error_set(err, TIPPE_ECOMPUTE,
                                 "tolerance on %s: derivative of %s not found", t->field,
                                 tippe_sweep_boundary_name(b->boundary));
        if (st)
            break;
        /* Implicit function theorem: f(Z2*(p), p) = 0. */
        b->dz_dp[i] = b->df_dz_per_mm != 0 ? -df_dp / b->df_dz_per_mm : INFINITY;
        b->dz_dp_err[i] = b->df_dz_per_mm != 0 ? abserr / fabs(b->df_dz_per_mm) : INFINITY;
    }
    cache_clear(&cache);
    return st;
}

int tippe_sweep_bands(const tippe_design *d, const tippe_sweep_result *r,
                      tippe_sweep_bands_result *out, tippe_error *err)
{
    memset(out, 0, sizeof *out);
    int nt = tippe_design_n_tolerances(d);
    out->n_tolerances = nt;
    int st = find_crossings(d, r, nt, out, err);
    for (int i = 0; i < nt && st == TIPPE_OK && out->n > 0; i++)
        st = tippe_cancel_requested() ? tippe_cancel_error(err) : sensitivities(d, i, out, err);
    for (int k = 0; k < out->n && st == TIPPE_OK; k++) {
        tippe_sweep_band *b = &out->bands[k];
        double sum2 = 0, lin = 0;
        for (int i = 0; i < nt; i++) {
            double s = fabs(b->dz_dp[i]) * tol_reach(tippe_design_tolerance(d, i));
            sum2 += s * s;
            lin += s;
        }
        b->band_mm = sqrt(sum2);
        b->worst_mm = lin;
    }
    return st;
}

double tippe_sweep_band_at(const tippe_sweep_bands_result *b, double z2_mm)
{
    double w = 0;
    for (int k = 0; b && k < b->n; k++)
        if (fabs(b->bands[k].z2_mm - z2_mm) <= 2.0 * TIPPE_SWEEP_XTOL_MM)
            w = GSL_MAX(w, b->bands[k].band_mm);
    return w;
}

static double robust(double from_mm, double to_mm, const tippe_sweep_bands_result *b)
{
    double w = to_mm - from_mm - tippe_sweep_band_at(b, from_mm) - tippe_sweep_band_at(b, to_mm);
    return w > 0 ? w : 0; /* bands that overlap leave nothing certain */
}

double tippe_sweep_zone_robust_mm(const tippe_sweep_result *r, const tippe_sweep_bands_result *b,
                                  int i)
{
    if (i < 0 || i >= r->n_zones)
        return 0;
    return robust(r->zones[i].z2_from_mm, r->zones[i].z2_to_mm, b);
}

void tippe_sweep_robust_widths(const tippe_sweep_result *r, const tippe_sweep_bands_result *b,
                               double robust_mm[3], double *narrowest_mm)
{
    int has[3] = {0, 0, 0};
    robust_mm[0] = robust_mm[1] = robust_mm[2] = 0;
    /* Runs as tippe_sweep_summarise makes them (tippe_sweep_family_run). */
    for (int i = 0, f; i < r->n_zones;) {
        double from, to;
        i = tippe_sweep_family_run(r, i, &f, &from, &to);
        if (f >= 0) {
            has[f] = 1;
            robust_mm[f] = GSL_MAX(robust_mm[f], robust(from, to, b));
        }
    }
    /* 0 unless 3-in-1, as tippe_sweep_summary's narrowest_zone_mm. */
    *narrowest_mm = has[0] && has[1] && has[2]
                        ? GSL_MIN(robust_mm[0], GSL_MIN(robust_mm[1], robust_mm[2]))
                        : 0.0;
}

/* The tolerance that moves crossing k most, and by how much (mm). */
static int main_term(const tippe_design *d, const tippe_sweep_band *b, int nt, double *mm)
{
    int best = -1;
    *mm = 0;
    for (int i = 0; i < nt; i++) {
        double s = fabs(b->dz_dp[i]) * tol_reach(tippe_design_tolerance(d, i));
        if (best < 0 || s > *mm) {
            best = i;
            *mm = s;
        }
    }
    return best;
}

void tippe_sweep_print_bands(FILE *out, const tippe_design *d, const tippe_sweep_result *r,
                             const tippe_sweep_bands_result *b)
{
    int nt = tippe_design_n_tolerances(d);
    fprintf(out, "\ntolerances (%d; independent, combined in quadrature):\n", nt);
    for (int i = 0; i < nt; i++) {
        const tippe_tolerance *t = tippe_design_tolerance(d, i);
        char pct[32] = "";
        if (t->percent > 0)
            snprintf(pct, sizeof pct, " (%g%%)", t->percent);
        char clip[80] = "";
        if (t->minus < t->plus_minus || t->plus < t->plus_minus) /* at its range's end */
            snprintf(clip, sizeof clip, " (within its range: %.4g .. %.4g)", t->value - t->minus,
                     t->value + t->plus);
        fprintf(out, "  %-34s %9.4g +/- %-8.3g %-7s%s  %s%s\n", t->field, t->value,
                t->plus_minus, t->unit, pct, t->rule, clip);
    }
    /* the zones do not depend on friction: listed, not combined (tippe/design.h) */
    fprintf(out, "  %-34s within a factor %g (patch friction's radius: check, launch and map rerun "
                 "at a/%g and %g a; moves no zone: not in the count or the bands)\n",
            TIPPE_TOL_PATCH_RADIUS_KEY, tippe_design_patch_radius_span(d),
            tippe_design_patch_radius_span(d), tippe_design_patch_radius_span(d));
    fprintf(out, "\n%-18s %10s %12s %12s  %s\n", "boundary", "Z2 (mm)", "band +/- mm",
            "worst +/- mm", "moved most by");
    for (int k = 0; k < b->n; k++) {
        const tippe_sweep_band *bd = &b->bands[k];
        double mm = 0;
        int i = main_term(d, bd, nt, &mm);
        if (!isfinite(bd->band_mm)) { /* the path runs along the boundary there */
            fprintf(out, "%-18s %10.3f %12s %12s  (the path is tangent to the boundary)\n",
                    tippe_sweep_boundary_name(bd->boundary), bd->z2_mm, "unbounded",
                    "unbounded");
            continue;
        }
        fprintf(out, "%-18s %10.3f %12.3f %12.3f  %s (+/-%.3f mm)\n",
                tippe_sweep_boundary_name(bd->boundary), bd->z2_mm, bd->band_mm, bd->worst_mm,
                i >= 0 ? tippe_design_tolerance(d, i)->field : "-", mm);
    }
    fprintf(out, "\n%-5s %10s %10s %11s %12s\n", "zone", "from (mm)", "to (mm)", "width (mm)",
            "robust (mm)");
    for (int i = 0; i < r->n_zones; i++) {
        const tippe_sweep_zone *z = &r->zones[i];
        fprintf(out, "%-5s %10.3f %10.3f %11.3f %12.3f%s\n", tippe_group_name(z->group),
                z->z2_from_mm, z->z2_to_mm, z->z2_to_mm - z->z2_from_mm,
                tippe_sweep_zone_robust_mm(r, b, i),
                z->within_travel ? "" : "  beyond physical travel");
    }
    double rob[3], narrow;
    tippe_sweep_robust_widths(r, b, rob, &narrow);
    fprintf(out, "robust   widest run of each group less its bands: I %.3f mm, II %.3f mm, "
                 "III %.3f mm; narrowest %.3f mm (0 unless 3-in-1)\n",
            rob[0], rob[1], rob[2], narrow);
}

/* cJSON with failure recorded, not returned at every call. */
static cJSON *put(cJSON *parent, const char *key, cJSON *item, int *ok)
{
    if (!item || !(key ? cJSON_AddItemToObject(parent, key, item)
                       : cJSON_AddItemToArray(parent, item))) {
        cJSON_Delete(item);
        *ok = 0;
        return NULL;
    }
    return item;
}

/* A number, or null where it is not finite (a band with df/dZ2 = 0). */
static cJSON *num(double x) { return isfinite(x) ? cJSON_CreateNumber(x) : cJSON_CreateNull(); }

/* band_from_mm, band_to_mm, robust_width_mm on every object of arr that has
 * z2_from_mm and z2_to_mm. */
static void add_zone_bands(cJSON *arr, const tippe_sweep_bands_result *b, int *ok)
{
    cJSON *z;
    cJSON_ArrayForEach(z, arr)
    {
        const cJSON *f = cJSON_GetObjectItemCaseSensitive(z, "z2_from_mm");
        const cJSON *t = cJSON_GetObjectItemCaseSensitive(z, "z2_to_mm");
        if (!cJSON_IsNumber(f) || !cJSON_IsNumber(t))
            continue;
        put(z, "band_from_mm", num(tippe_sweep_band_at(b, f->valuedouble)), ok);
        put(z, "band_to_mm", num(tippe_sweep_band_at(b, t->valuedouble)), ok);
        put(z, "robust_width_mm", num(robust(f->valuedouble, t->valuedouble, b)), ok);
    }
}

int tippe_sweep_json_add_bands(cJSON *o, const tippe_design *d, const tippe_sweep_result *r,
                               const tippe_sweep_bands_result *b)
{
    int ok = 1, nt = tippe_design_n_tolerances(d);
    cJSON *tols = put(o, "tolerances", cJSON_CreateArray(), &ok);
    for (int i = 0; tols && i < nt; i++) {
        const tippe_tolerance *t = tippe_design_tolerance(d, i);
        cJSON *to = put(tols, NULL, cJSON_CreateObject(), &ok);
        if (!to)
            break;
        put(to, "field", cJSON_CreateString(t->field), &ok);
        put(to, "value", num(t->value), &ok);
        put(to, "plus_minus", num(t->plus_minus), &ok);
        put(to, "from", num(t->value - t->minus), &ok); /* within the field's range */
        put(to, "to", num(t->value + t->plus), &ok);
        put(to, "unit", cJSON_CreateString(t->unit), &ok);
        put(to, "rule", cJSON_CreateString(t->rule), &ok);
    }
    /* a factor on the patch radius, for launches only: moves no zone (tippe/design.h) */
    put(o, "patch_radius_factor", num(tippe_design_patch_radius_span(d)), &ok);
    cJSON *bands = put(o, "bands", cJSON_CreateArray(), &ok);
    for (int k = 0; bands && k < b->n; k++) {
        const tippe_sweep_band *bd = &b->bands[k];
        cJSON *bo = put(bands, NULL, cJSON_CreateObject(), &ok);
        if (!bo)
            break;
        put(bo, "boundary", cJSON_CreateString(tippe_sweep_boundary_name(bd->boundary)), &ok);
        put(bo, "z2_mm", num(bd->z2_mm), &ok);
        put(bo, "band_mm", num(bd->band_mm), &ok);
        put(bo, "worst_mm", num(bd->worst_mm), &ok);
        put(bo, "combined", cJSON_CreateString("quadrature"), &ok);
        cJSON *sens = put(bo, "sensitivities", cJSON_CreateArray(), &ok);
        for (int i = 0; sens && i < nt; i++) {
            cJSON *so = put(sens, NULL, cJSON_CreateObject(), &ok);
            if (!so)
                break;
            put(so, "field", cJSON_CreateString(tippe_design_tolerance(d, i)->field), &ok);
            put(so, "dz2_dfield", num(bd->dz_dp[i]), &ok);
            put(so, "error", num(bd->dz_dp_err[i]), &ok);
        }
    }
    add_zone_bands(cJSON_GetObjectItemCaseSensitive(o, "zones"), b, &ok);
    add_zone_bands(cJSON_GetObjectItemCaseSensitive(o, "intervals"), b, &ok);
    double rob[3], narrow;
    tippe_sweep_robust_widths(r, b, rob, &narrow);
    cJSON *rw = put(o, "robust_zone_widths_mm", cJSON_CreateObject(), &ok);
    if (rw) {
        put(rw, "I", num(rob[0]), &ok);
        put(rw, "II", num(rob[1]), &ok);
        put(rw, "III", num(rob[2]), &ok);
    }
    put(o, "robust_narrowest_zone_mm", num(narrow), &ok);
    return ok ? 0 : -1;
}
