/* geometry.c - the scene's solid geometry, shared by the passes that draw it (shadow, prepass,
 * reflection, main): procedural meshes (gfx/meshgen.h) and OBJ models uploaded once, per-instance
 * model matrices, colours and extras uploaded once per frame from the state (cubes, boat,
 * stones, lure, fish, chest, bubbles, models), one instanced draw per mesh; the scene's lights
 * composed with their parents per frame; the chest's glow column drawn additively after the
 * opaque geometry in the colour modes. Positions are camera-relative (shaders/geometry.*).
 *
 * Matrices are composed in double from the state and the camera is subtracted before they are
 * rounded to float, so geometry 1e5 m from the origin stays exact.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/mathx.h"
#include "gfx/caustic_set.h"
#include "gfx/line.h"
#include "gfx/splash.h"
#include "gfx/wake.h"
#include "gfx/meshgen.h"
#include "gfx/render_impl.h"
#include "sim/floaters.h"

/* grid cells per side. Every attribute is linear across the plane, so the cells only need to keep
 * the interpolation's rounding small; 100 m cells do. Seen from a few metres up, a fine grid's
 * far rows are thinner than a pixel, and llvmpipe shades a block of pixels once for every
 * triangle crossing it: 64 cells cost the lake's frame 9% more for the same picture. */
#define SEABED_CELLS 8
#define SEABED_HALF 400.0    /* half its side, m (snapped to the camera) */
#define SEABED_OFFSET_UNITS -2.0f /* glPolygonOffset of its depth: toward the eye, depth steps */
#define SEABED_SNAP 16.0     /* the plane moves on this grid, m */
#define CUT_MARGIN 0.05f     /* m beyond the crest a draw still takes the cut at the surface */

/* sizes and looks of the things the state moves (the simulation has no sizes for them) */
#define FISH_LENGTH 0.45          /* m, nose to tail */
#define FISH_WIGGLE 0.07          /* tail swing at the tip, mesh units */
#define FISH_WIGGLE_HZ 1.2        /* tail beats per second when still */
#define FISH_WIGGLE_PER_SPEED 2.5 /* more beats per second per m/s of speed */
#define FISH_MAX_PITCH 0.6        /* rad: how far a fish noses up or down */
#define FISH_SPECIES_VARY 0.2     /* a species' fish differ by up to +-10% in size and shade */
#define GLOW_RADIUS 0.7           /* m, the chest's glow column */
#define GLOW_ABOVE 1.5            /* m: the column rises this far above the water's rest level */
#define GLOW_FADE_IN 1.0          /* s: the column grows brighter over this after a spawn */
#define GLOW_RADIANCE 1.4         /* radiance of an optically thick column, x objects.chest.glow */
#define GLOW_OPACITY 0.9          /* optical depth per metre of the column's chord, 1/m */
/* the column is a marker seen from afar: a camera beside it (diving for the chest) looks
 * through it, so it dims to GLOW_NEAR_MIN of itself as the camera's distance from its axis
 * falls from GLOW_NEAR_FAR to GLOW_NEAR_CLOSE metres */
#define GLOW_NEAR_CLOSE 1.5
#define GLOW_NEAR_FAR 10.0
#define GLOW_NEAR_MIN 0.2
#define WW_TEX_SHADOW 3            /* texture unit of the shadow map (shaders/shadow.glsl) */
#define WW_TEX_MATERIAL 4          /* texture unit of an OBJ material's map_Kd */
#define WW_TEX_CAUSTIC_SET 5       /* texture unit of the caustics' looped set (method texture) */
#define SPEC_DEFAULT 0.25         /* sun highlight on most things */
#define SPEC_WET 0.6              /* on fish, bubbles and drops */
/* a splash's drops: clear water seen as the sky and the sun it scatters, white at this size */
static const double SPRAY_ALBEDO[3] = {0.8, 0.85, 0.88};
/* sunlight lost per metre of water (red goes first): seed 003's green-blue under water */
#define WATER_EXTINCTION_R 0.45
#define WATER_EXTINCTION_G 0.09
#define WATER_EXTINCTION_B 0.07
#define WATER_DETAIL_SLOPE 0.06   /* water.frag.glsl: DETAIL_SLOPE, the DuDv ripples' slope */

/* the shared slots: one instanced draw each */
enum {
    SLOT_SEABED = 0,
    SLOT_BOX,
    SLOT_SPHERE,
    SLOT_STONE,
    SLOT_HULL,
    SLOT_FISH,
    SLOT_LURE,
    SLOT_CHEST,
    SLOT_GRID,
    SLOT_FISH_SLIM, /* objects.fish.species: one slot per body plan (ww_fish_shape order) */
    SLOT_FISH_DEEP,
    SLOT_FISH_LONG,
    SLOT_SPRAY,  /* a splash's drops (gfx/splash.h) */
    SLOT_BUBBLE, /* air bubbles: blended, back to front (WW_GEOM_PART_BUBBLES) */
    SLOT_COLUMN, /* glow: drawn additively, never into depth */
    SLOT_COUNT
};

static const ww_mesh_kind SLOT_KIND[SLOT_COUNT] = {
    [SLOT_BOX] = WW_MESH_BOX,     [SLOT_SPHERE] = WW_MESH_SPHERE, [SLOT_STONE] = WW_MESH_STONE,
    [SLOT_HULL] = WW_MESH_HULL,   [SLOT_FISH] = WW_MESH_FISH,     [SLOT_LURE] = WW_MESH_LURE,
    [SLOT_CHEST] = WW_MESH_CHEST, [SLOT_GRID] = WW_MESH_GRID,     [SLOT_COLUMN] = WW_MESHGEN_COLUMN,
    [SLOT_BUBBLE] = WW_MESH_SPHERE, [SLOT_SPRAY] = WW_MESHGEN_DROP,
    [SLOT_FISH_SLIM] = WW_MESHGEN_FISH_OF(WW_FISH_SLIM),
    [SLOT_FISH_DEEP] = WW_MESHGEN_FISH_OF(WW_FISH_DEEP),
    [SLOT_FISH_LONG] = WW_MESHGEN_FISH_OF(WW_FISH_LONG),
};

/* the slots whose things cast shadow volumes: what casts into the shadow map (not the seabed,
 * the see-through bubbles, a splash's drops or the glow) */
static int slot_casts(int s) {
    return s != SLOT_SEABED && s != SLOT_BUBBLE && s != SLOT_SPRAY && s != SLOT_COLUMN;
}

/* the slots of the fish species, whose instances carry a colour pattern */
static int slot_patterned(int s) {
    return s == SLOT_FISH_SLIM || s == SLOT_FISH_DEEP || s == SLOT_FISH_LONG;
}

/* a bubble's squared distance from the camera and its index, for the back-to-front order */
typedef struct bubble_order {
    double d2;
    int index;
} bubble_order;

static int farther_first(const void *a, const void *b) {
    const bubble_order *p = a, *q = b;
    if (p->d2 != q->d2) return p->d2 < q->d2 ? 1 : -1;
    return p->index - q->index;
}

/* one mesh on the GPU with its per-instance buffer */
typedef struct gmesh {
    GLuint vao, vbo, ibo, inst;
    GLsizei nindex;
    int ninst, cap;
    struct instance *copy; /* casters of stencil shadow volumes: this frame's instances; or NULL */
    float lo[3], hi[3];    /* the mesh's bounding box, mesh units */
    int closed;            /* closed and consistently wound (ww_meshgen_open_edges): behind
                            * its faces lies its inside */
    float blo[3], bhi[3];  /* this frame's instances' bounding box, camera-relative, m */
} gmesh;

typedef struct instance {
    float model[16]; /* column-major, camera-relative */
    float color[4];  /* albedo, emission factor */
    float extra[4];  /* wiggle phase rad, wiggle amplitude, specular, fish pattern (0 none,
                      * 1 + ww_fish_shape: geometry.frag.glsl's WW_FISH_PATTERNS) */
} instance;

typedef struct light_locs {
    GLint n, pos, dir, color, param, scatter;
} light_locs;

/* one build of the geometry program per kind of draw (geometry.frag.glsl's WW_GEOM_MODE):
 * llvmpipe runs both arms of a branch for every pixel, so the lit seabed paid for the bubble's
 * and the glow column's code while it was one program switched by a uniform (a fifth of the
 * lake's prepass). For the same reason the lit draws have three builds: plain, with the
 * material's texture (WW_MAT_MAP: an OBJ submesh with map_Kd) and with the fish species'
 * patterns (WW_FISH_PATTERNS: their slots), so the rest pay for neither; and, in scenes with
 * stencilled shadows, each again without the sun (WW_SUNLESS) for the second draw of what lies
 * in shadow, which then skips the sunlight's path, the caustics and the highlight */
enum {
    GEOM_DEPTH,
    GEOM_LIT,
    GEOM_GLOW,
    GEOM_BUBBLE,
    GEOM_LINE,
    GEOM_WAKE,
    GEOM_LIT_MAP,
    GEOM_LIT_FISH,
    GEOM_SUNLESS, /* the three lit builds without the sun, in the same order */
    GEOM_SUNLESS_MAP,
    GEOM_SUNLESS_FISH,
    GEOM_PROGS
};
static const int GEOM_MODE[GEOM_PROGS] = {
    [GEOM_DEPTH] = 0,   [GEOM_LIT] = 1,         [GEOM_GLOW] = 2,
    [GEOM_BUBBLE] = 3,  [GEOM_LINE] = 4,        [GEOM_WAKE] = 5,
    [GEOM_LIT_MAP] = 1, [GEOM_LIT_FISH] = 1,
    [GEOM_SUNLESS] = 1, [GEOM_SUNLESS_MAP] = 1, [GEOM_SUNLESS_FISH] = 1};

typedef struct geom_prog {
    GLuint prog; /* 0: the scene never draws this kind */
    float cut_set, cut_mode_set; /* the side and mode its u_clip_surface holds (set_uniforms,
                                  * apply_cut) */
    int box_serial;              /* the mesh box its u_mesh_centre and u_mesh_half hold */
    int inside_set;              /* what its u_inside holds */
    ww_sky_locs sky;
    GLint view_proj, clip, clip_surface, mesh_centre, mesh_half, inside, ambient, eye, mirrored,
        water_y, mirror_reach, fog_color, fog_density, fog_below_color, fog_below_density,
        extinction, caustics_loc, glow, glow_y;
    GLint shadow_map, shadow_on, sun_view_proj, shadow_filter, shadow_water, shadow_bend;
    GLint scatter_through;
    light_locs lights;
    GLint sway_loc, sway_axis_loc;
    GLint mat_kd, mat_ks, mat_ke, mat_map;
    GLint detail_loc, dudv_m_loc, dudv_o_loc, dudv_h_loc;
    GLint cset_loc, cset_at_loc, cset_frame_loc;
} geom_prog;

struct ww_geometry {
    geom_prog var[GEOM_PROGS];
    const geom_prog *cur; /* the program in use: per-draw uniforms (material, sway) go to it */
    int64_t uploaded; /* frame whose instances are in the buffers, -1 none */
    gmesh slot[SLOT_COUNT];
    gmesh hull_cap;   /* the lid over each hull's inside, drawing the hull slot's instances */
    int nobj;         /* OBJ models: one mesh per model */
    gmesh obj[WW_MAX_MODELS];
    int obj_model[WW_MAX_MODELS];
    const ww_mesh_data *obj_data[WW_MAX_MODELS]; /* its submeshes and materials (the scene's) */
    int sway;          /* the scene has a swaying model: the shader is built WW_SWAY */
    float obj_sway[WW_MAX_MODELS][4];      /* u_sway of each OBJ model this frame (0: rigid) */
    float obj_sway_axis[WW_MAX_MODELS][4]; /* its u_sway_axis */
    GLuint *image_tex; /* the scene's images a material draws (map_Kd), by asset index; 0 none */
    int nimage;
    struct bubble_order *bubble_order; /* scratch: this frame's bubbles, farthest first */
    ww_splash_drop *drops;             /* scratch: this frame's drops of the splashes */
    gmesh strand[2];   /* the fishing line and its rod (gfx/line.h), built each frame */
    gmesh wake;        /* the boat's wake (gfx/wake.h), built each frame */
    int wake_on;       /* the scene draws one: the shaders need the waves (geometry.vert.glsl) */
    float *strand_vert; /* scratch: a strand's or the wake's vertices ... */
    uint32_t *strand_index; /* ... and triangles, each built and uploaded in turn */
    instance *scratch; /* the largest slot's instances, filled per frame */
    int scratch_cap;
    int draws;         /* instanced draws of the last ww_geometry_draw (tests) */
    int glow_clip;     /* the last ww_geometry_draw had a clip plane (the glow draws with it) */
    float glow_cyl[6]; /* the glow column, camera-relative: axis x, z, radius, bottom y, top y */
    ww_water_waves waves; /* caustics and the surface clip: the wave field's phases at the camera */
    float detail[WW_WATER_NDETAIL][4]; /* ... and the surface's detail at the camera */
    float dudv_m[2][4], dudv_o[2][2];  /* ... and its DuDv ripples (ww_water_dudv) */
    ww_water_ubos ubos;
    int caustics;      /* 0 none, 1 analytic, 2 the looped set (geometry.frag.glsl: WW_CAUSTICS) */
    int surface_clip;  /* the prepass cuts its geometry at the wave surface instead of its plane;
                        * the reflection mirrors and clips at the surface over an instance */
    float slope;       /* a bound on the surface's slope (surface_slope_bound) */
    float mirror_reach; /* m: the footprint radius up to which the reflection mirrors an instance
                         * about the surface over its centre (mirror_reach) */
    double crest;      /* m: the most the surface rises above or sinks below its rest level */
    float cut_side;    /* this pass's side of the cut (geometry.vert.glsl: u_clip_surface) */
    float cut_level;   /* the rest level, camera-relative, m */
    float cut_now;     /* the side the next draw needs: cut_side, or 0 for a draw that cannot
                        * reach the surface */
    float cut_mode;    /* 0: the cut replaces the pass's plane (the prepass); 1: the reflection:
                        * an instance mirrored and clipped about the surface over it, the
                        * larger ones about the plane, and none wholly under the surface */
    float box[6];      /* the drawn mesh's bounding box (centre, half size), mesh units */
    int box_serial;    /* counts the changes of box */
    int inside_now;    /* 1: the draw is a closed mesh the reflection's or the prepass's cut may
                        * open, whose inside is shaded apart; 2: the hull, whose hollow is
                        * shaded so too (geometry.vert.glsl, .frag.glsl: u_inside) */
    GLuint caustic_tex; /* method texture: the set, a 2D array of frame pairs (red, green) */
    ww_caustic_set cset;
    float cset_at[4], cset_frame[2]; /* this frame's u_caustic_set_at, u_caustic_set_frame */
    /* stencilled shadows (stencil_shadows.c): the casters' meshes kept on the CPU (slots that
     * cast; OBJ models are the scene's), and how the next draws test depth and light */
    int keep_casters;
    ww_mesh_data caster_mesh[SLOT_COUNT];
    ww_geom_stage stage;
    /* this frame's lights, camera-relative */
    int nlights;
    float light_pos[WW_MAX_LIGHTS][3], light_dir[WW_MAX_LIGHTS][3], light_color[WW_MAX_LIGHTS][3],
        light_param[WW_MAX_LIGHTS][4], light_scatter[WW_MAX_LIGHTS];
};

