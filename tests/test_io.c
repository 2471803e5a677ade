/* test_io.c - frame files: atomic writes (nothing partial, no temporary left behind), mkdir -p,
 * whole-file reads, PNG and EXR round trips, half-float rounding, EXR attributes, and bad or
 * truncated inputs.
 */
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <OpenEXR/openexr.h>
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include "core/error.h"
#include "io/deflate.h"
#include "io/image.h"
#include "io/writers.h"
#include "test.h"

/* ---- helpers ---- */

/* a fresh folder for one test, copied out of ww_test_tmpdir's static buffer */
static void tmpdir(const char *name, char *dir, size_t cap) {
    const char *d = ww_test_tmpdir(name);
    ENSURE(d != NULL);
    snprintf(dir, cap, "%s", d ? d : "build/test-tmp/unknown");
}

/* entries of a folder whose name contains ".tmp." */
static int count_temp_files(const char *dir) {
    DIR *d = opendir(dir);
    if (!d) return -1;
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL)
        if (strstr(e->d_name, ".tmp.")) n++;
    closedir(d);
    return n;
}

/* entries of a folder other than . and .. */
static int count_entries(const char *dir) {
    DIR *d = opendir(dir);
    if (!d) return -1;
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL)
        if (strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0) n++;
    closedir(d);
    return n;
}

