/* meshgen.h - the procedural meshes of the scene's objects (ww_mesh_kind, scene/desc_reef.h):
 * box, sphere, stone, boat hull, fish, lure, chest, grid, the chest's glow column, and the lid
 * over the hull's inside. Pure CPU (no GL), so the tests check them without a context;
 * gfx/geometry.c uploads them.
 *
 *   ww_mesh_data m; ww_meshgen(WW_MESH_FISH, &m, &err);   // allocates vertex and index
 *   ... m.vertex (nvert x 8: position, normal, uv), m.index (CCW seen from outside) ...
 *   ww_meshgen_free(&m);
 *
 * Every mesh fits the unit box [-0.5, 0.5]^3 with its front (bow, head) toward +x and up +y.
 * Closed meshes (box, sphere, stone, fish, lure, chest, hull: a shell with thickness closed at
 * bow and stern, so its inside is walled in below the gunwale) are watertight by position. The
 * grid is an open plane at y = 0, normals up.
 * The fish's uv.x is the tail weight: 0 ahead of the body's middle, rising to 1 at the tail tip
 * (the vertex shader swings a vertex sideways by it). Other meshes carry texture-like uvs.
 */
#ifndef WW_MESHGEN_H
#define WW_MESHGEN_H

#include "core/error.h"
#include "scene/assets.h"
#include "scene/desc_fish_species.h"
#include "scene/desc_reef.h"

/* tessellation, shared with the tests that check volumes against the analytic shapes */
#define WW_MESHGEN_SLICES 24  /* around a body of revolution */
#define WW_MESHGEN_STACKS 16  /* pole to pole, or along a body */
#define WW_MESHGEN_GRID 16    /* cells per side of the grid */

/* proportions of the shapes (fractions of the unit box), for the tests' analytic volumes */
#define WW_STONE_THICKNESS 0.36  /* pebble height against its width */
#define WW_STONE_DEPTH 0.8       /* pebble depth (z) against its length (x) */
#define WW_CHEST_LID 0.3         /* lid height as a fraction of the chest's */
#define WW_CHEST_GAP 0.0         /* lid sits on the body */
#define WW_LURE_BALL 0.3         /* bobber ball radius */
#define WW_LURE_STEM 0.05        /* stem radius (the stem runs from the ball's top to y = 0.5) */

/* the chest's glow column (not a ww_mesh_kind): an open cylinder of radius 0.5 from y = -0.5 to
 * y = 0.5, normals outward, uv = (angle / 2 pi, height 0..1) */
#define WW_MESHGEN_COLUMN ((ww_mesh_kind)100)
/* the lid over the hull's inside (not a ww_mesh_kind): an open surface spanning the inner
 * gunwale of WW_MESH_HULL, normals up; the main pass draws it into depth before the water so
 * that no water shows inside a boat */
#define WW_MESHGEN_HULL_CAP ((ww_mesh_kind)101)
/* a splash's drop (not a ww_mesh_kind): an icosahedron of diameter 1 with the sphere's normals,
 * closed */
#define WW_MESHGEN_DROP ((ww_mesh_kind)110)

/* the fish species' bodies (not ww_mesh_kind words: objects.fish.species picks them by shape,
 * scene/desc_fish_species.h): WW_MESHGEN_FISH_SPECIES + shape. Head +x, as WW_MESH_FISH, with
 * its tail weight in uv.x; slim: a fusiform mackerel with a deeply forked tail and a small
 * dorsal fin; deep: a tall compressed disc with high dorsal and anal fins and a fan tail (an
 * angelfish or butterflyfish); long: a slender body that undulates from near the head, with a
 * long low dorsal fin and a small tail */
#define WW_MESHGEN_FISH_SPECIES 102
#define WW_MESHGEN_FISH_OF(shape) ((ww_mesh_kind)(WW_MESHGEN_FISH_SPECIES + (int)(shape)))

ww_result ww_meshgen(ww_mesh_kind kind, ww_mesh_data *out, ww_error *err);

/* WW_MESH_HULL's half-breadth where its outer skin crosses the mesh's y = 0 (the design
 * waterline) at station u (0 the transom .. 1 the stem, clamped), in the mesh's units (the
 * boat's length is 1) */
double ww_meshgen_hull_waterline(double u);
void ww_meshgen_free(ww_mesh_data *m);

/* signed volume enclosed by the triangles (divergence theorem: sum of det(a, b, c) / 6), m^3;
 * positive when the winding is counter-clockwise seen from outside */
double ww_meshgen_volume(const ww_mesh_data *m);

/* the directed edges (positions welded at WW_MESHGEN_WELD) without exactly one twin running the
 * other way: 0 for a closed, consistently wound mesh, whose faces all have its inside behind
 * them; -1 where memory ran out */
#define WW_MESHGEN_WELD 1e-5
long ww_meshgen_open_edges(const ww_mesh_data *m);

#endif
