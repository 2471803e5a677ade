/* bigalloc.c - big pixel buffers on transparent huge pages (see bigalloc.h). */
#include "core/bigalloc.h"

#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>

size_t ww_big_capacity(size_t bytes) {
    if (bytes < WW_BIG_MIN) return bytes;
    return (bytes + WW_BIG_PAGE - 1) / WW_BIG_PAGE * WW_BIG_PAGE;
}

void *ww_big_alloc(size_t bytes) {
    if (bytes < WW_BIG_MIN) return malloc(bytes);
    size_t cap = ww_big_capacity(bytes);
    if (cap < bytes) return NULL; /* rounding overflowed */
    void *p = aligned_alloc(WW_BIG_PAGE, cap);
    if (p) madvise(p, cap, MADV_HUGEPAGE); /* advice only: failure changes nothing */
    return p;
}

void *ww_big_realloc(void *p, size_t old, size_t n) {
    if (!p) return ww_big_alloc(n);
    if (old < WW_BIG_MIN && n < WW_BIG_MIN) return realloc(p, n);
    if (old >= WW_BIG_MIN && n <= ww_big_capacity(old)) return p;
    void *q = ww_big_alloc(n);
    if (!q) return NULL;
    memcpy(q, p, old < n ? old : n);
    free(p);
    return q;
}
