/* tippe/launch.h: hand launches of a design, and what they end in.
 *
 * Contents:
 * - launches: the hand's distributions and options, draws, runs and tallies, their
 *   comparison with Theorem 5.1 (tippe_launch_*; src/launch/launch.c);
 * - the patch radius's sensitivity (launch_radius.c) and a map's grid
 *   (launch_grid.c);
 * - the friction options' rules both front ends share (tippe_friction_choose,
 *   tippe_friction_for_design; friction_options.c);
 * - reports of launches (launch_report.c).
 * Depends on the design (tippe/design.h: a launch is drawn for a design at a Z2) and
 * the physics (tippe/physics.h). */
#ifndef TIPPE_LAUNCH_H
#define TIPPE_LAUNCH_H

#include <stddef.h>
#include <stdint.h>

#include "tippe/base.h"
#include "tippe/design.h"
#include "tippe/physics.h"

/* Launch: many hand launches of a top, and what they end in.
 *
 * A hand launch is a spin, a tilt of the symmetry axis away from the vertical,
 * a precession rate near the steady one for that tilt and spin, and a small
 * sliding velocity of the centre of mass in a random direction, drawn from
 * distributions whose defaults describe a hand-spun top of 50 mm diameter
 * (docs/launch.md justifies each default). Each launch runs through the
 * dynamics core at the verdict level (tippe/physics.h) and is compared with
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
    double creep_cap;         /* law patch: the creep reduction's cap (default
                                 TIPPE_PATCH_CREEP_CAP; 0: the full law) */
    double patch_radius_m;    /* law patch: the patch radius, m (0: Hertz from E*) */
    double patch_E_star_pa;   /* law patch: contact modulus for Hertz at m g, Pa (or 0) */
    double patch_radius_span; /* law patch: the radius sensitivity runs at a/F and a F with
                                 this F (> 1; 0: TIPPE_LAUNCH_RADIUS_SPAN); a design's is its
                                 tolerance on contact.patch_radius
                                 (tippe_design_patch_radius_span) */
    double g;                 /* m/s^2 */
    double t_end;             /* s, bound on each launch's simulated time */
    int until_flip;           /* 1: follow a tip to its flip (t_flip_s), 0: stop at the proof */
    /* the holes' openings at the pole down at theta = 0 and at the other, rad
     * (tippe_launch_polar_caps; 0: the sphere is whole): each launch records the
     * time its contact spends there (tippe_launch_record.cap_time_s) */
    double cap_half_angle_rad[2];
    /* 1: every launch's contact stays on the sphere within an opening (the model
     * before issue 35; tippe_dynamics_options.sphere_contact_only), to compare */
    int sphere_contact_only;
    char accuracy_name[16];   /* a preset of tippe/physics.h, or "custom" */
    tippe_dynamics_accuracy accuracy;
} tippe_launch_options;

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
 * half-normal (0.674 tilt_sd_rad), steady precession, the centre at rest
 * (U = V = 0; the contact point slips: tippe_dynamics_launch_slip), and the
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
    /* s, time the contact spent within a hole's opening at a pole up to t_s, and
     * the first time it was there (NAN: never): the model does not hold there */
    double cap_time_s, cap_first_s;
    /* the contact stood on a rim (1) at some time; its switches between sphere and
     * rim; the spin when it first left the rim it was launched on (NAN: did not) */
    int rim_touched;
    long rim_switches;
    double spin_leaving_rim_rad_s;
    double t_fall_s;         /* s, first came back below pi/2 after t_flip_s (NAN: did not) */
    double inverted_time_s;  /* s, model time spent above pi/2 */
    double energy_rel_error; /* max |E + D - E0| / E0 over the run */
    double creep_energy_rel; /* the patch law's creep reduction: the energy it moved over
                                E0 (tippe_dynamics_result.creep_energy_J; 0 otherwise) */
    int rolling;             /* Coulomb: rolling without slipping at the decision */
    int end_state_proved;    /* 0 under Coulomb friction with sticking: a trapped verdict
                                proves the well and range, not the rest state */
    double J0;               /* kg m^3/s, Jellett invariant at launch (eq 3.20) */
    double jellett_rel_drift;
    double jellett_drift_time_s; /* patch law: how soon drilling could change J by J0 (s) */
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

