/* test_audio.c - the sound track (render/audio.h) and WAV I/O (io/wav.h): header fields and
 * length of a scene's and a slice's track, silence where nothing sounds, a splash where the event
 * log has one, left/right balance, the engine's level against the boat's speed, the music ducked
 * under water, WAV files named in the scene used sample for sample, same bytes twice, slices that
 * butt sample-exactly, and bad audio input with its place. Tracks are made in process (step loop,
 * no rendering); one test goes through `render --audio` when GL is there.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "io/wav.h"
#include "sim/events.h"
#include "sim/state.h"
#include "sim/step.h"
#include "test.h"
#include "render/audio.h"

#define RATE 44100
/* a sample of digital silence: exactly 0 (dither is off where the mix is exactly 0) */
#define SILENCE_FLOOR 0.0
/* a splash's energy over the 50 ms after its event, in squared 16-bit units summed over both
 * channels: a quiet splash 8 m away measures ~1e9; anything audible is far above 1e6 */
#define SPLASH_MIN_ENERGY 1e6
/* left/right power ratio of a source 45 deg off-centre: equal-power panning gives ~13 */
#define PAN_MIN_RATIO 8.0
/* the engine's power at the boat's full-throttle speed (5 m/s) over its power at 0.3 throttle
 * (1.5 m/s): levels 0.73 and 0.41 of full give ~3.2 */
#define ENGINE_MIN_RATIO 2.0
/* under-water music level over the level above: the duck factor (0.35) up to dither and
 * rounding, which are ~1e-4 of the tone's level */
#define DUCK_TOL 2e-3
/* a track sample against the named WAV's sample times the gains: rounding and +-1 LSB TPDF
 * dither, in 16-bit units */
#define FILE_SAMPLE_TOL 2.0
/* a 24-bit or float sample read back against the value written (24-bit step) */
#define WAV_READ_TOL 1.2e-7

static const char *const BASE =
    "time: {dt: 1/120, fps: 30, duration: 2}\n"
    "camera:\n  path:\n    - {t: 0, position: [0, %g, 0], look_at: [0, %g, -20]}\n";

/* write text (a printf format with the camera height twice, then extra) as dir/name and load it */
static ww_scene *load(const char *dir, const char *name, double cam_y, const char *extra) {
    char path[600], text[4096];
    int n = snprintf(text, sizeof text, BASE, cam_y, cam_y);
    snprintf(text + n, sizeof text - (size_t)n, "%s", extra);
    snprintf(path, sizeof path, "%s/%s", dir, name);
    if (ww_test_write_text(path, text)) return NULL;
    ww_scene *sc = NULL;
    ww_error err = {0};
    ww_result r = ww_scene_load(path, NULL, 0, &sc, &err);
    ENSURE_MSG(r == WW_OK, "%s: %s:%d:%d %s", name, err.file, err.line, err.column, err.msg);
    return sc;
}

/* the track of steps [a, b) made as render does (the prefix stepped once and heard, not kept),
 * written and read back */
static int track(const ww_scene *sc, int64_t a, int64_t b, const char *path, ww_wav *out) {
    ww_error err = {0};
    ww_audio *au = NULL;
    ww_state *st = ww_state_new(sc);
    int ok = st && ww_audio_new(sc, a, b, &au, &err) == WW_OK;
    while (ok && st->step < b) {
        ok = ww_step(sc, st, &err) == WW_OK;
        if (ok) ww_audio_step(au, sc, st);
    }
    ok = ok && ww_audio_write(au, path, &err) == WW_OK && ww_wav_read(path, out, &err) == WW_OK;
    ENSURE_MSG(ok, "track %s: %s", path, err.msg);
    ww_audio_free(au);
    ww_state_free(st);
    return ok;
}

