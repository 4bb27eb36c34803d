/* SPDX-License-Identifier: MIT */
/* The application shades with its own GLSL program and stin only computes
 * shadows: a frame with STIN_EXPORT_VISIBILITY_ONLY hands back the light's
 * visibility as a texture, and the application's fragment shader reads it
 * with the chunk from stin_visibility_glsl(). Same scene as egl_shadow.c
 * (example_scene.h), written to the PPM named on the command line.
 *   cc egl_app_shader.c $(pkg-config --cflags --libs stin) -lEGL -lm */
#include "example_egl.h"

/* The shaders' first lines: GLSL 1.20, or GLSL ES 1.00 (OpenGL ES 2.0 and
 * 3.0) with the fragment stage's default precision, which ES asks for. */
static const char desktop_version[] = "#version 120\n";
static const char es_version[] = "#version 100\n";
static const char es_fragment_version[] = "#version 100\n"
                                          "#ifdef GL_FRAGMENT_PRECISION_HIGH\n"
                                          "precision highp float;\n"
                                          "#else\n"
                                          "precision mediump float;\n"
                                          "#endif\n";
static int on_es; /* the context is OpenGL ES (set by main) */

static const char vertex_shader[] =
    "attribute vec3 position;\n"
    "attribute vec3 normal;\n"
    "uniform mat4 view_proj;\n"
    "varying vec3 world_position, world_normal;\n"
    "void main()\n"
    "{\n"
    "    world_position = position;\n"
    "    world_normal = normal;\n"
    "    gl_Position = view_proj * vec4(position, 1.0);\n"
    "}\n";

/* After stin's chunk: Lambert with an ambient term, the light's diffuse
 * part times stin's visibility. */
static const char fragment_main[] =
    "uniform vec3 light_position, albedo;\n"
    "uniform float ambient;\n"
    "varying vec3 world_position, world_normal;\n"
    "void main()\n"
    "{\n"
    "    vec3 l = normalize(light_position - world_position);\n"
    "    float diffuse = max(dot(normalize(world_normal), l), 0.0);\n"
    "    gl_FragColor = vec4(albedo * (ambient + diffuse * stin_visibility(0)), 1.0);\n"
    "}\n";

typedef GLuint(APIENTRYP create_shader_fn)(GLenum type);
typedef void(APIENTRYP clear_fn)(GLbitfield mask);
typedef void(APIENTRYP enable_fn)(GLenum cap);
typedef void(APIENTRYP draw_elements_fn)(GLenum mode, GLsizei count, GLenum type,
                                         const void *indices);

static GLuint build_program(void)
{
    const char *vert[2], *frag[3];
    GLuint p, vs, fs;
    GLint ok = 0;
    LOAD(create_shader_fn, glCreateShader);
    LOAD(PFNGLSHADERSOURCEPROC, glShaderSource);
    LOAD(PFNGLCOMPILESHADERPROC, glCompileShader);
    LOAD(PFNGLCREATEPROGRAMPROC, glCreateProgram);
    LOAD(PFNGLATTACHSHADERPROC, glAttachShader);
    LOAD(PFNGLBINDATTRIBLOCATIONPROC, glBindAttribLocation);
    LOAD(PFNGLLINKPROGRAMPROC, glLinkProgram);
    LOAD(PFNGLGETPROGRAMIVPROC, glGetProgramiv);
    vert[0] = on_es ? es_version : desktop_version;
    vert[1] = vertex_shader;
    frag[0] = on_es ? es_fragment_version : desktop_version;
    frag[1] = stin_visibility_glsl(); /* right after #version (and ES's precision) */
    frag[2] = fragment_main;
    p = glCreateProgram();
    vs = glCreateShader(GL_VERTEX_SHADER);
    fs = glCreateShader(GL_FRAGMENT_SHADER);
    glShaderSource(vs, 2, vert, NULL);
    glShaderSource(fs, 3, frag, NULL);
    glCompileShader(vs);
    glCompileShader(fs);
    glAttachShader(p, vs);
    glAttachShader(p, fs);
    glBindAttribLocation(p, 0, "position");
    glBindAttribLocation(p, 1, "normal");
    glLinkProgram(p);
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    return ok ? p : 0;
}

/* One mesh from client arrays through a buffer: positions, normals (NULL:
 * the floor's +y), indices. */
