/* test_review.c - the review set (check/review.h, `waterworld review`): the list's syntax and its
 * file:line:column errors, the contact sheet's layout and labels, the HTML page's structure, and
 * the command end to end on the null backend (black frames, no GL). Then the first impression:
 * scenes/tour.yaml (`make demo`) does what it shows, checked on the simulation alone, and
 * scenes/review.list names frames its scenes have.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/image.h"
#include "io/writers.h"
#include "scene/scene.h"
#include "sim/events.h"
#include "sim/state.h"
#include "sim/step.h"
#include "test.h"
#include "check/review.h"
#include "render/contact.h"

static const char TINY[] =
    "# a tiny review list\n"
    "size: 64x36\n"
    "alpha | scenes/minimal.yaml | 0 | the sea <b> & \"sky\"\n"
    "\n"
    "beta  | scenes/minimal.yaml | 3 | second shot | --size 32x18 --set sky.time_of_day=6\n"
    "gamma | scenes/minimal.yaml | 1 | third, quoted | --set 'camera.path=[{t: 0, position: [0, 2, 5], look_at: [0, 0, 0]}]'\n";

TEST(review_list_parses) {
    ww_review_list l;
    ww_error err = {0};
    ENSURE_EQ_INT(ww_review_parse("tiny.list", TINY, strlen(TINY), &l, &err), WW_OK);
    ENSURE_EQ_INT(l.n, 3);
    if (l.n != 3) return;
    ENSURE(strcmp(l.shots[0].name, "alpha") == 0);
    ENSURE(strcmp(l.shots[0].scene, "scenes/minimal.yaml") == 0);
    ENSURE_EQ_INT(l.shots[0].frame, 0);
    ENSURE_EQ_INT(l.shots[0].line, 3);
    ENSURE_EQ_INT(l.shots[0].width, 64);
    ENSURE_EQ_INT(l.shots[0].height, 36);
    ENSURE(strcmp(l.shots[0].caption, "the sea <b> & \"sky\"") == 0);
    ENSURE_EQ_INT(l.shots[0].nsets, 0);
    ENSURE_EQ_INT(l.shots[1].width, 32);
    ENSURE_EQ_INT(l.shots[1].frame, 3);
    ENSURE_EQ_INT(l.shots[1].nsets, 1);
    ENSURE(strcmp(l.shots[1].sets[0], "sky.time_of_day=6") == 0);
    ENSURE_EQ_INT(l.shots[2].nsets, 1);
    ENSURE(strcmp(l.shots[2].sets[0], "camera.path=[{t: 0, position: [0, 2, 5], look_at: [0, 0, 0]}]") == 0);
    ww_review_free(&l);
}

/* each bad line: its text as line 2 of a list, the code, the column */
TEST(review_list_bad_line_has_line_and_column) {
    static const struct {
        const char *line;
        ww_result code;
        int column;
    } cases[] = {
        {"a | scenes/minimal.yaml | x1 | caption", WW_E_TYPE, 27},
        {"a | scenes/minimal.yaml | -1 | caption", WW_E_TYPE, 27},
        {"A | scenes/minimal.yaml | 1 | caption", WW_E_SYNTAX, 1},
        {"a | scenes/minimal.yaml | 1", WW_E_SYNTAX, 28},
        {"a | scenes/minimal.yaml | 1 |   ", WW_E_MISSING, 33},
        {"a | scenes/minimal.yaml | 1 | c | --frames 3", WW_E_SYNTAX, 35},
        {"a | scenes/minimal.yaml | 1 | c | --size 10x10", WW_E_RANGE, 42},
        {"a | scenes/minimal.yaml | 1 | c | --set novalue", WW_E_SYNTAX, 41},
        {"a | scenes/minimal.yaml | 1 | c | --set 'open", WW_E_SYNTAX, 41},
        {"a | scenes/minimal.yaml | 1 | c | d | e", WW_E_SYNTAX, 37},
        {"size: 12", WW_E_RANGE, 7},
        {"first | scenes/minimal.yaml | 1 | again", WW_E_DUPLICATE_KEY, 1},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char text[512];
        snprintf(text, sizeof text, "first | scenes/minimal.yaml | 0 | fine\n%s\n", cases[i].line);
        ww_review_list l;
        ww_error err = {0};
        ww_result r = ww_review_parse("bad.list", text, strlen(text), &l, &err);
        ENSURE_MSG(r == cases[i].code, "'%s': code %s, expected %s (%s)", cases[i].line, ww_result_name(r),
                   ww_result_name(cases[i].code), err.msg);
        ENSURE_MSG(err.line == 2 && err.column == cases[i].column, "'%s': at %d:%d, expected 2:%d (%s)",
                   cases[i].line, err.line, err.column, cases[i].column, err.msg);
        ENSURE(strcmp(err.file, "bad.list") == 0);
        ENSURE(l.shots == NULL);
    }
    ww_review_list l;
    ww_error err = {0};
    ENSURE_EQ_INT(ww_review_parse("empty.list", "# nothing\n", 10, &l, &err), WW_E_EMPTY);
}

