#version 330 core
// water.vert.glsl - displaces the camera-centred polar mesh with the wave field of the scene's
// family and its ripples (gerstner.glsl: ww_displace, the function the GPU probe also uses),
// each component faded by the local mesh spacing. Positions are camera-relative: the view
// matrix holds the camera's rotation only.

layout(location = 0) in vec2 a_local; // rest offset from the snapped mesh centre (x, z), m

uniform mat4 u_view_proj; // projection * camera rotation
uniform float u_skirt_r;  // rest radius from which a vertex is the skirt's, m
uniform vec3 u_origin;    // (centre.x - cam.x, level - cam.y, centre.z - cam.z), m

const float FAR_Z = 0.999999; // clip z over w of the farthest water, just inside the far plane

out vec2 v_local; // rest offset, for the per-pixel normal
out vec3 v_pos;   // displaced surface point relative to the camera, m

void main() {
    vec3 p = vec3(a_local.x, 0.0, a_local.y) + ww_displace(a_local, ww_grid_spacing(a_local));
    v_local = a_local;
    v_pos = u_origin + p;
    gl_Position = u_view_proj * vec4(v_pos, 1.0);
    // the skirt ring (water.c) lies far beyond the far plane: keep it inside, just before the
    // sky (drawn at the far plane), rather than clip the water short of the horizon
    if (dot(a_local, a_local) >= u_skirt_r * u_skirt_r)
        gl_Position.z = min(gl_Position.z, gl_Position.w * FAR_Z);
}
