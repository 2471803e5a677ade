/* audio_synth.c - the procedural sounds of seed 000's audio: splashes (a noise burst and Minnaert
 * bubbles), a low thump, a ratchet click train, a plucked arpeggio, FM bells, an underwater
 * rumble, the engine's harmonic wavetable and a slow chord pad. Every random choice comes from a
 * PCG stream seeded by (scene seed, sound, variant); nothing reads a clock.
 */
#include "render/audio_synth.h"

#include <math.h>
#include <stdlib.h>

#include "core/mathx.h"
#include "core/rng.h"

#define AUDIO_STREAM 0x6175000u /* audio's PCG streams start here, far above the simulation's */
#define TWO_PI 6.283185307179586

/* Minnaert (1933), "On musical air-bubbles and the sounds of running water":
 * f = (1 / (2 pi R)) sqrt(3 gamma p0 / rho) */
#define AIR_GAMMA 1.4       /* adiabatic index of air */
#define WATER_P0 101325.0   /* ambient pressure, Pa */
#define WATER_RHO 998.0     /* water density, kg/m^3 */

/* van den Doel (2005), "Physically based models for liquid sounds" (ACM TAP 2(4)): a bubble
 * rings as exp(-d t) sin(2 pi f(t) t) with d = 0.043 f + 0.0014 f^(3/2) and a pitch rising as
 * f(t) = f0 (1 + xi d t) while it nears the surface */
#define BUBBLE_DAMP_LIN 0.043
#define BUBBLE_DAMP_POW 0.0014
#define BUBBLE_RISE 0.1     /* xi */

double ww_minnaert_hz(double r) {
    return sqrt(3.0 * AIR_GAMMA * WATER_P0 / WATER_RHO) / (TWO_PI * r);
}

void ww_clip_free(ww_clip *c) {
    free(c->data);
    *c = (ww_clip){0};
}

static int clip_alloc(ww_clip *c, double seconds, int channels) {
    c->frames = (int64_t)(seconds * WW_AUDIO_RATE);
    c->channels = channels;
    c->data = calloc((size_t)c->frames * (size_t)channels, sizeof *c->data);
    return c->data != NULL;
}

static double uniform(ww_rng *r, double lo, double hi) { return lo + (hi - lo) * ww_rng_uniform(r); }
static double noise(ww_rng *r) { return 2.0 * ww_rng_uniform(r) - 1.0; }

/* scale to a peak of `peak` and fade the last `fade` seconds to exactly 0 (one-shots end silent) */
static void finish(ww_clip *c, double peak, double fade) {
    double m = 0.0;
    int64_t n = c->frames * c->channels;
    for (int64_t i = 0; i < n; i++) m = fmax(m, fabs(c->data[i]));
    double g = m > 0.0 ? peak / m : 0.0;
    int64_t nf = (int64_t)(fade * WW_AUDIO_RATE);
    for (int64_t i = 0; i < c->frames; i++) {
        int64_t left = c->frames - 1 - i;
        double w = left < nf ? (double)left / (double)nf : 1.0;
        for (int ch = 0; ch < c->channels; ch++)
            c->data[i * c->channels + ch] = (float)(c->data[i * c->channels + ch] * g * w);
    }
}

/* one bubble of radius r (m) from t0 (s), amplitude a, added to a mono clip */
static void add_bubble(ww_clip *c, double t0, double r, double a) {
    double f0 = ww_minnaert_hz(r);
    double d = BUBBLE_DAMP_LIN * f0 + BUBBLE_DAMP_POW * pow(f0, 1.5);
    int64_t i0 = (int64_t)(t0 * WW_AUDIO_RATE);
    int64_t len = (int64_t)(7.0 / d * WW_AUDIO_RATE); /* to e^-7 */
    double phase = 0.0;
    for (int64_t i = 0; i < len && i0 + i < c->frames; i++) {
        double t = (double)i / WW_AUDIO_RATE;
        phase += TWO_PI * f0 * (1.0 + BUBBLE_RISE * d * t) / WW_AUDIO_RATE;
        c->data[i0 + i] += (float)(a * exp(-d * t) * sin(phase));
    }
}

