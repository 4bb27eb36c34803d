#version 150
// SPDX-License-Identifier: MIT
// VDSM for an area light (a ball of radius u_radius round u_light), per
// triangle: one screen rectangle that holds every pixel whose segments
// to the ball may meet the triangle, for vdsm_soft.frag to test. Those
// points are x = v + s (v - q), v in the triangle, q in the ball, and x a
// receiver inside the draws' bounds [u_lo, u_hi]. q lies in the cube round
// the ball (corners c_j), so x is a convex sum of v_i + s (v_i - c_j);
// along the direction a from the centre to the triangle every vertex leads
// the cube by at least `lead`, so s lead <= (x - v).a <= the bounds' reach
// along a less the nearest vertex's: the rectangle bounds the 27 points
// v_i and v_i + s_max (v_i - c_j) on the screen, a pixel wider each side
// against rounding, at the points' nearest depth: the pass tests it
// against the visible surface's (LEQUAL, clamped), so a pixel whose
// surface lies before all of them is not shaded. Where a point lies behind
// the eye (or a vertex does not lead the cube) it is the whole viewport, at
// the near plane.
layout(triangles) in;
layout(triangle_strip, max_vertices = 4) out;
in vec3 g_world[];
uniform mat4 u_view_proj;
uniform vec4 u_light;     // the ball's centre (w 1)
uniform float u_radius;
uniform vec3 u_lo;        // the draws' world bounds: every receiver lies inside
uniform vec3 u_hi;
uniform vec4 u_viewport;  // x, y, width, height in pixels
uniform int u_cull_lit;   // a closed mesh: a triangle facing all of the ball casts nothing
flat out vec3 f_v0;
flat out vec3 f_v1;
flat out vec3 f_v2;

// A pixel position's vertex at normalised depth z, with the triangle for
// the fragment stage.
void put(vec3 v[3], vec2 px, float z)
{
    f_v0 = v[0];
    f_v1 = v[1];
    f_v2 = v[2];
    gl_Position = vec4(px / u_viewport.zw * 2.0 - 1.0, z, 1.0);
    EmitVertex();
}

void main()
{
    vec3 v[3] = vec3[3](g_world[0], g_world[1], g_world[2]);
    vec3 l = u_light.xyz;
    vec3 n = cross(v[1] - v[0], v[2] - v[0]);
    float len = length(n);
    if (len == 0.0)
        return; // no area: it blocks no segment
    // its back faces the eye sees cast the closed mesh's shadow from every
    // point of the ball that sees them
    if (u_cull_lit != 0 && dot(n, l - v[0]) > u_radius * len)
        return;
    vec3 a = normalize(v[0] + v[1] + v[2] - 3.0 * l);
    float cube = u_radius * (abs(a.x) + abs(a.y) + abs(a.z)); // the cube's reach along a
    float lead = 3.4e38, nearest = 3.4e38;
    for (int i = 0; i < 3; i++) {
        lead = min(lead, dot(v[i] - l, a) - cube);
        nearest = min(nearest, dot(v[i], a));
    }
    vec3 bounds = max(u_lo * a, u_hi * a); // the bounds' reach along a, per axis
    if (lead > 0.0) {
        float s = max(bounds.x + bounds.y + bounds.z - nearest, 0.0) / lead;
        vec2 lo = vec2(3.4e38), hi = vec2(-3.4e38);
        float z = 1.0;
        bool behind = false;
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 9; j++) {
                // j 0: the vertex; 1-8: its extrusions away from the cube's corners
                int k = j - 1;
                vec3 c = l + u_radius * (2.0 * vec3(k & 1, (k >> 1) & 1, (k >> 2) & 1) - 1.0);
                vec4 h = u_view_proj * vec4(j == 0 ? v[i] : v[i] + s * (v[i] - c), 1.0);
                behind = behind || h.w <= 0.0;
                vec2 px = (h.xy / h.w * 0.5 + 0.5) * u_viewport.zw;
                lo = min(lo, px);
                hi = max(hi, px);
                z = min(z, h.z / h.w);
            }
        if (!behind) {
            // a pixel beyond each side against rounding, inside the viewport
            lo = max(lo - 1.0, vec2(0.0));
            hi = min(hi + 1.0, u_viewport.zw);
            if (lo.x < hi.x && lo.y < hi.y) {
                put(v, lo, z);
                put(v, vec2(hi.x, lo.y), z);
                put(v, vec2(lo.x, hi.y), z);
                put(v, hi, z);
                EndPrimitive();
            }
            return;
        }
    }
    put(v, vec2(0.0), -1.0);
    put(v, vec2(u_viewport.z, 0.0), -1.0);
    put(v, vec2(0.0, u_viewport.w), -1.0);
    put(v, u_viewport.zw, -1.0);
    EndPrimitive();
}
