/* sweep.c - `waterworld sweep` (sweep.h): axes parsed from --vary, points enumerated on a grid or
 * drawn from seeded streams, each point loaded through the scene loader and measured with
 * ww_wave_stats_compute, rows written as CSV and JSON lines in point order from this process or
 * from forked workers, thumbnails rendered in a child process per point, and the contact sheet.
 */
#include "sweep/sweep.h"

#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/child.h"
#include "core/numfmt.h"
#include "core/readfile.h"
#include "core/rng.h"
#include "core/shword.h"
#include "io/image.h"
#include "io/json.h"
#include "io/stream.h"
#include "io/writers.h"
#include "render/audio.h"
#include "render/contact.h"
#include "render/job.h"
#include "sim/floater_stats.h"
#include "sim/wave_stats.h"

#define THUMB_W_DEFAULT 160
#define THUMB_H_DEFAULT 90
#define THUMB_SIDE_MIN 16
#define THUMB_SIDE_MAX 2048
#define MAX_BASE_SETS 256
#define MSG_MAX 1088 /* a ww_error's file, place and message */
#define SET_TEXT_MAX (2 * WW_SWEEP_VALUE_MAX) /* KEY=VALUE */

/* ---- the row: what a point measures ------------------------------------------------------ */

/* what a point measures: the wave statistics (sim/wave_stats.h) and, for scenes with floating
 * objects, their response over the run (sim/floater_stats.h; empty cells without them) */
typedef struct point_stats {
    ww_wave_stats w;
    ww_floater_stats f;
} point_stats;

/* the metric columns, in order */
typedef struct metric {
    const char *name;
    size_t offset;   /* in point_stats */
    int is_int;      /* an int field (else double) */
} metric;

#define METRIC(part, field, is_int) {#field, offsetof(point_stats, part.field), is_int}
static const metric METRICS[] = {
    METRIC(w, count, 1),           METRIC(w, hs, 0),         METRIC(w, peak_period, 0),
    METRIC(w, mean_wavelength, 0), METRIC(w, max_slope, 0),  METRIC(w, fold_sum, 0),
    METRIC(w, fold_margin, 0),     METRIC(w, total_amplitude, 0),
    METRIC(f, cube_heave_rms, 0),  METRIC(f, cube_tilt_rms, 0),
    METRIC(f, boat_heave_rms, 0),  METRIC(f, boat_pitch_rms, 0),
};
#undef METRIC
#define NMETRICS (sizeof METRICS / sizeof METRICS[0])

enum { ROW_OK = 0, ROW_WARN, ROW_ERROR };
static const char *const STATUS_NAME[] = {"ok", "warn", "error"};

enum { THUMB_NONE = 0, THUMB_OK, THUMB_SKIPPED, THUMB_FAILED };

/* one point's result; plain bytes, so a worker sends it through a pipe as it is */
typedef struct row {
    long long point;
    int status;                 /* ROW_* */
    ww_result code;             /* the load's result when status is ROW_ERROR */
    int thumb;                  /* THUMB_* */
    ww_result thumb_code;       /* when THUMB_FAILED */
    double metric[NMETRICS];
    char msg[MSG_MAX];          /* the load's error, or its warnings joined by "; " */
    char thumb_msg[MSG_MAX];    /* why there is no thumbnail */
} row;

/* ---- the sweep: axes and points ---------------------------------------------------------- */

typedef struct axis {
    const char *spec;           /* KEY=... as given */
    char key[WW_SWEEP_VALUE_MAX];
    const char *label;          /* shortest suffix of the key that no other axis ends with */
    int is_range;               /* A:B:N (or A:B with --random); else a list */
    double lo, hi;              /* range ends */
    int count;                  /* values on the grid: N, or the list's items */
    char *buf;                  /* a list's text, split in place into items */
    const char *items[WW_SWEEP_MAX_ITEMS];
} axis;

struct ww_sweep {
    ww_sweep_opts o;
    int naxes;
    axis ax[WW_SWEEP_MAX_AXES];
    long long npoints;
    int digits;                 /* width of point numbers in file names (at least 5) */
    unsigned char *text;        /* the scene file, read once */
    size_t len;
};

ww_sweep_opts ww_default_sweep_opts(void) {
    return (ww_sweep_opts){.jobs = 1, .point = -1, .thumb_w = THUMB_W_DEFAULT,
                           .thumb_h = THUMB_H_DEFAULT, .backend = WW_BACKEND_AUTO};
}

long long ww_sweep_points(const ww_sweep *s) { return s->npoints; }
int ww_sweep_axes(const ww_sweep *s) { return s->naxes; }
const char *ww_sweep_axis_key(const ww_sweep *s, int a) {
    WW_ASSERT(a >= 0 && a < s->naxes);
    return s->ax[a].key;
}

/* a value as text: the shortest that reads back as the same double (core/numfmt.h) */
static void fmt_num(char *buf, size_t cap, double v) { ww_num_text(buf, cap, v); }

/* a grid point computed from the range's ends: the shortest decimal within a millionth of a
 * millionth of the grid's scale, so 0.1:0.4:4 gives 0.2, not 0.20000000000000004 (the run gets
 * exactly the number its label shows) */
#define GRID_ROUNDING 1e-12
static void fmt_grid(char *buf, size_t cap, const axis *x, double v) {
    double scale = fmax(fabs(x->lo), fabs(x->hi));
    ww_num_text_near(buf, cap, v, GRID_ROUNDING * scale);
}

/* index of the first `sep` at or after i that is outside [], {} and quotes; len when none */
static size_t find_top(const char *t, size_t len, size_t i, char sep) {
    int depth = 0;
    char quote = 0;
    for (; i < len; i++) {
        char c = t[i];
        if (quote) {
            if (c == quote) quote = 0;
        } else if (c == '\'' || c == '"') {
            quote = c;
        } else if (c == '[' || c == '{') {
            depth++;
        } else if ((c == ']' || c == '}') && depth > 0) {
            depth--;
        } else if (c == sep && depth == 0) {
            return i;
        }
    }
    return len;
}