/* ---- small double matrices (column-major 4x4: m[c * 4 + r]) ---- */

static void m4_identity(double m[16]) {
    memset(m, 0, 16 * sizeof *m);
    m[0] = m[5] = m[10] = m[15] = 1.0;
}

static void m4_mul(const double a[16], const double b[16], double out[16]) {
    double r[16];
    for (int c = 0; c < 4; c++)
        for (int k = 0; k < 4; k++) {
            double s = 0.0;
            for (int j = 0; j < 4; j++) s += a[j * 4 + k] * b[c * 4 + j];
            r[c * 4 + k] = s;
        }
    memcpy(out, r, sizeof r);
}

/* translation t, rotation R (3x3 column-major), scale s: T R S */
static void m4_trs(double m[16], const double t[3], const double R[9], const double s[3]) {
    m4_identity(m);
    for (int c = 0; c < 3; c++)
        for (int r = 0; r < 3; r++) m[c * 4 + r] = R[c * 3 + r] * s[c];
    for (int r = 0; r < 3; r++) m[12 + r] = t[r];
}

static void m3_mul(const double a[9], const double b[9], double out[9]) {
    double r[9];
    for (int c = 0; c < 3; c++)
        for (int k = 0; k < 3; k++) {
            double s = 0.0;
            for (int j = 0; j < 3; j++) s += a[j * 3 + k] * b[c * 3 + j];
            r[c * 3 + k] = s;
        }
    memcpy(out, r, sizeof r);
}

/* heading h (0 = +x, pi/2 = +z, as the simulation's), then pitch (nose up +, about the body's
 * z) and roll (starboard +z down +, about the body's x): R = Ry(-h) Rz(pitch) Rx(roll) */
static void m3_hpr(double h, double pitch, double roll, double R[9]) {
    double ch = cos(-h), sh = sin(-h), cp = cos(pitch), sp = sin(pitch), cr = cos(roll),
           sr = sin(roll);
    double ry[9] = {ch, 0, -sh, 0, 1, 0, sh, 0, ch};
    double rz[9] = {cp, sp, 0, -sp, cp, 0, 0, 0, 1};
    double rx[9] = {1, 0, 0, 0, cr, sr, 0, -sr, cr};
    double t[9];
    m3_mul(ry, rz, t);
    m3_mul(t, rx, R);
}

/* unit quaternion w x y z -> rotation */
static void m3_quat(const double q[4], double R[9]) {
    double w = q[0], x = q[1], y = q[2], z = q[3];
    double n = w * w + x * x + y * y + z * z;
    if (!(n > 0.0)) {
        double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
        memcpy(R, I, sizeof I);
        return;
    }
    double s = 2.0 / n;
    R[0] = 1 - s * (y * y + z * z); R[1] = s * (x * y + w * z);     R[2] = s * (x * z - w * y);
    R[3] = s * (x * y - w * z);     R[4] = 1 - s * (x * x + z * z); R[5] = s * (y * z + w * x);
    R[6] = s * (x * z + w * y);     R[7] = s * (y * z - w * x);     R[8] = 1 - s * (x * x + y * y);
}

/* the boat's pose (no scale): hull centre, heading, pitch and roll of the state */
static void boat_pose(const ww_state *st, double m[16]) {
    double R[9], one[3] = {1, 1, 1};
    m3_hpr(st->boat_heading[0], st->boat_tilt[0], st->boat_tilt[1], R);
    m4_trs(m, st->boat_pos, R, one);
}

/* floater fl's frame now (f) and the inverse of the rigid frame its model was written at (inv) */
static void floater_rebase(const ww_scene *sc, const ww_state *st, int fl, const double frame[16],
                           double f[16], double inv[16]) {
    ww_floater_pose(sc, st, fl, f);
    m4_identity(inv);
    for (int r = 0; r < 3; r++) {
        for (int c = 0; c < 3; c++) inv[c * 4 + r] = frame[r * 4 + c];
        inv[12 + r] = -(frame[r * 4] * frame[12] + frame[r * 4 + 1] * frame[13] +
                        frame[r * 4 + 2] * frame[14]);
    }
}

/* a model's matrix `own` (its world matrix, or its frame: where its children and lights sit,
 * without its scale) this frame, composed with the boat's pose when its chain ends there */
static void model_to_world(const ww_scene *sc, const ww_state *st, int i, const double own[16],
                           double m[16]) {
    int p = sc->models.model[i].parent, root = i;
    while (p >= 0) { /* the root of the chain */
        root = p;
        p = sc->models.model[p].parent;
    }
    int fl = ww_floater_of_model(sc, root);
    if (fl >= 0) {
        /* a floating root: its simulated frame replaces the frame it was written at */
        double f[16], inv[16], rel[16];
        floater_rebase(sc, st, fl, sc->models.model[root].frame, f, inv);
        m4_mul(inv, own, rel);
        m4_mul(f, rel, m);
    } else if (p == WW_PARENT_BOAT && sc->boat.on) {
        double b[16];
        boat_pose(st, b);
        m4_mul(b, own, m);
    } else {
        memcpy(m, own, 16 * sizeof *m);
    }
}

static void model_world(const ww_scene *sc, const ww_state *st, int i, double m[16]) {
    model_to_world(sc, st, i, sc->models.model[i].world, m);
}

/* ---- GL meshes ---- */

/* the per-instance attributes from the bound GL_ARRAY_BUFFER into the bound vertex array:
 * model matrix in locations 3..6, colour in 7, extras in 8, one per instance */
static void instance_attribs(const ww_gl *gl) {
    for (int c = 0; c < 6; c++) {
        GLuint loc = 3 + (GLuint)c;
        gl->EnableVertexAttribArray(loc);
        gl->VertexAttribPointer(loc, 4, GL_FLOAT, GL_FALSE, sizeof(instance),
                                (void *)(c * 4 * sizeof(float)));
        gl->VertexAttribDivisor(loc, 1);
    }
}

/* the vertex buffer bound (GL_ARRAY_BUFFER) as the mesh's: position, normal, uv, 8 floats */
static void vertex_attribs(const ww_gl *gl) {
    GLsizei stride = 8 * sizeof(float);
    gl->EnableVertexAttribArray(0);
    gl->VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, (void *)0);
    gl->EnableVertexAttribArray(1);
    gl->VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, (void *)(3 * sizeof(float)));
    gl->EnableVertexAttribArray(2);
    gl->VertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, stride, (void *)(6 * sizeof(float)));
}

/* vertex layout: position, normal, uv; instances as instance_attribs */
static void mesh_upload(const ww_gl *gl, gmesh *m, const float *verts, int nvert,
                        const GLuint *idx, int nindex, int cap) {
    gl->GenVertexArrays(1, &m->vao);
    gl->BindVertexArray(m->vao);
    gl->GenBuffers(1, &m->vbo);
    gl->BindBuffer(GL_ARRAY_BUFFER, m->vbo);
    gl->BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)nvert * 8 * sizeof(float), verts, GL_STATIC_DRAW);
    for (int k = 0; k < 3; k++) {
        m->lo[k] = INFINITY;
        m->hi[k] = -INFINITY;
    }
    for (int i = 0; i < nvert; i++)
        for (int k = 0; k < 3; k++) {
            m->lo[k] = fminf(m->lo[k], verts[8 * i + k]);
            m->hi[k] = fmaxf(m->hi[k], verts[8 * i + k]);
        }
    vertex_attribs(gl);
    gl->GenBuffers(1, &m->ibo);
    gl->BindBuffer(GL_ELEMENT_ARRAY_BUFFER, m->ibo);
    gl->BufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)nindex * sizeof(GLuint), idx,
                   GL_STATIC_DRAW);
    m->nindex = nindex;

    gl->GenBuffers(1, &m->inst);
    gl->BindBuffer(GL_ARRAY_BUFFER, m->inst);
    gl->BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)cap * (GLsizeiptr)sizeof(instance), NULL,
                   GL_DYNAMIC_DRAW);
    instance_attribs(gl);
    m->cap = cap;
    gl->BindVertexArray(0);
}

/* m draws the instances of src (its own instance buffer dropped): the hull's lid is drawn
 * wherever a hull is, with no upload of its own */
static void mesh_share_instances(const ww_gl *gl, gmesh *m, const gmesh *src) {
    gl->DeleteBuffers(1, &m->inst);
    m->inst = 0;
    gl->BindVertexArray(m->vao);
    gl->BindBuffer(GL_ARRAY_BUFFER, src->inst);
    instance_attribs(gl);
    m->cap = src->cap;
    gl->BindVertexArray(0);
}

/* a strand's mesh (gfx/line.h): room for nvert vertices and nindex indices, rewritten each
 * frame, and its one instance (its colour; the vertices are camera-relative already) */
static void strand_new(const ww_gl *gl, gmesh *m, int nvert, int nindex) {
    gl->GenVertexArrays(1, &m->vao);
    gl->BindVertexArray(m->vao);
    gl->GenBuffers(1, &m->vbo);
    gl->BindBuffer(GL_ARRAY_BUFFER, m->vbo);
    gl->BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)nvert * 8 * sizeof(float), NULL, GL_DYNAMIC_DRAW);
    vertex_attribs(gl);
    gl->GenBuffers(1, &m->ibo);
    gl->BindBuffer(GL_ELEMENT_ARRAY_BUFFER, m->ibo);
    gl->BufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)nindex * sizeof(GLuint), NULL,
                   GL_DYNAMIC_DRAW);
    gl->GenBuffers(1, &m->inst);
    gl->BindBuffer(GL_ARRAY_BUFFER, m->inst);
    gl->BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)sizeof(instance), NULL, GL_DYNAMIC_DRAW);
    instance_attribs(gl);
    m->cap = 1;
    gl->BindVertexArray(0);
}

static void mesh_free(const ww_gl *gl, gmesh *m) {
    free(m->copy);
    if (m->vao) gl->DeleteVertexArrays(1, &m->vao);
    GLuint b[3] = {m->vbo, m->ibo, m->inst};
    if (m->vbo) gl->DeleteBuffers(3, b);
    *m = (gmesh){0};
}

/* the seabed: a flat grid, normals up, in a unit square [-1, 1]^2 scaled per frame */
static ww_result seabed_new(const ww_gl *gl, gmesh *m, ww_error *err) {
    int nv = (SEABED_CELLS + 1) * (SEABED_CELLS + 1), ni = SEABED_CELLS * SEABED_CELLS * 6;
    float *v = malloc((size_t)nv * 8 * sizeof *v);
    GLuint *ix = malloc((size_t)ni * sizeof *ix);
    if (!v || !ix) {
        free(v);
        free(ix);
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "geometry: out of memory");
    }
    for (int j = 0, k = 0; j <= SEABED_CELLS; j++) {
        for (int i = 0; i <= SEABED_CELLS; i++, k++) {
            float *p = v + 8 * k;
            p[0] = -1.0f + 2.0f * (float)i / SEABED_CELLS;
            p[1] = 0.0f;
            p[2] = -1.0f + 2.0f * (float)j / SEABED_CELLS;
            p[3] = 0.0f;
            p[4] = 1.0f;
            p[5] = 0.0f;
            p[6] = (float)i / SEABED_CELLS;
            p[7] = (float)j / SEABED_CELLS;
        }
    }
    int n = 0;
    for (int j = 0; j < SEABED_CELLS; j++) {
        for (int i = 0; i < SEABED_CELLS; i++) {
            GLuint a = (GLuint)(j * (SEABED_CELLS + 1) + i), b = a + 1,
                   c = a + SEABED_CELLS + 1, d = c + 1;
            GLuint q[6] = {a, c, b, b, c, d};
            memcpy(ix + n, q, sizeof q);
            n += 6;
        }
    }
    mesh_upload(gl, m, v, nv, ix, ni, 1);
    free(v);
    free(ix);
    return WW_OK;
}