/* the label: head line with index, name, scene and frame; the caption wrapped; the options */
TEST(review_label_lines) {
    ww_review_shot s = {.name = "beta", .scene = "scenes/x.yaml", .frame = 12, .nsets = 1,
                        .caption = "one two three four five six"};
    snprintf(s.sets[0], sizeof s.sets[0], "sky.time_of_day=6");
    char label[1024];
    ww_review_label(&s, 1, 14, label, sizeof label);
    ENSURE_MSG(strcmp(label, "02 beta: scenes/x.yaml frame 12\none two three\nfour five six\nsky.time_of_day=6") == 0,
               "label '%s'", label);
    s.checked = 1;
    s.t = 0.4;
    ww_review_label(&s, 1, 0, label, sizeof label);
    ENSURE_MSG(strncmp(label, "02 beta: scenes/x.yaml frame 12, t=0.40 s\none two three four five six\n\n", 70) == 0,
               "label '%s'", label);
}

/* contact.c's scaler: the mean of the source pixels under each output pixel, nearest when
 * enlarging */
TEST(review_contact_fit_averages) {
    ww_image src = {0}, out = {0};
    ENSURE(ww_image_alloc(&src, 4, 2, 4, WW_PIX_U8) == 0);
    for (int i = 0; i < 8; i++) {
        uint8_t *p = src.u8 + 4 * i;
        p[0] = (uint8_t)(10 * i);                 /* 0 10 20 30 / 40 50 60 70 */
        p[1] = (uint8_t)(i % 4 < 2 ? 100 : 200);
        p[2] = 7;
        p[3] = 255;
    }
    ENSURE(ww_contact_fit(&src, 2, 1, &out) == 0);
    ENSURE(out.channels == 3 && out.width == 2 && out.height == 1);
    /* left half: (0 + 10 + 40 + 50) / 4 = 25; right half: (20 + 30 + 60 + 70) / 4 = 45 */
    ENSURE_EQ_INT(out.u8[0], 25);
    ENSURE_EQ_INT(out.u8[3], 45);
    ENSURE_EQ_INT(out.u8[1], 100);
    ENSURE_EQ_INT(out.u8[4], 200);
    ENSURE_EQ_INT(out.u8[5], 7);
    ww_image_free(&out);
    ENSURE(ww_contact_fit(&src, 8, 4, &out) == 0);
    ENSURE_EQ_INT(out.u8[0], 0);
    ENSURE_EQ_INT(out.u8[(3 * 8 + 7) * 3], 70);
    ww_image_free(&out);
    ww_image_free(&src);
}

