// SPDX-License-Identifier: MIT
// Shared by the surface chunks "normal", "parallax" and "pom" (spliced in
// before them): the tangent frame, the map from tangent-plane offsets in
// scene units to uv, and the normal-map decode. One file for both tiers: the
// lit.frag of each defines how a sample is taken (SAMPLE_FOOTPRINT: a colour
// map at the unmoved uv's footprint; SAMPLE_LEVEL0: the height field's top
// level, legal inside loops).
uniform sampler2D u_normal_tex;  // unit 1: 128 + 127 n, A = mean-normal length
uniform sampler2D u_height_tex;  // unit 2: height in R, 1 = top, level 0 only
uniform vec4 u_surface;          // height scale, height bias, pom min steps, max steps
uniform int u_self_shadow;       // 0 off, 1 hard, 2 soft
#ifdef STIN_NO_DERIVATIVES
uniform vec4 u_uv_unit;          // xy: the mesh's mean object lengths of a unit of u, of v
#endif
vec3 s_t, s_b, s_n;              // orthonormal tangent frame, B = w * cross(N, T)
vec2 s_au, s_av;                 // uv change per scene unit along T and along B
// screen derivatives of the unmoved uv (set by surface_frame; initialised so
// the compiler sees no read of an unset value on paths it cannot follow)
vec2 s_dx = vec2(0.0), s_dy = vec2(0.0);
float s_depth;                   // pom: depth of the hit, 0..1 of the height scale

// Colour maps at the (moved) uv.
vec4 surface_sample(sampler2D t, vec2 uv)
{
    return SAMPLE_FOOTPRINT(t, uv, s_dx, s_dy);
}

void surface_frame()
{
    vec3 n = normalize(v_normal);
    vec3 t = v_tangent.xyz - n * dot(n, v_tangent.xyz);
    s_n = n;
    s_t = dot(t, t) > 1e-20 ? normalize(t) : normalize(cross(n, abs(n.x) > 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0)));
    s_b = (v_tangent.w < 0.0 ? -1.0 : 1.0) * cross(n, s_t);
#ifdef STIN_NO_DERIVATIVES
    // No derivatives: the uv scale is the mesh's mean length of a unit of u
    // and of v (u_uv_unit) times the model's scale along T (the world
    // tangent's length; B taken as scaled alike): exact for a mapping
    // without skew; colour maps take the moved uv's own footprint.
    vec2 unit = max(length(v_tangent.xyz) * u_uv_unit.xy, vec2(1e-20));
    s_au = vec2(1.0 / unit.x, 0.0);
    s_av = vec2(0.0, 1.0 / unit.y);
#else
    // The surface is affine per triangle: its world and uv derivatives give
    // uv = A (offset . T, offset . B) exactly, whatever the uv scale or skew.
    vec3 px = dFdx(v_world), py = dFdy(v_world);
    s_dx = dFdx(v_uv);
    s_dy = dFdy(v_uv);
    vec2 qx = vec2(dot(px, s_t), dot(px, s_b)), qy = vec2(dot(py, s_t), dot(py, s_b));
    float det = qx.x * qy.y - qy.x * qx.y;
    if (abs(det) > 1e-6 * (dot(qx, qx) + dot(qy, qy))) {
        s_au = (s_dx * qy.y - s_dy * qx.y) / det;
        s_av = (s_dy * qx.x - s_dx * qy.x) / det;
    } else { // seen edge-on: no usable footprint
        s_au = vec2(1.0, 0.0);
        s_av = vec2(0.0, 1.0);
    }
#endif
    s_depth = 0.0;
}

// The tangent-plane offset (scene units along T and B) as a uv offset.
vec2 surface_uv_offset(vec2 d)
{
    return s_au * d.x + s_av * d.y;
}

// The mapped normal at uv in world space; sets s_normal_length (Toksvig).
vec3 surface_map_normal(vec2 uv)
{
    vec4 m = surface_sample(u_normal_tex, uv);
    vec3 d = (m.rgb * 255.0 - 128.0) / 127.0;
    s_normal_length = clamp(m.a, 0.05, 1.0);
    return normalize(s_t * d.x + s_b * d.y + s_n * d.z);
}

float surface_height(vec2 uv)
{
    return SAMPLE_LEVEL0(u_height_tex, uv).r;
}
