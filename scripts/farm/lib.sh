# lib.sh - shared by the farm scripts (sourced, POSIX sh): the waterworld binary, the two
# commands a farm needs from it (the slice job lines, and join), and the byte comparisons that
# hold a farmed render or sweep to one process.
#
#   . scripts/farm/lib.sh
#   farm_render_jobs DIR N SCENE [render options]   N command lines on stdout, one per slice
#   farm_join DIR                                   join a render's or a sweep's DIR
#   farm_same_render REF DIR                        frames and sound track byte for byte
#   farm_same_sweep REF DIR                         sweep.jsonl and thumbnails byte for byte
#
# Environment: WW_BIN (default ./waterworld, else the one on PATH). The functions' own variables
# start with an underscore (sh has no locals): a script sourcing this keeps its names.

farm_ww() {
    _w=${WW_BIN:-./waterworld}
    [ -x "$_w" ] || _w=$(command -v waterworld || true)
    [ -n "$_w" ] || { echo "farm: no waterworld binary (build it with make, or set WW_BIN)" >&2; return 3; }
    # absolute, so that the job lines run from any folder and on any node of a shared filesystem
    case "$_w" in /*) ;; */*) _w="$(cd "$(dirname "$_w")" && pwd)/$(basename "$_w")" ;; esac
    echo "$_w"
}

# the joined sound track and stats in a render's DIR (render/slices.h names them)
FARM_AUDIO=audio.wav

# ---- the one place to switch ---------------------------------------------------------------
# `render --slices N --emit-jobs` and `join` are the contract of issue 18's split-and-join part.
# Until a build has them, farm_render_jobs and farm_join fall back to a stand-in made of what
# every build has (`render --frames A:B`, `sweep --point I`): the same slices, the same parts
# under DIR/slices/, the same joined names. Once `join` is in every build, delete the stand-in
# functions (farm_standin_*) and the two tests of `farm_have_join`.
farm_have_join() {
    "$(farm_ww)" join --help >/dev/null 2>&1
}

farm_render_jobs() {
    _d=$1 _n=$2
    shift 2
    if farm_have_join; then
        "$(farm_ww)" render "$@" -o "$_d" --audio "$FARM_AUDIO" --slices "$_n" --emit-jobs
    else
        farm_standin_render_jobs "$_d" "$_n" "$@"
    fi
}

farm_join() {
    if farm_have_join; then "$(farm_ww)" join "$1"; else farm_standin_join "$1"; fi
}

# stand-in: slice I of N of frames [A, B) is [A + I q + min(I, r), ...) with q, r = (B-A)/N,
# (B-A)%N (render/slices.h's cut); its sound part DIR/slices/slice_IIIII.wav. Takes SCENE
# --frames A:B [other options]; every slice's line is sh-quoted.
farm_standin_render_jobs() {
    _d=$1 _n=$2 _scene=$3
    shift 3
    _ww=$(farm_ww) || return $?
    _a="" _b="" _rest=""
    while [ $# -gt 0 ]; do
        case "$1" in
        --frames) _a=${2%%:*} _b=${2#*:}; shift 2 ;;
        *) _rest="$_rest $(farm_q "$1")"; shift ;;
        esac
    done
    [ -n "$_a" ] || { echo "farm: the stand-in needs --frames A:B" >&2; return 2; }
    _q=$(((_b - _a) / _n)) _r=$(((_b - _a) % _n)) _i=0
    while [ "$_i" -lt "$_n" ]; do
        _lo=$((_a + _i * _q + (_i < _r ? _i : _r)))
        _hi=$((_a + (_i + 1) * _q + (_i + 1 < _r ? _i + 1 : _r)))
        _part=$(printf '%s/slices/slice_%05d.wav' "$_d" "$_i")
        echo "mkdir -p $(farm_q "$_d/slices") && $(farm_q "$_ww") render $(farm_q "$_scene")$_rest" \
            "--frames $_lo:$_hi -o $(farm_q "$_d") --audio $(farm_q "$_part") --quiet"
        _i=$((_i + 1))
    done
}

# stand-in join: a sweep's DIR/points/ into DIR/sweep.jsonl, a render's slice sound parts into
# DIR/audio.wav (the PCM data butted, one header); written beside and renamed
farm_standin_join() {
    if [ -d "$1/points" ]; then
        cat "$1"/points/point_*.jsonl >"$1/.sweep.jsonl.tmp" && mv "$1/.sweep.jsonl.tmp" "$1/sweep.jsonl"
        return
    fi
    python3 - "$1" "$FARM_AUDIO" <<'PY' || return 1
import glob, os, sys, wave
d, name = sys.argv[1], sys.argv[2]
parts = sorted(glob.glob(os.path.join(d, "slices", "slice_*.wav")))
if not parts:
    sys.exit("farm: no slice_*.wav under %s/slices" % d)
tmp = os.path.join(d, "." + name + ".tmp")
with wave.open(parts[0]) as w0, wave.open(tmp, "wb") as out:
    out.setparams(w0.getparams())
    for p in parts:
        with wave.open(p) as w:
            out.writeframes(w.readframes(w.getnframes()))
os.replace(tmp, os.path.join(d, name))
PY
}
# ---- end of the place to switch ------------------------------------------------------------

# one word quoted for sh: 'it'\''s'
farm_q() {
    printf "'%s'" "$(printf '%s' "$1" | sed "s/'/'\\\\''/g")"
}

# every frame of REF is in DIR with the same bytes, and no more frames; the sound tracks equal
farm_same_render() {
    _bad=0 _n=0
    for _f in "$1"/frame_*.png; do
        _n=$((_n + 1))
        cmp -s "$_f" "$2/${_f##*/}" || { echo "farm: ${_f##*/} differs from one process" >&2; _bad=1; }
    done
    _m=$(ls "$2" | grep -c '^frame_.*\.png$')
    [ "$_m" -eq "$_n" ] || { echo "farm: $_m frames in $2, $_n in one process" >&2; _bad=1; }
    cmp -s "$1/$FARM_AUDIO" "$2/$FARM_AUDIO" ||
        { echo "farm: $2/$FARM_AUDIO differs from one process" >&2; _bad=1; }
    [ "$_bad" = 0 ] && echo "  same bytes: $_n frames and $FARM_AUDIO ($(wc -c <"$2/$FARM_AUDIO") bytes)"
    return "$_bad"
}

# sweep.jsonl and every thumbnail the same bytes as one process's
farm_same_sweep() {
    _bad=0 _n=0
    cmp -s "$1/sweep.jsonl" "$2/sweep.jsonl" || { echo "farm: sweep.jsonl differs" >&2; _bad=1; }
    for _f in "$1"/thumbs/point_*.png; do
        [ -e "$_f" ] || continue
        _n=$((_n + 1))
        cmp -s "$_f" "$2/thumbs/${_f##*/}" || { echo "farm: thumbs/${_f##*/} differs" >&2; _bad=1; }
    done
    [ "$_bad" = 0 ] && echo "  same bytes: sweep.jsonl ($(wc -l <"$2/sweep.jsonl") points) and $_n thumbnails"
    return "$_bad"
}
