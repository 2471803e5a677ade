/* test_checkpoint.c - checkpoints (render/checkpoint.h): the state read back hashes as the
 * straight run's at that step and goes on to the pinned end hash; a slice rendered from one is
 * byte-identical to the same frames of a full run, frames and sound track; another scene, other
 * --set values, another build, a truncated or damaged file are each refused with exit 2 and
 * nothing written; long prefixes show their progress.
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "core/hash.h"
#include "render/checkpoint.h"
#include "scene/scene.h"
#include "sim/state.h"
#include "sim/step.h"
#include "test.h"

/* `simulate --hash` of the whole lake and reef, as pinned in test_world.c */
#define LAKE_END_HASH 0x0ec10daeb2943062ULL
#define REEF_END_HASH 0x4382509839f42aebULL

/* frames of the sliced render compared, and the checkpoint interval of the lake, steps */
#define SLICE_FRAMES 3
#define LAKE_EVERY 150

static char dir_buf[600];

static const char *tmp(const char *name) {
    snprintf(dir_buf, sizeof dir_buf, "%s", ww_test_tmpdir(name));
    return dir_buf;
}

/* straight to the middle; write, read back; both on to the last frame's step */
static void roundtrip(const char *path, uint64_t pinned_end) {
    ww_scene *sc = NULL;
    ww_error err = {0};
    ENSURE_MSG(ww_scene_load(path, NULL, 0, &sc, &err) == WW_OK, "%s", err.msg);
    if (!sc) return;
    int64_t end = (sc->frame_count - 1) * sc->steps_per_frame, mid = end / 2 + 1;
    uint64_t h = 0;
    ENSURE(ww_checkpoint_scene_hash(path, NULL, NULL, 0, &h, &err) == WW_OK);
    ww_state *st = ww_state_new(sc);
    ENSURE(ww_sim_advance_to(sc, st, mid, &err) == WW_OK);
    char file[700];
    ww_checkpoint_path(tmp("ck"), mid, file, sizeof file);
    ENSURE_MSG(ww_checkpoint_write(file, h, st, NULL, 0, &err) == WW_OK, "%s", err.msg);
    ww_checkpoint ck;
    ENSURE_MSG(ww_checkpoint_read(file, sc, h, &ck, &err) == WW_OK, "%s", err.msg);
    if (ck.st) {
        ENSURE_EQ_INT(ck.step, mid);
        ENSURE_EQ_U64(ww_state_hash(sc, ck.st), ww_state_hash(sc, st));
        /* the pointers were bound into the new block, not read from the file */
        ENSURE((unsigned char *)ck.st->cam_pos > (unsigned char *)ck.st &&
               (unsigned char *)ck.st->cam_pos < (unsigned char *)ck.st + ck.st->bytes);
        ENSURE(ww_sim_advance_to(sc, ck.st, end, &err) == WW_OK);
        ENSURE(ww_sim_advance_to(sc, st, end, &err) == WW_OK);
        uint64_t a = ww_state_hash(sc, st), b = ww_state_hash(sc, ck.st);
        ENSURE_MSG(a == b, "%s: straight %016llx, from the checkpoint %016llx", path,
                   (unsigned long long)a, (unsigned long long)b);
        if (pinned_end) ENSURE_EQ_U64(b, pinned_end);
    }
    ww_checkpoint_free(&ck);
    ww_state_free(st);
    ww_scene_free(sc);
}

TEST(ckpt_state_hash_after_load_equals_straight_run) {
    roundtrip("scenes/lake.yaml", LAKE_END_HASH);
    roundtrip("scenes/reef.yaml", REEF_END_HASH);
    roundtrip("scenes/cubes.yaml", 0);
    roundtrip("scenes/fishing.yaml", 0);
}

/* what the build id and the scene hash hold */
TEST(ckpt_identity_build_and_scene) {
    ENSURE(ww_checkpoint_build_id() == ww_checkpoint_build_id());
    ww_error err = {0};
    ww_set set = {"seed=8"};
    uint64_t a = 0, b = 0, c = 0;
    ENSURE(ww_checkpoint_scene_hash("scenes/lake.yaml", NULL, NULL, 0, &a, &err) == WW_OK);
    ENSURE(ww_checkpoint_scene_hash("scenes/lake.yaml", NULL, &set, 1, &b, &err) == WW_OK);
    ENSURE(ww_checkpoint_scene_hash("scenes/reef.yaml", NULL, NULL, 0, &c, &err) == WW_OK);
    ENSURE(a != b && a != c && b != c);
    ENSURE(ww_checkpoint_scene_hash("scenes/no_such.yaml", NULL, NULL, 0, &a, &err) == WW_E_NOFILE);
}

