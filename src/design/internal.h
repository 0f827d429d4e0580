/* design/internal.h: what the design module's files share and no other
 * module sees. */
#ifndef TIPPE_DESIGN_INTERNAL_H
#define TIPPE_DESIGN_INTERNAL_H

#include "base/json.h"
#include "design/tolerance_read.h"
#include "tippe/design.h"

#define NAME_LEN 64
#define MAX_PARTS 50
#define MAX_FILE_MIB 4
/* Overlap depth that still counts as touching: far below print resolution
 * (~0.1 mm), far above double roundoff on mm-sized numbers (~1e-14 mm). */
#define TOL_MM 1e-6
/* Uniform r samples across the widest part; see the resolution note in docs. */
#define N_R_UNIFORM 4000
/* The same for an optimiser's candidates (TIPPE_DESIGN_COARSE_LAYOUT): 20 times
 * fewer uniform samples; every part's edges are still sampled exactly. */
#define N_R_COARSE 200
/* A sphere radius match (the part forming the sphere's surface), mm. */
#define SAME_LENGTH_MM 1e-9
/* Slack on the travel check for a sweep's rounded steps, mm. */
#define TRAVEL_SLACK_MM 1e-9
/* Beyond any coordinate in a design, mm: stands for an unbounded interval. */
#define BIG_MM 1e12
/* The densest solid: osmium, 22.587 g/cm^3 at 20 C (J. W. Arblaster, "Densities
 * of osmium and iridium", Platinum Metals Review 33 (1989) 14-16; the CRC
 * Handbook of Chemistry and Physics gives 22.59). Anything denser was typed in
 * another unit (kg/m^3 for g/cm^3: 7850 for steel). */
#define DENSITY_MAX_G_CM3 22.6
/* Sphere radii of a tippe top: a 2 mm bead to a 2 m ball. Outside, the number
 * was typed in another unit (metres: 0.025; um: 25000). */
#define RADIUS_MIN_MM 1.0
#define RADIUS_MAX_MM 1000.0
/* A part length below 10 um is finer than anything printed or machined: a
 * warning (probably metres); smaller lengths still load, for limit studies,
 * down to a picometre: below that (a subnormal 1e-320, ...) no part is that
 * thin, and its mass moments would underflow to nothing. */
#define LENGTH_HINT_MM 0.01
/* A part length or travel under 1 % of the sphere's radius whose value in metres
 * would fit the ball (1 mm .. its diameter) was probably typed in metres: a warning
 * with the hint. A moving weight under 1 % of the top's mass moves its centre of mass
 * by under R / 100 over the whole ball: a warning (issue 25.5). */
#define METRES_HINT_SHARE 0.01
#define LIGHT_WEIGHT_SHARE 0.01
#define LENGTH_MIN_MM 1e-9
/* The print block's numbers (docs/design-format.md, "print"): the loader's ranges,
 * which also bound the tolerance bands (tippe_design_field_range). A line or layer
 * outside them is not one a slicer makes; infill is a fraction; a weighed mass from
 * a microgram to a tonne; calibration may look one step past each end (-1 .. 2). */
#define PRINT_LINE_WIDTH_MIN_MM 0.05
#define PRINT_LINE_WIDTH_MAX_MM 3.0
#define PRINT_LAYER_HEIGHT_MIN_MM 0.01
#define PRINT_LAYER_HEIGHT_MAX_MM 2.0
#define PRINT_INFILL_MIN 0.0
#define PRINT_INFILL_MAX 1.0
#define PRINT_MEASURED_MASS_MIN_G 1e-6
#define PRINT_MEASURED_MASS_MAX_G 1e6
#define PRINT_CALIBRATION_MIN -1.0
#define PRINT_CALIBRATION_MAX 2.0
/* solid_infill_below_area: up to a square metre (PrusaSlicer sets no bound; a
 * top's layers are some 2000 mm^2 at most) */
#define PRINT_SOLID_BELOW_AREA_MAX_MM2 1e6
/* Intervals per r: a part gives at most 2, each void removes at most 2 more. */
#define MAX_IV (4 + 4 * MAX_PARTS)

enum { CLIP_NONE, CLIP_SPHERE, CLIP_CAVITY, CLIP_SHELL };

typedef enum { SHAPE_BALL, SHAPE_SHELL, SHAPE_CYLINDER, SHAPE_TUBE, SHAPE_TORUS, N_SHAPES } shape_kind;
static const char *const shape_names[N_SHAPES] = {"ball", "shell", "cylinder", "tube", "torus"};

