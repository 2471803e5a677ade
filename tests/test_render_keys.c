/* test_render_keys.c - how a scene asks to be drawn (scene/desc_render.h): each feature's forms
 * (true / false / a mapping of knobs / `on: false`), the knobs' values, and the plan creating a
 * pass exactly when its switch is on and the scene has what it needs. No GL.
 */
#include <string.h>

#include "scene/plan.h"
#include "scene/scene.h"
#include "test.h"

#define KNOB_TOL 1e-12 /* knobs are copied from the file, not computed */

static const char BASE[] = "time: {dt: 1/120, fps: 30, duration: 1}\n"
                           "render: {size: [320, 180]}\n";

static ww_scene *load(const char *text, const char *const *sets, int nsets) {
    ww_set s[8] = {{0}};
    for (int i = 0; i < nsets; i++) s[i].text = sets[i];
    ww_scene *sc = NULL;
    ww_error err = {0};
    ww_result r = ww_scene_load_string("keys.yaml", text, strlen(text), s, nsets, &sc, &err);
    ENSURE_MSG(r == WW_OK, "%s", err.msg);
    return sc;
}

static int has_pass(const ww_plan *p, ww_pass_id id) { return ww_plan_pass(p, id) != NULL; }

TEST(render_keys_feature_forms) {
    const char *sets[] = {"render.bloom=true", "render.reflection={scale: 0.25}",
                          "render.god_rays={on: false, samples: 16}", "render.shadows=map",
                          "render.fxaa=true"};
    ww_scene *sc = load(BASE, sets, 5);
    if (!sc) return;
    const ww_render_desc *d = &sc->render;
    ENSURE_EQ_INT(d->bloom.on, 1);
    ENSURE_EQ_INT(d->reflection.on, 1);
    ENSURE_NEAR(d->reflection.scale, 0.25, KNOB_TOL);
    ENSURE_EQ_INT(d->shafts.on, 0);
    ENSURE_EQ_INT(d->shafts.samples, 16); /* knobs are read even when the feature is off */
    ENSURE_EQ_INT(d->shadows.on, 1);
    ENSURE_EQ_INT(d->fxaa, 1);
    ww_scene_free(sc);
}

TEST(render_keys_hud_lights_and_look) {
    static const char text[] =
        "time: {dt: 1/120, fps: 30, duration: 1}\n"
        "render: {hud: [clock, chest_marker]}\n"
        "fog: {below: {color: [0.1, 0.2, 0.3], density: 0.05}}\n"
        "water: {look: {fresnel: bias_scale, fresnel_power: 3, foam: {amount: 0.8},"
        " caustics: true, alpha_blend: {alpha: 0.4}}}\n"
        "lights:\n"
        "  - {type: spot, position: [1, 2, 3], direction: [0, -2, 0], angle: 20}\n"
        "  - {position: [0, 1, 0], color: [1, 0, 0], range: 5}\n";
    ww_scene *sc = load(text, NULL, 0);
    if (!sc) return;
    const ww_render_desc *d = &sc->render;
    ENSURE_EQ_INT(d->hud.clock, 1);
    ENSURE_EQ_INT(d->hud.counters, 0);
    ENSURE_EQ_INT(d->hud.chest_marker, 1);
    ENSURE_NEAR(d->fog_below_density, 0.05, KNOB_TOL);
    ENSURE_NEAR(d->fog_below_color[2], 0.3, KNOB_TOL);
    ENSURE_EQ_INT(d->water.fresnel, WW_FRESNEL_BIAS_SCALE);
    ENSURE_NEAR(d->water.fresnel_power, 3.0, KNOB_TOL);
    ENSURE_EQ_INT(d->water.foam, 1);
    ENSURE_NEAR(d->water.foam_amount, 0.8, KNOB_TOL);
    ENSURE_EQ_INT(d->water.caustics, 1);
    ENSURE_EQ_INT(d->water.alpha_blend, 1);
    ENSURE_NEAR(d->water.alpha, 0.4, KNOB_TOL);
    ENSURE_EQ_INT(d->nlights, 2);
    ENSURE_EQ_INT(d->light[0].kind, WW_LIGHT_SPOT);
    ENSURE_NEAR(d->light[0].direction[1], -1.0, KNOB_TOL); /* normalised */
    ENSURE_NEAR(d->light[0].angle, 20.0 * 3.14159265358979323846 / 180.0, KNOB_TOL);
    ENSURE_EQ_INT(d->light[1].kind, WW_LIGHT_POINT);
    ENSURE_NEAR(d->light[1].range, 5.0, KNOB_TOL);
    ww_scene_free(sc);
}

