/* SPDX-License-Identifier: MIT */
/* stin-reference: the Embree reference of a scene written as an image with
 * the same channels as stin-render (for the README and for outside checks).
 * The file's csg list is drawn as stin-render draws it: its products shown
 * (the exact CSG reference) and casting, their primitives not on their own.
 *   stin-reference SCENE.json -o OUT.png|OUT.exr [--size WxH] [--gouraud] [--shadowed]
 *                 [--composite] */
#include "aov.h"
#include "image_io.h"
#include "reference.h"
#include "reference_csg.h"
#include "reference_surface.h"
#include "scene.h"
#include "scene_csg.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The scene's csg list as the reference's products (the file's, kept for
 * the reference's lifetime). */
typedef struct csg_list {
    scene_csg_products file;
    ref_csg_product *ref;
} csg_list;

static int csg_products(reference *r, const scene *s, csg_list *out)
{
    int i;
    if (!scene_csg_products_build(s, &out->file) ||
        !(out->ref = calloc((size_t)out->file.count + 1, sizeof *out->ref)))
        return 0;
    for (i = 0; i < out->file.count; i++) {
        out->ref[i].objects = out->file.products[i].objects;
        out->ref[i].primitive_count = out->file.products[i].primitive_count;
        out->ref[i].nodes = out->file.products[i].nodes;
        out->ref[i].node_count = out->file.products[i].node_count;
    }
    return reference_csg_mark(r, out->ref, out->file.count) &&
           reference_csg_cast(r, out->ref, out->file.count);
}

int main(int argc, char **argv)
{
    csg_list products = {{0}, NULL};
    const char *scene_path = NULL, *out = NULL;
    int w = 0, h = 0, per_vertex = 0, x, y, c, rc = 1, surface = -1;
    unsigned flags = 0;
    scene s;
    reference *r = NULL;
    float *px = NULL;
    image img;
    char err[512];
    for (x = 1; x < argc; x++) {
        if (!strcmp(argv[x], "-o") && x + 1 < argc) out = argv[++x];
        else if (!strcmp(argv[x], "--size") && x + 1 < argc) {
            if (sscanf(argv[++x], "%dx%d", &w, &h) != 2 || w < 1 || h < 1) return 2;
        } else if (!strcmp(argv[x], "--gouraud")) per_vertex = 1;
        else if (!strcmp(argv[x], "--shadowed")) flags |= REFERENCE_RENDER_SHADOWED;
        /* transparent surfaces composited front to back over the opaque hit,
         * each lit through the lights' transmittance (depth-peel's target) */
        else if (!strcmp(argv[x], "--composite"))
            flags |= REFERENCE_RENDER_COMPOSITE | REFERENCE_RENDER_TRANSMITTANCE;
        else if (!strcmp(argv[x], "--surface") && x + 1 < argc) {
            const char *t = argv[++x];
            surface = !strcmp(t, "plain") ? REF_SURFACE_PLAIN
                    : !strcmp(t, "normal") ? REF_SURFACE_NORMAL
                    : !strcmp(t, "parallax") ? REF_SURFACE_PARALLAX
                    : !strcmp(t, "pom") ? REF_SURFACE_POM : -2;
            if (surface == -2) {
                fprintf(stderr, "stin-reference: --surface wants plain, normal, parallax or pom\n");
                return 2;
            }
        }
        else if (argv[x][0] != '-' && !scene_path) scene_path = argv[x];
        else {
            fprintf(stderr, "usage: stin-reference SCENE.json -o OUT [--size WxH] [--gouraud] "
                            "[--shadowed] [--composite] [--surface plain|normal|parallax|pom]\n");
            return 2;
        }
    }
    if (!scene_path || !out) {
        fprintf(stderr, "usage: stin-reference SCENE.json -o OUT [--size WxH] [--gouraud] [--shadowed] "
                        "[--composite]\n");
        return 2;
    }
    memset(&img, 0, sizeof img);
    if (!scene_load(scene_path, &s, err, sizeof err)) {
        fprintf(stderr, "stin-reference: %s\n", err);
        return 2;
    }
    if (!w) {
        w = s.width;
        h = s.height;
    }
    r = reference_create(&s, err, sizeof err);
    if (r && s.csg_count && !csg_products(r, &s, &products)) {
        fprintf(stderr, "stin-reference: the csg list: out of memory or a bad product\n");
        goto done;
    }
    px = malloc(sizeof(float) * REFERENCE_CHANNELS * (size_t)w * h);
    if (!r || !px || !image_alloc(&img, w, h, REFERENCE_CHANNELS) ||
        !reference_render_ex(&s, r, w, h, per_vertex, flags, px)) {
        fprintf(stderr, "stin-reference: %s\n", r ? "render failed" : err);
        goto done;
    }
    if (surface >= 0) { /* the beauty with the surface technique (unshadowed) */
        ref_surface *rs = ref_surface_create(&s);
        ref_hit *hits = malloc(sizeof *hits * (size_t)w * h);
        if (!rs || !hits || !reference_primary(r, w, h, hits)) {
            fprintf(stderr, "stin-reference: surface reference failed\n");
            free(hits);
            if (rs)
                ref_surface_destroy(rs);
            goto done;
        }
        for (y = 0; y < w * h; y++)
            if (hits[y].hit)
                ref_surface_shade(&s, rs, &hits[y], surface, -1.0f,
                                  px + (size_t)y * REFERENCE_CHANNELS + REFERENCE_CH_R, NULL);
        free(hits);
        ref_surface_destroy(rs);
    }
    for (c = 0; c < REFERENCE_CHANNELS; c++)
        snprintf(img.channel_names[c], sizeof img.channel_names[c], "%s", reference_channel_names[c]);
    for (y = 0; y < h; y++) /* reference rows are bottom to top, files top to bottom */
        memcpy(img.pixels + (size_t)(h - 1 - y) * w * REFERENCE_CHANNELS,
               px + (size_t)y * w * REFERENCE_CHANNELS, sizeof(float) * REFERENCE_CHANNELS * w);
    if (!image_write(out, &img, strstr(out, ".png") != NULL, err, sizeof err)) {
        fprintf(stderr, "stin-reference: %s\n", err);
        goto done;
    }
    rc = 0;
done:
    image_free(&img);
    free(px);
    if (r)
        reference_destroy(r);
    scene_free(&s);
    scene_csg_products_free(&products.file);
    free(products.ref);
    return rc;
}
