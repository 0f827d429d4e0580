/* The tippe command's heavy-library modules (private to the command).
 *
 * The parts of the library that call PLplot, GEOS, lib3MF or cairo are compiled
 * once and linked twice: into libtippe.a, as every other part, and into modules
 * placed next to the tippe command (tippe-plot.so, tippe-profile.so, tippe-export.so,
 * tippe-animate.so; CMakeLists.txt says which sources each holds). The command
 * links the rest of the library and, instead of those parts, the stubs in this
 * folder: functions with the same names and prototypes (from include/tippe/)
 * that open their module on the first call and forward to it. So a command that
 * draws nothing loads none of the drawing libraries: linked, their 35 shared
 * objects made `tippe --help` cost 30 M instructions instead of 0.6 M
 * (callgrind). The modules call back into the library through the command's
 * exported symbols; the stubs never print, a missing module is an error. */
#ifndef TIPPE_MODULE_H
#define TIPPE_MODULE_H

#include "tippe/base.h"

#include <limits.h>
#include <pthread.h>
#include <string.h>

typedef struct {
    const char *name;  /* "plot": the file tippe-plot.so */
    const char *needs; /* the libraries it loads, with their Debian packages */
    pthread_mutex_t lock;
    int tried;
    void *handle; /* NULL until it is open; then open for the life of the process */
    char error[PATH_MAX + 1024];
} tippe_module;

#define TIPPE_MODULE(name, needs) {name, needs, PTHREAD_MUTEX_INITIALIZER, 0, NULL, ""}

/* The module's function `symbol`, opening the module (from the directory of the
 * running executable) on the first call; NULL with err set (TIPPE_ECOMPUTE) when
 * the module or the function is missing. Thread-safe. */
void *tippe_module_function(tippe_module *m, const char *symbol, tippe_error *err);

/* The module's function `symbol` if the module is already open, else NULL
 * (for a stub that frees: what a module never made needs no freeing). */
void *tippe_module_function_if_open(tippe_module *m, const char *symbol);

/* TIPPE_OK if the plotting module loads, else TIPPE_ECOMPUTE with err set: the
 * command checks it with a plot's output path, before any work. */
int tippe_module_plot_ready(tippe_error *err);

/* The module's function fn (a typed pointer), or NULL with err set. */
#define TIPPE_MODULE_FIND(m, fn, err) ((__typeof__(&fn))tippe_module_function(m, #fn, err))

/* The body of a stub that returns a tippe status: calls the module's fn with
 * the stub's arguments, or returns TIPPE_ECOMPUTE with err set. */
#define TIPPE_MODULE_CALL(m, fn, err, ...)                                                       \
    do {                                                                                         \
        __typeof__(&fn) real_ = TIPPE_MODULE_FIND(m, fn, err);                                   \
        return real_ ? real_(__VA_ARGS__) : TIPPE_ECOMPUTE;                                      \
    } while (0)

/* The same for a function that fills *out: without its module, *out is zeroed,
 * as the module's own failures leave it (the caller may read or free it). */
#define TIPPE_MODULE_FILL(m, fn, err, out, ...)                                                  \
    do {                                                                                         \
        __typeof__(&fn) real_ = TIPPE_MODULE_FIND(m, fn, err);                                   \
        if (real_)                                                                               \
            return real_(__VA_ARGS__);                                                           \
        memset(out, 0, sizeof *out);                                                             \
        return TIPPE_ECOMPUTE;                                                                   \
    } while (0)

/* The body of a stub that frees: calls the module's fn if the module is open. */
#define TIPPE_MODULE_FREE(m, fn, ...)                                                            \
    do {                                                                                         \
        __typeof__(&fn) real_ = (__typeof__(&fn))tippe_module_function_if_open(m, #fn);          \
        if (real_)                                                                               \
            real_(__VA_ARGS__);                                                                  \
    } while (0)

#endif
