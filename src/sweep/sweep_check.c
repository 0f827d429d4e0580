/* One central hand launch at one Z2 beside the zone the sweep puts it in
 * (tippe check), and its report for both front ends (tippe check --json,
 * tippe serve's /api/check); theory beside launches. */
#include "tippe/launch.h"
#include "base/json.h"
#include "tippe/sweep.h"

#include <cjson/cJSON.h>

#include <math.h>
#include <string.h>

static void number_or_null(cJSON *o, const char *key, double v)
{
    if (isfinite(v))
        cJSON_AddNumberToObject(o, key, v);
    else
        cJSON_AddNullToObject(o, key);
}

/* "set": the overrides the report reflects (an empty array without any). */
static void add_sets(cJSON *o, const char *const *sets, int n)
{
    cJSON *a = cJSON_AddArrayToObject(o, "set");
    for (int i = 0; a && i < n; i++)
        cJSON_AddItemToArray(a, cJSON_CreateString(sets[i]));
}

void tippe_sweep_zone_at(const tippe_design *d, double z2, tippe_sweep_point_zone *z)
{
    memset(z, 0, sizeof *z);
    tippe_sweep_result r;
    tippe_error e;
    if (tippe_sweep_design(d, 0.0, 0.0, NULL, &r, &e) == TIPPE_OK)
        for (int i = 0; i < r.n_zones; i++)
            if (z2 >= r.zones[i].z2_from_mm && z2 <= r.zones[i].z2_to_mm) {
                z->ok = 1;
                z->group = r.zones[i].group;
                z->from_mm = r.zones[i].z2_from_mm;
                z->to_mm = r.zones[i].z2_to_mm;
                break;
            }
    tippe_sweep_result_free(&r);
}

cJSON *tippe_sweep_theory_json(const tippe_top *t, double g, const tippe_sweep_point_zone *z,
                               const tippe_launch_tally *tl)
{
    cJSON *o = cJSON_CreateObject();
    if (!o)
        return NULL;
    tippe_theory_class cls;
    tippe_theory_classify(t->A / t->C, t->eps / t->R, &cls);
    cJSON_AddStringToObject(o, "group", tippe_group_family(cls.group));
    cJSON_AddStringToObject(o, "subgroup", tippe_group_name(cls.group));
    cJSON_AddNumberToObject(o, "A_over_C", t->A / t->C);
    cJSON_AddNumberToObject(o, "eps_over_R", t->eps / t->R);
    if (z->ok) {
        double b[2] = {z->from_mm, z->to_mm};
        cJSON_AddItemToObject(o, "zone_mm", cJSON_CreateDoubleArray(b, 2));
    } else {
        cJSON_AddNullToObject(o, "zone_mm");
    }
    tippe_theory_thresholds th;
    tippe_error e;
    if (tippe_theory_compute_thresholds(t, g, &th, &e) == TIPPE_OK) {
        if (th.has_n_minus)
            cJSON_AddNumberToObject(o, "n_minus_rad_s", th.n_minus_rad_s);
        else
            cJSON_AddNullToObject(o, "n_minus_rad_s");
        if (th.has_n_star)
            cJSON_AddNumberToObject(o, "n_star_rad_s", th.n_star_rad_s);
        else
            cJSON_AddNullToObject(o, "n_star_rad_s");
    }
    if (tl) {
        cJSON *p = cJSON_AddObjectToObject(o, "predicted");
        for (unsigned m = 0; p && m < 8; m++)
            if (tl->predicted[m])
                cJSON_AddNumberToObject(p, tippe_launch_predicted_name(m), (double)tl->predicted[m]);
        cJSON_AddNumberToObject(o, "agree", (double)tl->agree);
        cJSON_AddNumberToObject(o, "comparable", (double)tl->comparable);
        double lo, hi;
        tippe_launch_wilson(tl->agree, tl->comparable, TIPPE_LAUNCH_Z95, &lo, &hi);
        if (tl->comparable)
            cJSON_AddNumberToObject(o, "agreement", (double)tl->agree / (double)tl->comparable);
        else
            cJSON_AddNullToObject(o, "agreement");
        double b[2] = {lo, hi};
        cJSON_AddItemToObject(o, "agreement_ci95", cJSON_CreateDoubleArray(b, 2));
        cJSON_AddNumberToObject(o, "hang_tolerance_rad", TIPPE_LAUNCH_HANG_AGREE_RAD);
    }
    return o;
}

