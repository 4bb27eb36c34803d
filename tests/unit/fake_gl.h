/* SPDX-License-Identifier: MIT */
/* A fake OpenGL for unit tests: every entry point of src/gl_funcs.h as a stub
 * that records what stin asked for. No GL, no window, no heap.
 *
 *     fake_gl_config cfg = fake_gl_profile(FAKE_GL21);
 *     cfg.max_lights = 2;                      // tweak what the driver reports
 *     fake_gl_reset(&cfg);                     // installs cfg, zeroes the counters
 *     desc.get_proc_address = fake_gl_get_proc;
 *     ... stin calls ...
 *     assert_int_equal(fake_gl.textures_created, fake_gl.textures_deleted);
 *
 * fake_gl.gl is the GL state the calls left (fake_gl_state.h); link
 * fake_gl_state.c too.
 * The config is copied by fake_gl_reset; the strings it points to must stay
 * alive while the fake is used. Compile with -Isrc (uses gl_types.h). */
#ifndef FAKE_GL_H
#define FAKE_GL_H

#include "internal.h"
#include "fake_gl_state.h"

/* A framebuffer object of the caller's: its bits and status (0: complete). */
typedef struct fake_gl_fbo {
    GLuint name;
    int stencil_bits, depth_bits;
    GLenum status;
} fake_gl_fbo;

typedef struct fake_gl_config {
    const char *version;                 /* GL_VERSION; NULL makes glGetString return NULL */
    const char *glsl_version;            /* GL_SHADING_LANGUAGE_VERSION, NULL = none */
    const char *extensions;              /* GL_EXTENSIONS (space separated), NULL = none */
    const char *const *extension_list;   /* glGetStringi(GL_EXTENSIONS, i) */
    int extension_count;                 /* GL_NUM_EXTENSIONS */
    int core_profile;                    /* GL_CONTEXT_PROFILE_MASK reports core */
    int max_lights, stencil_bits, depth_bits, max_texture_size, max_texture_units;
    int max_texture_image_units, max_vertex_texture_units, max_draw_buffers;
    int max_geometry_output_vertices;
    int max_tess_gen_level;
    const char *const *missing;          /* NULL-terminated names ("glGenBuffers") that do not resolve */
    int fail_glsl_from;                  /* shaders with "#version N", N >= this, fail to
                                          * compile (e.g. 150); 0 = every shader compiles */
    int fail_link;                       /* every program fails to link */
    unsigned fail_link_from;             /* programs from the Nth made on fail to link (0: none) */
    /* The caller's framebuffer objects: bound, their bits are what
     * GL_STENCIL_BITS/GL_DEPTH_BITS and the attachment queries report and
     * their status what glCheckFramebufferStatus does. Other names made by
     * glGen* are complete framebuffers with the default's bits; names never
     * made are not framebuffers (glIsFramebuffer). */
    fake_gl_fbo *framebuffers;
    int framebuffer_count;
    GLenum generated_framebuffer_status; /* of the ones stin makes: 0 complete */
    int sample_buffers;                  /* GL_SAMPLE_BUFFERS of every framebuffer */
    unsigned long long max_array_bytes;  /* largest array texture a proxy takes; 0 = any */
} fake_gl_config;

/* Configs shaped like the emulation profiles of DESIGN.md. */
typedef enum fake_gl_profile_id {
    FAKE_GL11,      /* 1.1, no extensions */
    FAKE_GL13,      /* 1.3 + combine/dot3, no depth textures */
    FAKE_GL14,      /* 1.4 + ARB_shadow, two-sided stencil, wrap, depth clamp */
    FAKE_GL21,      /* 2.1 compatibility, GLSL 1.20, FBO */
    FAKE_GL33_CORE, /* 3.3 core, GLSL 3.30 */
    FAKE_GL45_CORE  /* 4.5 core, GLSL 4.50 */
} fake_gl_profile_id;

fake_gl_config fake_gl_profile(fake_gl_profile_id id);

