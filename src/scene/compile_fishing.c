/* compile_fishing.c - placeholder until its section lands (issue 4, in progress). */
#include "scene/compile_impl.h"

static const char *const no_keys[] = {NULL};

ww_result wwc_fishing(ctx *c, const section *objects) {
    section s;
    TRY(wwc_open_section(c, objects, "rod", no_keys, &s));
    TRY(wwc_open_section(c, objects, "fish", no_keys, &s));
    return WW_OK;
}

ww_result wwc_action_cast(ctx *c, const section *s, const ww_node *value, ww_event *ev) {
    (void)s;
    (void)ev;
    return wwc_fail(c, WW_E_INCONSISTENT, value, "cast: not supported yet");
}
