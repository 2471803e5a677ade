/* compile_reef.c - objects.chest, objects.bubbles and objects.models (scene/desc_reef.h), and the
 * `chest` script action. Defaults follow seed 000 for the chest (first spawn and interval about
 * five minutes, a 15 s lifetime) and measured bubble rise speeds for the emitters (see
 * sim/bubbles.h).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/mathx.h"
#include "scene/assets.h"
#include "scene/compile_impl.h"

static const rule R_CHEST_FIRST = CLOSED(0, WW_TIME_MAX, "s");
static const rule R_CHEST_EVERY = OPEN_LO(0, 1e9, "s");
static const rule R_CHEST_TTL = OPEN_LO(0, 1e9, "s");
static const rule R_CHEST_RADIUS = CLOSED(0, 1e4, "m");
static const rule R_CHEST_REACH = OPEN_LO(0, 1e3, "m");
static const rule R_CHEST_SIZE = OPEN_LO(0, 100, "m");
static const rule R_CHEST_GLOW = CLOSED(0, 100, "");
static const rule R_EMISSIVE = CLOSED(0, 1e4, "");
static const rule R_PLACE = FINITE("m");
static const rule R_BUBBLE_RATE = OPEN_LO(0, 1000, "1/s");
static const rule R_BUBBLE_SPEED = OPEN_LO(0, 100, "m/s");
static const rule R_BUBBLE_WOBBLE = CLOSED(0, 10, "m");
static const rule R_BUBBLE_FREQUENCY = CLOSED(0, 100, "Hz");
static const rule R_BUBBLE_SIZE = OPEN_LO(0, 1, "m");
static const rule R_BUBBLE_COUNT = WHOLE(1, WW_MAX_BUBBLES_PER_EMITTER, "");

static const char *const NEAR_WORDS[] = {[WW_CHEST_NEAR_AUTO] = "auto",
                                         [WW_CHEST_NEAR_BOAT] = "boat",
                                         [WW_CHEST_NEAR_CAMERA] = "camera", NULL};

/* seed 000: the first chest about five minutes in, then every five minutes, 15 s to find it */
void ww_chest_defaults(ww_chest_desc *d) {
    *d = (ww_chest_desc){.first = 300.0,
                         .every = 300.0,
                         .ttl = 15.0,
                         .radius = 12.0,
                         .near = WW_CHEST_NEAR_AUTO,
                         .reach = 2.0,
                         .size = {0.9, 0.6, 0.6},
                         .glow = 1.0};
}

static ww_result compile_chest(ctx *c, const section *objects) {
    static const char *const keys[] = {"first", "every", "ttl",  "radius", "near",
                                       "reach", "size",  "glow", NULL};
    ww_chest_desc *d = &c->sc->chest;
    int on = d->on; /* a chest event read earlier keeps it on */
    ww_chest_defaults(d);
    d->on = on;
    section s;
    TRY(wwc_open_section(c, objects, "chest", keys, &s));
    if (!s.map) return WW_OK;
    d->on = 1;
    TRY(wwc_get_number(c, &s, "first", &R_CHEST_FIRST, OPTIONAL, &d->first));
    TRY(wwc_get_number(c, &s, "every", &R_CHEST_EVERY, OPTIONAL, &d->every));
    TRY(wwc_get_number(c, &s, "ttl", &R_CHEST_TTL, OPTIONAL, &d->ttl));
    TRY(wwc_get_number(c, &s, "radius", &R_CHEST_RADIUS, OPTIONAL, &d->radius));
    int near = (int)d->near;
    TRY(wwc_get_word(c, &s, "near", NEAR_WORDS, &near));
    d->near = (ww_chest_near)near;
    TRY(wwc_get_number(c, &s, "reach", &R_CHEST_REACH, OPTIONAL, &d->reach));
    TRY(wwc_get_vec(c, &s, "size", 3, &R_CHEST_SIZE, OPTIONAL, d->size));
    TRY(wwc_get_number(c, &s, "glow", &R_CHEST_GLOW, OPTIONAL, &d->glow));

    /* objects.boat is read before this section (compile_objects) */
    if (d->near == WW_CHEST_NEAR_BOAT && !c->sc->boat.on)
        return wwc_fail(c, WW_E_INCONSISTENT, ww_node_find(s.map, "near"),
                        "%s.near is boat, but the scene has no boat: expected near: camera, or "
                        "an objects.boat section",
                        s.what);

    /* a new chest replaces the old one, so a lifetime past the interval would be cut short */
    if (d->ttl > d->every) {
        const ww_node *n = ww_node_find(s.map, "ttl");
        return wwc_fail(c, WW_E_INCONSISTENT, n ? n : s.map,
                        "%s.ttl = %g s is longer than %s.every = %g s: expected ttl <= every (the "
                        "next chest would replace this one before it expires)",
                        s.what, d->ttl, s.what, d->every);
    }
    return WW_OK;
}

