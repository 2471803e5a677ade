/* compile_render.c - how a scene is drawn (scene/desc_render.h): render.* (size, tone mapping
 * and each pass's switch and knobs), sky.*, fog.above / fog.below, water.look and lights.
 * A feature is `true` / `false` or a mapping of its knobs; a mapping means on unless it says
 * `on: false`.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/mathx.h"
#include "scene/assets.h"
#include "scene/compile_impl.h"

static const rule R_SIZE = WHOLE(WW_SIZE_MIN, WW_SIZE_MAX, "px");
static const rule R_EXPOSURE = OPEN_LO(0, 100, "");
static const rule R_GAMMA = CLOSED(0.5, 5, "");
static const rule R_HOURS = CLOSED(0, 24, "h");
static const rule R_DAY_LENGTH = CLOSED(0, 1e9, "s");
static const rule R_SUN_MAX = CLOSED(0, 90, "deg");
static const rule R_COLOR = CLOSED(0, 100, "");
static const rule R_ALBEDO = CLOSED(0, 1, "");
static const rule R_FOG_DENSITY = CLOSED(0, 10, "1/m");
static const rule R_SHADOW_SIZE = WHOLE(64, 8192, "texels");
static const rule R_SOFTNESS = CLOSED(0, 8, "texels");
static const rule R_SHADOW_DISTANCE = OPEN_LO(0, 1e5, "m");
static const rule R_SCALE = CLOSED(0.0625, 1, "");
static const rule R_THRESHOLD = CLOSED(0, 1e3, "");
static const rule R_STRENGTH = CLOSED(0, 100, "");
static const rule R_BLOOM_PASSES = WHOLE(1, 16, "");
static const rule R_SAMPLES = WHOLE(4, 256, "");
static const rule R_UNIT = CLOSED(0, 1, "");
static const rule R_SHAFT_WEIGHT = CLOSED(0, 10, "");
static const rule R_SHAFT_EXPOSURE = CLOSED(0, 100, "");
static const rule R_MSAA = WHOLE(0, 16, "samples");
static const rule R_GRID = CLOSED(0.25, 4, "");
static const rule R_FRAME_SCALE = CLOSED(0.25, 1, "");
static const rule R_INTENSITY = CLOSED(0, 1e6, "");
static const rule R_TURBIDITY = CLOSED(1.7, 10, ""); /* where Preetham's fit holds */
static const rule R_CLOUD_SPEED = CLOSED(0, 100, "cells/s");
static const rule R_CLOUD_SEED = WHOLE(0, 1000000, "");
static const rule R_FRESNEL = CLOSED(0, 16, "");
static const rule R_DISTORTION = CLOSED(0, 0.5, "");
static const rule R_PER_METRE = OPEN_LO(0, 1e3, "1/m");
static const rule R_DRIFT = CLOSED(0, 100, "m/s");
static const rule R_MURK = CLOSED(0, 100, "1/m");
static const rule R_POSITION = FINITE("m");
static const rule R_DIRECTION = FINITE("");
static const rule R_RANGE = OPEN_LO(0, 1e5, "m");
static const rule R_CONE = OPEN_LO(0, 89, "deg");
static const rule R_RATE = CLOSED(0, 100, "Hz");
static const rule R_FOAM_LIFE = CLOSED(0, 30, "s");
static const rule R_SCATTER = CLOSED(0, 20, "");

static const char *const TONEMAP_WORDS[] = {[WW_TONEMAP_EXP] = "exp", [WW_TONEMAP_ACES] = "aces",
                                            NULL};
static const char *const SKY_WORDS[] = {[WW_SKY_GRADIENT] = "gradient",
                                        [WW_SKY_CUBEMAP] = "cubemap", [WW_SKY_DOME] = "dome",
                                        [WW_SKY_PREETHAM] = "preetham", NULL};
static const char *const FRESNEL_WORDS[] = {[WW_FRESNEL_BIAS_SCALE] = "bias_scale",
                                            [WW_FRESNEL_SCHLICK] = "schlick", NULL};
static const char *const CAUSTICS_WORDS[] = {[WW_CAUSTICS_ANALYTIC] = "analytic",
                                             [WW_CAUSTICS_TEXTURE] = "texture", NULL};
static const char *const DETAIL_WORDS[] = {[WW_DETAIL_EXACT] = "exact",
                                           [WW_DETAIL_TEXTURE] = "texture", NULL};
static const char *const LIGHT_WORDS[] = {[WW_LIGHT_POINT] = "point", [WW_LIGHT_SPOT] = "spot",
                                          NULL};
