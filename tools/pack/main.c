/* SPDX-License-Identifier: MIT */
/*
 * stin-scene-pack: loads scene files with the tools' loader and writes each
 * as a scene pack (tools/common/scene_pack.h) for the browser front end.
 *
 *   stin-scene-pack OUT_DIR SCENE.json...   writes OUT_DIR/NAME.stinscene
 *   stin-scene-pack --variants OUT_DIR SCENE.json...
 *       writes OUT_DIR/NAME.VARIANT.stinscene for each of the surface tests'
 *       views the scene has (tools/common/scene_variant.h): the browser draws
 *       the scene the native rows judge
 */
#include "scene.h"
#include "scene_pack.h"
#include "scene_variant.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const variants[] = {"parallax-down", "parallax-limit"};

static int write_pack(const scene *s, const char *out)
{
    size_t size = scene_pack_size(s);
    unsigned char *block = malloc(size);
    FILE *f = block ? fopen(out, "wb") : NULL;
    int ok;
    if (f)
        scene_pack_write(s, block);
    ok = f && fwrite(block, 1, size, f) == size;
    if (f && fclose(f) != 0)
        ok = 0;
    if (!ok)
        fprintf(stderr, "stin-scene-pack: cannot write %s\n", out);
    free(block);
    return ok;
}

static int pack_one(const char *dir, const char *path, int variant)
{
    scene s, v;
    char err[512], out[1024], name[256];
    const char *base = strrchr(path, '/');
    size_t i;
    int ok = 1;
    snprintf(name, sizeof name, "%s", base ? base + 1 : path);
    if (strrchr(name, '.'))
        *strrchr(name, '.') = '\0';
    if (!scene_load(path, &s, err, sizeof err)) {
        fprintf(stderr, "stin-scene-pack: %s\n", err);
        return 0;
    }
    if (!variant) {
        snprintf(out, sizeof out, "%s/%s.stinscene", dir, name);
        ok = write_pack(&s, out);
    }
    for (i = 0; variant && i < sizeof variants / sizeof variants[0]; i++) {
        if (!scene_variant_make(&s, variants[i], &v))
            continue; /* the scene has no object for it */
        snprintf(out, sizeof out, "%s/%s.%s.stinscene", dir, name, variants[i]);
        ok &= write_pack(&v, out);
        scene_variant_free(&v, &s);
    }
    scene_free(&s);
    return ok;
}

int main(int argc, char **argv)
{
    int variant = argc > 1 && !strcmp(argv[1], "--variants");
    int i, ok = 1;
    if (argc < 3 + variant) {
        fprintf(stderr, "usage: stin-scene-pack [--variants] OUT_DIR SCENE.json...\n");
        return 2;
    }
    for (i = 2 + variant; i < argc; i++)
        ok &= pack_one(argv[1 + variant], argv[i], variant);
    return ok ? 0 : 1;
}
