/* test_fishing.c - the rod, lure and fish against closed forms and invariants: the lure's flight
 * with exponential drag against its closed form, the landing at the exact crossing at any dt and
 * speed (no tunnelling through crests), floating on the surface, at most one fish per cast, a
 * cast that must end in a bite and a catch, depth and speed bounds over a long run, two fish
 * spawned at one point, targets reached with a bounded turn rate, determinism, the loader.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/mathx.h"
#include "sim/events.h"
#include "sim/fish.h"
#include "sim/ripples.h"
#include "sim/rod.h"
#include "sim/state.h"
#include "sim/step.h"
#include "sim/water.h"
#include "test.h"

/* the stepped flight against the closed form: the update is exact, so only rounding differs */
#define LURE_FLIGHT_TOL 1e-9
/* the landing point against the closed-form crossing of a flat sea (bisection to 2^-60 dt) */
#define LURE_LANDING_TOL 1e-9
/* the floating lure's height above the exact surface against rod.float_height */
#define LURE_FLOAT_TOL 1e-9
/* how far under the surface the flight arc may dip before the reported landing: the sweep
 * samples every WW_LURE_SWEEP_STEP of chord, so only a crest narrower than that could hide;
 * the waves here are metres long, so the arc must stay above to rounding */
#define LURE_ARC_DIP_TOL 1e-9
/* a fish's height against its bounds (the clamp is exact) and its speed against max_speed */
#define FISH_BOUND_TOL 1e-9
#define FISH_SPEED_TOL 1e-12
/* a fighting fish's mouth against the lure: one rounding of the anchor */
#define FISH_MOUTH_TOL 1e-12
/* a fight of a second or more reaches this share of the tug's depth at 60 steps a second */
#define TUG_REACHED 0.95
/* the tugs' splashes of a fight against 1 + its length times WW_FISH_TUG_HZ: the last tug may
 * or may not have started when the fish is caught */
#define TUG_SPLASH_ONSETS_TOL 1.0
/* the yaw rate against turn_rate: one rounding of the clamp, rad/s */
#define FISH_TURN_RATE_TOL 1e-9

static ww_scene *load(const char *text) { return ww_test_scene_text("fishing.yaml", text); }

static int step_ok(const ww_scene *sc, ww_state *st) {
    ww_error err = {0};
    ww_result r = ww_step(sc, st, &err);
    ENSURE_MSG(r == WW_OK, "step %lld: %s", (long long)st->step, err.msg);
    return r == WW_OK;
}

/* how many events of kind k the last step emitted; the first one's entry in *e */
static int events_of(const ww_scene *sc, const ww_state *st, int kind, const double **e) {
    int n = 0;
    for (int i = 0; i < ww_events_count(sc, st); i++) {
        const double *x = st->events + i * WW_SIM_EVENT_STRIDE;
        if ((int)x[0] != kind) continue;
        if (n++ == 0 && e) *e = x;
    }
    return n;
}

static double surface(const ww_scene *sc, const ww_state *st, double x, double z) {
    ww_water_sample w;
    ww_water_at(sc, st, x, z, 0.0, &w);
    return w.height;
}

/* the closed form of dv/dt = g - k v, written out here independently of rod.c */
static void closed_form(const double p0[3], const double v0[3], double g, double k, double t,
                        double p[3]) {
    double e = exp(-k * t);
    p[0] = p0[0] + v0[0] * (1.0 - e) / k;
    p[1] = p0[1] + (v0[1] + g / k) * (1.0 - e) / k - g * t / k;
    p[2] = p0[2] + v0[2] * (1.0 - e) / k;
}

/* ---- rod and lure ------------------------------------------------------------------------- */

static const char *FLAT_CAST =
    "seed: 5\n"
    "time: {dt: %s, fps: %s, duration: 6}\n"
    "water: {waves: {model: flat}}\n"
    "objects: {rod: {drag: 0.5, gravity: 1, float_height: 0.02}}\n"
    "script:\n"
    "  - {t: 0.5, cast: {speed: %g, angle: %g, from: [1, 4, -2], heading: 30}}\n";

/* runs the flat cast; returns the landing x, z (NAN when it never landed) and checks the flight */
static void flat_cast(const char *dt, const char *fps, double speed, double angle_deg,
                      double land[2]) {
    char text[1024];
    snprintf(text, sizeof text, FLAT_CAST, dt, fps, speed, angle_deg);
    ww_scene *sc = load(text);
    land[0] = land[1] = NAN;
    if (!sc) return;
    ww_state *st = ww_state_new(sc);
    double a = ww_m_rad(angle_deg), h = ww_m_rad(30.0), k = 0.5, g = WW_G;
    double p0[3] = {1, 4, -2};
    double v0[3] = {speed * cos(a) * cos(h), speed * sin(a), speed * cos(a) * sin(h)};
    int64_t cast_step = sc->events[0].step;
    while (st->t < 6.0 && step_ok(sc, st)) {
        if (st->step < cast_step) continue;
        if ((int)st->lure_state[0] == WW_LURE_FLYING) {
            double p[3];
            closed_form(p0, v0, g, k, (double)(st->step - cast_step + 1) * sc->dt, p);
            for (int i = 0; i < 3; i++) ENSURE_NEAR(st->lure_pos[i], p[i], LURE_FLIGHT_TOL);
        } else if (events_of(sc, st, WW_SE_LURE_LAND, NULL)) {
            land[0] = st->lure_pos[0];
            land[1] = st->lure_pos[2];
            /* floating on the sea and its own splash */
            ENSURE_NEAR(st->lure_pos[1] - surface(sc, st, land[0], land[1]), 0.02, LURE_FLOAT_TOL);
            break;
        }
    }
    ww_state_free(st);
    ww_scene_free(sc);
}

