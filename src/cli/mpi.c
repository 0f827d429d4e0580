/* The ranks of tippe-mpi for the hand-launch verbs (see hands.h), and the
 * re-exec of tippe into tippe-mpi under mpirun.
 *
 * This file is compiled twice: into `tippe` (one rank), and with
 * TIPPE_WITH_MPI into `tippe-mpi` (src/cli/main_mpi.c), where launch and map
 * share their launches among the ranks: rank 0 hands out chunks of launch
 * indices to the other ranks as they return results, computes chunks itself
 * in between, and alone writes output. Every launch depends only on (seed,
 * draw, top, options), so the result is the single-process result whatever
 * the number of ranks. */
#include "hands.h"

#include <errno.h>
#include <limits.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#ifdef TIPPE_WITH_MPI
#include <mpi.h>
#endif

int hands_mpi_rank(void)
{
#ifdef TIPPE_WITH_MPI
    int r = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &r);
    return r;
#else
    return 0;
#endif
}

int hands_mpi_size(void)
{
#ifdef TIPPE_WITH_MPI
    int s = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &s);
    return s;
#else
    return 1;
#endif
}

/* All ranks go on only if every rank got this far (they parse the same
 * arguments, but a rank must never wait for work that will not come). */
int hands_mpi_agree(int status)
{
#ifdef TIPPE_WITH_MPI
    int worst = status;
    MPI_Allreduce(&status, &worst, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    return worst;
#else
    return status;
#endif
}

int tippe_cli_mpi_reexec(int argc, char **argv)
{
#ifndef TIPPE_WITH_MPI
    const char *size = getenv("OMPI_COMM_WORLD_SIZE");
    if (!size || atoi(size) <= 1)
        return 0;
    const char *rank = getenv("OMPI_COMM_WORLD_RANK");
    const int quiet = rank && atoi(rank) != 0; /* one message, not one per rank */
    char exe[PATH_MAX];
    ssize_t len = readlink("/proc/self/exe", exe, sizeof exe - 16);
    if (len <= 0) {
        if (!quiet)
            fprintf(stderr, "tippe: running under mpirun with %s ranks, but cannot find my own "
                            "directory (/proc/self/exe) to run tippe-mpi from\n", size);
        return 2;
    }
    exe[len] = '\0';
    char self[PATH_MAX];
    memcpy(self, exe, (size_t)len + 1);
    tippe_path_beside(self, "tippe-mpi", exe, sizeof exe);
    if (access(exe, X_OK) != 0) {
        if (!quiet)
            fprintf(stderr,
                    "tippe: running under mpirun with %s ranks, but %s was not built (configure "
                    "with Open MPI installed, e.g. apt-get install libopenmpi-dev, to get it); "
                    "run tippe without mpirun instead\n", size, exe);
        return 2;
    }
    char **args = malloc((size_t)(argc + 1) * sizeof *args);
    if (!args)
        return 1;
    args[0] = exe;
    for (int i = 1; i < argc; i++)
        args[i] = argv[i];
    args[argc] = NULL;
    execv(exe, args);
    if (!quiet)
        fprintf(stderr, "tippe: cannot run %s: %s\n", exe, strerror(errno));
    free(args);
    return 2;
#else
    (void)argc;
    (void)argv;
    return 0;
#endif
}

#ifdef TIPPE_WITH_MPI
enum { TAG_WORK = 7101, TAG_RESULT = 7102 };

/* Launches per chunk: a quarter of an even share of what is left (guided
 * scheduling: big chunks first, small ones at the end for balance), at least
 * one per OpenMP thread. */
static long chunk_size(long remaining, int ranks)
{
    long c = remaining / (4L * ranks);
    long t = omp_get_max_threads();
    if (c < t)
        c = t;
    return c < remaining ? c : remaining;
}

/* Rank 0: keeps every worker two chunks ahead (so that a worker never waits
 * while rank 0 computes a chunk of its own) and collects results into rec. */
static int mpi_master(const tippe_launch_plan *plan, const tippe_launch_options *o,
                      uint64_t seed, tippe_launch_record *rec, tippe_progress *prog,
                      tippe_error *err)
{
    const int size = hands_mpi_size();
    const long total = tippe_launch_plan_total(plan);
    long next = 0;
    int *assigned = calloc((size_t)size, sizeof *assigned);
    if (!assigned)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    int active = 0;
    for (int w = 1; w < size; w++) {
        for (int k = 0; k < 2 && next < total; k++) {
            long c = chunk_size(total - next, size), msg[2] = {next, next + c};
            MPI_Send(msg, 2, MPI_LONG, w, TAG_WORK, MPI_COMM_WORLD);
            next += c;
            assigned[w]++;
        }
        if (assigned[w])
            active++;
        else {
            long stop[2] = {-1, -1};
            MPI_Send(stop, 2, MPI_LONG, w, TAG_WORK, MPI_COMM_WORLD);
        }
    }
    int status = TIPPE_OK;
    char *buf = NULL;
    size_t buf_size = 0;
    for (;;) {
        int flag = 0;
        MPI_Status st;
        if (next < total) {
            MPI_Iprobe(MPI_ANY_SOURCE, TAG_RESULT, MPI_COMM_WORLD, &flag, &st);
            if (!flag) {
                long c = chunk_size(total - next, size), from = next;
                next += c;
                tippe_error e;
                tippe_launch_run(plan, o, seed, from, from + c, rec + from, prog, &e);
                continue;
            }
        } else {
            if (active == 0)
                break;
            MPI_Probe(MPI_ANY_SOURCE, TAG_RESULT, MPI_COMM_WORLD, &st);
        }
        int bytes = 0;
        MPI_Get_count(&st, MPI_BYTE, &bytes);
        if ((size_t)bytes > buf_size) {
            char *nb = realloc(buf, (size_t)bytes);
            if (!nb) {
                status = tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory receiving results");
                MPI_Abort(MPI_COMM_WORLD, 1);
            }
            buf = nb;
            buf_size = (size_t)bytes;
        }
        MPI_Recv(buf, bytes, MPI_BYTE, st.MPI_SOURCE, TAG_RESULT, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE);
        long range[2];
        memcpy(range, buf, sizeof range);
        memcpy(rec + range[0], buf + sizeof range,
               (size_t)(range[1] - range[0]) * sizeof *rec);
        tippe_progress_add(prog, range[1] - range[0]);
        const int w = st.MPI_SOURCE;
        assigned[w]--;
        if (next < total) {
            long c = chunk_size(total - next, size), msg[2] = {next, next + c};
            MPI_Send(msg, 2, MPI_LONG, w, TAG_WORK, MPI_COMM_WORLD);
            next += c;
            assigned[w]++;
        } else if (assigned[w] == 0) {
            long stop[2] = {-1, -1};
            MPI_Send(stop, 2, MPI_LONG, w, TAG_WORK, MPI_COMM_WORLD);
            active--;
        }
    }
    free(buf);
    free(assigned);
    return status;
}

/* Other ranks: compute chunks as they come, send each back without waiting
 * (the next chunk is already queued), until told to stop. */
static void mpi_worker(const tippe_launch_plan *plan, const tippe_launch_options *o,
                       uint64_t seed)
{
    long cur[2];
    MPI_Recv(cur, 2, MPI_LONG, 0, TAG_WORK, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    MPI_Request req = MPI_REQUEST_NULL;
    char *sending = NULL;
    while (cur[0] >= 0) {
        const long n = cur[1] - cur[0];
        const size_t bytes = 2 * sizeof(long) + (size_t)n * sizeof(tippe_launch_record);
        char *buf = malloc(bytes);
        if (!buf)
            MPI_Abort(MPI_COMM_WORLD, 1);
        memcpy(buf, cur, 2 * sizeof(long));
        tippe_error e;
        tippe_launch_run(plan, o, seed, cur[0], cur[1],
                         (tippe_launch_record *)(void *)(buf + 2 * sizeof(long)), NULL, &e);
        MPI_Wait(&req, MPI_STATUS_IGNORE);
        free(sending);
        MPI_Isend(buf, (int)bytes, MPI_BYTE, 0, TAG_RESULT, MPI_COMM_WORLD, &req);
        sending = buf;
        MPI_Recv(cur, 2, MPI_LONG, 0, TAG_WORK, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    }
    MPI_Wait(&req, MPI_STATUS_IGNORE);
    free(sending);
}
#endif

int hands_run_plan(const tippe_launch_plan *plan, const tippe_launch_options *o, uint64_t seed,
                   tippe_launch_record *rec, tippe_progress *prog, tippe_error *err)
{
    const long total = tippe_launch_plan_total(plan);
#ifdef TIPPE_WITH_MPI
    if (hands_mpi_size() > 1) {
        if (hands_mpi_rank() != 0) {
            mpi_worker(plan, o, seed);
            return TIPPE_OK;
        }
        int rc = mpi_master(plan, o, seed, rec, prog, err);
        if (rc)
            return rc;
        for (long i = 0; i < total; i++)
            if (rec[i].status != TIPPE_OK) /* rerun the one launch for its message */
                return tippe_launch_run(plan, o, seed, i, i + 1, rec + i, NULL, err);
        return TIPPE_OK;
    }
#endif
    return tippe_launch_run(plan, o, seed, 0, total, rec, prog, err);
}
