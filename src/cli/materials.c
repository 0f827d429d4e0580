/* tippe materials: the materials table (name, density, source) and where it is
 * read from. */
#include "cli.h"

#include "tippe/design.h"

#include <cjson/cJSON.h>

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

static const char *const VERB = "materials";

enum { WIDTH = 100, SOURCE_COLUMN = 52 };

/* Prints text from the current column (SOURCE_COLUMN) to WIDTH, continuing on
 * indented lines, broken at spaces. */
static void print_wrapped(const char *text)
{
    const int room = WIDTH - SOURCE_COLUMN;
    while (*text) {
        int n = (int)strlen(text);
        if (n > room) {
            n = room;
            while (n > 0 && text[n] != ' ')
                n--;
            if (n == 0)
                n = room;
        }
        printf("%.*s\n", n, text);
        text += n;
        while (*text == ' ')
            text++;
        if (*text)
            printf("%*s", SOURCE_COLUMN, "");
    }
}

static void print_table(const tippe_materials *t, const char *file, const char *why)
{
    printf("materials table %s\n(%s)\n\n", file, why);
    printf("%-18s %7s  %-4s %-4s %6s %5s  %s\n", "name", "g/cm^3", "prt", "scr", "E GPa", "nu",
           "source");
    for (int i = 0; i < tippe_materials_count(t); i++) {
        tippe_material m;
        tippe_materials_get(t, i, &m);
        char E[16] = "-", nu[16] = "-";
        if (isfinite(m.E_GPa))
            snprintf(E, sizeof E, "%.3g", m.E_GPa);
        if (isfinite(m.nu))
            snprintf(nu, sizeof nu, "%.2f", m.nu);
        printf("%-18s %7.3f  %-4s %-4s %6s %5s  ", m.name, m.density_g_cm3,
               m.printable ? "yes" : "no", m.set_screws ? "yes" : "no", E, nu);
        print_wrapped(m.source);
    }
    printf("\nprt: printable (a part of it may carry a \"print\" block); scr: set screws are "
           "sold in it\n(what tippe build proposes for a screw in a thread); E, nu: the elastic "
           "constants of the\nHertz patch (--friction patch), with their source in the JSON "
           "(--json). A design reads the\ntable its \"materials\" field names, relative to the "
           "design file (default materials.json\nnext to it, else the shipped table).\n");
}

/* The table to show: FILE (a table or a design), else the repository's. Fills
 * file and why; 0, or 2 after a message that says how to fix it. */
static int find_table(const char *arg, char *file, size_t size, const char **why)
{
    tippe_error err;
    if (arg) {
        /* a design names its table; anything else is taken as a table */
        if (tippe_design_materials_file(arg, file, size, &err) == TIPPE_OK) {
            *why = "the table this design reads";
            char beside[1024];
            tippe_path_beside(arg, "materials.json", beside, sizeof beside);
            if (strcmp(file, beside) && access(beside, F_OK) != 0 &&
                strstr(file, "/materials.json"))
                *why = "the shipped table this design reads: there is no materials.json beside it";
            if (access(file, F_OK) == 0)
                return 0;
            fprintf(stderr,
                    "tippe materials: %s reads its materials from %s (its \"materials\" field, "
                    "default materials.json next to it), which does not exist: copy "
                    "designs/materials.json there or name another table in the design "
                    "(docs/design-format.md)\n",
                    arg, file);
            return 2;
        }
        snprintf(file, size, "%s", arg);
        *why = "as given";
        return 0;
    }
    if (access("designs/materials.json", F_OK) == 0) {
        snprintf(file, size, "designs/materials.json");
        *why = "the shipped table, found as designs/materials.json here";
        return 0;
    }
    char dir[900];
    if (tippe_file_shipped_dir(dir, sizeof dir) && size > sizeof dir + 16) {
        snprintf(file, size, "%.900s/materials.json", dir);
        *why = "the shipped table (installed, or of the checkout tippe was built from)";
        return 0;
    }
    fprintf(stderr,
            "tippe materials: no materials table found: looked for designs/materials.json here "
            "and in %s.\nName a table or a design: tippe materials FILE.json (the format: "
            "docs/design-format.md).\n",
            dir);
    return 2;
}

int tippe_cli_materials(int argc, char **argv)
{
    int json = 0;
    tippe_cli_opt opts[] = {
        {.name = "json", .kind = TIPPE_CLI_FLAG, .value = &json,
         .help = "print one JSON object instead of the table"},
        {NULL},
    };
    tippe_cli_spec spec = {
        .verb = VERB,
        .synopsis = "[TABLE.json | DESIGN.json] [--json]",
        .about = "Lists a materials table: each material's name, density (g/cm^3), whether it\n"
                 "can be printed, and where its density comes from; and says which file that\n"
                 "is. Given a design, the table the design reads; given nothing, the shipped\n"
                 "table (designs/materials.json here, else the installed one).",
        .after = "Exit status: 0 ok, 2 no table or a bad one (the message says which file\n"
                 "and field). The format: docs/design-format.md.",
        .opts = opts,
        .max_args = 1,
        .args_name = "file",
    };
    const char *arg = NULL;
    int n_args = 0, rc = tippe_cli_parse(&spec, argc, argv, &arg, &n_args);
    if (rc)
        return rc == TIPPE_CLI_HELP ? 0 : rc;
    char file[1024];
    const char *why = NULL;
    if ((rc = find_table(n_args ? arg : NULL, file, sizeof file, &why)) != 0)
        return rc;
    tippe_materials *t = NULL;
    tippe_error err;
    if ((rc = tippe_materials_load(file, &t, &err)) != 0) {
        fprintf(stderr, "tippe materials: %s\n", err.msg);
        if (access(file, F_OK) != 0)
            fprintf(stderr, "tippe materials: %s does not exist: name an existing table, or "
                            "copy designs/materials.json there (docs/design-format.md)\n",
                    file);
        return rc == TIPPE_EINPUT ? 2 : 1;
    }
    if (json)
        rc = tippe_cli_print_json(VERB, tippe_materials_json(t, file));
    else
        print_table(t, file, why);
    tippe_materials_free(t);
    return rc;
}
