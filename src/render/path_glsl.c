/* SPDX-License-Identifier: MIT */
/* GL2 and GL4 tiers: per-pixel lighting in GLSL (shaders/gl2 with #version
 * 110 on compatibility contexts, shaders/gl4 with #version 150 and VAOs),
 * lights in batches of 8 with additive passes, the passes the shadow
 * schedule needs, and the AOV outputs. */
#include "render/glsl_private.h"
#include "render/terminator_fixed.h"

static const char *const vert_names[STIN__PROG_COUNT] = {
    "lit.vert", "lit.vert", "lit.vert", "volume.vert", "lit.vert", "volume.vert"};
static const char *const frag_names[STIN__PROG_COUNT] = {
    "lit.frag", "normal.frag", "flat.frag", "flat.frag", "terminator_band.frag",
    "depth_packed.frag"};
/* a program's fragment chunks, the terminator rule's lookup point, the
 * shadow technique's and the features' (render/path_features.h): at most
 * what gl/shader.c splices */
#define LIT_CHUNKS 8

static const stin__uniform_name program_uniforms[] = {
    STIN__UNIFORM(stin__program, u_model, "u_model"),
    STIN__UNIFORM(stin__program, u_view_proj, "u_view_proj"),
    STIN__UNIFORM(stin__program, u_normal_matrix, "u_normal_matrix"),
    STIN__UNIFORM(stin__program, u_terminator, "u_terminator"),
    STIN__UNIFORM(stin__program, u_eye, "u_eye"),
    STIN__UNIFORM(stin__program, u_ambient, "u_ambient"),
    STIN__UNIFORM(stin__program, u_albedo, "u_albedo"),
    STIN__UNIFORM(stin__program, u_specular, "u_specular"),
    STIN__UNIFORM(stin__program, u_shininess, "u_shininess"),
    STIN__UNIFORM(stin__program, u_light_count, "u_light_count"),
    STIN__UNIFORM(stin__program, u_lights, "u_lights"),
    STIN__UNIFORM(stin__program, u_albedo_tex, "u_albedo_tex"),
    STIN__UNIFORM(stin__program, u_has_albedo_tex, "u_has_albedo_tex"),
    STIN__UNIFORM(stin__program, u_shadow_kind, "u_shadow_kind"),
    STIN__UNIFORM(stin__program, u_shadow_matrix, "u_shadow_matrix"),
    STIN__UNIFORM(stin__program, u_shadow_params, "u_shadow_params"),
    STIN__UNIFORM(stin__program, u_shadow_map, "u_shadow_map"),
    STIN__UNIFORM(stin__program, u_shadow_soft, "u_shadow_soft"),
    STIN__UNIFORM(stin__program, u_shadow_depth, "u_shadow_depth"),
    STIN__UNIFORM(stin__program, u_color, "u_color"),
    STIN__UNIFORM(stin__program, u_uv_unit, "u_uv_unit"),
};

static void locate(stin_context *ctx, stin__program *p)
{
    const stin__path_feature *const *f;
    STIN__LOCATE(ctx, p->name, p, program_uniforms);
    for (f = stin__path_features(ctx); *f; f++)
        if ((*f)->locate)
            (*f)->locate(ctx, p);
    /* the volume program draws shadow-map depth from lights, the rest the camera's passes */
    stin__displace_locate(ctx, p->name,
                          p != &ctx->programs[STIN__PROG_VOLUME] &&
                              p != &ctx->programs[STIN__PROG_PACKED_DEPTH],
                          &p->displace);
    p->frame_serial = 0;
}

/* The shadow chunk of the lit programs. */
static const char *lit_shadow_chunk(const stin_context *ctx)
{
    return ctx->shadow->glsl_chunk ? ctx->shadow->glsl_chunk : "shadow_none.glsl";
}

/* The lit program of a surface variant. */
static stin__program *lit_program(stin_context *ctx, int variant)
{
    return variant == STIN__SURF_PLAIN ? &ctx->programs[STIN__PROG_LIT]
                                       : &ctx->glsl->lit[variant];
}

/* Chunk file `name` under dir as list[n] (its text in names[n]); n + 1. */
static int add_chunk(const char *dir, const char *name, char names[][40], const char **list,
                     int n)
{
    if (n == LIT_CHUNKS)
        return n; /* cannot happen: the terminator's, the shadow's and the features' at most */
    stin__formatf(names[n], 40, "%s%s", dir, name);
    list[n] = names[n];
    return n + 1;
}

/* The chunks of the features at `place` for variant `variant`, from list[n]. */
static int feature_chunks(const stin_context *ctx, stin__chunk_place place, int variant,
                          const char *dir, char names[][40], const char **list, int n)
{
    const stin__path_feature *const *f;
    for (f = stin__path_features(ctx); *f; f++) {
        const char *c[STIN__FEATURE_CHUNKS];
        int k, got = (*f)->place == place && (*f)->chunks ? (*f)->chunks(ctx, variant, c) : 0;
        for (k = 0; k < got; k++)
            n = add_chunk(dir, c[k], names, list, n);
    }
    return n;
}

/* A NULL-terminated chunk list around the shadow chunk: a lit program's of
 * `variant` (layer: with a peeled layer's chunks), or without lit the flat
 * program's shadow test (the shadow chunk and those wrapping its seam).
 * terminator_point.glsl comes first: map-pcf's lookups and the translucent
 * maps' start from its point. */
