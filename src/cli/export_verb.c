/* tippe export: printed bodies as STL and 3MF, OpenSCAD source, section drawing. */
#include "cli.h"

#include "tippe/build.h"
#include "tippe/design.h"
#include "tippe/export.h"
#include "tippe/physics.h"

#include <cjson/cJSON.h>

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static const char *const VERB = "export";

static int parse_formats(const char *text, unsigned *out)
{
    static const struct {
        const char *name;
        unsigned bit;
    } names[] = {{"stl", TIPPE_EXPORT_STL}, {"3mf", TIPPE_EXPORT_3MF},
                 {"scad", TIPPE_EXPORT_SCAD}, {"svg", TIPPE_EXPORT_SVG},
                 {"png", TIPPE_EXPORT_PNG}, {"pdf", TIPPE_EXPORT_PDF}};
    *out = 0;
    const char *p = text;
    while (*p) {
        size_t len = strcspn(p, ",");
        size_t k = 0;
        while (k < sizeof names / sizeof names[0] &&
               !(strlen(names[k].name) == len && !strncmp(p, names[k].name, len)))
            k++;
        if (k == sizeof names / sizeof names[0])
            return tippe_cli_usage_error(VERB,
                                         "--format %s: unknown format '%.*s' (formats: stl, "
                                         "3mf, scad, svg, png, pdf)",
                                         text, (int)len, p);
        *out |= names[k].bit;
        p += len + (p[len] == ',');
    }
    if (!*out)
        return tippe_cli_usage_error(VERB, "--format needs at least one format");
    return 0;
}

/* "group IIa" at Z2, for the drawing's title. */
static void zone_note(const tippe_design *d, double z2_mm, char *out, size_t size)
{
    tippe_top top;
    tippe_error err = {0};
    tippe_theory_class cls;
    if (tippe_design_top(d, z2_mm, &top, &err) ||
        tippe_theory_classify(top.A / top.C, top.eps / top.R, &cls)) {
        snprintf(out, size, "zone not defined here");
        return;
    }
    snprintf(out, size, "group %s of Theorem 5.1 (A/C = %.4f, eps/R = %.4f)",
             tippe_group_name(cls.group), top.A / top.C, top.eps / top.R);
}

/* A coordinate for a %.3f column: one that rounds to zero prints 0.000, not -0.000. */
static double coord_3dp(double v)
{
    return fabs(v) < 5e-4 ? 0.0 : v;
}

