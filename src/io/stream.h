/* stream.h - an output stream that appears under its final name only when complete: writes go
 * to "PATH.tmp.PID" beside it, and ww_stream_commit() fsyncs and renames. "-" means stdout.
 *
 *   ww_stream s; ww_stream_open(&s, path, &err); fprintf(s.f, ...);
 *   ww_stream_commit(&s, &err);   // or ww_stream_abort(&s) on failure: nothing is left behind
 */
#ifndef WW_STREAM_H
#define WW_STREAM_H

#include <stdio.h>

#include "core/error.h"

typedef struct ww_stream {
    FILE *f;
    int is_stdout;
    char path[512];
    char tmp[560];
} ww_stream;

ww_result ww_stream_open(ww_stream *s, const char *path, ww_error *err);
ww_result ww_stream_commit(ww_stream *s, ww_error *err);
void ww_stream_abort(ww_stream *s);

#endif
