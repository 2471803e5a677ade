/* water.c - the water surface: a static polar mesh built once (rings whose spacing grows
 * geometrically from 0.5 m to the horizon, scene/plan.h), re-centred each frame on the camera
 * snapped to a 0.5 m grid and displaced in the vertex shader by the scene's wave family and its
 * ripples (shaders/gerstner.glsl, the formulas of src/sim/waves.h and src/sim/ripples.c,
 * packed by waveblock.c), then shaded by water.frag.glsl with the optics the earlier passes of
 * the frame left (reflection, prepass) and foam's memory where the scene can fold.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/mathx.h"
#include "gfx/render_impl.h"
#include "sim/ripples.h"

#define WATER_SKIRT_R 1e6       /* the skirt ring's radius, m: within 0.06 deg of the horizon
                                 * seen from 1 km up */
#define WATER_SKIRT_MIN_FAR 1e3 /* far clips nearer than this (m) are a deliberate cut: no skirt */

#define WATER_FOAM_WAVES 4  /* water.frag.glsl: FOAM_WAVES */
#define WATER_FOAM_TAPS 4   /* water.frag.glsl: FOAM_TAPS */
#define WATER_FOAM_SPAN 2.0 /* lives the taps reach back over: exp(-2) = 13.5% left at the last */

/* one build of the water program. llvmpipe runs both arms of a branch for every pixel (it masks
 * lanes, it does not jump), so what a frame cannot use is left out at compile time: the side of
 * the surface the camera is on and which of the earlier passes' images there are to read are
 * #defines, not uniforms (WW_UNDERWATER, WW_REFLECT_TEX, WW_REFRACT_TEX); the program for a
 * combination is built the first time a frame needs it. About 15% of the lake's main pass. */
typedef struct water_prog {
    GLuint prog;
    ww_sky_locs sky;
    GLint view_proj, origin, ugrid;
    GLint water_color, ambient, fog_color, fog_density, pixel_angle;
    GLint fresnel, specular, distort, dudv_m, dudv_o, cam_axes, inv_size, clip_range;
    GLint reflection, scene_color, scene_depth, scene_depth_full, sky_cube, sky_dome;
    GLint sky_intensity, murk, foam, fog_below_color, fog_below_density, alpha;
    GLint detail, skirt, foam_wave, foam_phase, foam_step, foam_memory, dudv_grad;
    GLint gbuf_pos, gbuf_rest, gbuf_tag; /* the resolve's G-buffer (WW_WATER_RESOLVE) */
    GLint reflection_near, near_levels, reflection_depth, mirror; /* WW_REFLECT_DEPTH */
} water_prog;

/* WATER_EDGES: the prepass's depth at the frame's size is there to upsample its colour by */
enum { WATER_UNDER = 1, WATER_REFL = 2, WATER_REFR = 4, WATER_EDGES = 8, WATER_VARIANTS = 16 };

/* The water shaded once a pixel, where the main pass plans a G-buffer (its water_pos and
 * water_rest targets): the mesh draws only what the shading reads (the camera-relative surface
 * point and window depth, the rest offset, and the frame's tag) and sets a stencil bit where it
 * is in front; then one full-screen draw of the variant's resolve build shades the pixels with
 * the bit, and clears it. llvmpipe shades a block of pixels once for every triangle that
 * crosses it, and the rings beyond a few tens of metres are thinner than a pixel, so the mesh
 * drawn with the full shading paid for it many times over; the stencil test is what llvmpipe
 * skips blocks by (a discard would not be). WW_WATER_FORWARD=1 shades the mesh's fragments
 * instead, to compare. */
#define GBUF_BIT 0x80 /* the stencil bit of the water's pixels, clear again before the shadows
                       * count in the same stencil */
#define GBUF_TAG_WRAP 16777215.0f /* tags 1 .. 2^24 - 1: exact in a float */

struct ww_water {
    water_prog var[WATER_VARIANTS]; /* by the WATER_* bits; prog 0: not built yet */
    water_prog resolve[WATER_VARIANTS]; /* the same, shading from the G-buffer */
    int forward;                        /* WW_WATER_FORWARD=1: no G-buffer */
    int mirror_depth; /* the reflection mirrors objects: its depths are read (WW_REFLECT_DEPTH) */
    GLuint gbuf_prog, gbuf_fbo;         /* the mesh into the G-buffer; 0: not made yet */
    GLint gbuf_view_proj, gbuf_origin, gbuf_grid, gbuf_skirt, gbuf_tag;
    float tag;                          /* this frame's, written with the values */
    char defines[1024];             /* the scene's own, shared by every variant */
    int fade;                       /* WW_FADE (WW_WATER_FADE=0 turns it off) */
    GLuint vao, vbo, ibo;
    GLsizei ninner;     /* indices of the inner disc (drawn whole), first in the buffer */
    GLsizei per_seg;    /* indices of one angular segment of the outer rings, after the disc */
    int nseg;           /* segments around the mesh (render.grid) */
    double inner_r;     /* radius of the inner disc's outer ring, m */
    int cull;           /* draw only the segments in view (WW_WATER_CULL=0 turns it off) */
    int band;           /* the flat rings as one band (WW_WATER_BAND=0 keeps every ring) */
    float grid[3]; /* (s0, q - 1, angular step) for the shaders' spacing estimate */
    GLuint dudv_tex; /* water.look.detail: texture: the DuDv noise's gradient, tiled; 0: exact */
    int foam_n;                      /* components foam's memory re-evaluates, 0: none */
    int foam_slot[WATER_FOAM_WAVES]; /* their upload slots */
    float skirt_r; /* rest radius from which vertices belong to the skirt, m (huge: none) */
    ww_water_ubos ubos;
    ww_water_waves waves;    /* the components in upload order; phases set per frame */
    ww_ripple_block ripples; /* filled per frame when the scene has ripples */
};

/* the components foam's memory re-evaluates at past instants (water.frag.glsl): the
 * WATER_FOAM_WAVES that fold or steepen the surface most, and none (the code is not even built
 * into the shader) when the whole field can never cover half of a point with foam: then only
 * the rare meeting of every crest foams, and the lace of what it leaves would hardly show, for
 * about a tenth more per frame (scenes/demo.yaml, bound 0.37, differed in one pixel). Bounds,
 * reached only where every crest meets: with S = sum Q A k the Jacobian stays above (1 - S)^2,
 * and the slope m below sum A k e / (1 - S); the shader's ramps (FOLD_J_*, STEEP_*) turn them
 * into coverages */
