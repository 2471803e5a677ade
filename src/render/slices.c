/* slices.c - slices of a render and their completion records (render/slices.h). */
#include "render/slices.h"

#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "core/hash.h"
#include "render/checkpoint.h"
#include "core/readfile.h"
#include "core/shword.h"
#include "io/wav.h"
#include "render/audio_synth.h"
#include "io/writers.h"
#include "sim/state.h"
#include "sim/step.h"

#define RECORD_MAX_BYTES (64 * 1024)

/* a whole number >= 0 spanning all of [s, end) */
static int parse_whole(const char *s, const char *end, int64_t *v) {
    if (s == end || (size_t)(end - s) > 18) return 0;
    int64_t x = 0;
    for (const char *p = s; p < end; p++) {
        if (*p < '0' || *p > '9') return 0;
        x = 10 * x + (*p - '0');
    }
    *v = x;
    return 1;
}

ww_result ww_slice_parse(const char *text, int64_t *index, int64_t *count, ww_error *err) {
    const char *slash = strchr(text, '/');
    int64_t i = -1, n = -1;
    if (!slash || !parse_whole(text, slash, &i) || !parse_whole(slash + 1, slash + strlen(slash), &n))
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            "--slice wants I/N in whole numbers (slice I of N, 0-based), got '%s'", text);
    if (n < 1 || i >= n)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            "--slice %s: expected N >= 1 and 0 <= I < N (slices 0..N-1)", text);
    *index = i;
    *count = n;
    return WW_OK;
}

ww_result ww_slices_parse(const char *text, int64_t *count, ww_error *err) {
    int64_t n = -1;
    if (!parse_whole(text, text + strlen(text), &n) || n < 1)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "--slices wants a whole number N >= 1, got '%s'", text);
    *count = n;
    return WW_OK;
}

void ww_slice_range(int64_t first, int64_t last, int64_t i, int64_t n, int64_t *a, int64_t *b) {
    int64_t len = last - first, q = len / n, r = len % n;
    *a = first + i * q + (i < r ? i : r);
    *b = first + (i + 1) * q + (i + 1 < r ? i + 1 : r);
}

int64_t ww_slice_sample(const ww_scene *sc, int64_t step) {
    /* the same expression as audio.c's grid(): samples_per_step = dt * rate, then the product */
    double per_step = sc->dt * WW_AUDIO_RATE;
    return llround((double)step * per_step);
}

/* ---- the run's identity -------------------------------------------------------------------- */

/* what the scene is made from, as a checkpoint names it (its file, the script's, the --set
 * texts: render/checkpoint.h), and the state hash at step 0 (what the loader made of them, the
 * files it read included) */
static uint64_t scene_hash(const ww_slice_opts *so, const ww_scene *sc) {
    uint64_t h = WW_HASH_INIT;
    ww_error e = {0};
    if (ww_checkpoint_scene_hash(so->scene_path, so->script, so->sets, so->nsets, &h, &e))
        h = WW_HASH_INIT; /* loaded a moment ago: the state hash below still tells runs apart */
    ww_state *st = ww_state_new(sc);
    if (st) {
        uint64_t s = ww_state_hash(sc, st);
        h = ww_hash_bytes(h, &s, sizeof s);
        ww_state_free(st);
    }
    return h;
}

static const char *format_name(const ww_job_opts *jo) {
    return jo->format == WW_OUT_NONE ? "none" : ww_out_format_ext(jo->format);
}

/* the identity line: the scene's hash and every option that changes the bytes of an output */
static void run_line(ww_slice_opts *so, const ww_scene *sc, const ww_job_opts *jo) {
    static const char *const comp[] = {"zip", "none", "piz"};
    snprintf(so->run, sizeof so->run,
             "scene=%016" PRIx64 " frames=%lld:%lld slices=%lld format=%s size=%dx%d alpha=%d "
             "exr=%s/%s audio=%s stats=%s",
             scene_hash(so, sc), (long long)so->run_first, (long long)so->run_last,
             (long long)so->count, format_name(jo), jo->width, jo->height, jo->alpha,
             jo->exr_float ? "float" : "half", comp[jo->exr_compression],
             so->audio_name ? so->audio_name : "-", so->stats_name ? so->stats_name : "-");
}

/* `EXE render <words>`: every slice's command before its --slice */
static void command_words(const ww_slice_opts *so, FILE *f) {
    ww_sh_word(f, so->exe ? so->exe : "waterworld", 1);
    ww_sh_word(f, "render", 0);
    for (int k = 0; k < so->nwords; k++) ww_sh_word(f, so->words[k], 0);
}

static ww_result check_count(const ww_slice_opts *so, const ww_job_opts *jo, ww_error *err) {
    if (so->count > jo->last - jo->first)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            "%s: %lld slices of %lld frames (%lld..%lld): expected at most one "
                            "slice per frame",
                            so->index < 0 ? "--slices" : "--slice", (long long)so->count,
                            (long long)(jo->last - jo->first), (long long)jo->first,
                            (long long)jo->last - 1);
    if (jo->format != WW_OUT_PNG && jo->format != WW_OUT_EXR && jo->format != WW_OUT_NONE)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            "slices write frame files into a folder: --format png, exr or none, not %s",
                            format_name(jo));
    return WW_OK;
}