/* a whole finite number */
static int parse_number(const char *t, size_t len, double *v) {
    char b[64];
    if (len == 0 || len >= sizeof b) return 0;
    memcpy(b, t, len);
    b[len] = 0;
    char *e = NULL;
    errno = 0;
    *v = strtod(b, &e);
    return errno == 0 && *e == 0 && isfinite(*v);
}

/* a whole count in 1..max, or -1 */
static long long parse_count(const char *t, size_t len, long long max) {
    long long v = 0;
    if (len == 0) return -1;
    for (size_t i = 0; i < len; i++) {
        if (t[i] < '0' || t[i] > '9') return -1;
        v = v * 10 + (t[i] - '0');
        if (v > max) return -1;
    }
    return v;
}

static ww_result axis_error(ww_error *err, const char *spec, const char *why) {
    return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--vary '%s': %s", spec, why);
}

/* KEY=A:B:N, KEY=A:B (random points only) or KEY=v1,v2,... */
static ww_result parse_axis(const char *spec, int random, axis *a, ww_error *err) {
    const char *eq = strchr(spec, '=');
    a->spec = spec;
    if (!eq || eq == spec) return axis_error(err, spec, "expected KEY=A:B:N or KEY=v1,v2,...");
    size_t klen = (size_t)(eq - spec);
    if (klen >= sizeof a->key) return axis_error(err, spec, "the key is too long");
    memcpy(a->key, spec, klen);
    a->key[klen] = 0;
    const char *v = eq + 1;
    size_t len = strlen(v);
    if (len == 0) return axis_error(err, spec, "expected values after '='");

    size_t comma = find_top(v, len, 0, ','), colon = find_top(v, len, 0, ':');
    if (comma == len && colon < len) {
        /* a range: two or three parts */
        size_t c2 = find_top(v, len, colon + 1, ':');
        if (c2 < len && find_top(v, len, c2 + 1, ':') < len)
            return axis_error(err, spec, "a range is A:B:N, with two colons at most");
        a->is_range = 1;
        if (!parse_number(v, colon, &a->lo) || !parse_number(v + colon + 1, c2 - colon - 1, &a->hi))
            return axis_error(err, spec, "A and B of A:B:N must be finite numbers");
        if (c2 == len) {
            if (!random)
                return axis_error(err, spec, "a grid axis needs a count: A:B:N (A:B alone is for --random)");
            a->count = 1;
            return WW_OK;
        }
        long long n = parse_count(v + c2 + 1, len - c2 - 1, WW_SWEEP_MAX_POINTS);
        if (n < 1) return axis_error(err, spec, "N of A:B:N must be a whole number from 1 to 1000000");
        a->count = (int)n;
        return WW_OK;
    }

    /* a list, split in place at the top-level commas */
    if (!(a->buf = malloc(len + 1))) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory");
    memcpy(a->buf, v, len + 1);
    for (size_t i = 0; i <= len;) {
        size_t e = find_top(a->buf, len, i, ',');
        if (e == i) return axis_error(err, spec, "empty value in the list (two commas, or one at an end)");
        if (e - i >= WW_SWEEP_VALUE_MAX) return axis_error(err, spec, "a value is longer than 255 bytes");
        if (a->count == WW_SWEEP_MAX_ITEMS) return axis_error(err, spec, "more than 1024 values");
        a->buf[e] = 0;
        a->items[a->count++] = a->buf + i;
        i = e + 1;
    }
    return WW_OK;
}

/* labels: the shortest trailing part of each key (whole segments: "amplitude", then
 * "list[0].amplitude", ...) that no other axis's key also ends with */
static void make_labels(ww_sweep *s) {
    for (int a = 0; a < s->naxes; a++) {
        const char *k = s->ax[a].key, *label = k;
        for (const char *p = k + strlen(k); p > k; p--) {
            if (p[-1] != '.') continue;
            int clash = 0;
            size_t n = strlen(p);
            for (int b = 0; b < s->naxes && !clash; b++) {
                const char *o = s->ax[b].key;
                size_t m = strlen(o);
                clash = b != a && m >= n && strcmp(o + m - n, p) == 0 && (m == n || o[m - n - 1] == '.');
            }
            if (!clash) {
                label = p;
                break;
            }
        }
        s->ax[a].label = label;
    }
}

/* SplitMix64 (Steele, Lea and Flood 2014, "Fast splittable pseudorandom number generators"):
 * the (i + 1)-th output of the generator seeded with seed, used as point i's PCG seed */
