#version 430
// SPDX-License-Identifier: MIT
// Deep shadow maps, one layer of a face (deep_peel_layer.glsl), on GL 4.3:
// every fragment the layer keeps sets the flag (no atomics: any writer's 1
// will do), which the CPU clears before the pass and reads after it, so the
// early stop needs no occlusion query. A fragment the depth test then
// rejects still sets it, but only where a nearer kept fragment passes: the
// flag is set exactly when the layer drew something.
layout(std430, binding = 0) buffer deep_drawn
{
    uint drawn;
};
out vec4 o_layer;

// @chunks

void main()
{
    o_layer = deep_layer();
    drawn = 1u;
}
