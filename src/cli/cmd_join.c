/* cmd_join.c - `waterworld join DIR`: the slices of a render (DIR/slices/, render/slices.h) or the
 * points of a sweep (DIR/points/, sweep/sweep.h) put back together, once every one is complete.
 *
 * A render's slices: every slice 0..N-1 of one run must have its record in state done, its frames
 * and its parts; slices of another run (another scene hash or shaping option) are refused. Then
 * the sound track parts are concatenated after one header (the samples butt exactly: the joined
 * file is the bytes of one process's --audio) and the stats parts in frame order, each written
 * atomically into DIR. A sweep's points: every point_I.jsonl of 0..N-1 (N from points/sweep.job)
 * concatenated into sweep.jsonl and their CSV rows under the header into sweep.csv, the bytes of
 * a one-process sweep. What is missing is listed on stderr, one line each, and the commands that
 * complete the set go to stdout (`waterworld join DIR | sh` runs them); exit 1.
 */
#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli/cli.h"
#include "core/readfile.h"
#include "core/shword.h"
#include "io/image.h"
#include "io/stream.h"
#include "io/writers.h"
#include "render/contact.h"
#include "io/wav.h"
#include "render/audio_synth.h"
#include "render/slices.h"
#include "sweep/sweep.h"

#define JOB_MAX_BYTES (1 << 20)          /* points/sweep.job */
#define PART_MAX_BYTES ((size_t)1 << 31) /* one stats part or one point's row */
#define COPY_BLOCK 65536

static const char usage[] =
    "usage: waterworld join DIR [--quiet]\n"
    "\n"
    "Puts the slices of `render --slice I/N -o DIR` or the points of `sweep --point I -o DIR`\n"
    "back together once every one is complete:\n"
    "  slices: DIR/slices/slice_*.record, *.wav, *.stats.jsonl -> DIR/audio.wav (the sound track,\n"
    "          the bytes of one process's --audio) and DIR/stats.jsonl (the frames' lines in\n"
    "          order, then each slice's summary line); names as given to --audio / --stats\n"
    "  points: DIR/points/point_*.jsonl and *.csv -> DIR/sweep.jsonl and DIR/sweep.csv (the bytes\n"
    "          of a one-process sweep); with --thumbs, DIR/contact_sheet.png from DIR/thumbs/\n"
    "A slice or point that is missing, unfinished or of another run (another --set, size,\n"
    "format, ...) is listed on stderr, one a line, and the commands that complete the set are\n"
    "printed on stdout (waterworld join DIR | sh runs them); nothing is written.\n"
    "\n"
    "Exit: 0 joined, 1 something is missing (listed), 2 bad input (DIR holds neither).\n";

/* ---- a render's slices --------------------------------------------------------------------- */

typedef struct slices {
    const char *dir;
    ww_slice_record *rec;      /* by file, in the order read */
    int nrec, cap;
    const ww_slice_record *ref; /* the run the set belongs to */
    const ww_slice_record **mine, **other; /* by slice: its record of that run, of another */
} slices;

/* every DIR/slices/slice_IIIII.record that reads as one */
static ww_result read_records(slices *s, ww_error *err) {
    char path[1200];
    snprintf(path, sizeof path, "%s/slices", s->dir);
    DIR *d = opendir(path);
    if (!d) return ww_error_set(err, WW_E_NOFILE, NULL, 0, 0, "cannot open %s: %s", path, strerror(errno));
    struct dirent *e;
    ww_result r = WW_OK;
    while (!r && (e = readdir(d)) != NULL) {
        size_t n = strlen(e->d_name);
        if (strncmp(e->d_name, "slice_", 6) != 0 || n < 13 || strcmp(e->d_name + n - 7, ".record") != 0)
            continue;
        if (s->nrec == s->cap) {
            int cap = s->cap ? 2 * s->cap : 16;
            ww_slice_record *g = realloc(s->rec, (size_t)cap * sizeof *g);
            if (!g) {
                r = ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory for the slice records");
                break;
            }
            s->rec = g;
            s->cap = cap;
        }
        snprintf(path, sizeof path, "%s/slices/%s", s->dir, e->d_name);
        ww_error ignored = {0};
        if (ww_slice_record_read(path, &s->rec[s->nrec], &ignored) == WW_OK) s->nrec++;
    }
    closedir(d);
    return r;
}

