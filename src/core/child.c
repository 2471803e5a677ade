/* child.c - a function run in a forked child process, its report read back through a pipe
 * (core/child.h): bench's configurations and sweep's thumbnails each get a process of their own.
 */
#include "core/child.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

int ww_pipe_write_all(int fd, const void *p, size_t n) {
    const char *c = p;
    while (n > 0) {
        ssize_t w = write(fd, c, n);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) return -1;
        c += w;
        n -= (size_t)w;
    }
    return 0;
}

int ww_pipe_read_all(int fd, void *p, size_t n) {
    char *c = p;
    while (n > 0) {
        ssize_t r = read(fd, c, n);
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) return -1;
        c += r;
        n -= (size_t)r;
    }
    return 0;
}

ww_child_outcome ww_child_run(void (*fn)(const void *ctx, void *report), const void *ctx,
                              void *report, size_t size, ww_child_end *end) {
    ww_child_end e = {.outcome = WW_CHILD_REPORTED, .status = 0, .errnum = 0, .max_rss_kib = -1};
    memset(report, 0, size);
    int fd[2];
    if (pipe(fd) != 0) {
        e.outcome = WW_CHILD_NO_PIPE;
        e.errnum = errno;
        if (end) *end = e;
        return e.outcome;
    }
    fflush(NULL);
    pid_t pid = fork();
    if (pid == 0) {
        close(fd[0]);
        fn(ctx, report);
        _exit(ww_pipe_write_all(fd[1], report, size) == 0 ? 0 : 1);
    }
    int fork_errno = errno;
    close(fd[1]);
    int got = pid > 0 ? ww_pipe_read_all(fd[0], report, size) : -1;
    close(fd[0]);
    if (pid < 0) {
        e.outcome = WW_CHILD_NO_FORK;
        e.errnum = fork_errno;
        if (end) *end = e;
        return e.outcome;
    }
    /* wait4 rather than waitpid: the child's own peak RSS comes with its status */
    struct rusage ru;
    int status = 0;
    pid_t w;
    while ((w = wait4(pid, &status, 0, &ru)) < 0 && errno == EINTR) {}
    if (w == pid) {
        e.status = status;
        e.max_rss_kib = ru.ru_maxrss;
    }
    if (got != 0) {
        memset(report, 0, size);
        e.outcome = WW_CHILD_DIED;
    }
    if (end) *end = e;
    return e.outcome;
}

const char *ww_child_how_ended(int status, char *buf, size_t cap) {
    if (WIFSIGNALED(status))
        snprintf(buf, cap, "killed by signal %d", WTERMSIG(status));
    else
        snprintf(buf, cap, "exit status %d", WIFEXITED(status) ? WEXITSTATUS(status) : -1);
    return buf;
}
