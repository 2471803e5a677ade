/* audio.c - the sound track of a render (seed 000 section 4, rendered offline): one-shots for the
 * step's events, loops for the engine, the underwater ambience, the reel and the music, mixed in
 * float on an absolute sample grid, limited and dithered to 16-bit PCM.
 *
 * Time: step k ends at sample B(k) = llround(k dt 44100) of a grid that starts at step 0, so the
 * track of steps [a, b) is samples [B(a), B(b)) and slices butt together. A slice that does not
 * start at step 0 replays the simulation's prefix privately (no rendering) so that voices begun
 * before it and the loops' state (engine phase, smoothed levels) are what a full run has: frames
 * 0:30 + 30:60 give the same samples as 0:60.
 */
#include "render/audio.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/rng.h"
#include "io/wav.h"
#include "render/audio_synth.h"
#include "sim/events.h"
#include "sim/step.h"
#include "sim/water.h"

#define DITHER_STREAM 0x64697468u  /* "dith": TPDF dither draws, by absolute sample */
#define LIMIT_KNEE 0.8             /* the limiter is the identity below this level (-1.9 dBFS) */
#define PCM_FULL 32767.0

/* levels of each source at the reference distance, linear */
#define SPLASH_GAIN 0.9
#define TINY_GAIN 0.6
#define LURE_GAIN 0.5
#define THUD_GAIN 0.9
#define STINGER_GAIN 0.6           /* catch and collected sparkle, heard at the player */
#define SPAWN_GAIN 0.8
#define REEL_GAIN 0.35
#define ENGINE_GAIN 0.5
#define UNDERWATER_GAIN 0.6
#define CENTRE 0.70710678118654752 /* equal-power pan at the centre, cos(pi / 4) */

/* the reel charges before each cast: hold = min + charge (full - min) seconds */
#define REEL_HOLD_MIN 0.3
#define REEL_HOLD_FULL 1.2
#define REEL_FADE 0.01             /* s, in and out */

/* engine rate: procedural fundamental idle + per m/s; a WAV loop is played at 0.8..1.2x */
#define ENGINE_IDLE_HZ 30.0
#define ENGINE_HZ_PER_MS 9.0
#define ENGINE_FILE_RATE_LO 0.8
#define ENGINE_FILE_RATE_HI 1.2

/* one-pole smoothing times of the continuous controls, s (no zipper noise, no clicks) */
#define TAU_GAIN 0.05
#define TAU_RATE 0.1
#define TAU_UNDERWATER 0.2
#define TAU_DUCK 0.3
#define SILENT 1e-6                /* a smoothed level below this, heading to 0, is 0 */

typedef struct smooth {
    double v, target, k;           /* value, target, per-sample coefficient */
} smooth;

/* a one-shot still sounding: what a checkpoint keeps so that a track started after it hears the
 * clip's tail (audio.h, ww_audio_save) */
typedef struct voice {
    int clip;                      /* index into clip[], or WW_SOUND_COUNT + splash variant */
    int64_t n0;                    /* first sample on the absolute grid */
    double gl, gr;                 /* gains, as played */
} voice;

struct ww_audio {
    ww_audio_desc d;
    uint64_t seed;
    double samples_per_step;       /* dt * 44100 */
    int64_t b0, b1, cursor;        /* track [b0, b1) on the absolute grid; next sample to mix */
    float *mix;                    /* (b1 - b0) x 2, interleaved */
    ww_clip clip[WW_SOUND_COUNT];
    ww_clip splash[WW_AUDIO_SPLASH_VARIANTS];
    int nsplash;
    ww_clip music;                 /* frames 0 when off */
    int64_t splashes;              /* full splashes so far: picks the next variation */
    int engine_file;               /* the engine is a WAV loop, not the wavetable */
    smooth eng_l, eng_r, eng_rate, underwater, music_gain;
    double eng_phase;              /* position in the engine clip, samples */
    voice voices[WW_AUDIO_MAX_VOICES]; /* the one-shots sounding, in the order they were played */
    int nvoices;
    int64_t lost_until;            /* a full list dropped a voice that sounds until this sample */
};

static int64_t grid(const ww_audio *a, int64_t step) {
    return llround((double)step * a->samples_per_step);
}

