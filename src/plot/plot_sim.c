/* The figure of one simulated launch: time series on the left, the path in
 * (phi_dot, theta, n) space on the right, as in the paper's Figures 12 and 14. */
#include "plot/canvas.h"
#include "tippe/scenario.h"
#include "tippe/physics.h"

#include <math.h>
#include <plplot/plplot.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { PAGE_W = 1800, PAGE_H = 1100 };
/* A cmap0 slot for the raw 3D calls; plot.h's helpers use slots 0-2 and 16+. */
enum { SLOT_3D = 10 };

static const unsigned COL_TRAJ = 0x1f5fbf, COL_THEORY = 0x1a9641, COL_CURVE = 0xd7301f,
                      COL_GREY = 0x808080;

static void colour_3d(unsigned rgb)
{
    plscol0a(SLOT_3D, (PLINT)((rgb >> 16) & 0xff), (PLINT)((rgb >> 8) & 0xff),
             (PLINT)(rgb & 0xff), 1.0);
    plcol0(SLOT_3D);
}

static void range(const double *v, int n, double *lo, double *hi)
{
    *lo = INFINITY;
    *hi = -INFINITY;
    for (int i = 0; i < n; i++)
        if (isfinite(v[i])) {
            *lo = fmin(*lo, v[i]);
            *hi = fmax(*hi, v[i]);
        }
    if (!(*lo <= *hi)) {
        *lo = 0;
        *hi = 1;
    }
    /* at least 1% of the magnitude: a nearly constant series (a spin that changes in
     * its 10th digit) reads as constant, with distinct tick labels */
    const double mid = 0.5 * (*lo + *hi), half = fmax(0.5 * (*hi - *lo), 0.01 * fabs(mid));
    *lo = mid - half;
    *hi = mid + half;
    double pad = 0.1 * half;
    if (pad == 0)
        pad = 1e-3;
    *lo -= pad;
    *hi += pad;
}

/* Plain numbers on the axes (PLplot would otherwise factor out "x10^n"). */
static void label_plain(PLINT axis, PLFLT value, char *label, PLINT length, PLPointer data)
{
    (void)axis;
    const double step = data ? *(const double *)data : 0.0;
    if (fabs(value) < 1e-9 * (step > 0 ? step : 1.0))
        value = 0.0; /* no "-0" or "1e-17" at zero */
    snprintf(label, (size_t)length, "%.4g", value);
}

/* A 1-2-5 step giving at most about n intervals over span. */
static double tick_step(double span, double n)
{
    if (!(span > 0) || !isfinite(span))
        return 1.0;
    double raw = span / n, p10 = pow(10.0, floor(log10(raw))), m = raw / p10;
    return (m <= 1.0 ? 1.0 : m <= 2.0 ? 2.0 : m <= 5.0 ? 5.0 : 10.0) * p10;
}

/* Frame, grid and labels of a time-series panel, drawn here rather than with
 * the shared helper so that the stacked panels can share one labelled time
 * axis and keep their numbers apart. */
static void series_axes(double xspan, double yspan, int x_numbers, const char *xlabel,
                        const char *ylabel)
{
    const double xs = tick_step(xspan, 6), ys = tick_step(yspan, 5);
    colour_3d(0xc8c8c8);
    pllsty(2);
    plbox("g", xs, 0, "g", ys, 0);
    pllsty(1);
    colour_3d(0x000000);
    plschr(0.0, 0.62);
    double step = fmin(xs, ys);
    plslabelfunc(label_plain, &step);
    plbox(x_numbers ? "bcnost" : "bcst", xs, 0, "bcnostv", ys, 0);
    plslabelfunc(NULL, NULL);
    if (xlabel)
        plmtex("b", 2.8, 0.5, 0.5, xlabel);
    if (ylabel)
        plmtex("l", 6.5, 0.5, 0.5, ylabel);
    plschr(0.0, 1.0);
}

/* A horizontal dashed line across the current panel (theory's final values). */
static void hline(double t0, double t1, double y, unsigned rgb)
{
    double x[2] = {t0, t1}, yy[2] = {y, y};
    tippe_plot_line(2, x, yy, rgb, 1.5, TIPPE_PLOT_DASHED);
}

/* The samples as columns, theory's final states for J0, and room for the curve
 * of intermediate states (at most n points). */