typedef struct {
    char name[NAME_LEN];
    char material[NAME_LEN]; /* "" when density_g_cm3 was given inline */
    shape_kind shape;
    double radius_mm;       /* ball, shell (outer), cylinder, tube (outer) */
    double inner_radius_mm; /* cylinder, tube */
    double thickness_mm;    /* shell */
    double height_mm;       /* cylinder, tube; resolved when only a clip is given */
    double centre_radius_mm, radial_semi_mm, axial_semi_mm; /* torus */
    double z_mm;            /* moving parts: offset from Z2 */
    double density_g_cm3;   /* voids: the parent's */
    int is_void, moving, may_protrude;
    int printable;          /* the material's "printable" flag (voids: the parent's) */
    double E_pa, nu;        /* the material's elastic constants (E 0: not in the table) */
    int has_height, has_radius;
    int parent;             /* voids: index of the part cut from; else -1 */
    int clip;               /* CLIP_NONE, CLIP_SPHERE, CLIP_CAVITY, CLIP_SHELL */
    double clip_radius_mm;  /* resolved; 0 = not clipped */
    double clip_inner_mm;   /* CLIP_SHELL: the shell's cavity radius (the part is cut to
                               the wall between it and clip_radius_mm); else 0 */
    int printed;            /* has a "print" block */
    tippe_print_settings print;
    int calibrated;         /* the infill comes from measured_mass_g */
    double measured_mass_g;
    double infill;          /* used: print.infill, or the calibrated one */
    double solid_mass_kg, skin_mass_kg, print_rel_error;
    double mass_kg;         /* signed contribution */
    int fit;                /* a hole's "fit": TIPPE_DESIGN_FIT_* (NONE when not given) */
    double printed_radius_mm; /* a hole's "printed_radius_mm": printed there, cut to
                                 radius_mm after (0: printed at radius_mm) */
    int printed_radius_from_fit; /* printed_radius_mm is the tap drill's, not the file's
                                    (tippe_design_derive_printed_radii) */
    char catalogue_item[64];/* "catalogue_item": the hardware catalogue's item it is, or "" */
    char gcode[1024];       /* print.gcode as given (relative to the design file), or "" */
    double filament_diameter_mm; /* print.filament_diameter_mm: the G-code's filament, 0 the
                                    file's own */
    double printed_mass_kg; /* as printed, at `infill` */
    tippe_print_sliced sliced; /* the slicer model's layers (print.model slicer) */
    /* print.gcode: the G-code's body, matched to the part, the weighing's flow factor
     * and the layer model's moments and mass beside it */
    int has_gcode;
    tippe_gcode_body gcode_body;
    tippe_gcode_part gcode_part;
    double gcode_flow;
    char gcode_note[512];   /* the G-code's hole against the design's (gcode_cut_holes), or "" */
    double gcode_bed_shift_mm; /* the G-code placed by its own holes: its bed against the
                                  model's (0: where the model's part stands) */
    tippe_moments model_moments;
    double model_mass_kg;
    tippe_moments deposit, model_deposit; /* unit density: the printed part alone */
    /* what the print model's deposit loses after printing: the plastic inside its
       holes' radii where they are printed narrower (printed_radius_mm); unit density */
    tippe_moments cut;
} part;

struct tippe_design {
    char *path, *name;
    /* The design file's text as read once (or as given in memory,
     * tippe_design_load_text), kept so that tippe_design_derive and _reload parse
     * it again instead of opening the file again (issue 34: a sweep's bands read
     * the file 97 times); materials_dir: the folder of the materials table of a
     * design from memory, NULL for a file. */
    char *text, *materials_dir;
    size_t text_len;
    /* G-code bodies from memory (tippe_design_load_text_gcode), kept for reloads */
    tippe_design_gcode *gcodes;
    int n_gcodes;
    char *catalogue; /* "catalogue": the hardware catalogue file, resolved; NULL: not given */
    char *mat_file;  /* the materials table read, resolved; NULL: no part names a material */
    int mat_fallback; /* 1: no table beside the file, the shipped one was read (a note) */
    cJSON *mat_table; /* that table as read and checked, for the designs derived from this
                         one; NULL with mat_file */
    double radius_mm;
    double travel_mm[2], contact_mm[2];
    char contact_limit[2][256];
    /* Z2 where every part stays within the sphere (from > to: nowhere); the
     * sampled radii it and tippe_design_protrusion_at use (NULL: no layout) */
    double sphere_only_mm[2];
    double *rs;
    int nr;
    int n_parts;
    part *parts;
    tippe_moments fixed, moving; /* SI; moving at Z2 = 0 */
    char **overrides;            /* as loaded, for tippe_design_derive */
    int n_overrides;
    tippe_tolerance *tolerances; /* the tolerances block and the defaults */
    int n_tolerances;
    double patch_radius_span;    /* the block's contact.patch_radius, or 0: the default */
    /* Set only while it is built: a materials table already read and checked
     * (a source's, or the table of the design it is derived from; not owned) and
     * its resolved file, used instead of reading that file again. */
    const cJSON *known_table;
    const char *known_table_file;
    /* Set only while it is built: the design it is derived from (or NULL), whose
     * materials table is taken instead of reading it again (a G-code is kept by
     * design_printed.c's cache of bodies, keyed by the file). */
    const struct tippe_design *known_from;
    /* Whether the travel is the physical one (a source's variant). */
    int travel_physical, coarse_layout;
};


