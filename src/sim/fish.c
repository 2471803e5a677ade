/* fish.c - the fish: seed 000's wander with steering away and seed 003's targets, both with
 * bounded turn rates and separation (seed 003's future work: smooth turns, fish that do not pass
 * through each other), first-order velocity filter, depth bounds against the exact surface,
 * banking, and the bite / fight / catch / respawn cycle with the rod. Model in fish.h.
 */
#include "sim/fish.h"

#include <math.h>

#include "core/atan.h"
#include "core/lanes.h"
#include "core/mathx.h"
#include "core/rng.h"
#include "core/select.h"
#include "core/sincos.h"
#include "sim/events.h"
#include "sim/ripples.h"
#include "sim/rod.h"
#include "sim/water.h"

/* draw slots k of a fish (b = fish * 16 + k) */
enum { K_JITTER = 0, K_BIG, K_BIG_ANGLE, K_SPAWN_ANGLE, K_SPAWN_R, K_CRUISE, K_YAW, K_PHASE,
       K_FIGHT, K_TARGET_ANGLE, K_TARGET_R, K_TARGET_Y };

#define SPAWN_TRIES 8            /* draws for a spawn point clear of the other fish */
#define RETRY_STRIDE 4096        /* b offset per spawn retry (above every fish * 16 + k) */
#define PAIR_BASE (1u << 24)     /* b of a pair's separation direction */
#define AVOID_WEIGHT 3.0         /* steering away against the goal direction of weight 1 */
#define HOME_WEIGHT 2.0          /* turning back into the region at its edge */
#define HOME_START 0.8           /* fraction of the radius where turning back starts */
#define VERTICAL_GAIN 1.0        /* 1/s: vertical speed per metre off the wanted depth */
#define VERTICAL_MAX 0.5         /* of the speed: the steepest climb or dive */
#define SLOW_TURN_MIN 0.3        /* speed fraction while the goal is behind */
#define FLEE_HALF 3.0            /* (R/d)^2 - 1 at d = R/2: a threat there gives fear 1 */
#define FLEE_MIN_GAP 0.05        /* m: the closest a threat's surface counts (fear <= 2130 R^2) */
#define FAR_THREAT_MARGIN (1.0 + 1e-9) /* squared distance over (reach)^2: surely beyond it */
#define FLEE_RESPONSE 8.0        /* 1/s: extra velocity response at full fear */

/* the fish's draws of a step share a prefix (ww_rng_prefix of the seed, WW_RNG_FISH and the
 * step), worked out once a step: rng below */
static uint64_t fish_rng(const ww_scene *sc, const ww_state *st) {
    return ww_rng_prefix(sc->seed, WW_RNG_FISH, (uint64_t)st->step);
}
static double draw(uint64_t rng, int i, uint64_t k) {
    return ww_rng_draw_at(rng, (uint64_t)i * 16u + k);
}

/* a into [-pi, pi). Within 3 rad of 0 the quotient's floor is 0 whatever the rounding, so a is
 * its own wrap (a - 2 pi 0 = a to the bit) without the division and floor */
static double wrap_pi(double a) {
    if (fabs(a) < 3.0) return a;
    return a - WW_TAU * floor((a + WW_PI) / WW_TAU);
}

/* |(x, z)|: the fish's lengths are metres, far from hypot's overflow and underflow */
static double len2(double x, double z) { return sqrt(x * x + z * z); }

/* (x, z) made unit into (ox, oz) where its length is above least, else the heading yaw's */
static void unit_or_heading(double x, double z, double least, double yaw, double *ox, double *oz) {
    double h = len2(x, z);
    if (h > least) {
        *ox = x / h;
        *oz = z / h;
    } else {
        ww_sincos(yaw, oz, ox);
    }
}
/* sin x, by ww_sincos: the same on every libm */
static double sine(double x) {
    double s, c;
    ww_sincos(x, &s, &c);
    return s;
}

void ww_fish_depth_bounds(const ww_scene *sc, double h, double *lo, double *hi) {
    *lo = sc->water_level - sc->water_depth + sc->fish.margin;
    *hi = h - sc->fish.margin;
    if (*hi < *lo) *lo = *hi = 0.5 * (*lo + *hi); /* a trough down to the seabed */
}

static double surface(const ww_scene *sc, const ww_state *st, double x, double z) {
    ww_water_sample w;
    ww_water_at(sc, st, x, z, 0.0, &w);
    return w.height;
}

/* fish i's school (objects.fish.species): its species' region, cruising speed and body length,
 * or objects.fish's when the scene has no species */
static const ww_fish_species *species_of(const ww_fish_desc *f, int i) {
    return f->nspecies > 0 ? &f->species[f->species_of[i]] : NULL;
}
static const double *school_center(const ww_fish_desc *f, int i) {
    const ww_fish_species *sp = species_of(f, i);
    return sp ? sp->center : f->center;
}
static double school_radius(const ww_fish_desc *f, int i) {
    const ww_fish_species *sp = species_of(f, i);
    return sp ? sp->radius : f->radius;
}
static double cruise_speed(const ww_fish_desc *f, int i) {
    const ww_fish_species *sp = species_of(f, i);
    return sp ? sp->speed : f->speed;
}
static double body_length(const ww_fish_desc *f, int i) {
    const ww_fish_species *sp = species_of(f, i);
    return sp ? sp->length : f->length;
}

