/* A response of tippe serve: a JSON body, or a JSON error naming the field. */
#include "serve/internal.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void tippe_serve_response_free(serve_response *r)
{
    free(r->body);
    r->body = NULL;
}

void tippe_serve_respond_json(serve_response *r, int status, cJSON *o)
{
    tippe_serve_response_free(r);
    char *text = o ? cJSON_PrintUnformatted(o) : NULL;
    cJSON_Delete(o);
    if (!text) {
        static const char oom[] = "{\"error\":\"out of memory\",\"field\":null,\"status\":503}";
        r->status = 503;
        r->body = strdup(oom);
        r->len = r->body ? strlen(oom) : 0;
    } else {
        r->status = status;
        r->body = text;
        r->len = strlen(text);
    }
    r->type = "application/json";
}

/* The length of the well-formed UTF-8 character at s (n bytes left), 0 if
 * none starts there (RFC 3629: no overlong forms, no surrogates, at most
 * U+10FFFF). */
static size_t utf8_char(const unsigned char *s, size_t n)
{
    if (s[0] < 0x80)
        return 1;
    size_t len = s[0] >= 0xc2 && s[0] <= 0xdf ? 2 : s[0] >= 0xe0 && s[0] <= 0xef ? 3
                 : s[0] >= 0xf0 && s[0] <= 0xf4                               ? 4
                                                                                : 0;
    if (!len || len > n)
        return 0;
    for (size_t i = 1; i < len; i++)
        if ((s[i] & 0xc0) != 0x80)
            return 0;
    if ((s[0] == 0xe0 && s[1] < 0xa0) || (s[0] == 0xed && s[1] > 0x9f) ||
        (s[0] == 0xf0 && s[1] < 0x90) || (s[0] == 0xf4 && s[1] > 0x8f))
        return 0;
    return len;
}

size_t tippe_serve_clean_text(char *dst, size_t size, const char *src, int escape_controls)
{
    static const char replacement[] = "\xef\xbf\xbd"; /* U+FFFD */
    size_t n = 0, left = strlen(src);
    const unsigned char *s = (const unsigned char *)src;
    if (!size)
        return 0;
    while (left) {
        size_t len = utf8_char(s, left);
        char esc[8];
        const char *out = (const char *)s;
        size_t out_len = len;
        if (!len) { /* not UTF-8 (or a character cut by a %.Ns): replaced */
            out = replacement;
            out_len = 3;
            len = 1;
        } else if (escape_controls && (s[0] < 0x20 || s[0] == 0x7f)) {
            snprintf(esc, sizeof esc, "\\x%02x", s[0]);
            out = esc;
            out_len = 4;
        }
        if (n + out_len >= size)
            break; /* whole characters only */
        memcpy(dst + n, out, out_len);
        n += out_len;
        s += len;
        left -= len;
    }
    dst[n] = '\0';
    return n;
}

void tippe_serve_respond_error(serve_response *r, int status, const char *field, const char *fmt, ...)
{
    char raw[1400], msg[1400 * 3];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(raw, sizeof raw, fmt, ap);
    va_end(ap);
    /* a message may quote the request (a name, a key, a Host): its bytes are
     * not trusted to be UTF-8, and a %.80s may cut a character in two */
    tippe_serve_clean_text(msg, sizeof msg, raw, 0);
    cJSON *o = cJSON_CreateObject();
    if (o) {
        cJSON_AddStringToObject(o, "error", msg);
        char f[600];
        if (field)
            tippe_serve_clean_text(f, sizeof f, field, 1);
        if (field)
            cJSON_AddStringToObject(o, "field", f);
        else
            cJSON_AddNullToObject(o, "field");
        cJSON_AddNumberToObject(o, "status", status);
    }
    tippe_serve_respond_json(r, status, o);
}