/* A design file parsed once (design_source.c). */
struct tippe_design_source {
    char *path;
    char *text; /* the file's text as read once (text_len bytes and a NUL) */
    size_t text_len;
    cJSON *root;      /* the design file as parsed (duplicate keys refused) */
    char mat_file[1024];
    cJSON *materials; /* the materials table it names, read and checked once; or NULL */
};

/* ---- what one file of the module calls in another ---- */

/* z intervals at one radius (design_layout.c). */
typedef struct {
    int n;
    double lo[MAX_IV], hi[MAX_IV]; /* sorted, disjoint, lo < hi */
} ivset;

/* design.c: the loader's pieces that design sources reuse. */
int tippe_design_remember_overrides(tippe_design *d, const char *const *overrides, int n,
                                    tippe_error *err);
int tippe_design_finish(tippe_json_reader *c, cJSON *root, tippe_design *d,
                        const char *const *overrides, int n_overrides, int rc,
                        tippe_design **out, tippe_error *err);
char *tippe_design_dup_string(const char *s);
int tippe_design_build(tippe_json_reader *c, cJSON *root, const char *path, tippe_design *d,
                       int check);

/* design.c: a part's unit-density moments (closed forms; a void's positive). */
tippe_moments tippe_design_part_moments(const part *p);
/* The part as made (design_fit.c): the weight's hole of a printed part, tapped
 * (no fit, or "tap") and without a printed_radius_mm of the file's, printed at
 * its thread's tap drill. After the parts are resolved, before their moments. */
void tippe_design_derive_printed_radii(tippe_design *d);
/* design_printed.c: a printed part's unit-density moments as printed (its voids
 * added back: the caller subtracts them as usual); sets its infill and masses. */
int tippe_design_printed_moments(const tippe_json_reader *c, tippe_design *d, int i,
                                 tippe_moments *out);

/* design_parts.c: the file's keys, the parts and the materials table. */
/* a length in mm that must be > 0 (or >= 0 with allow_zero) */
int tippe_design_read_length(const tippe_json_reader *c, const cJSON *obj, const char *prefix,
                             const char *key, int required, int allow_zero, double *out,
                             int *present);
int tippe_design_known_materials(const tippe_design *d, const char *mat_file, cJSON **out);
extern const char *const tippe_design_top_keys[];
extern const char *const tippe_design_top_string_keys[];
extern const char *const tippe_design_part_string_keys[];
extern const char *const tippe_design_all_part_keys[];
extern const char *const tippe_design_print_keys[];
extern const char *const tippe_design_print_string_keys[];
int tippe_design_parse_part(const tippe_json_reader *c, const cJSON *obj, int index, part *p);
int tippe_design_load_materials(const char *mat_file, cJSON **out, tippe_error *err);
/* The table of a design whose "materials" field is absent, beside: the file
 * beside the design (its path) if it exists, else the shipped table
 * (tippe_file_shipped_dir) with *fell_back = 1. Returns 0 when neither exists
 * (buf then says where the shipped one was looked for). */
int tippe_design_default_table(const char *beside, char *buf, size_t size, int *fell_back);
int tippe_design_lookup_material(const tippe_json_reader *c, const cJSON *table,
                                 const char *mat_file, const char *name, const char *path,
                                 double *density, int *printable, double *E_pa, double *nu);

/* design_overrides.c: --set overrides. */
int tippe_design_apply_override(tippe_json_reader *c, cJSON *root, const char *text);

/* design_layout.c: where the parts are. */
int tippe_design_check_layout(const tippe_json_reader *c, tippe_design *d);
void tippe_design_material_ivs(const tippe_design *d, int i, double r, double dz, ivset *s);
const char *tippe_design_role_of(const part *p);

#endif
