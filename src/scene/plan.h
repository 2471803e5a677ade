/* plan.h - what a scene needs: which systems run and which render passes exist.
 * Compiled from a ww_scene (plain data, no GL); the renderer creates exactly these passes and the
 * simulation allocates exactly these systems. `waterworld plan SCENE` prints it.
 *
 *   ww_plan p; ww_plan_build(sc, &p); ww_plan_print(&p, stdout);
 */
#ifndef WW_PLAN_H
#define WW_PLAN_H

#include <stdio.h>

#include "scene/scene.h"

/* in the order they run; each exists only when the scene needs it (ww_plan_build) */
typedef enum ww_pass_id {
    WW_PASS_SKYMAP = 0, /* Preetham's sky and its clouds into a small map the others sample */
    WW_PASS_SHADOW,     /* sun depth map (render.shadows, with geometry to cast) */
    WW_PASS_PREPASS,    /* colour + depth of solid geometry for the water's refraction */
    WW_PASS_REFLECTION, /* the scene mirrored about the water plane (render.reflection) */
    WW_PASS_MAIN,       /* HDR: sky, lit geometry, water */
    WW_PASS_BLOOM,      /* bright pass + separable Gaussian, half resolution */
    WW_PASS_SHAFTS,     /* radial blur toward the sun over the depth-masked scene */
    WW_PASS_TONEMAP,    /* HDR (+ bloom + shafts) -> sRGB8 */
    WW_PASS_FXAA,       /* edge anti-aliasing of the sRGB8 image */
    WW_PASS_UPSCALE,    /* the sRGB8 image scaled up to the frame's size (render.scale < 1) */
    WW_PASS_HUD,        /* text and markers drawn into the last sRGB8 image (no target) */
    WW_PASS_COUNT
} ww_pass_id;

/* DEPTH24_STENCIL8: the prepass takes it instead of DEPTH24 only when the sun's shadows are
 * stencilled (render.shadows projected or volumes); the main pass also when it shades the water
 * from its G-buffer (the RGBA32F pair, and a stencil bit for the water's pixels) */
typedef enum ww_format {
    WW_FMT_RGBA16F = 0,
    WW_FMT_DEPTH24,
    WW_FMT_RGBA8,
    WW_FMT_DEPTH24_STENCIL8,
    WW_FMT_RGBA32F
} ww_format;

#define WW_PLAN_MAX_TARGETS 4

typedef struct ww_target_desc {
    const char *name;
    ww_format format;
    int width, height;
} ww_target_desc;

typedef struct ww_pass_desc {
    ww_pass_id id;
    const char *name;
    const char *what;                      /* one line for `plan` */
    int ntargets;                          /* 0: draws into an earlier pass's image */
    ww_target_desc targets[WW_PLAN_MAX_TARGETS];
    /* per target, > 1: a multisampled buffer that the pass draws into and resolves into its
     * plain targets (MSAA, render.msaa); 0 for the plain ones */
    int samples[WW_PLAN_MAX_TARGETS];
    /* per target, 1: a texture of the pass that its framebuffer does not hold (the pass draws
     * into it through a framebuffer of its own: the water's G-buffer) */
    int unattached[WW_PLAN_MAX_TARGETS];
} ww_pass_desc;

/* the water mesh (gfx/water.c): a static polar grid re-centred on the camera. Its rings are
 * WW_WATER_S0 apart at the centre and their spacing grows geometrically (by q per ring) so that
 * WW_WATER_RINGS rings reach WW_WATER_REACH x the far clip; the plan needs the same numbers to say
 * where the mesh becomes too coarse for a wave. */
#define WW_WATER_SEGMENTS 256 /* vertices around each ring, at render.grid 1 */
#define WW_WATER_RINGS 160    /* rings around the centre vertex, at render.grid 1 */
#define WW_WATER_S0 0.5       /* distance of the first ring from the centre, m, at render.grid 1 */
#define WW_WATER_REACH 0.9    /* outer ring radius as a fraction of the far clip */
#define WW_WATER_SNAP 0.5     /* the mesh centre moves on this grid, m */
#define WW_WATER_INNER_R 10.0 /* rings inside this radius are always drawn whole, m */

/* the shaders fade a component of wavelength L out where the sample spacing s grows from L / 4 to
 * L / 2 (shaders/gerstner.glsl, ww_wave_fade: at least 4 samples per wavelength) */
#define WW_FADE_START_SAMPLES 4.0
#define WW_FADE_END_SAMPLES 2.0

/* the sky map (pass skymap, gfx/pass_skymap.c): every direction's sky, WIDTH azimuths x HEIGHT
 * elevations, the rows spaced by the square root of the elevation so the horizon's haze band
 * gets the most of them (shaders/common.glsl, ww_sky_map_uv). The clear sky is smooth; a sky
 * with clouds gets twice the texels each way, for their edges in the water's reflection (demo's
 * frame 0 at 1280x720: 37.2 dB against the per-pixel sky at 256x128, 44.0 dB at 512x256) */
