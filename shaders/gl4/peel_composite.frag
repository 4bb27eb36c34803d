#version 150
// SPDX-License-Identifier: MIT
// depth-peel's composite: see shaders/gl2/peel_composite.frag (the same
// arithmetic, GLSL 1.50 names).
out vec4 frag_color;
uniform sampler2D u_ambient;
uniform sampler2D u_lights;
uniform sampler2D u_accum;
uniform sampler2D u_first;
uniform vec4 u_params;

void main()
{
    vec2 at = gl_FragCoord.xy * u_params.xy;
    vec4 acc = texture(u_accum, at);
    gl_FragDepth = texture(u_first, at).r;
    if (u_params.z > 0.5) {
        frag_color = vec4(acc.rgb, 1.0 - acc.a);
        return;
    }
    vec4 layer = texture(u_ambient, at);
    vec3 c = min(layer.rgb + texture(u_lights, at).rgb, vec3(1.0));
    frag_color = vec4(acc.rgb + acc.a * layer.a * c, acc.a * (1.0 - layer.a));
}
