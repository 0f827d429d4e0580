/* The words and JSON fields that say how a dynamics verdict was reached, shared by
 * simulate, check and launch (docs/dynamics.md, "Proved verdicts"). */
#include "cli.h"
#include "base/json.h"

#include <cjson/cJSON.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

void tippe_cli_print_verdict_proof(const tippe_dynamics_result *r, const char *prefix)
{
    const double th = r->theta_final_rad;
    if (r->how == TIPPE_DECIDED_OBSERVED) {
        printf("%s%s (observed, NOT proved): theta %.6g rad (%.2f deg), spin %.6g rad/s at "
               "t = %.6g s\n",
               prefix, tippe_verdict_name(r->verdict), th, th * 180 / M_PI, r->spin_final_rad_s,
               r->t_verdict);
        printf("%*s%s\n", (int)strlen(prefix), "",
               r->unproved_reason ? r->unproved_reason : "not proved");
        if (isfinite(r->jellett_drift_time_s))
            printf("%*sJ moved by up to %.3g %% of J0 in the run; drilling at m g can move it by "
                   "all of J0 in %.3g s (|dJ/dt| <= (3 pi/16) mu_c m g a (R + eps))\n",
                   (int)strlen(prefix), "", 100 * r->jellett_rel_drift, r->jellett_drift_time_s);
        return;
    }
    if (r->how == TIPPE_DECIDED_ENERGY_CONE) {
        if (r->verdict == TIPPE_VERDICT_TIP) /* the well of a flat end (a cut far pole) */
            printf("%s%s: stays above %.4g rad (%.2f deg), within its flat end's well, for ever "
                   "(now %.4g rad)\n",
                   prefix, tippe_verdict_name(r->verdict), r->theta_lo_rad,
                   r->theta_lo_rad * 180 / M_PI, th);
        else
            printf("%s%s: stays within %.4g rad (%.2f deg) of upright for ever (now %.4g rad)\n",
                   prefix, tippe_verdict_name(r->verdict), r->theta_hi_rad,
                   r->theta_hi_rad * 180 / M_PI, th);
        printf("%*sproved at t = %.6g s (energy_cone): the energy, margin %.3g J included, is "
               "below the centre of mass's height there and only falls under friction; the "
               "rest state within is not proved (J drifts)\n",
               (int)strlen(prefix), "", r->t_verdict, r->margin_J);
        return;
    }
    if (r->how == TIPPE_DECIDED_ROLLING) {
        printf("%s%s: rolls without slipping for ever (nothing dissipates), theta in [%.6g, "
               "%.6g] rad ([%.2f, %.2f] deg)\n",
               prefix, tippe_verdict_name(r->verdict), r->theta_lo_rad, r->theta_hi_rad,
               r->theta_lo_rad * 180 / M_PI, r->theta_hi_rad * 180 / M_PI);
        printf("%*sproved at t = %.6g s (rolling): over one whole nutation period the force "
               "rolling needs stayed inside the friction cone (the motion repeats); Rn >= %.4g "
               "N\n",
               (int)strlen(prefix), "", r->t_verdict, r->Rn_bound_N);
        return;
    }
    if (r->verdict == TIPPE_VERDICT_BOUNDED) {
        printf("%sbounded (no rest state is forced: no friction or eps = 0): theta stays for "
               "ever in [%.6g, %.6g] rad ([%.2f, %.2f] deg)\n",
               prefix, r->theta_lo_rad, r->theta_hi_rad, r->theta_lo_rad * 180 / M_PI,
               r->theta_hi_rad * 180 / M_PI);
    } else if (r->how == TIPPE_DECIDED_FLAT_WELL) {
        printf("%sundecided (flat_well): confined to theta in [%.6g, %.6g] rad, a well whose "
               "steady states lie closer in energy than the margin; theory's minimum %.10f rad\n",
               prefix, r->theta_lo_rad, r->theta_hi_rad, th);
        printf("%*sstopped at t = %.6g s: margin %.3g J (never smaller later; a smaller rtol "
               "may decide)\n",
               (int)strlen(prefix), "", r->t_verdict, r->margin_J);
        return;
    } else if (!r->end_state_proved) {
        printf("%s%s: stays in the well of theta %.10f rad (%.4f deg), the rest state it "
               "reaches if it keeps sliding (rolling without slipping dissipates nothing and "
               "can last anywhere in the range below)\n",
               prefix, tippe_verdict_name(r->verdict), th, th * 180 / M_PI);
    } else {
        printf("%s%s: ends at theta %.10f rad (%.4f deg), spin %.6g rad/s, phi_dot %.6g rad/s\n",
               prefix, tippe_verdict_name(r->verdict), th, th * 180 / M_PI, r->spin_final_rad_s,
               r->phi_dot_final_rad_s);
    }
    printf("%*sproved at t = %.6g s (trapped): ", (int)strlen(prefix), "", r->t_verdict);
    if (r->verdict == TIPPE_VERDICT_BOUNDED)
        printf("energy below the well's escape level"); /* E never rises */
    else if (isinf(r->barrier_gap_J))
        printf("the well has no barrier (no interior maximum of V)");
    else
        printf("energy %.3g J below the well's barrier", r->barrier_gap_J);
    printf(", margin %.3g J; Rn >= %.4g N while theta in [%.6g, %.6g] rad\n", r->margin_J,
           r->Rn_bound_N, r->theta_lo_rad, r->theta_hi_rad);
}

