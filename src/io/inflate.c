/* inflate.c - the zlib / DEFLATE decoder of inflate.h (RFC 1950 around RFC 1951).
 *
 * The method is the one of zlib's inflate_fast (Mark Adler, zlib doc/algorithm.txt) and of
 * libdeflate's decompressor design notes (Eric Biggers): a 64-bit bit buffer refilled with one
 * 8-byte load, Huffman codes decoded by one lookup in a primary table indexed by the next
 * LITLEN_BITS / DIST_BITS bits (sub-tables for the rare longer codes), matches copied 8 bytes at a
 * time, and a fast loop that checks nothing but its margins while plenty of input and output
 * remain; a careful loop, bounds-checked at every step, finishes each block near the ends.
 */
#include "io/inflate.h"

#include <string.h>

#include "io/rfc1951.h"

#define LITLEN_BITS 11    /* primary table index bits: one lookup for codes up to 11 bits */
#define DIST_BITS 8
#define CLEN_BITS 7       /* code length codes are at most 7 bits long: no sub-tables */
#define MAX_CODE_BITS 15  /* RFC 1951 3.2.2 */
#define NUM_LITLEN 288    /* literal/length symbols 0..287 (286 and 287 never occur in data) */
#define NUM_DIST 32       /* distance symbols 0..31 (30 and 31 never occur in data) */
#define NUM_CLEN 19       /* code length symbols 0..18 */
#define MAX_HLIT 286
#define MAX_HDIST 30
#define END_OF_BLOCK 256
#define FIXED_DIST_LEN 5

/* a table holds its primary part and, at worst, one sub-table of the largest size for each symbol
 * whose code is longer than the primary index (each sub-table holds at least one such code) */
#define TABLE_SIZE(bits, nsym) ((1 << (bits)) + (nsym) * (1 << (MAX_CODE_BITS - (bits))))
#define LITLEN_TABLE_SIZE TABLE_SIZE(LITLEN_BITS, NUM_LITLEN)
#define DIST_TABLE_SIZE TABLE_SIZE(DIST_BITS, NUM_DIST)
#define CLEN_TABLE_SIZE (1 << CLEN_BITS)

/* the fast loop runs while it may refill twice (8-byte loads, at most 7 bytes taken each) and
 * write the longest match plus the 15 bytes a word copy may run over */
#define FAST_IN_MARGIN 16
#define FAST_OUT_MARGIN (MAX_MATCH + 16)


/* RFC 1951 3.2.7: the order in which code length code lengths are sent */
static const uint8_t CLEN_ORDER[NUM_CLEN] = {16, 17, 18, 0, 8,  7, 9,  6, 10, 5,
                                             11, 4,  12, 3, 13, 2, 14, 1, 15};

/* a table entry, one 32-bit word: value << 16 | kind << 8 | extra bits << 4 | code bits.
 * A sub-table pointer holds the sub-table's start as value, its index bits as extra and the
 * primary index bits as code bits; a sub-table entry holds the whole code length. */
enum { K_LIT, K_LEN, K_EOB, K_SUB, K_BAD };
#define E_BITS(e) ((e) & 15u)
#define E_EXTRA(e) (((e) >> 4) & 15u)
#define E_KIND(e) (((e) >> 8) & 7u)
#define E_VAL(e) ((e) >> 16)
#define ENTRY(val, kind, extra) ((uint32_t)(val) << 16 | (uint32_t)(kind) << 8 | (uint32_t)(extra) << 4)
#define MASK(n) ((1u << (n)) - 1u)

enum { T_LITLEN, T_DIST, T_CLEN };

typedef struct inflater {
    const unsigned char *in, *in_end;          /* next unread byte, end of the input */
    unsigned char *out, *out_start, *out_end;  /* next byte to write, the caller's buffer */
    uint64_t bitbuf;   /* unread bits, the next one lowest; bits above bitsleft may already hold
                        * the start of the byte at `in` (an 8-byte refill), never anything else */
    unsigned bitsleft; /* valid bits in bitbuf, 0..63 */
    unsigned overrun;  /* zero bytes fed past the end of the input (an error once consumed) */
    int fixed_built;   /* litlen/dist hold the fixed codes */
    ww_error *err;
    uint32_t litlen[LITLEN_TABLE_SIZE];
    uint32_t dist[DIST_TABLE_SIZE];
    uint32_t clen[CLEN_TABLE_SIZE];
    uint8_t lens[NUM_LITLEN + NUM_DIST];
} inflater;

