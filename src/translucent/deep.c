/* SPDX-License-Identifier: MIT */
/* Deep shadow maps on GL4 ("deep", seed 001).
 *
 * Per light, just before its lit pass: the transparent casters are peeled
 * from the light, layer by layer (Everitt's depth peeling: the depth test
 * LESS finds the nearest surface, the shader discards what the layer before
 * held), into RGBA32F texels of (depth, visibility behind it per channel),
 * eq 5.3 accumulating the visibility from layer to layer. Even layers live in
 * one array texture, odd ones in the other, so a pass never reads what it
 * writes. Spot and directional lights peel one face fitted as the shadow
 * maps are; point lights six 90-degree faces. A face stops at the first
 * layer that drew nothing (later layers would be empty too): on GL 4.3 (the
 * compute capability, with shader storage buffers) the peel shader sets a
 * 4-byte flag read back after the pass, on GL 3.2-4.2 an occlusion query
 * counts the pass's samples; a face no transparent caster's bounding box
 * reaches stops before its first layer (no clear, no draw, no wait). The
 * lookup reads a face's layers up to its first empty one (a uniform per
 * face), so stale texels beyond it are never read and the image is the
 * same with every layer peeled. Opaque casters
 * stay the shadows technique's; the lit programs multiply its visibility by
 * the deep map's (translucent_deep.glsl). */
#include "translucent/translucent_private.h"

#define EMPTY_DEPTH 2.0f /* beyond every window depth: an unused texel */

uint32_t stin__deep_slices(uint32_t layers) { return (layers + 1u) / 2u; }

size_t stin__deep_state_bytes(const stin_desc *d)
{
    (void)d;
    return sizeof(stin__deep_state);
}

static int chosen(const stin_context *ctx)
{
    return ctx->sel.choice[STIN_FEATURE_TRANSLUCENT_SHADOWS].technique == STIN_TECH_TRANSLUCENT_DEEP;
}

/* (Built before the deep set-up: with shadows off it will fall back.) */
const char *stin__deep_chunk(const stin_context *ctx)
{
    return chosen(ctx) && ctx->shadow && ctx->shadow->light ? "translucent_deep.glsl" : NULL;
}

void stin__deep_release(stin_context *ctx)
{
    stin__deep_state *s = ctx->deep;
    if (s->layers[0])
        GL(ctx, DeleteTextures)(2, s->layers);
    if (s->depth)
        GL(ctx, DeleteTextures)(1, &s->depth);
    if (s->fbo)
        GL(ctx, DeleteFramebuffers)(1, &s->fbo);
    if (s->program)
        GL(ctx, DeleteProgram)(s->program);
    if (s->query)
        GL(ctx, DeleteQueries)(1, &s->query);
    if (s->flag)
        GL(ctx, DeleteBuffers)(1, &s->flag);
    stin__memzero(s, sizeof *s);
}

