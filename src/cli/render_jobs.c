/* render_jobs.c - `render --jobs N`: the slices of one run rendered by child processes, then
 * joined in place (model in render_jobs.h). */
#include "cli/render_jobs.h"

#include <dirent.h>
#include <errno.h>
#include <signal.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli/cli.h"
#include "io/stream.h"
#include "render/slices.h"

extern char **environ;

/* the names the children give the joined files inside DIR (fixed, so that --resume finds the
 * slices of the same run: the names are part of a slice's identity) */
#define JOBS_AUDIO ".jobs-audio.wav"
#define JOBS_STATS ".jobs-stats.jsonl"
/* seconds between progress lines' updates */
#define PROGRESS_PERIOD 0.5

/* a signal handler takes no context: the one flag it sets is the file's only static */
static volatile sig_atomic_t jobs_signal;
static void on_signal(int sig) { jobs_signal = sig; }

typedef struct child {
    pid_t pid;
    int64_t first, last; /* its frames */
    int64_t seen;        /* its frames found on disk, from first on (progress) */
    int status;          /* wait status once it has exited */
    int running;
} child;

/* the environment with LP_NUM_THREADS=value added (the caller frees the array, not the
 * strings); NULL when out of memory */
static char **env_with(const char *assignment) {
    int n = 0;
    while (environ[n]) n++;
    char **env = malloc(((size_t)n + 2) * sizeof *env);
    if (!env) return NULL;
    for (int k = 0; k < n; k++) env[k] = environ[k];
    env[n] = (char *)assignment;
    env[n + 1] = NULL;
    return env;
}

static pid_t spawn_slice(const ww_render_jobs *o, int i, char **env, ww_error *err) {
    char slice[48];
    snprintf(slice, sizeof slice, "%d/%d", i, o->jobs);
    enum { EXTRA = 16 };
    char **argv = malloc(((size_t)o->nwords + EXTRA) * sizeof *argv);
    if (!argv) {
        ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "render --jobs: out of memory");
        return -1;
    }
    int n = 0;
    argv[n++] = (char *)o->exe;
    argv[n++] = "render";
    for (int k = 0; k < o->nwords; k++) argv[n++] = o->words[k];
    argv[n++] = "-o";
    argv[n++] = (char *)o->dir;
    argv[n++] = "--slice";
    argv[n++] = slice;
    argv[n++] = "--quiet";
    if (o->resume) argv[n++] = "--resume";
    if (o->audio_path) {
        argv[n++] = "--audio";
        argv[n++] = JOBS_AUDIO;
    }
    if (o->stats_path) {
        argv[n++] = "--stats";
        argv[n++] = JOBS_STATS;
    }
    argv[n] = NULL;
    pid_t pid = -1;
    int rc = posix_spawn(&pid, o->exe, NULL, NULL, argv, env);
    free(argv);
    if (rc != 0) {
        ww_error_set(err, WW_E_IO, o->exe, 0, 0, "render --jobs: cannot start slice %s: %s", slice,
                     strerror(rc));
        return -1;
    }
    return pid;
}

/* every slice's parts under DIR/slices/ (records, sound tracks, stats: slice_*.*), and the
 * folder when it is then empty */
static void remove_parts(const char *dir) {
    char path[1200];
    snprintf(path, sizeof path, "%s/slices", dir);
    DIR *d = opendir(path);
    if (!d) return;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        if (strncmp(e->d_name, "slice_", 6) != 0) continue;
        char part[1500];
        snprintf(part, sizeof part, "%s/%s", path, e->d_name);
        unlink(part);
    }
    closedir(d);
    rmdir(path);
}