/* the first step whose outbox holds an event of kind k, or -1 */
static int64_t event_step(const ww_scene *sc, ww_sim_event_kind k, int64_t last) {
    ww_error err = {0};
    ww_state *st = ww_state_new(sc);
    int64_t found = -1;
    while (st && found < 0 && st->step < last && ww_step(sc, st, &err) == WW_OK) {
        for (int i = 0; i < ww_events_count(sc, st); i++)
            if ((int)st->events[i * WW_SIM_EVENT_STRIDE] == (int)k) found = st->step;
    }
    ww_state_free(st);
    return found;
}

/* sum of squares in 16-bit units over frames [n0, n1), channel ch (-1: both) */
static double energy(const ww_wav *w, int64_t n0, int64_t n1, int ch) {
    double e = 0.0;
    for (int64_t n = n0 < 0 ? 0 : n0; n < n1 && n < w->frames; n++)
        for (int c = 0; c < 2; c++)
            if (ch < 0 || ch == c) e += pow(32768.0 * w->data[n * 2 + c], 2.0);
    return e;
}

static int64_t sample_of(int64_t step) { return llround((double)step / 120.0 * RATE); }

TEST(audio_wav_header_and_length) {
    const char *dir = ww_test_tmpdir("audio_len");
    ww_scene *sc = load(dir, "quiet.yaml", 2.0, "");
    if (!sc) return;
    char path[600];
    snprintf(path, sizeof path, "%s/all.wav", dir);
    ww_wav w = {0};
    if (track(sc, 0, sc->frame_count * sc->steps_per_frame, path, &w)) {
        /* 2 s at 44.1 kHz, and the canonical header */
        ENSURE_EQ_INT(w.frames, 88200);
        ENSURE_EQ_INT(w.channels, 2);
        ENSURE_EQ_INT(w.rate, RATE);
        ENSURE_EQ_INT(w.bits, 16);
        size_t len = 0;
        unsigned char *b = (unsigned char *)ww_test_read_file(path, &len);
        ENSURE_EQ_INT(len, WW_WAV_HEADER_BYTES + 88200 * 4);
        ENSURE(b && memcmp(b, "RIFF", 4) == 0 && memcmp(b + 8, "WAVEfmt ", 8) == 0 &&
               memcmp(b + 36, "data", 4) == 0);
        ENSURE(b && b[20] == 1 && b[22] == 2 && b[32] == 4 && b[34] == 16); /* PCM, 2 ch, 16-bit */
        ENSURE(b && (b[24] | b[25] << 8 | b[26] << 16) == RATE);
        free(b);
    }
    ww_wav_free(&w);
    /* a slice: frames 7:20 are steps 28:80, samples round(28 / 120 * 44100) = 10290 to 29400 */
    snprintf(path, sizeof path, "%s/slice.wav", dir);
    if (track(sc, 28, 80, path, &w)) ENSURE_EQ_INT(w.frames, 29400 - 10290);
    ww_wav_free(&w);
    ww_scene_free(sc);
}

TEST(audio_silence_without_events) {
    const char *dir = ww_test_tmpdir("audio_silence");
    ww_scene *sc = load(dir, "quiet.yaml", 2.0, "audio: {volume: 1}\n");
    if (!sc) return;
    char path[600];
    snprintf(path, sizeof path, "%s/q.wav", dir);
    ww_wav w = {0};
    if (track(sc, 0, 240, path, &w)) {
        double peak = 0.0;
        for (int64_t i = 0; i < w.frames * 2; i++) peak = fmax(peak, fabs(w.data[i]));
        ENSURE_MSG(peak <= SILENCE_FLOOR, "peak %g where nothing sounds", peak);
    }
    ww_wav_free(&w);
    ww_scene_free(sc);
}

static const char *const STONE_AT =
    "objects:\n  stones: {}\n"
    "script:\n  - {t: 0.5, throw: {speed: 4, angle: 60, from: [%g, 1.0, -6], heading: 0}}\n";

