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

vec4 layered(vec4 best, vec2 at, vec2 step)
{
    return best.a < 1.0 ? best : texture(u_accum, at + step * u_params.xy);
}

vec4 covering(vec4 acc, vec2 at)
{
    if (u_params.w < 0.5)
        return acc;
    acc = layered(acc, at, vec2(1.0, 0.0));
    acc = layered(acc, at, vec2(-1.0, 0.0));
    acc = layered(acc, at, vec2(0.0, 1.0));
    acc = layered(acc, at, vec2(0.0, -1.0));
    acc = layered(acc, at, vec2(1.0, 1.0));
    acc = layered(acc, at, vec2(-1.0, 1.0));
    acc = layered(acc, at, vec2(1.0, -1.0));
    return layered(acc, at, vec2(-1.0, -1.0));
}

void main()
{
    vec2 at = gl_FragCoord.xy * u_params.xy;
    vec4 acc = texture(u_accum, at);
    gl_FragDepth = texture(u_first, at).r;
    if (u_params.z > 0.5) {
        acc = covering(acc, at);
        frag_color = vec4(acc.rgb, 1.0 - acc.a);
        return;
    }
    vec4 layer = texture(u_ambient, at);
    vec3 c = min(layer.rgb + texture(u_lights, at).rgb, vec3(1.0));
    frag_color = vec4(acc.rgb + acc.a * layer.a * c, acc.a * (1.0 - layer.a));
}
