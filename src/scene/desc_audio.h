/* desc_audio.h - the scene's `audio:` section: the sound track `render --audio` synthesises from
 * the simulation's events (seed 000's sounds, rendered offline). Plain data filled by
 * scene/compile_audio.c; tools/audio.c mixes it.
 */
#ifndef WW_DESC_AUDIO_H
#define WW_DESC_AUDIO_H

typedef struct ww_audio_desc {
    int on;                    /* the scene has an audio section */
} ww_audio_desc;

#endif
