/* tippe serve's HTTP side (libmicrohttpd): the checks every request passes
 * (Host, Origin, the token, the method, the path), bodies up to their limit,
 * the page's files and the cheap GETs answered at once, and the requests that
 * compute handed to the workers: the connection is suspended until a worker or
 * the watchdog has its response (docs/serve.md, "Security" and "Limits"). */
#include "serve/internal.h"

#include "tippe/build.h"

#include <microhttpd.h>

#include <arpa/inet.h>
#include <math.h>
#include <sys/socket.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

/* One connection (libmicrohttpd's socket context): the time by which its
 * request must be in, on the server's list for the watchdog. */
typedef struct serve_conn {
    int fd;
    double deadline_s; /* INFINITY while a worker has its request */
    int shut;
    struct serve_conn *next;
} serve_conn;

static serve_conn *conn_of(struct MHD_Connection *con)
{
    const union MHD_ConnectionInfo *i =
        MHD_get_connection_info(con, MHD_CONNECTION_INFO_SOCKET_CONTEXT);
    return i ? i->socket_context : NULL;
}

static void set_deadline(serve_server *s, struct MHD_Connection *con, double deadline_s)
{
    serve_conn *sc = conn_of(con);
    if (!sc)
        return;
    pthread_mutex_lock(&s->conn_lock);
    sc->deadline_s = deadline_s;
    pthread_mutex_unlock(&s->conn_lock);
}

/* libmicrohttpd's thread: a connection opens (its headers are due) or closes
 * (off the list before its socket is closed, so the watchdog never touches
 * another's descriptor). */
static void notify_connection(void *cls, struct MHD_Connection *con, void **socket_context,
                              enum MHD_ConnectionNotificationCode code)
{
    serve_server *s = cls;
    if (code == MHD_CONNECTION_NOTIFY_STARTED) {
        const union MHD_ConnectionInfo *i =
            MHD_get_connection_info(con, MHD_CONNECTION_INFO_CONNECTION_FD);
        serve_conn *sc = i ? calloc(1, sizeof *sc) : NULL;
        if (!sc)
            return;
        sc->fd = i->connect_fd;
        sc->deadline_s = tippe_serve_now_s() + TIPPE_SERVE_HEADERS_S;
        pthread_mutex_lock(&s->conn_lock);
        sc->next = s->conns;
        s->conns = sc;
        pthread_mutex_unlock(&s->conn_lock);
        *socket_context = sc;
    } else if (code == MHD_CONNECTION_NOTIFY_CLOSED && *socket_context) {
        serve_conn *sc = *socket_context;
        pthread_mutex_lock(&s->conn_lock);
        for (serve_conn **p = &s->conns; *p; p = &(*p)->next)
            if (*p == sc) {
                *p = sc->next;
                break;
            }
        pthread_mutex_unlock(&s->conn_lock);
        free(sc);
        *socket_context = NULL;
    }
}

void tippe_serve_http_reap(serve_server *s)
{
    const double now = tippe_serve_now_s();
    pthread_mutex_lock(&s->conn_lock);
    for (serve_conn *sc = s->conns; sc; sc = sc->next)
        if (!sc->shut && now > sc->deadline_s) {
            /* libmicrohttpd sees the end of the stream and closes it on its thread */
            shutdown(sc->fd, SHUT_RDWR);
            sc->shut = 1;
            s->slow_closed++;
        }
    pthread_mutex_unlock(&s->conn_lock);
}

/* One connection's request. */
typedef struct {
    int started;
    char *body;
    size_t len, cap;
    int too_large;
    double declared; /* Content-Length, 0 if none */
    size_t limit;    /* the route's largest body: a JSON's, or an uploaded G-code's */
    int answered;    /* a response was queued at the first call (a refusal) */
    serve_job *job;  /* a request that computes, once handed over */
    int set_cookie;  /* the page was opened with the right ?token= */
} conn_ctx;

