// SPDX-License-Identifier: MIT
// VDSM shadow polygons (seed 000, step SP): triangle v's volume - the
// region its shadow fills, bounded by the triangle and its three edges
// extruded away from the light to infinity (w = 0), or with DC to the light
// depth `clip` - is drawn as the faces the eye sees, so every pixel whose
// visible surface could lie inside it is covered once and the fragment
// stage decides exactly. The faces are clipped in clip space to the
// viewport (plus a guard pixel: clipping also removes what lies behind the
// eye) and then, for conservative rasterisation, grown to hold the
// Minkowski sum with the pixel square (half side u_grow): every edge moved
// out by the square's reach along its normal, the corners mitred, or
// bevelled by the square's supporting line where they turn by over a right angle. A pixel a face
// covers only in part is then tested too, so no pixel centre is lost to
// rasterisation rules or vertex snapping.
// With u_depth_test each face carries its own depth (the pass tests it,
// LESS, against the visible surface's): a pixel's surface point inside the
// volume lies behind a face the eye sees, where the eye ray enters, so the
// faces behind the surface test nothing. A face with a corner before the
// near plane, or seen edge-on, passes everywhere.
uniform mat4 u_view_proj;
uniform vec4 u_camera;   // world: the eye (w 1), or the direction toward it (w 0)
uniform vec4 u_viewport; // x, y, width, height in pixels
uniform float u_grow;    // pixels every face grows by (0.5: conservative; 0: centres only)
uniform int u_depth_test; // emit each face's window depth (else every face at the near plane)
flat out vec3 f_v0;
flat out vec3 f_v1;
flat out vec3 f_v2;

vec3 tri[3]; // the triangle being drawn

const int CLIP_MAX = 8;  // a quad cut by four planes
const int GROWN_MAX = 12; // its corners, two where bevelled (at most three are)

// The plane through a, b and the homogeneous light.
vec4 light_plane(vec3 a, vec3 b)
{
    vec3 n = cross(b - a, u_light.xyz - a * u_light.w);
    return vec4(n, -dot(n, a));
}

// Away from the light, at infinity.
vec4 extruded(vec3 a) { return vec4(a * u_light.w - u_light.xyz, 0.0); }

// depth: the face's normalised depth over the pixel position,
// dot(depth.xy, px) + depth.z
void put(vec2 px, vec3 depth)
{
    f_v0 = tri[0];
    f_v1 = tri[1];
    f_v2 = tri[2];
    gl_Position = vec4(px / u_viewport.zw * 2.0 - 1.0, dot(depth.xy, px) + depth.z, 1.0);
    EmitVertex();
}

// A convex polygon as one strip, alternating from both ends.
void put_polygon(vec2 p[GROWN_MAX], int n, vec3 depth)
{
    if (n < 3)
        return;
    int i = 1, j = n - 1;
    put(p[0], depth);
    while (true) {
        put(p[i++], depth);
        if (i > j)
            break;
        put(p[j--], depth);
        if (i > j)
            break;
    }
    EndPrimitive();
}

// Where a face passes everywhere: the near plane under the depth test,
// else mid-range (nothing tests it).
vec3 everywhere() { return u_depth_test != 0 ? vec3(0.0, 0.0, -1.0) : vec3(0.0); }

