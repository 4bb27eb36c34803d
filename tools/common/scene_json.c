/* SPDX-License-Identifier: MIT */
/*
 * scene_load: reads a JSON scene file (docs/scene-format.md), validates every
 * value and builds the scene. Any problem stops the load with one message
 * "FILE: where: problem" and nothing allocated survives.
 *
 * The optional top-level "csg" list is validated here (known operations,
 * operands that exist) but not evaluated: the CSG renderer reads the file
 * itself, and every object stays an ordinary renderable mesh.
 */
#include "name_table.h"
#include "scene_entries.h"
#include "scene_internal.h"
#include "scene_primitives.h"
#include "stin/stin.h" /* the technique list only: the loader links no stin */

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SCENE_FILE_MAX (64L << 20)
#define TESSELLATION_MAX 1024
#define INSTANCES_MAX 1000000
#define IMAGE_SIZE_MAX 16384
/* The smallest camera.near: below it the camera's matrices cannot be
 * inverted for the output's positions (1e-20 could not; 1e-15 could). */
#define CAMERA_NEAR_MIN 1e-6f

static const float identity[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };

static const char *texture_kind_name(scene_texture_kind k)
{
    return k == SCENE_TEXTURE_NORMAL ? "normal" : k == SCENE_TEXTURE_HEIGHT ? "height" : "albedo";
}

/* Entry names double as references, so they must be usable and unique. */
static int check_name(scene_parser *p, const char *section, const char *name,
                      const char *taken, size_t stride, int taken_count)
{
    int i;
    if (!name[0] || strlen(name) >= SCENE_NAME_MAX)
        return scene_fail(p, section, "name '%s' must have 1 to %d characters", name, SCENE_NAME_MAX - 1);
    for (i = 0; i < taken_count; i++)
        if (strcmp(taken + (size_t)i * stride, name) == 0)
            return scene_fail(p, section, "duplicate name '%s'", name);
    return 1;
}

/* ---- meshes ------------------------------------------------------------- */

static int build_primitive(scene_parser *p, const cJSON *j, const char *where, scene_mesh *m)
{
    static const char *const plane_keys[] = { "primitive", "size", "subdivisions", NULL };
    static const char *const box_keys[] = { "primitive", "size", NULL };
    static const char *const sphere_keys[] = { "primitive", "radius", "slices", "stacks", NULL };
    static const char *const torus_keys[] = { "primitive", "major_radius", "minor_radius", "rings", "sides", NULL };
    static const char *const cyl_keys[] = { "primitive", "radius", "height", "slices", "capped", NULL };
    const int T = TESSELLATION_MAX;
    char prim[32] = "", path[256];
    int ok;
    if (!scene_get_string(p, j, "primitive", where, prim, sizeof prim))
        return 0;
    if (strcmp(prim, "plane") == 0) {
        float size[2] = { 1, 1 }, sub[2] = { 1, 1 };
        int n[2], i;
        if (!scene_check_object(p, j, where, plane_keys) ||
            !scene_get_vector(p, j, "size", where, 2, SCENE_POSITIVE, size) ||
            !scene_get_vector(p, j, "subdivisions", where, 2, SCENE_ANY, sub))
            return 0;
        for (i = 0; i < 2; i++) {
            if (sub[i] != floorf(sub[i]) || sub[i] < 1 || sub[i] > T) {
                scene_join(path, sizeof path, where, "subdivisions");
                return scene_fail(p, path, "expected two integers in [1, %d]", T);
            }
            n[i] = (int)sub[i];
        }
        ok = scene_prim_plane(m, size[0], size[1], n[0], n[1]);
    } else if (strcmp(prim, "box") == 0) {
        float size[3] = { 1, 1, 1 };
        if (!scene_check_object(p, j, where, box_keys) ||
            !scene_get_vector(p, j, "size", where, 3, SCENE_POSITIVE, size))
            return 0;
        ok = scene_prim_box(m, size[0], size[1], size[2]);
    } else if (strcmp(prim, "sphere") == 0) {
        float radius = 0.5f;
        int slices = 16, stacks = 16;
        if (!scene_check_object(p, j, where, sphere_keys) ||
            !scene_get_number(p, j, "radius", where, SCENE_POSITIVE, &radius) ||
            !scene_get_int(p, j, "slices", where, 3, T, &slices) ||
            !scene_get_int(p, j, "stacks", where, 2, T, &stacks))
            return 0;
        ok = scene_prim_sphere(m, radius, slices, stacks);
    } else if (strcmp(prim, "torus") == 0) {
        float major = 1, minor = 0.25f;
        int rings = 32, sides = 16;
        if (!scene_check_object(p, j, where, torus_keys) ||
            !scene_get_number(p, j, "major_radius", where, SCENE_POSITIVE, &major) ||
            !scene_get_number(p, j, "minor_radius", where, SCENE_POSITIVE, &minor) ||
            !scene_get_int(p, j, "rings", where, 3, T, &rings) ||
            !scene_get_int(p, j, "sides", where, 3, T, &sides))
            return 0;
        if (minor >= major) {
            scene_join(path, sizeof path, where, "minor_radius");
            return scene_fail(p, path, "must be smaller than major_radius (the tube would self-intersect)");
        }
        ok = scene_prim_torus(m, major, minor, rings, sides);
    } else if (strcmp(prim, "cylinder") == 0) {
        float radius = 0.5f, height = 1;
        int slices = 32, capped = 1;
        if (!scene_check_object(p, j, where, cyl_keys) ||
            !scene_get_number(p, j, "radius", where, SCENE_POSITIVE, &radius) ||
            !scene_get_number(p, j, "height", where, SCENE_POSITIVE, &height) ||
            !scene_get_int(p, j, "slices", where, 3, T, &slices) ||
            !scene_get_bool(p, j, "capped", where, &capped))
            return 0;
        ok = scene_prim_cylinder(m, radius, height, slices, capped);
    } else {
        scene_join(path, sizeof path, where, "primitive");
        return scene_fail(p, path, "unknown primitive '%s' (plane, box, sphere, torus, cylinder)", prim);
    }
    return ok ? 1 : scene_fail(p, where, "out of memory");
}

