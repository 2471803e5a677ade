/* test_bounds.c - every reader bounded, every bad input a clear exit 2 before any work (README,
 * "Limits"): scenes and scripts from /dev/zero and FIFOs, files past their caps refused unread,
 * images looked at on load and decoded only by a command that draws, WAV headers and the
 * streaming resampler, OBJ errors that name both places, empty lists, output paths checked before
 * the first frame, and command-line limits that agree with the scene's. Inputs are small files
 * made in each test's own folder (a file past a size cap is sparse: nothing is written).
 */
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io/png_read.h"
#include "io/wav.h"
#include "io/writers.h"
#include "scene/assets.h"
#include "scene/obj.h"
#include "scene/scene.h"
#include "test.h"
#include "check/compare.h"
#include "render/audio.h"

/* allocations the streaming resampler makes for a file, whatever its length: the clip and one
 * block of raw bytes */
#define RESAMPLER_ALLOCS 2

/* ---- files ----------------------------------------------------------------------------------- */

static int write_bytes(const char *path, const void *data, size_t len) {
    FILE *f = fopen(path, "wb");
    if (!f) return -1;
    int bad = fwrite(data, 1, len, f) != len;
    return fclose(f) != 0 || bad ? -1 : 0;
}

/* a file of `size` bytes that holds `head` at its start and a hole after it */
static int write_sparse(const char *path, const void *head, size_t len, off_t size) {
    if (write_bytes(path, head, len)) return -1;
    return truncate(path, size);
}

static void put16(unsigned char *p, unsigned v) {
    p[0] = (unsigned char)(v & 0xff);
    p[1] = (unsigned char)(v >> 8 & 0xff);
}
static void put32(unsigned char *p, unsigned v) {
    put16(p, v & 0xffff);
    put16(p + 2, v >> 16);
}
static void put32be(unsigned char *p, unsigned v) {
    for (int i = 0; i < 4; i++) p[i] = (unsigned char)(v >> (24 - 8 * i));
}

/* a PCM WAV of `frames` frames (samples from a counter), or only its header with a data chunk
 * that claims `frames` when data is 0 */
static int write_wav(const char *path, int rate, int channels, int bits, long frames, int data) {
    size_t bytes = (size_t)frames * (size_t)channels * (size_t)(bits / 8);
    size_t total = 44 + (data ? bytes : 0);
    unsigned char *b = calloc(1, total);
    if (!b) return -1;
    memcpy(b, "RIFF", 4);
    put32(b + 4, (unsigned)(36 + bytes));
    memcpy(b + 8, "WAVEfmt ", 8);
    put32(b + 16, 16);
    put16(b + 20, 1);
    put16(b + 22, (unsigned)channels);
    put32(b + 24, (unsigned)rate);
    put32(b + 28, (unsigned)(rate * channels * bits / 8));
    put16(b + 32, (unsigned)(channels * bits / 8));
    put16(b + 34, (unsigned)bits);
    memcpy(b + 36, "data", 4);
    put32(b + 40, (unsigned)bytes);
    for (size_t i = 0; data && i < bytes; i++) b[44 + i] = (unsigned char)(i * 37 + i / 5);
    int r = write_bytes(path, b, total);
    free(b);
    return r;
}

/* CRC-32 of PNG chunks (ISO 3309), bit by bit: a few bytes per test */
static unsigned crc32(const unsigned char *p, size_t n) {
    unsigned c = 0xffffffffu;
    for (size_t i = 0; i < n; i++) {
        c ^= p[i];
        for (int k = 0; k < 8; k++) c = c & 1 ? 0xedb88320u ^ (c >> 1) : c >> 1;
    }
    return c ^ 0xffffffffu;
}

/* a PNG that holds a header for w x h RGB8 and, when broken, an IDAT of garbage: readable
 * by a header reader, not decodable */
static int write_png_header(const char *path, unsigned w, unsigned h, int broken) {
    unsigned char b[128];
    size_t n = 0;
    memcpy(b, "\x89PNG\r\n\x1a\n", 8);
    n = 8;
    put32be(b + n, 13);
    memcpy(b + n + 4, "IHDR", 4);
    put32be(b + n + 8, w);
    put32be(b + n + 12, h);
    memcpy(b + n + 16, "\x08\x02\x00\x00\x00", 5);
    put32be(b + n + 21, crc32(b + n + 4, 17));
    n += 25;
    if (broken) {
        put32be(b + n, 8);
        memcpy(b + n + 4, "IDATgarbage!", 12);
        put32be(b + n + 16, crc32(b + n + 4, 12));
        n += 20;
    }
    put32be(b + n, 0);
    memcpy(b + n + 4, "IEND", 4);
    put32be(b + n + 8, crc32(b + n + 4, 4));
    n += 12;
    return write_bytes(path, b, n);
}

