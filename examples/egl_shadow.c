/* SPDX-License-Identifier: MIT */
/* stin on a headless EGL context (Mesa's surfaceless platform, or a GPU's
 * driver): the frame goes into the application's framebuffer object with a
 * depth-stencil attachment, then to the PPM named on the command line.
 *   cc egl_shadow.c $(pkg-config --cflags --libs stin) -lEGL -lm */
#include "example_egl.h"

int main(int argc, char **argv)
{
    example_egl e;
    int failed;
    const char *out = NULL;
    if (example_egl_args(&e, argc, argv, &out))
        return 2;
    if (example_egl_open(&e, "egl_shadow"))
        return 2;
    failed = example_render(get_proc, NULL, e.fbo, NULL);
    return example_egl_close(&e, out) || failed;
}
