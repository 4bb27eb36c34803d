// SPDX-License-Identifier: MIT
// The deferred outline's filter (src/post/outline.c; seed 004's Sobel on the
// normal buffer, its pixel step a uniform), for GLSL 1.10 and 1.50 (gl4's
// outline.frag maps texture2D to texture). Nine taps u_params.z pixels
// apart around the pixel, clamped into the viewport:
//   - a silhouette: some taps cover a surface and some do not;
//   - a crease: the Sobel magnitude of the normals (|Gx| + |Gy| summed over
//     x, y, z, n in -1..1) reaches u_params.x;
//   - a step in depth: across the pixel, in any of four directions, the
//     window depth halfway between the two opposite taps (exact on a plane:
//     window depth is affine in screen space) lies farther than u_params.y
//     of the eye distance from the pixel's own.
uniform sampler2D u_normal;        // 0.5 + 0.5 n, alpha 1 where a surface is (texel = window pixel)
uniform sampler2D u_depth;         // the same surfaces' window depth
uniform mat4 u_inverse_projection; // clip -> eye, the frame's projection
uniform vec4 u_viewport;           // x, y, width, height (window pixels)
uniform vec4 u_texel;              // 1 / texture width, 1 / texture height
uniform vec4 u_params;             // x normal edge, y depth edge, z step (pixels)

vec2 outline_tap(vec2 offset)
{
    vec2 lo = u_viewport.xy + 0.5, hi = u_viewport.xy + u_viewport.zw - 0.5;
    return clamp(gl_FragCoord.xy + offset * u_params.z, lo, hi) * u_texel.xy;
}

// Eye distance (along the view axis) at window depth d under the pixel.
float outline_distance(float d)
{
    vec2 ndc = (gl_FragCoord.xy - u_viewport.xy) / u_viewport.zw * 2.0 - 1.0;
    vec4 e = u_inverse_projection * vec4(ndc, d * 2.0 - 1.0, 1.0);
    return abs(e.z / e.w);
}

bool outline_edge()
{
    vec3 n[9];
    float d[9];
    int covered = 0;
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 3; i++) {
            vec2 t = outline_tap(vec2(float(i - 1), float(j - 1)));
            vec4 s = texture2D(u_normal, t);
            bool on = s.a > 0.5;
            n[j * 3 + i] = on ? s.xyz * 2.0 - 1.0 : vec3(0.0);
            d[j * 3 + i] = texture2D(u_depth, t).r;
            covered += on ? 1 : 0;
        }
    if (covered == 0)
        return false;
    if (covered < 9)
        return true;
    vec3 gx = (n[2] + 2.0 * n[5] + n[8]) - (n[0] + 2.0 * n[3] + n[6]);
    vec3 gy = (n[6] + 2.0 * n[7] + n[8]) - (n[0] + 2.0 * n[1] + n[2]);
    vec3 g = abs(gx) + abs(gy);
    if (g.x + g.y + g.z >= u_params.x)
        return true;
    float here = outline_distance(d[4]);
    float jump = 0.0;
    jump = max(jump, abs(outline_distance(0.5 * (d[3] + d[5])) - here));
    jump = max(jump, abs(outline_distance(0.5 * (d[1] + d[7])) - here));
    jump = max(jump, abs(outline_distance(0.5 * (d[0] + d[8])) - here));
    jump = max(jump, abs(outline_distance(0.5 * (d[2] + d[6])) - here));
    return jump >= u_params.y * here;
}
