/* tippe/build.h: from a design's zones to what a maker sets, buys and prints.
 *
 * For each behaviour the zones offer (stays up: group I; flips: group II;
 * hangs: group III) the build sheet takes the widest run of Z2 within the
 * physical travel (tippe/sweep.h) and shrinks it by the tolerance bands at
 * its ends (tippe/sweep.h): the robust range, where the behaviour holds
 * whatever the tolerances do (to first order). It converts Z2 into what one
 * measures: the depth of the weight's end below the rim of the hole it is
 * screwed into (a caliper's depth rod rests on the rim), or below the top end
 * of the rod it is screwed onto, and the turns of its thread from flush (the
 * pitch from the hardware catalogue, else ISO 261's coarse pitch). It gives
 * the spin needed there from Theorem 5.1's thresholds (tippe/physics.h) and
 * runs one central hand launch (tippe/physics.h, the check verb's) at a spin
 * above it, whose verdict is reported beside the behaviour it should give.
 *
 * Units: mm, rev/s in the sheet (the maker's); the library's SI inside. */
#ifndef TIPPE_BUILD_H
#define TIPPE_BUILD_H

#include <stdio.h>

#include "tippe/design.h"
#include "tippe/launch.h"
#include "tippe/base.h"

/* ISO 261 coarse-pitch metric threads (ISO 724 basic profile): the design
 * module's table (tippe/design.h), which the part as made reads too. */
typedef tippe_design_thread tippe_build_thread;

/* The ISO 261 coarse thread of nominal diameter d_mm (within 1e-6 mm), or NULL. */
const tippe_build_thread *tippe_build_thread_by_diameter(double d_mm);
/* The one whose pitch diameter d2 = d - 0.649519 P (ISO 724) is nearest d2_mm. */
const tippe_build_thread *tippe_build_thread_by_pitch_diameter(double d2_mm);
/* Tap drill for a full-form internal thread: d - P (ISO 2306's rule for
 * metric threads, about 77 % thread engagement). */
double tippe_build_tap_drill_mm(const tippe_build_thread *t);

/* The hardware catalogue (designs/catalogue.json): an object of named sets
 * ("iso4026"), each {"title", "source", "notes", "items": [...]}, each item a
 * screw {"name", "thread", "d_mm", "pitch_mm", "radius_mm", "height_mm" and,
 * optional, "length_mm", "socket_s_mm", "socket_t_mm"}. Read strictly, as a
 * design is: unknown or repeated keys, a missing or mistyped field, an empty
 * or repeated item name, a control character in a name are refused, and a
 * thread must be one that can be made: d_mm within ISO 261's diameters
 * (1 .. 300 mm), pitch_mm within its pitches (0.2 .. 6 mm) and at most d/4
 * (the coarsest ISO 261 pitch of a size never passes a quarter of its
 * diameter: M1 x 0.25), so the tap drill d - P is at least 3d/4; a "thread"
 * written "M10" names d_mm = 10; radius_mm (the screw modelled as a cylinder of
 * its pitch diameter) at most d/2, lengths positive and at most
 * TIPPE_BUILD_SCREW_MAX_MM. */
#define TIPPE_BUILD_THREAD_D_MIN_MM 1.0
#define TIPPE_BUILD_THREAD_D_MAX_MM 300.0
#define TIPPE_BUILD_THREAD_PITCH_MIN_MM 0.2
#define TIPPE_BUILD_THREAD_PITCH_MAX_MM 6.0
#define TIPPE_BUILD_SCREW_MAX_MM 1000.0
typedef struct {
    char name[64];                   /* "M10x12" */
    char thread[16];                 /* "M10" */
    double d_mm, pitch_mm;           /* the thread */
    double radius_mm, height_mm;     /* the screw as a design models it */
    double length_mm;                /* nominal length; NAN: not given */
    double socket_s_mm, socket_t_mm; /* hexagon socket; NAN: not given */
} tippe_build_catalogue_item;
typedef struct {
    char key[64];    /* "iso4026" */
    char title[160]; /* its "title", else its key */
    int n_items;
    tippe_build_catalogue_item *items;
} tippe_build_catalogue_set;
typedef struct {
    char file[1024];
    int n_sets;
    tippe_build_catalogue_set *sets;
} tippe_build_catalogue;

