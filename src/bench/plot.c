/* plot.c - the line-plot rasteriser of plot.h: axis ranges and "nice" ticks (steps of 1, 2 or 5
 * times a power of ten, as in Heckbert's "Nice numbers for graph labels", Graphics Gems 1990),
 * thick lines by stepping along the longer axis (a DDA), text as stb_easy_font's quads filled
 * as rectangles.
 */
#include "bench/plot.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include <stb/stb_easy_font.h>

#include "core/error.h"

#define WW_ASSERT_RGB8(im) WW_ASSERT((im)->type == WW_PIX_U8 && (im)->channels == 3 && (im)->u8)

#define TEXT_SCALE 2        /* font pixels -> image pixels for every label */
#define TEXT_MAX 160        /* characters drawn of one string */
#define FONT_QUAD_BYTES 64  /* 4 vertices of (x, y, z float, rgba8) */
#define LINE_HALF 1         /* a data line is 2 LINE_HALF + 1 pixels thick */
#define MARKER_HALF 3       /* markers are 2 MARKER_HALF + 1 pixels square */
#define TARGET_TICKS 5      /* about this many ticks on a chosen linear axis */
#define LEGEND_PAD 4        /* pixels between the legend's edge and its contents */
#define LEGEND_GAP 6        /* pixels kept between the legend and plotted data or the frame */

/* the panel's plotting rectangle and the data -> pixel map */
typedef struct frame {
    int px0, py0, px1, py1;   /* plot area, pixels (inclusive) */
    double u0, u1, v0, v1;    /* axis range in axis units (log10 of the value on a log axis) */
    int log_x, log_y;
    int any;                  /* some series has a usable point */
} frame;

void ww_plot_add(ww_plot *p, const char *label, const double *x, const double *y, int n,
                 ww_plot_rgb color) {
    if (p->nseries >= WW_PLOT_MAX_SERIES) return;
    p->series[p->nseries++] = (ww_plot_series){label, x, y, n, color};
}

static void put(ww_image *im, int x, int y, ww_plot_rgb c) {
    if (x < 0 || y < 0 || x >= im->width || y >= im->height) return;
    unsigned char *px = im->u8 + ((size_t)y * (size_t)im->width + (size_t)x) * (size_t)im->channels;
    px[0] = c.c[0];
    px[1] = c.c[1];
    px[2] = c.c[2];
}

/* the rectangle [x0, x1) x [y0, y1), cut to the image */
static void rect(ww_image *im, int x0, int y0, int x1, int y1, ww_plot_rgb c) {
    for (int y = y0 < 0 ? 0 : y0; y < y1 && y < im->height; y++)
        for (int x = x0 < 0 ? 0 : x0; x < x1 && x < im->width; x++) put(im, x, y, c);
}

void ww_plot_fill(ww_image *im, ww_plot_rgb color) {
    WW_ASSERT_RGB8(im);
    rect(im, 0, 0, im->width, im->height, color);
}

/* a printable copy of text (stb_easy_font indexes its tables by c - 32) */
static void clean_text(const char *text, char *out) {
    int n = 0;
    for (; text && text[n] && n < TEXT_MAX; n++) out[n] = text[n] >= 32 && text[n] < 127 ? text[n] : '?';
    out[n] = 0;
}

int ww_plot_text_width(const char *text, int scale) {
    char s[TEXT_MAX + 1];
    clean_text(text, s);
    stb_easy_font_spacing(0.0f); /* the library's one global, pinned before each use */
    return stb_easy_font_width(s) * scale;
}

