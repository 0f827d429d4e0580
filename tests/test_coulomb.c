/* Coulomb friction (issue 21): the energy balance dE/dt = -mu_c Rn |V_Q| while sliding,
 * Jellett's J, the viscous limit of the regularised law, the stick (rolling) phase
 * against the creep law's limit, convergence of reported times in the regularisation
 * speed v_s, Pliskin's spin dependence, and Cohen's (1977) launch. docs/dynamics.md,
 * "Coulomb friction", gives the figures these reproduce. */
#include "check.h"
#include "dynamics_fixtures.h"
#include "tippe/launch.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Cohen's (1977) top, his friction mu_c = 0.3 under law (v_s = vs). */
static tippe_dynamics_model cohen(tippe_friction_law law, double vs)
{
    return friction_model(cohen_ball(0.005), 0.0, law, 0.3, vs);
}

/* The M12 ball, mu = 2.3 s/m (viscous) or mu_c = 0.3 under law (v_s = vs). */
static tippe_dynamics_model m12(tippe_friction_law law, double vs)
{
    return friction_model(m12_ball(1.0), 2.3, law, 0.3, vs);
}

/* To t_end at the default accuracy, on past a tip verdict to the flip (t_flip). */
static int run_flip(const tippe_dynamics_model *md, const tippe_dynamics_initial *ic,
                    double t_end, tippe_dynamics_result *r)
{
    tippe_dynamics_options o = run_options(t_end, NULL, NULL, 0.0);
    o.until_flip = 1;
    return run_with(md, ic, o, r);
}

/* dE/dt = -mu_c Rn |V_Q| at every sample of a sliding flip (the M12 ball at 300 rad/s
 * slides all the way over), from central differences of E, and J conserved. */
static void test_energy_balance(void)
{
    tippe_dynamics_model md = m12(TIPPE_FRICTION_COULOMB, 1e-4);
    tippe_dynamics_initial ic = m12_launch(&md, 300.0);
    sample_buf b = {0, 0, NULL};
    tippe_dynamics_result r;
    const double dt = 2e-5;
    CHECK(run_samples(&md, &ic, 1.6, dt, NULL, &b, &r) == TIPPE_OK, "run");
    CHECK(r.stick_events == 0, "slides throughout: %ld stick events", r.stick_events);
    double worst = 0.0, slip_min = INFINITY;
    int crossed = 0;
    for (int i = 1; i + 1 < b.n; i++) {
        const tippe_dynamics_sample *s = &b.s[i];
        const double dEdt = (b.s[i + 1].E - b.s[i - 1].E) / (2.0 * dt);
        const double coulomb = -md.mu_c * s->Rn * s->slip_speed;
        worst = fmax(worst, fabs(dEdt - coulomb) / fabs(coulomb));
        slip_min = fmin(slip_min, s->slip_speed);
        crossed |= s->theta > 0.5 * M_PI;
    }
    printf("  energy balance: worst |dE/dt + mu_c Rn |V_Q|| / (mu_c Rn |V_Q|) = %.2g over %d "
           "samples, least slip %.3g m/s, J drift %.2g\n", worst, b.n, slip_min,
           r.jellett_rel_drift);
    CHECK(crossed && b.n > 40000, "flipped in %d samples", b.n);
    /* Central differences err by dt^2/6 |E'''| ~ (2e-5)^2 (300 rad/s)^2 / 6 = 6e-6 of
     * the power (E' varies at the spin rate), the law's regularisation by
     * v_s^2 / 2|V_Q|^2 < 3e-6 (|V_Q| > 0.04 m/s here); measured 2.2e-6. */
    CHECK(worst < 1e-4, "dE/dt against -mu_c Rn |V_Q|: worst relative difference %g "
                        "(least slip %g m/s)", worst, slip_min);
    CHECK(slip_min > 1e-2, "least slip %g m/s", slip_min);
    /* rk8pd at 1e-9: J and E + D conserved to ~1e-9 (as the viscous runs) */
    CHECK(r.jellett_rel_drift < 1e-8, "Jellett drift %g", r.jellett_rel_drift);
    CHECK(r.energy_rel_error < 1e-8, "energy balance %g", r.energy_rel_error);
    CHECK(r.energy_max_rise < 1e-12 * r.E0, "E rose by %g J", r.energy_max_rise);
    free(b.s);
}

/* The regularised law at slips far below v_s is viscous with mu = mu_c / v_s: Cohen's
 * top at mu = 3 s/m (slip <= 0.25 m/s) against mu_c = 300, v_s = 100 m/s, where they
 * differ by |V_Q|^2 / 2 v_s^2 <= 3.1e-6 relative. */
