/* GL2 and GL4 tiers: per-pixel lighting in GLSL (shaders/gl2 with #version
 * 110 on compatibility contexts, shaders/gl4 with #version 150 and VAOs),
 * lights in batches of 8 with additive passes, and the AOV outputs. */
#include "internal.h"

static const char *const frag_names[STIN__PROG_COUNT] = {"lit.frag", "normal.frag", "flat.frag"};

static void locate(stin_context *ctx, stin__program *p)
{
#define LOC(field, uniform) p->field = GL(ctx, GetUniformLocation)(p->name, uniform)
    LOC(u_model, "u_model");
    LOC(u_view_proj, "u_view_proj");
    LOC(u_normal_matrix, "u_normal_matrix");
    LOC(u_eye, "u_eye");
    LOC(u_ambient, "u_ambient");
    LOC(u_albedo, "u_albedo");
    LOC(u_specular, "u_specular");
    LOC(u_shininess, "u_shininess");
    LOC(u_light_count, "u_light_count");
    LOC(u_lights, "u_lights");
    LOC(u_albedo_tex, "u_albedo_tex");
    LOC(u_has_albedo_tex, "u_has_albedo_tex");
    LOC(u_color, "u_color");
#undef LOC
}

stin_result stin__glsl_init(stin_context *ctx, stin_tier tier, char *msg, size_t msg_size)
{
    const char *dir = tier == STIN_TIER_GL4 ? "gl4/" : "gl2/";
    char vert[32], frag[32];
    int i;
    stin__glsl_release(ctx);
    stin__formatf(vert, sizeof vert, "%slit.vert", dir);
    for (i = 0; i < STIN__PROG_COUNT; i++) {
        stin__program *p = &ctx->programs[i];
        stin__formatf(frag, sizeof frag, "%s%s", dir, frag_names[i]);
        p->name = stin__program_build(ctx, vert, frag, msg, msg_size);
        if (!p->name) {
            stin__glsl_release(ctx);
            return STIN_ERROR_GL;
        }
        locate(ctx, p);
    }
    stin__gl_check_errors(ctx, "shader set-up");
    return STIN_OK;
}

void stin__glsl_release(stin_context *ctx)
{
    int i;
    for (i = 0; i < STIN__PROG_COUNT; i++)
        if (ctx->programs[i].name) {
            GL(ctx, DeleteProgram)(ctx->programs[i].name);
            ctx->programs[i].name = 0;
        }
}

