/* fields_cubes.h - the state fields of the cubes system, an X-macro table appended to
 * WW_STATE_FIELDS (sim/state.h): X(type, name, count, system, comment), count 0 without cubes.
 * cube_pos, cube_vel and cube_rot are read (and cube_pos/cube_vel written when pushing) by the
 * boat, stones, fish and camera collision. The rest is the cubes' own (sim/cubes.c). */
#ifndef WW_FIELDS_CUBES_H
#define WW_FIELDS_CUBES_H

#define WW_N_CUBES(sc) ((sc)->cubes.on ? (sc)->cubes.count : 0)

/* the surface sample points of cube i: its columns' nodes (archimedes, ww_box_nodes_per_side
 * squared) or its centre (spring) */
static inline int ww_cube_samples(const ww_scene *sc, int i) {
    const ww_cube_desc *d = &sc->cubes.cube[i];
    int m = ww_box_nodes_per_side(d->columns > 0 ? d->columns : WW_CUBE_DEFAULT_COLUMNS);
    return d->buoyancy == WW_CUBE_SPRING ? 1 : m * m;
}
/* the sample points of the cubes of the same buoyancy before cube i */
static inline int ww_cube_samples_before(const ww_scene *sc, int i) {
    int sum = 0;
    for (int j = 0; j < i; j++)
        if (sc->cubes.cube[j].buoyancy == sc->cubes.cube[i].buoyancy)
            sum += ww_cube_samples(sc, j);
    return sum;
}
/* the archimedes cubes' sample points (all their nodes), and all the cubes' */
static inline int ww_cube_nodes_all(const ww_scene *sc) {
    int sum = 0;
    for (int j = 0; j < WW_N_CUBES(sc); j++)
        if (sc->cubes.cube[j].buoyancy != WW_CUBE_SPRING) sum += ww_cube_samples(sc, j);
    return sum;
}
static inline int ww_cube_samples_all(const ww_scene *sc) {
    int sum = 0;
    for (int j = 0; j < WW_N_CUBES(sc); j++) sum += ww_cube_samples(sc, j);
    return sum;
}
/* where cube i's warm starts begin, in sample points: the archimedes cubes' nodes first, in cube
 * order, so that one query takes them all; then a point a spring cube */
static inline int ww_cube_warm_index(const ww_scene *sc, int i) {
    int base = sc->cubes.cube[i].buoyancy == WW_CUBE_SPRING ? ww_cube_nodes_all(sc) : 0;
    return base + ww_cube_samples_before(sc, i);
}

#define WW_FIELDS_CUBES(X)                                                                        \
    X(double, cube_pos, 3 * WW_N_CUBES(sc), "cubes", "cube centres, m (3 per cube)")                \
    X(double, cube_vel, 3 * WW_N_CUBES(sc), "cubes", "cube velocities, m/s (3 per cube)")           \
    X(double, cube_rot, 4 * WW_N_CUBES(sc), "cubes", "cube orientations, unit quaternion w x y z (4 per cube)") \
    X(double, cube_omega, 3 * WW_N_CUBES(sc), "cubes", "cube angular velocities, world frame, rad/s (3 per cube)") \
    X(double, cube_press, 2 * WW_N_CUBES(sc), "cubes", "press: hold left, s (0: not pressed); held so far, s (2 per cube)") \
    X(double, cube_submerged, WW_N_CUBES(sc), "cubes", "submerged fraction of the volume, 0..1 (1 per cube)") \
    X(double, cube_warm, WW_WARM_STRIDE * ww_cube_samples_all(sc), "cubes", "warm starts of the surface queries (sim/water.h), m: last rest offset a - x and its change (4 per sample point: the archimedes cubes' surface nodes, sim/boxwater.h, in cube order, then 1 per spring cube)")

#endif