static void program_chunks(const stin_context *ctx, const char *dir, int variant, int lit,
                           int layer, char names[LIT_CHUNKS][40], const char *list[LIT_CHUNKS + 1])
{
    int n = add_chunk(dir, "terminator_point.glsl", names, list, 0);
    if (lit)
        n = feature_chunks(ctx, STIN__CHUNK_SURFACE, variant, dir, names, list, n);
    if (ctx->shadow->glsl_pre_chunk)
        n = add_chunk(dir, ctx->shadow->glsl_pre_chunk(ctx), names, list, n);
    n = add_chunk(dir, lit_shadow_chunk(ctx), names, list, n);
    n = feature_chunks(ctx, STIN__CHUNK_SEAM, variant, dir, names, list, n);
    if (lit && layer)
        n = feature_chunks(ctx, STIN__CHUNK_LAYER, variant, dir, names, list, n);
    list[n] = NULL;
}

/* layer: with the chunks of a peeled layer (when a feature has them) */
static int build_lit(stin_context *ctx, const char *dir, int variant, int tess, int layer,
                     const char *frag_defines, stin__program *p, char *msg, size_t size)
{
    char vert[32], frag[32], names[LIT_CHUNKS][40];
    const char *chunks[LIT_CHUNKS + 1];
    stin__program_source src;
    stin__formatf(vert, sizeof vert, "%slit.vert", dir);
    stin__formatf(frag, sizeof frag, "%slit.frag", dir);
    program_chunks(ctx, dir, variant, 1, layer, names, chunks);
    stin__memzero(&src, sizeof src);
    src.vert = vert;
    src.frag = frag;
    src.frag_chunks = chunks;
    src.frag_defines = frag_defines;
    src.tessellate = tess;
    stin__memzero(p, sizeof *p);
    p->name = stin__program_build_source(ctx, &src, msg, size);
    if (p->name)
        locate(ctx, p);
    return p->name != 0;
}

static int gl4(const stin_context *ctx) { return ctx->volume_vao != 0; }
/* GL2 on OpenGL ES 3.0+: vertices and indices from stin's stream buffers,
 * never from client memory (WebGL 2 has no client arrays) */
static int es_streams(const stin_context *ctx) { return !gl4(ctx) && ctx->volume_vbo != 0; }

int stin__glsl_build_lit(stin_context *ctx, int variant, int tess, int layer,
                         const char *frag_defines, stin__program *p, char *msg, size_t size)
{
    return build_lit(ctx, gl4(ctx) ? "gl4/" : "gl2/", variant, tess, layer, frag_defines, p, msg,
                     size);
}

/* Lit programs per surface variant from normal up to `top` into lit[];
 * returns the best one built (the one below the first that failed, whose
 * message is in msg). */
static int build_variants(stin_context *ctx, const char *dir, int tess, int top,
                          stin__program *lit, char *msg, size_t size)
{
    int v, best = STIN__SURF_PLAIN;
    for (v = STIN__SURF_NORMAL; v <= top; v++) {
        if (!build_lit(ctx, dir, v, tess, 1, NULL, &lit[v], msg, size))
            return best;
        best = v;
    }
    return best;
}

/* One lit program per variant from normal up to the one the choice asks
 * for; a variant that does not build leaves the best at the one below it. */
static void build_surface_variants(stin_context *ctx, const char *dir)
{
    int top = stin__lit_variant_top(ctx);
    char msg[160];
    ctx->glsl->best = build_variants(ctx, dir, 0, top, ctx->glsl->lit, msg,
                                            sizeof msg);
    if (ctx->glsl->best < top)
        stin__lit_variant_failed(ctx, ctx->glsl->best, msg);
}

/* The lit, normal, flat and volume programs into progs; 0 on failure (msg). */
static int build_programs(stin_context *ctx, const char *dir, int tess, stin__program *progs,
                          char *msg, size_t msg_size)
{
    char vert[32], frag[32], names[LIT_CHUNKS][40], flat_names[LIT_CHUNKS][40], none_name[40],
        pack_name[40];
    const char *chunks[LIT_CHUNKS + 1], *shadow_only[LIT_CHUNKS + 1], *no_shadow[2], *pack[2];
    int i;
    /* the lit program's surface and shadow functions (plain variant); flat.frag
     * serves the visibility output (the shadow test) and, with no test, the
     * depth-only volume and map passes */
    program_chunks(ctx, dir, STIN__SURF_PLAIN, 1, 1, names, chunks);
    program_chunks(ctx, dir, STIN__SURF_PLAIN, 0, 0, flat_names, shadow_only);
    stin__formatf(none_name, sizeof none_name, "%sshadow_none.glsl", dir);
    no_shadow[0] = none_name;
    no_shadow[1] = NULL;
    stin__formatf(pack_name, sizeof pack_name, "%spack_depth.glsl", dir);
    pack[0] = pack_name;
    pack[1] = NULL;
    for (i = 0; i < STIN__PROG_COUNT; i++) {
        stin__program *p = &progs[i];
        if (i == STIN__PROG_PACKED_DEPTH &&
            (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_DEPTH_TEXTURE))) {
            p->name = 0; /* maps are depth textures */
            continue;
        }
        stin__formatf(vert, sizeof vert, "%s%s", dir, vert_names[i]);
        stin__formatf(frag, sizeof frag, "%s%s", dir, frag_names[i]);
        p->name = stin__program_build(ctx, vert, frag,
                                      i == STIN__PROG_LIT      ? chunks
                                      : i == STIN__PROG_FLAT   ? shadow_only
                                      : i == STIN__PROG_VOLUME ? no_shadow
                                      : i == STIN__PROG_PACKED_DEPTH ? pack
                                                               : NULL,
                                      tess, msg, msg_size);
        if (!p->name)
            return 0;
        locate(ctx, p);
    }
    return 1;
}