typedef struct {
    int n;
    double *t, *th, *spin, *lslip, *al;
    double *cx, *cy, *cz;
    int nc;
    int have_pred;
    tippe_theory_prediction pred;
} sim_series;

static int series_fill(sim_series *s, const tippe_scenario *sc, const tippe_dynamics_result *res,
                       const tippe_dynamics_sample *smp, int n)
{
    s->n = n;
    s->t = malloc(8 * (size_t)n * sizeof *s->t);
    if (!s->t)
        return -1;
    s->th = s->t + n;
    s->spin = s->th + n;
    s->lslip = s->spin + n;
    s->al = s->lslip + n;
    s->cx = s->al + n;
    s->cy = s->cx + n;
    s->cz = s->cy + n;
    for (int i = 0; i < n; i++) {
        s->t[i] = smp[i].t;
        s->th[i] = smp[i].theta;
        s->spin[i] = smp[i].spin;
        s->al[i] = smp[i].phi_dot;
        /* 1e-16 m/s floors an exactly rolling contact on the log axis */
        s->lslip[i] = log10(fmax(smp[i].slip_speed, 1e-16));
    }
    tippe_error terr;
    s->have_pred =
        tippe_theory_predict(&sc->model.top, sc->model.g, res->J0, &s->pred, &terr) == TIPPE_OK;
    return 0;
}

/* theta, spin and log10 |V_Q| against time, stacked on the left. */
static void draw_series(sim_series *s, const tippe_dynamics_result *res)
{
    const int n = s->n;
    const double t_lo = s->t[0], t_hi = s->t[n - 1] > s->t[0] ? s->t[n - 1] : s->t[0] + 1;
    const double lx0 = 0.085, lx1 = 0.465;
    const tippe_theory_prediction *pred = &s->pred;

    /* theta against time, on the full [0, pi] so that tip and no tip read at a glance,
     * with a little room so that a top at 0 or pi is not hidden by the frame */
    tippe_plot_panel(lx0, lx1, 0.66, 0.90, t_lo, t_hi, -0.06, M_PI + 0.06);
    series_axes(t_hi - t_lo, M_PI, 0, NULL, "nutation #gh (rad)");
    for (int i = 0; s->have_pred && i < pred->n; i++)
        hline(t_lo, t_hi, pred->state[i].theta_rad, COL_THEORY);
    tippe_plot_line(n, s->t, s->th, COL_TRAJ, 1.5, TIPPE_PLOT_SOLID);

    double lo, hi;
    range(s->spin, n, &lo, &hi);
    /* after a lift-off theory's final spin is beside the point: keep the data's scale */
    if (s->have_pred && res->verdict != TIPPE_VERDICT_LOST_CONTACT)
        for (int i = 0; i < pred->n; i++) {
            lo = fmin(lo, pred->state[i].spin_rad_s);
            hi = fmax(hi, pred->state[i].spin_rad_s);
        }
    tippe_plot_panel(lx0, lx1, 0.39, 0.63, t_lo, t_hi, lo, hi);
    series_axes(t_hi - t_lo, hi - lo, 0, NULL, "spin n (rad/s)");
    for (int i = 0; s->have_pred && i < pred->n; i++)
        hline(t_lo, t_hi, pred->state[i].spin_rad_s, COL_THEORY);
    tippe_plot_line(n, s->t, s->spin, COL_TRAJ, 1.5, TIPPE_PLOT_SOLID);

    range(s->lslip, n, &lo, &hi);
    if (lo < hi - 14.0) { /* below 1e-14 of the largest speed is rounding: drawn on the floor */
        lo = hi - 14.0;
        for (int i = 0; i < n; i++)
            s->lslip[i] = fmax(s->lslip[i], lo);
    }
    tippe_plot_panel(lx0, lx1, 0.12, 0.36, t_lo, t_hi, lo, hi);
    series_axes(t_hi - t_lo, hi - lo, 1, "time t (s)", "log#d10#u sliding speed |V#dQ#u| (m/s)");
    tippe_plot_line(n, s->t, s->lslip, COL_TRAJ, 1.5, TIPPE_PLOT_SOLID);
}

/* The eq 5.4-5.6 curve of intermediate states on J0's branch, kept inside the
 * box [alo, ahi] x [nlo, nhi] of the trajectory. */
