/* tippe eval: the mass properties of a design with its weight at one Z2. */
#include "cli.h"

#include "tippe/design.h"
#include "tippe/profile.h"
#include "tippe/sweep.h"
#include "tippe/physics.h"

#include <cjson/cJSON.h>

#include <stdio.h>
#include <string.h>

static const char *const VERB = "eval";

static const char *side_text(int com_side)
{
    if (com_side > 0)
        return "above the centre (+z side down at theta = 0)";
    if (com_side < 0)
        return "below the centre (-z side down at theta = 0)";
    return "at the centre";
}

static void print_table(const tippe_design *d, double z2_mm, const tippe_top *t,
                        const tippe_cli_sets *sets)
{
    double from, to, cfrom, cto;
    tippe_design_travel_mm(d, &from, &to);
    tippe_design_contact_travel_mm(d, &cfrom, &cto);
    const double g_mm2 = 1e9; /* kg m^2 -> g mm^2 */
    printf("design   %s (%s)\n", tippe_design_name(d), tippe_design_path(d));
    char text[1024];
    if (sets->n)
        printf("changes  %s\n", tippe_cli_sets_text(sets, text, sizeof text));
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
    tippe_theory_class cls;
    if (tippe_theory_classify(t->A / t->C, t->eps / t->R, &cls) == TIPPE_OK)
        printf("group    %s, subgroup %s of Theorem 5.1%s%s (tippe classify tells more)\n",
               tippe_group_family(cls.group), tippe_group_name(cls.group),
               cls.boundary ? ", on the boundary " : "", cls.boundary ? cls.boundary : "");
    tippe_design_protrusion pr;
    tippe_design_protrusion_at(d, z2_mm, &pr);
    tippe_cli_print_model_validity(&pr, z2_mm, "contact  ", "the group above is");
    tippe_design_cap caps[2];
    if (tippe_design_polar_caps(d, z2_mm, caps))
        for (int k = 0; k < 2; k++)
            if (caps[k].half_angle_rad > 0)
                printf("pole     %s: the opening of '%s' (%.2f mm): tilted less than %.1f deg on "
                       "this pole the top stands on its rim, not on its sphere (%s)\n",
                       caps[k].pole > 0 ? "+z" : "-z", caps[k].part, 2 * caps[k].radius_mm,
                       caps[k].half_angle_rad * 180 / M_PI,
                       caps[k].pole == (t->com_side ? t->com_side : 1)
                           ? "the pole it stands on at theta = 0: upright and a hand launch's "
                             "small tilt are there, and the model does not apply"
                           : "the pole it stands on when inverted");
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
        tippe_design_print_info pi;
        if (!tippe_design_part_print(d, i, &pi) && pi.printed)
            printf("  (printed: walls, skins and infill, below)");
        printf("\n");
    }
    printf("\n");
    tippe_profile_print_printed_parts(stdout, d);
}

int tippe_cli_eval(int argc, char **argv)
{
    double z2_mm = 0.0;
    int json = 0;
    tippe_cli_sets sets = {.n = 0};
    tippe_cli_opt opts[] = {
        {.name = "z2", .kind = TIPPE_CLI_DOUBLE, .value = &z2_mm, .arg = "MM", .unit = "mm",
         .min = -TIPPE_CLI_Z2_MAX_MM, .max = TIPPE_CLI_Z2_MAX_MM, .required = 1,
         .help = "position of the moving weight's midpoint above the sphere's centre\n"
                 "(within the design's travel)"},
        {.name = "json", .kind = TIPPE_CLI_FLAG, .value = &json,
         .help = "print one JSON object (SI units) instead of the table"},
        {.name = "set", .kind = TIPPE_CLI_SET, .value = &sets, .arg = "FIELD=VALUE",
         .help = "change a field of the design before it is checked (repeatable), e.g.\n"
                 "--set parts.rod.material=nylon  --set radius_mm=30\n"
                 "--set parts.weight.height_mm=5  (VALUE null removes a field)"},
        {NULL},
    };
    tippe_cli_spec spec = {
        .verb = VERB,
        .synopsis = "DESIGN.json --z2 MM [--json] [--set FIELD=VALUE ...]",
        .about = "Mass, centre of mass and moments of inertia of a design with the midpoint of\n"
                 "its moving weight at height Z2 above the sphere's centre, and the group of\n"
                 "Theorem 5.1 that its A/C and eps/R fall in.",
        .after = "The table gives g, mm and g mm^2; A is about a transverse axis through the\n"
                 "centre of mass, C about the symmetry axis; eps is the distance from the\n"
                 "sphere's centre to the centre of mass. Exit status: 0 ok, 2 bad usage or\n"
                 "design, 1 computation failed. The design format: docs/design-format.md.",
        .opts = opts,
        .min_args = 1,
        .max_args = 1,
        .args_name = "design file",
    };
    const char *path = NULL;
    int n_args = 0;
    int rc = tippe_cli_parse(&spec, argc, argv, &path, &n_args);
    if (rc)
        return rc == TIPPE_CLI_HELP ? 0 : rc;

    tippe_error err = {0};
    tippe_design *d = NULL;
    rc = tippe_design_load(path, sets.item, sets.n, &d, &err);
    if (!rc)
        tippe_cli_design_warnings(VERB, d);
    tippe_top top;
    if (!rc)
        rc = tippe_design_top(d, z2_mm, &top, &err);
    if (rc) {
        tippe_design_free(d);
        return tippe_cli_fail(VERB, &err, rc);
    }
    if (json) {
        cJSON *o = tippe_sweep_eval_json(d, z2_mm, &top);
        if (o)
            tippe_cli_json_sets(o, &sets);
        rc = tippe_cli_print_json(VERB, o);
    } else {
        print_table(d, z2_mm, &top, &sets);
    }
    tippe_design_free(d);
    return rc;
}
