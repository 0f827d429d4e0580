/* tippe serve's work: the bounded queues (lanes), the workers that answer the requests
 * that compute, the watchdog that answers a request past its budget, and the
 * temporary folders (removed after sending and at a stop). */
#define _GNU_SOURCE /* pthread_timedjoin_np */
#include "serve/internal.h"

#include <dirent.h>
#include <errno.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/syscall.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

double tippe_serve_now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* ------------------------------------------------------------ the queue */

void tippe_serve_job_release(serve_server *s, serve_job *j)
{
    pthread_mutex_lock(&s->lock);
    const int last = --j->refs == 0;
    pthread_mutex_unlock(&s->lock);
    if (!last)
        return;
    cJSON_Delete(j->req);
    tippe_serve_response_free(&j->resp);
    tippe_serve_response_free(&j->timeout);
    free(j);
}

void tippe_serve_enqueue(serve_server *s, serve_job *j)
{
    pthread_mutex_lock(&s->lock);
    serve_lane *L = &s->lanes[j->lane];
    j->state = JOB_QUEUED;
    j->next = NULL;
    if (L->tail)
        L->tail->next = j;
    else
        L->head = j;
    L->tail = j;
    L->queued++;
    j->next_in_flight = s->in_flight;
    s->in_flight = j;
    pthread_cond_signal(&L->wake);
    pthread_mutex_unlock(&s->lock);
}

/* Takes j off the in-flight list (under the lock). */
static void unlist(serve_server *s, serve_job *j)
{
    for (serve_job **p = &s->in_flight; *p; p = &(*p)->next_in_flight)
        if (*p == j) {
            *p = j->next_in_flight;
            return;
        }
}

struct serve_worker {
    serve_server *s;
    int lane;
};

static void *worker(void *arg)
{
    serve_server *s = ((struct serve_worker *)arg)->s;
    serve_lane *L = &s->lanes[((struct serve_worker *)arg)->lane];
    /* the slow lanes yield their core to the shared one (Linux: per thread) */
    if (L != &s->lanes[SERVE_LANE_SHARED])
        setpriority(PRIO_PROCESS, (id_t)syscall(SYS_gettid), SERVE_SLOW_LANE_NICE);
    for (;;) {
        pthread_mutex_lock(&s->lock);
        while (!L->head && !s->stopping)
            pthread_cond_wait(&L->wake, &s->lock);
        serve_job *j = L->head;
        if (!j) { /* stopping, and nothing left */
            pthread_mutex_unlock(&s->lock);
            return NULL;
        }
        L->head = j->next;
        if (!L->head)
            L->tail = NULL;
        L->queued--;
        const int skip = j->state == JOB_ANSWERED; /* the watchdog answered it already */
        if (!skip)
            j->state = JOB_RUNNING;
        pthread_mutex_unlock(&s->lock);
        if (!skip) {
            serve_response r = {0};
            /* the library's long loops watch the job's flag: past its budget, or
             * with its client gone, the worker is free again within a second */
            tippe_cancel_watch(&j->cancel);
            j->route->answer(s, j->req, &r);
            tippe_cancel_watch(NULL);
            if (!r.status)
                tippe_serve_respond_error(&r, 500, NULL, "the endpoint gave no answer");
            pthread_mutex_lock(&s->lock);
            if (j->state == JOB_RUNNING) {
                j->resp = r;
                j->state = JOB_DONE;
                unlist(s, j);
                s->resume(j->con);
            } else {
                tippe_serve_response_free(&r); /* too late: the client has its 503 */
            }
            pthread_mutex_unlock(&s->lock);
        }
        tippe_serve_job_release(s, j);
    }
}

/* Whether the client of a suspended connection has closed it (a page that
 * aborted its request for a newer edit): its socket reads the end of the stream.
 * A suspended connection is libmicrohttpd's to close only once resumed, so fd is
 * its own while the job is in flight (under s->lock). */
static int client_gone(int fd)
{
    char c;
    if (fd < 0)
        return 0;
    const ssize_t n = recv(fd, &c, 1, MSG_PEEK | MSG_DONTWAIT);
    return n == 0 || (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR);
}

