/* tippe/launch.h: many hand launches of a top, and what they end in.
 *
 * A hand launch is a spin, a tilt of the symmetry axis away from the vertical,
 * a precession rate near the steady one for that tilt and spin, and a small
 * sliding velocity of the centre of mass in a random direction, drawn from
 * distributions whose defaults describe a hand-spun top of 50 mm diameter
 * (docs/launch.md justifies each default). Each launch runs through the
 * dynamics core at the verdict level (tippe/dynamics.h) and is compared with
 * Theorem 5.1's stable final states for its own Jellett invariant.
 *
 * Reproducibility: launch number `draw` of a run with seed S takes its random
 * numbers from its own GSL generator (mt19937) seeded by tippe_launch_mix(S,
 * draw), so a launch's initial state and outcome depend only on (S, draw, the
 * top, the options), not on the order in which launches run, on the number of
 * threads or on the number of MPI ranks. Results go to per-index slots and are
 * tallied in index order, so tallies are bit-identical whatever the parallelism.
 *
 * Everything here is reentrant; tippe_launch_run() runs its launches on OpenMP
 * threads (schedule(dynamic): launches differ in length by orders of magnitude). */
#ifndef TIPPE_LAUNCH_H
#define TIPPE_LAUNCH_H

#include <stdint.h>

#include "tippe/design.h"
#include "tippe/dynamics.h"
#include "tippe/error.h"
#include "tippe/progress.h"
#include "tippe/theory.h"
#include "tippe/top.h"

/* The launch distributions and the model they run in. */
typedef struct {
    double spin_from_rev_s, spin_to_rev_s; /* spin n uniform in [from, to], rev/s */
    double tilt_sd_rad;       /* tilt theta0 half-normal with this scale, rad */
    double tilt_max_rad;      /* draws above this are drawn again (< pi/2), rad */
    double precession_sd_rel; /* phi_dot = steady rate * (1 + sd * N(0, 1)) */
    double slide_sd_m_s;      /* sliding speed half-normal with this scale, m/s;
                                 direction uniform in [0, 2 pi) */
    tippe_friction_law law;   /* friction law (default viscous, eq 3.12) */
    double mu;                /* s/m, viscous sliding friction (eq 3.12), law viscous */
    double mu_c;              /* Coulomb coefficient, the Coulomb laws */
    double slip_scale_m_s;    /* Coulomb's regularisation speed v_s (0: the default) */
    double g;                 /* m/s^2 */
    double t_end;             /* s, bound on each launch's simulated time */
    int until_flip;           /* 1: follow a tip to its flip (t_flip_s), 0: stop at the proof */
    char accuracy_name[16];   /* a preset of tippe/dynamics.h, or "custom" */
    tippe_dynamics_accuracy accuracy;
} tippe_launch_options;

/* Viscous friction (eq 3.12) for a plastic ball on a table, s/m: a Coulomb
 * coefficient of about 0.3 divided by a typical contact slip speed of 0.13 m/s
 * (docs/launch.md derives it and gives the sources). */
#define TIPPE_LAUNCH_DEFAULT_MU_S_M 2.3

/* Coulomb friction of a printed (PLA or nylon) ball on a tabletop: 0.3, within the
 * published 0.2-0.5 for plastic on wood or laminate (docs/launch.md gives the sources). */
#define TIPPE_LAUNCH_DEFAULT_MU_C 0.3

/* The median of a half-normal distribution of scale 1 (sqrt(2) erf^-1(1/2)):
 * a central launch's tilt is this times the tilt scale. */
#define TIPPE_LAUNCH_HALF_NORMAL_MEDIAN 0.6744897501960817

/* The documented defaults (docs/launch.md): spin 5..25 rev/s, tilt scale
 * 0.1 rad (redrawn above 1 rad), precession spread 0.1, sliding 0.05 m/s,
 * viscous friction mu TIPPE_LAUNCH_DEFAULT_MU_S_M (eq 3.12; mu_c TIPPE_LAUNCH_DEFAULT_MU_C
 * if the law is set to Coulomb), g TIPPE_DEFAULT_G_M_S2,
 * t_end 600 s, preset "balanced", until_flip 1. */
void tippe_launch_options_default(tippe_launch_options *o);

/* TIPPE_EINPUT naming the first bad field. */
int tippe_launch_options_check(const tippe_launch_options *o, tippe_error *err);

