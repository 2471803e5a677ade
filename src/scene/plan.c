/* plan.c - from a compiled scene to the list of systems that run and render passes that exist.
 * A scene pays only for what it uses: no waves, no wave system; no casters, no shadow map; each
 * pass exists behind the scene key that asks for it (scene/desc_render.h).
 */
#include "scene/plan.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *const system_names[WW_SYS_COUNT] = {
#define WW_SYS_NAME(id, name, present, object) [WW_SYS_##id] = name,
    WW_SYSTEM_LIST(WW_SYS_NAME)
#undef WW_SYS_NAME
};

const char *ww_system_name(ww_system s) { return system_names[s]; }

void ww_scene_plan_systems(ww_scene *sc) {
#define WW_SYS_PRESENT(id, name, present, object) sc->system_on[WW_SYS_##id] = (present) ? 1 : 0;
    WW_SYSTEM_LIST(WW_SYS_PRESENT)
#undef WW_SYS_PRESENT
}

size_t ww_format_bytes_per_pixel(ww_format f) {
    switch (f) {
    case WW_FMT_RGBA16F: return 8;
    case WW_FMT_DEPTH24: return 4; /* stored as 24+8 */
    case WW_FMT_RGBA8: return 4;
    case WW_FMT_DEPTH24_STENCIL8: return 4;
    case WW_FMT_RGBA32F: return 16;
    }
    return 0;
}

const char *ww_format_name(ww_format f) {
    switch (f) {
    case WW_FMT_RGBA16F: return "rgba16f";
    case WW_FMT_DEPTH24: return "depth24";
    case WW_FMT_RGBA8: return "rgba8";
    case WW_FMT_DEPTH24_STENCIL8: return "d24s8";
    case WW_FMT_RGBA32F: return "rgba32f";
    }
    return "?";
}

/* a target side at a fraction of the frame's, at least one texel */
static int scaled(int side, double f) {
    int n = (int)lround(side * f);
    return n > 0 ? n : 1;
}

const ww_pass_desc *ww_plan_pass(const ww_plan *p, ww_pass_id id) {
    for (int i = 0; i < p->npasses; i++)
        if (p->passes[i].id == id) return &p->passes[i];
    return NULL;
}

int ww_plan_target(const ww_pass_desc *d, const char *name) {
    for (int t = 0; d && t < d->ntargets; t++)
        if (strcmp(d->targets[t].name, name) == 0) return t;
    return -1;
}

static void add_pass(ww_plan *p, ww_pass_id id, const char *name, const char *what) {
    ww_pass_desc *d = &p->passes[p->npasses++];
    d->id = id;
    d->name = name;
    d->what = what;
    d->ntargets = 0;
    for (int t = 0; t < WW_PLAN_MAX_TARGETS; t++) d->samples[t] = d->unattached[t] = 0;
}

static void add_target(ww_plan *p, const char *name, ww_format f, int w, int h) {
    ww_pass_desc *d = &p->passes[p->npasses - 1];
    d->targets[d->ntargets++] = (ww_target_desc){name, f, w, h};
}

/* a texture the pass draws into through a framebuffer of its own */
static void add_target_unattached(ww_plan *p, const char *name, ww_format f, int w, int h) {
    add_target(p, name, f, w, h);
    ww_pass_desc *d = &p->passes[p->npasses - 1];
    d->unattached[d->ntargets - 1] = 1;
}

/* post: a multisampled target (render.msaa samples per pixel) */
static void add_target_ms(ww_plan *p, const char *name, ww_format f, int w, int h, int samples) {
    add_target(p, name, f, w, h);
    ww_pass_desc *d = &p->passes[p->npasses - 1];
    d->samples[d->ntargets - 1] = samples;
}

/* ring growth q such that rings s0, s0 q, s0 q^2, ... apart end at radius reach after n rings:
 * s0 (q^n - 1) / (q - 1) = reach (bisection); 1 when evenly spaced rings already reach */
static double ring_growth(double s0, int n, double reach) {
    if (reach <= s0 * n) return 1.0;
    double lo = 1.0 + 1e-12, hi = 2.0;
    for (int it = 0; it < 200; it++) {
        double q = 0.5 * (lo + hi);
        double r = s0 * (pow(q, n) - 1.0) / (q - 1.0);
        if (r < reach) lo = q; else hi = q;
    }
    return 0.5 * (lo + hi);
}

