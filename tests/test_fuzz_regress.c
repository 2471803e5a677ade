/* test_fuzz_regress.c - what the fuzz targets (tests/fuzz/, `make fuzz`) found, kept as tests:
 * each crashing input, committed small under tests/data/fuzz/ or built here, must now give an
 * input error through every reader that met it. Also the image guard (core/stb_guard.h) itself:
 * the hostile shapes it refuses, the real files it lets through, and that nothing else in src/
 * calls stb_image's decoders directly.
 */
#include <dirent.h>
#include <stdlib.h>
#include <string.h>

#include <stb/stb_image.h>

#include "core/stb_guard.h"
#include "io/inflate.h"
#include "io/png_read.h"
#include "io/writers.h"
#include "scene/assets.h"
#include "test.h"
#include "check/compare.h"

/* ---- building inputs ------------------------------------------------------------------------ */

typedef struct bytes {
    unsigned char d[1024];
    size_t n;
} bytes;

static void put(bytes *b, const void *p, size_t n) {
    memcpy(b->d + b->n, p, n);
    b->n += n;
}
static void put_be32(bytes *b, uint32_t v) {
    unsigned char p[4] = {(unsigned char)(v >> 24), (unsigned char)(v >> 16), (unsigned char)(v >> 8),
                          (unsigned char)v};
    put(b, p, 4);
}


static void chunk(bytes *b, const char *type, const void *data, uint32_t n) {
    put_be32(b, n);
    size_t at = b->n;
    put(b, type, 4);
    if (n) put(b, data, n);
    put_be32(b, ww_test_crc32(b->d + at, n + 4));
}

/* a 1x1 RGB PNG (one red pixel, stored deflate block) with the chunks of `before` ahead of its
 * IDAT and `after` behind it: "e" an empty IDAT, "x" an unknown critical chunk XYZW, "p" a
 * suggested palette (PLTE) of 49 bytes, not a whole number of entries */
static void png_1x1(bytes *b, const char *before, const char *after) {
    static const unsigned char ihdr[13] = {0, 0, 0, 1, 0, 0, 0, 1, 8, 2, 0, 0, 0};
    static const unsigned char raw[4] = {0, 255, 0, 0}; /* filter none, R G B */
    unsigned char z[2 + 5 + 4 + 4] = {0x78, 0x01, 0x01, 4, 0, 0xfb, 0xff};
    memcpy(z + 7, raw, 4);
    uint32_t a = ww_adler32(1, raw, 4);
    for (int i = 0; i < 4; i++) z[11 + i] = (unsigned char)(a >> (24 - 8 * i));
    b->n = 0;
    put(b, "\x89PNG\r\n\x1a\n", 8);
    chunk(b, "IHDR", ihdr, 13);
    static const unsigned char pal[49];
    for (const char *c = before; *c; c++)
        if (*c == 'p') chunk(b, "PLTE", pal, sizeof pal);
        else chunk(b, *c == 'e' ? "IDAT" : "XYZW", "abc", *c == 'e' ? 0 : 3);
    chunk(b, "IDAT", z, sizeof z);
    for (const char *c = after; *c; c++) chunk(b, *c == 'e' ? "IDAT" : "XYZW", "abc", *c == 'e' ? 0 : 3);
    chunk(b, "IEND", NULL, 0);
}

/* the smallest JPEG head that reaches stb's Huffman table builder: SOI, then one DHT whose 16
 * code counts are `count` each (16 * count codes) */
static void jpeg_dht(bytes *b, unsigned count) {
    b->n = 0;
    put(b, "\xff\xd8\xff\xc4\x00\x13\x00", 7); /* SOI; DHT, length 19, class 0 table 0 */
    for (int i = 0; i < 16; i++) b->d[b->n++] = (unsigned char)count;
}

/* a 1x1 grey baseline JPEG up to its scan's data (FF 00, RST0, more data; no EOI), after the
 * tables `tables` names in order: q a quantisation table, d the DC and AC Huffman tables (one
 * code each), a the AC table alone */
