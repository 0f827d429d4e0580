/* Trajectory samples in memory and as CSV: what tippe simulate and tippe check write
 * with --csv and draw with --plot (tippe_plot_sim). */
#include "tippe/physics.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

int tippe_dynamics_samples_keep(const tippe_dynamics_sample *s, void *ctx)
{
    tippe_dynamics_samples *b = ctx;
    if (b->n == b->cap) {
        int cap = b->cap ? 2 * b->cap : 1024;
        tippe_dynamics_sample *p = realloc(b->s, (size_t)cap * sizeof *p);
        if (!p)
            return 1;
        b->s = p;
        b->cap = cap;
    }
    b->s[b->n++] = *s;
    return 0;
}

void tippe_dynamics_samples_free(tippe_dynamics_samples *b)
{
    if (!b)
        return;
    free(b->s);
    b->s = NULL;
    b->n = b->cap = 0;
}

double tippe_dynamics_default_sample_dt(const tippe_dynamics_initial *ic, double g,
                                        double R_m, double t_end)
{
    double w = sqrt(ic->theta_dot * ic->theta_dot + ic->spin * ic->spin +
                    pow(ic->phi_dot * sin(ic->theta), 2)) +
               sqrt(g / R_m);
    return fmax(t_end * 1e-5, fmin(t_end * 1e-4, 2 * M_PI / (16 * w)));
}

void tippe_dynamics_write_csv(FILE *out, const tippe_dynamics_sample *s, int n)
{
    fprintf(out, "t_s,theta_rad,theta_dot_rad_s,phi_dot_rad_s,spin_rad_s,U_m_s,V_m_s,Rn_N,"
                 "slip_speed_m_s,E_J,J_kg_m3_s,dissipated_J,phi_rad,psi_rad,x_m,y_m,patch_radius_m,"
                 "drill_torque_N_m\n");
    for (int i = 0; i < n; i++, s++)
        fprintf(out, "%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,"
                     "%.10g,%.10g,%.10g,%.10g,%.10g,%.10g\n",
                s->t, s->theta, s->theta_dot, s->phi_dot, s->spin, s->U, s->V, s->Rn,
                s->slip_speed, s->E, s->J, s->D, s->phi, s->psi, s->x, s->y, s->patch_radius,
                s->drill_torque);
}
