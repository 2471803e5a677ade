/* audio.c - placeholder: the sound track is being written (issue 6). */
#include "tools/audio.h"

ww_result ww_audio_new(const ww_scene *sc, int64_t first_step, int64_t last_step, ww_audio **out,
                       ww_error *err) {
    (void)sc, (void)first_step, (void)last_step;
    *out = NULL;
    return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--audio is not built yet");
}
void ww_audio_step(ww_audio *a, const ww_scene *sc, const ww_state *st) { (void)a, (void)sc, (void)st; }
ww_result ww_audio_write(ww_audio *a, const char *path, ww_error *err) {
    (void)a, (void)path, (void)err;
    return WW_OK;
}
void ww_audio_free(ww_audio *a) { (void)a; }