/* the crossing of y = 0 by the closed form, by bisection on time */
static void closed_form_landing(double speed, double angle_deg, double land[2]) {
    double a = ww_m_rad(angle_deg), h = ww_m_rad(30.0), k = 0.5, g = WW_G;
    double p0[3] = {1, 4, -2};
    double v0[3] = {speed * cos(a) * cos(h), speed * sin(a), speed * cos(a) * sin(h)};
    double lo = 0.0, hi = 100.0, p[3];
    for (int i = 0; i < 200; i++) {
        double m = 0.5 * (lo + hi);
        closed_form(p0, v0, g, k, m, p);
        if (p[1] > 0.0) lo = m;
        else hi = m;
    }
    closed_form(p0, v0, g, k, hi, p);
    land[0] = p[0];
    land[1] = p[2];
}

TEST(fishing_lure_flight_matches_drag_closed_form) {
    double got[2], want[2];
    flat_cast("1/120", "30", 12.0, 30.0, got);
    closed_form_landing(12.0, 30.0, want);
    ENSURE_NEAR(got[0], want[0], LURE_LANDING_TOL);
    ENSURE_NEAR(got[1], want[1], LURE_LANDING_TOL);
    /* drag shortens the cast: the range without drag is longer */
    double vx = 12.0 * cos(ww_m_rad(30.0)), vy = 12.0 * sin(ww_m_rad(30.0));
    double t_nodrag = (vy + sqrt(vy * vy + 2.0 * WW_G * 4.0)) / WW_G;
    ENSURE(hypot(want[0] - 1.0, want[1] + 2.0) < vx * t_nodrag);
}

TEST(fishing_lure_lands_at_the_same_point_at_any_dt_and_speed) {
    /* dt from 1/240 to 1/15 and a 300 m/s cast down at 60 degrees: one step crosses metres */
    const char *dts[][2] = {{"1/240", "30"}, {"1/60", "30"}, {"1/15", "15"}};
    double cases[][2] = {{12.0, 30.0}, {300.0, -60.0}, {4.0, -5.0}};
    for (int c = 0; c < 3; c++) {
        double want[2];
        closed_form_landing(cases[c][0], cases[c][1], want);
        for (int d = 0; d < 3; d++) {
            double got[2];
            flat_cast(dts[d][0], dts[d][1], cases[c][0], cases[c][1], got);
            ENSURE_NEAR(got[0], want[0], LURE_LANDING_TOL);
            ENSURE_NEAR(got[1], want[1], LURE_LANDING_TOL);
        }
    }
}

static const char *WAVY =
    "seed: 9\n"
    "time: {dt: 1/15, fps: 15, duration: 20}\n"
    "water:\n"
    "  waves:\n"
    "    list:\n"
    "      - {direction: 0, wavelength: 4, amplitude: 0.3, steepness: 0.3}\n"
    "      - {direction: 60, wavelength: 9, amplitude: 0.05, steepness: 0.4}\n"
    "objects: {rod: {drag: 0.3, window: 6, float_height: 0.03}}\n"
    "camera:\n"
    "  path:\n"
    "    - {t: 0, position: [0, 2, 10], look_at: [0, 0, 0]}\n"
    "script:\n"
    "  - {t: 1, cast: {speed: 60, angle: 0, from: [%g, 0.2, 0], heading: 0}}\n"
    "  - {t: 8, cast: {speed: 5, angle: 30, from: [0, 1.5, 0], heading: 90}}\n";

/* a fast flat cast skims over 4 m waves at dt = 1/15: each step spans a wavelength, so its ends
 * can both be above the water with a crest between them. The arc must be above the surface
 * everywhere before the landing, and after it the lure floats at float_height until reeled in.
 * Started at several places along the wave. Returns the flight time of the first cast. */