/* What the stubs saw since the last fake_gl_reset. */
#define FAKE_GL_MAX_LEVELS 16
#define FAKE_GL_MAX_SHADERS 64
#define FAKE_GL_MAX_PROGRAMS 2048
#define FAKE_GL_MAX_VAOS 64
#define FAKE_GL_MAX_QUERIES 1024
typedef struct fake_gl_state {
    fake_gl_config config;
    unsigned calls[STIN_GLFN_COUNT];     /* per entry point, index STIN_GLFN_<Name> */
    unsigned draw_calls, drawn_indices;
    unsigned uint_index_draws, ushort_index_draws; /* glDrawElements by index type */
    unsigned patch_draws;                /* draw calls of GL_PATCHES (tessellated) */
    unsigned draws_into_default;         /* draw calls while framebuffer 0 was bound */
    GLuint watched_framebuffer;          /* a test's choice (0 until it sets one) */
    unsigned draws_into_watched;         /* draw calls while that one was bound */
    unsigned depth_draws_into_watched;   /* of those, with depth tested and written */
    unsigned textures_created, textures_deleted;
    unsigned buffers_created, buffers_deleted;
    /* the latest glBufferData into GL_ARRAY_BUFFER: the buffer bound, the
     * bytes, the usage, an FNV-1a (64-bit) hash of the data, and
     * how many there were */
    struct {
        GLuint buffer;
        unsigned long long size, hash;
        GLenum usage;
        unsigned uploads;
    } array_data;
    unsigned vertex_arrays_created, vertex_arrays_deleted;
    unsigned shaders_created, shaders_deleted, shader_compile_failures;
    unsigned programs_created, programs_deleted, program_link_failures;
    unsigned deletes_of_zero;            /* glDelete* of name 0 (harmless, but suspicious) */
    /* glTexImage2D: the mip chain of the most recent level-0 upload. */
    GLsizei proxy_width;                 /* of the last proxy array texture (0: refused) */
    GLsizei array_width;                 /* of the last array texture made */
    unsigned tex_images;                 /* calls in total */
    unsigned tex_images_loose;           /* calls made while fake_gl_unpack_loose() */
    unsigned tex_levels;                 /* levels of the latest chain */
    int tex_level_width[FAKE_GL_MAX_LEVELS], tex_level_height[FAKE_GL_MAX_LEVELS];
    unsigned char tex_level_first_texel[FAKE_GL_MAX_LEVELS][4]; /* RGBA of texel (0, 0) */
    unsigned framebuffers_created, framebuffers_deleted;
    unsigned transform_feedbacks_created, transform_feedbacks_deleted;
    /* shader objects: "#version" of each, by name - 1 */
    int shader_version[FAKE_GL_MAX_SHADERS];
    /* whether shader name - 1 is a tessellation control stage, and program
     * name - 1001 has one attached: only such a program has tess.tesc's
     * uniforms (u_tess*), as a linked GL program has only its stages' */
    unsigned char shader_is_tesc[FAKE_GL_MAX_PROGRAMS], program_has_tesc[FAKE_GL_MAX_PROGRAMS];
    unsigned next_name;
    /* Queries (names 1, 2, ... of their own). GL_TIME_ELAPSED: what a
     * query ending now measured, in ns (a test's callback; NULL: 0 and no
     * result is written back), each query's result by name, and the queries
     * begun and results read; queries_unavailable makes
     * GL_QUERY_RESULT_AVAILABLE answer 0 (results still on the GPU). */
    GLuint64 (*time_elapsed)(void *user);
    void *time_elapsed_user;
    int queries_unavailable;
    GLuint next_query, active_time_query;
    GLuint64 query_ns[FAKE_GL_MAX_QUERIES];
    unsigned time_queries_begun, time_results_read;
    /* GL state (fake_gl_state.h) */
    fake_gl_glstate gl;
    /* glPushAttrib's stack: the whole state and the mask at each push */
    fake_gl_glstate attrib_stack[FAKE_GL_ATTRIB_STACK_DEPTH];
    GLbitfield attrib_mask[FAKE_GL_ATTRIB_STACK_DEPTH];
    unsigned attrib_depth;
    struct {
        GLuint name;
        fake_gl_vao state;
    } vaos[FAKE_GL_MAX_VAOS];            /* named vertex array objects, as first bound */
    int version;                         /* GL_VERSION as 10 * major + minor */
    /* State calls or queries the fake does not model (an enum it does not
     * know), and calls a real GL would refuse (a stack overflow, a unit out
     * of range): counted, the first of each described. */
    unsigned untracked, gl_errors;
    char untracked_what[96], gl_error_what[96];
} fake_gl_state;

extern fake_gl_state fake_gl;

void fake_gl_reset(const fake_gl_config *config);
/* stin_get_proc_fn: resolves "gl<Name>" for every entry point in gl_funcs.h
 * (alternate ARB/EXT names never resolve); `user` is ignored. */
void *fake_gl_get_proc(void *user, const char *name);
/* 1 when glTexImage now would not read tightly packed client rows (any
 * row length or skip, or a pixel unpack buffer bound; alignment is left
 * out: stin's 4-byte texels keep every row aligned). */
int fake_gl_unpack_loose(void);
/* glIsEnabled(cap): per-unit caps (GL_TEXTURE_2D, ...) of the active unit;
 * 0 for a cap the fake does not know. */
int fake_gl_is_enabled(GLenum cap);
/* The first entry point called since fake_gl_reset that is a generated
 * no-op yet not known to leave the tracked state alone ("glFoo"), or NULL:
 * a new state-changing entry point needs a stub in fake_gl_state.c. */
const char *fake_gl_untracked_entry_point(void);

/* A stin_log_fn that records into a fake_log passed as log_user: a count per
 * item and level, and the messages one per line (truncated when full). */
typedef struct fake_log {
    unsigned items[STIN_LOG_ITEM_COUNT];
    unsigned errors, warnings, infos;
    char text[16384];
    size_t used;
} fake_log;

void fake_log_fn(void *user, stin_log_level level, stin_log_item item, const char *message);
/* A zeroed desc on the fake GL; with `log` (emptied) it records the log. */
stin_desc fake_gl_desc(fake_log *log);
/* 1 if a logged message of `item` (STIN_LOG_ITEM_COUNT: any item) contains `s`. */
int fake_log_has(const fake_log *log, stin_log_item item, const char *s);

#endif
