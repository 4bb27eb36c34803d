// SPDX-License-Identifier: MIT
// Displacement "displace", vertex stage (spliced into every vertex shader that
// draws meshes, so every pass moves the same vertices the same way and depth
// EQUAL passes, shadow maps and vdsm see one surface): the world position
// moved along the world normal by h * scale - bias, h the height map's R at
// the vertex's uv, from the mip levels its distance calls for (see stin.h).
// gl4's main files map texture2DLod.
uniform sampler2D u_displace_map; // level 0, or the height map's copy with its mip chain
uniform vec4 u_displace;        // height scale, bias, 1 on / 0 off, guard band (< 0: none)
uniform vec4 u_displace_size;   // map width, height, 1: blend four texels here
uniform mat3 u_displace_normal; // the draw's normal matrix
uniform mat4 u_displace_clip;   // world -> the camera's clip space (the guard band)
uniform vec4 u_displace_lod;    // texels a pixel spans at eye distance 1 (or anywhere: w 0),
                                // the highest level (0: level 0 only), 1 perspective camera
uniform vec3 u_displace_eye;    // the camera's eye (world)

float displace_height_at(vec2 uv, float level)
{
    if (u_displace_size.z == 0.0)
        return texture2DLod(u_displace_map, uv, level).r;
    // bilinear by hand for nearest-only vertex textures: four texels fetched at
    // their centres (where any filter returns the texel) and blended here
    vec2 size = max(floor(u_displace_size.xy / exp2(level)), vec2(1.0));
    vec2 t = uv * size - 0.5;
    vec2 i = floor(t), f = t - i;
    vec2 a = (i + 0.5) / size, b = (i + 1.5) / size;
    float h00 = texture2DLod(u_displace_map, a, level).r;
    float h10 = texture2DLod(u_displace_map, vec2(b.x, a.y), level).r;
    float h01 = texture2DLod(u_displace_map, vec2(a.x, b.y), level).r;
    float h11 = texture2DLod(u_displace_map, b, level).r;
    return mix(mix(h00, h10, f.x), mix(h01, h11, f.x), f.y);
}

// The level from the vertex's linear distance to the eye (texels per pixel
// grow with it), blended between the two levels around it; up close level 0
// alone, as without the chain.
float displace_height(vec2 uv, vec3 world)
{
    if (u_displace_lod.y <= 0.0)
        return displace_height_at(uv, 0.0);
    float spread = u_displace_lod.x * (u_displace_lod.z > 0.0 ? distance(world, u_displace_eye) : 1.0);
    float lod = clamp(log2(max(spread, 1e-20)), 0.0, u_displace_lod.y);
    float lo = floor(lod);
    float h = displace_height_at(uv, lo);
    return lod > lo ? mix(h, displace_height_at(uv, lo + 1.0), lod - lo) : h;
}

vec4 displace_world(vec4 world, vec3 normal, vec2 uv)
{
    if (u_displace.z == 0.0)
        return world;
    if (u_displace.w >= 0.0) { // far outside the view: no fetch (the seed's visibility test)
        vec4 c = u_displace_clip * world;
        if (c.w > 0.0 && any(greaterThan(abs(c.xyz), vec3(c.w * (1.0 + u_displace.w)))))
            return world;
    }
    vec3 n = normalize(u_displace_normal * normal);
    return vec4(world.xyz + n * (displace_height(uv, world.xyz) * u_displace.x - u_displace.y), world.w);
}
