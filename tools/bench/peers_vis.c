/* SPDX-License-Identifier: MIT */
#include "peers_vis.h"
#include "light_reach.h"
#include "reference.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A shadow map blurs an edge over its texels: the pixels next to a change
 * of the reference's visibility (or of the object seen) are near it. */
#define EDGE_BAND 1

static int largest_step(const uint8_t *a, const uint8_t *b)
{
    int k, m = 0;
    for (k = 0; k < 3; k++) {
        int d = abs((int)a[k] - (int)b[k]);
        m = d > m ? d : m;
    }
    return m;
}

static int distance(const uint8_t *a, const uint8_t *b)
{
    int k, sum = 0;
    for (k = 0; k < 3; k++)
        sum += abs((int)a[k] - (int)b[k]);
    return sum;
}

int peers_ref_create(peers_ref *r, const scene *s, int width, int height,
                     const uint8_t *unshadowed, const uint8_t *ambient, char *err,
                     size_t err_size)
{
    size_t n = (size_t)width * (size_t)height, i;
    reference *ref;
    ref_hit *hits;
    memset(r, 0, sizeof *r);
    r->width = width;
    r->height = height;
    if (!(ref = reference_create(s, err, err_size)))
        return 0;
    r->image = malloc(n * REFERENCE_CHANNELS * sizeof *r->image);
    r->hits = hits = malloc(n * sizeof *hits);
    r->judged = calloc(n, 1);
    if (!r->image || !hits || !r->judged ||
        !reference_render(s, ref, width, height, 0, r->image) ||
        !reference_primary(ref, width, height, hits)) {
        snprintf(err, err_size, "the reference failed (or out of memory)");
        reference_destroy(ref);
        peers_ref_release(r);
        return 0;
    }
    reference_destroy(ref);
    for (i = 0; i < n; i++) {
        r->judged[i] = hits[i].hit && light_reaches(s, &hits[i]) &&
                       largest_step(unshadowed + 4 * i, ambient + 4 * i) >= PEERS_VIS_MIN_SHARE;
        r->judged_n += r->judged[i];
    }
    return 1;
}

void peers_ref_release(peers_ref *r)
{
    free(r->image);
    free(r->hits);
    free(r->judged);
    memset(r, 0, sizeof *r);
}

void peers_classify(const uint8_t *frame, const uint8_t *unshadowed, const uint8_t *full,
                    int n, uint8_t *vis)
{
    int i;
    for (i = 0; i < n; i++) {
        const uint8_t *c = frame + 4 * i, *u = unshadowed + 4 * i, *f = full + 4 * i;
        vis[i] = largest_step(u, f) < PEERS_VIS_MIN_SHARE / 2 || distance(c, u) <= distance(c, f);
    }
}

void peers_vis_output(const uint8_t *output, int n, uint8_t *vis)
{
    int i;
    for (i = 0; i < n; i++)
        vis[i] = output[4 * i] >= 128;
}

void peers_mismatch_of(const peers_ref *r, const uint8_t *vis, peers_mismatch *out)
{
    const ref_hit *hits = r->hits;
    int x, y, w = r->width, h = r->height;
    memset(out, 0, sizeof *out);
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            size_t i = (size_t)y * (size_t)w + (size_t)x;
            int lit = r->image[i * REFERENCE_CHANNELS + REFERENCE_CH_VIS_R] > 0.5f;
            if (!r->judged[i] || vis[i] == lit)
                continue;
            out->wrong++;
            out->far += !near_shadow_edge(hits, r->image, w, h, x, y, EDGE_BAND);
        }
    out->wrong_pct = 100.0 * (double)out->wrong / ((double)w * (double)h);
    out->far_pct = 100.0 * (double)out->far / ((double)w * (double)h);
}

long peers_disagree(const peers_ref *r, const uint8_t *a, const uint8_t *b)
{
    long i, n = (long)r->width * r->height, d = 0;
    for (i = 0; i < n; i++)
        d += r->judged[i] && a[i] != b[i];
    return d;
}