void ww_water_mesh_layout(double far_clip, double grid, ww_water_mesh *m) {
    if (!(grid > 0.0)) grid = 1.0;
    m->rings = (int)lround(WW_WATER_RINGS * grid);
    if (m->rings < 2) m->rings = 2;
    m->segments = 8 * (int)lround(WW_WATER_SEGMENTS * grid / 8.0);
    if (m->segments < 8) m->segments = 8;
    double s0 = WW_WATER_S0 / grid;
    m->reach = WW_WATER_REACH * far_clip;
    m->q = ring_growth(s0, m->rings, m->reach);
    m->s0 = m->q == 1.0 ? m->reach / m->rings : s0;
    m->dtheta = 2.0 * 3.14159265358979323846 / m->segments;
}

double ww_water_mesh_spacing(const ww_water_mesh *m, double r) {
    double ring = m->s0 + (m->q - 1.0) * r, around = r * m->dtheta;
    return ring > around ? ring : around;
}

/* the smallest distance from the mesh centre where the spacing reaches s (both of its terms
 * grow with r, so the max reaches s where the first of them does); INFINITY past the mesh */
double ww_water_mesh_distance_for(const ww_water_mesh *m, double s) {
    if (m->s0 >= s) return 0.0;
    double r = s / m->dtheta;
    if (m->q > 1.0) {
        double ring = (s - m->s0) / (m->q - 1.0);
        if (ring < r) r = ring;
    }
    return r <= m->reach ? r : INFINITY;
}

static int cmp_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* the fade ladder of one consumer from each component's fade-out distance (sorted here, INFINITY
 * for never within the mesh): how many are gone beyond which distance */
static void fade_ladder(ww_plan_fade *f, double start, double *out, int n) {
    qsort(out, (size_t)n, sizeof *out, cmp_double);
    f->components = n;
    f->start = start;
    f->nsteps = 0;
    for (int q = 0; q < WW_PLAN_FADE_STEPS && n > 0; q++) {
        int c = n <= WW_PLAN_FADE_STEPS ? q + 1 : q == 0 ? 1 : (n * q + 3) / 4; /* 1, ceil(n q / 4) */
        if (c > n || !isfinite(out[c - 1])) break;
        if (f->nsteps > 0 && f->faded[f->nsteps - 1] == c) continue;
        f->faded[f->nsteps] = c;
        f->beyond[f->nsteps] = out[c - 1];
        f->nsteps++;
    }
}

/* which components each consumer of the wave field evaluates, and where the shaders fade them
 * (the fade of shaders/gerstner.glsl): the vertex shader by the mesh spacing at the distance
 * from the mesh centre, the fragment shader by the pixel footprint at the distance from the
 * camera, d x pixel angle across the view (grazing views stretch it along the view, so there
 * components fade sooner) */
static void plan_water(const ww_scene *sc, int height, ww_plan_water *w) {
    double vert[WW_MAX_WAVES], frag[WW_MAX_WAVES];
    int n = 0;
    w->model = sc->wave_model;
    ww_water_mesh_layout(sc->far_clip, sc->render.grid, &w->mesh);
    w->image_height = height > 0 ? height : 1;
    w->pixel_angle = 2.0 * tan(0.5 * sc->fov) / w->image_height;
    w->shortest = INFINITY;
    w->longest = 0.0;
    for (int i = 0; sc->wave_model != WW_WAVES_FLAT && i < sc->nwaves; i++) {
        double L = sc->waves[i].wavelength;
        if (!(sc->waves[i].k > 0.0)) continue; /* as the shaders: no wave to draw */
        if (L < w->shortest) w->shortest = L;
        if (L > w->longest) w->longest = L;
        vert[n] = ww_water_mesh_distance_for(&w->mesh, L / WW_FADE_END_SAMPLES);
        frag[n] = L / (WW_FADE_END_SAMPLES * w->pixel_angle);
        if (frag[n] > w->mesh.reach) frag[n] = INFINITY;
        n++;
    }
    w->components = n;
    w->flat_beyond = ww_water_flat_beyond(sc, &w->mesh);
    double s = w->shortest;
    fade_ladder(&w->vertex, n ? ww_water_mesh_distance_for(&w->mesh, s / WW_FADE_START_SAMPLES) : INFINITY,
                vert, n);
    double fs = n ? s / (WW_FADE_START_SAMPLES * w->pixel_angle) : INFINITY;
    fade_ladder(&w->fragment, fs <= w->mesh.reach ? fs : INFINITY, frag, n);

    w->ripple_pool = sc->ripples_on ? sc->ripples.max : 0;
    if (w->ripple_pool > 0 && sc->ripples.wavenumber > 0.0) {
        double L = 2.0 * 3.14159265358979323846 / sc->ripples.wavenumber;
        w->ripple_wavelength = L;
        w->ripple_vertex_out = ww_water_mesh_distance_for(&w->mesh, L / WW_FADE_END_SAMPLES);
        w->ripple_fragment_out = L / (WW_FADE_END_SAMPLES * w->pixel_angle);
        if (w->ripple_fragment_out > w->mesh.reach) w->ripple_fragment_out = INFINITY;
    }
}

