/* SPDX-License-Identifier: MIT */
/* libFuzzer target: the scene loader (JSON text -> scene) on any bytes.
 * Relative file names resolve against tests/scenes/, so mutated scenes reach
 * the example models and textures too. Run from the repository root. */
#include "scene.h"
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
        if (scene_load_text("tests/scenes/fuzz.json", text, size, &s, err, sizeof err))
            scene_free(&s);
        else if (!err[0] || strchr(err, '\n'))
            abort(); /* every failure has exactly one line to say */
    }
    cJSON_Delete(probe);
    free(text);
    return 0;
}
