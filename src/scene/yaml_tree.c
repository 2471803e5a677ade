/* yaml_tree.c - YAML text to a plain tree of marked nodes; the only file that includes yaml.h.
 * It knows structure, not the schema: one document, a mapping on top, no duplicate keys, no
 * anchors, aliases or tags beyond !!str. Every node keeps libyaml's start mark, made 1-based.
 */
#include "scene/tree.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <yaml.h>

#include "core/arena.h"
#include "core/readfile.h"
#include "scene/scene.h"

#define TREE_BLOCK_BYTES (64u * 1024u)
#define TREE_MAX_DEPTH 64

typedef struct tree_block {
    struct tree_block *prev;
    ww_arena arena;
} tree_block;

struct ww_tree {
    ww_node *root;
    tree_block *blocks;    /* newest first; freed together */
    int nodes;             /* made so far, against WW_SCENE_MAX_NODES */
};

typedef struct parser {
    yaml_parser_t yp;
    ww_tree *t;
    const char *file;      /* owned by t */
    const char *text;
    size_t len;
    int column0;           /* added to columns on the first line */
    ww_error *err;
} parser;

/* ---- memory ---------------------------------------------------------------------------------- */

static void *tree_alloc(ww_tree *t, size_t n) {
    void *p = t->blocks ? ww_arena_alloc(&t->blocks->arena, n) : NULL;
    if (p) return p;

    /* the current block is full: chain a new one, big enough for n */
    size_t size = n + 16u > TREE_BLOCK_BYTES ? n + 16u : TREE_BLOCK_BYTES;
    tree_block *b = malloc(sizeof *b);
    if (!b) return NULL;
    if (ww_arena_init(&b->arena, size) != 0) {
        free(b);
        return NULL;
    }
    b->prev = t->blocks;
    t->blocks = b;
    return ww_arena_alloc(&b->arena, n);
}

ww_node *ww_tree_node(ww_tree *t, ww_node_kind kind, ww_mark mark) {
    ww_node *n = tree_alloc(t, sizeof *n);
    if (!n) return NULL;
    t->nodes++;
    n->kind = kind;
    n->mark = mark;
    n->text = "";
    return n;
}

const char *ww_tree_strndup(ww_tree *t, const char *s, size_t n) {
    char *d = tree_alloc(t, n + 1);
    if (!d) return NULL;
    memcpy(d, s, n);
    d[n] = 0;
    return d;
}

ww_node *ww_tree_root(const ww_tree *t) { return t->root; }

void ww_tree_free(ww_tree *t) {
    if (!t) return;
    while (t->blocks) {
        tree_block *b = t->blocks;
        t->blocks = b->prev;
        ww_arena_free(&b->arena);
        free(b);
    }
    free(t);
}

static ww_tree *tree_new(void) { return calloc(1, sizeof(ww_tree)); }

/* ---- nodes ----------------------------------------------------------------------------------- */

ww_node *ww_node_find(const ww_node *map, const char *key) {
    if (!map || map->kind != WW_NODE_MAP) return NULL;
    for (ww_node *c = map->first; c; c = c->next)
        if (strcmp(c->key->text, key) == 0) return c;
    return NULL;
}

ww_node *ww_node_at(const ww_node *parent, int i) {
    if (!parent || i < 0) return NULL;
    ww_node *c = parent->first;
    while (c && i-- > 0) c = c->next;
    return c;
}

void ww_node_append(ww_node *parent, ww_node *child) {
    WW_ASSERT(parent->kind != WW_NODE_SCALAR);
    WW_ASSERT(parent->kind != WW_NODE_MAP || child->key);
    child->next = NULL;
    if (parent->last)
        parent->last->next = child;
    else
        parent->first = child;
    parent->last = child;
    parent->n++;
}

int ww_node_is_null(const ww_node *n) {
    return n->kind == WW_NODE_SCALAR && !n->quoted &&
           (n->len == 0 || strcmp(n->text, "~") == 0 || strcmp(n->text, "null") == 0 ||
            strcmp(n->text, "Null") == 0 || strcmp(n->text, "NULL") == 0);
}

