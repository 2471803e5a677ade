/* checkpoint.h - the state of a run at one step, on disk, so that a later slice starts there
 * instead of simulating the prefix (`simulate --checkpoint-every K -o DIR`, `render
 * --from-checkpoint FILE`).
 *
 *   uint64_t h;
 *   ww_checkpoint_scene_hash(scene_path, script_path, sets, nsets, &h, &err);
 *   ww_checkpoint_write(path, h, st, sound, sound_bytes, &err);     // atomic
 *   ww_checkpoint ck;
 *   ww_checkpoint_read(path, sc, h, &ck, &err);   // refuses another scene, build or a bad file
 *   ... ww_state_copy(st, ck.st) ... ck.sound (render/audio.h's ww_audio_restore) ...
 *   ww_checkpoint_free(&ck);
 *
 * A file is a 96-byte header, then the payload: the state's arrays (sim/state.h, the bytes after
 * ww_state_arrays_offset(); the pointers of the block are never stored, ww_state_alloc binds
 * them again) and the sound track's synth state when there is one. Header, little-endian:
 *    0  magic "WWCKPT\r\n"         8  u32 format version    12 u32 header bytes (96)
 *   16  u64 build id              24  u64 scene hash       32  i64 step
 *   40  f64 t                     48  i32 event_next       52  u32 flags (bit 0: sound)
 *   56  u64 state array bytes     64  u64 sound bytes      72  u64 file bytes
 *   80  u64 payload checksum      88  u64 header checksum (FNV-1a 64 of bytes 0..87)
 * The checksums are FNV-1a 64 (core/hash.h): a changed byte always changes them (each step of
 * FNV-1a is a bijection of its state). docs/simulation.md, "Checkpoints", has the rules.
 */
#ifndef WW_CHECKPOINT_H
#define WW_CHECKPOINT_H

#include <stddef.h>
#include <stdint.h>

#include "core/error.h"
#include "scene/scene.h"
#include "sim/state.h"

#define WW_CKPT_VERSION 1
#define WW_CKPT_HEADER_BYTES 96
#define WW_CKPT_MAGIC "WWCKPT\r\n"
#define WW_CKPT_EXT ".wwck"

typedef struct ww_checkpoint {
    uint64_t build_id, scene_hash;
    int64_t step;
    ww_state *st;              /* owned: the state at `step`, bound to the reader's scene */
    unsigned char *sound;      /* owned: the synth's state (render/audio.h); NULL when none */
    size_t sound_bytes;
    size_t file_bytes;
} ww_checkpoint;

/* this build's identity: version, compiler, byte order and the state's field table (types,
 * names, counts) with the block's header size; a checkpoint from another build is refused */
uint64_t ww_checkpoint_build_id(void);
/* the scene as the user asked for it: the scene file's bytes, every --set in order, the --script
 * file's bytes (script_path may be NULL); errors name the file that cannot be read */
ww_result ww_checkpoint_scene_hash(const char *scene_path, const char *script_path,
                                   const ww_set *sets, int nsets, uint64_t *hash, ww_error *err);
/* DIR/step_000000001200.wwck */
void ww_checkpoint_path(const char *dir, int64_t step, char *buf, size_t cap);
/* the latest checkpoint in dir at or before max_step (by its name, DIR/step_N.wwck) into buf;
 * 1 found, 0 none at or before it, -1 none in dir at all or dir cannot be read */
int ww_checkpoint_find(const char *dir, int64_t max_step, char *buf, size_t cap);
/* write st (and sound, sound_bytes > 0; NULL: none) to path, atomically (PATH.tmp.PID renamed) */
ww_result ww_checkpoint_write(const char *path, uint64_t scene_hash, const ww_state *st,
                              const unsigned char *sound, size_t sound_bytes, ww_error *err);
/* read path for scene sc, whose hash is scene_hash: WW_E_NOFILE when it cannot be read,
 * WW_E_SYNTAX when it is not a whole checkpoint (truncated, a flipped bit, another format),
 * WW_E_INCONSISTENT when it was written by another build or for another scene (or other --set /
 * --script values); the message names the file. On success ck owns what it holds. */
ww_result ww_checkpoint_read(const char *path, const ww_scene *sc, uint64_t scene_hash,
                             ww_checkpoint *ck, ww_error *err);
void ww_checkpoint_free(ww_checkpoint *ck);

#endif
