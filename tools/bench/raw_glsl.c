/* GL2/GL4 raw loop: stin's lit shaders read from disk (shaders/gl2 or
 * shaders/gl4; lit.frag with the plain-surface and no-shadow chunks spliced
 * in at its marker, as stin builds its unshadowed program), per frame the view and light uniforms, per object the model
 * and material uniforms and a draw; attributes (GL2) or the VAO (GL4) are
 * re-bound only when the mesh changes. */
#include "raw.h"
#include "raw_math.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define RAW_LIGHTS_PER_PASS 8

static char *read_text(const char *path, char *err, size_t err_size)
{
    FILE *f = fopen(path, "rb");
    char *text = NULL;
    long n;
    if (!f) {
        snprintf(err, err_size, "cannot open shader %s (run from the repository root or pass "
                 "--shaders DIR)", path);
        return NULL;
    }
    if (fseek(f, 0, SEEK_END) == 0 && (n = ftell(f)) >= 0 && fseek(f, 0, SEEK_SET) == 0 &&
        (text = malloc((size_t)n + 1)) && fread(text, 1, (size_t)n, f) == (size_t)n) {
        text[n] = '\0';
    } else {
        snprintf(err, err_size, "cannot read shader %s", path);
        free(text);
        text = NULL;
    }
    fclose(f);
    return text;
}

#define CHUNK_MARKER "// @chunks"

/* Compiles `path`; with chunks (a NULL-terminated list of files), their text
 * is spliced in at the file's "// @chunks" line, as stin composes its lit
 * shaders (src/shader.c): the file up to the marker, each chunk, the rest. */
static GLuint compile(const raw_gl *gl, GLenum type, const char *path, const char *const *chunks,
                      char *err, size_t err_size)
{
    enum { MAX_PARTS = 6 };
    char *src = read_text(path, err, err_size), *texts[MAX_PARTS], log[1024];
    const GLchar *parts[MAX_PARTS + 1];
    GLint lengths[MAX_PARTS + 1];
    const char *marker = NULL;
    GLsizei count = 0;
    GLuint sh = 0;
    GLint ok = 0;
    int i, n = 0;
    if (!src)
        return 0;
    if (chunks && chunks[0] && !(marker = strstr(src, CHUNK_MARKER))) {
        snprintf(err, err_size, "%s has no '%s' line for its chunks", path, CHUNK_MARKER);
        goto done;
    }
    parts[count] = src;
    lengths[count++] = marker ? (GLint)(marker - src) : -1;
    for (i = 0; marker && chunks[i]; i++) {
        if (n == MAX_PARTS - 1 || !(texts[n] = read_text(chunks[i], err, err_size)))
            goto done;
        parts[count] = texts[n++];
        lengths[count++] = -1;
    }
    if (marker) {
        parts[count] = marker;
        lengths[count++] = -1;
    }
    sh = gl->CreateShader(type);
    gl->ShaderSource(sh, count, parts, lengths);
    gl->CompileShader(sh);
    gl->GetShaderiv(sh, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        log[0] = '\0';
        gl->GetShaderInfoLog(sh, (GLsizei)sizeof log, NULL, log);
        snprintf(err, err_size, "%s did not compile: %s", path, log);
        gl->DeleteShader(sh);
        sh = 0;
    }
done:
    while (n > 0)
        free(texts[--n]);
    free(src);
    return sh;
}

static GLuint link(const raw_gl *gl, const char *root, const char *sub, char *err,
                   size_t err_size)
{
    char vpath[1024], fpath[1024], surface[1024], shadow[1024], log[1024];
    const char *chunks[3];
    GLuint vs, fs, p;
    GLint ok = 0;
    snprintf(vpath, sizeof vpath, "%s/%s/lit.vert", root, sub);
    snprintf(fpath, sizeof fpath, "%s/%s/lit.frag", root, sub);
    /* stin's unshadowed plain-surface variant: these two chunks in lit.frag */
    snprintf(surface, sizeof surface, "%s/%s/surface_plain.glsl", root, sub);
    snprintf(shadow, sizeof shadow, "%s/%s/shadow_none.glsl", root, sub);
    chunks[0] = surface;
    chunks[1] = shadow;
    chunks[2] = NULL;
    if (!(vs = compile(gl, GL_VERTEX_SHADER, vpath, NULL, err, err_size)))
        return 0;
    if (!(fs = compile(gl, GL_FRAGMENT_SHADER, fpath, chunks, err, err_size))) {
        gl->DeleteShader(vs);
        return 0;
    }
    p = gl->CreateProgram();
    gl->AttachShader(p, vs);
    gl->AttachShader(p, fs);
    /* stin's fixed attribute locations, so the same layout feeds both */
    gl->BindAttribLocation(p, 0, "a_position");
    gl->BindAttribLocation(p, 1, "a_normal");
    gl->BindAttribLocation(p, 2, "a_uv");
    gl->BindAttribLocation(p, 3, "a_tangent"); /* no array: lit.vert's tangent is unused */
    gl->LinkProgram(p);
    gl->DeleteShader(vs);
    gl->DeleteShader(fs);
    gl->GetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        log[0] = '\0';
        gl->GetProgramInfoLog(p, (GLsizei)sizeof log, NULL, log);
        snprintf(err, err_size, "%s + %s did not link: %s", vpath, fpath, log);
        gl->DeleteProgram(p);
        return 0;
    }
    return p;
}

