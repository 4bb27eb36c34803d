#version 150
// SPDX-License-Identifier: MIT
// Coloured shadow maps on GL4 contexts (drawn through deep_peel.vert): as
// shaders/gl2/coloured_cast.frag, one transparent surface's eq 5.3 factor
//   (1 - a) clamp(1 - a + c, 0, 1)
// multiplied into the face's texel by the blending; opacity 0 casts nothing.
uniform vec4 u_albedo;
uniform sampler2D u_albedo_tex;
uniform int u_has_albedo_tex;
in vec2 v_uv;
out vec4 o_factor;

void main()
{
    vec4 c = u_has_albedo_tex != 0 ? u_albedo * textureLod(u_albedo_tex, v_uv, 0.0) : u_albedo;
    float a = clamp(c.a, 0.0, 1.0);
    if (a <= 0.0)
        discard;
    o_factor = vec4((1.0 - a) * clamp(vec3(1.0 - a) + c.rgb, 0.0, 1.0), 1.0);
}
