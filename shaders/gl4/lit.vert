#version 150
// Per-pixel lighting, vertex stage: world-space position, normal and uv.
// Invariant: the depth of a volume cap must equal, bit for bit, the depth the
// lit passes wrote for the surface it lies on (z-fail counts it behind).
invariant gl_Position;
uniform mat4 u_model;
uniform mat4 u_view_proj;
uniform mat3 u_normal_matrix;
in vec4 a_position;
in vec3 a_normal;
in vec2 a_uv;
out vec3 v_world;
out vec3 v_normal;
out vec2 v_uv;

void main()
{
    // w comes from the vertex fetch (1.0), exactly as in volume.vert, so that
    // volume caps and the surfaces they coincide with rasterise to equal depths.
    vec4 world = u_model * a_position;
    v_world = world.xyz;
    v_normal = u_normal_matrix * a_normal;
    v_uv = a_uv;
    gl_Position = u_view_proj * world;
}
