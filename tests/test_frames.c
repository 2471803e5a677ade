/* test_frames.c - frames out: the writers read back by other tools (oiiotool, ffprobe,
 * ffmpeg), --alpha, streams, make-video.sh, SIGKILL then --resume, SIGINT, thread counts,
 * --stats and the progress line; and the pieces underneath (queue, Y4M header, completeness
 * checks).
 */
#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "io/queue.h"
#include "io/writers.h"
#include "io/y4m.h"
#include "test.h"

#define W 256
#define H 144
#define SCENE "scenes/demo.yaml"
/* Y4M is limited range (219 luma levels for 256): RGB -> Y'CbCr -> RGB through ffmpeg comes back
 * within 2 levels per channel */
#define Y4M_ROUND_TRIP_LEVELS 2
/* the polls of a running render: every 5 ms, for at most 20 s */
#define POLL_US 5000
#define POLL_MAX 4000

static char *tmp(const char *name, char *buf, size_t cap) {
    snprintf(buf, cap, "%s", ww_test_tmpdir(name));
    return buf;
}

/* a shell command line's stdout (a group: pipes and || inside are kept), malloc'd; NULL on
 * failure */
static char *capture(const char *cmd, const char *dir) {
    char out[1024], group[2200];
    snprintf(out, sizeof out, "%s/capture.txt", dir);
    snprintf(group, sizeof group, "{ %s; }", cmd);
    if (ww_test_run(group, out, NULL) != 0) return NULL;
    return ww_test_read_file(out, NULL);
}

static long file_size(const char *path) {
    struct stat st;
    return stat(path, &st) == 0 ? (long)st.st_size : -1;
}

/* entries of dir whose name contains part */
static int dir_count(const char *dir, const char *part) {
    DIR *d = opendir(dir);
    if (!d) return -1;
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) n += strcmp(e->d_name, ".") && strcmp(e->d_name, "..") && strstr(e->d_name, part);
    closedir(d);
    return n;
}

/* frame_XXXXX.png files in dir; also counts temporary files ("frame_*.tmp.*") into *tmps */
static int count_frames(const char *dir, int n, int *tmps) {
    int have = 0;
    char cmd[2200];
    for (int f = 0; f < n; f++) {
        snprintf(cmd, sizeof cmd, "%s/frame_%05d.png", dir, f);
        if (file_size(cmd) > 0) have++;
    }
    if (tmps) *tmps = dir_count(dir, ".tmp.");
    return have;
}

/* start `waterworld ARGS` with SIGINT at its default (a test runner may ignore it) */
static pid_t spawn(const char *args, const char *err_path) {
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "exec %s %s", ww_test_bin(), args);
    pid_t pid = fork();
    if (pid == 0) {
        signal(SIGINT, SIG_DFL);
        signal(SIGTERM, SIG_DFL);
        int fd = open(err_path, O_WRONLY | O_CREAT | O_TRUNC, 0666);
        int nul = open("/dev/null", O_RDWR);
        if (fd >= 0) dup2(fd, 2);
        if (nul >= 0) {
            dup2(nul, 0);
            dup2(nul, 1);
        }
        execl("/bin/sh", "sh", "-c", cmd, (char *)NULL);
        _exit(127);
    }
    return pid;
}

/* wait until `path` exists (the run is under way), up to POLL_MAX polls; 1 when it did */
static int wait_for(const char *path, pid_t pid) {
    for (int i = 0; i < POLL_MAX; i++) {
        if (file_size(path) > 0) return 1;
        if (waitpid(pid, NULL, WNOHANG) == pid) return 0;
        usleep(POLL_US);
    }
    return 0;
}

