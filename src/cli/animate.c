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
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

static const char *const VERB = "animate";

static void animate_usage(FILE *out)
{
    fprintf(out,
            "usage: tippe animate SCENARIO.json -o FILM.mp4|FILM.webm|FILM.gif [options]\n"
            "       tippe animate DESIGN.json --z2 MM [--spin RAD_S] -o FILM [options]\n"
            "       tippe animate (SCENARIO.json | DESIGN.json --z2 MM) --frame T -o PICTURE.png\n"
            "\n"
            "Films a launch: the ball as a transparent shell seen from above the table, with a\n"
            "red dot at the pole on the weight's side (down at theta = 0), a blue stripe along a\n"
            "meridian (it turns with the spin), the moving weight and the centre of mass inside,\n"
            "the contact point's path on the table, the time, tilt, spin, Jellett drift and the\n"
            "verdict when it is reached, and theta against time. Frames are states of the\n"
            "integration at exact frame times (docs/animate.md).\n"
            "\n"
            "  -o FILE            the film (.mp4 H.264, .webm VP9, .gif) or, with --frame, a .png\n"
            "  --speed X          model seconds per second of film (default: the whole launch,\n"
            "                     to a tenth past its verdict, in --length seconds)\n"
            "  --length S         film length when --speed is not given, s (default 10)\n"
            "  --fps N            frames per second of film, 1 .. 120 (default 30)\n"
            "  --size WxH         picture size in pixels, even, 64x64 .. 3840x2160 (default\n"
            "                     640x480)\n"
            "  --frame T          write one picture at model time T (s) instead of a film\n"
            "  --json             print a JSON summary instead of the text\n"
            "\n"
            "A scenario's fields can be overridden as in tippe simulate:\n"
            "  --mu S_PER_M  --g M_S2  --t-end S  --theta RAD  --theta-dot RAD_S\n"
            "  --phi-dot RAD_S|steady|s1|s2|s3  --spin RAD_S  --U M_S  --V M_S  --z2 MM\n"
            "  --accuracy fast|balanced|precise  --stepper NAME  --rtol X  --set FIELD=VALUE\n"
            "A design gets tippe check's central hand launch (median tilt, steady precession,\n"
            "no sliding) at --spin (default 94.25 rad/s), with --mu (default 0.1 s/m), --g,\n"
            "--t-end (default 600 s), --accuracy and --set FIELD=VALUE for the design.\n"
            "  --help             this text\n"
            "\n"
            "A progress bar is shown on stderr when it is a terminal. Exit status: 0 ok, 2 bad\n"
            "usage or input, 1 the launch or the film could not be made.\n");
}

typedef struct {
    const char *input, *out, *z2_text, *spin_text;
    double speed, length_s, frame_t;
    int fps, width, height, json, still;
    tippe_cli_sets over;
} args;

static int parse_size(const char *text, int *w, int *h)
{
    char x;
    long a, b;
    char tail;
    if (sscanf(text, "%ld%c%ld%c", &a, &x, &b, &tail) != 3 || (x != 'x' && x != 'X'))
        return 0;
    if (a < 1 || a > 100000 || b < 1 || b > 100000)
        return 0;
    *w = (int)a;
    *h = (int)b;
    return 1;
}

/* Scenario fields that have their own option (as in tippe simulate). */
static const struct {
    const char *flag, *field;
} field_flags[] = {
    {"--mu", "mu"},
    {"--g", "g"},
    {"--t-end", "t_end"},
    {"--theta", "initial.theta"},
    {"--theta-dot", "initial.theta_dot"},
    {"--phi-dot", "initial.phi_dot"},
    {"--spin", "initial.spin"},
    {"--U", "initial.U"},
    {"--V", "initial.V"},
    {"--z2", "top.z2_mm"},
    {"--accuracy", "accuracy"},
    {"--stepper", "accuracy.stepper"},
    {"--rtol", "accuracy.rtol"},
};