static uint64_t splitmix64(uint64_t seed, uint64_t i) {
    uint64_t z = seed + (i + 1) * 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

void ww_sweep_values(const ww_sweep *s, long long i, char vals[][WW_SWEEP_VALUE_MAX]) {
    WW_ASSERT(i >= 0 && i < s->npoints);
    ww_rng r = {0, 0};
    if (s->o.random > 0) ww_rng_seed(&r, splitmix64(s->o.seed, (uint64_t)i), WW_RNG_SWEEP);
    /* a grid index has the last axis fastest; random draws go first axis first */
    for (int a = 0; a < s->naxes; a++) {
        const axis *x = &s->ax[a];
        int n = x->count, k;
        if (s->o.random > 0) {
            double u = ww_rng_uniform(&r);
            if (x->is_range) {
                fmt_num(vals[a], WW_SWEEP_VALUE_MAX, x->lo + (x->hi - x->lo) * u);
                continue;
            }
            k = (int)(u * n);
            if (k >= n) k = n - 1;
        } else {
            long long stride = 1;
            for (int b = a + 1; b < s->naxes; b++) stride *= s->ax[b].count;
            k = (int)((i / stride) % n);
        }
        if (!x->is_range) {
            snprintf(vals[a], WW_SWEEP_VALUE_MAX, "%s", x->items[k]);
        } else if (k == 0 || n == 1) {
            fmt_num(vals[a], WW_SWEEP_VALUE_MAX, x->lo);
        } else if (k == n - 1) {
            fmt_num(vals[a], WW_SWEEP_VALUE_MAX, x->hi);
        } else {
            /* weighted, not A + k (B - A) / (N - 1), then the decimal it stands for */
            double w = (double)(n - 1);
            double v = (x->lo * (double)(n - 1 - k) + x->hi * (double)k) / w;
            fmt_grid(vals[a], WW_SWEEP_VALUE_MAX, x, v);
        }
    }
}

/* ---- one point ----------------------------------------------------------------------------- */

/* the loader names a --set by its place among the sets; a point's own sets follow the base ones,
 * so "--set[nsets + a + 1]" is the axis a: say "--vary[a + 1]" */
static void relabel(const ww_sweep *s, ww_error *err) {
    int k = 0;
    char tail = 0;
    if (sscanf(err->file, "--set[%d%c", &k, &tail) == 2 && tail == ']' && k > s->o.nsets &&
        k <= s->o.nsets + s->naxes)
        snprintf(err->file, sizeof err->file, "--vary[%d]", k - s->o.nsets);
}

/* the scene at point i: the base sets, then KEY=VALUE of each axis */
static ww_result load_point(const ww_sweep *s, long long i, ww_scene **sc, ww_error *err) {
    char vals[WW_SWEEP_MAX_AXES][WW_SWEEP_VALUE_MAX];
    char text[WW_SWEEP_MAX_AXES][SET_TEXT_MAX];
    ww_set sets[MAX_BASE_SETS + WW_SWEEP_MAX_AXES];
    ww_sweep_values(s, i, vals);
    for (int k = 0; k < s->o.nsets; k++) sets[k] = s->o.sets[k];
    for (int a = 0; a < s->naxes; a++) {
        snprintf(text[a], sizeof text[a], "%.*s=%.*s", WW_SWEEP_VALUE_MAX - 1, s->ax[a].key,
                 WW_SWEEP_VALUE_MAX - 1, vals[a]);
        sets[s->o.nsets + a].text = text[a];
    }
    ww_result r = ww_scene_load_string(s->o.scene_path, (const char *)s->text, s->len, sets,
                                       s->o.nsets + s->naxes, sc, err);
    if (r) relabel(s, err);
    return r;
}

/* "file:line:column: message", as ww_error_print says it but without "error: " */
static void error_text(const ww_error *e, char *out, size_t cap) {
    if (e->file[0] && e->line > 0)
        snprintf(out, cap, "%s:%d:%d: %s", e->file, e->line, e->column, e->msg);
    else if (e->file[0])
        snprintf(out, cap, "%s: %s", e->file, e->msg);
    else
        snprintf(out, cap, "%s", e->msg);
}

/* ---- child processes ----------------------------------------------------------------------- */

typedef struct child_report {
    ww_result code;
    ww_error err;
} child_report;

/* fn in a child process (core/child.h: its own GL context, its own crash), its outcome in
 * rep's code and message */
static void in_child(void (*fn)(const void *ctx, void *rep), const void *ctx, child_report *rep) {
    ww_child_end end;
    switch (ww_child_run(fn, ctx, rep, sizeof *rep, &end)) {
    case WW_CHILD_REPORTED:
        return;
    case WW_CHILD_NO_PIPE:
        rep->code = ww_error_set(&rep->err, WW_E_IO, NULL, 0, 0, "pipe: %s", strerror(end.errnum));
        return;
    case WW_CHILD_NO_FORK:
        rep->code = ww_error_set(&rep->err, WW_E_IO, NULL, 0, 0, "fork: %s", strerror(end.errnum));
        return;
    case WW_CHILD_DIED: {
        char how[64];
        rep->code = ww_error_set(&rep->err, WW_E_BACKEND, NULL, 0, 0,
                                 "the rendering child process died (%s)",
                                 ww_child_how_ended(end.status, how, sizeof how));
        return;
    }
    }
}

static void probe_child(const void *ctx, void *report) {
    const ww_sweep *s = ctx;
    child_report *rep = report;
    ww_backend *b = NULL;
    rep->code = ww_backend_open(s->o.backend, &b, &rep->err);
    if (rep->code == WW_OK) ww_backend_close(b);
}

typedef struct thumb_ctx {
    const ww_sweep *s;
    ww_scene *sc;               /* the point's scene; the child resizes its own copy */
    long long point;
} thumb_ctx;

static void thumb_path(const ww_sweep *s, long long i, char *out, size_t cap) {
    snprintf(out, cap, "%s/thumbs/point_%0*lld.png", s->o.out_dir, s->digits, i);
}

/* render the thumbnail frame into a private folder with the render job, then move the frame to
 * its name: what a thumbnail shows is what `render --size` shows */
static void thumb_child(const void *ctx, void *report) {
    const thumb_ctx *t = ctx;
    child_report *rep = report;
    const ww_sweep *s = t->s;
    char dir[1024], frame[1100], final[1100];
    snprintf(dir, sizeof dir, "%s/thumbs/.point_%0*lld.%ld", s->o.out_dir, s->digits, t->point,
             (long)getpid());
    thumb_path(s, t->point, final, sizeof final);
    t->sc->width = s->o.thumb_w;
    t->sc->height = s->o.thumb_h;
    ww_job_opts o = ww_default_job_opts();
    o.out_dir = dir;
    o.first = s->o.thumb_frame;
    o.last = s->o.thumb_frame + 1;
    o.width = s->o.thumb_w;
    o.height = s->o.thumb_h;
    o.backend = s->o.backend;
    o.quiet = 1;
    ww_job_stats st;
    rep->code = ww_job_run(t->sc, &o, &st, &rep->err);
    snprintf(frame, sizeof frame, "%s/frame_%05lld.png", dir, (long long)s->o.thumb_frame);
    if (rep->code == WW_OK && rename(frame, final) != 0)
        rep->code = ww_error_set(&rep->err, WW_E_IO, final, 0, 0, "cannot move the thumbnail into place: %s",
                                 strerror(errno));
    unlink(frame);
    rmdir(dir);
}

/* ---- a row --------------------------------------------------------------------------------- */

static void compute_row(const ww_sweep *s, long long i, row *rw) {
    memset(rw, 0, sizeof *rw); /* every byte, padding too: the row travels through pipes */
    rw->point = i;
    ww_scene *sc = NULL;
    ww_error err = {0};
    ww_result r = load_point(s, i, &sc, &err);
    if (r != WW_OK) {
        rw->status = ROW_ERROR;
        rw->code = r;
        error_text(&err, rw->msg, sizeof rw->msg);
        for (size_t m = 0; m < NMETRICS; m++) rw->metric[m] = NAN;
        if (s->o.thumbs) {
            rw->thumb = THUMB_SKIPPED;
            snprintf(rw->thumb_msg, sizeof rw->thumb_msg, "the point did not load");
        }
        return;
    }

    point_stats st;
    ww_wave_stats_compute(sc, 0, 0, &st.w);
    r = ww_floater_stats_compute(sc, &st.f, &err);
    if (r != WW_OK) { /* the simulation failed (a NaN): the row says so */
        rw->status = ROW_ERROR;
        rw->code = r;
        error_text(&err, rw->msg, sizeof rw->msg);
        st.f = (ww_floater_stats){NAN, NAN, NAN, NAN, 0};
    }
    for (size_t m = 0; m < NMETRICS; m++) {
        const char *f = (const char *)&st + METRICS[m].offset;
        if (METRICS[m].is_int) {
            int v;
            memcpy(&v, f, sizeof v);
            rw->metric[m] = (double)v;
        } else {
            memcpy(&rw->metric[m], f, sizeof rw->metric[m]);
        }
    }
    if (rw->status == ROW_OK && sc->nwarnings > 0) {
        rw->status = ROW_WARN;
        size_t n = 0;
        for (int w = 0; w < sc->nwarnings && n < sizeof rw->msg; w++) {
            int k = snprintf(rw->msg + n, sizeof rw->msg - n, "%s%s", w ? "; " : "", sc->warnings[w]);
            n += k > 0 ? (size_t)k : 0;
        }
    }

    if (s->o.thumbs) {
        if (s->o.thumb_frame >= sc->frame_count) {
            rw->thumb = THUMB_SKIPPED;
            snprintf(rw->thumb_msg, sizeof rw->thumb_msg, "frame %lld is past this point's %lld frames",
                     (long long)s->o.thumb_frame, (long long)sc->frame_count);
        } else {
            thumb_ctx t = {s, sc, i};
            child_report rep;
            in_child(thumb_child, &t, &rep);
            rw->thumb = rep.code == WW_OK ? THUMB_OK : THUMB_FAILED;
            rw->thumb_code = rep.code;
            if (rep.code) error_text(&rep.err, rw->thumb_msg, sizeof rw->thumb_msg);
        }
    }
    ww_scene_free(sc);
}

/* ---- writing rows -------------------------------------------------------------------------- */

/* RFC 4180: quoted when it holds a comma, a quote or a line break; quotes doubled */
static void csv_cell(FILE *f, const char *t) {
    if (!strpbrk(t, ",\"\r\n")) {
        fputs(t, f);
        return;
    }
    fputc('"', f);
    for (; *t; t++) {
        if (*t == '"') fputc('"', f);
        fputc(*t, f);
    }
    fputc('"', f);
}

/* JSON's number grammar (RFC 8259 section 6): -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)? */
static int is_json_number(const char *t) {
    if (*t == '-') t++;
    if (*t == '0') {
        t++;
    } else if (*t >= '1' && *t <= '9') {
        while (*t >= '0' && *t <= '9') t++;
    } else {
        return 0;
    }
    if (*t == '.') {
        if (*++t < '0' || *t > '9') return 0;
        while (*t >= '0' && *t <= '9') t++;
    }
    if (*t == 'e' || *t == 'E') {
        t++;
        if (*t == '+' || *t == '-') t++;
        if (*t < '0' || *t > '9') return 0;
        while (*t >= '0' && *t <= '9') t++;
    }
    return *t == 0;
}

/* a value as set: a number stays a number, anything else (a word, a YAML list) is a string */
static void json_value(FILE *f, const char *t) {
    if (is_json_number(t))
        fputs(t, f);
    else
        ww_json_string(f, t);
}

static void csv_header(const ww_sweep *s, FILE *f) {
    fputs("point", f);
    for (int a = 0; a < s->naxes; a++) {
        fputc(',', f);
        csv_cell(f, s->ax[a].key);
    }
    fputs(",status", f);
    for (size_t m = 0; m < NMETRICS; m++) fprintf(f, ",%s", METRICS[m].name);
    fputs(",message\n", f);
}

static void csv_row(const ww_sweep *s, const row *rw, char vals[][WW_SWEEP_VALUE_MAX], FILE *f) {
    char num[32];
    fprintf(f, "%lld", rw->point);
    for (int a = 0; a < s->naxes; a++) {
        fputc(',', f);
        csv_cell(f, vals[a]);
    }
    fprintf(f, ",%s", STATUS_NAME[rw->status]);
    for (size_t m = 0; m < NMETRICS; m++) {
        fputc(',', f);
        if (rw->status == ROW_ERROR) continue;
        double v = rw->metric[m];
        if (isfinite(v)) {
            fmt_num(num, sizeof num, v);
            fputs(num, f);
        } else if (!isnan(v)) { /* NaN: nothing to measure (no floating objects): empty */
            fputs(v > 0 ? "inf" : "-inf", f);
        }
    }
    fputc(',', f);
    csv_cell(f, rw->msg);
    fputc('\n', f);
}

static void json_row(const ww_sweep *s, const row *rw, char vals[][WW_SWEEP_VALUE_MAX], FILE *f) {
    char num[32];
    fprintf(f, "{\"point\":%lld,\"values\":{", rw->point);
    for (int a = 0; a < s->naxes; a++) {
        if (a) fputc(',', f);
        ww_json_string(f, s->ax[a].key);
        fputc(':', f);
        json_value(f, vals[a]);
    }
    fprintf(f, "},\"status\":\"%s\"", STATUS_NAME[rw->status]);
    if (rw->status == ROW_ERROR) fprintf(f, ",\"code\":\"%s\"", ww_result_name(rw->code));
    if (rw->status != ROW_ERROR) {
        fputs(",\"metrics\":{", f);
        for (size_t m = 0; m < NMETRICS; m++) {
            fprintf(f, "%s\"%s\":", m ? "," : "", METRICS[m].name);
            if (isfinite(rw->metric[m])) {
                fmt_num(num, sizeof num, rw->metric[m]);
                fputs(num, f);
            } else {
                fputs("null", f);
            }
        }
        fputc('}', f);
    }
    if (rw->msg[0]) {
        fputs(",\"message\":", f);
        ww_json_string(f, rw->msg);
    }
    if (rw->thumb == THUMB_OK) fprintf(f, ",\"thumb\":\"thumbs/point_%0*lld.png\"", s->digits, rw->point);
    fputs("}\n", f);
}

/* where rows go: CSV and JSON lines (files or the stream) and the contact sheet */
typedef struct sink {
    const ww_sweep *s;
    FILE *csv, *jsonl;          /* NULL: not written */
    ww_stream csv_file, jsonl_file;
    int csv_open, jsonl_open;
    int sheet_on;
    ww_contact_layout L;
    ww_image sheet;
    long long rows, warned, failed;
} sink;

/* a grid's rows are its last axis; random points make a square */
static int sheet_cols(const ww_sweep *s) {
    return s->o.random > 0 ? (int)ceil(sqrt((double)s->npoints)) : s->ax[s->naxes - 1].count;
}

static void point_label(const ww_sweep *s, const row *rw, char vals[][WW_SWEEP_VALUE_MAX],
                        char *out, size_t cap) {
    size_t n = 0;
    int k = snprintf(out, cap, "#%lld%s%s", rw->point, rw->status == ROW_OK ? "" : " ",
                     rw->status == ROW_OK ? "" : STATUS_NAME[rw->status]);
    n = k > 0 ? (size_t)k : 0;
    for (int a = 0; a < s->naxes && n < cap; a++) {
        k = snprintf(out + n, cap - n, "\n%s=%s", s->ax[a].label, vals[a]);
        n += k > 0 ? (size_t)k : 0;
    }
}

static ww_result sink_row(sink *k, const row *rw, ww_error *err) {
    const ww_sweep *s = k->s;
    if (rw->thumb == THUMB_FAILED)
        return ww_error_set(err, rw->thumb_code, NULL, 0, 0, "thumbnail of point %lld: %s", rw->point,
                            rw->thumb_msg);
    char vals[WW_SWEEP_MAX_AXES][WW_SWEEP_VALUE_MAX];
    ww_sweep_values(s, rw->point, vals);
    if (k->csv) csv_row(s, rw, vals, k->csv);
    if (k->jsonl) json_row(s, rw, vals, k->jsonl);
    k->rows++;
    k->warned += rw->status == ROW_WARN;
    k->failed += rw->status == ROW_ERROR;
    if (s->o.point >= 0 && s->o.out_dir && s->o.thumbs) {
        /* the point's cell of the contact sheet, for `join`: whether it has a thumbnail, then
         * its label */
        char path[1100], text[2100];
        point_label(s, rw, vals, text + 8, sizeof text - 9);
        memcpy(text, rw->thumb == THUMB_OK ? "thumb 1\n" : "thumb 0\n", 8);
        strcat(text, "\n");
        snprintf(path, sizeof path, "%s/points/point_%0*lld.label", s->o.out_dir, s->digits, rw->point);
        ww_result r = ww_write_file_atomic(path, text, strlen(text), err);
        if (r) return r;
    }

    if (k->sheet_on) {
        ww_image thumb = {0};
        char path[1100], label[2048];
        if (rw->thumb == THUMB_OK) {
            thumb_path(s, rw->point, path, sizeof path);
            ww_result r = ww_read_png(path, &thumb, err);
            if (r) return r;
            if (thumb.width != s->o.thumb_w || thumb.height != s->o.thumb_h || thumb.channels < 3) {
                ww_image_free(&thumb);
                return ww_error_set(err, WW_E_IO, path, 0, 0, "thumbnail is %dx%d, expected %dx%d",
                                    thumb.width, thumb.height, s->o.thumb_w, s->o.thumb_h);
            }
        }
        point_label(s, rw, vals, label, sizeof label);
        ww_contact_put(&k->sheet, &k->L, (int)rw->point, rw->thumb == THUMB_OK ? &thumb : NULL, label);
        ww_image_free(&thumb);
    }
    return WW_OK;
}

static void sink_abort(sink *k) {
    if (k->csv_open) ww_stream_abort(&k->csv_file);
    if (k->jsonl_open) ww_stream_abort(&k->jsonl_file);
    k->csv_open = k->jsonl_open = 0;
    ww_image_free(&k->sheet);
}

static ww_result sink_open(sink *k, const ww_sweep *s, FILE *to, ww_error *err) {
    memset(k, 0, sizeof *k);
    k->s = s;
    char path[1100];
    ww_result r;
    if (s->o.point >= 0) {
        /* one JSON line: on the stream, or in OUT/points/ */
        if (!s->o.out_dir) {
            k->jsonl = to;
            return WW_OK;
        }
        /* and its CSV row beside it, for `join` to make sweep.csv (committed first: the JSON
         * line is the point's mark of completion) */
        snprintf(path, sizeof path, "%s/points/point_%0*lld.csv", s->o.out_dir, s->digits, s->o.point);
        if ((r = ww_stream_open(&k->csv_file, path, err))) return r;
        k->csv_open = 1;
        k->csv = k->csv_file.f;
        snprintf(path, sizeof path, "%s/points/point_%0*lld.jsonl", s->o.out_dir, s->digits, s->o.point);
        if ((r = ww_stream_open(&k->jsonl_file, path, err))) {
            sink_abort(k);
            return r;
        }
        k->jsonl_open = 1;
        k->jsonl = k->jsonl_file.f;
        return WW_OK;
    }
    if (!s->o.out_dir) {
        k->csv = to;
    } else {
        snprintf(path, sizeof path, "%s/sweep.csv", s->o.out_dir);
        if ((r = ww_stream_open(&k->csv_file, path, err))) return r;
        k->csv_open = 1;
        k->csv = k->csv_file.f;
        snprintf(path, sizeof path, "%s/sweep.jsonl", s->o.out_dir);
        if ((r = ww_stream_open(&k->jsonl_file, path, err))) {
            sink_abort(k);
            return r;
        }
        k->jsonl_open = 1;
        k->jsonl = k->jsonl_file.f;
    }
    csv_header(s, k->csv);
    if (s->o.thumbs) {
        ww_contact_plan((int)s->npoints, sheet_cols(s), s->o.thumb_w, s->o.thumb_h, s->naxes + 1, &k->L);
        if (ww_contact_new(&k->L, &k->sheet) != 0) {
            sink_abort(k);
            return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory for a %dx%d contact sheet",
                                k->L.width, k->L.height);
        }
        k->sheet_on = 1;
    }
    return WW_OK;
}

