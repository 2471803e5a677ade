/* state.c - the one-block simulation state: sizing, reset, copy, hash, JSON and NaN checks,
 * all driven by the WW_STATE_FIELDS table in state.h.
 */
#include "sim/state.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/hash.h"
#include "core/lanes.h"
#include "core/numfmt.h"

/* bytes of one field, rounded to 16 so every array starts aligned */
static size_t field_bytes(size_t elem, long long count) {
    size_t n = elem * (size_t)(count > 0 ? count : 0);
    return (n + 15u) & ~(size_t)15u;
}

static size_t header_bytes(void) { return (sizeof(ww_state) + 15u) & ~(size_t)15u; }

size_t ww_state_arrays_offset(void) { return header_bytes(); }

/* point the field pointers into the block that follows the header */
static void bind_fields(const ww_scene *sc, ww_state *st) {
    unsigned char *p = (unsigned char *)st + header_bytes();
#define WW_STATE_BIND(type, name, count, sys, comment)                                            \
    st->name = (type *)(void *)p;                                                                 \
    p += field_bytes(sizeof(type), (long long)(count));
    WW_STATE_FIELDS(WW_STATE_BIND)
#undef WW_STATE_BIND
}

static size_t state_bytes(const ww_scene *sc) {
    size_t n = header_bytes();
#define WW_STATE_SIZE(type, name, count, sys, comment)                                            \
    n += field_bytes(sizeof(type), (long long)(count));
    WW_STATE_FIELDS(WW_STATE_SIZE)
#undef WW_STATE_SIZE
    return n;
}

ww_state *ww_state_alloc(const ww_scene *sc) {
    size_t n = state_bytes(sc);
    ww_state *st = calloc(1, n);
    if (!st) return NULL;
    st->bytes = n;
    bind_fields(sc, st);
    return st;
}

void ww_state_free(ww_state *st) { free(st); }

void ww_state_clear(ww_state *st) {
    memset((unsigned char *)st + header_bytes(), 0, st->bytes - header_bytes());
}

void ww_state_copy(ww_state *dst, const ww_state *src) {
    WW_ASSERT(dst->bytes == src->bytes);
    dst->step = src->step;
    dst->t = src->t;
    dst->event_next = src->event_next;
    memcpy((unsigned char *)dst + header_bytes(), (const unsigned char *)src + header_bytes(),
           src->bytes - header_bytes());
}

uint64_t ww_state_hash(const ww_scene *sc, const ww_state *st) {
    (void)sc;
    uint64_t h = WW_HASH_INIT;
    int64_t step = st->step;
    int32_t ev = st->event_next;
    h = ww_hash_bytes(h, &step, sizeof step);
    h = ww_hash_bytes(h, &ev, sizeof ev);
    return ww_hash_bytes(h, (const unsigned char *)st + header_bytes(), st->bytes - header_bytes());
}

static void put_array(FILE *to, const char *name, const double *v, long long n) {
    fprintf(to, ",\"%s\":", name);
    if (n == 1) {
        ww_num_json(to, v[0]);
        return;
    }
    fputc('[', to);
    for (long long i = 0; i < n; i++) {
        if (i) fputc(',', to);
        ww_num_json(to, v[i]);
    }
    fputc(']', to);
}

/* an integer column (modes, flags, counters) as the same text a whole double would give */
static void put_int_array(FILE *to, const char *name, const int32_t *v, long long n) {
    fprintf(to, ",\"%s\":", name);
    if (n == 1) {
        fprintf(to, "%d", (int)v[0]);
        return;
    }
    fputc('[', to);
    for (long long i = 0; i < n; i++) fprintf(to, i ? ",%d" : "%d", (int)v[i]);
    fputc(']', to);
}

#define PUT_FIELD(to, name, v, n)                                                                 \
    _Generic((v), double *: put_array, int32_t *: put_int_array)(to, name, v, n)

