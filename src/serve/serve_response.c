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

void tippe_serve_respond_error(serve_response *r, int status, const char *field, const char *fmt, ...)
{
    char msg[1400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    cJSON *o = cJSON_CreateObject();
    if (o) {
        cJSON_AddStringToObject(o, "error", msg);
        if (field)
            cJSON_AddStringToObject(o, "field", field);
        else
            cJSON_AddNullToObject(o, "field");
        cJSON_AddNumberToObject(o, "status", status);
    }
    tippe_serve_respond_json(r, status, o);
}