/* Returns -1 after --help, else an exit status. */
static int parse_args(args *a, int argc, char **argv)
{
    const int n_flags = (int)(sizeof field_flags / sizeof field_flags[0]);
    for (int i = 1; i < argc; i++) {
        const char *s = argv[i], *field = NULL, *v;
        if (tippe_cli_is_help(s))
            return -1;
        if (!strcmp(s, "--json")) {
            a->json = 1;
            continue;
        }
        for (int k = 0; k < n_flags && !field; k++)
            if (!strcmp(s, field_flags[k].flag))
                field = field_flags[k].field;
        const int takes_value = field || !strcmp(s, "-o") || !strcmp(s, "--speed") ||
                                !strcmp(s, "--length") || !strcmp(s, "--fps") ||
                                !strcmp(s, "--size") || !strcmp(s, "--frame") ||
                                !strcmp(s, "--set");
        if (!takes_value) {
            if (tippe_cli_is_option(s, 0))
                return tippe_cli_usage_error(VERB, "unknown option '%s'", s);
            if (a->input)
                return tippe_cli_usage_error(VERB, "one input file only (got '%s' and '%s')",
                                             a->input, s);
            a->input = s;
            continue;
        }
        if (!(v = tippe_cli_value(VERB, argc, argv, &i)))
            return 2;
        long n;
        if (!strcmp(s, "-o")) {
            a->out = v;
        } else if (!strcmp(s, "--speed")) {
            if (!tippe_cli_parse_double(v, &a->speed) || !(a->speed > 0))
                return tippe_cli_usage_error(
                    VERB, "--speed '%s': expected a positive number of model seconds per "
                          "second of film", v);
        } else if (!strcmp(s, "--length")) {
            if (!tippe_cli_parse_double(v, &a->length_s) || !(a->length_s >= 0.5) ||
                a->length_s > 1200)
                return tippe_cli_usage_error(VERB, "--length '%s': expected 0.5 .. 1200 s", v);
        } else if (!strcmp(s, "--fps")) {
            if (!tippe_cli_parse_long(v, 1, 120, &n))
                return tippe_cli_usage_error(VERB, "--fps '%s': expected a whole number 1 .. 120",
                                             v);
            a->fps = (int)n;
        } else if (!strcmp(s, "--size")) {
            if (!parse_size(v, &a->width, &a->height) || a->width < 64 || a->width > 3840 ||
                a->height < 64 || a->height > 2160 || a->width % 2 || a->height % 2)
                return tippe_cli_usage_error(VERB,
                                             "--size '%s': expected WxH, even, 64x64 .. "
                                             "3840x2160 pixels", v);
        } else if (!strcmp(s, "--frame")) {
            if (!tippe_cli_parse_double(v, &a->frame_t) || !(a->frame_t >= 0))
                return tippe_cli_usage_error(VERB, "--frame '%s': expected a time >= 0 s", v);
            a->still = 1;
        } else if (!strcmp(s, "--set")) {
            if (tippe_cli_add_set(VERB, &a->over, v))
                return 2;
        } else {
            if (!strcmp(s, "--z2"))
                a->z2_text = v;
            if (!strcmp(s, "--spin"))
                a->spin_text = v;
            if (tippe_cli_sets_add(&a->over, field, v))
                return tippe_cli_usage_error(VERB, "more than %d overrides", TIPPE_CLI_MAX_SETS);
        }
    }
    if (!a->input)
        return tippe_cli_usage_error(VERB, "no scenario or design file given");
    if (!a->out)
        return tippe_cli_usage_error(VERB, "no output file given (-o FILM.mp4, .webm, .gif, "
                                           "or -o PICTURE.png with --frame T)");
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

/* The launch of a scenario file, with its design's weight when it has one. */
static int launch_of_scenario(const args *a, tippe_animate_launch *l, tippe_error *err)
{
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
        /* Only for the picture of the weight: the top itself is the scenario's. */
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
    static const char *const allowed[] = {"mu", "g", "t_end", "initial.spin", "top.z2_mm",
                                          "accuracy", "accuracy.stepper", "accuracy.rtol"};
    tippe_launch_options o;
    tippe_launch_options_default(&o);
    double z2 = NAN, spin = M_PI * (o.spin_from_rev_s + o.spin_to_rev_s);
    const char *design_sets[TIPPE_CLI_MAX_SETS];
    int n_design = 0;
    /* Split the overrides: the launch's options, and --set for the design. */
    for (int i = 0; i < a->over.n; i++) {
        const char *s = a->over.item[i], *eq = strchr(s, '=');
        size_t klen = eq ? (size_t)(eq - s) : strlen(s);
        int known = -1;
        for (int k = 0; k < (int)(sizeof allowed / sizeof allowed[0]); k++)
            if (strlen(allowed[k]) == klen && !strncmp(s, allowed[k], klen))
                known = k;
        if (known < 0 || !eq) {
            design_sets[n_design++] = s;
            continue;
        }
        const char *v = eq + 1;
        double x = NAN;
        const int is_number = tippe_cli_parse_double(v, &x);
        if (known >= 5) {
            if (known == 5 && tippe_dynamics_accuracy_preset(v, &o.accuracy, err) == TIPPE_OK) {
                snprintf(o.accuracy_name, sizeof o.accuracy_name, "%s", v);
            } else if (known == 5) {
                return TIPPE_EINPUT;
            } else if (known == 6) {
                if (!tippe_dynamics_stepper_known(v))
                    return tippe_error_set(err, TIPPE_EINPUT, "--stepper '%s': unknown stepper",
                                           v);
                snprintf(o.accuracy.stepper, sizeof o.accuracy.stepper, "%s", v);
                snprintf(o.accuracy_name, sizeof o.accuracy_name, "custom");
            } else if (!is_number || !(x >= 1e-14 && x <= 1e-2)) {
                return tippe_error_set(err, TIPPE_EINPUT, "--rtol '%s': expected 1e-14 .. 1e-2",
                                       v);
            } else {
                o.accuracy.rtol = x;
                snprintf(o.accuracy_name, sizeof o.accuracy_name, "custom");
            }
            continue;
        }
        if (!is_number)
            return tippe_error_set(err, TIPPE_EINPUT, "%.*s '%s': expected a number", (int)klen, s,
                                   v);
        if (known == 0)
            o.mu = x;
        else if (known == 1)
            o.g = x;
        else if (known == 2)
            o.t_end = x;
        else if (known == 3)
            spin = x;
        else
            z2 = x;
    }
    if (isnan(z2))
        return tippe_error_set(err, TIPPE_EINPUT,
                               "%s is a design: give the weight's position with --z2 MM",
                               a->input);
    int rc = tippe_launch_options_check(&o, err);
    if (rc)
        return rc;
    tippe_design *d = NULL;
    if ((rc = tippe_design_load(a->input, design_sets, n_design, &d, err)) != 0)
        return rc;
    memset(l, 0, sizeof *l);
    tippe_top top;
    if ((rc = tippe_design_top(d, z2, &top, err)) == 0 &&
        (rc = tippe_launch_central(&top, &o, spin, &l->initial, err)) == 0) {
        snprintf(l->title, sizeof l->title, "%s, Z2 = %g mm, hand launch at %.3g rev/s",
                 tippe_design_name(d), z2, spin / (2 * M_PI));
        l->model.top = top;
        l->model.g = o.g;
        l->model.mu = o.mu;
        l->t_end = o.t_end;
        l->accuracy = o.accuracy;
        tippe_animate_design_weight(d, z2, &top, &l->weight_offset_m, &l->weight_radius_m);
    }
    tippe_design_free(d);
    return rc;
}

static long file_size(const char *path)
{
    struct stat sb;
    return stat(path, &sb) == 0 ? (long)sb.st_size : -1;
}

static void print_summary(const args *a, const tippe_film *f, int film_format, double elapsed_s)
{
    const tippe_dynamics_result *r = &f->result;
    const long bytes = file_size(a->out);
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
            if (r->verdict != TIPPE_VERDICT_UNDECIDED)
                cJSON_AddNumberToObject(o, "t_verdict_s", r->t_verdict);
            cJSON_AddNumberToObject(o, "jellett_rel_drift", r->jellett_rel_drift);
            cJSON_AddNumberToObject(o, "bytes", (double)bytes);
            cJSON_AddNumberToObject(o, "elapsed_s", elapsed_s);
        }
        tippe_cli_print_json(VERB, o);
        return;
    }
    if (a->still) {
        printf("picture   %s: %dx%d PNG at t = %.6g s (%ld bytes)\n", a->out, f->opt.width_px,
               f->opt.height_px, f->samples[f->n_samples - 1].t, bytes);
    } else {
        printf("film      %s: %s, %dx%d, %d fps, %d frames = %.4g s of film (%ld bytes)\n",
               a->out, tippe_film_format_name(film_format), f->opt.width_px, f->opt.height_px,
               f->opt.fps, f->n_frames, (double)f->n_frames / f->opt.fps, bytes);
        printf("time      t = 0 .. %.6g s of the launch; 1 s of film = %.4g s\n",
               (f->n_frames - 1) * f->frame_dt, f->speed);
    }
    if (r->verdict != TIPPE_VERDICT_UNDECIDED)
        printf("verdict   %s at t = %.6g s (theta %.4g rad)\n", tippe_verdict_name(r->verdict),
               r->t_verdict, r->final.theta);
    else
        printf("verdict   none reached in the part shown (to t = %.6g s)\n", r->last.t);
    printf("accuracy  %d samples at exact times, Jellett drift %.2g, made in %.3g s\n",
           f->n_samples, r->jellett_rel_drift, elapsed_s);
}