static ww_result sink_commit(sink *k, ww_error *err) {
    ww_result r = WW_OK;
    if (k->csv && !k->csv_open && fflush(k->csv) != 0)
        r = ww_error_set(err, WW_E_IO, "stdout", 0, 0, "cannot write: %s", strerror(errno));
    if (k->jsonl && !k->jsonl_open && fflush(k->jsonl) != 0 && !r)
        r = ww_error_set(err, WW_E_IO, "stdout", 0, 0, "cannot write: %s", strerror(errno));
    if (!r && k->csv_open) {
        k->csv_open = 0;
        r = ww_stream_commit(&k->csv_file, err);
    }
    if (!r && k->jsonl_open) {
        k->jsonl_open = 0;
        r = ww_stream_commit(&k->jsonl_file, err);
    }
    if (!r && k->sheet_on) {
        char path[1100];
        snprintf(path, sizeof path, "%s/contact_sheet.png", k->s->o.out_dir);
        r = ww_write_png(path, &k->sheet, err);
    }
    sink_abort(k);
    return r;
}

/* ---- computing the rows -------------------------------------------------------------------- */

/* points [first, last) in this process */
static ww_result run_here(const ww_sweep *s, long long first, long long last, sink *k,
                          ww_error *err) {
    row rw;
    for (long long i = first; i < last; i++) {
        compute_row(s, i, &rw);
        ww_result r = sink_row(k, &rw, err);
        if (r) return r;
    }
    return WW_OK;
}