static double wavy_cast(double x0) {
    /* casts: 60 m/s flat along +x from (x0, 0.2, 0); 5 m/s at 30 degrees along +z */
    char text[2048];
    snprintf(text, sizeof text, WAVY, x0);
    ww_scene *sc = load(text);
    if (!sc) return NAN;
    ww_state *st = ww_state_new(sc);
    ww_state *prev = ww_state_new(sc);
    int lands = 0, reels = 0, floating_steps = 0;
    double worst_dip = 0.0, flight = NAN;
    while (st->t < 16.0) {
        ww_state_copy(prev, st);
        if (!step_ok(sc, st)) break;
        int state = (int)st->lure_state[0];
        /* where this step's arc began: the cast's start, or the last step's end */
        const double *cast = NULL;
        double p0[3], v0[3];
        for (int i = 0; i < 3; i++) {
            p0[i] = prev->lure_pos[i];
            v0[i] = prev->lure_vel[i];
        }
        if (events_of(sc, st, WW_SE_ROD_CAST, &cast)) {
            int second = lands > 0;
            double a = ww_m_rad(second ? 30.0 : 0.0), sp = second ? 5.0 : 60.0;
            for (int i = 0; i < 3; i++) p0[i] = cast[2 + i];
            v0[0] = second ? 0.0 : sp * cos(a);
            v0[1] = sp * sin(a);
            v0[2] = second ? sp * cos(a) : 0.0;
        }
        int landed = events_of(sc, st, WW_SE_LURE_LAND, NULL);
        if (cast || (int)prev->lure_state[0] == WW_LURE_FLYING) {
            /* sample the step's arc finely, up to the landing point if it landed */
            double g[3] = {0, -WW_G, 0}, p[3], v[3], d0[3], span = INFINITY;
            ww_m_sub3(st->lure_pos, p0, d0);
            if (landed) span = hypot(d0[0], d0[2]);
            /* the surface the flight met: this step's waves, the ripples before the splash */
            ww_field before = {.sc = sc, .phase = st->wave_phase, .t = st->t,
                               .ripples = prev->ripple};
            for (int j = 1; j <= 2000; j++) {
                ww_rod_flight(p0, v0, g, 0.3, sc->dt * j / 2000.0, p, v);
                if (hypot(p[0] - p0[0], p[2] - p0[2]) >= span) break;
                ww_water_sample w;
                ww_water_height(&before, p[0], p[2], NULL, &w);
                worst_dip = fmin(worst_dip, p[1] - w.height);
            }
        }
        if (landed) {
            if (lands == 0) flight = st->rod_line_time[0];
            lands++;
        }
        if (state == WW_LURE_FLOATING || state == WW_LURE_HOOKED) {
            floating_steps++;
            double h = surface(sc, st, st->lure_pos[0], st->lure_pos[2]);
            ENSURE_NEAR(st->lure_pos[1] - h, 0.03, LURE_FLOAT_TOL);
            ENSURE(st->lure_pos[1] > h);
        }
        reels += events_of(sc, st, WW_SE_REEL, NULL);
    }
    ENSURE_NEAR(worst_dip, 0.0, LURE_ARC_DIP_TOL);
    ENSURE_EQ_INT(lands, 2);
    ENSURE_EQ_INT(reels, 2); /* each window ran out */
    ENSURE(floating_steps > 10 * 15);
    ww_state_free(prev);
    ww_state_free(st);
    ww_scene_free(sc);
    return flight;
}

TEST(fishing_lure_never_tunnels_and_floats_on_waves) {
    printf("  flight times of a flat 60 m/s cast from x0 =");
    for (int k = 0; k < 8; k++) printf(" %.2f", wavy_cast(0.5 * k));
    printf(" s\n");
}

/* a charged cast from the camera: starts at the camera plus (forward, right, up) offset, flies
 * along the camera's flattened forward at the mapped angle and speed */
TEST(fishing_cast_from_the_camera) {
    ww_scene *sc = load("time: {dt: 1/120, fps: 30, duration: 3}\n"
                        "water: {waves: {model: flat}}\n"
                        "objects: {rod: {angle: [10, 40], speed: [6, 16], drag: 0.4,"
                        " offset: [0.5, 0.3, -0.2]}}\n"
                        "camera: {path: [{t: 0, position: [2, 3, 4], look_at: [2, 0, 0]}]}\n"
                        "script: [{t: 0.5, cast: {charge: 1}}]\n");
    if (!sc) return;
    ww_state *st = ww_state_new(sc);
    const double *e = NULL;
    while (st->t < 2.0 && step_ok(sc, st) && !events_of(sc, st, WW_SE_ROD_CAST, &e)) {}
    ENSURE(e != NULL);
    if (e) {
        /* forward flattened: -z; right of -z (y up) is +x */
        double start[3] = {2.0 + 0.3, 3.0 - 0.2, 4.0 - 0.5};
        for (int i = 0; i < 3; i++) ENSURE_NEAR(e[2 + i], start[i], LURE_FLIGHT_TOL);
        ENSURE_NEAR(e[5], 16.0, 0.0);
        double a = ww_m_rad(10.0), v0[3] = {0.0, 16.0 * sin(a), -16.0 * cos(a)}, p[3];
        closed_form(start, v0, WW_G, 0.4, sc->dt, p);
        for (int i = 0; i < 3; i++) ENSURE_NEAR(st->lure_pos[i], p[i], LURE_FLIGHT_TOL);
    }
    ww_state_free(st);
    ww_scene_free(sc);
}