static ww_result load_text(const char *name, const char *text, ww_scene **sc, ww_error *err) {
    *sc = NULL;
    return ww_scene_load_string(name, text, strlen(text), NULL, 0, sc, err);
}

/* ---- scenes and scripts --------------------------------------------------------------------- */

/* /dev/zero never ends: read to one byte past the cap, then refused */
TEST(bounds_scene_and_script_from_dev_zero) {
    ww_scene *sc = NULL;
    ww_error err = {0};
    ENSURE_EQ_INT(ww_scene_load("/dev/zero", NULL, 0, &sc, &err), WW_E_RANGE);
    ENSURE(sc == NULL && strcmp(err.file, "/dev/zero") == 0);
    ENSURE_EQ_INT(ww_scene_load_with_script("scenes/minimal.yaml", "/dev/zero", NULL, 0, &sc, &err),
                  WW_E_RANGE);
    ENSURE(sc == NULL && strcmp(err.file, "/dev/zero") == 0);
}

/* a regular file past the cap is refused by its size, unread (the file is a hole) */
TEST(bounds_scene_file_over_its_cap) {
    char path[600];
    snprintf(path, sizeof path, "%s/big.yaml", ww_test_tmpdir("big_scene"));
    static const char head[] = "time: {duration: 1}\n";
    ENSURE(write_sparse(path, head, sizeof head - 1, (off_t)WW_SCENE_MAX_BYTES + 1) == 0);
    ww_scene *sc = NULL;
    ww_error err = {0};
    ENSURE_EQ_INT(ww_scene_load(path, NULL, 0, &sc, &err), WW_E_RANGE);
    ENSURE(strcmp(err.file, path) == 0);
    /* at the cap exactly it is read (and fails as YAML: NUL bytes) */
    ENSURE(truncate(path, (off_t)WW_SCENE_MAX_BYTES) == 0);
    ENSURE(ww_scene_load(path, NULL, 0, &sc, &err) != WW_E_RANGE);
    ww_scene_free(sc);
}

/* more keys and values than the largest scene the format allows: refused at the first over */
TEST(bounds_scene_node_cap) {
    size_t n = (size_t)WW_SCENE_MAX_NODES + 16;
    char *text = malloc(16 + 2 * n);
    ENSURE(text != NULL);
    if (!text) return;
    size_t at = (size_t)sprintf(text, "script: [");
    for (size_t i = 0; i < n; i++) {
        text[at++] = '0';
        text[at++] = ',';
    }
    text[at - 1] = ']';
    text[at] = 0;
    ww_scene *sc = NULL;
    ww_error err = {0};
    ENSURE_EQ_INT(ww_scene_load_string("nodes.yaml", text, at, NULL, 0, &sc, &err), WW_E_RANGE);
    ENSURE_EQ_INT(err.line, 1);
    ENSURE(err.column > 2 * (WW_SCENE_MAX_NODES - 2));
    free(text);
}

/* ---- files a scene names ----------------------------------------------------------------------- */

/* a device or a FIFO named as an asset: refused at its line, without opening it (a FIFO with no
 * writer would block an open) */
TEST(bounds_named_files_must_be_regular) {
    const char *dir = ww_test_tmpdir("regular");
    char fifo[600], text[2048];
    snprintf(fifo, sizeof fifo, "%s/pipe.wav", dir);
    ENSURE(mkfifo(fifo, 0600) == 0);
    static const char *const keys[] = {
        "audio: {sounds: {thud: %s}}\n",
        "objects: {models: [{obj: %s}]}\n",
        "sky: {model: cubemap, cubemap: [%s, %s, %s, %s, %s, %s]}\n",
    };
    const char *paths[] = {"/dev/zero", fifo};
    for (size_t k = 0; k < sizeof keys / sizeof keys[0]; k++) {
        for (int p = 0; p < 2; p++) {
            int n = snprintf(text, sizeof text, "time: {duration: 1}\n");
            snprintf(text + n, sizeof text - (size_t)n, keys[k], paths[p], paths[p], paths[p],
                     paths[p], paths[p], paths[p]);
            ww_scene *sc = NULL;
            ww_error err = {0};
            ENSURE_MSG(load_text("named.yaml", text, &sc, &err) == WW_E_NOFILE && err.line == 2,
                       "%s: %s:%d:%d %s", text, err.file, err.line, err.column, err.msg);
            ww_scene_free(sc);
        }
    }
}

/* ---- images ---------------------------------------------------------------------------------- */

/* the header is all a load reads: a size past the caps is refused, a body that cannot decode
 * fails only when decoded, at the place that named it */
