/* Stubs of the files of printed bodies (src/export/export.c with mesh.c, drawing.c,
 * scad.c and profile.c: lib3MF, cairo, GEOS) for the tippe command: see module.h. */
#include "module.h"
#include "tippe/build.h"
#include "tippe/export.h"

static tippe_module export_module =
    TIPPE_MODULE("export", "GEOS, lib3MF and cairo: apt-get install libgeos-dev lib3mf-dev "
                           "libcairo2-dev");

int tippe_export_plan(const tippe_design *d, const tippe_export_request *q,
                      char (**paths)[4096], tippe_error *err)
{
    __typeof__(&tippe_export_plan) real =
        TIPPE_MODULE_FIND(&export_module, tippe_export_plan, err);
    if (!real)
        *paths = NULL;
    return real ? real(d, q, paths, err) : -1; /* a count, or -1 on failure */
}

int tippe_export_run(const tippe_design *d, const tippe_export_request *q,
                     tippe_export_result *out, tippe_error *err)
{
    TIPPE_MODULE_FILL(&export_module, tippe_export_run, err, out, d, q, out, err);
}

void tippe_export_result_free(tippe_export_result *r)
{
    TIPPE_MODULE_FREE(&export_module, tippe_export_result_free, r);
}

int tippe_export_sheet_write(const tippe_design *d, const tippe_build_sheet *s, const char *path,
                             tippe_error *err)
{
    TIPPE_MODULE_CALL(&export_module, tippe_export_sheet_write, err, d, s, path, err);
}

int tippe_export_gauge_write(const tippe_build_sheet *s, int family, const char *path,
                             tippe_error *err)
{
    TIPPE_MODULE_CALL(&export_module, tippe_export_gauge_write, err, s, family, path, err);
}
