/* Model files (OBJ, PLY, STL, glTF/glb, anything assimp reads) merged into
 * one indexed triangle mesh in the file's own coordinates. */
#include "scene_internal.h"
#include "scene_primitives.h"

#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

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

int scene_mesh_load_file(const char *path, scene_mesh *out, char *why, size_t why_size)
{
    const unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                           aiProcess_GenSmoothNormals | aiProcess_PreTransformVertices;
    const struct aiScene *sc;
    uint64_t verts, tris;
    uint32_t base = 0, tri = 0;
    unsigned i;
    FILE *probe = fopen(path, "rb");
    /* Check first so a missing file says why in the system's words. */
    if (!probe) {
        snprintf(why, why_size, "%s", strerror(errno));
        return 0;
    }
    fclose(probe);
    sc = aiImportFile(path, flags);
    if (!sc) {
        snprintf(why, why_size, "%s", aiGetErrorString());
        return 0;
    }
    if (!count_geometry(sc, &verts, &tris) || tris == 0) {
        snprintf(why, why_size, tris ? "too many vertices" : "no triangles in the file");
        aiReleaseImport(sc);
        return 0;
    }
    if (!scene_mesh_alloc(out, (uint32_t)verts, (uint32_t)tris)) {
        snprintf(why, why_size, "out of memory");
        aiReleaseImport(sc);
        return 0;
    }
    for (i = 0; i < sc->mNumMeshes; i++) {
        copy_mesh(sc->mMeshes[i], out, base, &tri);
        base += sc->mMeshes[i]->mNumVertices;
    }
    aiReleaseImport(sc);
    return 1;
}
