/* SPDX-License-Identifier: MIT */
/* GL1 surface detail: DOT3 bump mapping of tangent-space normal maps with
 * ARB_texture_env_dot3 and a normalisation cube map. It is the fixed-function
 * step of the surface chain (POM -> parallax -> normal -> dot3 -> plain) and
 * reads the same inputs as the GLSL techniques: the material's normal_map
 * (RGB = 0.5 + 0.5 n in the tangent frame), albedo texture and colour, and
 * the mesh tangents (xyz + handedness w, B = w * cross(N, T)).
 *
 * A bumped draw is an opaque draw whose material has a normal map. The
 * fixed-function passes draw it as usual but with a black diffuse material
 * (stin__dot3_material, called by set_material), so they keep its ambient
 * and its per-vertex specular; its diffuse term comes from one additive pass
 * per light (depth EQUAL, blend ONE ONE, the caller's stencil and scissor),
 * so it composes with the shadow-volume schedule like any lit pass:
 *
 *   unit 0  normalisation cube map; texture coordinates = the vector from the
 *           vertex to the light in the vertex's tangent frame (unnormalised,
 *           computed per frame into the frame scratch), interpolated, and
 *           normalised per pixel by the lookup: REPLACE
 *   unit 1  normal map at uv: DOT3_RGB(texture, previous) = max(N . L, 0)
 *   unit 2  MODULATE(previous, primary colour)
 *   unit 3  albedo texture at uv, MODULATE (materials that have one)
 *
 * The primary colour is GL's own lighting of the light with every vertex
 * normal pointed at the light (N . L = 1): attenuation * spot * light colour
 * * material colour, clamped, the same per-vertex factors as the plain pass;
 * specular, ambient and emission are black in this pass.
 *
 * Needs 3 texture units (4 for a material with an albedo texture: with 3 such
 * a material stays plain); a context with fewer falls back to plain at
 * creation. Limits on GL1, documented in stin.h: the per-pixel term is the
 * diffuse one only (specular stays per vertex, unbumped); blended draws stay
 * plain; there is no self-shadowing term (a bumped normal tilted toward a
 * light that is just below the surface's horizon still catches some of it).
 */
#include "internal.h"

#define CUBE_SIZE 32u
#define FLOATS_PER_VERTEX 6u /* tangent-space light vector, lighting normal */

struct stin__dot3_state {
    GLuint cube;          /* normalisation cube map; 0 = DOT3 not in use */
    GLenum dot3_rgb;      /* GL_DOT3_RGB (1.3/ARB) or GL_DOT3_RGB_EXT */
    int units;            /* texture units (3 without an albedo texture, 4 with) */
    int warned_scratch;   /* a mesh too big for the scratch was logged */
    int warned_split;     /* a mesh split for 16-bit indices was logged */
};

size_t stin__dot3_state_bytes(const stin_desc *d)
{
    (void)d;
    return sizeof(struct stin__dot3_state);
}

/* ---- cube map ------------------------------------------------------------ */

/* GL's cube-map face selection (GL 1.3, table 3.19) inverted: the direction
 * that lands at (s, t) of a face. */
void stin__dot3_cube_direction(int face, float s, float t, float out[3])
{
    float sc = 2.0f * s - 1.0f, tc = 2.0f * t - 1.0f;
    switch (face) {
    case 0: out[0] = 1.0f; out[1] = -tc; out[2] = -sc; break;  /* +X */
    case 1: out[0] = -1.0f; out[1] = -tc; out[2] = sc; break;  /* -X */
    case 2: out[0] = sc; out[1] = 1.0f; out[2] = tc; break;    /* +Y */
    case 3: out[0] = sc; out[1] = -1.0f; out[2] = -tc; break;  /* -Y */
    case 4: out[0] = sc; out[1] = -tc; out[2] = 1.0f; break;   /* +Z */
    default: out[0] = -sc; out[1] = -tc; out[2] = -1.0f; break; /* -Z */
    }
}