/* the band where fish i cruises and its targets lie: its school's centre.y +- spread, under
 * the highest crest */
static void cruise_band(const ww_scene *sc, int i, double *lo, double *hi) {
    const ww_fish_desc *f = &sc->fish;
    const double *center = school_center(f, i);
    double crest = 0.0;
    for (int w = 0; w < sc->nwaves; w++) crest += 2.0 * fabs(sc->waves[w].amplitude);
    double bed = sc->water_level - sc->water_depth + f->margin;
    double top = sc->water_level - f->margin - crest;
    *lo = fmax(bed, center[1] - f->spread);
    *hi = fmin(top, center[1] + f->spread);
    if (*hi < *lo) *lo = *hi = ww_m_clamp(center[1], bed, fmax(bed, top));
}

/* a point of the region: uniform in the disc, height uniform in the band */
static void region_point(const ww_scene *sc, uint64_t rng, int i, uint64_t ka, uint64_t kr,
                         uint64_t ky, double p[3]) {
    const ww_fish_desc *f = &sc->fish;
    double lo, hi;
    cruise_band(sc, i, &lo, &hi);
    const double *center = school_center(f, i);
    double a = WW_TAU * draw(rng, i, ka), r = school_radius(f, i) * sqrt(draw(rng, i, kr));
    double sa, ca;
    ww_sincos(a, &sa, &ca);
    p[0] = center[0] + r * ca;
    p[1] = lo + (hi - lo) * draw(rng, i, ky);
    p[2] = center[2] + r * sa;
}

static void new_target(const ww_scene *sc, const ww_state *st, uint64_t rng, int i) {
    region_point(sc, rng, i, K_TARGET_ANGLE, K_TARGET_R, K_TARGET_Y, st->fish_target + 3 * i);
}

/* place fish i: the scene's position at step 0 when given, else a drawn point at least one
 * separation from the fish [0, others) that are in the water */
static void spawn(const ww_scene *sc, ww_state *st, uint64_t rng, int i, int others, int first) {
    const ww_fish_desc *f = &sc->fish;
    double *p = st->fish_pos + 3 * i;
    if (first && i < f->npositions) {
        for (int k = 0; k < 3; k++) p[k] = f->positions[i][k];
    } else {
        for (int t = 0; t < SPAWN_TRIES; t++) {
            uint64_t off = (uint64_t)t * RETRY_STRIDE;
            region_point(sc, rng, i, K_SPAWN_ANGLE + off, K_SPAWN_R + off, K_CRUISE + off, p);
            int clear = 1;
            for (int j = 0; j < others && clear; j++) {
                if (j == i || st->fish_mode[j] == WW_FISH_AWAY) continue;
                double d[3];
                ww_m_sub3(p, st->fish_pos + 3 * j, d);
                clear = ww_m_len3(d) >= f->separation;
            }
            if (clear) break;
        }
    }
    double yaw = WW_TAU * draw(rng, i, K_YAW) - WW_PI;
    st->fish_cruise[2 * i] = p[1];
    st->fish_cruise[2 * i + 1] = WW_TAU * draw(rng, i, K_PHASE);
    st->fish_yaw[i] = yaw;
    st->fish_goal[i] = yaw;
    st->fish_yaw_rate[i] = 0.0;
    st->fish_bank[i] = 0.0;
    double sy, cy;
    ww_sincos(yaw, &sy, &cy);
    st->fish_vel[3 * i] = cruise_speed(f, i) * cy;
    st->fish_vel[3 * i + 1] = 0.0;
    st->fish_vel[3 * i + 2] = cruise_speed(f, i) * sy;
    st->fish_mode[i] = WW_FISH_SWIMMING;
    st->fish_timer[i] = 0.0;
    st->fish_reached[i] = 0.0;
    new_target(sc, st, rng, i);
}

void ww_fish_reset(const ww_scene *sc, ww_state *st) {
    st->fish_caught[0] = 0.0;
    uint64_t rng = fish_rng(sc, st);
    for (int i = 0; i < sc->fish.count; i++) spawn(sc, st, rng, i, i, 1);
}

/* a floating lure nobody has bitten this cast */
static int lure_free(const ww_scene *sc, const ww_state *st) {
    return sc->rod.on && (int)st->lure_state[0] == WW_LURE_FLOATING && st->rod_fish[0] < 0.0;
}

/* ---- distance tests over all fish or threats at once ----------------------------------------- */

/* points as lanes (one array a coordinate), padded to blocks of 8 with a point far from any
 * fish: the fish (kept as each fish moves, so a fish sees those before it where they moved to
 * this step) or the threats of a step */
