/* SPDX-License-Identifier: MIT */
/* The scene pack (scene_pack.h): one walk over the layout serves sizing,
 * writing and reading, so the three cannot disagree. */
#include "scene_pack.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PACK_MAGIC "STINPACK"
#define PACK_VERSION 1u

typedef struct pack_cursor {
    unsigned char *out;        /* writing: the block; NULL when sizing or reading */
    const unsigned char *in;   /* reading: the block */
    size_t at, size;           /* size: the block's, when reading */
    int failed;
} pack_cursor;

static size_t align4(size_t n) { return (n + 3u) & ~(size_t)3u; }

/* Moves bytes between the block and *field (copied in both directions), or
 * with share set, points *(void **)field at them inside the block. */
static void *pack_bytes(pack_cursor *c, void *field, size_t bytes, int share)
{
    size_t at = c->at;
    c->at = align4(c->at + bytes);
    if (c->failed)
        return NULL;
    if (c->in) {
        if (c->at > c->size || c->at < at) {
            c->failed = 1;
            return NULL;
        }
        if (share)
            return (void *)(c->in + at);
        memcpy(field, c->in + at, bytes);
    } else if (c->out && bytes) {
        memcpy(c->out + at, share ? *(void **)field : field, bytes);
    }
    return field;
}

#define PACK_FIELD(c, f) pack_bytes(c, &(f), sizeof(f), 0)

/* An array of count items of item bytes, shared with the block on reads. */
static void pack_array(pack_cursor *c, void *pointer_field, size_t count, size_t item)
{
    void *p = pack_bytes(c, pointer_field, count * item, 1);
    if (c->in && !c->failed && count && count * item / count != item)
        c->failed = 1;
    if (c->in)
        *(void **)pointer_field = c->failed ? NULL : p;
}

static void walk(pack_cursor *c, scene *s)
{
    char magic[8];
    uint32_t layout[7] = {PACK_VERSION, sizeof(scene_material), sizeof(scene_object),
                          sizeof(scene_light), sizeof(scene_camera), sizeof(scene_csg), 0};
    uint32_t expect[7];
    int i;
    memcpy(magic, PACK_MAGIC, 8);
    memcpy(expect, layout, sizeof expect);
    PACK_FIELD(c, magic);
    PACK_FIELD(c, layout);
    if (c->in && !c->failed &&
        (memcmp(magic, PACK_MAGIC, 8) || memcmp(layout, expect, sizeof layout)))
        c->failed = 1;
    PACK_FIELD(c, s->path);
    PACK_FIELD(c, s->mesh_count);
    PACK_FIELD(c, s->texture_count);
    PACK_FIELD(c, s->material_count);
    PACK_FIELD(c, s->object_count);
    PACK_FIELD(c, s->light_count);
    PACK_FIELD(c, s->csg_count);
    PACK_FIELD(c, s->camera);
    PACK_FIELD(c, s->has_camera);
    PACK_FIELD(c, s->ambient);
    PACK_FIELD(c, s->background);
    PACK_FIELD(c, s->width);
    PACK_FIELD(c, s->height);
    PACK_FIELD(c, s->shadow_map_size);
    if (c->failed || s->mesh_count < 0 || s->texture_count < 0 || s->material_count < 0 ||
        s->object_count < 0 || s->light_count < 0 || s->csg_count < 0) {
        c->failed = 1;
        return;
    }
    if (c->in) {
        s->meshes = calloc((size_t)s->mesh_count + 1, sizeof *s->meshes);
        s->textures = calloc((size_t)s->texture_count + 1, sizeof *s->textures);
        if (!s->meshes || !s->textures) {
            c->failed = 1;
            return;
        }
    }
    for (i = 0; i < s->mesh_count && !c->failed; i++) {
        scene_mesh *m = &s->meshes[i];
        PACK_FIELD(c, m->name);
        PACK_FIELD(c, m->vertex_count);
        PACK_FIELD(c, m->triangle_count);
        m->name[sizeof m->name - 1] = '\0';
        pack_array(c, &m->positions, m->vertex_count, 3 * sizeof(float));
        pack_array(c, &m->normals, m->vertex_count, 3 * sizeof(float));
        pack_array(c, &m->uvs, m->vertex_count, 2 * sizeof(float));
        pack_array(c, &m->indices, m->triangle_count, 3 * sizeof(uint32_t));
    }
    for (i = 0; i < s->texture_count && !c->failed; i++) {
        scene_texture *t = &s->textures[i];
        PACK_FIELD(c, t->name);
        PACK_FIELD(c, t->kind);
        PACK_FIELD(c, t->width);
        PACK_FIELD(c, t->height);
        t->name[sizeof t->name - 1] = '\0';
        if (t->width < 0 || t->height < 0)
            c->failed = 1;
        else
            pack_array(c, &t->rgba, (size_t)t->width * (size_t)t->height, 4);
    }
    pack_array(c, &s->materials, (size_t)s->material_count, sizeof *s->materials);
    pack_array(c, &s->objects, (size_t)s->object_count, sizeof *s->objects);
    pack_array(c, &s->lights, (size_t)s->light_count, sizeof *s->lights);
    pack_array(c, &s->csg, (size_t)s->csg_count, sizeof *s->csg);
}

size_t scene_pack_size(const scene *s)
{
    pack_cursor c;
    scene copy = *s;
    memset(&c, 0, sizeof c);
    walk(&c, &copy);
    return c.at;
}

void scene_pack_write(const scene *s, unsigned char *out)
{
    pack_cursor c;
    scene copy = *s;
    memset(&c, 0, sizeof c);
    memset(out, 0, scene_pack_size(s));
    c.out = out;
    walk(&c, &copy);
}

int scene_pack_read(const unsigned char *data, size_t size, scene *out, char *err, size_t err_size)
{
    pack_cursor c;
    memset(&c, 0, sizeof c);
    memset(out, 0, sizeof *out);
    c.in = data;
    c.size = size;
    if (((size_t)data & 3u) != 0)
        c.failed = 1;
    else
        walk(&c, out);
    if (!c.failed) {
        out->path[sizeof out->path - 1] = '\0';
        return 1;
    }
    scene_pack_release(out);
    if (err && err_size)
        snprintf(err, err_size, "not a scene pack of this build (version %u), or cut short",
                 PACK_VERSION);
    return 0;
}

void scene_pack_release(scene *s)
{
    free(s->meshes);
    free(s->textures);
    memset(s, 0, sizeof *s);
}
