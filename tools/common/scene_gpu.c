/* Scene -> libstin: meshes, textures, materials and one frame. */
#include "scene_gpu.h"

#include <stdlib.h>
#include <stdio.h>
#include <string.h>

/* Each capacity stin_create accepts (include/stin/stin.h, stin_desc):
 * max_meshes and max_textures <= 65535, max_vertices < 2^30,
 * max_triangles < 2^29, max_draws < 2^24; max_texture_bytes is a uint32_t. */
#define LIMIT_MESHES 65535u
#define LIMIT_TEXTURES 65535u
#define LIMIT_DRAWS (0x1000000u - 1u)
#define LIMIT_VERTICES (0x40000000u - 1u)
#define LIMIT_TRIANGLES (0x20000000u - 1u)
#define LIMIT_TEXTURE_BYTES 0xffffffffu

/* have, raised to want; 0 when want is past the library's limit. */
static int raise_to(uint32_t *have, uint64_t want, uint32_t limit)
{
    if (want > limit)
        return 0;
    if (*have < want)
        *have = (uint32_t)want;
    return 1;
}

/* Staging for one texture: level 0 plus the mip chain, with room for a
 * power-of-two resample (GL1). */
static uint64_t texture_bytes(const scene_texture *t)
{
    uint64_t w = 1, h = 1;
    while (w < (uint64_t)t->width)
        w <<= 1;
    while (h < (uint64_t)t->height)
        h <<= 1;
    return w * h * 4u * 2u;
}

int scene_gpu_size_desc_checked(const scene *s, stin_desc *desc, char *err, size_t err_size)
{
    uint64_t verts = 0, tris = 0, biggest = 0, bytes = 0;
    const char *what = NULL;
    int i;
    for (i = 0; i < s->mesh_count; i++) {
        verts += s->meshes[i].vertex_count;
        tris += s->meshes[i].triangle_count;
        if (s->meshes[i].triangle_count > biggest)
            biggest = s->meshes[i].triangle_count;
    }
    for (i = 0; i < s->texture_count; i++)
        if (texture_bytes(&s->textures[i]) > bytes)
            bytes = texture_bytes(&s->textures[i]);
    if (!raise_to(&desc->max_meshes, (uint64_t)s->mesh_count, LIMIT_MESHES))
        what = "meshes: more than 65535";
    else if (!raise_to(&desc->max_textures, (uint64_t)s->texture_count, LIMIT_TEXTURES))
        what = "textures: more than 65535";
    else if (!raise_to(&desc->max_draws, (uint64_t)s->object_count, LIMIT_DRAWS))
        what = "objects: more instances than stin draws in a frame";
    else if (!raise_to(&desc->max_lights, (uint64_t)s->light_count, 32u))
        what = "lights: at most 32";
    else if (!raise_to(&desc->max_vertices, verts, LIMIT_VERTICES))
        what = "meshes: more vertices than stin holds";
    else if (!raise_to(&desc->max_triangles, tris, LIMIT_TRIANGLES))
        what = "meshes: more triangles than stin holds";
    else if (!raise_to(&desc->max_mesh_triangles, biggest, LIMIT_TRIANGLES))
        what = "meshes: a mesh has more triangles than stin holds";
    else if (!raise_to(&desc->max_texture_bytes, bytes, LIMIT_TEXTURE_BYTES))
        what = "textures: a texture is too large to stage";
    if (what && err && err_size)
        snprintf(err, err_size, "%s: %s", s->path, what);
    return what == NULL;
}

void scene_gpu_size_desc(const scene *s, stin_desc *desc)
{
    scene_gpu_size_desc_checked(s, desc, NULL, 0);
}

static stin_texture_kind texture_kind(scene_texture_kind k)
{
    return k == SCENE_TEXTURE_NORMAL ? STIN_TEXTURE_NORMAL
         : k == SCENE_TEXTURE_HEIGHT ? STIN_TEXTURE_HEIGHT
                                     : STIN_TEXTURE_ALBEDO;
}