static unsigned char to_unorm8(float x)
{
    float v = 255.0f * x + 0.5f;
    return (unsigned char)(v < 0.0f ? 0.0f : v > 255.0f ? 255.0f : v);
}

/* Rows bottom to top (t from 0), texel centres; alpha 1. */
void stin__dot3_cube_face(int face, uint32_t size, unsigned char *rgba)
{
    uint32_t i, j;
    for (j = 0; j < size; j++)
        for (i = 0; i < size; i++) {
            float d[3], len;
            unsigned char *p = rgba + 4u * (j * size + i);
            stin__dot3_cube_direction(face, ((float)i + 0.5f) / (float)size,
                                      ((float)j + 0.5f) / (float)size, d);
            len = stin__sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            p[0] = to_unorm8(0.5f + 0.5f * d[0] / len);
            p[1] = to_unorm8(0.5f + 0.5f * d[1] / len);
            p[2] = to_unorm8(0.5f + 0.5f * d[2] / len);
            p[3] = 255;
        }
}

/* glTexEnvi on the active unit; the checked build audits pname and param. */
static void env(stin_context *ctx, GLenum pname, GLenum param)
{
#if defined(STIN_GL_CHECK) && STIN_GL_CHECK
    stin__gl_check_enum(ctx, STIN_GLFN_TexEnvi, pname, __FILE__, __LINE__);
#endif
    GL_ENUM(ctx, TexEnvi, param)(GL_TEXTURE_ENV, pname, (GLint)param);
}

static stin_result fall_back(stin_context *ctx, const char *why)
{
    char text[160];
    if (ctx->desc.techniques[STIN_FEATURE_SURFACE] == STIN_TECH_SURFACE_DOT3) {
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_TECHNIQUE_UNSUPPORTED,
                  "stin_create: surface technique dot3 was forced but %s", why);
        return STIN_ERROR_UNSUPPORTED;
    }
    stin__formatf(text, sizeof text, "dot3 %s", why);
    stin__demote(ctx, STIN_FEATURE_SURFACE, STIN_TECH_SURFACE_PLAIN, text);
    return STIN_OK;
}

stin_result stin__dot3_init(stin_context *ctx)
{
    uint32_t size = CUBE_SIZE;
    char why[128];
    int face;
    /* Faces are built one at a time in the larger of the texture staging and
     * the mesh scratch (both idle at creation); scenes size either tightly. */
    unsigned char *buf = ctx->staging_bytes >= ctx->scratch_bytes ? ctx->staging : ctx->scratch;
    size_t buf_bytes = ctx->staging_bytes >= ctx->scratch_bytes ? ctx->staging_bytes
                                                                 : ctx->scratch_bytes;
    stin__memzero(ctx->dot3, sizeof *ctx->dot3);
    if (ctx->sel.choice[STIN_FEATURE_SURFACE].technique != STIN_TECH_SURFACE_DOT3)
        return STIN_OK;
    while (size > 8u && 4u * size * size > buf_bytes)
        size /= 2u; /* 16 or 8 texels a side still normalise to within 0.5% */
    if (4u * size * size > buf_bytes) {
        stin__formatf(why, sizeof why, "needs %u bytes of staging or scratch for its cube map, "
                      "the context has %zu", 4u * size * size, buf_bytes);
        return fall_back(ctx, why);
    }
    ctx->dot3->units = ctx->sel.shadow_unit; /* 3, or 4 where selection spared one (albedo) */
    ctx->dot3->dot3_rgb = ctx->caps.gl_major * 10 + ctx->caps.gl_minor >= 13 ||
                                  stin_query_extension(ctx, "GL_ARB_texture_env_dot3")
                              ? GL_DOT3_RGB
                              : GL_DOT3_RGB_EXT;
    GL(ctx, GenTextures)(1, &ctx->dot3->cube);
    GL(ctx, ActiveTexture)(GL_TEXTURE0);
    GL_ENUM(ctx, BindTexture, GL_TEXTURE_CUBE_MAP)(GL_TEXTURE_CUBE_MAP, ctx->dot3->cube);
    GL_ENUM(ctx, TexParameteri, GL_TEXTURE_CUBE_MAP)(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER,
                                                     GL_LINEAR);
    GL_ENUM(ctx, TexParameteri, GL_TEXTURE_CUBE_MAP)(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER,
                                                     GL_LINEAR);
    {
        GLint wrap = ctx->caps.gl_major * 10 + ctx->caps.gl_minor >= 12 ? GL_CLAMP_TO_EDGE : GL_CLAMP;
        GL_ENUM(ctx, TexParameteri, GL_TEXTURE_CUBE_MAP)(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, wrap);
        GL_ENUM(ctx, TexParameteri, GL_TEXTURE_CUBE_MAP)(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, wrap);
    }
    for (face = 0; face < 6; face++) {
        GLenum target = (GLenum)(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)face);
        stin__dot3_cube_face(face, size, buf);
        stin__upload_bytes(ctx, target, GL_RGBA8, size, size, GL_RGBA, buf);
    }
    GL_ENUM(ctx, BindTexture, GL_TEXTURE_CUBE_MAP)(GL_TEXTURE_CUBE_MAP, 0);
    return STIN_OK;
}

