/* SPDX-License-Identifier: MIT */
/* Context creation in the caller's block: defaults, layout, detection,
 * selection and set-up of the chosen path. */
#include "internal.h"

#define DEFAULT(v, d) ((v) ? (v) : (d))
/* displacement.tess_pixels' floor: an edge split finer than a pixel adds
 * no detail a pixel shows, while the triangles grow with the square of
 * 1 / tess_pixels (a 512-triangle grid at 0.02 took minutes a frame). */
#define TESS_PIXELS_MIN 1.0f

stin_desc stin__desc_defaults(const stin_desc *desc)
{
    stin_desc d = *desc;
    d.max_meshes = DEFAULT(d.max_meshes, 64u);
    d.max_textures = DEFAULT(d.max_textures, 64u);
    d.max_draws = DEFAULT(d.max_draws, 1024u);
    d.max_lights = DEFAULT(d.max_lights, 8u);
    d.max_vertices = DEFAULT(d.max_vertices, 262144u);
    d.max_triangles = DEFAULT(d.max_triangles, 262144u);
    d.max_mesh_triangles = DEFAULT(d.max_mesh_triangles, d.max_triangles < 65536u ? d.max_triangles : 65536u);
    d.max_texture_bytes = DEFAULT(d.max_texture_bytes, 8u << 20);
    d.shadows.soft_samples = DEFAULT(d.shadows.soft_samples, 32u);
    d.shadows.map_size = DEFAULT(d.shadows.map_size, 1024u);
    d.shadows.choice_frames = DEFAULT(d.shadows.choice_frames, STIN__CHOICE_FRAMES);
    d.csg.max_primitives = DEFAULT(d.csg.max_primitives, 256u);
    d.csg.max_terms = DEFAULT(d.csg.max_terms, 256u);
    d.csg.max_literals = DEFAULT(d.csg.max_literals, 4096u);
    d.translucent.deep_layers = DEFAULT(d.translucent.deep_layers, 4u);
    d.translucent.deep_map_size = DEFAULT(d.translucent.deep_map_size, 512u);
    d.transparency.layers = DEFAULT(d.transparency.layers, 8u);
    d.csg.interval_layers = DEFAULT(d.csg.interval_layers, 4u);
    if (d.displacement.guard_band == 0.0f)
        d.displacement.guard_band = 1.0f;
    if (d.displacement.tess_pixels == 0.0f)
        d.displacement.tess_pixels = 4.0f;
    else if (d.displacement.tess_pixels > 0.0f && d.displacement.tess_pixels < TESS_PIXELS_MIN)
        d.displacement.tess_pixels = TESS_PIXELS_MIN; /* logged by stin_create */
    if (d.translucent.opaque_threshold == 0.0f)
        d.translucent.opaque_threshold = 0.5f;
    d.displacement.tess_max = DEFAULT(d.displacement.tess_max, 64u);
    return d;
}

static int desc_valid(const stin_desc *d)
{
    char unused[8];
    return stin__forced_known(d->tier, d->techniques, unused, sizeof unused) &&
           d->max_lights <= 32 && d->shadows.soft_samples <= 64 &&
           d->shadows.map_size <= 8192 && (d->shadows.map_size & (d->shadows.map_size - 1)) == 0 &&
           d->shadows.choice_frames <= 100000u &&
           d->max_meshes <= 65535 && d->max_textures <= 65535 &&
           d->max_mesh_triangles <= d->max_triangles && d->max_vertices < 0x40000000u &&
           d->max_triangles < 0x20000000u && d->max_draws < 0x1000000u &&
           d->displacement.guard_band >= 0.0f && d->displacement.guard_band <= 1e30f &&
           d->displacement.tess_pixels > 0.0f && d->displacement.tess_pixels <= 1e30f &&
           d->displacement.tess_max <= 64u &&
           d->csg.max_primitives < 0x1000000u && d->csg.max_terms < 0x1000000u &&
           d->csg.max_literals < 0x1000000u &&

           d->translucent.deep_layers <= 16 && d->translucent.deep_map_size <= 4096 &&
           (d->translucent.deep_map_size & (d->translucent.deep_map_size - 1)) == 0 && (d->translucent.deep_mono & ~1) == 0 &&
           d->translucent.opaque_threshold > 0.0f && d->translucent.opaque_threshold <= 1.0f &&
           d->transparency.layers <= STIN__PEEL_MAX_LAYERS &&
           d->csg.interval_layers <= STIN__CSG_INTERVAL_MAX_LAYERS;
}

