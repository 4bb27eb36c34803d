/* SPDX-License-Identifier: MIT */
/*
 * Scene files for stin's tools and tests (JSON, docs/scene-format.md).
 *
 * A scene is everything the render tool, the bench and the Embree reference
 * need: meshes as indexed triangles with per-vertex normals and uvs (already
 * tessellated primitives or files loaded with assimp), textures as RGBA8,
 * materials, object instances (mesh + material + object->world matrix),
 * lights and a camera. Memory comes from the heap (this is tool code, not
 * libstin) and is released by scene_free().
 */
#ifndef STIN_TOOLS_SCENE_H
#define STIN_TOOLS_SCENE_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define SCENE_NAME_MAX 64

typedef struct scene_mesh {
    char name[SCENE_NAME_MAX];
    uint32_t vertex_count, triangle_count;
    float *positions;   /* 3 per vertex, object space */
    float *normals;     /* 3 per vertex, unit length */
    float *uvs;         /* 2 per vertex */
    uint32_t *indices;  /* 3 per triangle, counter-clockwise front faces */
} scene_mesh;

typedef enum scene_texture_kind {
    SCENE_TEXTURE_ALBEDO = 0,
    SCENE_TEXTURE_NORMAL,
    SCENE_TEXTURE_HEIGHT
} scene_texture_kind;

typedef struct scene_texture {
    char name[SCENE_NAME_MAX];
    scene_texture_kind kind;   /* from how a material uses it */
    int width, height;
    uint8_t *rgba;             /* 4 bytes per pixel, rows bottom to top (GL order) */
} scene_texture;

typedef struct scene_material {
    char name[SCENE_NAME_MAX];
    float color[4];            /* linear albedo + opacity; default (0.8,0.8,0.8,1) */
    float specular[3];         /* default (0,0,0) */
    float shininess;           /* default 32 */
    int albedo, normal, height; /* texture index or -1 */
    float height_scale;        /* default 0.04 */
    char surface[16];          /* requested surface technique, "" = auto */
    int self_shadow;           /* pom self-shadowing: 0 off (default), 1 hard, 2 soft */
    int two_sided;             /* both sides of a closed mesh may be seen (stin_material) */
    int displace;              /* "displace": move the mesh by the height map (stin_material) */
    float height_bias;         /* "height_bias": d = h scale - bias; default scale / 2 */
    int has_height_bias;       /* given in the file; else the default follows height_scale */
} scene_material;

typedef struct scene_object {
    int mesh;                  /* index into meshes */
    int material;              /* index into materials */
    float transform[16];       /* column-major object -> world */
} scene_object;

typedef enum scene_light_type {
    SCENE_LIGHT_POINT = 0,
    SCENE_LIGHT_SPOT,
    SCENE_LIGHT_DIRECTIONAL
} scene_light_type;

typedef struct scene_light {
    scene_light_type type;
    float position[3];
    float direction[3];        /* normalised, the way light travels */
    float color[3];            /* default (1,1,1) */
    float intensity;           /* default 1 */
    float attenuation[3];      /* default (1,0,0) */
    float spot_cutoff_deg;     /* default 45 */
    float spot_exponent;       /* default 0 */
    float radius;              /* area light radius, default 0 */
    float range;               /* point/spot: distance past which the light is negligible
                                  (stin scissors its passes to it); 0 = unbounded, default 0.
                                  Not part of the shading: the test reference ignores it */
    float shadow_offset[2];    /* spot/directional "shadow_offset": shadow-map polygon offset
                                  (factor, units); (0, 0) = stin's default (1.1, 4) */
    int shadow_offset_off;     /* not in files: tests turn the offset off with it */
    int pcf_kernel;            /* "pcf_kernel": 1, 3 or 5 taps a side (map-pcf); 0 = 3 */
} scene_light;

typedef struct scene_camera {
    float eye[3], target[3], up[3];
    float fovy_deg;            /* vertical field of view, default 45 */
    float near_plane, far_plane; /* defaults 0.1 and 100 */
} scene_camera;

/* One entry of the file's csg list: a op b. An operand is a scene object
 * (>= 0) or an earlier entry's result (-1 - its index). */
typedef enum scene_csg_op { SCENE_CSG_UNION = 0, SCENE_CSG_INTERSECT, SCENE_CSG_SUBTRACT } scene_csg_op;
typedef struct scene_csg {
    scene_csg_op op;
    int a, b;
    int used;                  /* an operand of a later entry (else a product of its own) */
} scene_csg;

typedef struct scene {
    char path[512];
    scene_mesh *meshes; int mesh_count;
    scene_texture *textures; int texture_count;
    scene_material *materials; int material_count;
    scene_object *objects; int object_count;
    scene_light *lights; int light_count;
    scene_csg *csg; int csg_count; /* the csg list, in file order */
    scene_camera camera;       /* the file's, or one framing everything (scene_camera_frame) */
    int has_camera;            /* 0: the file has no camera */
    char *warnings;            /* NULL or lines "FILE: where: text\n": what a model file lost
                                  (a texture that cannot be read, an alpha mode stin lacks) */
    float ambient[3];          /* default (0.1,0.1,0.1) */
    float background[4];       /* default (0,0,0,0) */
    int width, height;         /* suggested image size, default 512 x 512 */
    int shadow_map_size;       /* texels a side of each shadow map (a power of two,
                                  16..8192); 0 = stin's default */
} scene;

/* Loads a scene file. On error returns 0, writes "FILE: problem" into err and
 * leaves *out empty (nothing to free). */
int scene_load(const char *path, scene *out, char *err, size_t err_size);
/* 1: model and image files are decoded once per process and their bytes
 * kept (scene_import_memo.c): a process that loads the same scenes many
 * times (stin-imagetest) forks a decoder once per file instead of once per
 * load. Off (0) by default. */
extern int scene_import_memo;
void scene_free(scene *s);

/* View and projection (column-major, GL conventions: right-handed eye space
 * looking down -z, clip z in [-w, w]) for an image of width x height. */
void scene_camera_matrices(const scene_camera *cam, int width, int height,
                           float view[16], float projection[16]);

/* Points cam at every object whole: at the centre of the objects' world
 * bounding box, from cam's direction (eye -> target, up and fovy kept) when
 * s->has_camera, else from +z and above (direction (0, 1, 2), y up, fovy
 * 45), at the distance where the box's bounding sphere fits the vertical and
 * horizontal field of view of a width x height image with a 5% margin; near
 * and far enclose the sphere. */
void scene_camera_frame(const scene *s, int width, int height, scene_camera *cam);

/* Total triangles over all objects (instances counted each time). */
uint64_t scene_triangle_count(const scene *s);

#ifdef __cplusplus
}
#endif
#endif
