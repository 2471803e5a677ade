/* golden.c - `render --golden DIR`: each rendered frame against its golden (per renderer key,
 * then the scene's fallback keys, then DIR itself), the diff and a copy of the golden for every
 * failure, and a self-contained HTML report (inline CSS, relative links, no script).
 */
#include "check/golden.h"

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "io/stream.h"
#include "io/writers.h"

#define FAMILY_SIZE 24     /* the renderer family's part of a key */
#define PATH_SIZE 600
#define WHY_SIZE 400
#define SOURCE_SIZE 96

typedef enum frame_status { FRAME_PASS, FRAME_FAIL, FRAME_MISSING } frame_status;

/* one frame's outcome, kept for the report */
typedef struct frame_check {
    int64_t frame;
    frame_status status;
    int measured;               /* res holds metrics (both images loaded, same size) */
    ww_cmp_result res;
    char golden[PATH_SIZE];     /* the golden used; for a missing one, the paths tried */
    char source[SOURCE_SIZE];   /* which candidate it was: the key, "fallback KEY", "flat" */
    char why[WHY_SIZE];         /* the rule that failed, or why no comparison was possible */
} frame_check;

/* ---- renderer keys ------------------------------------------------------------------------- */

/* the first run of letters and digits of s, lowercased */
static void first_word(const char *s, char *out, size_t cap) {
    size_t n = 0;
    while (*s && !isalnum((unsigned char)*s)) s++;
    while (*s && isalnum((unsigned char)*s) && n + 1 < cap) out[n++] = (char)tolower((unsigned char)*s++);
    out[n] = 0;
}

void ww_golden_renderer_key(const char *renderer, const char *gl_version, char *out, size_t cap) {
    const char *r = renderer ? renderer : "", *v = gl_version ? gl_version : "";
    if (strncasecmp(r, "mesa ", 5) == 0) r += 5; /* "Mesa Intel(R) UHD Graphics 620" */
    char family[FAMILY_SIZE];
    first_word(r, family, sizeof family);
    if (!family[0]) snprintf(family, sizeof family, "unknown");
    const char *m;
    int major, minor;
    if ((m = strstr(v, "Mesa ")) && sscanf(m + 5, "%d.%d", &major, &minor) == 2)
        snprintf(out, cap, "%s-mesa-%d.%d", family, major, minor);
    else if ((m = strstr(v, "NVIDIA ")) && sscanf(m + 7, "%d", &major) == 1)
        snprintf(out, cap, "nvidia-%d", major);
    else if (sscanf(v, "%d.%d", &major, &minor) == 2)
        snprintf(out, cap, "%s-gl-%d.%d", family, major, minor);
    else
        snprintf(out, cap, "%s", family);
}

/* ---- thresholds ---------------------------------------------------------------------------- */

ww_cmp_opts ww_golden_scene_opts(const ww_scene *sc) {
    ww_cmp_opts o = ww_cmp_default_opts();
    const ww_golden_desc *g = &sc->golden;
    if (g->has & WW_GOLDEN_HAS_THRESHOLD) o.threshold = g->threshold;
    if (g->has & WW_GOLDEN_HAS_YIQ) o.yiq = g->yiq;
    if (g->has & WW_GOLDEN_HAS_AA) o.detect_aa = g->aa;
    if (g->has & WW_GOLDEN_HAS_MAX) o.max = g->max;
    if (g->has & WW_GOLDEN_HAS_FAIL_PERCENT) o.fail_percent = g->fail_percent;
    if (g->has & WW_GOLDEN_HAS_FAIL_PIXELS) o.fail_pixels = (long)g->fail_pixels;
    if (g->has & WW_GOLDEN_HAS_PSNR_MIN) o.psnr_min = g->psnr_min;
    if (g->has & WW_GOLDEN_HAS_YIQ_PIXELS) o.yiq_pixels = g->yiq_pixels;
    if (g->has & WW_GOLDEN_HAS_SSIM_MIN) o.ssim_min = g->ssim_min;
    return o;
}

static int any_rule(const ww_cmp_opts *o) {
    return o->max >= 0 || o->fail_percent >= 0 || o->fail_pixels >= 0 || o->psnr_min >= 0 ||
           o->yiq_pixels >= 0 || o->ssim_min >= 0 || o->rel_max >= 0;
}

