/* Tests of hand launches (tippe/physics.h) and the progress bar (tippe/base.h):
 * Wilson intervals against their closed forms, the per-launch generators and the
 * launch distributions, bit-identical runs on 1 and 2 OpenMP threads, tallies,
 * the central launch, and outcomes that Theorem 5.1 forbids. */
#include "tippe/design.h"
#include "tippe/launch.h"
#include "tippe/base.h"

#include "check.h"

#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const double Z = TIPPE_LAUNCH_Z95;

static void test_wilson(void)
{
    const long ns[] = {1, 2, 5, 10, 50, 1000, 100000};
    for (int i = 0; i < (int)(sizeof ns / sizeof ns[0]); i++) {
        long n = ns[i];
        double lo, hi;
        /* 0 of n: [0, z^2/(n + z^2)]; n of n: [n/(n + z^2), 1] (the Wilson
         * formula with p = 0 or 1). A few ulps of rounding: 1e-14 relative. */
        tippe_launch_wilson(0, n, Z, &lo, &hi);
        double closed = Z * Z / ((double)n + Z * Z);
        CHECK(lo == 0.0, "0 of %ld: lo = %.17g", n, lo);
        CHECK(fabs(hi - closed) <= 1e-14 * closed, "0 of %ld: hi = %.17g, closed form %.17g", n,
              hi, closed);
        tippe_launch_wilson(n, n, Z, &lo, &hi);
        closed = (double)n / ((double)n + Z * Z);
        CHECK(hi == 1.0, "%ld of %ld: hi = %.17g", n, n, hi);
        CHECK(fabs(lo - closed) <= 1e-14 * closed, "%ld of %ld: lo = %.17g, closed form %.17g", n,
              n, lo, closed);
        /* The interval for k is the mirror of the one for n - k: rounding only. */
        for (long k = 0; k <= n && k <= 7; k++) {
            double l1, h1, l2, h2;
            tippe_launch_wilson(k, n, Z, &l1, &h1);
            tippe_launch_wilson(n - k, n, Z, &l2, &h2);
            CHECK(fabs(l1 - (1.0 - h2)) < 1e-14 && fabs(h1 - (1.0 - l2)) < 1e-14,
                  "k = %ld, n = %ld: [%g, %g] vs mirror [%g, %g]", k, n, l1, h1, 1 - h2, 1 - l2);
            CHECK(l1 <= (double)k / n && (double)k / n <= h1, "k/n outside its own interval");
        }
    }
    /* Published values: Newcombe (1998), Statistics in Medicine 17, 857-872, method
     * 3 (Wilson score) on his examples; 4 decimals there, so 5e-5 here. */
    const struct {
        long k, n;
        double lo, hi;
    } pub[] = {{81, 263, 0.2553, 0.3662}, {15, 148, 0.0624, 0.1605}, {0, 20, 0.0, 0.1611},
               {1, 29, 0.0061, 0.1718}};
    double lo, hi;
    for (int i = 0; i < 4; i++) {
        tippe_launch_wilson(pub[i].k, pub[i].n, Z, &lo, &hi);
        CHECK(fabs(lo - pub[i].lo) < 5e-5 && fabs(hi - pub[i].hi) < 5e-5,
              "%ld of %ld: [%.5f, %.5f], published [%.4f, %.4f]", pub[i].k, pub[i].n, lo, hi,
              pub[i].lo, pub[i].hi);
    }
    tippe_launch_wilson(0, 0, Z, &lo, &hi);
    CHECK(lo == 0.0 && hi == 1.0, "0 of 0 must be the whole [0, 1]");
}

static int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : x > y;
}

