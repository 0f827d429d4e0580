/* Stubs of the films (src/animate/animate.c and scene.c, cairo) for the tippe command:
 * see module.h. FFmpeg is opened later still, by src/animate/encode.c. */
#include "module.h"
#include "tippe/animate.h"

static tippe_module animate =
    TIPPE_MODULE("animate", "cairo: apt-get install libcairo2-dev");

int tippe_film_make(const tippe_animate_launch *launch, const tippe_animate_options *opt,
                    tippe_film *film, tippe_error *err)
{
    TIPPE_MODULE_FILL(&animate, tippe_film_make, err, film, launch, opt, film, err);
}

int tippe_film_make_still(const tippe_animate_launch *launch, const tippe_animate_options *opt,
                          double t_s, tippe_film *film, tippe_error *err)
{
    TIPPE_MODULE_FILL(&animate, tippe_film_make_still, err, film, launch, opt, t_s, film, err);
}

void tippe_film_free(tippe_film *film)
{
    TIPPE_MODULE_FREE(&animate, tippe_film_free, film);
}

long tippe_film_work(const tippe_film *film, tippe_film_format format)
{
    /* A film exists only once the module made it. */
    __typeof__(&tippe_film_work) real =
        (__typeof__(&tippe_film_work))tippe_module_function_if_open(&animate, "tippe_film_work");
    return real ? real(film, format) : 0;
}

int tippe_film_write(const tippe_film *film, tippe_film_format format, FILE *out,
                     tippe_progress *prog, tippe_error *err)
{
    TIPPE_MODULE_CALL(&animate, tippe_film_write, err, film, format, out, prog, err);
}

int tippe_film_write_png(const tippe_film *film, FILE *out, tippe_error *err)
{
    TIPPE_MODULE_CALL(&animate, tippe_film_write_png, err, film, out, err);
}
