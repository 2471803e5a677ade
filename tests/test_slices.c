/* test_slices.c - a render cut into slices and joined back (render --slices N --emit-jobs,
 * render --slice I/N, join): frames, sound track and stats equal to one process; missing,
 * unfinished and other-run slices listed with their commands; --resume completing the set; bad
 * --slice and --jobs values exit 2 with nothing written; render --jobs N (the slices in child
 * processes, joined in place) equal to one process, a failed slice named and finished by
 * --resume; a sweep's points joined into the one-process sweep.jsonl, sweep.csv and contact
 * sheet.
 * Renders are tiny (64x36, null backend unless said, LP_NUM_THREADS=1) so that these run in the
 * proc tier.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io/wav.h"
#include "render/slices.h"
#include "test.h"

/* lake.yaml has a sound track (music bed, engine, splashes); 25 frames at 30 fps of a 120 Hz
 * simulation cut in 3 gives slices of 9, 8 and 8 frames whose sample bounds (367.5 samples a
 * step) round at half samples */
#define SCENE "scenes/lake.yaml --frames 0:25 --size 64x36"
#define NSLICES 3
#define NFRAMES 25
/* the joined track of 25 frames: llround(100 steps x 367.5) samples */
#define TRACK_SAMPLES 36750
/* at least this share of the track's samples are not 0 (the music bed plays throughout): the
 * byte comparison is of a real track, not of silence */
#define MIN_SOUNDING_SHARE 0.5

static char cmdline[8192];

static int exists(const char *path) {
    struct stat sb;
    return stat(path, &sb) == 0;
}

static const char *ww(const char *fmt, const char *a, const char *b) {
    snprintf(cmdline, sizeof cmdline, fmt, a, b);
    return cmdline;
}

/* frames 0..n-1 of two folders hold the same bytes */
static int same_frames(const char *a, const char *b, int n) {
    for (int f = 0; f < n; f++) {
        char pa[800], pb[800];
        snprintf(pa, sizeof pa, "%s/frame_%05d.png", a, f);
        snprintf(pb, sizeof pb, "%s/frame_%05d.png", b, f);
        if (!ww_test_files_equal(pa, pb)) return 0;
    }
    return 1;
}

/* the one-process run: frames in dir/full, dir/full.wav, dir/full.jsonl */
static void render_full(const char *dir, const char *backend) {
    char args[1024];
    snprintf(args, sizeof args,
             "render " SCENE " --backend %s --quiet --audio %s/full.wav --stats %s/full.jsonl -o %s/full",
             backend, dir, dir, dir);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, NULL), 0);
}

/* the slices' commands into dir/jobs.sh (rendering into dir/sl) */
static void emit(const char *dir, const char *backend) {
    char args[1024], jobs[700];
    snprintf(args, sizeof args, "render " SCENE " --backend %s --quiet --audio --stats -o %s/sl --slices %d --emit-jobs",
             backend, dir, NSLICES);
    snprintf(jobs, sizeof jobs, "%s/jobs.sh", dir);
    ENSURE_EQ_INT(ww_test_ww(args, jobs, NULL), 0);
}

/* line i (0-based) of the job file */
static void job_line(const char *dir, int i, char *out, size_t cap) {
    char path[700];
    snprintf(path, sizeof path, "%s/jobs.sh", dir);
    char *t = ww_test_read_file(path, NULL), *p = t;
    out[0] = 0;
    for (int k = 0; p && k < i; k++) p = strchr(p, '\n') ? strchr(p, '\n') + 1 : NULL;
    if (p) snprintf(out, cap, "%.*s", (int)strcspn(p, "\n"), p);
    free(t);
}

/* the joined track and frames equal one process's; the stats hold every frame's line in order
 * (all_stats), or, after --resume kept frames that were not measured again, rising frames */