/* An uploaded G-code's request: {"text": the body, "name": ?name= (its file's name, for
 * messages)}; NULL with out set for a body that is not text (a NUL byte: binary G-code). */
static cJSON *gcode_request(struct MHD_Connection *con, const conn_ctx *c, serve_response *out)
{
    if (!c->body || !c->len) {
        tippe_serve_respond_error(out, 400, "gcode", "gcode: the body is empty (send the G-code "
                                                     "file's text)");
        return NULL;
    }
    if (memchr(c->body, '\0', c->len)) {
        tippe_serve_respond_error(out, 400, "gcode", "gcode: the body holds a NUL byte: not a "
                                                     "G-code text (binary .bgcode is not read)");
        return NULL;
    }
    const char *name = MHD_lookup_connection_value(con, MHD_GET_ARGUMENT_KIND, "name");
    char *text = malloc(c->len + 1);
    cJSON *o = text ? cJSON_CreateObject() : NULL;
    if (text) {
        memcpy(text, c->body, c->len);
        text[c->len] = '\0';
    }
    cJSON *t = o ? cJSON_CreateStringReference(text) : NULL;
    if (t)
        t->type &= ~cJSON_IsReference; /* cJSON_Delete frees it (malloc, as cJSON's own) */
    if (!t || !cJSON_AddItemToObject(o, "text", t) ||
        (name && !cJSON_AddStringToObject(o, "name", name))) {
        if (!t)
            free(text);
        cJSON_Delete(o);
        tippe_serve_respond_error(out, 503, NULL, "out of memory");
        return NULL;
    }
    return o;
}

static void add_common_headers(struct MHD_Response *resp, const char *type)
{
    MHD_add_response_header(resp, "Content-Type", type);
    MHD_add_response_header(resp, "X-Content-Type-Options", "nosniff");
    MHD_add_response_header(resp, "X-Frame-Options", "DENY");
    MHD_add_response_header(resp, "Referrer-Policy", "no-referrer");
    MHD_add_response_header(resp, "Cross-Origin-Resource-Policy", "same-origin");
    MHD_add_response_header(resp, "Content-Security-Policy",
                            "default-src 'self'; img-src 'self' data: blob:; "
                            "media-src 'self' blob:; style-src 'self'; script-src 'self'; "
                            "connect-src 'self'; frame-ancestors 'none'; base-uri 'none'; "
                            "form-action 'none'");
    MHD_add_response_header(resp, "Cache-Control", "no-store");
}

static void log_line(serve_server *s, const char *method, const char *url,
                     const serve_response *r)
{
    if (!s->o.log || r->status < 400)
        return;
    /* the URL arrives percent-decoded (%0a is a newline) and a message may quote
     * the request: control characters are escaped, so that a request cannot
     * write a line of its own into the log */
    char msg[1200] = "", clean_url[800], clean_method[80];
    if (r->type && !strcmp(r->type, "application/json") && r->body) {
        cJSON *o = cJSON_Parse(r->body);
        const cJSON *e = cJSON_GetObjectItemCaseSensitive(o, "error");
        if (cJSON_IsString(e)) {
            msg[0] = ':';
            msg[1] = ' ';
            tippe_serve_clean_text(msg + 2, sizeof msg - 2, e->valuestring, 1);
        }
        cJSON_Delete(o);
    }
    tippe_serve_clean_text(clean_url, sizeof clean_url, url, 1);
    tippe_serve_clean_text(clean_method, sizeof clean_method, method, 1);
    fprintf(s->o.log, "tippe serve: %d %s %s%s\n", r->status, clean_method, clean_url, msg);
    fflush(s->o.log);
}