static ww_result compile_emitter(ctx *c, const ww_node *item, int i, ww_emitter_desc *e) {
    static const char *const keys[] = {"at", "rate", "speed", "wobble", "frequency", "size",
                                       "count", NULL};
    section s;
    TRY(wwc_open_item(c, item, "objects.bubbles", i, keys, &s));
    *e = (ww_emitter_desc){.rate = 2.0,
                           .speed = 0.25,
                           .wobble = 0.03,
                           .frequency = 2.0,
                           .size = 0.01,
                           .count = 16};
    double count = e->count;
    TRY(wwc_get_vec(c, &s, "at", 3, &R_PLACE, REQUIRED, e->at));
    TRY(wwc_get_number(c, &s, "rate", &R_BUBBLE_RATE, OPTIONAL, &e->rate));
    TRY(wwc_get_number(c, &s, "speed", &R_BUBBLE_SPEED, OPTIONAL, &e->speed));
    TRY(wwc_get_number(c, &s, "wobble", &R_BUBBLE_WOBBLE, OPTIONAL, &e->wobble));
    TRY(wwc_get_number(c, &s, "frequency", &R_BUBBLE_FREQUENCY, OPTIONAL, &e->frequency));
    TRY(wwc_get_number(c, &s, "size", &R_BUBBLE_SIZE, OPTIONAL, &e->size));
    TRY(wwc_get_number(c, &s, "count", &R_BUBBLE_COUNT, OPTIONAL, &count));
    e->count = (int)count;

    /* a vent above the rest level would release bubbles into the air */
    if (!(e->at[1] < c->sc->water_level))
        return wwc_fail(c, WW_E_INCONSISTENT, ww_node_find(s.map, "at"),
                        "%s.at[1] = %g is not below the water level %g: expected an emitter under "
                        "water",
                        s.what, e->at[1], c->sc->water_level);
    return WW_OK;
}

static ww_result compile_bubbles(ctx *c, const section *objects) {
    ww_bubbles_desc *d = &c->sc->bubbles;
    const ww_node *list;
    *d = (ww_bubbles_desc){0};
    TRY(wwc_get_list(c, objects, "bubbles", WW_MAX_EMITTERS, &list));
    int i = 0, total = 0;
    for (const ww_node *item = list ? list->first : NULL; item; item = item->next, i++) {
        TRY(compile_emitter(c, item, i, &d->emitter[i]));
        d->emitter[i].first = total;
        total += d->emitter[i].count;
    }
    d->count = i;
    d->total = total;
    d->on = i > 0;
    return WW_OK;
}

/* ---- objects.models: a scene graph of static models (seed 001's GameObject hierarchy) -------
 * Each model's local matrix is T(position) Ry(yaw) Rx(pitch) Rz(roll) S(scale); its frame is its
 * parent's frame times T R (no scale), and its world matrix its parent's frame times its local.
 * A child inherits its parent's position and rotation but not its scale: its position is in
 * metres in the parent's turned frame, and a parent scaled [4, 1, 1] neither moves its children
 * 4x further along x nor stretches (or, turned, shears) their shapes. Seed 001 passes the whole
 * parent transform down the tree while drawing; here the static chains are folded once at load.
 * A chain that ends at the boat stays relative to the boat's frame: the renderer composes it
 * with the boat's pose each frame. */

static const rule R_SCALE = OPEN_LO(0, 1e4, "");
static const rule R_SWAY_AMPLITUDE = OPEN_LO(0, 10, "m");
static const rule R_SWAY_FREQUENCY = OPEN_LO(0, 5, "Hz");
static const rule R_SWAY_WAVELENGTH = OPEN_LO(0, 1e4, "m");
static const char *const BOOL_WORDS[] = {"false", "true", NULL};