/* DIR/NAME to path: a rename, or where that crosses file systems, an atomic copy */
static ww_result move_joined(const char *dir, const char *name, const char *path, ww_error *err) {
    char from[1200];
    snprintf(from, sizeof from, "%s/%s", dir, name);
    if (rename(from, path) == 0) return WW_OK;
    if (errno != EXDEV)
        return ww_error_set(err, WW_E_IO, path, 0, 0, "cannot move %s here: %s", from, strerror(errno));
    FILE *in = fopen(from, "rb");
    if (!in) return ww_error_set(err, WW_E_IO, from, 0, 0, "cannot read: %s", strerror(errno));
    ww_stream out;
    ww_result r = ww_stream_open(&out, path, err);
    char buf[1 << 16];
    size_t got;
    while (!r && (got = fread(buf, 1, sizeof buf, in)) > 0)
        if (fwrite(buf, 1, got, out.f) != got)
            r = ww_error_set(err, WW_E_IO, path, 0, 0, "cannot write: %s", strerror(errno));
    if (!r && ferror(in)) r = ww_error_set(err, WW_E_IO, from, 0, 0, "cannot read: %s", strerror(errno));
    fclose(in);
    if (r) {
        if (out.f) ww_stream_abort(&out);
        return r;
    }
    if ((r = ww_stream_commit(&out, err))) return r;
    unlink(from);
    return WW_OK;
}

/* frames of each slice now on disk, counted on from what was seen before (written atomically,
 * so a frame that exists is complete) */
static int64_t frames_seen(const ww_render_jobs *o, child *c, int n) {
    int64_t total = 0;
    char path[1200];
    const char *ext = ww_out_format_ext(o->format);
    int files = o->format == WW_OUT_PNG || o->format == WW_OUT_EXR;
    for (int i = 0; i < n; i++) {
        struct stat sb;
        while (files && c[i].first + c[i].seen < c[i].last) {
            snprintf(path, sizeof path, "%s/frame_%05lld.%s", o->dir,
                     (long long)(c[i].first + c[i].seen), ext);
            if (stat(path, &sb) != 0) break;
            c[i].seen++;
        }
        if (!c[i].running && WIFEXITED(c[i].status) && WEXITSTATUS(c[i].status) == 0)
            c[i].seen = c[i].last - c[i].first;
        total += c[i].seen;
    }
    return total;
}

static void progress_line(const ww_render_jobs *o, child *c, int n, double t0, int final) {
    int64_t all = o->last - o->first, done = frames_seen(o, c, n);
    double t = ww_now_seconds() - t0, fps = t > 0.0 ? (double)done / t : 0.0;
    fprintf(stderr, "\rrender: %lld/%lld frames in %d processes, %.2f fps", (long long)done,
            (long long)all, n, fps);
    if (!final && fps > 0.0 && done < all) fprintf(stderr, ", %.0f s left", (double)(all - done) / fps);
    fprintf(stderr, final ? "\n" : "   ");
}

/* wait for every child, forwarding SIGTERM (Ctrl-C reaches them from the terminal) */
static void wait_all(const ww_render_jobs *o, child *c, int n, int show, double t0) {
    int left = 0;
    for (int i = 0; i < n; i++) left += c[i].running;
    int forwarded = 0;
    double last_line = 0.0;
    while (left > 0) {
        if (jobs_signal == SIGTERM && !forwarded) {
            for (int i = 0; i < n; i++)
                if (c[i].running) kill(c[i].pid, SIGTERM);
            forwarded = 1;
        }
        int status = 0;
        pid_t pid = waitpid(-1, &status, show ? WNOHANG : 0);
        if (pid == 0 || (pid < 0 && errno == EINTR)) {
            if (show && ww_now_seconds() - last_line >= PROGRESS_PERIOD) {
                progress_line(o, c, n, t0, 0);
                last_line = ww_now_seconds();
            }
            if (pid == 0) usleep(50 * 1000);
            continue;
        }
        if (pid < 0) break; /* no child left to wait for */
        for (int i = 0; i < n; i++) {
            if (!c[i].running || c[i].pid != pid) continue;
            c[i].running = 0;
            c[i].status = status;
            left--;
        }
    }
    if (show) progress_line(o, c, n, t0, 1);
}

/* the result a child's wait status stands for (render's exit codes, main.c) */
static ww_result child_result(int status) {
    if (!WIFEXITED(status)) return WW_E_BACKEND;
    switch (WEXITSTATUS(status)) {
    case 0: return WW_OK;
    case 2: return WW_E_USAGE;
    case 130: return WW_E_INTERRUPTED;
    default: return WW_E_BACKEND;
    }
}