void tippe_serve_watchdog(serve_server *s)
{
    const double now = tippe_serve_now_s();
    pthread_mutex_lock(&s->lock);
    for (serve_job **p = &s->in_flight; *p;) {
        serve_job *j = *p;
        /* the slow lanes' own budget (TIPPE_SERVE_SLOW_BUDGET_FACTOR) */
        const double budget =
            j->lane == SERVE_LANE_SHARED ? s->o.budget_s : s->o.slow_budget_s;
        const int over = now - j->t_queued_s > budget, gone = !over && client_gone(j->fd);
        if (!over && !gone) {
            p = &j->next_in_flight;
            continue;
        }
        if (over)
            tippe_serve_respond_error(&j->timeout, 503, NULL,
                                      "over budget: %s took more than %g s of wall clock (%s); "
                                      "the server keeps serving",
                                      j->route->path, budget,
                                      j->state == JOB_QUEUED ? "waiting for a worker"
                                                             : "computing");
        else /* nobody reads it: the connection is closed once resumed */
            tippe_serve_respond_error(&j->timeout, 503, NULL,
                                      "cancelled: the client closed the connection");
        j->timeout.retry_after_s = 5;
        j->state = JOB_ANSWERED;
        j->cancel = 1; /* the worker computing it stops (tippe_cancel_requested) */
        if (over)
            s->over_budget++;
        else
            s->abandoned++;
        *p = j->next_in_flight;
        s->resume(j->con);
    }
    pthread_mutex_unlock(&s->lock);
}

/* ------------------------------------------------------------ temporaries */

int tippe_serve_tmp_make(serve_server *s, char *dir, size_t size)
{
    const char *tmp = getenv("TMPDIR");
    if (!tmp || !tmp[0])
        tmp = "/tmp";
    pthread_mutex_lock(&s->tmp_lock);
    int rc = -1;
    const int cap = (int)(sizeof s->tmp_dirs / sizeof s->tmp_dirs[0]);
    if (!s->stopping && s->n_tmp < cap &&
        snprintf(dir, size, "%s/tippe-serve.XXXXXX", tmp) < (int)size && mkdtemp(dir)) {
        snprintf(s->tmp_dirs[s->n_tmp++], sizeof s->tmp_dirs[0], "%s", dir);
        rc = 0;
    }
    pthread_mutex_unlock(&s->tmp_lock);
    return rc;
}

static void remove_dir(const char *dir)
{
    DIR *d = opendir(dir);
    if (d) {
        struct dirent *e;
        char path[4096 + 300];
        while ((e = readdir(d)))
            if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) {
                snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
                unlink(path);
            }
        closedir(d);
    }
    rmdir(dir);
}

void tippe_serve_tmp_remove(serve_server *s, const char *dir)
{
    pthread_mutex_lock(&s->tmp_lock);
    for (int i = 0; i < s->n_tmp; i++)
        if (!strcmp(s->tmp_dirs[i], dir)) {
            remove_dir(dir);
            memmove(s->tmp_dirs[i], s->tmp_dirs[s->n_tmp - 1], sizeof s->tmp_dirs[0]);
            s->n_tmp--;
            break;
        }
    pthread_mutex_unlock(&s->tmp_lock);
}

void tippe_serve_tmp_remove_all(serve_server *s)
{
    pthread_mutex_lock(&s->tmp_lock);
    for (int i = 0; i < s->n_tmp; i++)
        remove_dir(s->tmp_dirs[i]);
    s->n_tmp = 0;
    pthread_mutex_unlock(&s->tmp_lock);
}


int tippe_serve_work_start(serve_server *s, tippe_error *err)
{
    const int n = s->n_workers + SERVE_N_LANES - 1; /* and one per other lane */
    s->workers = calloc((size_t)n, sizeof *s->workers);
    s->worker_args = calloc((size_t)n, sizeof *s->worker_args);
    if (!s->workers || !s->worker_args)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    for (; s->n_started < n; s->n_started++) {
        struct serve_worker *a = &s->worker_args[s->n_started];
        a->s = s;
        a->lane = s->n_started < s->n_workers ? SERVE_LANE_SHARED
                                              : SERVE_LANE_SHARED + 1 + s->n_started - s->n_workers;
        if (pthread_create(&s->workers[s->n_started], NULL, worker, a))
            return tippe_error_set(err, TIPPE_ECOMPUTE, "cannot start a worker thread");
    }
    return TIPPE_OK;
}

void tippe_serve_work_stop(serve_server *s)
{
    pthread_mutex_lock(&s->lock);
    s->stopping = 1;
    for (int l = 0; l < SERVE_N_LANES; l++)
        pthread_cond_broadcast(&s->lanes[l].wake);
    pthread_mutex_unlock(&s->lock);
}

int tippe_serve_work_join(serve_server *s)
{
    /* workers still computing past their budget are cut with the process */
    int left = 0;
    for (int i = 0; i < s->n_started; i++) {
        struct timespec until;
        clock_gettime(CLOCK_REALTIME, &until);
        until.tv_sec += 1;
        if (pthread_timedjoin_np(s->workers[i], NULL, &until)) {
            pthread_detach(s->workers[i]);
            left++;
        }
    }
    return left;
}

int tippe_serve_work_busy(serve_server *s)
{
    pthread_mutex_lock(&s->lock);
    const int busy = s->in_flight != NULL;
    pthread_mutex_unlock(&s->lock);
    return busy;
}
