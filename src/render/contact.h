/* contact.h - a contact sheet: thumbnails in a grid, each labelled below with lines of text drawn
 * with stb_easy_font (its quads rasterised into the image here, no GL). Used by `sweep --thumbs`.
 *
 *   ww_contact_layout L;
 *   ww_contact_plan(n, cols, thumb_w, thumb_h, label_lines, &L);  // sizes only
 *   ww_image sheet; ww_contact_new(&L, &sheet);                    // RGB8, background; one malloc
 *   ww_contact_put(&sheet, &L, i, &thumb, "#3\namplitude=0.2");     // thumb may be NULL
 *   ww_write_png(path, &sheet, &err); ww_image_free(&sheet);       // the caller frees the sheet
 *
 * Thumbnails of another size are scaled first: ww_contact_fit(&frame, L.thumb_w, L.thumb_h, &thumb).
 *
 * Layout (what the tests compute too): cell i sits at column i % cols, row i / cols; a cell is the
 * thumbnail (thumb_w x thumb_h) above its label (label_h = lines * WW_CONTACT_LINE_H +
 * WW_CONTACT_PAD); cells are WW_CONTACT_GAP px apart and from the border, so
 *   width  = cols (thumb_w + GAP) + GAP,  height = rows (thumb_h + label_h + GAP) + GAP.
 * Label lines wider than the cell are cut and end in "..".
 */
#ifndef WW_CONTACT_H
#define WW_CONTACT_H

#include <stdint.h>

#include "io/image.h"

#define WW_CONTACT_GAP 4     /* px between cells and around the sheet */
#define WW_CONTACT_LINE_H 12 /* px per label line: stb_easy_font's line advance */
#define WW_CONTACT_PAD 4     /* px above the first label line */
#define WW_CONTACT_MAX_SIDE 16384 /* px; a larger sheet is refused */

typedef struct ww_contact_layout {
    int n, cols, rows;       /* cells */
    int thumb_w, thumb_h;    /* px */
    int label_h;             /* px below each thumbnail */
    int width, height;       /* the whole sheet, px */
} ww_contact_layout;

/* the layout of n cells in cols columns (cols is clamped to 1..n); 0, or -1 when the sheet
 * would exceed WW_CONTACT_MAX_SIDE on a side (L is still filled) */
int ww_contact_plan(int n, int cols, int thumb_w, int thumb_h, int label_lines,
                    ww_contact_layout *L);
/* allocate the sheet (RGB8) and paint the background; 0 ok, -1 out of memory */
int ww_contact_new(const ww_contact_layout *L, ww_image *sheet);
/* copy thumb (U8, 3 or 4 channels, at the layout's thumbnail size) into cell i, or mark the cell
 * as having no image when thumb is NULL; then draw the label's lines ('\n'-separated) below */
void ww_contact_put(ww_image *sheet, const ww_contact_layout *L, int i, const ww_image *thumb,
                    const char *label);
/* scale src (U8, 3 or 4 channels) to w x h into out (RGB8, allocated here; the caller frees it):
 * each output pixel is the mean of the source pixels under it (the nearest one when enlarging);
 * 0 ok, -1 out of memory */
int ww_contact_fit(const ww_image *src, int w, int h, ww_image *out);
/* draw one line of text with its top-left corner at (x, y), clipped to the image and to max_w px
 * (cut with ".." when wider); returns the width drawn, px */
int ww_contact_text(ww_image *im, int x, int y, int max_w, const char *text, const uint8_t rgb[3]);

#endif
