/* desc_reef.h - objects.chest, objects.bubbles, objects.models: the treasure chest (seed 000),
 * air bubbles (seed 003) and static models' bounds the camera cannot enter. Read by
 * compile_reef.c; simulated by sim/chest.c, sim/bubbles.c, sim/collide.c.
 *
 *   objects:
 *     chest: {first: 20, every: 300, ttl: 15, radius: 12, near: boat, reach: 2, size: [0.9, 0.6, 0.6]}
 *     bubbles: [{at: [3, -6, 2], rate: 2, speed: 0.25, wobble: 0.03, frequency: 2, size: 0.01, count: 16}]
 *     models: [{name: rock, min: [-1, -8, -1], max: [1, -6, 1]},
 *              {name: kelp, obj: models/kelp.obj, sway: {amplitude: 0.3, frequency: 0.2}}]
 */
#ifndef WW_DESC_REEF_H
#define WW_DESC_REEF_H

#define WW_MAX_EMITTERS 32
#define WW_MAX_BUBBLES_PER_EMITTER 64
#define WW_MAX_MODELS 64

/* what a chest spawns around */
typedef enum ww_chest_near {
    WW_CHEST_NEAR_AUTO = 0, /* the boat when the scene has one, else the camera */
    WW_CHEST_NEAR_BOAT,
    WW_CHEST_NEAR_CAMERA
} ww_chest_near;

typedef struct ww_chest_desc {
    int on;          /* the scene has a chest (a chest section or a chest event) */
    double first;    /* simulated time of the first scheduled spawn, s (like script times) */
    double every;    /* scheduled spawns at first + k every, s */
    double ttl;      /* lifetime of a chest, s (<= every) */
    double radius;   /* spawns within this distance of the anchor in XZ, m */
    ww_chest_near near;
    double reach;    /* collected when the camera is this close to the chest's box, m */
    double size[3];  /* box width (x), height (y), depth (z), m */
    double glow;     /* radiance of the glow column over its default, 0: no column */
} ww_chest_desc;

typedef struct ww_emitter_desc {
    double at[3];    /* the vent, m (below the water level) */
    double rate;     /* bubbles released per second, 1/s */
    double speed;    /* mean rise speed, m/s (each bubble +-10%) */
    double wobble;   /* lateral amplitude of the zigzag, m */
    double frequency;/* of the zigzag, Hz */
    double size;     /* largest bubble radius, m (each bubble 0.5..1 of it) */
    int count;       /* pool size: bubbles in flight at most */
    int first;       /* index of the pool's first bubble in the state's arrays */
} ww_emitter_desc;

typedef struct ww_bubbles_desc {
    int on;          /* the scene has bubble emitters */
    int count;       /* emitters */
    int total;       /* bubbles in all pools */
    ww_emitter_desc emitter[WW_MAX_EMITTERS];
} ww_bubbles_desc;

/* the shapes the renderer generates (gfx/meshgen.h), each within the unit box [-0.5, 0.5]^3 */
typedef enum ww_mesh_kind {
    WW_MESH_NONE = 0, /* bounds only: solid to the camera, not drawn */
    WW_MESH_BOX,
    WW_MESH_SPHERE,
    WW_MESH_STONE,
    WW_MESH_HULL,
    WW_MESH_FISH,
    WW_MESH_LURE,
    WW_MESH_CHEST,
    WW_MESH_GRID,
    WW_MESH_OBJ       /* an OBJ file: ww_model_desc.asset */
} ww_mesh_kind;

typedef struct ww_model_desc {
    char name[32];   /* for messages and the renderer; "" when not given */
    double min[3], max[3]; /* axis-aligned bounds, m (given, or the transformed mesh's) */
    ww_mesh_kind mesh;
    int asset;       /* WW_MESH_OBJ: index into the scene's assets' meshes */
    double position[3];    /* relative to the parent, m */
    double rotation[3];    /* yaw (about y; positive turns +x toward +z, like the boat's
                            * heading), pitch (about x), roll (about z), rad, applied roll
                            * first, then pitch, then yaw */
    double scale[3];
    double color[3];       /* linear RGB albedo (multiplies an OBJ's materials) */
    double emissive;       /* emitted radiance as a multiple of color (0: none), unlit */
    int parent;            /* index of the parent model, -1 world, WW_PARENT_BOAT the boat */
    double local[16];      /* model -> parent's frame, column-major: T R S */
    double frame[16];      /* the model's frame, where its children are placed: its parent's
                            * frame times its own T R, without its scale (a child inherits
                            * position and rotation, never scale: metres stay metres) */
    double world[16];      /* model -> world for static chains (parent -1 up the chain):
                            * the parent's frame times local, column-major; relative to the
                            * boat's frame when the chain ends at the boat (the renderer composes
                            * it with the boat's pose per frame) */
    int solid;             /* the camera cannot enter its bounds (default: unless it sways) */
    int oriented;          /* solid is the box obb_c, obb_h turned by obb_q (a turned mesh's own
                            * bounds), not the axis-aligned min/max */
    double obb_c[3];       /* its centre in the world (or the boat's frame), m */
    double obb_h[3];       /* its half extents along its own axes, m */
    double obb_q[4];       /* its turn, unit quaternion w x y z */
    /* sway (plants): the mesh bends with the water above its base, the tip most; drawn only */
    double sway_amplitude; /* sideways reach of the top, m (0: rigid) */
    double sway_frequency; /* Hz */
    double sway_wavelength;/* m: phase travels across a bed at this wavelength */
    double sway_dir[2];    /* unit (x, z) of the motion: the dominant wave's heading by default */
    int line, column;      /* where it was written */
} ww_model_desc;

#define WW_PARENT_BOAT (-2)

typedef struct ww_models_desc {
    int count;       /* static models (the solid ones' bounds stop the camera) */
    ww_model_desc model[WW_MAX_MODELS];
} ww_models_desc;

/* the file format's defaults (on stays 0); compile_reef.c */
void ww_chest_defaults(ww_chest_desc *d);

#endif
