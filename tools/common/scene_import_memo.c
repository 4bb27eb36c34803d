/* SPDX-License-Identifier: MIT */
/* scene_import: a decoder's run in a child (isolate.h), remembered per file
 * where scene_import_memo asks for it. */
#include "scene_internal.h"

#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int scene_import_memo;

/* A file's decoded bytes, under what identifies the file's contents. */
typedef struct memo_entry {
    struct memo_entry *next;
    isolate_work work;
    char *path;
    dev_t dev;
    ino_t ino;
    off_t size;
    struct timespec mtime;
    unsigned char *bytes;
    size_t count;
} memo_entry;

static memo_entry *memo;
static size_t memo_bytes;
/* Past this the memo keeps no more (the scenes' files take under 1 MB). */
#define MEMO_MAX ((size_t)256 << 20)

static int same_file(const memo_entry *e, isolate_work work, const char *path,
                     const struct stat *st)
{
    return e->work == work && !strcmp(e->path, path) && e->dev == st->st_dev &&
           e->ino == st->st_ino && e->size == st->st_size &&
           e->mtime.tv_sec == st->st_mtim.tv_sec && e->mtime.tv_nsec == st->st_mtim.tv_nsec;
}

static int copy_out(const unsigned char *bytes, size_t count, unsigned char **out,
                    size_t *out_size)
{
    *out = malloc(count ? count : 1);
    if (!*out)
        return 0;
    memcpy(*out, bytes, count);
    *out_size = count;
    return 1;
}

static void remember(isolate_work work, const char *path, const struct stat *st,
                     const unsigned char *bytes, size_t count)
{
    memo_entry *e;
    if (memo_bytes + count > MEMO_MAX || !(e = calloc(1, sizeof *e)))
        return;
    e->path = malloc(strlen(path) + 1);
    if (!e->path || !copy_out(bytes, count, &e->bytes, &e->count)) {
        free(e->path);
        free(e);
        return;
    }
    strcpy(e->path, path);
    e->work = work;
    e->dev = st->st_dev;
    e->ino = st->st_ino;
    e->size = st->st_size;
    e->mtime = st->st_mtim;
    e->next = memo;
    memo = e;
    memo_bytes += count;
}

int scene_import(isolate_work work, const char *path, unsigned char **out, size_t *out_size,
                 char *why, size_t why_size)
{
    struct stat st, again;
    const memo_entry *e;
    int known = scene_import_memo && stat(path, &st) == 0;
    for (e = memo; known && e; e = e->next)
        if (same_file(e, work, path, &st) && copy_out(e->bytes, e->count, out, out_size))
            return 1;
    if (!isolate_run(work, (void *)path, scene_import_seconds, SCENE_IMPORT_BYTES_MAX, out,
                     out_size, why, why_size))
        return 0;
    /* kept only if the file is the one stat'ed before the decoder read it */
    if (known && stat(path, &again) == 0 && st.st_mtim.tv_sec == again.st_mtim.tv_sec &&
        st.st_mtim.tv_nsec == again.st_mtim.tv_nsec && st.st_size == again.st_size)
        remember(work, path, &st, *out, *out_size);
    return 1;
}