static const char *const BOOL_WORDS[] = {"false", "true", NULL};
/* render.shadows as one word: off, or the technique (the order of ww_shadow_technique, plus 1) */
static const char *const SHADOW_WORDS[] = {"off", "map", "projected", "volumes", "volumes_visible",
                                           NULL};
static const char *const TECHNIQUE_WORDS[] = {[WW_SHADOW_MAP] = "map",
                                              [WW_SHADOW_PROJECTED] = "projected",
                                              [WW_SHADOW_VOLUMES] = "volumes",
                                              [WW_SHADOW_VOLUMES_VISIBLE] = "volumes_visible",
                                              NULL};
static const char *const HUD_WORDS[] = {"clock", "counters", "chest_marker", NULL};
static const char *const QUALITY_WORDS[] = {[WW_QUALITY_FINAL] = "final",
                                            [WW_QUALITY_PREVIEW] = "preview",
                                            [WW_QUALITY_DRAFT] = "draft", NULL};

/* render.quality's knob values over the defaults, each taken from `bench quality`'s
 * speed/error front on the lake, demo and reef at 1280x720 (docs/speed.md, "Quality presets"):
 * the knobs whose cheaper values cost the least picture per millisecond saved. The scene's own
 * keys, read after, override any of them. Final is the defaults themselves. */
static void apply_quality(ww_render_desc *d, ww_quality q) {
    d->quality = q;
    if (q == WW_QUALITY_FINAL) return;
    int draft = q == WW_QUALITY_DRAFT;
    d->reflection.scale = draft ? 0.125 : 0.25; /* the DuDv and the waves blur it anyway */
    d->shafts.samples = draft ? 16 : 32;
    /* the outlines seen through the water are upsampled by the full-size depth, so a quarter
     * keeps them where they lie; what it blurs is the seabed's detail under the murk */
    d->refraction_scale = 0.25;
    /* the whole frame smaller and scaled up: every pass gets cheaper in proportion, and what is
     * lost is the far water's finest detail, spread thin; at 0.9 and 0.75 a cheaper trade than
     * a coarser water mesh (whose rings fade the short waves nearer) at about the same error */
    d->scale = draft ? 0.75 : 0.9;
    if (draft) {
        d->shadows.size = 512;
        d->fxaa = 0; /* the edges are stepped, then softened by the scaling up */
    }
}
static const char *const FACE_NAMES[6] = {"+x", "-x", "+y", "-y", "+z", "-z"};

void ww_render_defaults(ww_render_desc *d) {
    *d = (ww_render_desc){0};
    d->shadows = (ww_shadow_desc){.on = 1, .size = 1024, .softness = 1.5, .distance = 60.0};
    d->refraction = 1;
    /* murk and the distortion blur what is refracted: half the resolution costs a quarter */
    d->refraction_scale = 0.5;
    d->reflection = (ww_reflection_desc){.on = 1, .scale = 0.5};
    /* the blur at a quarter of the frame draws the glow it draws at half (pass_bloom.c matches
     * the kernel) for a third of the time */
    d->bloom = (ww_bloom_desc){.on = 1, .threshold = 1.0, .strength = 0.6, .passes = 3,
                               .scale = 0.25};
    /* decay 0.985: at 0.95 the 48th sample, the light's end of the march, weighed 0.95^48 = 9%
     * of the first, so the sum was the mask around the pixel: a glow, in which an occluder in
     * front of the sun cast no ray. 0.985^48 = 48% keeps the light's end in the sum (Mitchell's
     * own examples use a decay near 1); the exposure halves to keep the mean. */
    d->shafts = (ww_shafts_desc){.on = 1, .samples = 48, .decay = 0.985, .density = 0.9,
                                 .weight = 0.35, .exposure = 0.13, .underwater = 3.0,
                                 .scale = 0.25}; /* the radial blur is smooth: a quarter of the
                                                  * frame looks the same at a quarter the cost */
    d->fxaa = 1;
    d->msaa = 0;
    d->grid = 1.0;
    d->scale = 1.0;
    d->sky = WW_SKY_PREETHAM;
    for (int i = 0; i < 6; i++) d->cubemap_image[i] = -1;
    d->dome_image = -1;
    d->sky_intensity = 1.0;
    d->sky_turbidity = 2.5;
    d->cloud_cover = 0.0;
    d->cloud_speed = 1.0;
    /* seed 003's green-blue water seen from inside; exp2 fog leaves 2% of the contrast at
     * 1.98 / density: 20 m, a clear lake's visibility */
    d->fog_below_color[0] = 0.02;
    d->fog_below_color[1] = 0.12;
    d->fog_below_color[2] = 0.15;
    d->fog_below_density = 0.1;
    d->seabed = 1;
    d->seabed_color[0] = 0.55;
    d->seabed_color[1] = 0.48;
    d->seabed_color[2] = 0.34;
    d->water = (ww_water_look){.fresnel = WW_FRESNEL_SCHLICK,
                               .fresnel_bias = 0.02,
                               .fresnel_scale = 0.98,
                               .fresnel_power = 5.0,
                               .distortion = 0.02,
                               .distortion_scale = 0.5,
                               .distortion_speed = 0.03,
                               .specular = 1.0,
                               .foam = 1,
                               .foam_amount = 0.5,
                               .foam_life = 2.0,
                               .murk = 0.15,
                               .caustics = 1,
                               .caustics_strength = 0.6,
                               .alpha_blend = 0,
                               .alpha = 0.6};
}

