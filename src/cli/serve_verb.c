/* tippe serve: the calculator as a local web page (src/serve/, docs/serve.md).
 * The verb reads its options and hands over to the server, which the command
 * loads (tippe-serve.so, with libmicrohttpd) only here. */
#include "cli.h"

#include "tippe/serve.h"

#include <stdio.h>
#include <string.h>

static const char *const VERB = "serve";

int tippe_cli_serve(int argc, char **argv)
{
    tippe_serve_options o = {.listen = TIPPE_SERVE_DEFAULT_LISTEN, .designs_dir = NULL};
    long threads = 0, queue = 0;
    double budget = TIPPE_SERVE_DEFAULT_BUDGET_S, slow_budget = 0;
    tippe_cli_opt opts[] = {
        {.name = "listen", .kind = TIPPE_CLI_STRING, .value = &o.listen, .arg = "HOST:PORT",
         .def = TIPPE_SERVE_DEFAULT_LISTEN,
         .help = "address and port to listen on (port 0: a free one). Any address but\n"
                 "127.0.0.1 and [::1] needs the access token printed in the URL at start"},
        {.name = "designs", .kind = TIPPE_CLI_STRING, .value = &o.designs_dir, .arg = "DIR",
         .def = "PREFIX/share/tippe/designs (a build tree: designs/)",
         .help = "the shipped designs the page lists, with their materials table and\n"
                 "catalogue: the only files the server reads"},
        {.name = "workers", .kind = TIPPE_CLI_LONG, .value = &threads, .arg = "N", .min = 1,
         .max = 256, .def = "one per core", .help = "worker threads computing requests"},
        {.name = "queue", .kind = TIPPE_CLI_LONG, .value = &queue, .arg = "N", .min = 1,
         .max = 4096, .def = "16 per worker",
         .help = "requests that may wait for a worker; more get 503 with Retry-After"},
        {.name = "budget", .kind = TIPPE_CLI_DOUBLE, .value = &budget, .arg = "S", .unit = "s",
         .min = 0.1, .max = 3600, .def = TIPPE_CLI_STR(TIPPE_SERVE_DEFAULT_BUDGET_S),
         .help = "wall-clock budget of one request, waiting included (past it: 503)"},
        {.name = "slow-budget", .kind = TIPPE_CLI_DOUBLE, .value = &slow_budget, .arg = "S",
         .unit = "s", .min = 0.1, .max = 14400,
         .def = TIPPE_CLI_STR(TIPPE_SERVE_SLOW_BUDGET_FACTOR) " x --budget",
         .help = "the same for the advice, builds, films and uploads (one at a time,\n"
                 "at a lower priority, each a whole tippe build's work)"},
        {.name = "token", .kind = TIPPE_CLI_STRING, .value = &o.token, .arg = "TEXT",
         .def = "random beyond loopback, none on it",
         .help = "the access token (16 to 64 characters) instead of a random one"},
        {NULL},
    };
    tippe_cli_spec spec = {
        .verb = VERB,
        .synopsis = "[--listen HOST:PORT] [--designs DIR] [--workers N] [--queue N]\n"
                    "                   [--budget S] [--slow-budget S] [--token TEXT]",
        .about = "Serves the calculator as a local web page: open a shipped design or your\n"
                 "own, change its numbers and see the zones, the 3-in-1 verdict and the zone\n"
                 "plot follow; check a launch, film it, download the build sheet and the\n"
                 "files to print. The page is built into the program and works offline; its\n"
                 "JSON API gives the numbers tippe's --json gives (docs/serve.md).",
        .after = "Prints the URL to open and serves until Ctrl-C or SIGTERM, which stop it\n"
                 "cleanly. It listens on loopback unless told otherwise; checks Host and\n"
                 "Origin so that no other web page can use it; limits bodies (1 MiB),\n"
                 "nesting, launches and films; reads only the designs folder. Exit status:\n"
                 "0 stopped by a signal, 2 bad usage, 1 the server could not start.",
        .opts = opts,
        .min_args = 0,
        .max_args = 0,
    };
    int n_args = 0;
    int rc = tippe_cli_parse(&spec, argc, argv, NULL, &n_args);
    if (rc)
        return rc == TIPPE_CLI_HELP ? 0 : rc;
    o.threads = (int)threads;
    o.queue = (int)queue;
    o.budget_s = budget;
    o.slow_budget_s = slow_budget;
    static char shipped[4096];
    if (!o.designs_dir) {
        if (!tippe_file_shipped_dir(shipped, sizeof shipped)) {
            fprintf(stderr, "tippe serve: no shipped designs found (looked in %s): name a folder "
                            "with --designs DIR\n", shipped);
            return 2;
        }
        o.designs_dir = shipped;
    }
    o.log = stderr;
    /* The build endpoint's files are written and renamed at once, not kept for
     * the end of the run as a verb's outputs are. */
    tippe_report_set_abort();
    tippe_error err = {0};
    rc = tippe_serve_run(&o, &err);
    if (rc)
        return tippe_cli_fail(VERB, &err, rc);
    return 0;
}
