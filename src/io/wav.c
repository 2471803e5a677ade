/* wav.c - RIFF/WAVE reading (PCM 8/16/24/32-bit, IEEE float 32/64-bit, mono or stereo, plain or
 * WAVE_FORMAT_EXTENSIBLE) and 16-bit PCM writing. Little-endian fields are assembled byte by byte,
 * so the code does not depend on the host's byte order.
 */
#include "io/wav.h"

#include <stdlib.h>
#include <string.h>

#include "io/writers.h"

enum { FMT_PCM = 1, FMT_FLOAT = 3, FMT_EXTENSIBLE = 0xFFFE };

static uint32_t le16(const unsigned char *p) { return (uint32_t)p[0] | (uint32_t)p[1] << 8; }
static uint32_t le32(const unsigned char *p) { return le16(p) | le16(p + 2) << 16; }

static void put16(unsigned char *p, uint32_t v) {
    p[0] = (unsigned char)(v & 0xff);
    p[1] = (unsigned char)(v >> 8 & 0xff);
}
static void put32(unsigned char *p, uint32_t v) {
    put16(p, v & 0xffff);
    put16(p + 2, v >> 16);
}

void ww_wav_free(ww_wav *w) {
    free(w->data);
    *w = (ww_wav){0};
}

/* one stored sample at p as a float in [-1, 1] */
static float decode(const unsigned char *p, int bits, int is_float) {
    if (is_float && bits == 32) {
        uint32_t u = le32(p);
        float f;
        memcpy(&f, &u, sizeof f);
        return f;
    }
    if (is_float) {
        uint64_t u = (uint64_t)le32(p) | (uint64_t)le32(p + 4) << 32;
        double d;
        memcpy(&d, &u, sizeof d);
        return (float)d;
    }
    switch (bits) {
    case 8: return (float)((int)p[0] - 128) / 128.0f; /* 8-bit WAV is unsigned */
    case 16: return (float)(int16_t)le16(p) / 32768.0f;
    case 24: {
        int32_t v = (int32_t)(le16(p) | (uint32_t)p[2] << 16);
        if (v & 0x800000) v -= 0x1000000;
        return (float)v / 8388608.0f;
    }
    default: return (float)((double)(int32_t)le32(p) / 2147483648.0);
    }
}

/* the fmt chunk's fields, checked */
static ww_result read_fmt(const char *name, const unsigned char *p, uint32_t size, ww_wav *w,
                          ww_error *err) {
    if (size < 16) return ww_error_set(err, WW_E_SYNTAX, name, 0, 0, "WAV fmt chunk too short");
    uint32_t tag = le16(p);
    w->channels = (int)le16(p + 2);
    w->rate = (int)le32(p + 4);
    w->bits = (int)le16(p + 14);
    if (tag == FMT_EXTENSIBLE && size >= 40) tag = le16(p + 24); /* the sub-format GUID's first word */
    if (tag != FMT_PCM && tag != FMT_FLOAT)
        return ww_error_set(err, WW_E_SYNTAX, name, 0, 0,
                            "WAV format %u is not read (PCM or IEEE float only)", tag);
    w->is_float = tag == FMT_FLOAT;
    int ok_bits = w->is_float ? (w->bits == 32 || w->bits == 64)
                              : (w->bits == 8 || w->bits == 16 || w->bits == 24 || w->bits == 32);
    if (!ok_bits)
        return ww_error_set(err, WW_E_SYNTAX, name, 0, 0, "WAV with %d-bit %s samples is not read",
                            w->bits, w->is_float ? "float" : "PCM");
    if (w->channels < 1 || w->channels > 2)
        return ww_error_set(err, WW_E_SYNTAX, name, 0, 0,
                            "WAV with %d channels: mono or stereo only", w->channels);
    if (w->rate < 1000 || w->rate > 384000)
        return ww_error_set(err, WW_E_SYNTAX, name, 0, 0, "WAV sample rate %d Hz is out of range",
                            w->rate);
    return WW_OK;
}

