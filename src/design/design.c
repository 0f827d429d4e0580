/* Design files: parse (cJSON), override, validate, and place the moving weight.
 *
 * Everything geometric in this file is in mm (as in the design file); the
 * moments handed to the geometry module, and the top, are SI.
 *
 * Overlap and travel are decided on the (r, z) half-plane, where every part is
 * a region of revolution. At a fixed r each region is a finite union of z
 * intervals, known in closed form (a disc, an annulus, a rectangle, an
 * ellipse, cut by a clip disc, minus voids). So at each sampled r the overlap
 * of two parts, and the Z2 shifts at which a moving part meets a fixed one,
 * are exact interval arithmetic; only r is sampled (a uniform grid plus every
 * radius where some part's boundary starts or ends, see sample_radii). To let
 * parts touch, material is eroded and voids dilated by TOL_MM before comparing:
 * "overlap" means sharing volume more than TOL_MM deep. docs/design-format.md
 * states the resolution this gives. */
#include "design/internal.h"
#include "tippe/base.h"
#include "base/json.h"

#include <cjson/cJSON.h>
#include <errno.h>
#include <gsl/gsl_errno.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>


/* "0.025 m is 25 mm" / "25000 um is 25 mm": what a length would be in mm if it
 * was typed in metres (small) or micrometres (large), when that fits in
 * [lo_mm, hi_mm] (and, from micrometres, is at least 1 mm: a 60 mm rod too long
 * for its ball is not 60 um); else "". */
static void unit_hint(double v_mm, double lo_mm, double hi_mm, char *buf, size_t cap)
{
    buf[0] = '\0';
    if (v_mm < lo_mm && v_mm * 1e3 >= lo_mm && v_mm * 1e3 <= hi_mm)
        snprintf(buf, cap, "; did you mean metres? %g m is %g mm", v_mm, v_mm * 1e3);
    else if (v_mm > hi_mm && v_mm * 1e-3 >= fmax(lo_mm, 1.0) && v_mm * 1e-3 <= hi_mm)
        snprintf(buf, cap, "; did you mean micrometres? %g um is %g mm", v_mm, v_mm * 1e-3);
}

/* The sphere's radius, checked before anything that depends on it, so that a
 * radius in the wrong unit is said as such (not as a travel or a part that no
 * longer fits). */
static int check_sphere_radius(const tippe_json_reader *c, double R)
{
    if (R >= RADIUS_MIN_MM && R <= RADIUS_MAX_MM)
        return TIPPE_OK;
    char hint[160];
    unit_hint(R, RADIUS_MIN_MM, RADIUS_MAX_MM, hint, sizeof hint);
    return tippe_json_fail(c, "radius_mm",
                           "%g mm is %s than any tippe top (a sphere radius is %g .. %g mm; "
                           "lengths in a design are in mm)%s",
                           R, R < RADIUS_MIN_MM ? "smaller" : "larger", RADIUS_MIN_MM,
                           RADIUS_MAX_MM, hint);
}

/* ------------------------------------------------------------ mass moments */



static int finite_moments(tippe_moments m)
{
    return isfinite(m.m) && isfinite(m.m_z) && isfinite(m.m_zz) && isfinite(m.m_rr);
}

/* ------------------------------------------------------------------- load */

char *tippe_design_dup_string(const char *s)
{
    size_t n = strlen(s) + 1;
    char *r = malloc(n);
    if (r)
        memcpy(r, s, n);
    return r;
}

/* travel_mm: [from, to], from < to. */
static int parse_travel(const tippe_json_reader *c, const cJSON *root, tippe_design *d)
{
    const cJSON *tr = cJSON_GetObjectItemCaseSensitive(root, "travel_mm");
    if (!tr)
        return tippe_json_fail(c, "travel_mm",
                               "missing (required: [from, to] in mm, the range of Z2)");
    if (!cJSON_IsArray(tr) || cJSON_GetArraySize(tr) != 2)
        return tippe_json_fail(c, "travel_mm", "must be an array [from, to] of two numbers (mm)");
    for (int k = 0; k < 2; k++) {
        const cJSON *v = cJSON_GetArrayItem(tr, k);
        char p[32];
        snprintf(p, sizeof p, "travel_mm[%d]", k);
        if (!cJSON_IsNumber(v) || !isfinite(v->valuedouble))
            return tippe_json_wrong_type(c, p, "a finite number (mm)", v);
        d->travel_mm[k] = v->valuedouble;
    }
    if (!(d->travel_mm[0] < d->travel_mm[1]))
        return tippe_json_fail(c, "travel_mm", "from (%g mm) must be less than to (%g mm)",
                               d->travel_mm[0], d->travel_mm[1]);
    return TIPPE_OK;
}

/* "catalogue": the hardware catalogue file (tippe/build.h), relative to the
 * design file; it must be readable (its contents are read where they are
 * used). A design from memory names only the designs folder's catalogue.json. */
