// gerstner.glsl - the wave field of src/sim/waves.h and the ripples of src/sim/ripples.c in float,
// shared by the water shaders and the GPU probe (prepended after common.glsl). Two functions
// carry the whole surface: ww_displace (what the water vertex shader and the probe displace
// with) and ww_partials (what the water fragment shader and the probe take normals from).
//
// Phases are taken at the centre (the snapped mesh centre, or the probe's camera) on the CPU in
// double and wrapped, and every position is relative to that centre, so phi = phase_c + kD . p
// stays exact in float far from the origin and at large t (gfx/water.c packs the blocks).
//
// Defines (program.c puts them after #version; gfx/water.c chooses them per scene):
//   WW_WAVE_MODEL  WW_MODEL_GERSTNER (also the spectrum model), _SINES, _STEEP or _FLAT: one
//                  family per program, so no branch and no pow() for the families not drawn
//   WW_RIPPLES     1: the ripple block and its loop exist
//   WW_FADE        0: every component at full amplitude everywhere (the probe, WW_WATER_FADE=0)

#define WW_MODEL_FLAT 0
#define WW_MODEL_GERSTNER 1
#define WW_MODEL_SINES 2
#define WW_MODEL_STEEP 3
#ifndef WW_WAVE_MODEL
#define WW_WAVE_MODEL WW_MODEL_GERSTNER
#endif
#ifndef WW_RIPPLES
#define WW_RIPPLES 0
#endif
#ifndef WW_FADE
#define WW_FADE 1
#endif
// WW_NWAVES: the count of components, u_nwaves, built in by the programs (water.c, geometry.c),
// so the loops over them have a fixed count llvmpipe's compiler unrolls
#ifndef WW_NWAVES
#define WW_NWAVES u_nwaves
#endif

// the components, sorted by wavenumber ascending (water.c keeps the permutation), so a loop can
// stop at the first one faded out: every later one is shorter and faded as well. A loop reads
// only what it needs: llvmpipe gathers each indexed load lane by lane, which costs more than
// recomputing k = |kD| and 2 pi / k.
layout(std140) uniform WwWaves {
    int u_nwaves;
    float u_slope2_total;       // sum of the components' mean square slopes
    vec4 u_wave[WW_MAX_WAVES];  // (k Dx, k Dz, A, Q): wavenumber * direction 1/m, m, 1 (Q 0 but gerstner)
    vec4 u_wave2[WW_MAX_WAVES]; // (phase at the centre rad in [0, 2 pi), exponent e, mean of
                                //  ((sin + 1) / 2)^e, mean square slope per (A k)^2: 1/2 but steep sines)
};

#if WW_RIPPLES
// the live entries of the ripple pool (sim/ripples.h), ages computed on the CPU in double
layout(std140) uniform WwRipples {
    int u_nripples;
    vec4 u_ripple_param;            // (alpha 1/m, beta 1/s, kr rad/m, v m/s)
    vec4 u_ripple_shape;            // (front width lambda = 2 pi / kr m, softening r0 = 1 / kr m, 0, 0)
    vec4 u_ripple_bound;            // (x - centre.x m, z - centre.z m, radius m, 0): every front
                                    // lies inside this circle (radius < 0: no ripple)
    vec4 u_ripple[WW_MAX_RIPPLES];  // (x - centre.x m, z - centre.z m, age s, A0 m)
};
#endif

uniform vec3 u_grid; // polar mesh: (first ring spacing s0 m, ring growth q - 1, angular step rad)

// local spacing of the polar mesh at rest offset p from its centre: rings are s0 q^j apart, so
// the ring spacing at radius r is s0 + (q - 1) r; around a ring the spacing is r dtheta
float ww_grid_spacing(vec2 p) {
    float r = length(p);
    return max(u_grid.x + u_grid.y * r, r * u_grid.z);
}

// anti-aliasing LOD: a wave's amplitude fades to 0 where its wavelength L drops from 4 to 2
// sample spacings s (mesh spacing for the geometry, pixel footprint for the normals), below
// which the samples cannot carry it (scene/plan.h: WW_FADE_START_SAMPLES, _END_SAMPLES).
// Takes 1 / s, so a loop over components divides once.
#define WW_FADE_FULL 4.0 // samples per wavelength from which a component is drawn whole
float ww_wave_fade(float L, float inv_s) {
#if WW_FADE
    return smoothstep(2.0, WW_FADE_FULL, L * inv_s);
#else
    return 1.0;
#endif
}

