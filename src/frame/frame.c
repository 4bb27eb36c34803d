/* SPDX-License-Identifier: MIT */
/* The frame: begin -> lights -> draws -> end. Lists live in the arena; end
 * orders the draws (opaque in submission order, then blended ones back to
 * front) and runs the frame plan: one list of stages, the same for every
 * tier and technique (run_plan below). */
#include "internal.h"

#include <limits.h>

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

/* The viewport within the context's limits: each side within
 * GL_MAX_VIEWPORT_DIMS, the origin not negative, the far corner (the window
 * size of the buffers stin keeps, which are textures) within
 * GL_MAX_TEXTURE_SIZE and the area an int, so no sum or product of its
 * fields overflows. A limit the driver reports as 0 is not checked. */
static int viewport_fits(const stin_caps *c, const int vp[4])
{
    int far = c->max_texture_size > 0 ? c->max_texture_size : INT_MAX, side;
    for (side = 0; side < 2; side++) {
        int dims = c->max_viewport_dims[side];
        if (vp[side] < 0 || (dims > 0 && vp[2 + side] > dims) || vp[side] > far - vp[2 + side])
            return 0;
    }
    return vp[2] <= INT_MAX / vp[3]; /* a point a pixel: vdsm's receivers */
}

stin_result stin_begin_frame(stin_context *ctx, const stin_frame_desc *desc)
{
    if (!ctx || !desc)
        return STIN_ERROR_INVALID_ARGUMENT;
    if (ctx->state != STIN__IDLE)
        return state_error(ctx, "stin_begin_frame", "a frame is already open");
    if (desc->viewport[2] <= 0 || desc->viewport[3] <= 0)
        return arg_error(ctx, "stin_begin_frame", "viewport width and height must be positive");
    if (!viewport_fits(&ctx->caps, desc->viewport)) {
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_BAD_ARGUMENT,
                  "stin_begin_frame: viewport (%d, %d, %d, %d) outside the context's limits: "
                  "x, y >= 0, width <= %d, height <= %d (GL_MAX_VIEWPORT_DIMS), x + width and "
                  "y + height <= %d (GL_MAX_TEXTURE_SIZE), width x height < 2^31",
                  desc->viewport[0], desc->viewport[1], desc->viewport[2], desc->viewport[3],
                  ctx->caps.max_viewport_dims[0], ctx->caps.max_viewport_dims[1],
                  ctx->caps.max_texture_size);
        return STIN_ERROR_INVALID_ARGUMENT;
    }
    if (!stin__finite_n(desc->view, 16) || !stin__finite_n(desc->projection, 16) ||
        !stin__finite_n(desc->ambient, 3) || !stin__finite_n(desc->clear_color, 4))
        return arg_error(ctx, "stin_begin_frame", "view, projection, ambient and clear colour "
                                                  "must be finite");
    if (stin__mat4_singular(desc->view) || stin__mat4_singular(desc->projection))
        return arg_error(ctx, "stin_begin_frame", "view and projection must be invertible "
                                                  "(an all-zero or singular matrix draws nothing)");
    if ((unsigned)desc->output > STIN_OUTPUT_VISIBILITY)
        return arg_error(ctx, "stin_begin_frame", "unknown output");
    if ((unsigned)desc->export_visibility > STIN_EXPORT_VISIBILITY_ONLY)
        return arg_error(ctx, "stin_begin_frame", "unknown export_visibility");
    if (desc->export_visibility && !stin__export_supported(ctx)) {
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_FALLBACK,
                  "stin_begin_frame: the visibility export needs framebuffer objects and packed "
                  "depth-stencil textures");
        return STIN_ERROR_UNSUPPORTED;
    }
    if (!stin__finite_n(desc->outline_color, 4) || !stin__finite_n(&desc->outline_step, 1) ||
        !stin__finite_n(&desc->outline_normal_edge, 1) ||
        !stin__finite_n(&desc->outline_depth_edge, 1) || desc->outline_step < 0.0f ||
        desc->outline_step > 64.0f || desc->outline_normal_edge < 0.0f ||
        desc->outline_depth_edge < 0.0f)
        return arg_error(ctx, "stin_begin_frame", "outline_step must lie in 0..64, the outline's "
                                                  "colour and edges must be finite, the edges "
                                                  "not negative");
    if (desc->outline_step > 0.0f && !stin__outline_supported(ctx)) {
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_FALLBACK,
                  "stin_begin_frame: the outline needs GLSL lighting, framebuffer objects and "
                  "packed depth-stencil textures");
        return STIN_ERROR_UNSUPPORTED;
    }
    if (desc->framebuffer && !(ctx->caps.present & STIN_CAP_BIT(STIN_CAP_FBO)))
        return arg_error(ctx, "stin_begin_frame", "a framebuffer name needs framebuffer objects");
    if (stin__target_check(ctx, desc->framebuffer, "stin_begin_frame") != STIN_OK)
        return STIN_ERROR_INVALID_ARGUMENT;
    ctx->frame = *desc;
    ctx->draw_count = ctx->light_count = 0;
    stin__csg_frame_begin(ctx);
    /* The projection every pass draws with, known from here on
     * (stin_query_frame_projection): a shadow technique may move its far
     * plane to infinity (volumes), whatever lights the frame gets. */
    stin__memcopy(ctx->projection, desc->projection, sizeof ctx->projection);
    stin__frame_choice_begin(ctx); /* vdsm or volumes, where measured (shadow/choice.c) */
    if (ctx->shadow->prepare)
        ctx->shadow->prepare(ctx);
    stin__mat4_mul(ctx->view_proj, ctx->projection, ctx->frame.view);
    stin__memzero(&ctx->stats, sizeof ctx->stats);
    ctx->state = STIN__IN_FRAME;
    return STIN_OK;
}

