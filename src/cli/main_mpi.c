/* tippe-mpi: the tippe command for mpirun. Its verbs are tippe's
 * (src/cli/verbs.c). Those marked mpi_all_ranks there, launch and map, share
 * their launches among all ranks (src/cli/launch_verb.c: rank 0 hands out chunks as
 * ranks finish and gathers the results, which equal the single-process
 * results); every other verb runs on rank 0 alone, so that it prints and writes
 * once. Ranks other than 0 print nothing: their stdout and stderr go to
 * /dev/null. All ranks exit with rank 0's status. The plain `tippe`, started by
 * mpirun with more than one rank, replaces itself by this program
 * (docs/launch.md). */
#include "cli.h"

#include <mpi.h>
#include <stdio.h>
#include <string.h>

#if defined(__SANITIZE_ADDRESS__)
/* The sanitizer build (-DTIPPE_SANITIZE=ON): Open MPI unloads its components
 * before LeakSanitizer reports what MPI_Init left, so that a leak's stack, cut
 * short at the first frame without a frame pointer, names no library; unwound
 * fully, it reaches the MPI_Init and MPI_Finalize frames that tests/lsan.supp
 * names. ASAN_OPTIONS from the environment still add to this. */
const char *__asan_default_options(void);
const char *__asan_default_options(void) { return "fast_unwind_on_malloc=0"; }
#endif

static void usage(FILE *out)
{
    fprintf(out, "usage: mpirun -np N tippe-mpi VERB [options]   (or mpirun -np N tippe VERB ...)\n"
                 "The tippe command with launch and map shared among MPI ranks.\n\n"
                 "verbs (* shared among the ranks; the others run on rank 0 alone):\n");
    for (int i = 0; i < tippe_cli_n_verbs; i++)
        fprintf(out, "  %-9s %c %s\n", tippe_cli_verbs[i].name,
                tippe_cli_verbs[i].mpi_all_ranks ? '*' : ' ', tippe_cli_verbs[i].summary);
}

int main(int argc, char **argv)
{
    MPI_Init(&argc, &argv);
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    int status = 2;
    const tippe_cli_verb *verb = argc >= 2 ? tippe_cli_find_verb(argv[1]) : NULL;
    if (verb && verb->mpi_all_ranks) {
        if (rank != 0) {
            /* Workers only compute; rank 0 reports (and alone writes files). */
            if (!freopen("/dev/null", "w", stdout) || !freopen("/dev/null", "w", stderr))
                MPI_Abort(MPI_COMM_WORLD, 1);
        }
        status = tippe_cli_run(verb, argc - 1, argv + 1);
    } else if (rank == 0) {
        if (verb) {
            status = tippe_cli_run(verb, argc - 1, argv + 1);
        } else if (argc >= 2 && tippe_cli_is_help(argv[1])) {
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
