#version 150
// SPDX-License-Identifier: MIT
// dual-peel's composite (src/transparency/dual_peel.c), composites as
// (C, T) from (0, 1), the layer's colour c (ambient + lights, clamped as the
// framebuffer clamps a surface's passes) and opacity a:
//   mode 0, a front layer under the front composite: C += T a c, T *= 1 - a
//   mode 1, a back layer over the back composite: C = a c + (1 - a) C, T *= 1 - a
//   mode 2, back under front, over the frame as premultiplied colour with
//   coverage 1 - T, at the first layer's depth (depth-peel's rule); into a
//   multisampled target (u_params.w = 1) only on the samples a blended
//   surface covers, and where the centre holds no layer, the nearest
//   neighbour's that does (src/transparency/peel_coverage.c)
out vec4 frag_color;
uniform sampler2D u_ambient;
uniform sampler2D u_lights;
uniform sampler2D u_accum; // the front or back composite (mode 2: front)
uniform sampler2D u_first;
uniform sampler2D u_back;  // mode 2: the back composite
uniform vec4 u_params;

// (C, T) of the front composite over the back one at `at`
vec4 both(vec2 at)
{
    vec4 front = texture(u_accum, at), back = texture(u_back, at);
    return vec4(front.rgb + front.a * back.rgb, front.a * back.a);
}

vec4 layered(vec4 best, vec2 at, vec2 step)
{
    return best.a < 1.0 ? best : both(at + step * u_params.xy);
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
    if (u_params.z > 1.5) {
        vec4 ct = covering(both(at), at);
        gl_FragDepth = texture(u_first, at).r;
        frag_color = vec4(ct.rgb, 1.0 - ct.a);
        return;
    }
    gl_FragDepth = 0.0; // no depth test: a value for every path
    vec4 layer = texture(u_ambient, at);
    vec3 c = min(layer.rgb + texture(u_lights, at).rgb, vec3(1.0));
    if (u_params.z > 0.5)
        frag_color = vec4(layer.a * c + (1.0 - layer.a) * acc.rgb, acc.a * (1.0 - layer.a));
    else
        frag_color = vec4(acc.rgb + acc.a * layer.a * c, acc.a * (1.0 - layer.a));
}
