/* tippe serve's work: the bounded queue, the workers that answer the requests
 * that compute, the watchdog that answers a request past its budget, and the
 * temporary folders (removed after sending and at a stop). */
#define _GNU_SOURCE /* pthread_timedjoin_np */
#include "serve/internal.h"

#include <dirent.h>
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
    j->state = JOB_QUEUED;
    j->next = NULL;
    if (s->queue_tail)
        s->queue_tail->next = j;
    else
        s->queue_head = j;
    s->queue_tail = j;
    s->queued++;
    j->next_in_flight = s->in_flight;
    s->in_flight = j;
    pthread_cond_signal(&s->wake);
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

static void *worker(void *arg)
{
    serve_server *s = arg;
    for (;;) {
        pthread_mutex_lock(&s->lock);
        while (!s->queue_head && !s->stopping)
            pthread_cond_wait(&s->wake, &s->lock);
        serve_job *j = s->queue_head;
        if (!j) { /* stopping, and nothing left */
            pthread_mutex_unlock(&s->lock);
            return NULL;
        }
        s->queue_head = j->next;
        if (!s->queue_head)
            s->queue_tail = NULL;
        s->queued--;
        const int skip = j->state == JOB_ANSWERED; /* the watchdog answered it already */
        if (!skip)
            j->state = JOB_RUNNING;
        pthread_mutex_unlock(&s->lock);
        if (!skip) {
            serve_response r = {0};
            if (j->route->exclusive)
                pthread_mutex_lock(&s->exclusive);
            j->route->answer(s, j->req, &r);
            if (j->route->exclusive)
                pthread_mutex_unlock(&s->exclusive);
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

void tippe_serve_watchdog(serve_server *s)
{
    const double now = tippe_serve_now_s();
    pthread_mutex_lock(&s->lock);
    for (serve_job **p = &s->in_flight; *p;) {
        serve_job *j = *p;
        if (now - j->t_queued_s <= s->o.budget_s) {
            p = &j->next_in_flight;
            continue;
        }
        tippe_serve_respond_error(&j->timeout, 503, NULL,
                            "over budget: %s took more than %g s of wall clock (%s); the "
                            "server keeps serving",
                            j->route->path, s->o.budget_s,
                            j->state == JOB_QUEUED ? "waiting for a worker" : "computing");
        j->timeout.retry_after_s = 5;
        j->state = JOB_ANSWERED;
        s->over_budget++;
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
    s->workers = calloc((size_t)s->n_workers, sizeof *s->workers);
    if (!s->workers)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "out of memory");
    for (; s->n_started < s->n_workers; s->n_started++)
        if (pthread_create(&s->workers[s->n_started], NULL, worker, s))
            return tippe_error_set(err, TIPPE_ECOMPUTE, "cannot start a worker thread");
    return TIPPE_OK;
}

void tippe_serve_work_stop(serve_server *s)
{
    pthread_mutex_lock(&s->lock);
    s->stopping = 1;
    pthread_cond_broadcast(&s->wake);
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
