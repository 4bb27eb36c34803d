/* The frame: begin -> lights -> draws -> end. Lists live in the arena; end
 * orders the draws (opaque in submission order, then blended ones back to
 * front) and runs the pass schedule of the chosen lighting path. */
#include "internal.h"

static int finite_n(const float *v, int n)
{
    int i;
    for (i = 0; i < n; i++)
        if (!stin__isfinite(v[i]))
            return 0;
    return 1;
}

static stin_result state_error(stin_context *ctx, const char *call, const char *why)
{
    stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_FRAME_STATE, "%s: %s", call, why);
    return STIN_ERROR_INVALID_STATE;
}

static stin_result arg_error(stin_context *ctx, const char *call, const char *why)
{
    stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_BAD_ARGUMENT, "%s: %s", call, why);
    return STIN_ERROR_INVALID_ARGUMENT;
}

stin_result stin_begin_frame(stin_context *ctx, const stin_frame_desc *desc)
{
    if (!ctx || !desc)
        return STIN_ERROR_INVALID_ARGUMENT;
    if (ctx->state != STIN__IDLE)
        return state_error(ctx, "stin_begin_frame", "a frame is already open");
    if (desc->viewport[2] <= 0 || desc->viewport[3] <= 0)
        return arg_error(ctx, "stin_begin_frame", "viewport width and height must be positive");
    if (!finite_n(desc->view, 16) || !finite_n(desc->projection, 16) ||
        !finite_n(desc->ambient, 3) || !finite_n(desc->clear_color, 4))
        return arg_error(ctx, "stin_begin_frame", "view, projection, ambient and clear colour "
                                                  "must be finite");
    if ((unsigned)desc->output > STIN_OUTPUT_VISIBILITY)
        return arg_error(ctx, "stin_begin_frame", "unknown output");
    if (desc->framebuffer && !(ctx->caps.present & STIN_CAP_BIT(STIN_CAP_FBO)))
        return arg_error(ctx, "stin_begin_frame", "a framebuffer name needs framebuffer objects");
    ctx->frame = *desc;
    ctx->draw_count = ctx->light_count = 0;
    stin__memzero(&ctx->stats, sizeof ctx->stats);
    ctx->state = STIN__IN_FRAME;
    return STIN_OK;
}

static float len3(const float v[3]) { return stin__sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

stin_result stin_add_light(stin_context *ctx, const stin_light_desc *light)
{
    stin_light_desc l;
    float n;
    int k;
    if (!ctx || !light)
        return STIN_ERROR_INVALID_ARGUMENT;
    if (ctx->state != STIN__IN_FRAME)
        return state_error(ctx, "stin_add_light", "no frame is open");
    l = *light;
    if ((unsigned)l.type > STIN_LIGHT_DIRECTIONAL || !finite_n(l.position, 3) ||
        !finite_n(l.direction, 3) || !finite_n(l.color, 3) || !finite_n(l.attenuation, 3) ||
        !stin__isfinite(l.intensity) || !stin__isfinite(l.spot_cutoff_deg) ||
        !stin__isfinite(l.spot_exponent))
        return arg_error(ctx, "stin_add_light", "unknown type or a non-finite value");
    if (l.color[0] == 0.0f && l.color[1] == 0.0f && l.color[2] == 0.0f)
        l.color[0] = l.color[1] = l.color[2] = 1.0f;
    if (l.intensity == 0.0f)
        l.intensity = 1.0f;
    if (l.attenuation[0] == 0.0f && l.attenuation[1] == 0.0f && l.attenuation[2] == 0.0f)
        l.attenuation[0] = 1.0f;
    if (l.attenuation[0] < 0 || l.attenuation[1] < 0 || l.attenuation[2] < 0)
        return arg_error(ctx, "stin_add_light", "attenuation factors must be >= 0");
    if (l.spot_cutoff_deg == 0.0f)
        l.spot_cutoff_deg = 45.0f;
    if (l.type == STIN_LIGHT_SPOT && (l.spot_cutoff_deg < 0.0f || l.spot_cutoff_deg > 90.0f))
        return arg_error(ctx, "stin_add_light", "spot_cutoff_deg must be in (0, 90]");
    if (l.pcf_kernel == 0)
        l.pcf_kernel = 3;
    if (l.pcf_kernel != 1 && l.pcf_kernel != 3 && l.pcf_kernel != 5)
        return arg_error(ctx, "stin_add_light", "pcf_kernel must be 1, 3 or 5");
    if (l.radius < 0.0f || l.range < 0.0f || !stin__isfinite(l.radius) || !stin__isfinite(l.range))
        return arg_error(ctx, "stin_add_light", "radius and range must be finite and >= 0");
    if (l.spot_exponent < 0.0f || l.spot_exponent > 128.0f)
        return arg_error(ctx, "stin_add_light", "spot_exponent must be in [0, 128]");
    if (l.type != STIN_LIGHT_POINT) {
        n = len3(l.direction);
        if (!(n > 0.0f))
            return arg_error(ctx, "stin_add_light", "spot and directional lights need a direction");
        for (k = 0; k < 3; k++)
            l.direction[k] /= n;
    }
    if (ctx->light_count >= ctx->desc.max_lights) {
        ctx->stats.dropped_lights++;
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_POOL_FULL,
                  "stin_add_light: more than desc.max_lights (%u) lights; light dropped",
                  ctx->desc.max_lights);
        return STIN_ERROR_CAPACITY;
    }
    ctx->lights[ctx->light_count++] = l;
    return STIN_OK;
}