static uint32_t mesh_vertex_limit(const stin_desc *d)
{
    uint64_t v = (uint64_t)d->max_mesh_triangles * 3u;
    return v < d->max_vertices ? (uint32_t)v : d->max_vertices;
}

/* Vertices of one chunk of shadow-volume triangles (16 bytes each). */
#define VOLUME_CHUNK_VERTICES (3u * 8192u)

/* The per-frame scratch: volumes need a facing byte per triangle and a
 * vertex chunk, DOT3 six floats per vertex, of the biggest mesh. */
static size_t frame_scratch_bytes(const stin_desc *d)
{
    size_t volumes = stin__align16(d->max_mesh_triangles) + 16u * VOLUME_CHUNK_VERTICES;
    size_t dot3 = (size_t)mesh_vertex_limit(d) * 6u * sizeof(float);
    return volumes > dot3 ? volumes : dot3;
}

/* One layout for sizing (ctx NULL) and for carving. */
static void *take(stin__arena *a, size_t bytes, int *ok)
{
    size_t start = stin__align16(a->used);
    if (start + bytes < start) {
        *ok = 0;
        return NULL;
    }
    a->used = start + bytes;
    if (!a->base)
        return NULL;
    if (a->used > a->size) {
        *ok = 0;
        return NULL;
    }
    return a->base + start;
}

static size_t layout(const stin_desc *d, stin__arena *a, stin_context *ctx)
{
    int ok = 1;
    uint32_t mv = mesh_vertex_limit(d);
    size_t scratch = stin__adjacency_scratch_bytes(mv, d->max_mesh_triangles);
    size_t tangent_scratch = (size_t)mv * 6u * sizeof(float);
    size_t frame_scratch = frame_scratch_bytes(d);
    void *p[15];
    uint32_t chunks = stin__index_chunks_max(d->max_mesh_triangles);
    size_t i;
    if (tangent_scratch > scratch)
        scratch = tangent_scratch;
    p[0] = take(a, sizeof(stin_context), &ok);
    /* stin's own mesh (assets/mesh.c: stin__mesh_builtin) after the caller's */
    p[1] = take(a, sizeof(stin__mesh_slot) * ((size_t)d->max_meshes + 1u), &ok);
    p[2] = take(a, sizeof(stin__texture_slot) * d->max_textures, &ok);
    p[3] = take(a, sizeof(stin__vertex) * ((size_t)d->max_vertices + STIN__BUILTIN_VERTICES), &ok);
    p[4] = take(a, sizeof(uint32_t) * 3u * ((size_t)d->max_triangles + STIN__BUILTIN_TRIANGLES),
                &ok);
    p[5] = take(a, sizeof(uint32_t) * 3u * ((size_t)d->max_triangles + STIN__BUILTIN_TRIANGLES),
                &ok);
    p[6] = take(a, sizeof(stin__range) * d->max_meshes, &ok);
    p[7] = take(a, sizeof(stin__range) * d->max_meshes, &ok);
    p[8] = take(a, scratch, &ok);
    p[9] = take(a, d->max_texture_bytes, &ok);
    p[10] = take(a, sizeof(stin__draw) * d->max_draws + sizeof(uint32_t) * d->max_draws, &ok);
    p[11] = take(a, sizeof(stin_light_desc) * d->max_lights, &ok);
    p[12] = take(a, frame_scratch, &ok);
    p[13] = take(a, sizeof(uint32_t) * ((size_t)d->max_vertices + STIN__BUILTIN_VERTICES), &ok);
    p[14] = take(a, sizeof(stin__index_chunk) * chunks * ((size_t)d->max_meshes + 1u), &ok);
    for (i = 0; i < stin__state_slot_count; i++) {
        const stin__state_slot *slot = &stin__state_slots[i];
        size_t bytes = slot->bytes(d);
        void *state = take(a, bytes, &ok);
        if (ctx && ok) {
            stin__memzero(state, bytes); /* the block is the caller's: nothing in it is zero */
            if (slot->place)
                slot->place(state, d);
            stin__memcopy((unsigned char *)ctx + slot->offset, &state, sizeof state);
        }
    }
    if (!ok)
        return 0;
    if (ctx) {
        ctx->meshes = (stin__mesh_slot *)p[1];
        ctx->textures = (stin__texture_slot *)p[2];
        ctx->vertices = (stin__vertex *)p[3];
        ctx->indices = (uint32_t *)p[4];
        ctx->adjacency = (uint32_t *)p[5];
        ctx->vertex_range_store = (stin__range *)p[6];
        ctx->triangle_range_store = (stin__range *)p[7];
        ctx->scratch = (unsigned char *)p[8];
        ctx->scratch_bytes = scratch;
        ctx->staging = (unsigned char *)p[9];
        ctx->staging_bytes = d->max_texture_bytes;
        ctx->draws = (stin__draw *)p[10];
        ctx->draw_order = (uint32_t *)(void *)((unsigned char *)p[10] +
                                               sizeof(stin__draw) * d->max_draws);
        ctx->lights = (stin_light_desc *)p[11];
        ctx->frame_scratch = (unsigned char *)p[12];
        ctx->frame_scratch_bytes = frame_scratch;
        ctx->welds = (uint32_t *)p[13];
        ctx->index_chunks = (stin__index_chunk *)p[14];
        ctx->index_chunks_per_mesh = chunks;
    }
    return stin__align16(a->used) + 16u; /* slack for aligning the caller's block */
}

