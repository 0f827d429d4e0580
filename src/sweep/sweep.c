/* Zones of a top along the travel of its moving weight (see tippe/sweep.h). */
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

enum { NB = TIPPE_SWEEP_N_BOUNDARIES, MAX_ITER = 200 };

/* b is capped so that b -+ 1 stay finite where it diverges (e -> 0 with k -> 1);
 * only the signs of b -+ 1 matter and they are unchanged by the cap. */
#define B_CAP 1e12

static const char *const boundary_names[NB] = {
    "A/C-1=-eps/R", "A/C-1=+eps/R", "A/C-1=-(eps/R)^2", "b=1", "b=-1", "eps/R=0",
};

const char *tippe_sweep_boundary_name(tippe_sweep_boundary b)
{
    return (int)b >= 0 && (int)b < (int)NB ? boundary_names[b] : "?";
}

void tippe_sweep_options_default(tippe_sweep_options *opt)
{
    opt->n_scan = 2000;
    opt->xtol_mm = TIPPE_SWEEP_XTOL_MM;
    opt->touch_tol = 1e-9;
}

/* The path and what went wrong on it, shared by every GSL callback. */
typedef struct {
    const tippe_sweep_path *path;
    int which;    /* boundary function for single-function callbacks */
    double sign;  /* +-1: the callbacks return sign * g */
    int failed;
    tippe_error err;
} ctx;

/* All boundary functions at z2 (Theorem 5.1; b by eq 5.11), plus the class at
 * the point. Returns TIPPE_OK or TIPPE_EINPUT where the path leaves the
 * classification's domain. */
static int eval_point(ctx *c, double z2_mm, double g[NB], tippe_theory_class *cls)
{
    double k = NAN, es = NAN;
    c->path->eval(z2_mm, c->path->params, &k, &es);
    double e = fabs(es);
    tippe_theory_class tmp;
    if (!cls)
        cls = &tmp;
    if (!isfinite(k) || !isfinite(es) || tippe_theory_classify(k, e, cls) != TIPPE_OK) {
        c->failed = 1;
        return tippe_error_set(&c->err, TIPPE_EINPUT,
                               "at Z2 = %.6g mm the top is outside the phase diagram "
                               "(A/C = %g, eps/R = %g; need A/C > 0 and 0 <= eps/R < 1)",
                               z2_mm, k, e);
    }
    /* Above the line k - 1 = -e^2 b is not real; it reaches 1/e there from below,
     * so 1/e continues it without a jump (and keeps b -+ 1 away from zero). */
    double b = cls->has_b ? cls->b : (e > 0 ? 1.0 / e : B_CAP);
    b = GSL_MAX(-B_CAP, GSL_MIN(B_CAP, b));
    g[TIPPE_SWEEP_I_II] = (k - 1.0) + e;      /* Theorem 5.1, group I / II */
    g[TIPPE_SWEEP_II_III] = (k - 1.0) - e;    /* group II / III */
    g[TIPPE_SWEEP_E2_LINE] = (k - 1.0) + e * e; /* IIb above this line */
    g[TIPPE_SWEEP_B_PLUS] = b - 1.0;          /* IIa / IIb */
    g[TIPPE_SWEEP_B_MINUS] = b + 1.0;         /* Ia / Ib, IIa / IIc */
    g[TIPPE_SWEEP_BALANCED] = es;             /* eps = 0 */
    return TIPPE_OK;
}

int tippe_sweep_boundary_values(const tippe_sweep_path *path, double z2_mm,
                                double g[TIPPE_SWEEP_N_BOUNDARIES], tippe_error *err)
{
    ctx c = {.path = path};
    if (eval_point(&c, z2_mm, g, NULL) != TIPPE_OK)
        return tippe_error_set(err, c.err.code, "%s", c.err.msg);
    return TIPPE_OK;
}

static double g_one(double z2_mm, void *vp)
{
    ctx *c = vp;
    double g[NB];
    if (eval_point(c, z2_mm, g, NULL) != TIPPE_OK)
        return GSL_NAN;
    return c->sign * g[c->which];
}

static int sgn(double x) { return x < 0.0 ? -1 : 1; }

/* Root of function c->which in [lo, hi], where it changes sign. */
static int find_root(ctx *c, double lo, double hi, double xtol, double *root, tippe_error *err)
{
    c->sign = 1.0;
    double flo = g_one(lo, c), fhi = g_one(hi, c);
    if (c->failed)
        return tippe_error_set(err, c->err.code, "%s", c->err.msg);
    if (flo == 0.0 || fhi == 0.0) {
        *root = flo == 0.0 ? lo : hi;
        return TIPPE_OK;
    }
    gsl_function F = {g_one, c};
    gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (!s)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "sweep: out of memory");
    int status = gsl_root_fsolver_set(s, &F, lo, hi);
    for (int it = 0; status == GSL_SUCCESS && it < MAX_ITER; it++) {
        status = gsl_root_fsolver_iterate(s);
        if (status != GSL_SUCCESS)
            break;
        status = gsl_root_test_interval(gsl_root_fsolver_x_lower(s),
                                        gsl_root_fsolver_x_upper(s), xtol, 0.0);
        if (status == GSL_SUCCESS) {
            *root = gsl_root_fsolver_root(s);
            break;
        }
        if (status == GSL_CONTINUE)
            status = GSL_SUCCESS;
        if (it == MAX_ITER - 1)
            status = GSL_EMAXITER;
    }
    gsl_root_fsolver_free(s);
    if (c->failed)
        return tippe_error_set(err, c->err.code, "%s", c->err.msg);
    if (status != GSL_SUCCESS)
        return tippe_error_set(err, TIPPE_ECOMPUTE,
                               "sweep: root of %s in Z2 = [%.6g, %.6g] mm not found: %s",
                               boundary_names[c->which], lo, hi, gsl_strerror(status));
    return TIPPE_OK;
}

