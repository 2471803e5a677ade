/* obj.c - the Wavefront OBJ + MTL reader (scene/obj.h): one pass over the text collects
 * positions, uvs, normals and fanned triangles with their material ranges, then the corners are
 * welded per distinct (v, vt, vn) and missing normals are filled with area-weighted smooth ones.
 * Seeds 000 and 003 load their boat and wreck through GLM's glmReadOBJ, which has no bounds on
 * counts and trusts every index; here every index is checked and every count capped.
 */
#include "scene/obj.h"

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/numparse.h"
#include "scene/files.h"

/* the MTL defaults (Wavefront's: Kd 0.8 grey, no specular, opaque) */
static const float DEFAULT_KD = 0.8f;
static const float DEFAULT_NS = 32.0f;
#define NUMBER_CHARS 64 /* longest number token read */

/* a growable array of fixed-size elements, capped at max elements */
typedef struct vec {
    void *p;
    size_t n, cap, size, max;
} vec;

static int vec_push(vec *v, const void *elem) {
    if (v->n >= v->max) return 0;
    if (v->n == v->cap) {
        size_t cap = v->cap ? v->cap * 2 : 64;
        if (cap > v->max) cap = v->max;
        if (cap > SIZE_MAX / v->size) return 0;
        void *p = realloc(v->p, cap * v->size);
        if (!p) return 0;
        v->p = p;
        v->cap = cap;
    }
    memcpy((char *)v->p + v->n * v->size, elem, v->size);
    v->n++;
    return 1;
}

/* one line of text being read */
typedef struct cur {
    const char *p, *end, *bol; /* position, end of text, beginning of the line */
    int line;
    const char *file;
} cur;

static int is_blank(char ch) { return ch == ' ' || ch == '\t' || ch == '\r' || ch == '\0'; }

static void skip_blank(cur *c) {
    while (c->p < c->end && is_blank(*c->p)) c->p++;
}

static int column(const cur *c) { return (int)(c->p - c->bol) + 1; }

/* at the end of the line's content (end of text, newline or a comment) after blanks */
static int at_eol(cur *c) {
    skip_blank(c);
    return c->p >= c->end || *c->p == '\n' || *c->p == '#';
}

/* the next whitespace-separated token; its length (0 at the end of the line) */
static size_t token(cur *c, const char **s) {
    if (at_eol(c)) return 0;
    *s = c->p;
    while (c->p < c->end && !is_blank(*c->p) && *c->p != '\n') c->p++;
    return (size_t)(c->p - *s);
}

/* the rest of the line's content without surrounding blanks (names with spaces) */
static size_t rest_of_line(cur *c, const char **s) {
    if (at_eol(c)) return 0;
    *s = c->p;
    const char *e = c->p;
    while (e < c->end && *e != '\n') e++;
    c->p = e;
    while (e > *s && is_blank(e[-1])) e--;
    return (size_t)(e - *s);
}

static void next_line(cur *c) {
    while (c->p < c->end && *c->p != '\n') c->p++;
    if (c->p < c->end) c->p++;
    c->bol = c->p;
    c->line++;
}

static ww_result fail(const cur *c, ww_result code, int col, ww_error *err, const char *fmt,
                      const char *a) {
    char msg[160];
    snprintf(msg, sizeof msg, fmt, a);
    return ww_error_set(err, code, c->file, c->line, col, "%s", msg);
}

/* a finite number token */
static ww_result number(cur *c, const char *what, double *out, ww_error *err) {
    const char *s;
    int col = (skip_blank(c), column(c));
    size_t n = token(c, &s);
    char buf[NUMBER_CHARS + 1];
    if (n == 0) return fail(c, WW_E_SYNTAX, col, err, "%s: expected a number, got the end of the line", what);
    if (n > NUMBER_CHARS) return fail(c, WW_E_SYNTAX, col, err, "%s: number too long", what);
    if (ww_parse_decimal(s, n, out)) return WW_OK; /* a short decimal: strtod's value, faster */
    memcpy(buf, s, n);
    buf[n] = '\0';
    char *e;
    errno = 0;
    *out = strtod(buf, &e);
    if (e != buf + n || !isfinite(*out)) {
        char msg[128];
        snprintf(msg, sizeof msg, "%s: '%s' is not a finite number", what, buf);
        return fail(c, WW_E_SYNTAX, col, err, "%s", msg);
    }
    return WW_OK;
}

