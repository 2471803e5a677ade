/* compile_reef.c - placeholder until its section lands (issue 4, in progress). */
#include "scene/compile_impl.h"

static const char *const no_keys[] = {NULL};

ww_result wwc_reef(ctx *c, const section *objects) {
    section s;
    TRY(wwc_open_section(c, objects, "chest", no_keys, &s));
    TRY(wwc_open_section(c, objects, "bubbles", no_keys, &s));
    TRY(wwc_open_section(c, objects, "models", no_keys, &s));
    return WW_OK;
}

ww_result wwc_action_chest(ctx *c, const section *s, const ww_node *value, ww_event *ev) {
    (void)s;
    (void)ev;
    return wwc_fail(c, WW_E_INCONSISTENT, value, "chest: not supported yet");
}
