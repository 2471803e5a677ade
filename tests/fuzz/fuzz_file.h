/* fuzz_file.h - helpers for the fuzz targets whose readers take paths: the input as a file in
 * memory (a memfd named /proc/self/fd/N, rewritten for each input), and a scratch folder on
 * tmpfs whose links point at the repository's test data, removed at exit. Include it first. */
#ifndef WW_FUZZ_FILE_H
#define WW_FUZZ_FILE_H

#define _GNU_SOURCE
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

/* the bytes as the file at the returned path (one per slot, a static buffer) */
static inline const char *fuzz_memfile(int slot, const unsigned char *data, size_t size) {
    static int fd[4] = {-1, -1, -1, -1};
    static char path[4][64];
    if (fd[slot] < 0) {
        fd[slot] = memfd_create("fuzz", 0);
        if (fd[slot] < 0) abort();
        snprintf(path[slot], sizeof path[slot], "/proc/self/fd/%d", fd[slot]);
    }
    if (ftruncate(fd[slot], 0) != 0 || (size && pwrite(fd[slot], data, size, 0) != (ssize_t)size))
        abort();
    return path[slot];
}

static char fuzz_dir_path[PATH_MAX];

static inline void fuzz_dir_remove(void) {
    char cmd[PATH_MAX + 16];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", fuzz_dir_path);
    if (fuzz_dir_path[0] && system(cmd) != 0) fprintf(stderr, "cannot remove %s\n", fuzz_dir_path);
}

/* a fresh folder /dev/shm/ww-fuzz-NAME-PID, removed at exit */
static inline const char *fuzz_dir(const char *name) {
    snprintf(fuzz_dir_path, sizeof fuzz_dir_path, "/dev/shm/ww-fuzz-%s-%d", name, (int)getpid());
    if (mkdir(fuzz_dir_path, 0700) != 0) abort();
    atexit(fuzz_dir_remove);
    return fuzz_dir_path;
}

/* in the scratch folder: a subfolder (target NULL) or a link to target, a path relative to the
 * current folder (the repository root) */
static inline void fuzz_dir_add(const char *name, const char *target) {
    char at[2 * PATH_MAX], cwd[PATH_MAX], to[2 * PATH_MAX];
    snprintf(at, sizeof at, "%s/%s", fuzz_dir_path, name);
    if (!target) {
        if (mkdir(at, 0700) != 0) abort();
        return;
    }
    if (!getcwd(cwd, sizeof cwd)) abort();
    snprintf(to, sizeof to, "%s/%s", cwd, target);
    if (symlink(to, at) != 0) abort();
}

/* write bytes to path (a file in the scratch folder) */
static inline void fuzz_write(const char *path, const void *data, size_t size) {
    FILE *f = fopen(path, "wb");
    if (!f || (size && fwrite(data, 1, size, f) != size) || fclose(f) != 0) abort();
}

#endif
