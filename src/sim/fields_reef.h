/* fields_reef.h - the state fields of the chest, bubbles and camera collision, an X-macro table
 * appended to WW_STATE_FIELDS (sim/state.h), counts 0 without them. The collision's fields exist
 * only when the scene has something solid (boat, cubes, chest or models), so scenes without
 * objects keep their state and hash. */
#ifndef WW_FIELDS_REEF_H
#define WW_FIELDS_REEF_H

#define WW_N_CHEST(sc) ((sc)->chest.on ? 1 : 0)
#define WW_N_EMITTERS(sc) ((sc)->bubbles.on ? (sc)->bubbles.count : 0)
#define WW_N_BUBBLES(sc) ((sc)->bubbles.on ? (sc)->bubbles.total : 0)
#define WW_N_SOLIDS(sc) (ww_scene_has_solids(sc) ? 1 : 0)

#define WW_FIELDS_REEF(X)                                                                         \
    X(double, chest_pos, 3 * WW_N_CHEST(sc), "chest", "chest position: centre of its base on the seabed, m (3)") \
    X(int32_t, chest_state, WW_N_CHEST(sc), "chest", "0 none, 1 present (1)")                       \
    X(int32_t, prizes, WW_N_CHEST(sc), "chest", "chests collected so far (1)")                      \
    X(double, chest_t0, WW_N_CHEST(sc), "chest", "simulated time the present chest spawned, s (1)") \
    X(double, chest_next, WW_N_CHEST(sc), "chest", "simulated time of the next scheduled spawn, s (1)") \
    X(double, bubble_pos, 3 * WW_N_BUBBLES(sc), "bubbles", "bubble centres, m (3 per bubble)")      \
    X(int32_t, bubble_on, WW_N_BUBBLES(sc), "bubbles", "0 free slot, 1 rising (1 per bubble)")      \
    X(double, bubble_t0, WW_N_BUBBLES(sc), "bubbles", "release time, s (1 per bubble)")             \
    X(double, bubble_wobble, 2 * WW_N_BUBBLES(sc), "bubbles", "zigzag phase, rad, and plane heading, rad (2 per bubble)") \
    X(double, bubble_speed, WW_N_BUBBLES(sc), "bubbles", "rise speed, m/s (1 per bubble)")          \
    X(double, bubble_radius, WW_N_BUBBLES(sc), "bubbles", "radius, m (1 per bubble)")               \
    X(double, bubble_next, WW_N_EMITTERS(sc), "bubbles", "next release time, s (1 per emitter)")    \
    X(double, collide_prev, 3 * WW_N_SOLIDS(sc), "collide", "camera position after collision, previous step, m (3)") \
    X(int32_t, collide_state, 2 * WW_N_SOLIDS(sc), "collide", "[0] what holds the camera back + 1 (0 free; what as in collide.h), [1] 1 when collide_prev may start a sweep (2)")

#endif
