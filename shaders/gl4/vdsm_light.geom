#version 150
// SPDX-License-Identifier: MIT
// VDSM step SM, the light pass: the occluder half of the light-view pyramid
// (src/shadow/vdsm_pyramid.c). Each draw twice:
// - here, drawn as GL_TRIANGLES_ADJACENCY so each triangle knows the far
//   vertex of its neighbour across every edge: every edge of the draw's
//   outline, grown past the texels it touches, into the stencil (the draw's
//   id): an edge is inside the draw's union only where a neighbour lies on
//   its other side in the light's view;
// - then vdsm_light_tris.geom: the triangles themselves at the texel
//   centres they cover, where the stencil does not hold the draw's id,
//   MAX-blended: x = -(an upper bound of the light depth there,
//   vdsm_light.frag).
// A texel the draw's outline does not touch and whose centre one of its
// triangles covers lies wholly inside the draw's union, so every ray through
// it meets one of the draw's triangles no deeper than the bound.
// The triangles are the ones the shadow polygons draw: with EP, those that do
// not face the light (the same test as vdsm_cull.glsl).
layout(triangles_adjacency) in;
layout(triangle_strip, max_vertices = 12) out;
in vec3 g_world[];

// the light's view (vdsm_light.glsl)
// @chunks

// A rectangle around segment ab reaching r past it every way (it holds the
// segment grown by the square of half side r / sqrt 2).
void mark(vec2 a, vec2 b, float r)
{
    vec2 d = b - a;
    float len = length(d);
    vec2 u = len > 0.0 ? d / len : vec2(1.0, 0.0);
    vec2 n = vec2(-u.y, u.x);
    put(a - u * r - n * r);
    put(a - u * r + n * r);
    put(b + u * r - n * r);
    put(b + u * r + n * r);
    EndPrimitive();
}

void main()
{
    if (!light_triangle(g_world[0], g_world[2], g_world[4]))
        return;
    vec2 t[3] = tri;
    vec2 o[3] = vec2[3](texel_of(g_world[1]), texel_of(g_world[3]), texel_of(g_world[5]));
    float r = (0.5 + u_grow) * 1.41421356;
    // Near edge-on in the light's view: its side of an edge is not robust.
    bool robust = robust_triangle();
    for (int e = 0; e < 3; e++) {
        vec2 a = t[e], b = t[e < 2 ? e + 1 : 0], c = t[e < 1 ? e + 2 : e - 1];
        float mine = orient(a, b, c), theirs = orient(a, b, o[e]);
        float len = distance(a, b);
        bool inside = robust && mine * theirs < 0.0 &&
                      abs(theirs) > 1e-4 * len * distance(a, o[e]);
        if (!inside)
            mark(a, b, r);
    }
}
