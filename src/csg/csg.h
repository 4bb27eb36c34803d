/* SPDX-License-Identifier: MIT */
/* CSG products of a frame (csg/csg.c: stin_draw_csg and its checks;
 * csg/normal_form.c: the expression as Goldfeather's sum of products). */
#ifndef STIN_CSG_H
#define STIN_CSG_H

#include "stin/stin.h"
#include "render/path.h"
#include "render/casters.h"
#include "gl/pass_state.h"

/* Literals (STIN__CSG_LITERAL) are render/casters.h's: the interface that
 * hands the products down to the shadow techniques reads them too. */
#define STIN__CSG_MAX_NODES 65536u
#define STIN__CSG_MAX_DEPTH 1024u
/* Steps of one normalisation: a node visited (a shared subtree is expanded
 * at every use), and per pair of terms crossed one and the literals of both
 * (a cross product of two long lists may leave nothing: a union doubled L
 * times, crossed with its complement, would take 4^L). */
#define STIN__CSG_MAX_WORK (1u << 24)

typedef struct stin__csg_term {
    uint32_t first, count;   /* literals[first .. first + count), sorted, each primitive once */
} stin__csg_term;

typedef struct stin__csg_product {
    uint32_t first_primitive, primitive_count; /* in the frame's primitive list */
    uint32_t first_term, term_count;
    int capped;               /* the resolve kept its near-plane cap somewhere */
} stin__csg_product;

/* One resolve's candidates and result (csg/pixels.c carves them;
 * csg/merge.c keeps them): on the CPU, arrays in the staging filled by
 * read-backs; on the GPU (gpu set: the frame's resolve on GLSL tiers with
 * FBOs and depth textures), depth textures, result and candidate NULL. */
typedef struct stin__csg_pixels {
    float *result;            /* nearest surviving depth per pixel */
    float *candidate;         /* this layer's depth; > 1 where it lost */
    unsigned char *stencil;   /* a stencil read back (interval's walk too) */
    int x, y, w, h;
    size_t pixels;
    int bits;                 /* stencil bits used (at most 8) */
    int gpu;                  /* kept on the GPU (csg/merge.c) */
} stin__csg_pixels;

/* desc.csg.interval_layers at most (csg/interval.c). */
#define STIN__CSG_INTERVAL_MAX_LAYERS 16u

/* The module's state in the caller's block (frame/modules.c's slot): its
 * size for the desc, and its arrays laid out behind it (csg/csg.c). */
size_t stin__csg_state_bytes(const stin_desc *d);
void stin__csg_state_place(void *state, const stin_desc *d);
/* At stin_begin_frame: no products, nothing resolved. */
void stin__csg_frame_begin(struct stin_context *ctx);
/* The products drawn into the frame so far. */
uint32_t stin__csg_product_count(const struct stin_context *ctx);

/* Where the normal form goes and how much room is left. */
typedef struct stin__csg_out {
    stin__csg_term *terms;
    uint32_t max_terms, term_count;
    uint32_t *literals;
    uint32_t max_literals, literal_count;
    uint32_t literal_base;    /* added to each term's `first` (the store's offset) */
    uint32_t scratch_peak;    /* words of scratch the normalisation used at most */
} stin__csg_out;

typedef enum stin__csg_nf_result {
    STIN__CSG_NF_OK = 0,
    STIN__CSG_NF_TERMS,       /* more terms than out->max_terms */
    STIN__CSG_NF_LITERALS,    /* more literals than out->max_literals */
    STIN__CSG_NF_SCRATCH,     /* intermediate forms outgrew the scratch */
    STIN__CSG_NF_DEPTH,       /* nested deeper than STIN__CSG_MAX_DEPTH */
    STIN__CSG_NF_WORK         /* more than STIN__CSG_MAX_WORK steps */
} stin__csg_nf_result;

/* The normal form of nodes[node_count - 1] (nodes already checked: ops
 * known, operands before their node, primitive indices in range) into out.
 * Pure: no context, no GL. On failure out's counts are left at 0. With
 * out->terms NULL it only counts (term_count, literal_count: no limits). */
