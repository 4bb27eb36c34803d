/* SPDX-License-Identifier: MIT */
/* isolate.h: fork, two pipes (result bytes, failure reason) and a deadline. */
#include "isolate.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

int isolate_write(int fd, const void *data, size_t n)
{
    const unsigned char *p = data;
    while (n) {
        ssize_t w = write(fd, p, n);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0)
            return 0;
        p += w;
        n -= (size_t)w;
    }
    return 1;
}

static long long now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (long long)ts.tv_sec * 1000 + ts.tv_nsec / 1000000;
}

/* The child's side: decoder noise on stderr would break the tools' one-line
 * error contract, so it goes nowhere; _exit skips the parent's atexit work. */
static void run_child(isolate_work work, void *arg, int data_fd, int why_fd)
{
    static const int crash_signals[] = { SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT };
    char why[512] = "";
    int devnull = open("/dev/null", O_WRONLY);
    size_t i;
    /* A crash must end the child: no handler inherited from the parent (a
     * test framework's, a sanitizer's) may carry on in the parent's code. */
    for (i = 0; i < sizeof crash_signals / sizeof crash_signals[0]; i++)
        signal(crash_signals[i], SIG_DFL);
    if (devnull >= 0) {
        dup2(devnull, STDOUT_FILENO);
        dup2(devnull, STDERR_FILENO);
        close(devnull);
    }
    if (work(arg, data_fd, why, sizeof why))
        _exit(0);
    isolate_write(why_fd, why, strnlen(why, sizeof why));
    _exit(3);
}

/* Reads the data pipe until EOF, the deadline or max_bytes. 1 at EOF. */
static int collect(int fd, long long deadline, size_t max_bytes, unsigned char **buf,
                   size_t *size, int *timed_out)
{
    size_t cap = 0;
    for (;;) {
        struct pollfd pfd;
        long long left = deadline - now_ms();
        ssize_t r;
        if (left <= 0) {
            *timed_out = 1;
            return 0;
        }
        pfd.fd = fd;
        pfd.events = POLLIN;
        r = poll(&pfd, 1, left > 1000 ? 1000 : (int)left);
        if (r < 0 && errno != EINTR)
            return 0;
        if (r <= 0)
            continue; /* nothing to read yet: a read would block */
        if (*size == cap) {
            size_t grown = cap ? 2 * cap : 65536;
            unsigned char *b;
            if (cap >= max_bytes)
                return 0;
            if (grown > max_bytes)
                grown = max_bytes;
            if (!(b = realloc(*buf, grown)))
                return 0;
            *buf = b;
            cap = grown;
        }
        r = read(fd, *buf + *size, cap - *size);
        if (r == 0)
            return 1;
        if (r < 0 && errno != EINTR && errno != EAGAIN)
            return 0;
        if (r > 0)
            *size += (size_t)r;
    }
}

int isolate_run(isolate_work work, void *arg, unsigned timeout_s, size_t max_bytes,
                unsigned char **out, size_t *out_size, char *why, size_t why_size)
{
    int data[2], reason[2], status = 0, timed_out = 0, done;
    unsigned char *buf = NULL;
    size_t size = 0;
    pid_t pid;
    *out = NULL;
    *out_size = 0;
    if (pipe(data) != 0 || (pipe(reason) != 0 && (close(data[0]), close(data[1]), 1))) {
        snprintf(why, why_size, "cannot make a pipe: %s", strerror(errno));
        return 0;
    }
    fflush(NULL); /* nothing buffered is written twice */
    pid = fork();
    if (pid < 0) {
        snprintf(why, why_size, "cannot start a process: %s", strerror(errno));
        close(data[0]), close(data[1]), close(reason[0]), close(reason[1]);
        return 0;
    }
    if (pid == 0) {
        close(data[0]);
        close(reason[0]);
        run_child(work, arg, data[1], reason[1]);
    }
    close(data[1]);
    close(reason[1]);
    done = collect(data[0], now_ms() + 1000LL * timeout_s, max_bytes, &buf, &size, &timed_out);
    close(data[0]);
    if (!done)
        kill(pid, SIGKILL);
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
        ;
    if (done && WIFEXITED(status) && WEXITSTATUS(status) == 0) {
        close(reason[0]);
        *out = buf;
        *out_size = size;
        return 1;
    }
    free(buf);
    if (timed_out) {
        snprintf(why, why_size, "took longer than %u s (the importer may loop on this file)", timeout_s);
    } else if (!done) {
        snprintf(why, why_size, "result larger than %zu bytes", max_bytes);
    } else if (WIFSIGNALED(status)) {
        snprintf(why, why_size, "the importer crashed on this file (signal %d)", WTERMSIG(status));
    } else if (!WIFEXITED(status) || WEXITSTATUS(status) != 3) {
        snprintf(why, why_size, "the importer crashed on this file (exit status %d)",
                 WIFEXITED(status) ? WEXITSTATUS(status) : -1);
    } else {
        char msg[512];
        ssize_t n = read(reason[0], msg, sizeof msg - 1);
        msg[n > 0 ? n : 0] = '\0';
        snprintf(why, why_size, "%s", n > 0 ? msg : "the importer failed");
    }
    close(reason[0]);
    return 0;
}
