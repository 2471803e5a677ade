/* compile_audio.c - the scene's `audio:` section (scene/desc_audio.h): master volume, the music
 * bed, spatialisation and engine knobs, and a WAV file per sound. Files are resolved against the
 * folder of the file that names them and checked to be readable regular files here; their
 * headers are checked against io/wav.h's caps when a command loads the scene (render/audio.h's
 * ww_audio_check, from cli/args.c) and they are decoded when a track is made (render/audio.c),
 * with their place kept for messages.
 */
#include <string.h>

#include "scene/compile_impl.h"

static const rule R_VOLUME = CLOSED(0, 16, "");
static const rule R_UNIT = CLOSED(0, 1, "");
static const rule R_DISTANCE = OPEN_LO(0, 1e4, "m");
static const rule R_SPEED = CLOSED(0, 100, "m/s");

static const char *const BOOL_WORDS[] = {"false", "true", NULL};

static const char *const SOUND_NAMES[] = {
#define WW_SOUND_NAME(id, name, what) name,
    WW_AUDIO_SOUNDS(WW_SOUND_NAME)
#undef WW_SOUND_NAME
    NULL};

void ww_audio_defaults(ww_audio_desc *d) {
    *d = (ww_audio_desc){0};
    d->volume = 1.0;
    d->music_volume = 0.3;
    d->music_duck = 0.35;     /* seed 000 lowers the BGM under water; a third keeps it present */
    d->reference_distance = 5.0;
    d->min_gain = 0.05;
    d->engine_threshold = 0.3; /* seed 000's "small threshold" */
    d->engine_floor = 0.3;
}

/* a file name at n into f, resolved and checked to be readable */
static ww_result get_file(ctx *c, const ww_node *n, const char *name, ww_audio_file *f) {
    if (n->kind != WW_NODE_SCALAR || ww_node_is_null(n))
        return wwc_fail(c, WW_E_TYPE, n, "%s: expected a WAV file name", name);
    TRY(wwc_resolve_path(c, n, f->path, sizeof f->path));
    const char *file = n->mark.file ? n->mark.file : c->file;
    snprintf(f->file, sizeof f->file, "%s", file ? file : "");
    f->line = n->mark.line;
    f->column = n->mark.column;
    return WW_OK;
}

/* sounds.splash: one file or a list of up to WW_AUDIO_SPLASH_VARIANTS */
static ww_result get_splash(ctx *c, const section *s, ww_audio_desc *d) {
    const ww_node *n;
    char name[128];
    TRY(wwc_lookup(c, s, "splash", OPTIONAL, &n));
    if (!n) return WW_OK;
    wwc_path_of(s, "splash", name, sizeof name);
    if (n->kind != WW_NODE_SEQ) {
        d->nsplash = 1;
        return get_file(c, n, name, &d->splash[0]);
    }
    const ww_node *list;
    TRY(wwc_get_list(c, s, "splash", WW_AUDIO_SPLASH_VARIANTS, &list));
    if (list->n == 0) return wwc_fail(c, WW_E_RANGE, list, "%s: expected 1 to %d files", name,
                                      WW_AUDIO_SPLASH_VARIANTS);
    int i = 0;
    for (const ww_node *it = list->first; it; it = it->next, i++)
        TRY(get_file(c, it, name, &d->splash[i]));
    d->nsplash = i;
    return WW_OK;
}

static ww_result compile_sounds(ctx *c, const section *top, ww_audio_desc *d) {
    section s;
    TRY(wwc_open_section(c, top, "sounds", SOUND_NAMES, &s));
    if (!s.map) return WW_OK;
    TRY(get_splash(c, &s, d));
    for (int k = 0; k < WW_SOUND_COUNT; k++) {
        const ww_node *n;
        char name[128];
        if (k == WW_SOUND_SPLASH) continue;
        TRY(wwc_lookup(c, &s, SOUND_NAMES[k], OPTIONAL, &n));
        if (!n) continue;
        wwc_path_of(&s, SOUND_NAMES[k], name, sizeof name);
        TRY(get_file(c, n, name, &d->sounds[k]));
    }
    return WW_OK;
}

/* music: true | false | {on, volume, duck, file}; a mapping means on unless it says on: false */
static ww_result compile_music(ctx *c, const section *top, ww_audio_desc *d) {
    static const char *const keys[] = {"on", "volume", "duck", "file", NULL};
    const ww_node *n;
    TRY(wwc_lookup(c, top, "music", OPTIONAL, &n));
    if (!n) return WW_OK;
    if (n->kind != WW_NODE_MAP) return wwc_get_word(c, top, "music", BOOL_WORDS, &d->music_on);
    section s;
    TRY(wwc_open_section(c, top, "music", keys, &s));
    d->music_on = 1;
    TRY(wwc_get_word(c, &s, "on", BOOL_WORDS, &d->music_on));
    TRY(wwc_get_number(c, &s, "volume", &R_VOLUME, OPTIONAL, &d->music_volume));
    TRY(wwc_get_number(c, &s, "duck", &R_UNIT, OPTIONAL, &d->music_duck));
    const ww_node *f;
    TRY(wwc_lookup(c, &s, "file", OPTIONAL, &f));
    return f ? get_file(c, f, "audio.music.file", &d->music_file) : WW_OK;
}

ww_result wwc_audio(ctx *c, const section *top) {
    static const char *const keys[] = {"volume", "music", "sounds", "reference_distance",
                                       "min_gain", "engine", NULL};
    static const char *const engine_keys[] = {"threshold", "floor", NULL};
    ww_audio_desc *d = &c->sc->audio;
    ww_audio_defaults(d);
    section s, e;
    TRY(wwc_open_section(c, top, "audio", keys, &s));
    d->on = s.map != NULL;
    if (!s.map) return WW_OK;
    TRY(wwc_get_number(c, &s, "volume", &R_VOLUME, OPTIONAL, &d->volume));
    TRY(wwc_get_number(c, &s, "reference_distance", &R_DISTANCE, OPTIONAL,
                       &d->reference_distance));
    TRY(wwc_get_number(c, &s, "min_gain", &R_UNIT, OPTIONAL, &d->min_gain));
    TRY(wwc_open_section(c, &s, "engine", engine_keys, &e));
    TRY(wwc_get_number(c, &e, "threshold", &R_SPEED, OPTIONAL, &d->engine_threshold));
    TRY(wwc_get_number(c, &e, "floor", &R_UNIT, OPTIONAL, &d->engine_floor));
    TRY(compile_music(c, &s, d));
    return compile_sounds(c, &s, d);
}
