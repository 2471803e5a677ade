#version 330 core
// geometry.vert.glsl - solid geometry (gfx/geometry.c): one mesh, drawn once per instance with
// the instance's model matrix and colour as per-instance attributes. Positions are
// camera-relative: the model matrix's translation is the instance's position minus the camera's.

layout(location = 0) in vec3 a_pos;      // mesh space, m
layout(location = 1) in vec3 a_normal;   // mesh space
layout(location = 2) in vec2 a_uv;
layout(location = 3) in mat4 a_model;    // mesh -> camera-relative world (locations 3..6)
layout(location = 7) in vec4 a_color;    // linear RGB albedo, a: emission factor

uniform mat4 u_view_proj;  // camera-relative world -> clip
uniform vec4 u_clip;       // keep a.x + b.y + c.z + d >= 0 (camera-relative), when enabled

out vec3 v_pos;     // camera-relative world, m
out vec3 v_normal;  // world
out vec2 v_uv;
out vec4 v_color;

void main() {
    vec4 p = a_model * vec4(a_pos, 1.0);
    v_pos = p.xyz;
    v_normal = mat3(a_model) * a_normal; // uniform scales only: no inverse transpose needed
    v_uv = a_uv;
    v_color = a_color;
    gl_ClipDistance[0] = dot(vec4(p.xyz, 1.0), u_clip);
    gl_Position = u_view_proj * p;
}
