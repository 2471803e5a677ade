/* files.c - the files a scene names, looked at and read under a cap (scene/files.h). */
#include "scene/files.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/readfile.h"

ww_result ww_file_check_named(const char *path, size_t max, const char *from, int line,
                              int column, ww_error *err) {
    struct stat st;
    if (stat(path, &st) != 0 || access(path, R_OK) != 0)
        return ww_error_set(err, WW_E_NOFILE, from, line, column, "cannot open '%s': %s", path,
                            strerror(errno));
    if (S_ISDIR(st.st_mode))
        return ww_error_set(err, WW_E_NOFILE, from, line, column,
                            "'%s' is a folder: expected a file", path);
    if (!S_ISREG(st.st_mode))
        return ww_error_set(err, WW_E_NOFILE, from, line, column,
                            "'%s' is not a regular file (a device, FIFO or socket): expected a "
                            "file",
                            path);
    if ((unsigned long long)st.st_size > (unsigned long long)max)
        return ww_error_set(err, WW_E_RANGE, from, line, column,
                            "'%s' is %lld bytes: expected at most %zu (%.0f MiB)", path,
                            (long long)st.st_size, max, (double)max / (1 << 20));
    return WW_OK;
}

ww_result ww_file_read_named(const char *path, size_t max, const char *from, int line,
                             int column, char **text, size_t *len, ww_error *err) {
    unsigned char *buf = NULL;
    *text = NULL;
    *len = 0;
    ww_result r = ww_file_check_named(path, max, from, line, column, err);
    if (r) return r;
    if ((r = ww_file_read_max(path, max, max, &buf, len, err))) {
        if (err) {
            snprintf(err->file, sizeof err->file, "%s", from ? from : "");
            err->line = line;
            err->column = column;
        }
        return r;
    }
    *text = (char *)buf;
    return WW_OK;
}

ww_result ww_file_named_at(ww_result r, const char *from, int line, int column, ww_error *err) {
    if (!err || !from || strcmp(err->file, from) == 0) return r;
    size_t n = strlen(err->msg);
    snprintf(err->msg + n, sizeof err->msg - n, " (named at %s:%d:%d)", from, line, column);
    return r;
}