static void nearest_clamped(stin_context *ctx, GLenum target)
{
    GL(ctx, TexParameteri)(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    GL(ctx, TexParameteri)(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    GL(ctx, TexParameteri)(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    GL(ctx, TexParameteri)(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    GL(ctx, TexParameteri)(target, GL_TEXTURE_MAX_LEVEL, 0);
}

/* 1 when the driver takes a layer array of n x n (GL_PROXY_TEXTURE_2D_ARRAY:
 * asks without allocating, raises no GL error and reads none). */
static int driver_takes(stin_context *ctx, GLsizei n, GLsizei slices)
{
    GLint width = 0, layers = 0;
    if (ctx->caps.es) { /* ES has no proxy textures: the limits are all it says */
        GL(ctx, GetIntegerv)(GL_MAX_ARRAY_TEXTURE_LAYERS, &layers);
        return n <= ctx->caps.max_texture_size && slices <= layers;
    }
    GL_ENUM(ctx, TexImage3D, GL_RGBA32F)(GL_PROXY_TEXTURE_2D_ARRAY, 0, GL_RGBA32F, n, n, slices,
                                        0, GL_RGBA, GL_FLOAT, NULL);
    GL(ctx, GetTexLevelParameteriv)(GL_PROXY_TEXTURE_2D_ARRAY, 0, GL_TEXTURE_WIDTH, &width);
    return width == n;
}

/* The largest face size from s->size down that the driver takes (maps of
 * desc.translucent.deep_map_size 4096 take 6.3 GB: allocating them left
 * GL_OUT_OF_MEMORY and no maps); logged when it steps down. 0 if it takes
 * none of MIN_SIZE (or s->size, if smaller) or more. */
#define MIN_SIZE 64u
static uint32_t fit_size(stin_context *ctx)
{
    stin__deep_state *s = ctx->deep;
    GLsizei slices = (GLsizei)(STIN__DEEP_FACES * s->slices);
    uint32_t size = s->size, least = s->size < MIN_SIZE ? s->size : MIN_SIZE;
    while (!driver_takes(ctx, (GLsizei)size, slices)) {
        if (size <= least)
            return 0;
        size /= 2u;
    }
    if (size != s->size)
        stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                  "deep: the driver takes no %u x %u x %d RGBA32F layer array "
                  "(translucent.deep_map_size): the maps are %u x %u",
                  (unsigned)s->size, (unsigned)s->size, (int)slices, (unsigned)size,
                  (unsigned)size);
    return size;
}

/* The textures and the framebuffer; "" or why they cannot be made. */
static const char *make_targets(stin_context *ctx)
{
    stin__deep_state *s = ctx->deep;
    GLsizei n, slices = (GLsizei)(STIN__DEEP_FACES * s->slices);
    GLenum status;
    int i;
    s->size = fit_size(ctx);
    if (!s->size)
        return "the driver takes none of its layer arrays (GL_PROXY_TEXTURE_2D_ARRAY)";
    n = (GLsizei)s->size;
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
    GL(ctx, GenTextures)(2, s->layers);
    for (i = 0; i < 2; i++) {
        GL(ctx, BindTexture)(GL_TEXTURE_2D_ARRAY, s->layers[i]);
        nearest_clamped(ctx, GL_TEXTURE_2D_ARRAY);
        GL_ENUM(ctx, TexImage3D, GL_RGBA32F)(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA32F, n, n, slices, 0,
                                            GL_RGBA, GL_FLOAT, NULL);
    }
    GL(ctx, BindTexture)(GL_TEXTURE_2D_ARRAY, 0);
    GL(ctx, GenTextures)(1, &s->depth);
    stin__rt_texture(ctx, s->depth, GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, n,
                     n);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    GL(ctx, GenFramebuffers)(1, &s->fbo);
    /* the layer before the depth: the service attaches 2D textures only */
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, s->fbo);
    GL(ctx, FramebufferTextureLayer)(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, s->layers[0], 0, 0);
    status = stin__rt_attach(ctx, s->fbo, 0, s->depth, 0);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, 0);
    return status == GL_FRAMEBUFFER_COMPLETE ? "" : "its RGBA32F layer framebuffer is incomplete";
}

/* 1 when the early stop may use the shader storage flag: GL 4.3's compute
 * capability, and no debug flag asking for the query. */
static int flag_wanted(const stin_context *ctx)
{
    return (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_COMPUTE)) &&
           !(ctx->desc.debug_flags & STIN_DEBUG_DEEP_QUERY_STOP);
}

static const stin__uniform_name peel_uniforms[] = {
    STIN__UNIFORM(stin__deep_state, u_model, "u_model"),
    STIN__UNIFORM(stin__deep_state, u_view_proj, "u_view_proj"),
    STIN__UNIFORM(stin__deep_state, u_albedo, "u_albedo"),
    STIN__UNIFORM(stin__deep_state, u_albedo_tex, "u_albedo_tex"),
    STIN__UNIFORM(stin__deep_state, u_has_albedo_tex, "u_has_albedo_tex"),
    STIN__UNIFORM(stin__deep_state, u_previous, "u_previous"),
    STIN__UNIFORM(stin__deep_state, u_previous_slice, "u_previous_slice"),
    STIN__UNIFORM(stin__deep_state, u_mono, "u_mono"),
};

