/* fields_boat.h - the state fields of the boat, an X-macro table appended to WW_STATE_FIELDS
 * (sim/state.h), count 0 without a boat. boat_pos, boat_vel and boat_heading are read by the
 * stones, fish and camera collision. */
#ifndef WW_FIELDS_BOAT_H
#define WW_FIELDS_BOAT_H

#define WW_N_BOAT(sc) ((sc)->boat.on ? 1 : 0)

#define WW_FIELDS_BOAT(X)                                                                         \
    X(double, boat_pos, 3 * WW_N_BOAT(sc), "hull centre, m (3)")                                 \
    X(double, boat_vel, 3 * WW_N_BOAT(sc), "velocity, m/s (3)")                                  \
    X(double, boat_heading, WW_N_BOAT(sc), "heading, rad (1)")

#endif
