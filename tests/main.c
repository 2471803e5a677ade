/* main.c - the test runner: registration, filtering, the allocation counter, the closing line. */
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "test.h"

#define MAX_TESTS 1024

typedef struct {
    const char *name;
    ww_test_fn fn;
} test_entry;

typedef struct {
    test_entry tests[MAX_TESTS];
    int ntests;
    int failed_now;
    double tol_scale;
} runner;

/* registration runs before main (constructors), so the registry is file-scope by necessity */
static runner R = {.tol_scale = 1.0};

void ww_test_register(const char *name, ww_test_fn fn) {
    if (R.ntests < MAX_TESTS) R.tests[R.ntests++] = (test_entry){name, fn};
}

void ww_test_fail(const char *file, int line, const char *fmt, ...) {
    va_list ap;
    fprintf(stderr, "    %s:%d: ", file, line);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    R.failed_now = 1;
}

double ww_test_tol(double tol) { return tol * R.tol_scale; }
int ww_test_failed_now(void) { return R.failed_now; }

/* allocation counting through the linker's --wrap */
void *__real_malloc(size_t n);
void *__real_calloc(size_t a, size_t b);
void *__real_realloc(void *p, size_t n);
void *__wrap_malloc(size_t n);
void *__wrap_calloc(size_t a, size_t b);
void *__wrap_realloc(void *p, size_t n);
static long alloc_count;
void *__wrap_malloc(size_t n) { alloc_count++; return __real_malloc(n); }
void *__wrap_calloc(size_t a, size_t b) { alloc_count++; return __real_calloc(a, b); }
void *__wrap_realloc(void *p, size_t n) { alloc_count++; return __real_realloc(p, n); }
long ww_test_alloc_count(void) { return alloc_count; }

static int cmp_entry(const void *a, const void *b) {
    return strcmp(((const test_entry *)a)->name, ((const test_entry *)b)->name);
}

int main(int argc, char **argv) {
    const char *scale = getenv("WW_TOL_SCALE");
    if (scale) R.tol_scale = atof(scale);
    qsort(R.tests, (size_t)R.ntests, sizeof R.tests[0], cmp_entry);

    int passed = 0, failed = 0;
    for (int i = 0; i < R.ntests; i++) {
        int want = argc < 2;
        for (int a = 1; a < argc; a++)
            if (strstr(R.tests[i].name, argv[a])) want = 1;
        if (!want) continue;
        R.failed_now = 0;
        fprintf(stderr, "%-48s ", R.tests[i].name);
        fflush(stderr);
        R.tests[i].fn();
        if (R.failed_now) {
            fprintf(stderr, "%-48s FAIL\n", R.tests[i].name);
            failed++;
        } else {
            fprintf(stderr, "ok\n");
            passed++;
        }
    }
    printf("%d passed, %d failed\n", passed, failed);
    return failed ? 1 : 0;
}