/* how many instances each slot may hold in this scene */
static void slot_caps(const ww_scene *sc, int cap[SLOT_COUNT]) {
    memset(cap, 0, SLOT_COUNT * sizeof *cap);
    cap[SLOT_SEABED] = sc->render.seabed ? 1 : 0;
    cap[SLOT_BOX] = sc->cubes.on ? sc->cubes.count : 0;
    cap[SLOT_HULL] = sc->boat.on ? 1 : 0;
    cap[SLOT_STONE] = sc->stones.on ? WW_MAX_STONES : 0;
    cap[SLOT_FISH] = sc->fish.on && sc->fish.nspecies == 0 ? sc->fish.count : 0;
    for (int k = 0; sc->fish.on && k < sc->fish.nspecies; k++)
        cap[SLOT_FISH_SLIM + sc->fish.species[k].shape] += sc->fish.species[k].count;
    cap[SLOT_LURE] = sc->rod.on ? 1 : 0;
    cap[SLOT_CHEST] = sc->chest.on ? 1 : 0;
    cap[SLOT_COLUMN] = sc->chest.on ? 1 : 0;
    cap[SLOT_BUBBLE] = sc->bubbles.on ? sc->bubbles.total : 0;
    cap[SLOT_SPRAY] = ww_splash_capacity(sc);
    for (int i = 0; i < sc->models.count; i++) {
        ww_mesh_kind k = sc->models.model[i].mesh;
        for (int s = 1; s < SLOT_COUNT; s++)
            if (SLOT_KIND[s] == k && k != WW_MESH_NONE && k != WW_MESH_OBJ && s != SLOT_BUBBLE)
                cap[s]++;
    }
}

void ww_geometry_free(ww_geometry *g, const ww_gl *gl) {
    if (!g) return;
    for (int i = 0; i < GEOM_PROGS; i++)
        if (g->var[i].prog) gl->DeleteProgram(g->var[i].prog);
    for (int s = 0; s < SLOT_COUNT; s++) {
        mesh_free(gl, &g->slot[s]);
        ww_meshgen_free(&g->caster_mesh[s]);
    }
    mesh_free(gl, &g->hull_cap);
    for (int i = 0; i < 2; i++) mesh_free(gl, &g->strand[i]);
    mesh_free(gl, &g->wake);
    free(g->strand_vert);
    free(g->strand_index);
    for (int i = 0; i < g->nobj; i++) mesh_free(gl, &g->obj[i]);
    for (int i = 0; i < g->nimage; i++)
        if (g->image_tex[i]) gl->DeleteTextures(1, &g->image_tex[i]);
    free(g->image_tex);
    free(g->bubble_order);
    free(g->drops);
    ww_water_ubos_free(gl, &g->ubos);
    if (g->caustic_tex) gl->DeleteTextures(1, &g->caustic_tex);
    ww_caustic_set_free(&g->cset);
    free(g->scratch);
    free(g);
}

/* the lights' uniforms (common.glsl) in program prog */
static light_locs find_lights(const ww_gl *gl, GLuint prog) {
    return (light_locs){ww_gfx_uniform(gl, prog, "u_nlights"), ww_gfx_uniform(gl, prog, "u_light_pos"),
                        ww_gfx_uniform(gl, prog, "u_light_dir"),
                        ww_gfx_uniform(gl, prog, "u_light_color"),
                        ww_gfx_uniform(gl, prog, "u_light_param"),
                        ww_gfx_uniform(gl, prog, "u_light_scatter")};
}

/* the first n of this frame's lights into the program in use, whose lights' uniforms are l */
static void put_lights(const ww_geometry *g, const ww_gl *gl, const light_locs *l, int n) {
    gl->Uniform1i(l->n, n);
    if (n <= 0) return;
    gl->Uniform3fv(l->pos, n, &g->light_pos[0][0]);
    gl->Uniform3fv(l->dir, n, &g->light_dir[0][0]);
    gl->Uniform3fv(l->color, n, &g->light_color[0][0]);
    gl->Uniform4fv(l->param, n, &g->light_param[0][0]);
    gl->Uniform1fv(l->scatter, n, g->light_scatter);
}

/* builds the program for draws of `kind` (GEOM_*) and finds its uniforms */
static ww_result make_program(ww_geometry *g, const ww_gl *gl, const ww_scene *sc, int kind,
                              ww_error *err) {
    static const char *const includes[] = {"common.glsl", "gerstner.glsl", "shadow.glsl", NULL};
    char defs[400];
    snprintf(defs, sizeof defs,
             "#define WW_WAVE_MODEL %d\n#define WW_NWAVES %d\n#define WW_RIPPLES 0\n"
             "#define WW_FADE 1\n#define WW_CAUSTICS %d\n#define WW_FISH_PATTERNS %d\n"
             "#define WW_MAT_MAP %d\n#define WW_SUNLESS %d\n#define WW_LIGHT_SCATTER %d\n"
             "#define WW_SWAY %d\n#define WW_GEOM_MODE %d\n#define WW_LIGHTS %d\n"
             "#define WW_NLIGHTS %d\n%s",
             ww_water_shader_model(sc->wave_model), ww_water_wave_count(sc), g->caustics,
             kind == GEOM_LIT_FISH || kind == GEOM_SUNLESS_FISH,
             kind == GEOM_LIT_MAP || kind == GEOM_SUNLESS_MAP, kind >= GEOM_SUNLESS,
             ww_lights_scatter_on(sc), g->sway,
             GEOM_MODE[kind], sc->render.nlights > 0, sc->render.nlights, ww_sky_defines(sc));
    geom_prog *v = &g->var[kind];
    ww_result rc = ww_gfx_program_defs(gl, "geometry.vert.glsl", "geometry.frag.glsl", includes,
                                       defs, &v->prog, err);
    if (rc != WW_OK) return rc;
    GLuint p = v->prog;
    GLuint idx = gl->GetUniformBlockIndex(p, "WwWaves");
    if (idx != GL_INVALID_INDEX) gl->UniformBlockBinding(p, idx, WW_UBO_WAVES);
    ww_sky_locs_init(gl, p, sc, &v->sky);
    v->view_proj = ww_gfx_uniform(gl, p, "u_view_proj");
    v->clip = ww_gfx_uniform(gl, p, "u_clip");
    v->clip_surface = ww_gfx_uniform(gl, p, "u_clip_surface");
    v->mesh_centre = ww_gfx_uniform(gl, p, "u_mesh_centre");
    v->mesh_half = ww_gfx_uniform(gl, p, "u_mesh_half");
    v->inside = ww_gfx_uniform(gl, p, "u_inside");
    v->box_serial = -1;
    v->ambient = ww_gfx_uniform(gl, p, "u_ambient");
    v->eye = ww_gfx_uniform(gl, p, "u_eye");
    v->mirrored = ww_gfx_uniform(gl, p, "u_mirrored");
    v->scatter_through = ww_gfx_uniform(gl, p, "u_scatter_through");
    v->water_y = ww_gfx_uniform(gl, p, "u_water_y");
    v->mirror_reach = ww_gfx_uniform(gl, p, "u_mirror_reach");
    v->fog_color = ww_gfx_uniform(gl, p, "u_fog_color");
    v->fog_density = ww_gfx_uniform(gl, p, "u_fog_density");
    v->fog_below_color = ww_gfx_uniform(gl, p, "u_fog_below_color");
    v->fog_below_density = ww_gfx_uniform(gl, p, "u_fog_below_density");
    v->extinction = ww_gfx_uniform(gl, p, "u_extinction");
    v->caustics_loc = ww_gfx_uniform(gl, p, "u_caustics");
    v->detail_loc = ww_gfx_uniform(gl, p, "u_detail");
    v->dudv_m_loc = ww_gfx_uniform(gl, p, "u_dudv_m");
    v->dudv_o_loc = ww_gfx_uniform(gl, p, "u_dudv_o");
    v->dudv_h_loc = ww_gfx_uniform(gl, p, "u_dudv_h");
    v->cset_loc = ww_gfx_uniform(gl, p, "u_caustic_set");
    v->cset_at_loc = ww_gfx_uniform(gl, p, "u_caustic_set_at");
    v->cset_frame_loc = ww_gfx_uniform(gl, p, "u_caustic_set_frame");
    v->glow = ww_gfx_uniform(gl, p, "u_glow");
    v->glow_y = ww_gfx_uniform(gl, p, "u_glow_y");
    v->shadow_map = ww_gfx_uniform(gl, p, "u_shadow_map");
    v->shadow_on = ww_gfx_uniform(gl, p, "u_shadow_on");
    v->sun_view_proj = ww_gfx_uniform(gl, p, "u_sun_view_proj");
    v->shadow_filter = ww_gfx_uniform(gl, p, "u_shadow_filter");
    v->shadow_water = ww_gfx_uniform(gl, p, "u_shadow_water");
    v->shadow_bend = ww_gfx_uniform(gl, p, "u_shadow_bend");
    v->sway_loc = g->sway ? ww_gfx_uniform(gl, p, "u_sway") : -1;
    v->sway_axis_loc = g->sway ? ww_gfx_uniform(gl, p, "u_sway_axis") : -1;
    v->mat_kd = ww_gfx_uniform(gl, p, "u_mat_kd");
    v->mat_ks = ww_gfx_uniform(gl, p, "u_mat_ks");
    v->mat_ke = ww_gfx_uniform(gl, p, "u_mat_ke");
    v->mat_map = ww_gfx_uniform(gl, p, "u_mat_map");
    v->lights = find_lights(gl, p);
    return WW_OK;
}

/* the program in use takes the cut the draw needs (side, mode, the mesh's box, whether its inside
 * is shaded as the cut's face), where it holds another */
static void apply_cut(ww_geometry *g, const ww_gl *gl) {
    geom_prog *v = &g->var[g->cur - g->var];
    if (v->cut_set != g->cut_now || v->cut_mode_set != g->cut_mode) {
        gl->Uniform4f(v->clip_surface, g->cut_now, g->cut_level, g->cut_mode, g->slope);
        v->cut_set = g->cut_now;
        v->cut_mode_set = g->cut_mode;
    }
    if (v->box_serial != g->box_serial) {
        gl->Uniform3f(v->mesh_centre, g->box[0], g->box[1], g->box[2]);
        gl->Uniform3f(v->mesh_half, g->box[3], g->box[4], g->box[5]);
        v->box_serial = g->box_serial;
    }
    if (v->inside_set != g->inside_now) {
        gl->Uniform1i(v->inside, g->inside_now);
        v->inside_set = g->inside_now;
    }
}

/* makes kind's program current */
static const geom_prog *use(ww_geometry *g, const ww_gl *gl, int kind) {
    g->cur = &g->var[kind];
    gl->UseProgram(g->cur->prog);
    apply_cut(g, gl);
    return g->cur;
}

/* the cut at the wave surface costs each vertex the waves a few times over: only a draw whose
 * instances reach the band the surface moves in pays it; the rest keep the plane, which they
 * lie wholly on the kept side of */
static void cut_for(ww_geometry *g, const ww_gl *gl, const gmesh *m) {
    float reach = (float)g->crest + CUT_MARGIN;
    int near = m->bhi[1] >= g->cut_level - reach && m->blo[1] <= g->cut_level + reach;
    g->cut_now = near ? g->cut_side : 0.0f;
    float box[6];
    for (int k = 0; k < 3; k++) {
        box[k] = 0.5f * (m->lo[k] + m->hi[k]);
        box[3 + k] = 0.5f * (m->hi[k] - m->lo[k]);
    }
    if (near && memcmp(box, g->box, sizeof box) != 0) {
        memcpy(g->box, box, sizeof box);
        g->box_serial++;
    }
    g->inside_now = near && g->cut_side != 0.0f && m->closed ? (m == &g->slot[SLOT_HULL] ? 2 : 1)
                                                             : 0;
    apply_cut(g, gl);
}

/* whether a horizontal clip plane (camera-relative, kept where >= 0) discards every instance
 * of m: the prepass from below where nothing rises above the water, the reflection of what lies
 * under it. Such a draw makes no fragment, so it is skipped and costs no vertices. The margin
 * keeps a draw whose bound only touches the plane, whatever the rounding of its vertices */
#define CLIPPED_MARGIN 1e-3f /* m */
static int clipped_away(const float *clip, const gmesh *m) {
    if (!clip || clip[0] != 0.0f || clip[2] != 0.0f || clip[1] == 0.0f) return 0;
    float y = clip[1] > 0.0f ? m->bhi[1] : m->blo[1]; /* the point the plane keeps most */
    return clip[1] * y + clip[3] < -CLIPPED_MARGIN * fabsf(clip[1]);
}

