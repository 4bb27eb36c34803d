#version 110
// One colour for every covered pixel, times the shadow test of light 0 where
// the shader does it (map-pcf): the visibility output.
uniform vec4 u_color;
uniform vec3 u_eye;
uniform vec4 u_lights[32]; // light 0: the light whose visibility this shows
varying vec3 v_world;
varying vec3 v_normal;

// @chunks
// float shadow_visibility(int i): the shadow technique's test of light i

void main()
{
    gl_FragColor = u_color * shadow_visibility(0);
}
