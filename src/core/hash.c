/* hash.c - FNV-1a, 64-bit (Fowler, Noll, Vo). Not cryptographic; stable across machines. */
#include "core/hash.h"

uint64_t ww_hash_bytes(uint64_t h, const void *data, size_t n) {
    const unsigned char *p = data;
    for (size_t i = 0; i < n; i++) {
        h ^= p[i];
        h *= 0x100000001b3ULL;
    }
    return h;
}
