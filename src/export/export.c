/* Export: profiles -> audited meshes -> STL, 3MF; SCAD source; section drawing. */
#include "tippe/export.h"

#include "export/drawing.h"
#include "export/scad.h"
#include "export/mesh.h"
#include "tippe/design.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* The design file's name without directory and extension: "m12-setscrew" for
 * "designs/m12-setscrew.json". */
static void design_stem(const tippe_design *d, char *out, size_t size)
{
    tippe_path_stem(tippe_design_path(d), out, size);
}

/* A body name as a file name part: letters, digits, '-', '_', '+' kept. */
static void file_part(const char *name, char *out, size_t size)
{
    size_t n = 0;
    for (const char *c = name; *c && n + 1 < size; c++)
        out[n++] = (isalnum((unsigned char)*c) || strchr("-_+", *c)) ? *c : '_';
    out[n] = '\0';
}

static void join(char *out, const char *dir, const char *stem, const char *tail)
{
    snprintf(out, 4096, "%s%s%s%s", dir, dir[0] && dir[strlen(dir) - 1] != '/' ? "/" : "", stem,
             tail);
}

/* Every path of the request, in the order they are written: the STL files,
 * then at most the five below. */
enum { N_SINGLE = 5 };
static int paths_of(const tippe_design *d, const tippe_export_request *q,
                    const tippe_profile_set *s, char (*paths)[4096])
{
    char stem[1024], tail[300];
    design_stem(d, stem, sizeof stem);
    int n = 0;
    for (int b = 0; (q->formats & TIPPE_EXPORT_STL) && b < s->n_bodies; b++) {
        char part[160];
        file_part(s->body[b].name, part, sizeof part);
        snprintf(tail, sizeof tail, "-%s.stl", part);
        join(paths[n++], q->dir, stem, tail);
    }
    static const struct {
        unsigned bit;
        const char *tail;
    } single[N_SINGLE] = {{TIPPE_EXPORT_3MF, ".3mf"},
                          {TIPPE_EXPORT_SCAD, ".scad"},
                          {TIPPE_EXPORT_SVG, "-section.svg"},
                          {TIPPE_EXPORT_PNG, "-section.png"},
                          {TIPPE_EXPORT_PDF, "-section.pdf"}};
    for (size_t k = 0; k < N_SINGLE; k++)
        if (q->formats & single[k].bit)
            join(paths[n++], q->dir, stem, single[k].tail);
    return n;
}

/* Room for every path of a request over s. */
static char (*paths_room(const tippe_profile_set *s))[4096]
{
    return malloc(((size_t)s->n_bodies + N_SINGLE) * sizeof(char[4096]));
}

int tippe_export_plan(const tippe_design *d, const tippe_export_request *q,
                      char (**paths)[4096], tippe_error *err)
{
    tippe_profile_set s;
    *paths = NULL;
    if (tippe_profile_build(d, &q->profile, &s, err))
        return -1;
    int n = -1;
    if (!(*paths = paths_room(&s)))
        tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    else
        n = paths_of(d, q, &s, *paths);
    tippe_profile_set_free(&s);
    return n;
}

/* Revolves body b, audits the mesh and fills e; the mesh stays in *m. */
static int mesh_body(const tippe_design *d, const tippe_profile_body *b, double chord_mm,
                     tippe_mesh *m, tippe_export_body *e, tippe_error *err)
{
    /* Half of the chord budget goes to the angular step, half to the profile. */
    int n_angles = tippe_profile_angle_steps(b->r_max_mm, chord_mm / 2);
    int rc = tippe_mesh_revolve(b, n_angles, m, err);
    if (rc)
        return rc;
    if ((rc = tippe_mesh_check(m, &e->audit, err)))
        return rc;
    snprintf(e->name, sizeof e->name, "%s", b->name);
    snprintf(e->material, sizeof e->material, "%s", b->material);
    e->n_angles = n_angles;
    e->n_triangles = m->n_triangles;
    e->mesh_volume_mm3 = tippe_mesh_volume_mm3(m);
    e->polygon_volume_mm3 = b->polygon_volume_mm3;
    e->exact_volume_mm3 = b->exact_volume_mm3;
    tippe_mesh_bounds(m, e->lo_mm, e->hi_mm);
    const tippe_mesh_audit *a = &e->audit;
    if (a->open_edges || a->nonmanifold_edges || a->flipped_edges || a->degenerate_triangles ||
        !(e->mesh_volume_mm3 > 0))
        return tippe_error_set(err, TIPPE_ECOMPUTE,
                               "%s: the mesh of body '%s' is not a clean closed surface (%ld open "
                               "edges, %ld non-manifold, %ld flipped, %ld degenerate facets, "
                               "volume %g mm^3): nothing written for it",
                               tippe_design_path(d), b->name, a->open_edges,
                               a->nonmanifold_edges, a->flipped_edges, a->degenerate_triangles,
                               e->mesh_volume_mm3);
    return TIPPE_OK;
}

