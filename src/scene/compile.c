/* compile.c - the second layer of the loader: the tree of yaml_tree.c, with --set applied, checked
 * and compiled into a ww_scene. One function per section over a shared layer of getters, each
 * value checked by a one-line rule (sokol's _SG_VALIDATE); the first error stops the load.
 */
#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/mathx.h"
#include "core/numfmt.h"
#include "core/rng.h"
#include "scene/assets.h"
#include "scene/compile_impl.h"
#include "scene/spectrum.h"

#define MAX_STEPS_PER_FRAME 1000000
#define EVENT_TIME_EPS 1e-9   /* s: an event at t fires on the step that reaches t - eps */

/* defaults of the wave keys (the rest are in ww_scene_defaults) */
#define DEFAULT_STEEPNESS 0.5    /* Gerstner Q of a component that gives none */
#define DEFAULT_EXPONENT 2.0     /* steep sines' e */
#define RANDOM_DEFAULT_COUNT 16  /* components of a water.waves.random with no count */
#define RIPPLE_DEFAULT_WAVENUMBER (2.0 * WW_TAU) /* rad/m: 0.5 m ripples */
#define WATER_SURFACE_TENSION 0.0728 /* sigma of clean water at 20 C, N/m */
#define WATER_DENSITY 1000.0         /* rho, kg/m^3 */
#define SPECTRUM_MIN_SLOPE 1e-6      /* sum k A of a spectrum's components below which the
                                      * sampled range holds no visible sea */

/* ---- rules ----------------------------------------------------------------------------------- */

/* every range of the schema, in file order; angles are checked in degrees */
static const rule R_SEED = WHOLE(0, 9007199254740991.0, ""); /* 2^53 - 1, exact in a double */
static const rule R_DT = OPEN_LO(0, 1, "s");
static const rule R_FPS = OPEN_LO(0, WW_FPS_MAX, "frames/s");
static const rule R_DURATION = OPEN_LO(0, WW_DURATION_MAX, "s");
static const rule R_START = CLOSED(0, WW_TIME_MAX, "s");
static const rule R_HOURS = CLOSED(0, 24, "h");
static const rule R_LEVEL = CLOSED(-1e6, 1e6, "m");
static const rule R_DEPTH = OPEN_LO(0, 1e4, "m");
static const rule R_WATER_COLOR = CLOSED(0, 1, "");
static const rule R_ANGLE = FINITE("deg");
static const rule R_DIR_VECTOR = FINITE("");
static const rule R_WAVELENGTH = CLOSED(0.001, 1e5, "m");
static const rule R_AMPLITUDE = CLOSED(0, 100, "m");
static const rule R_STEEPNESS = CLOSED(0, 1, "");
static const rule R_EXPONENT = CLOSED(1, 64, "");
static const rule R_WAVE_SPEED = CLOSED(0, 1e3, "m/s"); /* 0: deep-water dispersion */
static const rule R_SPEED = OPEN_LO(0, 1e3, "m/s");
static const rule R_RANDOM_COUNT = WHOLE(0, WW_MAX_WAVES, "");
static const rule R_RANDOM_SPREAD = CLOSED(0, 360, "deg");
static const rule R_WIND_SPEED = OPEN_LO(0, 100, "m/s");
static const rule R_FETCH = OPEN_LO(0, 1e8, "m");
static const rule R_PEAK_GAMMA = CLOSED(1, 10, "");
static const rule R_SPECTRUM_SPREAD = CLOSED(0, 180, "deg");
static const rule R_SPECTRUM_COUNT = WHOLE(1, WW_MAX_WAVES, "");
static const rule R_SPECTRUM_STEEPNESS = CLOSED(0, 0.95, "");
static const rule R_RIPPLE_AMPLITUDE = CLOSED(0, 10, "m");
static const rule R_RIPPLE_LIFETIME = OPEN_LO(0, 1e4, "s");
static const rule R_RIPPLE_MAX = WHOLE(1, WW_MAX_RIPPLES, "");
static const rule R_SPRAY = CLOSED(0, 4, "");
static const rule R_RADIAL_DECAY = CLOSED(0, 1e3, "1/m");
static const rule R_TIME_DECAY = CLOSED(0, 1e3, "1/s");
static const rule R_RIPPLE_WAVENUMBER = OPEN_LO(0, 1e4, "rad/m");
static const rule R_FOV = CLOSED(1, 179, "deg");
static const rule R_NEAR = OPEN_LO(0, 100, "m");
static const rule R_FAR_MAX = CLOSED(0, 1e7, "m"); /* lo is near, open: built in compile_camera */
static const rule R_KEY_TIME = CLOSED(0, WW_TIME_MAX, "s");
static const rule R_POSITION = FINITE("m");
static const rule R_PITCH = CLOSED(-89.9, 89.9, "deg");
static const rule R_EVENT_TIME = CLOSED(0, WW_TIME_MAX, "s");

/* script actions: an event holds "t" and exactly one of these; an action with a range is a
 * number, one without is read by its function from the event's mapping (compile_event) */
typedef ww_result (*action_fn)(ctx *c, const section *s, const ww_node *value, ww_event *ev);

typedef struct action {
    const char *key;
    ww_event_kind kind;
    const rule *range;
    action_fn parse;
} action;

static ww_result action_ripple(ctx *c, const section *s, const ww_node *value, ww_event *ev);

static const action ACTIONS[] = {
    {"time_of_day", WW_EV_TIME_OF_DAY, &R_HOURS, NULL},
    {"ripple", WW_EV_RIPPLE, NULL, action_ripple},
    {"throw", WW_EV_THROW, NULL, wwc_action_throw},     /* compile_stones.c */
    {"cast", WW_EV_CAST, NULL, wwc_action_cast},        /* compile_fishing.c */
    {"boat", WW_EV_BOAT, NULL, wwc_action_boat},        /* compile_boat.c */
    {"camera", WW_EV_CAMERA_MODE, NULL, wwc_action_camera}, /* compile_boat.c */
    {"press", WW_EV_PRESS, NULL, wwc_action_press},     /* compile_cubes.c */
    {"chest", WW_EV_CHEST, NULL, wwc_action_chest},     /* compile_reef.c */
};
#define NACTIONS ((int)(sizeof ACTIONS / sizeof ACTIONS[0]))

/* enum words, indexed by the enum value */
static const char *const SPECTRUM_WORDS[] = {[WW_SPECTRUM_PM] = "pierson_moskowitz",
                                             [WW_SPECTRUM_JONSWAP] = "jonswap", NULL};
static const char *const FOLD_WORDS[] = {[WW_FOLD_WARN] = "warn", [WW_FOLD_ERROR] = "error",
                                         [WW_FOLD_CLAMP] = "clamp", NULL};
static const char *const BOOL_WORDS[] = {"false", "true", NULL};
static const char *const INTERP_WORDS[] = {[WW_INTERP_CATMULL_ROM] = "catmull_rom",
                                           [WW_INTERP_LINEAR] = "linear", NULL};

/* ---- context --------------------------------------------------------------------------------- */

ww_result wwc_fail(ctx *c, ww_result code, const ww_node *at, const char *fmt, ...) {
    char msg[sizeof c->err->msg];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (!at) return ww_error_set(c->err, code, c->file, 0, 0, "%s", msg);
    return ww_error_set(c->err, code, at->mark.file, at->mark.line, at->mark.column, "%s", msg);
}

/* "FILE:LINE:COL: warning: ..." appended to the scene's warnings (the CLI prints them); past
 * WW_MAX_WARNINGS the rest are dropped */
void wwc_warn(ctx *c, const ww_node *at, const char *fmt, ...) {
    ww_scene *sc = c->sc;
    if (sc->nwarnings >= WW_MAX_WARNINGS) return;
    char msg[sizeof sc->warnings[0]];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    char *out = sc->warnings[sc->nwarnings++];
    int n = at ? snprintf(out, sizeof sc->warnings[0], "%s:%d:%d: warning: %s", at->mark.file,
                          at->mark.line, at->mark.column, msg)
               : snprintf(out, sizeof sc->warnings[0], "%s: warning: %s", c->file, msg);
    if (n < 0) out[0] = 0;
}

