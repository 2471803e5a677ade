/* golden.c - placeholder: render --golden is being written (issue 6). */
#include "tools/golden.h"

ww_cmp_opts ww_golden_scene_opts(const ww_scene *sc) {
    (void)sc;
    return ww_cmp_default_opts();
}

ww_result ww_golden_check(const ww_scene *sc, const ww_golden_opts *o, ww_golden_summary *s,
                          ww_error *err) {
    (void)sc, (void)o, (void)s;
    return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--golden is not built yet");
}
