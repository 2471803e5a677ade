/* collide.h - camera collision (seed 003, "4.1.3 Collision detection"): the camera cannot enter
 * solid objects; a scripted path that would pass through one is held at its surface, and the
 * contact is logged.
 *
 *   ww_camera_collide(sc, st);  // last in the step, after the path and the boat seat, when
 *                               // sc->camera_collide
 *
 * Solids, each grown by the margin m = the camera's near clip (so the near plane never cuts into
 * an object): the boat, a sphere (boat_pos, objects.boat.radius); the cubes, oriented boxes
 * (cube_pos, cube_rot, edge objects.cubes[i].size); the chest while present, its box
 * (chest.h); each solid model's bounds (objects.models): given min/max, or its mesh's own box
 * turned with it (an oriented box, so a tilted wreck has no invisible corners), the axis-aligned
 * box where it is not turned. Bubbles, fish and models with solid: false (swaying plants by
 * default) are not solid.
 *
 * Model. Let p0 be the camera's position after collision at the previous step (collide_prev)
 * and p1 the position the path (or seat) asks for now.
 *   1. p0 is pushed out of any solid that moved into it (to the nearest point of its surface).
 *   2. The segment p0 -> p1 is swept against every solid (slab test for boxes in the box's
 *      frame, ray-sphere for the boat: Ericson, "Real-Time Collision Detection", 5.3.2 and
 *      5.3.3); at the first entry the camera stops on the surface, and what is left of the move
 *      slides along it (the normal component removed), swept again, at most three times
 *      (Fauerby 2003, "Improved Collision detection and Response"). A fast camera cannot tunnel
 *      through a thin object between two steps, and a held camera never jumps to its path: a
 *      path straight through a solid leaves the camera on the near face (stopped head-on,
 *      sliding when the path moves sideways), and it is on its path again only when the sweep
 *      from where it is reaches it, i.e. once the path has gone around the solid.
 * At step 0 there is no previous position: p0 = p1, pushed out. The camera's distance to every
 * solid is at least m after each step (boxes are grown by m on every side, so a point outside
 * the grown box is at least m from the box).
 *
 * Seed 003 stops forward motion when the depth buffer holds a value < 0.5 (it cannot see
 * behind the camera and depends on the projection); here the test is geometric, both ways.
 *
 * In the boat's seat the camera rides with the boat: a camera not where the scripted path puts
 * it (the boat seat moved it) is not collided, and the next free step starts over as at step 0.
 *
 * Events: camera_blocked once per contact (the first step the camera is held back after a free
 * step): object index, the camera's position, magnitude the distance the path was cut short that
 * step (m), aux what: 0 boat, 1 cube, 2 chest, 3 model.
 */
#ifndef WW_COLLIDE_H
#define WW_COLLIDE_H

#include "sim/state.h"

/* aux of camera_blocked, and collide_state[0] - 1 */
enum { WW_SOLID_BOAT = 0, WW_SOLID_CUBE, WW_SOLID_CHEST, WW_SOLID_MODEL };

/* after the camera (and the boat seat): keep st->cam_pos out of solid objects, emitting
 * WW_SE_CAMERA_BLOCKED when it had to move it (when sc->camera_collide) */
void ww_camera_collide(const ww_scene *sc, ww_state *st);

#endif