/* ---- words: lists, suggestions --------------------------------------------------------------- */

/* edit distance (Levenshtein 1966) with two rows; names longer than 63 bytes are never near */
static int levenshtein(const char *a, const char *b) {
    size_t na = strlen(a), nb = strlen(b);
    if (na > 63 || nb > 63) return 1 << 20;
    int prev[64], row[64];
    for (size_t j = 0; j <= nb; j++) prev[j] = (int)j;
    for (size_t i = 1; i <= na; i++) {
        row[0] = (int)i;
        for (size_t j = 1; j <= nb; j++) {
            int sub = prev[j - 1] + (a[i - 1] != b[j - 1]);
            int del = prev[j] + 1, ins = row[j - 1] + 1;
            row[j] = sub < del ? (sub < ins ? sub : ins) : (del < ins ? del : ins);
        }
        memcpy(prev, row, (nb + 1) * sizeof *row);
    }
    return prev[nb];
}

/* the nearest word, when near enough to be a likely typo: distance <= max(2, len/3) */
const char *wwc_nearest(const char *typed, const char *const *words) {
    int len = (int)strlen(typed), limit = len / 3 > 2 ? len / 3 : 2;
    const char *best = NULL;
    int best_d = limit + 1;
    for (int i = 0; words[i]; i++) {
        int d = levenshtein(typed, words[i]);
        if (d < best_d) {
            best_d = d;
            best = words[i];
        }
    }
    return best;
}

const char *wwc_join_words(const char *const *words, char *buf, size_t size) {
    size_t at = 0;
    buf[0] = 0;
    for (int i = 0; words[i] && at < size; i++) {
        int n = snprintf(buf + at, size - at, "%s%s", i ? ", " : "", words[i]);
        if (n < 0) break;
        at += (size_t)n;
    }
    return buf;
}

static int in_words(const char *s, const char *const *words) {
    for (int i = 0; words[i]; i++)
        if (strcmp(s, words[i]) == 0) return 1;
    return 0;
}

/* ---- numbers --------------------------------------------------------------------------------- */

typedef enum num_status { NUM_OK = 0, NUM_NOT_A_NUMBER, NUM_NONFINITE, NUM_DIV_ZERO } num_status;

/* YAML's .inf, -.Inf, .nan and the bare words inf, infinity, nan, in any case */
static int is_nonfinite_word(const char *s) {
    if (*s == '+' || *s == '-') s++;
    if (*s == '.') s++;
    return strcasecmp(s, "inf") == 0 || strcasecmp(s, "infinity") == 0 ||
           strcasecmp(s, "nan") == 0;
}

static int is_digit(char ch) { return ch >= '0' && ch <= '9'; }

/* a decimal literal [+-]digits[.digits][e[+-]digits], spaces around it allowed */
static int parse_decimal(const char *s, size_t n, double *out) {
    while (n && *s == ' ') s++, n--;
    while (n && s[n - 1] == ' ') n--;
    size_t i = 0, digits = 0;
    if (i < n && (s[i] == '+' || s[i] == '-')) i++;
    for (; i < n && is_digit(s[i]); i++) digits++;
    if (i < n && s[i] == '.')
        for (i++; i < n && is_digit(s[i]); i++) digits++;
    if (!digits) return 0;
    if (i < n && (s[i] == 'e' || s[i] == 'E')) {
        i++;
        if (i < n && (s[i] == '+' || s[i] == '-')) i++;
        size_t e = i;
        while (i < n && is_digit(s[i])) i++;
        if (i == e) return 0;
    }
    char buf[128];
    if (i != n || n >= sizeof buf) return 0;
    memcpy(buf, s, n);
    buf[n] = 0;
    *out = strtod(buf, NULL);
    return 1;
}

/* an integer, a float, or a fraction a/b (so that dt: 1/120 is exact to the last bit) */
static num_status parse_number(const char *text, double *out) {
    if (is_nonfinite_word(text)) return NUM_NONFINITE;
    const char *slash = strchr(text, '/');
    double v, a, b;
    if (!slash) {
        if (!parse_decimal(text, strlen(text), &v)) return NUM_NOT_A_NUMBER;
    } else {
        if (!parse_decimal(text, (size_t)(slash - text), &a) ||
            !parse_decimal(slash + 1, strlen(slash + 1), &b))
            return NUM_NOT_A_NUMBER;
        if (b == 0.0) return NUM_DIV_ZERO;
        v = a / b;
    }
    if (!isfinite(v)) return NUM_NONFINITE;
    *out = v;
    return NUM_OK;
}

static int in_range(const rule *r, double v) {
    return (r->lo_open ? v > r->lo : v >= r->lo) && (r->hi_open ? v < r->hi : v <= r->hi);
}

/* the shortest text that reads back as v (core/numfmt.h) */
static const char *num_text(double v, char *buf, size_t size) {
    ww_num_text(buf, size, v);
    return buf;
}

/* "(0, 1] s" */
static const char *range_text(const rule *r, char *buf, size_t size) {
    char lo[32], hi[32];
    snprintf(buf, size, "%c%s, %s%c%s%s", r->lo_open ? '(' : '[', num_text(r->lo, lo, sizeof lo),
             num_text(r->hi, hi, sizeof hi), r->hi_open ? ')' : ']', r->unit[0] ? " " : "",
             r->unit);
    return buf;
}

/* what a node is, for "expected X, got Y" */
static const char *describe(const ww_node *n, char *buf, size_t size) {
    if (n->kind == WW_NODE_MAP) return "a mapping";
    if (n->kind == WW_NODE_SEQ) {
        snprintf(buf, size, "a list of %d", n->n);
        return buf;
    }
    if (ww_node_is_null(n)) return "nothing (null)";
    if (n->quoted)
        snprintf(buf, size, "the string \"%.40s\"", n->text);
    else
        snprintf(buf, size, "'%.40s'", n->text);
    return buf;
}

/* one number under its rule; name is the dotted path for messages */
ww_result wwc_check_number(ctx *c, const ww_node *n, const char *name, const rule *r,
                              double *out) {
    const char *expected = r->integer ? "a whole number" : "a number";
    char got[80], range[96];
    double v = 0.0;

    /* quoted values are strings: "0.5" is not a number, on purpose */
    if (n->kind != WW_NODE_SCALAR || n->quoted || ww_node_is_null(n)) {
        int looks = n->kind == WW_NODE_SCALAR && n->quoted && parse_number(n->text, &v) == NUM_OK;
        return wwc_fail(c, WW_E_TYPE, n, "%s: expected %s, got %s%s", name, expected,
                    describe(n, got, sizeof got), looks ? " (quotes make it a string)" : "");
    }
    switch (parse_number(n->text, &v)) {
    case NUM_NOT_A_NUMBER:
        return wwc_fail(c, WW_E_TYPE, n, "%s: expected %s, got %s", name, expected,
                    describe(n, got, sizeof got));
    case NUM_NONFINITE:
        if (r->lo == -DBL_MAX)
            return wwc_fail(c, WW_E_NONFINITE, n, "%s: expected a finite number, got %s", name,
                        n->text);
        return wwc_fail(c, WW_E_NONFINITE, n, "%s: expected a finite number in %s, got %s", name,
                    range_text(r, range, sizeof range), n->text);
    case NUM_DIV_ZERO:
        return wwc_fail(c, WW_E_RANGE, n,
                    "%s: division by zero in %s: expected a fraction a/b with b != 0", name,
                    n->text);
    case NUM_OK: break;
    }
    if (r->integer && v != floor(v))
        return wwc_fail(c, WW_E_TYPE, n, "%s: expected a whole number, got %s", name, n->text);
    if (!in_range(r, v))
        return wwc_fail(c, WW_E_RANGE, n, "%s must be in %s, got %s", name,
                    range_text(r, range, sizeof range), n->text);
    *out = v;
    return WW_OK;
}

