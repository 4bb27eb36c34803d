// SPDX-License-Identifier: MIT
// The lit and flat programs' first chunk, before the shadow technique's and
// the translucent ones': where a per-pixel shadow lookup starts (map-pcf,
// deep, coloured), from lit.vert's v_plane_* varyings.

// The facet's unit normal (either side): from the screen derivatives, or
// without them (STIN_NO_DERIVATIVES) the interpolated vertex normal, which
// is the facet's own where the corners carry their facet's normal (a
// flat-shaded, unwelded mesh) and the curved surface's elsewhere: the rule
// below then sees no facet turned from the light that the shading normal
// faces (its lookup point is still lifted onto the curved surface).
vec3 geometric_normal()
{
#ifdef STIN_NO_DERIVATIVES
    return dot(v_normal, v_normal) > 1e-20 ? normalize(v_normal) : vec3(0.0, 0.0, 1.0);
#else
    return normalize(cross(dFdx(v_world), dFdy(v_world)));
#endif
}

// Two world vectors that span the receiver's plane at v_world: its screen
// derivatives, or without them two perpendiculars of its normal ng (a
// receiver-plane bias only needs the plane, not the pixel's footprint).
void receiver_span(vec3 ng, out vec3 wx, out vec3 wy)
{
#ifdef STIN_NO_DERIVATIVES
    wx = normalize(cross(ng, abs(ng.x) > 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0)));
    wy = cross(ng, wx);
#else
    wx = dFdx(v_world);
    wy = dFdy(v_world);
#endif
}

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
