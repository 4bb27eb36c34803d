#version 150
// SPDX-License-Identifier: MIT
// VDSM step SM, the light pass's fragments (vdsm_light.geom), MAX-blended:
// x = -(light depth bound), y = -BIG (no receiver). The bound is the draw's
// deepest point, or, where this triangle alone covers the whole texel (grown
// by u_grow), its own deepest point over the texel. Marks write only the
// stencil.
uniform float u_bound;    // the draw's deepest light depth (its bounds' corners)
uniform float u_grow;     // texels the texel is grown by against rounding
uniform int u_perspective; // 1: 1/depth is affine across the map (spot, point), 0: depth is
flat in vec2 f_t0;
flat in vec2 f_t1;
flat in vec2 f_t2;
flat in vec3 f_depth;
out vec4 frag_color;

const float BIG = 1e30;

// The gradient of orient(a, b, p) in p.
vec2 edge_gradient(vec2 a, vec2 b) { return vec2(a.y - b.y, b.x - a.x); }

void main()
{
    vec2 c = gl_FragCoord.xy;
    float h = 0.5 + u_grow;
    vec2 g0 = edge_gradient(f_t1, f_t2), g1 = edge_gradient(f_t2, f_t0),
         g2 = edge_gradient(f_t0, f_t1);
    float area = dot(g2, f_t2 - f_t0);
    float s = area > 0.0 ? 1.0 : -1.0;
    // orient(edge, c) with the triangle on its positive side, less its fall
    // over the square of half side h
    float e0 = s * dot(g0, c - f_t1) - h * (abs(g0.x) + abs(g0.y));
    float e1 = s * dot(g1, c - f_t2) - h * (abs(g1.x) + abs(g1.y));
    float e2 = s * dot(g2, c - f_t0) - h * (abs(g2.x) + abs(g2.y));
    float bound = u_bound;
    if (e0 >= 0.0 && e1 >= 0.0 && e2 >= 0.0) {
        // barycentric weights are orient / area: an affine f over the texel
        vec3 w = u_perspective != 0 ? 1.0 / f_depth : f_depth;
        vec2 grad = (g0 * w.x + g1 * w.y + g2 * w.z) / area;
        float at = (dot(g0, c - f_t1) * w.x + dot(g1, c - f_t2) * w.y +
                    dot(g2, c - f_t0) * w.z) / area;
        float reach = h * (abs(grad.x) + abs(grad.y));
        float deepest = u_perspective != 0 ? 1.0 / max(at - reach, 1e-30) : at + reach;
        bound = min(bound, min(deepest, max(max(f_depth.x, f_depth.y), f_depth.z)));
    }
    frag_color = vec4(-bound, -BIG, 0.0, 0.0);
}
