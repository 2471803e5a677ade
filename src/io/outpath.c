/* outpath.c - output paths checked before any work (io/outpath.h): stat and access, never an
 * open or a create, so a check has no effect on the file system.
 */
#include "io/outpath.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define OUT_PATH_MAX 4096

/* the folder a file of path goes into: "." for a bare name */
static void parent_of(const char *path, char *out, size_t size) {
    const char *slash = strrchr(path, '/');
    if (!slash)
        snprintf(out, size, ".");
    else if (slash == path)
        snprintf(out, size, "/");
    else
        snprintf(out, size, "%.*s", (int)(slash - path), path);
}

/* folder exists, is a folder, and a file can be made in it */
static ww_result check_folder(const char *opt, const char *dir, const char *path, ww_error *err) {
    struct stat st;
    if (stat(dir, &st) != 0)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "%s '%s': folder '%s': %s", opt, path,
                            dir, strerror(errno));
    if (!S_ISDIR(st.st_mode))
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "%s '%s': '%s' is not a folder", opt,
                            path, dir);
    if (access(dir, W_OK | X_OK) != 0)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "%s '%s': cannot write in '%s': %s",
                            opt, path, dir, strerror(errno));
    return WW_OK;
}

ww_result ww_check_out_file(const char *opt, const char *path, int stdout_ok, ww_error *err) {
    size_t n = strlen(path);
    if (n == 0) return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "%s: expected a file name, got ''", opt);
    if (strcmp(path, "-") == 0)
        return stdout_ok ? WW_OK
                         : ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                                        "%s -: expected a file name (this output cannot go to "
                                        "stdout)",
                                        opt);
    if (n >= OUT_PATH_MAX || path[n - 1] == '/')
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "%s '%.200s': expected a file name", opt,
                            path);
    struct stat st;
    if (stat(path, &st) == 0) {
        if (S_ISDIR(st.st_mode))
            return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                                "%s '%s' is a folder: expected a file name", opt, path);
        /* the file is written beside its name and renamed over it: a device or FIFO would be
         * replaced by a plain file */
        if (!S_ISREG(st.st_mode))
            return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                                "%s '%s' is not a regular file (a device, FIFO or socket)%s", opt,
                                path, stdout_ok ? ": for stdout write -" : "");
    } else if (errno != ENOENT) {
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "%s '%s': %s", opt, path, strerror(errno));
    }
    char dir[OUT_PATH_MAX];
    parent_of(path, dir, sizeof dir);
    return check_folder(opt, dir, path, err);
}

ww_result ww_check_out_dir(const char *opt, const char *path, ww_error *err) {
    size_t n = strlen(path);
    if (n == 0) return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "%s: expected a folder, got ''", opt);
    if (strcmp(path, "-") == 0)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            "%s -: expected a folder (frame files cannot go to stdout: --format "
                            "y4m or raw can)",
                            opt);
    if (n >= OUT_PATH_MAX)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "%s: the folder name is too long", opt);

    /* the folder, or the nearest part of its path that exists: it is made from there */
    char p[OUT_PATH_MAX];
    snprintf(p, sizeof p, "%s", path);
    for (;;) {
        struct stat st;
        if (stat(p, &st) == 0) {
            if (!S_ISDIR(st.st_mode))
                return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                                    "%s '%s': '%s' is a file, not a folder", opt, path, p);
            if (access(p, W_OK | X_OK) != 0)
                return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                                    "%s '%s': cannot write in '%s': %s", opt, path, p,
                                    strerror(errno));
            return WW_OK;
        }
        if (errno == ENOTDIR)
            return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                                "%s '%s': a part of the path is a file, not a folder", opt, path);
        if (errno != ENOENT)
            return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "%s '%s': %s", opt, path,
                                strerror(errno));
        /* drop the last component (and the slashes before it) */
        char *slash = strrchr(p, '/');
        while (slash && slash > p && slash[1] == 0) {
            *slash = 0;
            slash = strrchr(p, '/');
        }
        if (!slash) {
            snprintf(p, sizeof p, ".");
        } else if (slash == p) {
            p[1] = 0;
        } else {
            *slash = 0;
        }
    }
}

/* the same file: the same name, or both existing with the same inode */
static int same_file(const char *a, const char *b) {
    if (strcmp(a, b) == 0) return 1;
    struct stat sa, sb;
    return stat(a, &sa) == 0 && stat(b, &sb) == 0 && sa.st_dev == sb.st_dev &&
           sa.st_ino == sb.st_ino;
}

ww_result ww_check_out_distinct(const char *opt_a, const char *a, const char *opt_b,
                                const char *b, ww_error *err) {
    if (!a || !b || !same_file(a, b)) return WW_OK;
    if (strcmp(a, "-") == 0)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "%s and %s both write to stdout (-)",
                            opt_a, opt_b);
    return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "%s and %s name the same file '%s'", opt_a,
                        opt_b, a);
}
