#version 330 core
// geometry.vert.glsl - solid geometry (gfx/geometry.c): one mesh, drawn once per instance with
// the instance's model matrix, colour and extras as per-instance attributes. Positions are
// camera-relative: the model matrix's translation is the instance's position minus the camera's.
// Fish swim: a travelling wave runs down the body, weighted by the tail weight in uv.x
// (gfx/meshgen.h), swinging vertices sideways (mesh z); a fish's phase and amplitude come per
// instance, so the whole school is one draw.
// Defines: WW_FISH_PATTERNS 1 in the build that draws the fish species (their colour patterns
// in geometry.frag.glsl need the mesh-space position).
// Plants sway (WW_SWAY, defined only in scenes with a swaying model): the water's surge pushes a
// plant sideways along u_sway_axis.zw by s = A w^2 sin(phase - lag w), w its height above the
// base over its height: the base stays, the tip moves most and lags, so a wave runs up a frond.
// The phase (CPU, from the frame's simulated time and the plant's place) is per draw.

#ifndef WW_FISH_PATTERNS
#define WW_FISH_PATTERNS 0
#endif

layout(location = 0) in vec3 a_pos;      // mesh space, m
layout(location = 1) in vec3 a_normal;   // mesh space
layout(location = 2) in vec2 a_uv;
layout(location = 3) in mat4 a_model;    // mesh -> camera-relative world (locations 3..6)
layout(location = 7) in vec4 a_color;    // linear RGB albedo, a: emission factor
layout(location = 8) in vec4 a_extra;    // (wiggle phase rad, wiggle amplitude, specular,
                                         //  fish pattern: 0 none, 1 + ww_fish_shape)

uniform mat4 u_view_proj;  // camera-relative world -> clip
uniform vec4 u_clip;       // keep a.x + b.y + c.z + d >= 0 (camera-relative), when enabled
uniform vec4 u_clip_surface; // (side, rest level camera-relative y m, mode, slope): side 0 keeps
                             // u_clip's plane alone. Mode 0 (the prepass): side 1 keeps what lies
                             // under the wave surface, -1 what lies over it, instead of the plane.
                             // Mode 1 (the reflection, side -1): the plane, and nothing of an
                             // instance that lies wholly under the surface; slope bounds the
                             // surface's slope, so its least height over the instance's footprint
uniform vec3 u_mesh_centre;  // the mesh's bounding box, mesh units: its centre ...
uniform vec3 u_mesh_half;    // ... and half its size
uniform int u_inside;        // 2: the hull, whose hollow's faces are marked (v_hollow)
uniform float u_water_y;     // the water plane (the surface over the camera), camera-relative y
uniform float u_mirror_reach; // mode 1: the footprint radius, m, up to which an instance is
                              // mirrored about the surface over its centre (a quarter of the
                              // dominant wavelength); none past twice that
uniform int u_shadow_bend; // the sunlight's bend at the water (shadow.glsl): 1 the shadow
                           // map's casters, warped as its receivers are; 2 the projected
                           // shadows' casters; 0 none
#if WW_SWAY
uniform vec4 u_sway;       // (amplitude at the tip m (0: rigid), phase rad, lag rad, height m)
uniform vec4 u_sway_axis;  // (mesh y of the base, 1 / mesh height, direction x, direction z)
#endif

out vec3 v_pos;     // camera-relative world, m
flat out float v_water_y; // the water plane the instance is shaded by, camera-relative y
flat out float v_hollow;  // 1: a face of the hull's hollow, its normal turned toward the box's
                          // centre (a convex shell's all turn away)
out vec3 v_normal;  // world
out vec2 v_uv;
out vec4 v_color;
out float v_spec;
#if WW_FISH_PATTERNS
out vec3 v_mesh;           // mesh space at rest (the pattern stays on the bending body)
flat out float v_pattern;
#endif
#if WW_GEOM_MODE == 5
flat out vec3 v_wake;      // the wake: the stern's odometer m, the transom's half-breadth m,
                           // the time s
#endif

const float WW_WIGGLE_K = 9.0; // rad per mesh unit: about 1.4 waves along the body
const float SURFACE_UNFADED = 1e-6; // m: a sample spacing no wave fades at (gerstner.glsl)
// the wake (WW_GEOM_MODE 5) lies this far over the surface, and more with the distance, where the
// water's mesh is coarser and its short waves fade: m, and m per m
const float WAKE_LIFT = 0.02;
const float WAKE_LIFT_PER_M = 0.002;

