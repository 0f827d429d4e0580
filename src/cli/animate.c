/* tippe animate: a film (or one picture) of a launch, from a scenario file or
 * from a design's central hand launch (as tippe check). */
#include "cli.h"

#include "tippe/animate.h"
#include "tippe/design.h"
#include "tippe/json.h"
#include "tippe/launch.h"
#include "tippe/progress.h"
#include "tippe/report.h"
#include "tippe/scenario.h"

#include <cjson/cJSON.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

static const char *const VERB = "animate";

/* What the command line asked for. */
typedef struct {
    const char *input, *out, *size_text, *accuracy, *stepper, *format;
    double speed, length_s, frame_t, z2_mm, spin, mu, g, t_end, rtol;
    long fps;
    int width, height, json, still;
    /* scenario-only overrides (--theta ...) and --set, in the order given */
    tippe_cli_sets over;
    int n_scenario_only;
    /* which of the options a scenario and a design share were given */
    int has_z2, has_spin, has_mu, has_g, has_t_end, has_rtol;
} args;

static int parse_size(const char *text, int *w, int *h)
{
    char x, tail;
    long a, b;
    if (sscanf(text, "%ld%c%ld%c", &a, &x, &b, &tail) != 3 || (x != 'x' && x != 'X'))
        return 0;
    if (a < 64 || a > 3840 || b < 64 || b > 2160 || a % 2 || b % 2)
        return 0;
    *w = (int)a;
    *h = (int)b;
    return 1;
}

