/* libFuzzer target: an optimisation spec (tippe_optimise_spec_load, as tippe
 * optimise reads it), in optimise/ so that the shipped specs' "../..." designs
 * and catalogue resolve. */
#include "fuzz.h"

#include "tippe/optimise.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *path = fuzz_write("optimise/spec.json", data, size);
    tippe_optimise_spec *s = NULL;
    tippe_error err;
    if (tippe_optimise_spec_load(path, &s, &err) == TIPPE_OK) {
        char label[512];
        for (int c = 0; c < tippe_optimise_spec_n_choices(s) && c < 64; c++)
            tippe_optimise_spec_choice_label(s, c, label, sizeof label);
    }
    tippe_optimise_spec_free(s);
    return 0;
}
