/* tippe/export.h: from a design to the files a maker prints from.
 *
 * One call writes, into one directory, for the printed bodies of a design
 * (tippe/profile.h): a binary STL per body and one 3MF with all bodies
 * (src/export/mesh.h), the OpenSCAD source of the whole top (src/export/scad.h) and the
 * dimensioned cross-section drawing (src/export/drawing.h). Every mesh is audited
 * (closed, manifold, consistently outward, no degenerate facet) before it is
 * written; a mesh that fails is an error, never a file. Files are named after
 * the design file: STEM-BODY.stl, STEM.3mf, STEM.scad, STEM-section.svg|png|pdf. */
#ifndef TIPPE_EXPORT_H
#define TIPPE_EXPORT_H

#include <stddef.h>

#include "tippe/build.h"
#include "tippe/design.h"
#include "tippe/base.h"
#include "tippe/profile.h"
#include "tippe/sweep.h"

enum {
    TIPPE_EXPORT_STL = 1,
    TIPPE_EXPORT_3MF = 2,
    TIPPE_EXPORT_SCAD = 4,
    TIPPE_EXPORT_SVG = 8,
    TIPPE_EXPORT_PNG = 16,
    TIPPE_EXPORT_PDF = 32,
    TIPPE_EXPORT_ALL = 63
};

/* Topology audit: edges used once (open), more than twice (non-manifold),
 * directed edges used twice (inconsistent orientation), triangles of zero area
 * after rounding to float (as written to STL). All zero for a good mesh. */
typedef struct {
    long open_edges, nonmanifold_edges, flipped_edges, degenerate_triangles;
} tippe_mesh_audit;

typedef struct {
    tippe_profile_options profile;
    double z2_mm;     /* the moving weight's place in the SCAD file and the drawing */
    unsigned formats; /* TIPPE_EXPORT_* bits */
    const char *dir;  /* output directory */
    const char *title_note; /* second title line of the drawing (the zone), or NULL */
    const char *fit_note;   /* why profile.fit_part is printed at fit_diameter_mm ("M10 x 1.5
                               tap drill"), for the drawing; NULL: "for its thread" */
    /* the section's .pdf at 1:1 on A4 landscape (the .svg and .png stay fitted) */
    int section_one_to_one;
    /* a setting's depth below the rim, dimensioned in the section (tippe
     * build: the drawn setting's); has_depth 0: none */
    int has_depth;
    double depth_rim_z_mm, depth_end_z_mm, depth_x_mm;
    char depth_label[64];
    const char *depth_from; /* "the rim", "the rod's end" */
} tippe_export_request;

typedef struct {
    char name[128], material[64];
    char stl_path[4096];
    int n_angles, n_triangles;
    double mesh_volume_mm3;    /* of the written mesh (float64 before rounding) */
    double polygon_volume_mm3; /* the profile revolved exactly (Pappus) */
    double exact_volume_mm3;   /* closed form; NAN for a split half */
    double lo_mm[3], hi_mm[3]; /* bounding box of the mesh as written (print frame) */
    tippe_mesh_audit audit;
} tippe_export_body;

typedef struct {
    tippe_profile_set profiles; /* bodies, warnings, clearance_applied */
    int n_bodies;
    tippe_export_body *body;
    int n_files;
    char (*file)[4096]; /* written, in order (n_files of them) */
    double seconds;
} tippe_export_result;

/* The paths a request would write, for checking before any work: *paths (on
 * the heap, free() it) gets every one, as many as there are bodies and formats;
 * returns how many, or -1 with err set if the profiles cannot be built (e.g.
 * nothing printable) or memory ran out. */
int tippe_export_plan(const tippe_design *d, const tippe_export_request *q,
                      char (**paths)[4096], tippe_error *err);

/* Builds and writes everything q asks for. On failure no file of this call is
 * left half-written (each is atomic); files already finished stay. */
int tippe_export_run(const tippe_design *d, const tippe_export_request *q,
                     tippe_export_result *out, tippe_error *err);

void tippe_export_result_free(tippe_export_result *r);

/* ---- the build sheet (src/export/build_sheet.c), from tippe_build_compute ---- */

/* The setting the section drawings show: the flips one, else the first
 * reachable (-1 when none). Its Z2, and for a weight measured from a rim or a
 * rod's end its depth as a dimension: the rim's and the weight end's z, the
 * x of the hole's wall (0 for a rod) and a label ("flips: 5.5 turns");
 * *has_depth 0 when there is no reference. */
