/* contact.c - contact sheets (contact.h): thumbnails blitted into a grid and labelled with
 * stb_easy_font, whose output is a list of axis-aligned quads that we fill into the image
 * ourselves, pixel for pixel, so the sheet needs no GL and is the same bytes on every machine.
 */
#include "render/contact.h"

#include <stdlib.h>
#include <string.h>

#include "core/error.h"

#include <stb/stb_easy_font.h>

#define LINE_MAX_CHARS 255
#define VERTS_PER_CHAR_MAX 64  /* the busiest glyph has well under 16 segments of 4 vertices */

static const uint8_t BACKGROUND[3] = {24, 24, 28};
static const uint8_t NO_IMAGE[3] = {70, 40, 40};
static const uint8_t LABEL[3] = {235, 235, 235};

int ww_contact_plan(int n, int cols, int thumb_w, int thumb_h, int label_lines,
                    ww_contact_layout *L) {
    WW_ASSERT(n >= 0 && thumb_w > 0 && thumb_h > 0 && label_lines >= 0);
    if (cols > n) cols = n;
    if (cols < 1) cols = 1;
    memset(L, 0, sizeof *L);
    L->n = n;
    L->cols = cols;
    L->rows = n > 0 ? (n + cols - 1) / cols : 0;
    L->thumb_w = thumb_w;
    L->thumb_h = thumb_h;
    L->label_h = label_lines * WW_CONTACT_LINE_H + WW_CONTACT_PAD;
    /* in 64 bits: a large grid must be refused, not wrapped */
    long long w = (long long)cols * (thumb_w + WW_CONTACT_GAP) + WW_CONTACT_GAP;
    long long h = (long long)L->rows * (thumb_h + L->label_h + WW_CONTACT_GAP) + WW_CONTACT_GAP;
    L->width = w > WW_CONTACT_MAX_SIDE ? WW_CONTACT_MAX_SIDE + 1 : (int)w;
    L->height = h > WW_CONTACT_MAX_SIDE ? WW_CONTACT_MAX_SIDE + 1 : (int)h;
    return w > WW_CONTACT_MAX_SIDE || h > WW_CONTACT_MAX_SIDE ? -1 : 0;
}

static void fill_rect(ww_image *im, int x0, int y0, int x1, int y1, const uint8_t rgb[3]) {
    if (x0 < 0) x0 = 0;
    if (y0 < 0) y0 = 0;
    if (x1 > im->width) x1 = im->width;
    if (y1 > im->height) y1 = im->height;
    for (int y = y0; y < y1; y++) {
        uint8_t *p = im->u8 + ((size_t)y * (size_t)im->width + (size_t)x0) * (size_t)im->channels;
        for (int x = x0; x < x1; x++, p += im->channels) {
            p[0] = rgb[0];
            p[1] = rgb[1];
            p[2] = rgb[2];
        }
    }
}

int ww_contact_new(const ww_contact_layout *L, ww_image *sheet) {
    if (ww_image_alloc(sheet, L->width, L->height, 3, WW_PIX_U8) != 0) return -1;
    fill_rect(sheet, 0, 0, L->width, L->height, BACKGROUND);
    return 0;
}

/* stb_easy_font reads its glyph table at c - 32: anything outside printable ASCII becomes '?' */
static char printable(char c) { return c >= 32 && c < 127 ? c : '?'; }

/* width of one glyph, px (the font's advance plus its spacing, which we pin at 0) */
static int glyph_width(char c) {
    char one[2] = {printable(c), 0};
    return stb_easy_font_width(one);
}

/* fill the quads stb_easy_font emits for one glyph at (x, y) */
static void draw_glyph(ww_image *im, int x, int y, int clip_x1, char c, const uint8_t rgb[3]) {
    float verts[VERTS_PER_CHAR_MAX * 4];  /* x, y, z, colour (4 bytes) per vertex: 16 bytes */
    char one[2] = {printable(c), 0};
    int nq = stb_easy_font_print((float)x, (float)y, one, NULL, verts, (int)sizeof verts);
    for (int q = 0; q < nq; q++) {
        /* a quad's corners in order (x0, y0), (x1, y0), (x1, y1), (x0, y1), whole pixels;
         * vertex j starts at float 4 j of the quad's 16 */
        const float *v = verts + 16 * q;
        int x0 = (int)v[0], y0 = (int)v[1], x1 = (int)v[8], y1 = (int)v[9];
        if (x1 > clip_x1) x1 = clip_x1;
        fill_rect(im, x0, y0, x1, y1, rgb);
    }
}