static int parse_catalogue(const tippe_json_reader *c, const cJSON *root, const char *path,
                           tippe_design *d)
{
    char rel[512], file[1024];
    int has = 0;
    int rc = tippe_json_string(c, root, "", "catalogue", 0, rel, sizeof rel, &has);
    if (rc || !has)
        return rc;
    if (!rel[0])
        return tippe_json_fail(c, "catalogue", "must be a file name (relative to the design file)");
    if (d->materials_dir) {
        if (strcmp(rel, "catalogue.json"))
            return tippe_json_fail(c, "catalogue",
                                   "'%s': a design sent as text uses the catalogue "
                                   "catalogue.json of the designs folder and names no other "
                                   "file", rel);
        snprintf(file, sizeof file, "%s/catalogue.json", d->materials_dir);
    } else
        tippe_path_beside(path, rel, file, sizeof file);
    if (access(file, R_OK) != 0)
        return tippe_json_fail(c, "catalogue", "%s: cannot be read (%s)", file, strerror(errno));
    free(d->catalogue);
    if (!(d->catalogue = tippe_design_dup_string(file)))
        return tippe_error_set(c->err, TIPPE_ECOMPUTE, "out of memory");
    return TIPPE_OK;
}

/* The top-level fields other than parts; mat_rel gets the materials file as
 * written (default materials.json), *has_mat_file whether it was given. */
static int parse_header(const tippe_json_reader *c, const cJSON *root, const char *path,
                        tippe_design *d, char *mat_rel, size_t mat_cap, int *has_mat_file)
{
    int rc;
    char name[256];
    if (!cJSON_IsObject(root))
        return tippe_json_wrong_type(c, NULL, "a JSON object (a design)", root);
    if ((rc = tippe_json_check_keys(c, root, "", "a design", tippe_design_top_keys, NULL)) ||
        (rc = tippe_json_string(c, root, "", "name", 1, name, sizeof name, NULL)) ||
        (rc = !name[0] ? tippe_json_fail(c, "name", "must not be empty") : TIPPE_OK) ||
        (rc = tippe_json_text(c, root, "", "notes", 0, NULL, 0, NULL)) ||
        (rc = tippe_design_read_length(c, root, "", "radius_mm", 1, 0, &d->radius_mm, NULL)) ||
        (rc = check_sphere_radius(c, d->radius_mm)))
        return rc;
    if (!(d->name = tippe_design_dup_string(name)) || !(d->path = tippe_design_dup_string(path)))
        return tippe_error_set(c->err, TIPPE_ECOMPUTE, "out of memory");
    if ((rc = parse_travel(c, root, d)))
        return rc;
    snprintf(mat_rel, mat_cap, "materials.json");
    if ((rc = tippe_json_string(c, root, "", "materials", 0, mat_rel, mat_cap, has_mat_file)))
        return rc;
    if (*has_mat_file && !mat_rel[0])
        return tippe_json_fail(c, "materials", "must be a file name (relative to the design file)");
    return parse_catalogue(c, root, path, d);
}

/* parts: 1 to MAX_PARTS parts with unique names. */
static int parse_parts(const tippe_json_reader *c, const cJSON *root, tippe_design *d)
{
    int rc;
    const cJSON *parts = cJSON_GetObjectItemCaseSensitive(root, "parts");
    if (!parts)
        return tippe_json_fail(c, "parts", "missing (required: an array of parts)");
    if (!cJSON_IsArray(parts))
        return tippe_json_wrong_type(c, "parts", "an array of parts", parts);
    int n = cJSON_GetArraySize(parts);
    if (n < 1 || n > MAX_PARTS)
        return tippe_json_fail(c, "parts", "must hold 1 to %d parts, not %d", MAX_PARTS, n);
    if (!(d->parts = calloc((size_t)n, sizeof *d->parts)))
        return tippe_error_set(c->err, TIPPE_ECOMPUTE, "out of memory");
    d->n_parts = n;
    int i = 0;
    for (const cJSON *p = parts->child; p; p = p->next, i++)
        if ((rc = tippe_design_parse_part(c, p, i, &d->parts[i])))
            return rc;
    char pth[64];
    for (i = 0; i < n; i++)
        for (int j = 0; j < i; j++)
            if (!strcmp(d->parts[i].name, d->parts[j].name)) {
                snprintf(pth, sizeof pth, "parts[%d].name", i);
                return tippe_json_fail(
                    c, pth, "'%s' is already the name of parts[%d]: names must be unique",
                    d->parts[i].name, j);
            }
    return TIPPE_OK;
}

/* Densities of the parts that name a material. The table is read only when
 * some part names one; its path is relative to the design file. */