static void test_viscous_limit(void)
{
    tippe_dynamics_model vis = cohen(TIPPE_FRICTION_VISCOUS, 0.0);
    vis.mu = 3.0;
    tippe_dynamics_model reg = cohen(TIPPE_FRICTION_COULOMB_CREEP, 100.0);
    reg.mu_c = 300.0;
    const tippe_dynamics_initial ic = {0.1, 0, 0, 100.0, 0, 0};
    tippe_dynamics_result a, b;
    CHECK(run_flip(&vis, &ic, 10.0, &a) == TIPPE_OK && run_flip(&reg, &ic, 10.0, &b) == TIPPE_OK,
          "runs");
    CHECK(a.verdict == TIPPE_VERDICT_TIP && b.verdict == TIPPE_VERDICT_TIP, "%s, %s",
          tippe_verdict_name(a.verdict), tippe_verdict_name(b.verdict));
    /* a 3e-6 relative change of the friction moves a 0.67 s flip by ~2e-6 s; the
     * integrations at rtol 1e-9 agree far better than that */
    printf("  viscous limit: flip %.9f s (viscous mu 3 s/m), %.9f s (mu_c 300, v_s 100 m/s)\n",
           a.t_flip, b.t_flip);
    CHECK(fabs(a.t_flip - b.t_flip) < 1e-5, "flip %.9f (viscous) vs %.9f (regularised)",
          a.t_flip, b.t_flip);
    /* and a 10x smaller v_s moves it measurably (the test can fail) */
    reg.slip_scale_m_s = 1.0;
    reg.mu_c = 3.0;
    CHECK(run_flip(&reg, &ic, 10.0, &b) == TIPPE_OK, "run");
    CHECK(!(fabs(a.t_flip - b.t_flip) < 1e-5), "v_s = 1 m/s is not viscous: %.9f vs %.9f",
          a.t_flip, b.t_flip);
}

/* The sliding law in the Euler-angle reference form (3.15-3.19 with the regularised
 * Coulomb coefficient) against the lab-frame form, along a sliding flip. */
static void test_against_euler(void)
{
    tippe_dynamics_model md = m12(TIPPE_FRICTION_COULOMB_CREEP, 1e-4);
    const tippe_dynamics_initial ic = {1.0, 0.0, 20.0, 300.0, 0.05, -0.02};
    sample_buf b = {0, 0, NULL};
    tippe_dynamics_result r;
    CHECK(run_samples(&md, &ic, 0.5, 0.01, NULL, &b, &r) == TIPPE_OK, "run");
    gsl_odeiv2_system sys = {euler_sys, NULL, TIPPE_EULER_DIM, &md};
    gsl_odeiv2_driver *d =
        gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-6, 1e-12, 1e-12);
    double y[TIPPE_EULER_DIM] = {ic.theta, ic.theta_dot, ic.phi_dot, ic.spin, ic.U, ic.V, 0, 0};
    double t = 0.0, worst = 0.0, th_lo = 10, th_hi = -10;
    int bad = 0;
    for (int i = 0; i < b.n; i++) {
        const tippe_dynamics_sample *s = &b.s[i];
        if (s->t > t && gsl_odeiv2_driver_apply(d, &t, s->t, y) != GSL_SUCCESS) {
            bad = 1;
            break;
        }
        /* relative to the scales: rad, spin 300 rad/s, speeds 1 m/s */
        const double diff[6] = {s->theta - y[0], (s->theta_dot - y[1]) / 300,
                                (s->phi_dot - y[2]) / 300, (s->spin - y[3]) / 300,
                                s->U - y[4], s->V - y[5]};
        for (int k = 0; k < 6; k++)
            worst = fmax(worst, fabs(diff[k]));
        th_lo = fmin(th_lo, y[0]);
        th_hi = fmax(th_hi, y[0]);
    }
    gsl_odeiv2_driver_free(d);
    CHECK(!bad && b.n == 51, "Euler reference integration (%d samples)", b.n);
    CHECK(th_lo > 0.3 && th_hi < M_PI - 0.3, "away from the poles: %g..%g", th_lo, th_hi);
    /* the lab form at rtol 1e-9 over ~150 turns: global error ~1e-7 of the scales;
     * a wrong friction term is O(1e-2) */
    printf("  Euler form: largest scaled difference %.2g\n", worst);
    CHECK(worst < 1e-6, "largest scaled difference %g", worst);
    free(b.s);
}