/* Returns 0, or an exit status (0 after --help is TIPPE_CLI_HELP). */
static int parse_args(args *a, int argc, char **argv)
{
    tippe_cli_opt opts[] = {
        {.name = "output", .short_name = 'o', .kind = TIPPE_CLI_STRING, .value = &a->out,
         .arg = "FILE", .required = 1,
         .help = "the film: .mp4 (H.264), .webm (VP9) or .gif; with --frame, a .png"},
        {.name = "format", .kind = TIPPE_CLI_STRING, .value = &a->format, .arg = "mp4|webm|gif",
         .help = "the film's format, when -o does not end in .mp4, .webm or .gif\n"
                 "(-o - writes to standard output)"},
        {.name = "speed", .kind = TIPPE_CLI_DOUBLE, .value = &a->speed, .arg = "X",
         .min = 1e-9, .max = 1e9,
         .help = "model seconds per second of film (default: the whole launch, to a\n"
                 "tenth past its verdict, in --length seconds)"},
        {.name = "length", .kind = TIPPE_CLI_DOUBLE, .value = &a->length_s, .arg = "S", .unit = "s",
         .min = 0.5, .max = 1200, .def = "10", .help = "film length when --speed is not given"},
        {.name = "fps", .kind = TIPPE_CLI_LONG, .value = &a->fps, .arg = "N", .min = 1,
         .max = 120, .def = "30", .help = "frames per second of film"},
        {.name = "size", .kind = TIPPE_CLI_STRING, .value = &a->size_text, .arg = "WxH",
         .def = "640x480", .help = "picture size in pixels, even, 64x64 .. 3840x2160"},
        {.name = "frame", .kind = TIPPE_CLI_DOUBLE, .value = &a->frame_t, .arg = "T", .unit = "s",
         .min = 0, .max = 1e9, .help = "write one picture at model time T instead of a film"},
        {.name = "json", .kind = TIPPE_CLI_FLAG, .value = &a->json,
         .help = "print a JSON summary instead of the text"},
        {.name = "z2", .kind = TIPPE_CLI_DOUBLE, .value = &a->z2_mm, .arg = "MM", .unit = "mm",
         .min = -TIPPE_CLI_Z2_MAX_MM, .max = TIPPE_CLI_Z2_MAX_MM,
         .help = "position of a design's moving weight (needed for a design; a\n"
                 "scenario's design top moves its weight there)"},
        {.name = "spin", .kind = TIPPE_CLI_DOUBLE, .value = &a->spin, .unit = "rad/s",
         .min = -1e6, .max = 1e6,
         .help = "launch spin (a design's default: tippe check's, 94.25 rad/s)"},
        {.name = "mu", .kind = TIPPE_CLI_DOUBLE, .value = &a->mu, .unit = "s/m", .min = 0,
         .max = 1e6, .help = "viscous sliding friction, eq 3.12 (a design's default: 0.1)"},
        {.name = "g", .kind = TIPPE_CLI_DOUBLE, .value = &a->g, .unit = "m/s^2", .min = 1e-6,
         .max = 1e6, .help = "gravity (default 9.81)"},
        {.name = "t-end", .kind = TIPPE_CLI_DOUBLE, .value = &a->t_end, .unit = "s", .min = 1e-9,
         .max = 1e9, .help = "bound on the launch's time (a design's default: 600)"},
        {.name = "accuracy", .kind = TIPPE_CLI_STRING, .value = &a->accuracy,
         .arg = "fast|balanced|precise", .help = "integrator preset (default balanced)"},
        {.name = "stepper", .kind = TIPPE_CLI_STRING, .value = &a->stepper, .arg = "NAME",
         .help = "GSL stepper (docs/dynamics.md)"},
        {.name = "rtol", .kind = TIPPE_CLI_DOUBLE, .value = &a->rtol, .min = 1e-14, .max = 1e-2,
         .help = "relative tolerance of the integrator"},
        {.name = "theta", .kind = TIPPE_CLI_DOUBLE, .value = &a->over, .unit = "rad", .min = 0,
         .max = M_PI, .field = "initial.theta", .help = "scenario launch tilt"},
        {.name = "theta-dot", .kind = TIPPE_CLI_DOUBLE, .value = &a->over, .unit = "rad/s",
         .min = -1e6, .max = 1e6, .field = "initial.theta_dot",
         .help = "scenario launch tilt rate"},
        {.name = "phi-dot", .kind = TIPPE_CLI_STRING, .value = &a->over,
         .arg = "RAD_S|steady|s1|s2|s3", .field = "initial.phi_dot",
         .help = "scenario launch precession rate or rule"},
        {.name = "U", .kind = TIPPE_CLI_DOUBLE, .value = &a->over, .unit = "m/s", .min = -1e3,
         .max = 1e3, .field = "initial.U", .help = "scenario launch sliding along the tilt"},
        {.name = "V", .kind = TIPPE_CLI_DOUBLE, .value = &a->over, .unit = "m/s", .min = -1e3,
         .max = 1e3, .field = "initial.V", .help = "scenario launch sliding across it"},
        {.name = "set", .kind = TIPPE_CLI_SET, .value = &a->over, .arg = "FIELD=VALUE",
         .help = "change a field of the scenario (or of the design) before it is\n"
                 "checked (repeatable)"},
        {NULL},
    };
    tippe_cli_spec spec = {
        .verb = VERB,
        .synopsis = "(SCENARIO.json | DESIGN.json --z2 MM [--spin RAD_S]) -o FILM.mp4|.webm|.gif\n"
                    "       [--speed X] [--fps N] [--size WxH] [--frame T -o PICTURE.png]",
        .about =
            "Films a launch: the ball as a transparent shell seen from above the table, with\n"
            "a red dot at the pole on the weight's side (down at theta = 0), a blue stripe\n"
            "along a meridian (it turns with the spin), the moving weight and the centre of\n"
            "mass (quartered disc) inside, the contact point's path on the table, the time,\n"
            "tilt, spin, Jellett drift and the verdict once reached, and theta against time.\n"
            "Frames are states of the integration at exact frame times. A design gets tippe\n"
            "check's central hand launch (median tilt, steady precession, no sliding).",
        .after = "A progress bar is shown on stderr when it is a terminal. Exit status: 0 ok,\n"
                 "2 bad usage or input, 1 the launch or the film could not be made.\n"
                 "docs/animate.md describes the picture and the time scale.",
        .opts = opts,
        .min_args = 1,
        .max_args = 1,
        .args_name = "scenario or design file",
    };
    int n_args = 0;
    int rc = tippe_cli_parse(&spec, argc, argv, &a->input, &n_args);
    if (rc)
        return rc;
    if (a->size_text && !parse_size(a->size_text, &a->width, &a->height))
        return tippe_cli_usage_error(VERB, "--size '%s': expected WxH, even, 64x64 .. 3840x2160 "
                                     "pixels", a->size_text);
    a->still = tippe_cli_find_opt(&spec, "frame")->seen;
    for (const char *const *n = (const char *const[]){"theta", "theta-dot", "phi-dot", "U", "V",
                                                      NULL};
         *n; n++)
        a->n_scenario_only += tippe_cli_find_opt(&spec, *n)->seen;
    a->has_z2 = tippe_cli_find_opt(&spec, "z2")->seen;
    a->has_spin = tippe_cli_find_opt(&spec, "spin")->seen;
    a->has_mu = tippe_cli_find_opt(&spec, "mu")->seen;
    a->has_g = tippe_cli_find_opt(&spec, "g")->seen;
    a->has_t_end = tippe_cli_find_opt(&spec, "t-end")->seen;
    a->has_rtol = tippe_cli_find_opt(&spec, "rtol")->seen;
    return 0;
}

