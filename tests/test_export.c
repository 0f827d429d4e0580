/* Export's library side: profiles and meshes of every shipped design against
 * the mass model's own volumes, the chord rule, and the checks that warn. */
#include "check.h"

#include "tippe/design.h"
#include "export/mesh.h"
#include "tippe/profile.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static const char *const designs[] = {"designs/m12-setscrew.json", "designs/m3-setscrew.json",
                                      "designs/shell-rod-iron.json",
                                      "designs/shell-rod-nylon.json", "designs/shell-band.json",
                                      "designs/shell-band-best.json",
                                      "designs/shell-rod-through.json",
                                      "designs/drilled-ball-blind.json",
                                      NULL};

/* Volume of the printed parts less their voids as the mass model has it:
 * the parts' masses over their densities (mm^3). */
static double mass_model_volume_mm3(const tippe_design *d)
{
    double v = 0;
    for (int i = 0; i < tippe_design_n_parts(d); i++) {
        tippe_design_part_info p;
        tippe_design_solid s;
        tippe_design_part(d, i, &p);
        tippe_design_part_solid(d, i, &s);
        int printed = tippe_profile_part_printed(d, i) ||
                      (s.is_void && tippe_profile_part_printed(d, s.parent));
        if (printed)
            v += p.mass_kg / (p.density_g_cm3 * 1e3) * 1e9; /* voids' masses are negative */
    }
    return v;
}

static double mesh_area_mm2(const tippe_mesh *m)
{
    double a = 0;
    for (long t = 0; t < m->n_triangles; t++) {
        const double *p = &m->xyz[3 * m->tri[3 * t]], *q = &m->xyz[3 * m->tri[3 * t + 1]],
                     *r = &m->xyz[3 * m->tri[3 * t + 2]];
        double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]},
               w[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
        a += 0.5 * hypot(hypot(u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2]),
                         u[0] * w[1] - u[1] * w[0]);
    }
    return a;
}

static void check_design(const char *path)
{
    tippe_design *d = NULL;
    tippe_error err = {0};
    if (tippe_design_load(path, NULL, 0, &d, &err)) {
        CHECK(0, "%s", err.msg);
        return;
    }
    tippe_profile_options o = tippe_profile_defaults();
    tippe_profile_set s;
    int rc = tippe_profile_build(d, &o, &s, &err);
    CHECK(rc == 0, "%s: %s", path, err.msg);
    if (rc) {
        tippe_design_free(d);
        return;
    }
    double total = 0;
    for (int b = 0; b < s.n_bodies; b++) {
        const tippe_profile_body *body = &s.body[b];
        int n = tippe_profile_angle_steps(body->r_max_mm, o.chord_mm / 2);
        /* the angular chord rule: sagitta of the widest circle within half the chord */
        CHECK(n % 4 == 0 && body->r_max_mm * (1 - cos(M_PI / n)) <= o.chord_mm / 2,
              "%s: %d steps for r = %g", path, n, body->r_max_mm);
        tippe_mesh m;
        tippe_mesh_audit a;
        CHECK(tippe_mesh_revolve(body, n, &m, &err) == 0, "%s", err.msg);
        CHECK(tippe_mesh_check(&m, &a, &err) == 0, "%s", err.msg);
        CHECK(a.open_edges == 0 && a.nonmanifold_edges == 0 && a.flipped_edges == 0 &&
                  a.degenerate_triangles == 0,
              "%s body %s: %ld open, %ld non-manifold, %ld flipped, %ld degenerate", path,
              body->name, a.open_edges, a.nonmanifold_edges, a.flipped_edges,
              a.degenerate_triangles);
        double v = tippe_mesh_volume_mm3(&m);
        /* Every facet is within the chord of the true surface, so mesh and body
         * differ by at most a layer that thick over the surface: |dV| <= chord x
         * area (the mesh's area, the true one's to O(chord / r); the error is
         * 0.17 .. 0.47 of the bound on the shipped designs). */
        double area = mesh_area_mm2(&m);
        CHECK(fabs(v - body->exact_volume_mm3) <= o.chord_mm * area,
              "%s body %s: mesh %.6g vs exact %.6g mm^3, beyond chord x area %.6g mm^3", path,
              body->name, v, body->exact_volume_mm3, o.chord_mm * area);
        /* The mesh's polygons are inscribed in the profile's circles: revolving
         * loses the factor sin(2 pi/n)/(2 pi/n) of the profile's volume, to 1e-12. */
        double k = sin(2 * M_PI / n) / (2 * M_PI / n);
        CHECK_CLOSE(v, k * body->polygon_volume_mm3, 1e-12, "%s body %s: mesh vs Pappus", path,
                    body->name);
        total += body->exact_volume_mm3;
        tippe_mesh_free(&m);
    }
    /* With no clearance the exported volume is the mass model's: two independent
     * sums (geometry closed forms in profile.c, part masses in design.c). */
    tippe_profile_options o0 = o;
    o0.clearance_mm = 0;
    tippe_profile_set s0;
    if (tippe_profile_build(d, &o0, &s0, &err) == 0) {
        double v0 = 0;
        for (int b = 0; b < s0.n_bodies; b++)
            v0 += s0.body[b].exact_volume_mm3;
        CHECK_CLOSE(v0, mass_model_volume_mm3(d), 1e-12, "%s: printed volume vs mass model",
                    path);
        tippe_profile_set_free(&s0);
    }
    CHECK(total > 0, "%s", path);
    tippe_profile_set_free(&s);
    tippe_design_free(d);
}

