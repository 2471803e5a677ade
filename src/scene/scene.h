/* scene.h - the compiled scene: immutable after load (the "model" of MuJoCo's model/data pair).
 *
 * Call order:
 *   ww_scene *sc = NULL; ww_error err = {0};
 *   ww_scene_load(path, sets, nsets, &sc, &err);   // parse YAML, apply --set, compile, validate
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

#define WW_MAX_WAVES 64
#define WW_MAX_KEYS 256
#define WW_MAX_EVENTS 1024

typedef enum ww_wave_model { WW_WAVES_FLAT = 0, WW_WAVES_GERSTNER } ww_wave_model;

typedef struct ww_wave {
    double direction;    /* heading of travel in the XZ plane, rad (0 = +x, 90 deg = +z) */
    double dir[2];       /* unit direction (cos, sin) of the heading */
    double wavelength;   /* m */
    double amplitude;    /* m */
    double steepness;    /* Gerstner Q, 0..1 (dimensionless) */
    double phase;        /* phase offset, rad */
    double k;            /* wavenumber 2 pi / wavelength, 1/m */
    double omega;        /* angular frequency, rad/s: sqrt(g k) unless speed is given */
    double speed;        /* phase speed omega / k, m/s */
} ww_wave;

typedef enum ww_interp { WW_INTERP_CATMULL_ROM = 0, WW_INTERP_LINEAR } ww_interp;

typedef struct ww_camera_key {
    double t;            /* simulated time, s */
    double position[3];  /* m */
    int has_look_at;     /* 1: look_at holds the target; 0: yaw/pitch hold the direction */
    double look_at[3];   /* m */
    double yaw, pitch;   /* rad; yaw 0 looks along -z, positive turns toward +x; pitch up */
    double fov;          /* vertical field of view, rad (0: the camera's default) */
} ww_camera_key;

typedef enum ww_event_kind { WW_EV_TIME_OF_DAY = 0 } ww_event_kind;

typedef struct ww_event {
    double t;            /* simulated time, s */
    int64_t step;        /* first step whose time is >= t */
    ww_event_kind kind;
    double value;        /* TIME_OF_DAY: hours 0..24 */
    int line, column;    /* where it was written, for messages */
} ww_event;

typedef enum ww_tonemap_op { WW_TONEMAP_EXP = 0, WW_TONEMAP_ACES } ww_tonemap_op;

typedef struct ww_scene {
    char path[256];            /* file it came from */
    char name[64];             /* file name without folder and extension */
    uint64_t seed;

    /* time */
    double dt;                 /* step, s */
    double fps;                /* frames per simulated second */
    double duration;           /* s */
    double start;              /* simulated time of frame 0 (and of step 0), s */
    int64_t steps_per_frame;   /* 1 / (fps dt), checked to be an integer at load */
    int64_t frame_count;       /* round(duration fps) */

    /* render */
    int width, height;         /* px */
    double exposure;           /* tone mapping exposure E */
    double gamma;              /* display gamma */
    ww_tonemap_op tonemap;

    /* sky */
    double time_of_day;        /* hours at start, 0..24 */
    double day_length;         /* simulated seconds per 24 h; 0 keeps the clock still */
    double sun_max_elevation;  /* elevation of the sun at noon, rad */

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

    /* camera */
    double fov;                /* default vertical field of view, rad */
    double near_clip, far_clip;/* m */
    ww_interp interp;
    int ncam;
    ww_camera_key cam[WW_MAX_KEYS];

    /* script timeline, sorted by t (stable for equal times) */
    int nevents;
    ww_event events[WW_MAX_EVENTS];
} ww_scene;

/* one --set KEY=VALUE as given on the command line */
typedef struct ww_set {
    const char *text;          /* "water.waves.list[1].amplitude=0.2" */
} ww_set;

ww_result ww_scene_load(const char *path, const ww_set *sets, int nsets, ww_scene **out,
                        ww_error *err);
/* same from a string in memory; name is used in messages in place of a file name */
ww_result ww_scene_load_string(const char *name, const char *text, size_t len, const ww_set *sets,
                               int nsets, ww_scene **out, ww_error *err);
void ww_scene_free(ww_scene *sc);

/* every default of the file format: what an empty scene file loads as (no waves, no events,
 * the default camera key). For code that builds a scene without a file (tests, tools). */
void ww_scene_defaults(ww_scene *sc);

/* a wave's derived fields (dir, k, omega, speed) from its direction and wavelength; speed is
 * the phase speed in m/s, or <= 0 for deep-water dispersion w^2 = g k */
void ww_wave_derive(ww_wave *w, double speed);

/* time of frame f, s */
static inline double ww_scene_frame_time(const ww_scene *sc, int64_t f) {
    return sc->start + (double)(f * sc->steps_per_frame) * sc->dt;
}

#endif
