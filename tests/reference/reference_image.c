/* SPDX-License-Identifier: MIT */
/* Whole-image reference AOVs: beauty, P, N, Z, the visibility of light 0
 * and its transmittance. */
#include <stdlib.h>
#include <string.h>

#include "reference_internal.h"

const char *const reference_channel_names[REFERENCE_CHANNELS] = {
    "R", "G", "B", "A", "P.X", "P.Y", "P.Z", "N.X", "N.Y", "N.Z", "Z", "vis.R", "vis.G", "vis.B",
    "T.R", "T.G", "T.B"};

/* Nothing lets light through: every material opaque, no CSG product
 * (transmittance rays would stop at its primitives). */
static int all_opaque(const scene *s, const reference *r)
{
    for (int i = 0; i < s->material_count; i++)
        if (s->materials[i].color[3] < 1.0f)
            return 0;
    return !r->csg_primitive;
}

/* weight: scratch of light_count entries, each light's visibility. */
static void pixel(const scene *s, const reference *r, const ref_hit *h, int per_vertex,
                  unsigned flags, float *weight, float *px)
{
    memset(px, 0, REFERENCE_CHANNELS * sizeof *px);
    int opaque = h->hit && s->materials[s->objects[h->object].material].color[3] >= 1.0f;
    if (h->hit)
        ref_light_weights(r, h, weight); /* an area light's integral: work once */
    if (h->hit && (flags & REFERENCE_RENDER_PER_LIGHT_PASSES) && !opaque) {
        reference_shade(s, r, h, per_vertex, px); /* blended: drawn last, unshadowed */
    } else if (h->hit && (flags & (REFERENCE_RENDER_SHADOWED | REFERENCE_RENDER_PER_LIGHT_PASSES))) {
        ref_shade_lights(s, r, h, per_vertex, s->lights, s->light_count, weight,
                         (flags & REFERENCE_RENDER_PER_LIGHT_PASSES) != 0, px);
    } else {
        reference_shade(s, r, h, per_vertex, px);
    }
    if (h->hit) {
        memcpy(px + REFERENCE_CH_PX, h->P, sizeof h->P);
        memcpy(px + REFERENCE_CH_NX, h->N, sizeof h->N);
        px[REFERENCE_CH_Z] = h->t; /* |P - eye|, see ref_fill_hit */
    }
    float vis0 = h->hit && s->light_count > 0 ? weight[0] : 1.0f;
    px[REFERENCE_CH_VIS_R] = px[REFERENCE_CH_VIS_G] = px[REFERENCE_CH_VIS_B] = vis0;
    px[REFERENCE_CH_T_R] = px[REFERENCE_CH_T_G] = px[REFERENCE_CH_T_B] = vis0;
    /* an area light in an opaque scene: its transmittance is its visibility,
     * and integrating it twice would double the reference's time */
    if (h->hit && s->light_count > 0 && !(ref_is_area_light(&s->lights[0]) && all_opaque(s, r)))
        reference_transmittance(r, h, 0, px + REFERENCE_CH_T_R);
}

static int render_traced(const scene *s, const reference *r, int width, int height,
                         int per_vertex, unsigned flags, float *out)
{
    size_t n = (size_t)width * (size_t)height;
    ref_hit *hits = malloc(n * sizeof *hits);
    float *weight = malloc(((size_t)s->light_count + 1) * sizeof *weight);
    int ok = hits && weight &&
             (r->csg_cast ? ref_csg_primary_cast(r, width, height, hits)
                          : reference_primary(r, width, height, hits));
    for (size_t i = 0; ok && i < n; i++) {
        float *px = out + i * REFERENCE_CHANNELS;
        pixel(s, r, &hits[i], per_vertex, flags, weight, px);
        if ((flags & REFERENCE_RENDER_COMPOSITE) &&
            reference_composite_pixel(s, r, width, height, (int)(i % (size_t)width),
                                      (int)(i / (size_t)width), per_vertex, flags, px, NULL) < 0)
            ok = 0;
    }
    if (ok)
        ok = rtcGetDeviceError(r->device) == RTC_ERROR_NONE;
    free(weight);
    free(hits);
    return ok;
}

/* Cached by the reference's state and the arguments (reference_cache.h). */
int reference_render_ex(const scene *s, const reference *r, int width, int height, int per_vertex,
                        unsigned flags, float *out)
{
    ref_hasher h;
    ref_cache_key key;
    ref_cache_part part;
    int cached = 0;
    if (!s || !r || r->s != s || !out || width <= 0 || height <= 0)
        return 0;
    if (ref_cache_key_begin(r, "render", &h)) {
        ref_hash_u64(&h, (uint64_t)width);
        ref_hash_u64(&h, (uint64_t)height);
        ref_hash_u64(&h, (uint64_t)(int64_t)per_vertex);
        ref_hash_u64(&h, flags);
        ref_cache_key_end(&h, &key);
        part.data = out;
        part.size = (size_t)width * (size_t)height * REFERENCE_CHANNELS * sizeof *out;
        cached = 1;
        if (ref_cache_load(&key, &part, 1))
            return 1;
    }
    int ok;
    if (cached)
        ref_cache_compute_begin();
    ok = render_traced(s, r, width, height, per_vertex, flags, out);
    if (cached)
        ref_cache_compute_end();
    if (!ok)
        return 0;
    if (cached)
        ref_cache_store(&key, &part, 1);
    return 1;
}

int reference_render(const scene *s, const reference *r, int width, int height, int per_vertex,
                     float *out)
{
    return reference_render_ex(s, r, width, height, per_vertex, 0u, out);
}
