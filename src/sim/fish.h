/* fish.h - fish (seed 000 section 3.5; seed 003 section 4.1.2): wander or swim to targets, steer
 * away from the boat, cubes and camera, keep apart, bank, bite a floating lure, fight, get
 * caught, respawn.
 *
 * Call order (sim/step.c): ww_fish_reset at step 0, ww_fish_step every step after the rod (the
 * lure's state is this step's). A catch calls ww_rod_reel (sim/rod.h).
 *
 * Swimming, per fish and step (headings: 0 = +x, pi/2 = +z):
 * - a goal direction in XZ. wander (seed 000): the goal heading takes a random walk,
 *   jitter sqrt(dt) sqrt(3) (2u - 1) per step (unit variance, so statistics do not depend on dt),
 *   plus an occasional turn of up to big_turn with probability big_turn_rate dt; the goal stays
 *   within 90 degrees of the heading. targets (seed 003): toward the target; within `reach` it is
 *   reached and a new one is drawn in the region. A floating lure within rod.attract (XZ) replaces
 *   the goal (the fish goes for it).
 * - fleeing (seed 000's steerAway, "strongest at close distances"): each of the boat (its
 *   sphere, objects.boat.radius), the cubes (their bounding spheres) and the camera (a point)
 *   whose surface is a gap d < `avoid` away frightens the fish by ((avoid / d)^2 - 1) / 3
 *   (inverse-square: 0 at `avoid`, 1 at avoid / 2, growing without bound closer in; d counted
 *   from 0.05 m) along the unit vector away from it (horizontal part along the XZ direction, the
 *   heading when the threat is straight above or below). The sum F is the fear vector, its
 *   length capped at 1 the fear w. The goal direction gets 3 F (XZ); the turn rate grows to
 *   turn_rate (1 + 2 w) (a C-start); the speed bursts to speed + (max_speed - speed) w and is
 *   not slowed by the turn; the desired velocity gets max_speed F; the filter's rate grows to
 *   response + 8 w; and the change of velocity is capped at WW_FISH_MAX_ACCEL dt (15 m/s^2).
 *   avoid: 0 switches fleeing off. A fish outside 0.8 radius of the region's centre is turned
 *   back toward it.
 * - bounded turn: the heading turns toward the goal by at most turn_rate dt (seed 003's future
 *   work: smooth turns instead of snapping), and the fish slows while the goal is far off its
 *   heading (speed x (0.3 + 0.7 max(0, cos err))), so it cannot circle a target forever.
 * - desired velocity: speed along the heading, plus a vertical part (1/s gain, at most half the
 *   speed) toward its cruising depth + swim[0] sin(2 pi t / swim[1] + phase) (seed 000's slight
 *   vertical swim), or the target's height; plus separation: each other fish closer than
 *   `separation` pushes with max_speed (1 - d / separation) along the line between them (for two
 *   fish at one point, a direction drawn per pair, opposite for the two); capped at max_speed.
 * - seed 000's first-order filter v <- v + (v_des - v)(1 - e^(-a dt)) (the change capped at
 *   WW_FISH_MAX_ACCEL dt), then p <- p + v dt. A convex blend, so |v| never exceeds max_speed.
 * - depth: y is clamped to [seabed + margin, surface(x, z) - margin] with the exact surface
 *   (seabed = water level - water depth); the vertical velocity into the bound is removed.
 * - banking: a coordinated turn's bank, tan(bank) = v omega / g (omega the yaw rate), clamped to
 *   max_bank (seed 000 banks from the yaw rate with no formula given).
 *
 * Fishing: a swimming fish whose centre is within rod.bite_radius (XZ) of a floating lure that no
 * fish has bitten this cast bites (lowest index first): `bite`, the lure is hooked. Fighting (seed
 * 000): the mouth (length / 2 ahead of the centre) goes to the hook, rod.hook_depth under the
 * lure, at WW_FISH_DASH from where the fish bit (it may bite from metres below), and stays there;
 * the heading is the bite's direction plus wiggle[0] sin(2 pi wiggle[1] tau). It tugs the float
 * under in bursts: the lure (which the rod's step floats on the surface) goes down by
 * WW_FISH_TUG_DEPTH sin^2(2 pi WW_FISH_TUG_HZ tau) on the half-periods where that sine is positive,
 * and the hook with it; each such half-period starts with a splash at the float, a ripple of
 * WW_FISH_TUG_SPLASH times rod.splash.
 * After a duration drawn in fight[lo, hi] the fish is caught: fish_caught + 1, `catch`, the rod
 * reels in, and the fish is away for `respawn` seconds, then reappears at a random place. If the
 * line is reeled in first (a new cast) the fish escapes (`fish_escape`).
 *
 * Random draws: ww_rng_draw(seed, WW_RNG_FISH, step, fish * 16 + k); spawn retries add 4096 per
 * try to b, the separation direction of a pair (i < j) uses b = 2^24 + 128 i + j.
 */
#ifndef WW_FISH_H
#define WW_FISH_H

#include "sim/state.h"

enum { WW_FISH_SWIMMING = 0, WW_FISH_FIGHTING, WW_FISH_AWAY };

#define WW_FISH_FLEE_TURN 2.0   /* extra turn rate at full fear, times turn_rate (a C-start) */
#define WW_FISH_MAX_ACCEL 15.0  /* m/s^2: the largest change of a swimming fish's velocity per
                                 * second from steering (the depth clamp may remove more) */
#define WW_FISH_DASH 3.0        /* m/s: a hooked fish's dash to the hook (a trout's burst) */
#define WW_FISH_TUG_DEPTH 0.05  /* m: how far a fighting fish pulls the float under */
#define WW_FISH_TUG_HZ 1.3      /* its tugs a second */
#define WW_FISH_TUG_SPLASH 1.0  /* each tug's splash at the float, of the lure's landing one */

void ww_fish_reset(const ww_scene *sc, ww_state *st);
void ww_fish_step(const ww_scene *sc, ww_state *st);

/* pure: the seabed-and-surface bounds of a fish's centre under a surface at height h, m */
void ww_fish_depth_bounds(const ww_scene *sc, double h, double *lo, double *hi);

#endif