static int resolve_materials(const tippe_json_reader *c, const char *path, const char *mat_rel,
                             int has_mat_file, tippe_design *d)
{
    int uses_table = 0;
    for (int i = 0; i < d->n_parts; i++)
        uses_table |= !d->parts[i].is_void && d->parts[i].material[0];
    if (!uses_table)
        return TIPPE_OK;
    char mat_file[1024];
    if (d->materials_dir) {
        /* a design from memory names no file: the shipped table only */
        if (strcmp(mat_rel, "materials.json"))
            return tippe_json_fail(c, "materials",
                                   "'%s': a design sent as text uses the materials table "
                                   "materials.json of the designs folder and names no other "
                                   "file", mat_rel);
        snprintf(mat_file, sizeof mat_file, "%s/materials.json", d->materials_dir);
    } else
        tippe_path_beside(path, mat_rel, mat_file, sizeof mat_file);
    /* No "materials" field and no materials.json beside the design: the shipped
     * table (installed, or the checkout's designs/), said in a note
     * (tippe_design_note); none at all is the first material's error. */
    if (!d->materials_dir && !has_mat_file) {
        char beside[sizeof mat_file], looked[sizeof mat_file];
        snprintf(beside, sizeof beside, "%s", mat_file);
        if (!tippe_design_default_table(beside, looked, sizeof looked, &d->mat_fallback)) {
            int i = 0;
            while (d->parts[i].is_void || !d->parts[i].material[0])
                i++;
            char pth[64];
            snprintf(pth, sizeof pth, "parts[%d].material", i);
            return tippe_json_fail(c, pth,
                                   "'%s' needs a materials table: there is no %s beside the "
                                   "design and no installed one (looked in %s); name one in "
                                   "the design's \"materials\" field",
                                   d->parts[i].material, beside, looked);
        }
        snprintf(mat_file, sizeof mat_file, "%s", looked);
    }
    cJSON *table = NULL;
    int rc = tippe_design_known_materials(d, mat_file, &table)
                 ? TIPPE_OK
                 : tippe_design_load_materials(mat_file, &table, c->err);
    if (rc) {
        if (has_mat_file) {
            char inner[sizeof c->err->msg];
            snprintf(inner, sizeof inner, "%s", c->err->msg);
            return tippe_json_fail(c, "materials", "%s", inner);
        }
        return rc;
    }
    char pth[64];
    for (int i = 0; i < d->n_parts && !rc; i++) {
        part *p = &d->parts[i];
        if (p->is_void || !p->material[0])
            continue;
        snprintf(pth, sizeof pth, "parts[%d].material", i);
        rc = tippe_design_lookup_material(c, table, mat_file, p->material, pth, &p->density_g_cm3,
                             &p->printable, &p->E_pa, &p->nu);
    }
    if (rc) {
        cJSON_Delete(table);
        return rc;
    }
    d->mat_table = table; /* kept for the designs derived from this one */
    if (!(d->mat_file = tippe_design_dup_string(mat_file)))
        rc = tippe_error_set(c->err, TIPPE_ECOMPUTE, "out of memory");
    return rc;
}

/* Void p takes its parent's density and motion. */
static int resolve_void(const tippe_json_reader *c, tippe_design *d, int i)
{
    part *p = &d->parts[i];
    char pth[64];
    int j = 0;
    while (j < d->n_parts && strcmp(d->parts[j].name, p->material))
        j++;
    snprintf(pth, sizeof pth, "parts[%d].cut_from", i);
    if (j == d->n_parts)
        return tippe_json_fail(c, pth, "no part named '%s'", p->material);
    if (d->parts[j].is_void)
        return tippe_json_fail(c, pth, "'%s' is itself a void: cut from the solid part",
                               p->material);
    p->parent = j;
    p->moving = d->parts[j].moving;
    p->density_g_cm3 = d->parts[j].density_g_cm3;
    p->printable = d->parts[j].printable;
    snprintf(p->material, sizeof p->material, "%s", d->parts[j].material);
    return TIPPE_OK;
}

/* The clip radius of part i: the sphere, or the cavity of the one fixed
 * shell (shell: its index, n_shell: how many fixed shells there are). */
static int resolve_clip(const tippe_json_reader *c, tippe_design *d, int i, int shell,
                        int n_shell)
{
    part *p = &d->parts[i];
    char pth[64];
    snprintf(pth, sizeof pth, "parts[%d].clip", i);
    if (p->clip && p->moving)
        return tippe_json_fail(c, pth,
                               "a void cut from a moving part cannot be clipped (its shape "
                               "would change as it moves)");
    if (p->clip == CLIP_SPHERE) {
        p->clip_radius_mm = d->radius_mm;
    } else if (p->clip == CLIP_CAVITY || p->clip == CLIP_SHELL) {
        const char *word = p->clip == CLIP_CAVITY ? "cavity" : "shell";
        if (n_shell != 1)
            return tippe_json_fail(c, pth,
                                   "\"%s\" needs exactly one fixed shell part, the design "
                                   "has %d",
                                   word, n_shell);
        if (d->parts[shell].z_mm != 0)
            return tippe_json_fail(c, pth, "\"%s\" needs the shell '%s' centred at z_mm = 0",
                                   word, d->parts[shell].name);
        double cavity = d->parts[shell].radius_mm - d->parts[shell].thickness_mm;
        p->clip_radius_mm = p->clip == CLIP_CAVITY ? cavity : d->parts[shell].radius_mm;
        p->clip_inner_mm = p->clip == CLIP_SHELL ? cavity : 0;
    }
    return TIPPE_OK;
}