/* Queues r (its body handed to MHD) on con. */
static enum MHD_Result send_response(serve_server *s, struct MHD_Connection *con,
                                     serve_response *r, const char *method, const char *url,
                                     int set_cookie)
{
    log_line(s, method, url, r);
    pthread_mutex_lock(&s->lock);
    if (r->status >= 400)
        s->refused++;
    else
        s->served++;
    pthread_mutex_unlock(&s->lock);
    struct MHD_Response *resp =
        MHD_create_response_from_buffer_with_free_callback(r->len, r->body, free);
    if (!resp)
        return MHD_NO;
    r->body = NULL; /* MHD frees it */
    add_common_headers(resp, r->type ? r->type : "application/json");
    if (r->retry_after_s > 0) {
        char v[16];
        snprintf(v, sizeof v, "%d", r->retry_after_s);
        MHD_add_response_header(resp, "Retry-After", v);
    }
    if (r->filename[0]) {
        char v[200];
        snprintf(v, sizeof v, "attachment; filename=\"%s\"", r->filename);
        MHD_add_response_header(resp, "Content-Disposition", v);
    }
    if (set_cookie && s->token[0]) {
        char v[160];
        snprintf(v, sizeof v, "tippe_token=%s; Path=/; HttpOnly; SameSite=Strict", s->token);
        MHD_add_response_header(resp, "Set-Cookie", v);
    }
    enum MHD_Result ret = MHD_queue_response(con, (unsigned)(r->status ? r->status : 500), resp);
    MHD_destroy_response(resp);
    return ret;
}

static enum MHD_Result send_error(serve_server *s, struct MHD_Connection *con, int status,
                                  const char *method, const char *url, const char *fmt, ...)
    __attribute__((format(printf, 6, 7)));
static enum MHD_Result send_error(serve_server *s, struct MHD_Connection *con, int status,
                                  const char *method, const char *url, const char *fmt, ...)
{
    char msg[600];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    serve_response r = {0};
    tippe_serve_respond_error(&r, status, NULL, "%s", msg);
    return send_response(s, con, &r, method, url, 0);
}

/* ------------------------------------------------------------ the checks */

static int equal_const_time(const char *a, const char *b)
{
    size_t n = strlen(a), m = strlen(b);
    unsigned char diff = (unsigned char)(n != m);
    for (size_t i = 0; i < n && i < m; i++)
        diff |= (unsigned char)(a[i] ^ b[i]);
    return diff == 0;
}

/* Host must name this server as the browser reached it: the address it
 * listens on (or, on loopback, localhost, 127.0.0.1 or [::1]) with its port.
 * A page elsewhere whose name was pointed at this machine (DNS rebinding)
 * sends its own name. On a wildcard address (0.0.0.0, [::]) any name is taken:
 * the token is then the door. */
static int host_ok(const serve_server *s, const char *host)
{
    if (!host)
        return 0;
    if (!strcmp(s->host, "0.0.0.0") || !strcmp(s->host, "[::]"))
        return 1;
    char want[400];
    const char *const loop[] = {"127.0.0.1", "localhost", "[::1]", NULL};
    /* on port 80 a browser leaves the port out of Host (RFC 9110, 7.2: the
     * scheme's default port may be omitted) */
    const int bare_ok = s->port == 80;
    snprintf(want, sizeof want, "%s:%d", s->host, s->port);
    if (!strcasecmp(host, want) || (bare_ok && !strcasecmp(host, s->host)))
        return 1;
    for (int i = 0; s->loopback && loop[i]; i++) {
        snprintf(want, sizeof want, "%s:%d", loop[i], s->port);
        if (!strcasecmp(host, want) || (bare_ok && !strcasecmp(host, loop[i])))
            return 1;
    }
    return 0;
}

/* The token, from ?token=, the X-Tippe-Token header or the cookie the page
 * got when it was opened with it. */