/* sway's defaults where the water has no waves to follow */
#define SWAY_AMPLITUDE 0.25   /* m at the top */
#define SWAY_FREQUENCY 0.2    /* Hz: a slow surge */
#define SWAY_WAVELENGTH 10.0  /* m */
static const rule R_ANGLE = FINITE("deg");
static const rule R_ALBEDO = CLOSED(0, 1, "");

static const char *const MESH_WORDS[] = {[WW_MESH_NONE] = "none",   [WW_MESH_BOX] = "box",
                                         [WW_MESH_SPHERE] = "sphere", [WW_MESH_STONE] = "stone",
                                         [WW_MESH_HULL] = "hull",   [WW_MESH_FISH] = "fish",
                                         [WW_MESH_LURE] = "lure",   [WW_MESH_CHEST] = "chest",
                                         [WW_MESH_GRID] = "grid",   NULL};

/* procedural meshes default to a light grey; an OBJ keeps its materials' colours */
static const double MODEL_GREY = 0.7;

/* column-major 4x4: out = a b (out may not alias) */
static void mat_mul(const double a[16], const double b[16], double out[16]) {
    for (int col = 0; col < 4; col++)
        for (int row = 0; row < 4; row++) {
            double v = 0.0;
            for (int k = 0; k < 4; k++) v += a[4 * k + row] * b[4 * col + k];
            out[4 * col + row] = v;
        }
}

/* T(p) Ry(yaw) Rx(pitch) Rz(roll) S(s) (S left out unless scaled), column-major. Yaw turns
 * like the boat's heading and the camera's yaw (positive: +x toward +z, -z toward +x, clockwise
 * seen from above), i.e. the right-handed rotation about +y by -yaw; pitch and roll are
 * right-handed about +x and +z (positive pitch lifts a -z nose, as the camera's). */
static void local_matrix(const ww_model_desc *m, int scaled, double out[16]) {
    double cy = cos(m->rotation[0]), sy = -sin(m->rotation[0]);
    double cp = cos(m->rotation[1]), sp = sin(m->rotation[1]);
    double cr = cos(m->rotation[2]), sr = sin(m->rotation[2]);
    /* R = Ry Rx Rz, rows */
    double r[3][3] = {{cy * cr + sy * sp * sr, -cy * sr + sy * sp * cr, sy * cp},
                      {cp * sr, cp * cr, -sp},
                      {-sy * cr + cy * sp * sr, sy * sr + cy * sp * cr, cy * cp}};
    for (int col = 0; col < 3; col++) {
        double k = scaled ? m->scale[col] : 1.0;
        for (int row = 0; row < 3; row++) out[4 * col + row] = r[row][col] * k;
        out[4 * col + 3] = 0.0;
    }
    for (int row = 0; row < 3; row++) out[12 + row] = m->position[row];
    out[15] = 1.0;
}

/* a number (the same on every axis) or a list of three */
static ww_result get_scale(ctx *c, const section *s, double out[3]) {
    const ww_node *n;
    TRY(wwc_lookup(c, s, "scale", OPTIONAL, &n));
    if (n && n->kind == WW_NODE_SCALAR) {
        char name[128];
        TRY(wwc_check_number(c, n, wwc_path_of(s, "scale", name, sizeof name), &R_SCALE, out));
        out[1] = out[2] = out[0];
        return WW_OK;
    }
    return wwc_get_vec(c, s, "scale", 3, &R_SCALE, OPTIONAL, out);
}

/* [yaw, pitch, roll] in degrees, or a single yaw */
static ww_result get_rotation(ctx *c, const section *s, double out[3]) {
    const ww_node *n;
    TRY(wwc_lookup(c, s, "rotation", OPTIONAL, &n));
    if (n && n->kind == WW_NODE_SCALAR) return wwc_get_angle(c, s, "rotation", &R_ANGLE, OPTIONAL, out);
    TRY(wwc_get_vec(c, s, "rotation", 3, &R_ANGLE, OPTIONAL, out));
    for (int a = 0; a < 3; a++) out[a] = ww_m_rad(out[a]);
    return WW_OK;
}

