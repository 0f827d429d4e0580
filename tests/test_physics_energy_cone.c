/* The energy cone's decisions against the same launches integrated on to t_end (issue
 * 38): every friction law only takes energy and E >= m g h(theta), so a top decided
 * `no_tip` (or `tip`) by the energy alone must stay within the range it was given for
 * the rest of the run. Checked on the M12 ball with its through hole's rims at four
 * eccentricities, from eps = 0 (the sphere level, only the ring's well) to eps = 2.19 mm,
 * under the patch law (its creep reduced, whose moved energy the margin carries once)
 * and the viscous law, launched upright at several spins and tilts and resting on the
 * far ring. The upright launches' decisions exercise the margin's creep term (the
 * reduced law's energy moved, counted once); the far-ring rests are decided at t = 0.
 * Also: no decision calls a top on one side a verdict of the other. */
#include "check.h"
#include "dynamics_fixtures.h"

#include <math.h>
#include <string.h>

/* The M12 ball with its weight eps from the centre and its through hole's openings. */
static tippe_top m12_rimmed(double eps)
{
    tippe_top t = m12_ball(1.0);
    t.eps = eps;
    t.rim_half_angle_rad[0] = t.rim_half_angle_rad[1] = asin(5.5 / 25.0);
    return t;
}

/* The launch decided, then again to t_end: theta after the decision within the
 * decision's range. Returns 1 if the cone decided it. The rerun takes the same steps up
 * to the decision under the reduced law and the viscous law (the verdict does not touch
 * the integration; the samples fall on the steps); 1e-9 rad is the integrator's error
 * (rtol 1e-9) on a tilt of order 1, the one slack the bound allows. */
static int check_launch(const tippe_dynamics_model *md, const tippe_dynamics_initial *ic,
                        const char *what, int *tips, int *with_creep)
{
    const double t_end = 20.0;
    tippe_dynamics_result r;
    if (run(md, ic, t_end, NULL, &r) != TIPPE_OK) {
        CHECK(0, "%s: the run failed", what);
        return 0;
    }
    if (r.how != TIPPE_DECIDED_ENERGY_CONE)
        return 0;
    CHECK(r.verdict == TIPPE_VERDICT_NO_TIP ? r.theta_hi_rad < 0.25 && ic->theta < M_PI / 2
                                            : r.verdict == TIPPE_VERDICT_TIP &&
                                                  r.theta_lo_rad > M_PI / 2,
          "%s: verdict %d with range [%g, %g] from theta %g", what, r.verdict, r.theta_lo_rad,
          r.theta_hi_rad, ic->theta);
    if (r.verdict == TIPPE_VERDICT_TIP)
        (*tips)++;
    if (r.creep_energy_J > 0.0)
        (*with_creep)++;
    sample_buf b = {0};
    tippe_dynamics_result rr;
    CHECK(run_samples(md, ic, t_end, 0.0, NULL, &b, &rr) == TIPPE_OK, "%s: rerun", what);
    double lo = INFINITY, hi = -INFINITY;
    int after = 0;
    for (int i = 0; i < b.n; i++)
        if (b.s[i].t >= r.t_verdict) {
            lo = fmin(lo, b.s[i].theta);
            hi = fmax(hi, b.s[i].theta);
            after++;
        }
    free(b.s);
    CHECK(after > 10 && lo >= r.theta_lo_rad - 1e-9 && hi <= r.theta_hi_rad + 1e-9,
          "%s: decided at %.3f s in [%.6f, %.6f], then theta in [%.6f, %.6f] (%d samples)",
          what, r.t_verdict, r.theta_lo_rad, r.theta_hi_rad, lo, hi, after);
    return 1;
}

int main(void)
{
    gsl_set_error_handler_off();
    const double eps_m[] = {0.0, 0.146e-3, 0.730e-3, 2.19e-3};
    const double spins_rev_s[] = {2.0, 4.0, 8.0};
    const double tilts_rad[] = {0.03, 0.15};
    int decided = 0, launches = 0, decided_eps0 = 0, tips = 0, with_creep = 0;
    for (int law = 0; law < 2; law++)
        for (int e = 0; e < 4; e++) {
            tippe_top top = m12_rimmed(eps_m[e]);
            tippe_dynamics_model md =
                law == 0 ? friction_model(top, 0.0, TIPPE_FRICTION_PATCH, 0.3, 0.0)
                         : friction_model(top, 2.3, TIPPE_FRICTION_VISCOUS, 0.0, 0.0);
            if (law == 0) {
                md.patch_radius_m = 0.19e-3; /* Hertz's at m g on laminate */
                md.creep_cap = TIPPE_PATCH_CREEP_CAP; /* the reduced law, as launches run it */
            }
            char what[160];
            for (int s = 0; s < 3; s++)
                for (int k = 0; k < 2; k++) {
                    tippe_dynamics_initial ic =
                        steady(&md, tilts_rad[k], 2.0 * M_PI * spins_rev_s[s]);
                    snprintf(what, sizeof what, "%s, eps %.3g mm, %g rev/s, tilt %g",
                             law ? "viscous" : "patch", eps_m[e] * 1e3, spins_rev_s[s],
                             tilts_rad[k]);
                    const int d = check_launch(&md, &ic, what, &tips, &with_creep);
                    decided += d;
                    decided_eps0 += d && eps_m[e] == 0.0;
                    launches++;
                }
            /* at rest on the far ring, nudged: a tip, never a no_tip */
            tippe_dynamics_initial inv = {3.1, 0.0, 0.0, 1.0, 0.0, 0.0};
            snprintf(what, sizeof what, "%s, eps %.3g mm, resting on the far ring",
                     law ? "viscous" : "patch", eps_m[e] * 1e3);
            decided += check_launch(&md, &inv, what, &tips, &with_creep);
            launches++;
        }
    printf("  %d of %d launches decided by the energy cone (%d at eps = 0, %d tips, %d with the "
           "reduction's energy in the margin); each stayed in its range to t_end\n",
           decided, launches, decided_eps0, tips, with_creep);
    /* the check means something only if the cone decided a fair share, eps = 0 and the
     * far ring among them */
    CHECK(decided >= launches / 3 && decided_eps0 >= 2 && tips >= 2 && with_creep >= 4,
          "only %d of %d decided (%d at eps = 0, %d tips, %d with creep energy)", decided,
          launches, decided_eps0, tips, with_creep);
    return check_summary("test_physics_energy_cone");
}