/* The peel program: with the storage flag (deep_peel_flag.frag) where it is
 * wanted and builds, else with the query's (deep_peel.frag). */
static int make_program(stin_context *ctx, char *msg, size_t size)
{
    static const char *const chunks[] = {"gl4/deep_peel_layer.glsl", NULL};
    stin__deep_state *s = ctx->deep;
    stin__program_source src;
    stin__memzero(&src, sizeof src);
    src.vert = "gl4/deep_peel.vert";
    src.frag_chunks = chunks;
    if (flag_wanted(ctx)) {
        src.frag = "gl4/deep_peel_flag.frag";
        s->program = stin__program_build_source(ctx, &src, msg, size);
        if (s->program)
            s->flagged = 1;
        else
            stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_FALLBACK,
                      "deep: the storage-flag peel program failed to build (%s); the early "
                      "stop uses an occlusion query", msg);
        msg[0] = '\0';
    }
    if (!s->program) {
        src.frag = "gl4/deep_peel.frag";
        s->program = stin__program_build_source(ctx, &src, msg, size);
    }
    if (!s->program)
        return 0;
    STIN__LOCATE(ctx, s->program, s, peel_uniforms);
    stin__displace_locate(ctx, s->program, 0, &s->displace);
    return 1;
}

void stin__deep_init(stin_context *ctx)
{
    stin__deep_state *s = ctx->deep;
    char msg[160], why[220];
    const char *fail = "";
    if (!chosen(ctx))
        return;
    stin__memzero(s, sizeof *s);
    s->size = ctx->desc.translucent.deep_map_size;
    if (ctx->caps.max_texture_size > 0 && s->size > (uint32_t)ctx->caps.max_texture_size)
        s->size = (uint32_t)ctx->caps.max_texture_size;
    s->layer_cap = ctx->desc.translucent.deep_layers;
    s->slices = stin__deep_slices(s->layer_cap);
    s->unit = ctx->sel.translucent_unit;
    msg[0] = '\0';
    if (!ctx->shadow->light)
        fail = "shadows are off, so no light is shadowed";
    else if (!stin__gl_available(ctx, STIN_GLFN_TexImage3D) ||
             !stin__gl_available(ctx, STIN_GLFN_FramebufferTextureLayer))
        fail = "glTexImage3D or glFramebufferTextureLayer did not load";
    else if (!make_program(ctx, msg, sizeof msg))
        fail = "its peel program failed to build";
    else
        fail = make_targets(ctx);
    if (fail[0]) {
        stin__formatf(why, sizeof why, "deep: %s%s%s%s", fail, msg[0] ? " (" : "", msg,
                      msg[0] ? ")" : "");
        stin__deep_release(ctx);
        stin__demote_at(ctx, stin__translucent_fallback_level(ctx, !ctx->shadow->light),
                        STIN_FEATURE_TRANSLUCENT_SHADOWS, STIN_TECH_TRANSLUCENT_SOLID, why);
        return;
    }
    if (s->flagged) { /* the early stop's flag: one uint, cleared before each pass */
        static const GLuint zero = 0;
        GL(ctx, GenBuffers)(1, &s->flag);
        GL(ctx, BindBuffer)(GL_SHADER_STORAGE_BUFFER, s->flag);
        GL(ctx, BufferData)(GL_SHADER_STORAGE_BUFFER, (GLsizeiptr)sizeof zero, &zero,
                            GL_DYNAMIC_READ);
        GL(ctx, BindBuffer)(GL_SHADER_STORAGE_BUFFER, 0);
    } else if (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_ANY_SAMPLES_QUERY)) {
        GL(ctx, GenQueries)(1, &s->query);
    }
    s->ready = 1;
}

