/* SPDX-License-Identifier: MIT */
/* GL1 tier: fixed-function lighting (per vertex, GL's own equation), lights
 * in batches of GL_MAX_LIGHTS with additive passes, the passes the shadow
 * schedule needs (ambient, one light, flat colour, volumes), and the AOV
 * outputs. */
#include "internal.h"
#include "render/draw_bounds.h"
#include "render/terminator_fixed.h"

static void set_light(stin_context *ctx, int unit, const stin_light_desc *l)
{
    GLenum id = (GLenum)(GL_LIGHT0 + unit);
    float zero[4] = {0, 0, 0, 1}, c[4], p[4];
    int k;
    for (k = 0; k < 3; k++)
        c[k] = l->color[k] * l->intensity;
    c[3] = 1.0f;
    if (l->type == STIN_LIGHT_DIRECTIONAL) {
        p[0] = -l->direction[0];
        p[1] = -l->direction[1];
        p[2] = -l->direction[2];
        p[3] = 0.0f;
    } else {
        p[0] = l->position[0];
        p[1] = l->position[1];
        p[2] = l->position[2];
        p[3] = 1.0f;
    }
    GL(ctx, Lightfv)(id, GL_AMBIENT, zero);
    GL(ctx, Lightfv)(id, GL_DIFFUSE, c);
    GL(ctx, Lightfv)(id, GL_SPECULAR, c);
    GL(ctx, Lightfv)(id, GL_POSITION, p); /* transformed by the view on the stack */
    GL(ctx, Lightfv)(id, GL_SPOT_DIRECTION, l->direction);
    GL(ctx, Lightf)(id, GL_SPOT_CUTOFF, l->type == STIN_LIGHT_SPOT ? l->spot_cutoff_deg : 180.0f);
    GL(ctx, Lightf)(id, GL_SPOT_EXPONENT, l->type == STIN_LIGHT_SPOT ? l->spot_exponent : 0.0f);
    GL(ctx, Lightf)(id, GL_CONSTANT_ATTENUATION, l->attenuation[0]);
    GL(ctx, Lightf)(id, GL_LINEAR_ATTENUATION, l->attenuation[1]);
    GL(ctx, Lightf)(id, GL_QUADRATIC_ATTENUATION, l->attenuation[2]);
    GL_ENABLE(ctx, id);
}

/* A light with colour c along world axis dir: used by the normal output. */
static void axis_light(stin_context *ctx, int unit, int axis, float sign, float value)
{
    stin_light_desc l;
    stin__memzero(&l, sizeof l);
    l.type = STIN_LIGHT_DIRECTIONAL;
    l.direction[axis] = -sign; /* light travels against the axis it lights */
    l.color[axis] = value;
    l.intensity = 1.0f;
    set_light(ctx, unit, &l);
    GL(ctx, Lightfv)((GLenum)(GL_LIGHT0 + unit), GL_SPECULAR, (const float[4]){0, 0, 0, 1});
}

static void disable_lights(stin_context *ctx, int from)
{
    int i;
    for (i = from; i < ctx->lights_per_pass; i++)
        GL_DISABLE(ctx, (GLenum)(GL_LIGHT0 + i));
}

static void scene_ambient(stin_context *ctx, int on)
{
    float ambient[4] = {0, 0, 0, 1};
    if (on) {
        ambient[0] = ctx->frame.ambient[0];
        ambient[1] = ctx->frame.ambient[1];
        ambient[2] = ctx->frame.ambient[2];
    }
    GL(ctx, LightModelfv)(GL_LIGHT_MODEL_AMBIENT, ambient);
}

static void set_batch(stin_context *ctx, int batch)
{
    int first = batch * ctx->lights_per_pass, i, n = 0;
    GL(ctx, MatrixMode)(GL_MODELVIEW);
    GL(ctx, LoadMatrixf)(ctx->frame.view);
    for (i = first; i < (int)ctx->light_count && n < ctx->lights_per_pass; i++, n++)
        set_light(ctx, n, &ctx->lights[i]);
    disable_lights(ctx, n);
    scene_ambient(ctx, batch == 0);
}