/* every point on `jobs` forked workers, point i on worker i mod jobs, each sending its rows in
 * order through its own pipe; reading them back in point order gives the bytes of one process,
 * and no worker runs more than one pipe's worth of rows ahead */
static ww_result run_workers(const ww_sweep *s, int jobs, sink *k, ww_error *err) {
    pid_t pid[WW_SWEEP_MAX_JOBS];
    int fd[WW_SWEEP_MAX_JOBS];
    int started = 0;
    ww_result r = WW_OK;
    fflush(NULL);
    for (; started < jobs; started++) {
        int p[2];
        if (pipe(p) != 0) {
            r = ww_error_set(err, WW_E_IO, NULL, 0, 0, "pipe: %s", strerror(errno));
            break;
        }
        pid_t c = fork();
        if (c == 0) {
            close(p[0]);
            for (int w = 0; w < started; w++) close(fd[w]);
            row rw;
            for (long long i = started; i < s->npoints; i += jobs) {
                compute_row(s, i, &rw);
                if (ww_pipe_write_all(p[1], &rw, sizeof rw) != 0) _exit(1);
            }
            _exit(0);
        }
        close(p[1]);
        if (c < 0) {
            close(p[0]);
            r = ww_error_set(err, WW_E_IO, NULL, 0, 0, "fork: %s", strerror(errno));
            break;
        }
        pid[started] = c;
        fd[started] = p[0];
    }

    row rw;
    for (long long i = 0; i < s->npoints && !r; i++) {
        int w = (int)(i % jobs);
        if (ww_pipe_read_all(fd[w], &rw, sizeof rw) != 0 || rw.point != i) {
            r = ww_error_set(err, WW_E_IO, NULL, 0, 0, "sweep worker %d stopped before point %lld", w, i);
            break;
        }
        r = sink_row(k, &rw, err);
    }

    /* on a failure the workers still running are ours to stop */
    for (int w = 0; w < started; w++) {
        close(fd[w]);
        if (r) kill(pid[w], SIGTERM);
    }
    for (int w = 0; w < started; w++) {
        int status = 0;
        while (waitpid(pid[w], &status, 0) < 0 && errno == EINTR) {}
        if (!r && !(WIFEXITED(status) && WEXITSTATUS(status) == 0)) {
            char how[64];
            r = ww_error_set(err, WW_E_IO, NULL, 0, 0, "sweep worker %d failed (%s)", w,
                             ww_child_how_ended(status, how, sizeof how));
        }
    }
    return r;
}

