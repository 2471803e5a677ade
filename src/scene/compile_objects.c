/* compile_objects.c - cross-checks between the scripted world's sections, once the whole scene is
 * read (an event that names a cube the scene does not have, ...). */
#include "scene/compile_impl.h"

const char *wwc_event_file(const ctx *c, const ww_event *ev) {
    return ev->in_script && c->sc->script_path[0] ? c->sc->script_path : c->file;
}

/* press.cube names a cube of objects.cubes */
static ww_result check_press(ctx *c) {
    const ww_scene *sc = c->sc;
    int n = sc->cubes.on ? sc->cubes.count : 0;
    for (int i = 0; i < sc->nevents; i++) {
        const ww_event *ev = &sc->events[i];
        if (ev->kind != WW_EV_PRESS || ev->index < n) continue;
        return ww_error_set(c->err, WW_E_INCONSISTENT, wwc_event_file(c, ev), ev->line, ev->column,
                            "press.cube = %d but the scene has %d cube%s (objects.cubes): "
                            "expected an index below %d",
                            ev->index, n, n == 1 ? "" : "s", n);
    }
    return WW_OK;
}

ww_result wwc_check_world(ctx *c) {
    TRY(check_press(c));
    return WW_OK;
}
