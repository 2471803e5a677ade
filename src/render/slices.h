/* slices.h - a render cut into N slices for a scheduler, and their completion records: what
 * `render --slices N --emit-jobs`, `render --slice I/N` and `join` share.
 *
 *   ww_slice_opts so = {.index = 1, .count = 3, .words = w, .nwords = n, ...};
 *   ww_slices_emit(&so, sc, &jo, stdout, &err);        // --emit-jobs: N command lines
 *   ww_slice_begin(&so, sc, &jo, &skip, &err);         // --slice: jo's range and part paths set,
 *   if (!skip) ww_job_run(sc, &jo, &st, &err);         //   the record says "started"
 *   ww_slice_end(&so, sc, &jo, st.renderer, &err);     // the record says "done", last
 *
 * Slice I of N of frames [A, B) is [A + I q + min(I, r), A + (I+1) q + min(I+1, r)) with
 * q, r = (B - A) / N, (B - A) % N: contiguous, near-equal (sizes differ by at most one).
 * A slice's frames go into DIR as a full run's do; its parts go under DIR/slices/:
 *   slice_IIIII.wav          the sound track of its frames (--audio): samples [B(a), B(b)) of
 *                            the full run's grid, so the parts butt sample-exactly
 *   slice_IIIII.stats.jsonl  its --stats lines
 *   slice_IIIII.record       the completion record, written atomically at the start ("state
 *                            started") and again after everything else ("state done")
 * The record names the slice, its frames and sample range, the run (scene hash and the options
 * that shape the output) and the command that renders it, so that `join` refuses a slice of
 * another run and prints the commands that complete the set.
 */
#ifndef WW_SLICES_H
#define WW_SLICES_H

#include <stdint.h>
#include <stdio.h>

#include "core/error.h"
#include "render/job.h"
#include "scene/scene.h"

#define WW_SLICE_RECORD_MAGIC "waterworld slice record 1"
#define WW_SLICE_AUDIO_DEFAULT "audio.wav"   /* the joined track in DIR */
#define WW_SLICE_STATS_DEFAULT "stats.jsonl" /* the joined stats in DIR */
#define WW_SLICE_LINE_MAX 16384              /* one record line: the command is the longest */

typedef struct ww_slice_opts {
    int64_t index, count;     /* --slice I/N (index -1 with --slices N --emit-jobs) */
    /* the render's own words minus the slicing ones (--slice, --slices, --emit-jobs,
     * --resume): what every slice's command repeats */
    char **words;
    int nwords;
    const char *exe;          /* the program named in command lines (NULL: "waterworld") */
    const char *scene_path, *script;    /* for the scene hash */
    const ww_set *sets;       /* --set texts, for the scene hash */
    int nsets;
    const char *audio_name;   /* joined track's name in DIR, NULL without --audio */
    const char *stats_name;   /* joined stats' name in DIR, NULL without --stats */
    /* --checkpoints DIR for --emit-jobs: each line then ends in --from-checkpoint DIR (render
     * takes the latest checkpoint at or before the slice's first frame); cmd_render.c's table
     * of slicing options sets it */
    const char *checkpoints;
    /* filled by ww_slice_begin */
    int64_t run_first, run_last;          /* the whole run's frames */
    char audio_part[1200], stats_part[1200], record[1200];
    char run[512];                         /* the run's identity line */
} ww_slice_opts;

/* "I/N": whole numbers, N >= 1, I < N; WW_E_USAGE naming --slice otherwise */
ww_result ww_slice_parse(const char *text, int64_t *index, int64_t *count, ww_error *err);
/* "N" >= 1 for --slices; WW_E_USAGE otherwise */
ww_result ww_slices_parse(const char *text, int64_t *count, ww_error *err);
/* pure: slice i of n of [first, last) */
void ww_slice_range(int64_t first, int64_t last, int64_t i, int64_t n, int64_t *a, int64_t *b);
/* pure: the sound track's absolute sample where step `step` ends (render/audio.h's grid) */
int64_t ww_slice_sample(const ww_scene *sc, int64_t step);

/* --emit-jobs: one line per slice, `EXE render <words> --slice I/N`; jo's range is the run's */
ww_result ww_slices_emit(ww_slice_opts *so, const ww_scene *sc, const ww_job_opts *jo, FILE *to,
                         ww_error *err);
/* --slice: checks N against the frames, sets jo's range, --audio and --stats to the parts,
 * writes the "started" record; with jo->resume, a slice whose record is done for this very run
 * sets *skip (nothing to do), and a record of another run turns resume off (its frames are not
 * this run's) */
ww_result ww_slice_begin(ww_slice_opts *so, const ww_scene *sc, ww_job_opts *jo, int *skip,
                         ww_error *err);
/* after the job: the "done" record, naming the renderer */
ww_result ww_slice_end(const ww_slice_opts *so, const ww_scene *sc, const ww_job_opts *jo,
                       const char *renderer, ww_error *err);

/* ---- the record, as join reads it ---------------------------------------------------------- */

typedef struct ww_slice_record {
    int done;                        /* state done (else started) */
    int64_t index, count;
    int64_t first, last;             /* the slice's frames */
    int64_t sample0, sample1;        /* its sound track's samples (0:0 without --audio) */
    char run[512];                   /* identity: scene hash and the shaping options */
    char format[8];                  /* png | exr | none */
    char renderer[128];              /* GL_RENDERER of a done slice */
    char audio[256], stats[256];     /* joined names, "-" for none */
    char command[WW_SLICE_LINE_MAX]; /* sh line without --slice */
} ww_slice_record;

/* DIR/slices/slice_IIIII.EXT (EXT: record, wav, stats.jsonl) */
void ww_slice_part_path(const char *dir, int64_t index, const char *ext, char *out, size_t cap);
/* the parts and frames a record names are on disk (the sound track at its length); 0 and why
 * otherwise */
int ww_slice_check(const char *dir, const ww_slice_record *rec, char *why, size_t cap);
/* a record file: WW_E_NOFILE when absent, WW_E_SYNTAX when it is not one */
ww_result ww_slice_record_read(const char *path, ww_slice_record *rec, ww_error *err);

#endif
