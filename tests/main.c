/* main.c - the test runner: registration, tiers, one child process and one temporary folder per
 * test, several at once, skips with their reasons, the allocation counter, the closing line.
 *
 *   ww-tests [-j N] [--tier T[,T...]] [--shuffle SEED] [--list] [FILTER...]
 *
 * T: unit, proc, image, long; test (= unit,proc,image, the default) or all.
 *
 * A test runs in a forked child with its output in a log of its own, so a crash, a leak report or
 * a hang is that test's failure alone and parallel tests never interleave their lines. The parent
 * keeps the last run's durations beside the binary (test-times.txt) and starts the longest
 * tests first; each run works in a fresh folder of its own (test-tmp/run-XXXXXX beside the
 * binary), so two runs can share a checkout.
 */
#define _GNU_SOURCE /* nftw's FTW_DEPTH and FTW_PHYS, strsignal */
#include <errno.h>
#include <fcntl.h>
#include <ftw.h>
#include <signal.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "gfx/backend.h"
#include "test.h"

#define MAX_TESTS 1024
#define DEFAULT_TIMEOUT_S 300.0 /* a hung test fails after this (WW_TEST_TIMEOUT, seconds) */

/* a child's exit status; ST_NONE: started, never finished (the run was interrupted) */
enum { ST_NONE = -1, ST_PASS = 0, ST_FAIL = 1, ST_SKIP = 3 };

typedef struct {
    const char *name;
    ww_test_fn fn;
    int tier;
    double expected; /* seconds, from the last run; -1 unknown */
    /* while and after it runs */
    pid_t pid;
    double start, secs;
    int status;
    char skip[512];
} test_entry;

typedef struct {
    test_entry tests[MAX_TESTS];
    int ntests;
    /* in the child: the test that runs and its folder */
    test_entry *current;
    char dir[800];
    int failed_now, skipped_now;
    unsigned require; /* bit per skip kind that fails instead (WW_REQUIRE_GL) */
    double tol_scale;
    char home[256]; /* the test binary's folder: build/, build/asan/ */
    /* the GL probe, made once in a child of its own before any test starts: index 1 EGL,
     * 2 OSMesa (ww_backend_kind); gl_error says why neither opens */
    int probed;
    int have[3];
    char error[3][768];
    char gl_error[1600];
} runner;

/* registration runs before main (constructors), so the registry is file-scope by necessity */
static runner R = {.tol_scale = 1.0};

#define NTIERS 4
static const char *tier_name[NTIERS] = {"unit", "proc", "image", "long"};

