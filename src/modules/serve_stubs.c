/* Stub of tippe serve (src/serve/, libmicrohttpd and libzip) for the tippe command:
 * see module.h. The server is loaded only by `tippe serve`. */
#include "module.h"
#include "tippe/serve.h"

static tippe_module serve =
    TIPPE_MODULE("serve", "libmicrohttpd and libzip: apt-get install libmicrohttpd-dev libzip-dev");

int tippe_serve_run(const tippe_serve_options *o, tippe_error *err)
{
    TIPPE_MODULE_CALL(&serve, tippe_serve_run, err, o, err);
}
