#include "cli_log.h"

#include <stdio.h>

void cli_log_fn(void *user, stin_log_level level, stin_log_item item, const char *message)
{
    cli_log *l = (cli_log *)user;
    static const char *const names[] = {"error", "warning", "info"};
    (void)item;
    if (level == STIN_LOG_LEVEL_ERROR)
        l->errors++;
    if (level == STIN_LOG_LEVEL_INFO && !l->verbose)
        return;
    fprintf(stderr, "%s: stin %s: %s\n", l->program, names[level], message);
}
