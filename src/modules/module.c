/* Opening the command's heavy-library modules (see module.h), in the manner
 * of src/animate/encode.c with FFmpeg: on the first call that needs one. */
#include "module.h"

#include <dlfcn.h>
#include <limits.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#ifndef TIPPE_BIN_TO_MODULES
#define TIPPE_BIN_TO_MODULES "../lib/tippe"
#endif

/* The module's path: next to the running executable (a build tree, as
 * tippe-mpi is found), else in the installed module folder relative to it
 * (PREFIX/bin/tippe opens PREFIX/lib/tippe/tippe-plot.so; CMakeLists.txt). */
static int module_path(const tippe_module *m, char *path, size_t size)
{
    char exe[PATH_MAX];
    ssize_t len = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (len <= 0)
        return 0;
    exe[len] = '\0';
    char name[64], rel[128];
    snprintf(name, sizeof name, "tippe-%s.so", m->name);
    if (tippe_path_beside(exe, name, path, size) != TIPPE_OK)
        return 0;
    if (access(path, F_OK) == 0)
        return 1;
    char installed[PATH_MAX + 64];
    snprintf(rel, sizeof rel, TIPPE_BIN_TO_MODULES "/%s", name);
    if (tippe_path_beside(exe, rel, installed, sizeof installed) == TIPPE_OK &&
        access(installed, F_OK) == 0)
        return snprintf(path, size, "%s", installed) < (int)size;
    return 1; /* neither: the error names the path beside the program */
}

static void module_open(tippe_module *m)
{
    char path[PATH_MAX + 32];
    if (!module_path(m, path, sizeof path)) {
        snprintf(m->error, sizeof m->error,
                 "cannot find the directory of the running program (/proc/self/exe) to load "
                 "tippe-%s.so from", m->name);
        return;
    }
    /* RTLD_NOW: a module that does not fit this program fails here, with a
     * message, and not at some later call. */
    m->handle = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (m->handle)
        return;
    /* dlerror() often starts with the path: say it once. */
    const char *why = dlerror();
    const size_t n = strlen(path);
    if (!strncmp(why, path, n) && !strncmp(why + n, ": ", 2))
        why += n + 2;
    snprintf(m->error, sizeof m->error,
             "cannot load %s (built with the tippe program; it needs %s): %s", path, m->needs,
             why);
}

void *tippe_module_function(tippe_module *m, const char *symbol, tippe_error *err)
{
    pthread_mutex_lock(&m->lock);
    if (!m->tried) {
        module_open(m);
        m->tried = 1;
    }
    void *fn = m->handle ? dlsym(m->handle, symbol) : NULL;
    pthread_mutex_unlock(&m->lock);
    if (!m->handle)
        tippe_error_set(err, TIPPE_ECOMPUTE, "%s", m->error);
    else if (!fn)
        tippe_error_set(err, TIPPE_ECOMPUTE, "tippe-%s.so has no %s: it does not belong to this "
                        "tippe program (rebuild both)", m->name, symbol);
    return fn;
}

void *tippe_module_function_if_open(tippe_module *m, const char *symbol)
{
    pthread_mutex_lock(&m->lock);
    void *fn = m->handle ? dlsym(m->handle, symbol) : NULL;
    pthread_mutex_unlock(&m->lock);
    return fn;
}
