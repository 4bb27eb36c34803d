/* Whole-image reference AOVs: beauty, P, N, Z and the visibility of light 0. */
#include <stdlib.h>
#include <string.h>

#include "reference_internal.h"

const char *const reference_channel_names[REFERENCE_CHANNELS] = {
    "R", "G", "B", "A", "P.X", "P.Y", "P.Z", "N.X", "N.Y", "N.Z", "Z", "vis.R", "vis.G", "vis.B"};

static void pixel(const scene *s, const reference *r, const ref_hit *h, int per_vertex,
                  unsigned flags, float *weight, float *px)
{
    memset(px, 0, REFERENCE_CHANNELS * sizeof *px);
    float vis0 = 1.0f;
    if (h->hit && s->light_count > 0) {
        if (flags & REFERENCE_RENDER_SHADOWED)
            for (int i = 0; i < s->light_count; i++)
                weight[i] = reference_visibility(r, h, i);
        vis0 = (flags & REFERENCE_RENDER_SHADOWED) ? weight[0] : reference_visibility(r, h, 0);
    }
    reference_shade_weighted(s, r, h, per_vertex,
                             (flags & REFERENCE_RENDER_SHADOWED) && h->hit ? weight : NULL, px);
    if (h->hit) {
        memcpy(px + REFERENCE_CH_PX, h->P, sizeof h->P);
        memcpy(px + REFERENCE_CH_NX, h->N, sizeof h->N);
        px[REFERENCE_CH_Z] = h->t; /* |P - eye|, see ref_fill_hit */
    }
    px[REFERENCE_CH_VIS_R] = px[REFERENCE_CH_VIS_G] = px[REFERENCE_CH_VIS_B] = vis0;
}

int reference_render_ex(const scene *s, const reference *r, int width, int height, int per_vertex,
                        unsigned flags, float *out)
{
    if (!s || !r || r->s != s || !out || width <= 0 || height <= 0)
        return 0;
    size_t n = (size_t)width * (size_t)height;
    ref_hit *hits = malloc(n * sizeof *hits);
    float *weight = malloc((s->light_count > 0 ? (size_t)s->light_count : 1) * sizeof *weight);
    int ok = hits && weight && reference_primary(r, width, height, hits);
    for (size_t i = 0; ok && i < n; i++)
        pixel(s, r, &hits[i], per_vertex, flags, weight, out + i * REFERENCE_CHANNELS);
    if (ok)
        ok = rtcGetDeviceError(r->device) == RTC_ERROR_NONE;
    free(weight);
    free(hits);
    return ok;
}

int reference_render(const scene *s, const reference *r, int width, int height, int per_vertex,
                     float *out)
{
    return reference_render_ex(s, r, width, height, per_vertex, 0u, out);
}