/* ---- events ---------------------------------------------------------------------------------- */

static ww_mark mark_of(const parser *p, yaml_mark_t m) {
    int line = (int)m.line + 1;
    int column = (int)m.column + 1 + (m.line == 0 ? p->column0 : 0);
    return (ww_mark){p->file, line, column};
}

/* reader errors (bad UTF-8, control characters) give a byte offset, not a mark */
static ww_mark mark_at_offset(const parser *p, size_t offset) {
    ww_mark m = {p->file, 1, 1 + p->column0};
    for (size_t i = 0; i < offset && i < p->len; i++) {
        if (p->text[i] == '\n') {
            m.line++;
            m.column = 1;
        } else {
            m.column++;
        }
    }
    return m;
}

static ww_result syntax_error(parser *p) {
    const yaml_parser_t *y = &p->yp;
    if (y->error == YAML_MEMORY_ERROR)
        return ww_error_set(p->err, WW_E_NOMEM, p->file, 0, 0, "out of memory parsing YAML");

    ww_mark m = y->error == YAML_READER_ERROR ? mark_at_offset(p, y->problem_offset)
                                              : mark_of(p, y->problem_mark);
    const char *problem = y->problem ? y->problem : "unknown problem";
    if (y->context) {
        ww_mark c = mark_of(p, y->context_mark);
        return ww_error_set(p->err, WW_E_SYNTAX, m.file, m.line, m.column,
                            "not valid YAML: %s (%s that starts at %d:%d)", problem, y->context,
                            c.line, c.column);
    }
    return ww_error_set(p->err, WW_E_SYNTAX, m.file, m.line, m.column, "not valid YAML: %s",
                        problem);
}

static ww_result next_event(parser *p, yaml_event_t *ev) {
    return yaml_parser_parse(&p->yp, ev) ? WW_OK : syntax_error(p);
}

static ww_result nomem(parser *p) {
    return ww_error_set(p->err, WW_E_NOMEM, p->file, 0, 0, "out of memory reading the scene");
}

/* anchors, aliases and tags make a tree into a graph or change types: the scene needs neither */
static ww_result check_plain(parser *p, const yaml_event_t *ev, const yaml_char_t *anchor,
                             const yaml_char_t *tag, const char *plain_tag) {
    ww_mark m = mark_of(p, ev->start_mark);
    if (anchor)
        return ww_error_set(p->err, WW_E_TYPE, m.file, m.line, m.column,
                            "anchor '&%s' is not supported: expected a plain value", anchor);
    if (tag && strcmp((const char *)tag, plain_tag) != 0)
        return ww_error_set(p->err, WW_E_TYPE, m.file, m.line, m.column,
                            "tag '%s' is not supported: expected an untagged value (or !!str)",
                            tag);
    return WW_OK;
}

/* ---- nodes from events ----------------------------------------------------------------------- */

static ww_result parse_node(parser *p, const yaml_event_t *ev, int depth, ww_node **out);

static ww_result parse_scalar(parser *p, const yaml_event_t *ev, ww_node **out) {
    ww_result r = check_plain(p, ev, ev->data.scalar.anchor, ev->data.scalar.tag, YAML_STR_TAG);
    if (r) return r;
    ww_node *n = ww_tree_node(p->t, WW_NODE_SCALAR, mark_of(p, ev->start_mark));
    const char *text = (const char *)ev->data.scalar.value;
    if (!n || !(n->text = ww_tree_strndup(p->t, text, ev->data.scalar.length))) return nomem(p);
    n->len = ev->data.scalar.length;
    n->quoted = ev->data.scalar.style != YAML_PLAIN_SCALAR_STYLE || ev->data.scalar.tag != NULL;
    *out = n;
    return WW_OK;
}

