/* cmd_compare.c - `waterworld compare EXPECTED ACTUAL`: two images, or two folders of frames
 * matched by name, under the thresholds of check/compare.h; a line (or a JSON object) per pair.
 */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

#include "check/compare.h"
#include "cli/cli.h"
#include "io/json.h"
#include "io/outpath.h"
#include "io/writers.h"

static const char usage[] =
    "usage: waterworld compare EXPECTED ACTUAL [--diff FILE|DIR] [thresholds] [--json]\n"
    "\n"
    "Compares two images (PNG 8/16-bit grey/RGB/RGBA, or EXR) or two folders of frames (*.png,\n"
    "*.exr matched by name; a frame missing from ACTUAL or extra in it fails).\n"
    "\n"
    "  --diff FILE|DIR    diff image (PNG): the expected image faded, differences red,\n"
    "                     anti-aliasing yellow; for folders, DIR/NAME.png for each failing pair\n"
    "  --json             one JSON object per pair (and a summary object for folders)\n"
    "thresholds (a pixel differs when a channel differs by more than --threshold):\n"
    "  --threshold T      per-pixel threshold, 8-bit levels (EXR: relative error; default 0)\n"
    "  --max M            fail when a channel differs by more than M levels (EXR: linear)\n"
    "  --fail-percent P   fail when more than P% of pixels differ\n"
    "  --fail-pixels N    fail when more than N pixels differ\n"
    "  --psnr-min DB      fail when the PSNR (as ImageMagick's) is below DB\n"
    "  --yiq Y            pixelmatch threshold 0..1 (default 0.1); alone: no pixel may exceed it\n"
    "  --yiq-pixels N     fail when more than N pixels exceed the YIQ threshold (not AA)\n"
    "  --no-aa            count anti-aliased pixels as differences too\n"
    "  --ssim-min S       fail when the mean SSIM is below S\n"
    "  --rel-max R        fail when a channel's relative error exceeds R (for EXR)\n"
    "With no rule given, any pixel over --threshold fails (default: exact match). Identical\n"
    "images are found first by a content hash.\n"
    "\n"
    "Exit: 0 every pair passes, 1 a pair differs (or a frame is missing or extra), 2 bad input\n"
    "(unreadable file, not an image, sizes or channel kinds differ).\n";

typedef struct cmp_args {
    const char *expected, *actual, *diff;
    int json;
    ww_cmp_opts o;
} cmp_args;

typedef struct cmp_tally {
    long pairs, passed, failed, missing, extra, errors;
    ww_error first;          /* the first bad-input error of a folder run */
} cmp_tally;

static int is_dir(const char *p) {
    struct stat st;
    return stat(p, &st) == 0 && S_ISDIR(st.st_mode);
}

static ww_result parse_args(int argc, char **argv, cmp_args *a, ww_error *err) {
    ww_result r = WW_OK;
    for (int i = 0; i < argc && !r; i++) {
        if (strcmp(argv[i], "--json") == 0) {
            a->json = 1;
            continue;
        }
        if (ww_cli_opt(argc, argv, &i, "--diff", &a->diff, &r, err)) continue;
        if (ww_cmp_opt_arg(argc, argv, &i, &a->o, &r, err)) continue;
        if (argv[i][0] == '-' && argv[i][1])
            return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "compare: unknown option '%s' (see --help)",
                                argv[i]);
        if (!a->expected)
            a->expected = argv[i];
        else if (!a->actual)
            a->actual = argv[i];
        else
            return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                                "compare: takes two paths, got a third: '%s'", argv[i]);
    }
    if (r) return r;
    if (!a->actual)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0, "compare: needs EXPECTED and ACTUAL (see --help)");
    return WW_OK;
}

