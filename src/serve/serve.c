/* tippe serve: the address and the token, the shipped designs read once, the
 * start of the workers and the listener, and the stop on SIGINT or SIGTERM
 * (see tippe/serve.h). */
#include "serve/internal.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

/* ------------------------------------------------------------ start-up */

/* --listen HOST:PORT: HOST an IPv4 address, [IPv6] or localhost. */
static int parse_listen(serve_server *s, const char *listen, tippe_error *err)
{
    const char *colon = strrchr(listen, ':');
    char *end = NULL;
    long port = colon ? strtol(colon + 1, &end, 10) : -1;
    if (!colon || colon == listen || !end || *end || end == colon + 1 || port < 0 ||
        port > 65535 || (size_t)(colon - listen) >= sizeof s->host)
        return tippe_error_set(err, TIPPE_EINPUT,
                               "--listen %s: expected HOST:PORT (127.0.0.1:8765, [::1]:8765, "
                               "localhost:8765; port 0 picks a free one)",
                               listen);
    snprintf(s->host, sizeof s->host, "%.*s", (int)(colon - listen), listen);
    s->port = (int)port;
    if (!strcmp(s->host, "localhost"))
        snprintf(s->host, sizeof s->host, "127.0.0.1");
    /* The default's address and IPv6's only: any other (127.0.0.2 too) needs the
     * token, so that a test can try the token on an address that stays local. */
    s->loopback = !strcmp(s->host, "127.0.0.1") || !strcmp(s->host, "[::1]");
    return TIPPE_OK;
}

static int make_token(char *out, size_t size, tippe_error *err)
{
    unsigned char raw[24];
    int fd = open("/dev/urandom", O_RDONLY | O_CLOEXEC);
    ssize_t n = fd >= 0 ? read(fd, raw, sizeof raw) : -1;
    if (fd >= 0)
        close(fd);
    if (n != (ssize_t)sizeof raw)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "cannot read /dev/urandom for the token");
    for (size_t i = 0; i < sizeof raw && 2 * i + 2 < size; i++)
        snprintf(out + 2 * i, 3, "%02x", raw[i]);
    return TIPPE_OK;
}

static int by_name(const void *a, const void *b)
{
    return strcmp(((const serve_design *)a)->name, ((const serve_design *)b)->name);
}

/* The shipped designs: every *.json of the folder that loads as a design. */
static int read_designs(serve_server *s, tippe_error *err)
{
    DIR *dir = opendir(s->designs_dir);
    if (!dir)
        return tippe_error_set(err, TIPPE_EINPUT, "--designs %s: cannot open: %s",
                               s->designs_dir, strerror(errno));
    struct dirent *e;
    int cap = 0;
    while ((e = readdir(dir))) {
        size_t n = strlen(e->d_name);
        if (n < 6 || n - 5 >= sizeof s->designs[0].name || strcmp(e->d_name + n - 5, ".json"))
            continue;
        char path[4096 + 300];
        snprintf(path, sizeof path, "%s/%s", s->designs_dir, e->d_name);
        tippe_design *d = NULL;
        tippe_error ignored = {0};
        if (tippe_design_load(path, NULL, 0, &d, &ignored))
            continue; /* materials.json, catalogue.json, a broken file */
        FILE *f = fopen(path, "rb");
        char *text = NULL;
        long len = -1;
        if (f && !fseek(f, 0, SEEK_END) && (len = ftell(f)) >= 0 && !fseek(f, 0, SEEK_SET) &&
            (text = malloc((size_t)len + 1)) && fread(text, 1, (size_t)len, f) == (size_t)len) {
            text[len] = '\0';
            if (s->n_designs == cap) {
                cap = cap ? 2 * cap : 32;
                serve_design *more = realloc(s->designs, (size_t)cap * sizeof *more);
                if (!more) {
                    free(text);
                    text = NULL;
                    cap = s->n_designs;
                }
                else
                    s->designs = more;
            }
            if (text) {
                serve_design *sd = &s->designs[s->n_designs++];
                snprintf(sd->name, sizeof sd->name, "%.*s", (int)(n - 5), e->d_name);
                snprintf(sd->title, sizeof sd->title, "%s", tippe_design_name(d));
                sd->text = text;
                sd->len = (size_t)len;
                text = NULL;
            }
        }
        free(text);
        if (f)
            fclose(f);
        tippe_design_free(d);
    }
    closedir(dir);
    if (!s->n_designs)
        return tippe_error_set(err, TIPPE_EINPUT, "--designs %s: no design file in it",
                               s->designs_dir);
    qsort(s->designs, (size_t)s->n_designs, sizeof *s->designs, by_name);
    return TIPPE_OK;
}

static int read_materials(serve_server *s, tippe_error *err)
{
    char path[4096 + 32];
    snprintf(path, sizeof path, "%s/materials.json", s->designs_dir);
    tippe_materials *t = NULL;
    int rc = tippe_materials_load(path, &t, err);
    if (rc)
        return rc;
    cJSON *o = tippe_materials_json(t, NULL);
    tippe_materials_free(t);
    s->materials_json = o ? cJSON_PrintUnformatted(o) : NULL;
    cJSON_Delete(o);
    if (!s->materials_json)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    s->materials_len = strlen(s->materials_json);
    return TIPPE_OK;
}

static void server_free(serve_server *s)
{
    for (int i = 0; i < s->n_designs; i++)
        free(s->designs[i].text);
    free(s->designs);
    free(s->materials_json);
    free(s->workers);
    free(s->worker_args);
}

