/* Shared by the benchmarks in tools/ and tools/bench/ (header only; not a tool). */
#ifndef TIPPE_BENCH_UTIL_H
#define TIPPE_BENCH_UTIL_H

#include <gsl/gsl_sort.h>
#include <stddef.h>
#include <time.h>

/* Wall-clock seconds on a monotonic clock. */
static inline double bench_now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Sorts v in place and returns v[n/2]: the median of an odd number of repeats
 * (the upper of the middle two for an even number). */
static inline double bench_median(double *v, size_t n)
{
    gsl_sort(v, 1, n);
    return v[n / 2];
}

#endif