void stin__dot3_release(stin_context *ctx)
{
    if (ctx->dot3->cube)
        GL(ctx, DeleteTextures)(1, &ctx->dot3->cube);
    ctx->dot3->cube = 0;
}

int stin__dot3_bumped(const stin_context *ctx, const stin_material *m)
{
    if (!ctx->dot3->cube || m->color[3] < 1.0f || !stin__texture_lookup(ctx, m->normal_map) ||
        m->surface == STIN_TECH_SURFACE_PLAIN) /* the material asks for no bump */
        return 0;
    return ctx->dot3->units >= (stin__texture_lookup(ctx, m->albedo) ? 4 : 3);
}

void stin__dot3_material(stin_context *ctx, const stin_material *m)
{
    float no_diffuse[4];
    if (!stin__dot3_bumped(ctx, m))
        return;
    no_diffuse[0] = no_diffuse[1] = no_diffuse[2] = 0.0f;
    no_diffuse[3] = m->color[3]; /* GL takes the lit alpha from the diffuse material */
    GL(ctx, Materialfv)(GL_FRONT_AND_BACK, GL_DIFFUSE, no_diffuse);
}

/* ---- tangent-space light vectors ----------------------------------------- */

static float dot3f(const float a[3], const float b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void cross3f(float o[3], const float a[3], const float b[3])
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

static void normalize3f(float v[3])
{
    float l = stin__sqrtf(dot3f(v, v));
    if (l > 1e-30f) {
        v[0] /= l;
        v[1] /= l;
        v[2] /= l;
    }
}

/* Upper 3x3 of a column-major 4x4 times v. */
static void mul3(float o[3], const float m[16], const float v[3])
{
    int r;
    for (r = 0; r < 3; r++)
        o[r] = m[r] * v[0] + m[4 + r] * v[1] + m[8 + r] * v[2];
}

/* Two exact ways to one answer: the vector to the light in the tangent frame
 * the object has in the world (T and B transformed as tangents, N by the
 * normal matrix, re-orthonormalised).
 *  - A similarity transform (rotation, mirror, uniform scale: A^T A = s^2 I)
 *    preserves angles, so the object-space frame dotted with the light moved
 *    into object space by the inverse model matrix gives the same direction
 *    (scaled by s, which the cube map removes): no square roots per vertex.
 *  - Any other transform (non-uniform scale, shear) takes the world-space
 *    frame per vertex. */
void stin__dot3_light_vectors(const stin__vertex *v, uint32_t n, const float model[16],
                              const float light_world[4], float *out)
{
    float G[9], s2, inv[16], nm[9], det;
    int i, j, similar = 1;
    uint32_t k;
    for (i = 0; i < 3; i++) /* G = A^T A: dot products of the columns */
        for (j = 0; j < 3; j++)
            G[3 * i + j] = model[4 * i] * model[4 * j] + model[4 * i + 1] * model[4 * j + 1] +
                           model[4 * i + 2] * model[4 * j + 2];
    s2 = (G[0] + G[4] + G[8]) / 3.0f;
    for (i = 0; i < 9; i++) {
        float d = G[i] - (i % 4 == 0 ? s2 : 0.0f);
        if (d > 1e-5f * s2 || d < -1e-5f * s2)
            similar = 0;
    }
    if (similar && s2 > 0.0f && stin__mat4_invert(inv, model)) {
        float lo[3], w = light_world[3];
        for (i = 0; i < 3; i++) /* light in object space; w stays */
            lo[i] = inv[i] * light_world[0] + inv[4 + i] * light_world[1] +
                    inv[8 + i] * light_world[2] + inv[12 + i] * w;
        for (k = 0; k < n; k++) {
            const stin__vertex *p = &v[k];
            float L[3], B[3], *o = out + FLOATS_PER_VERTEX * k;
            L[0] = lo[0] - p->position[0] * w;
            L[1] = lo[1] - p->position[1] * w;
            L[2] = lo[2] - p->position[2] * w;
            cross3f(B, p->normal, p->tangent);
            o[0] = dot3f(p->tangent, L);
            o[1] = p->tangent[3] * dot3f(B, L);
            o[2] = dot3f(p->normal, L);
            /* GL lights with the normal matrix A^-T = A / s^2: L itself points at the light */
            o[3] = L[0];
            o[4] = L[1];
            o[5] = L[2];
        }
        return;
    }
    stin__mat3_normal(nm, model);
    det = model[0] * (model[5] * model[10] - model[9] * model[6]) -
          model[4] * (model[1] * model[10] - model[9] * model[2]) +
          model[8] * (model[1] * model[6] - model[5] * model[2]);
    for (k = 0; k < n; k++) {
        const stin__vertex *p = &v[k];
        float P[3], L[3], T[3], N[3], B[3], d, *o = out + FLOATS_PER_VERTEX * k;
        mul3(P, model, p->position);
        for (i = 0; i < 3; i++)
            L[i] = light_world[i] - (P[i] + model[12 + i]) * light_world[3];
        mul3(T, model, p->tangent);
        for (i = 0; i < 3; i++)
            N[i] = nm[i] * p->normal[0] + nm[3 + i] * p->normal[1] + nm[6 + i] * p->normal[2];
        normalize3f(N);
        d = dot3f(N, T);
        for (i = 0; i < 3; i++)
            T[i] -= N[i] * d;
        normalize3f(T);
        cross3f(B, N, T); /* A B_object keeps this side of T: w, flipped by a mirror */
        d = det < 0.0f ? -p->tangent[3] : p->tangent[3];
        o[0] = dot3f(T, L);
        o[1] = d * dot3f(B, L);
        o[2] = dot3f(N, L);
        /* A^T L: the normal matrix A^-T turns it back into L */
        for (i = 0; i < 3; i++)
            o[3 + i] = model[4 * i] * L[0] + model[4 * i + 1] * L[1] + model[4 * i + 2] * L[2];
    }
}

/* ---- the DOT3 pass ------------------------------------------------------- */

static const void *at_offset(const void *base, size_t offset)
{
    return (const void *)((uintptr_t)base + offset);
}

static int bumped_draw(const stin_context *ctx, const stin__draw *d)
{
    return d->material.color[3] >= 1.0f && stin__dot3_bumped(ctx, &d->material);
}

static int any_bumped(const stin_context *ctx)
{
    uint32_t i;
    for (i = 0; i < ctx->draw_count; i++)
        if (bumped_draw(ctx, &ctx->draws[i]))
            return 1;
    return 0;
}

static void unit(stin_context *ctx, int u)
{
    GL(ctx, ActiveTexture)((GLenum)(GL_TEXTURE0 + (GLenum)u));
}

static void client_unit(stin_context *ctx, int u)
{
    GL(ctx, ClientActiveTexture)((GLenum)(GL_TEXTURE0 + (GLenum)u));
}

static void setup_units(stin_context *ctx)
{
    unit(ctx, 0); /* normalised light vector */
    GL_DISABLE(ctx, GL_TEXTURE_2D);
    GL_ENABLE(ctx, GL_TEXTURE_CUBE_MAP);
    GL_ENUM(ctx, BindTexture, GL_TEXTURE_CUBE_MAP)(GL_TEXTURE_CUBE_MAP, ctx->dot3->cube);
    env(ctx, GL_TEXTURE_ENV_MODE, GL_COMBINE);
    env(ctx, GL_COMBINE_RGB, GL_REPLACE);
    env(ctx, GL_SOURCE0_RGB, GL_TEXTURE);
    env(ctx, GL_OPERAND0_RGB, GL_SRC_COLOR);
    env(ctx, GL_COMBINE_ALPHA, GL_REPLACE);
    env(ctx, GL_SOURCE0_ALPHA, GL_PRIMARY_COLOR);
    env(ctx, GL_OPERAND0_ALPHA, GL_SRC_ALPHA);
    env(ctx, GL_RGB_SCALE, 1);

    unit(ctx, 1); /* N . L */
    GL_ENABLE(ctx, GL_TEXTURE_2D);
    env(ctx, GL_TEXTURE_ENV_MODE, GL_COMBINE);
    env(ctx, GL_COMBINE_RGB, ctx->dot3->dot3_rgb);
    env(ctx, GL_SOURCE0_RGB, GL_TEXTURE);
    env(ctx, GL_OPERAND0_RGB, GL_SRC_COLOR);
    env(ctx, GL_SOURCE1_RGB, GL_PREVIOUS);
    env(ctx, GL_OPERAND1_RGB, GL_SRC_COLOR);
    env(ctx, GL_COMBINE_ALPHA, GL_REPLACE);
    env(ctx, GL_SOURCE0_ALPHA, GL_PREVIOUS);
    env(ctx, GL_OPERAND0_ALPHA, GL_SRC_ALPHA);
    env(ctx, GL_RGB_SCALE, 1);

    unit(ctx, 2); /* times the lit colour; its texture (the normal map) is not read */
    GL_ENABLE(ctx, GL_TEXTURE_2D);
    env(ctx, GL_TEXTURE_ENV_MODE, GL_COMBINE);
    env(ctx, GL_COMBINE_RGB, GL_MODULATE);
    env(ctx, GL_SOURCE0_RGB, GL_PREVIOUS);
    env(ctx, GL_OPERAND0_RGB, GL_SRC_COLOR);
    env(ctx, GL_SOURCE1_RGB, GL_PRIMARY_COLOR);
    env(ctx, GL_OPERAND1_RGB, GL_SRC_COLOR);
    env(ctx, GL_COMBINE_ALPHA, GL_REPLACE);
    env(ctx, GL_SOURCE0_ALPHA, GL_PREVIOUS);
    env(ctx, GL_OPERAND0_ALPHA, GL_SRC_ALPHA);
    env(ctx, GL_RGB_SCALE, 1);

    client_unit(ctx, 1);
    GL(ctx, EnableClientState)(GL_TEXTURE_COORD_ARRAY);
    if (ctx->dot3->units >= 4) { /* times the albedo texture, per draw */
        unit(ctx, 3);
        env(ctx, GL_TEXTURE_ENV_MODE, GL_MODULATE);
        client_unit(ctx, 3);
        GL(ctx, EnableClientState)(GL_TEXTURE_COORD_ARRAY);
    }
}

/* Every unit back to GL's defaults, nothing bound, unit 0 active. */
static void restore_units(stin_context *ctx)
{
    int u;
    for (u = ctx->dot3->units - 1; u >= 0; u--) {
        unit(ctx, u);
        env(ctx, GL_TEXTURE_ENV_MODE, GL_MODULATE);
        if (u < 3) {
            env(ctx, GL_COMBINE_RGB, GL_MODULATE);
            env(ctx, GL_COMBINE_ALPHA, GL_MODULATE);
            env(ctx, GL_SOURCE0_RGB, GL_TEXTURE);
            env(ctx, GL_SOURCE1_RGB, GL_PREVIOUS);
            env(ctx, GL_SOURCE0_ALPHA, GL_TEXTURE);
            env(ctx, GL_SOURCE1_ALPHA, GL_PREVIOUS);
        }
        if (u == 0) {
            GL_DISABLE(ctx, GL_TEXTURE_CUBE_MAP);
            GL_ENUM(ctx, BindTexture, GL_TEXTURE_CUBE_MAP)(GL_TEXTURE_CUBE_MAP, 0);
        } else {
            GL_DISABLE(ctx, GL_TEXTURE_2D);
            GL(ctx, BindTexture)(GL_TEXTURE_2D, 0);
        }
        if (u == 1 || u == 3) {
            client_unit(ctx, u);
            GL(ctx, DisableClientState)(GL_TEXTURE_COORD_ARRAY);
        }
    }
    client_unit(ctx, 0);
    ctx->bound_mesh = 0xffffffffu; /* unit 0's coordinates and the normals point at scratch */
}

/* A mesh whose vectors do not fit the scratch: per-vertex diffuse instead
 * (lighting with its own normals, units 0-2 off), logged once. */
static void draw_plain_diffuse(stin_context *ctx, const stin__draw *d, const void *base)
{
    const stin__mesh_slot *m = &ctx->meshes[d->mesh_slot];
    const GLsizei stride = (GLsizei)sizeof(stin__vertex);
    const void *idx = m->vbo ? NULL : (const void *)(ctx->indices + 3u * m->first_triangle);
    if (!ctx->dot3->warned_scratch) {
        ctx->dot3->warned_scratch = 1;
        stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                  "surface dot3: a mesh of %u vertices needs %lu frame scratch bytes, %zu available; "
                  "drawn with per-vertex diffuse", m->vertex_count,
                  (unsigned long)(m->vertex_count * FLOATS_PER_VERTEX * sizeof(float)),
                  ctx->frame_scratch_bytes);
    }
    if (m->vbo)
        GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, m->vbo);
    client_unit(ctx, 0);
    GL(ctx, TexCoordPointer)(2, GL_FLOAT, stride, at_offset(base, 24));
    GL(ctx, NormalPointer)(GL_FLOAT, stride, at_offset(base, 12));
    if (m->vbo)
        GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, 0);
    unit(ctx, 0);
    GL_DISABLE(ctx, GL_TEXTURE_CUBE_MAP);
    unit(ctx, 1);
    GL_DISABLE(ctx, GL_TEXTURE_2D);
    unit(ctx, 2);
    GL_DISABLE(ctx, GL_TEXTURE_2D);
    stin__mesh_draw(ctx, m, GL_TRIANGLES, idx, NULL);
    GL_ENABLE(ctx, GL_TEXTURE_2D);
    unit(ctx, 1);
    GL_ENABLE(ctx, GL_TEXTURE_2D);
    unit(ctx, 0);
    GL_ENABLE(ctx, GL_TEXTURE_CUBE_MAP);
}

