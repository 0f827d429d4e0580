/* Signals of the tippe command (see cli.h): an interrupted verb stops at once,
 * leaves no temporary behind and no old file changed.
 *
 * The handler does the whole job itself rather than setting a flag for the
 * work to poll: a single long integration, an encoder, or a write blocked on a
 * FIFO polls nothing, and every output file still exists only as a
 * temporary (tippe/base.h) until the verb has finished, so removing the
 * temporaries (and the output directory the run made, then empty) and ending
 * the process is always a clean stop. It uses only async-signal-safe calls
 * (unlink, rmdir, write, signal, raise). */
#include "cli.h"

#include "tippe/base.h"

#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static const int stop_signals[] = {SIGINT, SIGTERM, SIGHUP, SIGPIPE};
enum { N_STOP = sizeof stop_signals / sizeof stop_signals[0] };
static char stop_message[N_STOP][160]; /* written ahead: snprintf is not signal-safe */
static volatile sig_atomic_t pending;
/* The output directory this run made, removed by a stop (as by a failure). */
static char made_dir[4096];
static volatile sig_atomic_t have_made_dir;

static const char *signal_name(int sig)
{
    switch (sig) {
    case SIGINT:
        return "SIGINT";
    case SIGTERM:
        return "SIGTERM";
    case SIGHUP:
        return "SIGHUP";
    default:
        return "SIGPIPE";
    }
}

/* Ends the process as killed by sig, so that the shell sees 128 + sig (130 for
 * SIGINT, 143 for SIGTERM) and a script's loop stops on Ctrl-C as it should. */
static void die_by(int sig)
{
    signal(sig, SIG_DFL);
    raise(sig); /* delivered as soon as the handler returns */
    sigset_t s;
    sigemptyset(&s);
    sigaddset(&s, sig);
    sigprocmask(SIG_UNBLOCK, &s, NULL);
    _exit(128 + sig); /* not reached */
}

static void on_stop(int sig)
{
    if (tippe_report_committing()) {
        pending = sig; /* the outputs are being renamed into place: let it finish */
        return;
    }
    tippe_report_remove_temporaries();
    if (have_made_dir)
        rmdir(made_dir); /* empty now, unless someone else put a file there */
    for (int i = 0; i < N_STOP; i++)
        if (stop_signals[i] == sig && stop_message[i][0]) {
            ssize_t ignored = write(STDERR_FILENO, stop_message[i], strlen(stop_message[i]));
            (void)ignored;
        }
    die_by(sig);
}

/* A file-size limit (ulimit -f) then fails the write with EFBIG, which the
 * checked writes report, instead of killing the process mid-file. */
static void on_file_size(int sig)
{
    (void)sig;
}

void tippe_cli_signals_install(const char *verb)
{
    for (int i = 0; i < N_STOP; i++) {
        if (stop_signals[i] == SIGPIPE) /* the reader went away: quiet, as for any filter */
            stop_message[i][0] = '\0';
        else
            snprintf(stop_message[i], sizeof stop_message[i],
                     "tippe %s: stopped by %s; temporary files removed, existing files left as "
                     "they were\n",
                     verb, signal_name(stop_signals[i]));
        struct sigaction sa, old;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = on_stop;
        sigfillset(&sa.sa_mask); /* one stop at a time */
        /* nohup's ignored SIGHUP stays ignored. SIGINT is caught even when the
         * shell ignores it for a background job: an explicit kill -INT must
         * still stop the work cleanly. */
        if (sigaction(stop_signals[i], NULL, &old) == 0 && old.sa_handler == SIG_IGN &&
            (stop_signals[i] == SIGHUP || stop_signals[i] == SIGPIPE))
            continue;
        sigaction(stop_signals[i], &sa, NULL);
    }
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_file_size;
    sa.sa_flags = SA_RESTART;
    sigaction(SIGXFSZ, &sa, NULL);
}

int tippe_cli_signals_mkdir(const char *dir)
{
    if (strlen(dir) >= sizeof made_dir) {
        errno = ENAMETOOLONG;
        return -1;
    }
    sigset_t stop, old;
    sigemptyset(&stop);
    for (int i = 0; i < N_STOP; i++)
        sigaddset(&stop, stop_signals[i]);
    sigprocmask(SIG_BLOCK, &stop, &old);
    int rc = mkdir(dir, 0777);
    int e = errno;
    if (rc == 0) {
        memcpy(made_dir, dir, strlen(dir) + 1);
        have_made_dir = 1;
    }
    sigprocmask(SIG_SETMASK, &old, NULL); /* a stop that came meanwhile is handled here */
    errno = e;
    return rc;
}

const char *tippe_cli_signals_made_dir(void)
{
    return have_made_dir ? made_dir : NULL;
}

int tippe_cli_signal_pending(const char *verb)
{
    const int sig = pending;
    if (!sig)
        return 0;
    if (sig != SIGPIPE)
        fprintf(stderr, "tippe %s: stopped by %s just after its files were written\n", verb,
                signal_name(sig));
    tippe_report_remove_temporaries();
    die_by(sig);
    return 128 + sig;
}