static void material_defaults(stin_material *m)
{
    if (m->color[0] == 0.0f && m->color[1] == 0.0f && m->color[2] == 0.0f && m->color[3] == 0.0f) {
        m->color[0] = m->color[1] = m->color[2] = 0.8f;
        m->color[3] = 1.0f;
    }
    if (m->shininess == 0.0f)
        m->shininess = 32.0f;
    if (m->shininess > 128.0f)
        m->shininess = 128.0f;
    if (m->shininess < 0.0f)
        m->shininess = 0.0f;
    if (m->height_scale == 0.0f)
        m->height_scale = 0.04f;
    if (m->height_bias == 0.0f)
        m->height_bias = 0.5f * m->height_scale;
    if (m->pom_min_steps == 0)
        m->pom_min_steps = 8;
    if (m->pom_max_steps == 0)
        m->pom_max_steps = 32;
    if (m->pom_max_steps > 64)
        m->pom_max_steps = 64;
    if (m->pom_min_steps > m->pom_max_steps)
        m->pom_min_steps = m->pom_max_steps;
}

static float eye_depth(const stin_context *ctx, const stin__mesh_slot *m, const float xf[16])
{
    float c[3], w[3], e[3];
    int k;
    for (k = 0; k < 3; k++)
        c[k] = 0.5f * (m->info.bounds_min[k] + m->info.bounds_max[k]);
    stin__mat4_transform_point(xf, c, w);
    stin__mat4_transform_point(ctx->frame.view, w, e);
    return -e[2];
}

