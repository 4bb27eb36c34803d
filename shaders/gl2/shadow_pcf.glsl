// SPDX-License-Identifier: MIT
// Shadow maps with percentage-closer filtering (technique "map-pcf").
// u_shadow_kind: 0 no map for this pass's light, 1 one map (spot or
// directional), 2 a point light's six 90-degree maps side by side in one
// atlas, 3 across and 2 up (face f in column f mod 3, row f / 3), so one
// sampler serves the six and a fragment runs one face's taps.
// Each map: world -> [0,1] texture space by u_shadow_matrix[face] (a face's
// into its cell). Bias: each tap compares the depth of the receiver's own
// plane at the tap (receiver-plane depth bias, from the screen derivatives,
// or without them from the plane of the normal: terminator_point.glsl),
// and only where the light grazes the receiver is the position pushed along
// the geometric normal, toward the side the eye sees, by up to
// u_shadow_params.z times its clip w (1.5 texels' width at the point: w is 1
// for an orthographic map, the distance along the light's axis for a
// perspective one). The kernel is (2 r + 1) x (2 r + 1) taps of the
// hardware's 2x2 compare, r = params.y, a face's taps kept half a texel
// inside its cell so none reads a neighbouring face.
// An area light (radius > 0) is shadowed by percentage-closer soft shadows
// instead: pcss_visibility below.
// Every tap is pcf_tap(at, z, texel), from the chunk spliced in before this
// one (src/shadow/map_pcf.c): pcf_tap_compare.glsl where the map compares,
// pcf_tap_depth.glsl where it is read as a number and compared here.
uniform int u_shadow_kind;
uniform mat4 u_shadow_matrix[6];
// x, w: a texel's width and height in [0,1]; y: kernel radius; z: normal offset per unit w
uniform vec4 u_shadow_params;
// per face (0 for one map), for an area light: x, the texels a tap
// spreads per unit of window depth between blocker and receiver (0: radius
// 0, the kernel below); y, the window depth per unit of 1 / distance along
// the map's axis; z, 1 / the map's projection scale (proj[0])
uniform vec3 u_shadow_soft[6];

#define PCSS_SEARCH 16
#define PCSS_DEPTH_STEPS 5
#define PCSS_FILTER 48
// blockers are searched for from the receiver up to this fraction of its
// distance from the light: the search region is the light's own size in
// the map at the receiver (a blocker half-way casts a penumbra that wide)
#define PCSS_NEAREST 0.5

// Tap i of n of a Vogel disc (uniform over the unit disc), turned by the
// pixel's angle (cs: its cosine and sine) and stretched by k_a along a: the
// light's disc facing the receiver, seen on the map's plane.
vec2 pcss_tap(int i, int n, vec2 cs, vec2 a, float k_a)
{
    float r = sqrt((float(i) + 0.5) / float(n));
    float phi = float(i) * 2.3999632;
    vec2 u = r * vec2(cos(phi), sin(phi));
    u = vec2(cs.x * u.x - cs.y * u.y, cs.y * u.x + cs.x * u.y);
    return u + a * (k_a * dot(a, u));
}

// Percentage-closer soft shadows. Window depth is affine in 1 / distance,
// so the ray from the receiver (t, at distance w along the axis) to a point
// u of the light's disc crosses window depth z at t + soft.x (t.z - z) u
// texels. A blocker search over the region that spans from the receiver to
// PCSS_NEAREST of its distance finds the blockers' mean depth (each by a
// bisection of taps: a comparing sampler cannot read), and a disc
// of taps sized by that depth averages the compares: exact for one planar
// blocker. The taps turn per pixel so the penumbra takes many levels, and
// are clamped to [lo, hi] (a face's cell) as the kernel's are. mid,
// extent: the map's (the cell's) centre and half size in [0,1].
float pcss_visibility(vec3 t, float w, vec2 dz, vec2 texel, vec2 lo, vec2 hi, vec2 mid,
                      vec2 extent, vec3 soft)
{
    // interleaved gradient noise: a stable angle per pixel
    float angle = 6.2831853 * fract(52.9829189 * fract(dot(gl_FragCoord.xy,
                                                           vec2(0.06711056, 0.00583715))));
    vec2 cs = vec2(cos(angle), sin(angle));
    // the receiver's slope from the map's axis: the disc facing it is
    // stretched by sqrt(1 + |a|^2) along a on the map's plane
    vec2 a = (t.xy - mid) / extent * soft.z;
    float a2 = dot(a, a);
    float k_a = a2 > 1e-8 ? (sqrt(1.0 + a2) - 1.0) / a2 : 0.5;
    // the window depths searched: from the receiver's up to the nearest's
    float span = soft.y * (1.0 / PCSS_NEAREST - 1.0) / w;
    float reach = soft.x * span;
    float blocked = 0.0, depth = 0.0;
    for (int i = 0; i < PCSS_SEARCH; i++) {
        vec2 at = clamp(t.xy + pcss_tap(i, PCSS_SEARCH, cs, a, k_a) * reach * texel, lo, hi);
        float ref = t.z + dot(at - t.xy, dz);
        float b = 1.0 - pcf_tap(at, ref, texel);
        if (b > 0.0) {
            float near = t.z - span, far = ref;
            for (int k = 0; k < PCSS_DEPTH_STEPS; k++) {
                float z = 0.5 * (near + far);
                if (pcf_tap(at, z, texel) > 0.5)
                    near = z;
                else
                    far = z;
            }
            blocked += b;
            depth += b * 0.5 * (near + far);
        }
    }
    if (blocked <= 0.0)
        return 1.0;
    // the penumbra's radius for the mean blocker, at least a texel
    float spread = max(soft.x * (t.z - depth / blocked), 1.0);
    float sum = 0.0;
    for (int i = 0; i < PCSS_FILTER; i++) {
        vec2 at = clamp(t.xy + pcss_tap(i, PCSS_FILTER, cs, a, k_a) * spread * texel, lo, hi);
        sum += pcf_tap(at, t.z + dot(at - t.xy, dz), texel);
    }
    return sum / float(PCSS_FILTER);
}

