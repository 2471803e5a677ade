/* wav.c - RIFF/WAVE reading (PCM 8/16/24/32-bit, IEEE float 32/64-bit, mono or stereo, plain or
 * WAVE_FORMAT_EXTENSIBLE) and 16-bit PCM writing. Little-endian fields are assembled byte by byte,
 * so the code does not depend on the host's byte order.
 */
#include "io/wav.h"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/readfile.h"
#include "io/stream.h"
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
    if (w->rate < WW_WAV_MIN_RATE || w->rate > WW_WAV_MAX_RATE)
        return ww_error_set(err, WW_E_SYNTAX, name, 0, 0,
                            "WAV sample rate %d Hz is out of range: expected %d to %d Hz", w->rate,
                            WW_WAV_MIN_RATE, WW_WAV_MAX_RATE);
    return WW_OK;
}

/* where the bytes come from: memory (ww_wav_parse) or a file read with pread (the streaming
 * readers), so that one chunk walk serves both */
typedef struct src {
    const unsigned char *mem;
    int fd;
    uint64_t len;
} src;

static size_t src_read(const src *s, uint64_t off, void *buf, size_t n) {
    if (off >= s->len) return 0;
    if (n > s->len - off) n = (size_t)(s->len - off);
    if (s->mem) {
        memcpy(buf, s->mem + off, n);
        return n;
    }
    size_t got = 0;
    while (got < n) {
        ssize_t k = pread(s->fd, (char *)buf + got, n - got, (off_t)(off + got));
        if (k < 0 && errno == EINTR) continue;
        if (k <= 0) break;
        got += (size_t)k;
    }
    return got;
}

/* the fmt fields into w and where the samples lie: walk the chunks, each padded to an even
 * size; w->frames counts the whole frames of the data chunk (a cut-off one: what is there) */
static ww_result scan(const char *name, const src *s, ww_wav *w, uint64_t *data_at,
                      ww_error *err) {
    unsigned char h[12];
    *w = (ww_wav){0};
    if (src_read(s, 0, h, sizeof h) < sizeof h || memcmp(h, "RIFF", 4) != 0 ||
        memcmp(h + 8, "WAVE", 4) != 0)
        return ww_error_set(err, WW_E_SYNTAX, name, 0, 0, "not a RIFF/WAVE file");
    uint64_t data_len = 0;
    int have_fmt = 0, have_data = 0, chunks = 0;
    for (uint64_t at = 12; at + 8 <= s->len;) {
        unsigned char ch[8];
        if (src_read(s, at, ch, sizeof ch) < sizeof ch) break;
        if (++chunks > WW_WAV_MAX_CHUNKS)
            return ww_error_set(err, WW_E_RANGE, name, 0, 0,
                                "WAV with more than %d chunks: expected a handful", WW_WAV_MAX_CHUNKS);
        uint32_t size = le32(ch + 4);
        uint64_t body = at + 8, avail = s->len - body;
        if (memcmp(ch, "fmt ", 4) == 0) {
            /* read_fmt reads at most 40 bytes (the extensible sub-format's first word) */
            unsigned char f[40] = {0};
            if (size > avail)
                return ww_error_set(err, WW_E_SYNTAX, name, 0, 0, "WAV fmt chunk is cut short");
            src_read(s, body, f, size < sizeof f ? size : sizeof f);
            ww_result r = read_fmt(name, f, size, w, err);
            if (r) return r;
            have_fmt = 1;
        } else if (memcmp(ch, "data", 4) == 0) {
            *data_at = body;
            data_len = size < avail ? size : avail;
            have_data = 1;
        }
        if (size > avail) break;
        at = body + size + (size & 1);
    }
    if (!have_fmt) return ww_error_set(err, WW_E_SYNTAX, name, 0, 0, "WAV without a fmt chunk");
    if (!have_data) return ww_error_set(err, WW_E_SYNTAX, name, 0, 0, "WAV without a data chunk");
    w->frames = (int64_t)(data_len / ((uint64_t)(w->bits / 8) * (uint64_t)w->channels));
    if (w->frames == 0) return ww_error_set(err, WW_E_SYNTAX, name, 0, 0, "WAV holds no samples");
    return WW_OK;
}

