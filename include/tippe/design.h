/* tippe/design.h: a top as designed.
 *
 * Contents:
 * - the design file: load, --set overrides, sources, materials, layout and physical
 *   travel, the parts' accessors, polar caps (tippe_design_*, tippe_materials_*);
 * - tolerances: how far a built top may be from its file (tippe_tolerance_*).
 * A design at a Z2 gives the top physics takes (tippe_design_top: tippe/top.h).
 * A design's printed parts are built on tippe/print.h (solids, the print model, G-code). */
#ifndef TIPPE_DESIGN_H
#define TIPPE_DESIGN_H

#include <stddef.h>

#include "tippe/base.h"
#include "tippe/print.h"
#include "tippe/top.h"

/* ---- the design file (src/design/design*.c) ---- */
/* Design: a top described by a design file (JSON), placed at one Z2.
 *
 * A design file gives the sphere radius, named parts (solids of revolution
 * about the z axis, in mm, each of a material from a materials table in
 * g/cm^3) and the travel of the moving weight. docs/design-format.md is the
 * complete description of the format and of every check made at load.
 *
 * Z2 is the height of the moving group's reference point (the midpoint of the
 * moving weight) above the sphere's centre, in mm, as in the paper (section 6).
 * The library side is SI: tippe_design_top() fills a tippe_top in kg, m, kg m^2.
 *
 * A loaded design is read-only: tippe_design_top() and the other accessors may
 * be called from many threads at once on the same design. */

typedef struct tippe_design tippe_design; /* opaque */

/* Loads path, applies the overrides ("parts.rod.material=nylon",
 * "parts.weight.height_mm=5", "radius_mm=30"; parts addressed by name) to the
 * parsed file, then validates everything. On failure returns TIPPE_EINPUT (the
 * file or an override is wrong; the message names the file, the JSON path and
 * what is wrong) or TIPPE_ECOMPUTE, and *out is NULL. */
int tippe_design_load(const char *path, const char *const *overrides, int n_overrides,
                      tippe_design **out, tippe_error *err);

/* The same for path's text, read already (len bytes) by a caller that had to
 * look into the file first (a design or a scenario?): as tippe_design_load(path)
 * without reading the file again (its materials table, catalogue and G-code are
 * found from path's folder). */
int tippe_design_load_read(const char *path, const char *text, size_t len,
                           const char *const *overrides, int n_overrides, tippe_design **out,
                           tippe_error *err);

/* The same for a design file's text in memory (len bytes; tippe serve's
 * requests): name stands for the file in every message ("the design"), and the
 * materials table is materials_dir/materials.json (a "materials" field naming
 * any other file is refused: a design from memory names no file on disk). */
int tippe_design_load_text(const char *name, const char *text, size_t len,
                           const char *materials_dir, const char *const *overrides,
                           int n_overrides, tippe_design **out, tippe_error *err);

/* A G-code's body read from memory (tippe serve's upload, tippe_gcode_parse_buffer with
 * override_density), for the part of that name whose print.gcode names it: the part is
 * then printed as that G-code deposits it, as from a file (scaled to the part's density,
 * matched to the part, a weighed mass scaling its lines). */
typedef struct {
    char part[64];
    tippe_gcode_body body;
    /* its beads near the axis (tippe_gcode_parse_near), for the holes' cuts as a file's
     * G-code is cut; the loader keeps its own copy (the caller still frees these) */
    tippe_gcode_beads beads;
} tippe_design_gcode;

/* tippe_design_load_text with G-code bodies from memory (n_gcodes of them; kept for the
 * design's reloads); a part whose print.gcode has no body here is refused as a design
 * from memory names no file. */
int tippe_design_load_text_gcode(const char *name, const char *text, size_t len,
                                 const char *materials_dir, const tippe_design_gcode *gcodes,
                                 int n_gcodes, const char *const *overrides, int n_overrides,
                                 tippe_design **out, tippe_error *err);

/* d loaded again from its file or text with its overrides and then extra ones,
 * checked in full as at load (tippe_design_derive skips the layout). */
int tippe_design_reload(const tippe_design *d, const char *const *extra, int n_extra,
                        tippe_design **out, tippe_error *err);

