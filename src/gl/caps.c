/* SPDX-License-Identifier: MIT */
/* Capability detection: GL/GLSL versions, exact extension tokens (parsed in
 * place, no copies), limits, and which entry points loaded. */
#include "internal.h"

static const int cap_min_version[] = {
#define STIN_X_(id, name, ver, exts) ver,
    STIN_CAP_LIST(STIN_X_)
#undef STIN_X_
};

static const char *const cap_extensions[] = {
#define STIN_X_(id, name, ver, exts) exts,
    STIN_CAP_LIST(STIN_X_)
#undef STIN_X_
};

/* OpenGL ES: the ES version that has each capability in core and the ES
 * extensions that give it earlier; `also` must be listed as well (float
 * textures are core in ES 3.0 but colour-renderable, which is what stin
 * renders into, only with EXT_color_buffer_float). Fragment derivatives are
 * core in GLSL ES 3.00 and OES_standard_derivatives on ES 2.0 (without them
 * the shaders take their derivative-free paths). Capabilities left out are
 * never present on ES: fixed function and its texture environments, EXT's
 * two-sided stencil (ES 2.0 has separate stencil), depth clamp (Mesa's
 * EXT_depth_clamp is left to a later change: volumes take the far plane at
 * infinity), timer queries (EXT_disjoint_timer_query's entry points are not
 * loaded) and drawing from a transform feedback object (GL 4.0; ES 3.0 has
 * the objects, not that draw) and sample-count occlusion queries
 * (GL_SAMPLES_PASSED): ES answers only whether any passed, which is
 * ANY_SAMPLES_QUERY. */
typedef struct es_rule {
    int version;            /* ES major * 10 + minor, 0 = never core */
    const char *extensions; /* any one of them gives it */
    const char *also;       /* NULL, or one that must be listed too */
} es_rule;

static const es_rule es_rules[STIN_CAP_COUNT] = {
    [STIN_CAP_STENCIL] = {20, "", NULL},
    [STIN_CAP_MULTITEXTURE] = {20, "", NULL},
    [STIN_CAP_TEXTURE_CUBE_MAP] = {20, "", NULL},
    [STIN_CAP_DEPTH_TEXTURE] = {30, "GL_OES_depth_texture", NULL},
    [STIN_CAP_SHADOW] = {30, "GL_EXT_shadow_samplers", NULL},
    [STIN_CAP_STENCIL_WRAP] = {20, "", NULL},
    [STIN_CAP_SEPARATE_STENCIL] = {20, "", NULL},
    [STIN_CAP_VBO] = {20, "", NULL},
    [STIN_CAP_GLSL] = {20, "", NULL},
    [STIN_CAP_FBO] = {20, "", NULL},
    [STIN_CAP_FLOAT_TEXTURE] = {30, "", "GL_EXT_color_buffer_float"},
    [STIN_CAP_VAO] = {30, "GL_OES_vertex_array_object", NULL},
    [STIN_CAP_GEOMETRY_SHADER] = {32, "", NULL},
    [STIN_CAP_TESSELLATION] = {32, "", NULL},
    [STIN_CAP_COMPUTE] = {31, "", NULL},
    [STIN_CAP_PACKED_DEPTH_STENCIL] = {30, "GL_OES_packed_depth_stencil", NULL},
    [STIN_CAP_ELEMENT_INDEX_UINT] = {30, "GL_OES_element_index_uint", NULL},
    [STIN_CAP_FRAG_DEPTH] = {30, "GL_EXT_frag_depth", NULL},
    [STIN_CAP_DERIVATIVES] = {30, "GL_OES_standard_derivatives", NULL},
    /* "did any sample pass" is all stin asks of a query (peel and deep
     * stops, CSG's merge and overflow tests): core in ES 3.0 (ES 2.0's
     * EXT_occlusion_query_boolean names its entry points ...EXT, which
     * stin does not load) */
    [STIN_CAP_ANY_SAMPLES_QUERY] = {30, "", NULL},
    /* ES 3.2 renders into float targets but blends 32-bit ones only with
     * EXT_float_blend (dual peeling's RG32F MIN/MAX) */
    [STIN_CAP_FLOAT_BLEND] = {0, "GL_EXT_float_blend", "GL_EXT_color_buffer_float"},
};

int stin__token_in_list(const char *list, const char *token, size_t token_len)
{
    const char *p = list;
    if (!list || token_len == 0)
        return 0;
    while (*p) {
        const char *start;
        size_t n = 0;
        while (*p == ' ')
            p++;
        start = p;
        while (*p && *p != ' ') {
            p++;
            n++;
        }
        if (n == token_len) {
            size_t i = 0;
            while (i < n && start[i] == token[i])
                i++;
            if (i == n)
                return 1;
        }
    }
    return 0;
}