static void draw_bumped(stin_context *ctx, const stin__draw *d, const float light_world[4])
{
    const stin__mesh_slot *m = &ctx->meshes[d->mesh_slot];
    const stin__texture_slot *nt = stin__texture_lookup(ctx, d->material.normal_map);
    const stin__texture_slot *at = stin__texture_lookup(ctx, d->material.albedo);
    const GLsizei stride = (GLsizei)sizeof(stin__vertex);
    const void *base = m->vbo ? NULL : (const void *)(ctx->vertices + m->first_vertex);
    const void *idx = m->vbo ? NULL : (const void *)(ctx->indices + 3u * m->first_triangle);
    const float *vec = (const float *)(void *)ctx->frame_scratch;
    int fits = (size_t)m->vertex_count * FLOATS_PER_VERTEX * sizeof(float) <= ctx->frame_scratch_bytes;
    float mv[16];
    if (m->chunk_count > 1u) { /* per-vertex vectors follow the stored vertices, not chunks */
        if (!ctx->dot3->warned_split) {
            ctx->dot3->warned_split = 1;
            stin__log(ctx, STIN_LOG_LEVEL_WARNING, STIN_LOG_FALLBACK,
                      "surface dot3: a mesh of %u vertices without 32-bit element indices is "
                      "not drawn bumped (its lit passes are left out)", m->vertex_count, 0);
        }
        return;
    }
    if (ctx->lit_draw) /* the shadow test's rule for this receiver */
        ctx->lit_draw(ctx, d);
    stin__mat4_mul(mv, ctx->frame.view, d->transform);
    GL(ctx, MatrixMode)(GL_MODELVIEW);
    GL(ctx, LoadMatrixf)(mv);
    GL(ctx, Materialfv)(GL_FRONT_AND_BACK, GL_DIFFUSE, d->material.color);
    if (m->vbo) {
        GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, m->vbo);
        GL(ctx, BindBuffer)(GL_ELEMENT_ARRAY_BUFFER, m->ibo);
    }
    GL(ctx, VertexPointer)(3, GL_FLOAT, stride, base);
    client_unit(ctx, 1);
    GL(ctx, TexCoordPointer)(2, GL_FLOAT, stride, at_offset(base, 24));
    if (ctx->dot3->units >= 4) {
        client_unit(ctx, 3);
        GL(ctx, TexCoordPointer)(2, GL_FLOAT, stride, at_offset(base, 24));
        unit(ctx, 3);
        if (at) {
            GL_ENABLE(ctx, GL_TEXTURE_2D);
            GL(ctx, BindTexture)(GL_TEXTURE_2D, at->name);
        } else {
            GL_DISABLE(ctx, GL_TEXTURE_2D);
        }
    }
    if (m->vbo)
        GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, 0);
    if (!fits) {
        draw_plain_diffuse(ctx, d, base);
        return;
    }
    /* The lit pass runs after the volume pass: the frame scratch is free. */
    stin__dot3_light_vectors(ctx->vertices + m->first_vertex, m->vertex_count, d->transform,
                             light_world, (float *)(void *)ctx->frame_scratch);
    client_unit(ctx, 0);
    GL(ctx, TexCoordPointer)(3, GL_FLOAT, (GLsizei)(FLOATS_PER_VERTEX * sizeof(float)), vec);
    GL(ctx, NormalPointer)(GL_FLOAT, (GLsizei)(FLOATS_PER_VERTEX * sizeof(float)), vec + 3);
    unit(ctx, 1);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, nt->name);
    unit(ctx, 2);
    GL(ctx, BindTexture)(GL_TEXTURE_2D, nt->name);
    stin__mesh_draw(ctx, m, GL_TRIANGLES, idx, NULL);
}