stin_result stin_add_light(stin_context *ctx, const stin_light_desc *light)
{
    stin_light_desc l;
    if (!ctx || !light)
        return STIN_ERROR_INVALID_ARGUMENT;
    if (ctx->state != STIN__IN_FRAME)
        return state_error(ctx, "stin_add_light", "no frame is open");
    l = *light;
    if ((unsigned)l.type > STIN_LIGHT_DIRECTIONAL || !stin__finite_n(l.position, 3) ||
        !stin__finite_n(l.direction, 3) || !stin__finite_n(l.color, 3) || !stin__finite_n(l.attenuation, 3) ||
        !stin__isfinite(l.intensity) || !stin__isfinite(l.spot_cutoff_deg) ||
        !stin__isfinite(l.spot_exponent) || !stin__finite_n(l.shadow_offset, 2))
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
    if (l.type != STIN_LIGHT_POINT && !stin__normalize3(l.direction))
        return arg_error(ctx, "stin_add_light", "spot and directional lights need a direction");
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
    stin_result r;
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
    if (transform && !stin__finite_n(transform, 16)) {
        ctx->stats.dropped_draws++;
        return arg_error(ctx, "stin_draw", "transform must be finite; draw dropped");
    }
    if (stin__material_prepare(ctx, "stin_draw", "draw", material, &mat, &r) != STIN_OK) {
        ctx->stats.dropped_draws++;
        return r;
    }
    if (ctx->draw_count >= ctx->desc.max_draws) {
        ctx->stats.dropped_draws++;
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_POOL_FULL,
                  "stin_draw: more than desc.max_draws (%u) draws; draw dropped",
                  ctx->desc.max_draws);
        return STIN_ERROR_CAPACITY;
    }
    d = &ctx->draws[ctx->draw_count];
    d->mesh_slot = slot;
    d->csg = 0;
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

/* ---- stages ---------------------------------------------------------------- */
/* A light's deep or colour map, timed as the translucent stage. */
static void translucent_light(stin_context *ctx, uint32_t li)
{
    stin_stage was = stin__times_enter(ctx, STIN_STAGE_TRANSLUCENT);
    stin__translucent_light(ctx, li);
    (void)stin__times_enter(ctx, was);
}

/* GL is the caller's until now (the projection was set at begin). */
static void stage_prepare(stin_context *ctx)
{
    stin__pass_forget(ctx); /* the caller's state is unknown */
    ctx->units_used = 0;
    ctx->draw_fbo = ctx->frame.framebuffer;
}

