/* fields_fishing.h - the state fields of the rod, lure and fish, an X-macro table appended to
 * WW_STATE_FIELDS (sim/state.h), counts 0 without them. lure_pos is read by the fish, fish_pos
 * by the camera collision. */
#ifndef WW_FIELDS_FISHING_H
#define WW_FIELDS_FISHING_H

#define WW_N_ROD(sc) ((sc)->rod.on ? 1 : 0)
#define WW_N_FISH(sc) ((sc)->fish.on ? (sc)->fish.count : 0)

#define WW_FIELDS_FISHING(X)                                                                      \
    X(double, lure_pos, 3 * WW_N_ROD(sc), "lure position, m (3)")                                \
    X(double, lure_state, WW_N_ROD(sc), "0 idle, 1 flying, 2 floating (active), 3 hooked (1)")   \
    X(double, fish_pos, 3 * WW_N_FISH(sc), "fish positions, m (3 per fish)")                     \
    X(double, fish_caught, WW_N_FISH(sc) ? 1 : 0, "fish caught so far (1)")

#endif
