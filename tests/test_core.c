/* test_core.c - core utilities: rng streams, hash, arena, the child process helper, the short
 * number readers. */
#include <dirent.h>
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/arena.h"
#include "core/child.h"
#include "core/error.h"
#include "core/hash.h"
#include "core/numparse.h"
#include "core/rng.h"
#include "test.h"

TEST(core_rng_streams_independent_and_repeatable) {
    ww_rng a, b, c;
    ww_rng_seed(&a, 7, WW_RNG_STONES);
    ww_rng_seed(&b, 7, WW_RNG_STONES);
    ww_rng_seed(&c, 7, WW_RNG_FISH);
    int same_ab = 1, same_ac = 1;
    for (int i = 0; i < 100; i++) {
        uint32_t x = ww_rng_u32(&a), y = ww_rng_u32(&b), z = ww_rng_u32(&c);
        same_ab &= x == y;
        same_ac &= x == z;
    }
    ENSURE(same_ab);
    ENSURE(!same_ac);
}

TEST(core_rng_uniform_in_unit_interval_with_right_mean) {
    ww_rng r;
    ww_rng_seed(&r, 1, 1);
    double sum = 0;
    int n = 100000, bad = 0;
    for (int i = 0; i < n; i++) {
        double u = ww_rng_uniform(&r);
        bad += !(u >= 0.0 && u < 1.0);
        sum += u;
    }
    ENSURE_EQ_INT(bad, 0);
    /* standard error of the mean of U(0,1) over 1e5 draws is 0.0009; 5 sigma */
    ENSURE_NEAR(sum / n, 0.5, 0.0046);
}

TEST(core_hash_fnv1a_reference_values) {
    /* published FNV-1a 64 test vectors */
    ENSURE_EQ_U64(ww_hash_bytes(WW_HASH_INIT, "", 0), 0xcbf29ce484222325ULL);
    ENSURE_EQ_U64(ww_hash_bytes(WW_HASH_INIT, "a", 1), 0xaf63dc4c8601ec8cULL);
    ENSURE_EQ_U64(ww_hash_bytes(WW_HASH_INIT, "foobar", 6), 0x85944171f73967e8ULL);
}

TEST(core_arena_mark_release_and_bounds) {
    ww_arena a;
    ENSURE(ww_arena_init(&a, 1024) == 0);
    void *p = ww_arena_alloc(&a, 100);
    ENSURE(p != NULL);
    ENSURE(((uintptr_t)p & 15u) == 0);
    size_t m = ww_arena_mark(&a);
    ENSURE(ww_arena_alloc(&a, 900) != NULL);
    ENSURE(ww_arena_alloc(&a, 100) == NULL); /* full */
    ww_arena_release(&a, m);
    ENSURE(ww_arena_alloc(&a, 800) != NULL);
    ww_arena_free(&a);
}

TEST(core_exit_codes_follow_the_contract) {
    ENSURE_EQ_INT(ww_result_exit_code(WW_OK), 0);
    ENSURE_EQ_INT(ww_result_exit_code(WW_E_UNKNOWN_KEY), 2);
    ENSURE_EQ_INT(ww_result_exit_code(WW_E_INCONSISTENT), 2);
    ENSURE_EQ_INT(ww_result_exit_code(WW_E_IO), 3);
    ENSURE_EQ_INT(ww_result_exit_code(WW_E_NAN), 3);
}

/* ---- core/child.h ---------------------------------------------------------------------------- */

/* a report larger than a pipe's buffer (64 KiB on Linux), so it crosses in parts */
typedef struct big_report {
    int seen;               /* ctx's value, as the child saw it */
    unsigned char fill[200000];
} big_report;

static void child_fills(const void *ctx, void *report) {
    big_report *r = report;
    r->seen = *(const int *)ctx;
    for (size_t i = 0; i < sizeof r->fill; i++) r->fill[i] = (unsigned char)(i * 7u + 1u);
}

static void child_exits_3(const void *ctx, void *report) {
    (void)ctx;
    ((big_report *)report)->seen = 1;
    _exit(3);
}