/* Voids, clips and default sizes, resolved against the sphere and the shell. */
static int resolve_parts(const tippe_json_reader *c, tippe_design *d)
{
    int rc, shell = -1, n_shell = 0;
    char pth[64];
    for (int i = 0; i < d->n_parts; i++)
        if (d->parts[i].shape == SHAPE_SHELL && !d->parts[i].is_void && !d->parts[i].moving) {
            shell = i;
            n_shell++;
        }
    for (int i = 0; i < d->n_parts; i++) {
        part *p = &d->parts[i];
        if ((p->shape == SHAPE_BALL || p->shape == SHAPE_SHELL) && !p->has_radius)
            p->radius_mm = d->radius_mm; /* default: the sphere itself */
        if (p->shape == SHAPE_SHELL && p->thickness_mm >= p->radius_mm) {
            snprintf(pth, sizeof pth, "parts[%d].thickness_mm", i);
            return tippe_json_fail(c, pth, "%g mm is not less than the shell's radius %g mm",
                                   p->thickness_mm, p->radius_mm);
        }
        if (p->is_void && (rc = resolve_void(c, d, i)))
            return rc;
        if ((rc = resolve_clip(c, d, i, shell, n_shell)))
            return rc;
        if ((p->shape == SHAPE_CYLINDER || p->shape == SHAPE_TUBE) && !p->has_height)
            p->height_mm = 2 * p->clip_radius_mm; /* spans the clip ball */
        if (p->printed && p->material[0] && !p->printable) {
            snprintf(pth, sizeof pth, "parts[%d].print", i);
            return tippe_json_fail(c, pth,
                                   "material '%s' is not printable (the materials table says "
                                   "so): only a printed part has a print block",
                                   p->material);
        }
    }
    return TIPPE_OK;
}

typedef struct {
    const char *key;
    double value, extent; /* the field, and the part's size it makes */
    int axial;
} size_field;

/* No part is longer than the sphere's diameter in any direction, nor centred
 * beyond it: such a part cannot fit in the ball, and the top would rest on it
 * rather than on its sphere (the model's only contact). A clipped part is cut
 * to a ball no larger than the sphere, so only its fields are bounded. */
static int check_sizes(const tippe_json_reader *c, const tippe_design *d)
{
    const double D = 2 * d->radius_mm;
    char path[64], hint[160];
    for (int i = 0; i < d->n_parts; i++) {
        const part *p = &d->parts[i];
        size_field f[4];
        int n = 0;
        switch (p->shape) {
        case SHAPE_BALL:
        case SHAPE_SHELL:
            f[n++] = (size_field){"radius_mm", p->radius_mm, 2 * p->radius_mm, 0};
            break;
        case SHAPE_CYLINDER:
        case SHAPE_TUBE:
            f[n++] = (size_field){"radius_mm", p->radius_mm, 2 * p->radius_mm, 0};
            if (p->has_height)
                f[n++] = (size_field){"height_mm", p->height_mm, p->height_mm, 1};
            break;
        case SHAPE_TORUS:
        default:
            f[n++] = (size_field){"axial_semi_mm", p->axial_semi_mm, 2 * p->axial_semi_mm, 1};
            if (p->clip) {
                f[n++] = (size_field){"centre_radius_mm", p->centre_radius_mm,
                                        p->centre_radius_mm, 0};
                f[n++] = (size_field){"radial_semi_mm", p->radial_semi_mm, p->radial_semi_mm,
                                        0};
            } else {
                f[n++] = (size_field){"centre_radius_mm", p->centre_radius_mm,
                                        2 * (p->centre_radius_mm + p->radial_semi_mm), 0};
            }
            break;
        }
        for (int k = 0; k < n; k++) {
            if (!(f[k].extent > D + TOL_MM))
                continue;
            snprintf(path, sizeof path, "parts[%d].%s", i, f[k].key);
            unit_hint(f[k].value, LENGTH_HINT_MM, D * f[k].value / f[k].extent, hint,
                      sizeof hint);
            if (f[k].extent == f[k].value || !isfinite(f[k].extent))
                return tippe_json_fail(c, path,
                                       "%g mm is more than the sphere's diameter (%g mm): "
                                       "part '%s' cannot fit in the ball, and the top would "
                                       "rest on it rather than on its sphere%s",
                                       f[k].value, D, p->name, hint);
            return tippe_json_fail(c, path,
                                   "%g mm makes part '%s' %g mm %s, more than the sphere's "
                                   "diameter (%g mm): it cannot fit in the ball, and the top "
                                   "would rest on it rather than on its sphere%s",
                                   f[k].value, p->name, f[k].extent,
                                   f[k].axial ? "long" : "across", D, hint);
        }
        if (fabs(p->z_mm) > D) {
            snprintf(path, sizeof path, "parts[%d].z_mm", i);
            return tippe_json_fail(c, path,
                                   "%g mm puts part '%s' farther from %s than the sphere's "
                                   "diameter (%g mm)",
                                   p->z_mm, p->name, p->moving ? "Z2" : "the sphere's centre",
                                   D);
        }
    }
    return TIPPE_OK;
}

