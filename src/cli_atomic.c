#include "cli.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

FILE *tippe_cli_open_atomic(const char *path, char *tmp_path, size_t tmp_size)
{
    /* Same directory as the target, so that rename() is atomic. */
    int n = snprintf(tmp_path, tmp_size, "%s.tmp.XXXXXX", path);
    if (n < 0 || (size_t)n >= tmp_size)
        return NULL;
    int fd = mkstemp(tmp_path);
    if (fd < 0)
        return NULL;
    /* mkstemp creates the file 0600; an output file should get the permissions
     * fopen would give it (0666 less the umask). */
    mode_t mask = umask(0);
    umask(mask);
    if (fchmod(fd, 0666 & ~mask) != 0) {
        close(fd);
        unlink(tmp_path);
        return NULL;
    }
    FILE *f = fdopen(fd, "w");
    if (!f) {
        close(fd);
        unlink(tmp_path);
    }
    return f;
}

int tippe_cli_commit_atomic(FILE *f, const char *tmp_path, const char *path)
{
    int bad = ferror(f);
    if (fclose(f) != 0)
        bad = 1;
    if (bad || rename(tmp_path, path) != 0) {
        unlink(tmp_path);
        return -1;
    }
    return 0;
}

void tippe_cli_abort_atomic(FILE *f, const char *tmp_path)
{
    if (f)
        fclose(f);
    unlink(tmp_path);
}
