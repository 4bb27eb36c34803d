#version 150
// SPDX-License-Identifier: MIT
// VDSM step SM, the light pass's second half (vdsm_light.geom has the
// first): each triangle of the draw, from its own index buffer, at the
// texel centres it covers where the stencil does not hold the draw's
// outline marks, MAX-blended (vdsm_light.frag). A triangle near edge-on in
// the light's view is left out: it bounds nothing robustly.
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in vec3 g_world[];

// the light's view (vdsm_light.glsl)
// @chunks

void main()
{
    if (!light_triangle(g_world[0], g_world[1], g_world[2]) || !robust_triangle())
        return;
    put(tri[0]);
    put(tri[1]);
    put(tri[2]);
    EndPrimitive();
}