static int token_ok(const serve_server *s, struct MHD_Connection *con)
{
    if (!s->token[0])
        return 1;
    const char *t = MHD_lookup_connection_value(con, MHD_GET_ARGUMENT_KIND, "token");
    if (t && equal_const_time(t, s->token))
        return 1;
    t = MHD_lookup_connection_value(con, MHD_HEADER_KIND, "X-Tippe-Token");
    if (t && equal_const_time(t, s->token))
        return 1;
    t = MHD_lookup_connection_value(con, MHD_COOKIE_KIND, "tippe_token");
    return t && equal_const_time(t, s->token);
}

static enum MHD_Result count_host(void *cls, enum MHD_ValueKind kind, const char *key,
                                   const char *value)
{
    (void)kind;
    (void)value;
    if (key && !strcasecmp(key, "Host"))
        ++*(int *)cls;
    return MHD_YES;
}

/* 0 if the request may go on; else a refusal queued. */
static int refuse(serve_server *s, struct MHD_Connection *con, const char *url,
                  const char *method, enum MHD_Result *ret)
{
    /* RFC 9112, 3.2: a request with more than one Host is answered 400 (a proxy
     * and this server could otherwise read different ones) */
    int hosts = 0;
    MHD_get_connection_values(con, MHD_HEADER_KIND, count_host, &hosts);
    if (hosts > 1) {
        *ret = send_error(s, con, 400, method, url, "%d Host headers: a request has one", hosts);
        return 1;
    }
    const char *host = MHD_lookup_connection_value(con, MHD_HEADER_KIND, "Host");
    if (!host_ok(s, host)) {
        *ret = send_error(s, con, 403, method, url,
                          "Host '%.100s' is not this server (it answers to %s:%d%s): a page "
                          "elsewhere cannot use it",
                          host ? host : "(none)", s->host, s->port,
                          s->loopback ? ", localhost, 127.0.0.1 or [::1]" : "");
        return 1;
    }
    /* A browser names the page that sends a request: only this server's own.
     * No CORS headers are ever sent, so no other page can read an answer. */
    const char *origin = MHD_lookup_connection_value(con, MHD_HEADER_KIND, "Origin");
    if (origin) {
        char self[400];
        snprintf(self, sizeof self, "http://%s", host);
        if (strcasecmp(origin, self)) {
            *ret = send_error(s, con, 403, method, url,
                              "Origin '%.100s' is not this server's page (%s): cross-site "
                              "requests are refused",
                              origin, self);
            return 1;
        }
    }
    const char *site = MHD_lookup_connection_value(con, MHD_HEADER_KIND, "Sec-Fetch-Site");
    if (site && !strcmp(site, "cross-site")) {
        *ret = send_error(s, con, 403, method, url, "a cross-site request is refused");
        return 1;
    }
    if (!token_ok(s, con)) {
        *ret = send_error(s, con, 403, method, url,
                          "this server listens beyond loopback and needs its access token: "
                          "open the URL it printed at start (with ?token=...)");
        return 1;
    }
    /* no request names a file: paths are routes, and '..' is never one */
    if (strstr(url, "..") || strchr(url, '\\') || url[0] != '/') {
        *ret = send_error(s, con, 400, method, url,
                          "a path with '..' (or '\\') is refused: no request names a file");
        return 1;
    }
    return 0;
}

/* ------------------------------------------------------------- answers */

static const serve_asset *find_asset(const char *url)
{
    if (!strcmp(url, "/"))
        url = "/index.html";
    for (int i = 0; i < tippe_serve_n_assets; i++)
        if (!strcmp(tippe_serve_assets[i].path, url))
            return &tippe_serve_assets[i];
    return NULL;
}

static enum MHD_Result send_asset(serve_server *s, struct MHD_Connection *con,
                                  const serve_asset *a, int set_cookie)
{
    struct MHD_Response *resp = MHD_create_response_from_buffer(
        a->len, (void *)a->data, MHD_RESPMEM_PERSISTENT);
    if (!resp)
        return MHD_NO;
    add_common_headers(resp, a->type);
    if (set_cookie && s->token[0]) {
        char v[160];
        snprintf(v, sizeof v, "tippe_token=%s; Path=/; HttpOnly; SameSite=Strict", s->token);
        MHD_add_response_header(resp, "Set-Cookie", v);
    }
    pthread_mutex_lock(&s->lock);
    s->served++;
    pthread_mutex_unlock(&s->lock);
    enum MHD_Result ret = MHD_queue_response(con, MHD_HTTP_OK, resp);
    MHD_destroy_response(resp);
    return ret;
}