double ww_water_crest(const ww_scene *sc) {
    double crest = 0.0;
    for (int i = 0; sc->wave_model != WW_WAVES_FLAT && i < sc->nwaves; i++)
        crest += 2.0 * fabs(sc->waves[i].amplitude);
    if (sc->ripples_on) crest += fabs(sc->ripples.amplitude);
    return crest;
}

double ww_water_flat_beyond(const ww_scene *sc, const ww_water_mesh *m) {
    double longest = 0.0;
    for (int i = 0; sc->wave_model != WW_WAVES_FLAT && i < sc->nwaves; i++)
        if (sc->waves[i].k > 0.0 && sc->waves[i].wavelength > longest)
            longest = sc->waves[i].wavelength;
    if (sc->ripples_on && sc->ripples.max > 0 && sc->ripples.wavenumber > 0.0) {
        double L = 2.0 * 3.14159265358979323846 / sc->ripples.wavenumber;
        if (L > longest) longest = L;
    }
    return longest > 0.0 ? ww_water_mesh_distance_for(m, longest / WW_FADE_END_SAMPLES) : 0.0;
}

int ww_sky_map_on(const ww_scene *sc) {
    const ww_render_desc *rd = &sc->render;
    const char *exact = getenv("WW_SKY_EXACT");
    if (exact && strcmp(exact, "1") == 0) return 0;
    return rd->sky == WW_SKY_PREETHAM || (rd->sky == WW_SKY_DOME && rd->dome_image < 0);
}