/* Light pre-passes (shadow maps): before the target is bound and cleared,
 * because without FBOs they draw in the frame's own buffer. */
static void stage_light_prepasses(stin_context *ctx)
{
    uint32_t i;
    stin__translucent_frame(ctx); /* deep and colour maps are made per light, before its lit pass */
    for (i = 0; i < ctx->draw_count; i++) /* which casters the translucent choice leaves out */
        ctx->draws[i].shadow_caster = (unsigned char)!stin__translucent_skips(ctx, &ctx->draws[i]);
    if (ctx->shadow->light_prepass && ctx->light_count)
        ctx->shadow->light_prepass(ctx);
}

static void stage_target(stin_context *ctx)
{
    const stin_frame_desc *f = &ctx->frame;
    stin__pass_state ps = stin__pass_defaults;
    if (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_FBO))
        GL(ctx, BindFramebuffer)(GL_FRAMEBUFFER, f->framebuffer);
    GL(ctx, Viewport)(f->viewport[0], f->viewport[1], f->viewport[2], f->viewport[3]);
    stin__pass_apply(ctx, &ps); /* writes on, no scissor: the clear covers the buffer */
    if (!f->keep_contents) {
        GL(ctx, ClearColor)(f->clear_color[0], f->clear_color[1], f->clear_color[2],
                            f->clear_color[3]);
        stin__clear_depth(ctx, 1.0);
        GL(ctx, ClearStencil)(0);
        GL(ctx, Clear)(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT |
                       (ctx->target.stencil_bits > 0 ? GL_STENCIL_BUFFER_BIT : 0u));
    }
}

/* How a light is shaded once its visibility is set up: the lit pass, or for
 * the visibility output the same pass with a flat white material at the
 * sample's weight (the shadow test is the technique's either way). */
static void shade_lit(stin_context *ctx, const stin__path *path, const stin_light_desc *l,
                      float weight)
{
    stin_stage was = stin__times_enter(ctx, STIN_STAGE_LIGHTING);
    (void)weight;
    path->lit(ctx, l);
    (void)stin__times_enter(ctx, was);
}

static void shade_flat(stin_context *ctx, const stin__path *path, const stin_light_desc *l,
                       float weight)
{
    float white[4];
    stin_stage was = stin__times_enter(ctx, STIN_STAGE_LIGHTING);
    white[0] = white[1] = white[2] = weight;
    white[3] = 1.0f;
    path->flat(ctx, STIN__ALL, white, l);
    (void)stin__times_enter(ctx, was);
}

/* Lights whose visibility the technique writes into the screen mask, in
 * groups of four: each group's visibility into the mask's channels, then
 * one lit pass (or, for the visibility output, light 0's flat pass) reading
 * them. With deep or colour maps, a group of one: its map is made first.
 * Returns 0 when the mask cannot be drawn; lights the technique
 * declines (area lights' samples) are left unmarked in `masked`. */
static int masked_lights(stin_context *ctx, const stin__path *path, uint32_t lights,
                         int visibility, unsigned char *masked)
{
    stin_light_desc group[STIN__MASK_CHANNELS];
    int size = stin__translucent_active(ctx) ? 1 : STIN__MASK_CHANNELS;
    uint32_t li = 0;
    while (li < lights) {
        int n = 0;
        uint32_t first = li;
        if (size == 1)
            translucent_light(ctx, li);
        if (!stin__mask_begin(ctx, path, visibility ? STIN__ALL : STIN__OPAQUE,
                              ctx->shadow->mask_depth)) {
            stin__translucent_light_done(ctx);
            return 0;
        }
        for (; li < lights && n < size && (size > 1 || li == first); li++)
            if (ctx->shadow->mask(ctx, path, li, n)) {
                masked[li] = 1;
                group[n++] = ctx->lights[li];
            }
        stin__mask_end(ctx);
        (void)stin__times_enter(ctx, STIN_STAGE_LIGHTING);
        if (n > 0 && visibility) {
            static const float white[4] = {1, 1, 1, 1};
            path->flat(ctx, STIN__ALL, white, &group[0]);
        } else if (n > 0) {
            path->lit_lights(ctx, group, n);
        }
        (void)stin__times_enter(ctx, STIN_STAGE_SHADOW);
        stin__mask_read_done(ctx);
        stin__translucent_light_done(ctx);
    }
    return 1;
}

