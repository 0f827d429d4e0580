/* The effective potential V(theta; J) and its wells (tippe/physics.h), checked
 * against quantities computed another way: the energy of random states from the
 * dynamics module (E >= V), the intermediate states of eq 5.10 (critical points),
 * Theorem 5.1's predictions (minima) and a dense scan of V's slope (completeness). */
#include "tippe/physics.h"

#include "check.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdio.h>

/* m = g = C = R = 1, as in the paper's Figures 12-14 */
static tippe_top unit_top(double k, double e)
{
    tippe_top t = {1.0, 1.0, e, k, 1.0, -1, {0.0, 0.0}};
    return t;
}

/* One top per subgroup (the picks of tests/test_theory.c) and a small printed top. */
static const struct {
    const char *why;
    tippe_top top;
} tops[] = {
    {"Fig 12 (IIb)", {1, 1, 0.3, 0.92, 1, -1, {0.0, 0.0}}},
    {"Fig 14 (IIa)", {1, 1, 0.5, 0.55, 1, -1, {0.0, 0.0}}},
    {"Ia", {1, 1, 0.05, 0.9, 1, -1, {0.0, 0.0}}},
    {"Ib", {1, 1, 0.3, 0.6, 1, -1, {0.0, 0.0}}},
    {"IIc-ish", {1, 1, 0.3, 0.88, 1, -1, {0.0, 0.0}}},
    {"III", {1, 1, 0.3, 1.5, 1, -1, {0.0, 0.0}}},
    {"25 mm printed top", {0.012, 0.0125, 0.002, 6.9e-7, 8.1e-7, -1, {0.0, 0.0}}},
};
enum { N_TOPS = (int)(sizeof tops / sizeof tops[0]) };

/* E >= V on random states: the energy computed by the dynamics module from the
 * full state (kinetic + potential, section 4) never falls below the potential at
 * the state's theta and J; equal when the state is the minimiser (theta_dot = U =
 * V = 0, spin and precession in the split that V assumes). */
static void test_energy_bound(void)
{
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(r, 11);
    int below = 0, n = 0, eq_bad = 0;
    double worst_eq = 0.0;
    for (int t = 0; t < N_TOPS; t++) {
        const tippe_top *top = &tops[t].top;
        tippe_dynamics_model m = {.top = *top, .g = 9.81, .mu = 0.1};
        const double W = sqrt(9.81 / top->R);
        for (int i = 0; i < 400; i++) {
            tippe_dynamics_initial ic = {gsl_rng_uniform(r) * M_PI,
                                         (gsl_rng_uniform(r) - 0.5) * 4 * W,
                                         (gsl_rng_uniform(r) - 0.5) * 20 * W,
                                         (gsl_rng_uniform(r) - 0.5) * 100 * W,
                                         (gsl_rng_uniform(r) - 0.5) * W * top->R,
                                         (gsl_rng_uniform(r) - 0.5) * W * top->R};
            if (i % 4 == 0)
                ic.theta = i % 8 == 0 ? 0.0 : M_PI;
            tippe_dynamics_sample s;
            if (tippe_dynamics_evaluate(&m, &ic, &s, NULL) != TIPPE_OK)
                continue;
            n++;
            const double V = tippe_theory_potential(top, 9.81, s.J, s.theta);
            /* rounding of the sums: 1e-12 of the energy */
            if (!(s.E >= V - 1e-12 * fabs(s.E)))
                below++;
            /* the minimiser at this theta and J */
            const double x = cos(ic.theta), sn = sin(ic.theta);
            const double D = top->A * top->R * top->R * sn * sn +
                             top->C * (top->R * x - top->eps) * (top->R * x - top->eps);
            const double a = s.J * top->R * sn / D, spin = s.J * (top->R * x - top->eps) / D;
            if (sn > 1e-3) {
                tippe_dynamics_initial mn = {ic.theta, 0.0, a / sn, spin, 0.0, 0.0};
                tippe_dynamics_sample sm;
                tippe_dynamics_evaluate(&m, &mn, &sm, NULL);
                const double rel = fabs(sm.E - V) / V;
                if (rel > worst_eq)
                    worst_eq = rel;
                if (rel > 1e-12)
                    eq_bad++;
            }
        }
    }
    CHECK(n > 2000, "only %d states evaluated", n);
    CHECK(below == 0, "%d of %d states have E < V", below, n);
    CHECK(eq_bad == 0, "%d minimisers have E != V (worst %g)", eq_bad, worst_eq);
    gsl_rng_free(r);
}