TEST(bounds_images_header_at_load_decoded_when_drawn) {
    const char *dir = ww_test_tmpdir("images");
    char path[600];
    ww_assets a = {0};
    ww_error err = {0};
    int idx = -1;

    snprintf(path, sizeof path, "%s/wide.png", dir);
    ENSURE(write_png_header(path, WW_IMAGE_MAX_SIDE + 1, 16, 0) == 0);
    ENSURE_EQ_INT(ww_assets_image(&a, path, "s.yaml", 4, 9, &idx, &err), WW_E_RANGE);
    ENSURE(strcmp(err.file, "s.yaml") == 0 && err.line == 4 && err.column == 9);

    /* a 4096^2 header over garbage: loads (64 MB were never decoded), fails to decode */
    snprintf(path, sizeof path, "%s/broken.png", dir);
    ENSURE(write_png_header(path, 4096, 4096, 1) == 0);
    ENSURE_EQ_INT(ww_assets_image(&a, path, "s.yaml", 5, 3, &idx, &err), WW_OK);
    ENSURE(idx == 0 && a.image[0].width == 4096 && a.image[0].height == 4096);
    unsigned char *px = NULL;
    ENSURE_EQ_INT(ww_assets_decode(&a.image[0], &px, &err), WW_E_SYNTAX);
    ENSURE(px == NULL && strcmp(err.file, "s.yaml") == 0 && err.line == 5 && err.column == 3);

    /* a file past the byte cap: refused by its size */
    snprintf(path, sizeof path, "%s/huge.png", dir);
    ENSURE(write_sparse(path, "\x89PNG", 4, (off_t)WW_IMAGE_MAX_BYTES + 1) == 0);
    ENSURE_EQ_INT(ww_assets_image(&a, path, "s.yaml", 6, 1, &idx, &err), WW_E_RANGE);
    ww_assets_free(&a);

    /* the scene's texels: six 8192^2 faces fit, a seventh image does not */
    for (int i = 0; i < 7; i++) {
        snprintf(path, sizeof path, "%s/face%d.png", dir, i);
        ENSURE(write_png_header(path, WW_IMAGE_MAX_SIDE, WW_IMAGE_MAX_SIDE, 0) == 0);
        ENSURE_EQ_INT(ww_assets_image(&a, path, "s.yaml", 7 + i, 1, &idx, &err),
                      i < 6 ? WW_OK : WW_E_RANGE);
    }
    ww_assets_free(&a);
}

/* a JPEG whose frame header lies past the first 64 KiB (two large APP1 segments): the whole
 * file is looked at, and its size read */
TEST(bounds_image_header_past_the_peek) {
    const char *dir = ww_test_tmpdir("jpeg");
    char path[600];
    snprintf(path, sizeof path, "%s/exif.jpg", dir);
    size_t n = 2 + 2 * (2 + 65535) + 2 + 17 + 2;
    unsigned char *b = calloc(1, n);
    ENSURE(b != NULL);
    if (!b) return;
    size_t at = 0;
    b[at++] = 0xff, b[at++] = 0xd8;
    for (int s = 0; s < 2; s++) {
        b[at++] = 0xff, b[at++] = 0xe1, b[at++] = 0xff, b[at++] = 0xff;
        at += 65533;
    }
    static const unsigned char sof[] = {0xff, 0xc0, 0x00, 0x11, 0x08, 0x00, 0x30, 0x00, 0x50, 0x03,
                                        0x01, 0x11, 0x00, 0x02, 0x11, 0x00, 0x03, 0x11, 0x00};
    memcpy(b + at, sof, sizeof sof);
    at += sizeof sof;
    b[at++] = 0xff, b[at++] = 0xd9;
    ENSURE(write_bytes(path, b, at) == 0);
    free(b);
    ww_assets a = {0};
    ww_error err = {0};
    int idx = -1;
    ENSURE_MSG(ww_assets_image(&a, path, "s.yaml", 1, 1, &idx, &err) == WW_OK, "%s", err.msg);
    ENSURE(idx == 0 && a.nimage == 1 && a.image[0].width == 80 && a.image[0].height == 48);
    ww_assets_free(&a);
}

/* ---- OBJ ------------------------------------------------------------------------------------- */

/* a binary file: the OBJ's line and column of its first NUL, and the scene's place in the
 * message; a file without faces: the scene's place */