static void intermediate_curve(sim_series *s, const tippe_scenario *sc, double J0, double alo,
                               double ahi, double nlo, double nhi)
{
    const int sign = J0 >= 0 ? 1 : -1;
    s->nc = 0;
    for (int i = 1; i < s->n && s->nc < s->n; i++) {
        double q = M_PI * i / s->n;
        tippe_theory_state st;
        tippe_error terr;
        if (tippe_theory_intermediate(&sc->model.top, sc->model.g, q, sign, &st, &terr) !=
            TIPPE_OK)
            continue;
        if (st.phi_dot_rad_s < alo || st.phi_dot_rad_s > ahi || st.spin_rad_s < nlo ||
            st.spin_rad_s > nhi)
            continue;
        s->cx[s->nc] = st.phi_dot_rad_s;
        s->cy[s->nc] = q;
        s->cz[s->nc] = st.spin_rad_s;
        s->nc++;
    }
}

/* (alpha, theta, n): the projection of the paper's Figures 12 and 14, on the right.
 * 1 if a piece of the intermediate-state curve was drawn. */
static int draw_path_3d(sim_series *s, const tippe_scenario *sc, double J0)
{
    const int n = s->n;
    double alo, ahi, nlo, nhi;
    range(s->al, n, &alo, &ahi);
    range(s->spin, n, &nlo, &nhi);
    intermediate_curve(s, sc, J0, alo, ahi, nlo, nhi);
    const double vx0 = 0.56, vx1 = 0.98, vy0 = 0.24, vy1 = 0.88;
    tippe_plot_panel(vx0, vx1, vy0, vy1, 0, 1, 0, 1);
    tippe_plot_margin_text("t", 0.5, 0.5, 0.5, 0.9, 0x000000,
                           "path in (#ga, #gh, n), as the paper's Figures 12 and 14");
    plvpor(vx0, vx1, vy0, vy1);
    plwind(-1.25, 1.25, -0.8, 1.5);
    plw3d(1.35, 1.35, 1.3, alo, ahi, 0.0, M_PI, nlo, nhi, 25.0, 50.0);
    colour_3d(0x000000);
    plwidth(1.0);
    plschr(0.0, 0.62);
    plslabelfunc(label_plain, NULL);
    plbox3("bnostu", "precession #ga (rad/s)", 0.0, 0, "bnostu", "#gh (rad)", 0.0, 0,
           "bcdnost", "", 0.0, 0);
    plslabelfunc(NULL, NULL);
    plmtex("l", -0.5, 0.55, 0.5, "spin n (rad/s)");
    /* curve segments: consecutive kept points, broken where theta jumped */
    colour_3d(COL_CURVE);
    plwidth(2.5);
    int curve = 0;
    for (int i = 0; i < s->nc;) {
        int j = i + 1;
        while (j < s->nc && s->cy[j] - s->cy[j - 1] < 2.5 * M_PI / n)
            j++;
        if (j - i > 1) {
            plline3(j - i, s->cx + i, s->cy + i, s->cz + i);
            curve = 1;
        }
        i = j;
    }
    colour_3d(COL_TRAJ);
    plwidth(1.2);
    plline3(n, s->al, s->th, s->spin);
    colour_3d(COL_GREY);
    /* start (circle) and end (filled dot) */
    plssym(0.0, 1.6);
    plpoin3(1, s->al, s->th, s->spin, 4);
    colour_3d(0x000000);
    plpoin3(1, s->al + n - 1, s->th + n - 1, s->spin + n - 1, 17);
    plssym(0.0, 1.0);
    plwidth(1.0);
    plschr(0.0, 1.0);
    return curve;
}

/* One legend for both sides, in the strip under the 3D panel; the top's numbers
 * under it; the title (the verdict and the scenario) over the page. */