/* key: true | false | a mapping with keys (which may hold `on: false`). *on is set from the
 * value; *out is the mapping (map NULL for a word or when absent, so the knobs keep defaults) */
static ww_result get_feature(ctx *c, const section *s, const char *key, const char *const *keys,
                             int *on, section *out) {
    const ww_node *n;
    *out = (section){0};
    wwc_path_of(s, key, out->what, sizeof out->what);
    TRY(wwc_lookup(c, s, key, OPTIONAL, &n));
    if (!n) return WW_OK;
    if (n->kind == WW_NODE_MAP) {
        TRY(wwc_open_section(c, s, key, keys, out));
        *on = 1;
        return wwc_get_word(c, out, "on", BOOL_WORDS, on);
    }
    return wwc_get_word(c, s, key, BOOL_WORDS, on);
}

/* render.shadows: true | false | off | map | projected | volumes | volumes_visible, or a
 * mapping {on, technique, size, softness, distance} (size, softness and distance are the map's) */
static ww_result compile_shadows(ctx *c, const section *s, ww_shadow_desc *d) {
    static const char *const keys[] = {"on", "technique", "size", "softness", "distance", NULL};
    const ww_node *n;
    TRY(wwc_lookup(c, s, "shadows", OPTIONAL, &n));
    if (n && n->kind == WW_NODE_SCALAR && !ww_node_is_null(n) && strcmp(n->text, "true") != 0 &&
        strcmp(n->text, "false") != 0) {
        int w = 0;
        TRY(wwc_get_word(c, s, "shadows", SHADOW_WORDS, &w)); /* the design's spelling */
        d->on = w > 0;
        if (w > 0) d->technique = (ww_shadow_technique)(w - 1);
        return WW_OK;
    }
    section f;
    TRY(get_feature(c, s, "shadows", keys, &d->on, &f));
    int t = (int)d->technique;
    TRY(wwc_get_word(c, &f, "technique", TECHNIQUE_WORDS, &t));
    d->technique = (ww_shadow_technique)t;
    double size = d->size;
    TRY(wwc_get_number(c, &f, "size", &R_SHADOW_SIZE, OPTIONAL, &size));
    d->size = (int)size;
    TRY(wwc_get_number(c, &f, "softness", &R_SOFTNESS, OPTIONAL, &d->softness));
    return wwc_get_number(c, &f, "distance", &R_SHADOW_DISTANCE, OPTIONAL, &d->distance);
}

static ww_result compile_hud(ctx *c, const section *s, ww_hud_desc *d) {
    const ww_node *list;
    TRY(wwc_get_list(c, s, "hud", 3, &list));
    if (!list) return WW_OK;
    *d = (ww_hud_desc){0};
    int *flag[3] = {&d->clock, &d->counters, &d->chest_marker};
    int i = 0;
    for (const ww_node *item = list->first; item; item = item->next, i++) {
        char list_words[96];
        wwc_join_words(HUD_WORDS, list_words, sizeof list_words);
        if (item->kind != WW_NODE_SCALAR || ww_node_is_null(item))
            return wwc_fail(c, WW_E_TYPE, item, "render.hud[%d]: expected one of: %s", i,
                            list_words);
        int w = 0;
        while (HUD_WORDS[w] && strcmp(HUD_WORDS[w], item->text) != 0) w++;
        if (!HUD_WORDS[w]) {
            const char *near = wwc_nearest(item->text, HUD_WORDS);
            return wwc_fail(c, WW_E_ENUM, item, "render.hud[%d]: '%s' is not one of: %s%s%s%s", i,
                            item->text, list_words, near ? " (did you mean '" : "",
                            near ? near : "", near ? "'?)" : "");
        }
        *flag[w] = 1;
    }
    return WW_OK;
}

