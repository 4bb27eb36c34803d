#version 430
// SPDX-License-Identifier: MIT
// VDSM's deepest receiver per light texel (src/shadow/vdsm_receivers.c), GL
// 4.3: one fragment per pixel of the viewport, the position buffer's point
// there taken into the light's view as vdsm_receiver.vert takes it (the same
// facing test, the same push along the normal), its light depth kept by an
// atomic maximum of ordered bits in the texel it falls in: the texel a point
// drawn there would cover. The same pass is the light's facing pass
// (vdsm_facing.frag): it writes the light's mask channel, 1 where the side
// of the surface the eye sees faces the light, so the position buffer is
// read once for both.
layout(std430, binding = 0) buffer vdsm_deepest
{
    uint deepest[]; // per texel of level 0, row by row: ordered bits, 0 for none
};
uniform sampler2D u_position;
uniform sampler2D u_normal;
uniform sampler2D u_shading; // the terminator rule's second facing normal
uniform vec4 u_light;     // world: position (w 1), or the direction toward the light (w 0)
uniform mat4 u_light_vp;  // world -> the light's clip space
uniform vec4 u_depth_row; // world -> light depth
uniform int u_size;       // texels a side of level 0
out vec4 frag_color;

// Bits whose unsigned order is the floats' order (all above 0).
uint ordered(float f)
{
    uint u = floatBitsToUint(f);
    return (u & 0x80000000u) != 0u ? ~u : u | 0x80000000u;
}

void main()
{
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec4 p = texelFetch(u_position, px, 0);
    vec3 n = texelFetch(u_normal, px, 0).xyz;
    vec3 s = texelFetch(u_shading, px, 0).xyz;
    vec3 to_light = u_light.xyz - p.xyz * u_light.w;
    float facing = max(dot(n, to_light), dot(s, to_light));
    frag_color = vec4(p.w > 0.0 && facing > 0.0 ? 1.0 : 0.0);
    if (p.w == 0.0 || facing < -1e-4 * length(to_light))
        return;
    vec3 a = abs(p.xyz);
    float scale = max(max(a.x, a.y), max(a.z, 1e-3));
    vec3 o = p.xyz + n * (scale * 1.220703125e-4);
    vec4 c = u_light_vp * vec4(o, 1.0);
    if (!(c.w > 0.0))
        return; // behind the light nothing casts onto it
    vec2 t = floor((c.xy / c.w * 0.5 + 0.5) * float(u_size));
    if (any(lessThan(t, vec2(0.0))) || any(greaterThanEqual(t, vec2(float(u_size)))))
        return;
    atomicMax(deepest[int(t.y) * u_size + int(t.x)], ordered(dot(u_depth_row, vec4(o, 1.0))));
}