/* Reads the catalogue file path: TIPPE_EINPUT with "FILE: JSON.PATH: what is
 * wrong" for anything above. tippe_build_catalogue_free() the result. */
int tippe_build_catalogue_load(const char *path, tippe_build_catalogue **out, tippe_error *err);
/* Where a design's hardware catalogue is, one rule for tippe build, tippe serve
 * and tippe optimise: the design's own "catalogue" when it names one, else
 * catalogue.json in its folder (tippe_design_beside), when that file can be
 * read, else the shipped catalogue for a design that reads the shipped materials
 * table (tippe_design_shipped_catalogue); NULL: no catalogue. buf holds the second
 * when the third is not used (where a catalogue would be looked for, for a message). */
const char *tippe_build_catalogue_file(const tippe_design *d, char *buf, size_t size);
void tippe_build_catalogue_free(tippe_build_catalogue *c);
/* The first item (in file order) of radius_mm and height_mm (within 1e-6
 * mm), else the first whose thread the radius can be (from the item's modelled
 * pitch radius to its nominal d/2) and whose length is within js15 (ISO 4759-1
 * grade A) of height_mm; its set in *set (if not NULL); NULL when none matches. */
const tippe_build_catalogue_item *tippe_build_catalogue_match(const tippe_build_catalogue *c,
                                                              double radius_mm, double height_mm,
                                                              const tippe_build_catalogue_set **set);

/* The first item (in file order) named name, and its set in *set (if not
 * NULL); NULL when none is. */
const tippe_build_catalogue_item *tippe_build_catalogue_find(const tippe_build_catalogue *c,
                                                             const char *name,
                                                             const tippe_build_catalogue_set **set);

/* How the weight's place is measured. */
typedef enum {
    TIPPE_BUILD_MEASURE_NONE, /* no hole or rod on the axis found: Z2 only */
    TIPPE_BUILD_MEASURE_HOLE, /* weight's end below the rim of a hole in a printed body */
    TIPPE_BUILD_MEASURE_ROD   /* weight's end below the top end of a fixed rod */
} tippe_build_measure;

typedef struct {
    int reachable;                 /* the group has a run within the physical travel */
    int robust;                    /* its robust width is > 0 */
    double from_mm, to_mm;         /* the widest run (nominal) */
    double band_from_mm, band_to_mm; /* tolerance band at each end (0 at the travel's end) */
    double robust_from_mm, robust_to_mm; /* the run less its bands */
    double set_z2_mm;              /* the middle of the robust range (of the run if none) */
    /* depths (mm, positive below the reference) at robust_from, set, robust_to;
     * NAN without a reference */
    double depth_from_mm, depth_set_mm, depth_to_mm;
    double turns_from, turns_set, turns_to; /* depth / pitch; NAN without a pitch */
    /* spin the behaviour needs (rev/s): at set_z2 and the largest over the robust
     * range (0: any spin, group I) */
    double spin_needed_rev_s, spin_needed_max_rev_s;
    const char *spin_rule;         /* "any spin (theta = 0 stable)", "n0 > n*", "n0 > n-" */
    double spin_launch_rev_s;      /* the check's spin: 1.25 x spin_needed_rev_s (group I:
                                      the middle of the hand's range) */
    int beyond_hand;               /* spin_launch above the hand's range (launch options) */
    tippe_verdict verdict;         /* of the central launch at set_z2 */
    int launch_status;             /* TIPPE_OK or the dynamics' error */
    int verdict_ok;                /* the verdict is the behaviour's */
    double launch_t_s;             /* when it was decided */
    /* the launch's tilt at start and at its end, and the pole (+1, -1; 0: its
     * sphere) whose opening the top stands on then (tippe_design_cap_at_tilt);
     * rest_pole: the pole down at theta = 0 (the centre of mass's side) */
    double launch_theta0_rad, launch_theta_end_rad;
    int launch_cap_start, launch_cap_end, rest_pole;
    double launch_cap_time_s;      /* s the launch's contact spent on an opening, to launch_t_s */
    /* settable: a robust width of at least the sheet's min_setting_mm */
    double robust_width_mm;        /* robust_to - robust_from, 0 when none is robust */
    int settable;
    /* flips and hangs: the part of the range (robust, else nominal) whose needed
     * spin a hand reaches (at most the launch options' spin_to_rev_s): the
     * longest such run, its ends bisected; NAN when no part is (and for stays
     * up, which needs no spin) */
    double hand_from_mm, hand_to_mm;             /* Z2 */
    double depth_hand_from_mm, depth_hand_to_mm; /* as depth_from_mm, depth_to_mm */
} tippe_build_setting;

