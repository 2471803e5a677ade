/* splash.c - the spray a splash throws up (splash.h) */
#include "gfx/splash.h"

#include <math.h>
#include <string.h>

#include "core/mathx.h"
#include "core/rng.h"
#include "sim/ripples.h"
#include "sim/water.h"

#define RING 0.04            /* m: the least radius the drops leave from ... */
#define RING_SPREAD 0.08     /* ... and up to this much more */
#define ANGLE_LO 55.0        /* degrees from the level: the crown's drops rise steeply */
#define ANGLE_HI 80.0
#define SPEED_LO 0.55        /* of the speed that reaches the crown's height */
#define DROP_RADIUS 0.007    /* m: the least drop drawn ... */
#define DROP_RADIUS_SPREAD 0.011 /* ... and up to this much more */

int ww_splash_capacity(const ww_scene *sc) {
    if (!sc->ripples_on || !(sc->ripples.spray > 0.0)) return 0;
    return sc->ripples.max * WW_SPLASH_MAX_DROPS;
}

/* the bits of a double, for keying the draws */
static uint64_t bits(double x) {
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

int ww_splash_drops(const ww_scene *sc, const ww_state *st, ww_splash_drop *out, int max) {
    if (ww_splash_capacity(sc) == 0) return 0;
    int n = 0;
    for (int r = 0; r < st->ripple_slots[0]; r++) {
        const double *e = st->ripple + WW_RIPPLE_STRIDE * r;
        double amp = e[3], age = st->t - e[2];
        if (!(amp > 0.0) || age < 0.0) continue;
        double rise = ww_m_clamp(WW_SPLASH_RISE * amp, WW_SPLASH_RISE_MIN, WW_SPLASH_RISE_MAX);
        double top = sqrt(2.0 * WW_G * rise); /* the vertical speed that reaches the crown */
        if (age > 2.0 * top / WW_G) continue; /* every drop is back down */
        int count = (int)lround(fmin(sc->ripples.spray * WW_SPLASH_DROPS * amp / WW_SPLASH_A_REF,
                                     WW_SPLASH_MAX_DROPS));
        ww_water_sample ws;
        ww_water_at(sc, st, e[0], e[1], 0.0, &ws);
        uint64_t key = bits(e[2]) ^ (bits(e[0]) * 0x9e3779b97f4a7c15ull) ^
                       (bits(e[1]) * 0xc2b2ae3d27d4eb4full);
        uint64_t prefix = ww_rng_prefix(sc->seed, WW_RNG_SPLASH, key);
        for (int k = 0; k < count && n < max; k++) {
            double u[5];
            for (int j = 0; j < 5; j++) u[j] = ww_rng_draw_at(prefix, 8 * (uint64_t)k + j);
            double az = WW_TAU * u[0];
            double el = ww_m_rad(ANGLE_LO + (ANGLE_HI - ANGLE_LO) * u[1]);
            double vy = top * (SPEED_LO + (1.0 - SPEED_LO) * u[2]), vh = vy / tan(el);
            double y = vy * age - 0.5 * WW_G * age * age;
            if (y < 0.0) continue; /* fallen back */
            double ring = RING + RING_SPREAD * u[3] + vh * age;
            ww_splash_drop *d = &out[n++];
            d->p[0] = e[0] + ring * cos(az);
            d->p[1] = ws.height + y;
            d->p[2] = e[1] + ring * sin(az);
            d->radius = DROP_RADIUS + DROP_RADIUS_SPREAD * u[4];
        }
    }
    return n;
}