void ww_plan_build(const ww_scene *sc, int frame_width, int frame_height, ww_plan *p) {
    *p = (ww_plan){0};
    for (int s = 0; s < WW_SYS_COUNT; s++) p->system_on[s] = sc->system_on[s];
    /* render.scale: every pass draws at this size, and one last pass scales the sRGB8 image up
     * to the frame's */
    double fs = sc->render.scale > 0.0 ? sc->render.scale : 1.0;
    int width = scaled(frame_width, fs), height = scaled(frame_height, fs);

    /* solid geometry: what casts shadows and what refraction and shafts see under the water;
     * it also holds the frame's lights, which the water and the sky take from it */
    const ww_render_desc *rd = &sc->render;
    p->geometry = ww_scene_has_objects(sc) || rd->seabed || rd->nlights > 0;
    int casters = ww_scene_has_objects(sc);

    /* stencilled shadows (projected, volumes) need a stencil wherever they are drawn; every
     * other scene keeps plain depth */
    int stencil = rd->shadows.on && casters && rd->shadows.technique != WW_SHADOW_MAP;
    ww_format depth_fmt = stencil ? WW_FMT_DEPTH24_STENCIL8 : WW_FMT_DEPTH24;
    if (ww_sky_map_on(sc)) {
        add_pass(p, WW_PASS_SKYMAP, "skymap",
                 "Preetham's sky and clouds per direction, sampled by the sky, water, reflection");
        int k = rd->sky == WW_SKY_PREETHAM && rd->cloud_cover > 0.0 ? WW_SKY_MAP_CLOUDS : 1;
        add_target(p, "sky", WW_FMT_RGBA16F, k * WW_SKY_MAP_WIDTH, k * WW_SKY_MAP_HEIGHT);
    }
    if (rd->shadows.on && casters && rd->shadows.technique == WW_SHADOW_MAP) {
        add_pass(p, WW_PASS_SHADOW, "shadow", "sun depth map, orthographic, fitted to the view; PCF");
        add_target(p, "depth", WW_FMT_DEPTH24, rd->shadows.size, rd->shadows.size);
    }
    if (rd->refraction && p->geometry) {
        int pw = scaled(width, rd->refraction_scale), ph = scaled(height, rd->refraction_scale);
        /* smaller than the frame: its depth at the frame's size too, drawn alone, by which the
         * water puts the outlines of what it refracts where the frame's pixels lie; only where
         * something lies in the water (a seabed alone has no outlines worth it), and not for
         * seed 004's blended water, which refracts nothing */
        int full = (pw != width || ph != height) && casters && !rd->water.alpha_blend;
        add_pass(p, WW_PASS_PREPASS, "prepass",
                 full ? "solid geometry under the water: colour + depth; depth at the frame's size"
                      : "solid geometry under the water: colour + depth");
        add_target(p, "color", WW_FMT_RGBA16F, pw, ph);
        add_target(p, "depth", depth_fmt, pw, ph);
        if (full)
            add_target_unattached(p, "depth_full", WW_FMT_DEPTH24, width, height);
    }
    if (rd->reflection.on) {
        int rw = scaled(width, rd->reflection.scale), rh = scaled(height, rd->reflection.scale);
        add_pass(p, WW_PASS_REFLECTION, "reflection",
                 "camera mirrored about the water plane, clip plane, mipmapped; skipped under water");
        add_target(p, "color", WW_FMT_RGBA16F, rw, rh);
        add_target(p, "depth", WW_FMT_DEPTH24, rw, rh);
    }
    /* the water shaded once a pixel: its mesh draws what the shading needs into a G-buffer and
     * marks its pixels in the stencil, then one full-screen draw shades the marked pixels (a
     * mesh of thin far triangles had the water shaded once for every triangle crossing a block
     * of pixels). Not with MSAA, whose samples a pixel's one shading would merge, nor for
     * water blended over what lies below it (seed 004), whose folds blend layer over layer */
    int gbuffer = rd->msaa <= 1 && !rd->water.alpha_blend;
    add_pass(p, WW_PASS_MAIN, "main",
             !p->geometry ? (gbuffer ? "HDR: sky with sun disc, water from its G-buffer"
                                     : "HDR: sky with sun disc, water")
             : stencil    ? (gbuffer ? "HDR: sky, lit geometry, water from its G-buffer; "
                                       "stencilled sun shadows"
                                     : "HDR: sky, lit geometry, water; stencilled sun shadows")
             : gbuffer    ? "HDR: sky, lit geometry, water from its G-buffer"
                          : "HDR: sky, lit geometry, water");
    add_target(p, "hdr", WW_FMT_RGBA16F, width, height);
    add_target(p, "depth", gbuffer ? WW_FMT_DEPTH24_STENCIL8 : depth_fmt, width, height);
    if (gbuffer) {
        /* the water's surface point (camera-relative) and its window depth; its rest offset */
        add_target_unattached(p, "water_pos", WW_FMT_RGBA32F, width, height);
        add_target_unattached(p, "water_rest", WW_FMT_RGBA32F, width, height);
    }
    if (rd->msaa > 1) {
        /* post: drawn multisampled, resolved into hdr and depth at the end of the pass */
        add_target_ms(p, "hdr_ms", WW_FMT_RGBA16F, width, height, rd->msaa);
        add_target_ms(p, "depth_ms", depth_fmt, width, height, rd->msaa);
    }
    if (rd->bloom.on) {
        int bw = scaled(width, rd->bloom.scale), bh = scaled(height, rd->bloom.scale);
        add_pass(p, WW_PASS_BLOOM, "bloom", "bright pass, separable Gaussian ping-pong");
        add_target(p, "ping", WW_FMT_RGBA16F, bw, bh);
        add_target(p, "pong", WW_FMT_RGBA16F, bw, bh);
    }
    if (rd->shafts.on) {
        int sw = scaled(width, rd->shafts.scale), sh = scaled(height, rd->shafts.scale);
        add_pass(p, WW_PASS_SHAFTS, "shafts", "radial blur toward the sun over the masked scene");
        add_target(p, "shafts", WW_FMT_RGBA16F, sw, sh);
        /* post: the march before its smoothing (the occlusion mask is drawn into `shafts`
         * first, and the smoothing back into it) */
        add_target(p, "march", WW_FMT_RGBA16F, sw, sh);
    }
    add_pass(p, WW_PASS_TONEMAP, "tonemap",
             sc->tonemap == WW_TONEMAP_ACES ? "HDR -> sRGB8, ACES fit" : "HDR -> sRGB8, 1 - exp(-E c)");
    add_target(p, "ldr", WW_FMT_RGBA8, width, height);
    if (rd->fxaa) {
        add_pass(p, WW_PASS_FXAA, "fxaa", "edge anti-aliasing of the sRGB8 image");
        add_target(p, "ldr", WW_FMT_RGBA8, width, height);
        add_target(p, "edges", WW_FMT_DEPTH24, width, height);
    }
    if (width != frame_width || height != frame_height) {
        add_pass(p, WW_PASS_UPSCALE, "upscale", "the sRGB8 image scaled up to the frame, bilinear");
        add_target(p, "ldr", WW_FMT_RGBA8, frame_width, frame_height);
    }
    if (rd->hud.clock || rd->hud.counters || rd->hud.chest_marker)
        add_pass(p, WW_PASS_HUD, "hud", "text and markers over the final image");
    plan_water(sc, height, &p->water);
}

