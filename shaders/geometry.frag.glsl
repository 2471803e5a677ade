#version 330 core
// geometry.frag.glsl - lit solid geometry (gfx/geometry.c), after common.glsl, gerstner.glsl and
// shadow.glsl:
//   sun: Lambert + a little Blinn-Phong specular, shadowed (shadow.glsl), dimmed under water by
//        the column of water above the point, and focused into caustics by the wave field;
//   sky: hemisphere ambient (brighter on faces turned up);
//   lights: point and spot lights (seed 003's lantern) with the smooth range window of Karis,
//        "Real Shading in Unreal Engine 4" (SIGGRAPH 2013 course): (1 - (d/r)^4)^2 / (d^2 + 1),
//        spots fading over the outer `softness` of their cone;
//   fog: exp2 above and below the water (seeds 000, 003). Seed 000 fogs a point by the medium
//        the camera is in; here the segment camera -> point is split where it crosses the water
//        plane and each part is fogged by its own medium, far part first.
// Modes (WW_GEOM_MODE, one build of the program each: llvmpipe runs both arms of a branch for
// every pixel, so a mode switched by a uniform made the lit seabed pay for the others' code):
// 0 depth only (shadow map), 1 lit, 2 the chest's glow column (additive), 3 an air bubble
// (blended, premultiplied), 4 the fishing line or its rod (gfx/line.h: a ribbon facing the
// camera standing for a thin cylinder, lit as mode 1, blended by its coverage, premultiplied),
// 5 the boat's wake (gfx/wake.h: foam lying on the water, blended, premultiplied).
// Emission: the instance's emission times its albedo is added unlit (objects.models' emissive,
// the lure), so it feeds bloom.
// Defines: WW_CAUSTICS 1 when water.look.caustics is on (method analytic), 2 with method texture;
// WW_FISH_PATTERNS 1 in the build that draws the fish species' slots (their colour patterns,
// below); WW_MAT_MAP 1 in the build that draws an OBJ submesh with a map_Kd (geometry.c);
// WW_LIGHT_SCATTER 1 when a light glows in the water (common.glsl: the lights' in-scattering
// along the part of the view ray under water).

#ifndef WW_CAUSTICS
#define WW_CAUSTICS 0
#endif
#ifndef WW_FISH_PATTERNS
#define WW_FISH_PATTERNS 0
#endif
#ifndef WW_MAT_MAP
#define WW_MAT_MAP 0
#endif
// WW_SUNLESS 1: the build for the stencilled shadows' second draw of what lies in shadow
// (geometry.c): no sunlight reaches it, so none of the sun's terms is built in (what the lit
// build gives with ww_shadow 0: the ambient, the lights and the emission)
#ifndef WW_SUNLESS
#define WW_SUNLESS 0
#endif

#ifndef WW_GEOM_MODE
#define WW_GEOM_MODE 1
#endif
uniform vec3 u_ambient;        // sky ambient, linear RGB
uniform vec3 u_eye;            // the eye, camera-relative (the mirrored camera in reflections)
uniform int u_inside;          // reflection and prepass: 1 a closed mesh their cut may open,
                               // 2 the hull (its hollow too: geometry.vert.glsl)
uniform bool u_mirrored;       // reflection pass: u_eye is the camera mirrored below the water,
                               // and the path it stands for (camera -> surface -> p) is all air
uniform vec3 u_fog_color;      // above water, linear RGB
uniform float u_fog_density;   // above water, 1/m
uniform vec3 u_fog_below_color;
uniform float u_fog_below_density;
uniform vec3 u_extinction;     // sunlight lost per metre of water it crosses, 1/m per channel
uniform float u_caustics;      // strength (0 off)
// the lights' uniforms and their range window: common.glsl (the water shares them)
// the OBJ material of the submesh drawn (gfx/geometry.c; the identity for every other mesh)
uniform vec4 u_mat_kd;         // Kd, multiplying the instance's albedo (times map_Kd: WW_MAT_MAP)
uniform vec4 u_mat_ks;         // Ks and Ns (a): Blinn-Phong; Ns 0: the instance's own specular
uniform vec4 u_mat_ke;         // Ke, emitted radiance added unlit, linear RGB; a: d (opacity)
uniform sampler2D u_mat_map;   // map_Kd, sRGB (read as linear)
uniform vec4 u_glow;           // the glow column: axis x, z (camera-relative), radius m, 1/m
uniform vec2 u_glow_y;         // its bottom and top, camera-relative y, m

in vec3 v_pos;
flat in float v_hollow;        // 1: a face of the hull's hollow (u_inside 2)
flat in float v_water_y;       // the water plane (surface over the camera; in the reflection,
                               // over what the instance is mirrored about), camera-relative y