static ww_result parse_seq(parser *p, const yaml_event_t *ev, int depth, ww_node **out) {
    ww_result r = check_plain(p, ev, ev->data.sequence_start.anchor,
                              ev->data.sequence_start.tag, YAML_SEQ_TAG);
    if (r) return r;
    ww_node *seq = ww_tree_node(p->t, WW_NODE_SEQ, mark_of(p, ev->start_mark));
    if (!seq) return nomem(p);

    for (;;) {
        yaml_event_t item;
        if ((r = next_event(p, &item))) return r;
        if (item.type == YAML_SEQUENCE_END_EVENT) {
            yaml_event_delete(&item);
            break;
        }
        ww_node *child = NULL;
        r = parse_node(p, &item, depth + 1, &child);
        yaml_event_delete(&item);
        if (r) return r;
        ww_node_append(seq, child);
    }
    *out = seq;
    return WW_OK;
}

static ww_result parse_map(parser *p, const yaml_event_t *ev, int depth, ww_node **out) {
    ww_result r = check_plain(p, ev, ev->data.mapping_start.anchor, ev->data.mapping_start.tag,
                              YAML_MAP_TAG);
    if (r) return r;
    ww_node *map = ww_tree_node(p->t, WW_NODE_MAP, mark_of(p, ev->start_mark));
    if (!map) return nomem(p);

    for (;;) {
        /* key: a scalar, not yet in this mapping */
        yaml_event_t kev;
        if ((r = next_event(p, &kev))) return r;
        if (kev.type == YAML_MAPPING_END_EVENT) {
            yaml_event_delete(&kev);
            break;
        }
        ww_node *key = NULL;
        r = parse_node(p, &kev, depth + 1, &key);
        yaml_event_delete(&kev);
        if (r) return r;
        if (key->kind != WW_NODE_SCALAR)
            return ww_error_set(p->err, WW_E_TYPE, key->mark.file, key->mark.line,
                                key->mark.column, "expected a plain word as a key, got a %s",
                                key->kind == WW_NODE_SEQ ? "list" : "mapping");
        ww_node *twin = ww_node_find(map, key->text);
        if (twin)
            return ww_error_set(p->err, WW_E_DUPLICATE_KEY, key->mark.file, key->mark.line,
                                key->mark.column,
                                "duplicate key '%s' (first at %d:%d): expected each key once",
                                key->text, twin->key->mark.line, twin->key->mark.column);

        /* value */
        yaml_event_t vev;
        if ((r = next_event(p, &vev))) return r;
        ww_node *value = NULL;
        r = parse_node(p, &vev, depth + 1, &value);
        yaml_event_delete(&vev);
        if (r) return r;
        value->key = key;
        ww_node_append(map, value);
    }
    *out = map;
    return WW_OK;
}

static ww_result parse_node(parser *p, const yaml_event_t *ev, int depth, ww_node **out) {
    ww_mark m = mark_of(p, ev->start_mark);
    if (depth > TREE_MAX_DEPTH)
        return ww_error_set(p->err, WW_E_SYNTAX, m.file, m.line, m.column,
                            "nested more than %d levels deep: expected a flatter scene",
                            TREE_MAX_DEPTH);
    /* the largest scene the format allows (every list at its cap) holds a tenth of this */
    if (p->t->nodes >= WW_SCENE_MAX_NODES)
        return ww_error_set(p->err, WW_E_RANGE, m.file, m.line, m.column,
                            "more than %d YAML keys and values: expected a smaller scene",
                            WW_SCENE_MAX_NODES);
    switch (ev->type) {
    case YAML_SCALAR_EVENT: return parse_scalar(p, ev, out);
    case YAML_SEQUENCE_START_EVENT: return parse_seq(p, ev, depth, out);
    case YAML_MAPPING_START_EVENT: return parse_map(p, ev, depth, out);
    case YAML_ALIAS_EVENT:
        return ww_error_set(p->err, WW_E_TYPE, m.file, m.line, m.column,
                            "alias '*%s' is not supported: expected the value written out",
                            ev->data.alias.anchor);
    default:
        return ww_error_set(p->err, WW_E_SYNTAX, m.file, m.line, m.column,
                            "not valid YAML: expected a value");
    }
}

