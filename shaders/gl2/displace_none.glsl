// SPDX-License-Identifier: MIT
// No displacement (the context's displacement is off): the vertex stages'
// world position as it is, the same expression as without the chunk.
vec4 displace_world(vec4 world, vec3 normal, vec2 uv)
{
    return world;
}