/* A technique that counts against the frame's depth (volumes) pays the
 * mask a geometry pass of its own for that depth: with one point light,
 * counting in the frame's stencil and lighting where it allows is a pass
 * cheaper. An area light's samples add up in the mask and are lit once:
 * one lit pass instead of one a sample, and no 8-bit rounding a pass. */
static int mask_pays(const stin_context *ctx, uint32_t lights)
{
    const stin_light_desc *l = &ctx->lights[0];
    return !ctx->shadow->mask_depth || lights > 1 ||
           (lights == 1 && l->radius > 0.0f && l->type != STIN_LIGHT_DIRECTIONAL &&
            ctx->desc.shadows.soft_samples > 1);
}

/* Per light from `first` on (those before it lit already: the forward
 * pass): its visibility (stencil count, map test, screen mask) and its
 * lighting. The visibility output shows light 0 only. */
static void stage_lights(stin_context *ctx, const stin__path *path, int visibility,
                         uint32_t first)
{
    uint32_t li, lights = visibility ? (ctx->light_count > 0) : ctx->light_count;
    unsigned char masked[STIN__MAX_LIGHTS] = {0};
    stin_stage was = stin__times_enter(ctx, STIN_STAGE_SHADOW);
    for (li = 0; li < first && li < lights; li++)
        masked[li] = 1;
    if (ctx->shadow->mask && stin__mask_usable(ctx) && path->lit_lights &&
        mask_pays(ctx, lights))
        (void)masked_lights(ctx, path, lights, visibility, masked);
    for (li = 0; li < lights; li++)
        if (!masked[li]) {
            translucent_light(ctx, li);
            ctx->shadow->light(ctx, path, li, visibility ? shade_flat : shade_lit);
            stin__translucent_light_done(ctx);
        }
    stin__mask_frame_end(ctx);
    (void)stin__times_enter(ctx, was);
}

/* The forward pass's shading: light 0 and the ambient light in one pass
 * with depth writes, in the ambient pass's place. */
static void shade_forward(stin_context *ctx, const stin__path *path, const stin_light_desc *l,
                          float weight)
{
    stin_stage was = stin__times_enter(ctx, STIN_STAGE_LIGHTING);
    (void)weight;
    path->lit_ambient(ctx, l);
    (void)stin__times_enter(ctx, was);
}

/* 1 where the frame's opaque draws can take the ambient light and light 0
 * in one pass: the technique tests light 0 in the lit program itself (a
 * map sampled there) and nothing before the lights needs the frame's
 * depth on its own: no screen masks (they draw the depth into the mask
 * first), no CSG products (their faces go depth EQUAL on the resolved
 * depth), no deep or colour map made per light between the ambient and
 * lit passes, not the visibility output (its flat passes). The blended
 * draws, the export and the outline come after and find the same depth. */
static int forward_possible(const stin_context *ctx, const stin__path *path, int visibility)
{
    const stin__shadow_technique *t = ctx->shadow;
    return !visibility && path->lit_ambient && t->forward && !t->mask && t->fragment_test &&
           t->fragment_test(ctx, 0) && !stin__csg_product_count(ctx) &&
           !stin__translucent_active(ctx);
}

/* The opaque draws' first pass: ambient and light 0 at once where
 * forward_possible (returns 1: the lights from 1 on are left), else the
 * ambient pass (returns 0). A frame of one map-lit light draws each mesh
 * once from the camera instead of twice. */
static uint32_t stage_base(stin_context *ctx, const stin__path *path, int visibility)
{
    if (forward_possible(ctx, path, visibility)) {
        stin_stage was = stin__times_enter(ctx, STIN_STAGE_SHADOW);
        ctx->shadow->light(ctx, path, 0, shade_forward);
        (void)stin__times_enter(ctx, was);
        return 1;
    }
    path->ambient(ctx, visibility ? STIN__ALL : STIN__OPAQUE, visibility);
    return 0;
}