#define FISH_LANES (((WW_MAX_FISH > WW_MAX_CUBES + 2 ? WW_MAX_FISH : WW_MAX_CUBES + 2) + 7) / 8 * 8)
#define FAR_POINT 1e150 /* squared distances of 1e300: beyond any separation or reach */
typedef struct point_lanes {
    int n, nb;
    double x[FISH_LANES], y[FISH_LANES], z[FISH_LANES];
} point_lanes;

static void lanes_set(point_lanes *L, int k, const double p[3]) {
    L->x[k] = p[0], L->y[k] = p[1], L->z[k] = p[2];
}
static void lanes_pad(point_lanes *L, int n) {
    L->n = n;
    L->nb = (n + 7) / 8;
    for (int k = n; k < 8 * L->nb; k++) L->x[k] = L->y[k] = L->z[k] = FAR_POINT;
}

/* d2[k] = |p - point k|^2 for every point of L: ww_m_dot3 of ww_m_sub3(p, point) point by point
 * (the same operations in the same order, so the same bits), in lanes (restrict: GCC at -O2
 * vectorises no loop it would first have to check for overlap) */
static WW_LANES void squared_distances(const point_lanes *restrict L, const double p[3],
                                       double *restrict d2) {
    double px = p[0], py = p[1], pz = p[2];
    for (int b = 0; b < L->nb; b++)
        for (int j = 0; j < 8; j++) {
            int k = 8 * b + j;
            double dx = px - L->x[k], dy = py - L->y[k], dz = pz - L->z[k];
            d2[k] = dx * dx + dy * dy + dz * dz;
        }
}

/* the threats a fish flees, in the order their fears are summed: the boat (its sphere), the
 * cubes (their bounding spheres), the camera (a point); each with its surface's distance from
 * its centre and the squared distance beyond which it surely adds nothing */
typedef struct threats {
    point_lanes at;
    const double *centre[WW_MAX_CUBES + 2];
    double r[WW_MAX_CUBES + 2], far2[WW_MAX_CUBES + 2];
} threats;

static void threat_add(threats *T, const double *q, double r, double R) {
    int k = T->at.n++;
    lanes_set(&T->at, k, q);
    T->centre[k] = q;
    T->r[k] = r;
    /* a threat surely farther than R + r (by far more than the rounding of the root) */
    double reach = R + r;
    T->far2[k] = FAR_THREAT_MARGIN * reach * reach;
}

static void threats_of_step(const ww_scene *sc, const ww_state *st, threats *T) {
    double R = sc->fish.avoid;
    T->at.n = 0;
    if (sc->boat.on) threat_add(T, st->boat_pos, sc->boat.radius, R);
    for (int c = 0; c < WW_N_CUBES(sc); c++)
        threat_add(T, st->cube_pos + 3 * c, 0.5 * sqrt(3.0) * sc->cubes.cube[c].size, R);
    threat_add(T, st->cam_pos, 0.0, R);
    lanes_pad(&T->at, T->at.n);
}

/* add_fear past its first test: the threat at offset d (fish less threat) is within reach */
static void add_fear_near(const double d[3], double r, double R, double yaw, double fl[3]) {
    double dist = ww_m_len3(d), gap = fmax(dist - r, FLEE_MIN_GAP);
    if (!(gap < R)) return;
    double w = ((R / gap) * (R / gap) - 1.0) / FLEE_HALF, h = len2(d[0], d[2]);
    double ux, uz; /* the flight's heading: away from the threat, or on if it is straight above */
    if (h > 1e-9) {
        ux = d[0] / h;
        uz = d[2] / h;
    } else {
        ww_sincos(yaw, &uz, &ux);
    }
    fl[0] += w * ux;
    fl[1] += w * (dist > 1e-9 ? d[1] / dist : 0.0);
    fl[2] += w * uz;
}

/* the fear vector of fish i: the sum over the step's threats T of ((R/d)^2 - 1) / 3 for the gap
 * d between fish and the threat's surface (inverse-square, zero at R, 1 at R/2, unbounded as d
 * shrinks), along the unit vector away from it: horizontal as the XZ direction (the heading
 * when the threat is straight above or below), vertical as the 3D one; its length is the fear.
 * The threats' distances are tested all at once, and only those within reach summed, in order.
 * With R at most the least gap nothing is ever near */
static void fear(const ww_scene *sc, const ww_state *st, const threats *T, int i, double fl[3]) {
    const ww_fish_desc *f = &sc->fish;
    const double *p = st->fish_pos + 3 * i;
    double yaw = st->fish_yaw[i], R = f->avoid;
    fl[0] = fl[1] = fl[2] = 0.0;
    if (!(R > 0.0) || !(R > FLEE_MIN_GAP)) return;
    double d2[FISH_LANES];
    squared_distances(&T->at, p, d2);
    for (int k = 0; k < T->at.n; k++) {
        if (d2[k] > T->far2[k]) continue;
        double d[3];
        ww_m_sub3(p, T->centre[k], d);
        add_fear_near(d, T->r[k], R, yaw, fl);
    }
}

