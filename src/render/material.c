/* SPDX-License-Identifier: MIT */
/* A draw's material checked and completed: stin_draw's and
 * stin_draw_csg's one set of rules (finite values, ranges, live textures,
 * defaults), below both the frame and CSG that call it. */
#include "internal.h"

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

/* A material checked (finite values, ranges, live textures) and its
 * defaults applied; errors are logged as `call`'s, the item `dropped`. */
stin_result stin__material_prepare(stin_context *ctx, const char *call, const char *dropped,
                                   const stin_material *material, stin_material *out,
                                   stin_result *r)
{
    stin_material mat;
    stin__memzero(&mat, sizeof mat);
    if (material)
        mat = *material;
    *r = STIN_ERROR_INVALID_ARGUMENT;
    if (!stin__finite_n(mat.color, 4) || !stin__finite_n(mat.specular, 3) || !stin__isfinite(mat.shininess) ||
        !stin__isfinite(mat.height_scale) || !stin__isfinite(mat.height_bias)) {
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_BAD_ARGUMENT,
                  "%s: material values must be finite; %s dropped", call, dropped);
        return *r;
    }
    if (mat.height_scale < 0.0f || mat.self_shadow < 0 || mat.self_shadow > 2 ||
        (mat.surface != STIN_TECH_NONE &&
         stin__technique_feature(mat.surface) != STIN_FEATURE_SURFACE)) {
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_BAD_ARGUMENT,
                  "%s: material height_scale must be >= 0, self_shadow 0..2 and surface a "
                  "surface technique or none; %s dropped", call, dropped);
        return *r;
    }
    *r = STIN_ERROR_INVALID_HANDLE;
    if ((mat.normal_map.id && !stin__texture_lookup(ctx, mat.normal_map)) ||
        (mat.height_map.id && !stin__texture_lookup(ctx, mat.height_map))) {
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_BAD_HANDLE,
                  "%s: stale or unknown normal or height map 0x%x/0x%x; %s dropped", call,
                  mat.normal_map.id, mat.height_map.id, dropped);
        return *r;
    }
    if (mat.albedo.id && !stin__texture_lookup(ctx, mat.albedo)) {
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_BAD_HANDLE,
                  "%s: stale or unknown albedo texture 0x%x; %s dropped", call, mat.albedo.id,
                  dropped);
        return *r;
    }
    material_defaults(&mat);
    *out = mat;
    *r = STIN_OK;
    return STIN_OK;
}