#define FOAM_J_FULL 0.2  /* water.frag.glsl: FOLD_J_FULL, FOLD_J_NONE, STEEP_LO, STEEP_HI */
#define FOAM_J_NONE 0.9
#define FOAM_STEEP_LO 0.1
#define FOAM_STEEP_HI 0.6
#define FOAM_VISIBLE 0.5 /* the least coverage the field must be able to reach */
/* whether the scene's waves can foam enough for aged foam to show (the bounds above) */
static int foam_remembers(const ww_scene *sc) {
    const ww_water_look *lk = &sc->render.water;
    if (!lk->foam || lk->foam_amount <= 0.0 || lk->foam_life <= 0.0) return 0;
    if (sc->wave_model == WW_WAVES_FLAT) return 0;
    int gerstner = sc->wave_model == WW_WAVES_GERSTNER || sc->wave_model == WW_WAVES_SPECTRUM;
    double fold = 0.0, slope = 0.0;
    for (int i = 0; i < sc->nwaves && i < WW_MAX_WAVES; i++) {
        const ww_wave *wv = &sc->waves[i];
        double ak = wv->amplitude * wv->k;
        fold += (gerstner ? wv->steepness : 0.0) * ak;
        slope += ak * (wv->exponent > 1.0 ? wv->exponent : 1.0);
    }
    double jmin = fold < 1.0 ? (1.0 - fold) * (1.0 - fold) : 0.0;
    double m = slope / fmax(1.0 - fold, 1e-3);
    double cover = fmax(1.0 - ww_m_smoothstep(FOAM_J_FULL, FOAM_J_NONE, jmin),
                        ww_m_smoothstep(FOAM_STEEP_LO, FOAM_STEEP_HI, 1.0 - 1.0 / sqrt(1.0 + m * m)));
    return cover >= FOAM_VISIBLE;
}

static void foam_components(const ww_scene *sc, ww_water *w) {
    w->foam_n = 0;
    if (!foam_remembers(sc)) return;
    const ww_wave_block *b = &w->waves.block;
    double strength[WW_MAX_WAVES];
    for (int i = 0; i < b->n; i++) {
        const ww_wave *wv = &sc->waves[w->waves.order[i]];
        double e = wv->exponent > 1.0 ? wv->exponent : 1.0;
        strength[i] = wv->amplitude * wv->k * (e + b->wave[i][3]);
    }
    for (int n = 0; n < WATER_FOAM_WAVES && n < b->n; n++) {
        int best = -1;
        for (int i = 0; i < b->n; i++) {
            int taken = 0;
            for (int j = 0; j < n; j++) taken |= w->foam_slot[j] == i;
            if (!taken && (best < 0 || strength[i] > strength[best])) best = i;
        }
        w->foam_slot[n] = best;
        w->foam_n = n + 1;
    }
}

/* water.look.detail: texture. The DuDv noise (water.frag.glsl: ww_noise, value noise on a
 * lattice that repeats every DUDV_CELLS cells) is a fixed pattern in its cells; only the layers'
 * maps from the water to the cells move. So its gradient is computed once, DUDV_TEXELS texels per
 * cell over the whole period, and read per pixel with repeat wrapping (the tiling is exact) and
 * trilinear mipmaps (the box filter of the gradient, which the shader's fade by the footprint
 * completes), instead of four hashes and the interpolation per layer and pixel. */
#define DUDV_CELLS 256  /* water.frag.glsl: NOISE_MASK + 1 */
#define DUDV_TEXELS 4   /* texels per lattice cell: the gradient is a quadratic in a cell */

/* water.frag.glsl: ww_hash, the same integer hash of a lattice point, in [0, 1] */
static float dudv_hash(unsigned x, unsigned y) {
    uint32_t h = (x & 255u) + (y & 255u) * 256u;
    h = h * 747796405u + 2891336453u;
    h = ((h >> ((h >> 28u) + 4u)) ^ h) * 277803737u;
    h = (h >> 22u) ^ h;
    return (float)h * (1.0f / 4294967295.0f);
}

/* water.frag.glsl: ww_noise's gradient (per cell) at lattice coordinates (x, y) */
static void dudv_gradient(double x, double y, float g[2]) {
    double ix = floor(x), iy = floor(y), fx = x - ix, fy = y - iy;
    double ux = fx * fx * (3.0 - 2.0 * fx), uy = fy * fy * (3.0 - 2.0 * fy);
    double dx = 6.0 * fx * (1.0 - fx), dy = 6.0 * fy * (1.0 - fy);
    unsigned cx = (unsigned)ix, cy = (unsigned)iy;
    double a = dudv_hash(cx, cy), b = dudv_hash(cx + 1u, cy);
    double d = dudv_hash(cx, cy + 1u), e = dudv_hash(cx + 1u, cy + 1u);
    double k = a - b - d + e;
    g[0] = (float)(2.0 * dx * (b - a + k * uy));
    g[1] = (float)(2.0 * dy * (d - a + k * ux));
}

static ww_result dudv_texture(ww_water *w, const ww_gl *gl, ww_error *err) {
    const int n = DUDV_CELLS * DUDV_TEXELS;
    float *t = malloc((size_t)n * (size_t)n * 2 * sizeof *t);
    if (!t) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "water: out of memory for the DuDv texture");
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) /* texel centres, in cells */
            dudv_gradient((i + 0.5) / DUDV_TEXELS, (j + 0.5) / DUDV_TEXELS, &t[2 * ((size_t)j * n + i)]);
    gl->GenTextures(1, &w->dudv_tex);
    gl->BindTexture(GL_TEXTURE_2D, w->dudv_tex);
    gl->TexImage2D(GL_TEXTURE_2D, 0, GL_RG16F, n, n, 0, GL_RG, GL_FLOAT, t);
    ww_gfx_mipmap_tiled(gl, GL_TEXTURE_2D);
    gl->BindTexture(GL_TEXTURE_2D, 0);
    free(t);
    return WW_OK;
}

/* a ring counts as flat from this fraction beyond the radius where the fade ends */
#define FLAT_MARGIN 1e-3

