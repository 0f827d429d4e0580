/* The tippe command: dispatches to one verb; the verbs live in src/cli/<verb>.c and
 * their table in src/cli/verbs.c. */
#include "cli.h"

#include <stdio.h>
#include <string.h>

static void usage(FILE *out)
{
    fprintf(out,
            "usage: tippe VERB [options]   (tippe VERB --help for each verb)\n"
            "Design and check spherical tippe tops (Ciocci et al. 2012).\n\nverbs:\n");
    for (int i = 0; i < tippe_cli_n_verbs; i++)
        fprintf(out, "  %-9s %s\n", tippe_cli_verbs[i].name, tippe_cli_verbs[i].summary);
    fprintf(out, "\n  --help     this text\n  --version  print the version\n");
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        usage(stderr);
        return 2;
    }
    if (tippe_cli_is_help(argv[1])) {
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
    const tippe_cli_verb *v = tippe_cli_find_verb(argv[1]);
    if (v)
        return tippe_cli_run(v, argc - 1, argv + 1);
    fprintf(stderr, "tippe: unknown verb '%s' (try tippe --help)\n", argv[1]);
    return 2;
}
