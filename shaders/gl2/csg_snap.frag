#version 120
// SPDX-License-Identifier: MIT
// The GPU CSG resolve's snap (src/csg/merge.c): a product's face
// fragment is kept only where it lies on the resolved surface (within a
// band of the result, or in a direct resolve of the candidate taken), so
// the frame's depth gets the face's own depth, sample by sample. Without
// depth textures (bare OpenGL ES 2.0) the result is a window depth packed
// into RGBA8 (pack_depth.glsl), and the same program takes each candidate
// into it (u_samples.y < 0: the packed resolve's take).
uniform sampler2D u_result; // that depth (texel = window pixel)
uniform sampler2D u_ids;    // the id pass's: the face set on the result at each pixel centre
uniform vec4 u_params;      // x: the band; y: its growth by 1 / w (near-cut faces); zw: 1 / texture size
uniform vec4 u_samples;     // as gl4/csg_snap.frag's

// pack_depth.glsl where the result is packed
// @chunks

float result_at(vec2 at)
{
#ifdef STIN_NO_DEPTH_TEXTURE
    return unpack_depth(texture2D(u_result, at * u_params.zw));
#else
    return texture2D(u_result, at * u_params.zw).r;
#endif
}

float id_of(vec4 c)
{
    return floor(c.r * 255.0 + 0.5) * 256.0 + floor(c.g * 255.0 + 0.5);
}

// 0 (scs's term where no plain primitive drew) and the far plane (a
// candidate's lost pixels) hold no surface
bool holds(float r) { return r > 0.0 && r < 1.0; }

// (both textures are the result's size, edge clamped)
bool on_surface(vec2 at, float z, float band)
{
    float r = result_at(at);
    return holds(r) && abs(z - r) <= band &&
           (u_samples.w == 0.0 || id_of(texture2D(u_ids, at * u_params.zw)) == u_samples.z);
}

void main()
{
    float z = gl_FragCoord.z;
#ifdef STIN_NO_DERIVATIVES
    vec2 slope = vec2(0.0); // no slope band (a multisampled target's: ES 2.0 has none)
#else
    vec2 slope = vec2(dFdx(z), dFdy(z)); // before any branch: derivatives
#endif
#ifdef STIN_NO_DEPTH_TEXTURE
    if (u_samples.y < 0.0) { // the take: where the candidate lies nearer than the result so far
        if (z <= 0.0 || z >= result_at(gl_FragCoord.xy))
            discard;
        gl_FragColor = pack_depth(z);
        return;
    }
#endif
    float band = u_params.x + u_params.y * gl_FragCoord.w +
                 u_samples.x * (abs(slope.x) + abs(slope.y));
    gl_FragColor = vec4(floor(u_samples.z / 256.0) / 255.0, mod(u_samples.z, 256.0) / 255.0, 0.0,
                        1.0);
    if (on_surface(gl_FragCoord.xy, z, band))
        return;
    if (u_samples.y == 0.0 || holds(result_at(gl_FragCoord.xy)))
        discard; // the centre's surface is another face's: it decides the pixel
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++) {
            vec2 d = vec2(float(dx), float(dy));
            if (on_surface(gl_FragCoord.xy + d, z + dot(slope, d), band))
                return;
        }
    discard;
}