/* "4.5 (Core Profile) Mesa 22.3.6" -> 4, 5; vendor prefixes such as "OpenGL ES"
 * are skipped by starting at the first digit. */
static int parse_version(const char *s, int *major, int *minor)
{
    int a = 0, b = 0;
    if (!s)
        return 0;
    while (*s && (*s < '0' || *s > '9'))
        s++;
    if (!*s)
        return 0;
    while (*s >= '0' && *s <= '9')
        a = a * 10 + (*s++ - '0');
    if (*s != '.')
        return 0;
    s++;
    if (*s < '0' || *s > '9')
        return 0;
    b = *s - '0'; /* one digit: "1.20" is GLSL 1.2(0) */
    *major = a;
    *minor = b;
    return 1;
}

/* Which list an extension token is looked up in. */
enum { EXT_DESKTOP, EXT_ES, EXT_ES_ALSO };

static const char *ext_list(int c, int which)
{
    if (which == EXT_DESKTOP)
        return cap_extensions[c];
    return which == EXT_ES ? es_rules[c].extensions : es_rules[c].also;
}

static void mark_extension(uint64_t *bits, const char *tok, size_t len, int which)
{
    int c;
    for (c = 0; c < STIN_CAP_COUNT; c++)
        if (stin__token_in_list(ext_list(c, which), tok, len))
            *bits |= STIN_CAP_BIT(c);
}

static uint64_t extension_bits(const stin__caps_input *in, int which)
{
    uint64_t bits = 0;
    if (in->extension_at) {
        int i;
        for (i = 0; i < in->extension_count; i++) {
            const char *t = in->extension_at(in->extension_user, i);
            size_t n = 0;
            if (!t)
                continue;
            while (t[n])
                n++;
            mark_extension(&bits, t, n, which);
        }
    } else if (in->extensions) {
        const char *p = in->extensions;
        while (*p) {
            const char *start;
            while (*p == ' ')
                p++;
            start = p;
            while (*p && *p != ' ')
                p++;
            if (p > start)
                mark_extension(&bits, start, (size_t)(p - start), which);
        }
    }
    return bits;
}

/* Entry points every capability needs, from the table's "needs" column. */
static uint64_t caps_missing_entry_points(const unsigned char *loaded, int es)
{
    uint64_t missing = 0;
    int i;
    if (!loaded)
        return 0;
    for (i = 0; i < STIN_GLFN_COUNT; i++) {
        int need = stin__glfn_need((stin__glfn)i);
        if (es && stin__glfn_es_exempt((stin__glfn)i))
            continue; /* ES runs their capabilities without them */
        if (!loaded[i] && need < STIN_CAP_COUNT)
            missing |= STIN_CAP_BIT(need);
        /* the query objects' entry points serve both kinds of query */
        if (!loaded[i] && need == STIN_CAP_OCCLUSION_QUERY)
            missing |= STIN_CAP_BIT(STIN_CAP_ANY_SAMPLES_QUERY);
    }
    return missing;
}

/* "OpenGL ES 3.2 Mesa ..." (and "OpenGL ES-CM 1.1" for ES 1.x). */
static int is_es(const char *s)
{
    const char *p = "OpenGL ES";
    while (*p && s && *s == *p) {
        s++;
        p++;
    }
    return !*p;
}

/* "OpenGL ES 3.0 (WebGL 2.0 (...))": emscripten's GL_VERSION on WebGL. */
static int is_webgl(const char *s)
{
    static const char key[] = "(WebGL ";
    size_t i;
    for (; s && *s; s++) {
        for (i = 0; key[i] && s[i] == key[i]; i++)
            ;
        if (!key[i])
            return 1;
    }
    return 0;
}

/* The GLSL ES version each ES version ships with: 2.0 -> 1.00, 3.x -> 3.x0. */
static int es_glsl_cap(int ver)
{
    return ver >= 30 ? ver : ver >= 20 ? 10 : 0;
}

static uint64_t es_bits(const stin__caps_input *in, int ver)
{
    uint64_t have = 0, ext = extension_bits(in, EXT_ES), also = extension_bits(in, EXT_ES_ALSO);
    int c;
    for (c = 0; c < STIN_CAP_COUNT; c++) {
        const es_rule *r = &es_rules[c];
        int got = (r->version > 0 && ver >= r->version) || (ext & STIN_CAP_BIT(c));
        if (got && (!r->also || (also & STIN_CAP_BIT(c))))
            have |= STIN_CAP_BIT(c);
    }
    return have;
}