/* The top with the moving weight's midpoint at z2_mm; TIPPE_EINPUT if z2 is
 * outside the stated travel (closed interval, 1e-9 mm slack for a sweep's
 * rounded steps) or not finite. */
int tippe_design_top(const tippe_design *d, double z2_mm, tippe_top *top, tippe_error *err);

/* Same, without the travel check: pure geometry, for sweeps that look beyond
 * the travel (where parts would overlap, the numbers are what the formulas give). */
void tippe_design_top_any(const tippe_design *d, double z2_mm, tippe_top *top);

/* The travel the design states (travel_mm). */
void tippe_design_travel_mm(const tippe_design *d, double *from_mm, double *to_mm);

/* The physical travel: the largest Z2 interval containing the stated travel in
 * which no moving part overlaps a fixed part, no moving part leaves the sphere
 * (unless may_protrude) and no protruding moving part has its centre outside
 * the sphere. Its ends are where moving parts touch fixed ones (or the sphere). */
void tippe_design_contact_travel_mm(const tippe_design *d, double *from_mm, double *to_mm);

/* The model (the paper's) lets the top touch the table only with its sphere.
 * Where some material stands out of the sphere (a setscrew screwed out past the
 * surface, a fixed part with may_protrude), the top rests on that part instead
 * whenever the contact point comes near it, and the model does not apply.
 * This is the Z2 interval in which every part stays within the sphere (up to
 * the 1e-6 mm contact tolerance); from > to when there is none (a fixed part
 * stands out at every Z2). A design loaded by tippe_design_derive has no
 * layout: its interval is unbounded. */
void tippe_design_sphere_only_mm(const tippe_design *d, double *from_mm, double *to_mm);

/* Where the top's material stands out of the sphere at Z2. */
typedef struct {
    double protrusion_mm; /* farthest distance beyond the sphere's surface; 0: none */
    char part[64];        /* the part standing out farthest ("" if none) */
    int pole;             /* +1 or -1: the z side of that point (the pole it is near) */
    /* The tilts theta (the paper's: 0 = resting on the centre of mass's side,
     * pi = inverted) for which the top rests on standing-out material rather
     * than on its sphere: the direction of the table, at polar angle alpha
     * from the +z pole, meets material at distance rho > R and polar angle beta
     * when |alpha - beta| < acos(R / rho). The hull over all such points, rad. */
    double theta_from_rad, theta_to_rad;
} tippe_design_protrusion;

/* Fills *out for the moving weight at z2_mm (any Z2, not only the travel);
 * returns 1 if some material stands out of the sphere (the model does not
 * apply: see tippe_design_sphere_only_mm), 0 if not (*out zeroed). */
int tippe_design_protrusion_at(const tippe_design *d, double z2_mm, tippe_design_protrusion *out);

/* "part 'screw' stands out of the sphere by 0.598 mm near the +z pole: the top
 * rests on it, not on its sphere, for theta 0 .. 24.8 deg", for reports. */
void tippe_design_protrusion_text(const tippe_design_protrusion *p, char *buf, size_t size);

/* The same as JSON fields of o: "model_valid" (true/false) and "protrusion"
 * (null, or {part, protrusion_mm, pole ("+z"/"-z"), theta_range_rad}). */
struct cJSON;
void tippe_design_protrusion_json(struct cJSON *o, const tippe_design_protrusion *p);

/* What limits the physical travel at each end, e.g. "part 'weight' touches part
 * 'shell'"; for messages. */
const char *tippe_design_contact_limit(const tippe_design *d, int upper);

const char *tippe_design_name(const tippe_design *d);
const char *tippe_design_path(const tippe_design *d);
double tippe_design_radius_mm(const tippe_design *d);

/* Mass of the moving group (moving parts less their voids), kg. */
double tippe_design_moving_mass_kg(const tippe_design *d);

/* One part, for reports. mass_kg is the part's contribution to the total:
 * negative for a void (the mass it removes from the part it is cut from).
 * role is "fixed", "moving" or "void". */
