/* libFuzzer target: the command's option parser (tippe_cli_parse, src/cli/
 * options.c) with tippe simulate's option table and map's kinds besides (a
 * range with steps, a whole number with a short name, --seed, --threads): the
 * input is the command line after the verb, one argument per line. */
#include "fuzz.h"

#include "cli/cli.h"

enum { MAX_ARGS = 64 };

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size > 4096)
        return 0;
    char text[4097];
    memcpy(text, data, size);
    text[size] = '\0';
    char *argv[MAX_ARGS + 2];
    int argc = 0;
    argv[argc++] = "simulate";
    for (char *p = text, *nl; argc < MAX_ARGS && p <= text + size; p = nl + 1) {
        nl = strchr(p, '\n');
        if (!nl)
            nl = text + size;
        *nl = '\0';
        argv[argc++] = p;
        if (nl == text + size)
            break;
    }
    argv[argc] = NULL;

    const char *csv = NULL, *plot = NULL;
    double sample_dt = 0;
    int full = 0, json = 0;
    long n = 1, seed = 1, threads = 0;
    tippe_cli_range z2 = {0};
    tippe_cli_launch_args l;
    memset(&l, 0, sizeof l);
    tippe_cli_opt opts[] = {
        {.name = "csv", .kind = TIPPE_CLI_STRING, .value = &csv, .arg = "FILE",
         .help = "trajectory"},
        {.name = "plot", .kind = TIPPE_CLI_STRING, .value = &plot, .arg = "FILE",
         .help = "plot"},
        {.name = "sample-dt", .kind = TIPPE_CLI_DOUBLE, .value = &sample_dt, .unit = "s",
         .min = 0, .max = 1e6, .help = "sampling"},
        {.name = "full", .kind = TIPPE_CLI_FLAG, .value = &full, .help = "full"},
        {.name = "json", .kind = TIPPE_CLI_FLAG, .value = &json, .help = "JSON"},
        {.name = "z2-range", .kind = TIPPE_CLI_RANGE, .value = &z2, .unit = "mm", .min = -1000,
         .max = 1000, .max_steps = 1000, .help = "map's --z2 F:T:N"},
        {.name = "count", .short_name = 'n', .kind = TIPPE_CLI_LONG, .value = &n, .min = 1,
         .max = 1000000, .help = "launches"},
        TIPPE_CLI_SEED_OPT(&seed, "seed"),
        TIPPE_CLI_THREADS_OPT(&threads, "threads"),
        TIPPE_CLI_LAUNCH_OPTS(&l),
        {NULL},
    };
    tippe_cli_spec spec = {
        .verb = "simulate",
        .synopsis = "SCENARIO.json",
        .about = "fuzz",
        .opts = opts,
        .min_args = 1,
        .max_args = 1,
        .args_name = "scenario or design file",
        .progress = 1,
    };
    const char *args[2];
    int n_args = 0;
    tippe_cli_parse(&spec, argc, argv, args, &n_args);
    return 0;
}