/* GET /api/designs, /api/designs/NAME, /api/materials: answered at once. */
static int answer_get(serve_server *s, const char *url, serve_response *r)
{
    if (!strcmp(url, "/api/designs")) {
        cJSON *o = cJSON_CreateObject();
        cJSON *arr = o ? cJSON_AddArrayToObject(o, "designs") : NULL;
        for (int i = 0; arr && i < s->n_designs; i++) {
            cJSON *e = cJSON_CreateObject();
            if (!e || !cJSON_AddItemToArray(arr, e)) {
                cJSON_Delete(e);
                break;
            }
            cJSON_AddStringToObject(e, "name", s->designs[i].name);
            cJSON_AddStringToObject(e, "title", s->designs[i].title);
        }
        tippe_serve_respond_json(r, 200, o);
        return 1;
    }
    if (!strncmp(url, "/api/designs/", 13)) {
        const serve_design *d = tippe_serve_find_design(s, url + 13);
        if (!d) {
            tippe_serve_respond_error(r, 404, NULL,
                                "no shipped design '%.80s' (GET /api/designs lists them)",
                                url + 13);
            return 1;
        }
        r->status = 200;
        r->type = "application/json";
        r->body = malloc(d->len + 1);
        if (!r->body) {
            tippe_serve_respond_error(r, 503, NULL, "out of memory");
            return 1;
        }
        memcpy(r->body, d->text, d->len);
        r->len = d->len;
        return 1;
    }
    if (!strcmp(url, "/api/catalogue")) {
        /* the designs folder's catalogue, read now (a few KiB): the screws a page offers */
        char file[4096 + 32];
        snprintf(file, sizeof file, "%s/catalogue.json", s->designs_dir);
        tippe_build_catalogue *c = NULL;
        tippe_error err = {0};
        if (tippe_build_catalogue_load(file, &c, &err)) {
            tippe_serve_respond_error(r, 404, NULL, "no catalogue in the designs folder");
            return 1;
        }
        cJSON *o = cJSON_CreateObject();
        cJSON *arr = o ? cJSON_AddArrayToObject(o, "items") : NULL;
        for (int k = 0; arr && k < c->n_sets; k++)
            for (int i = 0; arr && i < c->sets[k].n_items; i++) {
                const tippe_build_catalogue_item *it = &c->sets[k].items[i];
                cJSON *e = cJSON_CreateObject();
                if (!e || !cJSON_AddItemToArray(arr, e)) {
                    cJSON_Delete(e);
                    break;
                }
                cJSON_AddStringToObject(e, "set", c->sets[k].key);
                cJSON_AddStringToObject(e, "title", c->sets[k].title);
                cJSON_AddStringToObject(e, "name", it->name);
                cJSON_AddStringToObject(e, "thread", it->thread);
                cJSON_AddNumberToObject(e, "d_mm", it->d_mm);
                cJSON_AddNumberToObject(e, "pitch_mm", it->pitch_mm);
                cJSON_AddNumberToObject(e, "radius_mm", it->radius_mm);
                cJSON_AddNumberToObject(e, "height_mm", it->height_mm);
            }
        tippe_build_catalogue_free(c);
        tippe_serve_respond_json(r, 200, o);
        return 1;
    }
    if (!strcmp(url, "/api/materials")) {
        r->status = 200;
        r->type = "application/json";
        r->body = malloc(s->materials_len + 1);
        if (!r->body) {
            tippe_serve_respond_error(r, 503, NULL, "out of memory");
            return 1;
        }
        memcpy(r->body, s->materials_json, s->materials_len);
        r->len = s->materials_len;
        return 1;
    }
    return 0;
}