/* n numbers into out (float) */
static ww_result numbers(cur *c, const char *what, int n, float *out, ww_error *err) {
    for (int i = 0; i < n; i++) {
        double d = 0.0;
        ww_result r = number(c, what, &d, err);
        if (r != WW_OK) return r;
        if (fabs(d) > 3.0e38) return fail(c, WW_E_RANGE, column(c), err, "%s: number beyond float range", what);
        out[i] = (float)d;
    }
    return WW_OK;
}

/* dir of `from` + name (name as is when absolute); 0 when it does not fit */
static int join_path(char *out, size_t size, const char *from, const char *name, size_t len) {
    const char *slash = strrchr(from, '/');
    int dir = name[0] == '/' || !slash ? 0 : (int)(slash - from) + 1;
    int n = snprintf(out, size, "%.*s%.*s", dir, from, (int)len, name);
    return n >= 0 && (size_t)n < size;
}

void ww_mesh_data_free(ww_mesh_data *m) {
    free(m->vertex);
    free(m->index);
    free(m->sub);
    free(m->material);
    *m = (ww_mesh_data){0};
}

/* OBJ and MTL are text: a NUL byte means a binary file (a binary STL or glTF, a compressed
 * model), which would otherwise read as lines of unknown keywords and no faces */
static ww_result check_text(const char *path, const char *text, size_t len, ww_error *err) {
    const char *nul = memchr(text, 0, len);
    if (!nul) return WW_OK;
    int line = 1, col = 1;
    for (const char *p = text; p < nul; p++) {
        if (*p == '\n') {
            line++;
            col = 1;
        } else {
            col++;
        }
    }
    return ww_error_set(err, WW_E_SYNTAX, path, line, col,
                        "a NUL byte: '%s' is not a text file (expected Wavefront OBJ/MTL text)",
                        path);
}

/* ---- MTL ---------------------------------------------------------------------------------- */

static ww_material default_material(void) {
    return (ww_material){.diffuse = {DEFAULT_KD, DEFAULT_KD, DEFAULT_KD},
                         .shininess = DEFAULT_NS,
                         .opacity = 1.0f,
                         .texture = -1};
}

/* Kd / Ks / Ke: r [g b] (one value means grey) */
static ww_result color(cur *c, const char *what, float out[3], ww_error *err) {
    ww_result r = numbers(c, what, 1, out, err);
    if (r != WW_OK) return r;
    if (at_eol(c)) {
        out[1] = out[2] = out[0];
        return WW_OK;
    }
    return numbers(c, what, 2, out + 1, err);
}