int scene_gpu_create(scene_gpu *g, const scene *s, stin_context *ctx, char *err, size_t err_size)
{
    int i;
    memset(g, 0, sizeof *g);
    g->src = s;
    g->meshes = calloc((size_t)s->mesh_count + 1, sizeof *g->meshes);
    g->textures = calloc((size_t)s->texture_count + 1, sizeof *g->textures);
    g->materials = calloc((size_t)s->material_count + 1, sizeof *g->materials);
    if (!g->meshes || !g->textures || !g->materials) {
        snprintf(err, err_size, "out of memory");
        scene_gpu_destroy(g, ctx);
        return 0;
    }
    for (i = 0; i < s->mesh_count; i++) {
        const scene_mesh *m = &s->meshes[i];
        stin_mesh_desc md;
        stin_result r;
        memset(&md, 0, sizeof md);
        md.positions = m->positions;
        md.normals = m->normals;
        md.uvs = m->uvs;
        md.vertex_count = m->vertex_count;
        md.indices = m->indices;
        md.index_count = 3u * m->triangle_count;
        r = stin_create_mesh(ctx, &md, &g->meshes[i]);
        if (r != STIN_OK) {
            snprintf(err, err_size, "%s: meshes.%s: %s", s->path, m->name, stin_result_name(r));
            scene_gpu_destroy(g, ctx);
            return 0;
        }
    }
    for (i = 0; i < s->texture_count; i++) {
        const scene_texture *t = &s->textures[i];
        stin_texture_desc td;
        stin_result r;
        memset(&td, 0, sizeof td);
        td.kind = texture_kind(t->kind);
        td.width = (uint32_t)t->width;
        td.height = (uint32_t)t->height;
        td.pixels = t->rgba;
        r = stin_create_texture(ctx, &td, &g->textures[i]);
        if (r != STIN_OK) {
            snprintf(err, err_size, "%s: textures.%s: %s", s->path, t->name, stin_result_name(r));
            scene_gpu_destroy(g, ctx);
            return 0;
        }
    }
    for (i = 0; i < s->material_count; i++) {
        const scene_material *sm = &s->materials[i];
        stin_material *m = &g->materials[i];
        memcpy(m->color, sm->color, sizeof m->color);
        memcpy(m->specular, sm->specular, sizeof m->specular);
        m->shininess = sm->shininess;
        if (sm->albedo >= 0)
            m->albedo = g->textures[sm->albedo];
        if (sm->normal >= 0)
            m->normal_map = g->textures[sm->normal];
        if (sm->height >= 0)
            m->height_map = g->textures[sm->height];
        /* stin's 0 means its default: a scene's explicit 0 is a flat field */
        m->height_scale = sm->height_scale > 0.0f ? sm->height_scale : 1e-30f;
        m->self_shadow = sm->self_shadow;
        m->two_sided = sm->two_sided;
        if (sm->surface[0])
            m->surface = stin_technique_from_name(sm->surface);
    }
    return 1;
}

void scene_gpu_destroy(scene_gpu *g, stin_context *ctx)
{
    int i;
    if (g->src && ctx) {
        for (i = 0; g->meshes && i < g->src->mesh_count; i++)
            if (g->meshes[i].id)
                stin_destroy_mesh(ctx, g->meshes[i]);
        for (i = 0; g->textures && i < g->src->texture_count; i++)
            if (g->textures[i].id)
                stin_destroy_texture(ctx, g->textures[i]);
    }
    free(g->meshes);
    free(g->textures);
    free(g->materials);
    memset(g, 0, sizeof *g);
}

void scene_gpu_light(const scene_light *in, stin_light_desc *out)
{
    memset(out, 0, sizeof *out);
    out->type = in->type == SCENE_LIGHT_SPOT          ? STIN_LIGHT_SPOT
              : in->type == SCENE_LIGHT_DIRECTIONAL ? STIN_LIGHT_DIRECTIONAL
                                                    : STIN_LIGHT_POINT;
    memcpy(out->position, in->position, sizeof out->position);
    memcpy(out->direction, in->direction, sizeof out->direction);
    memcpy(out->color, in->color, sizeof out->color);
    out->intensity = in->intensity;
    memcpy(out->attenuation, in->attenuation, sizeof out->attenuation);
    out->spot_cutoff_deg = in->spot_cutoff_deg;
    out->spot_exponent = in->spot_exponent;
    out->shadow_offset[0] = in->shadow_offset[0];
    out->shadow_offset[1] = in->shadow_offset[1];
    out->shadow_offset_off = in->shadow_offset_off;
    out->pcf_kernel = (uint32_t)in->pcf_kernel;
    out->radius = in->radius;
    out->range = in->range;
}

stin_result scene_gpu_frame(const scene_gpu *g, stin_context *ctx, int width, int height,
                            stin_output output, uint32_t framebuffer)
{
    const scene *s = g->src;
    stin_frame_desc fd;
    stin_result r;
    int i;
    memset(&fd, 0, sizeof fd);
    scene_camera_matrices(&s->camera, width, height, fd.view, fd.projection);
    fd.viewport[2] = width;
    fd.viewport[3] = height;
    fd.framebuffer = framebuffer;
    memcpy(fd.clear_color, s->background, sizeof fd.clear_color);
    memcpy(fd.ambient, s->ambient, sizeof fd.ambient);
    fd.output = output;
    if (output != STIN_OUTPUT_BEAUTY)
        memset(fd.clear_color, 0, sizeof fd.clear_color);
    r = stin_begin_frame(ctx, &fd);
    if (r != STIN_OK)
        return r;
    for (i = 0; i < s->light_count; i++) {
        stin_light_desc l;
        scene_gpu_light(&s->lights[i], &l);
        stin_add_light(ctx, &l);
    }
    for (i = 0; i < s->object_count; i++) {
        const scene_object *o = &s->objects[i];
        stin_draw(ctx, g->meshes[o->mesh], o->transform, &g->materials[o->material]);
    }
    return stin_end_frame(ctx);
}