in vec3 v_normal;
in vec2 v_uv;
in vec4 v_color;
in float v_spec;
#if WW_FISH_PATTERNS
in vec3 v_mesh;
flat in float v_pattern;
#endif
#if WW_GEOM_MODE == 5
flat in vec3 v_wake;
#endif
out vec4 o_color;

const float WW_SHININESS = 48.0;
const float WW_ETA_WATER = 1.333;
const float BUBBLE_DISC_MEAN = 0.55; // a bubble's mean reflectance over its disc (see mode 3)
const float WW_CAUSTIC_MIN_DET = 0.12; // caps the focus at about 8x (the sun is not a point)

#if WW_CAUSTICS == 1 && WW_WAVE_MODEL != WW_MODEL_FLAT
// caustics: the refracted sun through the surface above lands at x = q + d T(n(q)); to first
// order in the slope T_xz = -kappa grad h with kappa = 1 - 1 / eta, so the landing map is
// q -> q - d kappa grad h(q) and the light it carries spreads by its Jacobian determinant
// det(I - d kappa H), H the Hessian of the height (the irradiance is 1 / |det|, mean 1).
// H = -sum A k^2 D D^T sin(phi) for every family taken as sines; components shorter than the
// blur of the sun's disc over the depth (and the pixel) are faded out.
const int WW_NDETAIL = 6; // gfx/render_impl.h: WW_WATER_NDETAIL
// the surface's normal-only detail (gfx/waveblock.c), as water.frag.glsl's: (k Dx, k Dz 1/m,
// slope amplitude A k, phase at the camera rad), longest first
uniform vec4 u_detail[WW_NDETAIL];
// the water's DuDv pattern (water.frag.glsl; gfx/waveblock.c: ww_water_dudv): per layer the mat2
// from camera-relative metres to lattice cells and the offset, and (DETAIL_SLOPE / cells per
// metre, 0): the height of the small ripples it stands for per unit of noise
uniform vec4 u_dudv_m[2];
uniform vec2 u_dudv_o[2];
uniform vec2 u_dudv_h;
const float DUDV_WEIGHT0 = 0.6; // water.frag.glsl: LAYER_WEIGHT0, LAYER_WEIGHT1
const float DUDV_WEIGHT1 = 0.4;

// water.frag.glsl's lattice hash (PCG output permutation, 256 cells), so the caustics see the
// same ripples the water's shading draws
float ww_dudv_hash(ivec2 c) {
    uvec2 q = uvec2(c & 255);
    uint h = q.x + q.y * 256u;
    h = h * 747796405u + 2891336453u;
    h = ((h >> ((h >> 28u) + 4u)) ^ h) * 277803737u;
    h = (h >> 22u) ^ h;
    return float(h) * (1.0 / 4294967295.0);
}

// the Hessian (d2n/dx2, d2n/dy2, d2n/dxdy, in cells) of the DuDv's value noise in [-1, 1]: the
// same lattice values, interpolated with the septic fade 35f^4 - 84f^5 + 70f^6 - 20f^7, whose
// first three derivatives vanish at the cell edges. With the water's cubic fade the curvature
// jumps at every edge, with Perlin's quintic ("Improving Noise", 2002) it kinks there: either
// way the caustics would draw the lattice's straight lines.
vec3 ww_dudv_hessian(vec2 x) {
    vec2 i = floor(x), f = x - i, g = 1.0 - f;
    vec2 u = f * f * f * f * (35.0 - f * (84.0 - f * (70.0 - 20.0 * f)));
    vec2 du = 140.0 * f * f * f * g * g * g;
    vec2 ddu = 420.0 * f * f * g * g * (1.0 - 2.0 * f);
    ivec2 c = ivec2(i);
    float a = ww_dudv_hash(c), b = ww_dudv_hash(c + ivec2(1, 0));
    float d = ww_dudv_hash(c + ivec2(0, 1)), e = ww_dudv_hash(c + ivec2(1, 1));
    float k = a - b - d + e;
    return 2.0 * vec3(ddu.x * (b - a + k * u.y), ddu.y * (d - a + k * u.x), k * du.x * du.y);
}