size_t stin_memory_size(const stin_desc *desc)
{
    stin_desc d;
    stin__arena a;
    if (!desc)
        return 0;
    d = stin__desc_defaults(desc);
    if (!desc_valid(&d))
        return 0;
    a.base = NULL;
    a.size = (size_t)-1;
    a.used = 0;
    return layout(&d, &a, NULL);
}

uint64_t stin_deep_memory_bytes(const stin_desc *desc)
{
    stin_desc d;
    uint64_t texels;
    if (!desc)
        return 0;
    d = stin__desc_defaults(desc);
    if (!desc_valid(&d))
        return 0;
    texels = (uint64_t)d.translucent.deep_map_size * d.translucent.deep_map_size;
    return 2u * STIN__CUBE_FACES * stin__deep_slices(d.translucent.deep_layers) * texels * 16u + texels * 4u;
}

static void log_early(const stin_desc *d, stin_log_level level, stin_log_item item,
                      const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    stin__logv(d->log, d->log_user, level, item, fmt, ap);
    va_end(ap);
}

/* The lighting path; a shader failure walks one tier down and says so, and
 * the features that ran on the old lighting choose again. */
static stin_result init_lighting(stin_context *ctx)
{
    stin_choice *c = &ctx->sel.choice[STIN_FEATURE_LIGHTING];
    char msg[160], why[200];
    for (;;) {
        stin_technique next;
        stin_result r;
        if (c->technique == STIN_TECH_LIGHTING_FIXED)
            return stin__dot3_init(ctx); /* the pipeline is fixed; DOT3 needs its cube map */
        if (stin__glsl_init(ctx, c->technique == STIN_TECH_LIGHTING_GLSL150 ? STIN_TIER_GL4
                                                                             : STIN_TIER_GL2,
                            msg, sizeof msg) == STIN_OK)
            return STIN_OK;
        next = c->technique == STIN_TECH_LIGHTING_GLSL150 ? STIN_TECH_LIGHTING_GLSL110
                                                          : STIN_TECH_LIGHTING_FIXED;
        if (stin__needs_here(&ctx->caps, stin__technique_needs(next)) & ~ctx->caps.present)
            next = STIN_TECH_LIGHTING_FIXED;
        if (stin__needs_here(&ctx->caps, stin__technique_needs(next)) & ~ctx->caps.present) {
            stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_FALLBACK,
                      "lighting: %s failed (%s) and nothing below it runs here",
                      stin_technique_name(c->technique), msg);
            return STIN_ERROR_GL;
        }
        stin__formatf(why, sizeof why, "%s failed to build (%s)",
                      stin_technique_name(c->technique), msg);
        stin__demote(ctx, STIN_FEATURE_LIGHTING, next, why);
        r = stin__select_after_lighting(&ctx->caps, ctx->desc.techniques, &ctx->sel, msg,
                                        sizeof msg);
        if (r != STIN_OK) {
            stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_TECHNIQUE_UNSUPPORTED, "stin_create: %s",
                      msg);
            return r;
        }
        ctx->shadow = stin__shadow_technique_of(ctx->sel.choice[STIN_FEATURE_SHADOWS].technique);
        stin__selection_hand_down(ctx); /* the choice may have stepped down too */
    }
}