/* one pass/fail rule as the report shows it: the limit, what was measured, whether it held */
typedef struct rule_row {
    const char *name;
    double limit, value;
    int ok;
} rule_row;

static int rule_rows(const ww_cmp_opts *o, const ww_cmp_result *r, rule_row rows[7]) {
    int n = 0;
    if (o->max >= 0) rows[n++] = (rule_row){"max", o->max, r->max_abs, r->max_abs <= o->max};
    if (o->fail_percent >= 0)
        rows[n++] = (rule_row){"fail_percent", o->fail_percent, r->diff_percent,
                               r->diff_percent <= o->fail_percent};
    if (o->fail_pixels >= 0)
        rows[n++] = (rule_row){"fail_pixels", (double)o->fail_pixels, (double)r->diff_pixels,
                               r->diff_pixels <= o->fail_pixels};
    if (o->psnr_min >= 0)
        rows[n++] = (rule_row){"psnr_min", o->psnr_min, r->psnr, r->psnr >= o->psnr_min};
    if (o->yiq_pixels >= 0)
        rows[n++] = (rule_row){"yiq_pixels", o->yiq_pixels, (double)r->yiq_pixels,
                               (double)r->yiq_pixels <= o->yiq_pixels};
    if (o->ssim_min >= 0)
        rows[n++] = (rule_row){"ssim_min", o->ssim_min, r->ssim, r->ssim >= o->ssim_min};
    if (n == 0) /* compare's rule when none is given */
        rows[n++] = (rule_row){"no pixel over threshold", 0, (double)r->diff_pixels,
                               r->diff_pixels == 0};
    return n;
}

/* ---- files --------------------------------------------------------------------------------- */

static int is_dir(const char *path) {
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

static int is_file(const char *path) {
    struct stat st;
    return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

/* path is dir or lies inside it (path need not exist yet: its nearest existing ancestor is
 * resolved) */
static int inside_dir(const char *path, const char *dir) {
    char d[PATH_MAX], p[PATH_MAX], probe[PATH_SIZE];
    if (!realpath(dir, d)) return 0;
    snprintf(probe, sizeof probe, "%s", path);
    while (!is_dir(probe)) {
        char *slash = strrchr(probe, '/');
        if (!slash) {
            snprintf(probe, sizeof probe, ".");
            break;
        }
        *slash = 0;
        if (!probe[0]) snprintf(probe, sizeof probe, "/");
    }
    if (!realpath(probe, p)) return 0;
    size_t n = strlen(d);
    return strncmp(p, d, n) == 0 && (p[n] == 0 || p[n] == '/' || n == 1);
}

static ww_result path_join(char *out, size_t cap, const char *dir, const char *sub,
                           const char *name, ww_error *err) {
    int n = sub ? snprintf(out, cap, "%s/%s/%s", dir, sub, name)
                : snprintf(out, cap, "%s/%s", dir, name);
    if (n < 0 || (size_t)n >= cap)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "path too long: %s/%s/%s", dir,
                            sub ? sub : "", name);
    return WW_OK;
}

static ww_result copy_file(const char *from, const char *to, ww_error *err) {
    unsigned char *data = NULL;
    size_t len = 0;
    ww_result r = ww_read_file(from, &data, &len, err);
    if (!r) r = ww_write_file_atomic(to, data, len, err);
    free(data);
    return r;
}

/* the two files hold the same bytes */
static int same_bytes(const char *a, const char *b) {
    unsigned char *da = NULL, *db = NULL;
    size_t la = 0, lb = 0;
    int same = ww_read_file(a, &da, &la, NULL) == WW_OK && ww_read_file(b, &db, &lb, NULL) == WW_OK &&
               la == lb && memcmp(da, db, la) == 0;
    free(da);
    free(db);
    return same;
}

/* the folder of path (diff/, expected/), made when missing */
static ww_result make_parent(const char *path, ww_error *err) {
    char dir[PATH_SIZE];
    snprintf(dir, sizeof dir, "%s", path);
    char *slash = strrchr(dir, '/');
    if (!slash) return WW_OK;
    *slash = 0;
    return is_dir(dir) ? WW_OK : ww_make_dirs(dir, err);
}

/* a stale diff or expected copy of a frame that now passes */
static ww_result remove_stale(const char *path, ww_error *err) {
    if (unlink(path) == 0 || errno == ENOENT) return WW_OK;
    return ww_error_set(err, WW_E_IO, path, 0, 0, "cannot remove the stale %s: %s", path,
                        strerror(errno));
}

ww_result ww_golden_prepare(const ww_golden_opts *o, ww_error *err) {
    if (!o->golden_dir || !is_dir(o->golden_dir))
        return ww_error_set(err, WW_E_NOFILE, o->golden_dir, 0, 0,
                            "--golden %s: no such folder (bless the goldens first: waterworld "
                            "render SCENE -o %s)",
                            o->golden_dir ? o->golden_dir : "", o->golden_dir ? o->golden_dir : "DIR");
    if (o->out_dir && inside_dir(o->out_dir, o->golden_dir))
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            "the output folder %s lies in --golden %s: rendering would overwrite "
                            "the goldens (give another -o)",
                            o->out_dir, o->golden_dir);
    return WW_OK;
}

