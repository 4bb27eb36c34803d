/* SPDX-License-Identifier: MIT */
/* Replays fuzz inputs through a target without libFuzzer (plain cc with
 * AddressSanitizer + UBSan), for make check: every file of each directory
 * (or the file) named on the command line, else of REPLAY_DIRS (colon
 * separated, built in). Prints one PASS line, or dies on the input that
 * fails (the sanitizer says why) after naming it on stderr. */
#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int replay_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    uint8_t *buf;
    long size;
    if (!f)
        return 0;
    if (fseek(f, 0, SEEK_END) != 0 || (size = ftell(f)) < 0 || fseek(f, 0, SEEK_SET) != 0 ||
        !(buf = malloc((size_t)size + 1)) ) {
        fclose(f);
        return 0;
    }
    if (fread(buf, 1, (size_t)size, f) != (size_t)size) {
        free(buf);
        fclose(f);
        return 0;
    }
    fclose(f);
    fprintf(stderr, "replay %s\n", path);
    LLVMFuzzerTestOneInput(buf, (size_t)size);
    free(buf);
    return 1;
}

/* Files of dir, or dir itself when it is a file; the count replayed. */
static int replay(const char *dir)
{
    struct stat st;
    struct dirent *e;
    DIR *d;
    int n = 0;
    char path[1024];
    if (stat(dir, &st) != 0)
        return 0;
    if (!S_ISDIR(st.st_mode))
        return replay_file(dir);
    if (!(d = opendir(dir)))
        return 0;
    while ((e = readdir(d)))
        if (e->d_name[0] != '.') {
            snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
            if (stat(path, &st) == 0 && S_ISREG(st.st_mode))
                n += replay_file(path);
        }
    closedir(d);
    return n;
}

int main(int argc, char **argv)
{
    char dirs[] = REPLAY_DIRS, *dir, *rest = dirs;
    int i, n = 0;
    for (i = 1; i < argc; i++)
        n += replay(argv[i]);
    while (argc == 1 && (dir = strtok_r(rest, ":", &rest)))
        n += replay(dir);
    if (n == 0) {
        printf("FAIL %s replay: no inputs found\n", REPLAY_NAME);
        return 1;
    }
    printf("PASS %s replay: %d inputs\n", REPLAY_NAME, n);
    return 0;
}
