/* checkpoint.c - checkpoint files of checkpoint.h: the header, the build's identity, the scene's
 * hash, an atomic write and a read that refuses, with the file named, whatever is not a whole
 * checkpoint of this scene from this build.
 */
#include "render/checkpoint.h"

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/hash.h"
#include "core/readfile.h"
#include "io/writers.h"

#ifndef WW_VERSION
#define WW_VERSION "unknown"
#endif

/* the largest checkpoint read: a state block is sized by the scene's counts, all capped; this is
 * far past any of them and keeps a bad file from asking for unbounded memory */
#define CKPT_MAX_BYTES ((size_t)1 << 32)

enum { FLAG_SOUND = 1 };

/* ---- little-endian fields ------------------------------------------------------------------ */

static void put_u32(unsigned char *p, uint32_t v) {
    for (int i = 0; i < 4; i++) p[i] = (unsigned char)(v >> (8 * i));
}
static void put_u64(unsigned char *p, uint64_t v) {
    for (int i = 0; i < 8; i++) p[i] = (unsigned char)(v >> (8 * i));
}
static uint32_t get_u32(const unsigned char *p) {
    uint32_t v = 0;
    for (int i = 0; i < 4; i++) v |= (uint32_t)p[i] << (8 * i);
    return v;
}
static uint64_t get_u64(const unsigned char *p) {
    uint64_t v = 0;
    for (int i = 0; i < 8; i++) v |= (uint64_t)p[i] << (8 * i);
    return v;
}
static uint64_t double_bits(double d) {
    uint64_t u;
    memcpy(&u, &d, sizeof u);
    return u;
}

/* ---- identity ------------------------------------------------------------------------------ */

static uint64_t hash_str(uint64_t h, const char *s) { return ww_hash_bytes(h, s, strlen(s) + 1); }

uint64_t ww_checkpoint_build_id(void) {
    uint64_t h = hash_str(WW_HASH_INIT, "waterworld checkpoint");
    uint32_t order = 0x01020304u;
    uint64_t sizes[] = {WW_CKPT_VERSION, sizeof(ww_state), ww_state_arrays_offset(),
                        sizeof(double), sizeof(void *)};
    h = hash_str(h, WW_VERSION);
#ifdef __VERSION__
    h = hash_str(h, __VERSION__);
#endif
    h = ww_hash_bytes(h, &order, sizeof order);
    h = ww_hash_bytes(h, sizes, sizeof sizes);
    /* the field table as written: a field added, moved, retyped or resized is another layout */
#define WW_CKPT_FIELD(type, name, count, sys, comment) h = hash_str(h, #type " " #name " " #count);
    WW_STATE_FIELDS(WW_CKPT_FIELD)
#undef WW_CKPT_FIELD
    return h;
}

static ww_result hash_file(uint64_t *h, const char *tag, const char *path, ww_error *err) {
    unsigned char *data = NULL;
    size_t len = 0;
    ww_result r = ww_file_read_max(path, WW_SCENE_MAX_BYTES, WW_SCENE_MAX_BYTES, &data, &len, err);
    if (r) return r;
    uint64_t n = len;
    *h = hash_str(*h, tag);
    *h = ww_hash_bytes(*h, &n, sizeof n);
    *h = ww_hash_bytes(*h, data, len);
    free(data);
    return WW_OK;
}

ww_result ww_checkpoint_scene_hash(const char *scene_path, const char *script_path,
                                   const ww_set *sets, int nsets, uint64_t *hash, ww_error *err) {
    uint64_t h = hash_str(WW_HASH_INIT, "waterworld scene");
    ww_result r = hash_file(&h, "scene", scene_path, err);
    for (int i = 0; i < nsets && !r; i++) h = hash_str(hash_str(h, "set"), sets[i].text);
    if (!r && script_path) r = hash_file(&h, "script", script_path, err);
    *hash = h;
    return r;
}

void ww_checkpoint_path(const char *dir, int64_t step, char *buf, size_t cap) {
    snprintf(buf, cap, "%s/step_%012lld" WW_CKPT_EXT, dir, (long long)step);
}