static void smooth_init(smooth *s, double tau) {
    *s = (smooth){0.0, 0.0, 1.0 - exp(-1.0 / (tau * WW_AUDIO_RATE))};
}
static double smooth_tick(smooth *s) {
    s->v += s->k * (s->target - s->v);
    if (s->target == 0.0 && fabs(s->v) < SILENT) s->v = 0.0;
    return s->v;
}

/* ---- spatialisation ------------------------------------------------------------------------ */

/* equal-power pan by the source's bearing along the camera's right vector, and OpenAL's inverse
 * distance clamped model: gain = ref / max(d, ref), never below min_gain */
static void spatial(const ww_audio *a, const ww_state *st, const double *pos, double level,
                    double *gl, double *gr) {
    const double *c = st->cam_pos, *f = st->cam_fwd;
    double d[3] = {pos[0] - c[0], pos[1] - c[1], pos[2] - c[2]};
    double dist = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    double rx = -f[2], rz = f[0], rl = sqrt(rx * rx + rz * rz); /* right = forward x up */
    if (rl < 1e-9) rx = 1.0, rz = 0.0, rl = 1.0;                 /* looking straight up/down */
    double x = dist > 1e-9 ? (d[0] * rx + d[2] * rz) / (rl * dist) : 0.0;
    double theta = (x + 1.0) * M_PI / 4.0;
    double g = a->d.reference_distance / fmax(dist, a->d.reference_distance);
    g = level * fmax(g, a->d.min_gain);
    *gl = g * cos(theta);
    *gr = g * sin(theta);
}

/* ---- mixing -------------------------------------------------------------------------------- */

/* add a one-shot clip starting at absolute sample n0 (the part inside the track) */
static void add_clip(ww_audio *a, const ww_clip *c, int64_t n0, double gl, double gr) {
    int64_t i = n0 < a->b0 ? a->b0 - n0 : 0;
    int64_t end = c->frames < a->b1 - n0 ? c->frames : a->b1 - n0;
    for (; i < end; i++) {
        float *m = a->mix + 2 * (n0 + i - a->b0);
        const float *s = c->data + i * c->channels;
        m[0] += (float)(gl * s[0]);
        m[1] += (float)(gr * s[c->channels - 1]);
    }
}

/* sample of a looped clip at fractional position p (linear interpolation), channel ch */
static double loop_at(const ww_clip *c, double p, int ch) {
    int64_t i = (int64_t)p;
    double f = p - (double)i;
    int64_t j = i + 1 < c->frames ? i + 1 : 0;
    ch = ch < c->channels ? ch : 0;
    return (1.0 - f) * c->data[i * c->channels + ch] + f * c->data[j * c->channels + ch];
}

/* the loops from the cursor to absolute sample n1 under the current controls */
static void mix_loops(ww_audio *a, int64_t n1) {
    const ww_clip *eng = &a->clip[WW_SOUND_ENGINE], *uw = &a->clip[WW_SOUND_UNDERWATER];
    for (int64_t n = a->cursor; n < n1; n++) {
        /* outside the track (the prefix, a checkpoint's listener) only the state moves on */
        int in = n >= a->b0 && n < a->b1;
        double l = 0.0, r = 0.0;
        double gl = smooth_tick(&a->eng_l), gr = smooth_tick(&a->eng_r);
        double rate = smooth_tick(&a->eng_rate);
        if (gl != 0.0 || gr != 0.0) {
            if (in) {
                l += gl * loop_at(eng, a->eng_phase, 0);
                r += gr * loop_at(eng, a->eng_phase, 1);
            }
            a->eng_phase = fmod(a->eng_phase + rate, (double)eng->frames);
        }
        double gu = smooth_tick(&a->underwater) * CENTRE;
        if (in && gu != 0.0) { /* the loop's position is the absolute sample: no state to carry */
            double p = (double)(n % uw->frames);
            l += gu * loop_at(uw, p, 0);
            r += gu * loop_at(uw, p, 1);
        }
        double gm = smooth_tick(&a->music_gain);
        if (in && gm != 0.0 && a->music.frames) {
            double p = (double)(n % a->music.frames);
            l += gm * loop_at(&a->music, p, 0);
            r += gm * loop_at(&a->music, p, 1);
        }
        if (in && (l != 0.0 || r != 0.0)) {
            a->mix[2 * (n - a->b0)] += (float)l;
            a->mix[2 * (n - a->b0) + 1] += (float)r;
        }
    }
    if (n1 > a->cursor) a->cursor = n1;
}

