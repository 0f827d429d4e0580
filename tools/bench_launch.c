/* Launch throughput on 1 and 2 (or more) OpenMP threads: launches per second and
 * parallel efficiency for hand launches of a shipped design, and a check that
 * every thread count gives the same records bit for bit.
 *
 *   build/tools/bench_launch [N [Z2_MM [DESIGN [MAX_THREADS]]]]
 *
 * defaults: 200 launches of designs/m12-setscrew.json at Z2 = 15 mm (a mix of
 * tips and hangs, so launches of very different length), threads 1 and 2.
 * Run from the repository root. Prints the machine's load average too: on a
 * shared machine the efficiency is only as good as the cores that were free. */
#include "tippe/design.h"
#include "bench_util.h"
#include "tippe/launch.h"

#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double load_average(void)
{
    double l = -1;
    FILE *f = fopen("/proc/loadavg", "r");
    if (f) {
        if (fscanf(f, "%lf", &l) != 1)
            l = -1;
        fclose(f);
    }
    return l;
}

int main(int argc, char **argv)
{
    long n = argc > 1 ? atol(argv[1]) : 200;
    double z2 = argc > 2 ? atof(argv[2]) : 15.0;
    const char *path = argc > 3 ? argv[3] : "designs/m12-setscrew.json";
    int max_threads = argc > 4 ? atoi(argv[4]) : 2;
    if (n < 1 || max_threads < 1) {
        fprintf(stderr, "usage: bench_launch [N [Z2_MM [DESIGN [MAX_THREADS]]]]\n");
        return 2;
    }
    tippe_design *d = NULL;
    tippe_error e;
    tippe_top top;
    if (tippe_design_load(path, NULL, 0, &d, &e) || tippe_design_top(d, z2, &top, &e)) {
        fprintf(stderr, "bench_launch: %s\n", e.msg);
        return 2;
    }
    tippe_launch_options o;
    tippe_launch_options_default(&o);
    tippe_launch_plan plan = {1, n, &top, NULL, NULL};
    tippe_launch_record *ref = calloc((size_t)n, sizeof *ref), *rec = calloc((size_t)n, sizeof *rec);
    if (!ref || !rec)
        return 1;

    printf("bench_launch: %ld hand launches of %s at Z2 = %g mm, seed 1, preset %s, t_end %g s\n",
           n, tippe_design_name(d), z2, o.accuracy_name, o.t_end);
    printf("load average before: %.2f (cores online: %d)\n\n", load_average(), omp_get_num_procs());
    printf("threads   wall (s)   launches/s   speed-up   efficiency   same records\n");
    double t1 = 0;
    for (int th = 1; th <= max_threads; th++) {
        omp_set_num_threads(th);
        tippe_launch_record *out = th == 1 ? ref : rec;
        double t0 = bench_now_s();
        if (tippe_launch_run(&plan, &o, 1, 0, n, out, NULL, &e)) {
            fprintf(stderr, "bench_launch: %s\n", e.msg);
            return 1;
        }
        double dt = bench_now_s() - t0;
        if (th == 1)
            t1 = dt;
        int same = 1;
        for (long i = 0; i < n && th > 1; i++)
            same &= ref[i].verdict == rec[i].verdict && ref[i].t_s == rec[i].t_s &&
                    ref[i].theta_final_rad == rec[i].theta_final_rad &&
                    ref[i].rhs_evals == rec[i].rhs_evals;
        printf("%7d   %8.3f   %10.1f   %8.2f   %10.2f   %s\n", th, dt, (double)n / dt, t1 / dt,
               t1 / dt / th, same ? "yes" : "NO");
    }
    tippe_launch_tally t;
    tippe_launch_tally_records(ref, n, &t, &e);
    printf("\noutcomes: no_tip %ld, tip %ld, hang %ld, lost_contact %ld, undecided %ld; "
           "%.3g RHS evaluations\n", t.counts[0], t.counts[1], t.counts[2], t.counts[3],
           t.counts[4], t.rhs_evals);
    printf("load average after: %.2f\n", load_average());
    free(ref);
    free(rec);
    tippe_design_free(d);
    return 0;
}