void main() {
    vec3 q = a_pos;
    vec3 nrm = a_normal;
    if (a_extra.y != 0.0) {
        // z += w A sin(phase - K x): the body bends; its normal tilts by the slope dz/dx
        float w = a_uv.x, arg = a_extra.x - WW_WIGGLE_K * a_pos.x;
        q.z += w * a_extra.y * sin(arg);
        float slope = -w * a_extra.y * WW_WIGGLE_K * cos(arg);
        nrm = normalize(vec3(nrm.x - slope * nrm.z, nrm.y, nrm.z));
    }
    vec4 p = a_model * vec4(q, 1.0);
#if WW_GEOM_MODE == 5
    // the wake's points come at the rest level: each goes onto the surface over it, found as the
    // cut's below (the rest point the waves carry there, three fixed-point steps)
    {
        vec2 a = p.xz;
        for (int it = 0; it < 3; it++) a = p.xz - ww_displace(a, SURFACE_UNFADED).xz;
        p.y = u_clip_surface.y + ww_displace(a, SURFACE_UNFADED).y + WAKE_LIFT +
              WAKE_LIFT_PER_M * length(p.xz);
    }
#endif
    // the inverse transpose: models may scale unevenly (chest, OBJ models)
    v_normal = transpose(inverse(mat3(a_model))) * nrm;
#if WW_SWAY
    if (u_sway.x != 0.0) {
        // p += D s(y): the map's Jacobian is I + D grad(s)^T with D horizontal and grad(s)
        // vertical, so normals (the inverse transpose) lose ds/dy (D . n) from their y
        float w = clamp((a_pos.y - u_sway_axis.x) * u_sway_axis.y, 0.0, 1.0);
        float arg = u_sway.y - u_sway.z * w;
        float s = u_sway.x * w * w * sin(arg);
        float ds = u_sway.x * (2.0 * w * sin(arg) - u_sway.z * w * w * cos(arg)) / u_sway.w;
        vec2 d = u_sway_axis.zw;
        p.xz += d * s;
        vec3 n = normalize(v_normal);
        v_normal = vec3(n.x, n.y - ds * dot(d, n.xz), n.z);
    }
#endif
    v_pos = p.xyz;
    v_hollow = u_inside == 2 && dot(nrm, q - u_mesh_centre) < 0.0 ? 1.0 : 0.0;
    v_uv = a_uv;
    v_color = a_color;
    v_spec = a_extra.z;
#if WW_GEOM_MODE == 5
    v_wake = vec3(a_extra.zw, a_extra.x);
#endif
#if WW_FISH_PATTERNS
    v_mesh = a_pos;
    v_pattern = a_extra.w;
#endif
    float clip = dot(vec4(p.xyz, 1.0), u_clip);
    // the surface over a point x: the rest point a that the waves carry over x, by the fixed
    // point a <- x - D(a) (it contracts by sum Q k A per step: the lake's 0.11, so three steps
    // leave about a millimetre), then the height there. A loop of count 0 where the side is 0,
    // which llvmpipe skips, rather than a branch, whose both arms every vertex would run.
    // The prepass cuts at the surface over the vertex; the distance is interpolated linearly
    // across a triangle, so the cut follows the surface to the waves' curvature over it (about
    // 3 cm across a 1 m face on the lake). The reflection clips at a horizontal plane per
    // instance, not at the surface over each vertex: the mirror camera below would see into what
    // floats through a cut along the waves (the boat's lit inside showed along its waterline). The
    // mirror about the rest plane puts the image of what stands in a crest h above it 2 h too low,
    // a band of water between a float's waterline and its image, so an instance small against the
    // waves is mirrored about the surface over its centre: lowered by twice that height over the
    // rest plane before the mirror camera's matrix flips it, clipped there, and shaded with it as
    // its water plane (v_water_y). Its image then starts at its waterline, and its part under the
    // water is left out. That height stands for the waterline while the footprint's radius is
    // within a quarter of the dominant wavelength (u_mirror_reach), over which the surface's phase
    // turns a right angle; the weight w goes to the plane over the camera (u_water_y) and the rest
    // plane's mirror by twice that. An instance wholly under the surface (a pressed cube, a fish,
    // a sunken box under a crest) has no image even where it rises above that plane: its top, the
    // highest corner of its box, is compared with the least height of the surface over its
    // footprint, the height over its centre less the slope's bound times its radius
    float lift = 0.0; // m the instance's image rises over the rest plane's mirror image
    v_water_y = u_water_y;
    int cut = u_clip_surface.x != 0.0 ? 1 : 0;
    for (int k = 0; k < cut; k++) {
        bool whole = u_clip_surface.z != 0.0;
        mat3 m = mat3(a_model);
        vec3 c = (a_model * vec4(u_mesh_centre, 1.0)).xyz;
        vec2 x = whole ? c.xz : p.xz;
        vec2 a = x;
        for (int it = 0; it < 3; it++) a = x - ww_displace(a, SURFACE_UNFADED).xz;
        float h = u_clip_surface.y + ww_displace(a, SURFACE_UNFADED).y;
        float wiggle = abs(a_extra.y) * length(m[2]);
        float top = c.y + dot(abs(vec3(m[0].y, m[1].y, m[2].y)), u_mesh_half) + wiggle;
        float radius = dot(vec3(length(m[0].xz), length(m[1].xz), length(m[2].xz)), u_mesh_half) +
                       wiggle;
#if WW_SWAY
        radius += abs(u_sway.x);
#endif
        float w = whole ? clamp(2.0 - radius / u_mirror_reach, 0.0, 1.0) : 0.0;
        v_water_y = mix(u_water_y, h, w);
        lift = 2.0 * w * (h - u_clip_surface.y);
        float under = top < h - u_clip_surface.w * radius ? -1.0 : clip - (v_water_y - u_water_y);
        clip = whole ? under : u_clip_surface.x * (h - p.y);
    }
    gl_ClipDistance[0] = clip;
    vec3 at = u_shadow_bend == 1 ? ww_shadow_warp(p.xyz)
              : u_shadow_bend == 2 ? ww_shadow_unbend(p.xyz) : p.xyz;
    gl_Position = u_view_proj * vec4(at.x, at.y - lift, at.z, 1.0);
}