/* ---- one frame ----------------------------------------------------------------------------- */

/* the first candidate golden that exists; 0 (and the paths tried in f->golden) when none.
 * Folders in order: the renderer key, the scene's fallback keys, DIR itself; in each, the
 * frame-numbered file (frame_00012.png, what `render -o DIR` writes), then for frame 0 the
 * scene's own name (NAME.png for scenes/.../NAME.yaml: the project's single-frame goldens,
 * golden/features/fog.png, as `make golden` files them) */
static int find_golden(const ww_scene *sc, const ww_golden_opts *o, const char *key,
                       const char *name, frame_check *f) {
    const ww_golden_desc *g = &sc->golden;
    char path[PATH_SIZE], single[sizeof sc->name + 8];
    snprintf(single, sizeof single, "%s.png", sc->name);
    int names = f->frame == 0 && sc->name[0] ? 2 : 1;
    for (int i = -1; i <= g->nfallback; i++) {
        const char *sub = i < 0 ? key : i < g->nfallback ? g->fallback[i] : NULL;
        for (int k = 0; k < names; k++) {
            if (path_join(path, sizeof path, o->golden_dir, sub, k ? single : name, NULL)) continue;
            if (is_file(path)) {
                snprintf(f->golden, sizeof f->golden, "%s", path);
                if (i < 0) snprintf(f->source, sizeof f->source, "%s", key);
                else if (sub) snprintf(f->source, sizeof f->source, "fallback %s", sub);
                else snprintf(f->source, sizeof f->source, "flat");
                return 1;
            }
            size_t used = strlen(f->golden);
            snprintf(f->golden + used, sizeof f->golden - used, "%s%s", used ? ", " : "", path);
        }
    }
    return 0;
}

/* compare frame f->frame; only I/O on the output folder is an error, everything about the
 * golden is the frame's outcome */
