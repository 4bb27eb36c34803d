/* stin-reference: the Embree reference of a scene written as an image with
 * the same channels as stin-render (for the README and for outside checks).
 *   stin-reference SCENE.json -o OUT.png|OUT.exr [--size WxH] [--gouraud] [--shadowed] */
#include "aov.h"
#include "image_io.h"
#include "reference.h"
#include "scene.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char **argv)
{
    const char *scene_path = NULL, *out = NULL;
    int w = 0, h = 0, per_vertex = 0, x, y, c, rc = 1;
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
        else if (argv[x][0] != '-' && !scene_path) scene_path = argv[x];
        else {
            fprintf(stderr, "usage: stin-reference SCENE.json -o OUT [--size WxH] [--gouraud] [--shadowed]\n");
            return 2;
        }
    }
    if (!scene_path || !out) {
        fprintf(stderr, "usage: stin-reference SCENE.json -o OUT [--size WxH] [--gouraud] [--shadowed]\n");
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
    px = malloc(sizeof(float) * REFERENCE_CHANNELS * (size_t)w * h);
    if (!r || !px || !image_alloc(&img, w, h, REFERENCE_CHANNELS) ||
        !reference_render_ex(&s, r, w, h, per_vertex, flags, px)) {
        fprintf(stderr, "stin-reference: %s\n", r ? "render failed" : err);
        goto done;
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
    return rc;
}