/* Minimum of sign * g_which over [lo, hi] starting from guess (which must be
 * lower than both ends). */
static int find_min(ctx *c, double sign, double lo, double guess, double hi, double xtol,
                    double *xmin, double *fmin, tippe_error *err)
{
    c->sign = sign;
    double fg = g_one(guess, c), flo = g_one(lo, c), fhi = g_one(hi, c);
    if (c->failed)
        return tippe_error_set(err, c->err.code, "%s", c->err.msg);
    if (!(fg < flo && fg < fhi)) { /* flat to rounding: the guess is the minimum */
        *xmin = guess;
        *fmin = fg;
        return TIPPE_OK;
    }
    gsl_function F = {g_one, c};
    gsl_min_fminimizer *s = gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent);
    if (!s)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "sweep: out of memory");
    int status = gsl_min_fminimizer_set_with_values(s, &F, guess, fg, lo, flo, hi, fhi);
    /* Running out of iterations still leaves the best point found, whose value
     * is all that is used: accept it. */
    for (int it = 0; status == GSL_SUCCESS && it < MAX_ITER; it++) {
        status = gsl_min_fminimizer_iterate(s);
        if (status != GSL_SUCCESS)
            break;
        /* Brent's minimiser cannot narrow its interval below ~sqrt(DBL_EPSILON)
         * relative to x (a minimum is flat to that order), hence the relative part. */
        status = gsl_min_test_interval(gsl_min_fminimizer_x_lower(s),
                                       gsl_min_fminimizer_x_upper(s), xtol,
                                       4.0 * GSL_SQRT_DBL_EPSILON);
        if (status == GSL_SUCCESS)
            break;
        if (status == GSL_CONTINUE)
            status = GSL_SUCCESS;
    }
    *xmin = gsl_min_fminimizer_x_minimum(s);
    *fmin = gsl_min_fminimizer_f_minimum(s);
    gsl_min_fminimizer_free(s);
    if (c->failed)
        return tippe_error_set(err, c->err.code, "%s", c->err.msg);
    if (status != GSL_SUCCESS)
        return tippe_error_set(err, TIPPE_ECOMPUTE,
                               "sweep: minimum of |%s| near Z2 = %.6g mm not found: %s",
                               boundary_names[c->which], guess, gsl_strerror(status));
    return TIPPE_OK;
}

/* A growing array of events. */
typedef struct {
    tippe_sweep_event *v;
    int n, cap;
} evlist;

static int ev_push(evlist *l, double z2, int which, int touch)
{
    if (l->n == l->cap) {
        int cap = l->cap ? 2 * l->cap : 32;
        tippe_sweep_event *v = realloc(l->v, (size_t)cap * sizeof *v);
        if (!v)
            return -1;
        l->v = v;
        l->cap = cap;
    }
    l->v[l->n++] = (tippe_sweep_event){z2, (tippe_sweep_boundary)which, touch};
    return 0;
}

static int cmp_event(const void *a, const void *b)
{
    const tippe_sweep_event *x = a, *y = b;
    if (x->z2_mm != y->z2_mm)
        return x->z2_mm < y->z2_mm ? -1 : 1;
    return (int)x->boundary - (int)y->boundary;
}

