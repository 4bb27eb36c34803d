/* A stin log callback that prints to stderr, shared by the tools. */
#ifndef STIN_TOOLS_CLI_LOG_H
#define STIN_TOOLS_CLI_LOG_H

#include "stin/stin.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct cli_log {
    int verbose;          /* 1: info lines too */
    const char *program;  /* prefix */
    unsigned errors;      /* error lines seen */
} cli_log;

void cli_log_fn(void *user, stin_log_level level, stin_log_item item, const char *message);

#ifdef __cplusplus
}
#endif
#endif
