/* tippe animate: a film (or one picture) of a launch, from a scenario file or
 * from a design's central hand launch (as tippe check). */
#include "cli.h"

#include "tippe/animate.h"
#include "tippe/design.h"
#include "base/json.h"
#include "tippe/base.h"
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
    const char *input, *out, *size_text, *format;
    double speed, length_s, frame_t;
    long fps;
    int width, height, json, still;
    tippe_cli_launch_args l; /* the launch: scenario or design, and its options */
    /* where the design's weight puts a part out of the sphere (set by load_launch) */
    tippe_design_protrusion protrusion;
    double z2_mm;
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

/* Returns 0, or an exit status (TIPPE_CLI_HELP after --help). */
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
         .help = "model seconds per second of film (default: the whole launch in\n"
                 "--length seconds, docs/animate.md)"},
        {.name = "length", .kind = TIPPE_CLI_DOUBLE, .value = &a->length_s, .arg = "S",
         .unit = "s", .min = 0.5, .max = 1200, .def = "10",
         .help = "film length when --speed is not given"},
        {.name = "fps", .kind = TIPPE_CLI_LONG, .value = &a->fps, .arg = "N", .min = 1,
         .max = 120, .def = "30", .help = "frames per second of film"},
        {.name = "size", .kind = TIPPE_CLI_STRING, .value = &a->size_text, .arg = "WxH",
         .def = "640x480", .help = "picture size in pixels, even, 64x64 .. 3840x2160"},
        {.name = "frame", .kind = TIPPE_CLI_DOUBLE, .value = &a->frame_t, .arg = "T", .unit = "s",
         .min = 0, .max = 1e9, .help = "write one picture at model time T instead of a film"},
        {.name = "json", .kind = TIPPE_CLI_FLAG, .value = &a->json,
         .help = "print a JSON summary instead of the text"},
        TIPPE_CLI_LAUNCH_OPTS(&a->l),
        {NULL},
    };
    tippe_cli_spec spec = {
        .verb = VERB,
        .progress = 1,
        .synopsis = "(SCENARIO.json | DESIGN.json --z2 MM [--spin RATE]) -o FILM.mp4|.webm|.gif\n"
                    "       [--speed X] [--fps N] [--size WxH] [--frame T -o PICTURE.png]",
        .about =
            "Films a launch: the ball as a transparent shell seen from above the table, with\n"
            "a red dot at the pole on the weight's side (down at theta = 0), a blue stripe\n"
            "along a meridian (it turns with the spin), the moving weight and the centre of\n"
            "mass (quartered disc) inside, the contact point's path on the table, the time,\n"
            "tilt, spin, Jellett drift and the verdict once proved, and theta against time.\n"
            "Frames are states of the integration at exact frame times. A design without\n"
            "launch options gets tippe launch's central hand launch, as tippe simulate.",
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
    return tippe_cli_launch_finish(VERB, &spec, a->input, &a->l);
}

/* The launch of a scenario file or of a design's hand launch, with the
 * design's weight for the picture when the top comes from a design. */
