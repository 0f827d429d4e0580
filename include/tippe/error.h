/* tippe/error.h: how every tippe function reports failure.
 *
 * Like GSL, a function returns an int status (TIPPE_OK on success) and, when it
 * fails, fills a tippe_error with a message a user can act on: which file, which
 * field (as a JSON path such as "parts[2].radius_mm"), and what is wrong.
 * The status doubles as the process exit code of the tippe command. */
#ifndef TIPPE_ERROR_H
#define TIPPE_ERROR_H

enum {
    TIPPE_OK = 0,
    TIPPE_ECOMPUTE = 1, /* a computation failed (integrator, root finder, ...) */
    TIPPE_EINPUT = 2    /* bad usage or bad input: the user can fix it */
};

typedef struct {
    int code;
    char msg[1024];
} tippe_error;

/* Sets err (if not NULL) and returns code, so that callers can write
 * `return tippe_error_set(err, TIPPE_EINPUT, "%s: %s: ...", file, path);` */
int tippe_error_set(tippe_error *err, int code, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* Turns GSL's abort-on-error handler off, once per process and thread-safely:
 * every library entry point that calls GSL calls this first, and then checks
 * GSL's return codes itself (GSL's default handler would abort the process). */
void tippe_gsl_errors_as_codes(void);

#endif