static void light_vector(const stin_light_desc *l, float out[4])
{
    int k;
    for (k = 0; k < 3; k++)
        out[k] = l->type == STIN_LIGHT_DIRECTIONAL ? -l->direction[k] : l->position[k];
    out[3] = l->type == STIN_LIGHT_DIRECTIONAL ? 0.0f : 1.0f;
}

/* GL clamps the lit vertex colour to 1 before the combiners multiply it by
 * N.L, where the plain pass clamps after: a light brighter than 1 (colour *
 * intensity, or attenuation above 1) is lit at 1/2 or 1/4 and unit 2 scales
 * the product back (GL_RGB_SCALE 2 or 4), trading a bit or two of precision
 * for headroom up to 4. Returns the scale. */
static int light_scale(stin_context *ctx, const stin_light_desc *l, int gl_light)
{
    float peak = 0.0f, c[4];
    int k, scale;
    for (k = 0; k < 3; k++)
        if (l->color[k] * l->intensity > peak)
            peak = l->color[k] * l->intensity;
    if (l->type != STIN_LIGHT_DIRECTIONAL && l->attenuation[0] < 1.0f)
        peak = l->attenuation[0] > 0.0f ? peak / l->attenuation[0] : 4.0f * peak + 4.0f;
    scale = peak > 2.0f ? 4 : peak > 1.0f ? 2 : 1;
    if (scale == 1)
        return 1;
    for (k = 0; k < 3; k++)
        c[k] = l->color[k] * l->intensity / (float)scale;
    c[3] = 1.0f;
    GL(ctx, Lightfv)((GLenum)(GL_LIGHT0 + gl_light), GL_DIFFUSE, c);
    unit(ctx, 2);
    env(ctx, GL_RGB_SCALE, (GLenum)scale);
    return scale;
}