static void set_material(stin_context *ctx, const stin_material *m)
{
    float spec[4] = {m->specular[0], m->specular[1], m->specular[2], 1.0f};
    float black[4] = {0, 0, 0, 1};
    const stin__texture_slot *t = stin__texture_lookup(ctx, m->albedo);
    const stin__path_feature *const *f;
    GL(ctx, Materialfv)(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, m->color);
    GL(ctx, Materialfv)(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
    GL(ctx, Materialfv)(GL_FRONT_AND_BACK, GL_EMISSION, black);
    GL(ctx, Materialf)(GL_FRONT_AND_BACK, GL_SHININESS, m->shininess);
    if (t) {
        GL_ENABLE(ctx, GL_TEXTURE_2D);
        GL(ctx, BindTexture)(GL_TEXTURE_2D, t->name);
        GL(ctx, TexEnvi)(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    } else {
        GL_DISABLE(ctx, GL_TEXTURE_2D);
    }
    for (f = stin__path_features(ctx); *f; f++) /* bumped: diffuse comes from DOT3's passes */
        if ((*f)->fixed_material)
            (*f)->fixed_material(ctx, m);
}

/* The fixed path's arrays at base (a buffer offset, or client memory). */
static void fixed_pointers(stin_context *ctx, const stin__vertex *at)
{
    const char *base = (const char *)at;
    GL(ctx, VertexPointer)(3, GL_FLOAT, (GLsizei)sizeof(stin__vertex), base);
    GL(ctx, NormalPointer)(GL_FLOAT, (GLsizei)sizeof(stin__vertex), base + 12);
    GL(ctx, TexCoordPointer)(2, GL_FLOAT, (GLsizei)sizeof(stin__vertex), base + 24);
}

static void draw_mesh(stin_context *ctx, const stin__draw *d)
{
    const stin__mesh_slot *m = &ctx->meshes[d->mesh_slot];
    float mv[16];
    const void *idx;
    stin__mat4_mul(mv, ctx->frame.view, d->transform);
    GL(ctx, MatrixMode)(GL_MODELVIEW);
    GL(ctx, LoadMatrixf)(mv);
    idx = m->vbo ? NULL : (const void *)(ctx->indices + 3u * m->first_triangle);
    if (ctx->bound_mesh != d->mesh_slot) { /* consecutive draws of one mesh share arrays */
        if (m->vbo) {
            GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, m->vbo);
            GL(ctx, BindBuffer)(GL_ELEMENT_ARRAY_BUFFER, m->ibo);
        }
        fixed_pointers(ctx, m->vbo ? NULL : ctx->vertices + m->first_vertex);
        ctx->bound_mesh = d->mesh_slot;
    }
    stin__mesh_draw(ctx, m, GL_TRIANGLES, idx, fixed_pointers);
}

int stin__draw_solid(const stin_context *ctx, const stin__draw *d, float min_size)
{
    float c[24];
    int k;
    if (d->csg || d->material.two_sided || !ctx->meshes[d->mesh_slot].info.closed_manifold ||
        !stin__draw_world_corners(ctx, d, c))
        return 0;
    for (k = 1; k <= 4; k *= 2) /* corner 0 to its neighbour along each axis */
        if ((c[3 * k] - c[0]) * (c[3 * k] - c[0]) + (c[3 * k + 1] - c[1]) * (c[3 * k + 1] - c[1]) +
                (c[3 * k + 2] - c[2]) * (c[3 * k + 2] - c[2]) <
            min_size * min_size)
            return 0;
    return 1;
}

/* A lit draw: the shadow test's per-receiver part first, where it has one. */
static void draw_lit(stin_context *ctx, const stin__draw *d)
{
    if (ctx->lit_draw)
        ctx->lit_draw(ctx, d);
    draw_mesh(ctx, d);
}

static int in_set(const stin__draw *d, int which)
{
    return (which & (d->material.color[3] < 1.0f ? STIN__BLENDED : STIN__OPAQUE)) != 0;
}

/* The CSG products' faces on their resolved depth (opaque): a back face
 * lit from its side by two-sided lighting (GL flips its normal). GL flips
 * the normals of the faces it finds back-facing in the window: under a
 * mirroring transform the mesh's back faces wind the other way, so GL is
 * told clockwise is front for them (and culls accordingly). */
static void draw_csg_faces(stin_context *ctx, int which, int materials)
{
    uint32_t i, count;
    const stin__draw *faces = stin__resolved_faces(ctx, &count);
    stin__pass_state saved;
    if (!(which & STIN__OPAQUE))
        return;
    for (i = 0; i < count; i++) {
        const stin__draw *d = &faces[i];
        if (!stin__resolved_face_begin(ctx, d, &saved))
            continue;
        if (d->csg == STIN__CSG_BACK && stin__mat4_det(d->transform) < 0.0) {
            stin__pass_state ps = *stin__pass_current(ctx);
            ps.front_face = GL_CW;
            ps.cull_face = ps.cull_face == GL_BACK ? GL_FRONT : GL_BACK;
            stin__pass_apply(ctx, &ps);
        }
        if (d->csg == STIN__CSG_BACK)
            GL(ctx, LightModeli)(GL_LIGHT_MODEL_TWO_SIDE, 1);
        if (materials)
            set_material(ctx, &d->material);
        draw_lit(ctx, d);
        if (d->csg == STIN__CSG_BACK)
            GL(ctx, LightModeli)(GL_LIGHT_MODEL_TWO_SIDE, 0);
        stin__resolved_face_end(ctx, &saved);
    }
}

static void draw_set(stin_context *ctx, int which, int materials)
{
    uint32_t i;
    for (i = 0; i < ctx->draw_count; i++) {
        const stin__draw *d = &ctx->draws[ctx->draw_order[i]];
        if (!in_set(d, which))
            continue;
        if (materials)
            set_material(ctx, &d->material);
        draw_lit(ctx, d);
    }
    draw_csg_faces(ctx, which, materials);
}

/* Every draw's geometry seen from a light (its view and projection), no
 * materials: shadow-map casters. The camera's view comes back after. */
static void fixed_depth(stin_context *ctx, const float view[16], const float proj[16],
                        int casters, float solid_min)
{
    stin__pass_state caller = *stin__pass_current(ctx), ps = caller;
    float saved_view[16];
    uint32_t i;
    GL(ctx, MatrixMode)(GL_PROJECTION);
    GL(ctx, LoadMatrixf)(proj);
    stin__memcopy(saved_view, ctx->frame.view, sizeof saved_view);
    stin__memcopy(ctx->frame.view, view, sizeof saved_view);
    ctx->bound_mesh = 0xffffffffu;
    for (i = 0; i < ctx->draw_count; i++) { /* casters the translucent choice keeps */
        const stin__draw *d = &ctx->draws[ctx->draw_order[i]];
        int solid = stin__draw_solid(ctx, d, solid_min);
        if (!in_set(d, STIN__ALL) || !d->shadow_caster ||
            (casters & (solid ? STIN__DEPTH_OPEN_ONLY : STIN__DEPTH_SOLIDS_ONLY)))
            continue;
        if (casters & STIN__DEPTH_FAR_SIDE) { /* a closed solid's far side casts the same shadow */
            ps.cull = (unsigned char)solid;
            ps.cull_face = stin__mat4_det(d->transform) < 0.0 ? GL_BACK : GL_FRONT;
            /* half the slope term: the full one pushes the steep far faces
             * of a solid resting on a receiver past it (its shadow shrinks) */
            ps.offset_factor = ps.cull ? 0.5f * caller.offset_factor : caller.offset_factor;
            stin__pass_apply(ctx, &ps);
        }
        draw_mesh(ctx, d);
    }
    stin__pass_apply(ctx, &caller);
    ctx->bound_mesh = 0xffffffffu; /* CSG products: csg/cast.c, before these */
    stin__memcopy(ctx->frame.view, saved_view, sizeof saved_view);
}

/* Fixed-function passes add with SRC_ALPHA/ONE when blended (the lit
 * passes of a blended draw keep its opacity). */
static void pass_state(stin_context *ctx, int additive, int blend_alpha)
{
    stin__pass_state ps = stin__pass_draw(ctx, additive, blend_alpha);
    stin__pass_apply(ctx, &ps);
}

static int batch_count(const stin_context *ctx)
{
    int n = ((int)ctx->light_count + ctx->lights_per_pass - 1) / ctx->lights_per_pass;
    return n > 0 ? n : 1;
}

static void fixed_batches(stin_context *ctx, int which)
{
    const stin__path_feature *const *f;
    int batches = batch_count(ctx), b;
    uint32_t i;
    GL_ENABLE(ctx, GL_LIGHTING);
    if (which & STIN__OPAQUE)
        for (b = 0; b < batches; b++) { /* every opaque draw per light batch */
            set_batch(ctx, b);
            pass_state(ctx, b > 0, 0);
            ctx->stats.passes++;
            draw_set(ctx, STIN__OPAQUE, 1);
            for (f = stin__path_features(ctx); *f; f++)
                if ((*f)->fixed_batch)
                    (*f)->fixed_batch(ctx, b);
        }
    if (which & STIN__BLENDED)
        for (i = 0; i < ctx->draw_count; i++) { /* each blended draw whole, far to near */
            const stin__draw *d = &ctx->draws[ctx->draw_order[i]];
            if (!in_set(d, STIN__BLENDED))
                continue;
            for (b = 0; b < batches; b++) {
                set_batch(ctx, b);
                pass_state(ctx, b > 0, 1);
                set_material(ctx, &d->material);
                draw_mesh(ctx, d);
            }
        }
}

static void fixed_ambient(stin_context *ctx, int which, int depth_only)
{
    stin__pass_state ps = stin__pass_draw(ctx, 0, 0);
    GL_ENABLE(ctx, GL_LIGHTING);
    disable_lights(ctx, 0);
    scene_ambient(ctx, 1);
    ps.color_write = !depth_only;
    stin__pass_apply(ctx, &ps);
    draw_set(ctx, which, !depth_only);
    ctx->stats.passes++;
}

static void fixed_lit(stin_context *ctx, const stin_light_desc *light)
{
    const stin__path_feature *const *f;
    GL_ENABLE(ctx, GL_LIGHTING);
    GL(ctx, MatrixMode)(GL_MODELVIEW);
    GL(ctx, LoadMatrixf)(ctx->frame.view);
    set_light(ctx, 0, light);
    disable_lights(ctx, 1);
    scene_ambient(ctx, 0);
    pass_state(ctx, 1, 0);
    /* DOT3's bumped diffuse first: the stencil may count lit pixels */
    for (f = stin__path_features(ctx); *f; f++)
        if ((*f)->fixed_lights)
            (*f)->fixed_lights(ctx, light, 1);
    draw_set(ctx, STIN__OPAQUE, 1);
    ctx->stats.passes++;
}

/* A light's pass adds ONE / ONE with the light's colour times the draw's
 * opacity: the fragment's alpha is not the opacity any more once
 * map-combine's test has replaced it with its comparison (the albedo
 * texture's alpha is not applied to these passes). */
static void fixed_blended_one(stin_context *ctx, const stin__draw *d,
                              const stin_light_desc *light)
{
    GL_ENABLE(ctx, GL_LIGHTING);
    GL(ctx, MatrixMode)(GL_MODELVIEW);
    GL(ctx, LoadMatrixf)(ctx->frame.view);
    if (light) {
        stin_light_desc l = *light;
        l.intensity *= d->material.color[3];
        set_light(ctx, 0, &l);
        disable_lights(ctx, 1);
        scene_ambient(ctx, 0);
        pass_state(ctx, 1, 0);
    } else {
        disable_lights(ctx, 0);
        scene_ambient(ctx, 1);
        pass_state(ctx, 0, 1);
    }
    set_material(ctx, &d->material);
    draw_lit(ctx, d);
    ctx->stats.passes++;
}

static void fixed_flat(stin_context *ctx, int which, const float color[4],
                       const stin_light_desc *light)
{
    (void)light; /* the fixed maps' tests sit on the texture units already */
    GL_DISABLE(ctx, GL_LIGHTING);
    GL_DISABLE(ctx, GL_TEXTURE_2D);
    GL(ctx, Color4f)(color[0], color[1], color[2], color[3]);
    pass_state(ctx, 1, 0);
    draw_set(ctx, which, 0);
    ctx->stats.passes++;
}

/* World normal as 0.5 + 0.5 n without shaders: pass 1 lights +x,+y,+z with
 * half intensity over a 0.5 ambient; pass 2 multiplies by 1 - max(0, -n)
 * (negative light colours, which GL allows), which halves toward 0. */
static void fixed_normals(stin_context *ctx)
{
    float half[4] = {0.5f, 0.5f, 0.5f, 1.0f}, one[4] = {1, 1, 1, 1}, black[4] = {0, 0, 0, 1};
    int axis;
    GL_ENABLE(ctx, GL_LIGHTING);
    GL_DISABLE(ctx, GL_TEXTURE_2D);
    GL(ctx, Materialfv)(GL_FRONT_AND_BACK, GL_DIFFUSE, one);
    GL(ctx, Materialfv)(GL_FRONT_AND_BACK, GL_SPECULAR, black);
    GL(ctx, Materialfv)(GL_FRONT_AND_BACK, GL_EMISSION, black);
    GL(ctx, LightModelfv)(GL_LIGHT_MODEL_AMBIENT, one);

    GL(ctx, MatrixMode)(GL_MODELVIEW);
    GL(ctx, LoadMatrixf)(ctx->frame.view);
    for (axis = 0; axis < 3; axis++)
        axis_light(ctx, axis, axis, 1.0f, 0.5f);
    disable_lights(ctx, 3);
    GL(ctx, Materialfv)(GL_FRONT_AND_BACK, GL_AMBIENT, half);
    pass_state(ctx, 0, 0);
    draw_set(ctx, STIN__ALL, 0);

    GL(ctx, MatrixMode)(GL_MODELVIEW);
    GL(ctx, LoadMatrixf)(ctx->frame.view);
    for (axis = 0; axis < 3; axis++)
        axis_light(ctx, axis, axis, -1.0f, -1.0f);
    GL(ctx, Materialfv)(GL_FRONT_AND_BACK, GL_AMBIENT, one);
    {
        stin__pass_state ps = stin__pass_draw(ctx, 1, 0);
        ps.blend_src = GL_ZERO;
        ps.blend_dst = GL_SRC_COLOR;
        stin__pass_apply(ctx, &ps);
    }
    draw_set(ctx, STIN__ALL, 0);
    ctx->stats.passes += 2;
}

/* CSG resolve (csg/goldfeather.c): geometry alone, the camera's matrices. */
static void fixed_geometry_begin(stin_context *ctx)
{
    GL_DISABLE(ctx, GL_LIGHTING);
    GL_DISABLE(ctx, GL_TEXTURE_2D);
    ctx->bound_mesh = 0xffffffffu;
}

static void fixed_geometry_end(stin_context *ctx) { ctx->bound_mesh = 0xffffffffu; }

static void fixed_volume_begin(stin_context *ctx)
{
    GL_DISABLE(ctx, GL_LIGHTING);
    GL_DISABLE(ctx, GL_TEXTURE_2D);
    GL(ctx, DisableClientState)(GL_NORMAL_ARRAY);
    GL(ctx, DisableClientState)(GL_TEXTURE_COORD_ARRAY);
    if (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_VBO))
        GL(ctx, BindBuffer)(GL_ARRAY_BUFFER, 0);
    ctx->bound_mesh = 0xffffffffu;
}