int raw_glsl_create(raw_renderer *r, char *err, size_t err_size)
{
    const raw_gl *gl = r->gl;
    raw_program *p = &r->prog;
    const char *sub = r->cfg.tier == STIN_TIER_GL4 ? "gl4" : "gl2";
    if (!(p->name = link(gl, r->cfg.shader_dir, sub, err, err_size)))
        return 0;
#define LOC(field) p->field = gl->GetUniformLocation(p->name, #field)
    LOC(u_model);
    LOC(u_view_proj);
    LOC(u_normal_matrix);
    LOC(u_eye);
    LOC(u_ambient);
    LOC(u_albedo);
    LOC(u_specular);
    LOC(u_shininess);
    LOC(u_light_count);
    LOC(u_lights);
    LOC(u_has_albedo_tex);
#undef LOC
    return 1;
}

void raw_glsl_destroy(raw_renderer *r)
{
    const raw_gl *gl = r->gl;
    int i;
    if (!r->prog.name)
        return;
    gl->UseProgram(0);
    if (r->cfg.tier == STIN_TIER_GL4) {
        gl->BindVertexArray(0);
    } else {
        for (i = 0; i < 3; i++)
            gl->DisableVertexAttribArray((GLuint)i);
    }
    if (r->cfg.use_vbo || r->cfg.tier == STIN_TIER_GL4) {
        gl->BindBuffer(GL_ARRAY_BUFFER, 0);
        gl->BindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    }
    gl->Disable(GL_DEPTH_TEST);
    gl->DeleteProgram(r->prog.name);
    r->prog.name = 0;
}

/* Four vec4 per light, the layout lit.frag reads (see its header comment). */
static int pack_lights(const scene *s, float *out)
{
    int i, k, n = s->light_count < RAW_LIGHTS_PER_PASS ? s->light_count : RAW_LIGHTS_PER_PASS;
    for (i = 0; i < n; i++) {
        const scene_light *l = &s->lights[i];
        float *o = out + 16 * i;
        int dir = l->type == SCENE_LIGHT_DIRECTIONAL;
        for (k = 0; k < 3; k++) {
            o[k] = dir ? -l->direction[k] : l->position[k];
            o[4 + k] = l->direction[k];
            o[8 + k] = l->color[k] * l->intensity;
            o[12 + k] = l->attenuation[k];
        }
        o[3] = dir ? 0.0f : 1.0f;
        o[7] = l->type == SCENE_LIGHT_SPOT
                   ? (float)cos(l->spot_cutoff_deg * 3.14159265358979323846 / 180.0)
                   : -2.0f;
        o[11] = l->type == SCENE_LIGHT_SPOT ? l->spot_exponent : 0.0f;
        o[15] = 0.0f;
    }
    return n;
}

static void bind_mesh(const raw_renderer *r, const raw_mesh *m)
{
    const raw_gl *gl = r->gl;
    const char *base = (const char *)m->vertices;
    if (m->vao) {
        gl->BindVertexArray(m->vao);
        return;
    }
    if (m->vbo) {
        gl->BindBuffer(GL_ARRAY_BUFFER, m->vbo);
        gl->BindBuffer(GL_ELEMENT_ARRAY_BUFFER, m->ibo);
        base = NULL;
    }
    gl->VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, RAW_VERTEX_STRIDE, base);
    gl->VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, RAW_VERTEX_STRIDE, base + 12);
    gl->VertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, RAW_VERTEX_STRIDE, base + 24);
}

void raw_glsl_frame(const raw_renderer *r, int width, int height)
{
    const raw_gl *gl = r->gl;
    const raw_program *p = &r->prog;
    const scene *s = r->s;
    float view[16], proj[16], vp[16], nm[9], lights[16 * RAW_LIGHTS_PER_PASS];
    int i, n, bound = -1;

    scene_camera_matrices(&s->camera, width, height, view, proj);
    raw_mat4_mul(vp, proj, view);
    gl->Viewport(0, 0, width, height);
    gl->ClearColor(s->background[0], s->background[1], s->background[2], s->background[3]);
    gl->Clear(r->clear_bits);
    gl->Enable(GL_DEPTH_TEST);
    gl->UseProgram(p->name);
    gl->UniformMatrix4fv(p->u_view_proj, 1, GL_FALSE, vp);
    gl->Uniform3fv(p->u_eye, 1, s->camera.eye);
    gl->Uniform3fv(p->u_ambient, 1, s->ambient);
    n = pack_lights(s, lights);
    gl->Uniform1i(p->u_light_count, n);
    if (n)
        gl->Uniform4fv(p->u_lights, 4 * n, lights);
    gl->Uniform1i(p->u_has_albedo_tex, 0);
    if (r->cfg.tier != STIN_TIER_GL4)
        for (i = 0; i < 3; i++)
            gl->EnableVertexAttribArray((GLuint)i);

    for (i = 0; i < s->object_count; i++) {
        const scene_object *o = &s->objects[i];
        const scene_material *mat = &s->materials[o->material];
        const raw_mesh *m = &r->meshes[o->mesh];
        float shininess = mat->shininess > 128.0f ? 128.0f
                        : mat->shininess < 0.0f   ? 0.0f
                                                  : mat->shininess;
        if (o->mesh != bound) {
            bind_mesh(r, m);
            bound = o->mesh;
        }
        gl->UniformMatrix4fv(p->u_model, 1, GL_FALSE, o->transform);
        raw_mat3_normal(nm, o->transform);
        gl->UniformMatrix3fv(p->u_normal_matrix, 1, GL_FALSE, nm);
        gl->Uniform4fv(p->u_albedo, 1, mat->color);
        gl->Uniform3fv(p->u_specular, 1, mat->specular);
        gl->Uniform1f(p->u_shininess, shininess);
        gl->DrawElements(GL_TRIANGLES, m->index_count, GL_UNSIGNED_INT,
                         m->vbo ? NULL : (const void *)m->indices);
    }
}
