/* SPDX-License-Identifier: MIT */
/* The hooks features lend the lighting paths (render/path_features.h): with
 * none lent every answer is a context without the feature's, and with some
 * lent the first feature that has a hook gives the answer, or each one's is
 * called in the list's order. No GL: the wrappers only pick and call. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <string.h>

#include "internal.h"

static stin_context ctx;
static char calls[16]; /* which stub hooks ran, in order */

static void called(char c)
{
    size_t n = strlen(calls);
    if (n + 1 < sizeof calls)
        calls[n] = c;
}

static stin__draw draw_of_opacity(float a)
{
    stin__draw d;
    memset(&d, 0, sizeof d);
    d.material.color[3] = a;
    return d;
}

static void test_no_features_lent(void **state)
{
    stin__draw opaque = draw_of_opacity(1.0f), blended = draw_of_opacity(0.5f);
    stin_material m;
    (void)state;
    memset(&ctx, 0, sizeof ctx);
    memset(&m, 0, sizeof m);
    assert_null(*stin__path_features(&ctx));
    assert_int_equal(stin__lit_variant_top(&ctx), STIN__SURF_PLAIN);
    assert_int_equal(stin__lit_variant_for(&ctx, &m), STIN__SURF_PLAIN);
    stin__lit_variant_failed(&ctx, STIN__SURF_PLAIN, "no feature: nothing to step down");
    assert_int_equal(stin__camera_set(&ctx, &opaque), STIN__OPAQUE);
    assert_int_equal(stin__camera_set(&ctx, &blended), STIN__BLENDED);
    assert_int_equal(stin__light_maps_active(&ctx), 0);
    stin__light_maps_make(&ctx, 0);
    stin__light_maps_done(&ctx);
}

static int variant_top(const stin_context *c) { (void)c; return STIN__SURF_POM; }
static int variant_for(stin_context *c, const stin_material *m)
{
    (void)c;
    return m->normal_map.id ? STIN__SURF_NORMAL : STIN__SURF_PLAIN;
}
static void variant_failed(stin_context *c, int built, const char *msg)
{
    (void)c;
    (void)msg;
    called((char)('0' + built));
}
static int every_set(const stin_context *c, const stin__draw *d)
{
    (void)c;
    (void)d;
    return STIN__ALL;
}
static int maps_active(const stin_context *c) { (void)c; return 1; }
static void light_a(stin_context *c, uint32_t li) { (void)c; called((char)('a' + li)); }
static void light_b(stin_context *c, uint32_t li) { (void)c; called((char)('A' + li)); }
static void done_a(stin_context *c) { (void)c; called('x'); }

static void test_first_hook_answers_and_each_is_called(void **state)
{
    stin__path_feature bare, maps, surface;
    const stin__path_feature *list[4];
    stin__draw opaque = draw_of_opacity(1.0f);
    stin_material m;
    (void)state;
    memset(&ctx, 0, sizeof ctx);
    memset(&bare, 0, sizeof bare);
    memset(&m, 0, sizeof m);
    maps = bare;
    maps.maps_active = maps_active;
    maps.light = light_a;
    maps.light_done = done_a;
    surface = bare;
    surface.variant_top = variant_top;
    surface.variant_for = variant_for;
    surface.variant_failed = variant_failed;
    surface.camera_set = every_set;
    surface.light = light_b;
    list[0] = &bare;
    list[1] = &maps;
    list[2] = &surface;
    list[3] = NULL;
    ctx.path_features = list;
    calls[0] = '\0';
    assert_int_equal(stin__lit_variant_top(&ctx), STIN__SURF_POM);
    m.normal_map.id = 1;
    assert_int_equal(stin__lit_variant_for(&ctx, &m), STIN__SURF_NORMAL);
    stin__lit_variant_failed(&ctx, STIN__SURF_PARALLAX, "pom failed");
    assert_int_equal(stin__camera_set(&ctx, &opaque), STIN__ALL);
    assert_int_equal(stin__light_maps_active(&ctx), 1);
    stin__light_maps_make(&ctx, 2);
    stin__light_maps_done(&ctx);
    assert_string_equal(calls, "2cCx"); /* in the list's order, those with the hook */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_no_features_lent),
        cmocka_unit_test(test_first_hook_answers_and_each_is_called),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
