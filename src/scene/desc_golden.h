/* desc_golden.h - the scene's `golden:` section: the thresholds `render --golden` compares its
 * frames with, and the renderers whose goldens are accepted. Plain data filled by
 * scene/compile_golden.c; check/golden.c turns it into compare options (ww_golden_scene_opts),
 * and the command line's thresholds win over these.
 *
 *   golden:
 *     max: 8              # the names and units of `waterworld compare`'s options
 *     fail_percent: 0.1
 *     fallback: [llvmpipe-mesa-22.3]
 *
 * Zero means "not given": `has` holds a bit per key the section gives.
 */
#ifndef WW_DESC_GOLDEN_H
#define WW_DESC_GOLDEN_H

#define WW_GOLDEN_MAX_FALLBACK 8 /* renderer keys in golden.fallback */
#define WW_GOLDEN_KEY_SIZE 64    /* a renderer key, NUL included */

typedef enum ww_golden_has {
    WW_GOLDEN_HAS_THRESHOLD = 1 << 0,
    WW_GOLDEN_HAS_YIQ = 1 << 1,
    WW_GOLDEN_HAS_AA = 1 << 2,
    WW_GOLDEN_HAS_MAX = 1 << 3,
    WW_GOLDEN_HAS_FAIL_PERCENT = 1 << 4,
    WW_GOLDEN_HAS_FAIL_PIXELS = 1 << 5,
    WW_GOLDEN_HAS_PSNR_MIN = 1 << 6,
    WW_GOLDEN_HAS_YIQ_PIXELS = 1 << 7,
    WW_GOLDEN_HAS_SSIM_MIN = 1 << 8,
} ww_golden_has;

typedef struct ww_golden_desc {
    int on;                    /* the scene has a golden section */
    unsigned has;              /* WW_GOLDEN_HAS_* bits: the keys given */
    double threshold;          /* per-pixel threshold, 8-bit units (0..255) */
    double yiq;                /* pixelmatch YIQ threshold, 0..1 */
    int aa;                    /* 1: anti-aliased pixels are not counted (pixelmatch) */
    double max;                /* largest channel difference allowed, 8-bit units */
    double fail_percent;       /* largest share of pixels over threshold allowed, % */
    double fail_pixels;        /* most pixels over threshold allowed (whole) */
    double psnr_min;           /* smallest PSNR allowed, dB */
    double yiq_pixels;         /* most pixels over the YIQ threshold allowed (whole) */
    double ssim_min;           /* smallest mean SSIM allowed */
    int nfallback;             /* renderer keys whose goldens are accepted, in order */
    char fallback[WW_GOLDEN_MAX_FALLBACK][WW_GOLDEN_KEY_SIZE];
} ww_golden_desc;

#endif
