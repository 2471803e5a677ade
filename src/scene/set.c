/* set.c - --set KEY=VALUE overrides, applied to the tree before it is compiled, so that a value
 * from the command line is validated exactly like one from the file. New nodes carry the mark
 * "--set[N]:1:column", the column counted in the full KEY=VALUE text.
 */
#include <stdio.h>
#include <string.h>

#include "scene/tree.h"

#define SET_MAX_SEGMENTS 32
#define SET_MAX_INDEX 1000000

/* one step of the path: a name (".amplitude") or a list index ("[1]") */
typedef struct segment {
    const char *name;    /* NULL for an index */
    size_t len;          /* bytes of KEY up to the end of this segment */
    size_t name_len;
    long index;
    int column;          /* 1-based, in KEY=VALUE */
} segment;

typedef struct set_ctx {
    ww_tree *t;
    const char *text;    /* KEY=VALUE */
    size_t key_len;
    const char *file;    /* "--set[N]", owned by t */
    ww_error *err;
} set_ctx;

static ww_result set_error(const set_ctx *s, int column, const char *what) {
    return ww_error_set(s->err, WW_E_SET, s->file, 1, column, "--set '%s': %s", s->text, what);
}

static int is_name_char(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
           c == '_' || c == '-';
}

/* KEY := name ( "." name | "[" digits "]" )* */
static ww_result parse_key(const set_ctx *s, segment *seg, int *nseg) {
    const char *k = s->text;
    size_t i = 0;
    int n = 0;
    char msg[96];
    while (i < s->key_len) {
        if (n == SET_MAX_SEGMENTS) return set_error(s, (int)i + 1, "expected a shorter key");
        segment *g = &seg[n];
        g->column = (int)i + 1;

        if (k[i] == '[') {
            /* an index: digits and a closing bracket */
            if (n == 0) return set_error(s, 1, "expected a key name before '['");
            size_t j = i + 1;
            long v = 0;
            while (j < s->key_len && k[j] >= '0' && k[j] <= '9' && v <= SET_MAX_INDEX)
                v = v * 10 + (k[j++] - '0');
            if (j == i + 1 || v > SET_MAX_INDEX || j >= s->key_len || k[j] != ']')
                return set_error(s, g->column, "expected a list index like [0]");
            g->name = NULL;
            g->index = v;
            i = j + 1;
        } else {
            /* a name, after a dot unless it is the first */
            if (n > 0) {
                if (k[i] != '.') {
                    snprintf(msg, sizeof msg, "expected '.' or '[' after '%.*s', got '%c'",
                             (int)i, k, k[i]);
                    return set_error(s, (int)i + 1, msg);
                }
                i++;
                g->column = (int)i + 1;
            }
            size_t j = i;
            while (j < s->key_len && is_name_char(k[j])) j++;
            if (j == i && (i == s->key_len || k[i] == '.' || k[i] == '['))
                return set_error(s, g->column, "expected a key name between the dots");
            if (j == i) {
                snprintf(msg, sizeof msg, "expected a key name (letters, digits, _ or -), got '%c'",
                         k[i]);
                return set_error(s, g->column, msg);
            }
            g->name = k + i;
            g->name_len = j - i;
            i = j;
        }
        g->len = i;
        n++;
    }
    if (n == 0) return set_error(s, 1, "expected KEY=VALUE, got an empty key");
    *nseg = n;
    return WW_OK;
}

/* a fresh container named by segment g: a mapping when the next segment is a name, else a list */
static ww_node *new_container(const set_ctx *s, const segment *g) {
    ww_node_kind kind = g[1].name ? WW_NODE_MAP : WW_NODE_SEQ;
    return ww_tree_node(s->t, kind, (ww_mark){s->file, 1, g->column});
}

/* overwrite dst with src, keeping dst's place in its parent */
static void replace(ww_node *dst, const ww_node *src) {
    ww_node *key = dst->key, *next = dst->next;
    *dst = *src;
    dst->key = key;
    dst->next = next;
}

static const char *kind_name(const ww_node *n) {
    return n->kind == WW_NODE_MAP ? "a mapping" : n->kind == WW_NODE_SEQ ? "a list" : "a value";
}