static int has_crit(const tippe_theory_wells *w, double theta, double tol)
{
    for (int i = 0; i < w->n_crit; i++)
        if (fabs(w->crit_theta_rad[i] - theta) <= tol)
            return 1;
    return 0;
}

/* Critical points are the steady states: the poles and every point of the curve
 * of eq 5.10 for that J (tippe_theory_intermediate gives J at theta). */
static void test_critical_points_are_steady_states(void)
{
    int missing = 0, tried = 0;
    for (int t = 0; t < N_TOPS; t++) {
        const tippe_top *top = &tops[t].top;
        for (double th = 0.013; th < M_PI; th += 0.0517) {
            tippe_theory_state st;
            if (tippe_theory_intermediate(top, 9.81, th, 1, &st, NULL) != TIPPE_OK)
                continue;
            tippe_theory_wells w;
            CHECK(tippe_theory_find_wells(top, 9.81, st.J, &w, NULL) == TIPPE_OK, "wells");
            tried++;
            /* a simple root in x at ~1e-16 relative; theta loses at most 1/sin(theta) */
            if (!has_crit(&w, th, 1e-9)) {
                missing++;
                if (missing < 4)
                    printf("  %s: theta %g not among %d critical points\n", tops[t].why, th,
                           w.n_crit);
            }
            CHECK(w.crit_theta_rad[0] == 0.0 && w.crit_theta_rad[w.n_crit - 1] == M_PI,
                  "poles are critical");
        }
    }
    CHECK(tried > 100 && missing == 0, "%d of %d curve points missed", missing, tried);
}

/* Completeness: every sign change of dV/dtheta on a fine scan lies within one scan
 * step of a critical point found, and the number of sign changes matches. */
static void test_complete(void)
{
    int bad = 0, cases = 0;
    for (int t = 0; t < N_TOPS; t++) {
        const tippe_top *top = &tops[t].top;
        const double Jn = top->C * top->R * sqrt(9.81 / top->R);
        for (double jr = 0.01; jr < 30.0; jr *= 1.37) {
            const double J = jr * Jn;
            tippe_theory_wells w;
            tippe_theory_find_wells(top, 9.81, J, &w, NULL);
            const int N = 20000;
            int changes = 0, interior_simple = 0;
            double prev = tippe_theory_potential_slope(top, 9.81, J, M_PI / N);
            for (int i = 2; i < N; i++) {
                const double th = M_PI * i / N;
                const double s = tippe_theory_potential_slope(top, 9.81, J, th);
                if ((s < 0) != (prev < 0)) {
                    changes++;
                    if (!has_crit(&w, th, 2 * M_PI / N))
                        bad++;
                }
                prev = s;
            }
            for (int i = 0; i < w.n_crit; i++)
                if (w.crit_kind[i] != 0 && w.crit_theta_rad[i] > M_PI / N &&
                    w.crit_theta_rad[i] < M_PI - M_PI / N)
                    interior_simple++;
            if (changes != interior_simple)
                bad++;
            cases++;
        }
    }
    CHECK(cases > 50 && bad == 0, "%d mismatches in %d cases", bad, cases);
}

/* Minima are Theorem 5.1's stable states (tippe_theory_predict): same kinds, same
 * angles to 1e-9 rad (both solve eq 5.10; theory.c with Brent in theta to 1e-14). */
