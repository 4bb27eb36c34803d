#version 120
// SPDX-License-Identifier: MIT
// Per-pixel lighting, vertex stage: world-space position, normal and uv.
// Invariant: the depth of a volume cap must equal, bit for bit, the depth the
// lit passes wrote for the surface it lies on (z-fail counts it behind).
invariant gl_Position;
uniform mat4 u_model;
uniform mat4 u_view_proj;
uniform mat3 u_normal_matrix;
// 1: the draw's vertex normals describe its surface (the terminator rule of
// the map-pcf chunk), 0: it keeps its facets (displaced, or not set)
uniform float u_terminator;
attribute vec4 a_position;
attribute vec3 a_normal;
attribute vec2 a_uv;
attribute vec4 a_tangent;
varying vec3 v_world;
varying vec3 v_normal;
// each corner's tangent plane, interpolated exactly for the terminator rule
// (shadow_pcf.glsl): (c.n) n, and n n^T's diagonal and off-diagonal (xy xz yz)
varying vec3 v_plane_dn;
varying vec3 v_plane_nn;
varying vec3 v_plane_nx;
varying vec2 v_uv;
varying vec4 v_tangent;

// the displacement chunk (displace.glsl or displace_none.glsl)
// @chunks

void main()
{
    // w comes from the vertex fetch (1.0), exactly as in volume.vert, so that
    // volume caps and the surfaces they coincide with rasterise to equal depths.
    vec4 world = displace_world(u_model * a_position, a_normal, a_uv);
    v_world = world.xyz;
    v_normal = u_normal_matrix * a_normal;
    float len = length(v_normal);
    vec3 n = len > 0.0 ? v_normal * (u_terminator / len) : vec3(0.0);
    v_plane_dn = dot(world.xyz, n) * n;
    v_plane_nn = n * n;
    v_plane_nx = vec3(n.x * n.y, n.x * n.z, n.y * n.z);
    v_uv = a_uv;
    // tangents follow the surface (the model matrix), normals its inverse transpose
    v_tangent = vec4(mat3(u_model[0].xyz, u_model[1].xyz, u_model[2].xyz) * a_tangent.xyz,
                     a_tangent.w);
    gl_Position = u_view_proj * world;
}