static void print_text(const tippe_design *d, const tippe_export_request *q,
                       const tippe_export_result *r)
{
    printf("design     %s (%s)\n", tippe_design_name(d), tippe_design_path(d));
    printf("chord      %.4g mm (mesh within it of the true surface)\n", q->profile.chord_mm);
    int grown = 0;
    for (int i = 0; i < r->profiles.n_parts; i++)
        if (r->profiles.clearance_applied[i] && q->profile.fit_diameter_mm > 0 &&
            i == q->profile.fit_part) {
            tippe_design_part_info p;
            tippe_design_solid hs;
            tippe_design_part(d, i, &p);
            /* a hole at its printed_radius_mm is the part as made: the print
             * model lays it there too (docs/printing.md, "The part as made") */
            int as_made = !tippe_design_part_solid(d, i, &hs) && hs.printed_radius_mm > 0 &&
                          fabs(2 * hs.printed_radius_mm - q->profile.fit_diameter_mm) < 1e-9;
            printf("fit        hole '%s' printed %.4g mm across: %s (the design's fit); %s\n",
                   p.name, q->profile.fit_diameter_mm, q->fit_note,
                   as_made ? "the print model lays it there too and cuts it to the hole's radius"
                           : "printed only, not in the mass model");
            grown = 1;
        } else if (r->profiles.clearance_applied[i]) {
            tippe_design_part_info p;
            tippe_design_part(d, i, &p);
            printf("clearance  %.4g mm radial on hole '%s' (takes hardware); printed only, "
                   "not in the mass model\n",
                   q->profile.clearance_mm, p.name);
            grown = 1;
        }
    if (!grown)
        printf("clearance  none applied (no hole of a printed body takes hardware)\n");
    for (int k = 0; k < r->profiles.n_sockets; k++) {
        tippe_design_part_info p;
        tippe_design_part(d, r->profiles.socket_part[k], &p);
        printf("socket     for rod '%s' at z %+.3f .. %+.3f mm, %.4g mm across (printed only, "
               "not in the mass model)\n",
               p.name, r->profiles.socket_rim_z_mm[k], r->profiles.socket_floor_z_mm[k],
               2 * r->profiles.socket_r_mm[k]);
    }
    printf("\n%-18s %-10s %9s %8s %13s %13s %10s  %s\n", "body", "material", "triangles",
           "steps", "mesh mm^3", "exact mm^3", "rel.err", "bounding box mm (x, y, z)");
    for (int b = 0; b < r->n_bodies; b++) {
        const tippe_export_body *e = &r->body[b];
        char exact[32], rel[32];
        if (isnan(e->exact_volume_mm3)) {
            snprintf(exact, sizeof exact, "(split)");
            snprintf(rel, sizeof rel, "-");
        } else {
            snprintf(exact, sizeof exact, "%.3f", e->exact_volume_mm3);
            snprintf(rel, sizeof rel, "%+.2e",
                     (e->mesh_volume_mm3 - e->exact_volume_mm3) / e->exact_volume_mm3);
        }
        printf("%-18s %-10s %9d %8d %13.3f %13s %10s  %.3f..%.3f, %.3f..%.3f, %.3f..%.3f\n",
               e->name, e->material, e->n_triangles, e->n_angles, e->mesh_volume_mm3, exact, rel,
               coord_3dp(e->lo_mm[0]), coord_3dp(e->hi_mm[0]), coord_3dp(e->lo_mm[1]), coord_3dp(e->hi_mm[1]),
               coord_3dp(e->lo_mm[2]), coord_3dp(e->hi_mm[2]));
    }
    printf("\nevery mesh: 0 open edges, 0 non-manifold edges, 0 flipped edges, 0 degenerate "
           "facets\n");
    for (int k = 0; k < r->n_files; k++)
        printf("wrote      %s\n", r->file[k]);
    printf("time       %.2f s\n", r->seconds);
}