/* The seed of launch `draw` of a run with seed `seed`: the (draw + 1)-th output
 * of a splitmix64 generator whose state is the first output of a splitmix64
 * generator started at `seed` (docs/launch.md). */
uint64_t tippe_launch_mix(uint64_t seed, uint64_t draw);

/* Draws launch `draw`'s initial state. The random numbers are always drawn in
 * the same order (spin, tilt, precession, sliding speed, sliding direction);
 * spin_rad_s, if finite, then replaces the drawn spin (a map cell's spin), so
 * that the other variables of a draw are the same at every spin. */
int tippe_launch_draw(const tippe_top *top, const tippe_launch_options *o, uint64_t seed,
                      uint64_t draw, double spin_rad_s, tippe_dynamics_initial *ic,
                      tippe_error *err);

/* The central hand launch (for `tippe check`): the median tilt of the
 * half-normal (0.674 tilt_sd_rad), steady precession, no sliding, and the
 * given spin (rad/s). */
int tippe_launch_central(const tippe_top *top, const tippe_launch_options *o, double spin_rad_s,
                         tippe_dynamics_initial *ic, tippe_error *err);

/* A hang agrees with theory when the angles differ by less than this, rad: a
 * proved hang reports the well's minimum of V, a root of eq 5.10 like theory's
 * angle, so both agree to ~1e-12; 1e-8 leaves room for ill-conditioned roots. */
#define TIPPE_LAUNCH_HANG_AGREE_RAD 1e-8

enum { TIPPE_LAUNCH_N_VERDICTS = 6 }; /* tippe_verdict values 0 .. 5 */

/* One launch and its outcome. Plain data (no pointers), so that records can be
 * sent between MPI ranks as bytes. */
typedef struct {
    long index;              /* position in the run */
    long draw;               /* the random draw it used (tippe_launch_mix) */
    int status;              /* TIPPE_OK, or the dynamics' error code */
    tippe_dynamics_initial ic;
    tippe_verdict verdict;
    double t_s;              /* s, when the verdict was reached (decision time) */
    tippe_decision how;      /* trapped, lost_contact or t_end */
    double theta_final_rad;  /* the end state (tippe_dynamics_result.theta_final_rad) */
    double spin_final_rad_s; /* its spin */
    double barrier_gap_J, margin_J; /* of a trapped decision (NAN otherwise) */
    /* trapped or bounded: theta stays in [theta_lo_rad, theta_hi_rad] with Rn above
     * Rn_bound_N (NAN otherwise); a bounded launch has no end state (NAN) */
    double theta_lo_rad, theta_hi_rad, Rn_bound_N;
    double t_flip_s;         /* s, theta first passed pi/2 (NAN: not, or not followed) */
    int rolling;             /* Coulomb: rolling without slipping at the decision */
    int end_state_proved;    /* 0 under Coulomb friction with sticking: a trapped verdict
                                proves the well and range, not the rest state */
    double J0;               /* kg m^3/s, Jellett invariant at launch (eq 3.20) */
    double jellett_rel_drift;
    long rhs_evals;
    /* Theorem 5.1 for J0: theory_ok = 0 where it gives no prediction (J0 = 0,
     * or a neutral balanced ball). predicted is a bit set of (1 << tippe_final_kind);
     * hang_theta_rad the predicted hanging angle (NAN if no hang is predicted). */
    int theory_ok;
    unsigned predicted;
    double hang_theta_rad;
    /* 1 the verdict is a predicted state (a hang within TIPPE_LAUNCH_HANG_AGREE_RAD),
     * 0 it is not, -1 not comparable (lost_contact, undecided, no prediction). */
    int agrees;
} tippe_launch_record;

/* One launch of draw `draw` (its initial state from tippe_launch_draw, spin
 * replaced by spin_rad_s if finite), integrated and compared with theory.
 * rec->index is set to `draw`. Returns the dynamics' status (rec->status). */
int tippe_launch_one(const tippe_top *top, const tippe_launch_options *o, uint64_t seed,
                     uint64_t draw, double spin_rad_s, tippe_launch_record *rec,
                     tippe_error *err);

/* Runs the given initial state (for `tippe check`) the same way. */
int tippe_launch_run_initial(const tippe_top *top, const tippe_launch_options *o,
                             const tippe_dynamics_initial *ic, tippe_launch_record *rec,
                             tippe_error *err);