int tippe_sweep_check_run(const tippe_design *d, double z2_mm, const tippe_launch_options *o,
                          double spin_rad_s, tippe_sweep_check *out, tippe_error *err)
{
    memset(out, 0, sizeof *out);
    out->d = d;
    out->z2_mm = z2_mm;
    int rc;
    if ((rc = tippe_design_top(d, z2_mm, &out->top, err)) != 0)
        return tippe_error_blame(err, "z2_mm"); /* no top at this Z2 */
    /* the run records its time on a hole's rim at a pole (issue 25.7) */
    tippe_launch_options oc = *o;
    tippe_launch_polar_caps(d, z2_mm, &out->top, oc.cap_half_angle_rad);
    if ((rc = tippe_launch_central(&out->top, &oc, spin_rad_s, &out->ic, err)) != 0 ||
        (rc = tippe_launch_run_initial(&out->top, &oc, &out->ic, &out->rec, err)) != 0)
        return rc;
    tippe_sweep_zone_at(d, z2_mm, &out->zone);
    return TIPPE_OK;
}

static cJSON *theory_json(const tippe_sweep_check *r, const tippe_launch_options *o)
{
    cJSON *th = tippe_sweep_theory_json(&r->top, o->g, &r->zone, NULL);
    if (!th)
        return NULL;
    if (r->rec.theory_ok) {
        cJSON_AddStringToObject(th, "prediction", tippe_launch_predicted_name(r->rec.predicted));
        if (isfinite(r->rec.hang_theta_rad))
            cJSON_AddNumberToObject(th, "hang_theta_rad", r->rec.hang_theta_rad);
    } else {
        cJSON_AddNullToObject(th, "prediction");
    }
    if (r->rec.agrees < 0)
        cJSON_AddNullToObject(th, "agrees");
    else
        cJSON_AddBoolToObject(th, "agrees", r->rec.agrees);
    return th;
}

/* How the verdict was reached (docs/dynamics.md, "Proved verdicts"). */
/* How the verdict was reached, with null where a field does not apply. */
static void add_decision_json(cJSON *o, const tippe_launch_record *rec)
{
    cJSON_AddStringToObject(o, "decided_by", tippe_decision_name(rec->how));
    number_or_null(o, "margin_J", rec->margin_J);
    number_or_null(o, "barrier_gap_J", rec->barrier_gap_J);
    tippe_json_add_range(o, "theta_range_rad", rec->theta_lo_rad, rec->theta_hi_rad);
    number_or_null(o, "Rn_bound_N", rec->Rn_bound_N);
    number_or_null(o, "t_flip_s", rec->t_flip_s);
    number_or_null(o, "t_fall_s", rec->t_fall_s);
    number_or_null(o, "inverted_time_s", rec->inverted_time_s);
}

int tippe_sweep_check_laws(const tippe_design *d, double z2_mm, const tippe_launch_options *o,
                           int n, double spin_rad_s, tippe_sweep_check_law *out, tippe_error *err)
{
    memset(out, 0, (size_t)n * sizeof *out);
    for (int i = 0; i < n; i++) {
        tippe_sweep_check_law *l = &out[i];
        l->o = o[i];
        int rc = tippe_sweep_check_run(d, z2_mm, &o[i], spin_rad_s, &l->check, err);
        tippe_dynamics_model m;
        tippe_launch_friction_model(&o[i], &m);
        m.top = l->check.top; /* the patch law's Hertz radius needs its m g and R */
        tippe_dynamics_friction_text(&m, l->friction, sizeof l->friction);
        if (!rc)
            rc = tippe_launch_trajectory(&l->check.top, &o[i], &l->check.ic, 0.0, &l->samples,
                                         &l->run, err);
        if (rc) {
            char msg[sizeof err->msg];
            snprintf(msg, sizeof msg, "%s", err->msg);
            return tippe_error_set(err, rc, "under %s friction: %s",
                                   tippe_friction_law_name(o[i].law), msg);
        }
    }
    return TIPPE_OK;
}

