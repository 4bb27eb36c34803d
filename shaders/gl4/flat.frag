#version 150
// One colour for every covered pixel, times the shadow test of light 0 where
// the shader does it (map-pcf): the visibility output.
out vec4 frag_color;
uniform vec4 u_color;
uniform vec3 u_eye;
uniform vec4 u_lights[32]; // light 0: the light whose visibility this shows
in vec3 v_world;
in vec3 v_normal;

// The chunks are shared with shaders/gl2 and use GLSL 1.10's names: map them.
#define texture2D texture
#define shadow2D(s, c) vec4(texture(s, c))

// @chunks
// float shadow_visibility(int i): the shadow technique's test of light i

void main()
{
    frag_color = u_color * shadow_visibility(0);
}
