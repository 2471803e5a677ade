/* pass_hud.c - seed 000's overlay, headless (render.hud): a 24-hour clock from the sky clock,
 * the counters (fish caught, prizes, and the boat's speed and camera mode when there is a
 * boat) as stb_easy_font text on a dark translucent box in the top left corner, and the chest
 * marker: a glowing diamond over the chest's projected position while a chest is present,
 * held at the screen's edge with an arrow pointing to it when the chest is off screen or behind
 * the camera. Everything is built on the CPU as triangles in pixels each frame (into one
 * buffer allocated at create) and drawn in one call, alpha-blended into the last RGBA8 image
 * (the FXAA pass's, else the tone mapping's): the pass has no target of its own.
 * Seed 000 draws the clock with ImGui and the counters in the window title.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <stb/stb_easy_font.h>

#include "gfx/render_impl.h"

#define HUD_REF_HEIGHT 360.0     /* text scale 1 up to this image height, then x height / this */
#define HUD_MARGIN 4.0           /* px at scale 1: box from the corner, text from the box edge */
#define HUD_LINE 10.0            /* px at scale 1 between lines (stb_easy_font glyphs are ~7) */
#define HUD_MAX_LINES 3
#define HUD_LINE_CHARS 64
#define HUD_QUAD_BYTES 64        /* stb_easy_font: 4 vertices of 16 bytes per quad */
#define HUD_MAX_QUADS 2048       /* more than the longest lines need */
#define HUD_MAX_VERTS (6 * HUD_MAX_QUADS + 256)
#define HUD_FLOATS 6             /* x, y, r, g, b, a */
#define HUD_MARKER_R 5.0         /* marker diamond half-size, px at scale 1 */
#define HUD_GLOW_R 14.0          /* its glow's reach, px at scale 1 */
#define HUD_EDGE 16.0            /* px at scale 1 from the screen edge for an off-screen marker */
#define HUD_CHEST_LIFT 0.4       /* the marker sits this far over the chest's base, m */
#define HUD_MS_TO_KNOTS 1.94384

static const float HUD_TEXT[4] = {1.0f, 1.0f, 1.0f, 1.0f};
static const float HUD_BOX[4] = {0.0f, 0.0f, 0.0f, 0.55f};
static const float HUD_GOLD[4] = {1.0f, 0.85f, 0.35f, 1.0f};
static const float HUD_GLOW[4] = {1.0f, 0.75f, 0.2f, 0.0f}; /* the glow's rim: transparent */

typedef struct hud_pass {
    const ww_rt *target; /* the last RGBA8 image */
    GLuint prog, vao, vbo;
    GLint size;
    float *verts;        /* HUD_MAX_VERTS x HUD_FLOATS */
    int nverts;
    char *quads;         /* stb_easy_font's output, HUD_MAX_QUADS quads */
} hud_pass;

static void hud_destroy(void *self, const ww_gl *gl) {
    hud_pass *p = self;
    if (!p) return;
    if (p->prog) gl->DeleteProgram(p->prog);
    if (p->vbo) gl->DeleteBuffers(1, &p->vbo);
    if (p->vao) gl->DeleteVertexArrays(1, &p->vao);
    free(p->verts);
    free(p->quads);
    free(p);
}