/* Moments: parts add, voids subtract (with the parent's density); the fixed
 * parts and the moving group at Z2 = 0. */
static int sum_moments(const tippe_json_reader *c, tippe_design *d)
{
    d->fixed = d->moving = (tippe_moments){0, 0, 0, 0};
    for (int i = 0; i < d->n_parts; i++) {
        part *p = &d->parts[i];
        tippe_moments unit = tippe_design_part_moments(p);
        int rc;
        if (p->printed && (rc = tippe_design_printed_moments(c, d, i, &unit)))
            return rc;
        tippe_moments m = tippe_moments_scale(unit, p->density_g_cm3 * 1e3);
        if (!finite_moments(m) || !(m.m > 0))
            return tippe_error_set(c->err, TIPPE_ECOMPUTE,
                                   "%s: parts[%d]: the geometry module gave no finite positive "
                                   "mass for part '%s'", c->file, i, p->name);
        p->mass_kg = p->is_void ? -m.m : m.m;
        tippe_moments *into = p->moving ? &d->moving : &d->fixed;
        *into = p->is_void ? tippe_moments_sub(*into, m) : tippe_moments_add(*into, m);
    }
    if (!(d->moving.m > 0) || !(d->fixed.m + d->moving.m > 0))
        return tippe_error_set(c->err, TIPPE_ECOMPUTE, "%s: total or moving mass is not "
                                                       "positive", c->file);
    return TIPPE_OK;
}

/* A parsed (and overridden) design file, checked step by step; check = 0
 * skips the layout checks (overlaps, travel), for tippe_design_derive. */
int tippe_design_build(tippe_json_reader *c, cJSON *root, const char *path, tippe_design *d,
                 int check)
{
    char mat_rel[512];
    int has_mat_file = 0, rc;
    d->sphere_only_mm[0] = -BIG_MM; /* no layout (a derived design): no limit known */
    d->sphere_only_mm[1] = BIG_MM;
    if ((rc = parse_header(c, root, path, d, mat_rel, sizeof mat_rel, &has_mat_file)) ||
        (rc = parse_parts(c, root, d)) ||
        (rc = resolve_materials(c, path, mat_rel, has_mat_file, d)) ||
        (rc = resolve_parts(c, d)) || (check && (rc = check_sizes(c, d))) ||
        (check && (rc = tippe_design_check_layout(c, d))) ||
        (tippe_design_derive_printed_radii(d), (rc = sum_moments(c, d))))
        return rc;
    if (!check) /* a derived design (a field moved by a tolerance) needs no tolerances */
        return TIPPE_OK;
    return tippe_tolerances_read(c, cJSON_GetObjectItemCaseSensitive(root, "tolerances"), d,
                                 &d->tolerances, &d->n_tolerances, &d->patch_radius_span);
}

/* Keeps the overrides a design was built with (src/design/design.c, below), so that
 * tippe_design_derive can rebuild it with more. */

/* A design read from a file (text NULL) or from a text in memory: with
 * materials_dir, a design from memory (path only names it in messages, and its
 * materials table is materials_dir's); without, the text of the file path, read
 * before (its tables found from path's folder). from: the design being derived
 * (or NULL), whose materials table and G-code are used where they are the same
 * files. The text is kept in the design, so that no design reads its file twice. */
static int load(const char *path, const char *text, size_t text_len, const char *materials_dir,
                const tippe_design *from, const tippe_design_gcode *gcodes, int n_gcodes,
                const char *const *overrides, int n_overrides, int check, tippe_design **out,
                tippe_error *err)
{
    /* The geometry module may call GSL: report, never abort. */
    tippe_gsl_errors_as_codes();
    *out = NULL;
    if (!path)
        return tippe_error_set(err, TIPPE_EINPUT, "no design file given");
    if (n_overrides < 0)
        n_overrides = 0;
    tippe_json_reader *c =
        tippe_json_reader_new(path, err, TIPPE_JSON_WORDS_FIELD, "set by --set ");
    tippe_design *d = calloc(1, sizeof *d);
    if (!c || !d) {
        free(c);
        tippe_design_free(d);
        return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    }
    cJSON *root = NULL;
    int rc = TIPPE_OK;
    if (!text) { /* the file, read once: its text stays in d */
        rc = tippe_json_read(c, MAX_FILE_MIB, "design", &d->text, &d->text_len);
    } else if (!(d->text = malloc(text_len + 1)) ||
               (materials_dir && !(d->materials_dir = tippe_design_dup_string(materials_dir)))) {
        rc = tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    } else {
        memcpy(d->text, text, text_len);
        d->text[text_len] = '\0';
        d->text_len = text_len;
    }
    if (!rc && text && n_gcodes > 0) {
        if (!(d->gcodes = calloc((size_t)n_gcodes, sizeof *d->gcodes)))
            rc = tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
        /* the bodies and their beads copied: the design and its reloads own theirs */
        for (int k = 0; !rc && k < n_gcodes; k++) {
            d->gcodes[k] = gcodes[k];
            d->gcodes[k].beads.bead = NULL;
            d->n_gcodes = k + 1;
            const size_t nb = gcodes[k].beads.n * sizeof *gcodes[k].beads.bead;
            if (nb && !(d->gcodes[k].beads.bead = malloc(nb)))
                rc = tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
            else if (nb)
                memcpy(d->gcodes[k].beads.bead, gcodes[k].beads.bead, nb);
        }
    }
    if (!rc)
        rc = tippe_json_parse_text(c, d->text, d->text_len, MAX_FILE_MIB, "design", &root);
    if (!rc)
        rc = tippe_json_check_duplicates(c, root, "");
    for (int i = 0; !rc && i < n_overrides; i++)
        rc = tippe_design_apply_override(c, root, overrides[i]);
    if (!rc) {
        if (from) {
            d->known_table = from->mat_table;
            d->known_table_file = from->mat_file;
            d->known_from = from;
        }
        rc = tippe_design_build(c, root, path, d, check);
        d->known_table = NULL;
        d->known_table_file = NULL;
        d->known_from = NULL;
    }
    return tippe_design_finish(c, root, d, overrides, n_overrides, rc, out, err);
}