static void draw_key_and_title(const tippe_scenario *sc, const tippe_dynamics_result *res,
                               int curve)
{
    const double vx0 = 0.56, vx1 = 0.98;
    tippe_plot_panel(vx0, vx1, 0.095, 0.225, 0, 1, 0, 1);
    const tippe_plot_key keys[] = {
        {TIPPE_PLOT_KEY_LINE, "simulation (3D: open circle start, dot end)", COL_TRAJ, 1, 2.0,
         TIPPE_PLOT_SOLID},
        {TIPPE_PLOT_KEY_LINE, "Theorem 5.1 final state(s) for the launch's J", COL_THEORY, 1,
         1.5, TIPPE_PLOT_DASHED},
        {TIPPE_PLOT_KEY_LINE, "intermediate states (eqs 5.4-5.6, 5.10)", COL_CURVE, 1, 2.5,
         TIPPE_PLOT_SOLID},
    };
    tippe_plot_legend(keys, curve ? 3 : 2, "tl", 1, 0.7); /* the curve's key where drawn */
    const tippe_top *top = &sc->model.top;
    char note[400];
    tippe_theory_class cls;
    tippe_theory_classify(top->A / top->C, top->eps / top->R, &cls);
    /* two short lines: one would run off the page's right edge */
    tippe_plot_panel(0.0, 1.0, 0.0, 1.0, 0, 1, 0, 1);
    snprintf(note, sizeof note, "A/C = %.4g, #ge/R = %.4g (group %s)", top->A / top->C,
             top->eps / top->R, tippe_group_name(cls.group));
    tippe_plot_text(0.76, 0.047, 0.0, 0.5, 0.75, 0x000000, note);
    /* the coefficient of the law the run used: mu (s/m) is eq 3.12's only */
    if (tippe_friction_law_takes(sc->model.law, TIPPE_LAW_PARAM_MU))
        snprintf(note, sizeof note, "#gm = %.3g s/m, J#d0#u = %.4g kg m#u3#d/s", sc->model.mu,
                 res->J0);
    else
        snprintf(note, sizeof note, "%s #gm#dc#u = %.3g, J#d0#u = %.4g kg m#u3#d/s",
                 tippe_friction_law_type_of(sc->model.law)->label,
                 sc->model.mu_c, res->J0);
    tippe_plot_text(0.76, 0.017, 0.0, 0.5, 0.75, 0x000000, note);
    char esc[300], title[600];
    tippe_plot_escape(sc->name, esc, sizeof esc);
    if (res->verdict == TIPPE_VERDICT_UNDECIDED)
        snprintf(title, sizeof title, "undecided at t = %.4g s: %s", res->t_verdict, esc);
    else
        snprintf(title, sizeof title, "%s (decided at t = %.4g s): %s",
                 tippe_verdict_name(res->verdict), res->t_verdict, esc);
    /* last: the title helper restores the current panel, so one must exist */
    tippe_plot_page_title(title, fmin(1.1, 110.0 / (double)strlen(title)));
}

int tippe_plot_sim(const char *path, const tippe_scenario *sc, const tippe_dynamics_result *res,
                   const tippe_dynamics_sample *smp, int n, tippe_error *err)
{
    if (n < 2)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "%s: fewer than 2 samples to plot", path);
    sim_series s;
    if (series_fill(&s, sc, res, smp, n))
        return tippe_error_set(err, TIPPE_ECOMPUTE, "%s: out of memory", path);
    tippe_plot *p = NULL;
    int rc = tippe_plot_open(path, PAGE_W, PAGE_H, &p, err);
    if (rc) {
        free(s.t);
        return rc;
    }
    draw_series(&s, res);
    const int curve = draw_path_3d(&s, sc, res->J0);
    draw_key_and_title(sc, res, curve);
    free(s.t);
    return tippe_plot_close(p, err);
}

/* ---- one launch under several friction laws (tippe check --friction A,B) ---- */

/* Blue, red, green, purple: told apart in colour and, for grey print, by line style. */
static const unsigned COL_LAW[4] = {0x1f5fbf, 0xd7301f, 0x1a9641, 0x7b3294};
static const int STYLE_LAW[4] = {TIPPE_PLOT_SOLID, TIPPE_PLOT_DASHED, TIPPE_PLOT_SOLID,
                                 TIPPE_PLOT_DOTTED};