/* a stone thrown from x = x0 in front of the camera: its track and splash step */
static int stone_track(const char *dir, const char *name, double x0, ww_wav *w, int64_t *splash) {
    char extra[512], path[600];
    snprintf(extra, sizeof extra, STONE_AT, x0);
    ww_scene *sc = load(dir, name, 2.0, extra);
    if (!sc) return 0;
    *splash = event_step(sc, WW_SE_SPLASH_FULL, 240);
    snprintf(path, sizeof path, "%s/%s.wav", dir, name);
    int ok = *splash > 0 && track(sc, 0, 240, path, w);
    ww_scene_free(sc);
    return ok;
}

TEST(audio_splash_where_the_event_is) {
    const char *dir = ww_test_tmpdir("audio_splash");
    ww_wav w = {0};
    int64_t s = -1;
    if (stone_track(dir, "left.yaml", -6.0, &w, &s)) {
        int64_t n = sample_of(s), win = RATE / 20;
        double before = energy(&w, n - win, n, -1), after = energy(&w, n, n + win, -1);
        ENSURE_MSG(before <= SILENCE_FLOOR && after > SPLASH_MIN_ENERGY,
                   "splash at step %lld: energy before %g, after %g", (long long)s, before, after);
        /* nothing at all before the throw's splash (the throw itself is silent) */
        ENSURE(energy(&w, 0, n, -1) <= SILENCE_FLOOR);
    }
    ENSURE_MSG(s > 0, "no splash_full event");
    ww_wav_free(&w);
}

TEST(audio_pan_follows_the_source) {
    const char *dir = ww_test_tmpdir("audio_pan");
    ww_wav l = {0}, r = {0};
    int64_t sl = -1, sr = -1;
    if (stone_track(dir, "left.yaml", -6.0, &l, &sl) && stone_track(dir, "right.yaml", 6.0, &r, &sr)) {
        int64_t win = RATE / 2;
        double ll = energy(&l, sample_of(sl), sample_of(sl) + win, 0);
        double lr = energy(&l, sample_of(sl), sample_of(sl) + win, 1);
        double rl = energy(&r, sample_of(sr), sample_of(sr) + win, 0);
        double rr = energy(&r, sample_of(sr), sample_of(sr) + win, 1);
        ENSURE_MSG(ll > PAN_MIN_RATIO * lr, "source on the left: L %g, R %g", ll, lr);
        ENSURE_MSG(rr > PAN_MIN_RATIO * rl, "source on the right: L %g, R %g", rl, rr);
    }
    ww_wav_free(&l);
    ww_wav_free(&r);
}

/* the boat's engine power over [3, 4) s at a throttle held from 0.2 s */
static double engine_power(const char *dir, const char *name, double throttle) {
    char extra[600], path[600];
    snprintf(extra, sizeof extra,
             "objects:\n  boat: {position: [0, 0.25, -10], heading: 90}\n"
             "audio: {reference_distance: 1000}\n"
             "script:\n  - {t: 0.2, boat: {throttle: %g, until: 5}}\n", throttle);
    ww_scene *sc = load(dir, name, 2.0, extra);
    if (!sc) return -1.0;
    ww_wav w = {0};
    snprintf(path, sizeof path, "%s/%s.wav", dir, name);
    double e = -1.0;
    if (track(sc, 0, 480, path, &w)) e = energy(&w, 3 * RATE, 4 * RATE, -1);
    ww_wav_free(&w);
    ww_scene_free(sc);
    return e;
}

TEST(audio_engine_follows_speed) {
    const char *dir = ww_test_tmpdir("audio_engine");
    double idle = engine_power(dir, "idle.yaml", 0.0);
    double slow = engine_power(dir, "slow.yaml", 0.3);
    double fast = engine_power(dir, "fast.yaml", 1.0);
    ENSURE_MSG(idle == 0.0, "a boat at rest is silent: %g", idle);
    ENSURE_MSG(slow > SPLASH_MIN_ENERGY, "the engine at 1.5 m/s: %g", slow);
    ENSURE_MSG(fast > ENGINE_MIN_RATIO * slow, "engine power fast %g, slow %g", fast, slow);
}

