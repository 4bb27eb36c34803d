#version 150
// SPDX-License-Identifier: MIT
// VDSM step DC, the receiver half of the light-view pyramid: one point per
// pixel of the position buffer (gl_VertexID), at the point the shadow test
// starts its segment from (vdsm.frag's offset, the same expression), in the
// light's view, carrying its light depth. Pixels with nothing drawn, or
// whose surface turns away from the light (the facing pass leaves them 0
// whatever is drawn), are not receivers and go outside the view; so do
// points behind the light.
uniform sampler2D u_position;
uniform sampler2D u_normal;
uniform sampler2D u_shading; // the terminator rule's second facing normal
uniform vec4 u_light;     // world: position (w 1), or the direction toward the light (w 0)
uniform mat4 u_light_vp;  // world -> the light's clip space
uniform vec4 u_depth_row; // world -> light depth
uniform vec4 u_rect;      // the viewport: x, y, width, height (whole numbers)
out float v_depth;

void main()
{
    ivec4 r = ivec4(u_rect);
    ivec2 px = r.xy + ivec2(gl_VertexID % r.z, gl_VertexID / r.z);
    vec4 p = texelFetch(u_position, px, 0);
    vec3 n = texelFetch(u_normal, px, 0).xyz;
    vec3 s = texelFetch(u_shading, px, 0).xyz;
    vec3 to_light = u_light.xyz - p.xyz * u_light.w;
    float facing = max(dot(n, to_light), dot(s, to_light));
    v_depth = 0.0;
    // vdsm_facing.frag's test with room for rounding: never drop one it keeps
    if (p.w == 0.0 || facing < -1e-4 * length(to_light)) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        return;
    }
    vec3 a = abs(p.xyz);
    float scale = max(max(a.x, a.y), max(a.z, 1e-3));
    vec3 o = p.xyz + n * (scale * 1.220703125e-4);
    vec4 c = u_light_vp * vec4(o, 1.0);
    // at z 0: no depth clipping; behind the light nothing casts onto it
    gl_Position = c.w > 0.0 ? vec4(c.xy / c.w, 0.0, 1.0) : vec4(2.0, 2.0, 2.0, 1.0);
    v_depth = dot(u_depth_row, vec4(o, 1.0));
}
