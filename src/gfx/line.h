/* line.h - the fishing line and the rod that holds it, as ribbons facing the camera, built on
 * the CPU each frame (no GL: the tests check the shapes without a context). gfx/geometry.c draws
 * them blended in the main pass (geometry.frag.glsl mode 4).
 *
 * A cast's line runs from the rod's tip to the top of the lure's stem. The tip is where the cast
 * left: a place given (`cast: {from}`), or the tip of the rod the camera holds, which stays at
 * rod.offset (forward, right, up) from the camera as the camera moves. Its shape is a parabola
 * sagging by how the line is held: a little behind a lure in flight, slack (down onto the water,
 * where it then lies) from a floating lure, straight when a fish pulls on it; no point of it goes
 * under the surface but the leader, which hangs from a lure on the water down to the hook. The
 * rod is drawn up to that tip, tapering, rising along the cast's heading (the camera's, for the
 * rod it holds), and the line runs up along its top from the reel, through the guides, to the
 * tip.
 *
 * A line is far thinner than a pixel (3 mm is a fifth of a pixel at 10 m in a 1280x720
 * frame): drawn at its width it would break into dashes where it falls between pixel centres.
 * So each ribbon is at least 2 pixels wide and carries its true width in pixels, which the
 * fragment shader turns into coverage (after Persson's phone-wire AA, "Graphics Gems for Games",
 * SIGGRAPH 2012): a thin line fades instead of breaking up, and covers as much of the picture as
 * the real line would.
 *
 * Vertex layout (8 floats, the geometry meshes'): position camera-relative m, the unit vector
 * across the ribbon, then (s, w): s -1 .. 1 across it, w the strand's true width in pixels
 * there. The two strands are drawn with their own colours: the line (and the leader) and the
 * rod. */
#ifndef WW_GFX_LINE_H
#define WW_GFX_LINE_H

#include <stdint.h>

#include "scene/scene.h"
#include "sim/state.h"

#define WW_LURE_SIZE 0.09 /* m: the bobber's height, its mesh's unit box scaled (geometry.c) */

/* the ribbons' capacity: the line's segments, the leader's one and the line's along the rod (one a
 * segment of the rod), the rod's */
#define WW_LINE_SEGMENTS 48
#define WW_ROD_SEGMENTS 12
#define WW_LINE_MAX_VERTS (2 * (WW_LINE_SEGMENTS + 1) + 4 + 2 * (WW_ROD_SEGMENTS + 1))
#define WW_LINE_MAX_INDEX (6 * (WW_LINE_SEGMENTS + 1 + WW_ROD_SEGMENTS))
#define WW_ROD_MAX_VERTS (2 * (WW_ROD_SEGMENTS + 1))
#define WW_ROD_MAX_INDEX (6 * WW_ROD_SEGMENTS)

/* the camera the ribbons face */
typedef struct ww_line_eye {
    double pos[3];      /* world, m */
    double fwd[3];      /* the view axis, unit */
    double pixel_angle; /* a pixel at view depth d is d * pixel_angle wide */
    double near;        /* the near plane, m: depths are taken no nearer */
} ww_line_eye;

typedef enum ww_strand { WW_STRAND_LINE = 0, WW_STRAND_ROD } ww_strand;

/* the tip of the rod the line leaves from, world m; 0 when no line is out (the lure idle) */
int ww_line_tip(const ww_scene *sc, const ww_state *st, double tip[3]);

/* the line's points from the tip to the lure (at most WW_LINE_SEGMENTS + 1), world m; 0 when no
 * line is out or it is drawn 0 wide */
int ww_line_points(const ww_scene *sc, const ww_state *st, double (*p)[3]);

/* the rod's points from its butt to its tip (WW_ROD_SEGMENTS + 1) and their widths, world m; 0
 * when no line is out or it is drawn 0 wide */
int ww_line_rod_points(const ww_scene *sc, const ww_state *st, double (*p)[3], double *width);

/* the ribbons of strand `which`: vertices (8 floats each, at most WW_LINE_MAX_VERTS or
 * WW_ROD_MAX_VERTS) and triangles (at most WW_LINE_MAX_INDEX or WW_ROD_MAX_INDEX indices);
 * returns the index count (0: nothing to draw), *nvert the vertices */
int ww_line_build(const ww_scene *sc, const ww_state *st, const ww_line_eye *eye,
                  ww_strand which, float *vert, uint32_t *index, int *nvert);

#endif
