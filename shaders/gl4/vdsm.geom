#version 150
// SPDX-License-Identifier: MIT
// VDSM shadow polygons (seed 000, step SP): each triangle's volume - the
// region its shadow fills, bounded by the triangle and its three edges
// extruded away from the light to infinity (w = 0) - is drawn as the faces
// the eye sees, so every pixel whose visible surface could lie inside it is
// covered once and the fragment stage decides exactly. The faces are clipped
// in clip space to the viewport (plus a guard pixel: clipping also removes
// what lies behind the eye) and then, for conservative rasterisation, grown
// by u_grow pixels: the Minkowski sum with the pixel square, as the grown
// bounding box cut by every edge moved out by the square's reach. A pixel a
// face covers only in part is then tested too, so no pixel centre is lost to
// rasterisation rules or vertex snapping.
layout(triangles) in;
layout(triangle_strip, max_vertices = 48) out;
in vec3 g_world[];
uniform mat4 u_view_proj;
uniform vec4 u_light;    // world: position (w 1), or the direction toward the light (w 0)
uniform vec4 u_camera;   // world: the eye (w 1), or the direction toward it (w 0)
uniform vec4 u_viewport; // x, y, width, height in pixels
uniform float u_grow;    // pixels every face grows by (0.5: conservative; 0: centres only)
uniform int u_cull_lit;  // EP: drop triangles facing the light (closed meshes)
uniform int u_caps;      // also draw the triangle itself where the eye sees its volume through it
flat out vec3 f_v0;
flat out vec3 f_v1;
flat out vec3 f_v2;

const int CLIP_MAX = 8;  // a quad cut by four planes
const int GROWN_MAX = 12; // a box cut by eight edges

float side(vec4 plane, vec4 x) { return dot(plane.xyz, x.xyz) + plane.w * x.w; }

// The plane through a, b and the homogeneous light.
vec4 light_plane(vec3 a, vec3 b)
{
    vec3 n = cross(b - a, u_light.xyz - a * u_light.w);
    return vec4(n, -dot(n, a));
}

// Away from the light, at infinity.
vec4 extruded(vec3 a) { return vec4(a * u_light.w - u_light.xyz, 0.0); }

void put(vec2 px)
{
    f_v0 = g_world[0];
    f_v1 = g_world[1];
    f_v2 = g_world[2];
    gl_Position = vec4(px / u_viewport.zw * 2.0 - 1.0, 0.0, 1.0);
    EmitVertex();
}

// A convex polygon as one strip, alternating from both ends.
void put_polygon(vec2 p[GROWN_MAX], int n)
{
    if (n < 3)
        return;
    int i = 1, j = n - 1;
    put(p[0]);
    while (true) {
        put(p[i++]);
        if (i > j)
            break;
        put(p[j--]);
        if (i > j)
            break;
    }
    EndPrimitive();
}

// Keeps the part of polygon c with dot(plane, c) >= 0.
int clip4(inout vec4 c[CLIP_MAX], int n, vec4 plane)
{
    vec4 o[CLIP_MAX];
    int m = 0;
    for (int i = 0; i < n; i++) {
        vec4 a = c[i], b = c[i + 1 < n ? i + 1 : 0];
        float da = dot(plane, a), db = dot(plane, b);
        if (da >= 0.0 && m < CLIP_MAX)
            o[m++] = a;
        if ((da >= 0.0) != (db >= 0.0) && m < CLIP_MAX)
            o[m++] = mix(a, b, da / (da - db));
    }
    for (int i = 0; i < m; i++)
        c[i] = o[i];
    return m;
}

// Keeps the part of polygon p with dot(line.xy, p) + line.z >= 0.
int clip2(inout vec2 p[GROWN_MAX], int n, vec3 line)
{
    vec2 o[GROWN_MAX];
    int m = 0;
    for (int i = 0; i < n; i++) {
        vec2 a = p[i], b = p[i + 1 < n ? i + 1 : 0];
        float da = dot(line.xy, a) + line.z, db = dot(line.xy, b) + line.z;
        if (da >= 0.0 && m < GROWN_MAX)
            o[m++] = a;
        if ((da >= 0.0) != (db >= 0.0) && m < GROWN_MAX)
            o[m++] = mix(a, b, da / (da - db));
    }
    for (int i = 0; i < m; i++)
        p[i] = o[i];
    return m;
}