static ww_result hud_create(ww_renderer *r, const ww_scene *sc, const ww_pass_desc *d,
                            const ww_rt *rt, void **self, ww_error *err) {
    (void)sc;
    (void)rt;
    const ww_gl *gl = r->gl;
    const ww_rt *target = ww_renderer_output(r, WW_PASS_UPSCALE);
    if (!target) target = ww_renderer_output(r, WW_PASS_FXAA);
    if (!target) target = ww_renderer_output(r, WW_PASS_TONEMAP);
    if (!target || !ww_gfx_rt_texture(target, WW_FMT_RGBA8))
        return ww_error_set(err, WW_E_GL, NULL, 0, 0, "pass %s: no RGBA8 image to draw into",
                            d->name);
    hud_pass *p = calloc(1, sizeof *p);
    if (!p) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "hud pass: out of memory");
    p->target = target;
    p->verts = malloc(sizeof(float) * HUD_FLOATS * HUD_MAX_VERTS);
    p->quads = malloc((size_t)HUD_QUAD_BYTES * HUD_MAX_QUADS);
    if (!p->verts || !p->quads) {
        hud_destroy(p, gl);
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "hud pass: out of memory");
    }
    ww_result rc = ww_gfx_program(gl, "hud.vert.glsl", "hud.frag.glsl", NULL, &p->prog, err);
    if (rc != WW_OK) {
        hud_destroy(p, gl);
        return rc;
    }
    p->size = ww_gfx_uniform(gl, p->prog, "u_size");
    gl->GenVertexArrays(1, &p->vao);
    gl->GenBuffers(1, &p->vbo);
    gl->BindVertexArray(p->vao);
    gl->BindBuffer(GL_ARRAY_BUFFER, p->vbo);
    gl->BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(sizeof(float) * HUD_FLOATS * HUD_MAX_VERTS), NULL,
                   GL_STREAM_DRAW);
    GLsizei stride = (GLsizei)(sizeof(float) * HUD_FLOATS);
    gl->EnableVertexAttribArray(0);
    gl->VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, stride, (const void *)0);
    gl->EnableVertexAttribArray(1);
    gl->VertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, stride, (const void *)(2 * sizeof(float)));
    gl->BindVertexArray(0);
    gl->BindBuffer(GL_ARRAY_BUFFER, 0);
    *self = p;
    return WW_OK;
}

static void vert(hud_pass *p, double x, double y, const float c[4]) {
    WW_ASSERT(p->nverts < HUD_MAX_VERTS);
    float *v = p->verts + (size_t)p->nverts++ * HUD_FLOATS;
    v[0] = (float)x;
    v[1] = (float)y;
    memcpy(v + 2, c, 4 * sizeof(float));
}

static void tri(hud_pass *p, const double a[2], const double b[2], const double c[2],
                const float ca[4], const float cb[4], const float cc[4]) {
    vert(p, a[0], a[1], ca);
    vert(p, b[0], b[1], cb);
    vert(p, c[0], c[1], cc);
}

static void rect(hud_pass *p, double x0, double y0, double x1, double y1, const float c[4]) {
    double a[2] = {x0, y0}, b[2] = {x1, y0}, cc[2] = {x1, y1}, d[2] = {x0, y1};
    tri(p, a, b, cc, c, c, c);
    tri(p, a, cc, d, c, c, c);
}

/* text at (x, y) (top left), scale s: stb_easy_font's quads as two triangles each */
static void text(hud_pass *p, const char *s, double x, double y, double scale) {
    stb_easy_font_spacing(0.0f); /* the library's one setting, pinned before every use */
    int nq = stb_easy_font_print(0.0f, 0.0f, (char *)s, NULL, p->quads,
                                 HUD_QUAD_BYTES * HUD_MAX_QUADS);
    for (int q = 0; q < nq; q++) {
        const float *v = (const float *)(p->quads + (size_t)q * HUD_QUAD_BYTES);
        /* vertices 16 bytes apart: x, y, z and a packed colour */
        double x0 = x + scale * v[0], y0 = y + scale * v[1];
        double x1 = x + scale * v[8], y1 = y + scale * v[9];
        rect(p, x0, y0, x1, y1, HUD_TEXT);
    }
}

