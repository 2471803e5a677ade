/* review.c - the review set (review.h): the list of shots parsed with file:line:column errors,
 * each shot's scene loaded to check its frame, and the contact sheet and HTML page built from the
 * rendered frames. Rendering itself is `waterworld render`, run by cli/cmd_review.c.
 */
#include "check/review.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/readfile.h"
#include "io/image.h"
#include "io/stream.h"
#include "io/writers.h"
#include "render/contact.h"
#include "scene/scene.h"

#define LIST_MAX_BYTES (1u << 20)
#define FIELDS 5

/* ---- the list ------------------------------------------------------------------------------ */

typedef struct span {
    const char *p;   /* first character (spaces trimmed) */
    size_t n;
    int col;         /* 1-based column of p */
} span;

static int is_space(char c) { return c == ' ' || c == '\t' || c == '\r'; }

static span trim(const char *line, const char *b, const char *e) {
    while (b < e && is_space(*b)) b++;
    while (e > b && is_space(e[-1])) e--;
    return (span){b, (size_t)(e - b), (int)(b - line) + 1};
}

static int span_is(span s, const char *word) { return s.n == strlen(word) && memcmp(s.p, word, s.n) == 0; }

/* copy a span into a fixed buffer; -1 when it does not fit */
static int span_copy(span s, char *out, size_t cap) {
    if (s.n >= cap) return -1;
    memcpy(out, s.p, s.n);
    out[s.n] = 0;
    return 0;
}

/* "WxH" with each side in the render size range */
static int parse_size(span s, int *w, int *h) {
    char buf[32];
    if (span_copy(s, buf, sizeof buf) != 0) return -1;
    char *e = NULL;
    errno = 0;
    long a = buf[0] >= '0' && buf[0] <= '9' ? strtol(buf, &e, 10) : -1;
    if (a < 0 || errno || (*e != 'x' && *e != 'X')) return -1;
    const char *hb = e + 1;
    long b = *hb >= '0' && *hb <= '9' ? strtol(hb, &e, 10) : -1;
    if (b < 0 || errno || *e != 0) return -1;
    if (a < WW_SIZE_MIN || a > WW_SIZE_MAX || b < WW_SIZE_MIN || b > WW_SIZE_MAX) return -1;
    *w = (int)a;
    *h = (int)b;
    return 0;
}

typedef struct parser {
    const char *path;
    int line;
    ww_error *err;
} parser;

static ww_result bad(const parser *ps, int col, ww_result code, const char *fmt, const char *what,
                     size_t n) {
    char shown[64];
    size_t k = n < sizeof shown - 1 ? n : sizeof shown - 1;
    memcpy(shown, what, k);
    shown[k] = 0;
    return ww_error_set(ps->err, code, ps->path, ps->line, col, fmt, shown);
}