int ww_checkpoint_find(const char *dir, int64_t max_step, char *buf, size_t cap) {
    DIR *d = opendir(dir);
    if (!d) return -1;
    long long best = -1;
    int any = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        const char *n = e->d_name;
        if (strncmp(n, "step_", 5) != 0) continue;
        char *end = NULL;
        long long step = strtoll(n + 5, &end, 10);
        if (end == n + 5 || strcmp(end, WW_CKPT_EXT) != 0 || step < 0) continue;
        any = 1;
        if (step <= max_step && step > best) best = step;
    }
    closedir(d);
    if (best >= 0) ww_checkpoint_path(dir, best, buf, cap);
    return best >= 0 ? 1 : any ? 0 : -1;
}

/* ---- write --------------------------------------------------------------------------------- */

ww_result ww_checkpoint_write(const char *path, uint64_t scene_hash, const ww_state *st,
                              const unsigned char *sound, size_t sound_bytes, ww_error *err) {
    size_t off = ww_state_arrays_offset(), nstate = st->bytes - off;
    size_t total = WW_CKPT_HEADER_BYTES + nstate + sound_bytes;
    unsigned char *buf = malloc(total);
    if (!buf) return ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory for a checkpoint");
    unsigned char *h = buf, *payload = buf + WW_CKPT_HEADER_BYTES;
    memcpy(payload, (const unsigned char *)st + off, nstate);
    if (sound_bytes) memcpy(payload + nstate, sound, sound_bytes);

    memset(h, 0, WW_CKPT_HEADER_BYTES);
    memcpy(h, WW_CKPT_MAGIC, 8);
    put_u32(h + 8, WW_CKPT_VERSION);
    put_u32(h + 12, WW_CKPT_HEADER_BYTES);
    put_u64(h + 16, ww_checkpoint_build_id());
    put_u64(h + 24, scene_hash);
    put_u64(h + 32, (uint64_t)st->step);
    put_u64(h + 40, double_bits(st->t));
    put_u32(h + 48, (uint32_t)st->event_next);
    put_u32(h + 52, sound_bytes ? FLAG_SOUND : 0);
    put_u64(h + 56, nstate);
    put_u64(h + 64, sound_bytes);
    put_u64(h + 72, total);
    put_u64(h + 80, ww_hash_bytes(WW_HASH_INIT, payload, nstate + sound_bytes));
    put_u64(h + 88, ww_hash_bytes(WW_HASH_INIT, h, 88));
    ww_result r = ww_write_file_atomic(path, buf, total, err);
    free(buf);
    return r;
}

/* ---- read ---------------------------------------------------------------------------------- */

/* the header's promises against the bytes read: whole, unchanged, of this format */
static ww_result check_whole(const char *path, const unsigned char *d, size_t len, ww_error *err) {
    if (len < 8 || memcmp(d, WW_CKPT_MAGIC, 8) != 0)
        return ww_error_set(err, WW_E_SYNTAX, path, 0, 0,
                            "not a waterworld checkpoint (no \"WWCKPT\" signature)%s",
                            len < 8 ? ": the file is shorter than a signature" : "");
    if (len < WW_CKPT_HEADER_BYTES)
        return ww_error_set(err, WW_E_SYNTAX, path, 0, 0,
                            "truncated checkpoint: %zu bytes, shorter than its %d-byte header",
                            len, WW_CKPT_HEADER_BYTES);
    if (get_u32(d + 8) != WW_CKPT_VERSION)
        return ww_error_set(err, WW_E_INCONSISTENT, path, 0, 0,
                            "checkpoint format version %u; this build reads version %d: "
                            "simulate again with this build",
                            (unsigned)get_u32(d + 8), WW_CKPT_VERSION);
    if (ww_hash_bytes(WW_HASH_INIT, d, 88) != get_u64(d + 88) ||
        get_u32(d + 12) != WW_CKPT_HEADER_BYTES)
        return ww_error_set(err, WW_E_SYNTAX, path, 0, 0,
                            "corrupt checkpoint: its header's checksum does not match");
    uint64_t nstate = get_u64(d + 56), nsound = get_u64(d + 64), total = get_u64(d + 72);
    if (total != WW_CKPT_HEADER_BYTES + nstate + nsound || nstate > CKPT_MAX_BYTES ||
        nsound > CKPT_MAX_BYTES)
        return ww_error_set(err, WW_E_SYNTAX, path, 0, 0,
                            "corrupt checkpoint: its header's sizes do not add up");
    if (len != total)
        return ww_error_set(err, WW_E_SYNTAX, path, 0, 0,
                            "truncated checkpoint: %zu bytes, its header says %llu", len,
                            (unsigned long long)total);
    if (ww_hash_bytes(WW_HASH_INIT, d + WW_CKPT_HEADER_BYTES, len - WW_CKPT_HEADER_BYTES) !=
        get_u64(d + 80))
        return ww_error_set(err, WW_E_SYNTAX, path, 0, 0,
                            "corrupt checkpoint: the state's checksum does not match");
    return WW_OK;
}