/* Rolling without slipping (the stick phase) is the limit of the creep law as
 * v_s -> 0: Cohen's launch sticks within 0.03 s; theta at 0.3 s under the creep law
 * approaches the rolling one linearly in v_s (an independent check of the rolling
 * equations, which the creep law does not use). */
static void test_stick_limit(void)
{
    const tippe_dynamics_initial ic = {0.1, 0, 0, 100.0, 0, 0};
    double th[3];
    const double vs[2] = {1e-4, 1e-5};
    for (int i = 0; i < 3; i++) {
        tippe_dynamics_model md = i == 0 ? cohen(TIPPE_FRICTION_COULOMB, 1e-4)
                                         : cohen(TIPPE_FRICTION_COULOMB_CREEP, vs[i - 1]);
        sample_buf b = {0, 0, NULL};
        tippe_dynamics_result r;
        CHECK(run_samples(&md, &ic, 0.3, 0.3, NULL, &b, &r) == TIPPE_OK, "run %d", i);
        th[i] = b.n ? b.s[b.n - 1].theta : NAN;
        if (i == 0)
            CHECK(r.stick_events == 1 && r.slip_events == 0 && r.rolling_time_s > 0.26,
                  "sticks once and rolls: %ld, %ld, %g s", r.stick_events, r.slip_events,
                  r.rolling_time_s);
        free(b.s);
    }
    const double d1 = fabs(th[1] - th[0]), d2 = fabs(th[2] - th[0]);
    printf("  stick limit: theta(0.3 s) rolling %.8f, creep %.8f (v_s 1e-4), %.8f (1e-5)\n",
           th[0], th[1], th[2]);
    /* measured: 1.9e-4 and 1.0e-5 rad; linear convergence means a ratio near 10 */
    CHECK(d2 < 5e-5 && d1 / d2 > 5 && d1 / d2 < 40,
          "theta(0.3 s): rolling %.8f, creep %.8f (v_s 1e-4), %.8f (1e-5)", th[0], th[1],
          th[2]);
}

/* Cohen's launch (spin 100 rad/s about the axis, theta0 = 0.1, the centre of mass at
 * rest). Cohen's figure has theta = pi/2 at ~0.94 s; here the slip vanishes within
 * 0.03 s, the top rolls and the rolling force stays inside the cone: no flip. A
 * second, independent run to 20 s confirms it never slips again and theta stays in
 * the range the decision claimed. */
static void test_cohen(void)
{
    tippe_dynamics_model md = cohen(TIPPE_FRICTION_COULOMB, 0.0);
    const tippe_dynamics_initial ic = {0.1, 0, 0, 100.0, 0, 0};
    tippe_dynamics_result r;
    CHECK(run_flip(&md, &ic, 100.0, &r) == TIPPE_OK, "run");
    printf("  Cohen 1977 launch: %s (decided by %s at %.4f s), theta in [%.4f, %.4f] rad, "
           "flip %g s (Cohen ~0.94 s)\n",
           tippe_verdict_name(r.verdict), tippe_decision_name(r.how), r.t_verdict,
           r.theta_lo_rad, r.theta_hi_rad, r.t_flip);
    CHECK(r.how == TIPPE_DECIDED_ROLLING && r.verdict == TIPPE_VERDICT_NO_TIP && isnan(r.t_flip),
          "%s by %s", tippe_verdict_name(r.verdict), tippe_decision_name(r.how));
    CHECK(r.rolling && !r.end_state_proved, "rolling, end state not claimed");
    sample_buf b = {0, 0, NULL};
    tippe_dynamics_result r2;
    CHECK(run_samples(&md, &ic, 20.0, 0.0, NULL, &b, &r2) == TIPPE_OK, "long run");
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < b.n; i++)
        if (b.s[i].t > r.t_verdict) {
            lo = fmin(lo, b.s[i].theta);
            hi = fmax(hi, b.s[i].theta);
        }
    CHECK(r2.slip_events == 0 && r2.stick_events == 1, "20 s: %ld slips", r2.slip_events);
    /* the claimed range holds the whole later motion (steps sample it: 1e-6 rad slack) */
    CHECK(lo >= r.theta_lo_rad - 1e-6 && hi <= r.theta_hi_rad + 1e-6,
          "20 s: theta in [%.6f, %.6f], claimed [%.6f, %.6f]", lo, hi, r.theta_lo_rad,
          r.theta_hi_rad);
    /* rolling dissipates nothing: E constant after sticking, to the integration error */
    CHECK(fabs(b.s[b.n - 1].E - r.final.E) < 1e-9 * r.E0, "E changed by %g J while rolling",
          b.s[b.n - 1].E - r.final.E);
    free(b.s);
    /* the creep law (no sticking) rises on the creep's time scale, ~1/v_s */
    tippe_dynamics_model cr = cohen(TIPPE_FRICTION_COULOMB_CREEP, 1e-2);
    tippe_dynamics_result c1, c2;
    CHECK(run_flip(&cr, &ic, 100.0, &c1) == TIPPE_OK, "creep run");
    cr.slip_scale_m_s = 1e-3;
    CHECK(run_flip(&cr, &ic, 100.0, &c2) == TIPPE_OK, "creep run");
    /* measured 1.14 s and 5.26 s */
    CHECK(c2.t_flip > 3.0 * c1.t_flip, "creep flips at %g s (v_s 1e-2), %g s (1e-3)", c1.t_flip,
          c2.t_flip);
}

