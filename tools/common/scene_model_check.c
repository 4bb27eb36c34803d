/* SPDX-License-Identifier: MIT */
/* Checks on a model or texture file before a decoder reads it. */
#include "scene_internal.h"

#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

/* A PLY header is text up to "end_header"; assimp's reader seeks for that
 * line forever when it is missing, so look for it within this many bytes. */
#define PLY_HEADER_MAX 65536

int scene_check_regular_file(const char *path, char *why, size_t why_size)
{
    struct stat st;
    if (stat(path, &st) != 0) {
        snprintf(why, why_size, "%s", strerror(errno));
        return 0;
    }
    if (!S_ISREG(st.st_mode)) {
        snprintf(why, why_size, "not a regular file");
        return 0;
    }
    return 1;
}

static int ply_header_ends(FILE *f)
{
    char line[PLY_HEADER_MAX];
    size_t read_total = 0;
    while (read_total < PLY_HEADER_MAX && fgets(line, sizeof line, f)) {
        size_t n = strlen(line);
        read_total += n;
        while (n && (line[n - 1] == '\n' || line[n - 1] == '\r' || line[n - 1] == ' '))
            line[--n] = '\0';
        if (strcmp(line, "end_header") == 0)
            return 1;
    }
    return 0;
}

int scene_model_precheck(const char *path, char *why, size_t why_size)
{
    char magic[5] = "";
    int ok = 1;
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(why, why_size, "%s", strerror(errno));
        return 0;
    }
    if (fread(magic, 1, 4, f) == 4 && memcmp(magic, "ply", 3) == 0 && isspace((unsigned char)magic[3])) {
        ok = ply_header_ends(f);
        if (!ok)
            snprintf(why, why_size, "PLY header has no end_header line in its first %d bytes",
                     PLY_HEADER_MAX);
    }
    fclose(f);
    return ok;
}