int tippe_cli_animate(int argc, char **argv)
{
    args a = {.length_s = 10, .fps = 30, .width = 640, .height = 480};
    int rc = parse_args(&a, argc, argv);
    if (rc < 0) {
        animate_usage(stdout);
        return 0;
    }
    if (rc)
        return rc;
    tippe_film_format format = TIPPE_FILM_MP4;
    const char *dot = strrchr(a.out, '.');
    const int png = dot && !strchr(dot, '/') && !strcasecmp(dot, ".png");
    if (a.still && !png)
        return tippe_cli_usage_error(VERB, "--frame writes a picture: -o %s must end in .png",
                                     a.out);
    if (!a.still && png)
        return tippe_cli_usage_error(VERB, "-o %s: a .png is one picture; give --frame T", a.out);
    if (!a.still && !tippe_film_format_of(a.out, &format))
        return tippe_cli_usage_error(VERB, "-o %s: unknown film format (use .mp4, .webm or .gif)",
                                     a.out);
    /* Before any work, so that bad usage costs nothing and leaves nothing. */
    if (tippe_cli_check_output(VERB, "-o", a.out, 0))
        return 2;

    tippe_error err;
    tippe_animate_launch launch;
    rc = is_design(a.input) ? launch_of_design(&a, &launch, &err)
                            : launch_of_scenario(&a, &launch, &err);
    if (rc)
        return tippe_cli_fail(VERB, &err, rc);
    tippe_animate_options opt;
    tippe_animate_options_default(&opt);
    opt.speed = a.speed;
    opt.film_s = a.length_s;
    opt.fps = a.fps;
    opt.width_px = a.width;
    opt.height_px = a.height;

    const double t0 = tippe_cli_now_s();
    tippe_film film;
    rc = a.still ? tippe_film_make_still(&launch, &opt, a.frame_t, &film, &err)
                 : tippe_film_make(&launch, &opt, &film, &err);
    tippe_report_file rf;
    if (!rc)
        rc = tippe_report_open(&rf, a.out, a.still ? "the picture" : "the film", &err);
    if (!rc) {
        if (a.still) {
            rc = tippe_film_write_png(&film, rf.f, &err);
        } else {
            tippe_progress prog;
            tippe_progress_start(&prog, stderr, "tippe animate", tippe_film_work(&film, format),
                                 TIPPE_PROGRESS_AUTO);
            rc = tippe_film_write(&film, format, rf.f, &prog, &err);
            tippe_progress_finish(&prog);
        }
        if (rc)
            tippe_report_abort(&rf);
        else
            rc = tippe_report_commit(&rf, &err);
    }
    if (rc) {
        tippe_film_free(&film);
        return tippe_cli_fail(VERB, &err, rc);
    }
    print_summary(&a, &film, format, tippe_cli_now_s() - t0);
    tippe_film_free(&film);
    return 0;
}