static cJSON *to_json(const tippe_design *d, const tippe_export_request *q,
                      const tippe_export_result *r)
{
    cJSON *o = cJSON_CreateObject();
    if (!o)
        return NULL;
    cJSON_AddStringToObject(o, "design", tippe_design_name(d));
    cJSON_AddStringToObject(o, "file", tippe_design_path(d));
    cJSON_AddNumberToObject(o, "z2_mm", q->z2_mm);
    cJSON_AddNumberToObject(o, "chord_mm", q->profile.chord_mm);
    cJSON_AddNumberToObject(o, "clearance_mm", q->profile.clearance_mm);
    if (q->profile.fit_diameter_mm > 0) {
        tippe_design_part_info p;
        tippe_design_part(d, q->profile.fit_part, &p);
        cJSON *fit = cJSON_AddObjectToObject(o, "hole_fit");
        if (fit) {
            cJSON_AddStringToObject(fit, "hole", p.name);
            cJSON_AddNumberToObject(fit, "printed_diameter_mm", q->profile.fit_diameter_mm);
            cJSON_AddStringToObject(fit, "why", q->fit_note);
        }
    } else {
        cJSON_AddNullToObject(o, "hole_fit");
    }
    cJSON_AddBoolToObject(o, "clearance_in_mass_model", 0);
    cJSON *holes = cJSON_AddArrayToObject(o, "holes_with_clearance");
    for (int i = 0; holes && i < r->profiles.n_parts; i++)
        if (r->profiles.clearance_applied[i]) {
            tippe_design_part_info p;
            tippe_design_part(d, i, &p);
            cJSON_AddItemToArray(holes, cJSON_CreateString(p.name));
        }
    cJSON *bodies = cJSON_AddArrayToObject(o, "bodies");
    for (int b = 0; bodies && b < r->n_bodies; b++) {
        const tippe_export_body *e = &r->body[b];
        cJSON *j = cJSON_CreateObject();
        if (!j || !cJSON_AddItemToArray(bodies, j)) {
            cJSON_Delete(j);
            break;
        }
        cJSON_AddStringToObject(j, "name", e->name);
        cJSON_AddStringToObject(j, "material", e->material);
        if (e->stl_path[0])
            cJSON_AddStringToObject(j, "stl", e->stl_path);
        cJSON_AddNumberToObject(j, "triangles", e->n_triangles);
        cJSON_AddNumberToObject(j, "angle_steps", e->n_angles);
        cJSON_AddNumberToObject(j, "mesh_volume_mm3", e->mesh_volume_mm3);
        cJSON_AddNumberToObject(j, "profile_volume_mm3", e->polygon_volume_mm3);
        if (isnan(e->exact_volume_mm3))
            cJSON_AddNullToObject(j, "exact_volume_mm3");
        else
            cJSON_AddNumberToObject(j, "exact_volume_mm3", e->exact_volume_mm3);
        cJSON_AddItemToObject(j, "bbox_min_mm", cJSON_CreateDoubleArray(e->lo_mm, 3));
        cJSON_AddItemToObject(j, "bbox_max_mm", cJSON_CreateDoubleArray(e->hi_mm, 3));
        cJSON_AddNumberToObject(j, "open_edges", (double)e->audit.open_edges);
        cJSON_AddNumberToObject(j, "degenerate_facets", (double)e->audit.degenerate_triangles);
    }
    cJSON *so = cJSON_AddArrayToObject(o, "sockets");
    for (int k = 0; so && k < r->profiles.n_sockets; k++) {
        tippe_design_part_info p;
        tippe_design_part(d, r->profiles.socket_part[k], &p);
        cJSON *j = cJSON_CreateObject();
        if (!j || !cJSON_AddItemToArray(so, j)) {
            cJSON_Delete(j);
            break;
        }
        cJSON_AddStringToObject(j, "rod", p.name);
        cJSON_AddNumberToObject(j, "diameter_mm", 2 * r->profiles.socket_r_mm[k]);
        cJSON_AddNumberToObject(j, "rim_z_mm", r->profiles.socket_rim_z_mm[k]);
        cJSON_AddNumberToObject(j, "floor_z_mm", r->profiles.socket_floor_z_mm[k]);
        cJSON_AddNumberToObject(j, "volume_mm3", r->profiles.socket_volume_mm3[k]);
    }
    cJSON *w = cJSON_AddArrayToObject(o, "warnings");
    for (int k = 0; w && k < r->profiles.n_warnings; k++)
        cJSON_AddItemToArray(w, cJSON_CreateString(r->profiles.warning[k]));
    cJSON *files = cJSON_AddArrayToObject(o, "files");
    for (int k = 0; files && k < r->n_files; k++)
        cJSON_AddItemToArray(files, cJSON_CreateString(r->file[k]));
    cJSON_AddNumberToObject(o, "seconds", r->seconds);
    return o;
}

typedef struct {
    tippe_export_request q;
    const char *dir, *formats, *path;
    double z2_mm;
    int json;
    tippe_cli_sets sets;
} export_args;

