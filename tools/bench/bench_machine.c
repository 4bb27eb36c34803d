/* SPDX-License-Identifier: MIT */
#include "bench_machine.h"

#include <stdio.h>
#include <string.h>

/* Value of a "key<tabs>: value" line of /proc/cpuinfo, newline stripped. */
static const char *field(char *line, const char *key)
{
    char *colon;
    if (strncmp(line, key, strlen(key)) != 0 || !(colon = strchr(line, ':')))
        return NULL;
    colon++;
    while (*colon == ' ' || *colon == '\t')
        colon++;
    colon[strcspn(colon, "\n")] = '\0';
    return colon;
}

void bench_cpu_model(char *out, size_t size)
{
    FILE *f = fopen("/proc/cpuinfo", "r");
    char line[512];
    const char *v;
    snprintf(out, size, "unknown CPU");
    if (!f)
        return;
    while (fgets(line, sizeof line, f))
        if ((v = field(line, "model name"))) {
            snprintf(out, size, "%s", v);
            break;
        }
    fclose(f);
}

int bench_cpu_count(void)
{
    FILE *f = fopen("/proc/cpuinfo", "r");
    char line[512];
    int n = 0;
    if (!f)
        return 0;
    while (fgets(line, sizeof line, f))
        if (field(line, "processor"))
            n++;
    fclose(f);
    return n;
}