/* the two triangles between rings j and j2 (> j) in segment i */
static size_t quad(GLuint *idx, size_t k, int nseg, int j, int j2, int i) {
    GLuint a = (GLuint)(1 + j * nseg + i), b = (GLuint)(1 + j * nseg + (i + 1) % nseg);
    GLuint c = a + (GLuint)((j2 - j) * nseg), d = b + (GLuint)((j2 - j) * nseg);
    idx[k++] = a; idx[k++] = b; idx[k++] = c;
    idx[k++] = b; idx[k++] = d; idx[k++] = c;
    return k;
}

/* centre vertex, then m.rings rings of m.segments vertices; indexed triangles in
 * two blocks: the inner disc (a fan and the rings within WW_WATER_INNER_R), then the outer rings
 * one angular segment after another, so that a wedge of segments is one contiguous range and the
 * draw can skip what lies outside the view (water_draw). Beyond the radius where the mesh lies
 * flat, one band stands for the rings (their vertices stay in the buffer, unused). The layout is
 * the plan's (scene/plan.h), which reports where the spacing fades each wave. */
static ww_result build_mesh(ww_water *w, const ww_gl *gl, const ww_scene *sc, ww_error *err) {
    ww_water_mesh m;
    ww_water_mesh_layout(sc->far_clip, sc->render.grid, &m);
    double far_clip = sc->far_clip;
    const int nseg = m.segments, nring = m.rings;
    w->nseg = nseg;
    double q = m.q, s0 = m.s0, dtheta = m.dtheta;
    w->grid[0] = (float)s0;
    w->grid[1] = (float)(q - 1.0);
    w->grid[2] = (float)dtheta;

    size_t nvert = 1 + (size_t)nring * (size_t)nseg;
    size_t nidx = (size_t)nseg * 3 + (size_t)(nring - 1) * (size_t)nseg * 6;
    float *v = malloc(nvert * 2 * sizeof *v);
    GLuint *idx = malloc(nidx * sizeof *idx);
    if (!v || !idx) {
        free(v);
        free(idx);
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "water: out of memory for the mesh");
    }

    /* vertices: ring j (1-based) at radius s0 (q^j - 1) / (q - 1), or j s0 when q = 1. With a far
     * clip of a kilometre or more the last ring is a skirt pushed out to WATER_SKIRT_R, where the
     * plane seen from any height a camera takes lies within a pixel of the horizon: the water
     * then meets the sky at the horizon, fogged into it, instead of ending in a hard band at the
     * far clip (the vertex shader keeps the skirt's depth inside the far plane) */
    int skirt = far_clip >= WATER_SKIRT_MIN_FAR && nring > 2 && m.reach < WATER_SKIRT_R;
    w->skirt_r = skirt ? (float)(0.5 * WATER_SKIRT_R) : 1e30f;
    /* beyond the flat radius the vertex shader moves no vertex, so the rings there lie in the
     * rest plane and one band from the first of them to the last ring before the skirt draws
     * what they drew, its position and rest offset interpolated across it exactly as across
     * theirs (both are affine over a plane). Their rings grow with the distance, so from tens of
     * metres out each was a fraction of a pixel tall on screen, and llvmpipe shaded each 4x4 block
     * near the horizon once for every one of the many thin triangles crossing it (the margin keeps
     * the shader's float spacing clear of the fade's end) */
    double flat_r = w->fade && w->band ? ww_water_flat_beyond(sc, &m) * (1.0 + FLAT_MARGIN)
                                       : INFINITY;
    int last = skirt ? nring - 2 : nring - 1; /* the last ring before the skirt */
    int first_flat = nring;                   /* the first ring at or beyond flat_r */
    v[0] = v[1] = 0.0f;
    double r = 0.0, step = s0;
    int ninner = 1; /* rings in the inner disc */
    for (int j = 0; j < nring; j++) {
        r += step;
        step *= q;
        if (skirt && j == nring - 1) r = WATER_SKIRT_R;
        if (r <= WW_WATER_INNER_R || j == 0) {
            ninner = j + 1;
            w->inner_r = r;
        }
        if (r >= flat_r && j < first_flat) first_flat = j;
        for (int i = 0; i < nseg; i++) {
            size_t at = 1 + (size_t)j * (size_t)nseg + (size_t)i;
            v[2 * at] = (float)(r * cos(i * dtheta));
            v[2 * at + 1] = (float)(r * sin(i * dtheta));
        }
    }

    /* triangles: a fan around the centre, then two per quad between neighbouring rings */
    size_t k = 0;
    for (int i = 0; i < nseg; i++) {
        idx[k++] = 0;
        idx[k++] = (GLuint)(1 + (i + 1) % nseg);
        idx[k++] = (GLuint)(1 + i);
    }
    for (int j = 0; j + 1 < ninner; j++)
        for (int i = 0; i < nseg; i++) k = quad(idx, k, nseg, j, j + 1, i);
    w->ninner = (GLsizei)k;
    /* the outer rings each segment's quads join, in order: every ring up to the first flat one
     * (never one inside the disc), then the last before the skirt, then the skirt */
    int *chain = malloc((size_t)nring * sizeof *chain), n = 0;
    if (!chain) {
        free(v);
        free(idx);
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "water: out of memory for the mesh");
    }
    if (first_flat < ninner - 1) first_flat = ninner - 1;
    for (int j = ninner - 1; j < nring; j++)
        if (j <= first_flat || j >= last) chain[n++] = j;
    for (int i = 0; i < nseg; i++)
        for (int c = 0; c + 1 < n; c++) k = quad(idx, k, nseg, chain[c], chain[c + 1], i);
    free(chain);
    w->per_seg = (GLsizei)(6 * (n - 1));
    WW_ASSERT(k <= nidx);
    nidx = k;

    gl->GenVertexArrays(1, &w->vao);
    gl->GenBuffers(1, &w->vbo);
    gl->GenBuffers(1, &w->ibo);
    gl->BindVertexArray(w->vao);
    gl->BindBuffer(GL_ARRAY_BUFFER, w->vbo);
    gl->BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(nvert * 2 * sizeof *v), v, GL_STATIC_DRAW);
    gl->EnableVertexAttribArray(0);
    gl->VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), NULL);
    gl->BindBuffer(GL_ELEMENT_ARRAY_BUFFER, w->ibo);
    gl->BufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)(nidx * sizeof *idx), idx, GL_STATIC_DRAW);
    gl->BindVertexArray(0);
    gl->BindBuffer(GL_ARRAY_BUFFER, 0);
    free(v);
    free(idx);
    return WW_OK;
}