/* records by run line, then slice */
static int by_run(const void *pa, const void *pb) {
    const ww_slice_record *a = pa, *b = pb;
    int c = strcmp(a->run, b->run);
    return c ? c : (a->index > b->index) - (a->index < b->index);
}

/* the run of the set: the one most records belong to (ties: the one holding the lowest slice);
 * then each slice's record of that run, or of another */
static ww_result pick_run(slices *s, ww_error *err) {
    qsort(s->rec, (size_t)s->nrec, sizeof *s->rec, by_run);
    int best = -1, best_n = 0;
    for (int i = 0, n; i < s->nrec; i += n) {
        for (n = 1; i + n < s->nrec && strcmp(s->rec[i + n].run, s->rec[i].run) == 0;) n++;
        if (n > best_n || (n == best_n && s->rec[i].index < s->rec[best].index)) {
            best = i;
            best_n = n;
        }
    }
    if (best < 0) return WW_OK;
    s->ref = &s->rec[best];
    s->mine = calloc((size_t)s->ref->count, sizeof *s->mine);
    s->other = calloc((size_t)s->ref->count, sizeof *s->other);
    if (!s->mine || !s->other)
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory for %lld slices",
                            (long long)s->ref->count);
    for (int k = 0; k < s->nrec; k++) {
        const ww_slice_record *r = &s->rec[k];
        if (r->index >= s->ref->count) continue;
        if (strcmp(r->run, s->ref->run) == 0) s->mine[r->index] = r;
        else s->other[r->index] = r;
    }
    return WW_OK;
}

/* this run's record of slice i; *other: a record of slice i from another run */
static const ww_slice_record *find(const slices *s, int64_t i, const ww_slice_record **other) {
    *other = s->other[i];
    return s->mine[i];
}

/* the fields of run line a that differ from b's: "scene 4b20... (this set: 181c...), size ..." */
static void run_diff(const char *a, const char *b, char *out, size_t cap) {
    size_t n = 0;
    out[0] = 0;
    while (*a && n + 1 < cap) {
        size_t la = strcspn(a, " "), key = strcspn(a, "=");
        const char *m = b;
        while (*m && !(strncmp(m, a, key + 1) == 0)) m += strcspn(m, " ") + (m[strcspn(m, " ")] == ' ');
        size_t lm = strcspn(m, " ");
        if (key < la && (lm != la || strncmp(m, a, la) != 0)) {
            int k = snprintf(out + n, cap - n, "%s%.*s %.*s (this set: %.*s)", n ? ", " : "",
                             (int)key, a, (int)(la - key - 1), a + key + 1,
                             *m ? (int)(lm - key - 1) : 4, *m ? m + key + 1 : "none");
            n += k > 0 ? (size_t)k : 0;
        }
        a += la + (a[la] == ' ');
    }
}

/* every slice of the run complete? else each listed on stderr and its command on stdout */
static long long check_slices(const slices *s, int quiet) {
    const ww_slice_record *ref = s->ref;
    long long bad = 0;
    for (int64_t i = 0; i < ref->count; i++) {
        const ww_slice_record *other, *rec = find(s, i, &other);
        char why[1200];
        int resume = 1;
        if (rec && rec->done && ww_slice_check(s->dir, rec, why, sizeof why)) continue;
        if (!rec && other) {
            char diff[1000];
            run_diff(other->run, ref->run, diff, sizeof diff);
            snprintf(why, sizeof why, "of another run: %s", diff);
            resume = 0; /* its frames are the other run's: all rendered again */
        } else if (!rec) {
            snprintf(why, sizeof why, "missing (no record in %s/slices)", s->dir);
        } else if (!rec->done) {
            snprintf(why, sizeof why, "not finished (started; failed, stopped or still running)");
        }
        if (!quiet) fprintf(stderr, "slice %lld/%lld: %s\n", (long long)i, (long long)ref->count, why);
        printf("%s --slice %lld/%lld%s\n", ref->command, (long long)i, (long long)ref->count,
               resume ? " --resume" : "");
        bad++;
    }
    return bad;
}