int tippe_plot_sim_laws(const char *path, const char *title, int n_laws,
                        const char *const *labels, const tippe_dynamics_samples *runs,
                        double t_window_s, tippe_error *err)
{
    if (n_laws < 1 || n_laws > 4)
        return tippe_error_set(err, TIPPE_EINPUT, "%s: 1 to 4 laws to plot, not %d", path,
                               n_laws);
    double t_end = 0.0, t_first = INFINITY;
    int most = 0;
    for (int k = 0; k < n_laws; k++) {
        if (runs[k].n < 2)
            return tippe_error_set(err, TIPPE_ECOMPUTE, "%s: fewer than 2 samples to plot", path);
        t_end = fmax(t_end, runs[k].s[runs[k].n - 1].t);
        if (runs[k].s[1].t > 0)
            t_first = fmin(t_first, runs[k].s[1].t);
        most = runs[k].n > most ? runs[k].n : most;
    }
    const double t_w = t_window_s > 0 && t_window_s < t_end ? t_window_s : t_end;
    double *x = malloc(2 * (size_t)most * sizeof *x);
    if (!x)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "%s: out of memory", path);
    double *y = x + most;
    tippe_plot *p = NULL;
    int rc = tippe_plot_open(path, PAGE_W, PAGE_H, &p, err);
    if (rc) {
        free(x);
        return rc;
    }
    const double vx0 = 0.075, vx1 = 0.70;
    /* top: the launch itself, linear time over [0, t_w] */
    tippe_plot_panel(vx0, vx1, 0.56, 0.90, 0.0, t_w, -0.06, M_PI + 0.06);
    series_axes(t_w, M_PI, 1, "time t (s)", "nutation #gh (rad)");
    hline(0.0, t_w, 0.5 * M_PI, COL_GREY);
    for (int k = 0; k < n_laws; k++) {
        int m = 0;
        for (int i = 0; i < runs[k].n && runs[k].s[i].t <= t_w * (1 + 1e-12); i++, m++) {
            x[m] = runs[k].s[i].t;
            y[m] = runs[k].s[i].theta;
        }
        tippe_plot_line(m, x, y, COL_LAW[k], 2.0, STYLE_LAW[k]);
    }
    char head[160];
    snprintf(head, sizeof head, "the launch: t = 0 .. %.3g s", t_w);
    tippe_plot_margin_text("t", 0.8, 0.0, 0.0, 0.8, 0x000000, head);
    /* bottom: the whole run to t_end on a logarithmic time axis */
    const double l0 = floor(log10(fmax(t_first, t_end * 1e-5))), l1 = log10(t_end);
    tippe_plot_panel(vx0, vx1, 0.10, 0.44, l0, l1, -0.06, M_PI + 0.06);
    colour_3d(0xc8c8c8);
    pllsty(2);
    plbox("gl", 1.0, 0, "g", 0.5, 0);
    pllsty(1);
    colour_3d(0x000000);
    plschr(0.0, 0.62);
    plbox("bclnst", 1.0, 0, "bcnstv", 0.5, 0);
    plmtex("b", 2.8, 0.5, 0.5, "time t (s), logarithmic");
    plmtex("l", 6.5, 0.5, 0.5, "nutation #gh (rad)");
    plschr(0.0, 1.0);
    hline(l0, l1, 0.5 * M_PI, COL_GREY);
    for (int k = 0; k < n_laws; k++) {
        int m = 0;
        for (int i = 0; i < runs[k].n; i++)
            if (runs[k].s[i].t > 0 && log10(runs[k].s[i].t) >= l0) {
                x[m] = log10(runs[k].s[i].t);
                y[m] = runs[k].s[i].theta;
                m++;
            }
        tippe_plot_line(m, x, y, COL_LAW[k], 2.0, STYLE_LAW[k]);
    }
    snprintf(head, sizeof head, "the whole run: t = %.3g .. %.4g s", pow(10.0, l0), t_end);
    tippe_plot_margin_text("t", 0.8, 0.0, 0.0, 0.8, 0x000000, head);
    /* the key: one line per law, and the 90 degree line */
    tippe_plot_key keys[5];
    char esc[4][400];
    for (int k = 0; k < n_laws; k++) {
        tippe_plot_escape(labels[k], esc[k], sizeof esc[k]);
        keys[k] = (tippe_plot_key){TIPPE_PLOT_KEY_LINE, esc[k], COL_LAW[k], 1, 2.5, STYLE_LAW[k]};
    }
    keys[n_laws] = (tippe_plot_key){TIPPE_PLOT_KEY_LINE, "#gh = #gp/2 (a flip passes it)",
                                    COL_GREY, 1, 1.5, TIPPE_PLOT_DASHED};
    tippe_plot_panel(0.715, 0.995, 0.10, 0.90, 0, 1, 0, 1);
    tippe_plot_legend(keys, n_laws + 1, "tl", 1, 0.62);
    char t[600];
    tippe_plot_escape(title, t, sizeof t);
    tippe_plot_page_title(t, fmin(1.1, 110.0 / (double)strlen(t)));
    free(x);
    return tippe_plot_close(p, err);
}