/* ---- steering: worked out for every swimming fish before any moves -------------------------- */

/* A fish's steering reads only its own state, the threats and the lure, and no fish's move
 * changes any of these but the lure's being free (a bite, a catch): so each step works out the
 * steering of every swimming fish first, its trigonometry in lanes, and the fish then move in
 * order, each pushed by those before it where they moved to. A fish whose lure test has changed
 * since is steered again from its goal before the lure (steering.base), alone. */
typedef struct steering {
    int lured;                     /* lure_free when the steering was worked out */
    double base[2][FISH_LANES];    /* the unit goal direction (x, z) from the fish's mode alone */
    double u[2][FISH_LANES];       /* after the lure, the fear and the way home: unit */
    double fl[3][FISH_LANES];      /* the fear vector */
    double alarm[FISH_LANES];      /* its length, at most 1 */
    double goal0[FISH_LANES];      /* wander: the goal heading after the step's jitter */
    double goal[FISH_LANES];       /* wander: the goal heading kept within 90 degrees of yaw */
    double yaw0[FISH_LANES];       /* the heading before the turn, rad */
    double yaw[FISH_LANES];        /* after it */
    double turn[FISH_LANES];       /* the turn, rad */
    double cruise[FISH_LANES];     /* the fish's cruising speed, m/s */
    double y_want[FISH_LANES];     /* the depth it heads for, m */
    double py[FISH_LANES];         /* its y, m */
    double want_v[3][FISH_LANES];  /* the velocity it wants before the others' push and its fear */
} steering;

/* what every lane of the steering reads the same */
typedef struct steer_params {
    double dt, turn_rate, max_speed;
} steer_params;

/* the goal direction from fish i's mode: wander's jittered heading (its direction is made in
 * lanes, wander_bases) or the direction to its target, a new one drawn when it is reached */
static void goal_from_mode(const ww_scene *sc, ww_state *st, uint64_t rng, int i, steering *S) {
    const ww_fish_desc *f = &sc->fish;
    double *p = st->fish_pos + 3 * i;
    if (f->mode == WW_FISH_WANDER) {
        double goal = st->fish_goal[i];
        goal += f->jitter * sqrt(sc->dt) * sqrt(3.0) * (2.0 * draw(rng, i, K_JITTER) - 1.0);
        if (draw(rng, i, K_BIG) < f->big_turn_rate * sc->dt)
            goal += f->big_turn * (2.0 * draw(rng, i, K_BIG_ANGLE) - 1.0);
        S->goal0[i] = wrap_pi(goal);
        return;
    }
    double *t = st->fish_target + 3 * i, d[3];
    ww_m_sub3(t, p, d);
    if (ww_m_len3(d) < f->reach) {
        st->fish_reached[i] += 1.0;
        new_target(sc, st, rng, i);
        ww_m_sub3(t, p, d);
    }
    unit_or_heading(d[0], d[2], 1e-9, st->fish_yaw[i], &S->base[0][i], &S->base[1][i]);
}

/* the unit XZ direction fish i wants (S->u), from its mode's goal direction, the lure (when
 * lured: a free floating lure nearby wins over the mode) and its fear vector */
static void aim(const ww_scene *sc, const ww_state *st, int lured, int i, steering *S) {
    const ww_fish_desc *f = &sc->fish;
    const double *p = st->fish_pos + 3 * i;
    double g[2] = {S->base[0][i], S->base[1][i]};
    if (lured) {
        double dx = st->lure_pos[0] - p[0], dz = st->lure_pos[2] - p[2], h = len2(dx, dz);
        if (h < sc->rod.attract && h > 1e-9) {
            g[0] = dx / h;
            g[1] = dz / h;
        }
    }

    /* away from the boat, the cubes and the camera */
    g[0] += AVOID_WEIGHT * S->fl[0][i];
    g[1] += AVOID_WEIGHT * S->fl[2][i];

    /* back into the region near its edge */
    const double *center = school_center(f, i);
    double cx = center[0] - p[0], cz = center[2] - p[2], r = len2(cx, cz), R = school_radius(f, i);
    if (r > HOME_START * R) {
        double w = HOME_WEIGHT * (r - HOME_START * R) / ((1.0 - HOME_START) * R);
        g[0] += w * cx / r;
        g[1] += w * cz / r;
    }
    unit_or_heading(g[0], g[1], 1e-12, st->fish_yaw[i], &S->u[0][i], &S->u[1][i]);
}

/* selects on the bits (core/select.h), so that the loops vectorise: x < lo ? lo : x > hi ? hi :
 * x, and a's wrap into [-pi, pi) */
WW_LANE_STEP double clamp_lane(double x, double lo, double hi) {
    return ww_pick(ww_mask(x < lo), lo, ww_pick(ww_mask(x > hi), hi, x));
}
/* floor q, but +0 for -0 (which wrap_lane's a - 2 pi floor q cannot tell apart): below 2^52 q
 * rounded to a whole number by adding and taking away 2^52 with its sign, less 1 where that
 * went up; from 2^52 on (and for an infinity or a NaN) q itself. GCC vectorises no floor
 * under -ftrapping-math */