// The filtered visibility of light i (1 lit): maps carry no colour.
float pcf_visibility(int i)
{
    if (u_shadow_kind == 0)
        return 1.0; // a shadowed pass lights one light, so i is always that one
    vec3 wx, wy, ng = geometric_normal();
    receiver_span(ng, wx, wy);
    vec4 light = u_lights[4 * i];
    vec2 texel = u_shadow_params.xw;
    // one map: no clamp of our own (its edge clamp is the same)
    vec2 lo = vec2(-1.0), hi = vec2(2.0);
    vec2 mid = vec2(0.5), extent = vec2(0.5);
    int face = 0;
    if (u_shadow_kind == 2) {
        // the face is the major axis of the direction from the light
        vec3 d = v_world - light.xyz;
        vec3 a = abs(d);
        if (a.x >= a.y && a.x >= a.z) face = d.x > 0.0 ? 0 : 1;
        else if (a.y >= a.z) face = d.y > 0.0 ? 2 : 3;
        else face = d.z > 0.0 ? 4 : 5;
        // its cell, less half a texel each side: the hardware's 2x2 compare
        // at a texel's centre gives the texel beyond no weight
        float row = face >= 3 ? 1.0 : 0.0;
        vec2 cell = vec2(1.0 / 3.0, 0.5);
        lo = vec2(float(face) - 3.0 * row, row) * cell + 0.5 * texel;
        hi = lo + cell - texel;
        extent = 0.5 * cell;
        mid = lo - 0.5 * texel + extent;
    }
    // the side the eye sees; turned away from the light by its facet and its
    // shading normal, it is in its own shadow (no offset point past a thin
    // caster may say otherwise)
    if (dot(ng, u_eye - v_world) < 0.0)
        ng = -ng;
    vec3 shading;
    vec3 world = terminator_point(ng, shading);
    vec3 to_light = normalize(light.w == 0.0 ? light.xyz : light.xyz - world);
    float cos_l = dot(ng, to_light);
    if (cos_l <= 0.0 && dot(shading, to_light) <= 0.0)
        return 0.0;
    vec4 c = u_shadow_matrix[face] * vec4(world, 1.0);
    if (c.w <= 0.0)
        return 0.0;
    // the normal offset: u_shadow_params.z texels' width where this point
    // is (a perspective map's texels grow with the distance from the light,
    // w), only where the light grazes the receiver (cos under 0.3, all of it
    // under 0.1). Elsewhere the receiver plane below keeps each tap off the
    // surface, and a push would only move the shadow: along the normal of a
    // fin's side it carries the lookup point sideways out from under the
    // next fin's edge (and toward a light head-on, through a thin gap)
    float push = (1.0 - smoothstep(0.1, 0.3, cos_l)) * u_shadow_params.z * c.w;
    vec3 p = world + ng * push;
    c = u_shadow_matrix[face] * vec4(p, 1.0);
    if (c.w <= 0.0)
        return 0.0;
    vec3 t = c.xyz / c.w;
    // receiver plane: the map depth's change per unit of u and v across
    // this point's plane, from its screen derivatives projected into the
    // map, so each tap of the kernel compares the plane's own depth there
    // and a wide kernel does not shadow a sloped receiver with itself
    vec4 ex = u_shadow_matrix[face] * vec4(wx, 0.0);
    vec4 ey = u_shadow_matrix[face] * vec4(wy, 0.0);
    vec3 tx = (ex.xyz - t * ex.w) / c.w, ty = (ey.xyz - t * ey.w) / c.w;
    float det = tx.x * ty.y - tx.y * ty.x;
    vec2 dz = abs(det) > 1e-12 ? vec2(tx.z * ty.y - ty.z * tx.y, tx.x * ty.z - ty.x * tx.z) / det
                               : vec2(0.0);
    if (u_shadow_soft[face].x > 0.0)
        return pcss_visibility(t, c.w, dz, texel, lo, hi, mid, extent, u_shadow_soft[face]);
    // the loop runs only the kernel's taps (a uniform bound: no wasted taps)
    int r = int(u_shadow_params.y + 0.5);
    float sum = 0.0, n = 0.0;
    for (int y = -r; y <= r; y++)
        for (int x = -r; x <= r; x++) {
            vec2 at = clamp(t.xy + vec2(float(x), float(y)) * texel, lo, hi);
            sum += pcf_tap(at, t.z + dot(at - t.xy, dz), texel);
            n += 1.0;
        }
    return sum / n;
}

// The seam every shadow chunk defines: grey for an opaque caster's map.
vec3 shadow_transmittance(int light)
{
    return vec3(pcf_visibility(light));
}
