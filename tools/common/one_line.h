/* SPDX-License-Identifier: MIT */
/* Makes text from a file safe to print as one line of an error message. */
#ifndef STIN_TOOLS_ONE_LINE_H
#define STIN_TOOLS_ONE_LINE_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Copies src into dst (always NUL-terminated when size > 0), keeping
 * printable ASCII and well-formed UTF-8 and writing every other byte as an
 * escape (\n, \t, \r, \xNN), so the result is one line of valid UTF-8. An
 * escape or character that does not fit whole is left out. */
void one_line_copy(char *dst, size_t size, const char *src);

#ifdef __cplusplus
}
#endif
#endif