// the fade has taken wavelength L away entirely: at most 2 samples per wavelength
bool ww_faded_out(float L, float inv_s) {
#if WW_FADE
    return L * inv_s <= 2.0;
#else
    return false;
#endif
}

// a pixel's footprint on the water: pix (m) across the view, stretched by `stretch` along it
struct ww_footprint {
    vec2 along, across; // unit, horizontal
    float stretch;      // >= 1
    float inv_pix;      // 1 / pix, 1/m
};

ww_footprint ww_footprint_make(vec2 along, vec2 across, float stretch, float pix) {
    return ww_footprint(along, across, stretch, 1.0 / max(pix, 1e-6));
}

// a footprint of s in every direction (a mesh spacing; 0 with the fade off)
ww_footprint ww_footprint_round(float s) {
    return ww_footprint_make(vec2(1.0, 0.0), vec2(0.0, 1.0), 1.0, s);
}

// the fade of wavelength L travelling along unit d, by the footprint along d:
// pix |(d.along stretch, d.across)|, never below pix
float ww_wave_fade_along(float L, vec2 d, ww_footprint fp) {
#if WW_FADE
    vec2 e = vec2(dot(d, fp.along) * fp.stretch, dot(d, fp.across));
    return ww_wave_fade(L, fp.inv_pix * inversesqrt(max(dot(e, e), 1e-12)));
#else
    return 1.0;
#endif
}

// phase of component i at rest offset p: phi = k D.x - w t + p0, with x = centre + p
float ww_wave_phi(int i, vec2 p) {
    return u_wave2[i].x + dot(u_wave[i].xy, p);
}

#if WW_RIPPLES
// the sum of the pool's ripples at offset q from the centre, as ripples.c: (h, dh/dx, dh/dz).
//   h = A0 e^(-alpha r) e^(-beta age) sin(kr (r - v age)) W,  r = sqrt(d^2 + r0^2)
// W the causal front (1 behind r = v age, 0 one wavelength ahead, C1 between). Each ripple is
// faded by the footprint along its radius; when the footprint is too coarse in every direction
// none is evaluated. Ripples are local: what their fade removes does not widen the highlight.
vec3 ww_ripples(vec2 q, ww_footprint fp) {
    vec3 s = vec3(0.0);
    float alpha = u_ripple_param.x, beta = u_ripple_param.y, kr = u_ripple_param.z;
    float v = u_ripple_param.w, lambda = u_ripple_shape.x, r0 = u_ripple_shape.y;
    if (ww_faded_out(lambda, fp.inv_pix)) return s;
    // outside the circle that holds every front no ripple has arrived: the loop's count is per
    // point, so llvmpipe leaves it for a block of pixels none of which lies inside (a branch
    // would cost every pixel the loop's body)
    vec2 dc = q - u_ripple_bound.xy;
    float rb = u_ripple_bound.z;
    int n = rb >= 0.0 && dot(dc, dc) <= rb * rb ? u_nripples : 0;
    for (int i = 0; i < n; i++) {
        vec4 e = u_ripple[i];
        vec2 d = q - e.xy;
        float r = sqrt(dot(d, d) + r0 * r0);
        float age = e.z;
        float u = (v * age - r) / lambda + 1.0;
        if (u <= 0.0) continue; // the front has not arrived
        float w = 1.0, dw = 0.0;
        if (u < 1.0) {
            w = u * u * (3.0 - 2.0 * u);
            dw = 6.0 * u * (1.0 - u);
        }
        float dl = length(d);
        float f = ww_wave_fade_along(lambda, dl > 0.0 ? d / dl : fp.across, fp);
        float env = f * e.w * exp(-alpha * r - beta * age);
        float psi = kr * (r - v * age);
        float sp = sin(psi), cp = cos(psi);
        // dh/dr of env sin(psi) W, then the chain rule through r(x, z): dr/dx = dx / r
        float dhdr = env * (-alpha * sp * w + kr * cp * w - sp * dw / lambda);
        s += vec3(env * sp * w, dhdr * d / r);
    }
    return s;
}
#endif