/* a word-valued key as a node (NULL when absent) */
static ww_result get_name(ctx *c, const section *s, const char *key, size_t max,
                          const ww_node **out) {
    TRY(wwc_lookup(c, s, key, OPTIONAL, out));
    const ww_node *n = *out;
    if (!n) return WW_OK;
    if (n->kind != WW_NODE_SCALAR || ww_node_is_null(n) || n->len == 0)
        return wwc_fail(c, WW_E_TYPE, n, "%s.%s: expected a word", s->what, key);
    if (n->len >= max)
        return wwc_fail(c, WW_E_RANGE, n, "%s.%s is %zu characters: expected at most %zu",
                        s->what, key, n->len, max - 1);
    return WW_OK;
}

static ww_assets *scene_assets(ctx *c) {
    if (!c->sc->assets) c->sc->assets = calloc(1, sizeof *c->sc->assets);
    return c->sc->assets;
}

/* the wave the plants follow: the component of largest amplitude (the first of equals); NULL
 * when the water is flat */
static const ww_wave *dominant_wave(const ww_scene *sc) {
    const ww_wave *best = NULL;
    for (int i = 0; i < sc->nwaves; i++)
        if (!best || sc->waves[i].amplitude > best->amplitude) best = &sc->waves[i];
    return best;
}

/* sway: {amplitude, frequency, direction, wavelength}: the plant bends in the vertex shader
 * (shaders/geometry.vert.glsl), moved by the dominant wave's orbital surge under it: that
 * wave's heading, frequency and wavelength unless given */
static ww_result compile_sway(ctx *c, const section *s, ww_model_desc *m) {
    static const char *const keys[] = {"amplitude", "frequency", "direction", "wavelength", NULL};
    section w;
    TRY(wwc_open_section(c, s, "sway", keys, &w));
    if (!w.map) return WW_OK;
    if (m->mesh != WW_MESH_OBJ)
        return wwc_fail(c, WW_E_INCONSISTENT, w.map,
                        "%s: sway bends an OBJ model's mesh: expected an obj: file", s->what);
    const ww_wave *dom = dominant_wave(c->sc);
    double heading = dom ? dom->direction : 0.0;
    m->sway_amplitude = SWAY_AMPLITUDE;
    m->sway_frequency = dom ? dom->omega / (2.0 * WW_PI) : SWAY_FREQUENCY;
    m->sway_wavelength = dom ? dom->wavelength : SWAY_WAVELENGTH;
    if (m->sway_frequency > R_SWAY_FREQUENCY.hi) m->sway_frequency = R_SWAY_FREQUENCY.hi;
    TRY(wwc_get_number(c, &w, "amplitude", &R_SWAY_AMPLITUDE, OPTIONAL, &m->sway_amplitude));
    TRY(wwc_get_number(c, &w, "frequency", &R_SWAY_FREQUENCY, OPTIONAL, &m->sway_frequency));
    TRY(wwc_get_heading(c, &w, "direction", OPTIONAL, &heading));
    TRY(wwc_get_number(c, &w, "wavelength", &R_SWAY_WAVELENGTH, OPTIONAL, &m->sway_wavelength));
    m->sway_dir[0] = cos(heading);
    m->sway_dir[1] = sin(heading);

    /* a top swinging farther than the plant is tall would tear it from its base */
    const ww_mesh_data *md = &c->sc->assets->mesh[m->asset];
    double tall = (md->max[1] - md->min[1]) * m->scale[1];
    if (m->sway_amplitude > tall) {
        const ww_node *n = ww_node_find(w.map, "amplitude");
        return wwc_fail(c, WW_E_INCONSISTENT, n ? n : w.map,
                        "%s.sway.amplitude = %g m is more than the model's height %g m: expected "
                        "at most its height",
                        s->what, m->sway_amplitude, tall);
    }
    return WW_OK;
}

