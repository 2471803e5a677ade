/* deflate.c - the fast zlib stream of deflate.h. One final block of fixed Huffman codes (RFC 1951
 * 3.2.6): literals and match lengths on the fixed literal/length code, distances on the 5-bit
 * code, extra bits after each. Matches are found by hashing the next four bytes into a table of
 * last positions (one candidate, checked and extended to 258 bytes), taken greedily; the zlib
 * wrapper (RFC 1950) is a 2-byte header and the Adler-32 of the input (inflate.h), with the
 * tables of rfc1951.h shared with the reader.
 */
#include "io/deflate.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "io/inflate.h"
#include "io/rfc1951.h"

#define HASH_BITS 15
#define WINDOW 32768      /* deflate's largest distance */
#define MIN_MATCH 4       /* shorter matches cost more bits than their literals on fixed codes */

typedef struct bits {
    unsigned char *out;
    size_t n;
    uint64_t acc;  /* pending bits, least significant first */
    int count;
} bits;

static void put(bits *b, uint32_t value, int count) {
    b->acc |= (uint64_t)value << b->count;
    b->count += count;
    while (b->count >= 8) {
        b->out[b->n++] = (unsigned char)b->acc;
        b->acc >>= 8;
        b->count -= 8;
    }
}

/* Huffman codes go most significant bit first: reversed into the least-significant-first stream */
static uint32_t reverse(uint32_t code, int count) {
    uint32_t r = 0;
    for (int i = 0; i < count; i++, code >>= 1) r = (r << 1) | (code & 1);
    return r;
}

/* the fixed literal/length code of symbol s (RFC 1951 3.2.6) */
static void put_symbol(bits *b, int s) {
    if (s < 144)
        put(b, reverse(0x30u + (uint32_t)s, 8), 8);
    else if (s < 256)
        put(b, reverse(0x190u + (uint32_t)(s - 144), 9), 9);
    else if (s < 280)
        put(b, reverse((uint32_t)(s - 256), 7), 7);
    else
        put(b, reverse(0xC0u + (uint32_t)(s - 280), 8), 8);
}

static void put_match(bits *b, int len, int dist) {
    int l = 28;
    while (LEN_BASE[l] > len) l--;
    put_symbol(b, 257 + l);
    put(b, (uint32_t)(len - LEN_BASE[l]), LEN_EXTRA[l]);
    int d = 29;
    while (DIST_BASE[d] > dist) d--;
    put(b, reverse((uint32_t)d, 5), 5);
    put(b, (uint32_t)(dist - DIST_BASE[d]), DIST_EXTRA[d]);
}

static uint32_t hash4(const unsigned char *p) {
    uint32_t v;
    memcpy(&v, p, 4);
    return (v * 2654435761u) >> (32 - HASH_BITS); /* Knuth's multiplicative hash */
}


unsigned char *ww_zlib_fast(const unsigned char *data, size_t len, size_t *out_len) {
    if (len >= UINT32_MAX) return NULL; /* positions are kept in 32 bits */
    /* worst case: every byte a 9-bit literal, plus the wrapper and the block's end */
    size_t cap = len + len / 8 + 16;
    uint32_t *head = calloc((size_t)1 << HASH_BITS, sizeof *head); /* position + 1; 0: empty */
    bits b = {.out = malloc(cap)};
    if (!head || !b.out) {
        free(head);
        free(b.out);
        return NULL;
    }
    b.out[b.n++] = 0x78; /* deflate, 32 KiB window */
    b.out[b.n++] = 0x01; /* fastest; (0x78 * 256 + 0x01) is a multiple of 31 */
    put(&b, 1, 1);       /* BFINAL */
    put(&b, 1, 2);       /* BTYPE 01: fixed codes */

    size_t i = 0;
    while (i < len) {
        int best = 0;
        size_t dist = 0;
        if (i + MIN_MATCH <= len) {
            uint32_t h = hash4(data + i);
            size_t cand = head[h];
            head[h] = (uint32_t)(i + 1);
            if (cand && i - (cand - 1) <= WINDOW) {
                const unsigned char *p = data + cand - 1, *q = data + i;
                size_t room = len - i < MAX_MATCH ? len - i : MAX_MATCH;
                size_t n = 0;
                while (n < room && p[n] == q[n]) n++;
                best = (int)n;
                dist = i - (cand - 1);
            }
        }
        if (best < MIN_MATCH) {
            put_symbol(&b, data[i]);
            i++;
            continue;
        }
        put_match(&b, best, (int)dist);
        /* the matched positions enter the table too, so later runs find them */
        size_t end = i + (size_t)best;
        for (i++; i < end && i + MIN_MATCH <= len; i++) head[hash4(data + i)] = (uint32_t)(i + 1);
        i = end;
    }
    put_symbol(&b, 256); /* end of block */
    if (b.count > 0) b.out[b.n++] = (unsigned char)b.acc; /* the last partial byte, zero-padded */
    uint32_t adler = ww_adler32(1, data, len);
    for (int k = 3; k >= 0; k--) b.out[b.n++] = (unsigned char)(adler >> (8 * k));
    free(head);
    *out_len = b.n;
    return b.out;
}
