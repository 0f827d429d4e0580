/* What tippe launch, map and check share (see hands.h): their options, and the
 * words and JSON in which they describe the top, the launches and theory. */
#include "hands.h"

#include "tippe/sweep.h"
#include "tippe/launch.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <string.h>

const char *const hands_verdict_names[TIPPE_LAUNCH_N_VERDICTS] = {
    "no_tip", "tip", "hang", "lost_contact", "undecided", "bounded"};

enum { MAX_HAND_OPTS = 48 };

/* The options every hand-launch verb reads: the model and the integrator. */
static int model_options(hands_args *a, tippe_cli_opt *t)
{
    tippe_launch_options *o = &a->o;
    tippe_cli_opt m[] = {
        {.name = "tilt", .kind = TIPPE_CLI_DOUBLE, .value = &o->tilt_sd_rad, .arg = "SD",
         .unit = "rad", .min = 0, .max = 0.7, .def = "0.1, or --tilt-max/2 if less",
         .help = "tilt at launch: half-normal with scale SD, at most --tilt-max/2"},
        /* with --tilt in every verb that has it: SD <= MAX / 2 (see tilt_defaults) */
        {.name = "tilt-max", .kind = TIPPE_CLI_DOUBLE, .value = &o->tilt_max_rad, .arg = "MAX",
         .unit = "rad", .min = 1e-3, .max = 1.4, .def = "1, or 2 x --tilt if more",
         .help = "largest tilt at launch: larger draws are drawn again"},
        {.name = "g", .kind = TIPPE_CLI_DOUBLE, .value = &o->g, .unit = "m/s^2", .min = 0.01,
         .max = 1000, .def = "9.81", .help = "gravity"},
        {.name = "t-end", .kind = TIPPE_CLI_DOUBLE, .value = &o->t_end, .unit = "s",
         .min = 1e-3, .max = 1e6, .def = "600", .help = "longest simulated time of one launch"},
        {.name = "accuracy", .kind = TIPPE_CLI_STRING, .value = &a->accuracy, .arg = "PRESET",
         .def = "balanced", .help = "integrator preset: fast, balanced or precise"},
        {.name = "stepper", .kind = TIPPE_CLI_STRING, .value = &a->stepper, .arg = "NAME",
         .help = "a GSL stepper instead of the preset's: rk2, rk4, rkf45, rkck, rk8pd,\n"
                 "rk1imp, rk2imp, rk4imp, bsimp, msadams, msbdf"},
        {.name = "rtol", .kind = TIPPE_CLI_DOUBLE, .value = &o->accuracy.rtol, .min = 1e-14,
         .max = 1e-2, .help = "relative tolerance instead of the preset's"},
        {.name = "set", .kind = TIPPE_CLI_SET, .value = &a->sets, .arg = "FIELD=VALUE",
         .help = "change a field of the design (repeatable), e.g. --set radius_mm=30"},
        {.name = "json", .kind = TIPPE_CLI_FLAG, .value = &a->json,
         .help = "print one JSON object (SI units) instead of the text"},
    };
    const int n = (int)(sizeof m / sizeof m[0]);
    memcpy(t, m, sizeof m);
    return n + hands_friction_options(&a->fr, o, t + n);
}

/* The options of the drawn hand launches (launch and map). */
static int distribution_options(hands_args *a, tippe_cli_opt *t)
{
    tippe_launch_options *o = &a->o;
    tippe_cli_opt m[] = {
        TIPPE_CLI_SEED_OPT(&a->seed, "random seed: the same seed gives the same launches and "
                                     "counts on\nany number of threads or ranks"),
        {.name = "precession-rel", .kind = TIPPE_CLI_DOUBLE, .value = &o->precession_sd_rel,
         .arg = "SD", .min = 0, .max = 1, .def = "0.1",
         .help = "precession = steady rate x (1 + SD N(0,1))"},
        {.name = "slide", .kind = TIPPE_CLI_DOUBLE, .value = &o->slide_sd_m_s, .arg = "SD",
         .unit = "m/s", .min = 0, .max = 10, .def = "0.05",
         .help = "sliding speed: half-normal with scale SD, random direction"},
        TIPPE_CLI_THREADS_OPT(&a->threads, "OpenMP threads; the counts do not depend on it"),
    };
    const int n = (int)(sizeof m / sizeof m[0]);
    memcpy(t, m, sizeof m);
    return n;
}