float ww_caustic(vec2 q, float depth) {
    float kappa = 1.0 - 1.0 / WW_ETA_WATER;
    float blur = depth * 2.0 * WW_SUN_RADIUS + 0.05;
    mat2 H = mat2(0.0);
    for (int i = 0; i < WW_NWAVES; i++) {
        vec4 w = u_wave[i];
        float k = length(w.xy), L = 2.0 * WW_PI / k;
        float f = smoothstep(2.0 * blur, 6.0 * blur, L);
        if (f == 0.0) break; // sorted by k: the rest are shorter still
        vec2 d = w.xy / k;
        H -= (f * w.z * k * k * sin(ww_wave_phi(i, q))) * outerProduct(d, d);
    }
    // the surface's fine detail (a height (A k / k) sin phi each): the short ripples that make
    // most of what a seabed shows, long swells alone focusing only a few percent
    for (int j = 0; j < WW_NDETAIL; j++) {
        vec4 w = u_detail[j];
        float k = length(w.xy), L = 2.0 * WW_PI / k;
        float f = smoothstep(2.0 * blur, 6.0 * blur, L);
        if (f == 0.0) break; // longest first: the rest are shorter still
        vec2 d = w.xy / k;
        H -= (f * w.z * k * sin(w.w + dot(w.xy, q))) * outerProduct(d, d);
    }
    // the irregular small ripples the water's DuDv pattern draws (seed 002): a height
    // u_dudv_h.x sum_j w_j n_j(M_j q + o_j), whose Hessian is M_j^T Hn M_j per layer. Without
    // them, 10 m down only the two longest detail sines outlast the sun's blur and their
    // product draws a plaid; real caustics there are an irregular web.
    for (int j = 0; j < 2; j++) {
        mat2 m = mat2(u_dudv_m[j].xy, u_dudv_m[j].zw);
        float f = smoothstep(2.0 * blur, 6.0 * blur, 1.0 / length(m[0])); // a cell, m
        if (f == 0.0) continue;
        vec3 hn = ww_dudv_hessian(m * q + u_dudv_o[j]);
        mat2 hc = mat2(hn.x, hn.z, hn.z, hn.y);
        H += (f * u_dudv_h.x * (j == 0 ? DUDV_WEIGHT0 : DUDV_WEIGHT1)) * (transpose(m) * hc * m);
    }
    mat2 J = mat2(1.0) - (depth * kappa) * H;
    return 1.0 / max(abs(determinant(J)), WW_CAUSTIC_MIN_DET);
}
#endif

#if WW_CAUSTICS == 2
// method texture: seed 003's looped set of caustic frames (gfx/caustic_set.c), computed from the
// wave field on a periodic patch and focused at the seabed's depth; sampled at the surface point
// q the refracted sun ray left from, the two frames of this instant blended
uniform sampler2DArray u_caustic_set;
uniform vec4 u_caustic_set_at;    // (camera x, z wrapped to the patch m; 1 / patch 1/m; depth m)
uniform vec2 u_caustic_set_frame; // (frame, the next one's weight)

float ww_caustic(vec2 q, float depth) {
    vec2 uv = (q + u_caustic_set_at.xy) * u_caustic_set_at.z;
    // layer i holds frames i and i + 1: one lookup for both
    vec2 ab = texture(u_caustic_set, vec3(uv, u_caustic_set_frame.x)).rg;
    float c = mix(ab.x, ab.y, u_caustic_set_frame.y);
    // shallower than the depth it was focused at, the focusing d kappa H grows with the depth
    // (to first order): the contrast scales down with it
    return 1.0 + (c - 1.0) * min(depth / u_caustic_set_at.w, 1.0);
}
#endif

// exp2 fog of colour c over length l in the medium above (below = false) or below the water
vec3 ww_fog(vec3 c, float l, bool below) {
    float k = (below ? u_fog_below_density : u_fog_density) * l;
    return mix(below ? u_fog_below_color : u_fog_color, c, exp(-k * k));
}

// the eye: in the reflection the camera mirrored about the plane the instance is mirrored
// about (u_eye holds it mirrored about the surface over the camera)
vec3 ww_eye() {
    return u_mirrored ? vec3(u_eye.x, 2.0 * v_water_y, u_eye.z) : u_eye;
}

// the segment eye -> p split at the water plane: the far part first, then the near part
vec3 ww_fog_segment(vec3 c, vec3 p) {
    vec3 e = ww_eye();
    float he = e.y - v_water_y, hp = p.y - v_water_y, len = length(p - e);
    bool eye_below = he < 0.0 && !u_mirrored, p_below = hp < 0.0, split = eye_below != p_below;
    // unsplit, the far part is the whole segment: two fogs, not three (llvmpipe would work out
    // the unsplit case's as well for every pixel)
    float near = split ? len * he / (he - hp) : 0.0; // where the segment crosses the plane
    c = ww_fog(c, len - near, p_below);
    return split ? ww_fog(c, near, eye_below) : c;
}