/* The end of every load (a file, a text, a source's variant): the design
 * remembers its overrides, the parse is freed, and the design is handed out or,
 * on failure, freed. */
int tippe_design_finish(tippe_json_reader *c, cJSON *root, tippe_design *d,
                        const char *const *overrides, int n_overrides, int rc,
                        tippe_design **out, tippe_error *err)
{
    if (!rc)
        rc = tippe_design_remember_overrides(d, overrides, n_overrides, err);
    cJSON_Delete(root);
    free(c);
    if (rc) {
        tippe_design_free(d);
        return rc;
    }
    *out = d;
    return TIPPE_OK;
}

int tippe_design_load(const char *path, const char *const *overrides, int n_overrides,
                      tippe_design **out, tippe_error *err)
{
    return load(path, NULL, 0, NULL, NULL, NULL, 0, overrides, n_overrides, 1, out, err);
}

int tippe_design_load_read(const char *path, const char *text, size_t len,
                           const char *const *overrides, int n_overrides, tippe_design **out,
                           tippe_error *err)
{
    *out = NULL;
    /* a text over the cap: the file's own read refuses it, in its words */
    if (!text || len > ((size_t)MAX_FILE_MIB << 20))
        return tippe_design_load(path, overrides, n_overrides, out, err);
    return load(path, text, len, NULL, NULL, NULL, 0, overrides, n_overrides, 1, out, err);
}

int tippe_design_load_text(const char *name, const char *text, size_t len,
                           const char *materials_dir, const char *const *overrides,
                           int n_overrides, tippe_design **out, tippe_error *err)
{
    *out = NULL;
    if (!text || !materials_dir)
        return tippe_error_set(err, TIPPE_EINPUT, "%s: no design text given", name);
    return load(name, text, len, materials_dir, NULL, NULL, 0, overrides, n_overrides, 1, out,
                err);
}

int tippe_design_load_text_gcode(const char *name, const char *text, size_t len,
                                 const char *materials_dir, const tippe_design_gcode *gcodes,
                                 int n_gcodes, const char *const *overrides, int n_overrides,
                                 tippe_design **out, tippe_error *err)
{
    *out = NULL;
    if (!text || !materials_dir)
        return tippe_error_set(err, TIPPE_EINPUT, "%s: no design text given", name);
    return load(name, text, len, materials_dir, NULL, gcodes, n_gcodes, overrides, n_overrides,
                1, out, err);
}

/* d's file or text again, with d's overrides and then extra ones. */
static int reload(const tippe_design *d, const char *const *extra, int n_extra, int check,
                  tippe_design **out, tippe_error *err)
{
    *out = NULL;
    if (n_extra < 0)
        n_extra = 0;
    const char **all = malloc(((size_t)d->n_overrides + (size_t)n_extra + 1) * sizeof *all);
    if (!all)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    for (int i = 0; i < d->n_overrides; i++)
        all[i] = d->overrides[i];
    for (int i = 0; i < n_extra; i++)
        all[d->n_overrides + i] = extra[i];
    int rc = load(d->path, d->text, d->text_len, d->materials_dir, d, d->gcodes, d->n_gcodes, all,
                  d->n_overrides + n_extra, check, out, err);
    free(all);
    return rc;
}

int tippe_design_reload(const tippe_design *d, const char *const *extra, int n_extra,
                        tippe_design **out, tippe_error *err)
{
    return reload(d, extra, n_extra, 1, out, err);
}

int tippe_design_derive(const tippe_design *d, const char *const *extra, int n_extra,
                        tippe_design **out, tippe_error *err)
{
    return reload(d, extra, n_extra, 0, out, err);
}

/* Part i's length fields below LENGTH_HINT_MM or that look like metres, one at a time (*k counts them
 * across parts): the key, or NULL past the last. */