stin_result stin_draw(stin_context *ctx, stin_mesh mesh, const float transform[16],
                      const stin_material *material)
{
    stin__draw *d;
    stin__mesh_slot *m;
    uint32_t slot;
    stin_material mat;
    if (!ctx)
        return STIN_ERROR_INVALID_ARGUMENT;
    if (ctx->state != STIN__IN_FRAME)
        return state_error(ctx, "stin_draw", "no frame is open");
    m = stin__mesh_lookup(ctx, mesh, &slot);
    if (!m) {
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_BAD_HANDLE,
                  "stin_draw: stale or unknown mesh handle 0x%x; draw dropped", mesh.id);
        ctx->stats.dropped_draws++;
        return STIN_ERROR_INVALID_HANDLE;
    }
    if (transform && !finite_n(transform, 16)) {
        ctx->stats.dropped_draws++;
        return arg_error(ctx, "stin_draw", "transform must be finite; draw dropped");
    }
    stin__memzero(&mat, sizeof mat);
    if (material)
        mat = *material;
    if (!finite_n(mat.color, 4) || !finite_n(mat.specular, 3) || !stin__isfinite(mat.shininess) ||
        !stin__isfinite(mat.height_scale) || !stin__isfinite(mat.height_bias)) {
        ctx->stats.dropped_draws++;
        return arg_error(ctx, "stin_draw", "material values must be finite; draw dropped");
    }
    if (mat.height_scale < 0.0f || mat.self_shadow < 0 || mat.self_shadow > 2 ||
        (mat.surface != STIN_TECH_NONE &&
         stin__technique_feature(mat.surface) != STIN_FEATURE_SURFACE)) {
        ctx->stats.dropped_draws++;
        return arg_error(ctx, "stin_draw", "material height_scale must be >= 0, self_shadow 0..2 "
                                           "and surface a surface technique or none; draw dropped");
    }
    if ((mat.normal_map.id && !stin__texture_lookup(ctx, mat.normal_map)) ||
        (mat.height_map.id && !stin__texture_lookup(ctx, mat.height_map))) {
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_BAD_HANDLE,
                  "stin_draw: stale or unknown normal or height map 0x%x/0x%x; draw dropped",
                  mat.normal_map.id, mat.height_map.id);
        ctx->stats.dropped_draws++;
        return STIN_ERROR_INVALID_HANDLE;
    }
    if (mat.albedo.id && !stin__texture_lookup(ctx, mat.albedo)) {
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_BAD_HANDLE,
                  "stin_draw: stale or unknown albedo texture 0x%x; draw dropped", mat.albedo.id);
        ctx->stats.dropped_draws++;
        return STIN_ERROR_INVALID_HANDLE;
    }
    material_defaults(&mat);
    if (ctx->draw_count >= ctx->desc.max_draws) {
        ctx->stats.dropped_draws++;
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_POOL_FULL,
                  "stin_draw: more than desc.max_draws (%u) draws; draw dropped",
                  ctx->desc.max_draws);
        return STIN_ERROR_CAPACITY;
    }
    d = &ctx->draws[ctx->draw_count];
    d->mesh_slot = slot;
    if (transform)
        stin__memcopy(d->transform, transform, sizeof d->transform);
    else
        stin__mat4_identity(d->transform);
    d->material = mat;
    d->sort_depth = eye_depth(ctx, m, d->transform);
    ctx->draw_order[ctx->draw_count] = ctx->draw_count;
    ctx->draw_count++;
    return STIN_OK;
}

void stin_query_frame_projection(const stin_context *ctx, float out[16])
{
    if (!ctx || !out)
        return;
    stin__memcopy(out, ctx->projection, sizeof ctx->projection);
}

static int blended(const stin__draw *d) { return d->material.color[3] < 1.0f; }

/* Stable: opaque draws first in submission order, then blended ones far to near. */
static void order_draws(stin_context *ctx)
{
    uint32_t i, n = ctx->draw_count, o = 0;
    uint32_t *ord = ctx->draw_order;
    for (i = 0; i < n; i++)
        if (!blended(&ctx->draws[i]))
            ord[o++] = i;
    for (i = 0; i < n; i++)
        if (blended(&ctx->draws[i])) {
            uint32_t j = o++;
            while (j > 0 && blended(&ctx->draws[ord[j - 1]]) &&
                   ctx->draws[ord[j - 1]].sort_depth < ctx->draws[i].sort_depth) {
                ord[j] = ord[j - 1];
                j--;
            }
            ord[j] = i;
        }
}