static int load_launch(args *a, tippe_animate_launch *l, tippe_error *err)
{
    tippe_scenario sc;
    int rc = tippe_cli_launch_load(a->input, &a->l, &sc, err);
    if (rc)
        return rc;
    memset(l, 0, sizeof *l);
    snprintf(l->title, sizeof l->title, "%s", sc.name);
    l->model = sc.model;
    l->initial = sc.initial;
    l->t_end = sc.t_end;
    l->accuracy = sc.accuracy;
    a->protrusion = sc.protrusion;
    a->z2_mm = sc.z2_mm;
    if (sc.design) /* the picture of the weight: the scenario's design, as loaded */
        tippe_animate_design_weight(sc.design, sc.z2_mm, &sc.model.top, &l->weight_offset_m,
                                    &l->weight_radius_m);
    tippe_scenario_free(&sc);
    return TIPPE_OK;
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
                             tippe_cli_progress_mode());
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
            /* |v + omega x q| at launch (eq 3.7) */
            cJSON_AddNumberToObject(o, "contact_slip_m_s",
                                    tippe_dynamics_launch_slip(&f->launch.model.top,
                                                               &f->launch.initial));
            cJSON_AddStringToObject(o, "verdict", tippe_verdict_name(r->verdict));
            if (r->verdict != TIPPE_VERDICT_UNDECIDED)
                cJSON_AddNumberToObject(o, "t_verdict_s", r->t_verdict);
            tippe_cli_json_verdict_proof(o, r);
            if (isfinite(f->t_settled))
                cJSON_AddNumberToObject(o, "t_settled_s", f->t_settled);
            cJSON_AddNumberToObject(o, "jellett_rel_drift", r->jellett_rel_drift);
            tippe_design_protrusion_json(o, &a->protrusion);
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
    char slide[200];
    fprintf(out, "launch    theta %.4g rad, spin %.4g rad/s; %s\n", f->launch.initial.theta,
            f->launch.initial.spin,
            tippe_launch_slip_text(&f->launch.model.top, &f->launch.initial, NULL, slide,
                                   sizeof slide));
    if (r->verdict == TIPPE_VERDICT_BOUNDED)
        fprintf(out, "verdict   bounded, decided (%s) at t = %.6g s: theta stays in "
                "[%.4g, %.4g] rad (no end state)\n",
                tippe_decision_name(r->how), r->t_verdict, r->theta_lo_rad, r->theta_hi_rad);
    else if (r->how == TIPPE_DECIDED_ENERGY_CONE && r->verdict == TIPPE_VERDICT_TIP)
        fprintf(out, "verdict   tip, proved at t = %.6g s by the energy alone (energy_cone): "
                "theta stays above %.4g rad for ever; the rest state is not proved\n",
                r->t_verdict, r->theta_lo_rad);
    else if (r->how == TIPPE_DECIDED_ENERGY_CONE)
        fprintf(out, "verdict   no_tip, proved at t = %.6g s by the energy alone (energy_cone): "
                "theta stays below %.4g rad for ever; the rest state is not proved\n",
                r->t_verdict, r->theta_hi_rad);
    else if (r->how == TIPPE_DECIDED_OBSERVED)
        fprintf(out, "verdict   %s, observed at t = %.6g s (NOT proved): theta %.4g rad; %s\n",
                tippe_verdict_name(r->verdict), r->t_verdict, r->theta_final_rad,
                r->unproved_reason ? r->unproved_reason : "not proved");
    else if (r->how == TIPPE_DECIDED_ROLLING)
        fprintf(out, "verdict   %s, decided (rolling) at t = %.6g s: rolls without slipping for "
                "ever, theta in [%.4g, %.4g] rad\n",
                tippe_verdict_name(r->verdict), r->t_verdict, r->theta_lo_rad, r->theta_hi_rad);
    else if (r->verdict != TIPPE_VERDICT_UNDECIDED && !r->end_state_proved)
        fprintf(out, "verdict   %s, decided (%s) at t = %.6g s; stays in the well of theta %.4g "
                "rad (its rest state if it keeps sliding), theta in [%.4g, %.4g] rad\n",
                tippe_verdict_name(r->verdict), tippe_decision_name(r->how), r->t_verdict,
                r->theta_final_rad, r->theta_lo_rad, r->theta_hi_rad);
    else if (r->verdict != TIPPE_VERDICT_UNDECIDED)
        fprintf(out, "verdict   %s, decided (%s) at t = %.6g s; end state theta %.4g rad\n",
                tippe_verdict_name(r->verdict), tippe_decision_name(r->how), r->t_verdict,
                r->theta_final_rad);
    else
        fprintf(out, "verdict   none proved in the part shown (to t = %.6g s)\n", r->last.t);
    if (isfinite(f->t_settled))
        fprintf(out, "settled   theta within 0.05 rad of its end state from t = %.6g s\n",
                f->t_settled);
    tippe_cli_fprint_model_validity(out, &a->protrusion, a->z2_mm, "contact   ",
                                    "the verdict above is");
    if (isfinite(r->jellett_drift_time_s)) /* drilling moves J: no error measure */
        fprintf(out, "accuracy  %d samples at exact times, J not conserved (drilling), made in "
                     "%.3g s\n",
                f->n_samples, elapsed_s);
    else
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
    rc = load_launch(&a, &launch, &err);
    if (rc)
        return tippe_cli_fail(VERB, &err, rc);
    /* before the launch is integrated */
    if (a.still && !(a.frame_t <= launch.t_end))
        return tippe_cli_usage_error(VERB, "--frame %g s: the frame's time must lie within 0 .. "
                                     "t_end = %g s of the launch (give a larger --t-end, or an "
                                     "earlier --frame)", a.frame_t, launch.t_end);
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