/* Reported times converge as v_s -> 0 (to 1e-4 s) and the flip time grows in
 * proportion to the spin (Pliskin: theta_dot ~ mu_c m g R / (C n)); under viscous
 * friction it does not grow. */
static void test_spin_and_convergence(void)
{
    double tf[2][2];
    const double spins[2] = {200.0, 400.0};
    for (int i = 0; i < 2; i++) {
        const double vs[2] = {1e-4, 1e-5};
        for (int j = 0; j < 2; j++) {
            tippe_dynamics_model md = m12(TIPPE_FRICTION_COULOMB, vs[j]);
            tippe_dynamics_initial ic = m12_launch(&md, spins[i]);
            tippe_dynamics_result r;
            CHECK(run_flip(&md, &ic, 60.0, &r) == TIPPE_OK, "run");
            tf[i][j] = r.t_flip;
        }
        printf("  spin %g rad/s: flip %.7f s (v_s 1e-4), %.7f s (1e-5)\n", spins[i], tf[i][0],
               tf[i][1]);
        CHECK(fabs(tf[i][0] - tf[i][1]) < 1e-4, "spin %g: flip %.6f (v_s 1e-4) vs %.6f (1e-5)",
              spins[i], tf[i][0], tf[i][1]);
    }
    const double ratio = tf[1][0] / tf[0][0];
    /* measured 1.91: linear in n up to the launch's own slide-in */
    CHECK(ratio > 1.6 && ratio < 2.4, "Coulomb: flip(400)/flip(200) = %g", ratio);
    tippe_dynamics_result a, b;
    tippe_dynamics_model vis = m12(TIPPE_FRICTION_VISCOUS, 0.0);
    tippe_dynamics_initial i1 = m12_launch(&vis, 200.0), i2 = m12_launch(&vis, 400.0);
    CHECK(run_flip(&vis, &i1, 60.0, &a) == TIPPE_OK && run_flip(&vis, &i2, 60.0, &b) == TIPPE_OK,
          "runs");
    CHECK(b.t_flip / a.t_flip < 1.0, "viscous: flip(400)/flip(200) = %g", b.t_flip / a.t_flip);
}

/* Every rolling decision among 40 hand launches of the M12 ball (tippe_launch_draw, seed 1)
 * holds when integrated on to 10 s: no break-away, theta within the claimed range. */
static void test_rolling_claims(void)
{
    tippe_launch_options lo;
    tippe_launch_options_default(&lo);
    const tippe_dynamics_model md = m12(TIPPE_FRICTION_COULOMB, 0.0);
    int n_rolling = 0;
    for (int draw = 0; draw < 40; draw++) {
        tippe_dynamics_initial ic;
        tippe_error e;
        if (tippe_launch_draw(&md.top, &lo, 1, (uint64_t)draw, NAN, &ic, &e)) {
            CHECK(0, "draw %d: %s", draw, e.msg);
            continue;
        }
        tippe_dynamics_result r;
        CHECK(run(&md, &ic, 600.0, NULL, &r) == TIPPE_OK, "draw %d", draw);
        if (r.how != TIPPE_DECIDED_ROLLING)
            continue;
        n_rolling++;
        sample_buf b = {0, 0, NULL};
        tippe_dynamics_result r2;
        CHECK(run_samples(&md, &ic, 10.0, 0.0, NULL, &b, &r2) == TIPPE_OK, "draw %d on", draw);
        double th_lo = INFINITY, th_hi = -INFINITY;
        for (int i = 0; i < b.n; i++)
            if (b.s[i].t > r.t_verdict) {
                th_lo = fmin(th_lo, b.s[i].theta);
                th_hi = fmax(th_hi, b.s[i].theta);
            }
        /* the claim is for the exact rolling motion; steps sample theta: 1e-6 rad slack */
        CHECK(r2.slip_events == 0 && th_lo >= r.theta_lo_rad - 1e-6 &&
                  th_hi <= r.theta_hi_rad + 1e-6,
              "draw %d: %ld slips; theta [%.6f, %.6f] against the claimed [%.6f, %.6f]", draw,
              r2.slip_events, th_lo, th_hi, r.theta_lo_rad, r.theta_hi_rad);
        free(b.s);
    }
    printf("  rolling claims: %d of 40 hand launches decided rolling, each held to 10 s\n",
           n_rolling);
    CHECK(n_rolling >= 10, "%d rolling decisions", n_rolling);
}