int ww_plot_text(ww_image *im, int x, int y, int scale, const char *text, ww_plot_rgb color) {
    char s[TEXT_MAX + 1];
    /* stb_easy_font uses about 270 bytes of quads per character */
    float quads[TEXT_MAX * 300 / sizeof(float)];
    clean_text(text, s);
    stb_easy_font_spacing(0.0f);
    int n = stb_easy_font_print(0.0f, 0.0f, s, NULL, quads, (int)sizeof quads);
    for (int q = 0; q < n; q++) {
        const float *v = quads + q * (FONT_QUAD_BYTES / (int)sizeof(float));
        float xa = v[0], xb = v[0], ya = v[1], yb = v[1];
        for (int k = 1; k < 4; k++) { /* 4 floats (x, y, z, rgba) per vertex */
            xa = fminf(xa, v[4 * k]);
            xb = fmaxf(xb, v[4 * k]);
            ya = fminf(ya, v[4 * k + 1]);
            yb = fmaxf(yb, v[4 * k + 1]);
        }
        rect(im, x + (int)lroundf(xa * (float)scale), y + (int)lroundf(ya * (float)scale),
             x + (int)lroundf(xb * (float)scale), y + (int)lroundf(yb * (float)scale), color);
    }
    return stb_easy_font_width(s) * scale;
}

/* 1, 2 or 5 times a power of ten, near x (Heckbert's nice number, rounded) */
static double nice_step(double x) {
    double e = floor(log10(x)), f = x / pow(10.0, e);
    double nf = f < 1.5 ? 1.0 : f < 3.0 ? 2.0 : f < 7.0 ? 5.0 : 10.0;
    return nf * pow(10.0, e);
}

/* height of one line of text, pixels */
static int line_height(int scale) {
    char one[] = "0";
    return stb_easy_font_height(one) * scale;
}

static int usable(double v, int log_axis) { return isfinite(v) && (!log_axis || v > 0.0); }
static double to_axis(double v, int log_axis) { return log_axis ? log10(v) : v; }

/* the range of the data in axis units; 0 when there is none */
static int data_range(const ww_plot *p, double *u0, double *u1, double *v0, double *v1) {
    int any = 0;
    for (int s = 0; s < p->nseries; s++) {
        const ww_plot_series *se = &p->series[s];
        for (int i = 0; i < se->n; i++) {
            if (!usable(se->x[i], p->log_x) || !usable(se->y[i], p->log_y)) continue;
            double u = to_axis(se->x[i], p->log_x), v = to_axis(se->y[i], p->log_y);
            if (!any) {
                *u0 = *u1 = u;
                *v0 = *v1 = v;
                any = 1;
            }
            *u0 = fmin(*u0, u);
            *u1 = fmax(*u1, u);
            *v0 = fmin(*v0, v);
            *v1 = fmax(*v1, v);
        }
    }
    for (int i = 0; i < p->nxticks; i++) {
        if (!usable(p->xticks[i], p->log_x)) continue;
        double u = to_axis(p->xticks[i], p->log_x);
        if (!any) *u0 = *u1 = u;
        *u0 = fmin(*u0, u);
        *u1 = fmax(*u1, u);
    }
    return any;
}

/* widen [a, b] to something drawable: a linear axis starts at a multiple of its tick step
 * (and at 0 when the data are all positive and near it), a log axis gets a margin */
static void pad_range(double *a, double *b, int log_axis) {
    if (!(*b > *a)) {
        double d = log_axis ? 0.5 : (*a != 0.0 ? 0.5 * fabs(*a) : 1.0);
        *a -= d;
        *b += d;
    }
    if (log_axis) {
        double m = 0.06 * (*b - *a);
        *a -= m;
        *b += m;
        return;
    }
    if (*a > 0.0 && *a < 0.5 * *b) *a = 0.0;
    double step = nice_step((*b - *a) / TARGET_TICKS);
    *a = floor(*a / step) * step;
    *b = ceil(*b / step) * step;
}

/* tick values (not axis units) inside [a, b] of an axis */
static int linear_ticks(double a, double b, double *out) {
    int n = 0;
    double step = nice_step((b - a) / TARGET_TICKS);
    for (double v = ceil(a / step - 1e-9) * step; v <= b + 1e-9 * step && n < WW_PLOT_MAX_TICKS;
         v += step)
        out[n++] = fabs(v) < 1e-12 * step ? 0.0 : v;
    return n;
}

