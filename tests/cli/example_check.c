/* SPDX-License-Identifier: MIT */
/* Checks an example's PPM (examples/example_scene.h) against the exact
 * answer: per floor pixel, whether the segment to the light passes through
 * the sphere. Pixels within 0.03 (6% of the radius: the 48x24 mesh is
 * within 0.5% of the sphere, the rest is the shadow technique's edge) of
 * the sphere's outline, in the image or in the shadow, are left out; a
 * shadowed pixel must be nearer the ambient-only grey than the lit grey.
 * Prints one PASS/FAIL line. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define W 320
#define H 240
#define MARGIN 0.03
#define BUDGET 0.002

static const double eye[3] = {0, 3, 6}, at[3] = {0, 0.4, 0}, light[3] = {1.5, 4, 1};
static const double centre[3] = {0, 0.6, 0}, radius = 0.5, ambient = 0.15, albedo = 0.8;

static double dot(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void normalize(double *v)
{
    double l = sqrt(dot(v, v));
    v[0] /= l, v[1] /= l, v[2] /= l;
}

/* Distance from the sphere's centre to the segment a..b. */
static double segment_distance(const double *a, const double *b)
{
    double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, ac[3], t, p[3];
    int k;
    for (k = 0; k < 3; k++)
        ac[k] = centre[k] - a[k];
    t = dot(ac, ab) / dot(ab, ab);
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    for (k = 0; k < 3; k++)
        p[k] = a[k] + t * ab[k] - centre[k];
    return sqrt(dot(p, p));
}

int main(int argc, char **argv)
{
    unsigned char *img = malloc(3 * W * H);
    double f[3] = {at[0] - eye[0], at[1] - eye[1], at[2] - eye[2]}, s[3], u[3];
    double half = tan(45.0 * M_PI / 360.0);
    long checked = 0, shadowed = 0, wrong = 0;
    int x, y, w, h, maxv;
    FILE *in = argc == 2 ? fopen(argv[1], "rb") : NULL;
    if (!in || !img || fscanf(in, "P6 %d %d %d", &w, &h, &maxv) != 3 || w != W || h != H ||
        fgetc(in) == EOF || fread(img, 1, 3 * W * H, in) != 3 * W * H) {
        printf("FAIL %s: not a %dx%d PPM\n", argc == 2 ? argv[1] : "example", W, H);
        return 0;
    }
    fclose(in);
    normalize(f);
    s[0] = -f[2], s[1] = 0, s[2] = f[0];
    normalize(s);
    u[0] = s[1] * f[2] - s[2] * f[1], u[1] = s[2] * f[0] - s[0] * f[2], u[2] = s[0] * f[1] - s[1] * f[0];
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            double nx = (2.0 * (x + 0.5) / W - 1.0) * half * W / H;
            double ny = (1.0 - 2.0 * (y + 0.5) / H) * half; /* PPM rows top to bottom */
            double d[3], p[3], l[3], t, lit, expect_shadow, dist, grey;
            int k;
            for (k = 0; k < 3; k++)
                d[k] = f[k] + nx * s[k] + ny * u[k];
            normalize(d);
            if (d[1] >= 0)
                continue;
            t = -eye[1] / d[1];
            for (k = 0; k < 3; k++)
                p[k] = eye[k] + t * d[k];
            if (fabs(p[0]) > 4 - MARGIN || fabs(p[2]) > 4 - MARGIN ||
                segment_distance(eye, p) < radius + MARGIN)
                continue; /* off the floor, or the sphere (or its outline) in front */
            dist = segment_distance(p, light);
            if (fabs(dist - radius) < MARGIN)
                continue; /* the shadow's edge */
            for (k = 0; k < 3; k++)
                l[k] = light[k] - p[k];
            normalize(l);
            lit = albedo * (ambient + (l[1] > 0 ? l[1] : 0));
            lit = lit > 1 ? 1 : lit;
            expect_shadow = dist < radius;
            grey = img[3 * (y * W + x) + 1] / 255.0;
            checked++;
            shadowed += expect_shadow != 0;
            if ((grey < 0.5 * (lit + albedo * ambient)) != expect_shadow)
                wrong++;
        }
    if (checked > 0 && shadowed >= 200 && wrong <= BUDGET * checked)
        printf("PASS %s: %ld of %ld floor pixels (%ld in the exact shadow) on the wrong side of "
               "lit/ambient (at most %.1f%%)\n", argv[1], wrong, checked, shadowed, 100 * BUDGET);
    else
        printf("FAIL %s: %ld of %ld floor pixels (%ld in the exact shadow) on the wrong side of "
               "lit/ambient (at most %.1f%%, at least 200 shadowed)\n", argv[1], wrong, checked,
               shadowed, 100 * BUDGET);
    free(img);
    return 0;
}
