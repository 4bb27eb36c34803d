/* SPDX-License-Identifier: MIT */
/*
 * Every framebuffer read-back of the image tests, hashed into a log when
 * STIN_READBACK_LOG names a file: the proof that a change which should not
 * move a pixel (a refactoring) moved none. Linked with
 * -Wl,--wrap=stin_platform_read_color,--wrap=stin_platform_read_depth, so
 * neither the platform library nor the tests change. tools/compare-readbacks.sh
 * runs it before and after and diffs the logs.
 */
#include "stin_platform.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

int __real_stin_platform_read_color(stin_platform *p, uint8_t *rgba);
int __real_stin_platform_read_depth(stin_platform *p, float *depth);
int __wrap_stin_platform_read_color(stin_platform *p, uint8_t *rgba);
int __wrap_stin_platform_read_depth(stin_platform *p, float *depth);

/* FNV-1a, 64-bit: any changed byte changes the hash. */
static uint64_t hash_bytes(const void *data, size_t n)
{
    const unsigned char *b = (const unsigned char *)data;
    uint64_t h = 1469598103934665603ull;
    size_t i;
    for (i = 0; i < n; i++) {
        h ^= b[i];
        h *= 1099511628211ull;
    }
    return h;
}

static void log_readback(stin_platform *p, const char *kind, const void *data, size_t texel)
{
    const char *path = getenv("STIN_READBACK_LOG");
    int w = stin_platform_width(p), h = stin_platform_height(p);
    FILE *f;
    if (!path || !*path)
        return;
    f = fopen(path, "a");
    if (!f)
        return;
    fprintf(f, "%s %dx%d %016llx\n", kind, w, h,
            (unsigned long long)hash_bytes(data, (size_t)w * (size_t)h * texel));
    fclose(f);
}

int __wrap_stin_platform_read_color(stin_platform *p, uint8_t *rgba)
{
    int ok = __real_stin_platform_read_color(p, rgba);
    if (ok)
        log_readback(p, "color", rgba, 4);
    return ok;
}

int __wrap_stin_platform_read_depth(stin_platform *p, float *depth)
{
    int ok = __real_stin_platform_read_depth(p, depth);
    if (ok)
        log_readback(p, "depth", depth, sizeof(float));
    return ok;
}
