/* util.c - helpers shared by the test files: run the binary, temporary folders, read files. */
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "test.h"

int ww_test_run(const char *cmdline, const char *out_path, const char *err_path) {
    ww_test_needs_proc("runs a process");
    char buf[4096];
    snprintf(buf, sizeof buf, "%s >%s 2>%s </dev/null", cmdline, out_path ? out_path : "/dev/null",
             err_path ? err_path : "/dev/null");
    int st = system(buf);
    if (st == -1 || !WIFEXITED(st)) return -1;
    return WEXITSTATUS(st);
}

const char *ww_test_bin(void) {
    const char *b = getenv("WW_BIN");
    return b && b[0] ? b : "./waterworld";
}

char *ww_test_read_file(const char *path, size_t *len) {
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    size_t cap = 4096, n = 0;
    char *buf = malloc(cap + 1);
    size_t got;
    while (buf && (got = fread(buf + n, 1, cap - n, f)) > 0) {
        n += got;
        if (n == cap) {
            char *nb = realloc(buf, cap * 2 + 1);
            if (!nb) { free(buf); buf = NULL; break; }
            buf = nb;
            cap *= 2;
        }
    }
    fclose(f);
    if (!buf) return NULL;
    buf[n] = 0;
    if (len) *len = n;
    return buf;
}

uint32_t ww_test_crc32(const unsigned char *p, size_t n) {
    uint32_t c = 0xffffffffu;
    for (size_t i = 0; i < n; i++) {
        c ^= p[i];
        for (int k = 0; k < 8; k++) c = c & 1u ? 0xedb88320u ^ (c >> 1) : c >> 1;
    }
    return c ^ 0xffffffffu;
}

int ww_test_have_tool(const char *cmd) {
    const char *path = getenv("PATH");
    if (!path || strchr(cmd, '/')) return access(cmd, X_OK) == 0;
    char dir[4096];
    while (*path) {
        size_t n = strcspn(path, ":");
        snprintf(dir, sizeof dir, "%.*s/%s", (int)n, n ? path : ".", cmd);
        if (access(dir, X_OK) == 0) return 1;
        path += n + (path[n] == ':');
    }
    return 0;
}

int ww_test_ww(const char *args, const char *out_path, const char *err_path) {
    char cmdline[8192];
    snprintf(cmdline, sizeof cmdline, "%s %s", ww_test_bin(), args);
    return ww_test_run(cmdline, out_path, err_path);
}

int ww_test_write_text(const char *path, const char *text) {
    FILE *f = fopen(path, "wb");
    if (!f) return -1;
    int bad = fputs(text, f) < 0;
    return fclose(f) != 0 || bad ? -1 : 0;
}

int ww_test_file_contains(const char *path, const char *needle) {
    char *s = ww_test_read_file(path, NULL);
    int found = s && strstr(s, needle);
    free(s);
    return found;
}

int ww_test_files_equal(const char *a, const char *b) {
    size_t na = 0, nb = 0;
    char *x = ww_test_read_file(a, &na), *y = ww_test_read_file(b, &nb);
    int same = x && y && na == nb && memcmp(x, y, na) == 0;
    free(x);
    free(y);
    return same;
}
