/* Hand launches: distributions, per-launch generators, OpenMP runs, tallies
 * and Wilson intervals (tippe/launch.h, docs/launch.md). */
#include "tippe/launch.h"
#include "tippe/base.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The median of a half-normal distribution in units of its scale: sqrt(2)
 * erfinv(1/2) = Phi^-1(3/4). */
#define HALF_NORMAL_MEDIAN TIPPE_LAUNCH_HALF_NORMAL_MEDIAN

void tippe_launch_options_default(tippe_launch_options *o)
{
    memset(o, 0, sizeof *o);
    o->spin_from_rev_s = 5.0;
    o->spin_to_rev_s = 25.0;
    o->tilt_sd_rad = 0.1;
    o->tilt_max_rad = 1.0;
    o->precession_sd_rel = 0.1;
    o->slide_sd_m_s = 0.05;
    /* docs/launch.md: a tabletop's Coulomb coefficient (~0.3) over the median contact
     * slip speed before a hand-spun M12 ball flips (~0.13 m/s, measured). */
    o->mu = TIPPE_LAUNCH_DEFAULT_MU_S_M;
    /* The paper's viscous law (eq 3.12), not Coulomb's: the rigid point contact rolls
     * for ever once it sticks, which contradicts the hand launches of Table 1
     * (docs/dynamics.md, "Why design launches default to the viscous law"). */
    o->law = tippe_friction_law_at(0)->law; /* the table's first: the viscous law */
    o->mu_c = TIPPE_LAUNCH_DEFAULT_MU_C;
    o->slip_scale_m_s = 0.0;
    o->creep_cap = TIPPE_PATCH_CREEP_CAP;
    o->g = TIPPE_DEFAULT_G_M_S2;
    o->t_end = 600.0;
    o->until_flip = 1;
    snprintf(o->accuracy_name, sizeof o->accuracy_name, "balanced");
    tippe_dynamics_accuracy_preset("balanced", &o->accuracy, NULL);
}

int tippe_launch_options_check(const tippe_launch_options *o, tippe_error *err)
{
    if (!(o->spin_from_rev_s >= 0 && o->spin_from_rev_s <= o->spin_to_rev_s &&
          isfinite(o->spin_to_rev_s)))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "spin range %g .. %g rev/s: need 0 <= FROM <= TO, finite",
                               o->spin_from_rev_s, o->spin_to_rev_s);
    /* theta0 must stay below pi/2: the steady precession rate divides by cos(theta). */
    if (!(o->tilt_max_rad > 0 && o->tilt_max_rad <= 1.4))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "largest tilt %g rad must be in (0, 1.4] (below pi/2)",
                               o->tilt_max_rad);
    /* Redrawing above tilt_max must terminate quickly: keep it >= 2 scales. */
    if (!(o->tilt_sd_rad >= 0 && o->tilt_sd_rad <= 0.5 * o->tilt_max_rad))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "tilt scale %g rad must be in [0, %g] (half the largest tilt)",
                               o->tilt_sd_rad, 0.5 * o->tilt_max_rad);
    if (!(o->precession_sd_rel >= 0 && o->precession_sd_rel <= 1))
        return tippe_error_set(err, TIPPE_EINPUT, "precession spread %g must be in [0, 1]",
                               o->precession_sd_rel);
    if (!(o->slide_sd_m_s >= 0 && isfinite(o->slide_sd_m_s)))
        return tippe_error_set(err, TIPPE_EINPUT, "sliding speed scale %g m/s must be >= 0",
                               o->slide_sd_m_s);
    if (!(o->mu >= 0 && isfinite(o->mu)))
        return tippe_error_set(err, TIPPE_EINPUT, "mu = %g s/m must be >= 0", o->mu);
    const tippe_friction_law_type *law = tippe_friction_law_type_of(o->law);
    if (!law) /* a law of the friction laws' table */
        return tippe_error_set(err, TIPPE_EINPUT, "unknown friction law %d", (int)o->law);
    /* the dynamics refuses a patch wider than R/2 (it knows R); here only a number */
    if (!(o->patch_radius_m >= 0 && isfinite(o->patch_radius_m)) ||
        !(o->patch_E_star_pa >= 0 && isfinite(o->patch_E_star_pa)))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "patch radius %g m and E* %g Pa must be >= 0 and finite",
                               o->patch_radius_m, o->patch_E_star_pa);
    /* a design's launches get the radius or Hertz's modulus (tippe_launch_patch_modulus):
     * neither would silently be the point limit */
    if (law->patch && !(o->patch_radius_m > 0) && !(o->patch_E_star_pa > 0))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "the patch law needs the patch radius or the contact modulus "
                               "E* (Hertz at m g)");
    if (!(o->mu_c >= 0 && o->mu_c <= 10))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "Coulomb friction coefficient mu_c = %g must be in [0, 10]",
                               o->mu_c);
    if (!(o->slip_scale_m_s >= 0 && o->slip_scale_m_s <= 1))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "Coulomb slip scale %g m/s must be in [0, 1] (0: the default)",
                               o->slip_scale_m_s);
    if (!(o->creep_cap >= 0 && o->creep_cap <= 1e4))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "the creep reduction's cap %g must be in [0, 1e4] (0: the full "
                               "law)", o->creep_cap);
    if (!(o->g > 0 && isfinite(o->g)))
        return tippe_error_set(err, TIPPE_EINPUT, "g = %g m/s^2 must be positive", o->g);
    if (!(o->t_end > 0 && isfinite(o->t_end)))
        return tippe_error_set(err, TIPPE_EINPUT, "t_end = %g s must be positive", o->t_end);
    if (!tippe_dynamics_stepper_known(o->accuracy.stepper))
        return tippe_error_set(err, TIPPE_EINPUT, "unknown stepper '%s'", o->accuracy.stepper);
    if (!(o->accuracy.rtol >= 1e-14 && o->accuracy.rtol <= 1e-2))
        return tippe_error_set(err, TIPPE_EINPUT, "rtol = %g must be in [1e-14, 1e-2]",
                               o->accuracy.rtol);
    return TIPPE_OK;
}

