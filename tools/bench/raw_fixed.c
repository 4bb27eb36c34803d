/* SPDX-License-Identifier: MIT */
/* GL1 raw loop: fixed-function lighting with stin's light model (local
 * viewer, separate specular, GL_NORMALIZE), per object a modelview, a
 * material and a draw; vertex arrays are re-pointed only when the mesh
 * changes, as a hand-written loop would. */
#include "raw.h"
#include "raw_math.h"

static void set_light(const raw_gl *gl, int unit, const scene_light *l)
{
    GLenum id = (GLenum)(GL_LIGHT0 + unit);
    const float zero[4] = {0, 0, 0, 1};
    float c[4], p[4];
    int k;
    for (k = 0; k < 3; k++) {
        c[k] = l->color[k] * l->intensity;
        /* directional: w = 0 and the position points at the light */
        p[k] = l->type == SCENE_LIGHT_DIRECTIONAL ? -l->direction[k] : l->position[k];
    }
    c[3] = 1.0f;
    p[3] = l->type == SCENE_LIGHT_DIRECTIONAL ? 0.0f : 1.0f;
    gl->Lightfv(id, GL_AMBIENT, zero);
    gl->Lightfv(id, GL_DIFFUSE, c);
    gl->Lightfv(id, GL_SPECULAR, c);
    gl->Lightfv(id, GL_POSITION, p); /* world: the view is on the modelview stack */
    gl->Lightfv(id, GL_SPOT_DIRECTION, l->direction);
    gl->Lightf(id, GL_SPOT_CUTOFF, l->type == SCENE_LIGHT_SPOT ? l->spot_cutoff_deg : 180.0f);
    gl->Lightf(id, GL_SPOT_EXPONENT, l->type == SCENE_LIGHT_SPOT ? l->spot_exponent : 0.0f);
    gl->Lightf(id, GL_CONSTANT_ATTENUATION, l->attenuation[0]);
    gl->Lightf(id, GL_LINEAR_ATTENUATION, l->attenuation[1]);
    gl->Lightf(id, GL_QUADRATIC_ATTENUATION, l->attenuation[2]);
    gl->Enable(id);
}

static void set_material(const raw_gl *gl, const scene_material *m)
{
    float spec[4] = {m->specular[0], m->specular[1], m->specular[2], 1.0f};
    float shininess = m->shininess > 128.0f ? 128.0f : m->shininess < 0.0f ? 0.0f : m->shininess;
    gl->Materialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, m->color);
    gl->Materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
    gl->Materialf(GL_FRONT_AND_BACK, GL_SHININESS, shininess);
}

static void bind_mesh(const raw_renderer *r, const raw_mesh *m)
{
    const raw_gl *gl = r->gl;
    const char *base = (const char *)m->vertices;
    if (m->vbo) {
        gl->BindBuffer(GL_ARRAY_BUFFER, m->vbo);
        gl->BindBuffer(GL_ELEMENT_ARRAY_BUFFER, m->ibo);
        base = NULL;
    }
    gl->VertexPointer(3, GL_FLOAT, RAW_VERTEX_STRIDE, base);
    gl->NormalPointer(GL_FLOAT, RAW_VERTEX_STRIDE, base + 12);
}

void raw_fixed_frame(const raw_renderer *r, int width, int height)
{
    const raw_gl *gl = r->gl;
    const scene *s = r->s;
    const float black[4] = {0, 0, 0, 1};
    float view[16], proj[16], mv[16], ambient[4];
    int i, bound = -1;

    scene_camera_matrices(&s->camera, width, height, view, proj);
    gl->Viewport(0, 0, width, height);
    gl->ClearColor(s->background[0], s->background[1], s->background[2], s->background[3]);
    gl->Clear(r->clear_bits);

    /* Everything the loop depends on is set per frame: stin's frames run on
     * the same context in between and leave GL at its defaults. */
    gl->Enable(GL_DEPTH_TEST);
    gl->Enable(GL_LIGHTING);
    gl->Enable(GL_NORMALIZE); /* as stin, which cannot know transforms do not scale */
    gl->LightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    if (r->cfg.separate_specular)
        gl->LightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    ambient[0] = s->ambient[0];
    ambient[1] = s->ambient[1];
    ambient[2] = s->ambient[2];
    ambient[3] = 1.0f;
    gl->LightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
    gl->Materialfv(GL_FRONT_AND_BACK, GL_EMISSION, black);
    gl->MatrixMode(GL_PROJECTION);
    gl->LoadMatrixf(proj);
    gl->MatrixMode(GL_MODELVIEW);
    gl->LoadMatrixf(view);
    for (i = 0; i < s->light_count; i++)
        set_light(gl, i, &s->lights[i]);
    gl->EnableClientState(GL_VERTEX_ARRAY);
    gl->EnableClientState(GL_NORMAL_ARRAY);

    for (i = 0; i < s->object_count; i++) {
        const scene_object *o = &s->objects[i];
        const raw_mesh *m = &r->meshes[o->mesh];
        raw_mat4_mul(mv, view, o->transform);
        gl->LoadMatrixf(mv);
        set_material(gl, &s->materials[o->material]);
        if (o->mesh != bound) {
            bind_mesh(r, m);
            bound = o->mesh;
        }
        gl->DrawElements(GL_TRIANGLES, m->index_count, GL_UNSIGNED_INT,
                         m->vbo ? NULL : (const void *)m->indices);
    }
}

/* Back to GL's defaults for whatever runs next on the context. */
void raw_fixed_reset(const raw_renderer *r)
{
    const raw_gl *gl = r->gl;
    int i;
    for (i = 0; i < r->s->light_count; i++)
        gl->Disable((GLenum)(GL_LIGHT0 + i));
    gl->Disable(GL_LIGHTING);
    gl->Disable(GL_NORMALIZE);
    gl->Disable(GL_DEPTH_TEST);
    if (r->cfg.separate_specular)
        gl->LightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR);
    gl->DisableClientState(GL_VERTEX_ARRAY);
    gl->DisableClientState(GL_NORMAL_ARRAY);
    if (r->cfg.use_vbo) {
        gl->BindBuffer(GL_ARRAY_BUFFER, 0);
        gl->BindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    }
}