/* foam's memory per frame: the chosen components' phases at the centre (already wrapped in
 * the wave block) and their frequencies, and the taps' spacing */
static void set_foam_memory(const ww_water *w, const water_prog *v, const ww_gl *gl,
                            const ww_scene *sc) {
    float wave[WATER_FOAM_WAVES][4] = {{0}}, phase[WATER_FOAM_WAVES][4] = {{0}};
    float step[WATER_FOAM_WAVES][2] = {{0}};
    const ww_wave_block *b = &w->waves.block;
    double life = sc->render.water.foam_life, dt = WATER_FOAM_SPAN * life / WATER_FOAM_TAPS;
    double longest = 0.0;
    for (int j = 0; j < w->foam_n; j++) {
        int i = w->foam_slot[j];
        const ww_wave *wv = &sc->waves[w->waves.order[i]];
        wave[j][0] = b->wave[i][0];
        wave[j][1] = b->wave[i][1];
        wave[j][2] = (float)(b->wave[i][3] * wv->amplitude * wv->k);
        wave[j][3] = (float)(wv->amplitude * wv->k);
        phase[j][0] = b->wave2[i][0];
        phase[j][1] = (float)wv->omega;
        phase[j][2] = (float)(wv->exponent > 1.0 ? wv->exponent : 1.0);
        step[j][0] = (float)cos(wv->omega * dt);
        step[j][1] = (float)sin(wv->omega * dt);
        longest = fmax(longest, WW_TAU / wv->k);
    }
    gl->Uniform4fv(v->foam_wave, WATER_FOAM_WAVES, &wave[0][0]);
    gl->Uniform4fv(v->foam_phase, WATER_FOAM_WAVES, &phase[0][0]);
    gl->Uniform2fv(v->foam_step, WATER_FOAM_WAVES, &step[0][0]);
    gl->Uniform4f(v->foam_memory, (float)w->foam_n, (float)life, (float)dt, (float)longest);
}

/* the scene's own #defines, the same for every variant of the program. The switches a scene
 * keeps for its whole run are built in rather than tested per pixel (see water_prog) */
static void scene_defines(const ww_scene *sc, int foam_n, char *out, size_t size) {
    const ww_water_look *lk = &sc->render.water;
    char detail[400];
    ww_water_detail_define(detail, sizeof detail);
    snprintf(out, size,
             "#define WW_FOAM_MEMORY %d\n#define WW_FOAM_N %d\n#define WW_LIGHT_SCATTER %d\n"
             "#define WW_SKY_DOME_IMAGE %d\n#define WW_DUDV_TEXTURE %d\n"
             "#define WW_SKY_CUBE %d\n#define WW_ALPHA_BLEND %d\n#define WW_FOAM %d\n"
             "#define WW_FRESNEL_SCHLICK %d\n#define WW_LIGHTS %d\n#define WW_NLIGHTS %d\n%s%s",
             foam_remembers(sc), foam_n, ww_lights_scatter_on(sc), ww_sky_dome_image_on(sc),
             lk->detail == WW_DETAIL_TEXTURE, sc->render.sky == WW_SKY_CUBEMAP,
             lk->alpha_blend != 0, lk->foam && lk->foam_amount > 0.0,
             lk->fresnel == WW_FRESNEL_SCHLICK, sc->render.nlights > 0, sc->render.nlights, detail,
             ww_sky_defines(sc));
}

/* builds variant `bits` (WATER_*) of the program, drawn with the mesh or (resolve) over the
 * screen from the G-buffer, and finds its uniforms */
static ww_result build_variant(ww_water *w, const ww_gl *gl, const ww_scene *sc, int bits,
                               int resolve, ww_error *err) {
    water_prog *v = resolve ? &w->resolve[bits] : &w->var[bits];
    /* DuDv distorts and details only what there is a texture of to distort */
    int distort = sc->render.water.distortion > 0.0 && (bits & (WATER_REFL | WATER_REFR));
    char defs[1400];
    snprintf(defs, sizeof defs,
             "#define WW_UNDERWATER %d\n#define WW_REFLECT_TEX %d\n#define WW_REFRACT_TEX %d\n"
             "#define WW_DISTORT %d\n#define WW_WATER_RESOLVE %d\n#define WW_REFRACT_EDGES %d\n"
             "#define WW_REFLECT_DEPTH %d\n%s",
             (bits & WATER_UNDER) != 0, (bits & WATER_REFL) != 0, (bits & WATER_REFR) != 0,
             distort != 0, resolve, (bits & WATER_EDGES) != 0,
             (bits & WATER_REFL) != 0 && w->mirror_depth, w->defines);
    ww_result rc = ww_water_program(gl, sc, resolve ? "fullscreen.vert.glsl" : "water.vert.glsl",
                                    "water.frag.glsl", w->fade, defs, &v->prog, err);
    if (rc != WW_OK) return rc;
    GLuint p = v->prog;
    ww_sky_locs_init(gl, p, sc, &v->sky);
    v->view_proj = ww_gfx_uniform(gl, p, "u_view_proj");
    v->origin = ww_gfx_uniform(gl, p, "u_origin");
    v->ugrid = ww_gfx_uniform(gl, p, "u_grid");
    v->water_color = ww_gfx_uniform(gl, p, "u_water_color");
    v->ambient = ww_gfx_uniform(gl, p, "u_ambient");
    v->fog_color = ww_gfx_uniform(gl, p, "u_fog_color");
    v->fog_density = ww_gfx_uniform(gl, p, "u_fog_density");
    v->pixel_angle = ww_gfx_uniform(gl, p, "u_pixel_angle");
    v->fresnel = ww_gfx_uniform(gl, p, "u_fresnel");
    v->specular = ww_gfx_uniform(gl, p, "u_specular");
    v->distort = ww_gfx_uniform(gl, p, "u_distort");
    v->dudv_m = ww_gfx_uniform(gl, p, "u_dudv_m");
    v->dudv_o = ww_gfx_uniform(gl, p, "u_dudv_o");
    v->cam_axes = ww_gfx_uniform(gl, p, "u_cam_axes");
    v->inv_size = ww_gfx_uniform(gl, p, "u_inv_size");
    v->clip_range = ww_gfx_uniform(gl, p, "u_clip_range");
    v->reflection = ww_gfx_uniform(gl, p, "u_reflection");
    v->reflection_near = ww_gfx_uniform(gl, p, "u_reflection_near");
    v->near_levels = ww_gfx_uniform(gl, p, "u_near_levels");
    v->reflection_depth = ww_gfx_uniform(gl, p, "u_reflection_depth");
    v->mirror = ww_gfx_uniform(gl, p, "u_mirror");
    v->scene_color = ww_gfx_uniform(gl, p, "u_scene_color");
    v->scene_depth = ww_gfx_uniform(gl, p, "u_scene_depth");
    v->scene_depth_full = ww_gfx_uniform(gl, p, "u_scene_depth_full");
    v->sky_cube = ww_gfx_uniform(gl, p, "u_sky_cube");
    v->sky_dome = ww_gfx_uniform(gl, p, "u_sky_dome_image");
    v->sky_intensity = ww_gfx_uniform(gl, p, "u_sky_intensity");
    v->murk = ww_gfx_uniform(gl, p, "u_murk");
    v->foam = ww_gfx_uniform(gl, p, "u_foam");
    v->fog_below_color = ww_gfx_uniform(gl, p, "u_fog_below_color");
    v->fog_below_density = ww_gfx_uniform(gl, p, "u_fog_below_density");
    v->alpha = ww_gfx_uniform(gl, p, "u_alpha");
    v->detail = ww_gfx_uniform(gl, p, "u_detail");
    v->skirt = ww_gfx_uniform(gl, p, "u_skirt_r");
    v->foam_wave = ww_gfx_uniform(gl, p, "u_foam_wave");
    v->foam_phase = ww_gfx_uniform(gl, p, "u_foam_phase");
    v->foam_step = ww_gfx_uniform(gl, p, "u_foam_step");
    v->foam_memory = ww_gfx_uniform(gl, p, "u_foam_memory");
    v->dudv_grad = ww_gfx_uniform(gl, p, "u_dudv_grad");
    v->gbuf_pos = ww_gfx_uniform(gl, p, "u_water_pos");
    v->gbuf_rest = ww_gfx_uniform(gl, p, "u_water_rest");
    v->gbuf_tag = ww_gfx_uniform(gl, p, "u_water_tag");
    return WW_OK;
}

