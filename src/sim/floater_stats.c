/* floater_stats.c - heave and tilt RMS of the floating objects (floater_stats.h). */
#include "sim/floater_stats.h"

#include <math.h>

#include "sim/state.h"
#include "sim/step.h"

#define SETTLE_FRACTION 0.25 /* of the run, before sampling starts */

/* the angle between the vertical and the nearest of the box's axes, for unit quaternion q */
static double box_tilt(const double q[4]) {
    double w = q[0], x = q[1], y = q[2], z = q[3];
    if (w == 0.0 && x == 0.0 && y == 0.0 && z == 0.0) return 0.0;
    /* the world y components of the rotated x, y and z axes (third row of the matrix) */
    double ax = 2.0 * (x * y + w * z), ay = 1.0 - 2.0 * (x * x + z * z), az = 2.0 * (y * z - w * x);
    double m = fmax(fabs(ax), fmax(fabs(ay), fabs(az)));
    return acos(fmin(m, 1.0));
}

ww_result ww_floater_stats_compute(const ww_scene *sc, ww_floater_stats *out, ww_error *err) {
    *out = (ww_floater_stats){NAN, NAN, NAN, NAN, 0};
    int ncubes = sc->cubes.on ? sc->cubes.count : 0;
    if (ncubes == 0 && !sc->boat.on) return WW_OK;
    ww_state *st = ww_state_new(sc);
    if (!st) return ww_error_set(err, WW_E_NOMEM, sc->path, 0, 0, "out of memory for the state");

    /* two passes over the same deterministic run would double the cost: accumulate sums of
     * y and y^2 (heave about the mean) and of angle^2 */
    double cy[2 * WW_MAX_CUBES] = {0}, ct2 = 0.0, by[2] = {0}, bp2 = 0.0;
    int64_t first = (int64_t)ceil(SETTLE_FRACTION * (double)sc->frame_count), n = 0;
    ww_result r = WW_OK;
    for (int64_t f = 0; f < sc->frame_count && r == WW_OK; f++) {
        r = ww_sim_advance_to(sc, st, f * sc->steps_per_frame, err);
        if (r != WW_OK || f < first) continue;
        n++;
        for (int i = 0; i < ncubes; i++) {
            double y = st->cube_pos[3 * i + 1], a = box_tilt(st->cube_rot + 4 * i);
            cy[2 * i] += y;
            cy[2 * i + 1] += y * y;
            ct2 += a * a;
        }
        if (sc->boat.on) {
            by[0] += st->boat_pos[1];
            by[1] += st->boat_pos[1] * st->boat_pos[1];
            bp2 += st->boat_tilt[0] * st->boat_tilt[0];
        }
    }
    ww_state_free(st);
    if (r != WW_OK || n == 0) return r;
    out->samples = (int)n;
    double dn = (double)n;
    if (ncubes > 0) {
        double h = 0.0;
        for (int i = 0; i < ncubes; i++) {
            double mean = cy[2 * i] / dn;
            h += sqrt(fmax(cy[2 * i + 1] / dn - mean * mean, 0.0));
        }
        out->cube_heave_rms = h / ncubes;
        out->cube_tilt_rms = sqrt(ct2 / (dn * ncubes));
    }
    if (sc->boat.on) {
        double mean = by[0] / dn;
        out->boat_heave_rms = sqrt(fmax(by[1] / dn - mean * mean, 0.0));
        out->boat_pitch_rms = sqrt(bp2 / dn);
    }
    return WW_OK;
}
