/* tippe export: printed bodies as STL and 3MF, OpenSCAD source, section drawing. */
#include "cli.h"

#include "tippe/design.h"
#include "tippe/export.h"
#include "tippe/theory.h"

#include <cjson/cJSON.h>

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static const char *const VERB = "export";

static void export_usage(FILE *out)
{
    fprintf(out,
            "usage: tippe export DESIGN.json -o DIR [--z2 MM] [--format LIST] [--chord-mm MM]\n"
            "                    [--clearance-mm MM] [--min-wall-mm MM] [--split [--split-z MM]]\n"
            "                    [--json] [--set FIELD=VALUE ...]\n"
            "\n"
            "Writes what a maker prints from: every fixed part of a printable material, less\n"
            "the voids cut from it, as one solid per printed body.\n"
            "\n"
            "  -o DIR             output directory (created if missing; its parent must exist)\n"
            "  --format LIST      comma-separated, default stl,3mf,scad,svg,png:\n"
            "                       stl   binary STL per body      DIR/STEM-BODY.stl\n"
            "                       3mf   all bodies in one 3MF    DIR/STEM.3mf\n"
            "                       scad  OpenSCAD source          DIR/STEM.scad\n"
            "                       svg, png, pdf  section drawing DIR/STEM-section.EXT\n"
            "                     (STEM is the design file's name without .json)\n"
            "  --z2 MM            moving weight's place in the drawing and the OpenSCAD file,\n"
            "                     mm (default: the middle of the design's travel)\n"
            "  --chord-mm MM      largest distance from the mesh to the true surface, mm\n"
            "                     (default 0.01; 0.001 .. 1); half goes to the profile's arcs,\n"
            "                     half to the steps around the axis\n"
            "  --clearance-mm MM  radial clearance of holes that take hardware, mm (default\n"
            "                     0.2; 0 .. 2). Printed only: the mass model (eval, sweep)\n"
            "                     keeps the design's hole\n"
            "  --min-wall-mm MM   warn about printed walls thinner than this, mm (default 0.9:\n"
            "                     two 0.45 mm perimeters)\n"
            "  --split            cut each body at a plane across the axis into two halves, each\n"
            "                     written standing on its flat cut face (no supports needed)\n"
            "  --split-z MM       height of the cut plane above the centre, mm (default 0)\n"
            "  --json             print the report as one JSON object\n"
            "  --set FIELD=VALUE  change a field of the design first (see tippe eval --help)\n"
            "  --help             this text\n"
            "\n"
            "Each mesh is checked before it is written (closed, manifold, outward, no\n"
            "degenerate facet) and the report gives its volume beside the exact volume of\n"
            "the body. Exit status: 0 ok, 2 bad usage or design (or nothing printable),\n"
            "1 a file could not be written. See docs/export.md.\n");
}

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

/* Creates dir if it is missing (one level): 0, or 2 after a usage error. */
static int make_dir(const char *dir)
{
    struct stat st;
    if (stat(dir, &st) == 0) {
        if (!S_ISDIR(st.st_mode))
            return tippe_cli_usage_error(VERB, "-o %s: not a directory", dir);
        return 0;
    }
    if (mkdir(dir, 0777) != 0)
        return tippe_cli_usage_error(VERB, "-o %s: cannot create the directory: %s", dir,
                                     strerror(errno));
    return 0;
}

typedef struct {
    const char *path, *dir;
    const char *z2_text;
    const char *values[5]; /* chord, clearance, min wall, split z */
    unsigned formats;
    int split, json;
    tippe_cli_sets sets;
} export_args;

static int parse_args(int argc, char **argv, export_args *a)
{
    static const char *const number_opts[] = {"--chord-mm", "--clearance-mm", "--min-wall-mm",
                                              "--split-z"};
    const char *v;
    a->formats = TIPPE_EXPORT_STL | TIPPE_EXPORT_3MF | TIPPE_EXPORT_SCAD | TIPPE_EXPORT_SVG |
                 TIPPE_EXPORT_PNG;
    for (int i = 1; i < argc; i++) {
        const char *arg = argv[i];
        int matched = 0;
        if (tippe_cli_is_help(arg)) {
            export_usage(stdout);
            return -1;
        } else if (!strcmp(arg, "--json")) {
            a->json = 1;
        } else if (!strcmp(arg, "--split")) {
            a->split = 1;
        } else if (tippe_cli_option(VERB, argc, argv, &i, "-o", 0, &v) ||
                   tippe_cli_option(VERB, argc, argv, &i, "--output", 1, &v)) {
            if (!v)
                return 2;
            a->dir = v;
        } else if (tippe_cli_option(VERB, argc, argv, &i, "--z2", 1, &v)) {
            if (!v)
                return 2;
            a->z2_text = v;
        } else if (tippe_cli_option(VERB, argc, argv, &i, "--format", 1, &v)) {
            if (!v || parse_formats(v, &a->formats))
                return 2;
        } else if (tippe_cli_option(VERB, argc, argv, &i, "--set", 1, &v)) {
            if (!v || tippe_cli_add_set(VERB, &a->sets, v))
                return 2;
        } else {
            for (int k = 0; k < 4 && !matched; k++)
                if (tippe_cli_option(VERB, argc, argv, &i, number_opts[k], 1, &v)) {
                    if (!v)
                        return 2;
                    a->values[k] = v;
                    matched = 1;
                }
            if (matched)
                continue;
            if (tippe_cli_is_option(arg, 0))
                return tippe_cli_usage_error(VERB, "unknown option '%s'", arg);
            if (a->path)
                return tippe_cli_usage_error(VERB, "one design file only (got also '%s')", arg);
            a->path = arg;
        }
    }
    if (!a->path)
        return tippe_cli_usage_error(VERB, "no design file given");
    if (!a->dir)
        return tippe_cli_usage_error(VERB, "-o DIR is required (where the files go)");
    if (a->values[3] && !a->split)
        return tippe_cli_usage_error(VERB, "--split-z needs --split");
    return 0;
}