static void test_mix(void)
{
    CHECK(tippe_launch_mix(1, 0) == tippe_launch_mix(1, 0), "mix is not a function");
    CHECK(tippe_launch_mix(1, 0) != tippe_launch_mix(2, 0), "seeds 1 and 2 give the same key");
    CHECK(tippe_launch_mix(1, 0) != tippe_launch_mix(1, 1), "draws 0 and 1 give the same key");
    /* 10^4 keys of 64 bits: a collision has probability ~3e-12 for a good mixer. */
    enum { N = 10000 };
    uint64_t *k = malloc(N * sizeof *k);
    for (int i = 0; i < N; i++)
        k[i] = tippe_launch_mix(12345, (uint64_t)i);
    qsort(k, N, sizeof *k, cmp_u64);
    int dup = 0;
    for (int i = 1; i < N; i++)
        dup += k[i] == k[i - 1];
    CHECK(dup == 0, "%d duplicate keys among %d draws", dup, N);
    /* Bits are balanced: each of the 64 bits is set in ~half of the keys; 5
     * binomial sigmas (50) around 5000. */
    int worst = 0;
    for (int b = 0; b < 64; b++) {
        int ones = 0;
        for (int i = 0; i < N; i++)
            ones += (int)((k[i] >> b) & 1u);
        if (abs(ones - N / 2) > worst)
            worst = abs(ones - N / 2);
    }
    CHECK(worst < 250, "a key bit is set %d times away from half of %d", worst, N);
    free(k);
}

static tippe_top m12_top(double z2)
{
    tippe_design *d = NULL;
    tippe_error e;
    tippe_top t = {0};
    if (tippe_design_load("designs/m12-setscrew.json", NULL, 0, &d, &e) ||
        tippe_design_top(d, z2, &t, &e)) {
        printf("cannot load designs/m12-setscrew.json at Z2 = %g: %s\n", z2, e.msg);
        exit(1);
    }
    tippe_design_free(d);
    return t;
}