stin__csg_nf_result stin__csg_normal_form(const stin_csg_node *nodes, uint32_t node_count,
                                          uint32_t *scratch, uint32_t scratch_words,
                                          stin__csg_out *out);

/* The resolve (csg/resolve.c): the frame's products into its depth
 * buffer (after the target's clear, before the ambient pass); 0 when it
 * cannot (logged once): the products are not drawn. depth_again puts the
 * resolved depth into the bound framebuffer too, depth LESS (the screen
 * mask's copy of the frame's depth). */
/* At stin_create after the lighting and shadows: on a core profile the
 * depth program (GL4 lighting), else csg-off (demoted, logged). */
void stin__csg_init(struct stin_context *ctx);
void stin__csg_release(struct stin_context *ctx);
int stin__csg_resolve(struct stin_context *ctx, const stin__path *path);
void stin__csg_depth_again(struct stin_context *ctx, const stin__path *path);
/* GL4: a texture of the resolved depth (its r), left bound on unit 0; 0
 * when this frame resolved nothing. origin: the window pixel of its texel
 * (0, 0) (the viewport's corner for the CPU resolve's R32F copy, (0, 0)
 * for the GPU resolve's depth texture). */
GLuint stin__csg_depth_texture(struct stin_context *ctx, int origin[2]);
/* The band around the resolved depth within which face d's fragment lies
 * on the resolved surface (render/resolved.h; csg/merge.c). */
void stin__csg_snap_band(const struct stin_context *ctx, const stin__draw *d, float band[2]);
/* The faces of the resolved products as draws (csg/csg.c), after the
 * resolve; face_list: them (the render passes' stin__resolved faces hook). */
void stin__csg_faces(struct stin_context *ctx);
const stin__draw *stin__csg_face_list(const struct stin_context *ctx, uint32_t *count);
/* The frame's products as the shadow techniques walk them (render/casters.h:
 * the product and term hooks). */
int stin__csg_caster_product(const struct stin_context *ctx, uint32_t i,
                             stin__caster_product *out);
const uint32_t *stin__csg_caster_term(const struct stin_context *ctx,
                                      const stin__caster_product *p, uint32_t t,
                                      uint32_t *count);
/* Around a face draw of a path's pass: depth LESS becomes EQUAL, the face
 * culled that the draw does not show (skipped, returning 0, in map-depth's
 * pass for the back sides the eye sees); end restores the pass state. */
int stin__csg_face_begin(struct stin_context *ctx, const stin__draw *d, stin__pass_state *saved);
void stin__csg_face_end(struct stin_context *ctx, const stin__pass_state *saved);

/* The near and far planes (csg/near.c). The cap lies at window depth
 * STIN__CSG_CAP_DEPTH (2^-10: just behind the near plane, far from any
 * other surface's depth). */
#define STIN__CSG_CAP_DEPTH (1.0f / 1024.0f)
void stin__csg_cap_init(struct stin_context *ctx);
/* 0 when the frame's camera has no usable cap plane (singular). */
int stin__csg_cap_transform(const struct stin_context *ctx, float out[16]);
/* Whether the frame's near and far planes cut d's bounding box. */
void stin__csg_planes_cut(const struct stin_context *ctx, const stin__draw *d, int *near_cut,
                          int *far_cut);
/* The same, and the largest clip coordinate of d's bounding box's corners
 * (the scale of the clipper's rounding where the near plane cuts d). */
void stin__csg_clip_extent(const struct stin_context *ctx, const stin__draw *d, int *near_cut,
                           int *far_cut, float *reach);
/* Every product resolved into r in the bound framebuffer, with the
 * current camera (ctx->frame.view, projection, view_proj, viewport), each
 * by the chain's first method that takes it (csg/resolve.c). */
void stin__csg_resolve_pixels(struct stin_context *ctx, const stin__path *path,
                              stin__csg_pixels *r);

