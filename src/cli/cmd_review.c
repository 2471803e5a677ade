/* cmd_review.c - `waterworld review LIST`: render one frame per shot of a review list with
 * `waterworld render` (this binary, run as a child per shot, a few at once), then build the
 * labelled contact sheet and the HTML page from the frames (check/review.h).
 */
#include <errno.h>
#include <signal.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "check/review.h"
#include "cli/cli.h"
#include "io/outpath.h"
#include "render/job.h"

extern char **environ;

static const char usage[] =
    "usage: waterworld review LIST [-o DIR] [--jobs N] [--size WxH] [--backend B] [--cols N]\n"
    "                         [--thumb WxH] [--no-render] [--quiet]\n"
    "\n"
    "Renders one frame per shot of LIST with `waterworld render` into DIR/shots/NAME.png, then\n"
    "writes DIR/review.png (every shot in one labelled contact sheet) and DIR/index.html (every\n"
    "shot at full size with its label; the images beside it, so the folder opens offline).\n"
    "\n"
    "LIST holds one shot a line, fields separated by '|' (# starts a comment):\n"
    "  NAME | SCENE.yaml | FRAME | CAPTION | [--size WxH] [--set KEY=VALUE]... [--script FILE]\n"
    "and `size: WxH` lines set the size of the shots after them (default 640x360).\n"
    "\n"
    "  -o DIR        output folder (default out/review)\n"
    "  --jobs N      renders at once (default 2)\n"
    "  --size WxH    render every shot at this size instead of the list's\n"
    "  --backend B   passed to render: auto | egl | osmesa | null (black frames, no GL)\n"
    "  --cols N      cells per row of the contact sheet (default 4)\n"
    "  --thumb WxH   cell size in the contact sheet (default 480x270; shots are scaled)\n"
    "  --no-render   build the sheet and the page from the frames already in DIR/shots/\n"
    "  --quiet       no progress lines\n"
    "\n"
    "A bad list line is an error at LIST:line:column (exit 2) before anything renders; a shot\n"
    "whose render fails leaves a marked cell, and the command exits with the render's failure.\n";

/* Ctrl-C or SIGTERM during the renders: the children (same process group) get it too and stop
 * cleanly; this process starts no more, collects them, removes their folders and exits 130 */
static volatile sig_atomic_t stop_signal;
static void on_signal(int sig) { stop_signal = sig; }

typedef struct job {
    pid_t pid;
    int shot;
    double started;
} job;

static ww_result mkdir_p(const char *dir, ww_error *err) {
    char buf[1100];
    snprintf(buf, sizeof buf, "%s", dir);
    for (char *p = buf + 1;; p++) {
        if (*p == '/' || *p == 0) {
            char c = *p;
            *p = 0;
            if (mkdir(buf, 0777) != 0 && errno != EEXIST)
                return ww_error_set(err, WW_E_IO, buf, 0, 0, "cannot make the folder: %s", strerror(errno));
            *p = c;
            if (!c) break;
        }
    }
    return WW_OK;
}

static int parse_wxh(const char *s, int *w, int *h) {
    char *e = NULL;
    long a = strtol(s, &e, 10);
    if (e == s || (*e != 'x' && *e != 'X')) return -1;
    const char *b = e + 1;
    long c = strtol(b, &e, 10);
    if (e == b || *e != 0 || a < 16 || c < 16 || a > 16384 || c > 16384) return -1;
    *w = (int)a;
    *h = (int)c;
    return 0;
}

typedef struct opts {
    const char *list, *out, *backend;
    int jobs, quiet, no_render;
    int size_w, size_h;       /* 0: the list's sizes */
    ww_review_sheet_opts sheet;
} opts;

/* the private folder a shot renders into, beside its final name */
static void tmp_dir(const char *out, const ww_review_shot *s, char *buf, size_t cap) {
    snprintf(buf, cap, "%s/shots/.%s.%ld", out, s->name, (long)getpid());
}