static ww_result parse_mtl(const ww_obj_textures *tx, const char *path, const char *text, size_t len, vec *mats,
                           ww_error *err) {
    cur c = {.p = text, .end = text + len, .bol = text, .line = 1, .file = path};
    ww_material *m = NULL;
    ww_result r = check_text(path, text, len, err);
    for (; c.p < c.end && r == WW_OK; next_line(&c)) {
        const char *kw;
        int col = (skip_blank(&c), column(&c));
        size_t n = token(&c, &kw);
        if (n == 0) continue;
#define IS(word) (n == sizeof(word) - 1 && memcmp(kw, word, n) == 0)
        if (IS("newmtl")) {
            const char *name;
            int ncol = (skip_blank(&c), column(&c));
            size_t nl = rest_of_line(&c, &name);
            ww_material nm = default_material();
            if (nl == 0 || nl >= sizeof nm.name)
                return fail(&c, WW_E_SYNTAX, ncol, err, "%s", nl ? "newmtl: name longer than 63 characters" : "newmtl: expected a name");
            memcpy(nm.name, name, nl);
            if (!vec_push(mats, &nm))
                return fail(&c, WW_E_RANGE, col, err, "more than %s materials", "256");
            m = (ww_material *)mats->p + mats->n - 1;
            continue;
        }
        int prop = IS("Kd") || IS("Ks") || IS("Ke") || IS("Ns") || IS("d") || IS("Tr") ||
                   IS("map_Kd");
        if (!prop) continue; /* Ka, illum, Ni, map_Bump, ...: not drawn */
        if (!m) return fail(&c, WW_E_SYNTAX, col, err, "%s", "a material property before any newmtl");
        if (IS("Kd")) r = color(&c, "Kd", m->diffuse, err);
        else if (IS("Ks")) r = color(&c, "Ks", m->specular, err);
        else if (IS("Ke")) r = color(&c, "Ke", m->emission, err);
        else if (IS("Ns")) r = numbers(&c, "Ns", 1, &m->shininess, err);
        else if (IS("d")) r = numbers(&c, "d", 1, &m->opacity, err);
        else if (IS("Tr")) {
            float tr;
            r = numbers(&c, "Tr", 1, &tr, err);
            m->opacity = 1.0f - tr;
        } else {
            /* map_Kd [-option value...] file: options start with '-', the file is the last
             * token; without options the rest of the line (names with spaces) */
            const char *name;
            int fcol = (skip_blank(&c), column(&c));
            size_t nl;
            if (c.p < c.end && *c.p == '-') {
                const char *t;
                size_t tl;
                nl = 0;
                while ((tl = token(&c, &t)) > 0) {
                    fcol = column(&c) - (int)tl;
                    name = t;
                    nl = tl;
                }
            } else {
                nl = rest_of_line(&c, &name);
            }
            if (nl == 0) return fail(&c, WW_E_SYNTAX, fcol, err, "%s", "map_Kd: expected a file name");
            char file[WW_ASSET_PATH];
            if (!join_path(file, sizeof file, path, name, nl))
                return fail(&c, WW_E_RANGE, fcol, err, "%s", "map_Kd: file name too long");
            r = tx->load(tx->ctx, file, path, c.line, fcol, &m->texture, err);
            continue;
        }
#undef IS
    }
    return r;
}

/* ---- OBJ ---------------------------------------------------------------------------------- */

typedef struct corner {
    int v, t, n; /* 0-based indices, -1 absent */
} corner;

typedef struct sub {
    size_t first;  /* first triangle */
    int material;
} sub;

typedef struct obj {
    vec pos, uv, nrm;  /* float x3, x2, x3 */
    vec tri;           /* corner x3 */
    vec subs;          /* sub */
    vec mats;          /* ww_material */
    int nlib;
} obj;

static void obj_free(obj *o) {
    free(o->pos.p);
    free(o->uv.p);
    free(o->nrm.p);
    free(o->tri.p);
    free(o->subs.p);
    free(o->mats.p);
}

/* one index of a corner: 1-based, or negative from the end of what is read so far */
static ww_result index_of(cur *c, const char *s, size_t n, int col, size_t count, const char *what,
                          int *out, ww_error *err) {
    char buf[NUMBER_CHARS + 1];
    if (n == 0 || n > NUMBER_CHARS)
        return fail(c, WW_E_SYNTAX, col, err, "f: expected a %s index", what);
    long v;
    if (!ww_parse_integer(s, n, &v)) { /* not a short whole number: strtol says what it is */
        memcpy(buf, s, n);
        buf[n] = '\0';
        char *e;
        errno = 0;
        v = strtol(buf, &e, 10);
        if (e != buf + n || errno)
            return fail(c, WW_E_SYNTAX, col, err, "f: '%s' is not a whole number", buf);
    }
    long i = v > 0 ? v - 1 : (long)count + v;
    if (v == 0 || i < 0 || (size_t)i >= count) {
        char msg[128];
        snprintf(msg, sizeof msg, "f: %s index %ld is out of range: %zu read so far", what, v,
                 count);
        return fail(c, WW_E_RANGE, col, err, "%s", msg);
    }
    *out = (int)i;
    return WW_OK;
}

