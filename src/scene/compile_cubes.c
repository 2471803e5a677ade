/* compile_cubes.c - placeholder until its section lands (issue 4, in progress). */
#include "scene/compile_impl.h"

static const char *const no_keys[] = {NULL};

ww_result wwc_cubes(ctx *c, const section *objects) {
    section s;
    TRY(wwc_open_section(c, objects, "cubes", no_keys, &s));
    return WW_OK;
}

ww_result wwc_action_press(ctx *c, const section *s, const ww_node *value, ww_event *ev) {
    (void)s;
    (void)ev;
    return wwc_fail(c, WW_E_INCONSISTENT, value, "press: not supported yet");
}