static int build_mesh(scene_parser *p, const cJSON *j, const char *where, const char *name,
                      scene *s, scene_entries *e)
{
    static const char *const file_keys[] = { "file", NULL };
    char rel[512] = "", full[1024], path[256];
    scene_mesh m;
    if (!cJSON_IsObject(j))
        return scene_fail(p, where, "expected an object");
    if (cJSON_GetObjectItemCaseSensitive(j, "primitive")) {
        memset(&m, 0, sizeof m);
        return build_primitive(p, j, where, &m) && scene_entries_add_mesh(p, e, s, name, &m);
    }
    if (!cJSON_GetObjectItemCaseSensitive(j, "file"))
        return scene_fail(p, where, "needs a 'primitive' or a 'file'");
    if (!scene_check_object(p, j, where, file_keys) ||
        !scene_get_string(p, j, "file", where, rel, sizeof rel))
        return 0;
    scene_join(path, sizeof path, where, "file");
    if (!scene_resolve_path(p->file, rel, full, sizeof full))
        return scene_fail(p, path, "path too long");
    return scene_entries_add_model(p, e, s, name, path, full, rel);
}

static int parse_meshes(scene_parser *p, const cJSON *j, scene *s, scene_entries *e)
{
    const cJSON *c;
    char where[256];
    if (!cJSON_IsObject(j) || cJSON_GetArraySize(j) == 0)
        return scene_fail(p, "meshes", "expected an object of named meshes");
    for (c = j->child; c; c = c->next) {
        if (!check_name(p, "meshes", c->string, e->entries ? e->entries[0].name : "",
                        sizeof *e->entries, e->entry_count))
            return 0;
        snprintf(where, sizeof where, "meshes.%s", c->string);
        if (!build_mesh(p, c, where, c->string, s, e))
            return 0;
    }
    return 1;
}

/* ---- textures and materials --------------------------------------------- */

static int parse_textures(scene_parser *p, const cJSON *j, scene *s)
{
    const cJSON *c;
    char where[256];
    int n = cJSON_GetArraySize(j);
    if (!cJSON_IsObject(j))
        return scene_fail(p, "textures", "expected an object of named textures");
    if (n == 0)
        return 1;
    s->textures = calloc((size_t)n, sizeof *s->textures);
    if (!s->textures)
        return scene_fail(p, "textures", "out of memory");
    s->texture_count = n;
    n = 0;
    for (c = j->child; c; c = c->next, n++) {
        if (!check_name(p, "textures", c->string, s->textures[0].name, sizeof *s->textures, n))
            return 0;
        strcpy(s->textures[n].name, c->string);
        snprintf(where, sizeof where, "textures.%s", c->string);
        if (!scene_texture_build(p, c, where, s->textures, n, &s->textures[n]))
            return 0;
    }
    return 1;
}

/* Resolves a texture slot of a material; the first material to use a
 * texture fixes its kind, a later conflicting use is an error. */
static int texture_slot(scene_parser *p, const cJSON *j, const char *key, const char *where,
                        scene *s, int *used, scene_texture_kind kind, int *out)
{
    char name[SCENE_NAME_MAX] = "", path[256];
    int i;
    if (!cJSON_GetObjectItemCaseSensitive(j, key))
        return 1;
    if (!scene_get_string(p, j, key, where, name, sizeof name))
        return 0;
    scene_join(path, sizeof path, where, key);
    for (i = 0; i < s->texture_count && strcmp(s->textures[i].name, name) != 0; i++)
        ;
    if (i == s->texture_count)
        return scene_fail(p, path, "unknown texture '%s'", name);
    if (used[i] && s->textures[i].kind != kind)
        return scene_fail(p, path, "texture '%s' is already used as a %s map", name,
                          texture_kind_name(s->textures[i].kind));
    used[i] = 1;
    s->textures[i].kind = kind;
    *out = i;
    return 1;
}

/* A material's "surface": one of stin's surface techniques (a technique of
 * another feature would drop the draw). */
static int check_surface(scene_parser *p, const char *where, const char *name)
{
#define SCENE_TECHNIQUE_(id, text, feature, tier) {text, feature},
    static const struct { const char *name; stin_feature feature; } list[] = {
        STIN_TECHNIQUE_LIST(SCENE_TECHNIQUE_)};
#undef SCENE_TECHNIQUE_
    char names[128] = "", path[256];
    size_t i;
    if (!name[0])
        return 1;
    for (i = 0; i < sizeof list / sizeof list[0]; i++) {
        if (list[i].feature != STIN_FEATURE_SURFACE)
            continue;
        if (!strcmp(list[i].name, name))
            return 1;
        snprintf(names + strlen(names), sizeof names - strlen(names), "%s%s",
                 names[0] ? ", " : "", list[i].name);
    }
    scene_join(path, sizeof path, where, "surface");
    return scene_fail(p, path, "'%s' is not a surface technique (%s, or none for automatic)",
                      name, names);
}