/* ---- getters: sections, values --------------------------------------------------------------- */

const char *wwc_where(const section *s) { return s->what[0] ? s->what : "the top level"; }

/* "section.key" */
const char *wwc_path_of(const section *s, const char *key, char *buf, size_t size) {
    if (snprintf(buf, size, "%s%s%s", s->what, s->what[0] ? "." : "", key) < 0) buf[0] = 0;
    return buf;
}

/* every key of the mapping must be in keys; else point at it and suggest the nearest */
ww_result wwc_check_keys(ctx *c, const section *s, const char *const *keys) {
    char list[256];
    for (const ww_node *v = s->map->first; v; v = v->next) {
        const char *k = v->key->text;
        if (in_words(k, keys)) continue;
        const char *near = wwc_nearest(k, keys);
        wwc_join_words(keys, list, sizeof list);
        if (near)
            return wwc_fail(c, WW_E_UNKNOWN_KEY, v->key,
                        "unknown key '%s' in %s: did you mean '%s'? (expected one of: %s)", k,
                        wwc_where(s), near, list);
        return wwc_fail(c, WW_E_UNKNOWN_KEY, v->key, "unknown key '%s' in %s: expected one of: %s",
                    k, wwc_where(s), list);
    }
    return WW_OK;
}

/* node as a section named what, holding only keys */
static ww_result open_map(ctx *c, const ww_node *node, const char *what,
                          const char *const *keys, section *out) {
    char got[80];
    out->map = NULL;
    snprintf(out->what, sizeof out->what, "%s", what);
    if (node->kind != WW_NODE_MAP)
        return wwc_fail(c, WW_E_TYPE, node, "%s: expected a mapping, got %s", what,
                    describe(node, got, sizeof got));
    out->map = node;
    return wwc_check_keys(c, out, keys);
}

/* the sub-mapping parent.key; out->map stays NULL when absent */
ww_result wwc_open_section(ctx *c, const section *parent, const char *key,
                              const char *const *keys, section *out) {
    char what[sizeof out->what];
    wwc_path_of(parent, key, what, sizeof what);
    const ww_node *node = parent->map ? ww_node_find(parent->map, key) : NULL;
    if (!node) {
        out->map = NULL;
        snprintf(out->what, sizeof out->what, "%s", what);
        return WW_OK;
    }
    return open_map(c, node, what, keys, out);
}

/* item i of the list named list_name */
ww_result wwc_open_item(ctx *c, const ww_node *item, const char *list_name, int i,
                           const char *const *keys, section *out) {
    char what[sizeof out->what];
    snprintf(what, sizeof what, "%s[%d]", list_name, i);
    return open_map(c, item, what, keys, out);
}

/* the value under key, NULL when absent; a missing REQUIRED key is reported at the mapping */
ww_result wwc_lookup(ctx *c, const section *s, const char *key, need nd, const ww_node **out) {
    *out = s->map ? ww_node_find(s->map, key) : NULL;
    if (*out || nd == OPTIONAL) return WW_OK;
    return wwc_fail(c, WW_E_MISSING, s->map, "%s is missing required key '%s'", wwc_where(s), key);
}

ww_result wwc_resolve_path(ctx *c, const ww_node *n, char *out, size_t size) {
    WW_ASSERT(n && n->kind == WW_NODE_SCALAR);
    const char *from = n->mark.file ? n->mark.file : c->file;
    const char *slash = from ? strrchr(from, '/') : NULL;
    int dir = n->text[0] == '/' || !slash ? 0 : (int)(slash - from) + 1;
    int len = snprintf(out, size, "%.*s%s", dir, from ? from : "", n->text);
    if (n->len == 0)
        return wwc_fail(c, WW_E_TYPE, n, "expected a file name, got an empty string");
    if (len < 0 || (size_t)len >= size)
        return wwc_fail(c, WW_E_RANGE, n, "the file name '%.60s...' is longer than %zu characters",
                        n->text, size - 1);
    /* looked at, not opened: opening a FIFO would wait for a writer. The file is read at load
     * and again when it is drawn or played, so it must be a regular file (a pipe gives its bytes
     * once, /dev/zero never ends) */
    struct stat st;
    if (stat(out, &st) != 0 || access(out, R_OK) != 0)
        return wwc_fail(c, WW_E_NOFILE, n, "cannot open '%s': %s", out, strerror(errno));
    if (S_ISDIR(st.st_mode))
        return wwc_fail(c, WW_E_NOFILE, n, "'%s' is a folder: expected a file", out);
    if (!S_ISREG(st.st_mode))
        return wwc_fail(c, WW_E_NOFILE, n,
                        "'%s' is not a regular file (a device, FIFO or socket): expected a file "
                        "that can be read twice, at load and when it is used",
                        out);
    return WW_OK;
}

/* the getters leave *out alone when an optional key is absent: it holds the default */
ww_result wwc_get_number(ctx *c, const section *s, const char *key, const rule *r, need nd,
                            double *out) {
    const ww_node *n;
    char name[128];
    TRY(wwc_lookup(c, s, key, nd, &n));
    return n ? wwc_check_number(c, n, wwc_path_of(s, key, name, sizeof name), r, out) : WW_OK;
}

/* written in degrees, stored in radians */
ww_result wwc_get_angle(ctx *c, const section *s, const char *key, const rule *r, need nd,
                           double *out) {
    const ww_node *n;
    char name[128];
    double deg;
    TRY(wwc_lookup(c, s, key, nd, &n));
    if (!n) return WW_OK;
    TRY(wwc_check_number(c, n, wwc_path_of(s, key, name, sizeof name), r, &deg));
    *out = ww_m_rad(deg);
    return WW_OK;
}

/* a list of exactly len numbers, each under r */
ww_result wwc_get_vec(ctx *c, const section *s, const char *key, int len, const rule *r,
                         need nd, double *out) {
    const ww_node *n;
    char name[128], item[144], got[80];
    double v[4];
    WW_ASSERT(len <= 4);
    TRY(wwc_lookup(c, s, key, nd, &n));
    if (!n) return WW_OK;
    wwc_path_of(s, key, name, sizeof name);
    if (n->kind != WW_NODE_SEQ || n->n != len)
        return wwc_fail(c, WW_E_TYPE, n, "%s: expected a list of %d %s, got %s", name, len,
                    r->integer ? "whole numbers" : "numbers", describe(n, got, sizeof got));
    int i = 0;
    for (const ww_node *e = n->first; e; e = e->next, i++) {
        snprintf(item, sizeof item, "%s[%d]", name, i);
        TRY(wwc_check_number(c, e, item, r, &v[i]));
    }
    memcpy(out, v, (size_t)len * sizeof *v);
    return WW_OK;
}

/* a heading: degrees (0 = +x, 90 = +z), or a vector [x, z] in the XZ plane, which must not be
 * zero; stored in radians */
ww_result wwc_get_heading(ctx *c, const section *s, const char *key, need nd, double *out) {
    const ww_node *n;
    char name[128];
    TRY(wwc_lookup(c, s, key, nd, &n));
    if (!n) return WW_OK;
    if (n->kind != WW_NODE_SEQ) return wwc_get_angle(c, s, key, &R_ANGLE, nd, out);
    double v[2];
    TRY(wwc_get_vec(c, s, key, 2, &R_DIR_VECTOR, nd, v));
    if (v[0] == 0.0 && v[1] == 0.0)
        return wwc_fail(c, WW_E_RANGE, n,
                    "%s: the vector [0, 0] has no direction: expected a heading in degrees or a "
                    "non-zero [x, z]",
                    wwc_path_of(s, key, name, sizeof name));
    *out = atan2(v[1], v[0]);
    return WW_OK;
}