static ww_result fail(inflater *s, const char *what) {
    return ww_error_set(s->err, WW_E_TYPE, NULL, 0, 0, "zlib: %s", what);
}

static uint64_t load_le64(const unsigned char *p) {
    uint64_t v;
    memcpy(&v, p, 8);
#if __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
    v = __builtin_bswap64(v);
#endif
    return v;
}

/* ---- bits ---------------------------------------------------------------------------------- */

/* careful refill, a byte at a time, to 49..56 bits (never 64: the fast refill shifts by bitsleft);
 * past the end of the input it feeds zero bytes and counts them, so a Huffman lookup near the end
 * may peek 15 bits; consuming one of them is "truncated" */
#define SLOW_REFILL_BITS 48
static void refill_slow(inflater *s) {
    while (s->bitsleft <= SLOW_REFILL_BITS) {
        uint64_t b = 0;
        if (s->in < s->in_end)
            b = *s->in++;
        else
            s->overrun++;
        s->bitbuf |= b << s->bitsleft;
        s->bitsleft += 8;
    }
}

/* a zero byte fed past the end has been consumed */
static int past_end(const inflater *s) { return s->overrun * 8u > s->bitsleft; }

static uint32_t get_bits(inflater *s, unsigned n) {
    if (s->bitsleft < n) refill_slow(s);
    uint32_t v = (uint32_t)(s->bitbuf & MASK(n));
    s->bitbuf >>= n;
    s->bitsleft -= n;
    return v;
}

/* drop the bits up to the next byte boundary and give the whole bytes still in the bit buffer
 * back to the input (stored blocks and the Adler-32 are read as bytes); -1: truncated */
static int align_to_byte(inflater *s) {
    s->bitsleft -= s->bitsleft & 7u;
    unsigned bytes = s->bitsleft >> 3;
    if (bytes < s->overrun) return -1;
    s->in -= bytes - s->overrun;
    s->bitbuf = 0;
    s->bitsleft = 0;
    s->overrun = 0;
    return 0;
}

/* ---- Huffman tables (RFC 1951 3.2.2) ------------------------------------------------------ */

static uint32_t symbol_entry(int type, int sym) {
    if (type == T_CLEN) return ENTRY(sym, K_LIT, 0);
    if (type == T_DIST) return sym < 30 ? ENTRY(DIST_BASE[sym], K_LEN, DIST_EXTRA[sym]) : ENTRY(0, K_BAD, 0);
    if (sym < END_OF_BLOCK) return ENTRY(sym, K_LIT, 0);
    if (sym == END_OF_BLOCK) return ENTRY(0, K_EOB, 0);
    if (sym < 286) return ENTRY(LEN_BASE[sym - 257], K_LEN, LEN_EXTRA[sym - 257]);
    return ENTRY(0, K_BAD, 0);
}

static uint32_t reverse_bits(uint32_t code, unsigned n) {
    uint32_t r = 0;
    for (unsigned i = 0; i < n; i++, code >>= 1) r = r << 1 | (code & 1u);
    return r;
}

/* the longest code of the sub-table that the code `code` of length len (sorted index i) opens:
 * canonical codes sharing their first `root` bits follow one another in sorted order */
static unsigned subtable_bits(const uint16_t *sorted, const uint8_t *lens, int i, int ncodes,
                              uint32_t code, unsigned root) {
    unsigned len = lens[sorted[i]], last = len;
    uint32_t prefix = code >> (len - root);
    for (int k = i + 1; k < ncodes; k++) {
        unsigned l = lens[sorted[k]];
        code = (code + 1) << (l - last);
        last = l;
        if (code >> (l - root) != prefix) break;
        len = l;
    }
    return len - root;
}

/* the decoding table of the code given by its code lengths; -1 when the lengths are not a
 * code: over-subscribed, or incomplete other than a lone 1-bit code (RFC 1951 3.2.7: "one
 * distance code of one bit") or none at all (a block of literals only); the code length code
 * must be complete */
