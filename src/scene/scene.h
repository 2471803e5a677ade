/* scene.h - the compiled scene: immutable after load (the "model" of MuJoCo's model/data pair).
 *
 * Call order:
 *   ww_scene *sc = NULL; ww_error err = {0};
 *   ww_scene_load(path, sets, nsets, &sc, &err);   // parse YAML, apply --set, compile, validate
 *   (or ww_scene_load_with_script(path, script_path, sets, nsets, &sc, &err))
 *   ... ww_state_new(sc) / ww_step(sc, st) / ww_render_frame(r, sc, st) ...
 *   ww_scene_free(sc);                              // the caller frees what load returned
 *
 * Units: SI (m, s, kg/m^3); angles are stored in radians (the file says degrees); colours are
 * linear RGB. The script timeline is sorted by time and lives inside the scene.
 */
#ifndef WW_SCENE_H
#define WW_SCENE_H

#include <stddef.h>
#include <stdint.h>

#include "core/error.h"
#include "scene/desc_boat.h"
#include "scene/desc_cubes.h"
#include "scene/desc_fishing.h"
#include "scene/desc_floaters.h"
#include "scene/desc_reef.h"
#include "scene/desc_audio.h"
#include "scene/desc_golden.h"
#include "scene/desc_render.h"
#include "scene/desc_stones.h"

#define WW_MAX_WAVES 256
#define WW_MAX_RIPPLES 256
#define WW_MAX_KEYS 256
#define WW_MAX_EVENTS 1024
#define WW_MAX_WARNINGS 8

/* what a load reads, capped so that no input asks for unbounded memory or time (README,
 * "Limits"): past a cap the load stops with WW_E_RANGE naming the file, and the scene line that
 * named it. The caps of the files a scene names are in scene/assets.h and scene/obj.h. */
#define WW_SCENE_MAX_BYTES ((size_t)4 << 20) /* a scene or --script file, bytes */
#define WW_SCENE_MAX_NODES 262144            /* YAML keys and values of one file with its --set */

/* limits shared by the scene and the command line, so that neither accepts what the other
 * refuses */
#define WW_TIME_MAX 1e9          /* s: time.start, camera key times, event times */
#define WW_DURATION_MAX 1e7      /* s: time.duration */
#define WW_FPS_MAX 1000.0        /* frames/s: time.fps */
#define WW_SIZE_MIN 16           /* px: render.size, --size, each side */
#define WW_SIZE_MAX 16384

/* water.waves.model. Every family is a list of components (ww_wave) evaluated by src/sim/waves.h
 * and shaders/gerstner.glsl; the model decides the profile of each component:
 *   FLAT        no components
 *   GERSTNER    x' = x + Q A D cos(phi), y = A sin(phi)                          (seed 000)
 *   SINES       y = A sin(phi), no sideways motion (Q = 0)                        (seeds 001, 004)
 *   STEEP_SINES y = 2 A (((sin(phi) + 1) / 2)^e - mean_e), no sideways motion     (seed 001)
 *   SPECTRUM    Gerstner components sampled from a wave spectrum at load (scene/spectrum.h) */
typedef enum ww_wave_model {
    WW_WAVES_FLAT = 0,
    WW_WAVES_GERSTNER,
    WW_WAVES_SINES,
    WW_WAVES_STEEP_SINES,
    WW_WAVES_SPECTRUM
} ww_wave_model;

typedef struct ww_wave {
    double direction;    /* heading of travel in the XZ plane, rad (0 = +x, 90 deg = +z) */
    double dir[2];       /* unit direction (cos, sin) of the heading */
    double wavelength;   /* m */
    double amplitude;    /* m */
    double steepness;    /* Gerstner Q, 0..1 (dimensionless); 0 for sines and steep sines */
    double exponent;     /* steep sines: sharpness e >= 1 (seed 001's k); 1 for the others */
    double mean;         /* mean of ((sin + 1) / 2)^e over a period (from the exponent); steep
                          * sines subtract it so the surface rests at the water level (seed 001's
                          * formula raises it). Only the steep_sines model reads it. */
    double phase;        /* phase offset, rad */
    double k;            /* wavenumber 2 pi / wavelength, 1/m */
    double omega;        /* angular frequency, rad/s: sqrt(g k) unless speed is given */
    double speed;        /* phase speed omega / k, m/s */
    int line, column;    /* where the component was written (or the section it was drawn from) */
} ww_wave;

/* water.waves.random: components drawn from seeded distributions (stream WW_RNG_WAVES), added
 * after the list for the gerstner, sines and steep_sines models */