/* a range [lo, hi] of two numbers under r with lo < hi, or lo <= hi when equal is allowed */
ww_result wwc_get_range(ctx *c, const section *s, const char *key, const rule *r,
                           int allow_equal, double out[2]) {
    const ww_node *n;
    char name[128];
    double v[2] = {out[0], out[1]};
    TRY(wwc_lookup(c, s, key, OPTIONAL, &n));
    if (!n) return WW_OK;
    TRY(wwc_get_vec(c, s, key, 2, r, OPTIONAL, v));
    if (allow_equal ? !(v[0] <= v[1]) : !(v[0] < v[1]))
        return wwc_fail(c, WW_E_INCONSISTENT, n, "%s = [%g, %g]: expected [lo, hi] with lo %s hi",
                    wwc_path_of(s, key, name, sizeof name), v[0], v[1], allow_equal ? "<=" : "<");
    out[0] = v[0];
    out[1] = v[1];
    return WW_OK;
}

/* one of words; *out is its index */
ww_result wwc_get_word(ctx *c, const section *s, const char *key, const char *const *words,
                          int *out) {
    const ww_node *n;
    char name[128], list[128], got[80];
    TRY(wwc_lookup(c, s, key, OPTIONAL, &n));
    if (!n) return WW_OK;
    wwc_path_of(s, key, name, sizeof name);
    wwc_join_words(words, list, sizeof list);
    if (n->kind != WW_NODE_SCALAR || ww_node_is_null(n))
        return wwc_fail(c, WW_E_TYPE, n, "%s: expected one of: %s, got %s", name, list,
                    describe(n, got, sizeof got));
    for (int i = 0; words[i]; i++) {
        if (strcmp(n->text, words[i]) == 0) {
            *out = i;
            return WW_OK;
        }
    }
    const char *near = wwc_nearest(n->text, words);
    if (near)
        return wwc_fail(c, WW_E_ENUM, n, "%s: '%s' is not one of: %s (did you mean '%s'?)", name,
                    n->text, list, near);
    return wwc_fail(c, WW_E_ENUM, n, "%s: '%s' is not one of: %s", name, n->text, list);
}

/* a list of at most max items; *out stays NULL when absent */
ww_result wwc_get_list(ctx *c, const section *s, const char *key, int max,
                          const ww_node **out) {
    char name[128], got[80];
    TRY(wwc_lookup(c, s, key, OPTIONAL, out));
    if (!*out) return WW_OK;
    wwc_path_of(s, key, name, sizeof name);
    if ((*out)->kind != WW_NODE_SEQ)
        return wwc_fail(c, WW_E_TYPE, *out, "%s: expected a list, got %s", name,
                    describe(*out, got, sizeof got));
    if ((*out)->n > max)
        return wwc_fail(c, WW_E_RANGE, *out, "%s has %d items: expected at most %d", name,
                    (*out)->n, max);
    return WW_OK;
}

/* the value node of the first present key, else the mapping: where to blame a combination */
static const ww_node *blame(const section *s, const char *a, const char *b) {
    const ww_node *n = s->map ? ww_node_find(s->map, a) : NULL;
    if (!n && s->map) n = ww_node_find(s->map, b);
    return n ? n : s->map;
}

/* one key looking at the origin from a little above the water */
static void default_camera(ww_scene *sc) {
    sc->cam[0] = (ww_camera_key){
        .t = 0.0, .position = {0.0, 2.0, 10.0}, .has_look_at = 1, .look_at = {0.0, 0.0, 0.0}};
    sc->ncam = 1;
}

/* ---- sections -------------------------------------------------------------------------------- */

static ww_result compile_time(ctx *c, const section *top) {
    static const char *const keys[] = {"dt", "fps", "duration", "start", "integrator", NULL};
    static const char *const integrators[] = {[WW_INTEGRATE_EXACT] = "exact",
                                              [WW_INTEGRATE_EULER] = "euler", NULL};
    ww_scene *sc = c->sc;
    section s;
    TRY(wwc_open_section(c, top, "time", keys, &s));
    int integrator = (int)sc->integrator;
    TRY(wwc_get_word(c, &s, "integrator", integrators, &integrator));
    sc->integrator = (ww_integrator)integrator;
    TRY(wwc_get_number(c, &s, "dt", &R_DT, OPTIONAL, &sc->dt));
    TRY(wwc_get_number(c, &s, "fps", &R_FPS, OPTIONAL, &sc->fps));
    TRY(wwc_get_number(c, &s, "duration", &R_DURATION, OPTIONAL, &sc->duration));
    TRY(wwc_get_number(c, &s, "start", &R_START, OPTIONAL, &sc->start));

    /* frames must land on steps: 1/(fps dt) whole within 1e-6 relative */
    const ww_node *at = blame(&s, "dt", "fps");
    double steps = 1.0 / (sc->fps * sc->dt);
    if (steps > MAX_STEPS_PER_FRAME)
        return wwc_fail(c, WW_E_RANGE, at,
                    "dt = %g is too small for fps = %g: 1/(fps*dt) = %.6g steps per frame, "
                    "expected at most %d",
                    sc->dt, sc->fps, steps, MAX_STEPS_PER_FRAME);
    long long n = llround(steps);
    if (n < 1 || fabs(steps - (double)n) > 1e-6 * steps) {
        char shown[32];
        snprintf(shown, sizeof shown, "%.2f", steps);
        if (fabs(steps - (double)n) < 0.005) snprintf(shown, sizeof shown, "%.9g", steps);
        return wwc_fail(c, WW_E_INCONSISTENT, at,
                    "dt must divide the frame interval 1/fps: 1/(%g*%g) = %s steps; expected a "
                    "whole number (for example dt: 1/%.15g)",
                    sc->fps, sc->dt, shown, sc->fps * (double)(n < 1 ? 1 : n));
    }
    sc->steps_per_frame = n;

    /* at least one frame */
    sc->frame_count = llround(sc->duration * sc->fps);
    if (sc->frame_count < 1)
        return wwc_fail(c, WW_E_RANGE, blame(&s, "duration", "fps"),
                    "duration * fps = %g frames: expected at least 1 frame (duration >= %g s)",
                    sc->duration * sc->fps, 0.5 / sc->fps);
    return WW_OK;
}

/* what the model makes of a component's steepness and exponent: each is checked whatever the
 * model and read only by the models it means something to (Q by gerstner, e by steep sines), so
 * one scene can be switched between families with a single --set or sweep axis */
static double model_steepness(ww_wave_model model, double q) {
    return model == WW_WAVES_SINES || model == WW_WAVES_STEEP_SINES ? 0.0 : q;
}

static double model_exponent(ww_wave_model model, double e) {
    return model == WW_WAVES_STEEP_SINES ? e : 1.0;
}

static ww_result compile_wave(ctx *c, const ww_node *item, int i, ww_wave_model model,
                              ww_wave *w) {
    static const char *const keys[] = {"direction", "wavelength", "amplitude", "steepness",
                                       "exponent", "phase", "speed", NULL};
    section s;
    TRY(wwc_open_item(c, item, "water.waves.list", i, keys, &s));
    *w = (ww_wave){.steepness = DEFAULT_STEEPNESS,
                   .exponent = DEFAULT_EXPONENT,
                   .line = s.map->mark.line,
                   .column = s.map->mark.column};
    double speed = 0.0;
    TRY(wwc_get_heading(c, &s, "direction", REQUIRED, &w->direction));
    TRY(wwc_get_number(c, &s, "wavelength", &R_WAVELENGTH, REQUIRED, &w->wavelength));
    TRY(wwc_get_number(c, &s, "amplitude", &R_AMPLITUDE, REQUIRED, &w->amplitude));
    TRY(wwc_get_number(c, &s, "steepness", &R_STEEPNESS, OPTIONAL, &w->steepness));
    TRY(wwc_get_number(c, &s, "exponent", &R_EXPONENT, OPTIONAL, &w->exponent));
    TRY(wwc_get_angle(c, &s, "phase", &R_ANGLE, OPTIONAL, &w->phase));
    TRY(wwc_get_number(c, &s, "speed", &R_WAVE_SPEED, OPTIONAL, &speed));
    w->steepness = model_steepness(model, w->steepness);
    w->exponent = model_exponent(model, w->exponent);
    ww_wave_derive(w, speed);
    return WW_OK;
}