static int build_table(uint32_t *table, size_t cap, unsigned root, const uint8_t *lens, int nsym,
                       int type) {
    uint16_t count[MAX_CODE_BITS + 1] = {0}, offs[MAX_CODE_BITS + 2];
    uint16_t sorted[NUM_LITLEN];
    for (int i = 0; i < nsym; i++) count[lens[i]]++;
    count[0] = 0;

    /* Kraft's inequality, counted in codes still free at each length */
    int left = 1, ncodes = 0;
    for (int len = 1; len <= MAX_CODE_BITS; len++) {
        left = 2 * left - count[len];
        if (left < 0) return -1;
        ncodes += count[len];
    }
    if (left > 0) {
        int lone = ncodes == 1 && count[1] == 1;
        if (type == T_CLEN || !(ncodes == 0 || lone)) return -1;
        for (size_t j = 0; j < ((size_t)1 << root); j++) table[j] = ENTRY(0, K_BAD, 0);
        if (ncodes == 0) return 0;
    }

    /* symbols sorted by code length, then by value: the canonical order */
    offs[1] = 0;
    for (int len = 1; len <= MAX_CODE_BITS; len++) offs[len + 1] = (uint16_t)(offs[len] + count[len]);
    for (int i = 0; i < nsym; i++)
        if (lens[i]) sorted[offs[lens[i]]++] = (uint16_t)i;

    /* codes in canonical order are consecutive numbers, shifted left as the length grows; each
     * fills every table slot whose low bits are its bit-reversed code */
    uint32_t code = 0, sub_prefix = UINT32_MAX;
    unsigned prev = lens[sorted[0]], sub_bits = 0;
    size_t next_free = (size_t)1 << root, sub_start = 0;
    for (int i = 0; i < ncodes; i++) {
        unsigned len = lens[sorted[i]];
        if (i > 0) code = (code + 1) << (len - prev);
        prev = len;
        uint32_t rev = reverse_bits(code, len), e = symbol_entry(type, sorted[i]) | len;
        if (len <= root) {
            for (uint32_t j = rev; j < (1u << root); j += 1u << len) table[j] = e;
            continue;
        }
        if (code >> (len - root) != sub_prefix) {
            sub_prefix = code >> (len - root);
            sub_bits = subtable_bits(sorted, lens, i, ncodes, code, root);
            sub_start = next_free;
            next_free += (size_t)1 << sub_bits;
            if (next_free > cap) return -1; /* cannot happen for a code that passed Kraft */
            table[rev & MASK(root)] = ENTRY(sub_start, K_SUB, sub_bits) | root;
        }
        for (uint32_t j = rev >> root; j < (1u << sub_bits); j += 1u << (len - root))
            table[sub_start + j] = e;
    }
    return 0;
}

/* ---- decoding ----------------------------------------------------------------------------- */

static uint32_t lookup(const uint32_t *table, unsigned root, uint64_t bits) {
    uint32_t e = table[bits & MASK(root)];
    if (E_KIND(e) == K_SUB) e = table[E_VAL(e) + ((bits >> root) & MASK(E_EXTRA(e)))];
    return e;
}

static uint32_t decode_slow(inflater *s, const uint32_t *table, unsigned root) {
    refill_slow(s);
    uint32_t e = lookup(table, root, s->bitbuf);
    s->bitbuf >>= E_BITS(e);
    s->bitsleft -= E_BITS(e);
    return e;
}

/* the smallest multiple of a distance 1..7 that is at least 8 (no division in the copy) */
static const uint8_t PERIOD_WORD[8] = {0, 8, 8, 9, 8, 10, 12, 14};

static void copy8(unsigned char *dst, const unsigned char *src) {
    uint64_t v;
    memcpy(&v, src, 8);
    memcpy(dst, &v, 8);
}

/* copy a match of len bytes from dist back, 8 bytes at a time with the first 16 (most matches)
 * unconditional; may write up to 15 bytes past out + len. A distance under 8 repeats a pattern
 * of dist bytes: after its first 8 bytes, copied one at a time, the bytes PERIOD_WORD[dist] back
 * (a multiple of dist, at least 8) are the same ones, so the rest goes in words from there */
