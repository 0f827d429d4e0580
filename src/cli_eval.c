/* tippe eval: the mass properties of a design with its weight at one Z2. */
#include "cli.h"

#include "tippe/design.h"

#include <cjson/cJSON.h>

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_SETS 64

static void eval_usage(FILE *out)
{
    fprintf(out,
            "usage: tippe eval DESIGN.json --z2 MM [--json] [--set FIELD=VALUE ...]\n"
            "\n"
            "Mass, centre of mass and moments of inertia of a design with the midpoint of its\n"
            "moving weight at height Z2 above the sphere's centre.\n"
            "\n"
            "  --z2 MM            position of the moving weight, mm (within the design's travel)\n"
            "  --json             print one JSON object (SI units) instead of the table\n"
            "  --set FIELD=VALUE  change a field of the design before it is checked, e.g.\n"
            "                     --set parts.rod.material=nylon  --set radius_mm=30\n"
            "                     --set parts.weight.height_mm=5  (VALUE null removes a field)\n"
            "  --help             this text\n"
            "\n"
            "The table gives g, mm and g mm^2; A is about a transverse axis through the centre\n"
            "of mass, C about the symmetry axis; eps is the distance from the sphere's centre to\n"
            "the centre of mass. Exit status: 0 ok, 2 bad usage or design, 1 computation failed.\n"
            "The design format is described in docs/design-format.md.\n");
}

__attribute__((format(printf, 1, 2)))
static int usage_error(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "tippe eval: ");
    vfprintf(stderr, fmt, ap);
    fprintf(stderr, " (try tippe eval --help)\n");
    va_end(ap);
    return 2;
}

static const char *side_text(int com_side)
{
    if (com_side > 0)
        return "above the centre (+z side down at theta = 0)";
    if (com_side < 0)
        return "below the centre (-z side down at theta = 0)";
    return "at the centre";
}

static void print_table(const tippe_design *d, double z2_mm, const tippe_top *t)
{
    double from, to, cfrom, cto;
    tippe_design_travel_mm(d, &from, &to);
    tippe_design_contact_travel_mm(d, &cfrom, &cto);
    const double g_mm2 = 1e9; /* kg m^2 -> g mm^2 */
    printf("design   %s (%s)\n", tippe_design_name(d), tippe_design_path(d));
    printf("Z2       %10.3f mm     travel %.3f .. %.3f mm, physical %.3f .. %.3f mm\n", z2_mm,
           from, to, cfrom, cto);
    printf("R        %10.3f mm\n", t->R * 1e3);
    printf("m        %10.3f g      (moving weight %.3f g)\n", t->m * 1e3,
           tippe_design_moving_mass_kg(d) * 1e3);
    printf("eps      %10.4f mm     centre of mass %s\n", t->eps * 1e3, side_text(t->com_side));
    printf("eps/R    %10.6f\n", t->eps / t->R);
    printf("A        %10.2f g mm^2 (transverse, through the centre of mass)\n", t->A * g_mm2);
    printf("C        %10.2f g mm^2 (axial)\n", t->C * g_mm2);
    printf("A/C      %10.6f        (A/C - 1 = %+.6f)\n", t->A / t->C, t->A / t->C - 1);
    printf("\n%-12s %-9s %-7s %-12s %9s %12s\n", "part", "shape", "role", "material",
           "g/cm^3", "mass g");
    int n = tippe_design_n_parts(d);
    for (int i = 0; i < n; i++) {
        tippe_design_part_info p;
        if (tippe_design_part(d, i, &p))
            continue;
        printf("%-12s %-9s %-7s %-12s %9.3f %12.3f", p.name, p.shape, p.role, p.material,
               p.density_g_cm3, p.mass_kg * 1e3);
        if (p.cut_from)
            printf("  (cut from %s)", p.cut_from);
        if (p.may_protrude)
            printf("  (may protrude)");
        printf("\n");
    }
}