static ww_result check_frame(const ww_scene *sc, const ww_golden_opts *o, const ww_cmp_opts *cmp,
                             const char *key, frame_check *f, ww_error *err) {
    char name[32], actual[PATH_SIZE], diff[PATH_SIZE], expected[PATH_SIZE];
    snprintf(name, sizeof name, "frame_%05lld.png", (long long)f->frame);
    ww_result r = path_join(actual, sizeof actual, o->out_dir, NULL, name, err);
    if (!r) r = path_join(diff, sizeof diff, o->out_dir, "diff", name, err);
    if (!r) r = path_join(expected, sizeof expected, o->out_dir, "expected", name, err);
    if (r) return r;

    f->status = FRAME_FAIL;
    if (!find_golden(sc, o, key, name, f)) {
        f->status = FRAME_MISSING;
        snprintf(f->why, sizeof f->why, "no golden image");
        if (!(r = remove_stale(diff, err))) r = remove_stale(expected, err);
        return r;
    }
    /* llvmpipe gives the same bytes run after run: equal files pass without decoding */
    if (same_bytes(f->golden, actual)) {
        f->status = FRAME_PASS;
        f->measured = 1;
        f->res = (ww_cmp_result){.identical = 1, .psnr = INFINITY, .ssim = 1, .pass = 1};
        if (!(r = remove_stale(diff, err))) r = remove_stale(expected, err);
        return r;
    }
    ww_cmp_image a = {0}, b = {0};
    ww_error e = {0};
    /* both decoded and measured at once; after a failure, one by one to tell whose it was */
    int measured = ww_cmp_pair(f->golden, actual, cmp, &a, &b, &f->res, &e) == WW_OK;
    if (!measured && (r = ww_cmp_load(actual, &b, err))) goto done; /* just rendered: an error */
    if (!measured && ww_cmp_load(f->golden, &a, &e)) {
        snprintf(f->why, sizeof f->why, "unreadable golden: %.300s", e.msg);
    } else if (!measured && ww_cmp_images(&a, &b, cmp, &f->res, &e)) {
        snprintf(f->why, sizeof f->why, "not comparable: %.300s", e.msg);
    } else {
        f->measured = 1;
        if (f->res.pass) f->status = FRAME_PASS;
        else snprintf(f->why, sizeof f->why, "%s", f->res.why[0] ? f->res.why : "a rule failed");
    }
    if (f->status == FRAME_PASS) {
        if (!(r = remove_stale(diff, err))) r = remove_stale(expected, err);
        goto done;
    }
    if ((r = make_parent(diff, err)) || (r = make_parent(expected, err))) goto done;
    if (f->measured && (r = ww_cmp_write_diff(diff, &a, &b, cmp, err))) goto done;
    if (!f->measured && (r = remove_stale(diff, err))) goto done;
    r = copy_file(f->golden, expected, err);
done:
    ww_cmp_image_free(&a);
    ww_cmp_image_free(&b);
    return r;
}

/* ---- the report ---------------------------------------------------------------------------- */

static const char css[] =
    "body{font:14px/1.4 sans-serif;margin:16px;color:#222;background:#fff}"
    "h1{padding:8px 12px;color:#fff;font-size:20px}"
    ".pass{background:#2e7d32}.fail{background:#b71c1c}"
    "table{border-collapse:collapse;margin:8px 0}"
    "th,td{border:1px solid #bbb;padding:2px 8px;text-align:left;vertical-align:top}"
    "th{background:#eceff1}td.num{text-align:right;font-family:monospace}"
    "td.bad{background:#ffcdd2}td.ok{background:#c8e6c9}"
    ".frame{border:1px solid #bbb;margin:12px 0;padding:8px}"
    ".frame h3{margin:0 0 4px 0}.why{font-weight:bold;color:#b71c1c}"
    ".trio{display:grid;grid-template-columns:repeat(3,1fr);gap:8px}"
    "figure{margin:0}figure img{width:100%;image-rendering:pixelated;border:1px solid #888}"
    "figcaption{text-align:center}code{background:#f5f5f5}"
    ".tables{display:flex;flex-wrap:wrap;gap:16px;align-items:flex-start}";

/* s as HTML text or attribute value */
static void html(FILE *f, const char *s) {
    for (; *s; s++) {
        switch (*s) {
        case '&': fputs("&amp;", f); break;
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '"': fputs("&quot;", f); break;
        case '\'': fputs("&#39;", f); break;
        default: fputc(*s, f);
        }
    }
}

static void num(FILE *f, double v) {
    if (isinf(v)) fputs(v > 0 ? "inf" : "-inf", f);
    else fprintf(f, "%.6g", v);
}

static void row_text(FILE *f, const char *name, const char *value) {
    fprintf(f, "<tr><th>%s</th><td>", name);
    html(f, value);
    fputs("</td></tr>\n", f);
}

