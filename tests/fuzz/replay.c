/* replay.c - a main() for the fuzz targets without libFuzzer: each file named on the command line
 * is read whole and handed to LLVMFuzzerTestOneInput once. `make test` builds every target this
 * way with the project's own compiler and flags (and sanitizers, in the asan build) and replays
 * its committed seeds (tests/fuzz/corpus/NAME/), so a target that stops compiling as the readers
 * change, or a seed that crashes, fails the suite rather than waiting for `make fuzz`. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
/* libFuzzer calls this before the first input when a target defines it */
int LLVMFuzzerInitialize(int *argc, char ***argv) __attribute__((weak));

int main(int argc, char **argv) {
    if (LLVMFuzzerInitialize) LLVMFuzzerInitialize(&argc, &argv);
    int n = 0;
    for (int i = 1; i < argc; i++) {
        FILE *f = fopen(argv[i], "rb");
        if (!f) {
            fprintf(stderr, "replay: cannot open %s\n", argv[i]);
            return 2;
        }
        size_t cap = 1 << 16, len = 0, got;
        uint8_t *buf = malloc(cap);
        while (buf && (got = fread(buf + len, 1, cap - len, f)) > 0)
            if ((len += got) == cap) {
                uint8_t *grown = realloc(buf, cap *= 2);
                if (!grown) free(buf);
                buf = grown;
            }
        fclose(f);
        if (!buf) return 3;
        LLVMFuzzerTestOneInput(buf, len);
        free(buf);
        n++;
    }
    printf("replayed %d inputs\n", n);
    return 0;
}