void scene_material_defaults(scene_material *m)
{
    const scene_material d = { "", { 0.8f, 0.8f, 0.8f, 1 }, { 0, 0, 0 }, 32, -1, -1, -1, 0.04f, "", 0, 0, 0, 0, 0 };
    char name[SCENE_NAME_MAX];
    memcpy(name, m->name, sizeof name);
    *m = d;
    memcpy(m->name, name, sizeof name);
}

static int parse_material(scene_parser *p, const cJSON *j, const char *where, scene *s,
                          int *used, scene_material *m)
{
    static const char *const keys[] = { "color", "opacity", "specular", "shininess", "albedo",
                                        "normal", "height", "height_scale", "surface",
                                        "self_shadow", "two_sided", "displace", "height_bias",
                                        NULL };
    char self_shadow[8] = "off";
    float shininess;
    char path[256];
    scene_material_defaults(m);
    shininess = m->shininess;
    if (!scene_check_object(p, j, where, keys) ||
        !scene_get_vector(p, j, "color", where, 3, SCENE_UNIT, m->color) ||
        !scene_get_number(p, j, "opacity", where, SCENE_UNIT, &m->color[3]) ||
        !scene_get_vector(p, j, "specular", where, 3, SCENE_UNIT, m->specular) ||
        !scene_get_number(p, j, "shininess", where, SCENE_NONNEGATIVE, &shininess) ||
        !texture_slot(p, j, "albedo", where, s, used, SCENE_TEXTURE_ALBEDO, &m->albedo) ||
        !texture_slot(p, j, "normal", where, s, used, SCENE_TEXTURE_NORMAL, &m->normal) ||
        !texture_slot(p, j, "height", where, s, used, SCENE_TEXTURE_HEIGHT, &m->height) ||
        !scene_get_number(p, j, "height_scale", where, SCENE_NONNEGATIVE, &m->height_scale) ||
        !scene_get_string(p, j, "surface", where, m->surface, sizeof m->surface) ||
        !scene_get_string(p, j, "self_shadow", where, self_shadow, sizeof self_shadow) ||
        !scene_get_bool(p, j, "two_sided", where, &m->two_sided) ||
        !scene_get_bool(p, j, "displace", where, &m->displace) ||
        !check_surface(p, where, m->surface))
        return 0;
    m->has_height_bias = cJSON_GetObjectItemCaseSensitive(j, "height_bias") != NULL;
    if (!scene_get_number(p, j, "height_bias", where, SCENE_ANY, &m->height_bias))
        return 0;
    m->self_shadow = !strcmp(self_shadow, "hard") ? 1 : !strcmp(self_shadow, "soft") ? 2 : 0;
    if (m->self_shadow == 0 && strcmp(self_shadow, "off")) {
        scene_join(path, sizeof path, where, "self_shadow");
        return scene_fail(p, path, "expected \"off\", \"hard\" or \"soft\" (got '%s')",
                          self_shadow);
    }
    if (shininess > 128) { /* the GL limit every tier shares */
        scene_join(path, sizeof path, where, "shininess");
        return scene_fail(p, path, "must be in [0, 128] (got %g)", shininess);
    }
    m->shininess = shininess;
    return 1;
}

static int parse_materials(scene_parser *p, const cJSON *j, scene *s)
{
    const cJSON *c;
    char where[256];
    int n = j ? cJSON_GetArraySize(j) : 0, *used, ok = 1;
    if (j && !cJSON_IsObject(j))
        return scene_fail(p, "materials", "expected an object of named materials");
    /* One spare slot for the implicit "default" material. */
    s->materials = calloc((size_t)n + 1, sizeof *s->materials);
    used = calloc((size_t)s->texture_count + 1, sizeof *used);
    if (!s->materials || !used) {
        free(used);
        return scene_fail(p, "materials", "out of memory");
    }
    n = 0;
    for (c = j ? j->child : NULL; c && ok; c = c->next, n++) {
        ok = check_name(p, "materials", c->string, s->materials[0].name, sizeof *s->materials, n);
        if (ok) {
            strcpy(s->materials[n].name, c->string);
            snprintf(where, sizeof where, "materials.%s", c->string);
            ok = parse_material(p, c, where, s, used, &s->materials[n]);
        }
        s->material_count = n + 1;
    }
    free(used);
    return ok;
}

static int find_named(const char *base, size_t stride, int count, const char *name)
{
    int i;
    for (i = 0; i < count; i++)
        if (strcmp(base + (size_t)i * stride, name) == 0)
            return i;
    return -1;
}

/* ---- objects ------------------------------------------------------------ */

static float det3(const float m[16])
{
    return m[0] * (m[5] * m[10] - m[9] * m[6]) - m[4] * (m[1] * m[10] - m[9] * m[2]) +
           m[8] * (m[1] * m[6] - m[5] * m[2]);
}