/* Halving the chord halves the volume error (order 1 in the chord). */
static void check_convergence(void)
{
    tippe_design *d = NULL;
    tippe_error err = {0};
    if (tippe_design_load("designs/shell-band.json", NULL, 0, &d, &err)) {
        CHECK(0, "%s", err.msg);
        return;
    }
    double e[3];
    const double chord[3] = {0.04, 0.02, 0.01};
    for (int k = 0; k < 3; k++) {
        tippe_profile_options o = tippe_profile_defaults();
        o.chord_mm = chord[k];
        tippe_profile_set s;
        tippe_mesh m;
        tippe_profile_build(d, &o, &s, &err);
        int n = tippe_profile_angle_steps(s.body[0].r_max_mm, o.chord_mm / 2);
        tippe_mesh_revolve(&s.body[0], n, &m, &err);
        e[k] = fabs(tippe_mesh_volume_mm3(&m) / s.body[0].exact_volume_mm3 - 1);
        tippe_mesh_free(&m);
        tippe_profile_set_free(&s);
    }
    for (int k = 0; k < 2; k++) {
        double order = log2(e[k] / e[k + 1]);
        /* ceil() of the step counts moves each ratio a few %: 0.8 .. 1.2 */
        CHECK(order > 0.8 && order < 1.2, "order %g between chords %g and %g", order, chord[k],
              chord[k + 1]);
    }
    tippe_design_free(d);
}

static void check_warnings_and_clearance(void)
{
    tippe_error err = {0};
    tippe_design *d = NULL;
    const char *thin[] = {"parts.shell.thickness_mm=0.5"};
    if (tippe_design_load("designs/shell-rod-iron.json", thin, 1, &d, &err) == 0) {
        tippe_profile_options o = tippe_profile_defaults();
        tippe_profile_set s;
        CHECK(tippe_profile_build(d, &o, &s, &err) == 0, "%s", err.msg);
        /* the wall is 0.5 mm: the estimate (area over length) is close to it */
        CHECK(fabs(s.thinnest_wall_mm - 0.5) < 0.05, "thin wall %g mm", s.thinnest_wall_mm);
        tippe_profile_set_free(&s);
        tippe_design_free(d);
    }
    if (tippe_design_load("designs/m12-setscrew.json", NULL, 0, &d, &err) == 0) {
        tippe_profile_options o = tippe_profile_defaults();
        tippe_profile_set s;
        CHECK(tippe_profile_build(d, &o, &s, &err) == 0, "%s", err.msg);
        CHECK(s.clearance_applied[1] == 1 && s.clearance_applied[0] == 0,
              "the hole (part 1) takes the screw: clearance");
        CHECK(isnan(s.thinnest_wall_mm) && s.n_warnings == 0, "m12: %d warnings", s.n_warnings);
        tippe_profile_set_free(&s);
        o.chord_mm = 0;
        CHECK(tippe_profile_build(d, &o, &s, &err) == TIPPE_EINPUT, "chord 0 refused");
        o = tippe_profile_defaults();
        o.split = 1;
        o.split_z_mm = 30;
        CHECK(tippe_profile_build(d, &o, &s, &err) == TIPPE_EINPUT, "split plane outside");
        tippe_design_free(d);
    }
}

int main(void)
{
    for (int k = 0; designs[k]; k++)
        check_design(designs[k]);
    check_convergence();
    check_warnings_and_clearance();
    return check_summary("test_export");
}