/* water.waves.random: the description; count stays 0 when the section is absent */
static ww_result compile_random(ctx *c, const section *waves, ww_wave_model model, int nlisted,
                                section *s) {
    static const char *const keys[] = {"count",  "wavelength", "amplitude", "direction",
                                       "spread", "steepness",  "exponent",  NULL};
    ww_wave_random *r = &c->sc->wave_random;
    TRY(wwc_open_section(c, waves, "random", keys, s));
    if (!s->map) return WW_OK;
    double count = RANDOM_DEFAULT_COUNT;
    TRY(wwc_get_number(c, s, "count", &R_RANDOM_COUNT, OPTIONAL, &count));
    TRY(wwc_get_range(c, s, "wavelength", &R_WAVELENGTH, 0, r->wavelength));
    TRY(wwc_get_range(c, s, "amplitude", &R_AMPLITUDE, 1, r->amplitude));
    TRY(wwc_get_heading(c, s, "direction", OPTIONAL, &r->direction));
    TRY(wwc_get_angle(c, s, "spread", &R_RANDOM_SPREAD, OPTIONAL, &r->spread));
    TRY(wwc_get_number(c, s, "steepness", &R_STEEPNESS, OPTIONAL, &r->steepness));
    TRY(wwc_get_number(c, s, "exponent", &R_EXPONENT, OPTIONAL, &r->exponent));
    r->steepness = model_steepness(model, r->steepness);
    r->exponent = model_exponent(model, r->exponent);

    /* the list and the drawn components share the scene's WW_MAX_WAVES slots */
    if (nlisted + (int)count > WW_MAX_WAVES)
        return wwc_fail(c, WW_E_RANGE, blame(s, "count", "count"),
                    "%s.count = %d with %d listed waves makes %d components: expected at most "
                    "%d in all",
                    s->what, (int)count, nlisted, nlisted + (int)count, WW_MAX_WAVES);
    r->count = (int)count;
    return WW_OK;
}

/* the random components, appended after the list; drawn from the stream WW_RNG_WAVES in a fixed
 * order per component: wavelength (log-uniform), amplitude (uniform), heading (uniform in
 * direction +- spread / 2), phase (uniform) */
static void draw_random(ww_scene *sc, const ww_node *at) {
    const ww_wave_random *r = &sc->wave_random;
    ww_rng rng;
    ww_rng_seed(&rng, sc->seed, WW_RNG_WAVES);
    double ratio = r->wavelength[1] / r->wavelength[0];
    for (int i = 0; i < r->count; i++) {
        ww_wave *w = &sc->waves[sc->nwaves++];
        *w = (ww_wave){.steepness = r->steepness,
                       .exponent = r->exponent,
                       .line = at->mark.line,
                       .column = at->mark.column};
        w->wavelength = r->wavelength[0] * pow(ratio, ww_rng_uniform(&rng));
        w->amplitude = ww_m_lerp(r->amplitude[0], r->amplitude[1], ww_rng_uniform(&rng));
        w->direction = r->direction + r->spread * (ww_rng_uniform(&rng) - 0.5);
        w->phase = WW_TAU * ww_rng_uniform(&rng);
        ww_wave_derive(w, 0.0);
    }
}

/* water.waves.spectrum: read by model spectrum (and checked, then ignored, by flat) */
static ww_result compile_spectrum(ctx *c, const section *waves, ww_wave_model model,
                                  section *s) {
    static const char *const keys[] = {"kind",   "wind_speed", "fetch",      "gamma",
                                       "direction", "spread",  "count",      "wavelength",
                                       "steepness", NULL};
    ww_spectrum_desc *d = &c->sc->spectrum;
    TRY(wwc_open_section(c, waves, "spectrum", keys, s));
    if (!s->map) return WW_OK;
    if (model != WW_WAVES_SPECTRUM && model != WW_WAVES_FLAT)
        return wwc_fail(c, WW_E_INCONSISTENT, s->map->key,
                    "water.waves.spectrum is read only by model: spectrum, and the model is %s: "
                    "remove it, or set water.waves.model: spectrum",
                    ww_wave_model_words[model]);
    int kind = (int)d->kind;
    TRY(wwc_get_word(c, s, "kind", SPECTRUM_WORDS, &kind));
    d->kind = (ww_spectrum_kind)kind;
    TRY(wwc_get_number(c, s, "wind_speed", &R_WIND_SPEED, OPTIONAL, &d->wind_speed));
    TRY(wwc_get_number(c, s, "fetch", &R_FETCH, OPTIONAL, &d->fetch));
    TRY(wwc_get_number(c, s, "gamma", &R_PEAK_GAMMA, OPTIONAL, &d->gamma));
    TRY(wwc_get_heading(c, s, "direction", OPTIONAL, &d->direction));
    TRY(wwc_get_angle(c, s, "spread", &R_SPECTRUM_SPREAD, OPTIONAL, &d->spread));
    double count = d->count;
    TRY(wwc_get_number(c, s, "count", &R_SPECTRUM_COUNT, OPTIONAL, &count));
    d->count = (int)count;
    TRY(wwc_get_range(c, s, "wavelength", &R_WAVELENGTH, 0, d->wavelength));
    return wwc_get_number(c, s, "steepness", &R_SPECTRUM_STEEPNESS, OPTIONAL, &d->steepness);
}

/* water.fold: above sum Q k A = 1 the Gerstner surface can loop over itself: the Jacobian of
 * x -> x + D(x) is at least 1 - sum Q k A and reaches 0 where the crests line up (Tessendorf
 * 2001, "Simulating Ocean Water", on choppy waves; Finch 2004, GPU Gems ch. 1, for the Q) */
static ww_result check_fold(ctx *c, const section *waves) {
    ww_scene *sc = c->sc;
    double sum = ww_waves_fold_sum(sc);
    sc->fold_sum_given = sc->fold_sum = sum;
    if (!(sum > 1.0)) return WW_OK;
    WW_ASSERT(waves->map);
    const ww_node *at = waves->map->key ? waves->map->key : waves->map;
    switch (sc->fold) {
    case WW_FOLD_ERROR:
        return wwc_fail(c, WW_E_RANGE, at,
                    "water.waves: sum Q k A = %.6g > 1, so the Gerstner surface folds over "
                    "itself (margin 1 - sum = %.6g): expected at most 1 under water.fold: error "
                    "(warn keeps the waves as given, clamp scales every steepness to a sum of %g)",
                    sum, 1.0 - sum, WW_FOLD_CLAMP_SUM);
    case WW_FOLD_WARN:
        wwc_warn(c, at,
             "water.waves folds: sum Q k A = %.6g > 1, margin 1 - sum = %.6g (water.fold: warn "
             "keeps it; clamp scales the steepness, error refuses)",
             sum, 1.0 - sum);
        return WW_OK;
    case WW_FOLD_CLAMP: {
        double f = WW_FOLD_CLAMP_SUM / sum;
        for (int i = 0; i < sc->nwaves; i++) sc->waves[i].steepness *= f;
        sc->fold_sum = ww_waves_fold_sum(sc);
        wwc_warn(c, at,
             "water.waves folds: sum Q k A = %.6g > 1; water.fold: clamp scaled every steepness "
             "by %.6g to a sum of %.6g (margin %.6g)",
             sum, f, sc->fold_sum, 1.0 - sc->fold_sum);
        return WW_OK;
    }
    }
    return WW_OK;
}