static void jpeg_head(bytes *b, const char *tables) {
    put(b, "\xff\xd8", 2);
    for (const char *t = tables; *t; t++) {
        if (*t == 'q') {
            put(b, "\xff\xdb\x00\x43\x00", 5);
            for (int i = 0; i < 64; i++) b->d[b->n++] = 1;
        } else {
            int both = *t == 'd';
            static const unsigned char one_code[17] = {1};
            put(b, "\xff\xc4\x00", 3);
            b->d[b->n++] = (unsigned char)(2 + 18 * (both ? 2 : 1));
            for (int c = both ? 0 : 1; c < 2; c++) {
                b->d[b->n++] = (unsigned char)(c << 4);
                put(b, one_code, 16);
                b->d[b->n++] = 0;
            }
        }
    }
    static const unsigned char rest[] = {
        0xff, 0xc0, 0x00, 0x0b, 8, 0, 1, 0, 1, 1, 1, 0x11, 0,              /* SOF0 1x1 grey */
        0xff, 0xda, 0x00, 0x08, 1, 1, 0x00, 0, 63, 0,                      /* SOS */
        0x12, 0xff, 0x00, 0x34, 0xff, 0xd0, 0x56};                         /* data, FF 00, RST0 */
    put(b, rest, sizeof rest);
}

static const char *vet(const bytes *b) { return ww_image_vet(b->d, b->n); }

static int says(const char *why, const char *needle) { return why && strstr(why, needle); }

static const char *write_tmp(const char *dir, const char *name, const bytes *b) {
    static char path[512];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "wb");
    ENSURE(f && fwrite(b->d, 1, b->n, f) == b->n);
    if (f) fclose(f);
    return path;
}

/* ---- the inputs the fuzzers found ----------------------------------------------------------- */

/* fuzz_image, stb_image 2.27 without the guard: a DHT segment whose 16 counts add up to 604
 * codes made stbi__build_huffman write past its 257-entry size table ("index 257 out of bounds
 * for type 'stbi_uc[257]'", from stbi__process_marker <- stbi__decode_jpeg_header), and its value
 * loop past the 256-entry value table: an out-of-bounds write from any texture a scene names */
TEST(fuzz_regress_jpeg_dht_with_604_codes) {
    const char *path = "tests/data/fuzz/jpeg_dht_604_codes.jpg";
    size_t len = 0;
    unsigned char *f = (unsigned char *)ww_test_read_file(path, &len);
    ENSURE(f != NULL);
    if (!f) return;
    ENSURE(says(ww_image_vet(f, len), "more than 256 codes"));
    int w, h, comp;
    ENSURE(ww_stbi_info_from_memory(f, (int)len, &w, &h, &comp) == 0);
    ENSURE(says(stbi_failure_reason(), "more than 256 codes"));
    ENSURE(ww_stbi_load_from_memory(f, (int)len, &w, &h, &comp, 4) == NULL);
    free(f);

    /* the texture path: loading reads the size from the frame header, which comes before the
     * table; decoding (by the commands that draw) is an input error at the place that named it */
    ww_assets a = {0};
    ww_error err = {0};
    int idx = -1;
    ENSURE_EQ_INT(ww_assets_image(&a, path, "scene.yaml", 7, 5, &idx, &err), WW_OK);
    unsigned char *rgba = NULL;
    if (idx >= 0) ENSURE_EQ_INT(ww_assets_decode(&a.image[idx], &rgba, &err), WW_E_SYNTAX);
    ENSURE(rgba == NULL);
    ENSURE_EQ_INT(err.line, 7);
    ENSURE_MSG(strstr(err.msg, "more than 256 codes"), "%s", err.msg);
    ww_assets_free(&a);
    ww_image im;
    ENSURE_EQ_INT(ww_read_png(path, &im, &err), WW_E_SYNTAX);
    ww_image_free(&im);
}