void tippe_sweep_check_laws_free(tippe_sweep_check_law *l, int n)
{
    for (int i = 0; i < n; i++)
        tippe_dynamics_samples_free(&l[i].samples);
}

double tippe_sweep_check_law_energy_lost(const tippe_sweep_check_law *l)
{
    /* D, the integral of the dissipation (eq 4.1), over E0 (section 4) */
    return l->run.E0 > 0 ? l->run.last.D / l->run.E0 : NAN;
}

cJSON *tippe_sweep_check_laws_json(const tippe_sweep_check_law *l, int n,
                                   const char *const *sets, int n_sets)
{
    if (n < 1)
        return NULL;
    /* the first law's report gives the design, the launch and theory: the
     * launch (and with it J0) does not depend on the law */
    cJSON *o = tippe_sweep_check_json(&l[0].check, &l[0].o, sets, n_sets);
    if (!o)
        return NULL;
    static const char *const per_law[] = {
        "verdict", "model_valid", "on_polar_cap", "t_s", "decided_by", "margin_J",
        "barrier_gap_J", "theta_range_rad", "Rn_bound_N", "t_flip_s", "theta_final_rad",
        "spin_final_rad_s", "jellett_rel_drift", "jellett_drift_time_s", "options"};
    for (size_t k = 0; k < sizeof per_law / sizeof per_law[0]; k++)
        if (strcmp(per_law[k], "model_valid") != 0) /* the design's at Z2: kept */
            cJSON_DeleteItemFromObjectCaseSensitive(o, per_law[k]);
    cJSON *th = cJSON_GetObjectItemCaseSensitive(o, "theory");
    if (th) /* agreement is per law */
        cJSON_DeleteItemFromObjectCaseSensitive(th, "agrees");
    cJSON *arr = cJSON_AddArrayToObject(o, "laws");
    for (int i = 0; arr && i < n; i++) {
        const tippe_sweep_check_law *x = &l[i];
        const tippe_launch_record *rec = &x->check.rec;
        cJSON *j = cJSON_CreateObject();
        if (!j || !cJSON_AddItemToArray(arr, j)) {
            cJSON_Delete(j);
            break;
        }
        tippe_dynamics_model m;
        tippe_launch_friction_model(&x->o, &m);
        tippe_dynamics_friction_json(j, &m);
        cJSON_DeleteItemFromObjectCaseSensitive(j, "mu_s_m"); /* in "friction" */
        cJSON_AddStringToObject(j, "friction_text", x->friction);
        cJSON_AddStringToObject(j, "verdict", tippe_verdict_name(rec->verdict));
        cJSON_AddNumberToObject(j, "t_s", rec->t_s);
        add_decision_json(j, rec);
        number_or_null(j, "theta_final_rad", rec->theta_final_rad);
        number_or_null(j, "spin_final_rad_s", rec->spin_final_rad_s);
        if (rec->agrees < 0)
            cJSON_AddNullToObject(j, "agrees");
        else
            cJSON_AddBoolToObject(j, "agrees", rec->agrees);
        /* the trajectory to t_end: when theta first passed and came back below
         * pi/2, where and with what energy the run ended */
        cJSON *r = cJSON_AddObjectToObject(j, "run");
        if (r) {
            number_or_null(r, "t_flip_s", x->run.t_flip);
            number_or_null(r, "t_fall_s", x->run.t_fall);
            cJSON_AddNumberToObject(r, "t_end_s", x->run.last.t);
            cJSON_AddNumberToObject(r, "theta_end_rad", x->run.last.theta);
            cJSON_AddNumberToObject(r, "E0_J", x->run.E0);
            cJSON_AddNumberToObject(r, "E_end_J", x->run.last.E);
            cJSON_AddNumberToObject(r, "dissipated_J", x->run.last.D);
            number_or_null(r, "energy_lost", tippe_sweep_check_law_energy_lost(x));
            cJSON_AddNumberToObject(r, "energy_rel_error", x->run.energy_rel_error);
            cJSON_AddNumberToObject(r, "samples", x->samples.n);
        }
        cJSON_AddItemToObject(j, "options", tippe_launch_options_json(&x->o, 1));
    }
    return o;
}