/* The half-angles of the holes' openings (tippe_design_polar_caps) at the pole
 * the top of d at z2_mm rests on at theta = 0 (its centre of mass's side,
 * top->com_side; +z when centred) into caps_rad[0], at the other into
 * caps_rad[1]; 0 where the sphere is whole. For tippe_launch_options and
 * tippe_dynamics_options.cap_half_angle_rad. */
void tippe_launch_polar_caps(const tippe_design *d, double z2_mm, const tippe_top *top,
                             double caps_rad[2]);

/* Runs the given initial state (for `tippe check`) as tippe_launch_run runs a
 * drawn one: integrated and compared with theory. Returns the dynamics' status
 * (rec->status). */
int tippe_launch_run_initial(const tippe_top *top, const tippe_launch_options *o,
                             const tippe_dynamics_initial *ic, tippe_launch_record *rec,
                             tippe_error *err);

/* The tilt theta(t) of a launch (ic) sampled every t_end_s / (n - 1) from 0
 * to t_end_s (trajectory level; the samples stop early where the contact is
 * lost): t_s[0 .. *n_out - 1], theta_rad[...]. For a plot of one launch. */
int tippe_launch_trace(const tippe_top *top, const tippe_launch_options *o,
                       const tippe_dynamics_initial *ic, double t_end_s, int n, double *t_s,
                       double *theta_rad, int *n_out, tippe_error *err);

/* One launch (ic) at the trajectory level to o->t_end, as tippe check --csv and
 * --plot and tippe simulate --csv integrate it: the verdict is recorded and the run
 * goes on to t_end (run_to_t_end), a tip is followed to its flip, samples every
 * sample_dt_s (<= 0: tippe_dynamics_default_sample_dt) into *samples (zeroed by
 * the caller; free with tippe_dynamics_samples_free, also on failure). *res has
 * E0 and the state where the run stopped (res->last: theta, the energy dissipated
 * D). The dynamics' status. */