static void check_joined(const char *dir, int all_stats) {
    char sl[700], a[700], b[700];
    snprintf(sl, sizeof sl, "%s/sl", dir);
    snprintf(a, sizeof a, "%s/sl/audio.wav", dir);
    snprintf(b, sizeof b, "%s/full.wav", dir);
    ENSURE_MSG(ww_test_files_equal(a, b), "joined %s differs from one process's %s", a, b);
    size_t len = 0;
    char *wav = ww_test_read_file(a, &len);
    ENSURE_EQ_INT((long long)len, WW_WAV_HEADER_BYTES + 4LL * TRACK_SAMPLES);
    long sounding = 0;
    for (size_t i = WW_WAV_HEADER_BYTES; wav && i + 1 < len; i += 2) sounding += wav[i] || wav[i + 1];
    ENSURE_MSG((double)sounding >= MIN_SOUNDING_SHARE * 2 * TRACK_SAMPLES,
               "only %ld of %d samples sound", sounding, 2 * TRACK_SAMPLES);
    free(wav);
    char full[700];
    snprintf(full, sizeof full, "%s/full", dir);
    ENSURE_MSG(same_frames(sl, full, NFRAMES), "frames of the slices differ from one process's");
    /* stats: timings differ between runs, so the frame lines' frames in order, then one summary
     * per slice */
    snprintf(a, sizeof a, "%s/sl/stats.jsonl", dir);
    char *st = ww_test_read_file(a, NULL);
    int lines = st ? ww_test_json_lines(st) : -1;
    ENSURE_MSG(all_stats ? lines == NFRAMES + NSLICES : lines > NSLICES && lines <= NFRAMES + NSLICES,
               "%d stats lines", lines);
    char *p = st;
    for (int f = 0, prev = -1; p && f < lines - NSLICES; f++) {
        int frame = -1;
        ENSURE_MSG(sscanf(p, "{\"frame\": %d,", &frame) == 1 && frame > prev && (!all_stats || frame == f),
                   "stats line %d: %.40s", f, p);
        prev = frame;
        p = strchr(p, '\n') ? strchr(p, '\n') + 1 : NULL;
    }
    for (int i = 0; p && i < NSLICES; i++) {
        char want[64];
        snprintf(want, sizeof want, "{\"slice\": %d, \"summary\": true", i);
        ENSURE_MSG(strncmp(p, want, strlen(want)) == 0, "summary %d: %.60s", i, p);
        p = strchr(p, '\n') ? strchr(p, '\n') + 1 : NULL;
    }
    free(st);
}

TEST(slice_ranges_contiguous_near_equal) {
    const int64_t lens[] = {1, 2, 3, 25, 100, 9999, 10000000000LL};
    const int64_t ns[] = {1, 2, 3, 7, 64, 1000};
    for (size_t l = 0; l < sizeof lens / sizeof lens[0]; l++) {
        for (size_t k = 0; k < sizeof ns / sizeof ns[0]; k++) {
            int64_t n = ns[k], first = 5, last = 5 + lens[l], prev = first, lo = last, hi = 0;
            if (n > lens[l]) continue;
            for (int64_t i = 0; i < n; i++) {
                int64_t a, b;
                ww_slice_range(first, last, i, n, &a, &b);
                ENSURE_EQ_INT(a, prev);
                ENSURE(b > a);
                lo = b - a < lo ? b - a : lo;
                hi = b - a > hi ? b - a : hi;
                prev = b;
            }
            ENSURE_EQ_INT(prev, last);
            ENSURE(hi - lo <= 1);
        }
    }
}

TEST_PROC(slices_joined_equal_one_process) {
    char dir[512];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("slices_eq"));
    setenv("LP_NUM_THREADS", "1", 1);
    render_full(dir, "null");
    emit(dir, "null");
    char line[4096];
    job_line(dir, 1, line, sizeof line);
    ENSURE_MSG(strstr(line, " --audio --stats -o ") && strstr(line, " --slice 1/3") && !strstr(line, "--emit-jobs"),
               "line 1: %s", line);
    ENSURE_EQ_INT(ww_test_run(ww("sh %s/jobs.sh", dir, NULL), NULL, NULL), 0);
    ENSURE_EQ_INT(ww_test_ww(ww("join %s/sl", dir, NULL), NULL, NULL), 0);
    check_joined(dir, 1);
}

/* slices that start from checkpoints (--emit-jobs --checkpoints DIR) simulate no prefix and
 * still join to one process's frames and sound track */