/* every switch on: every pass in run order; each switched off: its pass gone, nothing else */
TEST(render_keys_plan_follows_switches) {
    static const char text[] = "time: {dt: 1/120, fps: 30, duration: 1}\n"
                               "render: {shadows: true, refraction: true, reflection: true,"
                               " bloom: true, god_rays: true, fxaa: true, hud: [clock],"
                               " seabed: true, scale: 0.5}\n"
                               "objects: {cubes: [{position: [0, 0, 0]}]}\n";
    static const struct {
        const char *set;
        ww_pass_id gone;
    } off[] = {
        {"render.shadows=false", WW_PASS_SHADOW},   {"render.refraction=false", WW_PASS_PREPASS},
        {"render.reflection=false", WW_PASS_REFLECTION}, {"render.bloom=false", WW_PASS_BLOOM},
        {"render.god_rays=false", WW_PASS_SHAFTS},  {"render.fxaa=false", WW_PASS_FXAA},
        {"render.hud=[]", WW_PASS_HUD},     {"sky.model=gradient", WW_PASS_SKYMAP},
        {"render.scale=1", WW_PASS_UPSCALE},
    };
    ww_scene *sc = load(text, NULL, 0);
    if (!sc) return;
    ww_plan p;
    ww_plan_build(sc, 320, 180, &p);
    ENSURE_EQ_INT(p.npasses, WW_PASS_COUNT);
    for (int i = 0; i < p.npasses; i++) ENSURE_EQ_INT(p.passes[i].id, i);
    ww_scene_free(sc);

    for (size_t k = 0; k < sizeof off / sizeof off[0]; k++) {
        const char *sets[] = {off[k].set};
        sc = load(text, sets, 1);
        if (!sc) return;
        ww_plan_build(sc, 320, 180, &p);
        ENSURE_MSG(p.npasses == WW_PASS_COUNT - 1 && !has_pass(&p, off[k].gone), "%s: %d passes",
                   off[k].set, p.npasses);
        ww_scene_free(sc);
    }
}

/* a scene pays for what it has: no casters, no shadow map; no solid geometry, no prepass */
TEST(render_keys_plan_needs_what_it_draws) {
    static const char text[] = "time: {dt: 1/120, fps: 30, duration: 1}\n"
                               "render: {shadows: true, refraction: true}\n";
    const char *bare[] = {"render.seabed=false"};
    ww_scene *sc = load(text, bare, 1);
    if (!sc) return;
    ww_plan p;
    ww_plan_build(sc, 320, 180, &p);
    ENSURE(!has_pass(&p, WW_PASS_SHADOW));
    ENSURE(!has_pass(&p, WW_PASS_PREPASS));
    ENSURE_EQ_INT(p.geometry, 0);
    ww_scene_free(sc);

    const char *sets[] = {"render.seabed=true"};
    sc = load(text, sets, 1);
    if (!sc) return;
    ww_plan_build(sc, 320, 180, &p);
    ENSURE(!has_pass(&p, WW_PASS_SHADOW)); /* a seabed receives shadows but casts none */
    ENSURE(has_pass(&p, WW_PASS_PREPASS));
    ENSURE_EQ_INT(p.geometry, 1);
    ww_scene_free(sc);
}

