// SPDX-License-Identifier: MIT
// Shadow maps with percentage-closer filtering (technique "map-pcf").
// u_shadow_kind: 0 no map for this pass's light, 1 one map (spot or
// directional), 2 a point light's six 90-degree maps side by side in one
// atlas, 3 across and 2 up (face f in column f mod 3, row f / 3), so one
// sampler serves the six and a fragment runs one face's taps.
// Each map: world -> [0,1] texture space by u_shadow_matrix[face] (a face's
// into its cell); the position is pushed along the geometric normal, toward
// the side the eye sees, by u_shadow_params.z times its clip w (1.5 texels'
// width at the point: w is 1 for an orthographic map, the distance along the
// light's axis for a perspective one) before the lookup (normal-offset
// bias); the kernel is (2 r + 1) x (2 r + 1) taps of the hardware's 2x2
// compare, r = params.y, a face's taps kept half a texel inside its cell so
// none reads a neighbouring face.
uniform int u_shadow_kind;
uniform mat4 u_shadow_matrix[6];
// x, w: a texel's width and height in [0,1]; y: kernel radius; z: normal offset per unit w
uniform vec4 u_shadow_params;
uniform sampler2DShadow u_shadow_map;

// The filtered visibility of light i (1 lit): maps carry no colour.
float pcf_visibility(int i)
{
    if (u_shadow_kind == 0)
        return 1.0; // a shadowed pass lights one light, so i is always that one
    vec3 ng = normalize(cross(dFdx(v_world), dFdy(v_world)));
    vec4 light = u_lights[4 * i];
    vec2 texel = u_shadow_params.xw;
    // one map: no clamp of our own (its edge clamp is the same)
    vec2 lo = vec2(-1.0), hi = vec2(2.0);
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
    }
    // the side the eye sees; turned away from the light, it is in its own
    // shadow (no offset point past a thin caster may say otherwise)
    if (dot(ng, u_eye - v_world) < 0.0)
        ng = -ng;
    if (dot(ng, light.w == 0.0 ? light.xyz : light.xyz - v_world) <= 0.0)
        return 0.0;
    // the offset is u_shadow_params.z texels' width where this point is: a
    // perspective map's texels grow with the distance from the light (w)
    vec4 c = u_shadow_matrix[face] * vec4(v_world, 1.0);
    if (c.w <= 0.0)
        return 0.0;
    c = u_shadow_matrix[face] * vec4(v_world + ng * (u_shadow_params.z * c.w), 1.0);
    if (c.w <= 0.0)
        return 0.0;
    vec3 t = c.xyz / c.w;
    // the loop runs only the kernel's taps (a uniform bound: no wasted taps)
    int r = int(u_shadow_params.y + 0.5);
    float sum = 0.0, n = 0.0;
    for (int y = -r; y <= r; y++)
        for (int x = -r; x <= r; x++) {
            vec2 at = clamp(t.xy + vec2(float(x), float(y)) * texel, lo, hi);
            sum += shadow2D(u_shadow_map, vec3(at, t.z)).r;
            n += 1.0;
        }
    return sum / n;
}

// The seam every shadow chunk defines: grey for an opaque caster's map.
vec3 shadow_transmittance(int light)
{
    return vec3(pcf_visibility(light));
}