/* *given: the model's bounds were written (else they are the transformed mesh's) */
static ww_result compile_model(ctx *c, const ww_node *item, int i, ww_model_desc *m,
                               const ww_node **parent, int *given) {
    static const char *const keys[] = {"name",  "mesh",  "obj",    "position", "rotation",
                                       "scale", "color", "parent", "min",      "max",
                                       "emissive", "float", "solid", "sway", NULL};
    static const char *const axes[] = {"x", "y", "z"};
    section s;
    const ww_node *name, *obj;
    TRY(wwc_open_item(c, item, "objects.models", i, keys, &s));
    *m = (ww_model_desc){.scale = {1.0, 1.0, 1.0}, .parent = -1, .asset = -1,
                         .line = s.map->mark.line, .column = s.map->mark.column};
    TRY(get_name(c, &s, "name", sizeof m->name, &name));
    if (name) {
        if (strcmp(name->text, "boat") == 0)
            return wwc_fail(c, WW_E_INCONSISTENT, name,
                            "%s.name: 'boat' names the boat as a parent: expected another name",
                            s.what);
        snprintf(m->name, sizeof m->name, "%s", name->text);
    }
    int mesh = WW_MESH_NONE;
    TRY(wwc_get_word(c, &s, "mesh", MESH_WORDS, &mesh));
    m->mesh = (ww_mesh_kind)mesh;
    TRY(wwc_lookup(c, &s, "obj", OPTIONAL, &obj));
    if (obj) {
        if (ww_node_find(s.map, "mesh"))
            return wwc_fail(c, WW_E_INCONSISTENT, obj, "%s: both mesh and obj: expected one",
                            s.what);
        if (obj->kind != WW_NODE_SCALAR || ww_node_is_null(obj))
            return wwc_fail(c, WW_E_TYPE, obj, "%s.obj: expected a file name", s.what);
        char path[WW_ASSET_PATH];
        TRY(wwc_resolve_path(c, obj, path, sizeof path));
        ww_assets *a = scene_assets(c);
        if (!a) return wwc_fail(c, WW_E_NOMEM, obj, "out of memory for the scene's assets");
        TRY(ww_assets_obj(a, path, obj->mark.file ? obj->mark.file : c->file, obj->mark.line,
                          obj->mark.column, &m->asset, c->err));
        m->mesh = WW_MESH_OBJ;
    }
    TRY(wwc_get_vec(c, &s, "position", 3, &R_PLACE, OPTIONAL, m->position));
    TRY(get_rotation(c, &s, m->rotation));
    TRY(get_scale(c, &s, m->scale));
    double grey = m->mesh == WW_MESH_OBJ ? 1.0 : MODEL_GREY;
    for (int a = 0; a < 3; a++) m->color[a] = grey;
    TRY(wwc_get_vec(c, &s, "color", 3, &R_ALBEDO, OPTIONAL, m->color));
    TRY(wwc_get_number(c, &s, "emissive", &R_EMISSIVE, OPTIONAL, &m->emissive));
    TRY(get_name(c, &s, "parent", sizeof m->name, parent));
    local_matrix(m, 1, m->local);
    TRY(compile_sway(c, &s, m));
    /* plants sway and the camera swims through them; everything else is solid */
    m->solid = m->sway_amplitude == 0.0;
    TRY(wwc_get_word(c, &s, "solid", BOOL_WORDS, &m->solid));

    /* bounds: given, or the transformed mesh's once the world matrix is known; a node without
     * a mesh that is not solid only places its children (a group) */
    *given = 0;
    int bounded = ww_node_find(s.map, "min") || ww_node_find(s.map, "max");
    if (!bounded && (m->mesh != WW_MESH_NONE || !m->solid)) return WW_OK;
    TRY(wwc_get_vec(c, &s, "min", 3, &R_PLACE, REQUIRED, m->min));
    TRY(wwc_get_vec(c, &s, "max", 3, &R_PLACE, REQUIRED, m->max));
    for (int a = 0; a < 3; a++)
        if (!(m->min[a] < m->max[a]))
            return wwc_fail(c, WW_E_INCONSISTENT, ww_node_find(s.map, "max"),
                            "%s: max.%s = %g is not above min.%s = %g: expected min < max on "
                            "every axis",
                            s.what, axes[a], m->max[a], axes[a], m->min[a]);
    *given = 1;
    return WW_OK;
}

/* the axis-aligned bounds of the mesh's box under the model's world matrix */
static void transformed_bounds(const ww_scene *sc, ww_model_desc *m) {
    double lo[3] = {-0.5, -0.5, -0.5}, hi[3] = {0.5, 0.5, 0.5};
    if (m->mesh == WW_MESH_OBJ)
        for (int a = 0; a < 3; a++) {
            lo[a] = sc->assets->mesh[m->asset].min[a];
            hi[a] = sc->assets->mesh[m->asset].max[a];
        }
    for (int a = 0; a < 3; a++) {
        m->min[a] = HUGE_VAL;
        m->max[a] = -HUGE_VAL;
    }
    for (int k = 0; k < 8; k++) {
        double p[3] = {k & 1 ? hi[0] : lo[0], k & 2 ? hi[1] : lo[1], k & 4 ? hi[2] : lo[2]};
        for (int a = 0; a < 3; a++) {
            const double *w = m->world;
            double v = w[a] * p[0] + w[4 + a] * p[1] + w[8 + a] * p[2] + w[12 + a];
            if (v < m->min[a]) m->min[a] = v;
            if (v > m->max[a]) m->max[a] = v;
        }
    }
}

