/* SPDX-License-Identifier: MIT */
/* The features' hooks called for the lighting paths and the post stages,
 * with the answers of "no feature there" where none gives one
 * (render/path_features.h). */
#include "internal.h"

const stin__path_feature *const *stin__path_features(const stin_context *ctx)
{
    static const stin__path_feature *const none[1] = {NULL};
    return ctx->path_features ? ctx->path_features : none;
}

/* The feature that gives the lit program's variants, or NULL. */
static const stin__path_feature *variants(const stin_context *ctx)
{
    const stin__path_feature *const *f;
    for (f = stin__path_features(ctx); *f; f++)
        if ((*f)->variant_for)
            return *f;
    return NULL;
}

int stin__lit_variant_top(const stin_context *ctx)
{
    const stin__path_feature *v = variants(ctx);
    return v ? v->variant_top(ctx) : STIN__SURF_PLAIN;
}

void stin__lit_variant_failed(stin_context *ctx, int built, const char *msg)
{
    const stin__path_feature *v = variants(ctx);
    if (v)
        v->variant_failed(ctx, built, msg);
}

int stin__lit_variant_for(stin_context *ctx, const stin_material *m)
{
    const stin__path_feature *v = variants(ctx);
    return v ? v->variant_for(ctx, m) : STIN__SURF_PLAIN;
}

int stin__camera_set(const stin_context *ctx, const stin__draw *d)
{
    const stin__path_feature *const *f;
    for (f = stin__path_features(ctx); *f; f++)
        if ((*f)->camera_set)
            return (*f)->camera_set(ctx, d);
    return d->material.color[3] < 1.0f ? STIN__BLENDED : STIN__OPAQUE;
}

int stin__in_peeled_layer(const stin_context *ctx)
{
    const stin__path_feature *const *f;
    for (f = stin__path_features(ctx); *f; f++)
        if ((*f)->in_layer && (*f)->in_layer(ctx))
            return 1;
    return 0;
}

int stin__light_maps_active(const stin_context *ctx)
{
    const stin__path_feature *const *f;
    for (f = stin__path_features(ctx); *f; f++)
        if ((*f)->maps_active && (*f)->maps_active(ctx))
            return 1;
    return 0;
}

void stin__light_maps_make(stin_context *ctx, uint32_t li)
{
    const stin__path_feature *const *f;
    for (f = stin__path_features(ctx); *f; f++)
        if ((*f)->light)
            (*f)->light(ctx, li);
}

void stin__light_maps_done(stin_context *ctx)
{
    const stin__path_feature *const *f;
    for (f = stin__path_features(ctx); *f; f++)
        if ((*f)->light_done)
            (*f)->light_done(ctx);
}