/* the thresholds in the words of the options that set them */
static void describe_opts(const ww_cmp_opts *o, int exact, char *out, size_t cap) {
    int n = snprintf(out, cap, "per-pixel threshold %g, yiq %g, anti-aliasing %s; rules:",
                     o->threshold, o->yiq, o->detect_aa ? "detected" : "counted");
    const struct { const char *name; double v; } rules[] = {
        {"max", o->max}, {"fail_percent", o->fail_percent}, {"fail_pixels", (double)o->fail_pixels},
        {"psnr_min", o->psnr_min}, {"yiq_pixels", o->yiq_pixels}, {"ssim_min", o->ssim_min},
        {"rel_max", o->rel_max}};
    for (size_t i = 0; i < sizeof rules / sizeof rules[0]; i++) {
        if (rules[i].v < 0 || n < 0 || (size_t)n >= cap) continue;
        n += snprintf(out + n, cap - (size_t)n, " %s %g", rules[i].name, rules[i].v);
    }
    if (exact && n >= 0 && (size_t)n < cap)
        snprintf(out + n, cap - (size_t)n, " none given, so no pixel may differ by more than the "
                 "threshold (%g: %s)", o->threshold, o->threshold > 0 ? "near match" : "exact match");
}

static void write_metrics(FILE *f, const frame_check *c, const ww_cmp_opts *o) {
    const ww_cmp_result *r = &c->res;
    fputs("<div class=\"tables\"><table class=\"metrics\"><tr><th>metric</th><th>value</th></tr>\n", f);
    const struct { const char *name; double v; } m[] = {
        {"max abs difference (8-bit levels)", r->max_abs},
        {"mean abs difference (8-bit levels)", r->mean_abs},
        {"RMSE (normalised, as ImageMagick)", r->rmse},
        {"PSNR (dB)", r->psnr},
        {"pixels over threshold", (double)r->diff_pixels},
        {"pixels over threshold (%)", r->diff_percent},
        {"pixels over the YIQ threshold (pixelmatch)", (double)r->yiq_pixels},
        {"of which anti-aliasing (not counted)", (double)r->aa_pixels},
        {"SSIM (mean, luma)", r->ssim}};
    for (size_t i = 0; i < sizeof m / sizeof m[0]; i++) {
        fprintf(f, "<tr><td>%s</td><td class=\"num\">", m[i].name);
        num(f, m[i].v);
        fputs("</td></tr>\n", f);
    }
    fputs("</table>\n<table class=\"rules\"><tr><th>rule</th><th>limit</th><th>measured</th>"
          "<th>result</th></tr>\n", f);
    rule_row rows[7];
    int n = rule_rows(o, r, rows);
    for (int i = 0; i < n; i++) {
        fprintf(f, "<tr><td>%s</td><td class=\"num\">", rows[i].name);
        num(f, rows[i].limit);
        fputs("</td><td class=\"num\">", f);
        num(f, rows[i].value);
        fprintf(f, "</td><td class=\"%s\">%s</td></tr>\n", rows[i].ok ? "ok" : "bad",
                rows[i].ok ? "holds" : "FAILS");
    }
    fputs("</table></div>\n", f);
}

static void write_failed(FILE *f, const frame_check *c, const ww_cmp_opts *o) {
    char name[32];
    snprintf(name, sizeof name, "frame_%05lld.png", (long long)c->frame);
    fprintf(f, "<section class=\"frame\" id=\"%s\"><h3>%s</h3>\n<p class=\"why\">failed: ", name,
            name);
    html(f, c->why);
    fputs("</p>\n<p>golden: <code>", f);
    html(f, c->golden);
    fputs("</code> (", f);
    html(f, c->source);
    fputs(")</p>\n<div class=\"trio\">\n", f);
    const struct { const char *dir, *caption; int shown; } fig[] = {
        {"expected/", "golden", 1}, {"", "actual", 1},
        {"diff/", "diff (red: differs, yellow: anti-aliasing)", c->measured}};
    for (size_t i = 0; i < 3; i++) {
        if (!fig[i].shown) {
            fputs("<figure><figcaption>no diff: the images cannot be compared</figcaption>"
                  "</figure>\n", f);
            continue;
        }
        fprintf(f, "<figure><a href=\"%s%s\"><img src=\"%s%s\" alt=\"%s\"></a>"
                   "<figcaption>%s</figcaption></figure>\n",
                fig[i].dir, name, fig[i].dir, name, fig[i].caption, fig[i].caption);
    }
    fputs("</div>\n", f);
    if (c->measured) write_metrics(f, c, o);
    fputs("</section>\n", f);
}