static int exit_status(pid_t pid, int *signalled) {
    int st = 0;
    waitpid(pid, &st, 0);
    *signalled = WIFSIGNALED(st) ? WTERMSIG(st) : 0;
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/* every frame file present decodes, at the render size */
static int frames_decode(const char *dir, int n) {
    int bad = 0;
    for (int f = 0; f < n; f++) {
        char p[2200];
        snprintf(p, sizeof p, "%s/frame_%05d.png", dir, f);
        if (file_size(p) < 0) continue;
        ww_image im;
        ww_error err;
        if (ww_read_png(p, &im, &err) != WW_OK || im.width != W || im.height != H) bad++;
        ww_image_free(&im);
    }
    return bad;
}

static int same_frames(const char *a, const char *b, int n) {
    int diff = 0;
    for (int f = 0; f < n; f++) {
        char pa[2200], pb[2200];
        snprintf(pa, sizeof pa, "%s/frame_%05d.png", a, f);
        snprintf(pb, sizeof pb, "%s/frame_%05d.png", b, f);
        diff += !ww_test_files_equal(pa, pb);
    }
    return diff;
}

/* ---- pieces -------------------------------------------------------------------------------- */

TEST(frames_queue_is_fifo_and_close_drains) {
    ww_queue q;
    ENSURE_EQ_INT(ww_queue_init(&q, 3), 0);
    int v[3] = {1, 2, 3};
    for (int i = 0; i < 3; i++) ww_queue_push(&q, &v[i]);
    ENSURE(ww_queue_pop(&q) == &v[0]);
    ww_queue_push(&q, &v[0]); /* wraps around the ring */
    ww_queue_close(&q);
    ENSURE(ww_queue_pop(&q) == &v[1]);
    ENSURE(ww_queue_pop(&q) == &v[2]);
    ENSURE(ww_queue_pop(&q) == &v[0]);
    ENSURE(ww_queue_pop(&q) == NULL);
    ww_queue_free(&q);
}

TEST(frames_y4m_rates_and_colours) {
    long n, d;
    ww_fps_rational(30.0, &n, &d);
    ENSURE(n == 30 && d == 1);
    ww_fps_rational(30000.0 / 1001.0, &n, &d);
    ENSURE(n == 30000 && d == 1001);
    ww_fps_rational(12.5, &n, &d);
    ENSURE(n == 25 && d == 2);
    char h[160];
    ww_y4m_header(h, sizeof h, 640, 360, 24000.0 / 1001.0, 1);
    ENSURE_MSG(strcmp(h, "YUV4MPEG2 W640 H360 F24000:1001 Ip A1:1 C420jpeg XYSCSS=420JPEG "
                         "XCOLORRANGE=LIMITED\n") == 0, "header: %s", h);

    /* BT.709 limited range: black 16/128/128, white 235/128/128, pure red Y 63 Cb 102 Cr 240 */
    ww_image im;
    ENSURE_EQ_INT(ww_image_alloc(&im, 3, 1, 3, WW_PIX_U8), 0);
    const uint8_t px[9] = {0, 0, 0, 255, 255, 255, 255, 0, 0};
    memcpy(im.u8, px, sizeof px);
    uint8_t out[64];
    ENSURE_EQ_INT(ww_y4m_frame_bytes(3, 1, 0), 6 + 9);
    ww_y4m_frame(&im, 0, out);
    ENSURE(memcmp(out, "FRAME\n", 6) == 0);
    const uint8_t want[9] = {16, 235, 63, 128, 128, 102, 128, 128, 240};
    for (int i = 0; i < 9; i++) ENSURE_MSG(out[6 + i] == want[i], "byte %d: %d != %d", i, out[6 + i], want[i]);
    /* 4:2:0 of a 3x1 image: chroma 2x1, the last block cut at the edge (red alone) */
    ENSURE_EQ_INT(ww_y4m_frame_bytes(3, 1, 1), 6 + 3 + 2 * 2);
    ww_y4m_frame(&im, 1, out);
    ENSURE_EQ_INT(out[6 + 3 + 1], 102);
    ENSURE_EQ_INT(out[6 + 3 + 2 + 1], 240);
    ww_image_free(&im);
}

TEST(frames_completeness_checks_catch_truncation) {
    char dir[160], png[1024], exr[1024], cut[1024];
    tmp("frames_complete", dir, sizeof dir);
    snprintf(png, sizeof png, "%s/a.png", dir);
    snprintf(exr, sizeof exr, "%s/a.exr", dir);
    ww_image im, hdr;
    ww_error err;
    ENSURE_EQ_INT(ww_image_alloc(&im, 40, 30, 3, WW_PIX_U8), 0);
    ENSURE_EQ_INT(ww_image_alloc(&hdr, 40, 30, 4, WW_PIX_F32), 0);
    for (size_t i = 0; i < 40 * 30 * 3; i++) im.u8[i] = (uint8_t)(i * 7);
    for (size_t i = 0; i < 40 * 30 * 4; i++) hdr.f32[i] = (float)i * 0.01f;
    ENSURE_EQ_INT(ww_write_png(png, &im, &err), WW_OK);
    ENSURE_EQ_INT(ww_write_exr(exr, &hdr, NULL, &err), WW_OK);
    ENSURE(ww_png_complete(png));
    ENSURE(ww_exr_complete(exr));
    /* the same files cut short by 10 bytes */
    const char *files[2] = {png, exr};
    for (int k = 0; k < 2; k++) {
        size_t n = 0;
        char *b = ww_test_read_file(files[k], &n);
        snprintf(cut, sizeof cut, "%s/cut.%s", dir, k ? "exr" : "png");
        FILE *f = fopen(cut, "wb");
        ENSURE(b && f && fwrite(b, 1, n - 10, f) == n - 10);
        if (f) fclose(f);
        free(b);
        ENSURE_MSG(!(k ? ww_exr_complete(cut) : ww_png_complete(cut)), "truncated %s passes", cut);
    }
    ww_image_free(&im);
    ww_image_free(&hdr);
}

/* ---- writers, read by other tools ---------------------------------------------------------- */

TEST_PROC(frames_exr_read_by_oiiotool) {
    REQUIRE_GL();
    char dir[160], a[1024], info[900];
    tmp("frames_exr", dir, sizeof dir);
    struct { const char *args, *type, *comp; } cases[] = {
        {"", "half", "zip"},
        {"--exr-float --exr-compression piz", "float", "piz"},
        {"--exr-compression none --alpha", "half", "none"},
    };
    for (int k = 0; k < 3; k++) {
        snprintf(a, sizeof a, "render " SCENE " --size %dx%d --frames 2 --format exr %s -o %s/%d --quiet",
                 W, H, cases[k].args, dir, k);
        ENSURE_EQ_INT(ww_test_ww(a, NULL, NULL), 0);
        snprintf(a, sizeof a, "oiiotool --info -v %s/%d/frame_00001.exr", dir, k);
        char *s = capture(a, dir);
        ENSURE_MSG(s, "%s failed", a);
        if (!s) continue;
        snprintf(info, sizeof info, "%d x  %d, 4 channel, %s", W, H, cases[k].type);
        ENSURE_MSG(strstr(s, info), "want '%s' in: %s", info, s);
        snprintf(info, sizeof info, "compression: \"%s\"", cases[k].comp);
        ENSURE_MSG(strstr(s, info), "want '%s' in: %s", info, s);
        ENSURE(strstr(s, "channel list: R, G, B, A"));
        ENSURE(strstr(s, "frame: 1"));
        ENSURE(strstr(s, "scene: \"demo\""));
        ENSURE(strstr(s, "renderer: \""));
        ENSURE_MSG(strstr(s, "time: 0.0333"), "frame 1 at 30 fps: %s", s);
        free(s);
    }
    /* --alpha: A is 0 or 1 and both occur (sky and water) */
    snprintf(a, sizeof a, "%s/2/frame_00000.exr", dir);
    ww_image im;
    ww_error err;
    ENSURE_EQ_INT(ww_read_exr(a, &im, &err), WW_OK);
    long zero = 0, one = 0, other = 0;
    for (size_t i = 0; i < (size_t)im.width * (size_t)im.height; i++) {
        float v = im.f32[4 * i + 3];
        zero += v == 0.0f;
        one += v == 1.0f;
        other += v != 0.0f && v != 1.0f;
    }
    ENSURE_MSG(zero > 0 && one > 0 && other == 0, "alpha 0: %ld, 1: %ld, other %ld", zero, one, other);
    ww_image_free(&im);
}

/* --alpha: RGBA8 whose alpha is 0 exactly where only the sky is seen. The demo's camera looks at
 * the horizon: the top row is sky, the bottom row water; the RGB equals the RGB-only frame. */
TEST_PROC(frames_png_alpha_is_sky_coverage) {
    REQUIRE_GL();
    char dir[160], a[2048];
    tmp("frames_alpha", dir, sizeof dir);
    snprintf(a, sizeof a, "render " SCENE " --size %dx%d --frames 1 --alpha -o %s/rgba --quiet", W, H, dir);
    ENSURE_EQ_INT(ww_test_ww(a, NULL, NULL), 0);
    snprintf(a, sizeof a, "render " SCENE " --size %dx%d --frames 1 -o %s/rgb --quiet", W, H, dir);
    ENSURE_EQ_INT(ww_test_ww(a, NULL, NULL), 0);
    ww_image ra, rb;
    ww_error err;
    snprintf(a, sizeof a, "%s/rgba/frame_00000.png", dir);
    ENSURE_EQ_INT(ww_read_png(a, &ra, &err), WW_OK);
    snprintf(a, sizeof a, "%s/rgb/frame_00000.png", dir);
    ENSURE_EQ_INT(ww_read_png(a, &rb, &err), WW_OK);
    ENSURE_EQ_INT(ra.channels, 4);
    ENSURE_EQ_INT(rb.channels, 3);
    if (ra.channels == 4 && rb.channels == 3) {
        long top0 = 0, bottom255 = 0, other = 0, rgb_diff = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                size_t i = (size_t)y * W + (size_t)x;
                uint8_t al = ra.u8[4 * i + 3];
                other += al != 0 && al != 255;
                if (y == 0) top0 += al == 0;
                if (y == H - 1) bottom255 += al == 255;
                for (int c = 0; c < 3; c++) rgb_diff += ra.u8[4 * i + c] != rb.u8[3 * i + c];
            }
        }
        ENSURE_MSG(top0 == W && bottom255 == W && other == 0,
                   "top row alpha 0: %ld/%d, bottom row 255: %ld/%d, other values %ld", top0, W,
                   bottom255, W, other);
        ENSURE_EQ_INT(rgb_diff, 0);
    }
    ww_image_free(&ra);
    ww_image_free(&rb);
}

