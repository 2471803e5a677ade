/* wav.h - RIFF/WAVE files (Microsoft/IBM "Multimedia Programming Interface and Data
 * Specifications 1.0", 1991, and the WAVE_FORMAT_EXTENSIBLE note): the sound track's writer and
 * the reader for the files a scene's `audio:` section names (and the tests).
 *
 *   ww_wav w = {0};
 *   ww_wav_info("drop.wav", &w, &err);     // the header only: rate, channels, bits, frames
 *   ww_wav_read_resampled("drop.wav", 44100, &w, &err);  // streamed through a linear resampler
 *   ww_wav_read("drop.wav", &w, &err);     // any rate, mono or stereo, PCM 8/16/24/32 or float
 *   w.data[i * w.channels + c]             // samples as float in [-1, 1], interleaved
 *   ww_wav_free(&w);                       // also after a failure
 *   ww_wav_write16(path, s16, frames, 2, 44100, &err);   // PCM 16-bit, atomic (temp + rename)
 *
 * Bounds (README, "Limits"): a file the scene names is a regular file of at most WW_WAV_MAX_BYTES
 * and WW_WAV_MAX_SECONDS, 1 or 2 channels at 1 to 384 kHz, with at most WW_WAV_MAX_CHUNKS
 * chunks; ww_wav_info and ww_wav_read_resampled check them all before a sample is read. The
 * resampler reads the file in blocks, so its memory is its result alone.
 */
#ifndef WW_WAV_H
#define WW_WAV_H

#include <stddef.h>
#include <stdint.h>

#include "core/error.h"

#define WW_WAV_HEADER_BYTES 44 /* the canonical PCM header the writer emits */
#define WW_WAV_MAX_BYTES ((int64_t)1 << 30) /* a file read: 10 minutes of 192 kHz 24-bit stereo
                                             * is 691 MB */
#define WW_WAV_MAX_SECONDS 600.0             /* a file read: a 10-minute music bed */
#define WW_WAV_MAX_CHUNKS 1024               /* RIFF chunks walked (files hold a handful) */
#define WW_WAV_MIN_RATE 1000                 /* Hz */
#define WW_WAV_MAX_RATE 384000

typedef struct ww_wav {
    int rate;          /* samples per second per channel */
    int channels;      /* 1 or 2 */
    int bits;          /* bits per sample as stored in the file */
    int is_float;      /* IEEE float samples (format 3) */
    int64_t frames;    /* samples per channel */
    float *data;       /* frames x channels, interleaved, [-1, 1] */
} ww_wav;

/* WW_E_NOFILE unreadable, WW_E_SYNTAX not a WAVE file we read (the message says why),
 * WW_E_RANGE past a cap */
ww_result ww_wav_read(const char *path, ww_wav *out, ww_error *err);
/* the header of a file: every field but data (NULL), every cap checked */
ww_result ww_wav_info(const char *path, ww_wav *out, ww_error *err);
/* the file's samples linearly resampled to rate (out->rate): out->frames =
 * ww_wav_resampled_frames(frames, file rate, rate), out->data that many frames x channels
 * floats, the only allocation of the size of the sound */
ww_result ww_wav_read_resampled(const char *path, int rate, ww_wav *out, ww_error *err);
/* pure: frames of a sound of `frames` at from_rate resampled to to_rate (output frame i samples
 * the input at i * from_rate / to_rate, up to its last frame) */
int64_t ww_wav_resampled_frames(int64_t frames, int from_rate, int to_rate);
/* the same from bytes in memory; name stands for the file in messages */
ww_result ww_wav_parse(const char *name, const unsigned char *bytes, size_t len, ww_wav *out,
                       ww_error *err);
void ww_wav_free(ww_wav *w);

/* the canonical 44-byte header of a 16-bit PCM file of `frames` frames (the writer's, and
 * `join`'s for a track put together from slices); -1 when the data is past what RIFF holds */
int ww_wav_header16(unsigned char b[WW_WAV_HEADER_BYTES], int64_t frames, int channels, int rate);
/* the 44-byte header and the samples of a 16-bit PCM file, written atomically */
ww_result ww_wav_write16(const char *path, const int16_t *samples, int64_t frames, int channels,
                         int rate, ww_error *err);

#endif