static void point_command(const ww_sweep *s, FILE *to);

/* OUT/points/sweep.job, what `join` needs to gather the points: their count, the file names'
 * width, the CSV header and the command of every point (without its --point I). Every point
 * writes the same bytes, atomically, before its own files. With thumbnails, the contact sheet's
 * layout too (each point's label goes in its point_NNNNN.label). */
static ww_result write_job(const ww_sweep *s, ww_error *err) {
    char *buf = NULL, path[1100];
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    if (!f) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory for the sweep's job file");
    fprintf(f, "%s\npoints %lld\ndigits %d\n", WW_SWEEP_JOB_MAGIC, s->npoints, s->digits);
    /* the contact sheet's layout: columns, thumbnail size, label lines */
    if (s->o.thumbs) fprintf(f, "sheet %d %d %d %d\n", sheet_cols(s), s->o.thumb_w, s->o.thumb_h, s->naxes + 1);
    fputs("csv ", f);
    csv_header(s, f); /* ends the line */
    fputs("command ", f);
    point_command(s, f);
    fputc('\n', f);
    fclose(f);
    snprintf(path, sizeof path, "%s/points/sweep.job", s->o.out_dir);
    ww_result r = ww_write_file_atomic(path, buf, len, err);
    free(buf);
    return r;
}

