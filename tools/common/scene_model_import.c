/* SPDX-License-Identifier: MIT */
/* Child side of a model import: assimp's node tree -> one part per (node,
 * mesh) pair with the node's accumulated transform, the meshes the parts
 * use, their materials (scene_model_materials.c). Runs in the isolated
 * child: a hostile file may crash it, but every count and index is still
 * checked so that a valid-looking one cannot make it read out of bounds. */
#include "scene_internal.h"
#include "scene_model.h"
#include "scene_primitives.h"

#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct importer {
    const struct aiScene *sc;
    const char *path;
    scene_model *m;
    int32_t *mesh_out;     /* per assimp mesh: model mesh, -1 not yet; [n..2n) mirrored */
    int32_t *material_out; /* per assimp material: model material, -3 not yet */
    uint64_t vertices, triangles;
    char *why;
    size_t why_size;
} importer;

static int fail(importer *im, const char *msg)
{
    snprintf(im->why, im->why_size, "%s", msg);
    return 0;
}

/* aiMatrix4x4 is row-major (a1..a4 the first row). */
static void to_column_major(const struct aiMatrix4x4 *a, float out[16])
{
    const float r[16] = { a->a1, a->b1, a->c1, a->d1, a->a2, a->b2, a->c2, a->d2,
                          a->a3, a->b3, a->c3, a->d3, a->a4, a->b4, a->c4, a->d4 };
    memcpy(out, r, sizeof r);
}

static double det3(const float m[16])
{
    return (double)m[0] * ((double)m[5] * m[10] - (double)m[9] * m[6]) -
           (double)m[4] * ((double)m[1] * m[10] - (double)m[9] * m[2]) +
           (double)m[8] * ((double)m[1] * m[6] - (double)m[5] * m[2]);
}

static int triangle_count(const struct aiMesh *src)
{
    unsigned f, n = 0;
    for (f = 0; f < src->mNumFaces; f++)
        n += src->mFaces[f].mNumIndices == 3; /* points and lines are skipped */
    return (int)n;
}

/* Copies an assimp mesh; `mirrored` reverses the winding, for a node whose
 * transform mirrors (stin culls by winding in world space). */
static int copy_mesh(const struct aiMesh *src, scene_mesh *dst, int mirrored)
{
    unsigned v, f, t = 0;
    if (!scene_mesh_alloc(dst, src->mNumVertices, (uint32_t)triangle_count(src)))
        return 0;
    for (v = 0; v < src->mNumVertices; v++) {
        float *p = dst->positions + 3 * (size_t)v, *n = dst->normals + 3 * (size_t)v;
        float *uv = dst->uvs + 2 * (size_t)v, len = 0;
        p[0] = src->mVertices[v].x;
        p[1] = src->mVertices[v].y;
        p[2] = src->mVertices[v].z;
        if (src->mNormals) {
            n[0] = src->mNormals[v].x;
            n[1] = src->mNormals[v].y;
            n[2] = src->mNormals[v].z;
            len = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        }
        /* Normals of degenerate or unused vertices can be zero or NaN; the
         * mesh contract promises unit length, so substitute +y. */
        if (len > 1e-12f && isfinite(len)) {
            n[0] /= len;
            n[1] /= len;
            n[2] /= len;
        } else {
            n[0] = 0;
            n[1] = 1;
            n[2] = 0;
        }
        uv[0] = src->mTextureCoords[0] ? src->mTextureCoords[0][v].x : 0.0f;
        uv[1] = src->mTextureCoords[0] ? src->mTextureCoords[0][v].y : 0.0f;
    }
    for (f = 0; f < src->mNumFaces; f++) {
        const struct aiFace *face = &src->mFaces[f];
        if (face->mNumIndices != 3)
            continue;
        dst->indices[3 * (size_t)t + 0] = face->mIndices[0];
        dst->indices[3 * (size_t)t + 1] = face->mIndices[mirrored ? 2 : 1];
        dst->indices[3 * (size_t)t + 2] = face->mIndices[mirrored ? 1 : 2];
        t++;
    }
    return 1;
}

/* The model mesh for assimp mesh i (copied on first use), -1 on error. */
static int32_t use_mesh(importer *im, unsigned i, int mirrored)
{
    const struct aiMesh *src = im->sc->mMeshes[i];
    int32_t *slot = &im->mesh_out[i + (mirrored ? im->sc->mNumMeshes : 0)];
    scene_mesh *grown;
    if (*slot >= 0)
        return *slot;
    im->vertices += src->mNumVertices;
    im->triangles += (uint64_t)triangle_count(src);
    if (im->vertices > UINT32_MAX || im->triangles > UINT32_MAX / 3)
        return fail(im, "too many vertices"), -1;
    grown = realloc(im->m->meshes, (im->m->mesh_count + 1) * sizeof *grown);
    if (!grown)
        return fail(im, "out of memory"), -1;
    im->m->meshes = grown;
    memset(&grown[im->m->mesh_count], 0, sizeof *grown);
    snprintf(grown[im->m->mesh_count].name, SCENE_NAME_MAX, "%.40s%s", src->mName.data,
             mirrored ? " (mirrored)" : "");
    if (!copy_mesh(src, &grown[im->m->mesh_count], mirrored))
        return fail(im, "out of memory"), -1;
    *slot = (int32_t)im->m->mesh_count++;
    return *slot;
}