TEST_PROC(slices_from_checkpoints_joined_equal_one_process) {
    char dir[512], args[1800], jobs[700];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("slices_ck"));
    setenv("LP_NUM_THREADS", "1", 1);
    render_full(dir, "null");
    /* every 20 steps: a checkpoint inside each slice's prefix (a frame is 4 steps) */
    snprintf(args, sizeof args, "simulate scenes/lake.yaml --frames 0:25 --checkpoint-every 20 --quiet -o %s/ck", dir);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, NULL), 0);
    snprintf(args, sizeof args,
             "render " SCENE " --backend null --quiet --audio --stats -o %s/sl --slices %d "
             "--emit-jobs --checkpoints %s/ck", dir, NSLICES, dir);
    snprintf(jobs, sizeof jobs, "%s/jobs.sh", dir);
    ENSURE_EQ_INT(ww_test_ww(args, jobs, NULL), 0);
    char line[4096];
    job_line(dir, 2, line, sizeof line);
    ENSURE_MSG(strstr(line, " --from-checkpoint ") && strstr(line, " --slice 2/3"), "line 2: %s", line);
    ENSURE_EQ_INT(ww_test_run(ww("sh %s/jobs.sh", dir, NULL), NULL, NULL), 0);
    ENSURE_EQ_INT(ww_test_ww(ww("join %s/sl", dir, NULL), NULL, NULL), 0);
    check_joined(dir, 1);
}

/* the same with a GL backend: the frames are pictures, and they too are byte-identical */
TEST_IMAGE(slices_joined_equal_one_process_gl) {
    REQUIRE_GL();
    char dir[512];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("slices_gl"));
    setenv("LP_NUM_THREADS", "1", 1);
    render_full(dir, "auto");
    emit(dir, "auto");
    ENSURE_EQ_INT(ww_test_run(ww("sh %s/jobs.sh", dir, NULL), NULL, NULL), 0);
    ENSURE_EQ_INT(ww_test_ww(ww("join %s/sl", dir, NULL), NULL, NULL), 0);
    check_joined(dir, 1);
}

TEST_PROC(slices_missing_listed_resume_completes) {
    char dir[512], line[4096], errf[700], outf[700];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("slices_missing"));
    snprintf(errf, sizeof errf, "%s/err.txt", dir);
    snprintf(outf, sizeof outf, "%s/rerun.sh", dir);
    setenv("LP_NUM_THREADS", "1", 1);
    render_full(dir, "null");
    emit(dir, "null");
    for (int i = 0; i < NSLICES; i += 2) {
        job_line(dir, i, line, sizeof line);
        ENSURE_EQ_INT(ww_test_run(line, NULL, NULL), 0);
    }
    /* slice 1 missing: named on stderr, its command (with --resume) on stdout, exit 1 */
    ENSURE_EQ_INT(ww_test_ww(ww("join %s/sl", dir, NULL), outf, errf), 1);
    ENSURE(ww_test_file_contains(errf, "slice 1/3: missing"));
    ENSURE(!ww_test_file_contains(errf, "slice 0/3") && !ww_test_file_contains(errf, "slice 2/3"));
    ENSURE(ww_test_file_contains(outf, " --slice 1/3 --resume\n"));
    ENSURE_EQ_INT(ww_test_run(ww("sh %s", outf, NULL), NULL, NULL), 0);

    /* slice 2 stopped part way: its record still says started and a frame is gone */
    char rec[700];
    snprintf(rec, sizeof rec, "%s/sl/slices/slice_00002.record", dir);
    char *t = ww_test_read_file(rec, NULL), *st = t ? strstr(t, "state done") : NULL;
    ENSURE(st != NULL);
    if (st) memcpy(st, "state strt", 10);
    ENSURE(t && ww_test_write_text(rec, t) == 0);
    free(t);
    ENSURE_EQ_INT(ww_test_run(ww("rm %s/sl/frame_00020.png", dir, NULL), NULL, NULL), 0);
    ENSURE_EQ_INT(ww_test_ww(ww("join %s/sl", dir, NULL), outf, errf), 1);
    ENSURE(ww_test_file_contains(errf, "slice 2/3: not finished"));
    ENSURE(ww_test_file_contains(outf, " --slice 2/3 --resume\n"));
    ENSURE_EQ_INT(ww_test_run(ww("sh %s", outf, NULL), NULL, NULL), 0);
    /* a complete slice run again with --resume is left as it is */
    job_line(dir, 0, line, sizeof line);
    char *q = strstr(line, " --quiet");
    if (q) memmove(q, q + 8, strlen(q + 8) + 1);
    strcat(line, " --resume");
    ENSURE_EQ_INT(ww_test_run(line, NULL, errf), 0);
    ENSURE(ww_test_file_contains(errf, "already complete"));
    ENSURE_EQ_INT(ww_test_ww(ww("join %s/sl", dir, NULL), NULL, NULL), 0);
    check_joined(dir, 0);
}