#if WW_FISH_PATTERNS
// a species' markings over its albedo c, in mesh space (head +x, back +y, unit length):
//   1 slim (mackerel): a dark back with wavy dark bars over a silver belly, lateral line above
//     the middle;
//   2 deep (angelfish, butterflyfish): dark vertical bands (one through the eye), dark fin edges;
//   3 long: a paler belly and pale spots along the flank.
// Every fish gets a dark eye with a light ring. Bands fade to their mean where they would be
// finer than a pixel (fwidth), so a far school does not shimmer.
vec3 ww_fish_pattern(vec3 c, vec3 m, float pattern) {
    int k = int(pattern + 0.5);
    vec2 eye = k == 1 ? vec2(0.40, 0.02) : k == 2 ? vec2(0.33, 0.07) : vec2(0.44, 0.012);
    float eye_r = k == 1 ? 0.02 : k == 2 ? 0.03 : 0.014;
    if (k == 1) {
        vec3 belly = vec3(0.72, 0.75, 0.78);
        float back = smoothstep(-0.005, 0.025, m.y);
        float ph = 48.0 * m.x + 3.0 * sin(90.0 * m.y);
        float aa = clamp(1.0 - 2.0 * fwidth(ph) / 6.2832, 0.0, 1.0);
        float bar = mix(0.5, smoothstep(0.2, 0.6, sin(ph)), aa);
        c = mix(belly, c * (1.0 - 0.7 * bar), back);
    } else if (k == 2) {
        float ph = 4.5 * m.x + 0.17;
        float aa = clamp(1.0 - 4.0 * fwidth(ph), 0.0, 1.0);
        float f = fract(ph);
        float band = mix(0.3, smoothstep(0.0, 0.04, f) * (1.0 - smoothstep(0.26, 0.3, f)), aa);
        band = max(band, smoothstep(0.36, 0.42, abs(m.y)));
        c = mix(c, c * 0.05, band);
    } else if (k == 3) {
        c = mix(c, vec3(0.85, 0.62, 0.5), smoothstep(0.0, -0.03, m.y));
        float ph = 70.0 * m.x, aa = clamp(1.0 - 2.0 * fwidth(ph) / 6.2832, 0.0, 1.0);
        float spot = smoothstep(0.75, 0.9, sin(ph) * sin(160.0 * m.y + 1.0)) * aa;
        c = mix(c, vec3(0.95, 0.8, 0.65), 0.6 * spot);
    }
    float d = length(m.xy - eye);
    if (abs(m.z) > 0.004) {
        c = mix(c, vec3(0.8), 1.0 - smoothstep(eye_r, eye_r * 1.35, d));
        c = mix(c, vec3(0.02), 1.0 - smoothstep(eye_r * 0.75, eye_r * 0.95, d));
    }
    return c;
}
#endif

#if WW_GEOM_MODE == 5
// the wake's foam: times s, widths m (gfx/wake.h's WW_WAKE_BAND is WAKE_ARM_BAND)
const float WAKE_WASH_LIFE = 1.2;    // the wash's fresh foam fades by e in this ...
const float WAKE_ARM_LIFE = 2.5;     // ... the arms' and the bow wave's ...
const float WAKE_LACE_LIFE = 3.5;    // ... and the lace either leaves
const float WAKE_WASH_SPREAD = 0.08; // the wash widens by this each side per m behind the stern
const float WAKE_ARM_BAND = 0.3;     // the bow wave's and the arms' band inside the edge ...
const float WAKE_ARM_GROW = 0.03;    // ... widening by this per m behind the stern
const float WAKE_COVER_MAX = 0.85;
const float WAKE_WASH_FRESH = 0.8;   // the wash's fresh coverage right behind the transom
const float WAKE_ARM_FRESH = 0.8;    // the arms' and bow wave's
const float WAKE_LACE_FRESH = 0.8;   // the lace's, where it starts ...
const float WAKE_ARM_LACE = 0.6;     // ... and the share of it the arms' breaking leaves
const float WAKE_CREST_SPACING = 0.9; // m between the arms' breaking crests, across them
const float WAKE_CREST_CYCLE = 1.5;  // s over which their raggedness changes
const float WAKE_GROW = 0.7;         // noise level the coverage lifts the patches by
const float WAKE_SOFT = 0.6;         // a patch's edge, in the noise's range
const float WAKE_LACE_WIDTH = 0.35;  // the lace's lines: the noise's range about its middle
const float WAKE_LACE_MEAN = 0.2;    // the lace's mean cover (of its old^2) where it fades out

