/* desc_golden.h - the scene's `golden:` section: the thresholds `render --golden` compares its
 * frames with, and the renderers whose goldens are accepted. Plain data filled by
 * scene/compile_golden.c; the command line's thresholds win over these.
 */
#ifndef WW_DESC_GOLDEN_H
#define WW_DESC_GOLDEN_H

typedef struct ww_golden_desc {
    int on;                    /* the scene has a golden section */
} ww_golden_desc;

#endif
