/* The plot formats tippe writes (see tippe/plot.h). Apart from plot.c, which
 * draws with PLplot, so that the command checks a plot's file name without
 * loading PLplot (the plotting modules are loaded only to draw). */
#include "plot/canvas.h"

#include <string.h>
#include <strings.h>

const char *tippe_plot_device(const char *path)
{
    const char *dot = path ? strrchr(path, '.') : NULL;
    if (!dot || strchr(dot, '/'))
        return NULL;
    if (!strcasecmp(dot, ".png"))
        return "pngcairo";
    if (!strcasecmp(dot, ".svg"))
        return "svgcairo";
    if (!strcasecmp(dot, ".pdf"))
        return "pdfcairo";
    return NULL;
}