void stin__deep_uniforms(stin_context *ctx, const stin__program *p)
{
    const stin__deep_state *s = ctx->deep;
    float params[4];
    int i;
    params[0] = (float)s->slices;
    params[1] = (float)s->size;
    params[2] = s->normal_offset;
    params[3] = (float)s->layer_cap;
    if (!stin__translucent_set(ctx, &p->deep, s->kind, &s->matrix[0][0], params))
        return;
    GL(ctx, Uniform1iv)(p->deep.face_layers, STIN__DEEP_FACES, s->face_layers);
    for (i = 0; i < 2; i++)
        stin__bind_unit(ctx, s->unit + i, GL_TEXTURE_2D_ARRAY, s->layers[i]);
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
}

int stin__deep_active(const stin_context *ctx)
{
    return ctx->deep->ready && ctx->deep->frame_transparent;
}

/* The transparent draws through the peel program in the caller's order:
 * the depth test makes the layers independent of it, and the order test
 * sees that (the camera's far-to-near order would hide an order
 * dependence). */
static void draw_transparent(stin_context *ctx)
{
    const stin__deep_state *s = ctx->deep;
    stin__translucent_draw_casters(ctx, s->u_model, s->u_albedo, s->u_has_albedo_tex, &s->displace);
}

/* Whether a transparent caster's bounding box reaches into the face's
 * frustum (view_proj): one whose corners all lie beyond one of its planes
 * draws nothing there. A displaced caster leaves its mesh's box: it counts. */
static int face_reached(const stin_context *ctx, const float view_proj[16])
{
    uint32_t i;
    int c, k;
    for (i = 0; i < ctx->draw_count; i++) {
        const stin__draw *d = &ctx->draws[i];
        const stin_mesh_info *info = &ctx->meshes[d->mesh_slot].info;
        unsigned beyond = 0x3fu; /* per plane: every corner so far beyond it */
        float m[16];
        if (d->material.color[3] >= 1.0f)
            continue;
        if (d->material.displace)
            return 1;
        stin__mat4_mul(m, view_proj, d->transform);
        for (c = 0; c < 8 && beyond; c++) {
            const float p[3] = {(c & 1) ? info->bounds_max[0] : info->bounds_min[0],
                                (c & 2) ? info->bounds_max[1] : info->bounds_min[1],
                                (c & 4) ? info->bounds_max[2] : info->bounds_min[2]};
            float x[4];
            unsigned out = 0;
            for (k = 0; k < 4; k++)
                x[k] = m[k] * p[0] + m[4 + k] * p[1] + m[8 + k] * p[2] + m[12 + k];
            for (k = 0; k < 3; k++)
                out |= (x[k] < -x[3] ? 1u : 0u) << (2 * k) | (x[k] > x[3] ? 2u : 0u) << (2 * k);
            beyond &= out;
        }
        if (!beyond)
            return 1;
    }
    return 0;
}

/* One face's layers, from its view and projection; layer k of the face is
 * slice face * slices + k / 2 of layers[k % 2]. With the early stop a face
 * no transparent caster reaches peels nothing (its lookup reads no layer),
 * and one that does stops at its first empty layer. */