static void delete_programs(stin_context *ctx, stin__program *progs, int n)
{
    int i;
    for (i = 0; i < n; i++)
        if (progs[i].name) {
            GL(ctx, DeleteProgram)(progs[i].name);
            progs[i].name = 0;
        }
}

/* "displace-tess": the same programs tessellated, swapped in for frames
 * with displaced draws (stin__glsl_tessellate); a set that does not build
 * moves displacement to "displace". */
static void build_tessellated(stin_context *ctx, const char *dir)
{
    char msg[160], why[220];
    int ok = build_programs(ctx, dir, 1, ctx->glsl->tess.programs, msg, sizeof msg) &&
             build_variants(ctx, dir, 1, ctx->glsl->best, ctx->glsl->tess.lit, msg,
                            sizeof msg) == ctx->glsl->best;
    if (ok)
        return;
    delete_programs(ctx, ctx->glsl->tess.programs, STIN__PROG_COUNT);
    delete_programs(ctx, ctx->glsl->tess.lit, STIN__SURF_COUNT);
    stin__formatf(why, sizeof why, "its tessellated programs failed to build (%s)", msg);
    stin__displace_untessellate(ctx, why);
}

static void swap_programs(stin__program *a, stin__program *b, int n)
{
    int i;
    for (i = 0; i < n; i++) {
        stin__program t = a[i];
        a[i] = b[i];
        b[i] = t;
    }
}

void stin__glsl_tessellate(stin_context *ctx, int on)
{
    if (!on == !ctx->glsl->tess.active || !ctx->glsl->tess.programs[STIN__PROG_LIT].name)
        return;
    swap_programs(ctx->programs, ctx->glsl->tess.programs, STIN__PROG_COUNT);
    swap_programs(ctx->glsl->lit, ctx->glsl->tess.lit, STIN__SURF_COUNT);
    ctx->glsl->tess.active = on;
    ctx->glsl->current = NULL;
}

stin_result stin__glsl_init(stin_context *ctx, stin_tier tier, char *msg, size_t msg_size)
{
    const char *dir = tier == STIN_TIER_GL4 ? "gl4/" : "gl2/";
    stin__glsl_release(ctx);
    if (!build_programs(ctx, dir, 0, ctx->programs, msg, msg_size)) {
        stin__glsl_release(ctx);
        return STIN_ERROR_GL;
    }
    build_surface_variants(ctx, dir);
    if (stin__displace_tessellated(ctx))
        build_tessellated(ctx, dir);
    if (tier == STIN_TIER_GL4) { /* core profiles have no client arrays: stream volumes */
        GL(ctx, GenBuffers)(1, &ctx->volume_vbo);
        GL(ctx, GenBuffers)(1, &ctx->volume_ibo);
        GL(ctx, GenVertexArrays)(1, &ctx->volume_vao);
        GL(ctx, BindVertexArray)(ctx->volume_vao);
        GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, ctx->volume_vbo);
        GL(ctx, EnableVertexAttribArray)(0);
        GL(ctx, VertexAttribPointer)(0, 4, GL_FLOAT, GL_FALSE, 0, NULL);
        GL(ctx, BindVertexArray)(0);
        GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, 0);
    } else if (ctx->caps.es && ctx->caps.gl_major >= 3) {
        GL(ctx, GenBuffers)(1, &ctx->volume_vbo);
        GL(ctx, GenBuffers)(1, &ctx->volume_ibo);
    }
    return STIN_OK;
}

void stin__glsl_release(stin_context *ctx)
{
    stin__glsl_tessellate(ctx, 0);
    delete_programs(ctx, ctx->programs, STIN__PROG_COUNT);
    delete_programs(ctx, ctx->glsl->lit, STIN__SURF_COUNT);
    delete_programs(ctx, ctx->glsl->tess.programs, STIN__PROG_COUNT);
    delete_programs(ctx, ctx->glsl->tess.lit, STIN__SURF_COUNT);
    stin__lit_cache_release(ctx);
    ctx->glsl->current = NULL;
    if (ctx->volume_vbo)
        GL(ctx, DeleteBuffers)(1, &ctx->volume_vbo);
    if (ctx->volume_vao)
        GL(ctx, DeleteVertexArrays)(1, &ctx->volume_vao);
    if (ctx->volume_ibo)
        GL(ctx, DeleteBuffers)(1, &ctx->volume_ibo);
    ctx->volume_vbo = ctx->volume_vao = ctx->volume_ibo = 0;
}

/* Packs up to 8 lights: position, direction + cos(cutoff), colour + exponent,
 * attenuation (the layout lit.frag reads). */
static void lit_bind(stin_context *ctx, const stin__program *p);