/* translate * rotate * scale, or an explicit matrix. */
static int parse_transform(scene_parser *p, const cJSON *j, const char *where, float out[16])
{
    float t[3] = { 0, 0, 0 }, r[4] = { 0, 1, 0, 0 }, sc[3] = { 1, 1, 1 }, m[16];
    const cJSON *scale = cJSON_GetObjectItemCaseSensitive(j, "scale");
    char path[256];
    memcpy(out, identity, sizeof identity);
    if (cJSON_GetObjectItemCaseSensitive(j, "matrix")) {
        if (cJSON_GetObjectItemCaseSensitive(j, "translate") || cJSON_GetObjectItemCaseSensitive(j, "rotate") || scale)
            return scene_fail(p, where, "'matrix' cannot be combined with translate, rotate or scale");
        if (!scene_get_vector(p, j, "matrix", where, 16, SCENE_ANY, out))
            return 0;
        scene_join(path, sizeof path, where, "matrix");
        if (out[3] != 0 || out[7] != 0 || out[11] != 0 || out[15] != 1)
            return scene_fail(p, path, "must be affine (last row 0 0 0 1, column-major)");
        if (!(det3(out) > 1e-12f))
            return scene_fail(p, path, "must keep orientation (determinant > 0)");
        return 1;
    }
    if (cJSON_IsNumber(scale)) {
        if (!scene_get_number(p, j, "scale", where, SCENE_POSITIVE, &sc[0]))
            return 0;
        sc[1] = sc[2] = sc[0];
    } else if (!scene_get_vector(p, j, "scale", where, 3, SCENE_POSITIVE, sc)) {
        return 0;
    }
    if (!scene_get_vector(p, j, "translate", where, 3, SCENE_ANY, t) ||
        !scene_get_vector(p, j, "rotate", where, 4, SCENE_ANY, r))
        return 0;
    {
        double len = sqrt((double)r[0] * r[0] + (double)r[1] * r[1] + (double)r[2] * r[2]);
        double a = r[3] * 3.14159265358979323846 / 180.0, c = cos(a), s = sin(a);
        double x, y, z;
        if (!(len > 0)) {
            scene_join(path, sizeof path, where, "rotate");
            return scene_fail(p, path, "axis (first three numbers) must not be zero");
        }
        x = r[0] / len, y = r[1] / len, z = r[2] / len;
        /* Rodrigues rotation, column-major. */
        memcpy(m, identity, sizeof identity);
        m[0] = (float)(c + x * x * (1 - c));
        m[1] = (float)(y * x * (1 - c) + z * s);
        m[2] = (float)(z * x * (1 - c) - y * s);
        m[4] = (float)(x * y * (1 - c) - z * s);
        m[5] = (float)(c + y * y * (1 - c));
        m[6] = (float)(z * y * (1 - c) + x * s);
        m[8] = (float)(x * z * (1 - c) + y * s);
        m[9] = (float)(y * z * (1 - c) - x * s);
        m[10] = (float)(c + z * z * (1 - c));
    }
    memcpy(out, identity, sizeof identity);
    out[0] = sc[0];
    out[5] = sc[1];
    out[10] = sc[2];
    scene_mat4_mul(m, out, out);
    out[12] = t[0];
    out[13] = t[1];
    out[14] = t[2];
    return 1;
}

/* "repeat": {"count": [nx, ny, nz], "step": [dx, dy, dz]} -> grid offsets. */
static int parse_repeat(scene_parser *p, const cJSON *j, const char *where, int count[3], float step[3])
{
    static const char *const keys[] = { "count", "step", NULL };
    const cJSON *r = cJSON_GetObjectItemCaseSensitive(j, "repeat");
    float cf[3] = { 1, 1, 1 };
    char path[256];
    int i;
    count[0] = count[1] = count[2] = 1;
    step[0] = step[1] = step[2] = 0;
    if (!r)
        return 1;
    scene_join(path, sizeof path, where, "repeat");
    if (!scene_check_object(p, r, path, keys) || !scene_require(p, r, "count", path) ||
        !scene_get_vector(p, r, "count", path, 3, SCENE_ANY, cf) ||
        !scene_get_vector(p, r, "step", path, 3, SCENE_ANY, step))
        return 0;
    for (i = 0; i < 3; i++) {
        if (cf[i] != floorf(cf[i]) || cf[i] < 1 || cf[i] > 10000) {
            snprintf(path, sizeof path, "%s.repeat.count", where);
            return scene_fail(p, path, "expected three integers in [1, 10000]");
        }
        count[i] = (int)cf[i];
    }
    return 1;
}

static int ensure_default_material(scene *s)
{
    int i = find_named(s->materials[0].name, sizeof *s->materials, s->material_count, "default");
    if (i >= 0)
        return i;
    /* parse_materials left room for exactly this one. */
    i = s->material_count++;
    strcpy(s->materials[i].name, "default");
    scene_material_defaults(&s->materials[i]);
    return i;
}

static int add_instances(scene_parser *p, scene *s, int *cap, const char *where, int mesh, int material,
                         const float m[16], const int count[3], const float step[3])
{
    long long n = (long long)count[0] * count[1] * count[2];
    int x, y, z;
    if (s->object_count + n > INSTANCES_MAX)
        return scene_fail(p, where, "more than %d object instances in the scene", INSTANCES_MAX);
    while (s->object_count + n > *cap) {
        int grown = *cap ? 2 * *cap : 64;
        scene_object *o = realloc(s->objects, (size_t)grown * sizeof *o);
        if (!o)
            return scene_fail(p, where, "out of memory");
        s->objects = o;
        *cap = grown;
    }
    for (z = 0; z < count[2]; z++)
        for (y = 0; y < count[1]; y++)
            for (x = 0; x < count[0]; x++) {
                scene_object *o = &s->objects[s->object_count++];
                o->mesh = mesh;
                o->material = material;
                memcpy(o->transform, m, 16 * sizeof(float));
                o->transform[12] += x * step[0];
                o->transform[13] += y * step[1];
                o->transform[14] += z * step[2];
            }
    return 1;
}

/* names: one SCENE_NAME_MAX slot per objects[] entry ("" when unnamed), for
 * csg, each named one in table (its entry). An entry of several parts (a model file's nodes) gives one instance
 * per part: object transform * node transform, and the node's material
 * unless the object names one. */