// A face given by n homogeneous world points (3 or 4): clipped, grown, drawn.
void put_face(vec4 w[4], int n)
{
    vec4 c[CLIP_MAX];
    for (int i = 0; i < n; i++)
        c[i] = u_view_proj * w[i];
    // the guard: one pixel and the growth beyond the viewport's edges
    vec2 g = vec2(1.0) + 2.0 * (u_grow + 1.0) / u_viewport.zw;
    n = clip4(c, n, vec4(-1.0, 0.0, 0.0, g.x));
    n = clip4(c, n, vec4(1.0, 0.0, 0.0, g.x));
    n = clip4(c, n, vec4(0.0, -1.0, 0.0, g.y));
    n = clip4(c, n, vec4(0.0, 1.0, 0.0, g.y));
    if (n < 3)
        return;
    vec2 q[GROWN_MAX];
    vec2 lo = vec2(3.4e38), hi = vec2(-3.4e38);
    float area = 0.0;
    for (int i = 0; i < n; i++) {
        q[i] = (c[i].xy / max(c[i].w, 1e-30) * 0.5 + 0.5) * u_viewport.zw;
        lo = min(lo, q[i]);
        hi = max(hi, q[i]);
    }
    if (u_grow <= 0.0) {
        put_polygon(q, n);
        return;
    }
    for (int i = 0; i < n; i++) {
        vec2 a = q[i], b = q[i + 1 < n ? i + 1 : 0];
        area += a.x * b.y - b.x * a.y;
    }
    float turn = area >= 0.0 ? 1.0 : -1.0;
    vec2 r[GROWN_MAX];
    r[0] = lo - u_grow;
    r[1] = vec2(hi.x + u_grow, lo.y - u_grow);
    r[2] = hi + u_grow;
    r[3] = vec2(lo.x - u_grow, hi.y + u_grow);
    int m = 4;
    for (int i = 0; i < n && m >= 3; i++) {
        vec2 a = q[i], b = q[i + 1 < n ? i + 1 : 0];
        vec2 out_n = turn * vec2(b.y - a.y, a.x - b.x); // outward for this winding
        if (out_n == vec2(0.0))
            continue;
        float reach = u_grow * (abs(out_n.x) + abs(out_n.y));
        m = clip2(r, m, vec3(-out_n, dot(out_n, a) + reach));
    }
    put_polygon(r, m);
}

void main()
{
    vec3 v[3] = vec3[3](g_world[0], g_world[1], g_world[2]);
    vec3 nc = cross(v[1] - v[0], v[2] - v[0]);
    vec4 cap = vec4(nc, -dot(nc, v[0]));
    float lit = side(cap, u_light);
    // No area, or edge-on to the light: no shadow of its own (its neighbours cast it).
    if (lit == 0.0 || dot(nc, nc) == 0.0)
        return;
    if (u_cull_lit != 0 && lit > 0.0)
        return;
    // The volume's faces, oriented so the triangle is inside each.
    vec4 faces[3];
    bool eye_inside = side(cap, u_camera) * lit < 0.0;
    for (int e = 0; e < 3; e++) {
        vec4 f = light_plane(v[e], v[e < 2 ? e + 1 : 0]);
        if (side(f, vec4(v[e < 1 ? e + 2 : e - 1], 1.0)) < 0.0)
            f = -f;
        faces[e] = f;
        if (side(f, u_camera) < 0.0)
            eye_inside = false;
    }
    vec2 screen[GROWN_MAX];
    if (eye_inside) { // every pixel may be in it: the whole viewport
        screen[0] = vec2(0.0);
        screen[1] = vec2(u_viewport.z, 0.0);
        screen[2] = u_viewport.zw;
        screen[3] = vec2(0.0, u_viewport.w);
        put_polygon(screen, 4);
        return;
    }
    vec4 w[4];
    for (int e = 0; e < 3; e++) {
        if (side(faces[e], u_camera) > 0.0)
            continue; // the eye is on the inner side: a face it sees from within
        vec3 a = v[e], b = v[e < 2 ? e + 1 : 0];
        w[0] = vec4(a, 1.0);
        w[1] = vec4(b, 1.0);
        w[2] = extruded(b);
        w[3] = extruded(a);
        put_face(w, 4);
    }
    // The triangle itself: where the eye looks into the volume through it,
    // what it sees there lies behind the triangle and is hidden by it, unless
    // the triangle is not in the depth buffer (blended) or lies before the
    // near plane.
    if (side(cap, u_camera) * lit > 0.0) {
        bool near_cut = false;
        for (int i = 0; i < 3; i++) {
            vec4 c = u_view_proj * vec4(v[i], 1.0);
            near_cut = near_cut || c.z < -c.w;
        }
        if (u_caps != 0 || near_cut) {
            w[0] = vec4(v[0], 1.0);
            w[1] = vec4(v[1], 1.0);
            w[2] = vec4(v[2], 1.0);
            put_face(w, 3);
        }
    }
}