static int write_drawings(const tippe_design *d, const tippe_export_request *q,
                          const tippe_profile_set *s, char (*paths)[4096], int first, int n,
                          tippe_error *err)
{
    tippe_top top;
    tippe_design_top_any(d, q->z2_mm, &top);
    tippe_drawing_options o = {.z2_mm = q->z2_mm,
                               .com_z_mm = top.com_side * top.eps * 1e3,
                               .title = tippe_design_name(d),
                               .note = q->title_note,
                               .clearance_mm = q->profile.clearance_mm,
                               .clearance_applied = s->clearance_applied,
                               .chord_mm = q->profile.chord_mm,
                               .fit_part = q->profile.fit_part,
                               .fit_diameter_mm = q->profile.fit_diameter_mm,
                               .fit_note = q->fit_note,
                               .has_cut = q->profile.split,
                               .joint = q->profile.joint,
                               .cut_z_mm = q->profile.split_z_mm,
                               .n_sockets = s->n_sockets,
                               .has_depth = q->has_depth,
                               .depth_rim_z_mm = q->depth_rim_z_mm,
                               .depth_end_z_mm = q->depth_end_z_mm,
                               .depth_x_mm = q->depth_x_mm,
                               .depth_label = q->depth_label[0] ? q->depth_label : NULL,
                               .depth_from = q->depth_from};
    for (int k = 0; k < s->n_sockets; k++) {
        o.socket_part[k] = s->socket_part[k];
        o.socket_r_mm[k] = s->socket_r_mm[k];
        o.socket_rim_z_mm[k] = s->socket_rim_z_mm[k];
        o.socket_floor_z_mm[k] = s->socket_floor_z_mm[k];
    }
    for (int k = first; k < n; k++) {
        const char *dot = strrchr(paths[k], '.');
        o.one_to_one = q->section_one_to_one && dot && !strcmp(dot, ".pdf");
        int rc = tippe_drawing_write(d, &o, paths[k], err);
        if (rc)
            return rc;
    }
    return TIPPE_OK;
}

/* The slicer settings the mass model assumed: the first printed part's print
 * block with its infill as the model uses it (calibrated by weighing when the
 * design says so); a design without one is modelled solid (100 %). */
