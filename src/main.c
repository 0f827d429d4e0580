/* The tippe command: dispatches to one verb; the verbs live in src/cli_*.c. */
#include "cli.h"

#include <stdio.h>
#include <string.h>

static const tippe_cli_verb verbs[] = {
    {"eval", tippe_cli_eval, "mass, centre of mass and moments of a design at one Z2"},
    {"classify", tippe_cli_classify, "group of Theorem 5.1 and spin thresholds for A/C, eps/R"},
    {"simulate", tippe_cli_simulate, "integrate one launch of a scenario: tip, no tip or hang"},
    {"sweep", tippe_cli_sweep, "zones of a design along the travel of its weight, plots"},
    {"compare", tippe_cli_compare, "zone tables of several designs side by side"},
    {"launch", tippe_cli_launch, "many hand launches at one Z2: outcome counts against theory"},
    {"map", tippe_cli_map, "outcome of hand launches over a grid of Z2 and spin, heat map"},
    {"check", tippe_cli_check, "one central hand launch at one Z2 beside the calculator's zone"},
};
static const int n_verbs = (int)(sizeof verbs / sizeof verbs[0]);

static void usage(FILE *out)
{
    fprintf(out,
            "usage: tippe VERB [options]   (tippe VERB --help for each verb)\n"
            "Design and check spherical tippe tops (Ciocci et al. 2012).\n\nverbs:\n");
    for (int i = 0; i < n_verbs; i++)
        fprintf(out, "  %-9s %s\n", verbs[i].name, verbs[i].summary);
    fprintf(out, "\n  --help     this text\n  --version  print the version\n");
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        usage(stderr);
        return 2;
    }
    if (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
        usage(stdout);
        return 0;
    }
    if (!strcmp(argv[1], "--version")) {
        printf("tippe %s\n", TIPPE_VERSION);
        return 0;
    }
    int mpi = tippe_cli_mpi_reexec(argc, argv); /* under mpirun -np N > 1: execs tippe-mpi */
    if (mpi)
        return mpi;
    for (int i = 0; i < n_verbs; i++)
        if (!strcmp(argv[1], verbs[i].name))
            return verbs[i].run(argc - 1, argv + 1);
    fprintf(stderr, "tippe: unknown verb '%s' (try tippe --help)\n", argv[1]);
    return 2;
}
