#version 150
// SPDX-License-Identifier: MIT
// As shaders/gl2/depth_packed.frag: a shadow map's depth packed into the
// colour target where no depth texture exists (pack_depth.glsl, shared).
out vec4 frag_color;

// @chunks

void main()
{
    frag_color = pack_depth(gl_FragCoord.z);
}