static void peel_face(stin_context *ctx, int face, const float view[16], const float proj[16])
{
    stin__deep_state *s = ctx->deep;
    int stop_early = (s->query || s->flag) && !(ctx->desc.debug_flags & STIN_DEBUG_DEEP_NO_EARLY_STOP);
    static const GLuint zero = 0;
    float view_proj[16];
    uint32_t k;
    stin__mat4_mul(view_proj, proj, view);
    stin__light_window_matrix(s->matrix[face], view, proj);
    s->face_layers[face] = (GLint)s->layer_cap;
    if (stop_early && !face_reached(ctx, view_proj)) {
        s->face_layers[face] = 0;
        return;
    }
    GL(ctx, UniformMatrix4fv)(s->u_view_proj, 1, GL_FALSE, view_proj);
    ctx->stats.translucent.deep_faces++;
    for (k = 0; k < s->layer_cap; k++) {
        GLint slice = (GLint)((uint32_t)face * s->slices + k / 2u);
        GLuint drawn = 1;
        int counted = 0;
        GL(ctx, FramebufferTextureLayer)(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, s->layers[k % 2u], 0,
                                         slice);
        GL(ctx, ClearColor)(EMPTY_DEPTH, 1.0f, 1.0f, 1.0f);
        stin__clear_depth(ctx, 1.0);
        GL(ctx, Clear)(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        /* layer k - 1 on the deep unit; the texture drawn into is on none */
        stin__bind_unit(ctx, s->unit, GL_TEXTURE_2D_ARRAY, k > 0 ? s->layers[(k - 1u) % 2u] : 0);
        GL(ctx, ActiveTexture)(GL_TEXTURE0);
        GL(ctx, Uniform1i)(s->u_previous_slice,
                           k > 0 ? (GLint)((uint32_t)face * s->slices + (k - 1u) / 2u) : -1);
        if (stop_early && s->flag)
            GL(ctx, BufferSubData)(GL_SHADER_STORAGE_BUFFER, 0, (GLsizeiptr)sizeof zero, &zero);
        else if (stop_early) /* a caller's samples query: no early stop */
            counted = stin__any_samples_begin(ctx, s->query);
        draw_transparent(ctx);
        ctx->stats.translucent.deep_layers++;
        ctx->stats.passes++;
        if (stop_early && s->flag) { /* the shader's writes, visible to the read-back */
            GL(ctx, MemoryBarrier)(GL_BUFFER_UPDATE_BARRIER_BIT);
            GL(ctx, GetBufferSubData)(GL_SHADER_STORAGE_BUFFER, 0, (GLsizeiptr)sizeof drawn,
                                      &drawn);
        } else if (counted) {
            drawn = (GLuint)stin__any_samples_end(ctx, s->query);
        }
        if (!drawn) { /* empty, so every deeper layer would be: the lookup stops here */
            s->face_layers[face] = (GLint)k;
            break;
        }
    }
}

void stin__deep_light(stin_context *ctx, uint32_t li)
{
    stin__deep_state *s = ctx->deep;
    stin__pass_state ps = stin__pass_defaults;
    s->kind = 0;
    if (!stin__deep_active(ctx) || li >= ctx->light_count)
        return;
    stin__translucent_say_area(ctx, &ctx->lights[li], &s->said_area, "deep");
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, s->fbo);
    GL(ctx, Viewport)(0, 0, (GLsizei)s->size, (GLsizei)s->size);
    ps.depth_test = 1; /* LESS with writes: the nearest surface behind the last layer */
    stin__pass_apply(ctx, &ps);
    GL(ctx, UseProgram)(s->program);
    stin__lit_program_forget(ctx); /* the lit program is no longer current */
    ctx->bound_mesh = 0xffffffffu;
    GL(ctx, Uniform1i)(s->u_albedo_tex, 0);
    GL(ctx, Uniform1i)(s->u_previous, s->unit);
    GL(ctx, Uniform1i)(s->u_mono, ctx->desc.translucent.deep_mono);
    if (s->flag) /* binding 0 of the peel shader (and the generic binding) */
        GL(ctx, BindBufferBase)(GL_SHADER_STORAGE_BUFFER, 0, s->flag);
    /* the other texture is sampled by no one while its slices are drawn */
    stin__bind_unit(ctx, s->unit + 1, GL_TEXTURE_2D_ARRAY, 0);
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
    s->kind = stin__translucent_faces(ctx, &ctx->lights[li], s->size, peel_face, &s->normal_offset);
    if (s->flag)
        GL(ctx, BindBufferBase)(GL_SHADER_STORAGE_BUFFER, 0, 0);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
    stin__bind_unit(ctx, s->unit, GL_TEXTURE_2D_ARRAY, 0);
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
    GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, ctx->draw_fbo);
    GL(ctx, Viewport)(ctx->frame.viewport[0], ctx->frame.viewport[1], ctx->frame.viewport[2],
                      ctx->frame.viewport[3]);
    ctx->bound_mesh = 0xffffffffu;
}

void stin__deep_light_done(stin_context *ctx)
{
    stin__deep_state *s = ctx->deep;
    if (!s->kind)
        return;
    s->kind = 0;
    stin__translucent_unbind(ctx, s->unit, GL_TEXTURE_2D_ARRAY);
}