/* one pair: load, compare, print, diff; bad input is returned (and printed in JSON mode) */
static ww_result compare_pair(const cmp_args *a, const char *name, const char *pe, const char *pa,
                              const char *diff, int *pass, ww_error *err) {
    ww_cmp_image e, x;
    ww_cmp_result res;
    ww_result r = ww_cmp_pair(pe, pa, &a->o, &e, &x, &res, err);
    if (r == WW_OK && diff) r = ww_cmp_write_diff(diff, &e, &x, &a->o, err);
    ww_cmp_image_free(&e);
    ww_cmp_image_free(&x);
    if (r != WW_OK) {
        if (a->json) {
            printf("{\"name\":");
            ww_json_string(stdout, name);
            printf(",\"error\":\"%s\",\"message\":", ww_result_name(r));
            ww_json_string(stdout, err->msg);
            printf(",\"pass\":false}\n");
        } else {
            printf("%s: error: %s\n", name, err->msg);
        }
        return r;
    }
    *pass = res.pass;
    if (a->json) {
        printf("{\"name\":");
        ww_json_string(stdout, name);
        printf(",\"expected\":");
        ww_json_string(stdout, pe);
        printf(",\"actual\":");
        ww_json_string(stdout, pa);
        if (diff) {
            printf(",\"diff\":");
            ww_json_string(stdout, diff);
        }
        putchar(',');
        ww_cmp_result_json_fields(&res, &a->o, stdout);
        printf("}\n");
    } else {
        printf("%s: ", name);
        ww_cmp_result_line(&res, stdout);
        putchar('\n');
    }
    return WW_OK;
}

/* ---- folders ---------------------------------------------------------------------------------- */

static int frame_name(const char *n) {
    size_t len = strlen(n);
    return n[0] != '.' && len > 4 &&
           (strcasecmp(n + len - 4, ".png") == 0 || strcasecmp(n + len - 4, ".exr") == 0);
}

static int cmp_str(const void *x, const void *y) {
    return strcmp(*(char *const *)x, *(char *const *)y);
}

/* the frame files of a folder, sorted; *names and each name are malloc'd */
static ww_result list_frames(const char *dir, char ***names, size_t *n, ww_error *err) {
    *names = NULL;
    *n = 0;
    DIR *d = opendir(dir);
    if (!d) return ww_error_set(err, WW_E_NOFILE, NULL, 0, 0, "cannot read folder '%s'", dir);
    size_t cap = 0;
    ww_result r = WW_OK;
    for (struct dirent *e; (e = readdir(d)) != NULL;) {
        if (!frame_name(e->d_name)) continue;
        if (*n == cap) {
            cap = cap ? 2 * cap : 64;
            char **nn = realloc(*names, cap * sizeof *nn);
            if (!nn) {
                r = WW_E_NOMEM;
                break;
            }
            *names = nn;
        }
        if (!((*names)[*n] = strdup(e->d_name))) {
            r = WW_E_NOMEM;
            break;
        }
        (*n)++;
    }
    closedir(d);
    if (r) return ww_error_set(err, r, NULL, 0, 0, "listing '%s': out of memory", dir);
    if (*n) qsort(*names, *n, sizeof **names, cmp_str);
    return WW_OK;
}

static void free_names(char **names, size_t n) {
    for (size_t i = 0; i < n; i++) free(names[i]);
    free(names);
}

static void report_alone(const cmp_args *a, const char *name, int missing) {
    if (a->json) {
        printf("{\"name\":");
        ww_json_string(stdout, name);
        printf(",\"%s\":true,\"pass\":false}\n", missing ? "missing" : "extra");
    } else {
        printf("%s: %s\n", name, missing ? "FAIL: missing from ACTUAL" : "FAIL: extra in ACTUAL (not in EXPECTED)");
    }
}

/* "dir/name" into buf; the diff's name ends in .png */
static void join(char *buf, size_t cap, const char *dir, const char *name, int as_png) {
    size_t len = strlen(name);
    if (as_png && len > 4)
        snprintf(buf, cap, "%s/%.*s.png", dir, (int)(len - 4), name);
    else
        snprintf(buf, cap, "%s/%s", dir, name);
}

static void compare_one(const cmp_args *a, const char *name, cmp_tally *t) {
    char pe[4096], pa[4096], pd[4096];
    join(pe, sizeof pe, a->expected, name, 0);
    join(pa, sizeof pa, a->actual, name, 0);
    if (a->diff) join(pd, sizeof pd, a->diff, name, 1);
    ww_error e = {0};
    int pass = 0;
    t->pairs++;
    ww_result r = compare_pair(a, name, pe, pa, a->diff ? pd : NULL, &pass, &e);
    /* a diff image only where the pair failed */
    if (r == WW_OK && pass && a->diff) remove(pd);
    if (r != WW_OK) {
        if (t->errors++ == 0) t->first = e;
    } else if (pass) {
        t->passed++;
    } else {
        t->failed++;
    }
}

