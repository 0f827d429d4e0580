/* The profile options' defaults (see tippe/profile.h). Apart from profile.c,
 * which needs GEOS, so that a command sets its options without loading GEOS. */
#include "tippe/profile.h"

tippe_profile_options tippe_profile_defaults(void)
{
    return (tippe_profile_options){.chord_mm = 0.01,
                                   .clearance_mm = 0.2,
                                   .min_wall_mm = 0.9,
                                   .split = 0,
                                   .split_z_mm = 0};
}