/* knobs size the targets: reflection and bloom at their fractions, the shadow map square */
TEST(render_keys_plan_target_sizes) {
    const char *sets[] = {"render.reflection={scale: 0.25}", "render.bloom={scale: 0.5}",
                          "render.shadows={size: 512}", "objects.cubes=[{position: [0, 0, 0]}]",
                          "render.refraction={scale: 0.25}"};
    ww_scene *sc = load(BASE, sets, 5);
    if (!sc) return;
    ww_plan p;
    ww_plan_build(sc, 320, 180, &p);
    const ww_pass_desc *r = ww_plan_pass(&p, WW_PASS_REFLECTION);
    const ww_pass_desc *b = ww_plan_pass(&p, WW_PASS_BLOOM);
    const ww_pass_desc *s = ww_plan_pass(&p, WW_PASS_SHADOW);
    const ww_pass_desc *q = ww_plan_pass(&p, WW_PASS_PREPASS);
    ENSURE(r && b && s && q);
    if (r && b && s && q) {
        ENSURE_EQ_INT(q->targets[0].width, 80);
        ENSURE_EQ_INT(q->targets[1].height, 45);
        ENSURE_EQ_INT(r->targets[0].width, 80);
        ENSURE_EQ_INT(r->targets[0].height, 45);
        ENSURE_EQ_INT(b->targets[0].width, 160);
        ENSURE_EQ_INT(s->targets[0].width, 512);
        ENSURE_EQ_INT(s->targets[0].height, 512);
    }
    ww_scene_free(sc);
}

/* render.scale: every pass draws at that fraction of the frame (its own scales taken of that),
 * and the last target, which the frame is read from, is the frame's size */
TEST(render_keys_plan_frame_scale) {
    const char *sets[] = {"render.scale=0.75", "render.refraction={scale: 0.5}",
                          "objects.cubes=[{position: [0, 0, 0]}]"};
    ww_scene *sc = load(BASE, sets, 3);
    if (!sc) return;
    ww_plan p;
    ww_plan_build(sc, 320, 180, &p);
    const ww_pass_desc *m = ww_plan_pass(&p, WW_PASS_MAIN), *q = ww_plan_pass(&p, WW_PASS_PREPASS);
    const ww_pass_desc *t = ww_plan_pass(&p, WW_PASS_TONEMAP), *u = ww_plan_pass(&p, WW_PASS_UPSCALE);
    ENSURE(m && q && t && u);
    if (m && q && t && u) {
        ENSURE_EQ_INT(m->targets[0].width, 240);
        ENSURE_EQ_INT(m->targets[0].height, 135);
        ENSURE_EQ_INT(q->targets[0].width, 120);
        ENSURE_EQ_INT(t->targets[0].width, 240);
        ENSURE_EQ_INT(u->targets[0].width, 320);
        ENSURE_EQ_INT(u->targets[0].height, 180);
        ENSURE_EQ_INT(p.passes[p.npasses - 1].id, WW_PASS_UPSCALE);
    }
    ww_scene_free(sc);
    /* below a quarter the frame would be mostly guessed: refused, the key named */
    ww_set bad[1] = {{.text = "render.scale=0.1"}};
    ww_scene *none = NULL;
    ww_error err = {0};
    ENSURE(ww_scene_load_string("keys.yaml", BASE, strlen(BASE), bad, 1, &none, &err) != WW_OK);
    ENSURE_MSG(strstr(err.msg, "scale") != NULL, "%s", err.msg);
    ww_scene_free(none);
}

/* render.shadows: the word forms and the mapping's technique pick the technique; only the map
 * has a shadow pass, and only the stencilled ones give the prepass a stencil (the main pass has
 * one in every scene that shades its water from the G-buffer, this one among them) */
static ww_format depth_format(const ww_plan *p, ww_pass_id id) {
    const ww_pass_desc *d = ww_plan_pass(p, id);
    for (int i = 0; d && i < d->ntargets; i++)
        if (d->targets[i].format == WW_FMT_DEPTH24 || d->targets[i].format == WW_FMT_DEPTH24_STENCIL8)
            return d->targets[i].format;
    return WW_FMT_RGBA8; /* none */
}