static void begin_target(stin_context *ctx)
{
    const stin_frame_desc *f = &ctx->frame;
    if (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_FBO))
        GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, f->framebuffer);
    GL(ctx, Viewport)(f->viewport[0], f->viewport[1], f->viewport[2], f->viewport[3]);
    GL(ctx, DepthMask)(GL_TRUE);
    GL(ctx, ColorMask)(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    GL(ctx, StencilMask)(0xffffffffu);
    if (!f->no_clear) {
        GL(ctx, ClearColor)(f->clear_color[0], f->clear_color[1], f->clear_color[2],
                            f->clear_color[3]);
        GL(ctx, ClearDepth)(1.0);
        GL(ctx, ClearStencil)(0);
        GL(ctx, Clear)(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT |
                       (ctx->caps.stencil_bits > 0 ? GL_STENCIL_BUFFER_BIT : 0u));
    }
}

/* Samples of a light: several for an area light with soft shadows. */
static uint32_t light_samples(const stin_context *ctx, const stin_light_desc *l)
{
    return l->radius > 0.0f && l->type != STIN_LIGHT_DIRECTIONAL ? ctx->desc.soft_shadow_samples : 1u;
}

/* One light sample as a homogeneous world position (w = 0: toward the light). */
static void sample_light(const stin_light_desc *l, uint32_t i, uint32_t n, stin_light_desc *out,
                         float world[4])
{
    *out = *l;
    if (l->type == STIN_LIGHT_DIRECTIONAL) {
        world[0] = -l->direction[0];
        world[1] = -l->direction[1];
        world[2] = -l->direction[2];
        world[3] = 0.0f;
        return;
    }
    stin_light_sample(l, i, n, out->position);
    out->intensity = l->intensity / (float)n;
    world[0] = out->position[0];
    world[1] = out->position[1];
    world[2] = out->position[2];
    world[3] = 1.0f;
}

/* Ambient first, then per light (sample): its stencil volumes, then the
 * opaque draws lit by it where the stencil count is zero; blended draws
 * last, unshadowed. The visibility output runs the same schedule for light 0
 * and adds white where it is visible. */
static void run_volumes(stin_context *ctx, const stin__path *path, int visibility)
{
    uint32_t li, s, lights = visibility ? (ctx->light_count > 0) : ctx->light_count;
    path->ambient(ctx, visibility ? STIN__ALL : STIN__OPAQUE, visibility);
    for (li = 0; li < lights; li++) {
        const stin_light_desc *l = &ctx->lights[li];
        uint32_t n = light_samples(ctx, l);
        int rect[4], scissored = stin__light_scissor(ctx, l, rect);
        if (scissored && (rect[2] <= 0 || rect[3] <= 0))
            continue; /* the light touches nothing on screen */
        for (s = 0; s < n; s++) {
            stin_light_desc one;
            float world[4];
            sample_light(l, s, n, &one, world);
            stin__volume_light(ctx, path, world, scissored ? rect : NULL);
            if (visibility) {
                float w = 1.0f / (float)n, white[4];
                white[0] = white[1] = white[2] = w;
                white[3] = 1.0f;
                path->flat(ctx, STIN__ALL, white);
            } else {
                path->lit(ctx, &one);
            }
        }
        GL_DISABLE(ctx, GL_STENCIL_TEST);
        GL_DISABLE(ctx, GL_SCISSOR_TEST);
    }
    if (visibility && !lights)
        path->flat(ctx, STIN__ALL, (const float[4]){1, 1, 1, 1});
    if (!visibility)
        path->batches(ctx, STIN__BLENDED);
}

/* Shadow maps: ambient, then per light its map's test on the lit pass (point
 * lights: stencil volumes where there is a stencil buffer); blended last. */