/* 1 if the file is a design (it has "parts"), 0 if it is taken as a scenario;
 * a file that cannot be read is left to the scenario reader's messages. */
static int is_design(const char *path)
{
    tippe_error e;
    tippe_json_reader *r = tippe_json_reader_new(path, &e, TIPPE_JSON_WORDS_KEY, NULL);
    cJSON *root = NULL;
    int design = 0;
    if (r && tippe_json_load(r, 16, "scenario", &root) == TIPPE_OK)
        design = cJSON_IsObject(root) && cJSON_GetObjectItemCaseSensitive(root, "parts") != NULL;
    cJSON_Delete(root);
    free(r);
    return design;
}

/* A shared option's value as a scenario override "field=value" (number if
 * text is NULL): 0, or 2 after a usage error. */
static int add_override(args *a, int given, const char *field, double x, const char *text)
{
    if (!given)
        return 0;
    char num[64];
    if (!text) {
        snprintf(num, sizeof num, "%.17g", x);
        text = num;
    }
    if (tippe_cli_sets_add(&a->over, field, text))
        return tippe_cli_usage_error(VERB, "too many overrides (at most %d)",
                                     TIPPE_CLI_MAX_SETS);
    return 0;
}

/* The launch of a scenario file, with its design's weight when it has one;
 * -2 after a usage error. */
static int launch_of_scenario(args *a, tippe_animate_launch *l, tippe_error *err)
{
    if (add_override(a, a->has_z2, "top.z2_mm", a->z2_mm, NULL) ||
        add_override(a, a->has_spin, "initial.spin", a->spin, NULL) ||
        add_override(a, a->has_mu, "mu", a->mu, NULL) ||
        add_override(a, a->has_g, "g", a->g, NULL) ||
        add_override(a, a->has_t_end, "t_end", a->t_end, NULL) ||
        add_override(a, a->accuracy != NULL, "accuracy", 0, a->accuracy) ||
        add_override(a, a->stepper != NULL, "accuracy.stepper", 0, a->stepper) ||
        add_override(a, a->has_rtol, "accuracy.rtol", a->rtol, NULL))
        return -2;
    tippe_scenario sc;
    int rc = tippe_scenario_load(a->input, a->over.item, a->over.n, &sc, err);
    if (rc)
        return rc;
    memset(l, 0, sizeof *l);
    snprintf(l->title, sizeof l->title, "%s", sc.name);
    l->model = sc.model;
    l->initial = sc.initial;
    l->t_end = sc.t_end;
    l->accuracy = sc.accuracy;
    if (sc.design_path[0]) {
        /* Only for the picture of the weight: the top itself is the scenario's
         * (a scenario's own design "set" list is not applied to the picture). */
        tippe_design *d = NULL;
        if (tippe_design_load(sc.design_path, NULL, 0, &d, err) == TIPPE_OK)
            tippe_animate_design_weight(d, sc.z2_mm, &sc.model.top, &l->weight_offset_m,
                                        &l->weight_radius_m);
        tippe_design_free(d);
    }
    return TIPPE_OK;
}