/* the reel loop while the rod charges before each scripted cast (the simulation has no charging
 * phase: a cast arrives with its charge, so the hold it stands for is placed before it) */
static void mix_reels(ww_audio *a, const ww_scene *sc) {
    const ww_clip *c = &a->clip[WW_SOUND_REEL];
    for (int e = 0; e < sc->nevents; e++) {
        const ww_event *ev = &sc->events[e];
        if (ev->kind != WW_EV_CAST) continue;
        double charge = ev->v[2];
        if (!(ev->flags & WW_CAST_CHARGE)) { /* an explicit speed: the charge it maps from */
            double s0 = sc->rod.speed[0], s1 = sc->rod.speed[1];
            charge = s1 > s0 ? (ev->v[0] - s0) / (s1 - s0) : 1.0;
        }
        charge = fmin(1.0, fmax(0.0, charge));
        int64_t end = grid(a, ev->step);
        int64_t len = llround((REEL_HOLD_MIN + charge * (REEL_HOLD_FULL - REEL_HOLD_MIN)) * WW_AUDIO_RATE);
        int64_t fade = llround(REEL_FADE * WW_AUDIO_RATE);
        for (int64_t i = 0; i < len; i++) {
            int64_t n = end - len + i;
            if (n < a->b0 || n >= a->b1) continue;
            double w = fmin(1.0, fmin((double)i / fade, (double)(len - i) / fade));
            double v = REEL_GAIN * CENTRE * w * c->data[(i % c->frames) * c->channels];
            a->mix[2 * (n - a->b0)] += (float)v;
            a->mix[2 * (n - a->b0) + 1] += (float)v;
        }
    }
}

/* ---- events and controls ------------------------------------------------------------------- */

/* the clip of a voice's index */
static const ww_clip *voice_clip(const ww_audio *a, int clip) {
    return clip < WW_SOUND_COUNT ? &a->clip[clip] : &a->splash[clip - WW_SOUND_COUNT];
}

/* forget the voices that ended by sample n (their last sample is before it), keeping the order */
static void prune_voices(ww_audio *a, int64_t n) {
    int k = 0;
    for (int i = 0; i < a->nvoices; i++)
        if (a->voices[i].n0 + voice_clip(a, a->voices[i].clip)->frames > n) a->voices[k++] = a->voices[i];
    a->nvoices = k;
}

static void remember_voice(ww_audio *a, const ww_clip *c, int64_t n0, double gl, double gr) {
    int clip = c >= a->clip && c < a->clip + WW_SOUND_COUNT ? (int)(c - a->clip)
                                                           : WW_SOUND_COUNT + (int)(c - a->splash);
    if (a->nvoices < WW_AUDIO_MAX_VOICES) {
        a->voices[a->nvoices++] = (voice){clip, n0, gl, gr};
    } else if (n0 + c->frames > a->lost_until) {
        a->lost_until = n0 + c->frames;
    }
}

static void play(ww_audio *a, const ww_state *st, const ww_clip *c, const double *pos, double level) {
    double gl = level * CENTRE, gr = gl;
    if (pos) spatial(a, st, pos, level, &gl, &gr);
    add_clip(a, c, grid(a, st->step), gl, gr);
    remember_voice(a, c, grid(a, st->step), gl, gr);
}