static ww_result parse_corner(cur *c, obj *o, const char *s, size_t n, corner *k, ww_error *err) {
    int col = column(c) - (int)n;
    const char *slash1 = memchr(s, '/', n);
    const char *slash2 = slash1 ? memchr(slash1 + 1, '/', (size_t)(s + n - slash1 - 1)) : NULL;
    *k = (corner){-1, -1, -1};
    size_t nv = slash1 ? (size_t)(slash1 - s) : n;
    ww_result r = index_of(c, s, nv, col, o->pos.n, "vertex", &k->v, err);
    if (r != WW_OK || !slash1) return r;
    const char *t = slash1 + 1;
    size_t nt = slash2 ? (size_t)(slash2 - t) : (size_t)(s + n - t);
    if (nt > 0 || !slash2) {
        r = index_of(c, t, nt, col + (int)(t - s), o->uv.n, "texture", &k->t, err);
        if (r != WW_OK) return r;
    }
    if (!slash2) return WW_OK;
    const char *q = slash2 + 1;
    return index_of(c, q, (size_t)(s + n - q), col + (int)(q - s), o->nrm.n, "normal", &k->n, err);
}

/* col: the column of the line's `f`, for errors about the whole polygon */
static ww_result parse_face(cur *c, obj *o, int col, ww_error *err) {
    corner first = {0, 0, 0}, prev = {0, 0, 0}, k;
    int count = 0;
    const char *s;
    size_t n;
    while ((n = token(c, &s)) > 0) {
        ww_result r = parse_corner(c, o, s, n, &k, err);
        if (r != WW_OK) return r;
        if (++count > WW_OBJ_MAX_CORNERS)
            return fail(c, WW_E_RANGE, col, err, "f: more than %s corners", "256");
        /* fan from the first corner: (0, i - 1, i) */
        if (count >= 3) {
            corner t[3] = {first, prev, k};
            if (!vec_push(&o->tri, t))
                return fail(c, WW_E_RANGE, col, err, "more than %s triangles (or out of memory)",
                            "4194304");
        }
        if (count == 1) first = k;
        prev = k;
    }
    if (count < 3) return fail(c, WW_E_SYNTAX, col, err, "%s", "f: expected at least 3 corners");
    return WW_OK;
}

static ww_result parse_mtllib(cur *c, const ww_obj_textures *tx, obj *o, ww_error *err) {
    const char *s;
    size_t n;
    int any = 0;
    while ((n = token(c, &s)) > 0) {
        int col = column(c) - (int)n;
        char file[WW_ASSET_PATH];
        any = 1;
        if (++o->nlib > WW_OBJ_MAX_LIBRARIES)
            return fail(c, WW_E_RANGE, col, err, "more than %s mtllib files", "16");
        if (!join_path(file, sizeof file, c->file, s, n))
            return fail(c, WW_E_RANGE, col, err, "%s", "mtllib: file name too long");
        char *text;
        size_t len;
        ww_result r = ww_file_read_named(file, WW_OBJ_MAX_BYTES, c->file, c->line, col, &text,
                                         &len, err);
        if (r != WW_OK) return r;
        r = parse_mtl(tx, file, text, len, &o->mats, err);
        free(text);
        if (r != WW_OK) return ww_file_named_at(r, c->file, c->line, col, err);
    }
    if (!any) return fail(c, WW_E_SYNTAX, column(c), err, "%s", "mtllib: expected a file name");
    return WW_OK;
}

static ww_result parse_usemtl(cur *c, obj *o, ww_error *err) {
    const char *s;
    int col = (skip_blank(c), column(c));
    size_t n = rest_of_line(c, &s);
    int found = -1;
    const ww_material *m = o->mats.p;
    for (size_t i = 0; i < o->mats.n && found < 0; i++)
        if (strlen(m[i].name) == n && memcmp(m[i].name, s, n) == 0) found = (int)i;
    if (found < 0) {
        char name[64];
        snprintf(name, sizeof name, "%.*s", n > 60 ? 60 : (int)n, s);
        return fail(c, WW_E_MISSING, col, err,
                    "usemtl '%s' names no material of the mtllib files read before it", name);
    }
    sub *last = o->subs.n ? (sub *)o->subs.p + o->subs.n - 1 : NULL;
    if (last && last->first == o->tri.n) {
        last->material = found; /* the previous material covered no face */
        return WW_OK;
    }
    sub nsub = {o->tri.n, found};
    if (!vec_push(&o->subs, &nsub))
        return fail(c, WW_E_RANGE, col, err, "%s", "too many usemtl changes (or out of memory)");
    return WW_OK;
}

