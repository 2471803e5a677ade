// gerstner.glsl - the Gerstner wave field of src/sim/waves.h in float, for the water vertex and
// fragment shaders (prepended after common.glsl). Phases are taken at the mesh centre on the CPU
// in double, so phi = phase_c + kD . local stays exact far from the origin and at large t.

uniform int u_nwaves;
uniform vec4 u_wave[WW_MAX_WAVES];        // (k Dx, k Dz, A, Q): wavenumber * direction, m, 1
uniform float u_wave_phase[WW_MAX_WAVES]; // phase at the mesh centre, rad in [0, 2 pi)
uniform vec3 u_grid; // polar mesh: (first ring spacing s0 m, ring growth q - 1, angular step rad)

// local spacing of the polar mesh at rest offset p from its centre: rings are s0 q^j apart, so
// the ring spacing at radius r is s0 + (q - 1) r; around a ring the spacing is r dtheta
float ww_grid_spacing(vec2 p) {
    float r = length(p);
    return max(u_grid.x + u_grid.y * r, r * u_grid.z);
}

// anti-aliasing LOD: a wave's amplitude fades to 0 where its wavelength 2 pi / k drops from
// 4 to 2 sample spacings s (mesh spacing for the geometry, pixel footprint for the normals),
// below which the samples cannot carry it
float ww_wave_fade(float k, float s) {
    return smoothstep(2.0, 4.0, (2.0 * WW_PI / k) / max(s, 1e-6));
}

// phase of wave i at rest offset p: phi = k D.x - w t + p0, with x = centre + p
float ww_wave_phi(int i, vec2 p) {
    return u_wave_phase[i] + dot(u_wave[i].xy, p);
}
