/* The hardware a maker buys: ISO metric threads (ISO 261, ISO 724), their tap
 * drills, and heat-set inserts. Calls nothing else of the build module. */
#include "build/internal.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

/* ISO 261, coarse series (first choice sizes M1.6 .. M24). */
static const tippe_build_thread iso261[] = {
    {"M1.6", 1.6, 0.35}, {"M2", 2, 0.4},     {"M2.5", 2.5, 0.45}, {"M3", 3, 0.5},
    {"M4", 4, 0.7},      {"M5", 5, 0.8},     {"M6", 6, 1.0},      {"M8", 8, 1.25},
    {"M10", 10, 1.5},    {"M12", 12, 1.75},  {"M14", 14, 2.0},    {"M16", 16, 2.0},
    {"M20", 20, 2.5},    {"M24", 24, 3.0},
};
enum { N_ISO = sizeof iso261 / sizeof iso261[0] };

/* ISO 724: the pitch diameter of the basic profile, d2 = d - (3 sqrt(3) / 8) P. */
static double pitch_diameter_mm(const tippe_build_thread *t)
{
    return t->d_mm - 0.649519052838329 * t->pitch_mm;
}

const tippe_build_thread *tippe_build_thread_by_diameter(double d_mm)
{
    for (int k = 0; k < N_ISO; k++)
        if (fabs(iso261[k].d_mm - d_mm) < 1e-6)
            return &iso261[k];
    return NULL;
}

const tippe_build_thread *tippe_build_thread_by_pitch_diameter(double d2_mm)
{
    int best = 0;
    for (int k = 1; k < N_ISO; k++)
        if (fabs(pitch_diameter_mm(&iso261[k]) - d2_mm) <
            fabs(pitch_diameter_mm(&iso261[best]) - d2_mm))
            best = k;
    return &iso261[best];
}

double tippe_build_tap_drill_mm(const tippe_build_thread *t) { return t->d_mm - t->pitch_mm; }

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