/* a 440 Hz tone of amplitude 0.5 (1 s) and a silent clip, as WAV files beside the scenes */
static void write_clips(const char *dir) {
    int16_t tone[RATE], zero[RATE] = {0};
    for (int i = 0; i < RATE; i++) tone[i] = (int16_t)lrint(16384.0 * sin(2.0 * M_PI * 440.0 * i / RATE));
    char path[600];
    ww_error err = {0};
    snprintf(path, sizeof path, "%s/tone.wav", dir);
    ENSURE(ww_wav_write16(path, tone, RATE, 1, RATE, &err) == WW_OK);
    snprintf(path, sizeof path, "%s/silent.wav", dir);
    ENSURE(ww_wav_write16(path, zero, RATE, 1, RATE, &err) == WW_OK);
}

static const char *const MUSIC =
    "audio:\n  music: {file: tone.wav, volume: 0.5, duck: 0.35}\n  sounds: {underwater: silent.wav}\n";

TEST(audio_named_wav_is_used) {
    const char *dir = ww_test_tmpdir("audio_file");
    write_clips(dir);
    ww_scene *sc = load(dir, "music.yaml", 2.0, MUSIC);
    if (!sc) return;
    char path[600];
    snprintf(path, sizeof path, "%s/tone.wav", dir);
    ww_wav tone = {0}, w = {0};
    ENSURE(ww_wav_read(path, &tone, NULL) == WW_OK);
    snprintf(path, sizeof path, "%s/m.wav", dir);
    if (tone.frames == RATE && track(sc, 0, 240, path, &w)) {
        /* the music loops from t = 0: sample n is the tone's n mod 1 s times the music volume
         * (a mono file plays on both channels, as a stereo one plays L to L and R to R) */
        double worst = 0.0;
        for (int64_t n = 0; n < w.frames; n++) {
            double want = 32768.0 * 0.5 * tone.data[n % RATE];
            worst = fmax(worst, fabs(32768.0 * w.data[2 * n] - want));
        }
        ENSURE_MSG(worst <= FILE_SAMPLE_TOL, "track against the named WAV: off by %g", worst);
    }
    ww_wav_free(&tone);
    ww_wav_free(&w);
    ww_scene_free(sc);
}

/* a 22.05 kHz file is resampled linearly: sample 2i is the file's i, sample 2i + 1 the mean of i
 * and i + 1 (a ramp, so every interpolated value is known) */
TEST(audio_named_wav_resampled) {
    enum { HALF = 2205 };
    const char *dir = ww_test_tmpdir("audio_resample");
    int16_t ramp[HALF];
    for (int i = 0; i < HALF; i++) ramp[i] = (int16_t)(10 * i);
    char path[600];
    snprintf(path, sizeof path, "%s/ramp.wav", dir);
    ENSURE(ww_wav_write16(path, ramp, HALF, 1, RATE / 2, NULL) == WW_OK);
    ww_scene *sc = load(dir, "ramp.yaml", 2.0, "audio: {music: {file: ramp.wav, volume: 1}}\n");
    if (!sc) return;
    ww_wav w = {0};
    snprintf(path, sizeof path, "%s/r.wav", dir);
    if (track(sc, 0, 60, path, &w)) {
        double worst = 0.0;
        for (int64_t n = 0; n < 2 * HALF - 1; n++)
            worst = fmax(worst, fabs(32768.0 * w.data[2 * n + 1] - 5.0 * (double)n));
        ENSURE_MSG(worst <= FILE_SAMPLE_TOL, "resampled ramp: off by %g", worst);
        /* then the loop starts again: 2 HALF - 1 samples per cycle */
        ENSURE(fabs(32768.0 * w.data[2 * (2 * HALF - 1)]) <= FILE_SAMPLE_TOL);
    }
    ww_wav_free(&w);
    ww_scene_free(sc);
}

