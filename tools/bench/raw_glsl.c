/* SPDX-License-Identifier: MIT */
/* GL2/GL4 raw loop: stin's unshadowed plain lit program (raw_program.c),
 * per frame the view and light uniforms, per object the model and material
 * uniforms and a draw; attributes (GL2) or the VAO (GL4) are re-bound only
 * when the mesh changes. */
#include "raw.h"
#include "raw_math.h"

#include <math.h>
#include <stdio.h>

#define RAW_LIGHTS_PER_PASS 8

/* lit.frag specialised to the scene's lights (the first 8, the one pass
 * this loop draws) and untextured materials, as stin specialises its lit
 * programs (src/render/lit_specialise.c): the loop's program is the one stin
 * draws the same scene with, written here from lit.frag's own defines. */
static void specialise(const scene *s, char *out, size_t size)
{
    int i, n = s->light_count < RAW_LIGHTS_PER_PASS ? s->light_count : RAW_LIGHTS_PER_PASS;
    int directional = 0, positional = 0, spot = 0, attenuation = 0;
    for (i = 0; i < n; i++) {
        const scene_light *l = &s->lights[i];
        if (l->type == SCENE_LIGHT_DIRECTIONAL) {
            directional = 1;
            continue;
        }
        positional = 1;
        spot |= l->type == SCENE_LIGHT_SPOT;
        attenuation |= l->attenuation[0] != 1.0f || l->attenuation[1] != 0.0f ||
                       l->attenuation[2] != 0.0f;
    }
    snprintf(out, size,
             "#define STIN_SPECIALISED 1\n#define STIN_LIGHT_COUNT %d\n"
             "#define STIN_DIRECTIONAL %d\n#define STIN_POSITIONAL %d\n#define STIN_SPOT %d\n"
             "#define STIN_ATTENUATION %d\n#define STIN_ALBEDO_TEX 0\n",
             n, directional, positional, spot, attenuation);
}

int raw_glsl_create(raw_renderer *r, char *err, size_t err_size)
{
    const raw_gl *gl = r->gl;
    raw_program *p = &r->prog;
    char defines[256];
    specialise(r->s, defines, sizeof defines);
    if (!(p->name = raw_program_link(gl, &r->cfg, defines, err, err_size)))
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