/* One line of the bill of materials. */
typedef struct {
    char what[256];    /* "set screw M10x12, ISO 4026 (DIN 913), brass" */
    char detail[320];  /* dimensions, hole, thread */
    int quantity;
} tippe_build_bom_line;

enum { TIPPE_BUILD_MAX_BOM = 16 };

/* How the hole that takes the screw is printed. */
typedef enum {
    TIPPE_BUILD_HOLE_TAP,    /* at the thread's tap drill, to be tapped */
    TIPPE_BUILD_HOLE_SLIDE,  /* the design's hole plus the clearance: a sliding fit */
    TIPPE_BUILD_HOLE_INSERT, /* at a heat-set insert's pilot hole (tippe_build_insert_for) */
    TIPPE_BUILD_HOLE_DESIGN  /* the hole's "fit" in the design file, else TAP (the default) */
} tippe_build_hole_fit;

/* A brass heat-set threaded insert for a metric thread: the pilot hole its
 * vendor says to make in a thermoplastic part, and its largest outer diameter
 * (non-flanged). Source: TIPPE_BUILD_INSERT_SOURCE; sizes M3 .. M6 only. */
typedef struct {
    const char *thread;   /* "M3" */
    double pilot_mm;      /* hole diameter (tolerance -0 / +0.1 mm) */
    double outer_max_mm;  /* the insert's knurl, at most */
    double length_mm;     /* a common insert's length (TIPPE_BUILD_INSERT_LENGTH_SOURCE):
                             the screw is held only where its thread is within it */
} tippe_build_insert;
#define TIPPE_BUILD_INSERT_LENGTH_SOURCE                                                   \
    "ruthex standard heat-set inserts M3x5.7, M4x8.1, M5x9.5, M6x12.7 (the length is in "    \
    "the part name; tools.creative3dp.com's heat-set insert chart gives the pocket depth as " \
    "the length plus 0.5 mm)"
#define TIPPE_BUILD_INSERT_SOURCE                                                          \
    "Accu Ltd, 'Threaded Heat-Set Insert Pilot Hole Size Charts for 3D Printing' "          \
    "(accu.co.uk/p/488), heat-set inserts, non-flanged"
/* The insert for thread (ISO name, "M3"), or NULL: the table has none. */
const tippe_build_insert *tippe_build_insert_for(const char *thread);

/* The screw's hole as the design's "fit" asks it printed (for tippe export,
 * which has no --hole): *part the hole's part index and *diameter_mm its
 * printed diameter when the fit is tap (the tap drill of the ISO 261 thread
 * nearest the screw's modelled pitch diameter) or insert (the insert's pilot
 * hole); *part = -1 when the design gives no fit or "slide" (the clearance
 * applies). note: why, for the drawing ("M10 x 1.5 tap drill"). TIPPE_EINPUT,
 * naming the file and the field, for a tap or insert fit on a hole that no
 * screw of the weight enters, or an insert the table does not have. */
int tippe_build_design_fit(const tippe_design *d, double clearance_mm, int *part,
                           double *diameter_mm, char *note, size_t note_size, tippe_error *err);