typedef struct ww_wave_random {
    int count;             /* 0: none */
    double wavelength[2];  /* m, drawn log-uniformly in [lo, hi] */
    double amplitude[2];   /* m, drawn uniformly in [lo, hi] */
    double direction;      /* mean heading, rad */
    double spread;         /* headings uniform in direction +- spread / 2, rad */
    double steepness;      /* Q of each drawn component (gerstner) */
    double exponent;       /* e of each drawn component (steep_sines) */
} ww_wave_random;

typedef enum ww_spectrum_kind { WW_SPECTRUM_PM = 0, WW_SPECTRUM_JONSWAP } ww_spectrum_kind;

/* water.waves.spectrum (model: spectrum); see scene/spectrum.h for the formulas */
typedef struct ww_spectrum_desc {
    ww_spectrum_kind kind;
    double wind_speed;     /* m/s: U at 19.5 m (Pierson-Moskowitz), U at 10 m (JONSWAP) */
    double fetch;          /* m (JONSWAP) */
    double gamma;          /* peak enhancement factor (JONSWAP), 1..10 */
    double direction;      /* mean heading, rad */
    double spread;         /* standard deviation of the headings, rad */
    int count;             /* components */
    double wavelength[2];  /* sampled range, m */
    double steepness;      /* global sum Q k A over the components, < 1 so it cannot fold */
} ww_spectrum_desc;

/* water.fold: what loading does when sum Q k A > 1 (the Gerstner surface loops over itself) */
typedef enum ww_fold_policy { WW_FOLD_WARN = 0, WW_FOLD_ERROR, WW_FOLD_CLAMP } ww_fold_policy;
#define WW_FOLD_CLAMP_SUM 0.9 /* clamp scales every Q so that sum Q k A is this (margin 0.1) */

/* water.ripples: seed 000's damped radial waves, one per splash or script event:
 *   h = A0 e^(-alpha r) e^(-beta age) sin(kr (r - v age)) W(r, age)
 * with W a causal front that is 1 behind r = v age and 0 one ripple wavelength ahead of it
 * (seed 000's formula has no front: it fills the whole lake at once). See sim/ripples.h. */
typedef struct ww_ripple_desc {
    double amplitude;      /* A0 of a ripple whose event gives none, m */
    double lifetime;       /* s; older ripples are pruned */
    int max;               /* pool size; a full pool replaces its oldest ripple */
    double radial_decay;   /* alpha, 1/m */
    double time_decay;     /* beta, 1/s */
    double wavenumber;     /* kr (seed 000's omega, which multiplies r - v t), rad/m */
    double speed;          /* v, m/s: capillary-gravity phase speed of kr unless given */
    double spray;          /* the splash's droplets drawn (gfx/splash.h): 0 none, 1 as made */
} ww_ripple_desc;

/* time.integrator: how the systems of the scripted world advance their motion over a step.
 * EXACT (default): closed forms where they exist (boat speed, stone parabola, spring cubes), the
 * energy-keeping midpoint rule for Archimedes cubes, RK4 for stones with drag. EULER: the seeds'
 * semi-implicit Euler (v += a dt, then x += v dt), kept as the baseline `bench sim` measures the
 * exact integrators against. */
typedef enum ww_integrator { WW_INTEGRATE_EXACT = 0, WW_INTEGRATE_EULER } ww_integrator;

typedef enum ww_interp { WW_INTERP_CATMULL_ROM = 0, WW_INTERP_LINEAR } ww_interp;

typedef struct ww_camera_key {
    double t;            /* simulated time, s */
    double position[3];  /* m */
    int has_look_at;     /* 1: look_at holds the target; 0: yaw/pitch hold the direction */
    double look_at[3];   /* m */
    double yaw, pitch;   /* rad; yaw 0 looks along -z, positive turns toward +x; pitch up */
    double fov;          /* vertical field of view, rad (0: the camera's default) */
} ww_camera_key;

/* script actions; the payload of each (value, at, v, index, flags) is documented by the system
 * that reads it (sim/<system>.h) */
typedef enum ww_event_kind {
    WW_EV_TIME_OF_DAY = 0, /* set the clock */
    WW_EV_RIPPLE,          /* add a ripple */
    WW_EV_THROW,           /* throw a stone (sim/stones.h) */
    WW_EV_CAST,            /* cast the rod (sim/rod.h) */
    WW_EV_BOAT,            /* boat throttle and steering until a time (sim/boat.h) */
    WW_EV_CAMERA_MODE,     /* camera: free | boat (sim/boat.h) */
    WW_EV_PRESS,           /* press a cube (sim/cubes.h) */
    WW_EV_CHEST            /* force a chest spawn (sim/chest.h) */
} ww_event_kind;