TEST_PROC(frames_y4m_and_raw_streams) {
    REQUIRE_GL();
    char dir[160], a[2048];
    tmp("frames_y4m", dir, sizeof dir);
    const int n = 3;
    /* to stdout, through a pipe into ffprobe; to a file with 4:2:0 */
    snprintf(a, sizeof a, "%s render " SCENE " --size %dx%d --frames %d --format y4m -o - --quiet | "
             "ffprobe -v error -count_frames -show_streams -of flat -", ww_test_bin(), W, H, n);
    char *s = capture(a, dir);
    snprintf(a, sizeof a, "render " SCENE " --size %dx%d --frames %d --format y4m --y4m-420 -o %s/v.y4m --quiet",
             W, H, n, dir);
    ENSURE_EQ_INT(ww_test_ww(a, NULL, NULL), 0);
    snprintf(a, sizeof a, "ffprobe -v error -count_frames -show_streams -of flat %s/v.y4m", dir);
    char *f = capture(a, dir);
    const char *want[] = {"nb_read_frames=\"3\"", "width=256", "height=144", "r_frame_rate=\"30/1\"",
                          "color_range=\"tv\""};
    for (size_t i = 0; i < sizeof want / sizeof want[0]; i++) {
        ENSURE_MSG(s && strstr(s, want[i]), "stdout stream: want %s in %s", want[i], s ? s : "(none)");
        ENSURE_MSG(f && strstr(f, want[i]), "file stream: want %s in %s", want[i], f ? f : "(none)");
    }
    ENSURE(s && strstr(s, "pix_fmt=\"yuv444p\""));
    ENSURE(f && strstr(f, "pix_fmt=\"yuvj420p\"") + !!strstr(f, "pix_fmt=\"yuv420p\""));
    free(s);
    free(f);

    /* raw: W H 3 bytes a frame, the PNG's pixels; Y4M 4:4:4 decoded by ffmpeg comes back close */
    snprintf(a, sizeof a, "render " SCENE " --size %dx%d --frames %d --format raw -o %s/v.rgb --quiet", W, H, n, dir);
    ENSURE_EQ_INT(ww_test_ww(a, NULL, NULL), 0);
    snprintf(a, sizeof a, "%s/v.rgb", dir);
    ENSURE_EQ_INT(file_size(a), (long)W * H * 3 * n);
    snprintf(a, sizeof a, "render " SCENE " --size %dx%d --frames 1 -o %s/png --quiet", W, H, dir);
    ENSURE_EQ_INT(ww_test_ww(a, NULL, NULL), 0);
    snprintf(a, sizeof a, "render " SCENE " --size %dx%d --frames %d --format y4m -o %s/v444.y4m --quiet", W, H, n, dir);
    ENSURE_EQ_INT(ww_test_ww(a, NULL, NULL), 0);
    snprintf(a, sizeof a, "ffmpeg -v error -y -i %s/v444.y4m -vf scale=in_color_matrix=bt709:in_range=tv:"
             "out_range=pc:flags=accurate_rnd+full_chroma_int -pix_fmt rgb24 -f rawvideo %s/back.rgb", dir, dir);
    ENSURE_EQ_INT(ww_test_run(a, NULL, NULL), 0);
    size_t nr = 0, nb = 0;
    snprintf(a, sizeof a, "%s/v.rgb", dir);
    unsigned char *raw = (unsigned char *)ww_test_read_file(a, &nr);
    snprintf(a, sizeof a, "%s/back.rgb", dir);
    unsigned char *back = (unsigned char *)ww_test_read_file(a, &nb);
    ww_image png;
    ww_error err;
    snprintf(a, sizeof a, "%s/png/frame_00000.png", dir);
    ENSURE_EQ_INT(ww_read_png(a, &png, &err), WW_OK);
    ENSURE(raw && png.u8 && memcmp(raw, png.u8, (size_t)W * H * 3) == 0);
    ENSURE(raw && back && nr == nb);
    int worst = 0;
    for (size_t i = 0; raw && back && i < nr && i < nb; i++) {
        int d = abs((int)raw[i] - (int)back[i]);
        if (d > worst) worst = d;
    }
    ENSURE_NEAR(worst, 0, Y4M_ROUND_TRIP_LEVELS);
    ww_image_free(&png);
    free(raw);
    free(back);
}

