/* desc_stones.h - objects.stones: thrown stones that skip (Clanet, Hersen & Bocquet 2004) or
 * sink. Read by compile_stones.c; simulated by sim/stones.c. */
#ifndef WW_DESC_STONES_H
#define WW_DESC_STONES_H

#define WW_MAX_STONES 32

typedef struct ww_stones_desc {
    int on;      /* stones can be thrown (a stones section or a throw event) */
} ww_stones_desc;

#endif
