/* SPDX-License-Identifier: MIT */
/*
 * stin-scene-pack: loads scene files with the tools' loader and writes each
 * as a scene pack (tools/common/scene_pack.h) for the browser front end.
 *
 *   stin-scene-pack OUT_DIR SCENE.json...   writes OUT_DIR/NAME.stinscene
 */
#include "scene.h"
#include "scene_pack.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int pack_one(const char *dir, const char *path)
{
    scene s;
    char err[512], out[1024], name[256];
    const char *base = strrchr(path, '/');
    unsigned char *block;
    size_t size;
    FILE *f;
    int ok;
    snprintf(name, sizeof name, "%s", base ? base + 1 : path);
    if (strrchr(name, '.'))
        *strrchr(name, '.') = '\0';
    if (!scene_load(path, &s, err, sizeof err)) {
        fprintf(stderr, "stin-scene-pack: %s\n", err);
        return 0;
    }
    size = scene_pack_size(&s);
    block = malloc(size);
    snprintf(out, sizeof out, "%s/%s.stinscene", dir, name);
    f = block ? fopen(out, "wb") : NULL;
    if (f)
        scene_pack_write(&s, block);
    ok = f && fwrite(block, 1, size, f) == size;
    if (f && fclose(f) != 0)
        ok = 0;
    if (!ok)
        fprintf(stderr, "stin-scene-pack: cannot write %s\n", out);
    free(block);
    scene_free(&s);
    return ok;
}

int main(int argc, char **argv)
{
    int i, ok = 1;
    if (argc < 3) {
        fprintf(stderr, "usage: stin-scene-pack OUT_DIR SCENE.json...\n");
        return 2;
    }
    for (i = 2; i < argc; i++)
        ok &= pack_one(argv[1], argv[i]);
    return ok ? 0 : 1;
}