int tippe_launch_trajectory(const tippe_top *top, const tippe_launch_options *o,
                            const tippe_dynamics_initial *ic, double sample_dt_s,
                            tippe_dynamics_samples *samples, tippe_dynamics_result *res,
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
    /* NULL, or each group's holes' openings at the poles (tippe_launch_polar_caps: a
     * map's cells at different Z2), in place of the options' cap_half_angle_rad */
    const double (*caps_rad)[2];
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
    /* Over every launch, whatever its verdict (the patch law's flips that fall back and
     * end as observed hangs): how many passed pi/2 (t_flip_s set) and the median time,
     * how many of those came back below it (t_fall_s set) and the median time (NAN if
     * none). */
    long passed, fell;
    double median_t_passed_s, median_t_fall_s;
    /* Trapped decisions (no_tip, tip, hang): how many, how many of them in a well
     * with no barrier, and the smallest barrier gap / margin of the others
     * (INFINITY if none). */
    long trapped, trapped_no_barrier;
    long rolling; /* decided rolling for ever (Coulomb friction with sticking) */
    double min_gap_over_margin;
    /* launches whose contact lay within a hole's opening at a pole at some time
     * up to their verdict (cap_first_s finite): the model does not hold there */
    long on_cap;
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

/* ---- Sensitivity to the patch radius (issue 27; docs/dynamics.md, "Radius sensitivity")
 * The patch radius is uncertain (surface finish, the table, wear): under the patch law a
 * launch (or a batch of launches, with the same draws) is run again at 1/F and F times the
 * radius it used (F the options' span, 2 by default: 0.5x and 2x), and called robust to
 * the radius only when every launch makes the same passage over pi/2 (t_flip set or not),
 * the same fall back (t_fall set or not), loses contact or not alike, and gives the same
 * verdict where both verdicts were decided (an observed verdict, a snapshot at t_end of a
 * top that rocks on, is not compared: it is not converged), at all three radii. */
enum { TIPPE_LAUNCH_RADIUS_RUNS = 3 };
/* The span F when the options leave it 0: runs at 0.5x and 2x. */
#define TIPPE_LAUNCH_RADIUS_SPAN 2.0
/* The span F of o (o->patch_radius_span if > 1, else TIPPE_LAUNCH_RADIUS_SPAN). */
double tippe_launch_radius_span(const tippe_launch_options *o);
/* The factors on the used radius, in run order: 1/F, 1 (the plain run), F. */
double tippe_launch_radius_factor(const tippe_launch_options *o, int i);

/* The patch radius a launch of top under o uses, m: o->patch_radius_m if > 0, else Hertz's
 * at m g from o->patch_E_star_pa; 0 for the other laws. */
double tippe_launch_patch_radius(const tippe_top *top, const tippe_launch_options *o);

/* *out = *o with the patch radius factor times the used one (given, not Hertz). 1 if that
 * radius is beyond what the dynamics accepts (R/2: not run), else 0. */
int tippe_launch_radius_options(const tippe_top *top, const tippe_launch_options *o,
                                double factor, tippe_launch_options *out);

typedef struct {
    double factor, radius_m;
    int ran;                 /* 0: not run, the radius exceeds R/2 */
    long n;                  /* launches */
    long counts[TIPPE_LAUNCH_N_VERDICTS];
    long passed, fell;       /* launches that passed pi/2; of those, came back below */
    double median_t_flip_s, median_t_fall_s; /* over those (NAN if none) */
    tippe_launch_record first; /* launch 0: tippe check's one launch */
} tippe_launch_radius_run;

typedef struct {
    tippe_launch_radius_run run[TIPPE_LAUNCH_RADIUS_RUNS]; /* 1/F, 1x, F */
    long changed; /* launches whose outcome (verdict, flip, fall) differs between radii */
    int robust;   /* all three ran and changed == 0 */
} tippe_launch_radius_sensitivity;

/* Summarises three runs of the same n launches (rec[i] at radius_m[i], rec[i] NULL: not
 * run). TIPPE_ECOMPUTE if out of memory. */
int tippe_launch_radius_summary(const tippe_launch_record *const rec[TIPPE_LAUNCH_RADIUS_RUNS],
                                long n, const double radius_m[TIPPE_LAUNCH_RADIUS_RUNS],
                                tippe_launch_radius_sensitivity *out, tippe_error *err);

/* One launch ic (tippe check) at the three radii. plain: the launch already run under o
 * (used as the middle run), or NULL to run it here. TIPPE_EINPUT if o is not the patch
 * law; otherwise the status of a run that failed. */
int tippe_launch_radius_sensitivity_initial(const tippe_top *top, const tippe_launch_options *o,
                                            const tippe_dynamics_initial *ic,
                                            const tippe_launch_record *plain,
                                            tippe_launch_radius_sensitivity *out,
                                            tippe_error *err);


/* The contact is at rest at a launch when its slip is below this fraction of the
 * speed scale R |omega| + |v| (rounding: the terms of V_Q are of that size and
 * cancel to ~1e-16 of it where they cancel at all). */
#define TIPPE_LAUNCH_SLIP_ROUNDING_REL 1e-12

/* How a launch state slides, in words for the launch lines of check, simulate,
 * animate: "no sliding (contact at rest)" only where the slip
 * (tippe_dynamics_launch_slip) is 0 to rounding; otherwise "centre at rest (U = V =
 * 0), contact slip 0.0222 m/s" or "centre sliding at 0.05 m/s (U 0.03, V 0.04 m/s),
 * contact slip 0.071 m/s". *slip_m_s (may be NULL) gets the slip. Returns buf. */
const char *tippe_launch_slip_text(const tippe_top *top, const tippe_dynamics_initial *ic,
                                   double *slip_m_s, char *buf, size_t size);

/* The contact modulus E* of a design's ball (the materials table's E_GPa and nu of its
 * sphere's material) on a table surface (NULL: TIPPE_CONTACT_DEFAULT_TABLE), for the
 * Hertz patch at m g. TIPPE_EINPUT naming what is missing (then give the radius). */
int tippe_launch_patch_modulus(const tippe_design *d, const char *table, double *E_star_pa,
                               tippe_error *err);


/* ---- reports of launches (tippe's --json, tippe serve) ---- */
struct cJSON;
/* The model of a launch's options: law, coefficients, g (no top). */
void tippe_launch_friction_model(const tippe_launch_options *o, tippe_dynamics_model *m);
/* A launch's options: the hand-launch distribution (without the spin's when
 * fixed_spin), the friction, g, t_end and the accuracy. NULL if out of memory. */
struct cJSON *tippe_launch_options_json(const tippe_launch_options *o, int fixed_spin);
/* The radius sensitivity as JSON: {"robust", "changed", "runs": [{"factor", "patch_mm",
 * "ran", and for one launch (one_launch) "verdict", "t_s", "theta_final_rad", "t_flip_s",
 * "t_fall_s", "inverted_time_s", else "counts" {verdict: n}, "passed_pi_2", "fell_back",
 * "median_t_flip_s", "median_t_fall_s"}]}. NULL if out of memory. */
struct cJSON *tippe_launch_radius_json(const tippe_launch_radius_sensitivity *s, int one_launch);


/* ---- the friction options' rules (src/launch/friction_options.c) ---- */
/* The friction options as a front end was given them (its names mapped onto the
 * parameters): which were given, and the values the rules need. */
typedef struct {
    const char *laws;   /* the law, or (names.list) several comma-separated; NULL: none */
    unsigned given;     /* bits 1 << tippe_friction_param_id of the parameters given */
    double patch_mm;    /* when given */
    const char *table;  /* when given */
} tippe_friction_given;

/* How a front end names the parameters in its messages ("--patch-mm" or "patch_mm"),
 * says "choose the law L" (a format with one %s: "--friction %s"), and whether the
 * law may be a list (tippe check compares laws). */
typedef struct {
    const char *name[TIPPE_LAW_N_PARAMS];
    const char *choose;
    int list;
} tippe_friction_names;

/* The rules of the friction options, one place for both front ends: the laws named
 * (or, with none, the law a coefficient given alone names: mu the viscous, mu_c or
 * slip_scale Coulomb's, patch_mm or table the patch law; else o->law), each parameter
 * given belongs to a law among them, one of patch_mm and table, a known table. Fills
 * laws[0 .. *n_laws - 1] (room for TIPPE_MAX_FRICTION_LAWS), o->law (the first) and
 * o->patch_radius_m. TIPPE_EINPUT naming the parameter in err->field (its key) and,
 * in the message, by names. */
int tippe_friction_choose(const tippe_friction_given *g, const tippe_friction_names *names,
                          tippe_friction_law *laws, int *n_laws, tippe_launch_options *o,
                          tippe_error *err);
/* The rules that need the design, where one of laws[0 .. n_laws - 1] has a patch: the
 * radius sensitivity's span is the design's tolerance unless given (o->patch_radius_span
 * > 0), a given radius (o->patch_radius_m) is at most half the ball's radius, else the
 * radius is Hertz's on table (NULL: TIPPE_CONTACT_DEFAULT_TABLE; o->patch_E_star_pa,
 * tippe_launch_patch_modulus). Nothing under the other laws. TIPPE_EINPUT with
 * err->field, the parameter named by names in the message. */
int tippe_friction_for_design(const tippe_design *d, const tippe_friction_law *laws, int n_laws,
                              const char *table, const tippe_friction_names *names,
                              tippe_launch_options *o, tippe_error *err);

/* ---- a map's grid (tippe map; src/launch/launch_grid.c) ----
 * Hand launches over a grid of Z2 and spin (tippe_launch_plan's groups are its cells,
 * cell (i, j) at z2_mm[i] and spin_rev_s[j] is i * n_spin + j), with the patch law's
 * reruns at 1/F and F times the radius. The front end runs the plan (and the reruns)
 * where it likes, on threads or ranks; making the grid and tallying it are here. */
typedef struct {
    int n_z2, n_spin;
    long per_cell, n_cells, total;  /* launches per cell, cells, launches */
    double *z2_mm, *spin_rev_s;     /* the grid's values */
    tippe_top *tops;                /* the top at each Z2 */
    /* 1 where a part stands out of the sphere at z2_mm[i]: the top rests on it and the
     * model does not apply (docs/design-format.md) */
    unsigned char *model_invalid;
    tippe_top *cell_tops;           /* each cell's top, spin and holes' openings: the plan */
    double *cell_spin_rad_s;
    double (*cell_caps)[2];
    tippe_launch_record *rec;       /* the plan's launches, cell after cell */
    tippe_launch_tally *cells;      /* each cell's tally (tippe_launch_grid_tally) */
    /* the patch law's radius sensitivity: the same launches at 1/F ([0]) and F ([2])
     * times the radius, the plain run being rec ([1]); NULL where not run (a radius
     * beyond R/2) */
    int radius_runs;
    tippe_launch_record *rec_radius[TIPPE_LAUNCH_RADIUS_RUNS];
    double radius_m[TIPPE_LAUNCH_RADIUS_RUNS], factor[TIPPE_LAUNCH_RADIUS_RUNS];
    long *cell_changed;          /* launches of each cell whose outcome differs between radii */
    long changed, cells_changed; /* their sum, and the cells with any */
} tippe_launch_grid;

/* The grid of d: n_z2 values from z2_from_mm to z2_to_mm, n_spin spins from
 * spin_from_rad_s to spin_to_rad_s (evenly, both ends; one value: the first), per_cell
 * launches each under o; the radius reruns if o's law has a patch and
 * radius_sensitivity. TIPPE_EINPUT (err->field "z2_mm") where d has no top at a Z2,
 * TIPPE_ECOMPUTE out of memory. Free with tippe_launch_grid_free, also on failure. */
int tippe_launch_grid_make(const tippe_design *d, double z2_from_mm, double z2_to_mm, int n_z2,
                           double spin_from_rad_s, double spin_to_rad_s, int n_spin,
                           long per_cell, const tippe_launch_options *o, int radius_sensitivity,
                           tippe_launch_grid *g, tippe_error *err);
/* The plan of its launches (into g->rec, or g->rec_radius[i] with the options of
 * tippe_launch_grid_radius_options). */
tippe_launch_plan tippe_launch_grid_plan(const tippe_launch_grid *g);
void tippe_launch_grid_radius_options(const tippe_launch_grid *g, const tippe_launch_options *o,
                                      int i, tippe_launch_options *out);
/* The launches to run, reruns included (for a progress bar). */
long tippe_launch_grid_work(const tippe_launch_grid *g);
/* After the runs: each cell's tally and, with the reruns, what changed between radii.
 * TIPPE_ECOMPUTE if out of memory. */
int tippe_launch_grid_tally(tippe_launch_grid *g, tippe_error *err);
/* The tallied grid as a map (for tables and plots). */
tippe_launch_map tippe_launch_grid_map(const tippe_launch_grid *g);
void tippe_launch_grid_free(tippe_launch_grid *g);
#endif