TEST_PROC(slices_of_another_run_refused) {
    char dir[512], line[4096], errf[700], outf[700];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("slices_other"));
    snprintf(errf, sizeof errf, "%s/err.txt", dir);
    snprintf(outf, sizeof outf, "%s/rerun.sh", dir);
    setenv("LP_NUM_THREADS", "1", 1);
    render_full(dir, "null");
    emit(dir, "null");
    ENSURE_EQ_INT(ww_test_run(ww("sh %s/jobs.sh", dir, NULL), NULL, NULL), 0);
    /* slice 1 again with another sea */
    job_line(dir, 1, line, sizeof line);
    strcat(line, " --set water.waves.list[0].amplitude=0.3");
    ENSURE_EQ_INT(ww_test_run(line, NULL, NULL), 0);
    ENSURE_EQ_INT(ww_test_ww(ww("join %s/sl", dir, NULL), outf, errf), 1);
    ENSURE(ww_test_file_contains(errf, "slice 1/3: of another run: scene "));
    /* its frames are the other run's: the command renders them again, not --resume */
    ENSURE(ww_test_file_contains(outf, " --slice 1/3\n"));
    ENSURE_EQ_INT(ww_test_run(ww("sh %s", outf, NULL), NULL, NULL), 0);
    ENSURE_EQ_INT(ww_test_ww(ww("join %s/sl", dir, NULL), NULL, NULL), 0);
    check_joined(dir, 1);
}

TEST_PROC(slices_bad_values_exit_2) {
    char dir[512], errf[700], args[1024];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("slices_bad"));
    snprintf(errf, sizeof errf, "%s/err.txt", dir);
    const struct { const char *opts, *says; } bad[] = {
        {"--slice 3/3", "0 <= I < N"},
        {"--slice 0/0", "N >= 1"},
        {"--slice a/3", "--slice wants I/N"},
        {"--slice -1/3", "--slice wants I/N"},
        {"--slice 1/", "--slice wants I/N"},
        {"--slice 1.5/3", "--slice wants I/N"},
        {"--frames 0:4 --slice 0/5", "at most one slice per frame"},
        {"--frames 0:4 --slices 5 --emit-jobs", "at most one slice per frame"},
        {"--slices 0 --emit-jobs", "--slices wants"},
        {"--slices 3", "goes with --emit-jobs"},
        {"--emit-jobs", "goes with --slices"},
        {"--slices 3 --emit-jobs --slice 0/3", "one or the other"},
        {"--slice 0/3 --format y4m", "--format png, exr or none"},
        {"--slice 0/3 --audio=sub/x.wav", "plain file name"},
        {"--slice 0/3 --stats=frame_00000.png", "ending in .jsonl"},
        {"--jobs 0", "--jobs wants 1..64"},
        {"--jobs 65", "--jobs wants 1..64"},
        {"--jobs two", "--jobs wants 1..64"},
        {"--jobs", "--jobs"},
        {"--jobs 2 --format y4m", "written by one process"},
        {"--jobs 2 --slice 0/2", "one or the other"},
        {"--jobs 2 --slices 2 --emit-jobs", "one or the other"},
        {"--jobs 2 --set water.nope=1", "nope"},
    };
    char out[700];
    snprintf(out, sizeof out, "%s/o", dir);
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        snprintf(args, sizeof args, "render scenes/lake.yaml --size 64x36 --backend null -o %s %s",
                 out, bad[i].opts);
        ENSURE_MSG(ww_test_ww(args, NULL, errf) == 2, "%s: not exit 2", bad[i].opts);
        ENSURE_MSG(ww_test_file_contains(errf, bad[i].says), "%s: message lacks '%s'", bad[i].opts,
                   bad[i].says);
        ENSURE_MSG(!exists(out), "%s: %s was made", bad[i].opts, out);
    }
    ENSURE_EQ_INT(ww_test_ww(ww("join %s/nothing", dir, NULL), NULL, errf), 2);
    ENSURE(ww_test_file_contains(errf, "holds neither slices/"));
}

/* `render --jobs N`, its sound track and stats named anywhere (here where check_joined reads
 * them): the frames and track of one process, the stats' summaries one a slice, and nothing of
 * the slices left in the folder */