WW_LANE_STEP double floor_lane(double q) {
    const uint64_t sign = 0x8000000000000000u;
    uint64_t u = ww_sc_bits(q);
    double big = ww_sc_double(ww_sc_bits(0x1p52) | (u & sign));
    double n = (q + big) - big;
    n = n - ww_pick(ww_mask(n > q), 1.0, 0.0);
    return ww_pick(ww_mask((int64_t)(u & ~sign) < 0x4330000000000000), n, q);
}
WW_LANE_STEP double wrap_lane(double a) {
    int64_t mag = (int64_t)(ww_sc_bits(a) & ~0x8000000000000000u);
    return ww_pick(ww_mask(mag < 0x4008000000000000), a, /* |a| < 3 */
                        a - WW_TAU * floor_lane((a + WW_PI) / WW_TAU));
}

/* fish k's bounded turn toward its goal direction (faster when frightened), its wander goal
 * kept within 90 degrees of the new heading, and the velocity it wants: along the heading (a
 * burst toward max_speed when frightened, not slowed by a turn then) and toward the wanted
 * depth. The same operations as a fish's own step with branches, so the same bits */
WW_LANE_STEP void steer_lane(const steer_params *P, steering *S, int k) {
    double alarm = S->alarm[k], yaw0 = S->yaw0[k], dt = P->dt;
    double want = ww_atan2(S->u[1][k], S->u[0][k]);
    double rate = P->turn_rate * (1.0 + WW_FISH_FLEE_TURN * alarm);
    double turn = clamp_lane(wrap_lane(want - yaw0), -rate * dt, rate * dt);
    double yaw = wrap_lane(yaw0 + turn);
    S->turn[k] = turn;
    S->yaw[k] = yaw;
    double off = clamp_lane(wrap_lane(S->goal0[k] - yaw), -0.5 * WW_PI, 0.5 * WW_PI);
    S->goal[k] = wrap_lane(yaw + off);

    double cruise = S->cruise[k];
    double speed = cruise + (P->max_speed - cruise) * alarm;
    double sw, cw, sy, cy; /* sw unused: ww_sincos gives both */
    ww_sincos(wrap_lane(want - yaw), &sw, &cw);
    double ahead = ww_pick(ww_mask(cw > 0.0), cw, 0.0); /* fmax(0, cw) */
    double slow = SLOW_TURN_MIN + (1.0 - SLOW_TURN_MIN) * ahead;
    speed *= slow + (1.0 - slow) * alarm;
    double vy_max = VERTICAL_MAX * cruise;
    ww_sincos(yaw, &sy, &cy);
    S->want_v[0][k] = speed * cy;
    S->want_v[1][k] = clamp_lane(VERTICAL_GAIN * (S->y_want[k] - S->py[k]), -vy_max, vy_max);
    S->want_v[2][k] = speed * sy;
}

/* the lanes' steps, over nb blocks of 8 */
static WW_LANES void wander_bases(steering *restrict S, int nb) {
    for (int b = 0; b < nb; b++)
        for (int j = 0; j < 8; j++) {
            int k = 8 * b + j;
            ww_sincos(S->goal0[k], &S->base[1][k], &S->base[0][k]);
        }
}
/* wander's depth: the fish's cruising depth plus swim[0] sin(2 pi t / T + its phase) */
static WW_LANES void wander_depths(steering *restrict S, const double *restrict depth,
                                   const double *restrict phase, double amplitude, double w,
                                   int nb) {
    for (int b = 0; b < nb; b++)
        for (int j = 0; j < 8; j++) {
            int k = 8 * b + j;
            S->y_want[k] = depth[k] + amplitude * sine(w + phase[k]);
        }
}
static WW_LANES void steer_lanes(const steer_params *restrict P, steering *restrict S, int nb) {
    for (int b = 0; b < nb; b++)
        for (int j = 0; j < 8; j++) steer_lane(P, S, 8 * b + j);
}
/* a coordinated turn's bank from the yaw rate: atan(|v_xz| rate / g), within +-max_bank */
static WW_LANES void banks(const double *restrict vx, const double *restrict vz,
                           const double *restrict rate, double max_bank, double *restrict bank,
                           int nb) {
    for (int b = 0; b < nb; b++)
        for (int j = 0; j < 8; j++) {
            int k = 8 * b + j;
            double a = ww_atan(sqrt(vx[k] * vx[k] + vz[k] * vz[k]) * rate[k] / WW_G);
            bank[k] = clamp_lane(a, -max_bank, max_bank);
        }
}

/* the push of the other fish closer than the separation, m/s: every fish's distance tested at
 * once (L: where each is now), then those within the separation in order */