TEST(bounds_obj_binary_and_faceless_name_both_places) {
    const char *dir = ww_test_tmpdir("obj");
    char path[600], mtl[600];
    ww_assets a = {0};
    ww_error err = {0};
    int idx = -1;
    snprintf(path, sizeof path, "%s/bin.obj", dir);
    ENSURE(write_bytes(path, "v 0 0 0\nv 1\0\x01\x02 0 0\n", 20) == 0);
    ENSURE_EQ_INT(ww_assets_obj(&a, path, "scene.yaml", 12, 10, &idx, &err), WW_E_SYNTAX);
    ENSURE(strcmp(err.file, path) == 0 && err.line == 2 && err.column == 4);
    ENSURE(strstr(err.msg, "scene.yaml:12:10") != NULL);

    snprintf(path, sizeof path, "%s/points.obj", dir);
    ENSURE(ww_test_write_text(path, "v 0 0 0\nv 1 0 0\nv 0 1 0\n") == 0);
    ENSURE_EQ_INT(ww_assets_obj(&a, path, "scene.yaml", 12, 10, &idx, &err), WW_E_EMPTY);
    ENSURE(strcmp(err.file, "scene.yaml") == 0 && err.line == 12 && err.column == 10);
    ENSURE(strstr(err.msg, "points.obj") != NULL);

    /* an error in an MTL: the MTL's line, then where the OBJ named it and where the scene did */
    snprintf(mtl, sizeof mtl, "%s/bad.mtl", dir);
    ENSURE(ww_test_write_text(mtl, "newmtl red\nKd 1 zero 0\n") == 0);
    snprintf(path, sizeof path, "%s/lib.obj", dir);
    ENSURE(ww_test_write_text(path, "# model\nmtllib bad.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n") == 0);
    ENSURE_EQ_INT(ww_assets_obj(&a, path, "scene.yaml", 12, 10, &idx, &err), WW_E_SYNTAX);
    ENSURE(strcmp(err.file, mtl) == 0 && err.line == 2);
    char obj_place[700];
    snprintf(obj_place, sizeof obj_place, "%s:2:8", path);
    ENSURE_MSG(strstr(err.msg, obj_place) && strstr(err.msg, "scene.yaml:12:10"), "%s", err.msg);
    ENSURE_EQ_INT(a.nmesh, 0);
    ww_assets_free(&a);
}

/* the scene's OBJ models together: at most WW_OBJ_MAX_ELEMENTS triangles (two files of 2.1M
 * triangles over three vertices: about 20 MB of text each) */
TEST_LONG(bounds_obj_triangles_capped_over_the_scene) {
    const char *dir = ww_test_tmpdir("obj_total");
    const long per = WW_OBJ_MAX_ELEMENTS / 2 + 100000;
    char path[2][600];
    ww_assets a = {0};
    ww_error err = {0};
    for (int k = 0; k < 2; k++) {
        snprintf(path[k], sizeof path[k], "%s/m%d.obj", dir, k);
        FILE *f = fopen(path[k], "w");
        ENSURE(f != NULL);
        if (!f) return;
        fputs("v 0 0 0\nv 1 0 0\nv 0 1 0\n", f);
        for (long i = 0; i < per; i++) fputs("f 1 2 3\n", f);
        fclose(f);
    }
    int idx = -1;
    ENSURE_EQ_INT(ww_assets_obj(&a, path[0], "s.yaml", 1, 1, &idx, &err), WW_OK);
    ENSURE_EQ_INT(ww_assets_obj(&a, path[1], "s.yaml", 2, 1, &idx, &err), WW_E_RANGE);
    ENSURE(err.line == 2 && a.nmesh == 1);
    ww_assets_free(&a);
}

/* ---- WAV ------------------------------------------------------------------------------------- */

/* the header against every cap, no sample read */
TEST(bounds_wav_header_caps) {
    const char *dir = ww_test_tmpdir("wav");
    char path[600];
    ww_wav w;
    ww_error err = {0};
    long at_cap = (long)(WW_WAV_MAX_SECONDS * 1000.0);

    /* 1 kHz 8-bit mono: 600 s is the cap, one frame more is over it */
    snprintf(path, sizeof path, "%s/long.wav", dir);
    ENSURE(write_wav(path, 1000, 1, 8, at_cap, 1) == 0);
    ENSURE_EQ_INT(ww_wav_info(path, &w, &err), WW_OK);
    ENSURE(w.frames == at_cap && w.data == NULL);
    ENSURE(write_wav(path, 1000, 1, 8, at_cap + 1, 1) == 0);
    ENSURE_EQ_INT(ww_wav_info(path, &w, &err), WW_E_RANGE);
    ENSURE_EQ_INT(ww_wav_read_resampled(path, 44100, &w, &err), WW_E_RANGE);

    /* channels and rates outside what is read */
    snprintf(path, sizeof path, "%s/odd.wav", dir);
    ENSURE(write_wav(path, 44100, 3, 16, 10, 1) == 0);
    ENSURE_EQ_INT(ww_wav_info(path, &w, &err), WW_E_SYNTAX);
    ENSURE(write_wav(path, WW_WAV_MIN_RATE - 1, 1, 16, 10, 1) == 0);
    ENSURE_EQ_INT(ww_wav_info(path, &w, &err), WW_E_SYNTAX);
    ENSURE(write_wav(path, WW_WAV_MAX_RATE + 1, 1, 16, 10, 1) == 0);
    ENSURE_EQ_INT(ww_wav_info(path, &w, &err), WW_E_SYNTAX);

    /* a data chunk that claims more than the file holds: what is there */
    ENSURE(write_wav(path, 1000, 1, 8, 60000000, 0) == 0);
    ENSURE_EQ_INT(ww_wav_info(path, &w, &err), WW_E_SYNTAX); /* no samples at all */

    /* more chunks than a WAV holds */
    size_t nchunks = WW_WAV_MAX_CHUNKS + 1, len = 12 + 8 * nchunks;
    unsigned char *b = calloc(1, len);
    ENSURE(b != NULL);
    if (!b) return;
    memcpy(b, "RIFF", 4);
    put32(b + 4, (unsigned)(len - 8));
    memcpy(b + 8, "WAVE", 4);
    for (size_t i = 0; i < nchunks; i++) memcpy(b + 12 + 8 * i, "junk", 4);
    ENSURE(write_bytes(path, b, len) == 0);
    free(b);
    ENSURE_EQ_INT(ww_wav_info(path, &w, &err), WW_E_RANGE);

    /* a file past the byte cap (a hole after a valid header), and a device */
    snprintf(path, sizeof path, "%s/huge.wav", dir);
    ENSURE(write_wav(path, 44100, 2, 16, 100, 1) == 0);
    ENSURE(truncate(path, (off_t)WW_WAV_MAX_BYTES + 1) == 0);
    ENSURE_EQ_INT(ww_wav_info(path, &w, &err), WW_E_RANGE);
    ENSURE_EQ_INT(ww_wav_info("/dev/zero", &w, &err), WW_E_NOFILE);
}