static void render_jobs(const char *dir, const char *backend, const char *more, const char *errf,
                        int want_exit) {
    char args[1400];
    snprintf(args, sizeof args,
             "render " SCENE " --backend %s --audio %s/sl/audio.wav --stats %s/sl/stats.jsonl "
             "-o %s/sl --jobs %d %s",
             backend, dir, dir, dir, NSLICES, more);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, errf), want_exit);
}

static void check_jobs_left_nothing(const char *dir) {
    char path[700];
    const char *gone[] = {"slices", ".jobs-audio.wav", ".jobs-stats.jsonl"};
    for (size_t i = 0; i < sizeof gone / sizeof gone[0]; i++) {
        snprintf(path, sizeof path, "%s/sl/%s", dir, gone[i]);
        ENSURE_MSG(!exists(path), "%s is left", path);
    }
}

TEST_PROC(render_jobs_equal_one_process) {
    char dir[512], errf[700];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("jobs_eq"));
    snprintf(errf, sizeof errf, "%s/err.txt", dir);
    unsetenv("LP_NUM_THREADS");
    render_full(dir, "null");
    render_jobs(dir, "null", "", errf, 0);
    ENSURE(ww_test_file_contains(errf, "rendered 25 frames (0..24) at 64x36 in 3 processes"));
    /* the cores shared out between the three, at least one thread each */
    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    char threads[64];
    snprintf(threads, sizeof threads, "(LP_NUM_THREADS=%ld each)", cores > NSLICES ? cores / NSLICES : 1);
    ENSURE_MSG(ww_test_file_contains(errf, threads), "no %s in the summary", threads);
    check_joined(dir, 1);
    check_jobs_left_nothing(dir);
    /* more processes than frames: one a frame */
    char args[1024];
    snprintf(args, sizeof args, "render scenes/lake.yaml --frames 0:2 --size 64x36 --backend null "
             "-o %s/two --jobs 8", dir);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, errf), 0);
    ENSURE(ww_test_file_contains(errf, "in 2 processes"));
}

/* with a GL backend the frames are pictures, and byte-identical too */
TEST_IMAGE(render_jobs_equal_one_process_gl) {
    REQUIRE_GL();
    char dir[512];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("jobs_gl"));
    setenv("LP_NUM_THREADS", "1", 1);
    render_full(dir, "auto");
    render_jobs(dir, "auto", "--quiet", NULL, 0);
    check_joined(dir, 1);
    check_jobs_left_nothing(dir);
    /* --golden checks the joined frames as one process does: one process's frames as goldens */
    char args[1400], errf[700];
    snprintf(errf, sizeof errf, "%s/golden.txt", dir);
    snprintf(args, sizeof args, "render " SCENE " --backend auto -o %s/g --jobs 2 --golden %s/full",
             dir, dir);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, errf), 0);
    ENSURE(ww_test_file_contains(errf, "golden: 25 frames, 25 passed, 0 failed, 0 missing"));
}

/* a slice that fails is named with its frames and exit code, the others' frames are kept, and
 * the same command with --resume finishes the run */
TEST_PROC(render_jobs_failed_slice_named_resume_finishes) {
    char dir[512], errf[700], path[700];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("jobs_fail"));
    snprintf(errf, sizeof errf, "%s/err.txt", dir);
    setenv("LP_NUM_THREADS", "1", 1);
    render_full(dir, "null");
    /* frame 20 (slice 2's) cannot be written: a folder stands in its place */
    snprintf(path, sizeof path, "%s/sl/frame_00020.png", dir);
    ENSURE_EQ_INT(ww_test_run(ww("mkdir -p %s", path, NULL), NULL, NULL), 0);
    render_jobs(dir, "null", "--quiet", errf, 3);
    ENSURE(ww_test_file_contains(errf, "slice 2/3 (frames 17..24) exited 3"));
    ENSURE(ww_test_file_contains(errf, "--resume"));
    snprintf(path, sizeof path, "%s/sl/frame_00000.png", dir);
    ENSURE_MSG(exists(path), "slice 0's frames are gone");
    ENSURE_EQ_INT(ww_test_run(ww("rmdir %s/sl/frame_00020.png", dir, NULL), NULL, NULL), 0);
    render_jobs(dir, "null", "--quiet --resume", errf, 0);
    check_joined(dir, 0); /* the frames kept were not measured again */
    check_jobs_left_nothing(dir);
}

