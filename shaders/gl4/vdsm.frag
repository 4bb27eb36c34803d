#version 150
// SPDX-License-Identifier: MIT
// VDSM, per covered pixel: the exact segment-triangle test (Moller-Trumbore)
// from the pixel's visible surface point to the light against the triangle
// whose shadow polygon covers it. A hit writes 0 into the light's mask
// channel (the colour mask keeps the others); anything else is discarded,
// so the polygons' order does not matter.
uniform sampler2D u_position;
uniform sampler2D u_normal;
uniform vec4 u_light;   // world: position (w 1), or the direction toward the light (w 0)
flat in vec3 f_v0;
flat in vec3 f_v1;
flat in vec3 f_v2;
out vec4 frag_color;

void main()
{
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec4 p = texelFetch(u_position, px, 0);
    if (p.w == 0.0)
        discard;
    vec3 n = texelFetch(u_normal, px, 0).xyz;
    // Leave the surface toward the side the eye sees, by more than the
    // interpolated position's error (measured on llvmpipe: up to 1e-5 of the
    // eye distance, far above float rounding): the pixel's own triangle then
    // lies behind the origin and is never hit (no acne). 2^-13 of the point's
    // size, about the reference's own offset (1e-4 of the scene).
    vec3 a = abs(p.xyz);
    float scale = max(max(a.x, a.y), max(a.z, 1e-3));
    vec3 o = p.xyz + n * (scale * 1.220703125e-4);
    vec3 d = u_light.xyz - o * u_light.w; // to the light (point) or along it (directional)
    vec3 e1 = f_v1 - f_v0, e2 = f_v2 - f_v0;
    vec3 pv = cross(d, e2);
    float det = dot(e1, pv);
    if (det == 0.0)
        discard;
    float inv = 1.0 / det;
    vec3 tv = o - f_v0;
    float u = dot(tv, pv) * inv;
    vec3 qv = cross(tv, e1);
    float v = dot(d, qv) * inv;
    float t = dot(e2, qv) * inv;
    // Edges widened by 2^-20 so a ray through an edge two triangles share hits
    // at least one of them despite rounding.
    const float edge = 9.5367431640625e-7;
    float tmax = u_light.w > 0.0 ? 1.0 : 3.4e38;
    if (u < -edge || v < -edge || u + v > 1.0 + edge || t <= 0.0 || t >= tmax)
        discard;
    frag_color = vec4(0.0);
}
