/* desc_reef.h - objects.chest, objects.bubbles, objects.models: the treasure chest (seed 000),
 * air bubbles (seed 003) and static models' bounds the camera cannot enter. Read by
 * compile_reef.c; simulated by sim/chest.c, sim/bubbles.c, sim/collide.c. */
#ifndef WW_DESC_REEF_H
#define WW_DESC_REEF_H

typedef struct ww_chest_desc {
    int on;      /* the scene has a chest */
} ww_chest_desc;

typedef struct ww_bubbles_desc {
    int on;      /* the scene has bubble emitters */
} ww_bubbles_desc;

typedef struct ww_models_desc {
    int count;   /* static models (their bounds are solid to the camera) */
} ww_models_desc;

#endif
