/* SPDX-License-Identifier: MIT */
/* The named mesh entries of a scene while it loads (scene_entries.h): parts
 * of primitives and model files, and the models' materials and textures
 * joining the scene's. */
#include "scene_entries.h"
#include "scene_primitives.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const float identity[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };

/* "entry/name", cut to fit a scene name: names of what a model brings. */
static void model_name(char out[SCENE_NAME_MAX], const char *entry, const char *name)
{
    size_t n = strlen(entry), k = strlen(name);
    n = n < SCENE_NAME_MAX - 2 ? n : SCENE_NAME_MAX - 2;
    memmove(out, entry, n);
    out[n++] = '/';
    k = k < SCENE_NAME_MAX - 1 - n ? k : SCENE_NAME_MAX - 1 - n;
    memmove(out + n, name, k);
    out[n + k] = '\0';
}

int scene_warn(scene_parser *p, scene *s, const char *where, const char *text)
{
    size_t old = s->warnings ? strlen(s->warnings) : 0;
    size_t add = strlen(p->file) + strlen(where) + strlen(text) + 6;
    char *grown = realloc(s->warnings, old + add);
    if (!grown)
        return scene_fail(p, where, "out of memory");
    s->warnings = grown;
    snprintf(grown + old, add, "%s: %s: %s\n", p->file, where, text);
    return 1;
}

/* Grows *array (of *cap elements of size) to hold need. */
static int reserve(void **array, int *cap, int need, size_t size)
{
    void *grown;
    int n = *cap ? *cap : 16;
    if (need <= *cap)
        return 1;
    while (n < need)
        n *= 2;
    grown = realloc(*array, (size_t)n * size);
    if (!grown)
        return 0;
    *array = grown;
    *cap = n;
    return 1;
}

static int add_entry(scene_parser *p, scene_entries *e, const char *name, int parts)
{
    scene_entry *grown = realloc(e->entries, ((size_t)e->entry_count + 1) * sizeof *grown);
    if (!grown || !reserve((void **)&e->parts, &e->part_cap, e->part_count + parts, sizeof *e->parts))
        return scene_fail(p, "meshes", "out of memory");
    e->entries = grown;
    grown += e->entry_count++;
    snprintf(grown->name, sizeof grown->name, "%s", name);
    grown->first_part = e->part_count;
    grown->part_count = parts;
    return 1;
}

int scene_entries_add_mesh(scene_parser *p, scene_entries *e, scene *s, const char *name, scene_mesh *m)
{
    scene_part *part;
    if (!reserve((void **)&s->meshes, &e->mesh_cap, s->mesh_count + 1, sizeof *s->meshes) ||
        !add_entry(p, e, name, 1)) {
        scene_mesh_release(m);
        return scene_fail(p, "meshes", "out of memory");
    }
    snprintf(m->name, sizeof m->name, "%s", name);
    s->meshes[s->mesh_count] = *m;
    part = &e->parts[e->part_count++];
    part->mesh = s->mesh_count++;
    part->material = -1;
    memcpy(part->transform, identity, sizeof identity);
    return 1;
}

/* Each line of the model's warnings, prefixed with where it came from. */
static int forward_warnings(scene_parser *p, scene *s, const char *where, const char *rel,
                            const char *lines)
{
    char text[768];
    while (lines && *lines) {
        const char *nl = strchr(lines, '\n');
        int n = nl ? (int)(nl - lines) : (int)strlen(lines);
        snprintf(text, sizeof text, "'%s': %.*s", rel, n, lines);
        if (!scene_warn(p, s, where, text))
            return 0;
        lines += n + (nl != NULL);
    }
    return 1;
}

int scene_entries_add_model(scene_parser *p, scene_entries *e, scene *s, const char *name,
                            const char *where, const char *full, const char *rel)
{
    scene_model m;
    scene_model *models;
    int *owner, base = s->mesh_count;
    uint32_t i;
    char why[512];
    if (!scene_model_load(full, &m, why, sizeof why))
        return scene_fail(p, where, "cannot open '%s': %s", rel, why);
    models = realloc(e->models, ((size_t)e->model_count + 1) * sizeof *models);
    if (models)
        e->models = models;
    owner = realloc(e->model_entry, ((size_t)e->model_count + 1) * sizeof *owner);
    if (owner)
        e->model_entry = owner;
    if (!models || !owner ||
        !reserve((void **)&s->meshes, &e->mesh_cap, s->mesh_count + (int)m.mesh_count, sizeof *s->meshes) ||
        !add_entry(p, e, name, (int)m.part_count)) {
        scene_model_free(&m);
        return scene_fail(p, where, "out of memory");
    }
    for (i = 0; i < m.mesh_count; i++) {
        char mesh_name[SCENE_NAME_MAX];
        if (m.mesh_count == 1) /* the entry's own name, as before nodes were kept */
            snprintf(mesh_name, sizeof mesh_name, "%s", name);
        else
            model_name(mesh_name, name, m.meshes[i].name);
        s->meshes[s->mesh_count] = m.meshes[i];
        memcpy(s->meshes[s->mesh_count++].name, mesh_name, sizeof mesh_name);
    }
    m.mesh_count = 0; /* the scene owns them now */
    for (i = 0; i < m.part_count; i++) {
        scene_part *part = &e->parts[e->part_count++];
        part->mesh = base + (int)m.parts[i].mesh;
        part->material = m.parts[i].material; /* model-relative until add_materials */
        memcpy(part->transform, m.parts[i].transform, sizeof part->transform);
    }
    e->model_entry[e->model_count] = e->entry_count - 1;
    e->models[e->model_count++] = m;
    return forward_warnings(p, s, where, rel, m.warnings);
}

