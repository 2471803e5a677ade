/* fields_stones.h - the state fields of the stones, an X-macro table appended to
 * WW_STATE_FIELDS (sim/state.h), counts 0 without stones. stone_pos, stone_state and skips are
 * read by others (renderer, HUD); the rest is sim/stones.c's own. */
#ifndef WW_FIELDS_STONES_H
#define WW_FIELDS_STONES_H

#define WW_N_STONES(sc) ((sc)->stones.on ? WW_MAX_STONES : 0)

#define WW_FIELDS_STONES(X)                                                                       \
    X(double, stone_pos, 3 * WW_N_STONES(sc), "stones", "stone positions, m (3 per slot)")          \
    X(int32_t, stone_state, WW_N_STONES(sc), "stones", "0 free slot, 1 flying, 2 sinking (1 per slot)") \
    X(int32_t, skips, WW_N_STONES(sc) ? 1 : 0, "stones", "skips so far, all stones (1)")            \
    X(double, stone_vel, 3 * WW_N_STONES(sc), "stones", "stone velocities, m/s (3 per slot)")       \
    X(double, stone_spin, WW_N_STONES(sc), "stones", "spin about the disc's axis, rad/s (1 per slot)") \
    X(int32_t, stone_bounces, WW_N_STONES(sc), "stones", "skips of this stone so far (1 per slot)") \
    X(double, stone_t0, WW_N_STONES(sc), "stones", "time the stone was thrown, s (1 per slot)")

#endif