// The face's depth as a function of the pixel position, fitted to its
// clipped corners c (homogeneous) at pixels q: exact, the face being planar;
// the near plane where a corner lies before it (or at the eye) or the face
// is seen edge-on (under a thousandth of a pixel).
vec3 depth_plane(vec4 c[CLIP_MAX], vec2 q[GROWN_MAX], int n)
{
    float z[CLIP_MAX];
    if (u_depth_test == 0)
        return everywhere();
    for (int i = 0; i < n; i++) {
        if (!(c[i].w > 0.0) || c[i].z < -c[i].w)
            return everywhere();
        z[i] = c[i].z / c[i].w;
    }
    int bi = 1, bj = 2;
    float best = 0.0;
    for (int i = 1; i + 1 < n; i++)
        for (int j = i + 1; j < n; j++) {
            vec2 a = q[i] - q[0], b = q[j] - q[0];
            float area = abs(a.x * b.y - a.y * b.x);
            if (area > best) {
                best = area;
                bi = i;
                bj = j;
            }
        }
    if (best < 1e-3)
        return everywhere();
    vec2 a = q[bi] - q[0], b = q[bj] - q[0];
    float det = a.x * b.y - a.y * b.x, za = z[bi] - z[0], zb = z[bj] - z[0];
    vec2 g = vec2(za * b.y - zb * a.y, zb * a.x - za * b.x) / det;
    return vec3(g, z[0] - dot(g, q[0]));
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

// How far the pixel square (half side u_grow) reaches along unit normal n.
float reach(vec2 n) { return u_grow * (abs(n.x) + abs(n.y)); }

// Where the lines a.(x - b) = reach(a) and c.(x - b) = reach(c) meet, for
// unit normals a and c at most a right angle apart. Nearly parallel, the
// lines nearly coincide: the corner goes out along their mean by the larger
// reach and 1e-3 pixels, more than where they meet lies off either line.
vec2 corner(vec2 b, vec2 a, vec2 c)
{
    float ra = reach(a), rc = reach(c), det = a.x * c.y - a.y * c.x;
    if (abs(det) < 1e-3)
        return b + (max(ra, rc) + 1e-3) * normalize(a + c);
    return b + (ra * vec2(c.y, -c.x) - rc * vec2(a.y, -a.x)) / det;
}

// Convex polygon q (n corners, either winding; repeated or collinear
// corners allowed) grown into r to hold its Minkowski sum with the pixel
// square: each edge's line moved out by the square's reach along its
// normal, meeting its neighbour's line; where the corner turns by over a
// right angle, both meet the line the square supports across the corner
// (normal on the bisector) instead of running far out. Every line supports
// the sum, so r holds it. Exterior angles sum to 360 degrees,
// so at most three corners are cut: r has at most n + 3 corners. Returns
// r's corner count.
int grow_polygon(vec2 q[GROWN_MAX], int n, out vec2 r[GROWN_MAX])
{
    vec2 p[GROWN_MAX];
    int k = 0;
    for (int i = 0; i < n; i++) // an edge needs a direction
        if (distance(q[i], q[i > 0 ? i - 1 : n - 1]) > 1e-4)
            p[k++] = q[i];
    if (k < 2) { // a point (or nothing): the pixel square around it
        vec2 c = q[0];
        r[0] = c - u_grow;
        r[1] = c + vec2(u_grow, -u_grow);
        r[2] = c + u_grow;
        r[3] = c + vec2(-u_grow, u_grow);
        return n > 0 ? 4 : 0;
    }
    float area = 0.0;
    for (int i = 0; i < k; i++) {
        vec2 a = p[i], b = p[i + 1 < k ? i + 1 : 0];
        area += a.x * b.y - b.x * a.y;
    }
    float turn = area >= 0.0 ? 1.0 : -1.0; // outward normals for this winding
    int m = 0;
    for (int i = 0; i < k; i++) {
        vec2 a = p[i > 0 ? i - 1 : k - 1], b = p[i], c = p[i + 1 < k ? i + 1 : 0];
        vec2 n1 = turn * normalize(vec2(b.y - a.y, a.x - b.x));
        vec2 n2 = turn * normalize(vec2(c.y - b.y, b.x - c.x));
        if (dot(n1, n2) >= 0.0) {
            if (m < GROWN_MAX)
                r[m++] = corner(b, n1, n2);
        } else if (m + 2 <= GROWN_MAX) {
            // the bisector; near a hairpin (the polygon doubling back) straight on
            vec2 h = n1 + n2;
            vec2 t = dot(h, h) > 1e-4 ? normalize(h) : normalize(b - a);
            r[m++] = corner(b, n1, t);
            r[m++] = corner(b, t, n2);
        }
    }
    return m;
}

// A face given by n homogeneous world points (3 or 4) as the polygon to
// draw, r (returns its corner count, 0: nothing) in pixels, and its depth
// plane: clipped, projected and grown; with `screen`, the whole viewport
// passing everywhere. One function for every part, called once per face:
// where a shader's branches run under a mask (llvmpipe; diverging lanes on
// a GPU) each call site costs every invocation.
int face_polygon(vec4 w[4], int n, bool screen, out vec2 r[GROWN_MAX], out vec3 depth)
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
    vec2 q[GROWN_MAX];
    for (int i = 0; i < n; i++)
        q[i] = (c[i].xy / max(c[i].w, 1e-30) * 0.5 + 0.5) * u_viewport.zw;
    n = n < 3 ? 0 : n;
    depth = n < 3 ? everywhere() : depth_plane(c, q, n);
    int m = n;
    if (u_grow <= 0.0) {
        for (int i = 0; i < n; i++)
            r[i] = q[i];
    } else {
        m = grow_polygon(q, n, r);
    }
    if (screen) {
        r[0] = vec2(0.0);
        r[1] = vec2(u_viewport.z, 0.0);
        r[2] = u_viewport.zw;
        r[3] = vec2(0.0, u_viewport.w);
        m = 4;
        depth = everywhere();
    }
    return m;
}