/* ---- the command line --------------------------------------------------------------------- */

static char cmd[4096];

static int run_ww(const char *err_name, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static int run_ww(const char *err_name, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(cmd, sizeof cmd, fmt, ap);
    va_end(ap);
    return ww_test_ww(cmd, NULL, err_name);
}

static int exists(const char *path) {
    struct stat sb;
    return stat(path, &sb) == 0;
}

/* the lake's checkpoints every LAKE_EVERY steps into dir */
static int lake_checkpoints(const char *dir) {
    return run_ww(NULL, "simulate scenes/lake.yaml --checkpoint-every %d -o %s --quiet", LAKE_EVERY, dir);
}

TEST_PROC(ckpt_render_slice_from_checkpoint_byte_identical) {
    REQUIRE_GL();
    char ck[700], full[700], part[700], a[800], b[800];
    snprintf(ck, sizeof ck, "%s", tmp("ck"));
    snprintf(full, sizeof full, "%s", tmp("full"));
    snprintf(part, sizeof part, "%s", tmp("part"));
    ENSURE_EQ_INT(lake_checkpoints(ck), 0);
    /* step 1200 is frame 300: frames 310..312 step 40 past it, sound playing (music, engine) */
    const char *common = "render scenes/lake.yaml --frames 310:313 --size 64x36 --threads 1 --quiet";
    setenv("LP_NUM_THREADS", "1", 1);
    ENSURE_EQ_INT(run_ww(NULL, "%s -o %s --audio %s/t.wav", common, full, full), 0);
    ENSURE_EQ_INT(run_ww(NULL, "%s -o %s --audio %s/t.wav --from-checkpoint %s/step_000000001200.wwck",
                         common, part, part, ck), 0);
    int same = 0;
    for (int f = 310; f < 313; f++) {
        snprintf(a, sizeof a, "%s/frame_%05d.png", full, f);
        snprintf(b, sizeof b, "%s/frame_%05d.png", part, f);
        same += ww_test_files_equal(a, b);
    }
    ENSURE_EQ_INT(same, SLICE_FRAMES);
    snprintf(a, sizeof a, "%s/t.wav", full);
    snprintf(b, sizeof b, "%s/t.wav", part);
    ENSURE(ww_test_files_equal(a, b));
}

/* the sound track alone (no GL) from checkpoints taken while one-shots were still sounding
 * (steps 300, 450, 750: splashes of the throws at 1 s and 3 s, the cast) and one after */
TEST_PROC(ckpt_sound_track_from_checkpoint_sample_exact) {
    char ck[700], a[800], b[800];
    snprintf(ck, sizeof ck, "%s", tmp("ck"));
    ENSURE_EQ_INT(lake_checkpoints(ck), 0);
    static const int steps[] = {300, 450, 750, 1500};
    int same = 0;
    for (int i = 0; i < 4; i++) {
        int s = steps[i], first = s / 4 + 1;
        snprintf(a, sizeof a, "%s/full_%d.wav", ck, s);
        snprintf(b, sizeof b, "%s/part_%d.wav", ck, s);
        const char *common = "render scenes/lake.yaml --backend null --format none --quiet";
        ENSURE_EQ_INT(run_ww(NULL, "%s --frames %d:%d --audio %s", common, first, first + 45, a), 0);
        ENSURE_EQ_INT(run_ww(NULL, "%s --frames %d:%d --audio %s --from-checkpoint %s/step_%012d.wwck",
                             common, first, first + 45, b, ck, s), 0);
        same += ww_test_files_equal(a, b);
    }
    /* the folder: the latest checkpoint at or before frame 200's step 800 (step 750) */
    snprintf(b, sizeof b, "%s/part_dir.wav", ck);
    ENSURE_EQ_INT(run_ww(NULL, "render scenes/lake.yaml --backend null --format none --quiet "
                               "--frames 200:245 --audio %s --from-checkpoint %s", b, ck), 0);
    snprintf(a, sizeof a, "%s/full_dir.wav", ck);
    ENSURE_EQ_INT(run_ww(NULL, "render scenes/lake.yaml --backend null --format none --quiet "
                               "--frames 200:245 --audio %s", a), 0);
    same += ww_test_files_equal(a, b);
    ENSURE_EQ_INT(same, 5);
}

TEST_PROC(ckpt_simulate_from_checkpoint_reaches_pinned_hash) {
    char ck[700], out[800];
    snprintf(ck, sizeof ck, "%s", tmp("ck"));
    ENSURE_EQ_INT(lake_checkpoints(ck), 0);
    snprintf(out, sizeof out, "%s/hash.txt", ck);
    snprintf(cmd, sizeof cmd,
             "simulate scenes/lake.yaml --hash --from-checkpoint %s/step_000000001200.wwck", ck);
    ENSURE_EQ_INT(ww_test_ww(cmd, out, NULL), 0);
    char *h = ww_test_read_file(out, NULL), pinned[17];
    snprintf(pinned, sizeof pinned, "%016llx", (unsigned long long)LAKE_END_HASH);
    ENSURE(h && strncmp(h, pinned, 16) == 0);
    free(h);
    /* loaded and not stepped: the hash at the checkpoint's own frame (step 1200 = frame 300) */
    snprintf(cmd, sizeof cmd,
             "simulate scenes/lake.yaml --frames 300:301 --hash --from-checkpoint "
             "%s/step_000000001200.wwck", ck);
    ENSURE_EQ_INT(ww_test_ww(cmd, out, NULL), 0);
    char *x = ww_test_read_file(out, NULL);
    ENSURE_EQ_INT(ww_test_ww("simulate scenes/lake.yaml --frames 301 --hash", out, NULL), 0);
    char *y = ww_test_read_file(out, NULL);
    ENSURE(x && y && strcmp(x, y) == 0);
    free(x);
    free(y);
    /* a chain: from step 750 on, the checkpoints written again are the same files, sound state
     * included (the listener restored from the first one) */
    char chain[800], a[900], b[900];
    snprintf(chain, sizeof chain, "%s/chain", ck);
    ENSURE_EQ_INT(run_ww(NULL, "simulate scenes/lake.yaml --quiet --checkpoint-every %d -o %s "
                               "--from-checkpoint %s/step_000000000750.wwck", LAKE_EVERY, chain, ck), 0);
    int same = 0, n = 0;
    for (int s = 900; s < 2400; s += LAKE_EVERY, n++) {
        snprintf(a, sizeof a, "%s/step_%012d.wwck", ck, s);
        snprintf(b, sizeof b, "%s/step_%012d.wwck", chain, s);
        same += ww_test_files_equal(a, b);
    }
    ENSURE_EQ_INT(same, n);
}

/* a copy of src with its bytes changed at `at` (or cut to `cut` bytes when cut >= 0) */
static void doctor(const char *src, const char *dst, long at, unsigned char xor_with, long cut,
                   int fake_build) {
    size_t n = 0;
    unsigned char *d = (unsigned char *)ww_test_read_file(src, &n);
    ENSURE(d != NULL);
    if (!d) return;
    if (at >= 0 && (size_t)at < n) d[at] ^= xor_with;
    if (fake_build) {
        /* another build's id, with the header's checksum made right for it: the file is whole,
         * only its build differs */
        for (int i = 16; i < 24; i++) d[i] ^= 0x5a;
        uint64_t h = ww_hash_bytes(WW_HASH_INIT, d, 88);
        for (int i = 0; i < 8; i++) d[88 + i] = (unsigned char)(h >> (8 * i));
    }
    FILE *f = fopen(dst, "wb");
    ENSURE(f != NULL);
    if (f) {
        fwrite(d, 1, cut >= 0 ? (size_t)cut : n, f);
        fclose(f);
    }
    free(d);
}

TEST_PROC(ckpt_refusals_exit_2_and_leave_nothing) {
    char ck[700], good[800], bad[800], out[800], wav[800], errf[800];
    snprintf(ck, sizeof ck, "%s", tmp("ck"));
    ENSURE_EQ_INT(lake_checkpoints(ck), 0);
    snprintf(good, sizeof good, "%s/step_000000000600.wwck", ck);
    snprintf(bad, sizeof bad, "%s/bad.wwck", ck);
    snprintf(out, sizeof out, "%s/out", ck);
    snprintf(wav, sizeof wav, "%s/t.wav", ck);
    snprintf(errf, sizeof errf, "%s/err.txt", ck);
    struct {
        const char *name, *scene, *set;
        long at, cut;
        int fake, from_good;
        const char *says;
    } cases[] = {
        {"other scene", "scenes/reef.yaml", "", -1, -1, 0, 1, "another scene"},
        {"other --set", "scenes/lake.yaml", "--set seed=8", -1, -1, 0, 1, "other --set"},
        {"other build", "scenes/lake.yaml", "", -1, -1, 1, 0, "another build"},
        {"truncated", "scenes/lake.yaml", "", -1, 5000, 0, 0, "truncated"},
        {"truncated header", "scenes/lake.yaml", "", -1, 40, 0, 0, "truncated"},
        {"bit flip in the state", "scenes/lake.yaml", "", 5000, -1, 0, 0, "corrupt"},
        {"bit flip in the header", "scenes/lake.yaml", "", 33, -1, 0, 0, "corrupt"},
        {"not a checkpoint", "scenes/lake.yaml", "", 0, -1, 0, 0, "not a waterworld checkpoint"},
    };
    int refused = 0;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        if (!cases[i].from_good) doctor(good, bad, cases[i].at, 0x10, cases[i].cut, cases[i].fake);
        const char *file = cases[i].from_good ? good : bad;
        int rc = run_ww(errf, "render %s %s --backend null --frames 200:202 -o %s --audio %s "
                              "--from-checkpoint %s", cases[i].scene, cases[i].set, out, wav, file);
        ENSURE_MSG(rc == 2, "%s: exit %d, expected 2", cases[i].name, rc);
        ENSURE_MSG(ww_test_file_contains(errf, file), "%s: the message names no file", cases[i].name);
        ENSURE_MSG(ww_test_file_contains(errf, cases[i].says), "%s: the message does not say '%s'",
                   cases[i].name, cases[i].says);
        ENSURE_MSG(!exists(out) && !exists(wav), "%s: output left behind", cases[i].name);
        refused += rc == 2;
    }
    ENSURE_EQ_INT(refused, (int)(sizeof cases / sizeof cases[0]));
    /* a checkpoint after the first frame asked for */
    ENSURE_EQ_INT(run_ww(errf, "render scenes/lake.yaml --backend null --frames 100:102 -o %s "
                               "--from-checkpoint %s", out, good), 2);
    ENSURE(ww_test_file_contains(errf, "after the first frame"));
    ENSURE(!exists(out));
    /* simulate refuses the same way */
    doctor(good, bad, 5000, 0x01, -1, 0);
    ENSURE_EQ_INT(run_ww(errf, "simulate scenes/lake.yaml --hash --from-checkpoint %s", bad), 2);
    ENSURE_EQ_INT(run_ww(errf, "simulate scenes/lake.yaml --checkpoint-every 0 -o %s", out), 2);
    ENSURE_EQ_INT(run_ww(errf, "simulate scenes/lake.yaml --checkpoint-every 10"), 2);
    ENSURE(!exists(out));
}

/* a long prefix says how far it is; --quiet says nothing */
TEST_PROC(ckpt_prefix_progress_line) {
    char errf[800];
    snprintf(errf, sizeof errf, "%s/err.txt", tmp("p"));
    const char *r = "render scenes/lake.yaml --set time.duration=200 --backend null --format none "
                    "--frames 5990:5991";
    ENSURE_EQ_INT(run_ww(errf, "%s --progress", r), 0);
    ENSURE(ww_test_file_contains(errf, "simulating the prefix: step "));
    ENSURE(ww_test_file_contains(errf, "steps/s  ETA "));
    ENSURE_EQ_INT(run_ww(errf, "%s --quiet", r), 0);
    char *e = ww_test_read_file(errf, NULL);
    ENSURE(e && e[0] == 0);
    free(e);
    ENSURE_EQ_INT(run_ww(errf, "simulate scenes/lake.yaml --set time.duration=200 --progress"), 0);
    ENSURE(ww_test_file_contains(errf, "simulating: step "));
}