typedef struct {
    const char *name;
    const char *shape;    /* "ball", "shell", "cylinder", "tube", "torus" */
    const char *material; /* material name, "(inline)" for density_g_cm3, or the
                             parent's for a void */
    const char *role;
    const char *cut_from; /* a void's parent part, else NULL */
    double density_g_cm3;
    double mass_kg;
    double z_mm;          /* centre height; for a moving part, its offset from Z2 */
    int may_protrude;
    int printable;        /* 1: the material is printable filament; 0: bought
                             hardware, or a density given inline (see
                             tippe_design_part_printable) */
} tippe_design_part_info;

int tippe_design_n_parts(const tippe_design *d);
/* Fills *out for part i (0-based, file order); TIPPE_EINPUT if i is out of range. */
int tippe_design_part(const tippe_design *d, int i, tippe_design_part_info *out);

/* A hole's "fit" (docs/design-format.md): how it is printed for the screw it
 * takes. NONE when the file gives none (each verb keeps its default). */
enum {
    TIPPE_DESIGN_FIT_NONE = 0,
    TIPPE_DESIGN_FIT_TAP,    /* at the thread's tap drill, to be tapped */
    TIPPE_DESIGN_FIT_INSERT, /* at a heat-set insert's pilot hole */
    TIPPE_DESIGN_FIT_SLIDE   /* the design's hole plus the export clearance */
};
/* Part i's fit (NONE for i out of range). */
int tippe_design_part_fit(const tippe_design *d, int i);

/* ISO 261 coarse-pitch metric threads (ISO 724 basic profile): the table the
 * part as made (a tapped hole's tap drill) and the build sheet (tippe/build.h's
 * tippe_build_thread, the same type) read. */
typedef struct {
    const char *name;   /* "M10" */
    double d_mm;        /* nominal (major) diameter */
    double pitch_mm;    /* coarse pitch, ISO 261 */
} tippe_design_thread;
/* The ISO 261 coarse thread of nominal diameter d_mm (within 1e-6 mm), or NULL. */
const tippe_design_thread *tippe_design_thread_by_diameter(double d_mm);
/* The one whose pitch diameter d2 = d - 0.649519 P (ISO 724) is nearest d2_mm. */
const tippe_design_thread *tippe_design_thread_by_pitch_diameter(double d2_mm);
/* Tap drill for a full-form internal thread: d - P (ISO 2306's rule for
 * metric threads, about 77 % thread engagement). */
double tippe_design_tap_drill_mm(const tippe_design_thread *t);
/* A part's "catalogue_item": the name of the hardware catalogue's item it is
 * (tippe/build.h), or "" when it names none. */
const char *tippe_design_part_catalogue_item(const tippe_design *d, int i);
/* The design's "catalogue": the hardware catalogue file, resolved from the
 * design file's folder (checked readable at load); NULL when not given. */
const char *tippe_design_catalogue(const tippe_design *d);
/* name as the design finds a file it names (its materials table, catalogue):
 * relative to the design file's folder (tippe_path_beside), or in the designs
 * folder of a design from memory. TIPPE_EINPUT (buf cut) when it does not fit. */
int tippe_design_beside(const tippe_design *d, const char *name, char *buf, size_t size);
/* A design that reads the shipped materials table (no "materials" field, no
 * materials.json beside it: tippe_design_note) and has no "catalogue" field and no
 * catalogue.json beside it reads the shipped catalogue too, the one beside that table,
 * as tippe serve's designs do: its path into buf and 1, else 0 (also when unreadable). */
int tippe_design_shipped_catalogue(const tippe_design *d, char *buf, size_t size);

/* How part i is printed (docs/design-format.md, "Printed parts"). A part
 * without a print block is solid: printed = 0 and the rest is zero. */
