/* SPDX-License-Identifier: MIT */
/*
 * The GL-error property of every image test (see gl_errors.h). Linked with
 * -Wl,--wrap=NAME for each function of STIN_CALLS (STIN_CALL_WRAP in the
 * Makefile): the linker sends the tests' and the tools' calls to
 * __wrap_NAME, which counts the depth of stin calls around __real_NAME. A
 * name in one list and not the other fails the link.
 *
 * A message counts when its type is an error or undefined behaviour, or
 * its severity is high (Mesa's "user error" is GL_DEBUG_TYPE_ERROR, high);
 * performance and other notes do not, nor the shader compiler's warnings
 * (Mesa gives them high severity, but only when a program is compiled
 * rather than found in its shader cache, so they come and go with the
 * cache; a shader that fails to compile fails stin_create).
 */
#include "gl_errors.h"
#include "stin/stin_debug.h"

#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <string.h>

/* Every public function that takes a context (or loads GL itself): value
 * returning (X) and void (V). */
#define STIN_CALLS(X, V)                                                                       \
    X(stin_result, stin_create, (const stin_desc *a, void *b, size_t c, stin_context **d),       \
      (a, b, c, d))                                                                            \
    V(stin_destroy, (stin_context * a), (a))                                                   \
    X(stin_desc, stin_query_desc, (const stin_context *a), (a))                                \
    X(const stin_caps *, stin_query_caps, (const stin_context *a), (a))                        \
    X(stin_tier, stin_query_tier, (const stin_context *a), (a))                                \
    X(stin_choice, stin_query_choice, (const stin_context *a, stin_feature b), (a, b))         \
    X(stin_result, stin_detect_caps,                                                           \
      (stin_get_proc_fn a, void *b, uint64_t c, int d, stin_caps *e), (a, b, c, d, e))         \
    X(int, stin_query_extension, (const stin_context *a, const char *b), (a, b))               \
    X(stin_result, stin_create_mesh, (stin_context * a, const stin_mesh_desc *b, stin_mesh *c), \
      (a, b, c))                                                                               \
    X(stin_result, stin_query_mesh_info,                                                       \
      (const stin_context *a, stin_mesh b, stin_mesh_info *c), (a, b, c))                      \
    X(stin_result, stin_query_mesh_adjacency,                                                  \
      (const stin_context *a, stin_mesh b, uint32_t c, uint32_t d[3]), (a, b, c, d))           \
    X(stin_result, stin_query_mesh_tangent,                                                    \
      (const stin_context *a, stin_mesh b, uint32_t c, float d[4]), (a, b, c, d))              \
    V(stin_destroy_mesh, (stin_context * a, stin_mesh b), (a, b))                              \
    X(stin_result, stin_update_mesh,                                                           \
      (stin_context * a, stin_mesh b, const stin_mesh_update_desc *c), (a, b, c))              \
    X(stin_result, stin_create_texture,                                                        \
      (stin_context * a, const stin_texture_desc *b, stin_texture *c), (a, b, c))              \
    V(stin_destroy_texture, (stin_context * a, stin_texture b), (a, b))                        \
    X(stin_result, stin_begin_frame, (stin_context * a, const stin_frame_desc *b), (a, b))     \
    X(stin_result, stin_add_light, (stin_context * a, const stin_light_desc *b), (a, b))       \
    X(stin_result, stin_draw,                                                                  \
      (stin_context * a, stin_mesh b, const float c[16], const stin_material *d), (a, b, c, d)) \
    X(stin_result, stin_end_frame, (stin_context * a), (a))                                    \
    X(stin_result, stin_draw_csg, (stin_context * a, const stin_csg_desc *b), (a, b))          \
    X(uint32_t, stin_query_csg_terms,                                                          \
      (const stin_context *a, uint32_t b, uint32_t c, uint32_t *d, uint32_t e, uint32_t *f),   \
      (a, b, c, d, e, f))                                                                      \
    X(stin_frame_stats, stin_query_frame_stats, (const stin_context *a), (a))                  \
    V(stin_query_frame_projection, (const stin_context *a, float b[16]), (a, b))               \
    X(stin_result, stin_query_visibility_map, (const stin_context *a, stin_visibility_map *b),  \
      (a, b))                                                                                  \
    X(stin_result, stin_bind_visibility, (stin_context * a, int b), (a, b))                    \
    X(stin_debug_counters, stin_debug_query_counters, (const stin_context *a), (a))            \
    X(stin_result, stin_debug_query_shadow_map,                                                \
      (const stin_context *a, uint32_t b, stin_debug_map *c), (a, b, c))