ww_result ww_wav_parse(const char *name, const unsigned char *b, size_t len, ww_wav *w,
                       ww_error *err) {
    *w = (ww_wav){0};
    if (len < 12 || memcmp(b, "RIFF", 4) != 0 || memcmp(b + 8, "WAVE", 4) != 0)
        return ww_error_set(err, WW_E_SYNTAX, name, 0, 0, "not a RIFF/WAVE file");
    const unsigned char *data = NULL;
    size_t data_len = 0;
    int have_fmt = 0;

    /* walk the chunks; each is padded to an even size */
    for (size_t at = 12; at + 8 <= len;) {
        uint32_t size = le32(b + at + 4);
        size_t body = at + 8, avail = len - body;
        if (memcmp(b + at, "fmt ", 4) == 0) {
            if (size > avail)
                return ww_error_set(err, WW_E_SYNTAX, name, 0, 0, "WAV fmt chunk is cut short");
            ww_result r = read_fmt(name, b + body, size, w, err);
            if (r) return r;
            have_fmt = 1;
        } else if (memcmp(b + at, "data", 4) == 0) {
            data = b + body;
            data_len = size < avail ? size : avail; /* a cut-off data chunk: what is there */
        }
        if (size > avail) break;
        at = body + size + (size & 1);
    }
    if (!have_fmt) return ww_error_set(err, WW_E_SYNTAX, name, 0, 0, "WAV without a fmt chunk");
    if (!data) return ww_error_set(err, WW_E_SYNTAX, name, 0, 0, "WAV without a data chunk");

    size_t bytes = (size_t)(w->bits / 8), frame = bytes * (size_t)w->channels;
    w->frames = (int64_t)(data_len / frame);
    if (w->frames == 0) return ww_error_set(err, WW_E_SYNTAX, name, 0, 0, "WAV holds no samples");
    w->data = malloc((size_t)w->frames * (size_t)w->channels * sizeof *w->data);
    if (!w->data) return ww_error_set(err, WW_E_NOMEM, name, 0, 0, "out of memory for the WAV");
    for (size_t i = 0; i < (size_t)w->frames * (size_t)w->channels; i++)
        w->data[i] = decode(data + i * bytes, w->bits, w->is_float);
    return WW_OK;
}

ww_result ww_wav_read(const char *path, ww_wav *out, ww_error *err) {
    unsigned char *bytes = NULL;
    size_t len = 0;
    *out = (ww_wav){0};
    ww_result r = ww_read_file(path, &bytes, &len, err);
    if (r) return r;
    r = ww_wav_parse(path, bytes, len, out, err);
    free(bytes);
    if (r) ww_wav_free(out);
    return r;
}

ww_result ww_wav_write16(const char *path, const int16_t *s, int64_t frames, int channels,
                         int rate, ww_error *err) {
    WW_ASSERT(frames >= 0 && (channels == 1 || channels == 2) && rate > 0);
    uint64_t data_len = (uint64_t)frames * (uint64_t)channels * 2u;
    if (data_len > 0xFFFFFFFFu - WW_WAV_HEADER_BYTES)
        return ww_error_set(err, WW_E_RANGE, path, 0, 0, "the track is too long for a WAV file");
    unsigned char *b = malloc(WW_WAV_HEADER_BYTES + (size_t)data_len);
    if (!b) return ww_error_set(err, WW_E_NOMEM, path, 0, 0, "out of memory for the WAV");

    /* the canonical header: RIFF, fmt (PCM, 16 bytes), data */
    memcpy(b, "RIFF", 4);
    put32(b + 4, (uint32_t)(36 + data_len));
    memcpy(b + 8, "WAVEfmt ", 8);
    put32(b + 16, 16);
    put16(b + 20, FMT_PCM);
    put16(b + 22, (uint32_t)channels);
    put32(b + 24, (uint32_t)rate);
    put32(b + 28, (uint32_t)(rate * channels * 2)); /* byte rate */
    put16(b + 32, (uint32_t)(channels * 2));        /* block align */
    put16(b + 34, 16);
    memcpy(b + 36, "data", 4);
    put32(b + 40, (uint32_t)data_len);
    for (uint64_t i = 0; i < (uint64_t)frames * (uint64_t)channels; i++)
        put16(b + WW_WAV_HEADER_BYTES + 2 * i, (uint16_t)s[i]);

    ww_result r = ww_write_file_atomic(path, b, WW_WAV_HEADER_BYTES + (size_t)data_len, err);
    free(b);
    return r;
}