typedef struct {
    int printed;
    tippe_print_settings settings; /* as given (settings.infill: the slicer's) */
    double wall_mm, skin_mm;       /* perimeters x line width, layers x layer height */
    double infill;                 /* used: settings.infill, or calibrated */
    int calibrated;                /* infill solved from measured_mass_kg */
    double measured_mass_kg;
    double solid_mass_kg;          /* the printed part (part less its voids) if solid */
    double skin_mass_kg;           /* its walls and top/bottom skins alone (0 % infill) */
    double printed_mass_kg;        /* as printed, at `infill` */
    double rel_error;              /* bound on the print model's relative error in the
                                      part's mass and moments (QAGS estimates) */
    /* what is deposited, by the model in use (the slicer's rules: spacing-wide
     * lines; the continuous rule: walls and skins together in skin_mass_kg) */
    const char *model;             /* "slicer", "skins" or "gcode" */
    double filament_volume_mm3;    /* printed mass / density: the slicer's estimate */
    double wall_mass_kg, solid_infill_mass_kg, sparse_mass_kg, anchor_mass_kg;
    double cut_mass_kg;            /* the layer model's: what the cut after printing takes
                                      from holes printed narrower (printed_radius_mm); the
                                      masses above are before it, printed_mass_kg after */
    int n_layers;                  /* 0 for the continuous rule */
    double body_A_over_C;          /* the printed part alone, about its own centre of mass */
    /* print.gcode: the part from the slicer's G-code, the layer model beside it */
    int from_gcode;
    const char *gcode;             /* as given in the design (relative to it) */
    const char *generator;         /* the slicer that wrote it, "" if it does not say */
    double gcode_cut_mass_kg;      /* its plastic inside the design's holes, taken as cut
                                      away after printing (tapped, drilled, bored) */
    const char *gcode_note;        /* its holes against the design's ("" when they agree) */
    double gcode_support_mass_kg;  /* its support and support interface lines, left out of
                                      the part (removed after printing) */
    double flow_factor;            /* a weighing's scale on the G-code's lines (1: none) */
    double model_mass_kg;          /* the layer model's mass at the same infill */
    double model_body_A_over_C;
} tippe_design_print_info;

/* Fills *out for part i; TIPPE_EINPUT if i is out of range. */
int tippe_design_part_print(const tippe_design *d, int i, tippe_design_print_info *out);

/* Whether part i (0-based, file order) is made of a printable filament: its
 * material's "printable" flag in the materials table (a void: its parent's).
 * 0 for bought hardware, for a material without the flag, for a density given
 * inline and for i out of range. */
int tippe_design_part_printable(const tippe_design *d, int i);

/* The elastic constants of the material the table touches: the first fixed ball or
 * shell part's (the sphere's surface), from the materials table's E_GPa and nu (Pa and
 * dimensionless), and its material's name. 1 if the table gives them, else 0. */
int tippe_design_ball_elastic(const tippe_design *d, double *E_pa, double *nu,
                              const char **material);

/* d's file loaded again with d's overrides and then extra ones, every field
 * checked but not the layout (overlaps, travel, the sphere's surface): for
 * sensitivities, where a tolerance may move a part a fraction of a mm into
 * its neighbour. The result has no physical travel (use its geometry only). */
int tippe_design_derive(const tippe_design *d, const char *const *extra, int n_extra,
                        tippe_design **out, tippe_error *err);

/* The value of a number field as --set addresses it ("radius_mm",
 * "parts.screw.height_mm", "parts[2].z_mm"; a part's density_g_cm3 whether
 * given inline or by material) in the loaded design. *part_index is the part,
 * or -1 for radius_mm. TIPPE_EINPUT with why filled (no such part, not a
 * number field of that shape, a height the clip decides, the radius of the
 * part forming the sphere, a void's density). */
int tippe_design_field(const tippe_design *d, const char *field, double *value, int *part_index,
                       char *why, size_t why_cap);

/* The length fields part i has in the file (not the sphere's radius for the
 * part forming the sphere, nor a height a clip decides, nor a zero inner
 * radius), at most cap of them, into keys; returns how many. */
int tippe_design_part_lengths(const tippe_design *d, int i, const char **keys, int cap);

/* Whether part i is the fixed ball or shell whose outer surface is the sphere
 * the top rolls on (radius radius_mm, centred). */
int tippe_design_forms_sphere(const tippe_design *d, int i);

/* A pole where the surface is not the sphere: a hole opens there, and a top
 * tilted less than half_angle_rad on that pole stands on the hole's rim. */
typedef struct {
    int pole;              /* +1 or -1: the z side */
    double half_angle_rad; /* 0: the sphere is whole there */
    double radius_mm;      /* of the opening */
    char part[64];         /* the void that opens there */
} tippe_design_cap;