static void separation(const ww_scene *sc, const ww_state *st, const point_lanes *L, uint64_t rng,
                       int i, double push[3]) {
    const ww_fish_desc *f = &sc->fish;
    const double *p = st->fish_pos + 3 * i;
    push[0] = push[1] = push[2] = 0.0;
    if (!(f->separation > 0.0)) return;
    double d2[FISH_LANES], far2 = FAR_THREAT_MARGIN * f->separation * f->separation;
    squared_distances(L, p, d2);
    for (int j = 0; j < f->count; j++) {
        /* surely beyond the separation: passed without the root */
        if (d2[j] > far2 || j == i || st->fish_mode[j] == WW_FISH_AWAY) continue;
        double d[3];
        ww_m_sub3(p, st->fish_pos + 3 * j, d);
        double dist = ww_m_len3(d);
        if (!(dist < f->separation)) continue;
        double u[3];
        if (dist > 1e-9) {
            for (int k = 0; k < 3; k++) u[k] = d[k] / dist;
        } else {
            /* one point: a horizontal direction drawn for the pair, opposite for the two */
            int lo = i < j ? i : j, hi = i < j ? j : i;
            double a = WW_TAU * ww_rng_draw_at(rng, PAIR_BASE + (uint64_t)lo * WW_MAX_FISH +
                                                        (uint64_t)hi);
            double s = i == lo ? 1.0 : -1.0;
            double sa, ca;
            ww_sincos(a, &sa, &ca);
            u[0] = s * ca;
            u[1] = 0.0;
            u[2] = s * sa;
        }
        double m = f->max_speed * (1.0 - dist / f->separation);
        for (int k = 0; k < 3; k++) push[k] += m * u[k];
    }
}

/* what every fish's step reads the same: the lowest the surface reaches (nothing in the fish's
 * step adds a ripple), the velocity filter's rate without fear, the threats (none moves during
 * the fish's step), and where each fish is as lanes */
typedef struct fish_step_consts {
    double lowest;            /* ww_water_lowest, m */
    double calm_filter;       /* 1 - e^(-response dt) */
    const threats *threats;
    const point_lanes *fish;  /* kept by ww_fish_step as each fish moves */
    uint64_t rng;             /* the draws' prefix, fish_rng */
} fish_step_consts;

/* y into the bounds at the fish's (x, z); the velocity into a bound is removed. A fish deeper
 * than the margin below the lowest the surface reaches anywhere needs no query: the bound
 * under the surface cannot act on it, nor can a trough squeeze the bounds (its lower bound is
 * the seabed's, as ww_fish_depth_bounds gives it for any surface at or above that) */
static void keep_in_water(const ww_scene *sc, const ww_state *st, const fish_step_consts *ks,
                          double p[3], double v[3]) {
    double lo, hi, low = ks->lowest;
    ww_fish_depth_bounds(sc, low, &lo, &hi);
    if (!(p[1] <= hi && hi > lo)) ww_fish_depth_bounds(sc, surface(sc, st, p[0], p[2]), &lo, &hi);
    if (p[1] > hi) {
        p[1] = hi;
        if (v[1] > 0.0) v[1] = 0.0;
    }
    if (p[1] < lo) {
        p[1] = lo;
        if (v[1] < 0.0) v[1] = 0.0;
    }
}

/* the steering of every fish that swims this step (those neither away nor fighting) */
static void steer_all(const ww_scene *sc, ww_state *st, const fish_step_consts *ks,
                      const steer_params *P, steering *S) {
    const ww_fish_desc *f = &sc->fish;
    int nb = (f->count + 7) / 8;
    double depth[FISH_LANES], phase[FISH_LANES];
    /* the lanes of the others, and the padding, hold a fish heading along +x, unfrightened */
    for (int k = 0; k < 8 * nb; k++) {
        S->base[0][k] = S->u[0][k] = 1.0;
        S->base[1][k] = S->u[1][k] = 0.0;
        S->fl[0][k] = S->fl[1][k] = S->fl[2][k] = S->alarm[k] = 0.0;
        S->goal0[k] = S->yaw0[k] = S->cruise[k] = S->y_want[k] = S->py[k] = 0.0;
        depth[k] = phase[k] = 0.0;
    }
    S->lured = lure_free(sc, st);
    for (int i = 0; i < f->count; i++) {
        int mode = (int)st->fish_mode[i];
        if (mode == WW_FISH_AWAY || mode == WW_FISH_FIGHTING) continue;
        double fl[3];
        fear(sc, st, ks->threats, i, fl);
        for (int k = 0; k < 3; k++) S->fl[k][i] = fl[k];
        S->alarm[i] = fmin(1.0, ww_m_len3(fl));
        goal_from_mode(sc, st, ks->rng, i, S);
        S->yaw0[i] = st->fish_yaw[i];
        S->cruise[i] = cruise_speed(f, i);
        S->py[i] = st->fish_pos[3 * i + 1];
        if (f->mode == WW_FISH_TARGETS) {
            S->y_want[i] = st->fish_target[3 * i + 1];
        } else {
            depth[i] = st->fish_cruise[2 * i];
            phase[i] = st->fish_cruise[2 * i + 1];
        }
    }
    if (f->mode == WW_FISH_WANDER) {
        double T = f->swim[1] > 0.0 ? f->swim[1] : 1.0;
        wander_bases(S, nb);
        wander_depths(S, depth, phase, f->swim[0], WW_TAU * st->t / T, nb);
    }
    for (int i = 0; i < f->count; i++) {
        int mode = (int)st->fish_mode[i];
        if (mode != WW_FISH_AWAY && mode != WW_FISH_FIGHTING) aim(sc, st, S->lured, i, S);
    }
    steer_lanes(P, S, nb);
}

