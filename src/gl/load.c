/* SPDX-License-Identifier: MIT */
/* Resolves the GL entry-point table from the caller's get_proc_address and,
 * in checked builds, audits each call against the capability profile. */
#include "internal.h"

static const char *const gl_names[] = {
#define STIN_X_(ret, name, params, need, alt) "gl" #name,
    STIN_GL_FUNCS(STIN_X_)
#undef STIN_X_
};

static const char *const gl_alt_names[] = {
#define STIN_X_(ret, name, params, need, alt) alt,
    STIN_GL_FUNCS(STIN_X_)
#undef STIN_X_
};

static const int gl_needs[] = {
#define STIN_X_(ret, name, params, need, alt) need,
    STIN_GL_FUNCS(STIN_X_)
#undef STIN_X_
};

const char *stin__glfn_name(stin__glfn fn)
{
    return (unsigned)fn < STIN_GLFN_COUNT ? gl_names[fn] : "gl?";
}

int stin__glfn_need(stin__glfn fn) { return (unsigned)fn < STIN_GLFN_COUNT ? gl_needs[fn] : NEED_CORE; }

/* Per NEED_* from NEED_CORE: the desktop GL version, and the OpenGL ES
 * version with the same entry points and enums (-1: never). */
static const int need_versions[NEED_COUNT - NEED_CORE] = {11, 12, 13, 14, 30, 31, 32, 33, 42, 43,
                                                         11, 11, -1};
static const int need_es_versions[NEED_COUNT - NEED_CORE] = {20, 30, 20, 20, 30, 30, 32, 30, 31,
                                                            30, 20, -1, 20};

int stin__need_version(int need)
{
    return need >= NEED_CORE && need < NEED_COUNT ? need_versions[need - NEED_CORE] : 0;
}

int stin__need_version_in(int need, int es)
{
    if (need < NEED_CORE || need >= NEED_COUNT)
        return 0;
    return es ? need_es_versions[need - NEED_CORE] : need_versions[need - NEED_CORE];
}

const char *stin__need_name(int need)
{
    static const char *const names[NEED_COUNT - NEED_CORE] = {
        "GL 1.1", "GL 1.2", "GL 1.3", "GL 1.4", "GL 3.0", "GL 3.1", "GL 3.2", "GL 3.3", "GL 4.2",
        "GL 4.3",
        "its version or extension", "desktop GL (not OpenGL ES)", "OpenGL ES"};
    return need >= NEED_CORE && need < NEED_COUNT ? names[need - NEED_CORE]
                                                  : stin_cap_name((stin_cap)need);
}

/* What fn needs on this context: the query object calls are audited as
 * occlusion queries on desktop (GL 1.5 brought both), but ES 3.0 has the
 * objects without sample counts (primitive and any-samples queries).
 * glMemoryBarrier is audited with the compute paths that call it on
 * desktop (ARB_compute_shader may bring them below GL 4.2), but ES 3.1 has
 * it in core for vdsm's image atomics (COMPUTE stays off there). */
static int need_of(const stin_context *ctx, stin__glfn fn)
{
    if (ctx->caps.es && gl_needs[fn] == STIN_CAP_OCCLUSION_QUERY)
        return NEED_GL30;
    if (ctx->caps.es && fn == STIN_GLFN_MemoryBarrier)
        return NEED_GL42;
    return gl_needs[fn];
}

static int need_present(const stin_context *ctx, int need)
{
    int version = stin__need_version_in(need, ctx->caps.es);
    if (version < 0)
        return 0;
    if (version)
        return ctx->caps.gl_major * 10 + ctx->caps.gl_minor >= version;
    return (ctx->caps.present & STIN_CAP_BIT(need)) != 0;
}

/* Entry points OpenGL ES 3.2 lacks besides fixed function: their ES
 * counterparts differ in name or type (glClearDepthf) or do not exist. */
static int desktop_only_name(stin__glfn fn)
{
    switch (fn) {
    case STIN_GLFN_ClientActiveTexture: case STIN_GLFN_ActiveStencilFaceEXT:
    case STIN_GLFN_BindFragDataLocation: case STIN_GLFN_ClampColor:
    case STIN_GLFN_ProvokingVertex: case STIN_GLFN_GetTexLevelParameteriv:
    case STIN_GLFN_DrawTransformFeedback: case STIN_GLFN_GetBufferSubData:
    case STIN_GLFN_ClearBufferData: case STIN_GLFN_QueryCounter:
    case STIN_GLFN_GetQueryObjectui64v:
        return 1;
    default:
        return 0;
    }
}