int tippe_export_shown_setting(const tippe_build_sheet *s, double *z2_mm, int *has_depth,
                               double *rim_z_mm, double *end_z_mm, double *x_mm, char *label,
                               size_t label_size);
/* What the sheet's depths start from: "the rim", "the rod's end". */
const char *tippe_export_depth_from(const tippe_build_sheet *s);

/* Writes setting family's gauge as binary STL (TIPPE_EINPUT if none applies). */
int tippe_export_gauge_write(const tippe_build_sheet *s, int family, const char *path,
                             tippe_error *err);

/* The sheet on one page (A3 landscape, longer when its text needs it): the section drawing with the weight
 * at the flip's setting, the settings table, bill of materials, thread, print
 * settings, notes and steps. The format follows path's extension: .pdf, .svg
 * (cairo; text as glyphs) or .png (1906 x 1347 px). Written atomically. */
int tippe_export_sheet_write(const tippe_design *d, const tippe_build_sheet *s, const char *path,
                            tippe_error *err);

/* ==== tippe build's files (tippe build, tippe serve's /api/build) ==== */
/* The sheet's files in dir, named by the design's stem (tippe_build_stem):
 * STEM-build.json, -build.md, -sheet.pdf, -sheet.svg, -sheet.png (the first
 * TIPPE_EXPORT_BUILD_SHEET), then the gauges -gauge-stays-up.stl, -flips.stl,
 * -hangs.stl (written where tippe_build_gauge_applies). */
enum { TIPPE_EXPORT_BUILD_SHEET = 5, TIPPE_EXPORT_BUILD_FILES = 8 };
void tippe_export_build_paths(const tippe_design *d, const char *dir, char (*out)[4096]);
/* The export request of a build into dir (q->profile: tippe_profile_defaults or
 * the caller's): every format, split, joined on a ring and with rod sockets
 * when the printed body closes around its hardware, the weight mid-travel
 * until the sheet's settings are known. */
void tippe_export_build_request(const tippe_design *d, double clearance_mm, const char *dir,
                                tippe_export_request *q);
/* Writes the sheet s of d to paths (tippe_export_build_paths) and, with q (NULL:
 * the sheet only), tippe export's files into r: the drawing with the weight at
 * the flip's setting (else the first setting there is), the screw's hole at the
 * sheet's tap drill or insert pilot (fit_note, fit_note_size: room for why). */
int tippe_export_build_write(const tippe_design *d, const tippe_build_sheet *s,
                             char (*paths)[4096], tippe_export_request *q, char *fit_note,
                             size_t fit_note_size, tippe_export_result *r, tippe_error *err);

/* ==== the slicer in the loop (tippe slice, docs/printing.md) ==== */
/* What to slice with. dir exists (the 3MF, the G-code and the slicer's log go
 * there); slicer is the program to run (a path, or a name on PATH: no shell),
 * profile a PrusaSlicer config; clearance_mm the export's clearance of holes
 * for hardware (0: the mass model's holes). verdict: the build sheet's options
 * for the two verdicts (tippe_build_options_default's). */
typedef struct {
    const char *dir, *slicer, *profile;
    double clearance_mm;
    tippe_build_options verdict;
} tippe_export_slice_request;

/* The part as the slicer made it beside the print model's. */
typedef struct {
    int part;                       /* the design's one printed part */
    char part_name[128];
    char model_3mf[4096], gcode[4200], log[4200];
    tippe_design *sliced;           /* the design with the G-code as the part (print.gcode) */
    tippe_sweep_result model_sweep, sliced_sweep; /* with their bands */
    tippe_build_sheet *model_sheet, *sliced_sheet; /* the verdicts alone
                                                      (tippe_build_compute_verdict) */
} tippe_export_slice_result;

/* Writes d's 3MF into q->dir (committing the report set: the slicer reads it
 * from disk, and begins a new one), runs the slicer on it, reads the G-code
 * back as the printed part (d reloaded from the text it was read from, with
 * print.gcode set), and sweeps and judges both. TIPPE_EINPUT: no printed part
 * or more than one, or more than one printed body; TIPPE_ECOMPUTE: the
 * slicer failed (its log named). out is filled (free it) only on success. */
/* The design's one printed part (its index, its name into name), or -1 with
 * err saying there is none or more than one: slice takes exactly one. */
int tippe_export_slice_part(const tippe_design *d, char *name, size_t cap, tippe_error *err);
int tippe_export_slice(const tippe_design *d, const tippe_export_slice_request *q,
                       tippe_export_slice_result *out, tippe_error *err);
void tippe_export_slice_result_free(tippe_export_slice_result *r);

#endif