TEST_PROC(frames_make_video) {
    REQUIRE_GL();
    char dir[160], a[2048];
    tmp("frames_video", dir, sizeof dir);
    snprintf(a, sizeof a, "WW_BIN=%s MAKE_VIDEO_PRESET=ultrafast sh -c 'scripts/make-video.sh " SCENE
             " %s/demo.mp4 --size %dx%d --frames 6 --quiet'", ww_test_bin(), dir, W, H);
    ENSURE_EQ_INT(ww_test_run(a, NULL, NULL), 0);
    snprintf(a, sizeof a, "ffprobe -v error -count_frames -show_streams -of flat %s/demo.mp4", dir);
    char *s = capture(a, dir);
    const char *want[] = {"codec_name=\"h264\"", "pix_fmt=\"yuv420p\"", "nb_read_frames=\"6\"",
                          "color_space=\"bt709\"", "width=256"};
    for (size_t i = 0; i < sizeof want / sizeof want[0]; i++)
        ENSURE_MSG(s && strstr(s, want[i]), "want %s in %s", want[i], s ? s : "(none)");
    /* a sound track exactly when the plan names one */
    snprintf(a, sizeof a, "%s plan " SCENE " | grep -c '^audio:' || true", ww_test_bin());
    char *p = capture(a, dir);
    int audio = p && atoi(p) > 0;
    ENSURE_EQ_INT(s && strstr(s, "codec_type=\"audio\"") != NULL, audio);
    free(p);
    free(s);
    /* nothing beside it: the temporary folder is gone */
    ENSURE_EQ_INT(dir_count(dir, "make-video"), 0);
    /* ffmpeg missing: a message and exit 3, no output */
    snprintf(a, sizeof a, "PATH=/nonexistent WW_BIN=%s /bin/bash scripts/make-video.sh " SCENE " %s/x.mp4",
             ww_test_bin(), dir);
    char err_path[1024];
    snprintf(err_path, sizeof err_path, "%s/err.txt", dir);
    ENSURE_EQ_INT(ww_test_run(a, NULL, err_path), 3);
    ENSURE(ww_test_file_contains(err_path, "ffmpeg"));
}

