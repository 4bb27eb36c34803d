/* SPDX-License-Identifier: MIT */
/* Printable names of every public enum, technique name round trips, and the
 * heap-free formatter (stin__format) that every log line goes through. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <limits.h>
#include <string.h>

#include "internal.h"

static void assert_named(const char *name, const char *unknown)
{
    assert_non_null(name);
    assert_true(name[0] != '\0');
    assert_string_not_equal(name, unknown);
}

/* n names, none empty, none equal to another. */
static void assert_distinct(const char *const *names, int n)
{
    int i, j;
    for (i = 0; i < n; i++)
        for (j = i + 1; j < n; j++)
            assert_string_not_equal(names[i], names[j]);
}

static void test_results_have_names(void **state)
{
    const char *names[STIN_ERROR_INVALID_STATE + 1];
    int r;
    (void)state;
    for (r = STIN_OK; r <= STIN_ERROR_INVALID_STATE; r++) {
        names[r] = stin_result_name((stin_result)r);
        assert_named(names[r], "unknown result");
    }
    assert_distinct(names, STIN_ERROR_INVALID_STATE + 1);
    assert_string_equal(stin_result_name((stin_result)(STIN_ERROR_INVALID_STATE + 1)),
                        "unknown result");
}

static void test_log_items_have_text(void **state)
{
    const char *text[STIN_LOG_ITEM_COUNT];
    int i;
    (void)state;
    for (i = 0; i < STIN_LOG_ITEM_COUNT; i++) {
        text[i] = stin_log_item_text((stin_log_item)i);
        assert_named(text[i], "unknown log item");
    }
    assert_distinct(text, STIN_LOG_ITEM_COUNT);
    assert_string_equal(stin_log_item_text(STIN_LOG_ITEM_COUNT), "unknown log item");
}

static void test_caps_have_names(void **state)
{
    const char *names[STIN_CAP_COUNT];
    int c;
    (void)state;
    for (c = 0; c < STIN_CAP_COUNT; c++) {
        names[c] = stin_cap_name((stin_cap)c);
        assert_named(names[c], "unknown capability");
    }
    assert_distinct(names, STIN_CAP_COUNT);
    assert_string_equal(stin_cap_name(STIN_CAP_COUNT), "unknown capability");
    assert_true(STIN_CAP_COUNT <= 64); /* they fit the uint64_t masks */
}

static void test_tiers_and_features_have_names(void **state)
{
    static const stin_tier tiers[] = {STIN_TIER_AUTO, STIN_TIER_GL1, STIN_TIER_GL2, STIN_TIER_GL4};
    const char *names[4], *features[STIN_FEATURE_COUNT];
    int i;
    (void)state;
    for (i = 0; i < 4; i++) {
        names[i] = stin_tier_name(tiers[i]);
        assert_named(names[i], "unknown tier");
    }
    assert_distinct(names, 4);
    assert_string_equal(stin_tier_name((stin_tier)3), "unknown tier");
    for (i = 0; i < STIN_FEATURE_COUNT; i++) {
        features[i] = stin_feature_name((stin_feature)i);
        assert_named(features[i], "unknown feature");
    }
    assert_distinct(features, STIN_FEATURE_COUNT);
    assert_string_equal(stin_feature_name(STIN_FEATURE_COUNT), "unknown feature");
}

static void test_stages_have_names(void **state)
{
    const char *names[STIN_STAGE_COUNT];
    int i;
    (void)state;
    for (i = 0; i < STIN_STAGE_COUNT; i++) {
        names[i] = stin_stage_name((stin_stage)i);
        assert_named(names[i], "unknown stage");
    }
    assert_distinct(names, STIN_STAGE_COUNT);
    assert_string_equal(stin_stage_name(STIN_STAGE_COUNT), "unknown stage");
}

