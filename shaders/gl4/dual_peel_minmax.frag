#version 150
// SPDX-License-Identifier: MIT
// dual-peel's geometry pass (src/transparency/dual_peel.c), MAX-blended
// into RG32F: a blended fragment in front of the opaque depth and, after
// the first pass, strictly between the last pass's nearest and farthest
// writes (-z, z), so each texel ends as (-near, far) of the surfaces no pass
// has taken yet. z is gl_FragCoord.z, the value the lit programs' chunk
// (dual_peel.glsl) compares with: stored in float, it comes back exact.
out vec4 frag_color;
uniform sampler2D u_previous; // the last pass's (-near, far)
uniform sampler2D u_opaque;   // the opaque draws' depth
uniform vec4 u_params;        // 1 / texture size (x, y), after the first pass

void main()
{
    vec2 at = gl_FragCoord.xy * u_params.xy;
    float z = gl_FragCoord.z;
    if (z >= texture(u_opaque, at).r)
        discard;
    if (u_params.z != 0.0) {
        vec2 last = texture(u_previous, at).rg;
        if (z <= -last.x || z >= last.y)
            discard;
    }
    frag_color = vec4(-z, z, 0.0, 0.0);
}