void ww_test_register(const char *name, ww_test_fn fn, int tier) {
    if (R.ntests < MAX_TESTS) R.tests[R.ntests++] = (test_entry){name, fn, tier, -1.0, 0, 0, 0, 0, ""};
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

void ww_test_skip(int kind, const char *fmt, ...) {
    char why[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(why, sizeof why, fmt, ap);
    va_end(ap);
    if (R.require & (1u << kind)) {
        fprintf(stderr, "    WW_REQUIRE_GL=1, but: %s\n", why);
        R.failed_now = 1;
        return;
    }
    if (!R.skipped_now && R.current) snprintf(R.current->skip, sizeof R.current->skip, "%s", why);
    R.skipped_now = 1;
}

void ww_test_needs_proc(const char *what) {
    if (R.current && R.current->tier == WW_TIER_UNIT) {
        fprintf(stderr, "    a unit test %s: declare it with TEST_PROC\n", what);
        R.failed_now = 1;
    }
}

double ww_test_tol(double tol) { return tol * R.tol_scale; }
int ww_test_failed_now(void) { return R.failed_now; }

int ww_test_have_gl(void) {
    ww_test_needs_proc("asks for GL");
    return R.have[WW_BACKEND_EGL] || R.have[WW_BACKEND_OSMESA];
}

const char *ww_test_gl_error(void) { return R.gl_error; }
const char *ww_test_build_dir(void) { return R.home; }

int ww_test_have_backend(int kind) {
    ww_test_needs_proc("asks for GL");
    return kind > 0 && kind < 3 && R.have[kind];
}

const char *ww_test_backend_error(int kind) { return kind > 0 && kind < 3 ? R.error[kind] : "?"; }

const char *ww_test_tmpdir(const char *name) {
    static char path[1100];
    snprintf(path, sizeof path, "%s/%s", R.dir[0] ? R.dir : "build", name);
    mkdir(path, 0777);
    return path;
}

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

/* the tier check: the link wraps fork and ww_backend_open too, so a unit test that reaches
 * either, directly or through the library (sweep --jobs, bench, the render job), is told so;
 * the null backend opens no GL and is fine in a unit test */
pid_t __real_fork(void);
pid_t __wrap_fork(void);
ww_result __real_ww_backend_open(ww_backend_kind kind, ww_backend **out, ww_error *err);
ww_result __wrap_ww_backend_open(ww_backend_kind kind, ww_backend **out, ww_error *err);
pid_t __wrap_fork(void) {
    ww_test_needs_proc("forks a process");
    return __real_fork();
}
ww_result __wrap_ww_backend_open(ww_backend_kind kind, ww_backend **out, ww_error *err) {
    if (kind != WW_BACKEND_NULL) ww_test_needs_proc("opens a GL backend");
    return __real_ww_backend_open(kind, out, err);
}

static double now_s(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int rm_entry(const char *path, const struct stat *sb, int flag, struct FTW *ftw) {
    (void)sb;
    (void)flag;
    (void)ftw;
    remove(path);
    return 0;
}

static void rm_tree(const char *path) { nftw(path, rm_entry, 16, FTW_DEPTH | FTW_PHYS); }

/* ---- the GL probe: a child opens each backend once, so that no test process inherits a context
 * and every GL test agrees on the answer */
typedef struct {
    int ok[3];
    char msg[3][768];
} probe_report;

static void probe_gl(void) {
    int fd[2];
    probe_report rep = {0};
    if (pipe(fd) != 0) return;
    fflush(NULL);
    pid_t pid = fork();
    if (pid == 0) {
        close(fd[0]);
        for (int k = WW_BACKEND_EGL; k <= WW_BACKEND_OSMESA; k++) {
            ww_backend *b = NULL;
            ww_error err = {0};
            rep.ok[k] = ww_backend_open((ww_backend_kind)k, &b, &err) == WW_OK;
            ww_backend_close(b);
            snprintf(rep.msg[k], sizeof rep.msg[k], "%s", rep.ok[k] ? "" : err.msg);
        }
        ssize_t w = write(fd[1], &rep, sizeof rep);
        close(fd[1]);
        exit(w == (ssize_t)sizeof rep ? 0 : 1);
    }
    close(fd[1]);
    ssize_t n = 0, got;
    while (pid > 0 && n < (ssize_t)sizeof rep && (got = read(fd[0], (char *)&rep + n, sizeof rep - (size_t)n)) > 0)
        n += got;
    close(fd[0]);
    int st = 0;
    if (pid > 0) waitpid(pid, &st, 0);
    if (n != (ssize_t)sizeof rep) {
        memset(&rep, 0, sizeof rep);
        for (int k = WW_BACKEND_EGL; k <= WW_BACKEND_OSMESA; k++)
            snprintf(rep.msg[k], sizeof rep.msg[k], "the GL probe process died (status 0x%x)", st);
    }
    for (int k = WW_BACKEND_EGL; k <= WW_BACKEND_OSMESA; k++) {
        R.have[k] = rep.ok[k];
        snprintf(R.error[k], sizeof R.error[k], "%s", rep.msg[k]);
    }
    snprintf(R.gl_error, sizeof R.gl_error, "EGL: %s; OSMesa: %s", R.error[1], R.error[2]);
    R.probed = 1;
}

/* WW_REQUIRE_GL: "1" or a list of gl, egl, osmesa; a backend named implies GL */
static unsigned parse_require(const char *s) {
    unsigned m = 0;
    if (!s || !s[0] || strcmp(s, "0") == 0) return 0;
    if (strcmp(s, "1") == 0 || strstr(s, "gl")) m |= 1u << WW_SKIP_GL;
    if (strstr(s, "egl")) m |= 1u << WW_SKIP_EGL;
    if (strstr(s, "osmesa")) m |= 1u << WW_SKIP_OSMESA | 1u << WW_SKIP_GL;
    return m;
}

/* ---- the child: run one test in its own folder with its output in its own log */
static void run_child(test_entry *t, const char *root) {
    setpgid(0, 0); /* a timeout kills the test with everything it started */
    char log[700];
    snprintf(R.dir, sizeof R.dir, "%s/%s", root, t->name);
    snprintf(log, sizeof log, "%s/%s.log", root, t->name);
    int fd = open(log, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
        dup2(fd, 1);
        dup2(fd, 2);
        close(fd);
    }
    setvbuf(stdout, NULL, _IOLBF, 0);
    if (mkdir(R.dir, 0777) != 0) {
        fprintf(stderr, "    cannot make %s: %s\n", R.dir, strerror(errno));
        exit(ST_FAIL);
    }
    R.current = t;
    t->fn();
    if (R.skipped_now && !R.failed_now) {
        char path[700];
        snprintf(path, sizeof path, "%s/%s.skip", root, t->name);
        FILE *f = fopen(path, "w");
        if (f) {
            fputs(t->skip, f);
            fclose(f);
        }
    }
    fflush(NULL);
    exit(R.failed_now ? ST_FAIL : R.skipped_now ? ST_SKIP : ST_PASS);
}

/* ---- the parent */
typedef struct {
    int jobs;
    int tiers;          /* bit per tier */
    unsigned shuffle;   /* 0: longest first */
    int list;
    double timeout;
    char home[256];     /* the folder of the test binary */
    char times[300];    /* durations of the last run, in home */
    char **filters;
    int nfilters;
} options;

static int wanted(const options *o, const test_entry *t) {
    if (!(o->tiers & (1 << t->tier))) return 0;
    if (o->nfilters == 0) return 1;
    for (int a = 0; a < o->nfilters; a++)
        if (strstr(t->name, o->filters[a])) return 1;
    return 0;
}

static void load_times(const char *path) {
    FILE *f = fopen(path, "r");
    if (!f) return;
    char name[256];
    double s;
    while (fscanf(f, "%255s %lf", name, &s) == 2)
        for (int i = 0; i < R.ntests; i++)
            if (strcmp(R.tests[i].name, name) == 0) R.tests[i].expected = s;
    fclose(f);
}

/* every test's last known duration, this run's where it ran */
static void save_times(const char *path) {
    char tmp[600];
    snprintf(tmp, sizeof tmp, "%s.tmp", path);
    FILE *f = fopen(tmp, "w");
    if (!f) return;
    for (int i = 0; i < R.ntests; i++) {
        const test_entry *t = &R.tests[i];
        double s = t->pid ? t->secs : t->expected;
        if (s >= 0) fprintf(f, "%s %.3f\n", t->name, s);
    }
    if (fclose(f) == 0) rename(tmp, path);
}

static unsigned lcg(unsigned *s) { return *s = *s * 1103515245u + 12345u, *s >> 8; }

/* unit tests first (they are quick and say most about a change), then the rest longest first
 * (unknown durations count as long), which keeps the cores busy to the end; --shuffle proves
 * the order does not matter */
static int by_tier_then_longest(const void *a, const void *b) {
    const test_entry *x = *(test_entry *const *)a, *y = *(test_entry *const *)b;
    int ux = x->tier != WW_TIER_UNIT, uy = y->tier != WW_TIER_UNIT;
    if (ux != uy) return ux - uy;
    double ex = x->expected < 0 ? 1e9 : x->expected, ey = y->expected < 0 ? 1e9 : y->expected;
    if (ex != ey) return ex > ey ? -1 : 1;
    return strcmp(x->name, y->name);
}

static void print_log(const char *root, const test_entry *t) {
    char path[700];
    snprintf(path, sizeof path, "%s/%s.log", root, t->name);
    FILE *f = fopen(path, "r");
    if (!f) return;
    char line[4096];
    while (fgets(line, sizeof line, f)) {
        fputs(line, stderr);
        if (!strchr(line, '\n')) fputc('\n', stderr);
    }
    fclose(f);
}

static void read_skip(const char *root, test_entry *t) {
    char path[700];
    snprintf(path, sizeof path, "%s/%s.skip", root, t->name);
    FILE *f = fopen(path, "r");
    t->skip[0] = 0;
    if (f) {
        size_t n = fread(t->skip, 1, sizeof t->skip - 1, f);
        t->skip[n] = 0;
        fclose(f);
    }
    if (!t->skip[0]) snprintf(t->skip, sizeof t->skip, "(no reason given)");
}

static void finish(const char *root, test_entry *t, int st, int timed_out) {
    t->secs = now_s() - t->start;
    if (timed_out) t->status = ST_FAIL;
    else if (WIFEXITED(st)) t->status = WEXITSTATUS(st) == ST_SKIP ? ST_SKIP
                                      : WEXITSTATUS(st) == ST_PASS ? ST_PASS : ST_FAIL;
    else t->status = ST_FAIL;
    const char *verdict = t->status == ST_PASS ? "ok" : t->status == ST_SKIP ? "skipped" : "FAIL";
    fprintf(stderr, "%-56s %-7s %6.2f s\n", t->name, verdict, t->secs);
    print_log(root, t);
    if (timed_out) fprintf(stderr, "    timed out after %.0f s\n", t->secs);
    else if (WIFSIGNALED(st)) fprintf(stderr, "    died of signal %d (%s)\n", WTERMSIG(st), strsignal(WTERMSIG(st)));
    if (t->status == ST_SKIP) {
        read_skip(root, t);
        fprintf(stderr, "    skipped: %s\n", t->skip);
    }
    if (t->status == ST_FAIL) fprintf(stderr, "%-56s FAIL\n", t->name);
    else {
        char path[800];
        snprintf(path, sizeof path, "%s/%s", root, t->name);
        rm_tree(path);
        snprintf(path, sizeof path, "%s/%s.log", root, t->name);
        remove(path);
        snprintf(path, sizeof path, "%s/%s.skip", root, t->name);
        remove(path);
    }
}

static volatile sig_atomic_t interrupted;
static void on_signal(int sig) { interrupted = sig; }

static int run_all(const options *o, test_entry **order, int n, const char *root) {
    int next = 0, running = 0;
    test_entry *slot[64] = {0};
    int jobs = o->jobs < 1 ? 1 : o->jobs > 64 ? 64 : o->jobs;
    while ((next < n || running > 0) && !interrupted) {
        for (int s = 0; s < jobs && next < n; s++) {
            if (slot[s]) continue;
            test_entry *t = order[next++];
            fflush(NULL);
            t->start = now_s();
            t->status = ST_NONE;
            pid_t pid = fork();
            if (pid == 0) run_child(t, root);
            if (pid < 0) {
                fprintf(stderr, "%-56s FAIL\n    fork: %s\n", t->name, strerror(errno));
                t->pid = -1; /* counted, as failed */
                t->status = ST_FAIL;
                continue;
            }
            setpgid(pid, pid);
            t->pid = pid;
            slot[s] = t;
            running++;
        }
        int st = 0;
        pid_t pid = waitpid(-1, &st, WNOHANG);
        if (pid > 0) {
            for (int s = 0; s < jobs; s++)
                if (slot[s] && slot[s]->pid == pid) {
                    finish(root, slot[s], st, 0);
                    slot[s] = NULL;
                    running--;
                }
            continue;
        }
        /* nothing ended: check the clocks, then sleep a little */
        double t = now_s();
        for (int s = 0; s < jobs; s++)
            if (slot[s] && t - slot[s]->start > o->timeout) {
                kill(-slot[s]->pid, SIGKILL);
                waitpid(slot[s]->pid, &st, 0);
                finish(root, slot[s], st, 1);
                slot[s] = NULL;
                running--;
            }
        struct timespec nap = {0, 5 * 1000 * 1000};
        nanosleep(&nap, NULL);
    }
    if (interrupted) {
        for (int s = 0; s < jobs; s++)
            if (slot[s]) kill(-slot[s]->pid, SIGKILL);
        while (wait(NULL) > 0) {
        }
        return 1;
    }
    return 0;
}

/* "unit,proc" -> a bit per tier; 0 for a bad name */
static int parse_tiers(const char *s) {
    int bits = 0;
    while (*s) {
        size_t n = strcspn(s, ",");
        int b = 0;
        for (int k = 0; k < NTIERS; k++)
            if (strlen(tier_name[k]) == n && strncmp(s, tier_name[k], n) == 0) b = 1 << k;
        if (n == 4 && strncmp(s, "test", 4) == 0) b = 1 << WW_TIER_UNIT | 1 << WW_TIER_PROC | 1 << WW_TIER_IMAGE;
        if (n == 3 && strncmp(s, "all", 3) == 0) b = (1 << NTIERS) - 1;
        if (!b) return 0;
        bits |= b;
        s += n + (s[n] == ',');
    }
    return bits;
}

static int parse_options(int argc, char **argv, options *o) {
    const char *j = getenv("WW_TEST_JOBS");
    long ncpu = sysconf(_SC_NPROCESSORS_ONLN);
    o->jobs = j ? atoi(j) : ncpu > 0 ? (int)ncpu : 1;
    o->tiers = parse_tiers("test");
    o->timeout = getenv("WW_TEST_TIMEOUT") ? atof(getenv("WW_TEST_TIMEOUT")) : DEFAULT_TIMEOUT_S;
    /* beside the binary: build/, build/asan/ and build/cov/ keep their own */
    const char *slash = strrchr(argv[0], '/');
    snprintf(o->home, sizeof o->home, "%.*s", slash ? (int)(slash - argv[0]) : 1, slash ? argv[0] : ".");
    snprintf(o->times, sizeof o->times, "%s/test-times.txt", o->home);
    snprintf(R.home, sizeof R.home, "%s", o->home);
    o->filters = calloc((size_t)argc, sizeof *o->filters);
    for (int a = 1; a < argc; a++) {
        const char *s = argv[a];
        if (strcmp(s, "-j") == 0 && a + 1 < argc) o->jobs = atoi(argv[++a]);
        else if (strncmp(s, "-j", 2) == 0 && s[2]) o->jobs = atoi(s + 2);
        else if (strcmp(s, "--list") == 0) o->list = 1;
        else if (strcmp(s, "--shuffle") == 0 && a + 1 < argc) o->shuffle = (unsigned)strtoul(argv[++a], NULL, 10) | 1u;
        else if (strcmp(s, "--tier") == 0 && a + 1 < argc) {
            if (!(o->tiers = parse_tiers(argv[++a]))) return -1;
        } else if (s[0] == '-') return -1;
        else o->filters[o->nfilters++] = argv[a];
    }
    return 0;
}

int main(int argc, char **argv) {
    options o = {0};
    if (parse_options(argc, argv, &o) != 0) {
        fprintf(stderr, "usage: ww-tests [-j N] [--tier T[,T...]] [--shuffle SEED] [--list] "
                        "[FILTER...]\n  T: unit, proc, image, long; test (unit,proc,image) or all\n");
        return 2;
    }
    const char *scale = getenv("WW_TOL_SCALE");
    if (scale) R.tol_scale = atof(scale);
    R.require = parse_require(getenv("WW_REQUIRE_GL"));
    load_times(o.times);

    test_entry *order[MAX_TESTS];
    int n = 0, need_gl = 0;
    for (int i = 0; i < R.ntests; i++)
        if (wanted(&o, &R.tests[i])) {
            order[n++] = &R.tests[i];
            need_gl |= R.tests[i].tier != WW_TIER_UNIT;
        }
    qsort(order, (size_t)n, sizeof order[0], by_tier_then_longest);
    if (o.shuffle)
        for (int i = n - 1; i > 0; i--) {
            int k = (int)(lcg(&o.shuffle) % (unsigned)(i + 1));
            test_entry *x = order[i];
            order[i] = order[k];
            order[k] = x;
        }
    if (o.list) {
        for (int i = 0; i < n; i++)
            printf("%s %s %.2f\n", order[i]->name, tier_name[order[i]->tier], order[i]->expected);
        free(o.filters);
        return 0;
    }

    /* every run in a fresh folder of its own, so two runs at once never share a file */
    char base[300], root[512];
    snprintf(base, sizeof base, "%s/test-tmp", o.home);
    mkdir(base, 0777);
    snprintf(root, sizeof root, "%s/run-XXXXXX", base);
    if (!mkdtemp(root)) {
        fprintf(stderr, "ww-tests: cannot make a folder under %s: %s\n", base, strerror(errno));
        return 2;
    }
    if (need_gl) probe_gl();
    if (R.probed && (R.require & 1u << WW_SKIP_GL))
        for (int k = WW_BACKEND_EGL; k <= WW_BACKEND_OSMESA; k++)
            if ((R.require & 1u << (k == WW_BACKEND_EGL ? WW_SKIP_EGL : WW_SKIP_OSMESA)) && !R.have[k])
                fprintf(stderr, "WW_REQUIRE_GL names a backend that does not open: %s\n", R.error[k]);
    signal(SIGINT, on_signal);
    signal(SIGTERM, on_signal);

    double t0 = now_s();
    int stopped = run_all(&o, order, n, root);
    double wall = now_s() - t0;

    int passed = 0, failed = 0, skipped = 0;
    double tier_s[NTIERS] = {0}, tier_wall[NTIERS][2];
    int tier_n[NTIERS] = {0};
    for (int k = 0; k < NTIERS; k++) tier_wall[k][0] = 1e300, tier_wall[k][1] = 0;
    for (int i = 0; i < n; i++) {
        const test_entry *t = order[i];
        if (!t->pid) continue;
        passed += t->status == ST_PASS;
        failed += t->status == ST_FAIL || t->status == ST_NONE;
        skipped += t->status == ST_SKIP;
        tier_n[t->tier]++;
        tier_s[t->tier] += t->secs;
        if (t->start < tier_wall[t->tier][0]) tier_wall[t->tier][0] = t->start;
        if (t->start + t->secs > tier_wall[t->tier][1]) tier_wall[t->tier][1] = t->start + t->secs;
    }
    if (!stopped) save_times(o.times);

    fprintf(stderr, "\n");
    for (int k = 0; k < NTIERS; k++)
        if (tier_n[k])
            fprintf(stderr, "tier %-4s %4d tests, %7.1f s of test time, %6.1f s wall\n", tier_name[k],
                    tier_n[k], tier_s[k], tier_wall[k][1] - tier_wall[k][0]);
    fprintf(stderr, "%d tests in %.1f s with -j %d%s\n", passed + failed + skipped, wall, o.jobs,
            stopped ? " (interrupted)" : "");
    if (skipped) {
        fprintf(stderr, "skipped:\n");
        for (int i = 0; i < n; i++)
            if (order[i]->pid && order[i]->status == ST_SKIP)
                fprintf(stderr, "  %-54s %s\n", order[i]->name, order[i]->skip);
    }
    if (failed) {
        fprintf(stderr, "failed (logs and folders kept in %s):\n", root);
        for (int i = 0; i < n; i++)
            if (order[i]->pid && (order[i]->status == ST_FAIL || order[i]->status == ST_NONE))
                fprintf(stderr, "  %s%s\n", order[i]->name,
                        order[i]->status == ST_NONE ? " (stopped by the interrupt)" : "");
    } else rm_tree(root);
    printf("%d passed, %d failed, %d skipped\n", passed, failed, skipped);
    free(o.filters);
    return failed || stopped ? 1 : 0;
}
