#version 150
// SPDX-License-Identifier: MIT
// Shadow-volume vertices: homogeneous object space, w = 0 at infinity. The
// transform is written exactly as in lit.vert so coincident caps get equal depths.
// Invariant: the depth of a volume cap must equal, bit for bit, the depth the
// lit passes wrote for the surface it lies on (z-fail counts it behind).
invariant gl_Position;
uniform mat4 u_model;
uniform mat4 u_view_proj;
out vec3 g_object; // for volume_extrude.geom (the GPU's own extrusion)

// the attributes (vertex_attributes.glsl, or tess_eval.glsl for a
// tessellation evaluation stage) and the displacement chunk (gl2's
// displace.glsl or displace_none.glsl)
#define texture2DLod textureLod
// @chunks

void main()
{
    vec4 world = displace_world(u_model * a_position, a_normal, a_uv);
    gl_Position = u_view_proj * world;
    g_object = a_position.xyz;
}
