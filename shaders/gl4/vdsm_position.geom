#version 150
// SPDX-License-Identifier: MIT
// VDSM position buffer, geometry stage: each triangle unchanged, its three
// corners and vertex normals handed to every fragment (flat) with the
// fragment's barycentrics, for the terminator rule (vdsm_position.frag).
// A triangle whose vertex normals all equal its facet normal (planes,
// boxes), or has none, is marked flat: it keeps today's facet rule exactly.
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
invariant gl_Position; // as lit.vert: the buffer covers what the lit passes cover
in vec3 vs_world[];
in vec3 vs_normal[];
out vec3 v_world;
out vec3 v_bary;
flat out mat3 v_corners;
flat out mat3 v_normals;
flat out float v_smooth;

void main()
{
    mat3 corners = mat3(vs_world[0], vs_world[1], vs_world[2]);
    mat3 normals = mat3(0.0);
    vec3 facet = cross(corners[1] - corners[0], corners[2] - corners[0]);
    float len = length(facet), smooth_ = 0.0;
    facet = len > 0.0 ? facet / len : vec3(0.0);
    for (int k = 0; k < 3; k++) {
        float n = length(vs_normal[k]);
        if (!(n > 0.0) || len == 0.0) {
            smooth_ = -1.0; // no normals: the facet
            break;
        }
        normals[k] = vs_normal[k] / n;
        if (abs(dot(normals[k], facet)) < 1.0 - 1e-6) // either way round: CSG's inner walls
            smooth_ = 1.0;
    }
    for (int k = 0; k < 3; k++) {
        gl_Position = gl_in[k].gl_Position;
        v_world = vs_world[k];
        v_bary = vec3(k == 0 ? 1.0 : 0.0, k == 1 ? 1.0 : 0.0, k == 2 ? 1.0 : 0.0);
        v_corners = corners;
        v_normals = normals;
        v_smooth = smooth_ > 0.0 ? 1.0 : 0.0;
        EmitVertex();
    }
    EndPrimitive();
}
