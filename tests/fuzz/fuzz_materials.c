/* libFuzzer target: a materials table (tippe_materials_load, as tippe materials
 * reads it), and the shipped M12 design reading it (as every design does). */
#include "fuzz.h"

#include "tippe/design.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *path = fuzz_write("materials.json", data, size);
    tippe_materials *t = NULL;
    tippe_error err;
    if (tippe_materials_load(path, &t, &err) == TIPPE_OK) {
        for (int i = 0; i < tippe_materials_count(t); i++) {
            tippe_material m;
            tippe_materials_get(t, i, &m);
        }
        tippe_materials_free(t);
        /* the design's table is this one: materials.json beside it */
        static char design[1024];
        snprintf(design, sizeof design, "%s/m12-setscrew.json", fuzz_root);
        tippe_design *d = NULL;
        tippe_design_load(design, NULL, 0, &d, &err);
        tippe_design_free(d);
    }
    return 0;
}
