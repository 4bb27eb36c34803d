/* SPDX-License-Identifier: MIT */
/* Shadow volumes cut past the visible receivers and culled against the view
 * (shadow/volume_reach.c). The camera sits at the origin looking down -z
 * (view = identity, 90 degrees, near 0.1, far plane at infinity as the
 * volumes' frame draws it); a floor at y = -2 is the receiver. A cut is
 * exact only if every receiver point, the eye and the caster lie inside it;
 * a cull is exact only if the cut volume misses the frustum. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <string.h>

#include "shadow/volume_reach.h"
#include "render/draw_bounds.h"

static float side(const float pl[4], const float p[3])
{
    return pl[0] * p[0] + pl[1] * p[1] + pl[2] * p[2] + pl[3];
}

static void box_corners(const float lo[3], const float hi[3], float out[24])
{
    int c, k;
    for (c = 0; c < 8; c++)
        for (k = 0; k < 3; k++)
            out[3 * c + k] = (c >> k) & 1 ? hi[k] : lo[k];
}

/* The reach a frame would compute: the floor (x -5..5, z -10..-1) and the eye. */
static void make_reach(stin__volume_reach *r, const float light[4])
{
    float vp[16];
    const float n = 0.1f, eps = 2.4e-7f;
    memset(r, 0, sizeof *r);
    memset(vp, 0, sizeof vp);
    vp[0] = vp[5] = 1.0f; /* cot(45 degrees) */
    vp[10] = eps - 1.0f;
    vp[11] = -1.0f;
    vp[14] = (eps - 2.0f) * n;
    stin__frustum_planes(vp, r->camera);
    memcpy(r->light, light, sizeof r->light);
    r->bounded = 1;
    r->box_min[0] = -5.0f;
    r->box_min[1] = -2.0f;
    r->box_min[2] = -10.0f;
    r->box_max[0] = 5.0f;
    r->box_max[1] = 0.0f; /* the eye */
    r->box_max[2] = 0.0f;
}

static void assert_inside(const float pl[4], const float *pts, int n)
{
    int i;
    for (i = 0; i < n; i++)
        assert_true(side(pl, pts + 3 * i) <= 0.0f);
}

/* A sun straight above: the cut is a horizontal plane just below the floor. */
static void test_directional_cut_just_past_the_floor(void **state)
{
    static const float light[4] = {0, 1, 0, 0}, lo[3] = {-1, -1, -6}, hi[3] = {1, 0, -4};
    stin__volume_reach r;
    float corners[24], recv[24], pl[4], below[3] = {0, -2.05f, -5};
    (void)state;
    make_reach(&r, light);
    box_corners(lo, hi, corners);
    box_corners(r.box_min, r.box_max, recv);
    assert_int_equal(stin__volume_reach_caster(&r, corners, pl), 1);
    assert_true(pl[1] < -0.999f && pl[0] == 0.0f && pl[2] == 0.0f); /* normal: down */
    assert_inside(pl, corners, 8);
    assert_inside(pl, recv, 8);
    assert_true(side(pl, below) > 0.0f); /* 5 cm under the floor is cut off */
}

/* A point light: the cut crosses the axis from the light through the caster,
 * every receiver corner inside; a light inside the caster's bounds cuts
 * nothing (no plane crosses every ray). */
static void test_point_cut_and_light_inside(void **state)
{
    static const float light[4] = {0, 4, -5, 1}, lo[3] = {-1, 0.5f, -6}, hi[3] = {1, 1.5f, -4};
    static const float inside[4] = {0, 1, -5, 1};
    stin__volume_reach r;
    float corners[24], recv[24], pl[4];
    (void)state;
    make_reach(&r, light);
    box_corners(lo, hi, corners);
    box_corners(r.box_min, r.box_max, recv);
    assert_int_equal(stin__volume_reach_caster(&r, corners, pl), 1);
    assert_true(pl[3] != -1.0f);
    assert_inside(pl, corners, 8);
    assert_inside(pl, recv, 8);
    make_reach(&r, inside);
    assert_int_equal(stin__volume_reach_caster(&r, corners, pl), 1);
    assert_true(pl[0] == 0.0f && pl[1] == 0.0f && pl[2] == 0.0f && pl[3] == -1.0f);
}

/* Behind the eye with the sun above, the volume never enters the view: culled.
 * High above the view, its shadow still falls on the visible floor: kept. */
static void test_cull_only_what_cannot_reach_the_view(void **state)
{
    static const float light[4] = {0, 1, 0, 0};
    static const float behind_lo[3] = {-1, -1, 4}, behind_hi[3] = {1, 0, 6};
    static const float above_lo[3] = {-1, 20, -6}, above_hi[3] = {1, 21, -4};
    stin__volume_reach r;
    float corners[24], pl[4];
    (void)state;
    make_reach(&r, light);
    box_corners(behind_lo, behind_hi, corners);
    assert_int_equal(stin__volume_reach_caster(&r, corners, pl), 0);
    box_corners(above_lo, above_hi, corners);
    assert_int_equal(stin__volume_reach_caster(&r, corners, pl), 1);
    r.bounded = 0; /* STIN_DEBUG_VOLUME_UNBOUNDED: nothing cut or culled */
    box_corners(behind_lo, behind_hi, corners);
    assert_int_equal(stin__volume_reach_caster(&r, corners, pl), 1);
    assert_true(pl[3] == -1.0f);
}

/* The world plane in a caster's object space: a point keeps its side. */
static void test_plane_to_object_keeps_sides(void **state)
{
    static const float model[16] = {2, 0, 0, 0, 0, 0.5f, 0, 0, 0, 0, 1, 0, 3, -1, 2, 1};
    static const float world[4] = {0.6f, -0.8f, 0, 1.5f}, p[3] = {0.25f, -4, 1};
    float obj[4], w[3];
    (void)state;
    stin__volume_plane_to_object(world, model, obj);
    stin__mat4_transform_point(model, p, w);
    assert_true(side(obj, p) - side(world, w) < 1e-5f && side(world, w) - side(obj, p) < 1e-5f);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_directional_cut_just_past_the_floor),
        cmocka_unit_test(test_point_cut_and_light_inside),
        cmocka_unit_test(test_cull_only_what_cannot_reach_the_view),
        cmocka_unit_test(test_plane_to_object_keeps_sides),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
