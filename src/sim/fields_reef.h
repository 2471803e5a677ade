/* fields_reef.h - the state fields of the chest, bubbles and camera collision, an X-macro table
 * appended to WW_STATE_FIELDS (sim/state.h), counts 0 without them. */
#ifndef WW_FIELDS_REEF_H
#define WW_FIELDS_REEF_H

#define WW_N_CHEST(sc) ((sc)->chest.on ? 1 : 0)

#define WW_FIELDS_REEF(X)                                                                         \
    X(double, chest_pos, 3 * WW_N_CHEST(sc), "chest position on the seabed, m (3)")              \
    X(double, chest_state, WW_N_CHEST(sc), "0 none, 1 present (1)")                              \
    X(double, prizes, WW_N_CHEST(sc), "chests collected so far (1)")

#endif