ww_result ww_slices_emit(ww_slice_opts *so, const ww_scene *sc, const ww_job_opts *jo, FILE *to,
                         ww_error *err) {
    (void)sc;
    ww_result r = check_count(so, jo, err);
    if (r) return r;
    char word[64];
    for (int64_t i = 0; i < so->count; i++) {
        command_words(so, to);
        snprintf(word, sizeof word, "%lld/%lld", (long long)i, (long long)so->count);
        ww_sh_word(to, "--slice", 0);
        ww_sh_word(to, word, 0);
        /* with checkpoints, each slice starts from the latest one before its first frame */
        if (so->checkpoints) {
            ww_sh_word(to, "--from-checkpoint", 0);
            ww_sh_word(to, so->checkpoints, 0);
        }
        fputc('\n', to);
    }
    if (fflush(to) != 0 || ferror(to))
        return ww_error_set(err, WW_E_IO, "stdout", 0, 0, "cannot write: %s", strerror(errno));
    return WW_OK;
}

/* ---- records ------------------------------------------------------------------------------- */

static ww_result write_record(const ww_slice_opts *so, const ww_job_opts *jo, const ww_scene *sc,
                              const char *renderer, ww_error *err) {
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    if (!f) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory for a slice record");
    int64_t s0 = 0, s1 = 0;
    if (so->audio_name) {
        s0 = ww_slice_sample(sc, jo->first * sc->steps_per_frame);
        s1 = ww_slice_sample(sc, jo->last * sc->steps_per_frame);
    }
    fprintf(f, "%s\nstate %s\nslice %lld/%lld\nframes %lld:%lld\n", WW_SLICE_RECORD_MAGIC,
            renderer ? "done" : "started", (long long)so->index, (long long)so->count,
            (long long)jo->first, (long long)jo->last);
    fprintf(f, "samples %lld:%lld\nformat %s\naudio %s\nstats %s\nrun %s\nfps %.17g\n",
            (long long)s0, (long long)s1, format_name(jo), so->audio_name ? so->audio_name : "-",
            so->stats_name ? so->stats_name : "-", so->run, sc->fps);
    if (renderer) fprintf(f, "renderer %s\n", renderer);
    fputs("command ", f);
    command_words(so, f);
    fputc('\n', f);
    fclose(f);
    ww_result r = ww_write_file_atomic(so->record, buf, len, err);
    free(buf);
    return r;
}

/* "key value" on one line of the record; returns the value or NULL */
static const char *field(char *line, const char *key) {
    size_t n = strlen(key);
    return strncmp(line, key, n) == 0 && line[n] == ' ' ? line + n + 1 : NULL;
}

static int range_of(const char *v, int64_t *a, int64_t *b) {
    const char *colon = v ? strchr(v, ':') : NULL;
    return colon && parse_whole(v, colon, a) && parse_whole(colon + 1, colon + strlen(colon), b);
}

ww_result ww_slice_record_read(const char *path, ww_slice_record *rec, ww_error *err) {
    unsigned char *data = NULL;
    size_t len = 0;
    memset(rec, 0, sizeof *rec);
    ww_result r = ww_file_read_max(path, RECORD_MAX_BYTES, RECORD_MAX_BYTES, &data, &len, err);
    if (r) return r;
    char *text = (char *)data, *save = NULL;
    int ok = strncmp(text, WW_SLICE_RECORD_MAGIC "\n", strlen(WW_SLICE_RECORD_MAGIC) + 1) == 0;
    int seen = 0;
    for (char *line = strtok_r(text, "\n", &save); ok && line; line = strtok_r(NULL, "\n", &save)) {
        const char *v;
        if ((v = field(line, "state"))) rec->done = strcmp(v, "done") == 0, seen |= 1;
        else if ((v = field(line, "slice"))) {
            const char *slash = strchr(v, '/');
            ok = slash && parse_whole(v, slash, &rec->index) &&
                 parse_whole(slash + 1, slash + strlen(slash), &rec->count);
            seen |= 2;
        } else if ((v = field(line, "frames"))) ok = range_of(v, &rec->first, &rec->last), seen |= 4;
        else if ((v = field(line, "samples"))) ok = range_of(v, &rec->sample0, &rec->sample1);
        else if ((v = field(line, "format"))) snprintf(rec->format, sizeof rec->format, "%s", v);
        else if ((v = field(line, "audio"))) snprintf(rec->audio, sizeof rec->audio, "%s", v);
        else if ((v = field(line, "stats"))) snprintf(rec->stats, sizeof rec->stats, "%s", v);
        else if ((v = field(line, "renderer"))) snprintf(rec->renderer, sizeof rec->renderer, "%s", v);
        else if ((v = field(line, "run"))) snprintf(rec->run, sizeof rec->run, "%s", v), seen |= 8;
        else if ((v = field(line, "command")))
            snprintf(rec->command, sizeof rec->command, "%s", v), seen |= 16;
    }
    free(data);
    if (!ok || seen != 31 || rec->count < 1 || rec->index >= rec->count || rec->last <= rec->first)
        return ww_error_set(err, WW_E_SYNTAX, path, 0, 0, "not a whole slice record");
    return WW_OK;
}