/* fish i along its steering S: pushed apart from the others, away from the threats, its
 * velocity filtered toward the one it wants, moved, and kept in the water */
static void swim(const ww_scene *sc, ww_state *st, const fish_step_consts *ks,
                 const steer_params *P, steering *S, int i) {
    const ww_fish_desc *f = &sc->fish;
    double *p = st->fish_pos + 3 * i, *v = st->fish_vel + 3 * i, dt = sc->dt;
    int lured = lure_free(sc, st);
    if (lured != S->lured) { /* a bite or a catch by a fish before it */
        aim(sc, st, lured, i, S);
        steer_lane(P, S, i);
    }
    st->fish_yaw[i] = S->yaw[i];
    if (f->mode == WW_FISH_WANDER) st->fish_goal[i] = S->goal[i];

    double alarm = S->alarm[i], fl[3] = {S->fl[0][i], S->fl[1][i], S->fl[2][i]};
    double want_v[3] = {S->want_v[0][i], S->want_v[1][i], S->want_v[2][i]};
    double push[3];
    separation(sc, st, ks->fish, ks->rng, i, push);
    for (int k = 0; k < 3; k++) want_v[k] += push[k] + f->max_speed * fl[k];
    double n = ww_m_len3(want_v);
    if (n > f->max_speed)
        for (int k = 0; k < 3; k++) want_v[k] *= f->max_speed / n;

    /* seed 000's first-order filter (quicker when frightened), the change of velocity bounded
     * by WW_FISH_MAX_ACCEL dt, then move */
    double a = alarm == 0.0 ? ks->calm_filter
                            : -expm1(-(f->response + FLEE_RESPONSE * alarm) * dt), dv[3];
    for (int k = 0; k < 3; k++) dv[k] = (want_v[k] - v[k]) * a;
    double dvn = ww_m_len3(dv);
    if (dvn > WW_FISH_MAX_ACCEL * dt)
        for (int k = 0; k < 3; k++) dv[k] *= WW_FISH_MAX_ACCEL * dt / dvn;
    for (int k = 0; k < 3; k++) {
        v[k] += dv[k];
        p[k] += v[k] * dt;
    }
    keep_in_water(sc, st, ks, p, v);
    st->fish_yaw_rate[i] = S->turn[i] / dt; /* its bank: banks(), once every fish has moved */
}

/* the mouth toward the hook, the heading wiggling about the bite's direction, tau into the
 * fight: the fish dashes there at WW_FISH_DASH from where it bit (a fish 2.5 m under the lure
 * used to be there in one frame), then holds it */
static void anchor(const ww_scene *sc, ww_state *st, const fish_step_consts *ks, int i,
                   double tau) {
    const ww_fish_desc *f = &sc->fish;
    double *p = st->fish_pos + 3 * i, *v = st->fish_vel + 3 * i;
    double yaw0 = st->fish_yaw[i];
    double yaw = wrap_pi(st->fish_goal[i] + f->wiggle[0] * sine(WW_TAU * f->wiggle[1] * tau));
    double half = 0.5 * body_length(f, i), sy, cy;
    ww_sincos(yaw, &sy, &cy);
    double q[3] = {st->lure_pos[0] - half * cy, st->lure_pos[1] - sc->rod.hook_depth,
                   st->lure_pos[2] - half * sy};
    double d[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]}, dn = ww_m_len3(d);
    double reach = WW_FISH_DASH * sc->dt, u = dn > reach ? reach / dn : 1.0;
    for (int k = 0; k < 3; k++) {
        v[k] = u * d[k] / sc->dt;
        p[k] += u * d[k];
    }
    keep_in_water(sc, st, ks, p, v);
    st->fish_yaw[i] = yaw;
    st->fish_yaw_rate[i] = wrap_pi(yaw - yaw0) / sc->dt;
    st->fish_bank[i] = 0.0;
}

static void bite(const ww_scene *sc, ww_state *st, const fish_step_consts *ks, int i) {
    const ww_fish_desc *f = &sc->fish;
    const double *p = st->fish_pos + 3 * i;
    st->fish_mode[i] = WW_FISH_FIGHTING;
    st->fish_timer[i] = 0.0;
    st->fish_fight[i] = f->fight[0] + (f->fight[1] - f->fight[0]) * draw(ks->rng, i, K_FIGHT);
    st->fish_goal[i] = ww_atan2(st->lure_pos[2] - p[2], st->lure_pos[0] - p[0]);
    st->rod_fish[0] = (double)i;
    st->lure_state[0] = WW_LURE_HOOKED;
    ww_emit(sc, st, WW_SE_BITE, i, p, 0.0, (double)i);
    anchor(sc, st, ks, i, 0.0);
}