/* the sounds of the step's events, at the step's end sample, heard from the step's camera */
static void play_events(ww_audio *a, const ww_scene *sc, const ww_state *st) {
    if (!ww_scene_has_objects(sc)) return;
    int n = ww_events_count(sc, st);
    for (int i = 0; i < n; i++) {
        const double *e = st->events + i * WW_SIM_EVENT_STRIDE, *pos = e + 2, mag = e[5];
        switch ((ww_sim_event_kind)e[0]) {
        case WW_SE_STONE_SKIP: /* seed 000: a skip plays a full splash, cycling drop1/2/3 */
        case WW_SE_SPLASH_FULL:
            play(a, st, &a->splash[a->splashes++ % a->nsplash], pos,
                 SPLASH_GAIN * fmin(1.0, 0.4 + 0.06 * mag));
            break;
        case WW_SE_SPLASH_TINY:
            play(a, st, &a->clip[WW_SOUND_TINY_SPLASH], pos, TINY_GAIN * fmin(1.0, 0.5 + 0.1 * mag));
            break;
        case WW_SE_LURE_LAND: play(a, st, &a->clip[WW_SOUND_TINY_SPLASH], pos, LURE_GAIN); break;
        case WW_SE_STONE_THUD:
            play(a, st, &a->clip[WW_SOUND_THUD], pos, THUD_GAIN * fmin(1.0, 0.4 + 0.3 * mag));
            break;
        case WW_SE_CATCH: play(a, st, &a->clip[WW_SOUND_CATCH], NULL, STINGER_GAIN); break;
        case WW_SE_CHEST_SPAWN: play(a, st, &a->clip[WW_SOUND_SPARKLE_SPAWN], pos, SPAWN_GAIN); break;
        case WW_SE_CHEST_COLLECT: play(a, st, &a->clip[WW_SOUND_SPARKLE], NULL, STINGER_GAIN); break;
        default: break;
        }
    }
}

/* pure: the engine's level for a speed: 0 at or below the threshold, then from the floor at the
 * threshold to 1 at the boat's top speed */
static double engine_level(const ww_audio_desc *d, double speed, double max_speed) {
    if (speed <= d->engine_threshold) return 0.0;
    double u = max_speed > d->engine_threshold
                   ? (speed - d->engine_threshold) / (max_speed - d->engine_threshold) : 1.0;
    return d->engine_floor + (1.0 - d->engine_floor) * fmin(1.0, u);
}

/* the loops' targets from the state after a step */
static void set_controls(ww_audio *a, const ww_scene *sc, const ww_state *st) {
    if (sc->boat.on) {
        double speed = fabs(st->boat_speed[0]), gl = 0.0, gr = 0.0;
        double level = ENGINE_GAIN * engine_level(&a->d, speed, sc->boat.max_speed);
        if (level > 0.0) spatial(a, st, st->boat_pos, level, &gl, &gr);
        a->eng_l.target = gl;
        a->eng_r.target = gr;
        double u = sc->boat.max_speed > 0.0 ? fmin(1.0, speed / sc->boat.max_speed) : 0.0;
        a->eng_rate.target = a->engine_file
            ? ENGINE_FILE_RATE_LO + (ENGINE_FILE_RATE_HI - ENGINE_FILE_RATE_LO) * u
            : (ENGINE_IDLE_HZ + ENGINE_HZ_PER_MS * speed) * WW_ENGINE_TABLE / WW_AUDIO_RATE;
    }
    /* under water by the renderer's rule: below the exact surface over the camera */
    ww_water_sample ws;
    ww_water_at(sc, st, st->cam_pos[0], st->cam_pos[2], 0.0, &ws);
    int under = st->cam_pos[1] < ws.height;
    a->underwater.target = under ? UNDERWATER_GAIN : 0.0;
    if (a->d.music_on) a->music_gain.target = a->d.music_volume * (under ? a->d.music_duck : 1.0);
}

void ww_audio_step(ww_audio *a, const ww_scene *sc, const ww_state *st) {
    mix_loops(a, grid(a, st->step));
    prune_voices(a, grid(a, st->step));
    play_events(a, sc, st);
    set_controls(a, sc, st);
}

/* ---- clips --------------------------------------------------------------------------------- */

/* a WAV named in the scene, linearly resampled to 44.1 kHz as it is read (io/wav.h: the file is
 * never held whole, the clip is the only allocation); errors name the scene's place */
static ww_result load_file(const ww_audio_file *f, const char *what, ww_clip *out, ww_error *err) {
    ww_wav w;
    ww_error e;
    *out = (ww_clip){0};
    ww_result r = ww_wav_read_resampled(f->path, WW_AUDIO_RATE, &w, &e);
    if (r) return ww_error_set(err, r, f->file, f->line, f->column, "%s: '%s': %s", what, f->path, e.msg);
    *out = (ww_clip){.data = w.data, .frames = w.frames, .channels = w.channels};
    return WW_OK;
}