/* the same overrun in its smallest form: 17 codes of each length */
TEST(fuzz_regress_jpeg_dht_smallest) {
    bytes b;
    jpeg_dht(&b, 17);
    ENSURE(says(vet(&b), "more than 256 codes"));
    int w, h, comp;
    ENSURE(ww_stbi_load_from_memory(b.d, (int)b.n, &w, &h, &comp, 0) == NULL);
    jpeg_dht(&b, 16); /* 256 codes: the table is full, not overrun (the file then ends) */
    ENSURE(!says(vet(&b), "more than 256 codes"));
    ENSURE(vet(&b) != NULL);
}

/* fuzz_image: a progressive JPEG whose AC scans name a Huffman table no DHT defined. stb 2.27
 * decodes with the table's uninitialised memory; a fast-AC entry read from it took more bits
 * than the reader held, and the next refill shifted by 33 ("shift exponent 33 is too large",
 * stb_image.h:2065): seen only when that memory was not zero (MALLOC_PERTURB_ or a long run) */
TEST(fuzz_regress_jpeg_undefined_huffman_table) {
    const char *path = "tests/data/fuzz/jpeg_undefined_ac_table.jpg";
    size_t len = 0;
    unsigned char *f = (unsigned char *)ww_test_read_file(path, &len);
    ENSURE(f != NULL);
    if (!f) return;
    ENSURE_MSG(says(ww_image_vet(f, len), "Huffman table used before it is defined"), "%s",
               ww_image_vet(f, len));
    int w, h, comp;
    ENSURE(ww_stbi_load_from_memory(f, (int)len, &w, &h, &comp, 4) == NULL);
    free(f);

    /* the same check on a good baseline file: its first scan's tables removed from view by
     * renaming the DHT marker to a comment (COM) makes the scan's tables undefined */
    f = (unsigned char *)ww_test_read_file("tests/fuzz/corpus/image/baseline.jpg", &len);
    ENSURE(f != NULL);
    if (!f) return;
    ENSURE(ww_image_vet(f, len) == NULL);
    int renamed = 0;
    for (size_t i = 0; i + 1 < len && !renamed; i++)
        if (f[i] == 0xff && f[i + 1] == 0xc4) f[i + 1] = 0xfe, renamed = 1;
    ENSURE(renamed);
    ENSURE(says(ww_image_vet(f, len), "Huffman table used before it is defined"));
    free(f);
}

/* fuzzing the image path, stb_image 2.27 without the guard: a PNG whose first IDAT is empty
 * makes stb add an offset to its still-null data pointer in stbi__parse_png_file (UBSan:
 * "applying zero offset to null pointer", stb_image.h:5130); refused before stb sees it. Our own
 * reader (the compare loader's) takes the file: the empty chunk adds no data */
TEST(fuzz_regress_png_empty_first_idat) {
    bytes b;
    png_1x1(&b, "e", "");
    ENSURE(says(vet(&b), "empty IDAT"));
    const char *dir = ww_test_tmpdir("empty_idat");
    const char *path = write_tmp(dir, "empty_idat.png", &b);
    ww_assets a = {0};
    ww_error err = {0};
    int idx = -1;
    ENSURE_EQ_INT(ww_assets_image(&a, path, "scene.yaml", 3, 9, &idx, &err), WW_OK);
    unsigned char *rgba = NULL;
    if (idx >= 0) ENSURE_EQ_INT(ww_assets_decode(&a.image[idx], &rgba, &err), WW_E_SYNTAX);
    ENSURE(rgba == NULL && err.line == 3);
    ENSURE_MSG(strstr(err.msg, "empty IDAT"), "%s", err.msg);
    ww_assets_free(&a);
    ww_image im;
    ENSURE_EQ_INT(ww_read_png(path, &im, &err), WW_E_SYNTAX);
    ww_image_free(&im);
    ww_cmp_image c;
    ENSURE_MSG(ww_cmp_load(path, &c, &err) == WW_OK, "%s", err.msg);
    ENSURE(c.width == 1 && c.height == 1);
    ww_cmp_image_free(&c);

    /* after the data, an empty IDAT is harmless to stb and passes */
    png_1x1(&b, "", "e");
    ENSURE(vet(&b) == NULL);
    int w, h, comp;
    unsigned char *px = ww_stbi_load_from_memory(b.d, (int)b.n, &w, &h, &comp, 3);
    ENSURE(px && w == 1 && h == 1 && px[0] == 255 && px[1] == 0 && px[2] == 0);
    stbi_image_free(px);
}