/* whether m's instances lie wholly beyond one side of the view (left, right, bottom or top of
 * clip space, x or y past -w or w), their box widened by `margin` m across (a plant's sway):
 * such a draw makes no fragment either. The near and far planes are not tested: the shadow
 * volumes' pass clamps depth instead of clipping it */
static int outside_view(vec4 *vp, const gmesh *m, float margin) {
    float lo[3] = {m->blo[0] - margin, m->blo[1], m->blo[2] - margin};
    float hi[3] = {m->bhi[0] + margin, m->bhi[1], m->bhi[2] + margin};
    for (int k = 0; k < 4; k++) {
        int row = k / 2;
        float s = (k & 1) ? -1.0f : 1.0f; /* w + x >= 0, w - x >= 0, then y */
        float d = vp[3][3] + s * vp[3][row], most = d;
        for (int c = 0; c < 3; c++) {
            float a = vp[c][3] + s * vp[c][row];
            most += a > 0.0f ? a * hi[c] : a * lo[c];
        }
        if (most < 0.0f) return 1;
    }
    return 0;
}

static int is_lit(int kind) {
    return kind == GEOM_LIT || kind == GEOM_LIT_MAP || kind == GEOM_LIT_FISH ||
           kind >= GEOM_SUNLESS;
}

/* while a lit program is in use, switches to the lit build `kind` (GEOM_LIT, _MAP, _FISH) when
 * the scene has it, else to the plain one, each without the sun in the stencilled shadows'
 * second draw; a depth-only draw keeps its program */
static void use_lit(ww_geometry *g, const ww_gl *gl, int kind) {
    int cur = (int)(g->cur - g->var);
    if (!is_lit(cur)) return;
    if (!g->var[kind].prog) kind = GEOM_LIT;
    if (g->stage == WW_GEOM_STAGE_SUNLESS) {
        int dark = kind == GEOM_LIT ? GEOM_SUNLESS : kind == GEOM_LIT_MAP ? GEOM_SUNLESS_MAP
                                                                         : GEOM_SUNLESS_FISH;
        if (g->var[dark].prog) kind = dark;
    }
    if (cur != kind) use(g, gl, kind);
}

/* the GL texture of the scene's image `index` (a material's map_Kd), uploaded the first time a
 * material names it: sRGB, mipmapped, repeating (OBJ uvs tile); -1 names none */
static ww_result material_texture(ww_geometry *g, const ww_gl *gl, const ww_scene *sc, int index,
                                  ww_error *err) {
    if (index < 0 || !sc->assets || index >= sc->assets->nimage) return WW_OK;
    if (!g->image_tex) {
        g->image_tex = calloc((size_t)sc->assets->nimage, sizeof *g->image_tex);
        if (!g->image_tex) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "geometry: out of memory");
        g->nimage = sc->assets->nimage;
    }
    if (g->image_tex[index]) return WW_OK;
    const ww_image_data *im = &sc->assets->image[index];
    unsigned char *rgba = NULL;
    ww_result r = ww_assets_decode(im, &rgba, err);
    if (r) return r;
    gl->GenTextures(1, &g->image_tex[index]);
    gl->BindTexture(GL_TEXTURE_2D, g->image_tex[index]);
    gl->PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl->TexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, im->width, im->height, 0, GL_RGBA,
                   GL_UNSIGNED_BYTE, rgba);
    ww_gfx_mipmap_tiled(gl, GL_TEXTURE_2D);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    ww_assets_pixels_free(rgba);
    return WW_OK;
}

/* method texture: the looped set computed once (caustic_set.c), uploaded as a 2D array of
 * half-float frame pairs, mipmapped so the far seabed averages toward the mean, repeating */
static ww_result caustic_set_new(ww_geometry *g, const ww_gl *gl, const ww_scene *sc, ww_error *err) {
    ww_result rc = ww_caustic_set_make(sc, &g->cset, err);
    if (rc != WW_OK) return rc;
    const ww_caustic_set *cs = &g->cset;
    gl->GenTextures(1, &g->caustic_tex);
    gl->BindTexture(GL_TEXTURE_2D_ARRAY, g->caustic_tex);
    gl->PixelStorei(GL_UNPACK_ALIGNMENT, 4);
    /* layer i holds frames i and i + 1 (looped) in red and green: one lookup blends them */
    size_t per = (size_t)cs->size * (size_t)cs->size;
    float *pair = malloc(2 * per * (size_t)cs->frames * sizeof *pair);
    if (!pair) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "caustics: out of memory");
    for (int f = 0; f < cs->frames; f++) {
        const float *a = cs->texel + per * (size_t)f;
        const float *b = cs->texel + per * (size_t)((f + 1) % cs->frames);
        float *o = pair + 2 * per * (size_t)f;
        for (size_t i = 0; i < per; i++) {
            o[2 * i] = a[i];
            o[2 * i + 1] = b[i];
        }
    }
    gl->TexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RG16F, cs->size, cs->size, cs->frames, 0, GL_RG,
                   GL_FLOAT, pair);
    free(pair);
    free(g->cset.texel); /* the GL copy is all the frames need; the set keeps its geometry */
    g->cset.texel = NULL;
    ww_gfx_mipmap_tiled(gl, GL_TEXTURE_2D_ARRAY);
    gl->BindTexture(GL_TEXTURE_2D_ARRAY, 0);
    GLenum e = gl->GetError();
    if (e != GL_NO_ERROR)
        return ww_error_set(err, WW_E_GL, NULL, 0, 0, "caustics: the texture set raised GL error 0x%04x",
                            (unsigned)e);
    return WW_OK;
}

/* a bound on the slope of the water's surface, dh/dx along any direction. A component's height
 * A s(k x - w t) has slope k A s': s' is at most 1 for a sine, e / 2 for a steep sine's
 * ((sin + 1) / 2)^e (taken as e here); Gerstner's horizontal pull squeezes a crest by
 * 1 - sum Q k A, which divides the slope. The ripples' rings add theirs, amplitude times
 * wavenumber */
static double surface_slope_bound(const ww_scene *sc) {
    double slope = 0.0, squeeze = 0.0;
    for (int i = 0; sc->wave_model != WW_WAVES_FLAT && i < sc->nwaves; i++) {
        const ww_wave *w = &sc->waves[i];
        slope += w->k * fabs(w->amplitude) * fmax(w->exponent, 1.0);
        squeeze += w->steepness * w->k * fabs(w->amplitude);
    }
    slope /= fmax(1.0 - squeeze, 0.25);
    if (sc->ripples_on) slope += fabs(sc->ripples.amplitude) * sc->ripples.wavenumber;
    return slope;
}

/* the footprint radius up to which the reflection mirrors an instance about the surface over its
 * centre rather than the rest plane (geometry.vert.glsl): a quarter of the wavelength of the
 * component that raises the surface most, over which its height turns from its value at the
 * centre through a right angle */
static double mirror_reach(const ww_scene *sc) {
    double most = 0.0, reach = 1.0;
    for (int i = 0; sc->wave_model != WW_WAVES_FLAT && i < sc->nwaves; i++)
        if (fabs(sc->waves[i].amplitude) > most) {
            most = fabs(sc->waves[i].amplitude);
            reach = 0.25 * sc->waves[i].wavelength;
        }
    return reach;
}

ww_result ww_geometry_new(ww_renderer *r, const ww_scene *sc, ww_geometry **out, ww_error *err) {
    const ww_gl *gl = r->gl;
    ww_geometry *g = calloc(1, sizeof *g);
    if (!g) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "geometry: out of memory");
    g->uploaded = -1;
    g->caustics = sc->render.water.caustics && sc->wave_model != WW_WAVES_FLAT && sc->nwaves > 0;
    if (g->caustics && sc->render.water.caustics_method == WW_CAUSTICS_TEXTURE) g->caustics = 2;
    g->surface_clip = (sc->render.refraction || sc->render.reflection.on) &&
                      sc->wave_model != WW_WAVES_FLAT && sc->nwaves > 0;
    g->crest = ww_water_crest(sc);
    g->slope = (float)surface_slope_bound(sc);
    g->mirror_reach = (float)mirror_reach(sc);
    for (int i = 0; i < sc->models.count; i++)
        if (sc->models.model[i].sway_amplitude > 0.0) g->sway = 1;
    g->keep_casters = sc->render.shadows.on && (sc->render.shadows.technique == WW_SHADOW_VOLUMES ||
                                                sc->render.shadows.technique ==
                                                    WW_SHADOW_VOLUMES_VISIBLE);
    ww_result rc = make_program(g, gl, sc, GEOM_LIT, err);
    if (rc == WW_OK) rc = make_program(g, gl, sc, GEOM_DEPTH, err);
    g->wake_on = sc->boat.on && sc->boat.wake > 0.0;
    if (rc == WW_OK && (g->caustics == 1 || g->surface_clip || g->wake_on)) {
        ww_water_waves_init(sc, &g->waves);
        rc = ww_water_ubos_new(gl, sc, &g->waves, &g->ubos, err);
    }
    if (rc == WW_OK && g->caustics == 2) rc = caustic_set_new(g, gl, sc, err);
    int cap[SLOT_COUNT], most = 1;
    slot_caps(sc, cap);
    if (rc == WW_OK && cap[SLOT_SEABED]) rc = seabed_new(gl, &g->slot[SLOT_SEABED], err);
    for (int s = 1; s < SLOT_COUNT && rc == WW_OK; s++) {
        if (cap[s] > most) most = cap[s];
        if (!cap[s]) continue;
        ww_mesh_data m;
        rc = ww_meshgen(SLOT_KIND[s], &m, err);
        if (rc != WW_OK) break;
        mesh_upload(gl, &g->slot[s], m.vertex, m.nvert, m.index, (int)m.nindex, cap[s]);
        g->slot[s].closed = ww_meshgen_open_edges(&m) == 0;
        if (g->keep_casters && slot_casts(s)) {
            g->caster_mesh[s] = m; /* the stencil shadows' volumes are built from it */
            g->slot[s].copy = malloc((size_t)cap[s] * sizeof(instance));
            if (!g->slot[s].copy)
                rc = ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "geometry: out of memory");
        } else {
            ww_meshgen_free(&m);
        }
        if (s != SLOT_HULL || rc != WW_OK) continue;
        rc = ww_meshgen(WW_MESHGEN_HULL_CAP, &m, err);
        if (rc != WW_OK) break;
        mesh_upload(gl, &g->hull_cap, m.vertex, m.nvert, m.index, (int)m.nindex, 1);
        mesh_share_instances(gl, &g->hull_cap, &g->slot[SLOT_HULL]);
        ww_meshgen_free(&m);
    }
    /* OBJ models: their own mesh each (the assets helper decodes them) */
    for (int i = 0; i < sc->models.count && rc == WW_OK; i++) {
        const ww_model_desc *d = &sc->models.model[i];
        if (d->mesh != WW_MESH_OBJ || !sc->assets || d->asset < 0 || d->asset >= sc->assets->nmesh)
            continue;
        const ww_mesh_data *m = &sc->assets->mesh[d->asset];
        mesh_upload(gl, &g->obj[g->nobj], m->vertex, m->nvert, m->index, (int)m->nindex, 1);
        g->obj[g->nobj].closed = ww_meshgen_open_edges(m) == 0;
        if (g->keep_casters && !(g->obj[g->nobj].copy = malloc(sizeof(instance))))
            rc = ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "geometry: out of memory");
        g->obj_data[g->nobj] = m;
        g->obj_model[g->nobj++] = i;
        for (int k = 0; k < m->nmaterial && rc == WW_OK; k++)
            rc = material_texture(g, gl, sc, m->material[k].texture, err);
    }
    if (rc == WW_OK && g->slot[SLOT_SPRAY].cap > 0 &&
        !(g->drops = malloc((size_t)g->slot[SLOT_SPRAY].cap * sizeof *g->drops)))
        rc = ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "geometry: out of memory");
    if (rc == WW_OK && sc->bubbles.on &&
        !(g->bubble_order = malloc((size_t)sc->bubbles.total * sizeof *g->bubble_order)))
        rc = ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "geometry: out of memory");
    if (rc == WW_OK) {
        g->scratch = malloc((size_t)most * sizeof *g->scratch);
        g->scratch_cap = most;
        if (!g->scratch) rc = ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "geometry: out of memory");
    }
    /* the glow column's and the bubbles' own programs, in the scenes that draw them */
    if (rc == WW_OK && g->slot[SLOT_COLUMN].cap > 0) rc = make_program(g, gl, sc, GEOM_GLOW, err);
    if (rc == WW_OK && g->slot[SLOT_BUBBLE].cap > 0) rc = make_program(g, gl, sc, GEOM_BUBBLE, err);
    if (rc == WW_OK && sc->rod.on && sc->rod.line_width > 0.0) {
        strand_new(gl, &g->strand[WW_STRAND_LINE], WW_LINE_MAX_VERTS, WW_LINE_MAX_INDEX);
        strand_new(gl, &g->strand[WW_STRAND_ROD], WW_ROD_MAX_VERTS, WW_ROD_MAX_INDEX);
        rc = make_program(g, gl, sc, GEOM_LINE, err);
    }
    if (rc == WW_OK && g->wake_on) {
        strand_new(gl, &g->wake, WW_WAKE_MAX_VERTS, WW_WAKE_MAX_INDEX);
        rc = make_program(g, gl, sc, GEOM_WAKE, err);
    }
    /* scratch for the strands' and the wake's vertices, each built and uploaded in turn */
    if (rc == WW_OK && (g->strand[0].vao || g->wake.vao)) {
        int nv = WW_LINE_MAX_VERTS > WW_WAKE_MAX_VERTS ? WW_LINE_MAX_VERTS : WW_WAKE_MAX_VERTS;
        int ni = WW_LINE_MAX_INDEX > WW_WAKE_MAX_INDEX ? WW_LINE_MAX_INDEX : WW_WAKE_MAX_INDEX;
        g->strand_vert = malloc((size_t)nv * 8 * sizeof *g->strand_vert);
        g->strand_index = malloc((size_t)ni * sizeof *g->strand_index);
        if (!g->strand_vert || !g->strand_index)
            rc = ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "geometry: out of memory");
    }
    if (rc == WW_OK && g->nimage > 0) rc = make_program(g, gl, sc, GEOM_LIT_MAP, err);
    if (rc == WW_OK && sc->fish.on && sc->fish.nspecies > 0)
        rc = make_program(g, gl, sc, GEOM_LIT_FISH, err);
    /* the stencilled techniques draw what lies in shadow again, without the sun */
    if (sc->render.shadows.on && sc->render.shadows.technique != WW_SHADOW_MAP)
        for (int k = GEOM_LIT; k <= GEOM_LIT_FISH && rc == WW_OK; k++)
            if (is_lit(k) && g->var[k].prog)
                rc = make_program(g, gl, sc, k == GEOM_LIT ? GEOM_SUNLESS
                                             : k == GEOM_LIT_MAP ? GEOM_SUNLESS_MAP
                                                                 : GEOM_SUNLESS_FISH, err);
    if (rc != WW_OK) {
        ww_geometry_free(g, gl);
        return rc;
    }
    g->cur = &g->var[GEOM_LIT];
    *out = g;
    return WW_OK;
}

