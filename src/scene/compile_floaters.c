/* compile_floaters.c - objects.models[].float (scene/desc_floaters.h): which models float and
 * their body. Read after objects.models is compiled (compile_reef.c), so the model's mesh, scale
 * and folded frame are known. Knobs and defaults follow a cube's (desc_cubes.h); the model is in
 * sim/floaters.c.
 *
 *   - {name: crate, mesh: box, scale: [0.8, 0.5, 0.6], position: [0, 0, -5], rotation: 20,
 *      float: {density: 500, columns: 4, drag: {linear: 0.8, quadratic: 1.05, angular: 1.5},
 *              nudge: 1}}
 */
#include <math.h>
#include <string.h>

#include "scene/assets.h"
#include "scene/compile_impl.h"

static const rule R_FLOAT_DENSITY = CLOSED(1, 1e5, "kg/m^3");
static const rule R_FLOAT_COLUMNS = WHOLE(1, WW_CUBE_MAX_COLUMNS, "");
static const rule R_FLOAT_DRAG_RATE = CLOSED(0, 1e3, "1/s");
static const rule R_FLOAT_DRAG_CD = CLOSED(0, 100, "");
static const rule R_FLOAT_NUDGE = CLOSED(0, 100, "");
/* each edge of the floating box, as a cube's size */
#define FLOAT_EDGE_MIN 0.01
#define FLOAT_EDGE_MAX 100.0

/* rotation matrix (column-major 4x4's upper 3x3, rigid) to a unit quaternion w x y z
 * (Shepperd 1978: the largest of the four squares first, for accuracy) */
static void quat_of_frame(const double m[16], double q[4]) {
    double r00 = m[0], r11 = m[5], r22 = m[10];
    double r10 = m[1], r01 = m[4], r20 = m[2], r02 = m[8], r21 = m[6], r12 = m[9];
    double tr = r00 + r11 + r22;
    if (tr >= r00 && tr >= r11 && tr >= r22) {
        double s = 2.0 * sqrt(1.0 + tr);
        q[0] = 0.25 * s, q[1] = (r21 - r12) / s, q[2] = (r02 - r20) / s, q[3] = (r10 - r01) / s;
    } else if (r00 >= r11 && r00 >= r22) {
        double s = 2.0 * sqrt(1.0 + r00 - r11 - r22);
        q[0] = (r21 - r12) / s, q[1] = 0.25 * s, q[2] = (r01 + r10) / s, q[3] = (r02 + r20) / s;
    } else if (r11 >= r22) {
        double s = 2.0 * sqrt(1.0 + r11 - r00 - r22);
        q[0] = (r02 - r20) / s, q[1] = (r01 + r10) / s, q[2] = 0.25 * s, q[3] = (r12 + r21) / s;
    } else {
        double s = 2.0 * sqrt(1.0 + r22 - r00 - r11);
        q[0] = (r10 - r01) / s, q[1] = (r02 + r20) / s, q[2] = (r12 + r21) / s, q[3] = 0.25 * s;
    }
    double n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (int k = 0; k < 4; k++) q[k] /= n;
}

/* the body: the mesh's bounds times the scale, its centre placed by the model's frame */
static ww_result body_of(ctx *c, const ww_node *at, const char *what, const ww_model_desc *m,
                         ww_floater_desc *f) {
    static const char *const axes[] = {"x", "y", "z"};
    double lo[3] = {-0.5, -0.5, -0.5}, hi[3] = {0.5, 0.5, 0.5};
    if (m->mesh == WW_MESH_OBJ)
        for (int a = 0; a < 3; a++) {
            lo[a] = c->sc->assets->mesh[m->asset].min[a];
            hi[a] = c->sc->assets->mesh[m->asset].max[a];
        }
    for (int a = 0; a < 3; a++) {
        f->extent[a] = (hi[a] - lo[a]) * m->scale[a];
        f->offset[a] = 0.5 * (hi[a] + lo[a]) * m->scale[a];
        if (!(f->extent[a] >= FLOAT_EDGE_MIN && f->extent[a] <= FLOAT_EDGE_MAX))
            return wwc_fail(c, WW_E_RANGE, at,
                            "%s: the floating box's %s edge (mesh bounds x scale) is %g m: "
                            "expected %g..%g m",
                            what, axes[a], f->extent[a], FLOAT_EDGE_MIN, FLOAT_EDGE_MAX);
    }
    const double *F = m->frame; /* a root: T R */
    for (int r = 0; r < 3; r++)
        f->position[r] = F[12 + r] + F[r] * f->offset[0] + F[4 + r] * f->offset[1] +
                         F[8 + r] * f->offset[2];
    quat_of_frame(F, f->rotation);
    return WW_OK;
}

