/* tippe/serve.h: tippe serve, the calculator as a local web page.
 *
 * A front end like the command (layer 7, docs/architecture.md): a small HTTP
 * server (libmicrohttpd) that serves one page, built into the program, and a
 * JSON API over the library (docs/serve.md). It parses requests, checks their
 * limits, calls the library and writes responses; it never computes physics and
 * never opens a file a request names (it reads only the shipped designs folder).
 *
 * Requests that compute run on a bounded pool of worker threads with a bounded
 * queue (beyond it: 503 with Retry-After); each has a wall-clock budget (past
 * it: 503, a JSON error). SIGINT and SIGTERM stop the server: it stops
 * accepting, lets the requests in flight finish within their budget, removes
 * its temporary files and returns. */
#ifndef TIPPE_SERVE_H
#define TIPPE_SERVE_H

#include <stddef.h>
#include <stdio.h>

#include "tippe/base.h"

/* Defaults and limits (docs/serve.md, "Limits"). */
#define TIPPE_SERVE_DEFAULT_LISTEN "127.0.0.1:8765"
#define TIPPE_SERVE_MAX_BODY_BYTES (1 << 20)  /* a request's body: 1 MiB */
/* an uploaded G-code (POST /api/gcode): PrusaSlicer's of a 50 mm ball at 0.2 mm layers is
 * a few MiB, at 0.1 mm about 30 MiB (tippe/print.h) */
#define TIPPE_SERVE_MAX_GCODE_BYTES (64 << 20)
#define TIPPE_SERVE_MAX_DEPTH 32              /* JSON nesting of a request */
#define TIPPE_SERVE_DEFAULT_BUDGET_S 30.0     /* wall clock per request */
/* The advice's and the exclusive lane's requests (the build sheet and its advice,
 * builds, films, uploads, sections) run one at a time at nice 10 and cost a whole
 * tippe build: 21 and 29 s of wall clock for a design with a G-code on a machine
 * at load 3 to 4 (docs/serve.md), near the shared lane's 30 s. They get this many
 * times --budget (--slow-budget), still a limit on each. */
#define TIPPE_SERVE_SLOW_BUDGET_FACTOR 4.0
#define TIPPE_SERVE_MAX_FILM_S 8.0            /* model time of a film */
#define TIPPE_SERVE_MAX_FILM_PX 480           /* a film's width and height */
#define TIPPE_SERVE_MAX_FILM_FPS 25
/* Connections (issue 36: 256 clients trickling their headers kept every other
 * client out). At most 256 at once and 64 from one address (a browser opens 6
 * per server, RFC 9112 leaves it to the client; the load bench 16); a request's
 * headers must all arrive within 10 s of the connection (or of the previous
 * answer, 30 s, on a kept-alive one) and its body within 30 s of its headers,
 * else the connection is closed; idle for 30 s while answering, closed. */
#define TIPPE_SERVE_MAX_CONNECTIONS 256
#define TIPPE_SERVE_MAX_CONNECTIONS_PER_IP 64
#define TIPPE_SERVE_HEADERS_S 10.0
#define TIPPE_SERVE_KEEPALIVE_S 30.0
#define TIPPE_SERVE_BODY_S 30.0
#define TIPPE_SERVE_IDLE_S 30

typedef struct {
    const char *listen;      /* "HOST:PORT" (IPv4, "[IPv6]" or localhost); NULL: the default */
    const char *designs_dir; /* the shipped designs, materials and catalogue */
    int threads;             /* workers; 0: one per core */
    int queue;               /* requests waiting for a worker; 0: 16 per worker */
    double budget_s;         /* wall clock per request; 0: the default */
    double slow_budget_s;    /* the same on the advice's and exclusive lanes; 0:
                                TIPPE_SERVE_SLOW_BUDGET_FACTOR x budget_s */
    const char *token;       /* the access token; NULL: random when not on loopback */
    FILE *log;               /* the URL to open, then one line per refused or failed
                                request; NULL: nothing */
} tippe_serve_options;

/* Serves until SIGINT or SIGTERM (blocked in the calling thread and the
 * server's threads, and waited for here). TIPPE_EINPUT for a bad --listen or
 * designs folder, TIPPE_ECOMPUTE if the server cannot start (address in use). */
int tippe_serve_run(const tippe_serve_options *o, tippe_error *err);

#endif