/* The shadow module's set-up; a module that cannot run here releases what
 * it made and demotes itself (stin__demote), and the next one is set up. */
static stin_result init_shadows(stin_context *ctx)
{
    for (;;) {
        stin_technique t = ctx->sel.choice[STIN_FEATURE_SHADOWS].technique;
        stin_result r;
        ctx->shadow = stin__shadow_technique_of(t);
        stin__mask_init(ctx); /* for this technique's units */
        if (!ctx->shadow->init)
            return STIN_OK;
        r = ctx->shadow->init(ctx);
        if (r != STIN_OK || ctx->sel.choice[STIN_FEATURE_SHADOWS].technique == t)
            return r;
    }
}

/* A missing GL 1.1 entry point is fatal (it would be called); a missing
 * extension entry point turns its capability off. Both are named. */
static stin_result check_entry_points(stin_context *ctx)
{
    stin_result r = STIN_OK;
    int i, es = stin__gl_is_es(&ctx->gl), desktop_only = 0;
    for (i = 0; i < STIN_GLFN_COUNT; i++) {
        int need = stin__glfn_need((stin__glfn)i);
        if (ctx->gl_loaded[i])
            continue;
        if (!es && need == NEED_ES)
            continue; /* glClearDepthf and the like: called on ES only */
        if (es && stin__glfn_desktop_only((stin__glfn)i)) {
            desktop_only++; /* expected there: one line for them all */
            continue;
        }
        if (need == NEED_CORE || (need == NEED_DESKTOP && !es)) {
            stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_MISSING_ENTRY_POINT,
                      "stin_create: GL 1.1 entry point %s did not load",
                      stin__glfn_name((stin__glfn)i));
            r = STIN_ERROR_GL;
        } else {
            stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_MISSING_ENTRY_POINT,
                      "%s did not load: %s is off", stin__glfn_name((stin__glfn)i),
                      stin__need_name(need));
        }
    }
    if (desktop_only)
        stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_MISSING_ENTRY_POINT,
                  "OpenGL ES: %d desktop-only entry points are not used", desktop_only);
    return r;
}

static void log_selection(stin_context *ctx)
{
    char names[512];
    int f;
    stin__cap_names(ctx->caps.present, names, sizeof names);
    stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_CAPS, "\"%s\": %s %d.%d, GLSL %d.%d, %s: %s",
              (const char *)GL(ctx, GetString)(GL_VERSION), ctx->caps.es ? "OpenGL ES" : "GL",
              ctx->caps.gl_major, ctx->caps.gl_minor, ctx->caps.glsl_major,
              ctx->caps.glsl_minor,
              ctx->caps.es ? "ES"
              : ctx->caps.profile == STIN_GL_PROFILE_CORE ? "core" : "compatibility", names);
    if (ctx->caps.hidden) {
        stin__cap_names(ctx->caps.hidden, names, sizeof names);
        stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_CAPS, "hidden by the caps mask: %s", names);
    }
    stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_TIER_SELECTED, "tier %s (%s)",
              stin_tier_name(ctx->sel.tier),
              ctx->desc.tier == STIN_TIER_AUTO ? "best available" : "forced");
    for (f = 0; f < STIN_FEATURE_COUNT; f++) {
        const stin_choice *c = &ctx->sel.choice[f];
        stin__log(ctx, STIN_LOG_LEVEL_INFO,
                  c->fell_back ? STIN_LOG_FALLBACK : STIN_LOG_TECHNIQUE_SELECTED,
                  "%s: %s (%s)", stin_feature_name((stin_feature)f),
                  stin_technique_name(c->technique), c->reason);
    }
}

/* Every GL object the context made at set-up (each release is a no-op for
 * what was never made). */
static void release_gl(stin_context *ctx)
{
    stin__glsl_release(ctx);
    stin__dot3_release(ctx);
    stin__choice_release(ctx); /* volumes' objects; ctx->shadow back to the selection's */
    if (ctx->shadow && ctx->shadow->release)
        ctx->shadow->release(ctx);
    stin__mask_release(ctx);
    stin__export_release(ctx);
    stin__outline_release(ctx);
    stin__csg_interval_release(ctx);
    stin__csg_release(ctx);
    stin__deep_release(ctx);
    stin__coloured_release(ctx);
    stin__peel_release(ctx);
    stin__times_release(ctx);
}

