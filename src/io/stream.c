/* stream.c - atomic text/binary output streams (trace files, event logs); see stream.h. */
#include "io/stream.h"

#include <errno.h>
#include <string.h>
#include <unistd.h>

ww_result ww_stream_open(ww_stream *s, const char *path, ww_error *err) {
    memset(s, 0, sizeof *s);
    if (strcmp(path, "-") == 0) {
        s->f = stdout;
        s->is_stdout = 1;
        return WW_OK;
    }
    snprintf(s->path, sizeof s->path, "%s", path);
    snprintf(s->tmp, sizeof s->tmp, "%s.tmp.%ld", path, (long)getpid());
    s->f = fopen(s->tmp, "wb");
    if (!s->f)
        return ww_error_set(err, WW_E_IO, path, 0, 0, "cannot create %s: %s", s->tmp, strerror(errno));
    return WW_OK;
}

ww_result ww_stream_commit(ww_stream *s, ww_error *err) {
    if (s->is_stdout) {
        if (fflush(stdout) != 0)
            return ww_error_set(err, WW_E_IO, "stdout", 0, 0, "cannot write: %s", strerror(errno));
        return WW_OK;
    }
    int bad = ferror(s->f) || fflush(s->f) != 0 || fsync(fileno(s->f)) != 0;
    int e = errno;
    bad |= fclose(s->f) != 0;
    s->f = NULL;
    if (bad || rename(s->tmp, s->path) != 0) {
        if (!bad) e = errno;
        unlink(s->tmp);
        return ww_error_set(err, WW_E_IO, s->path, 0, 0, "cannot write %s: %s", s->path, strerror(e));
    }
    return WW_OK;
}

void ww_stream_abort(ww_stream *s) {
    if (s->is_stdout || !s->f) return;
    fclose(s->f);
    s->f = NULL;
    unlink(s->tmp);
}