/* Stick-slip: Cohen's sphere launched rolling (V_Q = 0) with a strong nutation at
 * mu_c = 0.1 breaks loose and sticks again every nutation period. The break-away
 * (bisected on |F| = mu_c Rn) and the re-sticking are checked against the creep law,
 * which knows neither: theta at 2 s agrees as v_s -> 0. */
static void test_stick_slip(void)
{
    const double R = 0.025, eps = 0.005, th = 0.3, thd = 20.0, n = 10.0;
    const double h = R - eps * cos(th);
    const tippe_dynamics_initial ic = {th, thd, 0, n, thd * h, -sin(th) * R * n};
    double theta[2];
    long sticks = 0, slips = 0;
    for (int i = 0; i < 2; i++) {
        tippe_dynamics_model md = i == 0 ? cohen(TIPPE_FRICTION_COULOMB, 1e-6)
                                         : cohen(TIPPE_FRICTION_COULOMB_CREEP, 1e-5);
        md.mu_c = 0.1;
        sample_buf b = {0, 0, NULL};
        tippe_dynamics_result r;
        CHECK(run_samples(&md, &ic, 2.0, 2.0, NULL, &b, &r) == TIPPE_OK, "run %d", i);
        theta[i] = b.n ? b.s[b.n - 1].theta : NAN;
        if (i == 0) {
            sticks = r.stick_events;
            slips = r.slip_events;
            CHECK(r.energy_max_rise < 1e-10 * r.E0, "E rose by %g J", r.energy_max_rise);
            CHECK(r.jellett_rel_drift < 1e-8, "Jellett drift %g", r.jellett_rel_drift);
        }
        free(b.s);
    }
    printf("  stick-slip: %ld sticks, %ld breaks in 2 s; theta(2 s) %.8f (sticking, v_s 1e-6), "
           "%.8f (creep, 1e-5)\n", sticks, slips, theta[0], theta[1]);
    /* measured 8 and 7; without the margin for sticking again the contact stuck again at
     * once where it broke loose (343 breaks in 100 s instead of 100) */
    CHECK(sticks >= 5 && slips >= 5 && slips <= 10, "%ld sticks, %ld breaks", sticks, slips);
    /* measured 6e-5 rad; the creep law at 1e-4 m/s is 9e-4 away */
    CHECK(fabs(theta[0] - theta[1]) < 3e-4, "theta(2 s): %.8f vs %.8f", theta[0], theta[1]);
}

static void test_names_and_input(void)
{
    CHECK(tippe_friction_law_parse("coulomb") == TIPPE_FRICTION_COULOMB, "parse");
    CHECK(tippe_friction_law_parse("viscous") == TIPPE_FRICTION_VISCOUS, "parse");
    CHECK(tippe_friction_law_parse("coulomb-creep") == TIPPE_FRICTION_COULOMB_CREEP, "parse");
    CHECK(tippe_friction_law_parse("Coulomb") == -1, "case-sensitive");
    CHECK(!strcmp(tippe_friction_law_name(TIPPE_FRICTION_COULOMB), "coulomb"), "name");
    tippe_dynamics_model md = cohen(TIPPE_FRICTION_COULOMB, 0.0);
    md.mu_c = -0.1;
    const tippe_dynamics_initial ic = {0.1, 0, 0, 100.0, 0, 0};
    tippe_dynamics_result r;
    tippe_dynamics_options o;
    tippe_dynamics_options_default(&o);
    tippe_error e;
    CHECK(tippe_dynamics_run(&md, &ic, &o, &r, &e) == TIPPE_EINPUT && strstr(e.msg, "mu_c"),
          "negative mu_c refused");
    md.mu_c = 0.0;
    CHECK(tippe_dynamics_frictionless(&md), "mu_c = 0 is frictionless");
}

int main(void)
{
    test_names_and_input();
    test_energy_balance();
    test_viscous_limit();
    test_against_euler();
    test_stick_limit();
    test_cohen();
    test_spin_and_convergence();
    test_rolling_claims();
    test_stick_slip();
    return check_summary("test_coulomb");
}
