#version 400 core
// SPDX-License-Identifier: MIT
// Displacement by tessellation, control stage. Each edge's level comes from
// that edge alone - its world length in pixels at the distance of its
// midpoint from the camera, over the target length - so the two patches that
// share an edge split it alike and no crack opens. The camera's eye and scale
// serve every pass (light passes too), so maps and vdsm see the surface the
// camera sees. Draws that are not displaced keep level 1: their one triangle.
// (gl/shader.c replaces the #version line where the context has
// ARB_tessellation_shader on GLSL 1.50.)
layout(vertices = 3) out;
uniform mat4 u_model;
uniform vec4 u_displace;  // displace.glsl's; z: 1 when this draw is displaced
uniform vec4 u_tess;      // pixels per unit at eye distance 1, target edge in pixels,
                          // highest level, 1 perspective / 0 orthographic camera
uniform vec3 u_tess_eye;  // the camera's eye, world space
in vec4 c_position[];
in vec3 c_normal[];
in vec2 c_uv[];
in vec4 c_tangent[];
out vec4 e_position[];
out vec3 e_normal[];
out vec2 e_uv[];
out vec4 e_tangent[];

// symmetric in a and b: both patches of an edge compute the same bits
float edge_level(vec3 a, vec3 b)
{
    float dist = u_tess.w > 0.0 ? max(distance(u_tess_eye, (a + b) * 0.5), 1e-6) : 1.0;
    return clamp(distance(a, b) * u_tess.x / (dist * u_tess.y), 1.0, u_tess.z);
}

void main()
{
    e_position[gl_InvocationID] = c_position[gl_InvocationID];
    e_normal[gl_InvocationID] = c_normal[gl_InvocationID];
    e_uv[gl_InvocationID] = c_uv[gl_InvocationID];
    e_tangent[gl_InvocationID] = c_tangent[gl_InvocationID];
    if (gl_InvocationID != 0)
        return;
    if (u_displace.z == 0.0) {
        gl_TessLevelOuter[0] = gl_TessLevelOuter[1] = gl_TessLevelOuter[2] = 1.0;
        gl_TessLevelInner[0] = 1.0;
        return;
    }
    vec3 p0 = (u_model * c_position[0]).xyz;
    vec3 p1 = (u_model * c_position[1]).xyz;
    vec3 p2 = (u_model * c_position[2]).xyz;
    // outer level k is the edge opposite vertex k (where its coordinate is 0)
    gl_TessLevelOuter[0] = edge_level(p1, p2);
    gl_TessLevelOuter[1] = edge_level(p2, p0);
    gl_TessLevelOuter[2] = edge_level(p0, p1);
    gl_TessLevelInner[0] = max(gl_TessLevelOuter[0], max(gl_TessLevelOuter[1], gl_TessLevelOuter[2]));
}
