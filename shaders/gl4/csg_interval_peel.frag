#version 150
// SPDX-License-Identifier: MIT
// CSG "interval" (src/csg/interval.c): one layer of one primitive's crossings
// of the camera rays. Drawn with depth LESS into a fresh depth layer, after
// discarding what lies at or in front of the layer before (read from the
// other array: never the texture drawn into), so the nearest crossing left
// is this layer. The colour keeps the fragment's float depth - the
// rasteriser's own for one mesh drawn the same way each pass, so the
// comparison is exact (the depth layer only serves the depth test) - and
// its side: 1 front (the ray enters), 0.5 back
// (it leaves), 0 (the clear) no crossing. A layer the walk chose is peeled
// once more in the frame's own depth buffer (which may rasterise a hair
// differently: a window's buffer is not flipped as a texture is), against
// the layer before give or take u_tolerance, and read back from there.
uniform sampler2DArray u_previous;
uniform int u_previous_slice; // < 0: the first layer
uniform int u_mirrored;       // the draw's transform mirrors: its sides swap
uniform float u_tolerance;    // 0 in the layers; a little in the frame's buffer
out vec4 o_crossing;

void main()
{
    if (u_previous_slice >= 0) {
        vec2 previous = texelFetch(u_previous, ivec3(ivec2(gl_FragCoord.xy), u_previous_slice),
                                   0).rg;
        // nothing left behind an empty layer; else only what lies behind it
        if (previous.g < 0.25 || gl_FragCoord.z <= previous.r + u_tolerance)
            discard;
    }
    bool front = gl_FrontFacing != (u_mirrored != 0);
    o_crossing = vec4(gl_FragCoord.z, front ? 1.0 : 0.5, 0.0, 1.0);
}