/* weld corners per distinct (v, vt, vn): open addressing over a power-of-two table */
static uint32_t corner_hash(const corner *k) {
    uint32_t h = (uint32_t)k->v * 0x9E3779B1u;
    h ^= (uint32_t)(k->t + 1) * 0x85EBCA77u;
    h ^= (uint32_t)(k->n + 1) * 0xC2B2AE3Du;
    return h ^ (h >> 15);
}

static ww_result build(obj *o, const char *path, ww_mesh_data *m, ww_error *err) {
    size_t ntri = o->tri.n, ncorner = 3 * ntri;
    const corner *tri = o->tri.p;
    const float *pos = o->pos.p, *uv = o->uv.p, *nrm = o->nrm.p;
    if (ntri == 0)
        return ww_error_set(err, WW_E_EMPTY, path, 0, 0, "'%s' holds no faces", path);

    /* area-weighted face normals summed per position, for corners without vn: the cross
     * product's length is twice the triangle's area */
    double *acc = calloc(o->pos.n * 3, sizeof *acc);
    size_t cap = 1;
    while (cap < 2 * ncorner) cap *= 2;
    int32_t *table = malloc(cap * sizeof *table);
    corner *keys = malloc(ncorner * sizeof *keys);
    m->index = malloc(ncorner * sizeof *m->index);
    if (!acc || !table || !keys || !m->index) {
        free(acc);
        free(table);
        free(keys);
        return ww_error_set(err, WW_E_NOMEM, path, 0, 0, "out of memory reading '%s'", path);
    }
    for (size_t f = 0; f < ntri; f++) {
        const float *p0 = pos + 3 * tri[3 * f].v, *p1 = pos + 3 * tri[3 * f + 1].v,
                    *p2 = pos + 3 * tri[3 * f + 2].v;
        double e1[3], e2[3];
        for (int i = 0; i < 3; i++) {
            e1[i] = (double)p1[i] - p0[i];
            e2[i] = (double)p2[i] - p0[i];
        }
        double cr[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                        e1[0] * e2[1] - e1[1] * e2[0]};
        for (int k = 0; k < 3; k++)
            for (int i = 0; i < 3; i++) acc[3 * tri[3 * f + k].v + i] += cr[i];
    }

    /* weld */
    for (size_t i = 0; i < cap; i++) table[i] = -1;
    size_t nvert = 0;
    for (size_t i = 0; i < ncorner; i++) {
        const corner *k = &tri[i];
        size_t h = corner_hash(k) & (cap - 1);
        while (table[h] >= 0) {
            const corner *q = &keys[table[h]];
            if (q->v == k->v && q->t == k->t && q->n == k->n) break;
            h = (h + 1) & (cap - 1);
        }
        if (table[h] < 0) {
            table[h] = (int32_t)nvert;
            keys[nvert++] = *k;
        }
        m->index[i] = (uint32_t)table[h];
    }
    free(table);

    m->vertex = malloc(nvert * 8 * sizeof *m->vertex);
    m->sub = malloc((o->subs.n + 1) * sizeof *m->sub);
    if (!m->vertex || !m->sub) {
        free(acc);
        free(keys);
        return ww_error_set(err, WW_E_NOMEM, path, 0, 0, "out of memory reading '%s'", path);
    }
    m->nvert = (int)nvert;
    m->nindex = (uint32_t)ncorner;
    for (int a = 0; a < 3; a++) {
        m->min[a] = HUGE_VAL;
        m->max[a] = -HUGE_VAL;
    }
    for (size_t i = 0; i < nvert; i++) {
        const corner *k = &keys[i];
        float *out = m->vertex + 8 * i;
        double nv[3];
        for (int a = 0; a < 3; a++) {
            out[a] = pos[3 * k->v + a];
            if (out[a] < m->min[a]) m->min[a] = out[a];
            if (out[a] > m->max[a]) m->max[a] = out[a];
            nv[a] = k->n >= 0 ? nrm[3 * k->n + a] : acc[3 * k->v + a];
        }
        double len = sqrt(nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2]);
        if (!(len > 0.0) && k->n >= 0) { /* a zero vn: fall back to the computed one */
            for (int a = 0; a < 3; a++) nv[a] = acc[3 * k->v + a];
            len = sqrt(nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2]);
        }
        for (int a = 0; a < 3; a++)
            out[3 + a] = len > 0.0 && isfinite(len) ? (float)(nv[a] / len) : (a == 1 ? 1.0f : 0.0f);
        out[6] = k->t >= 0 ? uv[2 * k->t] : 0.0f;
        out[7] = k->t >= 0 ? 1.0f - uv[2 * k->t + 1] : 0.0f;
    }
    free(acc);
    free(keys);

    /* submeshes: the faces before the first usemtl take the default material */
    const sub *s = o->subs.p;
    int ns = 0;
    if (o->subs.n == 0 || s[0].first > 0)
        m->sub[ns++] = (ww_submesh){0, (uint32_t)(3 * (o->subs.n ? s[0].first : ntri)), -1};
    for (size_t i = 0; i < o->subs.n; i++) {
        size_t end = i + 1 < o->subs.n ? s[i + 1].first : ntri;
        if (end == s[i].first) continue;
        m->sub[ns++] = (ww_submesh){(uint32_t)(3 * s[i].first),
                                    (uint32_t)(3 * (end - s[i].first)), s[i].material};
    }
    m->nsub = ns;
    m->nmaterial = (int)o->mats.n;
    m->material = o->mats.p;
    o->mats.p = NULL;
    return WW_OK;
}

