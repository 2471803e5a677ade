/* compile_golden.c - the scene's `golden:` section (scene/desc_golden.h): the thresholds of
 * `render --golden`, under the names and units of `waterworld compare`'s options, and the list of
 * renderer keys whose goldens are accepted when there are none for the renderer at hand.
 */
#include <stdio.h>
#include <string.h>

#include "scene/compile_impl.h"

static const rule R_LEVELS = CLOSED(0, 255, "8-bit levels");
static const rule R_YIQ = CLOSED(0, 1, "");
static const rule R_PERCENT = CLOSED(0, 100, "%");
static const rule R_PIXELS = WHOLE(0, 1e12, "px");
static const rule R_PSNR = CLOSED(0, 1000, "dB");
static const rule R_SSIM = CLOSED(-1, 1, "");

static const char *const BOOL_WORDS[] = {"false", "true", NULL};

/* a threshold key: read with its rule, its bit set in has when given */
static ww_result get_threshold(ctx *c, const section *s, const char *key, const rule *r,
                               unsigned bit, double *out) {
    const ww_node *n;
    TRY(wwc_lookup(c, s, key, OPTIONAL, &n));
    if (!n) return WW_OK;
    TRY(wwc_get_number(c, s, key, r, OPTIONAL, out));
    c->sc->golden.has |= bit;
    return WW_OK;
}

/* a renderer key as check/golden.c makes them: lowercase letters, digits, '.', '_' and '-',
 * starting with a letter or digit (it names a folder: no '/', no "..") */
static int valid_key(const char *k) {
    if (!((k[0] >= 'a' && k[0] <= 'z') || (k[0] >= '0' && k[0] <= '9'))) return 0;
    for (const char *p = k; *p; p++) {
        int ok = (*p >= 'a' && *p <= 'z') || (*p >= '0' && *p <= '9') || *p == '.' || *p == '-' ||
                 *p == '_';
        if (!ok) return 0;
    }
    return strstr(k, "..") == NULL;
}

static ww_result compile_fallback(ctx *c, const section *s) {
    ww_golden_desc *g = &c->sc->golden;
    const ww_node *list;
    TRY(wwc_get_list(c, s, "fallback", WW_GOLDEN_MAX_FALLBACK, &list));
    int i = 0;
    for (const ww_node *item = list ? list->first : NULL; item; item = item->next, i++) {
        if (item->kind != WW_NODE_SCALAR || ww_node_is_null(item) ||
            item->len >= WW_GOLDEN_KEY_SIZE || !valid_key(item->text))
            return wwc_fail(c, WW_E_TYPE, item,
                            "golden.fallback[%d]: expected a renderer key such as "
                            "llvmpipe-mesa-22.3 (lowercase letters, digits, '.', '_', '-'; at "
                            "most %d characters; `waterworld backends --key` prints this one's)",
                            i, WW_GOLDEN_KEY_SIZE - 1);
        for (int k = 0; k < i; k++)
            if (strcmp(g->fallback[k], item->text) == 0)
                return wwc_fail(c, WW_E_INCONSISTENT, item,
                                "golden.fallback[%d] '%s' repeats golden.fallback[%d]", i,
                                item->text, k);
        snprintf(g->fallback[i], sizeof g->fallback[i], "%s", item->text);
    }
    g->nfallback = i;
    return WW_OK;
}

ww_result wwc_golden(ctx *c, const section *top) {
    static const char *const keys[] = {"threshold", "yiq", "aa", "max", "fail_percent",
                                       "fail_pixels", "psnr_min", "yiq_pixels", "ssim_min",
                                       "fallback", NULL};
    ww_golden_desc *g = &c->sc->golden;
    section s;
    TRY(wwc_open_section(c, top, "golden", keys, &s));
    g->on = s.map != NULL;
    TRY(get_threshold(c, &s, "threshold", &R_LEVELS, WW_GOLDEN_HAS_THRESHOLD, &g->threshold));
    TRY(get_threshold(c, &s, "yiq", &R_YIQ, WW_GOLDEN_HAS_YIQ, &g->yiq));
    TRY(get_threshold(c, &s, "max", &R_LEVELS, WW_GOLDEN_HAS_MAX, &g->max));
    TRY(get_threshold(c, &s, "fail_percent", &R_PERCENT, WW_GOLDEN_HAS_FAIL_PERCENT,
                      &g->fail_percent));
    TRY(get_threshold(c, &s, "fail_pixels", &R_PIXELS, WW_GOLDEN_HAS_FAIL_PIXELS,
                      &g->fail_pixels));
    TRY(get_threshold(c, &s, "psnr_min", &R_PSNR, WW_GOLDEN_HAS_PSNR_MIN, &g->psnr_min));
    TRY(get_threshold(c, &s, "yiq_pixels", &R_PIXELS, WW_GOLDEN_HAS_YIQ_PIXELS, &g->yiq_pixels));
    TRY(get_threshold(c, &s, "ssim_min", &R_SSIM, WW_GOLDEN_HAS_SSIM_MIN, &g->ssim_min));
    const ww_node *aa;
    TRY(wwc_lookup(c, &s, "aa", OPTIONAL, &aa));
    if (aa) {
        TRY(wwc_get_word(c, &s, "aa", BOOL_WORDS, &g->aa));
        g->has |= WW_GOLDEN_HAS_AA;
    }
    return compile_fallback(c, &s);
}
