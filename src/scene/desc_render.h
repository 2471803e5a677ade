/* desc_render.h - how a scene is drawn: the render pipeline's switches and knobs (render.*), the
 * sky model, fog above and below the water, the water's optics (water.look) and the scene's
 * lights. Plain data filled by scene/compile_render.c; scene/plan.c turns the switches into
 * passes and gfx/ reads the knobs. Each feature defaults to what seed 000 draws (every pass on
 * but the HUD; a pass still needs what it works on: no casters, no shadow map); a switched-off
 * feature's pass is not created at all.
 *
 * In the file a feature is `true` / `false` or a mapping of its knobs (which means on, unless
 * it says `on: false`):
 *   render: {shadows: {size: 2048}, reflection: {scale: 0.25}, bloom: false, fxaa: true}
 */
#ifndef WW_DESC_RENDER_H
#define WW_DESC_RENDER_H

#define WW_MAX_LIGHTS 8
#define WW_PATH_MAX 256

typedef enum ww_sky_model {
    WW_SKY_GRADIENT = 0,
    WW_SKY_CUBEMAP,
    WW_SKY_DOME,
    WW_SKY_PREETHAM /* Preetham, Shirley and Smits 1999: the default */
} ww_sky_model;
typedef enum ww_fresnel { WW_FRESNEL_BIAS_SCALE = 0, WW_FRESNEL_SCHLICK } ww_fresnel;
typedef enum ww_light_kind { WW_LIGHT_POINT = 0, WW_LIGHT_SPOT } ww_light_kind;

/* how the sun's shadows are made (docs/rendering.md "Shadows"): the shadow map (seed 000), or
 * seed 003's planar projected shadows on the seabed, or its stencil shadow volumes (optionally
 * drawn themselves, translucent) */
typedef enum ww_shadow_technique {
    WW_SHADOW_MAP = 0,
    WW_SHADOW_PROJECTED,
    WW_SHADOW_VOLUMES,
    WW_SHADOW_VOLUMES_VISIBLE
} ww_shadow_technique;

/* directional shadows from the sun: by default a map, orthographic, fitted to the visible scene */
typedef struct ww_shadow_desc {
    int on;
    ww_shadow_technique technique;
    int size;          /* shadow map texels per side */
    double softness;   /* PCF kernel radius, texels (0: one hardware-filtered tap) */
    double distance;   /* the map covers what the camera sees up to this distance, m */
} ww_shadow_desc;

/* planar reflection (seeds 000, 002): the camera mirrored about the water plane */
typedef struct ww_reflection_desc {
    int on;
    double scale;      /* target size as a fraction of the frame's */
} ww_reflection_desc;

/* bright pass + separable Gaussian bloom, ping-pong at `scale` of the frame (seed 000) */
typedef struct ww_bloom_desc {
    int on;
    double threshold;  /* luminance above which light blooms (after exposure) */
    double strength;   /* how much of the blurred light is added back */
    int passes;        /* horizontal + vertical blur pairs */
    double scale;      /* target size as a fraction of the frame's */
} ww_bloom_desc;

/* light shafts: radial blur toward the projected sun over the depth-masked scene (seed 000,
 * after Mitchell, "Volumetric Light Scattering as a Post-Process", GPU Gems 3 ch. 13) */
typedef struct ww_shafts_desc {
    int on;
    int samples;       /* taps along each pixel's ray toward the sun */
    double decay, density, weight, exposure;
    double underwater; /* factor on exposure when the camera is under water */
    double scale;      /* target size as a fraction of the frame's */
} ww_shafts_desc;

/* how caustics are drawn: the focusing of the wave field's curvature per pixel, or seed 003's
 * looped set of caustic textures computed from the wave field when the renderer is made */
typedef enum ww_caustics_method { WW_CAUSTICS_ANALYTIC = 0, WW_CAUSTICS_TEXTURE } ww_caustics_method;

/* how the water's DuDv ripples are evaluated per pixel: the value noise's gradient computed
 * exactly, or read from a tiled, mipmapped texture of it made once (gfx/water.c) */
typedef enum ww_water_detail_method { WW_DETAIL_EXACT = 0, WW_DETAIL_TEXTURE } ww_water_detail_method;