ww_result wwc_render(ctx *c, const section *top) {
    static const char *const keys[] = {"size", "quality", "tonemap", "shadows", "refraction",
                                       "reflection", "bloom", "god_rays", "fxaa", "msaa", "grid",
                                       "scale", "hud", "seabed", NULL};
    static const char *const tonemap_keys[] = {"operator", "exposure", "gamma", "dither", NULL};
    static const char *const reflection_keys[] = {"on", "scale", NULL};
    static const char *const refraction_keys[] = {"on", "scale", NULL};
    static const char *const bloom_keys[] = {"on", "threshold", "strength", "passes", "scale",
                                             NULL};
    static const char *const shaft_keys[] = {"on", "samples", "decay", "density", "weight",
                                             "exposure", "underwater", "scale", NULL};
    static const char *const seabed_keys[] = {"on", "color", NULL};
    ww_scene *sc = c->sc;
    ww_render_desc *d = &sc->render;
    section s, tm, f;
    TRY(wwc_open_section(c, top, "render", keys, &s));
    double size[2] = {sc->width, sc->height};
    TRY(wwc_get_vec(c, &s, "size", 2, &R_SIZE, OPTIONAL, size));
    sc->width = (int)size[0];
    sc->height = (int)size[1];
    int quality = (int)d->quality;
    TRY(wwc_get_word(c, &s, "quality", QUALITY_WORDS, &quality));
    apply_quality(d, (ww_quality)quality);

    TRY(wwc_open_section(c, &s, "tonemap", tonemap_keys, &tm));
    int op = (int)sc->tonemap;
    TRY(wwc_get_word(c, &tm, "operator", TONEMAP_WORDS, &op));
    sc->tonemap = (ww_tonemap_op)op;
    TRY(wwc_get_number(c, &tm, "exposure", &R_EXPOSURE, OPTIONAL, &sc->exposure));
    TRY(wwc_get_number(c, &tm, "gamma", &R_GAMMA, OPTIONAL, &sc->gamma));
    TRY(wwc_get_word(c, &tm, "dither", BOOL_WORDS, &sc->dither));

    TRY(compile_shadows(c, &s, &d->shadows));
    TRY(get_feature(c, &s, "refraction", refraction_keys, &d->refraction, &f));
    TRY(wwc_get_number(c, &f, "scale", &R_SCALE, OPTIONAL, &d->refraction_scale));

    TRY(get_feature(c, &s, "reflection", reflection_keys, &d->reflection.on, &f));
    TRY(wwc_get_number(c, &f, "scale", &R_SCALE, OPTIONAL, &d->reflection.scale));

    TRY(get_feature(c, &s, "bloom", bloom_keys, &d->bloom.on, &f));
    TRY(wwc_get_number(c, &f, "threshold", &R_THRESHOLD, OPTIONAL, &d->bloom.threshold));
    TRY(wwc_get_number(c, &f, "strength", &R_STRENGTH, OPTIONAL, &d->bloom.strength));
    double passes = d->bloom.passes;
    TRY(wwc_get_number(c, &f, "passes", &R_BLOOM_PASSES, OPTIONAL, &passes));
    d->bloom.passes = (int)passes;
    TRY(wwc_get_number(c, &f, "scale", &R_SCALE, OPTIONAL, &d->bloom.scale));

    ww_shafts_desc *g = &d->shafts;
    TRY(get_feature(c, &s, "god_rays", shaft_keys, &g->on, &f));
    double samples = g->samples;
    TRY(wwc_get_number(c, &f, "samples", &R_SAMPLES, OPTIONAL, &samples));
    g->samples = (int)samples;
    TRY(wwc_get_number(c, &f, "decay", &R_UNIT, OPTIONAL, &g->decay));
    TRY(wwc_get_number(c, &f, "density", &R_UNIT, OPTIONAL, &g->density));
    TRY(wwc_get_number(c, &f, "weight", &R_SHAFT_WEIGHT, OPTIONAL, &g->weight));
    TRY(wwc_get_number(c, &f, "exposure", &R_SHAFT_EXPOSURE, OPTIONAL, &g->exposure));
    TRY(wwc_get_number(c, &f, "underwater", &R_SHAFT_EXPOSURE, OPTIONAL, &g->underwater));
    TRY(wwc_get_number(c, &f, "scale", &R_SCALE, OPTIONAL, &g->scale));

    TRY(wwc_get_word(c, &s, "fxaa", BOOL_WORDS, &d->fxaa));
    double msaa = d->msaa;
    TRY(wwc_get_number(c, &s, "msaa", &R_MSAA, OPTIONAL, &msaa));
    d->msaa = (int)msaa;
    TRY(wwc_get_number(c, &s, "grid", &R_GRID, OPTIONAL, &d->grid));
    TRY(wwc_get_number(c, &s, "scale", &R_FRAME_SCALE, OPTIONAL, &d->scale));
    TRY(compile_hud(c, &s, &d->hud));

    TRY(get_feature(c, &s, "seabed", seabed_keys, &d->seabed, &f));
    return wwc_get_vec(c, &f, "color", 3, &R_ALBEDO, OPTIONAL, d->seabed_color);
}