/* Selection and every module's GL set-up. The caller's framebuffer
 * binding survives it: the modules bind their own targets and leave 0
 * bound, and a fixed-function frame's glPopAttrib gives the read buffer
 * of the binding at its push back to the frame's target (GL_FRONT into
 * an FBO: GL_INVALID_OPERATION). */
static stin_result set_up(stin_context *ctx)
{
    char msg[256];
    GLint fb[2] = {0, 0};
    int fbo = (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_FBO)) != 0;
    stin_result r = stin__select(&ctx->caps, ctx->desc.tier, ctx->desc.techniques, &ctx->sel,
                                 msg, sizeof msg);
    if (r != STIN_OK) {
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, ctx->sel.failure, "stin_create: %s", msg);
        return r;
    }
    if (fbo)
        stin__framebuffer_save(ctx, fb);
    ctx->shadow = stin__shadow_technique_of(ctx->sel.choice[STIN_FEATURE_SHADOWS].technique);
    stin__selection_hand_down(ctx); /* before the first program is built */
    stin__hooks_install_paths(ctx); /* the lighting path builds the features' chunks in */
    r = init_lighting(ctx);
    if (r == STIN_OK)
        r = init_shadows(ctx);
    if (r == STIN_OK) {
        stin__deep_init(ctx);
        stin__coloured_init(ctx);
        if (fbo) /* before the choices that look at the bound framebuffer */
            stin__framebuffer_restore(ctx, fb);
        stin__peel_init(ctx);
        stin__displace_init(ctx);
        stin__csg_init(ctx);
        stin__csg_interval_init(ctx);
        stin__hooks_install(ctx); /* after csg's init, which may turn it off */
        stin__outline_init(ctx);
        stin__times_init(ctx);
        stin__choice_init(ctx); /* volumes beside vdsm, after every choice is final */
    }
    if (r != STIN_OK)
        release_gl(ctx); /* nothing half-made stays behind */
    if (fbo)
        stin__framebuffer_restore(ctx, fb);
    return r;
}