/* slices drawn by different renderers (machines with another Mesa, --backend null) may differ
 * in their pixels: said, not refused (a cluster's nodes are the user's to choose) */
static void warn_renderers(const slices *s) {
    const ww_slice_record *a = s->mine[0];
    for (int64_t i = 1; i < s->ref->count; i++) {
        if (strcmp(s->mine[i]->renderer, a->renderer) == 0) continue;
        fprintf(stderr, "join: warning: slice %lld was drawn by '%s', slice 0 by '%s': their "
                        "frames may differ where they meet\n",
                (long long)i, s->mine[i]->renderer, a->renderer);
    }
}

/* copy n bytes of f to out */
static int copy_bytes(FILE *f, FILE *out, long long n) {
    static unsigned char block[COPY_BLOCK];
    while (n > 0) {
        size_t k = n < COPY_BLOCK ? (size_t)n : COPY_BLOCK;
        if (fread(block, 1, k, f) != k || fwrite(block, 1, k, out) != k) return -1;
        n -= (long long)k;
    }
    return 0;
}

/* DIR/NAME: one header, then the samples of each part after its own header */
static ww_result join_audio(const slices *s, long long *samples, ww_error *err) {
    const ww_slice_record *ref = s->ref;
    const ww_slice_record *first, *last, *other;
    first = find(s, 0, &other);
    last = find(s, ref->count - 1, &other);
    *samples = last->sample1 - first->sample0;
    unsigned char h[WW_WAV_HEADER_BYTES];
    char path[1200];
    snprintf(path, sizeof path, "%s/%s", s->dir, ref->audio);
    if (ww_wav_header16(h, *samples, 2, (int)WW_AUDIO_RATE) != 0)
        return ww_error_set(err, WW_E_RANGE, path, 0, 0, "the joined track is too long for a WAV file");
    ww_stream out;
    ww_result r = ww_stream_open(&out, path, err);
    if (r) return r;
    int bad = fwrite(h, 1, sizeof h, out.f) != sizeof h;
    int64_t expect = first->sample0;
    for (int64_t i = 0; i < ref->count && !bad && !r; i++) {
        const ww_slice_record *rec = find(s, i, &other);
        char part[1200];
        ww_slice_part_path(s->dir, i, "wav", part, sizeof part);
        if (rec->sample0 != expect) {
            r = ww_error_set(err, WW_E_INCONSISTENT, part, 0, 0,
                             "starts at sample %lld, expected %lld (slices do not butt)",
                             (long long)rec->sample0, (long long)expect);
            break;
        }
        FILE *f = fopen(part, "rb");
        bad = !f || fseek(f, WW_WAV_HEADER_BYTES, SEEK_SET) != 0 ||
              copy_bytes(f, out.f, 4 * (rec->sample1 - rec->sample0)) != 0;
        if (f) fclose(f);
        if (bad) r = ww_error_set(err, WW_E_IO, part, 0, 0, "cannot copy its samples: %s", strerror(errno));
        expect = rec->sample1;
    }
    if (!r && bad) r = ww_error_set(err, WW_E_IO, path, 0, 0, "cannot write: %s", strerror(errno));
    if (r) {
        ww_stream_abort(&out);
        return r;
    }
    return ww_stream_commit(&out, err);
}

/* DIR/NAME: the frame lines of the parts in order, then each part's summary tagged with its
 * slice */
