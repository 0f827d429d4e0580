/* What tippe launch, map and check share (see hands.h): their options, and the
 * words and JSON in which they describe the top, the launches and theory. */
#include "hands.h"

#include "tippe/sweep.h"
#include "tippe/physics.h"

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

int hands_friction_options(hands_friction *f, tippe_launch_options *o, tippe_cli_opt *t)
{
    tippe_cli_opt m[] = {
        {.name = "friction", .kind = TIPPE_CLI_STRING, .value = &f->friction, .arg = "LAW",
         .def = "viscous",
         .help = "friction law: viscous (eq 3.12, the paper's), coulomb (sliding\n"
                 "|F| = mu_c Rn, sticking and rolling without slipping), coulomb-creep\n"
                 "(regularised, no sticking) or patch (Coulomb-Contensou on a spinning\n"
                 "contact patch: --patch-mm, or Hertz on --table; verdicts observed, not\n"
                 "proved); docs/dynamics.md"},
        {.name = "patch-mm", .kind = TIPPE_CLI_DOUBLE, .value = &f->patch_mm, .arg = "A",
         .unit = "mm", .min = 1e-6, .max = 10, .def = "Hertz at m g",
         .help = "patch law: the contact patch's radius (default: Hertz's from the\n"
                 "ball's and the table's E and nu at the static load m g; given alone,\n"
                 "it selects --friction patch)"},
        {.name = "table", .kind = TIPPE_CLI_STRING, .value = &f->table, .arg = "SURFACE",
         .def = TIPPE_CONTACT_DEFAULT_TABLE,
         .help = "patch law: the table's surface for the Hertz patch: glass, laminate,\n"
                 "wood or steel (docs/contact-patch.md; given alone, it selects\n"
                 "--friction patch)"},
        {.name = "mu-c", .kind = TIPPE_CLI_DOUBLE, .value = &o->mu_c, .arg = "X", .min = 0,
         .max = 10, .def = TIPPE_CLI_STR(TIPPE_LAUNCH_DEFAULT_MU_C),
         .help = "Coulomb friction coefficient (given alone, it selects --friction\n"
                 "coulomb): a printed PLA or nylon ball on a tabletop (docs/launch.md)"},
        {.name = "slip-scale", .kind = TIPPE_CLI_DOUBLE, .value = &o->slip_scale_m_s,
         .arg = "V", .unit = "m/s", .min = 1e-9, .max = 1,
         .def = TIPPE_CLI_STR(TIPPE_COULOMB_SLIP_SCALE_M_S),
         .help = "Coulomb's regularisation speed v_s (given alone, it selects --friction\n"
                 "coulomb): sliding below it is smoothed, and sticking is tried below\n"
                 "30 v_s (docs/dynamics.md)"},
        {.name = "mu", .kind = TIPPE_CLI_DOUBLE, .value = &o->mu, .unit = "s/m", .min = 0,
         .max = 1e6, .def = "2.3",
         .help = "viscous sliding friction (eq 3.12), the default law's coefficient: a\n"
                 "table's Coulomb coefficient over a typical slip speed (docs/launch.md)"},
    };
    const int n = (int)(sizeof m / sizeof m[0]);
    memcpy(t, m, sizeof m);
    return n;
}

/* 1 if law is among f's laws. */
static int has_law(const hands_friction *f, tippe_friction_law law)
{
    for (int i = 0; i < f->n_laws; i++)
        if (f->laws[i] == law)
            return 1;
    return 0;
}

/* --friction LAW (or, where the verb compares laws, LAW,LAW,...) into f->laws:
 * 0, or 2 after a usage error. */
static int parse_laws(const char *verb, hands_friction *f, int allow_list)
{
    char buf[128];
    snprintf(buf, sizeof buf, "%s", f->friction);
    f->n_laws = 0;
    for (char *save = NULL, *w = strtok_r(buf, ",", &save); w; w = strtok_r(NULL, ",", &save)) {
        const int law = tippe_friction_law_parse(w);
        if (law < 0)
            return tippe_cli_usage_error(verb, "--friction '%s': expected viscous, coulomb, "
                                               "coulomb-creep or patch%s",
                                         w, allow_list ? " (or several, comma-separated)" : "");
        if (has_law(f, (tippe_friction_law)law))
            return tippe_cli_usage_error(verb, "--friction '%s': %s twice", f->friction, w);
        if (f->n_laws == HANDS_MAX_LAWS)
            return tippe_cli_usage_error(verb, "--friction '%s': at most %d laws", f->friction,
                                         HANDS_MAX_LAWS);
        f->laws[f->n_laws++] = (tippe_friction_law)law;
    }
    if (f->n_laws == 0)
        return tippe_cli_usage_error(verb, "--friction '%s': expected a law", f->friction);
    if (f->n_laws > 1 && !allow_list)
        return tippe_cli_usage_error(verb, "--friction '%s': one law (tippe check compares "
                                           "several)", f->friction);
    return 0;
}

