/* obj.h - the Wavefront OBJ + MTL reader behind ww_assets_obj (scene/assets.h), private to
 * src/scene. Text in, one ww_mesh_data out; textures named by map_Kd are handed to the caller's
 * loader (assets.c's puts them in the scene's asset table: ww_assets_obj_parse).
 *
 *   ww_mesh_data m = {0};
 *   ww_obj_parse(&textures, "boat.obj", text, len, &m, &err);   // reads the mtllib files itself
 *   ... on success m's arrays belong to the caller (ww_assets_free frees them in the table);
 *   on failure nothing is left allocated in m.
 *
 * What is read: v, vt, vn, f (triangles, quads and n-gons fanned from the first corner; 1-based
 * and negative indices; v, v/vt, v//vn, v/vt/vn), usemtl (a new submesh), mtllib (files
 * relative to the OBJ, several per line); o, g, s, l, p and the rest are ignored. MTL: newmtl,
 * Kd, Ks, Ns, d, Tr, Ke, map_Kd (relative to the MTL; options before the file name skipped).
 * Corners without vn get the area-weighted mean of the face normals around their position
 * (smooth shading); vertices are shared per distinct (v, vt, vn). uv is stored as GL samples an
 * image uploaded top row first: (u, 1 - v) of the file.
 * Errors name the OBJ's or MTL's own file:line:column. Counts are capped (below) so that a
 * hostile file cannot ask for unbounded memory.
 */
#ifndef WW_OBJ_H
#define WW_OBJ_H

#include <stddef.h>

#include "scene/assets.h"

#define WW_OBJ_MAX_BYTES (256u << 20)    /* largest OBJ or MTL file read, bytes */
#define WW_OBJ_MAX_ELEMENTS (1 << 22)    /* v, vt, vn lines each, and triangles after fanning */
#define WW_OBJ_MAX_CORNERS 256           /* corners of one polygon */
#define WW_OBJ_MAX_MATERIALS 256         /* materials over all of an OBJ's libraries */
#define WW_OBJ_MAX_LIBRARIES 16          /* mtllib files of one OBJ */

/* how the reader hands over a texture a material names (map_Kd): the caller loads it and gives
 * back its index in its image table (assets.c puts it in the scene's assets) */
typedef struct ww_obj_textures {
    ww_result (*load)(void *ctx, const char *path, const char *from, int line, int column,
                      int *index, ww_error *err);
    void *ctx;
} ww_obj_textures;

ww_result ww_obj_parse(const ww_obj_textures *tx, const char *path, const char *text, size_t len,
                       ww_mesh_data *out, ww_error *err);

/* frees the arrays of one mesh and zeroes it */
void ww_mesh_data_free(ww_mesh_data *m);

#endif