static ww_result join_stats(const slices *s, long long *lines, ww_error *err) {
    const ww_slice_record *ref = s->ref;
    char path[1200];
    snprintf(path, sizeof path, "%s/%s", s->dir, ref->stats);
    ww_stream out;
    ww_result r = ww_stream_open(&out, path, err);
    if (r) return r;
    *lines = 0;
    for (int pass = 0; pass < 2 && !r; pass++) {
        for (int64_t i = 0; i < ref->count && !r; i++) {
            char part[1200];
            ww_slice_part_path(s->dir, i, "stats.jsonl", part, sizeof part);
            unsigned char *data = NULL;
            size_t len = 0;
            if ((r = ww_file_read_max(part, PART_MAX_BYTES, PART_MAX_BYTES, &data, &len, err))) break;
            char *save = NULL;
            for (char *l = strtok_r((char *)data, "\n", &save); l; l = strtok_r(NULL, "\n", &save)) {
                int summary = strncmp(l, "{\"summary\"", 10) == 0;
                if (pass == 0 && !summary) {
                    fprintf(out.f, "%s\n", l);
                    ++*lines;
                } else if (pass == 1 && summary) {
                    fprintf(out.f, "{\"slice\": %lld, %s\n", (long long)i, l + 1);
                }
            }
            free(data);
        }
    }
    if (!r && ferror(out.f)) r = ww_error_set(err, WW_E_IO, path, 0, 0, "cannot write: %s", strerror(errno));
    if (r) {
        ww_stream_abort(&out);
        return r;
    }
    return ww_stream_commit(&out, err);
}

static ww_result join_slices(const char *dir, int quiet, ww_error *err) {
    slices s = {.dir = dir};
    ww_result r = read_records(&s, err);
    if (!r) r = pick_run(&s, err);
    if (!r && !s.ref)
        r = ww_error_set(err, WW_E_MISMATCH, NULL, 0, 0,
                         "join %s: no slice record in %s/slices: render the slices first "
                         "(render SCENE --slices N --emit-jobs prints their commands)",
                         dir, dir);
    long long bad = r ? 0 : check_slices(&s, quiet);
    if (!r && !bad && !quiet) warn_renderers(&s);
    if (!r && bad)
        r = ww_error_set(err, WW_E_MISMATCH, NULL, 0, 0,
                         "join %s: %lld of %lld slices are not complete; the commands that "
                         "complete them are on stdout",
                         dir, bad, (long long)s.ref->count);
    long long samples = 0, lines = 0;
    if (!r && strcmp(s.ref->audio, "-") != 0) r = join_audio(&s, &samples, err);
    if (!r && strcmp(s.ref->stats, "-") != 0) r = join_stats(&s, &lines, err);
    if (!r && !quiet) {
        const ww_slice_record *other, *a = find(&s, 0, &other), *b = find(&s, s.ref->count - 1, &other);
        fprintf(stderr, "joined %lld slices of %s: frames %lld..%lld", (long long)s.ref->count, dir,
                (long long)a->first, (long long)b->last - 1);
        if (strcmp(s.ref->audio, "-") != 0)
            fprintf(stderr, ", %s/%s (%lld samples, %.3f s)", dir, s.ref->audio, samples,
                    (double)samples / WW_AUDIO_RATE);
        if (strcmp(s.ref->stats, "-") != 0) fprintf(stderr, ", %s/%s (%lld frame lines)", dir, s.ref->stats, lines);
        fprintf(stderr, "\n");
    }
    free(s.mine);
    free(s.other);
    free(s.rec);
    return r;
}

/* ---- a sweep's points ---------------------------------------------------------------------- */

typedef struct sweep_job {
    long long points;
    int digits;
    int sheet, cols, thumb_w, thumb_h, lines; /* a contact sheet of thumbnails */
    char *csv_header;          /* with its newline */
    char *command;
} sweep_job;

