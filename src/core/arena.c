/* arena.c - the bump allocator of arena.h. */
#include "core/arena.h"

#include <stdlib.h>
#include <string.h>

int ww_arena_init(ww_arena *a, size_t size) {
    a->base = malloc(size ? size : 1);
    a->size = a->base ? size : 0;
    a->used = a->peak = 0;
    return a->base ? 0 : -1;
}

void *ww_arena_alloc(ww_arena *a, size_t n) {
    size_t at = (a->used + 15u) & ~(size_t)15u;
    if (at > a->size || n > a->size - at) return NULL;
    a->used = at + n;
    if (a->used > a->peak) a->peak = a->used;
    memset(a->base + at, 0, n);
    return a->base + at;
}

size_t ww_arena_mark(const ww_arena *a) { return a->used; }

void ww_arena_release(ww_arena *a, size_t mark) {
    if (mark <= a->used) a->used = mark;
}

void ww_arena_free(ww_arena *a) {
    free(a->base);
    a->base = NULL;
    a->size = a->used = 0;
}