/* --accuracy, --stepper and --rtol into a->o: 0, or 2 after a usage error. */
static int apply_accuracy(hands_args *a, const tippe_cli_spec *spec)
{
    tippe_launch_options *o = &a->o;
    const double rtol = o->accuracy.rtol; /* --rtol, if given, wins over the preset's */
    tippe_error e;
    if (a->accuracy) {
        if (tippe_dynamics_accuracy_preset(a->accuracy, &o->accuracy, &e))
            return tippe_cli_usage_error(a->verb, "--accuracy: %s", e.msg);
        snprintf(o->accuracy_name, sizeof o->accuracy_name, "%s", a->accuracy);
    }
    if (a->stepper) {
        if (!tippe_dynamics_stepper_known(a->stepper) ||
            strlen(a->stepper) >= sizeof o->accuracy.stepper)
            return tippe_cli_usage_error(a->verb, "--stepper '%s': unknown (see tippe %s --help)",
                                         a->stepper, a->verb);
        snprintf(o->accuracy.stepper, sizeof o->accuracy.stepper, "%s", a->stepper);
        snprintf(o->accuracy_name, sizeof o->accuracy_name, "custom");
    }
    const tippe_cli_opt *r = tippe_cli_find_opt((tippe_cli_spec *)spec, "rtol");
    if (r && r->seen) {
        o->accuracy.rtol = rtol;
        snprintf(o->accuracy_name, sizeof o->accuracy_name, "custom");
    }
    return 0;
}

/* --tilt SD and --tilt-max MAX go together (SD <= MAX / 2, so that redrawing
 * above MAX ends quickly): the one given sets the other's default, so that
 * each is accepted alone over the whole range its --help shows. */
static void tilt_defaults(tippe_cli_spec *spec, tippe_launch_options *o)
{
    const tippe_cli_opt *sd = tippe_cli_find_opt(spec, "tilt");
    const tippe_cli_opt *max = tippe_cli_find_opt(spec, "tilt-max");
    if (!sd || !max || o->tilt_sd_rad <= 0.5 * o->tilt_max_rad)
        return;
    if (sd->seen && !max->seen)
        o->tilt_max_rad = 2 * o->tilt_sd_rad;
    else if (max->seen && !sd->seen)
        o->tilt_sd_rad = 0.5 * o->tilt_max_rad;
}

tippe_cli_opt hands_friction_opt(tippe_friction_param_id id, void *value)
{
    const tippe_friction_param *p = &tippe_friction_params[id];
    return (tippe_cli_opt){.name = p->option,
                           .kind = p->number ? TIPPE_CLI_DOUBLE : TIPPE_CLI_STRING,
                           .value = value,
                           .arg = p->arg,
                           .unit = p->unit,
                           .min = p->min,
                           .max = p->max,
                           .def = p->def,
                           .help = p->help};
}

int hands_friction_options(hands_friction *f, tippe_launch_options *o, tippe_cli_opt *t)
{
    tippe_cli_opt m[] = {
        hands_friction_opt(TIPPE_LAW_PARAM_LAW, &f->friction),
        hands_friction_opt(TIPPE_LAW_PARAM_PATCH_MM, &f->patch_mm),
        hands_friction_opt(TIPPE_LAW_PARAM_TABLE, &f->table),
        hands_friction_opt(TIPPE_LAW_PARAM_MU_C, &o->mu_c),
        hands_friction_opt(TIPPE_LAW_PARAM_SLIP_SCALE, &o->slip_scale_m_s),
        hands_friction_opt(TIPPE_LAW_PARAM_MU, &o->mu),
        hands_friction_opt(TIPPE_LAW_PARAM_CREEP_CAP, &o->creep_cap),
    };
    m[0].help = tippe_friction_law_help(HANDS_HELP_WIDTH, "; docs/dynamics.md", f->help,
                                       sizeof f->help);
    const int n = (int)(sizeof m / sizeof m[0]);
    memcpy(t, m, sizeof m);
    return n;
}

