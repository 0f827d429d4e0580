/* The option parser of the tippe command (see cli.h): a verb's table of options
 * drives getopt_long and the generated --help, so that every verb reads
 * "--opt=value" and "--opt value" alike, checks numbers against the same kind
 * of range and speaks one unit language. */
#include "cli.h"

#include "tippe/base.h"

#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_OPTS = 64, FIRST_LONG = 256, PROGRESS_OPT = FIRST_LONG - 1 };

static int progress_forced; /* --progress was given */

int tippe_cli_progress_mode(void)
{
    return progress_forced ? TIPPE_PROGRESS_ON : TIPPE_PROGRESS_AUTO;
}

/* Unit suffixes a number may carry, by family (the first row of a family is
 * its base unit); a number is converted to its option's unit. */
static const struct {
    const char *family, *suffix;
    double factor; /* value in the family's base unit per suffix unit */
} units[] = {
    {"rad/s", "rad/s", 1.0},
    {"rad/s", "rev/s", 2.0 * M_PI},
    {"rad/s", "rpm", 2.0 * M_PI / 60.0},
    {"mm", "mm", 1.0},
    {"mm", "cm", 10.0},
    {"mm", "m", 1000.0},
    {"rad", "rad", 1.0},
    {"rad", "deg", M_PI / 180.0},
};
enum { N_UNITS = (int)(sizeof units / sizeof units[0]) };

/* The row of unit in the table (its family's base), or -1. */
static int unit_row(const char *unit)
{
    for (int i = 0; unit && i < N_UNITS; i++)
        if (!strcmp(units[i].suffix, unit))
            return i;
    return -1;
}

int tippe_cli_parse_unit(const char *text, const char *unit, double *out)
{
    char *end = NULL;
    double x = strtod(text, &end);
    if (end == text || !isfinite(x))
        return 0;
    if (*end != '\0') {
        int u = unit_row(unit);
        if (u < 0)
            return 0;
        int k = 0;
        while (k < N_UNITS &&
               !(!strcmp(units[k].family, units[u].family) && !strcmp(units[k].suffix, end)))
            k++;
        if (k == N_UNITS)
            return 0;
        x *= units[k].factor / units[u].factor;
    }
    *out = x;
    return isfinite(x);
}

tippe_cli_opt *tippe_cli_find_opt(tippe_cli_spec *spec, const char *name)
{
    for (tippe_cli_opt *o = spec->opts; o->name; o++)
        if (!strcmp(o->name, name))
            return o;
    return NULL;
}

static int takes_value(const tippe_cli_opt *o)
{
    return o->kind != TIPPE_CLI_FLAG;
}

/* "--name" or "-n, --name", as the user types it. */
static void opt_label(const tippe_cli_opt *o, char *buf, size_t size)
{
    if (o->short_name && !o->name[1] && o->name[0] == o->short_name)
        snprintf(buf, size, "-%c", o->short_name);
    else
        snprintf(buf, size, "--%s", o->name);
}

/* " of UNIT", with the suffixes a number may carry when UNIT has others
 * (" of rad/s (or suffix rad/s, rev/s, rpm)"); "" without a unit. */
static void unit_text(const char *unit, char *buf, size_t size)
{
    buf[0] = '\0';
    if (!unit)
        return;
    int n = snprintf(buf, size, " of %s", unit);
    int u = unit_row(unit), first = 1;
    for (int k = 0; u >= 0 && k < N_UNITS && n > 0 && (size_t)n < size; k++)
        if (!strcmp(units[k].family, units[u].family) && strcmp(units[k].family, units[k].suffix)) {
            n += snprintf(buf + n, size - (size_t)n, "%s%s", first ? " (or suffix " : ", ",
                          units[k].suffix);
            first = 0;
        }
    if (!first && n > 0 && (size_t)n < size)
        snprintf(buf + n, size - (size_t)n, ")");
}