/* the G-buffer's program and its framebuffer over the main pass's targets, made at the first
 * frame that uses them */
static ww_result gbuf_new(ww_water *w, const ww_gl *gl, const ww_scene *sc, const ww_rt *main,
                          ww_error *err) {
    ww_result rc = ww_water_program(gl, sc, "water.vert.glsl", "water_gbuf.frag.glsl", w->fade,
                                    w->defines, &w->gbuf_prog, err);
    if (rc != WW_OK) return rc;
    w->gbuf_view_proj = ww_gfx_uniform(gl, w->gbuf_prog, "u_view_proj");
    w->gbuf_origin = ww_gfx_uniform(gl, w->gbuf_prog, "u_origin");
    w->gbuf_grid = ww_gfx_uniform(gl, w->gbuf_prog, "u_grid");
    w->gbuf_skirt = ww_gfx_uniform(gl, w->gbuf_prog, "u_skirt_r");
    w->gbuf_tag = ww_gfx_uniform(gl, w->gbuf_prog, "u_water_tag");
    gl->GenFramebuffers(1, &w->gbuf_fbo);
    gl->BindFramebuffer(GL_FRAMEBUFFER, w->gbuf_fbo);
    for (int i = 0; i < 2; i++)
        gl->FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + (GLenum)i, GL_TEXTURE_2D,
                                 ww_gfx_rt_texture_nth(main, WW_FMT_RGBA32F, i), 0);
    gl->FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D,
                             ww_gfx_rt_texture(main, WW_FMT_DEPTH24_STENCIL8), 0);
    GLenum bufs[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    gl->DrawBuffers(2, bufs);
    GLenum status = gl->CheckFramebufferStatus(GL_FRAMEBUFFER);
    /* tag 0 is no frame's: a pixel no frame has written is never taken for this frame's
     * (the main pass clears its colour after setting its own clear colour) */
    if (status == GL_FRAMEBUFFER_COMPLETE) {
        gl->ClearColor(0.0f, 0.0f, 0.0f, 0.0f);
        gl->Clear(GL_COLOR_BUFFER_BIT);
    }
    gl->BindFramebuffer(GL_FRAMEBUFFER, main->fbo);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        return ww_error_set(err, WW_E_GL, NULL, 0, 0,
                            "water: the G-buffer's framebuffer is incomplete (0x%04x)",
                            (unsigned)status);
    return WW_OK;
}

ww_result ww_water_new(const ww_gl *gl, const ww_scene *sc, int edges, int mirror_depth,
                       ww_water **out, ww_error *err) {
    ww_water *w = calloc(1, sizeof *w);
    if (!w) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "water: out of memory");
    const char *cull = getenv("WW_WATER_CULL"), *fade = getenv("WW_WATER_FADE");
    const char *band = getenv("WW_WATER_BAND"), *fwd = getenv("WW_WATER_FORWARD");
    w->cull = !(cull && strcmp(cull, "0") == 0);
    w->fade = !(fade && strcmp(fade, "0") == 0);
    w->band = !(band && strcmp(band, "0") == 0);
    w->forward = fwd && strcmp(fwd, "1") == 0;
    w->mirror_depth = mirror_depth;
    ww_water_waves_init(sc, &w->waves);
    foam_components(sc, w);
    scene_defines(sc, w->foam_n, w->defines, sizeof w->defines);
    /* the variant seen from above with the images the scene's passes make: built now, so a
     * shader that does not compile fails here rather than in the middle of a run */
    int first = (sc->render.reflection.on ? WATER_REFL : 0) |
                (sc->render.refraction ? WATER_REFR : 0) | (edges ? WATER_EDGES : 0);
    ww_result rc = build_variant(w, gl, sc, first, 0, err);
    if (rc == WW_OK) rc = build_mesh(w, gl, sc, err);
    if (rc == WW_OK) rc = ww_water_ubos_new(gl, sc, &w->waves, &w->ubos, err);
    if (rc == WW_OK && sc->render.water.detail == WW_DETAIL_TEXTURE) rc = dudv_texture(w, gl, err);
    if (rc != WW_OK) {
        ww_water_free(w, gl);
        return rc;
    }
    *out = w;
    return WW_OK;
}

