/* SPDX-License-Identifier: MIT */
/* CSG's own state: only the files of src/csg/ include this header
 * (tools/check-layers.sh). The cast and interval parts are their own
 * files' (csg/cast.c, csg/interval.c), laid out behind this struct; the
 * merge's stays here for the unit tests, which watch its framebuffers. */
#ifndef STIN_CSG_PRIVATE_H
#define STIN_CSG_PRIVATE_H

#include "internal.h"

struct stin__csg_cast_state;
struct stin__csg_interval_state;

/* Stencil thresholds the GPU resolve counts in occlusion queries to learn
 * a stencil's largest value without reading it (csg/merge.c): 1..16, 32,
 * 64, 128, 255; one query more tells whether a candidate kept a pixel. */
#define STIN__CSG_MERGE_THRESHOLDS 20
enum { STIN__CSG_MERGE_WORK, STIN__CSG_MERGE_RESULT };
typedef struct stin__csg_merge_state {
    GLuint merge_prog, kill_prog, snap_prog;
    GLint u_depth, u_select, u_params;
    GLint snap_model, snap_view_proj, snap_result, snap_params, snap_samples, snap_ids;
    stin__displace_locs snap_displace;
    GLuint fbo[2], texture[2]; /* work (depth-stencil), result (depth) */
    GLenum format;
    int width, height;        /* grown to the largest viewport window so far */
    size_t bytes;
    GLuint queries[STIN__CSG_MERGE_THRESHOLDS + 1]; /* 0: no occlusion queries */
    int said_failed;
    /* a multisampled frame's snap: which face set lies on the result at
     * each pixel centre (RGBA8, the targets' size; made at the first such
     * frame, grown, never shrunk); ids_done: this resolve's are drawn */
    GLuint id_fbo, id_texture;
    int id_width, id_height, ids_done, said_ids_failed;
    /* the packed resolve (no depth textures: bare OpenGL ES 2.0): the
     * frame's own buffers are the work, the result is texture[RESULT]
     * (RGBA8, a window depth packed), no framebuffer of its own */
    int packed, said_packed;
    /* a direct resolve's take: the framebuffer each candidate's faces are
     * snapped into (the frame's, or a light's map: csg/cast.c), the work
     * texture they are kept on (texel = window pixel) and its size, and
     * the polygon offset (factor, units) they take there (a map's; 0, 0) */
    GLuint direct_target, direct_work;
    int direct_width, direct_height;
    float direct_offset[2];
} stin__csg_merge_state;

/* The frame's products, laid out by stin__csg_state_place behind the
 * struct in the caller's block (sizes from the desc). */
typedef struct stin__csg_state {
    stin__draw *primitives;   /* csg.max_primitives: mesh, transform, material each */
    stin__csg_product *products; /* csg.max_terms (a product has at least one term) */
    stin__csg_term *terms;    /* csg.max_terms */
    uint32_t *literals;       /* csg.max_literals */
    uint32_t *scratch;        /* normalisation, scratch_words */
    uint32_t scratch_words;
    uint32_t primitive_count, product_count, term_count, literal_count;
    stin__draw *faces;        /* 3 csg.max_primitives: the faces the frame's passes draw */
    uint32_t face_count;
    int resolved;             /* this frame's products are in its depth buffer */
    int said_unusable, said_layers, said_planes;
    /* OpenGL ES without NV_read_depth_stencil (WebGL 2): no depth or stencil
     * read-back, so only the GPU resolve runs (csg/resolve.c) */
    int no_readback;
    uint32_t cap_slot;        /* the near-plane cap's mesh (csg/near.c), STIN__NO_SLOT: none */
    float cap_transform[16];  /* this frame's: the cap onto the near plane */
    int cap_usable;
    /* core profiles: the resolved depth goes back through an R32F texture and
     * a program writing gl_FragDepth (made at stin_create; the texture at the
     * first frame, grown, never shrunk) */
    GLuint depth_prog, depth_tex;
    GLint u_depth, u_origin;
    int tex_width, tex_height;
    int said_scs_fallback, said_scs_capped;
    struct stin__csg_cast_state *cast; /* products casting into the lights' maps (csg/cast.c) */
    GLuint resolve_fbo;       /* the framebuffer a resolve runs in (the frame's, or a
                               * light map's: csg/cast.c), bound again by interval */
    struct stin__csg_interval_state *interval; /* csg/interval.c */
    stin__csg_merge_state merge;       /* csg/merge.c */
    int merged;               /* this frame's resolve kept its depth on the GPU */
    int in_place;             /* ... and runs in the frame's own buffers (csg/merge.c) */
    int direct;               /* ... or snaps each candidate into the frame's depth */
    int result_pending;       /* in place: the result texture has yet to take the depth
                               * of pending_fbo (when a pass first asks for it) */
    GLuint pending_fbo;
    int region[4];            /* window x, y, w, h the resolve's passes keep to: the
                               * viewport, or on the GPU the term's or candidate's
                               * rectangle (csg/bounds.c) */
} stin__csg_state;

/* The sizes of the parts csg/cast.c and csg/interval.c keep to themselves. */
size_t stin__csg_cast_state_bytes(void);
size_t stin__csg_interval_state_bytes(void);

#endif