/* the lines of text the scene asks for; returns how many */
static int hud_lines(const ww_frame *f, char lines[HUD_MAX_LINES][HUD_LINE_CHARS]) {
    const ww_scene *sc = f->sc;
    const ww_state *st = f->st;
    const ww_hud_desc *h = &sc->render.hud;
    int n = 0;
    if (h->clock) {
        /* whole minutes of the clock, 00:00 .. 23:59 */
        long minutes = (long)floor(st->time_of_day[0] * 60.0 + 1e-9);
        minutes = ((minutes % 1440) + 1440) % 1440;
        snprintf(lines[n++], HUD_LINE_CHARS, "%02ld:%02ld", minutes / 60, minutes % 60);
    }
    if (h->counters) {
        int fish = sc->fish.on ? (int)st->fish_caught[0] : 0;
        int prizes = sc->chest.on ? (int)st->prizes[0] : 0;
        snprintf(lines[n++], HUD_LINE_CHARS, "fish %d  prizes %d", fish, prizes);
        if (sc->boat.on)
            snprintf(lines[n++], HUD_LINE_CHARS, "boat %.1f m/s (%.1f kn)  %s",
                     fabs(st->boat_speed[0]), fabs(st->boat_speed[0]) * HUD_MS_TO_KNOTS,
                     st->boat_camera[0] > 0.5 ? "boat" : "free");
    }
    return n;
}

/* a diamond of half-size rad at (x, y) with a glow fading out to rad_glow */
static void diamond(hud_pass *p, double x, double y, double rad, double rad_glow) {
    static const double dx[4] = {0, 1, 0, -1}, dy[4] = {-1, 0, 1, 0};
    double c[2] = {x, y};
    for (int i = 0; i < 4; i++) {
        int j = (i + 1) % 4;
        double a[2] = {x + rad * dx[i], y + rad * dy[i]}, b[2] = {x + rad * dx[j], y + rad * dy[j]};
        double ga[2] = {x + rad_glow * dx[i], y + rad_glow * dy[i]};
        double gb[2] = {x + rad_glow * dx[j], y + rad_glow * dy[j]};
        tri(p, c, a, b, HUD_GOLD, HUD_GOLD, HUD_GOLD);
        tri(p, a, ga, gb, HUD_GOLD, HUD_GLOW, HUD_GLOW);
        tri(p, a, gb, b, HUD_GOLD, HUD_GLOW, HUD_GOLD);
    }
}

/* the chest marker: on screen, a diamond with a short glowing bar above it (the chest's light
 * column); off screen or behind, a diamond at the edge and an arrow toward the chest */
static void chest_marker(hud_pass *p, const ww_frame *f, double w, double h, double s) {
    const ww_state *st = f->st;
    if (!f->sc->chest.on || st->chest_state[0] < 0.5) return;
    double rel[3] = {st->chest_pos[0] - f->cam_pos[0],
                     st->chest_pos[1] + HUD_CHEST_LIFT - f->cam_pos[1],
                     st->chest_pos[2] - f->cam_pos[2]};
    vec4 pt = {(float)rel[0], (float)rel[1], (float)rel[2], 1.0f}, clip;
    glm_mat4_mulv((vec4 *)f->view_proj, pt, clip);
    double nx, ny;
    int on = 0;
    if (clip[3] > 1e-6f) {
        nx = clip[0] / clip[3];
        ny = clip[1] / clip[3];
        on = fabs(nx) <= 1.0 && fabs(ny) <= 1.0;
    } else {
        /* behind: the direction across the view in the camera's right and up */
        nx = rel[0] * f->right[0] + rel[1] * f->right[1] + rel[2] * f->right[2];
        ny = rel[0] * f->up[0] + rel[1] * f->up[1] + rel[2] * f->up[2];
        if (nx == 0.0 && ny == 0.0) ny = -1.0;
    }
    double x, y;
    if (on) {
        x = 0.5 * (nx + 1.0) * w;
        y = 0.5 * (1.0 - ny) * h;
        double bw = 1.0 * s, top = y - 4.0 * HUD_GLOW_R * s;
        float fade[4] = {HUD_GOLD[0], HUD_GOLD[1], HUD_GOLD[2], 0.0f};
        double a[2] = {x - bw, top}, b[2] = {x + bw, top}, c[2] = {x + bw, y}, d[2] = {x - bw, y};
        tri(p, a, b, c, fade, fade, HUD_GOLD);
        tri(p, a, c, d, fade, HUD_GOLD, HUD_GOLD);
        diamond(p, x, y, HUD_MARKER_R * s, HUD_GLOW_R * s);
        return;
    }
    /* scale the direction from the centre onto the rectangle HUD_EDGE inside the screen */
    double hx = 0.5 * w - HUD_EDGE * s, hy = 0.5 * h - HUD_EDGE * s;
    double dx = nx * 0.5 * w, dy = -ny * 0.5 * h; /* px, y down */
    double k = fmax(fabs(dx) / hx, fabs(dy) / hy);
    dx /= k;
    dy /= k;
    x = 0.5 * w + dx;
    y = 0.5 * h + dy;
    diamond(p, x, y, HUD_MARKER_R * s, HUD_GLOW_R * s);
    /* the arrow: a triangle beyond the diamond pointing outward */
    double len = sqrt(dx * dx + dy * dy), ux = dx / len, uy = dy / len;
    double base = (HUD_MARKER_R + 2.0) * s, tip = (HUD_MARKER_R + 9.0) * s, half = 4.0 * s;
    double t[2] = {x + ux * tip, y + uy * tip};
    double a[2] = {x + ux * base - uy * half, y + uy * base + ux * half};
    double b[2] = {x + ux * base + uy * half, y + uy * base - ux * half};
    tri(p, t, a, b, HUD_GOLD, HUD_GOLD, HUD_GOLD);
}

