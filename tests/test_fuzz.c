/* test_fuzz.c - a deterministic mutation test of the scene loader: valid scenes with random byte
 * flips, cuts, insertions and line swaps (seeded PCG, never the clock) must load or fail with an
 * input error that names a place, never crash, never leak (the ASan run checks that), and a scene
 * that loads must hold only finite numbers. `make fuzz` runs the same loader under libFuzzer.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/rng.h"
#include "scene/scene.h"
#include "sim/state.h"
#include "sim/step.h"
#include "test.h"

#define MUTANTS_PER_FILE 1500
#define STEPS_PER_MUTANT 24 /* steps each loadable mutant is simulated */

static const char alphabet[] = "{}[]:,-#&*!|>'\"%@`. \n\t0123456789eE+-naif/xyz_";

static size_t mutate(ww_rng *r, char *buf, size_t len, size_t cap) {
    int edits = 1 + (int)(ww_rng_u32(r) % 4);
    for (int e = 0; e < edits && len > 0; e++) {
        size_t at = ww_rng_u32(r) % len;
        switch (ww_rng_u32(r) % 4) {
        case 0: /* replace a byte with a YAML-significant one */
            buf[at] = alphabet[ww_rng_u32(r) % (sizeof alphabet - 1)];
            break;
        case 1: { /* cut a run */
            size_t n = 1 + ww_rng_u32(r) % 16;
            if (at + n > len) n = len - at;
            memmove(buf + at, buf + at + n, len - at - n);
            len -= n;
            break;
        }
        case 2: /* insert a byte */
            if (len + 1 < cap) {
                memmove(buf + at + 1, buf + at, len - at);
                buf[at] = alphabet[ww_rng_u32(r) % (sizeof alphabet - 1)];
                len++;
            }
            break;
        default: /* truncate */
            len = at;
            break;
        }
    }
    return len;
}

static int scene_is_finite(const ww_scene *sc) {
    int ok = isfinite(sc->dt) && isfinite(sc->fps) && isfinite(sc->duration) && isfinite(sc->start);
    for (int i = 0; i < sc->nwaves; i++)
        ok &= isfinite(sc->waves[i].k) && isfinite(sc->waves[i].omega) &&
              isfinite(sc->waves[i].amplitude) && isfinite(sc->waves[i].steepness) &&
              isfinite(sc->waves[i].mean) && isfinite(sc->waves[i].phase);
    ok &= isfinite(sc->fold_sum);
    if (sc->ripples_on)
        ok &= isfinite(sc->ripples.speed) && sc->ripples.wavenumber > 0.0 &&
              sc->ripples.max >= 1 && sc->ripples.max <= WW_MAX_RIPPLES;
    for (int i = 0; i < sc->ncam; i++)
        ok &= isfinite(sc->cam[i].position[0]) && isfinite(sc->cam[i].t);
    return ok && sc->steps_per_frame >= 1 && sc->frame_count >= 1;
}

static void fuzz_file(const char *path, uint64_t stream) {
    size_t len = 0;
    char *orig = ww_test_read_file(path, &len);
    ENSURE_MSG(orig != NULL, "cannot read %s", path);
    if (!orig) return;
    size_t cap = len + 64;
    char *buf = malloc(cap);
    ww_rng r;
    ww_rng_seed(&r, 12345, stream);
    int loaded = 0, rejected = 0, bad = 0;
    for (int m = 0; m < MUTANTS_PER_FILE && buf; m++) {
        memcpy(buf, orig, len);
        size_t n = mutate(&r, buf, len, cap);
        ww_scene *sc = NULL;
        ww_error err = {0};
        ww_result res = ww_scene_load_string(path, buf, n, NULL, 0, &sc, &err);
        if (res == WW_OK) {
            loaded++;
            if (!scene_is_finite(sc)) bad++;
            /* a scene that loads also steps: at worst a NaN report (exit 3), never a crash */
            ww_state *st = ww_state_new(sc);
            ww_result sr = st ? ww_sim_advance_to(sc, st, STEPS_PER_MUTANT, &err) : WW_E_NOMEM;
            if (sr != WW_OK && sr != WW_E_NAN) bad++;
            ww_state_free(st);
            ww_scene_free(sc);
        } else {
            rejected++;
            /* an input error (exit 2) with a message; sc stays NULL */
            if (ww_result_exit_code(res) != 2 || !err.msg[0] || sc) bad++;
        }
    }
    ENSURE_EQ_INT(bad, 0);
    ENSURE(loaded + rejected == MUTANTS_PER_FILE);
    ENSURE(rejected > 0); /* the mutations do reach the validator */
    free(buf);
    free(orig);
}

