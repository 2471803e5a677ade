/* test_io.c - frame files: atomic writes (nothing partial, no temporary left behind), mkdir -p,
 * whole-file reads, and PNG round trips, reproducible bytes and bad inputs.
 */
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <stb/stb_image_write.h>

#include "core/error.h"
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

static void write_text(const char *path, const char *text) {
    FILE *f = fopen(path, "wb");
    ENSURE(f != NULL);
    if (!f) return;
    fputs(text, f);
    fclose(f);
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
    write_text(path, "the old content, longer than the new one\n");
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
        fprintf(stderr, "(skipped as root) ");
        return;
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

    write_text(file, "x");
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
    write_text(path, "hello");
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
    write_text(text, "this is not a picture\n");
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