/* splitmix64's output function (Steele, Lea and Flood 2014). */
static uint64_t fmix64(uint64_t z)
{
    z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
    return z ^ (z >> 31);
}

#define GOLDEN_GAMMA UINT64_C(0x9E3779B97F4A7C15)

uint64_t tippe_launch_mix(uint64_t seed, uint64_t draw)
{
    /* Mixing the seed first makes seeds 1, 2, 3 give unrelated streams of keys. */
    const uint64_t state = fmix64(seed + GOLDEN_GAMMA);
    return fmix64(state + (draw + 1) * GOLDEN_GAMMA);
}

static void model_of(const tippe_top *top, const tippe_launch_options *o, tippe_dynamics_model *m)
{
    tippe_launch_friction_model(o, m);
    m->top = *top;
}

/* The steady precession (theta_dot = 0 at launch, eq 3.15 with Rn = m g) for
 * the tilt and spin, spread by the factor (1 + sd z). */
static int precession(const tippe_top *top, const tippe_launch_options *o, double theta,
                      double spin, double z, double *phi_dot, tippe_error *err)
{
    tippe_dynamics_model m;
    model_of(top, o, &m);
    int rc = tippe_dynamics_precession(&m, theta, spin, TIPPE_PRECESSION_STEADY, phi_dot, err);
    if (rc)
        return rc;
    *phi_dot *= 1.0 + o->precession_sd_rel * z;
    return TIPPE_OK;
}

int tippe_launch_draw(const tippe_top *top, const tippe_launch_options *o, uint64_t seed,
                      uint64_t draw, double spin_rad_s, tippe_dynamics_initial *ic,
                      tippe_error *err)
{
    gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
    if (!r)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "cannot allocate a random number generator");
    const uint64_t key = tippe_launch_mix(seed, draw);
    /* GSL generators take 32 bits of seed: fold the 64-bit key. */
    gsl_rng_set(r, (unsigned long)((key ^ (key >> 32)) & UINT64_C(0xffffffff)));

    const double spin_rev_s = gsl_ran_flat(r, o->spin_from_rev_s, o->spin_to_rev_s);
    double tilt;
    do
        tilt = fabs(gsl_ran_gaussian(r, o->tilt_sd_rad));
    while (tilt > o->tilt_max_rad);
    const double z_prec = gsl_ran_gaussian(r, 1.0);
    const double slide = fabs(gsl_ran_gaussian(r, o->slide_sd_m_s));
    const double dir = gsl_ran_flat(r, 0.0, 2.0 * M_PI);
    gsl_rng_free(r);

    memset(ic, 0, sizeof *ic);
    ic->theta = tilt;
    ic->theta_dot = 0.0;
    ic->spin = isfinite(spin_rad_s) ? spin_rad_s : 2.0 * M_PI * spin_rev_s;
    ic->U = slide * cos(dir);
    ic->V = slide * sin(dir);
    return precession(top, o, tilt, ic->spin, z_prec, &ic->phi_dot, err);
}