typedef struct ww_event {
    double t;            /* simulated time, s */
    int64_t step;        /* first step whose time is >= t */
    ww_event_kind kind;
    double value;        /* TIME_OF_DAY: hours 0..24; RIPPLE: amplitude A0, m */
    double at[2];        /* RIPPLE: centre (x, z), m */
    double v[8];         /* the other actions' numbers */
    int index;           /* the other actions' object index */
    int flags;           /* the other actions' options */
    int line, column;    /* where it was written, for messages */
    int in_script;       /* written in the --script file (ww_scene.script_path), not the scene */
} ww_event;

typedef enum ww_tonemap_op { WW_TONEMAP_EXP = 0, WW_TONEMAP_ACES } ww_tonemap_op;

/* the simulation's systems: X(ID, name, present, object) with `present` an expression of the
 * compiled scene `sc`, and `object` 1 for the systems of the scripted world (they emit
 * simulation events: a scene with one has the events outbox, ww_scene_has_objects). This list
 * makes the ww_system enum, the names `plan` prints, and sc->system_on (ww_scene_plan_systems:
 * decided once, when the scene is compiled); sim/systems.c runs them in its own order. The
 * collision needs something solid for the camera to meet. */
#define WW_SYSTEM_LIST(X)                                                                         \
    X(CLOCK, "clock", 1, 0)                      /* sky clock: time of day, sun, sky colours */  \
    X(CAMERA, "camera", 1, 0)                    /* camera path */                               \
    X(WAVES, "waves", sc->nwaves > 0, 0)         /* wave phases */                               \
    X(SCRIPT, "script", sc->nevents > 0, 0)      /* script events */                             \
    X(RIPPLES, "ripples", sc->ripples_on, 0)     /* the ripple pool */                           \
    X(CUBES, "cubes", sc->cubes.on, 1)           /* floating cubes */                            \
    X(FLOATERS, "floaters", sc->floaters.on, 1)  /* floating models */                           \
    X(STONES, "stones", sc->stones.on, 1)        /* thrown stones */                             \
    X(ROD, "rod", sc->rod.on, 1)                 /* rod and lure */                              \
    X(FISH, "fish", sc->fish.on, 1)              /* fish */                                      \
    X(CHEST, "chest", sc->chest.on, 1)           /* treasure chest */                            \
    X(BUBBLES, "bubbles", sc->bubbles.on, 1)     /* air bubbles */                               \
    X(BOAT, "boat", sc->boat.on, 1)              /* the boat */                                  \
    X(COLLIDE, "collide", sc->camera_collide && ww_scene_has_solids(sc), 0) /* camera collision */

typedef enum ww_system {
#define WW_SYS_ENUM(id, name, present, object) WW_SYS_##id,
    WW_SYSTEM_LIST(WW_SYS_ENUM)
#undef WW_SYS_ENUM
    WW_SYS_COUNT
} ww_system;

typedef struct ww_scene {
    char path[256];            /* file it came from */
    char name[64];             /* file name without folder and extension */
    char script_path[256];     /* the --script file merged into the timeline, "" for none */
    uint64_t seed;

    /* time */
    double dt;                 /* step, s */
    double fps;                /* frames per simulated second */
    double duration;           /* s */
    double start;              /* simulated time of frame 0 (and of step 0), s */
    ww_integrator integrator;  /* time.integrator */
    int64_t steps_per_frame;   /* 1 / (fps dt), checked to be an integer at load */
    int64_t frame_count;       /* round(duration fps) */

    /* render */
    int width, height;         /* px */
    double exposure;           /* tone mapping exposure E */
    double gamma;              /* display gamma */
    ww_tonemap_op tonemap;
    int dither;                /* an ordered dither of one level before the 8-bit rounding */

    /* sky */
    double time_of_day;        /* hours at start, 0..24 */
    double day_length;         /* simulated seconds per 24 h; 0 keeps the clock still */
    double sun_max_elevation;  /* elevation of the sun at noon, rad */

    /* how it is drawn: the passes' switches and knobs, sky model, fog below, water optics,
     * lights (scene/desc_render.h) */
    ww_render_desc render;
    struct ww_assets *assets;  /* decoded files the scene names (scene/assets.h); NULL: none;
                                * owned, freed by ww_scene_free */

    /* fog above water (exp2) */
    double fog_color[3];       /* linear RGB; all < 0 means "use the sky horizon colour" */
    double fog_density;        /* 1/m */

    /* water */
    double water_level;        /* y of the rest plane, m */
    double water_depth;        /* m */
    double water_color[3];     /* deep-water scattering colour, linear RGB */
    ww_wave_model wave_model;
    int nwaves;
    ww_wave waves[WW_MAX_WAVES];
    ww_wave_random wave_random;
    ww_spectrum_desc spectrum;
    ww_fold_policy fold;
    double fold_sum;           /* sum Q k A of the components as loaded (after a clamp) */
    double fold_sum_given;     /* the same before the policy was applied */
    int ripples_on;            /* the scene has a ripples section or ripple events */
    ww_ripple_desc ripples;

    /* what loading noticed but accepted (fold: warn); the CLI prints them to stderr */
    int nwarnings;
    char warnings[WW_MAX_WARNINGS][256];

    /* camera */
    double fov;                /* default vertical field of view, rad */
    double near_clip, far_clip;/* m */
    ww_interp interp;
    int ncam;
    ww_camera_key cam[WW_MAX_KEYS];

    /* the scripted world: each system exists only when its `on` is set */
    ww_cubes_desc cubes;
    ww_boat_desc boat;
    ww_stones_desc stones;
    ww_rod_desc rod;
    ww_fish_desc fish;
    ww_chest_desc chest;
    ww_bubbles_desc bubbles;
    ww_models_desc models;
    ww_floaters_desc floaters; /* objects.models[].float (compile_floaters.c) */
    int camera_collide;        /* camera.collide: the camera stops at solid objects */

    /* what comes out besides the frames */
    ww_audio_desc audio;       /* audio: the sound track of render --audio */
    ww_golden_desc golden;     /* golden: thresholds and accepted renderers of render --golden */

    /* script timeline, sorted by t (stable for equal times) */
    int nevents;
    ww_event events[WW_MAX_EVENTS];

    /* the systems this scene has: what the simulation steps and `plan` prints */
    int system_on[WW_SYS_COUNT];
} ww_scene;

