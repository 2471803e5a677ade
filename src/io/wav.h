/* wav.h - RIFF/WAVE files (Microsoft/IBM "Multimedia Programming Interface and Data
 * Specifications 1.0", 1991, and the WAVE_FORMAT_EXTENSIBLE note): the sound track's writer and
 * the reader for the files a scene's `audio:` section names (and the tests).
 *
 *   ww_wav w = {0};
 *   ww_wav_read("drop.wav", &w, &err);     // any rate, mono or stereo, PCM 8/16/24/32 or float
 *   w.data[i * w.channels + c]             // samples as float in [-1, 1], interleaved
 *   ww_wav_free(&w);                       // also after a failure
 *   ww_wav_write16(path, s16, frames, 2, 44100, &err);   // PCM 16-bit, atomic (temp + rename)
 */
#ifndef WW_WAV_H
#define WW_WAV_H

#include <stddef.h>
#include <stdint.h>

#include "core/error.h"

#define WW_WAV_HEADER_BYTES 44 /* the canonical PCM header the writer emits */

typedef struct ww_wav {
    int rate;          /* samples per second per channel */
    int channels;      /* 1 or 2 */
    int bits;          /* bits per sample as stored in the file */
    int is_float;      /* IEEE float samples (format 3) */
    int64_t frames;    /* samples per channel */
    float *data;       /* frames x channels, interleaved, [-1, 1] */
} ww_wav;

/* WW_E_NOFILE unreadable, WW_E_SYNTAX not a WAVE file we read (the message says why) */
ww_result ww_wav_read(const char *path, ww_wav *out, ww_error *err);
/* the same from bytes in memory; name stands for the file in messages */
ww_result ww_wav_parse(const char *name, const unsigned char *bytes, size_t len, ww_wav *out,
                       ww_error *err);
void ww_wav_free(ww_wav *w);

/* the 44-byte header and the samples of a 16-bit PCM file, written atomically */
ww_result ww_wav_write16(const char *path, const int16_t *samples, int64_t frames, int channels,
                         int rate, ww_error *err);

#endif