#define WW_SKY_MAP_WIDTH 256
#define WW_SKY_MAP_HEIGHT 128
#define WW_SKY_MAP_CLOUDS 2 /* the factor on both with sky.clouds.cover > 0 */

typedef struct ww_water_mesh {
    int rings;      /* WW_WATER_RINGS x render.grid */
    int segments;   /* WW_WATER_SEGMENTS x render.grid, a multiple of 8 */
    double s0;      /* first ring spacing, m (WW_WATER_S0 / render.grid) */
    double q;       /* ring growth per ring (1: evenly spaced) */
    double dtheta;  /* angle between neighbouring vertices of a ring, rad */
    double reach;   /* radius of the outer ring, m */
} ww_water_mesh;

/* the mesh for a far clip distance and a density factor (render.grid; 0 reads as 1): rings and
 * segments scale by grid and the first ring's spacing by 1 / grid */
void ww_water_mesh_layout(double far_clip, double grid, ww_water_mesh *m);
/* sample spacing of the mesh at distance r from its centre: rings s0 + (q - 1) r apart, r dtheta
 * around a ring; the larger one */
double ww_water_mesh_spacing(const ww_water_mesh *m, double r);
/* the smallest distance from the mesh centre where the spacing reaches s; INFINITY past the mesh */
double ww_water_mesh_distance_for(const ww_water_mesh *m, double s);
/* the most the surface can rise above or sink below its rest level, m: every component at its
 * crest at once, and the largest ripple on top */
double ww_water_crest(const ww_scene *sc);
/* the distance from the mesh centre beyond which the water vertex shader fades every wave and
 * ripple out (gerstner.glsl: a component is gone where the spacing reaches half its wavelength),
 * so the mesh lies flat at the rest level there; INFINITY if it never does within the mesh */
double ww_water_flat_beyond(const ww_scene *sc, const ww_water_mesh *m);

/* how one consumer of the wave field thins it with distance: each component is evaluated whole
 * up to where it starts to fade and not at all beyond where it is faded out */
#define WW_PLAN_FADE_STEPS 6
typedef struct ww_plan_fade {
    int components;                   /* evaluated where nothing is faded */
    double start;                     /* m: the shortest component starts to fade beyond this
                                       * (INFINITY: not within the mesh) */
    int nsteps;                       /* faded[i] components are faded out beyond beyond[i] m:
                                       * each count up to 6 components, else 1, n/4, n/2, 3n/4, n */
    int faded[WW_PLAN_FADE_STEPS];
    double beyond[WW_PLAN_FADE_STEPS];
} ww_plan_fade;

typedef struct ww_plan_water {
    ww_wave_model model;
    int components;         /* wave components every consumer starts from */
    double shortest, longest; /* wavelengths, m */
    ww_water_mesh mesh;
    double pixel_angle;     /* angle of one pixel at the image centre at the scene's fov, rad */
    int image_height;       /* px, what the pixel angle is for */
    ww_plan_fade vertex;    /* water vertex shader: faded by the mesh spacing */
    ww_plan_fade fragment;  /* fragment shader: faded by the pixel footprint across the view */
    int ripple_pool;        /* pool entries (0: no ripples) */
    double ripple_wavelength;               /* m */
    double ripple_vertex_out, ripple_fragment_out; /* m: ripples faded out beyond */
    double flat_beyond;     /* m: the mesh lies flat beyond (ww_water_flat_beyond) */
} ww_plan_water;

typedef struct ww_plan {
    int system_on[WW_SYS_COUNT];
    int geometry;      /* the scene has solid geometry (objects, models, seabed) to draw */
    int npasses;
    ww_pass_desc passes[WW_PASS_COUNT];
    ww_plan_water water;
} ww_plan;

/* the passes for frames of width x height: drawn at render.scale of that size, the last
 * sRGB8 image scaled up to it */
void ww_plan_build(const ww_scene *sc, int width, int height, ww_plan *p);
/* 1 when the scene's sky is drawn from the sky map (pass skymap): Preetham's sky (sky.model
 * preetham, or dome without a picture), unless the environment sets WW_SKY_EXACT=1, which
 * evaluates it per pixel as before (comparisons, the map's own error) */
int ww_sky_map_on(const ww_scene *sc);
/* the planned pass id, or NULL */
const ww_pass_desc *ww_plan_pass(const ww_plan *p, ww_pass_id id);
/* the index of d's target called name, or -1 (d may be NULL) */
int ww_plan_target(const ww_pass_desc *d, const char *name);
size_t ww_format_bytes_per_pixel(ww_format f);
const char *ww_format_name(ww_format f);
void ww_plan_print(const ww_scene *sc, const ww_plan *p, FILE *to);

#endif