static void fixed_volume_draw(stin_context *ctx, const float model[16], const float *xyzw,
                              uint32_t n)
{
    float mv[16];
    stin__mat4_mul(mv, ctx->frame.view, model);
    GL(ctx, MatrixMode)(GL_MODELVIEW);
    GL(ctx, LoadMatrixf)(mv);
    GL(ctx, VertexPointer)(4, GL_FLOAT, 0, xyzw);
    GL(ctx, DrawArrays)(GL_TRIANGLES, 0, (GLsizei)n);
}

static void fixed_volume_end(stin_context *ctx)
{
    GL(ctx, EnableClientState)(GL_NORMAL_ARRAY);
    GL(ctx, EnableClientState)(GL_TEXTURE_COORD_ARRAY);
    ctx->bound_mesh = 0xffffffffu;
}

static void fixed_begin(stin_context *ctx)
{
    ctx->bound_mesh = 0xffffffffu;
    GL(ctx, MatrixMode)(GL_PROJECTION);
    GL(ctx, PushMatrix)();
    GL(ctx, LoadMatrixf)(ctx->projection);
    GL(ctx, MatrixMode)(GL_MODELVIEW);
    GL(ctx, PushMatrix)();
    GL_ENABLE(ctx, GL_NORMALIZE);
    GL(ctx, ShadeModel)(GL_SMOOTH);
    GL(ctx, LightModeli)(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    GL(ctx, LightModeli)(GL_LIGHT_MODEL_TWO_SIDE, 0);
    if (ctx->caps.present & STIN_CAP_BIT(STIN_CAP_SEPARATE_SPECULAR))
        GL_ENUM(ctx, LightModeli, GL_LIGHT_MODEL_COLOR_CONTROL)(GL_LIGHT_MODEL_COLOR_CONTROL,
                                                                GL_SEPARATE_SPECULAR_COLOR);
    GL(ctx, EnableClientState)(GL_VERTEX_ARRAY);
    GL(ctx, EnableClientState)(GL_NORMAL_ARRAY);
    GL(ctx, EnableClientState)(GL_TEXTURE_COORD_ARRAY);
}

/* Lights, enables, texture units and the matrix mode come back with the
 * frame's glPopAttrib (frame/state.c); the client arrays and matrices are ours. */
static void fixed_end(stin_context *ctx)
{
    GL(ctx, DisableClientState)(GL_VERTEX_ARRAY);
    GL(ctx, DisableClientState)(GL_NORMAL_ARRAY);
    GL(ctx, DisableClientState)(GL_TEXTURE_COORD_ARRAY);
    GL(ctx, MatrixMode)(GL_PROJECTION);
    GL(ctx, PopMatrix)();
    GL(ctx, MatrixMode)(GL_MODELVIEW);
    GL(ctx, PopMatrix)();
}

const stin__path *stin__fixed_path(void)
{
    static const stin__path path = {fixed_begin,        fixed_end,         fixed_ambient,
                                    fixed_lit,          fixed_flat,        fixed_volume_begin,
                                    fixed_volume_draw,  fixed_volume_end,  fixed_batches,
                                    fixed_normals,      fixed_depth,       NULL,
                                    fixed_geometry_begin, draw_mesh,       fixed_geometry_end,
                                    fixed_blended_one,  NULL,
                                    stin__fixed_terminator_band};
    return &path;
}
