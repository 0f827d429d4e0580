/* export/mesh.h: triangle meshes of printed bodies, and the files a slicer reads.
 *
 * tippe_mesh_revolve() turns a body's (r, z) profile (tippe/profile.h) into a
 * closed, manifold, outward-oriented triangle mesh: each profile edge sweeps a
 * band of quads around the axis, split into two triangles; an edge with one end
 * on the axis sweeps a fan of triangles to one pole vertex (no degenerate
 * facets); edges lying on the axis sweep nothing. The angular step keeps every
 * circle within sag_mm of the true one. Units: mm.
 *
 * Output files are written atomically (tippe/base.h). */
#ifndef TIPPE_EXPORT_MESH_H
#define TIPPE_EXPORT_MESH_H

#include "tippe/export.h"

typedef struct {
    int n_vertices, n_triangles;
    double *xyz;       /* 3 per vertex */
    unsigned *tri;     /* 3 vertex indices per triangle, counter-clockwise seen from outside */
    int n_angles;      /* steps around the axis */
} tippe_mesh;

/* Revolves body b with n_angles steps (>= 3). If b->flip, the mesh is turned
 * upside down (z -> -z, y -> -y) for printing; a split half is then moved so
 * that its cut face lies in the plane z = 0. */
int tippe_mesh_revolve(const tippe_profile_body *b, int n_angles, tippe_mesh *m,
                       tippe_error *err);

/* Signed volume (divergence theorem), mm^3: positive for an outward mesh. */
double tippe_mesh_volume_mm3(const tippe_mesh *m);
void tippe_mesh_bounds(const tippe_mesh *m, double lo[3], double hi[3]);

int tippe_mesh_check(const tippe_mesh *m, tippe_mesh_audit *a, tippe_error *err);

/* Binary STL (little-endian float32, as slicers expect). */
int tippe_mesh_write_stl(const tippe_mesh *m, const char *path, const char *solid_name,
                         tippe_error *err);

/* One 3MF file (lib3mf) holding n meshes as separate objects named names[k],
 * each a build item shifted by offset_x_mm[k] along x so they do not overlap. */
int tippe_mesh_write_3mf(const tippe_mesh *meshes, const char *const *names,
                         const double *offset_x_mm, int n, const char *path, tippe_error *err);

/* What a 3MF file carries besides its meshes: the model's metadata (3MF core
 * names: "Title", "Application", "Description", ...) and, for slicers, the
 * per-object print settings in PrusaSlicer's format (the part
 * /Metadata/Slic3r_PE_model.config; ids are the objects' resource ids 1, 2,
 * ... in the order given). */
typedef struct {
    int n_meta;
    const char *const *meta_keys, *const *meta_values;
    int has_print;          /* 0: no slicer settings written */
    int perimeters, top_bottom_layers;
    double line_width_mm, layer_height_mm, infill; /* infill: 0 .. 1 */
    /* the rest of the settings the print model follows (print_slicer.c), so that
     * the slicer deposits what tippe modelled */
    const char *pattern;    /* PrusaSlicer's fill_pattern; rectilinear at 100 % */
    double external_width_mm, infill_width_mm, top_min_mm, bottom_min_mm, infill_overlap;
    double anchor_mm, anchor_max_mm;
    /* the settings the model assumes, with the design's values (tippe_print_pinned_settings) */
    tippe_print_pin pins[32];
    int n_pins;
    /* per object (NULL: none): 1 turns PrusaSlicer's automatic supports on for it,
     * from the build plate only; 0 turns them off (tippe_export_body_needs_support) */
    const int *support;
} tippe_mesh_3mf_extra;

/* Whether body b, standing as printed, wants supports (export_support.c). */
int tippe_export_body_needs_support(const tippe_profile_body *b);

/* tippe_mesh_write_3mf with the extras (x may be NULL). */
int tippe_mesh_write_3mf_extra(const tippe_mesh *meshes, const char *const *names,
                               const double *offset_x_mm, int n, const tippe_mesh_3mf_extra *x,
                               const char *path, tippe_error *err);

void tippe_mesh_free(tippe_mesh *m);

#endif
