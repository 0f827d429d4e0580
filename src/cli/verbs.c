/* The verbs of the tippe command, one table for both front ends: src/cli/main.c
 * (tippe) and src/cli/main_mpi.c (tippe-mpi). A new verb is one line here and
 * its prototype in cli.h.
 *
 * tippe-mpi runs every verb, but distributes only those with mpi_all_ranks set
 * (launch and map, which share their launches among the ranks in
 * src/cli/launch_verb.c); every other verb runs on rank 0 alone, so that it prints
 * and writes its files once. */
#include "cli.h"

#include <string.h>

const tippe_cli_verb tippe_cli_verbs[] = {
    {"eval", tippe_cli_eval, "mass, centre of mass and moments of a design at one Z2", 0},
    {"classify", tippe_cli_classify, "group of Theorem 5.1 and spin thresholds for A/C, eps/R",
     0},
    {"simulate", tippe_cli_simulate, "integrate one launch of a scenario: tip, no tip or hang",
     0},
    {"sweep", tippe_cli_sweep, "zones of a design along the travel of its weight, plots", 0},
    {"optimise", tippe_cli_optimise, "search a design space for the widest narrowest zone", 0},
    {"compare", tippe_cli_compare, "zone tables of several designs side by side", 0},
    {"launch", tippe_cli_launch, "many hand launches at one Z2: outcome counts against theory",
     1},
    {"map", tippe_cli_map, "outcome of hand launches over a grid of Z2 and spin, heat map", 1},
    {"check", tippe_cli_check, "one central hand launch at one Z2 beside the calculator's zone",
     0},
    {"materials", tippe_cli_materials, "the materials table: densities, sources, where it is read",
     0},
    {"animate", tippe_cli_animate, "a film (MP4, WebM, GIF) or a picture of one launch", 0},
    {"export", tippe_cli_export, "printed bodies as STL and 3MF, OpenSCAD source, section drawing",
     0},
    {"build", tippe_cli_build, "build sheet: settings to measure, spins, bill of materials, files",
     0},
    {"slice", tippe_cli_slice, "slice the printed body with PrusaSlicer and read its G-code back",
     0},
    {"serve", tippe_cli_serve, "the calculator as a local web page, live as you edit a design",
     0},
};
const int tippe_cli_n_verbs = (int)(sizeof tippe_cli_verbs / sizeof tippe_cli_verbs[0]);

const tippe_cli_verb *tippe_cli_find_verb(const char *name)
{
    for (int i = 0; i < tippe_cli_n_verbs; i++)
        if (!strcmp(name, tippe_cli_verbs[i].name))
            return &tippe_cli_verbs[i];
    return NULL;
}