static int ticks(double a, double b, int log_axis, double *out) {
    int n = 0;
    if (!log_axis) return linear_ticks(a, b, out);
    /* less than a factor of 3: evenly spaced values read better than powers */
    if (b - a < 0.5) return linear_ticks(pow(10.0, a), pow(10.0, b), out);
    /* powers of ten; 2 and 5 between them over a few decades, every digit within one */
    static const double few[] = {1.0, 2.0, 5.0}, all[] = {1, 2, 3, 4, 5, 6, 7, 8, 9};
    const double *man = b - a <= 1.0 ? all : few;
    int nm = b - a <= 1.0 ? 9 : b - a <= 2.5 ? 3 : 1;
    for (double e = floor(a); e <= ceil(b); e += 1.0)
        for (int m = 0; m < nm && n < WW_PLOT_MAX_TICKS; m++) {
            double u = e + log10(man[m]);
            if (u >= a && u <= b) out[n++] = pow(10.0, u);
        }
    return n;
}

static int map_x(const frame *f, double u) {
    return f->px0 + (int)lround((u - f->u0) / (f->u1 - f->u0) * (double)(f->px1 - f->px0));
}
static int map_y(const frame *f, double v) {
    return f->py1 - (int)lround((v - f->v0) / (f->v1 - f->v0) * (double)(f->py1 - f->py0));
}

/* a square of half-size h at (x, y), kept inside the plot area */
static void stamp(ww_image *im, const frame *f, int x, int y, int h, ww_plot_rgb c) {
    for (int yy = y - h; yy <= y + h; yy++)
        for (int xx = x - h; xx <= x + h; xx++)
            if (xx >= f->px0 && xx <= f->px1 && yy >= f->py0 && yy <= f->py1) put(im, xx, yy, c);
}

/* a thick line: one stamp per pixel along the longer axis */
static void line(ww_image *im, const frame *f, int xa, int ya, int xb, int yb, ww_plot_rgb c) {
    int dx = xb - xa, dy = yb - ya;
    int n = abs(dx) > abs(dy) ? abs(dx) : abs(dy);
    if (n == 0) {
        stamp(im, f, xa, ya, LINE_HALF, c);
        return;
    }
    for (int i = 0; i <= n; i++) {
        double u = (double)i / (double)n;
        stamp(im, f, xa + (int)lround(u * dx), ya + (int)lround(u * dy), LINE_HALF, c);
    }
}

static void tick_label(double v, char *buf, size_t cap) { snprintf(buf, cap, "%g", v); }

/* the legend's size: rows of a swatch and a label, the widest label */
static int legend_size(const ww_plot *p, int s, int lh, int *w, int *h) {
    int tw = 0, n = 0;
    for (int k = 0; k < p->nseries; k++) {
        if (!p->series[k].label) continue;
        int t = ww_plot_text_width(p->series[k].label, s);
        tw = t > tw ? t : tw;
        n++;
    }
    *w = LEGEND_PAD + 34 + tw + LEGEND_PAD;
    *h = n * lh + LEGEND_PAD;
    return n;
}

/* plotted pixels (markers and the lines between them, LEGEND_GAP around them) inside box */
static long covered(const ww_plot *p, const frame *f, const int box[4]) {
    long n = 0;
    int g = MARKER_HALF + LEGEND_GAP;
    for (int k = 0; k < p->nseries; k++) {
        const ww_plot_series *se = &p->series[k];
        int have = 0, lx = 0, ly = 0;
        for (int i = 0; i < se->n; i++) {
            if (!usable(se->x[i], f->log_x) || !usable(se->y[i], f->log_y)) {
                have = 0;
                continue;
            }
            int x = map_x(f, to_axis(se->x[i], f->log_x));
            int y = map_y(f, to_axis(se->y[i], f->log_y));
            int m = have ? (abs(x - lx) > abs(y - ly) ? abs(x - lx) : abs(y - ly)) : 0;
            for (int j = 0; j <= m; j++) {
                double u = m ? (double)j / (double)m : 1.0;
                int xx = lx + (int)lround(u * (x - lx)), yy = ly + (int)lround(u * (y - ly));
                if (!have) xx = x, yy = y;
                n += xx >= box[0] - g && xx < box[2] + g && yy >= box[1] - g && yy < box[3] + g;
            }
            lx = x;
            ly = y;
            have = 1;
        }
    }
    return n;
}