static ww_result read_job(const char *dir, unsigned char **data, sweep_job *j, ww_error *err) {
    char path[1200];
    size_t len = 0;
    snprintf(path, sizeof path, "%s/points/sweep.job", dir);
    ww_result r = ww_file_read_max(path, JOB_MAX_BYTES, JOB_MAX_BYTES, data, &len, err);
    if (r)
        return ww_error_set(err, WW_E_MISMATCH, path, 0, 0,
                            "missing: no point has run yet (sweep ... --emit-jobs prints their commands)");
    char *t = (char *)*data, *csv = strstr(t, "\ncsv "), *cmd = strstr(t, "\ncommand ");
    memset(j, 0, sizeof *j);
    if (strncmp(t, WW_SWEEP_JOB_MAGIC "\n", strlen(WW_SWEEP_JOB_MAGIC) + 1) != 0 || !csv || !cmd ||
        sscanf(t + strlen(WW_SWEEP_JOB_MAGIC), "\npoints %lld\ndigits %d", &j->points, &j->digits) != 2 ||
        j->points < 1 || j->digits < 1 || j->digits > 20)
        return ww_error_set(err, WW_E_SYNTAX, path, 0, 0, "not a sweep job file");
    const char *sheet = strstr(t, "\nsheet ");
    j->sheet = sheet && sheet < csv &&
               sscanf(sheet, "\nsheet %d %d %d %d", &j->cols, &j->thumb_w, &j->thumb_h, &j->lines) == 4;
    j->csv_header = csv + 5;
    cmd[1] = 0;                /* the header keeps its newline */
    j->command = cmd + 9;
    char *nl = strchr(j->command, '\n');
    if (nl) *nl = 0;
    return WW_OK;
}

static void point_path(const char *dir, const sweep_job *j, long long i, const char *ext, char *out,
                       size_t cap) {
    snprintf(out, cap, "%s/points/point_%0*lld.%s", dir, j->digits, i, ext);
}

/* a complete part: a regular file ending in a newline */
static int part_complete(const char *path) {
    FILE *f = fopen(path, "rb");
    if (!f) return 0;
    int ok = fseek(f, -1, SEEK_END) == 0 && fgetc(f) == '\n';
    fclose(f);
    return ok;
}

static ww_result join_file(const char *dir, const sweep_job *j, const char *name, const char *ext,
                           const char *header, ww_error *err) {
    char path[1200];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    ww_stream out;
    ww_result r = ww_stream_open(&out, path, err);
    if (r) return r;
    if (header) fputs(header, out.f);
    for (long long i = 0; i < j->points && !r; i++) {
        char part[1200];
        unsigned char *data = NULL;
        size_t len = 0;
        point_path(dir, j, i, ext, part, sizeof part);
        if ((r = ww_file_read_max(part, PART_MAX_BYTES, PART_MAX_BYTES, &data, &len, err))) break;
        if (fwrite(data, 1, len, out.f) != len)
            r = ww_error_set(err, WW_E_IO, path, 0, 0, "cannot write: %s", strerror(errno));
        free(data);
    }
    if (r) {
        ww_stream_abort(&out);
        return r;
    }
    return ww_stream_commit(&out, err);
}

/* DIR/contact_sheet.png from the thumbnails and the points' labels, as a one-process sweep
 * composes it */
static ww_result join_sheet(const char *dir, const sweep_job *j, ww_error *err) {
    ww_contact_layout L;
    ww_image sheet = {0};
    char path[1200];
    if (j->points > WW_SWEEP_MAX_POINTS ||
        ww_contact_plan((int)j->points, j->cols, j->thumb_w, j->thumb_h, j->lines, &L) != 0)
        return WW_OK; /* too large for a sheet: the sweep itself would refuse to make one */
    if (ww_contact_new(&L, &sheet) != 0)
        return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory for a %dx%d contact sheet",
                            L.width, L.height);
    ww_result r = WW_OK;
    for (long long i = 0; i < j->points && !r; i++) {
        unsigned char *text = NULL;
        size_t len = 0;
        point_path(dir, j, i, "label", path, sizeof path);
        if ((r = ww_file_read_max(path, JOB_MAX_BYTES, JOB_MAX_BYTES, &text, &len, err))) break;
        int has = strncmp((char *)text, "thumb 1\n", 8) == 0;
        if (len > 8 && text[len - 1] == '\n') text[len - 1] = 0;
        ww_image thumb = {0};
        snprintf(path, sizeof path, "%s/thumbs/point_%0*lld.png", dir, j->digits, i);
        if (has && !(r = ww_read_png(path, &thumb, err)) &&
            (thumb.width != j->thumb_w || thumb.height != j->thumb_h || thumb.channels < 3))
            r = ww_error_set(err, WW_E_IO, path, 0, 0, "thumbnail is %dx%d, expected %dx%d",
                             thumb.width, thumb.height, j->thumb_w, j->thumb_h);
        if (!r) ww_contact_put(&sheet, &L, (int)i, has ? &thumb : NULL, len > 8 ? (char *)text + 8 : "");
        ww_image_free(&thumb);
        free(text);
    }
    snprintf(path, sizeof path, "%s/contact_sheet.png", dir);
    if (!r) r = ww_write_png(path, &sheet, err);
    ww_image_free(&sheet);
    return r;
}

