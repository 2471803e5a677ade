/* readfile.c - a whole file into memory under a cap (core/readfile.h): the one reader under the
 * scene loader, the asset readers and io/'s ww_read_file, so that no read grows without bound.
 */
#include "core/readfile.h"

#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

ww_result ww_file_read_max(const char *path, size_t max_regular, size_t max_stream,
                           unsigned char **data, size_t *len, ww_error *err) {
    WW_ASSERT(max_regular <= SIZE_MAX / 2 && max_stream <= SIZE_MAX / 2);
    *data = NULL;
    *len = 0;
    int fd = open(path, O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return ww_error_set(err, WW_E_NOFILE, NULL, 0, 0, "cannot read '%s': %s", path,
                            strerror(errno));
    struct stat st;
    int e = fstat(fd, &st) != 0 ? errno : S_ISDIR(st.st_mode) ? EISDIR : 0;
    if (e != 0) {
        close(fd);
        return ww_error_set(err, WW_E_NOFILE, NULL, 0, 0, "cannot read '%s': %s", path,
                            strerror(e));
    }
    int regular = S_ISREG(st.st_mode);
    size_t max = regular ? max_regular : max_stream;
    if (regular && (uint64_t)st.st_size > (uint64_t)max) {
        close(fd);
        return ww_error_set(err, WW_E_RANGE, NULL, 0, 0,
                            "'%s' is %lld bytes: expected at most %zu (%.0f MiB)", path,
                            (long long)st.st_size, max, (double)max / (1 << 20));
    }

    /* size from fstat, but read to the end in case the file changed meanwhile; a stream grows
     * by doubling up to one byte past the cap, which tells "too large" from "exactly the cap" */
    size_t cap = regular ? (size_t)st.st_size + 1 : 65536, n = 0;
    if (cap > max + 1) cap = max + 1;
    unsigned char *buf = malloc(cap + 1);
    for (;;) {
        if (!buf) {
            close(fd);
            return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "cannot read '%s': out of memory",
                                path);
        }
        if (n == cap) {
            if (cap > max) {
                free(buf);
                close(fd);
                return ww_error_set(err, WW_E_RANGE, NULL, 0, 0,
                                    "'%s' holds more than %zu bytes (%.0f MiB)%s", path, max,
                                    (double)max / (1 << 20),
                                    regular ? "" : ": it is not a regular file and did not end");
            }
            size_t next = cap <= (max + 1) / 2 ? cap * 2 : max + 1;
            unsigned char *nb = realloc(buf, next + 1);
            if (!nb) free(buf);
            buf = nb;
            cap = next;
            continue;
        }
        ssize_t got = read(fd, buf + n, cap - n);
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) {
            e = errno;
            free(buf);
            close(fd);
            return ww_error_set(err, WW_E_NOFILE, NULL, 0, 0, "cannot read '%s': %s", path,
                                strerror(e));
        }
        if (got == 0) break;
        n += (size_t)got;
    }
    close(fd);
    buf[n] = 0;
    *data = buf;
    *len = n;
    return WW_OK;
}

