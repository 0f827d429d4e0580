/* serve/internal.h: what the files of tippe serve share (src/serve/):
 * serve.c runs the server (options, address, signals, workers, the watchdog),
 * serve_http.c speaks HTTP (libmicrohttpd: routes, the checks every request
 * passes, bodies, suspended requests), serve_request.c reads a request's JSON
 * strictly, serve_api.c answers the endpoints by calling the library, and
 * serve_zip.c packs the build's files; the page's files are built in
 * (serve_page.c, generated from src/serve/page/ by cmake/embed.cmake). */
#ifndef TIPPE_SERVE_INTERNAL_H
#define TIPPE_SERVE_INTERNAL_H

#include "tippe/design.h"
#include "tippe/serve.h"

#include <cjson/cJSON.h>
#include <pthread.h>
#include <stddef.h>

struct MHD_Connection;

/* ---- a response ---- */
typedef struct {
    int status;              /* HTTP status; 0: not set */
    const char *type;        /* Content-Type */
    char *body;              /* malloc'd (owned), or NULL */
    size_t len;
    char filename[128];      /* Content-Disposition: attachment; "" for none */
    int retry_after_s;       /* Retry-After on a 503; 0: none */
} serve_response;

/* o (taken, may be NULL: out of memory) as the JSON body of status. */
void tippe_serve_respond_json(serve_response *r, int status, cJSON *o);
/* {"error": message, "field": field (or null), "status": status}. */
void tippe_serve_respond_error(serve_response *r, int status, const char *field, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
void tippe_serve_response_free(serve_response *r);
/* src (NUL-terminated, any bytes) into dst as well-formed UTF-8: a byte that
 * starts no character (or a character cut short) becomes U+FFFD, and with
 * escape_controls a control character becomes \xNN (a log line stays one line).
 * Whole characters only; returns the length written. */
size_t tippe_serve_clean_text(char *dst, size_t size, const char *src, int escape_controls);

/* ---- the shipped designs, read once at start ---- */
typedef struct {
    char name[96];   /* the file's stem: "m12-setscrew" */
    char title[256]; /* its "name" field */
    char *text;
    size_t len;
} serve_design;

/* ---- the server ---- */
typedef struct serve_server serve_server;

typedef struct {
    const char *path;   /* "/api/sweep" */
    int compute;        /* 1: runs on a worker (POST, JSON body); 0: answered at once (GET) */
    int lane;           /* SERVE_LANE_*: where it queues */
    void (*answer)(serve_server *s, const cJSON *req, serve_response *out);
    /* 1: the body is a G-code's text (Content-Type text/x-gcode, up to
     * TIPPE_SERVE_MAX_GCODE_BYTES), handed over as {"text", "name": ?name=} */
    int gcode;
} serve_route;

/* A queue and the threads that take from it. The shared lane (sweeps, evals,
 * verdicts, checks: --workers threads) answers what a page asks after each edit;
 * the advice (the whole build sheet, a second or two) and the exclusive lane
 * (builds and films, seconds each, one at a time: the library's file writer keeps
 * one table of temporaries) have a thread each, at a lower priority (nice 10), so
 * that they never hold a shared worker nor take its core from it. */
typedef struct {
    struct serve_job *head, *tail;
    int queued, max;
    pthread_cond_t wake;
} serve_lane;
enum { SERVE_LANE_SHARED, SERVE_LANE_ADVICE, SERVE_LANE_EXCLUSIVE, SERVE_N_LANES };
/* Waiting at most: advice, one per client editing (its client gone, it is dropped
 * unseen); builds and films, four (each takes 1 to 4 s: within the budget). Beyond,
 * 503 busy. */
#define SERVE_ADVICE_QUEUE 32
#define SERVE_EXCLUSIVE_QUEUE 4
/* The priority of the advice's and exclusive lanes' threads (setpriority). */
#define SERVE_SLOW_LANE_NICE 10

struct serve_server {
    tippe_serve_options o;
    char designs_dir[4096];
    int loopback;        /* listening on a loopback address only */
    char token[65];      /* "" on loopback without --token */
    int port;
    char host[300];      /* the address as the URL gives it: "127.0.0.1", "[::1]" */
    serve_design *designs;
    int n_designs;
    char *materials_json; /* GET /api/materials, built at start */
    size_t materials_len;
    /* work: a bounded queue, a pool of workers and the requests in flight */
    pthread_mutex_t lock;
    serve_lane lanes[SERVE_N_LANES];
    struct serve_job *in_flight;
    int stopping;
    int n_workers, n_started; /* the shared lane's; one more thread per other lane */
    pthread_t *workers;
    struct serve_worker *worker_args;
    /* hands a suspended request back to libmicrohttpd (serve_http.c sets it) */
    void (*resume)(struct MHD_Connection *con);
    /* temporaries (build folders): removed after sending and at stop */
    pthread_mutex_t tmp_lock;
    char tmp_dirs[64][4096];
    int n_tmp;
    /* open connections and the time by which each must have sent its request
     * (serve_http.c); the watchdog shuts those past it */
    pthread_mutex_t conn_lock;
    struct serve_conn *conns;
    long slow_closed;
    /* counts, for the log */
    long served, refused, over_budget, abandoned;
    struct MHD_Daemon *daemon;
};

/* A request that computes: queued, then run by a worker, then answered. */
typedef enum { JOB_QUEUED, JOB_RUNNING, JOB_DONE, JOB_ANSWERED } serve_job_state;
typedef struct serve_job {
    int refs; /* the connection's and the queue's or worker's */
    serve_job_state state;
    int lane;
    int fd;                /* the suspended connection's socket (to see its client leave) */
    volatile int cancel;   /* set by the watchdog: the library's long loops stop (base.h) */
    double t_queued_s;
    const serve_route *route;
    cJSON *req;
    serve_response resp;      /* the worker's */
    serve_response timeout;   /* the watchdog's, when the budget ran out */
    struct MHD_Connection *con;
    struct serve_job *next, *next_in_flight;
} serve_job;

double tippe_serve_now_s(void);
/* serve_http.c */
int tippe_serve_http_start(serve_server *s, tippe_error *err);
void tippe_serve_http_stop(serve_server *s);
/* Shuts the connections that have not sent their whole request in time (slow
 * clients holding connections): called by the watchdog's tick. */
void tippe_serve_http_reap(serve_server *s);

/* serve_work.c: the workers (start, stop taking work, join), the queues (the
 * caller checked that j's lane has room), the watchdog's check (under no lock):
 * a job past its budget or whose client has gone is answered and cancelled. */
int tippe_serve_work_start(serve_server *s, tippe_error *err);
void tippe_serve_work_stop(serve_server *s);
/* Joins the workers: how many are still computing (detached, cut at exit). */
int tippe_serve_work_join(serve_server *s);
int tippe_serve_work_busy(serve_server *s);
void tippe_serve_tmp_remove_all(serve_server *s);
void tippe_serve_enqueue(serve_server *s, serve_job *j);
void tippe_serve_job_release(serve_server *s, serve_job *j);
void tippe_serve_watchdog(serve_server *s);
const serve_route *tippe_serve_find_route(const char *path);
/* A temporary folder for one request (mkdtemp under TMPDIR), recorded so that
 * a stop removes it: 0 or -1. tippe_serve_tmp_remove removes it and its files. */
int tippe_serve_tmp_make(serve_server *s, char *dir, size_t size);
void tippe_serve_tmp_remove(serve_server *s, const char *dir);

/* ---- serve_request.c: a request's JSON, strictly ---- */
/* Parses body (len bytes): a JSON object nested at most TIPPE_SERVE_MAX_DEPTH
 * deep. NULL with a 400 in out when it is not. */
cJSON *tippe_serve_request_parse(const char *body, size_t len, serve_response *out);
/* Refuses a key of req not in allowed (NULL-terminated): 0, or -1 with a 400
 * naming the field. */
int tippe_serve_request_keys(const cJSON *req, const char *const *allowed, serve_response *out);
/* A number at key in [min, max]; absent: *v keeps its default unless required.
 * 0, or -1 with a 400 naming the field and what is wrong. */
int tippe_serve_request_number(const cJSON *req, const char *key, double min, double max,
                         int required, double *v, serve_response *out);
/* A string at key that is one of words (NULL-terminated): its index, or -1
 * with a 400; absent: def (or a 400 when def < 0). */
int tippe_serve_request_word(const cJSON *req, const char *key, const char *const *words, int def,
                       serve_response *out);
/* The design at key: an object (a design file's content) or the name of a
 * shipped design; loaded with the shipped materials table under the name stem
 * (NULL: key), which its messages and the files of a build start with. NULL
 * with a 400 naming the field (the loader's message: field and what is wrong). */
tippe_design *tippe_serve_request_design(serve_server *s, const cJSON *req, const char *key,
                                         const char *stem, serve_response *out);
/* The string at key as a file stem (letters, digits, '-', '_'; at most 64) into
 * stem, left as it was when absent: 0, or -1 with a 400. */
int tippe_serve_request_stem(const cJSON *req, const char *key, char *stem, size_t size,
                             serve_response *out);
/* The shipped design called name, or NULL. */
const serve_design *tippe_serve_find_design(const serve_server *s, const char *name);

/* ---- serve_api.c: the endpoints ---- */
extern const serve_route tippe_serve_routes[];
/* Drops the advice's kept answers (at a stop). */
void tippe_serve_advice_forget(void);

/* ---- serve_gcode.c: G-code uploads, read in memory and kept by id ---- */
void tippe_serve_api_gcode(serve_server *s, const cJSON *req, serve_response *out);
/* The body kept for an upload's id (the hex after "upload:"), and its file's name: 1,
 * or 0 when it is not kept (any more); read with E in mm of diameter_mm filament
 * when > 0 (a design's print.filament_diameter_mm, as the command reads a file),
 * else the file's own. A status < 0 (err set) when that reading fails. */
int tippe_serve_gcode_find(const char *id, double diameter_mm, tippe_gcode_body *out,
                           tippe_gcode_beads *beads, char *name, size_t size, tippe_error *err);
/* A copy (malloc'd, NUL-terminated) of the text of the upload id, for a build's zip: 1,
 * 0 when it is not kept (any more), -1 out of memory. */
int tippe_serve_gcode_text(const char *id, char **text, size_t *len);
void tippe_serve_gcode_forget(void);

/* ---- serve_section.c: the section drawing (tippe export's SVG) ---- */
void tippe_serve_api_section(serve_server *s, const cJSON *req, serve_response *out);

/* ---- serve_zip.c: files of a folder into one zip in memory (libzip) ---- */
/* ... and n_extra more members from memory (the design as sent and the G-codes it names,
 * which the build folder does not hold). */
typedef struct {
    const char *name;
    const char *data;
    size_t len;
} serve_zip_member;
int tippe_serve_zip_folder(const char *dir, const char *const *names, int n,
                           const serve_zip_member *extra, int n_extra, char **out, size_t *len,
                           tippe_error *err);

/* ---- serve_page.c (generated): the page's files ---- */
typedef struct {
    const char *path; /* "/app.js" */
    const char *type;
    const unsigned char *data;
    size_t len;
} serve_asset;
extern const serve_asset tippe_serve_assets[];
extern const int tippe_serve_n_assets;

#endif
