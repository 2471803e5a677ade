/* geometry.c - the scene's solid geometry, shared by the passes that draw it (shadow, prepass,
 * reflection, main): meshes uploaded once, per-instance model matrices and colours uploaded once
 * per frame, one instanced draw per mesh (shaders/geometry.*). Positions are camera-relative.
 * What it holds now: the seabed, a grid plane water.depth below the rest level that follows the
 * camera.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gfx/render_impl.h"

#define SEABED_CELLS 64      /* grid cells per side */
#define SEABED_HALF 400.0    /* half its side, m (snapped to the camera) */
#define SEABED_SNAP 16.0     /* the plane moves on this grid, m */

/* one mesh on the GPU with its per-instance buffer (mat4 model + vec4 colour per instance) */
typedef struct gmesh {
    GLuint vao, vbo, ibo, inst;
    GLsizei nindex;
    int ninst, cap;
} gmesh;

typedef struct instance {
    float model[16]; /* column-major */
    float color[4];  /* albedo, emission factor */
} instance;

struct ww_geometry {
    GLuint prog;
    ww_sky_locs sky;
    GLint view_proj, clip, ambient, cam, fog_color, fog_density, fog_below_color,
        fog_below_density, depth_only;
    int64_t uploaded; /* frame whose instances are in the buffers, -1 none */
    gmesh seabed;
};

/* vertex layout: position, normal, uv */
static void mesh_upload(const ww_gl *gl, gmesh *m, const float *verts, int nvert,
                        const GLuint *idx, int nindex, int cap) {
    gl->GenVertexArrays(1, &m->vao);
    gl->BindVertexArray(m->vao);
    gl->GenBuffers(1, &m->vbo);
    gl->BindBuffer(GL_ARRAY_BUFFER, m->vbo);
    gl->BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)nvert * 8 * sizeof(float), verts, GL_STATIC_DRAW);
    GLsizei stride = 8 * sizeof(float);
    gl->EnableVertexAttribArray(0);
    gl->VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, (void *)0);
    gl->EnableVertexAttribArray(1);
    gl->VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, (void *)(3 * sizeof(float)));
    gl->EnableVertexAttribArray(2);
    gl->VertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, stride, (void *)(6 * sizeof(float)));
    gl->GenBuffers(1, &m->ibo);
    gl->BindBuffer(GL_ELEMENT_ARRAY_BUFFER, m->ibo);
    gl->BufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)nindex * sizeof(GLuint), idx,
                   GL_STATIC_DRAW);
    m->nindex = nindex;

    /* instances: model matrix in locations 3..6, colour in 7, one per instance */
    gl->GenBuffers(1, &m->inst);
    gl->BindBuffer(GL_ARRAY_BUFFER, m->inst);
    gl->BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)cap * (GLsizeiptr)sizeof(instance), NULL,
                   GL_DYNAMIC_DRAW);
    for (int c = 0; c < 5; c++) {
        GLuint loc = 3 + (GLuint)c;
        gl->EnableVertexAttribArray(loc);
        gl->VertexAttribPointer(loc, 4, GL_FLOAT, GL_FALSE, sizeof(instance),
                                (void *)(c * 4 * sizeof(float)));
        gl->VertexAttribDivisor(loc, 1);
    }
    m->cap = cap;
    gl->BindVertexArray(0);
}

static void mesh_free(const ww_gl *gl, gmesh *m) {
    if (m->vao) gl->DeleteVertexArrays(1, &m->vao);
    GLuint b[3] = {m->vbo, m->ibo, m->inst};
    gl->DeleteBuffers(3, b);
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

void ww_geometry_free(ww_geometry *g, const ww_gl *gl) {
    if (!g) return;
    if (g->prog) gl->DeleteProgram(g->prog);
    mesh_free(gl, &g->seabed);
    free(g);
}

ww_result ww_geometry_new(ww_renderer *r, const ww_scene *sc, ww_geometry **out, ww_error *err) {
    static const char *const includes[] = {"common.glsl", NULL};
    const ww_gl *gl = r->gl;
    (void)sc;
    ww_geometry *g = calloc(1, sizeof *g);
    if (!g) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "geometry: out of memory");
    g->uploaded = -1;
    ww_result rc = ww_gfx_program(gl, "geometry.vert.glsl", "geometry.frag.glsl", includes,
                                  &g->prog, err);
    if (rc == WW_OK) rc = seabed_new(gl, &g->seabed, err);
    if (rc != WW_OK) {
        ww_geometry_free(g, gl);
        return rc;
    }
    ww_sky_locs_init(gl, g->prog, &g->sky);
    g->view_proj = ww_gfx_uniform(gl, g->prog, "u_view_proj");
    g->clip = ww_gfx_uniform(gl, g->prog, "u_clip");
    g->ambient = ww_gfx_uniform(gl, g->prog, "u_ambient");
    g->cam = ww_gfx_uniform(gl, g->prog, "u_cam");
    g->fog_color = ww_gfx_uniform(gl, g->prog, "u_fog_color");
    g->fog_density = ww_gfx_uniform(gl, g->prog, "u_fog_density");
    g->fog_below_color = ww_gfx_uniform(gl, g->prog, "u_fog_below_color");
    g->fog_below_density = ww_gfx_uniform(gl, g->prog, "u_fog_below_density");
    g->depth_only = ww_gfx_uniform(gl, g->prog, "u_depth_only");
    *out = g;
    return WW_OK;
}