static void write_passed(FILE *f, const frame_check *fr, int64_t n, int64_t passed) {
    fprintf(f, "<details><summary>%lld passed frames</summary>\n<table><tr><th>frame</th>"
               "<th>golden</th><th>from</th><th>max</th><th>PSNR (dB)</th><th>SSIM</th></tr>\n",
            (long long)passed);
    for (int64_t i = 0; i < n; i++) {
        const frame_check *c = &fr[i];
        if (c->status != FRAME_PASS) continue;
        fprintf(f, "<tr><td><a href=\"frame_%05lld.png\">%05lld</a></td><td><code>",
                (long long)c->frame, (long long)c->frame);
        html(f, c->golden);
        fputs("</code></td><td>", f);
        html(f, c->source);
        if (c->res.identical) {
            fputs("</td><td colspan=\"3\">identical</td></tr>\n", f);
            continue;
        }
        fputs("</td><td class=\"num\">", f);
        num(f, c->res.max_abs);
        fputs("</td><td class=\"num\">", f);
        num(f, c->res.psnr);
        fputs("</td><td class=\"num\">", f);
        num(f, c->res.ssim);
        fputs("</td></tr>\n", f);
    }
    fputs("</table></details>\n", f);
}

typedef struct report_in {
    const ww_scene *sc;
    const ww_golden_opts *o;
    const ww_cmp_opts *cmp;
    int exact;
    const frame_check *frames;
    const ww_golden_summary *s;
} report_in;

static void write_report(FILE *f, const report_in *in) {
    const ww_golden_summary *s = in->s;
    int ok = s->failed == 0 && s->missing == 0;
    char line[1024];
    snprintf(line, sizeof line, "%s: %lld frames, %lld passed, %lld failed, %lld missing",
             ok ? "PASS" : "FAIL", (long long)s->frames, (long long)s->passed,
             (long long)s->failed, (long long)s->missing);
    fputs("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>golden ", f);
    html(f, in->sc->name);
    fprintf(f, ": %s</title>\n<style>%s</style></head><body>\n<h1 class=\"%s\">", ok ? "PASS" : "FAIL",
            css, ok ? "pass" : "fail");
    html(f, line);
    fputs("</h1>\n<table class=\"summary\">\n", f);
    snprintf(line, sizeof line, "%s (%s)", in->sc->name, in->sc->path);
    row_text(f, "scene", line);
    snprintf(line, sizeof line, "%s | %s", in->o->renderer ? in->o->renderer : "",
             in->o->gl_version ? in->o->gl_version : "");
    row_text(f, "renderer", line);
    row_text(f, "renderer key", s->key);
    row_text(f, "goldens from", s->golden_dir);
    describe_opts(in->cmp, in->exact, line, sizeof line);
    row_text(f, "thresholds", line);
    snprintf(line, sizeof line, "%lld..%lld", (long long)in->o->first, (long long)in->o->last - 1);
    row_text(f, "frames", line);
    fputs("</table>\n", f);
    int64_t n = s->frames;
    if (s->failed) fputs("<h2>Failed frames</h2>\n", f);
    for (int64_t i = 0; i < n; i++)
        if (in->frames[i].status == FRAME_FAIL) write_failed(f, &in->frames[i], in->cmp);
    if (s->missing) fputs("<h2>Frames without a golden</h2>\n<ul>\n", f);
    for (int64_t i = 0; i < n; i++) {
        const frame_check *c = &in->frames[i];
        if (c->status != FRAME_MISSING) continue;
        fprintf(f, "<li class=\"missing-frame\"><a href=\"frame_%05lld.png\">frame_%05lld.png</a>:"
                   " none of <code>", (long long)c->frame, (long long)c->frame);
        html(f, c->golden);
        fputs("</code></li>\n", f);
    }
    if (s->missing) fputs("</ul>\n", f);
    if (s->passed) write_passed(f, in->frames, n, s->passed);
    fputs("</body></html>\n", f);
}

/* ---- the check ----------------------------------------------------------------------------- */