static const char *const SOUND_KEYS[] = {
#define WW_SOUND_NAME(id, name, what) "audio.sounds." name,
    WW_AUDIO_SOUNDS(WW_SOUND_NAME)
#undef WW_SOUND_NAME
};

/* one named file's header: its length added to *seconds, against the scene's cap */
static ww_result check_file(const ww_audio_file *f, const char *what, double *seconds,
                            ww_error *err) {
    if (!f->path[0]) return WW_OK;
    ww_wav w;
    ww_error e = {0};
    ww_result r = ww_wav_info(f->path, &w, &e);
    if (r) return ww_error_set(err, r, f->file, f->line, f->column, "%s: '%s': %s", what, f->path, e.msg);
    double s = (double)w.frames / w.rate;
    *seconds += s;
    if (*seconds > WW_AUDIO_MAX_FILE_SECONDS)
        return ww_error_set(err, WW_E_RANGE, f->file, f->line, f->column,
                            "%s: '%s' (%.1f s) makes the scene's sound files %.1f s long: "
                            "expected at most %.0f s in all",
                            what, f->path, s, *seconds, WW_AUDIO_MAX_FILE_SECONDS);
    return WW_OK;
}

ww_result ww_audio_check(const ww_scene *sc, ww_error *err) {
    const ww_audio_desc *d = &sc->audio;
    double seconds = 0.0;
    ww_result r = WW_OK;
    if (!d->on) return WW_OK;
    for (int s = 0; s < WW_SOUND_COUNT && !r; s++)
        if (s != WW_SOUND_SPLASH) r = check_file(&d->sounds[s], SOUND_KEYS[s], &seconds, err);
    for (int v = 0; v < d->nsplash && !r; v++)
        r = check_file(&d->splash[v], SOUND_KEYS[WW_SOUND_SPLASH], &seconds, err);
    if (!r) r = check_file(&d->music_file, "audio.music.file", &seconds, err);
    return r;
}

static ww_result load_clips(ww_audio *a, ww_error *err) {
    const char *const *names = SOUND_KEYS;
    ww_result r;
    for (int s = 0; s < WW_SOUND_COUNT; s++) {
        if (s == WW_SOUND_SPLASH) continue;
        if (a->d.sounds[s].path[0]) {
            if ((r = load_file(&a->d.sounds[s], names[s], &a->clip[s], err))) return r;
        } else if (!ww_synth((ww_sound)s, 0, a->seed, &a->clip[s])) {
            return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory for the sounds");
        }
    }
    a->engine_file = a->d.sounds[WW_SOUND_ENGINE].path[0] != 0;
    a->nsplash = a->d.nsplash ? a->d.nsplash : WW_AUDIO_SPLASH_VARIANTS;
    for (int v = 0; v < a->nsplash; v++) {
        if (a->d.nsplash) {
            if ((r = load_file(&a->d.splash[v], names[WW_SOUND_SPLASH], &a->splash[v], err))) return r;
        } else if (!ww_synth(WW_SOUND_SPLASH, v, a->seed, &a->splash[v])) {
            return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory for the sounds");
        }
    }
    if (!a->d.music_on) return WW_OK;
    if (a->d.music_file.path[0]) return load_file(&a->d.music_file, "audio.music.file", &a->music, err);
    if (!ww_synth_music(&a->music))
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory for the music");
    return WW_OK;
}

/* ---- the track ----------------------------------------------------------------------------- */

