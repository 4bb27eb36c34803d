// SPDX-License-Identifier: MIT
// The lit and flat programs' first chunk, before the shadow technique's and
// the translucent ones': where a per-pixel shadow lookup starts (map-pcf,
// deep, coloured), from lit.vert's v_plane_* varyings.

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