static ww_result compile_waves(ctx *c, const section *water) {
    static const char *const keys[] = {"model", "list", "random", "spectrum", NULL};
    ww_scene *sc = c->sc;
    section s, rs, ss;
    const ww_node *list;
    TRY(wwc_open_section(c, water, "waves", keys, &s));
    int m = (int)sc->wave_model;
    TRY(wwc_get_word(c, &s, "model", ww_wave_model_words, &m));
    ww_wave_model model = (ww_wave_model)m;
    sc->wave_model = model;
    TRY(wwc_get_list(c, &s, "list", WW_MAX_WAVES, &list));

    /* the spectrum model samples its own components */
    const ww_node *own = list ? list : s.map ? ww_node_find(s.map, "random") : NULL;
    if (model == WW_WAVES_SPECTRUM && own)
        return wwc_fail(c, WW_E_INCONSISTENT, own->key,
                    "water.waves.%s is not read by model: spectrum (its components are sampled "
                    "from water.waves.spectrum): remove it, or use model gerstner, sines or "
                    "steep_sines",
                    own->key->text);

    /* the list, then the random draws; checked even when flat water ignores them */
    int i = 0;
    for (const ww_node *item = list ? list->first : NULL; item; item = item->next, i++)
        TRY(compile_wave(c, item, i, model, &sc->waves[i]));
    sc->nwaves = i;
    TRY(compile_random(c, &s, model, sc->nwaves, &rs));
    if (sc->wave_random.count > 0) draw_random(sc, rs.map);

    TRY(compile_spectrum(c, &s, model, &ss));
    if (model == WW_WAVES_SPECTRUM) {
        const ww_node *at = ss.map ? ss.map : s.map;
        const ww_spectrum_desc *d = &sc->spectrum;
        ww_spectrum_sample(d, sc->seed, sc->waves);
        sc->nwaves = d->count;
        double slope = 0.0, m0 = 0.0;
        for (int j = 0; j < sc->nwaves; j++) {
            const ww_wave *w = &sc->waves[j];
            slope += w->k * w->amplitude;
            m0 += 0.5 * w->amplitude * w->amplitude;
            sc->waves[j].line = at->mark.line;
            sc->waves[j].column = at->mark.column;
        }
        /* a range that misses the spectrum leaves an empty sea, and the one Q that would make
         * sum Q k A = steepness overflows (a float in the shader first) */
        if (slope < SPECTRUM_MIN_SLOPE) {
            double wp = ww_spectrum_peak(d);
            return wwc_fail(c, WW_E_INCONSISTENT, at,
                        "water.waves.spectrum: the wavelengths [%g, %g] m hold almost none of "
                        "this spectrum's energy (Hs = %.3g m, sum k A = %.3g): expected a range "
                        "nearer its peak at %.4g m",
                        d->wavelength[0], d->wavelength[1], 4.0 * sqrt(m0), slope,
                        WW_TAU * WW_G / (wp * wp));
        }
    }
    if (model == WW_WAVES_FLAT) {
        memset(sc->waves, 0, sizeof sc->waves);
        sc->nwaves = 0;
        sc->wave_random.count = 0;
    }
    return check_fold(c, &s);
}

/* capillary-gravity phase speed c = sqrt(g / k + sigma k / rho) (Lamb 1932, "Hydrodynamics",
 * sec. 267: w^2 = g k + sigma k^3 / rho in deep water) */
static double ripple_speed(double k) {
    return sqrt(WW_G / k + WATER_SURFACE_TENSION * k / WATER_DENSITY);
}

static ww_result compile_ripples(ctx *c, const section *water) {
    static const char *const keys[] = {"amplitude",  "lifetime",   "max",   "radial_decay",
                                       "time_decay", "wavenumber", "speed", "spray", NULL};
    ww_ripple_desc *d = &c->sc->ripples;
    section s;
    TRY(wwc_open_section(c, water, "ripples", keys, &s));
    if (!s.map) return WW_OK;
    c->sc->ripples_on = 1;
    double max = d->max;
    TRY(wwc_get_number(c, &s, "amplitude", &R_RIPPLE_AMPLITUDE, OPTIONAL, &d->amplitude));
    TRY(wwc_get_number(c, &s, "lifetime", &R_RIPPLE_LIFETIME, OPTIONAL, &d->lifetime));
    TRY(wwc_get_number(c, &s, "max", &R_RIPPLE_MAX, OPTIONAL, &max));
    d->max = (int)max;
    TRY(wwc_get_number(c, &s, "radial_decay", &R_RADIAL_DECAY, OPTIONAL, &d->radial_decay));
    TRY(wwc_get_number(c, &s, "time_decay", &R_TIME_DECAY, OPTIONAL, &d->time_decay));
    TRY(wwc_get_number(c, &s, "wavenumber", &R_RIPPLE_WAVENUMBER, OPTIONAL, &d->wavenumber));
    d->speed = ripple_speed(d->wavenumber);
    TRY(wwc_get_number(c, &s, "spray", &R_SPRAY, OPTIONAL, &d->spray));
    return wwc_get_number(c, &s, "speed", &R_SPEED, OPTIONAL, &d->speed);
}

static ww_result compile_water(ctx *c, const section *top) {
    static const char *const keys[] = {"level", "depth", "color", "fold", "waves", "ripples",
                                       "look", NULL};
    ww_scene *sc = c->sc;
    section s;
    TRY(wwc_open_section(c, top, "water", keys, &s));
    TRY(wwc_get_number(c, &s, "level", &R_LEVEL, OPTIONAL, &sc->water_level));
    TRY(wwc_get_number(c, &s, "depth", &R_DEPTH, OPTIONAL, &sc->water_depth));
    TRY(wwc_get_vec(c, &s, "color", 3, &R_WATER_COLOR, OPTIONAL, sc->water_color));
    int fold = (int)sc->fold;
    TRY(wwc_get_word(c, &s, "fold", FOLD_WORDS, &fold));
    sc->fold = (ww_fold_policy)fold;
    TRY(compile_waves(c, &s));
    TRY(compile_ripples(c, &s));
    return wwc_water_look(c, &s);
}

static ww_result compile_camera_key(ctx *c, const ww_node *item, int i, ww_camera_key *k) {
    static const char *const keys[] = {"t", "position", "look_at", "yaw", "pitch", "fov", NULL};
    section s;
    TRY(wwc_open_item(c, item, "camera.path", i, keys, &s));
    *k = (ww_camera_key){0};
    TRY(wwc_get_number(c, &s, "t", &R_KEY_TIME, REQUIRED, &k->t));
    TRY(wwc_get_vec(c, &s, "position", 3, &R_POSITION, REQUIRED, k->position));
    TRY(wwc_get_vec(c, &s, "look_at", 3, &R_POSITION, OPTIONAL, k->look_at));
    TRY(wwc_get_angle(c, &s, "yaw", &R_ANGLE, OPTIONAL, &k->yaw));
    TRY(wwc_get_angle(c, &s, "pitch", &R_PITCH, OPTIONAL, &k->pitch));
    TRY(wwc_get_angle(c, &s, "fov", &R_FOV, OPTIONAL, &k->fov));

    /* aim by look_at, or by yaw (and pitch), never both */
    const ww_node *look = ww_node_find(s.map, "look_at");
    const ww_node *yaw = ww_node_find(s.map, "yaw"), *pitch = ww_node_find(s.map, "pitch");
    if (!look && !yaw)
        return wwc_fail(c, WW_E_MISSING, s.map,
                    "%s is missing required key 'look_at' or 'yaw': expected one to aim the "
                    "camera",
                    s.what);
    if (look && (yaw || pitch)) {
        const ww_node *other = yaw ? yaw : pitch;
        return wwc_fail(c, WW_E_INCONSISTENT, other->key,
                    "%s has both look_at and %s: expected look_at alone, or yaw and pitch",
                    s.what, other->key->text);
    }
    k->has_look_at = look != NULL;
    if (look && memcmp(k->look_at, k->position, sizeof k->position) == 0)
        return wwc_fail(c, WW_E_INCONSISTENT, look,
                    "%s: look_at equals position, so the camera has no direction: expected "
                    "another point",
                    s.what);
    return WW_OK;
}