// two octaves of value noise at q (cells), in [0, 1], each faded to its mean where its cells
// span under about two pixels (fp: a pixel in cells along each axis); y: the first's weight
vec2 ww_wake_noise(vec2 q, vec2 fp) {
    float f = max(fp.x, fp.y);
    float w1 = 1.0 - smoothstep(0.25, 0.5, f), w2 = 1.0 - smoothstep(0.25, 0.5, 3.0 * f);
    float n1 = mix(0.5, ww_value_noise(q), w1);
    float n2 = mix(0.5, ww_value_noise(3.0 * q + vec2(37.0, 91.0)), w2);
    return vec2(0.65 * n1 + 0.35 * n2, w1);
}

// foam: a fresh coverage as patches of the noise n that grow with it, and an older coverage as
// a lace along the middle level of the noise l, thinner as it fades (its mean where l fades out)
float ww_wake_foam(float fresh, float old, vec2 n, vec2 l) {
    float patch = n.x + WAKE_GROW * (fresh - 0.5);
    float f = sqrt(fresh) * smoothstep(0.5 - 0.5 * WAKE_SOFT, 0.5 + 0.5 * WAKE_SOFT, patch);
    float ridge = 1.0 - abs(2.0 * l.x - 1.0);
    float lace = old * old * smoothstep(1.0 - WAKE_LACE_WIDTH * old, 1.0, ridge);
    return max(f, mix(WAKE_LACE_MEAN * old * old, lace, l.y));
}
#endif