/* a cubemap's six image files, resolved against the scene file's folder */
static ww_result compile_cubemap(ctx *c, const section *s) {
    ww_render_desc *d = &c->sc->render;
    const ww_node *list;
    TRY(wwc_get_list(c, s, "cubemap", 6, &list));
    if (d->sky == WW_SKY_CUBEMAP && !list)
        return wwc_fail(c, WW_E_MISSING, s->map,
                        "sky.model is cubemap but sky.cubemap is missing: expected a list of six "
                        "image files (+x, -x, +y, -y, +z, -z)");
    if (!list) return WW_OK;
    if (list->n != 6)
        return wwc_fail(c, WW_E_RANGE, list,
                        "sky.cubemap: expected six image files (+x, -x, +y, -y, +z, -z), got %d",
                        list->n);
    int i = 0;
    for (const ww_node *item = list->first; item; item = item->next, i++) {
        if (item->kind != WW_NODE_SCALAR || ww_node_is_null(item))
            return wwc_fail(c, WW_E_TYPE, item, "sky.cubemap[%d] (%s): expected a file name", i,
                            FACE_NAMES[i]);
        TRY(wwc_resolve_path(c, item, d->cubemap[i], sizeof d->cubemap[i]));
    }
    /* only a cubemap sky decodes its faces (a gradient sky may keep the list, unused) */
    if (d->sky != WW_SKY_CUBEMAP) return WW_OK;
    if (!c->sc->assets && !(c->sc->assets = calloc(1, sizeof *c->sc->assets)))
        return wwc_fail(c, WW_E_NOMEM, list, "out of memory for the scene's assets");
    i = 0;
    for (const ww_node *item = list->first; item; item = item->next, i++)
        TRY(ww_assets_image(c->sc->assets, d->cubemap[i],
                            item->mark.file ? item->mark.file : c->file, item->mark.line,
                            item->mark.column, &d->cubemap_image[i], c->err));
    /* a GL cubemap's faces are squares of one size */
    const ww_image_data *im = c->sc->assets->image;
    int side = im[d->cubemap_image[0]].width;
    for (i = 0; i < 6; i++) {
        const ww_image_data *f = &im[d->cubemap_image[i]];
        if (f->width != side || f->height != side)
            return wwc_fail(c, WW_E_INCONSISTENT, list,
                            "sky.cubemap[%d] (%s) is %dx%d, sky.cubemap[0] (+x) %dx%d: expected "
                            "six square faces of one size",
                            i, FACE_NAMES[i], f->width, f->height, side,
                            im[d->cubemap_image[0]].height);
    }
    return WW_OK;
}

/* the mean linear colour of the dome picture's outer ring, from DOME_RING_INNER of the inscribed
 * circle's radius to its edge (the sky from about 5 deg above the horizon down to it): the
 * colour far water and objects fade into, as Preetham's haze is for its sky. Without it the fog
 * took the procedural sky's horizon, and the farthest water drew a grey line under the picture's
 * horizon. */
