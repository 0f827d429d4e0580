#include "tippe/base.h"

#include <gsl/gsl_errno.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdio.h>

int tippe_error_set(tippe_error *err, int code, const char *fmt, ...)
{
    if (err) {
        va_list ap;
        va_start(ap, fmt);
        err->code = code;
        vsnprintf(err->msg, sizeof err->msg, fmt, ap);
        va_end(ap);
        err->field[0] = '\0';
    }
    return code;
}

int tippe_error_set_field(tippe_error *err, int code, const char *field, const char *fmt, ...)
{
    if (err) {
        va_list ap;
        va_start(ap, fmt);
        err->code = code;
        vsnprintf(err->msg, sizeof err->msg, fmt, ap);
        va_end(ap);
        snprintf(err->field, sizeof err->field, "%s", field ? field : "");
    }
    return code;
}

int tippe_error_blame(tippe_error *err, const char *field)
{
    if (!err)
        return TIPPE_OK;
    snprintf(err->field, sizeof err->field, "%s", field ? field : "");
    return err->code;
}

static void gsl_handler_off(void) { gsl_set_error_handler_off(); }

void tippe_gsl_errors_as_codes(void)
{
    static pthread_once_t once = PTHREAD_ONCE_INIT;
    pthread_once(&once, gsl_handler_off);
}