/* fuzz_png, whose harness holds our reader's pixels against stb_image's: a truecolour PNG
 * with a suggested palette of 49 bytes. stb refuses the file ("invalid PLTE"); our reader
 * passes over the chunk, as libpng does (a benign error for a palette the decoding never
 * reads). A difference of verdicts, not of pixels: the harness allows this one */
TEST(fuzz_regress_png_odd_suggested_palette) {
    bytes b;
    png_1x1(&b, "p", "");
    ww_png_pixels px;
    ww_error err = {0};
    ENSURE_MSG(ww_png_decode(b.d, b.n, &px, &err) == WW_OK, "%s", err.msg);
    ENSURE(px.px && px.width == 1 && px.channels == 3 && ((unsigned char *)px.px)[0] == 255);
    free(px.px);
    int w, h, comp;
    ENSURE(ww_stbi_load_from_memory(b.d, (int)b.n, &w, &h, &comp, 0) == NULL);
    ENSURE(strcmp(stbi_failure_reason(), "invalid PLTE") == 0);
}

/* ---- the guard ------------------------------------------------------------------------------ */

/* every image file the repository holds passes the vet and decodes through it as before */
TEST(stb_guard_passes_real_files) {
    const char *dirs[] = {"tests/data", "scenes/cubemap", "tests/fuzz/corpus/image",
                          "tests/fuzz/corpus/png"};
    int files = 0;
    for (int d = 0; d < 4; d++) {
        DIR *dir = opendir(dirs[d]);
        ENSURE_MSG(dir != NULL, "%s", dirs[d]);
        if (!dir) continue;
        struct dirent *e;
        while ((e = readdir(dir))) {
            const char *dot = strrchr(e->d_name, '.');
            if (!dot || (strcmp(dot, ".png") && strcmp(dot, ".jpg") && strcmp(dot, ".tga"))) continue;
            /* broken on purpose: a damaged file, and a header alone (the size cap's test) */
            if (strcmp(e->d_name, "corrupt.png") == 0 || strcmp(e->d_name, "too_wide.png") == 0)
                continue;
            char path[512];
            snprintf(path, sizeof path, "%s/%s", dirs[d], e->d_name);
            size_t len = 0;
            unsigned char *f = (unsigned char *)ww_test_read_file(path, &len);
            const char *why = f ? ww_image_vet(f, len) : "unreadable";
            ENSURE_MSG(why == NULL, "%s: %s", path, why);
            int w, h, comp;
            unsigned char *px = f ? ww_stbi_load_from_memory(f, (int)len, &w, &h, &comp, 4) : NULL;
            ENSURE_MSG(px != NULL, "%s: %s", path, stbi_failure_reason());
            stbi_image_free(px);
            free(f);
            files++;
        }
        closedir(dir);
    }
    ENSURE(files >= 20);
}

