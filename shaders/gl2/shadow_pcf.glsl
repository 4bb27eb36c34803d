// SPDX-License-Identifier: MIT
// Shadow maps with percentage-closer filtering (technique "map-pcf").
// u_shadow_kind: 0 no map for this pass's light, 1 one map (spot or
// directional), 2 a point light's six 90-degree maps side by side in one
// atlas, 3 across and 2 up (face f in column f mod 3, row f / 3), so one
// sampler serves the six and a fragment runs one face's taps.
// Each map: world -> [0,1] texture space by u_shadow_matrix[face] (a face's
// into its cell). Bias: each tap compares the depth of the receiver's own
// plane at the tap (receiver-plane depth bias, from the screen derivatives),
// and only where the light grazes the receiver is the position pushed along
// the geometric normal, toward the side the eye sees, by up to
// u_shadow_params.z times its clip w (1.5 texels' width at the point: w is 1
// for an orthographic map, the distance along the light's axis for a
// perspective one). The kernel is (2 r + 1) x (2 r + 1) taps of the
// hardware's 2x2 compare, r = params.y, a face's taps kept half a texel
// inside its cell so none reads a neighbouring face.
uniform int u_shadow_kind;
uniform mat4 u_shadow_matrix[6];
// x, w: a texel's width and height in [0,1]; y: kernel radius; z: normal offset per unit w
uniform vec4 u_shadow_params;
uniform sampler2DShadow u_shadow_map;

// The terminator rule (the test reference's and vdsm's; Hanika, "Hacking
// the Shadow Terminator", 2021). On a triangle whose vertex normals bend away
// from its facet ng (eye side), the lookup starts from the point on the
// surface those normals describe: P projected onto each corner's tangent
// plane, blended by the barycentrics, sum b_i ((c_i - P).n_i) n_i =
// sum b_i (c_i.n_i) n_i - (sum b_i n_i n_i^T) P, both sums interpolated
// exactly from per-corner values (lit.vert), kept where it lies above the
// facet. `facing` gets the shading normal turned to ng's side (ng where the
// triangle is flat: every corner's normal its facet's, or none).
vec3 terminator_point(vec3 ng, out vec3 facing)
{
    mat3 nn = mat3(v_plane_nn.x, v_plane_nx.x, v_plane_nx.y,
                   v_plane_nx.x, v_plane_nn.y, v_plane_nx.z,
                   v_plane_nx.y, v_plane_nx.z, v_plane_nn.z);
    facing = ng;
    if (v_plane_nn.x + v_plane_nn.y + v_plane_nn.z < 0.5 || dot(ng, nn * ng) >= 1.0 - 1e-6)
        return v_world;
    vec3 s = normalize(v_normal);
    facing = dot(s, ng) < 0.0 ? -s : s;
    vec3 lift = v_plane_dn - nn * v_world;
    return dot(lift, ng) > 0.0 ? v_world + lift : v_world;
}

// The filtered visibility of light i (1 lit): maps carry no colour.
float pcf_visibility(int i)
{
    if (u_shadow_kind == 0)
        return 1.0; // a shadowed pass lights one light, so i is always that one
    vec3 wx = dFdx(v_world), wy = dFdy(v_world);
    vec3 ng = normalize(cross(wx, wy));
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
    // the loop runs only the kernel's taps (a uniform bound: no wasted taps)
    int r = int(u_shadow_params.y + 0.5);
    float sum = 0.0, n = 0.0;
    for (int y = -r; y <= r; y++)
        for (int x = -r; x <= r; x++) {
            vec2 at = clamp(t.xy + vec2(float(x), float(y)) * texel, lo, hi);
            sum += shadow2D(u_shadow_map, vec3(at, t.z + dot(at - t.xy, dz))).r;
            n += 1.0;
        }
    return sum / n;
}

// The seam every shadow chunk defines: grey for an opaque caster's map.
vec3 shadow_transmittance(int light)
{
    return vec3(pcf_visibility(light));
}