/* The resolve's pixels (csg/pixels.c). bytes: what the CPU's need for w x
 * h. at: the CPU's for the viewport at `offset` bytes into the staging;
 * gpu: the GPU resolve's (the stencil read alone); 0 when it has not the
 * room. read_depth, read_stencil (inside stin__pack_begin): the bound
 * framebuffer's in the resolve's region into r's arrays. write_depth: r's
 * result into the bound depth buffer (func: the depth test). upload_result:
 * r's result into the core profiles' R32F texture, left bound on unit 0. */
size_t stin__csg_pixels_bytes(int w, int h);
int stin__csg_pixels_at(struct stin_context *ctx, size_t offset, stin__csg_pixels *r);
int stin__csg_pixels_gpu(struct stin_context *ctx, stin__csg_pixels *r);
float *stin__csg_pixels_held(struct stin_context *ctx, const stin__csg_pixels *r);
/* The read-back resolve into a multisampled framebuffer object
 * (csg/resolve_msaa.c): ready: whether the context has what it needs (else
 * stin_draw_csg refuses the product); resolve: the frame's products through
 * a single-sampled copy of its depth, their faces drawn into the frame on
 * the result so each sample takes its own face's depth; 0 when it cannot
 * (logged once). */
int stin__csg_msaa_readback_ready(const struct stin_context *ctx);
int stin__csg_msaa_resolve(struct stin_context *ctx, const stin__path *path,
                           stin__csg_pixels *r);
void stin__csg_read_depth(struct stin_context *ctx, const stin__csg_pixels *r, float *out);
void stin__csg_read_stencil(struct stin_context *ctx, const stin__csg_pixels *r);
void stin__csg_write_depth(struct stin_context *ctx, const stin__path *path,
                           const stin__csg_pixels *r, GLenum func);
/* identity: identity matrices and no program around draws in clip
 * coordinates (compatibility contexts). draw_depth_pixels: values into the
 * bound depth buffer by glDrawPixels under pass state ps. */
void stin__csg_identity_begin(struct stin_context *ctx, const stin__path *path);
void stin__csg_identity_end(struct stin_context *ctx, const stin__path *path);
void stin__csg_draw_depth_pixels(struct stin_context *ctx, const stin__path *path,
                                 const stin__csg_pixels *r, const float *values,
                                 const stin__pass_state *ps);
void stin__csg_upload_result(struct stin_context *ctx, const stin__csg_pixels *r);

/* Products casting shadows (csg/cast.c). A map technique calls cast after
 * clearing a light's map (viewport map_vp, in framebuffer map_fbo; in_place:
 * the map is drawn in the frame's own framebuffer, whose stencil the resolve
 * may use) and before drawing the casters with depth LESS: the products'
 * surface seen from the light, pushed back by the light's slope-scaled
 * offset (factor, units as glPolygonOffset), goes into the map's depth.
 * Returns 1 when it drew any. The rectangle goes in bands of the rows the
 * staging holds (without depth read-back, in one: the direct GPU resolve,
 * the map's faces with its offset). cast_again writes the same surface unbiased into the
 * framebuffer `target` (bound; in_place as for cast; viewport map_vp) and
 * draws the primitives there depth EQUAL with the fixed path's current
 * colour state (map-combine's ramp, map-depth's side colours): from the
 * kept pixels where one band held them, else resolving the bands again. */
int stin__csg_cast(struct stin_context *ctx, const stin__path *path, const float view[16],
                   const float proj[16], const int map_vp[4], GLuint map_fbo, int in_place,
                   float factor, float units);
void stin__csg_cast_again(struct stin_context *ctx, const int map_vp[4], GLuint target,
                          int in_place);
void stin__csg_cast_release(struct stin_context *ctx);
/* Logs once per context that the frame's products cast no shadow `why`
 * (a technique or light that does not take them); nothing without
 * products or lights. */
void stin__csg_cast_none(struct stin_context *ctx, const char *why);
/* Whether the frame's products cast at all (there are some, CSG is on and
 * STIN_DEBUG_CSG_NO_CAST is not set). */
int stin__csg_cast_wanted(const struct stin_context *ctx);

