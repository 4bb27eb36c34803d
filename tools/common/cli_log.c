/* SPDX-License-Identifier: MIT */
#include "cli_log.h"

#include <stdio.h>

void cli_log_fn(void *user, stin_log_level level, stin_log_item item, const char *message)
{
    cli_log *l = (cli_log *)user;
    static const char *const names[] = {"error", "warning", "info"};
    if (level == STIN_LOG_LEVEL_ERROR)
        l->errors++;
    if (l->collect && level == STIN_LOG_LEVEL_ERROR) {
        if (!l->first_error[0])
            snprintf(l->first_error, sizeof l->first_error, "%s", message);
        return;
    }
    if (l->collect && item == STIN_LOG_FALLBACK && l->note_count < CLI_LOG_NOTES)
        snprintf(l->notes[l->note_count++], sizeof l->notes[0], "%s", message);
    if (level == STIN_LOG_LEVEL_INFO && !l->verbose)
        return;
    fprintf(stderr, "%s: stin %s: %s\n", l->program, names[level], message);
}