static pid_t spawn_render(const char *exe, const opts *o, const ww_review_shot *s, ww_error *err) {
    char frames[64], size[40], dir[1100];
    snprintf(frames, sizeof frames, "%lld:%lld", s->frame, s->frame + 1);
    snprintf(size, sizeof size, "%dx%d", s->width, s->height);
    tmp_dir(o->out, s, dir, sizeof dir);
    char *argv[16 + 2 * WW_REVIEW_MAX_SETS];
    int n = 0;
    argv[n++] = (char *)exe;
    argv[n++] = "render";
    argv[n++] = (char *)s->scene;
    argv[n++] = "--frames";
    argv[n++] = frames;
    argv[n++] = "--size";
    argv[n++] = size;
    argv[n++] = "--quiet";
    argv[n++] = "-o";
    argv[n++] = dir;
    if (o->backend) {
        argv[n++] = "--backend";
        argv[n++] = (char *)o->backend;
    }
    if (s->script[0]) {
        argv[n++] = "--script";
        argv[n++] = (char *)s->script;
    }
    for (int k = 0; k < s->nsets; k++) {
        argv[n++] = "--set";
        argv[n++] = (char *)s->sets[k];
    }
    argv[n] = NULL;
    pid_t pid = -1;
    int rc = posix_spawn(&pid, exe, NULL, NULL, argv, environ);
    if (rc != 0) {
        ww_error_set(err, WW_E_IO, exe, 0, 0, "cannot run render: %s", strerror(rc));
        return -1;
    }
    return pid;
}

/* a finished render: move its frame into place; the failure as a result */
static ww_result finish(const opts *o, const ww_review_shot *s, int status, ww_error *err) {
    char dir[1100], frame[1200], final[1100];
    tmp_dir(o->out, s, dir, sizeof dir);
    snprintf(frame, sizeof frame, "%s/frame_%05lld.png", dir, s->frame);
    ww_review_shot_path(o->out, s, final, sizeof final);
    ww_result r = WW_OK;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        r = ww_error_set(err, code == 130 ? WW_E_INTERRUPTED : code == 3 ? WW_E_BACKEND : WW_E_IO, NULL, 0, 0,
                         "shot '%s' (line %d): render exited %d", s->name, s->line, code);
    } else if (rename(frame, final) != 0) {
        r = ww_error_set(err, WW_E_IO, final, 0, 0, "cannot move the frame into place: %s", strerror(errno));
    }
    unlink(frame);
    rmdir(dir);
    return r;
}

static ww_result render_all(const opts *o, const ww_review_list *l, ww_error *err) {
    char exe[1024];
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n <= 0) return ww_error_set(err, WW_E_IO, "/proc/self/exe", 0, 0, "cannot find this binary");
    exe[n] = 0;

    /* handlers, not SIG_IGN: an ignored signal would stay ignored in the children */
    struct sigaction sa, old_int, old_term;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &old_int);
    sigaction(SIGTERM, &sa, &old_term);
    stop_signal = 0;

    job running[64];
    int nrun = 0, next = 0, done = 0;
    ww_result first_fail = WW_OK;
    ww_error fail_err = {0};
    double t0 = ww_now_seconds();
    while (done < l->n) {
        /* start renders up to --jobs */
        if (stop_signal && nrun == 0) break;
        while (!stop_signal && nrun < o->jobs && next < l->n) {
            const ww_review_shot *s = &l->shots[next];
            char final[1100];
            ww_review_shot_path(o->out, s, final, sizeof final);
            unlink(final); /* a failed render must not leave last run's picture in its cell */
            ww_error e = {0};
            pid_t pid = spawn_render(exe, o, s, &e);
            if (pid < 0) {
                if (!first_fail) fail_err = e, first_fail = e.code;
                next++;
                done++;
                continue;
            }
            running[nrun++] = (job){pid, next++, ww_now_seconds()};
        }
        if (nrun == 0) continue;
        int status = 0;
        pid_t pid = waitpid(-1, &status, 0);
        if (pid < 0) {
            if (errno == EINTR) continue;
            return ww_error_set(err, WW_E_IO, NULL, 0, 0, "waitpid: %s", strerror(errno));
        }
        for (int j = 0; j < nrun; j++) {
            if (running[j].pid != pid) continue;
            const ww_review_shot *s = &l->shots[running[j].shot];
            ww_error e = {0};
            ww_result r = finish(o, s, status, &e);
            done++;
            if (r) {
                if (!stop_signal) ww_error_print(&e, stderr);
                if (!first_fail) fail_err = e, first_fail = r;
            } else if (!o->quiet) {
                fprintf(stderr, "review: [%d/%d] %-22s %5.1f s\n", done, l->n, s->name, ww_now_seconds() - running[j].started);
            }
            running[j] = running[--nrun];
            break;
        }
    }
    sigaction(SIGINT, &old_int, NULL);
    sigaction(SIGTERM, &old_term, NULL);
    if (stop_signal)
        return ww_error_set(err, WW_E_INTERRUPTED, NULL, 0, 0,
                            "interrupted by %s: %d of %d shots finished, no sheet written",
                            stop_signal == SIGINT ? "SIGINT" : "SIGTERM", done, l->n);
    if (!o->quiet) fprintf(stderr, "review: %d shots rendered in %.1f s\n", l->n, ww_now_seconds() - t0);
    if (first_fail) *err = fail_err;
    return first_fail;
}

