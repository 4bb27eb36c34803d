// SPDX-License-Identifier: MIT
// Deep shadow maps' lookup (technique "deep", src/translucent/deep.c),
// spliced after the shadow technique's chunk: the transmittance through the
// transparent casters of the light being shaded, times the shadow
// technique's own visibility (its opaque casters), through the same seam.
// u_deep_kind: 0 no deep map for this pass, 1 one face, 2 six faces (a
// point light: the face is the major axis of the light-to-point direction,
// as map-pcf's). Layer k of face f is slice f * u_deep_params.x + k / 2 of
// u_deep_even (k even) or u_deep_odd (k odd): x its depth in the face's
// window coordinates, yzw the visibility behind it; unused texels hold depth
// 2 (beyond everything). The point is pushed u_deep_params.z times its clip
// w (1.5 texels' width there) along its normal toward the side the eye
// sees, so its own layer lies behind it: from the terminator rule's point
// along its shading normal (terminator_point.glsl; the facet's on a flat
// triangle), so a smooth mesh's lit side is not darkened by its own facets.
uniform int u_deep_kind;
uniform mat4 u_deep_matrix[6];  // world -> [0,1] window coordinates of face f
uniform vec4 u_deep_params;     // x: slices per face, y: texels a side, z: offset per unit w, w: layers
uniform sampler2DArray u_deep_even;
uniform sampler2DArray u_deep_odd;
uniform int u_deep_face_layers[6]; // layers face f holds (0: no transparent caster reaches it)

// The face of a point light's cube that direction d from the light falls
// in: +x, -x, +y, -y, +z, -z by its major axis (ties to the earlier axis).
int deep_face(vec3 d)
{
    vec3 a = abs(d);
    int axis = (a.x >= a.y && a.x >= a.z) ? 0 : (a.y >= a.z ? 1 : 2);
    return 2 * axis + (d[axis] > 0.0 ? 0 : 1);
}

vec3 deep_transmittance(int light)
{
    if (u_deep_kind == 0)
        return vec3(1.0); // a pass with a deep map lights that one light
    int face = u_deep_kind == 2 ? deep_face(v_world - u_lights[4 * light].xyz) : 0;
    // the side of the facet the eye sees; the lookup starts from the
    // terminator rule's point and is pushed along its normal (the facet's
    // on a flat triangle) by the offset at its clip w
    vec3 side = normalize(cross(dFdx(v_world), dFdy(v_world)));
    side *= sign(dot(side, u_eye - v_world) + 1e-30);
    vec3 normal;
    vec3 start = terminator_point(side, normal);
    float w = (u_deep_matrix[face] * vec4(start, 1.0)).w;
    vec3 pushed = start + normal * (u_deep_params.z * max(w, 0.0));
    // the push may carry the point across a seam: look it up in the face it
    // now lies in, not the one it left (the push is the same on both sides)
    if (u_deep_kind == 2)
        face = deep_face(pushed - u_lights[4 * light].xyz);
    vec4 c = u_deep_matrix[face] * vec4(pushed, 1.0);
    if (w <= 0.0 || c.w <= 0.0)
        return vec3(1.0);
    vec3 t = c.xyz / c.w;
    if (t.x < 0.0 || t.y < 0.0 || t.x >= 1.0 || t.y >= 1.0)
        return vec3(1.0); // outside the face: no transparent caster was fitted there
    int size = int(u_deep_params.y);
    ivec2 texel = clamp(ivec2(t.xy * u_deep_params.y), ivec2(0), ivec2(size - 1));
    int first = face * int(u_deep_params.x);
    int layers = min(int(u_deep_params.w), u_deep_face_layers[face]);
    vec3 v = vec3(1.0);
    for (int k = 0; k < layers; k++) {
        vec4 layer = (k - 2 * (k / 2)) == 0
                         ? texelFetch(u_deep_even, ivec3(texel, first + k / 2), 0)
                         : texelFetch(u_deep_odd, ivec3(texel, first + k / 2), 0);
        if (layer.x >= t.z)
            break; // this layer and the ones after it lie behind the point
        v = layer.yzw;
    }
    return v;
}

vec3 deep_shadow_transmittance(int light)
{
    return shadow_transmittance(light) * deep_transmittance(light);
}
#define shadow_transmittance deep_shadow_transmittance
