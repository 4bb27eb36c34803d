/* SPDX-License-Identifier: MIT */
/* stin on an OSMesa context (software, no display): a sphere's shadow on a
 * floor, written to the PPM named on the command line.
 *   cc osmesa_shadow.c $(pkg-config --cflags --libs stin) -lOSMesa -lm */
#include "example_scene.h"

#include <GL/osmesa.h>

/* stin asks for every GL entry point through this (function pointers do
 * not convert to void * in ISO C: copy the bits). */
static void *get_proc(void *user, const char *name)
{
    OSMESAproc fn = OSMesaGetProcAddress(name);
    void *p;
    (void)user;
    memcpy(&p, &fn, sizeof p);
    return p;
}

int main(int argc, char **argv)
{
    /* RGBA with a 24-bit depth and an 8-bit stencil buffer (stencil volumes) */
    OSMesaContext osm = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *pixels = malloc(4u * EXAMPLE_W * EXAMPLE_H);
    int failed;
    if (argc != 2 || !osm || !pixels ||
        !OSMesaMakeCurrent(osm, pixels, GL_UNSIGNED_BYTE, EXAMPLE_W, EXAMPLE_H)) {
        fprintf(stderr, "usage: osmesa_shadow OUT.ppm (and an OSMesa context)\n");
        return 2;
    }
    failed = example_render(get_proc, NULL, 0, NULL);
    glFinish(); /* OSMesa draws into `pixels`, rows bottom to top */
    failed = failed || write_ppm(argv[1], pixels);
    OSMesaDestroyContext(osm);
    free(pixels);
    return failed;
}