/* Crossings and touches of one boundary function along the scan. */
static int events_of(ctx *c, int which, int n, const double *z, const double *gv /* [n+1][NB] */,
                     const tippe_sweep_options *o, evlist *out, tippe_error *err)
{
    c->which = which;
    evlist cross = {0};
    int st = TIPPE_OK;
#define G(j) gv[(size_t)(j) * NB + (size_t)which]
    for (int j = 0; j < n && st == TIPPE_OK; j++) {
        if (sgn(G(j)) == sgn(G(j + 1)))
            continue;
        double r = 0.0;
        st = find_root(c, z[j], z[j + 1], o->xtol_mm, &r, err);
        if (st == TIPPE_OK && ev_push(&cross, r, which, 0))
            st = tippe_error_set(err, TIPPE_ECOMPUTE, "sweep: out of memory");
    }
    /* A near-zero local minimum of |g| between scan points with no sign change
     * around it: a touch, a near miss, or a dip across the boundary and back. */
    for (int j = 1; j < n && st == TIPPE_OK; j++) {
        double a = fabs(G(j - 1)), m = fabs(G(j)), b = fabs(G(j + 1));
        int s = sgn(G(j));
        if (!(m < a && m <= b) || sgn(G(j - 1)) != s || sgn(G(j + 1)) != s)
            continue;
        double guess = z[j];
        if (m == b) /* the minimum lies between j and j + 1 */
            guess = 0.5 * (z[j] + z[j + 1]);
        double xm = guess, fm = 0.0;
        st = find_min(c, s, z[j - 1], guess, z[j + 1], o->xtol_mm, &xm, &fm, err);
        if (st != TIPPE_OK)
            break;
        if (fm > o->touch_tol)
            continue; /* a near miss: the group does not change */
        if (fm >= -o->touch_tol) {
            if (ev_push(out, xm, which, 1))
                st = tippe_error_set(err, TIPPE_ECOMPUTE, "sweep: out of memory");
            continue;
        }
        double r1 = xm, r2 = xm;
        st = find_root(c, z[j - 1], xm, o->xtol_mm, &r1, err);
        if (st == TIPPE_OK)
            st = find_root(c, xm, z[j + 1], o->xtol_mm, &r2, err);
        if (st == TIPPE_OK && (ev_push(&cross, r1, which, 0) || ev_push(&cross, r2, which, 0)))
            st = tippe_error_set(err, TIPPE_ECOMPUTE, "sweep: out of memory");
    }
#undef G
    if (st == TIPPE_OK && cross.n > 1)
        qsort(cross.v, (size_t)cross.n, sizeof *cross.v, cmp_event);
    /* Two crossings of the same boundary with |g| never above touch_tol between
     * them are one touch seen through rounding (e.g. a scan point on the touch). */
    for (int i = 0; i < cross.n && st == TIPPE_OK; i++) {
        if (i + 1 < cross.n) {
            double r1 = cross.v[i].z2_mm, r2 = cross.v[i + 1].z2_mm, peak = 0.0, xpk = 0.5 * (r1 + r2);
            if (r2 - r1 > 2.0 * o->xtol_mm) {
                c->sign = 1.0;
                double gm = g_one(xpk, c);
                if (c->failed) {
                    st = tippe_error_set(err, c->err.code, "%s", c->err.msg);
                    break;
                }
                peak = fabs(gm);
                if (peak <= o->touch_tol && gm != 0.0) {
                    double fm = 0.0;
                    st = find_min(c, -sgn(gm), r1, xpk, r2, o->xtol_mm, &xpk, &fm, err);
                    peak = fabs(fm);
                }
            }
            if (st == TIPPE_OK && peak <= o->touch_tol) {
                if (ev_push(out, xpk, which, 1))
                    st = tippe_error_set(err, TIPPE_ECOMPUTE, "sweep: out of memory");
                i++;
                continue;
            }
        }
        if (st == TIPPE_OK && ev_push(out, cross.v[i].z2_mm, which, 0))
            st = tippe_error_set(err, TIPPE_ECOMPUTE, "sweep: out of memory");
    }
    free(cross.v);
    return st;
}

void tippe_sweep_result_free(tippe_sweep_result *r)
{
    if (!r)
        return;
    free(r->zones);
    free(r->events);
    memset(r, 0, sizeof *r);
}

/* Appends zone z to r, merging it into the previous one when nothing changes. */
static int zone_push(tippe_sweep_result *r, int *cap, tippe_sweep_zone z)
{
    if (r->n_zones > 0) {
        tippe_sweep_zone *p = &r->zones[r->n_zones - 1];
        if (p->group == z.group && p->com_side == z.com_side &&
            p->within_travel == z.within_travel) {
            p->z2_to_mm = z.z2_to_mm;
            p->to_boundaries = z.to_boundaries;
            return 0;
        }
    }
    if (r->n_zones == *cap) {
        int nc = *cap ? 2 * *cap : 16;
        tippe_sweep_zone *v = realloc(r->zones, (size_t)nc * sizeof *v);
        if (!v)
            return -1;
        r->zones = v;
        *cap = nc;
    }
    r->zones[r->n_zones++] = z;
    return 0;
}

