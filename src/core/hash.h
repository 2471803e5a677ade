/* hash.h - 64-bit FNV-1a over bytes: state hashes pinned in tests, exact-image fast paths. */
#ifndef WW_HASH_H
#define WW_HASH_H

#include <stddef.h>
#include <stdint.h>

#define WW_HASH_INIT 0xcbf29ce484222325ULL

uint64_t ww_hash_bytes(uint64_t h, const void *data, size_t n);

#endif
