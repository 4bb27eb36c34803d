#version 120
// SPDX-License-Identifier: MIT
// Coloured shadow maps: one transparent surface's eq 5.3 factor
//   (1 - a) clamp(1 - a + c, 0, 1)   per channel
// (a the opacity, c the colour: material times albedo texel), which the
// blending (dst * src) multiplies into the face's texel. A texel of opacity
// 0 casts nothing, so it writes neither the factor nor the nearest depth.
uniform vec4 u_albedo;
uniform sampler2D u_albedo_tex;
uniform int u_has_albedo_tex;
varying vec2 v_uv;

void main()
{
    // bias -16: level 0, as deep reads it (the light's footprint says
    // nothing about the camera's)
    vec4 c = u_has_albedo_tex != 0 ? u_albedo * texture2D(u_albedo_tex, v_uv, -16.0) : u_albedo;
    float a = clamp(c.a, 0.0, 1.0);
    if (a <= 0.0)
        discard;
    gl_FragColor = vec4((1.0 - a) * clamp(vec3(1.0 - a) + c.rgb, 0.0, 1.0), 1.0);
}
