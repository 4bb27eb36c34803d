#version 150
// SPDX-License-Identifier: MIT
// The GPU CSG resolve's snap (src/csg/merge.c): a product's face
// fragment is kept only where it lies on the resolved surface (within a
// band of the result, or in a direct resolve of the candidate taken), so
// the frame's depth gets the face's own depth, sample by sample.
uniform sampler2D u_result; // that depth (texel = window pixel)
uniform sampler2D u_ids;    // the id pass's: the face set on the result at each pixel centre
uniform vec4 u_params;      // x: the band; y: its growth by 1 / w (near-cut faces); zw: unused here
// x: the band's growth by the face's depth change over a pixel (a
// multisampled target: a fragment of a triangle that covers samples but
// not the centre has its plane's depth there, not the depth of the
// triangle the resolve rasterised there); y: 1 where a pixel whose centre
// shows no surface (a silhouette) keeps the face where its plane meets a
// neighbouring pixel's surface at that pixel's centre; z: this face set's
// id (1..65535), written as the colour (the id pass); w: 1 where the
// surface must also be this face set's (u_ids)
uniform vec4 u_samples;
out vec4 o_id;

float id_of(vec4 c)
{
    return floor(c.r * 255.0 + 0.5) * 256.0 + floor(c.g * 255.0 + 0.5);
}

// 0 (scs's term where no plain primitive drew) and the far plane (a
// candidate's lost pixels) hold no surface
bool holds(float r) { return r > 0.0 && r < 1.0; }

bool on_surface(ivec2 q, float z, float band)
{
    float r = texelFetch(u_result, q, 0).r;
    return holds(r) && abs(z - r) <= band &&
           (u_samples.w == 0.0 || id_of(texelFetch(u_ids, q, 0)) == u_samples.z);
}

void main()
{
    float z = gl_FragCoord.z;
    vec2 slope = vec2(dFdx(z), dFdy(z)); // before any branch: derivatives
    float band = u_params.x + u_params.y * gl_FragCoord.w +
                 u_samples.x * (abs(slope.x) + abs(slope.y));
    ivec2 p = ivec2(gl_FragCoord.xy);
    o_id = vec4(floor(u_samples.z / 256.0) / 255.0, mod(u_samples.z, 256.0) / 255.0, 0.0, 1.0);
    if (on_surface(p, z, band))
        return;
    if (u_samples.y == 0.0 || holds(texelFetch(u_result, p, 0).r))
        discard; // the centre's surface is another face's: it decides the pixel
    ivec2 last = textureSize(u_result, 0) - 1;
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++)
            if (on_surface(clamp(p + ivec2(dx, dy), ivec2(0), last),
                           z + slope.x * float(dx) + slope.y * float(dy), band))
                return;
    discard;
}