static void slicer_settings(const tippe_design *d, const tippe_profile_options *po,
                            tippe_mesh_3mf_extra *x, char *desc, size_t size)
{
    memset(x, 0, sizeof *x);
    tippe_print_settings ps = tippe_print_defaults();
    double infill = 1.0;
    int calibrated = 0, block = 0;
    for (int i = 0; i < tippe_design_n_parts(d) && !block; i++) {
        tippe_design_print_info pr;
        if (!tippe_design_part_print(d, i, &pr) && pr.printed) {
            ps = pr.settings;
            infill = pr.infill;
            calibrated = pr.calibrated;
            block = 1;
        }
    }
    x->has_print = 1;
    x->perimeters = ps.perimeters;
    x->top_bottom_layers = ps.top_bottom_layers;
    x->line_width_mm = ps.line_width_mm;
    x->layer_height_mm = ps.layer_height_mm;
    x->infill = infill;
    /* at 100 % only a line pattern fills solid: PrusaSlicer refuses another one
     * there (PrintConfig.cpp validation) and the print model uses rectilinear */
    x->pattern = infill >= 1 ? "rectilinear" : tippe_print_pattern_name(ps.pattern);
    x->external_width_mm = ps.external_width_mm;
    x->infill_width_mm = ps.infill_width_mm;
    x->top_min_mm = ps.top_min_mm;
    x->bottom_min_mm = ps.bottom_min_mm;
    x->infill_overlap = ps.infill_overlap;
    x->anchor_mm = ps.anchor_mm;
    x->anchor_max_mm = ps.anchor_max_mm;
    x->n_pins = tippe_print_pinned_settings(&ps, x->pins, (int)(sizeof x->pins / sizeof x->pins[0]));
    char fit[120] = "";
    if (po->fit_diameter_mm > 0)
        snprintf(fit, sizeof fit, ", except the screw's, printed %.2f mm across for its thread",
                 po->fit_diameter_mm);
    snprintf(desc, size,
             "Print with the axis vertical%s: %d perimeters of %.2f mm, %d top/bottom layers of "
             "%.2f mm, %.4g %% %s infill (%s). Holes for hardware have %.2f mm radial clearance%s.",
             po->split ? ", each half on its flat cut face" : "", ps.perimeters,
             ps.line_width_mm, ps.top_bottom_layers, ps.layer_height_mm, 100 * infill, x->pattern,
             !block       ? "solid: the design has no print block"
             : calibrated ? "calibrated from the weighed part"
                          : "the design's slicer setting",
             po->clearance_mm, fit);
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int tippe_export_run(const tippe_design *d, const tippe_export_request *q,
                     tippe_export_result *out, tippe_error *err)
{
    double t0 = now_s();
    memset(out, 0, sizeof *out);
    int rc = tippe_profile_build(d, &q->profile, &out->profiles, err);
    if (rc)
        return rc;
    const tippe_profile_set *s = &out->profiles;
    int nb = s->n_bodies;
    out->body = calloc((size_t)nb, sizeof *out->body);
    tippe_mesh *meshes = calloc((size_t)nb, sizeof *meshes);
    char(*paths)[4096] = paths_room(s);
    if (!out->body || !meshes || !paths) {
        free(meshes);
        free(paths);
        return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    }
    out->n_bodies = nb;
    int np = paths_of(d, q, s, paths), k = 0;
    for (int b = 0; !rc && b < nb; b++)
        rc = mesh_body(d, &s->body[b], q->profile.chord_mm, &meshes[b], &out->body[b], err);
    for (int b = 0; !rc && (q->formats & TIPPE_EXPORT_STL) && b < nb; b++, k++) {
        snprintf(out->body[b].stl_path, sizeof out->body[b].stl_path, "%s", paths[k]);
        rc = tippe_mesh_write_stl(&meshes[b], paths[k], s->body[b].name, err);
    }
    if (!rc && (q->formats & TIPPE_EXPORT_3MF)) {
        const char **names = calloc((size_t)nb, sizeof *names);
        double *dx = calloc((size_t)nb, sizeof *dx);
        if (!names || !dx)
            rc = tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
        /* side by side on the plate, 5 mm apart */
        for (int b = 0; !rc && b < nb; b++) {
            names[b] = s->body[b].name;
            dx[b] = b ? dx[b - 1] + s->body[b - 1].r_max_mm + s->body[b].r_max_mm + 5 : 0;
        }
        tippe_mesh_3mf_extra x;
        int *support = calloc((size_t)nb, sizeof *support);
        if (!support)
            rc = tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
        for (int b = 0; !rc && b < nb; b++)
            support[b] = tippe_export_body_needs_support(&s->body[b]);
        char desc[600];
        const char *keys[3] = {"Title", "Application", "Description"};
        const char *vals[3] = {tippe_design_name(d), "tippe " TIPPE_VERSION, desc};
        if (!rc) {
            slicer_settings(d, &q->profile, &x, desc, sizeof desc);
            x.n_meta = 3;
            x.meta_keys = keys;
            x.meta_values = vals;
            x.support = x.has_print ? support : NULL;
            rc = tippe_mesh_write_3mf_extra(meshes, names, dx, nb, &x, paths[k++], err);
        }
        free(support);
        free(names);
        free(dx);
    }
    if (!rc && (q->formats & TIPPE_EXPORT_SCAD)) {
        int fn = tippe_profile_angle_steps(tippe_design_radius_mm(d), q->profile.chord_mm / 2);
        rc = tippe_scad_write(d, s, &q->profile, q->z2_mm, fn, paths[k++], err);
    }
    if (!rc && k < np)
        rc = write_drawings(d, q, s, paths, k, np, err);
    if (!rc) {
        out->n_files = np;
        out->file = paths; /* the result's now */
        paths = NULL;
    }
    for (int b = 0; b < nb; b++)
        tippe_mesh_free(&meshes[b]);
    free(meshes);
    free(paths);
    out->seconds = now_s() - t0;
    return rc;
}

void tippe_export_result_free(tippe_export_result *r)
{
    if (!r)
        return;
    tippe_profile_set_free(&r->profiles);
    free(r->body);
    free(r->file);
    memset(r, 0, sizeof *r);
}