/* A design's central hand launch (tippe check's). */
static int launch_of_design(const args *a, tippe_animate_launch *l, tippe_error *err)
{
    if (!a->has_z2)
        return tippe_error_set(err, TIPPE_EINPUT,
                               "%s is a design: give the weight's position with --z2 MM",
                               a->input);
    if (a->n_scenario_only)
        return tippe_error_set(err, TIPPE_EINPUT,
                               "--theta, --theta-dot, --phi-dot, --U and --V change a scenario; "
                               "%s is a design, launched as tippe check launches it",
                               a->input);
    tippe_launch_options o;
    tippe_launch_options_default(&o);
    double spin = M_PI * (o.spin_from_rev_s + o.spin_to_rev_s);
    if (a->has_spin)
        spin = a->spin;
    if (a->has_mu)
        o.mu = a->mu;
    if (a->has_g)
        o.g = a->g;
    if (a->has_t_end)
        o.t_end = a->t_end;
    int rc = TIPPE_OK;
    if (a->accuracy) {
        if ((rc = tippe_dynamics_accuracy_preset(a->accuracy, &o.accuracy, err)) != 0)
            return rc;
        snprintf(o.accuracy_name, sizeof o.accuracy_name, "%s", a->accuracy);
    }
    if (a->stepper) {
        if (!tippe_dynamics_stepper_known(a->stepper))
            return tippe_error_set(err, TIPPE_EINPUT, "--stepper '%s': unknown stepper",
                                   a->stepper);
        snprintf(o.accuracy.stepper, sizeof o.accuracy.stepper, "%s", a->stepper);
        snprintf(o.accuracy_name, sizeof o.accuracy_name, "custom");
    }
    if (a->has_rtol) {
        o.accuracy.rtol = a->rtol;
        snprintf(o.accuracy_name, sizeof o.accuracy_name, "custom");
    }
    if ((rc = tippe_launch_options_check(&o, err)) != 0)
        return rc;
    tippe_design *d = NULL;
    if ((rc = tippe_design_load(a->input, a->over.item, a->over.n, &d, err)) != 0)
        return rc;
    memset(l, 0, sizeof *l);
    tippe_top top;
    if ((rc = tippe_design_top(d, a->z2_mm, &top, err)) == 0 &&
        (rc = tippe_launch_central(&top, &o, spin, &l->initial, err)) == 0) {
        snprintf(l->title, sizeof l->title, "%s, Z2 = %g mm, hand launch at %.3g rev/s",
                 tippe_design_name(d), a->z2_mm, spin / (2 * M_PI));
        l->model.top = top;
        l->model.g = o.g;
        l->model.mu = o.mu;
        l->t_end = o.t_end;
        l->accuracy = o.accuracy;
        tippe_animate_design_weight(d, a->z2_mm, &top, &l->weight_offset_m, &l->weight_radius_m);
    }
    tippe_design_free(d);
    return rc;
}

/* Writes the film or the picture through the report module (a temporary
 * renamed into place, or straight to a device); *bytes is its size (-1 if not
 * a regular file). FFmpeg seeks back to finish an MP4 or a WebM, so the
 * encoder gets a stream of its own on the path the report module chose. */