static void set_lights(stin_context *ctx, const stin__program *p, int batch)
{
    float packed[4 * 4 * STIN__LIGHTS_PER_PASS];
    int first = batch * STIN__LIGHTS_PER_PASS, n = 0, i, k;
    const float zero[3] = {0, 0, 0};
    for (i = first; i < (int)ctx->light_count && n < STIN__LIGHTS_PER_PASS; i++, n++) {
        const stin_light_desc *l = &ctx->lights[i];
        float *o = packed + 16 * n;
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
    GL(ctx, Uniform1i)(p->u_light_count, n);
    if (n)
        GL(ctx, Uniform4fv)(p->u_lights, 4 * n, packed);
    GL(ctx, Uniform3fv)(p->u_ambient, 1, batch == 0 ? ctx->frame.ambient : zero);
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

static void draw_mesh(stin_context *ctx, const stin__program *p, const stin__draw *d)
{
    const stin__mesh_slot *m = &ctx->meshes[d->mesh_slot];
    float nm[9];
    const void *idx = NULL;
    GL(ctx, UniformMatrix4fv)(p->u_model, 1, GL_FALSE, d->transform);
    stin__mat3_normal(nm, d->transform);
    GL(ctx, UniformMatrix3fv)(p->u_normal_matrix, 1, GL_FALSE, nm);
    if (ctx->bound_mesh == d->mesh_slot) {
        if (!m->vao && !m->vbo)
            idx = ctx->indices + 3u * m->first_triangle;
    } else if (m->vao) {
        GL(ctx, BindVertexArray)(m->vao);
    } else if (m->vbo) {
        GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, m->vbo);
        GL(ctx, BindBuffer)(GL_ELEMENT_ARRAY_BUFFER, m->ibo);
        stin__mesh_bind_attributes(ctx, NULL);
    } else {
        stin__mesh_bind_attributes(ctx, ctx->vertices + m->first_vertex);
        idx = ctx->indices + 3u * m->first_triangle;
    }
    ctx->bound_mesh = d->mesh_slot;
    GL(ctx, DrawElements)(GL_TRIANGLES, (GLsizei)(3u * m->triangle_count), GL_UNSIGNED_INT, idx);
}

static void pass_state(stin_context *ctx, int additive, int blend_alpha)
{
    GL(ctx, DepthFunc)(additive ? GL_EQUAL : GL_LESS);
    GL(ctx, DepthMask)(additive ? GL_FALSE : GL_TRUE);
    if (additive || blend_alpha) {
        GL_ENABLE(ctx, GL_BLEND);
        GL(ctx, BlendFunc)(blend_alpha ? GL_SRC_ALPHA : GL_ONE,
                           additive ? GL_ONE : GL_ONE_MINUS_SRC_ALPHA);
    } else {
        GL_DISABLE(ctx, GL_BLEND);
    }
}

static const stin__program *use(stin_context *ctx, int which)
{
    const stin__program *p = &ctx->programs[which];
    float vp[16];
    GL(ctx, UseProgram)(p->name);
    stin__mat4_mul(vp, ctx->frame.projection, ctx->frame.view);
    GL(ctx, UniformMatrix4fv)(p->u_view_proj, 1, GL_FALSE, vp);
    return p;
}

static void run_beauty(stin_context *ctx)
{
    const stin__program *p = use(ctx, STIN__PROG_LIT);
    float eye[3], inv[16];
    int batches = ((int)ctx->light_count + STIN__LIGHTS_PER_PASS - 1) / STIN__LIGHTS_PER_PASS, b;
    uint32_t i;
    if (batches < 1)
        batches = 1;
    stin__mat4_invert(inv, ctx->frame.view);
    eye[0] = inv[12];
    eye[1] = inv[13];
    eye[2] = inv[14];
    GL(ctx, Uniform3fv)(p->u_eye, 1, eye);
    GL(ctx, Uniform1i)(p->u_albedo_tex, 0);
    for (b = 0; b < batches; b++) {
        set_lights(ctx, p, b);
        pass_state(ctx, b > 0, 0);
        ctx->stats.passes++;
        for (i = 0; i < ctx->draw_count; i++) {
            const stin__draw *d = &ctx->draws[ctx->draw_order[i]];
            if (d->material.color[3] < 1.0f)
                break; /* blended draws come last in the order */
            set_material(ctx, p, &d->material);
            draw_mesh(ctx, p, d);
        }
    }
    for (i = 0; i < ctx->draw_count; i++) {
        const stin__draw *d = &ctx->draws[ctx->draw_order[i]];
        if (d->material.color[3] >= 1.0f)
            continue;
        set_material(ctx, p, &d->material);
        for (b = 0; b < batches; b++) {
            set_lights(ctx, p, b);
            pass_state(ctx, b > 0, 1);
            draw_mesh(ctx, p, d);
        }
    }
}

static void run_single(stin_context *ctx, int which)
{
    const stin__program *p = use(ctx, which);
    const float white[4] = {1, 1, 1, 1};
    uint32_t i;
    if (which == STIN__PROG_FLAT)
        GL(ctx, Uniform4fv)(p->u_color, 1, white);
    pass_state(ctx, 0, 0);
    for (i = 0; i < ctx->draw_count; i++)
        draw_mesh(ctx, p, &ctx->draws[ctx->draw_order[i]]);
    ctx->stats.passes++;
}

void stin__glsl_run(stin_context *ctx)
{
    int gl4 = ctx->sel.choice[STIN_FEATURE_LIGHTING].technique == STIN_TECH_LIGHTING_GLSL150;
    int i;
    ctx->bound_mesh = 0xffffffffu;
    GL_ENABLE(ctx, GL_DEPTH_TEST);
    if (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_MULTITEXTURE))
        GL(ctx, ActiveTexture)(GL_TEXTURE0);
    if (!gl4)
        for (i = 0; i < 4; i++)
            GL(ctx, EnableVertexAttribArray)((GLuint)i);
    switch (ctx->frame.output) {
    case STIN_OUTPUT_NORMAL: run_single(ctx, STIN__PROG_NORMAL); break;
    case STIN_OUTPUT_VISIBILITY: run_single(ctx, STIN__PROG_FLAT); break;
    default: run_beauty(ctx); break;
    }
    if (!gl4)
        for (i = 0; i < 4; i++)
            GL(ctx, DisableVertexAttribArray)((GLuint)i);
}
