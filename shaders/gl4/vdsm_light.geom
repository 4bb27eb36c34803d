#version 150
// SPDX-License-Identifier: MIT
// VDSM step SM, the light pass: the occluder half of the light-view pyramid
// (src/shadow_vdsm_pyramid.c). Drawn as GL_TRIANGLES_ADJACENCY so each
// triangle knows the far vertex of its neighbour across every edge; each
// draw twice:
// - u_marks 1: every edge of the draw's outline, grown past the texels it
//   touches, into the stencil (the draw's id): an edge is inside the draw's
//   union only where a neighbour lies on its other side in the light's view;
// - u_marks 0: the triangles themselves at the texel centres they cover, where
//   the stencil does not hold the draw's id, MAX-blended: x = -(an upper bound
//   of the light depth there, vdsm_light.frag).
// A texel the draw's outline does not touch and whose centre one of its
// triangles covers lies wholly inside the draw's union, so every ray through
// it meets one of the draw's triangles no deeper than the bound.
// The triangles are the ones the shadow polygons draw: with EP, those that do
// not face the light (the same test as vdsm.geom).
layout(triangles_adjacency) in;
layout(triangle_strip, max_vertices = 15) out;
in vec3 g_world[];
uniform mat4 u_light_vp;  // world -> the light's clip space
uniform vec4 u_depth_row; // world -> light depth (linear, grows away from the light)
uniform vec4 u_light;     // world: position (w 1), or the direction toward the light (w 0)
uniform int u_cull_lit;   // EP: triangles facing the light are not drawn, so not here
uniform float u_size;     // texels a side of level 0
uniform float u_grow;     // texels a mark reaches past an edge, beyond the half texel
uniform int u_marks;      // 1: the outline's marks, 0: the triangles
flat out vec2 f_t0;
flat out vec2 f_t1;
flat out vec2 f_t2;
flat out vec3 f_depth;

vec2 tri[3];
vec3 depth;

vec2 texel_of(vec3 w)
{
    vec4 c = u_light_vp * vec4(w, 1.0);
    return (c.xy / c.w * 0.5 + 0.5) * u_size;
}

// Outputs are undefined after each vertex: all of them again every time.
void put(vec2 t)
{
    f_t0 = tri[0];
    f_t1 = tri[1];
    f_t2 = tri[2];
    f_depth = depth;
    gl_Position = vec4(t / u_size * 2.0 - 1.0, 0.0, 1.0);
    EmitVertex();
}

float orient(vec2 a, vec2 b, vec2 c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

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
    vec3 v0 = g_world[0], v1 = g_world[2], v2 = g_world[4];
    vec3 nc = cross(v1 - v0, v2 - v0);
    float lit = dot(nc, u_light.xyz) - dot(nc, v0) * u_light.w;
    if (lit == 0.0 || dot(nc, nc) == 0.0)
        return;                 // vdsm.geom draws nothing for it
    if (u_cull_lit != 0 && lit > 0.0)
        return;                 // dropped by EP there
    vec2 t[3] = vec2[3](texel_of(v0), texel_of(v1), texel_of(v2));
    tri = t;
    depth = vec3(dot(u_depth_row, vec4(v0, 1.0)), dot(u_depth_row, vec4(v1, 1.0)),
                 dot(u_depth_row, vec4(v2, 1.0)));
    vec2 o[3] = vec2[3](texel_of(g_world[1]), texel_of(g_world[3]), texel_of(g_world[5]));
    float r = (0.5 + u_grow) * 1.41421356;
    float area = orient(t[0], t[1], t[2]);
    // Near edge-on in the light's view: its side of an edge is not robust.
    float span = max(max(distance(t[0], t[1]), distance(t[1], t[2])), distance(t[2], t[0]));
    bool robust = abs(area) > 1e-4 * span * span;
    for (int e = 0; e < 3 && u_marks != 0; e++) {
        vec2 a = t[e], b = t[e < 2 ? e + 1 : 0], c = t[e < 1 ? e + 2 : e - 1];
        float mine = orient(a, b, c), theirs = orient(a, b, o[e]);
        float len = distance(a, b);
        bool inside = robust && mine * theirs < 0.0 &&
                      abs(theirs) > 1e-4 * len * distance(a, o[e]);
        if (!inside)
            mark(a, b, r);
    }
    if (u_marks != 0 || !robust)
        return;
    put(t[0]);
    put(t[1]);
    put(t[2]);
    EndPrimitive();
}