static enum MHD_Result handle(void *cls, struct MHD_Connection *con, const char *url,
                              const char *method, const char *version, const char *upload_data,
                              size_t *upload_data_size, void **con_cls)
{
    serve_server *s = cls;
    conn_ctx *c = *con_cls;
    const int get = !strcmp(method, "GET") || !strcmp(method, "HEAD");
    const int post = !strcmp(method, "POST");
    if (!c) {
        if (!(c = calloc(1, sizeof *c)))
            return MHD_NO;
        *con_cls = c;
        /* the headers are in; the body is due */
        set_deadline(s, con, tippe_serve_now_s() + TIPPE_SERVE_BODY_S);
        enum MHD_Result ret = MHD_YES;
        if (refuse(s, con, url, method, &ret)) {
            c->answered = 1;
            return ret;
        }
        const serve_route *rt = tippe_serve_find_route(url);
        const int api = !strncmp(url, "/api/", 5) || !strcmp(url, "/api");
        if (!get && !post) {
            c->answered = 1;
            return send_error(s, con, 405, method, url,
                              "method %.20s is not allowed (GET the page and lists, POST the "
                              "API's JSON)", method);
        }
        if (rt && !post) {
            c->answered = 1;
            return send_error(s, con, 405, method, url, "%s takes POST with a JSON body", url);
        }
        if (!rt && post) {
            c->answered = 1;
            return send_error(s, con, 404, method, url, "no endpoint %.100s (docs/serve.md)",
                              url);
        }
        if (rt) {
            /* JSON only (a G-code upload: text/x-gcode, no form's type either): a form
             * elsewhere cannot post here without a preflight */
            const char *type =
                MHD_lookup_connection_value(con, MHD_HEADER_KIND, "Content-Type");
            const char *want = rt->gcode ? "text/x-gcode" : "application/json";
            if (!type || strncasecmp(type, want, strlen(want))) {
                c->answered = 1;
                return send_error(s, con, 415, method, url,
                                  "the body must be %s (Content-Type: %s)",
                                  rt->gcode ? "a G-code's text" : "JSON", want);
            }
            c->limit = rt->gcode ? TIPPE_SERVE_MAX_GCODE_BYTES : TIPPE_SERVE_MAX_BODY_BYTES;
            const char *cl =
                MHD_lookup_connection_value(con, MHD_HEADER_KIND, "Content-Length");
            /* A body over the limit is read and dropped, so that the client gets
             * its 413 rather than a broken pipe; beyond 64 MiB the connection is
             * answered at once and closed. */
            const double length = cl ? strtod(cl, NULL) : 0;
            if (length > 64.0 * (1 << 20)) {
                c->answered = 1;
                return send_error(s, con, 413, method, url,
                                  "the body is %.20s bytes, more than the limit of %zu (%zu MiB)",
                                  cl, c->limit, c->limit >> 20);
            }
            c->too_large = length > (double)c->limit;
            c->declared = length;
        }
        if (get) {
            serve_response r = {0};
            const serve_asset *a = api ? NULL : find_asset(url);
            c->answered = 1;
            /* the page itself is where the token arrives; it then rides in a cookie */
            c->set_cookie = !api && s->token[0] &&
                            MHD_lookup_connection_value(con, MHD_GET_ARGUMENT_KIND, "token");
            if (a)
                return send_asset(s, con, a, c->set_cookie);
            if (api && answer_get(s, url, &r))
                return send_response(s, con, &r, method, url, 0);
            return send_error(s, con, 404, method, url, "no page or endpoint %.100s", url);
        }
        return MHD_YES;
    }
    if (c->answered)
        return MHD_YES; /* a refusal is on its way; the rest of the body is dropped */
    if (*upload_data_size) {
        size_t n = *upload_data_size;
        *upload_data_size = 0;
        if (c->too_large || c->len + n > c->limit) {
            /* a body without a length (chunked) has no end to wait for: the
             * connection is closed at the cap (libmicrohttpd cannot answer before
             * the body is read) */
            if (c->declared <= 0)
                return MHD_NO;
            c->too_large = 1;
            free(c->body);
            c->body = NULL;
            c->len = c->cap = 0;
            return MHD_YES;
        }
        if (c->len + n > c->cap) {
            size_t cap = c->cap ? c->cap : 4096;
            while (cap < c->len + n)
                cap *= 2;
            char *b = realloc(c->body, cap);
            if (!b)
                return MHD_NO;
            c->body = b;
            c->cap = cap;
        }
        memcpy(c->body + c->len, upload_data, n);
        c->len += n;
        return MHD_YES;
    }
    if (c->job) {
        /* resumed: the worker's answer or the watchdog's */
        serve_job *j = c->job;
        serve_response r = {0};
        pthread_mutex_lock(&s->lock);
        serve_response *from = j->state == JOB_ANSWERED ? &j->timeout : &j->resp;
        r = *from;
        from->body = NULL;
        pthread_mutex_unlock(&s->lock);
        c->answered = 1;
        return send_response(s, con, &r, method, url, 0);
    }
    c->answered = 1;
    if (c->too_large) /* only with a Content-Length: a chunked one was cut */
        return send_error(s, con, 413, method, url,
                          "the body is %.0f bytes, more than the limit of %zu (%zu MiB)",
                          c->declared, c->limit, c->limit >> 20);
    serve_response r = {0};
    const serve_route *route = tippe_serve_find_route(url);
    cJSON *req = route->gcode ? gcode_request(con, c, &r)
                              : tippe_serve_request_parse(c->body, c->len, &r);
    free(c->body);
    c->body = NULL;
    if (!req)
        return send_response(s, con, &r, method, url, 0);
    /* only this thread (libmicrohttpd's) adds to the queues: room now is room */
    const int lane = route->lane;
    pthread_mutex_lock(&s->lock);
    const int full = s->lanes[lane].queued >= s->lanes[lane].max || s->stopping;
    pthread_mutex_unlock(&s->lock);
    if (full) {
        cJSON_Delete(req);
        if (lane != SERVE_LANE_SHARED)
            tippe_serve_respond_error(&r, 503, NULL,
                                      "busy: %s is being computed and %d wait; try again in a "
                                      "few seconds",
                                      lane == SERVE_LANE_ADVICE ? "an advice" : "a build or film",
                                      s->lanes[lane].max);
        else
            tippe_serve_respond_error(&r, 503, NULL,
                                      "busy: %d requests are being computed and %d wait; try "
                                      "again in a second", s->n_workers, s->lanes[lane].max);
        r.retry_after_s = 1;
        return send_response(s, con, &r, method, url, 0);
    }
    serve_job *j = calloc(1, sizeof *j);
    if (!j) {
        cJSON_Delete(req);
        return send_error(s, con, 503, method, url, "out of memory");
    }
    j->refs = 2;
    j->req = req;
    j->route = route;
    j->lane = lane;
    const union MHD_ConnectionInfo *fd_info =
        MHD_get_connection_info(con, MHD_CONNECTION_INFO_CONNECTION_FD);
    j->fd = fd_info ? fd_info->connect_fd : -1;
    j->con = con;
    j->t_queued_s = tippe_serve_now_s();
    c->job = j;
    c->answered = 0;
    /* suspended before a worker can resume it; the answer is the worker's (and
     * the budget's) to time */
    set_deadline(s, con, INFINITY);
    MHD_suspend_connection(con);
    tippe_serve_enqueue(s, j);
    return MHD_YES;
}