/* the options field: words, --size WxH, --set KEY=VALUE, --script FILE */
static ww_result parse_options(const parser *ps, const char *line, span f, ww_review_shot *s) {
    const char *p = f.p, *end = f.p + f.n;
    while (p < end) {
        while (p < end && is_space(*p)) p++;
        if (p >= end) break;
        const char *b = p;
        while (p < end && !is_space(*p)) p++;
        span opt = {b, (size_t)(p - b), (int)(b - line) + 1};
        while (p < end && is_space(*p)) p++;
        /* the value: one word, or quoted with ' or " to hold spaces (flow YAML in a --set) */
        const char *vb = p;
        span val;
        if (p < end && (*p == '\'' || *p == '"')) {
            const char *q = memchr(p + 1, *p, (size_t)(end - p - 1));
            if (!q) return bad(ps, (int)(p - line) + 1, WW_E_SYNTAX, "unclosed quote %s", p, 1);
            val = (span){p + 1, (size_t)(q - p - 1), (int)(p - line) + 2};
            p = q + 1;
            if (p < end && !is_space(*p))
                return bad(ps, (int)(p - line) + 1, WW_E_SYNTAX, "a space must follow a closing quote, not '%s'", p, 1);
        } else {
            while (p < end && !is_space(*p)) p++;
            val = (span){vb, (size_t)(p - vb), (int)(vb - line) + 1};
        }
        int known = span_is(opt, "--size") || span_is(opt, "--set") || span_is(opt, "--script");
        if (!known)
            return bad(ps, opt.col, WW_E_SYNTAX,
                       "unknown render option '%s' in a review list (--size, --set, --script)", opt.p,
                       opt.n);
        if (val.n == 0)
            return bad(ps, opt.col, WW_E_SYNTAX, "%s wants a value", opt.p, opt.n);
        if (span_is(opt, "--size")) {
            if (parse_size(val, &s->width, &s->height) != 0)
                return bad(ps, val.col, WW_E_RANGE, "--size wants WIDTHxHEIGHT (each 16..16384), got '%s'",
                           val.p, val.n);
        } else if (span_is(opt, "--script")) {
            if (span_copy(val, s->script, sizeof s->script) != 0)
                return bad(ps, val.col, WW_E_RANGE, "script path too long: '%s..'", val.p, val.n);
        } else {
            if (s->nsets >= WW_REVIEW_MAX_SETS)
                return bad(ps, opt.col, WW_E_RANGE, "more than 16 --set options on one shot%s", "", 0);
            if (!memchr(val.p, '=', val.n))
                return bad(ps, val.col, WW_E_SYNTAX, "--set wants KEY=VALUE, got '%s'", val.p, val.n);
            if (span_copy(val, s->sets[s->nsets], sizeof s->sets[0]) != 0)
                return bad(ps, val.col, WW_E_RANGE, "--set too long: '%s..'", val.p, val.n);
            s->nsets++;
        }
    }
    return WW_OK;
}

static int name_ok(span s) {
    if (s.n == 0 || s.n > WW_REVIEW_NAME_MAX) return 0;
    for (size_t i = 0; i < s.n; i++) {
        char c = s.p[i];
        if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_')) return 0;
    }
    return 1;
}

static ww_result parse_shot(const parser *ps, const char *line, const char *e, int w, int h,
                            ww_review_shot *s) {
    span f[FIELDS];
    int nf = 0;
    const char *b = line;
    for (const char *p = line;; p++) {
        if (p == e || *p == '|') {
            /* the separator that would open a sixth field */
            if (nf == FIELDS)
                return bad(ps, (int)(b - line), WW_E_SYNTAX,
                           "too many fields: a shot is NAME | SCENE | FRAME | CAPTION | OPTIONS%s", "", 0);
            f[nf++] = trim(line, b, p);
            b = p + 1;
        }
        if (p == e) break;
    }
    if (nf < 4)
        return ww_error_set(ps->err, WW_E_SYNTAX, ps->path, ps->line, (int)(e - line) + 1,
                            "a shot is NAME | SCENE | FRAME | CAPTION [| OPTIONS]: %d field%s here", nf,
                            nf == 1 ? "" : "s");
    memset(s, 0, sizeof *s);
    s->line = ps->line;
    s->width = w;
    s->height = h;
    if (!name_ok(f[0]))
        return bad(ps, f[0].col, WW_E_SYNTAX, "shot name '%s' must be 1..40 of a-z, 0-9, '-', '_'", f[0].p,
                   f[0].n);
    span_copy(f[0], s->name, sizeof s->name);
    if (f[1].n == 0) return bad(ps, f[1].col, WW_E_MISSING, "no scene file%s", "", 0);
    if (span_copy(f[1], s->scene, sizeof s->scene) != 0)
        return bad(ps, f[1].col, WW_E_RANGE, "scene path too long: '%s..'", f[1].p, f[1].n);
    /* the frame: whole digits only */
    char num[24];
    int digits = f[2].n > 0 && f[2].n < 12 && span_copy(f[2], num, sizeof num) == 0;
    for (size_t i = 0; digits && i < f[2].n; i++) digits = num[i] >= '0' && num[i] <= '9';
    if (!digits)
        return bad(ps, f[2].col, WW_E_TYPE, "frame wants a whole frame number (0, 1, ...), got '%s'", f[2].p,
                   f[2].n);
    s->frame = strtoll(num, NULL, 10);
    if (f[3].n == 0) return bad(ps, f[3].col, WW_E_MISSING, "no caption: say what to look at%s", "", 0);
    if (span_copy(f[3], s->caption, sizeof s->caption) != 0)
        return bad(ps, f[3].col, WW_E_RANGE, "caption longer than 399 characters: '%s..'", f[3].p, f[3].n);
    return nf == FIELDS ? parse_options(ps, line, f[4], s) : WW_OK;
}