stin_result stin_create(const stin_desc *desc, void *memory, size_t memory_bytes,
                        stin_context **out)
{
    stin_desc d;
    stin__arena a;
    stin_context *ctx;
    size_t need;
    uint32_t serial;
    stin__create_bindings bindings;
    stin_result r;
    char msg[256];
    if (out)
        *out = NULL;
    if (!desc || !out || !desc->get_proc_address) {
        if (desc)
            log_early(desc, STIN_LOG_LEVEL_ERROR, STIN_LOG_BAD_ARGUMENT,
                      "stin_create: desc, out and desc->get_proc_address are required");
        return STIN_ERROR_INVALID_ARGUMENT;
    }
    d = stin__desc_defaults(desc);
    if (!stin__forced_known(d.tier, d.techniques, msg, sizeof msg)) {
        log_early(&d, STIN_LOG_LEVEL_ERROR, STIN_LOG_BAD_ARGUMENT, "stin_create: %s", msg);
        return STIN_ERROR_INVALID_ARGUMENT;
    }
    need = stin_memory_size(desc);
    if (!need) {
        log_early(&d, STIN_LOG_LEVEL_ERROR, STIN_LOG_BAD_ARGUMENT,
                  "stin_create: capacities out of range (max_lights <= 32, "
                  "max_mesh_triangles <= max_triangles, shadows.soft_samples <= 64, "
                  "shadows.map_size a power of two <= 8192, shadows.choice_frames <= 100000, "
                  "translucent.deep_layers <= 16, "
                  "translucent.deep_map_size a power of two <= 4096, translucent.deep_mono 0 or 1, "
                  "translucent.opaque_threshold in (0, 1], transparency.layers <= 64)");
        return STIN_ERROR_INVALID_ARGUMENT;
    }
    if (!memory || memory_bytes < need) {
        log_early(&d, STIN_LOG_LEVEL_ERROR, STIN_LOG_ARENA_TOO_SMALL,
                  "stin_create: memory block of %zu bytes is too small: this configuration "
                  "needs %zu bytes (stin_memory_size)", memory ? memory_bytes : (size_t)0, need);
        return STIN_ERROR_OUT_OF_MEMORY;
    }
    /* Align the block start; layout() reserved 16 bytes of slack for this. */
    a.base = (unsigned char *)memory + ((16u - ((uintptr_t)memory & 15u)) & 15u);
    a.size = memory_bytes - (size_t)(a.base - (unsigned char *)memory);
    a.used = 0;
    ctx = (stin_context *)(void *)a.base;
    /* The serial of the context made here before survives the clear (read
     * bytewise: a fresh block holds any value), so this one's handles carry
     * another tag and the old context's handles do not resolve here. */
    stin__memcopy(&serial, &ctx->creation_serial, sizeof serial);
    stin__memzero(ctx, sizeof *ctx);
    ctx->creation_serial = serial + 1u;
    ctx->handle_tag = stin__handle_tag(ctx->creation_serial, ctx);
    layout(&d, &a, ctx);
    ctx->desc = d;
    if (desc->displacement.tess_pixels != d.displacement.tess_pixels &&
        desc->displacement.tess_pixels != 0.0f)
        stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_BAD_ARGUMENT,
                  "stin_create: displacement.tess_pixels %f raised to %f: tessellation splits "
                  "no edge finer than a pixel", (double)desc->displacement.tess_pixels,
                  (double)TESS_PIXELS_MIN);
    /* The block is the caller's: nothing in it is assumed zero. */
    stin__memzero(ctx->meshes, sizeof(stin__mesh_slot) * (d.max_meshes + 1u));
    stin__memzero(ctx->textures, sizeof(stin__texture_slot) * d.max_textures);
    stin__range_init(&ctx->vertex_ranges, ctx->vertex_range_store, d.max_meshes, d.max_vertices);
    stin__range_init(&ctx->triangle_ranges, ctx->triangle_range_store, d.max_meshes,
                     d.max_triangles);

    if (stin__gl_load(&ctx->gl, d.get_proc_address, d.get_proc_user, ctx->gl_loaded)) {
        r = check_entry_points(ctx);
        if (r != STIN_OK)
            return r;
    }
    r = stin__caps_detect(&ctx->gl, ctx->gl_loaded,
                          d.caps_mask | (d.debug_flags & STIN_DEBUG_NO_DERIVATIVES
                                             ? STIN_CAP_BIT(STIN_CAP_DERIVATIVES)
                                             : 0u),
                          d.max_gl_version, &ctx->caps);
    if (r != STIN_OK) {
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_CAPS,
                  "stin_create: no current GL context (GL_VERSION unreadable)");
        return r;
    }
    stin__gl_audit_install(ctx); /* checked build: ES calls' enums audited from here */
    stin__target_init(ctx);
    stin__caller_detect(ctx);
    stin__create_bindings_save(ctx, &bindings);
    r = set_up(ctx);
    stin__create_bindings_restore(ctx, &bindings);
    if (r != STIN_OK)
        return r;
    ctx->lights_per_pass = STIN__LIGHTS_PER_PASS;
    if (ctx->sel.choice[STIN_FEATURE_LIGHTING].technique == STIN_TECH_LIGHTING_FIXED &&
        ctx->caps.max_lights < ctx->lights_per_pass)
        ctx->lights_per_pass = ctx->caps.max_lights > 0 ? ctx->caps.max_lights : 1;
    log_selection(ctx);
    *out = ctx;
    return STIN_OK;
}

void stin_destroy(stin_context *ctx)
{
    if (!ctx)
        return;
    stin__mesh_release_all(ctx);
    stin__texture_release_all(ctx);
    release_gl(ctx);
    stin__gl_audit_forget(ctx);
}

stin_desc stin_query_desc(const stin_context *ctx)
{
    stin_desc empty;
    if (ctx)
        return ctx->desc;
    stin__memzero(&empty, sizeof empty);
    return empty;
}

const stin_caps *stin_query_caps(const stin_context *ctx) { return ctx ? &ctx->caps : NULL; }

stin_tier stin_query_tier(const stin_context *ctx) { return ctx ? ctx->sel.tier : STIN_TIER_AUTO; }

stin_choice stin_query_choice(const stin_context *ctx, stin_feature feature)
{
    stin_choice none;
    if (ctx && (unsigned)feature < STIN_FEATURE_COUNT)
        return ctx->sel.choice[feature];
    stin__memzero(&none, sizeof none);
    return none;
}

stin_frame_stats stin_query_frame_stats(const stin_context *ctx)
{
    stin_frame_stats none;
    if (ctx)
        return ctx->stats;
    stin__memzero(&none, sizeof none);
    return none;
}