/* the resampler streams: its samples are the whole-file interpolation's to the bit (up and
 * down, across many blocks), its allocations the clip and one block whatever the length, and
 * the clip is the figure ww_wav_resampled_frames gives */
TEST(bounds_wav_resampler_streams) {
    const char *dir = ww_test_tmpdir("resample");
    char path[600];
    static const struct { int rate, channels, bits; long frames; } cases[] = {
        {22050, 2, 16, 30000}, {96000, 1, 24, 200000}, {1000, 1, 8, 9000}, {48000, 2, 32, 50000},
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        snprintf(path, sizeof path, "%s/in%zu.wav", dir, c);
        ENSURE(write_wav(path, cases[c].rate, cases[c].channels, cases[c].bits, cases[c].frames, 1) == 0);
        ww_wav whole, out;
        ww_error err = {0};
        ENSURE_EQ_INT(ww_wav_read(path, &whole, &err), WW_OK);
        long before = ww_test_alloc_count();
        ENSURE_EQ_INT(ww_wav_read_resampled(path, 44100, &out, &err), WW_OK);
        ENSURE(ww_test_alloc_count() - before <= RESAMPLER_ALLOCS);
        int64_t n = ww_wav_resampled_frames(cases[c].frames, cases[c].rate, 44100);
        ENSURE_EQ_INT(out.frames, n);
        ENSURE_EQ_INT(out.rate, 44100);
        ENSURE_EQ_INT(out.channels, cases[c].channels);
        /* the reference: render/audio.c's interpolation over the decoded file */
        double step = (double)cases[c].rate / 44100;
        long bad = 0;
        for (int64_t i = 0; i < n && out.data; i++) {
            double p = (double)i * step;
            int64_t j = (int64_t)p, k = j + 1 < whole.frames ? j + 1 : j;
            double t = p - (double)j;
            for (int ch = 0; ch < whole.channels; ch++) {
                float want = (float)((1.0 - t) * whole.data[j * whole.channels + ch] +
                                     t * whole.data[k * whole.channels + ch]);
                bad += out.data[i * whole.channels + ch] != want;
            }
        }
        ENSURE_MSG(bad == 0, "case %zu: %ld samples differ from the whole-file resampling", c, bad);
        ww_wav_free(&whole);
        ww_wav_free(&out);
    }
    /* the figure: a 600 s file at 1 kHz resamples to 600 s x 44.1 kHz + 1 frames (105.8 MB as
     * mono float), where the whole-file reader asked for its 60000 s at 1 kHz: 11 GB */
    ENSURE_EQ_INT(ww_wav_resampled_frames((int64_t)(WW_WAV_MAX_SECONDS * 1000), 1000, 44100),
                  (int64_t)(WW_WAV_MAX_SECONDS * 44100) - 44);
}