TEST(audio_underwater_ducks_music) {
    const char *dir = ww_test_tmpdir("audio_duck");
    write_clips(dir);
    ww_scene *up = load(dir, "up.yaml", 2.0, MUSIC), *down = load(dir, "down.yaml", -2.0, MUSIC);
    ww_wav a = {0}, b = {0};
    char pa[600], pb[600];
    snprintf(pa, sizeof pa, "%s/up.wav", dir);
    snprintf(pb, sizeof pb, "%s/down.wav", dir);
    if (up && down && track(up, 0, 240, pa, &a) && track(down, 0, 240, pb, &b)) {
        double ratio = sqrt(energy(&b, RATE, 2 * RATE, -1) / energy(&a, RATE, 2 * RATE, -1));
        ENSURE_NEAR(ratio, 0.35, DUCK_TOL);
    }
    ww_wav_free(&a);
    ww_wav_free(&b);
    ww_scene_free(up);
    ww_scene_free(down);
}

/* seed 000's world for 4 s: splashes, a thud, the reel before a cast, the lure, the boat */
TEST(audio_same_bytes_and_slices_butt) {
    const char *dir = ww_test_tmpdir("audio_det");
    ww_scene *sc = NULL;
    ww_error err = {0};
    const ww_set set = {"time.duration=4"};
    ENSURE(ww_scene_load("scenes/lake.yaml", &set, 1, &sc, &err) == WW_OK);
    if (!sc) return;
    char p[4][600];
    for (int i = 0; i < 4; i++) snprintf(p[i], sizeof p[i], "%s/t%d.wav", dir, i);
    ww_wav w[4] = {{0}};
    /* steps 192 = 1.6 s: the first stone's splash and the reel are sounding across the cut */
    if (track(sc, 0, 480, p[0], &w[0]) && track(sc, 0, 480, p[1], &w[1]) &&
        track(sc, 0, 192, p[2], &w[2]) && track(sc, 192, 480, p[3], &w[3])) {
        size_t la = 0, lb = 0;
        char *a = ww_test_read_file(p[0], &la), *b = ww_test_read_file(p[1], &lb);
        ENSURE(a && b && la == lb && memcmp(a, b, la) == 0);
        free(a);
        free(b);
        ENSURE_EQ_INT(w[2].frames + w[3].frames, w[0].frames);
        int64_t cut = w[2].frames, differ = 0;
        for (int64_t i = 0; i < w[0].frames * 2; i++) {
            float v = i < cut * 2 ? w[2].data[i] : w[3].data[i - cut * 2];
            differ += v != w[0].data[i];
        }
        ENSURE_MSG(differ == 0, "%lld samples of 0:1.6 + 1.6:4 differ from 0:4", (long long)differ);
        ENSURE(energy(&w[0], cut - 100, cut + 100, -1) > 0.0); /* the cut is inside a sound */
    }
    for (int i = 0; i < 4; i++) ww_wav_free(&w[i]);
    ww_scene_free(sc);
}

