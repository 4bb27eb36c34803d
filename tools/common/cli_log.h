/* SPDX-License-Identifier: MIT */
/* A stin log callback that prints to stderr, shared by the tools. */
#ifndef STIN_TOOLS_CLI_LOG_H
#define STIN_TOOLS_CLI_LOG_H

#include "stin/stin.h"

#ifdef __cplusplus
extern "C" {
#endif

#define CLI_LOG_NOTES 4

typedef struct cli_log {
    int verbose;          /* 1: info lines too */
    const char *program;  /* prefix */
    unsigned errors;      /* error lines seen */
    /* collect = 1: errors are not printed; the first is kept in first_error
     * for the tool's own one-line message. Fallbacks logged at info level
     * are kept in notes (the tool says what a frame actually used). */
    int collect;
    char first_error[256];
    char notes[CLI_LOG_NOTES][256];
    int note_count;
} cli_log;

void cli_log_fn(void *user, stin_log_level level, stin_log_item item, const char *message);

#ifdef __cplusplus
}
#endif
#endif
