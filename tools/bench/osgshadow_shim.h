/* SPDX-License-Identifier: MIT */
/* OpenSceneGraph 3.6's osgShadow for the peers section (osgshadow_shim.cpp,
 * built with g++ where libopenscenegraph-dev is installed:
 * STIN_BENCH_OSGSHADOW). Each peer is one osgViewer embedded in the
 * bench's current GL context (a compatibility profile: OSG draws with the
 * fixed-function state), drawing the scene handed to it with one shadow
 * technique. */
#ifndef STIN_BENCH_OSGSHADOW_SHIM_H
#define STIN_BENCH_OSGSHADOW_SHIM_H

#include <stddef.h>
#include <stdint.h>

/* The techniques, in the table's order. */
enum {
    OSGS_SHADOW_MAP,
    OSGS_SOFT_SHADOW_MAP,
    OSGS_STANDARD_SHADOW_MAP,
    OSGS_LISPSM,
    OSGS_PSSM,
    OSGS_VDSM,
    OSGS_NONE, /* the ShadowedScene without a technique: OSG's unshadowed frame */
    OSGS_TECHNIQUES
};

/* What a frame draws: the technique with every caster (SHADOWED), with
 * the eclipse (below) moved by eclipse_away to where it shadows nothing
 * visible as the only caster (UNSHADOWED: the technique's own lighting,
 * nothing in its maps), and with every caster plus an eclipse, a two-sided quad between the light
 * and the scene seen only by the shadow cameras (FULL: everything the
 * technique can shadow is in its shadow). */
enum { OSGS_SHADOWED, OSGS_UNSHADOWED, OSGS_FULL };

typedef struct osgs_mesh {
    const float *positions, *normals; /* 3 per vertex */
    const uint32_t *indices;          /* 3 per triangle */
    uint32_t vertex_count, index_count;
} osgs_mesh;

typedef struct osgs_object {
    int mesh;
    float transform[16];              /* column-major object -> world */
    float color[4], specular[3], shininess;
} osgs_object;

typedef struct osgs_light {
    int type;                         /* 0 point, 1 spot, 2 directional */
    float position[3], direction[3];  /* direction: the way light travels */
    float color[3];                   /* colour times intensity */
    float attenuation[3], spot_cutoff_deg, spot_exponent;
} osgs_light;

typedef struct osgs_scene {
    const osgs_mesh *meshes;
    int mesh_count;
    const osgs_object *objects;
    int object_count;
    osgs_light light;
    float ambient[3], background[4];
    float view[16], projection[16];   /* column-major, GL conventions */
    int width, height;
    unsigned framebuffer;             /* where the frames go */
    float eclipse_center[3], eclipse_normal[3], eclipse_half; /* the FULL frame's quad */
    float eclipse_away[3];            /* its offset in the UNSHADOWED frame */
} osgs_scene;

typedef struct osgs_peer osgs_peer;

/* The technique's name as osgShadow spells it. */
const char *osgs_name(int technique);
/* A peer drawing s (its arrays are copied) with `technique` and maps of
 * map_size texels a side; NULL with the reason in err. */
osgs_peer *osgs_create(const osgs_scene *s, int technique, int map_size, char *err,
                       size_t err_size);
/* One frame into s->framebuffer (no glFinish). 0 where OSG reported an
 * error (a shader that does not compile, a GL error): the reason in err. */
int osgs_frame(osgs_peer *p, int mode, char *err, size_t err_size);
void osgs_destroy(osgs_peer *p);

#endif
