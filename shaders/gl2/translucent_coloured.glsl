// SPDX-License-Identifier: MIT
// Coloured shadow maps' lookup (technique "coloured",
// src/translucent/coloured.c), spliced after the shadow technique's chunk:
// the product of the eq 5.3 factors of the transparent casters on the
// light's ray, where the point lies behind the nearest of them, times the
// shadow technique's own visibility, through the same seam. Shared by the
// gl4 lit programs (GLSL 1.10 names, mapped there).
// u_coloured_kind: 0 no map for this pass, 1 one face, 2 six faces (a point
// light: the face of the major axis, as map-pcf's). Face f is the cell at
// column f % 3, row f / 3 of a 3 x 2 atlas: u_coloured_map holds the
// product, u_coloured_depth the nearest transparent depth (1 where none).
// The point is pushed u_coloured_params.y times its clip w (1.5 texels'
// width there) along its normal toward the side the eye sees, from the
// terminator rule's point, as deep's lookup, so a pane's own depth lies
// behind its lit side.
uniform int u_coloured_kind;
uniform mat4 u_coloured_matrix[6]; // world -> [0,1] window coordinates of face f
uniform vec4 u_coloured_params;    // x: texels a side, y: offset per unit w, z: 0 skips the depth test
uniform sampler2D u_coloured_map;
uniform sampler2D u_coloured_depth;

// The face of a point light's cube that direction d from the light falls
// in: +x, -x, +y, -y, +z, -z by its major axis (ties to the earlier axis).
int coloured_face(vec3 d)
{
    vec3 a = abs(d);
    if (a.x >= a.y && a.x >= a.z)
        return d.x > 0.0 ? 0 : 1;
    if (a.y >= a.z)
        return d.y > 0.0 ? 2 : 3;
    return d.z > 0.0 ? 4 : 5;
}

vec3 coloured_transmittance(int light)
{
    if (u_coloured_kind == 0)
        return vec3(1.0); // a pass with a colour map lights that one light
    int face = u_coloured_kind == 2 ? coloured_face(v_world - u_lights[4 * light].xyz) : 0;
    // the side of the facet the eye sees; the lookup starts from the
    // terminator rule's point and is pushed along its normal (the facet's
    // on a flat triangle) by the offset at its clip w
    vec3 side = geometric_normal();
    side *= sign(dot(side, u_eye - v_world) + 1e-30);
    vec3 normal;
    vec3 start = terminator_point(side, normal);
    float w = (u_coloured_matrix[face] * vec4(start, 1.0)).w;
    vec3 pushed = start + normal * (u_coloured_params.y * max(w, 0.0));
    // the push may carry the point across a seam: look it up in the face it
    // now lies in, not the one it left (the push is the same on both sides)
    if (u_coloured_kind == 2)
        face = coloured_face(pushed - u_lights[4 * light].xyz);
    vec4 c = u_coloured_matrix[face] * vec4(pushed, 1.0);
    if (w <= 0.0 || c.w <= 0.0)
        return vec3(1.0);
    vec3 t = c.xyz / c.w;
    if (t.x < 0.0 || t.y < 0.0 || t.x >= 1.0 || t.y >= 1.0)
        return vec3(1.0); // outside the face: no transparent caster was fitted there
    float size = u_coloured_params.x;
    vec2 texel = clamp(floor(t.xy * size), vec2(0.0), vec2(size - 1.0));
    vec2 cell = vec2(float(face - 3 * (face / 3)), float(face / 3));
    vec2 uv = (cell * size + texel + 0.5) / (vec2(3.0, 2.0) * size);
    if (u_coloured_params.z != 0.0 && t.z <= texture2D(u_coloured_depth, uv).r)
        return vec3(1.0); // in front of every transparent caster on the ray
    return texture2D(u_coloured_map, uv).rgb;
}

vec3 coloured_shadow_transmittance(int light)
{
    return shadow_transmittance(light) * coloured_transmittance(light);
}
#define shadow_transmittance coloured_shadow_transmittance