TEST(fishing_charge_maps_longer_holds_to_flatter_faster_casts) {
    ww_scene *sc = load("objects: {rod: {angle: [10, 40], speed: [6, 16]}}\n");
    if (!sc) return;
    double a0, s0, a1, s1, ah, sh;
    ww_rod_charge_map(&sc->rod, 0.0, &a0, &s0);
    ww_rod_charge_map(&sc->rod, 1.0, &a1, &s1);
    ww_rod_charge_map(&sc->rod, 0.5, &ah, &sh);
    ENSURE_NEAR(ww_m_deg(a0), 40.0, 1e-12);
    ENSURE_NEAR(ww_m_deg(a1), 10.0, 1e-12);
    ENSURE_NEAR(s0, 6.0, 1e-12);
    ENSURE_NEAR(s1, 16.0, 1e-12);
    ENSURE_NEAR(ww_m_deg(ah), 25.0, 1e-12);
    ENSURE_NEAR(sh, 11.0, 1e-12);
    ww_scene_free(sc);
}

/* ---- fishing ------------------------------------------------------------------------------ */

/* a cast from (0, 1.5, 0) toward +x at 8 m/s, 20 degrees, lands near x = 7.5: the fish live in a
 * disc of radius 2.5 around it, within the attraction radius, so a bite must come */
static const char *POND =
    "seed: 11\n"
    "time: {dt: 1/60, fps: 30, duration: 40}\n"
    "water:\n"
    "  depth: 6\n"
    "  waves: {list: [{direction: 0, wavelength: 10, amplitude: 0.1, steepness: 0.5}]}\n"
    "objects:\n"
    "  rod: {window: 10, bite_radius: 1.0, attract: 8}\n"
    "  fish: {count: %d, center: [7.5, -1.5, 0], radius: %g, fight: [1, 3], respawn: 4}\n"
    "camera:\n"
    "  path:\n"
    "    - {t: 0, position: [0, 2, -20], look_at: [7, 0, 0]}\n"
    "script:\n"
    "  - {t: 1, cast: {speed: 8, angle: 20, from: [0, 1.5, 0], heading: 0}}\n"
    "  - {t: 15, cast: {speed: 8, angle: 20, from: [0, 1.5, 0], heading: 0}}\n";

typedef struct fishing_log {
    int casts, lands, bites, catches, reels, escapes;
    double t_land[2], t_bite[2], t_catch[2];
    int most_fighting;
    double max_fight_step; /* the longest step of a fighting fish over WW_FISH_DASH dt */
    double dip[2];         /* the least and the most the float was under its floating height
                            * while a fish fought, m */
    int splashes[2];       /* the tugs' splashes of each fight: the ripples of the steps without
                            * a landing ... */
    int splashes_astray;   /* ... and those not at the float or not while a fish fought */
} fishing_log;