/* ---- per frame ---- */

static void put(instance *in, const double m[16], const double cam[3], const double color[3],
                double emission, double spec) {
    for (int i = 0; i < 16; i++) {
        double v = m[i];
        if (i >= 12 && i < 15) v -= cam[i - 12];
        in->model[i] = (float)v;
    }
    for (int c = 0; c < 3; c++) in->color[c] = (float)color[c];
    in->color[3] = (float)emission;
    in->extra[0] = in->extra[1] = in->extra[3] = 0.0f;
    in->extra[2] = (float)spec;
}

/* a plant's sway this frame (shaders/geometry.vert.glsl): the surge under a wave of the sway's
 * wavelength travelling along its direction reaches a plant at (x, z) with phase
 * 2 pi (f t - (x, z).D / wavelength); a hash of its place adds up to a turn more, so plants
 * side by side across the wave do not move in lockstep. From the frame's simulated time only. */
#define SWAY_LAG 1.2 /* rad: how far the tip's swing trails the base's */
static void obj_sway(ww_geometry *g, const ww_scene *sc, const ww_state *st, int i,
                     const double world[16]) {
    const ww_model_desc *d = &sc->models.model[g->obj_model[i]];
    const ww_mesh_data *md = g->obj_data[i];
    for (int k = 0; k < 4; k++) g->obj_sway[i][k] = g->obj_sway_axis[i][k] = 0.0f;
    double tall = md->max[1] - md->min[1];
    if (d->sway_amplitude <= 0.0 || !(tall > 0.0)) return;
    double x = world[12], z = world[14];
    double along = (x * d->sway_dir[0] + z * d->sway_dir[1]) / d->sway_wavelength;
    double h = sin(x * 12.9898 + z * 78.233) * 43758.5453;
    double jitter = h - floor(h);
    double phase = 2.0 * WW_PI * (fmod(d->sway_frequency * st->t - along, 1.0) + jitter);
    /* the mesh's height in metres: its y axis's length in the world matrix */
    double sy = sqrt(world[4] * world[4] + world[5] * world[5] + world[6] * world[6]);
    g->obj_sway[i][0] = (float)d->sway_amplitude;
    g->obj_sway[i][1] = (float)phase;
    g->obj_sway[i][2] = (float)SWAY_LAG;
    g->obj_sway[i][3] = (float)(tall * sy);
    g->obj_sway_axis[i][0] = md->min[1];
    g->obj_sway_axis[i][1] = (float)(1.0 / tall);
    g->obj_sway_axis[i][2] = (float)d->sway_dir[0];
    g->obj_sway_axis[i][3] = (float)d->sway_dir[1];
}

static void slot_upload(const ww_gl *gl, gmesh *m, const instance *in, int n) {
    WW_ASSERT(n <= m->cap);
    m->ninst = n;
    if (n <= 0) return;
    /* the box the instances fill: the mesh's box through each one's matrix, row by row, the
     * box's z widened by the tail's beat (geometry.vert.glsl bends mesh z by up to its
     * amplitude) */
    for (int r = 0; r < 3; r++) {
        m->blo[r] = INFINITY;
        m->bhi[r] = -INFINITY;
    }
    for (int i = 0; i < n; i++) {
        float beat = fabsf(in[i].extra[1]);
        float lo[3] = {m->lo[0], m->lo[1], m->lo[2] - beat}, hi[3] = {m->hi[0], m->hi[1],
                                                                       m->hi[2] + beat};
        for (int r = 0; r < 3; r++) {
            float a, b;
            ww_gfx_box_row(in[i].model, r, lo, hi, &a, &b);
            m->blo[r] = fminf(m->blo[r], a);
            m->bhi[r] = fmaxf(m->bhi[r], b);
        }
    }
    if (m->copy) memcpy(m->copy, in, (size_t)n * sizeof *in);
    gl->BindBuffer(GL_ARRAY_BUFFER, m->inst);
    gl->BufferSubData(GL_ARRAY_BUFFER, 0, (GLsizeiptr)n * (GLsizeiptr)sizeof *in, in);
}

/* fish i's pose (yaw, pitch from its velocity, bank) scaled by its length, and its tail's
 * beat: phase and amplitude in extra[0..1] */
static void fish_instance(const ww_state *st, int i, double length, const double cam[3],
                          const double col[3], instance *in) {
    const double *v = st->fish_vel + 3 * i;
    double sp = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    double pitch = ww_m_clamp(atan2(v[1], hypot(v[0], v[2])), -FISH_MAX_PITCH, FISH_MAX_PITCH);
    double R[9], m[16], s[3] = {length, length, length};
    m3_hpr(st->fish_yaw[i], pitch, st->fish_bank[i], R);
    m4_trs(m, st->fish_pos + 3 * i, R, s);
    put(in, m, cam, col, 0.0, SPEC_WET);
    double hz = FISH_WIGGLE_HZ + FISH_WIGGLE_PER_SPEED * sp;
    double ph = fmod(2.0 * WW_PI * hz * st->t + 2.399963 * i, 2.0 * WW_PI);
    in->extra[0] = (float)ph;
    in->extra[1] = (float)(FISH_WIGGLE * (st->fish_mode[i] == 1.0 ? 2.0 : 1.0));
}

/* the fish of every species of this body plan: the species' colour and length, each fish
 * within +-FISH_SPECIES_VARY of them (from its index), its pattern in extra[3] */
static int species_fish(const ww_scene *sc, const ww_state *st, ww_fish_shape shape,
                        const double cam[3], instance *in) {
    int n = 0;
    for (int k = 0; k < sc->fish.nspecies; k++) {
        const ww_fish_species *sp = &sc->fish.species[k];
        if (sp->shape != shape) continue;
        for (int i = sp->first; i < sp->first + sp->count; i++) {
            if (st->fish_mode[i] == 2.0) continue; /* caught: away */
            double u = (double)((i * 7919) % 97) / 97.0 - 0.5, col[3];
            for (int c = 0; c < 3; c++) col[c] = sp->color[c] * (1.0 + FISH_SPECIES_VARY * u);
            fish_instance(st, i, sp->length * (1.0 + FISH_SPECIES_VARY * u), cam, col, &in[n]);
            in[n++].extra[3] = (float)(1 + shape);
        }
    }
    return n;
}

/* models of a procedural kind join that kind's slot */
static int add_models(const ww_scene *sc, const ww_state *st, ww_mesh_kind kind,
                      const double cam[3], instance *in, int n) {
    for (int i = 0; i < sc->models.count; i++) {
        const ww_model_desc *d = &sc->models.model[i];
        if (d->mesh != kind) continue;
        double m[16];
        model_world(sc, st, i, m);
        put(&in[n++], m, cam, d->color, d->emissive, SPEC_DEFAULT);
    }
    return n;
}

/* 1 when some light glows in the water (lights[].scatter > 0): the shaders then build
 * common.glsl's in-scattering (WW_LIGHT_SCATTER), which scenes without it never compile */
int ww_lights_scatter_on(const ww_scene *sc) {
    for (int i = 0; i < sc->render.nlights; i++)
        if (sc->render.light[i].scatter > 0.0) return 1;
    return 0;
}

/* the flicker of light i at time t: 1 - depth (1 + s) / 2 with s a sum of three sines at
 * incommensurate multiples of the rate (1, golden ratio, e), phases from the index: never a
 * clock, the same frame gives the same light */
static double flicker(const ww_light_desc *l, int i, double t) {
    if (l->flicker <= 0.0) return 1.0;
    double w = 2.0 * WW_PI * l->flicker_rate * t;
    double s = 0.5 * sin(w + 1.3 * i) + 0.3 * sin(1.6180339887 * w + 2.1 * i + 0.4) +
               0.2 * sin(2.7182818285 * w + 0.7 * i + 1.9);
    return 1.0 - l->flicker * 0.5 * (1.0 + s);
}

/* each light's world position and axis, composed with its parent this frame */
static void frame_lights(ww_geometry *g, const ww_scene *sc, const ww_state *st,
                         const double cam[3]) {
    g->nlights = sc->render.nlights;
    for (int i = 0; i < g->nlights; i++) {
        const ww_light_desc *l = &sc->render.light[i];
        double m[16];
        m4_identity(m);
        if (strcmp(l->parent, "boat") == 0 && sc->boat.on) {
            boat_pose(st, m);
        } else if (l->parent[0]) {
            for (int k = 0; k < sc->models.count; k++)
                /* in the model's frame, as a child model: metres, never its scale */
                if (strcmp(sc->models.model[k].name, l->parent) == 0)
                    model_to_world(sc, st, k, sc->models.model[k].frame, m);
        }
        double d[3];
        for (int r = 0; r < 3; r++) {
            double p = m[12 + r];
            d[r] = 0.0;
            for (int c = 0; c < 3; c++) {
                p += m[c * 4 + r] * l->position[c];
                d[r] += m[c * 4 + r] * l->direction[c];
            }
            g->light_pos[i][r] = (float)(p - cam[r]);
        }
        ww_m_normalize3(d);
        double f = flicker(l, i, st->t) * l->intensity;
        for (int r = 0; r < 3; r++) {
            g->light_dir[i][r] = (float)d[r];
            g->light_color[i][r] = (float)(l->color[r] * f);
        }
        double cos_outer = cos(l->angle), cos_inner = cos(l->angle * (1.0 - l->softness));
        g->light_param[i][0] = (float)l->range;
        g->light_param[i][1] = (float)cos_outer;
        g->light_param[i][2] = (float)(cos_inner > cos_outer + 1e-4 ? cos_inner : cos_outer + 1e-4);
        g->light_param[i][3] = l->kind == WW_LIGHT_SPOT ? 1.0f : 0.0f;
        g->light_scatter[i] = (float)l->scatter;
    }
}

/* a mesh built this frame (g->strand_vert, g->strand_index) into m's buffers, with its one
 * instance (its albedo and extra): the vertices are camera-relative already, so its matrix is
 * the identity */
static void built_upload(ww_geometry *g, const ww_gl *gl, gmesh *m, int nvert, int nindex,
                         const double albedo[3], const double extra[4]) {
    m->nindex = nindex;
    m->ninst = nindex > 0;
    if (nindex == 0) return;
    instance in = {.model = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}};
    for (int c = 0; c < 3; c++) in.color[c] = (float)albedo[c];
    for (int c = 0; c < 4; c++) in.extra[c] = (float)extra[c];
    gl->BindBuffer(GL_ARRAY_BUFFER, m->vbo);
    gl->BufferSubData(GL_ARRAY_BUFFER, 0, (GLsizeiptr)nvert * 8 * sizeof(float), g->strand_vert);
    gl->BindBuffer(GL_ARRAY_BUFFER, m->inst);
    gl->BufferSubData(GL_ARRAY_BUFFER, 0, (GLsizeiptr)sizeof in, &in);
    gl->BindVertexArray(m->vao);
    gl->BufferSubData(GL_ELEMENT_ARRAY_BUFFER, 0, (GLsizeiptr)nindex * sizeof(GLuint),
                      g->strand_index);
    gl->BindVertexArray(0);
}