typedef struct {
    tippe_build_hole_fit hole_fit;
    double clearance_mm;     /* export's radial clearance of holes for hardware */
    const char *catalogue;   /* hardware catalogue file; NULL: the design's "catalogue",
                                if it names one, else none */
    /* the catalogue read already (the command reads it before any work, so that
     * a bad one is refused first); NULL: tippe_build_compute reads catalogue */
    const tippe_build_catalogue *catalogue_read;
    /* the narrowest robust width a maker can set, mm; 0: a quarter turn of the
     * weight's thread (pitch / 4), or TIPPE_BUILD_MIN_SETTING_MM without one */
    double min_setting_mm;
    tippe_launch_options launch;
} tippe_build_options;

/* The narrowest settable width where the weight has no thread, mm. */
#define TIPPE_BUILD_MIN_SETTING_MM 0.5

typedef struct {
    char design_name[256], design_file[1024];
    /* the overrides the design was loaded with (--set), so that the sheet says
     * what it was made of and a step that runs it again repeats them */
    int n_overrides;
    char override[16][256];
    double radius_mm;
    double travel_from_mm, travel_to_mm; /* physical travel */
    double design_travel_from_mm, design_travel_to_mm; /* the design's travel_mm */
    int three_in_one;
    /* 3-in-1 and every behaviour settable (its robust width at least
     * min_setting_mm); 3-in-1 without it is "3-in-1 on paper only" */
    int settable;
    double min_setting_mm;               /* the one used (options, else the rule) */
    char min_setting_rule[96];           /* "a quarter turn of the M12 x 1.75 thread" */
    double hand_spin_rev_s;              /* the fastest hand spin (launch options' spin_to) */
    /* the launch check's friction law and its words (tippe_dynamics_friction_text) */
    tippe_dynamics_model launch_model;
    char launch_friction[320];
    tippe_build_setting set[3];          /* I stays up, II flips, III hangs */
    /* measuring */
    tippe_build_measure measure;
    char reference[200];                 /* "the rim of hole 'hole' (printed 9.43 mm)" */
    double reference_z_mm;               /* its height above the centre */
    double hole_diameter_mm;             /* the hole as printed, or 0 */
    int hole_part;                       /* its part index (a void), or -1 */
    int hole_tapped;                     /* printed at the tap drill (hole_fit TAP) */
    int hole_insert;                     /* printed for a heat-set insert (INSERT) */
    int hole_fit_from_design;            /* the fit is the design file's "fit" */
    tippe_build_insert insert;           /* with hole_insert */
    char fit_note[64];                   /* why the hole is printed so ("M10 x 1.5 tap drill"),
                                            with hole_tapped or hole_insert */
    /* Weighing the print to calibrate its infill: the print model's mass of the
     * printed part with the hole as the mass model has it, less the same with
     * the hole as printed (same infill): add it to the scale's reading before
     * giving measured_mass_g. NAN when not applicable (no print block, no hole). */
    double weigh_offset_g;
    /* the part as made (tippe_build_as_made): the --set the zones were computed with
     * ("parts.hole.printed_radius_mm=5.125"), or "" when the design is as made */
    char as_made_set[300];
    double rod_diameter_mm;              /* the rod the weight is threaded on, or 0 */
    int reference_up;                    /* 1: the reference faces +z (depth = ref - top end) */
    double weight_end_offset_mm;         /* the measured end of the weight above Z2 */
    char weight_name[128];
    /* the weight's thread */
    int has_thread;
    tippe_build_thread thread;           /* d_mm, pitch_mm (name: NULL, see thread_name) */
    char thread_name[16];                /* "M10" */
    char catalogue_item[64];             /* "M10x12" when matched, else "" */
    char catalogue_title[160];
    double tap_drill_mm;
    int thread_assumed;                  /* 1: no catalogue match, the nearest ISO size */
    int n_bom;
    tippe_build_bom_line bom[TIPPE_BUILD_MAX_BOM];
    char note[6][480];                   /* facts a maker should know */
    int n_notes;
    /* how each printed part is printed (its print block, or solid) */
    int n_print;
    struct {
        char part[64], material[64];
        int has_block;                   /* 0: no print block: modelled solid (100 %) */
        tippe_print_settings settings;
        double infill;                   /* used by the model (calibrated or the slicer's) */
        int calibrated;
        /* the model's part as made (its zones'): its mass, and what the tap cut
           from its hole after printing (0: none); 0 both for a part modelled solid */
        double printed_mass_kg, cut_mass_kg;
    } print[4];
    int needs_split;                     /* the printed body closes around hardware */
    int rod_sockets;                     /* the rod is held by sockets at both poles
                                            (tippe_profile_options.sockets) */
    int joint_ring;                      /* split, and a cut face is wide enough for tippe
                                            export's joint ring (else the halves are glued
                                            without one) */
    /* Not settable: changes a maker can buy or set (an infill of the slicer's
     * list, a material of the table, a catalogue screw or a length in whole
     * mm), each tried by sweeping the changed design with its tolerance bands
     * as the sheet is (tippe_build_advise); pairs of them where no single one
     * makes it settable. */
    int n_advice;
    struct {
        int n_set;
        char set[8][200];     /* the --set overrides that make the change */
        int pair;             /* two changes together */
        int settable;         /* every behaviour's robust width >= min_setting_mm */
        double narrowest_mm;  /* the narrowest robust width of the three with it (0 if
                                 a behaviour is missing or has no robust range) */
        double min_setting_mm; /* the rule with it (a new thread has its own) */
        char text[480];
    } advice[6];
    /* how many changed designs were swept for the advice */
    int n_advice_tried;
    /* the poles where a hole opens (tippe_design_polar_caps at the drawn
     * setting), and fixes for them, each tried by sweeping the changed design
     * (verdict as tippe_build_verdict: 2 settable, 1 on paper, 0 not, -1 failed) */
    int n_caps;
    tippe_design_cap caps[2];
    /* the opening as made when the hole is tapped (the thread's diameter) or
     * takes an insert (its knurl): diameter and half-angle; 0 when as modelled */
    double cap_made_mm[2], cap_made_half_angle_rad[2];
    int n_pole_fixes;
    struct {
        char text[900];
        int n_set;
        char set[3][200];
        int verdict;
        double narrowest_mm;
    } pole_fix[2];
    /* a printed part not yet weighed: the step to weigh it and run again when
     * the verdict differs within its infill tolerance, else a note that
     * weighing would not change it ("" for none) */
    char weigh_step[1600], weigh_note[400];
    int n_steps;
    char step[10][1600];                /* assembly steps, in order */
    /* each setting narrower than min_setting_mm, and each flips or hangs range
     * whose part a hand's spin reaches is narrower */
    int n_warnings;
    char warning[6][400];
} tippe_build_sheet;

