/* bigalloc.h - big pixel buffers on transparent huge pages.
 *
 *   float *px = ww_big_alloc(bytes);   // freed with free(); NULL: out of memory
 *
 * A block of WW_BIG_MIN bytes or more is 2 MiB-aligned, rounded up to whole 2 MiB and advised
 * MADV_HUGEPAGE; a smaller one is plain malloc. A fresh process pays for every page it touches
 * first: on this 2-core VM about 13 us per 4 KiB page, so a 1280x720 float RGBA image (14.7 MB,
 * 3600 pages) costs 45-54 ms to touch in 4 KiB pages and 2-17 ms in huge pages, and one decoded
 * 1280x720 PNG (about 1600 pages of stb_image's buffers) 21 ms.
 */
#ifndef WW_BIGALLOC_H
#define WW_BIGALLOC_H

#include <stddef.h>

#define WW_BIG_MIN ((size_t)1 << 20)  /* from this size on, huge-page blocks */
#define WW_BIG_PAGE ((size_t)2 << 20) /* x86-64 transparent huge page */

void *ww_big_alloc(size_t bytes);
/* what a block of `bytes` from ww_big_alloc can hold (bytes itself below WW_BIG_MIN) */
size_t ww_big_capacity(size_t bytes);
/* grow or shrink a block from ww_big_alloc whose requested size was old (realloc's contract:
 * NULL leaves p valid); a big block that already holds n bytes is returned as it is */
void *ww_big_realloc(void *p, size_t old, size_t n);

#endif
