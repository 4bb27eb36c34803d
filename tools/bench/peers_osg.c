/* SPDX-License-Identifier: MIT */
/* A scene handed to osgShadow (osgshadow_shim.h): the same meshes, object
 * transforms, materials, light 0, camera and size as stin's frame, and the
 * eclipse of the full-shadow frame: a quad across everything light 0 can
 * reach, between the light and the nearest vertex (directional: beyond the
 * scene's bounds toward the light). */
#include "peers_osg.h"
#ifdef STIN_BENCH_OSGSHADOW
#include "osgshadow_shim.h"
#include "stin_platform.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define ECLIPSE_AT 0.9f

static void world(const float m[16], const float *p, float out[3])
{
    int k;
    for (k = 0; k < 3; k++)
        out[k] = m[k] * p[0] + m[4 + k] * p[1] + m[8 + k] * p[2] + m[12 + k];
}

static float dot3(const float a[3], const float b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* The objects' world box: its centre and half diagonal. */
static void bounds(const scene *s, float centre[3], float *radius)
{
    float lo[3] = {1e30f, 1e30f, 1e30f}, hi[3] = {-1e30f, -1e30f, -1e30f}, p[3];
    int i, k;
    uint32_t v;
    for (i = 0; i < s->object_count; i++) {
        const scene_mesh *m = &s->meshes[s->objects[i].mesh];
        for (v = 0; v < m->vertex_count; v++) {
            world(s->objects[i].transform, m->positions + 3u * v, p);
            for (k = 0; k < 3; k++) {
                lo[k] = p[k] < lo[k] ? p[k] : lo[k];
                hi[k] = p[k] > hi[k] ? p[k] : hi[k];
            }
        }
    }
    *radius = 0.0f;
    for (k = 0; k < 3; k++) {
        centre[k] = 0.5f * (lo[k] + hi[k]);
        *radius += 0.25f * (hi[k] - lo[k]) * (hi[k] - lo[k]);
    }
    *radius = sqrtf(*radius);
}

static void eclipse(const scene *s, osgs_scene *o)
{
    const scene_light *l = &s->lights[0];
    float c[3], r, n[3], len, nearest = 1e30f, farthest = 0.0f, spread = 0.0f, p[3], d[3];
    int i, k;
    uint32_t v;
    bounds(s, c, &r);
    if (l->type == SCENE_LIGHT_DIRECTIONAL) {
        for (k = 0; k < 3; k++) {
            o->eclipse_normal[k] = l->direction[k];
            o->eclipse_center[k] = c[k] - l->direction[k] * 1.05f * r;
            o->eclipse_away[k] = l->direction[k] * 2.1f * r; /* past the scene */
        }
        o->eclipse_half = 1.5f * r;
        return;
    }
    for (k = 0; k < 3; k++)
        n[k] = l->type == SCENE_LIGHT_SPOT ? l->direction[k] : c[k] - l->position[k];
    len = sqrtf(dot3(n, n));
    for (k = 0; k < 3; k++)
        n[k] = len > 1e-6f ? n[k] / len : (k == 1 ? -1.0f : 0.0f);
    for (i = 0; i < s->object_count; i++) {
        const scene_mesh *m = &s->meshes[s->objects[i].mesh];
        for (v = 0; v < m->vertex_count; v++) {
            float along, across;
            world(s->objects[i].transform, m->positions + 3u * v, p);
            for (k = 0; k < 3; k++)
                d[k] = p[k] - l->position[k];
            along = dot3(d, n);
            across = sqrtf(fmaxf(dot3(d, d) - along * along, 0.0f));
            if (along > 0.01f * r && along < nearest)
                nearest = along;
            farthest = along > farthest ? along : farthest;
            if (along > 0.01f * r && across / along > spread)
                spread = across / along;
        }
    }
    if (nearest > 1e29f)
        nearest = r;
    spread = spread < 6.0f ? spread : 6.0f; /* 80 degrees off the axis at most */
    for (k = 0; k < 3; k++) {
        o->eclipse_normal[k] = n[k];
        o->eclipse_center[k] = l->position[k] + n[k] * ECLIPSE_AT * nearest;
        o->eclipse_away[k] = n[k] * (1.1f * farthest - ECLIPSE_AT * nearest); /* past it all */
    }
    o->eclipse_half = 1.1f * spread * ECLIPSE_AT * nearest;
}

struct osgs_peer *peers_osg_peer(const bench_env *env, const scene *s, int technique,
                                 int map_size, char *why, size_t why_size)
{
    const scene_light *l = &s->lights[0];
    osgs_mesh *meshes = calloc((size_t)s->mesh_count + 1, sizeof *meshes);
    osgs_object *objects = calloc((size_t)s->object_count + 1, sizeof *objects);
    osgs_scene o;
    struct osgs_peer *p = NULL;
    int i, k;
    if (!meshes || !objects) {
        snprintf(why, why_size, "out of memory");
        goto done;
    }
    for (i = 0; i < s->mesh_count; i++) {
        meshes[i].positions = s->meshes[i].positions;
        meshes[i].normals = s->meshes[i].normals;
        meshes[i].indices = s->meshes[i].indices;
        meshes[i].vertex_count = s->meshes[i].vertex_count;
        meshes[i].index_count = 3u * s->meshes[i].triangle_count;
    }
    for (i = 0; i < s->object_count; i++) {
        const scene_material *m = &s->materials[s->objects[i].material];
        objects[i].mesh = s->objects[i].mesh;
        memcpy(objects[i].transform, s->objects[i].transform, sizeof objects[i].transform);
        memcpy(objects[i].color, m->color, sizeof objects[i].color);
        memcpy(objects[i].specular, m->specular, sizeof objects[i].specular);
        objects[i].shininess = m->shininess;
    }
    memset(&o, 0, sizeof o);
    o.meshes = meshes;
    o.mesh_count = s->mesh_count;
    o.objects = objects;
    o.object_count = s->object_count;
    o.light.type = l->type == SCENE_LIGHT_SPOT ? 1 : l->type == SCENE_LIGHT_DIRECTIONAL ? 2 : 0;
    memcpy(o.light.position, l->position, sizeof o.light.position);
    memcpy(o.light.direction, l->direction, sizeof o.light.direction);
    for (k = 0; k < 3; k++)
        o.light.color[k] = l->color[k] * l->intensity;
    memcpy(o.light.attenuation, l->attenuation, sizeof o.light.attenuation);
    o.light.spot_cutoff_deg = l->spot_cutoff_deg;
    o.light.spot_exponent = l->spot_exponent;
    memcpy(o.ambient, s->ambient, sizeof o.ambient);
    memcpy(o.background, s->background, sizeof o.background);
    o.width = env->b.width;
    o.height = env->b.height;
    scene_camera_matrices(&s->camera, o.width, o.height, o.view, o.projection);
    o.framebuffer = stin_platform_framebuffer(env->b.plat);
    eclipse(s, &o);
    p = osgs_create(&o, technique, map_size, why, why_size);
done:
    free(meshes);
    free(objects);
    return p;
}
#else
typedef int peers_osg_not_built; /* ISO C wants a declaration */
#endif