/* Options and the design file: 0, TIPPE_CLI_HELP, or 2 after a usage error. */
static int export_parse(export_args *a, int argc, char **argv)
{
    tippe_export_request *q = &a->q;
    tippe_cli_opt opts[] = {
        {.name = "output", .short_name = 'o', .kind = TIPPE_CLI_STRING, .value = &a->dir,
         .arg = "DIR", .required = 1,
         .help = "output directory (created if missing; its parent must exist)"},
        {.name = "format", .kind = TIPPE_CLI_STRING, .value = &a->formats, .arg = "LIST",
         .def = "stl,3mf,scad,svg,png",
         .help = "comma-separated: stl (binary STL per body, DIR/STEM-BODY.stl),\n"
                 "3mf (all bodies, DIR/STEM.3mf), scad (OpenSCAD source, DIR/STEM.scad),\n"
                 "svg, png, pdf (section drawing, DIR/STEM-section.EXT);\n"
                 "STEM is the design file's name without .json"},
        {.name = "z2", .kind = TIPPE_CLI_DOUBLE, .value = &a->z2_mm, .arg = "MM", .unit = "mm",
         .min = -TIPPE_CLI_Z2_MAX_MM, .max = TIPPE_CLI_Z2_MAX_MM,
         .def = "middle of the travel",
         .help = "the moving weight's place in the drawing and the OpenSCAD file"},
        {.name = "chord-mm", .kind = TIPPE_CLI_DOUBLE, .value = &q->profile.chord_mm,
         .arg = "MM", .unit = "mm", .min = 0.001, .max = 1, .def = "0.01",
         .help = "largest distance from the mesh to the true surface; half goes to the\n"
                 "profile's arcs, half to the steps around the axis"},
        {.name = "clearance-mm", .kind = TIPPE_CLI_DOUBLE, .value = &q->profile.clearance_mm,
         .arg = "MM", .unit = "mm", .min = 0, .max = 2, .def = "0.2",
         .help = "radial clearance of holes that take hardware; printed only: the mass\n"
                 "model (eval, sweep) keeps the design's hole"},
        {.name = "min-wall-mm", .kind = TIPPE_CLI_DOUBLE, .value = &q->profile.min_wall_mm,
         .arg = "MM", .unit = "mm", .min = 0, .max = 10, .def = "0.9",
         .help = "warn about printed walls thinner than this (two 0.45 mm perimeters)"},
        {.name = "split", .kind = TIPPE_CLI_FLAG, .value = &q->profile.split,
         .help = "cut each body at a plane across the axis into two halves, each\n"
                 "written standing on its flat cut face (a solid body's halves need no\n"
                 "support; a shell's need it inside the dome: docs/printing.md)"},
        {.name = "split-z", .kind = TIPPE_CLI_DOUBLE, .value = &q->profile.split_z_mm,
         .arg = "MM", .unit = "mm", .min = -TIPPE_CLI_Z2_MAX_MM, .max = TIPPE_CLI_Z2_MAX_MM,
         .def = "0", .help = "height of the cut plane above the sphere's centre (with --split)"},
        {.name = "joint", .kind = TIPPE_CLI_FLAG, .value = &q->profile.joint,
         .help = "with --split: a groove 2 mm deep in both cut faces (the inner half of\n"
                 "each wall) and a printed ring that fills both, to align and join the\n"
                 "halves (body joint-ring; --clearance-mm of play)"},
        {.name = "sockets", .kind = TIPPE_CLI_FLAG, .value = &q->profile.sockets,
         .help = "with --split: a socket at each pole for a rod that spans the shell's\n"
                 "cavity (a pocket of the rod's radius plus the clearance, 1 mm into the\n"
                 "wall), so that the rod, cut that much longer, is held on the axis"},
        {.name = "json", .kind = TIPPE_CLI_FLAG, .value = &a->json,
         .help = "print the report as one JSON object"},
        {.name = "set", .kind = TIPPE_CLI_SET, .value = &a->sets, .arg = "FIELD=VALUE",
         .help = "change a field of the design before it is checked (repeatable)"},
        {NULL},
    };
    tippe_cli_spec spec = {
        .verb = VERB,
        .synopsis = "DESIGN.json -o DIR [--z2 MM] [--format LIST] [--chord-mm MM]\n"
                    "       [--clearance-mm MM] [--split [--split-z MM] [--joint] [--sockets]] [--json]",
        .about = "Writes what a maker prints from: every fixed part of a printable material,\n"
                 "less the voids cut from it, as one solid per printed body; the OpenSCAD\n"
                 "source of the whole top and its dimensioned section drawing.",
        .after = "Each mesh is checked before it is written (closed, manifold, outward, no\n"
                 "degenerate facet); the report gives its volume beside the exact volume of the\n"
                 "body. A hole whose design gives \"fit\": \"tap\" or \"insert\" is printed at\n"
                 "the screw's tap drill or the heat-set insert's pilot hole instead of with\n"
                 "the clearance (docs/design-format.md). Exit status: 0 ok, 2 bad usage or\n"
                 "design (or nothing printable), 1 a file could not be written. See\n"
                 "docs/export.md.",
        .opts = opts,
        .min_args = 1,
        .max_args = 1,
        .args_name = "design file",
    };
    int n_args = 0;
    int rc = tippe_cli_parse(&spec, argc, argv, &a->path, &n_args);
    if (rc)
        return rc;
    if (tippe_cli_find_opt(&spec, "split-z")->seen && !q->profile.split)
        return tippe_cli_usage_error(VERB, "--split-z needs --split");
    if (q->profile.joint && !q->profile.split)
        return tippe_cli_usage_error(VERB, "--joint needs --split");
    if (q->profile.sockets && !q->profile.split)
        return tippe_cli_usage_error(VERB, "--sockets needs --split (the rod is put in "
                                           "before the halves are joined)");
    if (parse_formats(a->formats, &q->formats))
        return 2;
    if (!strcmp(a->dir, "-")) /* several files cannot share standard output */
        return tippe_cli_usage_error(VERB, "-o -: export writes several files into a "
                                     "directory, not to standard output; give a directory");
    q->dir = a->dir;
    return 0;
}

