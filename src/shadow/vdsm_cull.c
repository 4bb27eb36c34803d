/* SPDX-License-Identifier: MIT */
/* VDSM's culling pass. The chain's steps (EP, SM, DC) drop most triangles
 * (the full chain keeps 0.07-0.34 of SP's primitives on the seed's scenes),
 * but in one geometry shader every triangle still runs the shadow
 * polygons' large body, all three side faces and its own: a driver that
 * runs shaders on masked lanes (llvmpipe) pays for all of it, and a GPU
 * sizes the stage's output for 48 vertices. So, per light, a small
 * geometry shader (shaders/gl4/vdsm_cull.geom) decides each triangle, and
 * for each that casts transform feedback writes one point per part of its
 * volume the eye sees - a side face, its own face or the whole viewport:
 * its world corners, DC's clip depth and the part, 48 bytes - into a
 * buffer sized to the frame's casting triangles (at most 4 parts each).
 * The shadow-polygon program (vdsm_fed.geom, 12 vertices out) then draws
 * each point's face in one draw. Where the context has transform feedback
 * objects (GL 4.0) the draw takes its count from the object on the GPU;
 * else a query reads it back (one wait per light). Both passes see the same
 * world points (displaced by the culling pass's vertex stage) and build the
 * same faces, so the mask and the primitives are the one-pass program's
 * (tests/image/vdsm_test.c "vdsm-cull-pass"). Tessellated frames keep the
 * one pass: their triangle count is not known before the draw. */
#include "shadow/vdsm_private.h"

#define BYTES_PER_PART 48u /* three vec4: a corner and one value each */
#define PARTS_PER_TRIANGLE 4u /* three side faces and its own, or the viewport */
#define TRIM_PASSES 60u /* passes over 4x the need before the buffer is given back */
#define TRIM_FLOOR 1024u /* parts the buffer always holds (48 KB) */

void stin__vdsm_cull_release(stin_context *ctx)
{
    stin__vdsm_cull *c = &ctx->vdsm->culling;
    GLuint none = 0;
    stin__vdsm_delete_programs(ctx, &c->cull_prog, &c->fed_prog, &none);
    if (c->buffer)
        GL(ctx, DeleteBuffers)(1, &c->buffer);
    if (c->vao)
        GL(ctx, DeleteVertexArrays)(1, &c->vao);
    if (c->feedback)
        GL(ctx, DeleteTransformFeedbacks)(1, &c->feedback);
    if (c->query)
        GL(ctx, DeleteQueries)(1, &c->query);
    stin__memzero(c, sizeof *c);
}

static GLuint cull_program(stin_context *ctx, char *msg, size_t size)
{
    static const char *const steps[] = {"gl4/vdsm_side.glsl", "gl4/vdsm_cull.glsl",
                                        "gl4/vdsm_volume.glsl", NULL};
    static const char *const kept[] = {"t_v0", "t_v1", "t_v2", NULL};
    stin__program_source src;
    stin__memzero(&src, sizeof src);
    src.vert = "gl4/vdsm.vert";
    src.geom = "gl4/vdsm_cull.geom";
    src.geom_chunks = steps;
    src.feedback = kept;
    return stin__program_build_source(ctx, &src, msg, size);
}

static GLuint fed_program(stin_context *ctx, char *msg, size_t size)
{
    static const char *const volume[] = {"gl4/vdsm_side.glsl", "gl4/vdsm_volume.glsl", NULL};
    static const char *const segment[] = {"gl4/vdsm_segment.glsl", NULL};
    static const char *const inputs[] = {"a_v0", "a_v1", "a_v2", NULL};
    stin__program_source src;
    stin__memzero(&src, sizeof src);
    src.vert = "gl4/vdsm_fed.vert";
    src.attributes = inputs;
    src.geom = "gl4/vdsm_fed.geom";
    src.geom_chunks = volume;
    src.frag = "gl4/vdsm.frag";
    src.frag_chunks = segment;
    return stin__program_build_source(ctx, &src, msg, size);
}

/* The fed pass's arrays: each kept part one vertex of three vec4s. */
static void arrays(stin_context *ctx, stin__vdsm_cull *c)
{
    GLuint i;
    GL(ctx, GenBuffers)(1, &c->buffer);
    GL(ctx, GenVertexArrays)(1, &c->vao);
    GL(ctx, BindVertexArray)(c->vao);
    GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, c->buffer);
    for (i = 0; i < 3; i++) {
        GL(ctx, EnableVertexAttribArray)(i);
        GL(ctx, VertexAttribPointer)(i, 4, GL_FLOAT, GL_FALSE, (GLsizei)BYTES_PER_PART,
                                     (const void *)(size_t)(16u * i));
    }
    GL(ctx, BindVertexArray)(0);
    GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, 0);
    ctx->bound_mesh = 0xffffffffu;
}

void stin__vdsm_cull_init(stin_context *ctx)
{
    stin__vdsm_cull *c = &ctx->vdsm->culling;
    char msg[160];
    stin__memzero(c, sizeof *c);
    msg[0] = '\0';
    c->cull_prog = cull_program(ctx, msg, sizeof msg);
    if (c->cull_prog)
        c->fed_prog = fed_program(ctx, msg, sizeof msg);
    if (!c->fed_prog) {
        stin__vdsm_cull_release(ctx);
        stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                  "vdsm: the culling pass's shaders failed to build (%s): one geometry "
                  "shader culls and draws the shadow polygons", msg);
        return;
    }
    stin__vdsm_polygon_locate(ctx, c->cull_prog, &c->cull);
    stin__vdsm_polygon_locate(ctx, c->fed_prog, &c->fed);
    arrays(ctx, c);
    if (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_TRANSFORM_FEEDBACK))
        GL(ctx, GenTransformFeedbacks)(1, &c->feedback);
    if (!c->feedback || (ctx->desc.debug_flags & STIN_DEBUG_VDSM_COUNT))
        GL(ctx, GenQueries)(1, &c->query);
    c->usable = 1;
}

