/* SPDX-License-Identifier: MIT */
/* Child side of a model import: assimp materials -> base colour, alpha and
 * its mode, OBJ specular, and the base-colour and normal textures decoded to
 * RGBA8 (files beside the model, or images embedded in a .glb: "*N"). A
 * texture that cannot be had is a warning; the material keeps its colour. */
#include "scene_internal.h"
#include "scene_model.h"
#include "image_io.h"

#include <assimp/GltfMaterial.h>
#include <assimp/material.h>
#include <assimp/scene.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int scene_model_warn(scene_model *m, const char *fmt, ...)
{
    char line[512];
    size_t old = m->warnings ? strlen(m->warnings) : 0;
    char *grown;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
    grown = realloc(m->warnings, old + strlen(line) + 2);
    if (!grown)
        return 0;
    m->warnings = grown;
    snprintf(grown + old, strlen(line) + 2, "%s\n", line);
    return 1;
}

/* Embedded texture N: compressed (PNG, JPEG: decoded from memory) or raw
 * BGRA texels, rows top first. */
static int decode_embedded(const struct aiScene *sc, const char *ref, image *img, char *why,
                           size_t why_size)
{
    char *end;
    long n = strtol(ref + 1, &end, 10);
    const struct aiTexture *t;
    size_t x, count;
    if (end == ref + 1 || *end || n < 0 || (unsigned long)n >= sc->mNumTextures || !sc->mTextures ||
        !(t = sc->mTextures[n]) || !t->pcData)
        return snprintf(why, why_size, "no embedded texture %.60s in the file", ref), 0;
    if (t->mHeight == 0)
        return image_read_memory(t->pcData, t->mWidth, t->achFormatHint, img, why, why_size);
    if (t->mWidth > 8192 || t->mHeight > 8192 || !image_alloc(img, (int)t->mWidth, (int)t->mHeight, 4))
        return snprintf(why, why_size, "embedded texture %.60s too large", ref), 0;
    count = (size_t)t->mWidth * t->mHeight;
    for (x = 0; x < count; x++) {
        img->pixels[4 * x + 0] = t->pcData[x].r / 255.0f;
        img->pixels[4 * x + 1] = t->pcData[x].g / 255.0f;
        img->pixels[4 * x + 2] = t->pcData[x].b / 255.0f;
        img->pixels[4 * x + 3] = t->pcData[x].a / 255.0f;
    }
    return 1;
}

/* A file next to the model; OBJ files written on Windows use backslashes. */
static int decode_file(const char *model_path, const char *ref, image *img, char *why, size_t why_size)
{
    char rel[1024], full[2048];
    size_t i;
    snprintf(rel, sizeof rel, "%s", ref);
    for (i = 0; rel[i]; i++)
        if (rel[i] == '\\')
            rel[i] = '/';
    if (!scene_resolve_path(model_path, rel, full, sizeof full))
        return snprintf(why, why_size, "path too long"), 0;
    return scene_check_regular_file(full, why, why_size) && image_read(full, img, why, why_size);
}

/* Index of the texture `ref` of `kind` in m, decoded once; -1 when it
 * cannot be had (warned), -2 when out of memory. */
static int32_t use_texture(scene_model *m, const struct aiScene *sc, const char *model_path,
                           const char *material, const char *ref, scene_texture_kind kind)
{
    char why[512] = "";
    scene_texture *grown, *t;
    image img;
    uint32_t i;
    size_t n;
    int ok;
    for (i = 0; i < m->texture_count; i++)
        if (m->textures[i].kind == kind && strlen(ref) < SCENE_NAME_MAX && !strcmp(m->textures[i].name, ref))
            return (int32_t)i;
    ok = ref[0] == '*' ? decode_embedded(sc, ref, &img, why, sizeof why)
                       : decode_file(model_path, ref, &img, why, sizeof why);
    if (ok && (img.width > SCENE_TEXTURE_SIZE_MAX || img.height > SCENE_TEXTURE_SIZE_MAX)) {
        snprintf(why, sizeof why, "larger than %d texels", SCENE_TEXTURE_SIZE_MAX);
        image_free(&img);
        ok = 0;
    }
    if (!ok)
        return scene_model_warn(m, "material '%s': texture '%s' left out: %s", material, ref, why) ? -1 : -2;
    grown = realloc(m->textures, (m->texture_count + 1) * sizeof *grown);
    if (!grown) {
        image_free(&img);
        return -2;
    }
    m->textures = grown;
    t = &grown[m->texture_count];
    memset(t, 0, sizeof *t);
    /* the end of a long path names it best */
    n = strlen(ref);
    snprintf(t->name, sizeof t->name, "%.63s", ref + (n < SCENE_NAME_MAX ? 0 : n - (SCENE_NAME_MAX - 1)));
    t->kind = kind;
    t->width = img.width;
    t->height = img.height;
    t->rgba = malloc(4 * (size_t)img.width * (size_t)img.height);
    if (!t->rgba) {
        image_free(&img);
        return -2;
    }
    /* glTF base colour textures are sRGB-encoded; stin's albedo is linear. */
    scene_image_to_rgba8(&img, kind == SCENE_TEXTURE_ALBEDO, t->rgba);
    image_free(&img);
    return (int32_t)m->texture_count++;
}