/* Goldfeather (csg/goldfeather.c): product p into r's result (csg/merge.c),
 * the chain's last method, which takes any product. Inside the resolve's
 * geometry_begin. Its passes the other methods share: the buffers cleared
 * within the resolve's region (colour writes off), the face a primitive
 * does not show (it shows its front, its back where complemented;
 * mirroring swaps). */
void stin__csg_goldfeather_product(struct stin_context *ctx, const stin__path *path,
                                   stin__csg_pixels *r, stin__csg_product *p);
void stin__csg_clear(struct stin_context *ctx, GLbitfield bits);
GLenum stin__csg_culled_face(const stin__draw *d, int complemented);

/* The window rectangle (normalised device min x, y, max x, y) d's bounding
 * box covers: the part of the box in front of the eye, projected (empty,
 * min > max, where it all lies behind the eye); whether two meet, within a
 * pixel (csg/bounds.c). */
void stin__csg_screen_rect(const struct stin_context *ctx, const stin__draw *d, float rect[4]);
int stin__csg_rects_meet(const struct stin_context *ctx, const float a[4], const float b[4]);
/* A primitive's world-space box (its mesh's bounds through its transform:
 * min x y z, max x y z), and whether two such boxes meet. */
void stin__csg_world_box(const struct stin_context *ctx, const stin__draw *d, float box[6]);
int stin__csg_world_boxes_meet(const float a[6], const float b[6]);
/* Whether the boxes lie apart by more than `units` steps of the target's
 * depth (at least those of a 24-bit buffer) on every ray of the viewport
 * through both: a face of the one never comes within that of a face of the
 * other at a pixel, so the coplanar rules' offsets cannot join them. 0
 * where unsure (a corner at or behind the eye, an oblique projection). */
int stin__csg_world_boxes_apart(const struct stin_context *ctx, const float a[6], const float b[6],
                                float units);
/* The resolve's region (csg/bounds.c). A candidate's surface lies inside
 * its own rectangle and every plain literal's of its term, so on the GPU
 * (where nothing outside is read back) a term's or candidate's passes,
 * clears and quads keep to that rectangle: fill follows the primitives,
 * not the viewport. reset: the whole viewport. narrow: the viewport cut
 * to normalised device rectangle ndc with a pixel's margin; 0 when nothing
 * is left (the candidate covers no pixel). keep_to: a pass state
 * scissored to the region. */
void stin__csg_region_reset(struct stin_context *ctx);
int stin__csg_region_narrow(struct stin_context *ctx, const float ndc[4]);
void stin__csg_region_keep_to(const struct stin_context *ctx, stin__pass_state *ps);
/* The window box (x, y, w, h) within the viewport that holds normalised
 * device rectangle ndc with a pixel's margin; 0 where it is empty. */
int stin__csg_window_box(const struct stin_context *ctx, const float ndc[4], int box[4]);
/* The clip w (the distance along the view) of d's bounding box's nearest
 * corner: a front-to-back key. */
float stin__csg_nearest_w(const struct stin_context *ctx, const stin__draw *d);
/* The eye of the frame's camera in world space; 0 where the projection is
 * orthographic (or singular). */
int stin__csg_eye(const struct stin_context *ctx, float eye[3]);
/* The eye's power with respect to the sphere at d's world box's centre
 * whose squared radius is the mean of the box's squared half-extents (for a
 * sphere mesh, the sphere): its squared distance minus its squared radius.
 * A front-to-back key for scs: where the depth leaves subtracted sphere A
 * inside sphere B, A's power from the eye is below B's, or the depth began
 * inside both (the radical plane between two lies where their powers are
 * equal, and the depth only moves away from the eye). */
float stin__csg_power(const struct stin_context *ctx, const stin__draw *d, const float eye[3]);
/* a = a cut to b (both normalised device min x, y, max x, y; empty: min > max). */
void stin__csg_rect_cut(float a[4], const float b[4]);