static int write_solid_png(const char *path, int w, int h, uint8_t r, uint8_t g, uint8_t b) {
    ww_image im = {0};
    if (ww_image_alloc(&im, w, h, 3, WW_PIX_U8) != 0) return -1;
    for (size_t i = 0; i < (size_t)w * (size_t)h; i++) {
        im.u8[3 * i] = r;
        im.u8[3 * i + 1] = g;
        im.u8[3 * i + 2] = b;
    }
    ww_error err = {0};
    int rc = ww_write_png(path, &im, &err) == WW_OK ? 0 : -1;
    ww_image_free(&im);
    return rc;
}

static const uint8_t *px(const ww_image *im, int x, int y) { return ww_test_pixel(im, x, y); }

/* the sheet: size from the layout formula, each shot scaled into its cell, a missing shot marked,
 * labels drawn below each cell */
TEST(review_sheet_layout_and_labels) {
    ww_review_list l;
    ww_error err = {0};
    ENSURE_EQ_INT(ww_review_parse("tiny.list", TINY, strlen(TINY), &l, &err), WW_OK);
    char dir[600], shots[700], path[800];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("review"));
    snprintf(shots, sizeof shots, "%s", ww_test_tmpdir("review/shots"));
    /* alpha red at 64x36, beta green at 32x18 (scaled up), gamma missing */
    ww_review_shot_path(dir, &l.shots[0], path, sizeof path);
    ENSURE(write_solid_png(path, 64, 36, 200, 10, 10) == 0);
    ww_review_shot_path(dir, &l.shots[1], path, sizeof path);
    ENSURE(write_solid_png(path, 32, 18, 10, 200, 10) == 0);

    ww_review_sheet_opts o = {.cols = 2, .thumb_w = 96, .thumb_h = 54};
    int missing = -1;
    ENSURE_EQ_INT(ww_review_sheet(&l, dir, &o, &missing, &err), WW_OK);
    ENSURE_EQ_INT(missing, 1);
    snprintf(path, sizeof path, "%s/review.png", dir);
    ww_image sheet = {0};
    ENSURE_EQ_INT(ww_read_png(path, &sheet, &err), WW_OK);
    ww_contact_layout L;
    ww_contact_plan(3, 2, 96, 54, WW_REVIEW_LABEL_LINES, &L);
    ENSURE_EQ_INT(L.rows, 2);
    ENSURE_EQ_INT(sheet.width, 2 * (96 + WW_CONTACT_GAP) + WW_CONTACT_GAP);
    ENSURE_EQ_INT(sheet.height, 2 * (54 + 4 * WW_CONTACT_LINE_H + WW_CONTACT_PAD + WW_CONTACT_GAP) + WW_CONTACT_GAP);
    ENSURE_EQ_INT(sheet.width, L.width);
    ENSURE_EQ_INT(sheet.height, L.height);
    if (sheet.width != L.width || sheet.height != L.height) {
        ww_image_free(&sheet);
        ww_review_free(&l);
        return;
    }
    int g = WW_CONTACT_GAP, cell_h = 54 + L.label_h + g;
    /* cell 0 red, cell 1 green (both corners: the whole cell is filled) */
    ENSURE(px(&sheet, g, g)[0] == 200 && px(&sheet, g + 95, g + 53)[0] == 200);
    ENSURE(px(&sheet, 2 * g + 96, g)[1] == 200 && px(&sheet, 2 * g + 96 + 95, g + 53)[1] == 200);
    /* cell 2 (row 1) marked as having no image: contact.c's colour (70, 40, 40) */
    const uint8_t *m = px(&sheet, g + 90, g + cell_h + 50);
    ENSURE_MSG(m[0] == 70 && m[1] == 40 && m[2] == 40, "missing cell %d %d %d", m[0], m[1], m[2]);
    /* label text below each cell: light pixels on the first label line, none in the gap */
    for (int c = 0; c < 3; c++) {
        int x0 = g + (c % 2) * (96 + g), y0 = g + (c / 2) * cell_h + 54 + WW_CONTACT_PAD;
        int lit = 0;
        for (int y = y0; y < y0 + WW_CONTACT_LINE_H; y++)
            for (int x = x0; x < x0 + 96; x++) lit += px(&sheet, x, y)[0] > 200;
        ENSURE_MSG(lit > 20, "cell %d label: %d lit pixels", c, lit);
    }
    ww_image_free(&sheet);
    ww_review_free(&l);
}

