// SPDX-License-Identifier: MIT
// VDSM step SM, the light pass (vdsm_light.geom, vdsm_light_tris.geom):
// what both halves share - the light's view, the fragment stage's inputs
// and the triangle as that view sees it.
uniform mat4 u_light_vp;  // world -> the light's clip space
uniform vec4 u_depth_row; // world -> light depth (linear, grows away from the light)
uniform vec4 u_light;     // world: position (w 1), or the direction toward the light (w 0)
uniform int u_cull_lit;   // EP: triangles facing the light are not drawn, so not here
uniform float u_size;     // texels a side of level 0
uniform float u_grow;     // texels a mark reaches past an edge, beyond the half texel
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

float orient(vec2 a, vec2 b, vec2 c)
{
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}


// Triangle v0 v1 v2 in the light's view (tri, depth); false where it casts
// nothing: no area, edge-on to the light (vdsm.geom draws nothing for it),
// or facing the light under EP (dropped there).
bool light_triangle(vec3 v0, vec3 v1, vec3 v2)
{
    vec3 nc = cross(v1 - v0, v2 - v0);
    float lit = dot(nc, u_light.xyz) - dot(nc, v0) * u_light.w;
    if (lit == 0.0 || dot(nc, nc) == 0.0)
        return false;
    if (u_cull_lit != 0 && lit > 0.0)
        return false;
    tri = vec2[3](texel_of(v0), texel_of(v1), texel_of(v2));
    depth = vec3(dot(u_depth_row, vec4(v0, 1.0)), dot(u_depth_row, vec4(v1, 1.0)),
                 dot(u_depth_row, vec4(v2, 1.0)));
    return true;
}

// Whether the triangle is far enough from edge-on in the light's view for
// its side of an edge to be robust.
bool robust_triangle()
{
    float area = orient(tri[0], tri[1], tri[2]);
    float span = max(max(distance(tri[0], tri[1]), distance(tri[1], tri[2])),
                     distance(tri[2], tri[0]));
    return abs(area) > 1e-4 * span * span;
}