ww_result ww_review_parse(const char *path, const char *text, size_t len, ww_review_list *out,
                          ww_error *err) {
    memset(out, 0, sizeof *out);
    snprintf(out->path, sizeof out->path, "%s", path);
    out->shots = calloc(WW_REVIEW_MAX_SHOTS, sizeof *out->shots);
    if (!out->shots) return ww_error_set(err, WW_E_NOMEM, path, 0, 0, "out of memory for the review list");
    parser ps = {path, 0, err};
    int w = WW_REVIEW_DEFAULT_W, h = WW_REVIEW_DEFAULT_H;
    ww_result r = WW_OK;
    for (const char *p = text, *end = text + len; p < end && !r;) {
        const char *e = memchr(p, '\n', (size_t)(end - p));
        if (!e) e = end;
        ps.line++;
        span all = trim(p, p, e);
        if (memchr(p, 0, (size_t)(e - p))) {
            r = bad(&ps, 1, WW_E_SYNTAX, "a NUL byte in the list%s", "", 0);
        } else if (all.n == 0 || all.p[0] == '#') {
            /* blank or comment */
        } else if (all.n >= 5 && memcmp(all.p, "size:", 5) == 0) {
            span v = trim(p, all.p + 5, all.p + all.n);
            if (parse_size(v, &w, &h) != 0)
                r = bad(&ps, v.col, WW_E_RANGE, "size: wants WIDTHxHEIGHT (each 16..16384), got '%s'", v.p, v.n);
        } else if (out->n >= WW_REVIEW_MAX_SHOTS) {
            r = bad(&ps, all.col, WW_E_RANGE, "more than 256 shots%s", "", 0);
        } else if (!(r = parse_shot(&ps, p, e, w, h, &out->shots[out->n]))) {
            ww_review_shot *s = &out->shots[out->n];
            for (int i = 0; i < out->n && !r; i++)
                if (strcmp(out->shots[i].name, s->name) == 0)
                    r = ww_error_set(err, WW_E_DUPLICATE_KEY, path, ps.line, all.col,
                                     "shot name '%s' already used on line %d", s->name, out->shots[i].line);
            out->n++;
        }
        p = e + 1;
    }
    if (!r && out->n == 0) r = ww_error_set(err, WW_E_EMPTY, path, 0, 0, "the review list holds no shot");
    if (r) ww_review_free(out);
    return r;
}

ww_result ww_review_load(const char *path, ww_review_list *out, ww_error *err) {
    unsigned char *data = NULL;
    size_t len = 0;
    memset(out, 0, sizeof *out);
    ww_result r = ww_file_read_max(path, LIST_MAX_BYTES, LIST_MAX_BYTES, &data, &len, err);
    if (r) return r;
    r = ww_review_parse(path, (const char *)data, len, out, err);
    free(data);
    return r;
}

