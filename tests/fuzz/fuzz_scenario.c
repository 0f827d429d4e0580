/* libFuzzer target: a scenario file (tippe_scenario_load, as tippe simulate and
 * tippe animate read it); its "top" may name ../m12-setscrew.json and the other
 * shipped designs. */
#include "fuzz.h"

#include "tippe/scenario.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *path = fuzz_write("scenarios/scenario.json", data, size);
    tippe_scenario sc;
    tippe_error err;
    if (tippe_scenario_load(path, NULL, 0, &sc, &err) == TIPPE_OK)
        tippe_scenario_free(&sc); /* a design top's design */
    return 0;
}
