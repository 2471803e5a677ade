/* fuzz_wav.c - libFuzzer entry for the WAV reader (io/wav.c) and the resampler behind it (a
 * scene's WAV files are resampled to 44.1 kHz when a sound track is made, render/audio.c): any
 * bytes in, samples or an error out, no crash. The input is parsed from memory, then handed to
 * ww_audio_new as every sound of a scene loaded once (all of them name one file in memory, so
 * nothing is synthesised). The corpus starts from small WAVs of each sample format. */
#include "fuzz_file.h"

#include <math.h>
#include <stdint.h>

#include "io/wav.h"
#include "render/audio.h"
#include "scene/scene.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static const char *const SOUNDS[] = {"splash", "tiny_splash", "thud", "reel", "catch",
                                     "sparkle", "sparkle_spawn", "engine", "underwater"};

/* a scene whose every sound is the file at path */
static ww_scene *scene_naming(const char *path) {
    char text[2048];
    int n = snprintf(text, sizeof text, "time: {dt: 1/120, fps: 30, duration: 1}\n"
                                        "audio:\n  music: false\n  sounds:\n");
    for (size_t i = 0; i < sizeof SOUNDS / sizeof SOUNDS[0]; i++)
        n += snprintf(text + n, sizeof text - (size_t)n, "    %s: %s\n", SOUNDS[i], path);
    ww_scene *sc = NULL;
    ww_error err;
    if (ww_scene_load_string("fuzz.yaml", text, (size_t)n, NULL, 0, &sc, &err) != WW_OK) {
        fprintf(stderr, "fuzz_wav: %s\n", err.msg);
        abort();
    }
    return sc;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    ww_wav w;
    ww_error err;
    ww_result r = ww_wav_parse("fuzz.wav", data, size, &w, &err);
    if (r == WW_OK && (w.frames < 1 || w.channels < 1 || w.channels > 2)) abort();
    ww_wav_free(&w);
    if (r != WW_OK) return 0;

    /* the resampler sees only files the reader takes */
    static ww_scene *sc;
    const char *path = fuzz_memfile(0, data, size);
    if (!sc) sc = scene_naming(path);
    ww_audio *a = NULL;
    if (ww_audio_new(sc, 0, 1, &a, &err) == WW_OK) ww_audio_free(a);
    return 0;
}