ww_result ww_review_check(ww_review_list *l, ww_error *err) {
    for (int i = 0; i < l->n; i++) {
        ww_review_shot *s = &l->shots[i];
        ww_set sets[WW_REVIEW_MAX_SETS];
        for (int k = 0; k < s->nsets; k++) sets[k].text = s->sets[k];
        ww_scene *sc = NULL;
        ww_error e = {0};
        ww_result r = ww_scene_load_with_script(s->scene, s->script[0] ? s->script : NULL, sets, s->nsets,
                                                &sc, &e);
        if (r) {
            char place[300] = "";
            if (e.file[0] && e.line > 0) snprintf(place, sizeof place, "%s:%d:%d: ", e.file, e.line, e.column);
            else if (e.file[0]) snprintf(place, sizeof place, "%s: ", e.file);
            return ww_error_set(err, r, l->path, s->line, 1, "shot '%s': %s%s", s->name, place, e.msg);
        }
        long long count = (long long)sc->frame_count;
        s->t = sc->start + (double)s->frame / sc->fps;
        ww_scene_free(sc);
        if (s->frame >= count)
            return ww_error_set(err, WW_E_RANGE, l->path, s->line, 1,
                                "shot '%s': frame %lld is past %s's %lld frames", s->name, s->frame,
                                s->scene, count);
        s->checked = 1;
    }
    return WW_OK;
}

void ww_review_free(ww_review_list *l) {
    free(l->shots);
    l->shots = NULL;
    l->n = 0;
}

/* ---- the sheet and the page ---------------------------------------------------------------- */

void ww_review_shot_path(const char *dir, const ww_review_shot *s, char *out, size_t cap) {
    snprintf(out, cap, "%s/shots/%s.png", dir, s->name);
}

/* append up to max_chars of text, broken at the last space that fits */
static const char *wrap_line(const char *text, int max_chars, char *out, size_t cap) {
    size_t n = strlen(text), limit = max_chars > 0 ? (size_t)max_chars : n;
    if (n <= limit) {
        snprintf(out, cap, "%s", text);
        return text + n;
    }
    size_t cut = limit;
    while (cut > limit / 2 && text[cut] != ' ') cut--;
    if (text[cut] != ' ') cut = limit;
    snprintf(out, cap, "%.*s", (int)cut, text);
    while (text[cut] == ' ') cut++;
    return text + cut;
}

void ww_review_label(const ww_review_shot *s, int i, int max_chars, char *out, size_t cap) {
    char head[600], t[40] = "", l2[WW_REVIEW_TEXT_MAX + 1], l3[WW_REVIEW_TEXT_MAX + 1], opts[1200] = "";
    if (s->checked) snprintf(t, sizeof t, ", t=%.2f s", s->t);
    snprintf(head, sizeof head, "%02d %s: %s frame %lld%s", i + 1, s->name, s->scene, s->frame, t);
    const char *rest = wrap_line(s->caption, max_chars, l2, sizeof l2);
    wrap_line(rest, 0, l3, sizeof l3);
    size_t n = 0;
    for (int k = 0; k < s->nsets && n < sizeof opts; k++) {
        int w = snprintf(opts + n, sizeof opts - n, "%s%s", k ? " " : "", s->sets[k]);
        n += w > 0 ? (size_t)w : 0;
    }
    if (s->script[0] && n < sizeof opts) snprintf(opts + n, sizeof opts - n, "%sscript %s", n ? " " : "", s->script);
    snprintf(out, cap, "%s\n%s\n%s\n%s", head, l2, l3, opts);
}

ww_result ww_review_sheet(const ww_review_list *l, const char *dir, const ww_review_sheet_opts *o,
                          int *missing, ww_error *err) {
    int cols = o && o->cols > 0 ? o->cols : 4;
    int tw = o && o->thumb_w > 0 ? o->thumb_w : 480, th = o && o->thumb_h > 0 ? o->thumb_h : 270;
    ww_contact_layout L;
    *missing = 0;
    if (ww_contact_plan(l->n, cols, tw, th, WW_REVIEW_LABEL_LINES, &L) != 0)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "a %dx%d contact sheet is over %d px on a side",
                            L.width, L.height, WW_CONTACT_MAX_SIDE);
    ww_image sheet = {0};
    if (ww_contact_new(&L, &sheet) != 0)
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory for a %dx%d contact sheet", L.width,
                            L.height);
    /* stb_easy_font's glyphs are about 6 px wide */
    int chars = tw / 6;
    for (int i = 0; i < l->n; i++) {
        char path[1100], label[2400];
        ww_review_shot_path(dir, &l->shots[i], path, sizeof path);
        ww_image frame = {0}, thumb = {0};
        ww_error e = {0};
        int have = ww_read_png(path, &frame, &e) == WW_OK && frame.type == WW_PIX_U8 && frame.channels >= 3;
        if (have && ww_contact_fit(&frame, tw, th, &thumb) != 0) have = 0;
        *missing += !have;
        ww_review_label(&l->shots[i], i, chars, label, sizeof label);
        ww_contact_put(&sheet, &L, i, have ? &thumb : NULL, label);
        ww_image_free(&frame);
        ww_image_free(&thumb);
    }
    char path[1100];
    snprintf(path, sizeof path, "%s/review.png", dir);
    ww_result r = ww_write_png(path, &sheet, err);
    ww_image_free(&sheet);
    return r;
}

