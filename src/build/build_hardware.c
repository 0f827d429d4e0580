/* The hardware a maker buys: ISO metric threads (ISO 261, ISO 724: the design
 * module's table), their tap drills, and heat-set inserts. Calls nothing else of
 * the build module. */
#include "build/internal.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

/* ISO 261's threads are the design module's table (design_fit.c: the part as
 * made prints a tapped hole at their tap drill): one table for both. */
const tippe_build_thread *tippe_build_thread_by_diameter(double d_mm)
{
    return tippe_design_thread_by_diameter(d_mm);
}

const tippe_build_thread *tippe_build_thread_by_pitch_diameter(double d2_mm)
{
    return tippe_design_thread_by_pitch_diameter(d2_mm);
}

double tippe_build_tap_drill_mm(const tippe_build_thread *t) { return tippe_design_tap_drill_mm(t); }

/* TIPPE_BUILD_INSERT_SOURCE's chart, non-flanged inserts, pilot hole -0/+0.1 mm;
 * lengths TIPPE_BUILD_INSERT_LENGTH_SOURCE's. */
static const tippe_build_insert inserts[] = {
    {"M3", 4.0, 4.4, 5.7},
    {"M4", 5.6, 6.1, 8.1},
    {"M5", 6.4, 7.1, 9.5},
    {"M6", 8.0, 8.5, 12.7},
};

const tippe_build_insert *tippe_build_insert_for(const char *thread)
{
    for (size_t k = 0; thread && k < sizeof inserts / sizeof inserts[0]; k++)
        if (!strcmp(inserts[k].thread, thread))
            return &inserts[k];
    return NULL;
}

/* ISO 724: basic minor diameter of the internal thread, D1 = D - (5 sqrt(3) / 8) P. */
double tippe_build_minor_diameter_mm(const tippe_build_thread *t)
{
    return t->d_mm - 1.082531754730548 * t->pitch_mm;
}
