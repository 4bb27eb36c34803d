/* SPDX-License-Identifier: MIT */
/* Model files (OBJ, PLY, STL, glTF/glb, anything assimp reads) merged into
 * one indexed triangle mesh in the file's own coordinates. */
#include "scene_internal.h"
#include "scene_primitives.h"
#include "isolate.h"

#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

unsigned scene_import_seconds = SCENE_IMPORT_SECONDS;

static int count_geometry(const struct aiScene *sc, uint64_t *verts, uint64_t *tris)
{
    unsigned i, f;
    *verts = *tris = 0;
    for (i = 0; i < sc->mNumMeshes; i++) {
        const struct aiMesh *m = sc->mMeshes[i];
        *verts += m->mNumVertices;
        for (f = 0; f < m->mNumFaces; f++)
            *tris += m->mFaces[f].mNumIndices == 3; /* points and lines are skipped */
    }
    return *verts <= UINT32_MAX && *tris <= UINT32_MAX / 3;
}

static void copy_mesh(const struct aiMesh *src, scene_mesh *dst, uint32_t base, uint32_t *tri)
{
    unsigned v, f;
    for (v = 0; v < src->mNumVertices; v++) {
        float *p = dst->positions + 3 * (size_t)(base + v);
        float *n = dst->normals + 3 * (size_t)(base + v);
        float *t = dst->uvs + 2 * (size_t)(base + v);
        float len = 0;
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
        t[0] = src->mTextureCoords[0] ? src->mTextureCoords[0][v].x : 0.0f;
        t[1] = src->mTextureCoords[0] ? src->mTextureCoords[0][v].y : 0.0f;
    }
    for (f = 0; f < src->mNumFaces; f++) {
        const struct aiFace *face = &src->mFaces[f];
        if (face->mNumIndices != 3)
            continue;
        dst->indices[3 * (size_t)*tri + 0] = base + face->mIndices[0];
        dst->indices[3 * (size_t)*tri + 1] = base + face->mIndices[1];
        dst->indices[3 * (size_t)*tri + 2] = base + face->mIndices[2];
        (*tri)++;
    }
}

/* Child side: import, merge, then stream counts and arrays to the parent. */
static int import_work(void *arg, int fd, char *why, size_t why_size)
{
    const unsigned flags = aiProcess_ValidateDataStructure | aiProcess_Triangulate |
                           aiProcess_JoinIdenticalVertices | aiProcess_GenSmoothNormals |
                           aiProcess_PreTransformVertices;
    const struct aiScene *sc = aiImportFile((const char *)arg, flags);
    scene_mesh m;
    uint64_t verts, tris;
    uint32_t base = 0, tri = 0, counts[2];
    unsigned i;
    int ok;
    if (!sc) {
        snprintf(why, why_size, "%s", aiGetErrorString());
        return 0;
    }
    memset(&m, 0, sizeof m);
    if (!count_geometry(sc, &verts, &tris) || tris == 0) {
        snprintf(why, why_size, tris ? "too many vertices" : "no triangles in the file");
        return 0;
    }
    if (!scene_mesh_alloc(&m, (uint32_t)verts, (uint32_t)tris)) {
        snprintf(why, why_size, "out of memory");
        return 0;
    }
    for (i = 0; i < sc->mNumMeshes; i++) {
        copy_mesh(sc->mMeshes[i], &m, base, &tri);
        base += sc->mMeshes[i]->mNumVertices;
    }
    counts[0] = m.vertex_count;
    counts[1] = m.triangle_count;
    ok = isolate_write(fd, counts, sizeof counts) &&
         isolate_write(fd, m.positions, (size_t)verts * 3 * sizeof(float)) &&
         isolate_write(fd, m.normals, (size_t)verts * 3 * sizeof(float)) &&
         isolate_write(fd, m.uvs, (size_t)verts * 2 * sizeof(float)) &&
         isolate_write(fd, m.indices, (size_t)tris * 3 * sizeof(uint32_t));
    if (!ok)
        snprintf(why, why_size, "cannot hand the mesh over");
    return ok;
}

/* Parent side: the bytes must be exactly counts + arrays, every index in range. */
static int unpack_mesh(const unsigned char *b, size_t size, scene_mesh *out, char *why,
                       size_t why_size)
{
    uint32_t counts[2], t;
    size_t need;
    if (size < sizeof counts)
        return snprintf(why, why_size, "the importer returned no mesh"), 0;
    memcpy(counts, b, sizeof counts);
    need = sizeof counts + (size_t)counts[0] * 8 * sizeof(float) + (size_t)counts[1] * 3 * sizeof(uint32_t);
    if (size != need || !counts[0] || !counts[1])
        return snprintf(why, why_size, "the importer returned a malformed mesh"), 0;
    if (!scene_mesh_alloc(out, counts[0], counts[1]))
        return snprintf(why, why_size, "out of memory"), 0;
    b += sizeof counts;
    memcpy(out->positions, b, (size_t)counts[0] * 3 * sizeof(float));
    b += (size_t)counts[0] * 3 * sizeof(float);
    memcpy(out->normals, b, (size_t)counts[0] * 3 * sizeof(float));
    b += (size_t)counts[0] * 3 * sizeof(float);
    memcpy(out->uvs, b, (size_t)counts[0] * 2 * sizeof(float));
    b += (size_t)counts[0] * 2 * sizeof(float);
    memcpy(out->indices, b, (size_t)counts[1] * 3 * sizeof(uint32_t));
    for (t = 0; t < 3 * counts[1]; t++)
        if (out->indices[t] >= counts[0]) {
            snprintf(why, why_size, "face index %u out of range (%u vertices)", out->indices[t],
                     counts[0]);
            scene_mesh_release(out);
            return 0;
        }
    return 1;
}

int scene_mesh_load_file(const char *path, scene_mesh *out, char *why, size_t why_size)
{
    unsigned char *bytes;
    size_t size;
    int ok;
    if (!scene_check_regular_file(path, why, why_size) || !scene_model_precheck(path, why, why_size))
        return 0;
    /* assimp can crash or loop on hostile files; the child takes the hit. */
    if (!isolate_run(import_work, (void *)path, scene_import_seconds, SCENE_IMPORT_BYTES_MAX,
                     &bytes, &size, why, why_size))
        return 0;
    ok = unpack_mesh(bytes, size, out, why, why_size);
    free(bytes);
    return ok;
}