/* this frame's instances (once per frame, whichever pass draws first) */
static void upload_instances(ww_geometry *g, const ww_gl *gl, const ww_frame *f) {
    const ww_scene *sc = f->sc;
    if (g->uploaded == f->frame) return;
    g->uploaded = f->frame;
    g->seabed.ninst = 0;
    if (sc->render.seabed) {
        /* centred on the camera snapped to a grid, so the grid does not swim */
        double cx = SEABED_SNAP * floor(f->cam_pos[0] / SEABED_SNAP + 0.5);
        double cz = SEABED_SNAP * floor(f->cam_pos[2] / SEABED_SNAP + 0.5);
        double y = sc->water_level - sc->water_depth;
        instance in = {{0}, {0}};
        in.model[0] = (float)SEABED_HALF;
        in.model[5] = 1.0f;
        in.model[10] = (float)SEABED_HALF;
        in.model[12] = (float)(cx - f->cam_pos[0]);
        in.model[13] = (float)(y - f->cam_pos[1]);
        in.model[14] = (float)(cz - f->cam_pos[2]);
        in.model[15] = 1.0f;
        for (int c = 0; c < 3; c++) in.color[c] = (float)sc->render.seabed_color[c];
        gl->BindBuffer(GL_ARRAY_BUFFER, g->seabed.inst);
        gl->BufferSubData(GL_ARRAY_BUFFER, 0, sizeof in, &in);
        g->seabed.ninst = 1;
    }
}

static void draw_mesh(const ww_gl *gl, const gmesh *m) {
    if (m->ninst <= 0) return;
    gl->BindVertexArray(m->vao);
    gl->DrawElementsInstanced(GL_TRIANGLES, m->nindex, GL_UNSIGNED_INT, NULL, m->ninst);
}

void ww_geometry_draw(ww_geometry *g, ww_renderer *r, const ww_frame *f, ww_geom_mode mode,
                      mat4 view_proj, const float *clip) {
    const ww_gl *gl = r->gl;
    const ww_scene *sc = f->sc;
    const ww_state *st = f->st;
    upload_instances(g, gl, f);

    gl->UseProgram(g->prog);
    ww_sky_locs_set(gl, &g->sky, st);
    gl->UniformMatrix4fv(g->view_proj, 1, GL_FALSE, (const GLfloat *)view_proj);
    if (clip) {
        gl->Enable(GL_CLIP_DISTANCE0);
        gl->Uniform4f(g->clip, clip[0], clip[1], clip[2], clip[3]);
    } else {
        gl->Disable(GL_CLIP_DISTANCE0);
        gl->Uniform4f(g->clip, 0.0f, 0.0f, 0.0f, 1.0f);
    }
    gl->Uniform3f(g->ambient, (float)st->ambient[0], (float)st->ambient[1], (float)st->ambient[2]);
    gl->Uniform3f(g->cam, 0.0f, (float)(f->cam_pos[1] - f->surface_y), 0.0f);
    const double *fog = sc->fog_color[0] < 0.0 ? st->sky_horizon : sc->fog_color;
    gl->Uniform3f(g->fog_color, (float)fog[0], (float)fog[1], (float)fog[2]);
    gl->Uniform1f(g->fog_density, (float)sc->fog_density);
    const double *fb = sc->render.fog_below_color;
    gl->Uniform3f(g->fog_below_color, (float)fb[0], (float)fb[1], (float)fb[2]);
    gl->Uniform1f(g->fog_below_density, (float)sc->render.fog_below_density);
    gl->Uniform1i(g->depth_only, mode == WW_GEOM_SHADOW);

    gl->Enable(GL_DEPTH_TEST);
    gl->DepthFunc(GL_LESS);
    gl->DepthMask(GL_TRUE);
    draw_mesh(gl, &g->seabed);
    gl->BindVertexArray(0);
    gl->Disable(GL_CLIP_DISTANCE0);
}