int ww_contact_text(ww_image *im, int x, int y, int max_w, const char *text, const uint8_t rgb[3]) {
    stb_easy_font_spacing(0.0f); /* the library's one setting, pinned before every use */
    size_t n = strlen(text);
    if (n > LINE_MAX_CHARS) n = LINE_MAX_CHARS;
    int total = 0;
    for (size_t i = 0; i < n; i++) total += glyph_width(text[i]);

    /* too wide: keep the longest prefix that leaves room for ".." */
    size_t keep = n;
    int cut = total > max_w, dots = 2 * glyph_width('.');
    if (cut) {
        int w = 0;
        keep = 0;
        while (keep < n && w + glyph_width(text[keep]) + dots <= max_w) w += glyph_width(text[keep++]);
    }
    int cx = x, clip = x + max_w;
    for (size_t i = 0; i < keep; i++) {
        draw_glyph(im, cx, y, clip, text[i], rgb);
        cx += glyph_width(text[i]);
    }
    for (int d = 0; cut && d < 2; d++) {
        draw_glyph(im, cx, y, clip, '.', rgb);
        cx += glyph_width('.');
    }
    return cx - x;
}

int ww_contact_fit(const ww_image *src, int w, int h, ww_image *out) {
    WW_ASSERT(src->type == WW_PIX_U8 && src->channels >= 3 && w > 0 && h > 0);
    if (ww_image_alloc(out, w, h, 3, WW_PIX_U8) != 0) return -1;
    size_t sw = (size_t)src->width, sh = (size_t)src->height, ch = (size_t)src->channels;
    for (size_t y = 0; y < (size_t)h; y++) {
        /* source rows [y0, y1): at least one */
        size_t y0 = y * sh / (size_t)h, y1 = (y + 1) * sh / (size_t)h;
        if (y1 <= y0) y1 = y0 + 1;
        for (size_t x = 0; x < (size_t)w; x++) {
            size_t x0 = x * sw / (size_t)w, x1 = (x + 1) * sw / (size_t)w;
            if (x1 <= x0) x1 = x0 + 1;
            unsigned long sum[3] = {0, 0, 0};
            for (size_t sy = y0; sy < y1; sy++) {
                const uint8_t *p = src->u8 + (sy * sw + x0) * ch;
                for (size_t sx = x0; sx < x1; sx++, p += ch) {
                    sum[0] += p[0];
                    sum[1] += p[1];
                    sum[2] += p[2];
                }
            }
            unsigned long n = (unsigned long)((y1 - y0) * (x1 - x0));
            uint8_t *d = out->u8 + (y * (size_t)w + x) * 3;
            for (int c = 0; c < 3; c++) d[c] = (uint8_t)((sum[c] + n / 2) / n);
        }
    }
    return 0;
}

void ww_contact_put(ww_image *sheet, const ww_contact_layout *L, int i, const ww_image *thumb,
                    const char *label) {
    WW_ASSERT(i >= 0 && i < L->n && sheet->type == WW_PIX_U8 && sheet->channels == 3);
    int x0 = WW_CONTACT_GAP + (i % L->cols) * (L->thumb_w + WW_CONTACT_GAP);
    int y0 = WW_CONTACT_GAP + (i / L->cols) * (L->thumb_h + L->label_h + WW_CONTACT_GAP);

    /* the thumbnail, or a marked empty cell */
    if (thumb) {
        WW_ASSERT(thumb->type == WW_PIX_U8 && thumb->width == L->thumb_w &&
                  thumb->height == L->thumb_h && thumb->channels >= 3);
        for (int y = 0; y < L->thumb_h; y++) {
            const uint8_t *src = thumb->u8 + (size_t)y * (size_t)thumb->width * (size_t)thumb->channels;
            uint8_t *dst = sheet->u8 + ((size_t)(y0 + y) * (size_t)sheet->width + (size_t)x0) * 3;
            for (int x = 0; x < L->thumb_w; x++, src += thumb->channels, dst += 3) memcpy(dst, src, 3);
        }
    } else {
        fill_rect(sheet, x0, y0, x0 + L->thumb_w, y0 + L->thumb_h, NO_IMAGE);
        ww_contact_text(sheet, x0 + 4, y0 + 4, L->thumb_w - 8, "no image", LABEL);
    }

    /* the label, one line per '\n' */
    int y = y0 + L->thumb_h + WW_CONTACT_PAD;
    char line[LINE_MAX_CHARS + 1];
    for (const char *p = label; p && *p && y + WW_CONTACT_LINE_H <= y0 + L->thumb_h + L->label_h;) {
        const char *e = strchr(p, '\n');
        size_t len = e ? (size_t)(e - p) : strlen(p);
        if (len > LINE_MAX_CHARS) len = LINE_MAX_CHARS;
        memcpy(line, p, len);
        line[len] = 0;
        ww_contact_text(sheet, x0, y, L->thumb_w, line, LABEL);
        y += WW_CONTACT_LINE_H;
        if (!e) break;
        p = e + 1;
    }
}
