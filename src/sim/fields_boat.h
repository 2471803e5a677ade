/* fields_boat.h - the state fields of the boat, an X-macro table appended to WW_STATE_FIELDS
 * (sim/state.h), count 0 without a boat. boat_pos, boat_vel and boat_heading are read by the
 * stones, fish and camera collision; boat_tilt by the renderer; boat_camera by the camera
 * collision (in the seat, the camera is inside the boat's sphere on purpose). */
#ifndef WW_FIELDS_BOAT_H
#define WW_FIELDS_BOAT_H

#define WW_N_BOAT(sc) ((sc)->boat.on ? 1 : 0)
#define WW_BOAT_SAMPLES 5 /* surface sample points: centre, bow, stern, port, starboard */
#define WW_BOAT_WAKE 40   /* the wake's trail: where the stern was, every WW_BOAT_WAKE_EVERY s */
#define WW_BOAT_WAKE_EVERY 0.2

#define WW_FIELDS_BOAT(X)                                                                         \
    X(double, boat_pos, 3 * WW_N_BOAT(sc), "boat", "hull centre, m (3)")                            \
    X(double, boat_vel, 3 * WW_N_BOAT(sc), "boat", "velocity, m/s (3)")                             \
    X(double, boat_heading, WW_N_BOAT(sc), "boat", "heading, rad in [-pi, pi) (1)")                 \
    X(double, boat_speed, WW_N_BOAT(sc), "boat", "forward speed along the heading, signed, m/s (1)") \
    X(double, boat_tilt, 2 * WW_N_BOAT(sc), "boat", "pitch (bow up +), roll (starboard down +), rad (2)") \
    X(double, boat_follow, 3 * WW_N_BOAT(sc), "boat", "last step's surface targets: height m, pitch, roll rad (3)") \
    X(double, boat_input, 3 * WW_N_BOAT(sc), "boat", "inputs in force: throttle, steer, until s (-1: none) (3)") \
    X(double, boat_command, 4 * WW_N_BOAT(sc), "boat", "inputs from this step's action: throttle, steer, until, 1 = pending (4)") \
    X(double, boat_look_yaw, WW_N_BOAT(sc), "boat", "seat view heading, rad (1)")                   \
    X(double, boat_warm, WW_WARM_STRIDE * WW_BOAT_SAMPLES * WW_N_BOAT(sc), "boat", "warm starts of the surface queries (sim/water.h), m: last rest offset a - x and its change (4 per sample: centre, bow, stern, port, starboard)") \
    X(int32_t, boat_camera, WW_N_BOAT(sc), "boat", "camera mode: 0 free (the path), 1 the boat's seat (1)") \
    X(double, boat_odometer, WW_N_BOAT(sc), "boat", "distance the hull has moved over the water, m (1)") \
    X(double, boat_wake, 4 * WW_BOAT_WAKE * WW_N_BOAT(sc), "boat", "the stern's trail for the wake, oldest overwritten: x, z m, t s, odometer m (4 per sample)") \
    X(int32_t, boat_wake_next, WW_N_BOAT(sc), "boat", "the trail's slot written next (1)")

#endif
