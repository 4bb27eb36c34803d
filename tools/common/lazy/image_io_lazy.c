/* SPDX-License-Identifier: MIT */
/*
 * image_io.h's file half for stin-render: OpenImageIO (image_io.cpp, built
 * into libstin_image_io.so beside the executable) is loaded at the first
 * file read, write or comparison. Linked in, it cost every start about
 * 0.55 CPU s (relocating the ~270 libraries it pulls in), and most runs of
 * stin-render touch no image file: bad input, --no-output, --caps.
 */
#include "image_io.h"

#include <dlfcn.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#define IMAGE_IO_LIBRARY "libstin_image_io.so"

typedef int (*write_fn)(const char *, const image *, int, char *, size_t);
typedef int (*read_fn)(const char *, image *, char *, size_t);
typedef int (*read_memory_fn)(const void *, size_t, const char *, image *, char *, size_t);
typedef int (*compare_fn)(const image *, const image *, const char *, const float *, double,
                          image_diff *);

/* The library's entry `name`, loaded once; NULL with err set (naming
 * `what`) when it cannot be. */
static void *entry(const char *name, const char *what, char *err, size_t err_size)
{
    static void *handle;
    char path[4096];
    void *f;
    if (!handle) {
        ssize_t n = readlink("/proc/self/exe", path, sizeof path - sizeof IMAGE_IO_LIBRARY);
        char *slash;
        if (n <= 0 || (size_t)n >= sizeof path - sizeof IMAGE_IO_LIBRARY) {
            snprintf(err, err_size, "%s: cannot find the folder of " IMAGE_IO_LIBRARY, what);
            return NULL;
        }
        path[n] = '\0';
        slash = strrchr(path, '/');
        memcpy(slash ? slash + 1 : path, IMAGE_IO_LIBRARY, sizeof IMAGE_IO_LIBRARY);
        handle = dlopen(path, RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            snprintf(err, err_size, "%s: %s", what, dlerror());
            return NULL;
        }
    }
    f = dlsym(handle, name);
    if (!f)
        snprintf(err, err_size, "%s: %s", what, dlerror());
    return f;
}

int image_write(const char *path, const image *img, int srgb, char *err, size_t err_size)
{
    void *p = entry("image_write", path, err, err_size);
    write_fn f;
    if (!p)
        return 0;
    memcpy(&f, &p, sizeof f);
    return f(path, img, srgb, err, err_size);
}

int image_read(const char *path, image *img, char *err, size_t err_size)
{
    void *p = entry("image_read", path, err, err_size);
    read_fn f;
    if (!p)
        return 0;
    memcpy(&f, &p, sizeof f);
    return f(path, img, err, err_size);
}

int image_read_memory(const void *data, size_t size, const char *format_hint, image *img,
                      char *err, size_t err_size)
{
    void *p = entry("image_read_memory", format_hint[0] ? format_hint : "embedded image", err,
                    err_size);
    read_memory_fn f;
    if (!p)
        return 0;
    memcpy(&f, &p, sizeof f);
    return f(data, size, format_hint, img, err, err_size);
}

int image_compare(const image *a, const image *b, const char *channels, const float *mask,
                  double threshold, image_diff *out)
{
    char err[256];
    void *p = entry("image_compare", "image_compare", err, sizeof err);
    compare_fn f;
    if (!p)
        return 0;
    memcpy(&f, &p, sizeof f);
    return f(a, b, channels, mask, threshold, out);
}
