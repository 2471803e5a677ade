/* desc_audio.h - the scene's `audio:` section: the sound track `render --audio` synthesises from
 * the simulation's events (seed 000's sounds, rendered offline). Plain data filled by
 * scene/compile_audio.c; render/audio.c mixes it. Every sound is procedural unless the section
 * names a WAV file for it (read by render/audio.c when a track is made; the file's place in the
 * scene is kept here so that its errors name file:line:column).
 */
#ifndef WW_DESC_AUDIO_H
#define WW_DESC_AUDIO_H

#define WW_AUDIO_PATH 256
#define WW_AUDIO_SPLASH_VARIANTS 3 /* seed 000's drop1/2/3, cycled through */

/* the sounds a scene may name a file for; SPLASH holds WW_AUDIO_SPLASH_VARIANTS slots */
#define WW_AUDIO_SOUNDS(X)                                                                        \
    X(SPLASH, "splash", "a full stone splash (list of up to 3 variations, cycled)")              \
    X(TINY_SPLASH, "tiny_splash", "a stone's tiny splash, the lure landing")                     \
    X(THUD, "thud", "a stone hitting a cube or the boat")                                        \
    X(REEL, "reel", "loop: the rod charging before a cast")                                      \
    X(CATCH, "catch", "stinger: a fish caught")                                                  \
    X(SPARKLE, "sparkle", "the chest collected")                                                 \
    X(SPARKLE_SPAWN, "sparkle_spawn", "the chest appearing")                                     \
    X(ENGINE, "engine", "loop: the boat's engine, its rate and level follow the speed")          \
    X(UNDERWATER, "underwater", "loop: the camera under water")

typedef enum ww_sound {
#define WW_SOUND_ENUM(id, name, what) WW_SOUND_##id,
    WW_AUDIO_SOUNDS(WW_SOUND_ENUM)
#undef WW_SOUND_ENUM
    WW_SOUND_COUNT
} ww_sound;

/* a WAV file named in the scene, and where */
typedef struct ww_audio_file {
    char path[WW_AUDIO_PATH];  /* resolved against the scene's folder; "" = procedural */
    char file[WW_AUDIO_PATH];  /* the scene (or --set) file that named it, for messages */
    int line, column;
} ww_audio_file;

typedef struct ww_audio_desc {
    int on;                    /* the scene has an audio section */
    double volume;             /* master gain, linear (1) */
    /* music bed: procedural chord pad, or a WAV looped from t = 0 */
    int music_on;              /* 0 by default: a scene asks for music */
    double music_volume;       /* linear (0.3) */
    double music_duck;         /* music gain while the camera is under water (0.35) */
    ww_audio_file music_file;
    /* spatialisation (OpenAL's inverse distance clamped model) */
    double reference_distance; /* m: full level at or inside this distance (5) */
    double min_gain;           /* the gain never falls below this far away (0.05) */
    /* the boat engine loop */
    double engine_threshold;   /* m/s: plays while |speed| exceeds this (0.3) */
    double engine_floor;       /* level at the threshold; 1 at the boat's max speed (0.3) */
    /* a file per sound (SPLASH's slot unused: its variations are splash[0, nsplash)) */
    ww_audio_file sounds[WW_SOUND_COUNT];
    ww_audio_file splash[WW_AUDIO_SPLASH_VARIANTS];
    int nsplash;               /* splash files named (0: procedural) */
} ww_audio_desc;

/* every default of the section (scene/compile_audio.c; the loader calls it for every scene) */
void ww_audio_defaults(ww_audio_desc *d);

#endif
