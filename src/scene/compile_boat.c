/* compile_boat.c - placeholder until its section lands (issue 4, in progress). */
#include "scene/compile_impl.h"

static const char *const no_keys[] = {NULL};

ww_result wwc_boat(ctx *c, const section *objects) {
    section s;
    TRY(wwc_open_section(c, objects, "boat", no_keys, &s));
    return WW_OK;
}

ww_result wwc_action_boat(ctx *c, const section *s, const ww_node *value, ww_event *ev) {
    (void)s;
    (void)ev;
    return wwc_fail(c, WW_E_INCONSISTENT, value, "boat: not supported yet");
}

ww_result wwc_action_camera(ctx *c, const section *s, const ww_node *value, ww_event *ev) {
    (void)s;
    (void)ev;
    return wwc_fail(c, WW_E_INCONSISTENT, value, "camera: not supported yet");
}
