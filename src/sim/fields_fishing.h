/* fields_fishing.h - the state fields of the rod, lure and fish, an X-macro table appended to
 * WW_STATE_FIELDS (sim/state.h), counts 0 without them. lure_pos is read by the fish, fish_pos
 * by the camera collision. The first four are read by other systems; the rest are the rod's
 * (sim/rod.h) and the fish's (sim/fish.h) own. */
#ifndef WW_FIELDS_FISHING_H
#define WW_FIELDS_FISHING_H

#define WW_N_ROD(sc) ((sc)->rod.on ? 1 : 0)
#define WW_N_FISH(sc) ((sc)->fish.on ? (sc)->fish.count : 0)

#define WW_FIELDS_FISHING(X)                                                                      \
    X(double, lure_pos, 3 * WW_N_ROD(sc), "rod", "lure position, m (3)")                            \
    X(int32_t, lure_state, WW_N_ROD(sc), "rod", "0 idle, 1 flying, 2 floating (active), 3 hooked (1)") \
    X(double, fish_pos, 3 * WW_N_FISH(sc), "fish", "fish positions, m (3 per fish)")                \
    X(int32_t, fish_caught, WW_N_FISH(sc) ? 1 : 0, "fish", "fish caught so far (1)")                \
    X(double, lure_vel, 3 * WW_N_ROD(sc), "rod", "lure velocity, m/s (3)")                          \
    X(double, rod_line_time, WW_N_ROD(sc), "rod", "seconds since the cast (1)")                     \
    X(double, rod_active_left, WW_N_ROD(sc), "rod", "seconds left in the floating lure's window (1)") \
    X(int32_t, rod_fish, WW_N_ROD(sc), "rod", "fish that bit this cast, -1 none (at most one) (1)") \
    X(int32_t, rod_casts, WW_N_ROD(sc), "rod", "casts so far (1)")                                  \
    X(int32_t, rod_held, WW_N_ROD(sc), "rod", "1: cast from the camera, which holds the rod (1)")   \
    X(double, rod_tip, 3 * WW_N_ROD(sc), "rod", "the rod's tip at the cast, where the line leaves, m (3)") \
    X(double, rod_dir, 3 * WW_N_ROD(sc), "rod", "the cast's level heading, unit (3)")              \
    X(double, fish_vel, 3 * WW_N_FISH(sc), "fish", "fish velocities, m/s (3 per fish)")             \
    X(double, fish_yaw, WW_N_FISH(sc), "fish", "heading, rad, 0 = +x, pi/2 = +z (1 per fish)")      \
    X(double, fish_yaw_rate, WW_N_FISH(sc), "fish", "yaw rate of the last step, rad/s (1 per fish)") \
    X(double, fish_bank, WW_N_FISH(sc), "fish", "bank (roll) angle, rad, the sign of the yaw rate (1 per fish)") \
    X(int32_t, fish_mode, WW_N_FISH(sc), "fish", "0 swimming, 1 fighting, 2 caught (away) (1 per fish)") \
    X(double, fish_timer, WW_N_FISH(sc), "fish", "fighting: seconds fought; caught: seconds to respawn (1 per fish)") \
    X(double, fish_fight, WW_N_FISH(sc), "fish", "duration of this fight, s (1 per fish)")          \
    X(double, fish_goal, WW_N_FISH(sc), "fish", "wander: goal heading; fighting: base heading, rad (1 per fish)") \
    X(double, fish_target, 3 * WW_N_FISH(sc), "fish", "targets mode: where the fish swims, m (3 per fish)") \
    X(double, fish_cruise, 2 * WW_N_FISH(sc), "fish", "cruising depth y, m, and vertical swim phase, rad (2 per fish)") \
    X(int32_t, fish_reached, WW_N_FISH(sc), "fish", "targets reached since spawn (1 per fish)")

#endif