/* walk the path from the root, making what is missing, and put value at its end */
static ww_result apply(const set_ctx *s, const segment *seg, int nseg, ww_node *value) {
    ww_node *cur = ww_tree_root(s->t);
    char msg[160];
    for (int i = 0; i < nseg; i++) {
        const segment *g = &seg[i];
        int last = i == nseg - 1;
        int at = i > 0 ? (int)seg[i - 1].len : 0; /* bytes of KEY before this segment */
        ww_node *child;

        if (g->name) {
            /* a key of a mapping */
            if (cur->kind != WW_NODE_MAP) {
                snprintf(msg, sizeof msg, "'%.*s' is %s, expected a mapping to hold '%.*s'", at,
                         s->text, kind_name(cur), (int)g->name_len, g->name);
                return set_error(s, g->column, msg);
            }
            ww_node *key = NULL;
            child = NULL;
            for (ww_node *c = cur->first; c; c = c->next)
                if (c->key->len == g->name_len && memcmp(c->key->text, g->name, g->name_len) == 0)
                    child = c;
            if (!child) {
                key = ww_tree_node(s->t, WW_NODE_SCALAR, (ww_mark){s->file, 1, g->column});
                child = last ? value : new_container(s, g);
                if (!key || !child || !(key->text = ww_tree_strndup(s->t, g->name, g->name_len)))
                    return ww_error_set(s->err, WW_E_NOMEM, s->file, 0, 0, "out of memory");
                key->len = g->name_len;
                child->key = key;
                ww_node_append(cur, child);
            }
        } else {
            /* an item of a list: an index up to the length, which appends */
            if (cur->kind != WW_NODE_SEQ) {
                snprintf(msg, sizeof msg, "'%.*s' is %s, expected a list to index", at, s->text,
                         kind_name(cur));
                return set_error(s, g->column, msg);
            }
            if (g->index > cur->n) {
                snprintf(msg, sizeof msg,
                         "index %ld is past the end of '%.*s' (%d items): expected at most %d",
                         g->index, at, s->text, cur->n, cur->n);
                return set_error(s, g->column, msg);
            }
            child = ww_node_at(cur, (int)g->index);
            if (!child) {
                child = last ? value : new_container(s, g);
                if (!child) return ww_error_set(s->err, WW_E_NOMEM, s->file, 0, 0, "out of memory");
                ww_node_append(cur, child);
            }
        }

        /* the end of the path takes the value; a null on the way becomes a container */
        if (last) {
            if (child != value) replace(child, value);
        } else if (ww_node_is_null(child)) {
            ww_node *fresh = new_container(s, g);
            if (!fresh) return ww_error_set(s->err, WW_E_NOMEM, s->file, 0, 0, "out of memory");
            replace(child, fresh);
        }
        cur = child;
    }
    return WW_OK;
}

ww_result ww_tree_set(ww_tree *t, int index, const char *text, ww_error *err) {
    char file[32];
    snprintf(file, sizeof file, "--set[%d]", index);
    set_ctx s = {.t = t, .text = text, .err = err};
    if (!(s.file = ww_tree_strndup(t, file, strlen(file))))
        return ww_error_set(err, WW_E_NOMEM, file, 0, 0, "out of memory");

    /* KEY=VALUE, split at the first '=' */
    const char *eq = strchr(text, '=');
    if (!eq) return set_error(&s, 1, "expected KEY=VALUE, found no '='");
    s.key_len = (size_t)(eq - text);
    segment seg[SET_MAX_SEGMENTS];
    int nseg = 0;
    ww_result r = parse_key(&s, seg, &nseg);
    if (r) return r;

    /* the value, with marks counted from its place in KEY=VALUE */
    ww_node *value = NULL;
    int column0 = (int)s.key_len + 1;
    r = ww_tree_parse_value(t, s.file, column0, eq + 1, strlen(eq + 1), &value, err);
    if (r == WW_E_EMPTY) return set_error(&s, column0 + 1, "expected a value after '='");
    if (r == WW_E_SYNTAX) {
        /* keep libyaml's place and words, but as a --set error */
        if (!err) return WW_E_SET;
        ww_error why = *err;
        /* libyaml places an unexpected end on the line after; a --set value has one line */
        if (why.line > 1 && !strchr(eq + 1, '\n')) {
            why.line = 1;
            why.column = (int)strlen(text) + 1;
        }
        return ww_error_set(err, WW_E_SET, why.file, why.line, why.column, "--set '%s': %s", text,
                            why.msg);
    }
    if (r) return r;
    return apply(&s, seg, nseg, value);
}