static ww_result hud_run(void *self, ww_renderer *r, const ww_frame *f, ww_error *err) {
    (void)err;
    hud_pass *p = self;
    const ww_gl *gl = r->gl;
    double w = p->target->width, h = p->target->height;
    double s = h > HUD_REF_HEIGHT ? floor(h / HUD_REF_HEIGHT) : 1.0;
    p->nverts = 0;

    /* the text box: the widest line plus margins */
    char lines[HUD_MAX_LINES][HUD_LINE_CHARS];
    int n = hud_lines(f, lines);
    if (n > 0) {
        int wmax = 0;
        stb_easy_font_spacing(0.0f);
        for (int i = 0; i < n; i++) {
            int lw = stb_easy_font_width(lines[i]);
            if (lw > wmax) wmax = lw;
        }
        double m = HUD_MARGIN * s;
        rect(p, m, m, m + 2.0 * m + wmax * s, m + 2.0 * m + (n * HUD_LINE - 3.0) * s, HUD_BOX);
        for (int i = 0; i < n; i++) text(p, lines[i], 2.0 * m, 2.0 * m + i * HUD_LINE * s, s);
    }
    if (f->sc->render.hud.chest_marker) chest_marker(p, f, w, h, s);
    if (p->nverts == 0) return WW_OK;

    /* over the image: colour blended, the image's alpha kept at 1 */
    ww_gfx_begin_pass(gl, p->target);
    gl->Enable(GL_BLEND);
    gl->BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    gl->UseProgram(p->prog);
    gl->Uniform2f(p->size, (float)w, (float)h);
    gl->BindVertexArray(p->vao);
    gl->BindBuffer(GL_ARRAY_BUFFER, p->vbo);
    gl->BufferSubData(GL_ARRAY_BUFFER, 0, (GLsizeiptr)(sizeof(float) * HUD_FLOATS * (size_t)p->nverts),
                      p->verts);
    gl->DrawArrays(GL_TRIANGLES, 0, p->nverts);
    gl->BindBuffer(GL_ARRAY_BUFFER, 0);
    gl->BindVertexArray(0);
    gl->Disable(GL_BLEND);
    return WW_OK;
}

const ww_pass_ops ww_pass_hud_ops = {hud_create, hud_run, hud_destroy};