/* The design file's name without directory and extension: the stem tippe build
 * (and tippe export, by the same rule in the export module) names its files with. */
void tippe_build_stem(const char *design_path, char *out, size_t size);

/* Whether the design's printed body closes around its hardware, so that it
 * must be printed in halves (tippe export --split). */
int tippe_build_needs_split(const tippe_design *d, double clearance_mm);

void tippe_build_options_default(tippe_build_options *o);

/* Everything above. TIPPE_EINPUT for a design that cannot be swept or a
 * catalogue that does not read; a launch that fails is recorded in its
 * setting (launch_status), not returned. */
int tippe_build_compute(const tippe_design *d, const tippe_build_options *o,
                        tippe_build_sheet *out, tippe_error *err);
/* The part as made for sheet s of d (both sheet builders use it): a hole printed
 * at its tap drill, narrower than the mass model's, is tapped after printing,
 * so its part's print model lays the walls from the printed hole and the tap
 * cuts what lies inside the model's radius (printed_radius_mm,
 * docs/printing.md). *made: d with the hole's printed_radius_mm set, or NULL
 * when d is already the part as made (the hole printed at its radius, wider,
 * or the design gives its own). */
int tippe_build_as_made(const tippe_design *d, const tippe_build_sheet *s, tippe_design **made,
                        tippe_error *err);
/* The verdict alone, as tippe_build_compute gives it (three_in_one, settable,
 * each setting's reachable, robust range and settable, min_setting_mm and its
 * rule, the thread and the hole's fit), without the settings' launch checks,
 * the bill, the steps, the poles' fixes or the advice: about the cost of a
 * sweep with its bands, where the whole sheet costs 40 to 90 times that
 * (tippe serve's /api/verdict, asked after every edit: docs/serve.md). The
 * rest of the sheet is left zero. */
