/* SPDX-License-Identifier: MIT */
/* Scene -> libstin: meshes, textures, materials and one frame. */
#include "scene_gpu.h"

#include <stdlib.h>
#include <stdio.h>
#include <string.h>

static stin_texture_kind texture_kind(scene_texture_kind k);

/* What stin_desc_fit could not raise, as the tool's message. */
static const char *capacity_message(const char *field)
{
    static const char *const names[][2] = {
        {"max_meshes", "meshes: more than 65535"},
        {"max_textures", "textures: more than 65535"},
        {"max_draws", "objects: more instances than stin draws in a frame"},
        {"max_lights", "lights: at most 32"},
        {"max_vertices", "meshes: more vertices than stin holds"},
        {"max_triangles", "meshes: more triangles than stin holds"},
        {"max_mesh_triangles", "meshes: a mesh has more triangles than stin holds"},
        {"max_texture_bytes", "textures: a texture is too large to stage"}};
    size_t i;
    for (i = 0; field && i < sizeof names / sizeof names[0]; i++)
        if (!strcmp(field, names[i][0]))
            return names[i][1];
    return "more than stin holds";
}

int scene_gpu_size_desc_checked(const scene *s, stin_desc *desc, char *err, size_t err_size)
{
    stin_asset_summary a;
    const char *field = NULL;
    int i;
    memset(&a, 0, sizeof a);
    a.meshes = (uint32_t)s->mesh_count;
    a.textures = (uint32_t)s->texture_count;
    a.draws = (uint32_t)s->object_count;
    a.lights = (uint32_t)s->light_count;
    for (i = 0; i < s->mesh_count; i++) {
        a.vertices += s->meshes[i].vertex_count;
        a.triangles += s->meshes[i].triangle_count;
        if (s->meshes[i].triangle_count > a.largest_mesh_triangles)
            a.largest_mesh_triangles = s->meshes[i].triangle_count;
    }
    for (i = 0; i < s->texture_count; i++) {
        stin_texture_desc td;
        uint64_t bytes;
        memset(&td, 0, sizeof td);
        td.kind = texture_kind(s->textures[i].kind);
        td.width = (uint32_t)s->textures[i].width;
        td.height = (uint32_t)s->textures[i].height;
        bytes = stin_texture_staging_bytes(&td);
        if (bytes > a.largest_texture_staging)
            a.largest_texture_staging = bytes;
    }
    if (stin_desc_fit(desc, &a, &field) == STIN_OK)
        return 1;
    if (err && err_size)
        snprintf(err, err_size, "%s: %s", s->path, capacity_message(field));
    return 0;
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

stin_mesh_desc scene_gpu_mesh_desc(const scene_mesh *m)
{
    stin_mesh_desc md;
    memset(&md, 0, sizeof md);
    md.positions = m->positions;
    md.normals = m->normals;
    md.uvs = m->uvs;
    md.vertex_count = m->vertex_count;
    md.indices = m->indices;
    md.index_count = 3u * m->triangle_count;
    return md;
}

stin_mesh_update_desc scene_gpu_mesh_update_desc(const scene_mesh *m)
{
    stin_mesh_update_desc ud;
    memset(&ud, 0, sizeof ud);
    ud.positions = m->positions;
    ud.normals = m->normals;
    ud.vertex_count = m->vertex_count;
    return ud;
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
        stin_mesh_desc md = scene_gpu_mesh_desc(m);
        stin_result r = stin_create_mesh(ctx, &md, &g->meshes[i]);
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
        m->displace = sm->displace;
        /* stin's 0 is its default (scale / 2): an explicit 0 is the tiniest bias */
        if (sm->has_height_bias)
            m->height_bias = sm->height_bias != 0.0f ? sm->height_bias : -1e-30f;
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
    out->shadow_offset_exact = in->shadow_offset_off;
    out->pcf_kernel = (uint32_t)in->pcf_kernel;
    out->radius = in->radius;
    out->range = in->range;
}

stin_result scene_gpu_frame(const scene_gpu *g, stin_context *ctx, int width, int height,
                            stin_output output, uint32_t framebuffer)
{
    return scene_gpu_frame_export(g, ctx, width, height, output, STIN_EXPORT_NONE, framebuffer);
}

static int csg_primitive(const scene_gpu *g, int object)
{
    int p, i;
    for (p = 0; p < g->csg_count; p++)
        for (i = 0; i < g->csg[p].primitive_count; i++)
            if (g->csg[p].objects[i] == object)
                return 1;
    return 0;
}

/* One product: its objects as primitives (a failure is stin's logged error). */
static void draw_csg(const scene_gpu *g, stin_context *ctx, const scene_gpu_csg *c)
{
    stin_csg_primitive *prims = calloc((size_t)c->primitive_count + 1, sizeof *prims);
    stin_csg_desc d;
    int i;
    if (!prims)
        return;
    for (i = 0; i < c->primitive_count; i++) {
        const scene_object *o = &g->src->objects[c->objects[i]];
        prims[i].mesh = g->meshes[o->mesh];
        memcpy(prims[i].transform, o->transform, sizeof prims[i].transform);
        prims[i].material = g->materials[o->material];
    }
    memset(&d, 0, sizeof d);
    d.primitives = prims;
    d.primitive_count = (uint32_t)c->primitive_count;
    d.nodes = c->nodes;
    d.node_count = (uint32_t)c->node_count;
    stin_draw_csg(ctx, &d);
    free(prims);
}

stin_result scene_gpu_frame_export(const scene_gpu *g, stin_context *ctx, int width, int height,
                                   stin_output output, stin_export ex, uint32_t framebuffer)
{
    const int viewport[4] = {0, 0, width, height};
    return scene_gpu_frame_viewport(g, ctx, viewport, output, ex, framebuffer);
}

stin_result scene_gpu_frame_viewport(const scene_gpu *g, stin_context *ctx,
                                     const int viewport[4], stin_output output, stin_export ex,
                                     uint32_t framebuffer)
{
    const scene *s = g->src;
    stin_frame_desc fd;
    stin_result r;
    int i;
    memset(&fd, 0, sizeof fd);
    scene_camera_matrices(&s->camera, viewport[2], viewport[3], fd.view, fd.projection);
    memcpy(fd.viewport, viewport, sizeof fd.viewport);
    fd.framebuffer = framebuffer;
    memcpy(fd.clear_color, s->background, sizeof fd.clear_color);
    memcpy(fd.ambient, s->ambient, sizeof fd.ambient);
    fd.output = output;
    fd.outline_step = g->outline_step;
    memcpy(fd.outline_color, g->outline_color, sizeof fd.outline_color);
    fd.export_visibility = ex;
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
        if (!csg_primitive(g, i))
            stin_draw(ctx, g->meshes[o->mesh], o->transform, &g->materials[o->material]);
    }
    for (i = 0; i < g->csg_count; i++)
        draw_csg(g, ctx, &g->csg[i]);
    return stin_end_frame(ctx);
}
