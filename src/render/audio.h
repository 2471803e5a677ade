/* audio.h - the sound track of a render, synthesised offline from the simulation's events (seed
 * 000's sounds): splashes, thuds, reel, catch, chest sparkle, boat engine, underwater ambience and
 * an optional music bed, panned and attenuated from the camera. Same scene, same bytes.
 *
 *   ww_audio *a = NULL;
 *   ww_audio_new(sc, first_step, last_step, &a, &err);  // the track covers steps [first, last)
 *   for each step s in [1, last): ww_step(sc, st, ...); ww_audio_step(a, sc, st);
 *   ww_audio_write(a, "out/demo.wav", &err);            // 44.1 kHz stereo 16-bit WAV, atomic
 *   ww_audio_free(a);
 *
 * Sample grid: step k ends at sample llround(k dt 44100) counted from step 0; the track is the
 * samples of [first, last). ww_audio_new decodes the scene's WAV files (errors name the scene's
 * file:line:column) and synthesises the other sounds; the caller then feeds it every step from
 * step 1 on, the prefix before `first` included: those steps are heard (the engine's and the
 * ambience's levels, the reels), not kept, so that a slice's samples equal the full run's, and
 * the prefix is simulated once, by the caller. ww_audio_step neither allocates nor fails. The audio object owns everything it allocates; ww_audio_free frees it (NULL is fine).
 */
#ifndef WW_AUDIO_H
#define WW_AUDIO_H

#include <stdint.h>

#include "core/error.h"
#include "scene/scene.h"
#include "sim/state.h"

/* all the WAV files of a scene together, s: each is held resampled to 44.1 kHz float (one file
 * is at most io/wav.h's WW_WAV_MAX_SECONDS); 900 s of stereo is 318 MB */
#define WW_AUDIO_MAX_FILE_SECONDS 900.0

/* the longest track one render makes (the mix is held whole, float stereo: 1.27 GB at the cap);
 * a longer one is made in slices (--frames A:B), whose tracks butt together */
#define WW_AUDIO_MAX_TRACK_SECONDS 3600.0

typedef struct ww_audio ww_audio;

/* the headers of the scene's WAV files against io/wav.h's caps and WW_AUDIO_MAX_FILE_SECONDS,
 * without reading a sample: every command runs it when it loads a scene (cli/args.c), so a bad
 * file is exit 2 at its scene line whatever the command; ww_audio_new runs it first too */
ww_result ww_audio_check(const ww_scene *sc, ww_error *err);
ww_result ww_audio_new(const ww_scene *sc, int64_t first_step, int64_t last_step, ww_audio **out,
                       ww_error *err);
/* after each step: the step's events, the camera, the boat's speed, above or below water */
void ww_audio_step(ww_audio *a, const ww_scene *sc, const ww_state *st);
/* one-shots a checkpoint remembers as still sounding; past this, a checkpoint holds no sound */
#define WW_AUDIO_MAX_VOICES 256

/* the synth's state after the last step fed (checkpoints, render/checkpoint.h): the loops' levels
 * and phase, the splash counter and the one-shots still sounding. With buf NULL, the size;
 * 0 when it cannot be kept (more than WW_AUDIO_MAX_VOICES one-shots were sounding at once).
 * ww_audio_restore, on a fresh track of the same scene whose first step is at or after st's,
 * makes it go on as the saved one would (st: the checkpoint's state); WW_E_RANGE when the
 * bytes do not fit this scene. A track that only listens (first = last step) is what
 * `simulate --checkpoint-every` feeds. */
size_t ww_audio_save(ww_audio *a, unsigned char *buf, size_t cap);
ww_result ww_audio_restore(ww_audio *a, const ww_state *st, const unsigned char *buf, size_t n,
                           ww_error *err);
/* once: the mix is converted in place and freed */
ww_result ww_audio_write(ww_audio *a, const char *path, ww_error *err);
void ww_audio_free(ww_audio *a);

#endif