ww_result ww_obj_parse(const ww_obj_textures *tx, const char *path, const char *text, size_t len,
                       ww_mesh_data *out, ww_error *err) {
    obj o = {.pos = {.size = 3 * sizeof(float), .max = WW_OBJ_MAX_ELEMENTS},
             .uv = {.size = 2 * sizeof(float), .max = WW_OBJ_MAX_ELEMENTS},
             .nrm = {.size = 3 * sizeof(float), .max = WW_OBJ_MAX_ELEMENTS},
             .tri = {.size = 3 * sizeof(corner), .max = WW_OBJ_MAX_ELEMENTS},
             .subs = {.size = sizeof(sub), .max = WW_OBJ_MAX_ELEMENTS},
             .mats = {.size = sizeof(ww_material), .max = WW_OBJ_MAX_MATERIALS}};
    cur c = {.p = text, .end = text + len, .bol = text, .line = 1, .file = path};
    *out = (ww_mesh_data){0};
    snprintf(out->path, sizeof out->path, "%s", path);
    ww_result r = check_text(path, text, len, err);
    for (; c.p < c.end && r == WW_OK; next_line(&c)) {
        const char *kw;
        int col = (skip_blank(&c), column(&c));
        size_t n = token(&c, &kw);
        if (n == 0) continue;
        float f[3] = {0.0f, 0.0f, 0.0f};
        vec *into = NULL;
        if (n == 1 && kw[0] == 'v') {
            r = numbers(&c, "v", 3, f, err);
            into = &o.pos;
        } else if (n == 2 && kw[0] == 'v' && kw[1] == 't') {
            r = numbers(&c, "vt", 1, f, err);
            if (r == WW_OK && !at_eol(&c)) r = numbers(&c, "vt", 1, f + 1, err);
            into = &o.uv;
        } else if (n == 2 && kw[0] == 'v' && kw[1] == 'n') {
            r = numbers(&c, "vn", 3, f, err);
            into = &o.nrm;
        } else if (n == 1 && kw[0] == 'f') {
            r = parse_face(&c, &o, col, err);
        } else if (n == 6 && memcmp(kw, "mtllib", 6) == 0) {
            r = parse_mtllib(&c, tx, &o, err);
        } else if (n == 6 && memcmp(kw, "usemtl", 6) == 0) {
            r = parse_usemtl(&c, &o, err);
        }
        if (r == WW_OK && into && !vec_push(into, f))
            r = ww_error_set(err, WW_E_RANGE, path, c.line, col,
                             "more than %d '%.*s' lines (or out of memory)", WW_OBJ_MAX_ELEMENTS,
                             (int)n, kw);
    }
    if (r == WW_OK) r = build(&o, path, out, err);
    obj_free(&o);
    if (r != WW_OK) ww_mesh_data_free(out);
    return r;
}
