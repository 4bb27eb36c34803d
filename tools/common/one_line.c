/* SPDX-License-Identifier: MIT */
#include "one_line.h"

#include <stdio.h>
#include <string.h>

/* Length of the well-formed UTF-8 sequence at s (2 to 4), or 0. Overlong
 * forms, surrogates and code points past U+10FFFF are not well formed. */
static size_t utf8_length(const unsigned char *s)
{
    size_t n, i;
    unsigned lo = 0x80, hi = 0xbf;
    if (s[0] >= 0xc2 && s[0] <= 0xdf)
        n = 2;
    else if (s[0] >= 0xe0 && s[0] <= 0xef)
        n = 3;
    else if (s[0] >= 0xf0 && s[0] <= 0xf4)
        n = 4;
    else
        return 0;
    if (s[0] == 0xe0)
        lo = 0xa0;
    else if (s[0] == 0xed)
        hi = 0x9f;
    else if (s[0] == 0xf0)
        lo = 0x90;
    else if (s[0] == 0xf4)
        hi = 0x8f;
    for (i = 1; i < n; i++) {
        if (s[i] < lo || s[i] > hi)
            return 0;
        lo = 0x80;
        hi = 0xbf;
    }
    return n;
}

void one_line_copy(char *dst, size_t size, const char *src)
{
    const unsigned char *s = (const unsigned char *)src;
    size_t used = 0;
    if (!size)
        return;
    while (*s) {
        char esc[8];
        const char *piece = esc;
        size_t n = utf8_length(s), step = n;
        if (n) {
            piece = (const char *)s;
        } else if (*s >= 0x20 && *s < 0x7f) {
            piece = (const char *)s;
            n = step = 1;
        } else {
            if (*s == '\n')
                n = (size_t)snprintf(esc, sizeof esc, "\\n");
            else if (*s == '\t')
                n = (size_t)snprintf(esc, sizeof esc, "\\t");
            else if (*s == '\r')
                n = (size_t)snprintf(esc, sizeof esc, "\\r");
            else
                n = (size_t)snprintf(esc, sizeof esc, "\\x%02x", *s);
            step = 1;
        }
        if (used + n >= size)
            break;
        memcpy(dst + used, piece, n);
        used += n;
        s += step;
    }
    dst[used] = '\0';
}