/* ---- one slice ----------------------------------------------------------------------------- */

static int file_exists(const char *path) {
    struct stat st;
    return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

void ww_slice_part_path(const char *dir, int64_t index, const char *ext, char *out, size_t cap) {
    snprintf(out, cap, "%s/slices/slice_%05lld.%s", dir, (long long)index, ext);
}

int ww_slice_check(const char *dir, const ww_slice_record *rec, char *why, size_t cap) {
    char path[1200];
    struct stat st;
    if (strcmp(rec->audio, "-") != 0) {
        ww_slice_part_path(dir, rec->index, "wav", path, sizeof path);
        long long want = WW_WAV_HEADER_BYTES + 4 * (rec->sample1 - rec->sample0);
        if (stat(path, &st) != 0 || (long long)st.st_size != want) {
            snprintf(why, cap, "its sound track %s is %s", path,
                     stat(path, &st) != 0 ? "missing" : "not the length of its frames");
            return 0;
        }
    }
    if (strcmp(rec->stats, "-") != 0) {
        ww_slice_part_path(dir, rec->index, "stats.jsonl", path, sizeof path);
        if (!file_exists(path)) {
            snprintf(why, cap, "its stats %s are missing", path);
            return 0;
        }
    }
    if (strcmp(rec->format, "none") == 0) return 1;
    for (int64_t f = rec->first; f < rec->last; f++) {
        snprintf(path, sizeof path, "%s/frame_%05lld.%s", dir, (long long)f, rec->format);
        if (!file_exists(path)) {
            snprintf(why, cap, "frame %lld (%s) is missing", (long long)f, path);
            return 0;
        }
    }
    return 1;
}

/* a name for a joined file in DIR: a plain file name ending in ext (never a frame's) */
static ww_result check_name(const char *opt, const char *name, const char *ext, ww_error *err) {
    size_t n = name ? strlen(name) : 0, e = strlen(ext);
    if (!name || (n > e && !strchr(name, '/') && strcmp(name + n - e, ext) == 0)) return WW_OK;
    return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                        "%s with --slice names the joined file inside the output folder: a plain "
                        "file name ending in %s, got '%s'",
                        opt, ext, name);
}

ww_result ww_slice_begin(ww_slice_opts *so, const ww_scene *sc, ww_job_opts *jo, int *skip,
                         ww_error *err) {
    *skip = 0;
    ww_result r = check_count(so, jo, err);
    if (!r) r = check_name("--audio", so->audio_name, ".wav", err);
    if (!r) r = check_name("--stats", so->stats_name, ".jsonl", err);
    if (r) return r;
    so->run_first = jo->first;
    so->run_last = jo->last;
    ww_slice_range(so->run_first, so->run_last, so->index, so->count, &jo->first, &jo->last);
    run_line(so, sc, jo);

    char dir[1100];
    snprintf(dir, sizeof dir, "%s/slices", jo->out_dir);
    ww_slice_part_path(jo->out_dir, so->index, "record", so->record, sizeof so->record);
    ww_slice_part_path(jo->out_dir, so->index, "wav", so->audio_part, sizeof so->audio_part);
    ww_slice_part_path(jo->out_dir, so->index, "stats.jsonl", so->stats_part, sizeof so->stats_part);

    if (jo->resume) {
        ww_slice_record rec;
        ww_error e = {0};
        if (!ww_slice_record_read(so->record, &rec, &e)) {
            int same = strcmp(rec.run, so->run) == 0 && rec.index == so->index;
            char why[256];
            if (same && rec.done && ww_slice_check(jo->out_dir, &rec, why, sizeof why)) {
                *skip = 1;
                return WW_OK;
            }
            /* frames of another run are not this one's: render them all again */
            if (!same) {
                jo->resume = 0;
                if (!jo->quiet)
                    fprintf(stderr, "slice %lld/%lld: %s is another run's (%s): rendering the "
                                    "whole slice again\n",
                            (long long)so->index, (long long)so->count, so->record, rec.run);
            }
        }
    }
    if ((r = ww_make_dirs(dir, err))) return r;
    jo->audio_path = so->audio_name ? so->audio_part : NULL;
    jo->stats_path = so->stats_name ? so->stats_part : NULL;
    return write_record(so, jo, sc, NULL, err);
}

ww_result ww_slice_end(const ww_slice_opts *so, const ww_scene *sc, const ww_job_opts *jo,
                       const char *renderer, ww_error *err) {
    WW_ASSERT(renderer);
    return write_record(so, jo, sc, renderer, err);
}