// The far ends of triangle v's edges: at infinity, or with DC where the
// light depth reaches the clip. The eye beyond that plane would see the far
// cap, which is not drawn: such a volume stays infinite.
void far_ends(vec3 v[3], float clip, out vec4 far[3])
{
    for (int i = 0; i < 3; i++)
        far[i] = extruded(v[i]);
    if (clip >= UNCLIPPED)
        return;
    for (int i = 0; i < 3; i++) {
        vec3 dir = far[i].xyz;
        float rate = dot(u_depth_row.xyz, dir);
        float t = rate > 0.0 ? max(clip - dot(u_depth_row, vec4(v[i], 1.0)), 0.0) / rate : -1.0;
        far[i] = vec4(v[i] + dir * t, 1.0);
        if (t < 0.0)
            clip = UNCLIPPED;
    }
    vec3 fn = cross(far[1].xyz - far[0].xyz, far[2].xyz - far[0].xyz);
    vec4 fp = vec4(fn, -dot(fn, far[0].xyz));
    if (clip >= UNCLIPPED || !(side(fp, u_camera) * side(fp, u_light) > 0.0))
        for (int i = 0; i < 3; i++)
            far[i] = extruded(v[i]);
}

// The parts of triangle v's volume the eye sees, as bits: PART_SIDE << e
// for the face extruded from edge e (v[e], v[e + 1]), PART_OWN for the
// triangle itself, PART_SCREEN for the whole viewport (the eye inside the
// volume: every pixel may be in it). caps: the triangle is not in the depth
// buffer (blended), so its own face counts wherever the eye looks into the
// volume through it.
const int PART_SIDE = 1;
const int PART_OWN = 8;
const int PART_SCREEN = 16;
int vdsm_parts(vec3 v[3], bool caps)
{
    vec3 nc = cross(v[1] - v[0], v[2] - v[0]);
    vec4 cap = vec4(nc, -dot(nc, v[0]));
    float lit = side(cap, u_light);
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
    if (eye_inside)
        return PART_SCREEN;
    int parts = 0;
    for (int e = 0; e < 3; e++) // where the eye is on the inner side, it sees the face from within
        if (!(side(faces[e], u_camera) > 0.0))
            parts |= PART_SIDE << e;
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
        if (caps || near_cut)
            parts |= PART_OWN;
    }
    return parts;
}

// Draws part `part` (one bit of vdsm_parts) of triangle v's volume, whose
// edges end at far.
void vdsm_part(vec3 v[3], vec4 far[3], int part)
{
    tri = v;
    bool own = part == PART_OWN;
    int e = part == PART_SIDE << 1 ? 1 : part == PART_SIDE << 2 ? 2 : 0;
    int f = e < 2 ? e + 1 : 0;
    vec4 w[4];
    w[0] = vec4(own ? v[0] : v[e], 1.0);
    w[1] = vec4(own ? v[1] : v[f], 1.0);
    w[2] = own ? vec4(v[2], 1.0) : far[f];
    w[3] = far[e];
    vec2 r[GROWN_MAX];
    vec3 depth;
    int m = face_polygon(w, own ? 3 : 4, part == PART_SCREEN, r, depth);
    put_polygon(r, m, depth);
}

// Draws every part of triangle v's volume the eye sees.
void vdsm_volume(vec3 v[3], float clip, bool caps)
{
    int parts = vdsm_parts(v, caps);
    vec4 far[3];
    far_ends(v, clip, far);
    for (int k = 0; k < 5; k++)
        if ((parts & (1 << k)) != 0)
            vdsm_part(v, far, 1 << k);
}