static ww_result compile_camera(ctx *c, const section *top) {
    static const char *const keys[] = {"fov", "near", "far", "interpolation", "collide", "path",
                                       NULL};
    ww_scene *sc = c->sc;
    section s;
    const ww_node *path;
    TRY(wwc_open_section(c, top, "camera", keys, &s));
    TRY(wwc_get_angle(c, &s, "fov", &R_FOV, OPTIONAL, &sc->fov));
    TRY(wwc_get_number(c, &s, "near", &R_NEAR, OPTIONAL, &sc->near_clip));
    rule far = R_FAR_MAX; /* (near, 1e7] */
    far.lo = sc->near_clip;
    far.lo_open = 1;
    TRY(wwc_get_number(c, &s, "far", &far, OPTIONAL, &sc->far_clip));
    int interp = (int)sc->interp;
    TRY(wwc_get_word(c, &s, "interpolation", INTERP_WORDS, &interp));
    sc->interp = (ww_interp)interp;
    TRY(wwc_get_word(c, &s, "collide", BOOL_WORDS, &sc->camera_collide));
    TRY(wwc_get_list(c, &s, "path", WW_MAX_KEYS, &path));
    /* no path is the default camera; an empty one is a path that lost its keys */
    if (path && path->n == 0)
        return wwc_fail(c, WW_E_RANGE, path,
                        "camera.path is an empty list: expected at least one key {t, position, "
                        "look_at} (or no path at all for the default camera)");

    /* keys in strictly increasing time */
    int i = 0;
    for (const ww_node *item = path ? path->first : NULL; item; item = item->next, i++) {
        ww_camera_key *k = &sc->cam[i];
        TRY(compile_camera_key(c, item, i, k));
        if (i > 0 && !(k->t > k[-1].t))
            return wwc_fail(c, WW_E_INCONSISTENT, ww_node_find(item, "t"),
                        "camera.path[%d].t = %g is not after camera.path[%d].t = %g: expected "
                        "key times to increase",
                        i, k->t, i - 1, k[-1].t);
    }
    sc->ncam = i;

    /* no path: the default key of ww_scene_defaults */
    if (sc->ncam == 0) default_camera(sc);
    return WW_OK;
}

/* {at: [x, z], amplitude: A0}: a ripple; A0 defaults to water.ripples.amplitude, and the event
 * turns the ripple pool on even without a water.ripples section */
static ww_result compile_ripple_event(ctx *c, const section *event, ww_event *ev) {
    static const char *const keys[] = {"at", "amplitude", NULL};
    section s;
    TRY(wwc_open_section(c, event, "ripple", keys, &s));
    ev->value = c->sc->ripples.amplitude;
    TRY(wwc_get_vec(c, &s, "at", 2, &R_POSITION, REQUIRED, ev->at));
    TRY(wwc_get_number(c, &s, "amplitude", &R_RIPPLE_AMPLITUDE, OPTIONAL, &ev->value));
    c->sc->ripples_on = 1;
    return WW_OK;
}

static ww_result action_ripple(ctx *c, const section *s, const ww_node *value, ww_event *ev) {
    (void)value;
    return compile_ripple_event(c, s, ev);
}

static ww_result compile_event(ctx *c, const ww_node *item, int i, ww_event *ev) {
    const char *keys[NACTIONS + 2] = {"t"};
    for (int a = 0; a < NACTIONS; a++) keys[a + 1] = ACTIONS[a].key;
    keys[NACTIONS + 1] = NULL;
    section s;
    TRY(wwc_open_item(c, item, "script", i, keys, &s));
    *ev = (ww_event){.line = s.map->mark.line,
                     .column = s.map->mark.column,
                     .in_script = s.map->mark.file && strcmp(s.map->mark.file, c->file) != 0};
    TRY(wwc_get_number(c, &s, "t", &R_EVENT_TIME, REQUIRED, &ev->t));

    /* exactly one action */
    const action *act = NULL;
    for (int a = 0; a < NACTIONS; a++) {
        const ww_node *n = ww_node_find(s.map, ACTIONS[a].key);
        if (!n) continue;
        if (act)
            return wwc_fail(c, WW_E_INCONSISTENT, n->key,
                        "%s has two actions, %s and %s: expected one action per event", s.what,
                        act->key, ACTIONS[a].key);
        act = &ACTIONS[a];
    }
    if (!act) {
        char list[128];
        return wwc_fail(c, WW_E_INCONSISTENT, s.map, "%s has no action: expected one of: %s",
                    s.what, wwc_join_words(keys + 1, list, sizeof list));
    }
    ev->kind = act->kind;
    if (act->range) return wwc_get_number(c, &s, act->key, act->range, REQUIRED, &ev->value);
    return act->parse(c, &s, ww_node_find(s.map, act->key), ev);
}

/* the scene's script list, then the --script file's (extra: its top level, or NULL); both are
 * validated alike, and the file's errors carry its own name and marks */
static ww_result compile_script(ctx *c, const section *top, const section *extra) {
    ww_scene *sc = c->sc;
    const ww_node *list;
    TRY(wwc_get_list(c, top, "script", WW_MAX_EVENTS, &list));
    int n = 0;
    for (const ww_node *item = list ? list->first : NULL; item; item = item->next, n++)
        TRY(compile_event(c, item, n, &sc->events[n]));
    if (extra) {
        static const char *const keys[] = {"script", NULL};
        TRY(wwc_check_keys(c, extra, keys));
        TRY(wwc_lookup(c, extra, "script", REQUIRED, &list));
        TRY(wwc_get_list(c, extra, "script", WW_MAX_EVENTS, &list));
        if (n + list->n > WW_MAX_EVENTS)
            return wwc_fail(c, WW_E_RANGE, list,
                            "script has %d items and the scene %d: expected at most %d together",
                            list->n, n, WW_MAX_EVENTS);
        int i = 0;
        for (const ww_node *item = list->first; item; item = item->next, i++, n++)
            TRY(compile_event(c, item, i, &sc->events[n]));
    }
    sc->nevents = n;

    /* stable insertion sort by time: equal times keep file order */
    for (int i = 1; i < n; i++) {
        ww_event e = sc->events[i];
        int j = i;
        for (; j > 0 && sc->events[j - 1].t > e.t; j--) sc->events[j] = sc->events[j - 1];
        sc->events[j] = e;
    }

    /* the first step n with start + n dt >= t - eps; events before start fire on step 0 */
    for (int i = 0; i < n; i++) {
        ww_event *e = &sc->events[i];
        double due = e->t - EVENT_TIME_EPS;
        int64_t step = due <= sc->start ? 0 : (int64_t)ceil((due - sc->start) / sc->dt);
        while (step > 0 && sc->start + (double)(step - 1) * sc->dt >= due) step--;
        while (sc->start + (double)step * sc->dt < due) step++;
        e->step = step;
    }
    return WW_OK;
}

/* objects: each system of the scripted world reads its own keys (compile_<system>.c) */
static ww_result compile_objects(ctx *c, const section *top) {
    static const char *const keys[] = {"cubes", "boat", "stones", "rod",   "fish",
                                       "chest", "bubbles", "models", NULL};
    section s;
    TRY(wwc_open_section(c, top, "objects", keys, &s));
    TRY(wwc_cubes(c, &s));
    TRY(wwc_boat(c, &s));
    TRY(wwc_stones(c, &s));
    TRY(wwc_fishing(c, &s));
    TRY(wwc_reef(c, &s));
    return wwc_floaters(c, &s);
}

/* ---- scene ----------------------------------------------------------------------------------- */