/* The allowed values of o, e.g. "a number of mm (or suffix cm, m) from 0 to 100". */
static void allowed_text(const tippe_cli_opt *o, char *buf, size_t size)
{
    const char *what = o->kind == TIPPE_CLI_LONG ? "a whole number" : "a number";
    char unit[96];
    unit_text(o->unit, unit, sizeof unit);
    if (o->kind == TIPPE_CLI_RANGE) {
        char steps[64] = "";
        if (o->max_steps > 0)
            snprintf(steps, sizeof steps, "[:STEPS] with STEPS 1 .. %ld", o->max_steps);
        snprintf(buf, size, "X or FROM:TO%s, numbers%s from %.10g to %.10g", steps, unit,
                 o->min, o->max);
    } else {
        snprintf(buf, size, o->kind == TIPPE_CLI_LONG ? "%s%s from %.0f to %.0f"
                                                      : "%s%s from %.10g to %.10g",
                 what, unit, o->min, o->max);
    }
}

static int bad_value(const tippe_cli_spec *spec, const tippe_cli_opt *o, const char *text,
                     const char *why)
{
    char label[80], allowed[256];
    opt_label(o, label, sizeof label);
    allowed_text(o, allowed, sizeof allowed);
    if (why)
        return tippe_cli_usage_error(spec->verb, "%s '%s': %s", label, text, why);
    return tippe_cli_usage_error(spec->verb, "%s '%s': expected %s", label, text, allowed);
}

/* A bound is printed with 10 significant digits (e.g. pi as 3.141592654, above
 * pi): a value beyond a bound by no more than that rounding (or a unit
 * conversion's last bit, as 180deg) is taken as the bound itself. */
static double snap_to_bounds(const tippe_cli_opt *o, double x)
{
    if (x > o->max && x <= o->max + 5e-10 * fabs(o->max))
        return o->max;
    if (x < o->min && x >= o->min - 5e-10 * fabs(o->min))
        return o->min;
    return x;
}

static int in_range(const tippe_cli_opt *o, double x)
{
    return x >= o->min && x <= o->max;
}

/* The unit suffix of a number's text ("" without one). */
static const char *suffix_of(const char *text)
{
    char *end = NULL;
    strtod(text, &end);
    return end;
}

/* "X", "FROM:TO" or "FROM:TO:STEPS" into r: 0, or 2 after the usage error. */
static int parse_range(const tippe_cli_spec *spec, const tippe_cli_opt *o, const char *text,
                       tippe_cli_range *r)
{
    char buf[256];
    if (strlen(text) >= sizeof buf)
        return bad_value(spec, o, text, "too long");
    snprintf(buf, sizeof buf, "%s", text);
    char *c1 = strchr(buf, ':'), *c2 = c1 ? strchr(c1 + 1, ':') : NULL;
    if (c1)
        *c1 = '\0';
    if (c2)
        *c2 = '\0';
    /* "5:40rev/s": a unit written on TO only applies to FROM too */
    char from_text[300];
    const char *to_unit = c1 ? suffix_of(c1 + 1) : "";
    snprintf(from_text, sizeof from_text, "%s%s", buf, *suffix_of(buf) ? "" : to_unit);
    double from, to;
    long steps = c1 ? 0 : 1;
    if (!tippe_cli_parse_unit(from_text, o->unit, &from) ||
        (c1 && !tippe_cli_parse_unit(c1 + 1, o->unit, &to)) ||
        (c2 && (o->max_steps <= 0 || !tippe_cli_parse_long(c2 + 1, 1, o->max_steps, &steps))))
        return bad_value(spec, o, text, NULL);
    if (!c1)
        to = from;
    from = snap_to_bounds(o, from);
    to = snap_to_bounds(o, to);
    if (!in_range(o, from) || !in_range(o, to))
        return bad_value(spec, o, text, NULL);
    if (from > to || (steps > 1 && from == to) || (steps == 1 && c2 && from != to))
        return bad_value(spec, o, text,
                         steps == 1 ? "one step needs FROM = TO"
                                    : "expected FROM < TO (FROM = TO with one step)");
    r->from = from;
    r->to = to;
    r->steps = steps;
    return 0;
}