/* the frame of a panel and where its legend goes: the first corner of the plot area (top left,
 * top right, bottom right, bottom left) that covers no plotted point or line; when each would,
 * a band above the plot area, which shrinks to make room. box: x0, y0, x1, y1 (exclusive) */
static int layout(const ww_plot *p, int x0, int y0, int w, int h, frame *f, int box[4]) {
    const int s = TEXT_SCALE, lh = line_height(s);
    *f = (frame){.px0 = x0 + 11 * 6 * s / 2 + 12, .px1 = x0 + w - 16, .py0 = y0 + 2 * lh + 8,
                 .py1 = y0 + h - 2 * lh - 12, .log_x = p->log_x, .log_y = p->log_y};
    box[0] = box[1] = box[2] = box[3] = 0;
    if (f->px1 - f->px0 < 20 || f->py1 - f->py0 < 20) return 0;
    int any = f->any = data_range(p, &f->u0, &f->u1, &f->v0, &f->v1);
    if (!any) {
        f->u0 = 0.0;
        f->u1 = 1.0;
        f->v0 = 0.0;
        f->v1 = 1.0;
    }
    pad_range(&f->u0, &f->u1, f->log_x);
    pad_range(&f->v0, &f->v1, f->log_y);
    int lw, lhgt;
    if (legend_size(p, s, lh, &lw, &lhgt) == 0) return 1;
    int m = LEGEND_GAP;
    const int corner[4][2] = {{f->px0 + m, f->py0 + m},
                              {f->px1 - m - lw, f->py0 + m},
                              {f->px1 - m - lw, f->py1 - m - lhgt},
                              {f->px0 + m, f->py1 - m - lhgt}};
    for (int c = 0; c < 4; c++) {
        int b[4] = {corner[c][0], corner[c][1], corner[c][0] + lw, corner[c][1] + lhgt};
        if (b[0] < f->px0 || b[1] < f->py0 || covered(p, f, b)) continue;
        for (int k = 0; k < 4; k++) box[k] = b[k];
        return 1;
    }
    /* every corner would hide data: the band above the plot area, right-aligned */
    int top = f->py0;
    f->py0 += lhgt + m;
    if (f->py1 - f->py0 < 20) f->py0 = f->py1 - 20;
    box[0] = f->px1 + 1 - lw;
    box[1] = top - lh / 2;
    box[2] = box[0] + lw;
    box[3] = box[1] + lhgt;
    return 1;
}

void ww_plot_legend_box(const ww_plot *p, int x0, int y0, int w, int h, int box[4]) {
    frame f;
    layout(p, x0, y0, w, h, &f, box);
}