// the displacement of rest offset p by the waves (each faded by the sample spacing s), plus the
// ripples' height at the displaced horizontal point (the world point it ends up at, where
// sim/water.h reads them):
//   gerstner     (sum Q A D cos(phi), sum A sin(phi))
//   sines        (0, sum A sin(phi))
//   steep sines  (0, sum 2 A (((sin(phi) + 1) / 2)^e - mean_e))   (seed 001)
vec3 ww_displace(vec2 p, float s) {
    vec3 d = vec3(0.0);
#if WW_WAVE_MODEL != WW_MODEL_FLAT
    float inv_s = 1.0 / max(s, 1e-6);
    for (int i = 0; i < WW_NWAVES; i++) {
        vec4 w = u_wave[i];
        float k = length(w.xy);
        float f = ww_wave_fade(2.0 * WW_PI / k, inv_s);
        if (f == 0.0) break; // sorted by k: the rest are shorter, faded out too
        float a = w.z * f;
        float phi = ww_wave_phi(i, p);
#if WW_WAVE_MODEL == WW_MODEL_GERSTNER
        d.xz += (w.w * a * cos(phi) / k) * w.xy;
        d.y += a * sin(phi);
#elif WW_WAVE_MODEL == WW_MODEL_SINES
        d.y += a * sin(phi);
#else
        float u = 0.5 * (sin(phi) + 1.0);
        d.y += 2.0 * a * (pow(u, u_wave2[i].y) - u_wave2[i].z);
#endif
    }
#endif
#if WW_RIPPLES
    d.y += ww_ripples(p + d.xz, ww_footprint_round(s)).x;
#endif
    return d;
}

// the partials dP/dx, dP/dz of the displaced surface point with respect to the rest offset p
// (seed 001's analytic normal is normalize(dpdz x dpdx)), each component faded by the footprint
// fp along its direction; `removed` is the mean square slope the fade took away (the shading
// widens the sun highlight by it). Ripples add their gradient at the displaced point through
// the chain rule: d(h(X(p)))/dx = grad h . dX/dx.
void ww_partials(vec2 p, ww_footprint fp, out vec3 dpdx, out vec3 dpdz, out float removed) {
    dpdx = vec3(1.0, 0.0, 0.0);
    dpdz = vec3(0.0, 0.0, 1.0);
    removed = 0.0;
    vec2 disp = vec2(0.0); // horizontal displacement, for where the ripples are read
#if WW_WAVE_MODEL != WW_MODEL_FLAT
    float seen = 0.0; // mean square slope of the components so far
    float inv_long = fp.inv_pix / fp.stretch; // 1 / the footprint along the view
    for (int i = 0; i < WW_NWAVES; i++) {
        vec4 w = u_wave[i];
        float k = length(w.xy), L = 2.0 * WW_PI / k;
        // the smallest footprint of any direction is pix: faded out there, faded everywhere
        if (ww_faded_out(L, fp.inv_pix)) {
            removed += max(u_slope2_total - seen, 0.0); // this one and all later ones
            break;
        }
#if WW_WAVE_MODEL == WW_MODEL_STEEP
        float slope2 = u_wave2[i].w * (w.z * k) * (w.z * k);
#else
        float slope2 = 0.5 * (w.z * k) * (w.z * k);
#endif
        seen += slope2;
        vec2 dir = w.xy / k;
        // the largest footprint of any direction is pix stretch: at least 4 samples per
        // wavelength there, at least 4 along every direction, so no fade to work out
        float f = L * inv_long >= WW_FADE_FULL ? 1.0 : ww_wave_fade_along(L, dir, fp);
        float a = w.z * f;
        float phi = ww_wave_phi(i, p);
#if WW_WAVE_MODEL == WW_MODEL_GERSTNER
        float qaks = w.w * a * k * sin(phi), akc = a * k * cos(phi);
        dpdx += vec3(-qaks * dir.x * dir.x, akc * dir.x, -qaks * dir.x * dir.y);
        dpdz += vec3(-qaks * dir.x * dir.y, akc * dir.y, -qaks * dir.y * dir.y);
#if WW_RIPPLES
        disp += (w.w * akc / (k * k)) * w.xy;
#endif
#elif WW_WAVE_MODEL == WW_MODEL_SINES
        float akc = a * k * cos(phi);
        dpdx.y += akc * dir.x;
        dpdz.y += akc * dir.y;
#else
        // d/dphi of 2 A (u^e - mean) with u = (sin + 1) / 2: A e u^(e - 1) cos
        float e = u_wave2[i].y;
        float u = 0.5 * (sin(phi) + 1.0);
        float um = e > 1.0 ? pow(u, e - 1.0) : 1.0;
        float akc = a * k * e * um * cos(phi);
        dpdx.y += akc * dir.x;
        dpdz.y += akc * dir.y;
#endif
        removed += (1.0 - f * f) * slope2;
    }
#endif
#if WW_RIPPLES
    vec3 g = ww_ripples(p + disp, fp);
    dpdx.y += g.y * dpdx.x + g.z * dpdx.z;
    dpdz.y += g.y * dpdz.x + g.z * dpdz.z;
#endif
}