void ww_scene_defaults(ww_scene *sc) {
    *sc = (ww_scene){0};
    sc->seed = 1;
    sc->dt = 1.0 / 120.0;
    sc->fps = 30.0;
    sc->duration = 10.0;
    sc->start = 0.0;
    sc->width = 1280;
    sc->height = 720;
    sc->exposure = 1.0;
    sc->gamma = 2.2;
    sc->tonemap = WW_TONEMAP_ACES; /* keeps colour and contrast in the highlights */
    sc->dither = 1;                /* gradients darker than a few levels a band do not band */
    sc->time_of_day = 16.5;
    sc->day_length = 0.0;
    sc->sun_max_elevation = ww_m_rad(60.0);
    for (int i = 0; i < 3; i++) sc->fog_color[i] = -1.0;
    sc->fog_density = 0.0004;
    ww_render_defaults(&sc->render);
    ww_audio_defaults(&sc->audio);
    sc->water_level = 0.0;
    sc->water_depth = 8.0;
    sc->water_color[0] = 0.01;
    sc->water_color[1] = 0.07;
    sc->water_color[2] = 0.15;
    sc->wave_model = WW_WAVES_GERSTNER;
    sc->wave_random = (ww_wave_random){.count = 0,
                                       .wavelength = {2.0, 30.0},
                                       .amplitude = {0.02, 0.1},
                                       .direction = 0.0,
                                       .spread = ww_m_rad(90.0),
                                       .steepness = DEFAULT_STEEPNESS,
                                       .exponent = DEFAULT_EXPONENT};
    sc->spectrum = (ww_spectrum_desc){.kind = WW_SPECTRUM_PM,
                                      .wind_speed = 8.0,
                                      .fetch = 1e5,
                                      .gamma = 3.3,
                                      .direction = 0.0,
                                      .spread = ww_m_rad(20.0),
                                      .count = 32,
                                      .wavelength = {1.0, 300.0},
                                      .steepness = 0.5};
    sc->fold = WW_FOLD_WARN;
    sc->ripples_on = 0;
    sc->ripples = (ww_ripple_desc){.amplitude = 0.05,
                                   .lifetime = 4.0,
                                   .max = 64,
                                   .radial_decay = 0.25,
                                   .time_decay = 0.6,
                                   .wavenumber = RIPPLE_DEFAULT_WAVENUMBER,
                                   .speed = ripple_speed(RIPPLE_DEFAULT_WAVENUMBER),
                                   .spray = 1.0};
    sc->fov = ww_m_rad(60.0);
    sc->near_clip = 0.1;
    sc->far_clip = 5000.0;
    sc->interp = WW_INTERP_CATMULL_ROM;
    sc->camera_collide = 1;
    /* each system's defaults, off: code that builds a scene and turns one on gets the format's */
    ww_boat_defaults(&sc->boat);
    ww_stones_defaults(&sc->stones);
    ww_rod_defaults(&sc->rod);
    ww_fish_defaults(&sc->fish);
    ww_chest_defaults(&sc->chest);
    default_camera(sc);
    /* derived as compile_time derives them: 1 / (30 * 1/120) = 4 steps, 10 s * 30 fps */
    sc->steps_per_frame = 4;
    sc->frame_count = 300;
    ww_scene_plan_systems(sc);
}

/* path as given; name is the file name without folder and extension */
static void scene_names(ww_scene *sc, const char *path) {
    snprintf(sc->path, sizeof sc->path, "%s", path);
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    const char *dot = strrchr(base, '.');
    int n = dot && dot != base ? (int)(dot - base) : (int)strlen(base);
    snprintf(sc->name, sizeof sc->name, "%.*s", n, base);
}

/* root: the scene file's tree; script_root: the --script file's, or NULL */
static ww_result compile_scene(ctx *c, const ww_node *root, const ww_node *script_root) {
    static const char *const keys[] = {"seed", "time", "render", "sky", "fog", "water",
                                       "lights", "objects", "camera", "script", "audio",
                                       "golden", NULL};
    section top = {.map = root};
    TRY(wwc_check_keys(c, &top, keys));
    double seed = (double)c->sc->seed;
    TRY(wwc_get_number(c, &top, "seed", &R_SEED, OPTIONAL, &seed));
    c->sc->seed = (uint64_t)seed;
    TRY(compile_time(c, &top));
    TRY(wwc_render(c, &top));
    TRY(wwc_sky(c, &top));
    TRY(wwc_fog(c, &top));
    TRY(compile_water(c, &top));
    TRY(wwc_lights(c, &top));
    TRY(compile_objects(c, &top));
    TRY(compile_camera(c, &top));
    section script = {.map = script_root};
    TRY(compile_script(c, &top, script_root ? &script : NULL));
    TRY(wwc_audio(c, &top));
    TRY(wwc_golden(c, &top));
    TRY(wwc_check_lights(c, root));
    TRY(wwc_check_world(c));
    ww_scene_plan_systems(c->sc);
    return WW_OK;
}

/* apply the sets, compile, free the trees (script: the --script file's, may be NULL); *out only
 * on success */
static ww_result load_tree(ww_tree *t, ww_tree *script, const char *path, const ww_set *sets,
                           int nsets, ww_scene **out, ww_error *err) {
    ww_result r = WW_OK;
    for (int i = 0; i < nsets && r == WW_OK; i++) {
        WW_ASSERT(sets[i].text);
        r = ww_tree_set(t, i + 1, sets[i].text, err);
    }
    ww_scene *sc = NULL;
    if (r == WW_OK && !(sc = calloc(1, sizeof *sc)))
        r = ww_error_set(err, WW_E_NOMEM, path, 0, 0, "out of memory for the scene");
    if (r == WW_OK) {
        ctx c = {.sc = sc, .file = path, .err = err};
        ww_scene_defaults(sc);
        sc->ncam = 0; /* the file's path, or the default key when it has none */
        scene_names(sc, path);
        const ww_node *sroot = script ? ww_tree_root(script) : NULL;
        if (sroot && sroot->mark.file)
            snprintf(sc->script_path, sizeof sc->script_path, "%s", sroot->mark.file);
        r = compile_scene(&c, ww_tree_root(t), script ? ww_tree_root(script) : NULL);
    }
    ww_tree_free(t);
    if (script) ww_tree_free(script);
    if (r != WW_OK) {
        ww_scene_free(sc);
        return r;
    }
    *out = sc;
    return WW_OK;
}

ww_result ww_scene_load(const char *path, const ww_set *sets, int nsets, ww_scene **out,
                        ww_error *err) {
    WW_ASSERT(path && out && nsets >= 0);
    *out = NULL;
    ww_tree *t = NULL;
    TRY(ww_tree_load(path, &t, err));
    return load_tree(t, NULL, path, sets, nsets, out, err);
}

ww_result ww_scene_load_with_script(const char *path, const char *script_path, const ww_set *sets,
                                    int nsets, ww_scene **out, ww_error *err) {
    if (!script_path) return ww_scene_load(path, sets, nsets, out, err);
    WW_ASSERT(path && out && nsets >= 0);
    *out = NULL;
    ww_tree *t = NULL, *script = NULL;
    TRY(ww_tree_load(path, &t, err));
    ww_result r = ww_tree_load(script_path, &script, err);
    if (r != WW_OK) {
        ww_tree_free(t);
        return r;
    }
    return load_tree(t, script, path, sets, nsets, out, err);
}

ww_result ww_scene_load_string(const char *name, const char *text, size_t len, const ww_set *sets,
                               int nsets, ww_scene **out, ww_error *err) {
    WW_ASSERT(name && text && out && nsets >= 0);
    *out = NULL;
    ww_tree *t = NULL;
    TRY(ww_tree_parse(name, text, len, &t, err));
    return load_tree(t, NULL, name, sets, nsets, out, err);
}

void ww_scene_free(ww_scene *sc) {
    if (!sc) return;
    if (sc->assets) {
        ww_assets_free(sc->assets);
        free(sc->assets);
    }
    free(sc);
}
