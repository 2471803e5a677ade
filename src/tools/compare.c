/* compare.c - placeholder: the metrics of compare.h are being written (issue 6). */
#include "tools/compare.h"

#include <string.h>

ww_cmp_opts ww_cmp_default_opts(void) {
    return (ww_cmp_opts){.threshold = 0, .yiq = 0.1, .detect_aa = 1, .max = -1, .fail_percent = -1,
                         .fail_pixels = -1, .psnr_min = -1, .yiq_pixels = -1, .ssim_min = -1,
                         .rel_max = -1};
}

int ww_cmp_opt_arg(int argc, char **argv, int *i, ww_cmp_opts *o, ww_result *r, ww_error *err) {
    (void)argc, (void)argv, (void)i, (void)o, (void)r, (void)err;
    return 0;
}