static void test_minima_are_stable_states(void)
{
    int bad = 0, cases = 0;
    for (int t = 0; t < N_TOPS; t++) {
        const tippe_top *top = &tops[t].top;
        const double Jn = top->C * top->R * sqrt(9.81 / top->R);
        for (double jr = 0.0113; jr < 40.0; jr *= 1.21) {
            const double J = jr * Jn;
            tippe_theory_prediction p;
            tippe_theory_wells w;
            if (tippe_theory_predict(top, 9.81, J, &p, NULL) != TIPPE_OK)
                continue;
            tippe_theory_find_wells(top, 9.81, J, &w, NULL);
            cases++;
            int ok = w.n_wells == p.n;
            for (int i = 0; ok && i < p.n; i++) {
                ok = !w.well[i].flat && fabs(w.well[i].theta_min_rad - p.state[i].theta_rad) < 1e-9;
                const tippe_final_kind k = w.well[i].theta_min_rad == 0.0    ? TIPPE_FINAL_NO_TIP
                                           : w.well[i].theta_min_rad == M_PI ? TIPPE_FINAL_TIP
                                                                              : TIPPE_FINAL_HANG;
                ok = ok && k == p.state[i].kind;
            }
            if (!ok) {
                bad++;
                if (bad < 5) {
                    printf("  %s J/Jn %g: predicted %d, wells %d:", tops[t].why, jr, p.n,
                           w.n_wells);
                    for (int i = 0; i < w.n_wells; i++)
                        printf(" [%g flat %d]", w.well[i].theta_min_rad, w.well[i].flat);
                    for (int i = 0; i < p.n; i++)
                        printf(" (%s %g)", tippe_final_kind_name(p.state[i].kind),
                               p.state[i].theta_rad);
                    printf("\n");
                }
            }
            /* each well's escape level is above its minimum */
            for (int i = 0; i < w.n_wells; i++)
                if (!(w.well[i].V_escape > w.well[i].V_min))
                    bad++;
        }
    }
    CHECK(cases > 100 && bad == 0, "%d of %d J values disagree with Theorem 5.1", bad, cases);
}

/* A degenerate minimum: J with |n0| = n- exactly (A.14) makes theta = 0 a quartic
 * minimum, which must be reported flat; slightly off it the well is not flat. */
static void test_flat(void)
{
    tippe_top top = unit_top(0.92, 0.3);
    tippe_theory_thresholds th;
    tippe_theory_compute_thresholds(&top, 1.0, &th, NULL);
    tippe_theory_wells w;
    tippe_theory_find_wells(&top, 1.0, th.J_minus, &w, NULL);
    /* the minimum is a double root there: its angle is only good to sqrt(1e-16) */
    CHECK(w.n_wells >= 1 && w.well[0].theta_min_rad < 1e-6 && w.well[0].flat,
          "J = J- : theta 0 well flat (%d wells, min %g, flat %d)", w.n_wells,
          w.well[0].theta_min_rad, w.well[0].flat);
    tippe_theory_find_wells(&top, 1.0, 0.9 * th.J_minus, &w, NULL);
    CHECK(w.n_wells == 1 && !w.well[0].flat && w.well[0].theta_min_rad == 0.0,
          "J = 0.9 J- : one sharp well at 0");
    /* a balanced ball with J = 0 is neutral */
    tippe_top ball = unit_top(0.8, 0.0);
    tippe_theory_find_wells(&ball, 1.0, 0.0, &w, NULL);
    CHECK(w.n_wells >= 1 && w.well[0].flat, "neutral ball flat");
}

/* The range where V <= E ends where V = E (to the bisection's 1e-14 rad). */
static void test_range(void)
{
    tippe_top top = unit_top(0.92, 0.3);
    tippe_theory_state st;
    tippe_theory_intermediate(&top, 1.0, 1.6, 1, &st, NULL);
    tippe_theory_wells w;
    tippe_theory_find_wells(&top, 1.0, st.J, &w, NULL);
    const int i = tippe_theory_well_index(&w, 1.6);
    CHECK(w.n_wells == 1 && fabs(w.well[i].theta_min_rad - 1.6) < 1e-9, "one hang well");
    const double E = w.well[i].V_min + 1e-3;
    double lo, hi;
    tippe_theory_well_range(&top, 1.0, &w, i, E, &lo, &hi);
    const double slope = fabs(tippe_theory_potential_slope(&top, 1.0, st.J, lo)) + 1e-300;
    CHECK(lo < 1.6 && hi > 1.6, "range [%g, %g] around 1.6", lo, hi);
    CHECK(fabs(tippe_theory_potential(&top, 1.0, st.J, lo) - E) < 1e-13 * E + 2e-14 * slope,
          "V(lo) = E");
    CHECK(fabs(tippe_theory_potential(&top, 1.0, st.J, hi) - E) < 1e-13 * E + 2e-14 * slope,
          "V(hi) = E");
}

int main(void)
{
    test_energy_bound();
    test_critical_points_are_steady_states();
    test_complete();
    test_minima_are_stable_states();
    test_flat();
    test_range();
    return check_summary("test_potential");
}