static void copy_match_fast(unsigned char *out, size_t dist, size_t len) {
    unsigned char *end = out + len;
    const unsigned char *src = out - dist;
    if (dist >= 8) {
        copy8(out, src);
        copy8(out + 8, src + 8);
        out += 16;
        src += 16;
    } else {
        for (int i = 0; i < 8; i++) out[i] = src[i];
        out += 8;
        src = out - PERIOD_WORD[dist];
    }
    while (out < end) {
        copy8(out, src);
        out += 8;
        src += 8;
    }
}

/* the fast loop of a Huffman block: returns 1 at the end of the block, 0 when the margins ran out,
 * -1 on an error (set) */
static int huffman_fast(inflater *s) {
    const unsigned char *in = s->in, *in_end = s->in_end;
    unsigned char *out = s->out, *out_end = s->out_end;
    uint64_t bb = s->bitbuf;
    unsigned bl = s->bitsleft;
    const uint32_t *lt = s->litlen, *dt = s->dist;
    int status = 0;

    while ((size_t)(in_end - in) >= FAST_IN_MARGIN && (size_t)(out_end - out) >= FAST_OUT_MARGIN) {
        /* refill to 56..63 bits with one load; the bits above bl are the next byte's own */
        bb |= load_le64(in) << bl;
        in += (63 - bl) >> 3;
        bl |= 56;

        /* up to two literals from one refill (each code is at most 15 bits) */
        uint32_t e = lookup(lt, LITLEN_BITS, bb);
        if (E_KIND(e) == K_LIT) {
            bb >>= E_BITS(e);
            bl -= E_BITS(e);
            *out++ = (unsigned char)E_VAL(e);
            e = lookup(lt, LITLEN_BITS, bb);
            if (E_KIND(e) == K_LIT) {
                bb >>= E_BITS(e);
                bl -= E_BITS(e);
                *out++ = (unsigned char)E_VAL(e);
                continue;
            }
        }
        bb >>= E_BITS(e);
        bl -= E_BITS(e);
        if (E_KIND(e) != K_LEN) {
            status = E_KIND(e) == K_EOB ? 1 : -1;
            if (status < 0) fail(s, "bad literal/length code");
            break;
        }
        size_t len = E_VAL(e) + (size_t)(bb & MASK(E_EXTRA(e)));
        bb >>= E_EXTRA(e);
        bl -= E_EXTRA(e);

        /* a second refill for the distance (a literal may have gone before the length) */
        bb |= load_le64(in) << bl;
        in += (63 - bl) >> 3;
        bl |= 56;
        e = lookup(dt, DIST_BITS, bb);
        bb >>= E_BITS(e);
        bl -= E_BITS(e);
        if (E_KIND(e) != K_LEN) {
            status = -1;
            fail(s, "bad distance code");
            break;
        }
        size_t dist = E_VAL(e) + (size_t)(bb & MASK(E_EXTRA(e)));
        bb >>= E_EXTRA(e);
        bl -= E_EXTRA(e);
        if (dist > (size_t)(out - s->out_start)) {
            status = -1;
            ww_error_set(s->err, WW_E_TYPE, NULL, 0, 0,
                         "zlib: distance %zu before the start of the output", dist);
            break;
        }
        copy_match_fast(out, dist, len);
        out += len;
    }
    s->in = in;
    s->out = out;
    s->bitbuf = bb;
    s->bitsleft = bl;
    return status;
}

/* the careful loop: every read and write checked */
static ww_result huffman_slow(inflater *s) {
    for (;;) {
        uint32_t e = decode_slow(s, s->litlen, LITLEN_BITS);
        if (past_end(s)) return fail(s, "truncated");
        if (E_KIND(e) == K_LIT) {
            if (s->out == s->out_end) goto too_large;
            *s->out++ = (unsigned char)E_VAL(e);
            continue;
        }
        if (E_KIND(e) == K_EOB) return WW_OK;
        if (E_KIND(e) != K_LEN) return fail(s, "bad literal/length code");
        size_t len = E_VAL(e) + get_bits(s, E_EXTRA(e));
        e = decode_slow(s, s->dist, DIST_BITS);
        if (E_KIND(e) != K_LEN) return past_end(s) ? fail(s, "truncated") : fail(s, "bad distance code");
        size_t dist = E_VAL(e) + get_bits(s, E_EXTRA(e));
        if (past_end(s)) return fail(s, "truncated");
        if (dist > (size_t)(s->out - s->out_start))
            return ww_error_set(s->err, WW_E_TYPE, NULL, 0, 0,
                                "zlib: distance %zu before the start of the output", dist);
        if (len > (size_t)(s->out_end - s->out)) goto too_large;
        for (size_t i = 0; i < len; i++, s->out++) *s->out = *(s->out - dist);
    }
too_large:
    return ww_error_set(s->err, WW_E_TYPE, NULL, 0, 0, "zlib: output larger than %zu bytes",
                        (size_t)(s->out_end - s->out_start));
}

