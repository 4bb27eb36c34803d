// SPDX-License-Identifier: MIT
// The map test of the casters an exact technique cannot cast (CSG products,
// displaced draws; shadow/cast_map.c), at v_world: map-pcf's test
// (shadow_pcf.glsl). The map atlas holds 3 x 2 cells, a spot or directional
// light's map in cell 0 (u_cast_faces 1) or a point light's six faces (6;
// face f in column f mod 3, row f / 3, picked by the major axis from the
// light); a (2r+1)^2 kernel of the hardware's 2x2 compare, kept half a
// texel inside the cell, each tap against the receiver's own plane there
// (receiver-plane bias from the screen derivatives of v_world). The tap,
// pcf_tap(at, z, texel), and the map's sampler u_shadow_map come before this
// chunk, as map-pcf's: the sampler's compare (pcf_tap_compare.glsl), or the
// shader's where depth textures cannot compare (pcf_tap_depth.glsl: OpenGL
// ES 2.0 with OES_depth_texture).
uniform mat4 u_cast_matrix[6]; // world -> [0,1] atlas space, per cell
uniform vec4 u_cast_params;    // x, w: a texel's width and height in [0,1]; y: kernel radius
uniform vec3 u_cast_light;     // a point light's position
uniform int u_cast_faces;

float cast_visibility()
{
    vec2 texel = u_cast_params.xw;
    int face = 0;
    if (u_cast_faces == 6) {
        vec3 d = v_world - u_cast_light;
        vec3 a = abs(d);
        if (a.x >= a.y && a.x >= a.z) face = d.x > 0.0 ? 0 : 1;
        else if (a.y >= a.z) face = d.y > 0.0 ? 2 : 3;
        else face = d.z > 0.0 ? 4 : 5;
    }
    float row = face >= 3 ? 1.0 : 0.0;
    vec2 cell = vec2(1.0 / 3.0, 0.5);
    vec2 lo = vec2(float(face) - 3.0 * row, row) * cell + 0.5 * texel;
    vec2 hi = lo + cell - texel;
    mat4 m = u_cast_matrix[face];
    vec4 c = m * vec4(v_world, 1.0);
    if (c.w <= 0.0)
        return 1.0; // behind the light's camera: nothing of the map is there
    vec3 t = c.xyz / c.w;
    if (u_cast_faces == 1 && (any(lessThan(t.xy, lo)) || any(greaterThan(t.xy, hi))))
        return 1.0; // outside a spot or directional map: no product casts there
#ifdef STIN_NO_DERIVATIVES
    // no derivatives and no normal here: every tap compares the point's own
    // depth, the map's slope-scaled polygon offset the only bias
    vec2 dz = vec2(0.0);
#else
    vec4 ex = m * vec4(dFdx(v_world), 0.0);
    vec4 ey = m * vec4(dFdy(v_world), 0.0);
    vec3 tx = (ex.xyz - t * ex.w) / c.w, ty = (ey.xyz - t * ey.w) / c.w;
    float det = tx.x * ty.y - tx.y * ty.x;
    vec2 dz = abs(det) > 1e-12 ? vec2(tx.z * ty.y - ty.z * tx.y, tx.x * ty.z - ty.x * tx.z) / det
                               : vec2(0.0);
#endif
    int r = int(u_cast_params.y + 0.5);
    float sum = 0.0, n = 0.0;
    for (int y = -r; y <= r; y++)
        for (int x = -r; x <= r; x++) {
            vec2 at = clamp(t.xy + vec2(float(x), float(y)) * texel, lo, hi);
            sum += pcf_tap(at, t.z + dot(at - t.xy, dz), texel);
            n += 1.0;
        }
    return sum / n;
}