/* the camera the frame's strands and wake are built for (gfx/line.h) */
static ww_line_eye frame_eye(const ww_frame *f) {
    ww_line_eye eye = {.pixel_angle = f->pixel_angle, .near = f->sc->near_clip};
    for (int k = 0; k < 3; k++) eye.pos[k] = f->cam_pos[k], eye.fwd[k] = f->fwd[k];
    return eye;
}

/* this frame's line and rod, facing the camera (gfx/line.h), with their colours */
#define ROD_ALBEDO 0.05 /* a dark carbon rod ... */
#define ROD_SPEC 0.8    /* ... with a bright highlight along it */
static void upload_strands(ww_geometry *g, const ww_gl *gl, const ww_frame *f) {
    const ww_scene *sc = f->sc;
    ww_line_eye eye = frame_eye(f);
    for (int which = 0; which < 2; which++) {
        gmesh *m = &g->strand[which];
        int nvert, nindex = ww_line_build(sc, f->st, &eye, (ww_strand)which, g->strand_vert,
                                          g->strand_index, &nvert);
        int rod = which == WW_STRAND_ROD;
        double albedo[3];
        for (int c = 0; c < 3; c++) albedo[c] = rod ? ROD_ALBEDO : sc->rod.line_color[c];
        double extra[4] = {0.0, 0.0, rod ? ROD_SPEC : SPEC_WET, 0.0};
        built_upload(g, gl, m, nvert, nindex, albedo, extra);
    }
}

/* this frame's wake (gfx/wake.h), with the foam's colour, and the time, the stern's odometer
 * and the transom's half-breadth in the instance's extra (x, z, w; y is the fish's wiggle, 0);
 * none under water */
#define FOAM_ALBEDO 0.85
#define WAKE_CREST_REPEAT (256 * 1.5) /* s: geometry.frag.glsl's WAKE_CREST_CYCLE, 256 times */
static void upload_wake(ww_geometry *g, const ww_gl *gl, const ww_frame *f) {
    const ww_scene *sc = f->sc;
    ww_line_eye eye = frame_eye(f);
    double stern[2] = {0.0, 0.0};
    int nvert = 0, nindex = f->underwater ? 0 : ww_wake_build(sc, f->st, &eye, g->strand_vert,
                                                              g->strand_index, &nvert, stern);
    double foam[3] = {FOAM_ALBEDO, FOAM_ALBEDO, FOAM_ALBEDO};
    /* the time, for the noise of the wake's crests: its offsets repeat after 256 cycles (the
     * noise's period, common.glsl), so wrapping there keeps it continuous in a float */
    double extra[4] = {fmod(f->st->t, WAKE_CREST_REPEAT), 0.0, stern[0], stern[1]};
    built_upload(g, gl, &g->wake, nvert, nindex, foam, extra);
}

/* this frame's instances (once per frame, whichever pass draws first) */
static void upload_instances(ww_geometry *g, const ww_gl *gl, const ww_frame *f) {
    const ww_scene *sc = f->sc;
    const ww_state *st = f->st;
    if (g->uploaded == f->frame) return;
    g->uploaded = f->frame;
    const double *cam = f->cam_pos;
    instance *in = g->scratch;
    double one[3] = {1, 1, 1};

    if (g->slot[SLOT_SEABED].cap) {
        /* centred on the camera snapped to a grid, so the grid does not swim */
        double c[3] = {SEABED_SNAP * floor(cam[0] / SEABED_SNAP + 0.5),
                       sc->water_level - sc->water_depth,
                       SEABED_SNAP * floor(cam[2] / SEABED_SNAP + 0.5)};
        double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, s[3] = {SEABED_HALF, 1.0, SEABED_HALF}, m[16];
        m4_trs(m, c, I, s);
        put(&in[0], m, cam, sc->render.seabed_color, 0.0, 0.0);
        slot_upload(gl, &g->slot[SLOT_SEABED], in, 1);
    }
    if (g->slot[SLOT_BOX].cap) {
        int n = 0;
        for (int i = 0; sc->cubes.on && i < sc->cubes.count; i++) {
            double R[9], m[16], s = sc->cubes.cube[i].size, sz[3] = {s, s, s};
            static const double wood[3] = {0.62, 0.42, 0.24};
            m3_quat(st->cube_rot + 4 * i, R);
            m4_trs(m, st->cube_pos + 3 * i, R, sz);
            put(&in[n++], m, cam, wood, 0.0, SPEC_DEFAULT);
        }
        slot_upload(gl, &g->slot[SLOT_BOX], in, add_models(sc, st, WW_MESH_BOX, cam, in, n));
    }
    if (g->slot[SLOT_HULL].cap) {
        int n = 0;
        if (sc->boat.on) {
            double m[16], s[16], S[3] = {sc->boat.length, sc->boat.length, sc->boat.length};
            static const double paint[3] = {0.55, 0.16, 0.08};
            double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, zero[3] = {0, 0, 0};
            boat_pose(st, m);
            m4_trs(s, zero, I, S);
            m4_mul(m, s, m);
            put(&in[n++], m, cam, paint, 0.0, SPEC_DEFAULT);
        }
        n = add_models(sc, st, WW_MESH_HULL, cam, in, n);
        slot_upload(gl, &g->slot[SLOT_HULL], in, n);
        g->hull_cap.ninst = n; /* the hull slot's buffer */
    }
    if (g->slot[SLOT_STONE].cap) {
        int n = 0;
        for (int i = 0; sc->stones.on && i < WW_MAX_STONES; i++) {
            if (st->stone_state[i] == 0.0) continue;
            double R[9], m[16], d = 2.0 * sc->stones.radius, s[3] = {d, d, d};
            static const double grey[3] = {0.42, 0.41, 0.39};
            m3_hpr(st->stone_spin[i] * (st->t - st->stone_t0[i]), 0.0, 0.0, R);
            m4_trs(m, st->stone_pos + 3 * i, R, s);
            put(&in[n++], m, cam, grey, 0.0, SPEC_DEFAULT);
        }
        slot_upload(gl, &g->slot[SLOT_STONE], in, add_models(sc, st, WW_MESH_STONE, cam, in, n));
    }
    for (int shape = 0; shape < WW_FISH_SHAPES; shape++) {
        gmesh *slot = &g->slot[SLOT_FISH_SLIM + shape];
        if (slot->cap) slot_upload(gl, slot, in, species_fish(sc, st, (ww_fish_shape)shape, cam, in));
    }
    if (g->slot[SLOT_FISH].cap) {
        int n = 0;
        for (int i = 0; sc->fish.on && sc->fish.nspecies == 0 && i < sc->fish.count; i++) {
            if (st->fish_mode[i] == 2.0) continue; /* caught: away */
            const double *v = st->fish_vel + 3 * i;
            double sp = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            double pitch = ww_m_clamp(atan2(v[1], hypot(v[0], v[2])), -FISH_MAX_PITCH, FISH_MAX_PITCH);
            double R[9], m[16], s[3] = {FISH_LENGTH, FISH_LENGTH, FISH_LENGTH};
            /* each fish a little different: hue and size from its index */
            double u = (double)((i * 7919) % 97) / 97.0;
            double col[3] = {0.45 + 0.25 * u, 0.5 + 0.1 * u, 0.45 - 0.15 * u};
            for (int k = 0; k < 3; k++) s[k] *= 0.85 + 0.3 * u;
            m3_hpr(st->fish_yaw[i], pitch, st->fish_bank[i], R);
            m4_trs(m, st->fish_pos + 3 * i, R, s);
            put(&in[n], m, cam, col, 0.0, SPEC_WET);
            double hz = FISH_WIGGLE_HZ + FISH_WIGGLE_PER_SPEED * sp;
            double ph = fmod(2.0 * WW_PI * hz * st->t + 2.399963 * i, 2.0 * WW_PI);
            in[n].extra[0] = (float)ph;
            in[n].extra[1] = (float)(FISH_WIGGLE * (st->fish_mode[i] == 1.0 ? 2.0 : 1.0));
            n++;
        }
        slot_upload(gl, &g->slot[SLOT_FISH], in, add_models(sc, st, WW_MESH_FISH, cam, in, n));
    }
    if (g->slot[SLOT_LURE].cap) {
        int n = 0;
        if (sc->rod.on && st->lure_state[0] != 0.0) {
            double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, m[16];
            double s[3] = {WW_LURE_SIZE, WW_LURE_SIZE, WW_LURE_SIZE};
            static const double red[3] = {0.85, 0.12, 0.08};
            m4_trs(m, st->lure_pos, I, s);
            put(&in[n++], m, cam, red, 0.15, SPEC_WET);
        }
        slot_upload(gl, &g->slot[SLOT_LURE], in, add_models(sc, st, WW_MESH_LURE, cam, in, n));
    }
    if (g->slot[SLOT_CHEST].cap) {
        int n = 0, nglow = 0;
        instance glow;
        if (sc->chest.on && st->chest_state[0] != 0.0) {
            const double *b = st->chest_pos, *sz = sc->chest.size;
            double c[3] = {b[0], b[1] + 0.5 * sz[1], b[2]}, I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, m[16];
            static const double gold[3] = {0.75, 0.52, 0.16};
            m4_trs(m, c, I, sz);
            put(&in[n++], m, cam, gold, 0.05, SPEC_WET);
            /* the glow column from the chest up through the surface */
            double top = sc->water_level + GLOW_ABOVE, h = fmax(top - b[1], 1.0);
            double gc[3] = {b[0], b[1] + 0.5 * h, b[2]}, gs[3] = {2 * GLOW_RADIUS, h, 2 * GLOW_RADIUS};
            static const double warm[3] = {1.0, 0.8, 0.35};
            m4_trs(m, gc, I, gs);
            double age = st->t - st->chest_t0[0];
            double axis = hypot(b[0] - cam[0], b[2] - cam[2]);
            double near = GLOW_NEAR_MIN + (1.0 - GLOW_NEAR_MIN) *
                                              ww_m_smoothstep(GLOW_NEAR_CLOSE, GLOW_NEAR_FAR, axis);
            double radiance = GLOW_RADIANCE * sc->chest.glow * near *
                              ww_m_smoothstep(0.0, GLOW_FADE_IN, age);
            put(&glow, m, cam, warm, radiance, 0.0);
            g->glow_cyl[0] = (float)(b[0] - cam[0]);
            g->glow_cyl[1] = (float)(b[2] - cam[2]);
            g->glow_cyl[2] = (float)GLOW_RADIUS;
            g->glow_cyl[3] = (float)(b[1] - cam[1]);
            g->glow_cyl[4] = (float)(b[1] + h - cam[1]);
            g->glow_cyl[5] = (float)GLOW_OPACITY;
            /* glow 0: no column at all */
            nglow = sc->chest.glow > 0.0;
        }
        slot_upload(gl, &g->slot[SLOT_CHEST], in, add_models(sc, st, WW_MESH_CHEST, cam, in, n));
        slot_upload(gl, &g->slot[SLOT_COLUMN], &glow, nglow);
    }
    if (g->slot[SLOT_SPHERE].cap)
        slot_upload(gl, &g->slot[SLOT_SPHERE], in, add_models(sc, st, WW_MESH_SPHERE, cam, in, 0));
    if (g->slot[SLOT_BUBBLE].cap) {
        /* back to front: each blends over the ones behind it (ties by index, so the order is
         * the same on every run) */
        bubble_order *order = g->bubble_order;
        int n = 0;
        for (int i = 0; i < sc->bubbles.total; i++) {
            if (st->bubble_on[i] == 0) continue;
            const double *b = st->bubble_pos + 3 * i;
            double d[3] = {b[0] - cam[0], b[1] - cam[1], b[2] - cam[2]};
            order[n++] = (bubble_order){d[0] * d[0] + d[1] * d[1] + d[2] * d[2], i};
        }
        qsort(order, (size_t)n, sizeof *order, farther_first);
        for (int k = 0; k < n; k++) {
            int i = order[k].index;
            double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, m[16], d = 2.0 * st->bubble_radius[i];
            double s[3] = {d, d, d};
            static const double air[3] = {1.0, 1.0, 1.0};
            m4_trs(m, st->bubble_pos + 3 * i, I, s);
            put(&in[k], m, cam, air, 0.0, SPEC_WET);
        }
        slot_upload(gl, &g->slot[SLOT_BUBBLE], in, n);
    }
    if (g->slot[SLOT_SPRAY].cap) {
        int n = ww_splash_drops(sc, st, g->drops, g->slot[SLOT_SPRAY].cap);
        for (int k = 0; k < n; k++) {
            double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, m[16], d = 2.0 * g->drops[k].radius;
            double s[3] = {d, d, d};
            m4_trs(m, g->drops[k].p, I, s);
            put(&in[k], m, cam, SPRAY_ALBEDO, 0.0, SPEC_WET);
        }
        slot_upload(gl, &g->slot[SLOT_SPRAY], in, n);
    }
    if (g->slot[SLOT_GRID].cap)
        slot_upload(gl, &g->slot[SLOT_GRID], in, add_models(sc, st, WW_MESH_GRID, cam, in, 0));
    for (int i = 0; i < g->nobj; i++) {
        const ww_model_desc *d = &sc->models.model[g->obj_model[i]];
        double m[16];
        model_world(sc, st, g->obj_model[i], m);
        put(&in[0], m, cam, d->color, d->emissive, SPEC_DEFAULT);
        slot_upload(gl, &g->obj[i], in, 1);
        if (g->sway) obj_sway(g, sc, st, i, m);
    }
    (void)one;
    if (g->strand[WW_STRAND_LINE].vao) upload_strands(g, gl, f);
    if (g->wake.vao) upload_wake(g, gl, f);
    frame_lights(g, sc, st, cam);

    if (g->caustics == 2) {
        /* the set: the camera wrapped to its patch (double), the two frames of this instant */
        const ww_caustic_set *cs = &g->cset;
        int i0, i1;
        double w;
        ww_caustic_set_frame(cs, st->t, &i0, &i1, &w);
        g->cset_at[0] = (float)(cam[0] - cs->patch * floor(cam[0] / cs->patch));
        g->cset_at[1] = (float)(cam[2] - cs->patch * floor(cam[2] / cs->patch));
        g->cset_at[2] = (float)(1.0 / cs->patch);
        g->cset_at[3] = (float)cs->depth;
        (void)i1; /* layer i0 holds frame i1 too */
        g->cset_frame[0] = (float)i0;
        g->cset_frame[1] = (float)w;
    } else if (g->caustics || g->surface_clip || g->wake_on) {
        /* the wave field's phases at the camera: the shader's positions are camera-relative;
         * the surface's fine detail focuses the light too */
        double centre[2] = {cam[0], cam[2]};
        ww_water_waves_phases(sc, st, centre, &g->waves);
        ww_water_ubos_upload(gl, &g->ubos, &g->waves, NULL, 0);
        ww_water_detail(st, centre, g->detail);
        ww_water_dudv(sc, st, centre, g->dudv_m, g->dudv_o);
    }
}