int tippe_serve_run(const tippe_serve_options *opt, tippe_error *err)
{
    serve_server *s = calloc(1, sizeof *s);
    if (!s)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    s->o = *opt;
    if (!s->o.listen)
        s->o.listen = TIPPE_SERVE_DEFAULT_LISTEN;
    if (!(s->o.budget_s > 0))
        s->o.budget_s = TIPPE_SERVE_DEFAULT_BUDGET_S;
    if (!(s->o.slow_budget_s > 0))
        s->o.slow_budget_s = TIPPE_SERVE_SLOW_BUDGET_FACTOR * s->o.budget_s;
    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    s->n_workers = s->o.threads > 0 ? s->o.threads : cores > 0 ? (int)cores : 1;
    s->lanes[SERVE_LANE_SHARED].max = s->o.queue > 0 ? s->o.queue : 16 * s->n_workers;
    s->lanes[SERVE_LANE_ADVICE].max =
        s->o.queue > 0 && s->o.queue < SERVE_ADVICE_QUEUE ? s->o.queue : SERVE_ADVICE_QUEUE;
    s->lanes[SERVE_LANE_EXCLUSIVE].max =
        s->o.queue > 0 && s->o.queue < SERVE_EXCLUSIVE_QUEUE ? s->o.queue : SERVE_EXCLUSIVE_QUEUE;
    snprintf(s->designs_dir, sizeof s->designs_dir, "%s", s->o.designs_dir ? s->o.designs_dir
                                                                           : "designs");
    pthread_mutex_init(&s->lock, NULL);
    pthread_mutex_init(&s->tmp_lock, NULL);
    pthread_mutex_init(&s->conn_lock, NULL);
    for (int l = 0; l < SERVE_N_LANES; l++)
        pthread_cond_init(&s->lanes[l].wake, NULL);
    int rc = parse_listen(s, s->o.listen, err);
    if (!rc && s->o.token) {
        if (strlen(s->o.token) < 16 || strlen(s->o.token) >= sizeof s->token)
            rc = tippe_error_set(err, TIPPE_EINPUT, "--token: 16 to 64 characters");
        else
            snprintf(s->token, sizeof s->token, "%s", s->o.token);
    } else if (!rc && !s->loopback) {
        rc = make_token(s->token, sizeof s->token, err);
    }
    if (!rc)
        rc = read_designs(s, err);
    if (!rc)
        rc = read_materials(s, err);
    if (rc) {
        server_free(s);
        free(s);
        return rc;
    }
    /* SIGINT and SIGTERM are waited for here: blocked in this thread and so in
     * every thread it starts (libmicrohttpd's, the workers). */
    sigset_t stop, old;
    sigemptyset(&stop);
    sigaddset(&stop, SIGINT);
    sigaddset(&stop, SIGTERM);
    sigaddset(&stop, SIGHUP);
    pthread_sigmask(SIG_BLOCK, &stop, &old);
    signal(SIGPIPE, SIG_IGN);
    if (!rc)
        rc = tippe_serve_work_start(s, err);
    if (!rc)
        rc = tippe_serve_http_start(s, err);
    if (!rc && s->o.log) {
        fprintf(s->o.log,
                "tippe serve: the calculator is at\n\n    http://%s:%d/%s%s\n\n"
                "%s; %d workers (and one for the advice, one for builds and films), %d waiting at most, %g s per "
                "request (%g s for the advice, builds and films); Ctrl-C stops it.\n",
                s->host, s->port, s->token[0] ? "?token=" : "", s->token,
                s->token[0] ? "Listening beyond loopback: the URL carries the access token "
                              "every request needs (keep it private)"
                            : "Loopback only: nothing outside this machine can reach it",
                s->n_workers, s->lanes[SERVE_LANE_SHARED].max, s->o.budget_s,
                s->o.slow_budget_s);
        fflush(s->o.log);
    }
    int sig = 0;
    while (!rc) {
        struct timespec tick = {0, 100 * 1000 * 1000};
        sig = sigtimedwait(&stop, NULL, &tick);
        if (sig > 0)
            break;
        tippe_serve_watchdog(s);
        tippe_serve_http_reap(s);
    }
    /* Stop: no new request is queued; those in flight finish within their
     * budget (the watchdog answers the rest), then the listener closes. */
    tippe_serve_work_stop(s);
    if (s->daemon) {
        const double t0 = tippe_serve_now_s();
        while (tippe_serve_work_busy(s) && tippe_serve_now_s() - t0 <= fmax(s->o.budget_s, s->o.slow_budget_s) + 1) {
            struct timespec t = {0, 50 * 1000 * 1000};
            nanosleep(&t, NULL);
            tippe_serve_watchdog(s);
        }
        struct timespec t = {0, 200 * 1000 * 1000}; /* the last answers leave */
        nanosleep(&t, NULL);
    }
    tippe_serve_http_stop(s);
    const int still_working = tippe_serve_work_join(s);
    tippe_serve_tmp_remove_all(s);
    tippe_serve_advice_forget();
    tippe_serve_gcode_forget();
    if (s->o.log && sig > 0) {
        fprintf(s->o.log, "tippe serve: stopped by %s (%ld answered, %ld refused, %ld over "
                          "budget, %ld left by their client, %ld slow connections closed)\n",
                sig == SIGINT ? "SIGINT" : sig == SIGTERM ? "SIGTERM" : "SIGHUP", s->served,
                s->refused, s->over_budget, s->abandoned, s->slow_closed);
        fflush(s->o.log);
    }
    pthread_sigmask(SIG_SETMASK, &old, NULL);
    if (!still_working) {
        server_free(s);
        pthread_mutex_destroy(&s->lock);
        pthread_mutex_destroy(&s->tmp_lock);
        pthread_mutex_destroy(&s->conn_lock);
        for (int l = 0; l < SERVE_N_LANES; l++)
            pthread_cond_destroy(&s->lanes[l].wake);
        free(s);
    } /* else s stays: a worker cut at exit may still read it */
    return rc;
}