/* a noise burst: white noise through a one-pole low-pass at fc, envelope attack then decay */
static void add_burst(ww_clip *c, ww_rng *r, double fc, double attack, double decay, double a) {
    double k = 1.0 - exp(-TWO_PI * fc / WW_AUDIO_RATE), y = 0.0;
    for (int64_t i = 0; i < c->frames; i++) {
        double t = (double)i / WW_AUDIO_RATE;
        double env = t < attack ? t / attack : exp(-(t - attack) / decay);
        y += k * (noise(r) - y);
        c->data[i] += (float)(a * env * y);
    }
}

/* splash: the impact's hiss and a cloud of bubbles of 1.5 to 6 mm (1 to 3 mm for a tiny one) */
static int synth_splash(ww_clip *c, ww_rng *r, int tiny) {
    if (!clip_alloc(c, tiny ? 0.3 : 0.7, 1)) return 0;
    add_burst(c, r, tiny ? 5000.0 : 2500.0, 0.002, tiny ? 0.012 : 0.04, tiny ? 0.5 : 1.0);
    int n = tiny ? 3 : 9;
    for (int i = 0; i < n; i++) {
        double rad = exp(uniform(r, log(tiny ? 1.0e-3 : 1.5e-3), log(tiny ? 3.0e-3 : 6.0e-3)));
        double t0 = (tiny ? 0.08 : 0.3) * pow(ww_rng_uniform(r), 2.0); /* most bubbles early */
        add_bubble(c, t0, rad, uniform(r, 0.3, 1.0));
    }
    finish(c, 0.8, 0.02);
    return 1;
}

/* thud: a sine falling from 115 to 55 Hz under a 0.12 s decay, and a short dull knock */
static int synth_thud(ww_clip *c, ww_rng *r) {
    if (!clip_alloc(c, 0.6, 1)) return 0;
    double phase = 0.0;
    for (int64_t i = 0; i < c->frames; i++) {
        double t = (double)i / WW_AUDIO_RATE;
        phase += TWO_PI * (55.0 + 60.0 * exp(-t / 0.03)) / WW_AUDIO_RATE;
        c->data[i] = (float)(exp(-t / 0.12) * sin(phase) * fmin(1.0, t / 0.002));
    }
    add_burst(c, r, 800.0, 0.001, 0.01, 0.4);
    finish(c, 0.9, 0.05);
    return 1;
}

/* reel: a ratchet, 12 clicks in a 0.5 s loop; each a damped 2.8 kHz ring over a noise tick */
static int synth_reel(ww_clip *c, ww_rng *r) {
    enum { CLICKS = 12 };
    if (!clip_alloc(c, 0.5, 1)) return 0;
    int64_t period = c->frames / CLICKS, ring = (int64_t)(0.012 * WW_AUDIO_RATE);
    for (int k = 0; k < CLICKS; k++) {
        double a = uniform(r, 0.7, 1.0), f = uniform(r, 2600.0, 3000.0);
        for (int64_t i = 0; i < ring; i++) {
            double t = (double)i / WW_AUDIO_RATE;
            double v = exp(-t / 0.0015) * (0.6 * sin(TWO_PI * f * t) + 0.4 * noise(r));
            c->data[k * period + i] += (float)(a * v);
        }
    }
    finish(c, 0.6, 0.0);
    return 1;
}

/* a plucked note: partials 1..3 at 1, 1/2, 1/4, decaying faster the higher they are */
static void add_pluck(ww_clip *c, double t0, double f, double a, double decay) {
    int64_t i0 = (int64_t)(t0 * WW_AUDIO_RATE);
    for (int64_t i = 0; i0 + i < c->frames; i++) {
        double t = (double)i / WW_AUDIO_RATE, v = 0.0;
        for (int p = 1; p <= 3; p++) v += exp(-t * p / decay) * sin(TWO_PI * f * p * t) / (1 << (p - 1));
        c->data[i0 + i] += (float)(a * v * fmin(1.0, t / 0.003));
    }
}

/* catch: a rising major arpeggio (C5 E5 G5 C6) */
static int synth_catch(ww_clip *c) {
    static const double notes[4] = {523.25, 659.26, 783.99, 1046.50};
    if (!clip_alloc(c, 1.6, 1)) return 0;
    for (int k = 0; k < 4; k++) add_pluck(c, 0.09 * k, notes[k], k == 3 ? 1.0 : 0.7, 0.4);
    finish(c, 0.8, 0.2);
    return 1;
}