/* the water's optics (seeds 000, 002, 004) */
typedef struct ww_water_look {
    ww_fresnel fresnel;          /* bias + scale (1 - v.n)^power, or Schlick with F0 */
    double fresnel_bias, fresnel_scale, fresnel_power;
    double distortion;           /* DuDv distortion of reflection/refraction lookups, screen fraction */
    double distortion_scale;     /* DuDv pattern tiles per metre */
    double distortion_speed;     /* m/s the pattern drifts */
    double specular;             /* sun highlight strength */
    int foam;                    /* foam on steep, grazing and folding surface */
    double foam_amount;          /* 0..1 */
    double foam_life;            /* s: foam a fold left fades as exp(-age / life); 0: no memory */
    double murk;                 /* extinction under water for refraction, 1/m */
    int caustics;                /* animated caustics on surfaces under water */
    double caustics_strength;
    ww_caustics_method caustics_method; /* focused per pixel, or a looped set of textures */
    int alpha_blend;             /* seed 004: the surface alpha-blended over what lies below */
    double alpha;                /* its opacity at normal incidence */
    ww_water_detail_method detail; /* the DuDv ripples: exact per pixel, or a texture */
} ww_water_look;

/* a point light or a spot (seed 003's lantern); position is world, or relative to the parent */
typedef struct ww_light_desc {
    ww_light_kind kind;
    double position[3];          /* m */
    double direction[3];         /* spot axis, unit */
    double color[3];             /* linear RGB */
    double intensity;            /* radiance scale */
    double range;                /* m: the light reaches zero here (smooth window) */
    double angle;                /* spot: half-angle of the cone, rad */
    double softness;             /* spot: fraction of the cone that fades out */
    double flicker;              /* 0..1: depth of the flicker */
    double flicker_rate;         /* Hz */
    double scatter;              /* its glow in the water (in-scattering), x fog.below.density; 0 off */
    char parent[32];             /* "" world; "boat"; or a model's name */
    int line, column;            /* where it was written */
} ww_light_desc;

typedef struct ww_hud_desc {
    int clock;                   /* 24-hour clock */
    int counters;                /* fish caught, prizes, boat speed, mode */
    int chest_marker;            /* screen-space glow marker at the chest */
} ww_hud_desc;

/* render.quality: a set of knob values (compile_render.c), the scene's own keys applied over it */
typedef enum ww_quality {
    WW_QUALITY_FINAL = 0, /* the defaults: the best picture the renderer's defaults give */
    WW_QUALITY_PREVIEW,   /* lighter reflection, shafts and water mesh: close to final */
    WW_QUALITY_DRAFT      /* every knob at its cheapest useful value, FXAA off */
} ww_quality;

typedef struct ww_render_desc {
    ww_quality quality;
    ww_shadow_desc shadows;
    int refraction;              /* scene prepass: colour + depth of what lies under the water */
    double refraction_scale;     /* its target size as a fraction of the frame's */
    ww_reflection_desc reflection;
    ww_bloom_desc bloom;
    ww_shafts_desc shafts;
    int fxaa;
    int msaa;                    /* samples of the main pass (0 or 1: none) */
    double grid;                 /* water mesh density factor (1: the default rings and segments) */
    double scale;                /* the frame is drawn at this fraction of its size, then scaled up */
    ww_hud_desc hud;

    /* sky */
    ww_sky_model sky;
    char cubemap[6][WW_PATH_MAX];/* +x, -x, +y, -y, +z, -z image files, resolved from the scene */
    int cubemap_image[6];        /* index in the scene's assets (scene/assets.h), -1 none */
    char dome_image_path[WW_PATH_MAX]; /* sky.image: the dome's picture, resolved; "" none */
    int dome_image;              /* its index in the scene's assets, -1 none (procedural dome) */
    double dome_horizon[3];      /* the picture's mean linear colour along its horizon ring
                                  * (the fog's colour with this sky: far water fades into it) */
    double sky_intensity;        /* cubemap and dome radiance scale */
    double sky_turbidity;        /* Preetham's turbidity T (haze: 2 clear .. 10 hazy) */
    double cloud_cover;          /* share of the sky the clouds cover, 0: none (preetham) */
    double cloud_speed;          /* drift, cloud-noise cells per second */
    int cloud_seed;              /* where in the noise the clouds start */

    /* fog under water (exp2); above-water fog is ww_scene.fog_* */
    double fog_below_color[3];   /* linear RGB */
    double fog_below_density;    /* 1/m */

    /* the seabed: a plane water.depth below the rest level */
    int seabed;
    double seabed_color[3];      /* linear RGB albedo */

    ww_water_look water;

    int nlights;
    ww_light_desc light[WW_MAX_LIGHTS];
} ww_render_desc;

/* the file format's defaults; compile_render.c */
void ww_render_defaults(ww_render_desc *d);

#endif