static void test_techniques_round_trip(void **state)
{
    const char *names[STIN_TECH_COUNT];
    int t;
    (void)state;
    for (t = 0; t < STIN_TECH_COUNT; t++) {
        names[t] = stin_technique_name((stin_technique)t);
        assert_named(names[t], "unknown technique");
    }
    assert_distinct(names, STIN_TECH_COUNT);
    for (t = 1; t < STIN_TECH_COUNT; t++)
        assert_int_equal(stin_technique_from_name(names[t]), t);
    assert_int_equal(stin_technique_from_name("none"), STIN_TECH_NONE);
    assert_int_equal(stin_technique_from_name(NULL), STIN_TECH_NONE);
    assert_int_equal(stin_technique_from_name(""), STIN_TECH_NONE);
    assert_int_equal(stin_technique_from_name("fixed"), STIN_TECH_NONE);
    assert_int_equal(stin_technique_from_name("fixed-function-x"), STIN_TECH_NONE);
    assert_int_equal(stin_technique_from_name("Fixed-Function"), STIN_TECH_NONE);
    assert_string_equal(stin_technique_name(STIN_TECH_COUNT), "unknown technique");
}

/* ---- the formatter ------------------------------------------------------------- */
#define GUARD 0x5a

static void test_format_conversions(void **state)
{
    char buf[128];
    size_t n;
    (void)state;
    n = stin__formatf(buf, sizeof buf, "%s|%d|%u|%x|%zu|%lu|%f|%%", "abc", -42, 42u, 0xbeefu,
                      (size_t)123456789, 4000000000ul, 2.5);
    assert_string_equal(buf, "abc|-42|42|beef|123456789|4000000000|2.500|%");
    assert_int_equal(n, strlen(buf));
    stin__formatf(buf, sizeof buf, "%d %d %u %x %x", INT_MIN, INT_MAX, UINT_MAX, 0u, 0xffffffffu);
    assert_string_equal(buf, "-2147483648 2147483647 4294967295 0 ffffffff");
    stin__formatf(buf, sizeof buf, "%zu", (size_t)SIZE_MAX);
    assert_string_equal(buf, "18446744073709551615");
    stin__formatf(buf, sizeof buf, "%f %f %f %f", -1.25, 2.9996, 0.0, 1e19);
    assert_string_equal(buf, "-1.250 3.000 0.000 inf");
    stin__formatf(buf, sizeof buf, "[%s]", (const char *)NULL);
    assert_string_equal(buf, "[(null)]");
    stin__formatf(buf, sizeof buf, "a%qb 100%");
    assert_string_equal(buf, "ab 100");
}

static void test_format_nan(void **state)
{
    char buf[16];
    volatile double zero = 0.0;
    (void)state;
    stin__formatf(buf, sizeof buf, "%f", zero / zero);
    assert_string_equal(buf, "nan");
}

/* Every buffer size from 0 up: the output is the full text's prefix, always
 * terminated, the return value is the full length, and nothing past `size`
 * is written. */
static void test_format_truncation_never_overflows(void **state)
{
    char full[128], buf[64];
    size_t len, size, i;
    (void)state;
    len = stin__formatf(full, sizeof full, "x=%d name=%s hex=%x %f%%", -7, "stin", 0xabcu, 3.5);
    assert_int_equal(len, strlen(full));
    assert_true(len < sizeof buf - 8);
    for (size = 0; size <= len + 2; size++) {
        memset(buf, GUARD, sizeof buf);
        assert_int_equal(stin__formatf(buf, size, "x=%d name=%s hex=%x %f%%", -7, "stin", 0xabcu,
                                       3.5),
                         len);
        for (i = size; i < sizeof buf; i++)
            assert_int_equal((unsigned char)buf[i], GUARD);
        if (size == 0)
            continue;
        assert_int_equal(buf[size - 1 < len ? size - 1 : len], '\0');
        assert_memory_equal(buf, full, size - 1 < len ? size - 1 : len);
    }
}

static void test_format_into_nothing_counts(void **state)
{
    (void)state;
    assert_int_equal(stin__formatf(NULL, 0, "%s-%d", "abc", 12), 6);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_results_have_names),
        cmocka_unit_test(test_log_items_have_text),
        cmocka_unit_test(test_caps_have_names),
        cmocka_unit_test(test_tiers_and_features_have_names),
        cmocka_unit_test(test_stages_have_names),
        cmocka_unit_test(test_techniques_round_trip),
        cmocka_unit_test(test_format_conversions),
        cmocka_unit_test(test_format_nan),
        cmocka_unit_test(test_format_truncation_never_overflows),
        cmocka_unit_test(test_format_into_nothing_counts),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