static void upload_lights(stin_context *ctx, const stin__program *p, const stin_light_desc *lights,
                          int n, int with_ambient)
{
    float *packed = ctx->glsl->packed;
    int i, k;
    for (i = 0; i < n; i++) {
        const stin_light_desc *l = &lights[i];
        float *o = packed + 16 * i;
        int dir = l->type == STIN_LIGHT_DIRECTIONAL;
        for (k = 0; k < 3; k++) {
            o[k] = dir ? -l->direction[k] : l->position[k];
            o[4 + k] = l->direction[k];
            o[8 + k] = l->color[k] * l->intensity;
            o[12 + k] = l->attenuation[k];
        }
        o[3] = dir ? 0.0f : 1.0f;
        o[7] = l->type == STIN_LIGHT_SPOT ? stin__cos_deg(l->spot_cutoff_deg) : -2.0f;
        o[11] = l->type == STIN_LIGHT_SPOT ? l->spot_exponent : 0.0f;
        o[15] = 0.0f;
    }
    ctx->glsl->light_n = n;
    ctx->glsl->light_key = stin__lit_lights_key(lights, n);
    ctx->glsl->with_ambient = with_ambient;
    ctx->glsl->serial++; /* every lit program's copy is stale now */
    lit_bind(ctx, p);
}

/* The features' uniforms for the pass: every one's in a lit program, else
 * those whose chunk wraps the shadow chunk's seam (the flat program's). */
static void features_uniforms(stin_context *ctx, const stin__program *p, int lit)
{
    const stin__path_feature *const *f;
    for (f = stin__path_features(ctx); *f; f++)
        if ((*f)->uniforms && (lit || (*f)->place == STIN__CHUNK_SEAM))
            (*f)->uniforms(ctx, p);
}

/* The per-frame uniforms of a lit program (matrices, eye, sampler units,
 * the current light batch), uploaded when the program is bound after they
 * changed: switching surface variants per draw costs this only once per
 * variant and pass. */
static void lit_refresh(stin_context *ctx, stin__program *p)
{
    const stin__path_feature *const *f;
    const float zero[3] = {0, 0, 0};
    float inv[16];
    if (p->frame_serial == ctx->glsl->serial)
        return;
    p->frame_serial = ctx->glsl->serial;
    GL(ctx, UniformMatrix4fv)(p->u_view_proj, 1, GL_FALSE, ctx->view_proj);
    stin__mat4_invert(inv, ctx->frame.view);
    GL(ctx, Uniform3fv)(p->u_eye, 1, inv + 12);
    GL(ctx, Uniform1i)(p->u_albedo_tex, 0);
    for (f = stin__path_features(ctx); *f; f++)
        if ((*f)->units)
            (*f)->units(ctx, p);
    GL(ctx, Uniform1i)(p->u_light_count, ctx->glsl->light_n);
    if (ctx->glsl->light_n)
        GL(ctx, Uniform4fv)(p->u_lights, 4 * ctx->glsl->light_n, ctx->glsl->packed);
    GL(ctx, Uniform3fv)(p->u_ambient, 1,
                        ctx->glsl->with_ambient ? ctx->frame.ambient : zero);
    if (ctx->shadow->uniforms)
        ctx->shadow->uniforms(ctx, p);
    features_uniforms(ctx, p, 1);
}

/* Makes p (a lit program) current with this pass's uniforms. */
static void lit_bind(stin_context *ctx, const stin__program *p)
{
    if (ctx->glsl->current != p) {
        GL(ctx, UseProgram)(p->name);
        ctx->glsl->current = p;
    }
    lit_refresh(ctx, (stin__program *)p);
}

/* The lit program of a draw's surface variant, bound, with its material. */
static const stin__program *lit_for_draw(stin_context *ctx, const stin__draw *d)
{
    const stin__path_feature *const *f;
    int v = stin__lit_variant_for(ctx, &d->material);
    const stin__program *q = stin__lit_specialised(
        ctx, lit_program(ctx, v), v, ctx->glsl->light_key,
        stin__texture_lookup(ctx, d->material.albedo) != NULL);
    lit_bind(ctx, q);
    for (f = stin__path_features(ctx); *f; f++)
        if ((*f)->material)
            (*f)->material(ctx, q, &d->material, v);
    return q;
}

static void set_batch(stin_context *ctx, const stin__program *p, int batch)
{
    int first = batch * STIN__LIGHTS_PER_PASS, n = (int)ctx->light_count - first;
    if (n > STIN__LIGHTS_PER_PASS)
        n = STIN__LIGHTS_PER_PASS;
    if (n < 0)
        n = 0;
    upload_lights(ctx, p, ctx->lights + first, n, batch == 0);
}

static void set_material(stin_context *ctx, const stin__program *p, const stin_material *m)
{
    const stin__texture_slot *t = stin__texture_lookup(ctx, m->albedo);
    GL(ctx, Uniform4fv)(p->u_albedo, 1, m->color);
    GL(ctx, Uniform3fv)(p->u_specular, 1, m->specular);
    GL(ctx, Uniform1f)(p->u_shininess, m->shininess);
    GL(ctx, Uniform1i)(p->u_has_albedo_tex, t != NULL);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, t ? t->name : 0);
}

static void bind_mesh_arrays(stin_context *ctx, const stin__mesh_slot *m, uint32_t slot)
{
    if (ctx->bound_mesh == slot)
        return;
    if (m->vao) {
        GL(ctx, BindVertexArray)(m->vao);
    } else if (m->vbo) {
        GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, m->vbo);
        GL(ctx, BindBuffer)(GL_ELEMENT_ARRAY_BUFFER, m->ibo);
        stin__mesh_bind_attributes(ctx, NULL);
    } else {
        stin__mesh_bind_attributes(ctx, ctx->vertices + m->first_vertex);
    }
    ctx->bound_mesh = slot;
}

