/* Private to the tippe command: one function per verb, each in src/cli_<verb>.c.
 * A verb parses its own arguments, calls the library, prints, and returns the
 * exit status: 0 success, 2 bad usage or bad input, 1 failed computation. */
#ifndef TIPPE_CLI_H
#define TIPPE_CLI_H

#include <stdio.h>

typedef struct {
    const char *name;
    int (*run)(int argc, char **argv); /* argv[0] is the verb's name */
    const char *summary;
} tippe_cli_verb;

int tippe_cli_eval(int argc, char **argv);
int tippe_cli_classify(int argc, char **argv);
int tippe_cli_simulate(int argc, char **argv);
int tippe_cli_sweep(int argc, char **argv);
int tippe_cli_compare(int argc, char **argv);
int tippe_cli_launch(int argc, char **argv);
int tippe_cli_map(int argc, char **argv);
int tippe_cli_check(int argc, char **argv);
/* Under mpirun with more than one rank (OMPI_COMM_WORLD_SIZE > 1), replaces the
 * process by tippe-mpi from the same directory with the same arguments; returns
 * only if it cannot (2, with a message) or if not under mpirun (0). */
int tippe_cli_mpi_reexec(int argc, char **argv);

/* Writes a file atomically: callers write to the FILE* returned by
 * tippe_cli_open_atomic() and then either commit (rename into place) or abort
 * (remove the temporary), so that no half-written output is ever left. */
FILE *tippe_cli_open_atomic(const char *path, char *tmp_path, size_t tmp_size);
int tippe_cli_commit_atomic(FILE *f, const char *tmp_path, const char *path);
void tippe_cli_abort_atomic(FILE *f, const char *tmp_path);

#endif
