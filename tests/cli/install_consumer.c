/* SPDX-License-Identifier: MIT */
/* An application built against an installed stin: the library linked in is
 * the header's version, and the API links without GL (stin loads it). */
#include <stin/stin.h>

#include <stdio.h>

int main(void)
{
    if (stin_version() != STIN_VERSION) {
        fprintf(stderr, "header %d, library %d\n", STIN_VERSION, stin_version());
        return 1;
    }
    if (!stin_result_name(STIN_OK) || !stin_result_name(STIN_OK)[0]) {
        fprintf(stderr, "stin_result_name gave nothing\n");
        return 1;
    }
    printf("stin %d.%d.%d\n", STIN_VERSION_MAJOR, STIN_VERSION_MINOR, STIN_VERSION_PATCH);
    return 0;
}
