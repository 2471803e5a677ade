/* chest.h - the treasure chest (seed 000, "3.6 Treasure Chest"): scheduled spawns near the boat or
 * the camera on the seabed, a lifetime, collection by the camera, a prizes counter.
 *
 *   ww_chest_reset(sc, st);   // step 0: no chest, first spawn due at sc->chest.first
 *   ww_chest_event(sc, st, ev);  // WW_EV_CHEST from the script
 *   ww_chest_step(sc, st);    // every step, after the fish, before the camera
 *
 * Model. Spawns are scheduled at first + k every (k = 0, 1, ...), on the first step whose time
 * reaches them; a spawn while a chest is present replaces it (chest_expire, then chest_spawn).
 * A chest expires ttl seconds after it spawned. The anchor is the boat (boat_pos) or the camera
 * (cam_pos); the chest's base centre is drawn uniformly over the disc of `radius` around the
 * anchor's XZ, r = R sqrt(u1), theta = 2 pi u2 (u from ww_rng_draw, stream WW_RNG_CHEST), at
 * y = water level - depth. It is collected when the camera comes within `reach` of its box
 * (distance to the nearest point of the box, not to its centre).
 *
 * Departures from seed 000, and why:
 *   - the seed draws the X and Z offsets each uniformly in [-R, R] (a square: corners at 1.41 R,
 *     and denser toward the middle of the disc); here the draw is uniform over the disc and never
 *     leaves it, even for u1 = 1 (the edge), with no NaN for R = 0;
 *   - the seed measures reach from the chest's centre; a camera that collides with the chest
 *     (sim/collide.h) could then never collect a chest larger than the reach, so reach is
 *     measured to the box;
 *   - the seed's next spawn is one interval after the previous chest ended; here spawns follow
 *     a fixed schedule, so "every" means what it says and a collected chest does not move the
 *     next one.
 *   - the camera read is the previous step's (the camera moves after the chest in seed 000's
 *     step order); at step 0, before any camera exists, the camera path's first point.
 *
 * Script: WW_EV_CHEST, ev->flags bit 0 set: spawn with base centre at (ev->v[0], ev->v[1]);
 * clear: by the random rule around the anchor.
 * Events: chest_spawn (magnitude: lifetime s), chest_expire, chest_collect (prizes so far);
 * position the chest's base centre.
 */
#ifndef WW_CHEST_H
#define WW_CHEST_H

#include "sim/state.h"

#define WW_CHEST_AT 1 /* ev->flags: ev->v[0..1] hold the place */

void ww_chest_reset(const ww_scene *sc, ww_state *st);
void ww_chest_step(const ww_scene *sc, ww_state *st);
/* WW_EV_CHEST */
void ww_chest_event(const ww_scene *sc, ww_state *st, const ww_event *ev);

/* pure: the point at draws (u1, u2) in [0, 1] over the disc of radius r around (cx, cz):
 * out = (cx + r sqrt(u1) cos(2 pi u2), cz + r sqrt(u1) sin(2 pi u2)); within r for any u */
void ww_chest_place(double cx, double cz, double r, double u1, double u2, double out[2]);

/* pure: distance from point p to the box of the given size (x, y, z) whose base centre is base
 * (0 inside) */
double ww_chest_distance(const double size[3], const double base[3], const double p[3]);

#endif
