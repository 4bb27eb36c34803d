// SPDX-License-Identifier: MIT
// Displacement "displace", vertex stage (spliced into every vertex shader that
// draws meshes, so every pass moves the same vertices the same way and depth
// EQUAL passes, shadow maps and vdsm see one surface): the world position
// moved along the world normal by h * scale - bias, h the height map's R at
// the vertex's uv (see stin.h). gl4's main files map texture2DLod.
uniform sampler2D u_displace_map;
uniform vec4 u_displace;        // height scale, bias, 1 on / 0 off, guard band (< 0: none)
uniform vec4 u_displace_size;   // map width, height, 1: blend four texels here
uniform mat3 u_displace_normal; // the draw's normal matrix
uniform mat4 u_displace_clip;   // world -> the camera's clip space (the guard band)

float displace_height(vec2 uv)
{
    if (u_displace_size.z == 0.0)
        return texture2DLod(u_displace_map, uv, 0.0).r;
    // bilinear by hand for nearest-only vertex textures: four texels fetched at
    // their centres (where any filter returns the texel) and blended here
    vec2 t = uv * u_displace_size.xy - 0.5;
    vec2 i = floor(t), f = t - i;
    vec2 a = (i + 0.5) / u_displace_size.xy, b = (i + 1.5) / u_displace_size.xy;
    float h00 = texture2DLod(u_displace_map, a, 0.0).r;
    float h10 = texture2DLod(u_displace_map, vec2(b.x, a.y), 0.0).r;
    float h01 = texture2DLod(u_displace_map, vec2(a.x, b.y), 0.0).r;
    float h11 = texture2DLod(u_displace_map, b, 0.0).r;
    return mix(mix(h00, h10, f.x), mix(h01, h11, f.x), f.y);
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
    return vec4(world.xyz + n * (displace_height(uv) * u_displace.x - u_displace.y), world.w);
}