static void test_draws(void)
{
    const tippe_top top = m12_top(10.0);
    tippe_launch_options o;
    tippe_launch_options_default(&o);
    tippe_error e;
    CHECK(tippe_launch_options_check(&o, &e) == TIPPE_OK, "defaults rejected: %s", e.msg);

    enum { N = 4000 };
    double s_spin = 0, s_tilt = 0, s_u = 0, s_v = 0, s_r = 0, s_r2 = 0, s_slide = 0;
    double max_tilt = 0;
    int bad = 0;
    tippe_dynamics_model m = {.top = top, .g = o.g, .mu = o.mu};
    for (int i = 0; i < N; i++) {
        tippe_dynamics_initial ic;
        if (tippe_launch_draw(&top, &o, 7, (uint64_t)i, NAN, &ic, &e)) {
            bad++;
            continue;
        }
        double steady;
        tippe_dynamics_precession(&m, ic.theta, ic.spin, TIPPE_PRECESSION_STEADY, &steady, &e);
        double r = ic.phi_dot / steady;
        s_spin += ic.spin / (2 * M_PI);
        s_tilt += ic.theta;
        s_u += ic.U;
        s_v += ic.V;
        s_slide += hypot(ic.U, ic.V);
        s_r += r;
        s_r2 += r * r;
        if (ic.theta > max_tilt)
            max_tilt = ic.theta;
        if (ic.theta_dot != 0.0 || ic.spin < 2 * M_PI * o.spin_from_rev_s ||
            ic.spin > 2 * M_PI * o.spin_to_rev_s)
            bad++;
    }
    CHECK(bad == 0, "%d draws failed or left their ranges", bad);
    /* Sample means within 4 standard errors (a false alarm every ~16000 runs;
     * the seed is fixed, so the test is deterministic anyway). */
    const double se_spin = (o.spin_to_rev_s - o.spin_from_rev_s) / sqrt(12.0 * N);
    CHECK(fabs(s_spin / N - 0.5 * (o.spin_from_rev_s + o.spin_to_rev_s)) < 4 * se_spin,
          "mean spin %g rev/s", s_spin / N);
    /* half-normal: mean sd sqrt(2/pi), standard deviation sd sqrt(1 - 2/pi) */
    const double se_tilt = o.tilt_sd_rad * sqrt(1 - 2 / M_PI) / sqrt(N);
    CHECK(fabs(s_tilt / N - o.tilt_sd_rad * sqrt(2 / M_PI)) < 4 * se_tilt, "mean tilt %g rad",
          s_tilt / N);
    const double se_slide = o.slide_sd_m_s * sqrt(1 - 2 / M_PI) / sqrt(N);
    CHECK(fabs(s_slide / N - o.slide_sd_m_s * sqrt(2 / M_PI)) < 4 * se_slide,
          "mean sliding speed %g m/s", s_slide / N);
    /* a uniform direction: each component averages 0 (standard error sd/sqrt(2N)) */
    const double se_uv = o.slide_sd_m_s / sqrt(2.0 * N);
    CHECK(fabs(s_u / N) < 4 * se_uv && fabs(s_v / N) < 4 * se_uv, "mean U %g, V %g m/s",
          s_u / N, s_v / N);
    CHECK(max_tilt <= o.tilt_max_rad, "tilt %g above the largest %g", max_tilt, o.tilt_max_rad);
    /* precession factor 1 + sd N(0,1): mean 1 (se sd/sqrt N), sd 0.1 (se sd/sqrt(2N)) */
    const double mean_r = s_r / N, sd_r = sqrt(s_r2 / N - mean_r * mean_r);
    CHECK(fabs(mean_r - 1) < 4 * o.precession_sd_rel / sqrt(N), "precession factor mean %g",
          mean_r);
    CHECK(fabs(sd_r - o.precession_sd_rel) < 4 * o.precession_sd_rel / sqrt(2.0 * N),
          "precession factor sd %g", sd_r);

    /* A fixed spin changes the spin and, through the steady rate, phi_dot; the
     * other draws stay the same (common random numbers over a map). */
    tippe_dynamics_initial a, b, c;
    tippe_launch_draw(&top, &o, 99, 5, NAN, &a, &e);
    tippe_launch_draw(&top, &o, 99, 5, 123.0, &b, &e);
    tippe_launch_draw(&top, &o, 99, 5, NAN, &c, &e);
    CHECK(b.spin == 123.0 && a.theta == b.theta && a.U == b.U && a.V == b.V,
          "fixed spin changed other draws");
    CHECK(memcmp(&a, &c, sizeof a) == 0, "the same (seed, draw) gave two launches");

    tippe_launch_options bad_o = o;
    bad_o.tilt_max_rad = 1.6;
    CHECK(tippe_launch_options_check(&bad_o, &e) == TIPPE_EINPUT, "tilt max beyond pi/2 accepted");
    bad_o = o;
    bad_o.spin_from_rev_s = 30;
    CHECK(tippe_launch_options_check(&bad_o, &e) == TIPPE_EINPUT, "spin FROM > TO accepted");
}

/* The central launch has theta_ddot = 0 at the start (steady precession, eq
 * 3.15 with theta_dot = U = 0): checked with the paper's Euler-angle equations. */
static void test_central(void)
{
    const tippe_top top = m12_top(15.0);
    tippe_launch_options o;
    tippe_launch_options_default(&o);
    tippe_dynamics_initial ic;
    tippe_error e;
    CHECK(tippe_launch_central(&top, &o, 90.0, &ic, &e) == TIPPE_OK, "%s", e.msg);
    CHECK(fabs(ic.theta - 0.6744897501960817 * o.tilt_sd_rad) < 1e-15, "tilt %g", ic.theta);
    CHECK(ic.U == 0 && ic.V == 0 && ic.theta_dot == 0 && ic.spin == 90.0, "not central");
    tippe_dynamics_model m = {.top = top, .g = o.g, .mu = o.mu};
    double y[TIPPE_EULER_DIM] = {ic.theta, 0, ic.phi_dot, ic.spin, 0, 0, 0, 0}, dy[8], Rn;
    CHECK(tippe_dynamics_euler_rhs(&m, y, dy, &Rn) == TIPPE_OK, "euler rhs failed");
    /* Scale of the terms that cancel in A theta_ddot: C n phi_dot sin(theta). */
    const double scale = top.C * fabs(ic.spin * ic.phi_dot) * sin(ic.theta) / top.A;
    CHECK(fabs(dy[1]) < 1e-12 * scale, "theta_ddot = %g at a steady launch (scale %g)", dy[1],
          scale);
}

