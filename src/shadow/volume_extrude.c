/* SPDX-License-Identifier: MIT */
/* Shadow volumes extruded by a geometry shader (GL4; shaders/gl4/
 * volume_extrude.geom): the volume shadow/volume_geometry.c builds on the
 * CPU, made on the GPU from the mesh's static vertex buffer and its
 * GL_TRIANGLES_ADJACENCY indices (assets/mesh_adjacency_buffer.c). On a GPU the CPU
 * build is the cost of the technique: tens of nanoseconds per caster
 * triangle and light, besides streaming the result, which with several
 * lights costs more than the stencil fill. Counting, culling and the z-pass /
 * z-fail choice stay per caster in shadow/volume.c. */
#include "shadow/volume_private.h"

static const stin__uniform_name extrude_uniforms[] = {
    STIN__UNIFORM(struct stin__volume_state, u_model, "u_model"),
    STIN__UNIFORM(struct stin__volume_state, u_view_proj, "u_view_proj"),
    STIN__UNIFORM(struct stin__volume_state, u_light, "u_light"),
    STIN__UNIFORM(struct stin__volume_state, u_far_plane, "u_far_plane"),
    STIN__UNIFORM(struct stin__volume_state, u_closed, "u_closed"),
    STIN__UNIFORM(struct stin__volume_state, u_caps, "u_caps"),
    STIN__UNIFORM(struct stin__volume_state, u_mode, "u_mode"),
};

void stin__volume_extrude_init(stin_context *ctx)
{
    struct stin__volume_state *v = ctx->volume;
    stin__program_source src;
    const char *no_shadow[2];
    char msg[160];
    v->extrude_prog = v->count_query = 0;
    v->cpu_only = 0;
    if (!ctx->volume_vao || !(ctx->caps.present & STIN_CAP_BIT(STIN_CAP_GEOMETRY_SHADER)) ||
        (ctx->desc.debug_flags & STIN_DEBUG_VOLUME_CPU))
        return;
    no_shadow[0] = "gl4/shadow_none.glsl";
    no_shadow[1] = NULL;
    stin__memzero(&src, sizeof src);
    src.vert = "gl4/volume.vert";
    src.geom = "gl4/volume_extrude.geom";
    src.frag = "gl4/flat.frag";
    src.frag_chunks = no_shadow;
    msg[0] = '\0';
    v->extrude_prog = stin__program_build_source(ctx, &src, msg, sizeof msg);
    if (!v->extrude_prog) {
        stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                  "volume: the extrusion shaders failed to build (%s): volumes are built on "
                  "the CPU",
                  msg);
        return;
    }
    STIN__LOCATE(ctx, v->extrude_prog, v, extrude_uniforms);
    v->set_mode = -1;
    if (ctx->desc.debug_flags & STIN_DEBUG_VOLUME_COUNT)
        GL(ctx, GenQueries)(1, &v->count_query);
    stin__mesh_adjacency_use(ctx, "its volumes are built on the CPU");
    stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_TECHNIQUE_SELECTED,
              "volume: extruded by a geometry shader from each mesh's adjacency indices");
}

void stin__volume_extrude_release(stin_context *ctx)
{
    struct stin__volume_state *v = ctx->volume;
    if (v->extrude_prog)
        GL(ctx, DeleteProgram)(v->extrude_prog);
    if (v->count_query)
        GL(ctx, DeleteQueries)(1, &v->count_query);
    v->extrude_prog = v->count_query = 0;
    stin__mesh_adjacency_use(ctx, NULL);
}

int stin__volume_extrude_enable(stin_context *ctx, int on)
{
    ctx->volume->cpu_only = !on;
    return ctx->volume->extrude_prog != 0;
}

static void draw_mode(stin_context *ctx, const stin__mesh_slot *m, int mode)
{
    if (ctx->volume->set_mode != mode)
        GL(ctx, Uniform1i)(ctx->volume->u_mode, ctx->volume->set_mode = mode);
    GL(ctx, DrawElements)(GL_TRIANGLES_ADJACENCY, (GLsizei)(6u * m->triangle_count),
                          m->index_type, NULL);
}

int stin__volume_extrude_draw(stin_context *ctx, const stin__draw *d, const float light_object[4],
                              const float far_plane_object[4], int zfail)
{
    struct stin__volume_state *v = ctx->volume;
    const stin__mesh_slot *m = &ctx->meshes[d->mesh_slot];
    int closed = m->info.closed_manifold != 0, counted;
    if (!v->extrude_prog || !m->adj_vao || v->cpu_only)
        return 0;
    if (!v->path_unbound) { /* the light's first extruded caster, or one after a CPU-built one */
        GL(ctx, UseProgram)(v->extrude_prog);
        GL(ctx, UniformMatrix4fv)(v->u_view_proj, 1, GL_FALSE, ctx->view_proj);
        v->set_closed = v->set_caps = -1;
    }
    GL(ctx, UniformMatrix4fv)(v->u_model, 1, GL_FALSE, d->transform);
    GL(ctx, Uniform4fv)(v->u_light, 1, light_object);
    GL(ctx, Uniform4fv)(v->u_far_plane, 1, far_plane_object);
    if (v->set_closed != closed)
        GL(ctx, Uniform1i)(v->u_closed, v->set_closed = closed);
    if (v->set_caps != zfail)
        GL(ctx, Uniform1i)(v->u_caps, v->set_caps = zfail);
    GL(ctx, BindVertexArray)(m->adj_vao);
    counted = v->count_query && stin__query_begin(ctx, STIN__QUERY_PRIMITIVES,
                                                  GL_PRIMITIVES_GENERATED, v->count_query);
    draw_mode(ctx, m, 0);
    if (zfail && !closed) {
        /* light caps of averted triangles, on the surface they came from:
         * the stored order, counted as the flipped triangle would be */
        stin__pass_state ps = *stin__pass_current(ctx);
        ps.front_face = GL_CW;
        stin__pass_apply(ctx, &ps);
        draw_mode(ctx, m, 1);
        ps.front_face = GL_CCW;
        stin__pass_apply(ctx, &ps);
    }
    if (counted) {
        GLuint n = 0;
        GL(ctx, EndQuery)(GL_PRIMITIVES_GENERATED);
        GL(ctx, GetQueryObjectuiv)(v->count_query, GL_QUERY_RESULT, &n);
        ctx->stats.shadows.volume_triangles += (uint32_t)n;
    }
    ctx->stats.shadows.volume_gpu_casters++;
    return 1;
}