int tippe_sweep_run(const tippe_sweep_path *path, double from_mm, double to_mm,
                    const tippe_sweep_options *opt, tippe_sweep_result *out, tippe_error *err)
{
    memset(out, 0, sizeof *out);
    tippe_gsl_errors_as_codes();
    tippe_sweep_options o;
    tippe_sweep_options_default(&o);
    if (opt)
        o = *opt;
    if (!path || !path->eval)
        return tippe_error_set(err, TIPPE_EINPUT, "sweep: no path");
    if (!isfinite(from_mm) || !isfinite(to_mm) || !(from_mm < to_mm))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "sweep: the range Z2 = [%g, %g] mm is empty (need from < to)",
                               from_mm, to_mm);
    if (o.n_scan < 2 || o.n_scan > 10000000 || !(o.xtol_mm > 0) || !(o.touch_tol >= 0))
        return tippe_error_set(err, TIPPE_EINPUT, "sweep: bad options (n_scan %d, xtol %g mm)",
                               o.n_scan, o.xtol_mm);
    out->from_mm = from_mm;
    out->to_mm = to_mm;

    int n = o.n_scan, st = TIPPE_OK;
    double *z = malloc((size_t)(n + 1) * sizeof *z);
    double *gv = malloc((size_t)(n + 1) * NB * sizeof *gv);
    evlist ev = {0};
    ctx c = {.path = path};
    if (!z || !gv) {
        st = tippe_error_set(err, TIPPE_ECOMPUTE, "sweep: out of memory");
        goto done;
    }
    for (int j = 0; j <= n && st == TIPPE_OK; j++) {
        z[j] = j == n ? to_mm : from_mm + (to_mm - from_mm) * j / n;
        if (eval_point(&c, z[j], gv + (size_t)j * NB, NULL) != TIPPE_OK)
            st = tippe_error_set(err, c.err.code, "%s", c.err.msg);
    }
    for (int w = 0; w < NB && st == TIPPE_OK; w++)
        st = events_of(&c, w, n, z, gv, &o, &ev, err);
    if (st != TIPPE_OK)
        goto done;
    if (ev.n > 1)
        qsort(ev.v, (size_t)ev.n, sizeof *ev.v, cmp_event);

    /* Cuts: crossings inside the range; crossings of several boundaries closer
     * than the location tolerance are one cut. */
    int zcap = 0, ncut = 0;
    double *cut = malloc((size_t)(ev.n + 2) * sizeof *cut);
    unsigned *cut_bits = malloc((size_t)(ev.n + 2) * sizeof *cut_bits);
    if (!cut || !cut_bits) {
        free(cut);
        free(cut_bits);
        st = tippe_error_set(err, TIPPE_ECOMPUTE, "sweep: out of memory");
        goto done;
    }
    cut[ncut] = from_mm, cut_bits[ncut++] = 0;
    for (int i = 0; i < ev.n; i++) {
        double x = ev.v[i].z2_mm;
        if (ev.v[i].touch || x - from_mm <= o.xtol_mm || to_mm - x <= o.xtol_mm)
            continue;
        if (ncut > 1 && x - cut[ncut - 1] <= 2.0 * o.xtol_mm) {
            cut_bits[ncut - 1] |= 1u << ev.v[i].boundary;
            continue;
        }
        cut[ncut] = x, cut_bits[ncut++] = 1u << ev.v[i].boundary;
    }
    cut[ncut] = to_mm, cut_bits[ncut++] = 0;
    for (int i = 0; i + 1 < ncut && st == TIPPE_OK; i++) {
        double mid = 0.5 * (cut[i] + cut[i + 1]), g[NB];
        tippe_theory_class cls;
        if (eval_point(&c, mid, g, &cls) != TIPPE_OK) {
            st = tippe_error_set(err, c.err.code, "%s", c.err.msg);
            break;
        }
        double es = g[TIPPE_SWEEP_BALANCED];
        tippe_sweep_zone zn = {
            .group = cls.group, .z2_from_mm = cut[i], .z2_to_mm = cut[i + 1],
            .com_side = es > 0 ? 1 : es < 0 ? -1 : 0,
            .from_boundaries = cut_bits[i], .to_boundaries = cut_bits[i + 1], .within_travel = 1,
        };
        if (zone_push(out, &zcap, zn))
            st = tippe_error_set(err, TIPPE_ECOMPUTE, "sweep: out of memory");
    }
    free(cut);
    free(cut_bits);
    if (st == TIPPE_OK) {
        out->events = ev.v;
        out->n_events = ev.n;
        ev.v = NULL;
    }
done:
    free(z);
    free(gv);
    free(ev.v);
    return st;
}

int tippe_sweep_mark_travel(tippe_sweep_result *r, double from_mm, double to_mm,
                            tippe_error *err)
{
    if (!isfinite(from_mm) || !isfinite(to_mm) || from_mm > to_mm)
        return tippe_error_set(err, TIPPE_EINPUT, "sweep: bad physical travel [%g, %g] mm",
                               from_mm, to_mm);
    /* Each zone splits into at most three parts: below, within, above. */
    tippe_sweep_zone *v = malloc((size_t)(3 * r->n_zones + 1) * sizeof *v);
    if (!v)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "sweep: out of memory");
    int n = 0;
    for (int i = 0; i < r->n_zones; i++) {
        tippe_sweep_zone z = r->zones[i];
        double ends[4] = {z.z2_from_mm, GSL_MAX(z.z2_from_mm, GSL_MIN(from_mm, z.z2_to_mm)),
                          GSL_MAX(z.z2_from_mm, GSL_MIN(to_mm, z.z2_to_mm)), z.z2_to_mm};
        for (int p = 0; p < 3; p++) {
            if (ends[p + 1] - ends[p] <= 0.0)
                continue;
            tippe_sweep_zone part = z;
            part.z2_from_mm = ends[p];
            part.z2_to_mm = ends[p + 1];
            part.from_boundaries = ends[p] == z.z2_from_mm ? z.from_boundaries : 0;
            part.to_boundaries = ends[p + 1] == z.z2_to_mm ? z.to_boundaries : 0;
            part.within_travel = p == 1;
            v[n++] = part;
        }
    }
    free(r->zones);
    r->zones = v;
    r->n_zones = n;
    r->has_travel = 1;
    r->travel_from_mm = from_mm;
    r->travel_to_mm = to_mm;
    return TIPPE_OK;
}

static void design_eval(double z2_mm, void *params, double *A_over_C, double *e_signed)
{
    tippe_top t;
    tippe_design_top_any(params, z2_mm, &t);
    *A_over_C = t.A / t.C;
    /* eps >= 0 with the side in com_side: their product is continuous in Z2. */
    *e_signed = (t.com_side > 0 ? 1.0 : t.com_side < 0 ? -1.0 : 0.0) * t.eps / t.R;
}

tippe_sweep_path tippe_sweep_design_path(const tippe_design *d)
{
    return (tippe_sweep_path){design_eval, (void *)d};
}

int tippe_sweep_design(const tippe_design *d, double from_mm, double to_mm,
                       const tippe_sweep_options *opt, tippe_sweep_result *out, tippe_error *err)
{
    memset(out, 0, sizeof *out);
    if (!(from_mm < to_mm))
        tippe_design_travel_mm(d, &from_mm, &to_mm);
    tippe_sweep_path p = tippe_sweep_design_path(d);
    int st = tippe_sweep_run(&p, from_mm, to_mm, opt, out, err);
    if (st != TIPPE_OK) {
        char msg[sizeof err->msg];
        snprintf(msg, sizeof msg, "%s", err ? err->msg : "");
        return tippe_error_set(err, st, "%s: %s", tippe_design_name(d), msg);
    }
    tippe_design_sphere_only_mm(d, &out->sphere_only_from_mm, &out->sphere_only_to_mm);
    out->has_sphere_only = 1;
    double pf, pt;
    tippe_design_contact_travel_mm(d, &pf, &pt);
    return tippe_sweep_mark_travel(out, pf, pt, err);
}