cJSON *tippe_sweep_check_json(const tippe_sweep_check *r, const tippe_launch_options *opt,
                              const char *const *sets, int n_sets)
{
    const tippe_dynamics_initial *ic = &r->ic;
    const tippe_launch_record *rec = &r->rec;
    cJSON *o = cJSON_CreateObject();
    if (o) {
        cJSON_AddStringToObject(o, "design", tippe_design_name(r->d));
        cJSON_AddStringToObject(o, "file", tippe_design_path(r->d));
        add_sets(o, sets, n_sets);
        cJSON_AddNumberToObject(o, "z2_mm", r->z2_mm);
        cJSON *ini = cJSON_AddObjectToObject(o, "initial");
        if (ini) {
            cJSON_AddNumberToObject(ini, "theta_rad", ic->theta);
            cJSON_AddNumberToObject(ini, "phi_dot_rad_s", ic->phi_dot);
            cJSON_AddStringToObject(ini, "phi_dot_rule", "steady");
            cJSON_AddNumberToObject(ini, "spin_rad_s", ic->spin);
            cJSON_AddNumberToObject(ini, "U_m_s", ic->U);
            cJSON_AddNumberToObject(ini, "V_m_s", ic->V);
            /* |v + omega x q| at launch (eq 3.7): the central launch's centre is at
             * rest, its contact point is not */
            cJSON_AddNumberToObject(ini, "contact_slip_m_s",
                                    tippe_dynamics_launch_slip(&r->top, ic));
        }
        cJSON_AddStringToObject(o, "verdict", tippe_verdict_name(rec->verdict));
        tippe_design_protrusion pr;
        tippe_design_protrusion_at(r->d, r->z2_mm, &pr);
        tippe_design_protrusion_json(o, &pr);
        /* a launch that starts or ends within a hole's opening at a pole stands on
         * its rim there, not on the sphere the model rolls (issue 25.7) */
        tippe_design_cap caps[2];
        tippe_design_polar_caps(r->d, r->z2_mm, caps);
        int side = r->top.com_side ? r->top.com_side : 1;
        int at_start = tippe_design_cap_at_tilt(caps, side, ic->theta);
        int at_end = isfinite(rec->theta_final_rad)
                         ? tippe_design_cap_at_tilt(caps, side, rec->theta_final_rad)
                         : 0;
        cJSON *oc = cJSON_AddObjectToObject(o, "on_polar_cap");
        if (oc) {
            cJSON_AddNumberToObject(oc, "time_s", rec->cap_time_s);
            number_or_null(oc, "first_s", rec->cap_first_s);
            if (at_start)
                cJSON_AddStringToObject(oc, "start", at_start > 0 ? "+z" : "-z");
            else
                cJSON_AddNullToObject(oc, "start");
            if (at_end)
                cJSON_AddStringToObject(oc, "end", at_end > 0 ? "+z" : "-z");
            else
                cJSON_AddNullToObject(oc, "end");
        }
        cJSON_AddNumberToObject(o, "t_s", rec->t_s);
        add_decision_json(o, rec);
        number_or_null(o, "theta_final_rad", rec->theta_final_rad);
        number_or_null(o, "spin_final_rad_s", rec->spin_final_rad_s);
        cJSON_AddNumberToObject(o, "J0_kg_m3_s", rec->J0);
        cJSON_AddNumberToObject(o, "jellett_rel_drift", rec->jellett_rel_drift);
        number_or_null(o, "jellett_drift_time_s", rec->jellett_drift_time_s);
        number_or_null(o, "energy_rel_error", rec->energy_rel_error);
        number_or_null(o, "creep_energy_rel", rec->creep_energy_rel);
        cJSON_AddItemToObject(o, "options", tippe_launch_options_json(opt, 1));
        if (tippe_friction_law_type_of(opt->law)->patch) /* the radius at m g this top's run started from */
            cJSON_AddNumberToObject(o, "patch_radius_mm", 1e3 * tippe_launch_patch_radius(&r->top, opt));
        cJSON_AddItemToObject(o, "theory", theory_json(r, opt));
    }
    return o;
}

