/* checkpoint_args.c - `--from-checkpoint FILE` for render and simulate: the file read against
 * the scene as the command line loaded it, and its place in the run checked.
 */
#include <stdio.h>
#include <sys/stat.h>

#include "cli/cli.h"
#include "render/audio.h"
#include "render/checkpoint.h"

ww_result ww_cli_checkpoint_load(const ww_cli_scene_opts *o, const ww_scene *sc, const char *path,
                                 int64_t first_step, int need_sound, ww_checkpoint *ck,
                                 ww_error *err) {
    /* a folder of checkpoints: the latest at or before the first step; when every one is later,
     * the run starts at step 0 (ck stays empty) */
    struct stat sb;
    char found[1024];
    if (stat(path, &sb) == 0 && S_ISDIR(sb.st_mode)) {
        int k = ww_checkpoint_find(path, first_step, found, sizeof found);
        if (k < 0)
            return ww_error_set(err, WW_E_NOFILE, path, 0, 0,
                                "--from-checkpoint: no checkpoint (step_N" WW_CKPT_EXT ") in this "
                                "folder");
        if (k == 0) return WW_OK;
        path = found;
    }
    uint64_t h;
    ww_result r = ww_checkpoint_scene_hash(o->scene_path, o->script, o->sets, o->nsets, &h, err);
    if (!r) r = ww_checkpoint_read(path, sc, h, ck, err);
    if (r) return r;
    int64_t spf = sc->steps_per_frame;
    if (ck->step > first_step)
        r = ww_error_set(err, WW_E_INCONSISTENT, path, 0, 0,
                         "--from-checkpoint: the checkpoint is at step %lld (frame %.6g), after "
                         "the first frame asked for, frame %lld (step %lld); use an earlier "
                         "checkpoint",
                         (long long)ck->step, (double)ck->step / (double)spf,
                         (long long)(first_step / spf), (long long)first_step);
    else if (need_sound && !ck->sound)
        r = ww_error_set(err, WW_E_INCONSISTENT, path, 0, 0,
                         "--from-checkpoint with --audio: the checkpoint holds no sound track "
                         "state (more than %d sounds were playing when it was written); use "
                         "another checkpoint, or render without --from-checkpoint",
                         WW_AUDIO_MAX_VOICES);
    if (r) ww_checkpoint_free(ck);
    return r;
}
