#version 430
// SPDX-License-Identifier: MIT
// vdsm's shadows of CSG products (src/shadow/vdsm_csg.c), second pass: per
// pixel, the crossings vdsm_csg_append.frag listed, walked in order from
// the light back to the surface. The light's own place (inside a primitive
// or not: found on the CPU) is where the walk starts; a crossing where the
// segment enters a primitive toward the light leaves it on the way back,
// one where it leaves enters it. Crossings within a hair of each other
// (2^-16 of their distance, plus 2^-16 of the point's size) are one step:
// duplicates count once, a primitive both entered and left there (a
// silhouette the segment grazes, a wall thinner than the hair) keeps its
// state, and primitives sharing a face's plane cross it together (the CSG
// coplanar rule). The point is in the product's shadow where the product's
// normal form holds anywhere along the way: then 0 goes into the light's
// mask channel, else the fragment is discarded. The walk empties the
// pixel's list for the next product (u_clear: only that).
layout(std430, binding = 0) coherent buffer vdsm_csg_heads
{
    uint heads[];
};
layout(std430, binding = 1) coherent buffer vdsm_csg_nodes
{
    uint used;
    uint unused0;
    uint capacity;
    uint unused;
    uvec4 nodes[];
};
layout(std430, binding = 2) readonly buffer vdsm_csg_terms
{
    uvec4 masks[]; // term j: masks[2j] its plain primitives, masks[2j + 1] its complemented
};
uniform int u_terms;
uniform uvec4 u_light_inside; // the primitives the light lies inside (a bit each)
uniform ivec4 u_frame;    // the frame's viewport: x, y, width, height
uniform int u_clear;
out vec4 frag_color;

bool product_holds(uvec4 inside)
{
    for (int j = 0; j < u_terms; j++) {
        uvec4 plain = masks[2 * j], complemented = masks[2 * j + 1];
        if ((inside & plain) == plain && (inside & complemented) == uvec4(0u))
            return true;
    }
    return false;
}

void main()
{
    ivec2 at = ivec2(gl_FragCoord.xy) - u_frame.xy;
    if (any(lessThan(at, ivec2(0))) || any(greaterThanEqual(at, u_frame.zw)))
        discard;
    int pixel = at.y * u_frame.z + at.x;
    uint head = heads[pixel];
    heads[pixel] = 0u;
    if (u_clear != 0 || head == 0u)
        discard;
    // No list is copied or sorted in place (it has no bound): each step
    // finds the farthest crossing left by a pass over the list and takes
    // every crossing within the hair of it by another.
    float unit = uintBitsToFloat(nodes[head - 1u].w);
    uvec4 inside = u_light_inside;
    bool shadow = product_holds(inside);
    float bound = 3.4e38; // crossings at or beyond it are walked
    while (!shadow) {
        float first = -1.0;
        for (uint i = head; i != 0u; i = nodes[i - 1u].z) {
            float t = uintBitsToFloat(nodes[i - 1u].x);
            if (t < bound)
                first = max(first, t);
        }
        if (first < 0.0)
            break;
        float low = first - 1.52587890625e-5 * (first + unit);
        uvec4 enter = uvec4(0u), leave = uvec4(0u);
        for (uint i = head; i != 0u; i = nodes[i - 1u].z) {
            uvec4 node = nodes[i - 1u];
            float t = uintBitsToFloat(node.x);
            if (t < bound && t >= low) {
                uint primitive = node.y >> 1;
                uvec4 bit = uvec4(0u);
                bit[primitive >> 5] = 1u << (primitive & 31u);
                if ((node.y & 1u) != 0u)
                    leave |= bit; // entered toward the light: left on the way back
                else
                    enter |= bit;
            }
        }
        uvec4 both = enter & leave;
        inside = (inside | (enter & ~both)) & ~(leave & ~both);
        shadow = product_holds(inside);
        bound = low;
    }
    if (!shadow)
        discard;
    frag_color = vec4(0.0);
}