static int parse_objects(scene_parser *p, const cJSON *j, scene *s, const scene_entries *e,
                         char (*names)[SCENE_NAME_MAX], name_table *table, int *first,
                         int *instances)
{
    static const char *const keys[] = { "name", "mesh", "material", "translate", "rotate",
                                        "scale", "matrix", "repeat", NULL };
    const cJSON *c;
    char where[64], ref[SCENE_NAME_MAX], path[96];
    int i = 0, cap = 0;
    for (c = j->child; c; c = c->next, i++) {
        float m[16], step[3], world[16];
        int count[3], entry, material = -1, k, taken;
        snprintf(where, sizeof where, "objects[%d]", i);
        if (!scene_check_object(p, c, where, keys) || !scene_require(p, c, "mesh", where) ||
            !scene_get_string(p, c, "name", where, names[i], SCENE_NAME_MAX))
            return 0;
        if (names[i][0] && name_table_find(table, names[i], &taken)) {
            scene_join(path, sizeof path, where, "name");
            return scene_fail(p, path, "duplicate object name '%s'", names[i]);
        }
        if (names[i][0])
            name_table_add(table, names[i], i);
        scene_join(path, sizeof path, where, "mesh");
        if (!scene_get_string(p, c, "mesh", where, ref, sizeof ref))
            return 0;
        entry = scene_entries_find(e, ref);
        if (entry < 0)
            return scene_fail(p, path, "unknown mesh '%s'", ref);
        if (cJSON_GetObjectItemCaseSensitive(c, "material")) {
            scene_join(path, sizeof path, where, "material");
            if (!scene_get_string(p, c, "material", where, ref, sizeof ref))
                return 0;
            material = find_named(s->materials[0].name, sizeof *s->materials, s->material_count, ref);
            if (material < 0)
                return scene_fail(p, path, "unknown material '%s'", ref);
        }
        if (!parse_transform(p, c, where, m) || !parse_repeat(p, c, where, count, step))
            return 0;
        first[i] = s->object_count;
        for (k = 0; k < e->entries[entry].part_count; k++) {
            const scene_part *part = &e->parts[e->entries[entry].first_part + k];
            int mat = material >= 0 ? material : part->material >= 0 ? part->material
                                                                     : ensure_default_material(s);
            scene_mat4_mul(m, part->transform, world);
            if (!add_instances(p, s, &cap, where, part->mesh, mat, world, count, step))
                return 0;
        }
        instances[i] = s->object_count - first[i];
    }
    return 1;
}

/* ---- lights, camera, csg ----------------------------------------------------- */

static int unit_direction(scene_parser *p, const char *where, float d[3])
{
    char path[256];
    float len = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (!(len > 1e-6f)) {
        scene_join(path, sizeof path, where, "direction");
        return scene_fail(p, path, "must not be zero");
    }
    d[0] /= len;
    d[1] /= len;
    d[2] /= len;
    return 1;
}

static int parse_light(scene_parser *p, const cJSON *j, const char *where, scene_light *l)
{
    static const char *const point_keys[] = { "type", "position", "color", "intensity",
                                              "attenuation", "radius", "range", "pcf_kernel", NULL };
    static const char *const spot_keys[] = { "type", "position", "direction", "color", "intensity",
                                             "attenuation", "radius", "range", "cutoff", "exponent",
                                             "shadow_offset", "pcf_kernel", NULL };
    static const char *const dir_keys[] = { "type", "direction", "color", "intensity",
                                            "shadow_offset", "pcf_kernel", NULL };
    const scene_light d = { SCENE_LIGHT_POINT, { 0, 0, 0 }, { 0, -1, 0 }, { 1, 1, 1 }, 1,
                            { 1, 0, 0 }, 45, 0, 0, 0, { 0, 0 }, 0, 0 };
    char type[16] = "", path[256];
    *l = d;
    if (!cJSON_IsObject(j))
        return scene_fail(p, where, "expected an object");
    if (!scene_require(p, j, "type", where) || !scene_get_string(p, j, "type", where, type, sizeof type))
        return 0;
    if (strcmp(type, "point") == 0) {
        l->type = SCENE_LIGHT_POINT;
        if (!scene_check_object(p, j, where, point_keys) || !scene_require(p, j, "position", where))
            return 0;
    } else if (strcmp(type, "spot") == 0) {
        l->type = SCENE_LIGHT_SPOT;
        if (!scene_check_object(p, j, where, spot_keys) || !scene_require(p, j, "position", where) ||
            !scene_require(p, j, "direction", where))
            return 0;
    } else if (strcmp(type, "directional") == 0) {
        l->type = SCENE_LIGHT_DIRECTIONAL;
        if (!scene_check_object(p, j, where, dir_keys) || !scene_require(p, j, "direction", where))
            return 0;
    } else {
        scene_join(path, sizeof path, where, "type");
        return scene_fail(p, path, "unknown light type '%s' (point, spot, directional)", type);
    }
    if (!scene_get_vector(p, j, "position", where, 3, SCENE_ANY, l->position) ||
        !scene_get_vector(p, j, "direction", where, 3, SCENE_ANY, l->direction) ||
        !scene_get_vector(p, j, "color", where, 3, SCENE_NONNEGATIVE, l->color) ||
        !scene_get_number(p, j, "intensity", where, SCENE_NONNEGATIVE, &l->intensity) ||
        !scene_get_vector(p, j, "attenuation", where, 3, SCENE_NONNEGATIVE, l->attenuation) ||
        !scene_get_number(p, j, "radius", where, SCENE_NONNEGATIVE, &l->radius) ||
        !scene_get_number(p, j, "range", where, SCENE_NONNEGATIVE, &l->range) ||
        !scene_get_vector(p, j, "shadow_offset", where, 2, SCENE_ANY, l->shadow_offset) ||
        !scene_get_int(p, j, "pcf_kernel", where, 0, 5, &l->pcf_kernel) ||
        !scene_get_number(p, j, "cutoff", where, SCENE_POSITIVE, &l->spot_cutoff_deg) ||
        !scene_get_number(p, j, "exponent", where, SCENE_NONNEGATIVE, &l->spot_exponent) ||
        !unit_direction(p, where, l->direction))
        return 0;
    if (l->pcf_kernel == 2 || l->pcf_kernel == 4) {
        scene_join(path, sizeof path, where, "pcf_kernel");
        return scene_fail(p, path, "must be 1, 3 or 5 (got %d)", l->pcf_kernel);
    }
    if (l->attenuation[0] + l->attenuation[1] + l->attenuation[2] <= 0) {
        scene_join(path, sizeof path, where, "attenuation");
        return scene_fail(p, path, "must not be all zero");
    }
    if (l->spot_cutoff_deg > 90) {
        scene_join(path, sizeof path, where, "cutoff");
        return scene_fail(p, path, "must be in (0, 90] degrees (got %g)", l->spot_cutoff_deg);
    }
    if (l->spot_exponent > 128) {
        scene_join(path, sizeof path, where, "exponent");
        return scene_fail(p, path, "must be in [0, 128] (got %g)", l->spot_exponent);
    }
    return 1;
}