int tippe_launch_central(const tippe_top *top, const tippe_launch_options *o, double spin_rad_s,
                         tippe_dynamics_initial *ic, tippe_error *err)
{
    if (!isfinite(spin_rad_s))
        return tippe_error_set(err, TIPPE_EINPUT, "spin %g rad/s is not finite", spin_rad_s);
    memset(ic, 0, sizeof *ic);
    ic->theta = HALF_NORMAL_MEDIAN * o->tilt_sd_rad;
    ic->spin = spin_rad_s;
    return precession(top, o, ic->theta, spin_rad_s, 0.0, &ic->phi_dot, err);
}

static int same_kind(tippe_verdict v, tippe_final_kind k)
{
    return (v == TIPPE_VERDICT_NO_TIP && k == TIPPE_FINAL_NO_TIP) ||
           (v == TIPPE_VERDICT_TIP && k == TIPPE_FINAL_TIP) ||
           (v == TIPPE_VERDICT_HANG && k == TIPPE_FINAL_HANG);
}

/* Theorem 5.1's stable states for the launch's J0 (tippe_theory_predict) and
 * whether the verdict is one of them. */
static void compare_with_theory(const tippe_top *top, double g, tippe_launch_record *rec)
{
    rec->theory_ok = 0;
    rec->predicted = 0;
    rec->hang_theta_rad = NAN;
    rec->agrees = -1;
    tippe_theory_prediction p;
    tippe_error e;
    if (tippe_theory_predict(top, g, rec->J0, &p, &e) != TIPPE_OK)
        return;
    rec->theory_ok = 1;
    for (int i = 0; i < p.n; i++) {
        rec->predicted |= 1u << p.state[i].kind;
        if (p.state[i].kind == TIPPE_FINAL_HANG)
            rec->hang_theta_rad = p.state[i].theta_rad;
    }
    /* theory is for J0, which a drilling patch does not keep: an observed verdict is not
     * compared */
    if (rec->verdict == TIPPE_VERDICT_LOST_CONTACT || rec->verdict == TIPPE_VERDICT_UNDECIDED ||
        rec->verdict == TIPPE_VERDICT_BOUNDED || rec->how == TIPPE_DECIDED_OBSERVED ||
        rec->how == TIPPE_DECIDED_ENERGY_CONE)
        return;
    rec->agrees = 0;
    for (int i = 0; i < p.n; i++)
        if (same_kind(rec->verdict, p.state[i].kind) &&
            (p.state[i].kind != TIPPE_FINAL_HANG ||
             fabs(p.state[i].theta_rad - rec->theta_final_rad) < TIPPE_LAUNCH_HANG_AGREE_RAD))
            rec->agrees = 1;
}

