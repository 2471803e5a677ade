/* child.h - run a function in a forked child process and bring its fixed-size report back to
 * the parent through a pipe, so that a crash, a leak or a GL context stays in the child and the
 * child's peak memory is its own. Used by bench (one child per configuration) and sweep (one
 * child per thumbnail, and the probe for a GL backend).
 *
 *   my_report rep;                                  // plain bytes: no pointers into the child
 *   ww_child_end end;
 *   switch (ww_child_run(fn, &ctx, &rep, sizeof rep, &end)) {
 *   case WW_CHILD_REPORTED: ...rep as fn left it...; break;
 *   case WW_CHILD_DIED:     ...rep zeroed; end.status is the wait status...; break;
 *   default:                ...no child ran; end.errnum says why (pipe or fork)...
 *   }
 *
 * The report is zeroed before fn runs (fn starts from zeros) and again when it comes back short.
 * ww_pipe_write_all and ww_pipe_read_all move whole records through a pipe for callers that
 * keep their own children (sweep's workers stream rows).
 * Buffered stdio is flushed before the fork so the child does not write the parent's pending
 * output a second time. Nothing is allocated; the caller owns ctx and the report.
 */
#ifndef WW_CHILD_H
#define WW_CHILD_H

#include <stddef.h>

typedef enum ww_child_outcome {
    WW_CHILD_REPORTED = 0, /* the child wrote its whole report */
    WW_CHILD_DIED,         /* it ran but the report came back short (crash, exit, write error) */
    WW_CHILD_NO_PIPE,      /* pipe() failed: no child ran */
    WW_CHILD_NO_FORK,      /* fork() failed: no child ran */
} ww_child_outcome;

typedef struct ww_child_end {
    ww_child_outcome outcome;
    int status;       /* the child's wait status (0 when no child ran or the wait failed) */
    int errnum;       /* errno of the failed pipe() or fork(), else 0 */
    long max_rss_kib; /* the child's peak resident set, KiB; -1 when no child ran or wait failed */
} ww_child_end;

/* fn(ctx, report) in a child; its report of `size` bytes copied into `report` here. ctx is
 * const: whatever the child changes stays in the child. end may be NULL. */
ww_child_outcome ww_child_run(void (*fn)(const void *ctx, void *report), const void *ctx,
                              void *report, size_t size, ww_child_end *end);

/* how a child ended, from its wait status: "killed by signal N" or "exit status N" */
const char *ww_child_how_ended(int status, char *buf, size_t cap);

/* all n bytes through a pipe or other fd, again after EINTR and short counts (a pipe may take or
 * hand over a large record in parts): 0 when all went, -1 on an error or an early end */
int ww_pipe_write_all(int fd, const void *p, size_t n);
int ww_pipe_read_all(int fd, void *p, size_t n);

#endif