static uint64_t desktop_bits(const stin__caps_input *in, int ver)
{
    uint64_t have = 0, ext = extension_bits(in, EXT_DESKTOP);
    int c;
    for (c = 0; c < STIN_CAP_COUNT; c++) {
        int min = cap_min_version[c];
        if ((min > 0 && ver >= min) || (ext & STIN_CAP_BIT(c)))
            have |= STIN_CAP_BIT(c);
    }
    return have;
}

int stin__caps_parse(const stin__caps_input *in, stin_caps *out)
{
    int ver, glsl, es;
    uint64_t have;
    if (!parse_version(in->version, &out->gl_major, &out->gl_minor))
        return 0;
    es = out->es = is_es(in->version);
    out->webgl = es && is_webgl(in->version);
    ver = out->gl_major * 10 + out->gl_minor;
    if (in->max_gl_version > 0 && ver > in->max_gl_version) {
        ver = in->max_gl_version;
        out->gl_major = ver / 10;
        out->gl_minor = ver % 10;
    }
    out->glsl_major = out->glsl_minor = 0;
    if (ver >= 20 && parse_version(in->glsl_version, &out->glsl_major, &out->glsl_minor)) {
        /* GLSL follows the GL version it ships with: 2.0 -> 1.10, 3.2 -> 1.50, 3.3+ -> same */
        int cap = es ? es_glsl_cap(ver)
                     : ver >= 33 ? ver : ver == 32 ? 15 : ver == 31 ? 14 : ver == 30 ? 13
                     : ver == 21 ? 12 : 11;
        if (out->glsl_major * 10 + out->glsl_minor > cap) {
            out->glsl_major = cap / 10;
            out->glsl_minor = cap % 10;
        }
    }
    glsl = out->glsl_major * 10 + out->glsl_minor;
    /* ES has one profile, without fixed function: "compatibility" is not it */
    out->profile = in->core_profile || es ? STIN_GL_PROFILE_CORE : STIN_GL_PROFILE_COMPATIBILITY;
    have = es ? es_bits(in, ver) : desktop_bits(in, ver);
    /* Capabilities that are not a plain version-or-extension rule. */
    have &= ~(STIN_CAP_BIT(STIN_CAP_GLSL) | STIN_CAP_BIT(STIN_CAP_GEOMETRY_SHADER) |
              STIN_CAP_BIT(STIN_CAP_GLSL_150) | STIN_CAP_BIT(STIN_CAP_FIXED_FUNCTION) | STIN_CAP_BIT(STIN_CAP_VERTEX_TEXTURE_FETCH));
    if (ver >= 20 && glsl >= (es ? 10 : 11)) /* GLSL ES 1.00 reads 1.0 */
        have |= STIN_CAP_BIT(STIN_CAP_GLSL);
    if (ver >= 32 && glsl >= (es ? 32 : 15))
        have |= STIN_CAP_BIT(STIN_CAP_GEOMETRY_SHADER);
    /* the GL4 tier's sources: #version 150, or GLSL ES 3.00 and later */
    if (ver >= (es ? 30 : 32) && glsl >= (es ? 30 : 15))
        have |= STIN_CAP_BIT(STIN_CAP_GLSL_150);
    if (!in->core_profile && !es)
        have |= STIN_CAP_BIT(STIN_CAP_FIXED_FUNCTION);
    have &= ~caps_missing_entry_points(in->loaded, es);
    if (!(have & STIN_CAP_BIT(STIN_CAP_GLSL))) /* geometry shaders, derivatives, frag depth are GLSL's */
        have &= ~(STIN_CAP_BIT(STIN_CAP_GEOMETRY_SHADER) | STIN_CAP_BIT(STIN_CAP_GLSL_150) |
                  STIN_CAP_BIT(STIN_CAP_DERIVATIVES) |
                  STIN_CAP_BIT(STIN_CAP_FRAG_DEPTH));
    /* WebGL hands a query's result over only once control is back in the
     * browser's event loop: read within the frame it says "nothing passed"
     * (depth-peel then stopped after one layer and drew no blended draw) */
    if (out->webgl)
        have &= ~STIN_CAP_BIT(STIN_CAP_ANY_SAMPLES_QUERY);
    out->hidden = have & in->caps_mask;
    out->present = have & ~in->caps_mask;
    /* desktop answers "any passed" with its sample counts: what hides
     * those hides it; nothing blends into float targets it cannot render */
    if (!es && !(out->present & STIN_CAP_BIT(STIN_CAP_OCCLUSION_QUERY)))
        out->present &= ~STIN_CAP_BIT(STIN_CAP_ANY_SAMPLES_QUERY);
    if (!(out->present & STIN_CAP_BIT(STIN_CAP_FLOAT_TEXTURE)))
        out->present &= ~STIN_CAP_BIT(STIN_CAP_FLOAT_BLEND);
    return 1;
}