TEST(audio_wav_reader_formats) {
    /* 24-bit stereo, 8-bit mono and float mono, built by hand */
    unsigned char b[128];
    ww_wav w = {0};
    static const unsigned char head[36] = {'R', 'I', 'F', 'F', 0, 0, 0, 0, 'W', 'A', 'V', 'E',
                                           'f', 'm', 't', ' ', 16, 0, 0, 0};
    /* fmt: tag, channels, rate 22050, byte rate, align, bits */
    const struct { int tag, ch, bits; unsigned char data[12]; float want[2]; } cases[3] = {
        {1, 2, 24, {0x00, 0x00, 0x40, 0x00, 0x00, 0xC0}, {0.5f, -0.5f}},
        {1, 1, 8, {0xC0, 0x40}, {0.5f, -0.5f}},
        {3, 1, 32, {0x00, 0x00, 0x40, 0x3F, 0x00, 0x00, 0x80, 0xBE}, {0.75f, -0.25f}},
    };
    for (int k = 0; k < 3; k++) {
        int bytes = cases[k].bits / 8 * 2; /* two samples */
        memcpy(b, head, 36);
        b[20] = (unsigned char)cases[k].tag;
        b[22] = (unsigned char)cases[k].ch;
        b[24] = 0x22, b[25] = 0x56; /* 22050 */
        b[32] = (unsigned char)(cases[k].bits / 8 * cases[k].ch);
        b[34] = (unsigned char)cases[k].bits;
        memcpy(b + 36, "data", 4);
        b[40] = (unsigned char)bytes, b[41] = b[42] = b[43] = 0;
        memcpy(b + 44, cases[k].data, (size_t)bytes);
        ww_error err = {0};
        ENSURE_MSG(ww_wav_parse("t.wav", b, 44 + (size_t)bytes, &w, &err) == WW_OK, "case %d: %s", k, err.msg);
        ENSURE_EQ_INT(w.rate, 22050);
        ENSURE_EQ_INT(w.channels, cases[k].ch);
        ENSURE_NEAR(w.data ? w.data[0] : 9, cases[k].want[0], WAV_READ_TOL);
        ENSURE_NEAR(w.data ? w.data[1] : 9, cases[k].want[1], WAV_READ_TOL);
        ww_wav_free(&w);
    }
    ww_error err = {0};
    ENSURE_EQ_INT(ww_wav_parse("t.wav", (const unsigned char *)"RIFFxxxxWAVEjunk", 16, &w, &err), WW_E_SYNTAX);
    ww_wav_free(&w);
}

TEST(audio_bad_wav_names_the_scene_place) {
    const char *dir = ww_test_tmpdir("audio_badwav");
    char path[600];
    snprintf(path, sizeof path, "%s/notwav.wav", dir);
    ENSURE(ww_test_write_text(path, "this is not a WAV file\n") == 0);
    ww_scene *sc = load(dir, "bad.yaml", 2.0, "audio:\n  sounds:\n    thud: notwav.wav\n");
    if (!sc) return;
    ww_audio *a = NULL;
    ww_error err = {0};
    ENSURE_EQ_INT(ww_audio_new(sc, 0, 30, &a, &err), WW_E_SYNTAX);
    ENSURE(a == NULL);
    ENSURE_MSG(err.line == 7 && err.column == 11 && strstr(err.file, "bad.yaml"),
               "error at %s:%d:%d: %s", err.file, err.line, err.column, err.msg);
    ENSURE(strstr(err.msg, "audio.sounds.thud") != NULL);
    ww_scene_free(sc);
}

TEST_PROC(audio_render_cli) {
    const char *dir = ww_test_tmpdir("audio_cli");
    char args[1200], out[600], wav[600];
    snprintf(out, sizeof out, "%s/plan.txt", dir);
    ENSURE_EQ_INT(ww_test_ww("plan scenes/lake.yaml --set audio.music=true", out, NULL), 0);
    ENSURE(ww_test_file_contains(out, "\naudio: 44100 Hz stereo 16-bit, volume 1, music on"));
    ENSURE_EQ_INT(ww_test_ww("plan scenes/minimal.yaml", out, NULL), 0);
    ENSURE(!ww_test_file_contains(out, "audio:"));
    ENSURE_EQ_INT(ww_test_ww("plan tests/bad/audio_range_volume.yaml", NULL, out), 2);
    ENSURE(ww_test_file_contains(out, "tests/bad/audio_range_volume.yaml:4:17"));
    /* frames 2:5 of a 30 fps scene: steps 8:20, samples 2940 to 7350; the sound track does not
     * depend on the pixels, so the null backend serves where no GL opens */
    snprintf(wav, sizeof wav, "%s/s.wav", dir);
    snprintf(args, sizeof args, "render scenes/minimal.yaml --frames 2:5 --format none --size 64x36 "
             "--backend null --quiet --audio %s", wav);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, NULL), 0);
    ww_wav w = {0};
    ENSURE(ww_wav_read(wav, &w, NULL) == WW_OK);
    ENSURE_EQ_INT(w.frames, 7350 - 2940);
    ww_wav_free(&w);
}
