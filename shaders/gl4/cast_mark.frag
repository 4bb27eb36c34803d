#version 150
// SPDX-License-Identifier: MIT
// Marks, in the stencil a light's shadow volumes counted, where the map of
// the casters volumes cannot cast (CSG products, displaced draws) shadows
// the surface (shadow/cast_map.c): a fragment the map lights (half its
// kernel or more) is discarded.
in vec3 v_world;
out vec4 frag_color;

// The chunk uses GLSL 1.10's names: map them.
#define shadow2D(s, c) vec4(texture(s, c))

// float cast_visibility(): cast_test.glsl
// @chunks

void main()
{
    if (cast_visibility() >= 0.5)
        discard;
    frag_color = vec4(0.0);
}
