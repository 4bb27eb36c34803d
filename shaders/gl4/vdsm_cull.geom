#version 150
// SPDX-License-Identifier: MIT
// VDSM's culling pass: the chain's steps (EP, SM, DC; vdsm_cull.glsl) decide
// each triangle in this small shader, and for one that casts transform
// feedback keeps one point per part of its volume the eye sees
// (vdsm_volume.glsl: a side face, its own face, or the whole viewport):
// its world corners, DC's clip depth (t_v0.w) and the part (t_v1.w). The
// shadow-polygon pass (vdsm_fed.geom) then draws each of those points'
// face alone, in one draw.
layout(triangles) in;
layout(points, max_vertices = 4) out;
in vec3 g_world[];
uniform int u_caps; // the draw's triangles also draw themselves (blended casters)
out vec4 t_v0;
out vec4 t_v1;
out vec4 t_v2;

// the light (vdsm_side.glsl), the chain's steps and the volume's parts
// @chunks

void main()
{
    vec3 v[3] = vec3[3](g_world[0], g_world[1], g_world[2]);
    float clip;
    if (!vdsm_casts(v, clip))
        return;
    int parts = vdsm_parts(v, u_caps != 0);
    for (int k = 0; k < 5; k++) {
        if ((parts & (1 << k)) == 0)
            continue;
        t_v0 = vec4(v[0], clip);
        t_v1 = vec4(v[1], float(1 << k));
        t_v2 = vec4(v[2], 0.0);
        EmitVertex();
        EndPrimitive();
    }
}