/* ---- detection against the live context --------------------------------- */
typedef struct stringi_user {
    const stin__gl *gl;
} stringi_user;

static const char *ext_at(void *user, int i)
{
    const stringi_user *u = (const stringi_user *)user;
    return (const char *)u->gl->GetStringi(GL_EXTENSIONS, (GLuint)i);
}

static int get_int(const stin__gl *gl, GLenum e)
{
    GLint v = 0;
    gl->GetIntegerv(e, &v);
    return v;
}

static void copy_text(char *dst, size_t size, const char *src)
{
    size_t i = 0;
    if (src)
        for (; src[i] && i + 1 < size; i++)
            dst[i] = src[i];
    dst[i] = '\0';
}

/* What the context has, the caps mask aside: a limit is queried only where
 * the version or a listed extension defines it (an unknown one is a GL error,
 * and stin raises none). */
static int has(const stin_caps *caps, stin_cap cap)
{
    return ((caps->present | caps->hidden) & STIN_CAP_BIT(cap)) != 0;
}

/* ES: no fixed-function limits (lights, units, clip planes) and no draw
 * buffers before 3.0; uniform space is counted in vectors. */
static void detect_es_limits(const stin__gl *gl, stin_caps *caps, int reported_version)
{
    caps->max_texture_size = get_int(gl, GL_MAX_TEXTURE_SIZE);
    gl->GetIntegerv(GL_MAX_VIEWPORT_DIMS, caps->max_viewport_dims);
    stin__framebuffer_bits(gl, 0, 0, &caps->stencil_bits, &caps->depth_bits);
    caps->max_texture_units = 1;
    if (reported_version < 20)
        return;
    caps->max_texture_image_units = get_int(gl, GL_MAX_TEXTURE_IMAGE_UNITS);
    caps->max_vertex_texture_units = get_int(gl, GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS);
    caps->max_vertex_uniform_vectors = get_int(gl, GL_MAX_VERTEX_UNIFORM_VECTORS);
    caps->max_fragment_uniform_vectors = get_int(gl, GL_MAX_FRAGMENT_UNIFORM_VECTORS);
    caps->max_draw_buffers = reported_version >= 30 ? get_int(gl, GL_MAX_DRAW_BUFFERS) : 1;
    if (reported_version >= 32)
        caps->max_geometry_output_vertices = get_int(gl, GL_MAX_GEOMETRY_OUTPUT_VERTICES);
    if (has(caps, STIN_CAP_TESSELLATION))
        caps->max_tess_gen_level = get_int(gl, GL_MAX_TESS_GEN_LEVEL);
}

static void detect_limits(const stin__gl *gl, stin_caps *caps, int reported_version)
{
    int core = caps->profile == STIN_GL_PROFILE_CORE;
    if (caps->es) {
        detect_es_limits(gl, caps, reported_version);
        return;
    }
    caps->max_texture_size = get_int(gl, GL_MAX_TEXTURE_SIZE);
    gl->GetIntegerv(GL_MAX_VIEWPORT_DIMS, caps->max_viewport_dims); /* GL 1.0: two values */
    caps->max_clip_planes = get_int(gl, GL_MAX_CLIP_PLANES);
    if (!core) {
        stin__framebuffer_bits(gl, 0, 0, &caps->stencil_bits, &caps->depth_bits);
        caps->max_lights = get_int(gl, GL_MAX_LIGHTS);
        caps->max_texture_units = has(caps, STIN_CAP_MULTITEXTURE)
                                      ? get_int(gl, GL_MAX_TEXTURE_UNITS)
                                      : 1;
    } else if (gl->GetFramebufferAttachmentParameteriv && gl->BindFramebuffer) {
        stin__framebuffer_bits(gl, 1, (GLuint)get_int(gl, GL_DRAW_FRAMEBUFFER_BINDING),
                               &caps->stencil_bits, &caps->depth_bits);
    }
    if (caps->max_texture_units < 1)
        caps->max_texture_units = 1;
    if (reported_version >= 20 && gl->CreateShader) {
        caps->max_texture_image_units = get_int(gl, GL_MAX_TEXTURE_IMAGE_UNITS);
        caps->max_vertex_texture_units = get_int(gl, GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS);
        caps->max_draw_buffers = get_int(gl, GL_MAX_DRAW_BUFFERS);
        /* GL 2.0 counts components; ES (and this field) vectors of four */
        caps->max_vertex_uniform_vectors = get_int(gl, GL_MAX_VERTEX_UNIFORM_COMPONENTS) / 4;
        caps->max_fragment_uniform_vectors = get_int(gl, GL_MAX_FRAGMENT_UNIFORM_COMPONENTS) / 4;
    }
    if (reported_version >= 32)
        caps->max_geometry_output_vertices = get_int(gl, GL_MAX_GEOMETRY_OUTPUT_VERTICES);
    if (has(caps, STIN_CAP_TESSELLATION))
        caps->max_tess_gen_level = get_int(gl, GL_MAX_TESS_GEN_LEVEL);
}