ww_result ww_sweep_run(ww_sweep *s, FILE *to, ww_error *err) {
    const ww_sweep_opts *o = &s->o;
    ww_result r;

    /* no GL means no thumbnails: say so before any work */
    if (o->thumbs) {
        child_report rep;
        in_child(probe_child, s, &rep);
        if (rep.code) {
            char why[MSG_MAX];
            error_text(&rep.err, why, sizeof why);
            return ww_error_set(err, rep.code, NULL, 0, 0, "--thumbs needs a GL backend: %s", why);
        }
    }

    /* folders, then the outputs */
    char path[1100];
    if (o->out_dir) {
        snprintf(path, sizeof path, "%s/%s", o->out_dir, o->point >= 0 ? "points" : "");
        if ((r = ww_make_dirs(path, err))) return r;
        snprintf(path, sizeof path, "%s/thumbs", o->out_dir);
        if (o->thumbs && (r = ww_make_dirs(path, err))) return r;
    }
    if (o->out_dir && o->point >= 0 && (r = write_job(s, err))) return r;
    sink k;
    if ((r = sink_open(&k, s, to, err))) return r;

    int jobs = o->jobs < 1 ? 1 : o->jobs;
    if (jobs > s->npoints) jobs = (int)s->npoints;
    if (o->point >= 0)
        r = run_here(s, o->point, o->point + 1, &k, err);
    else if (jobs == 1)
        r = run_here(s, 0, s->npoints, &k, err);
    else
        r = run_workers(s, jobs, &k, err);
    if (r) {
        sink_abort(&k);
        return r;
    }
    long long rows = k.rows, warned = k.warned, failed = k.failed;
    int sheet = k.sheet_on;
    if ((r = sink_commit(&k, err))) return r;

    if (!o->quiet && o->point < 0) {
        fprintf(stderr, "sweep: %lld points (%lld ok, %lld warn, %lld error)", rows,
                rows - warned - failed, warned, failed);
        if (o->out_dir)
            fprintf(stderr, " -> %s/sweep.csv, %s/sweep.jsonl%s%s%s", o->out_dir, o->out_dir,
                    sheet ? ", " : "", sheet ? o->out_dir : "", sheet ? "/contact_sheet.png" : "");
        fputc('\n', stderr);
    }
    return WW_OK;
}

/* ---- job lines ----------------------------------------------------------------------------- */

/* the command of every point, up to its --point I */
static void point_command(const ww_sweep *s, FILE *to) {
    const ww_sweep_opts *o = &s->o;
    static const char *const backend_name[] = {"auto", "egl", "osmesa", "null"};
    char num[64];
    {
        ww_sh_word(to, o->exe ? o->exe : "waterworld", 1);
        ww_sh_word(to, "sweep", 0);
        ww_sh_word(to, o->scene_path, 0);
        for (int a = 0; a < s->naxes; a++) {
            ww_sh_word(to, "--vary", 0);
            ww_sh_word(to, s->ax[a].spec, 0);
        }
        if (o->random > 0) {
            snprintf(num, sizeof num, "%lld", o->random);
            ww_sh_word(to, "--random", 0);
            ww_sh_word(to, num, 0);
            snprintf(num, sizeof num, "%llu", (unsigned long long)o->seed);
            ww_sh_word(to, "--seed", 0);
            ww_sh_word(to, num, 0);
        }
        for (int k = 0; k < o->nsets; k++) {
            ww_sh_word(to, "--set", 0);
            ww_sh_word(to, o->sets[k].text, 0);
        }
        if (o->thumbs) {
            ww_sh_word(to, "--thumbs", 0);
            snprintf(num, sizeof num, "%dx%d", o->thumb_w, o->thumb_h);
            ww_sh_word(to, "--thumb-size", 0);
            ww_sh_word(to, num, 0);
            snprintf(num, sizeof num, "%lld", (long long)o->thumb_frame);
            ww_sh_word(to, "--thumb-frame", 0);
            ww_sh_word(to, num, 0);
        }
        if (o->backend != WW_BACKEND_AUTO) {
            ww_sh_word(to, "--backend", 0);
            ww_sh_word(to, backend_name[o->backend], 0);
        }
        if (o->out_dir) {
            ww_sh_word(to, "-o", 0);
            ww_sh_word(to, o->out_dir, 0);
        }
    }
}

ww_result ww_sweep_emit_jobs(const ww_sweep *s, FILE *to, ww_error *err) {
    const ww_sweep_opts *o = &s->o;
    char num[64];
    for (long long i = 0; i < s->npoints; i++) {
        point_command(s, to);
        snprintf(num, sizeof num, "%lld", i);
        ww_sh_word(to, "--point", 0);
        ww_sh_word(to, num, 0);
        fputc('\n', to);
    }
    if (!o->quiet) {
        if (o->out_dir)
            fprintf(stderr, "sweep: %lld job lines; each writes %s/points/point_N.jsonl; merge them with\n"
                            "  waterworld join %s\n",
                    s->npoints, o->out_dir, o->out_dir);
        else
            fprintf(stderr, "sweep: %lld job lines; each prints its point's JSON line: keep their output\n"
                            "  in point order (e.g. parallel -k) to get sweep.jsonl\n", s->npoints);
    }
    if (fflush(to) != 0) return ww_error_set(err, WW_E_IO, "stdout", 0, 0, "cannot write: %s", strerror(errno));
    return WW_OK;
}

