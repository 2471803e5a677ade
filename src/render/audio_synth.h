/* audio_synth.h - the procedural sounds of the sound track (private to render/audio*.c): each is
 * a clip of float samples at WW_AUDIO_RATE, synthesised from a seeded random stream (core/rng.h)
 * and nothing else, so the same seed gives the same clip on every run.
 *
 *   ww_clip c;
 *   ww_synth(WW_SOUND_THUD, 0, seed, &c);   // 0 when out of memory
 *   ... c.data[i * c.channels + ch] ...
 *   ww_clip_free(&c);
 *
 * One-shots end in silence (their last samples are exactly 0); loops (reel, underwater, music,
 * the engine's one-period wavetable) are periodic: the sample after the last is the first.
 */
#ifndef WW_AUDIO_SYNTH_H
#define WW_AUDIO_SYNTH_H

#include <stdint.h>

#include "scene/desc_audio.h"

#define WW_AUDIO_RATE 44100
#define WW_ENGINE_TABLE 2048 /* samples in one period of the engine's wavetable */

typedef struct ww_clip {
    float *data;       /* frames x channels, interleaved */
    int64_t frames;
    int channels;      /* 1 or 2 */
} ww_clip;

/* the procedural clip of sound s (variant: which splash variation); 0 when out of memory */
int ww_synth(ww_sound s, int variant, uint64_t seed, ww_clip *out);
/* the music bed: one stereo cycle of a slow chord pad, looped from t = 0 */
int ww_synth_music(ww_clip *out);
void ww_clip_free(ww_clip *c);

/* pure: Minnaert's resonance of an air bubble of radius r (m) in water, Hz */
double ww_minnaert_hz(double r);

#endif