static void completed(void *cls, struct MHD_Connection *con, void **con_cls,
                      enum MHD_RequestTerminationCode toe)
{
    serve_server *s = cls;
    conn_ctx *c = *con_cls;
    (void)toe;
    /* kept alive: the next request's headers are due */
    set_deadline(s, con, tippe_serve_now_s() + TIPPE_SERVE_KEEPALIVE_S);
    if (!c)
        return;
    if (c->job)
        tippe_serve_job_release(s, c->job);
    free(c->body);
    free(c);
    *con_cls = NULL;
}

static void mhd_log(void *cls, const char *fmt, va_list ap)
{
    serve_server *s = cls;
    if (!s->o.log)
        return;
    char msg[512];
    vsnprintf(msg, sizeof msg, fmt, ap);
    size_t n = strlen(msg);
    while (n && msg[n - 1] == '\n')
        msg[--n] = '\0';
    fprintf(s->o.log, "tippe serve: libmicrohttpd: %s\n", msg);
    fflush(s->o.log);
}

int tippe_serve_http_start(serve_server *s, tippe_error *err)
{
    struct sockaddr_storage sa;
    memset(&sa, 0, sizeof sa);
    unsigned flags = MHD_USE_AUTO_INTERNAL_THREAD | MHD_ALLOW_SUSPEND_RESUME | MHD_USE_ERROR_LOG;
    char bare[300];
    snprintf(bare, sizeof bare, "%s", s->host);
    if (bare[0] == '[') {
        bare[strlen(bare) - 1] = '\0';
        struct sockaddr_in6 *a6 = (struct sockaddr_in6 *)&sa;
        a6->sin6_family = AF_INET6;
        a6->sin6_port = htons((uint16_t)s->port);
        if (inet_pton(AF_INET6, bare + 1, &a6->sin6_addr) != 1)
            return tippe_error_set(err, TIPPE_EINPUT, "--listen %s: not an IPv6 address", s->host);
        flags |= MHD_USE_IPv6;
    } else {
        struct sockaddr_in *a4 = (struct sockaddr_in *)&sa;
        a4->sin_family = AF_INET;
        a4->sin_port = htons((uint16_t)s->port);
        if (inet_pton(AF_INET, bare, &a4->sin_addr) != 1)
            return tippe_error_set(err, TIPPE_EINPUT,
                                   "--listen %s: not an IPv4 address (or [IPv6], or localhost)",
                                   s->host);
    }
    s->daemon = MHD_start_daemon(
        flags, (uint16_t)s->port, NULL, NULL, handle, s, MHD_OPTION_EXTERNAL_LOGGER, mhd_log, s,
        MHD_OPTION_SOCK_ADDR, &sa, MHD_OPTION_NOTIFY_COMPLETED, completed, s,
        MHD_OPTION_NOTIFY_CONNECTION, notify_connection, s,
        MHD_OPTION_CONNECTION_LIMIT, (unsigned)TIPPE_SERVE_MAX_CONNECTIONS,
        MHD_OPTION_PER_IP_CONNECTION_LIMIT, (unsigned)TIPPE_SERVE_MAX_CONNECTIONS_PER_IP,
        MHD_OPTION_CONNECTION_TIMEOUT, (unsigned)TIPPE_SERVE_IDLE_S, MHD_OPTION_END);
    if (!s->daemon)
        return tippe_error_set(err, TIPPE_ECOMPUTE,
                               "cannot listen on %s:%d (in use, or not an address of this "
                               "machine)", s->host, s->port);
    s->resume = MHD_resume_connection;
    const union MHD_DaemonInfo *info = MHD_get_daemon_info(s->daemon, MHD_DAEMON_INFO_BIND_PORT);
    if (info && info->port)
        s->port = info->port;
    return TIPPE_OK;
}

void tippe_serve_http_stop(serve_server *s)
{
    if (s->daemon)
        MHD_stop_daemon(s->daemon);
    s->daemon = NULL;
}

