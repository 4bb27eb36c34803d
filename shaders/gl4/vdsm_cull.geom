#version 150
// SPDX-License-Identifier: MIT
// VDSM's culling pass: the chain's steps (EP, SM, DC; vdsm_cull.glsl) decide
// each triangle in this small shader, and transform feedback keeps one point
// per triangle that casts: its world corners, DC's clip depth (t_v0.w) and
// whether it draws its own face (t_v1.w). The shadow-polygon pass
// (vdsm_fed.geom) then runs its large body on those alone, in one draw.
layout(triangles) in;
layout(points, max_vertices = 1) out;
in vec3 g_world[];
uniform int u_caps; // the draw's triangles also draw themselves (blended casters)
out vec4 t_v0;
out vec4 t_v1;
out vec4 t_v2;

// the light (vdsm_side.glsl) and the chain's steps
// @chunks

void main()
{
    vec3 v[3] = vec3[3](g_world[0], g_world[1], g_world[2]);
    float clip;
    if (!vdsm_casts(v, clip))
        return;
    t_v0 = vec4(v[0], clip);
    t_v1 = vec4(v[1], float(u_caps));
    t_v2 = vec4(v[2], 0.0);
    EmitVertex();
    EndPrimitive();
}