#define DOME_RING_INNER 0.94
static double srgb_to_linear(double v) {
    return v <= 0.04045 ? v / 12.92 : pow((v + 0.055) / 1.055, 2.4);
}
static ww_result dome_ring_mean(ctx *c, const ww_node *n, const ww_image_data *im, double out[3]) {
    unsigned char *rgba = NULL;
    ww_error e = {0};
    if (ww_assets_decode(im, &rgba, &e) != WW_OK)
        return wwc_fail(c, e.code ? e.code : WW_E_IO, n, "sky.image: %s", e.msg);
    double sum[3] = {0.0, 0.0, 0.0}, half = 0.5 * (im->width < im->height ? im->width : im->height);
    long count = 0;
    for (int y = 0; y < im->height; y++)
        for (int x = 0; x < im->width; x++) {
            double dx = (x + 0.5 - 0.5 * im->width) / half, dy = (y + 0.5 - 0.5 * im->height) / half;
            double r = sqrt(dx * dx + dy * dy);
            if (r < DOME_RING_INNER || r > 1.0) continue;
            const unsigned char *p = rgba + 4 * ((size_t)y * (size_t)im->width + (size_t)x);
            for (int k = 0; k < 3; k++) sum[k] += srgb_to_linear(p[k] / 255.0);
            count++;
        }
    ww_assets_pixels_free(rgba);
    for (int k = 0; k < 3; k++) out[k] = count ? sum[k] / (double)count : 0.0;
    return WW_OK;
}

/* sky.image: a picture of the sky mapped on the dome (sky.model dome only), resolved against the
 * scene file's folder and read (its size checked) now, decoded when the sky is drawn (and once
 * here, for the colour of its horizon) */
static ww_result compile_dome_image(ctx *c, const section *s) {
    ww_render_desc *d = &c->sc->render;
    const ww_node *n;
    TRY(wwc_lookup(c, s, "image", OPTIONAL, &n));
    if (!n) return WW_OK;
    if (n->kind != WW_NODE_SCALAR || ww_node_is_null(n) || n->len == 0)
        return wwc_fail(c, WW_E_TYPE, n, "sky.image: expected an image file name");
    if (d->sky != WW_SKY_DOME)
        return wwc_fail(c, WW_E_INCONSISTENT, n,
                        "sky.image is a picture for the dome: it needs sky.model dome");
    TRY(wwc_resolve_path(c, n, d->dome_image_path, sizeof d->dome_image_path));
    if (!c->sc->assets && !(c->sc->assets = calloc(1, sizeof *c->sc->assets)))
        return wwc_fail(c, WW_E_NOMEM, n, "out of memory for the scene's assets");
    TRY(ww_assets_image(c->sc->assets, d->dome_image_path, n->mark.file ? n->mark.file : c->file,
                        n->mark.line, n->mark.column, &d->dome_image, c->err));
    return dome_ring_mean(c, n, &c->sc->assets->image[d->dome_image], d->dome_horizon);
}

ww_result wwc_sky(ctx *c, const section *top) {
    static const char *const keys[] = {"model",     "time_of_day", "day_length", "sun_max_elevation",
                                       "cubemap",   "intensity",   "turbidity",  "clouds",
                                       "image",     NULL};
    static const char *const cloud_keys[] = {"cover", "speed", "seed", NULL};
    ww_scene *sc = c->sc;
    section s, cl;
    TRY(wwc_open_section(c, top, "sky", keys, &s));
    int model = (int)sc->render.sky;
    TRY(wwc_get_word(c, &s, "model", SKY_WORDS, &model));
    sc->render.sky = (ww_sky_model)model;
    TRY(wwc_get_number(c, &s, "time_of_day", &R_HOURS, OPTIONAL, &sc->time_of_day));
    TRY(wwc_get_number(c, &s, "day_length", &R_DAY_LENGTH, OPTIONAL, &sc->day_length));
    TRY(wwc_get_angle(c, &s, "sun_max_elevation", &R_SUN_MAX, OPTIONAL, &sc->sun_max_elevation));
    TRY(wwc_get_number(c, &s, "intensity", &R_INTENSITY, OPTIONAL, &sc->render.sky_intensity));
    TRY(wwc_get_number(c, &s, "turbidity", &R_TURBIDITY, OPTIONAL, &sc->render.sky_turbidity));
    TRY(wwc_open_section(c, &s, "clouds", cloud_keys, &cl));
    if (cl.map) {
        double seed = sc->render.cloud_seed;
        TRY(wwc_get_number(c, &cl, "cover", &R_UNIT, OPTIONAL, &sc->render.cloud_cover));
        TRY(wwc_get_number(c, &cl, "speed", &R_CLOUD_SPEED, OPTIONAL, &sc->render.cloud_speed));
        TRY(wwc_get_number(c, &cl, "seed", &R_CLOUD_SEED, OPTIONAL, &seed));
        sc->render.cloud_seed = (int)seed;
    }
    TRY(compile_dome_image(c, &s));
    return compile_cubemap(c, &s);
}

