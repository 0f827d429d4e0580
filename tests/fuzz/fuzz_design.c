/* libFuzzer target: a design file (tippe_design_load), then the top at the
 * middle of its travel and its warnings, as tippe eval reads a design. */
#include "fuzz.h"

#include "tippe/design.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *path = fuzz_write("design.json", data, size);
    tippe_design *d = NULL;
    tippe_error err;
    if (tippe_design_load(path, NULL, 0, &d, &err) == TIPPE_OK) {
        double from, to;
        tippe_design_travel_mm(d, &from, &to);
        tippe_top top;
        tippe_design_top(d, 0.5 * (from + to), &top, &err);
        char msg[512];
        for (int i = 0; i < 8 && tippe_design_warning(d, i, msg, sizeof msg); i++)
            ;
    }
    tippe_design_free(d);
    return 0;
}
