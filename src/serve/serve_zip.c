/* The files of a build, packed into one zip in memory with libzip (the
 * library lib3MF also uses): nothing of it is written to disk. */
#include "serve/internal.h"

#include <zip.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int tippe_serve_zip_folder(const char *dir, const char *const *names, int n,
                           const serve_zip_member *extra, int n_extra, char **out, size_t *len,
                           tippe_error *err)
{
    *out = NULL;
    *len = 0;
    zip_error_t ze;
    zip_error_init(&ze);
    zip_source_t *src = zip_source_buffer_create(NULL, 0, 0, &ze);
    zip_t *za = src ? zip_open_from_source(src, ZIP_TRUNCATE, &ze) : NULL;
    if (!za) {
        zip_source_free(src);
        zip_error_fini(&ze);
        return tippe_error_set(err, TIPPE_ECOMPUTE, "cannot start a zip (libzip)");
    }
    zip_source_keep(src); /* zip_close writes into it; it is read below */
    int rc = TIPPE_OK;
    char path[4096 + 300];
    for (int i = 0; !rc && i < n; i++) {
        snprintf(path, sizeof path, "%s/%s", dir, names[i]);
        zip_source_t *fs = zip_source_file(za, path, 0, -1);
        if (!fs || zip_file_add(za, names[i], fs, ZIP_FL_ENC_UTF_8) < 0) {
            zip_source_free(fs);
            rc = tippe_error_set(err, TIPPE_ECOMPUTE, "cannot add %s to the zip: %s", names[i],
                                 zip_strerror(za));
        }
    }
    for (int i = 0; !rc && i < n_extra; i++) {
        /* the buffer is the caller's until zip_close below (freep 0) */
        zip_source_t *ms = zip_source_buffer(za, extra[i].data, extra[i].len, 0);
        if (!ms || zip_file_add(za, extra[i].name, ms, ZIP_FL_ENC_UTF_8) < 0) {
            zip_source_free(ms);
            rc = tippe_error_set(err, TIPPE_ECOMPUTE, "cannot add %s to the zip: %s",
                                 extra[i].name, zip_strerror(za));
        }
    }
    if (rc) {
        zip_discard(za);
        zip_source_free(src);
        zip_error_fini(&ze);
        return rc;
    }
    if (zip_close(za) < 0) {
        rc = tippe_error_set(err, TIPPE_ECOMPUTE, "cannot write the zip: %s", zip_strerror(za));
        zip_discard(za);
        zip_source_free(src);
        zip_error_fini(&ze);
        return rc;
    }
    zip_int64_t size = -1;
    char *buf = NULL;
    if (zip_source_open(src) == 0) {
        if (zip_source_seek(src, 0, SEEK_END) == 0 && (size = zip_source_tell(src)) >= 0 &&
            zip_source_seek(src, 0, SEEK_SET) == 0 && (buf = malloc((size_t)size + 1)) &&
            zip_source_read(src, buf, (zip_uint64_t)size) != size) {
            free(buf);
            buf = NULL;
        }
        zip_source_close(src);
    }
    zip_source_free(src);
    zip_error_fini(&ze);
    if (!buf)
        return tippe_error_set(err, TIPPE_ECOMPUTE, "cannot read the zip back (libzip)");
    *out = buf;
    *len = (size_t)size;
    return TIPPE_OK;
}