static ww_result huffman_block(inflater *s) {
    int st = huffman_fast(s);
    if (st > 0) return WW_OK;
    if (st < 0) return WW_E_TYPE;
    return huffman_slow(s);
}

/* RFC 1951 3.2.4: LEN, NLEN, then LEN bytes as they are */
static ww_result stored_block(inflater *s) {
    if (align_to_byte(s) < 0 || s->in_end - s->in < 4) return fail(s, "truncated");
    unsigned len = (unsigned)s->in[0] | (unsigned)s->in[1] << 8;
    unsigned nlen = (unsigned)s->in[2] | (unsigned)s->in[3] << 8;
    s->in += 4;
    if ((len ^ 0xffffu) != nlen) return fail(s, "stored block length does not match its complement");
    if ((size_t)(s->in_end - s->in) < len) return fail(s, "truncated");
    if ((size_t)(s->out_end - s->out) < len)
        return ww_error_set(s->err, WW_E_TYPE, NULL, 0, 0, "zlib: output larger than %zu bytes",
                            (size_t)(s->out_end - s->out_start));
    memcpy(s->out, s->in, len);
    s->out += len;
    s->in += len;
    return WW_OK;
}

/* RFC 1951 3.2.6 */
static ww_result fixed_tables(inflater *s) {
    if (s->fixed_built) return WW_OK;
    for (int i = 0; i < NUM_LITLEN; i++) s->lens[i] = i < 144 ? 8 : i < 256 ? 9 : i < 280 ? 7 : 8;
    for (int i = 0; i < NUM_DIST; i++) s->lens[NUM_LITLEN + i] = FIXED_DIST_LEN;
    if (build_table(s->litlen, LITLEN_TABLE_SIZE, LITLEN_BITS, s->lens, NUM_LITLEN, T_LITLEN) < 0 ||
        build_table(s->dist, DIST_TABLE_SIZE, DIST_BITS, s->lens + NUM_LITLEN, NUM_DIST, T_DIST) < 0)
        return fail(s, "fixed tables"); /* cannot happen: the fixed codes are complete */
    s->fixed_built = 1;
    return WW_OK;
}

/* RFC 1951 3.2.7: the code lengths of the two codes, themselves Huffman-coded */
static ww_result dynamic_tables(inflater *s) {
    s->fixed_built = 0;
    unsigned hlit = get_bits(s, 5) + 257, hdist = get_bits(s, 5) + 1, hclen = get_bits(s, 4) + 4;
    if (hlit > MAX_HLIT || hdist > MAX_HDIST) return fail(s, "too many length or distance codes");
    uint8_t cl[NUM_CLEN] = {0};
    for (unsigned i = 0; i < hclen; i++) cl[CLEN_ORDER[i]] = (uint8_t)get_bits(s, 3);
    if (past_end(s)) return fail(s, "truncated");
    if (build_table(s->clen, CLEN_TABLE_SIZE, CLEN_BITS, cl, NUM_CLEN, T_CLEN) < 0)
        return fail(s, "bad code lengths");

    unsigned total = hlit + hdist;
    for (unsigned i = 0; i < total;) {
        uint32_t e = decode_slow(s, s->clen, CLEN_BITS);
        unsigned sym = E_VAL(e), rep = 1;
        uint8_t val = (uint8_t)sym;
        if (sym == 16) {
            if (i == 0) return fail(s, "bad code lengths");
            val = s->lens[i - 1];
            rep = 3 + get_bits(s, 2);
        } else if (sym == 17) {
            val = 0;
            rep = 3 + get_bits(s, 3);
        } else if (sym == 18) {
            val = 0;
            rep = 11 + get_bits(s, 7);
        }
        if (past_end(s)) return fail(s, "truncated");
        if (rep > total - i) return fail(s, "bad code lengths");
        memset(s->lens + i, val, rep);
        i += rep;
    }
    if (s->lens[END_OF_BLOCK] == 0) return fail(s, "bad code lengths (no end-of-block code)");
    if (build_table(s->litlen, LITLEN_TABLE_SIZE, LITLEN_BITS, s->lens, (int)hlit, T_LITLEN) < 0 ||
        build_table(s->dist, DIST_TABLE_SIZE, DIST_BITS, s->lens + hlit, (int)hdist, T_DIST) < 0)
        return fail(s, "bad code lengths");
    return WW_OK;
}

