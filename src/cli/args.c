/* The verbs' argument primitives: usage errors worded one way, numbers, Z2
 * ranges and --set options read one way (the option parser, options.c, and
 * every verb call these). */
#include "cli.h"

#include "tippe/base.h"
#include "tippe/design.h"
#include "tippe/scenario.h"

#include <cjson/cJSON.h>

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int tippe_cli_usage_error(const char *verb, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "tippe %s: ", verb);
    vfprintf(stderr, fmt, ap);
    fprintf(stderr, " (try tippe %s --help)\n", verb);
    va_end(ap);
    return 2;
}

int tippe_cli_fail(const char *verb, const tippe_error *err, int rc)
{
    fprintf(stderr, "tippe %s: %s\n", verb, err->msg);
    return rc == TIPPE_EINPUT ? 2 : 1;
}

int tippe_cli_is_help(const char *arg)
{
    return !strcmp(arg, "--help") || !strcmp(arg, "-h");
}

int tippe_cli_parse_double(const char *text, double *out)
{
    /* No errno test: an underflow to 0 or a subnormal is still the number the
     * user meant, and an overflow is caught as infinite. */
    char *end = NULL;
    *out = strtod(text, &end);
    return end != text && *end == '\0' && isfinite(*out);
}

int tippe_cli_parse_long(const char *text, long lo, long hi, long *out)
{
    char *end = NULL;
    errno = 0;
    long v = strtol(text, &end, 10);
    if (end == text || *end != '\0' || errno != 0 || v < lo || v > hi)
        return 0;
    *out = v;
    return 1;
}

int tippe_cli_parse_range(const char *text, double *from, double *to, int *steps, int max_steps)
{
    char buf[256];
    if (strlen(text) >= sizeof buf)
        return 0;
    snprintf(buf, sizeof buf, "%s", text);
    char *c1 = strchr(buf, ':');
    if (!c1)
        return 0;
    *c1 = '\0';
    char *c2 = strchr(c1 + 1, ':');
    if ((c2 != NULL) != (steps != NULL))
        return 0;
    if (c2)
        *c2 = '\0';
    if (!tippe_cli_parse_double(buf, from) || !tippe_cli_parse_double(c1 + 1, to))
        return 0;
    if (steps) {
        long s;
        if (!tippe_cli_parse_long(c2 + 1, 1, max_steps, &s) || (s == 1 && *from != *to))
            return 0;
        *steps = (int)s;
    }
    return 1;
}

int tippe_cli_sets_add(tippe_cli_sets *s, const char *field, const char *value)
{
    if (s->n == TIPPE_CLI_MAX_SETS)
        return -1;
    if (field) {
        snprintf(s->text[s->n], sizeof s->text[s->n], "%s=%s", field, value);
        s->item[s->n] = s->text[s->n];
    } else {
        s->item[s->n] = value;
    }
    s->n++;
    return 0;
}

int tippe_cli_add_set(const char *verb, tippe_cli_sets *s, const char *value)
{
    if (tippe_cli_sets_add(s, NULL, value))
        return tippe_cli_usage_error(verb, "too many --set options (at most %d)",
                                     TIPPE_CLI_MAX_SETS);
    return 0;
}

const char *tippe_cli_sets_text(const tippe_cli_sets *s, char *buf, size_t size)
{
    size_t len = 0;
    buf[0] = '\0';
    for (int i = 0; i < s->n; i++) {
        int n = snprintf(buf + len, size - len, "%s%s", i ? ", " : "", s->item[i]);
        if (n < 0 || (size_t)n >= size - len) {
            if (size > 4)
                snprintf(buf + size - 4, 4, "...");
            break;
        }
        len += (size_t)n;
    }
    return buf;
}

void tippe_cli_json_sets(cJSON *o, const tippe_cli_sets *s)
{
    cJSON *a = cJSON_AddArrayToObject(o, "set");
    for (int i = 0; a && i < s->n; i++)
        cJSON_AddItemToArray(a, cJSON_CreateString(s->item[i]));
}
