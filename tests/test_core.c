/* test_core.c - core utilities: rng streams, hash, arena. */
#include <string.h>

#include "core/arena.h"
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