/* an FM bell (Chowning 1973, "The synthesis of complex audio spectra by means of frequency
 * modulation"): carrier fc, modulator 1.4 fc (the inharmonic bell ratio), index decaying with
 * the amplitude */
static void add_bell(ww_clip *c, double t0, double fc, double a, double decay) {
    int64_t i0 = (int64_t)(t0 * WW_AUDIO_RATE);
    for (int64_t i = 0; i0 + i < c->frames; i++) {
        double t = (double)i / WW_AUDIO_RATE, env = exp(-t / decay);
        double v = sin(TWO_PI * fc * t + 3.0 * env * sin(TWO_PI * 1.4 * fc * t));
        c->data[i0 + i] += (float)(a * env * v * fmin(1.0, t / 0.002));
    }
}

/* sparkle: bells on a pentatonic scale, rising (collected) or falling over a rising hiss (spawn) */
static int synth_sparkle(ww_clip *c, ww_rng *r, int spawn) {
    static const double penta[5] = {1.0, 9.0 / 8.0, 5.0 / 4.0, 3.0 / 2.0, 5.0 / 3.0};
    if (!clip_alloc(c, 1.5, 1)) return 0;
    int n = spawn ? 5 : 7;
    for (int k = 0; k < n; k++) {
        int step = spawn ? n - 1 - k : k;
        double f = (spawn ? 880.0 : 1320.0) * penta[step % 5] * (step >= 5 ? 2.0 : 1.0);
        add_bell(c, 0.06 * k + uniform(r, 0.0, 0.01), f, uniform(r, 0.5, 0.8), 0.35);
    }
    if (spawn) { /* the whoosh: noise through a low-pass opening from 300 Hz to 6 kHz */
        double y = 0.0;
        for (int64_t i = 0; i < c->frames; i++) {
            double t = (double)i / WW_AUDIO_RATE;
            double fc = 300.0 * pow(20.0, fmin(1.0, t / 0.6));
            y += (1.0 - exp(-TWO_PI * fc / WW_AUDIO_RATE)) * (noise(r) - y);
            c->data[i] += (float)(0.5 * sin(M_PI * fmin(1.0, t / 0.8)) * y);
        }
    }
    finish(c, 0.7, 0.3);
    return 1;
}

/* underwater: a 6 s loop of low rumble (white noise through two one-pole low-passes at 250 Hz,
 * run twice round the loop so the filter's state wraps) with slow swells and a few big bubbles */
static int synth_underwater(ww_clip *c, ww_rng *r) {
    if (!clip_alloc(c, 6.0, 1)) return 0;
    float *w = malloc((size_t)c->frames * sizeof *w);
    if (!w) return 0;
    for (int64_t i = 0; i < c->frames; i++) w[i] = (float)noise(r);
    double k = 1.0 - exp(-TWO_PI * 250.0 / WW_AUDIO_RATE), y1 = 0.0, y2 = 0.0;
    for (int pass = 0; pass < 2; pass++) {
        for (int64_t i = 0; i < c->frames; i++) {
            y1 += k * (w[i] - y1);
            y2 += k * (y1 - y2);
            double t = (double)i / WW_AUDIO_RATE;
            c->data[i] = (float)(y2 * (0.7 + 0.3 * sin(TWO_PI * t / 3.0))); /* 2 swells per loop */
        }
    }
    free(w);
    for (int b = 0; b < 5; b++) add_bubble(c, uniform(r, 0.0, 5.5), uniform(r, 5e-3, 1.2e-2), 0.3);
    finish(c, 0.5, 0.0);
    return 1;
}

/* engine: one period of a harmonic series, 1/k amplitudes with the odd harmonics stronger (a
 * two-stroke's buzz); played at a speed-dependent rate */