/* Stores text as the value of o: 0, or 2 after a usage error. */
static int store(const tippe_cli_spec *spec, tippe_cli_opt *o, const char *text)
{
    double x;
    long l;
    char num[64];
    switch (o->kind) {
    case TIPPE_CLI_FLAG:
        *(int *)o->value = 1;
        return 0;
    case TIPPE_CLI_STRING:
        if (o->field)
            break;
        *(const char **)o->value = text;
        return 0;
    case TIPPE_CLI_DOUBLE:
        if (!tippe_cli_parse_unit(text, o->unit, &x) || !in_range(o, x = snap_to_bounds(o, x)))
            return bad_value(spec, o, text, NULL);
        if (o->field) {
            snprintf(num, sizeof num, "%.17g", x);
            text = num;
            break;
        }
        *(double *)o->value = x;
        return 0;
    case TIPPE_CLI_LONG:
        if (!tippe_cli_parse_long(text, (long)o->min, (long)o->max, &l))
            return bad_value(spec, o, text, NULL);
        *(long *)o->value = l;
        return 0;
    case TIPPE_CLI_RANGE:
        return parse_range(spec, o, text, o->value);
    case TIPPE_CLI_SET:
        break;
    }
    /* a --set item, or an option that stands for one */
    if (tippe_cli_sets_add(o->value, o->field, text))
        return tippe_cli_usage_error(spec->verb, "too many --set options and overrides (at "
                                     "most %d)", TIPPE_CLI_MAX_SETS);
    return 0;
}

/* getopt_long's tables for spec: 0, or -1 if the table is too long. */
static int build_getopt(const tippe_cli_spec *spec, struct option *lo, char *shorts)
{
    int n = 0, s = 0;
    shorts[s++] = ':'; /* a missing value is reported as ':' */
    shorts[s++] = 'h';
    for (const tippe_cli_opt *o = spec->opts; o->name; o++, n++) {
        if (n >= MAX_OPTS - 3) /* room for --help, --progress and the end */
            return -1;
        lo[n] = (struct option){o->name, takes_value(o) ? required_argument : no_argument, NULL,
                                FIRST_LONG + n};
        if (o->short_name) {
            shorts[s++] = o->short_name;
            if (takes_value(o))
                shorts[s++] = ':';
        }
    }
    lo[n++] = (struct option){"help", no_argument, NULL, 'h'};
    if (spec->progress)
        lo[n++] = (struct option){"progress", no_argument, NULL, PROGRESS_OPT};
    lo[n] = (struct option){NULL, 0, NULL, 0};
    shorts[s] = '\0';
    return 0;
}

/* The option getopt_long returned as c, or NULL. */
static tippe_cli_opt *option_for(tippe_cli_spec *spec, int c)
{
    int n = 0;
    for (tippe_cli_opt *o = spec->opts; o->name; o++, n++)
        if (c == FIRST_LONG + n || (o->short_name && c == o->short_name))
            return o;
    return NULL;
}

/* After getopt_long's '?' or ':' for the argument at argv[optind - 1]. */
static int getopt_error(const tippe_cli_spec *spec, int c, char **argv)
{
    const char *arg = argv[optind - 1];
    if (c == ':')
        return tippe_cli_usage_error(spec->verb, "%s needs a value", arg);
    if (optopt && optopt < FIRST_LONG && strncmp(arg, "--", 2))
        return tippe_cli_usage_error(spec->verb, "unknown option '-%c'", optopt);
    if (optopt >= FIRST_LONG) /* a flag given a value: --json=1 */
        return tippe_cli_usage_error(spec->verb, "%s takes no value", arg);
    /* an unknown long option, or a prefix of several (getopt_long says 0 for both) */
    size_t len = strcspn(arg + 2, "=");
    char which[256] = "";
    int n = 0;
    for (const tippe_cli_opt *o = spec->opts; o->name && !strncmp(arg, "--", 2); o++)
        if (!strncmp(o->name, arg + 2, len) && strlen(which) + strlen(o->name) + 8 < sizeof which)
            n += snprintf(which + strlen(which), sizeof which - strlen(which), "%s--%s",
                          n ? ", " : "", o->name) > 0;
    if (n > 1) /* a prefix of several: no prefix is an option (inexact_long_name) */
        return tippe_cli_usage_error(spec->verb, "unknown option '%.*s' (did you mean one of "
                                     "%s?)", (int)len + 2, arg, which);
    return tippe_cli_usage_error(spec->verb, "unknown option '%s'", arg);
}