/* A 16-bit chunk's attributes (stin__mesh_draw) in the bound mesh's buffer;
 * a vertex array's own binding is not the array buffer's, so it is bound
 * here, and put back to none after the last chunk where a vertex array
 * holds the mesh (as bind_mesh_arrays leaves it). */
static void glsl_rebase(stin_context *ctx, const stin__vertex *base)
{
    const stin__mesh_slot *m = &ctx->meshes[ctx->bound_mesh];
    GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, m->vbo);
    stin__mesh_bind_attributes(ctx, base);
    if (!base && m->vao)
        GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, 0);
}

void stin__glsl_submit_geometry(stin_context *ctx, GLint u_model, const stin__displace_locs *dl,
                                const stin__draw *d)
{
    const stin__mesh_slot *m = &ctx->meshes[d->mesh_slot];
    const void *idx = (m->vao || m->vbo) ? NULL : (const void *)(ctx->indices + 3u * m->first_triangle);
    GL(ctx, UniformMatrix4fv)(u_model, 1, GL_FALSE, d->transform);
    stin__displace_draw(ctx, dl, d);
    bind_mesh_arrays(ctx, m, d->mesh_slot);
    stin__mesh_draw(ctx, m, stin__displace_primitive(dl), idx, glsl_rebase);
}

/* The one geometry submission of the GLSL path: a draw's transform and
 * mesh through program p (its normal matrix where p has one). */
static void draw_uniforms(stin_context *ctx, const stin__program *p, const stin__draw *d)
{
    if (p->u_normal_matrix >= 0) {
        float nm[9];
        int k;
        stin__mat3_normal(nm, d->transform);
        if (d->csg == STIN__CSG_BACK) /* a cavity's wall faces into the cavity */
            for (k = 0; k < 9; k++)
                nm[k] = -nm[k];
        GL(ctx, UniformMatrix3fv)(p->u_normal_matrix, 1, GL_FALSE, nm);
    }
    /* the terminator rule where the vertex normals describe the drawn surface */
    if (p->u_terminator >= 0)
        GL(ctx, Uniform1f)(p->u_terminator,
                           d->csg == STIN__CSG_CAP || stin__displace_active(ctx, &d->material)
                               ? 0.0f
                               : 1.0f);
    /* the mesh's mean lengths of a unit of u and v: the surface's uv scale
     * where no derivatives tell it per pixel */
    if (p->u_uv_unit >= 0) {
        const float *unit = ctx->meshes[d->mesh_slot].uv_unit;
        /* 0: a mesh stin made itself (CSG's near cap), unit scale */
        const float v[4] = {unit[0] > 0.0f ? unit[0] : 1.0f, unit[1] > 0.0f ? unit[1] : 1.0f,
                            0.0f, 0.0f};
        GL(ctx, Uniform4fv)(p->u_uv_unit, 1, v);
    }
}

static void submit(stin_context *ctx, const stin__program *p, const stin__draw *d)
{
    draw_uniforms(ctx, p, d);
    stin__glsl_submit_geometry(ctx, p->u_model, &p->displace, d);
}

static int in_set(const stin_context *ctx, const stin__draw *d, int which)
{
    return (which & stin__camera_set(ctx, d)) != 0;
}

/* The CSG products' faces on their resolved depth (opaque). */
static void draw_csg_faces(stin_context *ctx, const stin__program *p, int which, int materials)
{
    uint32_t i, count;
    const stin__draw *faces = stin__resolved_faces(ctx, &count);
    stin__pass_state saved;
    if (!(which & STIN__OPAQUE) || stin__in_peeled_layer(ctx))
        return;
    for (i = 0; i < count; i++) {
        const stin__draw *d = &faces[i];
        const stin__program *q = p;
        if (!stin__resolved_face_begin(ctx, d, &saved))
            continue;
        if (materials && ctx->glsl->current)
            q = lit_for_draw(ctx, d);
        if (materials)
            set_material(ctx, q, &d->material);
        submit(ctx, q, d);
        stin__resolved_face_end(ctx, &saved);
    }
}

static void draw_set(stin_context *ctx, const stin__program *p, int which, int materials)
{
    uint32_t i;
    for (i = 0; i < ctx->draw_count; i++) {
        const stin__draw *d = &ctx->draws[ctx->draw_order[i]];
        const stin__program *q = p;
        if (!in_set(ctx, d, which))
            continue;
        if (materials && ctx->glsl->current) /* a lit pass: the draw's variant */
            q = lit_for_draw(ctx, d);
        if (materials)
            set_material(ctx, q, &d->material);
        submit(ctx, q, d);
    }
    draw_csg_faces(ctx, p, which, materials);
}

static void pass_state(stin_context *ctx, int additive, int blend_alpha)
{
    stin__pass_state ps = stin__pass_draw(ctx, additive, blend_alpha);
    stin__pass_apply(ctx, &ps);
}

static const stin__program *use(stin_context *ctx, int which)
{
    const stin__program *p = &ctx->programs[which];
    if (which == STIN__PROG_LIT) {
        ctx->glsl->serial++; /* a new pass: the view may have changed */
        lit_bind(ctx, p);
        return p;
    }
    ctx->glsl->current = NULL;
    GL(ctx, UseProgram)(p->name);
    GL(ctx, UniformMatrix4fv)(p->u_view_proj, 1, GL_FALSE, ctx->view_proj);
    return p;
}