stin_result stin__caps_detect(const stin__gl *gl, const unsigned char *loaded,
                              uint64_t caps_mask, int max_gl_version, stin_caps *caps)
{
    stin__caps_input in;
    stringi_user su;
    int major = 0, minor = 0, reported, es;
    stin__memzero(caps, sizeof *caps);
    stin__memzero(&in, sizeof in);
    if (!gl->GetString || !gl->GetIntegerv)
        return STIN_ERROR_GL;
    in.version = (const char *)gl->GetString(GL_VERSION);
    if (!parse_version(in.version, &major, &minor))
        return STIN_ERROR_GL;
    reported = major * 10 + minor;
    es = is_es(in.version);
    if (reported >= 20)
        in.glsl_version = (const char *)gl->GetString(GL_SHADING_LANGUAGE_VERSION);
    if (reported >= 32 && !es) { /* ES has no profile mask */
        GLint mask = 0;
        gl->GetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
        in.core_profile = (mask & GL_CONTEXT_CORE_PROFILE_BIT) != 0;
    }
    if (reported >= 30 && gl->GetStringi) {
        su.gl = gl;
        in.extension_at = ext_at;
        in.extension_user = &su;
        in.extension_count = get_int(gl, GL_NUM_EXTENSIONS);
    } else {
        in.extensions = (const char *)gl->GetString(GL_EXTENSIONS);
    }
    in.max_gl_version = max_gl_version;
    in.caps_mask = caps_mask;
    in.loaded = loaded;
    if (!stin__caps_parse(&in, caps))
        return STIN_ERROR_GL;
    copy_text(caps->renderer, sizeof caps->renderer, (const char *)gl->GetString(GL_RENDERER));
    detect_limits(gl, caps, reported);
    if (caps->stencil_bits <= 0)
        caps->present &= ~STIN_CAP_BIT(STIN_CAP_STENCIL);
    if (((caps->present | caps->hidden) & STIN_CAP_BIT(STIN_CAP_GLSL)) &&
        caps->max_vertex_texture_units > 0) {
        if (caps_mask & STIN_CAP_BIT(STIN_CAP_VERTEX_TEXTURE_FETCH))
            caps->hidden |= STIN_CAP_BIT(STIN_CAP_VERTEX_TEXTURE_FETCH);
        else if (caps->present & STIN_CAP_BIT(STIN_CAP_GLSL))
            caps->present |= STIN_CAP_BIT(STIN_CAP_VERTEX_TEXTURE_FETCH);
    }
    if (!(caps->present & STIN_CAP_BIT(STIN_CAP_FIXED_FUNCTION)))
        caps->max_lights = 0;
    return STIN_OK;
}

stin_result stin_detect_caps(stin_get_proc_fn get_proc, void *user, uint64_t caps_mask,
                             int max_gl_version, stin_caps *out)
{
    stin__gl gl;
    unsigned char loaded[STIN_GLFN_COUNT];
    if (!get_proc || !out)
        return STIN_ERROR_INVALID_ARGUMENT;
    stin__gl_load(&gl, get_proc, user, loaded);
    return stin__caps_detect(&gl, loaded, caps_mask, max_gl_version, out);
}

int stin_query_extension(const stin_context *ctx, const char *name)
{
    size_t n = 0;
    if (!ctx || !name)
        return 0;
    while (name[n])
        n++;
    if (ctx->caps.gl_major >= 3 && ctx->gl.GetStringi) { /* desktop 3.0+ and ES 3.0+ */
        GLint count = 0, i;
        STIN_GL_DRIVER(ctx)->GetIntegerv(GL_NUM_EXTENSIONS, &count);
        for (i = 0; i < count; i++) {
            const char *t = (const char *)ctx->gl.GetStringi(GL_EXTENSIONS, (GLuint)i);
            if (t && stin__token_in_list(t, name, n))
                return 1;
        }
        return 0;
    }
    return stin__token_in_list((const char *)ctx->gl.GetString(GL_EXTENSIONS), name, n);
}