/* "DIR/KEY" when every golden came from one folder, else each folder with its count */
static void summarise_sources(const frame_check *fr, int64_t n, char *out, size_t cap) {
    out[0] = 0;
    size_t used = 0;
    for (int64_t i = 0; i < n; i++) {
        if (fr[i].status == FRAME_MISSING) continue;
        const char *slash = strrchr(fr[i].golden, '/');
        int len = slash ? (int)(slash - fr[i].golden) : 0;
        int seen = 0;
        for (int64_t k = 0; k < i && !seen; k++) {
            const char *sk = strrchr(fr[k].golden, '/');
            seen = fr[k].status != FRAME_MISSING && sk && (int)(sk - fr[k].golden) == len &&
                   strncmp(fr[k].golden, fr[i].golden, (size_t)len) == 0;
        }
        if (seen) continue;
        long count = 0;
        for (int64_t k = i; k < n; k++) {
            const char *sk = strrchr(fr[k].golden, '/');
            count += fr[k].status != FRAME_MISSING && sk && (int)(sk - fr[k].golden) == len &&
                     strncmp(fr[k].golden, fr[i].golden, (size_t)len) == 0;
        }
        if (used + 1 >= cap) break;
        int w = snprintf(out + used, cap - used, "%s%.*s (%ld frame%s)", used ? ", " : "", len,
                         fr[i].golden, count, count == 1 ? "" : "s");
        used = w < 0 ? cap : used + (size_t)w < cap ? used + (size_t)w : cap - 1;
    }
    if (!out[0]) snprintf(out, cap, "none found");
}

static void log_frame(FILE *log, const frame_check *c, const char *out_dir) {
    if (!log || c->status == FRAME_PASS) return;
    if (c->status == FRAME_MISSING)
        fprintf(log, "golden: frame %05lld MISSING: no golden (looked for %s)\n",
                (long long)c->frame, c->golden);
    else
        fprintf(log, "golden: frame %05lld FAILED: %s (golden %s; diff %s/diff/frame_%05lld.png)\n",
                (long long)c->frame, c->why, c->golden, out_dir, (long long)c->frame);
}

ww_result ww_golden_check(const ww_scene *sc, const ww_golden_opts *o, ww_golden_summary *s,
                          ww_error *err) {
    *s = (ww_golden_summary){0};
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    ww_golden_renderer_key(o->renderer, o->gl_version, s->key, sizeof s->key);
    ww_result r = ww_golden_prepare(o, err);
    if (r) return r;
    WW_ASSERT(o->last >= o->first && o->out_dir);
    if ((r = path_join(s->report, sizeof s->report, o->out_dir, NULL, "report.html", err)))
        return r;
    int64_t n = o->last - o->first;
    frame_check *fr = n > 0 ? calloc((size_t)n, sizeof *fr) : NULL;
    if (n > 0 && !fr)
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory for %lld frames",
                            (long long)n);
    /* no rule at all: compare's default, no pixel over the per-pixel threshold */
    ww_cmp_opts cmp = o->cmp;
    int exact = !any_rule(&cmp);
    if (o->log) fprintf(o->log, "golden: renderer key %s (%s | %s)\n", s->key,
                        o->renderer ? o->renderer : "", o->gl_version ? o->gl_version : "");

    s->frames = n;
    for (int64_t i = 0; i < n && !r; i++) {
        fr[i].frame = o->first + i;
        r = check_frame(sc, o, &cmp, s->key, &fr[i], err);
        s->passed += fr[i].status == FRAME_PASS;
        s->failed += fr[i].status == FRAME_FAIL;
        s->missing += fr[i].status == FRAME_MISSING;
        if (!r) log_frame(o->log, &fr[i], o->out_dir);
    }
    if (!r) {
        summarise_sources(fr, n, s->golden_dir, sizeof s->golden_dir);
        ww_stream st;
        report_in in = {sc, o, &cmp, exact, fr, s};
        if (!(r = ww_stream_open(&st, s->report, err))) {
            write_report(st.f, &in);
            r = ww_stream_commit(&st, err);
        }
    }
    free(fr);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    s->wall_s = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    if (r || (s->failed == 0 && s->missing == 0)) return r;
    return ww_error_set(err, WW_E_MISMATCH, NULL, 0, 0,
                        "golden check failed: %lld of %lld frames differ, %lld without a golden; "
                        "see %s",
                        (long long)s->failed, (long long)n, (long long)s->missing, s->report);
}
