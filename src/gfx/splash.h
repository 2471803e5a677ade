/* splash.h - the spray a splash throws up, drawn from the ripples in the state (sim/ripples.h):
 * every ripple is something that hit the water (a stone's skip or sink, the lure landing, a
 * cube let go, a scripted ripple), so each young one throws a crown of drops that rise and fall
 * back on ballistic paths. Nothing in the simulation reads them: they are built each frame from
 * the pool's (x, z, t0, A0) and drawn as small lit icosahedra (gfx/geometry.c). No GL here: the
 * tests check the drops without a context.
 *
 * A splash of amplitude A throws about WW_SPLASH_DROPS (A / WW_SPLASH_A_REF) drops (scaled by
 * water.ripples.spray), to a crown height of WW_SPLASH_RISE A, from a ring a few centimetres
 * across at the surface over the ripple's centre, at 55 to 80 degrees from the level, each
 * drop's azimuth, angle, speed and size drawn from a counter-based stream keyed by the ripple
 * (core/rng.h: WW_RNG_SPLASH), so a frame shows the same drops whichever frames were rendered
 * before it. A drop is drawn from the splash's instant until it falls back below the surface
 * over the ripple's centre, which it was thrown from. */
#ifndef WW_GFX_SPLASH_H
#define WW_GFX_SPLASH_H

#include "scene/scene.h"
#include "sim/state.h"

#define WW_SPLASH_DROPS 40      /* drops of a splash of amplitude WW_SPLASH_A_REF ... */
#define WW_SPLASH_A_REF 0.03    /* m: a stone's skip or the lure's landing (their defaults) */
#define WW_SPLASH_MAX_DROPS 72  /* ... and at most this many, however large it is */
#define WW_SPLASH_RISE 6.0      /* the crown's height per m of amplitude ... */
#define WW_SPLASH_RISE_MIN 0.03 /* ... and its least and most, m */
#define WW_SPLASH_RISE_MAX 0.6

typedef struct ww_splash_drop {
    double p[3];   /* world, m */
    double radius; /* m */
} ww_splash_drop;

/* how many drops a scene's splashes can show at once at most (the pool's size times the most a
 * splash throws; 0 without ripples or spray) */
int ww_splash_capacity(const ww_scene *sc);

/* the drops in the air now, at most `max`; returns the count */
int ww_splash_drops(const ww_scene *sc, const ww_state *st, ww_splash_drop *out, int max);

#endif