/* ---- interruption and resume --------------------------------------------------------------- */

TEST_PROC(frames_sigkill_then_resume_matches_one_run) {
    REQUIRE_GL();
    char dir[160], a[2048], err_path[1024], first[1024];
    tmp("frames_kill", dir, sizeof dir);
    const int n = 24;
    snprintf(err_path, sizeof err_path, "%s/err.txt", dir);
    snprintf(a, sizeof a, "render " SCENE " --size %dx%d --frames %d -o %s/whole --quiet", W, H, n, dir);
    ENSURE_EQ_INT(ww_test_ww(a, NULL, NULL), 0);

    /* the killed run asks for far more frames than any renderer writes before the kill lands
     * (a GPU could finish 24 in the time a poll takes), then --resume completes the first n */
    const int many = 20000;
    snprintf(a, sizeof a, "render " SCENE " --size %dx%d --frames %d -o %s/killed --quiet "
             "--set time.duration=%d", W, H, many, dir, many / 30 + 1);
    pid_t pid = spawn(a, err_path);
    snprintf(first, sizeof first, "%s/killed/frame_00002.png", dir);
    int started = wait_for(first, pid);
    kill(pid, SIGKILL);
    int sig = 0;
    exit_status(pid, &sig);
    ENSURE_MSG(started && sig == SIGKILL, "the render ended before it could be killed");

    /* what is on disk decodes, and the run was cut short */
    snprintf(a, sizeof a, "%s/killed", dir);
    int all = count_frames(a, many, NULL), have = count_frames(a, n, NULL);
    ENSURE_MSG(all >= 3 && all < many, "%d of %d frames before the kill", all, many);
    ENSURE_EQ_INT(frames_decode(a, many), 0);

    snprintf(a, sizeof a, "render " SCENE " --size %dx%d --frames %d -o %s/killed --resume", W, H, n, dir);
    ENSURE_EQ_INT(ww_test_ww(a, NULL, err_path), 0);
    char want[64];
    snprintf(want, sizeof want, "%d already done", have);
    ENSURE_MSG(ww_test_file_contains(err_path, want), "resume should say '%s'", want);
    snprintf(a, sizeof a, "%s/killed", dir);
    int tmps = -1;
    ENSURE_EQ_INT(count_frames(a, n, &tmps), n);
    ENSURE_EQ_INT(tmps, 0);
    char b[1024];
    snprintf(b, sizeof b, "%s/whole", dir);
    ENSURE_EQ_INT(same_frames(a, b, n), 0);

    /* a damaged frame is rendered again */
    snprintf(a, sizeof a, "%s/killed/frame_00001.png", dir);
    ENSURE_EQ_INT(truncate(a, 100), 0);
    snprintf(a, sizeof a, "render " SCENE " --size %dx%d --frames %d -o %s/killed --resume --quiet", W, H, n, dir);
    ENSURE_EQ_INT(ww_test_ww(a, NULL, NULL), 0);
    snprintf(a, sizeof a, "%s/killed", dir);
    ENSURE_EQ_INT(same_frames(a, b, n), 0);

    /* --resume needs frame files */
    snprintf(a, sizeof a, "render " SCENE " --format y4m -o %s/x.y4m --resume", dir);
    ENSURE_EQ_INT(ww_test_ww(a, NULL, NULL), 2);
}

