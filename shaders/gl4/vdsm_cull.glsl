// SPDX-License-Identifier: MIT
// VDSM's culling steps (seed 000): which triangles cast at all, and where
// DC ends their extrusion. EP drops triangles facing the light (closed
// meshes: the ones behind them cast the same shadow). SM and DC read the
// light-view pyramid (src/shadow/vdsm_pyramid.c) over the triangle's
// footprint in the light's view: SM drops a triangle lying wholly deeper
// than the occluders there (every ray it meets already meets a drawn
// triangle first), DC one with no receiver behind it, and stops the
// extrusion at the deepest receiver there instead of infinity.
uniform int u_cull_lit;  // EP: drop triangles facing the light (closed meshes)
uniform int u_sm;        // SM: cull triangles behind the pyramid's occluders
uniform int u_dc;        // DC: cull triangles with no receiver behind, clip the rest there
uniform mat4 u_light_vp; // world -> the light's clip space (the pyramid's view)
uniform sampler2D u_pyramid; // x: occluder bound (BIG unknown), y: deepest receiver (-BIG none)
uniform float u_pyramid_size; // texels a side of level 0
uniform int u_pyramid_top;    // its coarsest level (1 x 1)

// Texels of the footprint are read this far out of it, against rounding
// between this pass, the light pass and the receivers (texels).
const float FOOTPRINT_MARGIN = 0.05;
// Depths are compared with this relative room.
const float DEPTH_ROOM = 1e-4;

// The pyramid over the triangle's footprint: (occluder bound, deepest
// receiver) of the finest level where it spans at most 2 x 2 texels.
// Returns false where the footprint is not wholly in the map (nothing known).
bool pyramid_read(vec3 v[3], out vec2 r)
{
    vec2 lo = vec2(3.4e38), hi = vec2(-3.4e38);
    for (int i = 0; i < 3; i++) {
        vec4 c = u_light_vp * vec4(v[i], 1.0);
        if (!(c.w > 0.0))
            return false;
        vec2 t = (c.xy / c.w * 0.5 + 0.5) * u_pyramid_size;
        lo = min(lo, t);
        hi = max(hi, t);
    }
    lo -= FOOTPRINT_MARGIN;
    hi += FOOTPRINT_MARGIN;
    if (lo.x < 0.0 || lo.y < 0.0 || hi.x > u_pyramid_size || hi.y > u_pyramid_size)
        return false;
    int level = 0;
    vec2 scale = vec2(1.0);
    ivec2 a = ivec2(floor(lo)), b = ivec2(floor(hi));
    while (level < u_pyramid_top && (b.x - a.x > 1 || b.y - a.y > 1)) {
        level++;
        scale *= 0.5;
        a = ivec2(floor(lo * scale));
        b = ivec2(floor(hi * scale));
    }
    int top = int(u_pyramid_size * scale.x) - 1;
    b = min(b, ivec2(top));
    r = vec2(-3.4e38);
    for (int y = a.y; y <= b.y; y++)
        for (int x = a.x; x <= b.x; x++)
            r = max(r, texelFetch(u_pyramid, ivec2(x, y), level).xy);
    return true;
}

// Whether triangle v casts; clip: the light depth where DC ends its
// extrusion (UNCLIPPED: at infinity).
bool vdsm_casts(vec3 v[3], out float clip)
{
    vec3 nc = cross(v[1] - v[0], v[2] - v[0]);
    float lit = side(vec4(nc, -dot(nc, v[0])), u_light);
    clip = UNCLIPPED;
    // No area, or edge-on to the light: no shadow of its own (its neighbours cast it).
    if (lit == 0.0 || dot(nc, nc) == 0.0)
        return false;
    if (u_cull_lit != 0 && lit > 0.0)
        return false;
    vec2 pyr;
    if ((u_sm != 0 || u_dc != 0) && pyramid_read(v, pyr)) {
        float nearest = 3.4e38;
        for (int i = 0; i < 3; i++)
            nearest = min(nearest, dot(u_depth_row, vec4(v[i], 1.0)));
        if (u_sm != 0 && nearest > pyr.x + DEPTH_ROOM * max(abs(pyr.x), abs(nearest)))
            return false; // behind the occluders all over its footprint
        if (u_dc != 0) {
            clip = pyr.y + DEPTH_ROOM * abs(pyr.y);
            if (clip < nearest)
                return false; // no receiver behind it
        }
    }
    return true;
}