/* the shapes of JPEG the walk refuses, each where stb would go on reading */
TEST(stb_guard_jpeg_shapes) {
    bytes b;
    /* a hostile DHT behind stray bytes and fill bytes before the frame header: stb scans over
     * them to the next marker, and so does the vet */
    b.n = 0;
    put(&b, "\xff\xd8\xff\xfe\x00\x04" "ab", 8); /* SOI, COM of 2 bytes */
    put(&b, "junk\xff\xff\xff\xc4\x00\x13\x10", 11);
    for (int i = 0; i < 16; i++) b.d[b.n++] = 255;
    ENSURE(says(vet(&b), "more than 256 codes"));

    /* the same table between two scans, after the frame header */
    b.n = 0;
    jpeg_head(&b, "qd");
    put(&b, "\xff\xc4\x00\x13\x00", 5);
    for (int i = 0; i < 16; i++) b.d[b.n++] = 20;
    ENSURE(says(vet(&b), "more than 256 codes"));

    /* a scan that runs to the end of the file; a segment that does; no SOF at all */
    b.n = 0;
    jpeg_head(&b, "qd");
    ENSURE(says(vet(&b), "end marker"));
    b.n = 0;
    jpeg_head(&b, "qd");
    put(&b, "\xff\xd9", 2);
    ENSURE(vet(&b) == NULL); /* well formed enough for stb: SOI, tables, SOF, one scan, EOI */
    put(&b, "anything after EOI", 18);
    ENSURE(vet(&b) == NULL);
    /* the scan's tables must be defined before it: no DHT, no DQT, neither, the AC
     * table alone (a baseline scan needs its DC table too) */
    const char *tables[] = {"d", "q", "", "qa"};
    const char *missing[] = {"quantisation table", "Huffman table", "quantisation table",
                             "Huffman table"};
    for (int i = 0; i < 4; i++) {
        b.n = 0;
        jpeg_head(&b, tables[i]);
        put(&b, "\xff\xd9", 2);
        ENSURE_MSG(says(vet(&b), missing[i]), "%s: %s", tables[i], vet(&b));
    }
    b.n = 0;
    put(&b, "\xff\xd8\xff\xe1\x40\x00" "Exif", 10);
    ENSURE(says(vet(&b), "past the end"));
    b.n = 0;
    put(&b, "\xff\xd8\xff\xd9", 4);
    ENSURE(says(vet(&b), "unknown marker"));

    /* frame headers stb would trust: 0 wide, 5 components, sampling 0 */
    static const unsigned char sofs[][15] = {
        {0xff, 0xd8, 0xff, 0xc0, 0x00, 0x0b, 8, 0, 1, 0, 0, 1, 1, 0x11, 0},
        {0xff, 0xd8, 0xff, 0xc0, 0x00, 0x0b, 8, 0, 1, 0, 1, 5, 1, 0x11, 0},
        {0xff, 0xd8, 0xff, 0xc0, 0x00, 0x0b, 8, 0, 1, 0, 1, 1, 1, 0x01, 0}};
    const char *why[] = {"bad size", "component count", "sampling"};
    for (int i = 0; i < 3; i++) {
        b.n = 0;
        put(&b, sofs[i], sizeof sofs[i]);
        ENSURE_MSG(says(vet(&b), why[i]), "%d: %s", i, vet(&b));
    }
}

TEST(stb_guard_png_shapes) {
    bytes b;
    png_1x1(&b, "", "");
    ENSURE(vet(&b) == NULL);
    png_1x1(&b, "x", ""); /* stb names an unknown critical chunk in a shared static string */
    ENSURE(says(vet(&b), "unknown critical chunk"));
    png_1x1(&b, "", "");
    b.n -= 12; /* no IEND */
    ENSURE(says(vet(&b), "IEND"));
    png_1x1(&b, "", "");
    b.d[8 + 3] = 0x20; /* IHDR says 32 bytes */
    ENSURE(says(vet(&b), "IHDR"));
    png_1x1(&b, "", "");
    b.d[33] = 0x7f; /* the IDAT runs far past the end */
    ENSURE(says(vet(&b), "past the end"));
    /* not PNG, not JPEG: left to stb (TGA has no signature), which says what it is not */
    b.n = 0;
    put(&b, "GIF89a", 6);
    ENSURE(vet(&b) == NULL);
    int w, h, comp;
    ENSURE(ww_stbi_load_from_memory(b.d, (int)b.n, &w, &h, &comp, 0) == NULL);
    ENSURE(ww_stbi_load_from_memory(b.d, -1, &w, &h, &comp, 0) == NULL);
}

/* the guard is the only door: no file of src/ but core/stb_image_impl.c calls a decoder of
 * stb_image's by its own name */
