#version 110
// SPDX-License-Identifier: MIT
// One colour for every covered pixel, times the shadow test of light 0 where
// the shader does it (map-pcf): the visibility output.
uniform vec4 u_color;
uniform vec3 u_eye;
uniform vec4 u_lights[32]; // light 0: the light whose visibility this shows
varying vec3 v_world;
varying vec3 v_normal;
varying vec3 v_plane_dn; // the terminator rule's tangent planes (lit.vert)
varying vec3 v_plane_nn;
varying vec3 v_plane_nx;

// @chunks
// vec3 shadow_transmittance(int light): the shadow technique's test of a light

// Alpha carries the mean, so a grey transmittance scales all four as before.
vec4 transmittance_rgba(vec3 t)
{
    return vec4(t, (t.r + t.g + t.b) / 3.0);
}

void main()
{
    gl_FragColor = u_color * transmittance_rgba(shadow_transmittance(0));
}