/* The caps at both poles (caps[0] +z, caps[1] -z) with the weight at Z2 (a
 * moving void travels with it); returns how many poles are open. */
int tippe_design_polar_caps(const tippe_design *d, double z2_mm, tippe_design_cap caps[2]);
/* The pole (+1, -1) whose opening a top at tilt theta rests on, 0 if it rests
 * on its sphere; rest_side is the z side down at theta = 0 (tippe_top.com_side
 * gives the side of the centre of mass, which is down). */
int tippe_design_cap_at_tilt(const tippe_design_cap caps[2], int rest_side, double theta_rad);
struct cJSON;
/* Adds "polar_caps": [{pole, part, opening_mm, half_angle_rad}] (the open poles). */
void tippe_design_caps_json(struct cJSON *o, const tippe_design_cap caps[2]);

/* Warning i (0, 1, ...) about a probable unit mistake in a design that loaded:
 * a part length below 0.01 mm, or one (or a travel) under 1 % of the sphere's radius
 * that in metres would fit the ball (metres typed for mm: the message says what it
 * would be); and a moving weight under 1 % of the top's mass. Writes the message (naming the field) into buf and returns 1, or
 * returns 0 past the last. (A sphere radius outside 1 .. 1000 mm and a density
 * above osmium's are errors at load, with the likely unit.) */
int tippe_design_warning(const tippe_design *d, int i, char *buf, size_t size);
/* Note i (0, 1, ...) about how a design that loaded was read, not a likely
 * mistake: a design without a "materials" field and without materials.json
 * beside it reads the shipped table (installed, or the checkout's designs/), and
 * the note names it; a second names the shipped catalogue it then reads
 * (tippe_design_shipped_catalogue). Writes it into buf and returns 1, or returns 0 past the last. */
int tippe_design_note(const tippe_design *d, int i, char *buf, size_t size);

/* The solid of part i, for exporters that rebuild its shape (mm). Fields that
 * the shape does not use are 0. clip_radius_mm is the ball the part is
 * intersected with (0: not clipped); height_mm is resolved (a clipped cylinder
 * without one spans its clip ball). parent is a void's part index, else -1;
 * for a moving part (or a void of one) z_mm is the offset from Z2. */
typedef struct {
    const char *shape; /* as in tippe_design_part_info */
    int is_void, moving, parent;
    double radius_mm, inner_radius_mm, thickness_mm, height_mm;
    double centre_radius_mm, radial_semi_mm, axial_semi_mm;
    double z_mm, clip_radius_mm;
    double clip_inner_mm; /* clip "shell": the part is cut to the wall between this
                             radius and clip_radius_mm; else 0 */
    double printed_radius_mm; /* a hole printed at another radius, then cut to radius_mm
                                 ("printed_radius_mm", or the tap drill's: below); 0:
                                 printed at radius_mm */
    int printed_radius_from_fit; /* printed_radius_mm is not the file's but the part as
                                    made: the weight's hole of a printed part, "tap" or no
                                    fit, printed at its thread's tap drill (design_fit.c) */
} tippe_design_solid;

/* Fills *out for part i; TIPPE_EINPUT if i is out of range. */
int tippe_design_part_solid(const tippe_design *d, int i, tippe_design_solid *out);

void tippe_design_free(tippe_design *d);

/* ---- the materials table (docs/design-format.md, "Materials") ---- */
typedef struct {
    const char *name, *source, *notes; /* notes "" if none */
    double density_g_cm3;
    int printable;
    int set_screws; /* "set_screws": set screws are sold in it (what the build
                       sheet may propose for a screw in a thread) */
    double E_GPa, nu; /* elastic constants (the Hertz patch); NAN when not given */
    const char *elastic_source; /* where E and nu come from; "" when not given */
} tippe_material;
typedef struct tippe_materials tippe_materials;

/* Reads and checks a materials table as tippe_design_load does (TIPPE_EINPUT
 * naming the file and field). */