static int parse_lights(scene_parser *p, const cJSON *j, scene *s)
{
    const cJSON *c;
    char where[64];
    int n = cJSON_GetArraySize(j);
    if (!cJSON_IsArray(j))
        return scene_fail(p, "lights", "expected an array");
    if (n == 0)
        return 1;
    if (n > SCENE_LIGHTS_MAX)
        return scene_fail(p, "lights", "at most %d (got %d)", SCENE_LIGHTS_MAX, n);
    s->lights = calloc((size_t)n, sizeof *s->lights);
    if (!s->lights)
        return scene_fail(p, "lights", "out of memory");
    s->light_count = n;
    n = 0;
    for (c = j->child; c; c = c->next, n++) {
        snprintf(where, sizeof where, "lights[%d]", n);
        if (!parse_light(p, c, where, &s->lights[n]))
            return 0;
    }
    return 1;
}

static int parse_camera(scene_parser *p, const cJSON *j, scene_camera *cam)
{
    static const char *const keys[] = { "eye", "target", "up", "fovy", "near", "far", NULL };
    const scene_camera d = { { 0, 0, 5 }, { 0, 0, 0 }, { 0, 1, 0 }, 45, 0.1f, 100 };
    float f[3], cr[3];
    int i;
    *cam = d;
    if (!scene_check_object(p, j, "camera", keys) || !scene_require(p, j, "eye", "camera") ||
        !scene_require(p, j, "target", "camera") ||
        !scene_get_vector(p, j, "eye", "camera", 3, SCENE_ANY, cam->eye) ||
        !scene_get_vector(p, j, "target", "camera", 3, SCENE_ANY, cam->target) ||
        !scene_get_vector(p, j, "up", "camera", 3, SCENE_ANY, cam->up) ||
        !scene_get_number(p, j, "fovy", "camera", SCENE_POSITIVE, &cam->fovy_deg) ||
        !scene_get_number(p, j, "near", "camera", SCENE_POSITIVE, &cam->near_plane) ||
        !scene_get_number(p, j, "far", "camera", SCENE_POSITIVE, &cam->far_plane))
        return 0;
    for (i = 0; i < 3; i++)
        f[i] = cam->target[i] - cam->eye[i];
    cr[0] = f[1] * cam->up[2] - f[2] * cam->up[1];
    cr[1] = f[2] * cam->up[0] - f[0] * cam->up[2];
    cr[2] = f[0] * cam->up[1] - f[1] * cam->up[0];
    if (!(f[0] * f[0] + f[1] * f[1] + f[2] * f[2] > 1e-12f))
        return scene_fail(p, "camera.target", "must differ from camera.eye");
    if (!(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2] > 1e-12f))
        return scene_fail(p, "camera.up", "must not be zero or parallel to the view direction");
    if (cam->fovy_deg >= 180)
        return scene_fail(p, "camera.fovy", "must be in (0, 180) degrees (got %g)", cam->fovy_deg);
    if (cam->near_plane < CAMERA_NEAR_MIN)
        return scene_fail(p, "camera.near", "must be at least %g (got %g)", CAMERA_NEAR_MIN,
                          cam->near_plane);
    if (!(cam->far_plane > cam->near_plane))
        return scene_fail(p, "camera.far", "must be greater than camera.near");
    return 1;
}

/* Operands name objects or earlier named csg results (table: an object's
 * entry, or -1 - a result's); an object operand must be one instance (no
 * repeat, not a model file of several parts). */