/* the one document of the stream; *out stays NULL when the stream holds none */
static ww_result parse_stream(parser *p, ww_node **out) {
    yaml_event_t ev;
    ww_result r;
    *out = NULL;

    /* stream start, then a document or the end */
    if ((r = next_event(p, &ev))) return r;
    yaml_event_delete(&ev);
    if ((r = next_event(p, &ev))) return r;
    yaml_event_type_t type = ev.type;
    yaml_event_delete(&ev);
    if (type == YAML_STREAM_END_EVENT) return WW_OK;

    /* the root node and the document end */
    if ((r = next_event(p, &ev))) return r;
    r = parse_node(p, &ev, 0, out);
    yaml_event_delete(&ev);
    if (r) return r;
    if ((r = next_event(p, &ev))) return r;
    yaml_event_delete(&ev);

    /* a second document would be silently ignored by a reader that stops here */
    if ((r = next_event(p, &ev))) return r;
    ww_mark m = mark_of(p, ev.start_mark);
    type = ev.type;
    yaml_event_delete(&ev);
    if (type != YAML_STREAM_END_EVENT)
        return ww_error_set(p->err, WW_E_SYNTAX, m.file, m.line, m.column,
                            "a second YAML document: expected one scene per file");
    return WW_OK;
}

static ww_result parse_into(ww_tree *t, const char *file, int column0, const char *text,
                            size_t len, ww_node **out, ww_error *err) {
    parser p = {.t = t, .text = text, .len = len, .column0 = column0, .err = err};
    if (!(p.file = ww_tree_strndup(t, file, strlen(file))) || !yaml_parser_initialize(&p.yp))
        return ww_error_set(err, WW_E_NOMEM, file, 0, 0, "out of memory reading the scene");
    yaml_parser_set_input_string(&p.yp, (const unsigned char *)text, len);
    yaml_parser_set_encoding(&p.yp, YAML_UTF8_ENCODING);
    ww_result r = parse_stream(&p, out);
    yaml_parser_delete(&p.yp);
    return r;
}

/* ---- public ---------------------------------------------------------------------------------- */

ww_result ww_tree_parse_value(ww_tree *t, const char *file, int column0, const char *text,
                              size_t len, ww_node **out, ww_error *err) {
    ww_result r = parse_into(t, file, column0, text, len, out, err);
    if (!r && !*out)
        r = ww_error_set(err, WW_E_EMPTY, file, 1, column0 + 1, "expected a value, got nothing");
    return r;
}

ww_result ww_tree_parse(const char *name, const char *text, size_t len, ww_tree **out,
                        ww_error *err) {
    *out = NULL;
    ww_tree *t = tree_new();
    if (!t) return ww_error_set(err, WW_E_NOMEM, name, 0, 0, "out of memory reading the scene");

    ww_node *root = NULL;
    ww_result r = parse_into(t, name, 0, text, len, &root, err);

    /* nothing, or a bare "---": no scene at all */
    if (!r && (!root || ww_node_is_null(root)))
        r = ww_error_set(err, WW_E_EMPTY, name, 0, 0,
                         "the file holds no YAML document: expected a mapping of sections "
                         "(time, render, sky, fog, water, camera, script)");
    if (!r && root->kind != WW_NODE_MAP)
        r = ww_error_set(err, WW_E_TYPE, name, root->mark.line, root->mark.column,
                         "expected a mapping of sections (time:, water:, ...) at the top level, "
                         "got a %s",
                         root->kind == WW_NODE_SEQ ? "list" : "single value");
    if (r) {
        ww_tree_free(t);
        return r;
    }
    t->root = root;
    *out = t;
    return WW_OK;
}

ww_result ww_tree_load(const char *path, ww_tree **out, ww_error *err) {
    *out = NULL;
    unsigned char *buf = NULL;
    size_t len = 0;
    ww_result r = ww_file_read_max(path, WW_SCENE_MAX_BYTES, WW_SCENE_MAX_BYTES, &buf, &len, err);
    if (r) {
        /* the reader's message names the file; the place is the file itself */
        if (err) snprintf(err->file, sizeof err->file, "%s", path);
        return r;
    }
    r = ww_tree_parse(path, (const char *)buf, len, out, err);
    free(buf);
    return r;
}