TEST(render_keys_shadow_techniques) {
    static const char text[] = "time: {dt: 1/120, fps: 30, duration: 1}\n"
                               "render: {size: [320, 180], refraction: true}\n"
                               "objects: {cubes: [{position: [0, 0, 0]}]}\n";
    static const struct {
        const char *set;
        int on;
        ww_shadow_technique technique;
        int stencil;
    } cases[] = {
        {"render.shadows=true", 1, WW_SHADOW_MAP, 0},
        {"render.shadows=false", 0, WW_SHADOW_MAP, 0},
        {"render.shadows=map", 1, WW_SHADOW_MAP, 0},
        {"render.shadows=off", 0, WW_SHADOW_MAP, 0},
        {"render.shadows={size: 512}", 1, WW_SHADOW_MAP, 0},
        {"render.shadows=projected", 1, WW_SHADOW_PROJECTED, 1},
        {"render.shadows=volumes", 1, WW_SHADOW_VOLUMES, 1},
        {"render.shadows=volumes_visible", 1, WW_SHADOW_VOLUMES_VISIBLE, 1},
        {"render.shadows={technique: volumes}", 1, WW_SHADOW_VOLUMES, 1},
        {"render.shadows={technique: projected, on: false}", 0, WW_SHADOW_PROJECTED, 0},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        ww_scene *sc = load(text, &cases[i].set, 1);
        if (!sc) return;
        ENSURE_MSG(sc->render.shadows.on == cases[i].on, "%s: on %d", cases[i].set,
                   sc->render.shadows.on);
        ENSURE_MSG(sc->render.shadows.technique == cases[i].technique, "%s: technique %d",
                   cases[i].set, (int)sc->render.shadows.technique);
        ww_plan p;
        ww_plan_build(sc, 320, 180, &p);
        int map = cases[i].on && cases[i].technique == WW_SHADOW_MAP;
        ENSURE_MSG(has_pass(&p, WW_PASS_SHADOW) == map, "%s: shadow pass", cases[i].set);
        ww_format want = cases[i].stencil ? WW_FMT_DEPTH24_STENCIL8 : WW_FMT_DEPTH24;
        ENSURE_MSG(depth_format(&p, WW_PASS_MAIN) == WW_FMT_DEPTH24_STENCIL8, "%s: main depth",
                   cases[i].set);
        ENSURE_MSG(depth_format(&p, WW_PASS_PREPASS) == want, "%s: prepass depth", cases[i].set);
        ENSURE_MSG(depth_format(&p, WW_PASS_REFLECTION) == WW_FMT_DEPTH24, "%s: reflection",
                   cases[i].set);
        ww_scene_free(sc);
    }
}

/* the water's G-buffer: two RGBA32F targets of the main pass that its framebuffer does not hold,
 * and a stencil in its depth; not with MSAA, nor with the water blended (seed 004), where the
 * main depth is plain again unless the shadows are stencilled */
TEST(render_keys_plan_water_gbuffer) {
    static const char text[] = "time: {dt: 1/120, fps: 30, duration: 1}\n"
                               "render: {size: [320, 180]}\n";
    static const struct {
        const char *set;
        int gbuffer;
    } cases[] = {
        {"render.fxaa=true", 1},
        {"render.msaa=4", 0},
        {"water.look.alpha_blend={on: true}", 0},
        {"render.scale=0.5", 1},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        ww_scene *sc = load(text, &cases[i].set, 1);
        if (!sc) return;
        ww_plan p;
        ww_plan_build(sc, 320, 180, &p);
        const ww_pass_desc *d = ww_plan_pass(&p, WW_PASS_MAIN);
        int n32 = 0, attached32 = 0;
        for (int t = 0; d && t < d->ntargets; t++) {
            if (d->targets[t].format != WW_FMT_RGBA32F) continue;
            n32++;
            attached32 += !d->unattached[t];
            ENSURE_MSG(d->targets[t].width == d->targets[0].width &&
                           d->targets[t].height == d->targets[0].height,
                       "%s: G-buffer %dx%d, main %dx%d", cases[i].set, d->targets[t].width,
                       d->targets[t].height, d->targets[0].width, d->targets[0].height);
        }
        ENSURE_MSG(n32 == 2 * cases[i].gbuffer, "%s: %d rgba32f targets", cases[i].set, n32);
        ENSURE_MSG(attached32 == 0, "%s: %d G-buffer targets attached", cases[i].set, attached32);
        ENSURE_MSG(depth_format(&p, WW_PASS_MAIN) ==
                       (cases[i].gbuffer ? WW_FMT_DEPTH24_STENCIL8 : WW_FMT_DEPTH24),
                   "%s: main depth", cases[i].set);
        ww_scene_free(sc);
    }
}

/* the prepass smaller than the frame also draws its depth at the frame's size, in a target its
 * framebuffer does not hold (the water's outlines are upsampled by it); not at full size, nor
 * for blended water, which refracts nothing, nor with a seabed alone. The frame's size is the
 * one drawn: draft's, at 0.75 of it, 240x135 */