static int print_json(const tippe_design *d, double z2_mm, const tippe_top *t)
{
    double from, to, cfrom, cto;
    tippe_design_travel_mm(d, &from, &to);
    tippe_design_contact_travel_mm(d, &cfrom, &cto);
    cJSON *o = cJSON_CreateObject();
    if (!o)
        return 1;
    int ok = cJSON_AddStringToObject(o, "design", tippe_design_name(d)) &&
             cJSON_AddStringToObject(o, "file", tippe_design_path(d)) &&
             cJSON_AddNumberToObject(o, "z2_mm", z2_mm) &&
             cJSON_AddNumberToObject(o, "mass_kg", t->m) &&
             cJSON_AddNumberToObject(o, "moving_mass_kg", tippe_design_moving_mass_kg(d)) &&
             cJSON_AddNumberToObject(o, "R_m", t->R) &&
             cJSON_AddNumberToObject(o, "eps_m", t->eps) &&
             cJSON_AddNumberToObject(o, "eps_over_R", t->eps / t->R) &&
             cJSON_AddNumberToObject(o, "A_kg_m2", t->A) &&
             cJSON_AddNumberToObject(o, "C_kg_m2", t->C) &&
             cJSON_AddNumberToObject(o, "A_over_C", t->A / t->C) &&
             cJSON_AddNumberToObject(o, "com_side", t->com_side);
    double tr[2] = {from, to}, ct[2] = {cfrom, cto};
    cJSON *a1 = cJSON_CreateDoubleArray(tr, 2);
    if (a1 && !cJSON_AddItemToObject(o, "travel_mm", a1)) {
        cJSON_Delete(a1);
        a1 = NULL;
    }
    cJSON *a2 = cJSON_CreateDoubleArray(ct, 2);
    if (a2 && !cJSON_AddItemToObject(o, "contact_travel_mm", a2)) {
        cJSON_Delete(a2);
        a2 = NULL;
    }
    if (!ok || !a1 || !a2) {
        cJSON_Delete(o);
        return 1;
    }
    cJSON *parts = cJSON_AddArrayToObject(o, "parts");
    int n = tippe_design_n_parts(d);
    for (int i = 0; parts && i < n; i++) {
        tippe_design_part_info p;
        cJSON *po = cJSON_CreateObject();
        if (!po || tippe_design_part(d, i, &p) || !cJSON_AddItemToArray(parts, po)) {
            cJSON_Delete(po);
            ok = 0;
            break;
        }
        ok = cJSON_AddStringToObject(po, "name", p.name) &&
             cJSON_AddStringToObject(po, "shape", p.shape) &&
             cJSON_AddStringToObject(po, "role", p.role) &&
             cJSON_AddStringToObject(po, "material", p.material) &&
             cJSON_AddNumberToObject(po, "density_g_cm3", p.density_g_cm3) &&
             cJSON_AddNumberToObject(po, "mass_kg", p.mass_kg);
        if (!ok)
            break;
    }
    char *s = (ok && parts) ? cJSON_Print(o) : NULL;
    cJSON_Delete(o);
    if (!s)
        return 1;
    printf("%s\n", s);
    free(s);
    return 0;
}

int tippe_cli_eval(int argc, char **argv)
{
    const char *path = NULL, *z2_text = NULL;
    const char *sets[MAX_SETS];
    int n_sets = 0, json = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            eval_usage(stdout);
            return 0;
        } else if (!strcmp(a, "--json")) {
            json = 1;
        } else if (!strcmp(a, "--z2") || !strcmp(a, "--set")) {
            if (i + 1 >= argc)
                return usage_error("%s needs a value", a);
            if (!strcmp(a, "--z2")) {
                z2_text = argv[++i];
            } else {
                if (n_sets == MAX_SETS)
                    return usage_error("too many --set options (at most %d)", MAX_SETS);
                sets[n_sets++] = argv[++i];
            }
        } else if (!strncmp(a, "--z2=", 5)) {
            z2_text = a + 5;
        } else if (!strncmp(a, "--set=", 6)) {
            if (n_sets == MAX_SETS)
                return usage_error("too many --set options (at most %d)", MAX_SETS);
            sets[n_sets++] = a + 6;
        } else if (a[0] == '-' && a[1] != '\0') {
            return usage_error("unknown option '%s'", a);
        } else if (!path) {
            path = a;
        } else {
            return usage_error("one design file only (got also '%s')", a);
        }
    }
    if (!path)
        return usage_error("no design file given");
    if (!z2_text)
        return usage_error("--z2 MM is required (position of the moving weight)");
    char *end = NULL;
    double z2_mm = strtod(z2_text, &end);
    if (end == z2_text || *end != '\0' || !isfinite(z2_mm))
        return usage_error("--z2: '%s' is not a number of mm", z2_text);

    tippe_error err = {0};
    tippe_design *d = NULL;
    int rc = tippe_design_load(path, sets, n_sets, &d, &err);
    tippe_top top;
    if (!rc)
        rc = tippe_design_top(d, z2_mm, &top, &err);
    if (rc) {
        fprintf(stderr, "tippe eval: %s\n", err.msg);
        tippe_design_free(d);
        return rc == TIPPE_EINPUT ? 2 : 1;
    }
    if (json)
        rc = print_json(d, z2_mm, &top);
    else
        print_table(d, z2_mm, &top);
    if (rc)
        fprintf(stderr, "tippe eval: out of memory while writing JSON\n");
    tippe_design_free(d);
    return rc ? 1 : 0;
}