static int parse_csg(scene_parser *p, const cJSON *j, name_table *table, const int *first,
                     const int *instances, scene *s)
{
    static const char *const keys[] = { "op", "a", "b", "name", NULL };
    static const char *const operand[] = { "a", "b" };
    const cJSON *c;
    char where[64], path[96], op[16] = "", ref[SCENE_NAME_MAX], (*results)[SCENE_NAME_MAX];
    int i = 0, k, ok = 1, taken;
    if (!cJSON_IsArray(j))
        return scene_fail(p, "csg", "expected an array");
    results = calloc((size_t)cJSON_GetArraySize(j) + 1, SCENE_NAME_MAX);
    s->csg = calloc((size_t)cJSON_GetArraySize(j) + 1, sizeof *s->csg);
    if (!results || !s->csg) {
        free(results);
        return scene_fail(p, "csg", "out of memory");
    }
    for (c = j->child; c && ok; c = c->next, i++) {
        snprintf(where, sizeof where, "csg[%d]", i);
        ok = scene_check_object(p, c, where, keys) && scene_require(p, c, "op", where) &&
             scene_require(p, c, "a", where) && scene_require(p, c, "b", where) &&
             scene_get_string(p, c, "op", where, op, sizeof op) &&
             scene_get_string(p, c, "name", where, results[i], SCENE_NAME_MAX);
        if (ok && strcmp(op, "subtract") != 0 && strcmp(op, "union") != 0 && strcmp(op, "intersect") != 0) {
            scene_join(path, sizeof path, where, "op");
            ok = scene_fail(p, path, "unknown operation '%s' (subtract, union, intersect)", op);
        }
        if (ok && results[i][0] && name_table_find(table, results[i], &taken)) {
            scene_join(path, sizeof path, where, "name");
            ok = scene_fail(p, path, "name '%s' is already taken", results[i]);
        }
        for (k = 0; k < 2 && ok; k++) {
            int object = -1, result = -1, named, *to = k ? &s->csg[i].b : &s->csg[i].a;
            ok = scene_get_string(p, c, operand[k], where, ref, sizeof ref);
            if (ok && name_table_find(table, ref, &named)) {
                object = named >= 0 ? named : -1;
                result = named < 0 ? -1 - named : -1;
            }
            scene_join(path, sizeof path, where, operand[k]);
            if (ok && object < 0 && result < 0)
                ok = scene_fail(p, path, "unknown object or csg result '%s'", ref);
            else if (ok && object >= 0 && instances[object] != 1)
                ok = scene_fail(p, path, "object '%s' is %d instances (repeat or a model file's "
                                "parts); a csg operand is one", ref, instances[object]);
            else if (ok && object >= 0)
                *to = first[object];
            else if (ok) {
                *to = -1 - result;
                s->csg[result].used = 1;
            }
        }
        if (ok) {
            s->csg[i].op = !strcmp(op, "union") ? SCENE_CSG_UNION
                         : !strcmp(op, "intersect") ? SCENE_CSG_INTERSECT : SCENE_CSG_SUBTRACT;
            s->csg_count = i + 1;
            if (results[i][0]) /* from here on: an entry's operands are earlier ones */
                name_table_add(table, results[i], -1 - i);
        }
    }
    free(results);
    return ok;
}

/* ---- top level ------------------------------------------------------------ */

static int parse_scene_objects(scene_parser *p, const cJSON *root, scene *s, const scene_entries *e)
{
    const cJSON *objects = cJSON_GetObjectItemCaseSensitive(root, "objects");
    const cJSON *csg = cJSON_GetObjectItemCaseSensitive(root, "csg");
    char (*names)[SCENE_NAME_MAX];
    name_table table;
    int ok, entries, *first, *instances;
    if (s->shadow_map_size & (s->shadow_map_size - 1))
        return scene_fail(p, "shadow_map_size", "must be a power of two in [16, 8192] (got %d)",
                          s->shadow_map_size);
    entries = cJSON_GetArraySize(objects);
    if (!cJSON_IsArray(objects) || entries == 0)
        return scene_fail(p, "objects", "expected a non-empty array");
    names = calloc((size_t)entries, SCENE_NAME_MAX);
    first = calloc((size_t)entries, sizeof *first);
    instances = calloc((size_t)entries, sizeof *instances);
    ok = name_table_init(&table, (size_t)entries + (size_t)cJSON_GetArraySize(csg));
    ok = ok && names && first && instances;
    if (!ok)
        scene_fail(p, "objects", "out of memory");
    ok = ok && parse_objects(p, objects, s, e, names, &table, first, instances) &&
         (!csg || parse_csg(p, csg, &table, first, instances, s));
    name_table_free(&table);
    free(names);
    free(first);
    free(instances);
    return ok;
}

static int parse_scene(scene_parser *p, const cJSON *root, scene *s)
{
    static const char *const keys[] = { "description", "width", "height", "camera", "ambient",
                                        "background", "meshes", "textures", "materials", "objects",
                                        "lights", "csg", "shadow_map_size", NULL };
    const cJSON *tex = cJSON_GetObjectItemCaseSensitive(root, "textures");
    const cJSON *lights = cJSON_GetObjectItemCaseSensitive(root, "lights");
    const cJSON *camera = cJSON_GetObjectItemCaseSensitive(root, "camera");
    char desc[1024];
    scene_entries e;
    int ok;

    s->width = s->height = 512;
    s->ambient[0] = s->ambient[1] = s->ambient[2] = 0.1f;
    if (!scene_check_object(p, root, "", keys) ||
        !scene_get_string(p, root, "description", "", desc, sizeof desc) ||
        !scene_get_int(p, root, "width", "", 1, IMAGE_SIZE_MAX, &s->width) ||
        !scene_get_int(p, root, "height", "", 1, IMAGE_SIZE_MAX, &s->height) ||
        !scene_get_vector(p, root, "ambient", "", 3, SCENE_UNIT, s->ambient) ||
        !scene_get_vector(p, root, "background", "", 4, SCENE_UNIT, s->background) ||
        !scene_get_int(p, root, "shadow_map_size", "", 16, 8192, &s->shadow_map_size) ||
        !scene_require(p, root, "meshes", "") || !scene_require(p, root, "objects", "") ||
        (camera && !parse_camera(p, camera, &s->camera)))
        return 0;
    s->has_camera = camera != NULL;
    memset(&e, 0, sizeof e);
    ok = parse_meshes(p, cJSON_GetObjectItemCaseSensitive(root, "meshes"), s, &e) &&
         (!tex || parse_textures(p, tex, s)) &&
         parse_materials(p, cJSON_GetObjectItemCaseSensitive(root, "materials"), s) &&
         scene_entries_add_materials(p, &e, s) && (!lights || parse_lights(p, lights, s)) &&
         parse_scene_objects(p, root, s, &e);
    scene_entries_free(&e);
    /* No camera in the file: one that frames everything (scene_camera.c). */
    if (ok && !camera)
        scene_camera_frame(s, s->width, s->height, &s->camera);
    return ok;
}

