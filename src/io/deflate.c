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
    int count;     /* below 32 between calls */
} bits;

/* up to 32 bits; the pending ones leave four whole bytes at a time */
static void put(bits *b, uint32_t value, int count) {
    b->acc |= (uint64_t)value << b->count;
    b->count += count;
    if (b->count >= 32) {
        uint32_t w = (uint32_t)b->acc;
        unsigned char le[4] = {(unsigned char)w, (unsigned char)(w >> 8), (unsigned char)(w >> 16),
                               (unsigned char)(w >> 24)};
        memcpy(b->out + b->n, le, 4);
        b->n += 4;
        b->acc >>= 32;
        b->count -= 32;
    }
}

/* the pending bits to whole bytes, the last one zero-padded */
static void put_flush(bits *b) {
    for (; b->count > 0; b->count -= 8, b->acc >>= 8) b->out[b->n++] = (unsigned char)b->acc;
    b->count = 0;
}

/* Huffman codes go most significant bit first: reversed into the least-significant-first stream */
static uint32_t reverse(uint32_t code, int count) {
    uint32_t r = 0;
    for (int i = 0; i < count; i++, code >>= 1) r = (r << 1) | (code & 1);
    return r;
}

/* the fixed codes (RFC 1951 3.2.6), reversed once a stream rather than bit by bit per symbol:
 * the literal/length code of each of its 288 symbols with its length, and the 5-bit distance
 * codes; with the length code of each match length and the distance code of each distance
 * (distances up to 256 one by one, longer ones by 128s, where every code's range starts on a
 * multiple of 128, as in zlib's trees.c), instead of a search of the bases per match */
typedef struct codes {
    uint16_t sym[288];
    uint8_t sym_bits[288];
    uint8_t dist[30];
    uint8_t len_code[MAX_MATCH + 1];
    uint8_t dist_code[512];
} codes;

static void codes_make(codes *c) {
    for (int s = 0; s < 288; s++) {
        uint32_t code = s < 144 ? 0x30u + (uint32_t)s
                        : s < 256 ? 0x190u + (uint32_t)(s - 144)
                        : s < 280 ? (uint32_t)(s - 256)
                                  : 0xC0u + (uint32_t)(s - 280);
        int n = s < 144 ? 8 : s < 256 ? 9 : s < 280 ? 7 : 8;
        c->sym[s] = (uint16_t)reverse(code, n);
        c->sym_bits[s] = (uint8_t)n;
    }
    for (int d = 0; d < 30; d++) c->dist[d] = (uint8_t)reverse((uint32_t)d, 5);
    for (int len = 0, l = 0; len <= MAX_MATCH; len++) {
        while (l < 28 && LEN_BASE[l + 1] <= len) l++;
        c->len_code[len] = (uint8_t)l;
    }
    for (int k = 0, d = 0; k < 512; k++) {
        int dist = k < 256 ? k + 1 : ((k - 256) << 7) + 1; /* the first distance of the slot */
        while (d < 29 && DIST_BASE[d + 1] <= dist) d++;
        c->dist_code[k] = (uint8_t)d;
    }
}

static void put_symbol(bits *b, const codes *c, int s) { put(b, c->sym[s], c->sym_bits[s]); }

static void put_match(bits *b, const codes *c, int len, int dist) {
    int l = c->len_code[len];
    put_symbol(b, c, 257 + l);
    put(b, (uint32_t)(len - LEN_BASE[l]), LEN_EXTRA[l]);
    int d = c->dist_code[dist <= 256 ? dist - 1 : 256 + ((dist - 1) >> 7)];
    put(b, c->dist[d], 5);
    put(b, (uint32_t)(dist - DIST_BASE[d]), DIST_EXTRA[d]);
}

static uint32_t hash4(const unsigned char *p) {
    uint32_t v;
    memcpy(&v, p, 4);
    return (v * 2654435761u) >> (32 - HASH_BITS); /* Knuth's multiplicative hash */
}

/* how many of the first `room` bytes of p and q agree */
static size_t common_prefix(const unsigned char *p, const unsigned char *q, size_t room) {
    size_t n = 0;
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    /* eight bytes at a time: read little-endian, the first byte that differs is the lowest
     * nonzero byte of the words' exclusive or */
    for (; n + 8 <= room; n += 8) {
        uint64_t x, y;
        memcpy(&x, p + n, 8);
        memcpy(&y, q + n, 8);
        if (x != y) return n + (size_t)__builtin_ctzll(x ^ y) / 8;
    }
#endif
    while (n < room && p[n] == q[n]) n++;
    return n;
}

unsigned char *ww_zlib_fast(const unsigned char *data, size_t len, size_t *out_len) {
    if (len >= UINT32_MAX) return NULL; /* positions are kept in 32 bits */
    /* worst case: every byte a 9-bit literal, plus the wrapper and the block's end */
    size_t cap = len + len / 8 + 16;
    uint32_t *head = calloc((size_t)1 << HASH_BITS, sizeof *head); /* position + 1; 0: empty */
    bits b = {.out = malloc(cap)};
    codes c;
    codes_make(&c);
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
                best = (int)common_prefix(p, q, room);
                dist = i - (cand - 1);
            }
        }
        if (best < MIN_MATCH) {
            put_symbol(&b, &c, data[i]);
            i++;
            continue;
        }
        put_match(&b, &c, best, (int)dist);
        /* the matched positions enter the table too, so later runs find them */
        size_t end = i + (size_t)best;
        for (i++; i < end && i + MIN_MATCH <= len; i++) head[hash4(data + i)] = (uint32_t)(i + 1);
        i = end;
    }
    put_symbol(&b, &c, 256); /* end of block */
    put_flush(&b);
    uint32_t adler = ww_adler32(1, data, len);
    for (int k = 3; k >= 0; k--) b.out[b.n++] = (unsigned char)(adler >> (8 * k));
    free(head);
    *out_len = b.n;
    return b.out;
}