/* a small structural check of HTML: every non-void element closed in order, no raw '<' or '&'
 * outside tags and entities; 0 when well formed */
static int html_check(const char *s, char *why, size_t cap) {
    static const char *voids[] = {"meta", "img", "br", "link", "!DOCTYPE"};
    char stack[64][16];
    int depth = 0;
    for (const char *p = s; *p; p++) {
        if (*p == '&') {
            const char *semi = strchr(p, ';');
            if (!semi || semi - p > 8) return snprintf(why, cap, "bare '&' at %ld", (long)(p - s)), -1;
            continue;
        }
        if (*p == '>') return snprintf(why, cap, "bare '>' at %ld", (long)(p - s)), -1;
        if (*p != '<') continue;
        const char *e = strchr(p, '>');
        if (!e) return snprintf(why, cap, "unclosed tag at %ld", (long)(p - s)), -1;
        /* a tag's attributes: quotes balanced, no '<' inside */
        int quotes = 0;
        for (const char *q = p + 1; q < e; q++) {
            if (*q == '"') quotes++;
            if (*q == '<') return snprintf(why, cap, "'<' inside a tag at %ld", (long)(q - s)), -1;
        }
        if (quotes % 2) return snprintf(why, cap, "odd quotes in tag at %ld", (long)(p - s)), -1;
        int closing = p[1] == '/';
        const char *nb = p + 1 + closing, *ne = nb;
        while (ne < e && *ne != ' ' && *ne != '\n') ne++;
        char name[16];
        snprintf(name, sizeof name, "%.*s", (int)(ne - nb), nb);
        int is_void = 0;
        for (size_t v = 0; v < sizeof voids / sizeof voids[0]; v++) is_void |= strcmp(name, voids[v]) == 0;
        if (closing) {
            if (depth == 0 || strcmp(stack[depth - 1], name) != 0)
                return snprintf(why, cap, "</%s> closes <%s>", name, depth ? stack[depth - 1] : "nothing"), -1;
            depth--;
        } else if (!is_void) {
            if (depth == 64) return snprintf(why, cap, "too deep"), -1;
            snprintf(stack[depth++], sizeof stack[0], "%s", name);
            /* style's body is CSS: skip to its end tag */
            if (strcmp(name, "style") == 0) {
                const char *end = strstr(e, "</style>");
                if (!end) return snprintf(why, cap, "unclosed style"), -1;
                e = end - 1;
            }
        }
        p = e;
    }
    if (depth) return snprintf(why, cap, "<%s> never closed", stack[depth - 1]), -1;
    return 0;
}

TEST(review_html_is_well_formed) {
    /* the checker itself */
    char why[200];
    ENSURE(html_check("<p>a &amp; b<br></p>", why, sizeof why) == 0);
    ENSURE(html_check("<p>a & b</p>", why, sizeof why) != 0);
    ENSURE(html_check("<p><b>x</p></b>", why, sizeof why) != 0);
    ENSURE(html_check("<p>1 < 2</p>", why, sizeof why) != 0);

    ww_review_list l;
    ww_error err = {0};
    ENSURE_EQ_INT(ww_review_parse("tiny.list", TINY, strlen(TINY), &l, &err), WW_OK);
    char dir[600], path[800];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("html"));
    ww_test_tmpdir("html/shots");
    ww_review_shot_path(dir, &l.shots[0], path, sizeof path);
    ENSURE(write_solid_png(path, 64, 36, 1, 2, 3) == 0);
    ENSURE_EQ_INT(ww_review_html(&l, dir, &err), WW_OK);
    snprintf(path, sizeof path, "%s/index.html", dir);
    char *html = ww_test_read_file(path, NULL);
    ENSURE(html != NULL);
    if (!html) return;
    ENSURE(strncmp(html, "<!DOCTYPE html>\n<html lang=\"en\">", 31) == 0);
    ENSURE_MSG(html_check(html, why, sizeof why) == 0, "index.html: %s", why);
    /* the caption escaped, the image beside the page, the missing shots marked */
    ENSURE(strstr(html, "the sea &lt;b&gt; &amp; &quot;sky&quot;") != NULL);
    ENSURE(strstr(html, "<img src=\"shots/alpha.png\" width=\"64\" height=\"36\"") != NULL);
    ENSURE(strstr(html, "shots/beta.png") == NULL);
    ENSURE(strstr(html, "no image") != NULL);
    ENSURE(strstr(html, "--set sky.time_of_day=6") != NULL);
    ENSURE(strstr(html, "href=\"review.png\"") != NULL);
    free(html);
    ww_review_free(&l);
}

