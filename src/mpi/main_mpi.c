/* tippe-mpi: the tippe command for mpirun. `launch` and `map` share their
 * launches among all ranks (src/cli_launch.c: rank 0 hands out chunks as ranks
 * finish and gathers the results, which equal the single-process results);
 * every other verb runs on rank 0 alone, so that it prints and writes once.
 * Ranks other than 0 print nothing: their stdout and stderr go to /dev/null.
 * All ranks exit with rank 0's status. The plain `tippe`, started by mpirun
 * with more than one rank, replaces itself by this program (docs/launch.md). */
#include "../cli.h"

#include <mpi.h>
#include <stdio.h>
#include <string.h>

static const struct {
    tippe_cli_verb verb;
    int all_ranks; /* 1: every rank takes part */
} verbs[] = {
    {{"launch", tippe_cli_launch, "many hand launches at one Z2, shared among the ranks"}, 1},
    {{"map", tippe_cli_map, "hand launches over a grid of Z2 and spin, shared among the ranks"}, 1},
    {{"check", tippe_cli_check, "one central hand launch (rank 0 only)"}, 0},
    {{"eval", tippe_cli_eval, "mass and moments of a design (rank 0 only)"}, 0},
    {{"classify", tippe_cli_classify, "group of Theorem 5.1 (rank 0 only)"}, 0},
    {{"simulate", tippe_cli_simulate, "one launch of a scenario (rank 0 only)"}, 0},
    {{"sweep", tippe_cli_sweep, "zones along the travel (rank 0 only)"}, 0},
    {{"compare", tippe_cli_compare, "zone tables side by side (rank 0 only)"}, 0},
};
static const int n_verbs = (int)(sizeof verbs / sizeof verbs[0]);

static void usage(FILE *out)
{
    fprintf(out, "usage: mpirun -np N tippe-mpi VERB [options]   (or mpirun -np N tippe VERB ...)\n"
                 "The tippe command with launch and map shared among MPI ranks.\n\nverbs:\n");
    for (int i = 0; i < n_verbs; i++)
        fprintf(out, "  %-9s %s\n", verbs[i].verb.name, verbs[i].verb.summary);
}

int main(int argc, char **argv)
{
    MPI_Init(&argc, &argv);
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    int status = 2, found = -1;
    if (argc >= 2)
        for (int i = 0; i < n_verbs; i++)
            if (!strcmp(argv[1], verbs[i].verb.name))
                found = i;
    if (found >= 0 && verbs[found].all_ranks) {
        if (rank != 0) {
            /* Workers only compute; rank 0 reports (and alone writes files). */
            if (!freopen("/dev/null", "w", stdout) || !freopen("/dev/null", "w", stderr))
                MPI_Abort(MPI_COMM_WORLD, 1);
        }
        status = verbs[found].verb.run(argc - 1, argv + 1);
    } else if (rank == 0) {
        if (found >= 0) {
            status = verbs[found].verb.run(argc - 1, argv + 1);
        } else if (argc >= 2 && (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h"))) {
            usage(stdout);
            status = 0;
        } else {
            if (argc >= 2)
                fprintf(stderr, "tippe-mpi: unknown verb '%s'\n", argv[1]);
            usage(stderr);
            status = 2;
        }
    }
    fflush(stdout);
    fflush(stderr);
    MPI_Bcast(&status, 1, MPI_INT, 0, MPI_COMM_WORLD);
    MPI_Finalize();
    return status;
}