/* the solid of a turned model: the mesh's own box turned with it (its axis-aligned bounds
 * would hold empty corners the camera could not enter). A world matrix without a turn keeps
 * the axis-aligned box (oriented stays 0), bit for bit the bounds it always had. */
static void oriented_bounds(const ww_scene *sc, ww_model_desc *m) {
    const double *w = m->world;
    if (w[1] == 0.0 && w[2] == 0.0 && w[4] == 0.0 && w[6] == 0.0 && w[8] == 0.0 && w[9] == 0.0)
        return;
    double lo[3] = {-0.5, -0.5, -0.5}, hi[3] = {0.5, 0.5, 0.5}, r[3][3], len[3];
    if (m->mesh == WW_MESH_OBJ)
        for (int a = 0; a < 3; a++) {
            lo[a] = sc->assets->mesh[m->asset].min[a];
            hi[a] = sc->assets->mesh[m->asset].max[a];
        }
    /* the world matrix is R S: its columns' lengths are the scale, their directions R's */
    for (int col = 0; col < 3; col++) {
        len[col] = sqrt(w[4 * col] * w[4 * col] + w[4 * col + 1] * w[4 * col + 1] +
                        w[4 * col + 2] * w[4 * col + 2]);
        for (int row = 0; row < 3; row++) r[row][col] = w[4 * col + row] / len[col];
    }
    for (int a = 0; a < 3; a++) {
        double mid = 0.5 * (lo[0] + hi[0]) * w[a] + 0.5 * (lo[1] + hi[1]) * w[4 + a] +
                     0.5 * (lo[2] + hi[2]) * w[8 + a];
        m->obb_c[a] = mid + w[12 + a];
        m->obb_h[a] = 0.5 * (hi[a] - lo[a]) * len[a];
    }
    /* rotation matrix -> quaternion (Shepperd's method: the largest of the four first) */
    double tr = r[0][0] + r[1][1] + r[2][2], q[4];
    if (tr > 0.0) {
        double s = 2.0 * sqrt(1.0 + tr);
        q[0] = 0.25 * s;
        q[1] = (r[2][1] - r[1][2]) / s;
        q[2] = (r[0][2] - r[2][0]) / s;
        q[3] = (r[1][0] - r[0][1]) / s;
    } else if (r[0][0] > r[1][1] && r[0][0] > r[2][2]) {
        double s = 2.0 * sqrt(1.0 + r[0][0] - r[1][1] - r[2][2]);
        q[0] = (r[2][1] - r[1][2]) / s;
        q[1] = 0.25 * s;
        q[2] = (r[0][1] + r[1][0]) / s;
        q[3] = (r[0][2] + r[2][0]) / s;
    } else if (r[1][1] > r[2][2]) {
        double s = 2.0 * sqrt(1.0 + r[1][1] - r[0][0] - r[2][2]);
        q[0] = (r[0][2] - r[2][0]) / s;
        q[1] = (r[0][1] + r[1][0]) / s;
        q[2] = 0.25 * s;
        q[3] = (r[1][2] + r[2][1]) / s;
    } else {
        double s = 2.0 * sqrt(1.0 + r[2][2] - r[0][0] - r[1][1]);
        q[0] = (r[1][0] - r[0][1]) / s;
        q[1] = (r[0][2] + r[2][0]) / s;
        q[2] = (r[1][2] + r[2][1]) / s;
        q[3] = 0.25 * s;
    }
    double n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (int k = 0; k < 4; k++) m->obb_q[k] = q[k] / n;
    m->oriented = 1;
}

/* parents by name (written before or after their children), cycles refused, world matrices
 * folded root first */