TEST_PROC(sweep_points_joined_equal_one_process) {
    char dir[512], errf[700], outf[700], a[700], b[700];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("sweep_join"));
    snprintf(errf, sizeof errf, "%s/err.txt", dir);
    snprintf(outf, sizeof outf, "%s/rerun.sh", dir);
    /* thumbnails on the null backend: black, but the contact sheet's labels are drawn */
    const char *sweep = "sweep scenes/demo.yaml --vary water.waves.list[0].amplitude=0.1:0.5:3 "
                        "--vary water.waves.model=gerstner,sines --quiet --thumbs --thumb-size 48x27 "
                        "--backend null";
    char args[1024];
    snprintf(args, sizeof args, "%s -o %s/one", sweep, dir);
    ENSURE_EQ_INT(ww_test_ww(args, NULL, NULL), 0);
    for (int i = 0; i < 6; i++) {
        if (i == 4) continue;
        snprintf(args, sizeof args, "%s -o %s/pts --point %d", sweep, dir, i);
        ENSURE_EQ_INT(ww_test_ww(args, NULL, NULL), 0);
    }
    ENSURE_EQ_INT(ww_test_ww(ww("join %s/pts", dir, NULL), outf, errf), 1);
    ENSURE(ww_test_file_contains(errf, "point 4: missing"));
    ENSURE(!ww_test_file_contains(errf, "point 3"));
    ENSURE(ww_test_file_contains(outf, " --point 4\n"));
    ENSURE_EQ_INT(ww_test_run(ww("sh %s", outf, NULL), NULL, NULL), 0);
    ENSURE_EQ_INT(ww_test_ww(ww("join %s/pts", dir, NULL), NULL, NULL), 0);
    const char *names[] = {"sweep.jsonl", "sweep.csv", "contact_sheet.png"};
    for (int k = 0; k < 3; k++) {
        snprintf(a, sizeof a, "%s/one/%s", dir, names[k]);
        snprintf(b, sizeof b, "%s/pts/%s", dir, names[k]);
        ENSURE_MSG(ww_test_files_equal(a, b), "joined %s differs from one process's", names[k]);
    }
}

TEST_PROC(slices_make_video_from_dir) {
    REQUIRE_TOOL("ffmpeg");
    REQUIRE_TOOL("ffprobe");
    char dir[512], line[4096], a[2048], outf[700];
    snprintf(dir, sizeof dir, "%s", ww_test_tmpdir("slices_video"));
    snprintf(outf, sizeof outf, "%s/probe.txt", dir);
    setenv("LP_NUM_THREADS", "1", 1);
    emit(dir, "null");
    for (int i = 0; i < NSLICES - 1; i++) {
        job_line(dir, i, line, sizeof line);
        ENSURE_EQ_INT(ww_test_run(line, NULL, NULL), 0);
    }
    /* a slice missing: join's exit 1, no video */
    snprintf(a, sizeof a, "WW_BIN=%s MAKE_VIDEO_PRESET=ultrafast scripts/make-video.sh --from-dir %s/sl %s/v.mp4",
             ww_test_bin(), dir, dir);
    ENSURE_EQ_INT(ww_test_run(a, NULL, NULL), 1);
    char mp4[700];
    snprintf(mp4, sizeof mp4, "%s/v.mp4", dir);
    FILE *f = fopen(mp4, "rb");
    ENSURE_MSG(!f, "%s made from an incomplete set", mp4);
    if (f) fclose(f);
    job_line(dir, NSLICES - 1, line, sizeof line);
    ENSURE_EQ_INT(ww_test_run(line, NULL, NULL), 0);
    ENSURE_EQ_INT(ww_test_run(a, NULL, NULL), 0);
    snprintf(a, sizeof a, "ffprobe -v error -count_frames -show_streams -of flat %s/v.mp4", dir);
    ENSURE_EQ_INT(ww_test_run(a, outf, NULL), 0);
    const char *want[] = {"codec_name=\"h264\"", "nb_read_frames=\"25\"", "codec_type=\"audio\"",
                          "color_space=\"bt709\"", "width=64"};
    for (size_t i = 0; i < sizeof want / sizeof want[0]; i++)
        ENSURE_MSG(ww_test_file_contains(outf, want[i]), "video lacks %s", want[i]);
}
