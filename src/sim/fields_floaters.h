/* fields_floaters.h - the state fields of the floaters system (floating models, sim/floaters.c),
 * an X-macro table appended to WW_STATE_FIELDS (sim/state.h): counts 0 without floating models,
 * so other scenes keep their state and hash. Read by the renderer (the models' poses) and camera
 * collision (their boxes). */
#ifndef WW_FIELDS_FLOATERS_H
#define WW_FIELDS_FLOATERS_H

#define WW_N_FLOATERS(sc) ((sc)->floaters.on ? (sc)->floaters.count : 0)

/* the surface sample points (the columns' nodes, sim/boxwater.h) of the floaters before
 * floater j */
static inline int ww_floater_samples_before(const ww_scene *sc, int j) {
    int sum = 0;
    for (int i = 0; i < j; i++) {
        int m = ww_box_nodes_per_side(sc->floaters.floater[i].columns);
        sum += m * m;
    }
    return sum;
}

#define WW_FIELDS_FLOATERS(X)                                                                     \
    X(double, floater_pos, 3 * WW_N_FLOATERS(sc), "floaters", "floating box centres, m (3 per floater)") \
    X(double, floater_vel, 3 * WW_N_FLOATERS(sc), "floaters", "velocities of the centres, m/s (3 per floater)") \
    X(double, floater_rot, 4 * WW_N_FLOATERS(sc), "floaters", "orientations, unit quaternion w x y z (4 per floater)") \
    X(double, floater_omega, 3 * WW_N_FLOATERS(sc), "floaters", "angular velocities, world frame, rad/s (3 per floater)") \
    X(double, floater_submerged, WW_N_FLOATERS(sc), "floaters", "submerged fraction of the box, 0..1 (1 per floater)") \
    X(double, floater_warm, WW_WARM_STRIDE * ww_floater_samples_before(sc, WW_N_FLOATERS(sc)), "floaters", "warm starts of the surface queries (sim/water.h), m: last rest offset a - x and its change (4 per surface node of a floater, sim/boxwater.h)")

#endif