static void child_is_killed(const void *ctx, void *report) {
    (void)ctx;
    (void)report;
    raise(SIGKILL);
}

TEST_PROC(core_child_brings_the_report_back_or_says_how_it_died) {
    big_report *r = malloc(sizeof *r);
    ENSURE(r != NULL);
    if (!r) return;
    int ctx = 42;
    ww_child_end end;
    ENSURE_EQ_INT(ww_child_run(child_fills, &ctx, r, sizeof *r, &end), WW_CHILD_REPORTED);
    ENSURE_EQ_INT(end.outcome, WW_CHILD_REPORTED);
    ENSURE_EQ_INT(end.status, 0);
    ENSURE(end.max_rss_kib > 0);
    ENSURE_EQ_INT(r->seen, 42);
    int same = 1;
    for (size_t i = 0; i < sizeof r->fill; i++) same &= r->fill[i] == (unsigned char)(i * 7u + 1u);
    ENSURE(same);

    /* a child that ends before reporting: the report is zeroed, the status says how */
    char how[64];
    ENSURE_EQ_INT(ww_child_run(child_exits_3, &ctx, r, sizeof *r, &end), WW_CHILD_DIED);
    ENSURE_EQ_INT(r->seen, 0);
    ENSURE(strcmp(ww_child_how_ended(end.status, how, sizeof how), "exit status 3") == 0);
    ENSURE_EQ_INT(ww_child_run(child_is_killed, &ctx, r, sizeof *r, NULL), WW_CHILD_DIED);
    ENSURE_EQ_INT(ww_child_run(child_is_killed, &ctx, r, sizeof *r, &end), WW_CHILD_DIED);
    ENSURE(strcmp(ww_child_how_ended(end.status, how, sizeof how), "killed by signal 9") == 0);
    free(r);
}

/* ---- short numbers (core/numparse.h) --------------------------------------------------------- */

/* whether the fast reader's answer for the n characters at s is strtod's: where it takes them
 * (returns 1) strtod must take the whole string to the same bits; *taken counts those */
static int decimal_agrees(const char *s, int *taken) {
    double fast = 0.0;
    size_t n = strlen(s);
    if (!ww_parse_decimal(s, n, &fast)) return 1;
    (*taken)++;
    char *e;
    double slow = strtod(s, &e);
    return e == s + n && memcmp(&fast, &slow, sizeof fast) == 0;
}

/* random decimals of every shape the reader might see (up to 21 digits, the point anywhere or
 * absent, exponents of both signs and cases, signs), and the edges: where the fast reader
 * answers, its bits are strtod's; and it answers for most short ones */
TEST(core_parse_decimal_gives_strtod_bits) {
    static const char *const edges[] = {
        "0", "-0", "+0.0", ".5", "5.", "-.5", "+.5", "1e22", "1e23", "1e-22", "1e-23",
        "9007199254740992", "9007199254740993", "-9007199254740992e-22", "0.1", "0.2", "0.3",
        "0.30000000000000004", "123456789012345678e-5", "1234567890123456789", "00000000000000000000001",
        "0.000000000000000000000000001", "1E5", "1e+05", "2.5e-0", "", "+", "-", ".", "e5", "1e",
        "1e+", "0x10", "0x1p3", "inf", "-inf", "nan", "1,5", "--1", "1.2.3", " 1", "1 ", "1e5.0",
        "3.4028234663852886e38", "4.9e-324", "1e99999999999"};
    int taken = 0, bad = 0;
    for (size_t k = 0; k < sizeof edges / sizeof edges[0]; k++)
        if (!decimal_agrees(edges[k], &taken)) {
            bad++;
            printf("    disagrees on '%s'\n", edges[k]);
        }
    ww_rng r;
    ww_rng_seed(&r, 5, 0);
    int random_taken = 0, tries = 200000;
    for (int i = 0; i < tries; i++) {
        char buf[64];
        int len = 0, ndig = 1 + (int)(ww_rng_u32(&r) % 21), point = (int)(ww_rng_u32(&r) % 24);
        uint32_t form = ww_rng_u32(&r);
        if (form & 1) buf[len++] = form & 2 ? '-' : '+';
        for (int d = 0; d < ndig; d++) {
            if (d == point) buf[len++] = '.';
            buf[len++] = (char)('0' + ww_rng_u32(&r) % 10);
        }
        if (form & 4) {
            buf[len++] = form & 8 ? 'e' : 'E';
            if (form & 16) buf[len++] = form & 32 ? '-' : '+';
            len += snprintf(buf + len, sizeof buf - (size_t)len, "%u", ww_rng_u32(&r) % 40);
        }
        buf[len] = '\0';
        if (!decimal_agrees(buf, &random_taken)) {
            if (bad++ < 10) printf("    disagrees on '%s'\n", buf);
        }
    }
    printf("    fast path took %d of %d random decimals\n", random_taken, tries);
    ENSURE_EQ_INT(bad, 0);
    ENSURE(random_taken > tries / 4);
    double d = 1.0;
    ENSURE(!ww_parse_decimal("1e23", 4, &d) && !ww_parse_decimal("nan", 3, &d));
    ENSURE(ww_parse_decimal("-0", 2, &d) && d == 0.0 && signbit(d));
}