static void draw_mesh(const float *pos, const float *nrm, uint32_t vertices, const uint32_t *idx,
                      uint32_t indices)
{
    GLuint buf[2];
    LOAD(PFNGLGENBUFFERSPROC, glGenBuffers);
    LOAD(PFNGLBINDBUFFERPROC, glBindBuffer);
    LOAD(PFNGLBUFFERDATAPROC, glBufferData);
    LOAD(PFNGLDELETEBUFFERSPROC, glDeleteBuffers);
    LOAD(PFNGLVERTEXATTRIBPOINTERPROC, glVertexAttribPointer);
    LOAD(PFNGLENABLEVERTEXATTRIBARRAYPROC, glEnableVertexAttribArray);
    LOAD(PFNGLDISABLEVERTEXATTRIBARRAYPROC, glDisableVertexAttribArray);
    LOAD(PFNGLVERTEXATTRIB3FPROC, glVertexAttrib3f);
    LOAD(draw_elements_fn, glDrawElements);
    glGenBuffers(2, buf);
    glBindBuffer(GL_ARRAY_BUFFER, buf[0]);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(vertices * 6 * sizeof(float)), NULL, GL_STREAM_DRAW);
    {
        LOAD(PFNGLBUFFERSUBDATAPROC, glBufferSubData);
        glBufferSubData(GL_ARRAY_BUFFER, 0, (GLsizeiptr)(vertices * 3 * sizeof(float)), pos);
        if (nrm)
            glBufferSubData(GL_ARRAY_BUFFER, (GLintptr)(vertices * 3 * sizeof(float)),
                            (GLsizeiptr)(vertices * 3 * sizeof(float)), nrm);
    }
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, NULL);
    glEnableVertexAttribArray(0);
    if (nrm) {
        glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0,
                              (const void *)(vertices * 3 * sizeof(float)));
        glEnableVertexAttribArray(1);
    } else {
        glVertexAttrib3f(1, 0.0f, 1.0f, 0.0f);
    }
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buf[1]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)(indices * sizeof *idx), idx, GL_STREAM_DRAW);
    /* 32-bit indices: OES_element_index_uint on ES 2.0 */
    glDrawElements(GL_TRIANGLES, (GLsizei)indices, GL_UNSIGNED_INT, NULL);
    glDisableVertexAttribArray(0);
    glDisableVertexAttribArray(1);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    glDeleteBuffers(2, buf);
}

/* The application's pass: its own depth (stin's is there too, for an
 * application whose transforms match bit for bit), its program, stin's
 * uniforms and map. The projection is stin's (see stin.h). */
static int app_pass(stin_context *ctx, const stin_frame_desc *fd, const stin_light_desc *light)
{
    static const float red[3] = {0.9f, 0.3f, 0.2f}, grey[3] = {0.8f, 0.8f, 0.8f};
    float proj[16], view_proj[16];
    int i, j, k;
    GLuint program = build_program();
    LOAD(clear_fn, glClear);
    LOAD(enable_fn, glEnable);
    LOAD(enable_fn, glDisable);
    LOAD(PFNGLUSEPROGRAMPROC, glUseProgram);
    LOAD(PFNGLGETUNIFORMLOCATIONPROC, glGetUniformLocation);
    LOAD(PFNGLUNIFORMMATRIX4FVPROC, glUniformMatrix4fv);
    LOAD(PFNGLUNIFORM3FVPROC, glUniform3fv);
    LOAD(PFNGLUNIFORM1FPROC, glUniform1f);
    LOAD(PFNGLDELETEPROGRAMPROC, glDeleteProgram);
    if (!program)
        return 1;
    stin_query_frame_projection(ctx, proj);
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            for (view_proj[4 * j + i] = 0.0f, k = 0; k < 4; k++)
                view_proj[4 * j + i] += proj[4 * k + i] * fd->view[4 * j + k];
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glUseProgram(program);
    if (stin_bind_visibility(ctx, 0) != STIN_OK) /* unit 0, this program's uniforms */
        return 1;
    glUniformMatrix4fv(glGetUniformLocation(program, "view_proj"), 1, GL_FALSE, view_proj);
    glUniform3fv(glGetUniformLocation(program, "light_position"), 1, light->position);
    glUniform1f(glGetUniformLocation(program, "ambient"), fd->ambient[0]);
    glUniform3fv(glGetUniformLocation(program, "albedo"), 1, red);
    draw_mesh(sphere_pos, sphere_nrm, SPHERE_VERTICES, sphere_idx, build_sphere());
    glUniform3fv(glGetUniformLocation(program, "albedo"), 1, grey);
    draw_mesh(floor_pos, NULL, 4, floor_idx, 6);
    glUseProgram(0);
    glDisable(GL_DEPTH_TEST);
    glDeleteProgram(program);
    return 0;
}

int main(int argc, char **argv)
{
    example_egl e;
    int failed;
    const char *out = NULL;
    if (example_egl_args(&e, argc, argv, &out))
        return 2;
    if (example_egl_open(&e, "egl_app_shader"))
        return 2;
    on_es = e.es != 0;
    failed = example_render(get_proc, NULL, e.fbo, app_pass);
    return example_egl_close(&e, out) || failed;
}