/* the scene's files together: each under 600 s, 900 s in all */
TEST(bounds_wav_files_of_a_scene_capped_together) {
    const char *dir = ww_test_tmpdir("wav_total");
    char a[600], b[600], scene[600];
    snprintf(a, sizeof a, "%s/a.wav", dir);
    snprintf(b, sizeof b, "%s/b.wav", dir);
    ENSURE(write_wav(a, 1000, 1, 8, 500000, 1) == 0); /* 500 s */
    ENSURE(write_wav(b, 1000, 1, 8, 500000, 1) == 0);
    snprintf(scene, sizeof scene, "%s/s.yaml", dir);
    ENSURE(ww_test_write_text(scene, "time: {duration: 1}\n"
                                     "audio:\n  music: {file: a.wav}\n  sounds:\n    thud: b.wav\n") == 0);
    ww_scene *sc = NULL;
    ww_error err = {0};
    ENSURE_EQ_INT(ww_scene_load(scene, NULL, 0, &sc, &err), WW_OK);
    if (!sc) return;
    ENSURE_EQ_INT(ww_audio_check(sc, &err), WW_E_RANGE);
    ENSURE(strcmp(err.file, scene) == 0 && err.line == 3);
    /* a track longer than an hour: refused before a file is read or a step taken */
    ww_audio *au = NULL;
    ww_scene_free(sc);
    ENSURE(ww_test_write_text(scene, "time: {dt: 1/10, fps: 1, duration: 3601}\naudio: {}\n") == 0);
    ENSURE_EQ_INT(ww_scene_load(scene, NULL, 0, &sc, &err), WW_OK);
    if (!sc) return;
    ENSURE_EQ_INT(ww_audio_new(sc, 0, 36010, &au, &err), WW_E_RANGE);
    ENSURE(au == NULL);
    ww_scene_free(sc);
}

/* ---- lists ----------------------------------------------------------------------------------- */

TEST(bounds_empty_lists) {
    ww_scene *sc = NULL;
    ww_error err = {0};
    ENSURE_EQ_INT(load_text("l.yaml", "camera: {path: []}\n", &sc, &err), WW_E_RANGE);
    ENSURE(err.line == 1 && err.column == 16);
    ENSURE_EQ_INT(load_text("l.yaml", "sky: {cubemap: []}\n", &sc, &err), WW_E_RANGE);
    ENSURE_EQ_INT(load_text("l.yaml", "audio: {sounds: {splash: []}}\n", &sc, &err), WW_E_RANGE);
    /* empty means none, as absent */
    static const char *const none[] = {
        "objects: {cubes: []}\n", "water: {waves: {list: []}}\n", "script: []\n", "lights: []\n",
        "objects: {bubbles: [], models: []}\n", "render: {hud: []}\n", "golden: {fallback: []}\n",
    };
    for (size_t i = 0; i < sizeof none / sizeof none[0]; i++) {
        ENSURE_MSG(load_text("l.yaml", none[i], &sc, &err) == WW_OK, "%s: %s", none[i], err.msg);
        if (!sc) continue;
        ENSURE(!sc->cubes.on && sc->nevents == 0 && sc->render.nlights == 0);
        ww_scene_free(sc);
    }
}

/* ---- the command line ------------------------------------------------------------------------ */

/* exit 2 and the file in the message; stdout empty */
static void ensure_exit2(const char *args, const char *errf, const char *needle) {
    int rc = ww_test_ww(args, NULL, errf);
    ENSURE_MSG(rc == 2, "%s: exit %d, expected 2", args, rc);
    if (needle) ENSURE_MSG(ww_test_file_contains(errf, needle), "%s: stderr lacks '%s'", args, needle);
}

/* the unbounded reads users met, now exit 2 in a fraction of a second */
TEST_PROC(bounds_cli_streams_and_caps_exit_2) {
    const char *d = ww_test_tmpdir("cli_streams");
    char dir[600], errf[700], args[2048], path[700];
    snprintf(dir, sizeof dir, "%s", d);
    snprintf(errf, sizeof errf, "%s/err.txt", dir);
    ensure_exit2("plan /dev/zero", errf, "/dev/zero");
    ensure_exit2("simulate scenes/minimal.yaml --script /dev/zero", errf, "/dev/zero");

    /* a scene from a FIFO with an endless writer: capped like /dev/zero (the writer ends on
     * SIGPIPE when the reader has had enough) */
    char cwd[512] = "";
    ENSURE(ww_test_bin()[0] == '/' || getcwd(cwd, sizeof cwd) != NULL);
    snprintf(args, sizeof args, "(cd %s && mkfifo s.yaml && { yes > s.yaml & } && %s%s%s plan s.yaml)",
             dir, cwd, cwd[0] ? "/" : "", ww_test_bin());
    ENSURE_EQ_INT(ww_test_run(args, NULL, errf), 2);

    /* a WAV named by the scene: /dev/zero, and 60 MB at 1 kHz (60000 s) */
    snprintf(path, sizeof path, "%s/zero.yaml", dir);
    ENSURE(ww_test_write_text(path, "time: {duration: 1}\naudio: {sounds: {thud: /dev/zero}}\n") == 0);
    for (int k = 0; k < 3; k++) {
        static const char *const cmds[] = {"plan %s", "simulate %s", "render %s --audio %s/a.wav -o %s/f"};
        snprintf(args, sizeof args, cmds[k], path, dir, dir);
        char place[800];
        snprintf(place, sizeof place, "%s:2:24", path);
        ensure_exit2(args, errf, place);
    }
    char wav[700];
    snprintf(wav, sizeof wav, "%s/long.wav", dir);
    ENSURE(write_wav(wav, 1000, 1, 8, 60000000, 0) == 0);
    ENSURE(truncate(wav, 44 + 60000000) == 0); /* the samples as a hole: 60 MB, nothing written */
    snprintf(path, sizeof path, "%s/long.yaml", dir);
    ENSURE(ww_test_write_text(path, "time: {duration: 1}\naudio: {music: {file: long.wav}}\n") == 0);
    snprintf(args, sizeof args, "render %s --audio %s/a.wav -o %s/f", path, dir, dir);
    ensure_exit2(args, errf, "long.yaml:2:23");
    snprintf(args, sizeof args, "sweep %s --vary seed=1:2:2", path);
    ensure_exit2(args, errf, "long.yaml:2:23");
    struct stat st;
    ENSURE(stat(wav, &st) == 0);
    snprintf(path, sizeof path, "%s/f", dir);
    ENSURE(stat(path, &st) != 0); /* no folder, no frame */
}

