/* Where the shipped designs and tables are: the checkout's designs/ for a
 * program run from its build tree, the installed share/tippe/designs for an
 * installed one (CMakeLists.txt defines the paths; docs/install.md). */
#define _GNU_SOURCE
#include "tippe/base.h"

#include <dlfcn.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#ifndef TIPPE_BUILD_DIR
#define TIPPE_BUILD_DIR ""
#endif
#ifndef TIPPE_BIN_TO_DATA
#define TIPPE_BIN_TO_DATA "../share/tippe/designs"
#endif
#ifndef TIPPE_LIB_TO_DATA
#define TIPPE_LIB_TO_DATA "../share/tippe/designs"
#endif
#ifndef TIPPE_INSTALL_DATA_DIR
#define TIPPE_INSTALL_DATA_DIR "/usr/local/share/tippe/designs"
#endif

/* A folder is the shipped one if it holds the materials table. */
static int holds_table(const char *dir)
{
    char f[PATH_MAX + 32];
    return snprintf(f, sizeof f, "%s/materials.json", dir) < (int)sizeof f && access(f, R_OK) == 0;
}

/* The directory of the file (program or shared library) holding this code, as
 * dladdr names it, made absolute; 0 if unknown. */
static int own_dir(char *dir, size_t size)
{
    Dl_info info;
    char real[PATH_MAX];
    if (!dladdr((void *)&own_dir, &info) || !info.dli_fname || !info.dli_fname[0])
        return 0;
    /* a program's own name may be bare (argv[0]); /proc/self/exe is then the file */
    const char *name = info.dli_fname;
    char exe[PATH_MAX];
    if (!strchr(name, '/')) {
        ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
        if (n <= 0)
            return 0;
        exe[n] = '\0';
        name = exe;
    }
    if (!realpath(name, real))
        return 0;
    /* realpath gives an absolute path: its folder is never "." */
    return tippe_path_dir(real, dir, size) == TIPPE_OK;
}

int tippe_file_shipped_dir(char *buf, size_t size)
{
    char dir[PATH_MAX], cand[PATH_MAX + 64], build[PATH_MAX];
    int have_dir = own_dir(dir, sizeof dir);
    /* a program or library of the build tree: the checkout it was built from */
    if (have_dir && TIPPE_BUILD_DIR[0] && realpath(TIPPE_BUILD_DIR, build) &&
        !strcmp(dir, build) && holds_table(TIPPE_SOURCE_DIR "/designs"))
        return snprintf(buf, size, "%s", TIPPE_SOURCE_DIR "/designs") < (int)size;
    static const char *const rel[] = {TIPPE_BIN_TO_DATA, TIPPE_LIB_TO_DATA};
    for (int i = 0; have_dir && i < 2; i++) {
        snprintf(cand, sizeof cand, "%s/%s", dir, rel[i]);
        char real[PATH_MAX];
        if (holds_table(cand) && realpath(cand, real))
            return snprintf(buf, size, "%s", real) < (int)size;
    }
    if (holds_table(TIPPE_INSTALL_DATA_DIR))
        return snprintf(buf, size, "%s", TIPPE_INSTALL_DATA_DIR) < (int)size;
    snprintf(buf, size, "%s/%s, %s", have_dir ? dir : "(the program's folder)", TIPPE_BIN_TO_DATA,
             TIPPE_INSTALL_DATA_DIR);
    return 0;
}
