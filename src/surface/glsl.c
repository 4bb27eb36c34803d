/* SPDX-License-Identifier: MIT */
/* GL2/GL4 surface detail: the lit program's surface chunks (normal mapping,
 * parallax with offset limiting, parallax occlusion mapping), which variant a
 * draw gets, and the per-draw surface inputs. The programs themselves are
 * built and switched in render/path_glsl.c, which calls these as the
 * surface's hooks (render/path_features.h); shaders/gl2|gl4/surface_*.glsl
 * hold the GLSL. Texture units: albedo 0, normal map 1, height map 2. */
#include "internal.h"

#define LOG_KEYS 32 /* materials whose step down is logged once */

struct stin__surf_glsl_state {
    int units_bound;      /* the surface units hold textures this frame */
    uint32_t logged[LOG_KEYS]; /* per-material step-downs already logged */
    uint32_t logged_count;
};

size_t stin__surf_glsl_state_bytes(const stin_desc *d)
{
    (void)d;
    return sizeof(struct stin__surf_glsl_state);
}

static const char *const variant_chunk[STIN__SURF_COUNT] = {
    "surface_plain.glsl", "surface_normal.glsl", "surface_parallax.glsl", "surface_pom.glsl"};

static const stin_technique variant_tech[STIN__SURF_COUNT] = {
    STIN_TECH_SURFACE_PLAIN, STIN_TECH_SURFACE_NORMAL, STIN_TECH_SURFACE_PARALLAX,
    STIN_TECH_SURFACE_POM};

static int variant_of(stin_technique t)
{
    switch (t) {
    case STIN_TECH_SURFACE_POM: return STIN__SURF_POM;
    case STIN_TECH_SURFACE_PARALLAX: return STIN__SURF_PARALLAX;
    case STIN_TECH_SURFACE_NORMAL:
    case STIN_TECH_SURFACE_DOT3: /* GL1's normal mapping: asks for normal mapping at most */
        return STIN__SURF_NORMAL;
    default: return STIN__SURF_PLAIN;
    }
}

static stin_technique technique_of(int variant)
{
    return (unsigned)variant < STIN__SURF_COUNT ? variant_tech[variant] : STIN_TECH_SURFACE_PLAIN;
}

int stin__surf_variant_top(const stin_context *ctx)
{
    stin_technique t = ctx->sel.choice[STIN_FEATURE_SURFACE].technique;
    return t == STIN_TECH_SURFACE_DOT3 ? STIN__SURF_PLAIN /* not chosen with GLSL lighting */
                                       : variant_of(t);
}

void stin__surf_variant_failed(stin_context *ctx, int built, const char *msg)
{
    char why[200];
    stin__formatf(why, sizeof why, "%s failed to build (%s)",
                  stin_technique_name(technique_of(built + 1)), msg);
    stin__demote(ctx, STIN_FEATURE_SURFACE, technique_of(built), why);
}

int stin__surf_chunks(const stin_context *ctx, int variant,
                      const char *names[STIN__FEATURE_CHUNKS])
{
    int n = 0;
    (void)ctx; /* every context has them */
    if (variant != STIN__SURF_PLAIN)
        names[n++] = "surface_frame.glsl";
    names[n++] = variant_chunk[(unsigned)variant < STIN__SURF_COUNT ? variant : 0];
    return n;
}

/* A small hash of what decides a draw's step down: logged once per key. */
static uint32_t step_key(const stin_material *m, int want, int got)
{
    uint32_t h = 2166136261u;
    uint32_t parts[5];
    int i;
    parts[0] = m->normal_map.id;
    parts[1] = m->height_map.id;
    parts[2] = (uint32_t)m->surface;
    parts[3] = (uint32_t)want;
    parts[4] = (uint32_t)got;
    for (i = 0; i < 5; i++)
        h = (h ^ parts[i]) * 16777619u;
    return h ? h : 1u;
}

