/* tippe/scenario.h: a launch described by a scenario file (JSON), for `tippe simulate`.
 *
 * docs/dynamics.md describes the format. In short:
 *   {"name": "...", "notes": "...",
 *    "top": {"m": kg, "R": m, "eps": m, "A": kg m^2, "C": kg m^2}
 *        or {"design": "path/to/design.json", "z2_mm": 10, "set": ["FIELD=VALUE", ...]},
 *    "g": 9.81, "mu": s/m (viscous, eq 3.12) or "friction": {"law": "viscous", "mu_s_m": s/m}
 *        | {"law": "coulomb" | "coulomb-creep", "mu": 0.3, "slip_scale_m_s": 1e-5},
 *    "initial": {"theta": rad, "theta_dot": rad/s, "phi_dot": rad/s | "steady" | "s1" |
 *                "s2" | "s3", "spin": rad/s, "U": m/s, "V": m/s},
 *    "t_end": s, "accuracy": "fast" | "balanced" | "precise" | {"stepper": "...", "rtol": ...}}
 * A design path is relative to the scenario file's directory (or absolute).
 * Parsing is strict: keys are case-sensitive, unknown and duplicate keys are
 * rejected, and every error names the file, the JSON path and what is wrong. */
#ifndef TIPPE_SCENARIO_H
#define TIPPE_SCENARIO_H

#include "tippe/design.h"
#include "tippe/launch.h"
#include "tippe/base.h"

enum { TIPPE_PHI_DOT_GIVEN = -1 }; /* phi_dot_rule when phi_dot was a number */

typedef struct {
    char path[1024];
    char name[256];
    char design_path[1024]; /* resolved path, "" for an explicit top */
    double z2_mm;           /* NAN for an explicit top */
    /* a design's material standing out of its sphere at z2_mm (the model does
     * not apply there: tippe_design_protrusion_at); zero for an explicit top */
    tippe_design_protrusion protrusion;
    /* a design's holes' openings at the pole it rests on at theta = 0 and at the
     * other (tippe_launch_polar_caps), rad; 0 for an explicit top */
    double cap_half_angle_rad[2];
    tippe_dynamics_model model;
    /* a design top: its ball's elastic constants (Pa; 0 if the materials table has none)
     * and material, for the patch law's Hertz radius */
    double ball_E_pa, ball_nu;
    char ball_material[64];
    tippe_dynamics_initial initial; /* phi_dot resolved from its rule */
    int phi_dot_rule;               /* TIPPE_PHI_DOT_GIVEN or a tippe_precession_rule */
    double t_end;                   /* s */
    tippe_dynamics_accuracy accuracy;
    char accuracy_name[16];         /* the preset's name, or "custom" */
    /* a design top: the design as loaded (with its "set" list), for what else a
     * front end shows of it (a film's weight) without reading it again; NULL for
     * an explicit top. Owned: tippe_scenario_free. */
    tippe_design *design;
} tippe_scenario;

/* Frees what a loaded scenario owns (its design); the struct itself is the
 * caller's. A failed load leaves nothing to free. */
void tippe_scenario_free(tippe_scenario *s);

/* Loads path, applies the overrides ("mu=0.1", "initial.spin=3",
 * "initial.phi_dot=steady", "accuracy=precise", "accuracy.rtol=1e-9",
 * "top.z2_mm=12"; VALUE is read as JSON, or as a string if it is not JSON),
 * then validates. TIPPE_EINPUT for a bad file or override (the message names
 * the file, the JSON path and what is wrong, and ends with "(set on the command
 * line: FIELD=VALUE)" when an override set that path), TIPPE_ECOMPUTE otherwise.
 * A precession a rule derives ("steady", ...) must lie in the range a number
 * may (|phi_dot| <= 1e6 rad/s): the rule divides by cos(theta), so a tilt near
 * pi/2 (or else a spin) that makes it larger is refused, naming initial.theta
 * (or initial.spin). */
int tippe_scenario_load(const char *path, const char *const *overrides, int n_overrides,
                        tippe_scenario *out, tippe_error *err);

/* The same for path's text, read already (len bytes) by a caller that had to
 * look into the file first (a scenario or a design?); path names it in
 * messages and is where a design it names is found from. */
int tippe_scenario_load_text(const char *path, const char *text, size_t len,
                             const char *const *overrides, int n_overrides, tippe_scenario *out,
                             tippe_error *err);

/* The scenario of a design's central hand launch with its weight at z2_mm,
 * without a scenario file: the design (with design_sets applied, as
 * tippe_design_load) and the defaults of tippe launch (docs/launch.md): tilt
 * TIPPE_LAUNCH_HALF_NORMAL_MEDIAN x 0.1 rad, steady precession, spin 15 rev/s,
 * centre at rest, the launch options' friction (viscous mu 2.3 s/m, eq 3.12), g, t_end
 * 600 s, preset "balanced"; then the
 * overrides as for tippe_scenario_load ("initial.spin=100"). Messages name the
 * design file. design_text: the design file's text when the caller has read it
 * already (design_len bytes), else NULL and the file is read. */
int tippe_scenario_for_design(const char *design_path, const char *design_text,
                              size_t design_len, double z2_mm,
                              const char *const *design_sets, int n_design_sets,
                              const char *const *overrides, int n_overrides,
                              tippe_scenario *out, tippe_error *err);

/* "steady", "s1", "s2", "s3", or "given". */
const char *tippe_scenario_phi_dot_rule_name(int rule);

#endif