/* The resolve's steps on its candidates (csg/merge.c), alike on the CPU
 * and the GPU. A candidate is the depth the bound framebuffer holds.
 * open: the candidate taken up; 0 when no pixel of it can be nearer than
 * the result (known on the CPU only). keep_where: its pixels whose stencil
 * & mask differs from want lose. take: its pixels kept where nearer than
 * the result (where select is not NULL, only the pixels whose interval
 * walk chose layer select->id; in a direct resolve, surface's faces
 * snapped into the frame instead); returns whether any was kept (on the
 * GPU counted by a query where want_kept asks and there are queries, else
 * 1).
 * stencil_max: the largest stencil value over the viewport, or a bound
 * above it no larger than limit (on the GPU from threshold queries). The
 * GPU steps switch programs: path's geometry_begin runs again after them
 * (path NULL: the caller rebinds its own). */
typedef struct stin__csg_select {
    GLuint texture;           /* interval's walk target (R8: layer + 1) */
    int id;
} stin__csg_select;
/* The faces a candidate's depth was drawn from, for the direct resolve
 * (take snaps them into the frame): term t's literals [first, first +
 * count), or where list is not NULL list[0..count), each its shown side
 * (the front of a plain one, the back of a complemented one); or, where
 * cap is not NULL, that draw alone with the side `cap_culled` culled
 * (goldfeather's near-plane cap). */
typedef struct stin__csg_surface {
    const stin__csg_product *p;
    const stin__csg_term *t;
    const uint32_t *list;
    uint32_t first, count;
    const stin__draw *cap;
    GLenum cap_culled;
} stin__csg_surface;
int stin__csg_candidate_open(struct stin_context *ctx, stin__csg_pixels *r);
void stin__csg_candidate_keep_where(struct stin_context *ctx, const stin__path *path,
                                    stin__csg_pixels *r, unsigned mask, unsigned want);
int stin__csg_candidate_take(struct stin_context *ctx, const stin__path *path,
                             stin__csg_pixels *r, const stin__csg_select *select,
                             const stin__csg_surface *surface, int want_kept);
unsigned stin__csg_stencil_max(struct stin_context *ctx, const stin__path *path,
                               stin__csg_pixels *r, unsigned limit);
/* The GPU resolve (csg/merge.c): programs at stin_create (nothing where
 * the tier or context lacks what it needs); begin: its framebuffers grown
 * to the viewport's window size, the result cleared and the work
 * framebuffer bound as the resolve's (0: cannot, logged once: the resolve
 * runs on the CPU); snap: the products' faces (csg/csg.c's list) into the
 * bound framebuffer, depth LESS, where they lie on the result; result: the
 * result's depth texture (texel = window pixel). */
void stin__csg_merge_init(struct stin_context *ctx);
void stin__csg_merge_release(struct stin_context *ctx);
int stin__csg_merge_ready(const struct stin_context *ctx);
int stin__csg_merge_begin(struct stin_context *ctx);
/* The work and result framebuffers (depth-stencil textures at the
 * viewport's window size, FBO and packed depth-stencil caps; the packed
 * resolve's result alone, RGBA8, no framebuffer); 0 when incomplete
 * (logged once). */
int stin__csg_merge_targets(struct stin_context *ctx);
void stin__csg_merge_snap(struct stin_context *ctx);
GLuint stin__csg_merge_result(struct stin_context *ctx);
/* The GPU resolve in place: a frame whose one candidate (one product of one
 * scs term) is resolved in the frame's own depth and stencil, just cleared,
 * needs no work buffer, merge or snap: the faces' depth the lit passes meet
 * is what its passes rasterised there (fits: not into a multisampled
 * framebuffer, whose depth the copy below cannot read). begin: the result
 * texture grown (0: cannot, logged once) and the frame's framebuffer bound
 * as the resolve's; end: its stencil cleared. The passes that draw the products again
 * elsewhere (stin__csg_depth_again, vdsm's position buffer) read the
 * result texture: result_ready copies the frame's depth into it the first
 * time one asks (at end where draw and read bindings are one). Later
 * passes only bring the frame's depth nearer, and where a nearer surface
 * hides a product the snap keeps none of its faces, as the depth test
 * against that surface would not. */