/* images: plan and simulate never decode; render does, and a face broken past its header is
 * exit 2 at its scene line, before any frame */
TEST_PROC(bounds_cli_images_decoded_only_when_drawn) {
    const char *d = ww_test_tmpdir("cli_images");
    char dir[600], errf[700], args[2048], path[700];
    snprintf(dir, sizeof dir, "%s", d);
    snprintf(errf, sizeof errf, "%s/err.txt", dir);
    for (int i = 0; i < 6; i++) {
        snprintf(path, sizeof path, "%s/f%d.png", dir, i);
        ENSURE(write_png_header(path, 64, 64, 1) == 0);
    }
    snprintf(path, sizeof path, "%s/sky.yaml", dir);
    ENSURE(ww_test_write_text(path, "time: {duration: 1}\nrender: {size: [32, 18]}\n"
                                    "sky:\n  model: cubemap\n"
                                    "  cubemap: [f0.png, f1.png, f2.png, f3.png, f4.png, f5.png]\n") == 0);
    snprintf(args, sizeof args, "plan %s", path);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, errf), 0);
    snprintf(args, sizeof args, "simulate %s --frames 2", path);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, errf), 0);
    REQUIRE_GL();
    snprintf(args, sizeof args, "render %s --frames 1 -o %s/frames", path, dir);
    char place[800];
    snprintf(place, sizeof place, "%s:5:13", path);
    ensure_exit2(args, errf, place);
    char frames[700];
    snprintf(frames, sizeof frames, "%s/frames", dir);
    struct stat st;
    ENSURE(stat(frames, &st) != 0);
}

/* every output path checked before any work: nothing is rendered, made or left behind */
TEST_PROC(bounds_cli_outputs_checked_first) {
    const char *d = ww_test_tmpdir("cli_outputs");
    char dir[600], errf[700], args[2048], file[700], frames[700];
    snprintf(dir, sizeof dir, "%s", d);
    snprintf(errf, sizeof errf, "%s/err.txt", dir);
    snprintf(file, sizeof file, "%s/file.txt", dir);
    snprintf(frames, sizeof frames, "%s/frames", dir);
    ENSURE(ww_test_write_text(file, "x\n") == 0);
    const char *scene = "scenes/minimal.yaml";
    static const char *const bad[] = {
        "render %s --frames 2 -o %s/frames --audio %s",             /* a folder as a file */
        "render %s --frames 2 -o %s/frames --stats %s",
        "render %s --frames 2 -o %s/frames --stats %s/no/such.jsonl", /* missing folder */
        "render %s --frames 2 -o %s/frames --stats /dev/null",      /* a device */
        "render %s --frames 2 -o %s/frames --audio %s/a.wav --stats %s/a.wav", /* one file */
        "render %s --frames 2 -o %s/file.txt/frames",               /* a file as a folder */
        "render %s --frames 2 -o - --stats - --format y4m",         /* stdout twice */
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        snprintf(args, sizeof args, bad[i], scene, dir, dir, dir, dir);
        ensure_exit2(args, errf, NULL);
        struct stat st;
        ENSURE_MSG(stat(frames, &st) != 0, "%s: made %s", args, frames);
    }
    snprintf(args, sizeof args, "simulate %s --trace %s", scene, dir);
    ensure_exit2(args, errf, "--trace");
    snprintf(args, sizeof args, "simulate %s --events %s/no/such.jsonl", scene, dir);
    ensure_exit2(args, errf, "--events");
    snprintf(args, sizeof args, "sweep %s --vary seed=1:2:2 -o %s", scene, file);
    ensure_exit2(args, errf, NULL);
    snprintf(args, sizeof args, "bench sim -o %s/sub --frames 1", file);
    ensure_exit2(args, errf, NULL);
    snprintf(args, sizeof args, "compare tests/data/checker.png tests/data/checker.png --diff %s", dir);
    ensure_exit2(args, errf, "--diff");
    snprintf(args, sizeof args, "compare tests/data/checker.png %s --diff %s", file, file);
    ensure_exit2(args, errf, "--diff");
}

