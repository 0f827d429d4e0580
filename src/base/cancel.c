/* A long computation cancelled from outside (tippe/base.h): one flag per
 * thread, read by the library's long loops. */
#include "tippe/base.h"

#include <stddef.h>

/* thread-local: each of tippe serve's workers watches its own request */
static _Thread_local const volatile int *watched;

const volatile int *tippe_cancel_watch(const volatile int *flag)
{
    const volatile int *old = watched;
    watched = flag;
    return old;
}

int tippe_cancel_requested(void)
{
    return watched && *watched;
}

int tippe_cancel_error(tippe_error *err)
{
    return tippe_error_set(err, TIPPE_ECOMPUTE,
                           "cancelled (the request is past its budget or its client has gone)");
}