ww_result ww_audio_new(const ww_scene *sc, int64_t first_step, int64_t last_step, ww_audio **out,
                       ww_error *err) {
    WW_ASSERT(first_step >= 0 && last_step >= first_step);
    *out = NULL;
    /* the mix is held whole (float stereo, 353 kB a second): its length is capped before any
     * file is read or any step taken */
    double seconds = (double)(last_step - first_step) * sc->dt;
    if (seconds > WW_AUDIO_MAX_TRACK_SECONDS)
        return ww_error_set(err, WW_E_RANGE, NULL, 0, 0,
                            "--audio: a sound track of %.0f s: expected at most %.0f s (%.2f GB "
                            "of mix); render it in slices with --frames A:B (their tracks butt "
                            "together)",
                            seconds, WW_AUDIO_MAX_TRACK_SECONDS,
                            WW_AUDIO_MAX_TRACK_SECONDS * WW_AUDIO_RATE * 2 * sizeof(float) / 1e9);
    ww_result r = ww_audio_check(sc, err);
    if (r) return r;
    ww_audio *a = calloc(1, sizeof *a);
    if (!a) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory for the sound track");
    a->d = sc->audio;
    a->seed = sc->seed;
    a->samples_per_step = sc->dt * WW_AUDIO_RATE;
    a->b0 = grid(a, first_step);
    a->b1 = grid(a, last_step);
    a->cursor = 0;
    smooth_init(&a->eng_l, TAU_GAIN);
    smooth_init(&a->eng_r, TAU_GAIN);
    smooth_init(&a->eng_rate, TAU_RATE);
    smooth_init(&a->underwater, TAU_UNDERWATER);
    smooth_init(&a->music_gain, TAU_DUCK);
    r = load_clips(a, err);
    size_t frames = (size_t)(a->b1 - a->b0);
    if (!r && !(a->mix = calloc(frames * 2 + 2, sizeof *a->mix)))
        r = ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory for a %.0f s sound track",
                         (double)frames / WW_AUDIO_RATE);
    ww_state *st = r ? NULL : ww_state_new(sc);
    if (!r && !st) r = ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory for the state");
    if (r) {
        ww_audio_free(a);
        return r;
    }

    /* the loops start at their step-0 levels; the caller's steps before first_step (the
     * prefix) are then heard, not kept */
    mix_reels(a, sc);
    set_controls(a, sc, st);
    smooth *all[] = {&a->eng_l, &a->eng_r, &a->eng_rate, &a->underwater, &a->music_gain};
    for (size_t i = 0; i < sizeof all / sizeof all[0]; i++) all[i]->v = all[i]->target;
    ww_state_free(st);
    *out = a;
    return WW_OK;
}

/* ---- checkpoints --------------------------------------------------------------------------- */

/* the synth's state as bytes (native doubles and integers: a checkpoint's build id says the
 * layout): cursor, splashes, engine phase, the five smoothers' value and target, then the
 * voices sounding. The smoothers' coefficients and the clips come from the scene. */
#define SAVE_FIXED (3 * 8 + 5 * 2 * 8 + 8)
#define SAVE_VOICE (4 * 8)

static unsigned char *put8(unsigned char *p, const void *v) { return memcpy(p, v, 8), p + 8; }
static const unsigned char *get8(const unsigned char *p, void *v) { return memcpy(v, p, 8), p + 8; }

static void smoothers(ww_audio *a, smooth **all) {
    all[0] = &a->eng_l, all[1] = &a->eng_r, all[2] = &a->eng_rate, all[3] = &a->underwater;
    all[4] = &a->music_gain;
}

size_t ww_audio_save(ww_audio *a, unsigned char *buf, size_t cap) {
    size_t n = SAVE_FIXED + (size_t)a->nvoices * SAVE_VOICE;
    if (a->lost_until > a->cursor) return 0;
    if (!buf) return n;
    WW_ASSERT(cap >= n);
    smooth *all[5];
    smoothers(a, all);
    int64_t nv = a->nvoices;
    unsigned char *p = buf;
    p = put8(p, &a->cursor);
    p = put8(p, &a->splashes);
    p = put8(p, &a->eng_phase);
    for (int i = 0; i < 5; i++) p = put8(put8(p, &all[i]->v), &all[i]->target);
    p = put8(p, &nv);
    for (int i = 0; i < a->nvoices; i++) {
        const voice *v = &a->voices[i];
        int64_t clip = v->clip;
        p = put8(put8(put8(put8(p, &clip), &v->n0), &v->gl), &v->gr);
    }
    return n;
}

