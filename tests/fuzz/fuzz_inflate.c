/* fuzz_inflate.c - libFuzzer entry for our zlib/DEFLATE decoder (io/inflate.c): any bytes in,
 * data or an error out, never a byte read or written outside the buffers, and the same verdict
 * and bytes as zlib's own inflate. The input is a 3-byte output capacity (little-endian, at most
 * 256 KiB) and the zlib stream; the corpus starts from zlib's streams of each block type
 * (tests/fuzz/make_seeds.c). */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <zlib.h>

#include "io/inflate.h"

#define CAP_MAX (1u << 18)

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* zlib's verdict: 1 with *n bytes when the stream ends inside cap bytes and its Adler-32 holds */
static int zlib_inflate(const uint8_t *src, size_t n, unsigned char *dst, size_t cap, size_t *out) {
    z_stream z;
    memset(&z, 0, sizeof z);
    if (inflateInit(&z) != Z_OK) abort();
    z.next_in = (Bytef *)src;
    z.avail_in = (uInt)n;
    z.next_out = dst;
    z.avail_out = (uInt)cap;
    int r = inflate(&z, Z_FINISH);
    *out = z.total_out;
    inflateEnd(&z);
    return r == Z_STREAM_END;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    if (size < 3) return 0;
    size_t cap = ((size_t)data[0] | (size_t)data[1] << 8 | (size_t)data[2] << 16) % (CAP_MAX + 1);
    const uint8_t *z = data + 3;
    size_t n = size - 3;
    /* exactly cap bytes, so that ASan sees a write past them */
    unsigned char *ours = malloc(cap ? cap : 1), *ref = malloc(cap ? cap : 1);
    if (!ours || !ref) abort();
    size_t got = 0, want = 0;
    ww_error err;
    int ok = ww_zlib_inflate(z, n, ours, cap, &got, &err) == WW_OK;
    int zok = zlib_inflate(z, n, ref, cap, &want);
    if (ok != zok || (ok && (got != want || memcmp(ours, ref, got) != 0))) abort();
    free(ours);
    free(ref);
    return 0;
}