static void draw_segments(const ww_water *w, const ww_gl *gl, int first, int count) {
    if (count <= 0) return;
    size_t offset = ((size_t)w->ninner + (size_t)first * (size_t)w->per_seg) * sizeof(GLuint);
    gl->DrawElements(GL_TRIANGLES, count * w->per_seg, GL_UNSIGNED_INT, (const void *)offset);
}

/* the wedge of outer segments the view can see: [first, first + count) modulo w->nseg.
 * The frustum is the cone of its four corner rays; unless it holds the vertical (then every
 * azimuth is in view) its shadow on the water plane is a wedge bounded by the corners' azimuths.
 * The margin covers the mesh centre's snap offset and the waves' sideways displacement, both
 * seen from the inner disc's edge, the nearest outer vertex. */
static void visible_segments(const ww_water *w, const ww_frame *f, const double centre[2],
                             int *first, int *count) {
    *first = 0;
    *count = w->nseg;
    if (!w->cull) return;
    double corner = atan(sqrt(f->tan_half[0] * f->tan_half[0] + f->tan_half[1] * f->tan_half[1]));
    double off = hypot(centre[0] - f->cam_pos[0], centre[1] - f->cam_pos[2]);
    off += w->waves.sideways;
    if (off >= w->inner_r) return;
    double margin = asin(off / w->inner_r) + 2.0 * WW_TAU / w->nseg;
    double vert = acos(ww_m_clamp(fabs(f->fwd[1]), 0.0, 1.0)); /* angle to the nearest vertical */
    if (vert <= corner + margin) return;

    double a0 = atan2(f->fwd[2], f->fwd[0]), lo = 0.0, hi = 0.0;
    for (int c = 0; c < 4; c++) {
        double sx = (c & 1) ? 1.0 : -1.0, sy = (c & 2) ? 1.0 : -1.0, d[3];
        for (int k = 0; k < 3; k++)
            d[k] = f->fwd[k] + sx * f->tan_half[0] * f->right[k] + sy * f->tan_half[1] * f->up[k];
        double da = atan2(d[2], d[0]) - a0;
        da -= WW_TAU * floor((da + WW_PI) / WW_TAU); /* to [-pi, pi) */
        if (da < lo) lo = da;
        if (da > hi) hi = da;
    }
    double step = WW_TAU / w->nseg;
    double from = floor((a0 + lo - margin) / step), to = floor((a0 + hi + margin) / step);
    int n = (int)(to - from) + 1;
    if (n >= w->nseg) return;
    int s = (int)fmod(from, (double)w->nseg);
    *first = s < 0 ? s + w->nseg : s;
    *count = n;
}

/* texture units of the water program */
enum { UNIT_REFLECTION = 0, UNIT_SCENE_COLOR, UNIT_SCENE_DEPTH, UNIT_SCENE_DEPTH_FULL,
       UNIT_REFLECTION_NEAR, UNIT_REFLECTION_DEPTH, UNIT_SKY_CUBE, UNIT_SKY_DOME, UNIT_DUDV,
       UNIT_GBUF_POS, UNIT_GBUF_REST };

static void bind_unit(const ww_gl *gl, int unit, GLenum target, GLuint tex) {
    gl->ActiveTexture(GL_TEXTURE0 + (GLenum)unit);
    gl->BindTexture(target, tex);
}

/* the optics' uniforms and textures: what the earlier passes of the frame left (r->shared) */
static void set_optics(const ww_water *w, const water_prog *v, int bits, const ww_renderer *r,
                       const ww_frame *f, const double centre[2]) {
    const ww_gl *gl = r->gl;
    const ww_scene *sc = f->sc;
    const ww_water_look *lk = &sc->render.water;
    const ww_shared *sh = &r->shared;
    int refl = (bits & WATER_REFL) != 0, refr = (bits & WATER_REFR) != 0;
    int edges = (bits & WATER_EDGES) != 0;

    gl->Uniform4f(v->fresnel, lk->fresnel == WW_FRESNEL_SCHLICK ? 1.0f : 0.0f,
                  (float)lk->fresnel_bias, (float)lk->fresnel_scale, (float)lk->fresnel_power);
    gl->Uniform1f(v->specular, (float)lk->specular);
    gl->Uniform2f(v->distort, (float)lk->distortion, (float)lk->distortion_scale);
    float m[2][4], o[2][2];
    ww_water_dudv(sc, f->st, centre, m, o);
    gl->Uniform4fv(v->dudv_m, 2, &m[0][0]);
    gl->Uniform2fv(v->dudv_o, 2, &o[0][0]);

    /* the screen's axes on the water: right, and farther (forward tilted by up, so that a
     * camera looking straight down still has one) */
    double rx = f->right[0], rz = f->right[2], fx = f->fwd[0] + f->up[0], fz = f->fwd[2] + f->up[2];
    double rl = hypot(rx, rz), fl = hypot(fx, fz);
    rl = rl > 1e-9 ? rl : 1.0;
    fl = fl > 1e-9 ? fl : 1.0;
    gl->Uniform4f(v->cam_axes, (float)(rx / rl), (float)(rz / rl), (float)(fx / fl), (float)(fz / fl));
    gl->Uniform2f(v->inv_size, 1.0f / (float)f->width, 1.0f / (float)f->height);
    gl->Uniform2f(v->clip_range, (float)sc->near_clip, (float)sc->far_clip);

    gl->Uniform1i(v->reflection, UNIT_REFLECTION);
    gl->Uniform1i(v->scene_color, UNIT_SCENE_COLOR);
    gl->Uniform1i(v->scene_depth, UNIT_SCENE_DEPTH);
    gl->Uniform1i(v->scene_depth_full, UNIT_SCENE_DEPTH_FULL);
    gl->Uniform1i(v->reflection_near, UNIT_REFLECTION_NEAR);
    gl->Uniform1i(v->near_levels, sh->reflection_near_levels);
    gl->Uniform1i(v->reflection_depth, UNIT_REFLECTION_DEPTH);
    gl->Uniform2f(v->mirror, (float)(sc->water_level - f->cam_pos[1]), (float)f->fwd[1]);
    gl->Uniform1i(v->sky_cube, UNIT_SKY_CUBE);
    gl->Uniform1i(v->sky_dome, UNIT_SKY_DOME);
    gl->Uniform1f(v->sky_intensity, (float)sc->render.sky_intensity);
    gl->Uniform1f(v->murk, (float)lk->murk);
    gl->Uniform1f(v->foam, lk->foam ? (float)lk->foam_amount : 0.0f);
    double fb[3];
    ww_fog_below_color(sc, f->st, fb);
    gl->Uniform3f(v->fog_below_color, (float)fb[0], (float)fb[1], (float)fb[2]);
    gl->Uniform1f(v->fog_below_density, (float)sc->render.fog_below_density);
    gl->Uniform1f(v->alpha, (float)lk->alpha);
    float det[WW_WATER_NDETAIL][4];
    ww_water_detail(f->st, centre, det);
    gl->Uniform4fv(v->detail, WW_WATER_NDETAIL, &det[0][0]);
    if (w->foam_n > 0) set_foam_memory(w, v, gl, sc); /* else the shader has no memory built in */
    bind_unit(gl, UNIT_REFLECTION, GL_TEXTURE_2D, refl ? sh->reflection_tex : 0);
    bind_unit(gl, UNIT_SCENE_COLOR, GL_TEXTURE_2D, refr ? sh->scene_color : 0);
    bind_unit(gl, UNIT_SCENE_DEPTH, GL_TEXTURE_2D, refr ? sh->scene_depth : 0);
    bind_unit(gl, UNIT_SCENE_DEPTH_FULL, GL_TEXTURE_2D, edges ? sh->scene_depth_full : 0);
    bind_unit(gl, UNIT_REFLECTION_NEAR, GL_TEXTURE_2D,
              refl && w->mirror_depth ? sh->reflection_near : 0);
    bind_unit(gl, UNIT_REFLECTION_DEPTH, GL_TEXTURE_2D,
              refl && w->mirror_depth ? sh->reflection_depth : 0);
    bind_unit(gl, UNIT_SKY_CUBE, GL_TEXTURE_CUBE_MAP, r->sky_cubemap);
    if (r->sky_dome_image) bind_unit(gl, UNIT_SKY_DOME, GL_TEXTURE_2D, r->sky_dome_image);
    if (w->dudv_tex) {
        gl->Uniform1i(v->dudv_grad, UNIT_DUDV);
        bind_unit(gl, UNIT_DUDV, GL_TEXTURE_2D, w->dudv_tex);
    }
    gl->ActiveTexture(GL_TEXTURE0);
}