TEST(stb_guard_is_the_only_caller) {
    static const char *const decoders[] = {"stbi_load", "stbi_info", "stbi_is_16_bit", "stbi_is_hdr",
                                           "stbi_loadf"};
    const char *dirs[] = {"src/core", "src/scene", "src/sim",  "src/gfx",   "src/io",
                          "src/render", "src/check", "src/bench", "src/sweep", "src/cli"};
    int scanned = 0;
    for (int d = 0; d < 10; d++) {
        DIR *dir = opendir(dirs[d]);
        ENSURE_MSG(dir != NULL, "%s", dirs[d]);
        if (!dir) continue;
        struct dirent *e;
        while ((e = readdir(dir))) {
            size_t n = strlen(e->d_name);
            if (n < 3 || strcmp(e->d_name + n - 2, ".c") != 0) continue;
            if (strcmp(e->d_name, "stb_image_impl.c") == 0) continue;
            char path[512];
            snprintf(path, sizeof path, "%s/%s", dirs[d], e->d_name);
            char *s = ww_test_read_file(path, NULL);
            for (int k = 0; s && k < 5; k++)
                for (const char *p = s; (p = strstr(p, decoders[k])); p++)
                    ENSURE_MSG(p > s && p[-1] == '_' && p - 3 >= s && strncmp(p - 3, "ww_", 3) == 0,
                               "%s calls %s directly (use core/stb_guard.h)", path, decoders[k]);
            free(s);
            scanned++;
        }
        closedir(dir);
    }
    ENSURE(scanned > 50);
}

/* an image's size from its first bytes, without stb (what loading a scene reads): a PNG's IHDR
 * and a JPEG's frame header give the decoder's own width and height from a prefix; a bad or cut
 * header is refused; a TGA is left to stb's info call */
TEST(stb_guard_header_size_from_a_prefix) {
    const char *files[] = {"tests/data/checker.png", "tests/fuzz/corpus/image/baseline.jpg",
                           "tests/fuzz/corpus/image/grey.jpg", "tests/fuzz/corpus/image/interlaced.png"};
    for (int i = 0; i < 4; i++) {
        size_t len = 0;
        unsigned char *f = (unsigned char *)ww_test_read_file(files[i], &len);
        ENSURE_MSG(f != NULL, "%s", files[i]);
        if (!f) continue;
        int w = 0, h = 0, dw = 0, dh = 0, comp;
        unsigned char *px = ww_stbi_load_from_memory(f, (int)len, &dw, &dh, &comp, 4);
        ENSURE_MSG(px != NULL, "%s", files[i]);
        stbi_image_free(px);
        /* the header alone: a PNG's first 24 bytes; a JPEG up to its frame header */
        size_t cut = files[i][strlen(files[i]) - 1] == 'g' && strstr(files[i], ".png") ? 24 : len;
        if (cut == len) {
            for (size_t k = 2; k + 1 < len; k++)
                if (f[k] == 0xff && (f[k + 1] == 0xc0 || f[k + 1] == 0xc1 || f[k + 1] == 0xc2)) {
                    cut = k + 2 + (size_t)(f[k + 2] << 8 | f[k + 3]); /* marker and segment */
                    break;
                }
        }
        ENSURE_EQ_INT(ww_image_header_size(f, cut, &w, &h), 1);
        ENSURE_MSG(w == dw && h == dh, "%s: header %dx%d, decoded %dx%d", files[i], w, h, dw, dh);
        ENSURE_EQ_INT(ww_image_header_size(f, cut - 1, &w, &h), -1); /* one byte short */
        free(f);
    }
    bytes b;
    jpeg_dht(&b, 17); /* the overrunning table comes before any frame header */
    int w, h;
    ENSURE_EQ_INT(ww_image_header_size(b.d, b.n, &w, &h), -1);
    ENSURE_EQ_INT(ww_stbi_size_from_prefix(b.d, (int)b.n, &w, &h), 0);
    size_t len = 0;
    unsigned char *tga = (unsigned char *)ww_test_read_file("tests/data/checker.tga", &len);
    ENSURE(tga && ww_image_header_size(tga, len, &w, &h) == 0);
    ENSURE(tga && ww_stbi_size_from_prefix(tga, 18, &w, &h) == 1 && w > 0 && h > 0);
    free(tga);
}