static int draw_mesh(const ww_gl *gl, const gmesh *m) {
    if (m->ninst <= 0) return 0;
    gl->BindVertexArray(m->vao);
    gl->DrawElementsInstanced(GL_TRIANGLES, m->nindex, GL_UNSIGNED_INT, NULL, m->ninst);
    return 1;
}

/* the material uniforms (geometry.frag.glsl): an OBJ submesh's, or with mt NULL the identity
 * every other mesh is drawn with (the instance's own albedo and specular, no emission, opaque) */
static void put_material(const ww_gl *gl, const geom_prog *v, const ww_material *mt,
                         GLuint tex) {
    if (!mt) {
        gl->Uniform4f(v->mat_kd, 1.0f, 1.0f, 1.0f, 0.0f);
        gl->Uniform4f(v->mat_ks, 0.0f, 0.0f, 0.0f, 0.0f);
        gl->Uniform4f(v->mat_ke, 0.0f, 0.0f, 0.0f, 1.0f);
    } else {
        const float *kd = mt->diffuse, *ks = mt->specular, *ke = mt->emission;
        gl->Uniform4f(v->mat_kd, kd[0], kd[1], kd[2], tex ? 1.0f : 0.0f);
        gl->Uniform4f(v->mat_ks, ks[0], ks[1], ks[2], fmaxf(mt->shininess, 1.0f));
        gl->Uniform4f(v->mat_ke, ke[0], ke[1], ke[2], mt->opacity);
    }
    gl->ActiveTexture(GL_TEXTURE0 + WW_TEX_MATERIAL);
    gl->BindTexture(GL_TEXTURE_2D, tex);
    gl->ActiveTexture(GL_TEXTURE0);
}

/* the material for the next draw, in the lit build that reads its texture when it has one */
static void set_material(ww_geometry *g, const ww_gl *gl, const ww_material *mt) {
    GLuint tex = 0;
    if (mt && mt->texture >= 0 && mt->texture < g->nimage) tex = g->image_tex[mt->texture];
    use_lit(g, gl, tex ? GEOM_LIT_MAP : GEOM_LIT);
    put_material(gl, g->cur, mt, tex);
}

/* model i's sway into the program in use (each build keeps its own) */
static void set_sway(const ww_geometry *g, const ww_gl *gl, int i) {
    if (!g->sway) return;
    gl->Uniform4fv(g->cur->sway_loc, 1, g->obj_sway[i]);
    gl->Uniform4fv(g->cur->sway_axis_loc, 1, g->obj_sway_axis[i]);
}

/* whether a model has a part drawn blended (a material's opacity below 1) */
static int has_blended(const ww_mesh_data *d) {
    for (int k = 0; d && k < d->nsub; k++) {
        int m = d->sub[k].material;
        if (m >= 0 && m < d->nmaterial && d->material[m].opacity < 1.0f) return 1;
    }
    return 0;
}

static int draw_obj(ww_geometry *g, const ww_gl *gl, int i, ww_geom_mode mode) {
    const gmesh *m = &g->obj[i];
    const ww_mesh_data *d = g->obj_data[i];
    if (m->ninst <= 0) return 0;
    if (mode == WW_GEOM_SHADOW || (mode == WW_GEOM_PREPASS_DEPTH && !has_blended(d)) || !d ||
        d->nsub <= 0) {
        set_material(g, gl, NULL);
        set_sway(g, gl, i);
        return draw_mesh(gl, m);
    }
    gl->BindVertexArray(m->vao);
    for (int pass = 0; pass < 2; pass++) {
        for (int k = 0; k < d->nsub; k++) {
            const ww_submesh *sub = &d->sub[k];
            const ww_material *mt = sub->material >= 0 && sub->material < d->nmaterial
                                        ? &d->material[sub->material] : NULL;
            int blended = mt && mt->opacity < 1.0f;
            if (blended != pass || sub->count == 0) continue;
            /* the prepass's depth has what it drew opaque, no more */
            if (blended && mode == WW_GEOM_PREPASS_DEPTH) continue;
            if (blended && g->stage != WW_GEOM_STAGE_NORMAL) continue; /* never blended twice */
            set_material(g, gl, mt);
            set_sway(g, gl, i);
            if (blended) {
                gl->Enable(GL_BLEND);
                gl->BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
                gl->DepthMask(GL_FALSE);
            }
            gl->DrawElementsInstanced(GL_TRIANGLES, (GLsizei)sub->count, GL_UNSIGNED_INT,
                                      (const void *)((size_t)sub->first * sizeof(GLuint)),
                                      m->ninst);
            if (blended) {
                gl->DepthMask(GL_TRUE);
                gl->Disable(GL_BLEND);
            }
        }
    }
    set_material(g, gl, NULL);
    return 1;
}

int ww_geometry_draw_count(const ww_geometry *g) { return g ? g->draws : 0; }

int ww_geometry_has_hulls(const ww_geometry *g) { return g && g->hull_cap.cap > 0; }

int ww_geometry_has_bubbles(const ww_geometry *g) { return g && g->slot[SLOT_BUBBLE].cap > 0; }

int ww_geometry_has_line(const ww_geometry *g) { return g && g->strand[0].vao != 0; }

int ww_geometry_has_wake(const ww_geometry *g) { return g && g->wake.vao != 0; }

/* the uniforms every draw of a frame shares, into program v (in use) */
static void set_uniforms(ww_geometry *g, const geom_prog *v, ww_renderer *r, const ww_frame *f,
                         ww_geom_mode mode, mat4 view_proj, const float *clip) {
    const ww_gl *gl = r->gl;
    const ww_scene *sc = f->sc;
    const ww_state *st = f->st;
    ww_sky_locs_set(gl, &v->sky, st);
    gl->UniformMatrix4fv(v->view_proj, 1, GL_FALSE, (const GLfloat *)view_proj);
    if (clip) gl->Uniform4f(v->clip, clip[0], clip[1], clip[2], clip[3]);
    else gl->Uniform4f(v->clip, 0.0f, 0.0f, 0.0f, 1.0f);
    /* the prepass keeps what lies on the far side of the wave surface itself (geometry.vert.glsl):
     * cut at the plane of the highest crest, a cube's top above the water stayed in the image the
     * water refracts, and the bilinear lookups bled it into the water around the cube as a pale
     * rim. The reflection's plane is the surface over the camera: an instance wholly under the
     * surface where it lies, under a crest, but over that plane was mirrored, lit as if in air,
     * and showed on the water as if it floated; such an instance is dropped, and one small
     * against the waves is mirrored and clipped about the surface over it */
    int prepass = mode == WW_GEOM_PREPASS || mode == WW_GEOM_PREPASS_DEPTH;
    int mirror = mode == WW_GEOM_REFLECTION;
    float side = clip && (prepass || mirror) && g->surface_clip
                     ? (f->underwater || mirror ? -1.0f : 1.0f)
                     : 0.0f;
    g->cut_side = g->cut_now = side;
    g->cut_mode = side != 0.0f && mirror ? 1.0f : 0.0f;
    g->cut_level = (float)(sc->water_level - f->cam_pos[1]);
    gl->Uniform4f(v->clip_surface, side, g->cut_level, g->cut_mode, g->slope);
    g->var[v - g->var].cut_set = side;
    g->var[v - g->var].cut_mode_set = g->cut_mode;
    g->inside_now = 0;
    gl->Uniform1i(v->inside, 0);
    g->var[v - g->var].inside_set = 0;
    float water_y = (float)(f->surface_y - f->cam_pos[1]);
    gl->Uniform3f(v->ambient, (float)st->ambient[0], (float)st->ambient[1], (float)st->ambient[2]);
    /* reflections see the world from the camera mirrored about the water plane */
    gl->Uniform3f(v->eye, 0.0f, mode == WW_GEOM_REFLECTION ? 2.0f * water_y : 0.0f, 0.0f);
    /* ... whose path to a point is air all the way: no under-water fog on it */
    gl->Uniform1i(v->mirrored, mode == WW_GEOM_REFLECTION);
    gl->Uniform1i(v->scatter_through, mode == WW_GEOM_PREPASS);
    gl->Uniform1f(v->water_y, water_y);
    gl->Uniform1f(v->mirror_reach, g->mirror_reach);
    double hz[3];
    ww_sky_horizon(sc, st, hz);
    const double *fog = sc->fog_color[0] < 0.0 ? hz : sc->fog_color;
    gl->Uniform3f(v->fog_color, (float)fog[0], (float)fog[1], (float)fog[2]);
    gl->Uniform1f(v->fog_density, (float)sc->fog_density);
    double fb[3];
    ww_fog_below_color(sc, st, fb);
    gl->Uniform3f(v->fog_below_color, (float)fb[0], (float)fb[1], (float)fb[2]);
    gl->Uniform1f(v->fog_below_density, (float)sc->render.fog_below_density);
    gl->Uniform3f(v->extinction, (float)WATER_EXTINCTION_R, (float)WATER_EXTINCTION_G,
                  (float)WATER_EXTINCTION_B);
    gl->Uniform1f(v->caustics_loc, g->caustics ? (float)sc->render.water.caustics_strength : 0.0f);

    /* the sun's shadow map, when the shadow pass drew one this frame */
    int shadowed = mode != WW_GEOM_SHADOW && mode != WW_GEOM_PREPASS_DEPTH &&
                   r->shared.shadow_map != 0;
    /* 2: in a stencilled shadow, no sunlight (shadow.glsl) */
    gl->Uniform1i(v->shadow_on, g->stage == WW_GEOM_STAGE_SUNLESS ? 2 : shadowed);
    gl->Uniform1i(v->shadow_map, WW_TEX_SHADOW);
    /* the sunlight's bend at the water (shadow.glsl): the map's casters and receivers, or the
     * projected shadows' casters (their mark stage) */
    gl->Uniform1i(v->shadow_bend, mode != WW_GEOM_SHADOW           ? 0
                                  : g->stage == WW_GEOM_STAGE_MARK ? 2
                                                                   : 1);
    if (shadowed || mode == WW_GEOM_SHADOW) {
        double u[3];
        ww_sun_in_water(st->sun_dir, u);
        gl->Uniform4f(v->shadow_water, (float)u[0], (float)u[1], (float)u[2],
                      (float)(sc->water_level - f->cam_pos[1]));
    }
    if (shadowed) {
        int size = sc->render.shadows.size;
        gl->ActiveTexture(GL_TEXTURE0 + WW_TEX_SHADOW);
        gl->BindTexture(GL_TEXTURE_2D, r->shared.shadow_map);
        gl->ActiveTexture(GL_TEXTURE0);
        gl->UniformMatrix4fv(v->sun_view_proj, 1, GL_FALSE, (const GLfloat *)r->shared.sun_view_proj);
        /* a texel in metres: the orthographic map spans 2 / |row 0| of its matrix */
        const float(*m)[4] = (const float(*)[4])r->shared.sun_view_proj;
        float row = sqrtf(m[0][0] * m[0][0] + m[1][0] * m[1][0] + m[2][0] * m[2][0]);
        gl->Uniform3f(v->shadow_filter, 1.0f / (float)size, (float)sc->render.shadows.softness,
                      2.0f / (row * (float)size));
    }
    put_lights(g, gl, &v->lights,
               mode == WW_GEOM_SHADOW || mode == WW_GEOM_PREPASS_DEPTH ? 0 : g->nlights);
    if (g->caustics == 2) {
        gl->ActiveTexture(GL_TEXTURE0 + WW_TEX_CAUSTIC_SET);
        gl->BindTexture(GL_TEXTURE_2D_ARRAY, g->caustic_tex);
        gl->ActiveTexture(GL_TEXTURE0);
        gl->Uniform1i(v->cset_loc, WW_TEX_CAUSTIC_SET);
        gl->Uniform4fv(v->cset_at_loc, 1, g->cset_at);
        gl->Uniform2fv(v->cset_frame_loc, 1, g->cset_frame);
    } else if (g->caustics || g->surface_clip || g->wake_on) {
        gl->BindBufferBase(GL_UNIFORM_BUFFER, WW_UBO_WAVES, g->ubos.waves);
        gl->Uniform4fv(v->detail_loc, WW_WATER_NDETAIL, &g->detail[0][0]);
        gl->Uniform4fv(v->dudv_m_loc, 2, &g->dudv_m[0][0]);
        gl->Uniform2fv(v->dudv_o_loc, 2, &g->dudv_o[0][0]);
        /* the ripples' height per unit of noise: water.frag.glsl's DETAIL_SLOPE times a cell */
        double scale = sc->render.water.distortion_scale;
        gl->Uniform2f(v->dudv_h_loc, scale > 0.0 ? (float)(WATER_DETAIL_SLOPE / scale) : 0.0f, 0.0f);
    }

    gl->Uniform1i(v->mat_map, WW_TEX_MATERIAL);
    put_material(gl, v, NULL, 0);
}