/* getopt_long takes any unique prefix of a long name (--z for --z2): a typing
 * slip then runs with a value meant for another option, and a new option can
 * silently change what a prefix means. Only the whole name is taken. After
 * getopt_long returned the option called name: 0 if it was typed whole, or 2
 * after the usage error. The text is the last argument read, or the one before
 * when the value came separately ("--z2 5"). */
static int inexact_long_name(const tippe_cli_spec *spec, const char *name, char **argv)
{
    const char *arg = argv[optind - 1];
    if (optarg && optarg == argv[optind - 1] && optind >= 2)
        arg = argv[optind - 2];
    if (strncmp(arg, "--", 2))
        return 0;
    const size_t len = strcspn(arg + 2, "=");
    if (len == strlen(name) && !strncmp(arg + 2, name, len))
        return 0;
    return tippe_cli_usage_error(spec->verb, "unknown option '%.*s' (did you mean --%s?)",
                                 (int)len + 2, arg, name);
}

/* Positional arguments and required options: 0, or 2 after a usage error. */
static int check_args(tippe_cli_spec *spec, int argc, char **argv)
{
    const char *what = spec->args_name ? spec->args_name : "file";
    const int n = argc - optind;
    if (n < spec->min_args)
        return tippe_cli_usage_error(spec->verb, "no %s given", what);
    if (n > spec->max_args && spec->max_args == 0)
        return tippe_cli_usage_error(spec->verb, "unexpected argument '%s'", argv[optind]);
    if (n > spec->max_args)
        return tippe_cli_usage_error(spec->verb, "at most %d %s%s (got also '%s')",
                                     spec->max_args, what, spec->max_args > 1 ? "s" : "",
                                     argv[optind + spec->max_args]);
    for (tippe_cli_opt *o = spec->opts; o->name; o++)
        if (o->required && !o->seen) {
            char label[80];
            opt_label(o, label, sizeof label);
            return tippe_cli_usage_error(spec->verb, "%s %s is required", label,
                                         o->arg ? o->arg : "X");
        }
    return 0;
}

int tippe_cli_parse(tippe_cli_spec *spec, int argc, char **argv, const char **args,
                    int *n_args)
{
    struct option lo[MAX_OPTS];
    char shorts[2 * MAX_OPTS + 4];
    if (build_getopt(spec, lo, shorts))
        return tippe_cli_usage_error(spec->verb, "internal error: too many options");
    optind = 0; /* glibc: start afresh (a process may parse more than once) */
    opterr = 0;
    int c, li = -1;
    while ((c = getopt_long(argc, argv, shorts, lo, &li)) != -1) {
        if (li >= 0 && inexact_long_name(spec, lo[li].name, argv))
            return 2;
        li = -1;
        if (c == 'h') {
            if (!spec->quiet_help)
                tippe_cli_help(spec, stdout);
            return TIPPE_CLI_HELP;
        }
        if (c == PROGRESS_OPT) {
            progress_forced = 1;
            continue;
        }
        tippe_cli_opt *o = (c == '?' || c == ':') ? NULL : option_for(spec, c);
        if (!o)
            return getopt_error(spec, c, argv);
        if (store(spec, o, optarg))
            return 2;
        o->seen = 1;
    }
    if (check_args(spec, argc, argv))
        return 2;
    /* getopt_long has moved the positional arguments after the options */
    *n_args = argc - optind;
    for (int i = 0; i < *n_args; i++)
        args[i] = argv[optind + i];
    tippe_cli_note_inputs(args, *n_args);
    const tippe_cli_opt *json = tippe_cli_find_opt(spec, "json");
    tippe_cli_note_json(json && json->seen);
    return 0;
}

/* ---- --help --------------------------------------------------------------- */

/* Prints text indented by indent after its first line. */
static void print_wrapped(FILE *out, const char *text, int indent)
{
    for (const char *p = text; *p; p++) {
        fputc(*p, out);
        if (*p == '\n')
            fprintf(out, "%*s", indent, "");
    }
}