ww_result ww_wav_parse(const char *name, const unsigned char *b, size_t len, ww_wav *w,
                       ww_error *err) {
    src s = {.mem = b, .fd = -1, .len = len};
    uint64_t at = 0;
    ww_result r = scan(name, &s, w, &at, err);
    if (r) return r;
    size_t bytes = (size_t)(w->bits / 8), n = (size_t)w->frames * (size_t)w->channels;
    w->data = malloc(n * sizeof *w->data);
    if (!w->data) return ww_error_set(err, WW_E_NOMEM, name, 0, 0, "out of memory for the WAV");
    for (size_t i = 0; i < n; i++) w->data[i] = decode(b + at + i * bytes, w->bits, w->is_float);
    return WW_OK;
}

ww_result ww_wav_read(const char *path, ww_wav *out, ww_error *err) {
    unsigned char *bytes = NULL;
    size_t len = 0;
    *out = (ww_wav){0};
    ww_result r = ww_file_read_max(path, (size_t)WW_WAV_MAX_BYTES, (size_t)WW_WAV_MAX_BYTES, &bytes,
                                   &len, err);
    if (r) return r;
    r = ww_wav_parse(path, bytes, len, out, err);
    free(bytes);
    if (r) ww_wav_free(out);
    return r;
}

/* the file open for pread, its header read and every cap checked */
static ww_result open_info(const char *path, src *s, ww_wav *w, uint64_t *data_at,
                           ww_error *err) {
    *s = (src){.fd = open(path, O_RDONLY | O_CLOEXEC | O_NONBLOCK)};
    if (s->fd < 0)
        return ww_error_set(err, WW_E_NOFILE, path, 0, 0, "cannot open '%s': %s", path,
                            strerror(errno));
    struct stat st;
    ww_result r = WW_OK;
    if (fstat(s->fd, &st) != 0 || !S_ISREG(st.st_mode))
        r = ww_error_set(err, WW_E_NOFILE, path, 0, 0,
                         "'%s' is not a regular file: expected a WAV file", path);
    else if ((int64_t)st.st_size > WW_WAV_MAX_BYTES)
        r = ww_error_set(err, WW_E_RANGE, path, 0, 0,
                         "the WAV file is %lld bytes: expected at most %lld (%.0f MiB)",
                         (long long)st.st_size, (long long)WW_WAV_MAX_BYTES,
                         (double)WW_WAV_MAX_BYTES / (1 << 20));
    s->len = (uint64_t)st.st_size;
    if (!r) r = scan(path, s, w, data_at, err);
    double seconds = (double)w->frames / (w->rate > 0 ? w->rate : 1);
    if (!r && seconds > WW_WAV_MAX_SECONDS)
        r = ww_error_set(err, WW_E_RANGE, path, 0, 0,
                         "the WAV file lasts %.1f s (%lld frames at %d Hz): expected at most %.0f s",
                         seconds, (long long)w->frames, w->rate, WW_WAV_MAX_SECONDS);
    if (r) {
        close(s->fd);
        s->fd = -1;
    }
    return r;
}

ww_result ww_wav_info(const char *path, ww_wav *out, ww_error *err) {
    src s;
    uint64_t at = 0;
    ww_result r = open_info(path, &s, out, &at, err);
    if (!r) close(s.fd);
    return r;
}

int64_t ww_wav_resampled_frames(int64_t frames, int from_rate, int to_rate) {
    WW_ASSERT(frames > 0 && from_rate > 0 && to_rate > 0);
    double step = (double)from_rate / to_rate;
    return (int64_t)((double)(frames - 1) / step) + 1;
}

/* frames decoded per block read from the file */
#define RESAMPLE_BLOCK 4096