static ww_result join_points(const char *dir, int quiet, ww_error *err) {
    unsigned char *data = NULL;
    sweep_job j;
    ww_result r = read_job(dir, &data, &j, err);
    long long bad = 0;
    for (long long i = 0; !r && i < j.points; i++) {
        char jsonl[1200], csv[1200];
        point_path(dir, &j, i, "jsonl", jsonl, sizeof jsonl);
        point_path(dir, &j, i, "csv", csv, sizeof csv);
        char label[1200];
        point_path(dir, &j, i, "label", label, sizeof label);
        if (part_complete(jsonl) && part_complete(csv) && (!j.sheet || part_complete(label))) continue;
        if (!quiet) fprintf(stderr, "point %lld: missing (%s)\n", i, jsonl);
        printf("%s --point %lld\n", j.command, i);
        bad++;
    }
    if (!r && bad)
        r = ww_error_set(err, WW_E_MISMATCH, NULL, 0, 0,
                         "join %s: %lld of %lld points are missing; the commands that compute them "
                         "are on stdout",
                         dir, bad, j.points);
    if (!r) r = join_file(dir, &j, "sweep.jsonl", "jsonl", NULL, err);
    if (!r) r = join_file(dir, &j, "sweep.csv", "csv", j.csv_header, err);
    if (!r && j.sheet) r = join_sheet(dir, &j, err);
    if (!r && !quiet)
        fprintf(stderr, "joined %lld points of %s: %s/sweep.jsonl, %s/sweep.csv%s\n", j.points, dir, dir,
                dir, j.sheet ? ", contact_sheet.png" : "");
    free(data);
    return r;
}

/* ---- the command --------------------------------------------------------------------------- */

static int is_dir(const char *dir, const char *sub) {
    char path[1200];
    struct stat st;
    snprintf(path, sizeof path, "%s/%s", dir, sub);
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

ww_result ww_cmd_join(int argc, char **argv, ww_error *err) {
    const char *dir = NULL;
    int quiet = 0;
    for (int i = 0; i < argc; i++) {
        if (ww_cli_is_help(argv[i])) {
            fputs(usage, stdout);
            return WW_OK;
        }
        if (strcmp(argv[i], "--quiet") == 0) {
            quiet = 1;
        } else if (argv[i][0] == '-' || dir) {
            return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "join: unexpected '%s' (see --help)", argv[i]);
        } else {
            dir = argv[i];
        }
    }
    if (!dir) return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "join needs a folder (waterworld join --help)");
    int has_slices = is_dir(dir, "slices"), has_points = is_dir(dir, "points");
    if (!has_slices && !has_points)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            "join: %s holds neither slices/ (render --slice I/N -o %s) nor points/ "
                            "(sweep --point I -o %s)",
                            dir, dir, dir);
    ww_result r = has_slices ? join_slices(dir, quiet, err) : WW_OK;
    if (!r && has_points) r = join_points(dir, quiet, err);
    if (fflush(stdout) != 0 && !r) r = ww_error_set(err, WW_E_IO, "stdout", 0, 0, "cannot write: %s", strerror(errno));
    return r;
}