static void glsl_batches(stin_context *ctx, int which)
{
    const stin__program *p = use(ctx, STIN__PROG_LIT);
    int batches = ((int)ctx->light_count + STIN__LIGHTS_PER_PASS - 1) / STIN__LIGHTS_PER_PASS, b;
    uint32_t i;
    if (batches < 1)
        batches = 1;
    if (which & STIN__OPAQUE)
        for (b = 0; b < batches; b++) {
            set_batch(ctx, p, b);
            pass_state(ctx, b > 0, 0);
            ctx->stats.passes++;
            draw_set(ctx, p, STIN__OPAQUE, 1);
        }
    if (which & STIN__BLENDED)
        for (i = 0; i < ctx->draw_count; i++) {
            const stin__draw *d = &ctx->draws[ctx->draw_order[i]];
            const stin__program *q;
            if (!in_set(ctx, d, STIN__BLENDED))
                continue;
            q = lit_for_draw(ctx, d);
            set_material(ctx, q, &d->material);
            for (b = 0; b < batches; b++) {
                set_batch(ctx, q, b);
                pass_state(ctx, b > 0, 1);
                submit(ctx, q, d);
            }
        }
}

static void glsl_ambient(stin_context *ctx, int which, int depth_only)
{
    const stin__program *p = use(ctx, STIN__PROG_LIT);
    stin__pass_state ps = stin__pass_draw(ctx, 0, 0);
    upload_lights(ctx, p, NULL, 0, 1);
    ps.color_write = !depth_only;
    stin__pass_apply(ctx, &ps);
    draw_set(ctx, p, which, 1);
    ctx->stats.passes++;
}

static void glsl_lit_lights(stin_context *ctx, const stin_light_desc *lights, int n)
{
    const stin__program *p = use(ctx, STIN__PROG_LIT);
    upload_lights(ctx, p, lights, n, 0);
    pass_state(ctx, 1, 0);
    draw_set(ctx, p, STIN__OPAQUE, 1);
    ctx->stats.passes++;
}

/* Ambient and one light in the ambient pass's place: a program's ambient
 * term rides with the first batch, as in glsl_batches. */
static void glsl_lit_ambient(stin_context *ctx, const stin_light_desc *light)
{
    const stin__program *p = use(ctx, STIN__PROG_LIT);
    upload_lights(ctx, p, light, 1, 1);
    pass_state(ctx, 0, 0);
    draw_set(ctx, p, STIN__OPAQUE, 1);
    ctx->stats.passes++;
}

static void glsl_lit(stin_context *ctx, const stin_light_desc *light)
{
    glsl_lit_lights(ctx, light, 1);
}

static void glsl_flat(stin_context *ctx, int which, const float color[4],
                      const stin_light_desc *light)
{
    const stin__program *p = use(ctx, STIN__PROG_FLAT);
    GL(ctx, Uniform4fv)(p->u_color, 1, color);
    if (ctx->shadow->uniforms || stin__light_maps_active(ctx)) { /* the lit pass's shadow test */
        float inv[16];
        stin__mat4_invert(inv, ctx->frame.view);
        GL(ctx, Uniform3fv)(p->u_eye, 1, inv + 12);
        if (light) { /* where the light is, as lit.frag has it: a point faces' */
            int dir = light->type == STIN_LIGHT_DIRECTIONAL, k; /* pick, the side test */
            float pos[4];
            for (k = 0; k < 3; k++)
                pos[k] = dir ? -light->direction[k] : light->position[k];
            pos[3] = dir ? 0.0f : 1.0f;
            GL(ctx, Uniform4fv)(p->u_lights, 1, pos);
        }
        if (ctx->shadow->uniforms)
            ctx->shadow->uniforms(ctx, p);
    }
    features_uniforms(ctx, p, 0);
    pass_state(ctx, 1, 0);
    draw_set(ctx, p, which, 0);
    ctx->stats.passes++;
}

static void glsl_normals(stin_context *ctx)
{
    const stin__program *p = use(ctx, STIN__PROG_NORMAL);
    pass_state(ctx, 0, 0);
    draw_set(ctx, p, STIN__ALL, 0);
    ctx->stats.passes++;
}

static void glsl_volume_begin(stin_context *ctx)
{
    use(ctx, STIN__PROG_VOLUME);
    if (gl4(ctx)) {
        GL(ctx, BindVertexArray)(ctx->volume_vao);
        GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, ctx->volume_vbo);
    } else {
        int i;
        if (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_VBO))
            GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, ctx->volume_vbo);
        for (i = 1; i < 4; i++)
            GL(ctx, DisableVertexAttribArray)((GLuint)i);
    }
    ctx->bound_mesh = 0xffffffffu;
}

static void glsl_volume_draw(stin_context *ctx, const float model[16], const float *xyzw,
                             uint32_t n)
{
    const stin__displace_locs *dl = &ctx->programs[STIN__PROG_VOLUME].displace;
    GL(ctx, UniformMatrix4fv)(ctx->programs[STIN__PROG_VOLUME].u_model, 1, GL_FALSE, model);
    stin__displace_draw(ctx, dl, NULL); /* volumes are never displaced */
    if (ctx->volume_vbo)
        GL(ctx, BufferData)(GL_ARRAY_BUFFER, (GLsizeiptr)(16u * n), xyzw, GL_STREAM_DRAW);
    if (!gl4(ctx))
        GL(ctx, VertexAttribPointer)(0, 4, GL_FLOAT, GL_FALSE, 0, ctx->volume_vbo ? NULL : xyzw);
    GL(ctx, DrawArrays)(stin__displace_primitive(dl), 0, (GLsizei)n);
}