int tippe_launch_run_initial(const tippe_top *top, const tippe_launch_options *o,
                             const tippe_dynamics_initial *ic, tippe_launch_record *rec,
                             tippe_error *err)
{
    tippe_gsl_errors_as_codes();
    rec->ic = *ic;
    rec->verdict = TIPPE_VERDICT_UNDECIDED;
    rec->theory_ok = 0;
    rec->predicted = 0;
    rec->hang_theta_rad = NAN;
    rec->agrees = -1;
    rec->t_s = rec->theta_final_rad = rec->spin_final_rad_s = NAN;
    rec->how = TIPPE_DECIDED_T_END;
    rec->barrier_gap_J = rec->margin_J = rec->t_flip_s = rec->t_fall_s = NAN;
    rec->inverted_time_s = rec->energy_rel_error = rec->creep_energy_rel = NAN;
    rec->cap_time_s = 0;
    rec->cap_first_s = NAN;
    rec->theta_lo_rad = rec->theta_hi_rad = rec->Rn_bound_N = NAN;
    rec->J0 = rec->jellett_rel_drift = rec->jellett_drift_time_s = NAN;
    rec->rhs_evals = 0;

    tippe_dynamics_model m;
    model_of(top, o, &m);
    tippe_dynamics_options opt;
    tippe_dynamics_options_default(&opt);
    opt.level = TIPPE_LEVEL_VERDICT; /* the least work that gives a final state */
    opt.t_end = o->t_end;
    opt.accuracy = o->accuracy;
    opt.until_flip = o->until_flip;
    opt.cap_half_angle_rad[0] = o->cap_half_angle_rad[0];
    opt.cap_half_angle_rad[1] = o->cap_half_angle_rad[1];
    opt.sphere_contact_only = o->sphere_contact_only;
    tippe_dynamics_result res;
    rec->status = tippe_dynamics_run(&m, ic, &opt, &res, err);
    if (rec->status != TIPPE_OK)
        return rec->status;
    rec->verdict = res.verdict;
    rec->t_s = res.t_verdict;
    rec->how = res.how;
    rec->theta_final_rad = res.theta_final_rad;
    rec->spin_final_rad_s = res.spin_final_rad_s;
    rec->barrier_gap_J = res.barrier_gap_J;
    rec->margin_J = res.margin_J;
    rec->theta_lo_rad = res.theta_lo_rad;
    rec->theta_hi_rad = res.theta_hi_rad;
    rec->Rn_bound_N = res.Rn_bound_N;
    rec->t_flip_s = res.t_flip;
    rec->t_fall_s = res.t_fall;
    rec->inverted_time_s = res.inverted_time_s;
    rec->energy_rel_error = res.energy_rel_error;
    rec->creep_energy_rel = res.creep_energy_J / res.E0;
    rec->cap_time_s = res.cap_time_s;
    rec->cap_first_s = res.cap_first_s;
    rec->rim_touched = res.rim_touched;
    rec->rim_switches = res.rim_switches;
    rec->spin_leaving_rim_rad_s = res.spin_leaving_rim_rad_s;
    rec->rolling = res.rolling;
    rec->end_state_proved = res.end_state_proved;
    rec->J0 = res.J0;
    rec->jellett_rel_drift = res.jellett_rel_drift;
    rec->jellett_drift_time_s = res.jellett_drift_time_s;
    rec->rhs_evals = res.rhs_evals;
    compare_with_theory(top, o->g, rec);
    return TIPPE_OK;
}

/* One launch of draw `draw` (its initial state from tippe_launch_draw, spin
 * replaced by spin_rad_s if finite), integrated and compared with theory.
 * rec->index is set to `draw`. Returns the dynamics' status (rec->status). */
static int launch_one(const tippe_top *top, const tippe_launch_options *o, uint64_t seed,
                      uint64_t draw, double spin_rad_s, tippe_launch_record *rec,
                      tippe_error *err)
{
    memset(rec, 0, sizeof *rec);
    rec->index = (long)draw;
    rec->draw = (long)draw;
    tippe_dynamics_initial ic;
    int rc = tippe_launch_draw(top, o, seed, draw, spin_rad_s, &ic, err);
    if (rc) {
        rec->status = rc;
        rec->verdict = TIPPE_VERDICT_UNDECIDED;
        rec->agrees = -1;
        return rc;
    }
    return tippe_launch_run_initial(top, o, &ic, rec, err);
}

/* Draws every launch of [from, to) into its record (index, draw, initial state)
 * before any integration, and checks its contact: a draw whose launch state has no
 * determined contact force (the denominator of eq 3.19 <= 0, strong friction times
 * a fast slide) would fail only after the other launches had run for minutes.
 * TIPPE_EINPUT naming the first such draw; a failed draw is left in its record's
 * status. */
static int draw_launches(const tippe_launch_plan *plan, const tippe_launch_options *o,
                         uint64_t seed, long from, long to, tippe_launch_record *out,
                         tippe_error *err)
{
    long bad = -1;
#pragma omp parallel for schedule(static)
    for (long i = 0; i < to - from; i++) {
        const long index = from + i;
        const int group = (int)(index / plan->per_group);
        tippe_launch_record *rec = &out[i];
        memset(rec, 0, sizeof *rec);
        rec->index = index;
        rec->draw = index % plan->per_group;
        rec->verdict = TIPPE_VERDICT_UNDECIDED;
        rec->agrees = -1;
        tippe_dynamics_model m;
        tippe_dynamics_sample s;
        tippe_error e;
        model_of(&plan->tops[group], o, &m);
        rec->status = tippe_launch_draw(&plan->tops[group], o, seed, (uint64_t)rec->draw,
                                        plan->spin_rad_s ? plan->spin_rad_s[group] : NAN,
                                        &rec->ic, &e);
        if (rec->status || tippe_dynamics_evaluate(&m, &rec->ic, &s, &e) == TIPPE_OK)
            continue;
#pragma omp critical(tippe_launch_bad)
        if (bad < 0 || index < bad)
            bad = index;
    }
    if (bad < 0)
        return TIPPE_OK;
    const int viscous = tippe_friction_law_takes(o->law, TIPPE_LAW_PARAM_MU); /* mu in s/m */
    return tippe_error_set(err, TIPPE_EINPUT,
                           "launch %ld (draw %ld): the contact force is undetermined at launch "
                           "(denominator of eq 3.19 <= 0: friction %s %g%s is too strong for "
                           "its sliding speed); lower it or the sliding (--slide)",
                           bad, bad % plan->per_group,
                           viscous ? "mu" : "mu_c", viscous ? o->mu : o->mu_c,
                           viscous ? " s/m" : "");
}

