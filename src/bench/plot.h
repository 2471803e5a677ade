/* plot.h - small line plots rasterised into an RGB8 image, for the figures bench writes: axes
 * with tick labels, one polyline with markers per series, a legend, text from stb_easy_font.
 *
 *   ww_image im; ww_image_alloc(&im, 1200, 480, 3, WW_PIX_U8);    // the caller owns the image
 *   ww_plot_fill(&im, WW_PLOT_WHITE);
 *   ww_plot p = {.title = "GPU", .xlabel = "components", .ylabel = "ms", .log_x = 1};
 *   ww_plot_add(&p, "fade on", xs, ys, n, WW_PLOT_BLUE);           // p keeps the pointers
 *   ww_plot_draw(&p, &im, 0, 0, 600, 480);                         // into a panel of the image
 *   ww_write_png("out/bench/waves.png", &im, &err);
 *
 * Points that are not finite (or not positive on a log axis) are skipped and break the line.
 * Nothing here allocates.
 */
#ifndef WW_PLOT_H
#define WW_PLOT_H

#include "io/image.h"

#define WW_PLOT_MAX_SERIES 8
#define WW_PLOT_MAX_TICKS 16

typedef struct ww_plot_rgb {
    unsigned char c[3];
} ww_plot_rgb;

#define WW_PLOT_WHITE ((ww_plot_rgb){{255, 255, 255}})
#define WW_PLOT_BLACK ((ww_plot_rgb){{0, 0, 0}})
#define WW_PLOT_GREY ((ww_plot_rgb){{200, 200, 200}})
#define WW_PLOT_BLUE ((ww_plot_rgb){{31, 119, 180}})
#define WW_PLOT_ORANGE ((ww_plot_rgb){{255, 127, 14}})
#define WW_PLOT_GREEN ((ww_plot_rgb){{44, 160, 44}})
#define WW_PLOT_RED ((ww_plot_rgb){{214, 39, 40}})
#define WW_PLOT_PURPLE ((ww_plot_rgb){{148, 103, 189}})
#define WW_PLOT_BROWN ((ww_plot_rgb){{140, 86, 75}})

typedef struct ww_plot_series {
    const char *label;
    const double *x, *y;
    int n;
    ww_plot_rgb color;
} ww_plot_series;

typedef struct ww_plot {
    const char *title, *xlabel, *ylabel;
    int log_x, log_y;            /* logarithmic axes */
    int nxticks;                 /* > 0: ticks at xticks[] instead of chosen ones */
    double xticks[WW_PLOT_MAX_TICKS];
    const char *note;            /* drawn in the middle of the panel (e.g. why it is empty) */
    int no_legend;               /* 1: place the legend but leave it undrawn (what it would cover) */
    int nseries;
    ww_plot_series series[WW_PLOT_MAX_SERIES];
} ww_plot;

/* append a series (ignored past WW_PLOT_MAX_SERIES); x and y must outlive the draw */
void ww_plot_add(ww_plot *p, const char *label, const double *x, const double *y, int n,
                 ww_plot_rgb color);
/* fill the whole image with one colour (RGB8 images only) */
void ww_plot_fill(ww_image *im, ww_plot_rgb color);
/* draw p into the panel [x0, x0 + w) x [y0, y0 + h) of an RGB8 image; returns the number of
 * data points drawn */
int ww_plot_draw(const ww_plot *p, ww_image *im, int x0, int y0, int w, int h);
/* where ww_plot_draw puts the legend of p in that panel: x0, y0, x1, y1 (exclusive), all 0 when
 * no series has a label. It covers no plotted point or line: the first free corner of the plot
 * area, else a band above it (the plot area shrinks to make room) */
void ww_plot_legend_box(const ww_plot *p, int x0, int y0, int w, int h, int box[4]);
/* text with its top-left corner at (x, y), each font pixel drawn as scale x scale pixels;
 * returns the width drawn in pixels */
int ww_plot_text(ww_image *im, int x, int y, int scale, const char *text, ww_plot_rgb color);
/* width in pixels that ww_plot_text would draw */
int ww_plot_text_width(const char *text, int scale);

#endif