int tippe_sweep_zone_model_invalid(const tippe_sweep_result *r, const tippe_sweep_zone *z,
                                   double from[2], double to[2])
{
    if (!r->has_sphere_only)
        return 0;
    const double a = r->sphere_only_from_mm, b = r->sphere_only_to_mm;
    const double f = z->z2_from_mm, t = z->z2_to_mm;
    if (a > b || t <= a || f >= b) { /* no sphere-only Z2 in the zone */
        from[0] = f;
        to[0] = t;
        return 1;
    }
    int n = 0;
    if (f < a) {
        from[n] = f;
        to[n++] = a;
    }
    if (t > b) {
        from[n] = b;
        to[n++] = t;
    }
    return n;
}

/* The part of zone z a maker can use: within the physical travel and the
 * sphere-only interval (the sphere-only interval is one piece, so this is one
 * piece too). Returns 1 and [*from_mm, *to_mm] where it is longer than 0. */
static int zone_usable(const tippe_sweep_result *r, const tippe_sweep_zone *z, double *from_mm,
                       double *to_mm)
{
    double f = z->z2_from_mm, t = z->z2_to_mm;
    if (!z->within_travel)
        return 0;
    /* Where a part stands out the top rests on it, not on its sphere: no zone of
     * the paper's model is there to use (docs/design-format.md). */
    if (r->has_sphere_only) {
        f = GSL_MAX(f, r->sphere_only_from_mm);
        t = GSL_MIN(t, r->sphere_only_to_mm);
    }
    if (!(t > f))
        return 0;
    *from_mm = f;
    *to_mm = t;
    return 1;
}

static const char *const family_names[3] = {"I", "II", "III"};

static int family_index(tippe_group g)
{
    const char *f = tippe_group_family(g);
    for (int k = 0; k < 3; k++)
        if (!strcmp(f, family_names[k]))
            return k;
    return -1;
}

int tippe_sweep_family_run(const tippe_sweep_result *r, int i, int *family, double *from_mm,
                           double *to_mm)
{
    double f2, t2;
    *family = zone_usable(r, &r->zones[i], from_mm, to_mm) ? family_index(r->zones[i].group) : -1;
    int j = i + 1;
    while (*family >= 0 && j < r->n_zones && zone_usable(r, &r->zones[j], &f2, &t2) &&
           family_index(r->zones[j].group) == *family) {
        *to_mm = t2;
        j++;
    }
    return j;
}

void tippe_sweep_summarise(const tippe_sweep_result *r, tippe_sweep_summary *out)
{
    memset(out, 0, sizeof *out);
    int has[3] = {0, 0, 0};
    for (int i = 0, f; i < r->n_zones;) {
        double from, to;
        i = tippe_sweep_family_run(r, i, &f, &from, &to);
        if (f >= 0) {
            out->widest_mm[f] = GSL_MAX(out->widest_mm[f], to - from);
            has[f] = 1;
        }
    }
    out->has_I = has[0];
    out->has_II = has[1];
    out->has_III = has[2];
    out->three_in_one = has[0] && has[1] && has[2];
    for (int k = 0; out->three_in_one && k < 3; k++)
        if (!out->narrowest_family || out->widest_mm[k] < out->narrowest_zone_mm) {
            out->narrowest_zone_mm = out->widest_mm[k];
            out->narrowest_family = family_names[k];
        }
}

/* ---- reports ---------------------------------------------------------------- */

/* mm with three decimals and no "-0.000". */
static double clean(double x) { return fabs(x) < 5e-4 ? 0.0 : x; }

static void boundary_list(unsigned bits, char *buf, size_t n)
{
    buf[0] = '\0';
    for (int b = 0; b < NB; b++) {
        if (!(bits & (1u << b)))
            continue;
        size_t len = strlen(buf);
        snprintf(buf + len, n - len, "%s%s", len ? ", " : "", boundary_names[b]);
    }
}

/* Whether the zones lie on both sides of the balanced point. */
static int mixed_sides(const tippe_sweep_result *r)
{
    for (int i = 1; i < r->n_zones; i++)
        if (r->zones[i].com_side != r->zones[0].com_side)
            return 1;
    return 0;
}

/* Whether the event is one of the zone ends (a crossing that changed group). */
static int ends_a_zone(const tippe_sweep_result *r, const tippe_sweep_event *ev)
{
    for (int i = 0; i + 1 < r->n_zones; i++)
        if ((r->zones[i].to_boundaries & (1u << ev->boundary)) &&
            fabs(r->zones[i].z2_to_mm - ev->z2_mm) <= 2.0 * TIPPE_SWEEP_XTOL_MM)
            return 1;
    return 0;
}

int tippe_sweep_event_ends_zone(const tippe_sweep_result *r, const tippe_sweep_event *ev)
{
    return ends_a_zone(r, ev);
}

/* Where the sweep leaves the Z2 in which every part stays inside the sphere:
 * what stands out there (the model lets the top touch the table with its
 * sphere only). */
