/* Paths of the files a file names (a design's materials table, catalogue and
 * G-code, a scenario's design, a spec's base design): one rule, "relative to
 * the folder of the file that names it", written once (issue 34: it was written
 * out by hand in 18 places). Plain string work: nothing here touches the disk. */
#include "tippe/base.h"

#include <stdio.h>
#include <string.h>

/* Where the name starts: after the last '/'. */
const char *tippe_path_base(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

/* "." for a bare name and "/" for a file at the root, as dirname(3) says them,
 * so that the folder can be opened or resolved as it stands. */
int tippe_path_dir(const char *path, char *out, size_t size)
{
    const char *slash = strrchr(path, '/');
    int n = !slash           ? snprintf(out, size, ".")
            : slash == path ? snprintf(out, size, "/")
                            : snprintf(out, size, "%.*s", (int)(slash - path), path);
    return n < 0 || (size_t)n >= size ? TIPPE_EINPUT : TIPPE_OK;
}

/* An absolute name stands alone; a relative one is joined to the folder part
 * of path as written (no "./" added for a bare path, so messages quote the
 * name as the user wrote it). */
int tippe_path_beside(const char *path, const char *name, char *out, size_t size)
{
    const char *slash = strrchr(path, '/');
    int n = name[0] == '/' || !slash
                ? snprintf(out, size, "%s", name)
                : snprintf(out, size, "%.*s/%s", (int)(slash - path), path, name);
    return n < 0 || (size_t)n >= size ? TIPPE_EINPUT : TIPPE_OK;
}

/* A file's stem names what is made from it ("m12-setscrew.stl"); a name that
 * is all extension (".json") keeps it, so the stem is never empty. */
void tippe_path_stem(const char *path, char *out, size_t size)
{
    snprintf(out, size, "%s", tippe_path_base(path));
    char *dot = strrchr(out, '.');
    if (dot && dot != out)
        *dot = '\0';
}

/* A dot in a folder's name is not an extension ("out.d/plot"). */
const char *tippe_path_ext(const char *path)
{
    const char *dot = strrchr(path, '.'), *slash = strrchr(path, '/');
    return (dot && (!slash || dot > slash)) ? dot + 1 : "";
}
