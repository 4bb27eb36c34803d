#version 150
// SPDX-License-Identifier: MIT
// dual-peel's composite (src/transparency/dual_peel.c), composites as
// (C, T) from (0, 1), the layer's colour c (ambient + lights, clamped as the
// framebuffer clamps a surface's passes) and opacity a:
//   mode 0, a front layer under the front composite: C += T a c, T *= 1 - a
//   mode 1, a back layer over the back composite: C = a c + (1 - a) C, T *= 1 - a
//   mode 2, back under front, over the frame as premultiplied colour with
//   coverage 1 - T, at the first layer's depth (depth-peel's rule)
out vec4 frag_color;
uniform sampler2D u_ambient;
uniform sampler2D u_lights;
uniform sampler2D u_accum; // the front or back composite (mode 2: front)
uniform sampler2D u_first;
uniform sampler2D u_back;  // mode 2: the back composite
uniform vec4 u_params;

void main()
{
    vec2 at = gl_FragCoord.xy * u_params.xy;
    vec4 acc = texture(u_accum, at);
    if (u_params.z > 1.5) {
        vec4 back = texture(u_back, at);
        gl_FragDepth = texture(u_first, at).r;
        frag_color = vec4(acc.rgb + acc.a * back.rgb, 1.0 - acc.a * back.a);
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
