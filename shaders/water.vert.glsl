#version 330 core
// water.vert.glsl - displaces the camera-centred polar mesh with the Gerstner sum (waves.h):
//   X = x + sum Q A D cos(phi),  Y = level + sum A sin(phi),  phi = phase_c + kD . local
// Positions are camera-relative: the view matrix holds the camera's rotation only.

layout(location = 0) in vec2 a_local; // rest offset from the snapped mesh centre (x, z), m

uniform mat4 u_view_proj; // projection * camera rotation
uniform vec3 u_origin;    // (centre.x - cam.x, level - cam.y, centre.z - cam.z), m

out vec2 v_local; // rest offset, for the per-pixel normal
out vec3 v_pos;   // displaced surface point relative to the camera, m

void main() {
    float s = ww_grid_spacing(a_local);
    vec3 p = vec3(a_local.x, 0.0, a_local.y);
    for (int i = 0; i < u_nwaves; i++) {
        vec4 w = u_wave[i];
        float k = length(w.xy);
        float a = w.z * ww_wave_fade(k, s);
        float phi = ww_wave_phi(i, a_local);
        p.xz += (w.w * a * cos(phi) / k) * w.xy;
        p.y += a * sin(phi);
    }
    v_local = a_local;
    v_pos = u_origin + p;
    gl_Position = u_view_proj * vec4(v_pos, 1.0);
}