int stin__glfn_es_exempt(stin__glfn fn)
{
    /* stin's storage-buffer reads and clears: without them its COMPUTE
     * paths cannot run, so ES 3.1's compute does not count (yet) */
    return stin__glfn_desktop_only(fn) && fn != STIN_GLFN_GetBufferSubData &&
           fn != STIN_GLFN_ClearBufferData;
}

int stin__glfn_desktop_only(stin__glfn fn)
{
    int need = stin__glfn_need(fn);
    return need == NEED_DESKTOP || need == STIN_CAP_FIXED_FUNCTION || desktop_only_name(fn);
}

int stin__gl_is_es(const stin__gl *gl)
{
    const char *v = gl->GetString ? (const char *)gl->GetString(GL_VERSION) : NULL;
    const char *p = "OpenGL ES";
    while (v && *p && *v == *p) {
        v++;
        p++;
    }
    return v && !*p;
}

int stin__gl_available(const stin_context *ctx, stin__glfn fn)
{
    return ctx->gl_loaded[fn] && need_present(ctx, need_of(ctx, fn));
}

/* Function and object pointers do not convert in ISO C; copy the bits. */
typedef void (*stin__any_fn)(void);
static void store_fn(void *slot, void *p) { stin__memcopy(slot, &p, sizeof p); }

int stin__gl_load(stin__gl *gl, stin_get_proc_fn get_proc, void *user,
                  unsigned char loaded[STIN_GLFN_COUNT])
{
    stin__any_fn *slots = (stin__any_fn *)(void *)gl;
    int i, missing = 0, es;
    for (i = 0; i < STIN_GLFN_COUNT; i++) {
        void *p = get_proc(user, gl_names[i]);
        if (!p && gl_alt_names[i][0])
            p = get_proc(user, gl_alt_names[i]);
        store_fn(&slots[i], p);
        loaded[i] = p != NULL;
    }
    es = stin__gl_is_es(gl);
    for (i = 0; i < STIN_GLFN_COUNT; i++) {
        if (es && stin__glfn_desktop_only((stin__glfn)i)) {
            store_fn(&slots[i], NULL);
            loaded[i] = 0;
        } else if (!es && gl_needs[i] == NEED_ES) {
            loaded[i] = 0; /* never called there; not missing either */
            continue;
        }
        if (!loaded[i])
            missing++;
    }
    return missing;
}

#if defined(STIN_GL_CHECK) && STIN_GL_CHECK

void stin__gl_check_call(struct stin_context *ctx, stin__glfn fn, const char *file, int line)
{
    int need = need_of(ctx, fn);
    stin__gl_audit_at(ctx, file, line);
    if (!ctx->gl_loaded[fn] || !need_present(ctx, need)) {
        ctx->gl_violations++;
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_GL_ERROR,
                  "%s at %s:%d called but the profile lacks %s", gl_names[fn], file, line,
                  stin__need_name(need));
    }
}