/* A peeled layer's lights without shadows, in batches of the path's size. */
static void unshadowed_lights(stin_context *ctx, const stin__path *path)
{
    uint32_t first;
    for (first = 0; first < ctx->light_count; first += STIN__LIGHTS_PER_PASS) {
        uint32_t n = ctx->light_count - first;
        path->lit_lights(ctx, ctx->lights + first,
                         (int)(n < STIN__LIGHTS_PER_PASS ? n : STIN__LIGHTS_PER_PASS));
    }
}

/* sorted, shadowed: one light's pass on the blended draw being lit. */
static void shade_sorted(stin_context *ctx, const stin__path *path, const stin_light_desc *l,
                         float weight)
{
    stin_stage was = stin__times_enter(ctx, STIN_STAGE_LIGHTING);
    (void)weight;
    path->blended_one(ctx, ctx->sorted_draw, l);
    (void)stin__times_enter(ctx, was);
}

/* sorted in a shadowed frame, where the technique tests a map per fragment:
 * each blended draw far to near, whole: its ambient pass over the frame
 * (dst (1 - a) + a ambient), then per light the technique's test around an
 * added pass at its opacity (+ a light_i). A point light's faces (map-pcf,
 * map-depth) and deep or colour maps are drawn again per draw. */
static void sorted_shadowed(stin_context *ctx, const stin__path *path)
{
    uint32_t i, li;
    for (i = 0; i < ctx->draw_count; i++) {
        const stin__draw *d = &ctx->draws[ctx->draw_order[i]];
        if (d->material.color[3] >= 1.0f)
            continue;
        ctx->sorted_draw = d;
        path->blended_one(ctx, d, NULL);
        for (li = 0; li < ctx->light_count; li++) {
            translucent_light(ctx, li);
            if (stin__sorted_light_shadowed(ctx, li)) {
                stin_stage was = stin__times_enter(ctx, STIN_STAGE_SHADOW);
                ctx->shadow->light(ctx, path, li, shade_sorted);
                (void)stin__times_enter(ctx, was);
            } else {
                shade_sorted(ctx, path, &ctx->lights[li], 1.0f);
            }
            stin__translucent_light_done(ctx);
        }
    }
    ctx->sorted_draw = NULL;
}

/* Peeled layers: each lit by the same stages as the opaque draws
 * (shadowed when the frame is and the technique's layers_begin agrees),
 * the technique's receivers made the layer's before its lights (vdsm: the
 * position buffer, so its per-light masks are the layer's) and the frame's
 * own again after the last layer; then composited over the frame. */
static void peeled_layers(stin_context *ctx, const stin__path *path, int shadowed)
{
    const stin__shadow_technique *t = ctx->shadow;
    shadowed = shadowed && (!t->layers_begin || t->layers_begin(ctx));
    while (stin__peel_layer_begin(ctx)) {
        path->ambient(ctx, STIN__OPAQUE, 0); /* the layer's depth, ambient and opacity */
        if (stin__peel_layer_lights(ctx)) {
            if (shadowed && t->layer)
                t->layer(ctx); /* the layer is the receiver now */
            if (shadowed)
                stage_lights(ctx, path, 0, 0);
            else
                unshadowed_lights(ctx, path);
        }
        stin__peel_layer_end(ctx);
    }
    stin__peel_end(ctx);
    if (shadowed && t->layers_end)
        t->layers_end(ctx, path);
}

/* Blended draws. depth-peel and dual-peel (behind the same stin__peel_*
 * calls): peeled_layers. sorted: per object far to near, lit and shadowed
 * light by light where the technique tests a map per fragment
 * (sorted_shadowed), else in the path's light batches unshadowed (logged by
 * stin__sorted_shadowed). */