ww_result ww_cmd_review(int argc, char **argv, ww_error *err) {
    opts o = {.out = "out/review", .jobs = 2};
    const char *jobs = NULL, *size = NULL, *cols = NULL, *thumb = NULL;
    ww_result r = WW_OK;
    for (int i = 0; i < argc && !r; i++) {
        if (ww_cli_is_help(argv[i])) {
            fputs(usage, stdout);
            return WW_OK;
        }
        if (ww_cli_opt(argc, argv, &i, "-o", &o.out, &r, err)) continue;
        if (ww_cli_opt(argc, argv, &i, "--jobs", &jobs, &r, err)) continue;
        if (ww_cli_opt(argc, argv, &i, "--size", &size, &r, err)) continue;
        if (ww_cli_opt(argc, argv, &i, "--backend", &o.backend, &r, err)) continue;
        if (ww_cli_opt(argc, argv, &i, "--cols", &cols, &r, err)) continue;
        if (ww_cli_opt(argc, argv, &i, "--thumb", &thumb, &r, err)) continue;
        if (strcmp(argv[i], "--no-render") == 0) {
            o.no_render = 1;
            continue;
        }
        if (strcmp(argv[i], "--quiet") == 0) {
            o.quiet = 1;
            continue;
        }
        if (argv[i][0] == '-' || o.list) {
            r = ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "review: unexpected argument '%s' (see --help)", argv[i]);
            break;
        }
        o.list = argv[i];
    }
    if (r) return r;
    if (!o.list) return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "review needs a list file (waterworld review --help)");
    if (jobs) {
        char *e = NULL;
        long v = strtol(jobs, &e, 10);
        if (e == jobs || *e || v < 1 || v > 64)
            return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--jobs wants 1..64, got '%s'", jobs);
        o.jobs = (int)v;
    }
    if (cols) {
        char *e = NULL;
        long v = strtol(cols, &e, 10);
        if (e == cols || *e || v < 1 || v > 64)
            return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--cols wants 1..64, got '%s'", cols);
        o.sheet.cols = (int)v;
    }
    if (size && parse_wxh(size, &o.size_w, &o.size_h) != 0)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--size wants WIDTHxHEIGHT (each 16..16384), got '%s'", size);
    if (thumb && parse_wxh(thumb, &o.sheet.thumb_w, &o.sheet.thumb_h) != 0)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--thumb wants WIDTHxHEIGHT (each 16..16384), got '%s'", thumb);
    if ((r = ww_check_out_dir("-o", o.out, err))) return r;

    /* the whole list is read and every shot's scene loaded before anything renders */
    ww_review_list l;
    if ((r = ww_review_load(o.list, &l, err))) return r;
    for (int i = 0; o.size_w && i < l.n; i++) {
        l.shots[i].width = o.size_w;
        l.shots[i].height = o.size_h;
    }
    if ((r = ww_review_check(&l, err))) {
        ww_review_free(&l);
        return r;
    }
    char shots[1100];
    snprintf(shots, sizeof shots, "%s/shots", o.out);
    if ((r = mkdir_p(shots, err))) {
        ww_review_free(&l);
        return r;
    }

    ww_error render_err = {0};
    ww_result rr = o.no_render ? WW_OK : render_all(&o, &l, &render_err);
    if (rr == WW_E_INTERRUPTED) {
        *err = render_err;
        ww_review_free(&l);
        return rr;
    }
    int missing = 0;
    r = ww_review_sheet(&l, o.out, &o.sheet, &missing, err);
    if (!r) r = ww_review_html(&l, o.out, err);
    if (!r && !o.quiet)
        fprintf(stderr, "review: %s/review.png and %s/index.html (%d shots%s)\n", o.out, o.out, l.n,
                missing ? ", some without an image" : "");
    if (!r && missing && !o.quiet) fprintf(stderr, "review: %d shot(s) without an image\n", missing);
    ww_review_free(&l);
    if (r) return r;
    if (rr) {
        *err = render_err;
        return rr;
    }
    return WW_OK;
}
