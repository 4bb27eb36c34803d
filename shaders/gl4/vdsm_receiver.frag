#version 150
// SPDX-License-Identifier: MIT
// VDSM step DC: a receiver's light depth, MAX-blended into y (x is the
// light pass's: -BIG does not change it).
in float v_depth;
out vec4 frag_color;

void main()
{
    frag_color = vec4(-1e30, v_depth, 0.0, 0.0);
}