/* RFC 1950 8.2, summed 8 bytes at a time: b gains 8 a plus the bytes weighted 8..1 */
uint32_t ww_adler32(uint32_t adler, const unsigned char *p, size_t n) {
    uint32_t a = adler & 0xffffu, b = adler >> 16;
    while (n > 0) {
        size_t k = n < ADLER_BLOCK ? n : ADLER_BLOCK;
        n -= k;
        for (; k >= 8; k -= 8, p += 8) {
            uint32_t sum = (uint32_t)p[0] + p[1] + p[2] + p[3] + p[4] + p[5] + p[6] + p[7];
            uint32_t w = 8u * p[0] + 7u * p[1] + 6u * p[2] + 5u * p[3] + 4u * p[4] + 3u * p[5] +
                         2u * p[6] + p[7];
            b += 8u * a + w;
            a += sum;
        }
        for (; k > 0; k--) {
            a += *p++;
            b += a;
        }
        a %= ADLER_MOD;
        b %= ADLER_MOD;
    }
    return b << 16 | a;
}

ww_result ww_zlib_inflate(const unsigned char *src, size_t n, unsigned char *dst, size_t cap,
                          size_t *out_len, ww_error *err) {
    if (out_len) *out_len = 0;
    if (n < 2) return ww_error_set(err, WW_E_TYPE, NULL, 0, 0, "zlib: truncated");
    /* RFC 1950 2.2: CM 8 (deflate), a window of at most 32 KiB, FCHECK, no preset dictionary */
    unsigned cmf = src[0], flg = src[1];
    if ((cmf & 15u) != 8 || (cmf >> 4) > 7)
        return ww_error_set(err, WW_E_TYPE, NULL, 0, 0, "zlib: not a deflate stream (CMF 0x%02x)", cmf);
    if ((cmf << 8 | flg) % 31u != 0)
        return ww_error_set(err, WW_E_TYPE, NULL, 0, 0, "zlib: header check failed");
    if (flg & 0x20u) return ww_error_set(err, WW_E_TYPE, NULL, 0, 0, "zlib: preset dictionary");

    inflater s;
    s.in = src + 2;
    s.in_end = src + n;
    s.out = s.out_start = dst;
    s.out_end = dst + cap;
    s.bitbuf = 0;
    s.bitsleft = 0;
    s.overrun = 0;
    s.fixed_built = 0;
    s.err = err;

    unsigned final = 0;
    while (!final) {
        final = get_bits(&s, 1);
        unsigned type = get_bits(&s, 2);
        if (past_end(&s)) return fail(&s, "truncated");
        ww_result r;
        if (type == 0)
            r = stored_block(&s);
        else if (type == 1)
            r = fixed_tables(&s);
        else if (type == 2)
            r = dynamic_tables(&s);
        else
            return fail(&s, "bad block type 3");
        if (r == WW_OK && type != 0) r = huffman_block(&s);
        if (r != WW_OK) return r;
    }

    /* RFC 1950: the Adler-32 of the data, most significant byte first */
    if (align_to_byte(&s) < 0 || s.in_end - s.in < 4) return fail(&s, "truncated");
    uint32_t want = (uint32_t)s.in[0] << 24 | (uint32_t)s.in[1] << 16 | (uint32_t)s.in[2] << 8 | s.in[3];
    size_t len = (size_t)(s.out - dst);
    if (ww_adler32(1, dst, len) != want) return fail(&s, "Adler-32 mismatch");
    if (out_len) *out_len = len;
    return WW_OK;
}