/* the command line's limits are the scene's: times, sizes, frames */
TEST_PROC(bounds_cli_limits_agree_with_the_scene) {
    const char *d = ww_test_tmpdir("cli_limits");
    char dir[600], errf[700], args[2048];
    snprintf(dir, sizeof dir, "%s", d);
    snprintf(errf, sizeof errf, "%s/err.txt", dir);
    const char *scene = "scenes/minimal.yaml";
    static const char *const bad[] = {
        "simulate %s --frames 0:1e12", "simulate %s --frames 1.5", "simulate %s --frames 0",
        "simulate %s --frames 5:3",    "simulate %s --frames 99999999999999999999",
        "probe %s --at 0,0 --from 1e12 --to 1e12", "probe %s --at 0,0 --every 1e8",
        "render %s --size 16385x100 --format none", "render %s --size 15x100 --format none",
        "simulate %s --set time.start=1e12", "simulate %s --set render.size=[16385,100]",
        "bench sim %s --frames 1e12",
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        snprintf(args, sizeof args, bad[i], scene);
        ensure_exit2(args, errf, NULL);
    }
    /* what the scene allows, the command line allows */
    snprintf(args, sizeof args, "probe %s --at 0,0 --from 1e9 --to 1e9", scene);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, errf), 0);
    snprintf(args, sizeof args, "simulate %s --set time.start=1e9 --frames 1", scene);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, errf), 0);
}

/* the frame readers (PNG, EXR, the compare loader) take images up to the largest frame render
 * makes, and refuse a larger one from its header: a PNG of 16385 x 1 is a few bytes, a
 * 32768 x 32768 one 1 MB, which compare held as 17 GB of floats */
TEST(bounds_frame_readers_capped_at_the_largest_frame) {
    ENSURE_EQ_INT(WW_FRAME_MAX_SIDE, WW_SIZE_MAX);
    const char *dir = ww_test_tmpdir("frame_cap");
    char png[600], exr[600];
    snprintf(png, sizeof png, "%s/wide.png", dir);
    snprintf(exr, sizeof exr, "%s/wide.exr", dir);
    ww_image im = {0}, hdr = {0}, back = {0};
    ww_error err = {0};
    ENSURE_EQ_INT(ww_image_alloc(&im, WW_FRAME_MAX_SIDE + 1, 1, 3, WW_PIX_U8), 0);
    ENSURE_EQ_INT(ww_image_alloc(&hdr, WW_FRAME_MAX_SIDE + 1, 1, 4, WW_PIX_F32), 0);
    if (!im.u8 || !hdr.f32) return;
    memset(im.u8, 0, (size_t)im.width * 3);
    memset(hdr.f32, 0, (size_t)hdr.width * 4 * sizeof(float));
    ENSURE_EQ_INT(ww_write_png(png, &im, &err), WW_OK);
    ww_exr_meta meta = {0};
    ENSURE_EQ_INT(ww_write_exr(exr, &hdr, &meta, &err), WW_OK);
    ENSURE_EQ_INT(ww_read_png(png, &back, &err), WW_E_RANGE);
    ENSURE_MSG(strstr(err.msg, "16385x1"), "%s", err.msg);
    ww_image_free(&back);
    ENSURE(ww_read_exr(exr, &back, &err) != WW_OK);
    ww_image_free(&back);
    ww_cmp_image c;
    ENSURE_EQ_INT(ww_cmp_load(png, &c, &err), WW_E_RANGE);
    ww_cmp_image_free(&c);
    ENSURE(ww_cmp_load(exr, &c, &err) != WW_OK);
    ww_cmp_image_free(&c);
    /* one pixel narrower is read */
    ww_image_free(&im);
    ENSURE_EQ_INT(ww_image_alloc(&im, WW_FRAME_MAX_SIDE, 1, 3, WW_PIX_U8), 0);
    if (im.u8) memset(im.u8, 0, (size_t)im.width * 3);
    ENSURE_EQ_INT(ww_write_png(png, &im, &err), WW_OK);
    ENSURE_EQ_INT(ww_cmp_load(png, &c, &err), WW_OK);
    ENSURE(c.width == WW_FRAME_MAX_SIDE && c.height == 1);
    ww_cmp_image_free(&c);
    ww_image_free(&im);
    ww_image_free(&hdr);
}