/* the command end to end on the null backend: renders, sheet, page; then a bad line, exit 2 */
TEST_PROC(cli_review_null_backend) {
    char dir[600], list[700], out[700], args[2400], err_path[700];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("cli_review"));
    snprintf(list, sizeof list, "%s/tiny.list", dir);
    snprintf(out, sizeof out, "%s/out", dir);
    snprintf(err_path, sizeof err_path, "%s/err.txt", dir);
    ENSURE(ww_test_write_text(list, TINY) == 0);
    snprintf(args, sizeof args, "review %s -o %s --backend null --thumb 64x36 --quiet", list, out);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, err_path), 0);
    const char *files[] = {"review.png", "index.html", "shots/alpha.png", "shots/beta.png", "shots/gamma.png"};
    for (int i = 0; i < 5; i++) {
        char p[900];
        snprintf(p, sizeof p, "%s/%s", out, files[i]);
        FILE *f = fopen(p, "rb");
        ENSURE_MSG(f != NULL, "%s missing", p);
        if (f) fclose(f);
    }
    /* each shot at its own size */
    char p[900];
    ww_image im = {0};
    ww_error err = {0};
    snprintf(p, sizeof p, "%s/shots/beta.png", out);
    ENSURE_EQ_INT(ww_read_png(p, &im, &err), WW_OK);
    ENSURE(im.width == 32 && im.height == 18);
    ww_image_free(&im);
    snprintf(p, sizeof p, "%s/index.html", out);
    ENSURE(ww_test_file_contains(p, "t = 0.10 s")); /* beta: frame 3 of minimal.yaml at 30 fps */

    /* a bad frame on line 5 (column 31): exit 2, the place named, nothing rendered */
    ENSURE(ww_test_write_text(list, "size: 64x36\n\n# a comment\nalpha | scenes/minimal.yaml | 0 | fine\n"
                                    "beta  | scenes/minimal.yaml | 1.5 | not a frame\n") == 0);
    snprintf(out, sizeof out, "%s/out2", dir);
    snprintf(args, sizeof args, "review %s -o %s --backend null --quiet", list, out);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, err_path), 2);
    char place[800];
    snprintf(place, sizeof place, "%s:5:31: error", list);
    ENSURE_MSG(ww_test_file_contains(err_path, place), "stderr lacks '%s'", place);
    snprintf(p, sizeof p, "%s/review.png", out);
    FILE *f = fopen(p, "rb");
    ENSURE(f == NULL);
    if (f) fclose(f);

    /* a frame past the scene's end: exit 2 at the shot's line */
    ENSURE(ww_test_write_text(list, "alpha | scenes/minimal.yaml | 100000 | past the end\n") == 0);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, err_path), 2);
    snprintf(place, sizeof place, "%s:1:1: error", list);
    ENSURE_MSG(ww_test_file_contains(err_path, place), "stderr lacks '%s'", place);
}