#define KEPT_MESSAGES 3

static struct {
    int depth, arming;
    const char *call;                  /* the outermost stin call now */
    unsigned pending, distinct, outside, armed_seen;
    char text[KEPT_MESSAGES * 240]; /* the first distinct pending messages */
    char first_outside[200];
    char last_line[192];               /* the name of the last result line */
} st;

static void enter(const char *name)
{
    if (st.depth++ == 0)
        st.call = name;
}

static void leave(void) { st.depth--; }

#define DECLARE_X(ret, name, params, args) ret __real_##name params; ret __wrap_##name params;
#define DECLARE_V(name, params, args) void __real_##name params; void __wrap_##name params;
#define WRAP_X(ret, name, params, args)                                                        \
    ret __wrap_##name params                                                                   \
    {                                                                                          \
        ret v;                                                                                 \
        enter(#name);                                                                          \
        v = __real_##name args;                                                                \
        leave();                                                                               \
        return v;                                                                              \
    }
#define WRAP_V(name, params, args)                                                             \
    void __wrap_##name params                                                                  \
    {                                                                                          \
        enter(#name);                                                                          \
        __real_##name args;                                                                    \
        leave();                                                                               \
    }
STIN_CALLS(DECLARE_X, DECLARE_V)
STIN_CALLS(WRAP_X, WRAP_V)

static void GLAPIENTRY on_message(GLenum source, GLenum type, GLuint id, GLenum severity,
                                  GLsizei length, const GLchar *message, const void *user)
{
    char one[232];
    size_t used;
    (void)id;
    (void)length;
    (void)user;
    if (type != GL_DEBUG_TYPE_ERROR && type != GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR &&
        severity != GL_DEBUG_SEVERITY_HIGH)
        return;
    if (source == GL_DEBUG_SOURCE_SHADER_COMPILER && type != GL_DEBUG_TYPE_ERROR)
        return;
    if (st.arming) {
        st.armed_seen++;
        return;
    }
    if (!st.depth) {
        if (!st.outside++)
            snprintf(st.first_outside, sizeof st.first_outside, "%s", message);
        return;
    }
    st.pending++;
    snprintf(one, sizeof one, "[%s] %.200s", st.call, message);
    if (strstr(st.text, one))
        return;
    used = strlen(st.text);
    if (st.distinct++ < KEPT_MESSAGES)
        snprintf(st.text + used, sizeof st.text - used, "%s%s", used ? "; " : "", one);
}

/* GL_KHR_debug in the extension list, read the way the context allows. */
static int lists_khr_debug(stin_platform *p, int version)
{
    typedef const GLubyte *(GLAPIENTRY * get_string_fn)(GLenum);
    typedef const GLubyte *(GLAPIENTRY * get_stringi_fn)(GLenum, GLuint);
    typedef void(GLAPIENTRY * get_integerv_fn)(GLenum, GLint *);
    get_string_fn get_string = (get_string_fn)stin_platform_get_proc_address(p, "glGetString");
    get_stringi_fn get_stringi =
        (get_stringi_fn)stin_platform_get_proc_address(p, "glGetStringi");
    get_integerv_fn get_integerv =
        (get_integerv_fn)stin_platform_get_proc_address(p, "glGetIntegerv");
    const char *list, *at;
    GLint i, n = 0;
    if (version >= 30 && get_stringi && get_integerv) {
        get_integerv(GL_NUM_EXTENSIONS, &n);
        for (i = 0; i < n; i++)
            if (!strcmp((const char *)get_stringi(GL_EXTENSIONS, (GLuint)i), "GL_KHR_debug"))
                return 1;
        return 0;
    }
    list = get_string ? (const char *)get_string(GL_EXTENSIONS) : NULL;
    for (at = list; at && (at = strstr(at, "GL_KHR_debug")); at += 12)
        if ((at == list || at[-1] == ' ') && (at[12] == ' ' || at[12] == '\0'))
            return 1;
    return 0;
}

void gl_errors_arm(run *r)
{
    typedef const GLubyte *(GLAPIENTRY * get_string_fn)(GLenum);
    typedef void(GLAPIENTRY * enable_fn)(GLenum);
    typedef GLenum(GLAPIENTRY * get_error_fn)(void);
    get_string_fn get_string =
        (get_string_fn)stin_platform_get_proc_address(r->plat, "glGetString");
    enable_fn enable = (enable_fn)stin_platform_get_proc_address(r->plat, "glEnable");
    get_error_fn get_error = (get_error_fn)stin_platform_get_proc_address(r->plat, "glGetError");
    PFNGLDEBUGMESSAGECALLBACKPROC set_callback = (PFNGLDEBUGMESSAGECALLBACKPROC)
        stin_platform_get_proc_address(r->plat, "glDebugMessageCallback");
    const char *v = get_string ? (const char *)get_string(GL_VERSION) : NULL;
    int major = 0, minor = 0, version;
    if (v && !strncmp(v, "OpenGL ES ", 10)) /* KHR_debug is listed on every ES version */
        v += 10;
    if (!v || sscanf(v, "%d.%d", &major, &minor) != 2 || !enable || !get_error) {
        report(r, "SKIP", "gl-errors", "GL errors are not checked: no GL version string");
        return;
    }
    version = 10 * major + minor;
    if ((version < 43 && !lists_khr_debug(r->plat, version)) || !set_callback) {
        report(r, "SKIP", "gl-errors",
               "GL errors are not checked: GL %d.%d without GL_KHR_debug has no debug callback",
               major, minor);
        return;
    }
    set_callback(on_message, NULL);
    enable(GL_DEBUG_OUTPUT);
    enable(GL_DEBUG_OUTPUT_SYNCHRONOUS); /* the message inside the call that raised it */
    st.arming = 1;
    enable(0); /* GL_INVALID_ENUM, the test's own */
    st.arming = 0;
    get_error();
    if (st.armed_seen)
        report(r, "PASS", "gl-errors",
               "KHR_debug callback armed on GL %d.%d: a deliberate glEnable(0) was reported; any "
               "error stin raises fails the test whose line follows",
               major, minor);
    else
        report(r, "SKIP", "gl-errors",
               "GL errors are not checked: GL_KHR_debug delivered no message for a deliberate "
               "glEnable(0)");
}

void gl_errors_flush(run *r, const char *next)
{
    char name[256], text[sizeof st.text], previous[sizeof st.last_line];
    unsigned n = st.pending, distinct = st.distinct;
    snprintf(previous, sizeof previous, "%s", st.last_line);
    snprintf(st.last_line, sizeof st.last_line, "%s", next);
    if (!n)
        return;
    snprintf(text, sizeof text, "%s", st.text);
    st.pending = st.distinct = 0;
    st.text[0] = '\0';
    snprintf(name, sizeof name, "%s/gl-errors", next);
    report(r, "FAIL", name, "%u GL error message%s during stin calls since the line %s: %s%s", n,
           n == 1 ? "" : "s", previous[0] ? previous : "(none)", text,
           distinct > KEPT_MESSAGES ? "; and more" : "");
    snprintf(st.last_line, sizeof st.last_line, "%s", next);
}

void gl_errors_finish(run *r)
{
    gl_errors_flush(r, "end");
    if (st.outside)
        fprintf(stderr,
                "stin-imagetest: %u GL error messages from the tests' own calls outside stin "
                "(not stin's; first: %s)\n",
                st.outside, st.first_outside);
}
