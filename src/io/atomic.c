/* atomic.c - the file primitives under the frame writers: mkdir -p, whole-file reads, and
 * atomic writes (temporary file beside the target, fsync, rename), so no reader ever sees a
 * partial file under the final name and no temporary file outlives a failed write.
 */
#include "io/writers.h"

#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/readfile.h"

ww_result ww_make_dirs(const char *path, ww_error *err) {
    size_t n = strlen(path);
    if (n == 0)
        return ww_error_set(err, WW_E_IO, NULL, 0, 0, "cannot create folder '': empty path");
    char *p = malloc(n + 1);
    if (!p)
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "cannot create folder '%s': out of memory",
                            path);
    memcpy(p, path, n + 1);

    /* create each prefix in turn; one that exists already is fine */
    for (size_t i = 1; i <= n; i++) {
        if (p[i] != '/' && p[i] != '\0') continue;
        if (p[i - 1] == '/') continue; /* "a//b" */
        char c = p[i];
        p[i] = '\0';
        int rc = mkdir(p, 0777);
        int e = errno;
        p[i] = c;
        if (rc != 0 && e != EEXIST) {
            free(p);
            return ww_error_set(err, WW_E_IO, NULL, 0, 0, "cannot create folder '%s': %s", path,
                                strerror(e));
        }
    }
    free(p);

    /* the last component may exist as something other than a folder */
    struct stat st;
    if (stat(path, &st) != 0)
        return ww_error_set(err, WW_E_IO, NULL, 0, 0, "cannot create folder '%s': %s", path,
                            strerror(errno));
    if (!S_ISDIR(st.st_mode))
        return ww_error_set(err, WW_E_IO, NULL, 0, 0, "cannot create folder '%s': %s", path,
                            strerror(ENOTDIR));
    return WW_OK;
}

ww_result ww_read_file(const char *path, unsigned char **data, size_t *len, ww_error *err) {
    return ww_file_read_max(path, SIZE_MAX / 2, WW_READ_STREAM_MAX, data, len, err);
}

/* write all of data to fd, retrying short writes and interruptions; 0 ok, else errno */
static int write_all(int fd, const unsigned char *data, size_t len) {
    while (len > 0) {
        ssize_t put = write(fd, data, len);
        if (put < 0 && errno == EINTR) continue;
        if (put < 0) return errno;
        if (put == 0) return EIO;
        data += put;
        len -= (size_t)put;
    }
    return 0;
}

ww_result ww_write_file_atomic(const char *path, const void *data, size_t len, ww_error *err) {
    /* the temporary name is the target's plus ".tmp.PID": same folder, so rename is atomic */
    size_t n = strlen(path) + 32;
    char *tmp = malloc(n);
    if (!tmp)
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "cannot write '%s': out of memory", path);
    snprintf(tmp, n, "%s.tmp.%ld", path, (long)getpid());

    const char *step = "create temporary file";
    int e = 0, rc;
    int fd = open(tmp, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) {
        e = errno;
        goto fail;
    }

    /* data, then fsync so the rename never publishes a name whose bytes are not on disk */
    step = "write";
    if ((e = write_all(fd, data, len)) != 0) goto fail;
    step = "fsync";
    if (fsync(fd) != 0) {
        e = errno;
        goto fail;
    }
    step = "close";
    rc = close(fd);
    fd = -1;
    if (rc != 0) {
        e = errno;
        goto fail;
    }
    step = "rename temporary file";
    if (rename(tmp, path) != 0) {
        e = errno;
        goto fail;
    }
    free(tmp);
    return WW_OK;

fail:
    /* the temporary file goes; the target keeps whatever it held before */
    if (fd >= 0) close(fd);
    unlink(tmp);
    free(tmp);
    return ww_error_set(err, WW_E_IO, NULL, 0, 0, "cannot write '%s' (%s): %s", path, step,
                        strerror(e));
}
