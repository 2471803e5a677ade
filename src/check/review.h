/* review.h - the review set: a list of shots (scene, frame, size, render options, caption), one
 * rendered frame per shot, and the two pages a person looks at: a labelled contact sheet (PNG)
 * and an HTML page with every shot at full size. `waterworld review` drives it (cli/cmd_review.c).
 *
 *   ww_review_list l;
 *   ww_review_load("scenes/review.list", &l, &err);   // parse: errors at file:line:column
 *   ww_review_check(&l, &err);                         // load each scene: frame in range, t
 *   ... render shot i into ww_review_shot_path(dir, &l.shots[i]) ...
 *   ww_review_sheet(&l, dir, &sheet_opts, &err);       // DIR/review.png
 *   ww_review_html(&l, dir, &err);                     // DIR/index.html
 *   ww_review_free(&l);
 *
 * The list is text, one shot a line, fields separated by '|' ('#' starts a comment line):
 *   NAME | SCENE.yaml | FRAME | CAPTION | [--size WxH] [--set KEY=VALUE]... [--script FILE]
 * NAME is [a-z0-9_-], unique, at most 40 characters; FRAME a whole frame number; the last field
 * may be left out; an option's value may be quoted ('...' or "...") to hold spaces. A line `size: WxH` sets the size of the shots after it (default 640x360).
 */
#ifndef WW_REVIEW_H
#define WW_REVIEW_H

#include <stddef.h>

#include "core/error.h"

#define WW_REVIEW_NAME_MAX 40
#define WW_REVIEW_MAX_SETS 16
#define WW_REVIEW_MAX_SHOTS 256
#define WW_REVIEW_TEXT_MAX 400     /* scene path, caption, each --set, script path */
#define WW_REVIEW_DEFAULT_W 640
#define WW_REVIEW_DEFAULT_H 360

typedef struct ww_review_shot {
    char name[WW_REVIEW_NAME_MAX + 1];
    char scene[WW_REVIEW_TEXT_MAX];
    long long frame;
    char caption[WW_REVIEW_TEXT_MAX];
    int width, height;                          /* the shot's render size, px */
    char script[WW_REVIEW_TEXT_MAX];            /* "" for none */
    char sets[WW_REVIEW_MAX_SETS][WW_REVIEW_TEXT_MAX];
    int nsets;
    int line;                                   /* its line in the list */
    int checked;                                /* ww_review_check filled t */
    double t;                                   /* simulated time of the frame, s */
} ww_review_shot;

typedef struct ww_review_list {
    char path[512];
    ww_review_shot *shots;                      /* n of them; one malloc */
    int n;
} ww_review_list;

/* what the sheet looks like; zero means default */
typedef struct ww_review_sheet_opts {
    int cols;               /* cells per row (default 4) */
    int thumb_w, thumb_h;   /* cell size, px (default 480x270); shots are scaled to it */
} ww_review_sheet_opts;

/* the label lines under a cell (and the cell count the layout plans for) */
#define WW_REVIEW_LABEL_LINES 4

ww_result ww_review_parse(const char *path, const char *text, size_t len, ww_review_list *out,
                          ww_error *err);
ww_result ww_review_load(const char *path, ww_review_list *out, ww_error *err);
/* load each shot's scene with its options: the frame must exist and the size be valid; fills
 * t. Errors name the shot's line in the list and carry the loader's message */
ww_result ww_review_check(ww_review_list *l, ww_error *err);
void ww_review_free(ww_review_list *l);

/* where shot s's frame goes: DIR/shots/NAME.png */
void ww_review_shot_path(const char *dir, const ww_review_shot *s, char *out, size_t cap);
/* the label of shot i in the sheet ('\n' between lines; long captions wrapped at max_chars) */
void ww_review_label(const ww_review_shot *s, int i, int max_chars, char *out, size_t cap);
/* the contact sheet DIR/review.png from the shots' frames (a missing frame: a marked cell);
 * *missing counts them */
ww_result ww_review_sheet(const ww_review_list *l, const char *dir, const ww_review_sheet_opts *o,
                          int *missing, ww_error *err);
/* DIR/index.html: every shot at full size beside its label, the images by relative path */
ww_result ww_review_html(const ww_review_list *l, const char *dir, ww_error *err);

#endif