static int same_record(const tippe_launch_record *a, const tippe_launch_record *b)
{
    return a->index == b->index && a->draw == b->draw && a->status == b->status &&
           a->verdict == b->verdict && memcmp(&a->ic, &b->ic, sizeof a->ic) == 0 &&
           a->t_s == b->t_s && a->theta_final_rad == b->theta_final_rad &&
           a->J0 == b->J0 && a->jellett_rel_drift == b->jellett_rel_drift &&
           a->rhs_evals == b->rhs_evals && a->predicted == b->predicted &&
           a->agrees == b->agrees;
}

static void run_with_threads(const tippe_launch_plan *plan, const tippe_launch_options *o,
                             int threads, tippe_launch_record *rec)
{
    tippe_error e;
    omp_set_num_threads(threads);
    int rc = tippe_launch_run(plan, o, 2024, 0, tippe_launch_plan_total(plan), rec, NULL, &e);
    CHECK(rc == TIPPE_OK, "run on %d threads: %s", threads, e.msg);
}

static void test_threads_and_tally(void)
{
    tippe_top tops[2] = {m12_top(10.0), m12_top(15.0)};
    const double spins[2] = {2 * M_PI * 8.0, 2 * M_PI * 20.0};
    tippe_launch_options o;
    tippe_launch_options_default(&o);
    /* Short runs: this checks reproducibility, not physics. */
    tippe_dynamics_accuracy_preset("fast", &o.accuracy, NULL);
    o.t_end = 40.0;
    tippe_launch_plan plan = {2, 6, tops, spins, NULL};
    const long n = tippe_launch_plan_total(&plan);
    tippe_launch_record *r1 = calloc((size_t)n, sizeof *r1), *r2 = calloc((size_t)n, sizeof *r2);
    run_with_threads(&plan, &o, 1, r1);
    run_with_threads(&plan, &o, 2, r2);
    int diff = 0;
    for (long i = 0; i < n; i++)
        diff += !same_record(&r1[i], &r2[i]);
    CHECK(diff == 0, "%d of %ld launches differ between 1 and 2 threads", diff, n);
    /* A slice of a run equals the same launches in a whole run (what MPI ranks do). */
    tippe_launch_record part[3];
    tippe_error e;
    tippe_launch_run(&plan, &o, 2024, 7, 10, part, NULL, &e);
    CHECK(same_record(&part[0], &r1[7]) && same_record(&part[2], &r1[9]),
          "launches 7..9 differ when run alone");
    /* Groups see the same draws: launch 3 of group 0 and of group 1 share tilt. */
    CHECK(r1[3].ic.theta == r1[6 + 3].ic.theta && r1[3].draw == 3 && r1[9].draw == 3,
          "groups do not share draws");
    CHECK(r1[0].ic.spin == spins[0] && r1[6].ic.spin == spins[1], "group spins not applied");

    tippe_launch_tally t;
    CHECK(tippe_launch_tally_records(r1, n, &t, &e) == TIPPE_OK, "%s", e.msg);
    long sum = 0, pred = 0;
    for (int v = 0; v < TIPPE_LAUNCH_N_VERDICTS; v++)
        sum += t.counts[v];
    for (int m = 0; m < 8; m++)
        pred += t.predicted[m];
    CHECK(sum == n && t.n == n, "counts add to %ld of %ld", sum, n);
    CHECK(pred == n, "predictions add to %ld of %ld", pred, n);
    CHECK(t.agree <= t.comparable && t.comparable <= n, "agree %ld, comparable %ld", t.agree,
          t.comparable);
    free(r1);
    free(r2);
}

/* Outcomes Theorem 5.1 rules out, whatever the hand: in group Ia no state
 * 0 < theta < pi is stable, so no launch may end hanging; in group III theta = pi
 * is never stable, so no launch may end tipped. */