TEST_PROC(frames_sigint_finishes_in_flight_and_exits_130) {
    /* what a signal does to the job needs no pixels: the null backend, so this runs without GL */
    char dir[160], a[2048], err_path[1024], first[1024];
    tmp("frames_int", dir, sizeof dir);
    /* far more frames than are ever written: the signal lands mid-run on any renderer (a GPU
     * renders 60 of these frames in well under the time the test waits) */
    const int n = 20000;
    snprintf(err_path, sizeof err_path, "%s/err.txt", dir);
    snprintf(a, sizeof a, "render " SCENE " --backend null --size %dx%d --frames %d -o %s/png --set time.duration=%d",
             W, H, n, dir, n / 30 + 1);
    pid_t pid = spawn(a, err_path);
    snprintf(first, sizeof first, "%s/png/frame_00001.png", dir);
    int started = wait_for(first, pid);
    kill(pid, SIGINT);
    int sig = 0, code = exit_status(pid, &sig);
    ENSURE_MSG(started, "the render ended before SIGINT");
    ENSURE_EQ_INT(code, 130);
    ENSURE(ww_test_file_contains(err_path, "interrupted by SIGINT"));
    ENSURE(ww_test_file_contains(err_path, "--resume"));
    snprintf(a, sizeof a, "%s/png", dir);
    int tmps = -1, have = count_frames(a, n, &tmps);
    ENSURE_MSG(have >= 2 && have < n, "%d frames", have);
    ENSURE_EQ_INT(tmps, 0);
    ENSURE_EQ_INT(frames_decode(a, n), 0);

    /* a Y4M file interrupted is not left at all (a stream is kept only whole) */
    snprintf(a, sizeof a, "render " SCENE " --backend null --size %dx%d --frames %d --format y4m -o %s/y/v.y4m --stats %s/y/s.jsonl "
             "--set time.duration=%d", W, H, n, dir, dir, n / 30 + 1);
    ENSURE_EQ_INT(mkdir(strcat(strcpy(first, dir), "/y"), 0777), 0);
    pid = spawn(a, err_path);
    /* the stream's temporary file grows as frames go in: signal once two frames are in it */
    snprintf(first, sizeof first, "%s/y", dir);
    char tmpfile[1100];
    snprintf(tmpfile, sizeof tmpfile, "%s/v.y4m.tmp.%ld", first, (long)pid); /* sh execs it */
    struct stat st;
    for (int i = 0; i < POLL_MAX && (stat(tmpfile, &st) != 0 || st.st_size < 2L * W * H * 3); i++)
        usleep(POLL_US);
    kill(pid, SIGTERM);
    code = exit_status(pid, &sig);
    ENSURE_EQ_INT(code, 130);
    ENSURE_EQ_INT(dir_count(first, ""), 0);
}

