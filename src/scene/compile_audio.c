/* compile_audio.c - the scene's `audio:` section (scene/desc_audio.h). */
#include "scene/compile_impl.h"

ww_result wwc_audio(ctx *c, const section *top) {
    static const char *const keys[] = {NULL};
    section s;
    TRY(wwc_open_section(c, top, "audio", keys, &s));
    c->sc->audio.on = s.map != NULL;
    return WW_OK;
}
