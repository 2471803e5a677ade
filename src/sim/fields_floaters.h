/* fields_floaters.h - the state fields of the floaters system (floating models, sim/floaters.c),
 * an X-macro table appended to WW_STATE_FIELDS (sim/state.h): counts 0 without floating models,
 * so other scenes keep their state and hash. Read by the renderer (the models' poses) and camera
 * collision (their boxes). */
#ifndef WW_FIELDS_FLOATERS_H
#define WW_FIELDS_FLOATERS_H

#define WW_N_FLOATERS(sc) ((sc)->floaters.on ? (sc)->floaters.count : 0)

#define WW_FIELDS_FLOATERS(X)                                                                     \
    X(double, floater_pos, 3 * WW_N_FLOATERS(sc), "floaters", "floating box centres, m (3 per floater)") \
    X(double, floater_vel, 3 * WW_N_FLOATERS(sc), "floaters", "velocities of the centres, m/s (3 per floater)") \
    X(double, floater_rot, 4 * WW_N_FLOATERS(sc), "floaters", "orientations, unit quaternion w x y z (4 per floater)") \
    X(double, floater_omega, 3 * WW_N_FLOATERS(sc), "floaters", "angular velocities, world frame, rad/s (3 per floater)") \
    X(double, floater_submerged, WW_N_FLOATERS(sc), "floaters", "submerged fraction of the box, 0..1 (1 per floater)")

#endif