/* Opaque use of a texture's alpha would show through the EXR's A. */
static void drop_unused_alpha(const scene_model *m, scene_texture *textures)
{
    uint32_t i, k;
    for (i = 0; i < m->texture_count; i++) {
        int blended = 0, opaque = 0;
        for (k = 0; k < m->material_count; k++)
            if (m->materials[k].albedo == (int32_t)i) {
                blended |= m->materials[k].alpha_mode == SCENE_ALPHA_BLEND;
                opaque |= m->materials[k].alpha_mode != SCENE_ALPHA_BLEND;
            }
        if (opaque && !blended)
            for (k = 0; k < (uint32_t)(textures[i].width * textures[i].height); k++)
                textures[i].rgba[4 * (size_t)k + 3] = 255;
    }
}

static void convert_material(const scene_model_material *in, const char *entry, int texture_base,
                             scene_material *out)
{
    scene_material_defaults(out);
    model_name(out->name, entry, in->name);
    memcpy(out->color, in->color, sizeof out->color);
    if (in->alpha_mode != SCENE_ALPHA_BLEND)
        out->color[3] = 1;
    memcpy(out->specular, in->specular, sizeof out->specular);
    if (in->specular[0] + in->specular[1] + in->specular[2] > 0)
        out->shininess = in->shininess;
    out->albedo = in->albedo >= 0 ? texture_base + in->albedo : -1;
    out->normal = in->normal >= 0 ? texture_base + in->normal : -1;
}

static int add_model_materials(scene_parser *p, scene_entries *e, scene *s, int k)
{
    scene_model *m = &e->models[k];
    const scene_entry *entry = &e->entries[e->model_entry[k]];
    int tex_base = s->texture_count, mat_base = s->material_count, i;
    char where[256], text[256];
    scene_texture *tex = realloc(s->textures,
                                 ((size_t)s->texture_count + m->texture_count + 1) * sizeof *tex);
    scene_material *mat;
    if (tex)
        s->textures = tex;
    /* one spare material slot stays for the implicit "default" */
    mat = realloc(s->materials, ((size_t)s->material_count + m->material_count + 1) * sizeof *mat);
    if (mat)
        s->materials = mat;
    if (!tex || !mat)
        return scene_fail(p, "materials", "out of memory");
    drop_unused_alpha(m, m->textures);
    for (i = 0; i < (int)m->texture_count; i++) {
        s->textures[s->texture_count] = m->textures[i];
        model_name(s->textures[s->texture_count++].name, entry->name, m->textures[i].name);
    }
    m->texture_count = 0; /* the scene owns the pixels now */
    for (i = 0; i < (int)m->material_count; i++) {
        convert_material(&m->materials[i], entry->name, tex_base, &s->materials[s->material_count++]);
        snprintf(where, sizeof where, "meshes.%s.file", entry->name);
        snprintf(text, sizeof text, "material '%s': alpha mode MASK drawn opaque (stin has no "
                 "alpha test)", m->materials[i].name);
        if (m->materials[i].alpha_mode == SCENE_ALPHA_MASK && !scene_warn(p, s, where, text))
            return 0;
    }
    for (i = entry->first_part; i < entry->first_part + entry->part_count; i++)
        if (e->parts[i].material >= 0)
            e->parts[i].material += mat_base;
    return 1;
}

int scene_entries_add_materials(scene_parser *p, scene_entries *e, scene *s)
{
    int k;
    for (k = 0; k < e->model_count; k++)
        if (!add_model_materials(p, e, s, k))
            return 0;
    return 1;
}

int scene_entries_find(const scene_entries *e, const char *name)
{
    int i;
    for (i = 0; i < e->entry_count; i++)
        if (strcmp(e->entries[i].name, name) == 0)
            return i;
    return -1;
}

void scene_entries_free(scene_entries *e)
{
    int k;
    for (k = 0; k < e->model_count; k++)
        scene_model_free(&e->models[k]);
    free(e->models);
    free(e->model_entry);
    free(e->entries);
    free(e->parts);
    memset(e, 0, sizeof *e);
}