/* The command's names of the friction parameters, for the library's messages. */
static const tippe_friction_names cli_names = {
    .name = {[TIPPE_LAW_PARAM_LAW] = "--friction",
             [TIPPE_LAW_PARAM_PATCH_MM] = "--patch-mm",
             [TIPPE_LAW_PARAM_TABLE] = "--table",
             [TIPPE_LAW_PARAM_MU_C] = "--mu-c",
             [TIPPE_LAW_PARAM_SLIP_SCALE] = "--slip-scale",
             [TIPPE_LAW_PARAM_MU] = "--mu",
             [TIPPE_LAW_PARAM_RADIUS_SPAN] = "--radius-span",
             [TIPPE_LAW_PARAM_CREEP_CAP] = "--creep-cap"},
    .choose = "--friction %s",
};

int hands_friction_apply(const char *verb, hands_friction *f, tippe_launch_options *o,
                         const tippe_cli_spec *spec, int allow_list)
{
    tippe_friction_given g = {.laws = f->friction, .patch_mm = f->patch_mm, .table = f->table};
    for (int p = 0; p < TIPPE_LAW_N_PARAMS; p++) {
        const tippe_cli_opt *x =
            tippe_cli_find_opt((tippe_cli_spec *)spec, tippe_friction_params[p].option);
        if (x && x->seen)
            g.given |= 1u << p;
    }
    if (o->patch_radius_span > 0) /* check, launch, map: --radius-span */
        g.given |= 1u << TIPPE_LAW_PARAM_RADIUS_SPAN;
    tippe_friction_names names = cli_names;
    names.list = allow_list;
    tippe_error e;
    if (tippe_friction_choose(&g, &names, f->laws, &f->n_laws, o, &e))
        return tippe_cli_usage_error(verb, "%s", e.msg);
    return 0;
}

int hands_friction_patch(const hands_friction *f, tippe_launch_options *o, const tippe_design *d,
                         tippe_error *err)
{
    return tippe_friction_for_design(d, f->laws, f->n_laws, f->table, &cli_names, o, err);
}

void hands_friction_law(const hands_friction *f, int i, const tippe_launch_options *o,
                        tippe_launch_options *out)
{
    *out = *o;
    out->law = f->laws[i];
}

int hands_patch(hands_args *a, const tippe_design *d, tippe_error *err)
{
    return hands_friction_patch(&a->fr, &a->o, d, err);
}

int hands_parse(hands_verb *v, hands_args *a, int argc, char **argv)
{
    tippe_cli_opt opts[MAX_HAND_OPTS];
    int n = 0;
    for (const tippe_cli_opt *o = v->own; o->name && n < MAX_HAND_OPTS; o++)
        opts[n++] = *o;
    if (n + 20 >= MAX_HAND_OPTS)
        return tippe_cli_usage_error(a->verb, "internal error: too many options");
    n += model_options(a, opts + n);
    if (v->distribution)
        n += distribution_options(a, opts + n);
    opts[n] = (tippe_cli_opt){NULL};
    v->spec.opts = opts;
    v->spec.min_args = v->spec.max_args = 1;
    v->spec.args_name = "design file";
    v->spec.quiet_help = hands_mpi_rank() != 0; /* one --help, not one per rank */
    int rc = tippe_cli_parse(&v->spec, argc, argv, &a->design, &(int){0});
    if (!rc)
        rc = apply_accuracy(a, &v->spec);
    if (!rc)
        tilt_defaults(&v->spec, &a->o);
    if (!rc)
        rc = hands_friction_apply(a->verb, &a->fr, &a->o, &v->spec, v->friction_list);
    tippe_error e;
    if (!rc && a->o.tilt_sd_rad > 0.5 * a->o.tilt_max_rad)
        rc = tippe_cli_usage_error(a->verb, "--tilt %g: at most half of --tilt-max (%g rad), "
                                   "%g; give --tilt-max %g or more", a->o.tilt_sd_rad,
                                   a->o.tilt_max_rad, 0.5 * a->o.tilt_max_rad,
                                   2 * a->o.tilt_sd_rad);
    /* the patch law's Hertz modulus comes with the design (hands_patch), later */
    tippe_launch_options chk = a->o;
    if (tippe_friction_law_type_of(chk.law)->patch && !(chk.patch_radius_m > 0))
        chk.patch_E_star_pa = 1.0;
    if (!rc && tippe_launch_options_check(&chk, &e))
        rc = tippe_cli_usage_error(a->verb, "%s", e.msg);
    if (!rc && a->threads > 0)
        omp_set_num_threads((int)a->threads);
    v->spec.opts = NULL; /* opts lives on this stack frame */
    return rc;
}