static void print_sphere_only(FILE *out, const tippe_sweep_result *r, const tippe_design *d)
{
    if (!r->has_sphere_only)
        return;
    const double a = r->sphere_only_from_mm, b = r->sphere_only_to_mm;
    double lo = r->from_mm, hi = r->to_mm; /* the sweep within the physical travel */
    if (r->has_travel) {
        lo = GSL_MAX(lo, r->travel_from_mm);
        hi = GSL_MIN(hi, r->travel_to_mm);
    }
    if (a <= b && lo >= a && hi <= b)
        return;
    if (a > b)
        fprintf(out, "contact  material stands out of the sphere at every Z2");
    else
        fprintf(out, "contact  every part stays inside the sphere only for Z2 = %.3f .. %.3f mm",
                clean(a), clean(b));
    fprintf(out, ": beyond, the top rests on what stands out and the model\n"
                 "         (contact on the sphere only) does not apply: zones there are "
                 "marked MODEL INVALID\n");
    tippe_design_protrusion p;
    const double z = a > b || hi > b ? hi : lo;
    if (d && tippe_design_protrusion_at(d, z, &p)) {
        char text[512];
        tippe_design_protrusion_text(&p, text, sizeof text);
        fprintf(out, "         at Z2 = %.3f mm %s\n", clean(z), text);
    }
}

/* The poles where a hole opens (issue 25.7): a top tilted on such a pole less
 * than the opening's half-angle stands on the hole's rim, not on its sphere, at
 * every Z2 (a fixed hole; a moving one is taken at the sweep's middle). */
static void print_polar_caps(FILE *out, const tippe_sweep_result *r, const tippe_design *d)
{
    tippe_design_cap caps[2];
    if (!d || !tippe_design_polar_caps(d, 0.5 * (r->from_mm + r->to_mm), caps))
        return;
    for (int k = 0; k < 2; k++)
        if (caps[k].half_angle_rad > 0)
            fprintf(out,
                    "pole     %s: the opening of '%s' (%.2f mm across): a top tilted less than "
                    "%.1f deg on this pole\n"
                    "         stands on the hole's rim, not on its sphere: the zones (the "
                    "paper's theory) do not apply there; tippe check and launch follow the rim\n",
                    k ? "-z" : "+z", caps[k].part, 2 * caps[k].radius_mm,
                    caps[k].half_angle_rad * 180 / M_PI);
}

static const char *side_down(int com_side)
{
    return com_side > 0 ? "+z side down" : com_side < 0 ? "-z side down" : "balanced";
}

void tippe_sweep_print_table(FILE *out, const tippe_sweep_result *r, const tippe_design *d)
{
    if (d) {
        double f, t;
        tippe_design_travel_mm(d, &f, &t);
        fprintf(out, "design   %s (%s)\n", tippe_design_name(d), tippe_design_path(d));
        fprintf(out, "travel   stated %.3f .. %.3f mm", clean(f), clean(t));
        if (r->has_travel)
            fprintf(out, ", physical %.3f .. %.3f mm", clean(r->travel_from_mm),
                    clean(r->travel_to_mm));
        fprintf(out, "\n");
    }
    fprintf(out, "sweep    Z2 = %.3f .. %.3f mm\n", clean(r->from_mm), clean(r->to_mm));
    print_sphere_only(out, r, d);
    print_polar_caps(out, r, d);
    fprintf(out, "\n");
    fprintf(out, "%-5s %10s %10s %11s  %-22s %s\n", "zone", "from (mm)", "to (mm)",
            "width (mm)", "ends on", "notes");
    int mixed = mixed_sides(r);
    for (int i = 0; i < r->n_zones; i++) {
        const tippe_sweep_zone *z = &r->zones[i];
        char ends[160], notes[320] = "";
        boundary_list(z->to_boundaries, ends, sizeof ends);
        if (!ends[0])
            snprintf(ends, sizeof ends, "%s",
                     i + 1 == r->n_zones ? "(end of sweep)" : "(physical travel)");
        if (!z->within_travel) {
            int upper = r->has_travel && z->z2_from_mm >= r->travel_to_mm;
            const char *why = d ? tippe_design_contact_limit(d, upper) : NULL;
            snprintf(notes, sizeof notes, "beyond physical travel%s%s%s", why ? " (" : "",
                     why ? why : "", why ? ")" : "");
        }
        if (mixed) {
            size_t len = strlen(notes);
            snprintf(notes + len, sizeof notes - len, "%s%s", len ? "; " : "",
                     side_down(z->com_side));
        }
        double bad_from[2], bad_to[2];
        /* beyond the physical travel the top cannot be set: said already */
        int n_bad = z->within_travel ? tippe_sweep_zone_model_invalid(r, z, bad_from, bad_to) : 0;
        for (int k = 0; k < n_bad; k++) {
            size_t len = strlen(notes);
            if (bad_from[k] == z->z2_from_mm && bad_to[k] == z->z2_to_mm)
                snprintf(notes + len, sizeof notes - len, "%sMODEL INVALID (part out of the "
                         "sphere)", len ? "; " : "");
            else
                snprintf(notes + len, sizeof notes - len, "%sMODEL INVALID %.3f .. %.3f mm",
                         len ? "; " : "", clean(bad_from[k]), clean(bad_to[k]));
        }
        fprintf(out, "%-5s %10.3f %10.3f %11.3f  %-22s %s\n", tippe_group_name(z->group),
                clean(z->z2_from_mm), clean(z->z2_to_mm), z->z2_to_mm - z->z2_from_mm, ends,
                notes);
    }
    for (int i = 0; i < r->n_events; i++) {
        const tippe_sweep_event *ev = &r->events[i];
        if (ev->touch) {
            fprintf(out, "touch at Z2 = %.3f mm: the path meets %s and turns back (no zone change)\n",
                    clean(ev->z2_mm), boundary_names[ev->boundary]);
        } else if (!ends_a_zone(r, ev)) {
            /* The paper's figures draw the -(eps/R)^2 line as the IIa|IIb (IIc|IIb)
             * boundary; say where the path crosses it even when b decides otherwise. */
            fprintf(out, "crosses %s at Z2 = %.3f mm (no change of group there)\n",
                    boundary_names[ev->boundary], clean(ev->z2_mm));
        }
    }
    tippe_sweep_summary s;
    tippe_sweep_summarise(r, &s);
    const int clipped = r->has_sphere_only &&
                        (r->sphere_only_from_mm > r->from_mm || r->sphere_only_to_mm < r->to_mm);
    const char *where = r->has_travel ? (clipped ? "within the physical travel where the model "
                                                   "applies"
                                                 : "within the physical travel")
                                      : "in the sweep";
    fprintf(out, "\n3-in-1   %s: groups reachable %s: %s%s%s%s\n", s.three_in_one ? "yes" : "no",
            where, s.has_I ? "I " : "", s.has_II ? "II " : "", s.has_III ? "III" : "",
            !s.has_I && !s.has_II && !s.has_III ? "none" : "");
    if (s.has_I || s.has_II || s.has_III) {
        fprintf(out, "zones    widest run of each group %s (subgroups together):", where);
        for (int k = 0; k < 3; k++)
            fprintf(out, " %s %.3f mm%s", family_names[k], s.widest_mm[k], k < 2 ? "," : "\n");
    }
    if (s.three_in_one)
        fprintf(out, "narrowest zone: %.3f mm (group %s)\n", s.narrowest_zone_mm,
                s.narrowest_family);
    else
        fprintf(out, "narrowest zone: 0 mm (not 3-in-1)\n");
}