/* The parts every triangle of the frame's casters may keep. */
static uint64_t parts_needed(const stin_context *ctx)
{
    uint64_t n = 0;
    uint32_t i;
    for (i = 0; i < ctx->draw_count; i++) {
        const stin__draw *d = &ctx->draws[ctx->draw_order[i]];
        if (d->shadow_caster)
            n += PARTS_PER_TRIANGLE * ctx->meshes[d->mesh_slot].triangle_count;
    }
    return n;
}

/* The buffer's store, for n parts and a quarter more (room to grow without
 * a reallocation per frame); 0 where it would pass 2 GB. */
static int allocate(stin_context *ctx, stin__vdsm_cull *c, uint64_t n)
{
    n += n / 4;
    if (n < TRIM_FLOOR)
        n = TRIM_FLOOR;
    if (n * BYTES_PER_PART > 0x7fffffffu)
        return 0;
    GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, c->buffer);
    GL(ctx, BufferData)(GL_ARRAY_BUFFER, (GLsizeiptr)(n * BYTES_PER_PART), NULL,
                        GL_DYNAMIC_COPY);
    GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, 0);
    c->capacity = (uint32_t)n;
    c->oversized = 0;
    return 1;
}

/* Room for every part of every triangle the frame's casters have: grown
 * when a light's pass needs more, given back when TRIM_PASSES passes in a
 * row needed under a quarter of it (a scene that once had many casters
 * does not keep their memory; one that swings between two sizes is not
 * reallocated every frame). 0 where it does not fit. */
static int reserve(stin_context *ctx, stin__vdsm_cull *c)
{
    uint64_t n = parts_needed(ctx);
    if (n > c->capacity)
        return allocate(ctx, c, n);
    if (c->capacity <= TRIM_FLOOR || n * 4 >= c->capacity)
        c->oversized = 0;
    else if (++c->oversized >= TRIM_PASSES)
        allocate(ctx, c, n); /* smaller: it cannot fail */
    return 1;
}

/* The buffer on feedback binding 0, of the feedback object where there is
 * one, else of the default one (bind 0 to give it back). */
static void feedback_target(stin_context *ctx, const stin__vdsm_cull *c, GLuint buffer)
{
    if (c->feedback)
        GL(ctx, BindTransformFeedback)(GL_TRANSFORM_FEEDBACK, buffer ? c->feedback : 0u);
    if (buffer || !c->feedback)
        GL(ctx, BindBufferBase)(GL_TRANSFORM_FEEDBACK_BUFFER, 0, buffer);
    if (!buffer)
        GL(ctx, BindBuffer)(GL_TRANSFORM_FEEDBACK_BUFFER, 0);
}

int stin__vdsm_cull_on(stin_context *ctx)
{
    stin__vdsm_cull *c = &ctx->vdsm->culling;
    if (!c->usable || ctx->vdsm->tess_active || (ctx->desc.debug_flags & STIN_DEBUG_VDSM_ONE_PASS))
        return 0;
    /* drawn from a count it cannot read under a caller's feedback query */
    if (!c->feedback && (ctx->queries_busy & STIN__QUERY_FEEDBACK))
        return 0;
    if (reserve(ctx, c))
        return 1;
    c->usable = 0; /* past 11 million casting triangles */
    stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
              "vdsm: the culling pass's buffer would pass 2 GB: one geometry shader culls "
              "and draws the shadow polygons from now on");
    return 0;
}

int stin__vdsm_cull_pass(stin_context *ctx, const float light[4])
{
    stin__vdsm_cull *c = &ctx->vdsm->culling;
    GLuint kept = 1;
    int counted;
    GL(ctx, UseProgram)(c->cull_prog);
    stin__vdsm_polygon_uniforms(ctx, &c->cull, light);
    feedback_target(ctx, c, c->buffer);
    GL_ENABLE(ctx, GL_RASTERIZER_DISCARD);
    counted = c->query && stin__query_begin(ctx, STIN__QUERY_FEEDBACK,
                                            GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, c->query);
    GL(ctx, BeginTransformFeedback)(GL_POINTS);
    stin__vdsm_draw_casters(ctx, &c->cull);
    GL(ctx, EndTransformFeedback)();
    if (counted) {
        GL(ctx, EndQuery)(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN);
        GL(ctx, GetQueryObjectuiv)(c->query, GL_QUERY_RESULT, &kept);
        c->kept = kept;
        ctx->stats.shadows.vdsm_kept_faces += kept;
    }
    GL_DISABLE(ctx, GL_RASTERIZER_DISCARD);
    feedback_target(ctx, c, 0);
    ctx->stats.shadows.vdsm_cull_passes++;
    ctx->stats.passes++;
    GL(ctx, UseProgram)(c->fed_prog);
    stin__vdsm_polygon_uniforms(ctx, &c->fed, light);
    return kept != 0;
}

void stin__vdsm_cull_draw(stin_context *ctx)
{
    const stin__vdsm_cull *c = &ctx->vdsm->culling;
    GL(ctx, BindVertexArray)(c->vao);
    if (c->feedback)
        GL(ctx, DrawTransformFeedback)(GL_POINTS, c->feedback);
    else
        GL(ctx, DrawArrays)(GL_POINTS, 0, (GLsizei)c->kept);
    GL(ctx, BindVertexArray)(0);
    ctx->bound_mesh = 0xffffffffu;
}