static int write_output(const args *a, const tippe_film *film, tippe_film_format format,
                        long *bytes, tippe_error *err)
{
    tippe_report_file rf;
    const char *what = a->still ? "the picture" : "the film";
    int rc = tippe_report_open_name(&rf, a->out, what, err);
    if (rc)
        return rc;
    FILE *f = fopen(rf.write_path, "wb");
    if (!f) {
        rc = tippe_error_set(err, TIPPE_ECOMPUTE, "%s: cannot write %s: %s", a->out, what,
                             strerror(errno));
        tippe_report_abort(&rf);
        return rc;
    }
    if (a->still) {
        rc = tippe_film_write_png(film, f, err);
    } else {
        tippe_progress prog;
        tippe_progress_start(&prog, stderr, "tippe animate", tippe_film_work(film, format),
                             TIPPE_PROGRESS_AUTO);
        rc = tippe_film_write(film, format, f, &prog, err);
        tippe_progress_finish(&prog);
    }
    const int write_failed = fflush(f) != 0 || ferror(f);
    const int e = errno;
    struct stat sb;
    *bytes = rf.mode == TIPPE_REPORT_REPLACE && fstat(fileno(f), &sb) == 0 ? (long)sb.st_size
                                                                            : -1;
    if ((fclose(f) != 0 || write_failed) && !rc)
        rc = tippe_error_set(err, TIPPE_ECOMPUTE, "%s: writing %s failed: %s", a->out, what,
                             strerror(e));
    if (rc) {
        tippe_report_abort(&rf);
        return rc;
    }
    return tippe_report_commit(&rf, err);
}

static void print_summary(const args *a, const tippe_film *f, int film_format, long bytes,
                          double elapsed_s)
{
    const tippe_dynamics_result *r = &f->result;
    /* A film written to standard output leaves it to the film. */
    FILE *out = strcmp(a->out, "-") ? stdout : stderr;
    if (a->json) {
        cJSON *o = cJSON_CreateObject();
        if (o) {
            cJSON_AddStringToObject(o, "input", a->input);
            cJSON_AddStringToObject(o, "output", a->out);
            cJSON_AddStringToObject(o, "format", a->still ? "PNG"
                                                          : tippe_film_format_name(film_format));
            cJSON_AddNumberToObject(o, "width_px", f->opt.width_px);
            cJSON_AddNumberToObject(o, "height_px", f->opt.height_px);
            if (a->still) {
                cJSON_AddNumberToObject(o, "t_s", f->samples[f->n_samples - 1].t);
            } else {
                cJSON_AddNumberToObject(o, "fps", f->opt.fps);
                cJSON_AddNumberToObject(o, "frames", f->n_frames);
                cJSON_AddNumberToObject(o, "film_s", (double)f->n_frames / f->opt.fps);
                cJSON_AddNumberToObject(o, "speed", f->speed);
                cJSON_AddNumberToObject(o, "t_shown_s", (f->n_frames - 1) * f->frame_dt);
            }
            cJSON_AddNumberToObject(o, "samples", f->n_samples);
            cJSON_AddStringToObject(o, "verdict", tippe_verdict_name(r->verdict));
            cJSON_AddStringToObject(o, "how", tippe_decision_name(r->how));
            if (r->verdict != TIPPE_VERDICT_UNDECIDED)
                cJSON_AddNumberToObject(o, "t_verdict_s", r->t_verdict);
            if (isfinite(r->theta_final_rad))
                cJSON_AddNumberToObject(o, "theta_final_rad", r->theta_final_rad);
            if (isfinite(r->barrier_gap_J))
                cJSON_AddNumberToObject(o, "barrier_gap_J", r->barrier_gap_J);
            if (isfinite(r->margin_J))
                cJSON_AddNumberToObject(o, "margin_J", r->margin_J);
            if (isfinite(f->t_settled))
                cJSON_AddNumberToObject(o, "t_settled_s", f->t_settled);
            cJSON_AddNumberToObject(o, "jellett_rel_drift", r->jellett_rel_drift);
            if (bytes >= 0)
                cJSON_AddNumberToObject(o, "bytes", (double)bytes);
            else
                cJSON_AddNullToObject(o, "bytes");
            cJSON_AddNumberToObject(o, "elapsed_s", elapsed_s);
        }
        char *text = o ? cJSON_Print(o) : NULL;
        cJSON_Delete(o);
        if (text)
            fprintf(out, "%s\n", text);
        free(text);
        return;
    }
    if (a->still) {
        fprintf(out, "picture   %s: %dx%d PNG at t = %.6g s (%ld bytes)\n", a->out, f->opt.width_px,
               f->opt.height_px, f->samples[f->n_samples - 1].t, bytes);
    } else {
        fprintf(out, "film      %s: %s, %dx%d, %d fps, %d frames = %.4g s of film (%ld bytes)\n",
               a->out, tippe_film_format_name(film_format), f->opt.width_px, f->opt.height_px,
               f->opt.fps, f->n_frames, (double)f->n_frames / f->opt.fps, bytes);
        fprintf(out, "time      t = 0 .. %.6g s of the launch; 1 s of film = %.4g s\n",
               (f->n_frames - 1) * f->frame_dt, f->speed);
    }
    if (r->verdict != TIPPE_VERDICT_UNDECIDED)
        fprintf(out, "verdict   %s, decided (%s) at t = %.6g s; end state theta %.4g rad\n",
                tippe_verdict_name(r->verdict), tippe_decision_name(r->how), r->t_verdict,
                r->theta_final_rad);
    if (isfinite(f->t_settled))
        fprintf(out, "settled   theta within 0.05 rad of its end state from t = %.6g s\n",
                f->t_settled);
    else
        fprintf(out, "verdict   none reached in the part shown (to t = %.6g s)\n", r->last.t);
    fprintf(out, "accuracy  %d samples at exact times, Jellett drift %.2g, made in %.3g s\n",
           f->n_samples, r->jellett_rel_drift, elapsed_s);
}