/* whole numbers: where the fast reader answers, strtol takes the whole string to the same value */
TEST(core_parse_integer_gives_strtol_value) {
    static const char *const cases[] = {"0", "-0", "1", "-1", "42", "-17", "000123",
                                        "999999999999999999", "1000000000000000000", "+5", "",
                                        "-", "1a", " 1", "1.0", "0x10", "--3"};
    int taken = 0;
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        long fast = 0;
        size_t n = strlen(cases[k]);
        if (!ww_parse_integer(cases[k], n, &fast)) continue;
        taken++;
        char *e;
        errno = 0;
        long slow = strtol(cases[k], &e, 10);
        ENSURE_MSG(e == cases[k] + n && errno == 0 && fast == slow, "'%s': %ld against %ld",
                   cases[k], fast, slow);
    }
    ENSURE_EQ_INT(taken, 8);
}

/* every number of every model this project ships: the fast readers answer for all of them, as
 * strtod and strtol do (the models' load is where they pay) */
TEST(core_parse_numbers_of_the_shipped_models) {
    DIR *dir = opendir("scenes/models");
    ENSURE(dir != NULL);
    if (!dir) return;
    int files = 0, decimals = 0, indices = 0, bad = 0;
    struct dirent *de;
    while ((de = readdir(dir)) != NULL) {
        size_t len = strlen(de->d_name);
        if (len < 5 || strcmp(de->d_name + len - 4, ".obj") != 0) continue;
        char path[512];
        snprintf(path, sizeof path, "scenes/models/%s", de->d_name);
        FILE *f = fopen(path, "r");
        if (!f) continue;
        files++;
        char line[512];
        while (fgets(line, sizeof line, f)) {
            int face = line[0] == 'f' && line[1] == ' ';
            int vertex = line[0] == 'v' && (line[1] == ' ' || line[2] == ' ');
            if (!face && !vertex) continue;
            for (char *tok = strtok(line + 2, " \t\r\n"); tok; tok = strtok(NULL, " \t\r\n")) {
                if (vertex) {
                    int taken = 0;
                    if (!decimal_agrees(tok, &taken) || !taken) bad++;
                    decimals++;
                    continue;
                }
                for (char *part = tok; *part;) { /* v/t/n corner */
                    size_t n = strcspn(part, "/");
                    long v;
                    if (n > 0 && (!ww_parse_integer(part, n, &v) || v != strtol(part, NULL, 10)))
                        bad++;
                    indices += n > 0;
                    part += n + (part[n] == '/');
                }
            }
        }
        fclose(f);
    }
    closedir(dir);
    printf("    %d files, %d decimals, %d indices\n", files, decimals, indices);
    ENSURE(files >= 10 && decimals > 10000 && indices > 10000);
    ENSURE_EQ_INT(bad, 0);
}
