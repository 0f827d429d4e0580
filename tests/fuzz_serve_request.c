/* A fuzz target for tippe serve's request reader (libFuzzer): any bytes as a
 * request body, parsed and read as the endpoints read theirs, the design loaded
 * from memory (the design loader, its overrides and checks, under any input).
 * Built with TIPPE_FUZZ=ON and clang it is a libFuzzer binary:
 *     cmake -S . -B build-fuzz -DCMAKE_C_COMPILER=clang -DTIPPE_FUZZ=ON
 *     cmake --build build-fuzz --target fuzz_serve_request
 *     build-fuzz/tests/fuzz_serve_request -max_total_time=600 tests/data/serve-requests
 * Otherwise a main() replays the files given (ctest replays
 * tests/data/serve-requests/, so the target keeps building and running). */
#include "serve/internal.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* Issue 36: a request names no file on disk. Any file the library opens while
 * serving a request, but the designs folder's two tables, is a finding: the
 * target aborts (libFuzzer saves the input; the replay fails). */
static int refuse_any_file(const char *path, const char *what, tippe_error *err)
{
    (void)err;
    static char mat[4200], cat[4200];
    snprintf(mat, sizeof mat, "%s/designs/materials.json", TIPPE_SOURCE_DIR);
    snprintf(cat, sizeof cat, "%s/designs/catalogue.json", TIPPE_SOURCE_DIR);
    if (strcmp(path, mat) && strcmp(path, cat)) {
        fprintf(stderr, "fuzz_serve_request: a request opened the %s file %s\n", what, path);
        abort();
    }
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    tippe_file_set_read_check(refuse_any_file);
    static serve_server s; /* no shipped designs: a name is refused, an object loaded */
    snprintf(s.designs_dir, sizeof s.designs_dir, "%s/designs", TIPPE_SOURCE_DIR);
    static const char *const keys[] = {"design", "z2_mm", "spin_rev_s", "friction", "format",
                                       "from_mm", "to_mm", "name", NULL};
    static const char *const words[] = {"viscous", "coulomb", "coulomb-creep", NULL};
    serve_response r = {0};
    cJSON *req = tippe_serve_request_parse((const char *)data, size, &r);
    if (req) {
        double z2 = 0;
        char stem[80] = "design";
        if (!tippe_serve_request_keys(req, keys, &r) &&
            !tippe_serve_request_number(req, "z2_mm", -1000, 1000, 0, &z2, &r) &&
            tippe_serve_request_word(req, "friction", words, 0, &r) >= 0 &&
            !tippe_serve_request_stem(req, "name", stem, sizeof stem, &r)) {
            tippe_design *d = tippe_serve_request_design(&s, req, "design", stem, &r);
            tippe_top top;
            if (d)
                tippe_design_top_any(d, z2, &top);
            tippe_design_free(d);
        }
        cJSON_Delete(req);
    }
    tippe_serve_response_free(&r);
    return 0;
}

#ifndef TIPPE_LIBFUZZER
int main(int argc, char **argv)
{
    int n = 0;
    for (int i = 1; i < argc; i++) {
        FILE *f = fopen(argv[i], "rb");
        if (!f) {
            fprintf(stderr, "fuzz_serve_request: cannot open %s\n", argv[i]);
            return 1;
        }
        static char buf[1 << 20];
        size_t len = fread(buf, 1, sizeof buf, f);
        fclose(f);
        LLVMFuzzerTestOneInput((const uint8_t *)buf, len);
        n++;
    }
    printf("fuzz_serve_request: replayed %d inputs\n1 passed, 0 failed\n", n);
    return 0;
}
#endif
