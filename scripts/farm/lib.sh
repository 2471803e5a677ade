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
# Environment: WW_BIN (default ./waterworld, else the one on PATH).

farm_ww() {
    ww=${WW_BIN:-./waterworld}
    [ -x "$ww" ] || ww=$(command -v waterworld || true)
    [ -n "$ww" ] || { echo "farm: no waterworld binary (build it with make, or set WW_BIN)" >&2; return 3; }
    # absolute, so that the job lines run from any folder and on any node of a shared filesystem
    case "$ww" in /*) ;; */*) ww="$(cd "$(dirname "$ww")" && pwd)/$(basename "$ww")" ;; esac
    echo "$ww"
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
    dir=$1 n=$2
    shift 2
    if farm_have_join; then
        "$(farm_ww)" render "$@" -o "$dir" --audio "$FARM_AUDIO" --slices "$n" --emit-jobs
    else
        farm_standin_render_jobs "$dir" "$n" "$@"
    fi
}

farm_join() {
    if farm_have_join; then "$(farm_ww)" join "$1"; else farm_standin_join "$1"; fi
}

# stand-in: slice I of N of frames [A, B) is [A + I q + min(I, r), ...) with q, r = (B-A)/N,
# (B-A)%N (render/slices.h's cut); its sound part DIR/slices/slice_IIIII.wav. Takes SCENE
# --frames A:B [other options]; every slice's line is sh-quoted.
farm_standin_render_jobs() {
    dir=$1 n=$2 scene=$3
    shift 3
    ww=$(farm_ww) || return $?
    a="" b="" rest=""
    while [ $# -gt 0 ]; do
        case "$1" in
        --frames) a=${2%%:*} b=${2#*:}; shift 2 ;;
        *) rest="$rest $(farm_q "$1")"; shift ;;
        esac
    done
    [ -n "$a" ] || { echo "farm: the stand-in needs --frames A:B" >&2; return 2; }
    q=$(((b - a) / n)) r=$(((b - a) % n)) i=0
    while [ "$i" -lt "$n" ]; do
        lo=$((a + i * q + (i < r ? i : r)))
        hi=$((a + (i + 1) * q + (i + 1 < r ? i + 1 : r)))
        part=$(printf '%s/slices/slice_%05d.wav' "$dir" "$i")
        echo "mkdir -p $(farm_q "$dir/slices") && $(farm_q "$ww") render $(farm_q "$scene")$rest" \
            "--frames $lo:$hi -o $(farm_q "$dir") --audio $(farm_q "$part") --quiet"
        i=$((i + 1))
    done
}

# stand-in join: a sweep's DIR/points/ into DIR/sweep.jsonl, a render's slice sound parts into
# DIR/audio.wav (the PCM data butted, one header); written beside and renamed
farm_standin_join() {
    dir=$1
    if [ -d "$dir/points" ]; then
        cat "$dir"/points/point_*.jsonl >"$dir/.sweep.jsonl.tmp" && mv "$dir/.sweep.jsonl.tmp" "$dir/sweep.jsonl"
        return
    fi
    python3 - "$dir" "$FARM_AUDIO" <<'PY' || return 1
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
    ref=$1 dir=$2 bad=0 n=0
    for f in "$ref"/frame_*.png; do
        n=$((n + 1))
        cmp -s "$f" "$dir/${f##*/}" || { echo "farm: ${f##*/} differs from one process" >&2; bad=1; }
    done
    m=$(ls "$dir" | grep -c '^frame_.*\.png$')
    [ "$m" -eq "$n" ] || { echo "farm: $m frames in $dir, $n in one process" >&2; bad=1; }
    cmp -s "$ref/$FARM_AUDIO" "$dir/$FARM_AUDIO" ||
        { echo "farm: $dir/$FARM_AUDIO differs from one process" >&2; bad=1; }
    [ "$bad" = 0 ] && echo "  same bytes: $n frames and $FARM_AUDIO ($(wc -c <"$dir/$FARM_AUDIO") bytes)"
    return "$bad"
}

# sweep.jsonl and every thumbnail the same bytes as one process's
farm_same_sweep() {
    ref=$1 dir=$2 bad=0 n=0
    cmp -s "$ref/sweep.jsonl" "$dir/sweep.jsonl" || { echo "farm: sweep.jsonl differs" >&2; bad=1; }
    for f in "$ref"/thumbs/point_*.png; do
        [ -e "$f" ] || continue
        n=$((n + 1))
        cmp -s "$f" "$dir/thumbs/${f##*/}" || { echo "farm: thumbs/${f##*/} differs" >&2; bad=1; }
    done
    [ "$bad" = 0 ] && echo "  same bytes: sweep.jsonl ($(wc -l <"$dir/sweep.jsonl") points) and $n thumbnails"
    return "$bad"
}