static ww_result compile_float(ctx *c, const ww_node *item, int i, ww_floater_desc *f) {
    static const char *const keys[] = {"density", "columns", "drag", "nudge", NULL};
    static const char *const drag_keys[] = {"linear", "quadratic", "angular", NULL};
    const ww_model_desc *m = &c->sc->models.model[i];
    section model = {.map = item}, s, drag;
    snprintf(model.what, sizeof model.what, "objects.models[%d]", i);
    TRY(wwc_open_section(c, &model, "float", keys, &s));
    const ww_node *at = ww_node_find(item, "float");
    if (m->parent != -1)
        return wwc_fail(c, WW_E_INCONSISTENT, at,
                        "%s floats but has a parent: expected a floating model to be a root of "
                        "objects.models (its children ride on it)",
                        model.what);
    if (m->mesh == WW_MESH_NONE)
        return wwc_fail(c, WW_E_INCONSISTENT, at,
                        "%s floats but has no mesh: expected mesh or obj (the floating box is the "
                        "mesh's bounds x scale)",
                        model.what);
    *f = (ww_floater_desc){.model = i, .columns = WW_CUBE_DEFAULT_COLUMNS};
    ww_cube_desc like = ww_cube_default(); /* a cube's knobs and defaults */
    f->drag_linear = like.drag_linear;
    f->drag_quadratic = like.drag_quadratic;
    f->drag_angular = like.drag_angular;
    f->nudge = like.nudge;
    double columns = f->columns;
    TRY(wwc_get_number(c, &s, "density", &R_FLOAT_DENSITY, REQUIRED, &f->density));
    TRY(wwc_get_number(c, &s, "columns", &R_FLOAT_COLUMNS, OPTIONAL, &columns));
    f->columns = (int)columns;
    TRY(wwc_get_number(c, &s, "nudge", &R_FLOAT_NUDGE, OPTIONAL, &f->nudge));
    TRY(wwc_open_section(c, &s, "drag", drag_keys, &drag));
    TRY(wwc_get_number(c, &drag, "linear", &R_FLOAT_DRAG_RATE, OPTIONAL, &f->drag_linear));
    TRY(wwc_get_number(c, &drag, "quadratic", &R_FLOAT_DRAG_CD, OPTIONAL, &f->drag_quadratic));
    TRY(wwc_get_number(c, &drag, "angular", &R_FLOAT_DRAG_RATE, OPTIONAL, &f->drag_angular));
    return body_of(c, at, s.what, m, f);
}

ww_result wwc_floaters(ctx *c, const section *objects) {
    ww_floaters_desc *d = &c->sc->floaters;
    const ww_node *list;
    *d = (ww_floaters_desc){0};
    TRY(wwc_get_list(c, objects, "models", WW_MAX_MODELS, &list));
    int i = 0;
    for (const ww_node *item = list ? list->first : NULL; item; item = item->next, i++) {
        const ww_node *fl = ww_node_find(item, "float");
        if (!fl) continue;
        if (d->count == WW_MAX_FLOATERS)
            return wwc_fail(c, WW_E_RANGE, fl,
                            "objects.models[%d].float: more than %d floating models", i,
                            WW_MAX_FLOATERS);
        TRY(compile_float(c, item, i, &d->floater[d->count]));
        d->plus_one[i] = ++d->count;
    }
    d->on = d->count > 0;
    return WW_OK;
}