void main() {
#if WW_GEOM_MODE == 0
    o_color = vec4(0.0);
#else
    vec3 p = v_pos;
    vec3 v = normalize(ww_eye() - p);
    float depth = v_water_y - p.y; // below the water plane, m (negative above)

#if WW_GEOM_MODE == 3
    {
        // an air bubble: a sphere of air seen from the water, blended over what lies behind it
        // (premultiplied: rgb is light added, a the share of the background it hides). Near its
        // centre the light passes through (water to air and back: little is reflected), so the
        // seabed shows through; toward the rim the rays meet the air past the critical angle,
        // asin(1 / 1.333) = 48.6 deg, and are reflected whole (total internal reflection), so
        // the rim is a bright ring of the water's light, brighter from above; and a highlight
        // of the (refracted) sun.
        vec3 n = normalize(v_normal);
        float c = abs(dot(n, v));
        float refl = smoothstep(0.8, 0.55, c) * 0.85 + 0.04; // TIR past cos 0.66, Fresnel inside
        // a bubble a few pixels across is sampled near its middle alone: it takes the disc's
        // mean instead (about half of it is past the critical angle), so a column of small
        // bubbles reads as the bright specks it is, not as nothing
        float tiny = clamp(2.0 * length(fwidth(n)) - 0.5, 0.0, 1.0);
        refl = mix(refl, BUBBLE_DISC_MEAN, tiny);
        vec3 r = reflect(-v, n);
        vec3 l = u_sun_dir;
        vec3 sun = u_sun_color * smoothstep(-0.02, 0.02, u_sun_dir.y);
        vec3 env = ww_sky(r);
        if (depth > 0.0) {
            vec3 ts = refract(-u_sun_dir, vec3(0.0, 1.0, 0.0), 1.0 / WW_ETA_WATER);
            if (ts.y < 0.0) l = -ts;
            sun *= exp(-u_extinction * depth / max(-l.y, 0.6));
            // what the rim mirrors: the daylight coming down through the water above it,
            // the water's own colour below
            vec3 down = u_ambient * exp(-u_extinction * depth) + 0.8 * sun;
            env = mix(u_fog_below_color, down, smoothstep(-0.3, 0.6, r.y));
        }
        float hi = pow(max(dot(n, normalize(l + v)), 0.0), 300.0);
        vec3 t = ww_fog_segment(vec3(1.0), p) - ww_fog_segment(vec3(0.0), p); // transmittance
        o_color = vec4(ww_fog_segment(env, p) * refl + sun * hi * 0.5 * t, refl);
    }
#elif WW_GEOM_MODE == 5
    {
        // the boat's wake (gfx/wake.h), a ribbon lying on the water from the stem back: v_normal
        // holds the foam's strength, the time since the stern passed (s) and the odometer (m
        // along the path, fixed to the water), v_uv the place across (-1 .. 1) and the half width
        // (m), v_wake the stern's odometer, the transom's half-breadth and the time. Two foams,
        // each a coverage that noise breaks into patches as it thins, and a lace it leaves in
        // the water (as the water's crest foam, water.frag.glsl):
        // - the wash behind the transom, streaks along the path, spreading slowly;
        // - the bow wave along the hull and the wedge's arms from where it leaves the hull, a
        //   band inside the ribbon's edge, in crests along the divergent waves' (54.7 degrees
        //   to the path);
        // both fading with the time since the stern passed. Each noise fades to its mean where
        // its cells shrink under two pixels, so a far wake does not shimmer. Foam is white, lit
        // by the sky and the sun (from above: it lies flat), fogged as every surface.
        float strength = v_normal.x, age = v_normal.y, along = v_normal.z;
        float x = v_uv.x * v_uv.y, ax = abs(x), back = v_wake.x - along; // m behind the stern
        float px = max(fwidth(along), fwidth(x)) + 1e-4;                 // m a pixel
        float grow = max(back, 0.0);
        float lace_left = WAKE_LACE_FRESH * strength * exp(-age / WAKE_LACE_LIFE);
        // the lace's noise: cells of a third of a metre, the same every way
        vec2 l = ww_wake_noise(vec2(along, x) * 3.0, px * vec2(3.0));

        // the wash: from the transom, as wide as it and spreading; streaks along the path
        float wide = v_wake.y + WAKE_WASH_SPREAD * grow;
        float in_wash = smoothstep(-0.3, 0.3, back) * (1.0 - smoothstep(0.45 * wide, wide, ax));
        vec2 n = ww_wake_noise(vec2(along * 0.7, x * 4.0), px * vec2(0.7, 4.0));
        float fresh = WAKE_WASH_FRESH * strength * exp(-age / WAKE_WASH_LIFE);
        float wash = ww_wake_foam(fresh * in_wash, lace_left * in_wash, n, l);

        // the bow wave and the arms: a band inside the ribbon's edge, widening behind the
        // stern. Their crests are a steady pattern that travels with the boat (Kelvin's), so
        // their foam is drawn in the boat's frame: along the hull one breaking wave, behind the
        // stern crests slanting back at 54.7 degrees to the path about WAKE_CREST_SPACING apart
        // across themselves, made ragged by a noise stretched along them that changes over
        // WAKE_CREST_CYCLE s (two of it crossfaded, each offset anew every cycle). What breaks
        // leaves a lace in the water inside the band, which moves out as the wedge widens.
        float band = WAKE_ARM_BAND + WAKE_ARM_GROW * grow, in_edge = v_uv.y - ax;
        float in_arm = smoothstep(0.0, 0.05 + px, in_edge) *
                       (1.0 - smoothstep(0.35 * band, band + px, in_edge));
        float behind_arm = WAKE_ARM_LACE * smoothstep(0.9 * band, 1.3 * band, in_edge) *
                           (1.0 - smoothstep(1.6 * band, 2.6 * band, in_edge));
        vec2 crest = vec2(0.578 * back + 0.816 * ax, 0.816 * back - 0.578 * ax);
        vec2 q = vec2(crest.x * 1.2, crest.y * 3.0), fq = px * vec2(1.2, 3.0);
        float cyc = v_wake.z / WAKE_CREST_CYCLE, k = floor(cyc), w = cyc - k;
        vec2 m = mix(ww_wake_noise(q + vec2(17.0, 5.0) * k, fq),
                     ww_wake_noise(q + vec2(17.0, 5.0) * (k + 1.0), fq), w);
        // the blend of two noises varies less than either: its spread restored about the mean
        m.x = 0.5 + (m.x - 0.5) * inversesqrt(w * w + (1.0 - w) * (1.0 - w));
        float aa = 1.0 - smoothstep(0.25, 0.5, px / WAKE_CREST_SPACING);
        float ph = 6.2832 * (crest.y / WAKE_CREST_SPACING + 2.0 * m.x);
        float feather = mix(0.5, smoothstep(-0.5, 0.5, sin(ph)), aa);
        float hugging = mix(0.45, 1.0, smoothstep(0.3, 0.6, m.x)); // along the hull: one wave
        feather = mix(hugging, feather, smoothstep(0.0, 2.0, back));
        fresh = WAKE_ARM_FRESH * strength * exp(-age / WAKE_ARM_LIFE);
        float arm = ww_wake_foam(fresh * in_arm * feather, lace_left * behind_arm, m, l);

        float cover = min(max(wash, arm), WAKE_COVER_MAX);
        vec3 up = vec3(0.0, 1.0, 0.0);
        vec3 sun = u_sun_color * smoothstep(-0.02, 0.02, u_sun_dir.y) * max(u_sun_dir.y, 0.0);
#if !WW_SUNLESS
        sun *= ww_shadow(p, up);
#endif
        vec3 c = ww_fog_segment(v_color.rgb * (u_ambient + sun), p);
        o_color = vec4(c * cover, cover);
    }
#elif WW_GEOM_MODE == 2
    {
        // the glow column as a glowing medium: along the view ray, the
        // radiance of an emitting and absorbing slab is S (1 - e^(-tau)), tau the optical depth
        // over the ray's chord through the cylinder; bounded by S however long the chord (the
        // camera inside the column looking along it). One wall per ray counts its chord: the
        // near wall seen from outside (it passes the depth test in front of the chest inside
        // the column), the far wall from inside; the column fades toward its top.
        vec3 n = normalize(v_normal);
        vec3 dir = -v;
        vec2 o = u_eye.xz - u_glow.xy;
        float a = dot(dir.xz, dir.xz), b = dot(o, dir.xz);
        float cc = dot(o, o) - u_glow.z * u_glow.z;
        if ((cc > 0.0) != (dot(n, v) > 0.0)) discard;
        float t0 = -1e9, t1 = 1e9;
        if (a > 1e-8) {
            float disc = b * b - a * cc;
            if (disc <= 0.0) discard;
            float q = sqrt(disc);
            t0 = (-b - q) / a;
            t1 = (-b + q) / a;
        } else if (cc > 0.0) {
            discard;
        }
        if (abs(dir.y) > 1e-6) {
            float ya = (u_glow_y.x - u_eye.y) / dir.y, yb = (u_glow_y.y - u_eye.y) / dir.y;
            t0 = max(t0, min(ya, yb));
            t1 = min(t1, max(ya, yb));
        }
        t0 = max(t0, 0.0);
        // the density falls from the axis as 1 - r^2 / R^2, so the column thins out to its
        // edge instead of ending in a hard wall: the optical depth is that profile integrated
        // along the chord, r^2(t) = a t^2 + 2 b t + |o|^2 (exact; 1.5x so a diameter through
        // the axis keeps the uniform column's 2R)
        float chord = 0.0;
        if (t1 > t0) {
            float R2 = u_glow.z * u_glow.z, o2 = dot(o, o);
            float i1 = t1 - (a * t1 * t1 * t1 / 3.0 + b * t1 * t1 + o2 * t1) / R2;
            float i0 = t0 - (a * t0 * t0 * t0 / 3.0 + b * t0 * t0 + o2 * t0) / R2;
            chord = max(1.5 * (i1 - i0), 0.0);
        }
        float ym = u_eye.y + dir.y * 0.5 * (t0 + t1);
        float up = 1.0 - clamp((ym - u_glow_y.x) / (u_glow_y.y - u_glow_y.x), 0.0, 1.0);
        vec3 c = v_color.rgb * v_color.a * (1.0 - exp(-u_glow.w * chord)) * up * up;
        // additive: the fog only takes light away
        vec3 fogged = ww_fog_segment(c, p) - ww_fog_segment(vec3(0.0), p);
        o_color = vec4(max(fogged, vec3(0.0)), 1.0);
    }
#else

#if WW_GEOM_MODE == 4
    // a strand of the line or the rod: v_normal is the unit vector across the ribbon and v_uv.x
    // the place across it (-1 .. 1), so the normal turns across the ribbon as a cylinder's
    // does from one side to the other, through the one facing the eye
    float across = clamp(v_uv.x, -1.0, 1.0);
    vec3 n = normalize(normalize(v_normal) * across + v * sqrt(max(1.0 - across * across, 0.0)));
#else
    vec3 n = normalize(v_normal);
    if (dot(n, v) < 0.0 && !gl_FrontFacing) n = -n; // open meshes seen from behind
    // the reflection's cut opens what floats, and the mirror camera below it sees inside
    // (which the waves' distortion shows along the waterline): there the face it sees is the
    // cut's, looking down at the water, not the inside of a wall lit as its outside (the low sun
    // on a cube's far wall showed as a bright patch in the water at its foot). The mirror turns
    // the winding over, so a face seen from inside is the one that counts as front facing. The
    // prepass's cut opens it to the camera above, where the inside of its bottom, lit as a top,
    // showed in the refraction along the waterline: a face seen from inside there is shaded as
    // a wall facing the camera, what the lookups beside it show of the float. The hull's hollow
    // (its inner skin, faces turned into the boat) is seen through the cut too, from below in
    // the mirror, where no view over the gunwale could see it: its lit faces showed as pink
    // specks in the image along the waterline
    if (u_inside != 0 && (gl_FrontFacing == u_mirrored || v_hollow > 0.5))
        n = u_mirrored ? vec3(0.0, -1.0, 0.0) : normalize(vec3(v.x, 1e-4, v.z));
#endif
    vec3 albedo = v_color.rgb * u_mat_kd.rgb;
#if WW_MAT_MAP
    albedo *= texture(u_mat_map, v_uv).rgb;
#endif
#if WW_FISH_PATTERNS
    if (v_pattern > 0.5) albedo = ww_fish_pattern(albedo, v_mesh, v_pattern);
#endif
    // the specular colour and exponent: the material's, or the instance's strength at
    // WW_SHININESS
    bool mat_spec = u_mat_ks.a > 0.0;
    vec3 ks = mat_spec ? u_mat_ks.rgb : vec3(v_spec);
    float shininess = mat_spec ? u_mat_ks.a : WW_SHININESS;

    // sunlight, through the water column above when under water
    float sun_up = smoothstep(-0.02, 0.02, u_sun_dir.y);
    vec3 sun = u_sun_color * sun_up;
    vec3 amb = u_ambient * (0.65 + 0.35 * n.y);
    vec3 l = u_sun_dir; // toward the sun: under water, back along the refracted ray
    if (depth > 0.0) {
        vec3 t = exp(-u_extinction * depth);
        // the sunlight's path down to p follows the refracted ray (Snell): depth over its
        // cosine, never more than depth / 0.66 (the critical angle), not depth / sin(elevation)
        vec3 ts = refract(-u_sun_dir, vec3(0.0, 1.0, 0.0), 1.0 / WW_ETA_WATER);
        sun *= exp(-u_extinction * depth / max(-ts.y, 0.6));
        if (ts.y < 0.0) {
            l = -ts;
            // what crosses the surface (Schlick's transmittance, F0 0.02) spreads over a beam
            // cos(theta_i) / cos(theta_t) as wide as it was: a horizontal face below gets the
            // irradiance the surface let through, never more than a face above the water.
            // Without it a low sun, bent steeply down, lit what lies under water up to twice
            // as brightly as what lies above it.
            float ci = max(u_sun_dir.y, 0.0), m = 1.0 - ci, m2 = m * m;
            sun *= (1.0 - (0.02 + 0.98 * m2 * m2 * m)) * ci / max(-ts.y, 1e-3);
        }
        amb *= t;
#if !WW_SUNLESS && (WW_CAUSTICS == 2 || (WW_CAUSTICS && WW_WAVE_MODEL != WW_MODEL_FLAT))
        // the surface point the refracted sun ray through p left from (camera-relative xz)
        vec3 tr = refract(-u_sun_dir, vec3(0.0, 1.0, 0.0), 1.0 / WW_ETA_WATER);
        vec2 q = p.xz - tr.xz * (depth / min(tr.y, -0.05));
        float caustic = ww_caustic(q, depth);
        sun *= max(1.0 + u_caustics * (caustic - 1.0), 0.0);
#endif
    }
#if WW_SUNLESS
    vec3 c = albedo * amb;
#else
    float lit = ww_shadow(p, n);
    float ndl = max(dot(n, l), 0.0);
    vec3 h = normalize(l + v);
    vec3 spec = ndl > 0.0 ? pow(max(dot(n, h), 0.0), shininess) * ks : vec3(0.0);
    vec3 c = albedo * (amb + sun * ndl * lit) + sun * spec * lit;
#endif

#if WW_LIGHTS
    for (int i = 0; i < WW_NLIGHTS; i++) {
        vec3 l;
        float att = ww_light_att(i, p, l);
        float nl = max(dot(n, l), 0.0);
        vec3 hl = normalize(l + v);
        vec3 sl = nl > 0.0 ? pow(max(dot(n, hl), 0.0), shininess) * ks : vec3(0.0);
        c += u_light_color[i] * att * (albedo * nl + sl);
    }
#endif
    c += albedo * v_color.a + u_mat_ke.rgb; // emission: the instance's factor, the material's Ke
    c = ww_fog_segment(c, p) + ww_lights_scatter_segment(ww_eye(), p, v_water_y, u_mirrored,
                                                         u_fog_below_density, gl_FragCoord.xy);
#if WW_GEOM_MODE == 4
    // coverage (after Persson's phone-wire AA, SIGGRAPH 2012): the ribbon is at least 2 pixels
    // wide and v_uv.y is the strand's true width in pixels. Wider than 2, a solid core with a
    // pixel's ramp at each edge; thinner, a tent across the 2 pixels whose sum is that width, so
    // a line far thinner than a pixel fades with distance instead of breaking into dashes
    float w = v_uv.y;
    float cover = min(1.0, (1.0 - abs(across)) * max(0.5 * w, 1.0)) * min(w, 1.0);
    o_color = vec4(c * cover, cover);
#else
    o_color = vec4(c, u_mat_ke.a);
#endif
#endif
#endif
}
