/* SPDX-License-Identifier: MIT */
/* Whole-image reference AOVs: beauty, P, N, Z, the visibility of light 0
 * and its transmittance. */
#include <stdlib.h>
#include <string.h>

#include "reference_internal.h"

const char *const reference_channel_names[REFERENCE_CHANNELS] = {
    "R", "G", "B", "A", "P.X", "P.Y", "P.Z", "N.X", "N.Y", "N.Z", "Z", "vis.R", "vis.G", "vis.B",
    "T.R", "T.G", "T.B"};

/* Scratch of one render: the lights split into samples and their weights. */
typedef struct scratch {
    scene_light *lights;
    float *weight;
} scratch;

static void pixel(const scene *s, const reference *r, const ref_hit *h, int per_vertex,
                  unsigned flags, scratch *w, float *px)
{
    memset(px, 0, REFERENCE_CHANNELS * sizeof *px);
    int opaque = h->hit && s->materials[s->objects[h->object].material].color[3] >= 1.0f;
    if (h->hit && (flags & REFERENCE_RENDER_PER_LIGHT_PASSES) && !opaque) {
        reference_shade(s, r, h, per_vertex, px); /* blended: drawn last, unshadowed */
    } else if (h->hit && (flags & (REFERENCE_RENDER_SHADOWED | REFERENCE_RENDER_PER_LIGHT_PASSES))) {
        int n = ref_expand_lights(r, h, w->lights, w->weight);
        ref_shade_lights(s, r, h, per_vertex, w->lights, n, w->weight,
                         (flags & REFERENCE_RENDER_PER_LIGHT_PASSES) != 0, px);
    } else {
        reference_shade(s, r, h, per_vertex, px);
    }
    if (h->hit) {
        memcpy(px + REFERENCE_CH_PX, h->P, sizeof h->P);
        memcpy(px + REFERENCE_CH_NX, h->N, sizeof h->N);
        px[REFERENCE_CH_Z] = h->t; /* |P - eye|, see ref_fill_hit */
    }
    float vis0 = h->hit && s->light_count > 0 ? reference_light_visibility(r, h, 0) : 1.0f;
    px[REFERENCE_CH_VIS_R] = px[REFERENCE_CH_VIS_G] = px[REFERENCE_CH_VIS_B] = vis0;
    px[REFERENCE_CH_T_R] = px[REFERENCE_CH_T_G] = px[REFERENCE_CH_T_B] = 1.0f;
    if (h->hit && s->light_count > 0)
        reference_transmittance(r, h, 0, px + REFERENCE_CH_T_R);
}

int reference_render_ex(const scene *s, const reference *r, int width, int height, int per_vertex,
                        unsigned flags, float *out)
{
    if (!s || !r || r->s != s || !out || width <= 0 || height <= 0)
        return 0;
    size_t n = (size_t)width * (size_t)height, cap = (size_t)ref_sample_capacity(r) + 1;
    ref_hit *hits = malloc(n * sizeof *hits);
    scratch w = {malloc(cap * sizeof *w.lights), malloc(cap * sizeof *w.weight)};
    int ok = hits && w.lights && w.weight &&
             (r->csg_cast ? ref_csg_primary_cast(r, width, height, hits)
                          : reference_primary(r, width, height, hits));
    for (size_t i = 0; ok && i < n; i++) {
        float *px = out + i * REFERENCE_CHANNELS;
        pixel(s, r, &hits[i], per_vertex, flags, &w, px);
        if ((flags & REFERENCE_RENDER_COMPOSITE) &&
            reference_composite_pixel(s, r, width, height, (int)(i % (size_t)width),
                                      (int)(i / (size_t)width), per_vertex, flags, px, NULL) < 0)
            ok = 0;
    }
    if (ok)
        ok = rtcGetDeviceError(r->device) == RTC_ERROR_NONE;
    free(w.weight);
    free(w.lights);
    free(hits);
    return ok;
}

int reference_render(const scene *s, const reference *r, int width, int height, int per_vertex,
                     float *out)
{
    return reference_render_ex(s, r, width, height, per_vertex, 0u, out);
}