/* cJSON helpers that record failure instead of returning it at every call. */
static cJSON *add_obj(cJSON *parent, cJSON *item, const char *key, int *ok)
{
    if (!item) {
        *ok = 0;
        return NULL;
    }
    if (!(key ? cJSON_AddItemToObject(parent, key, item) : cJSON_AddItemToArray(parent, item))) {
        cJSON_Delete(item);
        *ok = 0;
        return NULL;
    }
    return item;
}

static void add_pair(cJSON *o, const char *key, double a, double b, int *ok)
{
    double v[2] = {a, b};
    add_obj(o, cJSON_CreateDoubleArray(v, 2), key, ok);
}

/* The paper's zone names: group I is one zone whatever its subgroup. */
static const char *zone_label(tippe_group g)
{
    return (g == TIPPE_GROUP_IA || g == TIPPE_GROUP_IB) ? "I" : tippe_group_name(g);
}

static void add_ends_on(cJSON *zo, unsigned boundaries, int *ok)
{
    cJSON *ends = add_obj(zo, cJSON_CreateArray(), "ends_on", ok);
    for (int b = 0; ends && b < NB; b++)
        if (boundaries & (1u << b))
            add_obj(ends, cJSON_CreateString(boundary_names[b]), NULL, ok);
}

/* "model_invalid_mm": the pieces of the zone where a part stands out of the
 * sphere, [[from, to], ...] (empty where the model applies throughout). */
static void add_model_invalid(cJSON *zo, const tippe_sweep_result *r, const tippe_sweep_zone *z,
                              int *ok)
{
    cJSON *list = add_obj(zo, cJSON_CreateArray(), "model_invalid_mm", ok);
    double f[2], t[2];
    int n = tippe_sweep_zone_model_invalid(r, z, f, t);
    for (int k = 0; list && k < n; k++)
        add_pair(list, NULL, f[k], t[k], ok);
}

