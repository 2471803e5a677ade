/* tree.h - the first of the loader's three layers (MuJoCo src/xml): YAML text as a plain tree of
 * marked nodes, with no schema. compile.c turns the tree into a ww_scene.
 *
 * Call order:
 *   ww_tree *t = NULL;
 *   ww_tree_load(path, &t, &err);              // or ww_tree_parse(name, text, len, &t, &err)
 *   ww_tree_set(t, 1, "render.size=[256,144]", &err);   // each --set, in order, 1-based
 *   ... read ww_tree_root(t) ...
 *   ww_tree_free(t);                           // frees every node, string and mark file name
 *
 * The tree owns all its memory (a chain of arenas); nodes live until ww_tree_free. On an error the
 * tree is left as it was when the error struck and the caller still frees it (load and parse free
 * it themselves and return no tree).
 */
#ifndef WW_TREE_H
#define WW_TREE_H

#include <stddef.h>

#include "core/error.h"

typedef enum ww_node_kind { WW_NODE_SCALAR = 0, WW_NODE_SEQ, WW_NODE_MAP } ww_node_kind;

/* where a node starts: libyaml's start_mark made 1-based; a --set value says "--set[N]", line 1 */
typedef struct ww_mark {
    const char *file;    /* owned by the tree */
    int line, column;    /* 1-based */
} ww_mark;

typedef struct ww_node ww_node;
struct ww_node {
    ww_node_kind kind;
    ww_mark mark;
    /* scalar */
    const char *text;    /* NUL-terminated, as written without quotes */
    size_t len;
    int quoted;          /* quoted, block (| >) or !!str: a string, never a number */
    /* sequence and mapping: children in order; a mapping's children are its values */
    ww_node *first, *last;
    int n;
    /* links */
    ww_node *next;       /* next sibling in the parent */
    ww_node *key;        /* in a mapping: the scalar key naming this value; else NULL */
};

typedef struct ww_tree ww_tree;

/* read and parse a scene file; the top level must be a mapping */
ww_result ww_tree_load(const char *path, ww_tree **out, ww_error *err);
/* the same from memory; name stands for the file in marks and messages */
ww_result ww_tree_parse(const char *name, const char *text, size_t len, ww_tree **out,
                        ww_error *err);
/* parse text as one YAML value (any kind) into new nodes of t, not yet attached anywhere. Marks
 * name file; columns on the first line are shifted by column0 (the value's place in KEY=VALUE). */
ww_result ww_tree_parse_value(ww_tree *t, const char *file, int column0, const char *text,
                              size_t len, ww_node **out, ww_error *err);
ww_node *ww_tree_root(const ww_tree *t);
void ww_tree_free(ww_tree *t);

/* building blocks for edits (set.c): NULL when out of memory */
ww_node *ww_tree_node(ww_tree *t, ww_node_kind kind, ww_mark mark);
const char *ww_tree_strndup(ww_tree *t, const char *s, size_t n);

/* child of a mapping by key, or NULL */
ww_node *ww_node_find(const ww_node *map, const char *key);
/* i-th child of a sequence or mapping, or NULL */
ww_node *ww_node_at(const ww_node *parent, int i);
/* add child at the end of parent (for a mapping, set child->key first) */
void ww_node_append(ww_node *parent, ww_node *child);
/* plain "", "~", "null": YAML's null */
int ww_node_is_null(const ww_node *n);

/* apply the override text "KEY=VALUE" (the index-th --set, 1-based) to the tree (set.c).
 * KEY is a dotted path with list indices (water.waves.list[1].amplitude); VALUE is a YAML flow
 * value. Missing mappings are made; index == length appends. Errors: WW_E_SET. */
ww_result ww_tree_set(ww_tree *t, int index, const char *text, ww_error *err);

#endif