static void unbind_optics(const ww_gl *gl) {
    bind_unit(gl, UNIT_DUDV, GL_TEXTURE_2D, 0);
    bind_unit(gl, UNIT_SKY_DOME, GL_TEXTURE_2D, 0);
    bind_unit(gl, UNIT_SKY_CUBE, GL_TEXTURE_CUBE_MAP, 0);
    for (int u = UNIT_REFLECTION_DEPTH; u >= UNIT_REFLECTION; u--) bind_unit(gl, u, GL_TEXTURE_2D, 0);
}

/* the mesh's visible part: the inner disc whole, the outer rings' segments in view */
static void draw_mesh(const ww_water *w, const ww_gl *gl, const ww_frame *f,
                      const double centre[2]) {
    gl->BindVertexArray(w->vao);
    gl->DrawElements(GL_TRIANGLES, w->ninner, GL_UNSIGNED_INT, NULL);
    int first, count;
    visible_segments(w, f, centre, &first, &count);
    draw_segments(w, gl, first, count < w->nseg - first ? count : w->nseg - first);
    if (first + count > w->nseg) draw_segments(w, gl, 0, first + count - w->nseg);
    gl->BindVertexArray(0);
}

/* the shading's uniforms and textures on the bound build v */
static void set_shading(const ww_water *w, const water_prog *v, int bits, const ww_renderer *r,
                        const ww_frame *f, const double centre[2]) {
    const ww_gl *gl = r->gl;
    const ww_scene *sc = f->sc;
    const ww_state *st = f->st;
    /* fog colour: the scene's, or the sky at the horizon so the far water meets the sky */
    double hz[3];
    ww_sky_horizon(sc, st, hz); /* the sky's haze: gfx/sky.c */
    const double *fog = sc->fog_color[0] < 0.0 ? hz : sc->fog_color;
    ww_sky_locs_set(gl, &v->sky, st);
    ww_geometry_lights_set(r->geometry, gl, f, v->prog); /* lights[] */
    gl->Uniform3f(v->water_color, (float)sc->water_color[0], (float)sc->water_color[1],
                  (float)sc->water_color[2]);
    gl->Uniform3f(v->ambient, (float)st->ambient[0], (float)st->ambient[1], (float)st->ambient[2]);
    gl->Uniform3f(v->fog_color, (float)fog[0], (float)fog[1], (float)fog[2]);
    gl->Uniform1f(v->fog_density, (float)sc->fog_density);
    gl->Uniform1f(v->pixel_angle, f->pixel_angle);
    set_optics(w, v, bits, r, f, centre);
}

/* the mesh's placement on the bound program: view, origin, spacing, skirt */
static void set_mesh(const ww_water *w, const ww_gl *gl, const ww_frame *f, const double centre[2],
                     GLint view_proj, GLint origin, GLint grid, GLint skirt) {
    gl->UniformMatrix4fv(view_proj, 1, GL_FALSE, (const GLfloat *)f->view_proj);
    gl->Uniform3f(origin, (float)(centre[0] - f->cam_pos[0]),
                  (float)(f->sc->water_level - f->cam_pos[1]), (float)(centre[1] - f->cam_pos[2]));
    gl->Uniform3fv(grid, 1, w->grid);
    gl->Uniform1f(skirt, w->skirt_r);
}