int tippe_cli_animate(int argc, char **argv)
{
    args a = {.length_s = 10, .fps = 30, .width = 640, .height = 480};
    int rc = parse_args(&a, argc, argv);
    if (rc)
        return rc == TIPPE_CLI_HELP ? 0 : rc;
    tippe_film_format format = TIPPE_FILM_MP4;
    const char *dot = strrchr(a.out, '.');
    const int png = dot && !strchr(dot, '/') && !strcasecmp(dot, ".png");
    if (a.still && !png)
        return tippe_cli_usage_error(VERB, "--frame writes a picture: -o %s must end in .png",
                                     a.out);
    if (!a.still && png)
        return tippe_cli_usage_error(VERB, "-o %s: a .png is one picture; give --frame T", a.out);
    if (a.format) {
        char name[16];
        snprintf(name, sizeof name, ".%s", a.format);
        if (a.still || !tippe_film_format_of(name, &format))
            return tippe_cli_usage_error(VERB, "--format %s: expected mp4, webm or gif (for a "
                                         "film)", a.format);
    } else if (!a.still && !tippe_film_format_of(a.out, &format)) {
        return tippe_cli_usage_error(VERB, "-o %s: unknown film format (use .mp4, .webm or "
                                     ".gif, or give --format)", a.out);
    }
    /* Before any work, so that bad usage costs nothing and leaves nothing. */
    if (tippe_cli_check_output(VERB, "-o", a.out, 0))
        return 2;

    tippe_error err;
    tippe_animate_launch launch;
    rc = is_design(a.input) ? launch_of_design(&a, &launch, &err)
                            : launch_of_scenario(&a, &launch, &err);
    if (rc == -2)
        return 2; /* a usage error, already said */
    if (rc)
        return tippe_cli_fail(VERB, &err, rc);
    tippe_animate_options opt;
    tippe_animate_options_default(&opt);
    opt.speed = a.speed;
    opt.film_s = a.length_s;
    opt.fps = (int)a.fps;
    opt.width_px = a.width;
    opt.height_px = a.height;

    const double t0 = tippe_cli_now_s();
    tippe_film film;
    rc = a.still ? tippe_film_make_still(&launch, &opt, a.frame_t, &film, &err)
                 : tippe_film_make(&launch, &opt, &film, &err);
    long bytes = -1;
    if (!rc)
        rc = write_output(&a, &film, format, &bytes, &err);
    if (rc) {
        tippe_film_free(&film);
        return tippe_cli_fail(VERB, &err, rc);
    }
    print_summary(&a, &film, format, bytes, tippe_cli_now_s() - t0);
    tippe_film_free(&film);
    return 0;
}