/* The numbers of the request, with their ranges checked by the library. */
static int read_numbers(const export_args *a, tippe_export_request *q)
{
    static const char *const names[] = {"--chord-mm", "--clearance-mm", "--min-wall-mm",
                                        "--split-z"};
    double *dst[] = {&q->profile.chord_mm, &q->profile.clearance_mm, &q->profile.min_wall_mm,
                     &q->profile.split_z_mm};
    for (int k = 0; k < 4; k++)
        if (a->values[k] && tippe_cli_number(VERB, names[k], a->values[k], "mm", dst[k]))
            return 2;
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

static void print_text(const tippe_design *d, const tippe_export_request *q,
                       const tippe_export_result *r)
{
    printf("design     %s (%s)\n", tippe_design_name(d), tippe_design_path(d));
    printf("chord      %.4g mm (mesh within it of the true surface)\n", q->profile.chord_mm);
    int grown = 0;
    for (int i = 0; i < r->profiles.n_parts; i++)
        if (r->profiles.clearance_applied[i]) {
            tippe_design_part_info p;
            tippe_design_part(d, i, &p);
            printf("clearance  %.4g mm radial on hole '%s' (takes hardware); printed only, "
                   "not in the mass model\n",
                   q->profile.clearance_mm, p.name);
            grown = 1;
        }
    if (!grown)
        printf("clearance  none applied (no hole of a printed body takes hardware)\n");
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
               e->lo_mm[0], e->hi_mm[0], e->lo_mm[1], e->hi_mm[1], e->lo_mm[2], e->hi_mm[2]);
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
    cJSON *w = cJSON_AddArrayToObject(o, "warnings");
    for (int k = 0; w && k < r->profiles.n_warnings; k++)
        cJSON_AddItemToArray(w, cJSON_CreateString(r->profiles.warning[k]));
    cJSON *files = cJSON_AddArrayToObject(o, "files");
    for (int k = 0; files && k < r->n_files; k++)
        cJSON_AddItemToArray(files, cJSON_CreateString(r->file[k]));
    cJSON_AddNumberToObject(o, "seconds", r->seconds);
    return o;
}

int tippe_cli_export(int argc, char **argv)
{
    export_args a = {0};
    int rc = parse_args(argc, argv, &a);
    if (rc)
        return rc < 0 ? 0 : rc;
    tippe_export_request q = {.profile = tippe_profile_defaults(), .formats = a.formats,
                              .dir = a.dir};
    q.profile.split = a.split;
    if (read_numbers(&a, &q))
        return 2;
    double z2_mm = NAN;
    if (a.z2_text && tippe_cli_number(VERB, "--z2", a.z2_text, "mm", &z2_mm))
        return 2;

    tippe_error err = {0};
    tippe_design *d = NULL;
    rc = tippe_design_load(a.path, a.sets.item, a.sets.n, &d, &err);
    if (rc)
        return tippe_cli_fail(VERB, &err, rc);
    double t0, t1;
    tippe_design_travel_mm(d, &t0, &t1);
    q.z2_mm = a.z2_text ? z2_mm : 0.5 * (t0 + t1);
    tippe_top top;
    if ((rc = tippe_design_top(d, q.z2_mm, &top, &err))) {
        tippe_design_free(d);
        return tippe_cli_fail(VERB, &err, rc);
    }
    char note[200];
    zone_note(d, q.z2_mm, note, sizeof note);
    q.title_note = note;

    /* Every output path is checked before anything is written. */
    char(*paths)[4096] = malloc(TIPPE_EXPORT_MAX_FILES * sizeof *paths);
    int np = paths ? tippe_export_plan(d, &q, paths, TIPPE_EXPORT_MAX_FILES, &err) : -1;
    if (np < 0) {
        free(paths);
        tippe_design_free(d);
        if (!paths)
            return fprintf(stderr, "tippe %s: out of memory\n", VERB), 1;
        return tippe_cli_fail(VERB, &err, err.code ? err.code : TIPPE_EINPUT);
    }
    rc = make_dir(a.dir);
    for (int k = 0; !rc && k < np; k++)
        rc = tippe_cli_check_output(VERB, "-o", paths[k], 0);
    free(paths);
    if (rc) {
        tippe_design_free(d);
        return rc;
    }

    tippe_export_result r;
    rc = tippe_export_run(d, &q, &r, &err);
    for (int k = 0; k < r.profiles.n_warnings; k++)
        fprintf(stderr, "tippe %s: warning: %s\n", VERB, r.profiles.warning[k]);
    if (rc) {
        tippe_export_result_free(&r);
        tippe_design_free(d);
        return tippe_cli_fail(VERB, &err, rc);
    }
    if (a.json)
        rc = tippe_cli_print_json(VERB, to_json(d, &q, &r));
    else
        print_text(d, &q, &r);
    tippe_export_result_free(&r);
    tippe_design_free(d);
    return rc;
}