const char *hands_group_meaning(tippe_group g)
{
    switch (g) {
    case TIPPE_GROUP_IA:
    case TIPPE_GROUP_IB: return "theta = 0 stable at every spin: no tipping";
    case TIPPE_GROUP_IIA: return "tips at high spin; the hanging branch folds";
    case TIPPE_GROUP_IIB: return "tips at high spin, hangs at moderate spin";
    case TIPPE_GROUP_IIC: return "tips completely above n-";
    case TIPPE_GROUP_III: return "theta = pi never stable: hangs at high spin";
    }
    return "";
}

void hands_print_top(const tippe_design *d, double z2, const tippe_top *t, double g,
                      const tippe_sweep_point_zone *z)
{
    tippe_theory_class cls;
    tippe_theory_classify(t->A / t->C, t->eps / t->R, &cls);
    printf("design     %s (%s) at Z2 = %g mm\n", tippe_design_name(d), tippe_design_path(d), z2);
    printf("top        m %.2f g, R %.2f mm, eps %.3f mm, A/C %.5f, eps/R %.5f: group %s (%s)\n",
           1e3 * t->m, 1e3 * t->R, 1e3 * t->eps, t->A / t->C, t->eps / t->R,
           tippe_group_name(cls.group), hands_group_meaning(cls.group));
    if (z->ok)
        printf("zone       %s from %.3f to %.3f mm along the stated travel (tippe sweep)\n",
               tippe_group_name(z->group), z->from_mm, z->to_mm);
    tippe_theory_thresholds th;
    tippe_error e;
    if (tippe_theory_compute_thresholds(t, g, &th, &e) == TIPPE_OK) {
        printf("thresholds");
        if (th.has_n_minus)
            printf(" n- %.4g rad/s = %.2f rev/s (theta = 0 unstable above);", th.n_minus_rad_s,
                   th.n_minus_rad_s / (2 * M_PI));
        else
            printf(" n- none (theta = 0 stable at every spin);");
        if (th.has_n_star)
            printf(" n* %.4g rad/s = %.2f rev/s (theta = pi stable above, from theta = 0)\n",
                   th.n_star_rad_s, th.n_star_rad_s / (2 * M_PI));
        else
            printf(" n* none (theta = pi never stable)\n");
    }
}

void hands_print_distribution(const tippe_launch_options *o, int fixed_spin)
{
    if (!fixed_spin)
        printf("hands      spin uniform %.4g .. %.4g rad/s (%g .. %g rev/s); ",
               2 * M_PI * o->spin_from_rev_s, 2 * M_PI * o->spin_to_rev_s, o->spin_from_rev_s,
               o->spin_to_rev_s);
    else
        printf("hands      spin fixed per cell; ");
    printf("tilt half-normal, scale %g rad (redrawn above %g rad); precession steady x (1 + %g "
           "N(0,1)); sliding half-normal, scale %g m/s, random direction\n",
           o->tilt_sd_rad, o->tilt_max_rad, o->precession_sd_rel, o->slide_sd_m_s);
}

const char *hands_stepper_text(const tippe_launch_options *o, const char *stiff, char *buf,
                               size_t size)
{
    const char *used = tippe_dynamics_stepper_used(o->law, o->creep_cap, o->accuracy.stepper);
    if (strcmp(used, o->accuracy.stepper) != 0)
        snprintf(buf, size, stiff, used, tippe_friction_law_type_of(o->law)->name);
    else
        snprintf(buf, size, "%s", used);
    return buf;
}

