/* SPDX-License-Identifier: MIT */
/* Typed, range-checked reads of JSON members with "FILE: where: problem"
 * errors; every check a scene file needs goes through here so messages stay
 * uniform. */
#include "scene_internal.h"
#include "one_line.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

int scene_fail(scene_parser *p, const char *where, const char *fmt, ...)
{
    char msg[384], line[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (p->err && p->err_size) {
        if (where && where[0])
            snprintf(line, sizeof line, "%s: %s: %s", p->file, where, msg);
        else
            snprintf(line, sizeof line, "%s: %s", p->file, msg);
        /* Names and syntax errors quote the file's bytes: keep it one line. */
        one_line_copy(p->err, p->err_size, line);
    }
    return 0;
}

void scene_join(char *out, size_t size, const char *where, const char *key)
{
    if (where && where[0])
        snprintf(out, size, "%s.%s", where, key);
    else
        snprintf(out, size, "%s", key);
}

int scene_check_object(scene_parser *p, const cJSON *v, const char *where,
                       const char *const *allowed)
{
    const cJSON *c, *d;
    if (!cJSON_IsObject(v))
        return scene_fail(p, where, "expected an object");
    for (c = v->child; c; c = c->next) {
        const char *const *a = allowed;
        while (*a && strcmp(*a, c->string) != 0)
            a++;
        if (!*a)
            return where && where[0] ? scene_fail(p, where, "unknown key '%s'", c->string)
                                     : scene_fail(p, where, "unknown top-level key '%s'", c->string);
        for (d = v->child; d != c; d = d->next)
            if (strcmp(d->string, c->string) == 0)
                return scene_fail(p, where, "duplicate key '%s'", c->string);
    }
    return 1;
}

int scene_require(scene_parser *p, const cJSON *obj, const char *key, const char *where)
{
    if (cJSON_GetObjectItemCaseSensitive(obj, key))
        return 1;
    return scene_fail(p, where, "missing required key '%s'", key);
}

static int check_number(scene_parser *p, const cJSON *item, const char *path,
                        scene_range range, float *out)
{
    double x;
    if (!cJSON_IsNumber(item))
        return scene_fail(p, path, "expected a finite number");
    x = item->valuedouble;
    if (!isfinite(x) || fabs(x) > SCENE_NUMBER_LIMIT)
        return scene_fail(p, path, "expected a finite number with magnitude <= %g (got %g)",
                          SCENE_NUMBER_LIMIT, x);
    if (range == SCENE_POSITIVE && !(x > 0))
        return scene_fail(p, path, "must be > 0 (got %g)", x);
    if (range == SCENE_NONNEGATIVE && !(x >= 0))
        return scene_fail(p, path, "must be >= 0 (got %g)", x);
    if (range == SCENE_UNIT && !(x >= 0 && x <= 1))
        return scene_fail(p, path, "must be in [0, 1] (got %g)", x);
    *out = (float)x;
    return 1;
}

int scene_get_number(scene_parser *p, const cJSON *obj, const char *key, const char *where,
                     scene_range range, float *out)
{
    const cJSON *item = cJSON_GetObjectItemCaseSensitive(obj, key);
    char path[256];
    if (!item)
        return 1;
    scene_join(path, sizeof path, where, key);
    return check_number(p, item, path, range, out);
}

int scene_get_int(scene_parser *p, const cJSON *obj, const char *key, const char *where,
                  int lo, int hi, int *out)
{
    const cJSON *item = cJSON_GetObjectItemCaseSensitive(obj, key);
    char path[256];
    double x;
    if (!item)
        return 1;
    scene_join(path, sizeof path, where, key);
    x = cJSON_IsNumber(item) ? item->valuedouble : NAN;
    if (!(x >= lo && x <= hi) || x != floor(x))
        return scene_fail(p, path, "expected an integer in [%d, %d]", lo, hi);
    *out = (int)x;
    return 1;
}

int scene_get_vector(scene_parser *p, const cJSON *obj, const char *key, const char *where,
                     int n, scene_range range, float *out)
{
    const cJSON *item = cJSON_GetObjectItemCaseSensitive(obj, key), *e;
    char path[256], elem[280];
    float tmp[16];
    int i = 0;
    if (!item)
        return 1;
    scene_join(path, sizeof path, where, key);
    if (!cJSON_IsArray(item) || cJSON_GetArraySize(item) != n || n > 16)
        return scene_fail(p, path, "expected an array of %d numbers", n);
    for (e = item->child; e; e = e->next, i++) {
        snprintf(elem, sizeof elem, "%s[%d]", path, i);
        if (!check_number(p, e, elem, range, &tmp[i]))
            return 0;
    }
    memcpy(out, tmp, (size_t)n * sizeof(float));
    return 1;
}

int scene_get_bool(scene_parser *p, const cJSON *obj, const char *key, const char *where,
                   int *out)
{
    const cJSON *item = cJSON_GetObjectItemCaseSensitive(obj, key);
    char path[256];
    if (!item)
        return 1;
    scene_join(path, sizeof path, where, key);
    if (!cJSON_IsBool(item))
        return scene_fail(p, path, "expected true or false");
    *out = cJSON_IsTrue(item);
    return 1;
}

int scene_get_string(scene_parser *p, const cJSON *obj, const char *key, const char *where,
                     char *out, size_t size)
{
    const cJSON *item = cJSON_GetObjectItemCaseSensitive(obj, key);
    char path[256];
    size_t len;
    if (!item)
        return 1;
    scene_join(path, sizeof path, where, key);
    if (!cJSON_IsString(item) || !item->valuestring[0])
        return scene_fail(p, path, "expected a non-empty string");
    len = strlen(item->valuestring);
    if (len >= size)
        return scene_fail(p, path, "string longer than %zu characters", size - 1);
    memcpy(out, item->valuestring, len + 1);
    return 1;
}

int scene_resolve_path(const char *scene_file, const char *rel, char *out, size_t size)
{
    const char *slash = strrchr(scene_file, '/');
    int n;
    if (rel[0] == '/' || !slash)
        n = snprintf(out, size, "%s", rel);
    else
        n = snprintf(out, size, "%.*s/%s", (int)(slash - scene_file), scene_file, rel);
    return n >= 0 && (size_t)n < size;
}