/* Enums that belong to a capability, for the calls that take them. */
static int enum_need(GLenum e)
{
    switch (e) {
    case GL_LIGHTING: case GL_NORMALIZE: case GL_COLOR_MATERIAL: case GL_LIGHT0:
    case GL_LIGHT0 + 1: case GL_LIGHT0 + 2: case GL_LIGHT0 + 3: case GL_LIGHT0 + 4:
    case GL_LIGHT0 + 5: case GL_LIGHT0 + 6: case GL_LIGHT0 + 7:
        return STIN_CAP_FIXED_FUNCTION;
    case GL_TEXTURE_CUBE_MAP: case GL_TEXTURE_BINDING_CUBE_MAP:
    case GL_TEXTURE_CUBE_MAP_POSITIVE_X: case GL_TEXTURE_CUBE_MAP_NEGATIVE_X:
    case GL_TEXTURE_CUBE_MAP_POSITIVE_Y: case GL_TEXTURE_CUBE_MAP_NEGATIVE_Y:
    case GL_TEXTURE_CUBE_MAP_POSITIVE_Z: case GL_TEXTURE_CUBE_MAP_NEGATIVE_Z:
        return STIN_CAP_TEXTURE_CUBE_MAP;
    case GL_COMBINE: case GL_COMBINE_RGB: case GL_COMBINE_ALPHA: case GL_RGB_SCALE:
    case GL_CONSTANT: case GL_PRIMARY_COLOR: case GL_PREVIOUS: case GL_SOURCE0_RGB:
    case GL_SOURCE1_RGB: case GL_SOURCE0_ALPHA: case GL_SOURCE1_ALPHA: case GL_OPERAND0_RGB:
    case GL_OPERAND1_RGB: case GL_OPERAND0_ALPHA: case GL_OPERAND1_ALPHA:
        return STIN_CAP_TEXTURE_ENV_COMBINE;
    case GL_DOT3_RGB: case GL_DOT3_RGBA: case GL_DOT3_RGB_EXT: case GL_DOT3_RGBA_EXT:
        return STIN_CAP_TEXTURE_ENV_DOT3;
    case GL_DEPTH_CLAMP: return STIN_CAP_DEPTH_CLAMP;
    case GL_LIGHT_MODEL_COLOR_CONTROL: return STIN_CAP_SEPARATE_SPECULAR;
    case GL_STENCIL_TEST_TWO_SIDE_EXT: return STIN_CAP_STENCIL_TWO_SIDE;
    case GL_TEXTURE_COMPARE_MODE: case GL_TEXTURE_COMPARE_FUNC: case GL_COMPARE_R_TO_TEXTURE:
    case GL_DEPTH_TEXTURE_MODE:
        return STIN_CAP_SHADOW;
    case GL_DEPTH_COMPONENT: case GL_DEPTH_COMPONENT24: return STIN_CAP_DEPTH_TEXTURE;
    case GL_DEPTH24_STENCIL8: return STIN_CAP_PACKED_DEPTH_STENCIL;
    case GL_RGBA32F: case GL_RGBA16F: return STIN_CAP_FLOAT_TEXTURE;
    case GL_RG32F: return STIN_CAP_FLOAT_TEXTURE;
    case GL_ADD_SIGNED: case GL_ADD: return STIN_CAP_TEXTURE_ENV_COMBINE;
    case GL_ALPHA_TEST: case GL_TEXTURE_GEN_S: case GL_TEXTURE_GEN_T: case GL_TEXTURE_GEN_R:
    case GL_TEXTURE_GEN_Q: case GL_TEXTURE_1D:
        return STIN_CAP_FIXED_FUNCTION;
    case GL_INCR_WRAP: case GL_DECR_WRAP: return STIN_CAP_STENCIL_WRAP;
    case GL_POLYGON_STIPPLE: case GL_FOG: case GL_COLOR_ARRAY: case GL_INDEX_ARRAY:
    case GL_EDGE_FLAG_ARRAY:
        return STIN_CAP_FIXED_FUNCTION;
    case GL_COLOR_SUM: case GL_FOG_COORD_ARRAY: case GL_SECONDARY_COLOR_ARRAY: return NEED_GL14;
    case GL_TEXTURE_3D: return NEED_GL12;
    case GL_SAMPLE_ALPHA_TO_COVERAGE: case GL_SAMPLE_ALPHA_TO_ONE: case GL_SAMPLE_COVERAGE:
        return NEED_GL13;
    case GL_RASTERIZER_DISCARD: case GL_TEXTURE_2D_ARRAY: return NEED_GL30;
    case GL_SAMPLES_PASSED: return STIN_CAP_OCCLUSION_QUERY;
    case GL_ANY_SAMPLES_PASSED: return NEED_GL33; /* ES 3.0 */
    case GL_TIME_ELAPSED: return STIN_CAP_TIMER_QUERY;
    case GL_PRIMITIVE_RESTART: return NEED_GL31;
    case GL_SAMPLE_MASK: return NEED_GL32;
    case GL_PRIMITIVE_RESTART_FIXED_INDEX: return NEED_GL43;
    case GL_TEXTURE_2D: return -1; /* enable-able only with fixed function: see below */
    default: return NEED_CORE;
    }
}

void stin__gl_check_enum(struct stin_context *ctx, stin__glfn fn, GLenum e, const char *file,
                         int line)
{
    int need = enum_need(e);
    stin__gl_check_call(ctx, fn, file, line);
    if (need == -1)
        need = (fn == STIN_GLFN_Enable || fn == STIN_GLFN_Disable) ? STIN_CAP_FIXED_FUNCTION
                                                                   : NEED_CORE;
    if (!need_present(ctx, need)) {
        ctx->gl_violations++;
        stin__log(ctx, STIN_LOG_LEVEL_ERROR, STIN_LOG_GL_ERROR,
                  "%s(0x%x) at %s:%d needs %s, which the profile lacks", gl_names[fn],
                  (unsigned)e, file, line, stin__need_name(need));
    }
}
#endif