void hands_print_model(const tippe_launch_options *o, const tippe_top *top)
{
    tippe_dynamics_model m;
    char fr[320];
    tippe_launch_friction_model(o, &m);
    m.top = *top; /* the patch law's Hertz radius needs its m g and R */
    char stepper[64];
    hands_stepper_text(o, "%s for the stiff %s law", stepper, sizeof stepper);
    printf("model      friction %s, g %g m/s^2, t_end %g s, accuracy %s (%s, rtol %g), verdict "
           "level\n",
           tippe_dynamics_friction_text(&m, fr, sizeof fr), o->g, o->t_end, o->accuracy_name,
           stepper, o->accuracy.rtol);
}


static cJSON *json_counts(const tippe_launch_tally *t)
{
    cJSON *c = cJSON_CreateObject();
    for (int v = 0; c && v < TIPPE_LAUNCH_N_VERDICTS; v++)
        cJSON_AddNumberToObject(c, hands_verdict_names[v], (double)t->counts[v]);
    return c;
}

cJSON *hands_json_tally(const tippe_launch_tally *t)
{
    cJSON *o = cJSON_CreateObject();
    if (!o)
        return NULL;
    cJSON_AddNumberToObject(o, "n", (double)t->n);
    cJSON_AddNumberToObject(o, "on_polar_cap", (double)t->on_cap);
    cJSON_AddItemToObject(o, "counts", json_counts(t));
    cJSON_AddNumberToObject(o, "flips", (double)t->flips);
    if (t->flips)
        cJSON_AddNumberToObject(o, "median_t_flip_s", t->median_t_flip_s);
    else
        cJSON_AddNullToObject(o, "median_t_flip_s");
    /* every launch's passage over pi/2 and fall back, whatever its verdict */
    cJSON_AddNumberToObject(o, "passed_pi_2", (double)t->passed);
    tippe_cli_json_number_or_null(o, "median_t_passed_s", t->median_t_passed_s);
    cJSON_AddNumberToObject(o, "fell_back", (double)t->fell);
    tippe_cli_json_number_or_null(o, "median_t_fall_s", t->median_t_fall_s);
    cJSON_AddNumberToObject(o, "trapped", (double)t->trapped);
    cJSON_AddNumberToObject(o, "trapped_no_barrier", (double)t->trapped_no_barrier);
    cJSON_AddNumberToObject(o, "rolling", (double)t->rolling);
    if (isfinite(t->min_gap_over_margin))
        cJSON_AddNumberToObject(o, "min_gap_over_margin", t->min_gap_over_margin);
    else
        cJSON_AddNullToObject(o, "min_gap_over_margin");
    cJSON *fr = cJSON_AddObjectToObject(o, "fractions");
    cJSON *ci = cJSON_AddObjectToObject(o, "ci95");
    cJSON *mt = cJSON_AddObjectToObject(o, "median_theta_final_rad");
    cJSON *ms = cJSON_AddObjectToObject(o, "median_t_s");
    for (int v = 0; v < TIPPE_LAUNCH_N_VERDICTS; v++) {
        double lo, hi;
        tippe_launch_wilson(t->counts[v], t->n, TIPPE_LAUNCH_Z95, &lo, &hi);
        double b[2] = {lo, hi};
        if (fr)
            cJSON_AddNumberToObject(fr, hands_verdict_names[v],
                                    t->n ? (double)t->counts[v] / (double)t->n : 0.0);
        if (ci)
            cJSON_AddItemToObject(ci, hands_verdict_names[v], cJSON_CreateDoubleArray(b, 2));
        if (mt) {
            if (t->counts[v])
                cJSON_AddNumberToObject(mt, hands_verdict_names[v], t->median_theta_rad[v]);
            else
                cJSON_AddNullToObject(mt, hands_verdict_names[v]);
        }
        if (ms) {
            if (t->counts[v])
                cJSON_AddNumberToObject(ms, hands_verdict_names[v], t->median_t_s[v]);
            else
                cJSON_AddNullToObject(ms, hands_verdict_names[v]);
        }
    }
    return o;
}