/* a distance for people: 9.53, 27, 585 m */
static void put_m(double d, FILE *to) {
    if (d >= 100.0) fprintf(to, "%.0f m", d);
    else fprintf(to, "%.3g m", d);
}

/* one consumer's lines: "5 components; fading starts beyond 12 m; faded out: 1 beyond 40 m, ..."
 * and what the distances are measured by */
static void print_fade(const char *who, const ww_plan_fade *f, const char *note, FILE *to) {
    fprintf(to, "    %-16s %d components", who, f->components);
    if (!isfinite(f->start)) {
        fprintf(to, ", none faded within the mesh\n");
        return;
    }
    if (f->start > 0.0) {
        fputs("; fading starts beyond ", to);
        put_m(f->start, to);
    } else {
        fputs("; fading starts at the centre", to);
    }
    for (int i = 0; i < f->nsteps; i++) {
        fprintf(to, "%s %d ", i ? "," : "; faded out:", f->faded[i]);
        if (f->beyond[i] > 0.0) {
            fputs("beyond ", to);
            put_m(f->beyond[i], to);
        } else {
            fputs("everywhere", to);
        }
    }
    fprintf(to, "\n    %-16s (%s)\n", "", note);
}

static void print_ripple_fade(const char *who, double d, FILE *to) {
    fprintf(to, "    %-16s ", who);
    if (isfinite(d) && d > 0.0) {
        fputs("fades them out beyond ", to);
        put_m(d, to);
        fputc('\n', to);
    } else {
        fputs(isfinite(d) ? "too coarse for them everywhere\n" : "draws them across the mesh\n", to);
    }
}

static void print_water(const ww_scene *sc, const ww_plan_water *w, FILE *to) {
    fprintf(to, "water\n  waves      %s, %d components", ww_wave_model_name(w->model), w->components);
    if (w->components > 0)
        fprintf(to, ", wavelengths %.3g .. %.3g m", w->shortest, w->longest);
    fputc('\n', to);
    if (w->components > 0) {
        char note[160];
        fprintf(to, "    %-16s %d components everywhere (double)\n", "cpu physics", w->components);
        snprintf(note, sizeof note, "by the spacing of %d rings x %d segments, %.3g m at the centre "
                 "and x%.4f per ring; distances from the mesh centre", w->mesh.rings,
                 w->mesh.segments, w->mesh.s0, w->mesh.q);
        print_fade("vertex shader", &w->vertex, note, to);
        snprintf(note, sizeof note, "by the pixel footprint across the view, %.3g mrad per pixel at "
                 "%d px and fov %.3g deg; distances from the camera",
                 1e3 * w->pixel_angle, w->image_height, sc->fov * 180.0 / 3.14159265358979323846);
        print_fade("fragment shader", &w->fragment, note, to);
    }
    if (w->ripple_pool > 0) {
        fprintf(to, "  ripples    pool of %d (lifetime %g s), wavelength %.3g m\n", w->ripple_pool,
                sc->ripples.lifetime, w->ripple_wavelength);
        print_ripple_fade("vertex shader", w->ripple_vertex_out, to);
        print_ripple_fade("fragment shader", w->ripple_fragment_out, to);
    }
    if (isfinite(w->flat_beyond) && w->flat_beyond < w->mesh.reach) {
        fputs("  mesh       flat beyond ", to);
        put_m(w->flat_beyond, to);
        fputs(" from its centre, where the vertex shader moves nothing: the rings there are one "
              "band\n", to);
    }
}