/* the tour: every frame's camera and the events of the whole run */
TEST(tour_script_does_what_it_shows) {
    ww_scene *sc = NULL;
    ww_error err = {0};
    ENSURE_MSG(ww_scene_load("scenes/tour.yaml", NULL, 0, &sc, &err) == WW_OK, "%s", err.msg);
    if (!sc) return;
    ENSURE(sc->audio.on); /* make demo muxes its sound track */
    int n[WW_SE_COUNT] = {0};
    double collect_t = -1, first_below = -1, last_below = -1;
    long long frames_below = 0, frames_above = 0, frames_seat = 0;
    ww_state *st = ww_state_new(sc);
    int64_t last = sc->frame_count * sc->steps_per_frame;
    for (int64_t s = 0; s <= last; s++) {
        if (s > 0) ENSURE(ww_step(sc, st, &err) == WW_OK);
        double t = sc->start + (double)s * sc->dt;
        for (int i = 0; i < ww_events_count(sc, st); i++) {
            int k = (int)st->events[i * WW_SIM_EVENT_STRIDE];
            if (k > 0 && k < WW_SE_COUNT) n[k]++;
            if (k == WW_SE_CHEST_COLLECT) collect_t = t;
        }
        if (s % sc->steps_per_frame || s == last) continue;
        /* the camera of this frame: under the water (1 m below the still level) or above it */
        double y = st->cam_pos[1];
        if (y < -1.0) {
            frames_below++;
            if (first_below < 0) first_below = t;
            last_below = t;
        }
        frames_above += y > 0.5;
        frames_seat += st->boat_camera[0] == 1.0;
    }
    ENSURE(st->events_dropped[0] == 0.0);
    /* stones skip, and one sinks at once; a cast lands, a fish bites and is caught */
    ENSURE_MSG(n[WW_SE_STONE_THROW] == 3 && n[WW_SE_STONE_SKIP] >= 6 && n[WW_SE_STONE_SINK] == 3,
               "throws %d skips %d sinks %d", n[WW_SE_STONE_THROW], n[WW_SE_STONE_SKIP], n[WW_SE_STONE_SINK]);
    ENSURE(n[WW_SE_ROD_CAST] == 1 && n[WW_SE_LURE_LAND] == 1 && n[WW_SE_BITE] == 1 && n[WW_SE_CATCH] == 1);
    /* the boat drives through the cubes (one pressed) and the camera rides in its seat */
    ENSURE(n[WW_SE_BOAT_START] >= 1 && n[WW_SE_CUBE_PRESS] == 1 && n[WW_SE_CUBE_RELEASE] == 1);
    ENSURE_MSG(frames_seat >= 100, "%lld frames in the seat", frames_seat);
    /* a dive: under water for seconds in the second half, above water at the start and the end */
    ENSURE_MSG(frames_below >= 150 && first_below > 13 && last_below < sc->duration - 1,
               "%lld frames below, from %g s to %g s", frames_below, first_below, last_below);
    ENSURE(frames_above >= 300 && st->cam_pos[1] > 0.5);
    /* the chest is reached under water, during the dive */
    ENSURE_MSG(n[WW_SE_CHEST_SPAWN] == 1 && n[WW_SE_CHEST_COLLECT] == 1 && collect_t > first_below &&
                   collect_t < last_below,
               "chest spawned %d, collected %d at %g s", n[WW_SE_CHEST_SPAWN], n[WW_SE_CHEST_COLLECT], collect_t);
    ENSURE(st->prizes[0] == 1.0 && st->fish_caught[0] == 1.0);
    ww_state_free(st);
    ww_scene_free(sc);
}

/* the committed review list parses, and every shot's scene loads with its options and has the
 * frame (what `make review` checks before rendering) */
TEST(review_list_committed_is_valid) {
    ww_review_list l;
    ww_error err = {0};
    ENSURE_MSG(ww_review_load("scenes/review.list", &l, &err) == WW_OK, "%s:%d:%d: %s", err.file, err.line,
               err.column, err.msg);
    if (!l.shots) return;
    ENSURE(l.n >= 20);
    ENSURE_MSG(ww_review_check(&l, &err) == WW_OK, "%s:%d:%d: %s", err.file, err.line, err.column, err.msg);
    ww_review_free(&l);
}