static int looks_like_metres(double v, double R);
static const char *small_length(const part *p, int which, double R, double *value)
{
    const struct {
        const char *key;
        double v;
        int on;
    } f[] = {
        {"radius_mm", p->radius_mm, p->shape != SHAPE_TORUS},
        {"inner_radius_mm", p->inner_radius_mm,
         (p->shape == SHAPE_CYLINDER || p->shape == SHAPE_TUBE) && p->inner_radius_mm > 0},
        {"thickness_mm", p->thickness_mm, p->shape == SHAPE_SHELL},
        {"height_mm", p->height_mm,
         (p->shape == SHAPE_CYLINDER || p->shape == SHAPE_TUBE) && p->has_height},
        {"centre_radius_mm", p->centre_radius_mm, p->shape == SHAPE_TORUS},
        {"radial_semi_mm", p->radial_semi_mm, p->shape == SHAPE_TORUS},
        {"axial_semi_mm", p->axial_semi_mm, p->shape == SHAPE_TORUS},
    };
    for (size_t j = 0; j < sizeof f / sizeof f[0]; j++)
        if (f[j].on && (f[j].v < LENGTH_HINT_MM || looks_like_metres(f[j].v, R)) &&
            which-- == 0) {
            *value = f[j].v;
            return f[j].key;
        }
    return NULL;
}

/* Whether a length of v mm in a sphere of radius R mm reads as metres typed for mm
 * (issue 25.5): under METRES_HINT_SHARE of the radius, and 1000 v a length that
 * fits the ball (1 mm .. its diameter). A 16 mm screw typed 0.016 in a 25 mm ball
 * is caught; a 0.2 mm hole is not (200 mm would not fit). */
static int looks_like_metres(double v, double R)
{
    return v > 0 && v < METRES_HINT_SHARE * R && v * 1e3 >= 1.0 && v * 1e3 <= 2 * R;
}

int tippe_design_warning(const tippe_design *d, int i, char *buf, size_t size)
{
    int k = 0;
    const double R = d->radius_mm;
    for (int j = 0; j < d->n_parts; j++) {
        const part *p = &d->parts[j];
        double v;
        const char *key;
        for (int w = 0; (key = small_length(p, w, R, &v)) != NULL; w++) {
            if (k++ != i)
                continue;
            char hint[160];
            if (v < LENGTH_HINT_MM) {
                unit_hint(v, LENGTH_HINT_MM, 2 * R, hint, sizeof hint);
                snprintf(buf, size,
                         "parts[%d].%s: %g mm (part '%s') is finer than anything printed or "
                         "machined (lengths in a design are in mm)%s",
                         j, key, v, p->name, hint);
            } else {
                snprintf(buf, size,
                         "parts[%d].%s: %g mm (part '%s') is under %g %% of the sphere's "
                         "radius (%g mm; lengths in a design are in mm); did you mean metres? "
                         "%g m is %g mm",
                         j, key, v, p->name, 100 * METRES_HINT_SHARE, R, v, v * 1e3);
            }
            return 1;
        }
    }
    /* a travel typed in metres: [0, 0.02] for 0 .. 20 mm */
    double t0 = d->travel_mm[0], t1 = d->travel_mm[1];
    if (!d->travel_physical && t1 > t0 && looks_like_metres(t1 - t0, R) &&
        fmax(fabs(t0), fabs(t1)) < METRES_HINT_SHARE * R && k++ == i) {
        snprintf(buf, size,
                 "travel_mm: %g .. %g mm is under %g %% of the sphere's radius (%g mm; "
                 "lengths in a design are in mm); did you mean metres? %g .. %g m is "
                 "%g .. %g mm",
                 t0, t1, 100 * METRES_HINT_SHARE, R, t0, t1, t0 * 1e3, t1 * 1e3);
        return 1;
    }
    /* a moving weight too light to move the centre of mass (issue 25.5) */
    double mm = d->moving.m, mt = d->fixed.m + d->moving.m;
    if (mt > 0 && mm < LIGHT_WEIGHT_SHARE * mt && k++ == i) {
        snprintf(buf, size,
                 "the moving weight is %.3g g, %.2g %% of the top's %.4g g (under %g %%): "
                 "over the whole travel it moves the centre of mass by %.3g mm, so its "
                 "zones hang on hundredths of a millimetre (a wrong material or density?)",
                 mm * 1e3, 100 * mm / mt, mt * 1e3, 100 * LIGHT_WEIGHT_SHARE,
                 mm / mt * (t1 - t0));
        return 1;
    }
    return 0;
}

int tippe_design_note(const tippe_design *d, int i, char *buf, size_t size)
{
    if (!d->mat_fallback)
        return 0;
    char cat[1024 + 32];
    if (i == 0)
        snprintf(buf, size,
                 "materials: no materials.json beside the design: its materials are those of "
                 "the shipped table %s",
                 d->mat_file);
    else if (i == 1 && tippe_design_shipped_catalogue(d, cat, sizeof cat))
        snprintf(buf, size,
                 "catalogue: no catalogue.json beside the design: the screws tippe build "
                 "tries are those of the shipped catalogue %s",
                 cat);
    else
        return 0;
    return 1;
}