/* Every output path is checked before anything is written: 0, or the exit status. */
static int export_check_outputs(const tippe_design *d, const export_args *a)
{
    tippe_error err = {0};
    char(*paths)[4096] = NULL;
    int np = tippe_export_plan(d, &a->q, &paths, &err);
    if (np < 0) {
        free(paths);
        return tippe_cli_fail(VERB, &err, err.code ? err.code : TIPPE_EINPUT);
    }
    int rc = tippe_cli_make_output_dir(VERB, "-o", a->dir);
    for (int k = 0; !rc && k < np; k++)
        rc = tippe_cli_check_output(VERB, "-o", paths[k], 0);
    free(paths);
    return rc;
}

/* Meshes, files and the report: 0, or the exit status. */
static int export_write(const tippe_design *d, const export_args *a)
{
    tippe_error err = {0};
    tippe_export_result r;
    int rc = tippe_export_run(d, &a->q, &r, &err);
    for (int k = 0; k < r.profiles.n_warnings; k++)
        fprintf(stderr, "tippe %s: warning: %s\n", VERB, r.profiles.warning[k]);
    if (rc) {
        tippe_export_result_free(&r);
        return tippe_cli_fail(VERB, &err, rc);
    }
    if (a->json)
        rc = tippe_cli_print_json(VERB, to_json(d, &a->q, &r));
    else
        print_text(d, &a->q, &r);
    tippe_export_result_free(&r);
    return rc;
}

int tippe_cli_export(int argc, char **argv)
{
    export_args a = {.q = {.profile = tippe_profile_defaults()},
                     .formats = "stl,3mf,scad,svg,png",
                     .z2_mm = NAN};
    int rc = export_parse(&a, argc, argv);
    if (rc)
        return rc == TIPPE_CLI_HELP ? 0 : rc;
    tippe_error err = {0};
    tippe_design *d = NULL;
    if ((rc = tippe_design_load(a.path, a.sets.item, a.sets.n, &d, &err)))
        return tippe_cli_fail(VERB, &err, rc);
    double t0, t1;
    tippe_design_travel_mm(d, &t0, &t1);
    a.q.z2_mm = isnan(a.z2_mm) ? 0.5 * (t0 + t1) : a.z2_mm;
    tippe_top top;
    char note[200], fit_note[64];
    int fit_part;
    double fit_mm;
    /* the screw's hole as the design's fit asks (tap drill or insert pilot hole) */
    if ((rc = tippe_build_design_fit(d, a.q.profile.clearance_mm, &fit_part, &fit_mm, fit_note,
                                     sizeof fit_note, &err))) {
        rc = tippe_cli_fail(VERB, &err, rc);
    } else if (fit_part >= 0) {
        a.q.profile.fit_part = fit_part;
        a.q.profile.fit_diameter_mm = fit_mm;
        a.q.fit_note = fit_note;
    }
    if (rc) {
        /* reported */
    } else if ((rc = tippe_design_top(d, a.q.z2_mm, &top, &err))) {
        rc = tippe_cli_fail(VERB, &err, rc);
    } else {
        zone_note(d, a.q.z2_mm, note, sizeof note);
        a.q.title_note = note;
        rc = export_check_outputs(d, &a);
        if (!rc)
            rc = export_write(d, &a);
    }
    tippe_design_free(d);
    return rc;
}
