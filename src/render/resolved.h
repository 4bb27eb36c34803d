/* SPDX-License-Identifier: MIT */
/* A resolved depth: surfaces a feature puts into the frame's depth itself
 * (the CSG products, csg/goldfeather.c) rather than as draws, whose faces
 * (stin__draw.csg set) the passes draw depth EQUAL on it and whose depth
 * other buffers take again. The frame lends these services through the
 * context (frame/hooks.c), so no pass names the feature; the passes call
 * the wrappers in render/resolved.c, which do nothing where none was lent
 * (then the frame has no such faces and resolved nothing). */
#ifndef STIN_RESOLVED_H
#define STIN_RESOLVED_H

#include "stin/stin.h"
#include "gl/gl_types.h"
#include "gl/pass_state.h"
#include "render/path.h"

typedef struct stin__resolved {
    /* The faces to draw on the resolved depth this frame (count of them;
     * none before the resolve or where it resolved nothing). */
    const stin__draw *(*faces)(const stin_context *ctx, uint32_t *count);
    /* Around a pass's draw of face d: depth LESS becomes EQUAL, the side
     * culled that the draw does not show; 0 when the pass skips it (then
     * no face_end). face_end applies the pass state begin saved. */
    int (*face_begin)(stin_context *ctx, const stin__draw *d, stin__pass_state *saved);
    void (*face_end)(stin_context *ctx, const stin__pass_state *saved);
    /* The resolved depth again into the bound framebuffer, depth LESS
     * against what it holds (a copy of the frame's depth elsewhere). */
    void (*depth_again)(stin_context *ctx, const stin__path *path);
    /* GL4: a texture of the resolved depth (its r), left bound on unit 0;
     * 0 when the frame resolved none. origin: the window pixel of its
     * texel (0, 0). */
    GLuint (*depth_texture)(stin_context *ctx, int origin[2]);
    /* How near face d's fragment must lie to that depth texture's to be
     * on the resolved surface: |z - r| <= band[0] + band[1] / w (w: clip
     * w, the shader's 1 / gl_FragCoord.w). */
    void (*snap_band)(const stin_context *ctx, const stin__draw *d, float band[2]);
} stin__resolved;

const stin__draw *stin__resolved_faces(const stin_context *ctx, uint32_t *count);
int stin__resolved_face_begin(stin_context *ctx, const stin__draw *d, stin__pass_state *saved);
void stin__resolved_face_end(stin_context *ctx, const stin__pass_state *saved);
void stin__resolved_depth_again(stin_context *ctx, const stin__path *path);
GLuint stin__resolved_depth_texture(stin_context *ctx, int origin[2]);
void stin__resolved_snap_band(const stin_context *ctx, const stin__draw *d, float band[2]);

#endif
