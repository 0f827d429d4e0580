/* print/gcode_state.h: what the G-code reader (gcode.c) hands the deposit's
 * accumulator (gcode_body.c). Lengths in mm, volumes in mm^3, masses in kg. */
#ifndef TIPPE_PRINT_GCODE_STATE_H
#define TIPPE_PRINT_GCODE_STATE_H

#include "tippe/print.h"

#include <stddef.h>

/* Two nozzle heights closer than this are one level (slicers write z to 1e-3 mm). */
#define GC_LEVEL_EPS_MM 1e-4
/* No nozzle lays a wider bead: a move so short that E's rounding implies one is
 * clamped (for the footprint and the cross-section term). */
#define GC_MAX_BEAD_WIDTH_MM 3.0

#define GC_MAX_TOOLS 16

/* ------------------------------------------------------------ text (gcode_text.c) */

static inline int tippe_gcode_is_space(
                                       char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }
static inline int tippe_gcode_is_digit(char c) { return c >= '0' && c <= '9'; }
static inline int tippe_gcode_is_alpha(
                                       char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
static inline char tippe_gcode_upper(char c) { return c >= 'a' && c <= 'z' ? (char)(c - 32) : c; }

/* A G-code number at *p (< e); 0 and *p advanced, or -1. */
int tippe_gcode_scan_number(const char **p, const char *e, double *v);
/* [s, e) into dst, cut to cap - 1 bytes and NUL-terminated. */
void tippe_gcode_copy_text(char *dst, size_t cap, const char *s, const char *e);
/* Whether [s, e) is name, ignoring case. */
int tippe_gcode_same_ci(const char *s, const char *e, const char *name);
/* The feature a ;TYPE: or ; FEATURE: label names (unknown labels: other). */
tippe_gcode_feature tippe_gcode_feature_of(const char *s, const char *e);
/* Calls fn on each line [s, e) without its line end (LF or CRLF), counting lines
 * in *line_no; stops at fn's first nonzero return and returns it. */
int tippe_gcode_each_line(const char *text, size_t len, long *line_no,
                 int (*fn)(void *, const char *, const char *), void *ctx);

/* What the slicer's comments say of the print. */
typedef struct {
    double diam[GC_MAX_TOOLS], dens[GC_MAX_TOOLS]; /* mm, g/cm^3 per extruder */
    int n_diam, n_dens;
    int volumetric; /* -1 unknown */
    int cura;
    int labelled; /* a ;TYPE: or ; FEATURE: line anywhere */
    double filament_mm, filament_g; /* NAN if absent */
    char generator[64];
} tippe_gcode_config;

/* The config pass over the whole text; *n_lines gets the line count. */
void tippe_gcode_read_config(const char *text, size_t len, tippe_gcode_config *c, long *n_lines);

/* ------------------------------------------------------------ deposits (gcode_body.c) */

/* Sums about a reference point o: m, m x_i, m x_i x_j (xx yy zz xy xz yz). */
typedef struct {
    double m, s[3], q[6];
} tippe_gcode_moments;

/* Sorted distinct heights. */
typedef struct {
    double *z;
    size_t n, cap;
} tippe_gcode_levels;

/* A body deposit's centre line seen from above, for the footprint's clusters. */
typedef struct {
    float x0, y0, x1, y1, volume;
    unsigned char feature;
} tippe_gcode_seg;

#define GC_SCHEMES 4 /* object labels: slicer comments, M486, Klipper, Cura ;MESH: */
#define GC_MAX_NAMES 64

typedef struct {
    int n;
    char name[GC_MAX_NAMES][TIPPE_GCODE_NAME_MAX];
} tippe_gcode_names;

typedef struct {
    tippe_gcode_bead bead;
    int labelled;         /* the file labels its features (known before the moves) */
    int have_ref;
    double ref[3];
    tippe_gcode_moments mom[TIPPE_GCODE_N_FEATURES];
    double vol[TIPPE_GCODE_N_FEATURES], mass[TIPPE_GCODE_N_FEATURES];
    double len[TIPPE_GCODE_N_FEATURES], len_h[TIPPE_GCODE_N_FEATURES];
    double vol_h[TIPPE_GCODE_N_FEATURES], point_vol[TIPPE_GCODE_N_FEATURES];
    long n_moves[TIPPE_GCODE_N_FEATURES];
    double lo[TIPPE_GCODE_N_FEATURES][3], hi[TIPPE_GCODE_N_FEATURES][3];
    double zmin_nozzle[TIPPE_GCODE_N_FEATURES];
    tippe_gcode_levels all;        /* every deposit's nozzle height: the bead height's fallback */
    tippe_gcode_levels body, unlab; /* the body's and the unlabelled deposits' */
    tippe_gcode_seg *seg;
    size_t n_seg, cap_seg;
    tippe_gcode_names objects[GC_SCHEMES];
    double keep_radius_mm; /* > 0: the body's beads are kept (near), for cuts */
    tippe_gcode_beads near;
    size_t cap_near;
    int oom;              /* an allocation failed */
} tippe_gcode_acc;

/* Whether f can be part of the body (the unlabelled deposits may be, see gcode.h). */
static inline int tippe_gcode_body_candidate(int f)
{
    return f < TIPPE_GCODE_SKIRT_BRIM || f == TIPPE_GCODE_UNLABELLED;
}

void tippe_gcode_acc_init(tippe_gcode_acc *a, tippe_gcode_bead bead, int labelled);
/* A bead of mass dm along u -> v (mm, about some point; the box's middle
 * height), its cross-section w x h added when box: the sums of gcode_body.c. */
void tippe_gcode_add_bead(tippe_gcode_moments *m, const double u[3], const double v[3], double dm,
                          int box, double h, double w, double dx, double dy, double lxy);
void tippe_gcode_acc_free(tippe_gcode_acc *a);

/* The bead height at nozzle height z_mm with no height comment: z above the
 * highest level below it of the deposits that count (not custom G-code, nor
 * unlabelled G-code in a labelled file), or above the bed. */
double tippe_gcode_fallback_height(const tippe_gcode_acc *a, double z_mm);

/* Lays volume_mm3 of density rho_kg_mm3 uniformly along the nozzle's segment
 * p0 -> p1 (mm, bed frame; equal: a point) as a bead h_mm high (0: unknown).
 * count: whether this is a move of its own (not the second chord of an arc). */
void tippe_gcode_deposit(tippe_gcode_acc *a, int feature, const double p0[3], const double p1[3],
                double volume_mm3, double rho_kg_mm3, double h_mm, int count);

/* Records that a body deposit happened inside object name of the given scheme. */
void tippe_gcode_object_seen(tippe_gcode_acc *a, int scheme, const char *name);

/* Fills out's totals, mass properties, layers, objects and clusters. The
 * unlabelled deposits are the body when the file is not labelled.
 * TIPPE_EINPUT if the body has no deposit, TIPPE_ECOMPUTE if memory ran out. */
int tippe_gcode_acc_finish(tippe_gcode_acc *a, tippe_gcode_body *out, tippe_error *err);

/* The distance (mm) from (x, y) to the segment p0 -> p1 seen from above. */
double tippe_gcode_distance_xy(double x, double y, const double p0[3], const double p1[3]);


#endif