int hands_friction_apply(const char *verb, hands_friction *f, tippe_launch_options *o,
                         const tippe_cli_spec *spec, int allow_list)
{
    const tippe_cli_opt *mu = tippe_cli_find_opt((tippe_cli_spec *)spec, "mu");
    const tippe_cli_opt *mu_c = tippe_cli_find_opt((tippe_cli_spec *)spec, "mu-c");
    const tippe_cli_opt *vs = tippe_cli_find_opt((tippe_cli_spec *)spec, "slip-scale");
    const int mu_seen = mu && mu->seen;
    const int coulomb_seen = (mu_c && mu_c->seen) || (vs && vs->seen);
    int rc;
    if (f->friction) {
        if ((rc = parse_laws(verb, f, allow_list)) != 0)
            return rc;
    } else if (mu_seen && coulomb_seen) {
        return tippe_cli_usage_error(verb, "--mu (s/m, viscous) and --mu-c or --slip-scale "
                                           "(Coulomb) name different laws: give one, or "
                                           "--friction");
    } else {
        f->n_laws = 1;
        f->laws[0] = o->law;
        if ((f->patch_mm > 0 || f->table) && !mu_seen)
            f->laws[0] = TIPPE_FRICTION_PATCH; /* the patch's radius names its law, as --mu-c does */
        else if (coulomb_seen)
            f->laws[0] = TIPPE_FRICTION_COULOMB;
        else if (mu_seen)
            f->laws[0] = TIPPE_FRICTION_VISCOUS;
    }
    o->law = f->laws[0];
    /* a coefficient needs a law it belongs to among those given */
    int other = 0; /* a law other than viscous: --mu-c and --slip-scale apply to it */
    for (int i = 0; i < f->n_laws; i++)
        other |= f->laws[i] != TIPPE_FRICTION_VISCOUS;
    if (!other && coulomb_seen)
        return tippe_cli_usage_error(verb, "%s: with the viscous law give --mu (s/m)",
                                     mu_c && mu_c->seen
                                         ? "--mu-c is the Coulomb coefficient"
                                         : "--slip-scale is the Coulomb law's regularisation");
    if (!has_law(f, TIPPE_FRICTION_VISCOUS) && mu_seen)
        return tippe_cli_usage_error(verb, "--mu (s/m) is the viscous coefficient: with "
                                           "the %s law give --mu-c",
                                     tippe_friction_law_name(o->law));
    double E, nu;
    if (!has_law(f, TIPPE_FRICTION_PATCH) && (f->patch_mm > 0 || f->table))
        return tippe_cli_usage_error(verb, "--%s belongs to the patch law: give --friction "
                                           "patch",
                                     f->patch_mm > 0 ? "patch-mm" : "table");
    if (!has_law(f, TIPPE_FRICTION_PATCH) && o->patch_radius_span > 0) /* check, launch, map */
        return tippe_cli_usage_error(verb, "--radius-span belongs to the patch law (its radius "
                                           "sensitivity): give --friction patch");
    if (f->table && tippe_contact_table_surface(f->table, &E, &nu))
        return tippe_cli_usage_error(verb, "--table '%s': expected " TIPPE_CONTACT_TABLES,
                                     f->table);
    if (f->table && f->patch_mm > 0)
        return tippe_cli_usage_error(verb, "--patch-mm gives the radius, --table derives it: "
                                           "give one");
    o->patch_radius_m = f->patch_mm * 1e-3;
    return 0;
}

int hands_friction_patch(const hands_friction *f, tippe_launch_options *o, const tippe_design *d,
                         tippe_error *err)
{
    if (!has_law(f, TIPPE_FRICTION_PATCH))
        return TIPPE_OK;
    if (!(o->patch_radius_span > 0)) /* --radius-span, else the design's tolerance */
        o->patch_radius_span = tippe_design_patch_radius_span(d);
    if (o->patch_radius_m > 0)
        return TIPPE_OK;
    return tippe_launch_patch_modulus(d, f->table, &o->patch_E_star_pa, err);
}

void hands_friction_law(const hands_friction *f, int i, const tippe_launch_options *o,
                        tippe_launch_options *out)
{
    *out = *o;
    out->law = f->laws[i];
}

int hands_patch(hands_args *a, const tippe_design *d, tippe_error *err)
{
    if (!has_law(&a->fr, TIPPE_FRICTION_PATCH))
        return TIPPE_OK;
    /* the dynamics' bound (a patch wider than R/2 is no patch), said with the option */
    const double R_mm = tippe_design_radius_mm(d);
    if (a->o.patch_radius_m > 0 && a->fr.patch_mm > 0.5 * R_mm)
        return tippe_error_set(err, TIPPE_EINPUT,
                               "--patch-mm %g: wider than half the ball's radius (R/2 = %g mm); "
                               "a contact patch is small beside the ball (Hertz: a << R)",
                               a->fr.patch_mm, 0.5 * R_mm);
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
    if (chk.law == TIPPE_FRICTION_PATCH && !(chk.patch_radius_m > 0))
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

void hands_print_model(const tippe_launch_options *o, const tippe_top *top)
{
    tippe_dynamics_model m;
    char fr[320];
    tippe_launch_friction_model(o, &m);
    m.top = *top; /* the patch law's Hertz radius needs its m g and R */
    const int bdf = o->law == TIPPE_FRICTION_PATCH && !strcmp(o->accuracy.stepper, "rk8pd");
    printf("model      friction %s, g %g m/s^2, t_end %g s, accuracy %s (%s, rtol %g), verdict "
           "level\n",
           tippe_dynamics_friction_text(&m, fr, sizeof fr), o->g, o->t_end, o->accuracy_name,
           bdf ? "msbdf for the stiff patch law" : o->accuracy.stepper, o->accuracy.rtol);
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

