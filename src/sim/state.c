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

/* a double field of count values (its padding included) at p onto the NaN guard's runs: the
 * run before it grows where the field starts at its end, else the field starts a run. An
 * integer field, or the outbox, adds nothing, and the next double field starts a new run */
static void runs_bind_double(ww_state *st, const double *p, long long count, int outbox) {
    if (count <= 0 || outbox) return;
    uint32_t start = (uint32_t)(p - (const double *)(const void *)st);
    uint32_t n = (uint32_t)(field_bytes(sizeof(double), count) / sizeof(double));
    if (st->nruns > 0 && st->runs[st->nruns - 1].start + st->runs[st->nruns - 1].count == start) {
        st->runs[st->nruns - 1].count += n;
        return;
    }
    WW_ASSERT(st->nruns < WW_STATE_NFIELDS);
    st->runs[st->nruns].start = start;
    st->runs[st->nruns].count = n;
    st->nruns++;
}
static void runs_bind_int(ww_state *st, const int32_t *p, long long count, int outbox) {
    (void)st, (void)p, (void)count, (void)outbox;
}
#define RUNS_BIND(st, p, count, outbox)                                                           \
    _Generic((p), double *: runs_bind_double, int32_t *: runs_bind_int)(st, p, count, outbox)

/* point the field pointers into the block that follows the header, and find the runs */
static void bind_fields(const ww_scene *sc, ww_state *st) {
    unsigned char *p = (unsigned char *)st + header_bytes();
#define WW_STATE_BIND(type, name, count, sys, comment)                                            \
    st->name = (type *)(void *)p;                                                                 \
    p += field_bytes(sizeof(type), (long long)(count));
    WW_STATE_FIELDS(WW_STATE_BIND)
#undef WW_STATE_BIND
    st->nruns = 0;
#define WW_STATE_RUN(type, name, count, sys, comment)                                             \
    RUNS_BIND(st, st->name, (long long)(count),                                                   \
              (const void *)&st->name == (const void *)&st->events);
    WW_STATE_FIELDS(WW_STATE_RUN)
#undef WW_STATE_RUN
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

/* whether every value of the runs (sim/state.h) and the outbox's n_events values is finite.
 * x * 0 is 0 for a finite x and NaN for an infinite or NaN one, so sums of it are NaN exactly
 * when some value is not finite: eight independent sums (no branch per value), in blocks of 8,
 * a loop of fixed count that GCC's -O2 vectorises, across every run */
WW_LANE_STEP void finite_sums(double acc[8], const double *a, long long n) {
    long long i = 0;
    for (; i + 8 <= n; i += 8)
        for (int j = 0; j < 8; j++) acc[j] += a[i + j] * 0.0;
    for (; i < n; i++) acc[0] += a[i] * 0.0;
}
static WW_LANES int all_finite(const ww_state *st, long long n_events) {
    double acc[8] = {0.0};
    const double *base = (const double *)(const void *)st;
    for (int r = 0; r < st->nruns; r++)
        finite_sums(acc, base + st->runs[r].start, st->runs[r].count);
    finite_sums(acc, st->events, n_events);
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

/* the values of the event outbox a step can have written: its live events (its slots past
 * event_count are never written and stay zero, ww_events_clear) */
static long long outbox_live(const ww_state *st) {
    return (long long)st->event_count[0] * WW_SIM_EVENT_STRIDE;
}

/* the values of a field that a step can have written: the outbox's live ones, every other
 * field whole */
static long long live_count(const ww_state *st, const void *field, long long count) {
    return count > 0 && field == (const void *)st->events ? outbox_live(st) : count;
}

ww_result ww_state_check(const ww_scene *sc, const ww_state *st, ww_error *err) {
    if (all_finite(st, ww_scene_has_objects(sc) ? outbox_live(st) : 0)) return WW_OK;
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