static void run_pond(int count, double radius, double until, fishing_log *log) {
    char text[2048];
    snprintf(text, sizeof text, POND, count, radius);
    memset(log, 0, sizeof *log);
    ww_scene *sc = load(text);
    if (!sc) return;
    ww_state *st = ww_state_new(sc);
    double prev[3 * 64];
    ENSURE(count <= 64);
    log->dip[0] = INFINITY;
    log->dip[1] = -INFINITY;
    while (st->t < until && count <= 64) {
        memcpy(prev, st->fish_pos, sizeof(double) * 3 * (size_t)count);
        double t_before = st->t;
        int hooked_before = (int)st->lure_state[0] == WW_LURE_HOOKED;
        if (!step_ok(sc, st)) break;
        /* the ripples this step added (stamped with its end): a tug's splash is at the float,
         * while a fish fights */
        int landed = events_of(sc, st, WW_SE_LURE_LAND, NULL); /* its splash, not a tug's */
        for (int r = 0; r < st->ripple_slots[0] && !landed; r++) {
            const double *e = st->ripple + WW_RIPPLE_STRIDE * r;
            if (!(e[3] > 0.0) || e[2] < t_before + 0.5 * sc->dt) continue;
            ENSURE_NEAR(e[3], WW_FISH_TUG_SPLASH * sc->rod.splash, 0.0);
            int hooked = hooked_before || (int)st->lure_state[0] == WW_LURE_HOOKED;
            if (hooked && e[0] == st->lure_pos[0] && e[1] == st->lure_pos[2] && log->bites > 0 &&
                log->bites <= 2)
                log->splashes[log->bites - 1]++;
            else
                log->splashes_astray++;
        }
        const double *e = NULL;
        log->casts += events_of(sc, st, WW_SE_ROD_CAST, NULL);
        if (events_of(sc, st, WW_SE_LURE_LAND, NULL) && log->lands < 2)
            log->t_land[log->lands++] = st->t;
        int b = events_of(sc, st, WW_SE_BITE, &e), bitten = b ? (int)e[6] : -1;
        if (b) {
            ENSURE_EQ_INT(b, 1);
            ENSURE_EQ_INT((int)st->rod_fish[0], (int)e[6]);
            if (log->bites < 2) log->t_bite[log->bites] = st->t;
            log->bites += b;
        }
        int c = events_of(sc, st, WW_SE_CATCH, &e);
        if (c) {
            ENSURE_NEAR(e[5], st->fish_caught[0], 0.0);
            if (log->catches < 2) log->t_catch[log->catches] = st->t;
            log->catches += c;
        }
        log->reels += events_of(sc, st, WW_SE_REEL, NULL);
        log->escapes += events_of(sc, st, WW_SE_FISH_ESCAPE, NULL);
        int fighting = 0;
        for (int i = 0; i < count; i++) {
            if (st->fish_mode[i] != WW_FISH_FIGHTING) continue;
            fighting++;
            if (i == bitten) continue; /* it swam, then bit: two moves in this step */
            /* it dashes to the hook at WW_FISH_DASH, never faster; once there, the mouth, half a
             * length ahead of the centre, is at the lure (XZ) */
            const double *p = st->fish_pos + 3 * i, *q = prev + 3 * i;
            double step = sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                               (p[2] - q[2]) * (p[2] - q[2]));
            step /= WW_FISH_DASH * sc->dt;
            if (step > log->max_fight_step) log->max_fight_step = step;
            if (step >= 1.0 - 1e-9) continue; /* still on its way */
            double half = 0.5 * sc->fish.length, yaw = st->fish_yaw[i];
            ENSURE_NEAR(p[0] + half * cos(yaw), st->lure_pos[0], FISH_MOUTH_TOL);
            ENSURE_NEAR(p[2] + half * sin(yaw), st->lure_pos[2], FISH_MOUTH_TOL);
            /* the hook hangs under the float, tugged under with it */
            ENSURE_NEAR(p[1], st->lure_pos[1] - sc->rod.hook_depth, FISH_MOUTH_TOL);
        }
        if (fighting > log->most_fighting) log->most_fighting = fighting;
        if ((int)st->lure_state[0] == WW_LURE_HOOKED) {
            const double *l = st->lure_pos;
            double dip = surface(sc, st, l[0], l[2]) + sc->rod.float_height - l[1];
            log->dip[0] = fmin(log->dip[0], dip);
            log->dip[1] = fmax(log->dip[1], dip);
        }
        ENSURE((int)st->fish_caught[0] == log->catches);
    }
    ww_state_free(st);
    ww_scene_free(sc);
}

TEST(fishing_cast_near_fish_bites_then_catches_within_the_window) {
    fishing_log log;
    run_pond(3, 2.5, 30.0, &log);
    ENSURE_EQ_INT(log.casts, 2);
    ENSURE_EQ_INT(log.lands, 2);
    ENSURE_EQ_INT(log.bites, 2);
    ENSURE_EQ_INT(log.catches, 2);
    ENSURE_EQ_INT(log.reels, 2);
    ENSURE_EQ_INT(log.escapes, 0);
    for (int c = 0; c < 2; c++) {
        /* bite after landing and inside the 10 s window; catch after the bite, within fight hi */
        ENSURE(log.t_bite[c] >= log.t_land[c] && log.t_bite[c] < log.t_land[c] + 10.0);
        ENSURE(log.t_catch[c] - log.t_bite[c] >= 1.0 - 1e-9);
        ENSURE(log.t_catch[c] - log.t_bite[c] <= 3.0 + 1.0 / 60.0);
    }
    /* a fish that bites from below reaches the hook by its dash, not by a jump (it was placed
     * there in one step) */
    ENSURE_MSG(log.max_fight_step <= 1.0 + 1e-9, "a hooked fish jumped %.3f times its dash in "
               "one step", log.max_fight_step);
    /* the fish tugs the float under by up to WW_FISH_TUG_DEPTH, and never lifts it */
    ENSURE_MSG(log.dip[0] >= -LURE_FLOAT_TOL, "the float rose %.3g m over its height", -log.dip[0]);
    ENSURE_MSG(log.dip[1] <= WW_FISH_TUG_DEPTH + LURE_FLOAT_TOL &&
                   log.dip[1] >= TUG_REACHED * WW_FISH_TUG_DEPTH,
               "the float went %.4f m under (tugs %.2f m deep)", log.dip[1], WW_FISH_TUG_DEPTH);
    /* a splash at the float as each tug starts: one at the bite, then one every 1 /
     * WW_FISH_TUG_HZ s of the fight */
    for (int c = 0; c < 2; c++) {
        double tugs = 1.0 + WW_FISH_TUG_HZ * (log.t_catch[c] - log.t_bite[c]);
        ENSURE_MSG(fabs(log.splashes[c] - tugs) <= TUG_SPLASH_ONSETS_TOL,
                   "fight %d: %d splashes for %.2f tugs", c, log.splashes[c], tugs);
    }
    ENSURE_EQ_INT(log.splashes_astray, 0);
    printf("  bites %.3f s and %.3f s after landing, fights %.3f s and %.3f s; longest step on the "
           "line %.3f of the dash's; the float tugged %.4f to %.4f m under, with %d and %d "
           "splashes\n",
           log.t_bite[0] - log.t_land[0], log.t_bite[1] - log.t_land[1],
           log.t_catch[0] - log.t_bite[0], log.t_catch[1] - log.t_bite[1], log.max_fight_step,
           log.dip[0], log.dip[1], log.splashes[0], log.splashes[1]);
}