cJSON *tippe_sweep_json(const tippe_sweep_result *r, const tippe_design *d)
{
    cJSON *o = cJSON_CreateObject();
    int ok = o != NULL;
    if (!ok)
        return NULL;
    if (d) {
        double f, t;
        tippe_design_travel_mm(d, &f, &t);
        add_obj(o, cJSON_CreateString(tippe_design_name(d)), "design", &ok);
        add_obj(o, cJSON_CreateString(tippe_design_path(d)), "file", &ok);
        add_pair(o, "travel_mm", f, t, &ok);
        tippe_design_cap caps[2];
        tippe_design_polar_caps(d, 0.5 * (r->from_mm + r->to_mm), caps);
        tippe_design_caps_json(o, caps);
    }
    add_pair(o, "sweep_mm", r->from_mm, r->to_mm, &ok);
    if (r->has_travel)
        add_pair(o, "physical_travel_mm", r->travel_from_mm, r->travel_to_mm, &ok);
    if (r->has_sphere_only && r->sphere_only_from_mm <= r->sphere_only_to_mm)
        add_pair(o, "sphere_only_mm", r->sphere_only_from_mm,
                 r->sphere_only_to_mm, &ok);
    else if (r->has_sphere_only)
        add_obj(o, cJSON_CreateNull(), "sphere_only_mm", &ok);
    /* "zones": one entry per run of one zone label (I, IIa, IIb, IIc, III: the
     * paper's zones, Ia and Ib joined as I) and one side of the balanced point,
     * however the run was split (Ia|Ib, the ends of the physical travel).
     * "intervals": the runs as found, with subgroup and travel splits. */
    cJSON *zones = add_obj(o, cJSON_CreateArray(), "zones", &ok);
    for (int i = 0; zones && ok && i < r->n_zones;) {
        const char *label = zone_label(r->zones[i].group);
        int j = i + 1;
        while (j < r->n_zones && !strcmp(zone_label(r->zones[j].group), label) &&
               r->zones[j].com_side == r->zones[i].com_side)
            j++;
        cJSON *zo = add_obj(zones, cJSON_CreateObject(), NULL, &ok);
        if (!zo)
            break;
        const tippe_sweep_zone *first = &r->zones[i], *last = &r->zones[j - 1];
        add_obj(zo, cJSON_CreateString(label), "group", &ok);
        cJSON *subs = add_obj(zo, cJSON_CreateArray(), "subgroups", &ok);
        double reach_from = INFINITY, reach_to = -INFINITY;
        int all_within = 1;
        for (int k = i; subs && k < j; k++) {
            if (k == i || r->zones[k].group != r->zones[k - 1].group)
                add_obj(subs, cJSON_CreateString(tippe_group_name(r->zones[k].group)), NULL, &ok);
            if (r->zones[k].within_travel) {
                reach_from = fmin(reach_from, r->zones[k].z2_from_mm);
                reach_to = fmax(reach_to, r->zones[k].z2_to_mm);
            } else {
                all_within = 0;
            }
        }
        add_obj(zo, cJSON_CreateNumber(first->z2_from_mm), "z2_from_mm", &ok);
        add_obj(zo, cJSON_CreateNumber(last->z2_to_mm), "z2_to_mm", &ok);
        add_obj(zo, cJSON_CreateNumber(last->z2_to_mm - first->z2_from_mm), "width_mm", &ok);
        add_obj(zo, cJSON_CreateBool(all_within), "within_travel", &ok);
        if (reach_from <= reach_to)
            add_pair(zo, "reachable_mm", reach_from, reach_to, &ok);
        else
            add_obj(zo, cJSON_CreateNull(), "reachable_mm", &ok);
        add_obj(zo, cJSON_CreateNumber(first->com_side), "com_side", &ok);
        add_ends_on(zo, last->to_boundaries, &ok);
        tippe_sweep_zone run = *first;
        run.z2_to_mm = last->z2_to_mm;
        add_model_invalid(zo, r, &run, &ok);
        i = j;
    }
    cJSON *intervals = add_obj(o, cJSON_CreateArray(), "intervals", &ok);
    for (int i = 0; intervals && ok && i < r->n_zones; i++) {
        const tippe_sweep_zone *z = &r->zones[i];
        cJSON *zo = add_obj(intervals, cJSON_CreateObject(), NULL, &ok);
        if (!zo)
            break;
        add_obj(zo, cJSON_CreateString(tippe_group_name(z->group)), "group", &ok);
        add_obj(zo, cJSON_CreateString(tippe_group_family(z->group)), "family", &ok);
        add_obj(zo, cJSON_CreateNumber(z->z2_from_mm), "z2_from_mm", &ok);
        add_obj(zo, cJSON_CreateNumber(z->z2_to_mm), "z2_to_mm", &ok);
        add_obj(zo, cJSON_CreateNumber(z->z2_to_mm - z->z2_from_mm), "width_mm", &ok);
        add_obj(zo, cJSON_CreateBool(z->within_travel), "within_travel", &ok);
        add_obj(zo, cJSON_CreateNumber(z->com_side), "com_side", &ok);
        add_ends_on(zo, z->to_boundaries, &ok);
        add_model_invalid(zo, r, z, &ok);
    }
    cJSON *touches = add_obj(o, cJSON_CreateArray(), "touches", &ok);
    cJSON *crossings = add_obj(o, cJSON_CreateArray(), "crossings", &ok);
    for (int i = 0; touches && crossings && ok && i < r->n_events; i++) {
        cJSON *t = add_obj(r->events[i].touch ? touches : crossings, cJSON_CreateObject(), NULL,
                           &ok);
        if (!t)
            break;
        add_obj(t, cJSON_CreateString(boundary_names[r->events[i].boundary]), "boundary", &ok);
        add_obj(t, cJSON_CreateNumber(r->events[i].z2_mm), "z2_mm", &ok);
        if (!r->events[i].touch)
            add_obj(t, cJSON_CreateBool(ends_a_zone(r, &r->events[i])), "ends_zone", &ok);
    }
    tippe_sweep_summary s;
    tippe_sweep_summarise(r, &s);
    add_obj(o, cJSON_CreateBool(s.three_in_one), "three_in_one", &ok);
    add_obj(o, cJSON_CreateNumber(s.narrowest_zone_mm), "narrowest_zone_mm", &ok);
    add_obj(o, s.narrowest_family ? cJSON_CreateString(s.narrowest_family) : cJSON_CreateNull(),
            "narrowest_zone_family", &ok);
    cJSON *widths = add_obj(o, cJSON_CreateObject(), "zone_widths_mm", &ok);
    for (int k = 0; widths && k < 3; k++)
        add_obj(widths, cJSON_CreateNumber(s.widest_mm[k]), family_names[k], &ok);
    if (!ok) {
        cJSON_Delete(o);
        return NULL;
    }
    return o;
}