/* fighting on the line, the float tugged under (the rod's step floated it on the surface) and the
 * hook with it; caught when the fight's time is up */
/* one step of fish i's fight; returns 1 where a tug starts, with the fish thrashing at the float:
 * the caller adds that splash after every fish has moved, as the step's lowest surface (ks) has
 * no ripple added during it */
static int fight(const ww_scene *sc, ww_state *st, const fish_step_consts *ks, int i) {
    const ww_fish_desc *f = &sc->fish;
    double tau = st->fish_timer[i] += sc->dt;
    double s = sine(WW_TAU * WW_FISH_TUG_HZ * tau);
    st->lure_pos[1] -= s > 0.0 ? WW_FISH_TUG_DEPTH * s * s : 0.0;
    double was = tau - sc->dt;
    long k = (long)floor(2.0 * WW_FISH_TUG_HZ * tau);
    long k0 = was > 0.0 ? (long)floor(2.0 * WW_FISH_TUG_HZ * was) : -1;
    int tug = k != k0 && k % 2 == 0;
    anchor(sc, st, ks, i, tau);
    if (tau < st->fish_fight[i]) return tug;

    st->fish_caught[0] += 1.0;
    ww_emit(sc, st, WW_SE_CATCH, i, st->fish_pos + 3 * i, st->fish_caught[0], 0.0);
    st->fish_mode[i] = WW_FISH_AWAY;
    st->fish_timer[i] = f->respawn;
    ww_rod_reel(sc, st);
    return tug;
}

void ww_fish_step(const ww_scene *sc, ww_state *st) {
    const ww_fish_desc *f = &sc->fish;
    /* the calm filter as swim works it out at alarm 0, to the bit */
    threats T;
    point_lanes L;
    threats_of_step(sc, st, &T);
    for (int i = 0; i < f->count; i++) lanes_set(&L, i, st->fish_pos + 3 * i);
    lanes_pad(&L, f->count);
    fish_step_consts ks = {.lowest = ww_water_lowest(sc, st),
                           .calm_filter = -expm1(-(f->response + FLEE_RESPONSE * 0.0) * sc->dt),
                           .threats = &T, .fish = &L, .rng = fish_rng(sc, st)};
    steer_params P = {.dt = sc->dt, .turn_rate = f->turn_rate, .max_speed = f->max_speed};
    steering S;
    steer_all(sc, st, &ks, &P, &S);
    int banked[WW_MAX_FISH] = {0}; /* swam and did not bite: banks from its turn */
    double splash[2] = {NAN, NAN}; /* where a fighting fish's tug splashes this step */
    for (int i = 0; i < f->count; i++) {
        switch ((int)st->fish_mode[i]) {
        case WW_FISH_AWAY:
            st->fish_timer[i] -= sc->dt;
            if (st->fish_timer[i] <= 0.0) spawn(sc, st, ks.rng, i, f->count, 0);
            break;
        case WW_FISH_FIGHTING:
            if (sc->rod.on && (int)st->lure_state[0] == WW_LURE_HOOKED &&
                (int)st->rod_fish[0] == i) {
                if (fight(sc, st, &ks, i)) {
                    splash[0] = st->lure_pos[0];
                    splash[1] = st->lure_pos[2];
                }
                break;
            }
            /* the line was reeled in under it */
            st->fish_mode[i] = WW_FISH_SWIMMING;
            ww_emit(sc, st, WW_SE_FISH_ESCAPE, i, st->fish_pos + 3 * i, 0.0, 0.0);
            break;
        default:
            swim(sc, st, &ks, &P, &S, i);
            banked[i] = 1;
            if (lure_free(sc, st) &&
                len2(st->lure_pos[0] - st->fish_pos[3 * i],
                     st->lure_pos[2] - st->fish_pos[3 * i + 2]) < sc->rod.bite_radius) {
                bite(sc, st, &ks, i);
                banked[i] = 0;
            }
            break;
        }
        lanes_set(&L, i, st->fish_pos + 3 * i);
    }

    /* no fish's velocity or yaw rate changes after its own move */
    int nb = (f->count + 7) / 8;
    double vx[FISH_LANES], vz[FISH_LANES], rate[FISH_LANES], bank[FISH_LANES];
    for (int k = 0; k < 8 * nb; k++) {
        int on = k < f->count && banked[k];
        vx[k] = on ? st->fish_vel[3 * k] : 0.0;
        vz[k] = on ? st->fish_vel[3 * k + 2] : 0.0;
        rate[k] = on ? st->fish_yaw_rate[k] : 0.0;
    }
    banks(vx, vz, rate, f->max_bank, bank, nb);
    for (int i = 0; i < f->count; i++)
        if (banked[i]) st->fish_bank[i] = bank[i];
    if (!isnan(splash[0]))
        ww_ripples_add(sc, st, splash[0], splash[1], WW_FISH_TUG_SPLASH * sc->rod.splash);
}