/* The options of a plan's group: o, with the group's polar caps when the plan has them. */
static const tippe_launch_options *group_options(const tippe_launch_plan *plan,
                                                 const tippe_launch_options *o, int group,
                                                 tippe_launch_options *buf)
{
    if (!plan->caps_rad)
        return o;
    *buf = *o;
    buf->cap_half_angle_rad[0] = plan->caps_rad[group][0];
    buf->cap_half_angle_rad[1] = plan->caps_rad[group][1];
    return buf;
}

long tippe_launch_plan_total(const tippe_launch_plan *plan)
{
    return (long)plan->n_groups * plan->per_group;
}

int tippe_launch_run(const tippe_launch_plan *plan, const tippe_launch_options *o, uint64_t seed,
                     long from, long to, tippe_launch_record *out, tippe_progress *prog,
                     tippe_error *err)
{
    tippe_gsl_errors_as_codes();
    if (!plan || plan->n_groups < 1 || plan->per_group < 1 || !plan->tops)
        return tippe_error_set(err, TIPPE_EINPUT, "empty launch plan");
    if (!(from >= 0 && from <= to && to <= tippe_launch_plan_total(plan)))
        return tippe_error_set(err, TIPPE_EINPUT, "launches %ld .. %ld outside the plan (0 .. %ld)",
                               from, to, tippe_launch_plan_total(plan));
    int rc = tippe_launch_options_check(o, err);
    if (rc || (rc = draw_launches(plan, o, seed, from, to, out, err)))
        return rc;

    const long n = to - from;
    /* Each iteration writes only its own slot; nothing shared is written but
     * the progress counter (its own critical section). */
#pragma omp parallel for schedule(dynamic, 1)
    for (long i = 0; i < n; i++) {
        const tippe_dynamics_initial ic = out[i].ic;
        const int group = (int)(out[i].index / plan->per_group);
        tippe_launch_options og;
        tippe_error e;
        if (out[i].status == TIPPE_OK)
            tippe_launch_run_initial(&plan->tops[group], group_options(plan, o, group, &og),
                                     &ic, &out[i], &e);
        tippe_progress_add(prog, 1);
    }

    for (long i = 0; i < n; i++)
        if (out[i].status != TIPPE_OK) {
            /* The run is deterministic: repeating the launch recovers its message. */
            const long index = from + i;
            const int group = (int)(index / plan->per_group);
            tippe_launch_record again;
            tippe_error e;
            tippe_launch_options og;
            launch_one(&plan->tops[group], group_options(plan, o, group, &og), seed,
                       (uint64_t)(index % plan->per_group),
                       plan->spin_rad_s ? plan->spin_rad_s[group] : NAN, &again, &e);
            return tippe_error_set(err, out[i].status, "launch %ld (draw %ld): %s", index,
                                   index % plan->per_group, e.msg);
        }
    return TIPPE_OK;
}

static double median_of(double *v, long n)
{
    if (n == 0)
        return NAN;
    gsl_sort(v, 1, (size_t)n);
    return gsl_stats_median_from_sorted_data(v, 1, (size_t)n);
}