ww_result ww_audio_restore(ww_audio *a, const ww_state *st, const unsigned char *buf, size_t n,
                           ww_error *err) {
    int64_t cursor, splashes, nv = -1;
    double phase;
    smooth *all[5], saved[5];
    smoothers(a, all);
    const unsigned char *p = buf;
    if (n >= SAVE_FIXED) {
        p = get8(get8(get8(p, &cursor), &splashes), &phase);
        for (int i = 0; i < 5; i++) p = get8(get8(p, &saved[i].v), &saved[i].target);
        p = get8(p, &nv);
    }
    if (nv < 0 || nv > WW_AUDIO_MAX_VOICES || n != SAVE_FIXED + (size_t)nv * SAVE_VOICE ||
        cursor != grid(a, st->step) || splashes < 0 || !(phase >= 0.0))
        return ww_error_set(err, WW_E_RANGE, NULL, 0, 0,
                            "the sound track's state does not fit this scene");
    voice vs[WW_AUDIO_MAX_VOICES];
    for (int i = 0; i < nv; i++) {
        int64_t clip;
        p = get8(get8(get8(get8(p, &clip), &vs[i].n0), &vs[i].gl), &vs[i].gr);
        vs[i].clip = (int)clip;
        if (clip < 0 || clip >= WW_SOUND_COUNT + a->nsplash || clip == WW_SOUND_SPLASH ||
            vs[i].n0 > cursor)
            return ww_error_set(err, WW_E_RANGE, NULL, 0, 0,
                                "the sound track's state names a sound this scene does not have");
    }
    a->cursor = cursor;
    a->splashes = splashes;
    a->eng_phase = phase;
    for (int i = 0; i < 5; i++) all[i]->v = saved[i].v, all[i]->target = saved[i].target;
    /* the tails, added in the order the full run added them (after the reels, before the
     * loops), so every sample's float sum is the same */
    a->nvoices = 0;
    for (int i = 0; i < nv; i++) {
        const ww_clip *c = voice_clip(a, vs[i].clip);
        add_clip(a, c, vs[i].n0, vs[i].gl, vs[i].gr);
        remember_voice(a, c, vs[i].n0, vs[i].gl, vs[i].gr);
    }
    return WW_OK;
}

/* a stateless soft limiter: the identity up to the knee, then a tanh shoulder that meets full
 * scale only at infinity (no state, so slices of a track limit alike and nothing pumps) */
static double limit(double x) {
    double m = fabs(x);
    if (m <= LIMIT_KNEE) return x;
    double y = LIMIT_KNEE + (1.0 - LIMIT_KNEE) * tanh((m - LIMIT_KNEE) / (1.0 - LIMIT_KNEE));
    return x < 0.0 ? -y : y;
}

ww_result ww_audio_write(ww_audio *a, const char *path, ww_error *err) {
    mix_loops(a, a->b1);
    int64_t frames = a->b1 - a->b0;
    /* the 16-bit samples overwrite the mix in place: sample i goes to byte 2i once the float at
     * byte 4i it is made from was read (memcpy: the bytes change type, which no pointer cast may
     * say in C) */
    unsigned char *bytes = (unsigned char *)a->mix;

    /* TPDF dither of +-1 LSB from a counter-based draw per absolute sample; digital silence
     * (an exact 0) stays silent */
    for (int64_t i = 0; i < frames * 2; i++) {
        float m;
        memcpy(&m, bytes + 4 * i, sizeof m);
        double x = m * a->d.volume;
        int16_t s = 0;
        if (x != 0.0) {
            uint64_t n = (uint64_t)(a->b0 + i / 2), ch = (uint64_t)(i % 2);
            uint64_t draws = ww_rng_prefix(a->seed, DITHER_STREAM, n);
            double tpdf = ww_rng_draw_at(draws, 2 * ch) - ww_rng_draw_at(draws, 2 * ch + 1);
            double v = floor(limit(x) * PCM_FULL + tpdf + 0.5);
            s = (int16_t)fmax(-PCM_FULL - 1.0, fmin(PCM_FULL, v));
        }
        memcpy(bytes + 2 * i, &s, sizeof s);
    }
    const int16_t *pcm = (const int16_t *)(void *)bytes;
    ww_result r = ww_wav_write16(path, pcm, frames, 2, WW_AUDIO_RATE, err);
    /* the mix is spent: a second write would read 16-bit samples as floats */
    free(a->mix);
    a->mix = NULL;
    return r;
}

void ww_audio_free(ww_audio *a) {
    if (!a) return;
    for (int s = 0; s < WW_SOUND_COUNT; s++) ww_clip_free(&a->clip[s]);
    for (int v = 0; v < WW_AUDIO_SPLASH_VARIANTS; v++) ww_clip_free(&a->splash[v]);
    ww_clip_free(&a->music);
    free(a->mix);
    free(a);
}