static void log_step_once(stin_context *ctx, const stin_material *m, int want, int got,
                          const char *why)
{
    uint32_t key = step_key(m, want, got), i;
    for (i = 0; i < ctx->surf_glsl->logged_count; i++)
        if (ctx->surf_glsl->logged[i] == key)
            return;
    if (ctx->surf_glsl->logged_count == LOG_KEYS)
        return; /* said enough; the log stays quiet per frame */
    ctx->surf_glsl->logged[ctx->surf_glsl->logged_count++] = key;
    stin__log(ctx, STIN_LOG_LEVEL_INFO, STIN_LOG_FALLBACK,
              "surface: a material (normal map 0x%x, height map 0x%x) falls back from %s to %s: %s",
              m->normal_map.id, m->height_map.id, stin_technique_name(variant_tech[want]),
              stin_technique_name(variant_tech[got]), why);
}

int stin__surf_variant_for(stin_context *ctx, const stin_material *m)
{
    int want = stin__glsl_best_variant(ctx), v;
    if (m->surface != STIN_TECH_NONE) {
        int asked = variant_of(m->surface);
        if (asked < want)
            want = asked; /* the material's own request: not a fallback */
    }
    if (want > STIN__SURF_NORMAL && stin__displace_active(ctx, m))
        want = STIN__SURF_NORMAL; /* the relief is geometry: no parallax on top */
    v = want;
    if (v > STIN__SURF_PLAIN && !stin__texture_lookup(ctx, m->normal_map)) {
        v = STIN__SURF_PLAIN;
        log_step_once(ctx, m, want, v, "no normal map");
    } else if (v > STIN__SURF_NORMAL && !stin__texture_lookup(ctx, m->height_map)) {
        v = STIN__SURF_NORMAL;
        log_step_once(ctx, m, want, v, "no height map");
    }
    return v;
}

void stin__surf_locate(stin_context *ctx, stin__program *p)
{
    p->u_normal_tex = GL(ctx, GetUniformLocation)(p->name, "u_normal_tex");
    p->u_height_tex = GL(ctx, GetUniformLocation)(p->name, "u_height_tex");
    p->u_surface = GL(ctx, GetUniformLocation)(p->name, "u_surface");
    p->u_self_shadow = GL(ctx, GetUniformLocation)(p->name, "u_self_shadow");
}

void stin__surf_units(stin_context *ctx, const stin__program *p)
{
    if (p->u_normal_tex >= 0)
        GL(ctx, Uniform1i)(p->u_normal_tex, 1);
    if (p->u_height_tex >= 0)
        GL(ctx, Uniform1i)(p->u_height_tex, 2);
}

static void bind_unit(stin_context *ctx, int unit, const stin__texture_slot *t)
{
    GL(ctx, ActiveTexture)((GLenum)(GL_TEXTURE0 + (GLenum)unit));
    GL(ctx, BindTexture)(GL_TEXTURE_2D, t ? t->name : 0);
}

void stin__surf_material(stin_context *ctx, const stin__program *p, const stin_material *m,
                         int variant)
{
    float s[4];
    if (variant == STIN__SURF_PLAIN)
        return;
    bind_unit(ctx, 1, stin__texture_lookup(ctx, m->normal_map));
    bind_unit(ctx, 2, variant >= STIN__SURF_PARALLAX ? stin__texture_lookup(ctx, m->height_map)
                                                     : NULL);
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
    ctx->surf_glsl->units_bound = 1;
    s[0] = m->height_scale;
    s[1] = m->height_bias;
    s[2] = (float)m->pom_min_steps;
    s[3] = (float)m->pom_max_steps;
    if (p->u_surface >= 0)
        GL(ctx, Uniform4fv)(p->u_surface, 1, s);
    if (p->u_self_shadow >= 0)
        GL(ctx, Uniform1i)(p->u_self_shadow, m->self_shadow);
}

void stin__surf_unbind(stin_context *ctx)
{
    if (!ctx->surf_glsl->units_bound)
        return;
    bind_unit(ctx, 2, NULL);
    bind_unit(ctx, 1, NULL);
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
    ctx->surf_glsl->units_bound = 0;
}