int stin__csg_in_place_fits(const struct stin_context *ctx);
int stin__csg_in_place_begin(struct stin_context *ctx);
void stin__csg_in_place_end(struct stin_context *ctx);
/* The direct GPU resolve: candidates (goldfeather's layers, scs's terms)
 * are found in the work buffer as before, but each is taken by drawing
 * its own faces into the frame, depth LESS, kept within the snap's band of
 * the work buffer's depth: the frame's depth is then the result, holding
 * the faces' own rasterised depth, with no result buffer, merge quads or
 * final snap. The result texture is copied on demand as in place. fits:
 * any frame but interval's (its walk's layers are no one face set) and a
 * multisampled framebuffer (the copy); begin: the work buffer bound (0:
 * cannot, logged once); end: the frame's framebuffer bound again, the
 * scissor off. */
int stin__csg_direct_fits(const struct stin_context *ctx);
int stin__csg_direct_begin(struct stin_context *ctx);
void stin__csg_direct_end(struct stin_context *ctx);
/* The direct resolve from a light (csg/cast.c, on the GPU alone): fits
 * where the GPU resolve runs unpacked and not interval; begin: work
 * framebuffer `work` (depth-stencil texture `texture`, size x size,
 * cleared) bound as the resolve's, each candidate's faces snapped into the
 * map's framebuffer `target` with its polygon offset (factor, units); end:
 * `target` bound again. The frame's own resolve is left as it was. */
int stin__csg_direct_cast_fits(const struct stin_context *ctx);
void stin__csg_direct_cast_begin(struct stin_context *ctx, GLuint work, GLuint texture,
                                 int size, GLuint target, float factor, float units);
void stin__csg_direct_cast_end(struct stin_context *ctx, GLuint target);
void stin__csg_merge_result_ready(struct stin_context *ctx);
/* The packed GPU resolve, where no depth texture exists (bare OpenGL ES
 * 2.0: no depth textures, packed depth-stencil or fragment depth; an FBO's
 * depth and stencil renderbuffers apart are GL_FRAMEBUFFER_UNSUPPORTED on
 * Mesa): the frame's own depth and stencil, just cleared, are the work; each
 * candidate is taken by its own faces, depth EQUAL on it, writing their
 * window depth packed into the frame's colour where nearer than the result
 * so far (an RGBA8 texture, the colour copied into it after each take).
 * packed: this context resolves so; begin: the result grown and cleared to
 * the far plane (0: not a frame it fits, logged once: a caller's contents
 * kept, a multisampled framebuffer); end: the frame's buffers cleared again
 * as the target's clear left them, then the faces snapped onto the result
 * (its depth, not its colour, in the frame). */
int stin__csg_packed(const struct stin_context *ctx);
int stin__csg_packed_begin(struct stin_context *ctx);
void stin__csg_packed_end(struct stin_context *ctx);
/* The side of face draw d its pass culls (csg/csg.c). */
GLenum stin__csg_face_hidden(const stin__draw *d);

/* SCS (csg/scs.c): product p into r's result (csg/merge.c) when the CSG technique is scs
 * and every primitive of p is convex, returning 1; else 0 (logged once per
 * context: goldfeather resolves it). Inside the resolve's geometry_begin. */
int stin__csg_scs_product(struct stin_context *ctx, const stin__path *path, stin__csg_pixels *r,
                          const stin__csg_product *p);
/* Whether scs resolves p (the technique scs, p fit for it). */
int stin__csg_scs_takes(const struct stin_context *ctx, const stin__csg_product *p);

/* Interval (csg/interval.c): product p into r's result (csg/merge.c) when the CSG
 * technique is interval and p fits its limits, returning 1; else 0 (logged
 * once per context: scs or goldfeather resolves it). Inside the resolve's
 * geometry_begin, which it leaves as it found it. */
int stin__csg_interval_product(struct stin_context *ctx, const stin__path *path,
                               stin__csg_pixels *r, stin__csg_product *p);
/* Its programs at stin_create (after stin__csg_init; demotes to scs when
 * they do not build), its GL objects freed at release. */
void stin__csg_interval_init(struct stin_context *ctx);
void stin__csg_interval_release(struct stin_context *ctx);

#endif
