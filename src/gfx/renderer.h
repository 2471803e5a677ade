/* renderer.h - the frame renderer, built from the scene's plan (scene/plan.h): one pass object
 * per planned pass, created once, then run in order each frame into our own framebuffers
 * (HDR RGBA16F colour + depth, then tone mapping into sRGB8). Read back with glReadPixels and
 * flipped once, so images come out top row first.
 *
 *   ww_renderer *r = NULL;
 *   ww_renderer_new(gl, sc, &plan, &r, &err);     // compiles shaders, makes targets
 *   ww_render_frame(r, sc, st);                   // draws all passes
 *   ww_renderer_read_ldr(r, &img);                // RGB8 (or RGBA8) final image, caller allocs
 *   ww_renderer_read_hdr(r, &img);                // RGBA float linear HDR image
 *   ww_renderer_free(r);
 *
 * Shaders are embedded at build time; WW_SHADER_DIR=path/to/shaders loads them from files
 * instead (development).
 */
#ifndef WW_RENDERER_H
#define WW_RENDERER_H

#include "core/error.h"
#include "gfx/gl.h"
#include "io/image.h"
#include "scene/plan.h"
#include "scene/scene.h"
#include "sim/state.h"

typedef struct ww_renderer ww_renderer;

ww_result ww_renderer_new(const ww_gl *gl, const ww_scene *sc, const ww_plan *plan,
                          ww_renderer **out, ww_error *err);
void ww_renderer_free(ww_renderer *r);
ww_result ww_render_frame(ww_renderer *r, const ww_scene *sc, const ww_state *st, ww_error *err);
/* im must be allocated by the caller at the plan's size: U8 with 3 or 4 channels / F32 with 4 */
ww_result ww_renderer_read_ldr(ww_renderer *r, ww_image *im, ww_error *err);
ww_result ww_renderer_read_hdr(ww_renderer *r, ww_image *im, ww_error *err);
/* ms for one trivial full-screen pass (constant colour) into an RGBA16F target of w x h: the
 * backend's fill floor, which bench sets render times against */
ww_result ww_gfx_fill_floor(const ww_gl *gl, int w, int h, double *ms, ww_error *err);

/* the wave field as the water shaders evaluate it (shaders/gerstner.glsl, the functions the
 * water vertex shader displaces its mesh with, fade off): for n rest points given relative to the
 * camera position cam (world, m), draws one point each into an RGBA32F target and reads back
 * out[8 i ..]: displaced point relative to cam (x, y, z), 0, unit normal (x, y, z), 0. Waves and
 * ripples of st at st->t. For the GPU-vs-CPU accuracy test and bench. */
ww_result ww_gfx_water_probe(const ww_gl *gl, const ww_scene *sc, const ww_state *st,
                             const double cam[3], int n, const double *rest_xz, float *out,
                             ww_error *err);
/* glFinish; used by bench to split render from read-back time */
void ww_renderer_finish(ww_renderer *r);

#endif
