#version 150
// SPDX-License-Identifier: MIT
#ifdef GL_ARB_shader_image_load_store
#extension GL_ARB_shader_image_load_store : enable
#endif
// VDSM for an area light, per pixel of a triangle's rectangle
// (vdsm_soft.geom): the segments from the pixel's surface point to 64
// points of the light's disc - the disc of radius u_radius round u_light
// facing the point, as the reference integrates it - against the triangle,
// one bit each (Moller-Trumbore, as vdsm_segment.glsl), written where any
// is hit; the pass ORs them (glLogicOp) over every triangle, and
// vdsm_soft_resolve.frag turns the unset bits into the visibility. The
// disc's points (a Vogel spiral) turn by an angle per pixel, so the
// penumbra takes many levels rather than 64 copies of the hard shadow.
// The bits are two words (x: points 0-31, y: 32-63). OpenGL ES has no
// logic op: with STIN_SOFT_IMAGE (GLSL ES 3.20) they are ORed by image
// atomics into u_words, a pixel's two words side by side, and no colour is
// written.
// The rectangles' depth test writes no depth: it may run first (vdsm.frag).
#if defined(GL_ARB_shader_image_load_store) || defined(STIN_SOFT_IMAGE)
layout(early_fragment_tests) in;
#endif
flat in vec3 f_v0;
flat in vec3 f_v1;
flat in vec3 f_v2;
uniform sampler2D u_position;
uniform sampler2D u_normal;
uniform vec4 u_light; // the disc's centre (w 1)
uniform float u_radius;
#ifdef STIN_SOFT_IMAGE
layout(r32ui, binding = 0) uniform highp uimage2D u_words;
#else
out uvec4 frag_color;
#endif

const int SAMPLES = 64;

void main()
{
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec4 p = texelFetch(u_position, px, 0);
    if (p.w == 0.0)
        discard;
    vec3 n = texelFetch(u_normal, px, 0).xyz;
    // off the surface toward the side the eye sees, as vdsm_segment.glsl
    vec3 a = abs(p.xyz);
    float scale = max(max(a.x, a.y), max(a.z, 1e-3));
    vec3 o = p.xyz + n * (scale * 1.220703125e-4);
    vec3 l = u_light.xyz, to_light = l - o;
    vec3 e1 = f_v1 - f_v0, e2 = f_v2 - f_v0, tn = cross(e1, e2);
    // the ball wholly on the point's side of the triangle's plane: no
    // segment crosses it
    float side_o = dot(tn, o - f_v0), side_l = dot(tn, l - f_v0);
    if (side_o * side_l >= 0.0 && abs(side_l) >= u_radius * length(tn))
        discard;
    // the triangle's bounding sphere outside the cone from the point to the
    // ball
    vec3 c = (f_v0 + f_v1 + f_v2) / 3.0;
    float rho = sqrt(max(max(dot(f_v0 - c, f_v0 - c), dot(f_v1 - c, f_v1 - c)),
                         dot(f_v2 - c, f_v2 - c)));
    vec3 to_c = c - o;
    float dl = length(to_light), dc = length(to_c);
    if (dc - rho > dl + u_radius)
        discard; // beyond the light
    if (dc > rho && dl > u_radius) {
        float apart = acos(clamp(dot(to_c, to_light) / (dc * dl), -1.0, 1.0));
        if (apart > asin(u_radius / dl) + asin(rho / dc))
            discard;
    }
    // the disc facing the point: two axes across the direction to it
    vec3 w = to_light / dl;
    vec3 u = normalize(cross(w, abs(w.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0)));
    vec3 v = cross(w, u);
    // interleaved gradient noise: a stable angle per pixel
    float turn = 6.2831853 * fract(52.9829189 * fract(dot(gl_FragCoord.xy,
                                                          vec2(0.06711056, 0.00583715))));
    const float edge = 9.5367431640625e-7; // as vdsm_segment.glsl
    vec3 tv = o - f_v0;
    vec3 qv = cross(tv, e1);
    float t_num = dot(e2, qv);
    uvec2 bits = uvec2(0u);
    for (int k = 0; k < SAMPLES; k++) {
        float r = u_radius * sqrt((float(k) + 0.5) / float(SAMPLES));
        float phi = float(k) * 2.3999632 + turn;
        vec3 d = to_light + r * (cos(phi) * u + sin(phi) * v);
        vec3 pv = cross(d, e2);
        float det = dot(e1, pv);
        if (det == 0.0)
            continue;
        float inv = 1.0 / det;
        float bu = dot(tv, pv) * inv, bv = dot(d, qv) * inv, t = t_num * inv;
        if (bu >= -edge && bv >= -edge && bu + bv <= 1.0 + edge && t > 0.0 && t < 1.0)
            bits[k / 32] |= 1u << uint(k % 32);
    }
    if (bits == uvec2(0u))
        discard;
#ifdef STIN_SOFT_IMAGE
    if (bits.x != 0u)
        imageAtomicOr(u_words, ivec2(px.x * 2, px.y), bits.x);
    if (bits.y != 0u)
        imageAtomicOr(u_words, ivec2(px.x * 2 + 1, px.y), bits.y);
#else
    frag_color = uvec4(bits, 0u, 0u);
#endif
}