int tippe_launch_tally_records(const tippe_launch_record *r, long n, tippe_launch_tally *out,
                               tippe_error *err)
{
    memset(out, 0, sizeof *out);
    out->n = n;
    double *theta = malloc((size_t)(n > 0 ? n : 1) * sizeof *theta);
    double *t = malloc((size_t)(n > 0 ? n : 1) * sizeof *t);
    if (!theta || !t) {
        free(theta);
        free(t);
        return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory tallying %ld launches", n);
    }
    for (long i = 0; i < n; i++) {
        const tippe_launch_record *x = &r[i];
        if ((int)x->verdict >= 0 && (int)x->verdict < TIPPE_LAUNCH_N_VERDICTS)
            out->counts[x->verdict]++;
        if (x->agrees >= 0) {
            out->comparable++;
            out->agree += x->agrees;
        }
        out->predicted[x->theory_ok ? (x->predicted & 7u) : 0]++;
        if (x->jellett_rel_drift > out->max_jellett_rel_drift)
            out->max_jellett_rel_drift = x->jellett_rel_drift;
        out->rhs_evals += (double)x->rhs_evals;
        out->on_cap += x->status == TIPPE_OK && isfinite(x->cap_first_s);
    }
    long m_flip = 0;
    out->min_gap_over_margin = INFINITY;
    for (long i = 0; i < n; i++) {
        if (r[i].status != TIPPE_OK)
            continue;
        if (r[i].verdict == TIPPE_VERDICT_TIP && isfinite(r[i].t_flip_s))
            t[m_flip++] = r[i].t_flip_s;
        if (r[i].how == TIPPE_DECIDED_ROLLING)
            out->rolling++;
        if (r[i].how != TIPPE_DECIDED_TRAPPED || r[i].verdict == TIPPE_VERDICT_BOUNDED)
            continue;
        out->trapped++;
        if (isinf(r[i].barrier_gap_J))
            out->trapped_no_barrier++;
        else if (r[i].barrier_gap_J / r[i].margin_J < out->min_gap_over_margin)
            out->min_gap_over_margin = r[i].barrier_gap_J / r[i].margin_J;
    }
    out->flips = m_flip;
    out->median_t_flip_s = median_of(t, m_flip);
    long m_pass = 0, m_fall = 0;
    for (long i = 0; i < n; i++)
        if (r[i].status == TIPPE_OK && isfinite(r[i].t_flip_s))
            t[m_pass++] = r[i].t_flip_s;
    out->passed = m_pass;
    out->median_t_passed_s = median_of(t, m_pass);
    for (long i = 0; i < n; i++)
        if (r[i].status == TIPPE_OK && isfinite(r[i].t_flip_s) && isfinite(r[i].t_fall_s))
            t[m_fall++] = r[i].t_fall_s;
    out->fell = m_fall;
    out->median_t_fall_s = median_of(t, m_fall);
    for (int v = 0; v < TIPPE_LAUNCH_N_VERDICTS; v++) {
        long m = 0;
        for (long i = 0; i < n; i++)
            if ((int)r[i].verdict == v && r[i].status == TIPPE_OK) {
                t[m] = r[i].t_s;
                m++;
            }
        out->median_t_s[v] = median_of(t, m);
        m = 0; /* a bounded launch has no end angle (NAN) */
        for (long i = 0; i < n; i++)
            if ((int)r[i].verdict == v && r[i].status == TIPPE_OK &&
                isfinite(r[i].theta_final_rad))
                theta[m++] = r[i].theta_final_rad;
        out->median_theta_rad[v] = median_of(theta, m);
    }
    free(theta);
    free(t);
    return TIPPE_OK;
}

void tippe_launch_wilson(long k, long n, double z, double *lo, double *hi)
{
    if (n <= 0) {
        *lo = 0.0;
        *hi = 1.0;
        return;
    }
    const double nn = (double)n, p = (double)k / nn, z2 = z * z;
    const double denom = 1.0 + z2 / nn;
    const double centre = (p + z2 / (2.0 * nn)) / denom;
    const double half = z * sqrt(p * (1.0 - p) / nn + z2 / (4.0 * nn * nn)) / denom;
    /* At k = 0 and k = n the two terms cancel exactly in exact arithmetic:
     * return the exact end instead of a rounding residue. */
    *lo = k <= 0 ? 0.0 : fmax(0.0, centre - half);
    *hi = k >= n ? 1.0 : fmin(1.0, centre + half);
}

const char *tippe_launch_predicted_name(unsigned predicted)
{
    static const char *const names[8] = {
        "none",           "no_tip",    "tip",       "no_tip or tip",
        "hang",           "no_tip or hang", "tip or hang", "no_tip, tip or hang",
    };
    return names[predicted & 7u];
}

