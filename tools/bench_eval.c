/* How fast a design is evaluated: tippe_design_top() per second for each
 * shipped design (the inner loop of a Z2 sweep), and full loads per second
 * (parse, validate, overlap and travel checks, moments). Median of several
 * repeats. Run from the repository root: build/tools/bench_eval */
#include "tippe/design.h"
#include "bench_util.h"

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#define REPEATS 7

int main(int argc, char **argv)
{
    const char *designs[] = {"designs/m12-setscrew.json", "designs/m3-setscrew.json",
                             "designs/shell-rod-iron.json", "designs/shell-rod-nylon.json",
                             "designs/shell-band.json"};
    const int n_designs = (int)(sizeof designs / sizeof designs[0]);
    const int n_top = argc > 1 ? atoi(argv[1]) : 2000000;
    const int n_load = argc > 2 ? atoi(argv[2]) : 20;
    volatile double sink = 0; /* keeps the loops from being optimised away */
    printf("%-30s %16s %14s %12s\n", "design", "top evals/s", "ns/eval", "loads/s");
    for (int k = 0; k < n_designs; k++) {
        tippe_error err = {0};
        tippe_design *d = NULL;
        if (tippe_design_load(designs[k], NULL, 0, &d, &err)) {
            fprintf(stderr, "bench_eval: %s\n", err.msg);
            return 1;
        }
        double from, to, rate[REPEATS], loads[REPEATS];
        tippe_design_travel_mm(d, &from, &to);
        for (int r = 0; r < REPEATS; r++) {
            double t0 = bench_now_s(), acc = 0;
            for (int i = 0; i < n_top; i++) {
                tippe_top top;
                if (tippe_design_top(d, from + (to - from) * (i % 1000) / 999.0, &top, &err)) {
                    fprintf(stderr, "bench_eval: %s\n", err.msg);
                    return 1;
                }
                acc += top.A / top.C;
            }
            rate[r] = n_top / (bench_now_s() - t0);
            sink += acc;
        }
        tippe_design_free(d);
        for (int r = 0; r < REPEATS; r++) {
            double t0 = bench_now_s();
            for (int i = 0; i < n_load; i++) {
                if (tippe_design_load(designs[k], NULL, 0, &d, &err)) {
                    fprintf(stderr, "bench_eval: %s\n", err.msg);
                    return 1;
                }
                sink += tippe_design_radius_mm(d);
                tippe_design_free(d);
            }
            loads[r] = n_load / (bench_now_s() - t0);
        }
        double m = bench_median(rate, REPEATS);
        printf("%-30s %16.3e %14.1f %12.1f\n", designs[k], m, 1e9 / m,
               bench_median(loads, REPEATS));
    }
    printf("(median of %d repeats; %d evaluations and %d loads per repeat)\n", REPEATS, n_top,
           n_load);
    return sink == 0 ? 1 : 0;
}
