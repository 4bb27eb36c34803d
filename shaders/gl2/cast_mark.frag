#version 110
// SPDX-License-Identifier: MIT
// Marks, in the stencil a light's shadow volumes counted, where the map of
// the casters volumes cannot cast (CSG products, displaced draws) shadows
// the surface (shadow/cast_map.c): a fragment the map lights (half its
// kernel or more) is discarded.
varying vec3 v_world;

// float cast_visibility(): cast_test.glsl
// @chunks

void main()
{
    if (cast_visibility() >= 0.5)
        discard;
    gl_FragColor = vec4(0.0);
}
