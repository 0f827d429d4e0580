/* Output files written atomically (see tippe/report.h). */
#include "tippe/report.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

int tippe_report_open(tippe_report_file *rf, const char *path, const char *what,
                      tippe_error *err)
{
    rf->f = NULL;
    rf->what = what;
    rf->tmp_path[0] = '\0';
    if (snprintf(rf->path, sizeof rf->path, "%s", path) >= (int)sizeof rf->path)
        return tippe_error_set(err, TIPPE_EINPUT, "%s: path too long", path);
    /* Same directory as the target, so that the final rename is atomic. */
    snprintf(rf->tmp_path, sizeof rf->tmp_path, "%s.tmp.XXXXXX", path);
    int fd = mkstemp(rf->tmp_path);
    if (fd < 0)
        return tippe_error_set(err, TIPPE_EINPUT, "%s: cannot write %s here: %s", path, what,
                               strerror(errno));
    mode_t mask = umask(0);
    umask(mask);
    if (fchmod(fd, 0666 & ~mask) != 0 || !(rf->f = fdopen(fd, "w"))) {
        int e = errno;
        close(fd);
        unlink(rf->tmp_path);
        return tippe_error_set(err, TIPPE_ECOMPUTE, "%s: cannot write %s: %s", path, what,
                               strerror(e));
    }
    return TIPPE_OK;
}

int tippe_report_commit(tippe_report_file *rf, tippe_error *err)
{
    int bad = 0;
    if (rf->f) {
        bad = ferror(rf->f);
        if (fclose(rf->f) != 0)
            bad = 1;
        rf->f = NULL;
    }
    int status = TIPPE_OK;
    if (bad)
        status = tippe_error_set(err, TIPPE_ECOMPUTE, "%s: writing %s failed", rf->path, rf->what);
    else if (rename(rf->tmp_path, rf->path) != 0)
        status = tippe_error_set(err, TIPPE_ECOMPUTE, "%s: cannot rename %s into place: %s",
                                 rf->path, rf->what, strerror(errno));
    if (status != TIPPE_OK)
        unlink(rf->tmp_path);
    return status;
}

void tippe_report_abort(tippe_report_file *rf)
{
    if (rf->f)
        fclose(rf->f);
    rf->f = NULL;
    unlink(rf->tmp_path);
}
