/* Stubs of the printed bodies (src/profile.c, GEOS) for the tippe command: see
 * module.h. `eval` and `printed` need them; `export` has its own copy in its module. */
#include "module.h"
#include "tippe/profile.h"

#include <string.h>

static tippe_module profile =
    TIPPE_MODULE("profile", "GEOS: apt-get install libgeos-dev");

int tippe_profile_build(const tippe_design *d, const tippe_profile_options *opt,
                        tippe_profile_set *out, tippe_error *err)
{
    __typeof__(&tippe_profile_build) real = TIPPE_MODULE_FIND(&profile, tippe_profile_build, err);
    if (real)
        return real(d, opt, out, err);
    memset(out, 0, sizeof *out); /* as the module's own failures leave it */
    return TIPPE_ECOMPUTE;
}

void tippe_profile_set_free(tippe_profile_set *s)
{
    TIPPE_MODULE_FREE(&profile, tippe_profile_set_free, s);
}