int tippe_design_shipped_catalogue(const tippe_design *d, char *buf, size_t size)
{
    char beside[1024 + 32], dir[1024];
    if (!d->mat_fallback || !d->mat_file || d->catalogue ||
        tippe_design_beside(d, "catalogue.json", beside, sizeof beside) != TIPPE_OK ||
        access(beside, F_OK) == 0)
        return 0;
    tippe_path_dir(d->mat_file, dir, sizeof dir);
    const int n = snprintf(buf, size, "%s/catalogue.json", dir);
    return n > 0 && (size_t)n < size && access(buf, R_OK) == 0;
}

void tippe_design_protrusion_text(const tippe_design_protrusion *p, char *buf, size_t size)
{
    snprintf(buf, size,
             "part '%s' stands out of the sphere by %.3f mm near the %cz pole: the top rests "
             "on it, not on its sphere, for theta %.1f .. %.1f deg",
             p->part, p->protrusion_mm, p->pole > 0 ? '+' : '-', p->theta_from_rad * 180 / M_PI,
             p->theta_to_rad * 180 / M_PI);
}

void tippe_design_sphere_only_mm(const tippe_design *d, double *from_mm, double *to_mm)
{
    *from_mm = d->sphere_only_mm[0];
    *to_mm = d->sphere_only_mm[1];
}

int tippe_design_protrusion_at(const tippe_design *d, double z2_mm, tippe_design_protrusion *out)
{
    memset(out, 0, sizeof *out);
    const double *so = d->sphere_only_mm;
    if (!d->rs || !isfinite(z2_mm) ||
        (z2_mm >= so[0] - TRAVEL_SLACK_MM && z2_mm <= so[1] + TRAVEL_SLACK_MM))
        return 0;
    const double R = d->radius_mm;
    double worst = 0, worst_z = 0, a_lo = INFINITY, a_hi = -INFINITY;
    int worst_i = -1;
    ivset a;
    for (int i = 0; i < d->n_parts; i++) {
        const part *p = &d->parts[i];
        if (p->is_void)
            continue;
        for (int k = 0; k < d->nr; k++) {
            const double r = d->rs[k];
            tippe_design_material_ivs(d, i, r, p->moving ? z2_mm : 0, &a);
            for (int u = 0; u < 2 * a.n; u++) {
                /* p . n = r sin(alpha) + z cos(alpha) is linear in z: at each r an
                 * interval's end is the material farthest along any direction */
                const double z = u % 2 ? a.hi[u / 2] : a.lo[u / 2], rho = hypot(r, z);
                if (!(rho > R + TOL_MM))
                    continue;
                const double beta = atan2(r, z), w = acos(R / rho);
                a_lo = fmin(a_lo, fmax(0.0, beta - w));
                a_hi = fmax(a_hi, fmin(M_PI, beta + w));
                if (rho - R > worst) {
                    worst = rho - R;
                    worst_z = z;
                    worst_i = i;
                }
            }
        }
    }
    if (worst_i < 0)
        return 0;
    out->protrusion_mm = worst;
    snprintf(out->part, sizeof out->part, "%s", d->parts[worst_i].name);
    out->pole = worst_z >= 0 ? 1 : -1;
    /* theta = 0 rests on the centre of mass's side: the -z pole when it is below */
    tippe_top t;
    tippe_design_top_any(d, z2_mm, &t);
    out->theta_from_rad = t.com_side < 0 ? M_PI - a_hi : a_lo;
    out->theta_to_rad = t.com_side < 0 ? M_PI - a_lo : a_hi;
    return 1;
}

void tippe_design_free(tippe_design *d)
{
    if (!d)
        return;
    for (int i = 0; d->overrides && i < d->n_overrides; i++)
        free(d->overrides[i]);
    free(d->overrides);
    free(d->tolerances);
    free(d->rs);
    free(d->path);
    free(d->text);
    for (int k = 0; d->gcodes && k < d->n_gcodes; k++)
        tippe_gcode_beads_free(&d->gcodes[k].beads);
    free(d->gcodes);
    free(d->materials_dir);
    free(d->mat_file);
    cJSON_Delete(d->mat_table);
    free(d->catalogue);
    free(d->name);
    free(d->parts);
    free(d);
}

/* A built variant remembers its overrides (and its travel, when that was the
 * physical one) so that tippe_design_derive() rebuilds the same design. */
int tippe_design_remember_overrides(tippe_design *d, const char *const *overrides, int n,
                              tippe_error *err)
{
    if (!(d->overrides = calloc((size_t)n + 1, sizeof *d->overrides)))
        return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    char travel[128];
    snprintf(travel, sizeof travel, "travel_mm=[%.17g,%.17g]", d->travel_mm[0], d->travel_mm[1]);
    for (int i = 0; i <= n; i++) {
        if (i == n && !d->travel_physical)
            break;
        if (!(d->overrides[d->n_overrides++] = tippe_design_dup_string(i < n ? overrides[i] : travel)))
            return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    }
    return TIPPE_OK;
}
