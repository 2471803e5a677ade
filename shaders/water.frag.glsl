#version 330 core
// water.frag.glsl - per-pixel analytic normal of the wave field and ripples (gerstner.glsl:
// ww_partials, components filtered by the pixel footprint) and water shading: Schlick Fresnel
// between the lit deep-water colour and the reflected sky, Blinn-Phong sun glitter, exp2 fog.

uniform vec3 u_water_color; // deep-water scattering colour, linear RGB
uniform vec3 u_ambient;     // sky ambient, linear RGB
uniform vec3 u_fog_color;   // linear RGB (the CPU substitutes the horizon colour when asked)
uniform float u_fog_density; // 1/m
uniform float u_pixel_angle; // angle one pixel spans, rad

in vec2 v_local;
in vec3 v_pos;
out vec4 o_color;

const float F0 = 0.02;          // reflectance of water at normal incidence
const float SPEC_POWER = 600.0; // Blinn-Phong exponent of a calm surface

float schlick(float c) {
    float m = 1.0 - clamp(c, 0.0, 1.0), m2 = m * m;
    return F0 + (1.0 - F0) * (m2 * m2 * m);
}

void main() {
    float dist = length(v_pos);
    vec3 v = -v_pos / max(dist, 1e-6); // toward the camera

    // the pixel's footprint on the water: dist * pixel angle across the view, stretched by
    // 1 / sin(elevation) along it (grazing rays see long footprints)
    float hl = length(v.xz);
    vec2 along = hl > 1e-5 ? -v.xz / hl : vec2(1.0, 0.0);
    vec2 across = vec2(-along.y, along.x);
    float stretch = 1.0 / max(abs(v.y), 0.01);
    float pix = dist * u_pixel_angle;

    // surface partials dP/dx, dP/dz at the rest point (gerstner.glsl: ww_partials). The geometry
    // fades waves by the mesh spacing; the normals fade each wave by the footprint along its
    // direction instead, so they keep close-up detail the mesh cannot carry and drop what a
    // pixel cannot show. The slope variance of what the fades removed widens the sun highlight
    // instead of vanishing.
    vec3 dpdx, dpdz;
    float removed;
    ww_partials(v_local, ww_footprint_make(along, across, stretch, pix), dpdx, dpdz, removed);
    vec3 n = normalize(cross(dpdz, dpdx));

    vec3 l = u_sun_dir;
    float ndv = max(dot(n, v), 0.0);
    float ndl = max(dot(n, l), 0.0);
    float sun_up = smoothstep(-0.02, 0.02, l.y); // the horizon hides the sun

    // refraction: deep water lit by the sky and a little sun; reflection: the sky
    vec3 deep = u_water_color * (u_ambient + 0.1 * sun_up * ndl * u_sun_color);
    vec3 sky = ww_sky(reflect(-v, n));
    float fr = schlick(ndv);
    vec3 c = mix(deep, sky, fr);

    // sun glitter: normalised Blinn-Phong whose roughness grows with the removed slopes
    // (Beckmann m^2 ~ slope variance; exponent n = 2 / m^2 - 2). No n.l factor: a mirror
    // reflects a low sun as brightly as a high one, which is what makes the path at sunset
    vec3 h = normalize(l + v);
    float m2 = 2.0 / (SPEC_POWER + 2.0) + removed;
    float pw = 2.0 / m2 - 2.0;
    float spec = (pw + 8.0) / (8.0 * WW_PI) * pow(max(dot(n, h), 0.0), pw);
    c += u_sun_color * (spec * schlick(dot(h, v)) * sun_up);

    // exp2 fog toward the fog colour lit by the sun glow along the view
    float fog = exp(-(u_fog_density * dist) * (u_fog_density * dist));
    o_color = vec4(mix(u_fog_color + ww_sun_glow(-v), c, fog), 1.0);
}