TEST(render_keys_plan_prepass_full_depth) {
    static const char text[] = "time: {dt: 1/120, fps: 30, duration: 1}\n"
                               "render: {size: [320, 180]}\n"
                               "objects: {cubes: [{position: [0, 0, 0]}]}\n";
    static const struct {
        const char *set;
        int full, w, h;
    } cases[] = {
        {"render.refraction={scale: 0.5}", 1, 320, 180},
        {"render.quality=draft", 1, 240, 135},
        {"render.refraction={scale: 1}", 0, 0, 0},
        {"water.look.alpha_blend={on: true}", 0, 0, 0},
        {"objects={cubes: []}", 0, 0, 0},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const char *sets[2] = {cases[i].set, "render.seabed=true"};
        ww_scene *sc = load(text, sets, 2);
        if (!sc) return;
        ww_plan p;
        ww_plan_build(sc, 320, 180, &p);
        const ww_pass_desc *d = ww_plan_pass(&p, WW_PASS_PREPASS);
        ENSURE_MSG(d != NULL, "%s: no prepass", cases[i].set);
        int found = 0;
        for (int t = 0; d && t < d->ntargets; t++) {
            if (strcmp(d->targets[t].name, "depth_full") != 0) continue;
            found = 1;
            ENSURE_MSG(d->unattached[t], "%s: depth_full attached", cases[i].set);
            ENSURE_MSG(d->targets[t].format == WW_FMT_DEPTH24, "%s: depth_full format %d",
                       cases[i].set, (int)d->targets[t].format);
            ENSURE_MSG(d->targets[t].width == cases[i].w && d->targets[t].height == cases[i].h,
                       "%s: depth_full %dx%d", cases[i].set, d->targets[t].width,
                       d->targets[t].height);
        }
        ENSURE_MSG(found == cases[i].full, "%s: depth_full %s", cases[i].set,
                   found ? "present" : "absent");
        ww_scene_free(sc);
    }
}

/* render.quality sets its knobs over the defaults; the scene's own keys override them, in any
 * order in the file; final is the defaults themselves */
TEST(render_keys_quality_presets) {
    ww_scene *fin = load(BASE, NULL, 0);
    const char *draft_sets[] = {"render.quality=draft"};
    ww_scene *draft = load(BASE, draft_sets, 1);
    const char *over_sets[] = {"render.reflection={scale: 1}", "render.quality=draft",
                               "render.fxaa=true"};
    ww_scene *over = load(BASE, over_sets, 3);
    const char *prev_sets[] = {"render.quality=preview"};
    ww_scene *prev = load(BASE, prev_sets, 1);
    if (!fin || !draft || !over || !prev) goto done;
    ENSURE_EQ_INT(fin->render.quality, WW_QUALITY_FINAL);
    ENSURE_EQ_INT(draft->render.quality, WW_QUALITY_DRAFT);
    ENSURE(draft->render.reflection.scale < fin->render.reflection.scale);
    ENSURE(draft->render.refraction_scale < fin->render.refraction_scale);
    ENSURE(draft->render.shadows.size < fin->render.shadows.size);
    ENSURE(draft->render.shafts.samples < fin->render.shafts.samples);
    ENSURE(draft->render.scale < fin->render.scale);
    ENSURE_EQ_INT(draft->render.fxaa, 0);
    ENSURE(prev->render.reflection.scale < fin->render.reflection.scale);
    ENSURE(prev->render.reflection.scale > draft->render.reflection.scale);
    ENSURE(prev->render.refraction_scale < fin->render.refraction_scale);
    ENSURE(prev->render.scale < fin->render.scale);
    ENSURE(prev->render.scale > draft->render.scale);
    /* the water mesh keeps its density: the frame's scale is the cheaper trade */
    ENSURE_NEAR(prev->render.grid, fin->render.grid, KNOB_TOL);
    ENSURE_NEAR(draft->render.grid, fin->render.grid, KNOB_TOL);
    /* the scene's keys win over the preset */
    ENSURE_NEAR(over->render.reflection.scale, 1.0, KNOB_TOL);
    ENSURE_EQ_INT(over->render.fxaa, 1);
    ENSURE_EQ_INT(over->render.shadows.size, draft->render.shadows.size);
done:
    ww_scene_free(fin);
    ww_scene_free(draft);
    ww_scene_free(over);
    ww_scene_free(prev);
}