static ww_result resolve_graph(ctx *c, const ww_node *list, const ww_node *const *parent,
                               const int *given) {
    ww_models_desc *d = &c->sc->models;
    int n = d->count;
    for (int i = 0; i < n; i++) {
        ww_model_desc *m = &d->model[i];
        for (int j = 0; j < i && m->name[0]; j++)
            if (strcmp(d->model[j].name, m->name) == 0)
                return wwc_fail(c, WW_E_INCONSISTENT, ww_node_find(ww_node_at(list, i), "name"),
                                "objects.models[%d].name '%s' is also objects.models[%d]'s: "
                                "expected unique names",
                                i, m->name, j);
    }
    for (int i = 0; i < n; i++) {
        const ww_node *p = parent[i];
        if (!p) continue;
        ww_model_desc *m = &d->model[i];
        if (strcmp(p->text, "boat") == 0) {
            if (!c->sc->boat.on)
                return wwc_fail(c, WW_E_INCONSISTENT, p,
                                "objects.models[%d].parent is 'boat' but the scene has no "
                                "objects.boat",
                                i);
            m->parent = WW_PARENT_BOAT;
            continue;
        }
        int found = -1;
        for (int j = 0; j < n && found < 0; j++)
            if (strcmp(d->model[j].name, p->text) == 0) found = j;
        if (found < 0)
            return wwc_fail(c, WW_E_INCONSISTENT, p,
                            "objects.models[%d].parent '%s' names no model (objects.models[].name) "
                            "and is not 'boat'",
                            i, p->text);
        m->parent = found;
    }
    /* a chain longer than the model count loops */
    for (int i = 0; i < n; i++) {
        int k = i, steps = 0;
        while (k >= 0 && steps <= n) {
            k = d->model[k].parent;
            steps++;
            if (k == i) break;
        }
        if (k == i)
            return wwc_fail(c, WW_E_INCONSISTENT, parent[i],
                            "objects.models[%d].parent: '%s' is its own ancestor: expected a tree",
                            i, d->model[i].name);
    }
    /* fold root first: a model's depth is its chain's length, so pass by depth */
    int done[WW_MAX_MODELS] = {0}, left = n;
    while (left > 0)
        for (int i = 0; i < n; i++) {
            ww_model_desc *m = &d->model[i];
            int p = m->parent;
            if (done[i] || (p >= 0 && !done[p])) continue;
            double rigid[16];
            local_matrix(m, 0, rigid);
            if (p >= 0) {
                mat_mul(d->model[p].frame, m->local, m->world);
                mat_mul(d->model[p].frame, rigid, m->frame);
            } else {
                memcpy(m->world, m->local, sizeof m->world);
                memcpy(m->frame, rigid, sizeof m->frame);
            }
            if (!given[i] && (m->mesh != WW_MESH_NONE || m->solid)) {
                transformed_bounds(c->sc, m);
                oriented_bounds(c->sc, m);
            }
            done[i] = 1;
            left--;
        }
    return WW_OK;
}

static ww_result compile_models(ctx *c, const section *objects) {
    ww_models_desc *d = &c->sc->models;
    const ww_node *list, *parent[WW_MAX_MODELS] = {0};
    int given[WW_MAX_MODELS] = {0};
    *d = (ww_models_desc){0};
    TRY(wwc_get_list(c, objects, "models", WW_MAX_MODELS, &list));
    int i = 0;
    for (const ww_node *item = list ? list->first : NULL; item; item = item->next, i++)
        TRY(compile_model(c, item, i, &d->model[i], &parent[i], &given[i]));
    d->count = i;
    return resolve_graph(c, list, parent, given);
}

ww_result wwc_reef(ctx *c, const section *objects) {
    TRY(compile_chest(c, objects));
    TRY(compile_bubbles(c, objects));
    return compile_models(c, objects);
}

/* chest: {at: [x, z]} forces a spawn there; chest: {} (or nothing) forces one by the random
 * rule. ev->flags bit 0: at given; ev->v[0], v[1]: x, z (sim/chest.h) */
ww_result wwc_action_chest(ctx *c, const section *s, const ww_node *value, ww_event *ev) {
    static const char *const keys[] = {"at", NULL};
    c->sc->chest.on = 1;
    if (ww_node_is_null(value)) return WW_OK;
    section a;
    TRY(wwc_open_section(c, s, "chest", keys, &a));
    if (ww_node_find(a.map, "at")) {
        TRY(wwc_get_vec(c, &a, "at", 2, &R_PLACE, REQUIRED, ev->v));
        ev->flags |= 1;
    }
    return WW_OK;
}