ww_result wwc_fog(ctx *c, const section *top) {
    static const char *const keys[] = {"above", "below", NULL};
    static const char *const layer_keys[] = {"color", "density", NULL};
    ww_scene *sc = c->sc;
    section s, above, below;
    TRY(wwc_open_section(c, top, "fog", keys, &s));
    TRY(wwc_open_section(c, &s, "above", layer_keys, &above));
    TRY(wwc_get_vec(c, &above, "color", 3, &R_COLOR, OPTIONAL, sc->fog_color));
    TRY(wwc_get_number(c, &above, "density", &R_FOG_DENSITY, OPTIONAL, &sc->fog_density));
    TRY(wwc_open_section(c, &s, "below", layer_keys, &below));
    TRY(wwc_get_vec(c, &below, "color", 3, &R_COLOR, OPTIONAL, sc->render.fog_below_color));
    return wwc_get_number(c, &below, "density", &R_FOG_DENSITY, OPTIONAL,
                          &sc->render.fog_below_density);
}

ww_result wwc_water_look(ctx *c, const section *water) {
    static const char *const keys[] = {"fresnel", "fresnel_bias", "fresnel_scale",
                                       "fresnel_power", "distortion", "distortion_scale",
                                       "distortion_speed", "specular", "foam", "murk",
                                       "caustics", "alpha_blend", "detail", NULL};
    static const char *const foam_keys[] = {"on", "amount", "life", NULL};
    static const char *const caustic_keys[] = {"on", "strength", "method", NULL};
    static const char *const alpha_keys[] = {"on", "alpha", NULL};
    ww_water_look *w = &c->sc->render.water;
    section s, f;
    TRY(wwc_open_section(c, water, "look", keys, &s));
    int fresnel = (int)w->fresnel;
    TRY(wwc_get_word(c, &s, "fresnel", FRESNEL_WORDS, &fresnel));
    w->fresnel = (ww_fresnel)fresnel;
    TRY(wwc_get_number(c, &s, "fresnel_bias", &R_UNIT, OPTIONAL, &w->fresnel_bias));
    TRY(wwc_get_number(c, &s, "fresnel_scale", &R_UNIT, OPTIONAL, &w->fresnel_scale));
    TRY(wwc_get_number(c, &s, "fresnel_power", &R_FRESNEL, OPTIONAL, &w->fresnel_power));
    TRY(wwc_get_number(c, &s, "distortion", &R_DISTORTION, OPTIONAL, &w->distortion));
    TRY(wwc_get_number(c, &s, "distortion_scale", &R_PER_METRE, OPTIONAL, &w->distortion_scale));
    TRY(wwc_get_number(c, &s, "distortion_speed", &R_DRIFT, OPTIONAL, &w->distortion_speed));
    TRY(wwc_get_number(c, &s, "specular", &R_STRENGTH, OPTIONAL, &w->specular));
    TRY(wwc_get_number(c, &s, "murk", &R_MURK, OPTIONAL, &w->murk));
    int detail = (int)w->detail;
    TRY(wwc_get_word(c, &s, "detail", DETAIL_WORDS, &detail));
    w->detail = (ww_water_detail_method)detail;
    TRY(get_feature(c, &s, "foam", foam_keys, &w->foam, &f));
    TRY(wwc_get_number(c, &f, "amount", &R_UNIT, OPTIONAL, &w->foam_amount));
    TRY(wwc_get_number(c, &f, "life", &R_FOAM_LIFE, OPTIONAL, &w->foam_life));
    TRY(get_feature(c, &s, "caustics", caustic_keys, &w->caustics, &f));
    TRY(wwc_get_number(c, &f, "strength", &R_STRENGTH, OPTIONAL, &w->caustics_strength));
    int method = (int)w->caustics_method;
    TRY(wwc_get_word(c, &f, "method", CAUSTICS_WORDS, &method));
    w->caustics_method = (ww_caustics_method)method;
    TRY(get_feature(c, &s, "alpha_blend", alpha_keys, &w->alpha_blend, &f));
    return wwc_get_number(c, &f, "alpha", &R_UNIT, OPTIONAL, &w->alpha);
}