static int32_t texture_slot(scene_model *m, const struct aiScene *sc, const struct aiMaterial *mat,
                            const char *model_path, const char *name, enum aiTextureType type,
                            scene_texture_kind kind)
{
    struct aiString path;
    unsigned uv = 0;
    if (aiGetMaterialTextureCount(mat, type) == 0 ||
        aiGetMaterialTexture(mat, type, 0, &path, NULL, &uv, NULL, NULL, NULL, NULL) != AI_SUCCESS ||
        !path.data[0])
        return -1;
    if (uv != 0) /* scene meshes carry one uv set */
        return scene_model_warn(m, "material '%s': texture '%s' uses uv set %u, left out", name,
                                path.data, uv) ? -1 : -2;
    return use_texture(m, sc, model_path, name, path.data, kind);
}

static float clamp_unit(float x)
{
    return x > 0 ? (x < 1 ? x : 1) : 0; /* also NaN -> 0 */
}

int32_t scene_model_add_material(scene_model *m, const void *ai, unsigned index, const char *model_path)
{
    const struct aiScene *sc = ai;
    const struct aiMaterial *mat = sc->mMaterials[index];
    struct aiColor4D c = { 0.8f, 0.8f, 0.8f, 1 };
    struct aiString name, mode;
    scene_model_material *grown, *out;
    float opacity = 1, shininess = 0;
    int k;
    if (!mat)
        return -1;
    if (aiGetMaterialString(mat, AI_MATKEY_NAME, &name) != AI_SUCCESS || !name.data[0] ||
        !strcmp(name.data, AI_DEFAULT_MATERIAL_NAME))
        return -1; /* assimp's stand-in: the object's material applies */
    grown = realloc(m->materials, (m->material_count + 1) * sizeof *grown);
    if (!grown)
        return -2;
    m->materials = grown;
    out = &grown[m->material_count];
    memset(out, 0, sizeof *out);
    snprintf(out->name, sizeof out->name, "%.63s", name.data);
    if (aiGetMaterialColor(mat, AI_MATKEY_BASE_COLOR, &c) != AI_SUCCESS)
        aiGetMaterialColor(mat, AI_MATKEY_COLOR_DIFFUSE, &c); /* OBJ Kd (alpha 1) */
    if (aiGetMaterialFloatArray(mat, AI_MATKEY_OPACITY, &opacity, NULL) == AI_SUCCESS && opacity < c.a)
        c.a = opacity; /* OBJ d */
    out->color[0] = clamp_unit(c.r);
    out->color[1] = clamp_unit(c.g);
    out->color[2] = clamp_unit(c.b);
    out->color[3] = clamp_unit(c.a);
    out->alpha_mode = out->color[3] < 1 ? SCENE_ALPHA_BLEND : SCENE_ALPHA_OPAQUE;
    if (aiGetMaterialString(mat, AI_MATKEY_GLTF_ALPHAMODE, &mode) == AI_SUCCESS)
        out->alpha_mode = !strcmp(mode.data, "BLEND") ? SCENE_ALPHA_BLEND
                        : !strcmp(mode.data, "MASK")  ? SCENE_ALPHA_MASK
                                                      : SCENE_ALPHA_OPAQUE;
    else if (aiGetMaterialColor(mat, AI_MATKEY_COLOR_SPECULAR, &c) == AI_SUCCESS) {
        /* Blinn-Phong terms only from formats that have them (OBJ Ks, Ns). */
        out->specular[0] = clamp_unit(c.r);
        out->specular[1] = clamp_unit(c.g);
        out->specular[2] = clamp_unit(c.b);
        if (aiGetMaterialFloatArray(mat, AI_MATKEY_SHININESS, &shininess, NULL) == AI_SUCCESS)
            out->shininess = shininess > 0 ? (shininess < 128 ? shininess : 128) : 0;
    }
    m->material_count++; /* before the textures: their warnings name it */
    for (k = 0; k < 2; k++) {
        int32_t t = k == 0 ? texture_slot(m, sc, mat, model_path, out->name, aiTextureType_DIFFUSE,
                                          SCENE_TEXTURE_ALBEDO)
                           : texture_slot(m, sc, mat, model_path, out->name, aiTextureType_NORMALS,
                                          SCENE_TEXTURE_NORMAL);
        if (t == -2)
            return -2;
        out = &m->materials[m->material_count - 1];
        *(k == 0 ? &out->albedo : &out->normal) = t;
    }
    return (int32_t)(m->material_count - 1);
}
