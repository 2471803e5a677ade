/* state.c - the one-block simulation state: sizing, reset, copy, hash, JSON and NaN checks,
 * all driven by the WW_STATE_FIELDS table in state.h.
 */
#include "sim/state.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/hash.h"
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

/* the index of the first non-finite value of a (n values), or -1. x * 0 is 0 for a finite x and
 * NaN for an infinite or NaN one, so sums of it are NaN exactly when some value is not finite:
 * four independent sums (pipelined, no branch per value) say whether to look, and only then is
 * the index searched */
static long long first_bad_double(const double *a, long long n) {
    double acc[4] = {0.0, 0.0, 0.0, 0.0};
    long long i = 0;
    for (; i + 4 <= n; i += 4)
        for (int j = 0; j < 4; j++) acc[j] += a[i + j] * 0.0;
    for (; i < n; i++) acc[0] += a[i] * 0.0;
    if (acc[0] + acc[1] + acc[2] + acc[3] == 0.0) return -1;
    for (i = 0; i < n; i++)
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

ww_result ww_state_check(const ww_scene *sc, const ww_state *st, ww_error *err) {
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
