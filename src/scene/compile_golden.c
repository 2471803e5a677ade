/* compile_golden.c - the scene's `golden:` section (scene/desc_golden.h). */
#include "scene/compile_impl.h"

ww_result wwc_golden(ctx *c, const section *top) {
    static const char *const keys[] = {NULL};
    section s;
    TRY(wwc_open_section(c, top, "golden", keys, &s));
    c->sc->golden.on = s.map != NULL;
    return WW_OK;
}