/* ---- threads, stats, progress -------------------------------------------------------------- */

TEST_PROC(frames_threads_give_identical_bytes) {
    REQUIRE_GL();
    char dir[160], a[2048], b[1024];
    tmp("frames_threads", dir, sizeof dir);
    const int n = 6;
    snprintf(a, sizeof a, "render " SCENE " --size %dx%d --frames %d -o %s/t1 --threads 1 --quiet", W, H, n, dir);
    ENSURE_EQ_INT(ww_test_ww(a, NULL, NULL), 0);
    snprintf(a, sizeof a, "render " SCENE " --size %dx%d --frames %d -o %s/t4 --threads 4 --quiet", W, H, n, dir);
    ENSURE_EQ_INT(ww_test_ww(a, NULL, NULL), 0);
    snprintf(a, sizeof a, "%s/t1", dir);
    snprintf(b, sizeof b, "%s/t4", dir);
    ENSURE_EQ_INT(count_frames(b, n, NULL), n);
    ENSURE_EQ_INT(same_frames(a, b, n), 0);
}

TEST_PROC(frames_stats_and_progress) {
    /* timings and progress need no pixels: the null backend, so this runs without GL too */
    char dir[160], a[2048], err_path[1024], stats[1024];
    tmp("frames_stats", dir, sizeof dir);
    const int n = 4;
    snprintf(err_path, sizeof err_path, "%s/err.txt", dir);
    snprintf(stats, sizeof stats, "%s/s.jsonl", dir);
    snprintf(a, sizeof a, "render " SCENE " --size %dx%d --frames %d --backend null -o %s/png --stats %s", W, H, n, dir, stats);
    ENSURE_EQ_INT(ww_test_ww(a, NULL, err_path), 0);
    char *s = ww_test_read_file(stats, NULL);
    ENSURE_EQ_INT(s ? ww_test_json_lines(s) : -1, n + 1);
    const char *keys[] = {"\"frame\": 3,", "\"t\": 0.1,", "\"sim_ms\":", "\"render_ms\":",
                          "\"readback_ms\":", "\"encode_ms\":", "\"queue_wait_ms\":", "\"bytes\":",
                          "\"summary\": true", "\"frames\": 4,"};
    for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++)
        ENSURE_MSG(s && strstr(s, keys[i]), "want %s in %s", keys[i], s ? s : "(none)");
    free(s);
    /* stderr is a file here: no progress line unless asked */
    ENSURE(!ww_test_file_contains(err_path, "ETA"));
    ENSURE(ww_test_file_contains(err_path, "rendered 4 frames"));
    snprintf(a, sizeof a, "render " SCENE " --size %dx%d --frames %d --backend null -o %s/png --progress", W, H, n, dir);
    ENSURE_EQ_INT(ww_test_ww(a, NULL, err_path), 0);
    ENSURE(ww_test_file_contains(err_path, "\rframe 4/4"));
    ENSURE(ww_test_file_contains(err_path, "fps  ETA"));
    snprintf(a, sizeof a, "render " SCENE " --size %dx%d --frames %d --backend null -o %s/png --progress --quiet", W, H, n, dir);
    ENSURE_EQ_INT(ww_test_ww(a, NULL, err_path), 0);
    char *e = ww_test_read_file(err_path, NULL);
    ENSURE_MSG(e && e[0] == 0, "--quiet wins: %s", e ? e : "?");
    free(e);
}

TEST_LONG(frames_bench_output_tiny) {
    REQUIRE_GL();
    char dir[160], out[1024];
    tmp("frames_bench", dir, sizeof dir);
    snprintf(out, sizeof out, "%s/out.jsonl", dir);
    ENSURE_EQ_INT(ww_test_ww("bench output --tiny --frames 3 --json", out, NULL), 0);
    char *s = ww_test_read_file(out, NULL);
    ENSURE_EQ_INT(s ? ww_test_json_lines(s) : -1, 5);
    const char *want[] = {"\"format\": \"none\"", "\"format\": \"png\"", "\"format\": \"exr\"",
                          "\"format\": \"y4m\"", "\"png_over_none\":", "\"rss_long_kib\":"};
    for (size_t i = 0; i < sizeof want / sizeof want[0]; i++)
        ENSURE_MSG(s && strstr(s, want[i]), "want %s in %s", want[i], s ? s : "(none)");
    free(s);
}
