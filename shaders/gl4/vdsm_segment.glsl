// SPDX-License-Identifier: MIT
// VDSM's exact per-pixel test (vdsm.frag; vdsm_csg_append.frag): the
// segment from the pixel's visible surface point to the light against one
// triangle (Moller-Trumbore), as the fragment stages of the shadow polygons
// run it.
uniform sampler2D u_position;
uniform sampler2D u_normal;
uniform vec4 u_light;   // world: position (w 1), or the direction toward the light (w 0)

// Whether the segment from the surface under the fragment to the light
// meets triangle (v0, v1, v2): t its parameter there (0 < t < 1 toward a
// point light, t > 0 along a directional light's direction), det > 0 where
// it passes from the triangle's front (counter-clockwise) side to its back,
// unit the parameter's length of the point's own size (the scale the
// tolerances below are relative to).
bool vdsm_segment(vec3 v0, vec3 v1, vec3 v2, out float t, out float det, out float unit)
{
    t = det = unit = 0.0;
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec4 p = texelFetch(u_position, px, 0);
    if (p.w == 0.0)
        return false;
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
    vec3 e1 = v1 - v0, e2 = v2 - v0;
    vec3 pv = cross(d, e2);
    det = dot(e1, pv);
    if (det == 0.0)
        return false;
    float inv = 1.0 / det;
    vec3 tv = o - v0;
    float u = dot(tv, pv) * inv;
    vec3 qv = cross(tv, e1);
    float v = dot(d, qv) * inv;
    t = dot(e2, qv) * inv;
    unit = scale / max(length(d), 1e-30);
    // Edges widened by 2^-20 so a ray through an edge two triangles share hits
    // at least one of them despite rounding.
    const float edge = 9.5367431640625e-7;
    float tmax = u_light.w > 0.0 ? 1.0 : 3.4e38;
    return !(u < -edge || v < -edge || u + v > 1.0 + edge || t <= 0.0 || t >= tmax);
}