void tippe_cli_json_number_or_null(cJSON *o, const char *key, double v)
{
    if (isfinite(v))
        cJSON_AddNumberToObject(o, key, v);
    else
        cJSON_AddNullToObject(o, key);
}

void tippe_cli_json_verdict_proof(cJSON *o, const tippe_dynamics_result *r)
{
    cJSON_AddStringToObject(o, "decided_by", tippe_decision_name(r->how));
    tippe_cli_json_number_or_null(o, "decision_t_s", r->t_verdict);
    tippe_cli_json_number_or_null(o, "theta_final_rad", r->theta_final_rad);
    tippe_cli_json_number_or_null(o, "spin_final_rad_s", r->spin_final_rad_s);
    tippe_cli_json_number_or_null(o, "phi_dot_final_rad_s", r->phi_dot_final_rad_s);
    if (r->how == TIPPE_DECIDED_TRAPPED || r->how == TIPPE_DECIDED_ROLLING)
        tippe_json_add_range(o, "theta_range_rad", r->theta_lo_rad, r->theta_hi_rad);
    else
        cJSON_AddNullToObject(o, "theta_range_rad");
    /* an infinite gap (a single well) is null, with barrier false */
    tippe_cli_json_number_or_null(o, "barrier_gap_J", r->barrier_gap_J);
    tippe_cli_json_number_or_null(o, "margin_J", r->margin_J);
    tippe_cli_json_number_or_null(o, "Rn_bound_N", r->Rn_bound_N);
    tippe_cli_json_number_or_null(o, "t_flip_s", r->t_flip);
    tippe_cli_json_number_or_null(o, "t_fall_s", r->t_fall);
    cJSON_AddNumberToObject(o, "inverted_time_s", r->inverted_time_s);
    cJSON_AddBoolToObject(o, "rolling", r->rolling);
    cJSON_AddBoolToObject(o, "end_state_proved", r->end_state_proved);
    if (r->unproved_reason)
        cJSON_AddStringToObject(o, "unproved_reason", r->unproved_reason);
    else
        cJSON_AddNullToObject(o, "unproved_reason");
    tippe_cli_json_number_or_null(o, "jellett_drift_time_s", r->jellett_drift_time_s);
    cJSON_AddNumberToObject(o, "stick_events", (double)r->stick_events);
    cJSON_AddNumberToObject(o, "slip_events", (double)r->slip_events);
    cJSON_AddNumberToObject(o, "rolling_time_s", r->rolling_time_s);
}

int tippe_cli_fprint_model_validity(FILE *out, const tippe_design_protrusion *p, double z2_mm,
                                    const char *prefix, const char *what)
{
    if (!(p->protrusion_mm > 0))
        return 0;
    char text[512];
    tippe_design_protrusion_text(p, text, sizeof text);
    fprintf(out,
            "%sINVALID at Z2 = %g mm: %s; the model lets the top touch the table with its "
            "sphere only, so %s no prediction\n",
            prefix, z2_mm, text, what);
    return 1;
}

int tippe_cli_print_model_validity(const tippe_design_protrusion *p, double z2_mm,
                                   const char *prefix, const char *what)
{
    return tippe_cli_fprint_model_validity(stdout, p, z2_mm, prefix, what);
}