static void blended_draws(stin_context *ctx, const stin__path *path, int shadowed)
{
    if (ctx->desc.debug_flags & STIN_DEBUG_TRANSPARENCY_OPAQUE_ONLY)
        return;
    if (stin__peel_begin(ctx, path)) {
        peeled_layers(ctx, path, shadowed);
        return;
    }
    stin__sorted_frame(ctx);
    if (shadowed && stin__sorted_shadowed(ctx))
        sorted_shadowed(ctx, path);
    else
        path->batches(ctx, STIN__BLENDED);
}

static void stage_blended(stin_context *ctx, const stin__path *path, int shadowed)
{
    stin_stage was = stin__times_enter(ctx, STIN_STAGE_BLENDED);
    blended_draws(ctx, path, shadowed);
    (void)stin__times_enter(ctx, was);
}

/* The frame plan. Stages: light pre-passes -> target -> depth and ambient ->
 * per light visibility and lighting -> blended draws -> the visibility
 * export. Without shadows (no technique, or no lights) the lighting is all
 * lights in batches of the path's size and the blended draws go with it. */
static void run_plan(stin_context *ctx)
{
    const stin__path *path = stin__path_of(ctx);
    int visibility = ctx->frame.output == STIN_OUTPUT_VISIBILITY;
    int shadowed = ctx->shadow->light && ctx->light_count > 0 && !ctx->target.shadows_off;
    stage_prepare(ctx);
    stin__times_begin(ctx, STIN_STAGE_PREPASS);
    stage_light_prepasses(ctx);
    (void)stin__times_enter(ctx, STIN_STAGE_BASE);
    stage_target(ctx);
    path->begin(ctx);
    if (stin__csg_product_count(ctx))
        (void)stin__times_enter(ctx, STIN_STAGE_CSG);
    if (stin__csg_resolve(ctx, path)) { /* the products' depth, under every later pass */
        stin__csg_faces(ctx);
        if (ctx->shadow->after_csg)
            ctx->shadow->after_csg(ctx, path);
    }
    (void)stin__times_enter(ctx, STIN_STAGE_BASE);
    if (ctx->frame.export_visibility == STIN_EXPORT_VISIBILITY_ONLY) {
        path->ambient(ctx, STIN__OPAQUE, 1); /* the depth the application shades against */
    } else if (ctx->frame.output == STIN_OUTPUT_NORMAL) {
        path->normals(ctx);
    } else if (shadowed) {
        stage_lights(ctx, path, visibility, stage_base(ctx, path, visibility));
        if (!visibility)
            stage_blended(ctx, path, 1);
    } else if (visibility) {
        static const float white[4] = {1, 1, 1, 1};
        path->ambient(ctx, STIN__ALL, 1);
        path->flat(ctx, STIN__ALL, white, NULL);
    } else {
        path->batches(ctx, STIN__OPAQUE);
        stage_blended(ctx, path, 0);
    }
    if (shadowed && ctx->shadow->debug_overlay)
        ctx->shadow->debug_overlay(ctx, path);
    (void)stin__times_enter(ctx, STIN_STAGE_EXPORT);
    stin__export_stage(ctx, path, shadowed);
    stin__outline_stage(ctx, path);
    path->end(ctx);
    stin__times_end(ctx);
}

stin_result stin_end_frame(stin_context *ctx)
{
    uint32_t i;
    if (!ctx)
        return STIN_ERROR_INVALID_ARGUMENT;
    if (ctx->state != STIN__IN_FRAME)
        return state_error(ctx, "stin_end_frame", "no frame is open");
    if (stin__target_check(ctx, ctx->frame.framebuffer, "stin_end_frame") != STIN_OK) {
        ctx->state = STIN__IDLE; /* nothing drawn: the target went bad since begin */
        return STIN_ERROR_INVALID_ARGUMENT;
    }
    order_draws(ctx);
    ctx->stats.draws = ctx->draw_count;
    ctx->stats.lights = ctx->light_count;
    for (i = 0; i < ctx->draw_count; i++)
        ctx->stats.triangles += ctx->meshes[ctx->draws[i].mesh_slot].triangle_count;
    stin__state_save(ctx);
    stin__frame_choice_plan(ctx);
    run_plan(ctx);
    stin__frame_choice_end(ctx);
    stin__state_restore(ctx);
    ctx->state = STIN__IDLE;
    return STIN_OK;
}
