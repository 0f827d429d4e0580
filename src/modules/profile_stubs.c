/* Stubs of the printed bodies (src/profile/profile.c, GEOS) for the tippe command: see
 * module.h. `eval` and `printed` need them; `export` has its own copy in its module. */
#include "module.h"
#include "tippe/profile.h"

static tippe_module profile =
    TIPPE_MODULE("profile", "GEOS: apt-get install libgeos-dev");

int tippe_profile_build(const tippe_design *d, const tippe_profile_options *opt,
                        tippe_profile_set *out, tippe_error *err)
{
    TIPPE_MODULE_FILL(&profile, tippe_profile_build, err, out, d, opt, out, err);
}

void tippe_profile_set_free(tippe_profile_set *s)
{
    TIPPE_MODULE_FREE(&profile, tippe_profile_set_free, s);
}
