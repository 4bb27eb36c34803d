#version 110
// SPDX-License-Identifier: MIT
// A shadow map's depth where no depth texture exists: the fragment's window
// depth packed into the colour target (pack_depth.glsl); a depth
// renderbuffer beside it keeps the nearest caster.

// @chunks

void main()
{
    gl_FragColor = pack_depth(gl_FragCoord.z);
}