static void test_forbidden_outcomes(void)
{
    tippe_launch_options o;
    tippe_launch_options_default(&o);
    tippe_error e;
    const struct {
        double z2;
        tippe_group group;
        tippe_verdict forbidden;
    } cases[] = {{4.0, TIPPE_GROUP_IA, TIPPE_VERDICT_HANG}, {20.0, TIPPE_GROUP_III, TIPPE_VERDICT_TIP}};
    /* Theorem 5.1 is the sphere's: on the M12's rims J changes (issue 35) */
    o.sphere_contact_only = 1;
    for (int c = 0; c < 2; c++) {
        tippe_top top = m12_top(cases[c].z2);
        tippe_theory_class cls;
        tippe_theory_classify(top.A / top.C, top.eps / top.R, &cls);
        CHECK(cls.group == cases[c].group, "Z2 = %g mm is in %s, the test expects %s",
              cases[c].z2, tippe_group_name(cls.group), tippe_group_name(cases[c].group));
        tippe_launch_plan plan = {1, 6, &top, NULL, NULL};
        tippe_launch_record rec[6];
        CHECK(tippe_launch_run(&plan, &o, 5, 0, 6, rec, NULL, &e) == TIPPE_OK, "%s", e.msg);
        for (int i = 0; i < 6; i++) {
            CHECK(rec[i].verdict != cases[c].forbidden, "Z2 %g launch %d ends %s in group %s",
                  cases[c].z2, i, tippe_verdict_name(rec[i].verdict), tippe_group_name(cls.group));
            /* balanced preset: Jellett is conserved to ~1e-8 (docs/dynamics.md) */
            CHECK(rec[i].jellett_rel_drift < 1e-6, "Jellett drift %g", rec[i].jellett_rel_drift);
        }
    }
}

static void test_progress(void)
{
    CHECK(fabs(tippe_progress_eta_s(10.0, 25, 100) - 30.0) < 1e-12, "eta at a quarter");
    CHECK(tippe_progress_eta_s(10.0, 0, 100) < 0, "eta with nothing done");
    CHECK(tippe_progress_eta_s(10.0, 100, 100) == 0.0, "eta when done");
    char buf[32];
    CHECK(!strcmp(tippe_progress_format_duration(42.2, buf, sizeof buf), "42 s"), "%s", buf);
    CHECK(!strcmp(tippe_progress_format_duration(185, buf, sizeof buf), "3 min 05 s"), "%s", buf);
    CHECK(!strcmp(tippe_progress_format_duration(7620, buf, sizeof buf), "2 h 07 min"), "%s", buf);

    /* Forced on, on a file: plain lines (no bar redrawn with \r), the last at
     * 100% with the time spent. */
    FILE *f = tmpfile();
    tippe_progress p;
    tippe_progress_start(&p, f, "test", 40, TIPPE_PROGRESS_ON);
#pragma omp parallel for num_threads(2)
    for (int i = 0; i < 40; i++)
        tippe_progress_add(&p, 1);
    tippe_progress_finish(&p);
    CHECK(p.done == 40, "counted %ld of 40 from two threads", p.done);
    char text[4096] = "";
    rewind(f);
    size_t got = fread(text, 1, sizeof text - 1, f);
    text[got] = '\0';
    CHECK(strstr(text, "test: 40/40 (100.0%), done in") && !strchr(text, '\r'),
          "final line: '%s'", text);
    fclose(f);
    /* Automatic on a file that is not a terminal: nothing is written. */
    f = tmpfile();
    tippe_progress_start(&p, f, "quiet", 10, TIPPE_PROGRESS_AUTO);
    tippe_progress_add(&p, 10);
    tippe_progress_finish(&p);
    CHECK(ftell(f) == 0, "progress wrote %ld bytes to a plain file", ftell(f));
    fclose(f);
}

int main(void)
{
    test_wilson();
    test_mix();
    test_draws();
    test_central();
    test_threads_and_tally();
    test_forbidden_outcomes();
    test_progress();
    return check_summary("test_launch");
}