int tippe_build_compute_verdict(const tippe_design *d, const tippe_build_options *o,
                                tippe_build_sheet *out, tippe_error *err);

/* The sheet's first line after its title: the file, the --set changes, the
 * sphere and the weight's travel (the design's, and what its parts allow). */
void tippe_build_header_text(const tippe_build_sheet *s, char *buf, size_t size);

/* "; contact INVALID: starts on the hole's rim at +z" for a launch check that
 * starts or ends on a pole's opening, else "". */
const char *tippe_build_cap_text(const tippe_build_setting *x);

/* The launch check of setting k as the sheet's table gives it: "tip at 8.6 rev/s (as
 * expected); starts on the hole's rim at +z (modelled)", or "not run". */
void tippe_build_launch_text(const tippe_build_sheet *s, int k, char *buf, size_t size);

/* Advice k's overrides as a command line's options: "--set A --set B". */
void tippe_build_advice_sets(const tippe_build_sheet *s, int k, char *buf, size_t size);
/* The heading over the advice, and the sentence for none found. */
const char *tippe_build_advice_heading(const tippe_build_sheet *s);
const char *tippe_build_advice_none(void);

/* 1 when a launch check starts or ends on a hole's opening at a pole, where
 * the model (zones and launches) does not hold: the verdict's sentence says so. */
int tippe_build_poles_invalid(const tippe_build_sheet *s);

/* The sheet's verdict: "3-in-1 and settable", "3-in-1 on paper only" or
 * "not 3-in-1". */
const char *tippe_build_verdict(const tippe_build_sheet *s);
/* The verdict as a sentence with its reason (Markdown, the page). */
void tippe_build_verdict_text(const tippe_build_sheet *s, char *buf, size_t size);

/* The settings table's spin cell of family f: "any", or "above 7.2 rev/s (29.9
 * at the range's worst end); a hand (up to 25 rev/s) reaches it at depth 1.03
 * .. 9.10 mm". */
void tippe_build_spin_text(const tippe_build_sheet *s, int f, char *buf, size_t size);

/* "stays up", "flips", "hangs" for 0, 1, 2; the group's name "I", "II", "III". */
const char *tippe_build_behaviour(int family);
const char *tippe_build_family(int family);

/* Reports: the sheet as a cJSON object, and as Markdown a maker reads. */
struct cJSON;
struct cJSON *tippe_build_json(const tippe_build_sheet *s);
void tippe_build_markdown(FILE *f, const tippe_build_sheet *s);

/* Depth gauges, one per setting, printed flat side down:
 * - a screw in a hole: a flat disc (GAUGE_FLANGE_MM thick, 8 mm wider than the
 *   hole) with a pin on its face, pin_mm long (the setting's depth below the
 *   rim) and of tippe_build_gauge_pin_diameter_mm: put the pin in the hole, the
 *   disc on the rim, and turn the screw until it touches the pin's end;
 * - a bead on a rod: a sleeve pin_mm long (the depth below the rod's end) that
 *   slides over the rod (0.25 mm radial play): the bead is set when the sleeve,
 *   standing on it, is flush with the rod's end.
 * A gauge exists for a reachable setting whose depth is at least
 * TIPPE_BUILD_GAUGE_MIN_MM (a screw standing out of the ball, or nearly flush,
 * is measured with the caliper). */
#define TIPPE_BUILD_GAUGE_MIN_MM 1.0
#define TIPPE_BUILD_GAUGE_FLANGE_MM 2.0
int tippe_build_gauge_applies(const tippe_build_sheet *s, int family, double *pin_mm);
/* A hole gauge's pin diameter: 1 mm narrower than the printed hole, and with a
 * heat-set insert 0.5 mm narrower than its thread's minor diameter (ISO 724). */
double tippe_build_gauge_pin_diameter_mm(const tippe_build_sheet *s);


#endif