int ww_plot_draw(const ww_plot *p, ww_image *im, int x0, int y0, int w, int h) {
    WW_ASSERT_RGB8(im);
    const int s = TEXT_SCALE, lh = line_height(s);
    frame f;
    int box[4];
    if (!layout(p, x0, y0, w, h, &f, box)) return 0;

    /* title and the y label above the plot area */
    if (p->title)
        ww_plot_text(im, x0 + (w - ww_plot_text_width(p->title, s)) / 2, y0 + 6, s, p->title,
                     WW_PLOT_BLACK);
    if (p->ylabel) ww_plot_text(im, x0 + 8, f.py0 - lh, s, p->ylabel, WW_PLOT_BLACK);
    if (p->xlabel)
        ww_plot_text(im, (f.px0 + f.px1 - ww_plot_text_width(p->xlabel, s)) / 2, f.py1 + lh + 8, s,
                     p->xlabel, WW_PLOT_BLACK);
    int any = f.any;

    /* grid lines and tick labels */
    double tv[WW_PLOT_MAX_TICKS];
    char buf[32];
    int nt = p->nxticks > 0 ? p->nxticks : ticks(f.u0, f.u1, f.log_x, tv);
    for (int i = 0; i < nt; i++) {
        double v = p->nxticks > 0 ? p->xticks[i] : tv[i];
        if (!usable(v, f.log_x)) continue;
        int x = map_x(&f, to_axis(v, f.log_x));
        if (x < f.px0 || x > f.px1) continue;
        rect(im, x, f.py0, x + 1, f.py1, WW_PLOT_GREY);
        tick_label(v, buf, sizeof buf);
        ww_plot_text(im, x - ww_plot_text_width(buf, s) / 2, f.py1 + 6, s, buf, WW_PLOT_BLACK);
    }
    nt = ticks(f.v0, f.v1, f.log_y, tv);
    for (int i = 0; i < nt; i++) {
        int y = map_y(&f, to_axis(tv[i], f.log_y));
        if (y < f.py0 || y > f.py1) continue;
        rect(im, f.px0, y, f.px1, y + 1, WW_PLOT_GREY);
        tick_label(tv[i], buf, sizeof buf);
        ww_plot_text(im, f.px0 - 6 - ww_plot_text_width(buf, s), y - lh / 3, s, buf, WW_PLOT_BLACK);
    }

    /* the frame */
    rect(im, f.px0, f.py0, f.px1 + 1, f.py0 + 1, WW_PLOT_BLACK);
    rect(im, f.px0, f.py1, f.px1 + 1, f.py1 + 1, WW_PLOT_BLACK);
    rect(im, f.px0, f.py0, f.px0 + 1, f.py1 + 1, WW_PLOT_BLACK);
    rect(im, f.px1, f.py0, f.px1 + 1, f.py1 + 1, WW_PLOT_BLACK);

    /* the series: lines between consecutive usable points, a marker on each */
    int drawn = 0;
    for (int k = 0; k < p->nseries; k++) {
        const ww_plot_series *se = &p->series[k];
        int have = 0, lx = 0, ly = 0;
        for (int i = 0; i < se->n; i++) {
            if (!usable(se->x[i], f.log_x) || !usable(se->y[i], f.log_y)) {
                have = 0;
                continue;
            }
            int x = map_x(&f, to_axis(se->x[i], f.log_x)), y = map_y(&f, to_axis(se->y[i], f.log_y));
            if (have) line(im, &f, lx, ly, x, y, se->color);
            stamp(im, &f, x, y, MARKER_HALF, se->color);
            lx = x;
            ly = y;
            have = 1;
            drawn++;
        }
    }

    /* the legend where layout put it, on white */
    int ly = box[1] + LEGEND_PAD;
    for (int k = 0; k < p->nseries && !p->no_legend; k++) {
        const ww_plot_series *se = &p->series[k];
        if (!se->label) continue;
        if (ly == box[1] + LEGEND_PAD) rect(im, box[0], box[1], box[2], box[3], WW_PLOT_WHITE);
        rect(im, box[0] + LEGEND_PAD, ly + lh / 3 - 1, box[0] + LEGEND_PAD + 24, ly + lh / 3 + 2,
             se->color);
        ww_plot_text(im, box[0] + LEGEND_PAD + 30, ly, s, se->label, WW_PLOT_BLACK);
        ly += lh;
    }

    const char *note = p->note ? p->note : any ? NULL : "no data";
    if (note)
        ww_plot_text(im, (f.px0 + f.px1 - ww_plot_text_width(note, s)) / 2, (f.py0 + f.py1) / 2, s,
                     note, WW_PLOT_RED);
    return drawn;
}
