/* SPDX-License-Identifier: MIT */
/* Checks an example's PPM (examples/example_scene.h) against the exact
 * answer: per floor pixel, whether the segment to the light passes through
 * the sphere. Pixels within 0.03 (6% of the radius: the 48x24 mesh is
 * within 0.5% of the sphere, the rest is the shadow technique's edge) of
 * the sphere's outline, in the image or in the shadow, are left out; a
 * shadowed pixel must be nearer the ambient-only grey than the lit grey.
 * examples/skinned.c's picture (a path containing "skinned") is checked the
 * same way against its tube's last pose: the points within 0.2 of the two
 * bones' segments (the second turned up 60 degrees at the joint); also left
 * out where the nearest point of the bones lies within 0.35 of the joint
 * (linear blend skinning thins the tube there) or within 0.25 of an end
 * (the caps are flat, not round), and the margin is 0.04 (the 24-sided
 * tube is within 1.7% of its circle).
 * Prints one PASS/FAIL line. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 320
#define H 240
#define MARGIN 0.03
#define BUDGET 0.002

static const double eye[3] = {0, 3, 6}, at[3] = {0, 0.4, 0}, light[3] = {1.5, 4, 1};
static const double centre[3] = {0, 0.6, 0}, ambient = 0.15, albedo = 0.8;
static double radius = 0.5, margin = MARGIN;
/* the skinned tube's bones: (-1.2, 0.7, 0) to the joint (0, 0.7, 0), then
 * 1.2 at 60 degrees; 0 bones: the sphere */
#define BONE 1.2
static double bones[3][3];
static int tube;

static double dot(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void normalize(double *v)
{
    double l = sqrt(dot(v, v));
    v[0] /= l, v[1] /= l, v[2] /= l;
}

static double point_segment(const double *p, const double *a, const double *b, double *t_out)
{
    double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, ap[3], t, q[3];
    int k;
    for (k = 0; k < 3; k++)
        ap[k] = p[k] - a[k];
    t = dot(ap, ab) / dot(ab, ab);
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    for (k = 0; k < 3; k++)
        q[k] = a[k] + t * ab[k] - p[k];
    if (t_out)
        *t_out = t;
    return sqrt(dot(q, q));
}

static double clamp01(double v) { return v < 0 ? 0 : v > 1 ? 1 : v; }

/* Distance between segments a..b and c..d (both of some length), and how
 * far along c..d (0..1) the nearest point lies: the closest parameters of
 * the two lines, each clamped to its segment and the other recomputed. */
static double segment_segment(const double *a, const double *b, const double *c,
                              const double *d, double *t_out)
{
    double d1[3], d2[3], r[3], x[3], aa, e, f, bb, cc, denom, s, t;
    int k;
    for (k = 0; k < 3; k++) {
        d1[k] = b[k] - a[k];
        d2[k] = d[k] - c[k];
        r[k] = a[k] - c[k];
    }
    aa = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r), cc = dot(d1, r), bb = dot(d1, d2);
    denom = aa * e - bb * bb;
    s = denom > 1e-12 * aa * e ? clamp01((bb * f - cc * e) / denom) : 0;
    t = (bb * s + f) / e;
    if (t < 0)
        t = 0, s = clamp01(-cc / aa);
    else if (t > 1)
        t = 1, s = clamp01((bb - cc) / aa);
    for (k = 0; k < 3; k++)
        x[k] = a[k] + d1[k] * s - c[k] - d2[k] * t;
    *t_out = t;
    return sqrt(dot(x, x));
}

/* Distance from the occluder's core (the sphere's centre, or the bones) to
 * the segment a..b; along: how far along the bones the nearest point lies. */
static double segment_distance(const double *a, const double *b, double *along)
{
    double best = 1e30, t, d;
    int j;
    *along = 0;
    if (!tube)
        return point_segment(centre, a, b, NULL);
    for (j = 0; j < 2; j++) {
        d = segment_segment(a, b, bones[j], bones[j + 1], &t);
        if (d < best) {
            best = d;
            *along = (j + t) * BONE;
        }
    }
    return best;
}

/* Pixels the tube's model cannot decide: near the joint or an end. */
static int undecided(double along)
{
    return tube && (fabs(along - BONE) < 0.35 || along < 0.25 || along > 2 * BONE - 0.25);
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
    tube = strstr(argv[1], "skinned") != NULL;
    if (tube) {
        double a = 60.0 * M_PI / 180.0;
        bones[0][0] = -BONE, bones[0][1] = 0.7;
        bones[1][1] = 0.7;
        bones[2][0] = BONE * cos(a), bones[2][1] = 0.7 + BONE * sin(a);
        radius = 0.2;
        margin = 0.04;
    }
    normalize(f);
    s[0] = -f[2], s[1] = 0, s[2] = f[0];
    normalize(s);
    u[0] = s[1] * f[2] - s[2] * f[1], u[1] = s[2] * f[0] - s[0] * f[2], u[2] = s[0] * f[1] - s[1] * f[0];
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            double nx = (2.0 * (x + 0.5) / W - 1.0) * half * W / H;
            double ny = (1.0 - 2.0 * (y + 0.5) / H) * half; /* PPM rows top to bottom */
            double d[3], p[3], l[3], t, lit, expect_shadow, dist, grey, along;
            int k;
            for (k = 0; k < 3; k++)
                d[k] = f[k] + nx * s[k] + ny * u[k];
            normalize(d);
            if (d[1] >= 0)
                continue;
            t = -eye[1] / d[1];
            for (k = 0; k < 3; k++)
                p[k] = eye[k] + t * d[k];
            if (fabs(p[0]) > 4 - margin || fabs(p[2]) > 4 - margin ||
                segment_distance(eye, p, &along) < radius + margin)
                continue; /* off the floor, or the occluder (or its outline) in front */
            dist = segment_distance(p, light, &along);
            if (fabs(dist - radius) < margin || (dist < radius + margin && undecided(along)))
                continue; /* the shadow's edge, or where the model is not the mesh */
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