void ww_geometry_draw_parts(ww_geometry *g, ww_renderer *r, const ww_frame *f,
                            ww_geom_mode mode, mat4 view_proj, const float *clip, unsigned parts) {
    const ww_gl *gl = r->gl;
    upload_instances(g, gl, f);
    /* every program the scene has gets the frame's uniforms: the glow column and the hulls'
     * lids drawn after this with their own programs read them */
    for (int k = 0; k < GEOM_PROGS; k++)
        if (g->var[k].prog) set_uniforms(g, use(g, gl, k), r, f, mode, view_proj, clip);
    use(g, gl, mode == WW_GEOM_SHADOW || mode == WW_GEOM_PREPASS_DEPTH ? GEOM_DEPTH : GEOM_LIT);
    use_lit(g, gl, GEOM_LIT); /* without the sun in the stencilled shadows' second draw */
    if (clip) gl->Enable(GL_CLIP_DISTANCE0);
    else gl->Disable(GL_CLIP_DISTANCE0);
    /* the reflection clips an instance the waves reach at the surface over it, which lies up to
     * the crest's height twice below the pass's plane: a draw is skipped only below that */
    const float *skip = clip;
    float lowered[4];
    if (clip && g->cut_mode != 0.0f) {
        memcpy(lowered, clip, sizeof lowered);
        lowered[3] += 2.0f * (float)g->crest * fabsf(clip[1]);
        skip = lowered;
    }

    gl->Enable(GL_DEPTH_TEST);
    /* stencilled shadows: the shadowed pixels drawn again where they lie (the same program and
     * vertices give the same depth), or the casters' outlines tested against what is drawn */
    gl->DepthFunc(g->stage == WW_GEOM_STAGE_SUNLESS ? GL_EQUAL
                  : g->stage == WW_GEOM_STAGE_MARK  ? GL_LEQUAL
                                                    : GL_LESS);
    gl->DepthMask(g->stage == WW_GEOM_STAGE_NORMAL ? GL_TRUE : GL_FALSE);
    if (g->sway) gl->Uniform4f(g->cur->sway_loc, 0.0f, 0.0f, 0.0f, 0.0f); /* the meshes are rigid */
    int draws = 0;
    /* the seabed receives shadows but casts none worth a map */
    for (int s = 0; s < SLOT_COUNT; s++) {
        /* a splash's drops: no shadow, and no mirror image, which would show their unlit
         * undersides as dark specks under the splash */
        if (s == SLOT_COLUMN || s == SLOT_BUBBLE ||
            ((s == SLOT_SEABED || s == SLOT_SPRAY) && mode == WW_GEOM_SHADOW) ||
            (s == SLOT_SPRAY && mode == WW_GEOM_REFLECTION))
            continue;
        if (!(parts & (s == SLOT_SEABED ? WW_GEOM_PART_SEABED : WW_GEOM_PART_SOLIDS))) continue;
        if (g->slot[s].ninst <= 0 || clipped_away(skip, &g->slot[s]) ||
            outside_view(view_proj, &g->slot[s], 0.0f))
            continue;
        use_lit(g, gl, slot_patterned(s) ? GEOM_LIT_FISH : GEOM_LIT);
        cut_for(g, gl, &g->slot[s]);
        /* what rests on the seabed (a starfish, a plant's foot) has faces in its plane, where
         * the depths' rounding alone decided which was in front, pixel by pixel and differently
         * from one Mesa release to the next (and from one grid of the seabed to another): the
         * seabed's depth comes two steps toward the eye, so the sand covers them. Every draw of
         * it takes the same offset, so the shadows' redraw (GL_EQUAL) still meets its depth */
        if (s == SLOT_SEABED) {
            gl->Enable(GL_POLYGON_OFFSET_FILL);
            gl->PolygonOffset(0.0f, SEABED_OFFSET_UNITS);
        }
        draws += draw_mesh(gl, &g->slot[s]);
        if (s == SLOT_SEABED) gl->Disable(GL_POLYGON_OFFSET_FILL);
    }
    for (int i = 0; (parts & WW_GEOM_PART_SOLIDS) && i < g->nobj; i++) {
        if (clipped_away(skip, &g->obj[i]) ||
            outside_view(view_proj, &g->obj[i], g->sway ? fabsf(g->obj_sway[i][0]) : 0.0f))
            continue;
        cut_for(g, gl, &g->obj[i]);
        draws += draw_obj(g, gl, i, mode);
    }
    g->cut_now = g->cut_side;
    g->inside_now = 0;
    if (g->sway) gl->Uniform4f(g->cur->sway_loc, 0.0f, 0.0f, 0.0f, 0.0f); /* later draws are rigid */
    if ((parts & WW_GEOM_PART_WAKE) && mode == WW_GEOM_MAIN && g->wake.ninst > 0) {
        /* the wake on the water, under what floats (tested against depth, never written) */
        use(g, gl, GEOM_WAKE);
        gl->Enable(GL_BLEND);
        gl->BlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA); /* premultiplied */
        gl->DepthMask(GL_FALSE);
        draws += draw_mesh(gl, &g->wake);
        gl->Disable(GL_BLEND);
    }
    if ((parts & WW_GEOM_PART_BUBBLES) && mode == WW_GEOM_MAIN && g->slot[SLOT_BUBBLE].ninst > 0) {
        /* over everything already drawn, the sky included; tested against depth, never written */
        use(g, gl, GEOM_BUBBLE);
        gl->Enable(GL_BLEND);
        gl->BlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA); /* premultiplied: rim light, then cover */
        gl->DepthMask(GL_FALSE);
        draws += draw_mesh(gl, &g->slot[SLOT_BUBBLE]);
        gl->Disable(GL_BLEND);
    }
    if ((parts & WW_GEOM_PART_LINE) && mode == WW_GEOM_MAIN && g->strand[0].vao) {
        /* the rod and the line over everything, tested against depth, never written: each
         * pixel they cross takes their coverage of it (premultiplied). The line last: it lies
         * on the rod's top */
        use(g, gl, GEOM_LINE);
        gl->Enable(GL_BLEND);
        gl->BlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
        gl->DepthMask(GL_FALSE);
        draws += draw_mesh(gl, &g->strand[WW_STRAND_ROD]);
        draws += draw_mesh(gl, &g->strand[WW_STRAND_LINE]);
        gl->Disable(GL_BLEND);
    }

    g->glow_clip = clip != NULL;
    /* a pass that draws its parts in several calls counts them from the one with the solids */
    g->draws = (parts & WW_GEOM_PART_SOLIDS) ? draws : g->draws + draws;
    gl->DepthFunc(GL_LESS);
    gl->DepthMask(GL_TRUE);
    gl->BindVertexArray(0);
    gl->Disable(GL_CLIP_DISTANCE0);
}

/* this frame's lights into another program that includes common.glsl (the water's), which must
 * be in use: the same camera-relative positions, directions, colours and ranges the geometry
 * is lit by */
void ww_geometry_lights_set(ww_geometry *g, const ww_gl *gl, const ww_frame *f, GLuint prog) {
    if (!g) return;
    upload_instances(g, gl, f); /* once per frame: the lights follow their parents */
    light_locs l = find_lights(gl, prog);
    put_lights(g, gl, &l, g->nlights);
}

/* the chest's glow column: additive light drawn after the sky, never into depth. Drawn before
 * the sky, the sky pass (depth still clear there) overwrote it wherever nothing opaque lay
 * behind: everything below the horizon without a seabed, and the one-pixel row at eye level
 * where neither the water nor the seabed reaches. Uses the uniforms the last
 * ww_geometry_draw set (a program keeps them). */
void ww_geometry_draw_glow(ww_geometry *g, ww_renderer *r, ww_geom_mode mode) {
    const ww_gl *gl = r->gl;
    if (!g || (mode != WW_GEOM_MAIN && mode != WW_GEOM_REFLECTION) ||
        g->slot[SLOT_COLUMN].ninst <= 0)
        return;
    const geom_prog *v = use(g, gl, GEOM_GLOW);
    cut_for(g, gl, &g->slot[SLOT_COLUMN]); /* the reflection's cut by the column's own box */
    gl->Uniform4f(v->glow, g->glow_cyl[0], g->glow_cyl[1], g->glow_cyl[2], g->glow_cyl[5]);
    gl->Uniform2f(v->glow_y, g->glow_cyl[3], g->glow_cyl[4]);
    if (g->glow_clip) gl->Enable(GL_CLIP_DISTANCE0);
    gl->Enable(GL_DEPTH_TEST);
    gl->DepthFunc(GL_LESS);
    gl->Enable(GL_BLEND);
    gl->BlendFunc(GL_ONE, GL_ONE);
    gl->DepthMask(GL_FALSE);
    g->draws += draw_mesh(gl, &g->slot[SLOT_COLUMN]);
    gl->DepthMask(GL_TRUE);
    gl->Disable(GL_BLEND);
    gl->Disable(GL_CLIP_DISTANCE0);
    gl->BindVertexArray(0);
}

void ww_geometry_draw(ww_geometry *g, ww_renderer *r, const ww_frame *f, ww_geom_mode mode,
                      mat4 view_proj, const float *clip) {
    ww_geometry_draw_parts(g, r, f, mode, view_proj, clip, WW_GEOM_PART_ALL);
}

/* the lid over each hull's inside into depth alone. Drawn after the hull and before the water,
 * it hides the water under it (what fills a hull's inside in a wave or below the waterline)
 * while the inside, drawn already, keeps its colour; its faces point up, so from below (under
 * water, or an eye lower than the gunwale) it is culled and hides nothing */
void ww_geometry_draw_hull_mask(ww_geometry *g, ww_renderer *r, const ww_frame *f,
                                mat4 view_proj) {
    const ww_gl *gl = r->gl;
    upload_instances(g, gl, f);
    if (g->hull_cap.ninst <= 0) return;
    const geom_prog *v = use(g, gl, GEOM_DEPTH);
    gl->UniformMatrix4fv(v->view_proj, 1, GL_FALSE, (const GLfloat *)view_proj);
    gl->Disable(GL_CLIP_DISTANCE0);
    gl->Uniform4f(v->clip, 0.0f, 0.0f, 0.0f, 1.0f);
    gl->Enable(GL_DEPTH_TEST);
    gl->DepthFunc(GL_LESS);
    gl->DepthMask(GL_TRUE);
    gl->ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    gl->Enable(GL_CULL_FACE);
    gl->CullFace(GL_BACK);
    draw_mesh(gl, &g->hull_cap);
    gl->Disable(GL_CULL_FACE);
    gl->ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl->BindVertexArray(0);
}

void ww_geometry_set_stage(ww_geometry *g, ww_geom_stage stage) {
    if (g) g->stage = stage;
}

void ww_geometry_each_caster(ww_geometry *g, ww_caster_fn fn, void *user) {
    if (!g || !g->keep_casters) return;
    for (int s = 0; s < SLOT_COUNT; s++) {
        const gmesh *m = &g->slot[s];
        if (!m->copy || !g->caster_mesh[s].vertex) continue;
        int rigid = s != SLOT_FISH && !slot_patterned(s); /* fish swim: their bodies bend */
        for (int i = 0; i < m->ninst; i++) fn(user, s, &g->caster_mesh[s], m->copy[i].model, rigid);
    }
    /* a swaying plant is bent in the vertex shader; a volume from its rigid mesh would stand
     * still under it, so plants cast no stencilled shadow (the shadow map, drawn through the
     * same vertex shader, sways with them) */
    for (int i = 0; i < g->nobj; i++)
        if (g->obj[i].copy && g->obj[i].ninst > 0 && g->obj_data[i] &&
            !(g->sway && g->obj_sway[i][0] > 0.0f))
            fn(user, SLOT_COUNT + i, g->obj_data[i], g->obj[i].copy[0].model, 1);
}
