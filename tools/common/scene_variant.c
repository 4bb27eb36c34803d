/* SPDX-License-Identifier: MIT */
/* The surface tests' views of a normal-mapped scene (scene_variant.h). */
#include "scene_variant.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

int scene_variant_mapped(const scene *s, float centre[3], float normal[3])
{
    int o, k;
    for (o = 0; o < s->object_count; o++) {
        const scene_material *m = &s->materials[s->objects[o].material];
        const scene_mesh *me = &s->meshes[s->objects[o].mesh];
        const float *x = s->objects[o].transform;
        float len;
        if (m->normal < 0 || !me->vertex_count)
            continue;
        for (k = 0; k < 3; k++) { /* the mesh's first vertex normal through the transform */
            centre[k] = x[12 + k];
            normal[k] = x[k] * me->normals[0] + x[4 + k] * me->normals[1] + x[8 + k] * me->normals[2];
        }
        len = sqrtf(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
        for (k = 0; k < 3; k++)
            normal[k] /= len;
        return 1;
    }
    return 0;
}

int scene_variant_parallax_object(const scene *s)
{
    int o;
    for (o = 0; o < s->object_count; o++) {
        const scene_material *m = &s->materials[s->objects[o].material];
        if (m->normal >= 0 && m->height >= 0 && s->meshes[s->objects[o].mesh].uvs)
            return o;
    }
    return -1;
}

static void cross(const float a[3], const float b[3], float out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

void scene_variant_plane(const float n[3], float t[3], float b[3])
{
    float up[3] = {0, 1, 0}, len;
    int k;
    if (fabsf(n[1]) > 0.9f) {
        up[0] = 1;
        up[1] = 0;
    }
    cross(n, up, t);
    len = sqrtf(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
    for (k = 0; k < 3; k++)
        t[k] /= len;
    cross(n, t, b);
}

int scene_variant_down(const scene *s, scene *out)
{
    float c[3], n[3];
    int k;
    if (!scene_variant_mapped(s, c, n))
        return 0;
    *out = *s;
    for (k = 0; k < 3; k++) {
        out->camera.eye[k] = c[k] + 160.0f * n[k];
        out->camera.target[k] = c[k];
    }
    out->camera.up[0] = fabsf(n[1]) > 0.9f ? 1.0f : 0.0f;
    out->camera.up[1] = fabsf(n[1]) > 0.9f ? 0.0f : 1.0f;
    out->camera.up[2] = 0.0f;
    out->camera.fovy_deg = 0.25f;
    out->camera.near_plane = 150.0f;
    out->camera.far_plane = 170.0f;
    return 1;
}

int scene_variant_limit(const scene *s, scene *out, int *material)
{
    scene_texture *tex;
    scene_material *mat;
    float c[3], n[3], t[3], b[3];
    int o = scene_variant_parallax_object(s), mi, x, y, k;
    if (o < 0 || !scene_variant_mapped(s, c, n))
        return 0;
    mi = s->objects[o].material;
    tex = calloc((size_t)s->texture_count + 1, sizeof *tex);
    mat = calloc((size_t)s->material_count, sizeof *mat);
    if (tex)
        tex[s->texture_count].rgba = malloc(4 * 256 * 256);
    if (!tex || !mat || !tex[s->texture_count].rgba) {
        free(tex ? tex[s->texture_count].rgba : NULL);
        free(tex);
        free(mat);
        return 0;
    }
    /* the bilinear sample at any uv away from the repeat seam is exactly
     * ((u * 256 - 0.5) / 255, (v * 256 - 0.5) / 255), at every mip level */
    memcpy(tex, s->textures, sizeof *tex * (size_t)s->texture_count);
    tex[s->texture_count].kind = SCENE_TEXTURE_ALBEDO;
    strcpy(tex[s->texture_count].name, "uv-gradient");
    tex[s->texture_count].width = tex[s->texture_count].height = 256;
    for (y = 0; y < 256; y++)
        for (x = 0; x < 256; x++) {
            uint8_t *q = tex[s->texture_count].rgba + 4 * (256 * y + x);
            q[0] = (uint8_t)x;
            q[1] = (uint8_t)y;
            q[2] = 0;
            q[3] = 255;
        }
    memcpy(mat, s->materials, sizeof *mat * (size_t)s->material_count);
    mat[mi].albedo = s->texture_count;
    for (k = 0; k < 4; k++)
        mat[mi].color[k] = 1.0f;
    for (k = 0; k < 3; k++)
        mat[mi].specular[k] = 0.0f;
    mat[mi].height_scale = SCENE_VARIANT_LIMIT_SCALE;
    mat[mi].self_shadow = 0;
    *out = *s;
    out->textures = tex;
    out->texture_count = s->texture_count + 1;
    out->materials = mat;
    out->light_count = 0; /* beauty = ambient 1 * albedo: the sampled uv */
    for (k = 0; k < 3; k++)
        out->ambient[k] = 1.0f;
    scene_variant_plane(n, t, b);
    for (k = 0; k < 3; k++) { /* grazing: V.z from ~0.2 to ~0.45 over the object */
        out->camera.eye[k] = c[k] + 5.0f * t[k] + 1.5f * n[k];
        out->camera.target[k] = c[k];
        out->camera.up[k] = b[k];
    }
    out->camera.fovy_deg = 40.0f;
    out->camera.near_plane = 0.5f;
    out->camera.far_plane = 30.0f;
    *material = mi;
    return 1;
}

int scene_variant_make(const scene *s, const char *name, scene *out)
{
    int mi;
    if (!strcmp(name, "parallax-down"))
        return scene_variant_down(s, out);
    if (!strcmp(name, "parallax-limit"))
        return scene_variant_limit(s, out, &mi);
    return 0;
}

void scene_variant_free(scene *v, const scene *s)
{
    if (v->textures == s->textures) /* down: the source's own */
        return;
    free(v->textures[v->texture_count - 1].rgba);
    free(v->textures);
    free(v->materials);
    v->textures = NULL;
    v->materials = NULL;
}