/* the checkpoint belongs to this build and this scene */
static ww_result check_ours(const char *path, const unsigned char *d, const ww_scene *sc,
                            uint64_t scene_hash, ww_error *err) {
    uint64_t build = get_u64(d + 16), scene = get_u64(d + 24);
    if (build != ww_checkpoint_build_id())
        return ww_error_set(err, WW_E_INCONSISTENT, path, 0, 0,
                            "written by another build of waterworld (build id %016llx, this one "
                            "is %016llx: version %s): simulate its prefix again with this build",
                            (unsigned long long)build,
                            (unsigned long long)ww_checkpoint_build_id(), WW_VERSION);
    if (scene != scene_hash)
        return ww_error_set(err, WW_E_INCONSISTENT, path, 0, 0,
                            "written for another scene, or other --set / --script values (scene "
                            "hash %016llx, %s as given here is %016llx)",
                            (unsigned long long)scene, sc->path, (unsigned long long)scene_hash);
    int32_t ev = (int32_t)get_u32(d + 48);
    if ((int64_t)get_u64(d + 32) < 0 || ev < 0 || ev > sc->nevents ||
        (get_u32(d + 52) & FLAG_SOUND) != (get_u64(d + 64) ? FLAG_SOUND : 0u))
        return ww_error_set(err, WW_E_SYNTAX, path, 0, 0,
                            "corrupt checkpoint: its step, script position or flags are out of "
                            "range");
    return WW_OK;
}

ww_result ww_checkpoint_read(const char *path, const ww_scene *sc, uint64_t scene_hash,
                             ww_checkpoint *ck, ww_error *err) {
    memset(ck, 0, sizeof *ck);
    unsigned char *d = NULL;
    size_t len = 0;
    ww_error e = {0};
    ww_result r = ww_file_read_max(path, CKPT_MAX_BYTES, CKPT_MAX_BYTES, &d, &len, &e);
    if (r)
        return ww_error_set(err, r == WW_E_NOMEM ? r : WW_E_NOFILE, path, 0, 0,
                            "cannot read the checkpoint: %s", e.msg);
    if (!(r = check_whole(path, d, len, err))) {
        ww_state *st = ww_state_alloc(sc);
        size_t off = ww_state_arrays_offset(), nstate = (size_t)get_u64(d + 56);
        if (!st) r = ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory for the state");
        if (!r) r = check_ours(path, d, sc, scene_hash, err);
        /* the same scene gives the same counts; a mismatch here is a file made by hand */
        if (!r && nstate != st->bytes - off)
            r = ww_error_set(err, WW_E_INCONSISTENT, path, 0, 0,
                             "its state holds %zu bytes of arrays, this scene's %zu",
                             nstate, st->bytes - off);
        if (!r) {
            memcpy((unsigned char *)st + off, d + WW_CKPT_HEADER_BYTES, nstate);
            st->step = (int64_t)get_u64(d + 32);
            uint64_t tb = get_u64(d + 40);
            memcpy(&st->t, &tb, sizeof st->t);
            st->event_next = (int)(int32_t)get_u32(d + 48);
            ck->st = st;
            st = NULL;
            ck->build_id = get_u64(d + 16);
            ck->scene_hash = get_u64(d + 24);
            ck->step = ck->st->step;
            ck->file_bytes = len;
            ck->sound_bytes = (size_t)get_u64(d + 64);
            if (ck->sound_bytes && !(ck->sound = malloc(ck->sound_bytes)))
                r = ww_error_set(err, WW_E_NOMEM, NULL, 0, 0, "out of memory for a checkpoint");
            if (!r && ck->sound_bytes)
                memcpy(ck->sound, d + WW_CKPT_HEADER_BYTES + nstate, ck->sound_bytes);
        }
        ww_state_free(st);
    }
    free(d);
    if (r) ww_checkpoint_free(ck);
    return r;
}

void ww_checkpoint_free(ww_checkpoint *ck) {
    ww_state_free(ck->st);
    free(ck->sound);
    memset(ck, 0, sizeof *ck);
}