TEST(fuzz_scene_loader_mutations_demo) { fuzz_file("scenes/demo.yaml", 1); }
TEST(fuzz_scene_loader_mutations_full) { fuzz_file("tests/data/full.yaml", 2); }

TEST(fuzz_scene_set_mutations) {
    static const char *const sets[] = {"water.waves.list[1].amplitude=0.2", "render.size=[256,144]",
                                       "camera.path[0].position=[0,5,10]", "time.dt=1/120"};
    ww_rng r;
    ww_rng_seed(&r, 99, 3);
    int bad = 0;
    for (int m = 0; m < 2000; m++) {
        char buf[128];
        const char *s = sets[m % 4];
        size_t len = strlen(s);
        memcpy(buf, s, len);
        len = mutate(&r, buf, len, sizeof buf - 1);
        buf[len] = 0;
        ww_set set = {buf};
        ww_scene *sc = NULL;
        ww_error err = {0};
        ww_result res = ww_scene_load("scenes/minimal.yaml", &set, 1, &sc, &err);
        if (res == WW_OK)
            ww_scene_free(sc);
        else if (ww_result_exit_code(res) != 2 || !err.msg[0])
            bad++;
    }
    ENSURE_EQ_INT(bad, 0);
}
TEST(fuzz_scene_loader_mutations_spectrum) { fuzz_file("scenes/spectrum.yaml", 3); }
TEST(fuzz_scene_loader_mutations_ripples) { fuzz_file("scenes/ripples.yaml", 4); }
TEST(fuzz_scene_loader_mutations_lake) { fuzz_file("scenes/lake.yaml", 5); }
TEST(fuzz_scene_loader_mutations_reef) { fuzz_file("scenes/reef.yaml", 6); }

/* every libFuzzer target (tests/fuzz/fuzz_NAME.c), built by the Makefile with this build's own
 * compiler, flags and sanitizers around tests/fuzz/replay.c, replays its committed seeds and the
 * repository's own inputs without a crash: the targets keep compiling as the readers change, and
 * a seed that once crashed stays a regression test */
TEST_PROC(fuzz_targets_replay_their_seeds) {
    static const struct {
        const char *name, *also;
    } targets[] = {{"scene", "scenes/*.yaml tests/bad/*.yaml"}, {"obj", "tests/data/*.obj"},
                   {"png", "tests/data/*.png"}, {"inflate", ""}, {"exr", ""}, {"wav", ""},
                   {"image", "tests/data/*.png tests/data/*.tga tests/data/fuzz/*"}};
    const char *dir = ww_test_tmpdir("replay");
    for (size_t i = 0; i < sizeof targets / sizeof targets[0]; i++) {
        char cmd[1024], out[600];
        snprintf(out, sizeof out, "%s/%s.txt", dir, targets[i].name);
        snprintf(cmd, sizeof cmd, "%s/fuzz-replay/fuzz_%s tests/fuzz/corpus/%s/* %s",
                 ww_test_build_dir(), targets[i].name, targets[i].name, targets[i].also);
        ENSURE_MSG(ww_test_run(cmd, out, out) == 0, "%s (see %s)", cmd, out);
        char *text = ww_test_read_file(out, NULL);
        int n = 0;
        ENSURE_MSG(text && sscanf(text, "replayed %d inputs", &n) == 1 && n > 0, "%s: %s", cmd,
                   text ? text : "(no output)");
        free(text);
    }
}