static int is_dir(const char *path) {
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

/* ---- atomic writes and folders ---- */

TEST(io_atomic_write_into_missing_folder_leaves_nothing) {
    char dir[512], path[600];
    tmpdir("io_atomic_missing", dir, sizeof dir);
    snprintf(path, sizeof path, "%s/not/here.bin", dir);
    ww_error err;
    ENSURE_EQ_INT(ww_write_file_atomic(path, "abc", 3, &err), WW_E_IO);
    ENSURE(strstr(err.msg, "not/here.bin") != NULL);
    ENSURE(strstr(err.msg, strerror(ENOENT)) != NULL);
    ENSURE_EQ_INT(count_entries(dir), 0);
}

TEST(io_atomic_write_replaces_existing_file_whole) {
    char dir[512], path[600];
    tmpdir("io_atomic_replace", dir, sizeof dir);
    snprintf(path, sizeof path, "%s/f.txt", dir);
    ENSURE(ww_test_write_text(path, "the old content, longer than the new one\n") == 0);
    ww_error err;
    ENSURE_EQ_INT(ww_write_file_atomic(path, "new\n", 4, &err), WW_OK);
    size_t n = 0;
    char *got = ww_test_read_file(path, &n);
    ENSURE(got && n == 4 && memcmp(got, "new\n", 4) == 0);
    free(got);
    /* an empty write is a whole file too */
    ENSURE_EQ_INT(ww_write_file_atomic(path, NULL, 0, &err), WW_OK);
    got = ww_test_read_file(path, &n);
    ENSURE(got && n == 0);
    free(got);
    ENSURE_EQ_INT(count_temp_files(dir), 0);
    ENSURE_EQ_INT(count_entries(dir), 1);
}

TEST(io_atomic_write_over_a_folder_fails_and_cleans_up) {
    char dir[512], path[600];
    tmpdir("io_atomic_over_dir", dir, sizeof dir);
    snprintf(path, sizeof path, "%s/sub", dir);
    ENSURE_EQ_INT(mkdir(path, 0777), 0);
    ww_error err;
    /* the temporary file is written, then the rename fails: it must go */
    ENSURE_EQ_INT(ww_write_file_atomic(path, "abc", 3, &err), WW_E_IO);
    ENSURE(strstr(err.msg, "rename") != NULL);
    ENSURE_EQ_INT(count_temp_files(dir), 0);
    ENSURE(is_dir(path));
    ENSURE_EQ_INT(count_entries(dir), 1);
}

TEST(io_atomic_write_into_read_only_folder_fails_cleanly) {
    if (geteuid() == 0) {
        /* root ignores permission bits, so there is nothing to check */
        SKIP("running as root, which ignores permission bits");
    }
    char dir[512], ro[600], path[700];
    tmpdir("io_atomic_read_only", dir, sizeof dir);
    snprintf(ro, sizeof ro, "%s/ro", dir);
    snprintf(path, sizeof path, "%s/f.bin", ro);
    ENSURE_EQ_INT(mkdir(ro, 0555), 0);
    ww_error err;
    ENSURE_EQ_INT(ww_write_file_atomic(path, "abc", 3, &err), WW_E_IO);
    ENSURE(strstr(err.msg, strerror(EACCES)) != NULL);
    ENSURE_EQ_INT(count_entries(ro), 0);
    chmod(ro, 0777); /* so the next run can remove it */
}

TEST(io_make_dirs_nested_existing_and_file_in_the_way) {
    char dir[512], deep[600], file[600], under[700];
    tmpdir("io_make_dirs", dir, sizeof dir);
    snprintf(deep, sizeof deep, "%s/a/b//c/", dir);
    snprintf(file, sizeof file, "%s/plain", dir);
    snprintf(under, sizeof under, "%s/plain/x/y", dir);
    ww_error err;
    ENSURE_EQ_INT(ww_make_dirs(deep, &err), WW_OK);
    ENSURE(is_dir(deep));
    ENSURE_EQ_INT(ww_make_dirs(deep, &err), WW_OK); /* already there */
    ENSURE_EQ_INT(ww_make_dirs(dir, &err), WW_OK);

    ENSURE(ww_test_write_text(file, "x") == 0);
    ENSURE_EQ_INT(ww_make_dirs(under, &err), WW_E_IO);
    ENSURE(strstr(err.msg, "plain/x/y") != NULL);
    ENSURE(strstr(err.msg, strerror(ENOTDIR)) != NULL);
    ENSURE_EQ_INT(ww_make_dirs(file, &err), WW_E_IO); /* the last component is the file */
    ENSURE_EQ_INT(ww_make_dirs("", &err), WW_E_IO);
}

TEST(io_read_file_missing_and_folder) {
    char dir[512], path[600];
    tmpdir("io_read_file", dir, sizeof dir);
    snprintf(path, sizeof path, "%s/none", dir);
    unsigned char *data = (unsigned char *)"sentinel";
    size_t len = 5;
    ww_error err;
    ENSURE_EQ_INT(ww_read_file(path, &data, &len, &err), WW_E_NOFILE);
    ENSURE(data == NULL && len == 0);
    ENSURE_EQ_INT(ww_read_file(dir, &data, &len, &err), WW_E_NOFILE);
    ENSURE(ww_test_write_text(path, "hello") == 0);
    ENSURE_EQ_INT(ww_read_file(path, &data, &len, &err), WW_OK);
    ENSURE(data && len == 5 && memcmp(data, "hello", 6) == 0);
    free(data);
}

/* ---- PNG ---- */

/* a U8 image with a pattern that touches every byte value */
static void fill_u8(ww_image *im, int w, int h, int ch) {
    ENSURE_EQ_INT(ww_image_alloc(im, w, h, ch, WW_PIX_U8), 0);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
            for (int c = 0; c < ch; c++)
                im->u8[((size_t)y * w + x) * ch + c] = (uint8_t)(x * 7 + y * 13 + c * 29 + x * y);
}

static void png_round_trip(const char *name, int ch) {
    char dir[512], path[600];
    tmpdir(name, dir, sizeof dir);
    snprintf(path, sizeof path, "%s/a.png", dir);
    ww_image im, back;
    ww_error err;
    fill_u8(&im, 61, 37, ch);
    ENSURE_EQ_INT(ww_write_png(path, &im, &err), WW_OK);
    ENSURE_EQ_INT(ww_read_png(path, &back, &err), WW_OK);
    ENSURE_EQ_INT(back.width, 61);
    ENSURE_EQ_INT(back.height, 37);
    ENSURE_EQ_INT(back.channels, ch);
    ENSURE_EQ_INT(back.type, WW_PIX_U8);
    if (back.u8 && back.width == 61 && back.height == 37 && back.channels == ch)
        ENSURE(memcmp(im.u8, back.u8, (size_t)61 * 37 * ch) == 0);
    ENSURE_EQ_INT(count_temp_files(dir), 0);
    ww_image_free(&im);
    ww_image_free(&back);
}

/* stb_image_write into memory, for PNGs our writer does not make (grey, grey+alpha) */
typedef struct mem_out {
    unsigned char buf[1 << 16];
    size_t len;
} mem_out;

static void mem_put(void *ctx, void *data, int size) {
    mem_out *m = ctx;
    if (m->len + (size_t)size > sizeof m->buf) return;
    memcpy(m->buf + m->len, data, (size_t)size);
    m->len += (size_t)size;
}

/* PNG chunk CRC (ISO 3309, bitwise) and zlib's Adler-32, for a hand-made 16-bit PNG */
static uint32_t crc32_update(uint32_t crc, const unsigned char *p, size_t n) {
    crc = ~crc;
    for (size_t i = 0; i < n; i++) {
        crc ^= p[i];
        for (int k = 0; k < 8; k++) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

static void put_be32(unsigned char *p, uint32_t v) {
    p[0] = (unsigned char)(v >> 24);
    p[1] = (unsigned char)(v >> 16);
    p[2] = (unsigned char)(v >> 8);
    p[3] = (unsigned char)v;
}

static size_t put_chunk(unsigned char *out, const char *type, const unsigned char *data,
                        uint32_t n) {
    put_be32(out, n);
    memcpy(out + 4, type, 4);
    if (n) memcpy(out + 8, data, n);
    put_be32(out + 8 + n, crc32_update(0, out + 4, 4 + (size_t)n));
    return 12 + (size_t)n;
}

/* a 16-bit RGB PNG of w x h (w * h <= 16) pixels, its IDAT one stored deflate block */
static size_t make_png16(unsigned char *out, int w, int h, const uint16_t *rgb) {
    static const unsigned char sig[8] = {137, 80, 78, 71, 13, 10, 26, 10};
    unsigned char ihdr[13] = {0}, raw[16 * 7 + 16], z[sizeof raw + 11];
    size_t n = 0, r = 0;
    memcpy(out, sig, 8);
    n = 8;
    put_be32(ihdr, (uint32_t)w);
    put_be32(ihdr + 4, (uint32_t)h);
    ihdr[8] = 16; /* bit depth */
    ihdr[9] = 2;  /* colour type RGB */
    n += put_chunk(out + n, "IHDR", ihdr, 13);
    for (int y = 0; y < h; y++) {
        raw[r++] = 0; /* filter: none */
        for (int i = 0; i < w * 3; i++) {
            uint16_t v = rgb[(size_t)y * w * 3 + i];
            raw[r++] = (unsigned char)(v >> 8);
            raw[r++] = (unsigned char)v;
        }
    }
    uint32_t a = 1, b = 0;
    for (size_t i = 0; i < r; i++) {
        a = (a + raw[i]) % 65521u;
        b = (b + a) % 65521u;
    }
    size_t zn = 0;
    z[zn++] = 0x78;
    z[zn++] = 0x01;
    z[zn++] = 0x01; /* final block, stored */
    z[zn++] = (unsigned char)r;
    z[zn++] = (unsigned char)(r >> 8);
    z[zn++] = (unsigned char)~r;
    z[zn++] = (unsigned char)(~r >> 8);
    memcpy(z + zn, raw, r);
    zn += r;
    put_be32(z + zn, (b << 16) | a);
    zn += 4;
    n += put_chunk(out + n, "IDAT", z, (uint32_t)zn);
    n += put_chunk(out + n, "IEND", NULL, 0);
    return n;
}

TEST(io_png_round_trip_rgb_exact) { png_round_trip("io_png_rgb", 3); }

TEST(io_png_round_trip_rgba_exact) { png_round_trip("io_png_rgba", 4); }

TEST(io_png_bytes_identical_across_writes) {
    char dir[512], a[600], b[600];
    tmpdir("io_png_bytes", dir, sizeof dir);
    snprintf(a, sizeof a, "%s/a.png", dir);
    snprintf(b, sizeof b, "%s/b.png", dir);
    ww_image im;
    ww_error err;
    fill_u8(&im, 128, 96, 4);
    ENSURE_EQ_INT(ww_write_png(a, &im, &err), WW_OK);
    ENSURE_EQ_INT(ww_write_png(b, &im, &err), WW_OK);
    size_t na = 0, nb = 0;
    char *da = ww_test_read_file(a, &na), *db = ww_test_read_file(b, &nb);
    ENSURE(da && db);
    ENSURE(na > 0);
    ENSURE_EQ_INT(na, nb);
    if (da && db && na == nb) ENSURE(memcmp(da, db, na) == 0);
    free(da);
    free(db);
    ww_image_free(&im);
}

TEST(io_png_grey_reads_back_as_rgb_and_grey_alpha_as_rgba) {
    char dir[512], g[600], ga[600];
    tmpdir("io_png_grey", dir, sizeof dir);
    snprintf(g, sizeof g, "%s/grey.png", dir);
    snprintf(ga, sizeof ga, "%s/grey_alpha.png", dir);
    unsigned char px[5 * 3 * 2];
    for (int i = 0; i < 30; i++) px[i] = (unsigned char)(i * 8 + 3);
    ww_error err;
    mem_out *m = calloc(1, sizeof *m); /* 64 KiB: off the stack */
    ENSURE(m != NULL);
    if (!m) return;
    ENSURE(stbi_write_png_to_func(mem_put, m, 5, 3, 1, px, 5) != 0);
    ENSURE_EQ_INT(ww_write_file_atomic(g, m->buf, m->len, &err), WW_OK);
    m->len = 0;
    ENSURE(stbi_write_png_to_func(mem_put, m, 5, 3, 2, px, 10) != 0);
    ENSURE_EQ_INT(ww_write_file_atomic(ga, m->buf, m->len, &err), WW_OK);
    free(m);

    ww_image im;
    ENSURE_EQ_INT(ww_read_png(g, &im, &err), WW_OK);
    ENSURE_EQ_INT(im.channels, 3);
    int bad = 0;
    for (int i = 0; im.u8 && i < 15; i++)
        for (int c = 0; c < 3; c++) bad += im.u8[i * 3 + c] != px[i];
    ENSURE_EQ_INT(bad, 0);
    ww_image_free(&im);

    ENSURE_EQ_INT(ww_read_png(ga, &im, &err), WW_OK);
    ENSURE_EQ_INT(im.channels, 4);
    bad = 0;
    for (int i = 0; im.u8 && i < 15; i++) {
        for (int c = 0; c < 3; c++) bad += im.u8[i * 4 + c] != px[i * 2];
        bad += im.u8[i * 4 + 3] != px[i * 2 + 1];
    }
    ENSURE_EQ_INT(bad, 0);
    ww_image_free(&im);
}

TEST(io_png_16bit_reduced_to_high_bytes) {
    char dir[512], path[600];
    tmpdir("io_png_16bit", dir, sizeof dir);
    snprintf(path, sizeof path, "%s/deep.png", dir);
    static const uint16_t rgb[2 * 2 * 3] = {0x1234, 0xFFFF, 0x00FF, 0x8000, 0x7FFF, 0x0100,
                                            0x0000, 0xABCD, 0xFF00, 0x0001, 0x5A5A, 0xC3C3};
    unsigned char file[512];
    size_t n = make_png16(file, 2, 2, rgb);
    ww_error err;
    ENSURE_EQ_INT(ww_write_file_atomic(path, file, n, &err), WW_OK);
    ww_image im;
    ENSURE_EQ_INT(ww_read_png(path, &im, &err), WW_OK);
    ENSURE_EQ_INT(im.width, 2);
    ENSURE_EQ_INT(im.height, 2);
    ENSURE_EQ_INT(im.channels, 3);
    for (int i = 0; im.u8 && i < 12; i++) ENSURE_EQ_INT(im.u8[i], rgb[i] >> 8);
    ww_image_free(&im);
}

TEST(io_png_bad_inputs) {
    char dir[512], missing[600], text[600];
    tmpdir("io_png_bad", dir, sizeof dir);
    snprintf(missing, sizeof missing, "%s/missing.png", dir);
    snprintf(text, sizeof text, "%s/text.png", dir);
    ENSURE(ww_test_write_text(text, "this is not a picture\n") == 0);
    ww_image im;
    ww_error err;
    ENSURE_EQ_INT(ww_read_png(missing, &im, &err), WW_E_NOFILE);
    ENSURE(strstr(err.msg, "missing.png") != NULL);
    ENSURE(im.u8 == NULL && im.f32 == NULL);
    ENSURE_EQ_INT(ww_read_png(text, &im, &err), WW_E_SYNTAX);
    ENSURE(strstr(err.msg, "not a PNG") != NULL);
    ENSURE_EQ_INT(ww_read_png(dir, &im, &err), WW_E_NOFILE);
    ww_image_free(&im);
}

/* ---- EXR ---- */

/* half has an 11-bit significand: a normal value rounds to within 2^-11 of itself, relative */
#define HALF_REL_TOL 4.8828125e-4
/* below 2^-14 halves are denormal, spaced 2^-24 apart: rounding is within half that, absolute */
#define HALF_DENORM_TOL 2.98023223876953125e-8

/* the EXR test image: 37x23 RGBA with exact halves, a denormal and a smooth ramp */
static const float exr_specials[] = {0.0f, 1.0f, 0.5f, 65504.0f, -2.0f, 1e-5f};

static void fill_exr(ww_image *im, int ch) {
    ENSURE_EQ_INT(ww_image_alloc(im, 37, 23, ch, WW_PIX_F32), 0);
    size_t n = (size_t)37 * 23 * ch;
    for (size_t i = 0; i < n; i++)
        im->f32[i] = i % 7 < 6 ? exr_specials[(i / 7 + i) % 6] : (float)i * 0.37f - 300.0f;
}

static void ensure_half_near(double got, double want) {
    double tol = fabs(want) < 6.103515625e-05 ? HALF_DENORM_TOL : HALF_REL_TOL * fabs(want);
    ENSURE_NEAR(got, want, tol);
}

static ww_result write_test_exr(const char *path, int ch) {
    ww_image im;
    ww_error err;
    fill_exr(&im, ch);
    ww_exr_meta meta = {.frame = 7, .time = 0.25, .scene = "test", .renderer = NULL};
    ww_result r = ww_write_exr(path, &im, &meta, &err);
    ww_image_free(&im);
    return r;
}

TEST(io_exr_round_trip_rgba_within_half_precision) {
    char dir[512], path[600];
    tmpdir("io_exr_rgba", dir, sizeof dir);
    snprintf(path, sizeof path, "%s/a.exr", dir);
    ww_image im, back;
    ww_error err;
    fill_exr(&im, 4);
    ENSURE_EQ_INT(ww_write_exr(path, &im, NULL, &err), WW_OK);
    ENSURE_EQ_INT(ww_read_exr(path, &back, &err), WW_OK);
    ENSURE_EQ_INT(back.width, 37);
    ENSURE_EQ_INT(back.height, 23);
    ENSURE_EQ_INT(back.channels, 4);
    ENSURE_EQ_INT(back.type, WW_PIX_F32);
    if (back.f32 && back.width == 37 && back.height == 23 && back.channels == 4) {
        int exact_bad = 0;
        for (size_t i = 0; i < (size_t)37 * 23 * 4; i++) {
            float want = im.f32[i], got = back.f32[i];
            /* values a half holds exactly come back bit for bit */
            if (want == 0.0f || want == 1.0f || want == 0.5f || want == 65504.0f || want == -2.0f)
                exact_bad += got != want;
            ensure_half_near(got, want);
            if (ww_test_failed_now()) break;
        }
        ENSURE_EQ_INT(exact_bad, 0);
        /* 1e-5 is a half denormal: kept, not flushed to zero (5 -> index 5 of the specials) */
        ENSURE(back.f32[5] > 0.0f);
        ENSURE_NEAR(back.f32[5], 168.0 / 16777216.0, 0.0);
    }
    ENSURE_EQ_INT(count_temp_files(dir), 0);
    ww_image_free(&im);
    ww_image_free(&back);
}

TEST(io_exr_bytes_identical_across_writes) {
    char dir[512], a[600], b[600];
    tmpdir("io_exr_bytes", dir, sizeof dir);
    snprintf(a, sizeof a, "%s/a.exr", dir);
    snprintf(b, sizeof b, "%s/b.exr", dir);
    ENSURE_EQ_INT(write_test_exr(a, 4), WW_OK);
    ENSURE_EQ_INT(write_test_exr(b, 4), WW_OK);
    size_t na = 0, nb = 0;
    char *da = ww_test_read_file(a, &na), *db = ww_test_read_file(b, &nb);
    ENSURE(da && db);
    ENSURE_EQ_INT(na, nb);
    if (da && db && na == nb) ENSURE(memcmp(da, db, na) == 0);
    free(da);
    free(db);
}

TEST(io_exr_rgb_reads_back_with_alpha_one) {
    char dir[512], path[600];
    tmpdir("io_exr_rgb", dir, sizeof dir);
    snprintf(path, sizeof path, "%s/a.exr", dir);
    ww_image im, back;
    ww_error err;
    fill_exr(&im, 3);
    ENSURE_EQ_INT(ww_write_exr(path, &im, NULL, &err), WW_OK);
    ENSURE_EQ_INT(ww_read_exr(path, &back, &err), WW_OK);
    ENSURE_EQ_INT(back.channels, 4);
    for (size_t p = 0; back.f32 && p < (size_t)37 * 23 && !ww_test_failed_now(); p++) {
        for (int c = 0; c < 3; c++) ensure_half_near(back.f32[p * 4 + c], im.f32[p * 3 + c]);
        ENSURE(back.f32[p * 4 + 3] == 1.0f);
    }
    ww_image_free(&im);
    ww_image_free(&back);
}

/* the library's float -> half conversion, which the writer relies on: round to nearest even,
 * denormals kept, overflow to infinity, infinities and NaN preserved */
TEST(io_exr_half_conversion_rounds_to_nearest_even) {
    static const struct {
        float in, out;
    } cases[] = {
        {1.0f + 0x1p-11f, 1.0f},                      /* tie, even side is down */
        {1.0f + 3 * 0x1p-11f, 1.0f + 0x1p-9f},        /* tie, even side is up */
        {1.0f + 0x1p-11f + 0x1p-20f, 1.0f + 0x1p-10f}, /* just past the tie */
        {65519.0f, 65504.0f},                          /* below the tie to infinity */
        {0x1p-24f, 0x1p-24f},                          /* smallest denormal, exact */
        {0x1p-25f, 0.0f},                              /* tie between 0 and 2^-24: even is 0 */
        {1.5f * 0x1p-25f, 0x1p-24f},
        {3 * 0x1p-25f, 2 * 0x1p-24f},                  /* denormal tie, even side is up */
        {0x1p-14f - 0x1p-25f, 0x1p-14f},               /* denormal rounds up into normal */
        {-0.0f, -0.0f},
    };
    int n = (int)(sizeof cases / sizeof cases[0]);
    ww_image im, back;
    ww_error err;
    ENSURE_EQ_INT(ww_image_alloc(&im, n + 4, 1, 4, WW_PIX_F32), 0);
    for (int i = 0; i < (n + 4) * 4; i++) im.f32[i] = 1.0f;
    for (int i = 0; i < n; i++) im.f32[i * 4] = cases[i].in;
    im.f32[n * 4] = 65520.0f; /* tie between 65504 and 2^16: even side overflows */
    im.f32[(n + 1) * 4] = INFINITY;
    im.f32[(n + 2) * 4] = -INFINITY;
    im.f32[(n + 3) * 4] = NAN;
    char dir[512], path[600];
    tmpdir("io_exr_half", dir, sizeof dir);
    snprintf(path, sizeof path, "%s/h.exr", dir);
    ENSURE_EQ_INT(ww_write_exr(path, &im, NULL, &err), WW_OK);
    ENSURE_EQ_INT(ww_read_exr(path, &back, &err), WW_OK);
    for (int i = 0; back.f32 && i < n; i++) {
        float got = back.f32[i * 4];
        ENSURE_MSG(got == cases[i].out && signbit(got) == signbit(cases[i].out),
                   "case %d: %a -> %a, want %a", i, (double)cases[i].in, (double)got,
                   (double)cases[i].out);
    }
    if (back.f32) {
        ENSURE(isinf(back.f32[n * 4]) && back.f32[n * 4] > 0);
        ENSURE(isinf(back.f32[(n + 1) * 4]) && back.f32[(n + 1) * 4] > 0);
        ENSURE(isinf(back.f32[(n + 2) * 4]) && back.f32[(n + 2) * 4] < 0);
        ENSURE(isnan(back.f32[(n + 3) * 4]));
    }
    ww_image_free(&im);
    ww_image_free(&back);
}

TEST(io_exr_attributes_round_trip) {
    char dir[512], path[600], bare[600];
    tmpdir("io_exr_meta", dir, sizeof dir);
    snprintf(path, sizeof path, "%s/meta.exr", dir);
    snprintf(bare, sizeof bare, "%s/bare.exr", dir);
    ww_image im;
    ww_error err;
    fill_exr(&im, 4);
    ww_exr_meta meta = {.frame = 42, .time = 1.0 / 3.0, .scene = "harbour at dusk",
                        .renderer = "llvmpipe (LLVM 15.0.6, 256 bits)"};
    ENSURE_EQ_INT(ww_write_exr(path, &im, &meta, &err), WW_OK);
    ww_exr_meta none = {.frame = -1, .time = NAN, .scene = NULL, .renderer = NULL};
    ENSURE_EQ_INT(ww_write_exr(bare, &im, &none, &err), WW_OK);

    int frame = 0;
    double t = 0;
    char scene[64], gl[64];
    ENSURE_EQ_INT(ww_read_exr_meta(path, &frame, &t, scene, sizeof scene, gl, sizeof gl, &err),
                  WW_OK);
    ENSURE_EQ_INT(frame, 42);
    ENSURE(t == 1.0 / 3.0); /* a double attribute: exact */
    ENSURE(strcmp(scene, "harbour at dusk") == 0);
    ENSURE(strcmp(gl, "llvmpipe (LLVM 15.0.6, 256 bits)") == 0);

    /* strings cut to the caller's capacity; outputs may be NULL */
    char small[4];
    ENSURE_EQ_INT(ww_read_exr_meta(path, NULL, NULL, small, sizeof small, NULL, 0, &err), WW_OK);
    ENSURE(strcmp(small, "har") == 0);

    ENSURE_EQ_INT(ww_read_exr_meta(bare, &frame, &t, scene, sizeof scene, gl, sizeof gl, &err),
                  WW_OK);
    ENSURE_EQ_INT(frame, -1);
    ENSURE(isnan(t));
    ENSURE(scene[0] == '\0' && gl[0] == '\0');
    ww_image_free(&im);
}

/* an EXR our writer does not make, written with OpenEXRCore directly: 37x23 pixels, the named
 * channels (sorted) all of one type, a data window off the origin, no compression. Channel c
 * holds c * 1000 + pixel index + 0.125 (exact in float, rounded in half). */
enum { CORE_W = 37, CORE_H = 23, CORE_X0 = 3, CORE_Y0 = -2 };

static float core_value(int c, int y, int x) { return (float)(c * 1000 + y * CORE_W + x) + 0.125f; }

static exr_result_t write_core_exr(const char *path, const char *const *names, int n,
                                   exr_pixel_type_t type) {
    enum { W = CORE_W, H = CORE_H };
    float *rows = malloc(sizeof(float) * (size_t)n * W);
    exr_context_t ctx = NULL;
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    int part = 0;
    exr_attr_box2i_t win = {.min = {.x = CORE_X0, .y = CORE_Y0},
                            .max = {.x = CORE_X0 + W - 1, .y = CORE_Y0 + H - 1}};
    exr_attr_v2f_t centre = {.x = 0, .y = 0};
    exr_result_t rv = rows ? exr_start_write(&ctx, path, EXR_WRITE_FILE_DIRECTLY, &init)
                           : EXR_ERR_OUT_OF_MEMORY;
    if (!rv) rv = exr_add_part(ctx, NULL, EXR_STORAGE_SCANLINE, &part);
    if (!rv)
        rv = exr_initialize_required_attr(ctx, part, &win, &win, 1.0f, &centre, 1.0f,
                                          EXR_LINEORDER_INCREASING_Y, EXR_COMPRESSION_NONE);
    for (int c = 0; !rv && c < n; c++)
        rv = exr_add_channel(ctx, part, names[c], type, EXR_PERCEPTUALLY_LINEAR, 1, 1);
    if (!rv) rv = exr_write_header(ctx);

    /* one scanline per chunk; the library converts our floats when the file holds halves */
    /* OpenEXR 3.4's initializer sets the first field (pipe_size) and leaves the rest to zero,
     * which -Wmissing-field-initializers flags; the macro is the API, so that warning is off */
    #pragma GCC diagnostic push
    #pragma GCC diagnostic ignored "-Wmissing-field-initializers"
    exr_encode_pipeline_t enc = EXR_ENCODE_PIPELINE_INITIALIZER;
    #pragma GCC diagnostic pop
    for (int y = 0; !rv && y < H; y++) {
        exr_chunk_info_t ci;
        rv = exr_write_scanline_chunk_info(ctx, part, CORE_Y0 + y, &ci);
        if (!rv) rv = y == 0 ? exr_encoding_initialize(ctx, part, &ci, &enc)
                             : exr_encoding_update(ctx, part, &ci, &enc);
        for (int c = 0; !rv && c < enc.channel_count; c++) {
            exr_coding_channel_info_t *ch = &enc.channels[c];
            for (int x = 0; x < W; x++) rows[c * W + x] = core_value(c, y, x);
            ch->encode_from_ptr = (const uint8_t *)(rows + c * W);
            ch->user_pixel_stride = 4;
            ch->user_line_stride = 4 * W;
            ch->user_data_type = EXR_PIXEL_FLOAT;
            ch->user_bytes_per_element = 4;
        }
        if (!rv && y == 0) rv = exr_encoding_choose_default_routines(ctx, part, &enc);
        if (!rv) rv = exr_encoding_run(ctx, part, &enc);
    }
    if (ctx) exr_encoding_destroy(ctx, &enc);
    exr_result_t frv = exr_finish(&ctx);
    free(rows);
    return rv ? rv : frv;
}

/* read a write_core_exr file; rgb[s] is the sorted channel index that should land in slot s */
static void check_core_exr(const char *path, const int rgb[3], int half) {
    ww_image back;
    ww_error err;
    ENSURE_EQ_INT(ww_read_exr(path, &back, &err), WW_OK);
    ENSURE_EQ_INT(back.width, CORE_W);
    ENSURE_EQ_INT(back.height, CORE_H);
    int bad = 0;
    for (int y = 0; back.f32 && y < CORE_H; y++)
        for (int x = 0; x < CORE_W; x++) {
            const float *p = back.f32 + ((size_t)y * CORE_W + x) * 4;
            for (int s = 0; s < 3 && !half; s++) bad += p[s] != core_value(rgb[s], y, x);
            for (int s = 0; s < 3 && half; s++) ensure_half_near(p[s], core_value(rgb[s], y, x));
            bad += p[3] != 1.0f;
        }
    ENSURE_EQ_INT(bad, 0);
    ww_image_free(&back);
}

TEST(io_exr_reads_float_channels_and_skips_others) {
    char dir[512], path[600];
    tmpdir("io_exr_float", dir, sizeof dir);
    snprintf(path, sizeof path, "%s/f.exr", dir);
    static const char *const names[4] = {"B", "G", "R", "Z"};
    ENSURE_EQ_INT(write_core_exr(path, names, 4, EXR_PIXEL_FLOAT), EXR_ERR_SUCCESS);
    check_core_exr(path, (const int[3]){2, 1, 0}, 0);
}

/* a half channel we skip sorted ahead of R G B once made OpenEXRCore 3.1 write through NULL */
TEST(io_exr_reads_half_channels_and_skips_a_leading_one) {
    char dir[512], path[600];
    tmpdir("io_exr_half_skip", dir, sizeof dir);
    snprintf(path, sizeof path, "%s/h.exr", dir);
    static const char *const names[4] = {"AO", "B", "G", "R"};
    ENSURE_EQ_INT(write_core_exr(path, names, 4, EXR_PIXEL_HALF), EXR_ERR_SUCCESS);
    check_core_exr(path, (const int[3]){3, 2, 1}, 1);
}

TEST(io_exr_bad_and_truncated_inputs_fail_cleanly) {
    char dir[512], good[600], cut[600], text[600], missing[600];
    tmpdir("io_exr_bad", dir, sizeof dir);
    snprintf(good, sizeof good, "%s/good.exr", dir);
    snprintf(cut, sizeof cut, "%s/cut.exr", dir);
    snprintf(text, sizeof text, "%s/text.exr", dir);
    snprintf(missing, sizeof missing, "%s/missing.exr", dir);
    ww_image im;
    ww_error err;
    ENSURE_EQ_INT(ww_read_exr(missing, &im, &err), WW_E_NOFILE);
    ENSURE(strstr(err.msg, "missing.exr") != NULL);
    int frame;
    ENSURE_EQ_INT(ww_read_exr_meta(missing, &frame, NULL, NULL, 0, NULL, 0, &err), WW_E_NOFILE);
    ENSURE(ww_test_write_text(text, "this is not a picture\n") == 0);
    ENSURE_EQ_INT(ww_read_exr(text, &im, &err), WW_E_SYNTAX);
    ENSURE(im.f32 == NULL && im.u8 == NULL);

    ENSURE_EQ_INT(write_test_exr(good, 4), WW_OK);
    size_t n = 0;
    char *bytes = ww_test_read_file(good, &n);
    ENSURE(bytes != NULL && n > 200);
    if (!bytes || n <= 200) return;

    /* the first 100 bytes: a header cut short */
    ENSURE_EQ_INT(ww_write_file_atomic(cut, bytes, 100, &err), WW_OK);
    ENSURE_EQ_INT(ww_read_exr(cut, &im, &err), WW_E_SYNTAX);
    ENSURE(im.f32 == NULL);
    ENSURE_EQ_INT(ww_read_exr_meta(cut, &frame, NULL, NULL, 0, NULL, 0, &err), WW_E_SYNTAX);

    /* every other length, through the chunk table and the pixel data: an error, never a crash */
    int not_error = 0;
    for (size_t len = 0; len < n; len += 13) {
        ENSURE_EQ_INT(ww_write_file_atomic(cut, bytes, len, &err), WW_OK);
        ww_result r = ww_read_exr(cut, &im, &err);
        if (r != WW_E_SYNTAX) {
            not_error++;
            fprintf(stderr, "\n    length %zu of %zu read as %s", len, n, ww_result_name(r));
        }
        ww_image_free(&im);
    }
    ENSURE_EQ_INT(not_error, 0);
    free(bytes);
}

TEST(io_writers_fail_cleanly_into_missing_folder) {
    char dir[512], png[600], exr[600];
    tmpdir("io_writers_missing", dir, sizeof dir);
    snprintf(png, sizeof png, "%s/nope/a.png", dir);
    snprintf(exr, sizeof exr, "%s/nope/a.exr", dir);
    ww_image u8, f32;
    ww_error err;
    fill_u8(&u8, 8, 8, 3);
    fill_exr(&f32, 4);
    ENSURE_EQ_INT(ww_write_png(png, &u8, &err), WW_E_IO);
    ENSURE(strstr(err.msg, "nope/a.png") != NULL);
    ENSURE_EQ_INT(ww_write_exr(exr, &f32, NULL, &err), WW_E_IO);
    ENSURE_EQ_INT(count_entries(dir), 0);
    ww_image_free(&u8);
    ww_image_free(&f32);
}

/* the fast deflate of PNG frames against stb_image's inflater on the inputs that reach its edges:
 * nothing, one byte, runs past the longest match, a repeat at the window's far end, noise (only
 * literals), and a rendered-like ramp; plus the zlib wrapper's Adler-32 computed here by its
 * definition (stb_image does not check it) */
static uint32_t adler_by_definition(const unsigned char *p, size_t n) {
    uint32_t a = 1, b = 0;
    for (size_t i = 0; i < n; i++) {
        a = (a + p[i]) % 65521u;
        b = (b + a) % 65521u;
    }
    return (b << 16) | a;
}

static int zlib_round_trip(const unsigned char *data, size_t len) {
    size_t n = 0;
    unsigned char *z = ww_zlib_fast(data, len, &n);
    if (!z || n < 6) return free(z), 0;
    int out_len = -1;
    char *back = stbi_zlib_decode_malloc((const char *)z, (int)n, &out_len);
    uint32_t adler = (uint32_t)z[n - 4] << 24 | (uint32_t)z[n - 3] << 16 | (uint32_t)z[n - 2] << 8 | z[n - 1];
    int ok = out_len == (int)len && (len == 0 || (back && memcmp(back, data, len) == 0)) &&
             adler == adler_by_definition(data, len) && (z[0] * 256 + z[1]) % 31 == 0;
    free(back);
    free(z);
    return ok;
}

TEST(io_zlib_fast_round_trips) {
    enum { N = 200000 };
    unsigned char *d = calloc(N, 1);
    ENSURE(d != NULL);
    if (!d) return;
    ENSURE(zlib_round_trip(d, 0));
    d[0] = 'x';
    ENSURE(zlib_round_trip(d, 1));
    memset(d, 7, N); /* runs far past 258 */
    ENSURE(zlib_round_trip(d, N));
    uint32_t s = 12345;
    for (int i = 0; i < N; i++) d[i] = (unsigned char)((s = s * 1103515245u + 12345u) >> 24);
    ENSURE(zlib_round_trip(d, N));               /* noise: literals only */
    memcpy(d + 40000, d + 40000 - 32768, 1000); /* a repeat at distance 32768 exactly */
    ENSURE(zlib_round_trip(d, 50000));
    for (int i = 0; i < N; i++) d[i] = (unsigned char)(i % 3 == 0 ? 1 : (i / 3) % 251 & 3);
    ENSURE(zlib_round_trip(d, N));               /* a filtered ramp: short matches everywhere */
    free(d);
}