static void run_maps(stin_context *ctx, const stin__path *path, int visibility)
{
    uint32_t li, lights = visibility ? (ctx->light_count > 0) : ctx->light_count;
    const float white[4] = {1, 1, 1, 1};
    int stencil = (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_STENCIL)) != 0;
    path->ambient(ctx, visibility ? STIN__ALL : STIN__OPAQUE, visibility);
    for (li = 0; li < lights; li++) {
        const stin_light_desc *l = &ctx->lights[li];
        int mapped, face;
        if (stin__pcf_active(ctx)) { /* the lit program does the test */
            ctx->pcf_light = li;
            ctx->pcf_kind = l->type == STIN_LIGHT_POINT ? (stin__pcf_point(ctx, li) ? 2 : 0)
                                                         : (ctx->maps.valid[li] ? 1 : 0);
            if (visibility)
                path->flat(ctx, STIN__ALL, white);
            else
                path->lit(ctx, l);
            ctx->pcf_kind = 0;
            continue;
        }
        mapped = stin__maps_bind(ctx, li);
        if (!mapped && l->type == STIN_LIGHT_POINT && ctx->maps.faces) {
            for (face = 0; face < 6; face++) /* six maps, each lighting its own pyramid */
                if (stin__maps_face(ctx, li, face)) {
                    if (visibility)
                        path->flat(ctx, STIN__ALL, white);
                    else
                        path->lit(ctx, l);
                    stin__maps_face_end(ctx);
                }
            continue;
        }
        if (!mapped && l->type == STIN_LIGHT_POINT && stencil) {
            float world[4] = {l->position[0], l->position[1], l->position[2], 1.0f};
            stin__volume_light(ctx, path, world, NULL);
        }
        if (visibility)
            path->flat(ctx, STIN__ALL, white);
        else
            path->lit(ctx, l);
        if (mapped)
            stin__maps_unbind(ctx);
        GL_DISABLE(ctx, GL_STENCIL_TEST);
    }
    if (visibility && !lights)
        path->flat(ctx, STIN__ALL, white);
    if (!visibility)
        path->batches(ctx, STIN__BLENDED);
}

static void run_frame(stin_context *ctx)
{
    const stin__path *path =
        ctx->sel.choice[STIN_FEATURE_LIGHTING].technique == STIN_TECH_LIGHTING_FIXED
            ? stin__fixed_path()
            : stin__glsl_path();
    int volumes = ctx->sel.choice[STIN_FEATURE_SHADOWS].technique == STIN_TECH_SHADOWS_VOLUME;
    int maps = stin__maps_active(ctx) || stin__pcf_active(ctx);
    stin__volume_frame_setup(ctx);
    path->begin(ctx);
    switch (ctx->frame.output) {
    case STIN_OUTPUT_NORMAL:
        path->normals(ctx);
        break;
    case STIN_OUTPUT_VISIBILITY:
        if (maps) {
            run_maps(ctx, path, 1);
        } else if (volumes) {
            run_volumes(ctx, path, 1);
        } else {
            path->ambient(ctx, STIN__ALL, 1);
            path->flat(ctx, STIN__ALL, (const float[4]){1, 1, 1, 1});
        }
        break;
    default:
        if (maps && ctx->light_count)
            run_maps(ctx, path, 0);
        else if (volumes && ctx->light_count)
            run_volumes(ctx, path, 0);
        else
            path->batches(ctx, STIN__ALL);
        break;
    }
    path->end(ctx);
}

stin_result stin_end_frame(stin_context *ctx)
{
    uint32_t i;
    if (!ctx)
        return STIN_ERROR_INVALID_ARGUMENT;
    if (ctx->state != STIN__IN_FRAME)
        return state_error(ctx, "stin_end_frame", "no frame is open");
    order_draws(ctx);
    if (stin__maps_active(ctx) && ctx->light_count)
        stin__maps_render(ctx); /* before the clear: without FBOs they use the frame's buffer */
    if (stin__pcf_active(ctx) && ctx->light_count)
        stin__pcf_render(ctx);
    begin_target(ctx);
    ctx->stats.draws = ctx->draw_count;
    ctx->stats.lights = ctx->light_count;
    for (i = 0; i < ctx->draw_count; i++)
        ctx->stats.triangles += ctx->meshes[ctx->draws[i].mesh_slot].triangle_count;
    run_frame(ctx);
    stin__state_restore(ctx);
    stin__gl_check_errors(ctx, "stin_end_frame");
    ctx->state = STIN__IDLE;
    return STIN_OK;
}
