/* SPDX-License-Identifier: MIT */
/* Sizing a desc from the application's assets: the staging a texture
 * needs on any context, and capacities raised to a summary of the assets
 * within the limits stin_create accepts. */
#include "internal.h"

uint64_t stin_texture_staging_bytes(const stin_texture_desc *d)
{
    uint32_t w, h;
    int normal, derive, mips, resampled;
    if (!d || !d->width || !d->height || (uint64_t)d->width * d->height > STIN__MAX_TEXELS ||
        (unsigned)d->kind > STIN_TEXTURE_HEIGHT)
        return 0;
    /* the worst context: GL1 resamples to powers of two */
    w = stin__pot_at_least(d->width);
    h = stin__pot_at_least(d->height);
    resampled = w != d->width || h != d->height;
    normal = d->kind == STIN_TEXTURE_NORMAL;
    derive = normal && d->normal_from_height > 0.0f;
    /* height maps too: displacement's copy has the chain (any context may
     * displace) */
    mips = !d->base_level_only;
    /* the derived source is kept beside the chain whenever the size changes,
     * which a context's max_texture_size may do to any size: always count it */
    return stin__plan_staging(w, h, mips, resampled || normal,
                              derive ? 4ull * d->width * d->height : 0)
        .total;
}

typedef struct fit_field {
    uint32_t *have;
    uint64_t want, limit;
    const char *name;
} fit_field;

stin_result stin_desc_fit(stin_desc *desc, const stin_asset_summary *a, const char **field)
{
    fit_field f[8];
    size_t i, n = 0;
    if (field)
        *field = NULL;
    if (!desc || !a)
        return STIN_ERROR_INVALID_ARGUMENT;
#define FIELD(member, value, max) \
    f[n].have = &desc->member, f[n].want = (value), f[n].limit = (max), f[n++].name = #member
    FIELD(max_meshes, a->meshes, 65535u);
    FIELD(max_textures, a->textures, 65535u);
    FIELD(max_vertices, a->vertices, 0x40000000u - 1u);
    FIELD(max_triangles, a->triangles, 0x20000000u - 1u);
    FIELD(max_mesh_triangles, a->largest_mesh_triangles, 0x20000000u - 1u);
    FIELD(max_texture_bytes, a->largest_texture_staging, 0xffffffffu);
    FIELD(max_draws, a->draws, 0x1000000u - 1u);
    FIELD(max_lights, a->lights, 32u);
#undef FIELD
    for (i = 0; i < n; i++)
        if (f[i].want > f[i].limit) {
            if (field)
                *field = f[i].name;
            return STIN_ERROR_CAPACITY;
        }
    for (i = 0; i < n; i++)
        if (*f[i].have < f[i].want)
            *f[i].have = (uint32_t)f[i].want;
    /* all meshes hold at least the largest (the default 262144 may not) */
    if (desc->max_mesh_triangles > (desc->max_triangles ? desc->max_triangles : 262144u))
        desc->max_triangles = desc->max_mesh_triangles;
    return STIN_OK;
}