static void glsl_volume_end(stin_context *ctx)
{
    if (gl4(ctx)) {
        GL(ctx, BindVertexArray)(0);
        GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, 0);
    } else {
        int i;
        if (es_streams(ctx))
            GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, 0);
        for (i = 1; i < 4; i++)
            GL(ctx, EnableVertexAttribArray)((GLuint)i);
    }
    ctx->bound_mesh = 0xffffffffu;
}

static void glsl_begin(stin_context *ctx)
{
    int i;
    ctx->bound_mesh = 0xffffffffu;
    ctx->glsl->current = NULL;
    stin__lit_cache_frame(ctx);
    if (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_MULTITEXTURE))
        GL(ctx, ActiveTexture)(GL_TEXTURE0);
    if (!gl4(ctx))
        for (i = 0; i < 4; i++)
            GL(ctx, EnableVertexAttribArray)((GLuint)i);
}

static void glsl_end(stin_context *ctx)
{
    const stin__path_feature *const *f;
    int i;
    for (f = stin__path_features(ctx); *f; f++)
        if ((*f)->unbind)
            (*f)->unbind(ctx);
    ctx->glsl->current = NULL;
    if (!gl4(ctx))
        for (i = 0; i < 4; i++)
            GL(ctx, DisableVertexAttribArray)((GLuint)i);
}

/* The casters' depth through the volume program (shadow-map casters), or
 * without depth textures packed into colour: every one, or those keep
 * accepts. */
uint32_t stin__glsl_depth_kept(stin_context *ctx, const float view[16], const float proj[16],
                               stin__draw_keep_fn keep, const void *user)
{
    const stin__program *p = &ctx->programs[ctx->programs[STIN__PROG_PACKED_DEPTH].name
                                                ? STIN__PROG_PACKED_DEPTH
                                                : STIN__PROG_VOLUME];
    float view_proj[16];
    uint32_t i, drawn = 0;
    stin__mat4_mul(view_proj, proj, view);
    GL(ctx, UseProgram)(p->name);
    ctx->glsl->current = NULL; /* the lit program is no longer current */
    if (!gl4(ctx)) { /* before the frame's passes the arrays are not on yet (glsl_end turns them off) */
        int k; /* all four: displacement reads the normal and uv */
        for (k = 0; k < 4; k++)
            GL(ctx, EnableVertexAttribArray)((GLuint)k);
    }
    GL(ctx, UniformMatrix4fv)(p->u_view_proj, 1, GL_FALSE, view_proj);
    ctx->bound_mesh = 0xffffffffu;
    for (i = 0; i < ctx->draw_count; i++) {
        const stin__draw *d = &ctx->draws[ctx->draw_order[i]];
        if (d->shadow_caster && (!keep || keep(ctx, d, user))) {
            submit(ctx, p, d);
            drawn++;
        }
    }
    ctx->bound_mesh = 0xffffffffu;
    return drawn;
}

static void glsl_depth(stin_context *ctx, const float view[16], const float proj[16],
                       int casters, float solid_min)
{
    /* the fixed-function maps' options; the GLSL maps lift their lookups */
    (void)casters;
    (void)solid_min;
    (void)stin__glsl_depth_kept(ctx, view, proj, NULL, NULL);
}

/* CSG resolve (csg/goldfeather.c): geometry alone through the volume
 * program, whose position is invariant with the lit passes'. */
static void glsl_geometry_begin(stin_context *ctx)
{
    use(ctx, STIN__PROG_VOLUME);
    if (!gl4(ctx)) { /* a light's map resolve runs before the frame's passes turn them on */
        int k;
        for (k = 0; k < 4; k++)
            GL(ctx, EnableVertexAttribArray)((GLuint)k);
    }
    ctx->bound_mesh = 0xffffffffu;
}

static void glsl_geometry(stin_context *ctx, const stin__draw *d)
{
    submit(ctx, &ctx->programs[STIN__PROG_VOLUME], d);
}

static void glsl_geometry_end(stin_context *ctx) { ctx->bound_mesh = 0xffffffffu; }

/* The light's passes add SRC_ALPHA / ONE: the lit program's alpha is the
 * draw's opacity (times its albedo texture's). */
static void glsl_blended_one(stin_context *ctx, const stin__draw *d, const stin_light_desc *light)
{
    const stin__program *p = use(ctx, STIN__PROG_LIT), *q;
    upload_lights(ctx, p, light, light ? 1 : 0, light == NULL);
    pass_state(ctx, light != NULL, 1);
    q = lit_for_draw(ctx, d);
    set_material(ctx, q, &d->material);
    submit(ctx, q, d);
    ctx->stats.passes++;
}

/* n triangles' indices (bytes of them, of type) from client memory, or on
 * core profiles through the bound stream buffer. */
static void band_indices(stin_context *ctx, const stin__displace_locs *dl, GLenum type,
                         const void *idx, size_t bytes, uint32_t n)
{
    if (ctx->volume_vbo) {
        GL(ctx, BufferData)(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)bytes, idx, GL_STREAM_DRAW);
        idx = NULL;
    }
    GL(ctx, DrawElements)(stin__displace_primitive(dl), (GLsizei)(3u * n), type, idx);
}

/* The band's triangles copied on the stack a batch at a time: narrowed to
 * 16 bits without 32-bit indices (the mesh has at most 65,535 vertices:
 * frame.c draws no band of a split mesh), and without derivatives only
 * those whose facet facts hold (bv not NULL: terminator_band.frag cannot
 * ask them of its facet). */
