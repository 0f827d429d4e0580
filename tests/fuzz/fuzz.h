/* Shared by the libFuzzer targets of tests/fuzz/ (docs/fuzzing.md): a private
 * scratch directory holding copies of the shipped files an input may name (the
 * materials table, the catalogue, the designs), and the input written there as
 * the file a loader reads, so that each loader runs exactly as a user's file
 * makes it run. Not a library header: each target includes it once. */
#ifndef TIPPE_FUZZ_H
#define TIPPE_FUZZ_H

#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static char fuzz_root[256];

static void fuzz_remove_tree(const char *path)
{
    DIR *d = opendir(path);
    if (d) {
        struct dirent *e;
        while ((e = readdir(d)) != NULL) {
            if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, ".."))
                continue;
            char sub[1024];
            snprintf(sub, sizeof sub, "%s/%s", path, e->d_name);
            fuzz_remove_tree(sub);
        }
        closedir(d);
        rmdir(path);
    } else {
        unlink(path);
    }
}

static void fuzz_cleanup(void)
{
    if (fuzz_root[0])
        fuzz_remove_tree(fuzz_root);
}

/* Copies TIPPE_SOURCE_DIR/designs/NAME to fuzz_root/NAME. */
static void fuzz_copy_shipped(const char *name)
{
    char from[1024], to[1024], buf[65536];
    snprintf(from, sizeof from, "%s/designs/%s", TIPPE_SOURCE_DIR, name);
    snprintf(to, sizeof to, "%s/%s", fuzz_root, name);
    FILE *in = fopen(from, "rb"), *out = fopen(to, "wb");
    if (!in || !out) {
        fprintf(stderr, "fuzz: cannot copy %s to %s\n", from, to);
        abort();
    }
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, in)) > 0)
        fwrite(buf, 1, n, out);
    fclose(in);
    if (fclose(out) != 0)
        abort();
}

/* The scratch directory: fuzz_root with scenarios/ and optimise/ below it, so
 * that the shipped files' relative names ("../catalogue.json") resolve. */
static void fuzz_setup(void)
{
    if (fuzz_root[0])
        return;
    const char *tmp = getenv("TMPDIR");
    snprintf(fuzz_root, sizeof fuzz_root, "%s/tippe-fuzz-XXXXXX", tmp && tmp[0] ? tmp : "/tmp");
    if (!mkdtemp(fuzz_root)) {
        perror("fuzz: mkdtemp");
        abort();
    }
    atexit(fuzz_cleanup);
    char sub[512];
    snprintf(sub, sizeof sub, "%s/scenarios", fuzz_root);
    mkdir(sub, 0777);
    snprintf(sub, sizeof sub, "%s/optimise", fuzz_root);
    mkdir(sub, 0777);
    static const char *const shipped[] = {"materials.json", "catalogue.json",
                                          "m12-setscrew.json", "drilled-ball-blind.json",
                                          "shell-band.json", "shell-rod-iron.json", NULL};
    for (int i = 0; shipped[i]; i++)
        fuzz_copy_shipped(shipped[i]);
}

/* Writes the input as fuzz_root/name and returns its path (static storage). */
static const char *fuzz_write(const char *name, const uint8_t *data, size_t size)
{
    static char path[1024];
    fuzz_setup();
    snprintf(path, sizeof path, "%s/%s", fuzz_root, name);
    FILE *f = fopen(path, "wb");
    if (!f || (size && fwrite(data, 1, size, f) != size) || fclose(f) != 0) {
        perror(path);
        abort();
    }
    return path;
}

#endif