/* the G-buffer path (see GBUF_BIT): the mesh into the G-buffer, then the marked pixels shaded */
static ww_result draw_gbuf(ww_water *w, const ww_renderer *r, const ww_frame *f, int bits,
                           const ww_rt *main, const double centre[2], ww_error *err) {
    const ww_gl *gl = r->gl;
    ww_result rc = WW_OK;
    if (!w->gbuf_prog && (rc = gbuf_new(w, gl, f->sc, main, err))) return rc;
    if (!w->resolve[bits].prog && (rc = build_variant(w, gl, f->sc, bits, 1, err))) return rc;
    const water_prog *v = &w->resolve[bits];
    w->tag = w->tag >= GBUF_TAG_WRAP ? 1.0f : w->tag + 1.0f;

    gl->BindFramebuffer(GL_FRAMEBUFFER, w->gbuf_fbo);
    gl->Enable(GL_STENCIL_TEST);
    gl->StencilMask(GBUF_BIT);
    gl->StencilFunc(GL_ALWAYS, GBUF_BIT, GBUF_BIT);
    gl->StencilOpSeparate(GL_FRONT_AND_BACK, GL_KEEP, GL_KEEP, GL_REPLACE);
    gl->UseProgram(w->gbuf_prog);
    set_mesh(w, gl, f, centre, w->gbuf_view_proj, w->gbuf_origin, w->gbuf_grid, w->gbuf_skirt);
    gl->Uniform1f(w->gbuf_tag, w->tag);
    draw_mesh(w, gl, f, centre);

    /* every marked pixel shaded once, its bit cleared for the shadows' counts */
    gl->BindFramebuffer(GL_FRAMEBUFFER, main->fbo);
    gl->Disable(GL_DEPTH_TEST);
    gl->StencilFunc(GL_EQUAL, GBUF_BIT, GBUF_BIT);
    gl->StencilOpSeparate(GL_FRONT_AND_BACK, GL_KEEP, GL_KEEP, GL_ZERO);
    gl->UseProgram(v->prog);
    set_shading(w, v, bits, r, f, centre);
    gl->Uniform3fv(v->ugrid, 1, w->grid); /* the fades' spacing (gerstner.glsl) */
    gl->Uniform1i(v->gbuf_pos, UNIT_GBUF_POS);
    gl->Uniform1i(v->gbuf_rest, UNIT_GBUF_REST);
    gl->Uniform1f(v->gbuf_tag, w->tag);
    bind_unit(gl, UNIT_GBUF_POS, GL_TEXTURE_2D, ww_gfx_rt_texture_nth(main, WW_FMT_RGBA32F, 0));
    bind_unit(gl, UNIT_GBUF_REST, GL_TEXTURE_2D, ww_gfx_rt_texture_nth(main, WW_FMT_RGBA32F, 1));
    gl->ActiveTexture(GL_TEXTURE0);
    gl->BindVertexArray(r->empty_vao);
    gl->DrawArrays(GL_TRIANGLES, 0, 3);
    gl->BindVertexArray(0);
    bind_unit(gl, UNIT_GBUF_REST, GL_TEXTURE_2D, 0);
    bind_unit(gl, UNIT_GBUF_POS, GL_TEXTURE_2D, 0);
    unbind_optics(gl);
    gl->StencilMask(0xFF);
    gl->Disable(GL_STENCIL_TEST);
    gl->Enable(GL_DEPTH_TEST);
    return WW_OK;
}

ww_result ww_water_draw(ww_water *w, const ww_renderer *r, const ww_frame *f, ww_error *err) {
    const ww_gl *gl = r->gl;
    const ww_scene *sc = f->sc;
    const ww_state *st = f->st;
    const ww_shared *sh = &r->shared;
    int bits = (f->underwater ? WATER_UNDER : 0) |
               (sh->reflection && sh->reflection_tex ? WATER_REFL : 0) |
               (sh->scene_color && sh->scene_depth ? WATER_REFR : 0) |
               (sh->scene_depth_full ? WATER_EDGES : 0);

    /* the mesh follows the camera in whole grid steps, so its vertices do not swim */
    double centre[2] = {WW_WATER_SNAP * floor(f->cam_pos[0] / WW_WATER_SNAP + 0.5),
                        WW_WATER_SNAP * floor(f->cam_pos[2] / WW_WATER_SNAP + 0.5)};
    ww_water_waves_phases(sc, st, centre, &w->waves);
    if (sc->ripples_on) ww_water_pack_ripples(sc, st, centre, &w->ripples);
    ww_water_ubos_upload(gl, &w->ubos, &w->waves, sc->ripples_on ? &w->ripples : NULL, 0);
    ww_water_ubos_bind(gl, &w->ubos);

    gl->Enable(GL_DEPTH_TEST);
    gl->DepthFunc(GL_LESS);
    gl->DepthMask(GL_TRUE);
    /* the main pass plans the G-buffer where it can be used (not with MSAA, nor blending) */
    const ww_rt *main = ww_renderer_output(r, WW_PASS_MAIN);
    if (!w->forward && main && ww_gfx_rt_texture_nth(main, WW_FMT_RGBA32F, 1))
        return draw_gbuf(w, r, f, bits, main, centre, err);

    if (!w->var[bits].prog) {
        ww_result rc = build_variant(w, gl, sc, bits, 0, err);
        if (rc != WW_OK) return rc;
    }
    const water_prog *v = &w->var[bits];
    /* seed 004's mode: blended over what is already drawn below (water.frag.glsl's alpha) */
    int blend = sc->render.water.alpha_blend && !f->underwater;
    if (blend) {
        gl->Enable(GL_BLEND);
        gl->BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    }
    gl->UseProgram(v->prog);
    set_mesh(w, gl, f, centre, v->view_proj, v->origin, v->ugrid, v->skirt);
    set_shading(w, v, bits, r, f, centre);
    draw_mesh(w, gl, f, centre);
    unbind_optics(gl);
    if (blend) gl->Disable(GL_BLEND);
    return WW_OK;
}

void ww_water_free(ww_water *w, const ww_gl *gl) {
    if (!w) return;
    for (int i = 0; i < WATER_VARIANTS; i++) {
        if (w->var[i].prog) gl->DeleteProgram(w->var[i].prog);
        if (w->resolve[i].prog) gl->DeleteProgram(w->resolve[i].prog);
    }
    if (w->gbuf_prog) gl->DeleteProgram(w->gbuf_prog);
    if (w->gbuf_fbo) gl->DeleteFramebuffers(1, &w->gbuf_fbo);
    if (w->vao) gl->DeleteVertexArrays(1, &w->vao);
    if (w->vbo) gl->DeleteBuffers(1, &w->vbo);
    if (w->ibo) gl->DeleteBuffers(1, &w->ibo);
    if (w->dudv_tex) gl->DeleteTextures(1, &w->dudv_tex);
    ww_water_ubos_free(gl, &w->ubos);
    free(w);
}
