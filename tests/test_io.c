/* test_io.c - frame files: atomic writes (nothing partial, no temporary left behind), mkdir -p
 * and whole-file reads.
 */
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/error.h"
#include "io/image.h"
#include "io/writers.h"
#include "test.h"

/* ---- helpers ---- */

/* a fresh folder for one test, copied out of ww_test_tmpdir's static buffer */
static void tmpdir(const char *name, char *dir, size_t cap) {
    const char *d = ww_test_tmpdir(name);
    ENSURE(d != NULL);
    snprintf(dir, cap, "%s", d ? d : "build/test-tmp/unknown");
}

/* entries of a folder whose name contains ".tmp." */
static int count_temp_files(const char *dir) {
    DIR *d = opendir(dir);
    if (!d) return -1;
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL)
        if (strstr(e->d_name, ".tmp.")) n++;
    closedir(d);
    return n;
}

/* entries of a folder other than . and .. */
static int count_entries(const char *dir) {
    DIR *d = opendir(dir);
    if (!d) return -1;
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL)
        if (strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0) n++;
    closedir(d);
    return n;
}

static int is_dir(const char *path) {
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

static void write_text(const char *path, const char *text) {
    FILE *f = fopen(path, "wb");
    ENSURE(f != NULL);
    if (!f) return;
    fputs(text, f);
    fclose(f);
}

/* ---- atomic writes and folders ---- */

TEST(io_atomic_write_into_missing_folder_leaves_nothing) {
    char dir[512], path[600];
    tmpdir("io_atomic_missing", dir, sizeof dir);
    snprintf(path, sizeof path, "%s/not/here.bin", dir);
    ww_error err;
    ENSURE_EQ_INT(ww_write_file_atomic(path, "abc", 3, &err), WW_E_IO);
    ENSURE(strstr(err.msg, "not/here.bin") != NULL);
    ENSURE(strstr(err.msg, strerror(ENOENT)) != NULL);
    ENSURE_EQ_INT(count_entries(dir), 0);
}

TEST(io_atomic_write_replaces_existing_file_whole) {
    char dir[512], path[600];
    tmpdir("io_atomic_replace", dir, sizeof dir);
    snprintf(path, sizeof path, "%s/f.txt", dir);
    write_text(path, "the old content, longer than the new one\n");
    ww_error err;
    ENSURE_EQ_INT(ww_write_file_atomic(path, "new\n", 4, &err), WW_OK);
    size_t n = 0;
    char *got = ww_test_read_file(path, &n);
    ENSURE(got && n == 4 && memcmp(got, "new\n", 4) == 0);
    free(got);
    /* an empty write is a whole file too */
    ENSURE_EQ_INT(ww_write_file_atomic(path, NULL, 0, &err), WW_OK);
    got = ww_test_read_file(path, &n);
    ENSURE(got && n == 0);
    free(got);
    ENSURE_EQ_INT(count_temp_files(dir), 0);
    ENSURE_EQ_INT(count_entries(dir), 1);
}

TEST(io_atomic_write_over_a_folder_fails_and_cleans_up) {
    char dir[512], path[600];
    tmpdir("io_atomic_over_dir", dir, sizeof dir);
    snprintf(path, sizeof path, "%s/sub", dir);
    ENSURE_EQ_INT(mkdir(path, 0777), 0);
    ww_error err;
    /* the temporary file is written, then the rename fails: it must go */
    ENSURE_EQ_INT(ww_write_file_atomic(path, "abc", 3, &err), WW_E_IO);
    ENSURE(strstr(err.msg, "rename") != NULL);
    ENSURE_EQ_INT(count_temp_files(dir), 0);
    ENSURE(is_dir(path));
    ENSURE_EQ_INT(count_entries(dir), 1);
}

TEST(io_atomic_write_into_read_only_folder_fails_cleanly) {
    if (geteuid() == 0) {
        /* root ignores permission bits, so there is nothing to check */
        fprintf(stderr, "(skipped as root) ");
        return;
    }
    char dir[512], ro[600], path[700];
    tmpdir("io_atomic_read_only", dir, sizeof dir);
    snprintf(ro, sizeof ro, "%s/ro", dir);
    snprintf(path, sizeof path, "%s/f.bin", ro);
    ENSURE_EQ_INT(mkdir(ro, 0555), 0);
    ww_error err;
    ENSURE_EQ_INT(ww_write_file_atomic(path, "abc", 3, &err), WW_E_IO);
    ENSURE(strstr(err.msg, strerror(EACCES)) != NULL);
    ENSURE_EQ_INT(count_entries(ro), 0);
    chmod(ro, 0777); /* so the next run can remove it */
}

TEST(io_make_dirs_nested_existing_and_file_in_the_way) {
    char dir[512], deep[600], file[600], under[700];
    tmpdir("io_make_dirs", dir, sizeof dir);
    snprintf(deep, sizeof deep, "%s/a/b//c/", dir);
    snprintf(file, sizeof file, "%s/plain", dir);
    snprintf(under, sizeof under, "%s/plain/x/y", dir);
    ww_error err;
    ENSURE_EQ_INT(ww_make_dirs(deep, &err), WW_OK);
    ENSURE(is_dir(deep));
    ENSURE_EQ_INT(ww_make_dirs(deep, &err), WW_OK); /* already there */
    ENSURE_EQ_INT(ww_make_dirs(dir, &err), WW_OK);

    write_text(file, "x");
    ENSURE_EQ_INT(ww_make_dirs(under, &err), WW_E_IO);
    ENSURE(strstr(err.msg, "plain/x/y") != NULL);
    ENSURE(strstr(err.msg, strerror(ENOTDIR)) != NULL);
    ENSURE_EQ_INT(ww_make_dirs(file, &err), WW_E_IO); /* the last component is the file */
    ENSURE_EQ_INT(ww_make_dirs("", &err), WW_E_IO);
}

TEST(io_read_file_missing_and_folder) {
    char dir[512], path[600];
    tmpdir("io_read_file", dir, sizeof dir);
    snprintf(path, sizeof path, "%s/none", dir);
    unsigned char *data = (unsigned char *)"sentinel";
    size_t len = 5;
    ww_error err;
    ENSURE_EQ_INT(ww_read_file(path, &data, &len, &err), WW_E_NOFILE);
    ENSURE(data == NULL && len == 0);
    ENSURE_EQ_INT(ww_read_file(dir, &data, &len, &err), WW_E_NOFILE);
    write_text(path, "hello");
    ENSURE_EQ_INT(ww_read_file(path, &data, &len, &err), WW_OK);
    ENSURE(data && len == 5 && memcmp(data, "hello", 6) == 0);
    free(data);
}