int tippe_materials_load(const char *path, tippe_materials **out, tippe_error *err);
int tippe_materials_count(const tippe_materials *t);
/* Entry i (0 .. count - 1) in the file's order; its strings live as long as t. */
void tippe_materials_get(const tippe_materials *t, int i, tippe_material *out);
void tippe_materials_free(tippe_materials *t);
/* The table as tippe materials --json gives it: {materials: [{name,
 * density_g_cm3, printable, source, notes}], file} (no "file" when file is
 * NULL). NULL if out of memory. */
struct cJSON;
struct cJSON *tippe_materials_json(const tippe_materials *t, const char *file);
/* The materials table the loaded design read (resolved as at load: beside its
 * file, or the designs folder's for a design from memory); NULL when no part
 * names a material. */
const char *tippe_design_materials_path(const tippe_design *d);
/* That table as the design read it (a copy; tippe_materials_free), without
 * reading the file again; TIPPE_EINPUT when no part names a material. */
int tippe_design_materials(const tippe_design *d, tippe_materials **out, tippe_error *err);
/* The overrides ("FIELD=VALUE") the design was loaded with, in order; what a
 * report of it repeats so that the same design can be loaded again. */
int tippe_design_n_overrides(const tippe_design *d);
const char *tippe_design_override(const tippe_design *d, int i);
/* The materials table the design file at design_path reads: its "materials"
 * field (default "materials.json") relative to the design's directory.
 * TIPPE_EINPUT if the file is not a design (a JSON object with "parts"). */
int tippe_design_materials_file(const char *design_path, char *buf, size_t size,
                                tippe_error *err);

/* The thinnest wall of material around a hole (a cylinder or tube void cut
 * from a fixed ball), mm: the side wall at the hole's layer nearest the ball's
 * centre, and the floor or roof where the hole ends inside the ball; the rim
 * where a hole opens through the surface is not counted. INFINITY if there is
 * no such hole; *hole (may be NULL) names the thinnest. */
double tippe_design_min_hole_wall_mm(const tippe_design *d, const char **hole);

/* A design file read once, to build many variants of it (an optimiser's
 * candidates) without reading or parsing files again: the file's JSON and its
 * materials table stay in memory. A source is read-only once opened: builds
 * may run in many threads at once. */
typedef struct tippe_design_source tippe_design_source;

/* Reads and fully checks path (as tippe_design_load with no overrides). */
int tippe_design_source_open(const char *path, tippe_design_source **out, tippe_error *err);

/* The stated travel_mm is replaced by the physical travel: the widest stretch
 * of Z2 in which the moving parts touch nothing (for candidates whose stated
 * travel cannot be known beforehand). */
#define TIPPE_DESIGN_TRAVEL_PHYSICAL 1u
/* Overlaps and the travel are decided on 20 times fewer uniform radii (every
 * edge and corner of every part is still a sample, so contacts at edges stay
 * exact; a contact between two curved surfaces away from any edge may be
 * missed by up to the grid's spacing, ~0.13 mm for R = 25 mm). For screening
 * many candidates; a result worth keeping is rebuilt without it. */
#define TIPPE_DESIGN_COARSE_LAYOUT 2u

/* The design with overrides applied (the --set syntax of tippe_design_load),
 * checked as at load; flags: 0 or TIPPE_DESIGN_TRAVEL_PHYSICAL. Messages name
 * the file and blame the override that set a bad field ("(set by FIELD=VALUE)"). */
int tippe_design_source_build(const tippe_design_source *s, const char *const *overrides,
                              int n_overrides, unsigned flags, tippe_design **out,
                              tippe_error *err);

/* The file's JSON with the overrides applied, not checked (to write a variant
 * out as a design file); the caller owns *out (cJSON_Delete). */
struct cJSON;
int tippe_design_source_apply(const tippe_design_source *s, const char *const *overrides,
                              int n_overrides, struct cJSON **out, tippe_error *err);

/* The materials table the source's file names ("materials", default
 * materials.json beside it), as read when the source opened (a copy;
 * tippe_materials_free); TIPPE_EINPUT naming the file if it does not read. */
int tippe_design_source_materials(const tippe_design_source *s, tippe_materials **out,
                                  tippe_error *err);

void tippe_design_source_free(tippe_design_source *s);

