/* SPDX-License-Identifier: MIT */
/* libFuzzer target: the scene loader (JSON text -> scene) on any bytes,
 * then the csg list as products (a DAG: operands before their node, each
 * primitive in range) and stin's checks of them (stin_csg_measure; no GL).
 * Relative file names resolve against tests/scenes/, so mutated scenes reach
 * the example models and textures too. Run from the repository root. */
#include "scene.h"
#include "scene_csg.h"
#include "scene_internal.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Numbers above this skip the input: sizes and counts up to the format's
 * limits (8192^2 textures, 10^4-instance grids) are legal but take seconds
 * each, which would starve the search; unit tests cover those paths. */
#define FUZZ_NUMBER_MAX 300.0

static int has_big_number(const cJSON *j)
{
    for (; j; j = j->next) {
        if (cJSON_IsNumber(j) && !(j->valuedouble <= FUZZ_NUMBER_MAX && j->valuedouble >= -FUZZ_NUMBER_MAX))
            return 1;
        if (has_big_number(j->child))
            return 1;
    }
    return 0;
}

/* Every product's nodes name earlier nodes and its own primitives, which
 * are objects of the scene; the checks fail with one line or pass. */
static void check_products(const scene *s)
{
    scene_csg_products p;
    stin_desc desc;
    char err[1024] = "";
    int i, k, r;
    if (!scene_csg_products_build(s, &p))
        return; /* out of memory */
    for (i = 0; i < p.count; i++) {
        const scene_gpu_csg *c = &p.products[i];
        for (k = 0; c->nodes && k < c->node_count; k++) {
            const stin_csg_node *n = &c->nodes[k];
            if (n->op == STIN_CSG_PRIMITIVE ? n->primitive >= (uint32_t)c->primitive_count
                                            : n->a >= (uint32_t)k || n->b >= (uint32_t)k)
                abort();
        }
        for (k = 0; k < c->primitive_count; k++)
            if (c->objects[k] < 0 || c->objects[k] >= s->object_count)
                abort();
    }
    memset(&desc, 0, sizeof desc);
    r = scene_csg_products_check(s, &p, &desc, err, sizeof err);
    if (r == 0 && (!err[0] || strchr(err, '\n')))
        abort();
    scene_csg_products_free(&p);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text, err[1024];
    cJSON *probe;
    scene s;
    if (size > 65536)
        return 0;
    text = malloc(size + 1);
    if (!text)
        return 0;
    memcpy(text, data, size);
    text[size] = '\0';
    probe = cJSON_Parse(text);
    if (!has_big_number(probe)) {
        scene_import_seconds = 5; /* a looping decoder costs 5 s, not 60 */
        if (scene_load_text("tests/scenes/fuzz.json", text, size, &s, err, sizeof err)) {
            check_products(&s);
            scene_free(&s);
        }
        else if (!err[0] || strchr(err, '\n'))
            abort(); /* every failure has exactly one line to say */
    }
    cJSON_Delete(probe);
    free(text);
    return 0;
}