int tippe_launch_dominant(const tippe_launch_tally *t)
{
    int best = 0;
    for (int v = 1; v < TIPPE_LAUNCH_N_VERDICTS; v++)
        if (t->counts[v] > t->counts[best])
            best = v;
    return best;
}

typedef struct {
    double *t, *theta;
    int n, cap;
} trace_ctx;

static int trace_sample(const tippe_dynamics_sample *s, void *ctx)
{
    trace_ctx *c = ctx;
    if (c->n < c->cap) {
        c->t[c->n] = s->t;
        c->theta[c->n] = s->theta;
        c->n++;
    }
    return 0;
}

int tippe_launch_trace(const tippe_top *top, const tippe_launch_options *o,
                       const tippe_dynamics_initial *ic, double t_end_s, int n, double *t_s,
                       double *theta_rad, int *n_out, tippe_error *err)
{
    *n_out = 0;
    if (n < 2 || !(t_end_s > 0) || !isfinite(t_end_s))
        return tippe_error_set(err, TIPPE_EINPUT, "a trace needs 2 samples or more over a "
                                                  "positive time");
    tippe_dynamics_model m;
    model_of(top, o, &m);
    tippe_dynamics_options opt;
    tippe_dynamics_options_default(&opt);
    opt.level = TIPPE_LEVEL_TRAJECTORY;
    opt.t_end = t_end_s;
    opt.accuracy = o->accuracy;
    opt.sample_dt = t_end_s / (n - 1);
    opt.run_to_t_end = 1;
    opt.sphere_contact_only = o->sphere_contact_only;
    trace_ctx c = {t_s, theta_rad, 0, n};
    opt.on_sample = trace_sample;
    opt.sample_ctx = &c;
    tippe_dynamics_result res;
    int rc = tippe_dynamics_run(&m, ic, &opt, &res, err);
    *n_out = c.n;
    return rc;
}

int tippe_launch_trajectory(const tippe_top *top, const tippe_launch_options *o,
                            const tippe_dynamics_initial *ic, double sample_dt_s,
                            tippe_dynamics_samples *samples, tippe_dynamics_result *res,
                            tippe_error *err)
{
    tippe_dynamics_model m;
    model_of(top, o, &m);
    tippe_dynamics_options opt;
    tippe_dynamics_options_default(&opt);
    opt.level = TIPPE_LEVEL_TRAJECTORY;
    opt.t_end = o->t_end;
    opt.accuracy = o->accuracy;
    opt.run_to_t_end = 1;
    opt.until_flip = 1;
    opt.sphere_contact_only = o->sphere_contact_only;
    opt.sample_dt = sample_dt_s > 0 ? sample_dt_s
                                    : tippe_dynamics_default_sample_dt(ic, m.g, top->R, o->t_end);
    opt.on_sample = tippe_dynamics_samples_keep;
    opt.sample_ctx = samples;
    return tippe_dynamics_run(&m, ic, &opt, res, err);
}

int tippe_launch_patch_modulus(const tippe_design *d, const char *table, double *E_star_pa,
                               tippe_error *err)
{
    double Et, nut, Eb = 0.0, nub = 0.0;
    const char *mat = "";
    if (!table)
        table = TIPPE_CONTACT_DEFAULT_TABLE;
    if (tippe_contact_table_surface(table, &Et, &nut))
        return tippe_error_set(err, TIPPE_EINPUT, "unknown table '%s' (" TIPPE_CONTACT_TABLES ")",
                               table);
    if (!tippe_design_ball_elastic(d, &Eb, &nub, &mat))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "the ball's material '%s' has no E_GPa and nu in the materials "
                               "table, so the Hertz patch is unknown: give the patch radius "
                               "(--patch-mm)",
                               mat[0] ? mat : "(inline density)");
    return tippe_contact_hertz_modulus(Eb, nub, Et, nut, E_star_pa, err);
}

void tippe_launch_polar_caps(const tippe_design *d, double z2_mm, const tippe_top *top,
                             double caps_rad[2])
{
    tippe_design_cap caps[2];
    caps_rad[0] = caps_rad[1] = 0;
    if (!tippe_design_polar_caps(d, z2_mm, caps))
        return;
    const int rest = top->com_side ? top->com_side : 1; /* caps[0] is +z, caps[1] -z */
    caps_rad[0] = caps[rest > 0 ? 0 : 1].half_angle_rad;
    caps_rad[1] = caps[rest > 0 ? 1 : 0].half_angle_rad;
}