#define BAND_BATCH 256u
typedef struct band_batch {
    uint16_t narrow[3u * BAND_BATCH];
    uint32_t wide[3u * BAND_BATCH];
    uint32_t count;
    int is_narrow;
} band_batch;

static void band_flush(stin_context *ctx, const stin__displace_locs *dl, band_batch *b)
{
    if (b->count)
        band_indices(ctx, dl, b->is_narrow ? GL_UNSIGNED_SHORT : GL_UNSIGNED_INT,
                     b->is_narrow ? (const void *)b->narrow : (const void *)b->wide,
                     (b->is_narrow ? 6u : 12u) * b->count, b->count);
    b->count = 0;
}

static void band_batched(stin_context *ctx, const stin__displace_locs *dl, const stin__draw *d,
                         const float light[4], const stin__band_view *bv, int narrow,
                         const uint32_t *tris, uint32_t n)
{
    band_batch b;
    uint32_t t, i;
    b.count = 0;
    b.is_narrow = narrow;
    for (t = 0; t < n; t++) {
        const uint32_t *tri = tris + 3u * t;
        if (bv && !stin__band_triangle(ctx, bv, d, light, tri))
            continue;
        for (i = 0; i < 3u; i++) {
            b.narrow[3u * b.count + i] = (uint16_t)tri[i];
            b.wide[3u * b.count + i] = tri[i];
        }
        if (++b.count == BAND_BATCH)
            band_flush(ctx, dl, &b);
    }
    band_flush(ctx, dl, &b);
}

/* Some triangles of a mesh: indices from client memory, or on core
 * profiles through the volumes' stream buffer bound as the element array
 * (the mesh's own put back after). */
static void glsl_terminator_band(stin_context *ctx, const stin__draw *d, const float light[4],
                                 const uint32_t *tris, uint32_t n)
{
    const stin__program *p = use(ctx, STIN__PROG_BAND);
    const stin__mesh_slot *m = &ctx->meshes[d->mesh_slot];
    stin__band_view bv;
    float inv[16];
    if (!in_set(ctx, d, STIN__OPAQUE))
        return; /* not in the frame's depth */
    if (m->chunk_count > 1u) { /* its indices reach past 16 bits: no band (logged once) */
        if (!ctx->warned_split_band)
            stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                      "volume: a mesh of %u vertices without 32-bit element indices gets no "
                      "terminator band (its terminator may show its facets' shadow)",
                      m->vertex_count, 0);
        ctx->warned_split_band = 1;
        return;
    }
    stin__mat4_invert(inv, ctx->frame.view);
    GL(ctx, Uniform3fv)(p->u_eye, 1, inv + 12);
    GL(ctx, Uniform4fv)(p->u_color, 1, light);
    draw_uniforms(ctx, p, d);
    GL(ctx, UniformMatrix4fv)(p->u_model, 1, GL_FALSE, d->transform);
    stin__displace_draw(ctx, &p->displace, d);
    ctx->bound_mesh = 0xffffffffu;
    bind_mesh_arrays(ctx, m, d->mesh_slot);
    if (gl4(ctx) || es_streams(ctx))
        GL(ctx, BindBuffer)(GL_ELEMENT_ARRAY_BUFFER, ctx->volume_ibo);
    else if (m->vbo)
        GL(ctx, BindBuffer)(GL_ELEMENT_ARRAY_BUFFER, 0);
    if (!(ctx->caps.present & STIN_CAP_BIT(STIN_CAP_DERIVATIVES)) &&
        stin__band_view_init(ctx, d, &bv))
        band_batched(ctx, &p->displace, d, light, &bv, m->index_type == GL_UNSIGNED_SHORT, tris,
                     n);
    else if (m->index_type == GL_UNSIGNED_SHORT)
        band_batched(ctx, &p->displace, d, light, NULL, 1, tris, n);
    else
        band_indices(ctx, &p->displace, GL_UNSIGNED_INT, tris, 12u * n, n);
    if (gl4(ctx) || m->vbo)
        GL(ctx, BindBuffer)(GL_ELEMENT_ARRAY_BUFFER, m->ibo);
    ctx->bound_mesh = 0xffffffffu;
}

const stin__path *stin__glsl_path(void)
{
    static const stin__path path = {glsl_begin,       glsl_end,        glsl_ambient,
                                    glsl_lit,         glsl_flat,       glsl_volume_begin,
                                    glsl_volume_draw, glsl_volume_end, glsl_batches,
                                    glsl_normals,     glsl_depth,      glsl_lit_lights,
                                    glsl_geometry_begin, glsl_geometry, glsl_geometry_end,
                                    glsl_blended_one, glsl_lit_ambient, glsl_terminator_band};
    return &path;
}

const stin__path *stin__path_of(const stin_context *ctx)
{
    return ctx->sel.choice[STIN_FEATURE_LIGHTING].technique == STIN_TECH_LIGHTING_FIXED
               ? stin__fixed_path()
               : stin__glsl_path();
}

void stin__lit_program_forget(stin_context *ctx) { ctx->glsl->current = NULL; }

void stin__lit_uniforms_stale(stin_context *ctx) { ctx->glsl->serial++; }

int stin__glsl_tessellated(const stin_context *ctx) { return ctx->glsl->tess.active; }

int stin__glsl_best_variant(const stin_context *ctx) { return ctx->glsl->best; }

size_t stin__glsl_state_bytes(const stin_desc *d)
{
    (void)d;
    return sizeof(struct stin__glsl_state);
}