void ww_plan_print(const ww_scene *sc, const ww_plan *p, FILE *to) {
    fprintf(to, "scene %s\n", sc->path);
    fprintf(to, "frames %lld at %g fps, dt %.9g s (%lld steps per frame)\n",
            (long long)sc->frame_count, sc->fps, sc->dt, (long long)sc->steps_per_frame);
    fprintf(to, "systems\n");
    for (int s = 0; s < WW_SYS_COUNT; s++) {
        if (!p->system_on[s]) continue;
        fprintf(to, "  %-10s", ww_system_name((ww_system)s));
        if (s == WW_SYS_WAVES) fprintf(to, " %d %s waves", sc->nwaves, ww_wave_model_name(sc->wave_model));
        if (s == WW_SYS_CAMERA) fprintf(to, " %d keys, %s", sc->ncam,
                                        sc->interp == WW_INTERP_LINEAR ? "linear" : "catmull-rom");
        if (s == WW_SYS_SCRIPT) fprintf(to, " %d events", sc->nevents);
        if (s == WW_SYS_CLOCK) fprintf(to, " %.2f h, day length %g s", sc->time_of_day, sc->day_length);
        if (s == WW_SYS_RIPPLES) fprintf(to, " pool of %d, lifetime %g s", sc->ripples.max, sc->ripples.lifetime);
        if (s == WW_SYS_CUBES) fprintf(to, " %d cubes", sc->cubes.count);
        if (s == WW_SYS_FLOATERS) fprintf(to, " %d floating models", sc->floaters.count);
        if (s == WW_SYS_FISH)
            fprintf(to, " %d fish, %s", sc->fish.count,
                    sc->fish.mode == WW_FISH_TARGETS ? "swimming to targets" : "wandering");
        if (s == WW_SYS_FISH && sc->fish.nspecies > 0)
            fprintf(to, ", %d species in their own schools", sc->fish.nspecies);
        if (s == WW_SYS_STONES) fprintf(to, " up to %d in flight", WW_MAX_STONES);
        if (s == WW_SYS_ROD) fprintf(to, " lure active %g s after landing", sc->rod.window);
        if (s == WW_SYS_CHEST)
            fprintf(to, " first at %g s, every %g s, lasts %g s", sc->chest.first, sc->chest.every,
                    sc->chest.ttl);
        if (s == WW_SYS_BUBBLES) fprintf(to, " %d emitters", sc->bubbles.count);
        if (s == WW_SYS_BOAT) fprintf(to, " radius %g m", sc->boat.radius);
        if (s == WW_SYS_COLLIDE) {
            int solid = 0;
            for (int i = 0; i < sc->models.count; i++) solid += sc->models.model[i].solid;
            fprintf(to, " boat %d, cubes %d, chest %d, models %d", sc->boat.on,
                    sc->cubes.on ? sc->cubes.count : 0, sc->chest.on, solid);
            if (solid < sc->models.count)
                fprintf(to, " (%d not solid)", sc->models.count - solid);
        }
        fputc('\n', to);
    }
    print_water(sc, &p->water, to);
    fprintf(to, "passes\n");
    size_t total = 0;
    for (int i = 0; i < p->npasses; i++) {
        const ww_pass_desc *d = &p->passes[i];
        fprintf(to, "  %2d %-10s %s\n", i + 1, d->name, d->what);
        for (int t = 0; t < d->ntargets; t++) {
            const ww_target_desc *td = &d->targets[t];
            size_t bytes = (size_t)td->width * (size_t)td->height * ww_format_bytes_per_pixel(td->format);
            if (d->samples[t] > 1) bytes *= (size_t)d->samples[t]; /* post: every sample stored */
            total += bytes;
            fprintf(to, "      %-10s %-8s %5dx%-5d %10zu bytes", td->name, ww_format_name(td->format),
                    td->width, td->height, bytes);
            if (d->samples[t] > 1) fprintf(to, "  msaa x%d", d->samples[t]);
            fputc('\n', to);
        }
    }
    fprintf(to, "gpu memory %zu bytes (%.1f MiB) in render targets\n", total, (double)total / 1048576.0);
}