/* one --set KEY=VALUE as given on the command line */
typedef struct ww_set {
    const char *text;          /* "water.waves.list[1].amplitude=0.2" */
} ww_set;

ww_result ww_scene_load(const char *path, const ww_set *sets, int nsets, ww_scene **out,
                        ww_error *err);
/* the same with a script file (`--script FILE`, NULL: none): a YAML mapping whose only key is
 * `script:`, a list of events as in the scene; its events follow the scene's and the merged list
 * is sorted stably by time (scene events first at equal times). Its errors name the script file
 * with line and column. */
ww_result ww_scene_load_with_script(const char *path, const char *script_path, const ww_set *sets,
                                    int nsets, ww_scene **out, ww_error *err);
/* same from a string in memory; name is used in messages in place of a file name */
ww_result ww_scene_load_string(const char *name, const char *text, size_t len, const ww_set *sets,
                               int nsets, ww_scene **out, ww_error *err);
void ww_scene_free(ww_scene *sc);

/* every default of the file format: what an empty scene file loads as (no waves, no events,
 * the default camera key). For code that builds a scene without a file (tests, tools). */
void ww_scene_defaults(ww_scene *sc);

/* a wave's derived fields (dir, k, omega, speed, mean) from its direction, wavelength and
 * exponent; speed is the phase speed in m/s, or <= 0 for deep-water dispersion w^2 = g k */
void ww_wave_derive(ww_wave *w, double speed);

/* something the camera cannot pass through: the boat, cubes, the chest, models */
static inline int ww_scene_has_solids(const ww_scene *sc) {
    return sc->boat.on || sc->cubes.on || sc->chest.on || sc->models.count > 0;
}

/* any system of the scripted world is on (WW_SYSTEM_LIST's objects: they emit simulation
 * events), or a model (models block the camera, which logs it) */
static inline int ww_scene_has_objects(const ww_scene *sc) {
#define WW_SYS_OBJECT(id, name, present, object)                                                  \
    if ((object) && (present)) return 1;
    WW_SYSTEM_LIST(WW_SYS_OBJECT)
#undef WW_SYS_OBJECT
    return sc->models.count > 0;
}

/* decide which systems the scene has (sc->system_on) from its sections: done once at the end
 * of compiling; code that edits a compiled scene's sections (tests, tools) calls it again */
void ww_scene_plan_systems(ww_scene *sc);
const char *ww_system_name(ww_system s);

/* the model's word in the scene format: "gerstner", "sines", ...; the words, by model, NULL
 * last (scene/wave.c) */
const char *ww_wave_model_name(ww_wave_model m);
extern const char *const ww_wave_model_words[];

/* sum Q k A over the components: above 1 the Gerstner surface folds */
double ww_waves_fold_sum(const ww_scene *sc);

/* time of frame f, s */
static inline double ww_scene_frame_time(const ww_scene *sc, int64_t f) {
    return sc->start + (double)(f * sc->steps_per_frame) * sc->dt;
}

#endif