/* Turns cJSON's failure position into "line L, column C: problem". */
static int syntax_error(scene_parser *p, const char *text, const char *at)
{
    const char *c, *prev = at;
    int line = 1, col = 1;
    for (c = text; c < at; c++) {
        if (*c == '\n') {
            line++;
            col = 1;
        } else {
            col++;
        }
    }
    while (prev > text && strchr(" \t\r\n", prev[-1]))
        prev--;
    prev = prev > text ? prev - 1 : NULL;
    if (!*at)
        return scene_fail(p, "", "line %d, column %d: unexpected end of file", line, col);
    if (prev && *prev == ',' && (*at == '}' || *at == ']'))
        return scene_fail(p, "", "line %d, column %d: trailing ',' before '%c'", line, col, *at);
    if (prev && !strchr(",:[{", *prev) && strchr("\"{[-0123456789tfn", *at))
        return scene_fail(p, "", "line %d, column %d: expected ','", line, col);
    return scene_fail(p, "", "line %d, column %d: unexpected '%.12s'", line, col, at);
}

static char *read_text(scene_parser *p)
{
    FILE *f = fopen(p->file, "rb");
    char *text = NULL;
    long size;
    if (!f) {
        scene_fail(p, "", "cannot open: %s", strerror(errno));
        return NULL;
    }
    if (fseek(f, 0, SEEK_END) != 0 || (size = ftell(f)) < 0 || size > SCENE_FILE_MAX ||
        fseek(f, 0, SEEK_SET) != 0)
        scene_fail(p, "", "cannot read (not a regular file, or larger than %ld bytes)", SCENE_FILE_MAX);
    else if (!(text = malloc((size_t)size + 1)))
        scene_fail(p, "", "out of memory");
    else if (fread(text, 1, (size_t)size, f) != (size_t)size) {
        scene_fail(p, "", "read error");
        free(text);
        text = NULL;
    } else {
        text[size] = '\0';
        if (strlen(text) != (size_t)size) {
            scene_fail(p, "", "contains a NUL byte; not a JSON text file");
            free(text);
            text = NULL;
        }
    }
    fclose(f);
    return text;
}

/* Parses text (NUL-terminated) as the contents of path. */
static int load_from_text(scene_parser *p, const char *path, const char *text, scene *out)
{
    scene s;
    cJSON *root;
    const char *end = NULL, *body;
    int ok;
    memset(&s, 0, sizeof s);
    body = strncmp(text, "\xEF\xBB\xBF", 3) == 0 ? text + 3 : text; /* UTF-8 BOM */
    root = cJSON_ParseWithOpts(body, &end, 1);
    if (!root)
        return syntax_error(p, body, end ? end : body);
    strcpy(s.path, path);
    ok = parse_scene(p, root, &s);
    cJSON_Delete(root);
    if (!ok) {
        scene_free(&s);
        return 0;
    }
    *out = s;
    return 1;
}

static int start(scene_parser *p, const char *path, scene *out, char *err, size_t err_size)
{
    memset(out, 0, sizeof *out);
    p->file = path;
    p->err = err;
    p->err_size = err_size;
    if (err && err_size)
        err[0] = '\0';
    if (strlen(path) >= sizeof out->path)
        return scene_fail(p, "", "path longer than %zu characters", sizeof out->path - 1);
    return 1;
}

int scene_load(const char *path, scene *out, char *err, size_t err_size)
{
    scene_parser p;
    char *text;
    int ok;
    if (!start(&p, path, out, err, err_size) || !(text = read_text(&p)))
        return 0;
    ok = load_from_text(&p, path, text, out);
    free(text);
    return ok;
}

int scene_load_text(const char *path, const char *text, size_t size, scene *out, char *err,
                    size_t err_size)
{
    scene_parser p;
    if (!start(&p, path, out, err, err_size))
        return 0;
    if (memchr(text, '\0', size))
        return scene_fail(&p, "", "contains a NUL byte; not a JSON text file");
    return load_from_text(&p, path, text, out);
}

void scene_free(scene *s)
{
    int i;
    for (i = 0; i < s->mesh_count; i++)
        scene_mesh_release(&s->meshes[i]);
    for (i = 0; i < s->texture_count; i++)
        free(s->textures[i].rgba);
    free(s->warnings);
    free(s->meshes);
    free(s->textures);
    free(s->materials);
    free(s->objects);
    free(s->lights);
    free(s->csg);
    memset(s, 0, sizeof *s);
}