/* ---- tolerances (src/design/tolerance.c) ---- */
/* Tolerance: how far a built top may be from its design file.
 *
 * A design's "tolerances" block (docs/design-format.md) gives, per field, a
 * +/- value: absolute in the field's unit, or "N%" of it. Fields are named as
 * --set names them ("radius_mm", "parts.screw.height_mm", "parts[2].z_mm") or,
 * for a material's density shared by every part made of it (one spool of
 * filament, one error), "materials.NAME.density_g_cm3". Fields the block leaves
 * out get the documented defaults (printed dimension +/-0.2 mm, filament
 * density +/-3 %, hardware mass +/-2 % through its density, a printed part's
 * infill +/-25 % of it, or its weighed mass +/-0.1 g); 0 removes one.
 * The design reads and checks the block when it loads; a loaded design lists
 * the result (tippe_design_n_tolerances, tippe_design_tolerance). */

#define TIPPE_TOLERANCE_FIELD_LEN 160
#define TIPPE_TOLERANCE_MAX 200

/* Documented defaults. */
#define TIPPE_TOL_PRINTED_MM 0.2
#define TIPPE_TOL_FILAMENT_DENSITY_PERCENT 3.0
#define TIPPE_TOL_HARDWARE_MASS_PERCENT 2.0
/* A printed part's infill as the slicer states it (its real density is not
 * known: slicer mass estimates are off by 3 to 26 % against the scale), and
 * the reading of a 0.1 g kitchen scale when the part was weighed. */
#define TIPPE_TOL_INFILL_PERCENT 25.0
#define TIPPE_TOL_WEIGHED_G 0.1
/* The contact patch's radius (the patch friction law's a, tippe/physics.h) is known
 * only within a factor: surface finish, the table and wear move it (docs/contact-patch.md).
 * The block's "contact.patch_radius": F (1.01 <= F <= 10) says a lies in [a/F, a F]; it moves
 * no zone boundary (the zones do not depend on friction), so it is not in the per-field
 * list: check and launch run the patch law there (their radius sensitivity). */
#define TIPPE_TOL_PATCH_RADIUS_FACTOR 2.0
#define TIPPE_TOL_PATCH_RADIUS_KEY "contact.patch_radius"

typedef struct {
    char field[TIPPE_TOLERANCE_FIELD_LEN]; /* canonical: parts by name */
    double value;      /* nominal, in the field's unit */
    double plus_minus; /* absolute, in the field's unit (> 0) */
    double percent;    /* as given when relative, else 0 */
    const char *unit;  /* "mm", "g/cm^3", "g" or "" (infill, a fraction) */
    const char *rule;  /* "tolerances block", or the default's: "printed dimension",
                          "filament density", "hardware mass", "slicer infill",
                          "scale reading" */
    /* The field's interval, [value - minus, value + plus]: +/- plus_minus clipped to
     * the range the field loads in (tippe_design_field_range): an infill of 0.95 +/-
     * 25 % lies in 0.7125 .. 1, not beyond 1, where the design no longer loads. */
    double minus, plus;
} tippe_tolerance;

/* The range a number field (named as --set and the tolerances block name it,
 * "parts.body.print.infill", "materials.PLA.density_g_cm3") loads in: the
 * loader's own bounds; -/+INFINITY where it has none (z_mm; a length above 0). */
void tippe_design_field_range(const char *field, double *lo, double *hi);

int tippe_design_n_tolerances(const tippe_design *d);
/* The factor F of the patch radius's tolerance (the block's contact.patch_radius, else
 * TIPPE_TOL_PATCH_RADIUS_FACTOR). */
double tippe_design_patch_radius_span(const tippe_design *d);
/* Tolerance i (0-based), NULL out of range. */
const tippe_tolerance *tippe_design_tolerance(const tippe_design *d, int i);

/* The overrides that move t's field from its nominal value by delta (one per
 * part made of the material, for a material's density), written into
 * buf[0..cap-1]; returns how many, or -1 if cap is too small. For
 * tippe_design_derive. */
int tippe_tolerance_overrides(const tippe_design *d, const tippe_tolerance *t, double delta,
                              char (*buf)[TIPPE_TOLERANCE_FIELD_LEN + 40], int cap);

#endif