/* Returns 1 when it drew (and changed the scene ambient). */
static int passes(stin_context *ctx, const stin_light_desc *lights, int count)
{
    static const float black[4] = {0, 0, 0, 1};
    stin__pass_state saved, ps;
    int k, j, scale;
    uint32_t i;
    if (count <= 0 || !ctx->dot3->cube || !any_bumped(ctx))
        return 0;
    /* The caller's stencil test applies; its operations do not: the shadow
     * schedule increments where it lights (so coplanar fragments are lit
     * once), which would keep the plain pass of the same light from adding
     * its specular after this one. */
    saved = *stin__pass_current(ctx);
    ps = stin__pass_draw(ctx, 1, 0);
    ps.two_sided = 0;
    ps.front.fail = ps.front.zfail = ps.front.zpass = GL_KEEP;
    stin__pass_apply(ctx, &ps);
    GL(ctx, LightModelfv)(GL_LIGHT_MODEL_AMBIENT, black);
    GL(ctx, Materialfv)(GL_FRONT_AND_BACK, GL_AMBIENT, black);
    GL(ctx, Materialfv)(GL_FRONT_AND_BACK, GL_SPECULAR, black);
    GL(ctx, Materialfv)(GL_FRONT_AND_BACK, GL_EMISSION, black);
    setup_units(ctx);
    for (k = 0; k < count; k++) {
        float lw[4];
        if (count > 1)
            for (j = 0; j < count; j++) {
                if (j == k)
                    GL_ENABLE(ctx, (GLenum)(GL_LIGHT0 + j));
                else
                    GL_DISABLE(ctx, (GLenum)(GL_LIGHT0 + j));
            }
        light_vector(&lights[k], lw);
        scale = light_scale(ctx, &lights[k], k);
        for (i = 0; i < ctx->draw_count; i++) {
            const stin__draw *d = &ctx->draws[ctx->draw_order[i]];
            if (bumped_draw(ctx, d))
                draw_bumped(ctx, d, lw);
        }
        if (scale > 1) { /* the light as set_light left it */
            float c[4];
            for (j = 0; j < 3; j++)
                c[j] = lights[k].color[j] * lights[k].intensity;
            c[3] = 1.0f;
            GL(ctx, Lightfv)((GLenum)(GL_LIGHT0 + k), GL_DIFFUSE, c);
            unit(ctx, 2);
            env(ctx, GL_RGB_SCALE, 1);
        }
        ctx->stats.passes++;
    }
    if (count > 1)
        for (j = 0; j < count; j++)
            GL_ENABLE(ctx, (GLenum)(GL_LIGHT0 + j));
    restore_units(ctx);
    stin__pass_apply(ctx, &saved);
    return 1;
}

void stin__dot3_lights(stin_context *ctx, const stin_light_desc *lights, int count)
{
    (void)passes(ctx, lights, count);
}

void stin__dot3_batch(stin_context *ctx, int batch)
{
    int first = batch * ctx->lights_per_pass, n = (int)ctx->light_count - first;
    if (n > ctx->lights_per_pass)
        n = ctx->lights_per_pass;
    if (passes(ctx, ctx->lights + first, n) && batch == 0) {
        float ambient[4];
        ambient[0] = ctx->frame.ambient[0];
        ambient[1] = ctx->frame.ambient[1];
        ambient[2] = ctx->frame.ambient[2];
        ambient[3] = 1.0f;
        GL(ctx, LightModelfv)(GL_LIGHT_MODEL_AMBIENT, ambient);
    }
}
