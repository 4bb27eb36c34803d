/* SPDX-License-Identifier: MIT */
/* The services the frame lends the layers below it, pointing at the
 * features that give them: the frame is the one layer that names
 * features, so the shadow techniques, passes and post stages reach the
 * CSG products, and the lighting paths and the visibility export what the
 * surface, translucent shadows and transparency add to them, only through
 * these (render/casters.h, render/resolved.h, render/path_features.h). */
#include "internal.h"

static const stin__casters csg_casters = {
    stin__csg_cast_wanted,
    stin__csg_cast,
    stin__csg_cast_again,
    stin__csg_cast_none,
    stin__csg_caster_product,
    stin__csg_caster_term,
};

static const stin__resolved csg_resolved = {
    stin__csg_face_list,
    stin__csg_face_begin,
    stin__csg_face_end,
    stin__csg_depth_again,
    stin__csg_depth_texture,
    stin__csg_snap_band,
};

/* Surface detail: the lit program's variants and their chunks (GLSL), DOT3
 * (fixed function). */
static const stin__path_feature surface_feature = {
    .place = STIN__CHUNK_SURFACE,
    .chunks = stin__surf_chunks,
    .locate = stin__surf_locate,
    .units = stin__surf_units,
    .material = stin__surf_material,
    .unbind = stin__surf_unbind,
    .variant_top = stin__surf_variant_top,
    .variant_failed = stin__surf_variant_failed,
    .variant_for = stin__surf_variant_for,
    .fixed_material = stin__dot3_material,
    .fixed_lights = stin__dot3_lights,
    .fixed_batch = stin__dot3_batch,
};

/* Translucent shadows: the deep or colour map lookup and each light's map. */
static const stin__path_feature translucent_feature = {
    .place = STIN__CHUNK_SEAM,
    .chunks = stin__translucent_chunks,
    .locate = stin__translucent_locate,
    .uniforms = stin__translucent_uniforms,
    .maps_active = stin__translucent_active,
    .light = stin__translucent_light,
    .light_done = stin__translucent_light_done,
};

/* Transparency: the peel chunk and the draws of a peeled layer. */
static const stin__path_feature transparency_feature = {
    .place = STIN__CHUNK_LAYER,
    .chunks = stin__peel_chunks,
    .locate = stin__peel_locate,
    .uniforms = stin__peel_uniforms,
    .camera_set = stin__peel_camera_set,
    .in_layer = stin__peel_in_layer,
};

/* In the order the paths call them: locations and uniforms translucent's,
 * then transparency's, then the surface's (each chunk goes by its place). */
static const stin__path_feature *const path_features[] = {
    &translucent_feature,
    &transparency_feature,
    &surface_feature,
    NULL,
};

void stin__hooks_install_paths(stin_context *ctx)
{
    /* every feature's hooks answer for the feature's own choice, whatever
     * it is, so the list is the same for every context */
    ctx->path_features = path_features;
}

void stin__hooks_install(stin_context *ctx)
{
    /* csg-off is final once stin__csg_init has run: no products are ever
     * resolved or cast, which the hooks' absence says too */
    int csg = ctx->sel.choice[STIN_FEATURE_CSG].technique != STIN_TECH_CSG_OFF;
    ctx->casters.hooks = csg ? &csg_casters : NULL;
    ctx->casters.drew = 0;
    ctx->resolved = csg ? &csg_resolved : NULL;
}
