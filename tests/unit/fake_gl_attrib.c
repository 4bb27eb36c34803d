/* SPDX-License-Identifier: MIT */
/* glPushAttrib / glPopAttrib of the fake GL: the attribute groups the GL1
 * tier pushes (current, lighting, transform, enable, texture, pixel mode), each
 * restoring the fields the GL specification's attribute table puts in it.
 * A group the fake does not model is counted as untracked. */
#define FAKE_GL_STUBS
#include "fake_gl.h"

#include <stdio.h>
#include <string.h>

#define FAKE_MODELLED_BITS                                                            \
    (GL_CURRENT_BIT | GL_LIGHTING_BIT | GL_TRANSFORM_BIT | GL_ENABLE_BIT | GL_TEXTURE_BIT | \
     GL_PIXEL_MODE_BIT)
#define S (fake_gl.gl)

static const GLuint lighting_caps[] = {FAKE_GL_LIGHTING, FAKE_GL_COLOR_MATERIAL,
                                       FAKE_GL_LIGHT0,   FAKE_GL_LIGHT1, FAKE_GL_LIGHT2,
                                       FAKE_GL_LIGHT3,   FAKE_GL_LIGHT4, FAKE_GL_LIGHT5,
                                       FAKE_GL_LIGHT6,   FAKE_GL_LIGHT7};
static const GLuint transform_caps[] = {FAKE_GL_NORMALIZE,   FAKE_GL_RESCALE_NORMAL,
                                        FAKE_GL_CLIP_PLANE0, FAKE_GL_CLIP_PLANE1,
                                        FAKE_GL_CLIP_PLANE2, FAKE_GL_CLIP_PLANE3,
                                        FAKE_GL_CLIP_PLANE4, FAKE_GL_CLIP_PLANE5,
                                        FAKE_GL_CLIP_PLANE6, FAKE_GL_CLIP_PLANE7,
                                        FAKE_GL_DEPTH_CLAMP};

static void refuse(const char *what)
{
    if (!fake_gl.gl_errors++)
        snprintf(fake_gl.gl_error_what, sizeof fake_gl.gl_error_what, "%s", what);
}

static void restore_caps(fake_gl_glstate *to, const fake_gl_glstate *from, const GLuint *caps,
                         size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        to->enabled[caps[i]] = from->enabled[caps[i]];
}

static void restore_lighting(fake_gl_glstate *to, const fake_gl_glstate *from)
{
    memcpy(to->light_model_ambient, from->light_model_ambient, sizeof to->light_model_ambient);
    to->light_model_local_viewer = from->light_model_local_viewer;
    to->light_model_two_side = from->light_model_two_side;
    to->light_model_color_control = from->light_model_color_control;
    memcpy(to->lights, from->lights, sizeof to->lights);
    memcpy(to->material, from->material, sizeof to->material);
    to->color_material_face = from->color_material_face;
    to->color_material_mode = from->color_material_mode;
    to->shade_model = from->shade_model;
    restore_caps(to, from, lighting_caps, sizeof lighting_caps / sizeof lighting_caps[0]);
}

/* Texture group: every unit's bindings, environment, coordinate
 * generation and enables, and the active unit (not the client one, not
 * the texture matrices). */
static void restore_texture(fake_gl_glstate *to, const fake_gl_glstate *from)
{
    int u;
    to->active_texture = from->active_texture;
    for (u = 0; u < FAKE_GL_UNITS; u++) {
        fake_gl_unit *t = &to->units[u];
        const fake_gl_unit *f = &from->units[u];
        memcpy(t->enabled, f->enabled, sizeof t->enabled);
        memcpy(t->binding, f->binding, sizeof t->binding);
        t->env = f->env;
        memcpy(t->gen_mode, f->gen_mode, sizeof t->gen_mode);
        memcpy(t->eye_plane, f->eye_plane, sizeof t->eye_plane);
        memcpy(t->object_plane, f->object_plane, sizeof t->object_plane);
    }
}

static void restore_enables(fake_gl_glstate *to, const fake_gl_glstate *from)
{
    int u;
    memcpy(to->enabled, from->enabled, sizeof to->enabled);
    for (u = 0; u < FAKE_GL_UNITS; u++)
        memcpy(to->units[u].enabled, from->units[u].enabled, sizeof to->units[u].enabled);
}

void STIN_APIENTRY fake_PushAttrib(GLbitfield mask)
{
    COUNT(PushAttrib);
    if (mask & ~(GLbitfield)FAKE_MODELLED_BITS)
        fake_gl_state_untracked("glPushAttrib", mask & ~(GLbitfield)FAKE_MODELLED_BITS);
    if (fake_gl.attrib_depth >= FAKE_GL_ATTRIB_STACK_DEPTH) {
        refuse("glPushAttrib: stack overflow"); /* nothing is pushed */
        return;
    }
    fake_gl.attrib_stack[fake_gl.attrib_depth] = S;
    fake_gl.attrib_mask[fake_gl.attrib_depth] = mask;
    fake_gl.attrib_depth++;
}

void STIN_APIENTRY fake_PopAttrib(void)
{
    const fake_gl_glstate *from;
    GLbitfield mask;
    COUNT(PopAttrib);
    if (!fake_gl.attrib_depth) {
        refuse("glPopAttrib: stack underflow");
        return;
    }
    fake_gl.attrib_depth--;
    from = &fake_gl.attrib_stack[fake_gl.attrib_depth];
    mask = fake_gl.attrib_mask[fake_gl.attrib_depth];
    if (mask & GL_CURRENT_BIT)
        memcpy(S.current_color, from->current_color, sizeof S.current_color);
    if (mask & GL_LIGHTING_BIT)
        restore_lighting(&S, from);
    if (mask & GL_TRANSFORM_BIT) {
        S.matrix_mode = from->matrix_mode;
        restore_caps(&S, from, transform_caps, sizeof transform_caps / sizeof transform_caps[0]);
    }
    if (mask & GL_ENABLE_BIT)
        restore_enables(&S, from);
    if (mask & GL_TEXTURE_BIT)
        restore_texture(&S, from);
    if (mask & GL_PIXEL_MODE_BIT) /* the transfer part; pixel maps and zoom are not modelled */
        memcpy(S.pixel_transfer, from->pixel_transfer, sizeof S.pixel_transfer);
}
