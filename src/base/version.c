/* SPDX-License-Identifier: MIT */
/* The library's version, for applications that check it against the header. */
#include "stin/stin.h"

int stin_version(void) { return STIN_VERSION; }