TEST(fishing_at_most_one_fish_per_cast) {
    /* 40 fish crowd the landing point: still one bite per cast, one fighter at a time */
    fishing_log log;
    run_pond(40, 1.5, 30.0, &log);
    ENSURE_EQ_INT(log.bites, 2);
    ENSURE_EQ_INT(log.catches, 2);
    ENSURE_EQ_INT(log.most_fighting, 1);
}

TEST(fishing_recast_during_a_fight_lets_the_fish_escape) {
    ww_scene *sc = load(
        "seed: 2\n"
        "time: {dt: 1/60, fps: 30, duration: 10}\n"
        "water: {waves: {model: flat}}\n"
        "objects:\n"
        "  rod: {bite_radius: 1.0, attract: 8}\n"
        "  fish: {count: 1, center: [7.5, -1.5, 0], radius: 1, positions: [[7.5, -1.5, 0]],"
        " fight: [5, 5]}\n"
        "script:\n"
        "  - {t: 1, cast: {speed: 8, angle: 20, from: [0, 1.5, 0], heading: 0}}\n"
        "  - {t: 4, cast: {speed: 8, angle: 20, from: [0, 1.5, 0], heading: 180}}\n");
    if (!sc) return;
    ww_state *st = ww_state_new(sc);
    int bites = 0, escapes = 0, catches = 0;
    while (st->t < 6.0 && step_ok(sc, st)) {
        bites += events_of(sc, st, WW_SE_BITE, NULL);
        escapes += events_of(sc, st, WW_SE_FISH_ESCAPE, NULL);
        catches += events_of(sc, st, WW_SE_CATCH, NULL);
    }
    ENSURE_EQ_INT(bites, 1);
    ENSURE_EQ_INT(escapes, 1);
    ENSURE_EQ_INT(catches, 0);
    ENSURE_EQ_INT((int)st->fish_mode[0], WW_FISH_SWIMMING);
    ww_state_free(st);
    ww_scene_free(sc);
}

/* ---- swimming ----------------------------------------------------------------------------- */

/* 30 fish under steep waves in shallow water, a camera flying through them, 120 s at 1/60 */
static const char *SCHOOL =
    "seed: 21\n"
    "time: {dt: 1/60, fps: 30, duration: 120}\n"
    "water:\n"
    "  depth: 3\n"
    "  waves:\n"
    "    list:\n"
    "      - {direction: 20, wavelength: 12, amplitude: 0.4, steepness: 0.7}\n"
    "      - {direction: -35, wavelength: 5, amplitude: 0.1, steepness: 0.5}\n"
    "objects:\n"
    "  fish: {count: 30, center: [0, -1, 0], radius: 6, spread: 2, mode: %s}\n"
    "camera:\n"
    "  path:\n"
    "    - {t: 0, position: [-10, -1, 0], look_at: [0, -1, 0]}\n"
    "    - {t: 60, position: [10, -1, 0], look_at: [20, -1, 0]}\n"
    "    - {t: 120, position: [-10, -1, 0], look_at: [0, -1, 0]}\n";

static void school(const char *mode, int *min_reached, double *worst_turn) {
    char text[2048];
    snprintf(text, sizeof text, SCHOOL, mode);
    ww_scene *sc = load(text);
    if (!sc) return;
    ww_state *st = ww_state_new(sc);
    const ww_fish_desc *f = &sc->fish;
    double far = 0.0, fastest = 0.0;
    *worst_turn = 0.0;
    while (st->t < 120.0 && step_ok(sc, st)) {
        for (int i = 0; i < f->count; i++) {
            const double *p = st->fish_pos + 3 * i, *v = st->fish_vel + 3 * i;
            double lo, hi;
            ww_fish_depth_bounds(sc, surface(sc, st, p[0], p[2]), &lo, &hi);
            ENSURE(p[1] <= hi + FISH_BOUND_TOL && p[1] >= lo - FISH_BOUND_TOL);
            ENSURE(ww_m_len3(v) <= f->max_speed + FISH_SPEED_TOL);
            fastest = fmax(fastest, ww_m_len3(v));
            far = fmax(far, hypot(p[0] - f->center[0], p[2] - f->center[2]));
            *worst_turn = fmax(*worst_turn, fabs(st->fish_yaw_rate[i]));
            ENSURE(fabs(st->fish_bank[i]) <= f->max_bank);
        }
        if (ww_test_failed_now()) break;
    }
    *min_reached = 1 << 30;
    for (int i = 0; i < f->count; i++)
        if ((int)st->fish_reached[i] < *min_reached) *min_reached = (int)st->fish_reached[i];
    printf("  %s: farthest %.2f m from the centre (radius 6), fastest %.3f m/s (max %.1f), "
           "largest yaw rate %.1f deg/s, fewest targets %d\n",
           mode, far, fastest, f->max_speed, ww_m_deg(*worst_turn), *min_reached);
    ENSURE(far < 1.5 * f->radius);
    /* turn_rate, up to (1 + WW_FISH_FLEE_TURN) times it while fleeing the camera */
    ENSURE(*worst_turn <= f->turn_rate * (1.0 + WW_FISH_FLEE_TURN) + FISH_TURN_RATE_TOL);
    ww_state_free(st);
    ww_scene_free(sc);
}