ww_result ww_render_jobs_run(const ww_render_jobs *o, ww_render_jobs_stats *st, ww_error *err) {
    double t0 = ww_now_seconds();
    int n = o->jobs;
    if (o->last - o->first < n) n = (int)(o->last - o->first);
    if (n < 1) n = 1;
    ww_render_jobs run = *o;
    run.jobs = n;
    *st = (ww_render_jobs_stats){.jobs = n};

    /* llvmpipe's threads a process: the cores shared out, unless the caller chose */
    char assignment[64];
    char **env = environ, **made = NULL;
    if (!getenv("LP_NUM_THREADS")) {
        long cores = sysconf(_SC_NPROCESSORS_ONLN);
        st->threads = cores > n ? (int)(cores / n) : 1;
        snprintf(assignment, sizeof assignment, "LP_NUM_THREADS=%d", st->threads);
        if (!(env = made = env_with(assignment)))
            return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "render --jobs: out of memory");
    }
    /* a fresh run does not mix with parts an earlier one left */
    if (!o->resume) remove_parts(o->dir);

    child c[WW_RENDER_MAX_JOBS] = {{0}};
    struct sigaction sa, old_int, old_term;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal; /* not SIG_IGN: an ignored signal would stay so in the children */
    sigemptyset(&sa.sa_mask);
    jobs_signal = 0;
    sigaction(SIGINT, &sa, &old_int);
    sigaction(SIGTERM, &sa, &old_term);
    ww_result r = WW_OK;
    int started = 0;
    for (; started < n && !r && !jobs_signal; started++) {
        ww_slice_range(o->first, o->last, started, n, &c[started].first, &c[started].last);
        c[started].pid = spawn_slice(&run, started, env, err);
        if (c[started].pid < 0) {
            r = err->code ? err->code : WW_E_IO;
            break;
        }
        c[started].running = 1;
    }
    int show = o->progress == WW_PROGRESS_ON ||
               (o->progress == WW_PROGRESS_AUTO && !o->quiet && isatty(2));
    wait_all(o, c, started, show && !r, t0);
    sigaction(SIGINT, &old_int, NULL);
    sigaction(SIGTERM, &old_term, NULL);
    free(made);
    if (r) return r;

    /* the first failure in slice order, named; the parts stay for --resume */
    for (int i = 0; i < started; i++) {
        ww_result ri = child_result(c[i].status);
        if (!ri) continue;
        int code = WIFEXITED(c[i].status) ? WEXITSTATUS(c[i].status) : 128 + WTERMSIG(c[i].status);
        return ww_error_set(err, ri, NULL, 0, 0,
                            "render --jobs: slice %d/%d (frames %lld..%lld) %s %d; the frames "
                            "done are kept: run the same command with --resume to finish",
                            i, n, (long long)c[i].first, (long long)c[i].last - 1,
                            WIFEXITED(c[i].status) ? "exited" : "was killed, status", code);
    }
    if (started < n) /* a signal stopped the starting; every slice started has finished */
        return ww_error_set(err, WW_E_INTERRUPTED, NULL, 0, 0,
                            "render --jobs: interrupted by %s before every slice had started",
                            jobs_signal == SIGTERM ? "SIGTERM" : "SIGINT");

    /* the join: the sound track and stats into place, then the parts removed */
    if (o->audio_path || o->stats_path) {
        char *jargv[] = {(char *)o->dir, "--quiet", NULL};
        if ((r = ww_cmd_join(2, jargv, err))) return r;
        if (o->audio_path && (r = move_joined(o->dir, JOBS_AUDIO, o->audio_path, err))) return r;
        if (o->stats_path && (r = move_joined(o->dir, JOBS_STATS, o->stats_path, err))) return r;
    }
    remove_parts(o->dir);
    st->wall_s = ww_now_seconds() - t0;
    return WW_OK;
}