static ww_result compare_dirs(const cmp_args *a, ww_error *err) {
    char **ne, **na;
    size_t n_e, n_a;
    ww_result r = list_frames(a->expected, &ne, &n_e, err);
    if (r) return r;
    if ((r = list_frames(a->actual, &na, &n_a, err))) {
        free_names(ne, n_e);
        return r;
    }
    if (a->diff && (r = ww_make_dirs(a->diff, err))) goto done;

    /* walk both sorted lists together */
    cmp_tally t = {0};
    for (size_t i = 0, j = 0; i < n_e || j < n_a;) {
        int c = i == n_e ? 1 : j == n_a ? -1 : strcmp(ne[i], na[j]);
        if (c < 0) {
            report_alone(a, ne[i++], 1);
            t.missing++;
        } else if (c > 0) {
            report_alone(a, na[j++], 0);
            t.extra++;
        } else {
            compare_one(a, ne[i], &t);
            i++, j++;
        }
    }
    int pass = !t.failed && !t.missing && !t.extra && !t.errors;
    if (a->json)
        printf("{\"summary\":true,\"pairs\":%ld,\"passed\":%ld,\"failed\":%ld,\"missing\":%ld,"
               "\"extra\":%ld,\"errors\":%ld,\"pass\":%s}\n",
               t.pairs, t.passed, t.failed, t.missing, t.extra, t.errors, pass ? "true" : "false");
    else
        printf("%ld pairs: %ld passed, %ld failed, %ld missing, %ld extra, %ld errors\n", t.pairs,
               t.passed, t.failed, t.missing, t.extra, t.errors);
    if (t.errors) {
        if (err) *err = t.first;
        r = t.first.code;
    } else if (!pass) {
        r = ww_error_set(err, WW_E_MISMATCH, NULL, 0, 0,
                         "compare: %s and %s differ (%ld failed, %ld missing, %ld extra)",
                         a->expected, a->actual, t.failed, t.missing, t.extra);
    } else if (n_e == 0) {
        r = ww_error_set(err, WW_E_NOFILE, NULL, 0, 0, "compare: no *.png or *.exr frames in '%s'",
                         a->expected);
    }
done:
    free_names(ne, n_e);
    free_names(na, n_a);
    return r;
}

ww_result ww_cmd_compare(int argc, char **argv, ww_error *err) {
    for (int i = 0; i < argc; i++)
        if (ww_cli_is_help(argv[i])) {
            fputs(usage, stdout);
            return WW_OK;
        }
    cmp_args a = {.o = ww_cmp_default_opts()};
    ww_result r = parse_args(argc, argv, &a, err);
    if (r) return r;
    int de = is_dir(a.expected), da = is_dir(a.actual);
    if (de != da)
        return ww_error_set(err, WW_E_USAGE, NULL, 0, 0,
                            "compare: '%s' is a %s and '%s' a %s: give two files or two folders",
                            a.expected, de ? "folder" : "file", a.actual, da ? "folder" : "file");
    /* the diff is written at the end: a bad place for it is found before any image is read,
     * and it never overwrites what it compares */
    if (a.diff) {
        r = de ? ww_check_out_dir("--diff", a.diff, err) : ww_check_out_file("--diff", a.diff, 0, err);
        if (!r) r = ww_check_out_distinct("EXPECTED", a.expected, "--diff", a.diff, err);
        if (!r) r = ww_check_out_distinct("ACTUAL", a.actual, "--diff", a.diff, err);
        if (r) return r;
    }
    if (de) return compare_dirs(&a, err);
    int pass = 0;
    r = compare_pair(&a, a.actual, a.expected, a.actual, a.diff, &pass, err);
    if (r) return r;
    if (!pass)
        return ww_error_set(err, WW_E_MISMATCH, NULL, 0, 0, "compare: %s differs from %s", a.actual,
                            a.expected);
    return WW_OK;
}
