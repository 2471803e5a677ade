#version 330 core
// geometry.frag.glsl - lit solid geometry: the sun (Lambert) and the sky's ambient, with exp2
// fog toward the above- or below-water fog colour by which side of the water the camera and the
// point are on.

uniform vec3 u_ambient;        // sky ambient, linear RGB
uniform vec3 u_cam;            // camera position relative to the water's rest level (0, y, 0)
uniform vec3 u_fog_color;      // above water, linear RGB
uniform float u_fog_density;   // above water, 1/m
uniform vec3 u_fog_below_color;
uniform float u_fog_below_density;
uniform int u_depth_only;      // shadow pass: no colour

in vec3 v_pos;
in vec3 v_normal;
in vec2 v_uv;
in vec4 v_color;
out vec4 o_color;

void main() {
    if (u_depth_only != 0) {
        o_color = vec4(0.0);
        return;
    }
    vec3 n = normalize(v_normal);
    float sun_up = smoothstep(-0.02, 0.02, u_sun_dir.y);
    vec3 lit = v_color.rgb * (u_ambient + u_sun_color * max(dot(n, u_sun_dir), 0.0) * sun_up);
    lit += v_color.rgb * v_color.a;

    // fog: below the water when the camera is, above otherwise
    float dist = length(v_pos);
    bool below = u_cam.y < 0.0;
    float k = (below ? u_fog_below_density : u_fog_density) * dist;
    vec3 fog = below ? u_fog_below_color : u_fog_color;
    o_color = vec4(mix(fog, lit, exp(-k * k)), 1.0);
}