/* "[mm; default 5; 0 .. 100]": what the help line says of the value. A string
 * option that also takes a number (--phi-dot RATE|RULE) shows the number's
 * unit and range when it has them (min < max). */
static void value_note(const tippe_cli_opt *o, char *buf, size_t size)
{
    buf[0] = '\0';
    if (!takes_value(o) || o->kind == TIPPE_CLI_SET ||
        (o->kind == TIPPE_CLI_STRING && !(o->min < o->max)))
        return;
    int n = snprintf(buf, size, "[");
    if (o->unit)
        n += snprintf(buf + n, size - (size_t)n, "%s; ", o->unit);
    if (o->def)
        n += snprintf(buf + n, size - (size_t)n, "default %s; ", o->def);
    else if (o->required)
        n += snprintf(buf + n, size - (size_t)n, "required; ");
    snprintf(buf + n, size - (size_t)n,
             o->kind == TIPPE_CLI_LONG ? "%.0f .. %.0f]" : "%.10g .. %.10g]", o->min, o->max);
}

static void print_option(FILE *out, const tippe_cli_opt *o)
{
    enum { COLUMN = 26 };
    char left[128], note[256];
    const char *arg = o->arg ? o->arg : "X";
    if (o->short_name && !(o->name[1] == '\0' && o->name[0] == o->short_name))
        snprintf(left, sizeof left, "  -%c, --%s%s%s", o->short_name, o->name,
                 takes_value(o) ? " " : "", takes_value(o) ? arg : "");
    else if (o->short_name)
        snprintf(left, sizeof left, "  -%c%s%s", o->short_name, takes_value(o) ? " " : "",
                 takes_value(o) ? arg : "");
    else
        snprintf(left, sizeof left, "  --%s%s%s", o->name, takes_value(o) ? " " : "",
                 takes_value(o) ? arg : "");
    fprintf(out, "%-*s", COLUMN - 1, left);
    if ((int)strlen(left) >= COLUMN - 1)
        fprintf(out, "\n%*s", COLUMN - 1, "");
    fputc(' ', out);
    print_wrapped(out, o->help, COLUMN);
    value_note(o, note, sizeof note);
    if (o->kind == TIPPE_CLI_STRING && o->def && !note[0])
        snprintf(note, sizeof note, "[default %s]", o->def);
    if (note[0])
        fprintf(out, "\n%*s%s", COLUMN, "", note);
    fputc('\n', out);
}

/* The unit language, one line for each family spec's options use. */
static void print_units(const tippe_cli_spec *spec, FILE *out)
{
    int shown = 0;
    for (int u = 0; u < N_UNITS; u++) {
        if (strcmp(units[u].family, units[u].suffix))
            continue; /* from the family's base row */
        int used = 0;
        for (const tippe_cli_opt *o = spec->opts; o->name && !used; o++) {
            int r = unit_row(o->unit);
            used = r >= 0 && !strcmp(units[r].family, units[u].family);
        }
        if (!used)
            continue;
        const char *noun = !strcmp(units[u].family, "rad/s") ? "an angular rate (spin)"
                           : !strcmp(units[u].family, "mm")  ? "a length"
                                                             : "an angle";
        fprintf(out, "%s  %s may carry its unit:", shown++ ? "" : "\nUnits:\n", noun);
        for (int k = 0; k < N_UNITS; k++)
            if (!strcmp(units[k].family, units[u].family))
                fprintf(out, " 2.5%s", units[k].suffix);
        fprintf(out, "\n");
    }
}

void tippe_cli_help(const tippe_cli_spec *spec, FILE *out)
{
    fprintf(out, "usage: tippe %s %s\n\n", spec->verb, spec->synopsis);
    if (spec->about)
        fprintf(out, "%s\n\n", spec->about);
    fprintf(out, "options:\n");
    for (const tippe_cli_opt *o = spec->opts; o->name; o++)
        print_option(out, o);
    if (spec->progress)
        fprintf(out, "      --progress          show progress on stderr even when it is not a\n"
                     "                          terminal: plain lines with done/total and time left\n");
    fprintf(out, "  -h, --help              this text\n");
    print_units(spec, out);
    if (spec->after)
        fprintf(out, "\n%s\n", spec->after);
}
