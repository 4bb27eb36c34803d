#version 110
// SPDX-License-Identifier: MIT
// depth-peel's composite (src/transparency/peel.c). Mode 0 adds a lit layer
// under the composite so far, (C, T) front to back: C += T a c, T *= 1 - a,
// with c the layer's ambient plus its lights (clamped, as the framebuffer
// would) and a its opacity (0 where the layer has no surface). Mode 1 hands
// the composite to the blend that puts it over the frame as premultiplied
// colour C with coverage 1 - T (ONE, ONE_MINUS_SRC_ALPHA: colour C + T frame,
// alpha 1 - T + T alpha, the reference's), and the first layer's depth to
// the frame's depth test.
uniform sampler2D u_ambient; // the layer's ambient colour and opacity
uniform sampler2D u_lights;  // the layer's lights, added up
uniform sampler2D u_accum;   // (C, T) of the layers before it
uniform sampler2D u_first;   // the first layer's depth (mode 1)
uniform vec4 u_params;       // 1 / texture size (x, y), mode, covered samples only
// Mode 1 into a multisampled target (w = 1): the quad colours only the
// samples a blended surface covers (src/transparency/peel_coverage.c), so
// where the pixel centre holds no layer (T = 1) they take the composite of
// the nearest neighbour that does: edge neighbours first, then corners.

vec4 layered(vec4 best, vec2 at, vec2 step)
{
    return best.a < 1.0 ? best : texture2D(u_accum, at + step * u_params.xy);
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
    vec4 acc = texture2D(u_accum, at);
    gl_FragDepth = texture2D(u_first, at).r;
    if (u_params.z > 0.5) {
        acc = covering(acc, at);
        gl_FragColor = vec4(acc.rgb, 1.0 - acc.a);
        return;
    }
    vec4 layer = texture2D(u_ambient, at);
    vec3 c = min(layer.rgb + texture2D(u_lights, at).rgb, vec3(1.0));
    gl_FragColor = vec4(acc.rgb + acc.a * layer.a * c, acc.a * (1.0 - layer.a));
}