ww_result ww_wav_read_resampled(const char *path, int rate, ww_wav *out, ww_error *err) {
    src s;
    uint64_t at = 0;
    ww_wav w;
    *out = (ww_wav){0};
    ww_result r = open_info(path, &s, &w, &at, err);
    if (r) return r;
    const int ch = w.channels;
    const size_t bytes = (size_t)(w.bits / 8), frame = bytes * (size_t)ch;
    const double step = (double)w.rate / rate;
    const int64_t n = ww_wav_resampled_frames(w.frames, w.rate, rate);
    float *data = malloc((size_t)n * (size_t)ch * sizeof *data);
    unsigned char *raw = malloc(RESAMPLE_BLOCK * frame);
    float win[RESAMPLE_BLOCK * 2];
    if (!data || !raw) {
        free(data);
        free(raw);
        close(s.fd);
        return ww_error_set(err, WW_E_NOMEM, path, 0, 0, "out of memory for '%s'", path);
    }

    /* output frame i samples the input at p = i * step between frames j and k = j + 1 (the last
     * frame repeats): a window of input frames [w0, w0 + wn) is decoded from the file when k
     * leaves it, starting at j, so the file is read once, in order, in blocks */
    int64_t w0 = 0, wn = 0;
    for (int64_t i = 0; i < n && !r; i++) {
        double p = (double)i * step;
        int64_t j = (int64_t)p, k = j + 1 < w.frames ? j + 1 : j;
        double t = p - (double)j;
        if (j < w0 || k >= w0 + wn) {
            w0 = j;
            wn = w.frames - j < RESAMPLE_BLOCK ? w.frames - j : RESAMPLE_BLOCK;
            size_t want = (size_t)wn * frame;
            if (src_read(&s, at + (uint64_t)j * frame, raw, want) != want) {
                r = ww_error_set(err, WW_E_NOFILE, path, 0, 0,
                                 "cannot read '%s': it changed or ended while read", path);
                break;
            }
            for (size_t q = 0; q < (size_t)wn * (size_t)ch; q++)
                win[q] = decode(raw + q * bytes, w.bits, w.is_float);
        }
        const float *a = win + (j - w0) * ch, *b = win + (k - w0) * ch;
        for (int c = 0; c < ch; c++)
            data[i * ch + c] = (float)((1.0 - t) * a[c] + t * b[c]);
    }
    free(raw);
    close(s.fd);
    if (r) {
        free(data);
        return r;
    }
    *out = w;
    out->rate = rate;
    out->frames = n;
    out->data = data;
    return WW_OK;
}

int ww_wav_header16(unsigned char b[WW_WAV_HEADER_BYTES], int64_t frames, int channels, int rate) {
    WW_ASSERT(frames >= 0 && (channels == 1 || channels == 2) && rate > 0);
    uint64_t data_len = (uint64_t)frames * (uint64_t)channels * 2u;
    if (data_len > 0xFFFFFFFFu - WW_WAV_HEADER_BYTES) return -1;
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
    return 0;
}

ww_result ww_wav_write16(const char *path, const int16_t *s, int64_t frames, int channels,
                         int rate, ww_error *err) {
    WW_ASSERT(frames >= 0 && (channels == 1 || channels == 2) && rate > 0);
    unsigned char b[WW_WAV_HEADER_BYTES];
    if (ww_wav_header16(b, frames, channels, rate) != 0)
        return ww_error_set(err, WW_E_RANGE, path, 0, 0, "the track is too long for a WAV file");

    /* then the samples, little-endian, a block at a time: no copy of the track in memory */
    ww_stream out;
    ww_result r = ww_stream_open(&out, path, err);
    if (r) return r;
    int bad = fwrite(b, 1, sizeof b, out.f) != sizeof b;
    unsigned char block[8192];
    uint64_t n = (uint64_t)frames * (uint64_t)channels;
    for (uint64_t i = 0; i < n && !bad;) {
        size_t k = 0;
        for (; k + 2 <= sizeof block && i < n; k += 2, i++) put16(block + k, (uint16_t)s[i]);
        bad = fwrite(block, 1, k, out.f) != k;
    }
    if (bad) {
        ww_stream_abort(&out);
        return ww_error_set(err, WW_E_IO, path, 0, 0, "cannot write '%s': %s", path, strerror(errno));
    }
    return ww_stream_commit(&out, err);
}