void ww_state_write_json(const ww_scene *sc, const ww_state *st, FILE *to) {
    fprintf(to, "{\"step\":%lld,\"t\":", (long long)st->step);
    ww_num_json(to, st->t);
#define WW_STATE_JSON(type, name, count, sys, comment)                                            \
    PUT_FIELD(to, #name, st->name, (long long)(count));
    WW_STATE_FIELDS(WW_STATE_JSON)
#undef WW_STATE_JSON
    fputc('}', to);
}

/* whether a's n values are all finite. x * 0 is 0 for a finite x and NaN for an infinite or NaN
 * one, so sums of it are NaN exactly when some value is not finite: eight independent sums (no
 * branch per value), in blocks of 8 over a local array, a loop of fixed count that GCC's -O2
 * vectorises */
static WW_LANES int all_finite(const double *a, long long n) {
    double acc[8] = {0.0};
    long long i = 0;
    for (; i + 8 <= n; i += 8)
        for (int j = 0; j < 8; j++) acc[j] += a[i + j] * 0.0;
    for (; i < n; i++) acc[0] += a[i] * 0.0;
    double all = 0.0;
    for (int j = 0; j < 8; j++) all += acc[j];
    return all == 0.0;
}

/* the index of the first non-finite value of a (n values), or -1 */
static long long first_bad_double(const double *a, long long n) {
    for (long long i = 0; i < n; i++)
        if (!isfinite(a[i])) return i;
    return -1;
}
/* an integer is always finite */
static long long first_bad_int(const int32_t *a, long long n) { return (void)a, (void)n, -1; }
#define FIRST_BAD(p, n) _Generic((p), double *: first_bad_double, int32_t *: first_bad_int)(p, n)

/* the values of a field that a step can have written: the event outbox's live events only (its
 * slots past event_count are never written and stay zero, ww_events_clear); every other field
 * whole */
static long long live_count(const ww_state *st, const void *field, long long count) {
    if (count > 0 && field == (const void *)st->events)
        return (long long)st->event_count[0] * WW_SIM_EVENT_STRIDE;
    return count;
}

/* the fields of doubles that lie next to each other in the block make one run, [start, end),
 * summed at once: a call and a loop's tail a run instead of a field (the lake has 64 fields of
 * 1-128 values). A field of integers, or one read only in part (the outbox), ends a run. A
 * field's padding to 16 bytes is in its run; it is zero, and were it not, the search by field
 * below would find nothing and the check pass */
typedef struct double_runs {
    const double *start, *end;
    int finite;
} double_runs;

static inline __attribute__((always_inline)) void runs_add_double(double_runs *r,
                                                                   const double *p,
                                                                   long long live,
                                                                   long long count) {
    if (p != r->end) {
        if (r->start) r->finite &= all_finite(r->start, r->end - r->start);
        r->start = p;
    }
    r->end = p + field_bytes(sizeof(double), count) / sizeof(double);
    if (live < count) {
        r->finite &= all_finite(r->start, p + live - r->start);
        r->start = r->end = NULL;
    }
}
static void runs_add_int(double_runs *r, const int32_t *p, long long live, long long count) {
    (void)r, (void)p, (void)live, (void)count;
}
#define RUNS_ADD(r, p, live, count)                                                               \
    _Generic((p), double *: runs_add_double, int32_t *: runs_add_int)(r, p, live, count)

ww_result ww_state_check(const ww_scene *sc, const ww_state *st, ww_error *err) {
    double_runs r = {.start = NULL, .end = NULL, .finite = 1};
#define WW_STATE_RUN(type, name, count, sys, comment)                                             \
    RUNS_ADD(&r, st->name, live_count(st, st->name, (long long)(count)), (long long)(count));
    WW_STATE_FIELDS(WW_STATE_RUN)
#undef WW_STATE_RUN
    if (r.start) r.finite &= all_finite(r.start, r.end - r.start);
    if (r.finite) return WW_OK;
    /* something is not finite: which field, which value */
    long long i;
#define WW_STATE_CHECK(type, name, count, sys, comment)                                           \
    if ((i = FIRST_BAD(st->name, live_count(st, st->name, (long long)(count)))) >= 0)            \
        return ww_error_set(err, WW_E_NAN, sc->path, 0, 0,                                       \
                            "non-finite value in the %s system: %s[%lld] = %g at step %lld "      \
                            "(t = %.6f s)",                                                       \
                            sys, #name, i, (double)st->name[i], (long long)st->step, st->t);
    WW_STATE_FIELDS(WW_STATE_CHECK)
#undef WW_STATE_CHECK
    return WW_OK;
}
