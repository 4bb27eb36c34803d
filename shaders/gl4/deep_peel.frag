#version 150
// SPDX-License-Identifier: MIT
// Deep shadow maps, one layer of a face (deep_peel_layer.glsl); the early
// stop counts this pass's samples with an occlusion query (GL 3.2-4.2).
out vec4 o_layer;

// @chunks

void main()
{
    o_layer = deep_layer();
}