/* Many launches in groups: group i has top tops[i] and, if spin_rad_s is not
 * NULL, the fixed spin spin_rad_s[i] (a map cell). Launch number `index`
 * (0 <= index < n_groups * per_group) belongs to group index / per_group and
 * uses draw index % per_group: every group sees the same hands (common random
 * numbers), so differences between groups are not sampling noise of the draws. */
typedef struct {
    int n_groups;
    long per_group;
    const tippe_top *tops;
    const double *spin_rad_s;
} tippe_launch_plan;

long tippe_launch_plan_total(const tippe_launch_plan *plan);

/* Runs launches [from, to) of the plan on OpenMP threads into out[0 .. to-from)
 * and reports each to prog (may be NULL). Returns TIPPE_OK, or the error of the
 * lowest-numbered launch that failed (its message names the launch); the other
 * records are filled in any case. */
int tippe_launch_run(const tippe_launch_plan *plan, const tippe_launch_options *o, uint64_t seed,
                     long from, long to, tippe_launch_record *out, tippe_progress *prog,
                     tippe_error *err);

/* Counts over a run of records, in index order. */
typedef struct {
    long n;
    long counts[TIPPE_LAUNCH_N_VERDICTS]; /* by tippe_verdict */
    long comparable, agree;               /* launches with agrees >= 0, and agrees = 1 */
    long predicted[8];                    /* by predicted bit set (no prediction: 0) */
    /* median final theta and verdict time of each verdict (NAN where no launch
     * has it), and the largest Jellett drift */
    double median_theta_rad[TIPPE_LAUNCH_N_VERDICTS];
    double median_t_s[TIPPE_LAUNCH_N_VERDICTS];
    double max_jellett_rel_drift;
    double rhs_evals; /* total */
    /* Over tips followed to the flip (until_flip): how many, and the median model
     * time at which theta passed pi/2 (NAN if none). */
    long flips;
    double median_t_flip_s;
    /* Trapped decisions (no_tip, tip, hang): how many, how many of them in a well
     * with no barrier, and the smallest barrier gap / margin of the others
     * (INFINITY if none). */
    long trapped, trapped_no_barrier;
    long rolling; /* decided rolling for ever (Coulomb friction with sticking) */
    double min_gap_over_margin;
} tippe_launch_tally;

/* TIPPE_ECOMPUTE if out of memory. */
int tippe_launch_tally_records(const tippe_launch_record *r, long n, tippe_launch_tally *out,
                               tippe_error *err);

/* The normal quantile for a two-sided 95% interval, Phi^-1(0.975). */
#define TIPPE_LAUNCH_Z95 1.959963984540054

/* Wilson score interval for k successes in n trials at normal quantile z:
 * (p + z^2/2n -+ z sqrt(p (1 - p)/n + z^2/4n^2)) / (1 + z^2/n), p = k/n,
 * clamped to [0, 1]; [0, 1] for n = 0. */
void tippe_launch_wilson(long k, long n, double z, double *lo, double *hi);

/* The predicted bit set as text: "no_tip", "tip or hang", ..., "none". */
const char *tippe_launch_predicted_name(unsigned predicted);

/* An outcome map over a grid of Z2 and spin (`tippe map`). Cell (i, j), at
 * z2_mm[i] and spin_rev_s[j], is cells[i * n_spin + j]. */
typedef struct {
    int n_z2, n_spin;
    const double *z2_mm, *spin_rev_s;
    const tippe_launch_tally *cells;
    long per_cell;
} tippe_launch_map;

/* The index of the most frequent verdict of a cell (the lowest on a tie). */
int tippe_launch_dominant(const tippe_launch_tally *t);

/* The map as a heat map (src/plot_map.c): each cell coloured by its dominant
 * outcome, paler the smaller that outcome's share, against Z2 (mm) and spin
 * (rev/s); the zone boundaries of the design's sweep as vertical lines with the
 * zones named along the top, and theory's spin thresholds n- and n* (eq 5.11,
 * section 7.1) as curves. PNG, SVG or PDF by the extension, written atomically.
 * PLplot has one global state: call from one thread. */
int tippe_launch_plot_map(const char *file, const tippe_launch_map *map, const tippe_design *d,
                          double g, const char *title, tippe_error *err);

#endif