TEST(fishing_fish_stay_in_depth_and_speed_bounds_over_a_long_run) {
    int reached;
    double turn;
    school("wander", &reached, &turn);
    ENSURE_EQ_INT(reached, 0); /* wandering fish have no targets */
}

TEST(fishing_targets_are_reached_with_a_bounded_turn_rate) {
    int reached;
    double turn;
    school("targets", &reached, &turn);
    /* 120 s at about 1.2 m/s across a 12 m disc: every fish reaches several targets */
    ENSURE(reached >= 5);
}

TEST(fishing_two_fish_spawned_at_one_point_separate) {
    ww_scene *sc = load(
        "seed: 4\n"
        "time: {dt: 1/120, fps: 30, duration: 30}\n"
        "objects:\n"
        "  fish: {count: 3, center: [0, -2, 0], radius: 8, separation: 0.8,"
        " positions: [[1, -2, 1], [1, -2, 1], [1, -2, 1]]}\n");
    if (!sc) return;
    ww_state *st = ww_state_new(sc);
    double apart_at = -1.0, closest_after = 1e9;
    while (st->t < 30.0 && step_ok(sc, st)) {
        double closest = 1e9;
        for (int i = 0; i < 3; i++)
            for (int j = i + 1; j < 3; j++) {
                double d[3];
                ww_m_sub3(st->fish_pos + 3 * i, st->fish_pos + 3 * j, d);
                closest = fmin(closest, ww_m_len3(d));
            }
        ENSURE(isfinite(closest));
        if (apart_at < 0.0 && closest > 0.8) apart_at = st->t;
        if (apart_at >= 0.0) closest_after = fmin(closest_after, closest);
    }
    printf("  all pairs beyond the separation after %.3f s; closest afterwards %.3f m\n", apart_at,
           closest_after);
    ENSURE(apart_at > 0.0 && apart_at < 2.0);
    /* the soft push keeps them from meeting again */
    ENSURE(closest_after > 0.4);
    ww_state_free(st);
    ww_scene_free(sc);
}

/* Every swimming fish is steered before any moves; when a fish bites, those after it in the
 * same step must be steered again without the lure. Fish 0 is within the bite radius, fish 1
 * within the lure's attraction but far from fish 0 (no separation push), heading away from the
 * lure, which lies to its right, and its goal to its left. One fish step three ways: the lure taken before the step (fish 1 never
 * sees it), free with fish 0 biting, and free with fish 0 away (fish 1 chases it) */
static const char *LURE_TAKEN_MIDSTEP =
    "seed: 4\n"
    "time: {dt: 1/120, fps: 30, duration: 2}\n"
    "water: {waves: {model: flat}}\n"
    "objects:\n"
    "  rod: {bite_radius: 1.0, attract: 6}\n"
    "  fish: {count: 2, center: [1.5, -2, 0], radius: 30, positions: [[%g, -2, 0], [4, -2, 2]]}\n";

/* fish 1's state after one fish step from the set-up above: lure free or not, fish 0 at x0 */
static void step_with_lure(double x0, int lure_free, ww_state **out, const ww_scene **sc_out) {
    char text[1024];
    snprintf(text, sizeof text, LURE_TAKEN_MIDSTEP, x0);
    ww_scene *sc = load(text);
    *out = NULL;
    *sc_out = sc;
    if (!sc) return;
    ww_state *st = ww_state_new(sc);
    st->lure_pos[0] = 0.0;
    st->lure_pos[1] = 0.02;
    st->lure_pos[2] = 0.0;
    st->lure_state[0] = WW_LURE_FLOATING;
    st->rod_fish[0] = lure_free ? -1.0 : 1e6; /* not free: bitten by a fish that is not here */
    for (int i = 0; i < 2; i++) {
        st->fish_yaw[i] = 0.0;  /* along +x, away from the lure, which lies to its right */
        st->fish_goal[i] = 0.5; /* its goal to the left */
        st->fish_vel[3 * i] = st->fish_vel[3 * i + 1] = st->fish_vel[3 * i + 2] = 0.0;
    }
    ww_fish_step(sc, st);
    *out = st;
}

