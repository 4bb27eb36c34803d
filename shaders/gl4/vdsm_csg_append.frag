#version 430
// SPDX-License-Identifier: MIT
// vdsm's shadows of CSG products (src/shadow/vdsm_csg.c), first pass: each
// primitive's shadow polygons, and per covered pixel every crossing of its
// segment to the light with the primitive's triangles (vdsm_segment.glsl),
// appended to the pixel's list: the parameter, the primitive, and whether
// the segment enters it there (toward the light). A triangle covered by
// several faces of its volume, or an edge two triangles share, may append
// one crossing twice: the walk (vdsm_csg_walk.frag) counts it once. Nothing
// is drawn (colour writes are off).
layout(std430, binding = 0) coherent buffer vdsm_csg_heads
{
    uint heads[]; // per pixel of the viewport: its first node + 1 (0: none)
};
layout(std430, binding = 1) coherent buffer vdsm_csg_nodes
{
    uint used;     // nodes taken (may pass capacity: the CPU grows the pool)
    uint unused0;
    uint capacity; // nodes the pool holds
    uint unused;
    uvec4 nodes[]; // t's bits, primitive * 2 + entering, next node + 1, unit's bits
};
uniform int u_primitive;  // in its product
uniform int u_mirrored;   // its transform mirrors: the winding turns
uniform ivec4 u_frame;    // the frame's viewport: x, y, width, height
flat in vec3 f_v0;
flat in vec3 f_v1;
flat in vec3 f_v2;

// @chunks

void main()
{
    float t, det, unit;
    ivec2 at = ivec2(gl_FragCoord.xy) - u_frame.xy;
    if (any(lessThan(at, ivec2(0))) || any(greaterThanEqual(at, u_frame.zw)) ||
        !vdsm_segment(f_v0, f_v1, f_v2, t, det, unit))
        return;
    bool enters = (det > 0.0) != (u_mirrored != 0);
    uint i = atomicAdd(used, 1u);
    if (i >= capacity)
        return;
    uint next = atomicExchange(heads[at.y * u_frame.z + at.x], i + 1u);
    nodes[i] = uvec4(floatBitsToUint(t), uint(u_primitive) * 2u + (enters ? 1u : 0u), next,
                     floatBitsToUint(unit));
}