static int32_t use_material(importer *im, unsigned i)
{
    if (i >= im->sc->mNumMaterials || !im->sc->mMaterials)
        return -1; /* validated by assimp; no material is not an error */
    if (im->material_out[i] == -3)
        im->material_out[i] = scene_model_add_material(im->m, im->sc, i, im->path);
    if (im->material_out[i] == -2)
        return fail(im, "out of memory"), -2;
    return im->material_out[i];
}

static int add_part(importer *im, unsigned ai_mesh, const float world[16])
{
    const struct aiMesh *src;
    scene_model_part *part;
    double det = det3(world);
    int32_t mesh, material;
    int k;
    if (ai_mesh >= im->sc->mNumMeshes || !(src = im->sc->mMeshes[ai_mesh]))
        return fail(im, "a node names a mesh the file does not have");
    if (triangle_count(src) == 0)
        return 1;
    for (k = 0; k < 16; k++)
        if (!isfinite(world[k]))
            return scene_model_warn(im->m, "node mesh '%s': transform not finite, left out",
                                    src->mName.data) || fail(im, "out of memory");
    if (world[3] != 0 || world[7] != 0 || world[11] != 0 || world[15] != 1 || fabs(det) < 1e-30)
        return scene_model_warn(im->m, "node mesh '%s': transform not affine or singular, left out",
                                src->mName.data) || fail(im, "out of memory");
    if (im->m->part_count >= SCENE_MODEL_PARTS_MAX)
        return fail(im, "more than 1000000 node meshes");
    mesh = use_mesh(im, ai_mesh, det < 0);
    if (mesh < 0 || (material = use_material(im, src->mMaterialIndex)) < -1)
        return 0;
    part = realloc(im->m->parts, (im->m->part_count + 1) * sizeof *part);
    if (!part)
        return fail(im, "out of memory");
    im->m->parts = part;
    part += im->m->part_count++;
    part->mesh = (uint32_t)mesh;
    part->material = material;
    memcpy(part->transform, world, sizeof part->transform);
    return 1;
}

/* Depth-first, parent transform first: world = parent * local. */
static int walk(importer *im, const struct aiNode *node, const float parent[16], int depth)
{
    float local[16], world[16];
    unsigned i;
    if (depth > SCENE_MODEL_DEPTH_MAX)
        return fail(im, "node tree deeper than 256 levels");
    to_column_major(&node->mTransformation, local);
    scene_mat4_mul(parent, local, world);
    for (i = 0; i < node->mNumMeshes; i++)
        if (!add_part(im, node->mMeshes[i], world))
            return 0;
    for (i = 0; i < node->mNumChildren; i++)
        if (!node->mChildren || !node->mChildren[i] || !walk(im, node->mChildren[i], world, depth + 1))
            return node->mChildren && node->mChildren[i] ? 0 : fail(im, "a node has a missing child");
    return 1;
}

int scene_model_import_work(void *arg, int fd, char *why, size_t why_size)
{
    static const float identity[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
    /* No PreTransformVertices: nodes stay parts with their transforms. */
    const unsigned flags = aiProcess_ValidateDataStructure | aiProcess_Triangulate |
                           aiProcess_JoinIdenticalVertices | aiProcess_GenSmoothNormals;
    importer im;
    scene_model m;
    unsigned i;
    int ok;
    memset(&im, 0, sizeof im);
    memset(&m, 0, sizeof m);
    im.path = (const char *)arg;
    im.m = &m;
    im.why = why;
    im.why_size = why_size;
    im.sc = aiImportFile(im.path, flags);
    if (!im.sc) {
        snprintf(why, why_size, "%s", aiGetErrorString());
        return 0;
    }
    if (!im.sc->mRootNode || (im.sc->mNumMeshes && !im.sc->mMeshes))
        return fail(&im, "no node tree in the file");
    im.mesh_out = malloc((2 * (size_t)im.sc->mNumMeshes + 1) * sizeof *im.mesh_out);
    im.material_out = malloc(((size_t)im.sc->mNumMaterials + 1) * sizeof *im.material_out);
    if (!im.mesh_out || !im.material_out)
        return fail(&im, "out of memory");
    for (i = 0; i < 2 * im.sc->mNumMeshes; i++)
        im.mesh_out[i] = -1;
    for (i = 0; i < im.sc->mNumMaterials; i++)
        im.material_out[i] = -3;
    if (!walk(&im, im.sc->mRootNode, identity, 0))
        return 0; /* the child exits: no need to free */
    if (m.part_count == 0)
        return fail(&im, "no triangles in the file");
    ok = scene_model_write(fd, &m);
    if (!ok)
        fail(&im, "cannot hand the model over");
    return ok;
}
