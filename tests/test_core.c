/* test_core.c - core utilities: rng streams, hash, arena, the child process helper. */
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/arena.h"
#include "core/child.h"
#include "core/error.h"
#include "core/hash.h"
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
