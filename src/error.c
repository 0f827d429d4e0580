#include "tippe/error.h"

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
    }
    return code;
}
