// SPDX-License-Identifier: MIT
// Deep shadow maps, layer k of a face (seed 001): the nearest transparent
// surface behind layer k - 1 at this texel (the depth test LESS finds the
// nearest, this discards what layer k - 1 already holds), stored as its depth
// and the visibility behind it, per channel
//   V = V' (1 - a) clamp(1 - a + c, 0, 1)   (eq 5.3; mono: V = V' (1 - a))
// with V' the visibility layer k - 1 stored (1 for layer 0). A texel of
// opacity 0 casts nothing, so it takes no layer either. Shared by
// deep_peel.frag (early stop by occlusion query) and deep_peel_flag.frag
// (early stop by a shader storage flag).
uniform vec4 u_albedo;
uniform sampler2D u_albedo_tex;
uniform int u_has_albedo_tex;
uniform sampler2DArray u_previous; // the other ping-pong texture: layer k - 1
uniform int u_previous_slice;      // its slice, -1 for layer 0
uniform int u_mono;
in vec2 v_uv;

// The layer texel of this fragment (discards what the layer does not hold).
vec4 deep_layer()
{
    float z = gl_FragCoord.z;
    vec3 behind = vec3(1.0);
    if (u_previous_slice >= 0) {
        vec4 previous = texelFetch(u_previous, ivec3(ivec2(gl_FragCoord.xy), u_previous_slice), 0);
        if (z <= previous.x)
            discard; // layer k - 1 or nearer
        behind = previous.yzw;
    }
    // level 0: the light's footprint says nothing about the camera's
    vec4 c = u_has_albedo_tex != 0 ? u_albedo * textureLod(u_albedo_tex, v_uv, 0.0) : u_albedo;
    float a = clamp(c.a, 0.0, 1.0);
    if (a <= 0.0)
        discard;
    vec3 v = u_mono != 0 ? behind * (1.0 - a)
                         : behind * (1.0 - a) * clamp(vec3(1.0 - a) + c.rgb, 0.0, 1.0);
    return vec4(z, v);
}