static void html_text(FILE *f, const char *s) {
    for (; *s; s++) {
        switch (*s) {
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '&': fputs("&amp;", f); break;
        case '"': fputs("&quot;", f); break;
        default: fputc(*s, f);
        }
    }
}

static const char page_head[] =
    "<!DOCTYPE html>\n"
    "<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>waterworld review</title>\n"
    "<style>\n"
    "body { background: #18181c; color: #e8e8e8; font: 14px/1.4 sans-serif; margin: 16px; }\n"
    "a { color: #9cf; }\n"
    ".grid { display: grid; grid-template-columns: repeat(auto-fill, minmax(480px, 1fr)); gap: 16px; }\n"
    "figure { margin: 0; }\n"
    "figure img { width: 100%; height: auto; display: block; background: #333; }\n"
    ".missing { background: #462828; padding: 40px; text-align: center; }\n"
    "figcaption { margin-top: 4px; }\n"
    "code { color: #bbb; }\n"
    "</style>\n</head>\n<body>\n";

ww_result ww_review_html(const ww_review_list *l, const char *dir, ww_error *err) {
    char path[1100];
    snprintf(path, sizeof path, "%s/index.html", dir);
    ww_stream st;
    ww_result r = ww_stream_open(&st, path, err);
    if (r) return r;
    FILE *f = st.f;
    fputs(page_head, f);
    fputs("<h1>waterworld review</h1>\n<p>", f);
    fprintf(f, "%d shots from <code>", l->n);
    html_text(f, l->path);
    fputs("</code>; all of them on one page: <a href=\"review.png\">review.png</a>.</p>\n"
          "<div class=\"grid\">\n", f);
    for (int i = 0; i < l->n; i++) {
        const ww_review_shot *s = &l->shots[i];
        char img[1100];
        ww_review_shot_path(dir, s, img, sizeof img);
        FILE *probe = fopen(img, "rb");
        fputs("<figure id=\"", f);
        html_text(f, s->name);
        fputs("\">\n", f);
        if (probe) {
            fclose(probe);
            fprintf(f, "<a href=\"shots/%s.png\"><img src=\"shots/%s.png\" width=\"%d\" height=\"%d\" alt=\"",
                    s->name, s->name, s->width, s->height);
            html_text(f, s->caption);
            fputs("\"></a>\n", f);
        } else {
            fputs("<div class=\"missing\">no image</div>\n", f);
        }
        fprintf(f, "<figcaption><b>%02d %s</b>: <code>", i + 1, s->name);
        html_text(f, s->scene);
        fprintf(f, "</code> frame %lld", s->frame);
        if (s->checked) fprintf(f, ", t = %.2f s", s->t);
        fprintf(f, ", %dx%d<br>\n", s->width, s->height);
        html_text(f, s->caption);
        if (s->nsets || s->script[0]) {
            fputs("<br>\n<code>", f);
            for (int k = 0; k < s->nsets; k++) {
                fputs("--set ", f);
                html_text(f, s->sets[k]);
                fputc(' ', f);
            }
            if (s->script[0]) {
                fputs("--script ", f);
                html_text(f, s->script);
            }
            fputs("</code>", f);
        }
        fputs("</figcaption>\n</figure>\n", f);
    }
    fputs("</div>\n</body>\n</html>\n", f);
    return ww_stream_commit(&st, err);
}
