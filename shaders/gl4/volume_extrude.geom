#version 150
// SPDX-License-Identifier: MIT
// Shadow volumes extruded on the GPU (src/shadow/volume_extrude.c): the same
// volume src/shadow/volume_geometry.c builds on the CPU, from the mesh's
// static buffers and its GL_TRIANGLES_ADJACENCY indices, so a frame spends no
// CPU time per caster triangle. Closed casters: light caps, far caps and side
// quads on silhouette edges of the light-facing triangles. Other casters:
// every triangle's own volume, averted ones flipped to face the light, side
// quads skipped where the neighbour faces the same way (the two would
// cancel); their averted light caps keep the stored order and come from a
// second draw (u_mode 1) with the winding convention flipped, as on the CPU.
//
// Every triangle decides the facing of its neighbours as well as its own, and
// the two decisions about one triangle must agree to the bit, or a side quad
// loses its partner and the count leaks along it. So the facing is computed
// on the three points rotated to start at the lexicographically least one:
// the same operations on the same operands in every invocation that asks.
layout(triangles_adjacency) in;
layout(triangle_strip, max_vertices = 18) out;
in vec3 g_object[];      // object-space positions (volume.vert)
uniform mat4 u_model;
uniform mat4 u_view_proj;
uniform vec4 u_light;    // object space: position (w 1), or the direction toward the light (w 0)
uniform vec4 u_far_plane; // object space: where the volume is cut; (0, 0, 0, -1): infinity
uniform int u_closed;    // 1: a closed 2-manifold (averted triangles cast nothing)
uniform int u_caps;      // 1: z-fail, with light and far caps
uniform int u_mode;      // 0: sides and caps; 1: light caps of averted triangles only

bool before(vec3 a, vec3 b)
{
    return a.x < b.x || (a.x == b.x && (a.y < b.y || (a.y == b.y && a.z < b.z)));
}

// n . (l - l.w a) > 0, as stin__triangle_faces_light, on the canonical rotation.
bool faces_light(vec3 a, vec3 b, vec3 c)
{
    vec3 p0 = a, p1 = b, p2 = c;
    if (before(b, a) && before(b, c)) {
        p0 = b;
        p1 = c;
        p2 = a;
    } else if (before(c, a) && before(c, b)) {
        p0 = c;
        p1 = a;
        p2 = b;
    }
    vec3 n = cross(p1 - p0, p2 - p0);
    return dot(n, u_light.xyz - u_light.w * p0) > 0.0;
}

// Where the ray from the light through vertex i meets the far plane: with f
// its point at infinity, (plane . f) p - (plane . p) f (the plane (0, 0, 0,
// -1) gives f itself), as src/shadow/volume_geometry.c computes it.
vec4 far_point(int i)
{
    vec4 p = vec4(g_object[i], 1.0);
    vec4 f = vec4(g_object[i] * u_light.w - u_light.xyz, 0.0);
    return u_view_proj * (u_model * (dot(u_far_plane, f) * p - dot(u_far_plane, p) * f));
}

void emit(vec4 clip)
{
    gl_Position = clip;
    EmitVertex();
}

// A light cap lies on the surface it came from, and z-fail must count it as
// behind that surface (the CPU's caps match the lit pass's depths bit for
// bit and fail GL_LESS). Positions that passed through a geometry shader are
// not bit-equal to the lit pass's (measured: lines along a floor's edges),
// so the caps move back by 2^-20 in NDC depth (8 steps of a 24-bit buffer).
const float CAP_BACK = 1.0 / 1048576.0;

void emit_cap(vec4 clip)
{
    emit(vec4(clip.xy, clip.z + CAP_BACK * clip.w, clip.w));
}

void main()
{
    bool facing = faces_light(g_object[0], g_object[2], g_object[4]);
    if (u_mode == 1) {
        if (!facing) { // on its surface: the stored order, as the lit pass drew it
            emit_cap(gl_in[0].gl_Position);
            emit_cap(gl_in[2].gl_Position);
            emit_cap(gl_in[4].gl_Position);
            EndPrimitive();
        }
        return;
    }
    if (!facing && u_closed == 1)
        return; // inside the volume of the light-facing side
    // the triangle oriented toward the light: input vertex of oriented corner k
    int o[3];
    o[0] = 0;
    o[1] = facing ? 2 : 4;
    o[2] = facing ? 4 : 2;
    vec4 fin[3], inf[3];
    for (int k = 0; k < 3; k++) {
        fin[k] = gl_in[o[k]].gl_Position;
        inf[k] = far_point(o[k]);
    }
    if (u_caps == 1) {
        if (facing) {
            emit_cap(fin[0]);
            emit_cap(fin[1]);
            emit_cap(fin[2]);
            EndPrimitive();
        }
        emit(inf[2]);
        emit(inf[1]);
        emit(inf[0]);
        EndPrimitive();
    }
    for (int k = 0; k < 3; k++) {
        int k1 = (k + 1) % 3;
        // the stored edge under oriented edge k (k -> k1): the same one, or
        // with the triangle flipped, stored edge 2 - k reversed
        int s = facing ? k : 2 - k;
        vec3 a = g_object[2 * s], b = g_object[(2 * s + 2) % 6];
        vec3 across = g_object[2 * s + 1], own = g_object[(2 * s + 4) % 6];
        // no neighbour is marked by the triangle's own third vertex; the
        // neighbour's stored order runs the shared edge backwards
        if (across != own && faces_light(b, a, across) == facing)
            continue; // the neighbour's quad would cancel this one
        // the CPU's two triangles (fin k1, fin k, inf k), (fin k1, inf k, inf k1)
        emit(fin[k]);
        emit(inf[k]);
        emit(fin[k1]);
        emit(inf[k1]);
        EndPrimitive();
    }
}
