/* libFuzzer target: a hardware catalogue, as tippe build reads it and as a spec's
 * catalogue choice reads it
 * (tippe optimise with designs/optimise/drilled-ball-catalogue.json's "choose":
 * {"parts.screw": {"catalogue": "iso4026"}}): the spec is fixed, the
 * catalogue file it names is the input. */
#include "fuzz.h"

#include "tippe/build.h"
#include "tippe/optimise.h"

static const char spec[] =
    "{\"name\": \"fuzz\", \"design\": \"../drilled-ball-blind.json\",\n"
    " \"catalogue\": \"../fuzz-catalogue.json\",\n"
    " \"vary\": {\"parts.hole.z_mm\": [0, 25]},\n"
    " \"choose\": {\"parts.screw\": {\"catalogue\": \"iso4026\"},\n"
    "            \"parts.screw.material\": [\"iron\", \"brass\"]},\n"
    " \"tie\": {\"parts.hole.radius_mm\": \"parts.screw.radius_mm\"},\n"
    " \"objective\": \"narrowest_zone\"}\n";

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static char spec_path[1024];
    if (!spec_path[0]) {
        snprintf(spec_path, sizeof spec_path, "%s",
                 fuzz_write("optimise/catalogue-spec.json", (const uint8_t *)spec,
                            sizeof spec - 1));
    }
    const char *cat = fuzz_write("fuzz-catalogue.json", data, size);
    tippe_error err;
    /* tippe build's reader, which the optimiser's catalogue choice also uses */
    tippe_build_catalogue *c = NULL;
    if (tippe_build_catalogue_load(cat, &c, &err) == TIPPE_OK)
        tippe_build_catalogue_free(c);
    tippe_optimise_spec *s = NULL;
    if (tippe_optimise_spec_load(spec_path, &s, &err) == TIPPE_OK) {
        char label[512];
        for (int c = 0; c < tippe_optimise_spec_n_choices(s) && c < 64; c++)
            tippe_optimise_spec_choice_label(s, c, label, sizeof label);
    }
    tippe_optimise_spec_free(s);
    return 0;
}
