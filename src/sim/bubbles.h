/* bubbles.h - air bubbles (seed 003, "4.2.4 Transparent air bubbles"): emitters on the seabed
 * release bubbles that rise with a zigzag wobble and burst at the surface; each emitter owns a
 * fixed pool of bubbles (objects.bubbles[i].count), so nothing is allocated while stepping.
 *
 *   ww_bubbles_reset(sc, st);   // step 0: each column already full, as if running for ever
 *   ww_bubbles_step(sc, st);    // every step, after the chest
 *
 * Model. Emitter e releases a bubble at the times start + (k - u_e) / rate, k integer (u_e a
 * draw per emitter that staggers the emitters), into a free slot of its pool; with no free slot
 * the release is skipped, so the pool caps the flow at count bubbles in flight. A bubble released
 * at t0 is, at age a = t - t0 (closed form, no integration error):
 *
 *   y(a)  = at.y + v a
 *   xz(a) = at.xz + A (1 - e^(-2 pi f a)) sin(2 pi f a + phi) (cos theta, sin theta)
 *
 * v = speed (0.9 + 0.2 u): air bubbles of 1 to 10 mm radius in water rise at 0.2 to 0.35 m/s
 * (Haberman & Morton 1954; Clift, Grace & Weber, "Bubbles, Drops and Particles", 1978), the
 * default 0.25 m/s; bubbles above about 1 mm radius leave the straight path and zigzag or
 * spiral (path instability, Saffman 1956), here a planar zigzag of amplitude A = wobble and
 * frequency f in a random plane theta with a random phase phi, grown from zero at the vent
 * over about one period (the instability needs some rise to develop), so every bubble starts at
 * the emitter. Radius = size (0.5 + 0.5 u), for the renderer.
 *
 * A bubble bursts (its slot is freed) on the first step its top reaches the exact surface over
 * it (ww_water_at: waves and ripples); a stored bubble is therefore never above the surface. The
 * surface is only queried where it could be reached: above water level - sum 2|A_i| (waves) -
 * sum |A0| (ripples), a bound on how low the surface can be.
 *
 * Seed 003 only says the bubbles rise to the surface and move "like the fish, but simpler"; the
 * rise speed, the zigzag, the burst at the moving surface and the rate are this file's, from the
 * measurements cited above.
 */
#ifndef WW_BUBBLES_H
#define WW_BUBBLES_H

#include "sim/state.h"

void ww_bubbles_reset(const ww_scene *sc, ww_state *st);
void ww_bubbles_step(const ww_scene *sc, ww_state *st);

/* pure: the lateral wobble offset (along the bubble's plane) at age a, m */
double ww_bubble_wobble(double amplitude, double frequency, double phase, double age);

#endif