/* ---- setting up ---------------------------------------------------------------------------- */

void ww_sweep_free(ww_sweep *s) {
    if (!s) return;
    for (int a = 0; a < s->naxes; a++) free(s->ax[a].buf);
    free(s->text);
    free(s);
}

/* what the first point's load says about the sweep as a whole: a key that names nothing or a
 * scene that cannot be read fails every point alike */
static int fails_every_point(ww_result r) {
    return r == WW_E_UNKNOWN_KEY || r == WW_E_SET || r == WW_E_NOFILE || r == WW_E_EMPTY ||
           r == WW_E_SYNTAX || r == WW_E_NOMEM;
}

static ww_result check_opts(const ww_sweep_opts *o, ww_error *err) {
    if (!o->scene_path)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "sweep needs a scene file (waterworld sweep --help)");
    if (o->nvary < 1)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "sweep needs at least one --vary KEY=A:B:N");
    if (o->nvary > WW_SWEEP_MAX_AXES)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "more than %d --vary axes", WW_SWEEP_MAX_AXES);
    if (o->nsets > MAX_BASE_SETS)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "more than %d --set options", MAX_BASE_SETS);
    if (o->random < 0 || o->random > WW_SWEEP_MAX_POINTS)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--random wants 1 to %d points", WW_SWEEP_MAX_POINTS);
    if (o->jobs < 0 || o->jobs > WW_SWEEP_MAX_JOBS)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--jobs wants 1 to %d", WW_SWEEP_MAX_JOBS);
    if (o->thumbs && !o->out_dir)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--thumbs needs -o DIR for the images");
    if (o->thumbs && (o->thumb_w < THUMB_SIDE_MIN || o->thumb_h < THUMB_SIDE_MIN ||
                      o->thumb_w > THUMB_SIDE_MAX || o->thumb_h > THUMB_SIDE_MAX))
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--thumb-size wants each side in %d..%d, got %dx%d",
                            THUMB_SIDE_MIN, THUMB_SIDE_MAX, o->thumb_w, o->thumb_h);
    if (o->thumb_frame < 0)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--thumb-frame wants a frame number >= 0");
    return WW_OK;
}

ww_result ww_sweep_new(const ww_sweep_opts *o, ww_sweep **out, ww_error *err) {
    *out = NULL;
    ww_result r = check_opts(o, err);
    if (r) return r;
    ww_sweep *s = calloc(1, sizeof *s);
    if (!s) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory");
    s->o = *o;
    if (s->o.thumb_w == 0) s->o.thumb_w = THUMB_W_DEFAULT;
    if (s->o.thumb_h == 0) s->o.thumb_h = THUMB_H_DEFAULT;

    /* the axes, each key once */
    for (int a = 0; a < o->nvary && !r; a++) {
        s->naxes++;
        r = parse_axis(o->vary[a], o->random > 0, &s->ax[a], err);
        for (int b = 0; b < a && !r; b++)
            if (strcmp(s->ax[b].key, s->ax[a].key) == 0)
                r = ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--vary '%s': the key is already an axis (%s)",
                                 o->vary[a], o->vary[b]);
    }
    if (r) goto fail;
    make_labels(s);

    /* how many points, and is the one asked for among them */
    s->npoints = o->random > 0 ? o->random : 1;
    for (int a = 0; a < s->naxes && o->random == 0; a++) {
        s->npoints *= s->ax[a].count;
        if (s->npoints > WW_SWEEP_MAX_POINTS) {
            r = ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "the grid has more than %d points", WW_SWEEP_MAX_POINTS);
            goto fail;
        }
    }
    for (long long n = s->npoints - 1, d = 1; ; n /= 10, d++)
        if (n < 10) {
            s->digits = d < 5 ? 5 : (int)d;
            break;
        }
    if (o->point >= s->npoints) {
        r = ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--point %lld: the sweep has points 0..%lld", o->point,
                         s->npoints - 1);
        goto fail;
    }
    if (o->thumbs && o->point < 0) {
        ww_contact_layout L;
        if (ww_contact_plan((int)s->npoints, sheet_cols(s), s->o.thumb_w, s->o.thumb_h, s->naxes + 1, &L) != 0) {
            r = ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                             "--thumbs: %lld points make a contact sheet over %d px on a side; use a smaller "
                             "--thumb-size or fewer points", s->npoints, WW_CONTACT_MAX_SIDE);
            goto fail;
        }
    }

    /* the scene, read once; its first point shows whether the keys exist */
    if ((r = ww_file_read_max(o->scene_path, WW_SCENE_MAX_BYTES, WW_SCENE_MAX_BYTES, &s->text,
                                &s->len, err))) goto fail;
    ww_scene *sc = NULL;
    ww_error first = {0};
    ww_result fr = load_point(s, o->point >= 0 ? o->point : 0, &sc, &first);
    if (fr != WW_OK && fails_every_point(fr)) {
        *err = first;
        r = fr;
        goto fail;
    }
    /* the scene's WAV files, by their headers, as every command that loads a scene checks them */
    if (fr == WW_OK) r = ww_audio_check(sc, err);
    if (!r && fr == WW_OK && o->thumbs && o->thumb_frame >= sc->frame_count) {
        r = ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--thumb-frame %lld is past the scene's %lld frames",
                         (long long)o->thumb_frame, (long long)sc->frame_count);
    }
    ww_scene_free(sc);
    if (r) goto fail;
    *out = s;
    return WW_OK;
fail:
    ww_sweep_free(s);
    return r;
}
