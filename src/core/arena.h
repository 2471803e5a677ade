/* arena.h - one block, bump allocation, mark/release (Box2D's stack arena, MuJoCo's per-step
 * stack). Used for the YAML parser's load-time tree (scene/yaml_tree.c); never grows. No system
 * needs per-step scratch yet, so mark/release is called only by the tests (test_core.c).
 *
 *   ww_arena a; ww_arena_init(&a, bytes);    // one malloc
 *   void *p = ww_arena_alloc(&a, n);         // NULL when full (caller reports WW_E_NOMEM)
 *   size_t m = ww_arena_mark(&a); ... ww_arena_release(&a, m);
 *   ww_arena_free(&a);
 */
#ifndef WW_ARENA_H
#define WW_ARENA_H

#include <stddef.h>

typedef struct ww_arena {
    unsigned char *base;
    size_t size, used, peak;
} ww_arena;

int ww_arena_init(ww_arena *a, size_t size); /* 0 on success */
void *ww_arena_alloc(ww_arena *a, size_t n); /* zeroed, 16-byte aligned */
size_t ww_arena_mark(const ww_arena *a);
void ww_arena_release(ww_arena *a, size_t mark);
void ww_arena_free(ww_arena *a);

#endif