static int synth_engine(ww_clip *c) {
    c->frames = WW_ENGINE_TABLE;
    c->channels = 1;
    if (!(c->data = calloc(WW_ENGINE_TABLE, sizeof *c->data))) return 0;
    for (int i = 0; i < WW_ENGINE_TABLE; i++) {
        double x = TWO_PI * i / WW_ENGINE_TABLE, v = 0.0;
        for (int h = 1; h <= 12; h++) v += (h % 2 ? 1.5 : 1.0) * sin(h * x) / h;
        c->data[i] = (float)v;
    }
    finish(c, 0.7, 0.0);
    return 1;
}

int ww_synth(ww_sound s, int variant, uint64_t seed, ww_clip *out) {
    ww_rng r;
    ww_rng_seed(&r, seed, AUDIO_STREAM + 16u * (uint64_t)s + (uint64_t)variant);
    *out = (ww_clip){0};
    int ok = 0;
    switch (s) {
    case WW_SOUND_SPLASH: ok = synth_splash(out, &r, 0); break;
    case WW_SOUND_TINY_SPLASH: ok = synth_splash(out, &r, 1); break;
    case WW_SOUND_THUD: ok = synth_thud(out, &r); break;
    case WW_SOUND_REEL: ok = synth_reel(out, &r); break;
    case WW_SOUND_CATCH: ok = synth_catch(out); break;
    case WW_SOUND_SPARKLE: ok = synth_sparkle(out, &r, 0); break;
    case WW_SOUND_SPARKLE_SPAWN: ok = synth_sparkle(out, &r, 1); break;
    case WW_SOUND_ENGINE: ok = synth_engine(out); break;
    case WW_SOUND_UNDERWATER: ok = synth_underwater(out, &r); break;
    case WW_SOUND_COUNT: break;
    }
    if (!ok) ww_clip_free(out);
    return ok;
}

/* music: Cmaj7 - Am7 - Fmaj7 - G6, 4 s each, a 16 s stereo cycle. Each chord sounds over a 6 s
 * raised-cosine window (1 s overlap each side, wrapping round the cycle); each note is partials
 * 1..3 at 1, 0.3, 0.1, the right channel detuned by +0.15 % for width. Phasors are rotated by
 * complex multiplication, renormalised per window. */
static int synth_music(ww_clip *c) {
    static const double chords[4][4] = {{261.63, 329.63, 392.00, 493.88},
                                        {220.00, 261.63, 329.63, 392.00},
                                        {174.61, 220.00, 261.63, 329.63},
                                        {196.00, 246.94, 293.66, 329.63}};
    static const double partial_gain[3] = {1.0, 0.3, 0.1};
    const double chord_s = 4.0, overlap_s = 1.0;
    if (!clip_alloc(c, 4 * chord_s, 2)) return 0;
    int64_t win = (int64_t)((chord_s + 2 * overlap_s) * WW_AUDIO_RATE);
    float *env = malloc((size_t)win * sizeof *env);
    if (!env) return 0;
    for (int64_t i = 0; i < win; i++) env[i] = (float)(0.5 - 0.5 * cos(TWO_PI * (double)i / (double)win));
    for (int k = 0; k < 4; k++) {
        int64_t start = (int64_t)((k * chord_s - overlap_s) * WW_AUDIO_RATE);
        for (int ch = 0; ch < 2; ch++) {
            for (int nt = 0; nt < 4; nt++) {
                for (int p = 0; p < 3; p++) {
                    double f = chords[k][nt] * (p + 1) * (ch ? 1.0015 : 1.0);
                    double cr = cos(TWO_PI * f / WW_AUDIO_RATE), ci = sin(TWO_PI * f / WW_AUDIO_RATE);
                    double re = 1.0, im = 0.0, g = partial_gain[p];
                    int64_t at = (start % c->frames + c->frames) % c->frames;
                    for (int64_t i = 0; i < win; i++, at = at + 1 < c->frames ? at + 1 : 0) {
                        c->data[at * 2 + ch] += (float)(g * env[i] * im);
                        double t = re * cr - im * ci;
                        im = re * ci + im * cr;
                        re = t;
                    }
                }
            }
        }
    }
    free(env);
    finish(c, 0.5, 0.0);
    return 1;
}

int ww_synth_music(ww_clip *out) {
    *out = (ww_clip){0};
    if (!synth_music(out)) {
        ww_clip_free(out);
        return 0;
    }
    return 1;
}