TEST(fishing_a_bite_takes_the_lure_from_the_fish_after_it_in_the_step) {
    const ww_scene *sa, *sb, *sc;
    ww_state *taken, *bitten, *chased;
    step_with_lure(0.3, 0, &taken, &sa);
    step_with_lure(0.3, 1, &bitten, &sb);
    step_with_lure(-20.0, 1, &chased, &sc);
    if (!taken || !bitten || !chased) return;
    ENSURE_EQ_INT((int)bitten->fish_mode[0], WW_FISH_FIGHTING);
    ENSURE_EQ_INT((int)taken->fish_mode[0], WW_FISH_SWIMMING);
    /* the lure is not fish 1's to chase once fish 0 has it: the same step to the bit as if it
     * had been taken before */
    ENSURE(memcmp(bitten->fish_pos + 3, taken->fish_pos + 3, 3 * sizeof(double)) == 0);
    ENSURE(memcmp(bitten->fish_vel + 3, taken->fish_vel + 3, 3 * sizeof(double)) == 0);
    ENSURE(bitten->fish_yaw[1] == taken->fish_yaw[1] && bitten->fish_goal[1] == taken->fish_goal[1]);
    ENSURE(bitten->fish_bank[1] == taken->fish_bank[1]);
    /* and the lure does pull it where nothing takes it first: it turns the other way */
    printf("  fish 1's yaw rate: %.4f rad/s after the bite, %.4f chasing the lure\n",
           bitten->fish_yaw_rate[1], chased->fish_yaw_rate[1]);
    ENSURE(bitten->fish_yaw_rate[1] > 0.0 && chased->fish_yaw_rate[1] < 0.0);
    ww_state_free(taken);
    ww_state_free(bitten);
    ww_state_free(chased);
    ww_scene_free((ww_scene *)sa);
    ww_scene_free((ww_scene *)sb);
    ww_scene_free((ww_scene *)sc);
}

/* ---- determinism and the loader ----------------------------------------------------------- */

/* the pond with 12 fish after 1800 steps (two casts, catches); printed on a mismatch */
#define FISHING_HASH 0x736b5876c261c9d1ull

TEST(fishing_determinism_and_slices) {
    char text[2048];
    snprintf(text, sizeof text, POND, 12, 4.0);
    ww_scene *sc = load(text);
    if (!sc) return;
    ww_state *a = ww_state_new(sc), *b = ww_state_new(sc), *c = ww_state_new(sc);
    ww_error err = {0};
    ENSURE(ww_sim_advance_to(sc, a, 1800, &err) == WW_OK);
    ENSURE(ww_sim_advance_to(sc, b, 900, &err) == WW_OK);
    ww_state_copy(c, b);
    ENSURE(ww_sim_advance_to(sc, c, 1800, &err) == WW_OK);
    ENSURE_EQ_U64(ww_state_hash(sc, a), ww_state_hash(sc, c));
    ENSURE(a->fish_caught[0] >= 1.0);
    /* pinned: a change of the fishing model changes this on purpose; re-baseline by copying */
    uint64_t h = ww_state_hash(sc, a);
    if (h != FISHING_HASH) printf("  fishing hash after 1800 steps: 0x%016llx\n", (unsigned long long)h);
    ENSURE_EQ_U64(h, FISHING_HASH);
    ww_state_free(a);
    ww_state_free(b);
    ww_state_free(c);
    ww_scene_free(sc);
}

TEST(fishing_loader_payload_and_defaults) {
    ww_scene *sc = load("script:\n"
                        "  - {t: 1, cast: {charge: 0.25}}\n"
                        "  - {t: 2, cast: {speed: 9, angle: 15, from: [1, 2, 3], heading: 90}}\n");
    if (!sc) return;
    ENSURE(sc->rod.on && !sc->fish.on && sc->ripples_on);
    ENSURE_EQ_INT(sc->events[0].flags, WW_CAST_CHARGE);
    ENSURE_NEAR(sc->events[0].v[2], 0.25, 0.0);
    ENSURE_EQ_INT(sc->events[1].flags, WW_CAST_FROM);
    ENSURE_NEAR(sc->events[1].v[0], 9.0, 0.0);
    ENSURE_NEAR(sc->events[1].v[1], ww_m_rad(15.0), 1e-15);
    ENSURE_NEAR(sc->events[1].v[4], 2.0, 0.0);
    ENSURE_NEAR(sc->events[1].v[6], ww_m_rad(90.0), 1e-15);
    ww_scene_free(sc);

    sc = load("objects: {fish: {mode: targets}}\n");
    if (!sc) return;
    ENSURE(sc->fish.on && !sc->rod.on);
    ENSURE_EQ_INT(sc->fish.count, 12);
    ENSURE_EQ_INT(sc->fish.mode, WW_FISH_TARGETS);
    ENSURE_NEAR(sc->fish.radius, 15.0, 0.0);
    ENSURE_NEAR(sc->fish.center[1], -2.0, 0.0);
    ww_scene_free(sc);

    /* no fishing: nothing allocated */
    sc = load("seed: 1\n");
    if (!sc) return;
    ENSURE(!sc->rod.on && !sc->fish.on);
    ENSURE_EQ_INT(WW_N_FISH(sc), 0);
    ENSURE_EQ_INT(WW_N_ROD(sc), 0);
    ww_scene_free(sc);
}