static ww_result compile_light(ctx *c, const ww_node *item, int i, ww_light_desc *l) {
    static const char *const keys[] = {"type", "position", "direction", "color", "intensity",
                                       "range", "angle", "softness", "flicker", "flicker_rate",
                                       "parent", "scatter", NULL};
    section s;
    TRY(wwc_open_item(c, item, "lights", i, keys, &s));
    *l = (ww_light_desc){.kind = WW_LIGHT_POINT,
                         .direction = {0.0, -1.0, 0.0},
                         .color = {1.0, 0.8, 0.55},
                         .intensity = 4.0,
                         .range = 12.0,
                         .angle = ww_m_rad(30.0),
                         .softness = 0.25,
                         .flicker = 0.0,
                         .flicker_rate = 6.0,
                         .scatter = 1.0,
                         .line = s.map->mark.line,
                         .column = s.map->mark.column};
    int kind = (int)l->kind;
    TRY(wwc_get_word(c, &s, "type", LIGHT_WORDS, &kind));
    l->kind = (ww_light_kind)kind;
    TRY(wwc_get_vec(c, &s, "position", 3, &R_POSITION, REQUIRED, l->position));
    TRY(wwc_get_vec(c, &s, "direction", 3, &R_DIRECTION, OPTIONAL, l->direction));
    double len = sqrt(l->direction[0] * l->direction[0] + l->direction[1] * l->direction[1] +
                      l->direction[2] * l->direction[2]);
    if (!(len > 1e-9))
        return wwc_fail(c, WW_E_RANGE, ww_node_find(s.map, "direction"),
                        "%s.direction: expected a non-zero vector", s.what);
    for (int a = 0; a < 3; a++) l->direction[a] /= len;
    TRY(wwc_get_vec(c, &s, "color", 3, &R_COLOR, OPTIONAL, l->color));
    TRY(wwc_get_number(c, &s, "intensity", &R_INTENSITY, OPTIONAL, &l->intensity));
    TRY(wwc_get_number(c, &s, "range", &R_RANGE, OPTIONAL, &l->range));
    TRY(wwc_get_angle(c, &s, "angle", &R_CONE, OPTIONAL, &l->angle));
    TRY(wwc_get_number(c, &s, "softness", &R_UNIT, OPTIONAL, &l->softness));
    TRY(wwc_get_number(c, &s, "flicker", &R_UNIT, OPTIONAL, &l->flicker));
    TRY(wwc_get_number(c, &s, "flicker_rate", &R_RATE, OPTIONAL, &l->flicker_rate));
    TRY(wwc_get_number(c, &s, "scatter", &R_SCATTER, OPTIONAL, &l->scatter));
    const ww_node *parent;
    TRY(wwc_lookup(c, &s, "parent", OPTIONAL, &parent));
    if (parent) {
        if (parent->kind != WW_NODE_SCALAR || ww_node_is_null(parent) ||
            parent->len >= sizeof l->parent)
            return wwc_fail(c, WW_E_TYPE, parent,
                            "%s.parent: expected 'boat' or a model's name (at most %zu characters)",
                            s.what, sizeof l->parent - 1);
        snprintf(l->parent, sizeof l->parent, "%s", parent->text);
    }
    return WW_OK;
}

ww_result wwc_lights(ctx *c, const section *top) {
    ww_render_desc *d = &c->sc->render;
    const ww_node *list;
    TRY(wwc_get_list(c, top, "lights", WW_MAX_LIGHTS, &list));
    int i = 0;
    for (const ww_node *item = list ? list->first : NULL; item; item = item->next, i++)
        TRY(compile_light(c, item, i, &d->light[i]));
    d->nlights = i;
    return WW_OK;
}

/* a light's parent names the boat or a model; checked once models are read */
ww_result wwc_check_lights(ctx *c, const ww_node *root) {
    const ww_scene *sc = c->sc;
    for (int i = 0; i < sc->render.nlights; i++) {
        const ww_light_desc *l = &sc->render.light[i];
        if (!l->parent[0]) continue;
        if (strcmp(l->parent, "boat") == 0) {
            if (sc->boat.on) continue;
            return wwc_fail(c, WW_E_INCONSISTENT, ww_node_at(ww_node_find(root, "lights"), i),
                            "lights[%d].parent is 'boat' but the scene has no objects.boat", i);
        }
        int found = 0;
        for (int m = 0; m < sc->models.count && !found; m++)
            found = strcmp(sc->models.model[m].name, l->parent) == 0;
        if (!found)
            return wwc_fail(c, WW_E_INCONSISTENT, ww_node_at(ww_node_find(root, "lights"), i),
                            "lights[%d].parent '%s' names no model (objects.models[].name) and is "
                            "not 'boat'",
                            i, l->parent);
    }
    return WW_OK;
}
